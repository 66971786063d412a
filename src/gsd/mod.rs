//! GSD reader, keyword schema and rules (being written).
// TEMPORARY stub until the reader lands.
pub fn check(_text: &str) -> crate::diag::Diagnostics {
    crate::diag::Diagnostics::default()
}
pub fn decode(bytes: &[u8]) -> std::borrow::Cow<'_, str> {
    String::from_utf8_lossy(bytes)
}
