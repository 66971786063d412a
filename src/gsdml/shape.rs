//! Limits on the shape of the XML, checked in one streaming pass before
//! roxmltree builds the tree (rule E300).
//!
//! roxmltree looks for a duplicate among the attributes already read for
//! each new attribute, and copies every inherited namespace into each element
//! that declares one: both are quadratic. 10 000 nested elements that each
//! declare a namespace (a 270 KB file) took seven minutes to check, and a
//! million attributes on one element would take days. Real files are far
//! inside the limits: the corpus has at most 30 attributes on an element, 2
//! namespace declarations in a file and 11 levels of nesting.

use quick_xml::events::{BytesStart, Event};

use crate::diag::Diagnostic;

const MAX_ATTRIBUTES: usize = 256;
const MAX_NAMESPACES: usize = 64;
/// Nothing in gsdc recurses over the tree, but no GSDML file nests deeper
/// than a dozen levels, and a limit keeps it that way for future rules.
const MAX_DEPTH: usize = 256;

/// `Err` with an E300 at the first element beyond a limit. Syntax errors are
/// left to roxmltree, which reports them with a better message: the pass
/// stops at the first one, and since quick-xml is the more lenient parser,
/// roxmltree fails there too, never reading past it.
pub fn check(text: &str) -> Result<(), Diagnostic> {
    let mut reader = quick_xml::Reader::from_str(text);
    reader.config_mut().check_end_names = false;
    let (mut depth, mut namespaces) = (0, 0);
    loop {
        let at = usize::try_from(reader.buffer_position()).unwrap_or(usize::MAX);
        let (tag, opens) = match reader.read_event() {
            Ok(Event::Start(tag)) => (tag, true),
            Ok(Event::Empty(tag)) => (tag, false),
            Ok(Event::End(_)) => {
                depth = usize::saturating_sub(depth, 1); // an unmatched end tag is roxmltree's to report
                continue;
            }
            Ok(Event::Eof) | Err(_) => return Ok(()),
            Ok(_) => continue,
        };
        let span = at + 1..at + 1 + tag.name().as_ref().len(); // the name in the start tag
        if depth + 1 > MAX_DEPTH {
            return Err(too_deep().at(span));
        }
        namespaces += count_attributes(&tag).map_err(|d| d.at(span.clone()))?;
        if namespaces > MAX_NAMESPACES {
            return Err(too_many_namespaces().at(span));
        }
        depth += usize::from(opens);
    }
}

/// The element's namespace declarations, or an error when it has more than
/// [`MAX_ATTRIBUTES`] attributes (counted without reading the rest).
fn count_attributes(tag: &BytesStart<'_>) -> Result<usize, Diagnostic> {
    let mut attributes = tag.attributes();
    attributes.with_checks(false);
    let mut count = 0;
    let mut namespaces = 0;
    for attribute in attributes.take(MAX_ATTRIBUTES + 1) {
        count += 1;
        let declares = attribute.is_ok_and(|a| a.key.as_namespace_binding().is_some());
        namespaces += usize::from(declares);
    }
    if count > MAX_ATTRIBUTES {
        return Err(too_many_attributes());
    }
    Ok(namespaces)
}

fn too_deep() -> Diagnostic {
    Diagnostic::error(
        "E300",
        format!("elements nest deeper than {MAX_DEPTH} levels, the most gsdc reads"),
    )
    .label(format!("level {}", MAX_DEPTH + 1))
    .help("real GSDML files nest about a dozen levels deep: check that this is the right file")
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
    }

    #[test]
    fn syntax_errors_are_left_to_roxmltree() {
        assert!(check("<a><b></a>").is_ok());
        assert!(check("<a x=1 y='>").is_ok());
        assert!(check("<!-- never closed").is_ok());
    }
}
