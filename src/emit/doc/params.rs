//! Acyclic data: the parameter telegram, the DPV1 indexes, the PROFINET
//! records, the choices they may hold; and the diagnosis block.

use super::page::{code, text, Builder, Cell};
use super::{
    allowed, bits, bytes, choices_caption, drive_parameter, hex_bytes, mapping_value, Lang,
};
use crate::i18n::sheet as w;
use crate::ir::profibus::{
    Diagnosis, DiagnosisArea, PrmHolds, PrmParam, PrmType, PrmValue, Profibus, STANDARD_DIAG_BYTES,
};
use crate::ir::profinet::{
    ChannelDiagnosis, Dap, ParameterRecord, Profinet, RecordValue, RecordValueType,
};
use crate::ir::{Allowed, EntryKey, EntryType, Ir, MappingKind, MappingSet};
use crate::pkw::DiagArea;

pub(crate) fn section(doc: &mut Builder, ir: &Ir, lang: Lang) {
    // Parameters that map nothing: a gateway's, the card's own.
    let other_params = ir.profibus.as_ref().is_some_and(|p| {
        !p.user_prm.gateway.is_empty()
            || !p.user_prm.card.is_empty()
            || p.modules.iter().any(|m| m.safety.is_some())
    });
    let own_records = ir
        .profinet
        .as_ref()
        .is_some_and(|p| p.own_records_of_every_submodule().next().is_some());
    if ir.mappings.groups.is_empty() && !other_params && !own_records {
        return;
    }
    doc.section(
        "parameters",
        if ir.mappings.groups.is_empty() {
            lang.t(w::PARAMETERS)
        } else {
            lang.t(w::PARAMETERS_MAPPINGS)
        },
    );
    where_set(doc, ir, lang);
    if let Some(p) = ir.profibus.as_ref().filter(|p| p.user_prm.len > 0) {
        user_prm(doc, ir, p, lang);
    }
    if let Some(p) = &ir.profibus {
        f_parameters(doc, ir, p, lang);
    }
    dpv1_indexes(doc, ir, lang);
    let records = longest_records(ir);
    if !records.is_empty() {
        doc.subsection("records", lang.t(w::PROFINET_RECORDS));
        // Records of Unsigned16 entries alone say so once; others give each
        // entry's type.
        let typed = records.iter().any(|r| {
            r.refs
                .iter()
                .any(|f| ir.mappings.entry(f.entry).0.entry_type != EntryType::Unsigned16)
                || r.fail_safe.iter().any(|v| v.double_word)
        });
        let intro = if typed {
            w::RECORDS_INTRO_TYPED
        } else {
            w::RECORDS_INTRO
        };
        doc.para(text(lang.t(intro)));
        for record in records {
            record_table(doc, ir, lang, record, typed);
        }
        module_values(doc, ir, lang);
        fail_safe_values(doc, ir, lang);
    }
    choices(doc, ir, lang);
    if own_records {
        own_records_tables(doc, ir, lang);
    }
}

/// The records of the access point and the ports: each value's place,
/// type, default and what it holds.
fn own_records_tables(doc: &mut Builder, ir: &Ir, lang: Lang) {
    let Some(p) = &ir.profinet else {
        return;
    };
    doc.subsection("own-records", lang.t(w::OWN_RECORDS));
    doc.para(text(lang.t(w::OWN_RECORDS_INTRO)));
    let lists = p.record_lists.iter().enumerate();
    let lists = lists.map(|(list, records)| (own_records_whose(p, list, lang), records));
    let safety = p.safety_modules.iter();
    let safety = safety.map(|m| (lang.text(&m.name.text).to_string(), &m.records));
    for (whose, records) in lists.chain(safety) {
        for record in records {
            let rows = record
                .values
                .iter()
                .map(|v| own_value_row(lang, v))
                .collect();
            let head = [
                lang.t(w::BYTES),
                lang.t(w::NAME),
                lang.t(w::TYPE),
                lang.t(w::DEFAULT),
                lang.t(w::RANGE_OR_CHOICES),
            ];
            let name = lang.text(&record.name.text);
            let size = record_size(lang, record.length);
            let caption = w::own_record_caption(lang, &whose, record.index, name, &size);
            doc.table(caption, &head, rows);
        }
    }
}

/// Whose the records of list `list` are: the access point's or every
/// port's, followed by the names of the device access points that have
/// them where not every one has.
fn own_records_whose(p: &Profinet, list: usize, lang: Lang) -> String {
    let port = p.daps.iter().any(|d| d.port_records == list);
    let kind = lang.t(if port {
        w::PORT_RECORD
    } else {
        w::ACCESS_POINT_RECORD
    });
    let having = |d: &&Dap| d.access_point_records == list || d.port_records == list;
    let daps: Vec<&Dap> = p.daps.iter().filter(having).collect();
    if daps.len() == p.daps.len() {
        return kind.to_string();
    }
    let names: Vec<&str> = daps.iter().map(|d| lang.text(&d.name.text)).collect();
    w::records_of(lang, kind, &names.join(lang.t(w::LIST_SEPARATOR)))
}

/// `8 bytes`, `1 byte`.
fn record_size(lang: Lang, length: u16) -> String {
    match length {
        1 => lang.t(w::ONE_BYTE).to_string(),
        n => w::bytes_count(lang, n),
    }
}

/// Bytes (and bits), name, type, default, range or choices.
fn own_value_row(lang: Lang, v: &RecordValue) -> Vec<Cell> {
    let last = v.offset + v.data_type.bytes() - 1;
    let place = bytes(lang, v.offset, last);
    let place = match v.data_type {
        RecordValueType::Bits { first, last } if first == last => {
            w::byte_bits(lang, &place, &w::bit(lang, first))
        }
        RecordValueType::Bits { first, last } => {
            w::byte_bits(lang, &place, &w::bits(lang, first, last))
        }
        _ => place,
    };
    let choice_text = |value: i64| {
        let (_, text) = v.choices().iter().find(|(c, _)| *c == value)?;
        Some(lang.text(&text.text))
    };
    let default = match choice_text(v.default.into()) {
        Some(t) => format!("{}: {t}", v.default),
        None => v.default.to_string(),
    };
    let default = match v.changeable {
        true => default,
        false => w::fixed_value(lang, &default),
    };
    let holds = match v.choices() {
        [] => w::range(lang, v.min, v.max),
        choices => choices
            .iter()
            .map(|(value, t)| format!("{value}: {}", lang.text(&t.text)))
            .collect::<Vec<_>>()
            .join(lang.t(w::LIST_SEPARATOR)),
    };
    vec![
        text(place),
        text(lang.text(&v.text.text)),
        text(v.data_type.gsdml_name()),
        text(default),
        text(holds),
    ]
}

/// Where each set's drive parameters are set, and what carries them: the
/// master's User_Prm_Data and records, or nothing, at the drive.
fn where_set(doc: &mut Builder, ir: &Ir, lang: Lang) {
    let sets: Vec<&MappingSet> = ir.mappings.sets().collect();
    if sets.is_empty() {
        return;
    }
    doc.subsection("where-set", lang.t(w::WHERE_SET_HEADING));
    if sets.iter().any(|s| s.master_writes()) {
        doc.para(text(lang.t(w::SET_BY_THE_MASTER_PARA)));
    }
    if sets.iter().any(|s| !s.master_writes()) {
        doc.para(text(lang.t(w::SET_AT_THE_DRIVE_PARA)));
    }
    let rows = sets
        .iter()
        .map(|set| {
            let first = &set.entries[0];
            let last = &set.entries[set.entries.len() - 1];
            let parameters = match (first.parameter, last.parameter) {
                (Some(a), Some(b)) if a != b => code(w::range(
                    lang,
                    super::parameter_name(ir, a),
                    super::parameter_name(ir, b),
                )),
                _ => drive_parameter(ir, first),
            };
            vec![
                text(super::set_name(lang, set)),
                parameters,
                text(match set.master_writes() {
                    true => lang.t(w::BY_THE_MASTER),
                    false => lang.t(w::AT_THE_DRIVE),
                }),
                text(carriers(ir, lang, set)),
            ]
        })
        .collect();
    doc.table(
        lang.t(w::WHERE_SET_CAPTION),
        &[
            lang.t(w::MAPPING),
            lang.t(w::DRIVE_PARAMETERS),
            lang.t(w::SET),
            lang.t(w::CARRIED_BY),
        ],
        rows,
    );
}

/// What carries a set's values to the card: User_Prm_Data's bytes, the
/// PROFINET record, or nothing (set at the drive).
fn carriers(ir: &Ir, lang: Lang, set: &MappingSet) -> String {
    let mut found = Vec::new();
    let placed = |e: &crate::ir::MappingEntry| {
        ir.profibus
            .as_ref()
            .and_then(|p| p.user_prm.placed(PrmValue::Entry(e.key)))
    };
    if let (Some(first), Some(last)) = (
        set.entries.first().and_then(placed),
        set.entries.last().and_then(placed),
    ) {
        let end = last.offset + last.data_type.bytes() - 1;
        found.push(format!("User_Prm_Data {}", bytes(lang, first.offset, end)));
    }
    let record = ir.profinet.as_ref().and_then(|p| {
        p.modules.iter().flat_map(|m| &m.records).find(|r| {
            r.refs
                .iter()
                .any(|f| set.entries.iter().any(|e| e.key == f.entry))
        })
    });
    if let Some(record) = record {
        found.push(w::in_record(lang, record.index));
    }
    match found.is_empty() {
        true => lang.t(w::NOTHING_THE_DRIVE_HOLDS).to_string(),
        false => found.join(lang.t(w::SEMICOLON)),
    }
}

/// For each record index, the longest record a module carries.
fn longest_records(ir: &Ir) -> Vec<&ParameterRecord> {
    let mut longest: Vec<&ParameterRecord> = Vec::new();
    let all = ir
        .profinet
        .iter()
        .flat_map(|p| &p.modules)
        .flat_map(|m| &m.records);
    for record in all {
        // The most entries, then the most bytes: fail-safe values follow
        // the settings, as many as the module has output items.
        let size = |r: &ParameterRecord| (r.refs.len(), r.length);
        match longest.iter_mut().find(|r| r.index == record.index) {
            Some(known) if size(known) < size(record) => *known = record,
            Some(_) => {}
            None => longest.push(record),
        }
    }
    longest.sort_by_key(|r| r.index);
    longest
}

/// Each PROFIsafe module's F-parameters: the block's fixed bytes and each
/// parameter, with the module's description CRCs.
fn f_parameters(doc: &mut Builder, ir: &Ir, p: &Profibus, lang: Lang) {
    let safety_modules: Vec<_> = p
        .modules
        .iter()
        .filter_map(|m| Some((m, m.safety.as_ref()?)))
        .collect();
    if safety_modules.is_empty() {
        return;
    }
    doc.para(text(lang.t(w::F_PARAMETERS_INTRO)));
    for (module, safety) in safety_modules {
        let mut rows: Vec<Vec<Cell>> = Vec::new();
        if !safety.constant.is_empty() {
            let last = safety.constant.len() as u16 - 1;
            rows.push(vec![
                text(bytes(lang, 0, last)),
                text(lang.t(w::CONSTANT)),
                text(lang.t(w::CONSTANT)),
                code(hex_bytes(&safety.constant)),
                text("—"),
            ]);
        }
        for param in &safety.params {
            let mut row = param_row(ir, lang, param);
            // No drive parameter holds an F-parameter.
            row.pop();
            rows.push(row);
        }
        let caption = w::f_parameters_caption(
            lang,
            &module.name,
            &record_size(lang, safety.len),
            &format!("0x{:04X}", safety.crcs.f_param_desc),
            safety.crcs.f_io_structure_desc,
        );
        let head = [
            lang.t(w::BYTES),
            lang.t(w::NAME),
            lang.t(w::TYPE),
            lang.t(w::DEFAULT),
            lang.t(w::RANGE_OR_CHOICES),
        ];
        doc.table(caption, &head, rows);
    }
}

fn user_prm(doc: &mut Builder, ir: &Ir, p: &Profibus, lang: Lang) {
    let prm = &p.user_prm;
    doc.subsection("user-prm", lang.t(w::USER_PRM_HEADING));
    let intro = w::user_prm_intro(lang, prm.len);
    // The gateway's sentence says every type, the card's own among them.
    let words_only = prm.params().all(|p| p.data_type == PrmType::Unsigned16);
    let types = if !prm.gateway.is_empty() || !prm.card.is_empty() {
        lang.t(w::USER_PRM_GATEWAY_TYPES)
    } else if words_only {
        lang.t(w::USER_PRM_TYPES)
    } else {
        lang.t(w::USER_PRM_ENTRY_TYPES)
    };
    doc.para(text(format!("{intro}{types}")));
    // A drive parameter holds a mapping; a gateway's parameters have none.
    let drive_column = !prm.blocks.is_empty();
    let mut rows: Vec<Vec<Cell>> = Vec::new();
    if !prm.constant.is_empty() {
        let last = prm.constant.len() as u16 - 1;
        let name = if p
            .dpv1
            .is_some_and(|d| d.status_bytes[..] == prm.constant[..])
        {
            lang.t(w::DPV1_STATUS)
        } else {
            lang.t(w::CONSTANT)
        };
        rows.push(vec![
            text(bytes(lang, 0, last)),
            text(name),
            text(lang.t(w::CONSTANT)),
            code(hex_bytes(&prm.constant)),
            text("—"),
            text("—"),
        ]);
    }
    for param in prm.params() {
        rows.push(param_row(ir, lang, param));
    }
    let mut head = vec![
        lang.t(w::BYTES),
        lang.t(w::NAME),
        lang.t(w::TYPE),
        lang.t(w::DEFAULT),
        lang.t(w::RANGE_OR_CHOICES),
        lang.t(w::DRIVE_PARAMETER),
    ];
    if !drive_column {
        head.pop();
        for row in &mut rows {
            row.pop();
        }
    }
    doc.table(lang.t(w::USER_PRM_DATA), &head, rows);
    let defaults = ir.default_user_prm(prm);
    doc.para(vec![
        super::page::Run::Text(lang.t(w::WITH_EVERY_DEFAULT).into()),
        super::page::Run::Code(hex_bytes(&defaults)),
    ]);
}

/// Bytes, name, type, default, range or choices, drive parameter.
fn param_row(ir: &Ir, lang: Lang, param: &PrmParam) -> Vec<Cell> {
    let facts = ir.prm_facts(param);
    let last = param.offset + param.data_type.bytes() - 1;
    let (default, range, drive) = match facts.holds {
        PrmHolds::Mapping { set, entry } => (
            mapping_value(ir, lang, set, facts.default),
            allowed(lang, set),
            drive_parameter(ir, entry),
        ),
        PrmHolds::Number { min, max } => (
            facts.default.to_string(),
            w::range(lang, min, max),
            text("—"),
        ),
        PrmHolds::Card(p) => (
            card_value(lang, &p.allowed, facts.default),
            card_allowed(lang, &p.allowed),
            text("—"),
        ),
    };
    vec![
        text(bytes(lang, param.offset, last)),
        text(lang.text(facts.name)),
        text(param.data_type.to_string()),
        text(default),
        text(range),
        drive,
    ]
}

/// A card parameter's value, with its choice's text when it has one.
fn card_value(lang: Lang, allowed: &Allowed, value: u16) -> String {
    allowed
        .choices()
        .and_then(|set| set.choices.iter().find(|c| c.value == i64::from(value)))
        .map_or_else(
            || value.to_string(),
            |c| format!("{value}: {}", lang.text(&c.text)),
        )
}

/// A card parameter's range, or its choices one by one.
fn card_allowed(lang: Lang, allowed: &Allowed) -> String {
    match allowed {
        Allowed::Range { min, max } => w::range(lang, min, max),
        Allowed::Choices(set) => set
            .choices
            .iter()
            .map(|c| format!("{}: {}", c.value, lang.text(&c.text)))
            .collect::<Vec<_>>()
            .join(", "),
    }
}

fn dpv1_indexes(doc: &mut Builder, ir: &Ir, lang: Lang) {
    let Some(group) = ir.mappings.group(MappingKind::Dpv1Index) else {
        return;
    };
    doc.subsection("dpv1", lang.t(w::DPV1_INDEXES));
    doc.para(text(lang.t(w::DPV1_INTRO)));
    if let Some(length) = group.record_length {
        doc.para(text(w::index_record_length(lang, length)));
    }
    let prm_offset = |key: EntryKey| {
        ir.profibus
            .as_ref()
            .and_then(|p| p.user_prm.placed(PrmValue::Entry(key)))
            .map(|q| q.offset)
    };
    let rows = group
        .entries()
        .map(|(set, e)| {
            vec![
                text(e.key.number.to_string()),
                text(lang.text(&e.name)),
                text(mapping_value(ir, lang, set, e.default)),
                text(allowed(lang, set)),
                prm_offset(e.key).map_or_else(|| text("—"), |o| text(bytes(lang, o, o + 1))),
            ]
        })
        .collect();
    doc.table(
        lang.t(w::DPV1_CAPTION),
        &[
            lang.t(w::INDEX),
            lang.t(w::NAME),
            lang.t(w::DEFAULT),
            lang.t(w::RANGE_OR_CHOICES),
            lang.t(w::IN_USER_PRM),
        ],
        rows,
    );
}

/// A record's entries; with `typed`, each with its type.
fn record_table(doc: &mut Builder, ir: &Ir, lang: Lang, record: &ParameterRecord, typed: bool) {
    let rows = record
        .refs
        .iter()
        .map(|r| {
            let (set, entry) = ir.mappings.entry(r.entry);
            let last = r.offset + set.entry_type.bytes() - 1;
            let mut row = vec![
                text(bytes(lang, r.offset, last)),
                text(lang.text(&entry.name)),
                // The record's own: a module writes its value of a
                // per_module setting.
                text(mapping_value(ir, lang, set, r.default)),
                text(allowed(lang, set)),
                drive_parameter(ir, entry),
            ];
            if typed {
                row.insert(2, text(set.entry_type.gsdml_name()));
            }
            row
        })
        .chain(record.fail_safe.iter().map(|value| {
            let last = value.offset + value.bytes() - 1;
            let mut row = vec![
                text(bytes(lang, value.offset, last)),
                text(lang.text(&value.text.text)),
                text("0"),
                text(w::range(lang, 0, value.max())),
                text("—"),
            ];
            if typed {
                row.insert(2, text(value.data_type()));
            }
            row
        }))
        .collect();
    let mut head = vec![
        lang.t(w::BYTES),
        lang.t(w::NAME),
        lang.t(w::DEFAULT),
        lang.t(w::RANGE_OR_CHOICES),
        lang.t(w::DRIVE_PARAMETER),
    ];
    if typed {
        head.insert(2, lang.t(w::TYPE));
    }
    let name = lang.text(&record.name.text);
    doc.table(
        w::record_caption(lang, record.index, name, &record_size(lang, record.length)),
        &head,
        rows,
    );
}

/// The fail-safe values each module's settings record ends with, one per
/// output item: the record tables show the longest record's.
fn fail_safe_values(doc: &mut Builder, ir: &Ir, lang: Lang) {
    let Some(p) = &ir.profinet else {
        return;
    };
    let rows: Vec<Vec<Cell>> = p
        .modules
        .iter()
        .filter_map(|m| {
            let record = m.records.iter().find(|r| !r.fail_safe.is_empty())?;
            let values: Vec<String> = record
                .fail_safe
                .iter()
                .map(|v| w::fail_safe_value(lang, lang.text(&v.text.text), v.data_type()))
                .collect();
            Some(vec![
                text(lang.text(&m.name.text)),
                text(bytes(lang, record.fail_safe[0].offset, record.length - 1)),
                text(values.join(lang.t(w::SEMICOLON))),
            ])
        })
        .collect();
    if rows.is_empty() {
        return;
    }
    doc.table(
        lang.t(w::FAIL_SAFE_CAPTION),
        &[
            lang.t(w::MODULE),
            lang.t(w::BYTES),
            lang.t(w::FAIL_SAFE_VALUES),
        ],
        rows,
    );
}

/// For each setting each kind of module writes its own value of, the value
/// of each module: the record tables show the longest record's.
fn module_values(doc: &mut Builder, ir: &Ir, lang: Lang) {
    let Some(p) = &ir.profinet else {
        return;
    };
    for values in &p.module_values {
        let set = ir.mappings.set(values.set);
        let rows = values
            .modules
            .iter()
            .filter_map(|(_, ident_number, value)| {
                let module = p.modules.iter().find(|m| m.ident_number == *ident_number)?;
                Some(vec![
                    text(lang.text(&module.name.text)),
                    text(mapping_value(ir, lang, set, *value)),
                ])
            })
            .collect();
        let name = lang.text(&set.entries[0].name);
        let caption = match values.changeable {
            true => w::module_defaults_caption(lang, name),
            false => w::module_values_caption(lang, name),
        };
        doc.table(caption, &[lang.t(w::MODULE), lang.t(w::VALUE)], rows);
    }
}

/// A table for each set of choices.
fn choices(doc: &mut Builder, ir: &Ir, lang: Lang) {
    for set in ir.mappings.sets() {
        if let Some(values) = set.allowed.choices() {
            let rows = values
                .choices
                .iter()
                .map(|c| vec![text(c.value.to_string()), text(lang.text(&c.text))])
                .collect();
            let caption = choices_caption(lang, set);
            let mut caption_chars = caption.chars();
            let capitalised = caption_chars.next().map_or_else(String::new, |c| {
                c.to_uppercase().chain(caption_chars).collect()
            });
            doc.table(capitalised, &[lang.t(w::VALUE), lang.t(w::MEANING)], rows);
        }
    }
}

// ---------------------------------------------------------------------------
// Diagnosis

pub(crate) fn diagnosis_section(doc: &mut Builder, ir: &Ir, lang: Lang) {
    let Some((p, d)) = ir
        .profibus
        .as_ref()
        .and_then(|p| Some((p, p.diagnosis.as_ref()?)))
    else {
        return;
    };
    doc.section("diagnosis", lang.t(w::DIAGNOSIS));
    doc.para(text(w::diagnosis_intro(
        lang,
        STANDARD_DIAG_BYTES,
        d.length,
    )));
    if let Some(info) = &d.info {
        doc.para(text(lang.text(info)));
    }
    doc.table(
        lang.t(w::DIAGNOSIS_BYTE_BY_BYTE),
        &[lang.t(w::BYTE), lang.t(w::CONTENT)],
        diagnosis_rows(p, d, lang),
    );
    for area in &d.areas {
        area_table(doc, d, area, lang);
    }
}

/// The texts of each `UnitDiagType`: its areas' values and its bits.
pub(crate) fn dp_diagnosis_types_section(doc: &mut Builder, ir: &Ir, lang: Lang) {
    let Some(p) = ir
        .profibus
        .as_ref()
        .filter(|p| !p.diagnosis_types.is_empty())
    else {
        return;
    };
    doc.section_with_intro(
        "dp-diagnosis-types",
        lang.t(w::DP_DIAGNOSIS_TYPES),
        lang.t(w::DP_DIAGNOSIS_TYPES_INTRO),
    );
    for t in &p.diagnosis_types {
        for area in &t.areas {
            let rows = area
                .values
                .choices
                .iter()
                .map(|c| {
                    vec![
                        text(c.value.to_string()),
                        code(format!("0x{:02X}", c.value)),
                        text(lang.text(&c.text)),
                    ]
                })
                .collect();
            doc.table(
                w::diagnosis_type_values(lang, t.id, &bits(lang, area.first_bit, area.last_bit)),
                &[lang.t(w::VALUE), lang.t(w::HEX), lang.t(w::MEANING)],
                rows,
            );
        }
        if !t.bits.is_empty() {
            let rows = t
                .bits
                .iter()
                .map(|b| {
                    vec![
                        code(format!("X_{}({})", b.keyword(), b.bit)),
                        text(lang.text(&b.text)),
                    ]
                })
                .collect();
            doc.table(
                w::diagnosis_type_bits(lang, t.id),
                &[lang.t(w::BITS), lang.t(w::MEANING)],
                rows,
            );
        }
    }
}

/// The error types the card reports in a PROFIBUS channel's diagnosis.
pub(crate) fn dp_channel_diagnosis_section(doc: &mut Builder, ir: &Ir, lang: Lang) {
    let Some(p) = ir
        .profibus
        .as_ref()
        .filter(|p| !p.channel_diagnosis.is_empty())
    else {
        return;
    };
    doc.section_with_intro(
        "dp-channel-diagnosis",
        lang.t(w::DP_CHANNEL_DIAGNOSIS),
        lang.t(w::DP_CHANNEL_DIAGNOSIS_INTRO),
    );
    let rows = p
        .channel_diagnosis
        .iter()
        .map(|d| vec![code(d.error_type.to_string()), text(lang.text(&d.name))])
        .collect();
    doc.table(
        lang.t(w::DP_CHANNEL_DIAGNOSIS),
        &[lang.t(w::ERROR_TYPE), lang.t(w::NAME)],
        rows,
    );
}

/// The error types the card reports as PROFINET channel diagnosis.
pub(crate) fn channel_diagnosis_section(doc: &mut Builder, ir: &Ir, lang: Lang) {
    let Some(p) = ir
        .profinet
        .as_ref()
        .filter(|p| !p.channel_diagnosis.is_empty())
    else {
        return;
    };
    doc.section_with_intro(
        "channel-diagnosis",
        lang.t(w::CHANNEL_DIAGNOSIS),
        lang.t(w::CHANNEL_DIAGNOSIS_INTRO),
    );
    let rows = p
        .channel_diagnosis
        .iter()
        .map(|d| {
            vec![
                code(format!("0x{:04X}", d.error_type)),
                d.api
                    .map_or_else(|| text(""), |api| code(format!("0x{api:04X}"))),
                text(lang.text(&d.name.text)),
                text(d.help.as_ref().map_or("", |h| lang.text(&h.text))),
            ]
        })
        .collect();
    doc.table(
        lang.t(w::CHANNEL_DIAGNOSIS),
        &[
            lang.t(w::ERROR_TYPE),
            lang.t(w::API),
            lang.t(w::NAME),
            lang.t(w::HELP),
        ],
        rows,
    );
    extended_diagnosis_table(doc, &p.channel_diagnosis, lang);
}

/// Each extended error type under its channel diagnosis's, with the data
/// items of its add value (`1: Unsigned32`).
fn extended_diagnosis_table(doc: &mut Builder, all: &[ChannelDiagnosis], lang: Lang) {
    let rows: Vec<Vec<Cell>> = all
        .iter()
        .flat_map(|d| d.extended.iter().map(move |e| (d, e)))
        .map(|(d, e)| {
            let add_value = e
                .add_value
                .iter()
                .map(|(id, data_type)| format!("{id}: {}", data_type.name()))
                .collect::<Vec<_>>()
                .join(lang.t(w::LIST_SEPARATOR));
            vec![
                code(format!("0x{:04X}", d.error_type)),
                code(format!("0x{:04X}", e.error_type)),
                text(lang.text(&e.name.text)),
                text(e.help.as_ref().map_or("", |h| lang.text(&h.text))),
                text(add_value),
            ]
        })
        .collect();
    if rows.is_empty() {
        return;
    }
    doc.para(text(lang.t(w::EXTENDED_DIAGNOSIS_INTRO)));
    doc.table(
        lang.t(w::EXTENDED_DIAGNOSIS),
        &[
            lang.t(w::ERROR_TYPE),
            lang.t(w::EXTENDED_ERROR_TYPE),
            lang.t(w::NAME),
            lang.t(w::HELP),
            lang.t(w::ADD_VALUE),
        ],
        rows,
    );
}

fn diagnosis_rows(p: &Profibus, d: &Diagnosis, lang: Lang) -> Vec<Vec<Cell>> {
    let header = STANDARD_DIAG_BYTES;
    let mut rows = standard_diagnosis_rows(p, lang);
    rows.push(vec![
        text(bytes(lang, u16::from(header), u16::from(header))),
        text(w::diagnosis_header(lang, &format!("{:02X}", d.length))),
    ]);
    for byte in 1..d.length {
        let bit_of_byte = u16::from(byte - 1) * 8;
        let areas: Vec<String> = d
            .areas
            .iter()
            .filter(|a| a.first_bit < bit_of_byte + 8 && a.last_bit >= bit_of_byte)
            .map(|a| format!("Unit_Diag_Area {}", bits(lang, a.first_bit, a.last_bit)))
            .chain(
                d.bits
                    .iter()
                    .filter(|b| (bit_of_byte..bit_of_byte + 8).contains(&b.bit))
                    .map(|b| format!("{}({}): {}", b.keyword(), b.bit, lang.text(&b.text))),
            )
            .collect();
        let at = header + byte;
        let said = d.byte(at).map(|t| lang.text(t).to_string());
        let areas = areas.join(lang.t(w::LIST_SEPARATOR));
        let content = match (said, areas.is_empty()) {
            (Some(said), true) => said,
            (Some(said), false) => w::byte_and_areas(lang, &said, &areas),
            (None, false) => areas,
            (None, true) => lang.t(w::DEVICE_RELATED_UNDESCRIBED).to_string(),
        };
        let at = u16::from(at);
        rows.push(vec![text(bytes(lang, at, at)), text(content)]);
    }
    rows
}

/// The standard diagnosis before the device-related block.
pub(super) fn standard_diagnosis_rows(p: &Profibus, lang: Lang) -> Vec<Vec<Cell>> {
    let [ident_high, ident_low] = p.ident_number.to_be_bytes();
    vec![
        vec![text(bytes(lang, 0, 2)), text(lang.t(w::STATION_STATUS))],
        vec![text(bytes(lang, 3, 3)), text(lang.t(w::MASTER_ADDRESS))],
        vec![
            text(bytes(lang, 4, 5)),
            text(w::ident_number_bytes(lang, ident_high, ident_low)),
        ],
    ]
}

/// Each value of an area with the whole device-related block that reports
/// it, encoded by the firmware's own code.
fn area_table(doc: &mut Builder, d: &Diagnosis, area: &DiagnosisArea, lang: Lang) {
    let codec = DiagArea::new(area.first_bit, area.last_bit);
    let rows = area
        .values
        .choices
        .iter()
        .map(|c| {
            let mut block = vec![0u8; usize::from(d.length)];
            block[0] = d.length;
            codec.set(&mut block, c.value as u16);
            vec![
                text(c.value.to_string()),
                code(format!("0x{:02X}", c.value)),
                text(lang.text(&c.text)),
                code(hex_bytes(&block)),
            ]
        })
        .collect();
    doc.table(
        w::area_values(lang, &bits(lang, area.first_bit, area.last_bit)),
        &[
            lang.t(w::VALUE),
            lang.t(w::HEX),
            lang.t(w::MEANING),
            lang.t(w::BLOCK_OTHER_BITS_0),
        ],
        rows,
    );
}
