//! GSDML (PROFINET device description) reader and the rules beyond the PI
//! schema.
//!
//! [`check`] parses a GSDML file with roxmltree (DTDs refused; size, node
//! count, nesting, attributes and namespaces bounded) and runs every rule
//! of `docs/rules.md` over it: codes E300..E399 are errors, W300..W399
//! warnings. All failures are collected.
//!
//! The rules are linear passes over an index (`index::Index`) of the document's
//! GSDML elements, with hash maps for IDs and texts, so that checking the
//! largest real files takes milliseconds.

mod attributes;
pub(crate) mod datatype;
mod document;
pub(crate) mod index;
mod io;
mod keys;
mod network;
mod reader;
mod records;
mod safety;
mod shape;
mod slots;
pub(crate) mod tree;
pub(crate) mod values;
pub(crate) mod version;

use crate::diag::{Diagnostic, Diagnostics};
use index::Index;

pub(crate) use reader::parse_tree;
pub use reader::{decode, parse, INPUT_LIMIT};
pub use version::Version;

/// The namespace of every GSDML element.
pub const NAMESPACE: &str = "http://www.profibus.com/GSDML/2003/11/DeviceProfile";

/// Parses `text` and applies every rule beyond the XSD. `file_name` (the
/// name only, no directory) enables the naming-convention rules. Never
/// panics; diagnostics come back in source order.
pub fn check(text: &str, file_name: Option<&str>) -> Diagnostics {
    let mut out = Vec::new();
    match parse(text) {
        Ok(doc) => check_document(&doc, file_name, &mut out),
        Err(diagnostic) => out.push(diagnostic),
    }
    // Stable sort: diagnostics without a span first, the rest in file order.
    out.sort_by_key(|d| d.span.as_ref().map(|s| s.start));
    let mut diagnostics = Diagnostics(out);
    diagnostics.name_subjects(|offset| element_at(text, offset));
    diagnostics
}

/// The element whose start tag holds `offset` (or precedes it): what a
/// finding is about. Closing tags, comments and declarations are skipped.
fn element_at(text: &str, offset: usize) -> Option<String> {
    let mut end = text.get(..=offset.min(text.len().saturating_sub(1)))?.len();
    loop {
        let open = text[..end].rfind('<')?;
        let rest = &text[open + 1..];
        if rest.starts_with(['/', '!', '?']) {
            end = open;
            continue;
        }
        let name = rest
            .split(|c: char| c.is_whitespace() || c == '/' || c == '>')
            .next()?;
        let local = name.rsplit(':').next()?;
        return (!local.is_empty()).then(|| local.to_string());
    }
}

fn check_document(
    doc: &roxmltree::Document<'_>,
    file_name: Option<&str>,
    out: &mut Vec<Diagnostic>,
) {
    let Some(version) = document::check(doc, file_name, out) else {
        return; // not a GSDML file: the other rules would only add noise
    };
    let ctx = Ctx {
        idx: Index::new(doc),
        version,
    };
    attributes::check(&ctx, out);
    keys::check(&ctx, out);
    io::check(&ctx, out);
    slots::check(&ctx, out);
    network::check(&ctx, out);
    records::check(&ctx, out);
    safety::check(&ctx, out);
}

/// What every rule gets: the indexed document and the schema version the
/// file declares (the newest known one when it declares none readable).
struct Ctx<'a, 'input> {
    idx: Index<'a, 'input>,
    version: Version,
}

#[cfg(test)]
mod subject_tests {
    use super::element_at;

    #[test]
    fn the_subject_is_the_enclosing_start_tag() {
        let text = "<a:Root>\n  <ModuleItemRef ModuleItemTarget=\"IDM_X\"/>\n</a:Root>";
        let at = text.find("IDM_X").unwrap();
        assert_eq!(element_at(text, at).as_deref(), Some("ModuleItemRef"));
        assert_eq!(element_at(text, 1).as_deref(), Some("Root"));
        assert_eq!(
            element_at(text, text.len() - 1).as_deref(),
            Some("ModuleItemRef")
        );
        assert_eq!(element_at("no tags", 3), None);
    }
}
