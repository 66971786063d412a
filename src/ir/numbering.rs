//! How a drive names its parameters, so descriptions can write `F0-12`
//! where a number (0xF00C) is meant.
//!
//! A name is `<prefix><group><separator><index>`. The prefix stands for a
//! base that is added to the group (written in `group_radix`); the
//! [`AddressScheme`] says how the sum and the decimal index make the address:
//! - [`AddressScheme::Bytes`]: the sum is the high byte, the index the low byte.
//!   MD810 `F0-12` = 0xF00C, `A1-05` = 0xA105; Powtran `E3.05` (prefix
//!   E = 0xA0) = 0xA305; MV810 `P43.02` (prefix P = 0, radix 10) = 0x2B02.
//! - [`AddressScheme::Decimal`]: the sum times 100 plus the index (0..99), a
//!   PROFIdrive parameter number: `P10.05` (prefix P = 0) = 1005, as Danfoss
//!   FC 300 numbers par. 3-41 as PNU 341 (Design Guide MG.33.BC.02 p.238).

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Numbering {
    pub separator: String,
    pub group_radix: u32,
    /// Prefix and the base it stands for, longest prefix first.
    pub prefixes: Vec<(String, u8)>,
    pub scheme: AddressScheme,
}

/// How the group and the index of a name make its address.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AddressScheme {
    /// (base + group) << 8 | index, the index 0..255.
    Bytes,
    /// (base + group) × 100 + index, the index 0..99; groups are decimal.
    Decimal,
}

impl Numbering {
    pub fn new(
        separator: String,
        group_radix: u32,
        mut prefixes: Vec<(String, u8)>,
        scheme: AddressScheme,
    ) -> Self {
        prefixes.sort_by(|a, b| b.0.len().cmp(&a.0.len()).then_with(|| a.0.cmp(&b.0)));
        Numbering {
            separator,
            group_radix,
            prefixes,
            scheme,
        }
    }

    /// The address of a parameter name, or why the name is not one.
    pub fn parse(&self, name: &str) -> Result<u16, String> {
        let (prefix, base) = self
            .prefixes
            .iter()
            .find(|(prefix, _)| name.starts_with(prefix.as_str()))
            .ok_or_else(|| format!("`{name}` does not start with a known prefix"))?;
        let rest = &name[prefix.len()..];
        let (group, index) = rest
            .split_once(self.separator.as_str())
            .ok_or_else(|| format!("`{name}` has no `{}` separator", self.separator))?;
        let group = parse_digits(group, self.group_radix)
            .filter(|g| *g < self.groups())
            .ok_or_else(|| match self.group_radix {
                16 => format!("`{group}` is not a group: one hex digit"),
                _ => format!("`{group}` is not a group: two decimal digits"),
            })?;
        let last_index = self.indexes() - 1;
        let index = parse_digits(index, 10)
            .filter(|i| *i <= last_index)
            .ok_or_else(|| format!("`{index}` is not an index from 0 to {last_index}"))?;
        let sum = u32::from(*base) + group;
        let address = match self.scheme {
            AddressScheme::Bytes if sum > 0xFF => {
                return Err(format!(
                    "group `{prefix}{group}` is beyond the address space"
                ))
            }
            AddressScheme::Bytes => sum << 8 | index,
            // At most (255 + 99) * 100 + 99 = 35499: always an address.
            AddressScheme::Decimal => sum * 100 + index,
        };
        Ok(address as u16)
    }

    /// The name of an address, when a prefix covers it: a group is one hex
    /// digit (F0..FF) or two decimal digits (P00..P99), as names write it.
    pub fn format(&self, address: u16) -> Option<String> {
        let (sum, index) = match self.scheme {
            AddressScheme::Bytes => {
                let [high, low] = address.to_be_bytes();
                (u32::from(high), u32::from(low))
            }
            AddressScheme::Decimal => (u32::from(address) / 100, u32::from(address) % 100),
        };
        let (prefix, base) = self
            .prefixes
            .iter()
            .filter(|(_, base)| u32::from(*base) <= sum && sum - u32::from(*base) < self.groups())
            .max_by_key(|(_, base)| *base)?;
        let group = sum - u32::from(*base);
        let group = if self.group_radix == 16 {
            // One hex digit after a letter whose base is a multiple of 16 (F0..FF).
            format!("{group:X}")
        } else {
            format!("{group:02}")
        };
        Some(format!("{prefix}{group}{}{index:02}", self.separator))
    }
}

impl Numbering {
    /// How many groups a prefix has: one hex digit's or two decimal digits'.
    fn groups(&self) -> u32 {
        if self.group_radix == 16 {
            16
        } else {
            100
        }
    }

    /// How many indexes a group has: a byte's, or two decimal digits'.
    fn indexes(&self) -> u32 {
        match self.scheme {
            AddressScheme::Bytes => 0x100,
            AddressScheme::Decimal => 100,
        }
    }

    /// A name as the numbering writes it, for messages: the first prefix's
    /// first group, index 1 (`F0-01`, `P00.01`).
    pub fn example(&self) -> Option<String> {
        let (_, base) = self.prefixes.last()?;
        let first = match self.scheme {
            AddressScheme::Bytes => u16::from(*base) << 8,
            AddressScheme::Decimal => u16::from(*base) * 100,
        };
        self.format(first + 1)
    }
}

/// A group or an index: at most three digits.
fn parse_digits(text: &str, radix: u32) -> Option<u32> {
    if text.len() > 3 {
        return None;
    }
    digits(text, radix)
}

/// `text` as a number written in `radix`, when it is digits only and fits
/// 32 bits. `str::parse` and `from_str_radix` also take a leading `+`, which
/// a description's number never has (`F+0-+12`, `slave_family = "+1"`).
pub fn digits(text: &str, radix: u32) -> Option<u32> {
    if text.is_empty() || !(2..=36).contains(&radix) || !text.chars().all(|c| c.is_digit(radix)) {
        return None;
    }
    u32::from_str_radix(text, radix).ok()
}

#[cfg(test)]
mod tests {
    use super::{AddressScheme, Numbering};

    fn md810() -> Numbering {
        Numbering::new(
            "-".into(),
            16,
            vec![("F".into(), 0xF0), ("A".into(), 0xA0)],
            AddressScheme::Bytes,
        )
    }

    fn decimal() -> Numbering {
        Numbering::new(
            ".".into(),
            10,
            vec![("P".into(), 0)],
            AddressScheme::Decimal,
        )
    }

    #[test]
    fn md810_names_are_the_manuals_addresses() {
        let n = md810();
        assert_eq!(n.parse("F0-12"), Ok(0xF00C));
        assert_eq!(n.parse("F0-12"), Ok(61452));
        assert_eq!(n.parse("F0-00"), Ok(61440));
        assert_eq!(n.parse("FD-20"), Ok(0xFD14));
        assert_eq!(n.parse("A1-05"), Ok(0xA105));
        assert_eq!(n.format(0xF00C).as_deref(), Some("F0-12"));
        assert_eq!(n.format(0xFD14).as_deref(), Some("FD-20"));
        assert_eq!(n.example().as_deref(), Some("F0-01"));
    }

    /// PI9000's d group is 70..7F: 0x8000 (a fault code's Modbus address)
    /// has no name, rather than `d10.00`.
    #[test]
    fn a_hex_group_is_one_digit() {
        let n = Numbering::new(
            ".".into(),
            16,
            vec![("d".into(), 0x70), ("F".into(), 0xF0)],
            AddressScheme::Bytes,
        );
        assert_eq!(n.format(0x7F01).as_deref(), Some("dF.01"));
        assert_eq!(n.format(0x8000), None);
    }

    #[test]
    fn decimal_groups_like_mv810() {
        let n = Numbering::new(".".into(), 10, vec![("P".into(), 0)], AddressScheme::Bytes);
        assert_eq!(n.parse("P43.02"), Ok(0x2B02));
        assert_eq!(n.format(0x2B02).as_deref(), Some("P43.02"));
    }

    /// The decimal scheme: group × 100 + index, both ways.
    #[test]
    fn p10_05_is_1005() {
        let n = decimal();
        assert_eq!(n.parse("P10.05"), Ok(1005));
        assert_eq!(n.parse("P10.5"), Ok(1005));
        assert_eq!(n.parse("P00.00"), Ok(0));
        assert_eq!(n.parse("P20.47"), Ok(2047));
        assert_eq!(n.parse("P99.99"), Ok(9999));
        assert_eq!(n.format(1005).as_deref(), Some("P10.05"));
        assert_eq!(n.format(5).as_deref(), Some("P00.05"));
        assert_eq!(n.format(9999).as_deref(), Some("P99.99"));
        assert_eq!(n.format(10_000), None, "group 100 has no two digits");
        assert_eq!(n.example().as_deref(), Some("P00.01"));
        for address in 0..10_000 {
            let name = n.format(address).unwrap();
            assert_eq!(n.parse(&name), Ok(address), "{name}");
        }
    }

    /// Danfoss FC 300 writes par. 3-41 without a letter: an empty prefix.
    #[test]
    fn a_decimal_prefix_adds_hundreds() {
        let danfoss = Numbering::new(
            "-".into(),
            10,
            vec![(String::new(), 0)],
            AddressScheme::Decimal,
        );
        assert_eq!(danfoss.parse("3-41"), Ok(341));
        assert_eq!(danfoss.parse("4-14"), Ok(0x19E));
        assert_eq!(danfoss.format(341).as_deref(), Some("03-41"));
        let n = Numbering::new(
            ".".into(),
            10,
            vec![("P".into(), 0), ("H".into(), 20)],
            AddressScheme::Decimal,
        );
        assert_eq!(n.parse("H00.01"), Ok(2001));
        assert_eq!(n.format(2001).as_deref(), Some("H00.01"));
        assert_eq!(n.format(1999).as_deref(), Some("P19.99"));
        assert_eq!(n.example().as_deref(), Some("P00.01"));
        let top = Numbering::new(
            ".".into(),
            10,
            vec![("Z".into(), 255)],
            AddressScheme::Decimal,
        );
        assert_eq!(top.parse("Z99.99"), Ok(35_499));
        assert_eq!(top.format(35_499).as_deref(), Some("Z99.99"));
    }

    #[test]
    fn a_decimal_index_has_two_digits() {
        let n = decimal();
        let why = n.parse("P10.100").unwrap_err();
        assert_eq!(why, "`100` is not an index from 0 to 99");
        assert!(n.parse("P100.05").unwrap_err().contains("group"));
        assert!(n.parse("P1A.05").unwrap_err().contains("group"));
        assert!(n.parse("P10-05").unwrap_err().contains("separator"));
    }

    #[test]
    fn a_radix_no_number_system_has_is_an_error_not_a_panic() {
        let n = Numbering::new(".".into(), 54, vec![("P".into(), 0)], AddressScheme::Bytes);
        assert!(n.parse("P43.02").is_err());
    }

    #[test]
    fn bad_names_say_why() {
        let n = md810();
        assert!(n.parse("X0-01").unwrap_err().contains("prefix"));
        assert!(n.parse("F0.01").unwrap_err().contains("separator"));
        assert_eq!(
            n.parse("F0-256").unwrap_err(),
            "`256` is not an index from 0 to 255"
        );
        assert!(n.parse("FG-01").unwrap_err().contains("group"));
        assert!(n.parse("F").is_err());
        assert!(n.parse("F+0-+12").unwrap_err().contains("group"));
        assert!(n.parse("F0-+12").unwrap_err().contains("index"));
    }
}
