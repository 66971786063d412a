//! Generates every shipped description's files, and the PROFIdrive
//! fixture's, into OUT_DIR with gsdc's build-script API, as a firmware crate
//! would; and, for tests/numbering.rs, how gsdc itself names every address
//! and reads a few odd names, for each description that numbers its drive's
//! parameters (`<stem>.numbering`).

use std::fmt::Write as _;
use std::path::Path;

const DESCRIPTIONS: [&str; 5] = [
    "descriptions/md810dp.toml",
    "descriptions/mv810-pnet02.toml",
    "descriptions/9kdp1.toml",
    "descriptions/md810-gateway.toml",
    "tests/fixtures/valid/profidrive.toml",
];

/// Names that are not of most numberings: tests/numbering.rs reads each
/// with the layout's numbering, which must read it as gsdc does.
const ODD_NAMES: [&str; 20] = [
    "", "F", "P", "F0", "F0-", "-08", "Z0-08", "F0-256", "FG-01", "F0-0008", "F00-08", "f0-08",
    "F0.08", "P43-02", "P43.", "P999.99", "r43.02", "P4302", "F0-8", "F0-008",
];

fn main() {
    let out_dir = std::env::var("OUT_DIR").expect("cargo sets OUT_DIR");
    let checkout = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    for description in DESCRIPTIONS {
        let path = checkout.join(description);
        gsdc::build::generate(&path, &out_dir).unwrap_or_else(|e| panic!("{e}"));
        let loaded = gsdc::build::load_file(&path, description).unwrap_or_else(|e| panic!("{e}"));
        let ir = loaded.ir.expect("a shipped description has no errors");
        if let Some(numbering) = &ir.numbering {
            let stem = path.file_stem().unwrap().to_string_lossy();
            let file = Path::new(&out_dir).join(format!("{stem}.numbering"));
            std::fs::write(&file, numbering_lines(numbering)).unwrap();
        }
    }
}

/// `A F008 F0-08` for every address gsdc names, then `R "F0-8" none` (or
/// the address) for each of [`ODD_NAMES`] as gsdc reads it.
fn numbering_lines(numbering: &gsdc::ir::Numbering) -> String {
    let mut text = String::new();
    for address in 0..=u16::MAX {
        if let Some(name) = numbering.format(address) {
            writeln!(text, "A {address:04X} {name}").unwrap();
        }
    }
    for name in ODD_NAMES {
        match numbering.parse(name) {
            Ok(address) => writeln!(text, "R {name:?} {address:04X}").unwrap(),
            Err(_) => writeln!(text, "R {name:?} none").unwrap(),
        }
    }
    text
}
