//! The shipped descriptions, loaded as the tests need them.

/// The IR of `descriptions/<name>`, which must load without an error.
pub fn load(name: &str) -> gsdc::Ir {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("descriptions")
        .join(name);
    let text = std::fs::read_to_string(&path).unwrap();
    let (ir, diagnostics) = gsdc::load(name, &text);
    assert!(!diagnostics.has_errors(), "{name}: {diagnostics:?}");
    ir.unwrap()
}
