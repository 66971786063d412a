//! pnio's device model from the card's tables: what the device accepts in a
//! Connect. Nothing here is a number of its own; a deliberate mismatch (the
//! wire test's negative case) is the only change, and it says which.

use crate::card::{Card, Module, Submodule};
use pnio::cm::{DeviceModel, SlotModel, SubmoduleModel};
use pnio::eth::MacAddr;

/// How the device departs from the layout, to show that the controller sees it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mismatch {
    /// The plugged module presents another module ident (the layout's + 1).
    ModuleIdent,
    /// The plugged module's data submodule presents two more input bytes.
    InputLength,
    /// The plugged module's submodules are in API 0, as if the layout said
    /// so (the device then refuses a Connect that places them in the API the
    /// GSDML gives).
    Api,
}

pub fn device_model(
    card: &Card,
    station: &str,
    mac: MacAddr,
    plugged: &[(u16, &Module)],
    mismatch: Option<Mismatch>,
) -> DeviceModel {
    let mut slots = vec![SlotModel {
        slot: 0,
        module_ident: card.dap_ident,
        submodules: card.dap_submodules.iter().map(submodule_model).collect(),
    }];
    for &(slot, module) in plugged {
        let mut model = SlotModel {
            slot,
            module_ident: module.ident,
            submodules: module.submodules.iter().map(submodule_model).collect(),
        };
        match mismatch {
            Some(Mismatch::ModuleIdent) => model.module_ident += 1,
            Some(Mismatch::InputLength) => {
                if let Some(data) = model.submodules.iter_mut().find(|s| s.input_len > 0) {
                    data.input_len += 2;
                }
            }
            Some(Mismatch::Api) | None => {}
        }
        slots.push(model);
    }
    DeviceModel {
        vendor_id: card.vendor_id,
        device_id: card.device_id,
        instance: 1,
        station_name: station.to_string(),
        mac,
        max_alarm_data_length: 200,
        slots,
    }
}

fn submodule_model(s: &Submodule) -> SubmoduleModel {
    SubmoduleModel {
        subslot: s.subslot,
        submodule_ident: s.ident,
        input_len: s.input_len,
        output_len: s.output_len,
    }
}

/// The API of the submodule at (slot, subslot), as the layout places it (or,
/// with [`Mismatch::Api`], API 0 for a plugged module).
pub fn api_of(
    card: &Card,
    plugged: &[(u16, &Module)],
    mismatch: Option<Mismatch>,
    slot: u16,
    subslot: u16,
) -> Option<u32> {
    let submodules: &[Submodule] = if slot == 0 {
        &card.dap_submodules
    } else {
        &plugged.iter().find(|(s, _)| *s == slot)?.1.submodules
    };
    let api = submodules.iter().find(|s| s.subslot == subslot)?.api;
    Some(match mismatch {
        Some(Mismatch::Api) if slot != 0 => 0,
        _ => api,
    })
}
