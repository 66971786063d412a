//! The GSD files gsdc writes for the shipped descriptions: snapshots
//! reviewed against the manuals, an independent parser's reading compared
//! with the IR, and determinism.

#[path = "common/descriptions.rs"]
mod descriptions;
use descriptions::load;

use gsd_parser::{PrmBuilder, PrmValueConstraint, UserPrmDataType};
use gsdc::ir::profibus::Profibus;
use gsdc::ir::{Allowed, Ir};
use std::path::Path;

const DESCRIPTIONS: [&str; 2] = ["md810dp.toml", "9kdp1.toml"];

fn gsd_of(ir: &Ir) -> (String, &Profibus) {
    let artifacts = gsdc::compile(ir).unwrap();
    let profibus = ir.profibus.as_ref().unwrap();
    let gsd = artifacts
        .iter()
        .find(|a| a.file_name == profibus.file_name)
        .expect("a GSD artifact");
    (String::from_utf8(gsd.contents.clone()).unwrap(), profibus)
}

#[test]
fn md810dp_gsd_snapshot() {
    let (gsd, _) = gsd_of(&load("md810dp.toml"));
    insta::assert_snapshot!("MD810DP.GSD", gsd.replace("\r\n", "\n"));
}

#[test]
fn powtran_9kdp1_gsd_snapshot() {
    let (gsd, _) = gsd_of(&load("9kdp1.toml"));
    insta::assert_snapshot!("9KDP1.GSD", gsd.replace("\r\n", "\n"));
}

#[test]
fn gsd_files_are_ascii_crlf_and_at_most_80_columns() {
    for name in DESCRIPTIONS {
        let (gsd, _) = gsd_of(&load(name));
        assert!(gsd.is_ascii(), "{name}");
        assert!(gsd.ends_with("\r\n"), "{name}");
        for line in gsd.split_terminator("\r\n") {
            assert!(!line.contains('\n'), "{name}: bare LF in {line:?}");
            assert!(line.len() <= 80, "{name}: {line:?}");
        }
    }
}

#[test]
fn two_builds_give_identical_bytes() {
    for name in DESCRIPTIONS {
        let first = gsdc::compile(&load(name)).unwrap();
        let second = gsdc::compile(&load(name)).unwrap();
        assert_eq!(first, second, "{name}");
    }
}

/// gsd-parser (Rahix/profirust) reads what gsdc wrote, and what it reads is
/// what the IR says: each module's name and config bytes, every parameter's
/// default and range, the parameter telegram's length and default bytes.
#[test]
fn gsd_parser_reads_what_the_ir_says() {
    for name in DESCRIPTIONS {
        let ir = load(name);
        let (text, profibus) = gsd_of(&ir);
        let parsed = gsd_parser::parser::parse(Path::new(&profibus.file_name), &text)
            .unwrap_or_else(|e| panic!("{name}: gsd-parser rejects the GSD: {e}"));

        assert_eq!(parsed.ident_number, profibus.ident_number, "{name}");
        let modules: Vec<(String, Vec<u8>)> = parsed
            .available_modules
            .iter()
            .map(|m| (m.name.clone(), m.config.clone()))
            .collect();
        let expected: Vec<(String, Vec<u8>)> = profibus
            .modules
            .iter()
            .map(|m| (m.name.clone(), m.config.clone()))
            .collect();
        assert_eq!(modules, expected, "{name}");

        let largest = profibus
            .modules
            .iter()
            .map(|m| m.layout.bytes())
            .max()
            .unwrap();
        assert_eq!(u16::from(parsed.max_input_length), largest, "{name}");
        assert_eq!(u16::from(parsed.max_output_length), largest, "{name}");

        let prm = &parsed.user_prm_data;
        let params: Vec<_> = profibus.user_prm.params().collect();
        assert_eq!(prm.data_ref.len(), params.len(), "{name}");
        for ((offset, definition), param) in prm.data_ref.iter().zip(params) {
            let (set, mapping) = ir.mappings.entry(param.entry);
            assert_eq!(*offset, usize::from(param.offset), "{name}");
            assert_eq!(definition.name, mapping.name.en, "{name}");
            assert_eq!(definition.data_type, UserPrmDataType::Unsigned16, "{name}");
            assert_eq!(
                definition.default_value,
                i64::from(mapping.default),
                "{name}"
            );
            let Allowed::Range { min, max } = set.allowed else {
                panic!("{name}: the shipped descriptions map addresses");
            };
            assert_eq!(
                definition.constraint,
                PrmValueConstraint::MinMax(min.into(), max.into()),
                "{name}"
            );
        }

        let telegram = PrmBuilder::new(prm).into_bytes();
        assert_eq!(telegram.len(), usize::from(profibus.user_prm.len), "{name}");
        assert_eq!(
            telegram[..profibus.user_prm.constant.len()],
            profibus.user_prm.constant[..],
            "{name}"
        );
    }
}

#[test]
fn md810_parameter_telegram_is_status_bytes_then_f0_00_everywhere() {
    let ir = load("md810dp.toml");
    let (text, _) = gsd_of(&ir);
    let parsed = gsd_parser::parser::parse(Path::new("MD810DP.GSD"), &text).unwrap();
    let telegram = PrmBuilder::new(&parsed.user_prm_data).into_bytes();
    // 3 DPV1 status bytes, then 12 + 12 PZD mappings and 6 DPV1 indexes,
    // each F0-00 = 0xF000, big-endian.
    let mut expected = vec![0x00, 0x00, 0x00];
    expected.extend([0xF0, 0x00].repeat(30));
    assert_eq!(telegram, expected);
}

/// The I&M functions and the class 2 channel reach the GSD as the
/// description states them, and gsd-parser reads the file.
#[test]
fn im_and_the_class_2_channel_are_in_the_gsd() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/valid/no_warnings.toml");
    let loaded = gsdc::build::load_file(&path, "no_warnings.toml").unwrap();
    assert!(
        loaded.findings.diagnostics.is_empty(),
        "{:?}",
        loaded.findings.diagnostics
    );
    let (gsd, _) = gsd_of(loaded.ir.as_ref().unwrap());
    for line in [
        "C2_Read_Write_supp          = 1",
        "C2_Max_Data_Len             = 240",
        "C2_Response_Timeout         = 100",
        "C2_Max_Count_Channels       = 2",
        "Max_Initiate_PDU_Length     = 52",
        "Ident_Maintenance_supp      = 1",
    ] {
        assert!(gsd.contains(&format!("{line}\r\n")), "{line}");
    }
    gsd_parser::parser::parse(Path::new("X1DP.GSD"), &gsd).unwrap();
}
