//! The shipped descriptions, and the valid fixtures, loaded as the tests
//! need them.

// Each test crate that includes this module uses some of it.
#![allow(dead_code)]

use std::path::Path;

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
