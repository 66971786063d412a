//! The GSD emitter: IR to a GSD file through `templates/gsd.jinja`, then
//! wrapped to 80 columns with `\` continuations and given CRLF line ends.

use crate::ir::gateway::Gateway;
use crate::ir::profibus::{DpSafety, PrmHolds, PrmParam, PrmTextOf, Profibus};
use crate::ir::{Allowed, Choice, Ir};
use serde::Serialize;

const TEMPLATE: &str = include_str!("../../templates/gsd.jinja");
/// Longest line gsdc writes, line end excluded; keys are padded to
/// KEY_WIDTH so the `=` line up.
use crate::spec::{GSD_KEY_WIDTH as KEY_WIDTH, GSD_LINE_WIDTH as MAX_LINE};

#[derive(Serialize)]
struct Context<'a> {
    file_name: &'a str,
    generator: String,
    source: &'a str,
    fingerprint: String,
    gsd_revision: u8,
    vendor: &'a str,
    model: &'a str,
    revision: &'a str,
    ident_number: String,
    /// Header comment lines, each within the line limit.
    notes: Vec<String>,
    hardware_release: &'a str,
    software_release: &'a str,
    order_number: Option<&'a str>,
    implementation_type: Option<&'a str>,
    info_text: Option<&'a str>,
    bitmap_device: Option<&'a str>,
    baud_rates: Vec<Rate>,
    freeze_mode: u8,
    sync_mode: u8,
    fail_safe: u8,
    auto_baud: u8,
    min_slave_interval: u16,
    max_input_len: u16,
    max_output_len: u16,
    max_data_len: u16,
    max_module: u8,
    modular_station: u8,
    /// Which of the four limits above the GSD writes.
    limits: Limits,
    features: Features,
    slave_family: &'a str,
    max_diag_data_len: u8,
    diag_areas: Vec<DiagArea<'a>>,
    diag_bits: Vec<DiagBit<'a>>,
    /// `UnitDiagType = n` blocks.
    diag_types: Vec<DiagType<'a>>,
    /// `Channel_Diag(n)`: each error type and its text.
    channel_diagnosis: Vec<Value<'a>>,
    dpv1: Option<Dpv1>,
    /// Prm_Block_Structure and isochronous mode (GSD revision 4), as stated.
    dp_v2: Vec<(&'static str, u32)>,
    vendor_keywords: &'a [(String, String)],
    prm_len: u16,
    /// Max_User_Prm_Data_Len: the telegram's length, or more when stated;
    /// unwritten when 0 and unstated (a slave without parameters).
    prm_max_len: Option<u16>,
    prm_const: Option<String>,
    /// The constant bytes are exactly the DPV1 status bytes.
    prm_const_is_status: bool,
    prm_texts: Vec<PrmText<'a>>,
    /// Every `ExtUserPrmData`: the device's, then the PROFIsafe modules'.
    definitions: Vec<Param<'a>>,
    /// `(offset, ExtUserPrmData number)` of the device's parameters: its
    /// `Ext_User_Prm_Data_Ref` lines.
    refs: Vec<(u16, u16)>,
    /// What the modules are, for the comment above them.
    modules_note: &'static str,
    modules: Vec<Module<'a>>,
}

#[derive(Serialize)]
struct Limits {
    max_module: bool,
    max_input_len: bool,
    max_output_len: bool,
    max_data_len: bool,
}

/// The DP keyword gsdc always writes (0 unless stated), and those it
/// writes only when stated.
#[derive(Serialize)]
struct Features {
    set_slave_address: u8,
    stated: Vec<(&'static str, u8)>,
}

#[derive(Serialize)]
struct Rate {
    name: &'static str,
    max_tsdr: u16,
}

#[derive(Serialize)]
struct Value<'a> {
    value: i64,
    text: &'a str,
}

/// `Unit_Diag_Bit(n)` or `Unit_Diag_Not_Bit(n)` and its text.
#[derive(Serialize)]
struct DiagBit<'a> {
    keyword: String,
    bit: u16,
    text: &'a str,
}

#[derive(Serialize)]
struct DiagArea<'a> {
    first: u16,
    last: u16,
    /// Comment lines saying what the area shows, when the IR says it.
    notes: Vec<String>,
    values: Vec<Value<'a>>,
}

#[derive(Serialize)]
struct DiagType<'a> {
    id: u8,
    areas: Vec<DiagArea<'a>>,
    bits: Vec<DiagBit<'a>>,
}

#[derive(Serialize)]
struct Dpv1 {
    c1_read_write: u8,
    c1_max_data_len: u8,
    c1_response_timeout: u16,
    c2: Option<Class2>,
    ident_maintenance: u8,
    /// DPV1_Data_Types, Check_Cfg_Mode and the alarm keywords, when stated.
    stated: Vec<(&'static str, u8)>,
}

#[derive(Serialize)]
struct Class2 {
    max_data_len: u8,
    response_timeout: u16,
    max_count_channels: u8,
    max_initiate_pdu_length: u8,
}

#[derive(Serialize)]
struct PrmText<'a> {
    id: u16,
    values: Vec<Value<'a>>,
}

#[derive(Serialize)]
struct Param<'a> {
    id: u16,
    name: &'a str,
    data_type: String,
    default: u16,
    allowed: String,
    text_ref: Option<u16>,
    offset: u16,
    /// `Changeable = 0` and `Visible = 0` when so.
    fixed: bool,
    hidden: bool,
}

#[derive(Serialize)]
struct Module<'a> {
    name: &'a str,
    config: String,
    reference: Option<u16>,
    info: Option<&'a str>,
    safety: Option<ModuleSafety>,
}

/// A PROFIsafe module's F-parameter block and CRCs, as its lines say them.
#[derive(Serialize)]
struct ModuleSafety {
    len: u16,
    constant: Option<String>,
    /// `(offset, ExtUserPrmData number)` of each parameter.
    refs: Vec<(u16, u16)>,
    f_param_desc: String,
    f_io_structure_desc: u32,
}

/// The GSD text of a description with a PROFIBUS part.
pub fn emit(ir: &Ir, profibus: &Profibus) -> String {
    let rendered = render(TEMPLATE, ir, profibus)
        .expect("the GSD template renders every IR with a PROFIBUS part (tested)");
    finish(&rendered)
}

fn render(template: &str, ir: &Ir, profibus: &Profibus) -> Result<String, minijinja::Error> {
    let mut env = super::strict_templates();
    // At least one space after a key as long as the column or longer
    // (Manufacturer_Specific_Alarm_supp).
    env.add_filter("key", |key: String| format!("{:<KEY_WIDTH$}", key + " "));
    env.template_from_str(template)?
        .render(context(ir, profibus))
}

fn context<'a>(ir: &'a Ir, p: &'a Profibus) -> Context<'a> {
    let d = &ir.device;
    Context {
        file_name: &p.file_name,
        generator: crate::GENERATOR.to_string(),
        source: &ir.source_name,
        fingerprint: ir.fingerprint.to_string(),
        gsd_revision: p.gsd_revision,
        vendor: &d.vendor,
        model: &d.model,
        revision: &p.releases.revision,
        ident_number: super::hex16(p.ident_number),
        notes: notes(ir),
        hardware_release: &p.releases.hardware_release,
        software_release: &p.releases.software_release,
        order_number: d.order_number.as_deref(),
        implementation_type: p.implementation_type.as_deref(),
        info_text: p.info_text.as_deref(),
        bitmap_device: p.bitmap_device.as_deref(),
        baud_rates: p
            .baud_rates
            .iter()
            .map(|&(baud, max_tsdr)| Rate {
                name: baud.as_str(),
                max_tsdr,
            })
            .collect(),
        freeze_mode: p.freeze_mode.into(),
        sync_mode: p.sync_mode.into(),
        fail_safe: p.fail_safe.into(),
        auto_baud: p.auto_baud.into(),
        min_slave_interval: p.min_slave_interval,
        max_input_len: p.max_input_len,
        max_output_len: p.max_output_len,
        max_data_len: p.max_data_len,
        max_module: p.max_module,
        modular_station: p.modular_station.into(),
        limits: Limits {
            max_module: p.limits_written.max_module,
            max_input_len: p.limits_written.max_input_len,
            max_output_len: p.limits_written.max_output_len,
            max_data_len: p.limits_written.max_data_len,
        },
        features: features(p),
        slave_family: &p.slave_family,
        max_diag_data_len: p.max_diag_data_len,
        diag_areas: diag_areas(ir, p),
        diag_bits: diag_bits(p.diagnosis.iter().flat_map(|d| &d.bits), ""),
        diag_types: p
            .diagnosis_types
            .iter()
            .map(|t| DiagType {
                id: t.id,
                areas: t.areas.iter().map(plain_area).collect(),
                bits: diag_bits(t.bits.iter(), "X_"),
            })
            .collect(),
        channel_diagnosis: p
            .channel_diagnosis
            .iter()
            .map(|c| Value {
                value: c.error_type.into(),
                text: c.name.for_gsd(),
            })
            .collect(),
        dpv1: p.dpv1.map(|d| Dpv1 {
            c1_read_write: d.c1_read_write.into(),
            c1_max_data_len: d.c1_max_data_len,
            c1_response_timeout: d.c1_response_timeout,
            c2: d.c2.map(|c2| Class2 {
                max_data_len: c2.max_data_len,
                response_timeout: c2.response_timeout,
                max_count_channels: c2.max_count_channels,
                max_initiate_pdu_length: c2.max_initiate_pdu_length,
            }),
            ident_maintenance: d.ident_maintenance.into(),
            stated: [
                stated(&[
                    ("DPV1_Data_Types", d.data_types),
                    ("Check_Cfg_Mode", d.check_cfg_mode),
                    ("C1_Read_Write_required", d.c1_read_write_required),
                    ("C2_Read_Write_required", d.c2_read_write_required),
                ]),
                d.alarms.map(alarm_keywords).unwrap_or_default(),
            ]
            .concat(),
        }),
        dp_v2: dp_v2(p),
        vendor_keywords: &p.vendor_keywords,
        prm_len: p.user_prm.len,
        prm_max_len: match p.user_prm.max_len {
            Some(max) => Some(max.into()),
            None => (p.user_prm.len > 0).then_some(p.user_prm.len),
        },
        prm_const: (!p.user_prm.constant.is_empty()).then(|| hex_list(&p.user_prm.constant)),
        prm_const_is_status: p
            .dpv1
            .is_some_and(|d| d.status_bytes[..] == p.user_prm.constant[..]),
        prm_texts: p
            .user_prm
            .texts
            .iter()
            .map(|t| {
                let allowed = match t.of {
                    PrmTextOf::Set(set) => &ir.mappings.set(set).allowed,
                    PrmTextOf::Card(index) => &p.user_prm.card_params[index].allowed,
                };
                PrmText {
                    id: t.id,
                    values: allowed
                        .choices()
                        .map_or_else(Vec::new, |v| values(&v.choices)),
                }
            })
            .collect(),
        refs: p.user_prm.params().map(|p| (p.offset, p.id)).collect(),
        definitions: params(
            ir,
            p.user_prm.params().chain(
                p.modules
                    .iter()
                    .flat_map(|m| m.safety.iter().flat_map(|s| &s.params)),
            ),
        ),
        modules_note: match ir.gateway {
            Some(_) => "word blocks; plug them until INPUT and OUTPUT equal the nodes' words",
            None if p.modules.iter().all(|m| m.ppo.is_some()) => "one PPO type at a time",
            None => "the card's own",
        },
        modules: match &ir.gateway {
            Some(g) => gateway_modules(g),
            None => p
                .modules
                .iter()
                .map(|m| Module {
                    name: &m.name,
                    config: hex_list(&m.config),
                    reference: m.reference,
                    info: m.info.as_deref(),
                    safety: m.safety.as_ref().map(module_safety),
                })
                .collect(),
        },
    }
}

fn features(p: &Profibus) -> Features {
    let f = &p.features;
    let flag = |v: Option<bool>| v.map(u8::from);
    Features {
        set_slave_address: f.set_slave_address.unwrap_or(false).into(),
        stated: stated(&[
            ("Fail_Safe_required", flag(f.fail_safe_required)),
            ("Redundancy", flag(f.redundancy)),
            ("Repeater_Ctrl_Sig", f.repeater_ctrl_sig),
            ("24V_Pins", f.pins_24v),
            ("WD_Base_1ms_supp", flag(f.wd_base_1ms)),
            ("Publisher_supp", flag(f.publisher)),
            ("Modul_Offset", f.modul_offset),
        ]),
    }
}

/// The keywords among `keywords` a description states, with their values.
/// The alarm keywords: each kind supported, then each required, then the
/// modes, as stated.
fn alarm_keywords(a: crate::ir::profibus::Alarms) -> Vec<(&'static str, u8)> {
    let kinds = crate::ir::profibus::AlarmKind::ALL;
    let flagged = |flags: [bool; 6], required: bool| {
        kinds
            .into_iter()
            .zip(flags)
            .filter(|(_, on)| *on)
            .map(move |(k, _)| {
                let (supp, req) = k.keywords();
                (if required { req } else { supp }, 1)
            })
    };
    flagged(a.supported, false)
        .chain(flagged(a.required, true))
        .chain(stated(&[
            ("Alarm_Type_Mode_supp", a.type_mode),
            ("Extra_Alarm_SAP_supp", a.extra_alarm_sap),
        ]))
        .chain(stated(&[(
            "Alarm_Sequence_Mode_Count",
            a.sequence_mode_count,
        )]))
        .collect()
}

/// Prm_Block_Structure_supp and _req, then isochronous mode.
fn dp_v2(p: &crate::ir::profibus::Profibus) -> Vec<(&'static str, u32)> {
    use crate::ir::profibus::BlockStructure;
    let mut out = Vec::new();
    if let Some(b) = p.prm_block_structure {
        out.push(("Prm_Block_Structure_supp", 1));
        out.push((
            "Prm_Block_Structure_req",
            u32::from(b == BlockStructure::Required),
        ));
    }
    if let Some(i) = p.isochronous {
        out.push(("Isochron_Mode_supp", 1));
        out.extend(i.required.map(|r| ("Isochron_Mode_required", u32::from(r))));
        out.extend([
            ("TBASE_DP", i.tbase_dp),
            ("TDP_MAX", i.tdp_max.into()),
            ("TDP_MIN", i.tdp_min.into()),
            ("TBASE_IO", i.tbase_io),
            ("TI_MIN", i.ti_min.into()),
            ("TO_MIN", i.to_min.into()),
            ("T_PLL_W_MAX", i.t_pll_w_max.into()),
        ]);
    }
    out
}

fn stated<T: Copy + Into<u8>>(keywords: &[(&'static str, Option<T>)]) -> Vec<(&'static str, u8)> {
    keywords
        .iter()
        .filter_map(|&(keyword, v)| Some((keyword, v?.into())))
        .collect()
}

fn gateway_modules(g: &Gateway) -> Vec<Module<'_>> {
    g.modules
        .iter()
        .map(|m| Module {
            name: &m.name,
            config: hex_list(&[m.config]),
            reference: Some(m.reference.into()),
            info: None,
            safety: None,
        })
        .collect()
}

fn module_safety(s: &DpSafety) -> ModuleSafety {
    ModuleSafety {
        len: s.len,
        constant: (!s.constant.is_empty()).then(|| hex_list(&s.constant)),
        refs: s.params.iter().map(|p| (p.offset, p.id)).collect(),
        f_param_desc: super::hex16(s.crcs.f_param_desc),
        f_io_structure_desc: s.crcs.f_io_structure_desc,
    }
}

/// `Unit_Diag_Bit` and `Unit_Diag_Not_Bit` lines, with `prefix` `X_` in a
/// `UnitDiagType`.
fn diag_bits<'a>(
    bits: impl Iterator<Item = &'a crate::ir::profibus::DiagnosisBit>,
    prefix: &str,
) -> Vec<DiagBit<'a>> {
    bits.map(|b| DiagBit {
        keyword: format!("{prefix}{}", b.keyword()),
        bit: b.bit,
        text: b.text.for_gsd(),
    })
    .collect()
}

fn plain_area(a: &crate::ir::profibus::DiagnosisArea) -> DiagArea<'_> {
    DiagArea {
        first: a.first_bit,
        last: a.last_bit,
        notes: Vec::new(),
        values: values(&a.values.choices),
    }
}

/// The PROFIBUS diagnosis' areas, or a gateway's, with their notes as
/// comment lines.
fn diag_areas<'a>(ir: &'a Ir, p: &'a Profibus) -> Vec<DiagArea<'a>> {
    let plain = p.diagnosis.iter().flat_map(|d| &d.areas).map(plain_area);
    let gateway = ir
        .gateway
        .iter()
        .flat_map(|g| &g.diagnosis)
        .flat_map(|d| &d.gsd_areas)
        .map(|a| DiagArea {
            first: a.first_bit,
            last: a.last_bit,
            notes: super::wrap_words(&a.note, MAX_LINE - "; ".len()),
            values: values(&a.values),
        });
    plain.chain(gateway).collect()
}

/// The header notes as GSD comment lines: 7-bit ASCII (a character beyond
/// it shows as `?`; lowering keeps reasons ASCII for descriptions with a GSD
/// (E102), so only a marked value in another language shows so), wrapped to
/// the line limit with continuation lines indented.
fn notes(ir: &Ir) -> Vec<String> {
    let width = MAX_LINE - "; ".len();
    super::header_notes(ir, super::ArtifactKind::Gsd)
        .iter()
        .flat_map(|note| {
            let ascii: String = note
                .chars()
                .map(|c| if c.is_ascii() { c } else { '?' })
                .collect();
            let lines = super::wrap_words(&ascii, width - 2);
            lines
                .into_iter()
                .enumerate()
                .map(|(i, line)| if i == 0 { line } else { format!("  {line}") })
                .collect::<Vec<_>>()
        })
        .collect()
}

fn values(choices: &[Choice]) -> Vec<Value<'_>> {
    choices
        .iter()
        .map(|c| Value {
            value: c.value,
            text: c.text.for_gsd(),
        })
        .collect()
}

fn params<'a>(ir: &'a Ir, params: impl Iterator<Item = &'a PrmParam>) -> Vec<Param<'a>> {
    params
        .map(|param| {
            let facts = ir.prm_facts(param);
            Param {
                id: param.id,
                name: facts.name.for_gsd(),
                data_type: param.data_type.to_string(),
                default: facts.default,
                allowed: match facts.holds {
                    PrmHolds::Mapping { set, .. } => allowed(&set.allowed),
                    PrmHolds::Card(p) => allowed(&p.allowed),
                    PrmHolds::Number { min, max } => format!("{min}-{max}"),
                },
                text_ref: param.text,
                offset: param.offset,
                fixed: matches!(facts.holds, PrmHolds::Card(p) if !p.changeable),
                hidden: matches!(facts.holds, PrmHolds::Card(p) if !p.visible),
            }
        })
        .collect()
}

/// `min-max`, or the list of values when they are not contiguous.
fn allowed(allowed: &Allowed) -> String {
    match allowed {
        Allowed::Range { min, max } => format!("{min}-{max}"),
        Allowed::Choices(set) => {
            let mut values: Vec<i64> = set.choices.iter().map(|c| c.value).collect();
            values.sort_unstable();
            let contiguous = values.windows(2).all(|w| w[1] == w[0] + 1);
            match (contiguous, values.first(), values.last()) {
                (true, Some(first), Some(last)) if first != last => format!("{first}-{last}"),
                _ => values
                    .iter()
                    .map(i64::to_string)
                    .collect::<Vec<_>>()
                    .join(","),
            }
        }
    }
}

fn hex_list(bytes: &[u8]) -> String {
    bytes
        .iter()
        .map(|&b| super::hex8(b))
        .collect::<Vec<_>>()
        .join(",")
}

/// Wraps long lines and turns line ends into CRLF.
fn finish(rendered: &str) -> String {
    let mut out = String::with_capacity(rendered.len() + rendered.len() / 16);
    for line in rendered.lines() {
        for piece in wrap(line) {
            out.push_str(&piece);
            out.push_str("\r\n");
        }
    }
    out
}

/// Splits a line longer than [`MAX_LINE`] into pieces ending in `\`, only
/// where GSD lets a line go on: inside a string, after a space where there
/// is one (readers join the pieces back without the `\` and the line end),
/// and elsewhere after a comma of a number list. A value without such a
/// place (a `Slave_Family`, which readers take to the end of its line) is
/// never cut; lowering keeps those short enough. A comment goes on as
/// comment lines instead: after a `\` its rest would be read as a statement.
fn wrap(line: &str) -> Vec<String> {
    if line.starts_with(';') {
        return wrap_comment(line);
    }
    let mut pieces = Vec::new();
    let mut rest = line;
    let mut in_string = false;
    while rest.chars().count() > MAX_LINE {
        let Some(cut) = break_point(rest, in_string) else {
            break;
        };
        in_string ^= rest[..cut].matches('"').count() % 2 == 1;
        pieces.push(format!("{}\\", &rest[..cut]));
        rest = &rest[cut..];
    }
    pieces.push(rest.to_string());
    pieces
}

/// How a comment's further lines start.
const COMMENT_CONTINUED: &str = ";   ";

/// A long comment as comment lines, each cut after a space where there is
/// one. Lengths count characters: a Latin-1 GSD's are a byte each in the
/// file, two of those beyond ASCII here.
fn wrap_comment(line: &str) -> Vec<String> {
    let mut pieces = Vec::new();
    let mut rest = line.to_string();
    while rest.chars().count() > MAX_LINE {
        let at = |n: usize| rest.char_indices().nth(n).map_or(rest.len(), |(i, _)| i);
        let cut = rest[..at(MAX_LINE + 1)]
            .rfind(' ')
            .filter(|&i| i > COMMENT_CONTINUED.len())
            .unwrap_or(at(MAX_LINE));
        pieces.push(rest[..cut].trim_end().to_string());
        rest = format!("{COMMENT_CONTINUED}{}", rest[cut..].trim_start());
    }
    pieces.push(rest);
    pieces
}

/// Byte index to cut `line` at, leaving room for the `\`: the last space in
/// a string or comma outside one within the limit (in characters), else the
/// limit itself when it falls inside a string; `None` when the line may not
/// be cut there.
fn break_point(line: &str, starts_in_string: bool) -> Option<usize> {
    let limit = MAX_LINE - 1;
    let mut in_string = starts_in_string;
    let mut best = None;
    // Where the `limit`th character starts: a cut in a string without a
    // space falls there, on a character's boundary (a Latin-1 string's
    // characters beyond ASCII are two bytes here).
    let mut at_limit = line.len();
    for (n, (i, c)) in line.char_indices().enumerate() {
        if n == limit {
            at_limit = i;
            break;
        }
        match c {
            '"' => in_string = !in_string,
            ' ' if in_string => best = Some(i + 1),
            ',' if !in_string => best = Some(i + 1),
            _ => {}
        }
    }
    best.or(in_string.then_some(at_limit))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_misspelt_name_in_the_template_is_an_error_not_empty_text() {
        let text = include_str!("../../descriptions/md810dp.toml");
        let ir = crate::testing::load("md810dp.toml", text).0.unwrap();
        let profibus = ir.profibus.as_ref().unwrap();
        assert!(render(TEMPLATE, &ir, profibus).is_ok());
        let typo = TEMPLATE.replace("max_input_len", "max_inptu_len");
        let error = render(&typo, &ir, profibus).unwrap_err();
        assert_eq!(error.kind(), minijinja::ErrorKind::UndefinedError);
    }

    #[test]
    fn short_lines_stay_whole() {
        assert_eq!(wrap("Vendor_Name = \"x\""), ["Vendor_Name = \"x\""]);
    }

    #[test]
    fn long_strings_break_after_a_space_and_join_back() {
        let text = "word ".repeat(40);
        let line = format!("Info_Text = \"{}\"", text.trim_end());
        let pieces = wrap(&line);
        assert!(pieces.len() > 1);
        assert!(pieces.iter().all(|p| p.len() <= MAX_LINE));
        assert!(pieces[..pieces.len() - 1]
            .iter()
            .all(|p| p.ends_with(" \\")));
        let joined: String = pieces.iter().map(|p| p.trim_end_matches('\\')).collect();
        assert_eq!(joined, line);
    }

    #[test]
    fn a_long_word_in_a_string_is_cut_inside_the_string() {
        let line = format!("Info_Text = \"{}\"", "x".repeat(200));
        let pieces = wrap(&line);
        assert!(pieces.iter().all(|p| p.len() <= MAX_LINE));
        let joined: String = pieces.iter().map(|p| p.trim_end_matches('\\')).collect();
        assert_eq!(joined, line);
    }

    /// A Latin-1 GSD's characters beyond ASCII (two bytes in Rust, one in
    /// the file) are cut between, never inside, and counted as one: a word
    /// of them in a string, and a comment of them.
    #[test]
    fn latin1_characters_count_as_one_and_are_never_cut_inside() {
        let chars = |p: &String| p.chars().count();
        // `a` puts the limit inside a two-byte character.
        let line = format!("Info_Text = \"a{}\"", "\u{ff}".repeat(100));
        let pieces = wrap(&line);
        assert!(pieces.len() > 1 && pieces.iter().all(|p| chars(p) <= MAX_LINE));
        let joined: String = pieces.iter().map(|p| p.trim_end_matches('\\')).collect();
        assert_eq!(joined, line);
        let comment = format!("; {}", "\u{e9}".repeat(100));
        let pieces = wrap(&comment);
        assert!(pieces.len() > 1 && pieces.iter().all(|p| chars(p) <= MAX_LINE));
        let kept: String = pieces
            .iter()
            .map(|p| p.trim_start_matches(';').trim())
            .collect();
        assert_eq!(kept, "\u{e9}".repeat(100));
    }

    #[test]
    fn a_value_readers_take_to_the_end_of_the_line_is_never_cut() {
        let line = format!("Slave_Family = 1@{}", "Sub".repeat(30));
        assert_eq!(wrap(&line), [line]);
    }

    #[test]
    fn a_long_comment_goes_on_as_comment_lines() {
        let line = format!("; from {}.toml; do not edit", "n".repeat(150));
        let pieces = wrap(&line);
        assert!(pieces.len() > 2);
        assert!(pieces
            .iter()
            .all(|p| p.len() <= MAX_LINE && p.starts_with(';')));
        assert!(pieces.iter().all(|p| !p.ends_with('\\')));
        let words: String = pieces
            .iter()
            .map(|p| p.trim_start_matches(';').trim())
            .collect::<Vec<_>>()
            .join(" ");
        assert_eq!(words.replace(' ', ""), line[1..].replace(' ', ""));
    }

    #[test]
    fn long_number_lists_break_after_a_comma() {
        let line = format!("Ext_User_Prm_Data_Const(0) = {}", hex_list(&[0xAB; 30]));
        let pieces = wrap(&line);
        assert!(pieces.iter().all(|p| p.len() <= MAX_LINE));
        assert!(pieces[..pieces.len() - 1]
            .iter()
            .all(|p| p.ends_with(",\\")));
        let joined: String = pieces.iter().map(|p| p.trim_end_matches('\\')).collect();
        assert_eq!(joined, line);
    }

    #[test]
    fn allowed_values_are_a_range_when_contiguous() {
        assert_eq!(allowed(&Allowed::Range { min: 0, max: 65535 }), "0-65535");
        assert_eq!(allowed(&Allowed::of_values(&[2, 0, 1])), "0-2");
        assert_eq!(allowed(&Allowed::of_values(&[0, 5])), "0,5");
        assert_eq!(allowed(&Allowed::of_values(&[7])), "7");
    }
}
