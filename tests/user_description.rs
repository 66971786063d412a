//! A new user's first day with the description (issue 23): a second
//! release on one day, parameters numbered without a separator, and a
//! setting fixed per PROFINET module in a description with both buses.

use crate::support::descriptions::one;
use crate::support::{scratch, Scratch};
use gsdc::{Artifact, ArtifactKind, Diagnostics};

const PROFIDRIVE: &str = include_str!("fixtures/valid/profidrive.toml");

/// `text` with `from` replaced by `to`, which must be there.
fn edited(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "`{from}` is not in the text");
    text.replacen(from, to, 1)
}

fn load(text: &str) -> (Option<gsdc::Ir>, Diagnostics) {
    gsdc::load("ax200.toml", text)
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

// ---------------------------------------------------------------------------
// Parameters numbered without a separator: P1120, r0947, 2202.

const AX200: &str = include_str!("fixtures/valid/ax200.toml");

fn text_of(files: &[Artifact], kind: ArtifactKind) -> String {
    one(files.to_vec(), kind).1
}

#[test]
fn names_without_a_separator_are_read_and_written_as_the_description_writes_them() {
    let (ir, diagnostics) = load(AX200);
    let ir = ir.unwrap_or_else(|| panic!("{diagnostics:?}"));
    let numbering = ir.numbering.as_ref().unwrap();
    assert_eq!(numbering.parse("P1120"), Ok(1120));
    assert_eq!(numbering.parse("r0947"), Ok(947));
    // P and r both start at 0: each address the description names is
    // written back with the letter it was written with.
    assert_eq!(numbering.format(947).as_deref(), Some("r0947"));
    assert_eq!(numbering.format(1070).as_deref(), Some("P1070"));
    assert_eq!(numbering.format(922).as_deref(), Some("P0922"));
    let files = gsdc::compile(&ir).unwrap();
    let rust = text_of(&files, ArtifactKind::RustLayout);
    assert!(rust.contains("default: 0x042E, // P1070"), "{rust}");
    assert!(rust.contains("default: 0x03B3, // r0947"), "{rust}");
    assert!(rust.contains("parameter: Some(0x039A), // P0922"), "{rust}");
    let c = text_of(&files, ArtifactKind::CHeader);
    assert!(
        c.contains("#define AX200_PZD_IN_5_DEFAULT 0x03B3U /* r0947 */"),
        "{c}"
    );
    let datasheet = gsdc::document(&ir);
    let markdown = text_of(&datasheet, ArtifactKind::DatasheetMarkdown);
    assert!(
        markdown.contains("| PZD3 | bytes 4-5 | P1070 (default) | r0021 (default) |"),
        "{markdown}"
    );
}

#[test]
fn a_name_without_its_leading_zero_is_told_the_descriptions_form() {
    let text = edited(AX200, "default = \"P1070\"", "default = \"P947\"");
    let diagnostics = load(&text).1;
    let d = diagnostics.iter().find(|d| d.code == "E106").unwrap();
    assert_eq!(
        d.message,
        "`P947` is not a function-code name: 3 characters follow its prefix; the description's names have 4 digits, 2 of the group and 2 of the index"
    );
    assert_eq!(
        d.help.as_deref(),
        Some("the description numbers parameters as <prefix>GGII (prefix P or r; G a digit of the group, I of the index), e.g. P0001; or write the number")
    );
    // P09.47 with a separator the description does not have.
    let text = edited(AX200, "default = \"P1070\"", "default = \"P09.47\"");
    assert_eq!(codes(&text), ["E106"]);
}

#[test]
fn without_a_separator_both_widths_are_required() {
    for (from, to) in [
        ("group_digits = 2\n", ""),
        ("index_digits = 2\n", ""),
        ("group_digits = 2\nindex_digits = 2\n", ""),
    ] {
        let text = edited(AX200, from, to);
        assert!(
            codes(&text).contains(&"E156"),
            "without {from:?}: {:?}",
            codes(&text)
        );
    }
    let text = edited(AX200, "group_digits = 2", "group_digits = 4");
    assert!(codes(&text).contains(&"E101"), "{:?}", codes(&text));
    // With a separator, the widths fix the digits too: P10.70.
    let text = edited(AX200, "separator = \"\"", "separator = \".\"")
        .replace("\"P1070\"", "\"P10.70\"")
        .replace("\"P0000\", \"P2047\"", "\"P00.00\", \"P20.47\"")
        .replace(
            "r0021\", \"r0027\", \"r0947\", \"r0947",
            "r00.21\", \"r00.27\", \"r09.47\", \"r09.47",
        )
        .replace("\"r0000\", \"r2047\"", "\"r00.00\", \"r20.47\"")
        .replace("\"P0922\"", "\"P09.22\"")
        .replace("\"P1900\"", "\"P19.00\"")
        .replace("\"P1121\"", "\"P11.21\"");
    let (ir, diagnostics) = load(&text);
    let ir = ir.unwrap_or_else(|| panic!("{diagnostics:?}"));
    assert_eq!(ir.numbering.unwrap().format(947).as_deref(), Some("r09.47"));
}

/// ABB's ACS355 manual numbers parameters 2202 (group 22, index 02): no letter.
#[test]
fn a_numbering_may_have_no_prefix() {
    let mut text = edited(
        AX200,
        "prefixes = { P = 0, r = 0 }",
        "prefixes = { \"\" = 0 }",
    );
    for name in [
        "1070", "0000", "2047", "0021", "0027", "0947", "0922", "1900", "1121",
    ] {
        for prefix in ["P", "r"] {
            text = text.replace(&format!("\"{prefix}{name}\""), &format!("\"{name}\""));
        }
    }
    assert!(!text.contains("\"r0"), "{text}");
    let (ir, diagnostics) = load(&text);
    let ir = ir.unwrap_or_else(|| panic!("{diagnostics:?}"));
    let numbering = ir.numbering.unwrap();
    assert_eq!(numbering.parse("2202"), Ok(2202));
    assert_eq!(numbering.format(947).as_deref(), Some("0947"));
}

/// F and FA with hex groups and no separator: FA12 would be either's.
#[test]
fn prefixes_that_a_hex_group_could_extend_are_refused_without_a_separator() {
    let md810_like = "[function_codes]\nseparator = \"\"\ngroup_radix = 16\nprefixes = { F = 0xF0, FA = 0x10 }\ngroup_digits = 1\nindex_digits = 2\n";
    let text = edited(
        AX200,
        "[function_codes]\nseparator = \"\"\ngroup_radix = 10\nprefixes = { P = 0, r = 0 }\naddress = \"decimal\"\ngroup_digits = 2\nindex_digits = 2\n",
        md810_like,
    );
    assert!(codes(&text).contains(&"E155"), "{:?}", codes(&text));
}

// ---------------------------------------------------------------------------
// A setting fixed per PROFINET module in a description with both buses.

/// The `Ref` of the telegram selection in each module's settings record,
/// by module ID: (DefaultValue, Changeable).
fn telegram_selection_refs(gsdml: &str) -> Vec<(String, String, String)> {
    let doc = roxmltree::Document::parse(gsdml).unwrap();
    doc.descendants()
        .filter(|n| n.has_tag_name("ModuleItem"))
        .filter_map(|module| {
            let r = module.descendants().find(|n| {
                n.has_tag_name("Ref") && n.attribute("TextId") == Some("IDT_SETTINGS_1")
            })?;
            Some((
                module.attribute("ID").unwrap().to_string(),
                r.attribute("DefaultValue").unwrap().to_string(),
                r.attribute("Changeable").unwrap().to_string(),
            ))
        })
        .collect()
}

fn fixed(module: &str, value: &str) -> (String, String, String) {
    (module.into(), value.into(), "false".into())
}

#[test]
fn each_profinet_module_fixes_the_setting_when_the_card_also_has_profibus() {
    for profibus in ["absent", "user"] {
        let text = edited(
            AX200,
            "profibus = \"absent\"",
            &format!("profibus = \"{profibus}\""),
        );
        let files = compiled(&text);
        let gsdml = text_of(&files, ArtifactKind::Gsdml);
        assert_eq!(
            telegram_selection_refs(&gsdml),
            [
                fixed("IDM_STD_TEL_1", "1"),
                fixed("IDM_STD_TEL_2", "2"),
                fixed("IDM_PZD_2", "999"),
                fixed("IDM_PZD_4", "999"),
                fixed("IDM_PZD_6", "999"),
            ],
            "{profibus}"
        );
        let gsd = text_of(&files, ArtifactKind::Gsd);
        let selection = "ExtUserPrmData = 10 \"Telegram selection (P0922)\"";
        match profibus {
            // The master cannot set it: User_Prm_Data has the other
            // settings only (the fault reaction, the ramp-down time's byte).
            "absent" => {
                assert!(!gsd.contains("Telegram selection"), "{gsd}");
                assert!(!gsd.contains("Free telegram"), "{gsd}");
                assert!(
                    gsd.contains("Max_User_Prm_Data_Len       = 19\r\n"),
                    "{gsd}"
                );
                assert!(
                    gsd.contains("ExtUserPrmData = 9 \"Fault reaction (P1900)\""),
                    "{gsd}"
                );
                assert!(gsd.contains("Ext_User_Prm_Data_Ref(16)   = 9\r\n"), "{gsd}");
            }
            // A user value, as any setting: its default and choices.
            _ => {
                assert!(gsd.contains("ExtUserPrmData = 9 \"Telegram selection (P0922)\"\r\nUnsigned16 999 1,2,999\r\n"), "{gsd}");
                assert!(
                    gsd.contains("Max_User_Prm_Data_Len       = 21\r\n"),
                    "{gsd}"
                );
                assert!(
                    gsd.contains(
                        "Ext_User_Prm_Data_Ref(16)   = 9\r\nExt_User_Prm_Data_Ref(18)   = 10\r\nExt_User_Prm_Data_Ref(20)   = 11\r\n"
                    ),
                    "{gsd}"
                );
                assert!(!gsd.contains(selection));
            }
        }
    }
}

#[test]
fn what_a_per_module_setting_is_on_profibus_must_be_said_there_only() {
    let unsaid = edited(AX200, ", profibus = \"absent\"", "");
    assert_eq!(codes(&unsaid), ["E157"]);
    let d = load(&unsaid).1;
    let help = d.iter().next().unwrap().help.clone().unwrap();
    assert!(
        help.contains("profibus = \"user\"") && help.contains("profibus = \"absent\""),
        "{help}"
    );
    // Without [profibus] the key means nothing.
    let start = AX200.find("[profibus]").unwrap();
    let end = AX200.find("[profinet]").unwrap();
    let profinet_only = format!("{}{}", &AX200[..start], &AX200[end..]);
    assert_eq!(codes(&profinet_only), ["E002"]);
    let without_key = profinet_only.replace(", profibus = \"absent\"", "");
    assert_eq!(codes(&without_key), Vec::<&str>::new());
}

/// Each value `per_module` gives is a parameter the PROFIdrive channel must
/// reach (E154): a parameter beyond PNU 2047 for any kind of module,
/// telegram 2's as much as the others.
#[test]
fn every_per_module_value_is_kept_within_the_profidrive_pnus() {
    for key in [
        "user_defined = 999",
        "standard_telegram_1 = 1",
        "standard_telegram_2 = 2",
    ] {
        let (name, _) = key.split_once(" = ").unwrap();
        let text = edited(AX200, key, &format!("{name} = \"P2048\""));
        assert!(codes(&text).contains(&"E154"), "{key}: {:?}", codes(&text));
    }
}

/// The User_Prm_Data of tests/fixtures/valid/ax200.toml: PZD3..PZD6 out
/// (P1070), PZD3..PZD6 in (r0021, r0027, r0947, r0947), then the one setting
/// it carries, the fault reaction, `fault_reaction`.
/// AX200's User_Prm_Data: its words, the fault reaction's among them,
/// then the ramp-down time's byte (30 s, not its default).
fn ax200_user_prm(fault_reaction: u16) -> String {
    let words = [1070, 1070, 1070, 1070, 21, 27, 947, 947, fault_reaction];
    let bytes: Vec<String> = words
        .iter()
        .flat_map(|w: &u16| w.to_be_bytes())
        .chain([30])
        .map(|b| format!("0x{b:02X}"))
        .collect();
    bytes.join(", ")
}

/// Writes the files of `kinds` of the AX200 into a scratch directory.
#[track_caller]
fn written(name: &str, kinds: &[ArtifactKind]) -> Scratch {
    let dir = scratch(name);
    for file in compiled(AX200).iter().filter(|f| kinds.contains(&f.kind)) {
        std::fs::write(dir.join(&file.file_name), &file.contents).unwrap();
    }
    dir
}

fn run(command: &mut std::process::Command) {
    let output = command.output().unwrap();
    assert!(
        output.status.success(),
        "{command:?}\n{}{}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
}

/// The C layout reads User_Prm_Data without the setting it does not carry:
/// the fault reaction at bytes 16-17, checked against its own choices (999
/// is the telegram selection's, and refused there), then the ramp-down
/// time's one byte at 18.
#[test]
fn the_c_layout_reads_user_prm_data_without_the_setting_a_master_cannot_set() {
    let dir = written("c-prm", &[ArtifactKind::CHeader, ArtifactKind::CSupport]);
    let program = format!(
        r#"#include "ax200_layout.h"
#include <stdio.h>
int main(void)
{{
    const uint8_t ramp[] = {{ {ramp} }};
    const uint8_t free_telegram[] = {{ {free} }};
    ax200_user_prm_t prm;
    gsdc_prm_result_t result = ax200_decode_user_prm(ramp, sizeof ramp, &prm);
    if (AX200_USER_PRM_LEN != 19U || sizeof prm.settings != 4U) return 1;
    if (result.fault != GSDC_PRM_OK || prm.settings[0] != 1U) return 2;
    if (prm.settings[1] != 30U) return 5;
    if (prm.pzd_in[2] != 947U) return 3;
    result = ax200_decode_user_prm(free_telegram, sizeof free_telegram, &prm);
    if (result.fault != GSDC_PRM_NOT_ALLOWED || result.offset != 16U) return 4;
    puts("ok");
    return 0;
}}
"#,
        ramp = ax200_user_prm(1),
        free = ax200_user_prm(999)
    );
    std::fs::write(dir.join("main.c"), program).unwrap();
    let binary = dir.join("main");
    run(std::process::Command::new("gcc")
        .args([
            "-std=c99",
            "-Wall",
            "-Wextra",
            "-Wpedantic",
            "-Wconversion",
            "-Wsign-conversion",
            "-Werror",
            "-o",
        ])
        .arg(&binary)
        .arg(dir.join("main.c"))
        .current_dir(&dir));
    run(&mut std::process::Command::new(&binary));
}

/// The Rust layout alike.
#[test]
fn the_rust_layout_reads_user_prm_data_without_the_setting_a_master_cannot_set() {
    let dir = written(
        "rust-prm",
        &[ArtifactKind::RustLayout, ArtifactKind::RustSupport],
    );
    let program = format!(
        r#"include!("gsdc_support.rs");
#[allow(dead_code)]
mod ax200 {{
    include!("ax200_layout.rs");
}}
use gsdc_support::PrmError;
fn main() {{
    let prm = ax200::decode_user_prm(&[{ramp}]).unwrap();
    assert_eq!(prm.settings, [1, 30]);
    assert_eq!(prm.pzd_in[2], 947);
    assert_eq!(ax200::settings::USER_PRM_MAPPINGS[0].name, "Fault reaction (P1900)");
    let refused = ax200::decode_user_prm(&[{free}]).unwrap_err();
    assert_eq!(refused, PrmError::NotAllowed {{ offset: 16, value: 999 }});
}}
"#,
        ramp = ax200_user_prm(1),
        free = ax200_user_prm(999)
    );
    std::fs::write(dir.join("main.rs"), program).unwrap();
    let binary = dir.join("main");
    run(std::process::Command::new("rustc")
        .args(["--edition", "2021", "-o"])
        .arg(&binary)
        .arg(dir.join("main.rs")));
    run(&mut std::process::Command::new(&binary));
}

// ---------------------------------------------------------------------------
// Texts that break lines: a channel diagnosis's, as SEW's MOVI-C writes
// its remedies one per line, and no other.

const OWN_IDENTS: &str = include_str!("fixtures/valid/own_idents.toml");

/// The line break of own_idents.toml's extended diagnosis help reaches the
/// GSDML as `&#10;`, which a reader takes back as a line break (a literal
/// one would be read as a blank); a tab there, and a line break in the
/// device's name, are E135.
#[test]
fn only_a_diagnosis_text_breaks_lines_and_only_with_a_line_break() {
    let (ir, diagnostics) = gsdc::load("own_idents.toml", OWN_IDENTS);
    let ir = ir.unwrap_or_else(|| panic!("{diagnostics:?}"));
    let (_, gsdml) = one(gsdc::compile(&ir).unwrap(), ArtifactKind::Gsdml);
    let help = "- Let the motor cool down.\n- Check the motor's ventilation.";
    let tree = roxmltree::Document::parse(&gsdml).unwrap();
    let read_back = tree
        .descendants()
        .find(|n| {
            n.attribute("TextId") == Some("IDT_DIAG_0100_0001_HELP") && n.has_attribute("Value")
        })
        .and_then(|n| n.attribute("Value"));
    assert_eq!(read_back, Some(help));

    let errors = |text: &str| -> Vec<&'static str> {
        let (_, diagnostics) = gsdc::load("own_idents.toml", text);
        diagnostics.errors().map(|d| d.code).collect()
    };
    let tab = edited(OWN_IDENTS, "cool down.\\n- Check", "cool down.\\t- Check");
    assert_eq!(errors(&tab), ["E135"]);
    let name = edited(
        OWN_IDENTS,
        "en = \"X4 drive interface\"",
        "en = \"X4 drive\\ninterface\"",
    );
    assert_eq!(errors(&name), ["E135"]);
}
