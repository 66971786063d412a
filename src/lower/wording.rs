//! gsdc's own words in the device files: every text of the GSD and the
//! GSDML that is not the description's (which quotes its manual or
//! translates it), so that every generated file can say which words are
//! gsdc's and no engineer takes them for the manual's.

use crate::ir::{Profibus, Profinet, Text, Wording};
use std::collections::BTreeSet;

/// The texts gsdc wrote: the GSD's module names (a PPO type's, a gateway's
/// modules'; not those the description names), and each GSDML text that is not one the description gave,
/// once per TextId, in the order of the plan.
pub fn wording(
    (given, languages): (&BTreeSet<String>, &[String]),
    profibus: Option<&Profibus>,
    gateway: Option<&crate::ir::Gateway>,
    profinet: Option<&Profinet>,
) -> Vec<Wording> {
    let mut found = Vec::new();
    // The draft notice before the device's info text.
    if let Some(info) = profibus.and_then(|p| p.info_text.as_ref()) {
        if !given.contains(info) {
            found.push(Wording {
                place: "GSD Info_Text".to_string(),
                text: Text::english(info.clone()),
                around_the_descriptions: has_given_words(given, &Text::english(info.clone())),
            });
        }
    }
    let gsd_modules = profibus
        .into_iter()
        .flat_map(|p| p.modules.iter().map(|m| m.name.clone()))
        .chain(
            gateway
                .into_iter()
                .flat_map(|g| g.modules.iter().map(|m| m.name.clone())),
        );
    // A module of `[[profibus.modules]]` carries the description's name.
    for name in gsd_modules.filter(|name| !given.contains(name)) {
        found.push(Wording {
            place: "GSD Module".to_string(),
            text: Text::english(name),
            around_the_descriptions: false,
        });
    }
    let mut seen = BTreeSet::new();
    for text_ref in profinet.into_iter().flat_map(Profinet::text_refs) {
        // The file has the description's languages only.
        let mut text = text_ref.text.clone();
        text.others.retain(|(code, _)| languages.contains(code));
        if !seen.insert(text_ref.id.as_str()) || is_given(given, &text) {
            continue;
        }
        found.push(Wording {
            place: format!("GSDML {}", text_ref.id),
            around_the_descriptions: has_given_words(given, &text),
            text,
        });
    }
    found
}

/// Whether each language of `text` is a text the description gave.
fn is_given(given: &BTreeSet<String>, text: &Text) -> bool {
    given.contains(&text.en) && text.others.iter().all(|(_, t)| given.contains(t))
}

/// The fewest characters a text of the description has for gsdc to tell it
/// inside one of its own: `1` or `PZD` would be found everywhere.
const MIN_WORDS: usize = 6;

/// Whether gsdc wrote `text` around a text the description gave (a
/// module's info text, a bit's name with its values).
fn has_given_words(given: &BTreeSet<String>, text: &Text) -> bool {
    // The length first: it rules out most given texts (a large file's
    // hundreds of diagnosis texts, longer than gsdc's) without counting.
    given.iter().any(|g| {
        g.len() < text.en.len() && g.chars().count() >= MIN_WORDS && text.en.contains(g.as_str())
    })
}
