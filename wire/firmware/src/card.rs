//! What the card's firmware reads of a layout, under the same names for
//! every description: the layout's device tables (`DP_DEVICE`, `PN_DEVICE`:
//! identity, modules, User_Prm_Data and records by name, the PKW codec, the
//! PZD words the parameters map, the control and status words, the
//! diagnosis block, a gateway's nodes), its numbering (`NUMBERING`: the
//! manual's parameter names as addresses) and a gateway's codecs. build.rs
//! fills one [`Card`] per layout ([`crate::layouts::CARDS`]) with the
//! layout's items by the names every layout gives them; no number in it is
//! written by hand or taken from anywhere but the layout.

use crate::gsdc_support::{DpDevice, Numbering, PkwCodec, PnDevice, PrmError, UserPrm};

/// One description's card.
#[derive(Clone, Copy, Debug)]
pub struct Card {
    /// The description's file name without `.toml`: `md810dp`.
    pub name: &'static str,
    /// The description's fingerprint; the GSD and GSDML built from the same
    /// description carry it in their headers.
    pub fingerprint: &'static str,
    /// The layout's `DP_DEVICE`, for a description with PROFIBUS.
    pub dp: Option<&'static DpDevice>,
    /// A gateway's codecs.
    pub gateway: Option<Gateway>,
    /// The layout's `PN_DEVICE`, for a description with PROFINET.
    pub pn: Option<&'static PnDevice>,
    /// The layout's `NUMBERING`, when the description numbers the drive's
    /// parameters.
    pub numbering: Option<&'static Numbering>,
}

impl Card {
    /// The PKW channel's codec (`PkwCodec::None` without one): both tables
    /// carry the description's one telegram.
    pub fn pkw(&self) -> PkwCodec {
        match (self.dp, self.pn) {
            (Some(dp), _) => dp.pkw,
            (None, Some(pn)) => pn.pkw,
            (None, None) => PkwCodec::None,
        }
    }

    /// Whether PZD1 from the master is the control word, and PZD1 to the
    /// master the status word.
    pub fn control_and_status_words(&self) -> (bool, bool) {
        match (self.dp, self.pn) {
            (Some(dp), _) => (dp.control_word, dp.status_word),
            (None, Some(pn)) => (pn.control_word, pn.status_word),
            (None, None) => (false, false),
        }
    }
}

/// What a gateway's slave needs of the layout beyond `DP_DEVICE`.
#[derive(Clone, Copy, Debug)]
pub struct Gateway {
    /// The nodes User_Prm_Data puts in use, with where each one's words
    /// lie, by the layout's codec; `None` when Set_Prm is refused (a value
    /// out of range, totals beyond the gateway's limits).
    pub nodes: fn(&[u8]) -> Option<NodeSetup>,
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
    pub const EMPTY: Self = NodeSetup {
        input_len: 0,
        output_len: 0,
        nodes: [None; MAX_NODES],
    };

    /// Adds `node`, the next in ascending number.
    pub fn with(mut self, node: NodeData) -> Self {
        if let Some(slot) = self.nodes.iter_mut().find(|n| n.is_none()) {
            *slot = Some(node);
            self.input_len += 2 * usize::from(node.input_words);
            self.output_len += 2 * usize::from(node.output_words);
        }
        self
    }

    /// The nodes in use, in ascending number.
    pub fn nodes(&self) -> impl Iterator<Item = &NodeData> {
        self.nodes.iter().flatten()
    }
}

/// The gateway of the layout module `$layout`: its node codec and its
/// diagnosis codec, which every gateway layout names alike
/// (`gateway::NodeConfig`, `gateway::Diagnosis`, `gateway::DIAG`).
#[macro_export]
macro_rules! gateway_of {
    ($layout:path) => {{
        use $layout as layout;
        $crate::card::Gateway {
            nodes: |user_prm| {
                let config = layout::gateway::NodeConfig::decode(user_prm).ok()?;
                // Totals the layout refuses are a parameter fault too.
                let totals = config.totals().ok()?;
                let mut setup = $crate::card::NodeSetup::EMPTY;
                for (i, node) in (layout::gateway::FIRST_NODE..)
                    .take(usize::from(config.node_count))
                    .enumerate()
                {
                    setup = setup.with($crate::card::NodeData {
                        node,
                        input_offset: config.input_offset(node).unwrap_or(0),
                        input_words: config.input_words[i],
                        output_offset: config.output_offset(node).unwrap_or(0),
                        output_words: config.output_words[i],
                    });
                }
                debug_assert_eq!(
                    (setup.input_len, setup.output_len),
                    (totals.input_len(), totals.output_len())
                );
                Some(setup)
            },
            diagnosis: |event| {
                let diag = &layout::gateway::DIAG;
                // The block of the event's type has its code in a byte or
                // in a word: the one the layout's decoder takes.
                let byte = u8::try_from(event.code).ok().map(|code| {
                    let block = $crate::gsdc_support::gateway::DiagBlock::<
                        { layout::gateway::DIAG_MAX_LEN },
                    >::new(
                        (diag.code_at + 1) as u8, diag, event.kind, event.node
                    );
                    block.with_code_byte(diag, code)
                });
                let word = $crate::gsdc_support::gateway::DiagBlock::<
                    { layout::gateway::DIAG_MAX_LEN },
                >::new(
                    (diag.code_at + 2) as u8, diag, event.kind, event.node
                )
                .with_code_word(diag, event.code);
                byte.into_iter()
                    .chain([word])
                    .find(|block| layout::gateway::Diagnosis::decode(block.as_bytes()).is_ok())
                    .map(|block| $crate::card::DiagBytes::new(block.as_bytes()))
            },
        }
    }};
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
    /// Every parameter of `user_prm` by its GSD name, read through the
    /// layout's table; refused (Prm_Fault) as the table refuses it: a wrong
    /// length, a value the GSD does not allow.
    pub fn read(user_prm: &UserPrm, bytes: &[u8]) -> Result<Self, PrmError> {
        user_prm.check(bytes)?;
        let mut values = PrmValues {
            values: [("", 0); MAX_PRM_VALUES],
            len: 0,
        };
        for param in user_prm.params.iter().take(MAX_PRM_VALUES) {
            values.values[values.len] = (param.name, param.read(bytes)?);
            values.len += 1;
        }
        Ok(values)
    }

    /// The value of the parameter at `place` of User_Prm_Data's parameters.
    pub fn at(&self, place: usize) -> Option<u16> {
        self.values[..self.len].get(place).map(|&(_, v)| v)
    }

    /// Every parameter's name and value, in User_Prm_Data's order.
    pub fn iter(&self) -> impl Iterator<Item = (&'static str, u16)> + '_ {
        self.values[..self.len].iter().copied()
    }

    /// The value of the parameter the GSD names `name`.
    pub fn get(&self, name: &str) -> Option<u16> {
        self.iter().find(|&(n, _)| n == name).map(|(_, v)| v)
    }
}
