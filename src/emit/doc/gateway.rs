//! A gateway (MD810's bridge mode): the second bus and its nodes, the data
//! limits and order, the modules, a worked example (nodes, modules,
//! parameter telegram and a diagram of the data), and the diagnosis block
//! by type with the block each code gives, encoded by the firmware's code.

use super::page::{code, text, Builder, Cell, Run};
use super::svg::Style;
use super::telegrams::{words_figure, WordView};
use super::{bytes, decision_mark, hex_bytes, Lang};
use crate::i18n::{self, sheet as w};
use crate::ir::gateway::{DataOrder, DiagCode, Diagnosis, Gateway, Module, Node, ParamKey};
use crate::ir::profibus::{PrmValue, Profibus, STANDARD_DIAG_BYTES};
use crate::ir::{Direction, Ir};
use crate::pkw::support::gateway as firmware;

pub(crate) fn section(doc: &mut Builder, ir: &Ir, lang: Lang) {
    let (Some(g), Some(p)) = (&ir.gateway, &ir.profibus) else {
        return;
    };
    let bus = &g.bus;
    doc.section("gateway", w::gateway_heading(lang, bus));
    let own = g
        .own_node
        .map_or_else(String::new, |n| w::gateway_own_node(lang, n));
    doc.para(text(w::gateway_intro(
        lang,
        bus,
        g.first_node,
        g.last_node,
        &own,
    )));
    facts_table(doc, ir, g, lang);
    modules_part(doc, ir, g, lang);
    if let Some(example) = Example::of(g) {
        example_part(doc, ir, g, p, &example, lang);
    }
}

fn way(lang: Lang, direction: Direction) -> &'static str {
    match direction {
        Direction::In => lang.t(w::INPUT_NODES_TO_MASTER),
        Direction::Out => lang.t(w::OUTPUT_MASTER_TO_NODES),
    }
}

/// A cell with the mark of the decision at `path`, if it is one.
fn marked(ir: &Ir, lang: Lang, value: String, path: &str) -> Cell {
    let mut cell = text(value);
    cell.extend(mark(ir, lang, path));
    cell
}

/// A blank and the mark of the decision at `path`; nothing for a value the
/// manual gives.
fn mark(ir: &Ir, lang: Lang, path: &str) -> Vec<Run> {
    decision_mark(ir, lang, path).map_or_else(Vec::new, |m| vec![Run::Text(" ".into()), m])
}

fn facts_table(doc: &mut Builder, ir: &Ir, g: &Gateway, lang: Lang) {
    let count = &g.node_count;
    let words = |direction| {
        let first = g.nodes[0].words(direction);
        w::words_from_first(
            lang,
            &w::range(lang, first.min, first.max),
            lang.text(&first.name),
        )
    };
    let order = match g.data_order {
        DataOrder::NodeAscending => lang.t(w::ORDER_NODE_ASCENDING),
    };
    let mut rows = vec![
        (lang.t(w::SECOND_BUS), text(&g.bus)),
        (
            lang.t(w::NODE_NUMBERS),
            text(w::range(lang, g.first_node, g.last_node)),
        ),
    ];
    if let Some(own) = g.own_node {
        rows.push((lang.t(w::OWN_NODE), text(own.to_string())));
    }
    rows.extend([
        (lang.t(w::NODES_IN_USE), {
            let mut cell = text(w::node_count(
                lang,
                &w::range(lang, count.min, count.max),
                lang.text(&count.name),
                count.default,
            ));
            cell.extend(mark(ir, lang, "gateway.node_count.default"));
            cell
        }),
        (
            lang.t(w::WORDS_A_NODE_SENDS),
            marked(ir, lang, words(Direction::In), "gateway.input_words"),
        ),
        (
            lang.t(w::WORDS_A_NODE_RECEIVES),
            marked(ir, lang, words(Direction::Out), "gateway.output_words"),
        ),
        (lang.t(w::MAX_INPUT_LEN), text(g.max_input_len.to_string())),
        (
            lang.t(w::MAX_OUTPUT_LEN),
            text(g.max_output_len.to_string()),
        ),
        (
            lang.t(w::NODE_WORDS_IN_DATA),
            marked(ir, lang, order.to_string(), "gateway.data_order"),
        ),
        (lang.t(w::MAX_MODULE), text(g.max_modules.to_string())),
    ]);
    doc.table(
        w::gateway_caption(lang, &g.bus),
        &[lang.t(w::ITEM), lang.t(w::VALUE)],
        rows.into_iter().map(|(k, v)| vec![text(k), v]).collect(),
    );
}

fn modules_part(doc: &mut Builder, ir: &Ir, g: &Gateway, lang: Lang) {
    doc.subsection("gateway-modules", lang.t(w::MODULES));
    let mut intro = text(w::gateway_modules_intro(lang, g.max_modules));
    if let Some(mark) = decision_mark(ir, lang, "gateway.modules") {
        intro.push(Run::Text(lang.t(w::THE_MODULE_SIZES).into()));
        intro.push(mark);
        intro.push(Run::Text(lang.t(w::FULL_STOP).into()));
    }
    doc.para(intro);
    let rows = g
        .modules
        .iter()
        .map(|m| {
            vec![
                text(&m.name),
                text(way(lang, m.direction)),
                text(m.words.to_string()),
                text((2 * u16::from(m.words)).to_string()),
                code(format!("0x{:02X}", m.config)),
                text(if m.consistent {
                    lang.t(w::WHOLE_MODULE)
                } else {
                    lang.t(w::EACH_WORD)
                }),
            ]
        })
        .collect();
    doc.table(
        lang.t(w::THE_MODULES),
        &[
            lang.t(w::MODULE),
            lang.t(w::DIRECTION),
            lang.t(w::WORDS),
            lang.t(w::BYTE_COUNT),
            lang.t(w::CONFIG_BYTE),
            lang.t(w::CONSISTENCY),
        ],
        rows,
    );
}

// ---------------------------------------------------------------------------
// The worked example

/// A configuration gsdc makes up from the description: every node in use
/// sends its most words, as many nodes as Max_Input_Len holds (within the
/// count's range); the first half of them, rounded up, receive their most
/// words, the others their least. For MD810 this is the manual's example
/// (2.4 step 5): 15 nodes, 120 words in, 64 words out.
struct Example<'a> {
    /// The nodes in use, each with the words it sends and receives.
    nodes: Vec<(&'a Node, u8, u8)>,
}

impl<'a> Example<'a> {
    /// `None` when no configuration of that kind is within the limits and
    /// ranges.
    fn of(g: &'a Gateway) -> Option<Self> {
        let most_in = |count: usize| -> u32 {
            g.nodes[..count]
                .iter()
                .map(|n| u32::from(n.input_words.max))
                .sum()
        };
        let top = usize::from(g.node_count.max).min(g.nodes.len());
        let count = (usize::from(g.node_count.min)..=top)
            .rev()
            .find(|&n| 2 * most_in(n) <= u32::from(g.max_input_len))?;
        let receiving = count.div_ceil(2);
        let nodes: Vec<(&Node, u8, u8)> = g.nodes[..count]
            .iter()
            .enumerate()
            .map(|(i, n)| {
                let out = if i < receiving {
                    n.output_words.max
                } else {
                    n.output_words.min
                };
                (n, n.input_words.max, out)
            })
            .collect();
        let example = Example { nodes };
        let fits = 2 * example.words(Direction::Out) <= u32::from(g.max_output_len);
        let past_count_empty = g.nodes[count..]
            .iter()
            .all(|n| n.input_words.min == 0 && n.output_words.min == 0);
        (fits && past_count_empty).then_some(example)
    }

    fn count(&self) -> usize {
        self.nodes.len()
    }

    fn node_words(&self, direction: Direction) -> impl Iterator<Item = (u8, u8)> + '_ {
        self.nodes.iter().map(move |&(n, i, o)| {
            (
                n.number,
                match direction {
                    Direction::In => i,
                    Direction::Out => o,
                },
            )
        })
    }

    fn words(&self, direction: Direction) -> u32 {
        self.node_words(direction).map(|(_, w)| u32::from(w)).sum()
    }

    /// The value of a gateway parameter: the count, a node's words (0 past
    /// the count).
    fn value(&self, key: ParamKey) -> u16 {
        match key {
            ParamKey::NodeCount => self.count() as u16,
            ParamKey::Words { node, direction } => self
                .node_words(direction)
                .find(|&(n, _)| n == node)
                .map_or(0, |(_, w)| w.into()),
        }
    }

    /// Each node's first and last byte in the data one way, in the data
    /// order; nodes without words have none.
    fn places(&self, g: &Gateway, direction: Direction) -> Vec<(u8, u8, u16, u16)> {
        match g.data_order {
            DataOrder::NodeAscending => {
                let mut at = 0u16;
                self.node_words(direction)
                    .filter(|&(_, w)| w > 0)
                    .map(|(node, w)| {
                        let first = at;
                        at += 2 * u16::from(w);
                        (node, w, first, at - 1)
                    })
                    .collect()
            }
        }
    }
}

fn example_part(
    doc: &mut Builder,
    ir: &Ir,
    g: &Gateway,
    p: &Profibus,
    example: &Example,
    lang: Lang,
) {
    doc.subsection("gateway-example", lang.t(w::AN_EXAMPLE));
    let (input, output) = (example.words(Direction::In), example.words(Direction::Out));
    let first = &g.nodes[0];
    let receiving = example
        .node_words(Direction::Out)
        .filter(|&(_, w)| w > 0)
        .count();
    let nodes = w::gateway_example_nodes(
        lang,
        example.count(),
        first.input_words.max,
        g.max_input_len,
        receiving,
        first.output_words.max,
    );
    let totals = w::gateway_example_totals(lang, input, 2 * input, output, 2 * output);
    doc.para(text(format!("{nodes}{totals}")));
    example_nodes_table(doc, g, example, lang);
    let caption = lang.t(w::EXAMPLE_DATA);
    let lanes = [Direction::In, Direction::Out].map(|direction| {
        let boxes = example
            .places(g, direction)
            .into_iter()
            .map(|(node, words, first, last)| WordView {
                label: w::node(lang, node),
                role: w::words_count(lang, words),
                mapped: false,
                parameter: None,
                first_byte: first,
                last_byte: last,
                style: Style::Pzd,
                // A node's block, whatever its length: one box each.
                columns: 1,
            })
            .collect::<Vec<_>>();
        (way(lang, direction), boxes)
    });
    let svg = words_figure(
        lang,
        "nodes",
        caption,
        [(lanes[0].0, &lanes[0].1[..]), (lanes[1].0, &lanes[1].1[..])],
    );
    doc.figure(caption, svg);
    example_modules_table(doc, g, example, lang);
    example_prm_table(doc, ir, p, example, lang);
}

fn example_nodes_table(doc: &mut Builder, g: &Gateway, example: &Example, lang: Lang) {
    let place = |direction, node: u8| {
        example
            .places(g, direction)
            .into_iter()
            .find(|&(n, ..)| n == node)
            .map_or_else(
                || "—".to_string(),
                |(_, _, first, last)| bytes(lang, first, last),
            )
    };
    let mut rows: Vec<Vec<Cell>> = example
        .nodes
        .iter()
        .map(|&(n, input, output)| {
            vec![
                text(n.number.to_string()),
                text(input.to_string()),
                text(place(Direction::In, n.number)),
                text(output.to_string()),
                text(place(Direction::Out, n.number)),
            ]
        })
        .collect();
    let total = |direction| example.words(direction);
    rows.push(vec![
        text(lang.t(w::ALL_NODES)),
        text(total(Direction::In).to_string()),
        text(w::bytes_count(lang, 2 * total(Direction::In))),
        text(total(Direction::Out).to_string()),
        text(w::bytes_count(lang, 2 * total(Direction::Out))),
    ]);
    doc.table(
        lang.t(w::EXAMPLE_NODES),
        &[
            lang.t(w::NODE),
            lang.t(w::WORDS_SENT),
            lang.t(w::IN_INPUT_DATA),
            lang.t(w::WORDS_RECEIVED),
            lang.t(w::IN_OUTPUT_DATA),
        ],
        rows,
    );
}

fn example_modules_table(doc: &mut Builder, g: &Gateway, example: &Example, lang: Lang) {
    let mut rows = Vec::new();
    for direction in [Direction::In, Direction::Out] {
        let words = example.words(direction);
        let Some(plugged) = usize::try_from(words)
            .ok()
            .and_then(|words| g.fewest_modules(direction, words))
        else {
            continue;
        };
        let names: Vec<String> = runs(&plugged)
            .into_iter()
            .map(|(m, n)| match n {
                1 => m.name.clone(),
                n => format!("{} × {n}", m.name),
            })
            .collect();
        let config: Vec<u8> = plugged.iter().map(|m| m.config).collect();
        rows.push(vec![
            text(way(lang, direction)),
            text(words.to_string()),
            text(names.join(lang.t(w::LIST_SEPARATOR))),
            code(hex_bytes(&config)),
        ]);
    }
    doc.table(
        lang.t(w::EXAMPLE_MODULES),
        &[
            lang.t(w::DIRECTION),
            lang.t(w::WORDS),
            lang.t(w::MODULES_FEWEST),
            lang.t(w::CONFIG_BYTES_CHK_CFG),
        ],
        rows,
    );
}

/// Equal modules next to each other, counted.
fn runs<'a>(modules: &[&'a Module]) -> Vec<(&'a Module, usize)> {
    let mut runs: Vec<(&Module, usize)> = Vec::new();
    for &m in modules {
        match runs.last_mut() {
            Some((last, n)) if last.reference == m.reference => *n += 1,
            _ => runs.push((m, 1)),
        }
    }
    runs
}

/// The parameter telegram of the example, 16 bytes a row: the defaults,
/// with the gateway's parameters written as the example sets them.
fn example_prm_table(doc: &mut Builder, ir: &Ir, p: &Profibus, example: &Example, lang: Lang) {
    let prm = &p.user_prm;
    let mut bytes_of = ir.default_user_prm(prm);
    for param in &prm.gateway {
        if let PrmValue::Gateway(key) = param.value {
            param
                .data_type
                .write(&mut bytes_of, param.offset.into(), example.value(key));
        }
    }
    let rows = bytes_of
        .chunks(16)
        .enumerate()
        .map(|(i, chunk)| {
            let first = 16 * i as u16;
            vec![
                text(bytes(lang, first, first + chunk.len() as u16 - 1)),
                code(hex_bytes(chunk)),
            ]
        })
        .collect();
    doc.table(
        w::example_user_prm(lang, bytes_of.len()),
        &[lang.t(w::BYTES), lang.t(w::HEX)],
        rows,
    );
}

// ---------------------------------------------------------------------------
// Diagnosis

pub(crate) fn diagnosis_section(doc: &mut Builder, ir: &Ir, lang: Lang) {
    let (Some(g), Some(p)) = (&ir.gateway, &ir.profibus) else {
        return;
    };
    let Some(d) = &g.diagnosis else {
        return;
    };
    doc.section("diagnosis", lang.t(w::DIAGNOSIS));
    doc.para(text(w::gateway_diagnosis_intro(
        lang,
        STANDARD_DIAG_BYTES,
        &g.bus,
    )));
    let mut rows = super::params::standard_diagnosis_rows(p, lang);
    rows.extend(block_rows(g, d, lang));
    doc.table(
        lang.t(w::DIAGNOSIS_BYTE_BY_BYTE),
        &[lang.t(w::BYTE), lang.t(w::CONTENT)],
        rows,
    );
    types_table(doc, g, d, lang);
    let areas: Vec<String> = d
        .gsd_areas
        .iter()
        .map(|a| {
            let byte = u16::from(STANDARD_DIAG_BYTES) + 1 + a.first_bit / 8;
            w::bits_of_byte(lang, a.first_bit, a.last_bit, byte)
        })
        .collect();
    if !areas.is_empty() {
        doc.para(text(w::gsd_names_areas(
            lang,
            &i18n::list(lang.into(), &areas),
        )));
    }
}

/// `type 4`, `types 1 and 3`.
fn types_named(lang: Lang, values: &[u8]) -> String {
    let list: Vec<String> = values.iter().map(u8::to_string).collect();
    match list.len() {
        0 => String::new(),
        1 => w::diagnosis_type(lang, &list[0]),
        _ => w::diagnosis_types(lang, &i18n::list(lang.into(), &list)),
    }
}

/// The block's bytes after the standard ones: the header, then what each
/// place holds, for the types that have it.
fn block_rows(g: &Gateway, d: &Diagnosis, lang: Lang) -> Vec<Vec<Cell>> {
    let at = |offset: u8| u16::from(STANDARD_DIAG_BYTES + offset);
    let by_len: Vec<String> = {
        let mut lengths: Vec<u8> = d.types.iter().map(|t| t.len).collect();
        lengths.sort_unstable();
        lengths.dedup();
        lengths
            .iter()
            .map(|&len| {
                let types: Vec<u8> = d
                    .types
                    .iter()
                    .filter(|t| t.len == len)
                    .map(|t| t.value)
                    .collect();
                w::length_of_types(lang, len, &types_named(lang, &types))
            })
            .collect()
    };
    let mut rows = vec![vec![
        text(bytes(lang, at(0), at(0))),
        text(w::diagnosis_header(
            lang,
            &by_len.join(lang.t(w::OR_SEPARATOR)),
        )),
    ]];
    let listed: Vec<u8> = d
        .types
        .iter()
        .filter(|t| matches!(t.code, DiagCode::Listed(_)))
        .map(|t| t.value)
        .collect();
    for offset in 1..d.max_len {
        let mut contents: Vec<String> = Vec::new();
        if offset == d.type_at {
            contents.push(lang.t(w::THE_TYPE).into());
        }
        if offset == d.node_at {
            contents.push(w::the_node(
                lang,
                &g.bus,
                &w::range(lang, g.first_node, g.last_node),
            ));
        }
        if offset == d.code_at && !listed.is_empty() {
            contents.push(w::types_code(lang, &types_named(lang, &listed)));
        }
        for t in &d.types {
            if let DiagCode::Word(name) = &t.code {
                let half = match offset.checked_sub(d.code_at) {
                    Some(0) => lang.t(w::HIGH_BYTE),
                    Some(1) => lang.t(w::LOW_BYTE),
                    _ => continue,
                };
                contents.push(w::type_code_word_half(
                    lang,
                    &types_named(lang, &[t.value]),
                    lang.text(name),
                    half,
                ));
            }
        }
        let content = if contents.is_empty() {
            lang.t(w::NOT_USED).to_string()
        } else {
            contents.join(lang.t(w::PART_SEPARATOR))
        };
        rows.push(vec![
            text(bytes(lang, at(offset), at(offset))),
            text(content),
        ]);
    }
    rows
}

/// The node of the example blocks: the first that is not the gateway.
fn example_node(g: &Gateway) -> u8 {
    (g.first_node..=g.last_node)
        .find(|&n| Some(n) != g.own_node)
        .unwrap_or(g.first_node)
}

fn types_table(doc: &mut Builder, g: &Gateway, d: &Diagnosis, lang: Lang) {
    let node = example_node(g);
    let layout = crate::pkw::gateway_diag_layout(g, d);
    // Blocks as the firmware's encoder makes them.
    let block = |len: u8, kind: u8| firmware::DiagBlock::<64>::new(len, &layout, kind, node);
    let mut rows = Vec::new();
    for t in &d.types {
        match &t.code {
            DiagCode::Listed(set) => {
                for c in &set.choices {
                    // Lowering keeps a listed code within a byte.
                    let value = c.value as u8;
                    let bytes = block(t.len, t.value).with_code_byte(&layout, value);
                    rows.push(vec![
                        text(t.value.to_string()),
                        text(lang.text(&t.text)),
                        text(format!("{} (0x{value:02X})", c.value)),
                        text(lang.text(&c.text)),
                        code(hex_bytes(bytes.as_bytes())),
                    ]);
                }
            }
            DiagCode::Word(name) => {
                // The code word's bytes, found by encoding it three times.
                let with = |code: u16| block(t.len, t.value).with_code_word(&layout, code);
                let base = with(0);
                let high = with(0xFF00);
                let low = with(0x00FF);
                let shown: Vec<String> = base
                    .as_bytes()
                    .iter()
                    .zip(high.as_bytes().iter().zip(low.as_bytes()))
                    .map(|(b, (h, l))| match (b != h, b != l) {
                        (true, _) => "hh".to_string(),
                        (_, true) => "ll".to_string(),
                        _ => format!("{b:02X}"),
                    })
                    .collect();
                rows.push(vec![
                    text(t.value.to_string()),
                    text(lang.text(&t.text)),
                    text(lang.t(w::HHLL)),
                    text(lang.text(name)),
                    code(shown.join(" ")),
                ]);
            }
        }
    }
    doc.table(
        w::diagnosis_types_caption(lang, node),
        &[
            lang.t(w::TYPE),
            lang.t(w::MEANING),
            lang.t(w::FAULT_CODE),
            lang.t(w::FAULT_CODE_MEANING),
            lang.t(w::BLOCK_HEADER_FIRST),
        ],
        rows,
    );
}
