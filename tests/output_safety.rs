//! Writing output when the disk says no: `gsdc build` exits 2 with the path
//! and the OS error, `gsdc::build::generate` and
//! `gsdc::output::write_if_changed` return them, and no partial, truncated
//! or temporary file is left behind; a file already there is never replaced
//! by a broken one.
//!
//! A read-only and a full file system are real tmpfs mounts when the tests
//! may mount (as root); elsewhere those cases are skipped here and covered
//! by the failing-disk unit tests in `src/output.rs`. Permission bits are
//! not used: root ignores them.

use gsdc::output::{write_if_changed, Outcome};
use gsdc::{Artifact, ArtifactKind};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const MD810: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/descriptions/md810dp.toml");
/// What `gsdc build` writes for the MD810, in the order it writes them.
const MD810_FILES: [&str; 6] = [
    "MD810DP.GSD",
    "GSDML-V2.32-INOVANCE-MD810-20261122.xml",
    "md810dp_layout.rs",
    "gsdc_support.rs",
    "md810dp_layout.h",
    "gsdc_support.h",
];

fn scratch(name: &str) -> PathBuf {
    let dir =
        std::env::temp_dir().join(format!("gsdc-output-safety-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn build(description: &Path, out: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gsdc"))
        .arg("build")
        .arg(description)
        .arg("--out")
        .arg(out)
        .output()
        .unwrap()
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// Exit 2, and stderr names `path` and says `os_error`.
#[track_caller]
fn assert_io_error(output: &Output, path: &Path, os_error: &str) {
    let stderr = stderr(output);
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains(&path.display().to_string()) && stderr.contains(os_error),
        "no {} and {os_error:?} in {stderr}",
        path.display()
    );
}

fn names_in(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    names
}

/// The MD810 files with stale contents, as a previous release left them.
fn old_files(dir: &Path) {
    for name in MD810_FILES {
        std::fs::write(dir.join(name), format!("old {name}")).unwrap();
    }
}

/// Every old file is still there with its old content, and nothing else is.
#[track_caller]
fn assert_untouched(dir: &Path) {
    let mut expected = MD810_FILES.map(String::from).to_vec();
    expected.sort();
    assert_eq!(
        names_in(dir),
        expected,
        "a temporary or partial file is left"
    );
    for name in MD810_FILES {
        assert_eq!(
            std::fs::read_to_string(dir.join(name)).unwrap(),
            format!("old {name}")
        );
    }
}

/// A tmpfs mounted for one test, unmounted when dropped; `None` where this
/// process may not mount.
struct Tmpfs(PathBuf);

impl Tmpfs {
    fn mount(dir: &Path, size: &str) -> Option<Tmpfs> {
        let options = format!("size={size}");
        let mounted = Command::new("mount")
            .args(["-t", "tmpfs", "-o", &options, "tmpfs"])
            .arg(dir)
            .output()
            .is_ok_and(|o| o.status.success());
        if !mounted {
            eprintln!("cannot mount a tmpfs here: the case is left to src/output.rs's unit tests");
        }
        mounted.then(|| Tmpfs(dir.to_path_buf()))
    }

    fn make_read_only(&self) {
        let status = Command::new("mount")
            .args(["-o", "remount,ro"])
            .arg(&self.0)
            .status()
            .unwrap();
        assert!(status.success());
    }
}

impl Drop for Tmpfs {
    fn drop(&mut self) {
        let _ = Command::new("umount").arg(&self.0).status();
    }
}

#[test]
fn a_missing_output_directory_is_created() {
    let dir = scratch("missing");
    let out = dir.join("a/b/dist");
    let output = build(Path::new(MD810), &out);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert_eq!(names_in(&out).len(), MD810_FILES.len());

    let files = [Artifact {
        kind: ArtifactKind::Gsd,
        file_name: "X.GSD".into(),
        contents: b"x".to_vec(),
    }];
    let lib_out = dir.join("c/d");
    assert_eq!(
        write_if_changed(&lib_out, &files).unwrap(),
        [Outcome::Written]
    );
    assert_eq!(std::fs::read(lib_out.join("X.GSD")).unwrap(), b"x");
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn an_output_directory_under_a_file_cannot_be_created() {
    let dir = scratch("under-file");
    std::fs::write(dir.join("file"), b"").unwrap();
    let out = dir.join("file/dist");
    let output = build(Path::new(MD810), &out);
    assert_io_error(&output, &out, "Not a directory (os error 20)");
    assert!(stderr(&output).contains("cannot create"));

    let e = gsdc::build::generate(MD810, &out).unwrap_err().to_string();
    assert!(
        e.contains(&out.display().to_string()) && e.contains("os error 20"),
        "{e}"
    );
    std::fs::remove_dir_all(dir).unwrap();
}

/// `dist/MD810DP.GSD` is a directory: the error names it, and neither it
/// nor the files that could have been written are changed.
#[test]
fn an_output_path_that_is_a_directory_changes_nothing() {
    let dir = scratch("is-dir");
    old_files(&dir);
    let gsd = dir.join(MD810_FILES[0]);
    std::fs::remove_file(&gsd).unwrap();
    std::fs::create_dir(&gsd).unwrap();
    std::fs::write(gsd.join("keep"), b"").unwrap();
    let output = build(Path::new(MD810), &dir);
    assert_io_error(&output, &gsd, "Is a directory (os error 21)");
    assert!(stderr(&output).contains("no file was changed"));
    assert!(names_in(&gsd) == ["keep"]);
    std::fs::remove_dir_all(&gsd).unwrap();
    std::fs::write(&gsd, format!("old {}", MD810_FILES[0])).unwrap();
    assert_untouched(&dir);
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn a_description_that_is_a_symlink_loop_exits_2() {
    let dir = scratch("loop");
    let description = dir.join("loop.toml");
    std::os::unix::fs::symlink("loop.toml", &description).unwrap();
    let output = build(&description, &dir.join("out"));
    assert_io_error(
        &output,
        &description,
        "Too many levels of symbolic links (os error 40)",
    );
    assert!(!dir.join("out").exists());

    let e = gsdc::build::generate(&description, dir.join("out")).unwrap_err();
    assert!(e.to_string().contains("os error 40"), "{e}");
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn a_read_only_output_directory_changes_nothing() {
    let dir = scratch("read-only");
    let Some(fs) = Tmpfs::mount(&dir, "1m") else {
        return;
    };
    old_files(&dir);
    fs.make_read_only();
    let output = build(Path::new(MD810), &dir);
    let first = dir.join(MD810_FILES[0]);
    assert_io_error(&output, &first, "Read-only file system (os error 30)");
    assert_untouched(&dir);
    drop(fs);
    std::fs::remove_dir_all(dir).unwrap();
}

/// 64 KiB hold the old files and the new GSD, not the 59 KB GSDML as well.
#[test]
fn a_full_disk_changes_nothing_and_leaves_no_partial_file() {
    let dir = scratch("full");
    let Some(fs) = Tmpfs::mount(&dir, "64k") else {
        return;
    };
    old_files(&dir);
    let output = build(Path::new(MD810), &dir);
    let gsdml = dir.join(MD810_FILES[1]);
    assert_io_error(&output, &gsdml, "No space left on device (os error 28)");
    assert!(stderr(&output).contains("no file was changed"));
    assert_untouched(&dir);

    let e = gsdc::build::generate(MD810, &dir).unwrap_err().to_string();
    assert!(e.contains("os error 28"), "{e}");
    assert_untouched(&dir);
    drop(fs);
    std::fs::remove_dir_all(dir).unwrap();
}

/// The GSDML is immutable (`chattr +i`, which binds root too): its rename
/// fails after the GSD's succeeded, and the error says the GSD was written.
#[test]
fn a_failure_after_some_files_were_written_names_them() {
    let dir = scratch("partly");
    old_files(&dir);
    let gsdml = dir.join(MD810_FILES[1]);
    let immutable = Command::new("chattr")
        .arg("+i")
        .arg(&gsdml)
        .output()
        .is_ok_and(|o| o.status.success());
    if !immutable {
        eprintln!("chattr +i does not work here: the case is left to src/output.rs's unit tests");
        std::fs::remove_dir_all(dir).unwrap();
        return;
    }
    let output = build(Path::new(MD810), &dir);
    let _ = Command::new("chattr").arg("-i").arg(&gsdml).status();
    assert_io_error(&output, &gsdml, "Operation not permitted (os error 1)");
    let stderr = stderr(&output);
    let gsd = dir.join(MD810_FILES[0]);
    assert!(
        stderr.contains(&format!("already written: {}", gsd.display())),
        "{stderr}"
    );
    assert!(stderr.contains("the other files are as they were"));
    assert_ne!(
        std::fs::read_to_string(&gsd).unwrap(),
        format!("old {}", MD810_FILES[0])
    );
    for name in &MD810_FILES[1..] {
        assert_eq!(
            std::fs::read_to_string(dir.join(name)).unwrap(),
            format!("old {name}")
        );
    }
    assert_eq!(
        names_in(&dir).len(),
        MD810_FILES.len(),
        "a temporary is left"
    );
    std::fs::remove_dir_all(dir).unwrap();
}
