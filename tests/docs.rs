//! The complete examples in docs/description.md are descriptions gsdc
//! accepts and compiles, so the guide cannot drift from the format.

use crate::support::descriptions::guide_examples;

fn compiled(example: &str) -> gsdc::Ir {
    let (ir, diagnostics) = gsdc::load("example.toml", example);
    let errors: Vec<_> = diagnostics.errors().collect();
    assert!(errors.is_empty(), "{errors:#?}");
    let ir = ir.unwrap();
    gsdc::compile(&ir).expect("the example compiles");
    ir
}

#[test]
fn the_guides_example_compiles() {
    let ir = compiled(guide_examples()[0]);
    assert!(ir.profibus.is_some() && ir.profinet.is_some());
}

/// The gateway's example is the MD810 manual's: 120 words of TPDO (240
/// bytes of input) and 64 words of RPDO (128 bytes of output).
#[test]
fn the_gateway_example_compiles_with_the_manuals_totals() {
    let ir = compiled(guide_examples()[1]);
    let gateway = ir.gateway.unwrap();
    let in_use = &gateway.nodes[..usize::from(gateway.node_count.default)];
    let words = |direction| -> u16 {
        in_use
            .iter()
            .map(|n| u16::from(n.words(direction).default))
            .sum()
    };
    use gsdc::ir::Direction::{In, Out};
    assert_eq!((2 * words(In), 2 * words(Out)), (240, 128));
}
