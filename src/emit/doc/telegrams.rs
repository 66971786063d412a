//! The cyclic telegrams: the table of PPO types and PROFINET modules, an
//! overview diagram per bus (a row per module, a box per word), the words of
//! each telegram by name, and the control and status words bit by bit.

use super::page::{code, text, Builder, Cell};
use super::svg::{self, Align, Item, Line, Rect, Style, Svg, Weight};
use super::{bits, bytes, parameter_name, Lang};
use crate::i18n::sheet as w;
use crate::ir::profinet::{self, ModuleKind};
use crate::ir::{
    Allowed, Bus, Direction, EntryKey, Ir, Layout, MappingKind, ModuleId, PkwKind, Word,
};

/// A PPO type or a PROFINET module, named in the page's language.
struct Module<'a> {
    name: String,
    bus: Bus,
    layout: Layout,
    config: Option<&'a [u8]>,
    ident: Option<u32>,
    /// A PROFINET module's own words (standard telegram 1's are PROFIdrive's).
    profinet: Option<&'a profinet::Module>,
}

/// The PPO types and PROFINET modules, named in `lang`.
fn modules(ir: &Ir, lang: Lang) -> Vec<Module<'_>> {
    ir.cyclic_modules()
        .map(|m| Module {
            name: m
                .profinet
                .map_or(m.name, |p| lang.text(&p.name.text))
                .to_string(),
            bus: m.bus,
            layout: m.layout,
            config: match m.id {
                ModuleId::Config(bytes) => Some(bytes),
                ModuleId::IdentNumber(_) => None,
            },
            ident: match m.id {
                ModuleId::Config(_) => None,
                ModuleId::IdentNumber(number) => Some(number),
            },
            profinet: m.profinet,
        })
        .collect()
}

fn direction_name(lang: Lang, direction: Direction) -> &'static str {
    match direction {
        Direction::Out => lang.t(w::MASTER_TO_DRIVE),
        Direction::In => lang.t(w::DRIVE_TO_MASTER),
    }
}

pub(crate) fn section(doc: &mut Builder, ir: &Ir, lang: Lang) {
    let modules = modules(ir, lang);
    if modules.is_empty() {
        return;
    }
    let (heading, caption) = match (ir.profibus.is_some(), ir.profinet.is_some()) {
        (true, false) => (lang.t(w::CYCLIC_PPO), lang.t(w::PPO_TYPES)),
        (false, true) => (lang.t(w::CYCLIC_MODULES), lang.t(w::PROFINET_MODULES)),
        _ => (lang.t(w::CYCLIC_BOTH), lang.t(w::PPO_AND_MODULES)),
    };
    doc.section("telegrams", heading);
    doc.para(text(lang.t(w::TELEGRAMS_INTRO)));
    let rows = modules.iter().map(module_row).collect();
    doc.table(
        caption,
        &[
            lang.t(w::MODULE),
            lang.t(w::BUS),
            lang.t(w::PKW_WORDS),
            lang.t(w::PZD_WORDS),
            lang.t(w::BYTES_EACH_WAY),
            lang.t(w::CONFIG_BYTES_GSD),
            lang.t(w::MODULE_IDENT_GSDML),
        ],
        rows,
    );
    for bus in [Bus::Profibus, Bus::Profinet] {
        let of_bus: Vec<&Module> = modules.iter().filter(|m| m.bus == bus).collect();
        if !of_bus.is_empty() {
            let caption = match bus {
                Bus::Profibus => lang.t(w::PPO_OVERVIEW),
                Bus::Profinet => lang.t(w::MODULES_OVERVIEW),
            };
            doc.figure(caption, overview(ir, lang, &of_bus, caption));
        }
    }
}

fn module_row(m: &Module) -> Vec<Cell> {
    let dash = || text("—");
    vec![
        text(&m.name),
        text(match m.bus {
            Bus::Profibus => "PROFIBUS-DP",
            Bus::Profinet => "PROFINET",
        }),
        text(m.layout.pkw_words().to_string()),
        text(m.layout.pzd_words.to_string()),
        text(m.layout.bytes().to_string()),
        m.config.map_or_else(dash, |c| code(super::hex_bytes(c))),
        m.ident.map_or_else(dash, |i| code(format!("0x{i:08X}"))),
    ]
}

// ---------------------------------------------------------------------------
// The overview: a row per module

const MARGIN: u32 = 8;
const GAP: u32 = 4;
const OVERVIEW_WORD: u32 = 46;

/// The PKW channel's words, short, as the manuals label them.
fn pkw_labels(kind: PkwKind) -> [&'static str; 4] {
    match kind {
        PkwKind::StationCommandAddressValue => ["PKW0", "PKW1", "PKW2", "PKW3"],
        PkwKind::Profidrive => ["PKE", "IND", "PWE1", "PWE2"],
        _ => ["PKE", "IND", "PWE", "PWE"],
    }
}

fn overview(ir: &Ir, lang: Lang, modules: &[&Module], title: &str) -> Svg {
    let name_w = modules
        .iter()
        .map(|m| svg::text_width(&m.name, Weight::Bold))
        .max()
        .unwrap_or(0)
        + 2 * svg::PAD;
    let bytes_label = |m: &Module| w::bytes_count(lang, m.layout.bytes());
    let bytes_w = modules
        .iter()
        .map(|m| svg::text_width(&bytes_label(m), Weight::Normal))
        .max()
        .unwrap_or(0)
        + 2 * svg::PAD;
    let max_words = modules
        .iter()
        .map(|m| u32::from(m.layout.pkw_words() + m.layout.pzd_words))
        .max()
        .unwrap_or(0);
    let row_h = svg::height_for(&[line("PZD", Weight::Bold)]);
    let words_x = MARGIN + name_w + GAP;
    let bytes_x = words_x + max_words * (OVERVIEW_WORD + GAP) + GAP;
    let mut items = Vec::new();
    let mut y = MARGIN;
    for m in modules {
        items.push(slot(
            Rect {
                x: MARGIN,
                y,
                w: name_w,
                h: row_h,
            },
            Align::Start,
            line(&m.name, Weight::Bold),
        ));
        let pkw = if m.layout.pkw {
            pkw_labels(ir.telegram.pkw).to_vec()
        } else {
            Vec::new()
        };
        let pzd = (1..=m.layout.pzd_words).map(|n| format!("PZD{n}"));
        let labels = pkw
            .iter()
            .map(|l| (l.to_string(), Style::Pkw))
            .chain(pzd.map(|l| (l, Style::Pzd)));
        for (i, (label, style)) in labels.enumerate() {
            let x = words_x + i as u32 * (OVERVIEW_WORD + GAP);
            items.push(Item {
                rect: Rect {
                    x,
                    y,
                    w: OVERVIEW_WORD,
                    h: row_h,
                },
                style,
                align: Align::Middle,
                lines: vec![line(&label, Weight::Small)],
            });
        }
        items.push(slot(
            Rect {
                x: bytes_x,
                y,
                w: bytes_w,
                h: row_h,
            },
            Align::Start,
            line(&bytes_label(m), Weight::Normal),
        ));
        y += row_h + GAP + 2;
    }
    Svg {
        kind: "overview",
        width: bytes_x + bytes_w + MARGIN,
        height: y - GAP - 2 + MARGIN,
        title: title.to_string(),
        items,
    }
}

fn line(text: &str, weight: Weight) -> Line {
    Line {
        text: text.to_string(),
        weight,
    }
}

fn slot(rect: Rect, align: Align, line: Line) -> Item {
    Item {
        rect,
        style: Style::Slot,
        align,
        lines: vec![line],
    }
}

// ---------------------------------------------------------------------------
// The words of each telegram

/// A word of a telegram one way (or a gateway node's words): what the
/// diagram's box and the table's row show.
#[derive(Clone, PartialEq, Eq)]
pub(super) struct WordView {
    pub label: String,
    /// What it carries: for a mapped word, its default.
    pub role: String,
    pub mapped: bool,
    /// The drive parameter that sets a mapped word.
    pub parameter: Option<String>,
    pub first_byte: u16,
    pub last_byte: u16,
    pub style: Style,
    /// The columns its box spans in the diagram: 2 for a 32-bit value
    /// (telegram 2's speed), else 1.
    pub columns: u32,
}

fn words(ir: &Ir, lang: Lang, m: &Module, direction: Direction) -> Vec<WordView> {
    let pkw = if m.layout.pkw {
        pkw_words(ir.telegram.pkw, lang, direction)
    } else {
        Vec::new()
    };
    let standard_telegram = m.profinet.filter(|p| p.kind != ModuleKind::Pzd);
    let pzd = match standard_telegram {
        Some(module) => item_views(module, direction, lang),
        None => (1..=m.layout.pzd_words)
            .map(|n| pzd_view(ir, lang, (m.layout, n), direction))
            .collect(),
    };
    pkw.into_iter()
        .enumerate()
        .map(|(i, (label, role))| WordView {
            label: label.to_string(),
            role: role.to_string(),
            mapped: false,
            parameter: None,
            first_byte: 2 * i as u16,
            last_byte: 2 * i as u16 + 1,
            style: Style::Pkw,
            columns: 1,
        })
        .chain(pzd)
        .collect()
}

/// A standard telegram's words as its data items name them: a 32-bit item
/// (telegram 2's NSOLL_B, NIST_B) is one view of two words.
fn item_views(m: &profinet::Module, direction: Direction, lang: Lang) -> Vec<WordView> {
    m.placed_items(direction)
        .map(|(at, item)| {
            // The standard telegrams have no PKW channel: word `at` is PZD at + 1.
            let (first, last) = (at + 1, at + item.words());
            let label = match last == first {
                true => format!("PZD{first}"),
                false => format!("PZD{first}-PZD{last}"),
            };
            let first_byte = m.layout.pzd_word_offset(first);
            WordView {
                label,
                role: lang.text(&item.text.text).to_string(),
                mapped: false,
                parameter: None,
                first_byte,
                last_byte: first_byte + 2 * u16::from(item.words()) - 1,
                style: Style::Pzd,
                columns: u32::from(item.words()),
            }
        })
        .collect()
}

/// PZD word `n` of a module of PZD words: the control or status word, a
/// mapped word, or one no mapping names.
fn pzd_view(ir: &Ir, lang: Lang, (layout, n): (Layout, u8), direction: Direction) -> WordView {
    let (role, parameter, style) = match (n, ir.telegram.word(direction)) {
        (1, Some(word)) => (lang.text(&word.name).to_string(), None, Style::Word),
        _ => match mapped(ir, lang, direction, n) {
            Some((role, parameter)) => (role, Some(parameter), Style::Pzd),
            None => (lang.t(w::NOT_MAPPED).to_string(), None, Style::Pzd),
        },
    };
    let first_byte = layout.pzd_word_offset(n);
    WordView {
        label: format!("PZD{n}"),
        role,
        mapped: parameter.is_some(),
        parameter: parameter.flatten(),
        first_byte,
        last_byte: first_byte + 1,
        style,
        columns: 1,
    }
}

/// A mapped PZD word: what it carries by default, and the drive parameter
/// that sets it; `None` when no mapping names the word.
fn mapped(ir: &Ir, lang: Lang, direction: Direction, n: u8) -> Option<(String, Option<String>)> {
    let kind = match direction {
        Direction::Out => MappingKind::PzdOut,
        Direction::In => MappingKind::PzdIn,
    };
    let (set, entry) = ir
        .mappings
        .group(kind)?
        .entries()
        .find(|(_, e)| e.key == EntryKey { kind, number: n })?;
    let default = match &set.allowed {
        Allowed::Range { .. } => parameter_name(ir, entry.default),
        Allowed::Choices(values) => values
            .choices
            .iter()
            .find(|c| c.value == i64::from(entry.default))
            .map_or_else(
                || entry.default.to_string(),
                |c| lang.text(&c.text).to_string(),
            ),
    };
    Some((default, entry.parameter.map(|p| parameter_name(ir, p))))
}

/// The PKW words one way: label and role.
fn pkw_words(kind: PkwKind, lang: Lang, direction: Direction) -> Vec<(&'static str, &'static str)> {
    let out = direction == Direction::Out;
    match kind {
        PkwKind::None => Vec::new(),
        PkwKind::PkeIndPwe => vec![
            (
                "PKE",
                if out {
                    lang.t(w::ROLE_COMMAND_ADDRESS)
                } else {
                    lang.t(w::ROLE_RESPONSE_ADDRESS)
                },
            ),
            ("IND", lang.t(w::ROLE_ADDRESS_RESERVED)),
            ("PWE", lang.t(w::RESERVED)),
            (
                "PWE",
                if out {
                    lang.t(w::ROLE_VALUE_TO_WRITE)
                } else {
                    lang.t(w::ROLE_VALUE_OR_ERROR_CODE)
                },
            ),
        ],
        PkwKind::Profidrive => vec![
            (
                "PKE",
                if out {
                    lang.t(w::ROLE_REQUEST_ID_PNU)
                } else {
                    lang.t(w::ROLE_RESPONSE_ID_PNU)
                },
            ),
            ("IND", lang.t(w::ROLE_SUBINDEX)),
            ("PWE1", lang.t(w::ROLE_VALUE_HIGH)),
            (
                "PWE2",
                if out {
                    lang.t(w::ROLE_VALUE_LOW)
                } else {
                    lang.t(w::ROLE_VALUE_OR_ERROR_NUMBER)
                },
            ),
        ],
        PkwKind::StationCommandAddressValue => vec![
            ("PKW0", lang.t(w::ROLE_STATIONS)),
            (
                "PKW1",
                if out {
                    lang.t(w::ROLE_COMMAND)
                } else {
                    lang.t(w::ROLE_REPLY)
                },
            ),
            ("PKW2", lang.t(w::ROLE_ADDRESS)),
            (
                "PKW3",
                if out {
                    lang.t(w::ROLE_VALUE_OR_COUNT)
                } else {
                    lang.t(w::ROLE_VALUE_OR_ERROR)
                },
            ),
        ],
    }
}

/// The modules whose words, both ways, begin some longer module's words:
/// a figure each for the longest, listing the others.
fn figure_groups<'m, 'a>(
    ir: &Ir,
    lang: Lang,
    modules: &'m [Module<'a>],
) -> Vec<(&'m Module<'a>, Vec<&'m Module<'a>>)> {
    let both = |m: &Module| {
        [
            words(ir, lang, m, Direction::Out),
            words(ir, lang, m, Direction::In),
        ]
    };
    let mut by_length: Vec<&Module> = modules.iter().collect();
    // Longest first; the sort is stable, so equal lengths keep their order.
    by_length.sort_by_key(|m| std::cmp::Reverse(m.layout.bytes()));
    let mut groups: Vec<(&Module, Vec<&Module>)> = Vec::new();
    for m in by_length {
        let mine = both(m);
        let host = groups.iter_mut().find(|(longest, _)| {
            let theirs = both(longest);
            mine.iter().zip(&theirs).all(|(a, b)| b.starts_with(a))
        });
        match host {
            Some((_, others)) => others.push(m),
            None => groups.push((m, Vec::new())),
        }
    }
    groups
}

pub(crate) fn words_section(doc: &mut Builder, ir: &Ir, lang: Lang) {
    let modules = modules(ir, lang);
    if modules.is_empty() {
        return;
    }
    doc.section_with_intro("words", lang.t(w::WORDS_HEADING), lang.t(w::WORDS_INTRO));
    for (longest, others) in figure_groups(ir, lang, &modules) {
        let mut caption = longest.name.clone();
        if !others.is_empty() {
            let names: Vec<&str> = others.iter().map(|m| m.name.as_str()).collect();
            caption.push_str(&w::also_first_words(
                lang,
                &names.join(lang.t(w::LIST_SEPARATOR)),
            ));
        }
        let out = words(ir, lang, longest, Direction::Out);
        let inn = words(ir, lang, longest, Direction::In);
        let lanes = [
            (direction_name(lang, Direction::Out), &out[..]),
            (direction_name(lang, Direction::In), &inn[..]),
        ];
        doc.figure(
            caption.clone(),
            words_figure(lang, "words", &caption, lanes),
        );
        let rows = out
            .iter()
            .zip(&inn)
            .map(|(o, i)| {
                vec![
                    text(if o.label == i.label {
                        o.label.clone()
                    } else {
                        format!("{} / {}", o.label, i.label)
                    }),
                    text(bytes(lang, o.first_byte, o.last_byte)),
                    text(word_cell(lang, o)),
                    text(word_cell(lang, i)),
                ]
            })
            .collect();
        doc.table(
            caption,
            &[
                lang.t(w::WORD),
                lang.t(w::BYTES),
                direction_name(lang, Direction::Out),
                direction_name(lang, Direction::In),
            ],
            rows,
        );
    }
    for direction in Direction::BOTH {
        if let Some(word) = ir.telegram.word(direction) {
            bits_part(doc, lang, word, direction);
        }
    }
}

fn word_cell(lang: Lang, word: &WordView) -> String {
    match (word.mapped, &word.parameter) {
        (true, Some(p)) => w::default_set_by(lang, &word.role, p),
        (true, None) => w::default_value(lang, &word.role),
        (false, _) => word.role.clone(),
    }
}

const COLUMNS: u32 = 8;
const BOX_W: u32 = 104;
const BOX_GAP: u32 = 6;

/// Two lanes of word boxes, eight words a row, each lane under its title.
pub(super) fn words_figure(
    lang: Lang,
    kind: &'static str,
    title: &str,
    lanes: [(&str, &[WordView]); 2],
) -> Svg {
    let width_of = |columns: u32| columns * BOX_W + (columns - 1) * BOX_GAP;
    let lines_of = |w: &WordView| {
        let inner = width_of(w.columns) - 2 * svg::PAD;
        let mut lines = vec![line(&w.label, Weight::Bold)];
        lines.extend(
            svg::wrap(&w.role, inner, Weight::Normal, 3)
                .iter()
                .map(|l| line(l, Weight::Normal)),
        );
        if let Some(parameter) = &w.parameter {
            lines.push(line(parameter, Weight::Small));
        }
        lines.push(line(&bytes(lang, w.first_byte, w.last_byte), Weight::Small));
        lines
    };
    let box_h = lanes
        .iter()
        .flat_map(|(_, words)| words.iter())
        .map(|w| svg::height_for(&lines_of(w)))
        .max()
        .unwrap_or(0);
    let title_h = svg::height_for(&[line("X", Weight::Bold)]);
    let mut items = Vec::new();
    let mut y = MARGIN;
    for (name, words) in lanes {
        let w = svg::text_width(name, Weight::Bold) + 2 * svg::PAD;
        items.push(slot(
            Rect {
                x: MARGIN,
                y,
                w,
                h: title_h,
            },
            Align::Start,
            line(name, Weight::Bold),
        ));
        y += title_h + 2;
        let (mut row, mut col) = (0, 0);
        for word in words {
            let span = word.columns.clamp(1, COLUMNS);
            if col + span > COLUMNS {
                (row, col) = (row + 1, 0);
            }
            items.push(Item {
                rect: Rect {
                    x: MARGIN + col * (BOX_W + BOX_GAP),
                    y: y + row * (box_h + BOX_GAP),
                    w: width_of(span),
                    h: box_h,
                },
                style: word.style,
                align: Align::Middle,
                lines: lines_of(word),
            });
            col += span;
        }
        let rows = if words.is_empty() { 0 } else { row + 1 };
        y += rows * (box_h + BOX_GAP) + 8;
    }
    Svg {
        kind,
        width: 2 * MARGIN + width_of(COLUMNS),
        height: y - 8 - BOX_GAP + MARGIN,
        title: title.to_string(),
        items,
    }
}

// ---------------------------------------------------------------------------
// Control and status words

fn bits_part(doc: &mut Builder, lang: Lang, word: &Word, direction: Direction) {
    let name = lang.text(&word.name);
    let caption = w::bit_by_bit(lang, name, direction_name(lang, direction));
    doc.figure(caption.clone(), bits_figure(lang, &caption, word));
    let rows = word
        .bits
        .iter()
        .map(|b| {
            let values = b.values.as_ref().map_or_else(
                || lang.t(w::ONE_YES_ZERO_NO).to_string(),
                |v| {
                    v.choices
                        .iter()
                        .map(|c| format!("{} = {}", c.value, lang.text(&c.text)))
                        .collect::<Vec<_>>()
                        .join("; ")
                },
            );
            vec![
                text(bits(lang, b.first.into(), b.last.into())),
                text(lang.text(&b.name)),
                text(values),
            ]
        })
        .collect();
    doc.table(
        caption,
        &[lang.t(w::BITS), lang.t(w::NAME), lang.t(w::VALUES)],
        rows,
    );
}

/// Two rows of eight bits, the high byte above, bit 15 leftmost as the
/// manuals draw words; a field crossing the bytes is a box in each row.
fn bits_figure(lang: Lang, title: &str, word: &Word) -> Svg {
    let inner_of = |n: u32| n * BOX_W + (n - 1) * BOX_GAP - 2 * svg::PAD;
    // (first bit, last bit, field) of each run within a byte, fields and gaps alike.
    let mut parts: Vec<(u8, u8, Option<usize>)> = Vec::new();
    for byte in [1u8, 0] {
        for bit in (8 * byte..8 * byte + 8).rev() {
            let field = word
                .bits
                .iter()
                .position(|b| (b.first..=b.last).contains(&bit));
            match parts.last_mut() {
                Some((first, _, last_field))
                    if field.is_some() && *last_field == field && bit % 8 != 7 =>
                {
                    *first = bit
                }
                _ => parts.push((bit, bit, field)),
            }
        }
    }
    let name = |field: Option<usize>| field.map(|f| lang.text(&word.bits[f].name));
    let lines_of = |&(first, last, field): &(u8, u8, Option<usize>)| -> Vec<Line> {
        let width = inner_of(u32::from(last - first) + 1);
        name(field).map_or_else(Vec::new, |n| {
            svg::wrap(n, width, Weight::Normal, 3)
                .iter()
                .map(|l| line(l, Weight::Normal))
                .collect()
        })
    };
    let box_h = parts
        .iter()
        .map(|p| svg::height_for(&lines_of(p)))
        .max()
        .unwrap_or(0)
        .max(32);
    let number_h = svg::height_for(&[line("15", Weight::Small)]);
    let col_x = |bit: u8| MARGIN + (7 - u32::from(bit % 8)) * (BOX_W + BOX_GAP);
    let row_y =
        |bit: u8| MARGIN + u32::from(1 - bit / 8) * (number_h + box_h + BOX_GAP + 4) + number_h;
    let mut items = Vec::new();
    for bit in 0..16u8 {
        let number = w::bit(lang, bit);
        items.push(slot(
            Rect {
                x: col_x(bit),
                y: row_y(bit) - number_h,
                w: BOX_W,
                h: number_h,
            },
            Align::Middle,
            line(&number, Weight::Small),
        ));
    }
    for part in &parts {
        let &(first, last, field) = part;
        let n = u32::from(last - first) + 1;
        items.push(Item {
            rect: Rect {
                x: col_x(last),
                y: row_y(first),
                w: n * BOX_W + (n - 1) * BOX_GAP,
                h: box_h,
            },
            style: if field.is_some() {
                Style::Word
            } else {
                Style::Reserved
            },
            align: Align::Middle,
            lines: lines_of(part),
        });
    }
    Svg {
        kind: "bits",
        width: 2 * MARGIN + COLUMNS * BOX_W + (COLUMNS - 1) * BOX_GAP,
        height: row_y(0) + box_h + MARGIN,
        title: title.to_string(),
        items,
    }
}
