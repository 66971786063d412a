//! A file's PROFIsafe modules (`[[profinet.safety_modules]]`): their
//! safety IO data, F-parameters and description CRCs, carried as the file
//! has them and pinned to gsdc's fingerprint of what they describe.

use super::own_records::{safety_records, SafetyRecords};
use super::slots::{offered, one_range, slot_list};
use super::stack::is_true;
use super::{attribute, hex32, text, Notes, SUBMODULE_ATTRIBUTES};
use crate::description::safety::OPTIONAL_F_PARAMETERS;
use crate::device::pn::{Dap, DataItem, IoPart, PnDevice, PnModule, Submodule};
use crate::device::Attribute;
use crate::import::toml_out::{quote, TomlOut};
use crate::ir::profinet::Slots;
use crate::ir::safety::{
    crc_fingerprint, Described, FParameter, ItemShape, SafetyDataType, F_PARAMETER_ATTRIBUTES,
    F_PARAMETER_ELEMENTS,
};
use crate::lower::Offer;
use std::collections::BTreeSet;

const F_RECORD: &str = "RecordDataList/F_ParameterRecordDataItem";
const IO_CRC: &str = "IOData@F_IO_StructureDescCRC";
const IO_VERSION: &str = "IOData@F_IO_StructureDescVersion";
const CONSISTENCY: &str = "All items consistency";

/// A module whose one submodule says it supports PROFIsafe.
pub(super) fn is_safety_module(m: &PnModule) -> bool {
    matches!(m.submodules.as_slice(), [s] if attribute(&s.attributes, "PROFIsafeSupported").is_some_and(is_true))
}

/// A safety module as the description states it.
pub(super) struct Safety<'a> {
    module: &'a PnModule,
    submodule: &'a Submodule,
    pub slots: Slots,
    f_parameter_index: u16,
    f_parameters: Vec<FParameter>,
    io_structure_desc_version: Option<u8>,
    crcs: (u16, u32),
    /// Its submodule's records besides the F-parameters.
    records: SafetyRecords,
}

impl Safety<'_> {
    /// What it adds to each CR.
    pub fn offer(&self) -> Offer {
        let bytes = |p: &Option<IoPart>| {
            let len = p.as_ref().map_or(0, IoPart::len);
            u16::try_from(len).unwrap_or(u16::MAX)
        };
        Offer {
            slots: self.slots,
            input: bytes(&self.submodule.io.input) + 2,
            output: bytes(&self.submodule.io.output) + 2,
        }
    }

    pub fn id(&self) -> &str {
        &self.module.id
    }

    /// `[[profinet.safety_modules]]`.
    pub fn write(&self, out: &mut TomlOut) {
        let (m, s) = (self.module, self.submodule);
        out.array_item("profinet.safety_modules");
        if let Some(name) = &m.name {
            out.key("name", text(name));
        }
        if let Some(info) = m.info.as_ref().filter(|&i| Some(i) != m.name.as_ref()) {
            out.key("info", text(info));
        }
        let ident = m.ident.unwrap_or_default();
        out.key("ident", hex32(ident));
        if let Some(sub) = s.ident.filter(|&sub| sub != ident) {
            out.key("submodule_ident", hex32(sub));
        }
        if let Some(name) = s.name.as_ref().filter(|&n| Some(n) != m.name.as_ref()) {
            out.key("submodule_name", text(name));
        }
        if let Some(info) = s.info.as_ref().filter(|&i| Some(i) != m.info.as_ref()) {
            out.key("submodule_info", text(info));
        }
        if let Some(category) = m.attributes.iter().find(|a| &*a.name == super::CATEGORY) {
            if let crate::device::AttributeValue::Text(t) = &category.value {
                out.key("category", text(t));
            }
        }
        out.key("slots", slot_list(self.slots));
        if let Some(version) = self.io_structure_desc_version {
            out.key("io_structure_desc_version", version);
        }
        for (key, part) in [("input", &s.io.input), ("output", &s.io.output)] {
            let items = part.as_ref().map_or(&[][..], |p| &p.items[..]);
            out.key(key, item_list(items));
        }
        out.table("profinet.safety_modules.crcs");
        out.key("f_param_desc", self.crcs.0);
        out.key("f_io_structure_desc", self.crcs.1);
        out.key("of", quote(&self.fingerprint()));
        out.table("profinet.safety_modules.f_parameters");
        out.key("index", self.f_parameter_index);
        for p in self
            .f_parameters
            .iter()
            .filter(|p| !p.attributes.is_empty())
        {
            out.key(p.element, parameter_table(p));
        }
        self.records.write(out);
    }

    /// The fingerprint the build computes of what the CRCs describe.
    fn fingerprint(&self) -> String {
        let shapes = |p: &Option<IoPart>| -> Vec<ItemShape> {
            let items = p.as_ref().map_or(&[][..], |p| &p.items[..]);
            items.iter().filter_map(shape).collect()
        };
        crc_fingerprint(&Described {
            f_parameter_index: self.f_parameter_index,
            f_parameters: &self.f_parameters,
            io_structure_desc_version: self.io_structure_desc_version,
            input: &shapes(&self.submodule.io.input),
            output: &shapes(&self.submodule.io.output),
        })
    }
}

fn shape(item: &DataItem) -> Option<ItemShape> {
    Some(ItemShape {
        data_type: SafetyDataType::from_name(&item.data_type)?,
        use_as_bits: item.use_as_bits,
        bits: item
            .bits
            .iter()
            .map(|(offset, _)| u8::try_from(*offset).ok())
            .collect::<Option<_>>()?,
    })
}

/// The items one way, one inline table per line.
fn item_list(items: &[DataItem]) -> String {
    let mut list = String::from("[\n");
    for item in items {
        let name = item.text.as_ref().map_or_else(|| quote(""), text);
        let mut line = format!("  {{ type = {}, name = {name}", quote(&item.data_type));
        if item.use_as_bits && item.bits.is_empty() {
            line.push_str(", use_as_bits = true");
        }
        if !item.bits.is_empty() {
            let bits: Vec<String> = item
                .bits
                .iter()
                .map(|(offset, t)| format!("{{ bit = {offset}, name = {} }}", text(t)))
                .collect();
            line.push_str(&format!(", bits = [{}]", bits.join(", ")));
        }
        line.push_str(" },\n");
        list.push_str(&line);
    }
    list.push(']');
    list
}

/// `{ default = ..., allowed = "...", visible = ..., changeable = ... }`.
fn parameter_table(p: &FParameter) -> String {
    let keys: Vec<String> = p
        .attributes
        .iter()
        .map(|(name, value)| {
            let key = F_PARAMETER_ATTRIBUTES
                .iter()
                .find(|(n, _)| n == name)
                .map_or("", |(_, k)| k);
            let value = match *name {
                "AllowedValues" => quote(value),
                "DefaultValue" if value.parse::<u32>().is_err() => quote(value),
                _ => value.clone(),
            };
            format!("{key} = {value}")
        })
        .collect();
    format!("{{ {} }}", keys.join(", "))
}

/// The safety modules the device access points offer that the
/// description can say, in the order the first to offer each offers them
/// (its slots are that one's); each other is left out with why. `taken`
/// are the ident numbers of the modules and access points imported so far,
/// which a safety module's may not be (E176); each imported one's joins
/// them.
pub(super) fn safety_modules<'a>(
    device: &'a PnDevice,
    taken: &mut Vec<u32>,
    notes: &mut Notes,
) -> Vec<Safety<'a>> {
    let mut found = Vec::new();
    let mut seen = BTreeSet::new();
    let offers = device.daps.iter().flat_map(|dap| offered(device, dap));
    for (reference, module) in offers.filter(|(_, m)| is_safety_module(m)) {
        if !seen.insert(&module.id) {
            continue;
        }
        let read = one_range(reference).and_then(|slots| read(module, slots, taken, notes));
        match read {
            Ok(safety) => {
                taken.extend(module.ident);
                found.push(safety);
            }
            Err(why) => notes.unsaid(&format!("module `{}`", module.id), &module.place, &why),
        }
    }
    found
}

/// The safety modules an imported access point offers; each other is left
/// out with why: only access points the import leaves out offer it, and a
/// module no access point offers is in no catalogue entry (E183).
pub(super) fn offered_by<'a>(
    safety: Vec<Safety<'a>>,
    daps: &[&Dap],
    notes: &mut Notes,
) -> Vec<Safety<'a>> {
    let offers = |s: &Safety| {
        daps.iter()
            .any(|d| d.useable_modules.iter().any(|r| r.target == s.module.id))
    };
    let (kept, left): (Vec<Safety>, Vec<Safety>) = safety.into_iter().partition(offers);
    for s in left {
        notes.unsaid(
            &format!("module `{}`", s.module.id),
            &s.module.place,
            "only device access points the import leaves out offer it, and a module no device access point offers is in no catalogue entry (E183)",
        );
    }
    kept
}

/// A safety module the description can say, or why not; each record of
/// its submodule the description cannot say left out with why.
fn read<'a>(
    module: &'a PnModule,
    slots: Slots,
    taken: &[u32],
    notes: &mut Notes,
) -> Result<Safety<'a>, String> {
    let [submodule] = module.submodules.as_slice() else {
        return Err("it has more than one submodule".into());
    };
    if module.name.is_none() {
        return Err("it has no name".into());
    }
    if module.ident.is_none_or(|i| i == 0 || taken.contains(&i)) {
        return Err("its ModuleIdentNumber is 0 or another module's or access point's, which the description's cannot share (E176)".into());
    }
    if !module.useable_submodules.is_empty() {
        return Err(
            "it has pluggable submodules, which the description's safety modules do not".into(),
        );
    }
    let extra = module
        .attributes
        .iter()
        .find(|a| &*a.name != super::CATEGORY);
    let extra = extra.or_else(|| submodule.attributes.iter().find(|a| !known(a)));
    if let Some(a) = extra {
        return Err(format!(
            "it has {}, which the description's safety modules cannot say",
            a.name
        ));
    }
    for part in [&submodule.io.input, &submodule.io.output] {
        io_part(part.as_ref())?;
    }
    let number =
        |name: &str| attribute(&submodule.attributes, name).and_then(|v| v.parse::<u32>().ok());
    let f_parameter_index =
        number(&format!("{F_RECORD}@Index")).and_then(|i| u16::try_from(i).ok());
    let f_param_desc =
        number(&format!("{F_RECORD}@F_ParamDescCRC")).and_then(|c| u16::try_from(c).ok());
    let (Some(f_parameter_index), Some(f_param_desc), Some(f_io_structure_desc)) =
        (f_parameter_index, f_param_desc, number(IO_CRC))
    else {
        return Err("it lacks its F-parameter record's Index or F_ParamDescCRC, or its IOData's F_IO_StructureDescCRC".into());
    };
    let version = match attribute(&submodule.attributes, IO_VERSION) {
        None => None,
        Some(v) => Some(
            v.parse::<u8>()
                .map_err(|_| format!("{IO_VERSION} `{v}` is not a number 0 to 255"))?,
        ),
    };
    Ok(Safety {
        module,
        submodule,
        records: safety_records(submodule, notes),
        slots,
        f_parameter_index,
        f_parameters: f_parameters(&submodule.attributes),
        io_structure_desc_version: version,
        crcs: (f_param_desc, f_io_structure_desc),
    })
}

/// The submodule attributes a safety module's description says.
fn known(a: &Attribute) -> bool {
    let name = &*a.name;
    let fixed = SUBMODULE_ATTRIBUTES
        .iter()
        .filter(|(n, _)| !matches!(*n, "API" | "FixedInSubslots" | "Writeable_IM_Records"))
        .any(|(n, v)| {
            *n == name && v.is_none_or(|v| attribute(std::slice::from_ref(a), name) == Some(v))
        });
    let parameter = name.strip_prefix(F_RECORD).is_some_and(|rest| {
        matches!(rest, "@Index" | "@F_ParamDescCRC")
            || rest
                .strip_prefix('/')
                .and_then(|r| r.split_once('@'))
                .is_some_and(|(element, attribute)| {
                    F_PARAMETER_ELEMENTS.contains(&element)
                        && F_PARAMETER_ATTRIBUTES.iter().any(|(n, _)| *n == attribute)
                })
    });
    // Its isochronous mode is `[profinet.isochronous]`'s, the data
    // modules': the round trip judges it.
    let isochronous = name.starts_with("IsochroneMode@");
    fixed || parameter || isochronous || matches!(name, "PROFIsafeSupported" | IO_CRC | IO_VERSION)
        // The module's category, which the build repeats with
        // `submodule_categories`; the round trip judges it.
        || name == super::CATEGORY
}

/// Items the description's types say, with names, no `Length` or
/// `Subordinate`, all consistent as gsdc writes them.
fn io_part(part: Option<&IoPart>) -> Result<(), String> {
    let Some(part) = part else {
        return Err("it has no data one way".into());
    };
    if part.attributes.iter().any(|a| &*a.name != "Consistency")
        || attribute(&part.attributes, "Consistency") != Some(CONSISTENCY)
    {
        return Err(format!(
            "its IO data is not \"{CONSISTENCY}\" as gsdc writes it"
        ));
    }
    for item in &part.items {
        if SafetyDataType::from_name(&item.data_type).is_none() {
            return Err(format!(
                "its data type {} is not one of the description's safety data",
                item.data_type
            ));
        }
        if item.text.is_none() || item.length.is_some() || !item.attributes.is_empty() {
            return Err(
                "a data item has no name, or a Length or Subordinate the description does not say"
                    .into(),
            );
        }
    }
    Ok(())
}

/// Every F-parameter element the file has, with its attributes in gsdc's
/// order and spelling (numbers as numbers, booleans as `true`/`false`);
/// the required ones the file leaves out without attributes, as the build
/// writes them.
fn f_parameters(attributes: &[Attribute]) -> Vec<FParameter> {
    let mut elements = Vec::new();
    for element in F_PARAMETER_ELEMENTS {
        let of = format!("{F_RECORD}/{element}@");
        let stated: Vec<(&'static str, String)> = F_PARAMETER_ATTRIBUTES
            .iter()
            .filter_map(|(name, _)| {
                let value = attribute(attributes, &format!("{of}{name}"))?;
                let value = match *name {
                    "Visible" | "Changeable" => is_true(value).to_string(),
                    "DefaultValue" => value
                        .parse::<u32>()
                        .map_or_else(|_| value.to_string(), |n| n.to_string()),
                    _ => value.to_string(),
                };
                Some((*name, value))
            })
            .collect();
        if stated.is_empty() && OPTIONAL_F_PARAMETERS.contains(&element) {
            continue;
        }
        elements.push(FParameter {
            element,
            attributes: stated,
        });
    }
    elements
}
