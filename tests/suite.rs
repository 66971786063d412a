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

/// With `autotests = false`, a file in `tests/` that `tests.rs` does not
/// declare is compiled by nobody: its tests would pass CI unrun.
#[test]
fn every_test_file_is_a_module_of_the_one_binary() {
    let root = support::checkout("tests");
    let declared = std::fs::read_to_string(root.join("tests.rs")).unwrap();
    let undeclared: Vec<String> = std::fs::read_dir(&root)
        .unwrap()
        .map(|entry| entry.unwrap().path())
        .filter(|path| path.extension().is_some_and(|e| e == "rs"))
        .filter_map(|path| Some(path.file_stem()?.to_str()?.to_string()))
        .filter(|stem| stem != "tests")
        .filter(|stem| !declared.lines().any(|line| line == format!("mod {stem};")))
        .collect();
    assert!(
        undeclared.is_empty(),
        "not in tests/tests.rs: {undeclared:?}"
    );
}
