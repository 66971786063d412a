//! How a drive names its parameters, so descriptions can write `F0-12`
//! where a number (0xF00C) is meant.
//!
//! A name is `<prefix><group><separator><index>`: the prefix's base plus the
//! group (in `group_radix`) make the address's high byte, the decimal index
//! its low byte. MD810 `F0-12` = 0xF00C, `A1-05` = 0xA105; Powtran `E3.05`
//! (prefix E = 0xA0) = 0xA305; MV810 `P43.02` (prefix P = 0, radix 10) = 0x2B02.

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Numbering {
    pub separator: String,
    pub group_radix: u32,
    /// Prefix and the high-byte base it stands for, longest prefix first.
    pub prefixes: Vec<(String, u8)>,
}

impl Numbering {
    pub fn new(separator: String, group_radix: u32, mut prefixes: Vec<(String, u8)>) -> Self {
        prefixes.sort_by(|a, b| b.0.len().cmp(&a.0.len()).then_with(|| a.0.cmp(&b.0)));
        Numbering {
            separator,
            group_radix,
            prefixes,
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
        let index = parse_digits(index, 10)
            .filter(|i| *i <= 0xFF)
            .ok_or_else(|| format!("`{index}` is not an index from 0 to 255"))?;
        let high = u32::from(*base) + group;
        if high > 0xFF {
            return Err(format!(
                "group `{prefix}{group}` is beyond the address space"
            ));
        }
        Ok((high << 8 | index) as u16)
    }

    /// The name of an address, when a prefix covers it: a group is one hex
    /// digit (F0..FF) or two decimal digits (P00..P99), as names write it.
    pub fn format(&self, address: u16) -> Option<String> {
        let [high, low] = address.to_be_bytes();
        let (prefix, base) = self
            .prefixes
            .iter()
            .filter(|(_, base)| *base <= high && u32::from(high - base) < self.groups())
            .max_by_key(|(_, base)| *base)?;
        let group = u32::from(high - base);
        let group = if self.group_radix == 16 {
            // One hex digit after a letter whose base is a multiple of 16 (F0..FF).
            format!("{group:X}")
        } else {
            format!("{group:02}")
        };
        Some(format!("{prefix}{group}{}{low:02}", self.separator))
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

    /// A name as the numbering writes it, for messages: the first prefix's
    /// first group, index 1 (`F0-01`, `P00.01`).
    pub fn example(&self) -> Option<String> {
        let (_, base) = self.prefixes.last()?;
        self.format(u16::from(*base) << 8 | 1)
    }
}

fn parse_digits(text: &str, radix: u32) -> Option<u32> {
    if text.is_empty() || text.len() > 3 || !(2..=36).contains(&radix) {
        return None;
    }
    u32::from_str_radix(text, radix).ok()
}

#[cfg(test)]
mod tests {
    use super::Numbering;

    fn md810() -> Numbering {
        Numbering::new("-".into(), 16, vec![("F".into(), 0xF0), ("A".into(), 0xA0)])
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
    }

    /// PI9000's d group is 70..7F: 0x8000 (a fault code's Modbus address)
    /// has no name, rather than `d10.00`.
    #[test]
    fn a_hex_group_is_one_digit() {
        let n = Numbering::new(".".into(), 16, vec![("d".into(), 0x70), ("F".into(), 0xF0)]);
        assert_eq!(n.format(0x7F01).as_deref(), Some("dF.01"));
        assert_eq!(n.format(0x8000), None);
    }

    #[test]
    fn decimal_groups_like_mv810() {
        let n = Numbering::new(".".into(), 10, vec![("P".into(), 0)]);
        assert_eq!(n.parse("P43.02"), Ok(0x2B02));
        assert_eq!(n.format(0x2B02).as_deref(), Some("P43.02"));
    }

    #[test]
    fn a_radix_no_number_system_has_is_an_error_not_a_panic() {
        let n = Numbering::new(".".into(), 54, vec![("P".into(), 0)]);
        assert!(n.parse("P43.02").is_err());
    }

    #[test]
    fn bad_names_say_why() {
        let n = md810();
        assert!(n.parse("X0-01").unwrap_err().contains("prefix"));
        assert!(n.parse("F0.01").unwrap_err().contains("separator"));
        assert!(n.parse("F0-256").unwrap_err().contains("index"));
        assert!(n.parse("FG-01").unwrap_err().contains("group"));
        assert!(n.parse("F").is_err());
    }
}
