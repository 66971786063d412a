//! PROFIsafe submodules (`PROFIsafeSupported="true"`): their safety data
//! ends each way with one message trailer, the one their F_CRC_Length
//! takes, and they have an F-parameter record (E321). An F-host refuses a
//! module whose structure does not fit its F-parameters; the schema does
//! not see it.

use super::index::{child, children, describe, tag_span, El};
use super::Ctx;
use crate::diag::Diagnostic;

const TRAILERS: [&str; 2] = ["F_MessageTrailer4Byte", "F_MessageTrailer5Byte"];

pub fn check(ctx: &Ctx<'_, '_>, out: &mut Vec<Diagnostic>) {
    let submodules = ["VirtualSubmoduleItem", "SubmoduleItem"]
        .into_iter()
        .flat_map(|name| ctx.idx.all(name));
    for submodule in submodules.filter(|s| s.attribute("PROFIsafeSupported") == Some("true")) {
        if let Some(problem) = problem(submodule) {
            out.push(
                Diagnostic::error(
                    "E321",
                    format!("{} supports PROFIsafe, but {problem}", describe(submodule)),
                )
                .at(tag_span(submodule))
                .label("PROFIsafe submodule")
                .help("each way the safety data, then F_MessageTrailer4Byte for a 3-Byte-CRC or F_MessageTrailer5Byte for a 4-Byte-CRC (F_CRC_Length's DefaultValue), and an F_ParameterRecordDataItem"),
            );
        }
    }
}

/// What is wrong with a PROFIsafe submodule, if anything.
fn problem(submodule: &El<'_, '_>) -> Option<String> {
    let records = child(*submodule, "RecordDataList");
    let Some(parameters) = records.and_then(|r| child(r, "F_ParameterRecordDataItem")) else {
        return Some("has no F_ParameterRecordDataItem".into());
    };
    let crc_length = child(parameters, "F_CRC_Length")
        .and_then(|c| c.attribute("DefaultValue"))
        .unwrap_or("3-Byte-CRC");
    let trailer = match crc_length {
        "4-Byte-CRC" => TRAILERS[1],
        _ => TRAILERS[0],
    };
    let io = child(*submodule, "IOData");
    for direction in ["Input", "Output"] {
        let types: Vec<&str> = io
            .and_then(|io| child(io, direction))
            .into_iter()
            .flat_map(|part| children(part, "DataItem"))
            .filter_map(|item| item.attribute("DataType"))
            .collect();
        let trailers = types.iter().filter(|t| TRAILERS.contains(t)).count();
        if trailers != 1 || types.last() != Some(&trailer) {
            return Some(format!(
                "its {direction} does not end with the one {trailer} its F_CRC_Length {crc_length} takes"
            ));
        }
    }
    None
}
