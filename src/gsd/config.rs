//! PROFIBUS config identifier bytes: how many input and output bytes a
//! module's `Module = "name" 0x..` list declares.
//!
//! General format (bits 5-4 not 00): bit 7 consistency, bit 6 words, bits 5-4
//! direction (01 input, 10 output, 11 both), bits 3-0 length - 1.
//! Special format (bits 5-4 = 00): bits 7-6 say which length bytes follow,
//! with the same code as the general format's direction (00 none, 01 input,
//! 10 output, 11 output then input), bits 3-0 how many manufacturer-specific
//! bytes follow them. The PA profile files of the corpus fix the meaning:
//! "Analog Input (AI)long" is `0x42,0x84,...` (5 bytes in), "SP (long)" is
//! `0x82,0x84,...` (5 bytes out), "SP+CHECKBACK" is `0xC3,0x84,0x82,...`
//! (5 out, 3 in). A length byte has bit 7
//! consistency, bit 6 words, bits 5-0 length - 1. `0x00` alone is an empty
//! slot.

/// Data bytes a module exchanges.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct IoLengths {
    pub input: u32,
    pub output: u32,
}

/// A special-format identifier announces more bytes than the list has.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct CfgError {
    /// Index of the special identifier in the list.
    pub at: usize,
    /// Bytes it announces after itself.
    pub needs: usize,
}

pub fn io_lengths(bytes: &[u8]) -> Result<IoLengths, CfgError> {
    let mut lengths = IoLengths::default();
    let mut i = 0;
    while i < bytes.len() {
        let id = bytes[i];
        if id & 0x30 != 0 {
            add_general(&mut lengths, id);
            i += 1;
        } else {
            i = add_special(&mut lengths, bytes, i)?;
        }
    }
    Ok(lengths)
}

/// Bytes of a length: bit 6 says words; the low `mask` bits are length - 1.
fn data_bytes(byte: u8, mask: u8) -> u32 {
    let count = u32::from(byte & mask) + 1;
    if byte & 0x40 != 0 {
        count * 2
    } else {
        count
    }
}

fn add_general(lengths: &mut IoLengths, id: u8) {
    let n = data_bytes(id, 0x0F);
    if id & 0x10 != 0 {
        lengths.input += n;
    }
    if id & 0x20 != 0 {
        lengths.output += n;
    }
}

/// Reads the special identifier at `at`; returns the index after it.
fn add_special(lengths: &mut IoLengths, bytes: &[u8], at: usize) -> Result<usize, CfgError> {
    let id = bytes[at];
    let has_input = id & 0x40 != 0;
    let has_output = id & 0x80 != 0;
    let manufacturer = usize::from(id & 0x0F);
    let needs = usize::from(has_output) + usize::from(has_input) + manufacturer;
    let Some(following) = bytes.get(at + 1..at + 1 + needs) else {
        return Err(CfgError { at, needs });
    };
    let mut length_bytes = following.iter();
    if has_output {
        lengths.output += length_bytes.next().map_or(0, |&b| data_bytes(b, 0x3F));
    }
    if has_input {
        lengths.input += length_bytes.next().map_or(0, |&b| data_bytes(b, 0x3F));
    }
    Ok(at + 1 + needs)
}

/// One config identifier as what it carries: the form a description
/// writes it in, and the bytes it is ([`Identifier::bytes`],
/// [`identifiers`]).
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum Identifier {
    /// One byte of the general format.
    General { direction: Direction, data: Length },
    /// The special format: the length bytes of each way it has, then the
    /// manufacturer-specific bytes. With neither way nor bytes, `0x00`: an
    /// empty place.
    Special {
        output: Option<Length>,
        input: Option<Length>,
        vendor: Vec<u8>,
    },
}

/// Which way a general identifier's data goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    Input,
    Output,
    Both,
}

/// A length of data: words or bytes, how many (1..=16 in the general
/// format, 1..=64 in a special format's length byte), consistent or not.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Length {
    pub words: bool,
    pub count: u8,
    pub consistent: bool,
}

/// The most units a general identifier and a length byte carry.
pub const MAX_GENERAL_COUNT: u8 = 16;
pub const MAX_SPECIAL_COUNT: u8 = 64;
/// The most manufacturer-specific bytes a special identifier announces.
pub const MAX_VENDOR_BYTES: usize = 14;

impl Length {
    /// Bit 7 consistency, bit 6 words, then `count - 1` in the low bits.
    fn bits(self) -> u8 {
        u8::from(self.consistent) << 7 | u8::from(self.words) << 6 | self.count.saturating_sub(1)
    }

    fn of(byte: u8, mask: u8) -> Length {
        Length {
            words: byte & 0x40 != 0,
            count: (byte & mask) + 1,
            consistent: byte & 0x80 != 0,
        }
    }
}

impl Identifier {
    /// The bytes of the identifier; the caller keeps counts within their
    /// format's limits.
    pub fn bytes(&self) -> Vec<u8> {
        match self {
            Identifier::General { direction, data } => {
                let way = match direction {
                    Direction::Input => 0x10,
                    Direction::Output => 0x20,
                    Direction::Both => 0x30,
                };
                vec![data.bits() & !0x30 | way]
            }
            Identifier::Special {
                output,
                input,
                vendor,
            } => {
                let header = u8::from(output.is_some()) << 7
                    | u8::from(input.is_some()) << 6
                    | (vendor.len() as u8 & 0x0F);
                let lengths = [output, input].into_iter().flatten().map(|l| l.bits());
                std::iter::once(header)
                    .chain(lengths)
                    .chain(vendor.iter().copied())
                    .collect()
            }
        }
    }
}

/// A module's config bytes as identifiers, or where a special identifier
/// announces more bytes than there are.
pub fn identifiers(bytes: &[u8]) -> Result<Vec<Identifier>, CfgError> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let id = bytes[i];
        if id & 0x30 != 0 {
            let direction = match id & 0x30 {
                0x10 => Direction::Input,
                0x20 => Direction::Output,
                _ => Direction::Both,
            };
            out.push(Identifier::General {
                direction,
                data: Length::of(id, 0x0F),
            });
            i += 1;
            continue;
        }
        let (has_output, has_input) = (id & 0x80 != 0, id & 0x40 != 0);
        let vendor = usize::from(id & 0x0F);
        let needs = usize::from(has_output) + usize::from(has_input) + vendor;
        let Some(following) = bytes.get(i + 1..i + 1 + needs) else {
            return Err(CfgError { at: i, needs });
        };
        let mut rest = following.iter();
        let mut length = |present: bool| {
            present
                .then(|| rest.next().map(|&b| Length::of(b, 0x3F)))
                .flatten()
        };
        let output = length(has_output);
        let input = length(has_input);
        out.push(Identifier::Special {
            output,
            input,
            vendor: rest.copied().collect(),
        });
        i += 1 + needs;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn io(bytes: &[u8]) -> (u32, u32) {
        let l = io_lengths(bytes).unwrap();
        (l.input, l.output)
    }

    #[test]
    fn ppo_types() {
        assert_eq!(io(&[0xF3, 0xF1]), (12, 12));
        assert_eq!(io(&[0xF3, 0xFB]), (32, 32));
        assert_eq!(io(&[0x00, 0xF1]), (4, 4));
        assert_eq!(io(&[0x10, 0x20]), (1, 1));
    }

    #[test]
    fn special_format_with_length_bytes_and_manufacturer_data() {
        // PA actuator: 5 bytes out, 10 bytes in, 7 manufacturer bytes.
        let cfg = [0xC7, 0x84, 0x89, 0x08, 0x05, 0x08, 0x05, 0x05, 0x05, 0x0A];
        assert_eq!(io(&cfg), (10, 5));
        // 16 bytes each way, one manufacturer byte.
        assert_eq!(io(&[0xC1, 0x0F, 0x0F, 0x00]), (16, 16));
        assert_eq!(io(&[0x42, 0x84, 0x08, 0x05]), (5, 0));
        assert_eq!(io(&[0x82, 0x84, 0x08, 0x05]), (0, 5));
        assert_eq!(io(&[0xC3, 0x84, 0x82, 0x08, 0x05, 0x0A]), (3, 5));
    }

    /// Every identifier of the corpus's drive modules reads and writes back
    /// to its bytes.
    #[test]
    fn identifiers_write_back_their_bytes() {
        for cfg in [
            &[0xF3, 0xF1][..],
            &[0x00, 0xE1, 0xD1],
            &[0xF3, 0x63, 0x53],
            &[0xE1, 0xD1, 0x01, 0xFE],
            &[0xF3, 0xC3, 0xC1, 0xC1, 0xFD, 0x01, 0x61],
            &[0xC6, 0x85, 0x85, 0x05, 0x05, 0x0A, 0x05, 0x05, 0x0A],
            &[0x10, 0x5F],
        ] {
            let ids = identifiers(cfg).unwrap();
            let back: Vec<u8> = ids.iter().flat_map(Identifier::bytes).collect();
            assert_eq!(back, cfg);
        }
        let ids = identifiers(&[0x00, 0xE1, 0xC3, 0xC1, 0xC1, 0xFD, 0x01, 0x61]).unwrap();
        assert_eq!(
            ids[0],
            Identifier::Special {
                output: None,
                input: None,
                vendor: vec![]
            }
        );
        let words = |count| Length {
            words: true,
            count,
            consistent: true,
        };
        assert_eq!(
            ids[1],
            Identifier::General {
                direction: Direction::Output,
                data: words(2)
            }
        );
        assert_eq!(
            ids[2],
            Identifier::Special {
                output: Some(words(2)),
                input: Some(words(2)),
                vendor: vec![0xFD, 0x01, 0x61]
            }
        );
        assert_eq!(
            identifiers(&[0xC1, 0x0F]),
            Err(CfgError { at: 0, needs: 3 })
        );
    }

    #[test]
    fn truncated_special_format_is_an_error() {
        assert_eq!(io_lengths(&[0xC1, 0x0F]), Err(CfgError { at: 0, needs: 3 }));
    }
}
