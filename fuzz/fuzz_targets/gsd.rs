//! The GSD reader and rules on any bytes, as `gsdc check` reads them.
#![no_main]

libfuzzer_sys::fuzz_target!(|bytes: &[u8]| {
    let text = gsdc::gsd::decode(bytes);
    let _ = gsdc::gsd::check(&text);
});
