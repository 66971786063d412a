//! The datasheet: the fieldbus chapter of a drive manual, generated from the
//! IR as `<stem>.html` (one self-contained page, every language the
//! description has) and `<stem>.md` (for a manual's sources or a review).
//!
//! Kept out of [`crate::compile`]'s files: those ship with the card and go
//! into firmware; the datasheet is documentation, written by `gsdc doc`
//! ([`crate::document`]).
//!
//! The sections build a [`page::Doc`] per language; [`page`] renders it.
//! Diagrams are laid out in [`svg`], and PKW and diagnosis examples are
//! encoded by the firmware's own codecs ([`crate::pkw`]).

mod gateway;
mod identity;
mod page;
mod params;
mod pkw;
mod svg;
mod telegrams;

use super::{Artifact, ArtifactKind};
use crate::ir::{Allowed, DecisionKind, Holds, Ir, MappingEntry, MappingSet, Text};
use page::{Builder, Cell, Run};

/// A language of the datasheet: the description's texts in it, and gsdc's
/// own words, which exist in English and Chinese (in English on the page of
/// any other language).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Lang {
    En,
    Zh,
    /// Another ISO 639-1 code of the description, two ASCII letters.
    Other([u8; 2]),
}

impl Lang {
    /// The language of ISO 639-1 `code`.
    fn of(code: &str) -> Lang {
        match code.as_bytes() {
            b"en" => Lang::En,
            b"zh" => Lang::Zh,
            &[a, b] => Lang::Other([a, b]),
            _ => unreachable!("descriptions accept ISO 639-1 codes only"),
        }
    }

    fn code(&self) -> &str {
        match self {
            Lang::En => "en",
            Lang::Zh => "zh",
            Lang::Other(code) => std::str::from_utf8(code).expect("ASCII letters"),
        }
    }

    /// The language's own name on its switch; gsdc knows two of them, and
    /// names the others by their code.
    fn name(&self) -> &str {
        match self {
            Lang::En => "English",
            Lang::Zh => "中文",
            Lang::Other(_) => self.code(),
        }
    }

    /// gsdc's words in this language.
    fn t<'a>(self, en: &'a str, zh: &'a str) -> &'a str {
        match self {
            Lang::Zh => zh,
            _ => en,
        }
    }

    /// A sentence made in this language: both are built, one is kept.
    fn f(self, en: String, zh: String) -> String {
        match self {
            Lang::Zh => zh,
            _ => en,
        }
    }

    /// A description's text in this language, English where it has none.
    fn text(self, text: &Text) -> &str {
        match self {
            Lang::En => &text.en,
            _ => text.get(self.code()),
        }
    }

    fn table_label(self, n: usize) -> String {
        self.f(format!("Table {n}."), format!("表 {n}"))
    }

    fn figure_label(self, n: usize) -> String {
        self.f(format!("Figure {n}."), format!("图 {n}"))
    }
}

/// The datasheet of a description: `<stem>.html` and `<stem>.md`.
pub fn datasheet(ir: &Ir) -> Vec<Artifact> {
    let docs: Vec<page::Doc> = languages(ir).into_iter().map(|l| document(ir, l)).collect();
    let stem = super::source_stem(ir);
    vec![
        Artifact {
            kind: ArtifactKind::DatasheetHtml,
            file_name: format!("{stem}.html"),
            contents: page::html(&docs, crate::GENERATOR).into_bytes(),
        },
        Artifact {
            kind: ArtifactKind::DatasheetMarkdown,
            file_name: format!("{stem}.md"),
            contents: page::markdown(&docs, crate::GENERATOR).into_bytes(),
        },
    ]
}

/// English first, then every other language of the description in the
/// order of its codes.
fn languages(ir: &Ir) -> Vec<Lang> {
    std::iter::once(Lang::En)
        .chain(ir.languages.iter().map(|code| Lang::of(code)))
        .collect()
}

fn document(ir: &Ir, lang: Lang) -> page::Doc {
    let title = lang.f(
        format!(
            "{} {}: fieldbus interface",
            ir.device.vendor, ir.device.model
        ),
        format!("{} {}：现场总线接口", ir.device.vendor, ir.device.model),
    );
    let mut doc = Builder::new(lang, title);
    identity::section(&mut doc, ir, lang);
    telegrams::section(&mut doc, ir, lang);
    telegrams::words_section(&mut doc, ir, lang);
    gateway::section(&mut doc, ir, lang);
    pkw::section(&mut doc, ir, lang);
    params::section(&mut doc, ir, lang);
    params::diagnosis_section(&mut doc, ir, lang);
    gateway::diagnosis_section(&mut doc, ir, lang);
    identity::checklist_section(&mut doc, ir, lang);
    doc.finish()
}

// ---------------------------------------------------------------------------
// Formatting shared by the sections

/// A parameter address as the manual writes it, with the decimal number a
/// configuration tool shows: `F0-00 (61440)`, or `0x1000 (4096)` where the
/// description names no such parameter.
fn address(ir: &Ir, value: u16) -> String {
    match drive_name(ir, value) {
        Some(name) => format!("{name} ({value})"),
        None => format!("0x{value:04X} ({value})"),
    }
}

/// A parameter's name alone: `F0-08`, else `0x1000`.
fn parameter_name(ir: &Ir, value: u16) -> String {
    drive_name(ir, value).unwrap_or_else(|| format!("0x{value:04X}"))
}

/// The drive's name of an address (`Numbering::format`: a hex group is one
/// digit, so 9KDP1's Modbus address 0x8000 has none under the prefix d =
/// 0x70).
fn drive_name(ir: &Ir, value: u16) -> Option<String> {
    ir.numbering.as_ref()?.format(value)
}

/// A mapping's value: an address, a plain value, or a choice's text.
fn mapping_value(ir: &Ir, lang: Lang, set: &MappingSet, value: u16) -> String {
    match &set.allowed {
        Allowed::Range { .. } if set.holds == Holds::Address => address(ir, value),
        Allowed::Range { .. } => value.to_string(),
        Allowed::Choices(values) => values
            .choices
            .iter()
            .find(|c| c.value == i64::from(value))
            .map_or_else(
                || value.to_string(),
                |c| format!("{value}: {}", lang.text(&c.text)),
            ),
    }
}

/// What a mapping may hold, in words; addresses in hex too, as the
/// manuals write them.
fn allowed(lang: Lang, set: &MappingSet) -> String {
    match &set.allowed {
        Allowed::Range { min, max } if set.holds == Holds::Address => lang.f(
            format!("{min} to {max} (0x{min:04X} to 0x{max:04X})"),
            format!("{min}～{max}（0x{min:04X}～0x{max:04X}）"),
        ),
        Allowed::Range { min, max } => lang.f(format!("{min} to {max}"), format!("{min}～{max}")),
        Allowed::Choices(values) => lang.f(
            format!(
                "one of {} choices ({})",
                values.choices.len(),
                choices_caption(lang, set)
            ),
            format!(
                "{} 个选项之一（{}）",
                values.choices.len(),
                choices_caption(lang, set)
            ),
        ),
    }
}

/// The caption of a set's table of choices.
fn choices_caption(lang: Lang, set: &MappingSet) -> String {
    lang.f(
        format!("choices of {}", set_name(lang, set)),
        format!("{}的选项", set_name(lang, set)),
    )
}

/// `PZD2 receive to PZD12 receive`, or the one entry's name.
fn set_name(lang: Lang, set: &MappingSet) -> String {
    let first = lang.text(&set.entries[0].name);
    match set.entries.last() {
        Some(last) if set.entries.len() > 1 => lang.f(
            format!("{first} to {}", lang.text(&last.name)),
            format!("{first}～{}", lang.text(&last.name)),
        ),
        _ => first.to_string(),
    }
}

/// The drive parameter that holds a mapping, or a dash.
fn drive_parameter(ir: &Ir, entry: &MappingEntry) -> Cell {
    match entry.parameter {
        Some(p) => page::code(parameter_name(ir, p)),
        None => page::text("—"),
    }
}

/// A value followed by a mark when it is a placeholder.
fn with_placeholder(lang: Lang, value: String, placeholder: bool) -> Cell {
    let mut cell = vec![Run::Code(value)];
    if placeholder {
        cell.push(Run::Text(" ".into()));
        cell.push(Run::Mark(
            lang.t("placeholder, not assigned by PI", "占位值，非 PI 分配")
                .into(),
        ));
    }
    cell
}

/// What kind of decision a value is, as the checklist says it.
fn decision_kind(lang: Lang, kind: DecisionKind) -> &'static str {
    match kind {
        DecisionKind::Placeholder => lang.t("placeholder", "占位值"),
        DecisionKind::Choice => lang.t("the description's own choice", "描述文件自行确定"),
        DecisionKind::Convention => lang.t("gsdc's numbering", "gsdc 编号"),
        DecisionKind::Requirement => lang.t("required of the firmware", "固件须支持"),
        _ => lang.t("gsdc's default", "gsdc 默认值"),
    }
}

/// A mark for a value at `path` of the description (or inside it) that the
/// manual does not give, saying what kind of decision it is; `None` for a
/// value the manual gives.
fn decision_mark(ir: &Ir, lang: Lang, path: &str) -> Option<Run> {
    let inside = |outer: &str, inner: &str| {
        inner == outer
            || inner
                .strip_prefix(outer)
                .is_some_and(|r| r.starts_with('.'))
    };
    ir.decisions
        .iter()
        .find(|d| inside(&d.path, path) || inside(path, &d.path))
        .map(|d| Run::Mark(decision_kind(lang, d.kind).to_string()))
}

/// `bit 3`, `bits 9-10`.
fn bits(lang: Lang, first: u16, last: u16) -> String {
    match (first == last, lang) {
        (true, Lang::Zh) => format!("Bit{first}"),
        (false, Lang::Zh) => format!("Bit{first}-Bit{last}"),
        (true, _) => format!("bit {first}"),
        (false, _) => format!("bits {first}-{last}"),
    }
}

/// `bytes 8-9`, `byte 6`.
fn bytes(lang: Lang, first: u16, last: u16) -> String {
    match (first == last, lang) {
        (true, Lang::Zh) => format!("字节 {first}"),
        (false, Lang::Zh) => format!("字节 {first}-{last}"),
        (true, _) => format!("byte {first}"),
        (false, _) => format!("bytes {first}-{last}"),
    }
}

/// Bytes as the manuals write them where bytes matter: `03 00 34`.
fn hex_bytes(bytes: &[u8]) -> String {
    bytes
        .iter()
        .map(|b| format!("{b:02X}"))
        .collect::<Vec<_>>()
        .join(" ")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ir::{MappingKind, SetKey};

    /// A timeout of 100 ms is 100, not the parameter at address 100
    /// (`P00.100 (100)`), and its range has no hex.
    #[test]
    fn a_range_of_plain_values_is_shown_in_decimal() {
        let ir = crate::testing::mv810_with_timeout();
        let timeout = ir.mappings.set(SetKey {
            kind: MappingKind::Setting,
            first: 2,
        });
        assert_eq!(mapping_value(&ir, Lang::En, timeout, 100), "100");
        assert_eq!(allowed(Lang::En, timeout), "0 to 60000");
        assert_eq!(allowed(Lang::Zh, timeout), "0～60000");
    }
}
