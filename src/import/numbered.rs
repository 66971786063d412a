//! Names numbered by what they stand for: `PZD1(master->slaver)`,
//! `PZD2(master->slaver)` are one name with `{n}` from 1, as a description
//! writes a mapping's entries or a gateway's node parameters.

use super::toml_out::quote;
use crate::device::Text;

/// Names as `name = "PZD{n} ..."` writes them, `{n}` counting up from
/// `first`.
pub(super) struct Pattern {
    /// The TOML value: a string, or a table of every language.
    pub name: String,
    pub first: u32,
}

/// The names as one name with `{n}` for a number that counts up by one
/// from name to name, from the first name's, in every language: a PZD
/// mapping's `PZD{n}(master->slaver)`, a gateway's `Slave {n} TPDO words`.
pub(super) fn pattern(names: &[&Text]) -> Option<Pattern> {
    let first = names.first()?;
    // Each try reads every name: a name of many numbers stays linear.
    let tried = numbers_in(&first.primary).into_iter().take(MOST_TRIED);
    tried.into_iter().find_map(|start| {
        let pattern_of = |text_of: &dyn Fn(&Text) -> Option<String>| -> Option<String> {
            let mut found: Option<String> = None;
            for (i, name) in names.iter().enumerate() {
                let n = start.checked_add(u32::try_from(i).ok()?)?;
                let p = with_placeholder(&text_of(name)?, n)?;
                if found.as_ref().is_some_and(|q| *q != p) {
                    return None;
                }
                found = Some(p);
            }
            found
        };
        let primary = pattern_of(&|t: &Text| Some(t.primary.to_string()))?;
        let mut parts = vec![format!("en = {}", quote(&primary))];
        for code in first.translations.keys() {
            let p = pattern_of(&|t: &Text| t.translations.get(code).map(str::to_string))?;
            parts.push(format!("{code} = {}", quote(&p)));
        }
        let name = match parts.len() {
            1 => quote(&primary),
            _ => format!("{{ {} }}", parts.join(", ")),
        };
        Some(Pattern { name, first: start })
    })
}

/// The numbers of the first name tried as the one that counts.
const MOST_TRIED: usize = 8;

/// The decimal numbers a text has, in order.
fn numbers_in(text: &str) -> Vec<u32> {
    text.split(|c: char| !c.is_ascii_digit())
        .filter_map(|s| s.parse().ok())
        .collect()
}

/// `text` with its first standalone `n` written `{n}`.
fn with_placeholder(text: &str, n: u32) -> Option<String> {
    let digits = n.to_string();
    let bytes = text.as_bytes();
    let at = text.match_indices(&digits).map(|(i, _)| i).find(|&i| {
        let before = i.checked_sub(1).map(|b| bytes[b].is_ascii_digit());
        let after = bytes.get(i + digits.len()).map(u8::is_ascii_digit);
        before != Some(true) && after != Some(true)
    })?;
    Some(format!(
        "{}{{n}}{}",
        &text[..at],
        &text[at + digits.len()..]
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn texts(names: &[&str]) -> Vec<Text> {
        names.iter().map(Text::plain).collect()
    }

    fn found(names: &[&str]) -> Option<(String, u32)> {
        let texts = texts(names);
        let refs: Vec<&Text> = texts.iter().collect();
        pattern(&refs).map(|p| (p.name, p.first))
    }

    #[test]
    fn a_name_is_found_in_its_number_that_counts_up() {
        let slaves = [
            "Slave 1 TPDO words",
            "Slave 2 TPDO words",
            "Slave 3 TPDO words",
        ];
        assert_eq!(found(&slaves), Some(("\"Slave {n} TPDO words\"".into(), 1)));
        // The number that counts is the second; the first stays.
        let nodes = ["PDO2 of node 7", "PDO2 of node 8"];
        assert_eq!(found(&nodes), Some(("\"PDO2 of node {n}\"".into(), 7)));
        assert_eq!(found(&["Node 9 words", "Node 11 words"]), None);
        assert_eq!(found(&["Words", "Words"]), None);
        assert_eq!(found(&["Node 4294967295", "Node 4294967296"]), None);
    }
}
