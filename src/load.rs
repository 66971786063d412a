//! TOML text to the raw description, with TOML and serde errors turned into
//! diagnostics that point at the offending text.

use crate::description::Description;
use crate::diag::InputLimit;
use crate::diag::{Diagnostic, Diagnostics};
use serde::Deserialize;

/// The largest description gsdc reads (E006). Real ones are a few
/// kilobytes; the limit keeps a mistaken or hostile file from costing
/// memory and time. Nesting needs no limit of gsdc's own: the toml crate
/// stops at 80 levels with an error (E001), before the stack is at risk.
pub const INPUT_LIMIT: InputLimit = InputLimit {
    max_bytes: 1 << 20,
    code: "E006",
    what: "a description",
    help: "a description is a few kilobytes of TOML: check that this is the right file",
};

/// The text of a description's bytes: UTF-8, or E000 at the first byte
/// that is not.
pub fn decode(bytes: &[u8]) -> Result<&str, Diagnostic> {
    std::str::from_utf8(bytes).map_err(|e| {
        let at = e.valid_up_to();
        Diagnostic::error("E000", "the description is not UTF-8 text")
            .at(at..at + 1)
            .label("not UTF-8")
            .help("save the description as UTF-8")
    })
}

/// Parses a description. Errors carry spans into `text`. A text larger than
/// [`INPUT_LIMIT`] is refused before it is parsed.
pub fn parse(text: &str) -> Result<Description, Diagnostics> {
    INPUT_LIMIT
        .check(text.len())
        .map_err(|d| Diagnostics(vec![d]))?;
    let fail = |error: toml::de::Error| Diagnostics(vec![diagnose(text, &error)]);
    let root = toml::de::DeTable::parse(text).map_err(fail)?;
    // `[choices]` paths resolve in the tree with spans, which the
    // deserializer then consumes: the text is parsed once for both.
    let choice_targets = crate::description::choices::resolve_targets(root.get_ref(), text);
    let mut description =
        Description::deserialize(toml::de::Deserializer::from(root)).map_err(fail)?;
    description.choice_targets = choice_targets;
    Ok(description)
}

fn diagnose(text: &str, error: &toml::de::Error) -> Diagnostic {
    let message = in_words(error.message().trim_end());
    let span = error.span().map(|s| trim_span(text, s));
    let (code, label, mut help) = classify(&message);
    if let Some(suggestion) = did_you_mean(&message) {
        let rest = help.trim_start_matches("check the spelling; ");
        help = format!("did you mean `{suggestion}`? {rest}");
    }
    Diagnostic::error(code, first_line(&message))
        .at_opt(span)
        .label(label)
        .help(help)
}

/// serde names the Rust type a number must fit; a description's author
/// needs its range.
fn in_words(message: &str) -> String {
    [
        ("expected u8", "expected a whole number from 0 to 255"),
        ("expected u16", "expected a whole number from 0 to 65535"),
        (
            "expected u32",
            "expected a whole number from 0 to 4294967295",
        ),
        ("expected i64", "expected a whole number"),
    ]
    .iter()
    .fold(message.to_string(), |m, (rust, words)| {
        m.replace(rust, words)
    })
}

/// For an unknown key or value, the expected one it is closest to: serde
/// says ``unknown field `x`, expected one of `a`, `b` `` (or `` `a` or `b` ``).
fn did_you_mean(message: &str) -> Option<&str> {
    let rest = message
        .strip_prefix("unknown field ")
        .or_else(|| message.strip_prefix("unknown variant "))?;
    let mut quoted = rest.split('`').skip(1).step_by(2);
    let written = quoted.next()?;
    crate::spelling::closest(written, quoted)
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
    } else if let Some(help) = quoted_date(message) {
        ("E003", "a string, not a date", help)
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

/// The help for a date written as a string (`date = "2026-12-01"`): TOML
/// writes dates bare. The string is suggested as it is when it is a TOML
/// date or date-time.
fn quoted_date(message: &str) -> Option<String> {
    let quoted = message
        .strip_prefix("invalid type: string \"")?
        .strip_suffix("\", expected a TOML datetime")?;
    let example = match quoted.parse::<toml::value::Datetime>() {
        Ok(_) => quoted,
        Err(_) => "2026-12-01",
    };
    Some(format!(
        "remove the quotes: TOML writes a date without them, date = {example} (or a date-time, date = 2026-12-01T07:14:47)"
    ))
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_misspelt_key_or_value_gets_the_nearest_expected_one() {
        assert_eq!(
            did_you_mean("unknown field `baud_rate`, expected one of `dpv1`, `baud_rates`"),
            Some("baud_rates")
        );
        assert_eq!(
            did_you_mean("unknown variant `pke-ind-pw`, expected one of `none`, `pke-ind-pwe`"),
            Some("pke-ind-pwe")
        );
        assert_eq!(
            did_you_mean("unknown field `colour`, expected `name` or `bits`"),
            None
        );
        assert_eq!(did_you_mean("missing field `name`"), None);
    }

    #[test]
    fn a_quoted_date_is_told_to_lose_its_quotes() {
        let help = |m| quoted_date(m).unwrap();
        assert!(
            help("invalid type: string \"2026-12-01\", expected a TOML datetime").starts_with(
                "remove the quotes: TOML writes a date without them, date = 2026-12-01 "
            )
        );
        assert!(
            help("invalid type: string \"2026-12-01T07:14:47\", expected a TOML datetime")
                .contains("date = 2026-12-01T07:14:47 ")
        );
        // Not a date in any form: the example is a date.
        assert!(
            help("invalid type: string \"1 Dec\", expected a TOML datetime")
                .contains("date = 2026-12-01 ")
        );
        assert_eq!(
            quoted_date("invalid type: integer `5`, expected a TOML datetime"),
            None
        );
        assert_eq!(quoted_date("invalid type: string \"x\", expected u8"), None);
    }

    #[test]
    fn number_types_are_said_as_ranges() {
        assert_eq!(
            in_words("invalid value: integer `256`, expected u8"),
            "invalid value: integer `256`, expected a whole number from 0 to 255"
        );
    }
}
