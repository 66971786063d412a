//! `gsdc diff` on constructed pairs: a shipped description's GSD or GSDML
//! file against the same file after one fact changed, in the description
//! (as a maker would change it) or in the built file (for facts a
//! description does not give one by one, like a module's ident number).
//! Each pair must give the one change of the right kind and class, and
//! nothing else. Facts no shipped description can produce (GSD choice
//! texts, slots) are changed in a real GSD of the corpus.

use gsdc::device::{self, Device};
use gsdc::diff::{Change, Class, Kind};

use crate::support::{self, descriptions};

/// An edit that must find what it replaces.
enum Edit {
    /// In the description, the one place of the text.
    Description(&'static str, &'static str),
    /// In the built file, the first place of the text.
    File(&'static str, &'static str),
    /// In the built file, from the first `start` to the end of the `end`
    /// after it, removed.
    Cut(&'static str, &'static str),
}

use Edit::{Cut, Description as D, File as F};

/// The files a description's text builds, by name.
fn build(name: &str, text: &str) -> Vec<gsdc::Artifact> {
    let (ir, diagnostics) = descriptions::load_text(name, text);
    let ir = ir.unwrap_or_else(|| panic!("{name} does not load: {diagnostics:#?}"));
    gsdc::compile(&ir).unwrap_or_else(|d| panic!("{name} does not compile: {d:#?}"))
}

fn replace_once(text: &str, from: &str, to: &str, exactly_once: bool) -> String {
    let count = text.matches(from).count();
    assert!(count >= 1, "`{from}` is not in the text");
    assert!(
        !exactly_once || count == 1,
        "`{from}` is in the description {count} times"
    );
    text.replacen(from, to, 1)
}

/// MV810 as if the master set its mappings: the shipped MV810 sets them at
/// the drive (its manual's section 4), so its GSDML has no parameter
/// record; this one has records with choices and a value each module fixes.
const MV810_RECORDS: &str = "mv810-pnet02.toml, set by the master";

/// The name a description is built under, and its text.
fn source(description: &str) -> (&str, String) {
    match description {
        MV810_RECORDS => ("mv810-pnet02.toml", descriptions::mv810_set_by_master()),
        name => (name, descriptions::shipped_text(name)),
    }
}

/// The file of the description ending in `suffix` (`.GSD`, `.xml`), before
/// and after the edits.
fn files(description: &str, suffix: &str, edits: &[Edit]) -> (Vec<u8>, Vec<u8>) {
    let (description, text) = source(description);
    let mut changed = text.clone();
    for edit in edits {
        if let D(from, to) = edit {
            changed = replace_once(&changed, from, to, true);
        }
    }
    let pick = |text: &str| -> Vec<u8> {
        build(description, text)
            .into_iter()
            .find(|a| a.file_name.ends_with(suffix))
            .unwrap_or_else(|| panic!("{description} builds no {suffix}"))
            .contents
    };
    let old = pick(&text);
    let mut new = String::from_utf8(pick(&changed)).unwrap();
    for edit in edits {
        match edit {
            F(from, to) => new = replace_once(&new, from, to, false),
            Cut(start, end) => {
                let at = new
                    .find(start)
                    .unwrap_or_else(|| panic!("`{start}` not found"));
                let stop = at
                    + new[at..]
                        .find(end)
                        .unwrap_or_else(|| panic!("`{end}` not found"))
                    + end.len();
                new.replace_range(at..stop, "");
            }
            D(..) => {}
        }
    }
    (old, new.into_bytes())
}

fn read(bytes: &[u8], name: &str) -> Device {
    device::read(bytes, Some(name)).unwrap_or_else(|| panic!("{name} cannot be read"))
}

fn diff(old: &[u8], new: &[u8]) -> Vec<Change> {
    let (old, new) = (read(old, "FILE"), read(new, "FILE"));
    gsdc::diff::compare(&old, &new).expect("files of one kind")
}

/// The changes of one pair of a description's files.
fn changes(description: &str, suffix: &str, edits: &[Edit]) -> Vec<Change> {
    let (old, new) = files(description, suffix, edits);
    diff(&old, &new)
}

/// Exactly one change, of this class and kind, whose text holds `says`.
#[track_caller]
fn one(changes: &[Change], class: Class, kind: Kind, says: &str) -> Change {
    assert_eq!(changes.len(), 1, "expected one change: {changes:#?}");
    let change = changes[0].clone();
    assert_eq!((change.class, change.kind), (class, kind), "{change:#?}");
    assert!(
        change.change.contains(says),
        "`{}` does not say `{says}`",
        change.change
    );
    assert!(change.judged, "{change:#?}");
    change
}

/// The pair and its reverse: one change each way, of these classes.
#[track_caller]
fn both_ways(
    description: &str,
    suffix: &str,
    edits: &[Edit],
    kind: Kind,
    classes: (Class, Class),
    says: (&str, &str),
) {
    let (old, new) = files(description, suffix, edits);
    one(&diff(&old, &new), classes.0, kind, says.0);
    one(&diff(&new, &old), classes.1, kind, says.1);
}

const GSD: &str = ".GSD";
const GSDML: &str = ".xml";
use Class::{Breaking, Compatible, Cosmetic};

#[test]
fn identical_builds_have_no_change() {
    for description in [
        "md810dp.toml",
        "9kdp1.toml",
        "mv810-pnet02.toml",
        "md810-gateway.toml",
    ] {
        for suffix in [GSD, GSDML] {
            let text = descriptions::shipped_text(description);
            let Some(file) = build(description, &text)
                .into_iter()
                .find(|a| a.file_name.ends_with(suffix))
            else {
                continue;
            };
            assert_eq!(
                diff(&file.contents, &file.contents),
                [],
                "{description} {suffix}"
            );
        }
    }
}

/// Every real file of the corpus is read as a device, and is its own
/// equal: the comparison finds nothing where nothing changed.
#[test]
fn every_corpus_file_reads_and_equals_itself() {
    let mut read = 0;
    for folder in ["gsd", "gsdml"] {
        for name in support::file_names(&support::shared("corpus").join(folder)) {
            if name.ends_with(".tsv") {
                continue;
            }
            let bytes = support::corpus_file(&format!("{folder}/{name}"));
            let device = device::read(&bytes, Some(&name))
                .unwrap_or_else(|| panic!("{name} cannot be read"));
            assert_eq!(
                gsdc::diff::compare(&device, &device),
                Some(vec![]),
                "{name}"
            );
            read += 1;
        }
    }
    assert_eq!(read, 61 + 16);
}

/// A change in the description that no file carries (a comment, a
/// reason) changes nothing, though the reason is in each file's header.
#[test]
fn comments_and_reasons_change_nothing() {
    let edits = [
        D(
            "# 1.3.1: MD810 supports PPO1..PPO5",
            "# as 1.3.1 says, MD810 supports PPO1..PPO5",
        ),
        D(
            "the card must detect the rate\"",
            "the card detects the rate itself\"",
        ),
    ];
    assert_eq!(changes("md810dp.toml", GSD, &edits), []);
    assert_eq!(changes("md810dp.toml", GSDML, &edits), []);
}

// GSD: identity, timing, features.

#[test]
fn gsd_ident_number_breaks() {
    let edits = [D(
        "ident_number = { value = 0x0810",
        "ident_number = { value = 0x0812",
    )];
    let found = changes("md810dp.toml", GSD, &edits);
    one(&found[..1], Breaking, Kind::Identity, "\"2064\" → \"2066\"");
    // The draft notice names the placeholder: Info_Text changes with it.
    let notice = one(&found[1..], Cosmetic, Kind::Text, "0x0812 is a placeholder");
    assert_eq!(notice.subject, "Info_Text");
}

#[test]
fn gsd_revision_and_texts_are_cosmetic() {
    let edits = [D("revision = \"V1.00\"", "revision = \"V1.01\"")];
    let change = one(
        &changes("md810dp.toml", GSD, &edits),
        Cosmetic,
        Kind::Identity,
        "\"V1.00\" → \"V1.01\"",
    );
    assert_eq!(change.subject, "Revision");
    let edits = [D(
        "DPV1 acyclic read and write of six custom indexes\"",
        "DPV1 acyclic access to six custom indexes\"",
    )];
    one(
        &changes("md810dp.toml", GSD, &edits),
        Cosmetic,
        Kind::Text,
        "custom indexes",
    );
}

#[test]
fn gsd_max_tsdr_raised_breaks_lowered_does_not() {
    let edits = [D("\"1.5M\" = 150", "\"1.5M\" = 200")];
    both_ways(
        "md810dp.toml",
        GSD,
        &edits,
        Kind::Timing,
        (Breaking, Compatible),
        ("\"150\" → \"200\"", "\"200\" → \"150\""),
    );
}

#[test]
fn gsd_baud_rate_dropped_is_one_change() {
    let edits = [D("\"12M\" = 800\n", "")];
    let (old, new) = files("md810dp.toml", GSD, &edits);
    let change = one(&diff(&old, &new), Breaking, Kind::Timing, "\"1\" removed");
    assert_eq!(change.subject, "12M_supp");
    one(&diff(&new, &old), Compatible, Kind::Timing, "\"1\" added");
}

#[test]
fn gsd_min_slave_interval_and_auto_baud() {
    let edits = [D("min_slave_interval = 1\n", "min_slave_interval = 3\n")];
    both_ways(
        "md810dp.toml",
        GSD,
        &edits,
        Kind::Timing,
        (Breaking, Compatible),
        ("\"1\" → \"3\"", "\"3\" → \"1\""),
    );
    let edits = [D("auto_baud = true", "auto_baud = false")];
    both_ways(
        "md810dp.toml",
        GSD,
        &edits,
        Kind::Timing,
        (Breaking, Compatible),
        ("\"1\" → \"0\"", "\"0\" → \"1\""),
    );
}

#[test]
fn gsd_limits_lowered_break() {
    let edits = [F(
        "C1_Max_Data_Len             = 2",
        "C1_Max_Data_Len             = 1",
    )];
    both_ways(
        "md810dp.toml",
        GSD,
        &edits,
        Kind::Feature,
        (Breaking, Compatible),
        ("\"2\" → \"1\"", "\"1\" → \"2\""),
    );
}

#[test]
fn gsd_revision_keyword_is_compatible() {
    let edits = [F(
        "GSD_Revision                = 5",
        "GSD_Revision                = 4",
    )];
    one(
        &changes("md810dp.toml", GSD, &edits),
        Compatible,
        Kind::File,
        "\"5\" → \"4\"",
    );
}

#[test]
fn gsd_keyword_without_a_rule_is_breaking_and_not_judged() {
    let edits = [F(
        "Fail_Safe                   = 0",
        "Fail_Safe                   = 0\r\nVendor_Frobnicate = 1",
    )];
    let found = changes("md810dp.toml", GSD, &edits);
    assert_eq!(found.len(), 1, "{found:#?}");
    assert_eq!((found[0].class, found[0].judged), (Breaking, false));
}

// GSD: modules.

#[test]
fn gsd_module_removed_breaks_added_does_not() {
    // From the module's line: the header names the module first.
    let edits = [Cut("Module = \"PPO3: 2 PZD\" 0xF1", "EndModule\r\n")];
    both_ways(
        "md810dp.toml",
        GSD,
        &edits,
        Kind::Module,
        (Breaking, Compatible),
        ("removed (config bytes 0xF1)", "added (config bytes 0xF1)"),
    );
}

#[test]
fn gsd_config_bytes_changed_break_a_rename_does_not() {
    let edits = [F(
        "Module = \"PPO3: 2 PZD\" 0xF1",
        "Module = \"PPO3: 2 PZD\" 0xF2",
    )];
    one(
        &changes("md810dp.toml", GSD, &edits),
        Breaking,
        Kind::Module,
        "config bytes 0xF1 (4 bytes in, 4 out) → 0xF2 (6 bytes in, 6 out)",
    );
    let edits = [F(
        "Module = \"PPO3: 2 PZD\" 0xF1",
        "Module = \"PPO3: two PZD\" 0xF1",
    )];
    one(
        &changes("md810dp.toml", GSD, &edits),
        Cosmetic,
        Kind::Text,
        "\"PPO3: 2 PZD\" → \"PPO3: two PZD\"",
    );
}

// GSD: User_Prm_Data.

#[test]
fn gsd_parameter_default_reaches_new_projects_only() {
    let edits = [F("Unsigned16 61440 0-65535", "Unsigned16 61441 0-65535")];
    let change = one(
        &changes("md810dp.toml", GSD, &edits),
        Compatible,
        Kind::Parameter,
        "default 61440 → 61441",
    );
    assert!(
        change
            .subject
            .contains("\"PZD1(master->slaver)\" at byte 3 of User_Prm_Data"),
        "{}",
        change.subject
    );
}

#[test]
fn gsd_parameter_range_narrowed_breaks_widened_does_not() {
    let edits = [F("Unsigned8 1 1-30", "Unsigned8 1 1-20")];
    both_ways(
        "md810-gateway.toml",
        GSD,
        &edits,
        Kind::Parameter,
        (Breaking, Compatible),
        ("allowed 1..30 → 1..20", "allowed 1..20 → 1..30"),
    );
}

#[test]
fn gsd_parameter_type_changed_breaks() {
    let edits = [F("Unsigned8 1 1-30", "Signed8 1 1-30")];
    one(
        &changes("md810-gateway.toml", GSD, &edits),
        Breaking,
        Kind::Parameter,
        "type Unsigned8 → Signed8",
    );
}

#[test]
fn gsd_parameter_removed_breaks_and_added_with_the_fixed_default_does_not() {
    // Slave 5's TPDO words (default 0) at byte 9: without it, byte 9 is a
    // fixed 0, which old projects... send as before only when they kept 0.
    let edits = [F("Ext_User_Prm_Data_Ref(9)    = 10\r\n", "")];
    both_ways(
        "md810-gateway.toml",
        GSD,
        &edits,
        Kind::Parameter,
        (Breaking, Compatible),
        ("removed", "added, default 0"),
    );
}

#[test]
fn gsd_parameter_moved_breaks() {
    // Slave 5's TPDO words and RPDO words trade places.
    let edits = [
        F(
            "Ext_User_Prm_Data_Ref(9)    = 10",
            "Ext_User_Prm_Data_Ref(9)    = X",
        ),
        F(
            "Ext_User_Prm_Data_Ref(10)   = 11",
            "Ext_User_Prm_Data_Ref(10)   = 10",
        ),
        F(
            "Ext_User_Prm_Data_Ref(9)    = X",
            "Ext_User_Prm_Data_Ref(9)    = 11",
        ),
    ];
    let found = changes("md810-gateway.toml", GSD, &edits);
    assert_eq!(found.len(), 2, "{found:#?}");
    for change in &found {
        assert_eq!((change.class, change.kind), (Breaking, Kind::Parameter));
        assert!(
            change.change.starts_with("moved from byte"),
            "{}",
            change.change
        );
    }
}

#[test]
fn gsd_fixed_bytes_changed_break() {
    let edits = [D(
        "status_bytes = [0x00, 0x00, 0x00]",
        "status_bytes = [0x80, 0x00, 0x00]",
    )];
    one(
        &changes("md810dp.toml", GSD, &edits),
        Breaking,
        Kind::Parameter,
        "fixed byte 0: 0x00 → 0x80",
    );
}

#[test]
fn gsd_parameter_telegram_longer_breaks_once() {
    let edits = [D("last = 5\n", "last = 6\n")];
    let found = changes("md810dp.toml", GSD, &edits);
    // Index6 appended: the telegram grows, and so does the maximum the
    // device declares, which old projects stay within.
    one(
        &found[..1],
        Breaking,
        Kind::Parameter,
        "63 → 65 bytes, adding \"Index6\"",
    );
    let limit = one(&found[1..], Compatible, Kind::Parameter, "\"63\" → \"65\"");
    assert_eq!(limit.subject, "Max_User_Prm_Data_Len");
}

/// A file of GSD revision 0 or 1 states its parameter telegram's length
/// as User_Prm_Data_Len only: Max_User_Prm_Data_Len of the same value
/// offers the master the same telegram, no change either way; a longer
/// one is the limit raised (and the declared telegram longer).
#[test]
fn gsd_legacy_user_prm_data_len_is_the_same_limit() {
    let legacy = [F(
        "Max_User_Prm_Data_Len       = 63",
        "User_Prm_Data_Len           = 63",
    )];
    let (old, new) = files("md810dp.toml", GSD, &legacy);
    assert_eq!(diff(&old, &new), [], "legacy length stated");
    assert_eq!(diff(&new, &old), [], "legacy length replaced");
    let shorter = [F(
        "Max_User_Prm_Data_Len       = 63",
        "User_Prm_Data_Len           = 62",
    )];
    let (_, shorter) = files("md810dp.toml", GSD, &shorter);
    let found = diff(&shorter, &old);
    let limit = found
        .iter()
        .find(|c| c.subject == "Max_User_Prm_Data_Len")
        .unwrap_or_else(|| panic!("{found:#?}"));
    assert_eq!(
        (limit.class, limit.change.as_str()),
        (Compatible, "\"62\" → \"63\"")
    );
}

// GSD: diagnosis.

#[test]
fn gsd_diagnosis_texts_values_and_areas() {
    let edits = [D(
        "text = { en = \"DP card-drive comm. interrupted\"",
        "text = { en = \"DP card lost the drive\"",
    )];
    one(
        &changes("md810dp.toml", GSD, &edits),
        Cosmetic,
        Kind::Text,
        "\"DP card-drive comm. interrupted\" → \"DP card lost the drive\"",
    );
    let edits = [Cut("Value(52)", "\r\n")];
    both_ways(
        "md810dp.toml",
        GSD,
        &edits,
        Kind::Diagnosis,
        (Compatible, Compatible),
        ("removed", "added"),
    );
    let edits = [F("Unit_Diag_Area = 8-15", "Unit_Diag_Area = 8-14")];
    one(
        &changes("md810dp.toml", GSD, &edits),
        Breaking,
        Kind::Diagnosis,
        "bits 8-15 → 8-14",
    );
}

/// A PROFIenergy energy saving mode's ID is the number the controller asks
/// for, not a name in the file: SEW's MOVI-C with its mode 2 renumbered 3
/// (in each of its three access points' own submodules, line 75 the first)
/// is one breaking change each.
#[test]
fn an_energy_saving_modes_number_breaks() {
    let name = "GSDML-V2.34-SEW-MOVI-C-Decentralized-Electronics-20200731-071447.xml";
    let text = String::from_utf8(support::corpus_file(&format!("gsdml/{name}"))).unwrap();
    let (from, to) = (
        r#"EnergySavingModeItem ID="2""#,
        r#"EnergySavingModeItem ID="3""#,
    );
    assert_eq!(text.matches(from).count(), 3);
    let found = diff(text.as_bytes(), text.replace(from, to).as_bytes());
    assert_eq!(found.len(), 3, "{found:#?}");
    for change in &found {
        assert_eq!(
            (change.class, change.kind, change.change.as_str()),
            (Breaking, Kind::Feature, r#""2 255" → "3 255""#)
        );
        assert!(change.subject.ends_with("EnergySavingModeItem@ID"));
    }
    assert_eq!(found[0].old.as_ref().map(|p| p.line), Some(75));
}

/// What no shipped description builds, in a real GSD (profirust's mock
/// slave): choice texts and choices, bit areas, slots.
#[test]
fn gsd_choices_bits_and_slots_of_a_real_file() {
    let text = String::from_utf8(support::corpus_file("gsd/Rahix__mock.gsd")).unwrap();
    let pair = |from: &str, to: &str| {
        assert_eq!(text.matches(from).count(), 1, "`{from}`");
        diff(text.as_bytes(), text.replacen(from, to, 1).as_bytes())
    };
    // One choice text, of a parameter placed in the slave's part and in a
    // module's: one change, at two places.
    let change = one(
        &pair("Text(1)=\"Value 2\"", "Text(1)=\"Second value\""),
        Cosmetic,
        Kind::Text,
        "\"Value 2\" → \"Second value\"",
    );
    assert_eq!(change.more, 1);
    assert_eq!(
        change.subject,
        "choice 1 of parameter \"Peripheral Setting 2\" at byte 5 bits 1-2 of User_Prm_Data"
    );
    let found = pair("BitArea(1-2) 0 0-3", "BitArea(1-2) 0 0-2");
    assert_eq!(found.len(), 2, "{found:#?}");
    for change in &found {
        assert_eq!(
            (change.class, change.kind, change.change.as_str()),
            (Breaking, Kind::Parameter, "allowed 0..3 → 0..2")
        );
    }
    one(
        &pair(
            "Slot(1) = \"Data Interface\" 1 2-3",
            "Slot(1) = \"Data Interface\" 1 2",
        ),
        Breaking,
        Kind::Module,
        "allowed modules 2-3 → 2",
    );
    one(
        &pair(
            "Slot(1) = \"Data Interface\" 1 2-3",
            "Slot(1) = \"Data Interface\" 1 1-3",
        ),
        Compatible,
        Kind::Module,
        "allowed modules 2-3 → 1-3",
    );
    one(
        &pair(
            "Slot(1) = \"Data Interface\" 1 2-3",
            "Slot(1) = \"Data Interface\" 2 2-3",
        ),
        Compatible,
        Kind::Module,
        "default module 1 → 2",
    );
    one(
        &pair(
            "Unit_Diag_Bit(17) = \"Frobincated\"",
            "Unit_Diag_Bit(17) = \"Frobnicated\"",
        ),
        Cosmetic,
        Kind::Text,
        "\"Frobincated\" → \"Frobnicated\"",
    );
    one(
        &pair(
            "Unit_Diag_Bit(17) = \"Frobincated\"",
            "Unit_Diag_Bit(500) = \"Frobincated\"",
        ),
        Compatible,
        Kind::Diagnosis,
        "moved from bit 17",
    );
}

// GSDML: identity and file.

/// The IDs are also in the device symbol's file name, which gsdc derives
/// from them: the one fact of the description is two of the file.
#[test]
fn gsdml_vendor_and_device_ids_break() {
    for (from, to, says) in [
        (
            "vendor_id = { value = 0x0A10",
            "vendor_id = { value = 0x0A12",
            "0x0A10 → 0x0A12",
        ),
        (
            "device_id = { value = 0x0810",
            "device_id = { value = 0x0811",
            "0x0810 → 0x0811",
        ),
    ] {
        let found = changes("mv810-pnet02.toml", GSDML, &[D(from, to)]);
        one(&found[..1], Breaking, Kind::Identity, says);
        // The draft notice names the placeholders: the device's InfoText
        // changes with them.
        let notice = one(&found[1..2], Cosmetic, Kind::Text, "are placeholders");
        assert_eq!(notice.subject, "device DeviceIdentity/InfoText");
        let symbol = one(&found[2..], Cosmetic, Kind::Text, "GSDML-0A1");
        assert!(
            symbol.subject.ends_with("GraphicItemTarget"),
            "{}",
            symbol.subject
        );
    }
}

#[test]
fn gsdml_date_is_the_file_name() {
    let edits = [D("date = 2023-08-30", "date = 2023-09-01")];
    let (old, new) = files("mv810-pnet02.toml", GSDML, &edits);
    let old = device::read(&old, Some("GSDML-V2.32-MEGMEET-MV800-20230830.xml")).unwrap();
    let new = device::read(&new, Some("GSDML-V2.32-MEGMEET-MV800-20230901.xml")).unwrap();
    let found = gsdc::diff::compare(&old, &new).unwrap();
    one(
        &found,
        Cosmetic,
        Kind::File,
        "20230830.xml → GSDML-V2.32-MEGMEET-MV800-20230901.xml",
    );
}

#[test]
fn gsdml_dns_name_is_for_new_projects() {
    let edits = [D("dns_name = \"mv810-pnet02\"", "dns_name = \"mv810\"")];
    one(
        &changes("mv810-pnet02.toml", GSDML, &edits),
        Compatible,
        Kind::Identity,
        "\"mv810-pnet02\" → \"mv810\"",
    );
}

#[test]
fn gsdml_order_number_is_cosmetic() {
    let edits = [D(
        "software_release = \"V1.00\"\n",
        "software_release = \"V1.00\"\norder_number = \"MV810-PNET02\"\n",
    )];
    one(
        &changes("mv810-pnet02.toml", GSDML, &edits),
        Cosmetic,
        Kind::Identity,
        "\"MV810-PNET02\" added",
    );
}

// GSDML: timing and features.

#[test]
fn gsdml_min_device_interval_raised_breaks() {
    let edits = [D("min_device_interval = 32", "min_device_interval = 64")];
    both_ways(
        "mv810-pnet02.toml",
        GSDML,
        &edits,
        Kind::Timing,
        (Breaking, Compatible),
        ("\"32\" → \"64\"", "\"64\" → \"32\""),
    );
}

#[test]
fn gsdml_send_clocks_narrowed_break() {
    let edits = [D(
        "min_device_interval = 32\n",
        "min_device_interval = 32\nsend_clock = [32, 64]\n",
    )];
    both_ways(
        "mv810-pnet02.toml",
        GSDML,
        &edits,
        Kind::Timing,
        (Breaking, Compatible),
        ("\"32 64 128\" → \"32 64\"", "\"32 64\" → \"32 64 128\""),
    );
}

#[test]
fn gsdml_conformance_class_lowered_breaks() {
    let edits = [D(
        "min_device_interval = 32\n",
        "min_device_interval = 32\nconformance_class = \"A\"\n",
    )];
    both_ways(
        "mv810-pnet02.toml",
        GSDML,
        &edits,
        Kind::Feature,
        (Breaking, Compatible),
        ("\"B\" → \"A\"", "\"A\" → \"B\""),
    );
}

#[test]
fn gsdml_attribute_without_a_rule_is_breaking_and_not_judged() {
    let edits = [F(
        "ResetToFactoryModes=\"2\"",
        "ResetToFactoryModes=\"2\" Frobnicate=\"1\"",
    )];
    let found = changes("mv810-pnet02.toml", GSDML, &edits);
    assert_eq!(found.len(), 1, "{found:#?}");
    assert_eq!((found[0].class, found[0].judged), (Breaking, false));
    assert!(
        found[0].subject.ends_with("Frobnicate"),
        "{}",
        found[0].subject
    );
}

// GSDML: modules, submodules, IO data.

#[test]
fn gsdml_module_removed_breaks_added_does_not() {
    let edits = [D(
        "pzd_lengths = [1, 2, 3, 4, 5, 6,",
        "pzd_lengths = [1, 2, 3, 4, 6,",
    )];
    both_ways(
        "mv810-pnet02.toml",
        GSDML,
        &edits,
        Kind::Module,
        (Breaking, Compatible),
        ("removed", "added"),
    );
}

#[test]
fn gsdml_module_ident_changed_breaks() {
    let edits = [F(
        "ModuleIdentNumber=\"0x00000205\"",
        "ModuleIdentNumber=\"0x00000255\"",
    )];
    let change = one(
        &changes("mv810-pnet02.toml", GSDML, &edits),
        Breaking,
        Kind::Module,
        "ident number 0x00000205 → 0x00000255",
    );
    assert!(change
        .new
        .unwrap()
        .path
        .unwrap()
        .ends_with("ModuleItem[IDM_PKW_5]"));
}

#[test]
fn gsdml_module_no_longer_offered_breaks() {
    let edits = [Cut("<ModuleItemRef ModuleItemTarget=\"IDM_PKW_5\"", "/>")];
    both_ways(
        "mv810-pnet02.toml",
        GSDML,
        &edits,
        Kind::Module,
        (Breaking, Compatible),
        ("no longer offered", "now offered"),
    );
    let edits = [F(
        "ModuleItemTarget=\"IDM_PKW_5\" AllowedInSlots=\"1\"",
        "ModuleItemTarget=\"IDM_PKW_5\" AllowedInSlots=\"1..2\"",
    )];
    both_ways(
        "mv810-pnet02.toml",
        GSDML,
        &edits,
        Kind::Module,
        (Compatible, Breaking),
        ("\"1\" → \"1..2\"", "\"1..2\" → \"1\""),
    );
}

#[test]
fn gsdml_submodule_ident_and_api_break() {
    let edits = [F(
        "SubmoduleIdentNumber=\"0x00000205\"",
        "SubmoduleIdentNumber=\"0x00000206\"",
    )];
    one(
        &changes("mv810-pnet02.toml", GSDML, &edits),
        Breaking,
        Kind::Submodule,
        "ident number 0x00000205 → 0x00000206",
    );
    let edits = [F(
        "SubmoduleIdentNumber=\"0x00000205\" API=\"0\"",
        "SubmoduleIdentNumber=\"0x00000205\" API=\"14848\"",
    )];
    one(
        &changes("mv810-pnet02.toml", GSDML, &edits),
        Breaking,
        Kind::Module,
        "\"0\" → \"14848\"",
    );
}

#[test]
fn gsdml_port_removed_breaks() {
    let edits = [Cut(
        "<PortSubmoduleItem ID=\"IDS_PORT_2\"",
        "</PortSubmoduleItem>",
    )];
    both_ways(
        "mv810-pnet02.toml",
        GSDML,
        &edits,
        Kind::Submodule,
        (Breaking, Compatible),
        ("removed", "added"),
    );
}

#[test]
fn gsdml_io_length_and_types_break_texts_do_not() {
    let marker = "<DataItem DataType=\"Unsigned16\" TextId=\"IDT_PKW_STATION\"/>";
    let edits = [F(marker, "<DataItem DataType=\"Unsigned16\" TextId=\"IDT_PKW_STATION\"/><DataItem DataType=\"Unsigned8\" TextId=\"IDT_PKW_STATION\"/>")];
    one(
        &changes("mv810-pnet02.toml", GSDML, &edits),
        Breaking,
        Kind::IoData,
        "10 bytes",
    );
    let edits = [F(
        marker,
        "<DataItem DataType=\"Integer16\" TextId=\"IDT_PKW_STATION\"/>",
    )];
    let change = one(
        &changes("mv810-pnet02.toml", GSDML, &edits),
        Breaking,
        Kind::IoData,
        "Integer16",
    );
    assert!(change.why.contains("types"), "{}", change.why);
    let edits = [F(
        "Consistency=\"All items consistency\"",
        "Consistency=\"Item consistency\"",
    )];
    one(
        &changes("mv810-pnet02.toml", GSDML, &edits),
        Breaking,
        Kind::IoData,
        "\"All items consistency\" → \"Item consistency\"",
    );
}

/// A text used by every module is one change, at every place.
#[test]
fn gsdml_a_shared_text_is_one_change() {
    let edits = [D(
        "{ bit = 0, name = { en = \"Forward running\", zh = \"正转运行\" } }",
        "{ bit = 0, name = { en = \"Run forward\", zh = \"正转运行\" } }",
    )];
    let change = one(
        &changes("mv810-pnet02.toml", GSDML, &edits),
        Cosmetic,
        Kind::Text,
        "\"Forward running\" → \"Run forward\"",
    );
    assert_eq!(change.more, 12, "13 modules carry the control word");
    let edits = [D(
        "{ bit = 0, name = { en = \"Forward running\", zh = \"正转运行\" } }",
        "{ bit = 0, name = { en = \"Forward running\", zh = \"正转\" } }",
    )];
    one(
        &changes("mv810-pnet02.toml", GSDML, &edits),
        Cosmetic,
        Kind::Text,
        "(zh) \"正转运行\" → \"正转\"",
    );
}

#[test]
fn gsdml_language_removed_is_one_change() {
    let edits = [Cut("<Language xml:lang=\"zh\">", "</Language>")];
    both_ways(
        "mv810-pnet02.toml",
        GSDML,
        &edits,
        Kind::Language,
        (Compatible, Compatible),
        ("removed", "added"),
    );
}

// GSDML: records and their parameters.

#[test]
fn gsdml_record_index_changed_breaks_in_each_module() {
    let (old, new) = files(
        "md810dp.toml",
        GSDML,
        &[D(
            "dpv1_index = { index = 258,",
            "dpv1_index = { index = 259,",
        )],
    );
    let found = diff(&old, &new);
    assert!(!found.is_empty());
    for change in &found {
        assert_eq!(
            (change.class, change.kind, change.change.as_str()),
            (Breaking, Kind::Record, "index 258 → 259"),
            "{change:#?}"
        );
    }
}

#[test]
fn gsdml_record_removed_breaks_added_does_not() {
    let edits = [Cut(
        "<ParameterRecordDataItem Index=\"4\" Length=\"2\">",
        "</ParameterRecordDataItem>",
    )];
    both_ways(
        MV810_RECORDS,
        GSDML,
        &edits,
        Kind::Record,
        (Breaking, Compatible),
        ("removed", "added"),
    );
}

#[test]
fn gsdml_record_length_changed_breaks() {
    let edits = [F(
        "<ParameterRecordDataItem Index=\"4\" Length=\"2\">",
        "<ParameterRecordDataItem Index=\"4\" Length=\"4\">",
    )];
    one(
        &changes(MV810_RECORDS, GSDML, &edits),
        Breaking,
        Kind::Parameter,
        "2 → 4 bytes",
    );
}

#[test]
fn gsdml_record_default_changeable_or_fixed() {
    let edits = [F(
        "DefaultValue=\"0\" AllowedValues=\"0..14\"",
        "DefaultValue=\"3\" AllowedValues=\"0..14\"",
    )];
    one(
        &changes(MV810_RECORDS, GSDML, &edits),
        Compatible,
        Kind::Parameter,
        "default 0 → 3",
    );
    // P43.01 is fixed per module: a new fixed value is one the device acts on.
    let edits = [F("DefaultValue=\"1\" AllowedValues=\"0..1\" ValueItemTarget=\"IDV_SETTINGS_1\" Changeable=\"false\"", "DefaultValue=\"0\" AllowedValues=\"0..1\" ValueItemTarget=\"IDV_SETTINGS_1\" Changeable=\"false\"")];
    one(
        &changes(MV810_RECORDS, GSDML, &edits),
        Breaking,
        Kind::Parameter,
        "fixed value 1 → 0",
    );
    let edits = [F(
        "ValueItemTarget=\"IDV_PZD_OUT\" Changeable=\"true\"",
        "ValueItemTarget=\"IDV_PZD_OUT\" Changeable=\"false\"",
    )];
    both_ways(
        MV810_RECORDS,
        GSDML,
        &edits,
        Kind::Parameter,
        (Breaking, Compatible),
        ("fixed at 0", "changeable"),
    );
}

#[test]
fn gsdml_record_range_narrowed_breaks_widened_does_not() {
    let edits = [F("AllowedValues=\"0..14\"", "AllowedValues=\"0..10\"")];
    both_ways(
        MV810_RECORDS,
        GSDML,
        &edits,
        Kind::Parameter,
        (Breaking, Compatible),
        ("allowed 0..14 → 0..10", "allowed 0..10 → 0..14"),
    );
}

#[test]
fn gsdml_choice_texts_are_cosmetic() {
    let edits = [D("{ value = 0, text = { en = \"Disabled\", zh = \"无效\" } },\n    { value = 1, text = { en = \"Frequency reference (0.00 to P02.10)\"", "{ value = 0, text = { en = \"Not used\", zh = \"无效\" } },\n    { value = 1, text = { en = \"Frequency reference (0.00 to P02.10)\"")];
    let change = one(
        &changes(MV810_RECORDS, GSDML, &edits),
        Cosmetic,
        Kind::Text,
        "\"Disabled\" → \"Not used\"",
    );
    assert!(
        change.subject.starts_with("choice 0 of parameter"),
        "{}",
        change.subject
    );
}

#[test]
fn gsdml_parameter_moved_in_a_record_breaks() {
    let edits = [F("<Ref DataType=\"Unsigned16\" ByteOffset=\"2\" DefaultValue=\"0\" AllowedValues=\"0..14\" ValueItemTarget=\"IDV_PZD_OUT\" Changeable=\"true\" Visible=\"true\" TextId=\"IDT_PZD_OUT_3\"/>", "<Ref DataType=\"Unsigned16\" ByteOffset=\"4\" DefaultValue=\"0\" AllowedValues=\"0..14\" ValueItemTarget=\"IDV_PZD_OUT\" Changeable=\"true\" Visible=\"true\" TextId=\"IDT_PZD_OUT_3\"/>")];
    let found = changes(MV810_RECORDS, GSDML, &edits);
    // PZD3 moves past the record's 4 bytes: moved, and past the end.
    assert!(found.iter().all(|c| c.class == Breaking), "{found:#?}");
    assert!(
        found
            .iter()
            .any(|c| c.change == "moved from byte 2 to byte 4"),
        "{found:#?}"
    );
}

/// The places a change gives are lines of the files and GSDML paths.
#[test]
fn places_are_lines_and_element_paths() {
    let edits = [F(
        "DefaultValue=\"0\" AllowedValues=\"0..14\"",
        "DefaultValue=\"3\" AllowedValues=\"0..14\"",
    )];
    let (old, new) = files(MV810_RECORDS, GSDML, &edits);
    let change = one(&diff(&old, &new), Compatible, Kind::Parameter, "default");
    let old_place = change.old.unwrap();
    let line = String::from_utf8(old)
        .unwrap()
        .lines()
        .nth(old_place.line as usize - 1)
        .unwrap()
        .to_string();
    assert!(
        line.contains("DefaultValue=\"0\" AllowedValues=\"0..14\""),
        "{line}"
    );
    assert_eq!(
        old_place.path.as_deref(),
        Some("ApplicationProcess/ModuleList/ModuleItem[IDM_PKW_2]/VirtualSubmoduleList/VirtualSubmoduleItem[IDS_PKW_2]/RecordDataList/ParameterRecordDataItem[Index=1]/Ref[ByteOffset=0]")
    );
}

/// A module's only submodule written without FixedInSubslots is in
/// subslot 1: writing `FixedInSubslots="1"` changes nothing, another
/// subslot breaks old projects.
#[test]
fn gsdml_a_submodule_fixed_in_subslot_1_is_where_it_was() {
    let at = "<VirtualSubmoduleItem ID=\"IDS_PKW_1\" SubmoduleIdentNumber=\"0x00000201\" API=\"0\"";
    let stated = [F(at, "<VirtualSubmoduleItem ID=\"IDS_PKW_1\" SubmoduleIdentNumber=\"0x00000201\" API=\"0\" FixedInSubslots=\"1\"")];
    assert_eq!(changes("mv810-pnet02.toml", GSDML, &stated), vec![]);
    let moved = [F(at, "<VirtualSubmoduleItem ID=\"IDS_PKW_1\" SubmoduleIdentNumber=\"0x00000201\" API=\"0\" FixedInSubslots=\"2\"")];
    one(
        &changes("mv810-pnet02.toml", GSDML, &moved),
        Breaking,
        Kind::Module,
        "\"1\" → \"2\"",
    );
}

/// A port's MAUTypes attribute naming the MAU types of its MAUTypeList is
/// the list's older form, the same fact: no change. Naming another type
/// is one.
#[test]
fn gsdml_mau_types_repeating_the_mau_type_list_change_nothing() {
    let at = "TextId=\"IDT_PORT_1\">";
    let repeated = [F(at, "TextId=\"IDT_PORT_1\" MAUTypes=\"16\">")];
    assert_eq!(changes("mv810-pnet02.toml", GSDML, &repeated), vec![]);
    let other = [F(at, "TextId=\"IDT_PORT_1\" MAUTypes=\"30\">")];
    one(
        &changes("mv810-pnet02.toml", GSDML, &other),
        Compatible,
        Kind::Feature,
        "\"30\" added",
    );
}
