//! compile on every description that loads. The property: whatever the
//! loader accepts compiles to files that pass gsdc's own rules. An E900
//! (gsdc wrote a file its own checks reject) is a bug, so it fails here.
//! Every file a description names (its symbol) is a shipped symbol, so
//! that the shipped descriptions, which name theirs, load as seeds.
#![no_main]

const SYMBOL: &[u8] = include_bytes!("../../descriptions/symbols/md810dp.png");

libfuzzer_sys::fuzz_target!(|text: &str| {
    if let (Some(ir), _) = gsdc::load_with("fuzz.toml", text, &|_| Ok(SYMBOL.to_vec())) {
        if let Err(diagnostics) = gsdc::compile(&ir) {
            panic!("a loaded description does not compile: {diagnostics:?}");
        }
    }
});
