//! The manuals' telegrams, decoded against the shipped descriptions.

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

fn load(name: &str, text: &str) -> Ir {
    crate::load(name, text)
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
            name: Some("F0-08".into())
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
            name: Some("P43.02".into())
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

/// Standard telegram 1 has PROFIdrive's fixed words, no mapping.
#[test]
fn mv810_standard_telegram_1_names_its_words() {
    let ir = mv810();
    let t = decode(&ir, "standard telegram 1", Out, "047F 4000");
    let names: Vec<&str> = t.words.iter().map(|w| w.name.as_str()).collect();
    assert_eq!(names, ["STW1 (control word 1)", "NSOLL_A (speed setpoint)"]);
    assert!(t
        .words
        .iter()
        .all(|w| w.carries.is_none() && w.fields.is_empty()));
    assert_eq!(t.pkw, None);
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
