//! Setting up the drive: what the manual tells the user to set on the drive
//! and the card (parameters, switches) and the indicators it describes,
//! group by group as the manual gives them, before the telegrams.

use super::page::{code, text, Builder, Cell};
use super::{parameter_name, Lang};
use crate::i18n::sheet as w;
use crate::ir::manual::{SetupGroup, SetupStep, SetupTarget};
use crate::ir::Ir;

pub(crate) fn section(doc: &mut Builder, ir: &Ir, lang: Lang) {
    if ir.setup.is_empty() {
        return;
    }
    doc.section_with_intro("setup", lang.t(w::SETUP_HEADING), lang.t(w::SETUP_INTRO));
    for group in &ir.setup {
        group_table(doc, ir, lang, group);
    }
}

fn group_table(doc: &mut Builder, ir: &Ir, lang: Lang, group: &SetupGroup) {
    if let Some(info) = &group.info {
        doc.para(text(lang.text(info)));
    }
    let has = |f: fn(&SetupStep) -> bool| group.steps.iter().any(f);
    let columns = [
        has(|s| s.name.is_some()),
        has(|s| s.value.is_some()),
        has(|s| s.default.is_some()),
        has(|s| s.meaning.is_some() || !s.values.is_empty()),
    ];
    let head: Vec<&str> = [
        lang.t(w::SETTING),
        lang.t(w::NAME),
        lang.t(w::VALUE),
        lang.t(w::DEFAULT),
        lang.t(w::MEANING),
    ]
    .into_iter()
    .zip(std::iter::once(true).chain(columns))
    .filter_map(|(h, shown)| shown.then_some(h))
    .collect();
    let rows = group
        .steps
        .iter()
        .map(|step| {
            let cells = [
                (true, target(ir, lang, &step.target)),
                (columns[0], optional(lang, step.name.as_ref())),
                (columns[1], optional(lang, step.value.as_ref())),
                (columns[2], text(step.default.as_deref().unwrap_or("—"))),
                (columns[3], text(meaning(lang, step))),
            ];
            cells
                .into_iter()
                .filter_map(|(shown, cell)| shown.then_some(cell))
                .collect()
        })
        .collect();
    let caption = match &group.title {
        Some(title) => w::manual_section_titled(lang, &group.section, lang.text(title)),
        None => w::manual_section(lang, &group.section),
    };
    doc.table(caption, &head, rows);
    if let Some(note) = &group.note {
        doc.para(text(lang.text(note)));
    }
}

/// What a step sets: a drive parameter as the drive names it, a run of
/// them, or the manual's item.
fn target(ir: &Ir, lang: Lang, target: &SetupTarget) -> Cell {
    match target {
        SetupTarget::Parameter(address) => code(parameter_name(ir, *address)),
        SetupTarget::Parameters(first, last) => code(w::range(
            lang,
            parameter_name(ir, *first),
            parameter_name(ir, *last),
        )),
        SetupTarget::Item(item) => text(lang.text(item)),
        _ => text("—"),
    }
}

fn optional(lang: Lang, t: Option<&crate::ir::Text>) -> Cell {
    text(t.map_or("—", |t| lang.text(t)))
}

/// The meaning, then the table of values the manual gives, each with its
/// text: `配置 DP 节地址; 0: 禁止 DP 功能; 1~125: DP 通讯地址`.
fn meaning(lang: Lang, step: &SetupStep) -> String {
    let values = step
        .values
        .iter()
        .map(|(value, meaning)| w::value_means(lang, lang.text(value), lang.text(meaning)));
    let parts: Vec<String> = step
        .meaning
        .iter()
        .map(|m| lang.text(m).to_string())
        .chain(values)
        .collect();
    match parts.is_empty() {
        true => "—".to_string(),
        false => parts.join(lang.t(w::SEMICOLON)),
    }
}
