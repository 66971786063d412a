//! pnio's device model from the layout's device table (`PN_DEVICE`): what
//! the device accepts in a Connect. Nothing here is a number of its own; a deliberate
//! mismatch (the wire test's negative case) is the only change, and it says
//! which.

use pnio::cm::{DeviceModel, SlotModel, SubmoduleModel};
use pnio::eth::MacAddr;
use wire_firmware::gsdc_support::{PnDap, PnDevice, PnModule, PnSubmodule};

/// The device access point the device presents in slot 0, as the layout
/// gives it (`PnDevice::daps`).
#[derive(Debug, Clone, Copy)]
pub struct AccessPoint {
    /// Its number in the GSDML, from 1.
    pub number: usize,
    pub dap: &'static PnDap,
}

impl AccessPoint {
    /// DAP `number` (1 the first) of the layout's device, if it has one.
    pub fn of(device: &'static PnDevice, number: usize) -> Option<AccessPoint> {
        let dap = device.daps.get(number.checked_sub(1)?)?;
        Some(AccessPoint { number, dap })
    }

    /// Its own submodule, the interface (the device's) and its ports.
    fn submodules(&self, device: &PnDevice) -> impl Iterator<Item = PnSubmodule> + '_ {
        [self.dap.submodule, device.interface_submodule]
            .into_iter()
            .chain(self.dap.ports.iter().copied())
    }
}

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
    (device, dap): (&PnDevice, &AccessPoint),
    station: &str,
    mac: MacAddr,
    plugged: &[(u16, &PnModule)],
    mismatch: Option<Mismatch>,
) -> DeviceModel {
    let mut slots = vec![SlotModel {
        slot: 0,
        module_ident: dap.dap.ident,
        submodules: dap
            .submodules(device)
            .map(|s| submodule_model(&s))
            .collect(),
    }];
    for &(slot, module) in plugged {
        let mut model = SlotModel {
            slot,
            module_ident: module.ident,
            submodules: submodules(module).map(|s| submodule_model(&s)).collect(),
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
        vendor_id: device.vendor_id,
        device_id: device.device_id,
        // pnio's: the one instance of the device on its interface.
        instance: 1,
        station_name: station.to_string(),
        mac,
        max_alarm_data_length: MAX_ALARM_DATA_LENGTH,
        slots,
    }
}

/// A module's submodules: PROFIdrive's access point, if it has one, and the
/// one with the data.
fn submodules(module: &PnModule) -> impl Iterator<Item = PnSubmodule> {
    module.access_point.into_iter().chain([module.data])
}

fn submodule_model(s: &PnSubmodule) -> SubmoduleModel {
    // A submodule's IO data fits an RT frame (1440 bytes): the layouts'
    // modules carry at most 32.
    let bytes = |n: usize| u16::try_from(n).expect("IO data of an RT frame");
    SubmoduleModel {
        subslot: s.subslot,
        submodule_ident: s.ident,
        input_len: bytes(s.input_len),
        output_len: bytes(s.output_len),
    }
}

/// The API of the submodule at (slot, subslot), as the layout places it (or,
/// with [`Mismatch::Api`], API 0 for a plugged module): the access point's
/// submodules are in API 0, a module's in the module's.
pub fn api_of(
    (device, dap): (&PnDevice, &AccessPoint),
    plugged: &[(u16, &PnModule)],
    mismatch: Option<Mismatch>,
    slot: u16,
    subslot: u16,
) -> Option<u32> {
    if slot == 0 {
        let mut access_point = dap.submodules(device);
        return access_point.any(|s| s.subslot == subslot).then_some(0);
    }
    let (_, module) = plugged.iter().find(|(s, _)| *s == slot)?;
    submodules(module).find(|s| s.subslot == subslot)?;
    Some(match mismatch {
        Some(Mismatch::Api) => 0,
        _ => module.api,
    })
}
