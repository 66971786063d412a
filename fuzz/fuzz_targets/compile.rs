//! compile on every description that loads: files that pass gsdc's own
//! checks, or an E9xx diagnostic; never a panic.
#![no_main]

libfuzzer_sys::fuzz_target!(|text: &str| {
    if let (Some(ir), _) = gsdc::load("fuzz.toml", text) {
        let _ = gsdc::compile(&ir);
    }
});
