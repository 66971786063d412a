//! Generates every shipped description's files, and two fixtures' (a
//! PROFIdrive card, and one with ident numbers and records of its own), into OUT_DIR with gsdc's build-script API, as a firmware crate
//! would; `examples.rs`, the manuals' worked examples each description
//! gives (`[[examples]]`), for tests/manuals.rs to round-trip through the
//! layouts; and, for tests/numbering.rs, how gsdc itself names every address
//! and reads a few odd names, for each description that numbers its drive's
//! parameters (`<stem>.numbering`).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

const DESCRIPTIONS: [&str; 4] = [
    "md810dp.toml",
    "mv810-pnet02.toml",
    "9kdp1.toml",
    "md810-gateway.toml",
];

/// The PROFIdrive card, and the card whose ident numbers and records are
/// its own (an imported file's).
const FIXTURES: [&str; 2] = ["profidrive.toml", "own_idents.toml"];

fn main() {
    let out_dir = std::env::var("OUT_DIR").expect("cargo sets OUT_DIR");
    let descriptions = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../descriptions");
    let fixtures = Path::new(env!("CARGO_MANIFEST_DIR")).join("../fixtures/valid");
    let paths: Vec<PathBuf> = DESCRIPTIONS
        .iter()
        .map(|name| descriptions.join(name))
        .chain(FIXTURES.iter().map(|name| fixtures.join(name)))
        .collect();
    remove_device_files(Path::new(&out_dir));
    let mut examples = String::from(EXAMPLE_TYPE);
    for path in &paths {
        gsdc::build::generate(path, &out_dir).unwrap_or_else(|e| panic!("{e}"));
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        let loaded = gsdc::build::load_file(path, &name).unwrap_or_else(|e| panic!("{e}"));
        let ir = loaded.ir.expect("the description loads");
        examples.push_str(&examples_of(&name, &ir));
        if let Some(numbering) = &ir.numbering {
            let stem = name.trim_end_matches(".toml");
            let file = Path::new(&out_dir).join(format!("{stem}.numbering"));
            std::fs::write(file, numbering_lines(numbering)).expect("OUT_DIR is writable");
        }
    }
    std::fs::write(Path::new(&out_dir).join("examples.rs"), examples).expect("OUT_DIR is writable");
}

/// The GSD and GSDML files of an earlier build: a device file's name holds
/// the description's version and date, so a changed one would leave the old
/// file beside the new in OUT_DIR, which cargo keeps between builds, and
/// tests/device_tables.rs reads every device file there.
fn remove_device_files(out_dir: &Path) {
    let Ok(entries) = std::fs::read_dir(out_dir) else {
        return;
    };
    for path in entries.map(|e| e.expect("OUT_DIR is readable").path()) {
        let extension = path.extension().map(|e| e.to_ascii_lowercase());
        if matches!(extension.as_ref().and_then(|e| e.to_str()), Some("xml" | "gsd")) {
            std::fs::remove_file(&path).expect("OUT_DIR is writable");
        }
    }
}

/// Names that are not of most numberings: tests/numbering.rs reads each
/// with the layout's numbering, which must read it as gsdc does.
const ODD_NAMES: [&str; 20] = [
    "", "F", "P", "F0", "F0-", "-08", "Z0-08", "F0-256", "FG-01", "F0-0008", "F00-08", "f0-08",
    "F0.08", "P43-02", "P43.", "P999.99", "r43.02", "P4302", "F0-8", "F0-008",
];

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

/// What tests/manuals.rs reads.
const EXAMPLE_TYPE: &str = "\
/// A manual's worked example, as the description gives it: where the
/// manual prints it, the module (`None`: the PKW words of every module
/// that has them), whether it goes out (master to drive), whether its
/// bytes are the PKW words alone, and each telegram it stands for.
#[derive(Debug)]
pub struct Example {
    pub section: &'static str,
    pub printed: &'static str,
    pub module: Option<&'static str>,
    pub out: bool,
    pub pkw_only: bool,
    pub telegrams: &'static [&'static [u8]],
}
";

/// `pub const MD810DP: &[Example] = &[...];`, named after the file.
fn examples_of(name: &str, ir: &gsdc::Ir) -> String {
    let constant = name
        .trim_end_matches(".toml")
        .to_uppercase()
        .replace(['-', '.'], "_");
    let mut out =
        format!("\n/// The examples of {name}.\npub const EXAMPLES_{constant}: &[Example] = &[\n");
    for e in &ir.examples {
        let telegrams: Vec<String> = e
            .instances()
            .iter()
            .map(|t| {
                let bytes: Vec<String> = t.iter().map(|b| format!("0x{b:02X}")).collect();
                format!("&[{}]", bytes.join(", "))
            })
            .collect();
        let _ = writeln!(
            out,
            "    Example {{ section: {:?}, printed: {:?}, module: {:?}, out: {}, pkw_only: {}, telegrams: &[{}] }},",
            e.section,
            e.printed,
            e.module,
            e.direction == gsdc::ir::Direction::Out,
            e.part == gsdc::ir::manual::ExamplePart::Pkw,
            telegrams.join(", ")
        );
    }
    out.push_str("];\n");
    out
}
