//! The manuals' telegram examples, byte for byte, through the generated
//! layouts: decoded into the layout's types and encoded back.

use gsdc_firmware_check::{md810dp, mv810_pnet02, powtran_9kdp1};

/// `"10F0 0800 0000 1388"`, as the manuals print telegrams: hex words.
fn bytes<const N: usize>(hex: &str) -> [u8; N] {
    let bytes: Vec<u8> = hex
        .split_whitespace()
        .flat_map(|w| u16::from_str_radix(w, 16).unwrap().to_be_bytes())
        .collect();
    bytes.try_into().unwrap()
}

mod md810 {
    use super::*;
    use md810dp::*;

    /// F0-08, by the manual's numbering (1.4.2, figure 6: PKE low byte F0,
    /// IND high byte 08): (0xF0 + x) * 256 + yy, yy decimal.
    const F0_08: u16 = 0xF008;

    /// A PPO1 telegram carrying `pkw` and two PZD words.
    fn ppo1(pkw: &str) -> [u8; 12] {
        bytes(&format!("{pkw} 0001 1388"))
    }

    /// Manual 1.4.2, figure 6: the master reads F0-08.
    #[test]
    fn read_f0_08() {
        let telegram = ppo1("10F0 0800 0000 0000");
        let out = Ppo1Out::from_bytes(&telegram);
        assert_eq!(
            PkwRequest::decode(&out.pkw),
            Ok(PkwRequest::Read { address: F0_08 })
        );
        assert_eq!(out.pzd.map(|w| w.get()), [0x0001, 0x1388]);
        assert_eq!(out.to_bytes(), telegram);
        assert_eq!(PkwRequest::Read { address: F0_08 }.encode(), out.pkw);
    }

    /// Figure 6: the drive answers 5000, 50.00 Hz.
    #[test]
    fn answer_50_hz() {
        let telegram = ppo1("10F0 0800 0000 1388");
        let done = PkwResponse::Done {
            address: F0_08,
            value: 5000,
        };
        let answer = Ppo1In::from_bytes(&telegram);
        assert_eq!(PkwResponse::decode(&answer.pkw), Ok(done));
        let sent = Ppo1In {
            pkw: done.encode(),
            pzd: answer.pzd,
        };
        assert_eq!(sent.to_bytes(), telegram);
    }

    /// Figure 7: the master writes 20.00 Hz to F0-08.
    #[test]
    fn write_20_hz() {
        let telegram = ppo1("20F0 0800 0000 07D0");
        let write = PkwRequest::Write {
            address: F0_08,
            value: 2000,
        };
        let out = Ppo1Out::from_bytes(&telegram);
        assert_eq!(PkwRequest::decode(&out.pkw), Ok(write));
        assert_eq!(
            Ppo1Out {
                pkw: write.encode(),
                pzd: out.pzd
            }
            .to_bytes(),
            telegram
        );
    }

    /// Figures 6 and 7: "cannot execute", with error codes 1 to 4.
    #[test]
    fn error_answers() {
        let errors = [
            PkwErrorCode::IllegalCommand,
            PkwErrorCode::IllegalAddress,
            PkwErrorCode::IllegalData,
            PkwErrorCode::Other,
        ];
        for (x, error) in (1..=4).zip(errors) {
            let telegram = ppo1(&format!("70F0 0800 0000 000{x}"));
            let failed = PkwResponse::Failed {
                address: F0_08,
                error,
            };
            let answer = Ppo1In::from_bytes(&telegram);
            assert_eq!(PkwResponse::decode(&answer.pkw), Ok(failed));
            assert_eq!(
                Ppo1In {
                    pkw: failed.encode(),
                    pzd: answer.pzd
                }
                .to_bytes(),
                telegram
            );
        }
    }

    #[test]
    fn illegal_telegrams_are_refused() {
        let out = Ppo1Out::from_bytes(&ppo1("30F0 0800 0000 0000"));
        let illegal = PkwDecodeError::IllegalCommand {
            command: 3,
            address: F0_08,
        };
        assert_eq!(PkwRequest::decode(&out.pkw), Err(illegal));
        let answer = Ppo1In::from_bytes(&ppo1("70F0 0800 0000 0009"));
        assert_eq!(
            PkwResponse::decode(&answer.pkw),
            Err(PkwDecodeError::UnknownErrorCode(9))
        );
    }

    /// MD810's PPO5: the PKW and 12 PZD words, 32 bytes (1.3.1).
    #[test]
    fn ppo5_is_32_bytes() {
        let telegram: [u8; 32] = bytes(
            "10F0 0800 0000 0000 0001 0002 0003 0004 0005 0006 0007 0008 0009 000A 000B 000C",
        );
        let out = Ppo5Out::from_bytes(&telegram);
        assert_eq!(
            PkwRequest::decode(&out.pkw),
            Ok(PkwRequest::Read { address: F0_08 })
        );
        assert_eq!(
            out.pzd.map(|w| w.get()),
            core::array::from_fn(|i| i as u16 + 1)
        );
        assert_eq!(out.to_bytes(), telegram);
        assert_eq!(Ppo5In::from_bytes(&telegram).to_bytes(), telegram);
        assert_eq!(core::mem::size_of::<Ppo5Out>(), 32);
        assert_eq!(core::mem::align_of::<Ppo5Out>(), 1);
    }

    /// The config identifiers of the PPO table (FIELDBUS-NOTES §1).
    #[test]
    fn ppo_config_bytes() {
        assert_eq!(PPO1_CONFIG, [0xF3, 0xF1]);
        assert_eq!(PPO2_CONFIG, [0xF3, 0xF5]);
        assert_eq!(PPO3_CONFIG, [0xF1]);
        assert_eq!(PPO4_CONFIG, [0xF5]);
        assert_eq!(PPO5_CONFIG, [0xF3, 0xFB]);
    }

    /// The GSD's Max_User_Prm_Data_Len, read from the GSD generated beside
    /// the layout.
    fn gsd_user_prm_len() -> usize {
        let gsd = include_str!(concat!(env!("OUT_DIR"), "/MD810DP.GSD"));
        let line = gsd
            .lines()
            .find(|l| l.starts_with("Max_User_Prm_Data_Len"))
            .expect("the GSD gives Max_User_Prm_Data_Len");
        line.split('=').nth(1).unwrap().trim().parse().unwrap()
    }

    /// The parameter telegram with the GSD's defaults: the DPV1 status bytes,
    /// then F0-00 for each of PZD1..12 out, PZD1..12 in and Index0..5 (1.6).
    #[test]
    fn default_user_prm_is_f0_00_everywhere() {
        let mut telegram = vec![0x00, 0x00, 0x00];
        telegram.extend([0xF0, 0x00].repeat(30));
        assert_eq!(telegram.len(), gsd_user_prm_len());
        let prm = decode_user_prm(&telegram).unwrap();
        assert_eq!(prm.dpv1_status, USER_PRM_DPV1_STATUS);
        assert_eq!(prm.pzd_out, [0xF000; 12]);
        assert_eq!(prm.pzd_in, [0xF000; 12]);
        assert_eq!(prm.dpv1_index, [0xF000; 6]);
        assert_eq!(
            (pzd_out::DEFAULTS, pzd_in::DEFAULTS, dpv1_index::DEFAULTS),
            (prm.pzd_out, prm.pzd_in, prm.dpv1_index)
        );
    }

    /// The manual's example (1.6 step 5): Index0 = F0-02, Index1 = F0-08.
    #[test]
    fn user_prm_maps_dpv1_indexes() {
        let mut telegram = [0; USER_PRM_LEN];
        let at = dpv1_index::USER_PRM_OFFSET;
        telegram[at..at + 4].copy_from_slice(&[0xF0, 0x02, 0xF0, 0x08]);
        let prm = decode_user_prm(&telegram).unwrap();
        assert_eq!(prm.dpv1_index, [0xF002, 0xF008, 0, 0, 0, 0]);
        let short = decode_user_prm(&telegram[1..]);
        assert_eq!(
            short,
            Err(PrmError::Length {
                expected: 63,
                found: 62
            })
        );
    }

    /// A line of the GSD generated beside the layout: what follows `key`
    /// and `=`.
    fn gsd_value(key: &str) -> String {
        let gsd = include_str!(concat!(env!("OUT_DIR"), "/MD810DP.GSD"));
        let line = gsd
            .lines()
            .find(|l| l.starts_with(key))
            .unwrap_or_else(|| panic!("the GSD has {key}"));
        line.split_once('=').unwrap().1.trim().to_string()
    }

    /// Manual 1.8: when the communication between the DP card and the
    /// drive is interrupted the device-related diagnosis is header 3, then
    /// 0x00 0x34; the GSD says the same (Unit_Diag_Area = 8-15 with
    /// Value(52)) and its length.
    #[test]
    fn card_lost_the_drive_diagnosis() {
        let mut block = diagnosis::EMPTY;
        let lost = diagnosis::Bits8To15::DpCardDriveCommInterrupted;
        diagnosis::BITS_8_15.set(&mut block, lost.value());
        assert_eq!(block, [0x03, 0x00, 0x34]);
        assert_eq!(
            diagnosis::Bits8To15::from_value(diagnosis::BITS_8_15.get(&block)),
            Some(lost)
        );
        assert_eq!(gsd_value("Unit_Diag_Area"), "8-15");
        assert_eq!(
            gsd_value("Value(52)"),
            "\"DP card-drive comm. interrupted\""
        );
        let max_diag: usize = gsd_value("Max_Diag_Data_Len").parse().unwrap();
        assert_eq!(max_diag, 6 + diagnosis::LEN);
    }

    #[test]
    fn dpv1_indexes_as_a_profinet_record() {
        assert_eq!(dpv1_index::RECORD_LEN, 12);
        let record = bytes::<12>("F002 F008 F000 F000 F000 F000");
        assert_eq!(
            dpv1_index::decode_record(&record),
            Ok([0xF002, 0xF008, 0xF000, 0xF000, 0xF000, 0xF000])
        );
        assert!(dpv1_index::decode_record(&record[2..]).is_err());
    }

    /// Manual 1.7: an index's record is one function code, 2 bytes
    /// ("MLEN ... 只能为 2"), as SFB52 reads F0-02 into QW6; the GSD's
    /// C1_Max_Data_Len says the same.
    #[test]
    fn dpv1_records_are_2_bytes() {
        assert_eq!(dpv1_index::RECORD_DATA_LEN, 2);
        assert_eq!(dpv1_index::check_record_data(&[0x13, 0x88]), Ok(()));
        assert_eq!(
            dpv1_index::check_record_data(&[0x13, 0x88, 0x00]),
            Err(PrmError::Length {
                expected: 2,
                found: 3
            })
        );
        assert_eq!(gsd_value("C1_Max_Data_Len"), "2");
    }
}

mod mv810 {
    use super::*;
    use mv810_pnet02::*;

    /// P43.02, the parameter that says what PZD2 from the master means.
    fn p43_02() -> u16 {
        pzd_out::MAPPINGS[0].parameter.unwrap()
    }

    /// Section 3: the PN master reads P43.02 of the drive with the card,
    /// station 1, through a 12-PZD telegram with the PKW channel.
    #[test]
    fn read_p43_02() {
        assert_eq!(p43_02(), 0x2B02);
        let stations = Stations {
            target: 1,
            source: 0,
        };
        let telegram: [u8; 32] = bytes(&format!("0100 0003 2B02 0001{}", " 0000".repeat(12)));
        let out = PkwPzd12Out::from_bytes(&telegram);
        let read = PkwRequest {
            stations,
            address: p43_02(),
            access: PkwAccess::Read,
        };
        assert_eq!(PkwRequest::decode(&out.pkw), Ok(read));
        assert_eq!(
            PkwPzd12Out {
                pkw: read.encode(),
                pzd: out.pzd
            }
            .to_bytes(),
            telegram
        );

        // The drive answers 1: PZD2 carries the frequency reference.
        let answer: [u8; 32] = bytes(&format!("0001 0003 2B02 0001{}", " 0000".repeat(12)));
        let value = PkwResponse::decode(&PkwPzd12In::from_bytes(&answer).pkw).unwrap();
        assert_eq!(
            value.reply,
            PkwReply::Value(pzd_out::Choice::FrequencyReference.value())
        );
        assert_eq!(
            PkwPzd12In {
                pkw: value.encode(),
                pzd: Default::default()
            }
            .to_bytes(),
            answer
        );
    }

    /// Section 3: write P43.02 = 1, once without storing it (0x07), once
    /// into EEPROM (0x06); the drive replies with the command and value 0.
    #[test]
    fn write_p43_02() {
        let stations = Stations {
            target: 1,
            source: 0,
        };
        let writes = [
            ("0007", PkwAccess::Write { value: 1 }, PkwReply::Written),
            (
                "0006",
                PkwAccess::WriteAndStore { value: 1 },
                PkwReply::WrittenAndStored,
            ),
        ];
        for (command, access, written) in writes {
            let telegram: [u8; 8] = bytes(&format!("0100 {command} 2B02 0001"));
            let out = PkwPzd1Out::from_bytes(&bytes(&format!("0100 {command} 2B02 0001 0001")));
            let write = PkwRequest {
                stations,
                address: p43_02(),
                access,
            };
            assert_eq!(PkwRequest::decode(&out.pkw), Ok(write));
            assert_eq!(out.to_bytes()[..8], telegram);
            let reply = bytes::<8>(&format!("0001 {command} 2B02 0000"));
            let answer = PkwPzd1In::from_bytes(&bytes(&format!("0001 {command} 2B02 0000 0000")));
            let decoded = PkwResponse::decode(&answer.pkw).unwrap();
            assert_eq!((decoded.address, decoded.reply), (p43_02(), written));
            assert_eq!(answer.to_bytes()[..8], reply);
            assert_eq!(
                PkwPzd1In {
                    pkw: decoded.encode(),
                    pzd: answer.pzd
                }
                .to_bytes()[..8],
                reply
            );
        }
    }

    /// Section 3: an error reply is 0x80 + the command.
    #[test]
    fn error_reply() {
        let reply = bytes::<10>("0001 0087 2B02 0003 0000");
        let answer = PkwPzd1In::from_bytes(&reply);
        let failed = PkwReply::Failed {
            command: PkwCommand::Write,
            error: 3,
        };
        assert_eq!(
            PkwResponse::decode(&answer.pkw).map(|r| r.reply),
            Ok(failed)
        );
        assert_eq!(
            PkwRequest::decode(&answer.pkw),
            Err(PkwDecodeError::UnknownCommand(0x87))
        );
    }

    /// Section 3, PZD1: control word bits and the status word's control mode.
    #[test]
    fn control_and_status_words() {
        let run = control_word::FORWARD_RUNNING.mask() | control_word::FAULT_RESET.mask();
        assert_eq!(run, 0x0041);
        let status = 0b100_0010_0001; // forward running, ready, communication
        assert!(status_word::FORWARD_RUNNING.is_set(status));
        assert!(status_word::READY_STATUS.is_set(status));
        assert_eq!(
            status_word::ControlMode::from_word(status),
            Some(status_word::ControlMode::Communication)
        );
        assert_eq!(
            status_word::ControlMode::Terminal.to_word(status),
            0b010_0010_0001
        );
        assert_eq!(
            status_word::MotorType::from_word(status),
            Some(status_word::MotorType::Asynchronous)
        );
    }

    #[test]
    fn standard_telegram_1_is_two_words() {
        let telegram = bytes::<4>("047F 4000");
        assert_eq!(Telegram1Out::from_bytes(&telegram).to_bytes(), telegram);
        assert_eq!(TELEGRAM1_IDENT, 0x10);
    }

    /// The PZD mappings are P43.02..P43.12 (out) and P43.13..P43.23 (in),
    /// with section 3's choices (15 and 26 values, "15～30：保留" and
    /// "26～30：保留" left out). Section 4 sets them, and P43.01, at the
    /// drive, as function codes: no module carries a parameter record, so
    /// the controller writes nothing at startup and the card keeps what the
    /// keypad set.
    #[test]
    fn mappings_set_at_the_drive() {
        assert_eq!(
            pzd_out::MAPPINGS.map(|m| m.parameter.unwrap() - p43_02()),
            core::array::from_fn(|i| i as u16)
        );
        assert_eq!(pzd_in::MAPPINGS[0].parameter, Some(0x2B0D)); // P43.13
        assert!((0..=14).all(|v| pzd_out::ALLOWED.contains(v)));
        assert!(!pzd_out::ALLOWED.contains(15));
        assert!((0..=25).all(|v| pzd_in::ALLOWED.contains(v)));
        assert!(!pzd_in::ALLOWED.contains(26));
        assert!(settings::ALLOWED.contains(settings::Choice::UserDefinedMessage.value()));
        assert_eq!(settings::DEFAULTS, [1]);
        assert_eq!(PN_DEVICE.modules.len(), 13);
        for module in PN_DEVICE.modules {
            assert!(module.records.is_empty(), "{}", module.name);
        }
    }
}

mod pi9000 {
    use super::*;
    use powtran_9kdp1::*;

    /// Appendix I-3: command 1 is forward run; the card sends it in PZD1.
    #[test]
    fn command_word_in_ppo3() {
        let telegram = bytes::<4>("0001 1388");
        let out = Ppo3Out::from_bytes(&telegram);
        let command = control_word::CommandFunction::from_word(out.pzd[0].get());
        assert_eq!(command, Some(control_word::CommandFunction::ForwardRun));
        assert_eq!(control_word::CommandFunction::FaultReset.value(), 7);
        assert_eq!(
            status_word::StatusWordFunction::from_word(3),
            Some(status_word::StatusWordFunction::Stop)
        );
        assert_eq!(Ppo4In::from_bytes(&[0; 12]).to_bytes(), [0; 12]);
    }

    /// Appendix I: the fault code of 0x8000 in the diagnosis' low byte.
    #[test]
    fn fault_code_diagnosis() {
        let mut block = diagnosis::EMPTY;
        let fault = diagnosis::Bits8To15::MotorOverload;
        diagnosis::BITS_8_15.set(&mut block, fault.value());
        assert_eq!(block, [0x03, 0x00, 11]);
        assert_eq!(diagnosis::Bits8To15::from_value(0x0B), Some(fault));
    }

    /// Without DPV1 the parameter telegram is the mappings alone: PZD2..6
    /// each way, with appendix I's addresses as defaults.
    #[test]
    fn default_user_prm() {
        assert_eq!(USER_PRM_LEN, 20);
        let telegram = bytes::<20>("1000 2001 2002 2003 2004 1001 1002 1004 8000 8001");
        let prm = decode_user_prm(&telegram).unwrap();
        assert_eq!(
            prm,
            UserPrm {
                pzd_out: pzd_out::DEFAULTS,
                pzd_in: pzd_in::DEFAULTS
            }
        );
        assert_eq!(pzd_in::MAPPINGS[3].default, 0x8000);
    }
}

/// The manuals' worked examples as each description gives them
/// (`[[examples]]`), written by the build script.
mod examples {
    include!(concat!(env!("OUT_DIR"), "/examples.rs"));
}

/// A module of the device tables: its name, whether the tables say it
/// carries the PKW channel (`None`: a PROFINET module, whose table does
/// not say), and its bytes each way.
type TableModule = (&'static str, Option<bool>, usize);

fn dp_modules(
    device: &gsdc_firmware_check::gsdc_support::DpDevice,
) -> impl Iterator<Item = TableModule> {
    device
        .modules
        .iter()
        .map(|m| (m.name, Some(m.pkw), m.input_len))
}

fn pn_modules(
    device: &gsdc_firmware_check::gsdc_support::PnDevice,
) -> impl Iterator<Item = TableModule> {
    device
        .modules
        .iter()
        .map(|m| (m.name, None, m.data.input_len))
}

/// Each example of a description through its layout: the module it names
/// is one of the device tables' and as long as its telegram (an example of
/// the PKW words alone: every module the tables give the PKW channel is
/// long enough), and every telegram it stands for goes through the layout's
/// PKW codec (a request out, a response in) and comes back byte for byte.
/// The number of telegrams.
macro_rules! round_trip {
    ($layout:ident, $examples:expr, $modules:expr) => {{
        use $layout::{PkwRequest, PkwResponse, U16Be};
        let modules: Vec<TableModule> = $modules.collect();
        let mut telegrams = 0;
        for example in $examples {
            match example.module {
                Some(name) => {
                    let (_, pkw, len) = *modules
                        .iter()
                        .find(|m| m.0 == name)
                        .unwrap_or_else(|| panic!("{example:?}: no module {name}"));
                    assert_ne!(pkw, Some(false), "{example:?}");
                    for telegram in example.telegrams {
                        let expected = if example.pkw_only { 8 } else { len };
                        assert_eq!(telegram.len(), expected, "{example:?}");
                    }
                }
                None => {
                    let carriers: Vec<_> = modules.iter().filter(|m| m.1 == Some(true)).collect();
                    assert!(!carriers.is_empty(), "{example:?}");
                    assert!(carriers.iter().all(|m| m.2 >= 8), "{example:?}");
                    assert!(
                        example.telegrams.iter().all(|t| t.len() == 8),
                        "{example:?}"
                    );
                }
            }
            for telegram in example.telegrams {
                let words: [U16Be; 4] = core::array::from_fn(|i| {
                    U16Be::new(u16::from_be_bytes([telegram[2 * i], telegram[2 * i + 1]]))
                });
                let at = (example.section, example.printed);
                if example.out {
                    let request = PkwRequest::decode(&words);
                    assert_eq!(request.map(PkwRequest::encode), Ok(words), "{at:?}");
                } else {
                    let response = PkwResponse::decode(&words);
                    assert_eq!(response.map(PkwResponse::encode), Ok(words), "{at:?}");
                }
                telegrams += 1;
            }
        }
        telegrams
    }};
}

/// The examples of every description with a PKW channel; MD810's are
/// 1.4.2's read and write of F0-08, each answered done or failed with one
/// of four error codes: 12 telegrams. The other descriptions' manuals
/// print none (MV810's none, PI9000's only Modbus frames, not DP telegrams).
#[test]
fn every_example_of_the_manuals_round_trips() {
    use gsdc_firmware_check::{md810dp as md810, profidrive};
    let md810_modules = dp_modules(&md810::DP_DEVICE).chain(pn_modules(&md810::PN_DEVICE));
    assert_eq!(
        round_trip!(md810dp, examples::EXAMPLES_MD810DP, md810_modules),
        12
    );
    let mv810_modules = pn_modules(&mv810_pnet02::PN_DEVICE);
    assert_eq!(
        round_trip!(mv810_pnet02, examples::EXAMPLES_MV810_PNET02, mv810_modules),
        0
    );
    let profidrive_modules = dp_modules(&profidrive::DP_DEVICE);
    assert_eq!(
        round_trip!(
            profidrive,
            examples::EXAMPLES_PROFIDRIVE,
            profidrive_modules
        ),
        0
    );
    // Without a PKW channel there is nothing an example could be read by.
    assert!(examples::EXAMPLES_9KDP1.is_empty());
    // A fixture of no manual: no example to print.
    assert!(examples::EXAMPLES_OWN_IDENTS.is_empty());
    assert!(examples::EXAMPLES_MD810_GATEWAY.is_empty());
}
