//! The PROFINET part: identity, the device access point, the selectable
//! modules and the parameter records.

use super::checks::Checker;
use crate::description::{self as raw, ModulePkw};
use crate::diag::Diagnostic;
use crate::ir::profinet::{Date, Module, ModuleKind, ParameterRecord, Profinet};
use crate::ir::{Layout, MappingKind, MappingSet, PkwKind, Telegram};
use std::collections::BTreeSet;
use toml::Spanned;

/// The GSDML versions gsdc writes: it emits nothing a version lacks.
const SUPPORTED_VERSIONS: [&str; 1] = ["2.32"];
const DEFAULT_VERSION: &str = "2.32";
/// Record indexes 0..0x7FFF are the vendor's (IEC 61158-6-10).
const MAX_VENDOR_RECORD_INDEX: i64 = 0x7FFF;
/// Standard telegram 1 has two words each way.
const STANDARD_TELEGRAM_1_WORDS: u8 = 2;

pub fn lower(
    cx: &mut Checker,
    p: &Spanned<raw::Profinet>,
    device: &raw::Device,
    telegram: &Telegram,
    mappings: &[MappingSet],
) -> Option<Profinet> {
    let p = p.get_ref();
    let gsdml_version = version(cx, p.gsdml_version.as_ref())?;
    let date = date(cx, &p.date)?;
    let file_vendor = file_name_part(
        cx,
        p.file_vendor.as_ref().unwrap_or(&device.vendor),
        "profinet.file_vendor",
    );
    let family = file_name_part(cx, &device.family, "device.family");
    placeholder_warning(cx, &p.vendor_id, "vendor ID");
    placeholder_warning(cx, &p.device_id, "device ID");
    Some(Profinet {
        file_name: format!(
            "GSDML-V{gsdml_version}-{file_vendor}-{family}-{}.xml",
            date.compact()
        ),
        gsdml_version,
        date,
        vendor_id: *p.vendor_id.get_ref().value.get_ref(),
        vendor_id_placeholder: p.vendor_id.get_ref().placeholder,
        device_id: cx.spanned_in_range(&p.device_id.get_ref().value, 1, 0xFFFF, "device_id")?,
        device_id_placeholder: p.device_id.get_ref().placeholder,
        info: p.info.as_ref().map(|i| cx.text(i, None, "profinet.info")),
        dns_name: dns_name(cx, &p.dns_name),
        ports: cx.spanned_in_range(&p.ports, 1, 16, "ports")?,
        min_device_interval: cx.spanned_in_range(
            &p.min_device_interval,
            1,
            4096,
            "min_device_interval",
        )?,
        modules: modules(cx, p, telegram),
        records: records(cx, &p.records, mappings),
    })
}

fn version(cx: &mut Checker, v: Option<&Spanned<String>>) -> Option<String> {
    let Some(v) = v else {
        return Some(DEFAULT_VERSION.to_string());
    };
    if SUPPORTED_VERSIONS.contains(&v.get_ref().as_str()) {
        return Some(v.get_ref().clone());
    }
    cx.push(
        Diagnostic::error("E130", format!("gsdc does not write GSDML {}", v.get_ref()))
            .at(v.span())
            .label("unsupported version")
            .help(format!("write one of: {}", SUPPORTED_VERSIONS.join(", "))),
    );
    None
}

fn date(cx: &mut Checker, d: &Spanned<toml::value::Datetime>) -> Option<Date> {
    match (d.get_ref().date, d.get_ref().time, d.get_ref().offset) {
        (Some(date), None, None) => Some(Date {
            year: date.year,
            month: date.month,
            day: date.day,
        }),
        _ => {
            cx.push(
                Diagnostic::error("E131", "the GSDML date must be a date without a time")
                    .at(d.span())
                    .label("not a plain date")
                    .help("write a TOML date like date = 2023-08-30"),
            );
            None
        }
    }
}

/// Vendor and family as they go into the file name: letters, digits, `_`
/// and `.`, since `-` separates the name's parts.
fn file_name_part(cx: &mut Checker, part: &Spanned<String>, what: &str) -> String {
    let text = part.get_ref();
    let valid = !text.is_empty()
        && text
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '.');
    if !valid {
        cx.push(
            Diagnostic::error("E133", format!("`{text}` cannot be part of a GSDML file name"))
                .at(part.span())
                .label("not letters and digits")
                .help(format!("GSDML-V<version>-<Vendor>-<Family>-<date>.xml takes letters, digits and `_`; set {what}")),
        );
    }
    text.to_string()
}

fn placeholder_warning(cx: &mut Checker, id: &Spanned<raw::IdentNumber>, what: &str) {
    if id.get_ref().placeholder {
        cx.push(
            Diagnostic::warning("W102", format!("PROFINET {what} 0x{:04X} is a placeholder, not assigned by PI", id.get_ref().value.get_ref()))
                .at(id.span())
                .label("placeholder")
                .help("use the vendor ID PI assigned and the device ID the vendor assigned before shipping"),
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

fn modules(cx: &mut Checker, p: &raw::Profinet, telegram: &Telegram) -> Vec<Module> {
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
    if p.standard_telegram_1 {
        modules.push(standard_telegram_1(cx, p, telegram));
    }
    for &pkw in pkw_choices {
        for &pzd_words in &lengths {
            let layout = Layout { pkw, pzd_words };
            let pkw_text = if pkw { "PKW + " } else { "" };
            modules.push(Module {
                kind: ModuleKind::Pzd,
                name: format!("{pkw_text}{pzd_words} PZD"),
                ident: Module::ident_for(ModuleKind::Pzd, layout),
                layout,
            });
        }
    }
    modules
}

fn standard_telegram_1(cx: &mut Checker, p: &raw::Profinet, telegram: &Telegram) -> Module {
    if telegram.pzd_words < STANDARD_TELEGRAM_1_WORDS {
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
    let layout = Layout {
        pkw: false,
        pzd_words: STANDARD_TELEGRAM_1_WORDS,
    };
    Module {
        kind: ModuleKind::StandardTelegram1,
        name: "Standard telegram 1".into(),
        ident: Module::ident_for(ModuleKind::StandardTelegram1, layout),
        layout,
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

/// One record per kind of mapping the description has: PZD out, PZD in,
/// DPV1 indexes, settings; indexes 1, 2, 3, 4 unless the description says otherwise.
fn records(
    cx: &mut Checker,
    indexes: &raw::RecordIndexes,
    mappings: &[MappingSet],
) -> Vec<ParameterRecord> {
    let kinds = [
        (MappingKind::PzdOut, &indexes.pzd_out, 1),
        (MappingKind::PzdIn, &indexes.pzd_in, 2),
        (MappingKind::Dpv1Index, &indexes.dpv1_index, 3),
        (MappingKind::Setting, &indexes.settings, 4),
    ];
    let mut used = BTreeSet::new();
    kinds
        .into_iter()
        .filter_map(|(kind, given, default)| {
            let sets: Vec<usize> = (0..mappings.len())
                .filter(|&i| mappings[i].kind == kind)
                .collect();
            if sets.is_empty() {
                return None;
            }
            let index = match given {
                Some(i) => cx.spanned_in_range(i, 1, MAX_VENDOR_RECORD_INDEX, "a record index")?,
                None => default,
            };
            if !used.insert(index) {
                cx.push(
                    Diagnostic::error("E105", format!("record index {index} is used twice"))
                        .at_opt(given.as_ref().map(Spanned::span))
                        .label("used by another record")
                        .help("give each record its own index under [profinet.records]"),
                );
            }
            Some(ParameterRecord { kind, index, sets })
        })
        .collect()
}
