//! Parameter records: every Ref and Const inside its record's Length
//! (E316), Ref data types (E309), and each DefaultValue valid for its data
//! type and among its AllowedValues (E317).

use super::datatype::{
    integer_range, is_float, missing_length, record_size, unknown_type, Place, Size,
};
use super::index::{children, describe, value_span, El};
use super::values::{parse_u32, Number, NumberList};
use super::Ctx;
use crate::diag::Diagnostic;

/// Elements with a `Length` and `Ref`/`Const` children (the schema's
/// `RecordDataBaseG` users).
const RECORDS: [&str; 2] = ["ParameterRecordDataItem", "Request"];

pub fn check(ctx: &Ctx<'_, '_>, out: &mut Vec<Diagnostic>) {
    for record in RECORDS.iter().flat_map(|name| ctx.idx.all(name)) {
        let length = record.attribute("Length").and_then(parse_u32);
        for reference in children(*record, "Ref") {
            let Some(data_type) = reference.attribute("DataType") else {
                continue;
            };
            let Some(size) = record_size(data_type) else {
                out.push(unknown_type(&reference, data_type, Place::Record));
                continue;
            };
            match (end_of_ref(&reference, data_type, size), length) {
                (Err(diagnostic), _) => out.push(diagnostic),
                (Ok(Some(end)), Some(length)) if end > u64::from(length) => {
                    out.push(outside(record, &reference, end, length));
                }
                _ => {}
            }
            default_value(&reference, data_type, out);
        }
        for constant in children(*record, "Const") {
            let offset = constant.attribute("ByteOffset").map_or(Some(0), parse_u32);
            let bytes = constant
                .attribute("Data")
                .map(|d| d.split(',').count() as u64);
            if let (Some(offset), Some(bytes), Some(length)) = (offset, bytes, length) {
                let end = u64::from(offset) + bytes;
                if end > u64::from(length) {
                    out.push(outside(record, &constant, end, length));
                }
            }
        }
    }
}

/// The byte after the parameter, `None` when an attribute it depends on
/// is malformed (the attribute rules report that).
fn end_of_ref(
    reference: &El<'_, '_>,
    data_type: &str,
    size: Size,
) -> Result<Option<u64>, Diagnostic> {
    let number =
        |name: &str, default: u32| reference.attribute(name).map_or(Some(default), parse_u32);
    let Some(offset) = number("ByteOffset", 0) else {
        return Ok(None);
    };
    let bytes: Option<u64> = match size {
        Size::Bytes(n) => Some(n.into()),
        Size::FromLength => match reference.attribute("Length") {
            Some(length) => parse_u32(length).map(u64::from),
            None => return Err(missing_length(reference, data_type)),
        },
        Size::Bits => {
            // BitLength only counts for BitArea; a Bit is one bit.
            let bits = if data_type == "BitArea" {
                number("BitLength", 1)
            } else {
                Some(1)
            };
            let bits = number("BitOffset", 0).zip(bits);
            bits.map(|(offset, bits)| (u64::from(offset) + u64::from(bits)).div_ceil(8))
        }
    };
    Ok(bytes.map(|b| u64::from(offset) + b))
}

fn outside(record: &El<'_, '_>, item: &El<'_, '_>, end: u64, length: u32) -> Diagnostic {
    let what = named(item);
    Diagnostic::error(
        "E316",
        format!(
            "{what} ends at byte {end}, after the end of {} (Length {length})",
            describe_record(record)
        ),
    )
    .at(value_span(item, "ByteOffset"))
    .label(format!("ends at byte {end}"))
    .help(format!(
        "raise the record's Length to {end} or move the {} to a lower ByteOffset",
        item.tag_name().name()
    ))
}

fn describe_record(record: &El<'_, '_>) -> String {
    match record.attribute("Index") {
        Some(index) => format!("record {index}"),
        None => describe(record),
    }
}

fn default_value(reference: &El<'_, '_>, data_type: &str, out: &mut Vec<Diagnostic>) {
    let Some(text) = reference.attribute("DefaultValue") else {
        return;
    };
    let bit_length = reference
        .attribute("BitLength")
        .and_then(parse_u32)
        .unwrap_or(1)
        .min(64);
    let problem = match (integer_range(data_type, bit_length), is_float(data_type)) {
        (Some((lo, hi)), _) => match Number::parse(text) {
            Some(Number::Int(v)) if (lo..=hi).contains(&v) => None,
            _ => Some(format!("{data_type} takes integers from {lo} to {hi}")),
        },
        (None, true) => Number::parse(text)
            .is_none()
            .then(|| format!("{data_type} takes a number")),
        (None, false) => return, // strings, dates, ...: no numeric value to check
    };
    let problem = problem.or_else(|| {
        let value = Number::parse(text)?;
        let allowed = reference.attribute("AllowedValues")?;
        let contained = NumberList::parse(allowed)?.contains(value);
        (!contained).then(|| format!("AllowedValues is \"{allowed}\""))
    });
    if let Some(problem) = problem {
        out.push(
            Diagnostic::error(
                "E317",
                format!(
                    "DefaultValue \"{text}\" of {} is not allowed: {problem}",
                    named(reference)
                ),
            )
            .at(value_span(reference, "DefaultValue"))
            .label("invalid default")
            .help("the controller writes the DefaultValue at startup; make it one of the allowed values"),
        );
    }
}

/// `Ref "T_TEXT"`: a parameter by its name's TextId.
fn named(item: &El<'_, '_>) -> String {
    let element = item.tag_name().name();
    match item.attribute("TextId") {
        Some(text) => format!("{element} \"{text}\""),
        None => element.to_string(),
    }
}
