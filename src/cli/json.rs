//! `--format json`: one object per finding and one per file, through
//! serde_json, each on one line.

use crate::diag::{Diagnostic, Source};
use serde::Serialize;

/// A finding with its place as line and column (1-based), `null` where it
/// has none.
#[derive(Serialize)]
struct Finding<'a> {
    file: &'a str,
    line: Option<usize>,
    column: Option<usize>,
    severity: &'static str,
    code: &'static str,
    subject: Option<&'a str>,
    message: &'a str,
    label: Option<&'a str>,
    help: Option<&'a str>,
    /// The other place of a finding about two; left out when it has none.
    #[serde(skip_serializing_if = "Option::is_none")]
    also: Option<AlsoAt<'a>>,
}

/// A finding's second place.
#[derive(Serialize)]
struct AlsoAt<'a> {
    line: usize,
    column: usize,
    label: &'a str,
}

/// What ends a file's findings: CI can count clean files too.
#[derive(Serialize)]
struct Summary<'a> {
    file: &'a str,
    errors: usize,
    warnings: usize,
}

pub fn finding(source: &Source, d: &Diagnostic) -> String {
    let (line, column) = d
        .span
        .as_ref()
        .map(|span| source.line_col(span.start))
        .unzip();
    to_line(&Finding {
        file: source.name,
        line,
        column,
        severity: d.severity.as_str(),
        code: d.code,
        subject: d.subject(),
        message: &d.message,
        label: d.label.as_deref(),
        help: d.help.as_deref(),
        also: d.also().map(|also| {
            let (line, column) = source.line_col(also.span.start);
            AlsoAt {
                line,
                column,
                label: &also.label,
            }
        }),
    })
}

/// The summary of a file not checked, and why: no findings.
#[derive(Serialize)]
struct Skipped<'a> {
    file: &'a str,
    errors: usize,
    warnings: usize,
    skipped: &'a str,
}

pub fn skipped(file: &str, why: &str) -> String {
    to_line(&Skipped {
        file,
        errors: 0,
        warnings: 0,
        skipped: why,
    })
}

pub fn summary(file: &str, errors: usize, warnings: usize) -> String {
    to_line(&Summary {
        file,
        errors,
        warnings,
    })
}

fn to_line(value: &impl Serialize) -> String {
    serde_json::to_string(value).expect("strings and numbers serialize")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_finding_is_one_line_with_quotes_and_controls_escaped() {
        let d = Diagnostic::warning("W101", "a \"b\"\u{1}").help("x\ny");
        let source = Source::new("f\tg", "");
        assert_eq!(
            finding(&source, &d),
            "{\"file\":\"f\\tg\",\"line\":null,\"column\":null,\"severity\":\"warning\",\"code\":\"W101\",\"subject\":null,\"message\":\"a \\\"b\\\"\\u0001\",\"label\":null,\"help\":\"x\\ny\"}"
        );
        let d = Diagnostic::error("E101", "m").at(4..5);
        let source = Source::new("f", "ab\ncd\n");
        assert!(finding(&source, &d).contains("\"line\":2,\"column\":2,"));
    }

    #[test]
    fn a_summary_counts_errors_and_warnings() {
        assert_eq!(
            summary("x.gsd", 1, 2),
            "{\"file\":\"x.gsd\",\"errors\":1,\"warnings\":2}"
        );
    }
}
