//! Properties over generated descriptions that keep to the rules: the
//! loader accepts them, and they compile to files that pass gsdc's own
//! rules (compile refuses anything else with E900), the PI schema and
//! gsd-parser; compiling twice gives identical bytes. (The compile fuzz
//! target covers the descriptions that break rules.)

use crate::support::xsd;
use proptest::prelude::*;
use std::fmt::Write as _;
use std::path::Path;

/// A GSD-safe text: printable ASCII without `"`, 1..=32 characters.
fn gsd_text() -> impl Strategy<Value = String> {
    "[A-Za-z0-9 ._+/()-]{1,32}".prop_filter("not blank", |s| !s.trim().is_empty())
}

/// A TOML basic string holding `s` (the texts above need no escaping).
fn quoted(s: &str) -> String {
    format!("\"{s}\"")
}

/// A slave family: the main family and sub-families of GSD names, at most
/// 50 characters in all.
fn slave_family() -> impl Strategy<Value = String> {
    (0u8..=12, prop::collection::vec("[A-Za-z0-9]{1,32}", 0..4))
        .prop_map(|(main, subs)| {
            std::iter::once(main.to_string())
                .chain(subs)
                .collect::<Vec<_>>()
                .join("@")
        })
        .prop_filter("fits a GSD line", |f| f.len() <= 50)
}

prop_compose! {
    fn description()(
        vendor in gsd_text(),
        model in gsd_text(),
        info in "[A-Za-z0-9 ._+/()-]{1,256}".prop_filter("not blank", |s| !s.trim().is_empty()),
        slave_family in slave_family(),
        mapping_name in "[A-Za-z0-9 ._+()-]{1,28}",
        family in "[A-Za-z][A-Za-z0-9]{0,11}",
        pkw in prop::bool::ANY,
        pzd_words in 2u8..=16,
        ppo in prop::collection::btree_set(1u8..=5, 1..=5),
        ppo5_words in 1u8..=16,
        out_last in 1u8..=16,
        default in 0u16..=1000,
        dpv1 in prop::bool::ANY,
        diagnosis in prop::option::of((2u8..=10, prop::collection::btree_map(0i64..=255, gsd_text(), 1..8))),
        lengths in prop::collection::btree_set(1u8..=16, 1..=6),
        tsdr in 11u16..=1000,
    ) -> String {
        let mut toml = String::new();
        let _ = writeln!(toml, "[device]\nvendor = {}\nfamily = {}\nmodel = {}", quoted(&vendor), quoted(&family), quoted(&model));
        toml.push_str("revision = \"V1\"\nhardware_release = \"V1\"\nsoftware_release = \"V1\"\nname = { en = \"Card\", zh = \"卡\" }\n");
        let _ = writeln!(toml, "info = {}\n", quoted(&info));
        let _ = writeln!(toml, "[telegram]\npkw = {}\npzd_words = {pzd_words}\n", if pkw { "\"pke-ind-pwe\"" } else { "\"none\"" });
        let _ = writeln!(toml, "[mappings.pzd_out]\nname = \"{mapping_name}{{n}}\"\nfirst = 1\nlast = {}\ndefault = {default}\nrange = [0, 65535]\n", out_last.min(pzd_words));
        // Keep the PPO types that fit the telegram (PPO3 always does).
        let ppo5_words = ppo5_words.min(pzd_words);
        let fits = |p: &&u8| match **p {
            1 | 3 => true,
            2 | 4 => pzd_words >= 6,
            _ => true,
        } && (pkw || matches!(**p, 3 | 4));
        let mut types: Vec<String> = ppo.iter().filter(fits).map(|p| format!("\"PPO{p}\"")).collect();
        if types.is_empty() {
            types.push("\"PPO3\"".into());
        }
        // PPO5's words only with PPO5 (E002 otherwise).
        let ppo5 = if types.iter().any(|t| t == "\"PPO5\"") { format!("ppo5_pzd_words = {ppo5_words}\n") } else { String::new() };
        let _ = writeln!(toml, "[profibus]\nfile_name = \"CARD.GSD\"\nident_number = {{ value = 0x1234 }}\nppo_types = [{}]\n{ppo5}min_slave_interval = 1\nslave_family = {}\n", types.join(", "), quoted(&slave_family));
        let _ = writeln!(toml, "[profibus.baud_rates]\n\"1.5M\" = {tsdr}\n\"12M\" = 800\n");
        if dpv1 {
            toml.push_str("[profibus.dpv1]\nc1_read_write = true\n\n");
        }
        if let Some((length, values)) = diagnosis {
            let _ = writeln!(toml, "[profibus.diagnosis]\nlength = {length}\n\n[[profibus.diagnosis.areas]]\nbit = [0, 7]\nvalues = [");
            for (value, text) in values {
                let _ = writeln!(toml, "  {{ value = {value}, text = {} }},", quoted(&text));
            }
            toml.push_str("]\n\n");
        }
        let lengths: std::collections::BTreeSet<u8> = lengths.iter().map(|l| l.min(&pzd_words)).copied().collect();
        let lengths: Vec<String> = lengths.iter().map(u8::to_string).collect();
        let _ = writeln!(toml, "[profinet]\nvendor_id = {{ value = 0x0A10 }}\ndevice_id = {{ value = 0x0001 }}\ndate = 2026-01-31\nfile_vendor = \"Vendor\"\ndns_name = \"card\"\nports = 2\nmin_device_interval = 32\npzd_lengths = [{}]\nmodule_pkw = {}", lengths.join(", "), if pkw { "\"both\"" } else { "\"without\"" });
        toml
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn accepted_descriptions_compile_to_files_every_checker_accepts(text in description()) {
        // The generator keeps to the rules, so the loader must accept it.
        let (ir, diagnostics) = gsdc::load("card.toml", &text);
        let Some(ir) = ir else {
            return Err(TestCaseError::fail(format!("rejected: {diagnostics:?}\n{text}")));
        };
        let artifacts = gsdc::compile(&ir).map_err(|d| TestCaseError::fail(format!("{d:?}\n{text}")))?;
        prop_assert_eq!(&artifacts, &gsdc::compile(&ir).unwrap(), "compiling twice differs");
        for artifact in &artifacts {
            let contents = String::from_utf8(artifact.contents.clone()).unwrap();
            if artifact.file_name.ends_with(".GSD") {
                let parsed = gsd_parser::parser::parse(Path::new(&artifact.file_name), &contents);
                prop_assert!(parsed.is_ok(), "gsd-parser rejects it: {:?}\n{}", parsed.err(), text);
            } else if artifact.file_name.ends_with(".xml") {
                prop_assert_eq!(xsd::validate(&contents), Ok(()), "{}", text);
            }
        }
    }
}

/// Every text and name of a GSD at its longest, the long ones without a
/// space to break at: the GSD keeps its lines within 80 columns only where
/// GSD lets a line go on, and gsd-parser reads every value back whole.
#[test]
fn every_field_at_its_maximum_length_gives_a_gsd_gsd_parser_reads() {
    let name32 = "N".repeat(32);
    let slave_family = format!("1@{}@{}", "S".repeat(32), "T".repeat(15));
    assert_eq!(slave_family.len(), 50);
    let info = "I".repeat(256);
    let text = format!(
        r#"[device]
vendor = "{name32}"
family = "F"
model = "{name32}"
revision = "{name32}"
hardware_release = "{name32}"
software_release = "{name32}"
order_number = "{name32}"
name = "Card"
info = "{info}"

[telegram]
pkw = "pke-ind-pwe"
pzd_words = 16

[mappings.pzd_out]
name = "{m}{{n}}"
first = 1
last = 16
default = 0
choices = [{{ value = 0, text = "{name32}" }}, {{ value = 1, text = "{name32}" }}]

[profibus]
file_name = "ABCDEFGH.GSD"
ident_number = {{ value = 0xFFFF }}
implementation_type = "{name32}"
ppo_types = ["PPO1", "PPO2", "PPO3", "PPO4", "PPO5"]
ppo5_pzd_words = 16
min_slave_interval = 1
slave_family = "{slave_family}"

[profibus.baud_rates]
"12M" = 800

[profibus.diagnosis]
length = 63

[[profibus.diagnosis.areas]]
bit = [0, 15]
values = [{{ value = 65535, text = "{name32}" }}]
"#,
        m = "M".repeat(30),
    );
    let (ir, diagnostics) = gsdc::load("card.toml", &text);
    let ir = ir.unwrap_or_else(|| panic!("{diagnostics:?}"));
    let gsd = gsdc::compile(&ir)
        .unwrap()
        .into_iter()
        .find(|a| a.file_name == "ABCDEFGH.GSD")
        .unwrap();
    let gsd = String::from_utf8(gsd.contents).unwrap();
    assert!(gsd.lines().all(|l| l.len() <= 80), "{gsd}");
    let parsed = gsd_parser::parser::parse(Path::new("ABCDEFGH.GSD"), &gsd).unwrap();
    assert_eq!(
        (parsed.vendor.as_str(), parsed.implementation_type.as_str()),
        (name32.as_str(), name32.as_str())
    );
    assert_eq!(parsed.max_diag_data_length, 6 + 63);
    // gsd-parser keeps no Info_Text: read it back as a reader joins lines.
    let joined = gsd.replace("\\\r\n", "");
    assert!(joined.contains(&format!("= \"{info}\"\r\n")), "{gsd}");
    assert!(gsd.contains(&format!("Slave_Family                = {slave_family}\r\n")));
}
