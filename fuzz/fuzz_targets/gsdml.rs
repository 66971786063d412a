//! The GSDML reader and rules on any bytes, as `gsdc check` reads them.
#![no_main]

libfuzzer_sys::fuzz_target!(|bytes: &[u8]| {
    if let Ok(text) = gsdc::gsdml::decode(bytes) {
        let _ = gsdc::gsdml::check(&text, Some("GSDML-V2.32-Fuzz-Test-20260101.xml"));
    }
});
