//! Limits on the shape of the XML, checked in one pass over the tags before
//! roxmltree builds the tree (rule E300).
//!
//! roxmltree looks for a duplicate among the attributes already read for
//! each new attribute, and copies every inherited namespace into each element
//! that declares one: both are quadratic. 10 000 nested elements that each
//! declare a namespace (a 270 KB file) took seven minutes to check, and a
//! million attributes on one element would take days. And roxmltree spends
//! some 120 bytes on each node before its own node limit stops it. Real files
//! are far inside the limits: the corpus has at most 30 attributes on an
//! element, 2 namespace declarations in a file, 11 levels of nesting and
//! 8 881 elements.

use std::ops::Range;

use crate::diag::Diagnostic;

pub(crate) const MAX_ATTRIBUTES: usize = 256;
pub(crate) const MAX_NAMESPACES: usize = 64;
/// The device reader recurses over the elements (`crate::device`), and no
/// GSDML file nests deeper than a dozen levels.
pub(crate) const MAX_DEPTH: usize = 256;
/// Elements, comments, instructions and CDATA sections: a hundred times
/// the most of any real file (8 881 elements in the 1.1 MB SEW file).
/// 16 MiB of empty elements, four million of them, are refused here before
/// roxmltree allocates a node for any.
pub(crate) const MAX_NODES: usize = 1_000_000;

/// `Err` with an E300 at the first element beyond a limit. The pass reads
/// tags only as far as counting needs (from `<` to `<`, quoted values
/// skipped whole): on the corpus it takes half the time quick-xml's
/// tokenizer took for the same limits (2 ms against 3.7 ms).
/// Syntax errors are left to roxmltree, which reports them with a better
/// message: the pass stops at the first thing that is not well-formed XML,
/// and roxmltree, which reads every well-formed document this pass reads,
/// fails there too, never reading past it.
pub fn check(text: &str) -> Result<(), Diagnostic> {
    let mut scan = Scan { text, pos: 0 };
    let (mut depth, mut namespaces, mut nodes) = (0, 0, 0);
    while let Some(markup) = scan.next_markup() {
        let name = match markup {
            Markup::StartTag(name) => name,
            Markup::EndTag => {
                depth = usize::saturating_sub(depth, 1); // an unmatched end tag is roxmltree's to report
                continue;
            }
            Markup::Other(at) => {
                nodes += 1;
                if nodes > MAX_NODES {
                    return Err(too_many_nodes().at(at));
                }
                continue;
            }
        };
        if depth + 1 > MAX_DEPTH {
            return Err(too_deep().at(name));
        }
        nodes += 1;
        if nodes > MAX_NODES {
            return Err(too_many_nodes().at(name));
        }
        let Some(declared) = scan.attributes().map_err(|d| d.at(name.clone()))? else {
            return Ok(()); // not well-formed
        };
        namespaces += declared.namespaces;
        if namespaces > MAX_NAMESPACES {
            return Err(too_many_namespaces().at(name));
        }
        depth += usize::from(!declared.empty_element);
    }
    Ok(())
}

enum Markup {
    /// A start tag, read up to the end of its name (the span).
    StartTag(Range<usize>),
    EndTag,
    /// A comment, processing instruction or CDATA section (the span of its
    /// `<`).
    Other(Range<usize>),
}

struct Declared {
    namespaces: usize,
    /// `<a/>`, which opens no level.
    empty_element: bool,
}

struct Scan<'t> {
    text: &'t str,
    /// Always just after an ASCII byte the scan stopped at, so a char
    /// boundary.
    pos: usize,
}

impl Scan<'_> {
    /// Past the next piece of markup, skipping text: a start tag only up to
    /// its name. `None` at the end or at anything else (a DTD, which
    /// roxmltree refuses, or broken markup).
    fn next_markup(&mut self) -> Option<Markup> {
        self.skip_past("<")?;
        let lt = self.pos - 1..self.pos;
        let rest = &self.text.as_bytes()[self.pos..];
        match rest.first()? {
            b'/' => {
                self.skip_past(">")?;
                return Some(Markup::EndTag);
            }
            b'?' => self.skip_past("?>")?,
            b'!' if rest.starts_with(b"!--") => self.skip_past("-->")?,
            b'!' if rest.starts_with(b"![CDATA[") => self.skip_past("]]>")?,
            b'!' => return None,
            _ => {
                let start = self.pos;
                let len = rest
                    .iter()
                    .position(|&b| is_blank(b) || b == b'/' || b == b'>')?;
                self.pos += len;
                let name = start..start + len;
                return (len > 0).then_some(Markup::StartTag(name));
            }
        }
        Some(Markup::Other(lt))
    }

    /// Reads the attributes up to the end of the start tag: `Ok(None)` when
    /// the tag is not well-formed, `Err` past [`MAX_ATTRIBUTES`].
    fn attributes(&mut self) -> Result<Option<Declared>, Diagnostic> {
        let mut count = 0;
        let mut namespaces = 0;
        loop {
            self.skip_blanks();
            let bytes = self.text.as_bytes();
            match bytes.get(self.pos) {
                Some(b'>') => {
                    self.pos += 1;
                    return Ok(Some(Declared {
                        namespaces,
                        empty_element: false,
                    }));
                }
                Some(b'/') if bytes.get(self.pos + 1) == Some(&b'>') => {
                    self.pos += 2;
                    return Ok(Some(Declared {
                        namespaces,
                        empty_element: true,
                    }));
                }
                None | Some(b'/') => return Ok(None),
                Some(_) => {}
            }
            let Some(name) = self.attribute() else {
                return Ok(None);
            };
            count += 1;
            if count > MAX_ATTRIBUTES {
                return Err(too_many_attributes());
            }
            namespaces += usize::from(name == "xmlns" || name.starts_with("xmlns:"));
        }
    }

    /// `name = "value"` (or `'value'`), returning the name.
    fn attribute(&mut self) -> Option<&str> {
        let bytes = self.text.as_bytes();
        let start = self.pos;
        let len = bytes[start..]
            .iter()
            .position(|&b| is_blank(b) || matches!(b, b'=' | b'/' | b'>'))?;
        self.pos += len;
        self.skip_blanks();
        if bytes.get(self.pos) != Some(&b'=') || len == 0 {
            return None;
        }
        self.pos += 1;
        self.skip_blanks();
        let quote = match bytes.get(self.pos)? {
            b'"' => "\"",
            b'\'' => "'",
            _ => return None,
        };
        self.pos += 1;
        self.skip_past(quote)?;
        self.text.get(start..start + len)
    }

    fn skip_blanks(&mut self) {
        let bytes = self.text.as_bytes();
        while bytes.get(self.pos).copied().is_some_and(is_blank) {
            self.pos += 1;
        }
    }

    /// Moves just past the next `pattern`; `None` (and the end) if none.
    fn skip_past(&mut self, pattern: &str) -> Option<()> {
        let rest = &self.text[self.pos..];
        let found = match pattern.as_bytes() {
            // A plain loop: the gaps between tags and the attribute values
            // are a few bytes, shorter than a memchr call costs to set up.
            [byte] => rest.bytes().position(|b| b == *byte),
            _ => rest.find(pattern),
        };
        match found {
            Some(at) => {
                self.pos += at + pattern.len();
                Some(())
            }
            None => {
                self.pos = self.text.len();
                None
            }
        }
    }
}

/// XML's white space.
fn is_blank(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\r' | b'\n')
}

fn too_deep() -> Diagnostic {
    Diagnostic::error(
        "E300",
        format!("elements nest deeper than {MAX_DEPTH} levels, the most gsdc reads"),
    )
    .label(format!("level {}", MAX_DEPTH + 1))
    .help("real GSDML files nest about a dozen levels deep: check that this is the right file")
}

fn too_many_nodes() -> Diagnostic {
    Diagnostic::error(
        "E300",
        format!("the file has more than {MAX_NODES} elements, comments and instructions, the most gsdc reads"),
    )
    .label(format!("number {}", MAX_NODES + 1))
    .help("the largest real GSDML files have some ten thousand elements: check that this is the right file")
}

fn too_many_attributes() -> Diagnostic {
    Diagnostic::error(
        "E300",
        format!("an element has more than {MAX_ATTRIBUTES} attributes, the most gsdc reads"),
    )
    .label("this element")
    .help("GSDML elements have at most a few dozen attributes: check that this is the right file")
}

fn too_many_namespaces() -> Diagnostic {
    Diagnostic::error(
        "E300",
        format!("the file declares more than {MAX_NAMESPACES} XML namespaces, the most gsdc reads"),
    )
    .label(format!("namespace declaration number {}", MAX_NAMESPACES + 1))
    .help("a GSDML file declares two or three namespaces (xmlns=\"...\", xmlns:xsi=\"...\"): check that this is the right file")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn nested(depth: usize) -> String {
        format!("{}{}", "<a>".repeat(depth), "</a>".repeat(depth))
    }

    #[test]
    fn limits_reach_exactly_as_far_as_they_say() {
        assert!(check(&nested(MAX_DEPTH)).is_ok());
        let d = check(&nested(MAX_DEPTH + 1)).unwrap_err();
        assert_eq!(d.span, Some(3 * MAX_DEPTH + 1..3 * MAX_DEPTH + 2));

        let attributes = |n: usize| {
            let list: String = (0..n).map(|i| format!(" a{i}=\"1\"")).collect();
            format!("<r><e{list}/></r>")
        };
        assert!(check(&attributes(MAX_ATTRIBUTES)).is_ok());
        let d = check(&attributes(MAX_ATTRIBUTES + 1)).unwrap_err();
        assert!(d.message.contains("attributes"), "{}", d.message);
        assert_eq!(d.span, Some(4..5));

        let declarations = |n: usize| {
            let list: String = (0..n).map(|i| format!("<e xmlns:n{i}=\"u\"/>")).collect();
            format!("<r xmlns=\"u\">{list}</r>")
        };
        assert!(check(&declarations(MAX_NAMESPACES - 1)).is_ok());
        assert!(check(&declarations(MAX_NAMESPACES)).is_err());

        let elements = |n: usize| format!("<r>{}</r>", "<a/>".repeat(n - 1));
        assert!(check(&elements(MAX_NODES)).is_ok());
        let d = check(&elements(MAX_NODES + 1)).unwrap_err();
        assert!(d.message.contains("elements"), "{}", d.message);
        let last = 3 + 4 * (MAX_NODES - 1) + 1;
        assert_eq!(d.span, Some(last..last + 1));
        // Comments count too: each is a node of the tree.
        let comments = |n: usize| format!("<r>{}</r>", "<!---->".repeat(n - 1));
        assert!(check(&comments(MAX_NODES)).is_ok());
        let d = check(&comments(MAX_NODES + 1)).unwrap_err();
        let last = 3 + 7 * (MAX_NODES - 1);
        assert_eq!(d.span, Some(last..last + 1));
    }

    #[test]
    fn comments_cdata_and_instructions_hold_no_tags() {
        let inside = "<e xmlns:a=\"u\"/>".repeat(MAX_NAMESPACES + 1);
        for wrapped in [
            format!("<r><!--{inside}--></r>"),
            format!("<r><![CDATA[{inside}]]></r>"),
            format!("<?xml version=\"1.0\"?><?pi {inside}?><r/>"),
            format!("<r a='{inside}' b=\"x>y\"/>"),
        ] {
            assert!(check(&wrapped).is_ok(), "{wrapped}");
        }
        // Outside them, the same tags count.
        assert!(check(&format!("<r>{inside}</r>")).is_err());
    }

    #[test]
    fn blanks_around_equals_and_the_default_namespace_count() {
        let declarations = |n: usize| {
            let list: String = (0..n)
                .map(|i| format!("<e xmlns:n{i} = 'u' x\n=\t\"1\"/>"))
                .collect();
            format!("<r\nxmlns = \"u\" >{list}</r>")
        };
        assert!(check(&declarations(MAX_NAMESPACES - 1)).is_ok());
        let d = check(&declarations(MAX_NAMESPACES)).unwrap_err();
        assert!(d.message.contains("namespaces"), "{}", d.message);
        // `xmlnsfoo` is an attribute, not a declaration.
        let plain: String = (0..=MAX_NAMESPACES)
            .map(|_| "<e xmlnsfoo=\"u\"/>")
            .collect();
        assert!(check(&format!("<r>{plain}</r>")).is_ok());
    }

    /// The start tags the pass reads, all of them well-formed, reading to
    /// the end of the text.
    fn start_tags(text: &str) -> usize {
        let mut scan = Scan { text, pos: 0 };
        let mut count = 0;
        while let Some(markup) = scan.next_markup() {
            if let Markup::StartTag(_) = markup {
                assert!(scan.attributes().unwrap().is_some(), "at {}", scan.pos);
                count += 1;
            }
        }
        assert_eq!(scan.pos, text.len());
        count
    }

    #[test]
    fn the_pass_reads_every_element_of_real_files() {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/corpus/gsdml");
        let mut files = 0;
        for entry in std::fs::read_dir(dir).expect("the GSDML corpus is beside the checkout") {
            let path = entry.unwrap().path();
            if path.extension().is_none_or(|e| e != "xml") {
                continue;
            }
            let bytes = std::fs::read(&path).unwrap();
            let text = crate::gsdml::decode(&bytes).unwrap();
            let doc = roxmltree::Document::parse(&text).unwrap();
            let elements = doc.descendants().filter(|n| n.is_element()).count();
            assert_eq!(start_tags(&text), elements, "{}", path.display());
            files += 1;
        }
        assert!(files >= 16, "{files} files");
    }

    #[test]
    fn syntax_errors_are_left_to_roxmltree() {
        assert!(check("<a><b></a>").is_ok());
        assert!(check("<a x=1 y='>").is_ok());
        assert!(check("<!-- never closed").is_ok());
        assert!(check("<!DOCTYPE r><r/>").is_ok());
        assert!(check("<a b></a>").is_ok());
        assert!(check("<a/ >").is_ok());
        assert!(check("<").is_ok());
    }
}
