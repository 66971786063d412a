//! The card's part of one cyclic exchange, on any bus: the telegram from
//! the master goes to the drive (the PKW request answered, each PZD word
//! written where its mapping says), and the telegram to the master comes
//! from the drive.

use crate::card::{Card, PrmValues};
use crate::drive::Drive;
use crate::gsdc_support::{put_words, words, PKW_BYTES};

/// What a module's telegram holds, each way.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shape {
    /// Whether it starts with the PKW channel.
    pub pkw: bool,
    /// The PZD words after it.
    pub pzd_words: usize,
}

/// Takes the master's telegram `from_master` and writes the card's answer
/// to `to_master`; both are the module's length. `prm` holds the mappings
/// the master set.
pub fn exchange(
    card: &Card,
    shape: Shape,
    prm: &PrmValues,
    drive: &mut Drive,
    from_master: &[u8],
    to_master: &mut [u8],
) {
    let pzd_at = if shape.pkw { PKW_BYTES } else { 0 };
    if shape.pkw {
        let answer = crate::pkw::answer(card.pkw, drive, &words(&from_master[..PKW_BYTES]));
        put_words(&mut to_master[..PKW_BYTES], &answer);
    }
    for word in 1..=shape.pzd_words {
        let at = pzd_at + 2 * (word - 1);
        let value = u16::from_be_bytes([from_master[at], from_master[at + 1]]);
        if let Some(address) = target(card, prm, drive, word) {
            // A cyclic word has no answer: a write the drive refuses is
            // dropped, as the drive drops it.
            let _ = drive.write(address, value);
        }
        let answer = match drive.model.status_of {
            Some(status_of) if word == 1 && card.status_word => status_of.answer(value),
            _ => source(card, prm, drive, word).map_or(0, |a| drive.read(a).unwrap_or(0)),
        };
        to_master[at..at + 2].copy_from_slice(&answer.to_be_bytes());
    }
}

/// The drive parameter PZD word `word` from the master goes to: the
/// control word's, or the one its mapping names.
fn target(card: &Card, prm: &PrmValues, drive: &Drive, word: usize) -> Option<u16> {
    if word == 1 && card.control_word {
        drive.model.control_word
    } else {
        prm.mapped(card.pzd_out, word)
    }
}

/// The drive parameter PZD word `word` to the master comes from.
fn source(card: &Card, prm: &PrmValues, drive: &Drive, word: usize) -> Option<u16> {
    if word == 1 && card.status_word {
        drive.model.status_word
    } else {
        prm.mapped(card.pzd_in, word)
    }
}
