//! The card's application on the cyclic data: each cycle it reads what the
//! controller sent to the plugged modules, lets the drive act on it, and
//! writes the answer: the PKW channel answered through the layout's codec
//! against the drive model, the status word from the control word.

use crate::card::{Card, Module, Record};
use pnio::rt::IoImage;
use wire_firmware::drive::Drive;
use wire_firmware::gsdc_support::{put_words, words, U16Be};
use wire_firmware::pkw::answer;

pub struct Application {
    card: Card,
    drive: Drive,
    plugged: Vec<(u16, Module)>,
}

impl Application {
    pub fn new(card: &Card, plugged: &[(u16, &Module)]) -> Application {
        Application {
            card: card.clone(),
            drive: Drive::new(card.drive),
            plugged: plugged.iter().map(|(s, m)| (*s, (*m).clone())).collect(),
        }
    }

    /// A record the controller wrote, decoded: each value goes to the drive
    /// parameter its entry names (where the drive holds it). The values the
    /// drive refuses are returned by entry name.
    pub fn apply(&mut self, record: &Record, values: &[u16]) -> Vec<&'static str> {
        let mut refused = Vec::new();
        for (mapping, value) in record.mappings.iter().zip(values) {
            if let Some(address) = mapping.parameter {
                if self.drive.parameter(address).is_some()
                    && self.drive.write(address, *value).is_err()
                {
                    refused.push(mapping.name);
                }
            }
        }
        refused
    }

    /// One cycle over every plugged module's data submodule. Before the AR
    /// reaches data exchange there is nothing to read, and nothing happens.
    pub fn cycle(&mut self, image: &IoImage) {
        for (slot, module) in &self.plugged {
            for sub in module.submodules.iter().filter(|s| s.output_len > 0) {
                let Ok(out) = image.read_outputs(*slot, sub.subslot, |b, _| b.to_vec()) else {
                    continue;
                };
                let mut inputs = vec![0u8; usize::from(sub.input_len)];
                answer_telegram(&self.card, &mut self.drive, module.pkw, &out, &mut inputs);
                let _ = image.write_inputs(*slot, sub.subslot, &inputs);
            }
        }
    }
}

/// The drive's answer to one telegram: PKW words first when the module has
/// them, then PZD1, the control word, answered with the status word.
fn answer_telegram(card: &Card, drive: &mut Drive, pkw: bool, out: &[u8], inputs: &mut [u8]) {
    let mut pzd_at = 0;
    if let (true, Some(kind)) = (pkw, card.pkw) {
        if out.len() >= 8 && inputs.len() >= 8 {
            let request: [U16Be; 4] = words(&out[..8]);
            put_words(&mut inputs[..8], &answer(kind, drive, &request));
        }
        pzd_at = 8;
    }
    if let (Some(status_of), Some(control)) = (card.status_of, out.get(pzd_at..pzd_at + 2)) {
        let status = status_of(u16::from_be_bytes([control[0], control[1]]));
        if let Some(word) = inputs.get_mut(pzd_at..pzd_at + 2) {
            word.copy_from_slice(&status.to_be_bytes());
        }
    }
}
