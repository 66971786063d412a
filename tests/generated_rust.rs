//! The firmware layouts gsdc writes for the shipped descriptions: snapshots
//! reviewed against the manuals, formatted as rustfmt formats them, and
//! compiled, linted and run in the no_std crate `tests/firmware`.

#[path = "common/descriptions.rs"]
mod descriptions;
use descriptions::load;

use std::path::{Path, PathBuf};
use std::process::Command;

use descriptions::SHIPPED as DESCRIPTIONS;

/// The artifact of a shipped description whose name ends in `suffix`: its
/// file name and text.
fn artifact(name: &str, suffix: &str) -> (String, String) {
    let artifacts = gsdc::compile(&load(name)).unwrap();
    let found = artifacts
        .into_iter()
        .find(|a| a.file_name.ends_with(suffix))
        .unwrap_or_else(|| panic!("{name}: no artifact ending in {suffix}"));
    (found.file_name, String::from_utf8(found.contents).unwrap())
}

fn layout(name: &str) -> (String, String) {
    artifact(name, "_layout.rs")
}

/// Every description gives the same support module, with every part
/// inlined once as a module of its own.
#[test]
fn the_support_module_is_one_for_all_and_inlines_its_parts() {
    let support = artifact(DESCRIPTIONS[0], "gsdc_support.rs");
    for name in &DESCRIPTIONS[1..] {
        assert_eq!(artifact(name, "gsdc_support.rs"), support, "{name}");
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

/// A directory of this test's own under the target directory.
fn scratch_dir(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn md810dp_layout_snapshot() {
    insta::assert_snapshot!("md810dp_layout.rs", layout("md810dp.toml").1);
}

#[test]
fn mv810_pnet02_layout_snapshot() {
    insta::assert_snapshot!("mv810_pnet02_layout.rs", layout("mv810-pnet02.toml").1);
}

#[test]
fn powtran_9kdp1_layout_snapshot() {
    insta::assert_snapshot!("9kdp1_layout.rs", layout("9kdp1.toml").1);
}

#[test]
fn md810_gateway_layout_snapshot() {
    insta::assert_snapshot!("md810_gateway_layout.rs", layout("md810-gateway.toml").1);
}

/// Each layout is exactly what rustfmt makes of it. The files are checked
/// in a directory of their own, so no rustfmt.toml of the project applies.
#[test]
fn layouts_are_formatted_as_rustfmt_formats_them() {
    let dir = scratch_dir("rustfmt-check");
    let support = artifact(DESCRIPTIONS[0], "gsdc_support.rs");
    // Every shipped description's layout and every valid fixture's (the
    // PROFIdrive card's among them), and the support module.
    let layouts = descriptions::all_valid().into_iter().map(|(_, ir)| {
        let file = gsdc::compile(&ir)
            .unwrap()
            .into_iter()
            .find(|a| a.kind == gsdc::ArtifactKind::RustLayout)
            .unwrap();
        (file.file_name, String::from_utf8(file.contents).unwrap())
    });
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

/// `cargo test` and `cargo clippy -- -D warnings` in `tests/firmware`, whose
/// build script generates every layout with gsdc's build-script API: every
/// test of the crate runs and passes, and the build script asks cargo to run
/// it again when a description or a symbol it names changes.
#[test]
fn layouts_compile_in_a_no_std_crate_and_round_trip_the_manuals_examples() {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/firmware");
    let target_dir = scratch_dir("firmware-target");
    for args in [
        &["test", "--quiet"][..],
        &["clippy", "--quiet", "--all-targets", "--", "-D", "warnings"],
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
    let descriptions = Path::new(env!("CARGO_MANIFEST_DIR")).join("descriptions");
    for name in DESCRIPTIONS {
        assert!(
            reruns.contains(&format!("descriptions/{name}\n")),
            "{reruns}"
        );
        let text = std::fs::read_to_string(descriptions.join(name)).unwrap();
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
