//! The PROFINET part: identity, the device access point, the selectable
//! modules and the parameter records.

use super::checks::Checker;
use crate::description::{self as raw, ModulePkw};
use crate::diag::Diagnostic;
use crate::i18n::{self, files};
use crate::ir::profinet::{
    Category, Dap, Date, GraphicItem, Module, ModuleKind, Port, Profinet, SubslotLabels, TextRef,
    TimeOfDay, Version, FIRST_PORT_SUBSLOT,
};
use crate::ir::{Device, Layout, Mappings, PkwKind, Telegram, Text};
use crate::spec::Introduced;
use std::collections::{BTreeMap, BTreeSet};
use std::ops::Range;
use toml::Spanned;

mod daps;
mod diagnosis;
mod fail_safe;
mod idents;
mod ids;
mod interface;
mod io;
mod irt;
mod profienergy;
pub(crate) use profienergy::is_version as is_profile_version;
mod profile_words;
mod pzd_names;
mod safety;
mod slots;
pub(crate) use slots::EMPTY_MODULE_IDENT;
mod records;
mod stack;
mod submodule_records;
pub(crate) use stack::MAX_SLOT;

pub(crate) use diagnosis::{
    ADD_VALUE_BYTES, CHANNEL_ERROR_TYPES, EXTENDED_ERROR_TYPES, PROFILE_ERROR_TYPES,
};
pub(crate) use io::{
    category as module_category, description as module_description, gsdc_name as module_name,
    info_prefix, io_length, pkw_words, profidrive_telegram_1_name, IoNeed, Offer, MAX_IO_LENGTH,
    STANDARD_TELEGRAM_2_WORDS,
};
pub(crate) use profile_words::profile_words;

/// `info` after a notice that the file is a draft, naming the identity
/// numbers that are placeholders, while any is one: the DAP's InfoText
/// (and DeviceIdentity's, the same text) is what TIA Portal's catalog shows
/// of the device. gsdc's words in each language it has them in, English in
/// another.
fn draft(
    info: Text,
    (vendor, device): (&Spanned<raw::IdentNumber>, &Spanned<raw::IdentNumber>),
) -> Text {
    let placeholders: Vec<String> = [("VendorID", vendor), ("DeviceID", device)]
        .into_iter()
        .filter(|(_, id)| id.get_ref().placeholder)
        .map(|(name, id)| format!("{name} 0x{:04X}", id.get_ref().value.get_ref()))
        .collect();
    if placeholders.is_empty() {
        return info;
    }
    Text::composed(&[&info], |code, lang| {
        let notice = match placeholders.as_slice() {
            [one] => files::draft_one(lang, one),
            names => files::draft_many(lang, &i18n::list(lang, names)),
        };
        format!("{notice}{}", info.get(code))
    })
}

/// The GSDML versions gsdc writes: it emits nothing a version lacks. What
/// it writes in V2.32 the V2.44 schema accepts, and the corpus's V2.33 and
/// V2.34 files (ABB's FENA, Hilscher's, rt-labs', SEW's MOVI-C) have each
/// element and attribute of it; they are the drive files' versions that
/// `gsdc import` reads.
pub(crate) const SUPPORTED_VERSIONS: [Version; 3] = [
    Version::new(2, 32),
    Version::new(2, 33),
    Version::new(2, 34),
];
pub(crate) const DEFAULT_VERSION: Version = Version::new(2, 32);
/// gsdc's name of the interface submodule, where the description gives
/// none.
pub(crate) const INTERFACE_NAME: &str = "PN-IO";

pub fn lower(
    cx: &mut Checker,
    p: &Spanned<raw::Profinet>,
    desc: &raw::Description,
    (device, telegram, mappings): (&Device, &Telegram, &Mappings),
) -> Option<Profinet> {
    let records = records::plans(cx, p, desc, mappings);
    let interface_properties =
        irt::timing(cx, p.get_ref()).and_then(|timing| interface::properties(cx, p, timing));
    let near = p.span();
    let p = p.get_ref();
    let gsdml_version = version(cx, p.gsdml_version.as_ref())?;
    let required_schema_version =
        required_schema_version(cx, p.required_schema_version.as_ref(), gsdml_version)?;
    let pnio_version = pnio_version(cx, p.pnio_version.as_ref(), gsdml_version)?;
    let implementation_type = p
        .implementation_type
        .as_ref()
        .map(|t| cx.required(t, "profinet.implementation_type"));
    let product_family = p.product_family.as_ref().map_or_else(
        || desc.device.family.get_ref().clone(),
        |f| cx.required(f, "profinet.product_family"),
    );
    let interface_name = p.interface_name.as_ref().map_or_else(
        || Text::english(INTERFACE_NAME),
        |n| cx.text(n, None, "profinet.interface_name"),
    );
    let date = date(cx, &p.date)?;
    let file_vendor = file_name_part(
        cx,
        p.file_vendor.as_ref().unwrap_or(&desc.device.vendor),
        "profinet.file_vendor",
    );
    let family = file_name_part(cx, &desc.device.family, "device.family");
    placeholder_warning(cx, &p.vendor_id, ("vendor ID", "vendor_id"));
    placeholder_warning(cx, &p.device_id, ("device ID", "device_id"));
    let info = p.info.as_ref().map(|i| cx.text(i, None, "profinet.info"));
    let ports = cx.spanned_in_range(&p.ports, 1, 16, "ports")?;
    let interface_properties = interface_properties?;
    let client = p.media_redundancy.as_ref().filter(|m| *m.get_ref());
    let media_redundancy = client.is_some();
    interface::check_ring_ports(cx, client.map(Spanned::span), ports);
    let kinds = modules(cx, p, telegram);
    let telegram_1_name = standard_telegram_1_name(cx, (p, near), desc, telegram, &kinds)?;
    // As the description says it, whatever errors its settings have.
    let master_sets_settings = desc.settings.iter().any(|s| {
        s.set_at
            .as_ref()
            .is_none_or(|at| *at.get_ref() == raw::SetAt::Master)
    });
    let fail_safe = fail_safe::names(cx, p, &kinds, master_sets_settings);
    let pzd_names = pzd_names::lower(cx, p.pzd_names.as_ref(), telegram);
    let profile_words =
        profile_words::lower(cx, &p.profile_word_names, &kinds, telegram.profidrive);
    let stated = stated_categories(cx, p);
    let mut categories: Vec<Category> = Vec::new();
    let mut modules: Vec<Module> = kinds
        .into_iter()
        .map(|(kind, layout)| {
            let info = module_info(cx, &p.module_info, kind);
            let category = stated.iter().find(|(k, _)| *k == kind).map_or_else(
                || io::category(kind, layout, telegram.profidrive),
                |(_, c)| c.clone(),
            );
            if !categories.iter().any(|c| c.id == category.id) {
                categories.push(category.clone());
            }
            let names = io::Names {
                telegram_1: &telegram_1_name,
                info,
                category: category.id,
                fail_safe: fail_safe.as_ref(),
                pzd: pzd_names.as_ref(),
                profile_words: &profile_words,
            };
            io::module((kind, layout), telegram, (mappings, &records), names)
        })
        .collect();
    let mut ports: Vec<Port> = (1..=ports).map(|n| port(n, media_redundancy)).collect();
    let idents = idents::apply(cx, &p.ident_numbers, &mut modules, &mut ports);
    apply_module_texts(cx, &p.module_texts, &mut modules);
    apply_access_point_texts(cx, p.access_point_texts.as_ref(), &mut modules);
    {
        use crate::i18n::files as w;
        if idents.numbered_by_gsdc {
            cx.convention(
                if idents.stated {
                    w::IDENT_NUMBERS_REST
                } else {
                    w::IDENT_NUMBERS
                },
                w::IDENT_NUMBERS_RULE,
                w::IDENT_NUMBERS_WHY,
            );
        }
        cx.requirement(w::DAP, w::DAP_SERVICES, w::DAP_SERVICES_WHY);
        cx.requirement(
            w::INTERFACE,
            w::INTERFACE_SERVICES,
            w::INTERFACE_SERVICES_WHY,
        );
    }
    let value_items = records::value_items(mappings, &modules);
    let reading_plans = records::reading_plans(mappings, &modules);
    let module_values = records::module_values(mappings, &modules);
    // The PROFINET part's own info text, else the device's, else its name;
    // after the draft notice while an identity is a placeholder.
    let device_info = TextRef::new(
        ids::DEVICE_INFO,
        draft(
            info.or_else(|| device.info.clone())
                .unwrap_or_else(|| device.name.clone()),
            (&p.vendor_id, &p.device_id),
        ),
    );
    let module_slots = slots::module_slots(cx, p.module_slots.as_ref());
    let empty_module = slots::empty_module(cx, p.empty_module.as_ref());
    let safety_modules = safety::lower(cx, &p.safety_modules, &mut categories);
    let (module_slots, empty_module, safety_modules) =
        (module_slots?, empty_module?, safety_modules?);
    let first = daps::First {
        idents: &idents,
        name: p.name.as_ref().map_or_else(
            || device.name.clone(),
            |n| cx.text(n, None, "profinet.name"),
        ),
        info: device_info.clone(),
        ports,
        media_redundancy,
        device,
        version: gsdml_version,
        pnio_version,
        placement: io::Placement {
            module_slots,
            empty: empty_module.as_ref(),
            safety: &safety_modules,
        },
    };
    let daps = daps::lower(cx, p, first, &modules);
    let channel_diagnosis = diagnosis::lower(cx, &p.channel_diagnosis);
    let profienergy = profienergy::lower(cx, p.profienergy.as_ref(), gsdml_version);
    let mut daps = daps?;
    let record_lists = submodule_records::lower_lists(cx, p, &mut daps);
    let most_ports = daps.iter().map(|d| d.ports.len()).max().unwrap_or(0);
    let subslot_labels = subslot_labels(cx, p.subslot_labels.as_ref(), most_ports);
    let named_ports = name_ports(cx, p.port_names.as_ref(), &mut daps, most_ports);
    let module_releases = module_releases(cx, p.module_releases.as_ref(), &daps[0]);
    let (subslot_labels, module_releases) = (subslot_labels?, module_releases?);
    named_ports?;
    Some(Profinet {
        file_name: format!(
            "GSDML-{gsdml_version}-{file_vendor}-{family}-{}.xml",
            date.compact()
        ),
        gsdml_version,
        pnio_version,
        required_schema_version,
        implementation_type,
        product_family,
        date,
        // PI numbers vendors from 1: the schema's DeviceIdentity takes 0x0000,
        // but its CIM_Interface, naming the same vendor, does not (hex0T).
        vendor_id: cx.spanned_in_range(&p.vendor_id.get_ref().value, 1, 0xFFFF, "vendor_id")?,
        vendor_id_placeholder: p.vendor_id.get_ref().placeholder,
        device_id: cx.spanned_in_range(&p.device_id.get_ref().value, 1, 0xFFFF, "device_id")?,
        device_id_placeholder: p.device_id.get_ref().placeholder,
        device_info,
        dns_name: dns_name(cx, &p.dns_name),
        min_device_interval: cx.spanned_in_range(
            &p.min_device_interval,
            1,
            4096,
            "min_device_interval",
        )?,
        interface: TextRef::new(ids::INTERFACE_TEXT, interface_name),
        interface_ident: idents.interface,
        access_point_ident: idents.access_point,
        daps,
        subslot_labels,
        module_releases,
        submodule_categories: p
            .submodule_categories
            .as_ref()
            .is_some_and(|s| *s.get_ref()),
        functional_safety_class: p
            .functional_safety_class
            .as_ref()
            .is_none_or(|s| *s.get_ref()),
        interface_properties,
        categories,
        device_symbol: device.symbol.as_ref().map(|_| GraphicItem {
            id: ids::DEVICE_SYMBOL.to_string(),
            file: format!(
                "GSDML-{:04X}-{:04X}-{family}",
                p.vendor_id.get_ref().value.get_ref(),
                p.device_id.get_ref().value.get_ref()
            ),
        }),
        modules,
        module_slots,
        empty_module,
        safety_modules,
        value_items,
        records: reading_plans,
        module_values,
        channel_diagnosis: channel_diagnosis?,
        record_lists: record_lists?,
        profienergy: profienergy?,
    })
}

/// What the description adds to a kind of module's info text.
fn module_info(cx: &mut Checker, info: &raw::KindTexts, kind: ModuleKind) -> Option<Text> {
    kind_text(info, kind).map(|t| cx.text(t, None, "module info"))
}

/// A kind of module's text of `texts`.
fn kind_text(texts: &raw::KindTexts, kind: ModuleKind) -> Option<&Spanned<raw::Text>> {
    match kind {
        ModuleKind::Pzd => texts.user_defined.as_ref(),
        ModuleKind::StandardTelegram1 => texts.standard_telegram_1.as_ref(),
        ModuleKind::StandardTelegram2 => texts.standard_telegram_2.as_ref(),
    }
}

/// Each kind of module with the tag of its category's IDs.
const KINDS: [(ModuleKind, &str); 3] = [
    (ModuleKind::Pzd, "USER_DEFINED"),
    (ModuleKind::StandardTelegram1, "STANDARD_TELEGRAM_1"),
    (ModuleKind::StandardTelegram2, "STANDARD_TELEGRAM_2"),
];

/// `[profinet.categories]`: the hardware catalog's group of each kind of
/// module it names, one CategoryItem for each text however many kinds
/// share it. The kinds it leaves out are in gsdc's groups.
fn stated_categories(cx: &mut Checker, p: &raw::Profinet) -> Vec<(ModuleKind, Category)> {
    let mut stated: Vec<(ModuleKind, Category)> = Vec::new();
    for (kind, tag) in KINDS {
        let Some(given) = kind_text(&p.categories, kind) else {
            continue;
        };
        let text = cx.text(given, None, "category");
        let shared = stated.iter().find(|(_, c)| c.text.text == text);
        let category = shared.map_or_else(
            || Category {
                id: format!("IDC_{tag}"),
                text: TextRef::new(format!("IDT_CATEGORY_{tag}"), text),
            },
            |(_, c)| c.clone(),
        );
        stated.push((kind, category));
    }
    stated
}

/// `[profinet.module_texts]`: each module's own texts, in place of those
/// gsdc and the kind's keys give it (E177 for a key that names no module).
/// Its data submodule shows the module's name and info unless given its
/// own.
fn apply_module_texts(
    cx: &mut Checker,
    given: &BTreeMap<Spanned<String>, Spanned<raw::ModuleTexts>>,
    modules: &mut [Module],
) {
    for (key, texts) in given {
        let texts = texts.get_ref();
        let mut lower = |text: &Option<Spanned<raw::Text>>, field: &str| {
            let what = format!("profinet.module_texts.{}.{field}", key.get_ref());
            text.as_ref().map(|t| cx.text(t, None, &what))
        };
        let name = lower(&texts.name, "name");
        let info = lower(&texts.info, "info");
        let submodule_name = lower(&texts.submodule_name, "submodule_name");
        let submodule_info = lower(&texts.submodule_info, "submodule_info");
        idents::for_module(cx, key, modules, |m| {
            let tag = ids::module_tag(m.kind, m.layout);
            if let Some(name) = name {
                m.name.text = name;
            }
            if let Some(info) = info {
                m.info.text = info;
            }
            m.submodule_name = submodule_name.map_or_else(
                || m.name.clone(),
                |t| TextRef::new(format!("IDT_SUBMODULE_{tag}"), t),
            );
            m.submodule_info = submodule_info.map_or_else(
                || m.info.clone(),
                |t| TextRef::new(format!("IDT_SUBMODULE_INFO_{tag}"), t),
            );
        });
    }
}

/// `[profinet.access_point_texts]`: the PROFIdrive modules' access point's
/// name and info, in place of gsdc's (E002 where no module has one).
fn apply_access_point_texts(
    cx: &mut Checker,
    given: Option<&Spanned<raw::AccessPointTexts>>,
    modules: &mut [Module],
) {
    let Some(given) = given else { return };
    if !modules.iter().any(|m| m.access_point.is_some()) {
        cx.push(
            Diagnostic::error("E002", "access point texts on a card whose modules have no access point")
                .at(given.span())
                .label("no PROFIdrive module")
                .help("remove [profinet.access_point_texts], or offer a standard telegram on a PROFIdrive card: its modules have the access point"),
        );
        return;
    }
    let texts = given.get_ref();
    let mut lower = |text: &Option<Spanned<raw::Text>>, field: &str| {
        let what = format!("profinet.access_point_texts.{field}");
        text.as_ref().map(|t| cx.text(t, None, &what))
    };
    let (name, info) = (lower(&texts.name, "name"), lower(&texts.info, "info"));
    for access_point in modules.iter_mut().filter_map(|m| m.access_point.as_mut()) {
        if let Some(name) = &name {
            access_point.name.text = name.clone();
        }
        if let Some(info) = &info {
            access_point.info.text = info.clone();
        }
    }
}

/// `[profinet.subslot_labels]`: the interface's label and one for each
/// port of the access point with the most (E191 when the count differs).
fn subslot_labels(
    cx: &mut Checker,
    given: Option<&Spanned<raw::SubslotLabels>>,
    most_ports: usize,
) -> Option<Option<SubslotLabels>> {
    let Some(given) = given else {
        return Some(None);
    };
    let given = given.get_ref();
    let interface = cx.text(&given.interface, None, "profinet.subslot_labels.interface");
    let ports: Vec<TextRef> = (1..)
        .zip(given.ports.get_ref())
        .map(|(n, label)| {
            let text = cx.text(label, None, "profinet.subslot_labels.ports");
            TextRef::new(format!("{}{n}", ids::PORT_LABEL_TEXT), text)
        })
        .collect();
    one_per_port(cx, &given.ports, most_ports, ("label", "labels"))?;
    Some(Some(SubslotLabels {
        interface: TextRef::new(ids::INTERFACE_LABEL_TEXT, interface),
        ports,
    }))
}

/// `port_names`: each port's name in every access point, in place of gsdc's
/// (E191 unless one per port of the access point with the most).
fn name_ports(
    cx: &mut Checker,
    given: Option<&Spanned<Vec<Spanned<raw::Text>>>>,
    daps: &mut [Dap],
    most_ports: usize,
) -> Option<()> {
    let Some(given) = given else { return Some(()) };
    let names: Vec<Text> = given
        .get_ref()
        .iter()
        .map(|name| cx.text(name, None, "profinet.port_names"))
        .collect();
    one_per_port(cx, given, most_ports, ("name", "names"))?;
    for port in daps.iter_mut().flat_map(|d| d.ports.iter_mut()) {
        let number = usize::from(port.subslot - FIRST_PORT_SUBSLOT);
        port.text.text = names[number].clone();
    }
    Some(())
}

/// One of `given` per port of the access point with the most, in port
/// order (E191 otherwise); `one` and `many` name what is given.
fn one_per_port<T>(
    cx: &mut Checker,
    given: &Spanned<Vec<T>>,
    most_ports: usize,
    (one, many): (&str, &str),
) -> Option<()> {
    let count = given.get_ref().len();
    if count == most_ports {
        return Some(());
    }
    cx.push(
        Diagnostic::error("E191", format!("port {many}: {count} given, {most_ports} needed"))
            .at(given.span())
            .label(format!("one {one} per port"))
            .help(format!("give each port of the device access point with the most ports its {one}, in port order; an access point with fewer has the first ones")),
    );
    None
}

/// `module_releases`: the modules repeat the first device access point's
/// releases, so it must have one (E192).
fn module_releases(cx: &mut Checker, given: Option<&Spanned<bool>>, first: &Dap) -> Option<bool> {
    let Some(given) = given.filter(|g| *g.get_ref()) else {
        return Some(false);
    };
    if first.hardware_release.is_none() && first.software_release.is_none() {
        cx.push(
            Diagnostic::error("E192", "the modules have no release to repeat")
                .at(given.span())
                .label("the first device access point has no release")
                .help("give [device] hardware_release or software_release, the card's, or leave module_releases out"),
        );
        return None;
    }
    Some(true)
}

/// Port `number`; an MRP client starts with ports 1 and 2 as its ring, as
/// every two-port device with MRP in the corpus declares.
fn port(number: u8, media_redundancy: bool) -> Port {
    Port {
        id: format!("IDS_PORT_{number}"),
        subslot: FIRST_PORT_SUBSLOT + u16::from(number) - 1,
        ident: u32::from(FIRST_PORT_SUBSLOT + u16::from(number) - 1),
        text: TextRef::new(
            format!("IDT_PORT_{number}"),
            Text::gsdc(|lang| crate::i18n::files::port(lang, number)),
        ),
        default_ringport: media_redundancy && number <= 2,
    }
}

/// Standard telegram 1's name: the profile's when the card implements
/// PROFIdrive, else the description's own (E153 when it gives none: the
/// profile's name would say the card implements it).
fn standard_telegram_1_name(
    cx: &mut Checker,
    (p, near): (&raw::Profinet, std::ops::Range<usize>),
    desc: &raw::Description,
    telegram: &Telegram,
    kinds: &[(ModuleKind, Layout)],
) -> Option<Text> {
    let given = p.module_name.standard_telegram_1.as_ref();
    let offered = kinds
        .iter()
        .any(|(k, _)| *k == ModuleKind::StandardTelegram1);
    let stated = desc.telegram.as_ref().and_then(|t| t.profidrive.as_ref());
    let offer = p
        .standard_telegram_1
        .as_ref()
        .map_or(near.clone(), Spanned::span);
    if offered && stated.is_none() {
        cx.push(
            Diagnostic::error("E153", "standard telegram 1 without saying whether the card implements PROFIdrive")
                .at(offer)
                .label("PROFIdrive's or the manual's?")
                .help("set [telegram] profidrive = true when the drive follows the PROFIdrive profile (STW1 bit 0 is ON/OFF1), or = false with [profinet.module_name] standard_telegram_1 naming the manual's telegram"),
        );
        return None;
    }
    match given {
        Some(name) => Some(cx.text(name, None, "module_name.standard_telegram_1")),
        None if telegram.profidrive || !offered => Some(io::profidrive_telegram_1_name()),
        None => {
            let at = stated.map_or(near, Spanned::span);
            cx.push(
                Diagnostic::error("E153", "standard telegram 1 of a card without PROFIdrive needs the manual's name")
                    .at(at)
                    .label("not PROFIdrive")
                    .help("name it as the manual does: [profinet.module_name] standard_telegram_1 = { en = \"standard message 1\", zh = \"标准报文 1\" }; PROFIdrive's name would say the card implements the profile"),
            );
            None
        }
    }
}

/// The version as the description writes it: `2.32`, without the `V`.
fn version(cx: &mut Checker, v: Option<&Spanned<String>>) -> Option<Version> {
    let Some(v) = v else {
        return Some(DEFAULT_VERSION);
    };
    let text = v.get_ref();
    let version = (!text.starts_with(['V', 'v']))
        .then(|| Version::parse(text))
        .flatten()
        .filter(|version| SUPPORTED_VERSIONS.contains(version));
    if version.is_none() {
        let supported: Vec<String> = SUPPORTED_VERSIONS.iter().map(|v| v.number()).collect();
        cx.push(
            Diagnostic::error("E130", format!("gsdc does not write GSDML {text}"))
                .at(v.span())
                .label("unsupported version")
                .help(format!("write one of: {}", supported.join(", "))),
        );
    }
    version
}

/// E198 at `span` when the file's GSDML version is older than the one a
/// file at hand first shows `introduced` in: gsdc writes nothing a version
/// lacks, and no source at hand says that an older one has it.
pub(crate) fn written_in(
    cx: &mut Checker,
    span: Range<usize>,
    file: Version,
    introduced: Introduced,
) {
    if file >= introduced.version {
        return;
    }
    let since = introduced.version.number();
    cx.push(
        Diagnostic::error(
            "E198",
            format!(
                "{} is not written in a GSDML {file} file: gsdc writes it in {since} and later",
                introduced.name
            ),
        )
        .at(span)
        .label(format!("needs gsdml_version = \"{since}\" or later"))
        .help(format!(
            "set `gsdml_version = \"{since}\"` (or later) in [profinet], or leave this out: the first file at hand that has it is {}, and no source at hand shows it in an older version",
            introduced.shown_by
        )),
    );
}

/// `RequiredSchemaVersion`: the oldest GSDML version an engineering tool
/// must know to offer the access point, which cannot be later than the
/// file that describes it (E190). `Some(None)` when the description states
/// none.
fn required_schema_version(
    cx: &mut Checker,
    given: Option<&Spanned<String>>,
    file: Version,
) -> Option<Option<Version>> {
    let Some(given) = given else {
        return Some(None);
    };
    let refusal = |text: &str| {
        Diagnostic::error(
            "E190",
            format!("no device access point of a GSDML {file} file can require GSDML {text}"),
        )
        .help(format!(
            "write the oldest version whose elements the access point needs, from \"1.0\" to \"{}\" (the file's, `gsdml_version`), without the V",
            file.number()
        ))
    };
    up_to_file(cx, given, file, refusal).map(Some)
}

/// `PNIO_Version`: the PROFINET specification version the device is
/// certified against (p-net's `creating_gsdml_files.rst`), the file's own
/// unless stated. A file of one version cannot describe what a later one
/// added, and every access point of the corpus's files declares at most its
/// file's version (E197).
fn pnio_version(
    cx: &mut Checker,
    given: Option<&Spanned<String>>,
    file: Version,
) -> Option<Version> {
    let Some(given) = given else {
        return Some(file);
    };
    let refusal = |text: &str| {
        Diagnostic::error(
            "E197",
            format!("no device access point of a GSDML {file} file can declare PNIO_Version {text}"),
        )
        .help(format!(
            "write the PROFINET version the card is certified against, as the manual states it, from \"1.0\" to \"{}\" (the file's, `gsdml_version`), without the V; or raise `gsdml_version`",
            file.number()
        ))
    };
    up_to_file(cx, given, file, refusal)
}

/// A version the description states for its access points, from the
/// first, V1.0, to the file's own; `refusal`'s error at it otherwise.
fn up_to_file(
    cx: &mut Checker,
    given: &Spanned<String>,
    file: Version,
    refusal: impl Fn(&str) -> Diagnostic,
) -> Option<Version> {
    let text = given.get_ref();
    let first = Version::new(1, 0);
    let version = (!text.starts_with(['V', 'v']))
        .then(|| Version::parse(text))
        .flatten()
        .filter(|v| (first..=file).contains(v));
    if version.is_none() {
        cx.push(
            refusal(text)
                .at(given.span())
                .label("not a version from 1.0 to the file's"),
        );
    }
    version
}

/// The GSDML file name's date: a TOML local date, or a local date-time in
/// whole seconds for a second release on one day (PI's naming allows
/// `-yyyymmdd-hhmmss`; TIA Portal does not refresh an installed file name,
/// FIELDBUS-NOTES.md). A time with an offset is refused: the name has no
/// zone, and converting it would write a time the description does not.
fn date(cx: &mut Checker, d: &Spanned<toml::value::Datetime>) -> Option<Date> {
    let value = d.get_ref();
    let problem = match (value.date, value.time, value.offset) {
        (Some(date), time, None) => match time.map(time_of_day).transpose() {
            Ok(time) => {
                return Some(Date {
                    year: date.year,
                    month: date.month,
                    day: date.day,
                    time,
                })
            }
            Err(problem) => problem,
        },
        (Some(_), _, Some(_)) => "the GSDML date has a time zone, which a file name cannot show",
        (None, ..) => "the GSDML date is a time of day without a date",
    };
    cx.push(
        Diagnostic::error("E131", problem)
            .at(d.span())
            .label("not a local date or date-time")
            .help("write a TOML date, date = 2023-08-30, or a local date-time in whole seconds for a second release on one day, date = 2023-08-30T07:14:47 (the file name ends -20230830-071447)"),
    );
    None
}

/// A TOML time as a file name's `hhmmss`: whole seconds, no leap second.
/// TOML 1.1 may leave the seconds out: they are 00.
fn time_of_day(time: toml::value::Time) -> Result<TimeOfDay, &'static str> {
    let second = time.second.unwrap_or(0);
    if time.nanosecond.is_some_and(|n| n != 0) {
        return Err("the GSDML date has fractions of a second, which a file name cannot show");
    }
    if second > 59 {
        return Err("the GSDML date has second 60, which a file name cannot show");
    }
    Ok(TimeOfDay {
        hour: time.hour,
        minute: time.minute,
        second,
    })
}

/// Vendor and family as they go into the file name. The GSDML
/// specification (5.1) lets them hold any character a Windows file name
/// may, the space and `-` included (SEW's `MOVI-C-Decentralized-Electronics`);
/// gsdc keeps to printable ASCII, and neither part may start or end with a
/// space or `-`, so the name's parts stay readable and `gsdc check` splits
/// them as written.
fn file_name_part(cx: &mut Checker, part: &Spanned<String>, what: &str) -> String {
    let text = part.get_ref();
    let edge = |c: char| c == ' ' || c == '-';
    let valid = !text.is_empty()
        && !text.starts_with(edge)
        && !text.ends_with(edge)
        && text.chars().all(|c| {
            (c.is_ascii_graphic() || c == ' ')
                && !crate::gsdml::version::WINDOWS_FORBIDDEN.contains(&c)
        });
    if !valid {
        cx.push(
            Diagnostic::error("E133", format!("`{text}` cannot be part of a GSDML file name"))
                .at(part.span())
                .label("not a part of a file name")
                .help(format!("GSDML-V<version>-<Vendor>-<Family>-<date>.xml takes printable ASCII but < > : \" / \\ | ? *, not starting or ending with a space or `-`; set {what}")),
        );
    }
    text.to_string()
}

fn placeholder_warning(
    cx: &mut Checker,
    id: &Spanned<raw::IdentNumber>,
    (what, key): (&str, &str),
) {
    if id.get_ref().placeholder {
        let value = format!("0x{:04X}", id.get_ref().value.get_ref());
        cx.placeholder(
            Diagnostic::warning("W102", format!("PROFINET {what} {value} is a placeholder, not assigned by PI"))
                .at(id.span())
                .label("placeholder")
                .help("use the vendor ID PI assigned and the device ID the vendor assigned before shipping"),
            (&format!("profinet.{key}"), value),
            crate::i18n::files::NOT_ASSIGNED_BY_PI,
        );
    }
}

/// DNS_CompatibleName: lower-case labels of letters, digits and `-`, each
/// 1..63 long and not starting or ending with `-`, 240 characters in all.
fn dns_name(cx: &mut Checker, name: &Spanned<String>) -> String {
    let text = name.get_ref();
    let label_ok = |l: &str| {
        (1..=63).contains(&l.len())
            && !l.starts_with('-')
            && !l.ends_with('-')
            && l.chars()
                .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-')
    };
    if text.len() > 240 || !text.split('.').all(label_ok) {
        cx.push(
            Diagnostic::error(
                "E132",
                format!("`{text}` is not a DNS-compatible name of station"),
            )
            .at(name.span())
            .label("not a DNS name")
            .help("use lower-case letters, digits and `-`, e.g. \"mv810-pnet02\""),
        );
    }
    text.clone()
}

/// The selectable modules: standard telegrams 1 and 2 first when offered,
/// then the PZD lengths with the PKW channel, then without.
fn modules(cx: &mut Checker, p: &raw::Profinet, telegram: &Telegram) -> Vec<(ModuleKind, Layout)> {
    let pkw_choices: &[bool] = match p.module_pkw.get_ref() {
        ModulePkw::With => &[true],
        ModulePkw::Without => &[false],
        ModulePkw::Both => &[true, false],
    };
    if pkw_choices.contains(&true) && telegram.pkw == PkwKind::None {
        cx.push(
            Diagnostic::error(
                "E121",
                "modules with a PKW channel, but the telegram has none",
            )
            .at(p.module_pkw.span())
            .label("asks for PKW")
            .help("set telegram.pkw to the channel's kind, or module_pkw = \"without\""),
        );
    }
    let lengths = pzd_lengths(cx, &p.pzd_lengths, telegram.pzd_words);
    let mut modules = Vec::new();
    if p.standard_telegram_1.as_ref().is_some_and(|s| *s.get_ref()) {
        check_standard_telegram_1(cx, p, telegram);
        modules.push((
            ModuleKind::StandardTelegram1,
            Layout::new(false, io::STANDARD_TELEGRAM_1_WORDS),
        ));
    }
    if let Some(offer) = p.standard_telegram_2.as_ref().filter(|s| *s.get_ref()) {
        check_standard_telegram_2(cx, offer.span(), telegram);
        modules.push((
            ModuleKind::StandardTelegram2,
            Layout::new(false, io::STANDARD_TELEGRAM_2_WORDS),
        ));
    }
    for &pkw in pkw_choices {
        for &pzd_words in &lengths {
            modules.push((ModuleKind::Pzd, Layout::new(pkw, pzd_words)));
        }
    }
    modules
}

fn check_standard_telegram_1(cx: &mut Checker, p: &raw::Profinet, telegram: &Telegram) {
    if telegram.pzd_words < io::STANDARD_TELEGRAM_1_WORDS {
        cx.push(
            Diagnostic::error(
                "E113",
                "standard telegram 1 needs 2 PZD words; the telegram has 1",
            )
            .at(p.pzd_lengths.span())
            .label("for this device")
            .help("raise telegram.pzd_words to 2 or drop standard_telegram_1"),
        );
    }
}

/// Standard telegram 2 is PROFIdrive's only (E161), and needs four PZD
/// words of the telegram (E113).
fn check_standard_telegram_2(cx: &mut Checker, offer: std::ops::Range<usize>, telegram: &Telegram) {
    if !telegram.profidrive {
        cx.push(
            Diagnostic::error("E161", "standard telegram 2 of a card without PROFIdrive")
                .at(offer.clone())
                .label("PROFIdrive's telegram")
                .help("standard telegram 2 (STW1, NSOLL_B, STW2 / ZSW1, NIST_B, ZSW2) is the profile's: set [telegram] profidrive = true when the drive follows it, or offer the manual's telegram as PZD words"),
        );
    }
    if telegram.pzd_words < io::STANDARD_TELEGRAM_2_WORDS {
        cx.push(
            Diagnostic::error(
                "E113",
                format!(
                    "standard telegram 2 needs {} PZD words; the telegram has {}",
                    io::STANDARD_TELEGRAM_2_WORDS,
                    telegram.pzd_words
                ),
            )
            .at(offer)
            .label("for this device")
            .help("raise telegram.pzd_words to 4 or drop standard_telegram_2"),
        );
    }
}

/// Selectable PZD word counts, each within the telegram and given once, in
/// the order given.
fn pzd_lengths(cx: &mut Checker, lengths: &Spanned<Vec<Spanned<u8>>>, max: u8) -> Vec<u8> {
    if lengths.get_ref().is_empty() {
        cx.push(
            Diagnostic::error("E101", "pzd_lengths is empty")
                .at(lengths.span())
                .label("no module")
                .help("list the PZD word counts a user may select, e.g. [2, 6, 12]"),
        );
    }
    let mut seen = BTreeSet::new();
    lengths
        .get_ref()
        .iter()
        .filter_map(|n| {
            let words: u8 = cx.spanned_in_range(n, 1, i64::from(max), "a PZD length")?;
            if !seen.insert(words) {
                cx.duplicate(format!("PZD length {words}"), n.span());
                return None;
            }
            Some(words)
        })
        .collect()
}
