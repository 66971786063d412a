//! Who the card is and what ships with it; the bus parameters; and, last,
//! what must be checked before the files ship.

use super::page::{code, text, Builder, Cell, Run};
use super::{decision_kind, with_placeholder, Lang};
use crate::i18n::{sheet as w, Phrase};
use crate::ir::profibus::Profibus;
use crate::ir::profinet::{Dap, Irt, Isochronous, ProfiEnergy, Profinet, Slots};
use crate::ir::{Decision, Ir, MappingKind, PkwKind};

pub(crate) fn section(doc: &mut Builder, ir: &Ir, lang: Lang) {
    let mut intro = text(lang.text(&ir.device.name));
    if let Some(info) = &ir.device.info {
        intro.push(Run::Text(format!(
            "{}{}",
            lang.t(w::COLON),
            lang.text(info)
        )));
    }
    doc.para(intro);
    doc.para(vec![
        Run::Text(lang.t(w::GENERATED_BY).into()),
        Run::Code(crate::GENERATOR.into()),
        Run::Text(lang.t(w::FROM_THE_DESCRIPTION).into()),
        Run::Code(ir.source_name.clone()),
        Run::Text(lang.t(w::OPEN_FINGERPRINT).into()),
        Run::Code(ir.fingerprint.to_string()),
        Run::Text(lang.t(w::CHANGE_THE_DESCRIPTION).into()),
    ]);
    doc.section("identity", lang.t(w::IDENTITY_AND_FILES));
    device_table(doc, ir, lang);
    files_table(doc, ir, lang);
    if let Some(p) = &ir.profibus {
        profibus_table(doc, p, lang);
    }
    if let Some(p) = &ir.profinet {
        profinet_table(doc, p, lang);
    }
}

fn device_table(doc: &mut Builder, ir: &Ir, lang: Lang) {
    let d = &ir.device;
    let mut rows = vec![
        (lang.t(w::VENDOR), text(&d.vendor)),
        (lang.t(w::FAMILY), text(&d.family)),
        (lang.t(w::MODEL), text(&d.model)),
        (lang.t(w::NAME), text(lang.text(&d.name))),
    ];
    let optional = [
        (w::REVISION, &d.revision),
        (w::HARDWARE_RELEASE, &d.hardware_release),
        (w::SOFTWARE_RELEASE, &d.software_release),
        (w::ORDER_NUMBER, &d.order_number),
    ];
    rows.extend(
        optional
            .into_iter()
            .filter_map(|(word, value)| Some((lang.t(word), code(value.as_deref()?)))),
    );
    doc.table(
        lang.t(w::THE_DEVICE),
        &[lang.t(w::ITEM), lang.t(w::VALUE)],
        rows.into_iter().map(|(k, v)| vec![text(k), v]).collect(),
    );
}

fn files_table(doc: &mut Builder, ir: &Ir, lang: Lang) {
    let mut rows = Vec::new();
    if let Some(p) = &ir.profibus {
        let mut id = text("Ident_Number ");
        id.extend(with_placeholder(
            lang,
            format!("0x{:04X}", p.ident_number),
            p.ident_placeholder,
        ));
        rows.push(vec![code(&p.file_name), text(lang.t(w::GSD_FILE)), id]);
    }
    if let Some(p) = &ir.profinet {
        let mut id = text("VendorID ");
        id.extend(with_placeholder(
            lang,
            format!("0x{:04X}", p.vendor_id),
            p.vendor_id_placeholder,
        ));
        id.push(Run::Text(", DeviceID ".into()));
        id.extend(with_placeholder(
            lang,
            format!("0x{:04X}", p.device_id),
            p.device_id_placeholder,
        ));
        rows.push(vec![code(&p.file_name), text(lang.t(w::GSDML_FILE)), id]);
    }
    let bitmaps = ir
        .profibus
        .iter()
        .filter_map(|p| p.bitmap_device.as_ref())
        .chain(
            ir.profinet
                .iter()
                .filter_map(|p| p.device_symbol.as_ref().map(|s| &s.file)),
        );
    for bitmap in bitmaps {
        rows.push(vec![
            code(format!("{bitmap}.bmp")),
            text(lang.t(w::DEVICE_SYMBOL)),
            text(lang.t(w::SYMBOL_SIZE)),
        ]);
    }
    let layouts = [
        (
            crate::emit::rust::file_name(ir),
            crate::emit::rust::SUPPORT_FILE_NAME,
            lang.t(w::RUST_LAYOUT),
        ),
        (
            crate::emit::c::file_name(ir),
            crate::emit::c::SUPPORT_FILE_NAME,
            lang.t(w::C_LAYOUT),
        ),
    ];
    for (layout, support, what) in layouts {
        let mut file = code(layout);
        file.push(Run::Text(lang.t(w::WITH).into()));
        file.push(Run::Code(support.into()));
        rows.push(vec![
            file,
            text(what),
            vec![
                Run::Text(lang.t(w::FINGERPRINT).into()),
                Run::Code(ir.fingerprint.to_string()),
            ],
        ]);
    }
    doc.table(
        lang.t(w::GENERATED_FILES),
        &[
            lang.t(w::FILE),
            lang.t(w::WHAT_IT_IS),
            lang.t(w::IDENTIFICATION),
        ],
        rows,
    );
}

fn yes_no(lang: Lang, value: bool) -> Cell {
    text(if value { lang.t(w::YES) } else { lang.t(w::NO) })
}

fn profibus_table(doc: &mut Builder, p: &Profibus, lang: Lang) {
    let rates: Vec<&str> = p.baud_rates.iter().map(|(b, _)| b.as_str()).collect();
    let mut rows = vec![
        (lang.t(w::GSD_REVISION), code(p.gsd_revision.to_string())),
        (lang.t(w::BAUD_RATES), text(rates.join(", "))),
        (lang.t(w::AUTO_BAUD), yes_no(lang, p.auto_baud)),
        (
            lang.t(w::MIN_SLAVE_INTERVAL),
            text(format!("{} × 100 µs", p.min_slave_interval)),
        ),
        (lang.t(w::FREEZE_MODE), yes_no(lang, p.freeze_mode)),
        (lang.t(w::SYNC_MODE), yes_no(lang, p.sync_mode)),
        (lang.t(w::FAIL_SAFE), yes_no(lang, p.fail_safe)),
    ];
    if let Some(required) = p.features.fail_safe_required {
        rows.push((lang.t(w::FAIL_SAFE_REQUIRED), yes_no(lang, required)));
    }
    rows.push((
        lang.t(w::MAX_IO_BYTES),
        text(format!("{}, {}", p.max_input_len, p.max_output_len)),
    ));
    rows.push((
        lang.t(w::MAX_DIAG_DATA_LEN),
        text(p.max_diag_data_len.to_string()),
    ));
    if let Some(d) = &p.dpv1 {
        rows.push((lang.t(w::DPV1_C1_READ_WRITE), yes_no(lang, d.c1_read_write)));
        rows.push((
            lang.t(w::DPV1_C1_LIMITS),
            text(format!(
                "{}, {} × 10 ms",
                d.c1_max_data_len, d.c1_response_timeout
            )),
        ));
    }
    doc.table(
        lang.t(w::PROFIBUS_BUS_PARAMETERS),
        &[lang.t(w::PARAMETER), lang.t(w::VALUE)],
        rows.into_iter().map(|(k, v)| vec![text(k), v]).collect(),
    );
}

/// The file's GSDML version, the PROFINET version its access points are
/// certified against where it is another, and the oldest an engineering
/// tool must know to offer them, where the description states one.
fn gsdml_version(p: &Profinet, lang: Lang) -> Cell {
    let mut cell = code(p.gsdml_version.to_string());
    if p.pnio_version != p.gsdml_version {
        cell.extend([
            Run::Text("; PNIO_Version ".into()),
            Run::Code(p.pnio_version.to_string()),
        ]);
    }
    if let Some(required) = p.required_schema_version {
        let needs = format!("; {} ", lang.t(w::REQUIRED_SCHEMA_VERSION));
        cell.extend([Run::Text(needs), Run::Code(required.to_string())]);
    }
    cell
}

/// How many ports an access point has, with their labels on the device
/// where the description gives them: `2 (X1 P1, X1 P2)`.
fn ports(p: &Profinet, dap: &Dap, lang: Lang) -> Cell {
    let count = dap.ports.len();
    match &p.subslot_labels {
        None => text(count.to_string()),
        Some(labels) => {
            let own = labels.ports.iter().take(count);
            let names: Vec<&str> = own.map(|label| lang.text(&label.text)).collect();
            text(format!("{count} ({})", names.join(", ")))
        }
    }
}

/// The device's PROFINET parameters; with one device access point its
/// ports and IO data too, else a table of the access points has them.
fn profinet_table(doc: &mut Builder, p: &Profinet, lang: Lang) {
    // MinDeviceInterval counts 31.25 us = 125/4 us: a binary fraction, so
    // the product is exact in an f64 and prints as 312.5, not truncated.
    let micros = f64::from(p.min_device_interval) * 31.25;
    let mut rows = vec![
        (lang.t(w::GSDML_VERSION), gsdml_version(p, lang)),
        (lang.t(w::NAME_OF_STATION), code(&p.dns_name)),
        (
            lang.t(w::MIN_DEVICE_INTERVAL),
            text(format!(
                "{} × 31.25 µs = {} µs",
                p.min_device_interval, micros
            )),
        ),
    ];
    if let [dap] = p.daps.as_slice() {
        rows.insert(2, (lang.t(w::PORTS), ports(p, dap, lang)));
        rows.push((lang.t(w::MAX_IO_DATA), max_io_data(dap, lang)));
    }
    if let Some(basis) = &p.implementation_type {
        rows.insert(1, (lang.t(w::IMPLEMENTATION_TYPE), text(basis)));
    }
    let properties = &p.interface_properties;
    if let Some(irt) = &properties.irt {
        rows.push((lang.t(w::IRT), text(irt_summary(irt))));
    }
    if let Some(iso) = &properties.isochronous {
        rows.push((
            lang.t(w::ISOCHRONOUS_MODE),
            text(isochronous_summary(iso, lang)),
        ));
    }
    if p.module_slots != Slots::ONE || p.empty_module.is_some() {
        rows.push((lang.t(w::MODULE_SLOTS), text(slots_summary(p, lang))));
    }
    if !p.safety_modules.is_empty() {
        rows.push((lang.t(w::SAFETY_MODULES), text(safety_summary(p, lang))));
    }
    if let Some(energy) = &p.profienergy {
        rows.push(("PROFIenergy", text(profienergy_summary(energy))));
    }
    doc.table(
        lang.t(w::PROFINET_DEVICE),
        &[lang.t(w::PARAMETER), lang.t(w::VALUE)],
        rows.into_iter().map(|(k, v)| vec![text(k), v]).collect(),
    );
    if p.daps.len() > 1 {
        daps_table(doc, p, lang);
    }
}

/// RT_CLASS_3's timing as the GSDML names it: what the engineering tool
/// plans the IRT schedule with.
fn irt_summary(irt: &Irt) -> String {
    let numbers = |values: &[u16]| {
        let written: Vec<String> = values.iter().map(u16::to_string).collect();
        written.join(" ")
    };
    format!(
        "SendClock {} × 31.25 µs, ReductionRatio {}, MaxBridgeDelay {} ns, MaxPortTxDelay {} ns, MaxPortRxDelay {} ns",
        numbers(&irt.send_clock),
        numbers(&irt.reduction_ratio),
        irt.max_bridge_delay,
        irt.port_tx_delay,
        irt.port_rx_delay
    )
}

/// The data cycles the modules follow and their least input and output
/// times, in µs and in the GSDML's units.
fn isochronous_summary(iso: &Isochronous, lang: Lang) -> String {
    // T_DC_Base counts 31.25 us, a binary fraction: exact in an f64.
    let cycle = |n: u16| f64::from(n) * f64::from(iso.t_dc_base) * 31.25;
    let io_time = |n: u32| u64::from(n) * u64::from(iso.t_io_base);
    let micros = |ns: u64| ns as f64 / 1000.0;
    let summary = format!(
        "T_DC {}–{} µs (T_DC_Base {} × 31.25 µs, T_DC_Min {}, T_DC_Max {}); T_IO_InputMin {} µs, T_IO_OutputMin {} µs (T_IO_Base {} ns)",
        cycle(iso.t_dc_min),
        cycle(iso.t_dc_max),
        iso.t_dc_base,
        iso.t_dc_min,
        iso.t_dc_max,
        micros(io_time(iso.t_io_input_min)),
        micros(io_time(iso.t_io_output_min)),
        iso.t_io_base
    );
    match iso.required {
        true => format!("{summary}; {}", lang.t(w::ISOCHRONOUS_REQUIRED)),
        false => summary,
    }
}

/// The data modules' slots and the empty module's, as AllowedInSlots
/// lists them: `2..5; Empty (0x00007531): 1..5`.
fn slots_summary(p: &Profinet, lang: Lang) -> String {
    let data = p.module_slots.to_string();
    match &p.empty_module {
        None => data,
        Some(e) => format!(
            "{data}; {} (0x{:08X}): {}",
            lang.text(&e.name.text),
            e.ident,
            e.slots
        ),
    }
}

/// Each safety module with its ident number, slots and bytes each way:
/// `F-Modul (0x00002716): 1; 8/7`.
fn safety_summary(p: &Profinet, lang: Lang) -> String {
    let modules: Vec<String> = p
        .safety_modules
        .iter()
        .map(|m| {
            format!(
                "{} (0x{:08X}): {}; {}/{}",
                lang.text(&m.name.text),
                m.ident_number,
                m.slots,
                m.input_bytes(),
                m.output_bytes()
            )
        })
        .collect();
    modules.join(", ")
}

/// The PROFIenergy profile and each energy saving mode as the GSDML names
/// them: what the controller's energy management plans pauses with.
fn profienergy_summary(energy: &ProfiEnergy) -> String {
    let mut profile = vec![format!("ProfileVersion {}", energy.profile_version)];
    profile.extend(energy.entity_class.map(|c| format!("EntityClass Class{c}")));
    profile.extend(
        energy
            .entity_subclass
            .map(|c| format!("EntitySubclass Subclass{c}")),
    );
    let flags = [
        ("PROFIenergyASE_Supported", energy.ase),
        ("PESAP_uses_PROFIenergyASE", energy.pesap_uses_ase),
    ];
    profile.extend(
        flags
            .iter()
            .filter(|(_, on)| *on)
            .map(|(name, _)| name.to_string()),
    );
    let modes = energy.modes.iter().map(|m| {
        format!(
            "ID {}: TimeToPause {} ms, RTTO {} ms, TimeMinLengthOfStay {} ms",
            m.id, m.time_to_pause, m.regular_time_to_operate, m.min_length_of_stay
        )
    });
    std::iter::once(profile.join(", "))
        .chain(modes)
        .collect::<Vec<_>>()
        .join("; ")
}

fn max_io_data(dap: &Dap, lang: Lang) -> Vec<Run> {
    let each_way = format!("{}, {}", dap.max_input_length, dap.max_output_length);
    text(match dap.max_data_length {
        Some(together) => format!("{each_way}; {} {together}", lang.t(w::IO_DATA_TOGETHER)),
        None => each_way,
    })
}

/// One row per device access point: what tells the versions of the card
/// apart.
fn daps_table(doc: &mut Builder, p: &Profinet, lang: Lang) {
    let rows = p
        .daps
        .iter()
        .map(|dap| {
            let every = dap.modules.len() == p.modules.len()
                && dap.safety_modules.len() == p.safety_modules.len();
            let modules = if every {
                lang.t(w::ALL_MODULES).to_string()
            } else {
                let safety = dap
                    .safety_modules
                    .iter()
                    .map(|&i| &p.safety_modules[i].name);
                let names: Vec<&str> = dap
                    .modules
                    .iter()
                    .map(|&i| &p.modules[i].name)
                    .chain(safety)
                    .map(|name| lang.text(&name.text))
                    .collect();
                names.join(", ")
            };
            vec![
                text(lang.text(&dap.name.text)),
                code(format!("0x{:08X}", dap.ident)),
                dap.order_number.as_deref().map_or_else(Vec::new, code),
                dap.hardware_release.as_deref().map_or_else(Vec::new, code),
                dap.software_release.as_deref().map_or_else(Vec::new, code),
                ports(p, dap, lang),
                max_io_data(dap, lang),
                text(modules),
            ]
        })
        .collect();
    doc.table(
        lang.t(w::DEVICE_ACCESS_POINTS),
        &[
            lang.t(w::NAME),
            "ModuleIdentNumber",
            lang.t(w::ORDER_NUMBER),
            lang.t(w::HARDWARE_RELEASE),
            lang.t(w::SOFTWARE_RELEASE),
            lang.t(w::PORTS),
            lang.t(w::MAX_IO_DATA),
            lang.t(w::MODULES),
        ],
        rows,
    );
}

/// The placeholders, and the choices gsdc made where the manuals say
/// nothing, as far as this description uses them: the places a firmware
/// team checks against its card.
pub(crate) fn checklist_section(doc: &mut Builder, ir: &Ir, lang: Lang) {
    doc.section_with_intro("check", lang.t(w::TO_CHECK), lang.t(w::CHECKLIST_INTRO));
    let mut rows: Vec<Vec<Cell>> = Vec::new();
    let mut row = |what: &str, why: &str| rows.push(vec![text(what), vec![Run::Mark(why.into())]]);
    for decision in &ir.decisions {
        let kind = decision_kind(lang, decision.kind);
        let (path, value, reason) = decision_in(lang, decision);
        row(
            &format!("{path} = {value}"),
            &format!("{kind}{}{reason}", lang.t(w::COLON)),
        );
    }
    // The config bytes (the PPO types' and a gateway's modules'), Max_Module
    // and User_Prm_Data's layout are gsdc's layout decisions, listed above
    // with their values.
    row(lang.t(w::BYTE_ORDER), lang.t(w::BYTE_ORDER_RULE));
    if ir.profinet.is_some() {
        // The ident numbers are gsdc's unless the description states them
        // all (`[profinet.ident_numbers]`); the records' numbers are gsdc's.
        let numbered_by_gsdc = ir
            .decisions
            .iter()
            .any(|d| d.path.starts_with("profinet ident numbers"));
        let what = match numbered_by_gsdc {
            true => w::PROFINET_NUMBERS,
            false => w::PROFINET_RECORD_NUMBERS,
        };
        row(lang.t(what), lang.t(w::AS_TABLES_ABOVE));
    }
    if matches!(ir.telegram.pkw, PkwKind::PkeIndPwe | PkwKind::Profidrive) {
        row(lang.t(w::PKW_RESERVED_BITS), lang.t(w::WRITTEN_0));
    }
    if ir.mappings.group(MappingKind::Dpv1Index).is_some() {
        row(lang.t(w::DPV1_RECORD_DATA), lang.t(w::DPV1_RECORD_RULE));
    }
    doc.table(
        lang.t(w::CHECKLIST_CAPTION),
        &[lang.t(w::WHAT), lang.t(w::STATUS)],
        rows,
    );
}

/// A decision's path, value and reason in the page's language: gsdc's own
/// words from its catalogue, the description's as the description writes
/// them.
fn decision_in(lang: Lang, d: &Decision) -> (&str, &str, &str) {
    let Some(words) = d.words else {
        return (&d.path, &d.value, &d.reason);
    };
    let or = |phrase: Option<Phrase>, own| phrase.map_or(own, |p| lang.t(p));
    (
        or(words.path, &d.path),
        or(words.value, &d.value),
        lang.t(words.reason),
    )
}
