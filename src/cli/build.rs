//! `gsdc build`: descriptions to device files. Every description is loaded
//! and compiled before anything is written, so an error in one leaves the
//! output directory as it was; an I/O error while writing leaves it as it
//! was too, as far as the disk allows (see `gsdc::output::write_if_changed`).

use super::{display_name, report, say, Status};
use gsdc::output::{is_up_to_date, read_input, write_if_changed, Outcome, ReadError};
use gsdc::{Artifact, Diagnostic, Diagnostics};
use std::path::{Path, PathBuf};

pub fn run(descriptions: &[PathBuf], out: &Path, check: bool) -> Status {
    let mut status = Status::Ok;
    let mut artifacts = Vec::new();
    for path in descriptions {
        match compile_one(path) {
            Ok(files) => artifacts.extend(files),
            Err(s) => status = status.max(s),
        }
    }
    if status != Status::Ok {
        eprintln!("nothing written: fix the errors above");
        return status;
    }
    if check {
        check_all(&artifacts, out)
    } else {
        write_all(&artifacts, out)
    }
}

/// `--check`: compares, writes nothing, prints a unified diff per differing file.
fn check_all(artifacts: &[Artifact], out: &Path) -> Status {
    let mut status = Status::Ok;
    for artifact in artifacts {
        let path = out.join(&artifact.file_name);
        match is_up_to_date(out, &artifact.file_name, &artifact.contents) {
            Ok(true) => {}
            Ok(false) => {
                let existing = std::fs::read(&path).unwrap_or_default();
                say(unified_diff(&path, &existing, &artifact.contents).trim_end());
                status = status.max(Status::InputErrors);
            }
            Err(e) => {
                eprintln!("error: cannot read {}: {e}", path.display());
                status = Status::UsageOrIo;
            }
        }
    }
    if status == Status::InputErrors {
        eprintln!(
            "out of step: run `gsdc build` without --check to update {}",
            out.display()
        );
    }
    status
}

fn unified_diff(path: &Path, existing: &[u8], generated: &[u8]) -> String {
    let (old, new) = (
        String::from_utf8_lossy(existing),
        String::from_utf8_lossy(generated),
    );
    let name = path.display().to_string();
    similar::TextDiff::from_lines(old.as_ref(), new.as_ref())
        .unified_diff()
        .context_radius(3)
        .header(
            &format!("{name} (on disk)"),
            &format!("{name} (from the description)"),
        )
        .to_string()
}

fn compile_one(path: &Path) -> Result<Vec<Artifact>, Status> {
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
    gsdc::compile(&ir).map_err(|diagnostics| {
        report(&name, text, &diagnostics);
        Status::InputErrors
    })
}

/// The description could not be read as one: reported, exit 1.
fn input_error(name: &str, text: &str, diagnostic: Diagnostic) -> Status {
    report(name, text, &Diagnostics(vec![diagnostic]));
    Status::InputErrors
}

fn write_all(artifacts: &[Artifact], out: &Path) -> Status {
    let outcomes = match write_if_changed(out, artifacts) {
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
