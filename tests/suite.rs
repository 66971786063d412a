//! The suite's own rule: no test is left out. A test with the `ignore`
//! attribute, or a doc example marked `ignore`, is reported as ignored and
//! passes CI unrun; a test that cannot run here calls `support::cannot_run`, which
//! fails under CI, and a doc example that is not a test is `text`.

use crate::support;

#[test]
fn no_test_is_ignored() {
    // Written in two pieces, so that this file does not hold them whole.
    let marks = [
        concat!("#[", "ignore"),
        concat!("```", "ignore"),
        concat!(",", "ignore"),
    ];
    let mut files = support::rust_files("src");
    files.extend(support::rust_files("tests"));
    assert!(files.len() > 50, "{files:?}");
    let ignored: Vec<String> = files
        .iter()
        .flat_map(|path| {
            let text = std::fs::read_to_string(path).unwrap();
            let lines: Vec<String> = text
                .lines()
                .enumerate()
                .filter(|(_, line)| marks.iter().any(|mark| line.contains(mark)))
                .map(|(n, line)| format!("{}:{}: {}", path.display(), n + 1, line.trim()))
                .collect();
            lines
        })
        .collect();
    assert!(ignored.is_empty(), "ignored tests: {ignored:#?}");
}
