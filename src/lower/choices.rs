//! `[choices]`: the values a description marks as its own choice, each
//! with its reason. A path names a key as TOML writes it, with `[n]` for the
//! n-th element of an array (from 0): `profibus.min_slave_interval`,
//! `profibus.baud_rates."1.5M"`, `settings[0].default`. A path names a key
//! the description writes; a table marks everything in it.

use super::checks::Checker;
use crate::description::choices::{ChoiceTargets, Miss};
use crate::diag::Diagnostic;
use crate::ir::{Decision, DecisionKind};
use std::collections::BTreeMap;
use toml::Spanned;

pub fn lower(
    cx: &mut Checker,
    choices: &BTreeMap<Spanned<String>, Spanned<String>>,
    targets: &ChoiceTargets,
) -> Vec<Decision> {
    choices
        .iter()
        .filter_map(|(path, reason)| {
            // Both come from one table: every path has its target.
            let marked = match targets.get(path.get_ref())? {
                Ok(target) => target,
                Err(miss) => {
                    not_a_value(cx, path, miss);
                    return None;
                }
            };
            cx.gsd_comment(reason.get_ref(), reason.span(), "the reason of a choice");
            cx.push(
                Diagnostic::warning(
                    "W103",
                    format!("{} = {} is the description's own choice: {}", path.get_ref(), marked.shown, reason.get_ref()),
                )
                .at(marked.span.clone())
                .label("not from the manual")
                .help("confirm it with the firmware team and remove it from [choices]; `gsdc build --deny-warnings` refuses a build while any remains"),
            );
            Some(Decision {
                kind: DecisionKind::Choice,
                path: path.get_ref().clone(),
                value: marked.shown.clone(),
                reason: reason.get_ref().clone(),
                words: None,
            })
        })
        .collect()
}

/// E136 at a path that names no value: not a path, or one that leads
/// nowhere (with the closest key where it failed).
fn not_a_value(cx: &mut Checker, path: &Spanned<String>, miss: &Miss) {
    let diagnostic = match miss {
        Miss::NotAPath => Diagnostic::error("E136", format!("`{}` is not a key path", path.get_ref()))
            .at(path.span())
            .label("not a path")
            .help("write keys as TOML does, with `.` between them and `[n]` for an array's element: `profibus.baud_rates.\"1.5M\"`, `settings[0].default`"),
        Miss::Unknown { failed, suggestion } => Diagnostic::error(
            "E136",
            format!("`{}` names no value of the description", path.get_ref()),
        )
        .at(path.span())
        .label(format!("no `{failed}` here"))
        .help(format!(
            "a choice marks a key the description writes{}",
            suggestion.as_ref().map(|k| format!("; did you mean `{k}`?")).unwrap_or_default()
        )),
    };
    cx.push(diagnostic);
}
