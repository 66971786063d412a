//! `gsdc doc`: descriptions to datasheets, `<stem>.html` and `<stem>.md`.
//! Like `gsdc build`, every description is loaded before anything is
//! written, so an error in one leaves the output directory as it was, and
//! the files are written as `gsdc build` writes them (all or nothing, the
//! directory locked).

use super::build::{differing, merged, read_lock, write_all};
use super::{display_name, load_description, warn, Status};
use crate::Artifact;
use std::path::{Path, PathBuf};

pub const EXAMPLES: &str = "Examples:
  gsdc doc descriptions/md810dp.toml --out dist           # dist/md810dp.html, dist/md810dp.md
  gsdc doc descriptions/*.toml --out dist --check         # in CI: are the datasheets in step?
  gsdc doc descriptions/md810dp.toml --wire-results target/wire-results.txt   # with what was exchanged on the wire

Exit codes: 0 ok, 1 a description has errors, two give datasheets of one name,
or --check found a datasheet out of step; 2 usage or I/O error.";

#[derive(clap::Args)]
pub struct Args {
    /// Description files (TOML).
    #[arg(required = true, value_name = "DESCRIPTION")]
    descriptions: Vec<PathBuf>,
    /// Directory to write into; created if missing.
    #[arg(long, short, default_value = ".", value_name = "DIR")]
    out: PathBuf,
    /// Write nothing: exit 1 and name each datasheet in DIR that differs from
    /// what the descriptions give, or is missing.
    #[arg(long)]
    check: bool,
    /// The results `scripts/wire-test.sh --results FILE` recorded: each
    /// datasheet gains a "tested on the wire" section with the exchanges of
    /// the very files the description gives now, or says that none is
    /// recorded for them.
    #[arg(long, value_name = "FILE")]
    wire_results: Option<PathBuf>,
}

pub fn run(args: &Args) -> Status {
    let results = match args.wire_results.as_deref().map(read_results).transpose() {
        Ok(results) => results,
        Err(status) => return status,
    };
    let mut status = Status::Ok;
    let mut sets = Vec::new();
    for path in &args.descriptions {
        match document_one(path, results.as_deref()) {
            Ok(files) => sets.push((path.clone(), files)),
            Err(s) => status = status.max(s),
        }
    }
    if status != Status::Ok {
        warn("nothing written: fix the errors above");
        return status;
    }
    match merged(sets) {
        Ok(files) if args.check => check_all(&files, &args.out),
        Ok(files) => write_all(&files, &args.out, false),
        Err(status) => status,
    }
}

/// `--check`: names each datasheet that differs from the one in `out` or is
/// missing; nothing written. Names, not diffs: a page's diff is pages of
/// markup, and `gsdc doc` rewrites it whole. A `gsdc doc` at work on `out`
/// is waited for, as `gsdc build --check` waits.
fn check_all(files: &[Artifact], out: &Path) -> Status {
    let _lock = match read_lock(out) {
        Ok(lock) => lock,
        Err(status) => return status,
    };
    let status = differing(files, out, named);
    if status == Status::InputErrors {
        warn(&format!(
            "out of step: run `gsdc doc` without --check to update {}",
            display_name(out)
        ));
    }
    status
}

fn named(path: &Path, on_disk: Option<&[u8]>, _: &Artifact) -> String {
    let what = if on_disk.is_some() {
        "differs"
    } else {
        "missing"
    };
    format!("{what}: {}", display_name(path))
}

/// The datasheet of one description, with what `results` recorded on the
/// wire when given.
fn document_one(
    path: &Path,
    results: Option<&[crate::wire::Exchanged]>,
) -> Result<Vec<Artifact>, Status> {
    load_description(path).map(|ir| match results {
        Some(results) => crate::document_tested(&ir, results),
        None => crate::document(&ir),
    })
}

/// The exchanges of a results file; a file that cannot be read or is none
/// is a usage error (exit 2), named with the line.
fn read_results(path: &Path) -> Result<Vec<crate::wire::Exchanged>, Status> {
    let text = std::fs::read_to_string(path).map_err(|e| {
        warn(&format!("{}: {e}", display_name(path)));
        Status::UsageOrIo
    })?;
    crate::wire::parse(&text).map_err(|(line, why)| {
        warn(&format!(
            "{}:{line}: not a results file of scripts/wire-test.sh: {why}",
            display_name(path)
        ));
        Status::UsageOrIo
    })
}
