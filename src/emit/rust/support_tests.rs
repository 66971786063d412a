//! Tests of the hand-written support code the generated layouts are built
//! from: compiled here as the module tree that `gsdc_support.rs` inlines.

use super::support::pkw_pke_ind_pwe as pke_ind_pwe;
use super::support::pkw_profidrive as profidrive;
use super::support::pkw_station_command as station_command;
use super::support::*;

/// `"10F0 0800 0000 1388"`, as the manuals print a PKW channel.
fn pkw(hex: &str) -> [U16Be; 4] {
    let words: Vec<U16Be> = hex
        .split_whitespace()
        .map(|w| U16Be::new(u16::from_str_radix(w, 16).unwrap()))
        .collect();
    words.try_into().unwrap()
}

/// MD810 manual 1.4.2: a PPO1 telegram carrying "read F0-08" and two PZD
/// words; PPO3 the same PZD words alone.
#[test]
fn telegrams_split_into_pkw_and_pzd_words_and_back() {
    type Ppo1 = PkwTelegram<2, 12>;
    type Ppo3 = PzdTelegram<2, 4>;
    let bytes = [0x10, 0xF0, 0x08, 0x00, 0, 0, 0, 0, 0x00, 0x01, 0x13, 0x88];
    let ppo1 = Ppo1::from_bytes(&bytes);
    assert_eq!(ppo1.pkw.map(U16Be::get), [0x10F0, 0x0800, 0, 0]);
    assert_eq!(ppo1.pzd.map(U16Be::get), [0x0001, 0x1388]);
    assert_eq!(ppo1.to_bytes(), bytes);
    let ppo3 = Ppo3::from_bytes(&[0x00, 0x01, 0x13, 0x88]);
    assert_eq!(ppo3.pzd, ppo1.pzd);
    assert_eq!(ppo3.to_bytes(), bytes[8..]);
    assert_eq!((Ppo1::LEN, Ppo3::LEN), (12, 4));
    assert_eq!(Ppo1::default().to_bytes(), [0; 12]);
    assert_eq!(Ppo3::default().to_bytes(), [0; 4]);
    assert_eq!(core::mem::size_of::<Ppo1>(), 12);
}

#[test]
fn words_are_big_endian_with_alignment_1() {
    let mut word = U16Be::new(0x1388);
    assert_eq!(word.get(), 5000);
    let mut bytes = [0; 2];
    put_words(&mut bytes, &[word]);
    assert_eq!(bytes, [0x13, 0x88]);
    word.set(0x07D0);
    assert_eq!(words::<1>(&[0x07, 0xD0]), [word]);
    assert_eq!(core::mem::size_of::<[U16Be; 16]>(), 32);
    assert_eq!(core::mem::align_of::<[U16Be; 16]>(), 1);
}

#[test]
fn words_copy_as_far_as_both_reach() {
    assert_eq!(
        words::<3>(&[0x12, 0x34, 0x56]),
        [U16Be::new(0x1234), U16Be::new(0), U16Be::new(0)]
    );
    let mut bytes = [0xFF; 5];
    put_words(
        &mut bytes,
        &[U16Be::new(0x0102), U16Be::new(0x0304), U16Be::new(0x0506)],
    );
    assert_eq!(bytes, [1, 2, 3, 4, 0xFF]);
}

#[test]
fn the_pkw_channel_is_the_first_four_words() {
    let telegram = [0x10, 0xF0, 0x08, 0x00, 0, 0, 0, 0, 0x13, 0x88];
    let (channel, pzd) = telegram.split_at(PKW_BYTES);
    assert_eq!(words::<4>(channel), pkw("10F0 0800 0000 0000"));
    assert_eq!(words::<1>(pzd), [U16Be::new(0x1388)]);
}

#[test]
fn bit_fields_read_and_write_their_bits_only() {
    let control_mode = BitField::new(9, 10);
    assert_eq!(control_mode.mask(), 0x0600);
    assert_eq!(control_mode.get(0xFDFF), 0b10);
    assert!(control_mode.is_set(0x0200));
    assert!(!control_mode.is_set(0xF9FF));
    assert_eq!(control_mode.with(0xFFFF, 0), 0xF9FF);
    assert_eq!(
        control_mode.with(0, 0b111),
        0x0600,
        "bits beyond the field are dropped"
    );
    let whole = BitField::new(0, 15);
    assert_eq!(whole.mask(), 0xFFFF);
    assert_eq!(whole.with(0x1234, 7), 7);
    assert_eq!(BitField::new(3, 3).mask(), 0x0008);
}

fn is_small(value: u16) -> bool {
    value < 3
}

const MAPPINGS: [Mapping; 2] = [
    Mapping {
        name: "PZD2",
        number: 2,
        default: 0xF000,
        parameter: None,
        allowed: Allowed::Range {
            min: 0xF000,
            max: 0xF0FF,
        },
        bytes: 2,
    },
    Mapping {
        name: "PZD3",
        number: 3,
        default: 1,
        parameter: Some(0x2B02),
        allowed: Allowed::Choices(is_small),
        bytes: 2,
    },
];

#[test]
fn allowed_values_are_a_range_or_choices() {
    let [range, choices] = MAPPINGS.map(|m| m.allowed);
    assert!(range.contains(0xF000) && range.contains(0xF0FF));
    assert!(!range.contains(0xEFFF) && !range.contains(0xF100));
    assert!(choices.contains(2) && !choices.contains(3));
    assert_eq!(
        MAPPINGS.map(|m| (m.name, m.number, m.parameter)),
        [("PZD2", 2, None), ("PZD3", 3, Some(0x2B02))]
    );
}

#[test]
fn defaults_in_mapping_order() {
    const DEFAULTS: [u16; 2] = defaults(&MAPPINGS);
    assert_eq!(DEFAULTS, [0xF000, 1]);
}

fn length(expected: usize, found: usize) -> PrmError {
    PrmError::Length { expected, found }
}

fn not_allowed(offset: usize, value: u32) -> PrmError {
    PrmError::NotAllowed { offset, value }
}

#[test]
fn values_are_read_and_checked_at_their_offset() {
    let telegram = [0x80, 0xF0, 0x12, 0x00, 0x02];
    assert_eq!(read_bytes::<1>(&telegram, 0), Ok([0x80]));
    assert_eq!(read_values(&telegram, 1, &MAPPINGS), Ok([0xF012, 2]));
    let bad_choice = [0x80, 0xF0, 0x12, 0x00, 0x03];
    assert_eq!(
        read_values(&bad_choice, 1, &MAPPINGS),
        Err(not_allowed(3, 3))
    );
    let bad_address = [0x80, 0xA0, 0x12, 0x00, 0x02];
    let refused = read_values(&bad_address, 1, &MAPPINGS);
    assert_eq!(refused, Err(not_allowed(1, 0xA012)));
}

#[test]
fn reading_past_the_end_is_refused() {
    let telegram = [0x80, 0xF0, 0x12, 0x00, 0x02];
    let short = read_values(&telegram[..4], 1, &MAPPINGS);
    assert_eq!(short, Err(length(5, 4)));
    assert_eq!(read_bytes::<2>(&telegram, 4), Err(length(6, 5)));
    let far = read_values(&telegram, usize::MAX - 1, &MAPPINGS);
    assert_eq!(far, Err(length(usize::MAX, 5)));
}

#[test]
fn a_record_has_exactly_one_word_per_mapping() {
    let record = [0xF0, 0x00, 0x00, 0x01];
    assert_eq!(read_record(&record, &MAPPINGS), Ok([0xF000, 1]));
    assert_eq!(read_record(&record[1..], &MAPPINGS), Err(length(4, 3)));
    assert_eq!(check_len(&[], 0), Ok(()));
}

/// ABB FENA's record 1 starts with two Integer8 settings (stop mode 0 to 2,
/// control-zero mode 0 to 1), then an Unsigned16: each read at its own
/// offset, with no gaps.
const FENA_SETTINGS: [Mapping; 3] = [
    Mapping {
        name: "Stop mode",
        number: 1,
        default: 1,
        parameter: None,
        allowed: Allowed::Range { min: 0, max: 2 },
        bytes: 1,
    },
    Mapping {
        name: "Control-zero mode",
        number: 2,
        default: 0,
        parameter: None,
        allowed: Allowed::Range { min: 0, max: 1 },
        bytes: 1,
    },
    Mapping {
        name: "Fail safe control word",
        number: 3,
        default: 0,
        parameter: None,
        allowed: Allowed::Range {
            min: 0,
            max: 0xFFFF,
        },
        bytes: 2,
    },
];

#[test]
fn a_record_of_byte_and_word_settings_reads_each_at_its_offset() {
    assert_eq!(record_len(&FENA_SETTINGS), 4);
    let record = [2, 1, 0x04, 0x7E];
    assert_eq!(read_record(&record, &FENA_SETTINGS), Ok([2, 1, 0x047E]));
    assert_eq!(read_record(&record[..3], &FENA_SETTINGS), Err(length(4, 3)));
    assert_eq!(
        read_record(&[0, 2, 0, 0], &FENA_SETTINGS),
        Err(PrmError::NotAllowed {
            offset: 1,
            value: 2
        })
    );
}

/// A module's record of byte and word settings, as the device tables give
/// it: the telegram's record holds the stop mode alone, fixed at 0, the
/// PZD module's all three; a fixed entry must hold its value.
#[test]
fn a_device_record_of_byte_and_word_settings_decodes_each_at_its_offset() {
    use device::{PnRecord, RecordReading};
    let whole = PnRecord {
        index: 1,
        len: 4,
        reading: RecordReading::Whole,
        entries: &[&FENA_SETTINGS[0], &FENA_SETTINGS[1], &FENA_SETTINGS[2]],
        defaults: &[1, 0, 0],
        changeable: &[true, true, true],
        fail_safe: &[],
    };
    let mut values = [9; 3];
    assert_eq!(whole.decode(&[2, 1, 0x04, 0x7E], &mut values), Ok(()));
    assert_eq!(values, [2, 1, 0x047E]);
    assert_eq!(whole.decode(&[2, 1, 0x04], &mut values), Err(length(4, 3)));
    let fixed = PnRecord {
        len: 1,
        entries: &[&FENA_SETTINGS[0]],
        defaults: &[0],
        changeable: &[false],
        ..whole
    };
    let mut value = [9];
    assert_eq!(fixed.decode(&[0], &mut value), Ok(()));
    assert_eq!(value, [0]);
    assert_eq!(
        fixed.decode(&[1], &mut value),
        Err(PrmError::NotAllowed {
            offset: 0,
            value: 1
        })
    );
    assert_eq!(value, [0], "nothing is written when refused");
}

/// FENA's standard telegram 2: record 1 holds the two byte settings, then
/// the fail-safe values of STW1, NSOLL_B (32 bits) and STW2, each at its
/// offset after the entries, high byte first.
#[test]
fn a_device_record_ends_with_its_fail_safe_values() {
    use device::{PnRecord, RecordReading};
    let record = PnRecord {
        index: 1,
        len: 10,
        reading: RecordReading::Whole,
        entries: &[&FENA_SETTINGS[0], &FENA_SETTINGS[1]],
        defaults: &[0, 0],
        changeable: &[true, true],
        fail_safe: &[2, 4, 2],
    };
    let bytes = [2, 1, 0x04, 0x7E, 0x00, 0x01, 0x86, 0xA0, 0xAB, 0xCD];
    let mut settings = [9; 2];
    assert_eq!(record.decode(&bytes, &mut settings), Ok(()));
    assert_eq!(settings, [2, 1]);
    let mut values = [9; 3];
    assert_eq!(record.decode_fail_safe(&bytes, &mut values), Ok(()));
    assert_eq!(values, [0x047E, 100_000, 0xABCD]);
    assert_eq!(
        record.decode_fail_safe(&bytes[..9], &mut values),
        Err(length(10, 9))
    );
    assert_eq!(
        values,
        [0x047E, 100_000, 0xABCD],
        "nothing is written when refused"
    );
}

/// SEW MOVI-C's records of a port and of its access point: record 9001's
/// two Unsigned32 thresholds, high byte first; record 8200's alarm bit
/// (0 or 1) in bit 0, beside a bit area of bits 4 to 6 that holds 1 to 5
/// and a byte nobody may change from its default 1.
#[test]
fn an_access_point_record_reads_whole_values_and_bits() {
    use device::{PnRecordValue, PnSubmoduleRecord};
    const THRESHOLDS: [PnRecordValue; 2] = [record_value(0, 4, (0, 7)), record_value(4, 4, (0, 7))];
    let thresholds = PnSubmoduleRecord {
        index: 9001,
        len: 8,
        values: &THRESHOLDS,
    };
    let mut out = [9; 2];
    let bytes = [0, 0, 0, 10, 0x00, 0x01, 0x86, 0xA0];
    assert_eq!(thresholds.decode(&bytes, &mut out), Ok(()));
    assert_eq!(out, [10, 100_000]);
    assert_eq!(thresholds.decode(&bytes[..7], &mut out), Err(length(8, 7)));
    const ALARMS: [PnRecordValue; 3] = [
        PnRecordValue {
            max: 1,
            values: &[0, 1],
            ..record_value(0, 0, (0, 0))
        },
        PnRecordValue {
            min: 1,
            max: 5,
            default_value: 2,
            ..record_value(0, 0, (4, 6))
        },
        PnRecordValue {
            default_value: 1,
            changeable: false,
            ..record_value(1, 1, (0, 7))
        },
    ];
    let alarms = PnSubmoduleRecord {
        index: 8200,
        len: 2,
        values: &ALARMS,
    };
    let mut out = [9; 3];
    // Bit 0 set, bits 4 to 6 = 5, bit 7 and bits 1 to 3 no value's.
    assert_eq!(alarms.decode(&[0b0101_0001, 1], &mut out), Ok(()));
    assert_eq!(out, [1, 5, 1]);
    assert_eq!(
        alarms.decode(&[0b0110_0000, 1], &mut out),
        Err(not_allowed(0, 6)),
        "bits 4 to 6 hold 6, above 5"
    );
    assert_eq!(
        alarms.decode(&[0b0001_0000, 2], &mut out),
        Err(not_allowed(1, 2)),
        "the fixed byte changed"
    );
    assert_eq!(out, [1, 5, 1], "nothing is written when refused");
}

/// A value of a record of the access point or a port: whole bytes, or
/// bits of one byte when `bytes` is 0; any value, changeable.
const fn record_value(offset: usize, bytes: usize, bits: (u8, u8)) -> device::PnRecordValue {
    device::PnRecordValue {
        name: "value",
        offset,
        bytes,
        first_bit: bits.0,
        last_bit: bits.1,
        default_value: 0,
        min: 0,
        max: u32::MAX,
        values: &[],
        changeable: true,
    }
}

mod md810 {
    use super::pke_ind_pwe::*;
    use super::pkw;

    const F0_08: u16 = 0xF008;

    /// Manual 1.4.2, figure 6: read F0-08, the answer 50.00 Hz.
    #[test]
    fn read_f0_08() {
        let request = pkw("10F0 0800 0000 0000");
        assert_eq!(
            PkwRequest::decode(&request),
            Ok(PkwRequest::Read { address: F0_08 })
        );
        assert_eq!(PkwRequest::Read { address: F0_08 }.encode(), request);
        let answer = pkw("10F0 0800 0000 1388");
        let done = PkwResponse::Done {
            address: F0_08,
            value: 5000,
        };
        assert_eq!(PkwResponse::decode(&answer), Ok(done));
        assert_eq!(done.encode(), answer);
    }

    /// Manual 1.4.2, figure 7: write 20.00 Hz to F0-08; the answer echoes it.
    #[test]
    fn write_f0_08() {
        let write = PkwRequest::Write {
            address: F0_08,
            value: 2000,
        };
        assert_eq!(write.encode(), pkw("20F0 0800 0000 07D0"));
        assert_eq!(PkwRequest::decode(&pkw("20F0 0800 0000 07D0")), Ok(write));
        let done = PkwResponse::Done {
            address: F0_08,
            value: 2000,
        };
        assert_eq!(PkwResponse::decode(&pkw("10F0 0800 0000 07D0")), Ok(done));
    }

    #[test]
    fn cannot_execute_with_each_error_code() {
        let codes = [
            PkwErrorCode::IllegalCommand,
            PkwErrorCode::IllegalAddress,
            PkwErrorCode::IllegalData,
            PkwErrorCode::Other,
        ];
        for (error, code) in codes.into_iter().zip(1..) {
            let answer = pkw(&format!("70F0 0800 0000 000{code}"));
            let failed = PkwResponse::Failed {
                address: F0_08,
                error,
            };
            assert_eq!(PkwResponse::decode(&answer), Ok(failed));
            assert_eq!(failed.encode(), answer);
            assert_eq!(PkwErrorCode::from_code(error.code()), Some(error));
        }
        let unknown = PkwResponse::decode(&pkw("70F0 0800 0000 0005"));
        assert_eq!(unknown, Err(PkwDecodeError::UnknownErrorCode(5)));
    }

    #[test]
    fn no_request_ignores_what_the_master_left() {
        assert_eq!(PkwRequest::None.encode(), pkw("0000 0000 0000 0000"));
        assert_eq!(
            PkwRequest::decode(&pkw("00F0 0800 0000 1388")),
            Ok(PkwRequest::None)
        );
        assert_eq!(PkwResponse::None.encode(), pkw("0000 0000 0000 0000"));
        assert_eq!(
            PkwResponse::decode(&pkw("0000 0000 0000 0000")),
            Ok(PkwResponse::None)
        );
    }

    #[test]
    fn reserved_bits_are_not_read() {
        let request = PkwRequest::decode(&pkw("1FF0 08FF FFFF 0000"));
        assert_eq!(request, Ok(PkwRequest::Read { address: F0_08 }));
    }

    #[test]
    fn illegal_commands_and_codes_are_refused() {
        let illegal = PkwDecodeError::IllegalCommand {
            command: 3,
            address: F0_08,
        };
        assert_eq!(
            PkwRequest::decode(&pkw("30F0 0800 0000 0000")),
            Err(illegal)
        );
        assert_eq!(
            PkwResponse::decode(&pkw("20F0 0800 0000 0000")),
            Err(PkwDecodeError::UnknownResponse(2))
        );
        assert_eq!(PkwErrorCode::from_code(0), None);
    }
}

mod mv810 {
    use super::pkw;
    use super::station_command::*;

    /// P43.02 by the description's numbering: group 43 in the high byte.
    const P43_02: u16 = 0x2B02;
    const TO_DRIVE_1: Stations = Stations {
        target: 1,
        source: 0,
    };
    const FROM_DRIVE_1: Stations = Stations {
        target: 0,
        source: 1,
    };

    #[test]
    fn read_p43_02() {
        let read = PkwRequest {
            stations: TO_DRIVE_1,
            address: P43_02,
            access: PkwAccess::Read,
        };
        assert_eq!(read.encode(), pkw("0100 0003 2B02 0001"));
        assert_eq!(PkwRequest::decode(&pkw("0100 0003 2B02 0001")), Ok(read));
        let value = PkwResponse {
            stations: FROM_DRIVE_1,
            address: P43_02,
            reply: PkwReply::Value(1),
        };
        assert_eq!(value.encode(), pkw("0001 0003 2B02 0001"));
        assert_eq!(PkwResponse::decode(&pkw("0001 0003 2B02 0001")), Ok(value));
    }

    #[test]
    fn write_p43_02_with_and_without_storing() {
        for (access, code, reply) in [
            (
                PkwAccess::WriteAndStore { value: 1 },
                "0006",
                PkwReply::WrittenAndStored,
            ),
            (PkwAccess::Write { value: 1 }, "0007", PkwReply::Written),
        ] {
            let write = PkwRequest {
                stations: TO_DRIVE_1,
                address: P43_02,
                access,
            };
            let telegram = pkw(&format!("0100 {code} 2B02 0001"));
            assert_eq!(write.encode(), telegram);
            assert_eq!(PkwRequest::decode(&telegram), Ok(write));
            let written = PkwResponse {
                stations: FROM_DRIVE_1,
                address: P43_02,
                reply,
            };
            let answer = pkw(&format!("0001 {code} 2B02 0000"));
            assert_eq!(written.encode(), answer);
            assert_eq!(PkwResponse::decode(&answer), Ok(written));
        }
    }

    #[test]
    fn errors_reply_0x80_plus_the_command() {
        let failed = PkwReply::Failed {
            command: PkwCommand::Write,
            error: 2,
        };
        let response = PkwResponse {
            stations: FROM_DRIVE_1,
            address: P43_02,
            reply: failed,
        };
        assert_eq!(response.encode(), pkw("0001 0087 2B02 0002"));
        assert_eq!(
            PkwResponse::decode(&pkw("0001 0087 2B02 0002")),
            Ok(response)
        );
    }

    #[test]
    fn commands_the_manual_does_not_list_are_refused() {
        assert_eq!(
            PkwRequest::decode(&pkw("0100 0000 0000 0000")),
            Err(PkwDecodeError::UnknownCommand(0))
        );
        assert_eq!(
            PkwRequest::decode(&pkw("0100 0083 2B02 0001")),
            Err(PkwDecodeError::UnknownCommand(0x83))
        );
        assert_eq!(
            PkwResponse::decode(&pkw("0001 0085 2B02 0001")),
            Err(PkwDecodeError::UnknownCommand(0x85))
        );
        assert_eq!(
            PkwResponse::decode(&pkw("0001 0103 2B02 0001")),
            Err(PkwDecodeError::UnknownCommand(0x103))
        );
    }

    #[test]
    fn a_read_is_of_one_parameter() {
        assert_eq!(
            PkwRequest::decode(&pkw("0100 0003 2B02 0002")),
            Err(PkwDecodeError::ReadCount(2))
        );
    }

    #[test]
    fn command_codes() {
        for command in [
            PkwCommand::Read,
            PkwCommand::WriteAndStore,
            PkwCommand::Write,
        ] {
            assert_eq!(PkwCommand::from_code(command.code()), Some(command));
        }
        assert_eq!(PkwAccess::Write { value: 0 }.command(), PkwCommand::Write);
    }
}

mod profidrive_channel {
    use super::pkw;
    use super::profidrive::*;

    /// P10.05 by a decimal numbering: PNU 1005, 0x3ED.
    fn p10_05(subindex: u8) -> Parameter {
        Parameter {
            pnu: Pnu::new(1005).unwrap(),
            subindex,
        }
    }

    /// PKE = AK << 12 | PNU: request 1 for PNU 1005 is 0x13ED; IND's low
    /// byte and PWE are 0.
    #[test]
    fn read_pnu_1005() {
        let read = PkwRequest::Read {
            parameter: p10_05(0),
        };
        assert_eq!(read.encode(), pkw("13ED 0000 0000 0000"));
        assert_eq!(PkwRequest::decode(&pkw("13ED 0000 0000 0000")), Ok(read));
        let answer = PkwResponse::Word {
            parameter: p10_05(0),
            value: 5000,
        };
        assert_eq!(answer.encode(), pkw("13ED 0000 0000 1388"));
        assert_eq!(PkwResponse::decode(&pkw("13ED 0000 0000 1388")), Ok(answer));
    }

    /// A word goes in PWE2, a double word high word first in PWE1.
    #[test]
    fn words_in_pwe2_double_words_across_both() {
        let word = PkwRequest::WriteWord {
            parameter: p10_05(0),
            value: 0x07D0,
        };
        assert_eq!(word.encode(), pkw("23ED 0000 0000 07D0"));
        assert_eq!(PkwRequest::decode(&pkw("23ED 0000 0000 07D0")), Ok(word));
        let double = PkwRequest::WriteDoubleWord {
            parameter: p10_05(0),
            value: 0x0001_86A0,
        };
        assert_eq!(double.encode(), pkw("33ED 0000 0001 86A0"));
        assert_eq!(PkwRequest::decode(&pkw("33ED 0000 0001 86A0")), Ok(double));
        let answer = PkwResponse::DoubleWord {
            parameter: p10_05(0),
            value: 100_000,
        };
        assert_eq!(answer.encode(), pkw("23ED 0000 0001 86A0"));
        assert_eq!(PkwResponse::decode(&pkw("23ED 0000 0001 86A0")), Ok(answer));
        // PWE1 of a word is not read.
        assert_eq!(
            PkwResponse::decode(&pkw("13ED 0000 FFFF 1388")),
            Ok(PkwResponse::Word {
                parameter: p10_05(0),
                value: 5000
            })
        );
    }

    /// The subindex is IND's high byte; its low byte is written 0, not read.
    #[test]
    fn the_subindex_is_the_high_byte_of_ind() {
        let element = PkwRequest::WriteArrayWord {
            parameter: p10_05(2),
            value: 7,
        };
        assert_eq!(element.encode(), pkw("73ED 0200 0000 0007"));
        assert_eq!(PkwRequest::decode(&pkw("73ED 02FF 0000 0007")), Ok(element));
        let answer = PkwResponse::ArrayWord {
            parameter: p10_05(2),
            value: 7,
        };
        assert_eq!(answer.encode(), pkw("43ED 0200 0000 0007"));
        let length = PkwResponse::ArrayLength {
            parameter: p10_05(0),
            count: 3,
        };
        assert_eq!(length.encode(), pkw("63ED 0000 0000 0003"));
        assert_eq!(PkwResponse::decode(&pkw("63ED 0000 0000 0003")), Ok(length));
    }

    /// Every request and response id of the profile, both ways.
    #[test]
    fn each_profile_id_round_trips() {
        let p = p10_05(1);
        let requests = [
            PkwRequest::None,
            PkwRequest::Read { parameter: p },
            PkwRequest::WriteWord {
                parameter: p,
                value: 1,
            },
            PkwRequest::WriteDoubleWord {
                parameter: p,
                value: 0x1_0001,
            },
            PkwRequest::ReadDescription { parameter: p },
            PkwRequest::WriteDescription {
                parameter: p,
                value: 2,
            },
            PkwRequest::ReadArray { parameter: p },
            PkwRequest::WriteArrayWord {
                parameter: p,
                value: 3,
            },
            PkwRequest::WriteArrayDoubleWord {
                parameter: p,
                value: 4,
            },
            PkwRequest::ReadArrayLength { parameter: p },
        ];
        for (request, id) in requests.into_iter().zip(0u16..) {
            let words = request.encode();
            assert_eq!(words[0].get() >> 12, id, "{request:?}");
            assert_eq!(u16::from(request.id()), id);
            assert_eq!(PkwRequest::decode(&words), Ok(request));
        }
        let responses = [
            PkwResponse::None,
            PkwResponse::Word {
                parameter: p,
                value: 1,
            },
            PkwResponse::DoubleWord {
                parameter: p,
                value: 0x2_0000,
            },
            PkwResponse::Description {
                parameter: p,
                value: 3,
            },
            PkwResponse::ArrayWord {
                parameter: p,
                value: 4,
            },
            PkwResponse::ArrayDoubleWord {
                parameter: p,
                value: 5,
            },
            PkwResponse::ArrayLength {
                parameter: p,
                count: 6,
            },
            PkwResponse::Failed {
                parameter: p,
                error: PkwErrorNumber::OPERATING_STATE,
            },
            PkwResponse::NoAuthority { parameter: p },
        ];
        for (response, id) in responses.into_iter().zip(0u16..) {
            let words = response.encode();
            assert_eq!(words[0].get() >> 12, id, "{response:?}");
            assert_eq!(u16::from(response.id()), id);
            assert_eq!(PkwResponse::decode(&words), Ok(response));
        }
    }

    /// Response 7 carries the error number in PWE2, any number: a drive's
    /// own are beyond the profile's.
    #[test]
    fn cannot_execute_with_the_error_number_in_pwe2() {
        let failed = PkwResponse::Failed {
            parameter: p10_05(0),
            error: PkwErrorNumber::LIMIT_EXCEEDED,
        };
        assert_eq!(failed.encode(), pkw("73ED 0000 0000 0002"));
        assert_eq!(PkwResponse::decode(&pkw("73ED 0000 0000 0002")), Ok(failed));
        let own = PkwResponse::decode(&pkw("73ED 0000 0000 00C8"));
        assert_eq!(
            own,
            Ok(PkwResponse::Failed {
                parameter: p10_05(0),
                error: PkwErrorNumber(200)
            })
        );
        let numbers = [
            PkwErrorNumber::ILLEGAL_PNU,
            PkwErrorNumber::NOT_CHANGEABLE,
            PkwErrorNumber::LIMIT_EXCEEDED,
            PkwErrorNumber::BAD_SUBINDEX,
            PkwErrorNumber::NO_ARRAY,
            PkwErrorNumber::WRONG_TYPE,
            PkwErrorNumber::SETTING_NOT_ALLOWED,
            PkwErrorNumber::DESCRIPTION_NOT_CHANGEABLE,
            PkwErrorNumber::NO_MASTER_CONTROL,
            PkwErrorNumber::KEY_WORD_MISSING,
            PkwErrorNumber::OPERATING_STATE,
        ];
        assert_eq!(numbers.map(|n| n.0), [0, 1, 2, 3, 4, 5, 6, 7, 11, 12, 17]);
    }

    /// Request 10 is reserved, 11 to 15 are Siemens': refused, with the
    /// parameter the drive answers about.
    #[test]
    fn ids_beyond_the_profile_are_refused() {
        for id in 10..=15u8 {
            let request = pkw(&format!("{id:X}3ED 0100 0000 0001"));
            assert_eq!(
                PkwRequest::decode(&request),
                Err(PkwDecodeError::IllegalRequest {
                    id,
                    parameter: p10_05(1)
                })
            );
        }
        for id in 9..=12u8 {
            let report = pkw(&format!("{id:X}3ED 0000 0000 0001"));
            assert_eq!(
                PkwResponse::decode(&report),
                Err(PkwDecodeError::ChangeReport { id })
            );
        }
        for id in 13..=15u8 {
            let response = pkw(&format!("{id:X}3ED 0000 0000 0001"));
            assert_eq!(
                PkwResponse::decode(&response),
                Err(PkwDecodeError::UnknownResponse { id })
            );
        }
    }

    /// PKE holds 11 bits of PNU; SPM (bit 11) is written 0 and not read.
    #[test]
    fn the_pnu_has_11_bits_and_spm_is_not_read() {
        assert_eq!(Pnu::new(PNU_MAX).map(Pnu::get), Some(2047));
        assert_eq!(Pnu::new(2048), None);
        let top = Parameter {
            pnu: Pnu::new(2047).unwrap(),
            subindex: 0,
        };
        assert_eq!(
            PkwRequest::Read { parameter: top }.encode(),
            pkw("17FF 0000 0000 0000")
        );
        assert_eq!(
            PkwRequest::decode(&pkw("1BED 0000 0000 0000")),
            Ok(PkwRequest::Read {
                parameter: p10_05(0)
            })
        );
    }

    #[test]
    fn no_request_ignores_what_the_master_left() {
        assert_eq!(PkwRequest::None.encode(), pkw("0000 0000 0000 0000"));
        assert_eq!(
            PkwRequest::decode(&pkw("03ED 0200 1234 5678")),
            Ok(PkwRequest::None)
        );
        assert_eq!(PkwResponse::None.encode(), pkw("0000 0000 0000 0000"));
        assert_eq!(PkwRequest::None.parameter(), None);
    }
}

mod diagnosis {
    use crate::emit::rust::support::diagnosis::DiagArea;

    /// MD810 (1.8): header 3, then the fault code's high and low byte; the
    /// low byte is bits 8..15.
    #[test]
    fn an_area_is_its_bits_counted_from_the_byte_after_the_header() {
        let low_byte = DiagArea::new(8, 15);
        let mut block = [3, 0, 0];
        low_byte.set(&mut block, 0x34);
        assert_eq!(block, [3, 0, 0x34]);
        assert_eq!(low_byte.get(&block), 0x34);
        assert_eq!(low_byte.block_len(), 3);
        // Two bits in the middle of the first byte, the rest untouched.
        let mode = DiagArea::new(2, 3);
        let mut block = [3, 0xFF, 0xFF];
        mode.set(&mut block, 0b01);
        assert_eq!(block, [3, 0b1111_0111, 0xFF]);
        assert_eq!(mode.get(&block), 0b01);
        // Bits of the value beyond the area are dropped.
        mode.set(&mut block, 0b110);
        assert_eq!(mode.get(&block), 0b10);
    }

    #[test]
    fn an_area_across_two_bytes_has_its_first_bit_lowest() {
        let word = DiagArea::new(4, 11);
        let mut block = [3, 0, 0];
        word.set(&mut block, 0xAB);
        assert_eq!(block, [3, 0xB0, 0x0A]);
        assert_eq!(word.get(&block), 0xAB);
        assert_eq!(word.block_len(), 3);
    }

    #[test]
    fn a_block_too_short_loses_the_bits_past_its_end() {
        let low_byte = DiagArea::new(8, 15);
        let mut block = [3, 0];
        low_byte.set(&mut block, 0x34);
        assert_eq!(block, [3, 0]);
        assert_eq!(low_byte.get(&block), 0);
    }
}

/// MV810's "PKW + 3 PZD" module: its PZD record holds PZD2 and PZD3 of the
/// eleven mappings; the rest keep their defaults.
#[test]
fn a_record_prefix_holds_the_words_its_module_transports() {
    const ALLOWED: Allowed = Allowed::Range { min: 0, max: 14 };
    let mapping = |number| Mapping {
        name: "PZD receive",
        number,
        default: 0,
        parameter: None,
        allowed: ALLOWED,
        bytes: 2,
    };
    let mappings = [mapping(2), mapping(3), mapping(4)];
    assert_eq!(read_record_prefix(&[0, 1, 0, 3], &mappings), Ok([1, 3, 0]));
    assert_eq!(read_record_prefix(&[], &mappings), Ok([0, 0, 0]));
    assert_eq!(
        read_record_prefix(&[0, 1, 0], &mappings),
        Err(PrmError::Length {
            expected: 6,
            found: 3
        })
    );
    assert_eq!(
        read_record_prefix(&[0; 8], &mappings),
        Err(PrmError::Length {
            expected: 6,
            found: 8
        })
    );
    assert_eq!(
        read_record_prefix(&[0, 1, 0, 15], &mappings),
        Err(PrmError::NotAllowed {
            offset: 2,
            value: 15
        })
    );
}
