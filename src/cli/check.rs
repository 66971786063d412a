//! `gsdc check`: GSD and GSDML files against gsdc's rules.

use super::{display_name, report, Status};
use gsdc::Diagnostics;
use std::path::Path;

pub fn run(files: &[std::path::PathBuf]) -> Status {
    files
        .iter()
        .map(|f| check_one(f))
        .max()
        .unwrap_or(Status::Ok)
}

fn check_one(path: &Path) -> Status {
    let name = display_name(path);
    let bytes = match std::fs::read(path) {
        Ok(bytes) => bytes,
        Err(e) => {
            eprintln!("error: cannot read {name}: {e}");
            return Status::UsageOrIo;
        }
    };
    let (text, diagnostics) = check_bytes(path, &bytes);
    report(&name, &text, &diagnostics);
    let errors = diagnostics.errors().count();
    let warnings = diagnostics.iter().count() - errors;
    println!("{name}: {errors} error(s), {warnings} warning(s)");
    if errors > 0 {
        Status::InputErrors
    } else {
        Status::Ok
    }
}

/// GSDML by its `.xml` extension, GSD otherwise.
fn check_bytes(path: &Path, bytes: &[u8]) -> (String, Diagnostics) {
    let is_xml = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("xml"));
    if is_xml {
        // UTF-8, or ISO-8859-1 when the XML declaration says so.
        let text = match gsdc::gsdml::decode(bytes) {
            Ok(text) => text.into_owned(),
            Err(d) => {
                return (
                    String::from_utf8_lossy(bytes).into_owned(),
                    Diagnostics(vec![d]),
                )
            }
        };
        let file_name = path.file_name().map(|f| f.to_string_lossy().into_owned());
        let diagnostics = gsdc::gsdml::check(&text, file_name.as_deref());
        (text, diagnostics)
    } else {
        let text = gsdc::gsd::decode(bytes).into_owned();
        let diagnostics = gsdc::gsd::check(&text);
        (text, diagnostics)
    }
}
