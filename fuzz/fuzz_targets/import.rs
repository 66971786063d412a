//! `gsdc import` on any bytes, as a GSD or (when they start as XML does) a
//! GSDML file: never a panic, and a description it writes loads, as does
//! one it makes whose build is another device (`another_device`).
#![no_main]

libfuzzer_sys::fuzz_target!(|bytes: &[u8]| {
    let is_xml = bytes.trim_ascii_start().starts_with(b"<");
    let name = match is_xml {
        true => "GSDML-V2.32-Fuzz-Test-20260101.xml",
        false => "FUZZ.GSD",
    };
    let imported = gsdc::import::import(name, bytes);
    for toml in imported.description.iter().chain(&imported.another_device) {
        let (ir, diagnostics) = gsdc::load("imported.toml", toml);
        assert!(ir.is_some(), "an import that does not load: {diagnostics:#?}");
    }
});
