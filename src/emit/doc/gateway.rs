//! A gateway (MD810's bridge mode): the second bus and its nodes, the data
//! limits and order, the modules, a worked example (nodes, modules,
//! parameter telegram and a diagram of the data), and the diagnosis block
//! by type with the block each code gives, encoded by the firmware's code.

use super::page::{code, text, Builder, Cell, Run};
use super::svg::Style;
use super::telegrams::{words_figure, WordView};
use super::{bytes, decision_mark, hex_bytes, Lang};
use crate::ir::gateway::{DataOrder, DiagCode, Diagnosis, Gateway, Module, Node, ParamKey};
use crate::ir::profibus::{PrmValue, Profibus, STANDARD_DIAG_BYTES};
use crate::ir::{Direction, Ir};
use crate::pkw::support::gateway as firmware;

pub(crate) fn section(doc: &mut Builder, ir: &Ir, lang: Lang) {
    let (Some(g), Some(p)) = (&ir.gateway, &ir.profibus) else {
        return;
    };
    let bus = &g.bus;
    doc.section(
        "gateway",
        lang.f(
            format!("Cyclic data: the {bus} nodes' words"),
            format!("周期数据：{bus} 节点的字"),
        ),
    );
    let own = g.own_node.map_or_else(String::new, |n| {
        lang.f(
            format!(", the gateway itself being node {n}"),
            format!("，网桥本身为节点 {n}"),
        )
    });
    doc.para(text(lang.f(
        format!("The card is a gateway to {bus}: it carries the data of the {bus} nodes {} to {}{own}. The master sets in the parameter telegram how many nodes are in use and how many words each one sends (the master's input) and receives (its output), and plugs modules until its input and output equal the nodes' totals. Every word is 16 bits, high byte first.", g.first_node, g.last_node),
        format!("本卡为 {bus} 网桥：传送 {bus} 节点 {}～{} 的数据{own}。主站在参数报文中设定使用的节点数及每个节点发送（主站输入）和接收（主站输出）的字数，并插入模块，直至输入、输出长度等于各节点的总和。每个字 16 位，高字节在前。", g.first_node, g.last_node),
    )));
    facts_table(doc, ir, g, lang);
    modules_part(doc, ir, g, lang);
    if let Some(example) = Example::of(g) {
        example_part(doc, ir, g, p, &example, lang);
    }
}

fn range(lang: Lang, min: impl std::fmt::Display, max: impl std::fmt::Display) -> String {
    lang.f(format!("{min} to {max}"), format!("{min}～{max}"))
}

fn way(lang: Lang, direction: Direction) -> &'static str {
    match direction {
        Direction::In => lang.t("input, nodes → master", "输入，节点 → 主站"),
        Direction::Out => lang.t("output, master → nodes", "输出，主站 → 节点"),
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
        lang.f(
            format!(
                "{} (\"{}\" and on)",
                range(lang, first.min, first.max),
                lang.text(&first.name)
            ),
            format!(
                "{}（“{}”等）",
                range(lang, first.min, first.max),
                lang.text(&first.name)
            ),
        )
    };
    let order = match g.data_order {
        DataOrder::NodeAscending => lang.t(
            "the nodes in use in ascending node number, each node's words together",
            "使用中的节点按节点号升序排列，每个节点的字连续排列",
        ),
    };
    let mut rows = vec![
        (lang.t("Second bus", "第二总线"), text(&g.bus)),
        (
            lang.t("Node numbers", "节点号"),
            text(range(lang, g.first_node, g.last_node)),
        ),
    ];
    if let Some(own) = g.own_node {
        rows.push((
            lang.t("The gateway's own node", "网桥本身的节点号"),
            text(own.to_string()),
        ));
    }
    rows.extend([
        (lang.t("Nodes in use", "使用的节点数"), {
            let mut cell = text(lang.f(
                format!(
                    "{} (\"{}\"), default {}",
                    range(lang, count.min, count.max),
                    lang.text(&count.name),
                    count.default
                ),
                format!(
                    "{}（“{}”），默认值 {}",
                    range(lang, count.min, count.max),
                    lang.text(&count.name),
                    count.default
                ),
            ));
            cell.extend(mark(ir, lang, "gateway.node_count.default"));
            cell
        }),
        (
            lang.t("Words a node sends (input)", "每个节点发送的字数（输入）"),
            marked(ir, lang, words(Direction::In), "gateway.input_words"),
        ),
        (
            lang.t(
                "Words a node receives (output)",
                "每个节点接收的字数（输出）",
            ),
            marked(ir, lang, words(Direction::Out), "gateway.output_words"),
        ),
        (
            lang.t(
                "Input bytes at most (Max_Input_Len)",
                "最大输入字节数（Max_Input_Len）",
            ),
            text(g.max_input_len.to_string()),
        ),
        (
            lang.t(
                "Output bytes at most (Max_Output_Len)",
                "最大输出字节数（Max_Output_Len）",
            ),
            text(g.max_output_len.to_string()),
        ),
        (
            lang.t("The nodes' words in the data", "各节点的字在数据中的顺序"),
            marked(ir, lang, order.to_string(), "gateway.data_order"),
        ),
        (
            lang.t("Modules at most (Max_Module)", "最多模块数（Max_Module）"),
            text(g.max_modules.to_string()),
        ),
    ]);
    doc.table(
        lang.f(
            format!("The gateway to {}", g.bus),
            format!("{} 网桥", g.bus),
        ),
        &[lang.t("Item", "项目"), lang.t("Value", "值")],
        rows.into_iter().map(|(k, v)| vec![text(k), v]).collect(),
    );
}

fn modules_part(doc: &mut Builder, ir: &Ir, g: &Gateway, lang: Lang) {
    doc.subsection("gateway-modules", lang.t("Modules", "模块"));
    let mut intro = text(lang.f(
        format!("Each module is a block of words one way, with one config identifier byte (Chk_Cfg): bit 7 consistency, bit 6 words, bits 5-4 the direction (01 input, 10 output), bits 3-0 the words less one. The master plugs modules, at most {}, until their input words equal the words the nodes in use send and their output words the words they receive.", g.max_modules),
        format!("每个模块为一个方向的若干字，对应一个配置标识字节（Chk_Cfg）：位 7 一致性，位 6 字，位 5-4 方向（01 输入，10 输出），位 3-0 字数减 1。主站插入模块（最多 {} 个），使输入字数等于使用中的节点发送的字数，输出字数等于其接收的字数。", g.max_modules),
    ));
    if let Some(mark) = decision_mark(ir, lang, "gateway.modules") {
        intro.push(Run::Text(
            lang.t(" The module sizes: ", "模块大小：").into(),
        ));
        intro.push(mark);
        intro.push(Run::Text(lang.t(".", "。").into()));
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
                    lang.t("the whole module", "整个模块")
                } else {
                    lang.t("each word on its own", "按字")
                }),
            ]
        })
        .collect();
    doc.table(
        lang.t("The modules", "模块"),
        &[
            lang.t("Module", "模块"),
            lang.t("Direction", "方向"),
            lang.t("Words", "字数"),
            lang.t("Bytes", "字节数"),
            lang.t("Config byte", "配置字节"),
            lang.t("Consistency", "一致性"),
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
    doc.subsection("gateway-example", lang.t("An example", "示例"));
    let (input, output) = (example.words(Direction::In), example.words(Direction::Out));
    let first = &g.nodes[0];
    let receiving = example
        .node_words(Direction::Out)
        .filter(|&(_, w)| w > 0)
        .count();
    doc.para(text(lang.f(
        format!(
            "An example gsdc computes from the description: {} nodes in use, each sending its most words ({}), as many nodes as {} bytes of input hold; the first {receiving} of them also receive their most words ({}). That is {input} words ({} bytes) of input and {output} words ({} bytes) of output. The master plugs the modules and sends the parameter telegram of the tables below.",
            example.count(), first.input_words.max, g.max_input_len, first.output_words.max, 2 * input, 2 * output
        ),
        format!(
            "以下示例由 gsdc 根据设备描述计算：使用 {} 个节点，每个节点发送最多的字数（{}），节点数为 {} 字节输入所能容纳的最多节点数；其中前 {receiving} 个节点还接收最多的字数（{}）。即输入 {input} 个字（{} 字节），输出 {output} 个字（{} 字节）。主站插入下表的模块，并发送下表的参数报文。",
            example.count(), first.input_words.max, g.max_input_len, first.output_words.max, 2 * input, 2 * output
        ),
    )));
    example_nodes_table(doc, g, example, lang);
    let caption = lang.t(
        "The example's data: each node's words in the data order",
        "示例的数据：各节点的字按数据顺序排列",
    );
    let lanes = [Direction::In, Direction::Out].map(|direction| {
        let boxes = example
            .places(g, direction)
            .into_iter()
            .map(|(node, words, first, last)| WordView {
                label: lang.f(format!("node {node}"), format!("节点 {node}")),
                role: lang.f(format!("{words} words"), format!("{words} 个字")),
                mapped: false,
                parameter: None,
                first_byte: first,
                last_byte: last,
                style: Style::Pzd,
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
        text(lang.t("all", "合计")),
        text(total(Direction::In).to_string()),
        text(lang.f(
            format!("{} bytes", 2 * total(Direction::In)),
            format!("{} 字节", 2 * total(Direction::In)),
        )),
        text(total(Direction::Out).to_string()),
        text(lang.f(
            format!("{} bytes", 2 * total(Direction::Out)),
            format!("{} 字节", 2 * total(Direction::Out)),
        )),
    ]);
    doc.table(
        lang.t("The example's nodes", "示例的节点"),
        &[
            lang.t("Node", "节点"),
            lang.t("Words sent", "发送字数"),
            lang.t("In the input data", "在输入数据中"),
            lang.t("Words received", "接收字数"),
            lang.t("In the output data", "在输出数据中"),
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
            text(names.join(lang.t(", ", "、"))),
            code(hex_bytes(&config)),
        ]);
    }
    doc.table(
        lang.t(
            "The modules the master plugs for the example",
            "示例中主站插入的模块",
        ),
        &[
            lang.t("Direction", "方向"),
            lang.t("Words", "字数"),
            lang.t("Modules, fewest", "模块（最少）"),
            lang.t("Config bytes (Chk_Cfg)", "配置字节（Chk_Cfg）"),
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
        lang.f(
            format!("User_Prm_Data of the example, {} bytes", bytes_of.len()),
            format!("示例的 User_Prm_Data，{} 字节", bytes_of.len()),
        ),
        &[lang.t("Bytes", "字节"), lang.t("Hex", "十六进制")],
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
    doc.section("diagnosis", lang.t("Diagnosis", "诊断"));
    doc.para(text(lang.f(
        format!("The master reads the slave's diagnosis (STEP 7: SFC13): {STANDARD_DIAG_BYTES} standard bytes, then the device-related block: its header (bits 7-6 = 00, bits 5-0 = the block's length, the header included), the type, the {} node and the code, whose meaning depends on the type.", g.bus),
        format!("主站读取从站诊断数据（STEP 7：SFC13）：{STANDARD_DIAG_BYTES} 个标准字节，之后是设备专用诊断块：块头（位 7-6 = 00，位 5-0 = 块长度，含块头）、类型、{} 节点号和故障码，故障码的含义取决于类型。", g.bus),
    )));
    let mut rows = super::params::standard_diagnosis_rows(p, lang);
    rows.extend(block_rows(g, d, lang));
    doc.table(
        lang.t("The diagnosis, byte by byte", "诊断数据各字节"),
        &[lang.t("Byte", "字节"), lang.t("Content", "内容")],
        rows,
    );
    types_table(doc, g, d, lang);
    let areas: Vec<String> = d
        .gsd_areas
        .iter()
        .map(|a| {
            let byte = u16::from(STANDARD_DIAG_BYTES) + 1 + a.first_bit / 8;
            lang.f(
                format!("bits {}-{} (byte {byte})", a.first_bit, a.last_bit),
                format!("位 {}-{}（字节 {byte}）", a.first_bit, a.last_bit),
            )
        })
        .collect();
    if !areas.is_empty() {
        doc.para(text(lang.f(
            format!("The GSD names the values of Unit_Diag_Area {}, counted from the byte after the header, so an engineering tool shows the type and the listed codes as text.", areas.join(" and ")),
            format!("GSD 文件为 Unit_Diag_Area {}的取值命名（位从块头后一个字节算起），组态软件以文本显示类型和列出的故障码。", areas.join("、")),
        )));
    }
}

/// `type 4`, `types 1 and 3`.
fn types_named(lang: Lang, values: &[u8]) -> String {
    let list: Vec<String> = values.iter().map(u8::to_string).collect();
    match (list.split_last(), lang) {
        (_, Lang::Zh) => format!("类型 {}", list.join("、")),
        (Some((last, [])), _) => format!("type {last}"),
        (Some((last, rest)), _) => format!("types {} and {last}", rest.join(", ")),
        (None, _) => String::new(),
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
                lang.f(
                    format!("{len:02X} ({})", types_named(lang, &types)),
                    format!("{len:02X}（{}）", types_named(lang, &types)),
                )
            })
            .collect()
    };
    let mut rows = vec![vec![
        text(bytes(lang, at(0), at(0))),
        text(lang.f(
            format!("header: the block's length, {}", by_len.join(" or ")),
            format!("块头：块长度 {}", by_len.join("或 ")),
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
            contents.push(lang.t("the type (table below)", "类型（见下表）").into());
        }
        if offset == d.node_at {
            contents.push(lang.f(
                format!(
                    "the {} node, {}",
                    g.bus,
                    range(lang, g.first_node, g.last_node)
                ),
                format!(
                    "{} 节点号，{}",
                    g.bus,
                    range(lang, g.first_node, g.last_node)
                ),
            ));
        }
        if offset == d.code_at && !listed.is_empty() {
            contents.push(lang.f(
                format!("{}: the code", types_named(lang, &listed)),
                format!("{}：故障码", types_named(lang, &listed)),
            ));
        }
        for t in &d.types {
            if let DiagCode::Word(name) = &t.code {
                let half = match offset.checked_sub(d.code_at) {
                    Some(0) => lang.t("high byte", "高字节"),
                    Some(1) => lang.t("low byte", "低字节"),
                    _ => continue,
                };
                contents.push(format!(
                    "{}{}{}{}",
                    types_named(lang, &[t.value]),
                    lang.t(": ", "："),
                    lang.text(name),
                    lang.f(format!(", {half}"), format!("，{half}"))
                ));
            }
        }
        let content = if contents.is_empty() {
            lang.t("not used", "未使用").to_string()
        } else {
            contents.join(lang.t("; ", "；"))
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
                    text(lang.t("hhll: 16 bits, high byte first", "hhll：16 位，高字节在前")),
                    text(lang.text(name)),
                    code(shown.join(" ")),
                ]);
            }
        }
    }
    doc.table(
        lang.f(
            format!("Diagnosis types and codes, with the block each gives at node {node}"),
            format!("诊断类型与故障码，及节点 {node} 报出的诊断块"),
        ),
        &[
            lang.t("Type", "类型"),
            lang.t("Meaning", "含义"),
            lang.t("Code", "故障码"),
            lang.t("Meaning of the code", "故障码含义"),
            lang.t("Block, header first", "诊断块（含块头）"),
        ],
        rows,
    );
}
