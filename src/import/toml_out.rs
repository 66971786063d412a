//! A small writer of description TOML: tables, keys and values in the order
//! the import gives them, strings quoted as TOML basic strings.

use std::fmt::Write;

/// A description being written: its tables in order, each with its lines,
/// so that two imports (a GSD's and a GSDML file's) can be merged key by
/// key before it is written out.
#[derive(Default)]
pub(super) struct TomlOut {
    sections: Vec<Section>,
}

/// A table (`[name]` or `[[name]]`), or lines before any table or of
/// comments only (`header` empty).
#[derive(Clone)]
pub(super) struct Section {
    pub header: String,
    pub lines: Vec<Line>,
}

/// A key and its value written already, or a comment.
#[derive(Clone)]
pub(super) struct Line {
    pub key: Option<String>,
    pub text: String,
}

impl TomlOut {
    pub fn comment(&mut self, line: &str) {
        self.push(None, format!("# {line}"));
    }

    /// Comments after the tables so far, as a block of their own.
    pub fn comment_block(&mut self) {
        self.sections.push(Section {
            header: String::new(),
            lines: Vec::new(),
        });
    }

    /// `[name]`, after a blank line.
    pub fn table(&mut self, name: &str) {
        self.start(format!("[{name}]"));
    }

    /// `[[name]]`, after a blank line.
    pub fn array_item(&mut self, name: &str) {
        self.start(format!("[[{name}]]"));
    }

    /// `key = value`, the value written already (see [`quote`]).
    pub fn key(&mut self, key: &str, value: impl std::fmt::Display) {
        self.push(Some(key.to_string()), format!("{key} = {value}"));
    }

    pub fn string(&mut self, key: &str, value: &str) {
        self.key(key, quote(value));
    }

    fn start(&mut self, header: String) {
        self.sections.push(Section {
            header,
            lines: Vec::new(),
        });
    }

    fn push(&mut self, key: Option<String>, text: String) {
        if self.sections.is_empty() {
            self.comment_block();
        }
        if let Some(last) = self.sections.last_mut() {
            last.lines.push(Line { key, text });
        }
    }

    pub fn sections(self) -> Vec<Section> {
        self.sections
    }

    pub fn from_sections(sections: Vec<Section>) -> TomlOut {
        TomlOut { sections }
    }

    /// The text: each table after a blank line, a block of comments
    /// right after what comes before it.
    pub fn finish(self) -> String {
        let mut text = String::new();
        for section in self.sections {
            if !section.header.is_empty() {
                if !text.is_empty() {
                    text.push('\n');
                }
                let _ = writeln!(text, "{}", section.header);
            }
            for line in section.lines {
                let _ = writeln!(text, "{}", line.text);
            }
        }
        text
    }
}

/// A TOML basic string: `"`, `\` and control characters escaped.
pub(super) fn quote(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 2);
    out.push('"');
    // The runs between escapes are copied whole, and printable ASCII is
    // passed over by byte: a large file has a megabyte of texts, most of
    // them without any escape.
    let needs_look = |b: &u8| !crate::unicode::is_printable_ascii(*b) || matches!(b, b'"' | b'\\');
    let (mut run, mut at) = (0, 0);
    while let Some(skip) = text.as_bytes()[at..].iter().position(needs_look) {
        at += skip;
        // Every byte passed over was ASCII: a character starts here.
        let Some(c) = text[at..].chars().next() else {
            break;
        };
        let next = at + c.len_utf8();
        let short = match c {
            '"' => Some("\\\""),
            '\\' => Some("\\\\"),
            '\n' => Some("\\n"),
            '\t' => Some("\\t"),
            c if c.is_control() => None,
            _ => {
                at = next;
                continue;
            }
        };
        out.push_str(&text[run..at]);
        match short {
            Some(escape) => out.push_str(escape),
            None => {
                let _ = write!(out, "\\u{:04X}", u32::from(c));
            }
        }
        (run, at) = (next, next);
    }
    out.push_str(&text[run..]);
    out.push('"');
    out
}

/// `[a, b, c]` of values written already.
pub(super) fn list<T: std::fmt::Display>(items: impl IntoIterator<Item = T>) -> String {
    let items: Vec<String> = items.into_iter().map(|i| i.to_string()).collect();
    format!("[{}]", items.join(", "))
}

/// `0x1A`: bytes as the manuals and GSD files write them.
pub(super) fn hex(byte: u8) -> String {
    format!("0x{byte:02X}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strings_read_back_as_written() {
        for text in [
            "plain",
            "a \"quoted\" word",
            "back\\slash",
            "tab\there",
            "bell\u{7}",
            "– two\nlines, ± \u{85}C1 and \"end\"\n",
        ] {
            let doc = format!("k = {}", quote(text));
            let table: toml::Table = doc.parse().unwrap();
            assert_eq!(table["k"].as_str(), Some(text));
        }
    }
}
