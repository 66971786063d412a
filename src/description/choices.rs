//! Where each path of a description's `[choices]` leads: a key path as
//! TOML writes it, with `[n]` for the n-th element of an array (from 0):
//! `profibus.min_slave_interval`, `profibus.baud_rates."1.5M"`,
//! `settings[0].default`. Resolved in the tree with spans that the
//! description is then read from, so the text is parsed once.

use std::collections::BTreeMap;
use std::ops::Range;
use toml::de::{DeTable, DeValue};
use toml::Spanned;

/// The longest value a decision shows; longer ones end in `...`.
const MAX_SHOWN: usize = 60;

/// Where each path of `[choices]` leads in the description, found in the
/// tree with spans that the description is then read from (one parse of
/// the text for both, which a large imported description's build feels).
#[derive(Debug, Default)]
pub struct ChoiceTargets(BTreeMap<String, Result<Target, Miss>>);

impl ChoiceTargets {
    /// What `path` leads to; `None` for a path `[choices]` does not have.
    pub fn get(&self, path: &str) -> Option<&Result<Target, Miss>> {
        self.0.get(path)
    }
}

/// The value a path names: where it is written, and its text as shown.
#[derive(Debug)]
pub struct Target {
    pub span: Range<usize>,
    pub shown: String,
}

/// Why a path names no value.
#[derive(Debug)]
pub enum Miss {
    NotAPath,
    /// The key where it failed, and the closest key of the table there.
    Unknown {
        failed: String,
        suggestion: Option<String>,
    },
}

/// Each path of the `[choices]` table of `root`, resolved.
pub fn resolve_targets(root: &DeTable, text: &str) -> ChoiceTargets {
    let Some(DeValue::Table(choices)) = root.get("choices").map(Spanned::get_ref) else {
        return ChoiceTargets::default();
    };
    let resolved = choices
        .keys()
        .map(|path| {
            let path = path.get_ref().to_string();
            let target = resolve(root, &path, text);
            (path, target)
        })
        .collect();
    ChoiceTargets(resolved)
}
/// The value `path` names, with its span and text.
fn resolve(root: &DeTable, path: &str, text: &str) -> Result<Target, Miss> {
    let segments = parse_path(path).ok_or(Miss::NotAPath)?;
    let mut table = root;
    let mut value: Option<&Spanned<DeValue>> = None;
    for (i, segment) in segments.iter().enumerate() {
        if i > 0 {
            table = match value.map(Spanned::get_ref) {
                Some(DeValue::Table(t)) => t,
                _ => return Err(unknown(&segments[..i], None)),
            };
        }
        let Some(found) = table.get(segment.key.as_str()) else {
            return Err(unknown(&segments[..=i], Some(table)));
        };
        value = Some(found);
        for &index in &segment.indexes {
            value = match value.map(Spanned::get_ref) {
                Some(DeValue::Array(items)) => items.get(index),
                _ => None,
            };
            if value.is_none() {
                return Err(unknown(&segments[..=i], None));
            }
        }
    }
    let marked = value.ok_or(Miss::NotAPath)?;
    let span = marked.span();
    let shown = shown(marked.get_ref(), &text[span.clone()]);
    Ok(Target { span, shown })
}

/// Where the path failed, with the closest key of the table there.
fn unknown(reached: &[Segment], table: Option<&DeTable>) -> Miss {
    let failed = reached.last().map_or("", |s| s.key.as_str());
    let suggestion = table.and_then(|t| {
        crate::spelling::closest(failed, t.keys().map(|k| k.get_ref().as_ref())).map(str::to_string)
    });
    Miss::Unknown {
        failed: failed.to_string(),
        suggestion,
    }
}

struct Segment {
    key: String,
    indexes: Vec<usize>,
}

/// `a.b."1.5M".c[0][1]`: bare or quoted keys, each with any `[n]`.
fn parse_path(path: &str) -> Option<Vec<Segment>> {
    let mut segments = Vec::new();
    let mut rest = path;
    loop {
        let (key, after) = if let Some(quoted) = rest.strip_prefix('"') {
            let end = quoted.find('"')?;
            (quoted[..end].to_string(), &quoted[end + 1..])
        } else {
            let end = rest
                .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == '-'))
                .unwrap_or(rest.len());
            (rest[..end].to_string(), &rest[end..])
        };
        if key.is_empty() {
            return None;
        }
        let mut indexes = Vec::new();
        let mut after = after;
        while let Some(inner) = after.strip_prefix('[') {
            let end = inner.find(']')?;
            let index = super::digits(&inner[..end], 10)?;
            indexes.push(usize::try_from(index).ok()?);
            after = &inner[end + 1..];
        }
        segments.push(Segment { key, indexes });
        match after.strip_prefix('.') {
            Some(next) => rest = next,
            None if after.is_empty() => return Some(segments),
            None => return None,
        }
    }
}

/// The value's text on one line, at most [`MAX_SHOWN`] characters. A table
/// under its own `[header]` shows as `{ ... }`: its span is the header, and
/// the header's words are the path again, not the value.
fn shown(value: &DeValue, source: &str) -> String {
    if matches!(value, DeValue::Table(_)) && source.starts_with('[') {
        return "{ ... }".to_owned();
    }
    let one_line = source.split_whitespace().collect::<Vec<_>>().join(" ");
    if one_line.chars().count() <= MAX_SHOWN {
        return one_line;
    }
    let cut: String = one_line.chars().take(MAX_SHOWN - 3).collect();
    format!("{cut}...")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn keys(path: &str) -> Option<Vec<(String, Vec<usize>)>> {
        parse_path(path).map(|s| s.into_iter().map(|s| (s.key, s.indexes)).collect())
    }

    #[test]
    fn paths_are_toml_keys_with_indexes() {
        assert_eq!(
            keys("profibus.baud_rates.\"1.5M\""),
            Some(vec![
                ("profibus".into(), vec![]),
                ("baud_rates".into(), vec![]),
                ("1.5M".into(), vec![])
            ])
        );
        assert_eq!(
            keys("settings[0].default"),
            Some(vec![
                ("settings".into(), vec![0]),
                ("default".into(), vec![])
            ])
        );
        assert_eq!(keys("a..b"), None);
        assert_eq!(keys("a[x]"), None);
        assert_eq!(keys("settings[+0].default"), None);
        assert_eq!(keys("a b"), None);
        assert_eq!(keys(""), None);
    }

    /// How the value of the top-level `key` in `text` is shown.
    fn shown_key(text: &str, key: &str) -> String {
        let root = DeTable::parse(text).unwrap();
        let value = root.get_ref().get(key).unwrap();
        shown(value.get_ref(), &text[value.span()])
    }

    #[test]
    fn long_values_are_cut_and_kept_on_one_line() {
        assert_eq!(shown_key("a = [2,\n 6]", "a"), "[2, 6]");
        let long = shown_key(&format!("a = \"{}\"", "x".repeat(100)), "a");
        assert_eq!(long.chars().count(), MAX_SHOWN);
        assert!(long.ends_with("..."));
    }

    #[test]
    fn tables_show_their_values_not_their_header() {
        assert_eq!(shown_key("t = { x = 1 }", "t"), "{ x = 1 }");
        assert_eq!(shown_key("[t]\nx = 1\n", "t"), "{ ... }");
    }
}
