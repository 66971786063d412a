//! Splits the text after `#Profibus_DP` into logical lines of tokens.
//!
//! A logical line is one physical line plus every line joined to it by a `\`
//! at its end (also inside a string, and also when a comment follows the `\`,
//! as Siemens writes `0x54,0x81,\   ; Slot 1`). `;` starts a comment outside
//! strings. Every token keeps its byte span in the whole text, so diagnostics
//! point into the file as the user sees it.
//!
//! The lexer looks at each byte a bounded number of times: no backtracking,
//! so a 1 MB line costs what a 1 MB file of short lines costs.

use std::borrow::Cow;
use std::ops::Range;

#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum Tok<'a> {
    /// A run of characters that are not whitespace or punctuation: keywords,
    /// numbers, type names (`Unsigned8`, `1.5M_supp`, `Unit_Diag_!Bit`).
    Word,
    /// A string literal, continuations removed, without its quotes:
    /// borrowed from the text unless a continuation had to be removed.
    Str(Cow<'a, str>),
    /// One of `= ( ) , - @`.
    Punct(u8),
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Token<'a> {
    pub tok: Tok<'a>,
    pub span: Range<usize>,
}

/// A string literal that reached the end of its line without a closing quote.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Unterminated {
    pub span: Range<usize>,
}

const PUNCT: &[u8] = b"=(),-@";

/// Where the `#Profibus_DP` line is: its span and the offset just after it.
/// The marker is case-insensitive and may carry a trailing `; comment`.
pub(crate) fn find_marker(text: &str) -> Option<(Range<usize>, usize)> {
    const MARKER: &str = "#profibus_dp";
    let mut start = 0;
    while start < text.len() {
        let end = text[start..].find('\n').map_or(text.len(), |i| start + i);
        let line = &text[start..end];
        let indent = line.len() - line.trim_start().len();
        let rest = &line[indent..];
        if rest.len() >= MARKER.len()
            && rest.as_bytes()[..MARKER.len()].eq_ignore_ascii_case(MARKER.as_bytes())
        {
            let tail = rest[MARKER.len()..].trim_start();
            if tail.is_empty() || tail.starts_with(';') {
                let at = start + indent;
                return Some((at..at + MARKER.len(), (end + 1).min(text.len())));
            }
        }
        start = end + 1;
    }
    None
}

pub(crate) struct Lexer<'a> {
    bytes: &'a [u8],
    text: &'a str,
    pos: usize,
}

impl<'a> Lexer<'a> {
    pub fn new(text: &'a str, start: usize) -> Self {
        Lexer {
            bytes: text.as_bytes(),
            text,
            pos: start.min(text.len()),
        }
    }

    /// Reads the next logical line into `tokens` (cleared first). Returns
    /// false at the end of the text. Lines without tokens (blank, comment
    /// only) come back as empty.
    pub fn next_line(
        &mut self,
        tokens: &mut Vec<Token<'a>>,
        errors: &mut Vec<Unterminated>,
    ) -> bool {
        tokens.clear();
        if self.pos >= self.bytes.len() {
            return false;
        }
        while let Some(&b) = self.bytes.get(self.pos) {
            match b {
                b'\n' => {
                    self.pos += 1;
                    return true;
                }
                b';' => self.skip_comment(),
                b'\\' => match self.continuation_end(self.pos + 1) {
                    Some(next) => self.pos = next,
                    None => tokens.push(self.word()),
                },
                b'"' => tokens.push(self.string(errors)),
                b if is_space(b) => self.pos += 1,
                b if PUNCT.contains(&b) => {
                    tokens.push(Token {
                        tok: Tok::Punct(b),
                        span: self.pos..self.pos + 1,
                    });
                    self.pos += 1;
                }
                _ => tokens.push(self.word()),
            }
        }
        true
    }

    fn skip_comment(&mut self) {
        // `pos` is at the `;`, an ASCII byte, so slicing the text there holds.
        self.pos = match self.text[self.pos..].find('\n') {
            Some(newline) => self.pos + newline,
            None => self.bytes.len(),
        };
    }

    /// If only blanks (and outside strings a comment) follow `from` up to the
    /// end of the line, the offset after that line's newline: the `\` before
    /// `from` continues the line.
    fn continuation_end(&self, from: usize) -> Option<usize> {
        let mut i = from;
        while let Some(&b) = self.bytes.get(i) {
            match b {
                b'\n' => return Some(i + 1),
                b';' => {
                    let newline = self.bytes[i..].iter().position(|&c| c == b'\n')?;
                    return Some(i + newline + 1);
                }
                b if is_space(b) => i += 1,
                _ => return None,
            }
        }
        Some(i)
    }

    fn word(&mut self) -> Token<'a> {
        let start = self.pos;
        while let Some(&b) = self.bytes.get(self.pos) {
            // A `\` stops the word only when it ends the line: then it
            // belongs to the line, not to the word.
            let ends_line = || self.pos > start && self.continuation_end(self.pos + 1).is_some();
            if WORD_STOPS[usize::from(b)] && (b != b'\\' || ends_line()) {
                break;
            }
            self.pos += 1;
        }
        if self.pos == start {
            // A lone `\` in the middle of a line: a word of its own.
            self.pos += 1;
        }
        Token {
            tok: Tok::Word,
            span: start..self.pos,
        }
    }

    /// A string literal. Inside it `;` is text, and `\` before the end of
    /// the line joins the next line (the newline is dropped).
    fn string(&mut self, errors: &mut Vec<Unterminated>) -> Token<'a> {
        let start = self.pos;
        self.pos += 1;
        // The pieces before each continuation; none for nearly every string.
        let mut joined: Option<String> = None;
        let mut piece = self.pos;
        let last_piece = loop {
            let Some(&b) = self.bytes.get(self.pos) else {
                errors.push(Unterminated {
                    span: start..self.pos,
                });
                break &self.text[piece..self.pos];
            };
            match b {
                b'"' => {
                    self.pos += 1;
                    break &self.text[piece..self.pos - 1];
                }
                b'\n' => {
                    let end = if self.bytes[self.pos - 1] == b'\r' {
                        self.pos - 1
                    } else {
                        self.pos
                    };
                    errors.push(Unterminated { span: start..end });
                    break self.text[piece..self.pos].trim_end_matches('\r');
                }
                b'\\' => match self.string_continuation(self.pos + 1) {
                    Some(next) => {
                        let before = &self.text[piece..self.pos];
                        joined.get_or_insert_with(String::new).push_str(before);
                        self.pos = next;
                        piece = next;
                    }
                    None => self.pos += 1,
                },
                _ => self.pos += 1,
            }
        };
        let value = match joined {
            None => Cow::Borrowed(last_piece),
            Some(mut value) => {
                value.push_str(last_piece);
                Cow::Owned(value)
            }
        };
        Token {
            tok: Tok::Str(value),
            span: start..self.pos,
        }
    }

    fn string_continuation(&self, from: usize) -> Option<usize> {
        let mut i = from;
        while let Some(&b) = self.bytes.get(i) {
            match b {
                b'\n' => return Some(i + 1),
                b if is_space(b) => i += 1,
                _ => return None,
            }
        }
        None
    }
}

/// Blanks between tokens: space, tab, the CR of CRLF, and the form feeds and
/// Ctrl-Z end markers that old DOS editors left in files.
const fn is_space(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\r' | 0x0b | 0x0c | 0x1a)
}

/// The bytes a word stops at, as a table: blanks, the end of the line, a
/// comment, a string, punctuation, and `\` (which ends a word only when it
/// continues the line).
const WORD_STOPS: [bool; 256] = {
    let mut stops = [false; 256];
    let mut b = 0;
    while b < 256 {
        let byte = b as u8;
        stops[b] = is_space(byte) || matches!(byte, b'\n' | b';' | b'"' | b'\\');
        b += 1;
    }
    let mut p = 0;
    while p < PUNCT.len() {
        stops[PUNCT[p] as usize] = true;
        p += 1;
    }
    stops
};

#[cfg(test)]
mod tests {
    use super::*;

    fn lines(text: &str) -> Vec<Vec<String>> {
        let mut lexer = Lexer::new(text, 0);
        let mut tokens = Vec::new();
        let mut errors = Vec::new();
        let mut out = Vec::new();
        while lexer.next_line(&mut tokens, &mut errors) {
            out.push(
                tokens
                    .iter()
                    .map(|t| match &t.tok {
                        Tok::Str(s) => format!("\"{s}\""),
                        _ => text[t.span.clone()].to_string(),
                    })
                    .collect(),
            );
        }
        out
    }

    #[test]
    fn continuation_with_comment_after_backslash() {
        let text = "A = 1,\\   ; c\r\n2\r\nB=3";
        assert_eq!(
            lines(text),
            vec![vec!["A", "=", "1", ",", "2"], vec!["B", "=", "3"]]
        );
    }

    #[test]
    fn continuation_inside_string_drops_newline() {
        let text = "Info_Text = \"ab \\\ncd\" ; x\n";
        assert_eq!(lines(text), vec![vec!["Info_Text", "=", "\"ab cd\""]]);
    }

    #[test]
    fn semicolon_in_string_is_text() {
        assert_eq!(lines("X=\"a;b\""), vec![vec!["X", "=", "\"a;b\""]]);
    }

    #[test]
    fn marker_is_case_insensitive_with_comment() {
        let text = "; head\n  #PROFIBUS_DP ; id\nX=1";
        let (span, next) = find_marker(text).unwrap();
        assert_eq!(&text[span], "#PROFIBUS_DP");
        assert_eq!(&text[next..], "X=1");
        assert!(find_marker("#Profibus_DPX\n").is_none());
    }
}
