//! The shipped descriptions, and the valid fixtures, loaded as the tests
//! need them.

// Each test crate that includes this module uses some of it.
#![allow(dead_code)]

use std::path::Path;

/// The shipped descriptions, by file name.
pub const SHIPPED: [&str; 4] = [
    "md810dp.toml",
    "mv810-pnet02.toml",
    "9kdp1.toml",
    "md810-gateway.toml",
];

/// The IR of `descriptions/<name>`, which must load without an error; read
/// as the build reads it, so that the files it names (its symbol) are found.
pub fn load(name: &str) -> gsdc::Ir {
    load_from("descriptions", name)
}

/// The IR of `<folder>/<name>` under the repository, which must load
/// without an error.
pub fn load_from(folder: &str, name: &str) -> gsdc::Ir {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join(folder)
        .join(name);
    let loaded = gsdc::build::load_file(&path, name).unwrap();
    let diagnostics = &loaded.findings.diagnostics;
    assert!(!diagnostics.has_errors(), "{name}: {diagnostics:?}");
    loaded.ir.unwrap()
}

/// `text` (a shipped description, or one made from it) loaded as if it
/// stood in `descriptions/`: the files it names are read from there.
pub fn load_text(name: &str, text: &str) -> (Option<gsdc::Ir>, gsdc::Diagnostics) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("descriptions");
    gsdc::load_with(name, text, &|path: &str| {
        std::fs::read(dir.join(path)).map_err(|e| e.to_string())
    })
}

/// Copies the shipped descriptions' symbols into `dir/symbols`, for a test
/// that writes a description (or a copy of one) into `dir`.
pub fn copy_symbols(dir: &Path) {
    let from = Path::new(env!("CARGO_MANIFEST_DIR")).join("descriptions/symbols");
    let to = dir.join("symbols");
    std::fs::create_dir_all(&to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let path = entry.unwrap().path();
        std::fs::copy(&path, to.join(path.file_name().unwrap())).unwrap();
    }
}

/// Every shipped description and every valid fixture, by file name, in
/// name order within each folder.
pub fn all_valid() -> Vec<(String, gsdc::Ir)> {
    ["descriptions", "tests/fixtures/valid"]
        .iter()
        .flat_map(|folder| {
            let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join(folder);
            let mut names: Vec<String> = std::fs::read_dir(dir)
                .unwrap()
                .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                .filter(|n| n.ends_with(".toml"))
                .collect();
            names.sort();
            names
                .into_iter()
                .map(|name| (name.clone(), load_from(folder, &name)))
        })
        .collect()
}
