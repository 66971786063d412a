//! Checks of what a description means as a whole, beyond each value: a
//! mapping no module carries, a per-module setting without modules.

use super::checks::Checker;
use super::mappings::SetSpans;
use crate::description as raw;
use crate::diag::Diagnostic;
use crate::ir::profinet::ModuleKind;
use crate::ir::{MappingKind, Mappings, Profibus, Profinet};
use toml::Spanned;

pub fn check(
    cx: &mut Checker,
    desc: &raw::Description,
    mappings: &Mappings,
    (profibus, profinet): (Option<&Profibus>, Option<&Profinet>),
    spans: &SetSpans,
) {
    unmapped_words(cx, mappings, (profibus, profinet), spans);
    per_module_settings(cx, desc, (profibus, profinet));
}

/// W105: PZD words mapped beyond the longest PPO type and user-defined
/// module: no telegram carries them, so their mappings do nothing.
fn unmapped_words(
    cx: &mut Checker,
    mappings: &Mappings,
    (profibus, profinet): (Option<&Profibus>, Option<&Profinet>),
    spans: &SetSpans,
) {
    let ppo_words = profibus
        .into_iter()
        .flat_map(|p| &p.modules)
        .filter_map(|m| Some(m.layout?.pzd_words));
    let module_words = profinet
        .into_iter()
        .flat_map(|p| &p.modules)
        .filter(|m| m.kind == ModuleKind::Pzd)
        .map(|m| m.layout.pzd_words);
    let Some(carried) = ppo_words.chain(module_words).max() else {
        return;
    };
    for kind in [MappingKind::PzdOut, MappingKind::PzdIn] {
        let Some(group) = mappings.group(kind) else {
            continue;
        };
        let beyond: Vec<u8> = group
            .entries()
            .map(|(_, e)| e.key.number)
            .filter(|&n| n > carried)
            .collect();
        let (Some(first), Some(last)) = (beyond.first(), beyond.last()) else {
            continue;
        };
        let span = group.sets.first().and_then(|s| spans.get(&s.key)).cloned();
        cx.push(
            Diagnostic::warning(
                "W105",
                format!("{} maps PZD{first} to PZD{last}, which no module carries: the longest has {carried} PZD words", kind.key()),
            )
            .at_opt(span)
            .label("not carried")
            .help("map only the words a PPO type or module carries, or offer a longer one"),
        );
    }
}

/// E140: a setting fixed per module needs PROFINET modules that fix it.
/// With `[profibus]` too, whose PPO types fix nothing, the description says
/// whether User_Prm_Data carries it (E157 when it does not say; E002 for
/// `profibus` without `[profibus]`).
fn per_module_settings(
    cx: &mut Checker,
    desc: &raw::Description,
    (profibus, profinet): (Option<&Profibus>, Option<&Profinet>),
) {
    let offers = |kind| profinet.is_some_and(|p| p.modules.iter().any(|m| m.kind == kind));
    let (telegram_1, telegram_2) = (
        offers(ModuleKind::StandardTelegram1),
        offers(ModuleKind::StandardTelegram2),
    );
    for setting in &desc.settings {
        let Some(per_module) = &setting.per_module else {
            continue;
        };
        if let Some(drive) = setting
            .set_at
            .as_ref()
            .filter(|s| *s.get_ref() == raw::SetAt::Drive)
        {
            cx.push(
                Diagnostic::error(
                    "E158",
                    "a setting fixed per module, which the drive's own settings hold",
                )
                .at(per_module.span())
                .label("each module would write it at startup")
                .also_at(drive.span(), "set at the drive")
                .help("a module's parameter record writes the value it fixes; a setting set at the drive has no record: remove per_module, or say set_at = \"master\""),
            );
            continue;
        }
        let problem = if profinet.is_none() {
            Some("per_module needs PROFINET modules: the description has no [profinet]")
        } else if per_module.get_ref().standard_telegram_1.is_some() && !telegram_1 {
            Some("standard telegram 1 is not offered: set standard_telegram_1 = true or drop its value")
        } else if per_module.get_ref().standard_telegram_2.is_some() && !telegram_2 {
            Some("standard telegram 2 is not offered: set standard_telegram_2 = true or drop its value")
        } else {
            None
        };
        if let Some(problem) = problem {
            cx.push(
                Diagnostic::error(
                    "E140",
                    "a setting fixed per module without modules that can fix it",
                )
                .at(per_module.span())
                .label("per module")
                .help(problem),
            );
        }
        on_profibus(cx, per_module, profibus.is_some());
    }
}

/// Whether the description says what a PROFIBUS master does with a setting
/// fixed per PROFINET module, where there is one to say it of.
fn on_profibus(cx: &mut Checker, per_module: &Spanned<raw::PerModule>, has_profibus: bool) {
    match (&per_module.get_ref().profibus, has_profibus) {
        (None, true) => cx.push(
            Diagnostic::error(
                "E157",
                "a setting fixed per PROFINET module does not say what it is on PROFIBUS",
            )
            .at(per_module.span())
            .label("no `profibus` here")
            .help("PPO types fix nothing: say profibus = \"user\" (User_Prm_Data carries it and the master sets it, as any setting) or profibus = \"absent\" (the master cannot set it; the drive keeps its own value)"),
        ),
        (Some(said), false) => cx.push(
            Diagnostic::error("E002", "`profibus` in a description without [profibus]")
                .at(said.span())
                .label("means nothing here")
                .help("remove it: it says what a PROFIBUS master does with the setting"),
        ),
        _ => {}
    }
}
