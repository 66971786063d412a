//! The cyclic telegram: parameter channel (PKW) and process data (PZD).

use super::{Ident, Text};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum PkwKind {
    None,
    /// PROFIdrive-style PKE (2 bytes), IND (2), PWE (4): MD810.
    PkeIndPwe,
    /// Station (2 bytes), command (2), address (2), value (2): MV810.
    StationCommandAddressValue,
    /// The PROFIdrive profile's channel: PKE (request or response id, SPM,
    /// an 11-bit parameter number), IND (the subindex), PWE1, PWE2.
    Profidrive,
}

/// Words of the PKW channel, each way, when there is one.
pub const PKW_WORDS: u8 = 4;

#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Telegram {
    pub pkw: PkwKind,
    /// The most PZD words a module carries, each way.
    pub pzd_words: u8,
    pub control_word: Option<Word>,
    pub status_word: Option<Word>,
    /// The card implements the PROFIdrive profile: its standard telegrams
    /// are the profile's, in the profile's API with its word names.
    pub profidrive: bool,
}

impl Telegram {
    /// The word PZD1 carries in `direction`, when it has named bits.
    pub fn word(&self, direction: Direction) -> Option<&Word> {
        match direction {
            Direction::Out => self.control_word.as_ref(),
            Direction::In => self.status_word.as_ref(),
        }
    }
}

/// Which way data goes: out is master to drive (the master's outputs), in is
/// drive to master.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Direction {
    Out,
    In,
}

impl Direction {
    pub const BOTH: [Direction; 2] = [Direction::Out, Direction::In];
}

/// A control or status word with named bits, lowest bit first.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Word {
    pub name: Text,
    pub bits: Vec<BitField>,
}

#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct BitField {
    pub first: u8,
    pub last: u8,
    pub name: Text,
    /// The field's constant, unique within its word.
    pub ident: Ident,
    pub values: Option<ValueSet>,
}

/// Values with their meaning: a field's, a mapping's or a diagnosis area's.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct ValueSet {
    /// The type that enumerates them, unique within its scope.
    pub ident: Ident,
    pub choices: Vec<Choice>,
}

#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Choice {
    pub value: i64,
    pub text: Text,
    /// The value's name, unique within its set.
    pub ident: Ident,
}

/// One module's data: the PKW channel or not, then `pzd_words` PZD words;
/// the same length in both directions.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct Layout {
    pub pkw: bool,
    pub pzd_words: u8,
}

impl Layout {
    pub(crate) fn new(pkw: bool, pzd_words: u8) -> Self {
        Layout { pkw, pzd_words }
    }

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

    /// The byte where the PZD words start: after the PKW channel.
    pub fn pzd_offset(self) -> u16 {
        2 * u16::from(self.pkw_words())
    }

    /// The byte where PZD word `n` (from 1) starts.
    pub fn pzd_word_offset(self, n: u8) -> u16 {
        self.pzd_offset() + 2 * u16::from(n - 1)
    }
}
