//! Mappings: PZD words each way and DPV1 indexes, each numbered entry with
//! its default and what it may hold; and the settings, each a set of one.

use super::checks::{self, Checker, Defaults, DefaultsOf, GSD_NAME_LEN};
use super::resolve_address;
use super::telegram::value_set;
use crate::description as raw;
use crate::diag::Diagnostic;
use crate::ir::{
    Allowed, EntryKey, EntryType, Holds, Ident, MappingEntry, MappingGroup, MappingKind,
    MappingSet, Mappings, Numbering, PerModule, SetAt, SetKey, Telegram, Text,
};
use std::collections::BTreeMap;
use std::ops::Range;
use toml::Spanned;

/// The most settings a description may have: each is numbered by a byte.
const MAX_SETTINGS: usize = 255;

/// Where a diagnostic about a set's size points: its `last`, or a
/// setting's name.
pub type SetSpans = BTreeMap<SetKey, Range<usize>>;

/// Every mapping set of the description, grouped, with the place of each.
pub fn lower(
    cx: &mut Checker,
    desc: &raw::Description,
    numbering: Option<&Numbering>,
    telegram: &Telegram,
) -> (Mappings, SetSpans) {
    let m = &desc.mappings;
    let mut sets: Vec<(MappingSet, Range<usize>)> = [
        (MappingKind::PzdOut, &m.pzd_out),
        (MappingKind::PzdIn, &m.pzd_in),
        (MappingKind::Dpv1Index, &m.dpv1_index),
    ]
    .into_iter()
    .filter_map(|(kind, mapping)| {
        let mapping = mapping.as_ref()?;
        let set = lower_set(cx, kind, mapping, numbering, telegram)?;
        Some((set, mapping.last.span()))
    })
    .collect();
    sets.extend(lower_settings(cx, &desc.settings, numbering));
    let spans = sets.iter().map(|(s, span)| (s.key, span.clone())).collect();
    let mut mappings = group(sets.into_iter().map(|(s, _)| s).collect());
    record_lengths(cx, m, &mut mappings);
    (mappings, spans)
}

/// `record_length`: a DPV1 index's record bytes (1..=240, the most a DPV1
/// read or write carries); no other kind of mapping has records of its own.
fn record_lengths(cx: &mut Checker, m: &raw::Mappings, mappings: &mut Mappings) {
    for (kind, mapping) in [
        (MappingKind::PzdOut, &m.pzd_out),
        (MappingKind::PzdIn, &m.pzd_in),
    ] {
        if let Some(length) = mapping.as_ref().and_then(|m| m.record_length.as_ref()) {
            cx.push(
                Diagnostic::error("E139", format!("{} has no records of its own", kind.key()))
                    .at(length.span())
                    .label("only for DPV1 indexes")
                    .help("record_length says how long the record is that each DPV1 index reads and writes; give it under [mappings.dpv1_index]"),
            );
        }
    }
    let Some(length) = m.dpv1_index.as_ref().and_then(|m| m.record_length.as_ref()) else {
        return;
    };
    let length: Option<u8> = cx.spanned_in_range(length, 1, 240, "record_length");
    if let Some(g) = mappings
        .groups
        .iter_mut()
        .find(|g| g.kind == MappingKind::Dpv1Index)
    {
        g.record_length = length;
    }
}

/// The sets grouped by kind in telegram order, each group's sets by their
/// numbers: the same plan whatever order lowering found them in. A kind
/// with several sets (the settings) names each set's items after the number
/// of its first entry.
fn group(mut sets: Vec<MappingSet>) -> Mappings {
    sets.sort_by_key(|s| s.key);
    let mut groups: Vec<MappingGroup> = Vec::new();
    for set in sets {
        match groups.last_mut() {
            Some(g) if g.kind == set.key.kind => g.sets.push(set),
            _ => groups.push(MappingGroup {
                kind: set.key.kind,
                sets: vec![set],
                record_length: None,
            }),
        }
    }
    for g in groups.iter_mut().filter(|g| g.sets.len() > 1) {
        for set in &mut g.sets {
            let first = set.key.first;
            set.allowed_ident = set.allowed_ident.tagged(first);
            if let Allowed::Choices(values) = &mut set.allowed {
                values.ident = values.ident.tagged(first);
            }
        }
    }
    Mappings { groups }
}

fn lower_set(
    cx: &mut Checker,
    kind: MappingKind,
    m: &raw::Mapping,
    numbering: Option<&Numbering>,
    telegram: &Telegram,
) -> Option<MappingSet> {
    let (first, last) = numbers(cx, kind, m, telegram)?;
    let defaults = defaults(cx, m, numbering, usize::from(last - first) + 1)?;
    let parts = Parts {
        name: &m.name,
        range: &m.range,
        choices: &m.choices,
        parameter: &m.parameter,
        holds: Holds::Address,
        entry_type: EntryType::Unsigned16,
    };
    let mut set = build_set(cx, kind, &parts, (first, last), defaults, numbering)?;
    set.set_at = set_at(
        cx,
        &m.set_at,
        &format!("mappings.{}", kind.key()),
        m.name.span(),
    );
    Some(set)
}

/// Where setting `i`, which does not say, is set: by the master, said once
/// for all settings that do not say (W104 at the first, naming how many).
fn unsaid_setting(cx: &mut Checker, settings: &[raw::Setting], i: usize) -> SetAt {
    let unsaid: Vec<usize> = (0..settings.len())
        .filter(|&j| settings[j].set_at.is_none())
        .collect();
    if unsaid.first() == Some(&i) {
        let value = match unsaid.len() - 1 {
            0 => "\"master\"".to_string(),
            1 => "\"master\", as for 1 other setting".to_string(),
            n => format!("\"master\", as for {n} other settings"),
        };
        cx.defaulted(
            &format!("settings[{i}].set_at"),
            value,
            settings[i].name.span(),
        );
    }
    SetAt::Master
}

/// Where the set's drive parameters are set, as the description says; by
/// the master (what gsdc did before descriptions said it), W104, when it
/// does not. `near` is where the description would say it.
fn set_at(
    cx: &mut Checker,
    given: &Option<Spanned<raw::SetAt>>,
    table: &str,
    near: Range<usize>,
) -> SetAt {
    match given {
        Some(said) => said_set_at(said),
        None => {
            cx.defaulted(&format!("{table}.set_at"), "\"master\"", near);
            SetAt::Master
        }
    }
}

fn said_set_at(said: &Spanned<raw::SetAt>) -> SetAt {
    match said.get_ref() {
        raw::SetAt::Drive => SetAt::Drive,
        raw::SetAt::Master => SetAt::Master,
    }
}

/// The values a setting's modules write, each one its setting allows.
fn per_module(
    cx: &mut Checker,
    p: &Spanned<raw::PerModule>,
    allowed: &Allowed,
    numbering: Option<&Numbering>,
) -> Option<PerModule> {
    let mut value = |address: &Spanned<raw::Address>| {
        let value = resolve_address(cx, address, numbering)?;
        if !allowed.contains(i64::from(value)) {
            cx.push(
                Diagnostic::error(
                    "E108",
                    format!("{value} is not among the values the setting allows"),
                )
                .at(address.span())
                .label("not allowed")
                .help("each module's value must be one the setting allows"),
            );
            return None;
        }
        Some(value)
    };
    let per_module = p.get_ref();
    let user_defined = value(&per_module.user_defined)?;
    // A value given that the setting does not allow fails the whole.
    let mut given = |address: &Option<Spanned<raw::Address>>| match address {
        Some(address) => value(address).map(Some),
        None => Some(None),
    };
    Some(PerModule {
        standard_telegram_1: given(&per_module.standard_telegram_1)?,
        standard_telegram_2: given(&per_module.standard_telegram_2)?,
        user_defined,
        changeable: per_module.changeable.as_ref().is_some_and(|c| *c.get_ref()),
        in_user_prm: per_module
            .profibus
            .as_ref()
            .is_none_or(|p| *p.get_ref() == raw::OnProfibus::User),
    })
}

/// Settings: each a set of one entry, numbered from 1 in the order given;
/// with the span of each setting's name.
fn lower_settings(
    cx: &mut Checker,
    settings: &[raw::Setting],
    numbering: Option<&Numbering>,
) -> Vec<(MappingSet, Range<usize>)> {
    if let Some(extra) = settings.get(MAX_SETTINGS) {
        cx.push(
            Diagnostic::error("E134", format!("{} settings; a description holds at most {MAX_SETTINGS}", settings.len()))
                .at(extra.name.span())
                .label("setting 256")
                .help("each setting is numbered by a byte in the parameter telegram and the generated code; drop some"),
        );
    }
    settings
        .iter()
        .take(MAX_SETTINGS)
        .zip(1..=u8::MAX)
        .enumerate()
        .filter_map(|(i, (s, number))| {
            if let (Some(holds), Some(_)) = (&s.holds, &s.choices) {
                cx.push(
                    Diagnostic::error("E002", "`holds` on a setting with `choices`")
                        .at(holds.span())
                        .label("means nothing here")
                        .help("a setting with choices holds one of them: remove `holds`, which says what a range holds"),
                );
            }
            let default = (
                resolve_address(cx, &s.default, numbering)?,
                s.default.span(),
            );
            let parts = Parts {
                name: &s.name,
                range: &s.range,
                choices: &s.choices,
                parameter: &s.parameter,
                holds: s
                    .holds
                    .as_ref()
                    .map_or(Holds::Value, |h| match h.get_ref() {
                        raw::Holds::Value => Holds::Value,
                        raw::Holds::Address => Holds::Address,
                    }),
                entry_type: s
                    .data_type
                    .as_ref()
                    .map_or(EntryType::Unsigned16, |t| match t.get_ref() {
                        raw::SettingType::Unsigned8 => EntryType::Unsigned8,
                        raw::SettingType::Integer8 => EntryType::Integer8,
                        raw::SettingType::Unsigned16 => EntryType::Unsigned16,
                    }),
            };
            let mut set = build_set(
                cx,
                MappingKind::Setting,
                &parts,
                (number, number),
                vec![default],
                numbering,
            )?;
            set.set_at = match &s.set_at {
                Some(said) => said_set_at(said),
                None => unsaid_setting(cx, settings, i),
            };
            set.per_module = match &s.per_module {
                Some(p) => Some(per_module(cx, p, &set.allowed, numbering)?),
                None => None,
            };
            Some((set, s.name.span()))
        })
        .collect()
}

/// What mapping sets and settings have in common.
struct Parts<'a> {
    name: &'a Spanned<raw::Text>,
    range: &'a Option<Spanned<raw::Exactly<Spanned<raw::Address>, 2>>>,
    choices: &'a Option<Spanned<Vec<raw::Choice>>>,
    parameter: &'a Option<Spanned<raw::Address>>,
    /// What a range holds; choices hold choices.
    holds: Holds,
    /// How the entries are carried, which bounds their values.
    entry_type: EntryType,
}

fn build_set(
    cx: &mut Checker,
    kind: MappingKind,
    parts: &Parts,
    (first, last): (u8, u8),
    defaults: Vec<(u16, Range<usize>)>,
    numbering: Option<&Numbering>,
) -> Option<MappingSet> {
    let allowed = allowed(cx, parts, numbering)?;
    let mut checked = defaults.clone();
    checked.dedup(); // one `default` for all entries is reported once
    for (default, span) in checked {
        if !allowed.contains(i64::from(default)) {
            cx.push(
                Diagnostic::error(
                    "E108",
                    format!(
                        "default {default} is not among the values {} allows",
                        kind.key()
                    ),
                )
                .at(span)
                .label("not allowed")
                .help("pick a default within the range or among the choices"),
            );
        }
    }
    let parameter = match parts.parameter {
        Some(p) => Some(parameter_base(cx, p, numbering, last - first)?),
        None => None,
    };
    let what = match kind {
        MappingKind::Setting => "setting name",
        _ => "mapping name",
    };
    let name = cx.text(parts.name, None, what);
    check_rendered_name(cx, parts.name, &name, last, what);
    let entries: Vec<MappingEntry> = (first..=last)
        .zip(defaults)
        .map(|(number, (default, _))| MappingEntry {
            key: EntryKey { kind, number },
            name: render(&name, number),
            default,
            parameter: parameter.map(|base| base + u16::from(number - first)),
        })
        .collect();
    for entry in &entries {
        cx.given(&entry.name);
    }
    let holds = match allowed {
        Allowed::Choices(_) => Holds::Choice,
        Allowed::Range { .. } => parts.holds,
    };
    Some(MappingSet {
        key: SetKey { kind, first },
        allowed,
        holds,
        per_module: None,
        entry_type: parts.entry_type,
        // Said by the caller, which knows where the description says it.
        set_at: SetAt::Master,
        allowed_ident: Ident::of(&["allowed"]),
        entries,
    })
}

/// `first..=last`: PZD words within the telegram (after PZD1 when that is
/// the control or status word), record indexes within 0..=255.
fn numbers(
    cx: &mut Checker,
    kind: MappingKind,
    m: &raw::Mapping,
    telegram: &Telegram,
) -> Option<(u8, u8)> {
    let fixed_word = match kind {
        MappingKind::PzdOut => telegram.control_word.is_some(),
        MappingKind::PzdIn => telegram.status_word.is_some(),
        MappingKind::Dpv1Index | MappingKind::Setting => false,
    };
    let (min, max, what) = match kind {
        MappingKind::Dpv1Index | MappingKind::Setting => (0, 255, "a record index"),
        _ if fixed_word => (
            2,
            i64::from(telegram.pzd_words),
            "a PZD word number after the control or status word",
        ),
        _ => (1, i64::from(telegram.pzd_words), "a PZD word number"),
    };
    let first: u8 = cx.spanned_in_range(&m.first, min, max, what)?;
    let last: u8 = cx.spanned_in_range(&m.last, i64::from(first), max, what)?;
    Some((first, last))
}

/// One default per entry, with its span: `default` for all, or `defaults` one by one.
fn defaults(
    cx: &mut Checker,
    m: &raw::Mapping,
    numbering: Option<&Numbering>,
    count: usize,
) -> Option<Vec<(u16, Range<usize>)>> {
    let of = DefaultsOf {
        noun: "mapping",
        item: "entry",
        items: "entries",
        order: "first to last",
    };
    match cx.defaults(&m.default, &m.defaults, count, &of, m.name.span())? {
        Defaults::Same(default) => {
            let value = resolve_address(cx, default, numbering)?;
            Some(vec![(value, default.span()); count])
        }
        Defaults::Each(list) => list
            .get_ref()
            .iter()
            .map(|d| Some((resolve_address(cx, d, numbering)?, d.span())))
            .collect(),
    }
}

/// What a set's entries may hold, within their type's values.
fn allowed(cx: &mut Checker, m: &Parts, numbering: Option<&Numbering>) -> Option<Allowed> {
    let type_max = m.entry_type.max();
    match (m.range, m.choices) {
        (Some(_), Some(choices)) => {
            cx.push(
                Diagnostic::error("E119", "a mapping has both `range` and `choices`")
                    .at(choices.span())
                    .label("choices given here")
                    .help("a mapping holds either a parameter address within a range, or one of the choices"),
            );
            None
        }
        (Some(range), None) => {
            let raw::Exactly([min, max]) = range.get_ref();
            let (min, max) = (
                resolve_address(cx, min, numbering)?,
                resolve_address(cx, max, numbering)?,
            );
            if min > max {
                cx.reversed(range.span(), min, max);
                return None;
            }
            let what = format!("the value of an {} setting", m.entry_type.gsdml_name());
            let max = cx.in_range(max.into(), 0, type_max.into(), range.span(), &what)?;
            Some(Allowed::Range { min, max })
        }
        (None, Some(choices)) => Some(Allowed::Choices(value_set(
            cx,
            Ident::of(&["choice"]),
            choices.get_ref(),
            (0, type_max.into()),
            Some(GSD_NAME_LEN),
        ))),
        (None, None) => Some(Allowed::Range {
            min: 0,
            max: type_max,
        }),
    }
}

/// The first entry's drive parameter; the others follow it, so the last must fit too.
fn parameter_base(
    cx: &mut Checker,
    p: &Spanned<raw::Address>,
    numbering: Option<&Numbering>,
    extra: u8,
) -> Option<u16> {
    let base = resolve_address(cx, p, numbering)?;
    cx.in_range(
        i64::from(base),
        0,
        0xFFFF - i64::from(extra),
        p.span(),
        "the first mapping parameter",
    )
}

/// The longest name is the last entry's or node's: check that one for the
/// GSD, in the form the GSD shows.
pub(super) fn check_rendered_name(
    cx: &mut Checker,
    raw_name: &Spanned<raw::Text>,
    name: &Text,
    last: u8,
    what: &str,
) {
    if !checks::is_clean(name.for_gsd()) {
        return; // already reported by `Checker::text`
    }
    let raw = raw_name.get_ref();
    let span = raw
        .gsd
        .as_ref()
        .map_or_else(|| raw.en_span(&raw_name.span()), Spanned::span);
    let rendered = render(name, last);
    cx.check_gsd_text(rendered.for_gsd(), span, GSD_NAME_LEN, what);
}

/// A name with `{n}` as the entry's or node's number.
pub(super) fn render(name: &Text, number: u8) -> Text {
    let n = number.to_string();
    name.map(|text| text.replace("{n}", &n))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn loaded(name: &str) -> Mappings {
        let text = std::fs::read_to_string(format!(
            "{}/descriptions/{name}",
            env!("CARGO_MANIFEST_DIR")
        ))
        .unwrap();
        crate::testing::load(name, &text).0.unwrap().mappings
    }

    /// Lowering may find the sets in any order: the plan is the same.
    #[test]
    fn the_plan_does_not_depend_on_the_order_sets_are_found_in() {
        for name in ["md810dp.toml", "mv810-pnet02.toml", "9kdp1.toml"] {
            let mappings = loaded(name);
            let sets: Vec<MappingSet> = mappings.sets().cloned().collect();
            let mut reversed = sets.clone();
            reversed.reverse();
            // The settings' names depend on the group: regrouping gives them again.
            let plain = |mut s: MappingSet| {
                s.allowed_ident = Ident::of(&["allowed"]);
                if let Allowed::Choices(v) = &mut s.allowed {
                    v.ident = Ident::of(&["choice"]);
                }
                s
            };
            let mut regrouped = group(reversed.into_iter().map(plain).collect());
            // A group's record length is the description's, set after grouping.
            for (g, found) in regrouped.groups.iter_mut().zip(&mappings.groups) {
                g.record_length = found.record_length;
            }
            assert_eq!(regrouped, mappings, "{name}");
        }
    }
}
