//! Every rule code the source can emit is documented in docs/rules.md, and
//! every description code has an invalid fixture that shows it.

use std::collections::BTreeSet;
use std::path::Path;

/// Codes written as string literals (`"E104"`) anywhere under src/.
fn codes_in_source() -> BTreeSet<String> {
    let mut codes = BTreeSet::new();
    let mut dirs = vec![Path::new(env!("CARGO_MANIFEST_DIR")).join("src")];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                dirs.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                codes.extend(literal_codes(&std::fs::read_to_string(path).unwrap()));
            }
        }
    }
    codes
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

#[test]
fn every_code_is_documented() {
    let docs = include_str!("../docs/rules.md");
    let missing: Vec<String> = codes_in_source()
        .into_iter()
        .filter(|code| !docs.contains(&format!("### {code}")))
        .collect();
    assert!(missing.is_empty(), "not in docs/rules.md: {missing:?}");
}

#[test]
fn every_description_code_has_a_fixture() {
    let fixtures_dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/invalid");
    let expected: BTreeSet<String> = std::fs::read_dir(fixtures_dir)
        .unwrap()
        .filter_map(|e| {
            let text = std::fs::read_to_string(e.unwrap().path()).ok()?;
            Some(
                text.lines()
                    .find_map(|l| l.strip_prefix("# expect: "))?
                    .trim()
                    .to_string(),
            )
        })
        .collect();
    // E000 needs bytes that are not UTF-8 (tests/cli.rs), E006 a file over
    // 1 MiB (tests/adversarial.rs); W1xx are warnings.
    let uncovered: Vec<String> = codes_in_source()
        .into_iter()
        .filter(|c| c.starts_with("E0") || c.starts_with("E1"))
        .filter(|c| c != "E000" && c != "E006" && !expected.contains(c))
        .collect();
    assert!(uncovered.is_empty(), "no invalid fixture for {uncovered:?}");
}
