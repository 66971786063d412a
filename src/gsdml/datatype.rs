//! GSDML data types: which exist for IO data (`DataItemTypeEnumT`) and for
//! record parameters (`RecordDataRefTypeEnumT`), how many bytes each takes,
//! and the value range of the numeric ones.

use super::index::{tag_span, value_span, El};
use crate::diag::Diagnostic;

/// How much room a data type takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Size {
    Bytes(u32),
    /// Strings and octet strings: the element's `Length` attribute.
    FromLength,
    /// `Bit` and `BitArea`: `BitOffset` (and `BitLength`) within the byte at
    /// `ByteOffset`; record parameters only.
    Bits,
}

/// Where a type may be used.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Use {
    Both,
    IoOnly,
    RecordOnly,
}

/// Sizes from the GSDML specification's data type table and IEC 61158-6-10
/// (Date is BinaryDate, 7 octets; TimeStamp 12; the PROFIdrive types N2..X4
/// 2 or 4 octets).
const TYPES: &[(&str, Size, Use)] = &[
    ("Bit", Size::Bits, Use::RecordOnly),
    ("BitArea", Size::Bits, Use::RecordOnly),
    ("Integer8", Size::Bytes(1), Use::Both),
    ("Integer16", Size::Bytes(2), Use::Both),
    ("Integer32", Size::Bytes(4), Use::Both),
    ("Integer64", Size::Bytes(8), Use::Both),
    ("Unsigned8", Size::Bytes(1), Use::Both),
    ("Unsigned16", Size::Bytes(2), Use::Both),
    ("Unsigned32", Size::Bytes(4), Use::Both),
    ("Unsigned64", Size::Bytes(8), Use::Both),
    ("Float32", Size::Bytes(4), Use::Both),
    ("Float64", Size::Bytes(8), Use::Both),
    ("Date", Size::Bytes(7), Use::Both),
    ("TimeOfDay with date indication", Size::Bytes(6), Use::Both),
    (
        "TimeOfDay without date indication",
        Size::Bytes(4),
        Use::Both,
    ),
    (
        "TimeDifference with date indication",
        Size::Bytes(6),
        Use::Both,
    ),
    (
        "TimeDifference without date indication",
        Size::Bytes(4),
        Use::Both,
    ),
    ("NetworkTime", Size::Bytes(8), Use::Both),
    ("NetworkTimeDifference", Size::Bytes(8), Use::Both),
    ("VisibleString", Size::FromLength, Use::Both),
    ("OctetString", Size::FromLength, Use::Both),
    ("Float32+Status8", Size::Bytes(5), Use::IoOnly),
    ("F_MessageTrailer4Byte", Size::Bytes(4), Use::IoOnly),
    ("F_MessageTrailer5Byte", Size::Bytes(5), Use::IoOnly),
    ("Unsigned8+Unsigned8", Size::Bytes(2), Use::Both),
    ("Float32+Unsigned8", Size::Bytes(5), Use::Both),
    ("Boolean", Size::Bytes(1), Use::Both),
    ("UnicodeString8", Size::FromLength, Use::Both),
    ("61131_STRING", Size::FromLength, Use::Both),
    ("61131_WSTRING", Size::FromLength, Use::Both),
    ("TimeStamp", Size::Bytes(12), Use::Both),
    ("TimeStampDifference", Size::Bytes(12), Use::Both),
    ("TimeStampDifferenceShort", Size::Bytes(8), Use::Both),
    ("OctetString2+Unsigned8", Size::Bytes(3), Use::Both),
    ("Unsigned16_S", Size::Bytes(2), Use::Both),
    ("Integer16_S", Size::Bytes(2), Use::Both),
    ("Unsigned8_S", Size::Bytes(1), Use::Both),
    ("OctetString_S", Size::FromLength, Use::Both),
    ("N2", Size::Bytes(2), Use::Both),
    ("N4", Size::Bytes(4), Use::Both),
    ("V2", Size::Bytes(2), Use::Both),
    ("L2", Size::Bytes(2), Use::Both),
    ("R2", Size::Bytes(2), Use::Both),
    ("T2", Size::Bytes(2), Use::Both),
    ("T4", Size::Bytes(4), Use::Both),
    ("D2", Size::Bytes(2), Use::Both),
    ("E2", Size::Bytes(2), Use::Both),
    ("C4", Size::Bytes(4), Use::Both),
    ("X2", Size::Bytes(2), Use::Both),
    ("X4", Size::Bytes(4), Use::Both),
    ("Unipolar2.16", Size::Bytes(2), Use::Both),
];

/// The size of a `DataItem` data type, `None` if IO data cannot have it.
pub fn io_size(name: &str) -> Option<Size> {
    lookup(name, Use::IoOnly)
}

/// The size of a record `Ref` data type, `None` if records cannot have it.
pub fn record_size(name: &str) -> Option<Size> {
    lookup(name, Use::RecordOnly)
}

fn lookup(name: &str, wanted: Use) -> Option<Size> {
    TYPES
        .iter()
        .find(|(n, _, u)| *n == name && (*u == Use::Both || *u == wanted))
        .map(|(_, size, _)| *size)
}

/// Where a data type is used, for E309.
#[derive(Clone, Copy)]
pub enum Place {
    IoData,
    Record,
}

/// E309: the data type does not exist where it is used.
pub fn unknown_type(node: &El<'_, '_>, data_type: &str, place: Place) -> Diagnostic {
    let (what, examples) = match place {
        Place::IoData => (
            "IO data",
            "Unsigned8, Unsigned16, Integer32, Float32, or OctetString with Length",
        ),
        Place::Record => (
            "record parameters",
            "Bit, BitArea, Unsigned8, Unsigned16, Integer32, or VisibleString with Length",
        ),
    };
    Diagnostic::error(
        "E309",
        format!("\"{data_type}\" is not a data type of {what}"),
    )
    .at(value_span(node, "DataType"))
    .label("unknown data type")
    .help(format!(
        "use a DataType of the GSDML specification, e.g. {examples}"
    ))
}

/// E309: a string type without the Length that sizes it.
pub fn missing_length(node: &El<'_, '_>, data_type: &str) -> Diagnostic {
    Diagnostic::error(
        "E309",
        format!(
            "{} of type {data_type} has no Length",
            node.tag_name().name()
        ),
    )
    .at(tag_span(node))
    .label("Length missing")
    .help(format!(
        "{data_type} takes as many bytes as its Length attribute says: add Length=\"n\""
    ))
}

/// The value range of an integer type, `None` for the others.
pub fn integer_range(name: &str, bit_length: u32) -> Option<(i128, i128)> {
    let unsigned = |bits: u32| (0, (1i128 << bits) - 1);
    let signed = |bits: u32| (-(1i128 << (bits - 1)), (1i128 << (bits - 1)) - 1);
    Some(match name {
        "Bit" => unsigned(1),
        "BitArea" => unsigned(bit_length),
        "Unsigned8" => unsigned(8),
        "Unsigned16" => unsigned(16),
        "Unsigned32" => unsigned(32),
        "Unsigned64" => unsigned(64),
        "Integer8" => signed(8),
        "Integer16" => signed(16),
        "Integer32" => signed(32),
        "Integer64" => signed(64),
        _ => return None,
    })
}

pub fn is_float(name: &str) -> bool {
    matches!(name, "Float32" | "Float64")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn io_and_record_types_differ_where_the_schema_says() {
        assert_eq!(io_size("Unsigned16"), Some(Size::Bytes(2)));
        assert_eq!(io_size("UInt8"), None);
        assert_eq!(io_size("Bit"), None);
        assert_eq!(record_size("Bit"), Some(Size::Bits));
        assert_eq!(record_size("F_MessageTrailer4Byte"), None);
        assert_eq!(record_size("OctetString"), Some(Size::FromLength));
    }

    #[test]
    fn integer_ranges() {
        assert_eq!(integer_range("Unsigned8", 1), Some((0, 255)));
        assert_eq!(integer_range("Integer16", 1), Some((-32768, 32767)));
        assert_eq!(integer_range("BitArea", 3), Some((0, 7)));
        assert_eq!(integer_range("Float32", 1), None);
    }
}
