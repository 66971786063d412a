//! A new user's first day with the description (issue 23): a second
//! release on one day, parameters numbered without a separator, and a
//! setting fixed per PROFINET module in a description with both buses.
//! Self-contained: its helpers are its own.

use gsdc::{Artifact, ArtifactKind, Diagnostics};

const PROFIDRIVE: &str = include_str!("fixtures/valid/profidrive.toml");

/// `text` with `from` replaced by `to`, which must be there.
fn edited(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "`{from}` is not in the text");
    text.replacen(from, to, 1)
}

fn load(text: &str) -> (Option<gsdc::Ir>, Diagnostics) {
    gsdc::load("user.toml", text)
}

fn compiled(text: &str) -> Vec<Artifact> {
    let (ir, diagnostics) = load(text);
    let ir = ir.unwrap_or_else(|| panic!("{diagnostics:?}"));
    gsdc::compile(&ir).unwrap()
}

fn codes(text: &str) -> Vec<&'static str> {
    load(text).1.iter().map(|d| d.code).collect()
}

// ---------------------------------------------------------------------------
// A second release on one day: the GSDML file name with a time.

#[test]
fn a_local_date_time_names_the_gsdml_with_its_time() {
    let text = edited(
        PROFIDRIVE,
        "date = 2026-02-28",
        "date = 2026-12-01T07:14:47",
    );
    let files = compiled(&text);
    let gsdml = files
        .iter()
        .find(|f| f.kind == ArtifactKind::Gsdml)
        .unwrap();
    assert_eq!(gsdml.file_name, "GSDML-V2.32-Acme-X2-20261201-071447.xml");
    // gsdc's reader takes the name for what PI's naming allows (a name it
    // did not would be a finding of the naming rules).
    let contents = std::str::from_utf8(&gsdml.contents).unwrap();
    let findings = gsdc::gsdml::check(contents, Some(&gsdml.file_name));
    assert!(findings.is_empty(), "{findings:?}");
    // TOML 1.1 may leave out the seconds: they are 00.
    let text = edited(PROFIDRIVE, "date = 2026-02-28", "date = 2026-12-01 07:14");
    let files = compiled(&text);
    assert!(files
        .iter()
        .any(|f| f.file_name == "GSDML-V2.32-Acme-X2-20261201-071400.xml"));
    // A plain date stays as it was.
    assert!(compiled(PROFIDRIVE)
        .iter()
        .any(|f| f.file_name == "GSDML-V2.32-Acme-X2-20260228.xml"));
}

#[test]
fn what_a_file_name_cannot_say_is_e131() {
    for date in [
        "2026-12-01T07:14:47Z",
        "2026-12-01T07:14:47+01:00",
        "2026-12-01T07:14:47.5",
        "07:14:47",
    ] {
        let text = edited(PROFIDRIVE, "date = 2026-02-28", &format!("date = {date}"));
        assert_eq!(codes(&text), ["E131"], "{date}");
    }
}

#[test]
fn a_quoted_date_is_told_to_lose_its_quotes() {
    let text = edited(PROFIDRIVE, "date = 2026-02-28", "date = \"2026-12-01\"");
    let diagnostics = load(&text).1;
    let d = diagnostics.iter().next().unwrap();
    assert_eq!(d.code, "E003");
    let help = d.help.as_deref().unwrap();
    assert!(
        help.starts_with("remove the quotes: TOML writes a date without them, date = 2026-12-01 "),
        "{help}"
    );
    let text = edited(
        PROFIDRIVE,
        "date = 2026-02-28",
        "date = \"2026-12-01T07:14:47\"",
    );
    let help = load(&text).1.iter().next().unwrap().help.clone().unwrap();
    assert!(help.contains("date = 2026-12-01T07:14:47 "), "{help}");
}
