// How a drive numbers its parameters (gsdc templates/support/numbering.rs):
// a layout's `NUMBERING` reads a name as the manual writes it (`F0-08`) into
// the address the telegrams carry (0xF008) and writes an address back as a
// name, as gsdc reads and writes the description's names.

/// A drive's parameter names: `<prefix><group><separator><index>`, the
/// prefix standing for a base added to the group.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Numbering {
    /// Between the group and the index: `-`, `.`, or nothing when
    /// `exact_digits` fixes where the group ends.
    pub separator: &'static str,
    /// 16: a group is hex (`F0`..`FF`); 10: decimal (`P43`).
    pub group_radix: u8,
    /// Every prefix with its base, the longest first.
    pub prefixes: &'static [NumberingPrefix],
    pub scheme: AddressScheme,
    /// The digits of a group and of an index as names are written back.
    pub group_digits: u8,
    pub index_digits: u8,
    /// Whether a name has exactly these digits (the description fixes
    /// them); otherwise fewer are read too, at most three.
    pub exact_digits: bool,
    /// Addresses the description writes with a prefix other than the one
    /// [`Numbering::name`] would choose among prefixes of one base.
    pub written: &'static [WrittenPrefix],
}

/// A prefix and the base it stands for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NumberingPrefix {
    pub prefix: &'static str,
    pub base: u8,
}

/// The prefix the description writes `address` with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct WrittenPrefix {
    pub address: u16,
    pub prefix: &'static str,
}

/// How the group (with its base) and the index make an address.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AddressScheme {
    /// The group the high byte, the index the low byte: `F0-12` = 0xF00C.
    Bytes,
    /// The group times 10 to the index's digits, plus the index, a
    /// PROFIdrive parameter number: `P10.05` = 1005.
    Decimal,
}

/// A parameter's name, written by [`Numbering::name`].
#[derive(Clone, Copy, PartialEq, Eq)]
pub struct ParameterName {
    bytes: [u8; ParameterName::MAX],
    len: usize,
}

impl ParameterName {
    /// The longest name written: a prefix and seven digits and separators.
    pub const MAX: usize = 24;

    pub fn as_str(&self) -> &str {
        core::str::from_utf8(&self.bytes[..self.len]).unwrap_or("")
    }

    fn push(&mut self, text: &str) -> Option<()> {
        let end = self.len.checked_add(text.len())?;
        self.bytes
            .get_mut(self.len..end)?
            .copy_from_slice(text.as_bytes());
        self.len = end;
        Some(())
    }

    /// `value` in `radix` (10 or 16, upper-case), with leading zeros to
    /// `digits`.
    fn push_number(&mut self, value: u32, radix: u32, digits: u8) -> Option<()> {
        let mut written = [0u8; 10];
        let mut count = 0;
        let mut rest = value;
        while rest > 0 || count < usize::from(digits) {
            let digit = char::from_digit(rest % radix, radix)?.to_ascii_uppercase();
            *written.get_mut(count)? = digit as u8;
            rest /= radix;
            count += 1;
        }
        written[..count].reverse();
        self.push(core::str::from_utf8(&written[..count]).ok()?)
    }
}

impl core::fmt::Debug for ParameterName {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        core::fmt::Debug::fmt(self.as_str(), f)
    }
}

impl core::fmt::Display for ParameterName {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.as_str())
    }
}

impl Numbering {
    /// The address of the parameter the manual names `name`; `None` when
    /// the name is not one of this numbering (written otherwise than the
    /// description writes names, beyond the address space).
    pub fn address(&self, name: &str) -> Option<u16> {
        let prefix = self.prefixes.iter().find(|p| name.starts_with(p.prefix))?;
        let rest = &name[prefix.prefix.len()..];
        let (group, index) = self.split(rest)?;
        let group = self.group_value(group)?;
        let index = digits(index, 10, 3).filter(|&i| i < self.indexes())?;
        let address = self.compose(u32::from(prefix.base) + group, index)?;
        if self.exact_digits {
            // A name is read only as it is written back.
            let mut canonical = ParameterName {
                bytes: [0; ParameterName::MAX],
                len: 0,
            };
            canonical.push(prefix.prefix)?;
            self.push_parts(&mut canonical, group, index)?;
            if canonical.as_str() != name {
                return None;
            }
        }
        Some(address)
    }

    /// The name the manual gives the parameter at `address`: with the
    /// prefix the description writes it with, else the one of the highest
    /// base that covers it (of two of one base, the first of `prefixes`);
    /// `None` when no prefix covers it.
    pub fn name(&self, address: u16) -> Option<ParameterName> {
        let (sum, index) = match self.scheme {
            AddressScheme::Bytes => {
                let [high, low] = address.to_be_bytes();
                (u32::from(high), u32::from(low))
            }
            AddressScheme::Decimal => (
                u32::from(address) / self.multiplier(),
                u32::from(address) % self.multiplier(),
            ),
        };
        if index >= self.indexes() {
            return None;
        }
        let covers = |p: &&NumberingPrefix| {
            u32::from(p.base) <= sum && sum - u32::from(p.base) < self.groups()
        };
        let written = self
            .written
            .iter()
            .find(|w| w.address == address)
            .map(|w| w.prefix);
        let mut best: Option<&NumberingPrefix> = None;
        for prefix in self.prefixes.iter().filter(covers) {
            if Some(prefix.prefix) == written {
                best = Some(prefix);
                break;
            }
            match best {
                Some(b) if b.base >= prefix.base => {}
                _ => best = Some(prefix),
            }
        }
        let prefix = best?;
        let mut name = ParameterName {
            bytes: [0; ParameterName::MAX],
            len: 0,
        };
        name.push(prefix.prefix)?;
        self.push_parts(&mut name, sum - u32::from(prefix.base), index)?;
        Some(name)
    }

    /// The group's and the index's digits of what follows the prefix.
    fn split<'n>(&self, rest: &'n str) -> Option<(&'n str, &'n str)> {
        if self.exact_digits && self.separator.is_empty() {
            let group = usize::from(self.group_digits);
            let digits = group + usize::from(self.index_digits);
            if rest.len() != digits || !rest.is_char_boundary(group) {
                return None;
            }
            Some(rest.split_at(group))
        } else {
            rest.split_once(self.separator)
        }
    }

    fn group_value(&self, group: &str) -> Option<u32> {
        let most = if self.exact_digits {
            self.group_digits
        } else {
            3
        };
        digits(group, u32::from(self.group_radix), most).filter(|&g| g < self.groups())
    }

    fn compose(&self, sum: u32, index: u32) -> Option<u16> {
        let address = match self.scheme {
            AddressScheme::Bytes if sum > 0xFF => return None,
            AddressScheme::Bytes => sum << 8 | index,
            AddressScheme::Decimal => sum * self.multiplier() + index,
        };
        u16::try_from(address).ok()
    }

    /// Appends the group, the separator and the index to `to`.
    fn push_parts(&self, to: &mut ParameterName, group: u32, index: u32) -> Option<()> {
        to.push_number(group, u32::from(self.group_radix), self.group_digits)?;
        to.push(self.separator)?;
        to.push_number(index, 10, self.index_digits)
    }

    /// How many groups a prefix has: what its digits write.
    fn groups(&self) -> u32 {
        u32::from(self.group_radix).saturating_pow(self.group_digits.into())
    }

    /// How many indexes a group has: a byte's, or what the decimal scheme
    /// multiplies by, at most what the index's digits write when the
    /// description fixes them.
    fn indexes(&self) -> u32 {
        let scheme = match self.scheme {
            AddressScheme::Bytes => 0x100,
            AddressScheme::Decimal => self.multiplier(),
        };
        if self.exact_digits {
            scheme.min(10u32.saturating_pow(self.index_digits.into()))
        } else {
            scheme
        }
    }

    fn multiplier(&self) -> u32 {
        10u32.saturating_pow(self.index_digits.into())
    }
}

/// `text` as a number in `radix`, when it is 1 to `most` digits.
fn digits(text: &str, radix: u32, most: u8) -> Option<u32> {
    if text.is_empty() || text.len() > usize::from(most) {
        return None;
    }
    text.chars()
        .try_fold(0u32, |n, c| Some(n * radix + c.to_digit(radix)?))
}
