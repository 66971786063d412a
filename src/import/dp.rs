//! A GSD file's device ([`DpDevice`]) written as a description: identity,
//! timing, DP features, the modules by what their config identifiers carry
//! (a PPO type's by its name), the card's User_Prm_Data parameters and
//! constant bytes, DPV1 and diagnosis. Each keyword the description has no
//! place for is a warning at its line (W600); whether leaving it out makes
//! another device is the round trip's to judge (`super::round_trip`).

use super::gateway;

mod safety;
use super::toml_out::{hex, list, quote, Line, TomlOut};
use super::Notes;
use crate::device::dp::{DiagArea, DiagBit, DiagType, DpDevice, DpModule, Keyword};
use crate::device::{Allowed, Field, ParameterData, Value};
use crate::gsd::config::{identifiers, Direction, Identifier, Length};
use crate::gsd::Value as GsdValue;
use crate::ir::profibus::STANDARD_DIAG_BYTES;
use crate::spec::{DPV1_GSD_REVISION, DP_CHANNEL_DIAG_BYTES, IM_GSD_REVISION};

/// Keywords the description states, by their schema key.
const IMPORTED: &[&str] = &[
    "gsd_revision",
    "vendor_name",
    "model_name",
    "revision",
    "ident_number",
    "hardware_release",
    "software_release",
    "ordernumber",
    "info_text",
    "implementation_type",
    "<baud>_supp",
    "maxtsdr_<baud>",
    "auto_baud_supp",
    "freeze_mode_supp",
    "sync_mode_supp",
    "set_slave_add_supp",
    "fail_safe",
    "fail_safe_required",
    "channel_diag",
    "redundancy",
    "repeater_ctrl_sig",
    "24v_pins",
    "wd_base_1ms_supp",
    "publisher_supp",
    "min_slave_intervall",
    "modular_station",
    "modul_offset",
    "max_module",
    "max_input_len",
    "max_output_len",
    "max_data_len",
    "slave_family",
    "max_diag_data_len",
    "max_user_prm_data_len",
    "dpv1_slave",
    "c1_read_write_supp",
    "c1_max_data_len",
    "c1_response_timeout",
    "c2_read_write_supp",
    "c2_max_data_len",
    "c2_response_timeout",
    "c2_max_count_channels",
    "max_initiate_pdu_length",
    "ident_maintenance_supp",
    "dpv1_data_types",
    "check_cfg_mode",
    "c1_read_write_required",
    "c2_read_write_required",
    "diagnostic_alarm_supp",
    "process_alarm_supp",
    "pull_plug_alarm_supp",
    "status_alarm_supp",
    "update_alarm_supp",
    "manufacturer_specific_alarm_supp",
    "diagnostic_alarm_required",
    "process_alarm_required",
    "pull_plug_alarm_required",
    "status_alarm_required",
    "update_alarm_required",
    "manufacturer_specific_alarm_required",
    "alarm_type_mode_supp",
    "extra_alarm_sap_supp",
    "alarm_sequence_mode_count",
    "prm_block_structure_supp",
    "prm_block_structure_req",
    "isochron_mode_supp",
    "isochron_mode_required",
    "tbase_dp",
    "tdp_max",
    "tdp_min",
    "tbase_io",
    "ti_min",
    "to_min",
    "t_pll_w_max",
];

/// Keywords gsdc writes with one value only: the description need not say
/// them when the file has that value.
const FIXED: &[(&str, i64)] = &[("protocol_ident", 0), ("station_type", 0), ("fms_supp", 0)];

/// The description of `device`, read from `file`; `None` when the file is
/// not a drive's (no module is a telegram of PKW and PZD words).
/// `symbol` is the PNG's name the description gives as its device symbol
/// (`Bitmap_Device`, which `super::symbol` reads and judges).
pub(super) fn describe(
    device: &DpDevice,
    file: &str,
    symbol: Option<&str>,
    notes: &mut Notes,
) -> Option<TomlOut> {
    let card = match telegram(device) {
        TelegramShape {
            pkw,
            pzd_words: Some(pzd_words),
        } => Card::Drive { pkw, pzd_words },
        _ => match gateway::read(device, notes) {
            Ok(g) => Card::Gateway(Box::new(g)),
            Err(why) => {
                notes.refuse(&why.map_or_else(
                    || NEITHER.to_string(),
                    |why| format!("its modules are blocks of words one way each, as a gateway's, but {why}"),
                ));
                return None;
            }
        },
    };
    let vendor = vendor_keywords(device);
    for k in &device.keywords {
        let fixed = FIXED.iter().find(|(key, _)| *key == k.key);
        let said = IMPORTED.contains(&k.key.as_str())
            // Read by `super::symbol`, or left out there with its reason.
            || k.key == "bitmap_device"
            || fixed.is_some_and(|(_, v)| k.value.as_number() == Some(*v))
            || vendor.iter().any(|(v, _)| std::ptr::eq(*v, k));
        if !said {
            notes.unsaid(&k.name, &k.place, "the description has no key for it");
        }
    }
    for s in &device.slots {
        notes.unsaid(
            &format!("Slot({})", s.number),
            &s.place,
            "the description has no SlotDefinition",
        );
    }
    let mut out = TomlOut::default();
    out.comment(&format!(
        "Imported by gsdc import from {file}. Every value below is the file's,"
    ));
    out.comment("marked under [choices] (where one is not, its mark says why): confirm each against the manual, then remove its mark.");
    device_table(&mut out, device, symbol);
    if let Card::Drive { pkw, pzd_words } = card {
        out.table("telegram");
        out.string("pkw", if pkw { "pke-ind-pwe" } else { "none" });
        out.key("pzd_words", pzd_words);
    }
    profibus(&mut out, device, file, &card, notes);
    write_vendor_keywords(&mut out, &vendor);
    if let Card::Gateway(g) = &card {
        gateway::write(&mut out, g, file, notes);
    }
    manual(&mut out);
    out.table("choices");
    let reason = quote(&format!("imported from {file}"));
    let bus_part = match card {
        Card::Drive { .. } => "telegram",
        Card::Gateway(_) => "gateway",
    };
    for table in ["device", bus_part, "profibus"] {
        out.key(&quote(table), &reason);
    }
    if let Card::Gateway(_) = card {
        for (key, why) in gateway::choices(file) {
            out.key(&quote(&key), quote(&why));
        }
    }
    notes.chosen_marks(&mut out);
    Some(with_charset(out))
}

const NEITHER: &str = "no module of this GSD is a drive's telegram (PZD words each way, after a PKW channel or not), nor are its modules a gateway's blocks of words one way each: the description format describes drive option cards and gateways";

/// What the file's modules carry: a drive's telegram, or the nodes' words
/// of a gateway.
enum Card {
    Drive { pkw: bool, pzd_words: u8 },
    Gateway(Box<gateway::Gateway>),
}

/// The description, stating `charset = "latin-1"` in `[profibus]` when the
/// file's strings have characters beyond ASCII (the only ones it holds:
/// gsdc's comments are ASCII), so the build writes them as the file's bytes.
fn with_charset(out: TomlOut) -> TomlOut {
    let mut sections = out.sections();
    let is_ascii = sections
        .iter()
        .flat_map(|s| &s.lines)
        .all(|line| line.text.is_ascii());
    let profibus = sections.iter_mut().find(|s| s.header == "[profibus]");
    if let (false, Some(profibus)) = (is_ascii, profibus) {
        let charset = Line {
            key: Some("charset".to_string()),
            text: "charset = \"latin-1\"".to_string(),
        };
        profibus.lines.insert(0, charset);
    }
    TomlOut::from_sections(sections)
}

/// The PKW channel's presence and the most PZD words of the modules whose
/// data is a telegram.
struct TelegramShape {
    pkw: bool,
    pzd_words: Option<u8>,
}

fn telegram(device: &DpDevice) -> TelegramShape {
    let shapes: Vec<(bool, u8)> = device
        .modules
        .iter()
        .filter_map(|m| shape(&identifiers(&m.config).ok()?))
        .collect();
    TelegramShape {
        pkw: shapes.iter().any(|(pkw, _)| *pkw),
        pzd_words: shapes.iter().map(|(_, w)| *w).max(),
    }
}

/// A module's telegram: the PKW channel first or not, then words whose sum
/// is the same each way (1..=16).
fn shape(ids: &[Identifier]) -> Option<(bool, u8)> {
    let data: Vec<&Identifier> = ids.iter().filter(|i| !is_empty(i)).collect();
    let pkw = data.len() > 1 && data.first().is_some_and(|i| is_pkw(i));
    let (mut out, mut inp) = (0u32, 0u32);
    for id in &data[usize::from(pkw)..] {
        let Identifier::General { direction, data } = id else {
            return None;
        };
        if !data.words {
            return None;
        }
        let count = u32::from(data.count);
        match direction {
            Direction::Both => (out, inp) = (out + count, inp + count),
            Direction::Output => out += count,
            Direction::Input => inp += count,
        }
    }
    let words = u8::try_from(out)
        .ok()
        .filter(|&w| out == inp && (1..=16).contains(&w))?;
    Some((pkw, words))
}

/// An identifier of no data: an empty place (0x00), or a special-format
/// one of manufacturer bytes only (SINAMICS' `0x01,0xFE` after its PZD).
fn is_empty(id: &Identifier) -> bool {
    matches!(
        id,
        Identifier::Special {
            output: None,
            input: None,
            ..
        }
    )
}

/// `0xF3`: 4 consistent words each way, the PKW channel when data follows.
fn is_pkw(id: &Identifier) -> bool {
    matches!(id, Identifier::General { direction: Direction::Both, data } if *data == PKW)
}

const PKW: Length = Length {
    words: true,
    count: 4,
    consistent: true,
};

/// `key = n` for each keyword the file has, as a number.
fn numbers(out: &mut TomlOut, device: &DpDevice, keys: &[(&str, &str)]) {
    for (key, keyword) in keys {
        if let Some(n) = number_of(device, keyword) {
            out.key(key, n);
        }
    }
}

/// `key = true` or `false` for each keyword the file has, 0 or not.
fn flags(out: &mut TomlOut, device: &DpDevice, keys: &[(&str, &str)]) {
    for (key, keyword) in keys {
        if let Some(n) = number_of(device, keyword) {
            out.key(key, n != 0);
        }
    }
}

fn text_of<'a>(device: &'a DpDevice, keyword: &str) -> Option<&'a str> {
    device.keyword(keyword)?.value.as_str()
}

fn number_of(device: &DpDevice, keyword: &str) -> Option<i64> {
    device.keyword(keyword)?.value.as_number()
}

fn device_table(out: &mut TomlOut, device: &DpDevice, symbol: Option<&str>) {
    out.table("device");
    let model = text_of(device, "Model_Name").unwrap_or_default();
    for (key, keyword) in [
        ("vendor", "Vendor_Name"),
        ("family", "Model_Name"),
        ("model", "Model_Name"),
        ("revision", "Revision"),
        ("hardware_release", "Hardware_Release"),
        ("software_release", "Software_Release"),
    ] {
        if let Some(text) = text_of(device, keyword) {
            out.string(key, text);
        }
    }
    // A GSD names no family and no PROFINET name: the model stands for both.
    out.string("name", model);
    if let Some(order) = text_of(device, "OrderNumber") {
        out.string("order_number", order);
    }
    if let Some(info) = text_of(device, "Info_Text") {
        out.string("info", info);
    }
    if let Some(png) = symbol {
        out.string("symbol", png);
    }
}

fn profibus(out: &mut TomlOut, device: &DpDevice, file: &str, card: &Card, notes: &mut Notes) {
    let is_drive = matches!(card, Card::Drive { .. });
    out.table("profibus");
    out.string("file_name", &gsd_file_name(file, notes));
    // A file without GSD_Revision is of the specification's first edition,
    // which the description states as revision 0.
    match device.keyword("GSD_Revision") {
        None => out.key("gsd_revision", revision_written(device, 0, notes)),
        Some(k) => {
            if let Some(r) = k.value.as_number() {
                out.key("gsd_revision", revision_written(device, r, notes));
            }
        }
    }
    if let Some(ident) = device.ident_number() {
        out.key("ident_number", format!("{{ value = 0x{ident:04X} }}"));
    }
    if let Some(t) = text_of(device, "Implementation_Type") {
        out.string("implementation_type", t);
    }
    if let Some(n) = number_of(device, "Min_Slave_Intervall") {
        out.key("min_slave_interval", n);
    }
    if let Some(k) = device.keyword("Slave_Family") {
        out.string("slave_family", &family(k));
    }
    flags(
        out,
        device,
        &[
            ("auto_baud", "Auto_Baud_supp"),
            ("freeze_mode", "Freeze_Mode_supp"),
            ("sync_mode", "Sync_Mode_supp"),
            ("fail_safe", "Fail_Safe"),
            ("fail_safe_required", "Fail_Safe_required"),
            ("set_slave_address", "Set_Slave_Add_supp"),
            ("redundancy", "Redundancy"),
            ("wd_base_1ms", "WD_Base_1ms_supp"),
            ("publisher", "Publisher_supp"),
            ("modular_station", "Modular_Station"),
        ],
    );
    numbers(
        out,
        device,
        &[
            ("repeater_ctrl_sig", "Repeater_Ctrl_Sig"),
            ("pins_24v", "24V_Pins"),
            ("modul_offset", "Modul_Offset"),
            ("max_module", "Max_Module"),
        ],
    );
    // A gateway's lengths are its `[gateway]`'s.
    if is_drive {
        numbers(
            out,
            device,
            &[
                ("max_input_len", "Max_Input_Len"),
                ("max_output_len", "Max_Output_Len"),
            ],
        );
    }
    numbers(out, device, &[("max_data_len", "Max_Data_Len")]);
    if is_drive {
        if let Some(n) = DiagnosisPlan::of(device).max_diag_data_len {
            out.key("max_diag_data_len", n);
        }
    }
    // A gateway's modules, parameters and diagnosis are its `[gateway]`'s.
    if is_drive {
        if let Some(words) = ppo5_pzd_words(device) {
            out.key("ppo5_pzd_words", words);
        }
        modules(out, device, notes);
        user_prm(out, device, notes);
    }
    out.table("profibus.baud_rates");
    for (baud, max_tsdr) in device.baud_rates() {
        out.key(&quote(baud.as_str()), max_tsdr.unwrap_or(0));
    }
    dpv1(out, device);
    isochronous(out, device);
    if is_drive {
        diagnosis(out, device, notes);
    }
}

/// `[profibus.isochronous]` when the file has Isochron_Mode_supp = 1.
fn isochronous(out: &mut TomlOut, device: &DpDevice) {
    if number_of(device, "Isochron_Mode_supp") != Some(1) {
        return;
    }
    out.table("profibus.isochronous");
    flags(out, device, &[("required", "Isochron_Mode_required")]);
    numbers(
        out,
        device,
        &[
            ("tbase_dp", "TBASE_DP"),
            ("tdp_max", "TDP_MAX"),
            ("tdp_min", "TDP_MIN"),
            ("tbase_io", "TBASE_IO"),
            ("ti_min", "TI_MIN"),
            ("to_min", "TO_MIN"),
            ("t_pll_w_max", "T_PLL_W_MAX"),
        ],
    );
}

/// The file's name when it is one a GSD may have (8.3, a GSD extension),
/// else the last 8 letters, digits and `_` of its stem with `.GSD`.
fn gsd_file_name(file: &str, notes: &mut Notes) -> String {
    let (stem, ext) = file.rsplit_once('.').unwrap_or((file, "GSD"));
    let ext_ok =
        ["GSD", "GSE", "GSG", "GSF", "GSI", "GSS"].contains(&ext.to_ascii_uppercase().as_str());
    let kept: Vec<char> = stem
        .chars()
        .filter(|c| c.is_ascii_alphanumeric() || *c == '_')
        .collect();
    if ext_ok && kept.len() == stem.chars().count() && (1..=8).contains(&kept.len()) {
        return file.to_string();
    }
    let tail: String = kept[kept.len().saturating_sub(8)..].iter().collect();
    let name = format!(
        "{}.{}",
        if tail.is_empty() { "IMPORTED" } else { &tail },
        if ext_ok { ext } else { "GSD" }
    );
    notes.chosen(
        "profibus.file_name",
        format!("`{file}` is not a GSD file name (8.3): the description names it `{name}`"),
    );
    name
}

/// The file's GSD revision, or the least its DPV1 keywords need where the
/// file is older (Siemens' SI018133 states I&M in a revision-4 file), which
/// the description cannot say otherwise (E124): marked with why; the round
/// trip judges the change.
fn revision_written(device: &DpDevice, revision: i64, notes: &mut Notes) -> i64 {
    let stated = |keyword| number_of(device, keyword) == Some(1);
    let (needed, keyword) = match (stated("DPV1_Slave"), stated("Ident_Maintenance_supp")) {
        (true, true) => (IM_GSD_REVISION, "Ident_Maintenance_supp"),
        (true, false) => (DPV1_GSD_REVISION, "DPV1_Slave"),
        (false, _) => return revision,
    };
    let needed = i64::from(needed);
    if revision >= needed {
        return revision;
    }
    notes.chosen(
        "profibus.gsd_revision",
        format!("GSD_Revision {revision} is imported as {needed}: the file states {keyword}, which came with revision {needed} (E124); the round trip judges the change"),
    );
    needed
}

fn family(k: &Keyword) -> String {
    match &k.value {
        GsdValue::Family { main, sub } => std::iter::once(main.to_string())
            .chain(sub.iter().cloned())
            .collect::<Vec<_>>()
            .join("@"),
        other => other
            .as_number()
            .map_or_else(String::new, |n| n.to_string()),
    }
}

fn modules(out: &mut TomlOut, device: &DpDevice, notes: &mut Notes) {
    let ppo5_words = ppo5_pzd_words(device).unwrap_or(crate::lower::DEFAULT_PPO5_PZD_WORDS);
    for m in &device.modules {
        out.array_item("profibus.modules");
        out.string("name", &m.name);
        if let Some(r) = m.reference {
            out.key("reference", r);
        }
        let safety = safety::block(m);
        for k in &m.keywords {
            match (k.key.as_str(), k.value.as_str()) {
                ("info_text", Some(info)) => out.string("info", info),
                (key, _) if safety.is_some() && safety::CRC_KEYWORDS.contains(&key) => {}
                _ => notes.unsaid(
                    &k.name,
                    &k.place,
                    &format!(
                        "module \"{}\": the description's modules have no key for it",
                        m.name
                    ),
                ),
            }
        }
        module_data(out, m, ppo5_words, notes);
        if let Some(block) = &safety {
            safety::write(out, m, block, notes);
        }
        let safety_unsaid = safety
            .is_none()
            .then_some(("PROFIsafe parameters", &m.safety_prm_data));
        for (what, data) in [("User_Prm_Data part", &m.user_prm_data)]
            .into_iter()
            .chain(safety_unsaid)
        {
            if !data.is_empty() {
                let place = data.fields.first().map(|f| &f.place).unwrap_or(&m.place);
                notes.unsaid(
                    &format!("module \"{}\"'s {what}", m.name),
                    place,
                    "the description has no module-specific parameters",
                );
            }
        }
    }
}

/// The PZD words of the file's PPO5: a module named PPO5 of the PKW
/// channel and one block of words each way, when it has not PROFIdrive's
/// 10 words.
fn ppo5_pzd_words(device: &DpDevice) -> Option<u8> {
    device.modules.iter().find_map(|m| {
        let ids = identifiers(&m.config).ok()?;
        let (true, words) = shape(&ids)? else {
            return None;
        };
        let named = m.name.to_ascii_uppercase().contains("PPO5");
        let one_block = ids.len() == 2;
        (named && one_block && words != crate::lower::DEFAULT_PPO5_PZD_WORDS).then_some(words)
    })
}

/// `ppo = "PPOn"` for a standard PPO type's bytes (PPO5 with the file's
/// words), else `data`.
fn module_data(out: &mut TomlOut, m: &DpModule, ppo5_words: u8, notes: &mut Notes) {
    let ppo = (1..=5u8).find(|&n| {
        crate::lower::ppo_layout(n, ppo5_words)
            .is_some_and(|layout| crate::lower::ppo_config_bytes(layout) == m.config)
    });
    if let Some(n) = ppo {
        out.string("ppo", &format!("PPO{n}"));
        return;
    }
    let ids = match identifiers(&m.config) {
        Ok(ids) => ids,
        Err(_) => {
            notes.unsaid(
                &format!("module \"{}\"'s config bytes", m.name),
                &m.place,
                "a special identifier announces more bytes than there are",
            );
            return;
        }
    };
    let pkw_first = shape(&ids).is_some_and(|(pkw, _)| pkw);
    let written: Vec<String> = ids
        .iter()
        .enumerate()
        .map(|(i, id)| {
            identifier(
                id,
                pkw_first && i == ids.iter().position(|i| !is_empty(i)).unwrap_or(0),
            )
        })
        .collect();
    out.key("data", list(written));
}

/// One identifier as the description writes it.
fn identifier(id: &Identifier, as_pkw: bool) -> String {
    let length = |l: &Length, way: &str| -> Vec<String> {
        let unit = if l.words { "words" } else { "bytes" };
        vec![format!("{unit}{way} = {}", l.count)]
    };
    let mut parts: Vec<String> = match id {
        Identifier::General { .. } if as_pkw => vec!["pkw = true".into()],
        Identifier::General { direction, data } => {
            let way = match direction {
                Direction::Both => "",
                Direction::Output => "_out",
                Direction::Input => "_in",
            };
            let mut p = length(data, way);
            if !data.consistent {
                p.push("consistent = false".into());
            }
            p
        }
        Identifier::Special {
            output,
            input,
            vendor,
        } => {
            let mut p: Vec<String> = output.iter().flat_map(|l| length(l, "_out")).collect();
            p.extend(input.iter().flat_map(|l| length(l, "_in")));
            if output.iter().chain(input).any(|l| !l.consistent) {
                p.push("consistent = false".into());
            }
            if !vendor.is_empty() {
                p.push(format!("vendor = {}", list(vendor.iter().map(|b| hex(*b)))));
            }
            p
        }
    };
    if parts.is_empty() {
        return "{}".into();
    }
    parts.dedup();
    format!("{{ {} }}", parts.join(", "))
}

/// `[profibus.user_prm]` and `[[profibus.parameters]]`.
fn user_prm(out: &mut TomlOut, device: &DpDevice, notes: &mut Notes) {
    let prm = &device.user_prm_data;
    let constant = constant_bytes(prm, number_of(device, "DPV1_Slave") == Some(1));
    let max_length = number_of(device, "Max_User_Prm_Data_Len");
    let block_structure = match (
        number_of(device, "Prm_Block_Structure_supp"),
        number_of(device, "Prm_Block_Structure_req"),
    ) {
        (Some(1), Some(1)) => Some("required"),
        (Some(1), _) => Some("supported"),
        _ => None,
    };
    if !constant.is_empty() || max_length.is_some() || block_structure.is_some() {
        out.table("profibus.user_prm");
        if !constant.is_empty() {
            out.key("constant", list(constant.iter().map(|b| hex(*b))));
        }
        if let Some(max) = max_length {
            out.key("max_length", max);
        }
        if let Some(b) = block_structure {
            out.string("block_structure", b);
        }
    }
    for field in &prm.fields {
        parameter(out, "profibus.parameters", field, notes);
    }
}

/// The constant bytes from byte 0, gaps and the declared length filled
/// with zeros (what the master sends there), and a DPV1 slave's three
/// status bytes at least.
fn constant_bytes(prm: &ParameterData, dpv1: bool) -> Vec<u8> {
    let at_least = prm.length.map(|l| l as usize).into_iter();
    fixed_bytes(prm, at_least.chain(dpv1.then_some(3)))
}

/// The bytes the constants give from byte 0, gaps zero, as far as they
/// reach and at least to each of `ends`.
fn fixed_bytes(prm: &ParameterData, ends: impl Iterator<Item = usize>) -> Vec<u8> {
    let end = prm
        .consts
        .iter()
        .map(|c| c.byte_offset as usize + c.bytes.len())
        .chain(ends)
        .max()
        .unwrap_or(0);
    let mut bytes = vec![0u8; end];
    for c in &prm.consts {
        let at = c.byte_offset as usize;
        bytes[at..at + c.bytes.len()].copy_from_slice(&c.bytes);
    }
    bytes
}

/// A parameter as an item of the array `array`
/// (`profibus.parameters`), or W600 where a card parameter cannot be it.
fn parameter(out: &mut TomlOut, array: &str, f: &Field, notes: &mut Notes) {
    let name = f.name.primary.to_string();
    let Some((stored_key, stored)) = super::prm::stored_as(f).or_else(|| signed8(f)) else {
        let what = format!("parameter \"{name}\" of type {}", f.data_type);
        notes.unsaid(
            &what,
            &f.place,
            "card parameters are Unsigned8, Unsigned16, Signed8 from 0 to 127, or a Bit or BitArea of one byte",
        );
        return;
    };
    out.array_item(array);
    out.string("name", &name);
    out.key("offset", f.byte_offset);
    out.key(stored_key, stored);
    let default = match &f.default {
        Some(Value::Int(v)) => *v,
        _ => 0,
    };
    out.key("default", default);
    if !f.choices.is_empty() {
        let choices = f.choices.iter().filter_map(|c| match &c.value {
            Value::Int(v) if allows(&f.allowed, *v) => Some(format!(
                "{{ value = {v}, text = {} }}",
                quote(&c.text.primary)
            )),
            _ => None,
        });
        out.key("choices", list(choices));
    } else if let Allowed::Ranges(ranges) = &f.allowed {
        let ints: Vec<(i128, i128)> = ranges
            .iter()
            .filter_map(|(a, b)| match (a, b) {
                (Value::Int(a), Value::Int(b)) => Some((*a, *b)),
                _ => None,
            })
            .collect();
        match joined(ints).as_slice() {
            [(min, max)] => out.key("range", format!("[{min}, {max}]")),
            _ => notes.unsaid(
                &format!("parameter \"{name}\"'s allowed values"),
                &f.place,
                "a card parameter without texts takes one range of values",
            ),
        }
    }
    if !f.changeable {
        out.key("changeable", false);
    }
    if !f.visible {
        out.key("visible", false);
    }
    for a in &f.attributes {
        notes.unsaid(
            &format!("parameter \"{name}\"'s {}", a.name),
            &a.place,
            "the description's parameters have no key for it",
        );
    }
}

/// Ranges sorted and joined where they overlap or touch: a set of values
/// that is one run (`66,66`, `1,2,3`) is one range, which the description
/// can say (gsdc diff takes the two as the same values).
fn joined(mut ranges: Vec<(i128, i128)>) -> Vec<(i128, i128)> {
    ranges.sort_unstable();
    let mut out: Vec<(i128, i128)> = Vec::with_capacity(ranges.len());
    for (lo, hi) in ranges {
        match out.last_mut() {
            Some(last) if lo <= last.1.saturating_add(1) => last.1 = last.1.max(hi),
            _ => out.push((lo, hi)),
        }
    }
    out
}

/// A card parameter's `type = "Signed8"`, where its default and every value
/// it allows are from 0 to 127, which is all the format says of one.
fn signed8(f: &Field) -> Option<(&'static str, String)> {
    let in_range = |v: &Value| matches!(v, Value::Int(0..=127));
    let values_in_range = match &f.allowed {
        Allowed::Any => false,
        Allowed::Ranges(ranges) => ranges.iter().all(|(a, b)| in_range(a) && in_range(b)),
    };
    let default_in_range = f.default.as_ref().is_none_or(in_range);
    (f.data_type == "Signed8" && f.bits.is_none() && values_in_range && default_in_range)
        .then(|| ("type", quote("Signed8")))
}

/// Whether a value is among those a parameter allows (its texts may name
/// more).
fn allows(allowed: &Allowed, value: i128) -> bool {
    match allowed {
        Allowed::Any => true,
        Allowed::Ranges(ranges) => ranges.iter().any(|(a, b)| match (a, b) {
            (Value::Int(a), Value::Int(b)) => (*a..=*b).contains(&value),
            _ => false,
        }),
    }
}

fn dpv1(out: &mut TomlOut, device: &DpDevice) {
    if number_of(device, "DPV1_Slave") != Some(1) {
        return;
    }
    out.table("profibus.dpv1");
    numbers(
        out,
        device,
        &[
            ("c1_max_data_len", "C1_Max_Data_Len"),
            ("c1_response_timeout", "C1_Response_Timeout"),
        ],
    );
    flags(
        out,
        device,
        &[
            ("c1_read_write", "C1_Read_Write_supp"),
            ("ident_maintenance", "Ident_Maintenance_supp"),
            ("data_types", "DPV1_Data_Types"),
            ("check_cfg_mode", "Check_Cfg_Mode"),
            ("c1_read_write_required", "C1_Read_Write_required"),
            ("c2_read_write_required", "C2_Read_Write_required"),
        ],
    );
    if number_of(device, "C2_Read_Write_supp").is_some_and(|n| n != 0) {
        out.table("profibus.dpv1.c2");
        numbers(
            out,
            device,
            &[
                ("max_data_len", "C2_Max_Data_Len"),
                ("response_timeout", "C2_Response_Timeout"),
                ("max_count_channels", "C2_Max_Count_Channels"),
                ("max_initiate_pdu_length", "Max_Initiate_PDU_Length"),
            ],
        );
    }
    alarms(out, device);
}

/// `[profibus.dpv1.alarms]`: the alarm keywords the file states (a kind's
/// `_supp` or `_required` of 0 is what leaving it out says).
fn alarms(out: &mut TomlOut, device: &DpDevice) {
    let kinds = |required: bool| -> Vec<String> {
        crate::ir::profibus::AlarmKind::ALL
            .into_iter()
            .filter(|k| {
                let (supp, req) = k.keywords();
                number_of(device, if required { req } else { supp }).is_some_and(|n| n != 0)
            })
            .map(|k| quote(k.name()))
            .collect()
    };
    let (supported, required) = (kinds(false), kinds(true));
    let modes = [
        ("type_mode", "Alarm_Type_Mode_supp"),
        ("extra_alarm_sap", "Extra_Alarm_SAP_supp"),
    ];
    let count = "Alarm_Sequence_Mode_Count";
    let stated = modes.iter().any(|(_, k)| device.keyword(k).is_some());
    if supported.is_empty() && required.is_empty() && !stated && device.keyword(count).is_none() {
        return;
    }
    out.table("profibus.dpv1.alarms");
    if !supported.is_empty() {
        out.key("supported", list(supported));
    }
    if !required.is_empty() {
        out.key("required", list(required));
    }
    flags(out, device, &modes);
    numbers(out, device, &[("sequence_mode_count", count)]);
}

/// How the import states a file's Max_Diag_Data_Len, which says how long
/// the diagnosis may be and not what it carries. A file that gives the
/// device block's bits or areas gets a device block (`[profibus.diagnosis]`)
/// of all the rest, or, with channel diagnosis, of the least its bits need
/// (its choice, marked), the length stated, the rest left to the channels'
/// blocks. A file without them has its length stated as it is, and no
/// device block made up.
struct DiagnosisPlan {
    device_block: Option<i64>,
    /// The device block's length is the import's choice.
    device_block_chosen: bool,
    max_diag_data_len: Option<i64>,
    /// Why the channels' error types cannot be said, if they cannot.
    channels_unsaid: Option<&'static str>,
}

impl DiagnosisPlan {
    fn of(device: &DpDevice) -> DiagnosisPlan {
        let d = &device.diagnosis;
        let standard = i64::from(STANDARD_DIAG_BYTES);
        let channel_block = i64::from(DP_CHANNEL_DIAG_BYTES);
        let total = number_of(device, "Max_Diag_Data_Len").unwrap_or(standard);
        let after_standard = total - standard;
        let has_block = !d.areas.is_empty() || !d.bits.is_empty();
        let no_room = Some("Max_Diag_Data_Len leaves no room for a channel's block of 3 bytes");
        if !has_block {
            return DiagnosisPlan {
                device_block: None,
                device_block_chosen: false,
                max_diag_data_len: (after_standard > 0).then_some(total),
                channels_unsaid: if after_standard < channel_block {
                    no_room
                } else {
                    None
                },
            };
        }
        let least = least_device_block(device);
        if d.channel.is_empty() || after_standard - least < channel_block {
            return DiagnosisPlan {
                device_block: Some(after_standard),
                device_block_chosen: false,
                max_diag_data_len: None,
                channels_unsaid: no_room,
            };
        }
        DiagnosisPlan {
            device_block: Some(least),
            device_block_chosen: true,
            max_diag_data_len: Some(total),
            channels_unsaid: None,
        }
    }
}

/// The header byte and the bytes the file's device bits and areas reach.
fn least_device_block(device: &DpDevice) -> i64 {
    let d = &device.diagnosis;
    let bits = d.bits.iter().map(|b| b.bit);
    let last = bits
        .chain(d.areas.iter().map(|a| a.last))
        .max()
        .unwrap_or(0);
    1 + last / 8 + 1
}

/// `[profibus.diagnosis]`, the device block, and
/// `[[profibus.channel_diagnosis]]`, as [`DiagnosisPlan`] says; what the
/// description has no place for, a W600 each.
fn diagnosis(out: &mut TomlOut, device: &DpDevice, notes: &mut Notes) {
    let plan = DiagnosisPlan::of(device);
    if let Some(length) = plan.device_block {
        if plan.device_block_chosen {
            notes.chosen(
                "profibus.diagnosis.length",
                format!("the file does not say how long its device block is: {length}, the least its bits and areas need, the rest of its Max_Diag_Data_Len left to the channels' blocks"),
            );
        }
        device_block(out, device, length, notes);
    }
    let d = &device.diagnosis;
    for t in &d.types {
        diagnosis_type(out, t, notes);
    }
    for c in &d.channel {
        match plan.channels_unsaid {
            Some(why) => notes.unsaid(&format!("Channel_Diag({})", c.value), &c.place, why),
            None => {
                out.array_item("profibus.channel_diagnosis");
                out.key("error_type", c.value);
                out.string("name", &c.text.primary);
            }
        }
    }
}

fn device_block(out: &mut TomlOut, device: &DpDevice, length: i64, notes: &mut Notes) {
    let d = &device.diagnosis;
    out.table("profibus.diagnosis");
    out.key("length", length);
    write_bits(out, &d.bits, notes);
    write_areas(out, "profibus.diagnosis.areas", &d.areas);
}

/// `[[profibus.diagnosis_types]]`: a `UnitDiagType`'s areas and bits.
fn diagnosis_type(out: &mut TomlOut, t: &DiagType, notes: &mut Notes) {
    let Ok(id) = u8::try_from(t.id) else {
        notes.unsaid(
            &format!("UnitDiagType = {}", t.id),
            &t.place,
            "a diagnosis type is 0 to 255",
        );
        return;
    };
    out.array_item("profibus.diagnosis_types");
    out.key("id", id);
    write_bits(out, &t.bits, notes);
    write_areas(out, "profibus.diagnosis_types.areas", &t.areas);
}

/// `bits = [...]`, each bit's help text a W600.
fn write_bits(out: &mut TomlOut, bits: &[DiagBit], notes: &mut Notes) {
    let bits: Vec<String> = bits
        .iter()
        .map(|b| {
            if b.help.is_some() {
                let what = if b.when_clear {
                    "Unit_Diag_Not_Bit_Help"
                } else {
                    "Unit_Diag_Bit_Help"
                };
                notes.unsaid(
                    &format!("{what}({})", b.bit),
                    &b.place,
                    "the description's diagnosis bits have no help text",
                );
            }
            let clear = if b.when_clear { ", clear = true" } else { "" };
            format!(
                "{{ bit = {}, text = {}{clear} }}",
                b.bit,
                quote(&b.text.primary)
            )
        })
        .collect();
    if !bits.is_empty() {
        out.key("bits", format!("[\n    {},\n]", bits.join(",\n    ")));
    }
}

/// Each area as an item of `array`, with its values' texts.
fn write_areas(out: &mut TomlOut, array: &str, areas: &[DiagArea]) {
    for a in areas {
        out.array_item(array);
        out.key("bit", format!("[{}, {}]", a.first, a.last));
        let values = a.values.iter().map(|v| {
            format!(
                "{{ value = {}, text = {} }}",
                v.value,
                quote(&v.text.primary)
            )
        });
        out.key("values", list(values));
    }
}

/// `[manual]`, for the maintainer to fill, as comments: its title and
/// languages cannot be imported, and the description must load without.
pub(super) fn manual(out: &mut TomlOut) {
    out.comment_block();
    out.comment("");
    out.comment("Fill in the manual the values come from, then confirm each value under");
    out.comment("[choices] against it and remove its mark:");
    out.comment("[manual]");
    out.comment("title = \"...\"");
    out.comment("languages = [\"en\"]");
}

/// The keywords the GSD specification does not have, each once (a GSD reads
/// keywords without regard to case), with a value
/// `[profibus.vendor_keywords]` holds: a number of 0 to 2^32 - 1, or a
/// string (`is_vendor_string`). Others are left out.
fn vendor_keywords(device: &DpDevice) -> Vec<(&Keyword, String)> {
    let mut vendor: Vec<(&Keyword, String)> = Vec::new();
    for k in &device.keywords {
        let once = !vendor
            .iter()
            .any(|(v, _)| v.name.eq_ignore_ascii_case(&k.name));
        if !once || crate::lower::vendor_keyword_problem(&k.name).is_some() {
            continue;
        }
        let value = match &k.value {
            GsdValue::Number(n) => u32::try_from(*n).ok().map(|n| n.to_string()),
            GsdValue::Str(s) if is_vendor_string(s) => Some(quote(s)),
            _ => None,
        };
        vendor.extend(value.map(|v| (k, v)));
    }
    vendor
}

/// A string `[profibus.vendor_keywords]` holds: not empty, printable ASCII
/// without `"`, no longer than the longest string keyword (`Info_Text`).
fn is_vendor_string(s: &str) -> bool {
    let printable = s.chars().all(|c| (' '..='~').contains(&c) && c != '"');
    printable && !s.is_empty() && s.len() <= crate::gsd::keyword_max_len("Info_Text")
}

fn write_vendor_keywords(out: &mut TomlOut, vendor: &[(&Keyword, String)]) {
    if vendor.is_empty() {
        return;
    }
    out.table("profibus.vendor_keywords");
    for (k, value) in vendor {
        // Bare where TOML lets it be: a `.` would make a dotted key.
        match k.name.contains('.') {
            true => out.key(&quote(&k.name), value),
            false => out.key(&k.name, value),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::joined;

    #[test]
    fn a_set_of_values_in_one_run_is_one_range() {
        assert_eq!(joined(vec![(66, 66), (66, 66)]), [(66, 66)]);
        assert_eq!(joined(vec![(3, 3), (1, 1), (2, 2)]), [(1, 3)]);
        assert_eq!(joined(vec![(0, 4), (2, 9)]), [(0, 9)]);
        assert_eq!(joined(vec![(1, 1), (2, 2), (5, 5)]), [(1, 2), (5, 5)]);
    }
}
