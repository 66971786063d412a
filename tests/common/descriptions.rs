//! The shipped descriptions, loaded as the tests need them.

/// The IR of `descriptions/<name>`, which must load without an error; read
/// as the build reads it, so that the files it names (its symbol) are found.
pub fn load(name: &str) -> gsdc::Ir {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("descriptions")
        .join(name);
    let loaded = gsdc::build::load_file(&path, name).unwrap();
    let diagnostics = &loaded.findings.diagnostics;
    assert!(!diagnostics.has_errors(), "{name}: {diagnostics:?}");
    loaded.ir.unwrap()
}
