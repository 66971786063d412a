//! A User_Prm_Data parameter as a description states it, for a card's
//! parameters (`super::dp`) and a gateway's (`super::gateway`).

use super::toml_out::quote;
use crate::device::Field;

/// How a description says what a User_Prm_Data parameter takes of its
/// bytes, as a key and its value: `type = "Unsigned8"` or `"Unsigned16"`,
/// or bits of one byte, `bits = 3` or `bits = [4, 6]`; `None` for another
/// type, or bits past the byte (which GSD's reader takes, its rules not).
pub(super) fn stored_as(f: &Field) -> Option<(&'static str, String)> {
    match (f.data_type.as_str(), f.bits) {
        ("Unsigned8" | "Unsigned16", None) => Some(("type", quote(&f.data_type))),
        ("Bit" | "BitArea", Some(b)) => {
            let last = (u16::from(b.offset) + u16::from(b.length)).checked_sub(1)?;
            match (b.length, last) {
                (1, _) => Some(("bits", b.offset.to_string())),
                (_, 0..=7) => Some(("bits", format!("[{}, {last}]", b.offset))),
                _ => None,
            }
            .filter(|_| last <= 7)
        }
        _ => None,
    }
}
