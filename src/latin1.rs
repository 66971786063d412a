//! ISO-8859-1 text, as many GSD and some GSDML files are written: each byte
//! is the character of that number.

/// The text of Latin-1 bytes. Blocks of ASCII, nearly all of any real file,
/// are copied whole rather than character by character.
pub(crate) fn decode(bytes: &[u8]) -> String {
    const BLOCK: usize = 64;
    let wide = bytes.iter().filter(|b| !b.is_ascii()).count();
    let mut text = String::with_capacity(bytes.len() + wide);
    for block in bytes.chunks(BLOCK) {
        // ASCII is UTF-8 as it stands; anything else is taken byte by byte.
        match block.is_ascii().then(|| std::str::from_utf8(block)) {
            Some(Ok(ascii)) => text.push_str(ascii),
            _ => text.extend(block.iter().map(|&b| char::from(b))),
        }
    }
    text
}

#[cfg(test)]
mod tests {
    use super::decode;

    #[test]
    fn every_byte_is_its_own_character() {
        let all: Vec<u8> = (0..=255).collect();
        let expected: String = (0..=255u8).map(char::from).collect();
        assert_eq!(decode(&all), expected);
        assert_eq!(decode(b"Gr\xF6\xDFe \xB0C"), "Größe °C");
        assert_eq!(decode(b"\xFF"), "ÿ");
        assert_eq!(decode(b""), "");
    }
}
