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

    #[test]
    fn truncated_special_format_is_an_error() {
        assert_eq!(io_lengths(&[0xC1, 0x0F]), Err(CfgError { at: 0, needs: 3 }));
    }
}
