//! What no manual gave reaches every generated file's header: each
//! placeholder, each value the description marks as its own choice, each
//! default gsdc applied; and the description's translations are said.

use crate::support::descriptions;
use gsdc::ir::DecisionKind;

/// The comment lines at the top of a generated file, as text.
fn head(text: &str) -> String {
    text.lines()
        .skip_while(|l| l.starts_with("<?xml"))
        .take_while(|l| {
            let l = l.trim_start();
            [";", "//", "<!--", "/*", "*"]
                .iter()
                .any(|c| l.starts_with(c))
                || l.is_empty()
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// A note's words as a header shows them, whatever the line breaks.
fn words(text: &str) -> String {
    text.split_whitespace()
        .filter(|w| !["//", ";", "<!--", "-->", "/*", "*", "*/"].contains(w))
        .collect::<Vec<_>>()
        .join(" ")
}

#[test]
fn every_header_lists_every_decision() {
    for name in descriptions::shipped() {
        let ir = descriptions::load(&name);
        assert!(
            ir.decisions
                .iter()
                .any(|d| d.kind == DecisionKind::Placeholder),
            "{name}: the shipped descriptions have placeholders"
        );
        for artifact in gsdc::compile(&ir).unwrap() {
            if matches!(
                artifact.kind,
                gsdc::ArtifactKind::RustSupport
                    | gsdc::ArtifactKind::CSupport
                    | gsdc::ArtifactKind::DeviceSymbol
            ) {
                continue; // the same for every description, or a bitmap
            }
            let text = String::from_utf8(artifact.contents).unwrap();
            let head = words(&head(&text));
            for decision in &ir.decisions {
                let summary = words(&decision.summary());
                // The GSD is 7-bit ASCII: a character beyond shows as `?`.
                let ascii: String = summary
                    .chars()
                    .map(|c| if c.is_ascii() { c } else { '?' })
                    .collect();
                assert!(
                    head.contains(&summary) || head.contains(&ascii),
                    "{name}: {} lacks {summary:?} in\n{head}",
                    artifact.file_name
                );
            }
        }
    }
}

/// A description whose manual is in Chinese only (MD810's): its English
/// texts are said to be translations, in every header.
#[test]
fn translations_are_said_as_such() {
    let ir = descriptions::load("md810dp.toml");
    assert_eq!(ir.manual_languages, ["zh"]);
    for artifact in gsdc::compile(&ir).unwrap() {
        if matches!(
            artifact.kind,
            gsdc::ArtifactKind::RustSupport
                | gsdc::ArtifactKind::CSupport
                | gsdc::ArtifactKind::DeviceSymbol
        ) {
            continue;
        }
        let head = words(&head(&String::from_utf8(artifact.contents).unwrap()));
        assert!(
            head.contains("Texts in en are the description's translations of the manual's zh."),
            "{}: {head}",
            artifact.file_name
        );
    }
}

/// A marked choice: a W103 warning at the value, with the reason, and a
/// decision in the IR; the value shown on one line. (9KDP1 with two
/// choices of its own instead of the ones it ships with.)
#[test]
fn a_marked_choice_is_warned_about_at_its_value() {
    let shipped = descriptions::shipped_text("9kdp1.toml");
    let (head, rest) = shipped
        .split_once("\n[choices]\n")
        .expect("9kdp1.toml has [choices]");
    let (_, tail) = rest.split_once("\n[device]\n").expect("[device] follows");
    let text = format!(
        "{head}\n[choices]\n\"profibus.min_slave_interval\" = \"the manual gives none\"\n\"profibus.baud_rates.\\\"1.5M\\\"\" = \"the DP standard's value\"\n\n[device]\n{tail}"
    );
    let (ir, diagnostics) = descriptions::load_text("9kdp1.toml", &text);
    let ir = ir.unwrap_or_else(|| panic!("{diagnostics:?}"));
    let w103: Vec<_> = diagnostics.iter().filter(|d| d.code == "W103").collect();
    assert_eq!(w103.len(), 2, "{diagnostics:?}");
    for warning in w103 {
        let span = warning.span.clone().unwrap();
        let at = &text[span];
        assert!(["1", "150"].contains(&at), "{at}");
    }
    let choices: Vec<(&str, &str, &str)> = ir
        .decisions
        .iter()
        .filter(|d| d.kind == DecisionKind::Choice)
        .map(|d| (d.path.as_str(), d.value.as_str(), d.reason.as_str()))
        .collect();
    assert_eq!(
        choices,
        [
            (
                "profibus.baud_rates.\"1.5M\"",
                "150",
                "the DP standard's value"
            ),
            ("profibus.min_slave_interval", "1", "the manual gives none"),
        ]
    );
}

/// What gsdc's GSDML says the card's PROFINET stack does, where no
/// description key states it, is listed as required of the firmware: each
/// attribute the file writes, by the words of the listing.
#[test]
fn what_the_gsdml_claims_of_the_stack_is_listed() {
    let claims = [
        ("MultipleWriteSupported=\"true\"", "MultipleWriteSupported"),
        ("LLDP_NoD_Supported=\"true\"", "LLDP_NoD_Supported"),
        ("ResetToFactoryModes=\"2\"", "ResetToFactoryModes 2"),
        ("SupportedRT_Classes=\"RT_CLASS_1\"", "RT_CLASS_1"),
        ("SupportedProtocols=\"SNMP;LLDP\"", "SNMP and LLDP"),
        ("DCP_BoundarySupported=\"true\"", "DCP and PTP boundaries"),
        ("PTP_BoundarySupported=\"true\"", "DCP and PTP boundaries"),
        (
            "StartupMode=\"Legacy;Advanced\"",
            "startup modes Legacy and Advanced",
        ),
        (
            "ReductionRatio=\"1 2 4 8 16 32 64 128 256 512\"",
            "reduction ratios 1 to 512",
        ),
    ];
    for name in ["mv810-pnet02.toml", "md810dp.toml"] {
        let ir = descriptions::load(name);
        let required: Vec<&str> = ir
            .decisions
            .iter()
            .filter(|d| d.kind == DecisionKind::Requirement)
            .map(|d| d.value.as_str())
            .collect();
        let gsdml = gsdc::compile(&ir)
            .unwrap()
            .into_iter()
            .find(|a| a.kind == gsdc::ArtifactKind::Gsdml)
            .unwrap();
        let gsdml = String::from_utf8(gsdml.contents).unwrap();
        for (attribute, listed) in claims {
            assert!(gsdml.contains(attribute), "{name}: {attribute}");
            assert!(
                required.iter().any(|r| r.contains(listed)),
                "{name}: {listed} in {required:?}"
            );
        }
    }
}
