//! `[[profibus.parameters]]` and `[profibus.user_prm]`: the card's own
//! User_Prm_Data parameters at the bytes and bits the description puts
//! them, and the fixed bytes under them.

use super::checks::{Checker, GSD_NAME_LEN};
use super::param_values::{self, Holds, Stored, Taken};
use crate::description::dp as raw;
use crate::ir::profibus::{CardParam, PrmParam, PrmText, PrmTextOf, PrmType, PrmValue};
use crate::ir::Allowed;
use std::ops::Range;
use toml::Spanned;

/// The card's parameters (or a PROFIsafe module's), placed, each with
/// where it is written; numbered from `ids`, and `text_ids` for those with
/// choices; what each holds is `facts`, which `UserPrm::card_params` keeps
/// after the `facts_before` there already.
pub(super) struct Placed {
    pub params: Vec<PrmParam>,
    pub facts: Vec<CardParam>,
    /// The byte after the last one a parameter takes.
    pub end: usize,
}

pub(super) fn lower(
    cx: &mut Checker,
    params: &[raw::Parameter],
    (ids, text_ids): (
        &mut impl Iterator<Item = u16>,
        &mut impl Iterator<Item = u16>,
    ),
    facts_before: usize,
) -> Placed {
    let mut placed = Placed {
        params: Vec::new(),
        facts: Vec::new(),
        end: 0,
    };
    let mut taken = Taken::default();
    for p in params {
        let Some((data_type, fact)) = parameter(cx, p) else {
            continue;
        };
        let offset = usize::from(*p.offset.get_ref());
        let masks = bit_mask(data_type);
        taken.take(cx, p.name.get_ref(), (offset, &masks), p.offset.span());
        placed.end = placed.end.max(offset + masks.len());
        let text = fact.allowed.choices().and_then(|_| text_ids.next());
        placed.params.push(PrmParam {
            id: ids.next().unwrap_or(u16::MAX),
            offset: u16::from(*p.offset.get_ref()),
            value: PrmValue::Card(facts_before + placed.facts.len()),
            data_type,
            text,
        });
        placed.facts.push(fact);
    }
    placed
}

impl Placed {
    /// The value texts of those parameters that have choices.
    pub fn texts(&self) -> impl Iterator<Item = PrmText> + '_ {
        self.params
            .iter()
            .filter_map(|param| match (param.text, param.value) {
                (Some(id), PrmValue::Card(index)) => Some(PrmText {
                    id,
                    of: PrmTextOf::Card(index),
                }),
                _ => None,
            })
    }
}

/// The bits a parameter takes of each of its bytes, from its offset.
fn bit_mask(data_type: PrmType) -> Vec<u8> {
    match data_type {
        PrmType::Unsigned8 | PrmType::Signed8 => vec![0xFF],
        PrmType::Unsigned16 => vec![0xFF, 0xFF],
        PrmType::Bits { first, last } => vec![crate::ir::bits_of_byte(first, last)],
    }
}

fn parameter(cx: &mut Checker, p: &raw::Parameter) -> Option<(PrmType, CardParam)> {
    let name = cx.gsd_name(&p.name, GSD_NAME_LEN, "parameter name");
    let given = (p.data_type.as_ref(), p.bits.as_ref());
    let data_type = match param_values::stored(cx, &name, given)? {
        Stored::Bits { first, last } => PrmType::Bits { first, last },
        Stored::Type(raw::PrmType::Unsigned8) => PrmType::Unsigned8,
        Stored::Type(raw::PrmType::Signed8) => PrmType::Signed8,
        Stored::Type(raw::PrmType::Unsigned16) | Stored::Unsaid => PrmType::Unsigned16,
    };
    let most = i64::from(data_type.max());
    let choices = (p.range.as_ref(), p.choices.as_ref());
    let holds = param_values::holds(cx, &name, choices, most, Some(GSD_NAME_LEN))?;
    let default = param_values::default(cx, &name, &p.default, (most, &holds))?;
    let allowed = match holds {
        // Within the type's values, which are u16's.
        Holds::Range(min, max) => Allowed::Range {
            min: min as u16,
            max: max as u16,
        },
        Holds::Choices(set) => Allowed::Choices(set),
    };
    Some((
        data_type,
        CardParam {
            name: crate::ir::Text::english(name),
            default: default as u16,
            allowed,
            changeable: p.changeable.as_ref().is_none_or(|c| *c.get_ref()),
            visible: p.visible.as_ref().is_none_or(|v| *v.get_ref()),
        },
    ))
}

/// The most bytes User_Prm_Data holds: what its length keyword
/// (Max_User_Prm_Data_Len) takes.
pub(super) fn max_user_prm_len() -> usize {
    let (_, max) = crate::gsd::keyword_range("Max_User_Prm_Data_Len");
    usize::try_from(max).expect("the schema gives Max_User_Prm_Data_Len an Unsigned8 range")
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
