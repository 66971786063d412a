//! The device access points after the first, as `[[profinet.daps]]`: what
//! each says that differs from the first, in the keys the description has
//! for it. One that the format cannot say is left out (W600), with why.

use super::own_records::{own_records, OwnRecords};
use super::stack::{Declared, Placed};
use super::{attribute, hex32, list, mrp_client, submodules_of as submodules, text, Recognised};
use crate::device::pn::{Dap, PnDevice, SubmoduleKind};
use crate::device::{Attribute, Text};
use crate::import::toml_out::TomlOut;
use crate::import::Notes;
use crate::ir::profinet::Version;
use crate::lower::Offer;

/// What the description's device access points share: the first's value
/// stands for every one (`[profinet]` states it once).
const SHARED: &[&str] = &[
    // The device symbol: the description has one, for every DAP.
    crate::import::symbol::GSDML_SYMBOL_TYPE,
    crate::import::symbol::GSDML_SYMBOL_TARGET,
    "RequiredSchemaVersion",
    "ImplementationType",
    "MinDeviceInterval",
    "DNS_CompatibleName",
    "ModuleInfo/VendorName@Value",
    "CertificationInfo@ConformanceClass",
    "CertificationInfo@NetloadClass",
    super::profienergy::ASE_SUPPORTED,
];
const SHARED_INTERFACE: &[&str] = &[
    "ApplicationRelations/TimingProperties@SendClock",
    "ApplicationRelations/TimingProperties@PreferredSendClock",
];

/// A later device access point, as the description says it.
pub(super) struct DapEntry<'a> {
    pub dap: &'a Dap,
    keys: Vec<(&'static str, String)>,
    /// Its records where not the first's.
    records: OwnRecords,
}

impl DapEntry<'_> {
    pub fn write(&self, out: &mut TomlOut) {
        out.array_item("profinet.daps");
        for (key, value) in &self.keys {
            out.key(key, value);
        }
        self.records.write_later(out);
    }
}

/// Each device access point of `device` after the first that the format
/// can say; the others are left out (W600) with the reason. `device_info`
/// is DeviceIdentity's info text: what an entry without `info` gets;
/// `taken` the ident numbers of the first and of the modules imported.
pub(super) fn later_daps<'a>(
    offer: &Offered<'a, '_>,
    (first_stack, file): (&Declared, Version),
    device_info: Option<&Text>,
    (placed, taken, first_records): (&Placed, Vec<u32>, &OwnRecords),
    notes: &mut Notes,
) -> Vec<DapEntry<'a>> {
    let (first, others) = (&offer.device.daps[0], &offer.device.daps[1..]);
    let modules = offer.modules;
    let mut later: Vec<DapEntry> = Vec::new();
    for dap in others {
        let imported: Vec<&Dap> = std::iter::once(first)
            .chain(later.iter().map(|l| l.dap))
            .collect();
        let idents = (&taken[..], &imported[..]);
        let keys =
            entry_keys((first, dap), device_info, offer, idents, file).and_then(|mut keys| {
                let stack =
                    Declared::of(dap, (modules, placed), file, notes).over_first(first_stack)?;
                if !stack.is_empty() {
                    let pairs: Vec<String> =
                        stack.iter().map(|(k, v)| format!("{k} = {v}")).collect();
                    keys.push(("stack", format!("{{ {} }}", pairs.join(", "))));
                }
                Ok(keys)
            });
        match keys {
            Ok(keys) => {
                let records = own_records(dap, notes).unlike(first_records);
                later.push(DapEntry { dap, keys, records });
            }
            Err(why) => notes.unsaid(
                &format!("device access point `{}`", dap.item.id),
                &dap.item.place,
                &why,
            ),
        }
    }
    later
}

/// The modules the import takes, for the device access points to offer.
pub(super) struct Offered<'d, 'o> {
    pub device: &'d PnDevice,
    pub modules: &'o [Recognised<'d>],
    /// The safety modules imported, by their IDs.
    pub safety: &'o [(String, Offer)],
}

/// The keys of `dap`'s `[[profinet.daps]]` entry, or why it has none.
/// `taken` are the ident numbers of the modules and of the first DAP,
/// `imported` the DAPs imported before it.
fn entry_keys(
    (first, dap): (&Dap, &Dap),
    device_info: Option<&Text>,
    offer: &Offered,
    (taken, imported): (&[u32], &[&Dap]),
    file: Version,
) -> Result<Vec<(&'static str, String)>, String> {
    let ident = dap
        .item
        .ident
        .filter(|&i| i != 0)
        .ok_or("it has no ModuleIdentNumber the description can state")?;
    match imported.iter().find(|d| d.item.ident == Some(ident)) {
        Some(same) => same_slot_zero(same, dap)?,
        None if taken.contains(&ident) => {
            return Err(format!(
                "its ModuleIdentNumber 0x{ident:08X} is a module's, which the description's cannot share (E176)"
            ))
        }
        None => {}
    }
    shared_as_first(first, dap)?;
    let mut keys = vec![
        ("name", text(&dap.item.name.clone().unwrap_or_default())),
        ("ident", hex32(ident)),
    ];
    if let Some(info) = dap.item.info.as_ref().filter(|&i| Some(i) != device_info) {
        keys.push(("info", text(info)));
    }
    let own_submodule = submodules(dap, SubmoduleKind::Virtual).next();
    if let Some(s) = own_submodule.filter(|s| s.ident != Some(ident)) {
        keys.push(("submodule_ident", hex32(s.ident.unwrap_or(0))));
    }
    for (key, name) in [
        ("order_number", "ModuleInfo/OrderNumber@Value"),
        ("hardware_release", "ModuleInfo/HardwareRelease@Value"),
        ("software_release", "ModuleInfo/SoftwareRelease@Value"),
    ] {
        let value = attribute(&dap.item.attributes, name);
        if value != attribute(&first.item.attributes, name) {
            // A later DAP without the value would take the first's.
            let value = value.ok_or(format!("it has no {key}, which the first has"))?;
            keys.push((key, super::quote(value)));
        }
    }
    if let Some(version) = pnio_version(first, dap, file)? {
        keys.push(("pnio_version", super::quote(&version.number())));
    }
    keys.extend(ports(first, dap));
    if mrp_client(dap) != mrp_client(first) {
        keys.push(("media_redundancy", mrp_client(dap).to_string()));
    }
    if let Some(names) = offered(first, dap, offer)? {
        keys.push(("modules", names));
    }
    Ok(keys)
}

/// Err when `dap` shares `same`'s ident number but not its slot 0: its
/// own submodule's and its ports' ident numbers (E162).
fn same_slot_zero(same: &Dap, dap: &Dap) -> Result<(), String> {
    let slot_zero = |d: &Dap| {
        let own = submodules(d, SubmoduleKind::Virtual)
            .next()
            .map(|s| s.ident);
        let ports: Vec<Option<u32>> = submodules(d, SubmoduleKind::Port)
            .map(|s| s.ident)
            .collect();
        (own, ports)
    };
    if slot_zero(same) == slot_zero(dap) {
        return Ok(());
    }
    Err(format!(
        "its ModuleIdentNumber is device access point `{}`'s, whose own submodule or ports have other ident numbers: the device could not tell which slot 0 a project expects (E162)",
        same.item.id
    ))
}

/// `dap`'s PNIO_Version where it is not the first's (SEW's MOVI-C: V2.33,
/// then V2.34): a version from V1.0 to the file's, which a description
/// can state (E197).
fn pnio_version(first: &Dap, dap: &Dap, file: Version) -> Result<Option<Version>, String> {
    const NAME: &str = "PNIO_Version";
    let (mine, firsts) = (
        attribute(&dap.item.attributes, NAME),
        attribute(&first.item.attributes, NAME),
    );
    if mine == firsts {
        return Ok(None);
    }
    mine.and_then(Version::parse)
        .filter(|&v| v >= Version::new(1, 0) && v <= file)
        .map(Some)
        .ok_or(format!(
            "its PNIO_Version is not the first device access point's, and no version from V1.0 to the file's, {file}, which a description can state (E197)"
        ))
}

/// Err when `dap` differs from the first in what the description's
/// device access points share.
fn shared_as_first(first: &Dap, dap: &Dap) -> Result<(), String> {
    let of_kind = |d: &Dap, kind| -> Vec<Attribute> {
        submodules(d, kind)
            .flat_map(|s| s.attributes.clone())
            .collect()
    };
    let interface = |d: &Dap| of_kind(d, SubmoduleKind::Interface);
    // Its own submodule's PROFIenergy: the description's is every one's.
    let own = |d: &Dap| of_kind(d, SubmoduleKind::Virtual);
    let pairs = [
        (
            SHARED,
            first.item.attributes.clone(),
            dap.item.attributes.clone(),
        ),
        (SHARED_INTERFACE, interface(first), interface(dap)),
        (
            &super::profienergy::SUBMODULE_ATTRIBUTES,
            own(first),
            own(dap),
        ),
    ];
    for (names, a, b) in &pairs {
        for name in names.iter() {
            if attribute(a, name) != attribute(b, name) {
                return Err(format!(
                    "its {name} is not the first device access point's, and the description's share it"
                ));
            }
        }
    }
    let interface_ident = |d: &Dap| {
        submodules(d, SubmoduleKind::Interface)
            .next()
            .and_then(|s| s.ident)
    };
    if interface_ident(first) != interface_ident(dap) {
        return Err(
            "its interface's SubmoduleIdentNumber is not the first device access point's, and the description's share it".into(),
        );
    }
    let im = |d: &Dap| {
        submodules(d, SubmoduleKind::Virtual)
            .next()
            .and_then(|s| attribute(&s.attributes, "Writeable_IM_Records"))
            .map(str::to_string)
    };
    if im(first) != im(dap) {
        return Err("its Writeable_IM_Records are not the first device access point's, and the description's share them".into());
    }
    Ok(())
}

/// `ports` and `port_idents`, where they are not what the first DAP's
/// would give.
fn ports(first: &Dap, dap: &Dap) -> Vec<(&'static str, String)> {
    let idents = |d: &Dap| -> Vec<u32> {
        submodules(d, SubmoduleKind::Port)
            .map(|s| s.ident.unwrap_or(0))
            .collect()
    };
    let (mine, firsts) = (idents(dap), idents(first));
    let mut keys = Vec::new();
    if mine.len() != firsts.len() {
        keys.push(("ports", mine.len().to_string()));
    }
    if !firsts.starts_with(&mine) {
        keys.push(("port_idents", list(mine.iter().copied().map(hex32))));
    }
    keys
}

/// The modules the DAP offers (its `modules`, the first's `dap_modules`),
/// when fewer than the data and safety modules imported; Err when it
/// offers a data module the first does not, which the import does not
/// read. A module the first offers, or a safety module, that the import
/// leaves out is left out with its reason, here too.
pub(super) fn offered(first: &Dap, dap: &Dap, offer: &Offered) -> Result<Option<String>, String> {
    let Offered {
        device,
        modules,
        safety,
    } = *offer;
    let safety_module = |id: &str| {
        device
            .modules
            .iter()
            .any(|m| m.id == id && super::safety::is_safety_module(m))
    };
    let mut names = Vec::new();
    let mut data_modules = 0;
    for r in &dap.useable_modules {
        let data = modules.iter().find(|m| m.module.id == r.target);
        data_modules += usize::from(data.is_some());
        let safety_number = safety.iter().position(|(id, _)| *id == r.target);
        let name = data
            .map(|m| m.code_name())
            .or_else(|| safety_number.map(|n| crate::ir::safety::code_name(n + 1)));
        match name {
            Some(name) => {
                let name = super::quote(&name);
                if !names.contains(&name) {
                    names.push(name);
                }
            }
            None if first.useable_modules.iter().any(|f| f.target == r.target) => {}
            None if safety_module(&r.target) => {}
            None => {
                return Err(format!(
                    "it offers module `{}`, which the first device access point does not (the import takes the data modules the first offers)",
                    r.target
                ))
            }
        }
    }
    if data_modules == 0 {
        return Err("it offers none of the data modules the import takes".into());
    }
    let every = modules.len() + safety.len();
    Ok((names.len() != every).then(|| list(names)))
}
