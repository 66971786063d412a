//! The MD810 bridge mode (manual chapter 2) as the description rules see it:
//! the plan the shipped description gives, the manual's example and the
//! limits as default configurations, and what the rules refuse, each at its
//! line and column.

use crate::support::descriptions;
use gsdc::ir::gateway::{DiagCode, Gateway};
use gsdc::ir::Direction;

const NAME: &str = "md810-gateway.toml";

fn text() -> String {
    descriptions::shipped_text(NAME)
}

/// The description with each `from` (found exactly once) replaced.
fn variant(edits: &[(&str, &str)]) -> String {
    edits.iter().fold(text(), |text, (from, to)| {
        assert_eq!(text.matches(from).count(), 1, "{from:?}");
        text.replacen(from, to, 1)
    })
}

/// TPDO and RPDO defaults, one per slave 1..30, and the default count.
fn with_defaults(count: usize, input: &[u8], output: &[u8]) -> String {
    let list = |words: &[u8]| {
        let mut all = words.to_vec();
        all.resize(30, 0);
        format!("defaults = {all:?}")
    };
    let (input, output) = (list(input), list(output));
    variant(&[
        (
            "range = [1, 30]\ndefault = 1",
            &format!("range = [1, 30]\ndefault = {count}"),
        ),
        (
            "range = [0, 8]\ndefault = 0\n\n[gateway.output_words]",
            &format!("range = [0, 8]\n{input}\n\n[gateway.output_words]"),
        ),
        (
            "range = [0, 8]\ndefault = 0\n\n# 2.4 step 5",
            &format!("range = [0, 8]\n{output}\n\n# 2.4 step 5"),
        ),
    ])
}

fn gateway_of(text: &str) -> Gateway {
    let (ir, diagnostics) = descriptions::load_text(NAME, text);
    let ir = ir.unwrap_or_else(|| panic!("{diagnostics:?}"));
    ir.gateway.unwrap()
}

/// Bytes of input and output the defaults of the slaves in use carry.
fn default_totals(g: &Gateway) -> (usize, usize) {
    let in_use = &g.nodes[..usize::from(g.node_count.default)];
    let bytes = |direction| {
        let words: usize = in_use
            .iter()
            .map(|n| usize::from(n.words(direction).default))
            .sum();
        2 * words
    };
    (bytes(Direction::In), bytes(Direction::Out))
}

/// The codes of `text`'s errors, each with its line and column.
fn errors(text: &str) -> Vec<(&'static str, usize, usize)> {
    descriptions::error_places(NAME, text)
}

/// Line and column of the first `needle` in `text`, at `within` of it.
fn place(text: &str, needle: &str, within: &str) -> (usize, usize) {
    let at = text.find(needle).unwrap() + needle.find(within).unwrap();
    gsdc::line_col(text, at)
}

#[test]
fn the_plan_is_the_manuals() {
    let ir = descriptions::load(NAME);
    let g = ir.gateway.as_ref().unwrap();
    let profibus = ir.profibus.as_ref().unwrap();
    assert_eq!(g.bus, "CANopen");
    assert_eq!((g.first_node, g.last_node, g.own_node), (1, 30, Some(1)));
    assert_eq!((g.max_input_len, g.max_output_len), (244, 244));
    assert_eq!(
        (profibus.max_input_len, profibus.max_output_len),
        (244, 244)
    );
    assert_eq!((g.node_count.min, g.node_count.max), (1, 30));
    assert!(g
        .nodes
        .iter()
        .all(|n| (n.input_words.max, n.output_words.max) == (8, 8)));
    assert!(profibus.slave_family.starts_with("9@"));
    assert_eq!(ir.device.model, "MD810-gateway");
    // The node count's byte, then one byte per slave and direction.
    assert_eq!(profibus.user_prm.len, 1 + 30 * 2);
    assert!(profibus.dpv1.is_none() && profibus.user_prm.constant.is_empty());
    // 2.5: lengths 4, 4, 5; codes 35 and 34 of type 1, 32 of type 3, and
    // the drive's fault code of type 4; 6 + 5 bytes of diagnosis at most.
    let d = g.diagnosis.as_ref().unwrap();
    let types: Vec<(u8, u8, Vec<i64>)> = d
        .types
        .iter()
        .map(|t| {
            let codes = match &t.code {
                DiagCode::Listed(set) => set.choices.iter().map(|c| c.value).collect(),
                _ => Vec::new(),
            };
            (t.value, t.len, codes)
        })
        .collect();
    assert_eq!(
        types,
        [(1, 4, vec![35, 34]), (3, 4, vec![32]), (4, 5, vec![])]
    );
    assert_eq!((d.type_at, d.node_at, d.code_at), (1, 2, 3));
    assert_eq!(profibus.max_diag_data_len, 11);
}

/// 2.4 step 5: RPDO 64 words and TPDO 120 words, as 15 slaves of 8 TPDO
/// words, the first 8 of them with 8 RPDO words.
#[test]
fn the_manuals_example_is_a_valid_configuration() {
    let g = gateway_of(&with_defaults(15, &[8; 15], &[8; 8]));
    assert_eq!(default_totals(&g), (240, 128));
}

/// 30 slaves (2.4 step 4) and 244 bytes each way (2.2.1).
#[test]
fn thirty_slaves_at_the_limit_pass() {
    let mut words = [4; 30];
    words[..2].copy_from_slice(&[5, 5]);
    let g = gateway_of(&with_defaults(30, &words, &words));
    assert_eq!(default_totals(&g), (244, 244));
}

#[test]
fn a_31st_slave_is_refused() {
    let counted = variant(&[("range = [1, 30]", "range = [1, 31]")]);
    let at = place(&counted, "range = [1, 31]", "[1, 31]");
    assert_eq!(errors(&counted), [("E145", at.0, at.1)]);
    let default = variant(&[(
        "range = [1, 30]\ndefault = 1",
        "range = [1, 30]\ndefault = 31",
    )]);
    let at = place(&default, "default = 31", "31");
    assert_eq!(errors(&default), [("E108", at.0, at.1)]);
    let numbered = variant(&[("nodes = [1, 30]", "nodes = [1, 31]")]);
    let (ir, _) = descriptions::load_text(NAME, &numbered);
    assert_eq!(
        ir.unwrap().gateway.unwrap().nodes.len(),
        31,
        "a 31st number, counted only to 30"
    );
}

#[test]
fn a_245th_byte_is_refused() {
    let mut words = [4; 30];
    words[..3].copy_from_slice(&[5, 5, 5]);
    let over = with_defaults(30, &words, &[]);
    let at = place(&over, "defaults = [5, 5, 5", "[5");
    assert_eq!(errors(&over), [("E146", at.0, at.1)]);
    let limit = variant(&[("max_input_len = 244", "max_input_len = 245")]);
    let at = place(&limit, "max_input_len = 245", "245");
    assert_eq!(errors(&limit), [("E101", at.0, at.1)]);
}

/// 127 CANopen node numbers of one byte each way, and the count: 255 bytes.
#[test]
fn a_parameter_telegram_past_237_bytes_is_refused() {
    let many = variant(&[("nodes = [1, 30]", "nodes = [1, 127]")]);
    let at = place(&many, "[gateway]\n", "[gateway]");
    assert_eq!(errors(&many), [("E116", at.0, at.1)]);
}

/// What describes a drive's own telegram has no place beside [gateway].
#[test]
fn a_drives_telegram_beside_the_gateway_is_refused() {
    // (before what, the part, where the error points in it)
    let parts = [
        (
            "\n[profibus.baud_rates]",
            "ppo_types = [\"PPO1\"]\n",
            "[\"PPO1\"]",
        ),
        (
            "[gateway]\n",
            "[profibus.diagnosis]\nlength = 3\n\n",
            "[profibus.diagnosis]",
        ),
        (
            "[gateway]\n",
            "[[settings]]\nname = \"Mode\"\ndefault = 1\n\n",
            "\"Mode\"",
        ),
    ];
    for (before, part, at) in parts {
        let text = variant(&[(before, &format!("{part}{before}"))]);
        let place = place(&text, part, at);
        let errors = errors(&text);
        assert!(
            errors.contains(&("E144", place.0, place.1)),
            "{part}: {errors:?}"
        );
    }
}

/// Without data_order, gsdc says which order it lays the words out in.
#[test]
fn the_data_order_gsdc_chooses_is_said() {
    let text = variant(&[("data_order = \"node-ascending\"\n", "")]);
    let choice = text
        .lines()
        .find(|l| l.starts_with("\"gateway.data_order\""))
        .unwrap();
    let text = text.replace(&format!("{choice}\n"), "");
    let (ir, diagnostics) = descriptions::load_text(NAME, &text);
    let w104: Vec<_> = diagnostics.iter().filter(|d| d.code == "W104").collect();
    assert_eq!(w104.len(), 1, "{w104:?}");
    assert!(w104[0].message.contains("gateway.data_order"));
    let ir = ir.unwrap();
    assert!(ir.decisions.iter().any(|d| d.path == "gateway.data_order"));
}
