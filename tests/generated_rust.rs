//! The firmware layouts gsdc writes for the shipped descriptions (their
//! snapshots, reviewed against the manuals, are in outputs.rs): formatted
//! as rustfmt formats them, and compiled, linted and run in the no_std
//! crate `tests/firmware`.

use crate::support::{self, descriptions};
use gsdc::ArtifactKind;
use std::path::Path;
use std::process::Command;

/// The file of `kind` a shipped description gives: its name and text.
fn artifact(name: &str, kind: ArtifactKind) -> (String, String) {
    descriptions::one(gsdc::compile(&descriptions::load(name)).unwrap(), kind)
}

/// Every description gives the same support module, with every part
/// inlined once as a module of its own.
#[test]
fn the_support_module_is_one_for_all_and_inlines_its_parts() {
    let shipped = descriptions::shipped();
    let support = artifact(&shipped[0], ArtifactKind::RustSupport);
    assert_eq!(support.0, "gsdc_support.rs");
    for name in &shipped[1..] {
        assert_eq!(artifact(name, ArtifactKind::RustSupport), support, "{name}");
    }
    let text = support.1;
    for part in [
        "pkw_pke_ind_pwe",
        "pkw_station_command",
        "diagnosis",
        "gateway",
    ] {
        assert_eq!(
            text.matches(&format!("pub mod {part} {{")).count(),
            1,
            "{part}"
        );
        assert!(!text.contains(&format!("pub mod {part};")), "{part}");
    }
    assert!(text.contains("pub struct PkwTelegram<const PZD: usize, const BYTES: usize>"));
}

/// Each layout is exactly what rustfmt makes of it. The files are checked
/// in a directory of their own, so no rustfmt.toml of the project applies.
#[test]
fn layouts_are_formatted_as_rustfmt_formats_them() {
    let dir = support::scratch("rustfmt-check");
    let support = artifact(&descriptions::shipped()[0], ArtifactKind::RustSupport);
    // Every shipped description's layout and every valid fixture's (the
    // PROFIdrive card's among them), and the support module.
    let layouts = descriptions::all_valid()
        .into_iter()
        .map(|(_, ir)| descriptions::one(gsdc::compile(&ir).unwrap(), ArtifactKind::RustLayout));
    for (file_name, text) in layouts.chain([support]) {
        let path = dir.join(&file_name);
        std::fs::write(&path, text).unwrap();
        let output = Command::new("rustfmt")
            .args(["--check", "--edition", "2021"])
            .arg(&path)
            .output()
            .expect("rustfmt runs");
        assert!(
            output.status.success(),
            "{file_name} is not formatted as rustfmt formats it:\n{}{}",
            String::from_utf8_lossy(&output.stdout),
            String::from_utf8_lossy(&output.stderr)
        );
    }
}

/// `cargo test`, `cargo clippy -- -D warnings` and `cargo doc` in
/// `tests/firmware`, whose build script generates every layout with gsdc's
/// build-script API: every test of the crate runs and passes, every
/// intra-doc link of the layouts' docs resolves (the crate denies warnings,
/// rustdoc's among them), and the build script asks cargo to run it again
/// when a description or a symbol it names changes.
#[test]
fn layouts_compile_in_a_no_std_crate_and_round_trip_the_manuals_examples() {
    let crate_dir = support::checkout("tests/firmware");
    // Kept from run to run, as a target directory is: cargo rebuilds what
    // changed.
    let target_dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("firmware-target");
    for args in [
        &["test", "--quiet"][..],
        &["clippy", "--quiet", "--all-targets", "--", "-D", "warnings"],
        &["doc", "--quiet", "--no-deps"],
    ] {
        let output = Command::new(env!("CARGO"))
            .args(args)
            .current_dir(&crate_dir)
            .env("CARGO_TARGET_DIR", &target_dir)
            .output()
            .expect("cargo runs");
        assert!(
            output.status.success(),
            "cargo {} in tests/firmware failed:\n{}{}",
            args.join(" "),
            String::from_utf8_lossy(&output.stdout),
            String::from_utf8_lossy(&output.stderr)
        );
        if args[0] == "test" {
            let stdout = String::from_utf8(output.stdout).unwrap();
            assert_eq!(
                passed(&stdout),
                tests_in(&crate_dir.join("tests")),
                "{stdout}"
            );
        }
    }
    let reruns = build_script_output(&target_dir);
    for name in descriptions::shipped() {
        assert!(
            reruns.contains(&format!("descriptions/{name}\n")),
            "{reruns}"
        );
        let text = descriptions::shipped_text(&name);
        let symbol = text
            .lines()
            .find_map(|l| l.strip_prefix("symbol = \""))
            .expect("every shipped description names its symbol")
            .trim_end_matches('"');
        assert!(
            reruns.contains(&format!("descriptions/{symbol}\n")),
            "{reruns}"
        );
    }
}

/// The sum of the `N passed` of libtest's summaries.
fn passed(stdout: &str) -> usize {
    stdout
        .lines()
        .filter_map(|l| l.strip_prefix("test result: ok. "))
        .map(|rest| rest.split(' ').next().unwrap().parse::<usize>().unwrap())
        .sum()
}

/// The `#[test]` functions in the files of `dir`.
fn tests_in(dir: &Path) -> usize {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| std::fs::read_to_string(e.unwrap().path()).unwrap())
        .map(|text| text.matches("#[test]").count())
        .sum()
}

/// The `cargo:` lines the firmware crate's build script printed.
fn build_script_output(target_dir: &Path) -> String {
    let build = target_dir.join("debug/build");
    std::fs::read_dir(&build)
        .unwrap()
        .map(|e| e.unwrap().path().join("output"))
        .filter(|p| p.to_string_lossy().contains("gsdc-firmware-check-") && p.exists())
        .map(|p| std::fs::read_to_string(p).unwrap())
        .collect()
}
