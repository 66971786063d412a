//! `gsdc decode` on every description that loads, with any arguments: the
//! input is the description's text, then each argument after a NUL byte.
//! What it prints (the tables, the JSON, or the diagnostic that refused an
//! argument) comes without a panic, nothing of the input reaches the
//! terminal raw (no control character but the line end, no mark that
//! reorders text), and no line of a diagnostic quotes more than a few
//! thousand characters of an argument.
#![no_main]

/// Every file a description names (its symbol) is this one.
const SYMBOL: &[u8] = include_bytes!("../../descriptions/symbols/md810dp.png");

/// The longest line of a rendered diagnostic: its headline, help and label
/// show at most 1000 characters, each escape at most 10 bytes.
const LONGEST_LINE: usize = 10_000;

libfuzzer_sys::fuzz_target!(|input: &[u8]| {
    let mut parts = input.split(|&b| b == 0);
    let Some(Ok(text)) = parts.next().map(std::str::from_utf8) else {
        return;
    };
    let (Some(ir), _) = gsdc::load_with("fuzz.toml", text, &|_| Ok(SYMBOL.to_vec())) else {
        return;
    };
    let Ok(args) = parts.map(std::str::from_utf8).collect::<Result<Vec<&str>, _>>() else {
        return;
    };
    let Some(printed) = gsdc::cli::decode_output(&ir, &args) else {
        return;
    };
    let (shown, refused) = match &printed {
        Ok(shown) => (shown, false),
        Err(shown) => (shown, true),
    };
    for c in shown.chars() {
        let reorders = matches!(c, '\u{061C}' | '\u{200E}' | '\u{200F}' | '\u{202A}'..='\u{202E}' | '\u{2066}'..='\u{2069}');
        assert!(!(c.is_control() && c != '\n') && !reorders, "{c:?} printed raw");
    }
    if refused {
        assert!(shown.lines().all(|line| line.len() <= LONGEST_LINE), "a diagnostic line of more than {LONGEST_LINE} bytes");
    }
});
