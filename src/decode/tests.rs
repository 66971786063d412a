//! The manuals' telegrams, decoded against the shipped descriptions.

use super::diagnosis::{Area, Unread};
use super::pkw_channel::{Parameter, PkwError, Stations};
use super::*;
use crate::ir::Direction::{In, Out};

pub(crate) fn md810() -> Ir {
    load(
        "md810dp.toml",
        include_str!("../../descriptions/md810dp.toml"),
    )
}

pub(crate) fn mv810() -> Ir {
    load(
        "mv810-pnet02.toml",
        include_str!("../../descriptions/mv810-pnet02.toml"),
    )
}

/// A PROFIdrive card: its standard telegram 1 is the profile's.
fn profidrive() -> Ir {
    load(
        "profidrive.toml",
        include_str!("../../tests/fixtures/valid/profidrive.toml"),
    )
}

fn load(name: &str, text: &str) -> Ir {
    crate::testing::load(name, text)
        .0
        .expect("the shipped descriptions load")
}

fn decode(ir: &Ir, module: &str, direction: Direction, hex: &str) -> Telegram {
    let module = find_module(ir, module, direction).unwrap();
    let hex = Hex::parse(hex).unwrap();
    telegram(ir, module, direction, &hex, &MappingInForce::defaults()).unwrap()
}

/// Two PZD words after the manual's PKW channel.
fn ppo1(pkw: &str) -> String {
    format!("{pkw} 0000 0000")
}

fn names_and_values(t: &Telegram) -> Vec<(usize, &str, u16)> {
    t.words
        .iter()
        .map(|w| (w.offset, w.name.as_str(), w.value))
        .collect()
}

/// MD810 §1.4.2 figure 6: the master reads F0-08.
#[test]
fn md810_read_f0_08_with_ppo1() {
    let ir = md810();
    let t = decode(&ir, "PPO1", Out, &ppo1("10F0 0800 0000 0000"));
    assert_eq!((t.module.as_str(), t.direction, t.len), ("PPO1", Out, 12));
    assert_eq!(
        names_and_values(&t),
        [
            (0, "PKE", 0x10F0),
            (2, "IND", 0x0800),
            (4, "PWE high", 0),
            (6, "PWE low", 0),
            (8, "PZD1", 0),
            (10, "PZD2", 0),
        ]
    );
    let pkw = t.pkw.unwrap();
    assert_eq!(pkw.kind, PkwSide::Request);
    assert_eq!((pkw.code, pkw.meaning), (1, Some("read")));
    assert_eq!(
        pkw.parameter,
        Some(Parameter {
            address: 0xF008,
            name: Some("F0-08".into()),
            subindex: None,
        })
    );
    assert_eq!((pkw.value, pkw.error, pkw.refused), (None, None, None));
}

/// The drive's answer: done, F0-08 = 0x1388.
#[test]
fn md810_answer_to_the_read() {
    let ir = md810();
    let pkw = decode(&ir, "PPO1", In, &ppo1("10F0 0800 0000 1388"))
        .pkw
        .unwrap();
    assert_eq!(pkw.kind, PkwSide::Response);
    assert_eq!((pkw.code, pkw.meaning), (1, Some("done")));
    assert_eq!(pkw.parameter.unwrap().name.as_deref(), Some("F0-08"));
    assert_eq!(pkw.value, Some(5000));
    assert_eq!(pkw.error, None);
}

/// `70F0 0800 0000 errCode`, with the four codes the manual lists; a fifth
/// is refused as the firmware refuses it.
#[test]
fn md810_error_answers() {
    let ir = md810();
    let texts = [
        "illegal command",
        "illegal address",
        "illegal data",
        "other error",
    ];
    for (code, text) in (1..=4).zip(texts) {
        let hex = ppo1(&format!("70F0 0800 0000 000{code}"));
        let pkw = decode(&ir, "PPO1", In, &hex).pkw.unwrap();
        assert_eq!((pkw.code, pkw.meaning), (7, Some("cannot execute")));
        assert_eq!(pkw.parameter.unwrap().name.as_deref(), Some("F0-08"));
        assert_eq!(
            pkw.error,
            Some(PkwError {
                code,
                text: Some(text)
            })
        );
        assert_eq!(pkw.refused, None);
    }
    let pkw = decode(&ir, "PPO1", In, &ppo1("70F0 0800 0000 0005"))
        .pkw
        .unwrap();
    assert_eq!(pkw.error.unwrap().text, None);
    assert!(pkw.refused.unwrap().contains("error code 5"));
}

/// Figure 7, and a command the manual does not define.
#[test]
fn md810_write_and_an_undefined_command() {
    let ir = md810();
    let pkw = decode(&ir, "PPO1", Out, &ppo1("20F0 0800 0000 07D0"))
        .pkw
        .unwrap();
    assert_eq!(
        (pkw.code, pkw.meaning, pkw.value),
        (2, Some("write"), Some(2000))
    );
    let pkw = decode(&ir, "PPO1", Out, &ppo1("30F0 0800 0000 0000"))
        .pkw
        .unwrap();
    assert_eq!((pkw.code, pkw.meaning), (3, None));
    assert_eq!(pkw.parameter.unwrap().name.as_deref(), Some("F0-08"));
    assert!(pkw.refused.unwrap().starts_with("command 3 is not one"));
}

/// 32 bytes: PKW at 0-7, PZD1-12 at 8-31, each PZD word carrying F0-00.
#[test]
fn md810_ppo5_has_twelve_pzd_words_after_the_pkw() {
    let ir = md810();
    let pzd: Vec<String> = (1..=12).map(|n| format!("{n:04X}")).collect();
    let hex = format!("0000 0000 0000 0000 {}", pzd.join(" "));
    let t = decode(&ir, "ppo5", Out, &hex);
    assert_eq!(t.len, 32);
    assert_eq!(t.pkw.as_ref().unwrap().meaning, Some("no request"));
    let pzd: Vec<_> = t.words[4..].iter().collect();
    assert_eq!(pzd.len(), 12);
    for (n, word) in (1u8..=12).zip(pzd) {
        assert_eq!(word.offset, 6 + 2 * usize::from(n));
        assert_eq!(word.name, format!("PZD{n}"));
        assert_eq!(word.value, u16::from(n));
        let carries = word.carries.as_ref().unwrap();
        assert_eq!(carries.mapping, format!("PZD{n}(master->slaver)"));
        assert_eq!(
            (carries.value, carries.meaning.as_deref(), carries.source),
            (0xF000, Some("F0-00"), ValueSource::Default)
        );
        assert!(word.fields.is_empty());
    }
    assert!(t.words[..4].iter().all(|w| w.carries.is_none()));
}

/// A wrong length says how long the module is.
#[test]
fn a_telegram_of_the_wrong_length_is_refused() {
    let ir = md810();
    let module = find_module(&ir, "PPO1", Out).unwrap();
    let hex = Hex::parse("10F0 0800 0000 0000").unwrap();
    let d = telegram(&ir, module, Out, &hex, &MappingInForce::defaults()).unwrap_err();
    assert_eq!(d.code, "E412");
    assert_eq!(d.message, "PPO1 is 12 bytes; this is 8");
    assert_eq!(
        d.help.as_deref(),
        Some("PPO1 is 12 bytes each way: the PKW channel (8 bytes) and 2 PZD word(s)")
    );
}

/// MV810 section 3: station 1 reads P43.02 of 485 slave 2 (the manual's
/// layout, gsdc's example), through the PKW module with 12 PZD words.
#[test]
fn mv810_read_of_p43_02() {
    let ir = mv810();
    let pzd = "0000 ".repeat(12);
    let t = decode(
        &ir,
        "PKW + 12 PZD",
        Out,
        &format!("02 01 00 03 2B 02 00 01 {pzd}"),
    );
    assert_eq!(t.len, 32);
    let names: Vec<&str> = t.words.iter().map(|w| w.name.as_str()).take(6).collect();
    assert_eq!(
        names,
        [
            "Station",
            "Command",
            "Address",
            "Value",
            "Master sends control command word",
            "PZD2"
        ]
    );
    let pkw = t.pkw.unwrap();
    assert_eq!(
        pkw.stations,
        Some(Stations {
            target: 2,
            source: 1
        })
    );
    assert_eq!((pkw.code, pkw.meaning), (3, Some("read one")));
    assert_eq!(
        pkw.parameter,
        Some(Parameter {
            address: 0x2B02,
            name: Some("P43.02".into()),
            subindex: None,
        })
    );
    assert_eq!(pkw.value, None);

    let reply = decode(
        &ir,
        "PKW + 12 PZD",
        In,
        &format!("01 02 00 03 2B 02 00 01 {pzd}"),
    );
    let pkw = reply.pkw.unwrap();
    assert_eq!(
        pkw.stations,
        Some(Stations {
            target: 1,
            source: 2
        })
    );
    assert_eq!((pkw.code, pkw.value), (3, Some(1)));
    assert_eq!(pkw.parameter.unwrap().name.as_deref(), Some("P43.02"));

    let failed = decode(
        &ir,
        "PKW + 12 PZD",
        In,
        &format!("01 02 00 83 2B 02 00 05 {pzd}"),
    );
    let pkw = failed.pkw.unwrap();
    assert_eq!((pkw.code, pkw.meaning), (0x83, Some("read one failed")));
    assert_eq!(
        pkw.error,
        Some(PkwError {
            code: 5,
            text: None
        })
    );

    // A read whose count is not 1 is refused, as the firmware refuses it.
    let pkw = decode(
        &ir,
        "PKW + 12 PZD",
        Out,
        &format!("02 01 00 03 2B 02 00 02 {pzd}"),
    )
    .pkw
    .unwrap();
    assert!(pkw.refused.unwrap().contains("this one is 2"));
}

/// PZD1 is the control or status word, bit by bit; PZD2 on carry what
/// P43.02.. and P43.13.. select.
#[test]
fn mv810_control_and_status_words_and_mapped_words() {
    let ir = mv810();
    // Forward running and fault reset; PZD2 = 5000; no PKW request.
    let t = decode(&ir, "PKW + 2 PZD", Out, "0000 0000 0000 0000 0041 1388");
    let control = &t.words[4];
    assert_eq!(control.name, "Master sends control command word");
    let set: Vec<&str> = control
        .fields
        .iter()
        .filter(|f| f.value == 1)
        .map(|f| f.name.as_str())
        .collect();
    assert_eq!(set, ["Forward running", "Fault reset"]);
    assert_eq!(control.fields.len(), 8);
    let carries = t.words[5].carries.as_ref().unwrap();
    assert_eq!(carries.mapping, "PZD2 receive");
    assert_eq!(
        (carries.value, carries.meaning.as_deref()),
        (0, Some("Disabled"))
    );

    // Status: forward running, ready, motor 2, control mode 2 (communication).
    let mut mapping = MappingInForce::defaults();
    mapping.give(&ir, "pzd_in=3").unwrap();
    let module = find_module(&ir, "PKW + 2 PZD", In).unwrap();
    let hex = Hex::parse("0000 0000 0000 0000 0461 1388").unwrap();
    let t = telegram(&ir, module, In, &hex, &mapping).unwrap();
    let field = |name: &str| {
        t.words[4]
            .fields
            .iter()
            .find(|f| f.name == name)
            .unwrap()
            .clone()
    };
    assert_eq!(field("Forward running").value, 1);
    assert_eq!(field("Ready status").value, 1);
    let motor = field("Motor number");
    assert_eq!((motor.value, motor.text.as_deref()), (1, Some("Motor 2")));
    let mode = field("Control mode");
    assert_eq!((mode.first, mode.last, mode.value), (9, 10, 2));
    assert_eq!(mode.text.as_deref(), Some("Communication"));
    let carries = t.words[5].carries.as_ref().unwrap();
    assert_eq!(
        carries.meaning.as_deref(),
        Some("Output frequency (0.01 Hz)")
    );
    assert_eq!(carries.source, ValueSource::Given);
}

/// MV810's standard message 1 is the vendor's: PZD1 its control word bit
/// by bit, PZD2 unnamed and unmapped, and no PROFIdrive name.
#[test]
fn mv810_standard_message_1_names_its_words() {
    let ir = mv810();
    let t = decode(&ir, "standard message 1", Out, "0001 4000");
    let names: Vec<&str> = t.words.iter().map(|w| w.name.as_str()).collect();
    assert_eq!(names, ["Master sends control command word", "PZD2"]);
    assert_eq!(t.words[0].fields[0].name, "Forward running");
    assert_eq!(t.words[0].fields[0].value, 1);
    assert!(t.words[1].fields.is_empty());
    assert!(t.words.iter().all(|w| w.carries.is_none()));
    assert_eq!(t.pkw, None);
}

/// PROFIdrive's standard telegram 1 has the profile's fixed words: no
/// mapping, and STW1's bits the profile's, even where the description
/// names the bits of its vendor telegrams' control word.
#[test]
fn profidrive_standard_telegram_1_names_the_profiles_words() {
    let text = include_str!("../../tests/fixtures/valid/profidrive.toml").replace(
        "profidrive = true\n",
        "profidrive = true\ncontrol_word = { name = \"Vendor word\", bits = [{ bit = 0, name = \"Run\" }] }\n",
    );
    let with_vendor_word = crate::load("profidrive.toml", &text).0.unwrap();
    for ir in [profidrive(), with_vendor_word] {
        let t = decode(&ir, "standard telegram 1", Out, "047F 4000");
        let names: Vec<&str> = t.words.iter().map(|w| w.name.as_str()).collect();
        assert_eq!(
            names,
            ["STW1 (control word 1)", "NSOLL_A (speed setpoint A)"]
        );
        assert!(t.words.iter().all(|w| w.carries.is_none()));
        let stw1 = &t.words[0].fields;
        assert_eq!(stw1.len(), 11);
        assert_eq!((stw1[0].name.as_str(), stw1[0].value), ("ON (0: OFF1)", 1));
        assert_eq!(
            (stw1[10].name.as_str(), stw1[10].value),
            ("Control by PLC", 1)
        );
        assert!(t.words[1].fields.is_empty());
    }
}

/// Standard telegram 2: STW1's bits as telegram 1's, NSOLL_B's two words
/// (high word first, as PROFINET sends the Unsigned32) read as one value,
/// and STW2 a word; the other way ZSW1, NIST_B, ZSW2.
#[test]
fn profidrive_standard_telegram_2_reads_its_32_bit_speed() {
    let ir = profidrive();
    let t = decode(&ir, "standard telegram 2", Out, "047F 0001 86A0 F000");
    assert_eq!(
        names_and_values(&t),
        [
            (0, "STW1 (control word 1)", 0x047F),
            (2, "NSOLL_B (speed setpoint B), high word", 0x0001),
            (4, "NSOLL_B (speed setpoint B), low word", 0x86A0),
            (6, "STW2 (control word 2)", 0xF000),
        ]
    );
    assert_eq!(
        t.double_words,
        [telegram::DoubleWord {
            offset: 2,
            name: "NSOLL_B (speed setpoint B)".into(),
            value: 100_000,
        }]
    );
    assert_eq!(t.words[0].fields.len(), 11);
    assert!(t.words[1..]
        .iter()
        .all(|w| w.fields.is_empty() && w.carries.is_none()));
    let t = decode(&ir, "standard telegram 2", In, "0237 FFFF FFFE 0000");
    assert_eq!(t.double_words[0].name, "NIST_B (speed actual value B)");
    assert_eq!(t.double_words[0].value, 0xFFFF_FFFE);
    assert_eq!(t.words[3].name, "ZSW2 (status word 2)");
    assert_eq!(
        (
            t.words[0].fields[0].name.as_str(),
            t.words[0].fields[0].value
        ),
        ("Ready to switch on", 1)
    );
    // Telegram 1 has none.
    assert!(decode(&ir, "standard telegram 1", Out, "047F 4000")
        .double_words
        .is_empty());
}

fn md810_default_prm() -> String {
    format!("00 00 00 {}", "F0 00 ".repeat(30))
}

/// The default User_Prm_Data of md810dp: three DPV1 status bytes, then
/// F0-00 thirty times (12 PZD out, 12 PZD in, 6 indexes).
#[test]
fn md810_default_user_prm_data() {
    let ir = md810();
    let prm = prm(&ir, &Hex::parse(&md810_default_prm()).unwrap()).unwrap();
    assert_eq!(prm.len, 63);
    let constant: Vec<(&str, u8)> = prm
        .constant
        .iter()
        .map(|c| (c.name.as_str(), c.value))
        .collect();
    assert_eq!(
        constant,
        [
            ("DPV1_Status_1", 0),
            ("DPV1_Status_2", 0),
            ("DPV1_Status_3", 0)
        ]
    );
    assert_eq!(prm.params.len(), 30);
    for (i, param) in prm.params.iter().enumerate() {
        assert_eq!(param.offset, 3 + 2 * i);
        assert_eq!(param.id, u16::try_from(i + 1).unwrap());
        assert_eq!((param.value, param.default), (0xF000, 0xF000));
        assert_eq!(param.meaning.as_deref(), Some("F0-00"));
        assert!(param.allowed);
    }
    let names: Vec<&str> = prm.params.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(names[0], "PZD1(master->slaver)");
    assert_eq!(names[11], "PZD12(master->slaver)");
    assert_eq!(names[12], "PZD1(slaver->master)");
    assert_eq!(names[24], "Index0");
    assert_eq!(names[29], "Index5");
}

/// MD810 §1.6 step 5: PZD3 out = F0-12 at bytes 7-8, Index0 = F0-02 and
/// Index1 = F0-08 at bytes 51-54; the telegram's PZD3 is then named F0-12.
#[test]
fn md810_prm_with_the_manuals_values_maps_the_telegram() {
    let ir = md810();
    let mut bytes = Hex::parse(&md810_default_prm()).unwrap().bytes().to_vec();
    bytes[7..9].copy_from_slice(&[0xF0, 0x0C]);
    bytes[51..55].copy_from_slice(&[0xF0, 0x02, 0xF0, 0x08]);
    let hex: Vec<String> = bytes.iter().map(|b| format!("{b:02X}")).collect();
    let prm = prm(&ir, &Hex::parse(&hex.join("")).unwrap()).unwrap();
    let meaning = |name: &str| {
        let p = prm.params.iter().find(|p| p.name == name).unwrap();
        p.meaning.clone().unwrap()
    };
    assert_eq!(meaning("PZD3(master->slaver)"), "F0-12");
    assert_eq!(meaning("Index0"), "F0-02");
    assert_eq!(meaning("Index1"), "F0-08");
    assert_eq!(meaning("PZD3(slaver->master)"), "F0-00");

    let module = find_module(&ir, "PPO2", Out).unwrap();
    let telegram_hex = Hex::parse(&"0000 ".repeat(10)).unwrap();
    let t = telegram(&ir, module, Out, &telegram_hex, &prm.mapping()).unwrap();
    let pzd3 = t.words[6].carries.as_ref().unwrap();
    assert_eq!(t.words[6].name, "PZD3");
    assert_eq!(pzd3.meaning.as_deref(), Some("F0-12"));
    assert_eq!(pzd3.source, ValueSource::ParameterTelegram);
}

#[test]
fn prm_errors() {
    let ir = md810();
    let d = prm(&ir, &Hex::parse("00 00 00").unwrap()).unwrap_err();
    assert_eq!(d.code, "E412");
    let help = d.help.unwrap();
    assert!(
        help.starts_with("MD810DP.GSD's User_Prm_Data is 63 bytes: 3 DPV1 status bytes, then 2 bytes each for 12 pzd_out, 12 pzd_in, 6 dpv1_index;"),
        "{help}"
    );
    let d = prm(&mv810(), &Hex::parse("00").unwrap()).unwrap_err();
    assert_eq!(d.code, "E414");
}

/// MD810 §1.8: the card lost the drive.
#[test]
fn md810_diagnosis_card_lost_the_drive() {
    let ir = md810();
    let block = diagnosis(&ir, &Hex::parse("03 00 34").unwrap()).unwrap();
    assert_eq!((block.len, block.header), (3, 0x03));
    assert_eq!(
        block.areas,
        [Area {
            first_bit: 8,
            last_bit: 15,
            value: 0x34,
            text: Some("DP card-drive comm. interrupted".into())
        }]
    );
    let block = diagnosis(&ir, &Hex::parse("03 00 35").unwrap()).unwrap();
    assert_eq!(
        (block.areas[0].value, block.areas[0].text.as_deref()),
        (0x35, None)
    );
}

/// MD810 §1.8: byte 7, the high byte of the fault code (U0-62), is in no
/// Unit_Diag_Area; it is shown whole, by the description's word for it,
/// not dropped.
#[test]
fn md810_diagnosis_shows_the_high_byte_no_area_reads() {
    let block = diagnosis(&md810(), &Hex::parse("03 12 34").unwrap()).unwrap();
    assert_eq!(block.areas[0].value, 0x34);
    assert_eq!(
        block.unread,
        [Unread::Byte {
            at: 0,
            value: 0x12,
            text: "Device-related diagnosis, high byte".into()
        }]
    );
}

/// A set bit no area reads is shown with its Unit_Diag_Bit text, or as not
/// named: bit 0 and 9 have texts in the fixture, bit 23 none; bit 8 is
/// clear and not shown. Bit 9 clear shows its Unit_Diag_Not_Bit text.
#[test]
fn diagnosis_bits_outside_areas_are_each_shown_when_set() {
    let ir = load(
        "vendor_dp.toml",
        include_str!("../../tests/fixtures/valid/vendor_dp.toml"),
    );
    let block = diagnosis(&ir, &Hex::parse("08 01 02 80 00 00 00 00").unwrap()).unwrap();
    let bit = |bit, text: Option<&str>| Unread::Bit {
        bit,
        text: text.map(Into::into),
    };
    assert_eq!(
        block.unread,
        [
            bit(0, Some("Overcurrent")),
            bit(9, Some("Drive not ready")),
            bit(23, None)
        ]
    );
    let block = diagnosis(&ir, &Hex::parse("08 01 00 00 00 00 00 00").unwrap()).unwrap();
    assert_eq!(
        block.unread,
        [
            bit(0, Some("Overcurrent")),
            Unread::ClearBit {
                bit: 9,
                text: "Drive ready".into()
            }
        ]
    );
}

#[test]
fn diagnosis_errors() {
    let ir = md810();
    let d = diagnosis(&ir, &Hex::parse("03 00").unwrap()).unwrap_err();
    assert_eq!(d.code, "E412");
    // Channel-related, and a length that is not the block's.
    let d = diagnosis(&ir, &Hex::parse("  83 00 34").unwrap()).unwrap_err();
    assert_eq!((d.code, d.span), ("E417", Some(2..4)));
    assert!(d.message.contains("channel-related"), "{}", d.message);
    let d = diagnosis(&ir, &Hex::parse("05 00 34").unwrap()).unwrap_err();
    assert!(d.message.contains("the length 5"), "{}", d.message);
    let d = diagnosis(&mv810(), &Hex::parse("03 00 34").unwrap()).unwrap_err();
    assert_eq!(d.code, "E414");
}

/// The JSON a program reads: the fields, direction as `--direction` writes it.
#[test]
fn decoded_values_serialize_with_their_names() {
    let ir = md810();
    let t = decode(&ir, "PPO1", Out, &ppo1("10F0 0800 0000 0000"));
    let json = serde_json::to_value(&t).unwrap();
    assert_eq!(json["direction"], "out");
    assert_eq!(json["pkw"]["kind"], "request");
    assert_eq!(json["pkw"]["parameter"]["name"], "F0-08");
    assert_eq!(json["pkw"]["parameter"]["address"], 0xF008);
    assert_eq!(json["words"][4]["carries"]["source"], "default");
}

// ---------------------------------------------------------------------------
// The gateway (MD810 manual chapter 2)

pub(crate) fn md810_gateway() -> Ir {
    load(
        "md810-gateway.toml",
        include_str!("../../descriptions/md810-gateway.toml"),
    )
}

/// The gateway with each node's TPDO words in bits 0-3 and RPDO words in
/// bits 4-7 of one byte, instead of a byte each.
fn md810_gateway_in_bit_areas() -> Ir {
    let text = include_str!("../../descriptions/md810-gateway.toml");
    let text = text
        .replacen(
            "name = \"Slave {n} TPDO words\"\ntype = \"Unsigned8\"",
            "name = \"Slave {n} TPDO words\"\nbits = [0, 3]",
            1,
        )
        .replacen(
            "name = \"Slave {n} RPDO words\"\ntype = \"Unsigned8\"",
            "name = \"Slave {n} RPDO words\"\nbits = [4, 7]",
            1,
        );
    assert_eq!(text.matches("bits = [").count(), 2, "both parameters moved");
    load("md810-gateway.toml", &text)
}

/// User_Prm_Data of a gateway with one byte per parameter: the count, then
/// TPDO and RPDO words of slave 1, slave 2, ...; the other slaves 0.
fn gateway_prm(count: u8, input: &[u8], output: &[u8]) -> Hex {
    let mut bytes = [0u8; 61];
    bytes[0] = count;
    for (i, &w) in input.iter().enumerate() {
        bytes[1 + 2 * i] = w;
    }
    for (i, &w) in output.iter().enumerate() {
        bytes[2 + 2 * i] = w;
    }
    let hex: Vec<String> = bytes.iter().map(|b| format!("{b:02X}")).collect();
    Hex::parse(&hex.join(" ")).unwrap()
}

/// 2.4 step 5: TPDO 120 words, RPDO 64 words, as 15 slaves of 8 TPDO
/// words, the first 8 of them with 8 RPDO words.
fn manual_example_prm() -> Hex {
    gateway_prm(15, &[8; 15], &[8; 8])
}

#[test]
fn gateway_prm_of_the_manuals_example() {
    let ir = md810_gateway();
    let prm = prm(&ir, &manual_example_prm()).unwrap();
    assert_eq!((prm.len, prm.constant.len(), prm.params.len()), (61, 0, 61));
    let count = &prm.params[0];
    assert_eq!(
        (
            count.offset,
            count.name.as_str(),
            count.data_type.as_str(),
            count.value,
            count.default,
            count.range,
            count.allowed
        ),
        (
            0,
            "Number of CANopen slaves",
            "Unsigned8",
            15,
            1,
            Some([1, 30]),
            true
        )
    );
    // A number means nothing beyond itself.
    assert_eq!(
        (count.meaning.as_deref(), count.default_meaning.as_deref()),
        (None, None)
    );
    let slave_15 = &prm.params[29];
    assert_eq!(
        (slave_15.offset, slave_15.name.as_str(), slave_15.value),
        (29, "Slave 15 TPDO words", 8)
    );
    assert_eq!(prm.params[30].name, "Slave 15 RPDO words");
    assert!(prm.params.iter().all(|p| p.allowed));
    let nodes = prm.gateway.unwrap();
    assert_eq!(
        (
            nodes.node_count,
            nodes.input_words,
            nodes.output_words,
            nodes.input_len,
            nodes.output_len
        ),
        (15, 120, 64, 240, 128)
    );
    assert_eq!((nodes.max_input_len, nodes.max_output_len), (244, 244));
    assert_eq!(nodes.refused, None);
}

/// What the firmware refuses, in its order: the count, a node's words past
/// the count or out of range, the limits of 244 bytes.
#[test]
fn gateway_prm_the_card_refuses() {
    let ir = md810_gateway();
    let refused = |hex: Hex| prm(&ir, &hex).unwrap().gateway.unwrap().refused;

    let count_31 = prm(&ir, &gateway_prm(31, &[], &[])).unwrap();
    assert!(!count_31.params[0].allowed);
    assert_eq!(
        count_31.gateway.unwrap().refused.as_deref(),
        Some("Number of CANopen slaves: 31 is not allowed (1 to 30)")
    );
    let nine = prm(&ir, &gateway_prm(2, &[8, 9], &[])).unwrap();
    assert!(!nine.params[3].allowed && nine.params[1].allowed);
    assert_eq!(
        nine.gateway.unwrap().refused.as_deref(),
        Some("Slave 2 TPDO words: 9 is not allowed (0 to 8)")
    );
    assert_eq!(
        refused(gateway_prm(2, &[1, 1], &[0, 0, 1])).as_deref(),
        Some("node 3 is not in use (the count is 2) but carries words: Slave 3 RPDO words = 1")
    );
    // 30 slaves of 5 words: 300 bytes.
    assert_eq!(
        refused(gateway_prm(30, &[5; 30], &[])).as_deref(),
        Some("the input is 300 bytes; the gateway carries at most 244")
    );
    // 244 bytes each way pass (2.2.1's most).
    let mut at_limit = [4u8; 30];
    at_limit[..2].copy_from_slice(&[5, 5]);
    assert_eq!(refused(gateway_prm(30, &at_limit, &at_limit)), None);
    at_limit[29] = 5;
    assert_eq!(
        refused(gateway_prm(30, &[0; 30], &at_limit)).as_deref(),
        Some("the output is 246 bytes; the gateway carries at most 244")
    );
}

/// Bit areas: slave 1's TPDO and RPDO words share byte 1.
#[test]
fn gateway_prm_in_bit_areas() {
    let ir = md810_gateway_in_bit_areas();
    let mut bytes = [0u8; 31];
    bytes[..3].copy_from_slice(&[2, 0x98, 0x08]);
    let hex: Vec<String> = bytes.iter().map(|b| format!("{b:02X}")).collect();
    let prm = prm(&ir, &Hex::parse(&hex.concat()).unwrap()).unwrap();
    let fields: Vec<(usize, &str, u16, bool)> = prm.params[1..5]
        .iter()
        .map(|p| (p.offset, p.data_type.as_str(), p.value, p.allowed))
        .collect();
    assert_eq!(
        fields,
        [
            (1, "BitArea(0-3)", 8, true),
            (1, "BitArea(4-7)", 9, false),
            (2, "BitArea(0-3)", 8, true),
            (2, "BitArea(4-7)", 0, true),
        ]
    );
    assert_eq!(
        prm.gateway.unwrap().refused.as_deref(),
        Some("Slave 1 RPDO words: 9 is not allowed (0 to 8)")
    );
}

#[test]
fn gateway_prm_errors_name_its_parameters() {
    let d = prm(&md810_gateway(), &Hex::parse("0F").unwrap()).unwrap_err();
    assert_eq!(d.code, "E412");
    assert_eq!(
        d.help.as_deref(),
        Some("MD810GW.GSD's User_Prm_Data is 61 bytes: the 61 gateway parameters from Number of CANopen slaves to Slave 30 RPDO words; give it without the 7 standard bytes of Set_Prm")
    );
}

fn words_of(n: u16) -> String {
    (1..=n).map(|w| format!("{w:04X} ")).collect()
}

/// Two slaves of 8 TPDO words each: INPUT 16 words carries all 16, slave
/// 1's first (ascending node number, the description's data order).
#[test]
fn gateway_module_words_are_named_after_their_nodes() {
    let ir = md810_gateway();
    let mapping = prm(&ir, &gateway_prm(2, &[8, 8], &[8])).unwrap().mapping();
    let module = find_module(&ir, "input 16 words", In).unwrap();
    let hex = Hex::parse(&words_of(16)).unwrap();
    let t = telegram(&ir, module, In, &hex, &mapping).unwrap();
    assert_eq!(
        (t.module.as_str(), t.direction, t.len),
        ("INPUT 16 words", In, 32)
    );
    let g = t.gateway.as_ref().unwrap();
    assert_eq!(g.source, ValueSource::ParameterTelegram);
    assert!(g.attributed);
    assert_eq!((g.nodes.node_count, g.nodes.input_words), (2, 16));
    let named = |i: usize| {
        let w = &t.words[i];
        (
            w.offset,
            w.name.as_str(),
            w.value,
            w.node.map(|n| (n.node, n.word)),
        )
    };
    assert_eq!(named(0), (0, "word 1", 1, Some((1, 1))));
    assert_eq!(named(7), (14, "word 8", 8, Some((1, 8))));
    assert_eq!(named(8), (16, "word 9", 9, Some((2, 1))));
    assert_eq!(named(15), (30, "word 16", 16, Some((2, 8))));
    assert!(t.pkw.is_none() && t.words.iter().all(|w| w.carries.is_none()));

    // The 8 RPDO words of slave 1: OUTPUT 8 words carries them all.
    let module = find_module(&ir, "OUTPUT 8 words", Out).unwrap();
    let t = telegram(
        &ir,
        module,
        Out,
        &Hex::parse(&words_of(8)).unwrap(),
        &mapping,
    )
    .unwrap();
    assert!(t.words.iter().all(|w| w.node.map(|n| n.node) == Some(1)));
}

/// A module that carries part of the nodes' words, or more words than
/// they have, or under a configuration the card refuses: its words are
/// numbered, no node named.
#[test]
fn gateway_module_words_without_nodes() {
    let ir = md810_gateway();
    let unnamed = |mapping: &MappingInForce, module: &str, words: u16| {
        let module = find_module(&ir, module, In).unwrap();
        let hex = Hex::parse(&words_of(words)).unwrap();
        let t = telegram(&ir, module, In, &hex, mapping).unwrap();
        assert!(t.words.iter().all(|w| w.node.is_none()), "{module:?}");
        assert_eq!(t.words[words as usize - 1].name, format!("word {words}"));
        t.gateway.unwrap()
    };
    // The defaults: the bridge alone, no words.
    let g = unnamed(&MappingInForce::defaults(), "INPUT 4 words", 4);
    assert_eq!(
        (g.source, g.attributed, g.nodes.input_words),
        (ValueSource::Default, false, 0)
    );
    // The manual's example: 120 words, 16 in this module.
    let example = prm(&ir, &manual_example_prm()).unwrap().mapping();
    let g = unnamed(&example, "INPUT 16 words", 16);
    assert_eq!((g.attributed, g.nodes.input_words), (false, 120));
    // 16 words, but slave 2 has 9: refused.
    let refused = prm(&ir, &gateway_prm(2, &[7, 9], &[])).unwrap().mapping();
    let g = unnamed(&refused, "INPUT 16 words", 16);
    assert!(g.nodes.refused.is_some() && !g.attributed);
}

#[test]
fn gateway_modules_go_one_way() {
    let ir = md810_gateway();
    let d = find_module(&ir, "INPUT 16 words", Out).unwrap_err();
    assert_eq!((d.code, d.span), ("E413", Some(0..14)));
    assert_eq!(
        d.message,
        "the description has no output module `INPUT 16 words`"
    );
    assert_eq!(
        d.help.as_deref(),
        Some("the output modules (--direction out) are: OUTPUT 1 word, OUTPUT 2 words, OUTPUT 4 words, OUTPUT 8 words, OUTPUT 16 words")
    );
    let d = find_module(&ir, "PPO1", In).unwrap_err();
    assert!(d
        .help
        .unwrap()
        .starts_with("the modules are: INPUT 1 word, "));
    let module = find_module(&ir, "OUTPUT 2 words", Out).unwrap();
    let d = telegram(
        &ir,
        module,
        Out,
        &Hex::parse("0000").unwrap(),
        &MappingInForce::defaults(),
    )
    .unwrap_err();
    assert_eq!(d.message, "OUTPUT 2 words is 4 bytes; this is 2");
    assert_eq!(
        d.help.as_deref(),
        Some("OUTPUT 2 words is 4 bytes of the master's output, the words the nodes receive")
    );
}

/// 2.5's four blocks: type, CANopen slave, code (decimal 35, 34, 32), and
/// type 4's drive fault code, high byte first.
#[test]
fn gateway_diagnosis_of_2_5() {
    let ir = md810_gateway();
    let read = |hex: &str| {
        let block = diagnosis(&ir, &Hex::parse(hex).unwrap()).unwrap();
        assert!(block.areas.is_empty());
        block.gateway.unwrap()
    };
    for (hex, kind, node, code, text) in [
        (
            "04 01 02 23",
            "Parameter error",
            2,
            35,
            "Parameter PDO length does not match the drive",
        ),
        (
            "04 01 1E 22",
            "Parameter error",
            30,
            34,
            "Node in the configuration not online",
        ),
        (
            "04 03 01 20",
            "CANopen network fault",
            1,
            32,
            "CANopen slave dropped out while running",
        ),
    ] {
        let g = read(hex);
        assert_eq!(
            (g.kind.at, g.kind.text.as_deref()),
            (1, Some(kind)),
            "{hex}"
        );
        assert_eq!((g.node.at, g.node.value, g.node.allowed), (2, node, true));
        let c = g.code.unwrap();
        assert_eq!(
            (c.at, c.bytes, c.value, c.text.as_deref()),
            (3, 1, code, Some(text))
        );
    }
    let g = read("05 04 02 12 34");
    assert_eq!(g.kind.text.as_deref(), Some("Drive reports fault"));
    let c = g.code.unwrap();
    assert_eq!(
        (c.at, c.bytes, c.value, c.text.as_deref()),
        (3, 2, 0x1234, Some("Drive fault code"))
    );
    let block = diagnosis(&ir, &Hex::parse("0504021234").unwrap()).unwrap();
    assert_eq!(
        (block.len, block.header, block.bytes),
        (5, 5, vec![5, 4, 2, 0x12, 0x34])
    );
}

/// Values the description does not name decode, and say so.
#[test]
fn gateway_diagnosis_names_what_it_can() {
    let ir = md810_gateway();
    let read = |hex: &str| {
        diagnosis(&ir, &Hex::parse(hex).unwrap())
            .unwrap()
            .gateway
            .unwrap()
    };
    let g = read("04 01 00 99");
    assert_eq!(
        (g.node.value, g.node.allowed, g.node.range),
        (0, false, [1, 30])
    );
    assert_eq!(g.code.unwrap().text, None);
    let g = read("04 02 1F 23");
    assert_eq!((g.kind.value, g.kind.text.as_deref()), (2, None));
    assert_eq!((g.node.value, g.node.allowed, g.code), (31, false, None));
}

#[test]
fn gateway_diagnosis_errors() {
    let ir = md810_gateway();
    let fail = |hex: &str| diagnosis(&ir, &Hex::parse(hex).unwrap()).unwrap_err();
    // Bytes missing, bytes too many, after the header's length.
    let d = fail("04 01 02");
    assert_eq!((d.code, d.span.clone()), ("E412", Some(8..8)));
    assert_eq!(d.message, "the diagnosis block is 4 bytes; this is 3");
    assert_eq!(
        d.help.as_deref(),
        Some("the header has bits 7-6 00 and bits 5-0 the block's length: 4 bytes for type 1 or 3, 5 bytes for type 4, the header included")
    );
    assert_eq!(fail("04 01 02 23 00").span, Some(12..14));
    assert_eq!(fail("").code, "E412");
    // Not device-related; a length no type has; a length not the type's.
    let d = fail(" 84 01 02 23");
    assert_eq!((d.code, d.span), ("E417", Some(1..3)));
    assert!(d.message.contains("channel-related"), "{}", d.message);
    let d = fail("07 01 02 23 00 00 00");
    assert_eq!(
        d.message,
        "0x07 is not the header of this device's diagnosis block: it gives the length 7"
    );
    let d = fail("04 04 02 12");
    assert_eq!((d.code, d.span), ("E417", Some(0..2)));
    assert_eq!(
        d.message,
        "0x04 is not the header of a type 4 block: it gives the length 4"
    );
    assert_eq!(
        d.help.as_deref(),
        Some("a block of type 4 (Drive reports fault) is 5 bytes, the header included: it starts with 0x05")
    );
    assert_eq!(fail("05 01 02 23 00").code, "E417");
}

/// The JSON of a gateway's block and module, as docs/wire-format.md shows it.
#[test]
fn gateway_values_serialize_with_their_names() {
    let ir = md810_gateway();
    let block = diagnosis(&ir, &Hex::parse("05 04 02 12 34").unwrap()).unwrap();
    let json = serde_json::to_value(&block).unwrap();
    assert_eq!(json["areas"], serde_json::json!([]));
    assert_eq!(
        json["gateway"],
        serde_json::json!({
            "type": { "at": 1, "value": 4, "text": "Drive reports fault" },
            "node": { "at": 2, "value": 2, "range": [1, 30], "allowed": true },
            "code": { "at": 3, "bytes": 2, "value": 0x1234, "text": "Drive fault code" },
        })
    );
    let t = decode(&ir, "INPUT 1 word", In, "0001");
    let json = serde_json::to_value(&t).unwrap();
    assert_eq!(json["words"][0]["node"], serde_json::Value::Null);
    assert_eq!(json["gateway"]["source"], "default");
    assert_eq!(json["gateway"]["attributed"], false);
    assert_eq!(json["gateway"]["nodes"]["node_count"], 1);
    let md810 = decode(&md810(), "PPO1", Out, &ppo1("10F0 0800 0000 0000"));
    assert_eq!(
        serde_json::to_value(&md810).unwrap()["gateway"],
        serde_json::Value::Null
    );
}
