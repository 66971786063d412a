//! Bytes to text, text to XML tree. Everything that makes a file unreadable
//! is rule E300.

use std::borrow::Cow;

use crate::diag::InputLimit;
use crate::diag::{line_col, Diagnostic};
use crate::utf16;

/// The largest GSDML file gsdc reads: 15 times the largest in the corpus
/// (the 1.1 MB SEW file). Checking 16 MiB of real content takes about half
/// a second and 90 MB in a debug build.
pub const INPUT_LIMIT: InputLimit = InputLimit {
    max_bytes: 16 << 20,
    code: "E300",
    what: "a GSDML file",
    help: "the largest real GSDML files are a few megabytes: check that this is the right file",
};

/// Enough for the largest real GSDML files (the 1.1 MB SEW file has
/// 19 895 nodes) with a wide margin, small enough to bound memory on
/// hostile input. The shape pass refuses more than a million elements,
/// comments and instructions before roxmltree reads a byte, so this limit
/// is left to bound the text nodes between them, as a second guard.
const NODES_LIMIT: u32 = 4_000_000;

/// Parses GSDML text. DTDs are refused, never resolved (so no entity is
/// expanded and nothing is fetched); a text larger than [`INPUT_LIMIT`], a
/// document with more than `NODES_LIMIT` nodes, or one beyond the limits
/// of `shape` is refused.
pub fn parse(text: &str) -> Result<roxmltree::Document<'_>, Diagnostic> {
    INPUT_LIMIT.check(text.len())?;
    super::shape::check(text)?;
    let options = roxmltree::ParsingOptions {
        allow_dtd: false,
        nodes_limit: NODES_LIMIT,
        ..roxmltree::ParsingOptions::default()
    };
    roxmltree::Document::parse_with_options(text, options).map_err(|e| syntax_error(text, &e))
}

/// The elements of GSDML text as the device reader walks them
/// ([`super::tree`], which keeps `shape`'s bounds itself); `None` where
/// [`parse`] refuses the text (`gsdc check` says why).
pub(crate) fn parse_tree(text: &str) -> Option<super::tree::Tree<'_>> {
    INPUT_LIMIT.check(text.len()).ok()?;
    super::tree::Tree::parse(text)
}

fn syntax_error(text: &str, error: &roxmltree::Error) -> Diagnostic {
    let base = Diagnostic::error("E300", format!("the file is not well-formed XML: {error}"));
    match error {
        roxmltree::Error::DtdDetected => {
            let at = text.find("<!DOCTYPE").unwrap_or(0);
            base.at(at..at + "<!DOCTYPE".len().min(text.len() - at))
                .label("DTD here")
                .help("GSDML files have no DTD; remove the <!DOCTYPE ...> declaration")
        }
        roxmltree::Error::NodesLimitReached => base.help(format!(
            "the file has more than {NODES_LIMIT} XML nodes; no real GSDML file comes near that"
        )),
        _ => {
            let pos = error.pos();
            let at = offset_of(text, pos.row, pos.col);
            let end = text[at..].chars().next().map_or(at, |c| at + c.len_utf8());
            base.at(at..end)
                .label("here")
                .help("fix the XML syntax; an XML editor or `xmllint --noout` shows the same place")
        }
    }
}

/// Byte offset of a 1-based row and column (in characters), clamped to the text.
fn offset_of(text: &str, row: u32, col: u32) -> usize {
    let line_start = text
        .split_inclusive('\n')
        .take(row.saturating_sub(1) as usize)
        .map(str::len)
        .sum::<usize>();
    let line = &text[line_start..];
    line.char_indices()
        .nth(col.saturating_sub(1) as usize)
        .map_or(text.len(), |(i, _)| line_start + i)
}

/// Turns the bytes of a GSDML file into text, honouring the encoding of the
/// XML declaration: UTF-8 (the default), ISO-8859-1, which older vendor
/// files use, and UTF-16 (with a byte order mark, or detected from its
/// first character as XML's appendix F does), which some XML editors save.
/// Spans of later diagnostics refer to the returned text; lines and columns
/// are the same as in the file. More than [`INPUT_LIMIT`] bytes are refused
/// before they are decoded.
pub fn decode(bytes: &[u8]) -> Result<Cow<'_, str>, Diagnostic> {
    INPUT_LIMIT.check(bytes.len())?;
    if let Some(order) = utf16::byte_order(bytes) {
        return decode_utf16(bytes, order).map(Cow::Owned);
    }
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    let encoding = declared_encoding(bytes).unwrap_or_else(|| "utf-8".into());
    match encoding.as_str() {
        "utf-8" | "utf8" | "us-ascii" | "ascii" => std::str::from_utf8(bytes)
            .map(Cow::Borrowed)
            .map_err(|e| invalid_utf8(bytes, e.valid_up_to())),
        "iso-8859-1" | "iso8859-1" | "iso_8859-1" | "latin1" | "latin-1" | "l1" => {
            Ok(Cow::Owned(crate::latin1::decode(bytes)))
        }
        "utf-16" | "utf-16le" | "utf-16be" => Err(Diagnostic::error(
            "E300",
            format!("the file declares encoding \"{encoding}\" but is not UTF-16: its first characters are one byte each"),
        )
        .help("declare the encoding the file is saved in (encoding=\"UTF-8\"), or save it as UTF-16 with a byte order mark")),
        other => Err(Diagnostic::error("E300", format!("unsupported encoding \"{other}\""))
            .help("save the file as UTF-8 (or ISO-8859-1) and declare it in <?xml ... encoding=\"UTF-8\"?>")),
    }
}

/// UTF-16 text, which must declare a UTF-16 encoding or none.
fn decode_utf16(bytes: &[u8], order: utf16::ByteOrder) -> Result<String, Diagnostic> {
    let text = utf16::decode(bytes, order).map_err(|at| invalid_utf16(bytes, order, at))?;
    match declared_encoding(text.as_bytes()) {
        None => Ok(text),
        Some(e) if e.starts_with("utf-16") || e == "utf16" => Ok(text),
        Some(other) => Err(Diagnostic::error(
            "E300",
            format!("the file is UTF-16 but declares encoding \"{other}\""),
        )
        .help("declare encoding=\"UTF-16\", or save the file in the encoding it declares")),
    }
}

fn invalid_utf16(bytes: &[u8], order: utf16::ByteOrder, at: usize) -> Diagnostic {
    let valid = utf16::decode_lossy(&bytes[..at], order);
    let (line, column) = line_col(&valid, valid.len());
    Diagnostic::error(
        "E300",
        format!("the file is not valid UTF-16: an unpaired surrogate or odd byte at line {line}, column {column}"),
    )
    .help("save the file again from an editor that writes UTF-16 correctly, or as UTF-8")
}

/// The lower-cased `encoding` of the XML declaration, if there is one.
fn declared_encoding(bytes: &[u8]) -> Option<String> {
    let head = bytes.strip_prefix(b"<?xml")?;
    let end = head.windows(2).position(|w| w == b"?>")?;
    let declaration = std::str::from_utf8(&head[..end]).ok()?;
    let after = &declaration[declaration.find("encoding")? + "encoding".len()..];
    let after = after.trim_start().strip_prefix('=')?.trim_start();
    let quote = after.chars().next().filter(|c| *c == '"' || *c == '\'')?;
    let value = &after[1..];
    Some(value[..value.find(quote)?].to_ascii_lowercase())
}

fn invalid_utf8(bytes: &[u8], at: usize) -> Diagnostic {
    // The text is not valid UTF-8, so lines are counted on the valid prefix.
    let valid = std::str::from_utf8(&bytes[..at]).unwrap_or_default();
    let (line, column) = line_col(valid, valid.len());
    Diagnostic::error(
        "E300",
        format!("the file is not valid UTF-8: byte 0x{:02X} at line {line}, column {column}", bytes[at]),
    )
    .help("declare the real encoding in the XML declaration (encoding=\"iso-8859-1\") or save the file as UTF-8")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn latin1_is_decoded_by_declaration() {
        let bytes = b"<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?><a b=\"\xE4\"/>";
        assert_eq!(
            decode(bytes).unwrap(),
            "<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?><a b=\"\u{e4}\"/>"
        );
    }

    #[test]
    fn undeclared_latin1_is_an_error_with_position() {
        let d = decode(b"<a>\n\xE4</a>").unwrap_err();
        assert_eq!(d.code, "E300");
        assert!(d.message.contains("line 2, column 1"), "{}", d.message);
    }

    fn utf16(text: &str, order: utf16::ByteOrder, mark: bool) -> Vec<u8> {
        let units = text.encode_utf16();
        let mut bytes: Vec<u8> = match order {
            utf16::ByteOrder::Little => units.flat_map(u16::to_le_bytes).collect(),
            utf16::ByteOrder::Big => units.flat_map(u16::to_be_bytes).collect(),
        };
        if mark {
            bytes.splice(
                0..0,
                "\u{FEFF}".encode_utf16().flat_map(match order {
                    utf16::ByteOrder::Little => u16::to_le_bytes,
                    utf16::ByteOrder::Big => u16::to_be_bytes,
                }),
            );
        }
        bytes
    }

    #[test]
    fn utf16_that_declares_it_is_decoded_in_either_order() {
        let text = "<?xml version=\"1.0\" encoding=\"UTF-16\"?>\n<a b=\"\u{e4}\u{4e2d}\"/>";
        for order in [utf16::ByteOrder::Little, utf16::ByteOrder::Big] {
            for mark in [true, false] {
                assert_eq!(decode(&utf16(text, order, mark)).unwrap(), text);
            }
        }
        let undeclared = "<a/>";
        assert_eq!(
            decode(&utf16(undeclared, utf16::ByteOrder::Little, true)).unwrap(),
            undeclared
        );
    }

    #[test]
    fn utf16_declaring_another_encoding_or_broken_is_e300() {
        let lying = "<?xml version=\"1.0\" encoding=\"UTF-8\"?><a/>";
        let d = decode(&utf16(lying, utf16::ByteOrder::Little, true)).unwrap_err();
        assert!(
            d.message
                .contains("is UTF-16 but declares encoding \"utf-8\""),
            "{}",
            d.message
        );
        let mut broken = utf16("<a>\n", utf16::ByteOrder::Little, true);
        broken.extend([0x00, 0xD8, b'x', 0]);
        let d = decode(&broken).unwrap_err();
        assert!(
            d.message.contains("not valid UTF-16") && d.message.contains("line 2, column 1"),
            "{}",
            d.message
        );
        let d = decode(b"<?xml version=\"1.0\" encoding=\"UTF-16\"?><a/>").unwrap_err();
        assert!(d.message.contains("but is not UTF-16"), "{}", d.message);
    }

    #[test]
    fn offset_of_counts_characters() {
        assert_eq!(offset_of("ab\n\u{e4}x", 2, 2), 5);
        assert_eq!(offset_of("ab", 9, 9), 2);
    }
}
