//! What only PROFIBUS-DP needs: identity numbers, bus parameters, the PPO
//! modules with their config bytes, the parameter telegram and diagnosis.

use super::{EntryKey, Ident, Layout, MappingKind, SetKey, ValueSet};
pub use crate::gsd::Baud;

#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Profibus {
    pub file_name: String,
    pub gsd_revision: u8,
    pub ident_number: u16,
    /// Not assigned by PI: the files say so.
    pub ident_placeholder: bool,
    pub implementation_type: Option<String>,
    pub modules: Vec<PpoModule>,
    /// Max_Input_Len and Max_Output_Len: the largest module's bytes.
    pub max_input_len: u16,
    pub max_output_len: u16,
    /// Supported baud rates with MaxTsdr in bit times, slowest first.
    pub baud_rates: Vec<(Baud, u16)>,
    /// Units of 100 us.
    pub min_slave_interval: u16,
    pub slave_family: String,
    pub auto_baud: bool,
    pub freeze_mode: bool,
    pub sync_mode: bool,
    pub dpv1: Option<Dpv1>,
    pub user_prm: UserPrm,
    pub diagnosis: Option<Diagnosis>,
    /// Max_Diag_Data_Len: the standard diagnosis and the device's block.
    pub max_diag_data_len: u8,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct Dpv1 {
    pub c1_read_write: bool,
    pub c1_max_data_len: u8,
    /// Units of 10 ms.
    pub c1_response_timeout: u16,
    pub status_bytes: [u8; 3],
}

/// A PPO type as a module: PPO1..PPO5.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct PpoModule {
    pub ppo: u8,
    pub name: String,
    pub layout: Layout,
    /// The config identifier bytes Chk_Cfg carries for this module.
    pub config: Vec<u8>,
    /// Its name in generated code: `ppo1`.
    pub ident: Ident,
}

/// Config identifier bits (IEC 61158 / EN 50170): bit 7 consistency over
/// the whole length, bit 6 words, bits 5-4 direction (11 = in and out),
/// bits 3-0 length - 1.
const CONSISTENT_WORDS_IN_OUT: u8 = 0b1111_0000;

/// Words one general identifier byte can carry.
pub const MAX_WORDS_PER_IDENTIFIER: u8 = 16;

/// PPO1 `0xF3,0xF1`: the PKW as 4 consistent words in and out, then the PZD
/// as one consistent block in and out. Lowering keeps `pzd_words` within
/// 1..=16.
pub(crate) fn config_bytes(layout: Layout) -> Vec<u8> {
    let pkw = layout.pkw.then(|| identifier(super::telegram::PKW_WORDS));
    pkw.into_iter()
        .chain(std::iter::once(identifier(layout.pzd_words)))
        .collect()
}

fn identifier(words: u8) -> u8 {
    debug_assert!((1..=MAX_WORDS_PER_IDENTIFIER).contains(&words));
    CONSISTENT_WORDS_IN_OUT | (words - 1)
}

/// The standard PPO types: (PKW, PZD words). PPO5's PZD count may differ per
/// device (MD810 has 12), so the description gives it.
pub(crate) fn ppo_layout(ppo: u8, ppo5_pzd_words: u8) -> Option<Layout> {
    let (pkw, pzd_words) = match ppo {
        1 => (true, 2),
        2 => (true, 6),
        3 => (false, 2),
        4 => (false, 6),
        5 => (true, ppo5_pzd_words),
        _ => return None,
    };
    Some(Layout::new(pkw, pzd_words))
}

/// The parameter telegram (User_Prm_Data): constant bytes at offset 0 (the
/// DPV1 status bytes), then one block of Unsigned16 parameters per group of
/// mappings, in telegram order, then a gateway's parameters, with no gaps.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct UserPrm {
    pub constant: Vec<u8>,
    pub blocks: Vec<PrmBlock>,
    /// A gateway's parameters, after the blocks: bit areas share a byte.
    pub gateway: Vec<PrmParam>,
    /// The value texts the parameters refer to.
    pub texts: Vec<PrmText>,
    /// Bytes of the whole telegram.
    pub len: u16,
}

impl UserPrm {
    pub fn params(&self) -> impl Iterator<Item = &PrmParam> {
        self.blocks
            .iter()
            .flat_map(|b| &b.params)
            .chain(&self.gateway)
    }

    pub fn block(&self, kind: MappingKind) -> Option<&PrmBlock> {
        self.blocks.iter().find(|b| b.kind == kind)
    }
}

/// The parameters of one kind of mapping, consecutive from `offset`.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct PrmBlock {
    pub kind: MappingKind,
    pub offset: u16,
    pub params: Vec<PrmParam>,
}

/// An `ExtUserPrmData`: a mapping entry (Unsigned16) or a gateway
/// parameter, at its offset.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct PrmParam {
    /// Its reference number, from 1.
    pub id: u16,
    pub offset: u16,
    pub value: PrmValue,
    pub data_type: PrmType,
    /// The `PrmText` of its values, when its set has choices.
    pub text: Option<u16>,
}

/// What a parameter holds: its name, default and range are there.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum PrmValue {
    Entry(EntryKey),
    Gateway(super::gateway::ParamKey),
}

/// How a parameter is stored, big-endian.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum PrmType {
    Unsigned8,
    Unsigned16,
    /// Bits `first..=last` of the byte at the parameter's offset (GSD
    /// `Bit(n)` or `BitArea(first-last)`); other parameters may hold the
    /// byte's other bits.
    Bits {
        first: u8,
        last: u8,
    },
}

impl PrmType {
    /// Bytes from the parameter's offset.
    pub fn bytes(self) -> u16 {
        match self {
            PrmType::Unsigned16 => 2,
            PrmType::Unsigned8 | PrmType::Bits { .. } => 1,
        }
    }

    /// The largest value it holds.
    pub fn max(self) -> u16 {
        match self {
            PrmType::Unsigned8 => 0xFF,
            PrmType::Unsigned16 => 0xFFFF,
            PrmType::Bits { first, last } => (1 << (last - first + 1)) - 1,
        }
    }
}

/// A `PrmText`: the texts of a set's choices.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct PrmText {
    /// Its reference number, from 1.
    pub id: u16,
    pub set: SetKey,
}

/// Device-related diagnosis: the block length (header byte included) and
/// texts for values of bit areas counted from the first byte after the header.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Diagnosis {
    pub length: u8,
    pub areas: Vec<DiagnosisArea>,
}

#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct DiagnosisArea {
    pub first_bit: u16,
    pub last_bit: u16,
    /// The area's constant in generated code: `bits_8_15`.
    pub ident: Ident,
    pub values: ValueSet,
}

/// Bytes of the standard diagnosis before the device-related block.
pub const STANDARD_DIAG_BYTES: u8 = 6;

#[cfg(test)]
mod tests {
    use super::*;

    fn config(ppo: u8, ppo5: u8) -> Vec<u8> {
        config_bytes(ppo_layout(ppo, ppo5).unwrap())
    }

    #[test]
    fn ppo_config_bytes_match_the_profidrive_table() {
        assert_eq!(config(1, 12), [0xF3, 0xF1]);
        assert_eq!(config(2, 12), [0xF3, 0xF5]);
        assert_eq!(config(3, 12), [0xF1]);
        assert_eq!(config(4, 12), [0xF5]);
        assert_eq!(config(5, 12), [0xF3, 0xFB]);
        assert_eq!(config(5, 10), [0xF3, 0xF9]);
    }

    #[test]
    fn ppo_lengths_in_bytes() {
        let bytes = |ppo| ppo_layout(ppo, 12).unwrap().bytes();
        assert_eq!(
            [bytes(1), bytes(2), bytes(3), bytes(4), bytes(5)],
            [12, 20, 4, 12, 32]
        );
        assert!(ppo_layout(6, 12).is_none());
    }
}
