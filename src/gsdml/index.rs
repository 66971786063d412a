//! One pass over the document that files every GSDML element under its
//! local name, so that each rule visits only the elements it is about; and
//! the span helpers every rule uses.

use foldhash::{HashMap, HashMapExt};
use std::cell::OnceCell;
use std::ops::Range;

use roxmltree::{Document, ExpandedName, Node};

use super::NAMESPACE;

pub type El<'a, 'input> = Node<'a, 'input>;

/// Every kind of submodule item: they share one ID scope and the
/// attributes of submodules.
pub const SUBMODULE_ITEMS: &[&str] = &[
    "VirtualSubmoduleItem",
    "SubmoduleItem",
    "InterfaceSubmoduleItem",
    "PortSubmoduleItem",
];

pub struct Index<'a, 'input> {
    elements: Vec<El<'a, 'input>>,
    by_name: HashMap<&'a str, Vec<El<'a, 'input>>>,
    text: &'input str,
    /// Byte offsets where lines start, to tell lines without rescanning;
    /// found when first asked for, since only some findings need them.
    line_starts: OnceCell<Vec<usize>>,
}

impl<'a, 'input> Index<'a, 'input> {
    pub fn new(doc: &'a Document<'input>) -> Self {
        let elements: Vec<_> = doc.descendants().filter(in_gsdml).collect();
        let mut by_name: HashMap<&'a str, Vec<El<'a, 'input>>> = HashMap::new();
        for node in &elements {
            by_name
                .entry(node.tag_name().name())
                .or_default()
                .push(*node);
        }
        Index {
            elements,
            by_name,
            text: doc.input_text(),
            line_starts: OnceCell::new(),
        }
    }

    /// Every GSDML element in document order.
    pub fn elements(&self) -> &[El<'a, 'input>] {
        &self.elements
    }

    /// 1-based line of an element, for "first defined at line N" help texts.
    pub fn line_of(&self, node: &El<'_, '_>) -> usize {
        let line_starts = self.line_starts.get_or_init(|| {
            let breaks = self.text.match_indices('\n').map(|(i, _)| i + 1);
            std::iter::once(0).chain(breaks).collect()
        });
        line_starts.partition_point(|&start| start <= node.range().start)
    }

    /// Every GSDML element with this local name, in document order.
    pub fn all(&self, name: &str) -> &[El<'a, 'input>] {
        self.by_name.get(name).map_or(&[], Vec::as_slice)
    }
}

pub fn in_gsdml(node: &El<'_, '_>) -> bool {
    node.is_element() && node.tag_name().namespace() == Some(NAMESPACE)
}

pub fn parent_is(node: &El<'_, '_>, name: &str) -> bool {
    node.parent_element()
        .is_some_and(|p| p.tag_name().name() == name)
}

/// Whether the element's parent, grandparent, ... have these names; `A|B`
/// accepts either.
pub fn within(node: &El<'_, '_>, ancestors: &[&str]) -> bool {
    let mut current = *node;
    ancestors
        .iter()
        .all(|names| match current.parent_element() {
            Some(parent) if names.split('|').any(|n| n == parent.tag_name().name()) => {
                current = parent;
                true
            }
            _ => false,
        })
}

/// The GSDML child elements with this name.
pub fn children<'a, 'input: 'a>(
    node: El<'a, 'input>,
    name: &'a str,
) -> impl Iterator<Item = El<'a, 'input>> + 'a {
    node.children()
        .filter(move |c| in_gsdml(c) && c.tag_name().name() == name)
}

pub fn child<'a, 'input: 'a>(node: El<'a, 'input>, name: &'a str) -> Option<El<'a, 'input>> {
    children(node, name).next()
}

/// The element's name in its start tag (`<Name` without the `<`): where a
/// diagnostic about the whole element points.
pub fn tag_span(node: &El<'_, '_>) -> Range<usize> {
    let start = node.range().start + 1;
    let text = &node.document().input_text()[start..];
    let len = text
        .find(|c: char| c.is_whitespace() || c == '/' || c == '>')
        .unwrap_or(text.len());
    start..start + len
}

/// The value of the attribute (without quotes), or the element's tag when
/// the attribute is absent.
pub fn value_span<'n, 'm>(
    node: &El<'_, '_>,
    attribute: impl Into<ExpandedName<'n, 'm>>,
) -> Range<usize> {
    node.attribute_node(attribute)
        .map_or_else(|| tag_span(node), |a| a.range_value())
}

/// A short description of an element for messages: its name and its ID.
pub fn describe(node: &El<'_, '_>) -> String {
    let name = node.tag_name().name();
    match node.attribute("ID") {
        Some(id) => format!("{name} \"{id}\""),
        None => name.to_string(),
    }
}
