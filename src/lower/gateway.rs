//! The gateway part: the second bus's node numbers, the user parameters
//! that configure the nodes (with the defaults checked as a configuration
//! the gateway must accept), the word modules and the diagnosis. Where each
//! parameter lies in User_Prm_Data is decided by [`place`], which the
//! PROFIBUS lowering calls after the mapping blocks.

mod diagnosis;
mod modules;
mod params;

pub(crate) use modules::module_name;
pub use params::place;

use super::checks::Checker;
use crate::description::gateway as raw;
use crate::description::Description;
use crate::description::Exactly;
use crate::diag::Diagnostic;
use crate::ir::gateway::{DataOrder, Gateway, Node, ParamKey};
use crate::ir::profibus::PrmType;
use crate::ir::Direction;
use params::{default_configuration, node_count, node_words, NodeWords};
use std::ops::Range;
use toml::Spanned;

/// Node numbers, counts and words are bytes in the generated code.
const MAX_BYTE: i64 = 0xFF;

/// The gateway's plan, and what the PROFIBUS lowering needs to place its
/// parameters.
pub struct Lowered {
    pub gateway: Gateway,
    /// Each parameter's data type, in the order User_Prm_Data holds them.
    pub prm_types: Vec<(ParamKey, PrmType)>,
    /// The `[gateway]` table, where a parameter telegram too long is shown.
    pub span: Range<usize>,
}

/// Lowers `[gateway]`. Errors are reported and replaced by the nearest
/// valid value, so that the plan is whole (and unused: a description with an
/// error gives no IR).
pub fn lower(cx: &mut Checker, g: &Spanned<raw::Gateway>, desc: &Description) -> Lowered {
    let span = g.span();
    conflicts(cx, desc, &span);
    let g = g.get_ref();
    let (first_node, last_node) = node_numbers(cx, &g.nodes);
    let own_node = g.own_node.as_ref().and_then(|n| {
        cx.spanned_in_range(
            n,
            first_node.into(),
            last_node.into(),
            "the gateway's own node",
        )
    });
    // They become Max_Input_Len and Max_Output_Len; a gateway carries a
    // byte at least.
    let max_len = |cx: &mut Checker, len: &Spanned<i64>, keyword, what| {
        let most = crate::gsd::keyword_range(keyword).1;
        cx.gsd_number_from(len, keyword, 1, what)
            .unwrap_or(most as u16)
    };
    let max_input_len = max_len(cx, &g.max_input_len, "Max_Input_Len", "max_input_len");
    let max_output_len = max_len(cx, &g.max_output_len, "Max_Output_Len", "max_output_len");
    let data_order = data_order(cx, &g.data_order, &span);
    let nodes = first_node..=last_node;
    let (node_count, count_type) = node_count(cx, &g.node_count, nodes.len());
    let limits = [
        (Direction::In, max_input_len),
        (Direction::Out, max_output_len),
    ];
    let words: Vec<NodeWords> = limits
        .iter()
        .map(|&(direction, max_len)| {
            let raw = match direction {
                Direction::In => &g.input_words,
                Direction::Out => &g.output_words,
            };
            node_words(cx, raw, direction, nodes.clone(), max_len)
        })
        .collect();
    default_configuration(cx, &node_count, &words);
    let (modules, max_modules, fewest) = modules::modules(cx, &g.modules, &limits);
    let (nodes, node_types) = by_node(nodes, &words);
    let prm_types = std::iter::once((ParamKey::NodeCount, count_type))
        .chain(node_types)
        .collect();
    Lowered {
        gateway: Gateway {
            bus: cx.required(&g.bus, "bus"),
            first_node,
            last_node,
            own_node,
            max_input_len,
            max_output_len,
            data_order,
            node_count,
            nodes,
            modules,
            max_modules,
            fewest,
            diagnosis: g.diagnosis.as_ref().map(|d| diagnosis::lower(cx, d)),
        },
        prm_types,
        span,
    }
}

/// The description's order, or gsdc's (W104).
fn data_order(
    cx: &mut Checker,
    order: &Option<Spanned<raw::DataOrder>>,
    gateway: &Range<usize>,
) -> DataOrder {
    match order.as_ref().map(Spanned::get_ref) {
        Some(raw::DataOrder::NodeAscending) => DataOrder::NodeAscending,
        None => {
            cx.defaulted("gateway.data_order", "\"node-ascending\"", gateway.clone());
            DataOrder::NodeAscending
        }
    }
}

/// Each node with its words both ways, and the data types of those
/// parameters in User_Prm_Data's order: node by node, input first.
fn by_node(
    numbers: std::ops::RangeInclusive<u8>,
    words: &[NodeWords],
) -> (Vec<Node>, Vec<(ParamKey, PrmType)>) {
    let [input, output] = [&words[0], &words[1]];
    let nodes: Vec<Node> = numbers
        .zip(input.params.iter().zip(&output.params))
        .map(|(number, (i, o))| Node {
            number,
            input_words: i.clone(),
            output_words: o.clone(),
        })
        .collect();
    let types = nodes
        .iter()
        .flat_map(|n| {
            [
                (n.input_words.key, input.data_type),
                (n.output_words.key, output.data_type),
            ]
        })
        .collect();
    (nodes, types)
}

/// E144: what a gateway's description cannot have besides `[gateway]`.
fn conflicts(cx: &mut Checker, desc: &Description, gateway: &Range<usize>) {
    let profibus = desc.profibus.as_ref().map(Spanned::get_ref);
    let mappings = &desc.mappings;
    let mapping_span = [&mappings.pzd_out, &mappings.pzd_in, &mappings.dpv1_index]
        .into_iter()
        .flatten()
        .map(|m| m.name.span())
        .next();
    let found = [
        (
            desc.telegram.as_ref().map(|t| t.pkw.span()),
            "[telegram]",
            "its data are the nodes' words, not a PKW and PZD telegram",
        ),
        (
            mapping_span,
            "[mappings]",
            "the nodes' words are forwarded as they are, not mapped",
        ),
        (
            desc.settings.first().map(|s| s.name.span()),
            "[[settings]]",
            "its user parameters are the node parameters of [gateway]",
        ),
        (
            profibus
                .and_then(|p| p.ppo_types.as_ref())
                .map(Spanned::span),
            "ppo_types",
            "its modules are the word blocks of [gateway.modules]",
        ),
        (
            profibus
                .and_then(|p| p.diagnosis.as_ref())
                .map(Spanned::span),
            "[profibus.diagnosis]",
            "its diagnosis is [gateway.diagnosis]",
        ),
        (
            desc.profinet.as_ref().map(Spanned::span),
            "[profinet]",
            "gsdc describes PROFIBUS-DP gateways",
        ),
    ];
    for (span, what, why) in found {
        if let Some(span) = span {
            cx.push(
                Diagnostic::error("E144", format!("a gateway's description has no {what}"))
                    .at(span)
                    .label("not for a gateway")
                    .help(format!(
                        "remove it: {why}; a card with a second personality has a description for each"
                    )),
            );
        }
    }
    if desc.profibus.is_none() {
        cx.push(
            Diagnostic::error("E144", "a gateway's description needs [profibus]")
                .at(gateway.clone())
                .label("a gateway without [profibus]")
                .help("add [profibus] with the GSD's file name, ident number, baud rates and slave family (9 is Gateway)"),
        );
    }
}

/// `1 word`, `3 words`.
fn words_of(words: u32) -> String {
    match words {
        1 => "1 word".to_string(),
        n => format!("{n} words"),
    }
}

/// `[first, last]` within a byte, first not above last.
fn node_numbers(cx: &mut Checker, nodes: &Spanned<Exactly<Spanned<i64>, 2>>) -> (u8, u8) {
    let Exactly([first, last]) = nodes.get_ref();
    let first: u8 = cx
        .spanned_in_range(first, 0, MAX_BYTE, "a node number")
        .unwrap_or(1);
    let last: u8 = cx
        .spanned_in_range(last, 0, MAX_BYTE, "a node number")
        .unwrap_or(first);
    if first > last {
        cx.reversed(nodes.span(), first, last);
        return (first, first);
    }
    (first, last)
}
