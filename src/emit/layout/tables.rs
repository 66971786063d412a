//! The device tables, language-neutral: what a PROFIBUS-DP slave and a
//! PROFINET IO device need to know of the card (identity, modules, the
//! parameter telegram, records, diagnosis, the PKW codec), built once from
//! the plan as records of named fields holding numbers, texts, lists and
//! references to what the layout already declares. The Rust and C emitters
//! each write the same tables in their own syntax (`rust/tables.rs`,
//! `c/tables.rs`) over the support types of the same names
//! (`templates/support/device.rs`, `gsdc_support.h`), so a fact added here
//! is written once and reaches both languages.

use super::{Doc, Val};
use crate::ir::gateway::{self, DiagCode, ParamKey};
use crate::ir::profibus::{self, PrmHolds, PrmType, PrmValue, Profibus};
use crate::ir::profinet::{self, Profinet, RecordReading};
use crate::ir::safety::SafetyModule;
use crate::ir::{AddressScheme, Allowed, Direction, Ident, Ir, MappingKind, Numbering, PkwKind};

/// A table the layout declares: `DP_DEVICE` in Rust, `<prefix>_dp_device()`
/// in C.
pub(crate) struct Table {
    pub name: Ident,
    pub doc: Doc,
    pub record: Record,
}

/// A value of a support type: its fields in declaration order.
pub(crate) struct Record {
    /// `dp device`: `gsdc::DpDevice`, `gsdc_dp_device_t`.
    pub ty: Ident,
    pub fields: Vec<(&'static str, Value)>,
}

pub(crate) enum Value {
    /// A number or a text.
    Lit(Val),
    Bool(bool),
    /// A variant of a support enum: the enum's name, the variant's.
    Variant(Ident, Ident),
    /// A list of values of one kind.
    List(Elem, Vec<Value>),
    /// A value that may be absent: a list of scalars, or one record.
    Optional(Elem, Option<Box<Value>>),
    Record(Record),
    /// Entries of a group of mappings, by their place in the group (from
    /// 0), in the order a record holds them.
    Entries(MappingKind, Vec<usize>),
    /// Whether the layout declares the gateway's node totals function.
    NodeTotals(bool),
}

/// What a list or an optional value holds, as C declares it.
#[derive(Clone, Copy)]
pub(crate) enum Elem {
    Bool,
    Byte,
    Word,
    Long,
    /// A place in a list.
    Index,
    /// A record of the support type of this name.
    Record(&'static str),
}

/// `dp device` as an identifier, which each language spells.
pub(crate) fn type_ident(name: &str) -> Ident {
    Ident::of(&name.split(' ').collect::<Vec<_>>())
}

fn record(ty: &str, fields: Vec<(&'static str, Value)>) -> Record {
    Record {
        ty: type_ident(ty),
        fields,
    }
}

fn number(n: impl Into<u64>) -> Value {
    Value::Lit(Val::Dec(n.into()))
}

fn size(n: usize) -> Value {
    Value::Lit(Val::Dec(n as u64))
}

fn hex(n: impl Into<u64>, digits: usize) -> Value {
    Value::Lit(Val::Hex(n.into(), digits))
}

fn text(text: &str) -> Value {
    Value::Lit(Val::Text(text.to_string()))
}

fn variant(ty: &str, name: &str) -> Value {
    Value::Variant(type_ident(ty), type_ident(name))
}

/// The tables of a description: the PROFIBUS device with `[profibus]`, the
/// PROFINET device with `[profinet]`, the drive's parameter numbering when
/// the description gives one.
pub(crate) fn tables(ir: &Ir) -> Vec<Table> {
    let dp = ir.profibus.as_ref().map(|p| Table {
        name: Ident::of(&["dp", "device"]),
        doc: Doc::plain(format!(
            "The PROFIBUS-DP slave {} describes: its identity, every module, \
             User_Prm_Data with every parameter by the GSD's name, the \
             diagnosis block, the PKW codec, the PZD words User_Prm_Data \
             maps and a gateway's nodes.",
            p.file_name
        )),
        record: dp_device(ir, p),
    });
    let pn = ir.profinet.as_ref().map(|p| Table {
        name: Ident::of(&["pn", "device"]),
        doc: Doc::plain(format!(
            "The PROFINET IO device {} describes: its identity, the device \
             access point with its interface and ports, the device access points \
             after the first, every module with its submodules and parameter \
             records, the PKW codec and the PZD words the records map.",
            p.file_name
        )),
        record: pn_device(ir, p),
    });
    let numbering = ir.numbering.as_ref().map(|n| Table {
        name: Ident::of(&["numbering"]),
        doc: Doc::plain(
            "How the drive numbers its parameters: a name as the manual writes \
             it read into the address the telegrams carry, and an address \
             written back as a name.",
        ),
        record: numbering(n),
    });
    dp.into_iter().chain(pn).chain(numbering).collect()
}

fn pkw_codec(kind: PkwKind) -> Value {
    let name = match kind {
        PkwKind::None => "none",
        PkwKind::PkeIndPwe => "pke ind pwe",
        PkwKind::StationCommandAddressValue => "station command",
        PkwKind::Profidrive => "profidrive",
    };
    variant("pkw codec", name)
}

// ---------------------------------------------------------------------------
// PROFIBUS

fn dp_device(ir: &Ir, p: &Profibus) -> Record {
    let gateway = ir.gateway.as_ref().map(|g| Box::new(dp_gateway(p, g)));
    let diagnosis = p.diagnosis.as_ref().map(|d| Box::new(dp_diagnosis(d)));
    record(
        "dp device",
        vec![
            ("ident_number", hex(p.ident_number, 4)),
            ("freeze_mode", Value::Bool(p.freeze_mode)),
            ("sync_mode", Value::Bool(p.sync_mode)),
            (
                "modules",
                Value::List(Elem::Record("dp module"), dp_modules(ir, p)),
            ),
            ("max_modules", number(p.max_module)),
            ("node_totals", Value::NodeTotals(ir.gateway.is_some())),
            ("user_prm", Value::Record(user_prm(ir, p))),
            (
                "diagnosis_len",
                number(p.max_diag_data_len - profibus::STANDARD_DIAG_BYTES),
            ),
            (
                "diagnosis",
                Value::Optional(Elem::Record("dp diagnosis"), diagnosis),
            ),
            ("pkw", pkw_codec(ir.telegram.pkw)),
            (
                "control_word",
                Value::Bool(ir.telegram.control_word.is_some()),
            ),
            (
                "status_word",
                Value::Bool(ir.telegram.status_word.is_some()),
            ),
            ("pzd_out", pzd_params(ir, p, MappingKind::PzdOut)),
            ("pzd_in", pzd_params(ir, p, MappingKind::PzdIn)),
            (
                "gateway",
                Value::Optional(Elem::Record("dp gateway"), gateway),
            ),
        ],
    )
}

/// The place in User_Prm_Data's parameters of the one that holds `value`.
fn param_place(p: &Profibus, value: PrmValue) -> Option<usize> {
    p.user_prm.params().position(|param| param.value == value)
}

/// The PZD words of `kind` a parameter of User_Prm_Data maps: each entry's
/// number is its word.
fn pzd_params(ir: &Ir, p: &Profibus, kind: MappingKind) -> Value {
    let entries = ir
        .mappings
        .group(kind)
        .into_iter()
        .flat_map(|g| g.entries());
    let params = entries.filter_map(|(_, entry)| {
        let place = param_place(p, PrmValue::Entry(entry.key))?;
        Some(Value::Record(record(
            "pzd param",
            vec![("word", number(entry.key.number)), ("param", size(place))],
        )))
    });
    Value::List(Elem::Record("pzd param"), params.collect())
}

/// A drive's card's device-related block: its length and every area with
/// the values the GSD names.
fn dp_diagnosis(d: &profibus::Diagnosis) -> Value {
    let areas = d.areas.iter().map(|a| {
        let values = a.values.choices.iter().map(|c| number(c.value as u64));
        Value::Record(record(
            "dp diag area",
            vec![
                ("first_bit", number(a.first_bit)),
                ("last_bit", number(a.last_bit)),
                ("values", Value::List(Elem::Word, values.collect())),
            ],
        ))
    });
    Value::Record(record(
        "dp diagnosis",
        vec![
            ("len", number(d.length)),
            (
                "areas",
                Value::List(Elem::Record("dp diag area"), areas.collect()),
            ),
        ],
    ))
}

/// A gateway's nodes, each with the places of its words' parameters, and
/// its diagnosis types.
fn dp_gateway(p: &Profibus, g: &crate::ir::Gateway) -> Value {
    let place = |key| {
        param_place(p, PrmValue::Gateway(key))
            .expect("lowering places every gateway parameter in User_Prm_Data")
    };
    let nodes = g.nodes.iter().map(|n| {
        let words = |direction| {
            place(ParamKey::Words {
                node: n.number,
                direction,
            })
        };
        Value::Record(record(
            "gateway node",
            vec![
                ("node", number(n.number)),
                ("input_words", size(words(Direction::In))),
                ("output_words", size(words(Direction::Out))),
            ],
        ))
    });
    let diagnosis = g.diagnosis.as_ref().map(|d| Box::new(gateway_diagnosis(d)));
    Value::Record(record(
        "dp gateway",
        vec![
            ("node_count", size(place(ParamKey::NodeCount))),
            (
                "nodes",
                Value::List(Elem::Record("gateway node"), nodes.collect()),
            ),
            (
                "diagnosis",
                Value::Optional(Elem::Record("gateway diagnosis"), diagnosis),
            ),
        ],
    ))
}

fn gateway_diagnosis(d: &gateway::Diagnosis) -> Value {
    let types = d.types.iter().map(|t| {
        let (code, codes) = match &t.code {
            DiagCode::Listed(values) => (
                "byte",
                values
                    .choices
                    .iter()
                    .map(|c| number(c.value as u64))
                    .collect(),
            ),
            DiagCode::Word(_) => ("word", Vec::new()),
        };
        Value::Record(record(
            "gateway diag type",
            vec![
                ("value", number(t.value)),
                ("len", number(t.len)),
                ("code", variant("diag code", code)),
                ("codes", Value::List(Elem::Word, codes)),
            ],
        ))
    });
    Value::Record(record(
        "gateway diagnosis",
        vec![
            ("type_at", number(d.type_at)),
            ("node_at", number(d.node_at)),
            ("code_at", number(d.code_at)),
            (
                "types",
                Value::List(Elem::Record("gateway diag type"), types.collect()),
            ),
        ],
    ))
}

/// Every `Module` of the GSD: the PPO types or the vendor's modules, or a
/// gateway's word modules.
fn dp_modules(ir: &Ir, p: &Profibus) -> Vec<Value> {
    let ppos = p.modules.iter().map(|m| {
        dp_module(
            &m.name,
            &m.config,
            (m.input_len.into(), m.output_len.into()),
            (
                m.layout.is_some_and(|l| l.pkw),
                m.layout.map_or(0, |l| l.pzd_words),
            ),
            m.safety.as_ref().map_or(0, |s| s.len.into()),
        )
    });
    let words = ir.gateway.iter().flat_map(|g| &g.modules).map(|m| {
        let bytes = 2 * usize::from(m.words);
        let lengths = match m.direction {
            crate::ir::Direction::In => (bytes, 0),
            crate::ir::Direction::Out => (0, bytes),
        };
        dp_module(&m.name, &[m.config], lengths, (false, 0), 0)
    });
    ppos.chain(words).collect()
}

fn dp_module(
    name: &str,
    config: &[u8],
    (input_len, output_len): (usize, usize),
    (pkw, pzd_words): (bool, u8),
    f_parameter_len: usize,
) -> Value {
    Value::Record(record(
        "dp module",
        vec![
            ("name", text(name)),
            ("config", bytes(config)),
            ("input_len", size(input_len)),
            ("output_len", size(output_len)),
            ("pkw", Value::Bool(pkw)),
            ("pzd_words", number(pzd_words)),
            ("f_parameter_len", size(f_parameter_len)),
        ],
    ))
}

fn bytes(bytes: &[u8]) -> Value {
    Value::List(Elem::Byte, bytes.iter().map(|&b| hex(b, 2)).collect())
}

fn user_prm(ir: &Ir, p: &Profibus) -> Record {
    let status = p.dpv1.map(|d| Box::new(bytes(&d.status_bytes)));
    let params = p.user_prm.params().map(|param| {
        let facts = ir.prm_facts(param);
        let (data_type, first, last) = match param.data_type {
            // A Signed8 holds 0 to 127 (lowering), which a byte reads alike.
            PrmType::Unsigned8 | PrmType::Signed8 => ("unsigned8", 0, 7),
            PrmType::Unsigned16 => ("unsigned16", 0, 15),
            PrmType::Bits { first, last } if first == last => ("bit", first, last),
            PrmType::Bits { first, last } => ("bit area", first, last),
        };
        let (min, max, values) = allowed(&facts.holds);
        Value::Record(record(
            "dp param",
            vec![
                ("name", text(facts.name.for_gsd())),
                ("offset", number(param.offset)),
                ("data_type", variant("prm data type", data_type)),
                ("first_bit", number(first)),
                ("last_bit", number(last)),
                ("default_value", number(facts.default)),
                ("min", number(min)),
                ("max", number(max)),
                ("values", Value::List(Elem::Word, values)),
            ],
        ))
    });
    record(
        "user prm",
        vec![
            ("len", number(p.user_prm.len)),
            ("dpv1_status", Value::Optional(Elem::Byte, status)),
            (
                "params",
                Value::List(Elem::Record("dp param"), params.collect()),
            ),
        ],
    )
}

/// The range of a parameter, and its values when the GSD lists them.
fn allowed(holds: &PrmHolds) -> (u16, u16, Vec<Value>) {
    let values = match holds {
        PrmHolds::Mapping { set, .. } => &set.allowed,
        PrmHolds::Card(p) => &p.allowed,
        PrmHolds::Number { min, max } => return (*min, *max, Vec::new()),
    };
    match values {
        Allowed::Range { min, max } => (*min, *max, Vec::new()),
        Allowed::Choices(values) => {
            // Lowering keeps a mapping's values within Unsigned16.
            let mut sorted: Vec<u16> = values
                .choices
                .iter()
                .filter_map(|c| u16::try_from(c.value).ok())
                .collect();
            sorted.sort_unstable();
            let (min, max) = (sorted[0], sorted[sorted.len() - 1]);
            (min, max, sorted.into_iter().map(number).collect())
        }
    }
}

// ---------------------------------------------------------------------------
// PROFINET

fn pn_device(ir: &Ir, p: &Profinet) -> Record {
    record(
        "pn device",
        vec![
            ("vendor_id", hex(p.vendor_id, 4)),
            ("device_id", hex(p.device_id, 4)),
            ("dns_name", text(&p.dns_name)),
            (
                "daps",
                Value::List(
                    Elem::Record("pn dap"),
                    p.daps.iter().map(|d| pn_dap(p, d)).collect(),
                ),
            ),
            (
                "interface_submodule",
                fixed_submodule(profinet::INTERFACE_SUBSLOT, p.interface_ident),
            ),
            (
                "modules",
                Value::List(
                    Elem::Record("pn module"),
                    p.modules
                        .iter()
                        .map(|m| pn_module(ir, p, m))
                        .chain(p.empty_module.iter().map(pn_empty_module))
                        .collect(),
                ),
            ),
            (
                "safety_modules",
                Value::List(
                    Elem::Record("pn safety module"),
                    p.safety_modules.iter().map(pn_safety_module).collect(),
                ),
            ),
            ("pkw", pkw_codec(ir.telegram.pkw)),
            (
                "control_word",
                Value::Bool(ir.telegram.control_word.is_some()),
            ),
            (
                "status_word",
                Value::Bool(ir.telegram.status_word.is_some()),
            ),
            ("pzd_out", pn_pzds(ir, p, MappingKind::PzdOut)),
            ("pzd_in", pn_pzds(ir, p, MappingKind::PzdIn)),
        ],
    )
}

fn pn_submodule_records(records: &[profinet::SubmoduleRecord]) -> Value {
    let records = records.iter().map(|r| {
        Value::Record(record(
            "pn submodule record",
            vec![
                ("index", number(r.index)),
                ("len", number(r.length)),
                (
                    "values",
                    Value::List(
                        Elem::Record("pn record value"),
                        r.values.iter().map(pn_record_value).collect(),
                    ),
                ),
            ],
        ))
    });
    Value::List(Elem::Record("pn submodule record"), records.collect())
}

fn pn_record_value(v: &profinet::RecordValue) -> Value {
    let (bytes, (first_bit, last_bit)) = match v.data_type {
        profinet::RecordValueType::Bits { first, last } => (0, (first, last)),
        whole => (whole.bytes(), (0, 7)),
    };
    let listed = v.choices().iter();
    Value::Record(record(
        "pn record value",
        vec![
            ("name", text(&v.text.text.en)),
            ("offset", number(v.offset)),
            ("bytes", number(bytes)),
            ("first_bit", number(first_bit)),
            ("last_bit", number(last_bit)),
            ("default_value", number(v.default)),
            ("min", number(v.min)),
            ("max", number(v.max)),
            (
                "values",
                // Within 0..=u32::MAX: lowering checks each choice.
                Value::List(
                    Elem::Long,
                    listed.map(|(value, _)| number(*value as u64)).collect(),
                ),
            ),
            ("changeable", Value::Bool(v.changeable)),
        ],
    ))
}

/// The PZD words of `kind` a record entry maps, each with the record's
/// index and the entry's place in it: every module's record of a kind holds
/// the group's entries from its first on, as many as the module has words.
fn pn_pzds(ir: &Ir, p: &Profinet, kind: MappingKind) -> Value {
    let records = p.modules.iter().flat_map(|m| &m.records);
    let mut places: Vec<(u8, u16, usize)> = Vec::new();
    for r in records.filter(|r| r.kind == kind) {
        for (place, f) in r.refs.iter().enumerate() {
            if !places.iter().any(|&(word, _, _)| word == f.entry.number) {
                places.push((f.entry.number, r.index, place));
            }
        }
    }
    places.sort_unstable();
    debug_assert!(ir.mappings.group(kind).is_some() || places.is_empty());
    let pzds = places.into_iter().map(|(word, index, place)| {
        Value::Record(record(
            "pn pzd",
            vec![
                ("word", number(word)),
                ("record", number(index)),
                ("entry", size(place)),
            ],
        ))
    });
    Value::List(Elem::Record("pn pzd"), pzds.collect())
}

fn pn_ports(dap: &profinet::Dap) -> Vec<Value> {
    let ports = dap.ports.iter();
    ports.map(|p| fixed_submodule(p.subslot, p.ident)).collect()
}

/// A DAP; it offers the empty module, which follows the data modules in
/// `modules`, as every DAP does.
fn pn_dap(p: &Profinet, dap: &profinet::Dap) -> Value {
    let empty = p.empty_module.as_ref().map(|_| p.modules.len());
    Value::Record(record(
        "pn dap",
        vec![
            ("ident", hex(dap.ident, 8)),
            (
                "submodule",
                fixed_submodule(profinet::DAP_SUBSLOT, dap.submodule_ident),
            ),
            (
                "ports",
                Value::List(Elem::Record("pn submodule"), pn_ports(dap)),
            ),
            (
                "modules",
                Value::List(
                    Elem::Index,
                    dap.modules.iter().copied().chain(empty).map(size).collect(),
                ),
            ),
            (
                "access_point_records",
                pn_submodule_records(p.own_records(dap).0),
            ),
            ("port_records", pn_submodule_records(p.own_records(dap).1)),
        ],
    ))
}

/// A submodule without IO data: a DAP's own, the interface, a port.
fn fixed_submodule(subslot: u16, ident: u32) -> Value {
    submodule(subslot, ident, (0, 0))
}

fn submodule(subslot: u16, ident: u32, (input_len, output_len): (usize, usize)) -> Value {
    Value::Record(record(
        "pn submodule",
        vec![
            ("subslot", hex(subslot, 4)),
            ("ident", hex(ident, 8)),
            ("input_len", size(input_len)),
            ("output_len", size(output_len)),
        ],
    ))
}

fn pn_module(ir: &Ir, p: &profinet::Profinet, m: &profinet::Module) -> Value {
    let access_point = m.access_point.as_ref().map(|_| {
        Box::new(submodule(
            profinet::ACCESS_POINT_SUBSLOT,
            p.access_point_ident,
            (0, 0),
        ))
    });
    // The same both ways; a 32-bit item is two words (telegram 2's NSOLL_B).
    let bytes = usize::from(m.layout.bytes());
    let io = (bytes, bytes);
    module_record(
        (&m.name.text.en, m.ident_number, p.module_slots),
        vec![
            ("api", hex(m.api, 8)),
            ("pkw", Value::Bool(m.layout.pkw)),
            ("pzd_words", number(m.layout.pzd_words)),
            (
                "double_words",
                Value::List(
                    Elem::Index,
                    m.double_words().into_iter().map(number).collect(),
                ),
            ),
            (
                "access_point",
                Value::Optional(Elem::Record("pn submodule"), access_point),
            ),
            (
                "data",
                submodule(m.data_subslot(), m.submodule_ident_number, io),
            ),
        ],
        m.records.iter().map(|r| pn_record(ir, r)).collect(),
    )
}

/// The empty module as a module of no words, whose one submodule carries
/// no data.
/// A PROFIsafe module: its ident number, its submodule with the safety
/// data, and that submodule's records besides the F-parameters.
fn pn_safety_module(m: &SafetyModule) -> Value {
    let bytes = (m.input_bytes().into(), m.output_bytes().into());
    Value::Record(record(
        "pn safety module",
        vec![
            ("ident", hex(m.ident_number, 8)),
            (
                "submodule",
                submodule(profinet::DEFAULT_SUBSLOT, m.submodule_ident_number, bytes),
            ),
            ("records", pn_submodule_records(&m.records)),
        ],
    ))
}

fn pn_empty_module(e: &profinet::EmptyModule) -> Value {
    module_record(
        (&e.name.text.en, e.ident, e.slots),
        vec![
            ("api", hex(0u32, 8)),
            ("pkw", Value::Bool(false)),
            ("pzd_words", number(0u8)),
            ("double_words", Value::List(Elem::Index, Vec::new())),
            (
                "access_point",
                Value::Optional(Elem::Record("pn submodule"), None),
            ),
            (
                "data",
                fixed_submodule(profinet::DEFAULT_SUBSLOT, e.submodule_ident),
            ),
        ],
        Vec::new(),
    )
}

/// A `pn module` record: its name, ident number and every slot it may go
/// into, then `fields`, then its records.
fn module_record(
    (name, ident, slots): (&str, u32, profinet::Slots),
    fields: Vec<(&'static str, Value)>,
    records: Vec<Value>,
) -> Value {
    let mut all = vec![
        ("name", text(name)),
        ("ident", hex(ident, 8)),
        (
            "slots",
            Value::List(Elem::Word, slots.iter().map(number).collect()),
        ),
    ];
    all.extend(fields);
    all.push(("records", Value::List(Elem::Record("pn record"), records)));
    Value::Record(record("pn module", all))
}

fn pn_record(ir: &Ir, r: &profinet::ParameterRecord) -> Value {
    let group = ir
        .mappings
        .group(r.kind)
        .expect("lowering makes records of groups it made");
    let positions = r
        .refs
        .iter()
        .map(|f| {
            group
                .entries()
                .position(|(_, e)| e.key == f.entry)
                .expect("a record refers to entries of its group")
        })
        .collect();
    let reading = match ir.profinet.as_ref().and_then(|p| p.record(r.kind)) {
        Some(plan) if plan.reading == RecordReading::Prefix => "prefix",
        _ => "whole",
    };
    Value::Record(record(
        "pn record",
        vec![
            ("index", number(r.index)),
            ("len", number(r.length)),
            ("reading", variant("record reading", reading)),
            ("entries", Value::Entries(r.kind, positions)),
            (
                "defaults",
                Value::List(
                    Elem::Word,
                    r.refs.iter().map(|f| number(f.default)).collect(),
                ),
            ),
            (
                "changeable",
                Value::List(
                    Elem::Bool,
                    r.refs.iter().map(|f| Value::Bool(f.changeable)).collect(),
                ),
            ),
            (
                "fail_safe",
                Value::List(
                    Elem::Byte,
                    r.fail_safe.iter().map(|v| number(v.bytes())).collect(),
                ),
            ),
        ],
    ))
}

// ---------------------------------------------------------------------------
// The drive's parameter numbering

fn numbering(n: &Numbering) -> Record {
    let scheme = match n.scheme {
        AddressScheme::Bytes => "bytes",
        AddressScheme::Decimal => "decimal",
    };
    let prefixes = n.prefixes.iter().map(|(prefix, base)| {
        Value::Record(record(
            "numbering prefix",
            vec![("prefix", text(prefix)), ("base", hex(*base, 2))],
        ))
    });
    let written = n.written_prefixes.iter().map(|(address, prefix)| {
        Value::Record(record(
            "written prefix",
            vec![("address", hex(*address, 4)), ("prefix", text(prefix))],
        ))
    });
    let (group_digits, index_digits) = n.digits();
    record(
        "numbering",
        vec![
            ("separator", text(&n.separator)),
            ("group_radix", number(n.group_radix)),
            (
                "prefixes",
                Value::List(Elem::Record("numbering prefix"), prefixes.collect()),
            ),
            ("scheme", variant("address scheme", scheme)),
            ("group_digits", number(group_digits)),
            ("index_digits", number(index_digits)),
            ("exact_digits", Value::Bool(n.widths.is_some())),
            (
                "written",
                Value::List(Elem::Record("written prefix"), written.collect()),
            ),
        ],
    )
}
