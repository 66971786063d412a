//! A gateway's GSD written back as `[gateway]`: a card that carries the
//! data of the nodes of a second bus (MD810's bridge mode). Its modules are
//! blocks of words one way each, the same sizes both ways; its
//! User_Prm_Data is the count of nodes in use, then each node's input and
//! output words, named with the node's number; its diagnosis areas show the
//! types and the listed codes. Which type a code belongs to, and what a
//! type of a 16-bit code carries, no keyword says: gsdc's GSD says it in the
//! comments above the areas, which are read here; a file without them is
//! refused.

use super::numbered::{pattern, Pattern};
use super::toml_out::{list, quote, TomlOut};
use super::Notes;
use crate::device::dp::{DiagArea, DpDevice};
use crate::device::{Allowed, Field, Text, Value};
use crate::gsd::config::{identifiers, Direction, Identifier};

/// A gateway's GSD as the description says it.
pub(super) struct Gateway {
    first_node: u8,
    last_node: u8,
    max_input_len: i64,
    max_output_len: i64,
    node_count: Param,
    input_words: NodeWords,
    output_words: NodeWords,
    module_words: Vec<u8>,
    consistent: bool,
    diagnosis: Vec<DiagType>,
    /// One node only: its parameters' names do not show which number is
    /// the node's (the first is taken).
    one_node: bool,
}

/// The node count's parameter, or one direction's words of every node.
struct Param {
    /// As the description writes it: quoted, `{n}` standing for the node.
    name: String,
    /// `type` or `bits`, and its value ([`super::prm::stored_as`]).
    stored_as: (&'static str, String),
    range: (i128, i128),
    default: i128,
}

struct NodeWords {
    param: Param,
    defaults: Vec<i128>,
}

struct DiagType {
    value: i64,
    text: String,
    code: DiagCode<(i64, String)>,
}

/// A type's code: one byte of the listed values (with their texts once
/// the area's are read), or a 16-bit number of this meaning.
enum DiagCode<C> {
    Listed(Vec<C>),
    Word(String),
}

/// The file read as a gateway's: `Err(None)` when its modules are not
/// blocks of words one way each (not a gateway's GSD), `Err(Some(why))`
/// when they are but another part has no place in `[gateway]`.
pub(super) fn read(device: &DpDevice, notes: &mut Notes) -> Result<Gateway, Option<String>> {
    let WordBlocks {
        sizes,
        consistent,
        each,
    } = word_blocks(device).ok_or(None)?;
    let prm = &device.user_prm_data;
    let [count, words @ ..] = prm.fields.as_slice() else {
        return Err(Some(
            "a gateway's User_Prm_Data has the count of nodes in use first".into(),
        ));
    };
    if words.is_empty() || words.len() % 2 != 0 || !prm.consts.is_empty() {
        return Err(Some(
            "a gateway's User_Prm_Data is the node count, then each node's input and output words, and no constant bytes".into(),
        ));
    }
    let inputs: Vec<&Field> = words.iter().step_by(2).collect();
    let outputs: Vec<&Field> = words.iter().skip(1).step_by(2).collect();
    let (input_words, first_in) = node_words(&inputs)?;
    let (output_words, first_out) = node_words(&outputs)?;
    // Node numbers are bytes in the description and the layouts.
    let last = u32::try_from(inputs.len() - 1)
        .ok()
        .and_then(|n| first_in.checked_add(n));
    let (Some(first_node), Some(last_node)) = (
        u8::try_from(first_in)
            .ok()
            .filter(|_| first_in == first_out),
        last.and_then(|l| u8::try_from(l).ok()),
    ) else {
        return Err(Some(
            "the input and output words' names number the nodes differently, or past 255".into(),
        ));
    };
    let length = |keyword| {
        device
            .keyword(keyword)
            .and_then(|k| k.value.as_number())
            .ok_or_else(|| Some(format!("a gateway's GSD states {keyword}")))
    };
    let gateway = Gateway {
        first_node,
        last_node,
        max_input_len: length("Max_Input_Len")?,
        max_output_len: length("Max_Output_Len")?,
        node_count: param(count, &quote(&count.name.primary))?,
        input_words,
        output_words,
        module_words: sizes,
        consistent,
        diagnosis: diagnosis(device, notes)?,
        one_node: inputs.len() == 1,
    };
    module_names(device, &each, notes);
    Ok(gateway)
}

/// W600 for each module not named as gsdc names a gateway's word blocks:
/// the description has no key for their names.
fn module_names(device: &DpDevice, each: &[(crate::ir::Direction, u8)], notes: &mut Notes) {
    for (m, &(direction, words)) in device.modules.iter().zip(each) {
        let gsdc = crate::lower::gateway_module_name(direction, words);
        if m.name != gsdc {
            notes.unsaid(
                &format!("module name \"{}\"", m.name),
                &m.place,
                &format!("gsdc names a gateway's word blocks itself: \"{gsdc}\""),
            );
        }
    }
}

/// A gateway's modules: the sizes offered (the same each way), whether
/// each is consistent as a whole, and each module's direction and words.
struct WordBlocks {
    sizes: Vec<u8>,
    consistent: bool,
    each: Vec<(crate::ir::Direction, u8)>,
}

/// The modules as a gateway's word blocks: every module one general
/// identifier of words one way, the same sizes each way, all alike
/// consistent.
fn word_blocks(device: &DpDevice) -> Option<WordBlocks> {
    let mut each = Vec::new();
    let mut consistent = Vec::new();
    for m in &device.modules {
        let ids = identifiers(&m.config).ok()?;
        let [Identifier::General { direction, data }] = ids.as_slice() else {
            return None;
        };
        let direction = match direction {
            Direction::Input => crate::ir::Direction::In,
            Direction::Output => crate::ir::Direction::Out,
            Direction::Both => return None,
        };
        if !data.words || !m.user_prm_data.is_empty() {
            return None;
        }
        each.push((direction, data.count));
        consistent.push(data.consistent);
    }
    let sizes = |way: crate::ir::Direction| -> Vec<u8> {
        let mut sizes: Vec<u8> = each
            .iter()
            .filter(|(d, _)| *d == way)
            .map(|(_, words)| *words)
            .collect();
        sizes.sort_unstable();
        sizes
    };
    let input = sizes(crate::ir::Direction::In);
    let first = *consistent.first()?;
    let alike = consistent.iter().all(|c| *c == first);
    (input == sizes(crate::ir::Direction::Out) && alike).then_some(WordBlocks {
        sizes: input,
        consistent: first,
        each,
    })
}

/// One direction's parameters of every node: one name with the node's
/// number in it, one range, and each node's default; and the first node's
/// number.
fn node_words(fields: &[&Field]) -> Result<(NodeWords, u32), Option<String>> {
    let names: Vec<&Text> = fields.iter().map(|f| &f.name).collect();
    let Pattern { name, first } = pattern(&names).ok_or_else(|| {
        Some(format!(
            "the node parameters \"{}\" .. are not one name numbered by node",
            names.first().map_or("", |n| &n.primary)
        ))
    })?;
    let params: Vec<Param> = fields
        .iter()
        .map(|f| param(f, &name))
        .collect::<Result<_, _>>()?;
    let defaults = params.iter().map(|p| p.default).collect();
    let mut params = params.into_iter();
    let param = params.next().ok_or(None)?;
    if !params.all(|p| p.stored_as == param.stored_as && p.range == param.range) {
        return Err(Some(format!(
            "the node parameters {name} differ in type or range from node to node"
        )));
    }
    Ok((NodeWords { param, defaults }, first))
}

/// A gateway parameter: a byte, a word or bits of a byte, one range of
/// values, its default, nothing else.
fn param(f: &Field, name: &str) -> Result<Param, Option<String>> {
    let why = |what: &str| {
        Some(format!(
            "the gateway parameter \"{}\" {what}",
            f.name.primary
        ))
    };
    let stored_as = super::prm::stored_as(f).ok_or_else(|| {
        why(&format!(
            "is of type {}, not a byte, a word or bits of one byte",
            f.data_type
        ))
    })?;
    let range = match &f.allowed {
        Allowed::Ranges(r) => match r.as_slice() {
            [(Value::Int(min), Value::Int(max))] => (*min, *max),
            _ => return Err(why("takes other values than one range")),
        },
        Allowed::Any => return Err(why("gives no range")),
    };
    let default = match f.default {
        Some(Value::Int(d)) => d,
        _ => return Err(why("has no default")),
    };
    if !f.choices.is_empty() || !f.changeable || !f.visible || !f.attributes.is_empty() {
        return Err(why("has texts, attributes or is fixed or hidden"));
    }
    Ok(Param {
        name: name.to_string(),
        stored_as,
        range,
        default,
    })
}

/// The types of the area of bits 0-7 and the codes of the area of bits
/// 16-23, each type's code as the comments above the areas say it.
fn diagnosis(device: &DpDevice, notes: &Notes) -> Result<Vec<DiagType>, Option<String>> {
    let d = &device.diagnosis;
    if !d.bits.is_empty() || !d.types.is_empty() || !d.channel.is_empty() {
        return Err(Some(
            "a gateway's diagnosis is its areas of type and code, no bits or diagnosis types"
                .into(),
        ));
    }
    let area = |first: i64| {
        d.areas
            .iter()
            .find(|a| a.first == first && a.last == first + 7)
    };
    let (Some(types), codes) = (area(0), area(16)) else {
        return match d.areas.is_empty() {
            true => Ok(Vec::new()),
            false => Err(Some(
                "a gateway's diagnosis shows its types in bits 0-7".into(),
            )),
        };
    };
    if d.areas.len() != 1 + usize::from(codes.is_some()) {
        return Err(Some(
            "a gateway's diagnosis has an area of types (bits 0-7) and one of codes (bits 16-23)"
                .into(),
        ));
    }
    let mut said = codes_said(&note_above(types, notes, TYPES_NOTE))?;
    if let Some(codes) = codes {
        let note = note_above(codes, notes, CODES_NOTE);
        if note.is_empty() {
            return Err(Some(format!("no comment above the codes' area (bits 16-23) says which type each code belongs to, as gsdc's GSD does (`{CODES_NOTE}type 1 (35, 34) ...`)")));
        }
        said.extend(codes_said(&note)?);
    }
    let text_of = |value: i64| -> Option<String> {
        codes?
            .values
            .iter()
            .find(|v| v.value == value)
            .map(|v| v.text.primary.to_string())
    };
    types
        .values
        .iter()
        .map(|t| {
            let code = match said.iter().find(|(v, _)| *v == t.value) {
                Some((_, DiagCode::Listed(values))) => DiagCode::Listed(
                    values
                        .iter()
                        .map(|&v| text_of(v).map(|text| (v, text)).ok_or_else(|| missing(v)))
                        .collect::<Result<_, _>>()?,
                ),
                Some((_, DiagCode::Word(name))) => DiagCode::Word(name.clone()),
                None => return Err(unsaid_type(t.value)),
            };
            Ok(DiagType {
                value: t.value,
                text: t.text.primary.to_string(),
                code,
            })
        })
        .collect()
}

/// How gsdc's notes above the types' and the codes' areas begin.
const TYPES_NOTE: &str = "The type of the diagnosis";
const CODES_NOTE: &str = "The code of ";

/// The note gsdc writes above an area, from its first words on (the
/// comment lines above it joined, as they were wrapped); empty without.
fn note_above(area: &DiagArea, notes: &Notes, start: &str) -> String {
    let comment = notes.comments_above(&area.place).join(" ");
    comment
        .find(start)
        .map_or(String::new(), |at| comment[at..].to_string())
}

fn missing(code: i64) -> Option<String> {
    Some(format!(
        "the comment above the codes' area names code {code}, which the area does not list"
    ))
}

fn unsaid_type(value: i64) -> Option<String> {
    Some(format!(
        "no comment above its diagnosis areas says what code type {value} carries, as gsdc's GSD says it"
    ))
}

/// What a note says of the types' codes, read back: `The code of type 1
/// (35, 34) and type 3 (32)`, each listed code's type; `type 4 carries the
/// high byte of its 16-bit code (Drive fault code) here` or `type 4 carries
/// a 16-bit code (Drive fault code) in bits 16-31`, a type's 16-bit code.
fn codes_said(note: &str) -> Result<Vec<(i64, DiagCode<i64>)>, Option<String>> {
    let unread = |what: &str| {
        Some(format!(
            "the comment above a diagnosis area does not read as gsdc's: \"{what}\""
        ))
    };
    let mut said = Vec::new();
    for sentence in note.split("; ") {
        if let Some(listed) = sentence.strip_prefix(CODES_NOTE) {
            if listed.starts_with("types ") {
                return Err(Some(format!("the comment above the codes' area, \"{sentence}\", is an older gsdc's, which does not say which type each code belongs to: build the description again and import that")));
            }
            for item in listed.split("type ").skip(1) {
                let read = item.split_once(" (").and_then(|(value, rest)| {
                    let codes = rest.split_once(')')?.0.split(", ");
                    let codes = codes.map(|c| c.parse().ok()).collect::<Option<_>>()?;
                    Some((value.parse().ok()?, DiagCode::Listed(codes)))
                });
                said.push(read.ok_or_else(|| unread(sentence))?);
            }
        } else if let Some(word) = sentence.strip_prefix("type ") {
            // The code's meaning is in the parentheses after `code (`.
            let read = word.split_once(" carries ").and_then(|(value, rest)| {
                let (_, meaning) = rest.split_once("code (")?;
                let meaning = &meaning[..meaning.rfind(')')?];
                Some((value.parse().ok()?, DiagCode::Word(meaning.to_string())))
            });
            said.push(read.ok_or_else(|| unread(sentence))?);
        } else if sentence != TYPES_NOTE {
            return Err(unread(sentence));
        }
    }
    Ok(said)
}

/// `[gateway]` and its tables; and under `[choices]` what the GSD does not
/// say, with a warning each (W600).
pub(super) fn write(out: &mut TomlOut, g: &Gateway, file: &str, notes: &mut Notes) {
    out.table("gateway");
    out.string("bus", UNNAMED_BUS);
    out.key("nodes", format!("[{}, {}]", g.first_node, g.last_node));
    out.key("max_input_len", g.max_input_len);
    out.key("max_output_len", g.max_output_len);
    out.string("data_order", "node-ascending");
    out.table("gateway.node_count");
    write_param(out, &g.node_count);
    out.key("default", g.node_count.default);
    for (table, words) in [
        ("gateway.input_words", &g.input_words),
        ("gateway.output_words", &g.output_words),
    ] {
        out.table(table);
        write_param(out, &words.param);
        match words.defaults.as_slice() {
            [first, rest @ ..] if rest.iter().all(|d| d == first) => out.key("default", first),
            all => out.key("defaults", list(all)),
        }
    }
    out.table("gateway.modules");
    out.key("words", list(&g.module_words));
    out.key("consistent", g.consistent);
    for t in &g.diagnosis {
        out.array_item("gateway.diagnosis.types");
        out.key("value", t.value);
        out.string("text", &t.text);
        match &t.code {
            DiagCode::Listed(codes) => {
                let codes = codes
                    .iter()
                    .map(|(v, text)| format!("{{ value = {v}, text = {} }}", quote(text)));
                out.key("codes", list(codes));
            }
            DiagCode::Word(name) => out.string("code_word", name),
        }
    }
    for (key, why) in UNSAID {
        notes.note(format!("{file} does not say {why}: the description's `{key}` is the import's, marked under [choices]"));
    }
    notes.note(format!("{file} does not say whether the gateway is a node of the second bus itself: the description leaves `gateway.own_node` out"));
    if g.one_node {
        notes.note(format!("{file} names one node: which number in its parameters' names is the node's, they do not show; the import takes the first, {}", g.first_node));
    }
}

/// The reasons under `[choices]` for what a gateway's GSD does not say.
pub(super) fn choices(file: &str) -> impl Iterator<Item = (String, String)> + '_ {
    UNSAID.iter().map(move |(key, why)| {
        (
            key.to_string(),
            format!("{file} does not say {why}: the import's, to confirm against the manual"),
        )
    })
}

const UNNAMED_BUS: &str = "second bus";

/// The keys of `[gateway]` no GSD keyword gives, and what each says.
const UNSAID: [(&str, &str); 3] = [
    ("gateway.bus", "which bus the nodes are on"),
    (
        "gateway.data_order",
        "in which order the nodes' words follow each other",
    ),
    (
        "gateway.input_words",
        "which of each node's two parameters counts the words the master reads (the first, as gsdc writes them)",
    ),
];

fn write_param(out: &mut TomlOut, p: &Param) {
    out.key("name", &p.name);
    let (key, value) = &p.stored_as;
    out.key(key, value);
    out.key("range", format!("[{}, {}]", p.range.0, p.range.1));
}
