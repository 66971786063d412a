//! The value syntaxes of GSDML attributes (the simple types of
//! `GSDML-Primitives`): value lists like `0..4 7`, signed or float lists
//! like `-5..5 7.5`, hex ident numbers.

use std::cmp::Ordering;

/// A `ValueListT` (unsigned numbers and inclusive ranges, space
/// separated) as the set of numbers it denotes: sorted, merged ranges.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ValueList(Vec<(u32, u32)>);

impl ValueList {
    /// `None` unless every item is a number or a range `lo..hi` with lo <= hi.
    pub fn parse(text: &str) -> Option<Self> {
        let items: Option<Vec<_>> = text.split_whitespace().map(parse_unsigned_item).collect();
        items.filter(|i| !i.is_empty()).map(ValueList::from_ranges)
    }

    /// The set of the numbers in the ranges; empty when there are none.
    pub fn from_ranges(mut ranges: Vec<(u32, u32)>) -> Self {
        ranges.sort_unstable();
        let mut merged: Vec<(u32, u32)> = Vec::with_capacity(ranges.len());
        for (lo, hi) in ranges {
            match merged.last_mut() {
                Some(last) if lo <= last.1.saturating_add(1) => last.1 = last.1.max(hi),
                _ => merged.push((lo, hi)),
            }
        }
        ValueList(merged)
    }

    /// Sorted, non-overlapping, non-adjacent ranges.
    pub fn ranges(&self) -> &[(u32, u32)] {
        &self.0
    }

    pub fn contains(&self, value: u32) -> bool {
        let i = self.0.partition_point(|&(_, hi)| hi < value);
        self.0.get(i).is_some_and(|&(lo, _)| lo <= value)
    }

    /// The numbers in both lists.
    pub fn intersection(&self, other: &ValueList) -> ValueList {
        let (mut a, mut b) = (self.0.iter().peekable(), other.0.iter().peekable());
        let mut both = Vec::new();
        while let (Some(&&(lo_a, hi_a)), Some(&&(lo_b, hi_b))) = (a.peek(), b.peek()) {
            let (lo, hi) = (lo_a.max(lo_b), hi_a.min(hi_b));
            if lo <= hi {
                both.push((lo, hi));
            }
            // The range that ends first cannot overlap anything further.
            if hi_a < hi_b {
                a.next();
            } else {
                b.next();
            }
        }
        ValueList(both)
    }

    /// The numbers of `other` that are not in `self`, as ranges.
    pub fn missing_from(&self, other: &ValueList) -> Vec<(u32, u32)> {
        other
            .0
            .iter()
            .flat_map(|&range| uncovered(&self.0, range))
            .collect()
    }
}

fn parse_unsigned_item(item: &str) -> Option<(u32, u32)> {
    match item.split_once("..") {
        Some((lo, hi)) => Some((parse_u32(lo)?, parse_u32(hi)?)).filter(|(lo, hi)| lo <= hi),
        None => parse_u32(item).map(|v| (v, v)),
    }
}

/// The parts of `range` outside the sorted, merged `covered` ranges.
fn uncovered(covered: &[(u32, u32)], (lo, hi): (u32, u32)) -> Vec<(u32, u32)> {
    let mut gaps = Vec::new();
    let mut next = u64::from(lo);
    // Ranges that end before `lo` cannot cover anything: skip them by binary search.
    let first = covered.partition_point(|&(_, end)| end < lo);
    for &(start, end) in &covered[first..] {
        if u64::from(start) > u64::from(hi) {
            break;
        }
        if u64::from(start) > next {
            gaps.push((next as u32, start - 1));
        }
        next = next.max(u64::from(end) + 1);
    }
    if next <= u64::from(hi) {
        gaps.push((next as u32, hi));
    }
    gaps
}

/// Renders ranges as GSDML writes them: `3 5..7`.
pub fn show_ranges(ranges: &[(u32, u32)]) -> String {
    let items: Vec<String> = ranges
        .iter()
        .map(|&(lo, hi)| {
            if lo == hi {
                lo.to_string()
            } else {
                format!("{lo}..{hi}")
            }
        })
        .collect();
    items.join(" ")
}

/// Decimal digits only (the XSD integer types allow no sign or spaces here).
pub fn parse_u32(text: &str) -> Option<u32> {
    text.bytes()
        .all(|b| b.is_ascii_digit())
        .then(|| text.parse().ok())
        .flatten()
}

pub fn parse_bool(text: &str) -> Option<bool> {
    match text {
        "true" | "1" => Some(true),
        "false" | "0" => Some(false),
        _ => None,
    }
}

/// `0x` and 1 to `max_digits` hex digits, as in `Unsigned16hexT` and
/// `Unsigned32hexT`.
pub fn parse_hex(text: &str, max_digits: usize) -> Option<u32> {
    let digits = text.strip_prefix("0x")?;
    let ok =
        (1..=max_digits).contains(&digits.len()) && digits.bytes().all(|b| b.is_ascii_hexdigit());
    ok.then(|| u32::from_str_radix(digits, 16).ok()).flatten()
}

/// A number of a `SignedOrFloatValueListT` or a `DefaultValue`: integers
/// stay exact (64-bit values do not fit a float), the rest is a float.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Number {
    Int(i128),
    Float(f64),
}

impl Number {
    pub fn parse(text: &str) -> Option<Self> {
        let digits = text.strip_prefix('-').unwrap_or(text);
        if !digits.is_empty() && digits.bytes().all(|b| b.is_ascii_digit()) {
            return text.parse().ok().map(Number::Int);
        }
        let float_chars = |b: u8| b.is_ascii_digit() || matches!(b, b'.' | b'e' | b'E' | b'-');
        let starts_with_digit = digits.bytes().next().is_some_and(|b| b.is_ascii_digit());
        (starts_with_digit && digits.bytes().all(float_chars))
            .then(|| text.parse().ok().map(Number::Float))
            .flatten()
    }

    fn as_f64(self) -> f64 {
        match self {
            Number::Int(i) => i as f64,
            Number::Float(f) => f,
        }
    }
}

impl PartialOrd for Number {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        match (self, other) {
            (Number::Int(a), Number::Int(b)) => Some(a.cmp(b)),
            _ => self.as_f64().partial_cmp(&other.as_f64()),
        }
    }
}

impl std::fmt::Display for Number {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Number::Int(i) => write!(f, "{i}"),
            Number::Float(x) => write!(f, "{x}"),
        }
    }
}

/// A `SignedOrFloatValueListT` (`AllowedValues`): numbers and ranges.
#[derive(Debug, Clone, PartialEq)]
pub struct NumberList(Vec<(Number, Number)>);

impl NumberList {
    pub fn parse(text: &str) -> Option<Self> {
        let items: Option<Vec<_>> = text.split_whitespace().map(parse_number_item).collect();
        items.filter(|i| !i.is_empty()).map(NumberList)
    }

    pub fn contains(&self, value: Number) -> bool {
        self.0.iter().any(|(lo, hi)| *lo <= value && value <= *hi)
    }
}

fn parse_number_item(item: &str) -> Option<(Number, Number)> {
    match item.split_once("..") {
        Some((lo, hi)) => {
            Some((Number::parse(lo)?, Number::parse(hi)?)).filter(|(lo, hi)| lo <= hi)
        }
        None => Number::parse(item).map(|n| (n, n)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn value_lists_parse_ranges_and_singles() {
        let list = ValueList::parse("7 0..4 3..5").unwrap();
        assert_eq!(list.ranges(), &[(0, 5), (7, 7)]);
        assert!(list.contains(7) && list.contains(0) && !list.contains(6) && !list.contains(8));
        assert_eq!(ValueList::parse("4..1"), None);
        assert_eq!(ValueList::parse("1,2"), None);
        assert_eq!(ValueList::parse(""), None);
    }

    #[test]
    fn missing_from_reports_uncovered_parts() {
        let physical = ValueList::parse("0..4 6").unwrap();
        let allowed = ValueList::parse("1..8 2").unwrap();
        assert_eq!(physical.missing_from(&allowed), vec![(5, 5), (7, 8)]);
        assert_eq!(show_ranges(&physical.missing_from(&allowed)), "5 7..8");
        let all = ValueList::parse("0..4294967295").unwrap();
        assert!(all.missing_from(&allowed).is_empty());
    }

    #[test]
    fn intersection_of_sets() {
        let a = ValueList::parse("0..4 8..10").unwrap();
        let b = ValueList::parse("3..9 12").unwrap();
        assert_eq!(a.intersection(&b).ranges(), &[(3, 4), (8, 9)]);
        assert_eq!(b.intersection(&a), a.intersection(&b));
    }

    #[test]
    fn hex_ident_numbers() {
        assert_eq!(parse_hex("0x00000031", 8), Some(0x31));
        assert_eq!(parse_hex("12", 8), None);
        assert_eq!(parse_hex("0x123456789", 8), None);
        assert_eq!(parse_hex("0x12345", 4), None);
    }

    #[test]
    fn number_lists_compare_ints_exactly_and_floats() {
        let list = NumberList::parse("-5..5 7.5 18446744073709551615").unwrap();
        assert!(list.contains(Number::Int(-5)) && list.contains(Number::Float(7.5)));
        assert!(list.contains(Number::Int(18446744073709551615)));
        assert!(!list.contains(Number::Int(6)));
        assert_eq!(Number::parse("1e3"), Some(Number::Float(1000.0)));
        assert_eq!(Number::parse("abc"), None);
    }
}
