//! `gsdc import FILE... --out DESC.toml`: a card's GSD or GSDML file, or
//! both, written back as one description (`crate::import`), whose build
//! `gsdc diff` finds the same device as each file; the description is
//! written only then, and never over a file.

use super::{display_name, say, warn, Status, MAX_SHOWN};
use crate::diag::Diagnostic;
use crate::import::Imported;
use crate::Source;
use std::io::Write;
use std::path::{Path, PathBuf};

pub const EXAMPLES: &str = "Examples:
  gsdc import vendor/MD810DP.GSD --out descriptions/md810dp.toml
  gsdc import vendor/GSDML-V2.32-MEGMEET-MV800-20230830.xml --out descriptions/mv810.toml
  gsdc import vendor/MD810DP.GSD vendor/GSDML-V2.32-INOVANCE-MD810-20261122.xml --out md810.toml
  gsdc build descriptions/md810dp.toml --out dist && gsdc diff vendor/MD810DP.GSD dist/MD810DP.GSD
  gsdc import vendor/GSDML-V2.34-SEW-MOVI-C-Decentralized-Electronics-20200731-071447.xml --draft --out movi-c.toml

Exit codes: 0 written; 1 the file cannot be imported, or its import would build
another device (nothing written; with --draft, the draft written); 2 usage or I/O
error (DESC.toml exists already).";

#[derive(clap::Args)]
pub struct Args {
    /// The card's GSD file, its GSDML file, or both (one description with
    /// both buses).
    #[arg(required = true, num_args = 1..=2, value_name = "FILE")]
    files: Vec<PathBuf>,
    /// The description to write; it must not exist.
    #[arg(long, short, value_name = "DESC.toml")]
    out: PathBuf,
    /// When the import's build would be another device, write it all the
    /// same as a draft: its [draft] table lists each change and each part
    /// left out, and every build warns (W604) until it is deleted.
    #[arg(long)]
    draft: bool,
}

pub fn run(args: &Args) -> Status {
    let mut files = Vec::new();
    for path in &args.files {
        match read(path) {
            Ok(bytes) => files.push((path, bytes)),
            Err(status) => return status,
        }
    }
    let (written, symbol) = match files.as_slice() {
        [(path, bytes)] => {
            let beside = |name: &str| read_beside(path, name);
            let imported = crate::import::import_with(file_name(path), bytes, &beside);
            report(&display_name(path), &imported);
            ((imported.description, imported.draft), imported.symbol)
        }
        [a, b] => match gsd_first(a, b) {
            Some(((gsd, gsd_bytes), (gsdml, gsdml_bytes))) => {
                let beside = |name: &str| read_beside(gsd, name);
                let both = crate::import::import_both(
                    (file_name(gsd), gsd_bytes),
                    (file_name(gsdml), gsdml_bytes),
                    &beside,
                );
                report(&display_name(gsd), &both.gsd);
                report(&display_name(gsdml), &both.gsdml);
                ((both.description, both.draft), both.symbol)
            }
            None => {
                warn("error: two files are a card's GSD and its GSDML file");
                return Status::UsageOrIo;
            }
        },
        _ => return Status::UsageOrIo,
    };
    let (text, is_draft) = match written {
        (Some(description), _) => (description, false),
        (None, Some(draft)) if args.draft => (draft, true),
        (None, Some(_)) => {
            warn("nothing written: the import's build is another device (E601 above); with `--draft` it is written as a draft that lists each change");
            return Status::InputErrors;
        }
        (None, None) => return Status::InputErrors,
    };
    if let Err((written, e)) = write_outputs(&args.out, &text, symbol.as_ref()) {
        warn(&format!("error: {}: {e}", display_name(&written)));
        return Status::UsageOrIo;
    }
    if !is_draft {
        return Status::Ok;
    }
    warn(&format!(
        "{} is a draft: its build is another device; [draft] lists each change and each part left out, and every build warns (W604) until it is deleted",
        display_name(&args.out)
    ));
    Status::InputErrors
}

/// A file beside the device file `beside` by its name, or by the same
/// name in other letter case (GSD files name their bitmaps as written on
/// Windows).
fn read_beside(beside: &Path, name: &str) -> Result<Vec<u8>, String> {
    let dir = beside.parent().unwrap_or(Path::new("."));
    let exact = dir.join(name);
    let path = if exact.is_file() {
        exact
    } else {
        std::fs::read_dir(dir)
            .map_err(|e| e.to_string())?
            .filter_map(Result::ok)
            .map(|e| e.path())
            .find(|p| {
                p.file_name()
                    .and_then(|n| n.to_str())
                    .is_some_and(|n| n.eq_ignore_ascii_case(name))
            })
            .ok_or_else(|| "no such file beside it".to_string())?
    };
    match crate::output::read_device_file(&path) {
        Ok((_, bytes)) => Ok(bytes),
        Err(crate::output::ReadError::Io(e)) => Err(e.to_string()),
        Err(crate::output::ReadError::TooLarge(d)) => Err(d.message),
    }
}

/// The symbol's PNG beside the description, then the description: both or
/// neither, never over a file, in a folder made when missing. The error
/// names the file it is about.
fn write_outputs(
    out: &Path,
    description: &str,
    symbol: Option<&crate::import::ImportedSymbol>,
) -> Result<(), (PathBuf, std::io::Error)> {
    if let Some(dir) = out.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| (dir.to_path_buf(), e))?;
    }
    let png = symbol.map(|s| (out.with_file_name(&s.file_name), &s.png));
    if let Some((path, bytes)) = &png {
        write_new(path, bytes).map_err(|e| (path.clone(), e))?;
    }
    if let Err(e) = write_new(out, description.as_bytes()) {
        if let Some((path, _)) = &png {
            let _ = std::fs::remove_file(path);
        }
        return Err((out.to_path_buf(), e));
    }
    if let Some((path, _)) = &png {
        say(&format!("wrote {}", display_name(path)));
    }
    say(&format!("wrote {}", display_name(out)));
    Ok(())
}

type File<'a> = (&'a PathBuf, Vec<u8>);

/// The GSD and the GSDML file of two, told apart by their content.
fn gsd_first<'a, 'b>(a: &'b File<'a>, b: &'b File<'a>) -> Option<(&'b File<'a>, &'b File<'a>)> {
    use crate::file_kind::{detect, FileKind};
    let kind = |f: &File| detect(&f.1[..f.1.len().min(crate::file_kind::HEAD_BYTES)]);
    match (kind(a), kind(b)) {
        (FileKind::Gsd, FileKind::Gsdml) => Some((a, b)),
        (FileKind::Gsdml, FileKind::Gsd) => Some((b, a)),
        _ => None,
    }
}

fn file_name(path: &Path) -> &str {
    path.file_name()
        .and_then(|n| n.to_str())
        .unwrap_or("IMPORTED.GSD")
}

/// A device file's bytes, or the status of the error said.
fn read(path: &Path) -> Result<Vec<u8>, Status> {
    match crate::output::read_device_file(path) {
        Ok((_, bytes)) => Ok(bytes),
        Err(crate::output::ReadError::Io(e)) => {
            warn(&format!("error: {}: {e}", display_name(path)));
            Err(Status::UsageOrIo)
        }
        Err(crate::output::ReadError::TooLarge(d)) => {
            warn(&format!("error: {}: {}", display_name(path), d.message));
            Err(Status::InputErrors)
        }
    }
}

/// The diagnostics, then one line: what was left out and the round trip.
fn report(name: &str, imported: &Imported) {
    let source = Source::new(name, &imported.text);
    // Errors first: they say why nothing was written, and a file of many
    // keywords the description has no place for must not hide them. Nor
    // may a round trip of many changes hide what was left out, which
    // explains them: of many of both, each gets half.
    let (errors, mut warnings): (Vec<&Diagnostic>, Vec<&Diagnostic>) =
        imported.diagnostics.iter().partition(|d| d.is_error());
    // The decisions the import took for the whole file (a version, a name
    // of station, a class it writes otherwise) before what it left out at
    // an element.
    warnings.sort_by_key(|d| d.span.is_some());
    let errors_shown = errors
        .len()
        .min((MAX_SHOWN / 2).max(MAX_SHOWN.saturating_sub(warnings.len())));
    let warnings_shown = MAX_SHOWN - errors_shown;
    let shown = errors[..errors_shown]
        .iter()
        .chain(warnings.iter().take(warnings_shown));
    for d in shown {
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
    // Without a description or a draft nothing was built to compare: a
    // count of no changes would read as a clean round trip.
    let round_trip = match imported.description.is_some() || imported.draft.is_some() {
        true => format!(
            "round trip: {} breaking, {} compatible, {} cosmetic",
            r.breaking, r.compatible, r.cosmetic
        ),
        false => "no round trip: the import was refused (see the errors above)".to_string(),
    };
    warn(&format!(
        "{name}: {} not imported (W600); {round_trip}",
        imported.unsaid
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
