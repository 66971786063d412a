//! Generates every shipped description's files, and the PROFIdrive
//! fixture's, into OUT_DIR with gsdc's build-script API, as a firmware crate
//! would; and `examples.rs`, the manuals' worked examples each description
//! gives (`[[examples]]`), for tests/manuals.rs to round-trip through the
//! layouts.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

const DESCRIPTIONS: [&str; 4] = [
    "md810dp.toml",
    "mv810-pnet02.toml",
    "9kdp1.toml",
    "md810-gateway.toml",
];

fn main() {
    let out_dir = std::env::var("OUT_DIR").expect("cargo sets OUT_DIR");
    let descriptions = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../descriptions");
    let profidrive =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../fixtures/valid/profidrive.toml");
    let paths: Vec<PathBuf> = DESCRIPTIONS
        .iter()
        .map(|name| descriptions.join(name))
        .chain([profidrive])
        .collect();
    let mut examples = String::from(EXAMPLE_TYPE);
    for path in &paths {
        gsdc::build::generate(path, &out_dir).unwrap_or_else(|e| panic!("{e}"));
        examples.push_str(&examples_of(path));
    }
    std::fs::write(Path::new(&out_dir).join("examples.rs"), examples).expect("OUT_DIR is writable");
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
fn examples_of(path: &Path) -> String {
    let name = path.file_name().unwrap().to_string_lossy().into_owned();
    let loaded = gsdc::build::load_file(path, &name).unwrap_or_else(|e| panic!("{e}"));
    let ir = loaded.ir.expect("the description loads");
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
