//! Where a file's modules go: the slots its access point allows its data
//! modules (`[profinet] module_slots`), and a module without data that
//! stands in a slot where none is plugged (`[profinet.empty_module]`, SEW's
//! MOVI-C's "Empty").

use super::{api, attribute, has_io, hex32, text, Recognised};
use crate::device::pn::{Dap, ItemRef, PnDevice, PnModule};
use crate::gsdml::values::ValueList;
use crate::import::toml_out::TomlOut;
use crate::import::Notes;
use crate::ir::profinet::Slots;
use crate::lower::{EMPTY_MODULE_IDENT, MAX_SLOT};

/// A module of one submodule without IO data, records or pluggable
/// submodules, in API 0.
pub(super) fn is_empty_module(m: &PnModule) -> bool {
    m.useable_submodules.is_empty()
        && matches!(m.submodules.as_slice(), [s] if !has_io(s) && s.records.is_empty() && api(s) == 0)
}

/// The empty module of the first access point's offer, as the description
/// states it.
pub(super) struct Empty<'a> {
    pub module: &'a PnModule,
    pub slots: Slots,
}

impl Empty<'_> {
    /// `[profinet.empty_module]`: the texts, the slots, and the ident
    /// numbers where not gsdc's.
    pub fn write(&self, out: &mut TomlOut) {
        let m = self.module;
        out.table("profinet.empty_module");
        if let Some(name) = &m.name {
            out.key("name", text(name));
        }
        if let Some(info) = m.info.as_ref().filter(|&i| Some(i) != m.name.as_ref()) {
            out.key("info", text(info));
        }
        out.key("slots", slot_list(self.slots));
        let ident = m.ident.unwrap_or(EMPTY_MODULE_IDENT);
        if ident != EMPTY_MODULE_IDENT {
            out.key("ident", hex32(ident));
        }
        let submodule = m.submodules.first().and_then(|s| s.ident);
        if let Some(s) = submodule.filter(|&s| s != ident) {
            out.key("submodule_ident", hex32(s));
        }
    }
}

/// The first empty module `dap` offers, in one range of slots, with a
/// name and an ident number no other module or access point has
/// (`taken`); another, or one the description cannot say, is left out
/// with why.
pub(super) fn empty_module<'a>(
    device: &'a PnDevice,
    dap: &'a Dap,
    taken: &[u32],
    notes: &mut Notes,
) -> Option<Empty<'a>> {
    let mut found = None;
    for (reference, module) in offered(device, dap).filter(|(_, m)| is_empty_module(m)) {
        let why = match (&found, one_range(reference)) {
            (Some(_), _) => "the description has one empty module".to_string(),
            (None, Err(why)) => why,
            (None, Ok(_)) if module.name.is_none() => "it has no name".into(),
            (None, Ok(_)) if module.ident.is_some_and(|i| i == 0 || taken.contains(&i)) => {
                "its ModuleIdentNumber is 0 or another module's or access point's, which the description's cannot share (E176)".into()
            }
            (None, Ok(slots)) => {
                found = Some(Empty { module, slots });
                continue;
            }
        };
        notes.unsaid(&format!("module `{}`", module.id), &module.place, &why);
    }
    found
}

/// The modules `dap` offers, each with its reference.
pub(super) fn offered<'a>(
    device: &'a PnDevice,
    dap: &'a Dap,
) -> impl Iterator<Item = (&'a ItemRef, &'a PnModule)> {
    dap.useable_modules.iter().filter_map(|r| {
        let module = device.modules.iter().find(|m| m.id == r.target)?;
        Some((r, module))
    })
}

/// The slots the first access point allows every data module, where it
/// allows them all the same one range; else slot 1, and each module
/// allowed another range is left out of the slots with why (the round trip
/// judges it). A reference without a list of slots says nothing here.
pub(super) fn module_slots(dap: &Dap, modules: &[Recognised], notes: &mut Notes) -> Slots {
    let has_slots = |r: &&ItemRef| {
        ["AllowedInSlots", "FixedInSlots", "UsedInSlots"]
            .iter()
            .any(|a| attribute(&r.attributes, a).is_some())
    };
    let references = modules.iter().filter_map(|m| {
        let target = &m.module.id;
        dap.useable_modules.iter().find(|r| r.target == *target)
    });
    let references = references.filter(has_slots);
    let mut shared: Option<Slots> = None;
    for reference in references {
        let slots = match one_range(reference) {
            Ok(slots) if shared.is_none_or(|s| s == slots) => {
                shared = Some(slots);
                continue;
            }
            Ok(slots) => format!(
                "its slots {slots} are not the first module's, {}: the description's data modules share theirs",
                shared.unwrap_or(Slots::ONE)
            ),
            Err(why) => why,
        };
        notes.unsaid(
            &format!("ModuleItemRef `{}` AllowedInSlots", reference.target),
            &reference.place,
            &slots,
        );
    }
    shared.unwrap_or(Slots::ONE)
}

/// A reference's `AllowedInSlots` as one range of slots, or why not.
pub(super) fn one_range(reference: &ItemRef) -> Result<Slots, String> {
    for fixed in ["FixedInSlots", "UsedInSlots"] {
        if attribute(&reference.attributes, fixed).is_some() {
            return Err(format!("it has {fixed}, which the description cannot say"));
        }
    }
    let Some(value) = attribute(&reference.attributes, "AllowedInSlots") else {
        return Err("it has no AllowedInSlots, which gsdc writes".into());
    };
    let ranges = ValueList::parse(value).map(|l| l.ranges().to_vec());
    let within = |n: u32| u16::try_from(n).ok().filter(|n| (1..=MAX_SLOT).contains(n));
    match ranges.as_deref() {
        Some(&[(first, last)]) => match (within(first), within(last)) {
            (Some(first), Some(last)) => Ok(Slots { first, last }),
            _ => Err(format!(
                "AllowedInSlots `{value}` is not within the slots 1 to {MAX_SLOT} the description takes"
            )),
        },
        _ => Err(format!(
            "AllowedInSlots `{value}` is not one range of slots, which the description says"
        )),
    }
}

/// `[first, last]`.
pub(super) fn slot_list(slots: Slots) -> String {
    format!("[{}, {}]", slots.first, slots.last)
}
