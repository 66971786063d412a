//! Characters that change how a text reads rather than what it says: the
//! one list of them, for every place that keeps them out of a file gsdc
//! writes or off a terminal, and the one way gsdc escapes them for a
//! terminal.

use crate::spec::is_bidi_control;
use std::borrow::Cow;

/// Control characters (C0, DEL, C1), the line and paragraph separators,
/// the bidirectional formatting characters (`crate::spec`'s one list of
/// them) and the Unicode noncharacters: a character that breaks a line, a
/// string or the reading order, or that a terminal takes as a command.
pub fn is_unsafe(c: char) -> bool {
    let code = u32::from(c);
    c.is_control()
        || matches!(c, '\u{2028}' | '\u{2029}')
        || is_bidi_control(c)
        || (0xFDD0..=0xFDEF).contains(&code)
        || code & 0xFFFE == 0xFFFE
}

/// The first character of `s` that is unsafe ([`is_unsafe`]) and that
/// `allowed` does not let through. Printable ASCII, nearly every byte of a
/// device file's texts, is passed over a byte at a time without decoding.
pub fn first_unsafe(s: &str, allowed: impl Fn(char) -> bool) -> Option<char> {
    let mut at = 0;
    while let Some(skip) = s.as_bytes()[at..]
        .iter()
        .position(|b| !is_printable_ascii(*b))
    {
        at += skip;
        // A byte that is not printable ASCII starts a character here.
        let c = s[at..].chars().next()?;
        if is_unsafe(c) && !allowed(c) {
            return Some(c);
        }
        at += c.len_utf8();
    }
    None
}

/// A byte that is a printable ASCII character on its own: no escape, no
/// control, no part of a longer UTF-8 sequence.
pub fn is_printable_ascii(b: u8) -> bool {
    (0x20..0x7F).contains(&b)
}

/// What a terminal is shown for `c` when `c` is unsafe ([`is_unsafe`]),
/// written as JSON writes it (`\n`, `\r`, `\t`, `\u001b`, `\u202e`);
/// `None` when `c` is shown as it is. The one escaping of gsdc's terminal
/// output: every line of a diagnostic, quoted or not, and every name.
pub fn escaped(c: char) -> Option<String> {
    match c {
        '\n' => Some("\\n".into()),
        '\r' => Some("\\r".into()),
        '\t' => Some("\\t".into()),
        c if is_unsafe(c) => Some(format!("\\u{:04x}", u32::from(c))),
        _ => None,
    }
}

/// `text` with every unsafe character [`escaped`]: a text that cannot
/// move the cursor, recolour the terminal, start a line that passes for
/// other output or reorder what is around it.
pub fn escape(text: &str) -> Cow<'_, str> {
    if !text.chars().any(is_unsafe) {
        return Cow::Borrowed(text);
    }
    let mut shown = String::with_capacity(text.len() + 8);
    for c in text.chars() {
        match escaped(c) {
            Some(escape) => shown.push_str(&escape),
            None => shown.push(c),
        }
    }
    Cow::Owned(shown)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn control_and_reordering_characters_are_escaped_as_json_escapes_them() {
        assert_eq!(escape("dist/A.GSD"), "dist/A.GSD");
        assert!(matches!(escape("Müller 中.gsd"), Cow::Borrowed(_)));
        assert_eq!(
            escape("a\nb: 0 error(s)\r\t\u{1b}[31m\u{7f}\u{9b}"),
            "a\\nb: 0 error(s)\\r\\t\\u001b[31m\\u007f\\u009b"
        );
        assert_eq!(escape("x\u{202E}lmx.dsg"), "x\\u202elmx.dsg");
        assert_eq!(escape("\u{061C}\u{2066}\u{2028}"), "\\u061c\\u2066\\u2028");
        assert_eq!(escape("\u{FFFE}\u{FDD0}"), "\\ufffe\\ufdd0");
    }

    #[test]
    fn the_first_unsafe_character_is_found_past_printable_and_other_text() {
        let none = |_| false;
        assert_eq!(first_unsafe("Drehzahl – Sollwert ± 中", none), None);
        assert_eq!(first_unsafe("x\u{7f}y", none), Some('\u{7f}'));
        assert_eq!(first_unsafe("ä\u{85}", none), Some('\u{85}'));
        assert_eq!(first_unsafe("ab\u{202E}c\u{1b}", none), Some('\u{202E}'));
        assert_eq!(first_unsafe("end\u{FFFF}", none), Some('\u{FFFF}'));
        // What `allowed` lets through is passed over.
        assert_eq!(first_unsafe("two\nlines\t", |c| c == '\n'), Some('\t'));
        assert_eq!(first_unsafe("two\nlines", |c| c == '\n'), None);
    }
}
