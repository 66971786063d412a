//! What the card's firmware reads of a layout, by the same names for every
//! description: its telegram, its mappings and, per bus, its identity,
//! modules, parameters and diagnosis. Every number is a constant of the
//! layout; [`crate::layouts`] fills one [`Card`] per description.

use crate::cyclic::Shape;
use crate::gsdc_support::{Mapping, PnDevice, PnModule, PrmError};
use crate::pkw::PkwKind;

/// One description's card.
#[derive(Clone, Copy, Debug)]
pub struct Card {
    /// The description's file name without `.toml`: `md810dp`.
    pub name: &'static str,
    /// The description's fingerprint; the GSD and GSDML built from the same
    /// description carry it in their headers.
    pub fingerprint: &'static str,
    /// The PKW channel, when the telegram has one.
    pub pkw: Option<PkwKind>,
    /// Whether PZD1 from the master is the control word, and PZD1 to the
    /// master the status word.
    pub control_word: bool,
    pub status_word: bool,
    /// What the PZD words from the master carry: a mapping's `number` is
    /// its PZD word, its value a drive parameter's address.
    pub pzd_out: &'static [Mapping],
    /// What the PZD words to the master carry.
    pub pzd_in: &'static [Mapping],
    /// The status word the drive answers to the control word, by the
    /// layout's bits, for a drive whose control and status words are no
    /// parameters of its own (MV810).
    pub status_of: Option<fn(u16) -> u16>,
    pub profibus: Option<&'static Profibus>,
    pub profinet: Option<Profinet>,
}

/// What a PROFIBUS-DP slave needs of the layout.
#[derive(Clone, Copy, Debug)]
pub struct Profibus {
    /// Ident_Number: Set_Prm must carry it.
    pub ident_number: u16,
    /// The modules Chk_Cfg may plug, one at a time.
    pub modules: &'static [DpModule],
    /// The length of User_Prm_Data.
    pub user_prm_len: usize,
    /// Decodes User_Prm_Data with the layout's codec: the value of every
    /// parameter by its GSD name, or why Set_Prm is refused (Prm_Fault).
    pub decode_user_prm: fn(&[u8]) -> Result<PrmValues, PrmError>,
    /// The device-related diagnosis block, when the GSD describes one.
    pub diagnosis: Option<Diagnosis>,
    /// A gateway's nodes: then Chk_Cfg plugs any of `modules` whose words
    /// make the nodes' totals.
    pub gateway: Option<Gateway>,
}

/// What a gateway's slave needs of the layout.
#[derive(Clone, Copy, Debug)]
pub struct Gateway {
    /// The nodes User_Prm_Data puts in use, with where each one's words
    /// lie, by the layout's codec; or why Set_Prm is refused (a value out
    /// of range, totals beyond the gateway's limits).
    pub nodes: fn(&[u8]) -> Result<NodeSetup, PrmError>,
    /// The bytes of input and of output the config bytes' modules carry;
    /// `None` for config bytes that are not the gateway's modules.
    pub config_totals: fn(&[u8]) -> Option<(usize, usize)>,
    /// The block the gateway sends for a node's event, by the layout's
    /// codec; `None` for a type, node or code the layout does not list.
    pub diagnosis: fn(NodeEvent) -> Option<DiagBytes>,
}

/// What a node of a gateway reports: the diagnosis block's type, the node
/// and the code.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NodeEvent {
    pub kind: u8,
    pub node: u8,
    pub code: u16,
}

/// A diagnosis block of at most [`DiagBytes::MAX`] bytes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DiagBytes {
    bytes: [u8; DiagBytes::MAX],
    len: usize,
}

impl DiagBytes {
    /// A device-related block has at most 63 bytes (its header's length
    /// field has 6 bits).
    pub const MAX: usize = 63;

    pub fn new(block: &[u8]) -> Self {
        let mut bytes = [0; Self::MAX];
        bytes[..block.len()].copy_from_slice(block);
        DiagBytes {
            bytes,
            len: block.len(),
        }
    }

    pub fn as_bytes(&self) -> &[u8] {
        &self.bytes[..self.len]
    }
}

/// The most nodes a gateway has here.
pub const MAX_NODES: usize = 64;

/// The nodes in use and where their words lie in the data.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NodeSetup {
    /// Bytes of input (the nodes' words to the master) and of output.
    pub input_len: usize,
    pub output_len: usize,
    nodes: [Option<NodeData>; MAX_NODES],
}

/// One node in use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NodeData {
    pub node: u8,
    /// Where its words start in the input, in bytes, and how many.
    pub input_offset: usize,
    pub input_words: u8,
    /// Where its words start in the output, and how many.
    pub output_offset: usize,
    pub output_words: u8,
}

impl NodeSetup {
    pub fn new(input_len: usize, output_len: usize, nodes: &[NodeData]) -> Self {
        let mut held = [None; MAX_NODES];
        for (slot, node) in held.iter_mut().zip(nodes) {
            *slot = Some(*node);
        }
        NodeSetup {
            input_len,
            output_len,
            nodes: held,
        }
    }

    /// The nodes in use, in ascending number.
    pub fn nodes(&self) -> impl Iterator<Item = &NodeData> {
        self.nodes.iter().flatten()
    }
}

/// What a PROFINET device needs of the layout: its device table, and what
/// the table does not say yet.
#[derive(Clone, Copy, Debug)]
pub struct Profinet {
    /// The layout's `PN_DEVICE`.
    pub device: &'static PnDevice,
    /// PROVISIONAL, until `PnModule` says it: whether the module's telegram
    /// starts with the PKW channel, and its PZD words (by the module's length
    /// alone MD810's "PKW + 2 PZD" and "6 PZD", 12 bytes each, are one).
    pub shape: fn(&PnModule) -> Shape,
}

/// A module of the GSD.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DpModule {
    /// As the GSD names it: `PPO1: 4 PKW + 2 PZD`.
    pub name: &'static str,
    /// The config bytes Chk_Cfg carries for it.
    pub config: &'static [u8],
    /// Whether the telegram starts with the PKW channel.
    pub pkw: bool,
    /// The PZD words each way.
    pub pzd_words: usize,
}

impl DpModule {
    /// Bytes each way: the PKW channel's 8, then 2 per PZD word.
    pub const fn data_len(&self) -> usize {
        let pkw = if self.pkw {
            crate::gsdc_support::PKW_BYTES
        } else {
            0
        };
        pkw + 2 * self.pzd_words
    }
}

/// The device-related diagnosis block: its length and header, and the
/// area that carries the drive's code.
#[derive(Clone, Copy, Debug)]
pub struct Diagnosis {
    /// Bytes of the block, the header included.
    pub len: usize,
    /// The block with every area 0, the header first.
    pub empty: &'static [u8],
    /// The `Unit_Diag_Area` that carries the drive's code.
    pub code: crate::gsdc_support::diagnosis::DiagArea,
}

/// The most parameters a User_Prm_Data holds here.
pub const MAX_PRM_VALUES: usize = 64;

/// The values of User_Prm_Data, each with its parameter's GSD name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PrmValues {
    values: [(&'static str, u16); MAX_PRM_VALUES],
    len: usize,
}

impl PrmValues {
    pub const EMPTY: Self = PrmValues {
        values: [("", 0); MAX_PRM_VALUES],
        len: 0,
    };

    /// Adds `name` with `value`.
    pub fn with_value(mut self, name: &'static str, value: u16) -> Self {
        self.values[self.len] = (name, value);
        self.len += 1;
        self
    }

    /// Adds the values of `mappings`, in order.
    pub fn with(mut self, mappings: &[Mapping], values: &[u16]) -> Self {
        for (mapping, &value) in mappings.iter().zip(values) {
            self.values[self.len] = (mapping.name, value);
            self.len += 1;
        }
        self
    }

    /// Every parameter's name and value, in User_Prm_Data's order.
    pub fn iter(&self) -> impl Iterator<Item = (&'static str, u16)> + '_ {
        self.values[..self.len].iter().copied()
    }

    /// The value of the parameter the GSD names `name`.
    pub fn get(&self, name: &str) -> Option<u16> {
        self.iter().find(|&(n, _)| n == name).map(|(_, v)| v)
    }

    /// The value of the mapping of PZD word `word` among `mappings`.
    pub fn mapped(&self, mappings: &[Mapping], word: usize) -> Option<u16> {
        let mapping = mappings.iter().find(|m| usize::from(m.number) == word)?;
        self.get(mapping.name)
    }
}
