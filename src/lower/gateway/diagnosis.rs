//! The gateway's diagnosis block: a header byte (the block's length), then
//! the type, the node and the code, whose meaning depends on the type: one
//! byte with listed values, or a 16-bit number. A GSD `Unit_Diag_Area` can
//! show the types and the listed codes; which type a code belongs to, it
//! cannot say (the area's note in the GSD says it).

use super::super::checks::{Checker, GSD_NAME_LEN};
use super::super::telegram::{apart_in_c, value_set};
use crate::description::gateway as raw;
use crate::diag::Diagnostic;
use crate::ir::gateway::{DiagCode, DiagType, Diagnosis, GsdArea};
use crate::ir::{Choice, Ident, Scope};
use std::collections::{BTreeMap, BTreeSet};
use toml::Spanned;

/// Where the type, the node and the code are in the block, the header
/// being byte 0: one byte each, in this order.
const TYPE_AT: u8 = 1;
const NODE_AT: u8 = 2;
const CODE_AT: u8 = 3;

pub fn lower(cx: &mut Checker, d: &Spanned<raw::Diagnosis>) -> Diagnosis {
    let raw_types = &d.get_ref().types;
    if raw_types.get_ref().is_empty() {
        cx.push(
            Diagnostic::error("E101", "no diagnosis type")
                .at(raw_types.span())
                .label("empty")
                .help("give each type the gateway reports: [[gateway.diagnosis.types]] with value, text and codes"),
        );
    }
    let mut seen = Seen::default();
    // The layouts' own names beside the types': a type is not `TYPE_AT`.
    for own in [
        &["type", "at"][..],
        &["node", "at"],
        &["code", "at"],
        &["max", "len"],
        &["types"],
    ] {
        seen.names.reserve(&Ident::of(own));
    }
    let mut types: Vec<DiagType> = raw_types
        .get_ref()
        .iter()
        .filter_map(|t| diag_type(cx, t, &mut seen))
        .collect();
    let taken: Vec<String> = types
        .iter()
        .flat_map(|t| [t.ident.snake(), format!("{}_len", t.ident.snake())])
        .collect();
    let codes = types.iter_mut().filter_map(|t| match &mut t.code {
        DiagCode::Listed(set) => Some(set),
        DiagCode::Word(_) => None,
    });
    apart_in_c(taken, codes);
    Diagnosis {
        type_at: TYPE_AT,
        node_at: NODE_AT,
        code_at: CODE_AT,
        max_len: types.iter().map(|t| t.len).max().unwrap_or(CODE_AT + 1),
        gsd_areas: gsd_areas(&types),
        types,
    }
}

/// What the types so far have taken: their values, their names, and their
/// listed codes with the type of each.
#[derive(Default)]
struct Seen {
    types: BTreeSet<u8>,
    names: Scope,
    codes: BTreeMap<i64, u8>,
}

fn diag_type(cx: &mut Checker, t: &raw::DiagnosisType, seen: &mut Seen) -> Option<DiagType> {
    let value: u8 = cx.spanned_in_range(&t.value, 0, 0xFF, "a diagnosis type")?;
    if !seen.types.insert(value) {
        cx.duplicate(format!("diagnosis type {value}"), t.value.span());
    }
    let text = cx.text(&t.text, Some(GSD_NAME_LEN), "diagnosis text");
    let ident = seen.names.unique(Ident::from_text(&text.en, "type"), value);
    let code = match (&t.codes, &t.code_word) {
        (Some(codes), None) => {
            listed_once(cx, codes.get_ref(), value, &mut seen.codes);
            let set = value_set(
                cx,
                ident.tagged("code"),
                codes.get_ref(),
                (0, 0xFF),
                Some(GSD_NAME_LEN),
            );
            DiagCode::Listed(set)
        }
        (None, Some(word)) => DiagCode::Word(cx.text(word, Some(GSD_NAME_LEN), "diagnosis text")),
        (Some(codes), Some(_)) => {
            cx.push(
                Diagnostic::error("E149", "a diagnosis type with both `codes` and `code_word`")
                    .at(codes.span())
                    .label("remove this or `code_word`")
                    .help("a type's code is one byte with listed values (`codes`) or a 16-bit number (`code_word`)"),
            );
            return None;
        }
        (None, None) => {
            cx.push(
                Diagnostic::error("E149", "a diagnosis type with neither `codes` nor `code_word`")
                    .at(t.value.span())
                    .label("in this type")
                    .help("list the type's codes, `codes = [{ value = 35, text = \"...\" }]`, or say what its 16-bit code is, `code_word = \"...\"`"),
            );
            return None;
        }
    };
    Some(DiagType {
        value,
        len: CODE_AT + code.bytes(),
        text,
        ident,
        code,
    })
}

/// E105 for a code another type lists too: the GSD shows one text per code.
/// Codes given twice within a type are the value set's to report.
fn listed_once(
    cx: &mut Checker,
    codes: &[crate::description::Choice],
    kind: u8,
    seen: &mut BTreeMap<i64, u8>,
) {
    for code in codes {
        let value = *code.value.get_ref();
        match seen.insert(value, kind) {
            Some(other) if other != kind => cx.push(
                Diagnostic::error(
                    "E105",
                    format!("code {value} is given twice, by types {other} and {kind}"),
                )
                .at(code.value.span())
                .label("given again here")
                .help("a GSD shows one text per code: give each code to one type"),
            ),
            _ => {}
        }
    }
}

/// The type's texts; and the listed codes' with a note of the types they
/// belong to and of what the other types carry in the same byte.
fn gsd_areas(types: &[DiagType]) -> Vec<GsdArea> {
    let byte_area = |at: u8| {
        let first = u16::from(at - 1) * 8;
        (first, first + 7)
    };
    let (first_bit, last_bit) = byte_area(TYPE_AT);
    let mut areas = vec![GsdArea {
        first_bit,
        last_bit,
        note: "The type of the diagnosis".to_string(),
        values: types
            .iter()
            .map(|t| Choice {
                value: i64::from(t.value),
                text: t.text.clone(),
                ident: t.ident.clone(),
            })
            .collect(),
    }];
    let listed: Vec<(u8, &[Choice])> = types
        .iter()
        .filter_map(|t| match &t.code {
            DiagCode::Listed(set) => Some((t.value, set.choices.as_slice())),
            DiagCode::Word(_) => None,
        })
        .collect();
    let words = types.iter().filter_map(|t| match &t.code {
        DiagCode::Word(name) => Some((t.value, name.for_gsd())),
        DiagCode::Listed(_) => None,
    });
    let (first_bit, last_bit) = byte_area(CODE_AT);
    if listed.is_empty() {
        // No codes' area: the types' says what the types of a 16-bit code
        // carry, so that the GSD says it somewhere (`gsdc import` reads it).
        for (value, name) in words {
            areas[0].note.push_str(&format!(
                "; type {value} carries a 16-bit code ({name}) in bits {first_bit}-{}",
                last_bit + 8
            ));
        }
        return areas;
    }
    let mut note = format!("The code of {}", codes_by_type(&listed));
    for (value, name) in words {
        note.push_str(&format!(
            "; type {value} carries the high byte of its 16-bit code ({name}) here"
        ));
    }
    areas.push(GsdArea {
        first_bit,
        last_bit,
        note,
        values: listed.iter().flat_map(|(_, c)| c.iter().cloned()).collect(),
    });
    areas
}

/// Which type each listed code belongs to, which a GSD cannot say but its
/// reader (and `gsdc import`) needs: `type 1 (35, 34)`, `type 1 (35) and
/// type 3 (32)`, `type 1 (35), type 3 (32) and type 5 (7)`.
fn codes_by_type(listed: &[(u8, &[Choice])]) -> String {
    let each: Vec<String> = listed
        .iter()
        .map(|(value, codes)| {
            let codes: Vec<String> = codes.iter().map(|c| c.value.to_string()).collect();
            format!("type {value} ({})", codes.join(", "))
        })
        .collect();
    match each.as_slice() {
        [rest @ .., last] if !rest.is_empty() => format!("{} and {last}", rest.join(", ")),
        _ => each.concat(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn codes(values: &[i64]) -> Vec<Choice> {
        values
            .iter()
            .map(|&value| Choice {
                value,
                text: crate::ir::Text::english(""),
                ident: Ident::of(&["code"]),
            })
            .collect()
    }

    #[test]
    fn the_codes_are_named_by_type_as_a_sentence_names_them() {
        let (a, b, c) = (codes(&[35, 34]), codes(&[32]), codes(&[7]));
        assert_eq!(codes_by_type(&[(1, &a)]), "type 1 (35, 34)");
        assert_eq!(
            codes_by_type(&[(1, &a), (3, &b)]),
            "type 1 (35, 34) and type 3 (32)"
        );
        assert_eq!(
            codes_by_type(&[(1, &a), (3, &b), (5, &c)]),
            "type 1 (35, 34), type 3 (32) and type 5 (7)"
        );
    }
}
