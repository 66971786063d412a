//! How the exchange prints bytes and failures.

use std::fmt::Write as _;

/// Prints a failure; `false`.
pub fn failed(why: &str) -> bool {
    println!("    FAILED: {why}");
    false
}

/// The first byte where `a` and `b` differ, with both (`None` past an end).
pub fn first_difference(a: &[u8], b: &[u8]) -> Option<(usize, Option<u8>, Option<u8>)> {
    (0..a.len().max(b.len()))
        .map(|i| (i, a.get(i).copied(), b.get(i).copied()))
        .find(|(_, x, y)| x != y)
}

/// `0x34`, or `nothing` past the end of the bytes.
pub fn byte(value: Option<u8>) -> String {
    value.map_or("nothing".into(), |b| format!("0x{b:02X}"))
}

/// `03 00 34`.
pub fn hex(bytes: &[u8]) -> String {
    let mut text = String::new();
    for (i, b) in bytes.iter().enumerate() {
        if i > 0 {
            text.push(' ');
        }
        write!(text, "{b:02X}").unwrap();
    }
    text
}

/// `10F0 0800`: the bytes as the manuals print telegrams.
pub fn words(bytes: &[u8]) -> String {
    let mut text = String::new();
    for (i, pair) in bytes.chunks(2).enumerate() {
        if i > 0 {
            text.push(' ');
        }
        for b in pair {
            write!(text, "{b:02X}").unwrap();
        }
    }
    text
}
