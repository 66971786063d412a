//! The card's application: the records the controller wrote, decoded by the
//! layout, and each cycle the card's exchange with the drive
//! (`wire_firmware::cyclic`, the same code the DP slave runs) on every
//! plugged module's data.

use pnio::rt::IoImage;
use wire_firmware::card::{Card, PnModule, PnRecord, PrmValues};
use wire_firmware::cyclic::{exchange, Shape};
use wire_firmware::drive::Drive;

pub struct Application {
    card: &'static Card,
    drive: Drive,
    plugged: Vec<(u16, &'static PnModule)>,
    /// Each record's values, the layout's defaults until the controller
    /// writes it.
    records: Vec<(&'static PnRecord, PrmValues)>,
}

impl Application {
    pub fn new(card: &'static Card, plugged: &[(u16, &'static PnModule)]) -> Application {
        let records = plugged
            .iter()
            .flat_map(|(_, m)| m.records)
            .map(|r| {
                let defaults: Vec<u16> = r.mappings.iter().map(|m| m.default).collect();
                (r, PrmValues::EMPTY.with(r.mappings, &defaults))
            })
            .collect();
        Application {
            card,
            drive: Drive::new(wire_firmware::manuals::for_description(card.name)),
            plugged: plugged.to_vec(),
            records,
        }
    }

    /// The record a Write carried, decoded by the layout (the plugged
    /// module's record of that subslot and index), or `None` when the layout
    /// has no such record. Its values go to the drive parameters its entries
    /// name, where the drive holds them; the names of those the drive
    /// refuses are returned with the values.
    pub fn write(
        &mut self,
        slot: u16,
        subslot: u16,
        index: u16,
        bytes: &[u8],
    ) -> Option<Result<(PrmValues, Vec<&'static str>), String>> {
        let (_, module) = self.plugged.iter().find(|(s, _)| *s == slot)?;
        let record = module
            .records
            .iter()
            .find(|r| r.subslot == subslot && r.index == index)?;
        let values = match (record.decode)(bytes) {
            Ok(values) => values,
            Err(e) => return Some(Err(format!("{e:?}"))),
        };
        let mut refused = Vec::new();
        for (mapping, (_, value)) in record.mappings.iter().zip(values.iter()) {
            let Some(address) = mapping.parameter else {
                continue;
            };
            if self.drive.parameter(address).is_some() && self.drive.write(address, value).is_err()
            {
                refused.push(mapping.name);
            }
        }
        if let Some(held) = self
            .records
            .iter_mut()
            .find(|(r, _)| std::ptr::eq(*r, record))
        {
            held.1 = values;
        }
        Some(Ok((values, refused)))
    }

    /// One cycle over every plugged module's data submodule. Before the AR
    /// reaches data exchange there is nothing to read, and nothing happens.
    pub fn cycle(&mut self, image: &IoImage) {
        let prm = self
            .records
            .iter()
            .fold(PrmValues::EMPTY, |all, (record, values)| {
                let values: Vec<u16> = values.iter().map(|(_, v)| v).collect();
                all.with(record.mappings, &values)
            });
        for (slot, module) in &self.plugged {
            let shape = Shape {
                pkw: module.pkw,
                pzd_words: module.pzd_words,
            };
            for sub in module.submodules.iter().filter(|s| s.output_len > 0) {
                let Ok(from_controller) = image.read_outputs(*slot, sub.subslot, |b, _| b.to_vec())
                else {
                    continue;
                };
                let mut to_controller = vec![0u8; usize::from(sub.input_len)];
                exchange(
                    self.card,
                    shape,
                    &prm,
                    &mut self.drive,
                    &from_controller,
                    &mut to_controller,
                );
                let _ = image.write_inputs(*slot, sub.subslot, &to_controller);
            }
        }
    }
}
