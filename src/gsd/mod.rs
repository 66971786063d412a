//! PROFIBUS-DP GSD files: reader, keyword schema and rules.
//!
//! [`parse`] reads any text a vendor may have written (see `lexer` and
//! `reader` for what that takes) into a [`GsdFile`]; [`check`] adds the
//! keyword schema (`schemas/gsd-keywords.toml`) and the rules of
//! `docs/rules.md`; [`check_strict`] is the profile for the files gsdc
//! writes itself. Nothing here panics or recurses, whatever the input, and
//! the work is linear in the size of the text.

use std::borrow::Cow;

use crate::diag::InputLimit;
use crate::diag::{Diagnostics, Severity};

mod config;
mod lexer;
mod model;
mod prm;
mod reader;
mod rules;
mod schema;

pub use config::{io_lengths, CfgError, IoLengths};
pub use model::{
    Allowed, Arg, Baud, Block, ExtUserPrmData, GsdFile, IndexedText, Module, PrmDataType, PrmText,
    Setting, Slot, Spanned, UnitDiagArea, UnitDiagType, Value,
};

/// Bytes as vendors write them: UTF-8 if valid, else Latin-1 (each byte one
/// char). 272 of 654 real files are Latin-1 (umlauts in texts), and Latin-1
/// maps every byte, so nothing is ever lost or refused.
pub fn decode(bytes: &[u8]) -> Cow<'_, str> {
    match std::str::from_utf8(bytes) {
        Ok(text) => Cow::Borrowed(text),
        Err(_) => Cow::Owned(bytes.iter().map(|&b| char::from(b)).collect()),
    }
}

/// The largest GSD file gsdc reads (E229): the largest of the 654 real
/// files seen is 217 KB. Checking is linear, so the limit bounds time and
/// memory (about 2 s and 100 MB for 8 MiB in a debug build).
pub const INPUT_LIMIT: InputLimit = InputLimit {
    max_bytes: 8 << 20,
    code: "E229",
    what: "a GSD file",
    help:
        "the largest real GSD files are a few hundred kilobytes: check that this is the right file",
};

/// The parsed file, with what the reader could not read (E200-E204, E215,
/// E230). A text larger than [`INPUT_LIMIT`] is refused before it is read.
pub fn parse(text: &str) -> (GsdFile, Diagnostics) {
    if let Err(d) = INPUT_LIMIT.check(text.len()) {
        return (GsdFile::default(), Diagnostics(vec![d]));
    }
    let (file, diags) = reader::read(text);
    (file, Diagnostics(diags))
}

/// Parse + keyword schema + rules, as `gsdc check` applies them to a file
/// from a vendor. Never panics, whatever the text.
pub fn check(text: &str) -> Diagnostics {
    if let Err(d) = INPUT_LIMIT.check(text.len()) {
        return Diagnostics(vec![d]); // the rules would only add noise about an empty file
    }
    let (file, mut diags) = parse(text);
    diags.extend(rules::check(&file));
    // Stable sort: file-wide findings first, the rest in file order.
    diags.0.sort_by_key(|d| d.span.as_ref().map(|s| s.start));
    let lines = LineStarts::new(text);
    diags.name_subjects(|offset| keyword_at(text, lines.start_of(offset)?));
    diags
}

/// Where each line starts, found once: looking back from every finding
/// instead is quadratic on a megabyte line with thousands of findings.
struct LineStarts(Vec<usize>);

impl LineStarts {
    fn new(text: &str) -> Self {
        let breaks = text.match_indices('\n').map(|(i, _)| i + 1);
        LineStarts(std::iter::once(0).chain(breaks).collect())
    }

    /// The start of the line holding `offset`.
    fn start_of(&self, offset: usize) -> Option<usize> {
        let line = self.0.partition_point(|&start| start <= offset);
        self.0.get(line.checked_sub(1)?).copied()
    }
}

/// The keyword of the line starting at `start`: what a finding is about.
/// Reads no further than the keyword, however long the line.
fn keyword_at(text: &str, start: usize) -> Option<String> {
    let line = text[start..].trim_start_matches(|c: char| c.is_whitespace() && c != '\n');
    let keyword = line
        .split(|c: char| c == '=' || c == '(' || c == ';' || c.is_whitespace())
        .next()?;
    (!keyword.is_empty()).then(|| keyword.to_string())
}

/// [`check`] for a file gsdc wrote itself: adds the output-format rules
/// (E240 lines of at most 80 characters, E241 7-bit ASCII, E242 CRLF) and
/// reports every warning as an error, since gsdc's own output must meet every
/// limit a vendor file is forgiven (a 33-character module name that STEP 7
/// accepts from a vendor is still a defect in what gsdc writes).
pub fn check_strict(text: &str) -> Diagnostics {
    let mut diags = check(text);
    diags.extend(rules::output_format(text));
    for d in &mut diags.0 {
        d.severity = Severity::Error;
    }
    diags
}

#[cfg(test)]
mod subject_tests {
    use super::{keyword_at, LineStarts};

    #[test]
    fn the_subject_is_the_keyword_of_the_line() {
        let text = "#Profibus_DP\nMax_Input_Len = 249\nUnit_Diag_Bit(3) = \"x\"\n  \nEnd";
        let lines = LineStarts::new(text);
        let subject = |at: usize| keyword_at(text, lines.start_of(at)?);
        assert_eq!(
            subject(text.find("249").unwrap()).as_deref(),
            Some("Max_Input_Len")
        );
        assert_eq!(
            subject(text.find("\"x").unwrap()).as_deref(),
            Some("Unit_Diag_Bit")
        );
        assert_eq!(subject(0).as_deref(), Some("#Profibus_DP"));
        // A blank line has no keyword; the next line's is not taken.
        assert_eq!(subject(text.find("  ").unwrap()), None);
    }
}
