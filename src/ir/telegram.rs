//! The cyclic telegram: parameter channel (PKW) and process data (PZD).

use super::Text;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PkwKind {
    None,
    /// PROFIdrive-style PKE (2 bytes), IND (2), PWE (4): MD810.
    PkeIndPwe,
    /// Station (2 bytes), command (2), address (2), value (2): MV810.
    StationCommandAddressValue,
}

/// Words of the PKW channel, each way, when there is one.
pub const PKW_WORDS: u8 = 4;

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Telegram {
    pub pkw: PkwKind,
    /// The most PZD words a module carries, each way.
    pub pzd_words: u8,
    pub control_word: Option<Word>,
    pub status_word: Option<Word>,
}

/// A control or status word with named bits, lowest bit first.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Word {
    pub name: Text,
    pub bits: Vec<BitField>,
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BitField {
    pub first: u8,
    pub last: u8,
    pub name: Text,
    pub values: Vec<Choice>,
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Choice {
    pub value: i64,
    pub text: Text,
}

/// One module's data: the PKW channel or not, then `pzd_words` PZD words;
/// the same length in both directions.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Layout {
    pub pkw: bool,
    pub pzd_words: u8,
}

impl Layout {
    pub fn pkw_words(self) -> u8 {
        if self.pkw {
            PKW_WORDS
        } else {
            0
        }
    }

    /// Bytes in each direction.
    pub fn bytes(self) -> u16 {
        2 * (u16::from(self.pkw_words()) + u16::from(self.pzd_words))
    }
}
