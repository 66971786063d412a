//! What a parameter of the card's own may be, the same for a PROFIBUS
//! User_Prm_Data parameter (`[[profibus.parameters]]`) and a value of a
//! PROFINET record of the access point or a port: its bits or its type,
//! its range or its choices, its default, and its place beside the others.

use super::checks::Checker;
use super::telegram::value_set;
use crate::description::{BitRange, Choice, Exactly};
use crate::diag::Diagnostic;
use crate::ir::{Ident, ValueSet};
use std::ops::Range;
use toml::Spanned;

/// How a parameter is stored, as the description says it.
pub(super) enum Stored<T> {
    /// Whole bytes, of its `type`.
    Type(T),
    /// Bits `first` to `last` of one byte.
    Bits { first: u8, last: u8 },
    /// Neither: the format's default type.
    Unsaid,
}

/// A parameter's `type` or `bits`, not both (E175), its bits those of one
/// byte (E101).
pub(super) fn stored<T: Copy>(
    cx: &mut Checker,
    name: &str,
    (data_type, bits): (Option<&Spanned<T>>, Option<&Spanned<BitRange>>),
) -> Option<Stored<T>> {
    match (data_type, bits) {
        (Some(t), Some(_)) => {
            cx.push(
                Diagnostic::error("E175", format!("parameter \"{name}\" has both `type` and `bits`"))
                    .at(t.span())
                    .label("remove this or `bits`")
                    .help("`bits` stores the parameter in some bits of one byte (a Bit or BitArea); `type` in whole bytes"),
            );
            None
        }
        (_, Some(bits)) => {
            let (first, last) = bits_of_a_byte(cx, bits)?;
            Some(Stored::Bits { first, last })
        }
        (Some(t), None) => Some(Stored::Type(*t.get_ref())),
        (None, None) => Some(Stored::Unsaid),
    }
}

/// The first and last bit of `bits`, bits of one byte (E101).
fn bits_of_a_byte(cx: &mut Checker, bits: &Spanned<BitRange>) -> Option<(u8, u8)> {
    let range = bits.get_ref();
    if !(0..=7).contains(&range.first) || !(range.first..=7).contains(&range.last) {
        cx.push(
            Diagnostic::error(
                "E101",
                format!(
                    "bits {}..={} are not bits of one byte",
                    range.first, range.last
                ),
            )
            .at(bits.span())
            .label("not within 0..=7")
            .help(
                "a parameter's bits are bits of the byte at its offset: [first, last] within 0..=7",
            ),
        );
        return None;
    }
    // Checked above: 0 <= first <= last <= 7.
    Some((range.first as u8, range.last as u8))
}

/// What a parameter may hold.
pub(super) enum Holds {
    /// Both ends included.
    Range(i64, i64),
    Choices(ValueSet),
}

impl Holds {
    pub fn contains(&self, value: i64) -> bool {
        match self {
            Holds::Range(min, max) => (*min..=*max).contains(&value),
            Holds::Choices(set) => set.choices.iter().any(|c| c.value == value),
        }
    }
}

/// A parameter's `range = [min, max]`, as the description gives it.
pub(super) type GivenRange = Spanned<Exactly<Spanned<i64>, 2>>;

/// A parameter's `range` or `choices` (E119 for both), each within `0..=most`
/// (E101, E109 reversed); every value to `most` when it gives neither.
/// Choice texts are at most `gsd_limit` characters when given.
pub(super) fn holds(
    cx: &mut Checker,
    name: &str,
    (range, choices): (Option<&GivenRange>, Option<&Spanned<Vec<Choice>>>),
    most: i64,
    gsd_limit: Option<usize>,
) -> Option<Holds> {
    match (range, choices) {
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
            None
        }
        (Some(range), None) => {
            let Exactly([min, max]) = range.get_ref();
            let min: i64 = cx.spanned_in_range(min, 0, most, "the parameter's least value")?;
            let max: i64 = cx.spanned_in_range(max, 0, most, "the parameter's most value")?;
            if min > max {
                cx.reversed(range.span(), min, max);
                return None;
            }
            Some(Holds::Range(min, max))
        }
        (None, Some(choices)) => Some(Holds::Choices(value_set(
            cx,
            Ident::of(&["choice"]),
            choices.get_ref(),
            (0, most),
            gsd_limit,
        ))),
        (None, None) => Some(Holds::Range(0, most)),
    }
}

/// The default, within `0..=most` (E101) and among what the parameter
/// holds (E108, reported, the default still returned).
pub(super) fn default(
    cx: &mut Checker,
    name: &str,
    given: &Spanned<i64>,
    (most, holds): (i64, &Holds),
) -> Option<i64> {
    let default: i64 = cx.spanned_in_range(given, 0, most, "the parameter's default")?;
    if !holds.contains(default) {
        cx.push(
            Diagnostic::error(
                "E108",
                format!("default {default} is not among the values parameter \"{name}\" allows"),
            )
            .at(given.span())
            .label("not allowed")
            .help("pick a default within the range or among the choices"),
        );
    }
    Some(default)
}

/// The bits the parameters of one block take so far, each byte's with the
/// name of the parameter that takes them.
#[derive(Default)]
pub(super) struct Taken(Vec<(usize, u8, String)>);

impl Taken {
    /// Takes `masks`, the bits of each byte from `offset` on, for `name`;
    /// E114 at `span` for the bits another parameter took.
    pub fn take(
        &mut self,
        cx: &mut Checker,
        name: &str,
        (offset, masks): (usize, &[u8]),
        span: Range<usize>,
    ) {
        for (byte, &mask) in masks.iter().enumerate() {
            let at = offset + byte;
            if let Some((_, _, other)) = self.0.iter().find(|(o, m, _)| *o == at && m & mask != 0) {
                cx.push(
                    Diagnostic::error(
                        "E114",
                        format!("parameter \"{name}\" overlaps another at byte {at}"),
                    )
                    .at(span.clone())
                    .label("bits taken already")
                    .help(format!(
                        "\"{other}\" takes some of its bits: two parameters cannot share a bit"
                    )),
                );
            }
            self.0.push((at, mask, name.to_string()));
        }
    }
}
