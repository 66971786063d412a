//! `gsdc doc` on every description that loads: its datasheet is made
//! without a panic, in time linear in the description (a hang or a
//! quadratic blow-up is libFuzzer's timeout), and no text of the
//! description becomes markup: the page has only the elements gsdc writes,
//! and the Markdown no `<` that is not escaped (`\<`) outside code.
#![no_main]

/// Every file a description names (its symbol) is this one.
const SYMBOL: &[u8] = include_bytes!("../../descriptions/symbols/md810dp.png");

/// The elements of a datasheet page: HTML, and SVG for the diagrams.
const ELEMENTS: [&str; 32] = [
    "a", "body", "caption", "code", "figcaption", "figure", "g", "h1", "h2", "h3", "head",
    "html", "input", "label", "li", "main", "meta", "nav", "ol", "p", "rect", "strong", "style",
    "svg", "table", "tbody", "td", "text", "th", "thead", "title", "tr",
];

libfuzzer_sys::fuzz_target!(|text: &str| {
    let (Some(ir), _) = gsdc::load_with("fuzz.toml", text, &|_| Ok(SYMBOL.to_vec())) else {
        return;
    };
    for page in gsdc::document(&ir) {
        let shown = String::from_utf8(page.contents).expect("a datasheet is UTF-8");
        if page.file_name.ends_with(".html") {
            for element in elements(&shown) {
                assert!(ELEMENTS.contains(&element), "<{element}> in the page");
            }
        } else {
            assert_markdown_escapes_every_tag(&shown);
        }
    }
});

/// The name of every element opened in `html`.
fn elements(html: &str) -> impl Iterator<Item = &str> {
    html.split('<').skip(1).filter_map(|rest| {
        let end = rest
            .find(|c: char| !c.is_ascii_alphanumeric())
            .unwrap_or(rest.len());
        let name = &rest[..end];
        name.starts_with(|c: char| c.is_ascii_alphabetic()).then_some(name)
    })
}

/// Every `<` that could open an element is escaped, or in a code span.
fn assert_markdown_escapes_every_tag(markdown: &str) {
    for line in markdown.lines() {
        // Code spans (between backticks) show their text as written.
        for (i, part) in line.split('`').enumerate().filter(|(i, _)| i % 2 == 0) {
            let bytes = part.as_bytes();
            for (at, _) in part.match_indices('<') {
                let escaped = at > 0 && bytes[at - 1] == b'\\';
                let opens = bytes.get(at + 1).is_some_and(|b| b.is_ascii_alphabetic() || *b == b'/' || *b == b'!');
                assert!(escaped || !opens, "unescaped `<` in Markdown (part {i}): {line}");
            }
        }
    }
}
