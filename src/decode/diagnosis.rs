//! The device-related diagnosis block: the header byte, then the device's
//! bytes, read area by area as the GSD's `Unit_Diag_Area`s number their bits
//! (through the firmware's `DiagArea`); a gateway's block is read by its
//! type instead (`super::gateway`).

use crate::diag::Diagnostic;
use crate::ir::profibus::{Diagnosis, STANDARD_DIAG_BYTES};
use crate::pkw::DiagArea;
use serde::Serialize;

#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct DiagnosisBlock {
    pub len: usize,
    pub header: u8,
    pub bytes: Vec<u8>,
    /// The areas of a block described by `[profibus.diagnosis]`; empty for
    /// a gateway's.
    pub areas: Vec<Area>,
    /// What no area reads: each byte the description names, whole, and
    /// every other set bit, so nothing set is dropped.
    pub unread: Vec<Unread>,
    /// A gateway's block: its type, node and code.
    pub gateway: Option<GatewayDiagnosis>,
}

/// A gateway's diagnosis block, read by its type.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct GatewayDiagnosis {
    #[serde(rename = "type")]
    pub kind: DiagByte,
    pub node: DiagNode,
    /// `None` for a type the description does not name: its code's size
    /// is unknown.
    pub code: Option<DiagCodeValue>,
}

/// The type: its byte in the block (the header is byte 0), its value, and
/// the description's text; `None` for a type it does not name.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct DiagByte {
    pub at: usize,
    pub value: u8,
    pub text: Option<String>,
}

#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct DiagNode {
    pub at: usize,
    pub value: u8,
    /// The node numbers, both ends included, and whether `value` is one.
    pub range: [u8; 2],
    pub allowed: bool,
}

/// The code: one byte or a 16-bit number, high byte first, from `at`.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct DiagCodeValue {
    pub at: usize,
    pub bytes: u8,
    pub value: u16,
    /// A listed code's text (`None` for a code the type does not list), or
    /// what a 16-bit code is (`Drive fault code`).
    pub text: Option<String>,
}

/// A `Unit_Diag_Area`: bits counted from the byte after the header.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Area {
    pub first_bit: u16,
    pub last_bit: u16,
    pub value: u16,
    /// The description's text for the value; `None` when it names none.
    pub text: Option<String>,
}

/// Device bytes no area reads, counted from the byte after the header.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Unread {
    /// A byte the description names (`bytes`), shown whole.
    Byte { at: u8, value: u8, text: String },
    /// A set bit with its `Unit_Diag_Bit` text, `None` when it names none.
    Bit { bit: u16, text: Option<String> },
    /// A clear bit with its `Unit_Diag_Not_Bit` text.
    ClearBit { bit: u16, text: String },
}

/// Header bits 7-6: 00 is a device-related block.
const BLOCK_TYPE_MASK: u8 = 0b1100_0000;
/// Header bits 5-0: the block's length, the header included.
const LENGTH_MASK: u8 = 0b0011_1111;

/// Decodes `block`, which must be as long as `diagnosis` says; E417 when
/// its header is not that of a device-related block of this length (the
/// diagnostic has no place; the caller knows where byte 0 is).
pub(super) fn decode(diagnosis: &Diagnosis, block: &[u8]) -> Result<DiagnosisBlock, Diagnostic> {
    debug_assert_eq!(block.len(), usize::from(diagnosis.length));
    let header = block.first().copied().unwrap_or_default();
    let length = diagnosis.length;
    check_header(
        header,
        &[length],
        &format!("the device-related block starts with 0x{length:02X}: bits 7-6 00, bits 5-0 its length ({length} bytes, the header included)"),
    )?;
    let areas = diagnosis
        .areas
        .iter()
        .map(|area| {
            let value = DiagArea::new(area.first_bit, area.last_bit).get(block);
            let text = area
                .values
                .choices
                .iter()
                .find(|c| c.value == i64::from(value))
                .map(|c| c.text.en.clone());
            Area {
                first_bit: area.first_bit,
                last_bit: area.last_bit,
                value,
                text,
            }
        })
        .collect();
    Ok(DiagnosisBlock {
        len: block.len(),
        header,
        bytes: block.to_vec(),
        areas,
        unread: unread(diagnosis, block),
        gateway: None,
    })
}

/// What no area reads, in order: a byte the description names and no
/// area or bit text touches, whole; otherwise each set bit.
fn unread(diagnosis: &Diagnosis, block: &[u8]) -> Vec<Unread> {
    let read = |bit: u16| {
        diagnosis
            .areas
            .iter()
            .any(|a| (a.first_bit..=a.last_bit).contains(&bit))
    };
    let named_bit = |bit: u16, clear: bool| {
        diagnosis
            .bits
            .iter()
            .find(|b| b.bit == bit && b.clear == clear)
    };
    let device_bytes = block.get(1..).unwrap_or_default();
    let mut out = Vec::new();
    for (at, &value) in (0u8..).zip(device_bytes) {
        let bits = (0..8).map(|i| u16::from(at) * 8 + i);
        let untouched = bits
            .clone()
            .all(|b| !read(b) && named_bit(b, false).is_none() && named_bit(b, true).is_none());
        let named = diagnosis.byte(STANDARD_DIAG_BYTES + 1 + at);
        match named {
            Some(text) if untouched => out.push(Unread::Byte {
                at,
                value,
                text: text.en.clone(),
            }),
            _ => out.extend(bits.filter(|&b| !read(b)).filter_map(|bit| {
                if value & (1 << (bit % 8)) != 0 {
                    let text = named_bit(bit, false).map(|b| b.text.en.clone());
                    return Some(Unread::Bit { bit, text });
                }
                let text = named_bit(bit, true)?.text.en.clone();
                Some(Unread::ClearBit { bit, text })
            })),
        }
    }
    out
}

/// E417 (without a place) unless `header` is a device-related block's of
/// one of `lengths`; `help` says which headers are.
pub(super) fn check_header(header: u8, lengths: &[u8], help: &str) -> Result<(), Diagnostic> {
    let kind = match header & BLOCK_TYPE_MASK {
        0b0000_0000 => None,
        0b0100_0000 => Some("identifier-related"),
        0b1000_0000 => Some("channel-related"),
        _ => Some("a revision or status block"),
    };
    let wrong = match kind {
        Some(kind) => format!("bits 7-6 make it {kind}, not device-related"),
        None if !lengths.contains(&(header & LENGTH_MASK)) => {
            format!("it gives the length {}", header & LENGTH_MASK)
        }
        None => return Ok(()),
    };
    Err(Diagnostic::error(
        "E417",
        format!("0x{header:02X} is not the header of this device's diagnosis block: {wrong}"),
    )
    .label("header")
    .help(help))
}
