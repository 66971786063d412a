//! `[[setup]]` and `[[examples]]`: what the manual tells the user to set,
//! and the telegrams it prints, each checked against the rest of the
//! description. A set-up step that names a mapping's drive parameter must
//! agree with the mapping (E158, E159); an example must be a telegram the
//! description's modules carry and the firmware's codecs read (E160).

use super::checks::Checker;
use super::resolve_address;
use crate::description as raw;
use crate::diag::Diagnostic;
use crate::ir::manual::{Example, ExamplePart, ExampleWord, SetupGroup, SetupStep, SetupTarget};
use crate::ir::{
    Direction, Layout, MappingEntry, MappingSet, Mappings, Numbering, PkwKind, Profibus, Profinet,
    Text,
};
use std::ops::Range;
use toml::Spanned;

/// The set-up groups, each step checked against the mappings.
pub fn setup(
    cx: &mut Checker,
    groups: &[raw::SetupGroup],
    numbering: Option<&Numbering>,
    mappings: &Mappings,
) -> Vec<SetupGroup> {
    groups
        .iter()
        .map(|g| SetupGroup {
            section: cx.required(&g.section, "a set-up group's section"),
            title: g.title.as_ref().map(|t| cx.text(t, None, "a set-up title")),
            info: g.info.as_ref().map(|t| cx.text(t, None, "a set-up info")),
            steps: g
                .steps
                .iter()
                .filter_map(|s| step(cx, s, numbering, mappings))
                .collect(),
            note: g.note.as_ref().map(|t| cx.text(t, None, "a set-up note")),
        })
        .collect()
}

fn step(
    cx: &mut Checker,
    s: &raw::SetupStep,
    numbering: Option<&Numbering>,
    mappings: &Mappings,
) -> Option<SetupStep> {
    let named = [
        s.parameter.as_ref().map(Spanned::span),
        s.parameters.as_ref().map(Spanned::span),
        s.item.as_ref().map(Spanned::span),
    ];
    if let Some(second) = named.iter().flatten().nth(1) {
        cx.push(
            Diagnostic::error("E002", "a set-up step names two things")
                .at(second.clone())
                .label("one of parameter, parameters and item")
                .help("a step sets one drive parameter (parameter), a run of them (parameters) or something else (item): split it"),
        );
        return None;
    }
    let value = s.value.as_ref().map(|v| cx.text(v, None, "a set-up value"));
    let meaning = s
        .meaning
        .as_ref()
        .map(|t| cx.text(t, None, "a set-up meaning"));
    let target = if let Some(p) = &s.parameter {
        let address = resolve_address(cx, p, numbering)?;
        agree_parameter(
            cx,
            (address, p.span()),
            (value.as_ref(), s.value.as_ref()),
            numbering,
            mappings,
        );
        SetupTarget::Parameter(address)
    } else if let Some(run) = &s.parameters {
        let [first, last] = run.get_ref();
        let first = resolve_address(cx, first, numbering)?;
        let last = resolve_address(cx, last, numbering)?;
        if last < first {
            cx.reversed(run.span(), first, last);
            return None;
        }
        agree_run(cx, (first, last, run.span()), numbering, mappings);
        SetupTarget::Parameters(first, last)
    } else if let Some(item) = &s.item {
        let text = cx.text(item, None, "a set-up item");
        agree_entry(
            cx,
            &text,
            (value.as_ref(), s.value.as_ref()),
            (meaning.as_ref(), s.meaning.as_ref()),
            numbering,
            mappings,
        );
        SetupTarget::Item(text)
    } else {
        SetupTarget::None
    };
    Some(SetupStep {
        target,
        name: s.name.as_ref().map(|t| cx.text(t, None, "a set-up name")),
        value,
        default: s
            .default
            .as_ref()
            .map(|d| cx.required(d, "a set-up default")),
        meaning,
        values: s
            .values
            .iter()
            .map(|v| {
                (
                    cx.text(&v.value, None, "a set-up value"),
                    cx.text(&v.text, None, "a set-up value's text"),
                )
            })
            .collect(),
    })
}

/// The set and entry whose drive parameter is `address`.
fn mapped(mappings: &Mappings, address: u16) -> Option<(&MappingSet, &MappingEntry)> {
    mappings
        .sets()
        .find_map(|s| Some((s, s.entries.iter().find(|e| e.parameter == Some(address))?)))
}

/// A value as the manuals print one: decimal, hex after `0x`, or a
/// function-code name (`F0-02`) under `[function_codes]`.
fn number(text: &str, numbering: Option<&Numbering>) -> Option<u16> {
    let text = text.trim();
    match text.strip_prefix("0x").or_else(|| text.strip_prefix("0X")) {
        Some(hex) => u16::from_str_radix(hex, 16).ok(),
        None => text
            .parse()
            .ok()
            .or_else(|| Some(numbering?.read(text).ok()?.address)),
    }
}

/// E158 when a step sets a parameter the master writes at every startup.
fn set_by_master(cx: &mut Checker, set: &MappingSet, span: Range<usize>) {
    cx.push(
        Diagnostic::error(
            "E158",
            format!(
                "a set-up step sets the drive parameter of {}, which the master writes at every startup",
                set.entries[0].name.en
            ),
        )
        .at(span)
        .label("set at the drive here")
        .help("the master's User_Prm_Data or record would overwrite what this step sets: say set_at = \"drive\" on the mapping if the manual sets it at the drive, or drop the step"),
    );
}

/// E159: a step that disagrees with what the description says elsewhere.
fn disagrees(cx: &mut Checker, message: String, span: Range<usize>, label: &str, help: &str) {
    cx.push(
        Diagnostic::error("E159", message)
            .at(span)
            .label(label)
            .help(help.to_string()),
    );
}

/// A step's value must be one the parameter's mapping allows.
fn agree_value(
    cx: &mut Checker,
    set: &MappingSet,
    (value, written): (Option<&Text>, Option<&Spanned<raw::Text>>),
    (what, numbering): (&str, Option<&Numbering>),
) {
    let (Some(value), Some(written)) = (value, written) else {
        return;
    };
    let span = written.get_ref().en_span(&written.span());
    match number(&value.en, numbering) {
        None => disagrees(
            cx,
            format!("`{}` is not a number, and {what} holds one", value.en),
            span,
            "not a number",
            "write the value the step sets as a number (2, 0x2B02) or a function code (F0-12), so it can be checked against the mapping",
        ),
        Some(n) if !set.allowed.contains(n.into()) => disagrees(
            cx,
            format!("{n} is not among the values {what} allows"),
            span,
            "not allowed",
            "the step and the mapping must agree: fix the one the manual does not say",
        ),
        Some(_) => {}
    }
}

fn agree_parameter(
    cx: &mut Checker,
    (address, span): (u16, Range<usize>),
    value: (Option<&Text>, Option<&Spanned<raw::Text>>),
    numbering: Option<&Numbering>,
    mappings: &Mappings,
) {
    let Some((set, entry)) = mapped(mappings, address) else {
        return;
    };
    if set.master_writes() {
        set_by_master(cx, set, span);
    }
    agree_value(cx, set, value, (&entry.name.en, numbering));
}

/// A run of parameters that touches a mapping's must be all of one set's.
fn agree_run(
    cx: &mut Checker,
    (first, last, span): (u16, u16, Range<usize>),
    numbering: Option<&Numbering>,
    mappings: &Mappings,
) {
    let touched: Vec<&MappingSet> = mappings
        .sets()
        .filter(|s| {
            s.entries
                .iter()
                .any(|e| e.parameter.is_some_and(|p| (first..=last).contains(&p)))
        })
        .collect();
    let Some(set) = touched.first() else {
        return;
    };
    let name = |a: u16| {
        numbering
            .and_then(|n| n.format(a))
            .unwrap_or_else(|| format!("0x{a:04X}"))
    };
    let held = (
        set.entries[0].parameter,
        set.entries[set.entries.len() - 1].parameter,
    );
    if touched.len() > 1 || held != (Some(first), Some(last)) {
        let (a, b) = (held.0.unwrap_or(first), held.1.unwrap_or(last));
        disagrees(
            cx,
            format!(
                "{} to {} is not the run of one mapping's parameters: {} is {} to {}",
                name(first),
                name(last),
                set.entries[0].name.en,
                name(a),
                name(b)
            ),
            span,
            "not one mapping's parameters",
            "a run of parameters that a mapping holds must be all of that mapping's: fix the one the manual does not say",
        );
        return;
    }
    if set.master_writes() {
        set_by_master(cx, set, span);
    }
}

/// An item that names a mapping entry (`PZD3(master->slaver)`, an entry of
/// the master's configuration) takes a value its mapping allows; a meaning
/// that is a function-code name is that value (`F0-12` is 61452).
fn agree_entry(
    cx: &mut Checker,
    item: &Text,
    value: (Option<&Text>, Option<&Spanned<raw::Text>>),
    (meaning, meaning_written): (Option<&Text>, Option<&Spanned<raw::Text>>),
    numbering: Option<&Numbering>,
    mappings: &Mappings,
) {
    let Some((set, entry)) = mappings
        .sets()
        .find_map(|s| Some((s, s.entries.iter().find(|e| e.name.en == item.en)?)))
    else {
        return;
    };
    agree_value(cx, set, value, (&entry.name.en, numbering));
    let named = numbering
        .zip(meaning)
        .and_then(|(n, m)| n.read(m.en.trim()).ok());
    let number = value.0.and_then(|v| number(&v.en, numbering));
    if let (Some(named), Some(number), Some(written)) = (named, number, meaning_written) {
        if named.address != number {
            disagrees(
                cx,
                format!(
                    "{} is {} (0x{:04X}), not {number}",
                    meaning.map_or("", |m| m.en.as_str()),
                    named.address,
                    named.address
                ),
                written.get_ref().en_span(&written.span()),
                "another address",
                "the value a step enters and the function code it stands for must be the same address under [function_codes]",
            );
        }
    }
}

// ---------------------------------------------------------------------------
// Examples

/// What the examples are checked against: the telegram's PKW channel and
/// the modules of each bus.
pub struct Telegrams<'a> {
    pub pkw: PkwKind,
    pub profibus: Option<&'a Profibus>,
    pub profinet: Option<&'a Profinet>,
}

impl Telegrams<'_> {
    /// Every module by the name its file shows, with its layout.
    fn modules(&self) -> Vec<(String, Option<u8>, Layout)> {
        let ppo = self
            .profibus
            .into_iter()
            .flat_map(|p| &p.modules)
            .map(|m| (m.name.clone(), Some(m.ppo), m.layout));
        let pn = self
            .profinet
            .into_iter()
            .flat_map(|p| &p.modules)
            .map(|m| (m.name.text.en.clone(), None, m.layout));
        ppo.chain(pn).collect()
    }

    /// The module a description names: a PPO type (`PPO1`) or a module's
    /// name as its file shows it, case and blanks aside.
    fn module(&self, name: &str) -> Option<(String, Layout)> {
        let key = |s: &str| {
            s.chars()
                .filter(|c| !c.is_whitespace())
                .flat_map(char::to_lowercase)
                .collect::<String>()
        };
        self.modules()
            .into_iter()
            .find(|(shown, ppo, _)| {
                key(shown) == key(name) || ppo.is_some_and(|n| key(name) == format!("ppo{n}"))
            })
            .map(|(shown, _, layout)| (shown, layout))
    }
}

/// Each example, with its bytes read and checked: the module carries them
/// (its length, or the PKW channel's 8 bytes) and the firmware's codec
/// reads every PKW they hold and writes it back the same.
pub fn examples(cx: &mut Checker, given: &[raw::Example], telegrams: &Telegrams) -> Vec<Example> {
    given
        .iter()
        .filter_map(|e| example(cx, e, telegrams))
        .collect()
}

/// E160 at `span`.
fn cannot_carry(cx: &mut Checker, message: String, span: Range<usize>, label: &str, help: String) {
    cx.push(
        Diagnostic::error("E160", message)
            .at(span)
            .label(label)
            .help(help),
    );
}

fn example(cx: &mut Checker, e: &raw::Example, telegrams: &Telegrams) -> Option<Example> {
    let section = cx.required(&e.section, "an example's section");
    let meaning = cx.text(&e.meaning, None, "an example's meaning");
    let words = example_words(cx, e)?;
    let direction = match e.direction.get_ref() {
        raw::ExampleDirection::Out => Direction::Out,
        raw::ExampleDirection::In => Direction::In,
    };
    let part = match e.part.as_ref().map(Spanned::get_ref) {
        Some(raw::ExamplePart::Pkw) => ExamplePart::Pkw,
        _ => ExamplePart::Telegram,
    };
    let module = match &e.module {
        Some(name) => match telegrams.module(name.get_ref()) {
            Some(found) => Some(found),
            None => {
                let known: Vec<String> = telegrams.modules().into_iter().map(|m| m.0).collect();
                cannot_carry(
                    cx,
                    format!("no module of the description is `{}`", name.get_ref()),
                    name.span(),
                    "not a module",
                    format!(
                        "name a PPO type (PPO1) or a module as its file shows it: {}",
                        known.join(", ")
                    ),
                );
                return None;
            }
        },
        None => None,
    };
    let example = Example {
        section,
        module: module.as_ref().map(|(name, _)| name.clone()),
        direction,
        part,
        printed: e.bytes.get_ref().clone(),
        words,
        meaning,
        figure: e
            .figure
            .as_ref()
            .map(|f| cx.text(f, None, "an example's figure")),
    };
    let pkw = match (part, &module) {
        (ExamplePart::Telegram, None) => {
            cannot_carry(
                cx,
                "a whole telegram without its module".to_string(),
                e.bytes.span(),
                "whose telegram?",
                "say the module (module = \"PPO1\"), or part = \"pkw\" for the PKW words alone"
                    .into(),
            );
            return None;
        }
        (ExamplePart::Telegram, Some((name, layout))) => {
            let bytes = 2 * usize::from(layout.pkw_words() + layout.pzd_words);
            if example.len() != bytes {
                cannot_carry(
                    cx,
                    format!(
                        "{} bytes, but {name} carries {bytes} each way",
                        example.len()
                    ),
                    e.bytes.span(),
                    "not the module's length",
                    "give the whole telegram, or part = \"pkw\" for the PKW words alone".into(),
                );
                return None;
            }
            layout.pkw
        }
        (ExamplePart::Pkw, module) => {
            if telegrams.pkw == PkwKind::None || module.as_ref().is_some_and(|(_, l)| !l.pkw) {
                let span = e.part.as_ref().map_or(e.bytes.span(), Spanned::span);
                cannot_carry(
                    cx,
                    "PKW words, but the module has no PKW channel".to_string(),
                    span,
                    "no PKW here",
                    "name a module with the PKW channel, or give the whole telegram".into(),
                );
                return None;
            }
            if example.len() != crate::pkw::PKW_BYTES {
                cannot_carry(
                    cx,
                    format!("{} bytes of PKW words; the channel is {}", example.len(), crate::pkw::PKW_BYTES),
                    e.bytes.span(),
                    "not the PKW's length",
                    "the PKW channel is four words: PKE, IND, PWE, PWE (or as the description's kind names them)".into(),
                );
                return None;
            }
            true
        }
    };
    if pkw {
        for telegram in example.instances() {
            let words = crate::pkw::pkw_words(&telegram);
            if let Err(why) = crate::pkw::round_trips(telegrams.pkw, direction, &words) {
                cannot_carry(
                    cx,
                    format!("the firmware's PKW codec does not read {}: {why}", hex(&telegram[..crate::pkw::PKW_BYTES])),
                    e.bytes.span(),
                    match direction {
                        Direction::Out => "not a request the codec reads",
                        Direction::In => "not a response the codec reads",
                    },
                    "an example is a telegram the card exchanges: check the bytes against the manual, and direction (out is the master's request, in the drive's response)".into(),
                );
                return None;
            }
        }
    }
    Some(example)
}

fn hex(bytes: &[u8]) -> String {
    bytes
        .iter()
        .map(|b| format!("{b:02X}"))
        .collect::<Vec<_>>()
        .join(" ")
}

/// The printed bytes, group by group: hex digits (an even number of
/// them), or a name that `placeholders` gives the values of.
fn example_words(cx: &mut Checker, e: &raw::Example) -> Option<Vec<ExampleWord>> {
    let printed = e.bytes.get_ref();
    let mut words = Vec::new();
    let mut failed = false;
    for token in printed.split_whitespace() {
        let is_hex = token.len() % 2 == 0 && token.bytes().all(|b| b.is_ascii_hexdigit());
        if is_hex {
            let bytes = (0..token.len())
                .step_by(2)
                .map(|i| u8::from_str_radix(&token[i..i + 2], 16).expect("hex digits"))
                .collect();
            words.push(ExampleWord::Bytes(bytes));
            continue;
        }
        let named = e
            .placeholders
            .iter()
            .find(|(name, _)| name.get_ref() == token);
        match named {
            Some((name, values)) => {
                let values: Option<Vec<u16>> = values
                    .get_ref()
                    .iter()
                    .map(|v| cx.in_range(*v.get_ref(), 0, 0xFFFF, v.span(), "a word's value"))
                    .collect();
                match values {
                    Some(values) if !values.is_empty() => words.push(ExampleWord::Named {
                        name: name.get_ref().clone(),
                        values,
                    }),
                    Some(_) => {
                        cannot_carry(
                            cx,
                            format!("`{token}` stands for no value"),
                            name.span(),
                            "no values",
                            "give the values the word stands for: errCode = [1, 2, 3, 4]".into(),
                        );
                        failed = true;
                    }
                    None => failed = true,
                }
            }
            None => {
                cannot_carry(
                    cx,
                    format!("`{token}` is neither hex bytes nor a word the example names"),
                    e.bytes.span(),
                    "not bytes",
                    format!("print bytes as the manual does (10F0 0800), an even number of hex digits a group; a word the manual names instead (errCode) needs placeholders = {{ {token} = [...] }}"),
                );
                failed = true;
            }
        }
    }
    for name in e.placeholders.keys() {
        if !printed.split_whitespace().any(|t| t == name.get_ref()) {
            cannot_carry(
                cx,
                format!("`{}` is not in the example's bytes", name.get_ref()),
                name.span(),
                "not used",
                "name only the words the bytes leave open".into(),
            );
            failed = true;
        }
    }
    (!failed).then_some(words)
}

#[cfg(test)]
mod tests {
    const MD810: &str = include_str!("../../descriptions/md810dp.toml");
    const MV810: &str = include_str!("../../descriptions/mv810-pnet02.toml");

    /// The errors of `text` (a shipped description, changed): code and message.
    fn errors(name: &str, text: &str) -> Vec<(&'static str, String)> {
        let (_, diagnostics) = crate::testing::load(name, text);
        diagnostics
            .errors()
            .map(|d| (d.code, d.message.clone()))
            .collect()
    }

    fn changed(text: &str, from: &str, to: &str) -> String {
        assert!(text.contains(from), "{from}");
        text.replacen(from, to, 1)
    }

    #[test]
    fn the_shipped_steps_and_examples_agree() {
        assert_eq!(errors("md810dp.toml", MD810), []);
        assert_eq!(errors("mv810-pnet02.toml", MV810), []);
    }

    /// A run of parameters a mapping holds is all of them; a step that sets
    /// a parameter the master writes is E158.
    #[test]
    fn steps_agree_with_the_mappings() {
        let short = changed(
            MV810,
            "parameters = [\"P43.02\", \"P43.12\"]",
            "parameters = [\"P43.02\", \"P43.11\"]",
        );
        assert_eq!(
            errors("mv810-pnet02.toml", &short),
            [(
                "E159",
                "P43.02 to P43.11 is not the run of one mapping's parameters: PZD2 receive is P43.02 to P43.12".to_string()
            )]
        );
        let by_master = changed(
            MV810,
            "set_at = \"drive\"\nchoices = [\n    { value = 0, text = { en = \"standard",
            "set_at = \"master\"\nchoices = [\n    { value = 0, text = { en = \"standard",
        );
        let found = errors("mv810-pnet02.toml", &by_master);
        // Each of the three ways of section 4 sets P43.01.
        assert_eq!(found.len(), 3, "{found:?}");
        assert!(
            found
                .iter()
                .all(|(code, m)| *code == "E158" && m.contains("Message type (P43.01)")),
            "{found:?}"
        );
        let not_a_number = changed(
            MV810,
            "{ parameter = \"P43.01\", value = \"1\"",
            "{ parameter = \"P43.01\", value = \"one\"",
        );
        assert_eq!(
            errors("mv810-pnet02.toml", &not_a_number),
            [(
                "E159",
                "`one` is not a number, and Message type (P43.01) holds one".to_string()
            )]
        );
        let other_index = changed(
            MD810,
            "{ item = \"Index0\", value = \"F0-02\" }",
            "{ item = \"Index0\", value = \"F0-02\", meaning = \"F0-03\" }",
        );
        assert_eq!(
            errors("md810dp.toml", &other_index),
            [("E159", "F0-03 is 61443 (0xF003), not 61442".to_string())]
        );
    }

    /// An example is a telegram a module carries: its module, its length,
    /// its named words.
    #[test]
    fn examples_are_telegrams_the_modules_carry() {
        let first = "part = \"pkw\"\ndirection = \"out\"\nbytes = \"10F0 0800 0000 0000\"";
        let cases = [
            (
                "module = \"PPO9\"\ndirection = \"out\"\nbytes = \"10F0 0800 0000 0000\"",
                "no module of the description is `PPO9`",
            ),
            (
                "module = \"PPO1\"\ndirection = \"out\"\nbytes = \"10F0 0800 0000 0000\"",
                "8 bytes, but PPO1: 4 PKW + 2 PZD carries 12 each way",
            ),
            (
                "module = \"PPO3\"\npart = \"pkw\"\ndirection = \"out\"\nbytes = \"10F0 0800 0000 0000\"",
                "PKW words, but the module has no PKW channel",
            ),
            (
                "part = \"pkw\"\ndirection = \"out\"\nbytes = \"10F0 0800 0000\"",
                "6 bytes of PKW words; the channel is 8",
            ),
            (
                "part = \"pkw\"\ndirection = \"out\"\nbytes = \"10F0 0800 0000 xxxx\"",
                "`xxxx` is neither hex bytes nor a word the example names",
            ),
            (
                "part = \"pkw\"\ndirection = \"in\"\nbytes = \"10F0 0800 0000 0000\"\nplaceholders = { errCode = [1] }",
                "`errCode` is not in the example's bytes",
            ),
        ];
        for (example, message) in cases {
            let text = changed(MD810, first, example);
            assert_eq!(
                errors("md810dp.toml", &text),
                [("E160", message.to_string())],
                "{example}"
            );
        }
        // The same telegram as PPO1's whole, PZD words and all.
        let whole = changed(
            MD810,
            first,
            "module = \"PPO1\"\ndirection = \"out\"\nbytes = \"10F0 0800 0000 0000 0001 1388\"",
        );
        assert_eq!(errors("md810dp.toml", &whole), []);
        let ir = crate::testing::load("md810dp.toml", &whole).0.unwrap();
        assert_eq!(
            ir.examples[0].module.as_deref(),
            Some("PPO1: 4 PKW + 2 PZD")
        );
    }
}
