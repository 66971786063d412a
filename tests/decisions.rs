//! What no manual gave reaches every generated file's header: each
//! placeholder, each value the description marks as its own choice, each
//! default gsdc applied; and the description's translations are said.

use crate::support::descriptions;
use gsdc::ir::DecisionKind;
use gsdc::ArtifactKind;

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

/// The decisions a file of `kind` is about, by the key each stands at: a
/// GSD describes the PROFIBUS-DP slave (`[profibus]`, a gateway), a GSDML
/// the PROFINET device (`[profinet]`); both share the device, the telegram,
/// the mappings and settings, the numbering; the layouts carry both buses.
fn concerns(kind: ArtifactKind, path: &str) -> bool {
    let root = path.split(['.', '[', ' ']).next().unwrap();
    match kind {
        ArtifactKind::Gsd => root != "profinet",
        ArtifactKind::Gsdml => !["profibus", "gateway"].contains(&root),
        _ => true,
    }
}

/// The files of every shipped description and valid fixture that have a
/// header of their own (not the support files, the same for all, nor a
/// bitmap), with their headers' words.
fn headers() -> Vec<(String, gsdc::ir::Ir, ArtifactKind, String)> {
    let mut headers = Vec::new();
    for (name, ir) in descriptions::all_valid() {
        for artifact in gsdc::compile(&ir).unwrap() {
            if matches!(
                artifact.kind,
                ArtifactKind::RustSupport | ArtifactKind::CSupport | ArtifactKind::DeviceSymbol
            ) {
                continue;
            }
            let text = String::from_utf8(artifact.contents).unwrap();
            headers.push((
                format!("{name}: {}", artifact.file_name),
                ir.clone(),
                artifact.kind,
                words(&head(&text)),
            ));
        }
    }
    headers
}

/// Every header lists each decision that concerns its file, and no other:
/// a GSD none of the PROFINET placeholders, a GSDML none of PROFIBUS's.
#[test]
fn every_header_lists_the_decisions_that_concern_its_file() {
    let mut left_out = 0;
    for (file, ir, kind, head) in headers() {
        for decision in &ir.decisions {
            let summary = words(&decision.summary());
            // The GSD is 7-bit ASCII: a character beyond shows as `?`.
            let ascii: String = summary
                .chars()
                .map(|c| if c.is_ascii() { c } else { '?' })
                .collect();
            let listed = head.contains(&summary) || head.contains(&ascii);
            if concerns(kind, &decision.path) {
                assert!(listed, "{file} lacks {summary:?} in\n{head}");
            } else {
                assert!(!listed, "{file} lists {summary:?}, none of its business");
                left_out += 1;
            }
        }
    }
    // MD810's GSD leaves out its PROFINET placeholders, its GSDML its
    // PROFIBUS ident number, and more.
    assert!(left_out > 20, "{left_out}");
}

#[test]
fn the_shipped_descriptions_have_placeholders_to_list() {
    for name in descriptions::shipped() {
        let ir = descriptions::load(&name);
        assert!(
            ir.decisions
                .iter()
                .any(|d| d.kind == DecisionKind::Placeholder),
            "{name}: the shipped descriptions have placeholders"
        );
    }
}

/// The header of MD810's GSD, whose description has both buses: its own
/// placeholder, none of the GSDML's.
#[test]
fn the_gsd_of_a_card_with_both_buses_lists_no_profinet_placeholder() {
    let ir = descriptions::load("md810dp.toml");
    let (_, gsd) = descriptions::one(gsdc::compile(&ir).unwrap(), ArtifactKind::Gsd);
    let head = head(&gsd);
    assert!(
        head.contains("Placeholder: profibus.ident_number = 0x0810"),
        "{head}"
    );
    assert!(!head.contains("profinet"), "{head}");
    let (_, gsdml) = descriptions::one(gsdc::compile(&ir).unwrap(), ArtifactKind::Gsdml);
    let head = self::head(&gsdml);
    assert!(
        head.contains("Placeholder: profinet.vendor_id = 0x0A11"),
        "{head}"
    );
    assert!(!head.contains("profibus"), "{head}");
}

/// A description whose manual is in Chinese only (MD810's): its English
/// texts are said to be translations, in every header.
#[test]
fn translations_are_said_as_such() {
    let ir = descriptions::load("md810dp.toml");
    assert_eq!(ir.manual_languages, ["zh"]);
    for (file, _, _, head) in headers()
        .into_iter()
        .filter(|(f, ..)| f.starts_with("md810dp.toml"))
    {
        assert!(
            head.contains("Texts in en are the description's translations of the manual's zh."),
            "{file}: {head}"
        );
    }
}

/// A manual in English and texts in English and Chinese: the Chinese are
/// the description's translations, which only the GSDML has; the GSD and
/// the layouts have the manual's English alone and say nothing.
#[test]
fn only_a_file_with_the_translated_language_says_so() {
    let shipped = descriptions::shipped_text("md810dp.toml");
    let text = shipped.replace("languages = [\"zh\"]", "languages = [\"en\"]");
    assert_ne!(text, shipped);
    let (ir, diagnostics) = descriptions::load_text("md810dp.toml", &text);
    let ir = ir.unwrap_or_else(|| panic!("{diagnostics:?}"));
    let note = "Texts in zh are the description's translations of the manual's en.";
    let artifacts = gsdc::compile(&ir).unwrap();
    assert!(artifacts.iter().any(|a| a.kind == ArtifactKind::Gsd));
    for artifact in artifacts {
        let kind = artifact.kind;
        if matches!(
            kind,
            ArtifactKind::RustSupport | ArtifactKind::CSupport | ArtifactKind::DeviceSymbol
        ) {
            continue;
        }
        let head = words(&head(&String::from_utf8(artifact.contents).unwrap()));
        assert_eq!(
            head.contains(note),
            kind == ArtifactKind::Gsdml,
            "{}: {head}",
            artifact.file_name
        );
        assert!(
            !head.contains("Texts in en"),
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

/// Whether `text` is a string the description writes, or a mapping's name
/// rendered for one of its numbers (`"PZD{n} receive"` gives `PZD2 receive`).
fn written_in(description: &str, text: &str) -> bool {
    let quoted = |s: &str| description.contains(&format!("\"{s}\""));
    quoted(text)
        || (0..=255).any(|n: u32| {
            let n = n.to_string();
            text.contains(&n) && quoted(&text.replacen(&n, "{n}", 1))
        })
}

/// Every text of every GSDML the descriptions give is either the
/// description's (a string it writes, or a mapping name rendered) or listed
/// in the file's header as gsdc's wording, with its TextId: no text of
/// gsdc's passes for the manual's. The GSD's module names are listed too.
#[test]
fn every_text_gsdc_wrote_is_listed_as_its_wording() {
    for name in descriptions::shipped() {
        let ir = descriptions::load(&name);
        let description = descriptions::shipped_text(&name);
        for artifact in gsdc::compile(&ir).unwrap() {
            let text = String::from_utf8_lossy(&artifact.contents).into_owned();
            let header = words(&head(&text));
            match artifact.kind {
                gsdc::ArtifactKind::Gsdml => {
                    let doc = roxmltree::Document::parse(&text).unwrap();
                    let primary = doc
                        .descendants()
                        .find(|n| n.has_tag_name("PrimaryLanguage"))
                        .unwrap();
                    let mut listed = 0;
                    for t in primary.children().filter(|n| n.has_tag_name("Text")) {
                        let (id, value) = (
                            t.attribute("TextId").unwrap(),
                            t.attribute("Value").unwrap(),
                        );
                        let place = format!("GSDML {id} = \"{value}\"");
                        if header.contains(&words(&place)) {
                            listed += 1;
                        } else {
                            assert!(written_in(&description, value), "{name}: {id} = {value:?} is neither the description's nor listed as gsdc's");
                        }
                    }
                    assert!(listed > 0, "{name}: gsdc writes the ports' names at least");
                    assert_translations_are_the_files(&name, &doc, &head(&text));
                }
                gsdc::ArtifactKind::Gsd => {
                    for line in text.lines().filter(|l| l.starts_with("Module = \"")) {
                        let module = line.split('"').nth(1).unwrap();
                        let listed = format!("gsdc's wording: GSD Module = \"{module}\"");
                        assert!(header.contains(&words(&listed)), "{name}: {module}");
                    }
                }
                _ => {}
            }
        }
    }
}

/// A header's `in zh gsdc's translation` names languages the GSDML has a
/// text list in: a translation the file does not carry is not listed.
fn assert_translations_are_the_files(name: &str, doc: &roxmltree::Document, header: &str) {
    let xml = "http://www.w3.org/XML/1998/namespace";
    let languages: Vec<&str> = doc
        .descendants()
        .filter(|n| n.has_tag_name("Language"))
        .filter_map(|n| n.attribute((xml, "lang")))
        .collect();
    let mut translated = 0;
    for note in words(header).split("gsdc's wording: ").skip(1) {
        let Some((_, codes)) = note.split_once("; in ") else {
            continue;
        };
        let codes = codes.split(" gsdc's translation").next().unwrap();
        for code in codes.split(", ") {
            assert!(languages.contains(&code), "{name}: {code} in {note}");
            translated += 1;
        }
    }
    assert!(
        translated > 0 || languages.is_empty(),
        "{name}: its languages {languages:?} get gsdc's translation of the ports' names"
    );
}

/// Freeze_Mode_supp, Sync_Mode_supp and Fail_Safe are what the card's DP
/// stack does: unsaid, gsdc writes 0 and says so (W104, in every header);
/// said, the GSD has it. md810dp states each, as its own choice.
#[test]
fn freeze_sync_and_fail_safe_are_stated_or_gsdcs_defaults() {
    let text = descriptions::shipped_text("md810dp.toml");
    // Each key and its mark under [choices] gone.
    let keys = ["freeze_mode", "sync_mode", "fail_safe"];
    let unsaid: String = text
        .lines()
        .filter(|l| {
            !keys.iter().any(|k| {
                l.starts_with(&format!("{k} = ")) || l.starts_with(&format!("\"profibus.{k}\""))
            })
        })
        .map(|l| format!("{l}\n"))
        .collect();
    let (ir, diagnostics) = descriptions::load_text("md810dp.toml", &unsaid);
    for key in ["freeze_mode", "sync_mode", "fail_safe"] {
        let message = format!("profibus.{key} is not stated: gsdc uses false");
        assert!(
            diagnostics
                .iter()
                .any(|d| d.code == "W104" && d.message == message),
            "{message}"
        );
        assert!(ir
            .as_ref()
            .unwrap()
            .decisions
            .iter()
            .any(|d| d.kind == DecisionKind::Default && d.path == format!("profibus.{key}")));
    }
    let fail_safe = text.replacen("fail_safe = false", "fail_safe = true", 1);
    let ir = descriptions::load_text("md810dp.toml", &fail_safe)
        .0
        .unwrap();
    let gsd = descriptions::output_text(&ir, gsdc::ArtifactKind::Gsd);
    assert!(gsd.contains("Fail_Safe                   = 1"), "{gsd}");
    assert!(gsd.contains("Freeze_Mode_supp            = 0"));
}

/// What gsdc lays out where the manual gives no bytes is listed as gsdc's
/// layout: User_Prm_Data's order and offsets, the config identifiers and
/// Max_Module.
#[test]
fn gsdcs_layout_is_listed() {
    let layout_of = |name: &str| -> Vec<[String; 2]> {
        descriptions::load(name)
            .decisions
            .into_iter()
            .filter(|d| d.kind == DecisionKind::Layout)
            .map(|d| [d.path, d.value])
            .collect()
    };
    assert_eq!(
        layout_of("md810dp.toml"),
        [
            ["profibus Max_Module", "1"],
            ["profibus User_Prm_Data", "DPV1_Status_1..3 at bytes 0-2, pzd_out at bytes 3-26, pzd_in at bytes 27-50, dpv1_index at bytes 51-62; one Unsigned16 per entry, high byte first, no gaps"],
            ["profibus config identifiers", "the PKW 0xF3 (4 words in and out, consistent), the PZD 0xF0 | (words - 1) (words in and out, consistent): PPO1 0xF3,0xF1; PPO2 0xF3,0xF5; PPO3 0xF1; PPO4 0xF5; PPO5 0xF3,0xFB"],
        ]
    );
    // The gateway's modules: the manual's list is lost (2.4 step 5). 122
    // words each way (Max_Input_Len 244) need 10 modules of 16, 8, 4, 2
    // and 1 words at most: 20 in all. Its parameters (2.4 step 4): one
    // Unsigned8 node count, then two Unsigned8 word counts for each of the
    // 30 nodes, 61 bytes (Max_User_Prm_Data_Len).
    assert_eq!(
        layout_of("md810-gateway.toml"),
        [
            ["profibus Max_Module", "20"],
            ["profibus User_Prm_Data", "the node count at byte 0, each node's input and output words at bytes 1-60, in the order of the node table, no gaps; bit areas share a byte"],
            ["profibus config identifiers", "0x40 | 0x10 (input) or 0x20 (output) | (words - 1), 0x80 when consistent: INPUT 1 word 0x50; INPUT 2 words 0x51; INPUT 4 words 0x53; INPUT 8 words 0x57; INPUT 16 words 0x5F; OUTPUT 1 word 0x60; OUTPUT 2 words 0x61; OUTPUT 4 words 0x63; OUTPUT 8 words 0x67; OUTPUT 16 words 0x6F"],
        ]
    );
}
