//! The GSD files gsdc writes for the shipped descriptions (their
//! snapshots, reviewed against the manuals, are in outputs.rs): ASCII,
//! CRLF and 80 columns, an independent parser's reading compared with the
//! IR, and determinism.

use crate::support::descriptions::{self, load};
use gsd_parser::{PrmBuilder, PrmValueConstraint, UserPrmDataType};
use gsdc::ir::profibus::{PrmType, PrmValue, Profibus};
use gsdc::ir::{Allowed, Ir};
use gsdc::ArtifactKind;
use std::path::Path;

/// The shipped descriptions with a PROFIBUS part, each with its IR.
fn with_profibus() -> Vec<(String, Ir)> {
    let mut found = descriptions::load_shipped();
    found.retain(|(_, ir)| ir.profibus.is_some());
    assert!(!found.is_empty());
    found
}

fn gsd_of(ir: &Ir) -> (String, &Profibus) {
    let profibus = ir.profibus.as_ref().unwrap();
    let (file_name, gsd) = descriptions::one(gsdc::compile(ir).unwrap(), ArtifactKind::Gsd);
    assert_eq!(file_name, profibus.file_name);
    (gsd, profibus)
}

#[test]
fn gsd_files_are_ascii_crlf_and_at_most_80_columns() {
    for (name, ir) in with_profibus() {
        let (gsd, _) = gsd_of(&ir);
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
    for (name, _) in with_profibus() {
        let first = gsdc::compile(&load(&name)).unwrap();
        let second = gsdc::compile(&load(&name)).unwrap();
        assert_eq!(first, second, "{name}");
    }
}

/// What the IR says the modules are: name and config bytes, PPO types or
/// a gateway's word blocks.
fn expected_modules(ir: &Ir, profibus: &Profibus) -> Vec<(String, Vec<u8>)> {
    match &ir.gateway {
        Some(g) => g
            .modules
            .iter()
            .map(|m| (m.name.clone(), vec![m.config]))
            .collect(),
        None => profibus
            .modules
            .iter()
            .map(|m| (m.name.clone(), m.config.clone()))
            .collect(),
    }
}

/// A parameter as gsd-parser reads it: offset, name, type, default, range.
type ParsedParam = (usize, String, UserPrmDataType, i64, PrmValueConstraint);

/// What the IR says each parameter of User_Prm_Data is.
fn expected_params(ir: &Ir, profibus: &Profibus) -> Vec<ParsedParam> {
    profibus
        .user_prm
        .params()
        .map(|param| {
            let data_type = match param.data_type {
                PrmType::Unsigned8 => UserPrmDataType::Unsigned8,
                PrmType::Unsigned16 => UserPrmDataType::Unsigned16,
                PrmType::Bits { first, last } => UserPrmDataType::BitArea(first, last),
                other => panic!("a type the shipped descriptions do not use: {other:?}"),
            };
            let (name, default, min, max) = match param.value {
                PrmValue::Entry(key) => {
                    let (set, mapping) = ir.mappings.entry(key);
                    let Allowed::Range { min, max } = set.allowed else {
                        panic!("the shipped descriptions map addresses");
                    };
                    (mapping.name.en.clone(), mapping.default, min, max)
                }
                PrmValue::Gateway(key) => {
                    let p = ir.gateway.as_ref().unwrap().param(key);
                    (
                        p.name.en.clone(),
                        p.default.into(),
                        p.min.into(),
                        p.max.into(),
                    )
                }
                other => panic!("a parameter the shipped descriptions do not have: {other:?}"),
            };
            let range = PrmValueConstraint::MinMax(min.into(), max.into());
            (
                usize::from(param.offset),
                name,
                data_type,
                default.into(),
                range,
            )
        })
        .collect()
}

/// Each parameter as gsd-parser read it.
fn parsed_params(prm: &gsd_parser::UserPrmData) -> Vec<ParsedParam> {
    prm.data_ref
        .iter()
        .map(|(offset, d)| {
            let (name, default) = (d.name.clone(), d.default_value);
            (*offset, name, d.data_type, default, d.constraint.clone())
        })
        .collect()
}

/// gsd-parser (Rahix/profirust) reads what gsdc wrote, and what it reads is
/// what the IR says: each module's name and config bytes, the I/O limits,
/// every parameter's offset, type, default and range, the parameter
/// telegram's length and default bytes.
#[test]
fn gsd_parser_reads_what_the_ir_says() {
    for (name, ir) in with_profibus() {
        let (text, profibus) = gsd_of(&ir);
        let parsed = gsd_parser::parser::parse(Path::new(&profibus.file_name), &text)
            .unwrap_or_else(|e| panic!("{name}: gsd-parser rejects the GSD: {e}"));

        assert_eq!(parsed.ident_number, profibus.ident_number, "{name}");
        let modules: Vec<(String, Vec<u8>)> = parsed
            .available_modules
            .iter()
            .map(|m| (m.name.clone(), m.config.clone()))
            .collect();
        assert_eq!(modules, expected_modules(&ir, profibus), "{name}");

        if ir.gateway.is_none() {
            // One PPO type at a time: the largest sets the limits.
            let largest = profibus.modules.iter().map(|m| m.input_len).max();
            assert_eq!(Some(profibus.max_input_len), largest, "{name}");
            assert_eq!(Some(profibus.max_output_len), largest, "{name}");
        }
        assert_eq!(
            u16::from(parsed.max_input_length),
            profibus.max_input_len,
            "{name}"
        );
        assert_eq!(
            u16::from(parsed.max_output_length),
            profibus.max_output_len,
            "{name}"
        );

        let prm = &parsed.user_prm_data;
        let params = parsed_params(prm);
        assert_eq!(params, expected_params(&ir, profibus), "{name}");

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
    let path = crate::support::checkout("tests/fixtures/valid/no_warnings.toml");
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

/// The gateway with each slave's TPDO and RPDO words as bit areas of one
/// byte (0..8 takes 4 bits): User_Prm_Data shrinks from 61 to 31 bytes,
/// gsdc's own rules accept two parameters on one byte's different bits, and
/// gsd-parser reads the bit areas where the IR puts them.
#[test]
fn gateway_words_as_bit_areas_share_a_byte_per_slave() {
    let packed = descriptions::gateway_in_bit_areas();
    let (ir, diagnostics) = descriptions::load_text("md810-gateway.toml", &packed);
    let ir = ir.unwrap_or_else(|| panic!("{diagnostics:?}"));
    let (gsd, profibus) = gsd_of(&ir);
    assert_eq!(profibus.user_prm.len, 31);
    for expected in [
        "ExtUserPrmData = 2 \"Slave 1 TPDO words\"\r\nBitArea(0-3) 0 0-8\r\n",
        "ExtUserPrmData = 61 \"Slave 30 RPDO words\"\r\nBitArea(4-7) 0 0-8\r\n",
        "Ext_User_Prm_Data_Ref(30)   = 60\r\nExt_User_Prm_Data_Ref(30)   = 61\r\n",
    ] {
        assert!(gsd.contains(expected), "{expected:?}");
    }
    let parsed = gsd_parser::parser::parse(Path::new(&profibus.file_name), &gsd).unwrap();
    let params = parsed_params(&parsed.user_prm_data);
    assert_eq!(params, expected_params(&ir, profibus));
    let offsets: Vec<usize> = params.iter().map(|p| p.0).collect();
    assert_eq!(offsets[..5], [0, 1, 1, 2, 2]);
    assert_eq!(offsets[59..], [30, 30]);
}
