//! `[[profibus.parameters]]` and `[profibus.user_prm]`: the card's own
//! User_Prm_Data parameters at the bytes and bits the description puts
//! them, and the fixed bytes under them.

use super::checks::{Checker, GSD_NAME_LEN};
use super::telegram::value_set;
use crate::description::dp as raw;
use crate::diag::Diagnostic;
use crate::ir::profibus::{CardParam, PrmParam, PrmType, PrmValue};
use crate::ir::{Allowed, Ident};
use std::ops::Range;
use toml::Spanned;

/// The card's parameters, placed, each with where it is written; numbered
/// from `ids`, and `text_ids` for those with choices.
pub(super) struct Placed {
    pub params: Vec<PrmParam>,
    pub facts: Vec<CardParam>,
    /// The byte after the last one a parameter takes.
    pub end: usize,
}

pub(super) fn lower(
    cx: &mut Checker,
    params: &[raw::Parameter],
    ids: &mut impl Iterator<Item = u16>,
    text_ids: &mut impl Iterator<Item = u16>,
) -> Placed {
    let mut placed = Placed {
        params: Vec::new(),
        facts: Vec::new(),
        end: 0,
    };
    let mut taken: Vec<(usize, u16, String)> = Vec::new();
    for p in params {
        let Some((data_type, fact)) = parameter(cx, p) else {
            continue;
        };
        let offset = usize::from(*p.offset.get_ref());
        let bits = bit_mask(data_type);
        for (byte, mask) in bits.iter().enumerate() {
            let at = offset + byte;
            if let Some((_, _, other)) = taken.iter().find(|(o, m, _)| *o == at && m & mask != 0) {
                cx.push(
                    Diagnostic::error(
                        "E114",
                        format!(
                            "parameter \"{}\" overlaps another at byte {at}",
                            p.name.get_ref()
                        ),
                    )
                    .at(p.offset.span())
                    .label("bits taken already")
                    .help(format!(
                        "\"{other}\" takes some of its bits: two parameters cannot share a bit"
                    )),
                );
            }
            taken.push((at, *mask, p.name.get_ref().clone()));
        }
        placed.end = placed.end.max(offset + bits.len());
        let text = fact.allowed.choices().and_then(|_| text_ids.next());
        placed.params.push(PrmParam {
            id: ids.next().unwrap_or(u16::MAX),
            offset: u16::from(*p.offset.get_ref()),
            value: PrmValue::Card(placed.facts.len()),
            data_type,
            text,
        });
        placed.facts.push(fact);
    }
    placed
}

/// The bits a parameter takes of each of its bytes, from its offset.
fn bit_mask(data_type: PrmType) -> Vec<u16> {
    match data_type {
        PrmType::Unsigned8 | PrmType::Signed8 => vec![0xFF],
        PrmType::Unsigned16 => vec![0xFF, 0xFF],
        PrmType::Bits { first, last } => vec![((1u16 << (last + 1)) - 1) & !((1u16 << first) - 1)],
    }
}

fn parameter(cx: &mut Checker, p: &raw::Parameter) -> Option<(PrmType, CardParam)> {
    let name = cx.gsd_name(&p.name, GSD_NAME_LEN, "parameter name");
    let data_type = match (&p.data_type, &p.bits) {
        (Some(t), Some(_)) => {
            cx.push(
                Diagnostic::error("E175", format!("parameter \"{name}\" has both `type` and `bits`"))
                    .at(t.span())
                    .label("remove this or `bits`")
                    .help("`bits` stores the parameter in some bits of one byte (a GSD Bit or BitArea); `type` in whole bytes"),
            );
            return None;
        }
        (_, Some(bits)) => {
            let range = bits.get_ref();
            if !(0..=7).contains(&range.first) || !(range.first..=7).contains(&range.last) {
                cx.push(
                    Diagnostic::error("E101", format!("bits {}..={} are not bits of one byte", range.first, range.last))
                        .at(bits.span())
                        .label("not within 0..=7")
                        .help("a parameter's bits are bits of the byte at its offset: [first, last] within 0..=7"),
                );
                return None;
            }
            // Checked above: 0 <= first <= last <= 7.
            PrmType::Bits {
                first: range.first as u8,
                last: range.last as u8,
            }
        }
        (Some(t), None) => match t.get_ref() {
            raw::PrmType::Unsigned8 => PrmType::Unsigned8,
            raw::PrmType::Unsigned16 => PrmType::Unsigned16,
            raw::PrmType::Signed8 => PrmType::Signed8,
        },
        (None, None) => PrmType::Unsigned16,
    };
    let most = i64::from(data_type.max());
    let ident = Ident::of(&["choice"]);
    let allowed = match (&p.range, &p.choices) {
        (Some(_), Some(choices)) => {
            cx.push(
                Diagnostic::error(
                    "E119",
                    format!("parameter \"{name}\" has both `range` and `choices`"),
                )
                .at(choices.span())
                .label("choices given here")
                .help("a parameter takes a value within a range, or one of its choices"),
            );
            return None;
        }
        (Some(range), None) => {
            let crate::description::Exactly([min, max]) = range.get_ref();
            let min: u16 = cx.spanned_in_range(min, 0, most, "the parameter's least value")?;
            let max: u16 = cx.spanned_in_range(max, 0, most, "the parameter's most value")?;
            if min > max {
                cx.reversed(range.span(), min, max);
                return None;
            }
            Allowed::Range { min, max }
        }
        (None, Some(choices)) => Allowed::Choices(value_set(
            cx,
            ident,
            choices.get_ref(),
            (0, most),
            Some(GSD_NAME_LEN),
        )),
        (None, None) => Allowed::Range {
            min: 0,
            max: data_type.max(),
        },
    };
    let default: u16 = cx.spanned_in_range(&p.default, 0, most, "the parameter's default")?;
    if !allowed.contains(i64::from(default)) {
        cx.push(
            Diagnostic::error(
                "E108",
                format!("default {default} is not among the values parameter \"{name}\" allows"),
            )
            .at(p.default.span())
            .label("not allowed")
            .help("pick a default within the range or among the choices"),
        );
    }
    Some((
        data_type,
        CardParam {
            name: crate::ir::Text::english(name),
            default,
            allowed,
            changeable: p.changeable.as_ref().is_none_or(|c| *c.get_ref()),
            visible: p.visible.as_ref().is_none_or(|v| *v.get_ref()),
        },
    ))
}

/// The stated constant bytes of User_Prm_Data and their span.
pub(super) type Constant = (Vec<u8>, Range<usize>);

/// `[profibus.user_prm] constant`, its span when given.
pub(super) fn constant(user_prm: Option<&Spanned<raw::UserPrm>>) -> Option<Constant> {
    let u = user_prm?;
    let bytes = &u.get_ref().constant;
    let span = bytes.first()?.span().start..bytes.last()?.span().end;
    Some((bytes.iter().map(|b| *b.get_ref()).collect(), span))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_type_takes_its_bits() {
        assert_eq!(bit_mask(PrmType::Bits { first: 2, last: 3 }), [0b1100]);
        assert_eq!(bit_mask(PrmType::Bits { first: 7, last: 7 }), [0x80]);
        assert_eq!(bit_mask(PrmType::Unsigned16), [0xFF, 0xFF]);
    }
}
