//! The GSD reader, schema and rules against the real files of
//! `shared/corpus/gsd`, against the independent `gsd-parser`, and one small
//! hand-written file per rule.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use crate::support;
use gsdc::gsd::{self, Arg, Baud, PrmDataType, Value};
use gsdc::{Diagnostics, Severity};

// ---------------------------------------------------------------------------
// Corpus

fn corpus_dir() -> PathBuf {
    support::shared("corpus/gsd")
}

/// Every GSD file of the corpus (by name), read as bytes. Fails, never
/// skips, when the corpus is missing.
fn corpus() -> Vec<(String, Vec<u8>)> {
    let dir = corpus_dir();
    let entries = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("the GSD corpus must be at {}: {e}", dir.display()));
    let mut files: Vec<(String, Vec<u8>)> = entries
        .map(|e| e.expect("readable corpus entry").path())
        .filter(|p| !p.extension().is_some_and(|e| e.eq_ignore_ascii_case("tsv")))
        .map(|p| {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            (name, std::fs::read(&p).expect("readable corpus file"))
        })
        .collect();
    files.sort();
    assert!(
        files.len() >= 60,
        "expected the 61 corpus files, found {}",
        files.len()
    );
    files
}

/// Every finding in the corpus: (file, rule, count). Each error and each
/// calibrated warning is explained in docs/rules.md (GSD files), "Known
/// findings in the corpus". Siemens' own STEP 7 catalog files (`ivangre4__`)
/// have warnings only: STEP 7 imports them.
const KNOWN_FINDINGS: &[(&str, &str, usize)] = &[
    ("cotara__Red_ID.gsd", "W211", 16),
    // Compact, yet `Max_Module = 4` and 98 modules.
    ("ivangre4__DR0200A7.gse", "W233", 1),
    ("ivangre4__SI028131.GSD", "W205", 1),
    // `31.25_supp = 1` without `MaxTsdr_31.25`.
    ("ivangre4__SI028131.GSD", "W232", 1),
    ("ivangre4__SIEM8008.GSE", "W205", 1),
    ("ivangre4__SIEM8008.GSE", "W212", 1),
    ("ivangre4__SIEM8031.GSE", "W212", 1),
    ("ivangre4__SIEM8055.GSD", "W205", 3),
    ("ivangre4__SIEM8060.GSD", "W212", 1),
    ("ivangre4__SIEM80F9.GSE", "W205", 3),
    ("ivangre4__Siem8078.gsd", "W205", 4),
    ("ivangre4__si0380a7.gse", "W205", 2),
    ("ivangre4__si04806a.gse", "W205", 1),
    // No GSD_Revision: a revision-0 file, judged by revision 0.
    ("ivangre4__siem8037.gsd", "W205", 1),
    ("joao404__STM32F1002A.gsd", "E206", 1),
    ("joao404__STM32F1002A.gsd", "W205", 1),
    ("marcosgatcom__PRU_0CDA.GSD", "W210", 30),
    ("mbuesch__dummy_compact.gsd", "W210", 1),
    ("mbuesch__dummy_compact.gsd", "W233", 1),
    ("mbuesch__dummy_modular.gsd", "E208", 3),
    ("mbuesch__dummy_modular.gsd", "W210", 1),
    ("tuenhidiy__AVR_C0DE.GSD", "E224", 1),
    ("whatdtech__STM32F411_Profibus.gsd", "E224", 1),
];

#[test]
fn every_corpus_file_has_only_the_known_findings() {
    let mut found: BTreeMap<(String, &str), usize> = BTreeMap::new();
    let mut rendered = String::new();
    for (name, bytes) in corpus() {
        let text = gsd::decode(&bytes);
        for d in gsd::check(&text).iter() {
            *found.entry((name.clone(), d.code)).or_default() += 1;
            let source = gsdc::Source::new(&name, &text);
            rendered.push_str(&source.render(d));
        }
    }
    let expected: BTreeMap<(String, &str), usize> = KNOWN_FINDINGS
        .iter()
        .map(|(file, code, count)| ((file.to_string(), *code), *count))
        .collect();
    assert_eq!(found, expected, "{rendered}");
}

/// STEP 7 imports every file of Siemens' own catalog, so none has an error:
/// what they do is a warning at most.
#[test]
fn siemens_catalog_files_have_no_errors() {
    for (name, bytes) in corpus().iter().filter(|(n, _)| n.starts_with("ivangre4__")) {
        let text = gsd::decode(bytes);
        let diags = gsd::check(&text);
        assert!(!diags.has_errors(), "{name}: {diags:?}");
    }
}

#[test]
fn every_corpus_file_has_its_marker_and_modules() {
    for (name, bytes) in corpus() {
        let text = gsd::decode(&bytes);
        let (file, diags) = gsd::parse(&text);
        assert!(file.marker.is_some(), "{name}: no marker");
        assert!(!diags.has_errors(), "{name}: reader errors {diags:?}");
        assert!(!file.modules.is_empty(), "{name}: no modules");
        assert!(file.get("Vendor_Name").is_some(), "{name}: no Vendor_Name");
    }
}

/// gsd-parser (Rahix/profirust) reads the same modules, config bytes and
/// module reference numbers from every corpus file it can parse (it fails on
/// a few spellings, see FIELDBUS-NOTES.md section 3).
#[test]
fn gsd_parser_reads_the_same_modules() {
    let mut compared = 0;
    for (name, bytes) in corpus() {
        let text = gsd::decode(&bytes);
        let Ok(theirs) = gsd_parser::parser::parse(Path::new(&name), &text) else {
            continue;
        };
        let (ours, _) = gsd::parse(&text);
        let our_modules: Vec<_> = ours
            .modules
            .iter()
            .map(|m| {
                (
                    m.name.value.clone(),
                    m.config.value.clone(),
                    m.reference.as_ref().map(|r| r.value as u32),
                )
            })
            .collect();
        let their_modules: Vec<_> = theirs
            .available_modules
            .iter()
            .map(|m| (m.name.clone(), m.config.clone(), m.reference))
            .collect();
        assert_eq!(our_modules, their_modules, "{name}: modules differ");
        assert_eq!(
            ours.number("Ident_Number"),
            Some(i64::from(theirs.ident_number)),
            "{name}"
        );
        compared += 1;
    }
    assert!(
        compared >= 50,
        "gsd-parser parsed only {compared} corpus files"
    );
}

/// Files where gsd-parser's `PrmBuilder` builds a different default telegram
/// by its own simplifications, not by a fault of ours: it ORs a `Bit(n)`
/// default into the byte without clearing the const's bit (ABB writes
/// `Const(0) = 0x80` under a fixed `Bit(7) 0 0-0`, Siemens `0x80` under
/// `Bit(7) 0`), and it writes a `BitArea` over the whole byte, losing the
/// other areas of that byte (SIMOCODE pro packs four 2-bit areas per byte).
const PRM_BUILDER_DIFFERS: &[&str] = &[
    "siamect__abb_acs880_pb_slave.gsd",
    "ivangre4__SIEM8070.GSD",
    "ivangre4__si018070.gse",
    "ivangre4__SI0180fd.gse",
];

/// The default parameter telegram equals gsd-parser's `PrmBuilder`
/// wherever its builder models the parameters fully.
#[test]
fn default_user_prm_data_matches_gsd_parser() {
    let mut compared = 0;
    for (name, bytes) in corpus() {
        let text = gsd::decode(&bytes);
        let Ok(theirs) = gsd_parser::parser::parse(Path::new(&name), &text) else {
            continue;
        };
        let (ours, _) = gsd::parse(&text);
        let builder = gsd_parser::PrmBuilder::new(&theirs.user_prm_data);
        let same = ours.default_user_prm_data() == builder.as_bytes();
        assert_eq!(
            same,
            !PRM_BUILDER_DIFFERS.contains(&name.as_str()),
            "{name}"
        );
        compared += 1;
    }
    assert!(compared >= 50);
}

// ---------------------------------------------------------------------------
// Reader

#[test]
fn decode_falls_back_to_latin1() {
    assert_eq!(gsd::decode("Größe".as_bytes()), "Größe");
    assert_eq!(gsd::decode(b"Gr\xf6\xdfe"), "Größe");
}

#[test]
fn reader_handles_what_vendors_write() {
    let text = "; header comment\r\n  #PROFIBUS_DP ; the marker\r\n\
        GSD_REVISION = 0X05\r\n\
        Vendor_Name = \"A;B \\\r\nC\" ; comment\r\n\
        User_Prm_Data = 0x00,\\   ; first\r\n\t0x01 ,2\r\n\
        24V Pins = 1\r\n\
        Slave_Family = 3@TI@AM335x Board ; family\r\n\
        MaxTsdr_1.5M = 150\r\n\
        Unit_Diag_!Bit(0003) = \"x\"\r\n\
        Module = \"M\" 0x42,0x84,0x08,0x05\r\n5\r\nEndModule";
    let (file, diags) = gsd::parse(text);
    assert!(diags.is_empty(), "{diags:?}");
    assert_eq!(file.number("gsd_revision"), Some(5));
    assert_eq!(file.string("VENDOR_NAME"), Some("A;B C"));
    assert_eq!(
        file.get("User_Prm_Data").unwrap().value,
        Value::List(vec![0, 1, 2])
    );
    let pins = file.get("24V_Pins").unwrap();
    assert_eq!(pins.name, "24V Pins");
    assert_eq!(
        file.get("Slave_Family").unwrap().value,
        Value::Family {
            main: 3,
            sub: vec!["TI".into(), "AM335x Board".into()]
        }
    );
    let tsdr = file.get("maxtsdr_1.5m").unwrap();
    assert_eq!(tsdr.arg, Some(Arg::Baud(Baud::B1M5)));
    assert_eq!(&text[tsdr.name_span.clone()], "MaxTsdr_1.5M");
    let not_bit = file.get("Unit_Diag_Not_Bit").unwrap();
    assert_eq!(not_bit.index(), Some(3));
    let module = &file.modules[0];
    assert_eq!(module.reference.as_ref().map(|r| r.value), Some(5));
    assert_eq!(module.io_lengths().unwrap().input, 5);
}

#[test]
fn reader_reads_blocks() {
    let text = "#Profibus_DP\n\
        PrmText=1\nText(0)=\"off\"\nText(1)=\"on\"\nEndPrmText\n\
        ExtUserPrmData=7 \"Mode\"\nBitArea(4-6) 2 0,2,5\nPrm_Text_Ref=1\nChangeable=0\nEndExtUserPrmData\n\
        ExtUserPrmData=8 \"Speed\"\nSigned16 -5 -10-10\nEndExtUserPrmData\n\
        Unit_Diag_Area=16-17\nValue(0)=\"ok\"\nUnit_Diag_Area_End\n\
        UnitDiagType=130\nX_Unit_Diag_Area=24-25\nX_Value(1)=\"fault\"\nX_Unit_Diag_Area_End\nEndUnitDiagType\n\
        SlotDefinition\nSlot(1)=\"Data\" 1 1-3\nEndSlotDefinition\n\
        Physical_Interface = 0\nTransmission_Delay_12M = 0\nEnd_Physical_Interface\n\
        Module=\"M\" 0x10\n1\nData_Area_Beg\nLength=5\nData_Area_End\nEndModule\n";
    let (file, diags) = gsd::parse(text);
    assert!(diags.is_empty(), "{diags:?}");
    assert_eq!(file.prm_texts[0].texts[1].text.value, "on");
    let mode = &file.ext_user_prm_data[0];
    assert_eq!(
        mode.data_type.as_ref().unwrap().value,
        PrmDataType::BitArea(4, 6)
    );
    assert_eq!(mode.default.as_ref().unwrap().value, 2);
    assert_eq!(mode.allowed.value, gsd::Allowed::Set(vec![0, 2, 5]));
    assert_eq!(mode.prm_text_ref.as_ref().unwrap().value, 1);
    assert_eq!(mode.changeable, Some(false));
    let speed = &file.ext_user_prm_data[1];
    assert_eq!(speed.allowed.value, gsd::Allowed::Range(-10, 10));
    assert_eq!(speed.default.as_ref().unwrap().value, -5);
    assert_eq!(file.unit_diag_areas[0].values[0].text.value, "ok");
    assert_eq!(file.unit_diag_types[0].areas[0].values[0].index, 1);
    assert_eq!(file.slots[0].allowed.value, gsd::Allowed::Range(1, 3));
    assert_eq!(file.blocks[0].settings[0].name, "Transmission_Delay_12M");
    assert_eq!(
        file.modules[0].data_areas[0].settings[0].value,
        Value::Number(5)
    );
}

#[test]
fn default_telegram_lays_consts_then_refs_big_endian() {
    let text = "#Profibus_DP\n\
        ExtUserPrmData=1 \"A\"\nUnsigned16 61452 0-65535\nEndExtUserPrmData\n\
        ExtUserPrmData=2 \"B\"\nBit(1) 1 0-1\nEndExtUserPrmData\n\
        Ext_User_Prm_Data_Const(0)=0x80,0x00,0x08,0xFF\n\
        Ext_User_Prm_Data_Ref(3)=1\nExt_User_Prm_Data_Ref(2)=2\n\
        Module=\"M\" 0x10\nExt_Module_Prm_Data_Len=1\nExt_User_Prm_Data_Ref(0)=2\nEndModule\n";
    let (file, _) = gsd::parse(text);
    assert_eq!(file.default_user_prm_data(), [0x80, 0x00, 0x0A, 0xF0, 0x0C]);
    assert_eq!(file.modules[0].default_prm_data(&file), [0x02]);
}

/// Inputs a fuzzer would try: nothing here may panic, and time must grow
/// linearly (a quadratic step on these sizes would take minutes).
#[test]
fn reader_and_rules_survive_hostile_input() {
    let started = Instant::now();
    let long_line = format!(
        "#Profibus_DP\nUser_Prm_Data = {}0x01\n",
        "0x00,".repeat(200_000)
    );
    let long_word = format!(
        "#Profibus_DP\n{}\n\"{}",
        "A".repeat(1 << 20),
        "\\ \n".repeat(1 << 16)
    );
    let mut many_modules = String::from("#Profibus_DP\nModular_Station=1\nMax_Module=1\n");
    for i in 0..100_000 {
        many_modules.push_str(&format!(
            "Module=\"m{i}\" 0xC1,0x0F\n{i}\nExt_User_Prm_Data_Ref({i})={i}\n"
        ));
    }
    let many_refs = "#Profibus_DP\n".to_string()
        + &"Ext_User_Prm_Data_Ref(1)=1\n9.6_supp=1\nFoo_Bar_Baz=1\n".repeat(50_000);
    let garbage: String = (0u32..300_000)
        .map(|i| char::from((i.wrapping_mul(2_654_435_761) >> 24) as u8))
        .collect();
    let nesting =
        "Module=\"x\" 0x00\nData_Area_Beg\n".repeat(20_000) + &"EndModule\n".repeat(20_000);
    for text in [
        long_line,
        long_word,
        many_modules,
        many_refs,
        garbage,
        nesting,
        String::new(),
        "\\".into(),
        "\"".into(),
        "#Profibus_DP".into(),
    ] {
        let _ = gsd::check(&text);
        let _ = gsd::check_strict(&text);
        let (file, _) = gsd::parse(&text);
        let _ = file.default_user_prm_data();
    }
    assert!(
        started.elapsed() < Duration::from_secs(60),
        "took {:?}",
        started.elapsed()
    );
}

// ---------------------------------------------------------------------------
// Rules: a valid file, then one change per rule

const VALID: &[&str] = &[
    "; a drive",
    "#Profibus_DP",
    "GSD_Revision = 5",
    "Vendor_Name = \"Acme\"",
    "Model_Name = \"Drive\"",
    "Revision = \"V1\"",
    "Ident_Number = 0x1234",
    "Protocol_Ident = 0",
    "Station_Type = 0",
    "Hardware_Release = \"A1\"",
    "Software_Release = \"Z1\"",
    "1.5M_supp = 1",
    "MaxTsdr_1.5M = 150",
    "Min_Slave_Intervall = 6",
    "Slave_Family = 1@Drives",
    "Max_Diag_Data_Len = 9",
    "Modular_Station = 0",
    "Max_Input_Len = 12",
    "Max_Output_Len = 12",
    "DPV1_Slave = 1",
    "Max_User_Prm_Data_Len = 5",
    "Ext_User_Prm_Data_Const(0) = 0x00,0x00,0x00",
    "Ext_User_Prm_Data_Ref(3) = 1",
    "Unit_Diag_Bit(0) = \"Fault\"",
    "PrmText = 1",
    "Text(0) = \"Off\"",
    "Text(1) = \"On\"",
    "EndPrmText",
    "ExtUserPrmData = 1 \"Mode\"",
    "Unsigned16 1 0-2",
    "Prm_Text_Ref = 1",
    "EndExtUserPrmData",
    "Module = \"PPO1\" 0xF3,0xF1",
    "1",
    "EndModule",
];

fn valid() -> Vec<String> {
    VALID.iter().map(|s| s.to_string()).collect()
}

fn text_of(lines: &[String]) -> String {
    lines.join("\r\n") + "\r\n"
}

/// The valid file with `line` replaced (an empty replacement deletes it).
fn replaced(line: &str, by: &str) -> String {
    let mut lines = valid();
    let at = lines
        .iter()
        .position(|l| l == line)
        .unwrap_or_else(|| panic!("no line {line}"));
    if by.is_empty() {
        lines.remove(at);
    } else {
        lines[at] = by.to_string();
    }
    text_of(&lines)
}

/// The valid file with `extra` lines appended.
fn plus(extra: &[&str]) -> String {
    let mut lines = valid();
    lines.extend(extra.iter().map(|s| s.to_string()));
    text_of(&lines)
}

/// Every diagnostic has `code`, and the first points at `at`.
fn assert_only(diags: &Diagnostics, text: &str, code: &str, at: &str) {
    assert!(!diags.is_empty(), "expected {code}, got nothing");
    for d in diags.iter() {
        assert_eq!(d.code, code, "unexpected diagnostic {d:?}");
    }
    let span = diags.0[0].span.clone().expect("a span");
    assert_eq!(&text[span], at, "{code} points elsewhere");
}

fn assert_rule(text: &str, code: &str, at: &str) {
    assert_only(&gsd::check(text), text, code, at);
    let severity = if code.starts_with('E') {
        Severity::Error
    } else {
        Severity::Warning
    };
    assert_eq!(gsd::check(text).0[0].severity, severity);
}

#[test]
fn the_valid_file_is_clean_even_in_strict_mode() {
    let text = text_of(&valid());
    assert_eq!(gsd::check(&text), Diagnostics::default());
    assert_eq!(gsd::check_strict(&text), Diagnostics::default());
}

#[test]
fn e200_marker() {
    let text = replaced("#Profibus_DP", "");
    assert_rule(&text, "E200", "");
}

#[test]
fn e201_unreadable_line() {
    assert_rule(&plus(&["= 5"]), "E201", "= 5");
    assert_rule(&plus(&["Max_Data_Len 24"]), "E201", "Max_Data_Len 24");
}

#[test]
fn e202_unclosed_string() {
    assert_rule(
        &replaced("Model_Name = \"Drive\"", "Model_Name = \"Drive"),
        "E202",
        "\"Drive",
    );
}

#[test]
fn e203_unclosed_block() {
    assert_rule(&replaced("EndPrmText", ""), "E203", "PrmText");
}

#[test]
fn e204_stray_block_end() {
    assert_rule(&plus(&["EndModule"]), "E204", "EndModule");
}

#[test]
fn w205_unknown_keyword() {
    assert_rule(
        &plus(&["Min_Slave_Interval = 6"]),
        "W205",
        "Min_Slave_Interval",
    );
    let help = gsd::check(&plus(&["Min_Slave_Interval = 6"])).0[0]
        .help
        .clone()
        .unwrap();
    assert!(help.contains("Min_Slave_Intervall"), "{help}");
}

#[test]
fn e206_mandatory_keyword() {
    assert_rule(
        &replaced("Vendor_Name = \"Acme\"", ""),
        "E206",
        "#Profibus_DP",
    );
}

/// A file without GSD_Revision is revision 0, not a file missing a keyword:
/// no E206, and the keywords of later revisions get W210 as in any file.
#[test]
fn a_file_without_gsd_revision_is_revision_0() {
    let text = replaced("GSD_Revision = 5", "");
    assert_rule(&text, "W210", "DPV1_Slave");
    let label = gsd::check(&text).0[0].label.clone().unwrap();
    assert!(label.contains("this file says 0"), "{label}");
    let mut lines = valid();
    lines.retain(|l| !l.starts_with("GSD_Revision") && !l.starts_with("DPV1_Slave"));
    assert_eq!(gsd::check(&text_of(&lines)), Diagnostics::default());
}

#[test]
fn e207_value_type() {
    assert_rule(
        &replaced("Ident_Number = 0x1234", "Ident_Number = \"0x1234\""),
        "E207",
        "\"0x1234\"",
    );
    assert_rule(&plus(&["Unit_Diag_Bit = \"x\""]), "E207", "Unit_Diag_Bit");
}

#[test]
fn e208_value_range() {
    assert_rule(
        &replaced("Max_Diag_Data_Len = 9", "Max_Diag_Data_Len = 245"),
        "E208",
        "245",
    );
}

#[test]
fn w234_below_the_minimum_that_tools_accept() {
    let text = replaced("Min_Slave_Intervall = 6", "Min_Slave_Intervall = 0");
    assert_rule(&text, "W234", "0");
    // Below the tolerated minimum, or a keyword without one: still E208.
    assert_rule(
        &replaced("Max_Diag_Data_Len = 9", "Max_Diag_Data_Len = 5"),
        "E208",
        "5",
    );
}

#[test]
fn w209_string_length() {
    let long = format!("Model_Name = \"{}\"", "M".repeat(33));
    let text = replaced("Model_Name = \"Drive\"", &long);
    assert_rule(&text, "W209", &long["Model_Name = ".len()..]);
    assert!(
        gsd::check_strict(&text).has_errors(),
        "strict mode refuses it"
    );
    let module = format!("Module = \"{}\" 0xF3,0xF1", "P".repeat(33));
    let text = replaced("Module = \"PPO1\" 0xF3,0xF1", &module);
    assert_rule(&text, "W209", &module[9..44]);
}

#[test]
fn w210_keyword_newer_than_file() {
    assert_rule(
        &replaced("GSD_Revision = 5", "GSD_Revision = 2"),
        "W210",
        "DPV1_Slave",
    );
}

#[test]
fn w211_duplicate_keyword() {
    let text = plus(&["Max_Input_Len = 12"]);
    assert_rule(&text, "W211", "Max_Input_Len");
    let span = gsd::check(&text).0[0].span.clone().unwrap();
    assert!(
        span.start > text.find("Max_Input_Len").unwrap(),
        "points at the repetition"
    );
}

#[test]
fn w212_nonstandard_spelling() {
    assert_rule(&plus(&["24V Pins = 0"]), "W212", "24V Pins");
    assert_rule(
        &plus(&["Unit_Diag_!Bit(1) = \"x\""]),
        "W212",
        "Unit_Diag_!Bit",
    );
}

#[test]
fn e213_baud_without_max_tsdr() {
    assert_rule(&plus(&["12M_supp = 1"]), "E213", "12M_supp = 1");
    assert_rule(&plus(&["45.45_supp = 1"]), "E213", "45.45_supp = 1");
}

#[test]
fn w232_pa_baud_rate_without_max_tsdr() {
    assert_rule(&plus(&["31.25_supp = 1"]), "W232", "31.25_supp = 1");
    assert_eq!(
        gsd::check(&plus(&["31.25_supp = 1", "MaxTsdr_31.25 = 100"])),
        Diagnostics::default()
    );
}

#[test]
fn e214_no_baud_rate() {
    assert_rule(
        &replaced("1.5M_supp = 1", "1.5M_supp = 0"),
        "E214",
        "#Profibus_DP",
    );
}

#[test]
fn e215_config_bytes() {
    let text = replaced("Module = \"PPO1\" 0xF3,0xF1", "Module = \"PPO1\" 0xC1,0x0F");
    assert_rule(&text, "E215", "0xC1,0x0F");
    let text = replaced(
        "Module = \"PPO1\" 0xF3,0xF1",
        "Module = \"PPO1\" 0xF3,0x1F1",
    );
    assert_rule(&text, "E215", "0x1F1");
}

#[test]
fn e216_module_data_exceed_limits() {
    assert_rule(
        &replaced("Max_Input_Len = 12", "Max_Input_Len = 8"),
        "E216",
        "0xF3,0xF1",
    );
    let text = plus(&["Max_Data_Len = 20"]);
    assert_rule(&text, "E216", "0xF3,0xF1");
}

#[test]
fn e217_compact_station_without_a_module() {
    let mut lines = valid();
    let module = lines.iter().position(|l| l.starts_with("Module")).unwrap();
    lines.truncate(module);
    assert_rule(&text_of(&lines), "E217", "Modular_Station = 0");
}

#[test]
fn w233_compact_station_with_several_modules() {
    assert_rule(
        &plus(&["Module = \"PPO3\" 0xF1", "EndModule"]),
        "W233",
        "\"PPO3\"",
    );
}

#[test]
fn e218_modular_station_needs_max_module() {
    assert_rule(
        &replaced("Modular_Station = 0", "Modular_Station = 1"),
        "E218",
        "Modular_Station = 1",
    );
}

#[test]
fn e219_parameter_beyond_length() {
    let text = replaced("Max_User_Prm_Data_Len = 5", "Max_User_Prm_Data_Len = 4");
    assert_rule(&text, "E219", "Ext_User_Prm_Data_Ref(3) = 1");
    let text = replaced("1", "1\r\nExt_User_Prm_Data_Const(0) = 0x01");
    assert_rule(&text, "E219", "Ext_User_Prm_Data_Const(0) = 0x01");
}

#[test]
fn e220_reference_to_undefined_parameter() {
    assert_rule(
        &replaced(
            "Ext_User_Prm_Data_Ref(3) = 1",
            "Ext_User_Prm_Data_Ref(3) = 2",
        ),
        "E220",
        "2",
    );
}

#[test]
fn e221_default_outside_allowed_values() {
    assert_rule(
        &replaced("Unsigned16 1 0-2", "Unsigned16 3 0-2"),
        "E221",
        "3",
    );
    assert_rule(
        &replaced("Unsigned16 1 0-2", "Unsigned16 1 0-70000"),
        "E221",
        "0-70000",
    );
}

#[test]
fn e222_overlapping_parameters() {
    let text = plus(&["Ext_User_Prm_Data_Ref(4) = 1"]);
    let text = text.replace("Max_User_Prm_Data_Len = 5", "Max_User_Prm_Data_Len = 6");
    assert_rule(&text, "E222", "Ext_User_Prm_Data_Ref(4) = 1");
}

#[test]
fn e223_reference_to_undefined_text() {
    assert_rule(
        &replaced("Prm_Text_Ref = 1", "Prm_Text_Ref = 7"),
        "E223",
        "7",
    );
}

#[test]
fn e224_duplicate_ids() {
    let text = plus(&[
        "ExtUserPrmData = 1 \"Again\"",
        "Unsigned8 0 0-1",
        "EndExtUserPrmData",
    ]);
    assert_rule(&text, "E224", "1");
    let text = plus(&["PrmText = 1", "Text(0) = \"x\"", "EndPrmText"]);
    assert_rule(&text, "E224", "1");
}

#[test]
fn e225_dpv1_status_bytes() {
    let mut lines = valid();
    lines.retain(|l| !l.starts_with("Ext_User_Prm_Data") && !l.starts_with("Max_User"));
    lines.push("User_Prm_Data_Len = 2".into());
    assert_rule(&text_of(&lines), "E225", "DPV1_Slave = 1");
}

#[test]
fn w231_diagnosis_area_without_values() {
    assert_rule(
        &plus(&["Unit_Diag_Area = 0-7", "Unit_Diag_Area_End"]),
        "W231",
        "Unit_Diag_Area",
    );
}

#[test]
fn e226_diagnosis_bit_beyond_length() {
    assert_rule(
        &plus(&["Unit_Diag_Bit(24) = \"Late\""]),
        "E226",
        "Unit_Diag_Bit(24) = \"Late\"",
    );
    assert_rule(
        &plus(&[
            "Unit_Diag_Area = 16-31",
            "Value(0) = \"x\"",
            "Unit_Diag_Area_End",
        ]),
        "E226",
        "16-31",
    );
}

#[test]
fn e227_user_prm_data_length() {
    assert_rule(&plus(&["User_Prm_Data_Len = 6"]), "E227", "6");
    assert_rule(
        &plus(&[
            "User_Prm_Data_Len = 5",
            "User_Prm_Data = 0x00,0x00,0x00,0x00",
        ]),
        "E227",
        "0x00,0x00,0x00,0x00",
    );
}

#[test]
fn e228_parameter_data_type() {
    assert_rule(
        &replaced("Unsigned16 1 0-2", "Unsigned12 1 0-2"),
        "E228",
        "Unsigned12",
    );
    assert_rule(
        &replaced("Unsigned16 1 0-2", "BitArea(6-9) 1 0-2"),
        "E228",
        "BitArea(6-9)",
    );
    assert_rule(&replaced("Unsigned16 1 0-2", ""), "E228", "1");
}

/// What tools accept in a vendor's file is still a defect in gsdc's own.
#[test]
fn strict_profile_refuses_the_calibrated_warnings() {
    for (text, code) in [
        (plus(&["31.25_supp = 1"]), "W232"),
        (plus(&["Module = \"PPO3\" 0xF1", "EndModule"]), "W233"),
        (
            replaced("Min_Slave_Intervall = 6", "Min_Slave_Intervall = 0"),
            "W234",
        ),
    ] {
        let diags = gsd::check_strict(&text);
        assert!(diags.errors().any(|d| d.code == code), "{code}: {diags:?}");
    }
}

#[test]
fn strict_profile_checks_the_output_format() {
    let long = format!("Info_Text = \"{}\"", "x".repeat(80));
    let text = plus(&[&long]);
    assert_only(&gsd::check_strict(&text), &text, "E240", &long[80..]);
    let text = plus(&["Info_Text = \"Größe\""]);
    assert_only(&gsd::check_strict(&text), &text, "E241", "ö");
    let text = text_of(&valid()).replace("\r\n", "\n");
    let diags = gsd::check_strict(&text);
    assert_only(&diags, &text, "E242", "\n");
    assert!(diags.0[0].is_error());
}
