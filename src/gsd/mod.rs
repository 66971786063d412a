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
use crate::diag::{Diagnostic, Diagnostics, Severity};

mod config;
mod lexer;
pub(crate) mod model;
pub(crate) mod prm;
mod reader;
mod rules;
pub(crate) mod schema;

pub use config::{io_lengths, CfgError, IoLengths};
pub use model::{
    Allowed, Arg, Baud, Block, ExtUserPrmData, GsdFile, IndexedText, Module, PrmDataType, PrmText,
    Setting, Slot, Spanned, UnitDiagArea, UnitDiagType, Value,
};
pub(crate) use schema::{keyword_max_len, keyword_range};

/// Bytes as vendors write them: UTF-8 if valid, else Latin-1 (each byte one
/// char). 272 of 654 real files are Latin-1 (umlauts in texts), and Latin-1
/// maps every byte, so nothing is ever lost or refused.
pub fn decode(bytes: &[u8]) -> Cow<'_, str> {
    match std::str::from_utf8(bytes) {
        Ok(text) => Cow::Borrowed(text),
        Err(_) => Cow::Owned(crate::latin1::decode(bytes)),
    }
}

/// A GSD file's text and its findings, from the file's bytes: [`decode`]
/// then [`check`]. A file saved as UTF-16 has a NUL byte beside every
/// character and no keyword a tool could read: it gets one finding that
/// says so (E230), with its text decoded for showing, instead of a finding
/// for each of its lines.
pub fn check_bytes(bytes: &[u8]) -> (Cow<'_, str>, Diagnostics) {
    let Some(order) = crate::utf16::byte_order(bytes) else {
        let text = decode(bytes);
        let diagnostics = check(&text);
        return (text, diagnostics);
    };
    let text = crate::utf16::decode_lossy(bytes, order);
    let utf16 = Diagnostic::error(
        "E230",
        "the file is UTF-16 text: a NUL byte beside every character, which no GSD reader takes",
    )
    .help("save the file as ASCII or ISO-8859-1 (\"ANSI\" in Windows editors), as GSD files are written");
    (Cow::Owned(text), Diagnostics(vec![utf16]))
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
    let mut lines = LineCursor::new(text);
    diags.name_subjects(|offset| keyword_at(text, lines.start_of(offset)));
    diags
}

/// Finds the start of the line holding an offset, scanning forward from the
/// previous offset when the offsets come in file order (as the sorted
/// findings do): the whole text is scanned once, however many findings a
/// megabyte line has.
struct LineCursor<'a> {
    text: &'a str,
    /// Offset up to which the text has been scanned, and the start of the
    /// line holding it.
    scanned: usize,
    line_start: usize,
}

impl<'a> LineCursor<'a> {
    fn new(text: &'a str) -> Self {
        LineCursor {
            text,
            scanned: 0,
            line_start: 0,
        }
    }

    fn start_of(&mut self, offset: usize) -> usize {
        let offset = offset.min(self.text.len());
        if offset < self.scanned {
            // Out of order: look back from the offset itself.
            return self.last_newline(0..offset).map_or(0, |i| i + 1);
        }
        if let Some(i) = self.last_newline(self.scanned..offset) {
            self.line_start = i + 1;
        }
        self.scanned = offset;
        self.line_start
    }

    fn last_newline(&self, range: std::ops::Range<usize>) -> Option<usize> {
        let start = range.start;
        let found = match self.text.get(range.clone()) {
            Some(part) => part.rfind('\n'), // memrchr
            None => self.text.as_bytes()[range]
                .iter()
                .rposition(|&b| b == b'\n'),
        };
        found.map(|i| start + i)
    }
}

/// The keyword of the line starting at `start`: what a finding is about.
/// Reads no further than the keyword, however long the line.
fn keyword_at(text: &str, start: usize) -> Option<String> {
    let line = text
        .get(start..)?
        .trim_start_matches(|c: char| c.is_whitespace() && c != '\n');
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
mod utf16_tests {
    use super::check_bytes;

    #[test]
    fn a_utf16_gsd_is_one_finding_saying_so() {
        let text = ";comment\r\n#Profibus_DP\r\nGSD_Revision = 5\r\nVendor_Name = \"Acme\"\r\n";
        let mut bytes = vec![0xFF, 0xFE];
        bytes.extend(text.encode_utf16().flat_map(u16::to_le_bytes));
        let (decoded, diagnostics) = check_bytes(&bytes);
        assert_eq!(decoded, text);
        let codes: Vec<&str> = diagnostics.iter().map(|d| d.code).collect();
        assert_eq!(codes, ["E230"]);
        assert!(diagnostics.0[0].message.contains("UTF-16"));
        // The same text in 8 bits is checked as usual.
        let (_, diagnostics) = check_bytes(text.as_bytes());
        assert!(
            diagnostics.iter().all(|d| d.code != "E230"),
            "{diagnostics:?}"
        );
    }
}

#[cfg(test)]
mod subject_tests {
    use super::{keyword_at, LineCursor};

    #[test]
    fn the_subject_is_the_keyword_of_the_line() {
        let text = "#Profibus_DP\nMax_Input_Len = 249\nUnit_Diag_Bit(3) = \"x\"\n  \nEnd";
        let mut lines = LineCursor::new(text);
        let mut subject = |at: usize| keyword_at(text, lines.start_of(at));
        assert_eq!(subject(0).as_deref(), Some("#Profibus_DP"));
        assert_eq!(
            subject(text.find("249").unwrap()).as_deref(),
            Some("Max_Input_Len")
        );
        assert_eq!(
            subject(text.find("\"x").unwrap()).as_deref(),
            Some("Unit_Diag_Bit")
        );
        // A blank line has no keyword; the next line's is not taken.
        assert_eq!(subject(text.find("  ").unwrap()), None);
        // Back to an earlier line, out of order.
        assert_eq!(
            subject(text.find("Input").unwrap()).as_deref(),
            Some("Max_Input_Len")
        );
        assert_eq!(subject(text.len()).as_deref(), Some("End"));
    }
}
