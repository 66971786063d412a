//! The C emitter: IR to the firmware layout for C (`<stem>_layout.h`)
//! through `templates/c/layout.h.jinja`, and the support header every layout
//! includes (`gsdc_support.h`, from `templates/c/gsdc_support.h`), the same
//! for every description.
//!
//! C has one namespace per translation unit, so every name a layout declares
//! starts with a prefix spelt from the description's file name (`MD810DP_`,
//! `md810dp_`), and the codecs that do not depend on the description live
//! once in the support header, under its guard: any number of layouts can be
//! included together. [`verify`] reads every header back and refuses one
//! that declares a name without the prefix, or any name twice (counting the
//! support header's): C would flatten two names lowering keeps apart in Rust
//! (a field's mask and a value of the same words) into one.
//!
//! Every name and comment comes finished from here; the template arranges.
//! A comment the template writes around the names it arranges goes through
//! the `comment` filter, which wraps it as [`comment`] does here.

use super::{
    bit_range, capitalised, group_doc, hex16, hex8, mapping_literal, range_doc, Artifact,
    ArtifactKind,
};
use crate::diag::Diagnostic;
use crate::ir::mapping::{Allowed, Holds, MappingGroup, MappingKind, MappingSet};
use crate::ir::profibus::{Diagnosis, Profibus};
use crate::ir::profinet::RecordReading;
use crate::ir::profinet::{self, Profinet};
use crate::ir::{Bus, CyclicModule, Direction, Ident, Ir, PkwKind, ValueSet, Word};
use serde::Serialize;
use std::collections::BTreeSet;
use std::fmt::Write as _;

mod gateway;
mod tables;

const TEMPLATE: &str = include_str!("../../templates/c/layout.h.jinja");

/// The support header's file, its text, and the line the emitter gives the
/// release that wrote it.
pub const SUPPORT_FILE_NAME: &str = "gsdc_support.h";
const SUPPORT: &str = include_str!("../../templates/c/gsdc_support.h");
const SUPPORT_VERSION_LINE: &str = "#define GSDC_SUPPORT_VERSION 0\n";

/// Columns a comment or an initializer fills before it wraps.
const WIDTH: usize = 80;

#[derive(Serialize)]
struct Context {
    header: String,
    generator: &'static str,
    guard: String,
    /// The prefix, upper and lower case, without the underscore.
    p: String,
    l: String,
    support_version: u32,
    fingerprint: String,
    pkw: Option<String>,
    modules: Vec<ModuleItem>,
    words: Vec<WordItem>,
    groups: Vec<GroupItem>,
    profibus: Option<ProfibusItems>,
    gateway: Option<gateway::Items>,
    profinet: Option<ProfinetItems>,
    /// The device tables, finished.
    tables: String,
}

/// A PPO type or PROFINET module: its shape, and one telegram each way.
#[derive(Serialize)]
struct ModuleItem {
    /// `MD810DP_PPO1`: the base of its macros.
    name: String,
    /// `md810dp_ppo1`: the name of its compile-time checks.
    check: String,
    doc: String,
    bytes: u16,
    pzd_words: u8,
    pzd_offset: &'static str,
    telegrams: Vec<TelegramItem>,
}

#[derive(Serialize)]
struct TelegramItem {
    /// `md810dp_ppo1_out`, without the `_t`.
    name: String,
    doc: String,
}

#[derive(Serialize)]
struct WordItem {
    doc: String,
    fields: Vec<FieldItem>,
}

#[derive(Serialize)]
struct FieldItem {
    name: String,
    doc: String,
    mask: String,
    shift: u8,
    values: Option<ValueSetItem>,
}

#[derive(Serialize)]
struct ValueSetItem {
    is_value: String,
    choices: Vec<ChoiceItem>,
}

#[derive(Serialize)]
struct ChoiceItem {
    name: String,
    doc: String,
    value: String,
}

#[derive(Serialize)]
struct GroupItem {
    /// `MD810DP_PZD_OUT` and `md810dp_pzd_out`.
    name: String,
    lower: String,
    /// Its field in the decoded User_Prm_Data.
    field: &'static str,
    doc: String,
    sets: Vec<SetItem>,
    entries: Vec<EntryItem>,
    defaults: String,
    user_prm_offset: Option<u16>,
    /// The entries User_Prm_Data carries, by place, when not all
    /// (`UserPrm::partial`); empty when it carries all.
    user_prm_entries: Vec<usize>,
    record_index: Option<u16>,
    /// A module's PZD record holds the words it transports.
    record_prefix: bool,
    /// DPV1 indexes: the bytes of each index's record.
    record_length: Option<u8>,
    fixed: Vec<FixedItem>,
}

/// The value each PROFINET module fixes for a setting, by module ident.
#[derive(Serialize)]
struct FixedItem {
    name: String,
    doc: String,
    modules: Vec<String>,
    initializer: String,
}

#[derive(Serialize)]
struct SetItem {
    /// `MD810DP_PZD_OUT_ALLOWED`, and the function `md810dp_pzd_out_allowed`.
    name: String,
    allowed: String,
    doc: String,
    allowed_doc: String,
    /// The index after its last entry in the group.
    end: usize,
    choices: Option<ValueSetItem>,
    min: String,
    max: String,
    /// The body of the range check.
    check: Vec<String>,
}

#[derive(Serialize)]
struct EntryItem {
    number: u8,
    doc: String,
    name: String,
    default: String,
    /// ` /* F0-00 */`: the manual's name of an address, when it has one.
    default_comment: String,
    parameter: Option<String>,
    parameter_comment: String,
}

#[derive(Serialize)]
struct ProfibusItems {
    ident_doc: String,
    ident_number: String,
    configs: Vec<ConfigItem>,
    user_prm_len: u16,
    /// Whether User_Prm_Data has anything to decode.
    user_prm_fields: bool,
    /// Whether it has anything besides a gateway's node configuration,
    /// which its own decoder writes.
    user_prm_copied: bool,
    dpv1_status: Option<String>,
    diagnosis: Option<DiagnosisItems>,
}

#[derive(Serialize)]
struct ConfigItem {
    name: String,
    doc: String,
    len: usize,
    initializer: String,
}

#[derive(Serialize)]
struct DiagnosisItems {
    doc: String,
    len: u8,
    header: String,
    empty: String,
    areas: Vec<AreaItem>,
}

#[derive(Serialize)]
struct AreaItem {
    name: String,
    doc: String,
    first: u16,
    last: u16,
    values: ValueSetItem,
}

#[derive(Serialize)]
struct ProfinetItems {
    vendor_doc: String,
    vendor_id: String,
    device_doc: String,
    device_id: String,
    dap_ident: String,
    interface_subslot: String,
    first_port_subslot: String,
    ports: usize,
    module_slot: u16,
    modules: Vec<PnModuleItem>,
}

#[derive(Serialize)]
struct PnModuleItem {
    name: String,
    doc: String,
    ident: String,
    profidrive: Option<ProfidriveItem>,
}

/// Where a PROFIdrive module's submodules are: the profile's API, the
/// module access point's subslot and ident number, the telegram's subslot.
#[derive(Serialize)]
struct ProfidriveItem {
    doc: String,
    api: String,
    access_point_subslot: String,
    access_point_ident: String,
    data_subslot: String,
}

/// The C firmware layout of a description.
pub fn emit(ir: &Ir) -> String {
    render(TEMPLATE, ir).expect("the C layout template renders every IR (tested)")
}

fn render(template: &str, ir: &Ir) -> Result<String, minijinja::Error> {
    let mut env = super::code_templates();
    env.add_filter("comment", |text: String, indent: Option<usize>| {
        indented_comment(&text, indent.unwrap_or(0))
    });
    env.template_from_str(template)?.render(context(ir))
}

/// `md810dp_layout.h`, beside `md810dp_layout.rs`.
pub fn file_name(ir: &Ir) -> String {
    format!("{}_layout.h", super::layout_stem(ir))
}

/// The prefix of every name a layout declares, spelt from the layout's
/// stem: `md810dp` for `md810dp.toml`, `mv810_pnet02` for
/// `mv810-pnet02.toml`, and `gsdc_9kdp1` for `9kdp1.toml`, since a C name
/// cannot start with a digit (and the support header names nothing
/// `gsdc_` and a digit). Every other name that starts with the word `gsdc`
/// is the support header's: a stem that spells it (`gsdc.toml`,
/// `Gsdc-prm.toml`) or no word at all (`_.toml`, `网关.toml`) is prefixed
/// `layout` (`layout_gsdc`, `layout`), so that no layout can declare
/// `gsdc_node_totals` beside the support header's.
fn prefix(ir: &Ir) -> Ident {
    let stem = super::layout_stem(ir);
    let ident = Ident::from_text(&stem, "gsdc");
    match ident.words() {
        [gsdc, next, ..] if gsdc == "gsdc" && next.starts_with(|c: char| c.is_ascii_digit()) => {
            ident
        }
        [gsdc, ..] if gsdc == "gsdc" => Ident::from_text(&format!("layout_{stem}"), "layout"),
        _ => ident,
    }
}

/// `gsdc_support.h`: the hand-written support header, with the release that
/// wrote it, which each layout checks.
pub fn support_header() -> Artifact {
    let version = format!("#define GSDC_SUPPORT_VERSION {}\n", support_version());
    let text = format!(
        "/* @generated by {}; do not edit. */\n{}",
        crate::GENERATOR,
        SUPPORT.replacen(SUPPORT_VERSION_LINE, &version, 1)
    );
    Artifact {
        kind: ArtifactKind::CSupport,
        file_name: SUPPORT_FILE_NAME.to_string(),
        contents: text.into_bytes(),
    }
}

/// The crate's version as one number, major * 10000 + minor * 100 + patch.
fn support_version() -> u32 {
    [
        env!("CARGO_PKG_VERSION_MAJOR"),
        env!("CARGO_PKG_VERSION_MINOR"),
        env!("CARGO_PKG_VERSION_PATCH"),
    ]
    .iter()
    .map(|part| {
        part.parse::<u32>()
            .expect("cargo's version parts are numbers")
    })
    .fold(0, |version, part| version * 100 + part)
}

fn context(ir: &Ir) -> Context {
    let prefix = prefix(ir);
    let (p, l) = (prefix.upper_snake(), prefix.snake());
    let names = Names { p: &p, l: &l };
    Context {
        header: header(ir, &p, &l),
        generator: crate::GENERATOR,
        guard: format!("{p}_LAYOUT_H"),
        support_version: support_version(),
        fingerprint: ir.fingerprint.to_string(),
        pkw: pkw_doc(ir.telegram.pkw),
        modules: modules(ir, &names),
        words: Direction::BOTH
            .iter()
            .filter_map(|&dir| Some(word_item(&names, dir, ir.telegram.word(dir)?)))
            .collect(),
        groups: ir
            .mappings
            .groups
            .iter()
            .map(|g| group_item(ir, &names, g))
            .collect(),
        profibus: ir.profibus.as_ref().map(|pb| profibus_items(&names, pb)),
        gateway: ir
            .gateway
            .as_ref()
            .zip(ir.profibus.as_ref())
            .map(|(g, pb)| gateway::items(&names, g, pb)),
        profinet: ir.profinet.as_ref().map(|pn| profinet_items(&names, pn)),
        tables: tables::render(&names, &super::tables::tables(ir)),
        p,
        l,
    }
}

/// The prefix in both cases, and the names built on it.
struct Names<'a> {
    p: &'a str,
    l: &'a str,
}

impl Names<'_> {
    /// `MD810DP_PZD_OUT` of `["pzd", "out"]`.
    fn upper(&self, rest: &str) -> String {
        format!("{}_{}", self.p, rest.to_ascii_uppercase())
    }

    fn lower(&self, rest: &str) -> String {
        format!("{}_{}", self.l, rest.to_ascii_lowercase())
    }
}

fn header(ir: &Ir, p: &str, l: &str) -> String {
    let about = format!(
        "Firmware layout of {} {} for C: {}, from the same description as the \
         device files. \
         Multi-byte values on the bus are big-endian; telegrams are byte arrays, \
         read and written with the accessors of {SUPPORT_FILE_NAME}, which gsdc \
         writes beside this file. C99 or C++, no allocation; every name starts \
         with {p}_ or {l}_, so the layouts of several descriptions can be \
         included together.",
        ir.device.vendor,
        ir.device.model,
        super::layout_contents(ir)
    );
    let mut lines = vec![
        format!(
            "@generated by {} from {}; do not edit.",
            crate::GENERATOR,
            comment_text(&ir.source_name)
        ),
        format!("Description fingerprint: {}", ir.fingerprint),
        String::new(),
    ];
    lines.extend(wrap(&comment_text(&about), WIDTH - 3));
    let notes = super::header_notes(ir, super::ArtifactKind::CHeader);
    if !notes.is_empty() {
        lines.push(String::new());
    }
    for note in notes {
        let wrapped = wrap(&comment_text(&note), WIDTH - 5);
        lines.extend(wrapped.into_iter().enumerate().map(|(i, line)| {
            if i == 0 {
                line
            } else {
                format!("  {line}")
            }
        }));
    }
    block_comment(&lines)
}

fn pkw_doc(kind: PkwKind) -> Option<String> {
    let (name, codec) = match kind {
        PkwKind::None => return None,
        PkwKind::PkeIndPwe => ("PKE, IND, PWE", "gsdc_pke"),
        PkwKind::StationCommandAddressValue => ("station, command, address, value", "gsdc_station"),
        PkwKind::Profidrive => ("PROFIdrive: PKE, IND, PWE1, PWE2", "gsdc_profidrive"),
    };
    Some(comment(&format!(
        "The PKW channel ({name}) in bytes 0-7 of the telegrams that have one: \
         the master's requests are decoded with {codec}_request_decode into \
         {codec}_request_t, the drive's answers encoded from {codec}_response_t \
         with {codec}_response_encode (in {SUPPORT_FILE_NAME})."
    )))
}

// ---------------------------------------------------------------------------
// Telegrams

/// Each PPO type, then each PROFINET module.
fn modules(ir: &Ir, names: &Names) -> Vec<ModuleItem> {
    ir.cyclic_modules()
        .map(|m| module_item(ir, names, &m))
        .collect()
}

/// `"PPO1" of MD810DP.GSD`, `PROFINET module "PKW + 12 PZD" (MD810DP_PKW_PZD12_IDENT)`.
fn module_doc(names: &Names, m: &CyclicModule) -> String {
    match m.bus {
        Bus::Profibus => format!("\"{}\" of {}", m.name, m.file_name),
        Bus::Profinet => format!(
            "PROFINET module \"{}\" ({}_IDENT)",
            m.name,
            names.upper(&m.ident.upper_snake())
        ),
    }
}

fn module_item(ir: &Ir, names: &Names, m: &CyclicModule) -> ModuleItem {
    let words = match m.layout.pzd_words {
        1 => "PZD1".to_string(),
        n => format!("PZD1 to PZD{n}"),
    };
    let pzd_offset = m.layout.pzd_offset();
    let place = if m.layout.pkw {
        format!("the PKW channel in bytes 0-7, {words} from byte {pzd_offset}")
    } else {
        format!("{words} from byte 0")
    };
    let doc = format!(
        "{}: {} bytes each way, {place}.",
        module_doc(names, m),
        m.layout.bytes()
    );
    let base = m.ident.snake();
    ModuleItem {
        name: names.upper(&base),
        check: names.lower(&base),
        doc: comment(&doc),
        bytes: m.layout.bytes(),
        pzd_words: m.layout.pzd_words,
        pzd_offset: if m.layout.pkw { "GSDC_PKW_BYTES" } else { "0U" },
        telegrams: Direction::BOTH
            .iter()
            .map(|&dir| telegram_item(ir, names, m, &base, dir))
            .collect(),
    }
}

fn telegram_item(
    ir: &Ir,
    names: &Names,
    m: &CyclicModule,
    base: &str,
    dir: Direction,
) -> TelegramItem {
    let (suffix, way, word, standard) = match dir {
        Direction::Out => ("out", "Master to drive", "control word", "STW1 and NSOLL_A"),
        Direction::In => ("in", "Drive to master", "status word", "ZSW1 and NIST_A"),
    };
    let pzd1 = match (m.is_profidrive(), ir.telegram.word(dir)) {
        (true, _) => format!(": PROFIdrive {standard}."),
        (false, Some(_)) => format!(
            "; PZD1 is the {word}, {}_*.",
            names.upper(&word.replace(' ', "_"))
        ),
        (false, None) => ".".to_string(),
    };
    TelegramItem {
        name: names.lower(&format!("{base}_{suffix}")),
        doc: comment(&format!("{way}{pzd1}")),
    }
}

// ---------------------------------------------------------------------------
// Control and status words

fn word_item(names: &Names, dir: Direction, word: &Word) -> WordItem {
    let (module, way) = match dir {
        Direction::Out => ("control_word", "master to drive"),
        Direction::In => ("status_word", "drive to master"),
    };
    let base = names.upper(module);
    let fields = word
        .bits
        .iter()
        .map(|b| {
            let name = format!("{base}_{}", b.ident.upper_snake());
            let values = b.values.as_ref().map(|v| value_set_item(names, module, v));
            let see = if values.is_some() {
                "; its values follow"
            } else {
                ""
            };
            FieldItem {
                doc: comment(&format!(
                    "{}: {}{see}.",
                    bit_range(b.first.into(), b.last.into()),
                    b.name.en
                )),
                mask: format!("0x{:04X}U", field_mask(b.first, b.last)),
                shift: b.first,
                name,
                values,
            }
        })
        .collect();
    WordItem {
        doc: comment(&format!(
            "{}, PZD1 {way}: its bits, each with its mask and its first bit \
             for gsdc_field_get and gsdc_field_with.",
            word.name.en
        )),
        fields,
    }
}

fn field_mask(first: u8, last: u8) -> u16 {
    (first..=last).fold(0, |mask, bit| mask | 1 << bit)
}

/// The values of a set as macros named `<prefix>_<scope>_<set>_<value>`, and
/// the function that tells whether a number is one of them.
fn value_set_item(names: &Names, scope: &str, values: &ValueSet) -> ValueSetItem {
    let base = format!("{scope}_{}", values.ident.snake());
    ValueSetItem {
        is_value: names.lower(&format!("{base}_is_value")),
        choices: values
            .choices
            .iter()
            .map(|c| ChoiceItem {
                name: names.upper(&format!("{base}_{}", c.ident.snake())),
                doc: comment(&format!("{}.", c.text.en)),
                value: format!("{}U", c.value),
            })
            .collect(),
    }
}

// ---------------------------------------------------------------------------
// Mappings

fn group_item(ir: &Ir, names: &Names, g: &MappingGroup) -> GroupItem {
    let module = g.kind.key();
    let record = ir.profinet.as_ref().and_then(|p| p.record(g.kind));
    let single = g.sets.len() == 1;
    let mut end = 0;
    let sets = g
        .sets
        .iter()
        .map(|set| {
            end += set.entries.len();
            set_item(names, module, set, single, end)
        })
        .collect();
    let entries: Vec<EntryItem> = g
        .sets
        .iter()
        .flat_map(|set| set_entries(ir, g.kind, set))
        .collect();
    let name = names.upper(module);
    let defaults = initializer(
        &format!("{name}_DEFAULTS"),
        &entries
            .iter()
            .map(|e| e.default.clone())
            .collect::<Vec<_>>(),
    );
    GroupItem {
        lower: names.lower(module),
        field: module,
        doc: comment(&group_doc(g)),
        sets,
        entries,
        defaults,
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
        record_prefix: record.is_some_and(|r| r.reading == RecordReading::Prefix),
        record_length: g.record_length,
        fixed: fixed_items(ir, names, g, &name),
        name,
    }
}

/// For each set of `g` whose value PROFINET modules fix: an initializer of
/// gsdc_module_value_t[] with every module that carries it and its value.
fn fixed_items(ir: &Ir, names: &Names, g: &MappingGroup, group: &str) -> Vec<FixedItem> {
    let Some(profinet) = &ir.profinet else {
        return Vec::new();
    };
    g.sets
        .iter()
        .filter_map(|set| Some((set, profinet.fixed(set.key)?)))
        .map(|(set, fixed)| {
            let modules: Vec<String> = fixed
                .modules
                .iter()
                .map(|(ident, _, value)| {
                    let ident = names.upper(&format!("{}_IDENT", ident.snake()));
                    format!("{{ {ident}, {value}U }}")
                })
                .collect();
            let name = format!("{group}_FIXED_{}", set.key.first);
            FixedItem {
                doc: comment(&format!(
                    "The value of \"{}\" each PROFINET module fixes, by its ident number: the module writes it; the user cannot change it. An initializer of gsdc_module_value_t[{name}_COUNT].",
                    set.entries[0].name.en
                )),
                initializer: initializer(&name, &modules),
                modules,
                name,
            }
        })
        .collect()
}

fn set_item(names: &Names, module: &str, set: &MappingSet, single: bool, end: usize) -> SetItem {
    let holder = if single {
        "each entry".to_string()
    } else {
        format!("\"{}\"", set.entries[0].name.en)
    };
    let base = format!("{module}_{}", set.allowed_ident.snake());
    let name = names.upper(&base);
    let allowed_doc = comment(&format!("Whether {holder} may hold `value`."));
    let holder = capitalised(&holder);
    match &set.allowed {
        Allowed::Range { min, max } => SetItem {
            doc: comment(&range_doc(&holder, set.holds, *min, *max)),
            allowed: names.lower(&base),
            allowed_doc,
            end,
            choices: None,
            min: format!("{}U", mapping_literal(set.holds, *min)),
            max: format!("{}U", mapping_literal(set.holds, *max)),
            check: range_check(&name, *min, *max),
            name,
        },
        Allowed::Choices(values) => SetItem {
            doc: comment(&format!("{holder} holds one of these values.")),
            allowed: names.lower(&base),
            allowed_doc,
            end,
            choices: Some(value_set_item(names, module, values)),
            min: String::new(),
            max: String::new(),
            check: Vec::new(),
            name,
        },
    }
}

/// The body of a range check, without the comparisons an Unsigned16 always
/// passes (compilers warn about those).
fn range_check(name: &str, min: u16, max: u16) -> Vec<String> {
    let lower = (min > 0).then(|| format!("(value >= {name}_MIN)"));
    let upper = (max < u16::MAX).then(|| format!("(value <= {name}_MAX)"));
    match (lower, upper) {
        (None, None) => vec!["(void)value;".into(), "return true;".into()],
        (Some(one), None) | (None, Some(one)) => vec![format!("return {one};")],
        (Some(lower), Some(upper)) => vec![format!("return {lower} && {upper};")],
    }
}

fn set_entries<'a>(
    ir: &'a Ir,
    kind: MappingKind,
    set: &'a MappingSet,
) -> impl Iterator<Item = EntryItem> + 'a {
    // Parameter addresses read best in hex, with the manual's name beside
    // them; a choice is a plain number.
    let is_address = set.holds == Holds::Address;
    let name_of = |address: u16| {
        let name = ir.numbering.as_ref().and_then(|n| n.format(address));
        name.map_or_else(String::new, |name| {
            format!(" /* {} */", comment_text(&name))
        })
    };
    set.entries.iter().map(move |e| {
        let number = e.key.number;
        let what = match kind {
            MappingKind::PzdOut | MappingKind::PzdIn => format!("PZD{number}"),
            MappingKind::Dpv1Index => format!("DPV1 index {number}"),
            MappingKind::Setting => format!("Setting {number}"),
        };
        EntryItem {
            number,
            doc: comment(&format!("{what}: \"{}\".", e.name.en)),
            name: c_string(&e.name.en),
            default: format!("{}U", mapping_literal(set.holds, e.default)),
            default_comment: if is_address {
                name_of(e.default)
            } else {
                String::new()
            },
            parameter: e.parameter.map(|p| format!("{}U", hex16(p))),
            parameter_comment: e.parameter.map_or_else(String::new, name_of),
        }
    })
}

// ---------------------------------------------------------------------------
// Bus constants

fn profibus_items(names: &Names, p: &Profibus) -> ProfibusItems {
    let mut ident_doc = format!("PROFIBUS Ident_Number, as {} declares it.", p.file_name);
    if p.ident_placeholder {
        ident_doc.push_str(" A placeholder, not assigned by PI.");
    }
    ProfibusItems {
        ident_doc: comment(&ident_doc),
        ident_number: format!("{}U", hex16(p.ident_number)),
        configs: p
            .modules
            .iter()
            .map(|m| {
                let name = names.upper(&m.ident.snake());
                ConfigItem {
                    doc: comment(&format!(
                        "\"{}\": the config bytes Chk_Cfg accepts, an initializer \
                         of uint8_t[{name}_CONFIG_LEN].",
                        m.name
                    )),
                    len: m.config.len(),
                    initializer: initializer(&format!("{name}_CONFIG"), &hex_bytes(&m.config)),
                    name,
                }
            })
            .collect(),
        user_prm_len: p.user_prm.len,
        user_prm_fields: p.dpv1.is_some()
            || !p.user_prm.blocks.is_empty()
            || !p.user_prm.gateway.is_empty(),
        user_prm_copied: p.dpv1.is_some() || !p.user_prm.blocks.is_empty(),
        dpv1_status: p.dpv1.map(|d| {
            initializer(
                &names.upper("user_prm_dpv1_status"),
                &hex_bytes(&d.status_bytes),
            )
        }),
        diagnosis: p
            .diagnosis
            .as_ref()
            .map(|d| diagnosis_items(names, &p.file_name, d)),
    }
}

/// The device-related diagnosis: the first and last bit of each
/// `Unit_Diag_Area` of the GSD, and its values.
fn diagnosis_items(names: &Names, file_name: &str, d: &Diagnosis) -> DiagnosisItems {
    let header = names.upper("diagnosis_header");
    let empty: Vec<String> = std::iter::once(header)
        .chain((1..d.length).map(|_| "0x00U".to_string()))
        .collect();
    let said: String = super::diagnosis_said(d)
        .iter()
        .map(|line| format!(" {line}"))
        .collect();
    DiagnosisItems {
        doc: comment(&format!(
            "The device-related diagnosis {file_name} describes: a header byte, \
             then the bytes its Unit_Diag_Areas read. Each area's bits are \
             read and written with gsdc_diag_area_get and gsdc_diag_area_set.{said}"
        )),
        len: d.length,
        header: format!("0x{:02X}U", d.length),
        empty: initializer(&names.upper("diagnosis_empty"), &empty),
        areas: d
            .areas
            .iter()
            .map(|a| AreaItem {
                name: names.upper(&format!("diagnosis_{}", a.ident.snake())),
                doc: comment(&format!(
                    "{} of the device-related diagnosis; its values follow.",
                    bit_range(a.first_bit, a.last_bit)
                )),
                first: a.first_bit,
                last: a.last_bit,
                values: value_set_item(names, "diagnosis", &a.values),
            })
            .collect(),
    }
}

fn profinet_items(names: &Names, p: &Profinet) -> ProfinetItems {
    let mut vendor_doc = format!("PROFINET VendorID, as {} declares it.", p.file_name);
    if p.vendor_id_placeholder {
        vendor_doc.push_str(" A placeholder, not assigned by PI.");
    }
    let mut device_doc = "PROFINET DeviceID.".to_string();
    if p.device_id_placeholder {
        device_doc.push_str(" A placeholder.");
    }
    ProfinetItems {
        vendor_doc: comment(&vendor_doc),
        vendor_id: format!("{}U", hex16(p.vendor_id)),
        device_doc: comment(&device_doc),
        device_id: format!("{}U", hex16(p.device_id)),
        dap_ident: hex32(profinet::DAP_IDENT),
        interface_subslot: format!("{}U", hex16(profinet::INTERFACE_SUBSLOT)),
        first_port_subslot: format!("{}U", hex16(profinet::FIRST_PORT_SUBSLOT)),
        ports: p.ports.len(),
        module_slot: profinet::MODULE_SLOT,
        modules: p
            .modules
            .iter()
            .map(|m| PnModuleItem {
                name: names.upper(&m.ident.snake()),
                doc: comment(&format!(
                    "Module \"{}\": its ident number, and its submodule's.",
                    m.name.text.en
                )),
                ident: hex32(m.ident_number),
                profidrive: m.is_profidrive().then(|| ProfidriveItem {
                    doc: comment(&format!(
                        "Module \"{}\" is PROFIdrive's: its submodules are in the profile's API, the module access point (no data) in its subslot with its ident number, the telegram in the data subslot.",
                        m.name.text.en
                    )),
                    api: hex32(profinet::PROFIDRIVE_API),
                    access_point_subslot: format!("{}U", profinet::ACCESS_POINT_SUBSLOT),
                    access_point_ident: hex32(profinet::ACCESS_POINT_IDENT),
                    data_subslot: format!("{}U", profinet::PROFIDRIVE_DATA_SUBSLOT),
                }),
            })
            .collect(),
    }
}

// ---------------------------------------------------------------------------
// C text

fn hex_bytes(bytes: &[u8]) -> Vec<String> {
    bytes.iter().map(|&b| format!("{}U", hex8(b))).collect()
}

/// `0x00000202UL`: an unsigned long, which holds 32 bits where int has 16.
fn hex32(value: u32) -> String {
    format!("{}UL", super::hex32(value))
}

/// `#define NAME { a, b }`, wrapped with continuation lines when long.
fn initializer(name: &str, values: &[String]) -> String {
    let line = format!("#define {name} {{ {} }}", values.join(", "));
    if line.len() <= WIDTH {
        return line;
    }
    let mut lines = vec![format!("#define {name} {{")];
    let mut current = String::from("   ");
    for (i, value) in values.iter().enumerate() {
        let last = i + 1 == values.len();
        let item = if last {
            format!(" {value} }}")
        } else {
            format!(" {value},")
        };
        if current.len() + item.len() > WIDTH - 2 {
            lines.push(std::mem::replace(&mut current, String::from("   ")));
        }
        current.push_str(&item);
    }
    lines.push(current);
    lines.join(" \\\n")
}

/// A block comment of `text`, wrapped: `/* text */` on one line when it fits.
fn comment(text: &str) -> String {
    indented_comment(text, 0)
}

/// [`comment`] indented by `indent` columns, as inside a struct.
fn indented_comment(text: &str, indent: usize) -> String {
    let lines = wrap(&comment_text(text), WIDTH.saturating_sub(3 + indent));
    block_comment(&lines)
        .lines()
        .map(|line| format!("{:indent$}{line}", ""))
        .collect::<Vec<_>>()
        .join("\n")
}

/// `/* line` ... ` * line */`.
fn block_comment(lines: &[String]) -> String {
    let mut out = String::new();
    for (i, line) in lines.iter().enumerate() {
        out.push_str(if i == 0 { "/*" } else { " *" });
        if !line.is_empty() {
            out.push(' ');
            out.push_str(line);
        }
        out.push_str(if i + 1 == lines.len() { " */" } else { "\n" });
    }
    out
}

/// Words of `text` in lines of at most `width` characters (a longer word has
/// a line of its own); an empty text is one empty line.
fn wrap(text: &str, width: usize) -> Vec<String> {
    let lines = super::wrap_words(text, width);
    if lines.is_empty() {
        vec![String::new()]
    } else {
        lines
    }
}

/// A description's text, safe inside a C comment: on one line, with no `*/`
/// to end the comment, no `/*` for compilers to warn about, no `??` to start
/// a trigraph, and control and bidirectional formatting characters (which
/// compilers warn about) written as `<U+202E>`.
fn comment_text(text: &str) -> String {
    let mut visible = String::with_capacity(text.len());
    for c in text.chars() {
        if (c.is_control() && !c.is_whitespace()) || crate::spec::is_bidi_control(c) {
            let _ = write!(visible, "<U+{:04X}>", u32::from(c));
        } else {
            visible.push(c);
        }
    }
    let mut out = visible.split_whitespace().collect::<Vec<_>>().join(" ");
    for (from, to) in [("*/", "* /"), ("/*", "/ *"), ("??", "? ?")] {
        while out.contains(from) {
            out = out.replace(from, to);
        }
    }
    out
}

/// A C string literal of `text`: printable ASCII as it is (`\`, `"` and `?`
/// escaped, the last against trigraphs), any other byte as an octal escape,
/// which never swallows the character after it.
fn c_string(text: &str) -> String {
    let mut out = String::from("\"");
    for byte in text.bytes() {
        match byte {
            b'\\' | b'"' | b'?' => {
                out.push('\\');
                out.push(char::from(byte));
            }
            b' '..=b'~' => out.push(char::from(byte)),
            _ => out.push_str(&format!("\\{byte:03o}")),
        }
    }
    out.push('"');
    out
}

// ---------------------------------------------------------------------------
// Verification

/// A layout must declare every name with its prefix and no name twice, the
/// support header's included; else an E900 for each name at fault.
pub fn verify(ir: &Ir, file_name: &str, text: &str) -> Vec<Diagnostic> {
    let prefix = prefix(ir);
    let prefixes = [
        format!("{}_", prefix.upper_snake()),
        format!("{}_", prefix.snake()),
    ];
    let mut seen: BTreeSet<String> = declared_names(SUPPORT).into_iter().collect();
    let mut problems = Vec::new();
    for name in declared_names(text) {
        if !prefixes.iter().any(|p| name.starts_with(p.as_str())) {
            problems.push(breaks(
                file_name,
                format!("declaring `{name}` without the prefix {}", prefixes[0]),
            ));
        }
        if !seen.insert(name.clone()) {
            problems.push(breaks(file_name, format!("declaring `{name}` twice")));
        }
    }
    problems
}

fn breaks(file_name: &str, what: String) -> Diagnostic {
    Diagnostic::error(
        "E900",
        format!("gsdc generated {file_name} {what}; nothing was written"),
    )
    .help("this is a bug in gsdc: please report it with the description")
}

/// The names a header declares at file scope: macros, the types of
/// `typedef struct`/`enum` and function pointers, enumerators, functions,
/// and the names of compile-time checks (types in C99).
pub(crate) fn declared_names(text: &str) -> Vec<String> {
    let mut names = Vec::new();
    for line in text.lines() {
        let found = if let Some(rest) = line.strip_prefix("#define ") {
            identifier_at_start(rest)
        } else if let Some(rest) = line.strip_prefix("} ") {
            rest.strip_suffix(';').and_then(identifier_at_start)
        } else if line.starts_with("static inline ") {
            line.split('(')
                .next()
                .and_then(|head| head.rsplit([' ', '*']).next())
        } else if line.starts_with("typedef ") && line.contains("(*") {
            line.split("(*").nth(1).and_then(identifier_at_start)
        } else {
            enumerator(line)
        };
        names.extend(found.map(str::to_string));
    }
    names.extend(check_names(text));
    names
}

/// The last argument of each `GSDC_STATIC_ASSERT(condition, name);`, which
/// may wrap onto the next line.
fn check_names(text: &str) -> Vec<String> {
    text.split("GSDC_STATIC_ASSERT(")
        .skip(1)
        .filter_map(|rest| {
            let call = rest.split(");").next()?;
            let name = call.rsplit(',').next()?.trim();
            identifier_at_start(name).filter(|n| *n == name)
        })
        .map(str::to_string)
        .collect()
}

/// `    GSDC_PRM_OK = 0,`: an enumerator, upper case on a line of its own.
fn enumerator(line: &str) -> Option<&str> {
    let name = identifier_at_start(line.strip_prefix("    ")?)?;
    let rest = &line[4 + name.len()..];
    let upper = name.bytes().all(|b| !b.is_ascii_lowercase());
    (upper && (rest.is_empty() || rest == "," || rest.starts_with(" = "))).then_some(name)
}

fn identifier_at_start(text: &str) -> Option<&str> {
    let end = text
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(text.len());
    (end > 0).then(|| &text[..end])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn load(name: &str, text: &str) -> Ir {
        crate::testing::load(name, text).0.unwrap()
    }

    fn md810() -> Ir {
        load(
            "md810dp.toml",
            include_str!("../../descriptions/md810dp.toml"),
        )
    }

    /// One typo in the template (`m.pzd_wordz`) fails the rendering instead
    /// of writing a layout without the telegram's size.
    #[test]
    fn a_misspelt_name_in_the_template_is_an_error_not_empty_text() {
        let ir = md810();
        assert!(render(TEMPLATE, &ir).is_ok());
        let typo = TEMPLATE.replace("m.pzd_words", "m.pzd_wordz");
        assert_ne!(typo, TEMPLATE);
        let error = render(&typo, &ir).unwrap_err();
        assert_eq!(error.kind(), minijinja::ErrorKind::UndefinedError);
    }

    #[test]
    fn prefixes_and_file_names_come_from_the_stem() {
        let ir = md810();
        assert_eq!(file_name(&ir), "md810dp_layout.h");
        assert_eq!(prefix(&ir).upper_snake(), "MD810DP");
        let text = include_str!("../../descriptions/mv810-pnet02.toml");
        let ir = load("mv810-pnet02.toml", text);
        assert_eq!(file_name(&ir), "mv810_pnet02_layout.h");
        assert_eq!(prefix(&ir).snake(), "mv810_pnet02");
        let ir = load("9kdp1.toml", include_str!("../../descriptions/9kdp1.toml"));
        assert_eq!(file_name(&ir), "9kdp1_layout.h");
        assert_eq!(prefix(&ir).upper_snake(), "GSDC_9KDP1");
    }

    /// A gateway whose stem spells the support header's `gsdc` (or no word,
    /// which gave it the fallback `gsdc`) declared `gsdc_node_totals` twice:
    /// E900, a bug in gsdc, for a description the loader accepts. Its prefix
    /// is `layout` now, and the header passes its verification.
    #[test]
    fn a_stem_that_spells_gsdc_gets_a_prefix_of_its_own() {
        let text = include_str!("../../descriptions/md810-gateway.toml");
        for (name, expected) in [
            ("gsdc.toml", "layout_gsdc"),
            ("Gsdc.toml", "layout_gsdc"),
            ("gsdc-prm.toml", "layout_gsdc_prm"),
            ("_.toml", "layout"),
            ("é.toml", "layout"),
            ("网关.toml", "layout"),
            ("gsdc_9.toml", "gsdc_9"),
            ("gsdcx.toml", "gsdcx"),
        ] {
            let ir = load(name, text);
            assert_eq!(prefix(&ir).snake(), expected, "{name}");
            assert!(crate::compile(&ir).is_ok(), "{name}");
        }
    }

    /// A timeout is a plain value: its bounds and default in decimal, and
    /// said to be a value, not a parameter address.
    #[test]
    fn a_range_of_plain_values_is_written_in_decimal() {
        let header = emit(&crate::testing::mv810_with_timeout());
        for line in [
            "Communication timeout (P43.24)\" holds a value from 0 to 60000.",
            "#define MV810_PNET02_SETTINGS_ALLOWED_2_MIN 0U\n",
            "#define MV810_PNET02_SETTINGS_ALLOWED_2_MAX 60000U\n",
            "#define MV810_PNET02_SETTINGS_2_DEFAULT 100U\n",
        ] {
            assert!(header.contains(line), "{line}\n{header}");
        }
        assert!(!header.contains("0xEA60"), "{header}");
    }

    #[test]
    fn the_support_header_says_which_release_wrote_it() {
        assert_eq!(SUPPORT.matches(SUPPORT_VERSION_LINE).count(), 1);
        let support = String::from_utf8(support_header().contents).unwrap();
        let version = format!("#define GSDC_SUPPORT_VERSION {}\n", support_version());
        assert!(support.contains(&version), "{support}");
        assert!(!support.contains(SUPPORT_VERSION_LINE));
        // 0.1.0 is 100; 1.2.3 would be 10203.
        let [major, minor, patch] = [
            env!("CARGO_PKG_VERSION_MAJOR"),
            env!("CARGO_PKG_VERSION_MINOR"),
            env!("CARGO_PKG_VERSION_PATCH"),
        ]
        .map(|p| p.parse::<u32>().unwrap());
        assert_eq!(support_version(), major * 10000 + minor * 100 + patch);
    }

    #[test]
    fn every_shipped_layout_passes_verification() {
        for (name, text) in [
            (
                "md810dp.toml",
                include_str!("../../descriptions/md810dp.toml"),
            ),
            (
                "mv810-pnet02.toml",
                include_str!("../../descriptions/mv810-pnet02.toml"),
            ),
            ("9kdp1.toml", include_str!("../../descriptions/9kdp1.toml")),
            (
                "md810-gateway.toml",
                include_str!("../../descriptions/md810-gateway.toml"),
            ),
        ] {
            let ir = load(name, text);
            let header = emit(&ir);
            assert_eq!(verify(&ir, &file_name(&ir), &header), [], "{name}");
            assert!(declared_names(&header).len() > 50, "{name}");
        }
    }

    /// The scanner finds each kind of declaration, so verification sees
    /// every name the template writes.
    #[test]
    fn declarations_of_every_kind_are_found() {
        let text = "#define A_X 1U\n\
                    typedef struct {\n    uint8_t bytes[2];\n} a_t;\n\
                    GSDC_STATIC_ASSERT(sizeof(a_t) == 2U, a_size);\n\
                    GSDC_STATIC_ASSERT(1U + 2U ==\n                   3U, a_sum);\n\
                    static inline bool a_is_value(uint16_t value)\n\
                    typedef bool (*a_fn_t)(size_t index, uint16_t value);\n";
        let mut names = declared_names(text);
        names.sort();
        assert_eq!(
            names,
            ["A_X", "a_fn_t", "a_is_value", "a_size", "a_sum", "a_t"]
        );
        let support = declared_names(SUPPORT);
        for name in [
            "GSDC_SUPPORT_H",
            "gsdc_prm_result_t",
            "gsdc_entry_allows_t",
            "gsdc_pke_request_decode",
            "GSDC_PRM_OK",
            "GSDC_PKW_BAD_READ_COUNT",
        ] {
            assert!(support.iter().any(|n| n == name), "{name}");
        }
    }

    /// A status word whose field is named like a value of another field
    /// spells one C macro twice: refused, not written.
    #[test]
    fn a_name_declared_twice_or_without_the_prefix_is_refused() {
        let ir = md810();
        let header = emit(&ir);
        let twice = header.replace(
            "#define MD810DP_FINGERPRINT",
            "#define MD810DP_PPO1_BYTES 1U\n#define MD810DP_FINGERPRINT",
        );
        let problems = verify(&ir, "md810dp_layout.h", &twice);
        assert_eq!(problems.len(), 1, "{problems:?}");
        assert_eq!(problems[0].code, "E900");
        assert!(problems[0].message.contains("`MD810DP_PPO1_BYTES` twice"));
        let clash = header.replace(
            "#define MD810DP_FINGERPRINT",
            "#define GSDC_PKW_BYTES 8U\n#define MD810DP_FINGERPRINT",
        );
        let messages: Vec<_> = verify(&ir, "md810dp_layout.h", &clash)
            .into_iter()
            .map(|d| d.message)
            .collect();
        assert_eq!(messages.len(), 2, "{messages:?}");
        assert!(messages[0].contains("`GSDC_PKW_BYTES` without the prefix MD810DP_"));
        assert!(messages[1].contains("`GSDC_PKW_BYTES` twice"));
    }

    /// Rust keeps a field's mask and its values apart, a diagnosis area's
    /// bits and its values, a gateway's diagnosis types and their codes; C
    /// does not. A value whose C name meets another takes its number, as in
    /// Rust, and the layout is written: such names used to be E900, a bug in
    /// gsdc, for descriptions the loader accepts.
    #[test]
    fn a_value_whose_c_name_meets_another_takes_its_number() {
        let word = include_str!("../../descriptions/mv810-pnet02.toml")
            .replace("en = \"Asynchronous\"", "en = \"Mask\"");
        let area = include_str!("../../descriptions/md810dp.toml").replace(
            "[[profibus.diagnosis.areas]]",
            "[[profibus.diagnosis.areas]]\nbit = [7, 7]\nvalues = [{ value = 1, text = \"Last\" }]\n\n[[profibus.diagnosis.areas]]",
        );
        let gateway = include_str!("../../descriptions/md810-gateway.toml")
            .replace(
                "en = \"CANopen network fault\"",
                "en = \"Parameter error code node\"",
            )
            .replace(
                "en = \"Node in the configuration not online\"",
                "en = \"Node\"",
            )
            .replace("en = \"Drive reports fault\"", "en = \"Type at\"");
        for (name, text, declared) in [
            (
                "mv810-pnet02.toml",
                word,
                "#define MV810_PNET02_STATUS_WORD_MOTOR_TYPE_MASK_0 0U",
            ),
            (
                "md810dp.toml",
                area,
                "#define MD810DP_DIAGNOSIS_BIT_7_LAST_1 1U",
            ),
            (
                "md810-gateway.toml",
                gateway,
                "#define MD810_GATEWAY_DIAG_PARAMETER_ERROR_CODE_NODE_34 34U",
            ),
        ] {
            let ir = load(name, &text);
            let files = crate::compile(&ir).unwrap_or_else(|e| panic!("{name}: {e:?}"));
            let header = files
                .iter()
                .find(|f| f.kind == ArtifactKind::CHeader)
                .unwrap();
            let header = String::from_utf8_lossy(&header.contents);
            assert!(header.contains(declared), "{name}: {declared}");
        }
    }

    #[test]
    fn texts_cannot_break_out_of_comments_or_strings() {
        assert_eq!(comment_text("a */ b /* c ?? d"), "a * / b / * c ? ? d");
        assert_eq!(comment_text("a ???/ b"), "a ? ? ?/ b");
        assert_eq!(comment_text("**/"), "** /");
        assert_eq!(
            c_string("a \"b\" \\ ??= 中"),
            "\"a \\\"b\\\" \\\\ \\?\\?= \\344\\270\\255\""
        );
        assert_eq!(c_string("\u{1}7"), "\"\\0017\"");
        assert_eq!(comment_text("a\u{202E}b\u{7}c\nd"), "a<U+202E>b<U+0007>c d");
    }

    #[test]
    fn comments_and_initializers_wrap() {
        assert_eq!(comment("short"), "/* short */");
        let long = comment(&"word ".repeat(40));
        let lines: Vec<_> = long.lines().collect();
        assert!(lines.len() > 1);
        assert!(lines.iter().all(|l| l.len() <= WIDTH), "{long}");
        assert!(lines[0].starts_with("/* word"));
        assert!(lines[1..].iter().all(|l| l.starts_with(" * word")));
        assert!(long.ends_with("word */"));
        let member = indented_comment(&"word ".repeat(40), 4);
        assert!(member.lines().all(|l| l.len() <= WIDTH), "{member}");
        assert!(member.starts_with("    /* word"));
        assert!(member.lines().skip(1).all(|l| l.starts_with("     * word")));
        assert_eq!(
            initializer("X", &["1U".into(), "2U".into()]),
            "#define X { 1U, 2U }"
        );
        let values: Vec<String> = (0..30).map(|i| format!("0x{i:04X}U")).collect();
        let wrapped = initializer("X", &values);
        assert!(wrapped.lines().all(|l| l.len() <= WIDTH), "{wrapped}");
        assert!(wrapped.lines().rev().skip(1).all(|l| l.ends_with(" \\")));
        assert!(wrapped.ends_with("0x001DU }"));
        assert_eq!(wrapped.matches("0x").count(), 30);
    }

    #[test]
    fn range_checks_leave_out_what_an_unsigned16_always_passes() {
        assert_eq!(
            range_check("R", 0, 0xFFFF),
            ["(void)value;", "return true;"]
        );
        assert_eq!(range_check("R", 0, 0x10), ["return (value <= R_MAX);"]);
        assert_eq!(range_check("R", 1, 0xFFFF), ["return (value >= R_MIN);"]);
        assert_eq!(
            range_check("R", 1, 2),
            ["return (value >= R_MIN) && (value <= R_MAX);"]
        );
    }
}
