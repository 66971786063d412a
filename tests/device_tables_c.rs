//! The C device tables of every description with a bus, shipped or a valid
//! fixture, against the GSD and the GSDML the same description gives:
//! `tests/c/device_tables.c` dumps a layout's tables (and uses them as a
//! slave would), in the lines `tests/firmware/device_files.rs` reads from
//! the device files without gsdc; a layout's numbering names every address
//! and reads names as gsdc's own numbering does. Compiled as C99 with gcc and as C++17 with
//! g++, every warning an error (`./scripts/test.sh` installs them: without
//! them this test fails, it does not skip).

#[path = "firmware/device_files.rs"]
mod device_files;

use crate::support;
use std::path::{Path, PathBuf};
use std::process::Command;

const WARNINGS: [&str; 7] = [
    "-Wall",
    "-Wextra",
    "-Wpedantic",
    "-Wconversion",
    "-Wsign-conversion",
    "-Wshadow",
    "-Werror",
];

/// Every description with a bus: the shipped ones and the valid fixtures.
fn descriptions() -> Vec<PathBuf> {
    let mut found: Vec<PathBuf> = ["descriptions", "tests/fixtures/valid"]
        .iter()
        .flat_map(|dir| std::fs::read_dir(support::checkout(dir)).unwrap())
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    found.sort();
    found
}

/// The file in `dir` whose name ends in `suffix`, if the build wrote one.
fn file_ending(dir: &Path, suffix: &str) -> Option<PathBuf> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .find(|p| p.to_string_lossy().ends_with(suffix))
}

/// The function a header declares that returns a table of `ty`.
fn table_function(header: &str, ty: &str) -> Option<String> {
    let head = format!("static inline const {ty} *");
    header
        .lines()
        .find_map(|l| l.strip_prefix(head.as_str()))
        .map(|rest| rest.trim_end_matches("(void)").to_string())
}

/// The lines of `output` under `[section]`, up to the next section.
fn section(output: &str, name: &str) -> Option<Vec<String>> {
    let mut lines = output.lines().skip_while(|l| *l != format!("[{name}]"));
    lines.next()?;
    Some(
        lines
            .take_while(|l| !l.starts_with('['))
            .map(str::to_string)
            .collect(),
    )
}

#[test]
fn every_c_table_says_what_its_device_files_say() {
    let source = support::checkout("tests/c/device_tables.c");
    let scratch = support::scratch("tables");
    let descriptions = descriptions();
    assert!(descriptions.len() >= 6, "{descriptions:?}");
    let mut diagnoses = 0;
    let mut numberings = 0;
    for description in descriptions {
        let stem = description
            .file_stem()
            .unwrap()
            .to_string_lossy()
            .to_string();
        let dir = scratch.join(&stem);
        std::fs::create_dir_all(&dir).unwrap();
        let written = gsdc::build::generate(&description, &dir).unwrap();
        let layout = written
            .iter()
            .find(|p| p.to_string_lossy().ends_with("_layout.h"))
            .unwrap();
        let header = std::fs::read_to_string(layout).unwrap();
        let gsd = file_ending(&dir, ".GSD");
        let gsdml = file_ending(&dir, ".xml");
        let dp = table_function(&header, "gsdc_dp_device_t");
        let pn = table_function(&header, "gsdc_pn_device_t");
        let numbering = table_function(&header, "gsdc_numbering_t");
        assert_eq!(dp.is_some(), gsd.is_some(), "{stem}: a DP table with a GSD");
        assert_eq!(
            pn.is_some(),
            gsdml.is_some(),
            "{stem}: a PN table with a GSDML"
        );
        let mut defines = vec![format!(
            "-DLAYOUT_HEADER=\"{}\"",
            layout.file_name().unwrap().to_string_lossy()
        )];
        defines.extend(dp.iter().map(|f| format!("-DDP_DEVICE={f}")));
        defines.extend(pn.iter().map(|f| format!("-DPN_DEVICE={f}")));
        defines.extend(numbering.iter().map(|f| format!("-DNUMBERING={f}")));
        let ir = gsdc::build::load_file(&description, &stem)
            .unwrap()
            .ir
            .unwrap();
        assert_eq!(numbering.is_some(), ir.numbering.is_some(), "{stem}");
        for (compiler, language) in [
            ("gcc", &["-std=c99"][..]),
            ("g++", &["-x", "c++", "-std=c++17"]),
        ] {
            let program = dir.join(format!("device_tables_{compiler}"));
            let compiled = Command::new(compiler)
                .args(language)
                .args(WARNINGS)
                .arg("-I")
                .arg(&dir)
                .args(&defines)
                .arg(&source)
                .arg("-o")
                .arg(&program)
                .output()
                .unwrap_or_else(|e| panic!("{compiler} runs: {e}"));
            assert!(
                compiled.status.success(),
                "{stem} with {compiler}:\n{}",
                String::from_utf8_lossy(&compiled.stderr)
            );
            let run = Command::new(&program).args(ODD_NAMES).output().unwrap();
            let output = String::from_utf8(run.stdout).unwrap();
            assert!(run.status.success(), "{stem} with {compiler}:\n{output}");
            if let Some(gsd) = &gsd {
                let expected = device_files::dp_lines(gsd);
                assert_eq!(
                    section(&output, "dp"),
                    Some(expected),
                    "{stem} with {compiler}"
                );
            }
            if let Some(n) = &ir.numbering {
                assert_eq!(
                    section(&output, "numbering"),
                    Some(numbering_lines(n)),
                    "{stem} with {compiler}"
                );
                numberings += 1;
            }
            // A drive's card's diagnosis areas are the GSD's.
            if let (Some(areas), Some(gsd)) = (section(&output, "dp_diagnosis"), &gsd) {
                assert_eq!(
                    areas,
                    device_files::dp_diag_lines(gsd),
                    "{stem} with {compiler}"
                );
                diagnoses += 1;
            }
            if let Some(gsdml) = &gsdml {
                let expected = device_files::pn_lines(gsdml);
                assert_eq!(
                    section(&output, "pn"),
                    Some(expected),
                    "{stem} with {compiler}"
                );
            }
        }
    }
    assert!(diagnoses >= 4, "MD810's and 9KDP1's blocks, in C and C++");
    assert!(numberings >= 8, "four numberings at least, in C and C++");
}

/// Names that are not of most numberings, each read by the C numbering as
/// gsdc reads it.
const ODD_NAMES: [&str; 20] = [
    "", "F", "P", "F0", "F0-", "-08", "Z0-08", "F0-256", "FG-01", "F0-0008", "F00-08", "f0-08",
    "F0.08", "P43-02", "P43.", "P999.99", "r43.02", "P4302", "F0-8", "F0-008",
];

/// What `device_tables.c` prints of a numbering, by gsdc's own: every
/// address it names, with the name, and how it reads [`ODD_NAMES`].
fn numbering_lines(n: &gsdc::ir::Numbering) -> Vec<String> {
    let names = (0..=u16::MAX).filter_map(|a| Some(format!("{a:04X} {}", n.format(a)?)));
    let reads = ODD_NAMES.iter().map(|name| match n.parse(name) {
        Ok(address) => format!("read {name:?} {address:04X}"),
        Err(_) => format!("read {name:?} none"),
    });
    names.chain(reads).collect()
}
