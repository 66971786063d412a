//! Writing output when the disk says no: `gsdc build` exits 2 with the path
//! and the OS error, `gsdc::build::generate` and
//! `gsdc::build::write_files` return them, and no partial, truncated
//! or temporary file is left behind; a file already there is never replaced
//! by a broken one.
//!
//! A read-only and a full file system are real tmpfs mounts, an
//! immutable file is `chattr +i`, builds in PID namespaces run under
//! `unshare`, and a build is killed in its `fsync` by `strace`: all need
//! root (CI runs as root, `scripts/test.sh` installs the tools). Where they
//! cannot run, those cases are left to the failing-disk unit tests in
//! `src/output.rs` and the kills at random times; under CI they fail.
//! Permission bits are not used: root ignores them.

use crate::support::{self, descriptions, file_names, stderr};
use gsdc::build::{write_files, Outcome};
use gsdc::{Artifact, ArtifactKind};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const MD810: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/descriptions/md810dp.toml");
/// What `gsdc build` writes for the MD810, in the order it writes them.
const MD810_FILES: [&str; 8] = [
    "MD810DP.GSD",
    "GSDML-V2.32-INOVANCE-MD810-20261122.xml",
    "MD810DP.bmp",
    "GSDML-0A11-0810-MD810.bmp",
    "md810dp_layout.rs",
    "gsdc_support.rs",
    "md810dp_layout.h",
    "gsdc_support.h",
];

/// `gsdc build <description> --out <out>`, not yet started.
fn build_command(description: &Path, out: &Path) -> Command {
    let mut command = support::gsdc_command(["build"]);
    command.arg(description).arg("--out").arg(out);
    command
}

fn build(description: &Path, out: &Path) -> Output {
    build_command(description, out).output().unwrap()
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
        file_names(dir),
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
/// process may not mount (and under CI, a failure).
struct Tmpfs(PathBuf);

impl Tmpfs {
    fn mount(dir: &Path, size: &str) -> Option<Tmpfs> {
        let options = format!("size={size}");
        let mounted = support::succeeds(
            Command::new("mount")
                .args(["-t", "tmpfs", "-o", &options, "tmpfs"])
                .arg(dir),
        );
        if !mounted {
            support::cannot_run(
                "cannot mount a tmpfs here (it takes root): the case is left to src/output.rs's unit tests",
            );
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
    let dir = support::scratch("missing");
    let out = dir.join("a/b/dist");
    let output = build(Path::new(MD810), &out);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert_eq!(file_names(&out).len(), MD810_FILES.len());

    let files = [Artifact::new(ArtifactKind::Gsd, "X.GSD", b"x".to_vec())];
    let lib_out = dir.join("c/d");
    assert_eq!(
        write_files(&lib_out, &files, false).unwrap().outcomes,
        [Outcome::Written]
    );
    assert_eq!(std::fs::read(lib_out.join("X.GSD")).unwrap(), b"x");
}

#[test]
fn an_output_directory_under_a_file_cannot_be_created() {
    let dir = support::scratch("under-file");
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
}

/// `dist/MD810DP.GSD` is a directory: the error names it, and neither it
/// nor the files that could have been written are changed.
#[test]
fn an_output_path_that_is_a_directory_changes_nothing() {
    let dir = support::scratch("is-dir");
    old_files(&dir);
    let gsd = dir.join(MD810_FILES[0]);
    std::fs::remove_file(&gsd).unwrap();
    std::fs::create_dir(&gsd).unwrap();
    std::fs::write(gsd.join("keep"), b"").unwrap();
    let output = build(Path::new(MD810), &dir);
    assert_io_error(&output, &gsd, "Is a directory (os error 21)");
    assert!(stderr(&output).contains("no file was changed"));
    assert!(file_names(&gsd) == ["keep"]);
    std::fs::remove_dir_all(&gsd).unwrap();
    std::fs::write(&gsd, format!("old {}", MD810_FILES[0])).unwrap();
    assert_untouched(&dir);
}

#[test]
fn a_description_that_is_a_symlink_loop_exits_2() {
    let dir = support::scratch("loop");
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
}

#[test]
fn a_read_only_output_directory_changes_nothing() {
    let dir = support::scratch("read-only");
    let Some(fs) = Tmpfs::mount(&dir, "1m") else {
        return;
    };
    old_files(&dir);
    fs.make_read_only();
    let output = build(Path::new(MD810), &dir);
    let first = dir.join(MD810_FILES[0]);
    assert_io_error(&output, &first, "Read-only file system (os error 30)");
    assert_untouched(&dir);
}

/// 64 KiB hold the old files and the new GSD, not the 59 KB GSDML as well.
#[test]
fn a_full_disk_changes_nothing_and_leaves_no_partial_file() {
    let dir = support::scratch("full");
    // Unmounted when the test ends, before the scratch directory goes.
    let Some(_tmpfs) = Tmpfs::mount(&dir, "64k") else {
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
}

/// The GSDML is immutable (`chattr +i`, which binds root too): its rename
/// fails after the GSD's succeeded, and the error says the GSD was written.
#[test]
fn a_failure_after_some_files_were_written_names_them() {
    let dir = support::scratch("partly");
    old_files(&dir);
    let gsdml = dir.join(MD810_FILES[1]);
    if !support::succeeds(Command::new("chattr").arg("+i").arg(&gsdml)) {
        support::cannot_run(
            "chattr +i does not work here (it takes root and e2fsprogs): the case is left to src/output.rs's unit tests",
        );
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
        file_names(&dir).len(),
        MD810_FILES.len(),
        "a temporary is left"
    );
}

/// Two versions of the MD810 description, `a/md810dp.toml` and
/// `b/md810dp.toml`: the same file names, different contents in every file
/// (each header carries the description's fingerprint).
struct TwoVersions {
    descriptions: [PathBuf; 2],
    /// Each version's files, by name.
    sets: [Vec<(String, Vec<u8>)>; 2],
}

impl TwoVersions {
    fn new(dir: &Path) -> TwoVersions {
        let text = descriptions::shipped_text("md810dp.toml");
        let versions = [
            text.clone(),
            text.replace("min_slave_interval = 1", "min_slave_interval = 2"),
        ];
        assert_ne!(versions[0], versions[1]);
        let descriptions = [0, 1].map(|i| {
            let folder = dir.join(["a", "b"][i]);
            std::fs::create_dir_all(&folder).unwrap();
            descriptions::copy_symbols(&folder);
            let path = folder.join("md810dp.toml");
            std::fs::write(&path, &versions[i]).unwrap();
            path
        });
        let sets = [0, 1].map(|i| {
            let ir = descriptions::load_text("md810dp.toml", &versions[i])
                .0
                .unwrap();
            let mut files: Vec<(String, Vec<u8>)> = gsdc::compile(&ir)
                .unwrap()
                .into_iter()
                .map(|a| (a.file_name, a.contents))
                .collect();
            files.sort();
            files
        });
        // The support files are every build's and the symbols the same
        // picture; each other file tells the versions apart.
        for ((name_a, a), (_, b)) in sets[0].iter().zip(&sets[1]) {
            if !name_a.starts_with("gsdc_support.") && !name_a.ends_with(".bmp") {
                assert_ne!(a, b, "{name_a} is the same in both versions");
            }
        }
        TwoVersions { descriptions, sets }
    }

    /// Which version `dir` holds, whole: every file of it and nothing else.
    /// Panics on a mixed set, a partial file or a file left over.
    #[track_caller]
    fn version_in(&self, dir: &Path) -> usize {
        let mut found: Vec<(String, Vec<u8>)> = file_names(dir)
            .into_iter()
            .map(|name| {
                let contents = std::fs::read(dir.join(&name)).unwrap();
                (name, contents)
            })
            .collect();
        found.sort();
        let version = self.sets.iter().position(|set| *set == found);
        version.unwrap_or_else(|| {
            let which: Vec<String> = found
                .iter()
                .map(|(name, contents)| {
                    let from = self
                        .sets
                        .iter()
                        .position(|set| set.iter().any(|(n, c)| n == name && c == contents));
                    format!("{name}: {from:?}")
                })
                .collect();
            panic!("a mixed or partial set: {which:?}")
        })
    }
}

/// An output that is a symbolic link to a file elsewhere is replaced by a
/// regular file; the file it pointed to is not written. A link placed
/// where a killed build's temporary would be is removed, not followed.
#[test]
fn symbolic_links_in_the_output_directory_are_never_written_through() {
    let dir = support::scratch("symlink");
    let out = dir.join("out");
    std::fs::create_dir_all(&out).unwrap();
    let victim = dir.join("victim");
    std::fs::write(&victim, "not gsdc's").unwrap();
    std::os::unix::fs::symlink(&victim, out.join(MD810_FILES[0])).unwrap();
    let planted = out.join(format!(".{}.gsdc-1-0000000000000001.tmp", MD810_FILES[1]));
    std::os::unix::fs::symlink(&victim, &planted).unwrap();

    let output = build(Path::new(MD810), &out);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), "not gsdc's");
    let gsd = std::fs::symlink_metadata(out.join(MD810_FILES[0])).unwrap();
    assert!(
        gsd.file_type().is_file(),
        "the output is a file, not a link"
    );
    assert!(
        stderr(&output).contains(&format!(
            "removed {}, left by a gsdc build that was interrupted",
            planted.display()
        )),
        "{}",
        stderr(&output)
    );
    let mut expected = MD810_FILES.map(String::from).to_vec();
    expected.sort();
    assert_eq!(file_names(&out), expected);
}

#[test]
fn a_replaced_file_keeps_its_mode() {
    use std::os::unix::fs::PermissionsExt;
    let dir = support::scratch("mode");
    old_files(&dir);
    let gsd = dir.join(MD810_FILES[0]);
    std::fs::set_permissions(&gsd, std::fs::Permissions::from_mode(0o600)).unwrap();
    let output = build(Path::new(MD810), &dir);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert_ne!(std::fs::read_to_string(&gsd).unwrap(), "old MD810DP.GSD");
    let mode = std::fs::metadata(&gsd).unwrap().permissions().mode();
    assert_eq!(mode & 0o777, 0o600);
}

/// A build into a directory another holds waits for it: while this test
/// holds the lock (`flock`, as gsdc takes it), gsdc changes nothing; once
/// it is released, gsdc writes.
#[test]
fn a_build_waits_for_the_directory_another_build_holds() {
    let dir = support::scratch("lock");
    let versions = TwoVersions::new(&dir);
    let out = dir.join("out");
    assert_eq!(
        build(&versions.descriptions[0], &out).status.code(),
        Some(0)
    );
    let held = std::fs::File::open(&out).unwrap();
    held.lock().unwrap();
    let mut waiting = build_command(&versions.descriptions[1], &out)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    std::thread::sleep(std::time::Duration::from_millis(500));
    assert!(waiting.try_wait().unwrap().is_none(), "gsdc did not wait");
    assert_eq!(versions.version_in(&out), 0, "nothing changed while held");
    held.unlock().unwrap();
    assert!(waiting.wait().unwrap().success());
    assert_eq!(versions.version_in(&out), 1);
}

/// Two builds of the two versions into one directory at once, 25 times:
/// each time the directory holds one version whole. With `unshare` (PID
/// namespaces, as containers sharing a volume have) both builds run as
/// process 1, 25 times more.
#[test]
fn concurrent_builds_of_different_descriptions_never_mix_their_files() {
    let dir = support::scratch("concurrent");
    let versions = TwoVersions::new(&dir);
    let out = dir.join("out");
    let gsdc = support::GSDC;
    let unshared = support::succeeds(Command::new("unshare").args(["--pid", "--fork", "true"]));
    if !unshared {
        support::cannot_run(
            "unshare --pid does not work here (it takes root): the builds run without PID namespaces only",
        );
    }
    let wrappers: &[&[&str]] = if unshared {
        &[&[], &["unshare", "--pid", "--fork"]]
    } else {
        &[&[]]
    };
    let mut seen = [0, 0];
    for wrapper in wrappers {
        for _ in 0..25 {
            let children: Vec<_> = versions
                .descriptions
                .iter()
                .map(|description| {
                    let mut command = match wrapper.split_first() {
                        Some((program, args)) => {
                            let mut c = Command::new(program);
                            c.args(args).arg(gsdc);
                            c
                        }
                        None => Command::new(gsdc),
                    };
                    command
                        .arg("build")
                        .arg(description)
                        .arg("--out")
                        .arg(&out)
                        .stdout(std::process::Stdio::null())
                        .stderr(std::process::Stdio::piped())
                        .spawn()
                        .unwrap()
                })
                .collect();
            for child in children {
                let output = child.wait_with_output().unwrap();
                assert!(output.status.success(), "{}", stderr(&output));
                assert!(
                    !stderr(&output).contains("interrupted"),
                    "one build took the other's temporaries for leftovers: {}",
                    stderr(&output)
                );
            }
            seen[versions.version_in(&out)] += 1;
        }
    }
    eprintln!(
        "the directory held version a {} and b {} times",
        seen[0], seen[1]
    );
}

/// A build killed in the middle of an `fsync` (strace injects SIGKILL into
/// the second one: the GSD's temporary is complete, the GSDML's being
/// synced) leaves its temporaries and the old files; the next build removes
/// the temporaries, says so, and writes its set whole.
#[test]
fn a_build_killed_while_syncing_leaves_temporaries_the_next_build_removes() {
    let dir = support::scratch("killed");
    let versions = TwoVersions::new(&dir);
    let out = dir.join("out");
    assert_eq!(
        build(&versions.descriptions[0], &out).status.code(),
        Some(0)
    );
    let killed = Command::new("strace")
        .args(["-f", "-qq", "-o", "/dev/null", "-e", "trace=fsync"])
        .args(["-e", "inject=fsync:signal=KILL:when=2"])
        .arg(support::GSDC)
        .arg("build")
        .arg(&versions.descriptions[1])
        .arg("--out")
        .arg(&out)
        .output();
    // strace dies of the signal its process died of.
    let killed_by_sigkill = |o: &Output| {
        use std::os::unix::process::ExitStatusExt;
        o.status.signal() == Some(9) || o.status.code() == Some(128 + 9)
    };
    let Some(killed) = killed.ok().filter(killed_by_sigkill) else {
        support::cannot_run(
            "strace cannot inject a SIGKILL here (it needs strace and ptrace): the case is left to the kills at random times",
        );
        return;
    };
    let leftovers: Vec<String> = file_names(&out)
        .into_iter()
        .filter(|name| name.contains(".gsdc-"))
        .collect();
    assert_eq!(
        leftovers.len(),
        2,
        "{:?}: {}",
        file_names(&out),
        stderr(&killed)
    );
    let after = build(&versions.descriptions[1], &out);
    assert_eq!(after.status.code(), Some(0), "{}", stderr(&after));
    for leftover in &leftovers {
        let named = format!(
            "removed {}, left by a gsdc build that was interrupted",
            out.join(leftover).display()
        );
        assert!(stderr(&after).contains(&named), "{}", stderr(&after));
    }
    assert_eq!(versions.version_in(&out), 1);
}

/// Builds killed at random times, 40 of them, alternating the two
/// versions: after each, every output file is one version's whole file
/// (never a partial one), and after a build that finishes the directory
/// holds its version whole and no temporary.
#[test]
fn builds_killed_at_random_times_never_leave_a_partial_file() {
    let dir = support::scratch("random-kills");
    let versions = TwoVersions::new(&dir);
    let out = dir.join("out");
    assert_eq!(
        build(&versions.descriptions[0], &out).status.code(),
        Some(0)
    );
    let started = std::time::Instant::now();
    assert_eq!(
        build(&versions.descriptions[1], &out).status.code(),
        Some(0)
    );
    let duration = started.elapsed();
    let mut state = 0x9E37_79B9_7F4A_7C15_u64;
    let mut left = 0;
    for round in 0..40 {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        let delay = duration.mul_f64((state % 1000) as f64 / 1000.0);
        let mut child = build_command(&versions.descriptions[round % 2], &out)
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap();
        std::thread::sleep(delay);
        let _ = child.kill();
        let _ = child.wait();
        for name in file_names(&out) {
            let contents = std::fs::read(out.join(&name)).unwrap();
            if name.contains(".gsdc-") {
                left += 1;
                continue; // a temporary may be partial: nobody reads it
            }
            assert!(
                versions
                    .sets
                    .iter()
                    .flatten()
                    .any(|(n, c)| *n == name && *c == contents),
                "{name} is no version's whole file after round {round}"
            );
        }
    }
    eprintln!("40 kills left {left} temporaries");
    assert_eq!(
        build(&versions.descriptions[0], &out).status.code(),
        Some(0)
    );
    assert_eq!(versions.version_in(&out), 0);
}
