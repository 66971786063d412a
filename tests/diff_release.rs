//! Release discipline in the build: `gsdc build --released DIR` (and
//! `Config::released`) judges each GSD and GSDML against the last
//! release's files. A GSDML changed under its released name and a GSD
//! changed under its released Revision refuse the build; a breaking change
//! under the released ident number is a warning; a change no file carries
//! is none. Real processes and files, in a directory of their own.

use std::path::{Path, PathBuf};
use std::process::Output;

use crate::support::{self, descriptions, stderr};

/// A directory with a copy of one shipped description (and the symbols),
/// the release built from it, and room for builds.
struct Workspace {
    dir: support::Scratch,
    description: PathBuf,
}

impl Workspace {
    fn new(test: &str, description: &str) -> Workspace {
        let dir = support::scratch(test);
        descriptions::copy_symbols(&dir);
        let path = dir.join(description);
        std::fs::write(&path, descriptions::shipped_text(description)).unwrap();
        let workspace = Workspace {
            dir,
            description: path,
        };
        let release = workspace.build(&["--out", workspace.path("release").to_str().unwrap()]);
        assert!(release.status.success(), "{}", stderr(&release));
        workspace
    }

    fn path(&self, name: &str) -> PathBuf {
        self.dir.join(name)
    }

    /// Replaces the one place of `from` in the description.
    fn edit(&self, from: &str, to: &str) {
        let text = std::fs::read_to_string(&self.description).unwrap();
        assert_eq!(text.matches(from).count(), 1, "`{from}`");
        std::fs::write(&self.description, text.replacen(from, to, 1)).unwrap();
    }

    /// `gsdc build DESCRIPTION --firmware none ARGS`.
    fn build(&self, args: &[&str]) -> Output {
        support::gsdc_command(["build"])
            .arg(&self.description)
            .args(["--firmware", "none"])
            .args(args)
            .output()
            .expect("gsdc runs")
    }

    /// A build into `dist` against the release.
    fn against_release(&self, extra: &[&str]) -> Output {
        let (out, released) = (self.path("dist"), self.path("release"));
        let mut args = vec![
            "--out",
            out.to_str().unwrap(),
            "--released",
            released.to_str().unwrap(),
        ];
        args.extend(extra);
        self.build(&args)
    }
}

/// The release codes among a build's findings.
fn release_codes(out: &Output) -> Vec<String> {
    stderr(out)
        .lines()
        .filter_map(|l| {
            let code = l.strip_prefix("error[").or(l.strip_prefix("warning["))?;
            let code = &code[..4];
            code[1..].starts_with('5').then(|| code.to_string())
        })
        .collect()
}

#[test]
fn an_unchanged_build_passes_and_writes() {
    let w = Workspace::new("unchanged", "md810dp.toml");
    let out = w.against_release(&[]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(release_codes(&out), Vec::<String>::new());
    assert!(w.path("dist/MD810DP.GSD").is_file());
}

/// A comment and a reason are in no file's content (the reason is in each
/// header, which is a comment): no bump needed.
#[test]
fn a_comment_or_a_reason_needs_no_bump() {
    let w = Workspace::new("comment", "md810dp.toml");
    w.edit(
        "# 1.3.1: MD810 supports PPO1..PPO5",
        "# 1.3.1 says MD810 supports PPO1..PPO5",
    );
    w.edit(
        "the card must detect the rate\"",
        "the card detects the rate\"",
    );
    let out = w.against_release(&[]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(release_codes(&out), Vec::<String>::new());
}

#[test]
fn a_gsdml_changed_under_its_name_is_refused_until_its_date_changes() {
    let w = Workspace::new("gsdml", "md810dp.toml");
    // A record's name: a text, cosmetic, but TIA would never show it.
    w.edit(
        "name = { en = \"PZD function codes, controller to drive\"",
        "name = { en = \"PZD function codes, PLC to drive\"",
    );
    let out = w.against_release(&[]);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert_eq!(release_codes(&out), ["E501"]);
    let err = stderr(&out);
    assert!(err.contains("error[E501]: GSDML-V2.32-INOVANCE-MD810-20261122.xml differs from the released file of that name: 1 change(s), record 256"), "{err}");
    assert!(
        err.contains("date = 2026-11-22\n    |        ^^^^^^^^^^ the released file's date"),
        "{err}"
    );
    assert!(
        err.contains("help: TIA Portal keeps a GSDML it installed under this name"),
        "{err}"
    );
    assert!(!w.path("dist").exists(), "nothing written");
    // The same refusal in --check.
    let out = w.against_release(&["--check"]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(release_codes(&out), ["E501"]);

    // A second release on the same day: a date and time.
    w.edit("date = 2026-11-22", "date = 2026-11-22T14:30:00");
    let out = w.against_release(&[]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(release_codes(&out), Vec::<String>::new());
    assert!(w
        .path("dist/GSDML-V2.32-INOVANCE-MD810-20261122-143000.xml")
        .is_file());
}

#[test]
fn a_gsd_changed_under_its_revision_is_refused_until_it_is_bumped() {
    let w = Workspace::new("gsd", "md810dp.toml");
    w.edit("\"1.5M\" = 150", "\"1.5M\" = 200");
    let out = w.against_release(&[]);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    // Raising MaxTsdr breaks projects with tight bus timing, under the same
    // ident number: a warning beside the error.
    assert_eq!(release_codes(&out), ["E502", "W503"]);
    let err = stderr(&out);
    assert!(err.contains("MaxTsdr_1.5M: \"150\" → \"200\""), "{err}");
    assert!(
        err.contains("revision = \"V1.00\"\n   |            ^^^^^^^ the released file's revision"),
        "{err}"
    );

    w.edit("revision = \"V1.00\"", "revision = \"V1.01\"");
    let out = w.against_release(&[]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(release_codes(&out), ["W503"]);
    assert!(
        stderr(&out).contains("the released file's ident number"),
        "{}",
        stderr(&out)
    );
    let out = w.against_release(&["--deny-warnings"]);
    assert_eq!(out.status.code(), Some(1));
}

/// A GSDML under a new date is compared with the newest release of its
/// family: a breaking change there is a warning, a compatible one nothing.
#[test]
fn a_new_gsdml_is_compared_with_the_last_release_of_its_family() {
    let w = Workspace::new("family", "mv810-pnet02.toml");
    w.edit("date = 2023-08-30", "date = 2023-09-01");
    w.edit("min_device_interval = 32", "min_device_interval = 64");
    let out = w.against_release(&[]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(release_codes(&out), ["W503"]);
    let err = stderr(&out);
    assert!(err.contains("warning[W503]: GSDML-V2.32-MEGMEET-MV800-20230901.xml breaks PLC projects configured with the released GSDML-V2.32-MEGMEET-MV800-20230830.xml under the same vendor and device ID"), "{err}");
    assert!(err.contains("MinDeviceInterval: \"32\" → \"64\""), "{err}");
}

#[test]
fn a_missing_release_directory_is_a_usage_error() {
    let w = Workspace::new("missing", "9kdp1.toml");
    let out = w.build(&[
        "--out",
        w.path("dist").to_str().unwrap(),
        "--released",
        w.path("nowhere").to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).starts_with("error: --released: cannot read the released files in"),
        "{}",
        stderr(&out)
    );
}

/// Build scripts get the same through `Config::released`.
#[test]
fn build_scripts_are_refused_alike() {
    let w = Workspace::new("api", "md810dp.toml");
    w.edit("\"12M\" = 800", "\"12M\" = 900");
    let result = gsdc::build::Config::new()
        .firmware(&[])
        .released(w.path("release"))
        .generate(&w.description, w.path("dist"));
    match result {
        Err(gsdc::build::BuildError::Description { findings, .. }) => {
            let codes: Vec<&str> = findings
                .iter()
                .flat_map(|f| f.diagnostics.iter())
                .map(|d| d.code)
                .filter(|code| code[1..].starts_with('5'))
                .collect();
            assert_eq!(codes, ["E502", "W503"]);
        }
        other => panic!("{other:?}"),
    }
    let result = gsdc::build::Config::new()
        .released(w.path("nowhere"))
        .generate(&w.description, w.path("dist"));
    assert!(
        matches!(result, Err(gsdc::build::BuildError::Released { .. })),
        "{result:?}"
    );
    assert!(!Path::new(&w.path("dist")).exists());
}
