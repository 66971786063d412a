//! `[choices]`: the values a description marks as its own choice, each
//! with its reason. A path names a key as TOML writes it, with `[n]` for the
//! n-th element of an array (from 0): `profibus.min_slave_interval`,
//! `profibus.baud_rates."1.5M"`, `settings[0].default`. A path names a key
//! the description writes; a table marks everything in it.

use super::checks::Checker;
use crate::diag::Diagnostic;
use crate::ir::{Decision, DecisionKind};
use std::collections::BTreeMap;
use toml::de::{DeTable, DeValue};
use toml::Spanned;

/// The longest value a decision shows; longer ones end in `...`.
const MAX_SHOWN: usize = 60;

pub fn lower(
    cx: &mut Checker,
    choices: &BTreeMap<Spanned<String>, Spanned<String>>,
    text: &str,
) -> Vec<Decision> {
    if choices.is_empty() {
        return Vec::new();
    }
    // The description parsed already: the tree with spans cannot fail now.
    let Ok(root) = DeTable::parse(text) else {
        return Vec::new();
    };
    choices
        .iter()
        .filter_map(|(path, reason)| {
            let marked = resolve(cx, root.get_ref(), path)?;
            cx.gsd_comment(reason.get_ref(), reason.span(), "the reason of a choice");
            let span = marked.span();
            let value = shown(marked.get_ref(), &text[span.clone()]);
            cx.push(
                Diagnostic::warning(
                    "W103",
                    format!("{} = {value} is the description's own choice: {}", path.get_ref(), reason.get_ref()),
                )
                .at(span)
                .label("not from the manual")
                .help("confirm it with the firmware team and remove it from [choices]; `gsdc build --deny-warnings` refuses a build while any remains"),
            );
            Some(Decision {
                kind: DecisionKind::Choice,
                path: path.get_ref().clone(),
                value,
                reason: reason.get_ref().clone(),
                words: None,
            })
        })
        .collect()
}

/// The value `path` names, or E136 at the path.
fn resolve<'a>(
    cx: &mut Checker,
    root: &'a DeTable<'a>,
    path: &Spanned<String>,
) -> Option<&'a Spanned<DeValue<'a>>> {
    let Some(segments) = parse_path(path.get_ref()) else {
        cx.push(
            Diagnostic::error("E136", format!("`{}` is not a key path", path.get_ref()))
                .at(path.span())
                .label("not a path")
                .help("write keys as TOML does, with `.` between them and `[n]` for an array's element: `profibus.baud_rates.\"1.5M\"`, `settings[0].default`"),
        );
        return None;
    };
    let mut table = root;
    let mut value: Option<&Spanned<DeValue>> = None;
    for (i, segment) in segments.iter().enumerate() {
        if i > 0 {
            table = match value.map(Spanned::get_ref) {
                Some(DeValue::Table(t)) => t,
                _ => return unknown(cx, path, &segments[..i], None),
            };
        }
        let Some(found) = table.get(segment.key.as_str()) else {
            return unknown(cx, path, &segments[..=i], Some(table));
        };
        value = Some(found);
        for &index in &segment.indexes {
            value = match value.map(Spanned::get_ref) {
                Some(DeValue::Array(items)) => items.get(index),
                _ => None,
            };
            if value.is_none() {
                return unknown(cx, path, &segments[..=i], None);
            }
        }
    }
    value
}

/// E136: the path leads nowhere; the closest key of the table where it
/// failed is suggested.
fn unknown<T>(
    cx: &mut Checker,
    path: &Spanned<String>,
    reached: &[Segment],
    table: Option<&DeTable>,
) -> Option<T> {
    let failed = reached.last().map_or("", |s| s.key.as_str());
    let suggestion = table.and_then(|t| {
        crate::spelling::closest(failed, t.keys().map(|k| k.get_ref().as_ref()))
            .map(|k| format!("; did you mean `{k}`?"))
    });
    cx.push(
        Diagnostic::error(
            "E136",
            format!("`{}` names no value of the description", path.get_ref()),
        )
        .at(path.span())
        .label(format!("no `{failed}` here"))
        .help(format!(
            "a choice marks a key the description writes{}",
            suggestion.unwrap_or_default()
        )),
    );
    None
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
            let index = crate::ir::numbering::digits(&inner[..end], 10)?;
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
