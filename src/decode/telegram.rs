//! A cyclic telegram of one module: each word with its name and value, the
//! PKW request or response, the control or status word's fields, and what
//! each mapped PZD word carries under the mapping in force. A gateway's
//! modules are read in `super::gateway`, into the types here.

use super::mapping::{meaning, MappingInForce, ValueSource};
use super::module::Module;
use super::pkw_channel::{self, Pkw};
use super::profidrive;
use crate::ir::{Direction, Ir, Layout, MappingKind, Word};
use crate::pkw::{pkw_words, BitField, PKW_BYTES};
use serde::Serialize;

#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Telegram {
    pub module: String,
    #[serde(serialize_with = "super::serialize_direction")]
    pub direction: Direction,
    pub len: usize,
    pub words: Vec<DecodedWord>,
    /// The 32-bit values over two of the words (standard telegram 2's
    /// NSOLL_B and NIST_B), high word first.
    pub double_words: Vec<DoubleWord>,
    pub pkw: Option<Pkw>,
    /// A gateway module's: the node configuration it is read against.
    pub gateway: Option<GatewayData>,
}

/// What the node configuration in force adds up to, and why the card
/// refuses it when it does.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct NodeTotals {
    /// The nodes in use: the first `node_count` node numbers.
    pub node_count: u16,
    /// Words the nodes in use send (the master's input) and receive.
    pub input_words: u32,
    pub output_words: u32,
    /// The same in bytes, and the most the gateway carries.
    pub input_len: u32,
    pub output_len: u32,
    pub max_input_len: u16,
    pub max_output_len: u16,
    /// Why the card refuses the configuration, checked as the firmware's
    /// `totals` checks it; `None` when it takes it.
    pub refused: Option<String>,
}

/// A gateway module's telegram: the configuration its words are read
/// against.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct GatewayData {
    /// `parameter_telegram` with `--prm`, else `default`.
    pub source: ValueSource,
    pub nodes: NodeTotals,
    /// Whether each word is named after its node: the module carries all
    /// the words the nodes in use carry its way, so the data order places
    /// them. A module that carries part of them could be anywhere in the
    /// data, depending on the modules plugged before it.
    pub attributed: bool,
}

/// The node a word of a gateway module belongs to, and its number among
/// that node's words, from 1.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct NodeWord {
    pub node: u8,
    pub word: u16,
}

/// One 16-bit word, high byte first.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct DecodedWord {
    /// Its first byte in the telegram.
    pub offset: usize,
    pub name: String,
    pub value: u16,
    /// What a mapped PZD word carries under the mapping in force.
    pub carries: Option<Carried>,
    /// The fields of a control or status word, lowest bits first.
    pub fields: Vec<Field>,
    /// A gateway module's word: the node it belongs to, when known.
    pub node: Option<NodeWord>,
}

/// A 32-bit value over two words, high word first.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct DoubleWord {
    /// Its first byte in the telegram.
    pub offset: usize,
    pub name: String,
    pub value: u32,
}

/// The mapping of a PZD word and what its value makes the word carry.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Carried {
    /// The mapping entry's name: `PZD3(master->slaver)`.
    pub mapping: String,
    /// The mapping's value: a parameter address or a choice.
    pub value: u16,
    /// The parameter it names (`F0-12`) or the choice's text; `None` for a
    /// value that is not one of the choices.
    pub meaning: Option<String>,
    pub source: ValueSource,
}

/// Bits `first..=last` of a control or status word.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Field {
    pub first: u8,
    pub last: u8,
    pub name: String,
    pub value: u16,
    /// The text of the value, when the field has named values and this is one.
    pub text: Option<String>,
}

/// Decodes `bytes`, which must be as long as the telegram of `module`, a
/// PPO type or PROFINET module of this `layout`.
pub(super) fn decode(
    ir: &Ir,
    module: Module<'_>,
    layout: Layout,
    direction: Direction,
    bytes: &[u8],
    mapping: &MappingInForce,
) -> Telegram {
    debug_assert_eq!(bytes.len(), usize::from(layout.bytes()));
    let pkw_bytes = if layout.pkw { PKW_BYTES } else { 0 };
    let names = module.word_names(ir, direction);
    let words = names
        .into_iter()
        .zip(bytes.chunks_exact(2))
        .enumerate()
        .map(|(i, (name, pair))| {
            let offset = 2 * i;
            let value = u16::from_be_bytes([pair[0], pair[1]]);
            // PZD words count from 1 after the PKW channel.
            let pzd = (offset >= pkw_bytes).then(|| (offset - pkw_bytes) / 2 + 1);
            let carries = pzd
                .filter(|_| module.is_mapped())
                .and_then(|n| carried(ir, direction, n, mapping));
            let fields = match pzd {
                Some(1) => first_word_fields(ir, module, direction, value),
                _ => Vec::new(),
            };
            DecodedWord {
                offset,
                name,
                value,
                carries,
                fields,
                node: None,
            }
        })
        .collect();
    let pkw = layout
        .pkw
        .then(|| pkw_channel::decode(ir, direction, &pkw_words(bytes)))
        .flatten();
    let double_words = module
        .double_words(direction)
        .into_iter()
        .filter_map(|(word, name)| {
            let offset = 2 * word;
            let four = bytes.get(offset..offset + 4)?.try_into().ok()?;
            Some(DoubleWord {
                offset,
                name,
                value: u32::from_be_bytes(four),
            })
        })
        .collect();
    Telegram {
        module: module.name(),
        direction,
        len: bytes.len(),
        words,
        double_words,
        pkw,
        gateway: None,
    }
}

/// What PZD word `n` carries: the mapping entry numbered `n` of the
/// direction's kind, with its value in force.
fn carried(ir: &Ir, direction: Direction, n: usize, mapping: &MappingInForce) -> Option<Carried> {
    let (set, entry) = ir
        .mappings
        .group(pzd_kind(direction))?
        .entries()
        .find(|(_, e)| usize::from(e.key.number) == n)?;
    let (value, source) = mapping.value(entry);
    Some(Carried {
        mapping: entry.name.en.clone(),
        value,
        meaning: meaning(ir, &set.allowed, value),
        source,
    })
}

/// The kind of mapping a PZD word of `direction` carries.
fn pzd_kind(direction: Direction) -> MappingKind {
    match direction {
        Direction::Out => MappingKind::PzdOut,
        Direction::In => MappingKind::PzdIn,
    }
}

/// The fields of PZD1 when it is a control or status word: the
/// description's, or in a PROFIdrive card's standard telegram 1 or 2 the
/// profile's STW1 and ZSW1; with every set bit neither names.
fn first_word_fields(ir: &Ir, module: Module<'_>, direction: Direction, value: u16) -> Vec<Field> {
    let mut fields = if module.has_vendor_words() {
        match ir.telegram.word(direction) {
            Some(word) => described_fields(word, value),
            None => return Vec::new(),
        }
    } else if module.is_profidrive_telegram() {
        profidrive_fields(direction, value)
    } else {
        return Vec::new();
    };
    fields.extend(undescribed_bits(&fields, value));
    fields.sort_by_key(|f| f.first);
    fields
}

fn described_fields(word: &Word, value: u16) -> Vec<Field> {
    word.bits
        .iter()
        .map(|field| {
            let bits = BitField::new(field.first, field.last).get(value);
            let text = field.values.as_ref().and_then(|set| {
                let choice = set.choices.iter().find(|c| c.value == i64::from(bits))?;
                Some(choice.text.en.clone())
            });
            Field {
                first: field.first,
                last: field.last,
                name: field.name.en.clone(),
                value: bits,
                text,
            }
        })
        .collect()
}

/// The profile's bits of STW1 (out) or ZSW1 (in), each its own field.
fn profidrive_fields(direction: Direction, value: u16) -> Vec<Field> {
    (0..)
        .zip(profidrive::word_bits(direction))
        .map(|(bit, name)| Field {
            first: bit,
            last: bit,
            name: (*name).to_string(),
            value: (value >> bit) & 1,
            text: None,
        })
        .collect()
}

/// A field for each bit set in `value` that none of `fields` covers: the
/// card sets or reads it, and the description does not say what it means.
fn undescribed_bits(fields: &[Field], value: u16) -> Vec<Field> {
    (0..16u8)
        .filter(|&bit| value >> bit & 1 == 1)
        .filter(|&bit| !fields.iter().any(|f| (f.first..=f.last).contains(&bit)))
        .map(|bit| Field {
            first: bit,
            last: bit,
            name: format!("bit {bit} (not described)"),
            value: 1,
            text: None,
        })
        .collect()
}
