//! TOML text to the raw description, with TOML and serde errors turned into
//! diagnostics that point at the offending text.

use crate::description::Description;
use crate::diag::{Diagnostic, Diagnostics};

/// Parses a description. Errors carry spans into `text`.
pub fn parse(text: &str) -> Result<Description, Diagnostics> {
    toml::from_str::<Description>(text).map_err(|error| Diagnostics(vec![diagnose(text, &error)]))
}

fn diagnose(text: &str, error: &toml::de::Error) -> Diagnostic {
    let message = error.message().trim_end().to_string();
    let span = error.span().map(|s| trim_span(text, s));
    let (code, label, help) = classify(&message);
    Diagnostic::error(code, first_line(&message))
        .at_opt(span)
        .label(label)
        .help(help)
}

/// Codes by what serde and toml say; the wording is theirs and stable
/// enough, and a wrong guess only changes the code, never hides the error.
fn classify(message: &str) -> (&'static str, &'static str, String) {
    if message.starts_with("unknown field") {
        (
            "E002",
            "unknown key",
            "check the spelling; docs/description.md lists the keys of every table".into(),
        )
    } else if message.starts_with("missing field") {
        (
            "E004",
            "missing key",
            "add the key; docs/description.md shows a complete example".into(),
        )
    } else if message.starts_with("invalid type")
        || message.starts_with("invalid value")
        || message.starts_with("unknown variant")
        || message.starts_with("invalid length")
    {
        (
            "E003",
            "wrong type or value",
            "docs/description.md gives the type of every key".into(),
        )
    } else if message.contains("duplicate key") {
        (
            "E005",
            "duplicate key",
            "each key may appear once in a table".into(),
        )
    } else {
        (
            "E001",
            "TOML syntax error",
            "the description must be valid TOML (https://toml.io)".into(),
        )
    }
}

fn first_line(message: &str) -> String {
    message.lines().next().unwrap_or(message).to_string()
}

/// toml reports some spans covering a whole table; a caret on its first line
/// is enough.
fn trim_span(text: &str, span: std::ops::Range<usize>) -> std::ops::Range<usize> {
    let end = text
        .get(span.clone())
        .and_then(|s| s.find('\n'))
        .map_or(span.end, |newline| span.start + newline);
    span.start..end.max(span.start)
}
