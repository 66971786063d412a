//! The gateway's part of the layout: node numbers and limits, the node
//! parameters where User_Prm_Data's plan puts them, the modules' config
//! bytes and the diagnosis types with their codes. The codecs are the
//! support code's; the layout gives them its facts.

use super::{value_set, Const, Consts, Doc, Ref, Scope, Ty, Val, ValueSet};
use crate::ir::gateway::{self, DiagCode, ParamKey};
use crate::ir::profibus::{PrmType, PrmValue, Profibus};
use crate::ir::{Direction, Ident};
use serde::Serialize;

#[derive(Serialize)]
pub(crate) struct Gateway {
    pub doc: Doc,
    pub bus: Consts,
    pub nodes: Consts,
    pub own_node: Option<Consts>,
    pub max_lens: Consts,
    pub node_count: NodeCount,
    pub input_words: NodeWords,
    pub output_words: NodeWords,
    /// The node parameters and limits, as the support code takes them.
    pub params: Doc,
    pub node_config: NodeConfig,
    /// The words the nodes in use carry.
    pub totals: Doc,
    /// The DPV1 status bytes start User_Prm_Data.
    pub dpv1: bool,
    /// Each module's config byte.
    pub modules: Vec<Consts>,
    pub module_configs: Doc,
    pub max_modules: Consts,
    pub diagnosis: Option<Diagnosis>,
}

/// The parameter that says how many nodes are in use.
#[derive(Serialize)]
pub(crate) struct NodeCount {
    pub doc: Doc,
    pub field: PrmField,
}

/// One direction's parameters, one per node.
#[derive(Serialize)]
pub(crate) struct NodeWords {
    pub doc: Doc,
    pub fields: Vec<PrmField>,
}

/// A parameter where User_Prm_Data's plan puts it, and what it may hold.
#[derive(Serialize)]
pub(crate) struct PrmField {
    pub offset: u16,
    /// `unsigned8`, `unsigned16` or `bits`.
    pub ty: Ident,
    /// The bits of a `bits` parameter; 0 and 0 else.
    pub first: u8,
    pub last: u8,
    pub min: u8,
    pub max: u8,
    pub default: u8,
}

/// The node configuration User_Prm_Data sets, and its members.
#[derive(Serialize)]
pub(crate) struct NodeConfig {
    pub doc: Doc,
    pub node_count: Doc,
    pub input_words: Doc,
    pub output_words: Doc,
    /// The configuration of the GSD's defaults.
    pub default: Doc,
}

#[derive(Serialize)]
pub(crate) struct Diagnosis {
    pub type_at: u8,
    pub node_at: u8,
    pub code_at: u8,
    pub max_len: Consts,
    pub types: Vec<DiagType>,
}

/// A type of block the gateway reports, and what its code is.
#[derive(Serialize)]
pub(crate) struct DiagType {
    pub name: Ident,
    pub doc: Doc,
    pub text: String,
    pub value: u8,
    /// The block's bytes, the header included.
    pub len: u8,
    /// The values of a one-byte code.
    pub codes: Option<ValueSet>,
    /// The meaning of a 16-bit code.
    pub code_word: Option<String>,
}

fn first_node() -> Ref {
    Ref::Const(Scope::Gateway, Ident::of(&["first", "node"]))
}

fn doc(text: &str) -> Doc {
    Doc::at(Scope::Gateway).text(text)
}

fn consts(text: &str, items: Vec<Const>) -> Consts {
    Consts {
        doc: doc(text),
        items,
    }
}

pub(super) fn gateway(g: &gateway::Gateway, p: &Profibus) -> Gateway {
    let size = |n: u16| Val::Dec(n.into());
    let node = |n: u8| Val::Dec(n.into());
    let count = g.param(ParamKey::NodeCount);
    Gateway {
        doc: Doc::plain(format!(
            "The gateway to {}: its node numbers, the user parameters that say which nodes \
             are in use and how many words each one carries each way, the modules that carry \
             those words, and the diagnosis it reports.",
            g.bus
        )),
        bus: consts(
            "The second bus.",
            vec![Const::new(&["bus"], Ty::Text, Val::Text(g.bus.clone()))],
        ),
        nodes: consts(
            "The node numbers, both ends included: each one has its parameters.",
            vec![
                Const::new(&["first", "node"], Ty::U8, node(g.first_node)),
                Const::new(&["last", "node"], Ty::U8, node(g.last_node)),
                Const::new(&["nodes"], Ty::Size, size(g.nodes.len() as u16)),
            ],
        ),
        own_node: g.own_node.map(|own| {
            consts(
                "The gateway's own node number: it is a node itself.",
                vec![Const::new(&["own", "node"], Ty::U8, node(own))],
            )
        }),
        max_lens: consts(
            "Bytes of input (the words the nodes send, which the master reads) and of output, \
             at most: Max_Input_Len and Max_Output_Len.",
            vec![
                Const::new(&["max", "input", "len"], Ty::Size, size(g.max_input_len)),
                Const::new(&["max", "output", "len"], Ty::Size, size(g.max_output_len)),
            ],
        ),
        node_count: NodeCount {
            doc: doc(&format!(
                "\"{}\": how many nodes are in use, the first ones from ",
                count.name.en
            ))
            .link(first_node())
            .text(format!(", {} at most.", count.max)),
            field: field(p, count),
        },
        input_words: words(g, p, Direction::In),
        output_words: words(g, p, Direction::Out),
        params: doc("The node parameters and the data limits, as the support code takes them."),
        node_config: NodeConfig {
            doc: doc(
                "Which nodes are in use (the first `node_count` node numbers) and the words \
                 each node carries each way, as User_Prm_Data sets them.",
            ),
            node_count: doc("How many nodes are in use: the first ones from ")
                .link(first_node())
                .text("."),
            input_words: doc("The words each node sends, which the master reads; ")
                .link(first_node())
                .text(" first."),
            output_words: doc("The words each node receives, which the master writes."),
            default: doc("The configuration of the GSD's defaults."),
        },
        totals: doc(
            "The words of input and output the nodes in use carry: the master plugs modules \
             of as many. Refused: a count or a node's words out of its parameter's range, \
             words of a node not in use, more than ",
        )
        .link(Ref::Const(
            Scope::Gateway,
            Ident::of(&["max", "input", "len"]),
        ))
        .text(" or ")
        .link(Ref::Const(
            Scope::Gateway,
            Ident::of(&["max", "output", "len"]),
        ))
        .text(" bytes."),
        dpv1: p.dpv1.is_some(),
        modules: g
            .modules
            .iter()
            .map(|m| {
                consts(
                    &format!("Module \"{}\": its config identifier byte.", m.name),
                    vec![Const {
                        name: m.ident.tagged("config"),
                        ty: Ty::U8,
                        value: Val::hex_u8(m.config),
                    }],
                )
            })
            .collect(),
        module_configs: doc("Every module's config byte."),
        max_modules: consts(
            "Max_Module: the most modules a configuration within the limits needs.",
            vec![Const::new(
                &["max", "modules"],
                Ty::Size,
                node(g.max_modules),
            )],
        ),
        diagnosis: g.diagnosis.as_ref().map(diagnosis),
    }
}

/// Where User_Prm_Data's plan puts the parameter, and what it may hold.
fn field(p: &Profibus, param: &gateway::Param) -> PrmField {
    let placed = p
        .user_prm
        .placed(PrmValue::Gateway(param.key))
        .expect("lowering places every gateway parameter");
    let (ty, first, last) = match placed.data_type {
        // A gateway's parameters are never Signed8 (a setting's type).
        PrmType::Unsigned8 | PrmType::Signed8 => ("unsigned8", 0, 0),
        PrmType::Unsigned16 => ("unsigned16", 0, 0),
        PrmType::Bits { first, last } => ("bits", first, last),
    };
    PrmField {
        offset: placed.offset,
        ty: Ident::of(&[ty]),
        first,
        last,
        min: param.min,
        max: param.max,
        default: param.default,
    }
}

fn words(g: &gateway::Gateway, p: &Profibus, direction: Direction) -> NodeWords {
    let first = &g.nodes[0].words(direction).name.en;
    let what = match direction {
        Direction::In => "sends, which the master reads",
        Direction::Out => "receives, which the master writes",
    };
    NodeWords {
        doc: doc(&format!("\"{first}\" and on: the words each node {what}; "))
            .link(first_node())
            .text(" first."),
        fields: g
            .nodes
            .iter()
            .map(|n| field(p, n.words(direction)))
            .collect(),
    }
}

fn diagnosis(d: &gateway::Diagnosis) -> Diagnosis {
    let scope = Scope::GatewayDiagnosis;
    let types = d
        .types
        .iter()
        .map(|t| {
            let about = format!("{}, \"{}\"", t.value, t.text.en);
            let doc = Doc::at(scope.clone()).text(format!(
                "Type {about}: blocks of {} bytes, the header included; ",
                t.len
            ));
            let (doc, codes, code_word) = match &t.code {
                DiagCode::Listed(set) => {
                    let codes = value_set(set, Doc::plain(format!("The codes of type {about}.")));
                    let doc = doc
                        .text("the code is one byte, one of ")
                        .link(Ref::Values(scope.clone(), codes.name.clone()))
                        .text(".");
                    (doc, Some(codes), None)
                }
                DiagCode::Word(meaning) => {
                    let doc = doc.text(format!(
                        "the code is the {}, two bytes, high byte first.",
                        meaning.en
                    ));
                    (doc, None, Some(meaning.en.clone()))
                }
            };
            DiagType {
                name: t.ident.clone(),
                doc,
                text: t.text.en.clone(),
                value: t.value,
                len: t.len,
                codes,
                code_word,
            }
        })
        .collect();
    Diagnosis {
        type_at: d.type_at,
        node_at: d.node_at,
        code_at: d.code_at,
        max_len: consts(
            "Bytes of the longest block, the header included; the slave sends it after the 6 \
             bytes of the standard diagnosis.",
            vec![Const::new(
                &["diag", "max", "len"],
                Ty::Size,
                Val::Dec(d.max_len.into()),
            )],
        ),
        types,
    }
}
