//! The Rust emitter: IR to the firmware layout (`<stem>_layout.rs`) through
//! `templates/layout.rs.jinja`, and the support module every layout is built
//! from (`gsdc_support.rs`, from `templates/support/`), the same for every
//! description, so a build with several layouts writes it once.
//!
//! Every name comes from the IR; the context carries finished pieces of Rust
//! (identifiers, literals, doc lines) so the template only arranges them.

mod gateway;
mod tables;

use super::{
    bit_range, capitalised, group_doc, hex16, hex8, mapping_literal, range_doc, Artifact,
    ArtifactKind,
};
use crate::ir::mapping::{Allowed, Holds, MappingGroup, MappingSet};
use crate::ir::profibus::{Diagnosis, Profibus};
use crate::ir::profinet::RecordReading;
use crate::ir::profinet::{self, Profinet};
use crate::ir::{Bus, CyclicModule, Direction, Ir, PkwKind, Telegram, ValueSet, Word};
use serde::Serialize;

const TEMPLATE: &str = include_str!("../../templates/layout.rs.jinja");

/// The support module's file, and its parts: `pub mod name;` in the first
/// is replaced by the part's text.
pub const SUPPORT_FILE_NAME: &str = "gsdc_support.rs";
const SUPPORT: &str = include_str!("../../templates/support/mod.rs");
const SUPPORT_PARTS: [(&str, &str); 6] = [
    (
        "pkw_pke_ind_pwe",
        include_str!("../../templates/support/pkw_pke_ind_pwe.rs"),
    ),
    (
        "pkw_station_command",
        include_str!("../../templates/support/pkw_station_command.rs"),
    ),
    (
        "pkw_profidrive",
        include_str!("../../templates/support/pkw_profidrive.rs"),
    ),
    (
        "diagnosis",
        include_str!("../../templates/support/diagnosis.rs"),
    ),
    (
        "gateway",
        include_str!("../../templates/support/gateway.rs"),
    ),
    ("device", include_str!("../../templates/support/device.rs")),
];

#[derive(Serialize)]
struct Context<'a> {
    generator: &'static str,
    source: &'a str,
    fingerprint: String,
    /// What the layout holds, as `//` lines.
    summary: Vec<String>,
    /// Header comment lines: translations and decisions, wrapped.
    notes: Vec<String>,
    pkw_module: Option<&'static str>,
    telegrams: Vec<TelegramAlias>,
    words: Vec<WordModule>,
    groups: Vec<Group>,
    profibus: Option<ProfibusItems>,
    profinet: Option<ProfinetItems>,
    gateway: Option<gateway::Items>,
    /// The device tables, finished.
    tables: String,
}

#[derive(Serialize)]
struct TelegramAlias {
    name: String,
    doc: Vec<String>,
    /// `PkwTelegram` or `PzdTelegram`.
    generic: &'static str,
    pzd_words: u8,
    bytes: u16,
}

#[derive(Serialize)]
struct WordModule {
    module: &'static str,
    doc: String,
    fields: Vec<Field>,
}

#[derive(Serialize)]
struct Field {
    name: String,
    doc: String,
    first: u8,
    last: u8,
    values: Option<ValueEnum>,
}

#[derive(Serialize)]
struct ValueEnum {
    name: String,
    doc: String,
    variants: Vec<Variant>,
}

#[derive(Serialize)]
struct Variant {
    name: String,
    doc: String,
    value: i64,
}

/// A group of mappings: a module with their table, the offset in
/// User_Prm_Data and the PROFINET record.
#[derive(Serialize)]
struct Group {
    module: &'static str,
    doc: String,
    sets: Vec<SetAllowed>,
    entries: Vec<Entry>,
    user_prm_offset: Option<u16>,
    /// The entries User_Prm_Data carries, by place, when not all
    /// (`UserPrm::partial`); empty when it carries all.
    user_prm_entries: Vec<usize>,
    record_index: Option<u16>,
    /// How `decode_record` reads the record: `read_record` (every entry) or
    /// `read_record_prefix` (a module's PZD record holds its words).
    record_reader: &'static str,
    /// DPV1 indexes: the bytes each index's record holds.
    record_length: Option<u8>,
    /// Settings whose value each PROFINET module fixes.
    fixed: Vec<Fixed>,
}

/// The value each module fixes for a setting, by module ident number.
#[derive(Serialize)]
struct Fixed {
    constant: String,
    doc: String,
    /// Module ident constants and values.
    modules: Vec<(String, u16)>,
}

#[derive(Serialize)]
struct SetAllowed {
    /// The constant's name.
    allowed: String,
    doc: String,
    choices: Option<ValueEnum>,
    min: String,
    max: String,
}

#[derive(Serialize)]
struct Entry {
    name: String,
    number: u8,
    default: String,
    default_comment: String,
    parameter: String,
    parameter_comment: String,
    allowed: String,
}

#[derive(Serialize)]
struct ProfibusItems {
    file_name: String,
    ident_placeholder: bool,
    ident_number: String,
    ppos: Vec<Ppo>,
    user_prm_len: u16,
    dpv1_status: Option<String>,
    diagnosis: Option<DiagnosisItems>,
}

#[derive(Serialize)]
struct DiagnosisItems {
    /// Bytes of the block, the header included; also the header byte.
    len: u8,
    areas: Vec<DiagAreaItem>,
    /// What the description says of the block and of its bytes, a
    /// paragraph each.
    said: Vec<String>,
}

#[derive(Serialize)]
struct DiagAreaItem {
    constant: String,
    doc: String,
    first: u16,
    last: u16,
    values: ValueEnum,
}

#[derive(Serialize)]
struct Ppo {
    constant: String,
    name: String,
    config: String,
    config_len: usize,
}

#[derive(Serialize)]
struct ProfinetItems {
    file_name: String,
    vendor_id: String,
    vendor_placeholder: bool,
    device_id: String,
    device_placeholder: bool,
    dap_ident: String,
    interface_subslot: String,
    first_port_subslot: String,
    ports: usize,
    module_slot: u16,
    modules: Vec<PnModule>,
}

#[derive(Serialize)]
struct PnModule {
    name: String,
    constant: String,
    ident: String,
    /// PROFIdrive's API, access point and data subslot, for a profile telegram.
    profidrive: Option<ProfidriveItems>,
}

#[derive(Serialize)]
struct ProfidriveItems {
    api: String,
    access_point_subslot: u16,
    access_point_ident: String,
    data_subslot: u16,
}

/// The firmware layout of a description.
pub fn emit(ir: &Ir) -> String {
    render(TEMPLATE, ir).expect("the layout template renders every IR (tested)")
}

fn render(template: &str, ir: &Ir) -> Result<String, minijinja::Error> {
    super::code_templates()
        .template_from_str(template)?
        .render(context(ir))
}

/// `gsdc_support.rs`: the support code as one module, `gsdc_support`, with
/// its parts inlined as modules of their own. Firmware includes it once at
/// the crate root; the layouts refer to it as `crate::gsdc_support`.
pub fn support_module() -> Artifact {
    let mut text = format!(
        "// @generated by {}; do not edit.\n\
         // The support code of gsdc's firmware layouts. Include it once at the\n\
         // crate root: include!(concat!(env!(\"OUT_DIR\"), \"/gsdc_support.rs\"));\n\
         \n\
         // A crate uses only the parts its layouts need.\n\
         #[allow(dead_code)]\n\
         pub mod gsdc_support {{\n",
        crate::GENERATOR
    );
    for line in SUPPORT.lines() {
        let part = line
            .strip_prefix("pub mod ")
            .and_then(|l| l.strip_suffix(';'))
            .and_then(|name| SUPPORT_PARTS.iter().find(|(n, _)| *n == name));
        match part {
            Some((name, part)) => {
                text.push_str(&format!("    pub mod {name} {{\n"));
                indent(&mut text, part, 2);
                text.push_str("    }\n");
            }
            None => indent(&mut text, line, 1),
        }
    }
    text.push_str("}\n");
    Artifact {
        kind: ArtifactKind::RustSupport,
        file_name: SUPPORT_FILE_NAME.to_string(),
        contents: text.into_bytes(),
    }
}

/// Appends `text`'s lines indented by `levels` of four spaces; blank lines
/// stay empty, as rustfmt leaves them.
fn indent(out: &mut String, text: &str, levels: usize) {
    for line in text.lines() {
        if !line.is_empty() {
            out.push_str(&"    ".repeat(levels));
            out.push_str(line);
        }
        out.push('\n');
    }
}

/// `md810dp.toml` gives `md810dp_layout.rs`, `mv810-pnet02.toml`
/// `mv810_pnet02_layout.rs`: `_` for `-`, as Rust names its source files.
pub fn file_name(ir: &Ir) -> String {
    format!("{}_layout.rs", super::layout_stem(ir))
}

/// The header's paragraph: "Firmware layout of Inovance MD810DP: the cyclic
/// telegrams, ...", wrapped to rustfmt's width after `// `.
fn summary(ir: &Ir) -> Vec<String> {
    let text = format!(
        "Firmware layout of {} {}: {}, from the same description as the device \
         files. Multi-byte values on the bus are big-endian. no_std, no unsafe, \
         no dependencies. It is built from the support module gsdc writes beside \
         it, `gsdc_support.rs`, which the crate includes once at its root, \
         whatever the number of layouts. What each byte means on the wire: \
         docs/wire-format.md in gsdc's repository.",
        ir.device.vendor,
        ir.device.model,
        super::layout_contents(ir)
    );
    super::wrap_words(&text, 77)
}

fn context(ir: &Ir) -> Context<'_> {
    Context {
        generator: crate::GENERATOR,
        source: &ir.source_name,
        fingerprint: ir.fingerprint.to_string(),
        summary: summary(ir),
        notes: notes(ir),
        pkw_module: match ir.telegram.pkw {
            PkwKind::None => None,
            PkwKind::PkeIndPwe => Some("pkw_pke_ind_pwe"),
            PkwKind::StationCommandAddressValue => Some("pkw_station_command"),
            PkwKind::Profidrive => Some("pkw_profidrive"),
        },
        telegrams: telegrams(ir),
        words: Direction::BOTH
            .iter()
            .filter_map(|&dir| Some(word_module(dir, ir.telegram.word(dir)?)))
            .collect(),
        profibus: ir.profibus.as_ref().map(profibus_items),
        profinet: ir.profinet.as_ref().map(profinet_items),
        gateway: ir
            .gateway
            .as_ref()
            .zip(ir.profibus.as_ref())
            .map(|(g, p)| gateway::items(g, p)),
        groups: ir.mappings.groups.iter().map(|g| group(ir, g)).collect(),
        tables: tables::render(&super::tables::tables(ir)),
    }
}

/// Header notes in lines that keep the comment within 80 columns; a note's
/// continuation lines are indented.
fn notes(ir: &Ir) -> Vec<String> {
    super::header_notes(ir, super::ArtifactKind::RustLayout)
        .iter()
        .flat_map(|note| {
            super::wrap_words(note, 75)
                .into_iter()
                .enumerate()
                .map(|(i, line)| if i == 0 { line } else { format!("  {line}") })
                .collect::<Vec<_>>()
        })
        .collect()
}

// ---------------------------------------------------------------------------
// Telegrams

/// What differs between the two directions of a cyclic telegram.
struct DirectionText {
    /// Of the alias's name.
    suffix: &'static str,
    name: &'static str,
    /// What reads or writes the PKW channel in this direction.
    pkw: &'static str,
    /// The module of the word PZD1 carries, when the description has it.
    word_module: &'static str,
    standard_telegram_1: &'static str,
}

fn direction_text(direction: Direction) -> DirectionText {
    match direction {
        Direction::Out => DirectionText {
            suffix: "Out",
            name: "master to drive",
            pkw: "PkwRequest::decode",
            word_module: "control_word",
            standard_telegram_1: "STW1 and NSOLL_A",
        },
        Direction::In => DirectionText {
            suffix: "In",
            name: "drive to master",
            pkw: "PkwResponse::encode",
            word_module: "status_word",
            standard_telegram_1: "ZSW1 and NIST_A",
        },
    }
}

/// Each PPO type, then each PROFINET module, both ways.
fn telegrams(ir: &Ir) -> Vec<TelegramAlias> {
    ir.cyclic_modules()
        .flat_map(|m| {
            Direction::BOTH
                .iter()
                .map(move |&dir| telegram_alias(&ir.telegram, &m, dir))
        })
        .collect()
}

/// `"PPO1" of MD810DP.GSD`, `PROFINET module "PKW + 12 PZD" ([`PKW_PZD12_IDENT`])`.
fn module_doc(m: &CyclicModule) -> String {
    match m.bus {
        Bus::Profibus => format!("\"{}\" of {}", m.name, m.file_name),
        Bus::Profinet => format!(
            "PROFINET module \"{}\" ([`{}_IDENT`])",
            m.name,
            m.ident.upper_snake()
        ),
    }
}

fn telegram_alias(telegram: &Telegram, m: &CyclicModule, direction: Direction) -> TelegramAlias {
    let dir = direction_text(direction);
    let words = match m.layout.pzd_words {
        1 => "PZD1".to_string(),
        n => format!("PZD1 to PZD{n}"),
    };
    let pzd_doc = match (m.is_profidrive(), telegram.word(direction)) {
        (true, _) => format!("PROFIdrive {}.", dir.standard_telegram_1),
        (false, Some(_)) => format!("{words}; PZD1 is the word of [`{}`].", dir.word_module),
        (false, None) => format!("{words}."),
    };
    let mut doc = vec![format!(
        "{}, {}: {} bytes.",
        module_doc(m),
        dir.name,
        m.layout.bytes()
    )];
    if m.layout.pkw {
        doc.push(format!("The PKW channel: see [`{}`].", dir.pkw));
    }
    doc.push(pzd_doc);
    TelegramAlias {
        name: format!("{}{}", m.ident.camel(), dir.suffix),
        doc,
        generic: if m.layout.pkw {
            "PkwTelegram"
        } else {
            "PzdTelegram"
        },
        pzd_words: m.layout.pzd_words,
        bytes: m.layout.bytes(),
    }
}

// ---------------------------------------------------------------------------
// Control and status words

fn word_module(direction: Direction, word: &Word) -> WordModule {
    let dir = direction_text(direction);
    let fields = word
        .bits
        .iter()
        .map(|b| {
            let bits = bit_range(b.first.into(), b.last.into());
            let name = b.ident.upper_snake();
            let values = b
                .values
                .as_ref()
                .map(|v| value_enum(v, format!("The values of [`{name}`].")));
            let see = values
                .as_ref()
                .map_or_else(String::new, |v| format!("; values in [`{}`]", v.name));
            Field {
                doc: format!("{bits}: {}{see}.", doc_text(&b.name.en)),
                name,
                first: b.first,
                last: b.last,
                values,
            }
        })
        .collect();
    WordModule {
        module: dir.word_module,
        doc: format!("{}, PZD1 {}: its bits.", doc_text(&word.name.en), dir.name),
        fields,
    }
}

fn value_enum(values: &ValueSet, doc: String) -> ValueEnum {
    ValueEnum {
        name: values.ident.camel(),
        doc,
        variants: values
            .choices
            .iter()
            .map(|c| Variant {
                name: c.ident.camel(),
                doc: format!("{}.", doc_text(&c.text.en)),
                value: c.value,
            })
            .collect(),
    }
}

// ---------------------------------------------------------------------------
// Mappings

fn group(ir: &Ir, g: &MappingGroup) -> Group {
    let single = g.sets.len() == 1;
    let record = ir.profinet.as_ref().and_then(|p| p.record(g.kind));
    Group {
        module: g.kind.key(),
        doc: group_doc(g),
        sets: g.sets.iter().map(|set| set_allowed(set, single)).collect(),
        entries: g.sets.iter().flat_map(|set| set_entries(ir, set)).collect(),
        user_prm_offset: ir
            .profibus
            .as_ref()
            .and_then(|p| p.user_prm.block(g.kind))
            .map(|b| b.offset),
        user_prm_entries: ir
            .profibus
            .as_ref()
            .and_then(|p| p.user_prm.partial(g))
            .unwrap_or_default(),
        record_index: record.map(|r| r.index),
        record_reader: match record.map(|r| r.reading) {
            Some(RecordReading::Prefix) => "read_record_prefix",
            _ => "read_record",
        },
        record_length: g.record_length,
        fixed: fixed(ir, g),
    }
}

/// For each set of `g` whose value PROFINET modules fix: every module that
/// carries it, with its value.
fn fixed(ir: &Ir, g: &MappingGroup) -> Vec<Fixed> {
    let Some(profinet) = &ir.profinet else {
        return Vec::new();
    };
    g.sets
        .iter()
        .filter_map(|set| Some((set, profinet.fixed(set.key)?)))
        .map(|(set, fixed)| Fixed {
            constant: format!("FIXED_{}", set.key.first),
            doc: format!(
                "The value of \"{}\" each PROFINET module fixes, by its ident number: the module writes it; the user cannot change it.",
                doc_text(&set.entries[0].name.en)
            ),
            modules: fixed
                .modules
                .iter()
                .map(|(ident, _, value)| (format!("super::{}_IDENT", ident.upper_snake()), *value))
                .collect(),
        })
        .collect()
}

/// A group with one set says "each entry" in its docs; a set of a group of
/// several (the settings) names its one entry.
fn set_allowed(set: &MappingSet, single: bool) -> SetAllowed {
    let holder = if single {
        "each entry".to_string()
    } else {
        doc_text(&set.entries[0].name.en)
    };
    // The name as the description writes it (P43.01, not p43.01); only
    // gsdc's own words are capitalised to begin a sentence.
    let what = format!("What {holder} may hold.");
    let holder = capitalised(&holder);
    let allowed = set.allowed_ident.upper_snake();
    match &set.allowed {
        Allowed::Range { min, max } => SetAllowed {
            doc: range_doc(&holder, set.holds, *min, *max),
            allowed,
            choices: None,
            min: mapping_literal(set.holds, *min),
            max: mapping_literal(set.holds, *max),
        },
        Allowed::Choices(values) => {
            let choices = value_enum(values, what);
            SetAllowed {
                doc: format!("{holder} holds one of the values of [`{}`].", choices.name),
                allowed,
                choices: Some(choices),
                min: String::new(),
                max: String::new(),
            }
        }
    }
}

fn set_entries<'a>(ir: &'a Ir, set: &'a MappingSet) -> impl Iterator<Item = Entry> + 'a {
    // Parameter addresses read best in hex, with the manual's name beside
    // them; a value or a choice is a plain number.
    let is_address = set.holds == Holds::Address;
    let name_of = |address: u16| {
        ir.numbering
            .as_ref()
            .and_then(|n| n.format(address))
            .map_or_else(String::new, |name| format!(" // {name}"))
    };
    set.entries.iter().map(move |e| {
        let default = mapping_literal(set.holds, e.default);
        let default_comment = if is_address {
            name_of(e.default)
        } else {
            String::new()
        };
        Entry {
            name: format!("{:?}", e.name.en),
            number: e.key.number,
            default,
            default_comment,
            parameter: e
                .parameter
                .map_or_else(|| "None".into(), |p| format!("Some({})", hex16(p))),
            parameter_comment: e.parameter.map_or_else(String::new, name_of),
            allowed: set.allowed_ident.upper_snake(),
        }
    })
}

// ---------------------------------------------------------------------------
// Bus constants

fn profibus_items(p: &Profibus) -> ProfibusItems {
    ProfibusItems {
        file_name: p.file_name.clone(),
        ident_placeholder: p.ident_placeholder,
        ident_number: hex16(p.ident_number),
        ppos: p
            .modules
            .iter()
            .map(|m| Ppo {
                constant: m.ident.upper_snake(),
                name: m.name.clone(),
                config: hex_bytes(&m.config),
                config_len: m.config.len(),
            })
            .collect(),
        user_prm_len: p.user_prm.len,
        dpv1_status: p.dpv1.map(|d| hex_bytes(&d.status_bytes)),
        diagnosis: p.diagnosis.as_ref().map(diagnosis_items),
    }
}

/// The device-related diagnosis: an area constant and a value enum for each
/// `Unit_Diag_Area` of the GSD.
fn diagnosis_items(d: &Diagnosis) -> DiagnosisItems {
    let areas = d
        .areas
        .iter()
        .map(|a| {
            let constant = a.ident.upper_snake();
            let values = value_enum(&a.values, format!("The values of [`{constant}`]."));
            DiagAreaItem {
                doc: format!(
                    "{} of the device-related diagnosis: values in [`{}`].",
                    bit_range(a.first_bit, a.last_bit),
                    values.name
                ),
                constant,
                first: a.first_bit,
                last: a.last_bit,
                values,
            }
        })
        .collect();
    DiagnosisItems {
        len: d.length,
        areas,
        said: super::diagnosis_said(d)
            .iter()
            .map(|line| doc_text(line))
            .collect(),
    }
}

fn profinet_items(p: &Profinet) -> ProfinetItems {
    ProfinetItems {
        file_name: p.file_name.clone(),
        vendor_id: hex16(p.vendor_id),
        vendor_placeholder: p.vendor_id_placeholder,
        device_id: hex16(p.device_id),
        device_placeholder: p.device_id_placeholder,
        dap_ident: hex32(profinet::DAP_IDENT),
        interface_subslot: hex16(profinet::INTERFACE_SUBSLOT),
        first_port_subslot: hex16(profinet::FIRST_PORT_SUBSLOT),
        ports: p.ports.len(),
        module_slot: profinet::MODULE_SLOT,
        modules: p
            .modules
            .iter()
            .map(|m| PnModule {
                name: m.name.text.en.clone(),
                constant: m.ident.upper_snake(),
                ident: hex32(m.ident_number),
                profidrive: m.is_profidrive().then(|| ProfidriveItems {
                    api: hex32(profinet::PROFIDRIVE_API),
                    access_point_subslot: profinet::ACCESS_POINT_SUBSLOT,
                    access_point_ident: hex32(profinet::ACCESS_POINT_IDENT),
                    data_subslot: profinet::PROFIDRIVE_DATA_SUBSLOT,
                }),
            })
            .collect(),
    }
}

/// `0xF3, 0xF1`: the inside of an array literal.
fn hex_bytes(bytes: &[u8]) -> String {
    bytes
        .iter()
        .map(|&b| hex8(b))
        .collect::<Vec<_>>()
        .join(", ")
}

/// `0x0000_0202`: eight digits in two groups, as ident numbers are written.
fn hex32(value: u32) -> String {
    format!("0x{:04X}_{:04X}", value >> 16, value & 0xFFFF)
}

/// One line of a doc comment.
fn doc_text(text: &str) -> String {
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

#[cfg(test)]
use crate::pkw::support;

#[cfg(test)]
mod support_tests;

#[cfg(test)]
mod support_gateway_tests;

#[cfg(test)]
mod tests {
    use super::*;

    /// One typo in the template (`t.generik`) fails the rendering instead of
    /// writing a layout without the telegram's type.
    #[test]
    fn a_misspelt_name_in_the_template_is_an_error_not_empty_text() {
        let text = include_str!("../../descriptions/md810dp.toml");
        let ir = crate::testing::load("md810dp.toml", text).0.unwrap();
        assert!(render(TEMPLATE, &ir).is_ok());
        let typo = TEMPLATE.replace("t.generic", "t.generik");
        assert_ne!(typo, TEMPLATE);
        let error = render(&typo, &ir).unwrap_err();
        assert_eq!(error.kind(), minijinja::ErrorKind::UndefinedError);
    }

    /// A timeout is a plain value: its bounds and default in decimal, and
    /// said to be a value, not a parameter address.
    #[test]
    fn a_range_of_plain_values_is_written_in_decimal() {
        let layout = emit(&crate::testing::mv810_with_timeout());
        for line in [
            "/// Communication timeout (P43.24) holds a value from 0 to 60000.\n",
            "min: 0,\n",
            "max: 60000,\n",
            "default: 100,\n",
        ] {
            assert!(layout.contains(line), "{line}\n{layout}");
        }
        assert!(!layout.contains("0xEA60"), "{layout}");
    }

    /// A setting's name keeps its case where the docs name it: P43.01 is
    /// not p43.01.
    #[test]
    fn a_setting_is_named_as_the_description_writes_it() {
        let layout = emit(&crate::testing::mv810_with_timeout());
        assert!(
            layout.contains("/// What Message type (P43.01) may hold.\n"),
            "{layout}"
        );
    }

    #[test]
    fn file_names_are_identifiers() {
        let text = include_str!("../../descriptions/mv810-pnet02.toml");
        let ir = crate::testing::load("mv810-pnet02.toml", text).0.unwrap();
        assert_eq!(file_name(&ir), "mv810_pnet02_layout.rs");
    }

    #[test]
    fn diagnosis_areas_over_the_same_bits_get_their_own_names() {
        let text = include_str!("../../descriptions/md810dp.toml").replace(
            "[[profibus.diagnosis.areas]]",
            "[[profibus.diagnosis.areas]]\nbit = [8, 15]\nvalues = [{ value = 1, text = \"One\" }]\n\n[[profibus.diagnosis.areas]]",
        );
        let ir = crate::testing::load("md810dp.toml", &text).0.unwrap();
        let items = diagnosis_items(ir.profibus.as_ref().unwrap().diagnosis.as_ref().unwrap());
        let names: Vec<_> = items
            .areas
            .iter()
            .map(|a| (a.constant.as_str(), a.values.name.as_str()))
            .collect();
        assert_eq!(
            names,
            [("BITS_8_15", "Bits8To15"), ("BITS_8_15_8", "Bits8To158")]
        );
    }

    #[test]
    fn ident_numbers_in_two_groups() {
        assert_eq!(hex32(0x0000_0202), "0x0000_0202");
        assert_eq!(hex32(0x1234_ABCD), "0x1234_ABCD");
    }
}
