//! The gateway's user parameters: the node count and each node's words each
//! way, with their data types, ranges and defaults; the defaults checked as
//! a configuration the gateway must accept; and their places in
//! User_Prm_Data.

use super::super::checks::{Checker, Defaults, DefaultsOf, GSD_NAME_LEN};
use super::super::mappings::{check_rendered_name, render};
use super::super::telegram::mask;
use super::{words_of, MAX_BYTE};
use crate::description::gateway as raw;
use crate::description::BitRange;
use crate::description::Exactly;
use crate::diag::Diagnostic;
use crate::ir::gateway::{Param, ParamKey};
use crate::ir::profibus::{PrmParam, PrmType, PrmValue};
use crate::ir::Direction;
use std::ops::Range;
use toml::Spanned;

/// The count parameter: at most one per node number (E145).
pub(super) fn node_count(
    cx: &mut Checker,
    c: &raw::NodeCount,
    node_numbers: usize,
) -> (Param, PrmType) {
    let data_type = data_type(cx, &c.data_type, &c.bits, &c.name);
    let (min, max) = range(cx, &c.range, data_type, "the node count");
    if usize::from(max) > node_numbers {
        cx.push(
            Diagnostic::error(
                "E145",
                format!("up to {max} nodes counted, but there are {node_numbers} node numbers"),
            )
            .at(c.range.span())
            .label(format!("at most {node_numbers}"))
            .help("each node in use has a node number of [gateway] nodes, and parameters of its own: count no more nodes than there are numbers"),
        );
    }
    let default = default_in(cx, &c.default, (min, max), "the node count");
    let param = Param {
        key: ParamKey::NodeCount,
        name: cx.text(&c.name, Some(GSD_NAME_LEN), "parameter name"),
        min,
        max,
        default,
    };
    (param, data_type)
}

/// One direction's parameters, one per node, and where their defaults are.
pub(super) struct NodeWords {
    direction: Direction,
    pub(super) data_type: PrmType,
    pub(super) params: Vec<Param>,
    max_len: u16,
    /// Where the description gives the defaults.
    defaults_span: Range<usize>,
}

pub(super) fn node_words(
    cx: &mut Checker,
    w: &raw::NodeWords,
    direction: Direction,
    nodes: std::ops::RangeInclusive<u8>,
    max_len: u16,
) -> NodeWords {
    let data_type = data_type(cx, &w.data_type, &w.bits, &w.name);
    let what = "a node's words";
    let (min, max) = range(cx, &w.range, data_type, what);
    // A node's words alone fit the data limit.
    let _: Option<u8> = cx.in_range(
        max.into(),
        0,
        i64::from(max_len / 2),
        w.range.span(),
        "a node's words (half the data limit)",
    );
    let (defaults, defaults_span) = node_defaults(cx, w, nodes.len(), (min, max));
    let name = cx.text(&w.name, None, "parameter name");
    check_rendered_name(cx, &w.name, &name, *nodes.end(), "parameter name");
    let params = nodes
        .zip(defaults)
        .map(|(node, default)| Param {
            key: ParamKey::Words { node, direction },
            name: render(&name, node),
            min,
            max,
            default,
        })
        .collect();
    NodeWords {
        direction,
        data_type,
        params,
        max_len,
        defaults_span,
    }
}

/// One default per node: `default` for all or `defaults` one by one, each
/// within the range. After an error, every node's default is the range's
/// least, so that the checks after it still run.
fn node_defaults(
    cx: &mut Checker,
    w: &raw::NodeWords,
    count: usize,
    range: (u8, u8),
) -> (Vec<u8>, Range<usize>) {
    let what = "a node's words";
    let of = DefaultsOf {
        noun: "parameter",
        item: "node",
        items: "nodes",
        order: "the first node first",
    };
    match cx.defaults(&w.default, &w.defaults, count, &of, w.name.span()) {
        Some(Defaults::Same(default)) => {
            let value = default_in(cx, default, range, what);
            (vec![value; count], default.span())
        }
        Some(Defaults::Each(list)) => {
            let values = list
                .get_ref()
                .iter()
                .map(|d| default_in(cx, d, range, what))
                .collect();
            (values, list.span())
        }
        None => (vec![range.0; count], w.name.span()),
    }
}

/// The defaults are the configuration the GSD offers first: the gateway
/// must accept it. Nodes past the count carry no words (E148), and the
/// nodes in use fit the data limits (E146).
pub(super) fn default_configuration(cx: &mut Checker, count: &Param, words: &[NodeWords]) {
    let in_use = usize::from(count.default);
    for w in words {
        if let Some(unused) = w.params.iter().skip(in_use).find(|p| p.default != 0) {
            let ParamKey::Words { node, .. } = unused.key else {
                continue;
            };
            cx.push(
                Diagnostic::error(
                    "E148",
                    format!(
                        "node {node} has {} by default, but the default count is {in_use} nodes",
                        words_of(unused.default.into())
                    ),
                )
                .at(w.defaults_span.clone())
                .label("words of a node not in use")
                .help("a node past the count carries no data: give it 0 words, or raise the node count's default"),
            );
        }
        // 255 nodes of 255 words are 130050 bytes: more than 16 bits hold.
        let words: u32 = w
            .params
            .iter()
            .take(in_use)
            .map(|p| u32::from(p.default))
            .sum();
        let (bytes, max_len) = (2 * words, w.max_len);
        if bytes > u32::from(max_len) {
            let way = match w.direction {
                Direction::In => "input",
                Direction::Out => "output",
            };
            cx.push(
                Diagnostic::error(
                    "E146",
                    format!(
                        "the default configuration has {bytes} bytes of {way}; the gateway carries at most {max_len}"
                    ),
                )
                .at(w.defaults_span.clone())
                .label(format!("{} of {in_use} nodes", words_of(words)))
                .help(format!("the defaults of the nodes in use must add up to at most {} words", max_len / 2)),
            );
        }
    }
}

/// `type` or `bits`: exactly one (E149).
fn data_type(
    cx: &mut Checker,
    ty: &Option<Spanned<raw::PrmType>>,
    bits: &Option<Spanned<BitRange>>,
    name: &Spanned<crate::description::Text>,
) -> PrmType {
    match (ty, bits) {
        (Some(ty), None) => match ty.get_ref() {
            raw::PrmType::Unsigned8 => PrmType::Unsigned8,
            raw::PrmType::Unsigned16 => PrmType::Unsigned16,
        },
        (None, Some(bits)) => {
            let span = bits.span();
            let BitRange { first, last } = *bits.get_ref();
            let first: Option<u8> = cx.in_range(first, 0, 7, span.clone(), "a bit of a byte");
            let last: Option<u8> = cx.in_range(
                last,
                first.map_or(0, i64::from),
                7,
                span,
                "the last bit of a byte",
            );
            match (first, last) {
                (Some(first), Some(last)) => PrmType::Bits { first, last },
                _ => PrmType::Unsigned8,
            }
        }
        (Some(ty), Some(_)) => {
            cx.push(
                Diagnostic::error("E149", "a parameter with both `type` and `bits`")
                    .at(ty.span())
                    .label("remove this or `bits`")
                    .help("`type` gives a parameter whole bytes, `bits` some bits of one byte"),
            );
            PrmType::Unsigned8
        }
        (None, None) => {
            cx.push(
                Diagnostic::error("E149", "a parameter with neither `type` nor `bits`")
                    .at(name.span())
                    .label("in this parameter")
                    .help("add `type = \"Unsigned8\"` (or \"Unsigned16\"), or `bits = [first, last]` within one byte"),
            );
            PrmType::Unsigned8
        }
    }
}

/// `[min, max]` within what the data type holds and within a byte.
fn range(
    cx: &mut Checker,
    range: &Spanned<Exactly<Spanned<i64>, 2>>,
    data_type: PrmType,
    what: &str,
) -> (u8, u8) {
    let most = i64::from(data_type.max()).min(MAX_BYTE);
    let Exactly([min, max]) = range.get_ref();
    let min: u8 = cx.spanned_in_range(min, 0, most, what).unwrap_or(0);
    let max: u8 = cx.spanned_in_range(max, 0, most, what).unwrap_or(min);
    if min > max {
        cx.reversed(range.span(), min, max);
        return (min, min);
    }
    (min, max)
}

/// A default within `min..=max` (E108), or the minimum.
fn default_in(cx: &mut Checker, default: &Spanned<i64>, (min, max): (u8, u8), what: &str) -> u8 {
    let value = *default.get_ref();
    if (i64::from(min)..=i64::from(max)).contains(&value) {
        return value as u8;
    }
    cx.push(
        Diagnostic::error(
            "E108",
            format!("default {value} is not among the values {what} allows"),
        )
        .at(default.span())
        .label("not allowed")
        .help(format!("pick a default from {min} to {max}")),
    );
    min
}

/// Places the gateway's parameters from byte `start` on, numbering them on
/// from `ids`: a bit area goes into the byte of the parameter before it
/// when that is a bit area whose bits it leaves free; anything else starts
/// at the next free byte. Returns the parameters and the end.
pub fn place(
    types: &[(ParamKey, PrmType)],
    start: usize,
    ids: &mut impl Iterator<Item = u16>,
) -> (Vec<PrmParam>, usize) {
    let mut end = start;
    // The byte of the last bit area, and its bits in use.
    let mut open: Option<(usize, u32)> = None;
    let params = types
        .iter()
        .map(|&(key, data_type)| {
            let offset = match (data_type, open) {
                (PrmType::Bits { first, last }, Some((at, used)))
                    if used & mask(first, last) == 0 =>
                {
                    open = Some((at, used | mask(first, last)));
                    at
                }
                (PrmType::Bits { first, last }, _) => {
                    open = Some((end, mask(first, last)));
                    end += 1;
                    end - 1
                }
                _ => {
                    open = None;
                    end += usize::from(data_type.bytes());
                    end - usize::from(data_type.bytes())
                }
            };
            PrmParam {
                id: ids.next().unwrap_or(u16::MAX),
                offset: u16::try_from(offset).unwrap_or(u16::MAX),
                value: PrmValue::Gateway(key),
                data_type,
                text: None,
            }
        })
        .collect();
    (params, end)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn offsets(types: &[PrmType]) -> (Vec<u16>, usize) {
        let keyed: Vec<_> = types.iter().map(|&t| (ParamKey::NodeCount, t)).collect();
        let (params, end) = place(&keyed, 3, &mut (1..));
        (params.iter().map(|p| p.offset).collect(), end)
    }

    #[test]
    fn bit_areas_share_a_byte_while_their_bits_are_free() {
        let nibble = |first| PrmType::Bits {
            first,
            last: first + 3,
        };
        // A count byte, then two nodes of two nibbles each.
        assert_eq!(
            offsets(&[
                PrmType::Unsigned8,
                nibble(0),
                nibble(4),
                nibble(0),
                nibble(4)
            ]),
            (vec![3, 4, 4, 5, 5], 6)
        );
        // A bit area after a whole byte, or on bits already used, starts a byte.
        assert_eq!(
            offsets(&[nibble(0), PrmType::Unsigned16, nibble(0), nibble(2)]),
            (vec![3, 4, 6, 7], 8)
        );
    }

    #[test]
    fn parameters_are_numbered_on() {
        let keyed = [(ParamKey::NodeCount, PrmType::Unsigned8)];
        let mut ids = 5..;
        let (params, _) = place(&keyed, 0, &mut ids);
        assert_eq!(params[0].id, 5);
        assert_eq!(ids.next(), Some(6));
    }
}
