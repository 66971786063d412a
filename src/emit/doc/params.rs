//! Acyclic data: the parameter telegram, the DPV1 indexes, the PROFINET
//! records, the choices they may hold; and the diagnosis block.

use super::page::{code, text, Builder, Cell};
use super::{
    allowed, bits, bytes, choices_caption, drive_parameter, hex_bytes, mapping_value, Lang,
};
use crate::ir::profibus::{
    Diagnosis, DiagnosisArea, PrmHolds, PrmParam, PrmValue, Profibus, STANDARD_DIAG_BYTES,
};
use crate::ir::profinet::ParameterRecord;
use crate::ir::{EntryKey, Ir, MappingKind, MappingSet};
use crate::pkw::DiagArea;

pub(crate) fn section(doc: &mut Builder, ir: &Ir, lang: Lang) {
    let gateway_params = ir
        .profibus
        .as_ref()
        .is_some_and(|p| !p.user_prm.gateway.is_empty());
    if ir.mappings.groups.is_empty() && !gateway_params {
        return;
    }
    doc.section(
        "parameters",
        if ir.mappings.groups.is_empty() {
            lang.t("Parameters", "参数")
        } else {
            lang.t("Parameters: mappings and settings", "参数：映射与设置")
        },
    );
    where_set(doc, ir, lang);
    if let Some(p) = ir.profibus.as_ref().filter(|p| p.user_prm.len > 0) {
        user_prm(doc, ir, p, lang);
    }
    dpv1_indexes(doc, ir, lang);
    let records = longest_records(ir);
    if !records.is_empty() {
        doc.subsection(
            "records",
            lang.t("PROFINET parameter records", "PROFINET 参数记录"),
        );
        doc.para(text(lang.t(
            "The controller writes these records when it plugs a module. Each holds one Unsigned16 per entry, high byte first; a module's PZD record holds the words it transports, and the tables show the longest.",
            "控制器插入模块时写入以下参数记录。每个条目一个 Unsigned16，高字节在前；模块的 PZD 记录只含该模块传输的字，下表为最长的记录。",
        )));
        for record in records {
            record_table(doc, ir, lang, record);
        }
    }
    choices(doc, ir, lang);
}

/// Where each set's drive parameters are set, and what carries them: the
/// master's User_Prm_Data and records, or nothing, at the drive.
fn where_set(doc: &mut Builder, ir: &Ir, lang: Lang) {
    let sets: Vec<&MappingSet> = ir.mappings.sets().collect();
    if sets.is_empty() {
        return;
    }
    doc.subsection(
        "where-set",
        lang.t("Where each mapping is set", "各映射在何处设置"),
    );
    let by_master = sets.iter().any(|s| s.master_writes());
    let at_drive = sets.iter().any(|s| !s.master_writes());
    if by_master {
        doc.para(text(lang.t(
            "Set by the master: the configuration tool holds the values, and the master writes them at every startup, on PROFIBUS in the parameter telegram (User_Prm_Data), on PROFINET in the module's parameter records. A value changed at the drive is overwritten at the next startup.",
            "由主站设置：数值保存在组态软件中，主站在每次启动时写入，PROFIBUS 通过参数报文（User_Prm_Data），PROFINET 通过模块的参数记录。在变频器上修改的值会在下次启动时被覆盖。",
        )));
    }
    if at_drive {
        doc.para(text(lang.t(
            "Set at the drive: with its keypad, a PKW write or the drive's own tool, as its parameters. No parameter telegram or record carries them: the master writes nothing at startup, and the card uses what the drive holds.",
            "在变频器上设置：通过键盘、PKW 写操作或变频器自身的工具，作为其功能参数设置。参数报文和参数记录都不包含这些参数：主站在启动时不写入任何值，扩展卡使用变频器中保存的值。",
        )));
    }
    let rows = sets
        .iter()
        .map(|set| {
            let first = &set.entries[0];
            let last = &set.entries[set.entries.len() - 1];
            let parameters = match (first.parameter, last.parameter) {
                (Some(a), Some(b)) if a != b => code(lang.f(
                    format!(
                        "{} to {}",
                        super::parameter_name(ir, a),
                        super::parameter_name(ir, b)
                    ),
                    format!(
                        "{}～{}",
                        super::parameter_name(ir, a),
                        super::parameter_name(ir, b)
                    ),
                )),
                _ => drive_parameter(ir, first),
            };
            vec![
                text(super::set_name(lang, set)),
                parameters,
                text(match set.master_writes() {
                    true => lang.t("by the master", "由主站设置"),
                    false => lang.t("at the drive", "在变频器上设置"),
                }),
                text(carriers(ir, lang, set)),
            ]
        })
        .collect();
    doc.table(
        lang.t("Where each mapping is set", "各映射的设置位置"),
        &[
            lang.t("Mapping", "映射"),
            lang.t("Drive parameters", "变频器参数"),
            lang.t("Set", "设置"),
            lang.t("Carried by", "承载方式"),
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
        found.push(lang.f(
            format!("record {}", record.index),
            format!("记录 {}", record.index),
        ));
    }
    match found.is_empty() {
        true => lang
            .t("nothing: the drive holds them", "无：由变频器保存")
            .to_string(),
        false => found.join(lang.t("; ", "；")),
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
        match longest.iter_mut().find(|r| r.index == record.index) {
            Some(known) if known.refs.len() < record.refs.len() => *known = record,
            Some(_) => {}
            None => longest.push(record),
        }
    }
    longest.sort_by_key(|r| r.index);
    longest
}

fn user_prm(doc: &mut Builder, ir: &Ir, p: &Profibus, lang: Lang) {
    let prm = &p.user_prm;
    doc.subsection(
        "user-prm",
        lang.t(
            "PROFIBUS parameter telegram (User_Prm_Data)",
            "PROFIBUS 参数报文（User_Prm_Data）",
        ),
    );
    let intro = lang.f(
        format!("The master sends it before data exchange, after the 7 standard bytes: {} bytes, offsets counted from its first byte.", prm.len),
        format!("主站在数据交换前发送参数报文，位于 7 个标准字节之后：共 {} 字节，偏移从其第一个字节算起。", prm.len),
    );
    let types = if prm.gateway.is_empty() {
        lang.t(
            " Every entry is one Unsigned16, high byte first; the configuration tool shows it in decimal.",
            "每个条目为一个 Unsigned16，高字节在前；组态软件中以十进制显示。",
        )
    } else {
        lang.t(
            " An Unsigned8 is one byte, an Unsigned16 two, high byte first; a BitArea(first-last) is those bits of its byte, whose other bits other parameters hold. The configuration tool shows the values in decimal.",
            "Unsigned8 占一个字节，Unsigned16 占两个字节，高字节在前；BitArea(起始位-结束位) 为所在字节中的这些位，该字节的其余位属于其它参数。组态软件中以十进制显示。",
        )
    };
    doc.para(text(format!("{intro}{types}")));
    // A drive parameter holds a mapping; a gateway's parameters have none.
    let drive_column = !prm.blocks.is_empty();
    let mut rows: Vec<Vec<Cell>> = Vec::new();
    if !prm.constant.is_empty() {
        let last = prm.constant.len() as u16 - 1;
        let name = if p.dpv1.is_some() {
            lang.t(
                "DPV1_Status_1 to DPV1_Status_3",
                "DPV1_Status_1～DPV1_Status_3",
            )
        } else {
            lang.t("constant", "常量")
        };
        rows.push(vec![
            text(bytes(lang, 0, last)),
            text(name),
            text(lang.t("constant", "常量")),
            code(hex_bytes(&prm.constant)),
            text("—"),
            text("—"),
        ]);
    }
    for param in prm.params() {
        rows.push(param_row(ir, lang, param));
    }
    let mut head = vec![
        lang.t("Bytes", "字节"),
        lang.t("Name", "名称"),
        lang.t("Type", "类型"),
        lang.t("Default", "默认值"),
        lang.t("Range or choices", "范围或选项"),
        lang.t("Drive parameter", "变频器参数"),
    ];
    if !drive_column {
        head.pop();
        for row in &mut rows {
            row.pop();
        }
    }
    doc.table(lang.t("User_Prm_Data", "User_Prm_Data"), &head, rows);
    let defaults = ir.default_user_prm(prm);
    doc.para(vec![
        super::page::Run::Text(lang.t("With every default: ", "全部为默认值时：").into()),
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
            lang.f(format!("{min} to {max}"), format!("{min}～{max}")),
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

fn dpv1_indexes(doc: &mut Builder, ir: &Ir, lang: Lang) {
    let Some(group) = ir.mappings.group(MappingKind::Dpv1Index) else {
        return;
    };
    doc.subsection("dpv1", lang.t("DPV1 indexes", "DPV1 自定义 Index"));
    doc.para(text(lang.t(
        "A DPV1 class 1 master reads (SFB52) and writes (SFB53) the parameter mapped to an index.",
        "DPV1 一类主站通过 SFB52 读、SFB53 写映射到各 Index 的功能码。",
    )));
    if let Some(length) = group.record_length {
        doc.para(text(lang.f(
            format!("Each index's record is {length} bytes; the card refuses others."),
            format!("每个 Index 的记录长度为 {length} 字节；其它长度被拒绝。"),
        )));
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
        lang.t(
            "DPV1 indexes and the parameters they map",
            "DPV1 Index 及其映射的参数",
        ),
        &[
            lang.t("Index", "Index"),
            lang.t("Name", "名称"),
            lang.t("Default", "默认值"),
            lang.t("Range or choices", "范围或选项"),
            lang.t("In User_Prm_Data", "在 User_Prm_Data 中"),
        ],
        rows,
    );
}

fn record_table(doc: &mut Builder, ir: &Ir, lang: Lang, record: &ParameterRecord) {
    let rows = record
        .refs
        .iter()
        .map(|r| {
            let (set, entry) = ir.mappings.entry(r.entry);
            vec![
                text(bytes(lang, r.offset, r.offset + 1)),
                text(lang.text(&entry.name)),
                text(mapping_value(ir, lang, set, entry.default)),
                text(allowed(lang, set)),
                drive_parameter(ir, entry),
            ]
        })
        .collect();
    let name = lang.text(&record.name.text);
    doc.table(
        lang.f(
            format!("Record {}: {name}, {} bytes", record.index, record.length),
            format!("记录 {}：{name}，{} 字节", record.index, record.length),
        ),
        &[
            lang.t("Bytes", "字节"),
            lang.t("Name", "名称"),
            lang.t("Default", "默认值"),
            lang.t("Range or choices", "范围或选项"),
            lang.t("Drive parameter", "变频器参数"),
        ],
        rows,
    );
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
            doc.table(
                capitalised,
                &[lang.t("Value", "值"), lang.t("Meaning", "含义")],
                rows,
            );
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
    doc.section("diagnosis", lang.t("Diagnosis", "诊断"));
    doc.para(text(lang.f(
        format!("The slave's diagnosis: {STANDARD_DIAG_BYTES} standard bytes, then the device-related block of {} bytes, its header byte first (bits 7-6 = 00, bits 5-0 = the block's length). Unit_Diag_Area bits count from bit 0 of the byte after the header.", d.length),
        format!("从站诊断数据：{STANDARD_DIAG_BYTES} 个标准字节，之后是 {} 字节的设备专用诊断块，首字节为块头（位 7-6 = 00，位 5-0 = 块长度）。Unit_Diag_Area 的位从块头后一个字节的位 0 算起。", d.length),
    )));
    if let Some(info) = &d.info {
        doc.para(text(lang.text(info)));
    }
    doc.table(
        lang.t("The diagnosis, byte by byte", "诊断数据各字节"),
        &[lang.t("Byte", "字节"), lang.t("Content", "内容")],
        diagnosis_rows(p, d, lang),
    );
    for area in &d.areas {
        area_table(doc, d, area, lang);
    }
}

fn diagnosis_rows(p: &Profibus, d: &Diagnosis, lang: Lang) -> Vec<Vec<Cell>> {
    let header = STANDARD_DIAG_BYTES;
    let mut rows = standard_diagnosis_rows(p, lang);
    rows.push(vec![
        text(bytes(lang, u16::from(header), u16::from(header))),
        text(lang.f(
            format!("header: the block's length, {:02X}", d.length),
            format!("块头：块长度 {:02X}", d.length),
        )),
    ]);
    for byte in 1..d.length {
        let bit_of_byte = u16::from(byte - 1) * 8;
        let areas: Vec<String> = d
            .areas
            .iter()
            .filter(|a| a.first_bit < bit_of_byte + 8 && a.last_bit >= bit_of_byte)
            .map(|a| format!("Unit_Diag_Area {}", bits(lang, a.first_bit, a.last_bit)))
            .collect();
        let at = header + byte;
        let said = d.byte(at).map(|t| lang.text(t).to_string());
        let content = match (said, areas.is_empty()) {
            (Some(said), true) => said,
            (Some(said), false) => lang.f(
                format!("{said}: {}", areas.join(", ")),
                format!("{said}：{}", areas.join("、")),
            ),
            (None, false) => areas.join(", "),
            (None, true) => lang
                .t("device-related, not described", "设备专用，未定义")
                .to_string(),
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
        vec![
            text(bytes(lang, 0, 2)),
            text(lang.t("Station_Status_1 to Station_Status_3", "站状态 1～3")),
        ],
        vec![
            text(bytes(lang, 3, 3)),
            text(lang.t("the master's address", "主站号")),
        ],
        vec![
            text(bytes(lang, 4, 5)),
            text(lang.f(
                format!("Ident_Number, high byte then low: {ident_high:02X} {ident_low:02X}"),
                format!("Ident_Number，高字节、低字节：{ident_high:02X} {ident_low:02X}"),
            )),
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
        lang.f(
            format!(
                "Unit_Diag_Area {}: values",
                bits(lang, area.first_bit, area.last_bit)
            ),
            format!(
                "Unit_Diag_Area {}：取值",
                bits(lang, area.first_bit, area.last_bit)
            ),
        ),
        &[
            lang.t("Value", "值"),
            lang.t("Hex", "十六进制"),
            lang.t("Meaning", "含义"),
            lang.t(
                "Block (header first), other bits 0",
                "诊断块（含块头，其余位为 0）",
            ),
        ],
        rows,
    );
}
