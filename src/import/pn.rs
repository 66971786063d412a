//! A GSDML file's device ([`PnDevice`]) written as a description: identity
//! and file name, the device access point's interface properties, the
//! modules recognised from their IO data (the PKW channel and PZD words,
//! standard telegram 1), their parameter records as mappings and settings,
//! and the ident numbers as the file has them. What the format has no
//! place for is a warning at its element (W600): a device access point
//! after the first, pluggable submodules, a module of other data than 16-bit
//! words; the round trip then names each change leaving it out makes
//! (E601). A file without a module the format can say is refused at its
//! device access point (E602).

mod daps;
mod diagnosis;
mod fail_safe;
mod irt;
mod own_records;
mod profienergy;
mod safety;
mod slots;
mod stack;

use super::numbered::{pattern, Pattern};
use super::toml_out::{list, quote, TomlOut};
use super::Notes;
use crate::device::pn::{Dap, DataItem, PnDevice, PnModule, Record, Submodule, SubmoduleKind};
use crate::device::{Allowed, Attribute, AttributeValue, Field, Text, Value};
use crate::i18n::{files, Phrase};
use crate::ir::profinet::{ModuleKind, Slots, Version, PROFIDRIVE_API};
use crate::ir::{Direction, Layout, PkwKind};
use crate::lower::{Offer, STANDARD_TELEGRAM_2_WORDS};
use std::fmt::Write as _;

/// Attributes of the device access point gsdc writes, with the value it
/// writes (`None`: the description states it).
const DAP_ATTRIBUTES: &[(&str, Option<&str>)] = &[
    ("PNIO_Version", None),
    ("RequiredSchemaVersion", None),
    ("ImplementationType", None),
    ("PhysicalSlots", None),
    ("MinDeviceInterval", None),
    ("DNS_CompatibleName", None),
    ("FixedInSlots", Some("0")),
    ("ObjectUUID_LocalIndex", Some("1")),
    ("NameOfStationNotTransferable", None),
    ("DeviceAccessSupported", None),
    ("NumberOfDeviceAccessAR", None),
    ("SharedDeviceSupported", None),
    ("AddressAssignment", None),
    ("CheckDeviceID_Allowed", Some("true")),
    ("MultipleWriteSupported", Some("true")),
    ("LLDP_NoD_Supported", Some("true")),
    ("ResetToFactoryModes", Some("2")),
    ("ModuleInfo/VendorName@Value", None),
    ("ModuleInfo/OrderNumber@Value", None),
    ("ModuleInfo/HardwareRelease@Value", None),
    ("ModuleInfo/SoftwareRelease@Value", None),
    ("CertificationInfo@ConformanceClass", None),
    ("CertificationInfo@NetloadClass", None),
    ("IOConfigData@MaxInputLength", None),
    ("IOConfigData@MaxOutputLength", None),
    ("IOConfigData@MaxDataLength", None),
    ("PowerOnToCommReady", None),
    ("AdaptsRealIdentification", None),
    ("WebServer", None),
    // Read by `subslot_labels`, or left out there with its reason.
    ("SubslotList/SubslotItem@SubslotNumber", None),
    ("SubslotList/SubslotItem@TextId", None),
    // Read by `super::symbol`, or left out there with its reason.
    (super::symbol::GSDML_SYMBOL_TYPE, Some("DeviceSymbol")),
    (super::symbol::GSDML_SYMBOL_TARGET, None),
];

const INTERFACE_ATTRIBUTES: &[(&str, Option<&str>)] = &[
    ("SupportedRT_Classes", Some("RT_CLASS_1")),
    ("SupportedProtocols", Some("SNMP;LLDP")),
    ("DCP_BoundarySupported", Some("true")),
    ("PTP_BoundarySupported", Some("true")),
    ("ApplicationRelations@NumberOfAR", None),
    ("ApplicationRelations@StartupMode", Some("Legacy;Advanced")),
    ("ApplicationRelations/TimingProperties@SendClock", None),
    (
        "ApplicationRelations/TimingProperties@PreferredSendClock",
        None,
    ),
    (
        "ApplicationRelations/TimingProperties@ReductionRatio",
        Some("1 2 4 8 16 32 64 128 256 512"),
    ),
    ("MediaRedundancy@SupportedRole", Some("Client")),
    ("NetworkComponentDiagnosisSupported", None),
];

const PORT_ATTRIBUTES: &[(&str, Option<&str>)] = &[
    ("MAUTypeList/MAUTypeItem@Value", Some("16")),
    ("MAUTypeList/MAUTypeItem@AdjustSupported", None),
    // The older form of the MAUTypeList, which the comparison takes for it
    // when it names the same types.
    ("MAUTypes", Some("16")),
    ("IsDefaultRingport", Some("true")),
    ("PortDeactivationSupported", None),
    ("CheckMAUTypeSupported", None),
    ("CheckMAUTypeDifferenceSupported", None),
    ("LinkStateDiagnosisCapability", None),
];

const SUBMODULE_ATTRIBUTES: &[(&str, Option<&str>)] = &[
    ("API", None),
    ("MayIssueProcessAlarm", Some("false")),
    ("FixedInSubslots", None),
    ("Writeable_IM_Records", None),
];

/// Each kind of module by its key in `per_module`, `[profinet.module_info]`
/// and (the standard telegrams) `[profinet]`.
const MODULE_KIND_KEYS: [(&str, ModuleKind); 3] = [
    ("user_defined", ModuleKind::Pzd),
    ("standard_telegram_1", ModuleKind::StandardTelegram1),
    ("standard_telegram_2", ModuleKind::StandardTelegram2),
];

/// A module recognised: its data submodule, its PROFIdrive access point,
/// and what it carries.
struct Recognised<'a> {
    module: &'a PnModule,
    data: &'a Submodule,
    access_point: Option<&'a Submodule>,
    kind: ModuleKind,
    layout: Layout,
    pkw: Option<PkwKind>,
}

impl Recognised<'_> {
    /// Its name in generated code, the key of `[profinet.ident_numbers]`.
    fn code_name(&self) -> String {
        match self.kind {
            ModuleKind::StandardTelegram1 => "telegram1".into(),
            ModuleKind::StandardTelegram2 => "telegram2".into(),
            ModuleKind::Pzd if self.layout.pkw => format!("pkw_pzd{}", self.layout.pzd_words),
            ModuleKind::Pzd => format!("pzd{}", self.layout.pzd_words),
        }
    }

    fn is_profidrive(&self) -> bool {
        self.access_point.is_some()
    }
}

/// The description of `device`, read from `file`; `None` when refused.
/// `symbol` is the PNG's name the description gives as its device symbol
/// (the DAP's `DeviceSymbol`, which `super::symbol` reads and judges).
pub(super) fn describe(
    device: &PnDevice,
    file: &str,
    symbol: Option<&str>,
    notes: &mut Notes,
) -> Option<TomlOut> {
    let dap = device.daps.first().or_else(|| {
        notes.refuse_at("no DeviceAccessPointItem", &device.place);
        None
    })?;
    for s in &device.submodules {
        notes.unsaid(
            &format!("pluggable submodule `{}`", s.id),
            &s.place,
            "the description's modules each carry one submodule of data",
        );
    }
    let recognised: Vec<Recognised> = slots::offered(device, dap)
        .map(|(_, m)| m)
        .filter(|m| !slots::is_empty_module(m) && !safety::is_safety_module(m))
        .filter_map(|m| recognise(m, notes))
        .collect();
    let (modules, pkw) = one_pkw_kind(recognised, notes);
    if modules.is_empty() {
        notes.refuse_at(
            "no module of its device access point carries a drive's telegram (16-bit words as many each way, the PKW channel first or not; standard telegram 1)",
            &dap.item.place,
        );
        return None;
    }
    let name = file_name(file, device, notes)?;
    let device_info = attribute_text(&device.identity, "DeviceIdentity/InfoText@TextId");
    let mut taken: Vec<u32> = dap.item.ident.into_iter().collect();
    taken.extend(modules.iter().filter_map(|m| m.module.ident));
    let empty = slots::empty_module(device, dap, &taken, notes);
    taken.extend(empty.as_ref().and_then(|e| e.module.ident));
    let every_safety = safety::safety_modules(device, &mut taken, notes);
    let module_slots = slots::module_slots(dap, &modules, notes);
    let placed_with = |safety: &[safety::Safety]| stack::Placed {
        module_slots,
        empty: empty.as_ref().map(|e| Offer::empty(e.slots)),
        safety: safety
            .iter()
            .map(|s| (s.id().to_string(), s.offer()))
            .collect(),
    };
    let every_placed = placed_with(&every_safety);
    // The first's stack and records count only what it offers itself.
    let first_stack = stack::Declared::of(dap, (&modules, &every_placed), name.version, notes);
    let first_records = own_records::own_records(dap, notes);
    let later_with = |placed: &stack::Placed, notes: &mut Notes| {
        let offer = daps::Offered {
            device,
            modules: &modules,
            safety: &placed.safety,
        };
        let context = (placed, taken.clone(), &first_records);
        daps::later_daps(
            &offer,
            (&first_stack, name.version),
            device_info,
            context,
            notes,
        )
    };
    // Which later access points import does not depend on the safety
    // modules, but their entries name those by number: a trial run (its
    // findings dropped, the real run says them) finds the access points,
    // then only the safety modules they offer are taken.
    let trial = later_with(&every_placed, &mut Notes::scratch());
    let offering: Vec<&Dap> = std::iter::once(dap)
        .chain(trial.iter().map(|l| l.dap))
        .collect();
    let safety = safety::offered_by(every_safety, &offering, notes);
    let placed = placed_with(&safety);
    let later = later_with(&placed, notes);
    let offer = daps::Offered {
        device,
        modules: &modules,
        safety: &placed.safety,
    };
    // The first offers every data module the import takes; not every
    // safety module, where a later one offers those (SEW's MOVI-C).
    let first_offers = daps::offered(dap, dap, &offer).ok().flatten();
    let timing = irt::Declared::of(dap, &modules, notes);
    let energy = profienergy::Declared::of(dap, name.version, notes);
    let safety_class = functional_safety_class(
        std::iter::once(dap).chain(later.iter().map(|l| l.dap)),
        &placed.safety,
    );
    unsaid_extras(
        device,
        (dap, &later),
        (&modules, empty.as_ref()),
        // The safety modules the access points that offer them declare
        // FunctionalSafety for, as gsdc writes it.
        (
            &timing,
            energy.is_some(),
            if safety_class { &placed.safety } else { &[] },
        ),
        notes,
    );
    let mut out = TomlOut::default();
    out.comment(&format!(
        "Imported by gsdc import from {file}. Every value below is the file's,"
    ));
    out.comment("marked under [choices] (where one is not, its mark says why): confirm each against the manual, then remove its mark.");
    device_table(&mut out, device, dap, &name, symbol);
    let records = Records::of(&modules);
    telegram_table(&mut out, &modules, pkw);
    records.write_mappings(&mut out, notes);
    records.write_settings(&mut out, &modules, notes);
    let imported_daps: Vec<&Dap> = std::iter::once(dap)
        .chain(later.iter().map(|l| l.dap))
        .collect();
    profinet(
        &mut out,
        device,
        (&imported_daps, first_offers, safety_class),
        &name,
        (&modules, module_slots),
        notes,
        timing.irt.is_some(),
    );
    let stack = first_stack.keys();
    if !stack.is_empty() {
        out.table("profinet.stack");
        for (key, value) in stack {
            out.key(key, value);
        }
    }
    if let Some(energy) = &energy {
        energy.write(&mut out);
    }
    if let Some(empty) = &empty {
        empty.write(&mut out);
    }
    for s in &safety {
        s.write(&mut out);
    }
    timing.write(&mut out);
    records.write_indexes(&mut out);
    if let Some(fail_safe) = &records.fail_safe {
        fail_safe.write(&mut out);
    }
    module_texts(&mut out, &modules, notes);
    pzd_names(&mut out, &modules, notes);
    profile_word_names(&mut out, &modules, notes);
    access_point_texts(&mut out, &modules, notes);
    subslot_labels(&mut out, &imported_daps, notes);
    ident_numbers(&mut out, dap, &modules);
    for later in &later {
        later.write(&mut out);
    }
    for diagnosis in diagnosis::entries(device, notes) {
        diagnosis.write(&mut out);
    }
    first_records.write(&mut out);
    super::dp::manual(&mut out);
    choices(&mut out, file, &records, software_release(dap).is_some());
    notes.chosen_marks(&mut out);
    Some(out)
}

/// `[choices]`: every table imported marked with the file's name, and
/// the identity a GSDML file does not give marked with what stands for it.
fn choices(out: &mut TomlOut, file: &str, records: &Records, has_revision: bool) {
    out.table("choices");
    out.string(
        "\"device.model\"",
        "a GSDML file has no model name: the device access point's name stands for it",
    );
    if has_revision {
        out.string(
            "\"device.revision\"",
            "a GSDML file has no revision: its software release stands for it",
        );
    }
    let reason = quote(&format!("imported from {file}"));
    let mut tables = vec!["device", "telegram", "profinet"];
    if !records.mappings().is_empty() {
        tables.push("mappings");
    }
    if !records.settings.is_empty() {
        tables.push("settings");
    }
    for table in tables {
        out.key(&quote(table), &reason);
    }
}

/// A module's kind and layout from its IO data: 16-bit words, as many each
/// way; the PKW channel first when its four words have one of the names
/// gsdc gives them; standard telegram 1 in PROFIdrive's API behind an
/// access point, or a vendor's under gsdc's ID for it; standard telegram 2
/// in PROFIdrive's API behind an access point, a 32-bit value between two
/// words each way.
fn recognise<'a>(module: &'a PnModule, notes: &mut Notes) -> Option<Recognised<'a>> {
    if !module.useable_submodules.is_empty() {
        notes.unsaid(
            &format!("module `{}`", module.id),
            &module.place,
            "it takes pluggable submodules; the description's modules each carry one submodule of data",
        );
        return None;
    }
    let (access_point, data) = match module.submodules.as_slice() {
        [data] => (None, data),
        [map, data] if api(map) == PROFIDRIVE_API && !has_io(map) => (Some(map), data),
        _ => {
            notes.unsaid(
                &format!("module `{}`", module.id),
                &module.place,
                &format!(
                    "it has {} submodules; the description's modules carry one submodule of data (after PROFIdrive's access point)",
                    module.submodules.len()
                ),
            );
            return None;
        }
    };
    if access_point.is_some() && is_telegram_2(data) {
        return Some(Recognised {
            module,
            data,
            access_point,
            kind: ModuleKind::StandardTelegram2,
            layout: Layout::new(false, STANDARD_TELEGRAM_2_WORDS),
            pkw: None,
        });
    }
    let Some(words) = words(data) else {
        notes.unsaid(
            &format!("module `{}`", module.id),
            &data.place,
            "its IO data is not 16-bit words as many each way, nor PROFIdrive's standard telegram 2, which the description's modules carry (a vendor's own PROFINET layout has no place in the format yet)",
        );
        return None;
    };
    let input = data.io.input.as_ref().map_or(&[][..], |p| &p.items[..]);
    let telegram_1 = access_point.is_some() || module.id == "IDM_STD_TEL_1";
    let pkw = (!telegram_1 && words > 4)
        .then(|| pkw_of(&input[..4]))
        .flatten();
    let kind = match telegram_1 {
        true => ModuleKind::StandardTelegram1,
        false => ModuleKind::Pzd,
    };
    let pkw_words = if pkw.is_some() { 4 } else { 0 };
    Some(Recognised {
        module,
        data,
        access_point,
        kind,
        layout: Layout::new(pkw.is_some(), words - pkw_words),
        pkw,
    })
}

fn api(s: &Submodule) -> u32 {
    attribute(&s.attributes, "API")
        .and_then(|v| v.parse().ok())
        .unwrap_or(0)
}

fn has_io(s: &Submodule) -> bool {
    [&s.io.input, &s.io.output]
        .into_iter()
        .any(|p| p.as_ref().is_some_and(|p| !p.items.is_empty()))
}

/// The 16-bit words a submodule carries each way (1..=20), when every item
/// is one and both ways have as many.
fn words(s: &Submodule) -> Option<u8> {
    let count = |p: &Option<crate::device::pn::IoPart>| -> Option<usize> {
        let items = &p.as_ref()?.items;
        items
            .iter()
            .all(|i| &*i.data_type == "Unsigned16" && i.length.is_none())
            .then_some(items.len())
    };
    let (input, output) = (count(&s.io.input)?, count(&s.io.output)?);
    (input == output)
        .then(|| u8::try_from(input).ok())
        .flatten()
        .filter(|w| (1..=20).contains(w))
}

/// Standard telegram 2's IO data: Unsigned16, Unsigned32, Unsigned16 each
/// way (STW1, NSOLL_B, STW2; ZSW1, NIST_B, ZSW2).
fn is_telegram_2(s: &Submodule) -> bool {
    let shape = |p: &Option<crate::device::pn::IoPart>| {
        p.as_ref().is_some_and(|p| {
            let types: Vec<Option<&str>> = p
                .items
                .iter()
                .map(|i| i.length.is_none().then_some(&*i.data_type))
                .collect();
            types == [Some("Unsigned16"), Some("Unsigned32"), Some("Unsigned16")]
        })
    };
    shape(&s.io.input) && shape(&s.io.output)
}

/// The PKW channel whose word names (in English) four items have.
fn pkw_of(items: &[DataItem]) -> Option<PkwKind> {
    let names: Vec<&str> = items
        .iter()
        .map(|i| i.text.as_ref().map_or("", |t| &t.primary))
        .collect();
    [
        PkwKind::PkeIndPwe,
        PkwKind::StationCommandAddressValue,
        PkwKind::Profidrive,
    ]
    .into_iter()
    .find(|&kind| {
        let gsdc: Vec<&str> = crate::lower::pkw_words(kind)
            .iter()
            .map(|(_, p)| p.get(crate::i18n::Lang::En))
            .collect();
        gsdc == names
    })
}

/// The modules of one PKW channel (the first module's that has one), and
/// that channel (`PkwKind::None` without): a module of another channel's
/// word names is left out (W600), the description has one channel.
fn one_pkw_kind<'a>(
    modules: Vec<Recognised<'a>>,
    notes: &mut Notes,
) -> (Vec<Recognised<'a>>, PkwKind) {
    let Some(first) = modules.iter().find_map(|m| m.pkw) else {
        return (modules, PkwKind::None);
    };
    let (kept, other): (Vec<_>, Vec<_>) = modules
        .into_iter()
        .partition(|m| m.pkw.is_none_or(|k| k == first));
    for m in other {
        notes.unsaid(
            &format!("module `{}`", m.module.id),
            &m.module.place,
            "its PKW channel's words are named otherwise than the first module's; the description has one channel",
        );
    }
    (kept, first)
}

fn attribute<'a>(attributes: &'a [Attribute], name: &str) -> Option<&'a str> {
    found(attributes, name).map(|(_, value)| value)
}

/// The attribute `name`, with its value as written (a text's in the
/// primary language): what a finding about it points at.
fn found<'a>(attributes: &'a [Attribute], name: &str) -> Option<(&'a Attribute, &'a str)> {
    let a = attributes.iter().find(|a| &*a.name == name)?;
    let value = match &a.value {
        AttributeValue::Plain(v) => &**v,
        AttributeValue::Text(t) => &*t.primary,
    };
    Some((a, value))
}

fn attribute_text<'a>(attributes: &'a [Attribute], name: &str) -> Option<&'a Text> {
    attributes
        .iter()
        .find(|a| &*a.name == name)
        .and_then(|a| match &a.value {
            AttributeValue::Text(t) => Some(t),
            AttributeValue::Plain(_) => None,
        })
}

/// A text as the description writes it: a string, or every language.
fn text(t: &Text) -> String {
    if t.translations.keys().next().is_none() {
        return quote(&t.primary);
    }
    let mut every = format!("{{ en = {}", quote(&t.primary));
    for (code, text) in t.translations.iter() {
        let _ = write!(every, ", {code} = {}", quote(text));
    }
    every.push_str(" }");
    every
}

/// The vendor and the family of a file name's `Vendor-Family`, both of
/// which may hold `-` (`SEW-MOVI-C-Decentralized-Electronics`): split where
/// the family is the file's ProductFamily (its spaces as `-`) or the vendor
/// its VendorName; else at the only `-`; else at the first, the import's
/// choice, marked. The name the build writes is the same either way; the
/// family is also the ProductFamily it writes.
fn vendor_and_family<'n>(
    both: &'n str,
    device: &PnDevice,
    notes: &mut Notes,
) -> Option<(&'n str, &'n str)> {
    let splits: Vec<(&str, &str)> = both
        .match_indices('-')
        .map(|(i, _)| (&both[..i], &both[i + 1..]))
        .collect();
    // Compared in one letter case, spaces as `-`.
    let plain = |name: &str| name.replace(' ', "-").to_ascii_lowercase();
    let the_file = |name: &str| attribute(&device.identity, name).map(plain);
    let (product_family, vendor_name) = (
        the_file("DeviceFunction/Family@ProductFamily"),
        the_file("DeviceIdentity/VendorName@Value"),
    );
    let named = splits.iter().find(|(vendor, family)| {
        product_family == Some(plain(family)) || vendor_name == Some(plain(vendor))
    });
    let only = (splits.len() == 1).then(|| splits[0]);
    if let Some(split) = named.copied().or(only) {
        return Some(split);
    }
    let &(vendor, family) = splits.first()?;
    notes.chosen(
        "device.family",
        format!("the file name's `{both}` does not say where the vendor ends and the family begins, nor do its VendorName and ProductFamily: the import takes `{vendor}` and `{family}`"),
    );
    Some((vendor, family))
}

/// The parts of a GSDML file name gsdc writes: vendor, family, date.
struct FileName {
    /// The GSDML version the description's file declares.
    version: Version,
    vendor: String,
    family: String,
    date: String,
}

/// `GSDML-V2.32-Vendor-Family-20230830[-071447].xml`, read as `gsdc
/// check` reads file names; refused otherwise, since the description's
/// file name is made of these parts.
fn file_name(file: &str, device: &PnDevice, notes: &mut Notes) -> Option<FileName> {
    let parts = match crate::gsdml::version::parse_file_name(file) {
        Ok(parts) => parts,
        Err(why) => {
            notes.refuse(&format!(
                "`{file}` is not a GSDML file name (GSDML-V<version>-<vendor>-<family>-<yyyymmdd>.xml): {why}; the description makes the file name from its parts"
            ));
            return None;
        }
    };
    // `parse_file_name` found a date of eight digits and a time of six.
    let (vendor, family) = vendor_and_family(parts.vendor_and_family, device, notes)?;
    let date = parts.date;
    let day = format!("{}-{}-{}", &date[..4], &date[4..6], &date[6..]);
    let version = match crate::lower::SUPPORTED_GSDML_VERSIONS.contains(&parts.version) {
        true => parts.version,
        false => {
            let written = crate::lower::DEFAULT_GSDML_VERSION;
            notes.chosen(
                "profinet.gsdml_version",
                format!(
                    "GSDML {} is not imported: gsdc writes {written}, which the description names; the round trip judges the change",
                    parts.version
                ),
            );
            written
        }
    };
    Some(FileName {
        version,
        vendor: vendor.to_string(),
        family: family.to_string(),
        date: match parts.time {
            Some(t) => format!("{day}T{}:{}:{}", &t[..2], &t[2..4], &t[4..]),
            None => day,
        },
    })
}

fn software_release(dap: &Dap) -> Option<&str> {
    attribute(&dap.item.attributes, "ModuleInfo/SoftwareRelease@Value")
}

fn device_table(
    out: &mut TomlOut,
    device: &PnDevice,
    dap: &Dap,
    name: &FileName,
    symbol: Option<&str>,
) {
    out.table("device");
    let vendor = attribute(&device.identity, "DeviceIdentity/VendorName@Value").unwrap_or_default();
    out.string("vendor", vendor);
    out.string("family", &name.family);
    let dap_name = dap.item.name.clone().unwrap_or_default();
    out.string("model", &dap_name.primary);
    // A device access point may have no releases (SEW's MOVI-C); the
    // description then has none, nor the revision that stands for one.
    let software = software_release(dap);
    let releases = [
        ("revision", software),
        (
            "hardware_release",
            attribute(&dap.item.attributes, "ModuleInfo/HardwareRelease@Value"),
        ),
        ("software_release", software),
    ];
    for (key, value) in releases {
        if let Some(value) = value {
            out.string(key, value);
        }
    }
    out.key("name", text(&dap_name));
    if let Some(order) = attribute(&dap.item.attributes, "ModuleInfo/OrderNumber@Value") {
        out.string("order_number", order);
    }
    if let Some(info) = attribute_text(&device.identity, "DeviceIdentity/InfoText@TextId") {
        out.key("info", text(info));
    }
    if let Some(png) = symbol {
        out.string("symbol", png);
    }
}

/// `[telegram]` with the control and status words PZD1 carries: each
/// named bit as the file names it (a field of several bits, or the values
/// gsdc puts in a bit's name, stay in the names).
fn telegram_table(out: &mut TomlOut, modules: &[Recognised], pkw: PkwKind) {
    out.table("telegram");
    let pkw_key = match pkw {
        PkwKind::None => "none",
        PkwKind::PkeIndPwe => "pke-ind-pwe",
        PkwKind::StationCommandAddressValue => "station-command-address-value",
        PkwKind::Profidrive => "profidrive",
    };
    out.string("pkw", pkw_key);
    let words = modules
        .iter()
        .map(|m| m.layout.pzd_words)
        .max()
        .unwrap_or(1);
    out.key("pzd_words", words);
    if modules.iter().any(|m| m.kind != ModuleKind::Pzd) {
        out.key("profidrive", modules.iter().any(Recognised::is_profidrive));
    }
    for (table, direction) in [
        ("telegram.control_word", Direction::Out),
        ("telegram.status_word", Direction::In),
    ] {
        if let Some(word) = named_word(modules, direction) {
            out.table(table);
            out.key("name", text(&word.text.clone().unwrap_or_default()));
            let bits: Vec<String> = word
                .bits
                .iter()
                .map(|(bit, name)| format!("{{ bit = {bit}, name = {} }}", text(name)))
                .collect();
            out.key("bits", format!("[\n    {},\n]", bits.join(",\n    ")));
        }
    }
}

/// The control or status word (`direction`) the description's telegram
/// names: the first PZD word of a module of PZD words, where one such
/// module has bits in it.
fn named_word<'a>(modules: &[Recognised<'a>], direction: Direction) -> Option<&'a DataItem> {
    modules.iter().filter(|m| !m.is_profidrive()).find_map(|m| {
        let item = pzd_items(m, direction).first()?;
        (item.use_as_bits && !item.bits.is_empty()).then_some(item)
    })
}

/// A module's data items one way after its PKW channel's: its PZD words.
fn pzd_items<'a>(m: &Recognised<'a>, direction: Direction) -> &'a [DataItem] {
    io_items(m.data, direction)
        .get(usize::from(m.layout.pkw_words())..)
        .unwrap_or_default()
}

/// `[profinet.pzd_names]`: the names the modules of PZD words give their
/// PZD words each way, after a named control or status word, where every
/// module gives a word the same name and any name is not gsdc's `PZD{n}`;
/// else the names are left out, saying why.
fn pzd_names(out: &mut TomlOut, modules: &[Recognised], notes: &mut Notes) {
    let mut lists = Vec::new();
    'direction: for (key, direction) in [("output", Direction::Out), ("input", Direction::In)] {
        let first = usize::from(named_word(modules, direction).is_some());
        let mut names: Vec<&Text> = Vec::new();
        let of_words = modules.iter().filter(|m| !m.is_profidrive());
        for m in of_words {
            for (i, item) in pzd_items(m, direction).iter().enumerate().skip(first) {
                let same = match (names.get(i - first), &item.text) {
                    (_, None) => false,
                    (Some(&known), Some(name)) => known == name,
                    (None, Some(name)) => {
                        names.push(name);
                        true
                    }
                };
                if !same {
                    let why = format!(
                        "the description's pzd_names give PZD{} one name {key} in every module",
                        i + 1
                    );
                    notes.unsaid(
                        &format!("the name of PZD{} {key}", i + 1),
                        &item.place,
                        &why,
                    );
                    continue 'direction;
                }
            }
        }
        let gsdcs = (first + 1..)
            .zip(&names)
            .all(|(n, name)| same_text(name, &crate::ir::Text::english(format!("PZD{n}"))));
        if !gsdcs {
            lists.push((key, list(names.into_iter().map(text))));
        }
    }
    if !lists.is_empty() {
        out.table("profinet.pzd_names");
        for (key, names) in lists {
            out.key(key, names);
        }
    }
}

/// `[profinet.profile_word_names]`: the names PROFIdrive's standard
/// telegrams give the profile's words (FENA's "Output" and "Input"), where
/// a telegram names a word otherwise than the profile and every telegram
/// carrying it names it alike; a word named two ways is left out, saying
/// why.
fn profile_word_names(out: &mut TomlOut, modules: &[Recognised], notes: &mut Notes) {
    let mut names: Vec<(&str, Phrase, &Text)> = Vec::new();
    let mut two_ways: Vec<&str> = Vec::new();
    for m in modules.iter().filter(|m| m.is_profidrive()) {
        for direction in [Direction::Out, Direction::In] {
            let words = crate::lower::profile_words(m.kind, direction);
            for (&(word, profiles), item) in words.iter().zip(io_items(m.data, direction)) {
                let Some(name) = &item.text else { continue };
                match names.iter().find(|(known, _, _)| *known == word) {
                    Some((_, _, known)) if *known != name && !two_ways.contains(&word) => {
                        two_ways.push(word);
                        let why = "the description's profile_word_names give a word one name in every telegram";
                        notes.unsaid(&format!("the name of {word}"), &item.place, why);
                    }
                    Some(_) => {}
                    None => names.push((word, profiles, name)),
                }
            }
        }
    }
    let stated: Vec<(&str, &Text)> = names
        .into_iter()
        .filter(|(word, profiles, name)| {
            !two_ways.contains(word) && !same_text(name, &crate::ir::Text::phrase(*profiles))
        })
        .map(|(word, _, name)| (word, name))
        .collect();
    if !stated.is_empty() {
        out.table("profinet.profile_word_names");
        for (word, name) in stated {
            out.key(word, text(name));
        }
    }
}

/// `[profinet.access_point_texts]`: the PROFIdrive modules' access point's
/// name and info text (FENA's "Acyclic parameter access is possible
/// through this module"), each where it is not gsdc's and every module's
/// access point gives the same; else left out, saying why.
fn access_point_texts(out: &mut TomlOut, modules: &[Recognised], notes: &mut Notes) {
    let points: Vec<&Submodule> = modules.iter().filter_map(|m| m.access_point).collect();
    let Some(first) = points.first() else {
        return;
    };
    type TextOf = fn(&Submodule) -> Option<&Text>;
    let texts: [(&str, TextOf, Phrase); 2] = [
        ("name", |s| s.name.as_ref(), files::MODULE_ACCESS_POINT),
        ("info", |s| s.info.as_ref(), files::MODULE_ACCESS_POINT_INFO),
    ];
    let mut stated = Vec::new();
    for (key, text_of, gsdcs) in texts {
        let Some(own) = text_of(first) else { continue };
        if points.iter().any(|p| text_of(p) != Some(own)) {
            let why = "the description's access_point_texts give every PROFIdrive module's access point one text";
            notes.unsaid(&format!("the access point's {key}"), &first.place, why);
        } else if !same_text(own, &crate::ir::Text::phrase(gsdcs)) {
            stated.push((key, text(own)));
        }
    }
    if !stated.is_empty() {
        out.table("profinet.access_point_texts");
        for (key, own) in stated {
            out.key(key, own);
        }
    }
}

/// A submodule's data items one way.
fn io_items(data: &Submodule, direction: Direction) -> &[DataItem] {
    let part = match direction {
        Direction::Out => &data.io.output,
        Direction::In => &data.io.input,
    };
    part.as_ref()
        .map(|p| p.items.as_slice())
        .unwrap_or_default()
}

/// The modules' parameter records by kind, as gsdc writes them: a record
/// whose entries grow with the module's PZD words is a PZD mapping (the
/// first one controller to drive, the second drive to controller), one of
/// several numbered entries the same in every module the custom indexes,
/// any other the settings.
#[derive(Default)]
struct Records<'a> {
    pzd_out: Option<(&'a Record, Pattern)>,
    pzd_in: Option<(&'a Record, Pattern)>,
    dpv1_index: Option<(&'a Record, Pattern)>,
    settings: Vec<&'a Record>,
    /// The fail-safe values the first settings record ends with.
    fail_safe: Option<fail_safe::FailSafe<'a>>,
}

impl<'a> Records<'a> {
    fn of(modules: &[Recognised<'a>]) -> Records<'a> {
        let mut indexes: Vec<u32> = Vec::new();
        for m in modules {
            for r in &m.data.records {
                if !indexes.contains(&r.index) {
                    indexes.push(r.index);
                }
            }
        }
        let mut records = Records::default();
        for index in indexes {
            let all: Vec<&Record> = modules
                .iter()
                .flat_map(|m| m.data.records.iter().filter(|r| r.index == index))
                .collect();
            let Some(largest) = all.iter().copied().max_by_key(|r| r.data.fields.len()) else {
                continue;
            };
            let grows = all
                .iter()
                .any(|r| r.data.fields.len() != largest.data.fields.len());
            let names: Vec<&Text> = largest.data.fields.iter().map(|f| &f.name).collect();
            match (pattern(&names), grows) {
                (Some(p), true) if records.pzd_out.is_none() => {
                    records.pzd_out = Some((largest, p))
                }
                (Some(p), true) if records.pzd_in.is_none() => records.pzd_in = Some((largest, p)),
                // One entry could be either: a setting is the plainer.
                (Some(p), false)
                    if records.dpv1_index.is_none() && largest.data.fields.len() > 1 =>
                {
                    records.dpv1_index = Some((largest, p))
                }
                _ => records.settings.push(largest),
            }
        }
        // The first settings record may end with fail-safe values: its
        // settings are then those of the copy with the most of them.
        records.fail_safe = records
            .settings
            .first()
            .and_then(|first| fail_safe::of(modules, first.index));
        if let (Some(f), Some(first)) = (&records.fail_safe, records.settings.first_mut()) {
            *first = f.most_settings();
        }
        records
    }

    /// A copy of a settings record's entries that are settings: those
    /// before its fail-safe values.
    fn settings_of(&self, record: &'a Record) -> &'a [Field] {
        self.fail_safe
            .as_ref()
            .and_then(|f| f.settings_of(record))
            .unwrap_or(&record.data.fields)
    }

    fn mappings(&self) -> Vec<(&'static str, &(&'a Record, Pattern))> {
        [
            ("pzd_out", &self.pzd_out),
            ("pzd_in", &self.pzd_in),
            ("dpv1_index", &self.dpv1_index),
        ]
        .into_iter()
        .filter_map(|(key, r)| r.as_ref().map(|r| (key, r)))
        .collect()
    }

    fn write_mappings(&self, out: &mut TomlOut, notes: &mut Notes) {
        for (key, (record, pattern)) in self.mappings() {
            out.table(&format!("mappings.{key}"));
            out.key("name", &pattern.name);
            out.key("first", pattern.first);
            out.key("last", pattern.first + record.data.fields.len() as u32 - 1);
            for f in record
                .data
                .fields
                .iter()
                .filter(|f| f.data_type != "Unsigned16")
            {
                entry_type_unsaid(f, "a mapping's record entries are Unsigned16", notes);
            }
            defaults_and_values(out, &record.data.fields);
            out.string("set_at", "master");
        }
    }

    /// `[[settings]]`, one per entry of the settings record; an entry a
    /// module fixes (not changeable) is the value each kind of module fixes
    /// (`per_module`), its choices and default those of a module that lets
    /// the user change it. An entry every module lets the user change whose
    /// default differs by kind of module, or that a standard telegram
    /// carries, is each kind's default (`per_module` with `changeable`).
    fn write_settings(&self, out: &mut TomlOut, modules: &[Recognised], notes: &mut Notes) {
        for record in &self.settings {
            let fields = self.settings_of(record);
            for (i, field) in fields.iter().enumerate() {
                // By its name, and which of that name it is: a standard
                // telegram's record holds only the settings each kind of
                // module writes, at other offsets.
                let nth = fields[..i].iter().filter(|f| f.name == field.name).count();
                let in_modules: Vec<(ModuleKind, &Field)> = modules
                    .iter()
                    .filter_map(|m| {
                        let r = m.data.records.iter().find(|r| r.index == record.index)?;
                        let f = self
                            .settings_of(r)
                            .iter()
                            .filter(|f| f.name == field.name)
                            .nth(nth)?;
                        Some((m.kind, f))
                    })
                    .collect();
                // The default of a PZD module before a telegram's, as the
                // description's `default` is User_Prm_Data's, where a PZD
                // module's value is.
                let changeable = in_modules
                    .iter()
                    .filter(|(_, f)| f.changeable)
                    .min_by_key(|(kind, _)| *kind != ModuleKind::Pzd)
                    .map(|(_, f)| *f);
                out.array_item("settings");
                out.key("name", text(&field.name));
                setting_type(out, field, notes);
                defaults_and_values(out, std::slice::from_ref(changeable.unwrap_or(field)));
                out.string("set_at", "master");
                if changeable.is_none() || in_modules.iter().any(|(_, f)| !f.changeable) {
                    per_module(out, &in_modules, false);
                } else if defaults_differ_by_module(&in_modules) {
                    per_module(out, &in_modules, true);
                }
            }
        }
    }

    fn write_indexes(&self, out: &mut TomlOut) {
        let mut indexes: Vec<(&str, &Record)> = self
            .mappings()
            .into_iter()
            .map(|(key, (r, _))| (key, *r))
            .collect();
        if let Some(first) = self.settings.first() {
            indexes.push(("settings", first));
        }
        if indexes.is_empty() {
            return;
        }
        out.table("profinet.records");
        for (key, record) in indexes {
            match &record.name {
                Some(name) => out.key(
                    key,
                    format!("{{ index = {}, name = {} }}", record.index, text(name)),
                ),
                None => out.key(key, record.index),
            }
        }
    }
}

/// Whether an entry every module lets the user change needs `per_module`
/// to build: a standard telegram carries it (only `per_module` puts a
/// setting there), or its default is not one for all modules.
fn defaults_differ_by_module(in_modules: &[(ModuleKind, &Field)]) -> bool {
    let in_telegram = in_modules.iter().any(|(k, _)| *k != ModuleKind::Pzd);
    in_telegram
        || in_modules
            .iter()
            .any(|(_, f)| f.default != in_modules[0].1.default)
}

/// `per_module`: the value each kind of module fixes, where all modules of
/// the kind fix one value (the user's value where they do not fix it); or,
/// `changeable`, each kind's default, where all its modules have one.
fn per_module(out: &mut TomlOut, in_modules: &[(ModuleKind, &Field)], changeable: bool) {
    let value = |kind: ModuleKind| -> Option<String> {
        let values: Vec<Option<&Value>> = in_modules
            .iter()
            .filter(|(k, _)| *k == kind)
            .map(|(_, f)| {
                (changeable || !f.changeable)
                    .then_some(f.default.as_ref())
                    .flatten()
            })
            .collect();
        match values.first()? {
            Some(Value::Int(v)) if values.iter().all(|w| *w == values[0]) => Some(v.to_string()),
            _ => None,
        }
    };
    let parts: Vec<String> = MODULE_KIND_KEYS
        .into_iter()
        .filter_map(|(key, kind)| Some(format!("{key} = {}", value(kind)?)))
        .chain(changeable.then(|| "changeable = true".to_string()))
        .collect();
    out.key("per_module", format!("{{ {} }}", parts.join(", ")));
}

/// A setting's `type`: Unsigned16 unsaid, Unsigned8 and Integer8 said;
/// another is left out.
fn setting_type(out: &mut TomlOut, field: &Field, notes: &mut Notes) {
    match field.data_type.as_str() {
        "Unsigned16" => {}
        "Unsigned8" | "Integer8" => out.string("type", &field.data_type),
        _ => entry_type_unsaid(
            field,
            "a setting is an Unsigned16, an Unsigned8 or an Integer8",
            notes,
        ),
    }
}

fn entry_type_unsaid(field: &Field, why: &str, notes: &mut Notes) {
    let what = format!(
        "record entry \"{}\" of type {}",
        field.name.primary, field.data_type
    );
    notes.unsaid(&what, &field.place, why);
}

/// `default` (or `defaults`) and `range` or `choices` of entries.
fn defaults_and_values(out: &mut TomlOut, fields: &[Field]) {
    let defaults: Vec<String> = fields
        .iter()
        .map(|f| match &f.default {
            Some(Value::Int(v)) => v.to_string(),
            _ => "0".into(),
        })
        .collect();
    match defaults.iter().all(|d| *d == defaults[0]) {
        true => out.key("default", &defaults[0]),
        false => out.key("defaults", list(&defaults)),
    }
    let first = &fields[0];
    if !first.choices.is_empty() {
        let choices: Vec<String> = first
            .choices
            .iter()
            .filter_map(|c| match &c.value {
                Value::Int(v) => Some(format!("{{ value = {v}, text = {} }}", text(&c.text))),
                _ => None,
            })
            .collect();
        out.key("choices", format!("[\n    {},\n]", choices.join(",\n    ")));
    } else if let Allowed::Ranges(ranges) = &first.allowed {
        if let [(Value::Int(a), Value::Int(b))] = ranges.as_slice() {
            out.key("range", format!("[{a}, {b}]"));
        }
    }
}

fn profinet(
    out: &mut TomlOut,
    device: &PnDevice,
    (daps, first_offers, safety_class): (&[&Dap], Option<String>, bool),
    name: &FileName,
    (modules, module_slots): (&[Recognised], Slots),
    notes: &mut Notes,
    has_irt: bool,
) {
    let dap = daps[0];
    out.table("profinet");
    let id = |n: Option<u32>| format!("{{ value = 0x{:04X} }}", n.unwrap_or(0));
    out.key("vendor_id", id(device.vendor_id));
    out.key("device_id", id(device.device_id));
    out.string("file_vendor", &name.vendor);
    out.string("gsdml_version", &name.version.number());
    let attributes = &dap.item.attributes;
    if let Some(version) = pnio_version(attributes, name.version, notes) {
        out.string("pnio_version", &version.number());
    }
    if let Some(version) = required_schema_version(attributes, name.version, notes) {
        out.string("required_schema_version", &version.number());
    }
    if let Some(basis) = implementation_type(attributes, notes) {
        out.string("implementation_type", basis);
    }
    if let Some(name) = interface_name(daps, notes) {
        out.key("interface_name", text(name));
    }
    if let Some(names) = port_names(daps, notes) {
        out.key("port_names", list(names.into_iter().map(text)));
    }
    if let Some(family) = product_family(device, &name.family, notes) {
        out.string("product_family", family);
    }
    out.key("date", &name.date);
    out.string("dns_name", &name_of_station(attributes, notes));
    out.key("ports", submodules_of(dap, SubmoduleKind::Port).count());
    out.key(
        "min_device_interval",
        attribute(attributes, "MinDeviceInterval").unwrap_or("32"),
    );
    let lengths = |pkw: bool| -> Vec<u8> {
        modules
            .iter()
            .filter(|m| m.kind == ModuleKind::Pzd && m.layout.pkw == pkw)
            .map(|m| m.layout.pzd_words)
            .collect()
    };
    let (with, without) = (lengths(true), lengths(false));
    let module_pkw = match (with.is_empty(), without.is_empty()) {
        (false, true) => "with",
        (true, false) => "without",
        _ => "both",
    };
    if module_pkw == "both" && with != without {
        notes.chosen(
            "profinet.pzd_lengths",
            format!("the modules with the PKW channel have PZD words {with:?}, those without {without:?}: the description offers the same lengths both ways, {with:?}"),
        );
    }
    let offered = if with.is_empty() { &without } else { &with };
    out.key("pzd_lengths", list(offered));
    out.string("module_pkw", module_pkw);
    if module_slots != Slots::ONE {
        out.key("module_slots", slots::slot_list(module_slots));
    }
    if let Some(offered) = first_offers {
        out.key("dap_modules", offered);
    }
    for (key, kind) in &MODULE_KIND_KEYS[1..] {
        if modules.iter().any(|m| m.kind == *kind) {
            out.key(key, true);
        }
    }
    interface_properties(out, dap, notes, has_irt);
    module_im_records(out, modules, notes);
    if modules_repeat_releases(dap, modules) {
        out.key("module_releases", true);
    }
    if submodules_repeat_categories(modules) {
        out.key("submodule_categories", true);
    }
    if !safety_class {
        out.key("functional_safety_class", false);
    }
}

const CATEGORY: &str = "ModuleInfo@CategoryRef";

/// Whether every module's data submodule names its module's category too
/// (`submodule_categories`, MOVI-C's 16); others are left out at each
/// (`unsaid_extras`).
fn submodules_repeat_categories(modules: &[Recognised]) -> bool {
    modules.iter().all(|m| {
        let category = attribute(&m.module.attributes, CATEGORY);
        category.is_some() && attribute(&m.data.attributes, CATEGORY) == category
    })
}

/// The releases a module's ModuleInfo may give.
const MODULE_RELEASES: [&str; 2] = [
    "ModuleInfo/HardwareRelease@Value",
    "ModuleInfo/SoftwareRelease@Value",
];

/// Whether every module gives the releases the access point gives, each
/// the same (`module_releases`). Modules that give none are gsdc's
/// default; others are left out at each release (`unsaid_extras`).
fn modules_repeat_releases(dap: &Dap, modules: &[Recognised]) -> bool {
    let first = releases_of(&dap.item.attributes);
    first.iter().any(Option::is_some)
        && modules
            .iter()
            .all(|m| releases_of(&m.module.attributes) == first)
}

fn releases_of(attributes: &[Attribute]) -> [Option<&str>; 2] {
    MODULE_RELEASES.map(|name| attribute(attributes, name))
}

/// The interface's name, where not gsdc's and every access point imported
/// gives it alike (the description's is every access point's).
fn interface_name<'a>(daps: &[&'a Dap], notes: &mut Notes) -> Option<&'a Text> {
    let names: Vec<(&Submodule, Option<&Text>)> = daps
        .iter()
        .filter_map(|d| submodules_of(d, SubmoduleKind::Interface).next())
        .map(|s| (s, s.name.as_ref()))
        .collect();
    let (first, name) = *names.first()?;
    if let Some((other, _)) = names.iter().find(|(_, n)| *n != name) {
        let why = "its name is not the first access point's interface's, and the description's interface_name is every access point's";
        notes.unsaid(
            &format!("interface `{}`'s name", other.id),
            &other.place,
            why,
        );
        return None;
    }
    let gsdcs = crate::ir::Text::english(crate::lower::INTERFACE_NAME);
    let Some(name) = name else {
        let why = "gsdc names every interface";
        notes.unsaid(
            &format!("interface `{}` without a name", first.id),
            &first.place,
            why,
        );
        return None;
    };
    (!same_text(name, &gsdcs)).then_some(name)
}

/// The ports' names, one per port of the access point with the most
/// (MOVI-C's "Port 1 - RJ45 (X4233_1)"), where every access point imported
/// names a port alike and some name is not gsdc's "Port n" (the
/// description's are every access point's); else left out, saying why.
fn port_names<'a>(daps: &[&'a Dap], notes: &mut Notes) -> Option<Vec<&'a Text>> {
    let mut names: Vec<&Text> = Vec::new();
    for dap in daps {
        // Port n of each access point, as the build numbers them.
        for (n, port) in submodules_of(dap, SubmoduleKind::Port).enumerate() {
            let why = match (&port.name, names.get(n)) {
                (None, _) => "gsdc names every port",
                (Some(name), Some(&known)) if name != known => "its name is not the same port's of the other access points, and the description's port_names are every access point's",
                (Some(_), Some(_)) => continue,
                (Some(name), None) => {
                    names.push(name);
                    continue;
                }
            };
            notes.unsaid(&format!("port `{}`'s name", port.id), &port.place, why);
            return None;
        }
    }
    let gsdcs = (1..)
        .zip(&names)
        .all(|(n, name)| same_text(name, &crate::ir::Text::gsdc(|lang| files::port(lang, n))));
    (!gsdcs).then_some(names)
}

/// The access point's ImplementationType, where the description can say
/// it: one line of text (E117 otherwise).
fn implementation_type<'a>(attributes: &'a [Attribute], notes: &mut Notes) -> Option<&'a str> {
    let (a, basis) = found(attributes, "ImplementationType")?;
    one_line(a, basis, "implementation_type", notes)
}

/// The file's ProductFamily where it is not the family its name gives,
/// which gsdc writes by default (FENA's "ABB FENA", MOVI-C's
/// "MOVI-C Decentralized Electronics" against the name's
/// `MOVI-C-Decentralized-Electronics`), and the description can say it:
/// one line of text (E117 otherwise).
fn product_family<'a>(device: &'a PnDevice, family: &str, notes: &mut Notes) -> Option<&'a str> {
    let (a, product_family) = found(&device.identity, "DeviceFunction/Family@ProductFamily")?;
    if product_family == family {
        return None;
    }
    one_line(a, product_family, "product_family", notes)
}

/// `value`, attribute `a`'s, where the description's `key`, one line of
/// text (E117), can hold it; else left out saying so.
fn one_line<'a>(a: &Attribute, value: &'a str, key: &str, notes: &mut Notes) -> Option<&'a str> {
    if value.trim().is_empty() || value.chars().any(char::is_control) {
        let why = format!("the description's {key} is one line of text (E117)");
        notes.unsaid(&a.name, &a.place, &why);
        return None;
    }
    Some(value)
}

/// The access point's RequiredSchemaVersion, where gsdc can write it: a
/// version up to the file's (E190); a later one is left out, which the
/// round trip judges.
fn required_schema_version(
    attributes: &[Attribute],
    file: Version,
    notes: &mut Notes,
) -> Option<Version> {
    let why = format!("the description's required_schema_version is a GSDML version up to the file's, {file} (E190)");
    dap_version(attributes, "RequiredSchemaVersion", file, notes, &why)
}

/// The access point's PNIO_Version where it is not the file's version
/// (which the description's file declares by default): a version up to the
/// file's (E197); a later one is left out, which the round trip judges.
fn pnio_version(attributes: &[Attribute], file: Version, notes: &mut Notes) -> Option<Version> {
    let why =
        format!("the description's pnio_version is a version up to the file's, {file} (E197)");
    dap_version(attributes, "PNIO_Version", file, notes, &why).filter(|&version| version != file)
}

/// A version an access point's attribute declares, from V1.0 to the
/// file's; left out with `why` otherwise.
fn dap_version(
    attributes: &[Attribute],
    name: &str,
    file: Version,
    notes: &mut Notes,
    why: &str,
) -> Option<Version> {
    let (a, text) = found(attributes, name)?;
    let version = Version::parse(text).filter(|&v| v >= Version::new(1, 0) && v <= file);
    if version.is_none() {
        notes.unsaid(&format!("{name} `{text}`"), &a.place, why);
    }
    version
}

/// `module_writeable_im_records`: the records the first module's
/// submodules let the controller write, which the description gives every
/// module's; a submodule that declares others is left out at its attribute.
fn module_im_records(out: &mut TomlOut, modules: &[Recognised], notes: &mut Notes) {
    const NAME: &str = "Writeable_IM_Records";
    let submodules = || {
        modules
            .iter()
            .flat_map(|m| m.access_point.into_iter().chain([m.data]))
    };
    let first = submodules()
        .next()
        .and_then(|s| attribute(&s.attributes, NAME));
    let records = first.and_then(im_records);
    for s in submodules() {
        let value = found(&s.attributes, NAME);
        if records.is_some() && value.map(|(_, v)| v) == first {
            continue;
        }
        let what = match value {
            Some(_) => format!("submodule `{}`'s {NAME}", s.id),
            // The description gives it the first's list.
            None if records.is_some() => format!("submodule `{}` without {NAME}", s.id),
            None => continue,
        };
        notes.unsaid(
            &what,
            value.map_or(&s.place, |(a, _)| &a.place),
            "the description's module_writeable_im_records is one list of I&M1 to I&M4, each once, for every module's submodules",
        );
    }
    if let Some(records) = records {
        out.key("module_writeable_im_records", list(records));
    }
}

/// A Writeable_IM_Records list the description can state: I&M1 to I&M4,
/// each once.
fn im_records(value: &str) -> Option<Vec<u8>> {
    let mut records = Vec::new();
    for token in value.split_whitespace() {
        let n: u8 = token.parse().ok().filter(|n| (1..=4).contains(n))?;
        if records.contains(&n) {
            return None;
        }
        records.push(n);
    }
    (!records.is_empty()).then_some(records)
}

/// The DAP's DNS_CompatibleName in lower case: the name of station a
/// controller assigns has lower-case labels only (IEC 61158-6-10, E132),
/// while the schema lets a file propose `FENA`; the change is said.
fn name_of_station(attributes: &[Attribute], notes: &mut Notes) -> String {
    let name = attribute(attributes, "DNS_CompatibleName").unwrap_or_default();
    let lower = name.to_ascii_lowercase();
    if lower != name {
        notes.chosen(
            "profinet.dns_name",
            format!("DNS_CompatibleName `{name}` is imported as `{lower}`: a name of station has lower-case labels only (E132); the round trip judges the change"),
        );
    }
    lower
}

fn interface_properties(out: &mut TomlOut, dap: &Dap, notes: &mut Notes, has_irt: bool) {
    let interface = submodules_of(dap, SubmoduleKind::Interface).next();
    let interface_attributes = interface.map_or(&[][..], |s| &s.attributes[..]);
    let clocks = attribute(
        interface_attributes,
        "ApplicationRelations/TimingProperties@SendClock",
    );
    if let Some(clocks) = clocks {
        out.key("send_clock", list(clocks.split_whitespace()));
    }
    if let Some(preferred) = preferred_send_clock(interface_attributes, clocks, notes) {
        out.key("preferred_send_clock", preferred);
    }
    if let Some(class) = attribute(&dap.item.attributes, "CertificationInfo@ConformanceClass") {
        out.string(
            "conformance_class",
            written_conformance_class(class, has_irt, notes),
        );
    }
    if let Some(class) = attribute(&dap.item.attributes, "CertificationInfo@NetloadClass") {
        out.string("netload_class", class);
    }
    let own = submodules_of(dap, SubmoduleKind::Virtual).next();
    let records = own.and_then(|s| found(&s.attributes, "Writeable_IM_Records"));
    match records.map(|(a, value)| (a, im_records(value))) {
        None => out.key("writeable_im_records", "[]"),
        Some((_, Some(records))) => out.key("writeable_im_records", list(records)),
        Some((a, None)) => notes.unsaid(
            "Writeable_IM_Records",
            &a.place,
            "the description's writeable_im_records is a list of I&M1 to I&M4, each once",
        ),
    }
    if mrp_client(dap) {
        out.key("media_redundancy", true);
    }
}

/// TimingProperties' PreferredSendClock, when it is one of the send clocks
/// (the schema's default, 32, when SendClock is not written), as the
/// description's `preferred_send_clock` is (E150).
fn preferred_send_clock(
    interface: &[Attribute],
    clocks: Option<&str>,
    notes: &mut Notes,
) -> Option<u16> {
    const NAME: &str = "ApplicationRelations/TimingProperties@PreferredSendClock";
    let (a, preferred) = found(interface, NAME)?;
    let offered = |clock: u16| {
        clocks
            .unwrap_or("32")
            .split_whitespace()
            .any(|c| c.parse() == Ok(clock))
    };
    if let Some(clock) = preferred.parse().ok().filter(|&c| offered(c)) {
        return Some(clock);
    }
    let why = "the description's preferred_send_clock is one of its send clocks (E150)";
    notes.unsaid(&format!("PreferredSendClock `{preferred}`"), &a.place, why);
    None
}

/// Conformance class C (isochronous real time, RT_CLASS_3) is written as
/// B when its RT_CLASS_3 is not imported (`irt`), and said.
fn written_conformance_class<'a>(class: &'a str, has_irt: bool, notes: &mut Notes) -> &'a str {
    if class != "C" || has_irt {
        return class;
    }
    notes.chosen(
        "profinet.conformance_class",
        "conformance class C is imported as B: the interface's RT_CLASS_3 is not imported (its RT_Class3Properties are missing, or a value does not fit [profinet.irt]), and class C is RT_CLASS_3's (E151); the round trip judges the change".to_string(),
    );
    "B"
}

/// A DAP's submodules of one kind, in the file's order.
fn submodules_of(dap: &Dap, kind: SubmoduleKind) -> impl Iterator<Item = &Submodule> {
    dap.item.submodules.iter().filter(move |s| s.kind == kind)
}

/// Whether a DAP's interface is an MRP client.
fn mrp_client(dap: &Dap) -> bool {
    submodules_of(dap, SubmoduleKind::Interface)
        .next()
        .is_some_and(|s| attribute(&s.attributes, "MediaRedundancy@SupportedRole").is_some())
}

/// An ident number as the description writes it.
fn hex32(n: u32) -> String {
    format!("0x{n:08X}")
}

/// `[profinet.module_info]` and `[profinet.module_name]`: what each kind
/// of module's info text adds to gsdc's description of it, and a vendor's
/// telegram 1's name.
fn module_texts(out: &mut TomlOut, modules: &[Recognised], notes: &mut Notes) {
    categories(out, modules, notes);
    let profidrive = modules.iter().any(Recognised::is_profidrive);
    let mut infos: Vec<(&str, String)> = Vec::new();
    let mut name = None;
    let mut own: Vec<(String, Vec<(&str, String)>)> = Vec::new();
    for (key, kind) in MODULE_KIND_KEYS {
        let of_kind: Vec<&Recognised> = modules.iter().filter(|m| m.kind == kind).collect();
        let Some(first) = of_kind.first() else {
            continue;
        };
        let gsdc_name = crate::lower::module_name(kind, first.layout)
            .or_else(|| profidrive.then(crate::lower::profidrive_telegram_1_name));
        // Standard telegram 1 of a card without PROFIdrive: the first's name
        // is the kind's, `module_name`, and gsdc's description says it.
        let kind_name = gsdc_name
            .clone()
            .unwrap_or_else(|| ir_text(first.module.name.as_ref().unwrap_or(&Text::default())));
        if gsdc_name.is_none() {
            name = first.module.name.as_ref().map(text);
        }
        // What the kind's modules add to gsdc's description: the first's,
        // where it is gsdc's description with or without words after it.
        let added: Vec<Option<Text>> = of_kind
            .iter()
            .map(|m| added_info(m, &kind_name, profidrive))
            .collect();
        let kind_info = added
            .first()
            .cloned()
            .flatten()
            .filter(|t| !t.primary.is_empty());
        if let Some(info) = &kind_info {
            infos.push((key, text(info)));
        }
        for (m, added) in of_kind.iter().zip(added) {
            let module_name = m.module.name.as_ref().filter(|n| !same_text(n, &kind_name));
            let info_as_kinds =
                added.is_some() && added.filter(|t| !t.primary.is_empty()) == kind_info;
            let texts = own_texts(m, (module_name, !info_as_kinds), notes);
            if !texts.is_empty() {
                own.push((m.code_name(), texts));
            }
        }
    }
    if !infos.is_empty() {
        out.table("profinet.module_info");
        for (key, info) in infos {
            out.key(key, info);
        }
    }
    if let Some(name) = name {
        out.table("profinet.module_name");
        out.key("standard_telegram_1", name);
    }
    for (module, texts) in own {
        out.table(&format!("profinet.module_texts.{module}"));
        for (key, value) in texts {
            out.key(key, value);
        }
    }
}

/// A module's own texts (`[profinet.module_texts]`): its name where not
/// gsdc's or its kind's, its info where its kind's would not give it, and
/// its data submodule's name and info where not the module's.
fn own_texts<'k>(
    m: &Recognised,
    (name, own_info): (Option<&Text>, bool),
    notes: &mut Notes,
) -> Vec<(&'k str, String)> {
    let mut texts: Vec<(&str, String)> = name.map(|n| ("name", text(n))).into_iter().collect();
    match (&m.module.info, own_info) {
        (Some(info), true) => texts.push(("info", text(info))),
        (None, _) => notes.unsaid(
            &format!("module `{}` without an InfoText", m.module.id),
            &m.module.place,
            "gsdc gives every module an info text",
        ),
        (Some(_), false) => {}
    }
    if let Some(own) = other_than(&m.data.name, &m.module.name) {
        texts.push(("submodule_name", text(own)));
    }
    if let Some(own) = other_than(&m.data.info, &m.module.info) {
        texts.push(("submodule_info", text(own)));
    }
    texts
}

/// A submodule's own text, where it has one that is not its module's.
fn other_than<'a>(own: &'a Option<Text>, module: &Option<Text>) -> Option<&'a Text> {
    own.as_ref().filter(|&o| Some(o) != module.as_ref())
}

/// Whether a file's text is gsdc's, in English and in every language the
/// file gives it.
fn same_text(file: &Text, gsdc: &crate::ir::Text) -> bool {
    *file.primary == *gsdc.en
        && file
            .translations
            .iter()
            .all(|(code, text)| gsdc.get(code) == text)
}

/// `[profinet.subslot_labels]`, where every access point imported labels
/// its interface and then each of its ports (`SubslotList`), and a port's
/// label is the same in each; else the labels are left out, saying why.
fn subslot_labels(out: &mut TomlOut, daps: &[&Dap], notes: &mut Notes) {
    let Some(labelled) = daps.iter().find(|d| !d.subslot_labels.is_empty()) else {
        return;
    };
    let mut ports: Vec<&Text> = Vec::new();
    let mut interface = None;
    for dap in daps {
        let same_ports = labels_of(dap).and_then(|(own_interface, own_ports)| {
            if interface.is_some_and(|i| i != own_interface) {
                return Err("its interface's label is not the other access points'");
            }
            interface = Some(own_interface);
            for (n, label) in own_ports.into_iter().enumerate() {
                match ports.get(n) {
                    Some(&known) if known != label => {
                        return Err(
                            "a port's label is not the same port's of the other access points",
                        )
                    }
                    Some(_) => {}
                    None => ports.push(label),
                }
            }
            Ok(())
        });
        if let Err(why) = same_ports {
            let why =
                format!("{why}, and the description's subslot_labels are every access point's");
            notes.unsaid("SubslotList", &labelled.item.place, &why);
            return;
        }
    }
    out.table("profinet.subslot_labels");
    out.key(
        "interface",
        text(interface.expect("a labelled access point")),
    );
    out.key("ports", list(ports.into_iter().map(text)));
}

/// An access point's labels of its interface and of each of its ports,
/// when its `SubslotList` labels those and nothing else, in that order.
fn labels_of(dap: &Dap) -> Result<(&Text, Vec<&Text>), &'static str> {
    let subslots: Vec<Option<u32>> = submodules_of(dap, SubmoduleKind::Interface)
        .chain(submodules_of(dap, SubmoduleKind::Port))
        .map(|s| s.subslot)
        .collect();
    let labelled: Vec<Option<u32>> = dap
        .subslot_labels
        .iter()
        .map(|(n, _)| n.map(u32::from))
        .collect();
    if labelled != subslots {
        return Err("its SubslotList does not label its interface and then each of its ports");
    }
    let mut labels = dap.subslot_labels.iter().map(|(_, label)| label.as_ref());
    let interface = labels
        .next()
        .flatten()
        .ok_or("a SubslotItem has no TextId")?;
    let ports = labels
        .collect::<Option<Vec<&Text>>>()
        .ok_or("a SubslotItem has no TextId")?;
    Ok((interface, ports))
}

/// `[profinet.categories]`: each kind of module's group in the hardware
/// catalog, where its modules share one that is not gsdc's. Modules of a
/// kind in different groups are left out of it (W600): the description
/// puts a kind in one.
fn categories(out: &mut TomlOut, modules: &[Recognised], notes: &mut Notes) {
    let profidrive = modules.iter().any(Recognised::is_profidrive);
    let mut stated = Vec::new();
    for (key, kind) in MODULE_KIND_KEYS {
        let of_kind: Vec<&Recognised> = modules.iter().filter(|m| m.kind == kind).collect();
        let Some(first) = of_kind.first() else {
            continue;
        };
        // None, or gsdc's own (which differ by layout): nothing to state.
        let gsdcs = of_kind
            .iter()
            .all(|m| group_of(m).is_none_or(|g| is_gsdc_category(g, m, profidrive)));
        if gsdcs {
            continue;
        }
        let group = group_of(first);
        match of_kind.iter().find(|m| group_of(m) != group) {
            Some(other) => {
                let why = "the description's categories put every module of a kind in one group";
                notes.unsaid(
                    &format!("module `{}`'s category", other.module.id),
                    &other.module.place,
                    why,
                );
            }
            None => stated.extend(group.map(|g| (key, text(g)))),
        }
    }
    if !stated.is_empty() {
        out.table("profinet.categories");
        for (key, group) in stated {
            out.key(key, group);
        }
    }
}

/// A module's group in the hardware catalog.
fn group_of<'a>(m: &Recognised<'a>) -> Option<&'a Text> {
    attribute_text(&m.module.attributes, "ModuleInfo@CategoryRef")
}

/// Whether `group` is gsdc's category of the module in every language it
/// has.
fn is_gsdc_category(group: &Text, m: &Recognised, profidrive: bool) -> bool {
    let gsdc = crate::lower::module_category(m.kind, m.layout, profidrive);
    same_text(group, &gsdc.text.text)
}

/// What a module's info text adds after gsdc's description of it, in
/// every language (empty when it adds nothing); `None` when the text is
/// not gsdc's description at all.
fn added_info(m: &Recognised, name: &crate::ir::Text, profidrive: bool) -> Option<Text> {
    let info = m.module.info.as_ref()?;
    let gsdc = crate::lower::module_description(m.kind, m.layout, name, profidrive);
    let strip = |code: &str, full: &str| -> Option<String> {
        let own = gsdc.get(code);
        if full == own {
            return Some(String::new());
        }
        full.strip_prefix(&crate::lower::info_prefix(code, own))
            .map(str::to_string)
    };
    let mut added = Text::plain(strip("en", &info.primary)?);
    let mut translations = (*added.translations).clone();
    for (code, full) in info.translations.iter() {
        let language: std::sync::Arc<str> = std::sync::Arc::from(code);
        translations.insert_first(&language, &strip(code, full)?);
    }
    added.translations = std::sync::Arc::new(translations);
    Some(added)
}

/// A file's text as the description model's.
fn ir_text(t: &Text) -> crate::ir::Text {
    let mut text = crate::ir::Text::english(t.primary.to_string());
    text.others = t
        .translations
        .iter()
        .map(|(c, s)| (c.to_string(), s.to_string()))
        .collect();
    text
}

/// `[profinet.ident_numbers]`: every number as the file has it.
fn ident_numbers(out: &mut TomlOut, dap: &Dap, modules: &[Recognised]) {
    out.table("profinet.ident_numbers");
    let dap_ident = dap.item.ident.unwrap_or(0);
    out.key("dap", hex32(dap_ident));
    let submodule = |kind| submodules_of(dap, kind);
    if let Some(s) = submodule(SubmoduleKind::Virtual).next() {
        out.key("dap_submodule", hex32(s.ident.unwrap_or(0)));
    }
    if let Some(s) = submodule(SubmoduleKind::Interface).next() {
        out.key("interface", hex32(s.ident.unwrap_or(0)));
    }
    let ports: Vec<String> = submodule(SubmoduleKind::Port)
        .map(|s| hex32(s.ident.unwrap_or(0)))
        .collect();
    out.key("ports", list(ports));
    if let Some(ap) = modules.iter().find_map(|m| m.access_point) {
        out.key("access_point", hex32(ap.ident.unwrap_or(0)));
    }
    let entries = |of: &dyn Fn(&Recognised) -> Option<u32>| -> String {
        let items: Vec<String> = modules
            .iter()
            .filter_map(|m| Some(format!("{} = {}", m.code_name(), hex32(of(m)?))))
            .collect();
        format!("{{ {} }}", items.join(", "))
    };
    out.key("modules", entries(&|m| m.module.ident));
    let differ: Vec<&Recognised> = modules
        .iter()
        .filter(|m| m.data.ident != m.module.ident)
        .collect();
    if !differ.is_empty() {
        out.key(
            "submodules",
            entries(&|m| (m.data.ident != m.module.ident).then_some(m.data.ident?)),
        );
    }
}

/// Whether the file gsdc writes says what attribute `a` says, as the round
/// trip's comparison reads both: `known` holds the attributes gsdc writes
/// here, each with the one value it writes or `None` for the value the
/// description states (imported from `a`). One gsdc does not write means
/// its schema default (FENA's `NumberOfAdditionalInputCR="0"`); one it
/// writes may differ in spelling only (MOVI-C's `StartupMode="Advanced;Legacy"`,
/// a set).
fn fits(a: &Attribute, known: &[(&str, Option<&str>)]) -> bool {
    let value = attribute(std::slice::from_ref(a), &a.name);
    let same = |written: Option<&str>| crate::diff::same_gsdml_value(&a.name, written, value);
    let mut written = known
        .iter()
        .filter(|(name, _)| *name == &*a.name)
        .peekable();
    match written.peek() {
        None => same(None),
        Some(_) => written.any(|(_, v)| v.is_none_or(|v| same(Some(v)))),
    }
}

/// Whether `dap` offers one of the safety modules imported.
fn offers_safety(dap: &Dap, safety: &[(String, Offer)]) -> bool {
    dap.useable_modules
        .iter()
        .any(|r| safety.iter().any(|(id, _)| *id == r.target))
}

/// `functional_safety_class`: false where no access point that offers a
/// safety module declares the `FunctionalSafety` application class (SEW's
/// MOVI-C), else gsdc's default; where some do and some do not, the round
/// trip names those that differ.
fn functional_safety_class<'a>(
    daps: impl Iterator<Item = &'a Dap>,
    safety: &[(String, Offer)],
) -> bool {
    let declares = |dap: &Dap| {
        attribute(&dap.item.attributes, "CertificationInfo@ApplicationClass")
            .is_some_and(|c| c.split(';').any(|c| c == "FunctionalSafety"))
    };
    let mut offering = daps.filter(|d| offers_safety(d, safety)).peekable();
    offering.peek().is_none() || offering.any(declares)
}

/// The device access point's `ApplicationClass` gsdc writes: `Isochronous`
/// with the modules' isochronous mode, `EnergySaving` with PROFIenergy,
/// `FunctionalSafety` with safety modules.
fn application_class((isochronous, energy, safety): (bool, bool, bool)) -> Option<String> {
    let classes: Vec<&str> = [
        ("Isochronous", isochronous),
        ("EnergySaving", energy),
        ("FunctionalSafety", safety),
    ]
    .into_iter()
    .filter_map(|(class, declared)| declared.then_some(class))
    .collect();
    (!classes.is_empty()).then(|| classes.join(";"))
}

/// W600 for each of `attributes` of element `of` that is not `known`.
fn unsaid_attributes(
    notes: &mut Notes,
    attributes: &[Attribute],
    known: &[(&str, Option<&str>)],
    of: &str,
) {
    for a in attributes.iter().filter(|a| !fits(a, known)) {
        let why = "the description has no key for it, or gsdc writes another value";
        notes.unsaid(&format!("{of} {}", a.name), &a.place, why);
    }
}

/// W600 for each attribute and element the description has no place for,
/// or whose value gsdc writes another way.
fn unsaid_extras(
    device: &PnDevice,
    (first, later): (&Dap, &[daps::DapEntry]),
    (modules, empty): (&[Recognised], Option<&slots::Empty>),
    (timing, has_energy, safety): (&irt::Declared, bool, &[(String, Offer)]),
    notes: &mut Notes,
) {
    let with = |always: &'static [(&'static str, Option<&'static str>)], when: bool, extra| {
        let extra: &[_] = if when { extra } else { &[] };
        [always, extra].concat()
    };
    let (has_irt, has_isochronous) = (timing.irt.is_some(), timing.isochronous.is_some());
    let dap_known = with(
        DAP_ATTRIBUTES,
        has_energy,
        &[(profienergy::ASE_SUPPORTED, None)],
    );
    let own_known: Vec<_> = SUBMODULE_ATTRIBUTES
        .iter()
        .copied()
        .chain(profienergy::SUBMODULE_ATTRIBUTES.map(|name| (name, None)))
        .collect();
    let interface_known = [
        with(INTERFACE_ATTRIBUTES, has_irt, irt::IRT_INTERFACE_ATTRIBUTES),
        with(&[], has_isochronous, irt::ISOCHRONOUS_INTERFACE_ATTRIBUTES),
    ]
    .concat();
    let port_known = with(PORT_ATTRIBUTES, has_irt, irt::IRT_PORT_ATTRIBUTES);
    let mut data_known = with(
        SUBMODULE_ATTRIBUTES,
        has_isochronous,
        irt::ISOCHRONOUS_SUBMODULE_ATTRIBUTES,
    );
    if submodules_repeat_categories(modules) {
        data_known.push((CATEGORY, None));
    }
    for dap in [first].into_iter().chain(later.iter().map(|l| l.dap)) {
        let class = application_class((has_isochronous, has_energy, offers_safety(dap, safety)));
        let mut known = dap_known.clone();
        if let Some(class) = &class {
            known.push(("CertificationInfo@ApplicationClass", Some(class)));
        }
        unsaid_attributes(notes, &dap.item.attributes, &known, "DeviceAccessPointItem");
        for s in &dap.item.submodules {
            let known = match s.kind {
                SubmoduleKind::Interface => &interface_known,
                SubmoduleKind::Port => &port_known,
                _ => &own_known,
            };
            unsaid_attributes(notes, &s.attributes, known, s.kind.element());
        }
    }
    let mut module_known = vec![(CATEGORY, None)];
    if modules_repeat_releases(first, modules) {
        module_known.extend(MODULE_RELEASES.map(|name| (name, None)));
    }
    for m in modules {
        unsaid_attributes(notes, &m.module.attributes, &module_known, "ModuleItem");
        if let Some(s) = m.access_point {
            unsaid_attributes(
                notes,
                &s.attributes,
                SUBMODULE_ATTRIBUTES,
                "VirtualSubmoduleItem",
            );
        }
        unsaid_attributes(
            notes,
            &m.data.attributes,
            &data_known,
            "VirtualSubmoduleItem",
        );
    }
    if let Some(empty) = empty {
        unsaid_attributes(notes, &empty.module.attributes, &[], "ModuleItem");
        let submodules = &empty.module.submodules;
        for s in submodules {
            unsaid_attributes(
                notes,
                &s.attributes,
                SUBMODULE_ATTRIBUTES,
                "VirtualSubmoduleItem",
            );
        }
    }
    for a in device.identity.iter().filter(|a| {
        ![
            "DeviceIdentity/VendorName@Value",
            "DeviceIdentity/InfoText@TextId",
            "DeviceFunction/Family@MainFamily",
            "DeviceFunction/Family@ProductFamily",
        ]
        .contains(&&*a.name)
    }) {
        notes.unsaid(&a.name, &a.place, "the description has no key for it");
    }
    for a in &device.other {
        notes.unsaid(&a.name, &a.place, "the description has no key for it");
    }
    for u in &device.unit_diagnosis {
        notes.unsaid(
            &format!("UnitDiagTypeItem {}", u.id),
            &u.place,
            "the description has no PROFINET unit diagnosis",
        );
    }
    // A module of the first access point is imported or left out with its
    // reason; one only a later access point offers goes with it (left out
    // in `daps`).
    let offered = |m: &PnModule| {
        device
            .daps
            .iter()
            .flat_map(|d| &d.useable_modules)
            .any(|r| r.target == m.id)
    };
    for m in device.modules.iter().filter(|m| !offered(m)) {
        notes.unsaid(
            &format!("ModuleItem `{}`", m.id),
            &m.place,
            "no device access point offers it",
        );
    }
}
