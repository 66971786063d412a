//! Every count a description sets, at its limit and one past it: the limit
//! loads and compiles, one past is a description error with its code and
//! place, never a wrapped counter, a bug report (E900) or a layout that does
//! not compile.

use std::fmt::Write as _;

/// The device and the telegram without its PZD words.
const CARD: &str = r#"[device]
vendor = "Acme"
family = "X1"
model = "X1"
revision = "V1"
hardware_release = "V1"
software_release = "V1"
name = "Card"

[telegram]
pkw = "none"
"#;

/// A PROFIBUS and PROFINET card with `pzd_words` PZD words, `ports` ports,
/// `settings` settings and the extra TOML `more` (tables after [profinet]).
fn description(pzd_words: u32, ports: u32, settings: usize, more: &str) -> String {
    let mut text = format!("{CARD}pzd_words = {pzd_words}\n");
    for n in 0..settings {
        let _ = write!(
            text,
            "\n[[settings]]\nname = \"Setting {n}\"\nparameter = {n}\ndefault = 0\nrange = [0, 1]\n"
        );
    }
    let _ = write!(
        text,
        r#"
[profinet]
vendor_id = {{ value = 0x1234 }}
device_id = {{ value = 0x0001 }}
date = 2026-01-31
dns_name = "x1"
ports = {ports}
min_device_interval = 32
pzd_lengths = [1]
module_pkw = "without"
send_clock = [32]
conformance_class = "B"
netload_class = "I"
writeable_im_records = [1, 2, 3]
{more}"#
    );
    text
}

/// What loading and compiling `text` gives: `Ok` when both succeed, else
/// the first error's code and the text it points at.
fn outcome(text: &str) -> Result<(), (&'static str, String)> {
    let (ir, diagnostics) = gsdc::load("limits.toml", text);
    if let Some(error) = diagnostics.errors().next() {
        let span = error
            .span
            .clone()
            .expect("every description error has a place");
        return Err((error.code, text[span].to_string()));
    }
    let artifacts = gsdc::compile(&ir.unwrap()).map_err(|d| {
        let first = d.errors().next().unwrap();
        (first.code, first.message.clone())
    })?;
    assert!(!artifacts.is_empty());
    Ok(())
}

/// The GSDML `text` gives.
fn gsdml(text: &str) -> String {
    let ir = gsdc::load("limits.toml", text).0.unwrap();
    let gsdml = gsdc::compile(&ir)
        .unwrap()
        .into_iter()
        .find(|a| a.kind == gsdc::ArtifactKind::Gsdml)
        .unwrap();
    String::from_utf8(gsdml.contents).unwrap()
}

fn code(result: Result<(), (&'static str, String)>) -> &'static str {
    result.expect_err("one past the limit is an error").0
}

#[test]
fn pzd_words_16_and_17() {
    assert_eq!(outcome(&description(16, 2, 0, "")), Ok(()));
    assert_eq!(code(outcome(&description(17, 2, 0, ""))), "E101");
}

#[test]
fn ports_16_and_17() {
    assert_eq!(outcome(&description(2, 16, 0, "")), Ok(()));
    assert_eq!(
        outcome(&description(2, 17, 0, "")),
        Err(("E101", "17".to_string()))
    );
}

/// 255 settings take record entries 1..255 and text ids of their own; the
/// 256th would wrap an 8-bit counter.
#[test]
fn settings_255_and_256() {
    assert_eq!(outcome(&description(2, 2, 255, "")), Ok(()));
    // One record of 255 Unsigned16 entries.
    let settings = gsdml(&description(2, 2, 255, ""));
    let refs = settings
        .lines()
        .filter(|l| l.contains("<Ref ") && l.contains("IDT_SETTINGS_"));
    assert_eq!(refs.count(), 255);
    assert!(settings.contains("Length=\"510\""));
    let (code, at) = outcome(&description(2, 2, 256, "")).unwrap_err();
    assert_eq!(code, "E134");
    assert!(at.contains("Setting 255"), "{at}");
}

/// DPV1 indexes 0..=255 are 256 entries: on PROFINET a record of 512
/// bytes; the count does not wrap to 0.
#[test]
fn dpv1_indexes_up_to_255_and_256() {
    let indexes = |last: u32| {
        format!(
            "\n[mappings.dpv1_index]\nname = \"Index{{n}}\"\nfirst = 0\nlast = {last}\ndefault = 0\n"
        )
    };
    // The custom indexes are records 0..=last of each module: the record
    // of their mappings has an index past them.
    let records = "\n[profinet.records]\ndpv1_index = 256\n";
    let with = |last| {
        description(2, 2, 0, records).replacen(
            "\n[profinet]",
            &format!("{}\n[profinet]", indexes(last)),
            1,
        )
    };
    assert_eq!(outcome(&with(255)), Ok(()));
    assert!(gsdml(&with(255)).contains("Length=\"512\""));
    // An index is a byte: 256 is not one.
    assert_eq!(code(outcome(&with(256))), "E003");
}

/// A PROFIBUS card with two PZD words and the extra TOML `more` (tables
/// after [profibus.baud_rates]).
fn profibus_card(more: &str) -> String {
    format!(
        r#"{CARD}pzd_words = 2

[profibus]
file_name = "X1.GSD"
ident_number = {{ value = 0x1234 }}
ppo_types = ["PPO3"]
min_slave_interval = 1
slave_family = "1"

[profibus.baud_rates]
"12M" = 800
{more}"#
    )
}

/// On PROFIBUS the same 256 indexes are 512 bytes of User_Prm_Data: E116,
/// not a wrapped length.
#[test]
fn user_prm_data_237_and_239_bytes() {
    let gsd = |entries: u32| {
        profibus_card(&format!(
            r#"
[profibus.dpv1]
c1_read_write = true
status_bytes = [0, 0, 0]

[mappings.dpv1_index]
name = "Index{{n}}"
first = 0
last = {last}
default = 0
"#,
            last = entries - 1
        ))
    };
    // 3 DPV1 status bytes and 117 Unsigned16 entries: 237 bytes.
    assert_eq!(outcome(&gsd(117)), Ok(()));
    assert_eq!(code(outcome(&gsd(118))), "E116");
    assert_eq!(code(outcome(&gsd(256))), "E116");
}

/// The device-related block's header byte holds its length in 6 bits.
#[test]
fn a_diagnosis_block_of_63_and_64_bytes() {
    let gsd = |length: u32| {
        profibus_card(&format!(
            r#"
[profibus.diagnosis]
length = {length}

[[profibus.diagnosis.areas]]
bit = [0, 7]
values = [{{ value = 1, text = "One" }}]
"#
        ))
    };
    assert_eq!(outcome(&gsd(63)), Ok(()));
    assert_eq!(outcome(&gsd(64)), Err(("E101", "64".to_string())));
}
