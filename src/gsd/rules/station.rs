//! Station-wide rules: baud rates (E213, E214, W232), compact and modular
//! stations (E217, W233, E218), DPV1 status bytes (E225), diagnosis bits
//! (E226), diagnosis areas without values (W231).

use foldhash::HashSet;

use crate::diag::Diagnostic;
use crate::gsd::model::{Arg, Baud, GsdFile, Setting};
use crate::gsd::rules::file_span;
use crate::gsd::schema;

/// The standard part of a slave's diagnosis, before the device-related
/// bytes that `Unit_Diag_Bit(n)` counts bits in.
const STANDARD_DIAG_BYTES: i64 = 6;

/// User_Prm_Data bytes 0..2 of a DPV1 slave are its status bytes.
const DPV1_STATUS_BYTES: usize = 3;

pub(super) fn check(file: &GsdFile, out: &mut Vec<Diagnostic>) {
    bauds(file, out);
    module_count(file, out);
    dpv1_status_bytes(file, out);
    diag_bits(file, out);
    empty_diag_areas(file, out);
}

/// W231: an area with no `Value` line names no value. Configuration tools
/// differ here (gsd-parser refuses the block), so it is a warning for vendor
/// files and, through the strict profile, an error in gsdc's own.
fn empty_diag_areas(file: &GsdFile, out: &mut Vec<Diagnostic>) {
    let areas = file
        .unit_diag_areas
        .iter()
        .chain(file.unit_diag_types.iter().flat_map(|t| &t.areas));
    for area in areas.filter(|a| a.values.is_empty()) {
        out.push(
            Diagnostic::warning(
                "W231",
                format!("`{}` without a `Value`", area.keyword.value),
            )
            .at(area.keyword.span.clone())
            .label("names no value of these bits")
            .help("add `Value(n) = \"text\"` lines, or drop the area"),
        );
    }
}

fn bauds(file: &GsdFile, out: &mut Vec<Diagnostic>) {
    let supported: Vec<&Setting> = file
        .settings
        .iter()
        .filter(|s| s.key.ends_with("_supp") && s.value.as_number() == Some(1))
        .filter(|s| matches!(s.arg, Some(Arg::Baud(_))))
        .collect();
    if supported.is_empty() {
        out.push(
            Diagnostic::error("E214", "no baud rate is supported")
                .at(file_span(file))
                .label("no `<baud>_supp = 1` in this file")
                .help("add e.g. `1.5M_supp = 1` and `MaxTsdr_1.5M = 150` for each baud rate the device runs at"),
        );
    }
    let keys: HashSet<&str> = file.settings.iter().map(|s| &*s.key).collect();
    for supp in supported {
        let Some(Arg::Baud(baud)) = supp.arg else {
            continue;
        };
        let tsdr = format!("MaxTsdr_{}", baud.as_str());
        if !keys.contains(schema::normalize(&tsdr).as_str()) {
            out.push(baud_without_tsdr(supp, baud, &tsdr));
        }
    }
}

/// E213, or W232 at 31.25 kbit/s: that is the MBP rate of PROFIBUS PA, which
/// no DP master's RS-485 line runs at. A master reaches such a slave through
/// a DP/PA coupler or link and never computes a slot time from this
/// keyword; STEP 7 imports Siemens' own FDC 157-0 file, which leaves it out.
fn baud_without_tsdr(supp: &Setting, baud: Baud, tsdr: &str) -> Diagnostic {
    let (diagnostic, help) = if baud == Baud::B31k25 {
        (
            Diagnostic::warning("W232", format!("`{}` without `{tsdr}`", supp.name)),
            format!("add `{tsdr} = <bit times>`; tools accept the file without it, as 31.25 kbit/s (PROFIBUS PA) is reached through a DP/PA coupler or link"),
        )
    } else {
        (
            Diagnostic::error("E213", format!("`{}` without `{tsdr}`", supp.name)),
            format!("add `{tsdr} = <bit times>`: the master needs the response time at every supported baud rate"),
        )
    };
    diagnostic
        .at(supp.span.clone())
        .label(format!("no `{tsdr}` in this file"))
        .help(help)
}

fn module_count(file: &GsdFile, out: &mut Vec<Diagnostic>) {
    let modular = file.get("Modular_Station");
    if modular.and_then(|s| s.value.as_number()) == Some(1) {
        let max_module = file.get("Max_Module");
        if max_module.and_then(|s| s.value.as_number()).unwrap_or(0) < 1 {
            out.push(
                Diagnostic::error("E218", "modular station without `Max_Module` of at least 1")
                    .at(max_module
                        .or(modular)
                        .map_or_else(|| file_span(file), |s| s.span.clone()))
                    .label("`Modular_Station = 1` here needs `Max_Module >= 1`")
                    .help("set `Max_Module` to the number of modules the station takes"),
            );
        }
        return;
    }
    let count = file.modules.len();
    if count == 1 {
        return;
    }
    let diagnostic = match file.modules.get(1) {
        // A tool has nothing to configure such a station with.
        None => Diagnostic::error("E217", "compact station without a module")
            .at(modular.map_or_else(|| file_span(file), |s| s.span.clone()))
            .label("a compact station (`Modular_Station = 0` or absent) has one module")
            .help("add the station's module, or set `Modular_Station = 1` with `Max_Module`"),
        // STEP 7 imports Siemens' own SIPART DR file, compact with 98
        // modules; gsd-parser reads such a file with `Max_Module = 1`.
        Some(second) => Diagnostic::warning("W233", format!("compact station with {count} modules"))
            .at(second.name.span.clone())
            .label("a compact station (`Modular_Station = 0` or absent) has one module")
            .help("tools accept it (STEP 7's own catalog has such files); set `Modular_Station = 1` with `Max_Module` if the station takes several modules, or keep one"),
    };
    out.push(diagnostic);
}

fn dpv1_status_bytes(file: &GsdFile, out: &mut Vec<Diagnostic>) {
    let Some(dpv1) = file
        .get("DPV1_Slave")
        .filter(|s| s.value.as_number() == Some(1))
    else {
        return;
    };
    let declared = file.number("User_Prm_Data_Len").map(|n| n.max(0) as usize);
    let len = declared.unwrap_or_else(|| file.default_user_prm_data().len());
    if len < DPV1_STATUS_BYTES {
        out.push(
            Diagnostic::error("E225", format!("DPV1 slave with {len} bytes of User_Prm_Data"))
                .at(dpv1.span.clone())
                .label("a DPV1 slave's parameters start with 3 DPV1 status bytes")
                .help("add `Ext_User_Prm_Data_Const(0) = 0x00,0x00,0x00` and start vendor parameters at byte 3"),
        );
    }
}

/// The keywords whose index is a bit of the device-related diagnosis.
const DIAG_BIT_KEYS: [&str; 8] = [
    "unit_diag_bit",
    "unit_diag_not_bit",
    "unit_diag_bit_help",
    "unit_diag_not_bit_help",
    "x_unit_diag_bit",
    "x_unit_diag_not_bit",
    "x_unit_diag_bit_help",
    "x_unit_diag_not_bit_help",
];

fn diag_bits(file: &GsdFile, out: &mut Vec<Diagnostic>) {
    let Some(max_len) = file
        .number("Max_Diag_Data_Len")
        .filter(|n| (6..=crate::spec::DP_MAX_TELEGRAM as i64).contains(n))
    else {
        return;
    };
    let bits = (max_len - STANDARD_DIAG_BYTES) * 8;
    let types = file.unit_diag_types.iter();
    let settings = file
        .settings
        .iter()
        .chain(types.clone().flat_map(|t| &t.settings))
        .filter(|s| DIAG_BIT_KEYS.contains(&&*s.key));
    for s in settings {
        if let Some(bit) = s.index().filter(|&b| b < 0 || b >= bits) {
            out.push(beyond(bit, s.span.clone(), max_len, bits));
        }
    }
    let areas = file
        .unit_diag_areas
        .iter()
        .chain(types.flat_map(|t| &t.areas));
    for area in areas {
        if area.first > area.last {
            out.push(
                Diagnostic::error(
                    "E226",
                    format!("diagnosis area {}-{} runs backwards", area.first, area.last),
                )
                .at(area.range_span.clone())
                .label("first bit after last bit")
                .help("write the area as `first-last`"),
            );
        } else if let Some(bit) = [area.first, area.last]
            .into_iter()
            .find(|&b| b < 0 || b >= bits)
        {
            out.push(beyond(bit, area.range_span.clone(), max_len, bits));
        }
    }
}

fn beyond(bit: i64, span: std::ops::Range<usize>, max_len: i64, bits: i64) -> Diagnostic {
    Diagnostic::error("E226", format!("diagnosis bit {bit} outside Max_Diag_Data_Len"))
        .at(span)
        .label(format!("bits 0..{} fit in Max_Diag_Data_Len = {max_len}", bits - 1))
        .help("raise Max_Diag_Data_Len (6 standard bytes + the device-related bytes), or fix the bit number")
}
