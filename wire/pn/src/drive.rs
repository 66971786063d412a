//! The card's application: the records the controller wrote, decoded by the
//! layout, and each cycle the card's exchange with the drive
//! (`wire_firmware::cyclic`, the same code the DP slave runs) on every
//! plugged module's data.

use pnio::rt::IoImage;
use wire_firmware::card::Card;
use wire_firmware::cyclic::{exchange, PzdTargets, Shape};
use wire_firmware::drive::Drive;
use wire_firmware::gsdc_support::{Mapping, PnModule, PnRecord};

/// The entries of a record the controller wrote, each with its value.
pub type Decoded = Vec<(&'static Mapping, u16)>;

/// A record the controller wrote, as the layout decoded it: each value in
/// record order with its name (a module's entries, then the fail-safe
/// values it ends with; the values of a record of the access point or a
/// port), and the names of the entries whose values the drive refused.
pub struct Written {
    pub values: Vec<(String, u32)>,
    pub refused: Vec<&'static str>,
}

pub struct Application {
    card: &'static Card,
    drive: Drive,
    /// The ident number of the device access point it presents in slot 0.
    dap_ident: u32,
    plugged: Vec<(u16, &'static PnModule)>,
    /// Each record's values: the GSDML's until the controller writes it.
    records: Vec<(&'static PnRecord, Decoded)>,
    /// The 32-bit values last read from the controller's data.
    double_words: Vec<DoubleWord>,
}

/// A 32-bit value the layout read from the controller's data.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DoubleWord {
    pub slot: u16,
    pub subslot: u16,
    /// Its first PZD word, from 1.
    pub word: usize,
    pub value: u32,
}

impl Application {
    pub fn new(
        card: &'static Card,
        dap_ident: u32,
        plugged: &[(u16, &'static PnModule)],
    ) -> Application {
        let records = plugged
            .iter()
            .flat_map(|(_, m)| m.records)
            .map(|r| {
                (
                    r,
                    r.entries
                        .iter()
                        .copied()
                        .zip(r.defaults.iter().copied())
                        .collect(),
                )
            })
            .collect();
        Application {
            card,
            drive: wire_firmware::manuals::drive(card),
            dap_ident,
            plugged: plugged.to_vec(),
            records,
            double_words: Vec::new(),
        }
    }

    /// The record a Write carried, decoded by the layout (the plugged
    /// module's record of that index, on its data submodule; in slot 0 the
    /// card's own record of the access point or a port), or `None` when
    /// the layout has no such record. A module's values go to the drive
    /// parameters its entries name, where the drive holds them; the names
    /// of those the drive refuses are returned with the values.
    pub fn write(
        &mut self,
        slot: u16,
        subslot: u16,
        index: u16,
        bytes: &[u8],
    ) -> Option<Result<Written, String>> {
        if slot == 0 {
            return self.write_own(subslot, index, bytes);
        }
        let (_, module) = self.plugged.iter().find(|(s, _)| *s == slot)?;
        let record = module
            .records
            .iter()
            .find(|r| module.data.subslot == subslot && r.index == index)?;
        let mut values = vec![0; record.entries.len()];
        let mut fail_safe = vec![0; record.fail_safe.len()];
        let decoded = record
            .decode(bytes, &mut values)
            .and_then(|()| record.decode_fail_safe(bytes, &mut fail_safe));
        if let Err(e) = decoded {
            return Some(Err(format!("{e:?}")));
        }
        let decoded: Decoded = record.entries.iter().copied().zip(values).collect();
        let mut refused = Vec::new();
        for &(entry, value) in &decoded {
            let Some(address) = entry.parameter else {
                continue;
            };
            if self.drive.parameter(address).is_some() && self.drive.write(address, value).is_err()
            {
                refused.push(entry.name);
            }
        }
        if let Some(held) = self
            .records
            .iter_mut()
            .find(|(r, _)| core::ptr::eq(*r, record))
        {
            held.1 = decoded.clone();
        }
        let named = decoded
            .iter()
            .map(|(e, v)| (e.name.to_string(), u32::from(*v)));
        let fail_safe = fail_safe
            .into_iter()
            .enumerate()
            .map(|(i, v)| (format!("fail-safe value {}", i + 1), v));
        Some(Ok(Written {
            values: named.chain(fail_safe).collect(),
            refused,
        }))
    }

    /// A record of the access point's own submodule or of a port, decoded
    /// by its DAP's `access_point_records` or `port_records` in the layout
    /// (`PnDevice::own_record`). These are
    /// the card's settings, not the drive's: the card keeps none of them.
    fn write_own(&self, subslot: u16, index: u16, bytes: &[u8]) -> Option<Result<Written, String>> {
        let pn = self.card.pn?;
        // Of the access point it presents, or of another of its ident
        // number, which the controller may have been configured with.
        let daps = pn.daps.iter().filter(|d| d.ident == self.dap_ident);
        let port = if daps.clone().any(|d| d.submodule.subslot == subslot) {
            false
        } else if daps.flat_map(|d| d.ports).any(|p| p.subslot == subslot) {
            true
        } else {
            return None;
        };
        let record = pn.own_record(self.dap_ident, port, index)?;
        let mut values = vec![0; record.values.len()];
        if let Err(e) = record.decode(bytes, &mut values) {
            return Some(Err(format!("{e:?}")));
        }
        let names = record.values.iter().map(|v| v.name.to_string());
        Some(Ok(Written {
            values: names.zip(values).collect(),
            refused: Vec::new(),
        }))
    }

    /// One cycle over every plugged module's data, and the 32-bit values
    /// the layout read that differ from the last cycle's. Before the AR
    /// reaches data exchange there is nothing to read, and nothing happens.
    pub fn cycle(&mut self, image: &IoImage) -> Vec<DoubleWord> {
        let Some(pn) = self.card.pn else {
            return Vec::new();
        };
        let mut read = Vec::new();
        // The values of the plugged module's records (the one module of a
        // drive's card), as PN_DEVICE maps them to PZD words.
        let pzds = PzdTargets::of_records(pn, |index, entry| {
            let (_, decoded) = self.records.iter().find(|(r, _)| r.index == index)?;
            decoded.get(entry).map(|&(_, value)| value)
        });
        for (slot, module) in &self.plugged {
            let data = module.data;
            if data.output_len == 0 {
                continue;
            }
            let Ok(from_controller) = image.read_outputs(*slot, data.subslot, |b, _| b.to_vec())
            else {
                continue;
            };
            let mut to_controller = vec![0u8; data.input_len];
            let shape = Shape::of_pn(module);
            read.extend(
                shape
                    .double_words_of(&from_controller)
                    .map(|(word, value)| DoubleWord {
                        slot: *slot,
                        subslot: data.subslot,
                        word,
                        value,
                    }),
            );
            exchange(
                self.card,
                shape,
                &pzds,
                &mut self.drive,
                &from_controller,
                &mut to_controller,
            );
            let _ = image.write_inputs(*slot, data.subslot, &to_controller);
        }
        let changed = read
            .iter()
            .filter(|d| !self.double_words.contains(d))
            .copied()
            .collect();
        self.double_words = read;
        changed
    }
}
