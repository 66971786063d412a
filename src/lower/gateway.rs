//! The gateway part: the second bus's node numbers, the user parameters
//! that configure the nodes (with the defaults checked as a configuration
//! the gateway must accept), the word modules and the diagnosis. Where each
//! parameter lies in User_Prm_Data is decided by [`place`], which the
//! PROFIBUS lowering calls after the mapping blocks.

mod diagnosis;

use super::checks::{Checker, GSD_NAME_LEN};
use crate::description::gateway as raw;
use crate::description::{BitRange, Description};
use crate::diag::Diagnostic;
use crate::ir::gateway::{config_byte, DataOrder, Gateway, Module, Node, Param, ParamKey};
use crate::ir::profibus::{PrmParam, PrmType, PrmValue, MAX_WORDS_PER_IDENTIFIER};
use crate::ir::{Direction, Ident, Text};
use std::collections::BTreeSet;
use std::ops::Range;
use toml::Spanned;

/// A PROFIBUS slave's input and output each hold at most 244 bytes.
const MAX_DATA_LEN: i64 = 244;
/// Node numbers, counts and words are bytes in the generated code.
const MAX_BYTE: i64 = 0xFF;

/// The gateway's plan, and what the PROFIBUS lowering needs to place its
/// parameters.
pub struct Lowered {
    pub gateway: Gateway,
    /// Each parameter's data type, in the order User_Prm_Data holds them.
    pub prm_types: Vec<(ParamKey, PrmType)>,
    /// The `[gateway]` table, where a parameter telegram too long is shown.
    pub span: Range<usize>,
}

/// Lowers `[gateway]`. Errors are reported and replaced by the nearest
/// valid value, so that the plan is whole (and unused: a description with an
/// error gives no IR).
pub fn lower(cx: &mut Checker, g: &Spanned<raw::Gateway>, desc: &Description) -> Lowered {
    let span = g.span();
    conflicts(cx, desc, &span);
    let g = g.get_ref();
    let (first_node, last_node) = node_numbers(cx, &g.nodes);
    let own_node = g.own_node.as_ref().and_then(|n| {
        cx.spanned_in_range(
            n,
            first_node.into(),
            last_node.into(),
            "the gateway's own node",
        )
    });
    let max_len = |cx: &mut Checker, len: &Spanned<i64>, what| {
        cx.spanned_in_range(len, 1, MAX_DATA_LEN, what)
            .unwrap_or(MAX_DATA_LEN as u16)
    };
    let max_input_len = max_len(cx, &g.max_input_len, "max_input_len");
    let max_output_len = max_len(cx, &g.max_output_len, "max_output_len");
    let data_order = match &g.data_order {
        Some(order) => match order.get_ref() {
            raw::DataOrder::NodeAscending => DataOrder::NodeAscending,
        },
        None => {
            cx.defaulted("gateway.data_order", "\"node-ascending\"", span.clone());
            DataOrder::NodeAscending
        }
    };
    let nodes = first_node..=last_node;
    let (node_count, count_type) = node_count(cx, &g.node_count, nodes.len());
    let limits = [
        (Direction::In, max_input_len),
        (Direction::Out, max_output_len),
    ];
    let words: Vec<NodeWords> = limits
        .iter()
        .map(|&(direction, max_len)| {
            let raw = match direction {
                Direction::In => &g.input_words,
                Direction::Out => &g.output_words,
            };
            node_words(cx, raw, direction, nodes.clone(), max_len)
        })
        .collect();
    default_configuration(cx, &node_count, &words);
    let (modules, max_modules) = modules(cx, &g.modules, &limits);
    let mut prm_types = vec![(ParamKey::NodeCount, count_type)];
    let nodes = nodes
        .enumerate()
        .map(|(i, number)| {
            let [input, output] = [&words[0], &words[1]].map(|w| w.params[i].clone());
            for (param, w) in [(&input, &words[0]), (&output, &words[1])] {
                prm_types.push((param.key, w.data_type));
            }
            Node {
                number,
                input_words: input,
                output_words: output,
            }
        })
        .collect();
    Lowered {
        gateway: Gateway {
            bus: cx.required(&g.bus, "bus"),
            first_node,
            last_node,
            own_node,
            max_input_len,
            max_output_len,
            data_order,
            node_count,
            nodes,
            modules,
            max_modules,
            diagnosis: g.diagnosis.as_ref().map(|d| diagnosis::lower(cx, d)),
        },
        prm_types,
        span,
    }
}

/// E140: what a gateway's description cannot have besides `[gateway]`.
fn conflicts(cx: &mut Checker, desc: &Description, gateway: &Range<usize>) {
    let profibus = desc.profibus.as_ref().map(Spanned::get_ref);
    let mappings = &desc.mappings;
    let mapping_span = [&mappings.pzd_out, &mappings.pzd_in, &mappings.dpv1_index]
        .into_iter()
        .flatten()
        .map(|m| m.name.span())
        .next();
    let found = [
        (
            desc.telegram.as_ref().map(|t| t.pkw.span()),
            "[telegram]",
            "its data are the nodes' words, not a PKW and PZD telegram",
        ),
        (
            mapping_span,
            "[mappings]",
            "the nodes' words are forwarded as they are, not mapped",
        ),
        (
            desc.settings.first().map(|s| s.name.span()),
            "[[settings]]",
            "its user parameters are the node parameters of [gateway]",
        ),
        (
            profibus
                .and_then(|p| p.ppo_types.as_ref())
                .map(Spanned::span),
            "ppo_types",
            "its modules are the word blocks of [gateway.modules]",
        ),
        (
            profibus
                .and_then(|p| p.diagnosis.as_ref())
                .map(Spanned::span),
            "[profibus.diagnosis]",
            "its diagnosis is [gateway.diagnosis]",
        ),
        (
            desc.profinet.as_ref().map(Spanned::span),
            "[profinet]",
            "gsdc describes PROFIBUS-DP gateways",
        ),
    ];
    for (span, what, why) in found {
        if let Some(span) = span {
            cx.push(
                Diagnostic::error("E140", format!("a gateway's description has no {what}"))
                    .at(span)
                    .label("not for a gateway")
                    .help(format!(
                        "remove it: {why}; a card with a second personality has a description for each"
                    )),
            );
        }
    }
    if desc.profibus.is_none() {
        cx.push(
            Diagnostic::error("E140", "a gateway's description needs [profibus]")
                .at(gateway.clone())
                .label("a gateway without [profibus]")
                .help("add [profibus] with the GSD's file name, ident number, baud rates and slave family (9 is Gateway)"),
        );
    }
}

/// `1 word`, `3 words`.
fn words_of(words: u16) -> String {
    match words {
        1 => "1 word".to_string(),
        n => format!("{n} words"),
    }
}

/// `[first, last]` within a byte, first not above last.
fn node_numbers(cx: &mut Checker, nodes: &Spanned<[Spanned<i64>; 2]>) -> (u8, u8) {
    let [first, last] = nodes.get_ref();
    let first: u8 = cx
        .spanned_in_range(first, 0, MAX_BYTE, "a node number")
        .unwrap_or(1);
    let last: u8 = cx
        .spanned_in_range(last, 0, MAX_BYTE, "a node number")
        .unwrap_or(first);
    if first > last {
        reversed(cx, nodes.span(), first, last);
        return (first, first);
    }
    (first, last)
}

fn reversed(cx: &mut Checker, span: Range<usize>, min: impl ToString, max: impl ToString) {
    let (min, max) = (min.to_string(), max.to_string());
    cx.push(
        Diagnostic::error("E109", format!("range [{min}, {max}] is reversed"))
            .at(span)
            .label("minimum above maximum")
            .help("write the range as [minimum, maximum]"),
    );
}

/// The count parameter: at most one per node number (E141).
fn node_count(cx: &mut Checker, c: &raw::NodeCount, node_numbers: usize) -> (Param, PrmType) {
    let data_type = data_type(cx, &c.data_type, &c.bits, &c.name);
    let (min, max) = range(cx, &c.range, data_type, "the node count");
    if usize::from(max) > node_numbers {
        cx.push(
            Diagnostic::error(
                "E141",
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
struct NodeWords {
    direction: Direction,
    data_type: PrmType,
    params: Vec<Param>,
    max_len: u16,
    /// Where the description gives the defaults.
    defaults_span: Range<usize>,
}

fn node_words(
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
    check_rendered_name(cx, &w.name, &name, *nodes.end());
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
/// within the range.
fn node_defaults(
    cx: &mut Checker,
    w: &raw::NodeWords,
    count: usize,
    range: (u8, u8),
) -> (Vec<u8>, Range<usize>) {
    let what = "a node's words";
    match (&w.default, &w.defaults) {
        (Some(default), None) => {
            let value = default_in(cx, default, range, what);
            (vec![value; count], default.span())
        }
        (None, Some(list)) if list.get_ref().len() == count => {
            let values = list
                .get_ref()
                .iter()
                .map(|d| default_in(cx, d, range, what))
                .collect();
            (values, list.span())
        }
        (None, Some(list)) => {
            cx.push(
                Diagnostic::error(
                    "E122",
                    format!("{} defaults for {count} node numbers", list.get_ref().len()),
                )
                .at(list.span())
                .label(format!("expected {count} values"))
                .help("give one default per node number, the first node first"),
            );
            (vec![range.0; count], list.span())
        }
        (Some(default), Some(_)) => {
            cx.push(
                Diagnostic::error("E123", "node words with both `default` and `defaults`")
                    .at(default.span())
                    .label("remove this or `defaults`")
                    .help("`default` sets every node, `defaults` each one"),
            );
            (vec![range.0; count], default.span())
        }
        (None, None) => {
            cx.push(
                Diagnostic::error("E123", "node words with neither `default` nor `defaults`")
                    .at(w.name.span())
                    .label("in this parameter")
                    .help("add `default = ...` for every node, or `defaults = [...]` one per node"),
            );
            (vec![range.0; count], w.name.span())
        }
    }
}

/// The defaults are the configuration the GSD offers first: the gateway
/// must accept it. Nodes past the count carry no words (E144), and the
/// nodes in use fit the data limits (E142).
fn default_configuration(cx: &mut Checker, count: &Param, words: &[NodeWords]) {
    let in_use = usize::from(count.default);
    for w in words {
        if let Some(unused) = w.params.iter().skip(in_use).find(|p| p.default != 0) {
            let ParamKey::Words { node, .. } = unused.key else {
                continue;
            };
            cx.push(
                Diagnostic::error(
                    "E144",
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
        let words: u16 = w
            .params
            .iter()
            .take(in_use)
            .map(|p| u16::from(p.default))
            .sum();
        let (bytes, max_len) = (2 * words, w.max_len);
        if bytes > max_len {
            let way = match w.direction {
                Direction::In => "input",
                Direction::Out => "output",
            };
            cx.push(
                Diagnostic::error(
                    "E142",
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

/// `type` or `bits`: exactly one (E145).
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
                Diagnostic::error("E145", "a parameter with both `type` and `bits`")
                    .at(ty.span())
                    .label("remove this or `bits`")
                    .help("`type` gives a parameter whole bytes, `bits` some bits of one byte"),
            );
            PrmType::Unsigned8
        }
        (None, None) => {
            cx.push(
                Diagnostic::error("E145", "a parameter with neither `type` nor `bits`")
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
    range: &Spanned<[Spanned<i64>; 2]>,
    data_type: PrmType,
    what: &str,
) -> (u8, u8) {
    let most = i64::from(data_type.max()).min(MAX_BYTE);
    let [min, max] = range.get_ref();
    let min: u8 = cx.spanned_in_range(min, 0, most, what).unwrap_or(0);
    let max: u8 = cx.spanned_in_range(max, 0, most, what).unwrap_or(min);
    if min > max {
        reversed(cx, range.span(), min, max);
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

/// The longest name is the last node's: checked in the form the GSD shows.
fn check_rendered_name(
    cx: &mut Checker,
    raw_name: &Spanned<crate::description::Text>,
    name: &Text,
    last: u8,
) {
    let raw = raw_name.get_ref();
    let span = raw
        .gsd
        .as_ref()
        .map_or_else(|| raw.en_span(&raw_name.span()), Spanned::span);
    let rendered = render(name, last);
    cx.check_gsd_text(rendered.for_gsd(), span, GSD_NAME_LEN, "parameter name");
}

fn render(name: &Text, node: u8) -> Text {
    let n = node.to_string();
    name.map(|text| text.replace("{n}", &n))
}

/// The modules, input first, each size ascending, and Max_Module.
fn modules(cx: &mut Checker, m: &raw::Modules, limits: &[(Direction, u16)]) -> (Vec<Module>, u8) {
    let sizes = module_sizes(cx, &m.words);
    let fewest: Result<Vec<usize>, u16> = limits
        .iter()
        .map(|&(_, max_len)| fewest_modules(&sizes, max_len / 2))
        .collect();
    let most = match fewest {
        Ok(needed) => needed.iter().sum(),
        Err(words) => {
            cx.push(
                Diagnostic::error("E143", format!("no set of these modules carries {}", words_of(words)))
                    .at(m.words.span())
                    .label("sizes that leave a total out")
                    .help("the master plugs modules until they equal the nodes' words, which may be any number up to the limit: offer 1 word, the smallest size"),
            );
            0
        }
    };
    let consistent = *m.consistent.get_ref();
    let modules = [Direction::In, Direction::Out]
        .into_iter()
        .flat_map(|direction| sizes.iter().map(move |&words| (direction, words)))
        .zip(1..=u8::MAX)
        .map(|((direction, words), reference)| {
            let way = match direction {
                Direction::In => "input",
                Direction::Out => "output",
            };
            let unit = if words == 1 { "word" } else { "words" };
            Module {
                reference,
                name: format!("{} {words} {unit}", way.to_ascii_uppercase()),
                direction,
                words,
                consistent,
                config: config_byte(direction, words, consistent),
                ident: Ident::of(&[way, &words.to_string(), unit]),
            }
        })
        .collect();
    (modules, u8::try_from(most).unwrap_or(u8::MAX))
}

/// The sizes, ascending, each 1..=16 words (one identifier byte) and once.
fn module_sizes(cx: &mut Checker, words: &Spanned<Vec<Spanned<i64>>>) -> Vec<u8> {
    if words.get_ref().is_empty() {
        cx.push(
            Diagnostic::error("E101", "no module size")
                .at(words.span())
                .label("empty")
                .help("offer at least one size, e.g. words = [1, 2, 4, 8, 16]"),
        );
    }
    let mut seen = BTreeSet::new();
    for size in words.get_ref() {
        let max = i64::from(MAX_WORDS_PER_IDENTIFIER);
        if let Some(value) = cx.spanned_in_range::<u8, _>(size, 1, max, "a module's words") {
            if !seen.insert(value) {
                cx.duplicate(format!("module size {value}"), size.span());
            }
        }
    }
    seen.into_iter().collect()
}

/// The most modules of `sizes` any total of 0..=`words` words needs when
/// made of as few as it can be; or the first total no set of them makes.
fn fewest_modules(sizes: &[u8], words: u16) -> Result<usize, u16> {
    let words = usize::from(words);
    // fewest[t]: the fewest modules that make t words, if any do.
    let mut fewest: Vec<Option<usize>> = vec![None; words + 1];
    fewest[0] = Some(0);
    for total in 1..=words {
        fewest[total] = sizes
            .iter()
            .filter_map(|&size| {
                fewest
                    .get(total.checked_sub(usize::from(size))?)?
                    .map(|n| n + 1)
            })
            .min();
    }
    fewest
        .iter()
        .enumerate()
        .try_fold(0, |most, (total, n)| match n {
            Some(n) => Ok(most.max(*n)),
            None => Err(total as u16),
        })
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
    let mut open: Option<(usize, u8)> = None;
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

fn mask(first: u8, last: u8) -> u8 {
    (first..=last).fold(0, |m, bit| m | 1 << bit)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn module_counts_are_the_fewest_for_the_worst_total() {
        // 122 words of powers of two: 111 = 6 x 16 + 8 + 4 + 2 + 1 needs 10.
        assert_eq!(fewest_modules(&[1, 2, 4, 8, 16], 122), Ok(10));
        // Every size: 7 x 16 and one more for the rest.
        let all: Vec<u8> = (1..=16).collect();
        assert_eq!(fewest_modules(&all, 122), Ok(8));
        assert_eq!(fewest_modules(&[2, 4], 8), Err(1));
        assert_eq!(fewest_modules(&[1], 0), Ok(0));
    }

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
