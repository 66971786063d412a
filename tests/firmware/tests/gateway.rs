//! MD810's bridge mode (manual chapter 2) through its generated layout: the
//! manual's example configuration, the limits of 30 CANopen slaves and 244
//! bytes each way, the config bytes of the modules, and the four diagnosis
//! blocks of 2.5, decoded from bytes and encoded back.

use gsdc_firmware_check::md810_gateway::gateway::*;
use gsdc_firmware_check::md810_gateway::{decode_user_prm, PrmError, USER_PRM_LEN};

/// A configuration of `count` slaves with these TPDO (input) and RPDO
/// (output) words, slave 1 first; the others 0.
fn config(count: u8, input: &[u8], output: &[u8]) -> NodeConfig {
    let mut config = NodeConfig {
        node_count: count,
        input_words: [0; NODES],
        output_words: [0; NODES],
    };
    config.input_words[..input.len()].copy_from_slice(input);
    config.output_words[..output.len()].copy_from_slice(output);
    config
}

/// 2.4 step 5's example: RPDO 64 words, TPDO 120 words; 15 slaves of 8
/// TPDO words (2.2.1's most), the first 8 of them with 8 RPDO words.
fn manual_example() -> NodeConfig {
    config(15, &[8; 15], &[8; 8])
}

#[test]
fn the_manuals_example_is_240_bytes_in_and_128_out() {
    let example = manual_example();
    let totals = example.totals().unwrap();
    assert_eq!((totals.input_words, totals.output_words), (120, 64));
    assert_eq!((totals.input_len(), totals.output_len()), (240, 128));
    // User_Prm_Data: the count, then TPDO and RPDO words slave by slave.
    let user_prm = example.encode().unwrap();
    assert_eq!(user_prm.len(), USER_PRM_LEN);
    assert_eq!(user_prm[..5], [15, 8, 8, 8, 8]);
    assert_eq!(user_prm[15..19], [8, 8, 8, 0]);
    assert_eq!(user_prm[29..31], [8, 0]);
    assert!(user_prm[31..].iter().all(|&b| b == 0));
    assert_eq!(NodeConfig::decode(&user_prm), Ok(example));
    assert_eq!(decode_user_prm(&user_prm).unwrap().nodes, example);
}

/// The master plugs modules until INPUT and OUTPUT equal the totals (2.4
/// step 5): 7 x 16 + 8 words in, 4 x 16 words out.
#[test]
fn the_example_s_modules_carry_its_totals() {
    let mut plugged = vec![INPUT_16_WORDS_CONFIG; 7];
    plugged.push(INPUT_8_WORDS_CONFIG);
    plugged.extend([OUTPUT_16_WORDS_CONFIG; 4]);
    let totals = manual_example().totals().unwrap();
    assert_eq!(config_totals(&plugged), Ok(totals));
    plugged.pop();
    assert_ne!(config_totals(&plugged), Ok(totals));
    assert_eq!(
        config_totals(&[0x5F, 0xF3]),
        Err(CfgError::Unknown { at: 1, byte: 0xF3 })
    );
    assert_eq!(
        config_totals(&[INPUT_1_WORD_CONFIG; 21]),
        Err(CfgError::TooMany {
            modules: 21,
            max: MAX_MODULES
        })
    );
}

/// The slaves' words follow each other in ascending slave number.
#[test]
fn each_slave_s_words_have_their_place() {
    let example = manual_example();
    assert_eq!(example.input_offset(1), Some(0));
    assert_eq!(example.input_offset(15), Some(14 * 16));
    assert_eq!(example.output_offset(9), Some(8 * 16));
    assert_eq!(example.input_offset(16), None);
    assert_eq!(example.input_offset(0), None);
}

/// 30 slaves (2.4 step 4's most), 244 bytes each way (2.2.1's most).
fn at_the_limits() -> NodeConfig {
    let mut words = [4; NODES];
    words[..2].copy_from_slice(&[5, 5]);
    config(30, &words, &words)
}

#[test]
fn thirty_slaves_and_244_bytes_pass() {
    let totals = at_the_limits().totals().unwrap();
    assert_eq!((totals.input_len(), totals.output_len()), (244, 244));
    let user_prm = at_the_limits().encode().unwrap();
    assert_eq!(NodeConfig::decode(&user_prm), Ok(at_the_limits()));
}

#[test]
fn a_31st_slave_is_refused() {
    let mut config = at_the_limits();
    config.node_count = 31;
    assert_eq!(config.totals(), Err(TotalsError::NodeCount { count: 31 }));
    assert_eq!(
        config.encode(),
        Err(PrmError::NotAllowed {
            offset: 0,
            value: 31
        })
    );
    let mut user_prm = at_the_limits().encode().unwrap();
    user_prm[0] = 31;
    assert_eq!(
        NodeConfig::decode(&user_prm),
        Err(PrmError::NotAllowed {
            offset: 0,
            value: 31
        })
    );
}

/// One word more is 246 bytes: the 245th byte is one too many.
#[test]
fn a_245th_byte_is_refused() {
    let mut more_in = at_the_limits();
    more_in.input_words[2] = 5;
    assert_eq!(
        more_in.totals(),
        Err(TotalsError::TooLong {
            direction: Direction::In,
            len: 246,
            max: MAX_INPUT_LEN
        })
    );
    let mut more_out = at_the_limits();
    more_out.output_words[29] = 5;
    assert_eq!(
        more_out.totals(),
        Err(TotalsError::TooLong {
            direction: Direction::Out,
            len: 246,
            max: MAX_OUTPUT_LEN
        })
    );
}

/// At most two PDOs (8 function codes) each way per slave (2.2.1), and no
/// words for a slave past the count.
#[test]
fn a_slave_s_words_keep_to_their_range() {
    let mut nine = manual_example();
    nine.input_words[3] = 9;
    let refused = TotalsError::Words {
        node: 4,
        direction: Direction::In,
        words: 9,
    };
    assert_eq!(nine.totals(), Err(refused));
    let mut user_prm = manual_example().encode().unwrap();
    user_prm[7] = 9;
    assert_eq!(
        NodeConfig::decode(&user_prm),
        Err(PrmError::NotAllowed {
            offset: 7,
            value: 9
        })
    );
    let past = config(2, &[1, 1, 1], &[]);
    assert_eq!(past.totals(), Err(TotalsError::UnusedNode { node: 3 }));
}

/// The GSD's defaults: the bridge alone, no words.
#[test]
fn the_default_is_the_bridge_alone() {
    let mut user_prm = [0; USER_PRM_LEN];
    user_prm[0] = 1;
    assert_eq!(NodeConfig::decode(&user_prm), Ok(NodeConfig::DEFAULT));
    assert_eq!(NodeConfig::DEFAULT.encode(), Ok(user_prm));
    let totals = NodeConfig::DEFAULT.totals().unwrap();
    assert_eq!((totals.input_words, totals.output_words), (0, 0));
    assert_eq!(
        NodeConfig::decode(&user_prm[1..]),
        Err(PrmError::Length {
            expected: USER_PRM_LEN,
            found: USER_PRM_LEN - 1
        })
    );
}

/// A line of the GSD generated beside the layout: what follows `key` and `=`.
fn gsd_values(key: &str) -> Vec<String> {
    let gsd = include_str!(concat!(env!("OUT_DIR"), "/MD810GW.GSD"));
    gsd.lines()
        .filter(|l| l.starts_with(key))
        .map(|l| l.split_once('=').unwrap().1.trim().to_string())
        .collect()
}

/// What the layout says, the GSD says: lengths, modules, the limits.
#[test]
fn the_layout_agrees_with_the_gsd() {
    let number = |key| gsd_values(key)[0].parse::<usize>().unwrap();
    assert_eq!(number("Max_User_Prm_Data_Len"), USER_PRM_LEN);
    assert_eq!(number("Max_Diag_Data_Len"), 6 + DIAG_MAX_LEN);
    assert_eq!(number("Max_Input_Len"), MAX_INPUT_LEN);
    assert_eq!(number("Max_Output_Len"), MAX_OUTPUT_LEN);
    assert_eq!(number("Max_Module"), MAX_MODULES);
    let configs: Vec<String> = gsd_values("Module")
        .iter()
        .map(|m| m.rsplit(' ').next().unwrap().to_string())
        .collect();
    let expected: Vec<String> = MODULE_CONFIGS
        .iter()
        .map(|b| format!("0x{b:02X}"))
        .collect();
    assert_eq!(configs, expected);
}

/// 2.5's table, bytes 6 to 10 of SFC13's record: length, type, CANopen
/// slave, code, and a fifth byte, "保留" (reserved) unless the type is 4.
fn diagnosis_cases() -> [(&'static [u8], Diagnosis); 4] {
    [
        // 参数错误（1）, 参数PDO长度与变频器不匹配（35）.
        (
            &[4, 1, 7, 35],
            Diagnosis::ParameterError {
                node: 7,
                code: ParameterErrorCode::ParameterPdoLengthDoesNotMatchTheDrive,
            },
        ),
        // 参数错误（1）, 配置中有节点未在线（34）.
        (
            &[4, 1, 30, 34],
            Diagnosis::ParameterError {
                node: 30,
                code: ParameterErrorCode::NodeInTheConfigurationNotOnline,
            },
        ),
        // CANopen 网络故障（3）, 运行中 CANopen 从站掉线（32）.
        (
            &[4, 3, 1, 32],
            Diagnosis::CanopenNetworkFault {
                node: 1,
                code: CanopenNetworkFaultCode::CanopenSlaveDroppedOutWhileRunning,
            },
        ),
        // 变频报故障（4）: 变频器故障（高字节）, （低字节）.
        (
            &[5, 4, 12, 0x23, 0x01],
            Diagnosis::DriveReportsFault {
                node: 12,
                code: 0x2301,
            },
        ),
    ]
}

#[test]
fn the_four_diagnosis_blocks_decode_and_encode_back() {
    for (bytes, diagnosis) in diagnosis_cases() {
        assert_eq!(Diagnosis::decode(bytes), Ok(diagnosis), "{bytes:?}");
        assert_eq!(diagnosis.encode().as_bytes(), bytes, "{diagnosis:?}");
        assert_eq!(diagnosis.node(), bytes[2]);
    }
}

/// SFC13 reads bytes 6 to 10 whatever the length: the reserved fifth byte
/// of a 4-byte block is past its length and not read.
#[test]
fn the_reserved_byte_is_not_read() {
    let (bytes, diagnosis) = diagnosis_cases()[2];
    let record = [bytes, &[0xAA]].concat();
    assert_eq!(Diagnosis::decode(&record), Ok(diagnosis));
}

#[test]
fn blocks_the_table_does_not_have_are_refused() {
    let refused = [
        (&[4, 2, 7, 35][..], DiagError::Type { value: 2 }),
        (&[4, 1, 31, 35], DiagError::Node { value: 31 }),
        (&[4, 1, 0, 35], DiagError::Node { value: 0 }),
        (&[4, 1, 7, 33], DiagError::Code { kind: 1, value: 33 }),
        (&[4, 3, 7, 34], DiagError::Code { kind: 3, value: 34 }),
        (
            &[5, 1, 7, 35, 0],
            DiagError::Length {
                expected: 4,
                found: 5,
            },
        ),
        (
            &[4, 4, 7, 0x23],
            DiagError::Length {
                expected: 5,
                found: 4,
            },
        ),
        (
            &[5, 4, 7, 0x23],
            DiagError::Short {
                expected: 5,
                len: 4,
            },
        ),
        (&[0x44, 1, 7, 35], DiagError::Header { byte: 0x44 }),
        (
            &[],
            DiagError::Short {
                expected: 1,
                len: 0,
            },
        ),
    ];
    for (bytes, error) in refused {
        assert_eq!(Diagnosis::decode(bytes), Err(error), "{bytes:?}");
    }
}
