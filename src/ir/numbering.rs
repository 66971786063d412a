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
//!
//! Many drives write no separator (Siemens' MICROMASTER 440 parameter list
//! `r0948`, `P2115`; ABB's ACS355 manual `2202`): the description gives the
//! [`Widths`] of the group and the index
//! instead, and a name has exactly that many digits, leading zeros
//! included. In the decimal scheme the index's digits make the multiplier
//! (10 to the index's width), so the digits after the prefix read as one
//! number: `P1120` with widths 2 and 2 is group 11, index 20, parameter
//! 1120, as Siemens numbers it. With widths, a name is read only as it is
//! written back (`P947` and `P09.47` are refused where `P0947` is the
//! form), so that every name reads and writes back the same.

use crate::description::digits;
use std::collections::BTreeMap;

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Numbering {
    pub separator: String,
    pub group_radix: u32,
    /// Prefix and the base it stands for, longest prefix first.
    pub prefixes: Vec<(String, u8)>,
    pub scheme: AddressScheme,
    /// The digits of a group and of an index, when the description fixes
    /// them; without, a group is one hex or two decimal digits and an index
    /// at least two, and names with fewer are read too.
    pub widths: Option<Widths>,
    /// The prefix the description writes each address it names with, where
    /// two prefixes could (Siemens' `P` and `r` both start at 0): an address
    /// is written back with its description's prefix.
    pub written_prefixes: BTreeMap<u16, String>,
}

/// How many digits a group and an index have (1 to 3 each).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Widths {
    pub group: u8,
    pub index: u8,
}

/// How the group and the index of a name make its address.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AddressScheme {
    /// (base + group) << 8 | index, the index 0..255.
    Bytes,
    /// (base + group) × 10^(index digits) + index: × 100 and 0..99 unless
    /// the description's widths say otherwise; groups are decimal.
    Decimal,
}

/// A name read: its address and the prefix it was written with.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Named<'a> {
    pub address: u16,
    pub prefix: &'a str,
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
            widths: None,
            written_prefixes: BTreeMap::new(),
        }
    }

    /// The numbering with names of exactly these widths.
    pub fn with_widths(mut self, widths: Widths) -> Self {
        self.widths = Some(widths);
        self
    }

    /// The address of a parameter name, or why the name is not one.
    pub fn parse(&self, name: &str) -> Result<u16, String> {
        self.read(name).map(|named| named.address)
    }

    /// The address of a parameter name and its prefix, or why the name is
    /// not one.
    pub fn read<'a>(&'a self, name: &str) -> Result<Named<'a>, String> {
        let (prefix, base) = self
            .prefixes
            .iter()
            .find(|(prefix, _)| name.starts_with(prefix.as_str()))
            .ok_or_else(|| {
                format!(
                    "`{name}` does not start with a known prefix ({})",
                    self.prefix_list()
                )
            })?;
        let rest = &name[prefix.len()..];
        let (group, index) = self.split(name, rest)?;
        let group = self.group_value(group)?;
        let index = self.index_value(index)?;
        let address = self
            .address(u32::from(*base) + group, index)
            .ok_or_else(|| format!("`{name}` is beyond the address space"))?;
        let canonical = self.compose(prefix, group, index);
        if self.widths.is_some() && canonical != name {
            return Err(format!("the description writes it `{canonical}`"));
        }
        Ok(Named { address, prefix })
    }

    /// The name of an address, when a prefix covers it: with the prefix the
    /// description writes it with, else the one of the highest base (of two
    /// of one base, the first in the prefixes' order: `P` before `r`); the
    /// group and the index in their widths (without widths, a group is one
    /// hex digit, F0..FF, or two decimal digits, P00..P99).
    pub fn format(&self, address: u16) -> Option<String> {
        let (sum, index) = match self.scheme {
            AddressScheme::Bytes => {
                let [high, low] = address.to_be_bytes();
                (u32::from(high), u32::from(low))
            }
            AddressScheme::Decimal => {
                let multiplier = self.multiplier();
                (
                    u32::from(address) / multiplier,
                    u32::from(address) % multiplier,
                )
            }
        };
        if index >= self.indexes() {
            return None;
        }
        let covers = |(_, base): &&(String, u8)| {
            u32::from(*base) <= sum && sum - u32::from(*base) < self.groups()
        };
        let written = self.written_prefixes.get(&address);
        let (prefix, base) = self
            .prefixes
            .iter()
            .filter(covers)
            .find(|(prefix, _)| Some(prefix) == written)
            // `max_by_key` keeps the last of equal bases: reversed, the
            // first in the prefixes' order (the longest, then A..Z, a..z).
            .or_else(|| {
                self.prefixes
                    .iter()
                    .rev()
                    .filter(covers)
                    .max_by_key(|(_, base)| *base)
            })?;
        Some(self.compose(prefix, sum - u32::from(*base), index))
    }

    /// How the description writes its names, for a help line:
    /// `<prefix><group>-<index> (prefix F or A)`, `<prefix>GGII (prefix P or
    /// r; G a digit of the group, I of the index)`.
    pub fn form(&self) -> String {
        let prefixes = self.prefix_list();
        match self.widths {
            None => format!(
                "<prefix><group>{}<index> (prefix {prefixes})",
                self.separator
            ),
            Some(w) => format!(
                "<prefix>{}{}{} (prefix {prefixes}; G a digit of the group, I of the index)",
                "G".repeat(w.group.into()),
                self.separator,
                "I".repeat(w.index.into())
            ),
        }
    }

    /// A name as the numbering writes it, for messages: the first prefix's
    /// first group, index 1 (`F0-01`, `P00.01`, `P0001`).
    pub fn example(&self) -> Option<String> {
        let (_, base) = self.prefixes.last()?;
        self.format(self.address(u32::from(*base), 1)?)
    }
}

impl Numbering {
    /// The group and the index of what follows the prefix.
    fn split<'n>(&self, name: &str, rest: &'n str) -> Result<(&'n str, &'n str), String> {
        match self.widths {
            Some(w) if self.separator.is_empty() => {
                let (group, index) = (usize::from(w.group), usize::from(w.index));
                if rest.len() != group + index || !rest.is_char_boundary(group) {
                    return Err(format!(
                        "{} characters follow its prefix; the description's names have {} digits, {group} of the group and {index} of the index",
                        rest.chars().count(),
                        group + index
                    ));
                }
                Ok(rest.split_at(group))
            }
            _ => rest
                .split_once(self.separator.as_str())
                .ok_or_else(|| format!("`{name}` has no `{}` separator", self.separator)),
        }
    }

    fn group_value(&self, group: &str) -> Result<u32, String> {
        let most = match self.widths {
            Some(w) => usize::from(w.group),
            None => 3,
        };
        (group.len() <= most)
            .then(|| digits(group, self.group_radix))
            .flatten()
            .filter(|g| *g < self.groups())
            .ok_or_else(|| match (self.widths, self.group_radix) {
                (Some(w), 16) => format!("`{group}` is not a group: {} hex digit(s)", w.group),
                (Some(w), _) => format!("`{group}` is not a group: {} decimal digit(s)", w.group),
                (None, 16) => format!("`{group}` is not a group: one hex digit"),
                (None, _) => format!("`{group}` is not a group: two decimal digits"),
            })
    }

    fn index_value(&self, index: &str) -> Result<u32, String> {
        let last_index = self.indexes() - 1;
        parse_digits(index, 10)
            .filter(|i| *i <= last_index)
            .ok_or_else(|| format!("`{index}` is not an index from 0 to {last_index}"))
    }

    /// The address of a group's sum with its base and an index, if there is
    /// one: a byte's sum in the bytes scheme, 16 bits in all.
    fn address(&self, sum: u32, index: u32) -> Option<u16> {
        let address = match self.scheme {
            AddressScheme::Bytes if sum > 0xFF => return None,
            AddressScheme::Bytes => sum << 8 | index,
            AddressScheme::Decimal => sum * self.multiplier() + index,
        };
        u16::try_from(address).ok()
    }

    /// The digits of a group and of an index as names are written: the
    /// description's widths, else one hex digit after a letter whose base
    /// is a multiple of 16 (F0..FF) or two decimal digits (P43), and two of
    /// the index.
    pub fn digits(&self) -> (u8, u8) {
        match self.widths {
            Some(w) => (w.group, w.index),
            None if self.group_radix == 16 => (1, 2),
            None => (2, 2),
        }
    }

    /// `prefix`, `group` and `index` as the description writes a name.
    fn compose(&self, prefix: &str, group: u32, index: u32) -> String {
        let (group_digits, index_digits) = self.digits();
        let (group_digits, index_digits) = (usize::from(group_digits), usize::from(index_digits));
        let group = if self.group_radix == 16 {
            format!("{group:0group_digits$X}")
        } else {
            format!("{group:0group_digits$}")
        };
        format!("{prefix}{group}{}{index:0index_digits$}", self.separator)
    }

    /// How many groups a prefix has: its digits' (one hex digit's or two
    /// decimal digits' without widths).
    fn groups(&self) -> u32 {
        let digits = self
            .widths
            .map_or(if self.group_radix == 16 { 1 } else { 2 }, |w| w.group);
        self.group_radix.saturating_pow(digits.into())
    }

    /// How many indexes a group has: a byte's, or two decimal digits', at
    /// most what the index's digits write.
    fn indexes(&self) -> u32 {
        let scheme = match self.scheme {
            AddressScheme::Bytes => 0x100,
            AddressScheme::Decimal => self.multiplier(),
        };
        match self.widths {
            Some(w) => scheme.min(10u32.pow(w.index.into())),
            None => scheme,
        }
    }

    /// What the decimal scheme multiplies a group by: 10 to the index's
    /// digits, 100 without widths.
    fn multiplier(&self) -> u32 {
        10u32.pow(self.widths.map_or(2, |w| w.index).into())
    }

    /// The prefixes for a message, in their order: `A or F`, `H, P or r`.
    fn prefix_list(&self) -> String {
        let names: Vec<String> = self
            .prefixes
            .iter()
            .map(|(p, _)| {
                if p.is_empty() {
                    "none".to_string()
                } else {
                    p.clone()
                }
            })
            .collect();
        match names.split_last() {
            Some((last, [])) => last.clone(),
            Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
            None => "none".to_string(),
        }
    }
}

/// A group or an index: at most three digits.
fn parse_digits(text: &str, radix: u32) -> Option<u32> {
    if text.len() > 3 {
        return None;
    }
    digits(text, radix)
}

#[cfg(test)]
mod tests {
    use super::{AddressScheme, Numbering, Widths};

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

    /// Siemens writes P1120 and r0947: no separator, four digits, the
    /// number the parameter's; both letters start at 0 (MICROMASTER 440).
    fn siemens() -> Numbering {
        Numbering::new(
            String::new(),
            10,
            vec![("P".into(), 0), ("r".into(), 0)],
            AddressScheme::Decimal,
        )
        .with_widths(Widths { group: 2, index: 2 })
    }

    #[test]
    fn names_without_a_separator_read_as_their_number() {
        let n = siemens();
        assert_eq!(n.parse("P1120"), Ok(1120));
        assert_eq!(n.parse("r0947"), Ok(947));
        assert_eq!(n.parse("P0000"), Ok(0));
        assert_eq!(n.parse("P9999"), Ok(9999));
        assert_eq!(n.read("r0947").unwrap().prefix, "r");
        // Leading zeros are written: a name has exactly its four digits.
        assert!(n
            .parse("P947")
            .unwrap_err()
            .contains("have 4 digits, 2 of the group and 2 of the index"));
        assert!(n
            .parse("P09470")
            .unwrap_err()
            .starts_with("5 characters follow its prefix"));
        assert!(n.parse("P11.2").is_err());
        assert!(n.parse("P+120").unwrap_err().contains("group"));
        assert!(
            n.parse("X1120").unwrap_err().contains("(P or r)"),
            "{:?}",
            n.parse("X1120")
        );
        assert_eq!(
            n.format(1120).as_deref(),
            Some("P1120"),
            "of one base, the first prefix, without a written one"
        );
        assert_eq!(n.format(10_000), None);
        assert_eq!(n.example().as_deref(), Some("P0001"));
        assert_eq!(
            n.form(),
            "<prefix>GGII (prefix P or r; G a digit of the group, I of the index)"
        );
    }

    /// An address the description names is written back with its prefix.
    #[test]
    fn an_address_keeps_the_prefix_the_description_writes() {
        let mut n = siemens();
        n.written_prefixes.insert(1120, "P".into());
        n.written_prefixes.insert(947, "r".into());
        assert_eq!(n.format(1120).as_deref(), Some("P1120"));
        assert_eq!(n.format(947).as_deref(), Some("r0947"));
        // A prefix that does not cover the address is not taken.
        n.written_prefixes.insert(5, "Q".into());
        assert_eq!(n.format(5).as_deref(), Some("P0005"));
    }

    /// ABB's ACS355 manual writes 2202 (group 22, index 02): no letter.
    #[test]
    fn a_name_may_be_digits_alone() {
        let n = Numbering::new(
            String::new(),
            10,
            vec![(String::new(), 0)],
            AddressScheme::Decimal,
        )
        .with_widths(Widths { group: 2, index: 2 });
        assert_eq!(n.parse("2202"), Ok(2202));
        assert_eq!(n.parse("9902"), Ok(9902));
        assert_eq!(n.format(2910).as_deref(), Some("2910"));
        assert_eq!(
            n.form(),
            "<prefix>GGII (prefix none; G a digit of the group, I of the index)"
        );
        let bytes = Numbering::new(
            String::new(),
            10,
            vec![(String::new(), 0)],
            AddressScheme::Bytes,
        )
        .with_widths(Widths { group: 2, index: 2 });
        assert_eq!(bytes.parse("2910"), Ok(29 << 8 | 10));
        assert_eq!(
            bytes.format(29 << 8 | 100),
            None,
            "index 100 has no two digits"
        );
    }

    /// Widths with a separator: the names as the description writes them.
    #[test]
    fn widths_with_a_separator_fix_the_digits() {
        let n = Numbering::new(
            "-".into(),
            16,
            vec![("F".into(), 0xF0)],
            AddressScheme::Bytes,
        )
        .with_widths(Widths { group: 1, index: 3 });
        assert_eq!(n.parse("F0-012"), Ok(0xF00C));
        assert_eq!(n.format(0xF00C).as_deref(), Some("F0-012"));
        assert_eq!(
            n.parse("F0-12"),
            Err("the description writes it `F0-012`".into())
        );
        assert_eq!(
            n.parse("Fa-012"),
            Err("the description writes it `FA-012`".into())
        );
        assert_eq!(
            n.form(),
            "<prefix>G-III (prefix F; G a digit of the group, I of the index)"
        );
        let wide = Numbering::new(
            String::new(),
            10,
            vec![("P".into(), 0)],
            AddressScheme::Decimal,
        )
        .with_widths(Widths { group: 3, index: 2 });
        assert_eq!(wide.parse("P65535"), Ok(65535));
        assert!(wide
            .parse("P65536")
            .unwrap_err()
            .contains("beyond the address space"));
        assert_eq!(wide.format(65535).as_deref(), Some("P65535"));
    }

    /// Every name a numbering with widths reads writes back the same, and
    /// every address it writes reads back: over every string of the name's
    /// length for one prefix (hex digits in both cases), so nothing it
    /// reads is missed. (Two prefixes of one base write an address one
    /// way: the description's, `an_address_keeps_the_prefix_...`.)
    #[test]
    fn with_widths_every_name_reads_and_writes_back_the_same() {
        let numberings = [
            Numbering::new(
                String::new(),
                10,
                vec![("P".into(), 0)],
                AddressScheme::Decimal,
            )
            .with_widths(Widths { group: 2, index: 2 }),
            Numbering::new(
                String::new(),
                16,
                vec![("F".into(), 0xF0)],
                AddressScheme::Bytes,
            )
            .with_widths(Widths { group: 1, index: 3 }),
            Numbering::new(".".into(), 10, vec![("P".into(), 0)], AddressScheme::Bytes)
                .with_widths(Widths { group: 2, index: 2 }),
            Numbering::new(
                String::new(),
                10,
                vec![(String::new(), 3)],
                AddressScheme::Decimal,
            )
            .with_widths(Widths { group: 1, index: 3 }),
        ];
        for n in numberings {
            let w = n.widths.unwrap();
            let (prefix, _) = n.prefixes[0].clone();
            let alphabet: Vec<char> = "0123456789ABCDEFabcdef".chars().collect();
            let digits = usize::from(w.group + w.index);
            let mut read = 0;
            for k in 0..alphabet.len().pow(digits as u32) {
                let mut rest: String = (0..digits)
                    .map(|d| alphabet[k / alphabet.len().pow(d as u32) % alphabet.len()])
                    .collect();
                rest.insert_str(usize::from(w.group), &n.separator);
                let name = format!("{prefix}{rest}");
                if let Ok(address) = n.parse(&name) {
                    read += 1;
                    assert_eq!(n.format(address).as_deref(), Some(name.as_str()));
                }
            }
            let mut written = 0;
            for address in 0..=u16::MAX {
                if let Some(name) = n.format(address) {
                    written += 1;
                    assert_eq!(n.parse(&name), Ok(address), "{name}");
                }
            }
            assert_eq!(read, written, "{n:?}");
            assert!(written > 0);
        }
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
