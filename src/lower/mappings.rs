//! Mappings: PZD words each way and DPV1 indexes, each numbered entry with
//! its default and what it may hold.

use super::checks::{Checker, GSD_NAME_LEN};
use super::resolve_address;
use super::telegram::lower_choices;
use crate::description as raw;
use crate::diag::Diagnostic;
use crate::ir::{Allowed, MappingEntry, MappingKind, MappingSet, Numbering, Telegram, Text};
use std::ops::Range;
use toml::Spanned;

/// The mapping sets in telegram order, each with the span of its `last`
/// (where a diagnostic about the set's size points).
pub fn lower(
    cx: &mut Checker,
    m: &raw::Mappings,
    numbering: Option<&Numbering>,
    telegram: &Telegram,
) -> (Vec<MappingSet>, Vec<Range<usize>>) {
    [
        (MappingKind::PzdOut, &m.pzd_out),
        (MappingKind::PzdIn, &m.pzd_in),
        (MappingKind::Dpv1Index, &m.dpv1_index),
    ]
    .into_iter()
    .filter_map(|(kind, mapping)| {
        let mapping = mapping.as_ref()?;
        Some((
            lower_set(cx, kind, mapping, numbering, telegram)?,
            mapping.last.span(),
        ))
    })
    .unzip()
}

fn lower_set(
    cx: &mut Checker,
    kind: MappingKind,
    m: &raw::Mapping,
    numbering: Option<&Numbering>,
    telegram: &Telegram,
) -> Option<MappingSet> {
    let (first, last) = numbers(cx, kind, m, telegram)?;
    let defaults = defaults(cx, m, numbering, last - first + 1)?;
    let parts = Parts {
        name: &m.name,
        range: &m.range,
        choices: &m.choices,
        parameter: &m.parameter,
    };
    build_set(cx, kind, &parts, (first, last), defaults, numbering)
}

/// Settings: each a set of one entry, numbered from 1 in the order given;
/// with the span of each setting's name.
pub fn lower_settings(
    cx: &mut Checker,
    settings: &[raw::Setting],
    numbering: Option<&Numbering>,
) -> (Vec<MappingSet>, Vec<Range<usize>>) {
    settings
        .iter()
        .zip(1u8..)
        .filter_map(|(s, number)| {
            let default = (
                resolve_address(cx, &s.default, numbering)?,
                s.default.span(),
            );
            let parts = Parts {
                name: &s.name,
                range: &s.range,
                choices: &s.choices,
                parameter: &s.parameter,
            };
            let set = build_set(
                cx,
                MappingKind::Setting,
                &parts,
                (number, number),
                vec![default],
                numbering,
            )?;
            Some((set, s.name.span()))
        })
        .unzip()
}

/// What mapping sets and settings have in common.
struct Parts<'a> {
    name: &'a Spanned<raw::Text>,
    range: &'a Option<Spanned<[Spanned<raw::Address>; 2]>>,
    choices: &'a Option<Spanned<Vec<raw::Choice>>>,
    parameter: &'a Option<Spanned<raw::Address>>,
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
    let name = cx.text(parts.name, None, "mapping name");
    check_rendered_name(cx, parts.name, &name, last);
    let entries = (first..=last)
        .zip(defaults)
        .map(|(number, (default, _))| MappingEntry {
            number,
            name: render(&name, number),
            default,
            parameter: parameter.map(|base| base + u16::from(number - first)),
        })
        .collect();
    Some(MappingSet {
        kind,
        allowed,
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
    count: u8,
) -> Option<Vec<(u16, Range<usize>)>> {
    match (&m.default, &m.defaults) {
        (Some(default), None) => {
            let value = resolve_address(cx, default, numbering)?;
            Some(vec![(value, default.span()); usize::from(count)])
        }
        (None, Some(list)) if list.get_ref().len() == usize::from(count) => list
            .get_ref()
            .iter()
            .map(|d| Some((resolve_address(cx, d, numbering)?, d.span())))
            .collect(),
        (None, Some(list)) => {
            cx.push(
                Diagnostic::error(
                    "E122",
                    format!("{} defaults for {count} entries", list.get_ref().len()),
                )
                .at(list.span())
                .label(format!("expected {count} values"))
                .help("give one default per entry, first to last"),
            );
            None
        }
        (Some(default), Some(_)) => {
            cx.push(
                Diagnostic::error("E123", "a mapping has both `default` and `defaults`")
                    .at(default.span())
                    .label("remove this or `defaults`")
                    .help("`default` sets every entry, `defaults` each one"),
            );
            None
        }
        (None, None) => {
            cx.push(
                Diagnostic::error("E123", "a mapping has neither `default` nor `defaults`")
                    .at(m.name.span())
                    .label("in this mapping")
                    .help(
                        "add `default = ...` for every entry, or `defaults = [...]` one per entry",
                    ),
            );
            None
        }
    }
}

fn allowed(cx: &mut Checker, m: &Parts, numbering: Option<&Numbering>) -> Option<Allowed> {
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
            let [min, max] = range.get_ref();
            let (min, max) = (
                resolve_address(cx, min, numbering)?,
                resolve_address(cx, max, numbering)?,
            );
            if min > max {
                cx.push(
                    Diagnostic::error("E109", format!("range [{min}, {max}] is reversed"))
                        .at(range.span())
                        .label("minimum above maximum")
                        .help("write the range as [minimum, maximum]"),
                );
                return None;
            }
            Some(Allowed::Range { min, max })
        }
        (None, Some(choices)) => Some(Allowed::Choices(lower_choices(
            cx,
            choices.get_ref(),
            0,
            0xFFFF,
            Some(GSD_NAME_LEN),
        ))),
        (None, None) => Some(Allowed::Range {
            min: 0,
            max: 0xFFFF,
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

/// The longest name is the last entry's: check that one for the GSD.
fn check_rendered_name(cx: &mut Checker, raw_name: &Spanned<raw::Text>, name: &Text, last: u8) {
    if name.en.trim().is_empty() {
        return; // already reported as empty
    }
    let span = raw_name.get_ref().en_span(&raw_name.span());
    cx.check_gsd_text(&render(name, last).en, span, GSD_NAME_LEN, "mapping name");
}

fn render(name: &Text, number: u8) -> Text {
    let n = number.to_string();
    Text {
        en: name.en.replace("{n}", &n),
        zh: name.zh.as_ref().map(|z| z.replace("{n}", &n)),
    }
}
