//! A gateway: a card that carries the data of the nodes of a second bus
//! (MD810's bridge mode: PROFIBUS-DP to CANopen). The master sets how many
//! nodes are in use and how many words each one carries each way (user
//! parameters, placed in User_Prm_Data by [`super::profibus::UserPrm`]),
//! plugs word modules until its input and output equal the nodes' totals,
//! and reads a diagnosis block of type, node and code.

use super::{Choice, Direction, Ident, Text, ValueSet};

#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Gateway {
    /// The second bus, as the manual names it.
    pub bus: String,
    /// The node numbers, both ends included; every one has its parameters.
    pub first_node: u8,
    pub last_node: u8,
    /// The gateway's own node number, when it is a node itself.
    pub own_node: Option<u8>,
    /// Bytes the master reads and writes at most: Max_Input_Len, Max_Output_Len.
    pub max_input_len: u16,
    pub max_output_len: u16,
    pub data_order: DataOrder,
    /// How many nodes are in use: the first `count` node numbers.
    pub node_count: Param,
    /// Every node number's parameters, `first_node` first.
    pub nodes: Vec<Node>,
    /// The modules offered, input ones first, each size ascending.
    pub modules: Vec<Module>,
    /// Max_Module: the most modules any configuration within the limits
    /// needs, when each direction is made of as few modules as it can be.
    pub max_modules: u8,
    /// How each total of words within the limits is made of as few modules
    /// as it can be.
    pub fewest: Fewest,
    pub diagnosis: Option<Diagnosis>,
}

impl Gateway {
    pub fn param(&self, key: ParamKey) -> &Param {
        match key {
            ParamKey::NodeCount => &self.node_count,
            ParamKey::Words { node, direction } => self
                .nodes
                .iter()
                .find(|n| n.number == node)
                .map(|n| n.words(direction))
                .expect("lowering links only to nodes it made"),
        }
    }

    /// As few modules of `direction` as carry `words`, largest first; `None`
    /// when none do (lowering made sure any total within the limit is made).
    pub fn fewest_modules(&self, direction: Direction, words: usize) -> Option<Vec<&Module>> {
        let modules: Vec<&Module> = self
            .modules
            .iter()
            .filter(|m| m.direction == direction)
            .collect();
        let last = match direction {
            Direction::In => &self.fewest.input,
            Direction::Out => &self.fewest.output,
        };
        let mut plugged = Vec::new();
        let mut total = words;
        while total > 0 {
            let size = (*last.get(total)?)?;
            // A direction offers each size once.
            plugged.push(*modules.iter().find(|m| m.words == size)?);
            total -= usize::from(size);
        }
        plugged.sort_by_key(|m| std::cmp::Reverse(m.words));
        Some(plugged)
    }

    /// The parameters in the order User_Prm_Data holds them: the count, then
    /// each node's input words and output words.
    pub fn params(&self) -> impl Iterator<Item = &Param> {
        std::iter::once(&self.node_count).chain(
            self.nodes
                .iter()
                .flat_map(|n| [&n.input_words, &n.output_words]),
        )
    }
}

/// The order of the nodes' words in the master's input and output data.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum DataOrder {
    /// The nodes in use in ascending node number, each node's words together.
    NodeAscending,
}

/// A gateway parameter: what it is, not where it is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum ParamKey {
    NodeCount,
    /// The words node `node` carries in `direction` (in: the master reads them).
    Words {
        node: u8,
        direction: Direction,
    },
}

/// A user parameter with its range; its place and data type are in
/// User_Prm_Data's plan.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Param {
    pub key: ParamKey,
    /// With the node number filled in.
    pub name: Text,
    pub min: u8,
    pub max: u8,
    pub default: u8,
}

#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Node {
    pub number: u8,
    pub input_words: Param,
    pub output_words: Param,
}

impl Node {
    pub fn words(&self, direction: Direction) -> &Param {
        match direction {
            Direction::In => &self.input_words,
            Direction::Out => &self.output_words,
        }
    }
}

/// A block of words one way: one GSD module with one config identifier byte.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Module {
    /// Its GSD reference number, from 1.
    pub reference: u8,
    pub name: String,
    pub direction: Direction,
    pub words: u8,
    pub consistent: bool,
    /// The config identifier byte Chk_Cfg carries for it.
    pub config: u8,
    /// Its constant in generated code: `input_16_words`.
    pub ident: Ident,
}

/// For each total of 0..=the limit words, each way: the size of the last
/// module of the fewest that make it (`None` for 0 words, and for a total
/// no set of modules makes). Lowering computes it; the datasheet's example
/// reads it through [`Gateway::fewest_modules`].
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Fewest {
    pub input: Vec<Option<u8>>,
    pub output: Vec<Option<u8>>,
}

/// The device-related diagnosis: the header byte (block length, bits 7-6 =
/// 00), then the type, the node and the code at the places below.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Diagnosis {
    /// Byte offsets in the block, the header being byte 0.
    pub type_at: u8,
    pub node_at: u8,
    pub code_at: u8,
    pub types: Vec<DiagType>,
    /// Bytes of the longest block, the header included.
    pub max_len: u8,
    /// What the GSD's `Unit_Diag_Area`s can show: the type's texts, and the
    /// codes of the types that list theirs.
    pub gsd_areas: Vec<GsdArea>,
}

#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct DiagType {
    pub value: u8,
    pub text: Text,
    /// Its variant in generated code: `ParameterError`.
    pub ident: Ident,
    /// Bytes of its block, the header included.
    pub len: u8,
    pub code: DiagCode,
}

#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum DiagCode {
    /// One byte, one of these values.
    Listed(ValueSet),
    /// A 16-bit number, high byte first, with its meaning.
    Word(Text),
}

impl DiagCode {
    pub fn bytes(&self) -> u8 {
        match self {
            DiagCode::Listed(_) => 1,
            DiagCode::Word(_) => 2,
        }
    }
}

/// A `Unit_Diag_Area`, with a comment saying what it shows; bits count from
/// the first byte after the header.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct GsdArea {
    pub first_bit: u16,
    pub last_bit: u16,
    pub note: String,
    pub values: Vec<Choice>,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// MD810's bridge, sizes 1, 2, 4, 8 and 16 words each way: 111 words
    /// are 6 × 16 + 8 + 4 + 2 + 1, largest first; 0 words need none.
    #[test]
    fn the_fewest_modules_carry_the_words_largest_first() {
        let text = include_str!("../../descriptions/md810-gateway.toml");
        let ir = crate::testing::load("md810-gateway.toml", text).0.unwrap();
        let g = ir.gateway.as_ref().unwrap();
        let words = |direction, total| -> Vec<u8> {
            let plugged = g.fewest_modules(direction, total).unwrap();
            assert!(plugged.iter().all(|m| m.direction == direction));
            plugged.iter().map(|m| m.words).collect()
        };
        assert_eq!(
            words(Direction::In, 111),
            [16, 16, 16, 16, 16, 16, 8, 4, 2, 1]
        );
        assert_eq!(words(Direction::Out, 64), [16, 16, 16, 16]);
        assert!(words(Direction::In, 0).is_empty());
    }
}
