//! A PROFIdrive card's layout: its standard telegram 1 placed where the
//! GSDML declares it, and its PPO1 carrying the profile's parameter channel
//! for parameters numbered group × 100 + index (P10.05 is PNU 1005).

use gsdc_firmware_check::profidrive::*;

/// `"13ED 0000 0000 0000"`, as the manuals print telegrams: hex words.
fn bytes<const N: usize>(hex: &str) -> [u8; N] {
    let bytes: Vec<u8> = hex
        .split_whitespace()
        .flat_map(|w| u16::from_str_radix(w, 16).unwrap().to_be_bytes())
        .collect();
    bytes.try_into().unwrap()
}

/// A PPO1 telegram carrying `pkw` and the PZD words 047F 4000.
fn ppo1(pkw: &str) -> [u8; 12] {
    bytes(&format!("{pkw} 047F 4000"))
}

/// P10.05 with `subindex`: the setting's parameter, PNU 1005 (0x3ED).
fn p10_05(subindex: u8) -> Parameter {
    Parameter {
        pnu: Pnu::new(1005).unwrap(),
        subindex,
    }
}

#[test]
fn standard_telegram_1_is_placed_as_the_gsdml_declares_it() {
    assert_eq!(TELEGRAM1_API, 14848);
    assert_eq!(TELEGRAM1_ACCESS_POINT_SUBSLOT, 1);
    assert_eq!(TELEGRAM1_ACCESS_POINT_IDENT, 0xFFFF);
    assert_eq!(TELEGRAM1_DATA_SUBSLOT, 2);
    assert_eq!(TELEGRAM1_IDENT, 0x10);
    // STW1, NSOLL_A out; ZSW1, NIST_A in: 4 bytes each way.
    let out = Telegram1Out::from_bytes(&[0x04, 0x7F, 0x40, 0x00]);
    assert_eq!(out.pzd[0].get(), 0x047F);
    assert_eq!(out.pzd[1].get(), 0x4000);
}

/// Standard telegram 2 as ABB's FENA declares it: STW1, NSOLL_B (an
/// Unsigned32, high byte first on PROFINET), STW2; placed as telegram 1 is.
/// NSOLL_B = 100000 (0x000186A0) is PZD2 and PZD3.
#[test]
fn standard_telegram_2_carries_a_32_bit_speed() {
    assert_eq!(TELEGRAM2_IDENT, 0x20);
    assert_eq!(TELEGRAM2_API, 14848);
    assert_eq!(TELEGRAM2_ACCESS_POINT_SUBSLOT, 1);
    assert_eq!(TELEGRAM2_DATA_SUBSLOT, 2);
    let telegram = bytes::<8>("047F 0001 86A0 F000");
    let out = Telegram2Out::from_bytes(&telegram);
    assert_eq!(out.pzd[0].get(), 0x047F);
    assert_eq!(out.double_word(1), 100_000);
    assert_eq!(out.pzd[3].get(), 0xF000);
    let mut sent = Telegram2Out::default();
    sent.pzd[0] = out.pzd[0];
    sent.set_double_word(1, 100_000);
    sent.pzd[3] = out.pzd[3];
    assert_eq!(sent.to_bytes(), telegram);
    // The drive's answer: NIST_B of -1 (0xFFFFFFFF) across both words.
    let mut answer = Telegram2In::default();
    answer.set_double_word(1, u32::MAX);
    assert_eq!(answer.to_bytes(), bytes::<8>("0000 FFFF FFFF 0000"));
}

/// The description writes the setting's parameter as `P10.05`; the layout
/// holds 1005, the PNU the channel carries.
#[test]
fn p10_05_is_pnu_1005() {
    let [setting, _stop_mode] = settings::MAPPINGS;
    assert_eq!(setting.parameter, Some(1005));
    assert_eq!(Pnu::new(1005).map(Pnu::get), Some(0x03ED));
}

/// The master reads P10.05: request 1, PKE = 1 << 12 | 1005.
#[test]
fn read_p10_05() {
    let telegram = ppo1("13ED 0000 0000 0000");
    let out = Ppo1Out::from_bytes(&telegram);
    let read = PkwRequest::Read {
        parameter: p10_05(0),
    };
    assert_eq!(PkwRequest::decode(&out.pkw), Ok(read));
    assert_eq!(out.pzd.map(|w| w.get()), [0x047F, 0x4000]);
    let sent = Ppo1Out {
        pkw: read.encode(),
        pzd: out.pzd,
    };
    assert_eq!(sent.to_bytes(), telegram);
    // The drive answers response 1, the value of a word parameter in PWE2.
    let telegram = ppo1("13ED 0000 0000 0001");
    let answer = PkwResponse::Word {
        parameter: p10_05(0),
        value: 1,
    };
    assert_eq!(
        PkwResponse::decode(&Ppo1In::from_bytes(&telegram).pkw),
        Ok(answer)
    );
    let sent = Ppo1In {
        pkw: answer.encode(),
        pzd: Ppo1In::from_bytes(&telegram).pzd,
    };
    assert_eq!(sent.to_bytes(), telegram);
}

/// The master writes the word 1 to P10.05 (request 2); the drive echoes it
/// (response 1).
#[test]
fn write_a_word_to_p10_05() {
    let telegram = ppo1("23ED 0000 0000 0001");
    let write = PkwRequest::WriteWord {
        parameter: p10_05(0),
        value: 1,
    };
    let out = Ppo1Out::from_bytes(&telegram);
    assert_eq!(PkwRequest::decode(&out.pkw), Ok(write));
    let sent = Ppo1Out {
        pkw: write.encode(),
        pzd: out.pzd,
    };
    assert_eq!(sent.to_bytes(), telegram);
    let echo = PkwResponse::Word {
        parameter: p10_05(0),
        value: 1,
    };
    assert_eq!(
        echo.encode(),
        Ppo1In::from_bytes(&ppo1("13ED 0000 0000 0001")).pkw
    );
}

/// A double word goes high word first, PWE1 then PWE2; an array element's
/// subindex is IND's high byte.
#[test]
fn double_words_and_subindexes() {
    let write = PkwRequest::WriteArrayDoubleWord {
        parameter: p10_05(3),
        value: 100_000,
    };
    let telegram = ppo1("83ED 0300 0001 86A0");
    assert_eq!(write.encode(), Ppo1Out::from_bytes(&telegram).pkw);
    assert_eq!(
        PkwRequest::decode(&Ppo1Out::from_bytes(&telegram).pkw),
        Ok(write)
    );
}

/// The drive cannot execute: response 7, error number 2 (limit exceeded)
/// in PWE2.
#[test]
fn an_error_answer_carries_the_error_number_in_pwe2() {
    let telegram = ppo1("73ED 0000 0000 0002");
    let failed = PkwResponse::Failed {
        parameter: p10_05(0),
        error: PkwErrorNumber::LIMIT_EXCEEDED,
    };
    let answer = Ppo1In::from_bytes(&telegram);
    assert_eq!(PkwResponse::decode(&answer.pkw), Ok(failed));
    let sent = Ppo1In {
        pkw: failed.encode(),
        pzd: answer.pzd,
    };
    assert_eq!(sent.to_bytes(), telegram);
}

/// Request 14 (Siemens' "change and store in EEPROM") is not the
/// profile's: refused, with the parameter the drive answers about; a
/// parameter change report (response 9) is refused too.
#[test]
fn an_illegal_id_is_refused() {
    let out = Ppo1Out::from_bytes(&ppo1("E3ED 0000 0000 0001"));
    assert_eq!(
        PkwRequest::decode(&out.pkw),
        Err(PkwDecodeError::IllegalRequest {
            id: 14,
            parameter: p10_05(0)
        })
    );
    let answer = Ppo1In::from_bytes(&ppo1("93ED 0000 0000 0001"));
    assert_eq!(
        PkwResponse::decode(&answer.pkw),
        Err(PkwDecodeError::ChangeReport { id: 9 })
    );
    assert_eq!(Pnu::new(2048), None, "PKE has 11 bits of PNU");
}
