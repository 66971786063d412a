//! The raw `[gateway]` part: a card that carries the data of the nodes of a
//! second bus (MD810's bridge mode: PROFIBUS-DP to CANopen). The master sets
//! how many nodes there are and how many words each one carries each way
//! (user parameters), plugs word modules until the input and output totals
//! match, and reads a diagnosis block of type, node and code.

use super::{BitRange, Choice, Exactly, Text};
use serde::Deserialize;
use toml::Spanned;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Gateway {
    /// The second bus, as the manual names it: "CANopen".
    pub bus: Spanned<String>,
    /// The node numbers on the second bus, both ends included.
    pub nodes: Spanned<Exactly<Spanned<i64>, 2>>,
    /// The gateway's own node number, when it is a node itself.
    pub own_node: Option<Spanned<i64>>,
    /// Bytes of data the master reads (all nodes' input words) at most.
    pub max_input_len: Spanned<i64>,
    /// Bytes of data the master writes at most.
    pub max_output_len: Spanned<i64>,
    /// How the nodes' words follow each other in the data.
    pub data_order: Option<Spanned<DataOrder>>,
    /// The parameter that says how many nodes are in use.
    pub node_count: NodeCount,
    /// Per node: the words it sends, which the master reads.
    pub input_words: NodeWords,
    /// Per node: the words it receives, which the master writes.
    pub output_words: NodeWords,
    pub modules: Modules,
    pub diagnosis: Option<Spanned<Diagnosis>>,
}

/// The order of the nodes' words in the master's input and output data.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum DataOrder {
    /// The nodes in use in ascending node number, each node's words together.
    NodeAscending,
}

/// How a user parameter is stored: a whole byte or word, or some bits of a
/// byte (a GSD `BitArea`), which lets parameters share a byte.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
pub enum PrmType {
    Unsigned8,
    Unsigned16,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct NodeCount {
    pub name: Spanned<Text>,
    #[serde(rename = "type")]
    pub data_type: Option<Spanned<PrmType>>,
    /// Bits of a byte, instead of `type`.
    pub bits: Option<Spanned<BitRange>>,
    /// The counts the gateway takes, both ends included.
    pub range: Spanned<Exactly<Spanned<i64>, 2>>,
    pub default: Spanned<i64>,
}

/// One parameter per node for one direction; `{n}` in the name stands for
/// the node number.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct NodeWords {
    pub name: Spanned<Text>,
    #[serde(rename = "type")]
    pub data_type: Option<Spanned<PrmType>>,
    /// Bits of a byte, instead of `type`.
    pub bits: Option<Spanned<BitRange>>,
    /// Words one node may carry this way, both ends included.
    pub range: Spanned<Exactly<Spanned<i64>, 2>>,
    /// The default of every node; or `defaults`, one per node.
    pub default: Option<Spanned<i64>>,
    pub defaults: Option<Spanned<Vec<Spanned<i64>>>>,
}

/// The modules the master plugs: blocks of words, one module for each size
/// and direction.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Modules {
    /// The sizes offered, in words.
    pub words: Spanned<Vec<Spanned<i64>>>,
    /// Consistent over the whole module (config identifier bit 7), rather
    /// than word by word.
    pub consistent: Spanned<bool>,
}

/// The device-related diagnosis block: the header byte, then the type, the
/// node and the code, whose meaning depends on the type.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Diagnosis {
    pub types: Spanned<Vec<DiagnosisType>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DiagnosisType {
    pub value: Spanned<i64>,
    pub text: Spanned<Text>,
    /// The codes of this type, one byte; or `code_word`.
    pub codes: Option<Spanned<Vec<Choice>>>,
    /// The code is a 16-bit number, high byte first, meaning this.
    pub code_word: Option<Spanned<Text>>,
}
