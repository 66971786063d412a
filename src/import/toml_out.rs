//! A small writer of description TOML: tables, keys and values in the order
//! the import gives them, strings quoted as TOML basic strings.

use std::fmt::Write;

#[derive(Default)]
pub(super) struct TomlOut {
    text: String,
}

impl TomlOut {
    pub fn comment(&mut self, line: &str) {
        let _ = writeln!(self.text, "# {line}");
    }

    /// `[name]`, after a blank line.
    pub fn table(&mut self, name: &str) {
        self.blank();
        let _ = writeln!(self.text, "[{name}]");
    }

    /// `[[name]]`, after a blank line.
    pub fn array_item(&mut self, name: &str) {
        self.blank();
        let _ = writeln!(self.text, "[[{name}]]");
    }

    /// `key = value`, the value written already (see [`quote`]).
    pub fn key(&mut self, key: &str, value: impl std::fmt::Display) {
        let _ = writeln!(self.text, "{key} = {value}");
    }

    pub fn string(&mut self, key: &str, value: &str) {
        self.key(key, quote(value));
    }

    fn blank(&mut self) {
        if !self.text.is_empty() && !self.text.ends_with("\n\n") {
            self.text.push('\n');
        }
    }

    pub fn finish(self) -> String {
        self.text
    }
}

/// A TOML basic string: `"`, `\` and control characters escaped.
pub(super) fn quote(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 2);
    out.push('"');
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\t' => out.push_str("\\t"),
            c if c.is_control() => {
                let _ = write!(out, "\\u{:04X}", u32::from(c));
            }
            c => out.push(c),
        }
    }
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
        ] {
            let doc = format!("k = {}", quote(text));
            let table: toml::Table = doc.parse().unwrap();
            assert_eq!(table["k"].as_str(), Some(text));
        }
    }
}
