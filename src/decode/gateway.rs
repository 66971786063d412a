//! A gateway's data (MD810's bridge mode): what the node configuration in
//! force adds up to, a module's words (each node's, when the configuration
//! and the data order say which), and the diagnosis block read by its type.

use super::diagnosis::{
    check_header, DiagByte, DiagCodeValue, DiagNode, DiagnosisBlock, GatewayDiagnosis,
};
use super::hex::Hex;
use super::mapping::MappingInForce;
use super::module::word_name;
use super::telegram::{DecodedWord, GatewayData, NodeTotals, NodeWord, Telegram};
use crate::diag::Diagnostic;
use crate::ir::gateway::{DataOrder, DiagCode, DiagType, Diagnosis, Gateway, Module, Node, Param};
use crate::ir::Direction;
use crate::pkw::support::gateway as firmware;

/// The node configuration in force, added up.
pub(super) fn totals(g: &Gateway, mapping: &MappingInForce) -> NodeTotals {
    let count = mapping.gateway_value(&g.node_count);
    let words = |direction| -> u32 {
        in_use(g, count)
            .map(|n| u32::from(mapping.gateway_value(n.words(direction))))
            .sum()
    };
    let (input_words, output_words) = (words(Direction::In), words(Direction::Out));
    let mut totals = NodeTotals {
        node_count: count,
        input_words,
        output_words,
        input_len: 2 * input_words,
        output_len: 2 * output_words,
        max_input_len: g.max_input_len,
        max_output_len: g.max_output_len,
        refused: None,
    };
    totals.refused = refusal(g, mapping, &totals);
    totals
}

/// The nodes in use: the first `count`.
fn in_use(g: &Gateway, count: u16) -> impl Iterator<Item = &Node> {
    g.nodes.iter().take(count.into())
}

/// Why the card refuses the configuration, in the order the firmware's
/// `totals` checks it: the count, then node by node the words of a node
/// past the count (none allowed) or in use (within their range), then the
/// limits.
fn refusal(g: &Gateway, mapping: &MappingInForce, totals: &NodeTotals) -> Option<String> {
    let not_allowed = |p: &Param, value: u16| {
        format!(
            "{}: {value} is not allowed ({} to {})",
            p.name.en, p.min, p.max
        )
    };
    let count = totals.node_count;
    if !allows(&g.node_count, count) {
        return Some(not_allowed(&g.node_count, count));
    }
    for (i, node) in g.nodes.iter().enumerate() {
        for direction in [Direction::In, Direction::Out] {
            let param = node.words(direction);
            let value = mapping.gateway_value(param);
            if i >= usize::from(count) && value != 0 {
                return Some(format!(
                    "node {} is not in use (the count is {count}) but carries words: {} = {value}",
                    node.number, param.name.en
                ));
            }
            if i < usize::from(count) && !allows(param, value) {
                return Some(not_allowed(param, value));
            }
        }
    }
    let over = |way: &str, len: u32, max: u16| {
        (len > u32::from(max))
            .then(|| format!("{way} is {len} bytes; the gateway carries at most {max}"))
    };
    over("the input", totals.input_len, g.max_input_len)
        .or_else(|| over("the output", totals.output_len, g.max_output_len))
}

fn allows(p: &Param, value: u16) -> bool {
    (u16::from(p.min)..=u16::from(p.max)).contains(&value)
}

/// A gateway module's words, numbered from 1, each named after its node
/// when the configuration in force determines it.
pub(super) fn telegram(
    g: &Gateway,
    module: &Module,
    bytes: &[u8],
    mapping: &MappingInForce,
) -> Telegram {
    debug_assert_eq!(bytes.len(), 2 * usize::from(module.words));
    let nodes = totals(g, mapping);
    let carried = match module.direction {
        Direction::In => nodes.input_words,
        Direction::Out => nodes.output_words,
    };
    let attributed = nodes.refused.is_none() && carried == u32::from(module.words);
    let owners = if attributed {
        in_data_order(g, mapping, nodes.node_count, module.direction)
    } else {
        Vec::new()
    };
    let words = bytes
        .chunks_exact(2)
        .zip(1..=module.words)
        .enumerate()
        .map(|(i, (pair, n))| DecodedWord {
            offset: 2 * i,
            name: word_name(n),
            value: u16::from_be_bytes([pair[0], pair[1]]),
            carries: None,
            fields: Vec::new(),
            node: owners.get(i).copied(),
        })
        .collect();
    Telegram {
        module: module.name.clone(),
        direction: module.direction,
        len: bytes.len(),
        words,
        double_words: Vec::new(),
        pkw: None,
        gateway: Some(GatewayData {
            source: mapping.gateway_source(),
            nodes,
            attributed,
        }),
    }
}

/// Every word of the data one way, as the description's data order puts
/// the nodes' words.
fn in_data_order(
    g: &Gateway,
    mapping: &MappingInForce,
    count: u16,
    direction: Direction,
) -> Vec<NodeWord> {
    match g.data_order {
        DataOrder::NodeAscending => in_use(g, count)
            .flat_map(|n| {
                let words = mapping.gateway_value(n.words(direction));
                (1..=words).map(|word| NodeWord {
                    node: n.number,
                    word,
                })
            })
            .collect(),
    }
}

// ---------------------------------------------------------------------------
// Diagnosis

/// Decodes the block `hex` holds: as long as its header says, the header
/// being one of the types' lengths (E417 at the header otherwise, or when
/// it is not the length of the type the block names; E412 for bytes too
/// many or missing).
pub(super) fn diagnosis(
    g: &Gateway,
    d: &Diagnosis,
    hex: &Hex,
) -> Result<DiagnosisBlock, Diagnostic> {
    let help = lengths_help(d);
    let mut lengths: Vec<u8> = d.types.iter().map(|t| t.len).collect();
    lengths.sort_unstable();
    lengths.dedup();
    let Some(&header) = hex.bytes().first() else {
        return Err(hex
            .exactly(lengths[0].into(), "the diagnosis block", &help)
            .expect_err("an empty block is shorter than any type's"));
    };
    check_header(header, &lengths, &help).map_err(|e| e.at_opt(hex.span(0)))?;
    let block = hex.exactly(header.into(), "the diagnosis block", &help)?;
    let kind = block[usize::from(d.type_at)];
    let named = d.types.iter().find(|t| t.value == kind);
    if let Some(t) = named.filter(|t| t.len != header) {
        return Err(Diagnostic::error(
            "E417",
            format!(
                "0x{header:02X} is not the header of a type {kind} block: it gives the length {header}"
            ),
        )
        .at_opt(hex.span(0))
        .label("header")
        .help(format!(
            "a block of type {kind} ({}) is {} bytes, the header included: it starts with 0x{:02X}",
            t.text.en, t.len, t.len
        )));
    }
    let node = block[usize::from(d.node_at)];
    let gateway = GatewayDiagnosis {
        kind: DiagByte {
            at: d.type_at.into(),
            value: kind,
            text: named.map(|t| t.text.en.clone()),
        },
        node: DiagNode {
            at: d.node_at.into(),
            value: node,
            range: [g.first_node, g.last_node],
            allowed: (g.first_node..=g.last_node).contains(&node),
        },
        code: named.map(|t| code(g, d, t, block)),
    };
    Ok(DiagnosisBlock {
        len: block.len(),
        header,
        bytes: block.to_vec(),
        areas: Vec::new(),
        unread: Vec::new(),
        gateway: Some(gateway),
    })
}

/// The code of a block of type `t`, read as the firmware reads it.
fn code(g: &Gateway, d: &Diagnosis, t: &DiagType, block: &[u8]) -> DiagCodeValue {
    // The firmware's readers need only the places; the type was checked above.
    let layout = crate::pkw::gateway_diag_layout(g, d);
    let invariant =
        "lowering makes a type's blocks end with its code, and the header gave this type's length";
    let (value, text) = match &t.code {
        DiagCode::Listed(set) => {
            let value =
                firmware::code_byte(block, (t.value, t.len), &layout, Some).expect(invariant);
            let text = set
                .choices
                .iter()
                .find(|c| c.value == i64::from(value))
                .map(|c| c.text.en.clone());
            (value, text)
        }
        DiagCode::Word(name) => {
            let value = firmware::code_word(block, t.len, &layout).expect(invariant);
            (value, Some(name.en.clone()))
        }
    };
    DiagCodeValue {
        at: d.code_at.into(),
        bytes: t.code.bytes(),
        value,
        text,
    }
}

/// "the header has bits 7-6 00 and bits 5-0 the block's length: 4 bytes
/// for type 1 or 3, 5 bytes for type 4, the header included".
fn lengths_help(d: &Diagnosis) -> String {
    let mut lengths: Vec<(u8, Vec<String>)> = Vec::new();
    for t in &d.types {
        match lengths.iter_mut().find(|(len, _)| *len == t.len) {
            Some((_, types)) => types.push(t.value.to_string()),
            None => lengths.push((t.len, vec![t.value.to_string()])),
        }
    }
    let parts: Vec<String> = lengths
        .iter()
        .map(|(len, types)| format!("{len} bytes for type {}", types.join(" or ")))
        .collect();
    format!(
        "the header has bits 7-6 00 and bits 5-0 the block's length: {}, the header included",
        parts.join(", ")
    )
}
