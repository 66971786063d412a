//! The Rust emitter: IR to the firmware layout (`<stem>_layout.rs`) through
//! `templates/layout.rs.jinja`, with the hand-written support code of
//! `templates/*.rs` pasted in verbatim.
//!
//! The context carries finished pieces of Rust (identifiers, literals, doc
//! lines) so the template only arranges them; names come from the
//! description's English texts, made unique within their scope.

use crate::ir::mapping::{Allowed, MappingKind, MappingSet};
use crate::ir::profibus::{Diagnosis, Profibus};
use crate::ir::profinet::{self, ModuleKind, Profinet};
use crate::ir::{Choice, Ir, Layout, PkwKind, Telegram, Word};
use serde::Serialize;
use std::collections::BTreeSet;

const TEMPLATE: &str = include_str!("../../templates/layout.rs.jinja");
const SUPPORT: &str = include_str!("../../templates/support.rs");
const PKW_PKE_IND_PWE: &str = include_str!("../../templates/pkw_pke_ind_pwe.rs");
const PKW_STATION_COMMAND: &str = include_str!("../../templates/pkw_station_command.rs");
const DIAGNOSIS: &str = include_str!("../../templates/diagnosis.rs");

#[derive(Serialize)]
struct Context<'a> {
    generator: &'static str,
    source: &'a str,
    fingerprint: String,
    device: String,
    support: &'static str,
    pkw_support: Option<&'static str>,
    diagnosis_support: Option<&'static str>,
    telegrams: Vec<TelegramStruct>,
    words: Vec<WordModule>,
    groups: Vec<Group>,
    profibus: Option<ProfibusItems>,
    profinet: Option<ProfinetItems>,
}

#[derive(Serialize)]
struct TelegramStruct {
    name: String,
    doc: String,
    /// None when the telegram has no PKW channel.
    pkw_doc: Option<String>,
    pzd_doc: String,
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

/// The mapping sets of one kind: a module with their table, the offset in
/// User_Prm_Data and the PROFINET record.
#[derive(Serialize)]
struct Group {
    module: &'static str,
    doc: &'static str,
    sets: Vec<SetAllowed>,
    entries: Vec<Entry>,
    user_prm_offset: Option<usize>,
    record_index: Option<u16>,
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
    user_prm_len: usize,
    dpv1_status: Option<String>,
    diagnosis: Option<DiagnosisItems>,
}

#[derive(Serialize)]
struct DiagnosisItems {
    /// Bytes of the block, the header included; also the header byte.
    len: u8,
    areas: Vec<DiagAreaItem>,
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
    ppo: u8,
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
    ports: u8,
    module_slot: u16,
    modules: Vec<PnModule>,
}

#[derive(Serialize)]
struct PnModule {
    name: String,
    constant: String,
    ident: String,
}

/// The firmware layout of a description.
pub fn emit(ir: &Ir) -> String {
    let mut env = minijinja::Environment::new();
    env.set_trim_blocks(true);
    env.set_lstrip_blocks(true);
    env.set_keep_trailing_newline(true);
    env.add_template("layout.rs", TEMPLATE)
        .expect("templates/layout.rs.jinja is valid (tested)");
    env.get_template("layout.rs")
        .and_then(|t| t.render(context(ir)))
        .expect("the layout context always renders (tested)")
}

/// `md810dp.toml` gives `md810dp_layout.rs`, `mv810-pnet02.toml`
/// `mv810_pnet02_layout.rs`: `_` for `-`, as Rust names its source files.
pub fn file_name(ir: &Ir) -> String {
    let stem = std::path::Path::new(&ir.source_name)
        .file_stem()
        .map_or_else(
            || ir.source_name.clone(),
            |s| s.to_string_lossy().into_owned(),
        );
    format!("{}_layout.rs", stem.replace('-', "_"))
}

fn context(ir: &Ir) -> Context<'_> {
    Context {
        generator: crate::GENERATOR,
        source: &ir.source_name,
        fingerprint: ir.fingerprint.to_string(),
        device: format!("{} {}", ir.device.vendor, ir.device.model),
        // Without their final line end, like every other piece the template places.
        support: SUPPORT.trim_end(),
        pkw_support: match ir.telegram.pkw {
            PkwKind::None => None,
            PkwKind::PkeIndPwe => Some(PKW_PKE_IND_PWE.trim_end()),
            PkwKind::StationCommandAddressValue => Some(PKW_STATION_COMMAND.trim_end()),
        },
        diagnosis_support: ir
            .profibus
            .as_ref()
            .and_then(|p| p.diagnosis.as_ref())
            .map(|_| DIAGNOSIS.trim_end()),
        telegrams: telegrams(ir),
        words: DIRECTIONS
            .iter()
            .filter_map(|dir| Some(word_module(dir, (dir.word)(&ir.telegram).as_ref()?)))
            .collect(),
        profibus: ir.profibus.as_ref().map(profibus_items),
        profinet: ir.profinet.as_ref().map(profinet_items),
        groups: groups(ir).iter().map(|g| group(ir, g)).collect(),
    }
}

// ---------------------------------------------------------------------------
// Telegrams

/// What differs between the two directions of a cyclic telegram.
struct Direction {
    /// Of the struct's name.
    suffix: &'static str,
    name: &'static str,
    /// What reads or writes the PKW channel in this direction.
    pkw: &'static str,
    /// The word PZD1 carries, when the description has it, and its module.
    word: fn(&Telegram) -> &Option<Word>,
    word_module: &'static str,
    standard_telegram_1: &'static str,
}

/// Master to drive (the master's outputs), then drive to master.
const DIRECTIONS: [Direction; 2] = [
    Direction {
        suffix: "Out",
        name: "master to drive",
        pkw: "PkwRequest::decode",
        word: |t| &t.control_word,
        word_module: "control_word",
        standard_telegram_1: "STW1 and NSOLL_A",
    },
    Direction {
        suffix: "In",
        name: "drive to master",
        pkw: "PkwResponse::encode",
        word: |t| &t.status_word,
        word_module: "status_word",
        standard_telegram_1: "ZSW1 and NIST_A",
    },
];

/// A PPO type or a PROFINET module: one telegram struct each way.
struct Module {
    /// The structs' names without the direction.
    base: String,
    doc: String,
    layout: Layout,
    standard_telegram_1: bool,
}

/// Each PPO type, then each PROFINET module, both ways.
fn telegrams(ir: &Ir) -> Vec<TelegramStruct> {
    let ppos = ir.profibus.iter().flat_map(|p| {
        p.modules.iter().map(move |m| Module {
            base: format!("Ppo{}", m.ppo),
            doc: format!("\"{}\" of {}", m.name, p.file_name),
            layout: m.layout,
            standard_telegram_1: false,
        })
    });
    let modules = ir.profinet.iter().flat_map(|p| {
        p.modules.iter().map(|m| {
            let (constant, base) = pn_module_name(m);
            Module {
                base,
                doc: format!("PROFINET module \"{}\" ([`{constant}_IDENT`])", m.name),
                layout: m.layout,
                standard_telegram_1: m.kind == ModuleKind::StandardTelegram1,
            }
        })
    });
    ppos.chain(modules)
        .flat_map(|m| {
            DIRECTIONS
                .iter()
                .map(move |dir| telegram_struct(&ir.telegram, &m, dir))
        })
        .collect()
}

fn telegram_struct(telegram: &Telegram, m: &Module, dir: &Direction) -> TelegramStruct {
    let words = match m.layout.pzd_words {
        1 => "PZD1".to_string(),
        n => format!("PZD1 to PZD{n}"),
    };
    let pzd_doc = match (m.standard_telegram_1, (dir.word)(telegram)) {
        (true, _) => format!("PROFIdrive {}.", dir.standard_telegram_1),
        (false, Some(_)) => format!("{words}; PZD1 is the word of [`{}`].", dir.word_module),
        (false, None) => format!("{words}."),
    };
    TelegramStruct {
        name: format!("{}{}", m.base, dir.suffix),
        doc: format!("{}, {}: {} bytes.", m.doc, dir.name, m.layout.bytes()),
        pkw_doc: m
            .layout
            .pkw
            .then(|| format!("The PKW channel: see [`{}`].", dir.pkw)),
        pzd_doc,
        pzd_words: m.layout.pzd_words,
        bytes: m.layout.bytes(),
    }
}

/// The constant's and the struct's base name of a PROFINET module.
fn pn_module_name(m: &profinet::Module) -> (String, String) {
    match (m.kind, m.layout.pkw) {
        (ModuleKind::StandardTelegram1, _) => ("TELEGRAM1".into(), "Telegram1".into()),
        (ModuleKind::Pzd, true) => (
            format!("PKW_PZD{}", m.layout.pzd_words),
            format!("PkwPzd{}", m.layout.pzd_words),
        ),
        (ModuleKind::Pzd, false) => (
            format!("PZD{}", m.layout.pzd_words),
            format!("Pzd{}", m.layout.pzd_words),
        ),
    }
}

// ---------------------------------------------------------------------------
// Control and status words

fn word_module(dir: &Direction, word: &Word) -> WordModule {
    // `BitField` is imported into the module: no enum may take its name.
    let mut types = Names::taken(&["BitField"]);
    let mut constants = Names::default();
    let fields = word
        .bits
        .iter()
        .map(|b| {
            let bits = bit_range(b.first.into(), b.last.into());
            let name = constants.unique(upper_snake(&b.name.en, "BIT"), b.first);
            let values = (!b.values.is_empty()).then(|| ValueEnum {
                name: types.unique(camel(&b.name.en, "Field"), b.first),
                doc: format!("The values of [`{name}`]."),
                variants: variants(&b.values),
            });
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

fn bit_range(first: u16, last: u16) -> String {
    if first == last {
        format!("Bit {first}")
    } else {
        format!("Bits {first}-{last}")
    }
}

fn variants(choices: &[Choice]) -> Vec<Variant> {
    let mut names = Names::default();
    choices
        .iter()
        .map(|c| Variant {
            name: names.unique(camel(&c.text.en, "Value"), c.value),
            doc: format!("{}.", doc_text(&c.text.en)),
            value: c.value,
        })
        .collect()
}

// ---------------------------------------------------------------------------
// Mappings

/// Indexes into `Ir::mappings` of the sets of one kind; lowering orders the
/// sets by kind, so each kind's sets are consecutive.
struct SetsOfKind {
    kind: MappingKind,
    sets: Vec<usize>,
}

fn groups(ir: &Ir) -> Vec<SetsOfKind> {
    let mut groups: Vec<SetsOfKind> = Vec::new();
    for (i, set) in ir.mappings.iter().enumerate() {
        match groups.last_mut() {
            Some(g) if g.kind == set.kind => g.sets.push(i),
            _ => groups.push(SetsOfKind {
                kind: set.kind,
                sets: vec![i],
            }),
        }
    }
    groups
}

fn group(ir: &Ir, g: &SetsOfKind) -> Group {
    let single = g.sets.len() == 1;
    let mut sets = Vec::new();
    let mut entries = Vec::new();
    for &i in &g.sets {
        let set = &ir.mappings[i];
        // A kind with several sets (the settings) tells their names apart by
        // the number of each set's first entry; lowering gives every set one.
        let names = if single {
            SetNames {
                allowed: "ALLOWED".into(),
                choice: "Choice".into(),
                holder: "Each entry".into(),
            }
        } else {
            let first = &set.entries[0];
            SetNames {
                allowed: format!("ALLOWED_{}", first.number),
                choice: format!("Choice{}", first.number),
                holder: doc_text(&first.name.en),
            }
        };
        entries.extend(set_entries(ir, set, &names.allowed));
        sets.push(set_allowed(set, names));
    }
    Group {
        module: g.kind.key(),
        doc: group_doc(g.kind),
        sets,
        entries,
        user_prm_offset: ir.profibus.as_ref().map(|p| user_prm_offset(p, g)),
        record_index: ir
            .profinet
            .iter()
            .flat_map(|p| &p.records)
            .find(|r| r.kind == g.kind)
            .map(|r| r.index),
    }
}

fn group_doc(kind: MappingKind) -> &'static str {
    match kind {
        MappingKind::PzdOut => "The PZD words the master sends: what each one carries.",
        MappingKind::PzdIn => "The PZD words the drive sends: what each one carries.",
        MappingKind::Dpv1Index => {
            "The DPV1 record indexes: the parameter each one reads and writes."
        }
        MappingKind::Setting => "Drive settings the master gives at start-up.",
    }
}

/// What a set's items are called.
struct SetNames {
    /// The constant of what its entries may hold.
    allowed: String,
    /// The enum of its choices.
    choice: String,
    /// Its entries, in docs: "Each entry", or the name of a set's one entry.
    holder: String,
}

fn set_allowed(set: &MappingSet, names: SetNames) -> SetAllowed {
    let SetNames {
        allowed,
        choice,
        holder,
    } = names;
    match &set.allowed {
        Allowed::Range { min, max } => SetAllowed {
            doc: format!(
                "{holder} holds a parameter address from {} to {}.",
                hex16(*min),
                hex16(*max)
            ),
            allowed,
            choices: None,
            min: hex16(*min),
            max: hex16(*max),
        },
        Allowed::Choices(choices) => SetAllowed {
            doc: format!("{holder} holds one of the values of [`{choice}`]."),
            allowed,
            choices: Some(ValueEnum {
                doc: format!("What {} may hold.", holder.to_lowercase()),
                name: choice,
                variants: variants(choices),
            }),
            min: String::new(),
            max: String::new(),
        },
    }
}

fn set_entries<'a>(
    ir: &'a Ir,
    set: &'a MappingSet,
    allowed: &'a str,
) -> impl Iterator<Item = Entry> + 'a {
    // Parameter addresses read best in hex, with the manual's name beside
    // them; a choice is a plain number.
    let is_address = matches!(set.allowed, Allowed::Range { .. });
    let name_of = |address: u16| {
        ir.numbering
            .as_ref()
            .and_then(|n| n.format(address))
            .map_or_else(String::new, |name| format!(" // {name}"))
    };
    set.entries.iter().map(move |e| {
        let (default, default_comment) = if is_address {
            (hex16(e.default), name_of(e.default))
        } else {
            (e.default.to_string(), String::new())
        };
        Entry {
            name: format!("{:?}", e.name.en),
            number: e.number,
            default,
            default_comment,
            parameter: e
                .parameter
                .map_or_else(|| "None".into(), |p| format!("Some({})", hex16(p))),
            parameter_comment: e.parameter.map_or_else(String::new, name_of),
            allowed: allowed.to_string(),
        }
    })
}

/// Where the group's first entry starts in User_Prm_Data. Lowering lays the
/// entries out in mapping order, two bytes each, so the group's are
/// consecutive: the generated decoder reads them from there.
fn user_prm_offset(p: &Profibus, g: &SetsOfKind) -> usize {
    let offsets: Vec<usize> = p
        .user_prm
        .entries
        .iter()
        .filter(|e| g.sets.contains(&e.mapping.0))
        .map(|e| e.offset)
        .collect();
    let first = offsets.first().copied().unwrap_or(p.user_prm.byte_len());
    debug_assert!(offsets.iter().enumerate().all(|(i, &o)| o == first + 2 * i));
    first
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
            .map(|m| {
                let config = m.config_bytes();
                Ppo {
                    ppo: m.ppo,
                    name: m.name.clone(),
                    config: hex_bytes(&config),
                    config_len: config.len(),
                }
            })
            .collect(),
        user_prm_len: p.user_prm.byte_len(),
        dpv1_status: p.dpv1.map(|d| hex_bytes(&d.status_bytes)),
        diagnosis: p.diagnosis.as_ref().map(diagnosis_items),
    }
}

/// The device-related diagnosis: an area constant and a value enum for each
/// `Unit_Diag_Area` of the GSD, named after its bits.
fn diagnosis_items(d: &Diagnosis) -> DiagnosisItems {
    let mut types = Names::taken(&["DiagArea"]);
    // Beside the block's own constants; two areas over the same bits get
    // the first bit's number appended.
    let mut constants = Names::taken(&["LEN", "HEADER", "EMPTY"]);
    let areas = d
        .areas
        .iter()
        .map(|a| {
            let (constant, enum_name) = match (a.first_bit, a.last_bit) {
                (first, last) if first == last => (format!("BIT_{first}"), format!("Bit{first}")),
                (first, last) => (
                    format!("BITS_{first}_{last}"),
                    format!("Bits{first}To{last}"),
                ),
            };
            let constant = constants.unique(constant, a.first_bit);
            let values = ValueEnum {
                name: types.unique(enum_name, a.first_bit),
                doc: format!("The values of [`{constant}`]."),
                variants: variants(&a.values),
            };
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
        ports: p.ports,
        module_slot: profinet::MODULE_SLOT,
        modules: p
            .modules
            .iter()
            .map(|m| PnModule {
                name: m.name.clone(),
                constant: pn_module_name(m).0,
                ident: hex32(m.ident),
            })
            .collect(),
    }
}

/// `0xF3, 0xF1`: the inside of an array literal.
fn hex_bytes(bytes: &[u8]) -> String {
    bytes
        .iter()
        .map(|b| format!("0x{b:02X}"))
        .collect::<Vec<_>>()
        .join(", ")
}

fn hex16(value: u16) -> String {
    format!("0x{value:04X}")
}

/// `0x0000_0202`: eight digits in two groups, as ident numbers are written.
fn hex32(value: u32) -> String {
    format!("0x{:04X}_{:04X}", value >> 16, value & 0xFFFF)
}

// ---------------------------------------------------------------------------
// Names and docs

/// One line of a doc comment.
fn doc_text(text: &str) -> String {
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The runs of ASCII letters and digits of `text`, leaving out what is in
/// parentheses: units and remarks, as in `Output frequency (0.01 Hz)`.
fn ident_words(text: &str) -> Vec<String> {
    let mut depth = 0usize;
    let outside: String = text
        .chars()
        .map(|c| {
            match c {
                '(' => depth += 1,
                ')' => depth = depth.saturating_sub(1),
                _ if depth == 0 && c.is_ascii_alphanumeric() => return c,
                _ => {}
            }
            ' '
        })
        .collect();
    outside.split_whitespace().map(str::to_string).collect()
}

/// `Forward running` → `ForwardRunning`, `PID feedback` → `PidFeedback`;
/// `fallback` when the text has no letters or starts with a digit.
fn camel(text: &str, fallback: &str) -> String {
    let name: String = ident_words(text)
        .iter()
        .flat_map(|w| {
            let (head, tail) = w.split_at(1);
            [head.to_ascii_uppercase(), tail.to_ascii_lowercase()]
        })
        .collect();
    with_fallback(name, fallback)
}

/// `Forward running` → `FORWARD_RUNNING`.
fn upper_snake(text: &str, fallback: &str) -> String {
    let name = ident_words(text).join("_").to_ascii_uppercase();
    with_fallback(name, fallback)
}

fn with_fallback(name: String, fallback: &str) -> String {
    match name.chars().next() {
        None => fallback.to_string(),
        Some(c) if c.is_ascii_digit() => format!("{fallback}{name}"),
        // `Self` is the one keyword a capitalised word can spell.
        Some(_) if name == "Self" => format!("{name}{fallback}"),
        Some(_) => name,
    }
}

/// Names given in one scope, each once.
#[derive(Default)]
struct Names(BTreeSet<String>);

impl Names {
    fn taken(names: &[&str]) -> Self {
        Names(names.iter().map(|n| n.to_string()).collect())
    }

    /// `name`, or `name` with `tag` (a bit or value number) and then a
    /// counter appended until it is new.
    fn unique(&mut self, name: String, tag: impl std::fmt::Display) -> String {
        let sep = if name.contains('_') || name.chars().all(|c| !c.is_ascii_lowercase()) {
            "_"
        } else {
            ""
        };
        let mut candidate = name.clone();
        let mut n = 1;
        while self.0.contains(&candidate) {
            candidate = if n == 1 {
                format!("{name}{sep}{tag}")
            } else {
                format!("{name}{sep}{tag}{sep}{n}")
            };
            n += 1;
        }
        self.0.insert(candidate.clone());
        candidate
    }
}

#[cfg(test)]
#[path = "../../templates/support.rs"]
mod support;

#[cfg(test)]
mod support_tests;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_from_manual_texts() {
        assert_eq!(camel("Forward running", "V"), "ForwardRunning");
        assert_eq!(camel("PID feedback", "V"), "PidFeedback");
        assert_eq!(camel("Output frequency (0.01 Hz)", "V"), "OutputFrequency");
        assert_eq!(camel("DI1 to DI4 state", "V"), "Di1ToDi4State");
        assert_eq!(
            camel("Encoder/PG card abnormal", "V"),
            "EncoderPgCardAbnormal"
        );
        assert_eq!(camel("1st speed", "Value"), "Value1stSpeed");
        assert_eq!(camel("正转运行", "Value"), "Value");
        assert_eq!(camel("self", "Value"), "SelfValue");
        assert_eq!(upper_snake("Motor number", "BIT"), "MOTOR_NUMBER");
        assert_eq!(upper_snake("5 V supply", "BIT"), "BIT5_V_SUPPLY");
    }

    #[test]
    fn names_are_unique_in_their_scope() {
        let mut names = Names::taken(&["BitField"]);
        assert_eq!(names.unique("BitField".into(), 3), "BitField3");
        assert_eq!(names.unique("Stop".into(), 3), "Stop");
        assert_eq!(names.unique("Stop".into(), 3), "Stop3");
        assert_eq!(names.unique("Stop".into(), 3), "Stop32");
        let mut constants = Names::default();
        assert_eq!(constants.unique("FAULT".into(), 4), "FAULT");
        assert_eq!(constants.unique("FAULT".into(), 4), "FAULT_4");
        assert_eq!(constants.unique("FAULT".into(), 4), "FAULT_4_2");
    }

    #[test]
    fn file_names_are_identifiers() {
        let text = include_str!("../../descriptions/mv810-pnet02.toml");
        let ir = crate::load("mv810-pnet02.toml", text).0.unwrap();
        assert_eq!(file_name(&ir), "mv810_pnet02_layout.rs");
    }

    #[test]
    fn diagnosis_areas_over_the_same_bits_get_their_own_names() {
        let text = include_str!("../../descriptions/md810dp.toml").replace(
            "[[profibus.diagnosis.areas]]",
            "[[profibus.diagnosis.areas]]\nbit = [8, 15]\nvalues = [{ value = 1, text = \"One\" }]\n\n[[profibus.diagnosis.areas]]",
        );
        let ir = crate::load("md810dp.toml", &text).0.unwrap();
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
