//! The description loader on any text: a diagnostic or an IR, never a panic.
#![no_main]

libfuzzer_sys::fuzz_target!(|text: &str| {
    let _ = gsdc::load("fuzz.toml", text);
});
