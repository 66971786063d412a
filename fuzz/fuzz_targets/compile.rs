//! compile on every description that loads. The property: whatever the
//! loader accepts compiles to files that pass gsdc's own rules. An E900
//! (gsdc wrote a file its own checker rejects) is a bug, so it fails here.
#![no_main]

libfuzzer_sys::fuzz_target!(|text: &str| {
    if let (Some(ir), _) = gsdc::load("fuzz.toml", text) {
        if let Err(diagnostics) = gsdc::compile(&ir) {
            panic!("a loaded description does not compile: {diagnostics:?}");
        }
    }
});
