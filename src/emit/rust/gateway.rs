//! The gateway's part of the firmware layout: node numbers and limits, the
//! node parameters where User_Prm_Data's plan puts them, the modules' config
//! bytes and the typed diagnosis. Every number comes from the IR.

use super::{doc_text, hex_bytes, value_enum, ValueEnum};
use crate::ir::gateway::{DiagCode, Diagnosis, Gateway, ParamKey};
use crate::ir::profibus::{PrmType, PrmValue, Profibus};
use crate::ir::Direction;
use serde::Serialize;

#[derive(Serialize)]
pub(super) struct Items {
    bus: String,
    first_node: u8,
    last_node: u8,
    nodes: usize,
    own_node: Option<u8>,
    max_input_len: u16,
    max_output_len: u16,
    node_count: Field,
    input_words: Words,
    output_words: Words,
    /// The DPV1 status bytes start User_Prm_Data.
    dpv1: bool,
    modules: Vec<Module>,
    max_modules: u8,
    diagnosis: Option<DiagItems>,
}

/// One parameter: its doc line and its `PrmField` constant's value.
#[derive(Serialize)]
struct Field {
    doc: String,
    value: String,
}

/// One direction's parameters, one per node.
#[derive(Serialize)]
struct Words {
    doc: String,
    values: Vec<String>,
}

#[derive(Serialize)]
struct Module {
    constant: String,
    doc: String,
    config: String,
}

#[derive(Serialize)]
struct DiagItems {
    type_at: u8,
    node_at: u8,
    code_at: u8,
    max_len: u8,
    /// `1, 3, 4`.
    type_values: String,
    types: Vec<DiagTypeItem>,
    code_enums: Vec<ValueEnum>,
}

#[derive(Serialize)]
struct DiagTypeItem {
    variant: String,
    doc: String,
    value: u8,
    len: u8,
    /// The enum of its codes; none for a 16-bit code.
    code_enum: Option<String>,
    /// `u16` or the enum.
    code_type: String,
    /// Whether rustfmt keeps the variant's fields on its line: it does
    /// while they take at most 35 characters (`struct_variant_width`).
    one_line: bool,
}

pub(super) fn items(g: &Gateway, p: &Profibus) -> Items {
    let field = |key: ParamKey| field_value(g, p, key);
    let words = |direction: Direction| Words {
        doc: words_doc(g, direction),
        values: g
            .nodes
            .iter()
            .map(|n| field(n.words(direction).key))
            .collect(),
    };
    let count = g.param(ParamKey::NodeCount);
    Items {
        bus: g.bus.clone(),
        first_node: g.first_node,
        last_node: g.last_node,
        nodes: g.nodes.len(),
        own_node: g.own_node,
        max_input_len: g.max_input_len,
        max_output_len: g.max_output_len,
        node_count: Field {
            doc: format!(
                "\"{}\": how many nodes are in use, the first ones from [`FIRST_NODE`], {} at most.",
                doc_text(&count.name.en),
                count.max
            ),
            value: field(ParamKey::NodeCount),
        },
        input_words: words(Direction::In),
        output_words: words(Direction::Out),
        dpv1: p.dpv1.is_some(),
        modules: g
            .modules
            .iter()
            .map(|m| Module {
                constant: format!("{}_CONFIG", m.ident.upper_snake()),
                doc: format!("Module \"{}\": its config identifier byte.", m.name),
                config: hex_bytes(&[m.config]),
            })
            .collect(),
        max_modules: g.max_modules,
        diagnosis: g.diagnosis.as_ref().map(diag_items),
    }
}

/// `PrmField::new(1, PrmType::Unsigned8, [0, 8], 0)`: where User_Prm_Data's
/// plan puts the parameter, and what it may hold.
fn field_value(g: &Gateway, p: &Profibus, key: ParamKey) -> String {
    let placed = p
        .user_prm
        .placed(PrmValue::Gateway(key))
        .expect("lowering places every gateway parameter");
    let data_type = match placed.data_type {
        PrmType::Unsigned8 => "PrmType::Unsigned8".to_string(),
        PrmType::Unsigned16 => "PrmType::Unsigned16".to_string(),
        PrmType::Bits { first, last } => format!("PrmType::Bits({first}, {last})"),
    };
    let param = g.param(key);
    format!(
        "PrmField::new({}, {data_type}, [{}, {}], {})",
        placed.offset, param.min, param.max, param.default
    )
}

fn words_doc(g: &Gateway, direction: Direction) -> String {
    let first = &g.nodes[0].words(direction).name.en;
    let what = match direction {
        Direction::In => "sends, which the master reads",
        Direction::Out => "receives, which the master writes",
    };
    format!(
        "\"{}\" and on: the words each node {what}; [`FIRST_NODE`] first.",
        doc_text(first)
    )
}

fn diag_items(d: &Diagnosis) -> DiagItems {
    let types = d
        .types
        .iter()
        .map(|t| {
            let variant = t.ident.camel();
            let (code_enum, code_doc) = match &t.code {
                DiagCode::Listed(set) => (
                    Some(set.ident.camel()),
                    format!("the code is one byte, one of [`{}`]", set.ident.camel()),
                ),
                DiagCode::Word(name) => (
                    None,
                    format!(
                        "the code is the {}, two bytes, high byte first",
                        doc_text(&name.en)
                    ),
                ),
            };
            let code_type = code_enum.clone().unwrap_or_else(|| "u16".into());
            DiagTypeItem {
                one_line: format!("node: u8, code: {code_type}").len() <= 35,
                code_type,
                doc: format!(
                    "Type {}, \"{}\": blocks of {} bytes, the header included; {code_doc}.",
                    t.value,
                    doc_text(&t.text.en),
                    t.len
                ),
                variant,
                value: t.value,
                len: t.len,
                code_enum,
            }
        })
        .collect();
    let code_enums = d
        .types
        .iter()
        .filter_map(|t| match &t.code {
            DiagCode::Listed(set) => Some(value_enum(
                set,
                format!(
                    "The codes of type {}, \"{}\".",
                    t.value,
                    doc_text(&t.text.en)
                ),
            )),
            DiagCode::Word(_) => None,
        })
        .collect();
    DiagItems {
        type_at: d.type_at,
        node_at: d.node_at,
        code_at: d.code_at,
        max_len: d.max_len,
        type_values: d
            .types
            .iter()
            .map(|t| t.value.to_string())
            .collect::<Vec<_>>()
            .join(", "),
        types,
        code_enums,
    }
}
