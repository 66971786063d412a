//! `gsdc doc`: descriptions to datasheets, `<stem>.html` and `<stem>.md`.
//! Like `gsdc build`, every description is loaded before anything is
//! written, so an error in one leaves the output directory as it was, and
//! the files are written as `gsdc build` writes them (all or nothing, the
//! directory locked).

use super::build::{merged, write_all};
use super::{load_description, warn, Status};
use std::path::{Path, PathBuf};

pub const EXAMPLES: &str = "Example:
  gsdc doc descriptions/md810dp.toml --out dist   # dist/md810dp.html, dist/md810dp.md

Exit codes: 0 ok, 1 a description has errors, or two give datasheets of one name;
2 usage or I/O error.";

#[derive(clap::Args)]
pub struct Args {
    /// Description files (TOML).
    #[arg(required = true, value_name = "DESCRIPTION")]
    descriptions: Vec<PathBuf>,
    /// Directory to write into; created if missing.
    #[arg(long, short, default_value = ".", value_name = "DIR")]
    out: PathBuf,
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
        Ok(files) => write_all(&files, &args.out, false),
        Err(status) => status,
    }
}

/// The datasheet of one description.
fn document_one(path: &Path) -> Result<Vec<crate::Artifact>, Status> {
    load_description(path).map(|ir| crate::document(&ir))
}
