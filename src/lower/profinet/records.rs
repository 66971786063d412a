//! Parameter records: which record index holds which kind of mapping, the
//! Refs each module's records carry, and the ValueItems of their choices.

use super::ids::{kind_tag, value_tag};
use crate::description as raw;
use crate::diag::Diagnostic;
use crate::ir::profinet::{Module, ParameterRecord, RecordRef, TextRef, ValueItem};
use crate::ir::{MappingKind, Mappings, Text};
use crate::lower::checks::Checker;
use std::collections::BTreeSet;
use toml::Spanned;

/// Record indexes 0..0x7FFF are the vendor's (IEC 61158-6-10).
const MAX_VENDOR_RECORD_INDEX: i64 = 0x7FFF;

/// One record per kind of mapping the description has: PZD out, PZD in,
/// DPV1 indexes, settings; indexes 1, 2, 3, 4 unless the description says otherwise.
/// An index the description leaves out is gsdc's default, said (W104).
pub fn indexes(
    cx: &mut Checker,
    p: &Spanned<raw::Profinet>,
    mappings: &Mappings,
) -> Vec<(MappingKind, u16)> {
    let given = &p.get_ref().records;
    let kinds = [
        (MappingKind::PzdOut, &given.pzd_out, 1),
        (MappingKind::PzdIn, &given.pzd_in, 2),
        (MappingKind::Dpv1Index, &given.dpv1_index, 3),
        (MappingKind::Setting, &given.settings, 4),
    ];
    let mut used = BTreeSet::new();
    kinds
        .into_iter()
        .filter(|(kind, _, _)| mappings.group(*kind).is_some())
        .filter_map(|(kind, given, default)| {
            let index = match given {
                Some(i) => cx.spanned_in_range(i, 1, MAX_VENDOR_RECORD_INDEX, "a record index")?,
                None => {
                    let path = format!("profinet.records.{}", kind.key());
                    cx.defaulted(&path, default, p.span());
                    default
                }
            };
            if !used.insert(index) {
                cx.push(
                    Diagnostic::error("E105", format!("record index {index} is used twice"))
                        .at_opt(given.as_ref().map(Spanned::span))
                        .label("used by another record")
                        .help("give each record its own index under [profinet.records]"),
                );
            }
            Some((kind, index))
        })
        .collect()
}

/// The records a module carries: one Unsigned16 Ref per entry of the
/// record's kind, at offsets 0, 2, 4, ...
pub fn records(mappings: &Mappings, indexes: &[(MappingKind, u16)]) -> Vec<ParameterRecord> {
    indexes
        .iter()
        .filter_map(|&(kind, index)| {
            let group = mappings.group(kind)?;
            let refs: Vec<RecordRef> = group
                .entries()
                .zip((0..).step_by(2))
                .map(|((set, entry), offset)| RecordRef {
                    offset,
                    entry: entry.key,
                    text: TextRef::new(
                        format!("IDT_{}_{}", kind_tag(kind), entry.key.number),
                        entry.name.clone(),
                    ),
                    value_item: set
                        .allowed
                        .choices()
                        .map(|_| format!("IDV_{}", value_tag(set))),
                })
                .collect();
            Some(ParameterRecord {
                kind,
                index,
                name: TextRef::new(format!("IDT_RECORD_{index}"), record_name(kind)),
                // Entries per kind are bounded by lowering (at most 256 a set).
                length: u16::try_from(2 * refs.len()).unwrap_or(u16::MAX),
                refs,
            })
        })
        .collect()
}

/// gsdc's name of a record, in English and gsdc's Chinese.
fn record_name(kind: MappingKind) -> Text {
    let (en, zh) = match kind {
        MappingKind::PzdOut => (
            "PZD output mapping (controller to drive)",
            "PZD 输出映射（控制器到驱动器）",
        ),
        MappingKind::PzdIn => (
            "PZD input mapping (drive to controller)",
            "PZD 输入映射（驱动器到控制器）",
        ),
        MappingKind::Dpv1Index => ("Record index mapping", "记录索引映射"),
        MappingKind::Setting => ("Drive settings", "驱动器设置"),
    };
    Text::en_zh(en, zh)
}

/// One ValueItem per set of choices a module's record refers to, in the
/// order of the records and their sets.
pub fn value_items(mappings: &Mappings, modules: &[Module]) -> Vec<ValueItem> {
    let kinds: BTreeSet<MappingKind> = modules
        .iter()
        .flat_map(|m| &m.records)
        .map(|r| r.kind)
        .collect();
    kinds
        .into_iter()
        .filter_map(|kind| mappings.group(kind))
        .flat_map(|g| &g.sets)
        .filter_map(|set| {
            let tag = value_tag(set);
            let assignments = set
                .allowed
                .choices()?
                .choices
                .iter()
                .map(|c| {
                    let text = TextRef::new(format!("IDT_{tag}_VALUE_{}", c.value), c.text.clone());
                    (c.value, text)
                })
                .collect();
            Some(ValueItem {
                id: format!("IDV_{tag}"),
                set: set.key,
                assignments,
            })
        })
        .collect()
}
