//! The firmware layout of a description, language-neutral: its parts in
//! the order both layouts declare them, each item with its name (an
//! [`Ident`]), its numbers and its sentence ([`Doc`]), built once from the
//! IR. The Rust and C emitters walk the same model in their templates and
//! add only what is their own: the spelling of names and references, C's
//! prefix, macro initializers and name checks, Rust's support module and
//! generic telegram types. A fact added here reaches both languages.
//!
//! Each language declares some things the other does not (a C function
//! where Rust has a method, a Rust array where C has a count): their
//! sentences are the language's own, in its template.

mod doc;
mod gateway;
mod mappings;
pub(crate) mod tables;

pub(crate) use doc::{Doc, PkwItem, Ref, Scope, Val};
pub(crate) use gateway::Gateway;
pub(crate) use mappings::Group;

use super::bit_range;
use crate::ir::profibus::{self, Profibus as IrProfibus};
use crate::ir::profinet::{self, Profinet as IrProfinet};
use crate::ir::safety::SafetyModule;
use crate::ir::{Bus, CyclicModule, Direction, Ident, Ir, ValueSet as IrValueSet, Word as IrWord};
use serde::Serialize;

#[derive(Serialize)]
pub(crate) struct Layout {
    /// The PKW channel and its codec, for a telegram that has one.
    pub pkw: Option<Doc>,
    pub fingerprint: Consts,
    /// Each PPO type, then each PROFINET module.
    pub modules: Vec<Module>,
    /// The control word, then the status word, those the description has.
    pub words: Vec<Word>,
    pub groups: Vec<Group>,
    pub profibus: Option<Profibus>,
    pub gateway: Option<Gateway>,
    /// PROFINET's constants.
    pub profinet: Vec<Consts>,
    /// The device tables, which each language writes on its own.
    #[serde(skip)]
    pub tables: Vec<tables::Table>,
}

/// Constants under one sentence.
#[derive(Serialize)]
pub(crate) struct Consts {
    pub doc: Doc,
    pub items: Vec<Const>,
}

#[derive(Serialize)]
pub(crate) struct Const {
    pub name: Ident,
    pub ty: Ty,
    pub value: Val,
}

/// What a constant holds, for a language that declares its type.
#[derive(Serialize, Clone, Copy)]
#[serde(rename_all = "snake_case")]
pub(crate) enum Ty {
    U8,
    U16,
    U32,
    /// A length or a count.
    Size,
    Text,
}

impl Consts {
    fn one(doc: Doc, name: &[&str], ty: Ty, value: Val) -> Self {
        Consts {
            doc,
            items: vec![Const::new(name, ty, value)],
        }
    }
}

impl Const {
    fn new(name: &[&str], ty: Ty, value: Val) -> Self {
        Const {
            name: Ident::of(name),
            ty,
            value,
        }
    }
}

/// Bytes under a name: an array in Rust, a macro initializer in C.
#[derive(Serialize)]
pub(crate) struct Bytes {
    pub name: Ident,
    pub doc: Doc,
    pub bytes: Vec<Val>,
}

fn bytes(name: Ident, doc: Doc, bytes: &[u8]) -> Bytes {
    Bytes {
        name,
        doc,
        bytes: bytes.iter().map(|&b| Val::hex_u8(b)).collect(),
    }
}

/// A set of values with their meanings: a Rust enum, C macros.
#[derive(Serialize)]
pub(crate) struct ValueSet {
    pub name: Ident,
    /// For a language that declares the set as one item.
    pub doc: Doc,
    pub choices: Vec<Choice>,
}

#[derive(Serialize)]
pub(crate) struct Choice {
    pub name: Ident,
    pub doc: Doc,
    pub value: i64,
}

fn value_set(values: &IrValueSet, doc: Doc) -> ValueSet {
    ValueSet {
        name: values.ident.clone(),
        doc,
        choices: values
            .choices
            .iter()
            .map(|c| Choice {
                name: c.ident.clone(),
                doc: Doc::plain(format!("{}.", c.text.en)),
                value: c.value,
            })
            .collect(),
    }
}

/// The layout of `ir`.
pub(crate) fn build(ir: &Ir) -> Layout {
    Layout {
        pkw: pkw(ir),
        fingerprint: Consts::one(
            Doc::plain(
                "The fingerprint of the description; the device files generated from it \
                 carry the same in their headers.",
            ),
            &["fingerprint"],
            Ty::Text,
            Val::Text(ir.fingerprint.to_string()),
        ),
        modules: ir.cyclic_modules().map(|m| module(ir, &m)).collect(),
        words: Direction::BOTH
            .iter()
            .filter_map(|&dir| Some(word(dir, ir.telegram.word(dir)?)))
            .collect(),
        groups: ir
            .mappings
            .groups
            .iter()
            .map(|g| mappings::group(ir, g))
            .collect(),
        profibus: ir.profibus.as_ref().map(|p| self::profibus(ir, p)),
        gateway: ir
            .gateway
            .as_ref()
            .zip(ir.profibus.as_ref())
            .map(|(g, p)| gateway::gateway(g, p)),
        profinet: ir.profinet.as_ref().map(self::profinet).unwrap_or_default(),
        tables: tables::tables(ir),
    }
}

fn pkw(ir: &Ir) -> Option<Doc> {
    let name = super::pkw_name(ir.telegram.pkw)?;
    Some(
        Doc::at(Scope::Root)
            .text(format!(
                "The PKW channel ({name}) in bytes 0-7 of the telegrams that have one: \
                 the master's requests are decoded with "
            ))
            .link(Ref::Pkw(PkwItem::RequestDecode))
            .text(" into ")
            .link(Ref::Pkw(PkwItem::Request))
            .text(", the drive's answers encoded from ")
            .link(Ref::Pkw(PkwItem::Response))
            .text(" with ")
            .link(Ref::Pkw(PkwItem::ResponseEncode))
            .text("."),
    )
}

// ---------------------------------------------------------------------------
// Telegrams

/// A PPO type or PROFINET module: its size and place of its words, the
/// same both ways, and its telegram each way.
#[derive(Serialize)]
pub(crate) struct Module {
    pub name: Ident,
    pub doc: Doc,
    pub bytes: u16,
    pub pzd_words: u8,
    /// Whether the PKW channel comes first.
    pub pkw: bool,
    pub telegrams: Vec<Telegram>,
}

/// One direction of a module: what it is beyond the module's sentence.
#[derive(Serialize)]
pub(crate) struct Telegram {
    pub name: Ident,
    pub doc: Doc,
}

fn module(ir: &Ir, m: &CyclicModule) -> Module {
    let words = match m.layout.pzd_words {
        1 => "PZD1".to_string(),
        n => format!("PZD1 to PZD{n}"),
    };
    let place = if m.layout.pkw {
        format!(
            "the PKW channel in bytes 0-7, {words} from byte {}",
            m.layout.pzd_offset()
        )
    } else {
        format!("{words} from byte 0")
    };
    let doc = match m.bus {
        Bus::Profibus => Doc::plain(format!("\"{}\" of {}", m.name, m.file_name)),
        Bus::Profinet => Doc::at(Scope::Root)
            .text(format!("PROFINET module \"{}\" (", m.name))
            .link(Ref::Const(Scope::Root, m.ident.tagged("ident")))
            .text(")"),
    };
    Module {
        name: m.ident.clone(),
        doc: doc.text(format!(": {} bytes each way, {place}.", m.layout.bytes())),
        bytes: m.layout.bytes(),
        pzd_words: m.layout.pzd_words,
        pkw: m.layout.pkw,
        telegrams: Direction::BOTH
            .iter()
            .map(|&dir| telegram(ir, m, dir))
            .collect(),
    }
}

fn telegram(ir: &Ir, m: &CyclicModule, dir: Direction) -> Telegram {
    let (suffix, way) = match dir {
        Direction::Out => ("out", "Master to drive"),
        Direction::In => ("in", "Drive to master"),
    };
    let doc = Doc::at(Scope::Root).text(way);
    let doc = match (m.is_profidrive(), ir.telegram.word(dir)) {
        (true, _) => doc.text(format!(": PROFIdrive {}.", profidrive_words(m, dir))),
        (false, Some(_)) => {
            let word = word_name(dir);
            doc.text(format!("; PZD1 is the {}, ", word.replace('_', " ")))
                .link(Ref::Part(Scope::part(word)))
                .text(".")
        }
        (false, None) => doc.text("."),
    };
    Telegram {
        name: m.ident.tagged(suffix),
        doc,
    }
}

/// A PROFIdrive telegram's words in `dir`, a 32-bit value with its PZD
/// words (the layouts carry words).
fn profidrive_words(m: &CyclicModule, dir: Direction) -> &'static str {
    let telegram_2 = m
        .profinet
        .is_some_and(|p| p.kind == profinet::ModuleKind::StandardTelegram2);
    match (telegram_2, dir) {
        (false, Direction::Out) => "STW1 and NSOLL_A",
        (false, Direction::In) => "ZSW1 and NIST_A",
        (true, Direction::Out) => {
            "STW1, NSOLL_B (32 bits: PZD2 the high word, PZD3 the low) and STW2"
        }
        (true, Direction::In) => {
            "ZSW1, NIST_B (32 bits: PZD2 the high word, PZD3 the low) and ZSW2"
        }
    }
}

// ---------------------------------------------------------------------------
// Control and status words

/// The word PZD1 carries, its bits with their values.
#[derive(Serialize)]
pub(crate) struct Word {
    pub name: Ident,
    pub doc: Doc,
    pub fields: Vec<Field>,
}

#[derive(Serialize)]
pub(crate) struct Field {
    pub name: Ident,
    pub doc: Doc,
    pub first: u8,
    pub last: u8,
    pub mask: Val,
    pub values: Option<ValueSet>,
}

fn word_name(dir: Direction) -> &'static str {
    match dir {
        Direction::Out => "control_word",
        Direction::In => "status_word",
    }
}

fn word(dir: Direction, word: &IrWord) -> Word {
    let way = match dir {
        Direction::Out => "master to drive",
        Direction::In => "drive to master",
    };
    let scope = Scope::part(word_name(dir));
    let fields = word
        .bits
        .iter()
        .map(|b| {
            let values = b.values.as_ref().map(|v| {
                let doc = Doc::at(scope.clone())
                    .text("The values of ")
                    .link(Ref::Const(scope.clone(), b.ident.clone()))
                    .text(".");
                value_set(v, doc)
            });
            let doc = Doc::at(scope.clone()).text(format!(
                "{}: {}",
                bit_range(b.first.into(), b.last.into()),
                b.name.en
            ));
            let doc = match &values {
                Some(v) => doc
                    .text("; values in ")
                    .link(Ref::Values(scope.clone(), v.name.clone()))
                    .text("."),
                None => doc.text("."),
            };
            Field {
                name: b.ident.clone(),
                doc,
                first: b.first,
                last: b.last,
                mask: Val::hex_u16((b.first..=b.last).fold(0, |mask, bit| mask | 1 << bit)),
                values,
            }
        })
        .collect();
    Word {
        name: Ident::of(&word_name(dir).split('_').collect::<Vec<_>>()),
        doc: Doc::plain(format!("{}, PZD1 {way}: its bits.", word.name.en)),
        fields,
    }
}

// ---------------------------------------------------------------------------
// PROFIBUS

#[derive(Serialize)]
pub(crate) struct Profibus {
    pub ident_number: Consts,
    /// Each PPO type's config bytes.
    pub configs: Vec<Bytes>,
    pub user_prm_len: Consts,
    pub dpv1_status: Option<Bytes>,
    pub user_prm: UserPrm,
    pub diagnosis: Option<Diagnosis>,
    /// The error types of a channel's diagnosis, one constant each.
    pub channel_diagnosis: Option<Consts>,
    /// The values of each diagnosis type's areas, one constant each.
    pub diagnosis_types: Vec<Consts>,
}

/// User_Prm_Data decoded: what it holds.
#[derive(Serialize)]
pub(crate) struct UserPrm {
    pub doc: Doc,
    /// The DPV1 status bytes, when the GSD gives them.
    pub dpv1_status: Option<Doc>,
    pub groups: Vec<UserPrmGroup>,
    /// The gateway's node configuration.
    pub nodes: Option<Doc>,
}

/// A group of mappings in User_Prm_Data.
#[derive(Serialize)]
pub(crate) struct UserPrmGroup {
    pub name: Ident,
    pub doc: Doc,
    /// The entries it carries.
    pub count: usize,
    /// Whether it carries some of the group's entries only.
    pub partial: bool,
}

fn profibus(ir: &Ir, p: &IrProfibus) -> Profibus {
    let ident = format!(
        "PROFIBUS Ident_Number, as {} declares it.{}",
        p.file_name,
        placeholder(p.ident_placeholder, " A placeholder, not assigned by PI.")
    );
    Profibus {
        ident_number: Consts::one(
            Doc::plain(ident),
            &["profibus", "ident", "number"],
            Ty::U16,
            Val::hex_u16(p.ident_number),
        ),
        configs: p
            .modules
            .iter()
            .map(|m| {
                let doc = Doc::plain(format!("\"{}\": the config bytes Chk_Cfg accepts.", m.name));
                bytes(m.ident.tagged("config"), doc, &m.config)
            })
            .collect(),
        user_prm_len: Consts::one(
            Doc::plain(
                "The length of User_Prm_Data, the device-specific part of the parameter \
                 telegram.",
            ),
            &["user", "prm", "len"],
            Ty::Size,
            Val::Dec(p.user_prm.len.into()),
        ),
        dpv1_status: p.dpv1.map(|d| {
            let doc =
                Doc::plain("The DPV1 status bytes the GSD gives at the start of User_Prm_Data.");
            bytes(
                Ident::of(&["user", "prm", "dpv1", "status"]),
                doc,
                &d.status_bytes,
            )
        }),
        user_prm: user_prm(ir, p),
        diagnosis: p.diagnosis.as_ref().map(|d| diagnosis(&p.file_name, d)),
        channel_diagnosis: dp_channel_diagnosis(p),
        diagnosis_types: dp_diagnosis_types(p),
    }
}

/// The error types the card reports in a channel's diagnosis (bits 0-4 of
/// its third byte), one constant each, named after its text.
fn dp_channel_diagnosis(p: &IrProfibus) -> Option<Consts> {
    let items: Vec<Const> = p
        .channel_diagnosis
        .iter()
        .map(|d| Const {
            name: d.ident.clone(),
            ty: Ty::U8,
            value: Val::Dec(d.error_type.into()),
        })
        .collect();
    let doc = Doc::plain(format!(
        "The error types of a channel's diagnosis, as {}'s Channel_Diag names them.",
        p.file_name
    ));
    (!items.is_empty()).then_some(Consts { doc, items })
}

/// The values of each `UnitDiagType`'s areas, one constant each, named
/// after the type, the area's bits and the value's text
/// (`DP_DIAGNOSIS_TYPE_129_BITS_24_31_WRONG_F_CRC_LENGTH`): what the
/// firmware writes into those bits of the device-related block.
fn dp_diagnosis_types(p: &IrProfibus) -> Vec<Consts> {
    p.diagnosis_types
        .iter()
        .flat_map(|t| {
            t.areas.iter().map(move |a| {
                let id = t.id.to_string();
                let ty = if a.last_bit - a.first_bit < 8 {
                    Ty::U8
                } else {
                    Ty::U16
                };
                let items = a
                    .values
                    .choices
                    .iter()
                    .map(|c| {
                        let words: Vec<&str> = ["dp", "diagnosis", "type", &id]
                            .into_iter()
                            .chain(a.ident.words().iter().map(String::as_str))
                            .chain(c.ident.words().iter().map(String::as_str))
                            .collect();
                        Const {
                            name: Ident::of(&words),
                            ty,
                            // Lowering keeps an area's values within its bits.
                            value: Val::Dec(c.value as u64),
                        }
                    })
                    .collect();
                let doc = Doc::plain(format!(
                    "UnitDiagType {id}, {} of the device-related diagnosis: the values {}'s X_Value names.",
                    bit_range(a.first_bit, a.last_bit),
                    p.file_name
                ));
                Consts { doc, items }
            })
        })
        .collect()
}

fn user_prm(ir: &Ir, p: &IrProfibus) -> UserPrm {
    let groups = ir
        .mappings
        .groups
        .iter()
        .filter(|g| p.user_prm.block(g.kind).is_some())
        .map(|g| {
            let partial = p.user_prm.partial(g);
            let scope = Scope::part(g.kind.key());
            let doc = Doc::at(Scope::Root)
                .text("The values of the entries of ")
                .link(Ref::Part(scope))
                .text(if partial.is_some() {
                    " that User_Prm_Data carries."
                } else {
                    "."
                });
            UserPrmGroup {
                name: Ident::of(&g.kind.key().split('_').collect::<Vec<_>>()),
                doc,
                count: partial
                    .as_ref()
                    .map_or_else(|| g.entries().count(), Vec::len),
                partial: partial.is_some(),
            }
        })
        .collect();
    UserPrm {
        doc: Doc::plain("User_Prm_Data, decoded."),
        dpv1_status: p
            .dpv1
            .map(|_| Doc::plain("As the master sent them: it may set bits the GSD leaves clear.")),
        groups,
        nodes: ir
            .gateway
            .as_ref()
            .map(|_| Doc::plain("The gateway's node configuration.")),
    }
}

/// The device-related diagnosis: its length and header, and each
/// `Unit_Diag_Area` of the GSD with its values.
#[derive(Serialize)]
pub(crate) struct Diagnosis {
    pub doc: Doc,
    /// Bytes of the block, the header included.
    pub length: u8,
    pub len: Consts,
    pub header: Consts,
    /// The block with every area 0.
    pub empty: Doc,
    pub areas: Vec<Area>,
}

#[derive(Serialize)]
pub(crate) struct Area {
    pub name: Ident,
    pub doc: Doc,
    pub first: u16,
    pub last: u16,
    pub values: ValueSet,
}

/// What the description says of the block and of each byte after its
/// header, in English, each sentence after a blank: the fault code's bytes
/// as the manual names them.
fn said(d: &profibus::Diagnosis) -> String {
    let header = profibus::STANDARD_DIAG_BYTES;
    let info = d
        .info
        .iter()
        .map(|info| info.en.trim_end_matches('.').to_string());
    let bytes = d.bytes.iter().map(|(at, text)| {
        format!(
            "Byte {at} of the diagnosis (byte {} of the block): {}",
            at - header,
            text.en.trim_end_matches('.')
        )
    });
    info.chain(bytes).map(|s| format!(" {s}.")).collect()
}

fn diagnosis(file_name: &str, d: &profibus::Diagnosis) -> Diagnosis {
    let scope = Scope::part("diagnosis");
    let doc = |text: &str| Doc::at(scope.clone()).text(text);
    let areas = d
        .areas
        .iter()
        .map(|a| {
            let values = value_set(
                &a.values,
                doc("The values of ")
                    .link(Ref::Const(scope.clone(), a.ident.clone()))
                    .text("."),
            );
            Area {
                name: a.ident.clone(),
                doc: doc(&format!(
                    "{} of the device-related diagnosis; values in ",
                    bit_range(a.first_bit, a.last_bit)
                ))
                .link(Ref::Values(scope.clone(), values.name.clone()))
                .text("."),
                first: a.first_bit,
                last: a.last_bit,
                values,
            }
        })
        .collect();
    Diagnosis {
        length: d.length,
        doc: Doc::plain(format!(
            "The device-related diagnosis {file_name} describes: a header byte, then the \
             bytes its Unit_Diag_Areas read.{}",
            said(d)
        )),
        len: Consts::one(
            doc(
                "Bytes of the block, the header included (the slave sends them after the 6 \
                 bytes of the standard diagnosis).",
            ),
            &["len"],
            Ty::Size,
            Val::Dec(d.length.into()),
        ),
        header: Consts::one(
            doc("The header byte: device-related diagnosis (bits 7-6 = 00) of ")
                .link(Ref::Const(scope.clone(), Ident::of(&["len"])))
                .text(" bytes."),
            &["header"],
            Ty::U8,
            Val::hex_u8(d.length),
        ),
        empty: doc("The block with every area 0."),
        areas,
    }
}

// ---------------------------------------------------------------------------
// PROFINET

/// `sentence` for a number that is a placeholder, else nothing.
fn placeholder(is: bool, sentence: &str) -> &str {
    if is {
        sentence
    } else {
        ""
    }
}

/// The device access point's ident number, and its submodule's.
fn dap_idents(p: &IrProfinet) -> Consts {
    let first = p.first_dap();
    let dap = Val::hex_u32(first.ident);
    if first.submodule_ident == first.ident {
        return Consts::one(
            Doc::plain(
                "The module ident number of the device access point in slot 0, and of its \
                 submodule.",
            ),
            &["dap", "ident"],
            Ty::U32,
            dap,
        );
    }
    Consts {
        doc: Doc::plain(
            "The module ident number of the device access point in slot 0, and its \
             submodule's.",
        ),
        items: vec![
            Const::new(&["dap", "ident"], Ty::U32, dap),
            Const::new(
                &["dap", "submodule", "ident"],
                Ty::U32,
                Val::hex_u32(first.submodule_ident),
            ),
        ],
    }
}

/// The slot the modules go into, or the first and the last of their
/// slots, each taking one module.
fn module_slots(slots: profinet::Slots) -> Consts {
    if slots.first == slots.last {
        return Consts::one(
            Doc::plain("The slot the I/O module is plugged into."),
            &["module", "slot"],
            Ty::U16,
            Val::Dec(slots.first.into()),
        );
    }
    Consts {
        doc: Doc::plain(
            "The first and the last slot of the I/O modules: each slot between takes one, its own telegram.",
        ),
        items: vec![
            Const::new(&["first", "module", "slot"], Ty::U16, Val::Dec(slots.first.into())),
            Const::new(&["last", "module", "slot"], Ty::U16, Val::Dec(slots.last.into())),
        ],
    }
}

/// The empty module's ident numbers and slots.
fn empty_module(e: &profinet::EmptyModule) -> Consts {
    Consts {
        doc: Doc::plain(format!(
            "The empty module \"{}\", without data, which the controller plugs into a slot that has no I/O module: its ident number, its submodule's, and the first and the last slot it may go into.",
            e.name.text.en
        )),
        items: vec![
            Const::new(&["empty", "module", "ident"], Ty::U32, Val::hex_u32(e.ident)),
            Const::new(
                &["empty", "submodule", "ident"],
                Ty::U32,
                Val::hex_u32(e.submodule_ident),
            ),
            Const::new(&["empty", "module", "first", "slot"], Ty::U16, Val::Dec(e.slots.first.into())),
            Const::new(&["empty", "module", "last", "slot"], Ty::U16, Val::Dec(e.slots.last.into())),
        ],
    }
}

/// A safety module's ident numbers, slots, IO bytes and F-parameter
/// record: what the firmware plugs and hands its PROFIsafe layer.
fn safety_module(m: &SafetyModule) -> Consts {
    let constant = |what: &[&str], ty, value| Const {
        name: what.iter().fold(m.ident.clone(), |name, w| name.tagged(w)),
        ty,
        value,
    };
    Consts {
        doc: Doc::plain(format!(
            "Safety module \"{}\" (PROFIsafe): its ident number and its submodule's, the first and the last slot it may go into, the bytes of its safety data each way with the message trailer its PROFIsafe layer fills and checks, and the index of its F-parameter record.",
            m.name.text.en
        )),
        items: vec![
            constant(&["ident"], Ty::U32, Val::hex_u32(m.ident_number)),
            constant(&["submodule", "ident"], Ty::U32, Val::hex_u32(m.submodule_ident_number)),
            constant(&["first", "slot"], Ty::U16, Val::Dec(m.slots.first.into())),
            constant(&["last", "slot"], Ty::U16, Val::Dec(m.slots.last.into())),
            constant(&["input", "bytes"], Ty::U16, Val::Dec(m.input_bytes().into())),
            constant(&["output", "bytes"], Ty::U16, Val::Dec(m.output_bytes().into())),
            constant(&["f", "parameter", "index"], Ty::U16, Val::Dec(m.f_parameter_index.into())),
        ],
    }
}

/// The submodule ident numbers of the interface and the ports, where they
/// are not their subslots (gsdc's numbering, which the subslots say).
fn interface_idents(p: &IrProfinet) -> Option<Consts> {
    let by_subslot = p.interface_ident == u32::from(profinet::INTERFACE_SUBSLOT)
        && p.first_dap()
            .ports
            .iter()
            .all(profinet::Port::numbered_by_subslot);
    if by_subslot {
        return None;
    }
    let mut items = vec![Const::new(
        &["interface", "ident"],
        Ty::U32,
        Val::hex_u32(p.interface_ident),
    )];
    for (n, port) in (1u32..).zip(&p.first_dap().ports) {
        let name = format!("port{n}");
        items.push(Const::new(
            &[name.as_str(), "ident"],
            Ty::U32,
            Val::hex_u32(port.ident),
        ));
    }
    Some(Consts {
        doc: Doc::plain("The submodule ident numbers of the interface and of each port."),
        items,
    })
}

fn profinet(p: &IrProfinet) -> Vec<Consts> {
    let mut consts = vec![
        Consts::one(
            Doc::plain(format!(
                "PROFINET VendorID, as {} declares it.{}",
                p.file_name,
                placeholder(
                    p.vendor_id_placeholder,
                    " A placeholder, not assigned by PI."
                )
            )),
            &["profinet", "vendor", "id"],
            Ty::U16,
            Val::hex_u16(p.vendor_id),
        ),
        Consts::one(
            Doc::plain(format!(
                "PROFINET DeviceID.{}",
                placeholder(p.device_id_placeholder, " A placeholder.")
            )),
            &["profinet", "device", "id"],
            Ty::U16,
            Val::hex_u16(p.device_id),
        ),
        dap_idents(p),
        Consts {
            doc: Doc::plain(
                "The subslots of the interface submodule and of the first of its ports.",
            ),
            items: vec![
                Const::new(
                    &["interface", "subslot"],
                    Ty::U16,
                    Val::hex_u16(profinet::INTERFACE_SUBSLOT),
                ),
                Const::new(
                    &["first", "port", "subslot"],
                    Ty::U16,
                    Val::hex_u16(profinet::FIRST_PORT_SUBSLOT),
                ),
                Const::new(
                    &["ports"],
                    Ty::U8,
                    Val::Dec(p.first_dap().ports.len() as u64),
                ),
            ],
        },
    ];
    consts.extend(interface_idents(p));
    consts.push(module_slots(p.module_slots));
    consts.extend(p.empty_module.as_ref().map(empty_module));
    consts.extend(p.safety_modules.iter().map(safety_module));
    for m in &p.modules {
        let name = &m.name.text.en;
        let constant = |what: &str, ty, value| Const {
            name: what
                .split('_')
                .fold(m.ident.clone(), |name, w| name.tagged(w)),
            ty,
            value,
        };
        consts.push(if m.submodule_ident_number == m.ident_number {
            Consts {
                doc: Doc::plain(format!(
                    "Module \"{name}\": its ident number, and its submodule's."
                )),
                items: vec![constant("ident", Ty::U32, Val::hex_u32(m.ident_number))],
            }
        } else {
            Consts {
                doc: Doc::plain(format!(
                    "Module \"{name}\": its ident number, and its data submodule's."
                )),
                items: vec![
                    constant("ident", Ty::U32, Val::hex_u32(m.ident_number)),
                    constant(
                        "submodule_ident",
                        Ty::U32,
                        Val::hex_u32(m.submodule_ident_number),
                    ),
                ],
            }
        });
        if m.is_profidrive() {
            let subslot = |n: u16| Val::Dec(n.into());
            consts.push(Consts {
                doc: Doc::plain(format!(
                    "Module \"{name}\" is PROFIdrive's: its submodules are in the profile's \
                     API, the module access point (no data) in its subslot with its ident \
                     number, the telegram in the data subslot."
                )),
                items: vec![
                    constant("api", Ty::U32, Val::hex_u32(profinet::PROFIDRIVE_API)),
                    constant(
                        "access_point_subslot",
                        Ty::U16,
                        subslot(profinet::ACCESS_POINT_SUBSLOT),
                    ),
                    constant(
                        "access_point_ident",
                        Ty::U32,
                        Val::hex_u32(p.access_point_ident),
                    ),
                    constant(
                        "data_subslot",
                        Ty::U16,
                        subslot(profinet::PROFIDRIVE_DATA_SUBSLOT),
                    ),
                ],
            });
        }
    }
    consts.extend(channel_diagnosis(p));
    consts.extend(p.channel_diagnosis.iter().filter_map(extended_diagnosis));
    consts.extend(p.profienergy.as_ref().map(profienergy_modes));
    consts
}

/// The card's PROFIenergy energy saving modes, as the GSDML declares them:
/// each one's number and times, which the firmware answers PROFIenergy's
/// commands with.
fn profienergy_modes(energy: &profinet::ProfiEnergy) -> Consts {
    let mut items = vec![Const::new(
        &["profienergy", "modes"],
        // Up to 256: every number of a mode, 0 to 255, once.
        Ty::U16,
        Val::Dec(energy.modes.len() as u64),
    )];
    for mode in &energy.modes {
        let id = mode.id.to_string();
        let mode_id = ["profienergy", "mode", id.as_str(), "id"];
        items.push(Const::new(&mode_id, Ty::U8, Val::Dec(mode.id.into())));
        for (what, ms) in [
            ("time_to_pause", mode.time_to_pause),
            ("regular_time_to_operate", mode.regular_time_to_operate),
            ("min_length_of_stay", mode.min_length_of_stay),
        ] {
            let name = ["profienergy", "mode", id.as_str(), what, "ms"];
            items.push(Const::new(&name, Ty::U32, Val::Dec(ms.into())));
        }
    }
    Consts {
        doc: Doc::plain(
            "The PROFIenergy energy saving modes every device access point declares: each \
             mode's number (EnergySavingModeItem ID) and its TimeToPause, RTTO and \
             TimeMinLengthOfStay in ms, which the card answers PROFIenergy's commands with.",
        ),
        items,
    }
}

/// The error types the card reports as channel diagnosis, one constant
/// each, named after its text.
fn channel_diagnosis(p: &IrProfinet) -> Option<Consts> {
    error_types(
        Doc::plain(
            "The error types the card reports as channel diagnosis, as the GSDML's \
             ChannelDiagList names them; a profile's (0x9000 and up) in the profile's API.",
        ),
        p.channel_diagnosis.iter().map(|d| (&d.ident, d.error_type)),
    )
}

/// A channel diagnosis's extended error types, which the card reports
/// with its error type.
fn extended_diagnosis(d: &profinet::ChannelDiagnosis) -> Option<Consts> {
    error_types(
        Doc::plain(format!(
            "The extended error types of channel diagnosis 0x{:04X} (\"{}\"), as its \
             ExtChannelDiagList names them.",
            d.error_type, d.name.text.en
        )),
        d.extended.iter().map(|e| (&e.ident, e.error_type)),
    )
}

/// One constant per error type under `doc`; none without error types.
fn error_types<'a>(doc: Doc, named: impl Iterator<Item = (&'a Ident, u16)>) -> Option<Consts> {
    let items: Vec<Const> = named
        .map(|(name, error_type)| Const {
            name: name.clone(),
            ty: Ty::U16,
            value: Val::hex_u16(error_type),
        })
        .collect();
    (!items.is_empty()).then_some(Consts { doc, items })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plain(doc: &Doc) -> String {
        doc.render(|to| format!("<{to:?}>"))
    }

    fn settings(layout: &Layout) -> &Group {
        layout
            .groups
            .iter()
            .find(|g| g.name.snake() == "settings")
            .expect("MV810 has settings")
    }

    /// A timeout is a plain value: its bounds and default in decimal, and
    /// said to be a value, not a parameter address; a setting's name keeps
    /// its case (P43.01 is not p43.01) where the sentences name it.
    #[test]
    fn a_range_of_plain_values_is_a_value_in_decimal() {
        let layout = build(&crate::testing::mv810_with_timeout());
        let group = settings(&layout);
        let timeout = &group.sets[1];
        assert_eq!(
            plain(&timeout.doc),
            "\"Communication timeout (P43.24)\" holds a value from 0 to 60000."
        );
        let range = timeout.range.as_ref().unwrap();
        assert_eq!((&range.min, &range.max), (&Val::Dec(0), &Val::Dec(60000)));
        assert!(!range.has_min && range.has_max);
        assert_eq!(group.entries[1].default, Val::Dec(100));
        let choices = group.sets[0].choices.as_ref().unwrap();
        assert_eq!(
            plain(&choices.doc),
            "What \"Message type (P43.01)\" may hold."
        );
    }

    /// Each mapping group's doc says where its drive parameters are set:
    /// MV810's at the drive (its section 4), md810dp's by the master (1.6
    /// step 5's parameter telegram), and a group of both says so.
    #[test]
    fn a_groups_doc_says_where_its_parameters_are_set() {
        let doc_of = |layout: &Layout, name: &str| {
            let group = layout.groups.iter().find(|g| g.name.snake() == name);
            plain(&group.expect(name).doc)
        };
        let text = include_str!("../../../descriptions/mv810-pnet02.toml");
        let mv810 = build(&crate::testing::load("mv810-pnet02.toml", text).0.unwrap());
        for name in ["pzd_out", "pzd_in", "settings"] {
            assert!(
                doc_of(&mv810, name).ends_with(
                    " Set at the drive (keypad, PKW, the drive's own tool): the master writes \
                     none of them, and no parameter record or User_Prm_Data carries them."
                ),
                "{name}"
            );
        }
        let text = include_str!("../../../descriptions/md810dp.toml");
        let md810 = build(&crate::testing::load("md810dp.toml", text).0.unwrap());
        for name in ["pzd_out", "pzd_in", "dpv1_index"] {
            let doc = doc_of(&md810, name);
            assert!(
                doc.ends_with(" The master writes them at startup."),
                "{doc}"
            );
        }
        // P43.01 at the drive, the timeout unsaid: the master's.
        let mixed = build(&crate::testing::mv810_with_timeout());
        assert!(doc_of(&mixed, "settings").ends_with(
            " The master writes some of them at startup, those User_Prm_Data or the records \
             carry; the others are set at the drive."
        ));
    }

    /// Sentences name other items by reference, each from where it stands,
    /// so that each language can write the name its way.
    #[test]
    fn sentences_refer_to_the_items_they_name() {
        let text = include_str!("../../../descriptions/mv810-pnet02.toml");
        let layout = build(&crate::testing::load("mv810-pnet02.toml", text).0.unwrap());
        let status = Scope::part("status_word");
        let telegram = &layout.modules[0].telegrams[1];
        assert_eq!(
            plain(&telegram.doc),
            format!(
                "Drive to master; PZD1 is the status word, <{:?}>.",
                Ref::Part(status.clone())
            )
        );
        let field = layout.words[1]
            .fields
            .iter()
            .find(|f| f.values.is_some())
            .unwrap();
        assert_eq!(field.doc.at, status);
        assert!(field.doc.parts.contains(&doc::Part::Ref(Ref::Values(
            status,
            field.values.as_ref().unwrap().name.clone()
        ))));
        let pkw = layout.pkw.as_ref().unwrap();
        assert!(pkw
            .parts
            .contains(&doc::Part::Ref(Ref::Pkw(PkwItem::RequestDecode))));
    }

    /// Two areas over the same bits spell one name: lowering tells them
    /// apart, and the layout keeps its names.
    #[test]
    fn diagnosis_areas_over_the_same_bits_get_their_own_names() {
        let text = include_str!("../../../descriptions/md810dp.toml").replace(
            "[[profibus.diagnosis.areas]]",
            "[[profibus.diagnosis.areas]]\nbit = [8, 15]\nvalues = [{ value = 1, text = \"One\" }]\n\n[[profibus.diagnosis.areas]]",
        );
        let ir = crate::testing::load("md810dp.toml", &text).0.unwrap();
        let layout = build(&ir);
        let diagnosis = layout.profibus.unwrap().diagnosis.unwrap();
        let names: Vec<_> = diagnosis
            .areas
            .iter()
            .map(|a| (a.name.upper_snake(), a.values.name.camel()))
            .collect();
        assert_eq!(
            names,
            [
                ("BITS_8_15".to_string(), "Bits8To15".to_string()),
                ("BITS_8_15_8".to_string(), "Bits8To158".to_string())
            ]
        );
    }

    /// A sentence travels through a template as data and comes back whole.
    #[test]
    fn a_sentence_survives_the_template_context() {
        use serde::Deserialize as _;
        let doc = Doc::at(Scope::Gateway)
            .text("from ")
            .link(Ref::Const(Scope::Gateway, Ident::of(&["first", "node"])))
            .text(".");
        let value = minijinja::Value::from_serialize(&doc);
        assert_eq!(Doc::deserialize(value).unwrap(), doc);
        let ident = Ident::of(&["input", "1", "word"]);
        let value = minijinja::Value::from_serialize(&ident);
        assert_eq!(value.as_str(), Some("input_1_word"));
        assert_eq!(Ident::deserialize(value).unwrap(), ident);
    }
}
