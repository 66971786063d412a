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

/// The Latin-1 bytes of `text`, or the first character Latin-1 has not.
pub(crate) fn encode(text: &str) -> Result<Vec<u8>, char> {
    text.chars()
        .map(|c| u8::try_from(u32::from(c)).map_err(|_| c))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::{decode, encode};

    #[test]
    fn encoding_gives_back_the_bytes_decoded() {
        let all: Vec<u8> = (0..=255).collect();
        assert_eq!(encode(&decode(&all)), Ok(all));
        assert_eq!(encode("Größe °C"), Ok(b"Gr\xF6\xDFe \xB0C".to_vec()));
        assert_eq!(encode("汇川"), Err('汇'));
    }

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
