//! The telegram: PKW kind, PZD words, control and status words.

use super::checks::Checker;
use crate::description::{self as raw, Address, PkwKind};
use crate::diag::Diagnostic;
use crate::ir::{self, Ident, Numbering, Scope, Telegram, ValueSet};
use std::collections::BTreeSet;
use toml::Spanned;

/// A general config identifier byte carries at most 16 words.
const MAX_PZD_WORDS: i64 = 16;
const WORD_BITS: i64 = 16;

pub fn lower(cx: &mut Checker, t: &raw::Telegram) -> Telegram {
    // An out-of-range count is reported once; the nearest valid one keeps
    // the checks that depend on it from piling up more errors.
    let pzd_words = cx
        .spanned_in_range(&t.pzd_words, 1, MAX_PZD_WORDS, "pzd_words")
        .unwrap_or_else(|| (*t.pzd_words.get_ref()).clamp(1, MAX_PZD_WORDS as u8));
    Telegram {
        pkw: match t.pkw.get_ref() {
            PkwKind::None => ir::PkwKind::None,
            PkwKind::PkeIndPwe => ir::PkwKind::PkeIndPwe,
            PkwKind::StationCommandAddressValue => ir::PkwKind::StationCommandAddressValue,
            PkwKind::Profidrive => ir::PkwKind::Profidrive,
        },
        pzd_words,
        control_word: t
            .control_word
            .as_ref()
            .map(|w| lower_word(cx, w, "control word")),
        status_word: t
            .status_word
            .as_ref()
            .map(|w| lower_word(cx, w, "status word")),
        profidrive: t.profidrive.as_ref().is_some_and(|p| *p.get_ref()),
    }
}

/// The fields of a word; their constants and their value types are named
/// after them, each unique within the word.
fn lower_word(cx: &mut Checker, w: &raw::Word, what: &str) -> ir::Word {
    let mut used = 0u32;
    let mut constants = Scope::default();
    let mut types = Scope::default();
    let mut bits: Vec<ir::BitField> = w
        .bits
        .iter()
        .filter_map(|b| {
            let field = lower_bit_field(cx, b, &mut constants, &mut types)?;
            let mask = mask(field.first, field.last);
            if used & mask != 0 {
                cx.push(
                    Diagnostic::error("E114", format!("bits of the {what} overlap"))
                        .at(b.bit.span())
                        .label("already named by an earlier entry")
                        .help("each bit belongs to one entry"),
                );
            }
            used |= mask;
            Some(field)
        })
        .collect();
    let taken: Vec<String> = bits
        .iter()
        .flat_map(|b| ["mask", "shift"].map(|s| format!("{}_{s}", b.ident.snake())))
        .collect();
    apart_in_c(taken, bits.iter_mut().filter_map(|b| b.values.as_mut()));
    ir::Word {
        name: cx.text(&w.name, None, what),
        bits,
    }
}

/// The bits `first..=last` of a word or a byte.
pub(super) fn mask(first: u8, last: u8) -> u32 {
    (first..=last).fold(0, |m, b| m | 1 << b)
}

fn lower_bit_field(
    cx: &mut Checker,
    b: &raw::BitField,
    constants: &mut Scope,
    types: &mut Scope,
) -> Option<ir::BitField> {
    let range = b.bit.get_ref();
    let span = b.bit.span();
    let first: u8 = cx.in_range(range.first, 0, WORD_BITS - 1, span.clone(), "a bit number")?;
    let last: u8 = cx.in_range(
        range.last,
        i64::from(first),
        WORD_BITS - 1,
        span.clone(),
        "the last bit",
    )?;
    let name = cx.text(&b.name, None, "bit name");
    let max_value = (1i64 << (last - first + 1)) - 1;
    let values = (!b.values.is_empty()).then(|| {
        let ident = types.unique(Ident::from_text(&name.en, "field"), first);
        value_set(cx, ident, &b.values, (0, max_value), None)
    });
    Some(ir::BitField {
        first,
        last,
        ident: constants.unique(Ident::from_text(&name.en, "bit"), first),
        name,
        values,
    })
}

/// The largest parameter number of the PROFIdrive channel: PKE bits 10-0
/// (MM440 OI p.157, MASTERDRIVES Compendium 8.2-19).
const PNU_MAX: u16 = 0x07FF;

/// E154: with `pkw = "profidrive"` every parameter the description names
/// must be a PNU the channel can carry. A parameter is a mapping's value (a
/// parameter address, unless the mapping has choices), a setting's that
/// holds addresses, the drive parameter that holds a mapping or a setting
/// (the last entry's too), and whatever is written as a function-code name.
/// Values that do not resolve were reported where they were lowered.
pub fn check_pnus(cx: &mut Checker, desc: &raw::Description, numbering: Option<&Numbering>) {
    if !desc
        .telegram
        .as_ref()
        .is_some_and(|t| *t.pkw.get_ref() == PkwKind::Profidrive)
    {
        return;
    }
    let m = &desc.mappings;
    for mapping in [&m.pzd_out, &m.pzd_in, &m.dpv1_index].into_iter().flatten() {
        let holds_addresses = mapping.choices.is_none();
        let values = mapping
            .default
            .iter()
            .chain(mapping.defaults.iter().flat_map(|d| d.get_ref()))
            .chain(mapping.range.iter().flat_map(|r| &r.get_ref().0));
        for value in values {
            check_pnu(cx, value, numbering, holds_addresses, 0);
        }
        if let Some(parameter) = &mapping.parameter {
            let first = *mapping.first.get_ref();
            let after = mapping.last.get_ref().saturating_sub(first);
            check_pnu(cx, parameter, numbering, true, after);
        }
    }
    for setting in &desc.settings {
        let holds_addresses = setting.choices.is_none()
            && setting
                .holds
                .as_ref()
                .is_some_and(|h| *h.get_ref() == raw::Holds::Address);
        let values = std::iter::once(&setting.default)
            .chain(setting.range.iter().flat_map(|r| &r.get_ref().0))
            .chain(setting.per_module.iter().flat_map(|p| p.get_ref().values()));
        for value in values {
            check_pnu(cx, value, numbering, holds_addresses, 0);
        }
        if let Some(parameter) = &setting.parameter {
            check_pnu(cx, parameter, numbering, true, 0);
        }
    }
}

/// E154 for `value` (and the `after` parameters that follow it) when it is
/// a parameter beyond the PNU range: a name always, a number when
/// `is_parameter`.
fn check_pnu(
    cx: &mut Checker,
    value: &Spanned<Address>,
    numbering: Option<&Numbering>,
    is_parameter: bool,
    after: u8,
) {
    let (number, name) = match value.get_ref() {
        Address::Number(n) if is_parameter => (*n, None),
        Address::Number(_) => return,
        Address::Name(name) => match numbering.and_then(|n| n.parse(name).ok()) {
            Some(address) => (i64::from(address), Some(name)),
            None => return,
        },
    };
    let last = number + i64::from(after);
    if !(0..=0xFFFF).contains(&number) || last <= i64::from(PNU_MAX) {
        return;
    }
    let parameter = match name {
        Some(name) => format!("`{name}` is parameter {number}"),
        None => format!("parameter {number}"),
    };
    let (what, label) = match (after, name) {
        (0, Some(_)) => (format!("{parameter},"), "not a PNU"),
        (0, None) => (format!("{parameter} is"), "not a PNU"),
        _ => (
            format!("the last entry's parameter is {last} ({parameter} for the first),"),
            "the last entry's is not a PNU",
        ),
    };
    cx.push(
        Diagnostic::error(
            "E154",
            format!("{what} beyond the PROFIdrive channel's parameter numbers (0 to {PNU_MAX})"),
        )
        .at(value.span())
        .label(label)
        .help("the PKE holds an 11-bit PNU; the profile leaves IND's low byte, where Siemens drives select a page for higher numbers, undefined: number the parameter within 0 to 2047, or describe the drive's own channel"),
    );
}

/// A gateway's: no PKW channel, no PZD words. Its data are the nodes' words.
pub fn absent() -> Telegram {
    Telegram {
        pkw: ir::PkwKind::None,
        pzd_words: 0,
        control_word: None,
        status_word: None,
        profidrive: false,
    }
}

/// Choices with values within `min..=max`, each value once, each named
/// after its text; the set is named `ident`.
pub fn value_set(
    cx: &mut Checker,
    ident: Ident,
    choices: &[raw::Choice],
    (min, max): (i64, i64),
    gsd_limit: Option<usize>,
) -> ValueSet {
    let mut seen = BTreeSet::new();
    let mut names = Scope::default();
    let choices = choices
        .iter()
        .filter_map(|c| {
            let value: i64 = cx.spanned_in_range(&c.value, min, max, "a choice value")?;
            if !seen.insert(value) {
                cx.duplicate(format!("value {value}"), c.value.span());
            }
            let text = cx.text(&c.text, gsd_limit, "choice text");
            Some(ir::Choice {
                value,
                ident: names.unique(Ident::from_text(&text.en, "value"), value),
                text,
            })
        })
        .collect();
    ValueSet { ident, choices }
}

/// C declares the constants of a word or a block and the values of their
/// sets in one namespace, `<CONSTANT>_MASK` beside `<SET>_<VALUE>`, where
/// Rust keeps them apart (a constant, and a variant of an enum). A value
/// whose C name is `taken`, or another value's, gets its number as a tag
/// (`MASK_3`), as names that meet in Rust do: no description the loader
/// accepts gives a C layout that declares a name twice.
pub(in crate::lower) fn apart_in_c<'a>(
    taken: impl IntoIterator<Item = String>,
    sets: impl IntoIterator<Item = &'a mut ValueSet>,
) {
    let mut taken: BTreeSet<String> = taken.into_iter().collect();
    for set in sets {
        let base = set.ident.snake();
        let c_name = |ident: &Ident| format!("{base}_{}", ident.snake());
        let mut variants: BTreeSet<String> = set.choices.iter().map(|c| c.ident.camel()).collect();
        for choice in &mut set.choices {
            // Free: no C name taken, and no other variant of the enum.
            let free = |ident: &Ident| {
                !taken.contains(&c_name(ident))
                    && (*ident == choice.ident || !variants.contains(&ident.camel()))
            };
            let mut ident = choice.ident.clone();
            let mut n = 1;
            while !free(&ident) {
                ident = match n {
                    1 => choice.ident.tagged(choice.value),
                    _ => choice.ident.tagged(choice.value).tagged(n),
                };
                n += 1;
            }
            taken.insert(c_name(&ident));
            variants.insert(ident.camel());
            choice.ident = ident;
        }
    }
}
