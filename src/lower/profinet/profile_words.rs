//! PROFIdrive's standard telegrams' words, as the profile abbreviates and
//! names them, and `[profinet.profile_word_names]`: what the GSDML's data
//! items call them where not the profile's names.

use super::super::checks::Checker;
use crate::description as raw;
use crate::diag::Diagnostic;
use crate::i18n::{files, Phrase};
use crate::ir::profinet::ModuleKind;
use crate::ir::{Direction, Layout, Text};
use std::collections::BTreeMap;
use toml::Spanned;

/// The profile's words of PROFIdrive's standard telegram 1 or 2 one way, in
/// order: each its abbreviation (the key of
/// `[profinet.profile_word_names]`) and its name. Telegram 1 (MASTERDRIVES
/// Compendium table 8.2-16: "STW1 Control word 1", "NSOLL_A Speed setpoint
/// A", "ZSW1 Status word 1", "NIST_A Speed actual value A"); telegram 2:
/// control or status word 1, the 32-bit speed setpoint or actual value,
/// control or status word 2, as ABB's FENA declares them (Unsigned16,
/// Unsigned32, Unsigned16).
pub(crate) fn profile_words(
    kind: ModuleKind,
    direction: Direction,
) -> &'static [(&'static str, Phrase)] {
    match (kind, direction) {
        (ModuleKind::StandardTelegram2, Direction::In) => &[
            ("ZSW1", files::ZSW1),
            ("NIST_B", files::NIST_B),
            ("ZSW2", files::ZSW2),
        ],
        (ModuleKind::StandardTelegram2, Direction::Out) => &[
            ("STW1", files::STW1),
            ("NSOLL_B", files::NSOLL_B),
            ("STW2", files::STW2),
        ],
        (_, Direction::In) => &[("ZSW1", files::ZSW1), ("NIST_A", files::NIST_A)],
        (_, Direction::Out) => &[("STW1", files::STW1), ("NSOLL_A", files::NSOLL_A)],
    }
}

/// The names of the profile's words, by abbreviation: each a word of a
/// PROFIdrive standard telegram offered (E194 for another).
pub fn lower(
    cx: &mut Checker,
    given: &BTreeMap<Spanned<String>, Spanned<raw::Text>>,
    offered: &[(ModuleKind, Layout)],
    profidrive: bool,
) -> BTreeMap<String, Text> {
    let mut carried: Vec<&str> = Vec::new();
    let telegrams = offered
        .iter()
        .filter(|(kind, _)| profidrive && *kind != ModuleKind::Pzd);
    for (kind, _) in telegrams {
        for direction in [Direction::Out, Direction::In] {
            for (word, _) in profile_words(*kind, direction) {
                if !carried.contains(word) {
                    carried.push(word);
                }
            }
        }
    }
    let mut names = BTreeMap::new();
    for (word, name) in given {
        if !carried.contains(&word.get_ref().as_str()) {
            cx.push(no_such_word(word, &carried));
            continue;
        }
        let what = format!("profinet.profile_word_names.{}", word.get_ref());
        names.insert(word.get_ref().clone(), cx.text(name, None, &what));
    }
    names
}

fn no_such_word(word: &Spanned<String>, carried: &[&str]) -> Diagnostic {
    let help = match carried {
        [] => "no PROFIdrive standard telegram is offered: remove the table, or offer standard_telegram_1 or standard_telegram_2 on a PROFIdrive card".to_string(),
        words => format!(
            "name a word of the telegrams offered, as the profile abbreviates it: {}",
            words.join(", ")
        ),
    };
    Diagnostic::error(
        "E194",
        format!(
            "`{}` is no word of a PROFIdrive standard telegram offered",
            word.get_ref()
        ),
    )
    .at(word.span())
    .label("no such word")
    .help(help)
}
