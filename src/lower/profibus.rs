//! The PROFIBUS part: identity numbers, bus parameters, PPO modules, the
//! parameter telegram and the diagnosis.

use super::checks::{Checker, GSD_NAME_LEN};
use super::gateway;
use super::mappings::SetSpans;
use super::ppo::{config_bytes, ppo_layout};
use super::telegram::value_set;
use crate::description as raw;
use crate::diag::Diagnostic;
use crate::i18n::files;
use crate::ir::profibus::{
    Baud, Diagnosis, DiagnosisArea, DiagnosisBit, DiagnosisType, DpModule, Dpv1, Dpv1Class2,
    Features, GsdReleases, LimitsWritten, PrmBlock, PrmParam, PrmText, PrmTextOf, PrmType,
    PrmValue, Profibus, UserPrm, STANDARD_DIAG_BYTES,
};
use crate::ir::{EntryType, Ident, MappingSet, Mappings, PkwKind, Scope, Telegram, Text};
use crate::spec::{DPV1_GSD_REVISION, IM_GSD_REVISION};
use crate::spec::{GSD_KEY_WIDTH as KEY_WIDTH, GSD_LINE_WIDTH as MAX_LINE};
use std::collections::{BTreeMap, BTreeSet};
use std::ops::Range;
use toml::Spanned;

const DEFAULT_GSD_REVISION: u8 = 5;
/// The PPO types as the description names them: PPO1 to PPO5, no other
/// spelling (FIELDBUS-NOTES §1).
const PPO_NAMES: [&str; 5] = ["PPO1", "PPO2", "PPO3", "PPO4", "PPO5"];
/// PROFIdrive's PPO5 has 10 PZD words.
pub(crate) const DEFAULT_PPO5_PZD_WORDS: u8 = 10;
const DEFAULT_C1_MAX_DATA_LEN: u8 = 240;
const DEFAULT_C1_RESPONSE_TIMEOUT: u16 = 100;
/// A Unit_Diag_Area spans at most 16 bits.
const MAX_DIAG_AREA_BITS: i64 = 16;
/// Main slave families defined by PI (0 general .. 12 PA).
const MAX_MAIN_FAMILY: u8 = 12;

pub fn lower(
    cx: &mut Checker,
    p: &Spanned<raw::Profibus>,
    (telegram, mappings, set_spans): (&Telegram, &Mappings, &SetSpans),
    gateway: Option<&gateway::Lowered>,
    device: &crate::ir::Device,
) -> Option<Profibus> {
    let near = p.span();
    let p = p.get_ref();
    let mut feature = |given: &Option<Spanned<bool>>, key: &str| match given {
        Some(said) => *said.get_ref(),
        None => {
            cx.defaulted(&format!("profibus.{key}"), false, near.clone());
            false
        }
    };
    let (freeze_mode, sync_mode, fail_safe) = (
        feature(&p.freeze_mode, "freeze_mode"),
        feature(&p.sync_mode, "sync_mode"),
        feature(&p.fail_safe, "fail_safe"),
    );
    let gsd_revision = match &p.gsd_revision {
        // The specification's first edition, before GSD_Revision: the GSD
        // writes no revision (Siemens' SIMADYN D SS52 of 1998).
        Some(r) if *r.get_ref() == 0 => 0,
        Some(r) => cx.gsd_number(r, "GSD_Revision", "gsd_revision")?,
        None => DEFAULT_GSD_REVISION,
    };
    let constant = super::dp_params::constant(p.user_prm.as_ref());
    let dpv1 = p
        .dpv1
        .as_ref()
        .and_then(|d| lower_dpv1(cx, d, constant.as_ref()));
    if let (Some(d), Some(revision)) = (&dpv1, &p.gsd_revision) {
        if d.ident_maintenance && gsd_revision < IM_GSD_REVISION {
            cx.push(
                Diagnostic::error("E124", format!("I&M (Ident_Maintenance_supp) needs GSD revision {IM_GSD_REVISION}; this GSD is revision {gsd_revision}"))
                    .at(revision.span())
                    .label("too old for I&M")
                    .help(format!("set gsd_revision = {IM_GSD_REVISION}, or drop ident_maintenance")),
            );
        }
        if gsd_revision < DPV1_GSD_REVISION {
            cx.push(
                Diagnostic::error("E124", format!("DPV1 needs GSD revision {DPV1_GSD_REVISION}; this GSD is revision {gsd_revision}"))
                    .at(revision.span())
                    .label("too old for DPV1")
                    .help(format!("set gsd_revision = {DPV1_GSD_REVISION} or later, or drop [profibus.dpv1]")),
            );
        }
    }
    let mut user_prm = user_prm(
        cx,
        p,
        (dpv1.as_ref(), constant),
        (mappings, set_spans),
        gateway,
    );
    let ident = p.ident_number.get_ref();
    if ident.placeholder {
        let value = format!("0x{:04X}", ident.value.get_ref());
        cx.placeholder(
            Diagnostic::warning(
                "W101",
                format!("PROFIBUS ident number {value} is a placeholder, not assigned by PI"),
            )
            .at(p.ident_number.span())
            .label("placeholder")
            .help("apply to PI for an ident number before shipping the GSD"),
            ("profibus.ident_number", value),
            crate::i18n::files::NOT_ASSIGNED_BY_PI,
        );
    }
    let mut modules = modules(cx, p, telegram);
    if let Some(given) = &p.modules {
        let given = (&given.get_ref()[..], gsd_revision);
        super::dp_safety::lower(cx, given, &mut modules, &mut user_prm);
    }
    layout_decisions(
        cx,
        (&modules, p.max_module.is_some()),
        &user_prm,
        gateway.is_some(),
    );
    let diagnosis = p.diagnosis.as_ref().and_then(|d| diagnosis(cx, d));
    let diagnosis_types = diagnosis_types(cx, &p.diagnosis_types);
    let device_diag_len = diagnosis
        .as_ref()
        .map(|d| d.length)
        .or_else(|| {
            let d = gateway?.gateway.diagnosis.as_ref()?;
            Some(d.max_len)
        })
        .max(types_diag_len(&diagnosis_types));
    let limits = limits(cx, p, &modules, gateway);
    let features = features(cx, p, gsd_revision);
    fail_safe_required_supported(cx, p, fail_safe);
    let channel_diagnosis = super::dp_channel::lower(cx, &p.channel_diagnosis);
    let isochronous = p
        .isochronous
        .as_ref()
        .map(|i| super::dp_timing::isochronous(cx, i, gsd_revision));
    let prm_block_structure = p
        .user_prm
        .as_ref()
        .and_then(|u| u.get_ref().block_structure.as_ref())
        .map(|b| super::dp_timing::block_structure(cx, b, gsd_revision));
    Some(Profibus {
        latin1: p
            .charset
            .as_ref()
            .is_some_and(|c| *c.get_ref() == raw::Charset::Latin1),
        file_name: file_name(cx, &p.file_name),
        // `missing_gsd_identity` has refused a description without them.
        releases: GsdReleases::of(device)?,
        gsd_revision,
        ident_number: *ident.value.get_ref(),
        ident_placeholder: ident.placeholder,
        implementation_type: cx.optional_gsd_string(
            p.implementation_type.as_ref(),
            "Implementation_Type",
            "implementation_type",
        ),
        vendor_keywords: vendor_keywords(cx, &p.vendor_keywords),
        modules,
        max_input_len: limits.input,
        max_output_len: limits.output,
        max_data_len: limits.data,
        max_module: limits.module,
        modular_station: limits.modular,
        limits_written: limits.written,
        features,
        baud_rates: baud_rates(cx, &p.baud_rates),
        min_slave_interval: cx.gsd_number(
            &p.min_slave_interval,
            "Min_Slave_Intervall",
            "min_slave_interval",
        )?,
        slave_family: slave_family(cx, &p.slave_family),
        auto_baud: p.auto_baud,
        freeze_mode,
        sync_mode,
        fail_safe,
        dpv1,
        isochronous,
        prm_block_structure,
        user_prm,
        diagnosis_types,
        max_diag_data_len: max_diag_data_len(cx, p, device_diag_len),
        bitmap_device: device
            .symbol
            .is_some()
            .then(|| gsd_stem(p.file_name.get_ref())),
        info_text: info_text(
            device.info.as_ref(),
            *ident.value.get_ref(),
            ident.placeholder,
        ),
        diagnosis,
        channel_diagnosis: channel_diagnosis?,
    })
}

/// Max_Diag_Data_Len: the standard diagnosis and the device block, or what
/// the description states, never less (E174). A card with channel
/// diagnosis states it (E196): how many channels' blocks one diagnosis
/// carries is the firmware's to say; it holds one at least.
fn max_diag_data_len(cx: &mut Checker, p: &raw::Profibus, device_diag_len: Option<u8>) -> u8 {
    let mut needed = STANDARD_DIAG_BYTES + device_diag_len.unwrap_or(0);
    let mut what = "the standard diagnosis and the device block";
    if let Some(first) = p.channel_diagnosis.first() {
        needed += crate::spec::DP_CHANNEL_DIAG_BYTES;
        what = "the standard diagnosis, the device block and one channel's block";
        if p.max_diag_data_len.is_none() {
            cx.push(
                Diagnostic::error("E196", "channel diagnosis without a diagnosis length for its blocks")
                    .at(first.span())
                    .label("3 bytes for each channel's block")
                    .help(format!("state max_diag_data_len in [profibus]: {needed} for one channel's block, and 3 more for each further block one diagnosis carries at most (the firmware's number)")),
            );
            return needed;
        }
    }
    let Some(stated) = &p.max_diag_data_len else {
        return needed;
    };
    let value = *stated.get_ref();
    at_least(
        cx,
        ("max_diag_data_len", value.into(), stated.span()),
        needed.into(),
        what,
    );
    let (min, max) = crate::gsd::keyword_range("Max_Diag_Data_Len");
    let span = stated.span();
    cx.in_range::<u8>(value.into(), min, max, span, "max_diag_data_len");
    value.max(needed)
}

/// E195: Fail_Safe_required for a card that does not say Fail_Safe.
fn fail_safe_required_supported(cx: &mut Checker, p: &raw::Profibus, fail_safe: bool) {
    if let Some(required) = p.fail_safe_required.as_ref().filter(|r| *r.get_ref()) {
        if !fail_safe {
            cx.push(
                Diagnostic::error("E195", "fail-safe mode required but not supported")
                    .at(required.span())
                    .label("Fail_Safe_required without Fail_Safe")
                    .help("set fail_safe = true: a master can only meet what the card supports"),
            );
        }
    }
}

/// Max_Module and the data lengths: what the modules need, or what the
/// description states, never less (E174); a gateway's, its limits.
struct Limits {
    module: u8,
    input: u16,
    output: u16,
    data: u16,
    modular: bool,
    written: LimitsWritten,
}

fn limits(
    cx: &mut Checker,
    p: &raw::Profibus,
    modules: &[DpModule],
    gateway: Option<&gateway::Lowered>,
) -> Limits {
    let most = |f: fn(&DpModule) -> u16| modules.iter().map(f).max().unwrap_or(0);
    let (input, output) = gateway.map_or_else(
        || (most(|m| m.input_len), most(|m| m.output_len)),
        |g| (g.gateway.max_input_len, g.gateway.max_output_len),
    );
    let data = most(|m| m.input_len + m.output_len);
    let module = gateway.map_or(1, |g| g.gateway.max_modules);
    let modular = p.modular_station.as_ref().is_none_or(|m| *m.get_ref());
    if let (false, Some(m)) = (modular, &p.modular_station) {
        if modules.len() != 1 {
            cx.push(
                Diagnostic::error("E173", format!("a compact station has one module; this one has {}", modules.len()))
                    .at(m.span())
                    .label("modular_station = false")
                    .help("a compact station (Modular_Station = 0) is its one module: give one, or make the station modular"),
            );
        }
    }
    let mut stated = |value: Option<(u16, Range<usize>)>, derived: u16, keyword: &str| {
        let Some((value, span)) = value else {
            return (derived, false);
        };
        at_least(
            cx,
            (keyword, value, span.clone()),
            derived,
            "what the modules need",
        );
        let (min, max) = crate::gsd::keyword_range(keyword);
        cx.in_range::<u16>(i64::from(value), min, max, span, keyword);
        (value.max(derived), true)
    };
    let given = |v: &Option<Spanned<u8>>| v.as_ref().map(|v| (u16::from(*v.get_ref()), v.span()));
    let (input, input_stated) = stated(given(&p.max_input_len), input, "Max_Input_Len");
    let (output, output_stated) = stated(given(&p.max_output_len), output, "Max_Output_Len");
    let (module, module_stated) = stated(given(&p.max_module), module.into(), "Max_Module");
    let data_given = p.max_data_len.as_ref().map(|v| (*v.get_ref(), v.span()));
    let (data, data_stated) = match data_given {
        Some(_) => stated(data_given, data, "Max_Data_Len"),
        None => (input + output, false),
    };
    Limits {
        module: u8::try_from(module).unwrap_or(u8::MAX),
        input,
        output,
        data,
        modular,
        written: LimitsWritten {
            max_module: modular || module_stated,
            max_input_len: modular || input_stated,
            max_output_len: modular || output_stated,
            max_data_len: modular || data_stated,
        },
    }
}

/// The DP keywords a description may state, each within its keyword's
/// range and no newer than the GSD's revision (E172).
fn features(cx: &mut Checker, p: &raw::Profibus, gsd_revision: u8) -> Features {
    let mut flag = |v: &Option<Spanned<bool>>, keyword: &str| {
        let v = v.as_ref()?;
        cx.since_revision(keyword, v.span(), gsd_revision);
        Some(*v.get_ref())
    };
    let set_slave_address = flag(&p.set_slave_address, "Set_Slave_Add_supp");
    let redundancy = flag(&p.redundancy, "Redundancy");
    let wd_base_1ms = flag(&p.wd_base_1ms, "WD_Base_1ms_supp");
    let publisher = flag(&p.publisher, "Publisher_supp");
    let fail_safe_required = flag(&p.fail_safe_required, "Fail_Safe_required");
    let mut number = |v: &Option<Spanned<u8>>, keyword: &str| {
        let v = v.as_ref()?;
        cx.since_revision(keyword, v.span(), gsd_revision);
        cx.gsd_number(v, keyword, keyword)
    };
    Features {
        set_slave_address,
        redundancy,
        repeater_ctrl_sig: number(&p.repeater_ctrl_sig, "Repeater_Ctrl_Sig"),
        pins_24v: number(&p.pins_24v, "24V_Pins"),
        wd_base_1ms,
        publisher,
        modul_offset: number(&p.modul_offset, "Modul_Offset"),
        fail_safe_required,
    }
}

/// What the GSD lays out by gsdc's rules where the manual gives no bytes:
/// each module's config identifiers, Max_Module and User_Prm_Data's order
/// and offsets, listed in every header (the layouts carry each number).
/// A vendor's modules (`[[profibus.modules]]` with `data`) carry the
/// identifiers their description states, and a stated Max_Module is the
/// description's: neither is listed.
fn layout_decisions(
    cx: &mut Checker,
    (modules, max_module_stated): (&[DpModule], bool),
    user_prm: &UserPrm,
    gateway: bool,
) {
    let ppos: Vec<(u8, &DpModule)> = modules.iter().filter_map(|m| Some((m.ppo?, m))).collect();
    if !ppos.is_empty() {
        let bytes: Vec<String> = ppos
            .iter()
            .map(|(ppo, m)| {
                let config: Vec<String> = m.config.iter().map(|b| format!("0x{b:02X}")).collect();
                format!("PPO{ppo} {}", config.join(","))
            })
            .collect();
        cx.layout(
            "profibus config identifiers",
            format!(
                "the PKW 0xF3 (4 words in and out, consistent), the PZD 0xF0 | (words - 1) (words in and out, consistent): {}",
                bytes.join("; ")
            ),
            files::CONFIG_IDENTIFIERS_REASON,
        );
    }
    if !modules.is_empty() && !max_module_stated {
        cx.layout("profibus Max_Module", 1, files::MAX_MODULE_REASON);
    }
    if gateway || user_prm.blocks.is_empty() {
        return;
    }
    let mut places: Vec<String> = Vec::new();
    if !user_prm.constant.is_empty() {
        places.push(format!(
            "DPV1_Status_1..3 at bytes 0-{}",
            user_prm.constant.len() - 1
        ));
    }
    for block in &user_prm.blocks {
        let last = block
            .params
            .last()
            .map_or(block.offset, |p| p.offset + p.data_type.bytes() - 1);
        places.push(format!(
            "{} at bytes {}-{last}",
            block.kind.key(),
            block.offset
        ));
    }
    let params = || user_prm.blocks.iter().flat_map(|b| &b.params);
    let entries = match params().all(|p| p.data_type == PrmType::Unsigned16) {
        true => "one Unsigned16 per entry",
        false => "each entry of its type (a setting's, else Unsigned16)",
    };
    cx.layout(
        "profibus User_Prm_Data",
        format!("{}; {entries}, high byte first, no gaps", places.join(", ")),
        files::USER_PRM_LAYOUT_REASON,
    );
}

/// Info_Text: the device's info text (its GSD form), after a notice that
/// the file is a draft while the ident number is a placeholder, so that
/// STEP 7's and TIA Portal's catalog say it; within the GSD's 256
/// characters, the info cut at a word (`...`) where the notice leaves too
/// few.
fn info_text(info: Option<&Text>, ident: u16, placeholder: bool) -> Option<String> {
    let info = info.map(|i| i.for_gsd().to_string());
    if !placeholder {
        return info;
    }
    let notice = format!(
        "DRAFT, not for release: Ident_Number 0x{ident:04X} is a placeholder, not assigned by PI."
    );
    Some(match info {
        None => notice,
        Some(info) => within(
            &format!("{notice} {info}"),
            crate::gsd::keyword_max_len("Info_Text"),
        ),
    })
}

/// `text`, or as many of its words as fit in `limit` characters with `...`.
fn within(text: &str, limit: usize) -> String {
    if text.chars().count() <= limit {
        return text.to_string();
    }
    let mut out = String::new();
    for word in text.split(' ') {
        if out.chars().count() + 1 + word.chars().count() + "...".len() > limit {
            break;
        }
        if !out.is_empty() {
            out.push(' ');
        }
        out.push_str(word);
    }
    out.push_str("...");
    out
}

/// `MD810DP` of `MD810DP.GSD`: the GSD's bitmap takes its name (8.3, so at
/// most 8 characters, as Bitmap_Device allows).
fn gsd_stem(file_name: &str) -> String {
    file_name
        .rsplit_once('.')
        .map_or(file_name, |(stem, _)| stem)
        .to_string()
}

/// 8.3 names, ending in .GSD (neutral) or the language letter (.GSE, .GSG, …).
fn file_name(cx: &mut Checker, name: &Spanned<String>) -> String {
    let text = name.get_ref();
    let valid = text.rsplit_once('.').is_some_and(|(stem, ext)| {
        let ext = ext.to_ascii_uppercase();
        (1..=8).contains(&stem.len())
            && stem.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
            && ["GSD", "GSE", "GSG", "GSF", "GSI", "GSS"].contains(&ext.as_str())
    });
    if !valid {
        cx.push(
            Diagnostic::error("E112", format!("`{text}` is not a GSD file name"))
                .at(name.span())
                .label("not 8.3 with a GSD extension")
                .help("at most 8 letters, digits or `_`, then .GSD (or .GSE, .GSG, .GSF, .GSI, .GSS for one language)"),
        );
    }
    text.clone()
}

fn modules(cx: &mut Checker, p: &raw::Profibus, telegram: &Telegram) -> Vec<DpModule> {
    let ppo5_pzd_words = match &p.ppo5_pzd_words {
        Some(w) => cx
            .spanned_in_range(w, 1, 16, "ppo5_pzd_words")
            .unwrap_or(DEFAULT_PPO5_PZD_WORDS),
        None => DEFAULT_PPO5_PZD_WORDS,
    };
    if let Some(words) = &p.ppo5_pzd_words {
        let ppo5 = p.ppo_types.as_ref().map(Spanned::get_ref);
        let in_modules = p.modules.as_ref().is_some_and(|m| {
            m.get_ref()
                .iter()
                .any(|m| m.ppo.as_ref().is_some_and(|t| t.get_ref() == "PPO5"))
        });
        if !in_modules && !ppo5.is_some_and(|types| types.iter().any(|t| t.get_ref() == "PPO5")) {
            cx.push(
                Diagnostic::error("E002", "ppo5_pzd_words without PPO5 in ppo_types")
                    .at(words.span())
                    .label("no PPO5 to size")
                    .help("ppo5_pzd_words gives PPO5's PZD words: add \"PPO5\" to ppo_types, or remove it"),
            );
        }
    }
    if let Some(modules) = &p.modules {
        if let Some(types) = &p.ppo_types {
            cx.push(
                Diagnostic::error("E170", "both ppo_types and profibus.modules")
                    .at(types.span())
                    .label("remove this or [[profibus.modules]]")
                    .help("the modules are the PPO types gsdc lays out, or the modules [[profibus.modules]] gives (each may be a PPO type: `ppo = \"PPO1\"`)"),
            );
        }
        return super::dp_modules::lower(cx, modules, ppo5_pzd_words, telegram);
    }
    // Without a gateway, lowering refused a description without them.
    let Some(ppo_types) = &p.ppo_types else {
        return Vec::new();
    };
    if ppo_types.get_ref().is_empty() {
        cx.push(
            Diagnostic::error("E101", "ppo_types is empty")
                .at(ppo_types.span())
                .label("no PPO type")
                .help("offer at least one, e.g. ppo_types = [\"PPO1\"]"),
        );
    }
    let mut seen = BTreeSet::new();
    ppo_types
        .get_ref()
        .iter()
        .filter_map(|name| {
            let module = ppo_module(cx, name, ppo5_pzd_words, telegram)?;
            if !seen.insert(module.ppo) {
                cx.duplicate(name.get_ref().clone(), name.span());
                return None;
            }
            Some(module)
        })
        .collect()
}

fn ppo_module(
    cx: &mut Checker,
    name: &Spanned<String>,
    ppo5_pzd_words: u8,
    telegram: &Telegram,
) -> Option<DpModule> {
    let written = name.get_ref().as_str();
    let number = (1..).zip(PPO_NAMES).find(|(_, n)| *n == written);
    let Some((ppo, layout)) = number.and_then(|(n, _)| Some((n, ppo_layout(n, ppo5_pzd_words)?)))
    else {
        // `PPO02`, `PPO+1`, `PP01`: the type that ends as it does, if near.
        let last = written.chars().last();
        let ending_alike = PPO_NAMES.into_iter().filter(|n| n.chars().last() == last);
        let suggestion = crate::spelling::closest(written, ending_alike)
            .map(|n| format!("; did you mean `{n}`?"))
            .unwrap_or_default();
        cx.push(
            Diagnostic::error("E104", format!("`{written}` is not a PPO type"))
                .at(name.span())
                .label("unknown PPO type")
                .help(format!(
                    "PPO types are PPO1, PPO2, PPO3, PPO4 and PPO5{suggestion}"
                )),
        );
        return None;
    };
    if layout.pkw && telegram.pkw == PkwKind::None {
        cx.push(
            Diagnostic::error(
                "E121",
                format!("PPO{ppo} carries a PKW channel, but the telegram has none"),
            )
            .at(name.span())
            .label("has PKW")
            .help("set telegram.pkw to the channel's kind, or offer only PPO3 and PPO4"),
        );
    }
    if layout.pzd_words > telegram.pzd_words {
        cx.push(
            Diagnostic::error(
                "E113",
                format!(
                    "PPO{ppo} has {} PZD words; the telegram has {}",
                    layout.pzd_words, telegram.pzd_words
                ),
            )
            .at(name.span())
            .label("longer than the telegram")
            .help("raise telegram.pzd_words or drop this PPO type"),
        );
    }
    let pkw = if layout.pkw { "4 PKW + " } else { "" };
    Some(DpModule {
        ppo: Some(ppo),
        name: format!("PPO{ppo}: {pkw}{} PZD", layout.pzd_words),
        reference: Some(ppo.into()),
        info: None,
        layout: Some(layout),
        config: config_bytes(layout),
        input_len: layout.bytes(),
        output_len: layout.bytes(),
        ident: Ident::of(&[&format!("ppo{ppo}")]),
        safety: None,
    })
}

fn baud_rates(cx: &mut Checker, rates: &Spanned<BTreeMap<Baud, Spanned<u16>>>) -> Vec<(Baud, u16)> {
    let lowered: Vec<_> = rates
        .get_ref()
        .iter()
        .filter_map(|(&baud, tsdr)| {
            // No station answers in no time.
            let tsdr = cx.gsd_number_from(tsdr, "MaxTsdr_<baud>", 1, "MaxTsdr")?;
            Some((baud, tsdr))
        })
        .collect();
    if rates.get_ref().is_empty() {
        cx.push(
            Diagnostic::error("E111", "no baud rate is supported")
                .at(rates.span())
                .label("empty")
                .help("give MaxTsdr for each supported rate, e.g. \"1.5M\" = 150"),
        );
    }
    lowered
}

/// `1`, or `1@Drives@AC`: a main family number, then sub-families.
/// Readers take a Slave_Family to the end of its line (gsd-parser's
/// `family_ident`), so the GSD never continues it: with its key it fits one
/// line.
const MAX_SLAVE_FAMILY_LEN: usize = MAX_LINE - KEY_WIDTH - "= ".len();

fn slave_family(cx: &mut Checker, family: &Spanned<String>) -> String {
    let text = family.get_ref();
    if text.len() > MAX_SLAVE_FAMILY_LEN {
        cx.push(
            Diagnostic::error(
                "E120",
                format!("a slave family of {} characters does not fit a GSD line", text.len()),
            )
            .at(family.span())
            .label(format!("more than {MAX_SLAVE_FAMILY_LEN} characters"))
            .help(format!("GSD readers take Slave_Family to the end of its line, so it cannot be continued: keep it to {MAX_SLAVE_FAMILY_LEN} characters, with fewer or shorter sub-families")),
        );
        return text.clone();
    }
    let mut parts = text.split('@');
    let main_ok = parts
        .next()
        .and_then(|m| crate::description::digits(m, 10))
        .is_some_and(|m| m <= u32::from(MAX_MAIN_FAMILY));
    let subs_ok = parts.all(|s| {
        !s.is_empty()
            && s.len() <= GSD_NAME_LEN
            && s.chars().all(|c| super::checks::is_gsd_char(c, false))
    });
    if !(main_ok && subs_ok) {
        cx.push(
            Diagnostic::error("E120", format!("`{text}` is not a slave family"))
                .at(family.span())
                .label("expected <main>[@<sub>...]")
                .help(format!("the main family is a number 0..={MAX_MAIN_FAMILY} (1 = drives), sub-families follow after `@`")),
        );
    }
    text.clone()
}

/// The DPV1 class 1 channel; what the description leaves out is gsdc's
/// default, said (W104) where the description would state it.
fn lower_dpv1(
    cx: &mut Checker,
    d: &Spanned<raw::Dpv1>,
    constant: Option<&super::dp_params::Constant>,
) -> Option<Dpv1> {
    let near = d.span();
    let d = d.get_ref();
    let c1_max_data_len = match &d.c1_max_data_len {
        Some(l) => cx.gsd_number(l, "C1_Max_Data_Len", "c1_max_data_len")?,
        None => {
            cx.defaulted(
                "profibus.dpv1.c1_max_data_len",
                DEFAULT_C1_MAX_DATA_LEN,
                near.clone(),
            );
            DEFAULT_C1_MAX_DATA_LEN
        }
    };
    let c1_response_timeout = match &d.c1_response_timeout {
        Some(t) => cx.gsd_number(t, "C1_Response_Timeout", "c1_response_timeout")?,
        None => {
            cx.defaulted(
                "profibus.dpv1.c1_response_timeout",
                DEFAULT_C1_RESPONSE_TIMEOUT,
                near.clone(),
            );
            DEFAULT_C1_RESPONSE_TIMEOUT
        }
    };
    let status_bytes = match (&d.status_bytes, constant) {
        (Some(bytes), Some(_)) => {
            cx.duplicate(
                "the DPV1 status bytes (status_bytes and user_prm.constant)".into(),
                bytes.span(),
            );
            bytes.get_ref().0
        }
        (Some(bytes), None) => bytes.get_ref().0,
        (None, Some((bytes, span))) => match bytes.get(..3) {
            Some(&[a, b, c]) => [a, b, c],
            _ => {
                cx.push(
                    Diagnostic::error("E101", "user_prm.constant is shorter than the DPV1 status bytes")
                        .at(span.clone())
                        .label("fewer than 3 bytes")
                        .help("a DPV1 slave's User_Prm_Data starts with DPV1_Status_1..3: give them first"),
                );
                [0; 3]
            }
        },
        (None, None) => {
            cx.defaulted("profibus.dpv1.status_bytes", "[0, 0, 0]", near.clone());
            [0; 3]
        }
    };
    let c2 = match &d.c2 {
        Some(c2) => Some(class2(cx, c2.get_ref())?),
        None => None,
    };
    identification_and_maintenance(cx, d, near);
    let required = super::dp_timing::channels_required(cx, d);
    Some(Dpv1 {
        c1_read_write: d.c1_read_write,
        c1_max_data_len,
        c1_response_timeout,
        status_bytes,
        c2,
        ident_maintenance: d.ident_maintenance == Some(true),
        data_types: d.data_types.as_ref().map(|v| *v.get_ref()),
        check_cfg_mode: d.check_cfg_mode.as_ref().map(|v| *v.get_ref()),
        c1_read_write_required: required.0,
        c2_read_write_required: required.1,
        alarms: d
            .alarms
            .as_ref()
            .map(|a| super::dp_timing::alarms(cx, a.get_ref())),
    })
}

/// The class 2 channel: each value within the range the keyword schema
/// gives its keyword, and the lengths 0 (none) or at least the least a
/// class 2 master works with (C2_Max_Data_Len 48, Max_Initiate_PDU_Length
/// 52: the GSD specification's ranges, FIELDBUS-NOTES §3).
fn class2(cx: &mut Checker, c2: &raw::Dpv1Class2) -> Option<Dpv1Class2> {
    let zero_or = |cx: &mut Checker, v: &Spanned<u8>, keyword: &str, least: i64| match *v.get_ref()
    {
        0 => Some(0),
        _ => cx.gsd_number_from(v, keyword, least, keyword),
    };
    Some(Dpv1Class2 {
        max_data_len: zero_or(cx, &c2.max_data_len, "C2_Max_Data_Len", 48)?,
        response_timeout: cx.gsd_number(
            &c2.response_timeout,
            "C2_Response_Timeout",
            "C2_Response_Timeout",
        )?,
        // A class 2 channel the card offers has a connection at least.
        max_count_channels: cx.gsd_number_from(
            &c2.max_count_channels,
            "C2_Max_Count_Channels",
            1,
            "C2_Max_Count_Channels",
        )?,
        max_initiate_pdu_length: zero_or(
            cx,
            &c2.max_initiate_pdu_length,
            "Max_Initiate_PDU_Length",
            52,
        )?,
    })
}

/// W107: PI requires I&M, read over the class 2 channel, of DPV1 slaves
/// given a new ident number and certified after 1 October 2005 (PI, I&M
/// Functions test specification, order 2.392); E143: I&M without the class
/// 2 channel it is read over.
fn identification_and_maintenance(cx: &mut Checker, d: &raw::Dpv1, near: Range<usize>) {
    if d.ident_maintenance == Some(true) && d.c2.is_none() {
        cx.push(
            Diagnostic::error(
                "E143",
                "I&M is read over the DPV1 class 2 channel, which the description does not give",
            )
            .at(near)
            .label("ident_maintenance without c2")
            .help("add [profibus.dpv1.c2] with the channel's lengths, or drop ident_maintenance"),
        );
    } else if d.ident_maintenance.is_none() {
        cx.push(
            Diagnostic::warning("W107", "a DPV1 slave that does not say whether it has I&M")
                .at(near)
                .label("no ident_maintenance")
                .help("PI requires I&M (read over the class 2 channel) of DPV1 slaves with an ident number assigned and certified after 1 October 2005: set ident_maintenance = true with [profibus.dpv1.c2], or = false (and mark it under [choices] if the manual does not say)"),
        );
    }
}

/// The DPV1 status bytes first (a DPV1 slave's User_Prm_Data starts with
/// them), then one block per group of mappings in telegram order: one
/// parameter per entry of its set's type, numbered from 1; then a
/// gateway's parameters, as [`gateway::place`] places them. Sets with
/// choices get a PrmText each, numbered from 1 in the same order.
fn user_prm(
    cx: &mut Checker,
    p: &raw::Profibus,
    (dpv1, stated): (Option<&Dpv1>, Option<super::dp_params::Constant>),
    (mappings, set_spans): (&Mappings, &SetSpans),
    gateway: Option<&gateway::Lowered>,
) -> UserPrm {
    let constant = match stated {
        Some((bytes, _)) => bytes,
        None => dpv1.map_or_else(Vec::new, |d| d.status_bytes.to_vec()),
    };
    let mut ids = 1..=u16::MAX;
    let mut text_ids = 1..=u16::MAX;
    let card = super::dp_params::lower(cx, &p.parameters, (&mut ids, &mut text_ids), 0);
    let mut texts: Vec<PrmText> = card.texts().collect();
    let sets: Vec<PrmText> = mappings
        .sets()
        .filter(|s| s.allowed.choices().is_some() && in_user_prm(s))
        .zip(&mut text_ids)
        .map(|(s, id)| PrmText {
            id,
            of: PrmTextOf::Set(s.key),
        })
        .collect();
    let text_of = |set| {
        sets.iter()
            .find(|t| t.of == PrmTextOf::Set(set))
            .map(|t| t.id)
    };
    let mut end = constant.len().max(card.end);
    let mut overflowing = None;
    let blocks = mappings
        .groups
        .iter()
        .filter(|g| g.entries().any(|(set, _)| in_user_prm(set)))
        .map(|g| {
            let block_offset = end;
            let params = g
                .entries()
                .filter(|(set, _)| in_user_prm(set))
                .map(|(set, entry)| {
                    let data_type = prm_type(set.entry_type);
                    let offset = end;
                    end += usize::from(data_type.bytes());
                    if end > super::dp_params::max_user_prm_len() {
                        overflowing.get_or_insert(set.key);
                    }
                    PrmParam {
                        id: ids.next().unwrap_or(u16::MAX),
                        offset: saturate(offset),
                        value: PrmValue::Entry(entry.key),
                        data_type,
                        text: text_of(set.key),
                    }
                })
                .collect();
            PrmBlock {
                kind: g.kind,
                offset: saturate(block_offset),
                params,
            }
        })
        .collect();
    if let Some(set) = overflowing {
        let span = set_spans.get(&set).cloned();
        let too_long = telegram_too_long(end, span, "this mapping runs past the limit");
        cx.push(too_long.help("map fewer PZD words or DPV1 indexes"));
    }
    let (gateway, end) = match gateway {
        Some(g) => gateway_params(cx, g, end, &mut ids),
        None => (Vec::new(), end),
    };
    texts.extend(sets);
    if end > super::dp_params::max_user_prm_len() && card.end == end {
        let span = p.parameters.last().map(|p| p.offset.span());
        let too_long = telegram_too_long(end, span, "a parameter runs past the limit");
        cx.push(too_long.help("User_Prm_Data holds at most 237 bytes"));
    }
    UserPrm {
        constant,
        card: card.params,
        card_params: card.facts,
        blocks,
        gateway,
        texts,
        len: saturate(end),
        max_len: max_length(cx, p, end),
    }
}

/// `[profibus.user_prm] max_length`: Max_User_Prm_Data_Len when it says
/// more than the telegram's `len` bytes, never less (E174).
fn max_length(cx: &mut Checker, p: &raw::Profibus, len: usize) -> Option<u8> {
    let max = p.user_prm.as_ref()?.get_ref().max_length.as_ref()?;
    let value: u8 = cx.gsd_number(max, "Max_User_Prm_Data_Len", "max_length")?;
    let needed = u16::try_from(len).unwrap_or(u16::MAX);
    let stated = ("max_length", value.into(), max.span());
    at_least(cx, stated, needed, "the parameter telegram's length");
    Some(value)
}

/// E116: a parameter telegram of `end` bytes, longer than GSD allows.
fn telegram_too_long(end: usize, span: Option<Range<usize>>, label: &str) -> Diagnostic {
    let most = super::dp_params::max_user_prm_len();
    Diagnostic::error(
        "E116",
        format!("the parameter telegram would be {end} bytes; GSD allows {most}"),
    )
    .at_opt(span)
    .label(label)
}

/// E174: a stated limit below what the description needs.
fn at_least(
    cx: &mut Checker,
    (key, value, span): (&str, u16, Range<usize>),
    needed: u16,
    what: &str,
) {
    if value < needed {
        cx.push(
            Diagnostic::error(
                "E174",
                format!("{key} = {value} is less than {what} ({needed})"),
            )
            .at(span)
            .label("too small")
            .help(format!(
                "state at least {needed}, or leave it out: gsdc writes {what}"
            )),
        );
    }
}

/// How User_Prm_Data carries an entry of a set: as its type, GSD naming
/// an Integer8 Signed8.
fn prm_type(entry_type: EntryType) -> PrmType {
    match entry_type {
        EntryType::Unsigned8 => PrmType::Unsigned8,
        EntryType::Integer8 => PrmType::Signed8,
        EntryType::Unsigned16 => PrmType::Unsigned16,
    }
}

/// Whether User_Prm_Data carries a set's entries: all the master sets,
/// but a setting the description keeps from a PROFIBUS master
/// (`per_module.profibus`); none set at the drive.
fn in_user_prm(set: &MappingSet) -> bool {
    set.master_writes() && set.per_module.is_none_or(|f| f.in_user_prm)
}

/// A gateway's parameters from `start` on, within the limit (E116).
fn gateway_params(
    cx: &mut Checker,
    g: &gateway::Lowered,
    start: usize,
    ids: &mut impl Iterator<Item = u16>,
) -> (Vec<PrmParam>, usize) {
    let (params, end) = gateway::place(&g.prm_types, start, ids);
    gateway_prm_decision(cx, &params, end);
    let most = super::dp_params::max_user_prm_len();
    if end > most && start <= most {
        cx.push(
            Diagnostic::error(
                "E116",
                format!(
                    "the parameter telegram would be {end} bytes; GSD allows {}",
                    super::dp_params::max_user_prm_len()
                ),
            )
            .at(g.span.clone())
            .label("the gateway's parameters run past the limit")
            .help("use fewer node numbers, or store the node parameters in fewer bytes (`bits`)"),
        );
    }
    (params, end)
}

/// The gateway's parameters' order and bytes are gsdc's rule (the manual
/// names the parameters, not their bytes): listed in every header, as a
/// drive card's User_Prm_Data is.
fn gateway_prm_decision(cx: &mut Checker, params: &[PrmParam], end: usize) {
    let Some(first) = params.first() else {
        return;
    };
    let nodes_from = params.get(1).map_or(end, |p| usize::from(p.offset));
    cx.layout(
        "profibus User_Prm_Data",
        format!(
            "the node count at byte {}, each node's input and output words at bytes {nodes_from}-{}, in the order of the node table, no gaps; bit areas share a byte",
            first.offset,
            end.saturating_sub(1)
        ),
        files::GATEWAY_USER_PRM_LAYOUT_REASON,
    );
}

/// An offset or length past what a telegram may hold has been reported
/// (E116); the plan keeps the largest value instead of a wrapped one.
fn saturate(value: usize) -> u16 {
    u16::try_from(value).unwrap_or(u16::MAX)
}

/// The device-related block's header byte holds its length, header
/// included, in bits 5-0 (bits 7-6 are 00 for device-related): at most 63
/// bytes (IEC 61158-6-3, Ext_Diag_Data), well within Max_Diag_Data_Len.
const MAX_DEVICE_DIAG_BLOCK: i64 = 0x3F;

fn diagnosis(cx: &mut Checker, d: &Spanned<raw::Diagnosis>) -> Option<Diagnosis> {
    let raw = d.get_ref();
    let length: u8 = cx.spanned_in_range(
        &raw.length,
        1,
        MAX_DEVICE_DIAG_BLOCK,
        "the diagnosis length",
    )?;
    let bits = (i64::from(length) - 1) * 8;
    let mut constants = Scope::default();
    let mut types = Scope::default();
    let mut areas: Vec<DiagnosisArea> = raw
        .areas
        .iter()
        .filter_map(|a| diagnosis_area(cx, a, bits, (&mut constants, &mut types)))
        .collect();
    let taken: Vec<String> = areas
        .iter()
        .flat_map(|a| ["first", "last"].map(|s| format!("{}_{s}", a.ident.snake())))
        .collect();
    super::telegram::apart_in_c(taken, areas.iter_mut().map(|a| &mut a.values));
    let mut seen = std::collections::BTreeSet::new();
    let mut lowered = Vec::new();
    for b in &raw.bits {
        // A bit may have a text while set and another while clear.
        if !seen.insert((*b.bit.get_ref(), b.clear)) {
            let when = if b.clear { " (clear)" } else { "" };
            cx.duplicate(
                format!("diagnosis bit {}{when}", b.bit.get_ref()),
                b.bit.span(),
            );
            continue;
        }
        lowered.extend(diagnosis_bit(cx, b, bits));
    }
    let info = raw
        .info
        .as_ref()
        .map(|i| cx.text(i, None, "the diagnosis' info"));
    let bytes = diagnosis_bytes(cx, &raw.bytes, length);
    Some(Diagnosis {
        length,
        areas,
        bits: lowered,
        info,
        bytes,
    })
}

/// `[[profibus.diagnosis_types]]`: each type once (E105), its areas and
/// bits within the longest device-related block.
fn diagnosis_types(cx: &mut Checker, given: &[raw::DiagnosisType]) -> Vec<DiagnosisType> {
    let bits = (MAX_DEVICE_DIAG_BLOCK - 1) * 8;
    let mut seen = std::collections::BTreeSet::new();
    let mut lowered = Vec::new();
    for t in given {
        let id = *t.id.get_ref();
        if !seen.insert(id) {
            cx.duplicate(format!("diagnosis type {id}"), t.id.span());
            continue;
        }
        let (mut constants, mut types) = (Scope::default(), Scope::default());
        lowered.push(DiagnosisType {
            id,
            areas: t
                .areas
                .iter()
                .filter_map(|a| diagnosis_area(cx, a, bits, (&mut constants, &mut types)))
                .collect(),
            bits: t
                .bits
                .iter()
                .filter_map(|b| diagnosis_bit(cx, b, bits))
                .collect(),
        });
    }
    lowered
}

/// The device-related block the types' areas and bits need: the header
/// and every byte up to their last bit.
fn types_diag_len(types: &[DiagnosisType]) -> Option<u8> {
    let areas = types
        .iter()
        .flat_map(|t| t.areas.iter().map(|a| a.last_bit));
    let bits = types.iter().flat_map(|t| t.bits.iter().map(|b| b.bit));
    let last = areas.chain(bits).max()?;
    // Within the longest block, which lowering checked.
    Some((last / 8 + 2) as u8)
}

/// `Unit_Diag_Bit`: a bit within the block, its text for the GSD.
fn diagnosis_bit(cx: &mut Checker, b: &raw::dp::DiagnosisBit, bits: i64) -> Option<DiagnosisBit> {
    let bit = *b.bit.get_ref();
    if i64::from(bit) >= bits {
        cx.push(
            Diagnostic::error("E115", format!("bit {bit} is not within the diagnosis"))
                .at(b.bit.span())
                .label(format!("the device bytes hold bits 0..{bits}"))
                .help("bit 0 is the first byte after the header; raise the length or move the bit"),
        );
        return None;
    }
    let limit = crate::gsd::keyword_max_len("Unit_Diag_Bit");
    Some(DiagnosisBit {
        bit,
        text: cx.text(&b.text, Some(limit), "diagnosis text"),
        clear: b.clear,
    })
}

/// Each byte the description names, within the block after its header
/// (E101) and named once (E105), in the order of the bytes.
fn diagnosis_bytes(
    cx: &mut Checker,
    given: &[raw::DiagnosisByte],
    length: u8,
) -> Vec<(u8, crate::ir::Text)> {
    let header = STANDARD_DIAG_BYTES;
    let last = header + length - 1;
    let mut bytes: Vec<(u8, crate::ir::Text)> = Vec::new();
    for b in given {
        let at = *b.byte.get_ref();
        if !(header + 1..=last).contains(&at) {
            cx.push(
                Diagnostic::error("E101", format!("byte {at} is not in the device-related block"))
                    .at(b.byte.span())
                    .label(format!("the block's bytes after its header are {} to {last}", header + 1))
                    .help(format!("bytes are counted from the diagnosis' first: 0 to {} the standard diagnosis, {header} the header", header - 1)),
            );
            continue;
        }
        let text = cx.text(&b.text, None, "a diagnosis byte's text");
        if bytes.iter().any(|(known, _)| *known == at) {
            cx.duplicate(format!("diagnosis byte {at}"), b.byte.span());
            continue;
        }
        bytes.push((at, text));
    }
    bytes.sort_by_key(|(at, _)| *at);
    bytes
}

/// An area named after its bits: `BITS_8_15` and `Bits8To15`.
fn diagnosis_area(
    cx: &mut Checker,
    a: &raw::DiagnosisArea,
    bits: i64,
    (constants, types): (&mut Scope, &mut Scope),
) -> Option<DiagnosisArea> {
    let range = a.bit.get_ref();
    if bits == 0
        || range.first < 0
        || range.last < range.first
        || range.last >= bits
        || range.last - range.first >= MAX_DIAG_AREA_BITS
    {
        cx.push(
            Diagnostic::error("E115", format!("bits {}..={} are not within the diagnosis", range.first, range.last))
                .at(a.bit.span())
                .label(format!("the device bytes hold bits 0..{bits}"))
                .help(format!("bit 0 is the first byte after the header; an area spans at most {MAX_DIAG_AREA_BITS} bits")),
        );
        return None;
    }
    if a.values.is_empty() {
        cx.push(
            Diagnostic::error("E125", "a diagnosis area without values")
                .at(a.bit.span())
                .label("no text for any value of these bits")
                .help("give each value a text: values = [{ value = 0x34, text = \"...\" }]; or drop the area"),
        );
        return None;
    }
    let max_value = (1i64 << (range.last - range.first + 1)) - 1;
    // Checked above: 0 <= first <= last < bits <= 8 * 243.
    let (first, last) = (range.first as u16, range.last as u16);
    let (constant, type_name) = if first == last {
        let bit = Ident::of(&["bit", &first.to_string()]);
        (bit.clone(), bit)
    } else {
        let (f, l) = (first.to_string(), last.to_string());
        (
            Ident::of(&["bits", &f, &l]),
            Ident::of(&["bits", &f, "to", &l]),
        )
    };
    let ident = types.unique(type_name, first);
    Some(DiagnosisArea {
        first_bit: first,
        last_bit: last,
        ident: constants.unique(constant, first),
        values: value_set(cx, ident, &a.values, (0, max_value), Some(GSD_NAME_LEN)),
    })
}

/// `[profibus.vendor_keywords]`: each a name the GSD specification does not
/// have (E189), with a number the GSD's unsigned numbers hold or a string
/// as long as the longest string keyword (`Info_Text`) may be.
fn vendor_keywords(
    cx: &mut Checker,
    given: &BTreeMap<Spanned<String>, Spanned<raw::VendorValue>>,
) -> Vec<(String, String)> {
    let mut keywords: Vec<(String, String)> = Vec::new();
    for (name, value) in given {
        let what = format!("profibus.vendor_keywords.{}", name.get_ref());
        // A GSD's keywords are read without regard to case.
        if keywords
            .iter()
            .any(|(k, _)| k.eq_ignore_ascii_case(name.get_ref()))
        {
            cx.duplicate(format!("vendor keyword {}", name.get_ref()), name.span());
            continue;
        }
        let Some(name) = vendor_keyword_name(cx, name) else {
            continue;
        };
        let written = match value.get_ref() {
            raw::VendorValue::Number(n) => cx
                .in_range::<u32>(*n, 0, u32::MAX.into(), value.span(), &what)
                .map(|n| n.to_string()),
            raw::VendorValue::Text(text) => {
                let limit = crate::gsd::keyword_max_len("Info_Text");
                cx.check_gsd_string(text, value.span(), limit, &what);
                Some(format!("\"{text}\""))
            }
        };
        keywords.extend(written.map(|w| (name, w)));
    }
    keywords
}

/// The longest vendor keyword: shorter than the schema's lookup key.
const MAX_VENDOR_KEYWORD: usize = 47;

fn vendor_keyword_name(cx: &mut Checker, name: &Spanned<String>) -> Option<String> {
    let text = name.get_ref();
    let Some((label, help)) = vendor_keyword_problem(text) else {
        return Some(text.clone());
    };
    cx.push(
        Diagnostic::error("E189", format!("`{text}` is not a vendor keyword"))
            .at(name.span())
            .label(label)
            .help(help),
    );
    None
}

/// Why `name` cannot be a vendor keyword (E189): not a keyword's name, or
/// one of the GSD specification's; `None` when it can.
pub(crate) fn vendor_keyword_problem(name: &str) -> Option<(&'static str, String)> {
    let shaped = name.len() <= MAX_VENDOR_KEYWORD
        && name.starts_with(|c: char| c.is_ascii_alphabetic())
        && name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '.');
    if !shaped {
        return Some(("not a keyword's name", format!("a keyword is an ASCII letter, then letters, digits, `_` or `.`, at most {MAX_VENDOR_KEYWORD} characters")));
    }
    let spelling = crate::gsd::schema::resolve(name).spelling?;
    Some(("a GSD keyword", format!("{spelling} is the specification's: state it with the description's key for it, or leave it to gsdc")))
}

#[cfg(test)]
mod tests {
    /// md810dp with its diagnosis bytes as `bytes`.
    fn with_bytes(bytes: &str) -> crate::Diagnostics {
        let text = include_str!("../../descriptions/md810dp.toml");
        let start = text.find("bytes = [\n").expect("md810dp names its bytes");
        let end = start + text[start..].find("\n]\n").unwrap() + 3;
        let text = format!("{}bytes = {bytes}\n{}", &text[..start], &text[end..]);
        crate::testing::load("md810dp.toml", &text).1
    }

    fn errors(d: &crate::Diagnostics) -> Vec<(&'static str, String)> {
        d.errors().map(|e| (e.code, e.message.clone())).collect()
    }

    /// A draft's Info_Text is the notice and as much of the info as fits
    /// GSD's 256 characters, cut at a word.
    #[test]
    fn the_draft_notice_keeps_info_text_within_the_gsds_limit() {
        let long = crate::ir::Text::english("word ".repeat(60).trim_end());
        let text = super::info_text(Some(&long), 0x0810, true).unwrap();
        assert!(text.starts_with("DRAFT, not for release: Ident_Number 0x0810 is a placeholder"));
        assert!(text.ends_with(" word..."), "{text}");
        let limit = crate::gsd::keyword_max_len("Info_Text");
        assert_eq!(limit, 256);
        assert!(text.chars().count() <= limit, "{}", text.len());
        assert_eq!(
            super::info_text(Some(&long), 0x0810, false).unwrap(),
            long.en
        );
        assert_eq!(
            super::info_text(None, 0x0810, true).unwrap(),
            "DRAFT, not for release: Ident_Number 0x0810 is a placeholder, not assigned by PI."
        );
    }

    /// The bytes after the header are 7 and 8 of a 3-byte block: byte 6 is
    /// the header, 9 past the block; a byte named twice is one too many.
    #[test]
    fn diagnosis_bytes_are_those_after_the_header() {
        let ir_text = |b: &str| errors(&with_bytes(b));
        assert_eq!(
            ir_text("[{ byte = 7, text = \"x\" }, { byte = 8, text = \"y\" }]"),
            []
        );
        for outside in [6, 9] {
            assert_eq!(
                ir_text(&format!("[{{ byte = {outside}, text = \"x\" }}]")),
                [(
                    "E101",
                    format!("byte {outside} is not in the device-related block")
                )]
            );
        }
        assert_eq!(
            ir_text("[{ byte = 7, text = \"x\" }, { byte = 7, text = \"y\" }]"),
            [("E105", "diagnosis byte 7 is given twice".to_string())]
        );
    }
}
