//! `gsdc import FILE... --out DESC.toml`: a card's GSD file written back as
//! a description (`crate::import`), whose build `gsdc diff` finds the same
//! device; the description is written only then, and never over a file.

use super::{display_name, say, warn, Status, MAX_SHOWN};
use crate::import::Imported;
use crate::Source;
use std::io::Write;
use std::path::{Path, PathBuf};

pub const EXAMPLES: &str = "Examples:
  gsdc import vendor/MD810DP.GSD --out descriptions/md810dp.toml
  gsdc build descriptions/md810dp.toml --out dist && gsdc diff vendor/MD810DP.GSD dist/MD810DP.GSD

Exit codes: 0 written; 1 the file cannot be imported, or its import would build
another device (nothing written); 2 usage or I/O error (DESC.toml exists already).";

#[derive(clap::Args)]
pub struct Args {
    /// The card's GSD file (a GSDML file is refused for now).
    #[arg(required = true, value_name = "FILE")]
    files: Vec<PathBuf>,
    /// The description to write; it must not exist.
    #[arg(long, short, value_name = "DESC.toml")]
    out: PathBuf,
}

pub fn run(args: &Args) -> Status {
    if args.files.len() > 1 {
        warn("error: gsdc import takes one card's GSD file; a GSDML file cannot be imported yet");
        return Status::UsageOrIo;
    }
    let path = &args.files[0];
    let bytes = match crate::output::read_device_file(path) {
        Ok((_, bytes)) => bytes,
        Err(crate::output::ReadError::Io(e)) => {
            warn(&format!("error: {}: {e}", display_name(path)));
            return Status::UsageOrIo;
        }
        Err(crate::output::ReadError::TooLarge(d)) => {
            warn(&format!("error: {}: {}", display_name(path), d.message));
            return Status::InputErrors;
        }
    };
    let file_name = path
        .file_name()
        .and_then(|n| n.to_str())
        .unwrap_or("IMPORTED.GSD");
    let imported = crate::import::import(file_name, &bytes);
    report(&display_name(path), &imported);
    let Some(description) = &imported.description else {
        return Status::InputErrors;
    };
    match write_new(&args.out, description.as_bytes()) {
        Ok(()) => {
            say(&format!("wrote {}", display_name(&args.out)));
            Status::Ok
        }
        Err(e) => {
            warn(&format!("error: {}: {e}", display_name(&args.out)));
            Status::UsageOrIo
        }
    }
}

/// The diagnostics, then one line: what was left out and the round trip.
fn report(name: &str, imported: &Imported) {
    let source = Source {
        name,
        text: &imported.text,
    };
    for d in imported.diagnostics.iter().take(MAX_SHOWN) {
        warn(&source.render(d));
    }
    let hidden = imported
        .diagnostics
        .iter()
        .count()
        .saturating_sub(MAX_SHOWN);
    if hidden > 0 {
        warn(&format!("{name}: {hidden} more finding(s) not shown"));
    }
    let r = imported.round_trip;
    warn(&format!(
        "{name}: {} not imported (W600); round trip: {} breaking, {} compatible, {} cosmetic",
        imported.unsaid, r.breaking, r.compatible, r.cosmetic
    ));
}

/// Writes a file that does not exist yet, whole or not at all.
fn write_new(path: &Path, contents: &[u8]) -> std::io::Result<()> {
    let mut file = std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(path)?;
    let written = file.write_all(contents).and_then(|()| file.sync_all());
    if written.is_err() {
        let _ = std::fs::remove_file(path);
    }
    written
}
