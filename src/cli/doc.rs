//! `gsdc doc`: descriptions to datasheets, `<stem>.html` and `<stem>.md`.
//! Like `gsdc build`, every description is loaded before anything is
//! written, so an error in one leaves the output directory as it was.

use super::{display_name, report, say, Status};
use gsdc::output::{read_input, write_if_changed, Outcome, ReadError};
use gsdc::{Artifact, Diagnostic, Diagnostics};
use std::path::{Path, PathBuf};

pub fn run(descriptions: &[PathBuf], out: &Path) -> Status {
    let mut status = Status::Ok;
    let mut artifacts: Vec<Artifact> = Vec::new();
    for path in descriptions {
        match document_one(path) {
            Ok(files) => artifacts.extend(files),
            Err(s) => status = status.max(s),
        }
    }
    if status != Status::Ok {
        eprintln!("nothing written: fix the errors above");
        return status;
    }
    if let Some(name) = duplicate_name(&artifacts) {
        eprintln!("error: two descriptions give {name}: give them different file names");
        return Status::UsageOrIo;
    }
    let outcomes = match write_if_changed(out, &artifacts) {
        Ok(outcomes) => outcomes,
        Err(e) => {
            eprintln!("error: {e}");
            return Status::UsageOrIo;
        }
    };
    for (artifact, outcome) in artifacts.iter().zip(outcomes) {
        let verb = match outcome {
            Outcome::Written => "wrote",
            Outcome::Unchanged => "unchanged",
        };
        say(&format!(
            "{verb} {}",
            out.join(&artifact.file_name).display()
        ));
    }
    Status::Ok
}

/// `a/md810dp.toml` and `b/md810dp.toml` would write the same datasheet.
fn duplicate_name(artifacts: &[Artifact]) -> Option<&str> {
    let mut names: Vec<&str> = artifacts.iter().map(|a| a.file_name.as_str()).collect();
    names.sort_unstable();
    names.windows(2).find(|w| w[0] == w[1]).map(|w| w[0])
}

fn document_one(path: &Path) -> Result<Vec<Artifact>, Status> {
    let name = display_name(path);
    let bytes = read_input(path, &gsdc::load::INPUT_LIMIT).map_err(|e| match e {
        ReadError::TooLarge(d) => input_error(&name, "", d),
        ReadError::Io(e) => {
            eprintln!("error: cannot read {name}: {e}");
            Status::UsageOrIo
        }
    })?;
    let text = gsdc::load::decode(&bytes)
        .map_err(|d| input_error(&name, &String::from_utf8_lossy(&bytes), d))?;
    let source_name = path
        .file_name()
        .map_or_else(|| name.clone(), |f| f.to_string_lossy().into_owned());
    let (ir, diagnostics) = gsdc::load(&source_name, text);
    report(&name, text, &diagnostics);
    let ir = ir.ok_or(Status::InputErrors)?;
    Ok(gsdc::document(&ir))
}

/// The description could not be read as one: reported, exit 1.
fn input_error(name: &str, text: &str, diagnostic: Diagnostic) -> Status {
    report(name, text, &Diagnostics(vec![diagnostic]));
    Status::InputErrors
}
