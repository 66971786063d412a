//! The GSDML reader and rules on any bytes, as `gsdc check` reads them; and
//! the device reader (`gsdc diff`, `gsdc import`), which must never take a
//! file `gsdc check` finds not well-formed.
#![no_main]

libfuzzer_sys::fuzz_target!(|bytes: &[u8]| {
    let device = gsdc::device::read(bytes, None);
    if let Ok(text) = gsdc::gsdml::decode(bytes) {
        let _ = gsdc::gsdml::check(&text, Some("GSDML-V2.32-Fuzz-Test-20260101.xml"));
        if matches!(device, Some(gsdc::device::Device::Pn(_))) {
            assert!(
                gsdc::gsdml::parse(&text).is_ok(),
                "the device reader took a file the checker's parser refuses"
            );
        }
    }
});
