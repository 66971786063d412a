//! Bytes written in hex as people copy them from a bus monitor or a manual:
//! `10F0 0800 0000 1388`, `10 F0 08 00`, `10F008000000`. Each group between
//! blanks holds whole bytes, so a digit lost in a group is found where it
//! was lost. Every byte remembers where its digits are, so a diagnostic can
//! point at it.

use crate::diag::Diagnostic;
use std::ops::Range;

/// Bytes read from a hex argument, each with the place of its two digits.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Hex {
    bytes: Vec<u8>,
    spans: Vec<Range<usize>>,
    /// Length of the argument, where a missing byte is pointed at.
    end: usize,
}

impl Hex {
    /// The bytes `text` spells, or E410 at a character that is not a hex
    /// digit, or E411 at a group with an odd number of digits.
    pub fn parse(text: &str) -> Result<Hex, Diagnostic> {
        let mut hex = Hex {
            bytes: Vec::new(),
            spans: Vec::new(),
            end: text.len(),
        };
        for (start, group) in groups(text) {
            hex.push_group(start, group)?;
        }
        Ok(hex)
    }

    fn push_group(&mut self, start: usize, group: &str) -> Result<(), Diagnostic> {
        if let Some((at, c)) = group.char_indices().find(|(_, c)| !c.is_ascii_hexdigit()) {
            let at = start + at;
            return Err(Diagnostic::error("E410", format!("`{c}` is not a hex digit"))
                .at(at..at + c.len_utf8())
                .label("not 0-9 or A-F")
                .help("write the bytes in hex, two digits each, with or without blanks between them: 10F0 0800 or 10 F0 08 00"));
        }
        if group.len() % 2 == 1 {
            return Err(Diagnostic::error(
                "E411",
                format!("`{group}` has {} hex digits: a byte is two", group.len()),
            )
            .at(start..start + group.len())
            .label("odd number of digits")
            .help(
                "a digit is missing or one too many; write each byte as two digits (05, not 5)",
            ));
        }
        for (i, pair) in group.as_bytes().chunks_exact(2).enumerate() {
            let digits = std::str::from_utf8(pair).expect("ASCII hex digits");
            let byte = u8::from_str_radix(digits, 16).expect("two hex digits are a byte");
            let at = start + 2 * i;
            self.bytes.push(byte);
            self.spans.push(at..at + 2);
        }
        Ok(())
    }

    pub fn bytes(&self) -> &[u8] {
        &self.bytes
    }

    /// The bytes when there are exactly `len`, else E412 pointing at the
    /// bytes beyond `len` or at the end where bytes are missing. `what`
    /// names the data (`PPO1`); `help` says what it holds.
    pub fn exactly(&self, len: usize, what: &str, help: &str) -> Result<&[u8], Diagnostic> {
        let found = self.bytes.len();
        if found == len {
            return Ok(&self.bytes);
        }
        let (span, label) = match self.spans.get(len) {
            Some(first_extra) => (
                first_extra.start..self.end,
                format!("{} byte(s) too many", found - len),
            ),
            None => (
                self.end..self.end,
                format!("{} byte(s) missing", len - found),
            ),
        };
        Err(
            Diagnostic::error("E412", format!("{what} is {len} bytes; this is {found}"))
                .at(span)
                .label(label)
                .help(help),
        )
    }

    /// The place of byte `index`'s digits.
    pub fn span(&self, index: usize) -> Option<Range<usize>> {
        self.spans.get(index).cloned()
    }
}

/// The runs of non-blank characters with their byte offsets.
fn groups(text: &str) -> Vec<(usize, &str)> {
    let mut groups = Vec::new();
    let mut start = None;
    // A blank after the end closes the last group.
    for (i, c) in text.char_indices().chain([(text.len(), ' ')]) {
        match (c.is_whitespace(), start) {
            (true, Some(s)) => {
                groups.push((s, &text[s..i]));
                start = None;
            }
            (false, None) => start = Some(i),
            _ => {}
        }
    }
    groups
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_bytes_or_one_run_read_the_same() {
        let expected = [0x10, 0xF0, 0x08, 0x00, 0x00, 0x00, 0x13, 0x88];
        for text in [
            "10F0 0800 0000 1388",
            "10 F0 08 00 00 00 13 88",
            "10f0080000001388",
            "  10F0\t0800\n0000  1388 ",
        ] {
            assert_eq!(Hex::parse(text).unwrap().bytes(), expected, "{text:?}");
        }
        assert_eq!(Hex::parse("").unwrap().bytes(), [0u8; 0]);
    }

    #[test]
    fn a_bad_digit_is_pointed_at() {
        let d = Hex::parse("10F0 08G0").unwrap_err();
        assert_eq!((d.code, d.span), ("E410", Some(7..8)));
        // A wide character after a blank of more than one byte.
        let d = Hex::parse("10\u{3000}Fé").unwrap_err();
        assert_eq!(d.code, "E410");
        assert_eq!(&"10\u{3000}Fé"[d.span.unwrap()], "é");
    }

    #[test]
    fn a_group_with_an_odd_digit_count_is_pointed_at() {
        let d = Hex::parse("10F0 080 0000").unwrap_err();
        assert_eq!((d.code, d.span), ("E411", Some(5..8)));
    }

    #[test]
    fn a_wrong_length_points_at_the_extra_bytes_or_the_end() {
        let hex = Hex::parse("10F0 0800 AB").unwrap();
        assert_eq!(
            hex.exactly(5, "x", "h").unwrap(),
            [0x10, 0xF0, 0x08, 0x00, 0xAB]
        );
        let d = hex.exactly(3, "PPO3", "h").unwrap_err();
        assert_eq!((d.code, d.span), ("E412", Some(7..12)));
        assert_eq!(d.message, "PPO3 is 3 bytes; this is 5");
        let d = hex.exactly(12, "PPO1", "h").unwrap_err();
        assert_eq!(d.span, Some(12..12));
        assert_eq!(d.label.as_deref(), Some("7 byte(s) missing"));
    }
}
