//! `gsdc build`: descriptions to device files. Every description is loaded
//! and compiled before anything is written, so an error in one leaves the
//! output directory as it was.

use super::{display_name, report, say, Status};
use gsdc::output::{is_up_to_date, write_if_changed, Outcome};
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
    let bytes = std::fs::read(path).map_err(|e| {
        eprintln!("error: cannot read {name}: {e}");
        Status::UsageOrIo
    })?;
    let text = match String::from_utf8(bytes) {
        Ok(text) => text,
        Err(e) => {
            let at = e.utf8_error().valid_up_to();
            let text = String::from_utf8_lossy(e.as_bytes());
            let diagnostic = Diagnostic::error("E000", "the description is not UTF-8 text")
                .at(at..at + 1)
                .label("not UTF-8")
                .help("save the description as UTF-8");
            report(&name, &text, &Diagnostics(vec![diagnostic]));
            return Err(Status::InputErrors);
        }
    };
    let source_name = path
        .file_name()
        .map_or_else(|| name.clone(), |f| f.to_string_lossy().into_owned());
    let (ir, diagnostics) = gsdc::load(&source_name, &text);
    report(&name, &text, &diagnostics);
    let ir = ir.ok_or(Status::InputErrors)?;
    gsdc::compile(&ir).map_err(|diagnostics| {
        report(&name, &text, &diagnostics);
        Status::InputErrors
    })
}

fn write_all(artifacts: &[Artifact], out: &Path) -> Status {
    if let Err(e) = std::fs::create_dir_all(out) {
        eprintln!("error: cannot create {}: {e}", out.display());
        return Status::UsageOrIo;
    }
    for artifact in artifacts {
        let path = out.join(&artifact.file_name);
        match write_if_changed(out, &artifact.file_name, &artifact.contents) {
            Ok(Outcome::Written) => say(&format!("wrote {}", path.display())),
            Ok(Outcome::Unchanged) => say(&format!("unchanged {}", path.display())),
            Err(e) => {
                eprintln!("error: cannot write {}: {e}", path.display());
                return Status::UsageOrIo;
            }
        }
    }
    Status::Ok
}
