//! Tests of the gateway part of the support code: what the shipped gateway
//! (whole bytes, tested in tests/firmware) does not reach, parameters that
//! share a byte and 16-bit ones, and config bytes of no module.

use super::support::gateway::*;
use super::support::PrmError;

/// Two parameters in one byte: words in (bits 0-3) and out (bits 4-7).
const IN: PrmField = PrmField::new(1, PrmType::Bits(0, 3), [0, 8], 0);
const OUT: PrmField = PrmField::new(1, PrmType::Bits(4, 7), [0, 8], 2);

#[test]
fn bit_areas_share_a_byte() {
    let mut user_prm = [0xAA, 0];
    IN.write(&mut user_prm, 5).unwrap();
    OUT.write(&mut user_prm, 8).unwrap();
    assert_eq!(user_prm, [0xAA, 0x85]);
    IN.write(&mut user_prm, 3).unwrap();
    assert_eq!(user_prm, [0xAA, 0x83]);
    assert_eq!((IN.read(&user_prm), OUT.read(&user_prm)), (Ok(3), Ok(8)));
    assert_eq!(defaults(&[IN, OUT]), [0, 2]);
    assert_eq!(OUT.default(), 2);
}

#[test]
fn bits_beyond_the_range_are_refused() {
    // 0xF in bits 0-3: the type holds it, the range does not.
    let refused = Err(PrmError::NotAllowed {
        offset: 1,
        value: 15,
    });
    assert_eq!(IN.read(&[0, 0x0F]), refused);
    let mut user_prm = [0; 2];
    assert_eq!(
        OUT.write(&mut user_prm, 9),
        Err(PrmError::NotAllowed {
            offset: 1,
            value: 9
        })
    );
    assert_eq!(user_prm, [0, 0]);
}

#[test]
fn unsigned16_is_big_endian_and_within_a_byte_s_values() {
    let words = PrmField::new(0, PrmType::Unsigned16, [0, 200], 0);
    let mut user_prm = [0xFF; 3];
    words.write(&mut user_prm, 200).unwrap();
    assert_eq!(user_prm, [0x00, 0xC8, 0xFF]);
    assert_eq!(words.read(&user_prm), Ok(200));
    assert_eq!(
        words.read(&[0x01, 0x00]),
        Err(PrmError::NotAllowed {
            offset: 0,
            value: 256
        })
    );
}

#[test]
fn a_field_past_the_end_is_a_length_error() {
    let short = [0; 1];
    assert_eq!(
        IN.read(&short),
        Err(PrmError::Length {
            expected: 2,
            found: 1
        })
    );
    assert_eq!(
        OUT.write(&mut [0; 1], 1),
        Err(PrmError::Length {
            expected: 2,
            found: 1
        })
    );
}

#[test]
fn config_bytes_of_no_module_are_refused() {
    let modules = [0x50, 0x5F, 0x60];
    let totals = config_totals(&[0x5F, 0x50, 0x60, 0x5F], &modules, 4).unwrap();
    assert_eq!((totals.input_words, totals.output_words), (33, 1));
    // 0x70: input and output of one word, a byte no module of a gateway has.
    assert_eq!(
        config_totals(&[0x70], &[0x70], 4),
        Err(CfgError::Unknown { at: 0, byte: 0x70 })
    );
    assert_eq!(
        config_totals(&[0x51], &modules, 4),
        Err(CfgError::Unknown { at: 0, byte: 0x51 })
    );
}

/// A gateway of nodes 5 to 7: at most 4 words each way per node, 10 bytes
/// of input and 6 of output.
const SMALL: NodeParams<3> = {
    let words = PrmField::new(0, PrmType::Unsigned8, [0, 4], 0);
    NodeParams {
        first_node: 5,
        node_count: PrmField::new(0, PrmType::Unsigned8, [1, 3], 1),
        input_words: [words; 3],
        output_words: [words; 3],
        max_input_len: 10,
        max_output_len: 6,
    }
};

#[test]
fn totals_count_the_nodes_in_use_within_the_limits() {
    let carried = totals(&SMALL, 3, &[2, 0, 3], &[1, 1, 1]).unwrap();
    assert_eq!((carried.input_len(), carried.output_len()), (10, 6));
    let refused = [
        (0, [0, 0, 0], [0, 0, 0], TotalsError::NodeCount { count: 0 }),
        (4, [0, 0, 0], [0, 0, 0], TotalsError::NodeCount { count: 4 }),
        (
            3,
            [0, 5, 0],
            [0, 0, 0],
            TotalsError::Words {
                node: 6,
                direction: Direction::In,
                words: 5,
            },
        ),
        (1, [0, 0, 0], [0, 0, 1], TotalsError::UnusedNode { node: 7 }),
        (
            2,
            [4, 2, 0],
            [0, 0, 0],
            TotalsError::TooLong {
                direction: Direction::In,
                len: 12,
                max: 10,
            },
        ),
        (
            3,
            [0, 0, 0],
            [2, 1, 1],
            TotalsError::TooLong {
                direction: Direction::Out,
                len: 8,
                max: 6,
            },
        ),
    ];
    for (count, input, output, error) in refused {
        assert_eq!(totals(&SMALL, count, &input, &output), Err(error));
    }
}

#[test]
fn data_offsets_follow_the_nodes_in_use() {
    let words = [2, 0, 3];
    assert_eq!(data_offset(&SMALL, 3, &words, 5), Some(0));
    assert_eq!(data_offset(&SMALL, 3, &words, 7), Some(4));
    assert_eq!(data_offset(&SMALL, 2, &words, 7), None);
    assert_eq!(data_offset(&SMALL, 3, &words, 4), None);
    assert_eq!(data_offset(&SMALL, 3, &words, 8), None);
}

#[test]
fn fields_read_and_write_in_order() {
    let fields = [
        PrmField::new(0, PrmType::Unsigned8, [0, 9], 0),
        PrmField::new(2, PrmType::Unsigned8, [0, 9], 0),
    ];
    let mut user_prm = [0xEE; 3];
    write_fields(&mut user_prm, &fields, &[7, 9]).unwrap();
    assert_eq!(user_prm, [7, 0xEE, 9]);
    assert_eq!(read_fields(&user_prm, &fields), Ok([7, 9]));
    assert_eq!(
        read_fields(&[7, 0, 10], &fields),
        Err(PrmError::NotAllowed {
            offset: 2,
            value: 10
        })
    );
}

/// Type, node and code after the header; nodes 5 to 7.
const LAYOUT: DiagLayout = DiagLayout {
    type_at: 1,
    node_at: 2,
    code_at: 3,
    first_node: 5,
    last_node: 7,
    types: &[1, 9],
};

#[test]
fn diagnosis_blocks_are_read_as_long_as_their_header_says() {
    let block = DiagBlock::<6>::new(5, &LAYOUT, 9, 6).with_code_word(&LAYOUT, 0xBEEF);
    assert_eq!(block.as_bytes(), [5, 9, 6, 0xBE, 0xEF]);
    let bytes = [5, 9, 6, 0xBE, 0xEF, 0x11];
    let (kind, node, read) = read_diag(&bytes, &LAYOUT).unwrap();
    assert_eq!((kind, node, read), (9, 6, &bytes[..5]));
    assert_eq!(code_word(read, 5, &LAYOUT), Ok(0xBEEF));
    let listed = |value| (value == 3).then_some("three");
    assert_eq!(
        code_byte(read, (9, 4), &LAYOUT, listed),
        Err(DiagError::Length {
            expected: 4,
            found: 5
        })
    );
    let short = DiagBlock::<6>::new(4, &LAYOUT, 1, 7).with_code_byte(&LAYOUT, 3);
    assert_eq!(short.as_bytes(), [4, 1, 7, 3]);
    assert_eq!(
        code_byte(short.as_bytes(), (1, 4), &LAYOUT, listed),
        Ok("three")
    );
    assert_eq!(
        code_byte(&[4, 1, 7, 2], (1, 4), &LAYOUT, listed),
        Err(DiagError::Code { kind: 1, value: 2 })
    );
    assert_eq!(
        read_diag(&[4, 2, 7, 3], &LAYOUT),
        Err(DiagError::Type { value: 2 })
    );
    assert_eq!(
        read_diag(&[4, 1, 8, 3], &LAYOUT),
        Err(DiagError::Node { value: 8 })
    );
    // The header says 2 bytes: no room for the node.
    assert_eq!(
        read_diag(&[2, 1, 6], &LAYOUT),
        Err(DiagError::Short {
            expected: 3,
            len: 2
        })
    );
    // The header says 4 bytes; 3 came.
    assert_eq!(
        read_diag(&[4, 1, 6], &LAYOUT),
        Err(DiagError::Short {
            expected: 4,
            len: 3
        })
    );
}
