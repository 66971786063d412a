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

/// gsdc's own GSD must meet the strict rules: the vendor-file rules with
/// warnings as errors, plus 7-bit ASCII, CRLF and lines of at most 80 characters.
fn verify_gsd(file_name: &str, text: &str) -> Vec<Diagnostic> {
    crate::gsd::check_strict(text)
        .into_iter()
        .filter(Diagnostic::is_error)
        .map(|d| generated_file_breaks(file_name, d))
        .collect()
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
