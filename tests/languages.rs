//! gsdc's own words in a description's languages (src/i18n): the GSDML's
//! texts in German carry gsdc's German, the datasheet's switch names each
//! language in itself, and a language gsdc has no words in is W108, its
//! texts the description's and gsdc's words English.

use crate::support::{checkout, descriptions, file_names, gsdc, scratch, stderr};
use gsdc::ArtifactKind;
use std::collections::BTreeMap;

/// The texts of one language of a GSDML, by TextId: the primary language
/// (`None`) or `xml:lang`.
fn gsdml_texts(xml: &str, language: Option<&str>) -> BTreeMap<String, String> {
    let doc = roxmltree::Document::parse(xml).unwrap();
    let list = doc
        .descendants()
        .find(|n| match language {
            None => n.has_tag_name("PrimaryLanguage"),
            Some(code) => {
                n.has_tag_name("Language")
                    && n.attribute(("http://www.w3.org/XML/1998/namespace", "lang")) == Some(code)
            }
        })
        .unwrap_or_else(|| panic!("no texts in {language:?}"));
    list.children()
        .filter(|n| n.has_tag_name("Text"))
        .map(|n| {
            let id = n.attribute("TextId").unwrap().to_string();
            (id, n.attribute("Value").unwrap().to_string())
        })
        .collect()
}

fn gsdml_of(fixture: &str) -> String {
    let ir = descriptions::load_from("tests/fixtures/valid", fixture);
    descriptions::output_text(&ir, ArtifactKind::Gsdml)
}

/// The AX200's German texts: gsdc's words in German, and the description's
/// German texts. A German text equal to the English one is a name (PZD1,
/// Port 1, a module's `2 PZD`), never gsdc's words left in English.
#[test]
fn the_german_texts_of_a_gsdml_carry_gsdcs_german_words() {
    let xml = gsdml_of("ax200.toml");
    let english = gsdml_texts(&xml, None);
    let german = gsdml_texts(&xml, Some("de"));
    for (id, text) in [
        ("IDT_MODULE_INFO_PZD_2", "2 PZD-Wörter; 4 Byte je Richtung"),
        ("IDT_MODULE_STD_TEL_1", "Standardtelegramm 1"),
        ("IDT_ACCESS_POINT", "Modulzugriffspunkt"),
        ("IDT_NSOLL_A", "NSOLL_A (Drehzahlsollwert A)"),
        // The description's own name of STW1 (`profile_word_names`).
        ("IDT_STW1", "Ausgang"),
        ("IDT_ZSW1", "ZSW1 (Zustandswort 1)"),
        (
            "IDT_RECORD_1",
            "PZD-Zuordnung Ausgänge (Controller zum Antrieb)",
        ),
        ("IDT_RECORD_3", "Antriebseinstellungen"),
        ("IDT_CATEGORY_STANDARD_TELEGRAMS", "Standardtelegramme"),
        ("IDT_SETTINGS_1", "Telegrammauswahl (P0922)"),
    ] {
        assert_eq!(german[id], text, "{id}");
    }
    let names = [
        "IDT_PZD_",
        "IDT_PORT_",
        "IDT_INTERFACE",
        "IDT_CATEGORY_PZD",
        "IDT_MODULE_PZD_",
    ];
    for (id, text) in &german {
        if *text == english[id] {
            assert!(
                names.iter().any(|n| id.starts_with(n)),
                "{id} is English in the German texts: {text}"
            );
        }
    }
}

/// The language switch of the datasheet names each language in its own
/// words; a language gsdc has no words in, by its code.
#[test]
fn the_switch_names_each_language_in_itself() {
    let label = |code: &str, name: &str| {
        format!("<label for=\"lang-{code}\" lang=\"{code}\">{name}</label>")
    };
    for (folder, name, wanted) in [
        ("descriptions", "md810dp.toml", label("zh", "中文")),
        ("tests/fixtures/valid", "ax200.toml", label("de", "Deutsch")),
        ("tests/fixtures/valid", "french.toml", label("fr", "fr")),
    ] {
        let ir = descriptions::load_from(folder, name);
        let html = descriptions::output_text(&ir, ArtifactKind::DatasheetHtml);
        assert!(html.contains(&label("en", "English")), "{name}");
        assert!(html.contains(&wanted), "{name}: {wanted}");
    }
}

/// French, which gsdc has no words in: W108 at the first French text, with
/// where gsdc's words stay English and which languages gsdc has.
#[test]
fn a_language_gsdc_has_no_words_in_is_w108_at_its_first_text() {
    let text = std::fs::read_to_string(checkout("tests/fixtures/valid/french.toml")).unwrap();
    let (ir, diagnostics) = descriptions::load_text("french.toml", &text);
    assert!(ir.is_some(), "a warning, not an error");
    let w108: Vec<_> = diagnostics.iter().filter(|d| d.code == "W108").collect();
    assert_eq!(w108.len(), 1, "{diagnostics:?}");
    let warning = w108[0];
    assert_eq!(warning.severity, gsdc::Severity::Warning);
    let span = warning.span.clone().unwrap();
    assert_eq!(&text[span.clone()], "fr");
    let line = text[..span.start].lines().last().unwrap();
    assert!(
        line.starts_with("name = { en = \"X3 fieldbus card\""),
        "{line}"
    );
    assert!(warning.message.contains("`fr`"), "{}", warning.message);
    let help = warning.help.as_deref().unwrap();
    assert!(help.contains("en, zh and de"), "{help}");
    // gsdc's own languages are not warned about.
    for (folder, name) in [
        ("tests/fixtures/valid", "ax200.toml"),
        ("descriptions", "md810dp.toml"),
    ] {
        let text = std::fs::read_to_string(checkout(folder).join(name)).unwrap();
        let (_, diagnostics) = descriptions::load_text(name, &text);
        assert!(!diagnostics.iter().any(|d| d.code == "W108"), "{name}");
    }
}

/// The French texts of the GSDML are the description's; gsdc's own words
/// in them are English, as the warning says.
#[test]
fn a_language_without_words_keeps_its_texts_and_gsdcs_english() {
    let xml = gsdml_of("french.toml");
    let english = gsdml_texts(&xml, None);
    let french = gsdml_texts(&xml, Some("fr"));
    assert_eq!(french["IDT_DEVICE_NAME"], "Carte de bus de terrain X3");
    assert_eq!(french["IDT_CONTROL_WORD"], "Mot de commande");
    assert_eq!(
        french["IDT_MODULE_INFO_PZD_2"],
        english["IDT_MODULE_INFO_PZD_2"]
    );
    assert_eq!(
        french["IDT_MODULE_INFO_PZD_2"],
        "2 PZD words; 4 bytes each way"
    );
}

/// A shipping build refuses W108 as any warning.
#[test]
fn a_shipping_build_refuses_a_language_without_words() {
    let dir = scratch("deny");
    let output = gsdc([
        "build",
        "tests/fixtures/valid/french.toml",
        "--out",
        dir.to_str().unwrap(),
        "--deny-warnings",
    ]);
    assert_eq!(output.status.code(), Some(1));
    assert!(
        stderr(&output).contains("warning[W108]"),
        "{}",
        stderr(&output)
    );
    assert!(file_names(&dir).is_empty());
}
