//! Emitters: the IR to file contents, each verified before it is returned.

pub mod gsd;

use crate::diag::{Diagnostic, Diagnostics};
use crate::ir::Ir;

/// One generated file: its name (no directory) and its bytes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Artifact {
    pub file_name: String,
    pub contents: Vec<u8>,
}

/// Every file the description gives, each read back and checked by the same
/// rules `gsdc check` applies to third-party files. A file that breaks one is
/// not returned: the diagnostics say which rule, and that gsdc is at fault.
pub fn compile(ir: &Ir) -> Result<Vec<Artifact>, Diagnostics> {
    let mut artifacts = Vec::new();
    let mut problems = Diagnostics::default();
    if let Some(profibus) = &ir.profibus {
        let text = gsd::emit(ir, profibus);
        problems.extend(verify_gsd(&profibus.file_name, &text));
        artifacts.push(Artifact {
            file_name: profibus.file_name.clone(),
            contents: text.into_bytes(),
        });
    }
    if problems.has_errors() {
        return Err(problems);
    }
    Ok(artifacts)
}

fn verify_gsd(file_name: &str, text: &str) -> Vec<Diagnostic> {
    let format = gsd_format_problems(text);
    let rules = crate::gsd::check(text).into_iter().filter(Diagnostic::is_error);
    format
        .into_iter()
        .chain(rules)
        .map(|d| generated_file_breaks(file_name, d))
        .collect()
}

/// What gsdc promises of every GSD it writes, beyond what it accepts on
/// read: 7-bit ASCII, CRLF line ends, lines of at most 80 characters.
fn gsd_format_problems(text: &str) -> Vec<Diagnostic> {
    let mut problems = Vec::new();
    if let Some(at) = text.find(|c: char| !c.is_ascii() || (c.is_ascii_control() && c != '\r' && c != '\n')) {
        problems.push(Diagnostic::error("E901", "character outside 7-bit printable ASCII").at(at..at + 1));
    }
    let mut offset = 0;
    for line in text.split_inclusive('\n') {
        let content = line.trim_end_matches('\n');
        if !line.ends_with("\r\n") && !line.is_empty() {
            problems.push(Diagnostic::error("E902", "line does not end in CRLF").at(offset..offset + line.len()));
        }
        if content.trim_end_matches('\r').chars().count() > gsd::MAX_LINE {
            problems.push(Diagnostic::error("E903", format!("line longer than {} characters", gsd::MAX_LINE)).at(offset..offset + content.len()));
        }
        offset += line.len();
    }
    problems
}

/// A rule broken by gsdc's own output: an internal error, reported with the
/// rule it broke so the bug can be found.
fn generated_file_breaks(file_name: &str, d: Diagnostic) -> Diagnostic {
    Diagnostic {
        code: "E900",
        message: format!("gsdc generated {file_name} breaking rule {}: {}; nothing was written", d.code, d.message),
        span: None,
        help: Some("this is a bug in gsdc: please report it with the description".into()),
        ..d
    }
}
