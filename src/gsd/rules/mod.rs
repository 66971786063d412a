//! The GSD rules. Each has a stable code (`docs/rules.md`); all failures
//! are collected, never just the first. An error is what breaks a rule of
//! the file's own GSD revision in a way a tool refuses or misreads; what
//! tools accept (Siemens' own STEP 7 catalog files do it) is a warning.
//!
//! | code | rule |
//! |---|---|
//! | E200-E204 | reader: marker, unreadable line, unclosed string, unclosed block, stray block end |
//! | W205-W212, W234 | keyword schema: unknown, mandatory, type, range (W234: below the minimum, accepted by tools), string length, revision, duplicate, spelling |
//! | E213-E214, W232 | baud rates and MaxTsdr (W232: 31.25 kbit/s) |
//! | E215-E218, W233 | modules: config bytes, I/O lengths, compact (W233: several modules) and modular stations |
//! | E219-E225, E227-E228 | user parameter data |
//! | E226, W231 | diagnosis bits within Max_Diag_Data_Len; areas with values |
//! | E240-E242 | strict profile only: the format of gsdc's own output |

use crate::diag::Diagnostic;
use crate::gsd::model::{GsdFile, Setting};

mod keywords;
mod modules;
mod output;
mod params;
mod station;

pub(crate) use output::output_format;

pub(crate) fn check(file: &GsdFile) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    keywords::check(file, &mut out);
    station::check(file, &mut out);
    modules::check(file, &mut out);
    params::check(file, &mut out);
    out
}

/// Every list of settings in the file, each a scope of its own for
/// duplicates: the top level, each module, data area and block.
fn scopes(file: &GsdFile) -> Vec<&[Setting]> {
    let mut scopes: Vec<&[Setting]> = vec![&file.settings];
    for module in &file.modules {
        scopes.push(&module.settings);
        scopes.extend(module.data_areas.iter().map(|a| a.settings.as_slice()));
    }
    scopes.extend(file.ext_user_prm_data.iter().map(|d| d.settings.as_slice()));
    scopes.extend(file.unit_diag_types.iter().map(|t| t.settings.as_slice()));
    scopes.extend(file.blocks.iter().map(|b| b.settings.as_slice()));
    scopes
}

/// Where a diagnostic about the whole file points: the marker line.
fn file_span(file: &GsdFile) -> std::ops::Range<usize> {
    file.marker.clone().unwrap_or(0..0)
}
