//! The rule table (`gsdc::RULES`) is docs/rules.md's list of rules, code
//! and title, in its order; it holds exactly the codes the source emits; and
//! every description code has an invalid fixture that shows it.

use crate::support::{self, descriptions};
use std::collections::BTreeSet;

/// Codes written as string literals (`"E104"`) anywhere under src/.
fn codes_in_source() -> BTreeSet<String> {
    support::rust_files("src")
        .into_iter()
        .filter(|path| !path.ends_with("src/rules.rs"))
        .flat_map(|path| literal_codes(&std::fs::read_to_string(path).unwrap()))
        .collect()
}

fn literal_codes(text: &str) -> Vec<String> {
    text.split('"')
        .filter(|s| {
            s.len() == 4
                && (s.starts_with('E') || s.starts_with('W'))
                && s[1..].bytes().all(|b| b.is_ascii_digit())
        })
        .map(str::to_string)
        .collect()
}

/// `### E101: out of range` and `#### E201 cannot read this line`: code
/// and title of each rule the document describes, in its order.
fn documented_rules() -> Vec<(String, String)> {
    include_str!("../docs/rules.md")
        .lines()
        .filter_map(|line| {
            let heading = line
                .strip_prefix("####")
                .or_else(|| line.strip_prefix("###"))?;
            let (code, title) = heading.trim_start().split_once(' ')?;
            let code = code.trim_end_matches(':');
            let is_code = code.len() == 4
                && matches!(code.as_bytes()[0], b'E' | b'W')
                && code[1..].bytes().all(|b| b.is_ascii_digit());
            is_code.then(|| (code.to_string(), title.to_string()))
        })
        .collect()
}

#[test]
fn the_rule_table_is_the_documents_list() {
    let table: Vec<(String, String)> = gsdc::RULES
        .iter()
        .map(|r| (r.code.to_string(), r.title.to_string()))
        .collect();
    assert_eq!(table, documented_rules());
}

#[test]
fn the_rule_table_holds_the_codes_the_source_emits() {
    let table: BTreeSet<String> = gsdc::RULES.iter().map(|r| r.code.to_string()).collect();
    assert_eq!(table.len(), gsdc::RULES.len(), "a code listed twice");
    assert_eq!(codes_in_source(), table);
}

/// A code's letter is its severity.
#[test]
fn errors_are_e_and_warnings_w() {
    for rule in gsdc::RULES {
        let expected = match rule.code.as_bytes()[0] {
            b'E' => gsdc::Severity::Error,
            _ => gsdc::Severity::Warning,
        };
        assert_eq!(rule.severity, expected, "{}", rule.code);
    }
}

#[test]
fn every_description_code_has_a_fixture() {
    let expected: BTreeSet<String> = descriptions::invalid_fixtures()
        .iter()
        .filter_map(|path| {
            let text = std::fs::read_to_string(path).unwrap();
            descriptions::expected_code(&text).map(str::to_string)
        })
        .collect();
    // E000 needs bytes that are not UTF-8 (cli.rs), E006 a file over 1 MiB
    // (adversarial.rs); W1xx are warnings.
    let uncovered: Vec<String> = codes_in_source()
        .into_iter()
        .filter(|c| c.starts_with("E0") || c.starts_with("E1"))
        .filter(|c| c != "E000" && c != "E006" && !expected.contains(c))
        .collect();
    assert!(uncovered.is_empty(), "no invalid fixture for {uncovered:?}");
}
