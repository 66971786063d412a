//! Parameter records: which record index holds which kind of mapping, the
//! Refs each module's records carry (sized to the module: a PZD record holds
//! the words the module transports), and the ValueItems of their choices.

use super::fail_safe::FailSafeItem;
use super::ids::{kind_tag, value_tag};
use crate::description as raw;
use crate::diag::Diagnostic;
use crate::i18n::files;
use crate::ir::profinet::{
    self, FailSafeValue, Module, ModuleKind, ModuleValues, ParameterRecord, RecordReading,
    RecordRef, TextRef, ValueItem,
};
use crate::ir::{Layout, MappingEntry, MappingKind, MappingSet, Mappings, Text};
use crate::lower::checks::Checker;
use std::collections::{BTreeMap, BTreeSet};
use std::ops::Range;
use toml::Spanned;

/// Record indexes 0..0x7FFF are the vendor's (IEC 61158-6-10).
const MAX_VENDOR_RECORD_INDEX: i64 = 0x7FFF;

/// A record of one kind of mapping: its index and name.
pub struct RecordPlan {
    kind: MappingKind,
    index: u16,
    name: Text,
}

/// One record per kind of mapping the description has: PZD out, PZD in,
/// DPV1 indexes, settings; indexes 1, 2, 3, 4 and gsdc's names unless the
/// description says otherwise (an index it leaves out is gsdc's default,
/// said with W104). A record for a kind the description has none of is
/// E139: it would be left out of the file without a word.
pub fn plans(
    cx: &mut Checker,
    p: &Spanned<raw::Profinet>,
    desc: &raw::Description,
    mappings: &Mappings,
) -> Vec<RecordPlan> {
    let given = &p.get_ref().records;
    let kinds = [
        (MappingKind::PzdOut, &given.pzd_out, 1),
        (MappingKind::PzdIn, &given.pzd_in, 2),
        (MappingKind::Dpv1Index, &given.dpv1_index, 3),
        (MappingKind::Setting, &given.settings, 4),
    ];
    let m = &desc.mappings;
    let described = |kind| match kind {
        MappingKind::PzdOut => m.pzd_out.is_some(),
        MappingKind::PzdIn => m.pzd_in.is_some(),
        MappingKind::Dpv1Index => m.dpv1_index.is_some(),
        MappingKind::Setting => !desc.settings.is_empty(),
    };
    // The master writes a record of a kind when it sets one of its sets.
    let master_writes = |kind| {
        mappings
            .group(kind)
            .is_some_and(|g| g.sets.iter().any(MappingSet::master_writes))
    };
    // Each index in use, with the kind of its record and where the
    // description writes it (not at all for gsdc's default).
    let mut used: BTreeMap<u16, (MappingKind, Option<Range<usize>>)> = BTreeMap::new();
    kinds
        .into_iter()
        .filter_map(|(kind, given, default)| {
            let written = given.as_ref().map(|r| r.get_ref().index_span(&r.span()));
            if let (Some(span), false) = (&written, described(kind)) {
                no_mappings(cx, kind, span.clone());
            }
            // A kind whose mappings failed has said why.
            mappings.group(kind)?;
            if !master_writes(kind) {
                if let Some(span) = written {
                    set_at_the_drive(cx, kind, span, set_at_span(desc, kind));
                }
                return None;
            }
            let index = match given.as_ref().zip(written.clone()) {
                Some((record, span)) => {
                    let index = *record.get_ref().index.get_ref();
                    cx.in_range(index, 1, MAX_VENDOR_RECORD_INDEX, span, "a record index")?
                }
                None => {
                    let path = format!("profinet.records.{}", kind.key());
                    cx.defaulted(&path, default, p.span());
                    default
                }
            };
            match used.get(&index) {
                Some((other_kind, other)) => {
                    two_records(
                        cx,
                        index,
                        (kind, written.clone()),
                        (*other_kind, other.clone()),
                    );
                }
                None => {
                    if !custom_index_clash(
                        cx,
                        desc,
                        mappings,
                        index,
                        (kind, written.clone(), p.span()),
                    ) {
                        used.insert(index, (kind, written));
                    }
                }
            }
            let name = match given.as_ref().and_then(|r| r.get_ref().name.as_ref()) {
                Some(name) => cx.text(name, None, "record name"),
                None => record_name(kind),
            };
            Some(RecordPlan { kind, index, name })
        })
        .collect()
}

/// E105: two parameter records at one index, shown where the description
/// writes each index (one of them may be gsdc's default, written nowhere).
fn two_records(
    cx: &mut Checker,
    index: u16,
    (kind, written): (MappingKind, Option<Range<usize>>),
    (other_kind, other): (MappingKind, Option<Range<usize>>),
) {
    let label = |kind: MappingKind, written: bool| match written {
        true => format!("the record of {}", kind.key()),
        false => format!("{}'s record has index {index} by default", kind.key()),
    };
    let (first, second) = match (written, other) {
        (Some(here), other) => (
            (here, label(kind, true)),
            other.map(|o| (o, label(other_kind, true))),
        ),
        (None, Some(other)) => {
            let both = format!("{}, and {}", label(other_kind, true), label(kind, false));
            ((other, both), None)
        }
        (None, None) => unreachable!("gsdc's default indexes differ"),
    };
    let mut d = Diagnostic::error(
        "E105",
        format!(
            "record index {index} is used twice: the records of {} and {} would be one record of each module",
            other_kind.key(),
            kind.key()
        ),
    )
    .at(first.0)
    .label(first.1)
    .help("give each record its own index under [profinet.records]");
    if let Some((span, label)) = second {
        d = d.also_at(span, label);
    }
    cx.push(d);
}

/// E105 when a parameter record's index is one of the custom indexes
/// (`[mappings.dpv1_index]`), which are records of the same numbers on
/// each module: a read of the custom index would read the parameter
/// record. `record` is the kind, where its index is written (nowhere for
/// gsdc's default) and the `[profinet]` table. Whether it clashed.
fn custom_index_clash(
    cx: &mut Checker,
    desc: &raw::Description,
    mappings: &Mappings,
    index: u16,
    (kind, written, profinet): (MappingKind, Option<Range<usize>>, Range<usize>),
) -> bool {
    let (Some(custom), Some(group)) = (
        &desc.mappings.dpv1_index,
        mappings.group(MappingKind::Dpv1Index),
    ) else {
        return false;
    };
    let Some((_, entry)) = group
        .entries()
        .find(|(_, e)| u16::from(e.key.number) == index)
    else {
        return false;
    };
    let label = match written {
        Some(_) => format!("the record of {}", kind.key()),
        None => format!(
            "{}'s record has index {index} by default: no `{}` here",
            kind.key(),
            kind.key()
        ),
    };
    cx.push(
        Diagnostic::error(
            "E105",
            format!(
                "record index {index} is used twice: the record of {} and the custom index {}",
                kind.key(),
                entry.name.en
            ),
        )
        .at(written.unwrap_or(profinet))
        .label(label)
        .also_at(
            custom.first.span(),
            format!(
                "{} to {} are records {} to {} of each module",
                group.sets[0].entries[0].name.en,
                group.sets.last().and_then(|s| s.entries.last()).map_or("", |e| e.name.en.as_str()),
                custom.first.get_ref(),
                custom.last.get_ref()
            ),
        )
        .help(format!(
            "give the record of {} an index outside the custom indexes {} to {} under [profinet.records]",
            kind.key(),
            custom.first.get_ref(),
            custom.last.get_ref()
        )),
    );
    true
}

/// E158: a record for a kind of mapping the description sets at the drive,
/// where the master writes nothing.
fn set_at_the_drive(
    cx: &mut Checker,
    kind: MappingKind,
    span: Range<usize>,
    said: Option<Range<usize>>,
) {
    let table = match kind {
        MappingKind::Setting => "every setting of [[settings]] has".to_string(),
        kind => format!("[mappings.{}] has", kind.key()),
    };
    let mut d = Diagnostic::error(
        "E158",
        format!("a record for {}, which the drive's own settings hold", kind.key()),
    )
    .at(span)
    .label("the master would write it at every startup")
    .help(format!(
        "{table} set_at = \"drive\": no record carries it; remove this index, or say set_at = \"master\" if the master sets it"
    ));
    if let Some(said) = said {
        d = d.also_at(said, "set at the drive");
    }
    cx.push(d);
}

/// Where the description says a kind is set at the drive: the mapping's
/// `set_at`, or the first setting's.
fn set_at_span(desc: &raw::Description, kind: MappingKind) -> Option<Range<usize>> {
    let m = &desc.mappings;
    let said = match kind {
        MappingKind::PzdOut => m.pzd_out.as_ref()?.set_at.as_ref(),
        MappingKind::PzdIn => m.pzd_in.as_ref()?.set_at.as_ref(),
        MappingKind::Dpv1Index => m.dpv1_index.as_ref()?.set_at.as_ref(),
        MappingKind::Setting => desc.settings.iter().find_map(|s| s.set_at.as_ref()),
    };
    said.map(Spanned::span)
}

/// E139: a record for a kind of mapping the description does not have.
fn no_mappings(cx: &mut Checker, kind: MappingKind, span: Range<usize>) {
    let table = match kind {
        MappingKind::Setting => "[[settings]]".to_string(),
        kind => format!("[mappings.{}]", kind.key()),
    };
    cx.push(
        Diagnostic::error(
            "E139",
            format!(
                "a record for {}, but the description has no {table}",
                kind.key()
            ),
        )
        .at(span)
        .label("no record to index")
        .help(format!(
            "a record holds the entries of {table}: add them, or remove this index"
        )),
    );
}

/// The records a module carries, one Ref per entry, each of its set's type,
/// with no gaps: a user-defined module every kind, each PZD record with the
/// words the module transports; a standard telegram only the settings each
/// kind of module writes its own value of. The settings record ends with
/// the module's `fail_safe` values. A record with no entry for the module
/// is left out.
pub fn records(
    mappings: &Mappings,
    plans: &[RecordPlan],
    (kind, layout): (ModuleKind, Layout),
    mut fail_safe: Vec<FailSafeItem>,
) -> Vec<ParameterRecord> {
    plans
        .iter()
        .filter_map(|plan| {
            let group = mappings.group(plan.kind)?;
            let mut end = 0;
            let refs: Vec<RecordRef> = group
                .entries()
                .filter_map(|(set, entry)| ref_value(set, entry, kind, layout))
                .map(|(set, entry, value)| RecordRef {
                    offset: next_offset(&mut end, set),
                    entry: entry.key,
                    text: TextRef::new(
                        format!("IDT_{}_{}", kind_tag(plan.kind), entry.key.number),
                        entry.name.clone(),
                    ),
                    default: value.unwrap_or(entry.default),
                    changeable: set.per_module.is_none_or(|p| p.changeable),
                    value_item: set
                        .allowed
                        .choices()
                        .map(|_| format!("IDV_{}", value_tag(set))),
                })
                .collect();
            // Only the settings record (one per module) takes them.
            let items = match plan.kind {
                MappingKind::Setting => std::mem::take(&mut fail_safe),
                _ => Vec::new(),
            };
            let fail_safe: Vec<FailSafeValue> = items
                .into_iter()
                .map(|item| {
                    let value = FailSafeValue {
                        offset: end,
                        text: item.text,
                        double_word: item.double_word,
                    };
                    end = end.saturating_add(value.bytes());
                    value
                })
                .collect();
            (!refs.is_empty() || !fail_safe.is_empty()).then(|| ParameterRecord {
                kind: plan.kind,
                index: plan.index,
                name: TextRef::new(format!("IDT_RECORD_{}", plan.index), plan.name.clone()),
                length: end,
                refs,
                fail_safe,
            })
        })
        .collect()
}

/// Where an entry of `set` starts after the record's `end`, which it moves.
/// Entries per kind are bounded by lowering (at most 256 of at most two
/// bytes), so no record reaches u16::MAX.
fn next_offset(end: &mut u16, set: &MappingSet) -> u16 {
    let offset = *end;
    *end = end.saturating_add(set.entry_type.bytes());
    offset
}

/// Whether `entry` is in the module's record, and the value the module
/// writes for it if each kind of module writes its own.
fn ref_value<'a>(
    set: &'a MappingSet,
    entry: &'a MappingEntry,
    module: ModuleKind,
    layout: Layout,
) -> Option<(&'a MappingSet, &'a MappingEntry, Option<u16>)> {
    let carried = match entry.key.kind {
        MappingKind::PzdOut | MappingKind::PzdIn => entry.key.number <= layout.pzd_words,
        _ => true,
    };
    if !set.master_writes() {
        return None;
    }
    let value = match (module, set.per_module) {
        (ModuleKind::Pzd, per_module) if carried => per_module.map(|p| p.user_defined),
        (ModuleKind::StandardTelegram1, Some(p)) => Some(p.standard_telegram_1?),
        (ModuleKind::StandardTelegram2, Some(p)) => Some(p.standard_telegram_2?),
        _ => return None,
    };
    Some((set, entry, value))
}

/// How firmware reads each kind of record some module carries: its index,
/// the bytes of every entry, and whether a module's record holds them all
/// or the first (a PZD record holds the words the module transports).
pub fn reading_plans(mappings: &Mappings, modules: &[Module]) -> Vec<profinet::RecordPlan> {
    mappings
        .groups
        .iter()
        .filter_map(|group| {
            let record = modules
                .iter()
                .flat_map(|m| &m.records)
                .find(|r| r.kind == group.kind)?;
            let reading = match group.kind {
                MappingKind::PzdOut | MappingKind::PzdIn => RecordReading::Prefix,
                MappingKind::Dpv1Index | MappingKind::Setting => RecordReading::Whole,
            };
            Some(profinet::RecordPlan {
                kind: group.kind,
                index: record.index,
                length: group
                    .entries()
                    .map(|(set, _)| set.entry_type.bytes())
                    .fold(0, u16::saturating_add),
                reading,
            })
        })
        .collect()
}

/// For each set each kind of module writes its own value of: every module
/// whose records carry it, with the value the module writes.
pub fn module_values(mappings: &Mappings, modules: &[Module]) -> Vec<ModuleValues> {
    mappings
        .sets()
        .filter_map(|set| Some((set, set.per_module?)))
        .map(|(set, per_module)| ModuleValues {
            set: set.key,
            changeable: per_module.changeable,
            modules: modules
                .iter()
                .flat_map(|m| {
                    m.records
                        .iter()
                        .flat_map(move |r| r.refs.iter().map(move |f| (m, f)))
                })
                .filter(|(_, f)| set.entries.iter().any(|e| e.key == f.entry))
                .map(|(m, f)| (m.ident.clone(), m.ident_number, f.default))
                .collect(),
        })
        .collect()
}

/// gsdc's name of a record.
fn record_name(kind: MappingKind) -> Text {
    Text::phrase(match kind {
        MappingKind::PzdOut => files::RECORD_PZD_OUT,
        MappingKind::PzdIn => files::RECORD_PZD_IN,
        MappingKind::Dpv1Index => files::RECORD_INDEXES,
        MappingKind::Setting => files::RECORD_SETTINGS,
    })
}

/// One ValueItem per set of choices a module's record refers to, in the
/// order of the records and their sets.
pub fn value_items(mappings: &Mappings, modules: &[Module]) -> Vec<ValueItem> {
    let referred: BTreeSet<String> = modules
        .iter()
        .flat_map(|m| &m.records)
        .flat_map(|r| &r.refs)
        .filter_map(|r| r.value_item.clone())
        .collect();
    mappings
        .sets()
        .filter_map(|set| {
            let tag = value_tag(set);
            let id = format!("IDV_{tag}");
            if !referred.contains(&id) {
                return None;
            }
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
                id,
                help: None,
                assignments,
            })
        })
        .collect()
}
