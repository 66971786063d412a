//! Generates every shipped description's files, and the PROFIdrive
//! fixture's, into OUT_DIR with gsdc's build-script API, as a firmware crate
//! would.

use std::path::Path;

const DESCRIPTIONS: [&str; 4] = [
    "md810dp.toml",
    "mv810-pnet02.toml",
    "9kdp1.toml",
    "md810-gateway.toml",
];

fn main() {
    let out_dir = std::env::var("OUT_DIR").expect("cargo sets OUT_DIR");
    let descriptions = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../descriptions");
    for name in DESCRIPTIONS {
        gsdc::build::generate(descriptions.join(name), &out_dir).unwrap_or_else(|e| panic!("{e}"));
    }
    let profidrive =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../fixtures/valid/profidrive.toml");
    gsdc::build::generate(profidrive, &out_dir).unwrap_or_else(|e| panic!("{e}"));
}
