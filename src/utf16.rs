//! UTF-16 text, as some XML editors save GSDML files (and, by mistake,
//! GSD files): which byte order a file has, and its text.

/// The byte order of UTF-16 bytes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum ByteOrder {
    Little,
    Big,
}

/// Whether `bytes` look like UTF-16 and in which order: a byte order mark,
/// or a first character that is ASCII with its zero byte before or after
/// it (`<` `?` of an XML declaration, `;` of a GSD comment), as the XML
/// specification's appendix F detects an encoding without a mark. No
/// 8-bit text starts with a NUL byte or with a NUL after its first byte.
pub(crate) fn byte_order(bytes: &[u8]) -> Option<ByteOrder> {
    match bytes {
        [0xFF, 0xFE, ..] => Some(ByteOrder::Little),
        [0xFE, 0xFF, ..] => Some(ByteOrder::Big),
        [a, 0, ..] if a.is_ascii() && *a != 0 => Some(ByteOrder::Little),
        [0, b, ..] if b.is_ascii() && *b != 0 => Some(ByteOrder::Big),
        _ => None,
    }
}

/// The text of UTF-16 bytes without their byte order mark, or the offset
/// in `bytes` of the first unit that is not UTF-16 (an unpaired surrogate,
/// or a last byte without its pair).
pub(crate) fn decode(bytes: &[u8], order: ByteOrder) -> Result<String, usize> {
    let whole = bytes.len();
    let bytes = strip_mark(bytes, order);
    let mark = whole - bytes.len();
    let units = bytes.chunks_exact(2).map(|pair| match order {
        ByteOrder::Little => u16::from_le_bytes([pair[0], pair[1]]),
        ByteOrder::Big => u16::from_be_bytes([pair[0], pair[1]]),
    });
    let mut text = String::with_capacity(bytes.len() / 2);
    let mut at = mark;
    for c in char::decode_utf16(units) {
        let c = c.map_err(|_| at)?;
        at += 2 * c.len_utf16();
        text.push(c);
    }
    if bytes.len() % 2 == 1 {
        return Err(whole - 1);
    }
    Ok(text)
}

/// As much of the text of UTF-16 bytes as they hold, with U+FFFD for what
/// is not UTF-16: for looking at the start of a file.
pub(crate) fn decode_lossy(bytes: &[u8], order: ByteOrder) -> String {
    let units = strip_mark(bytes, order)
        .chunks_exact(2)
        .map(|pair| match order {
            ByteOrder::Little => u16::from_le_bytes([pair[0], pair[1]]),
            ByteOrder::Big => u16::from_be_bytes([pair[0], pair[1]]),
        });
    char::decode_utf16(units)
        .map(|c| c.unwrap_or(char::REPLACEMENT_CHARACTER))
        .collect()
}

fn strip_mark(bytes: &[u8], order: ByteOrder) -> &[u8] {
    let mark: &[u8] = match order {
        ByteOrder::Little => b"\xFF\xFE",
        ByteOrder::Big => b"\xFE\xFF",
    };
    bytes.strip_prefix(mark).unwrap_or(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn utf16le(text: &str, mark: bool) -> Vec<u8> {
        let mut bytes = if mark { vec![0xFF, 0xFE] } else { vec![] };
        bytes.extend(text.encode_utf16().flat_map(u16::to_le_bytes));
        bytes
    }

    fn utf16be(text: &str) -> Vec<u8> {
        text.encode_utf16().flat_map(u16::to_be_bytes).collect()
    }

    #[test]
    fn the_order_comes_from_the_mark_or_the_first_character() {
        assert_eq!(byte_order(&utf16le("<?xml", true)), Some(ByteOrder::Little));
        assert_eq!(
            byte_order(&utf16le("<?xml", false)),
            Some(ByteOrder::Little)
        );
        assert_eq!(byte_order(&utf16be("<?xml")), Some(ByteOrder::Big));
        assert_eq!(byte_order(b"\xFE\xFF\x00<"), Some(ByteOrder::Big));
        assert_eq!(byte_order(b"<?xml"), None);
        assert_eq!(byte_order(b"\xEF\xBB\xBF<?xml"), None);
        assert_eq!(byte_order(b"\0\0\0\0"), None, "zeros are no text");
        assert_eq!(byte_order(b"\xE4\0"), None, "Latin-1 then NUL is no UTF-16");
        assert_eq!(byte_order(b""), None);
    }

    #[test]
    fn text_in_either_order_with_a_character_beyond_the_bmp() {
        let text = "<a b=\"Größe 中 \u{1F600}\"/>";
        assert_eq!(
            decode(&utf16le(text, true), ByteOrder::Little).as_deref(),
            Ok(text)
        );
        assert_eq!(decode(&utf16be(text), ByteOrder::Big).as_deref(), Ok(text));
    }

    #[test]
    fn an_unpaired_surrogate_or_odd_byte_is_placed() {
        let mut bytes = utf16le("ab", false);
        bytes.extend([0x00, 0xD8]); // a high surrogate, then nothing
        bytes.extend(utf16le("c", false));
        assert_eq!(decode(&bytes, ByteOrder::Little), Err(4));
        assert_eq!(decode(b"a\0b", ByteOrder::Little), Err(2));
        let mut marked = utf16le("a", true);
        marked.extend([0x00, 0xDC]); // a low surrogate alone
        assert_eq!(decode(&marked, ByteOrder::Little), Err(4));
        assert_eq!(decode_lossy(&bytes, ByteOrder::Little), "ab\u{FFFD}c");
    }
}
