//! The build-script API (`gsdc::build`): the same steps as `gsdc build`,
//! its options (deny warnings, the PI schema), and an error that says what
//! went wrong in a form a program can match.

use crate::support::xsd::{pi_schema, refusing_schema};
use crate::support::{self, stderr};
use gsdc::build::{BuildError, Config};
use std::error::Error;
use std::path::PathBuf;

fn description(name: &str) -> PathBuf {
    support::checkout("descriptions").join(name)
}

#[test]
fn deny_warnings_refuses_the_placeholders_with_their_diagnostics() {
    let out = support::scratch("deny");
    let md810 = description("md810dp.toml");
    let e = Config::new()
        .deny_warnings(true)
        .generate(&md810, &out)
        .unwrap_err();
    let BuildError::Description { path, findings, .. } = &e else {
        panic!("{e:?}");
    };
    assert_eq!(path, &md810);
    assert!(findings[0].diagnostics.iter().any(|d| d.code == "W101"));
    let rendered = e.to_string();
    assert!(rendered.contains("warning[W101]"), "{rendered}");
    let text = std::fs::read_to_string(&md810).unwrap();
    let line = 1 + text[..text.find("ident_number = {").unwrap()]
        .matches('\n')
        .count();
    assert!(
        rendered.contains(&format!("md810dp.toml:{line}:16")),
        "{rendered}"
    );
    assert!(rendered.ends_with("the description has warnings, and they are denied"));
    assert!(e.source().is_none());
    assert_eq!(std::fs::read_dir(&out).unwrap().count(), 0);

    let paths = Config::new().generate(&md810, &out).unwrap();
    assert_eq!(
        paths.len(),
        8,
        "device files, their symbols, both layouts and their support files"
    );
    assert!(paths.iter().all(|p| p.is_file()));
}

#[test]
fn errors_say_which_file_and_what_went_wrong() {
    let dir = support::scratch("errors");
    let missing = dir.join("missing.toml");
    match gsdc::build::generate(&missing, &dir) {
        Err(BuildError::Read { path, error }) => {
            assert_eq!(path, missing);
            assert_eq!(error.kind(), std::io::ErrorKind::NotFound);
        }
        other => panic!("{other:?}"),
    }
    let e = gsdc::build::generate(&missing, &dir).unwrap_err();
    assert!(e
        .to_string()
        .starts_with(&format!("cannot read {}", missing.display())));
    assert!(e.source().is_some(), "the OS error is the source");

    std::fs::write(dir.join("file"), b"").unwrap();
    let under_a_file = dir.join("file/out");
    match gsdc::build::generate(description("md810dp.toml"), &under_a_file) {
        Err(BuildError::Write(e)) => {
            assert_eq!(e.path, under_a_file);
            assert_eq!(e.error.raw_os_error(), Some(20)); // ENOTDIR
        }
        other => panic!("{other:?}"),
    }

    let invalid = support::checkout("tests/fixtures/invalid/unknown_ppo.toml");
    let e = gsdc::build::generate_rust(&invalid, &dir).unwrap_err();
    let BuildError::Description { path, findings, .. } = &e else {
        panic!("{e:?}");
    };
    assert_eq!(path, &invalid);
    assert!(findings[0].diagnostics.iter().any(|d| d.code == "E104"));
    assert!(e.to_string().contains("error[E104]"), "{e}");

    let no_schema = Config::new()
        .xsd(dir.join("no-schema"))
        .generate(description("md810dp.toml"), &dir);
    assert!(
        matches!(&no_schema, Err(BuildError::Schema { dir: d, .. }) if *d == dir.join("no-schema")),
        "{no_schema:?}"
    );
}

/// One pipeline: the build script's error holds, line for line, the
/// diagnostics `gsdc build` prints for the same description.
#[test]
fn the_build_script_reports_what_gsdc_build_reports() {
    let invalid = support::checkout("tests/fixtures/invalid/unknown_ppo.toml");
    let dir = support::scratch("same");
    let cli = support::gsdc_command(["build"])
        .arg(&invalid)
        .arg("--out")
        .arg(&dir)
        .output()
        .unwrap();
    assert_eq!(cli.status.code(), Some(1));
    let printed = stderr(&cli);
    let from_cli: Vec<&str> = printed
        .lines()
        .filter(|l| !l.is_empty() && !l.starts_with("nothing written"))
        .collect();
    let e = gsdc::build::generate(&invalid, &dir).unwrap_err();
    let rendered = e.to_string();
    let from_api: Vec<&str> = rendered
        .lines()
        .filter(|l| !l.is_empty() && !l.starts_with("nothing written"))
        .collect();
    assert!(from_cli.len() > 5, "{printed}");
    assert_eq!(from_api, from_cli);
}

/// A build script's `generate` with a schema the GSDML breaks writes
/// nothing; `generate_rust` writes no GSDML, so validates none.
#[test]
fn a_build_script_with_a_schema_refuses_the_gsdml_but_not_the_layout() {
    let dir = support::scratch("schema");
    let refusing = refusing_schema(&dir);
    let out = dir.join("out");
    let mv810 = description("mv810-pnet02.toml");
    let e = Config::new()
        .xsd(&refusing)
        .generate(&mv810, &out)
        .unwrap_err();
    assert!(e.to_string().contains("error[E399]"), "{e}");
    assert!(!out.exists());
    let layout = Config::new()
        .xsd(&refusing)
        .generate_layout(&mv810, &out, gsdc::Language::Rust)
        .unwrap();
    assert_eq!(layout, out.join("mv810_pnet02_layout.rs"));
    // The language asked for, whatever the configuration's firmware says.
    let header = Config::new()
        .firmware(&[gsdc::Language::Rust])
        .generate_layout(&mv810, &out, gsdc::Language::C)
        .unwrap();
    assert_eq!(header, out.join("mv810_pnet02_layout.h"));
    let passed = Config::new()
        .xsd(pi_schema())
        .generate(&mv810, &out)
        .unwrap();
    assert_eq!(
        passed.len(),
        6,
        "the GSDML, its symbol, both layouts and their support files"
    );
}
