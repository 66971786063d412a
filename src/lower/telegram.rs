//! The telegram: PKW kind, PZD words, control and status words.

use super::checks::Checker;
use crate::description::{self as raw, PkwKind};
use crate::diag::Diagnostic;
use crate::ir::{self, Ident, Scope, Telegram, ValueSet};
use std::collections::BTreeSet;

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
    let bits = w
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
    ir::Word {
        name: cx.text(&w.name, None, what),
        bits,
    }
}

fn mask(first: u8, last: u8) -> u32 {
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
