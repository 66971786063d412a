//! The complete example in docs/description.md is a description gsdc
//! accepts and compiles, so the guide cannot drift from the format.

#[test]
fn the_guides_example_compiles() {
    let guide = include_str!("../docs/description.md");
    let start = guide
        .find("```toml\n")
        .expect("the guide has a TOML example")
        + "```toml\n".len();
    let end = start + guide[start..].find("```").unwrap();
    let example = &guide[start..end];
    let (ir, diagnostics) = gsdc::load("example.toml", example);
    let errors: Vec<_> = diagnostics.errors().collect();
    assert!(errors.is_empty(), "{errors:#?}");
    let ir = ir.unwrap();
    assert!(ir.profibus.is_some() && ir.profinet.is_some());
    gsdc::compile(&ir).expect("the example compiles");
}
