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
}

pub fn run(args: &Args) -> Status {
    let mut status = Status::Ok;
    let mut sets = Vec::new();
    for path in &args.descriptions {
        match document_one(path) {
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

/// The datasheet of one description.
fn document_one(path: &Path) -> Result<Vec<Artifact>, Status> {
    load_description(path).map(|ir| crate::document(&ir))
}
