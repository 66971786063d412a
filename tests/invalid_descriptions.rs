//! Every description under tests/fixtures/invalid/ is rejected with the code
//! its `# expect:` line names, and its rendered diagnostics are snapshotted
//! (`tests/snapshots/invalid/<fixture>.snap`).

use crate::support::{self, descriptions};
use gsdc::Source;

#[test]
fn there_are_enough_invalid_fixtures() {
    assert!(descriptions::invalid_fixtures().len() >= 15);
}

#[test]
fn each_invalid_description_is_rejected_with_its_code() {
    let fixtures = descriptions::invalid_fixtures();
    let names: Vec<&str> = fixtures
        .iter()
        .map(|path| path.file_stem().unwrap().to_str().unwrap())
        .collect();
    support::snapshots_in("invalid", || {
        for path in &fixtures {
            let name = path.file_name().unwrap().to_str().unwrap();
            let text = std::fs::read_to_string(path).unwrap();
            // Read as the build reads it: files the description names are
            // found beside it.
            let loaded = gsdc::build::load_file(path, name).unwrap();
            let (ir, diagnostics) = (loaded.ir, loaded.findings.diagnostics);
            assert!(ir.is_none(), "{name} was accepted");
            let code = descriptions::expected_code(&text)
                .expect("each fixture has an `# expect: CODE` line");
            let codes: Vec<&str> = diagnostics.iter().map(|d| d.code).collect();
            assert!(
                codes.contains(&code),
                "{name}: expected {code}, got {codes:?}"
            );
            for d in diagnostics.iter() {
                assert!(
                    d.span.is_some(),
                    "{name}: {} has no place in the file",
                    d.code
                );
                assert!(d.help.is_some(), "{name}: {} has no help", d.code);
            }
            let path = format!("tests/fixtures/invalid/{name}");
            let source = Source::new(&path, &text);
            let rendered: String = diagnostics.iter().map(|d| source.render(d)).collect();
            insta::assert_snapshot!(name.trim_end_matches(".toml"), rendered);
        }
    });
    support::assert_no_orphan_snapshots("invalid", names);
}
