//! The gateway's part of the C layout: node numbers and limits, the node
//! parameters where User_Prm_Data's plan puts them, the modules' config
//! bytes and the diagnosis types with their codes. The codecs are the
//! support header's (`gsdc_nodes_*`, `gsdc_node_totals`,
//! `gsdc_config_totals`, `gsdc_diag_*`); the layout gives them its facts.
//! Every number comes from the IR, as in the Rust layout's gateway module.
//! Texts go to the template raw: it writes them through its `comment`
//! filter.

use super::super::joined;
use super::{c_string, hex_bytes, initializer, value_set_item, Names, ValueSetItem};
use crate::ir::gateway::{DiagCode, Diagnosis, Gateway, Param, ParamKey};
use crate::ir::profibus::{PrmType, PrmValue, Profibus};
use crate::ir::Direction;
use serde::Serialize;

#[derive(Serialize)]
pub(super) struct Items {
    /// The second bus: its name, and its C string.
    bus: String,
    bus_string: String,
    first_node: u8,
    last_node: u8,
    nodes: usize,
    own_node: Option<u8>,
    max_input_len: u16,
    max_output_len: u16,
    node_count: CountItem,
    input_words: WordsItem,
    output_words: WordsItem,
    node_config_default: String,
    /// The DPV1 status bytes start User_Prm_Data.
    dpv1: bool,
    modules: Vec<ModuleItem>,
    module_configs: String,
    max_modules: u8,
    diagnosis: Option<DiagItems>,
}

/// The node count's parameter: its name, range and default, and its
/// `gsdc_prm_field_t` initializer.
#[derive(Serialize)]
struct CountItem {
    name: String,
    min: u8,
    max: u8,
    default: u8,
    field: String,
}

/// One direction's parameters, one per node, and their defaults.
#[derive(Serialize)]
struct WordsItem {
    /// The first node's parameter's name.
    first_name: String,
    fields: String,
    defaults: String,
}

#[derive(Serialize)]
struct ModuleItem {
    /// `MD810_GATEWAY_INPUT_1_WORD`, the base of its `_CONFIG`.
    name: String,
    text: String,
    config: String,
}

#[derive(Serialize)]
struct DiagItems {
    type_at: u8,
    node_at: u8,
    code_at: u8,
    max_len: u8,
    types: Vec<DiagTypeItem>,
    /// `A, B or C`: the types' macros.
    kinds: String,
}

#[derive(Serialize)]
struct DiagTypeItem {
    /// `MD810_GATEWAY_DIAG_PARAMETER_ERROR`: its value; `_LEN` its length.
    name: String,
    /// `md810_gateway_diag_parameter_error_fits`: its size check.
    check: String,
    text: String,
    value: u8,
    len: u8,
    code_len: u8,
    /// The meaning of a 16-bit code.
    code_word: Option<String>,
    /// The values of a one-byte code and the function that knows them, and
    /// the prefix of their macros.
    codes: Option<ValueSetItem>,
    codes_prefix: Option<String>,
    /// The `is_code` member of its `gsdc_diag_type_t`.
    is_code: String,
}

pub(super) fn items(names: &Names, g: &Gateway, p: &Profibus) -> Items {
    let count = g.param(ParamKey::NodeCount);
    let words = |direction| words_item(names, g, p, direction);
    Items {
        bus: g.bus.clone(),
        bus_string: c_string(&g.bus),
        first_node: g.first_node,
        last_node: g.last_node,
        nodes: g.nodes.len(),
        own_node: g.own_node,
        max_input_len: g.max_input_len,
        max_output_len: g.max_output_len,
        node_count: CountItem {
            name: count.name.en.clone(),
            min: count.min,
            max: count.max,
            default: count.default,
            field: initializer(
                &names.upper("node_count"),
                &field_members(
                    p,
                    ParamKey::NodeCount,
                    ["min", "max", "default"].map(|m| names.upper(&format!("node_count_{m}"))),
                ),
            ),
        },
        input_words: words(Direction::In),
        output_words: words(Direction::Out),
        node_config_default: initializer(
            &names.upper("node_config_default"),
            &[
                "node_count_default",
                "input_words_defaults",
                "output_words_defaults",
            ]
            .map(|n| names.upper(n)),
        ),
        dpv1: p.dpv1.is_some(),
        modules: g
            .modules
            .iter()
            .map(|m| ModuleItem {
                name: names.upper(&m.ident.snake()),
                text: m.name.clone(),
                config: hex_bytes(&[m.config]).concat(),
            })
            .collect(),
        module_configs: initializer(
            &names.upper("module_configs"),
            &g.modules
                .iter()
                .map(|m| names.upper(&format!("{}_config", m.ident.snake())))
                .collect::<Vec<_>>(),
        ),
        max_modules: g.max_modules,
        diagnosis: g.diagnosis.as_ref().map(|d| diag_items(names, d)),
    }
}

/// The members of a `gsdc_prm_field_t` initializer: where User_Prm_Data's
/// plan puts the parameter, how it is stored, and `[min, max, default]`.
fn field_members(p: &Profibus, key: ParamKey, [min, max, default]: [String; 3]) -> Vec<String> {
    let placed = p
        .user_prm
        .placed(PrmValue::Gateway(key))
        .expect("lowering places every gateway parameter");
    let (data_type, first, last) = match placed.data_type {
        PrmType::Unsigned8 => ("GSDC_PRM_UNSIGNED8", 0, 0),
        PrmType::Unsigned16 => ("GSDC_PRM_UNSIGNED16", 0, 0),
        PrmType::Bits { first, last } => ("GSDC_PRM_BITS", first, last),
    };
    vec![
        format!("{}U", placed.offset),
        data_type.to_string(),
        format!("{first}U"),
        format!("{last}U"),
        min,
        max,
        default,
    ]
}

/// `{ 1U, GSDC_PRM_UNSIGNED8, 0U, 0U, 0U, 8U, 0U }`: one node's parameter.
fn field_initializer(p: &Profibus, param: &Param) -> String {
    let range = [param.min, param.max, param.default].map(|v| format!("{v}U"));
    format!("{{ {} }}", field_members(p, param.key, range).join(", "))
}

fn words_item(names: &Names, g: &Gateway, p: &Profibus, direction: Direction) -> WordsItem {
    let name = names.upper(match direction {
        Direction::In => "input_words",
        Direction::Out => "output_words",
    });
    let params: Vec<&Param> = g.nodes.iter().map(|n| n.words(direction)).collect();
    let fields: Vec<String> = params.iter().map(|q| field_initializer(p, q)).collect();
    let defaults: Vec<String> = params.iter().map(|q| format!("{}U", q.default)).collect();
    WordsItem {
        first_name: params[0].name.en.clone(),
        fields: initializer(&name, &fields),
        defaults: initializer(&format!("{name}_DEFAULTS"), &defaults),
    }
}

fn diag_items(names: &Names, d: &Diagnosis) -> DiagItems {
    let types: Vec<DiagTypeItem> = d
        .types
        .iter()
        .map(|t| {
            let base = format!("diag_{}", t.ident.snake());
            let (codes, codes_prefix, code_word) = match &t.code {
                DiagCode::Listed(set) => (
                    Some(value_set_item(names, "diag", set)),
                    Some(names.upper(&format!("diag_{}", set.ident.snake()))),
                    None,
                ),
                DiagCode::Word(meaning) => (None, None, Some(meaning.en.clone())),
            };
            DiagTypeItem {
                is_code: codes
                    .as_ref()
                    .map_or_else(|| "NULL".to_string(), |c| c.is_value.clone()),
                codes,
                codes_prefix,
                code_word,
                name: names.upper(&base),
                check: names.lower(&format!("{base}_fits")),
                text: t.text.en.clone(),
                value: t.value,
                len: t.len,
                code_len: t.code.bytes(),
            }
        })
        .collect();
    let kinds: Vec<&str> = types.iter().map(|t| t.name.as_str()).collect();
    DiagItems {
        type_at: d.type_at,
        node_at: d.node_at,
        code_at: d.code_at,
        max_len: d.max_len,
        kinds: joined(&kinds, "or"),
        types,
    }
}
