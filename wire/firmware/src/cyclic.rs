//! The card's part of one cyclic exchange, on any bus: the telegram from
//! the master goes to the drive (the PKW request answered, each PZD word
//! written where the parameters the master set map it), and the telegram to
//! the master comes from the drive. A 32-bit value (standard telegram 2's
//! speed setpoint NSOLL_B) the drive model follows at once: it comes back in
//! the same place (the actual speed NIST_B), the model's own behaviour.

use crate::card::{Card, PrmValues};
use crate::drive::Drive;
use crate::gsdc_support::{
    double_word, put_double_word, put_words, words, DpDevice, PnDevice, PnModule, U16Be, PKW_BYTES,
};

/// What a module's telegram holds, each way.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shape {
    /// Whether it starts with the PKW channel.
    pub pkw: bool,
    /// The PZD words after it.
    pub pzd_words: usize,
    /// The PZD words (from 1) where a 32-bit value starts, the same both
    /// ways.
    pub double_words: &'static [usize],
}

impl Shape {
    /// The telegram of a PROFINET module, as its table gives it.
    pub fn of_pn(module: &PnModule) -> Self {
        Shape {
            pkw: module.pkw,
            pzd_words: module.pzd_words,
            double_words: module.double_words,
        }
    }

    /// Each 32-bit value of the telegram `from_master`, read through the
    /// layout's support code: its first PZD word (from 1) and the value.
    pub fn double_words_of<'a>(
        &'a self,
        from_master: &'a [u8],
    ) -> impl Iterator<Item = (usize, u32)> + 'a {
        let pzd: [U16Be; MAX_PZD] = words(&from_master[self.pzd_offset()..]);
        self.double_words
            .iter()
            .map(move |&word| (word, double_word(&pzd, word - 1)))
    }

    fn pzd_offset(&self) -> usize {
        if self.pkw {
            PKW_BYTES
        } else {
            0
        }
    }
}

/// The most PZD words a telegram has here.
pub const MAX_PZD: usize = 32;

/// The drive parameters the PZD words carry as the master set them: the
/// address of PZD word `n` at `n - 1`, each way.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PzdTargets {
    from_master: [Option<u16>; MAX_PZD],
    to_master: [Option<u16>; MAX_PZD],
}

impl PzdTargets {
    pub const NONE: Self = PzdTargets {
        from_master: [None; MAX_PZD],
        to_master: [None; MAX_PZD],
    };

    /// Set_Prm's: each PZD word `DP_DEVICE` maps to a parameter of
    /// User_Prm_Data carries the drive parameter that parameter holds.
    pub fn of_user_prm(dp: &DpDevice, prm: &PrmValues) -> Self {
        let mut targets = Self::NONE;
        for p in dp.pzd_out {
            targets.set_from_master(p.word, prm.at(p.param));
        }
        for p in dp.pzd_in {
            targets.set_to_master(p.word, prm.at(p.param));
        }
        targets
    }

    /// The records': each PZD word `PN_DEVICE` maps to an entry of a record
    /// carries the value `entry(record index, place)` gives it.
    pub fn of_records(pn: &PnDevice, entry: impl Fn(u16, usize) -> Option<u16>) -> Self {
        let mut targets = Self::NONE;
        for p in pn.pzd_out {
            targets.set_from_master(p.word, entry(p.record, p.entry));
        }
        for p in pn.pzd_in {
            targets.set_to_master(p.word, entry(p.record, p.entry));
        }
        targets
    }

    fn set_from_master(&mut self, word: u8, address: Option<u16>) {
        if let Some(slot) = usize::from(word)
            .checked_sub(1)
            .and_then(|i| self.from_master.get_mut(i))
        {
            *slot = address;
        }
    }

    fn set_to_master(&mut self, word: u8, address: Option<u16>) {
        if let Some(slot) = usize::from(word)
            .checked_sub(1)
            .and_then(|i| self.to_master.get_mut(i))
        {
            *slot = address;
        }
    }

    /// The parameter PZD word `word` from the master is written to.
    fn written(&self, word: usize) -> Option<u16> {
        *self.from_master.get(word.checked_sub(1)?)?
    }

    /// The parameter PZD word `word` to the master is read from.
    fn read(&self, word: usize) -> Option<u16> {
        *self.to_master.get(word.checked_sub(1)?)?
    }
}

/// Takes the master's telegram `from_master` and writes the card's answer
/// to `to_master`; both are the module's length. `pzds` holds the mappings
/// the master set.
pub fn exchange(
    card: &Card,
    shape: Shape,
    pzds: &PzdTargets,
    drive: &mut Drive,
    from_master: &[u8],
    to_master: &mut [u8],
) {
    let pzd_at = shape.pzd_offset();
    if shape.pkw {
        let answer = crate::pkw::answer(card.pkw(), drive, &words(&from_master[..PKW_BYTES]));
        put_words(&mut to_master[..PKW_BYTES], &answer);
    }
    let (control_word, status_word) = card.control_and_status_words();
    for word in 1..=shape.pzd_words {
        let at = pzd_at + 2 * (word - 1);
        let value = u16::from_be_bytes([from_master[at], from_master[at + 1]]);
        let target = if word == 1 && control_word {
            drive.control_word()
        } else {
            pzds.written(word)
        };
        if let Some(address) = target {
            // A cyclic word has no answer: a write the drive refuses is
            // dropped, as the drive drops it.
            let _ = drive.write(address, value);
        }
        let answer = match drive.model.status_of {
            Some(status_of) if word == 1 && status_word => status_of.answer(value),
            _ if word == 1 && status_word => drive.status_word().map_or(0, |a| read(drive, a)),
            _ => pzds.read(word).map_or(0, |a| read(drive, a)),
        };
        to_master[at..at + 2].copy_from_slice(&answer.to_be_bytes());
    }
    for (word, value) in shape.double_words_of(from_master) {
        let mut pair = [U16Be::new(0); 2];
        put_double_word(&mut pair, 0, value);
        let at = pzd_at + 2 * (word - 1);
        put_words(&mut to_master[at..at + 4], &pair);
    }
}

/// What a PZD word to the master carries of the parameter at `address`: 0
/// when the drive refuses the read.
fn read(drive: &Drive, address: u16) -> u16 {
    drive.read(address).unwrap_or(0)
}
