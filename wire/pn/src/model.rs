//! pnio's device model from the card's PROFINET table: what the device
//! accepts in a Connect. Nothing here is a number of its own; a deliberate
//! mismatch (the wire test's negative case) is the only change, and it says
//! which.

use pnio::cm::{DeviceModel, SlotModel, SubmoduleModel};
use pnio::eth::MacAddr;
use wire_firmware::card::{PnModule, PnSubmodule, Profinet};

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

/// pnio's answer to a Connect's maximum alarm data length: the value pnio's
/// own configuration gives every device.
const MAX_ALARM_DATA_LENGTH: u16 = 200;

pub fn device_model(
    profinet: &Profinet,
    station: &str,
    mac: MacAddr,
    plugged: &[(u16, &PnModule)],
    mismatch: Option<Mismatch>,
) -> DeviceModel {
    let mut slots = vec![SlotModel {
        slot: 0,
        module_ident: profinet.dap_ident,
        submodules: profinet
            .dap_submodules
            .iter()
            .map(submodule_model)
            .collect(),
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
        vendor_id: profinet.vendor_id,
        device_id: profinet.device_id,
        // pnio's: the one instance of the device on its interface.
        instance: 1,
        station_name: station.to_string(),
        mac,
        max_alarm_data_length: MAX_ALARM_DATA_LENGTH,
        slots,
    }
}

fn submodule_model(s: &PnSubmodule) -> SubmoduleModel {
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
    profinet: &Profinet,
    plugged: &[(u16, &PnModule)],
    mismatch: Option<Mismatch>,
    slot: u16,
    subslot: u16,
) -> Option<u32> {
    let submodules = if slot == 0 {
        profinet.dap_submodules
    } else {
        plugged.iter().find(|(s, _)| *s == slot)?.1.submodules
    };
    let api = submodules.iter().find(|s| s.subslot == subslot)?.api;
    Some(match mismatch {
        Some(Mismatch::Api) if slot != 0 => 0,
        _ => api,
    })
}
