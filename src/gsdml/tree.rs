//! A GSDML document as the device reader (`crate::device`) walks it: its
//! elements with their names, namespaces, attributes and places, and
//! nothing else.
//!
//! `gsdc check` reads files with roxmltree, whose tree keeps every node and
//! whose errors say exactly what is wrong; the device reader needs neither,
//! and reading a file's meaning is what `gsdc diff` and `gsdc import` do
//! for two files at a time. Here quick-xml finds the markup and the
//! elements are linked in one flat list with their attributes: reading the
//! device of the largest corpus file (SEW's 1.1 MB) took 5.3 ms through
//! roxmltree and takes about 4 ms so (in process, one thread), and `gsdc
//! diff` of the two largest files went from 111 M instructions to 75 M. A
//! document this reader accepts is one roxmltree accepts, with the same
//! elements, namespaces, places and attribute values (tested against it on
//! the corpus and on broken files, and fuzzed); what it refuses, the diff
//! explains with `gsdc check`'s diagnostics.

use std::borrow::Cow;
use std::ops::Range;

use quick_xml::events::Event;

use super::shape;

const XML_NAMESPACE: &str = "http://www.w3.org/XML/1998/namespace";

/// An element's place in [`Tree`]'s list.
pub type NodeId = u32;

const NONE: NodeId = NodeId::MAX;

pub struct Tree<'t> {
    text: &'t str,
    elements: Vec<Element<'t>>,
    attributes: Vec<Attribute<'t>>,
    /// The namespace names declared in the document, each once.
    namespaces: Vec<Cow<'t, str>>,
}

struct Element<'t> {
    /// The local name.
    name: &'t str,
    namespace: Option<u32>,
    /// From its start tag's `<` to the end of its end tag.
    range: Range<u32>,
    parent: NodeId,
    first_child: NodeId,
    next_sibling: NodeId,
    previous_sibling: NodeId,
    attributes: Range<u32>,
}

struct Attribute<'t> {
    name: &'t str,
    namespace: Option<u32>,
    value: Cow<'t, str>,
}

impl<'t> Tree<'t> {
    /// The elements of `text`; `None` when it is not well-formed XML (as
    /// far as reading its elements and attributes goes), has a DTD, or
    /// has no root element.
    pub fn parse(text: &'t str) -> Option<Tree<'t>> {
        if !has_only_xml_characters(text) {
            return None;
        }
        let mut builder = Builder {
            tree: Tree {
                text,
                elements: Vec::new(),
                attributes: Vec::new(),
                namespaces: Vec::new(),
            },
            open: Vec::new(),
            bindings: Vec::new(),
            declarations: 0,
            nodes: 0,
            raw: Vec::new(),
            root_closed: false,
        };
        let mut reader = quick_xml::Reader::from_str(text);
        reader.config_mut().check_comments = true;
        loop {
            let start = reader.buffer_position() as usize;
            let event = reader.read_event().ok()?;
            let end = reader.buffer_position() as usize;
            match event {
                Event::Start(_) => builder.open(start..end)?,
                Event::Empty(_) => {
                    builder.open(start..end)?;
                    builder.close(end);
                }
                Event::End(_) => builder.close(end),
                Event::Text(t) => builder.text(&t)?,
                Event::GeneralRef(r) => builder.reference(std::str::from_utf8(&r).ok()?)?,
                Event::CData(_) => {
                    builder.inside_root()?;
                    builder.count_node()?;
                }
                Event::DocType(_) => return None,
                Event::Decl(_) => is_declaration_first(&text[start..end], start)?,
                Event::Comment(_) | Event::PI(_) => builder.count_node()?,
                Event::Eof => break,
            }
        }
        builder.finish()
    }

    pub fn root_element(&self) -> Node<'_, 't> {
        Node { tree: self, id: 0 }
    }

    pub fn input_text(&self) -> &'t str {
        self.text
    }
}

/// What [`Tree::parse`] keeps while it reads.
struct Builder<'t> {
    tree: Tree<'t>,
    /// The open elements, outermost first, each with its last child so far.
    open: Vec<(NodeId, NodeId)>,
    /// Namespace prefixes in scope (`""` the default namespace), with the
    /// element that declared them.
    bindings: Vec<(&'t str, u32, NodeId)>,
    /// Namespace declarations so far, and elements, comments, instructions
    /// and CDATA sections: bounded as `gsdc check` bounds them (`shape`).
    declarations: usize,
    nodes: usize,
    /// The attributes of the start tag at hand, before they are resolved.
    raw: Vec<(&'t str, Cow<'t, str>)>,
    root_closed: bool,
}

impl<'t> Builder<'t> {
    /// A start tag, `tag` its place from `<` to `>`.
    fn open(&mut self, tag: Range<usize>) -> Option<()> {
        if self.root_closed || self.open.len() >= shape::MAX_DEPTH {
            return None; // a second root element, or too deep
        }
        self.count_node()?;
        let text = self.tree.text;
        let inner = text[tag.clone()].strip_prefix('<')?.strip_suffix('>')?;
        let inner = inner.strip_suffix('/').unwrap_or(inner);
        let name_end = inner.bytes().position(is_blank).unwrap_or(inner.len());
        let (qname, rest) = inner.split_at(name_end);
        let base = tag.start + 1 + name_end;
        let id = self.tree.elements.len() as NodeId;
        let mut raw = std::mem::take(&mut self.raw);
        raw_attributes(text, base, rest, &mut raw)?;
        for (name, uri) in raw.iter().filter(|(name, _)| is_declaration(name)) {
            self.declarations += 1;
            if self.declarations > shape::MAX_NAMESPACES {
                return None;
            }
            let prefix = match name.strip_prefix("xmlns:") {
                None => "",
                // `xmlns:` binds no prefix.
                Some(prefix) if !is_name(prefix) || prefix.contains(':') => return None,
                Some(prefix) => prefix,
            };
            let declared = self.declare(uri.clone());
            self.bindings.push((prefix, declared, id));
        }
        let first_attribute = self.tree.attributes.len() as u32;
        for (name, value) in raw.drain(..).filter(|(name, _)| !is_declaration(name)) {
            let (namespace, local) = self.resolve_attribute(name)?;
            let duplicate = self.tree.attributes[first_attribute as usize..]
                .iter()
                .any(|a| a.name == local && a.namespace == namespace);
            if duplicate {
                return None;
            }
            self.tree.attributes.push(Attribute {
                name: local,
                namespace,
                value,
            });
        }
        self.raw = raw;
        let (namespace, name) = self.resolve_element(qname)?;
        let parent = self.open.last().map_or(NONE, |&(parent, _)| parent);
        let previous_sibling = self.open.last().map_or(NONE, |&(_, last)| last);
        self.tree.elements.push(Element {
            name,
            namespace,
            range: tag.start as u32..tag.end as u32,
            parent,
            first_child: NONE,
            next_sibling: NONE,
            previous_sibling,
            attributes: first_attribute..self.tree.attributes.len() as u32,
        });
        if let Some((parent, last)) = self.open.last_mut() {
            match *last {
                NONE => self.tree.elements[*parent as usize].first_child = id,
                last => self.tree.elements[last as usize].next_sibling = id,
            }
            *last = id;
        }
        self.open.push((id, NONE));
        Some(())
    }

    /// The end of the element opened last, at `end`. (quick-xml checks that
    /// end tags match start tags.)
    fn close(&mut self, end: usize) {
        if let Some((id, _)) = self.open.pop() {
            self.tree.elements[id as usize].range.end = end as u32;
            while self.bindings.last().is_some_and(|&(_, _, by)| by == id) {
                self.bindings.pop();
            }
            self.root_closed = self.open.is_empty();
        }
    }

    /// Text between tags: only blanks outside the root element.
    fn text(&self, text: &[u8]) -> Option<()> {
        match self.open.is_empty() {
            true => text.iter().all(|&b| is_blank(b)).then_some(()),
            false => Some(()),
        }
    }

    fn count_node(&mut self) -> Option<()> {
        self.nodes += 1;
        (self.nodes <= shape::MAX_NODES).then_some(())
    }

    /// `&name;` in text: inside the root element, and one XML defines.
    fn reference(&self, name: &str) -> Option<()> {
        self.inside_root()?;
        resolve_reference(name).map(drop)
    }

    fn inside_root(&self) -> Option<()> {
        (!self.open.is_empty()).then_some(())
    }

    fn finish(self) -> Option<Tree<'t>> {
        (self.root_closed && self.open.is_empty()).then_some(self.tree)
    }

    /// The index of a declared namespace name (`xmlns=""`, which
    /// undeclares the default namespace, gives `""`, as in roxmltree).
    fn declare(&mut self, uri: Cow<'t, str>) -> u32 {
        let known = self.tree.namespaces.iter().position(|n| *n == uri);
        let index = known.unwrap_or_else(|| {
            self.tree.namespaces.push(uri);
            self.tree.namespaces.len() - 1
        });
        index as u32
    }

    fn binding(&self, prefix: &str) -> Option<u32> {
        self.bindings
            .iter()
            .rev()
            .find(|(p, _, _)| *p == prefix)
            .map(|&(_, namespace, _)| namespace)
    }

    /// An element's namespace and local name; an undeclared prefix is not
    /// well-formed.
    fn resolve_element(&mut self, qname: &'t str) -> Option<(Option<u32>, &'t str)> {
        if !is_name(qname) {
            return None;
        }
        match qname.split_once(':') {
            Some(("", local)) => Some((self.binding(""), local)),
            Some((prefix, local)) => Some((Some(self.prefix(prefix)?), local)),
            None => Some((self.binding(""), qname)),
        }
    }

    /// An attribute's namespace and local name: none without a prefix.
    fn resolve_attribute(&mut self, qname: &'t str) -> Option<(Option<u32>, &'t str)> {
        if !is_name(qname) {
            return None;
        }
        match qname.split_once(':') {
            Some(("", local)) => Some((None, local)),
            Some((prefix, local)) => Some((Some(self.prefix(prefix)?), local)),
            None => Some((None, qname)),
        }
    }

    /// The namespace a prefix is bound to; `None` when none declared it.
    fn prefix(&mut self, prefix: &str) -> Option<u32> {
        match prefix {
            "xml" => Some(self.declare(Cow::Borrowed(XML_NAMESPACE))),
            _ => self.binding(prefix),
        }
    }
}

/// Whether `name` is an XML name with a prefix or none (a name that
/// starts with `:` has none, as roxmltree reads it).
fn is_name(name: &str) -> bool {
    match memchr::memchr(b':', name.as_bytes()) {
        Some(0) => is_name_part(&name[1..]),
        Some(colon) => is_name_part(&name[..colon]) && is_name_part(&name[colon + 1..]),
        None => is_name_part(name),
    }
}

/// A name without a colon; ASCII names, which GSDML files have, without
/// decoding characters.
fn is_name_part(part: &str) -> bool {
    let bytes = part.as_bytes();
    if bytes.is_ascii() {
        let starts = |b: &u8| b.is_ascii_alphabetic() || *b == b'_';
        let goes_on = |b: &u8| b.is_ascii_alphanumeric() || matches!(b, b'_' | b'-' | b'.');
        return bytes.first().is_some_and(starts) && bytes.iter().all(goes_on);
    }
    let mut chars = part.chars();
    chars.next().is_some_and(is_name_start) && chars.all(is_name_char)
}

/// XML 1.0's `NameStartChar`, the colon left out (namespaces give it its
/// own meaning).
fn is_name_start(c: char) -> bool {
    matches!(c,
        'A'..='Z' | '_' | 'a'..='z' | '\u{C0}'..='\u{D6}' | '\u{D8}'..='\u{F6}'
        | '\u{F8}'..='\u{2FF}' | '\u{370}'..='\u{37D}' | '\u{37F}'..='\u{1FFF}'
        | '\u{200C}'..='\u{200D}' | '\u{2070}'..='\u{218F}' | '\u{2C00}'..='\u{2FEF}'
        | '\u{3001}'..='\u{D7FF}' | '\u{F900}'..='\u{FDCF}' | '\u{FDF0}'..='\u{FFFD}'
        | '\u{10000}'..='\u{EFFFF}')
}

/// XML 1.0's `NameChar`, the colon left out.
fn is_name_char(c: char) -> bool {
    is_name_start(c)
        || matches!(c, '-' | '.' | '0'..='9' | '\u{B7}' | '\u{300}'..='\u{36F}' | '\u{203F}'..='\u{2040}')
}

/// The XML declaration `<?xml version="1.0" ...?>`, at `start`: only
/// first in the document, with a version, then an encoding and
/// `standalone` when it has them, in this order. (Their values roxmltree
/// takes as they are, and so does this.)
fn is_declaration_first(declaration: &str, start: usize) -> Option<()> {
    let inner = declaration.strip_prefix("<?xml")?.strip_suffix("?>")?;
    let mut pseudo = Vec::new();
    raw_attributes(declaration, "<?xml".len(), inner, &mut pseudo)?;
    let mut names = pseudo.iter().map(|(name, _)| *name).peekable();
    let has_version = names.next() == Some("version");
    names.next_if_eq(&"encoding");
    names.next_if_eq(&"standalone");
    (start == 0 && has_version && names.next().is_none()).then_some(())
}

fn is_declaration(name: &str) -> bool {
    name == "xmlns" || name.starts_with("xmlns:")
}

/// XML's white space.
fn is_blank(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\n' | b'\r')
}

/// The attributes of a start tag (`rest`, from after its name to before
/// `>` or `/>`, at `base` in `text`) into `attributes`, each value
/// normalized as XML reads it; `None` when they are not well-formed, or
/// more than `gsdc check` reads.
fn raw_attributes<'t>(
    text: &'t str,
    base: usize,
    rest: &str,
    attributes: &mut Vec<(&'t str, Cow<'t, str>)>,
) -> Option<()> {
    let mut at = 0;
    let bytes = rest.as_bytes();
    loop {
        let blanks = bytes[at..].iter().take_while(|&&b| is_blank(b)).count();
        at += blanks;
        if at == bytes.len() {
            return Some(());
        }
        if blanks == 0 || attributes.len() == shape::MAX_ATTRIBUTES {
            return None; // attributes are separated by white space
        }
        let name_len = bytes[at..]
            .iter()
            .take_while(|&&b| !is_blank(b) && b != b'=')
            .count();
        let name = &text[base + at..base + at + name_len];
        at += name_len;
        at += bytes[at..].iter().take_while(|&&b| is_blank(b)).count();
        if name.is_empty() || bytes.get(at) != Some(&b'=') {
            return None;
        }
        at += 1;
        at += bytes[at..].iter().take_while(|&&b| is_blank(b)).count();
        let quote = *bytes.get(at).filter(|&&q| q == b'"' || q == b'\'')?;
        let length = memchr::memchr(quote, &bytes[at + 1..])?;
        let value = &text[base + at + 1..base + at + 1 + length];
        attributes.push((name, attribute_value(value)?));
        at += length + 2;
    }
}

/// An attribute's value as XML reads it: each white-space character a
/// blank (a `\r\n` one), then references replaced. `None` for a `<` or a
/// reference XML does not define (a DTD would be needed, and GSDML files
/// have none).
fn attribute_value(raw: &str) -> Option<Cow<'_, str>> {
    // Without an early exit, which the compiler vectorizes: texts are long.
    let special = |any: bool, &b: &u8| any | matches!(b, b'<' | b'&' | b'\t' | b'\n' | b'\r');
    if !raw.as_bytes().iter().fold(false, special) {
        return Some(Cow::Borrowed(raw));
    }
    if raw.contains('<') {
        return None;
    }
    let mut value = String::with_capacity(raw.len());
    let mut rest = raw;
    while let Some(i) = rest.find(['&', '\t', '\n', '\r']) {
        value.push_str(&rest[..i]);
        let after = &rest[i + 1..];
        rest = match rest.as_bytes()[i] {
            b'&' => {
                let end = after.find(';')?;
                value.push(resolve_reference(&after[..end])?);
                &after[end + 1..]
            }
            b'\r' => {
                value.push(' ');
                after.strip_prefix('\n').unwrap_or(after)
            }
            _ => {
                value.push(' ');
                after
            }
        };
    }
    value.push_str(rest);
    Some(Cow::Owned(value))
}

/// The character `&name;` stands for: one of XML's five entities or a
/// character reference to a character XML allows.
fn resolve_reference(name: &str) -> Option<char> {
    let code = match name {
        "lt" => return Some('<'),
        "gt" => return Some('>'),
        "amp" => return Some('&'),
        "apos" => return Some('\''),
        "quot" => return Some('"'),
        _ => match name.strip_prefix("#x") {
            Some(hex) => u32::from_str_radix(hex, 16).ok()?,
            None => name.strip_prefix('#')?.parse().ok()?,
        },
    };
    char::from_u32(code).filter(|&c| is_xml_char(c))
}

/// Whether `text` has none of the characters XML forbids: the control
/// characters but tab, line feed and carriage return, U+FFFE and U+FFFF
/// (the other forbidden ones, lone surrogates, a `str` cannot hold).
fn has_only_xml_characters(text: &str) -> bool {
    let bytes = text.as_bytes();
    // By blocks without an early exit, which the compiler vectorizes.
    let control = |block: &[u8]| {
        block
            .iter()
            .fold(false, |any, &b| any | (b < 0x20 && !is_blank(b)))
    };
    !bytes.chunks(4096).any(control)
        && memchr::memmem::find(bytes, "\u{FFFE}".as_bytes()).is_none()
        && memchr::memmem::find(bytes, "\u{FFFF}".as_bytes()).is_none()
}

fn is_xml_char(c: char) -> bool {
    matches!(c, '\t' | '\n' | '\r' | '\u{20}'..='\u{D7FF}' | '\u{E000}'..='\u{FFFD}' | '\u{10000}'..)
}

/// An element of a [`Tree`], with roxmltree's names for what it gives.
#[derive(Clone, Copy)]
pub struct Node<'a, 't> {
    tree: &'a Tree<'t>,
    id: NodeId,
}

/// An element's name: local name and namespace.
pub struct TagName<'a> {
    name: &'a str,
    namespace: Option<&'a str>,
}

impl<'a> TagName<'a> {
    pub fn name(&self) -> &'a str {
        self.name
    }

    pub fn namespace(&self) -> Option<&'a str> {
        self.namespace
    }
}

/// An attribute of an element.
pub struct AttributeRef<'a, 't> {
    tree: &'a Tree<'t>,
    attribute: &'a Attribute<'t>,
}

impl<'a> AttributeRef<'a, '_> {
    pub fn name(&self) -> &'a str {
        self.attribute.name
    }

    pub fn namespace(&self) -> Option<&'a str> {
        self.tree.namespace(self.attribute.namespace)
    }

    pub fn value(&self) -> &'a str {
        &self.attribute.value
    }
}

/// How an attribute is asked for: by its local name (an attribute without
/// a namespace), or by namespace and local name.
pub trait AttributeName {
    fn is(&self, namespace: Option<&str>, name: &str) -> bool;
}

impl AttributeName for &str {
    fn is(&self, namespace: Option<&str>, name: &str) -> bool {
        namespace.is_none() && name == *self
    }
}

impl AttributeName for (&str, &str) {
    fn is(&self, namespace: Option<&str>, name: &str) -> bool {
        namespace == Some(self.0) && name == self.1
    }
}

impl Tree<'_> {
    fn namespace(&self, index: Option<u32>) -> Option<&str> {
        index.map(|i| &*self.namespaces[i as usize])
    }
}

impl<'a, 't> Node<'a, 't> {
    fn element(&self) -> &'a Element<'t> {
        &self.tree.elements[self.id as usize]
    }

    fn node(&self, id: NodeId) -> Option<Node<'a, 't>> {
        (id != NONE).then_some(Node {
            tree: self.tree,
            id,
        })
    }

    pub fn id(&self) -> NodeId {
        self.id
    }

    pub fn tag_name(&self) -> TagName<'a> {
        let element = self.element();
        TagName {
            name: element.name,
            namespace: self.tree.namespace(element.namespace),
        }
    }

    pub fn range(&self) -> Range<usize> {
        let range = &self.element().range;
        range.start as usize..range.end as usize
    }

    pub fn attributes(&self) -> impl Iterator<Item = AttributeRef<'a, 't>> + 'a {
        let Range { start, end } = self.element().attributes.clone();
        let tree = self.tree;
        tree.attributes[start as usize..end as usize]
            .iter()
            .map(move |attribute| AttributeRef { tree, attribute })
    }

    pub fn attribute(&self, name: impl AttributeName) -> Option<&'a str> {
        self.attributes()
            .find(|a| name.is(a.namespace(), a.name()))
            .map(|a| a.value())
    }

    pub fn has_attribute(&self, name: impl AttributeName) -> bool {
        self.attribute(name).is_some()
    }

    pub fn parent_element(&self) -> Option<Node<'a, 't>> {
        self.node(self.element().parent)
    }

    pub fn prev_sibling_element(&self) -> Option<Node<'a, 't>> {
        self.node(self.element().previous_sibling)
    }

    /// The elements in this one, in document order.
    pub fn children(&self) -> impl Iterator<Item = Node<'a, 't>> + 'a {
        let first = self.node(self.element().first_child);
        std::iter::successors(first, |n| n.node(n.element().next_sibling))
    }
}

/// Whether `node` is a GSDML element.
pub fn in_gsdml(node: &Node<'_, '_>) -> bool {
    node.tag_name().namespace() == Some(super::NAMESPACE)
}

/// The GSDML elements in `node` named `name`.
pub fn children<'a, 't: 'a>(
    node: Node<'a, 't>,
    name: &'a str,
) -> impl Iterator<Item = Node<'a, 't>> + 'a {
    node.children()
        .filter(move |c| in_gsdml(c) && c.tag_name().name() == name)
}

/// The first GSDML element in `node` named `name`.
pub fn child<'a, 't: 'a>(node: Node<'a, 't>, name: &'a str) -> Option<Node<'a, 't>> {
    children(node, name).next()
}

#[cfg(test)]
mod tests {
    //! The tree against roxmltree, which `gsdc check` reads with: the same
    //! documents accepted, and in them the same elements, namespaces,
    //! places, parents and attribute values.

    use super::Tree;

    fn roxmltree(text: &str) -> Option<roxmltree::Document<'_>> {
        let options = roxmltree::ParsingOptions {
            allow_dtd: false,
            ..roxmltree::ParsingOptions::default()
        };
        roxmltree::Document::parse_with_options(text, options).ok()
    }

    /// Every element of both in document order: name, namespace, range,
    /// the parent's position, and each attribute as (namespace, name, value).
    fn assert_same(text: &str, what: &str) {
        let ours = Tree::parse(text);
        let theirs = roxmltree(text);
        assert_eq!(
            ours.is_some(),
            theirs.is_some(),
            "{what}: accepted by the tree: {}, by roxmltree: {}",
            ours.is_some(),
            theirs.is_some()
        );
        let (Some(ours), Some(theirs)) = (ours, theirs) else {
            return;
        };
        let theirs: Vec<_> = theirs.descendants().filter(|n| n.is_element()).collect();
        assert_eq!(ours.elements.len(), theirs.len(), "{what}: element count");
        for (i, theirs) in theirs.iter().enumerate() {
            let ours = super::Node {
                tree: &ours,
                id: i as u32,
            };
            let at = format!("{what}, element {i} <{}>", theirs.tag_name().name());
            assert_eq!(ours.tag_name().name(), theirs.tag_name().name(), "{at}");
            assert_eq!(
                ours.tag_name().namespace(),
                theirs.tag_name().namespace(),
                "{at}"
            );
            assert_eq!(ours.range(), theirs.range(), "{at}");
            let parent_range = |n: Option<std::ops::Range<usize>>| n;
            assert_eq!(
                parent_range(ours.parent_element().map(|p| p.range())),
                parent_range(theirs.parent_element().map(|p| p.range())),
                "{at}: parent"
            );
            let ours: Vec<_> = ours
                .attributes()
                .map(|a| (a.namespace(), a.name(), a.value()))
                .collect();
            let theirs: Vec<_> = theirs
                .attributes()
                .map(|a| (a.namespace(), a.name(), a.value()))
                .collect();
            assert_eq!(ours, theirs, "{at}: attributes");
        }
    }

    fn corpus() -> Vec<(String, String)> {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus");
        let mut files = Vec::new();
        for dir in ["gsdml", "gsdml-invalid"] {
            for entry in std::fs::read_dir(root.join(dir)).expect("../shared/corpus") {
                let path = entry.unwrap().path();
                if path.extension().is_some_and(|e| e == "xml") {
                    let text = crate::gsdml::decode(&std::fs::read(&path).unwrap())
                        .unwrap()
                        .into_owned();
                    files.push((path.display().to_string(), text));
                }
            }
        }
        assert!(files.len() >= 16, "the corpus is missing");
        files
    }

    #[test]
    fn reads_every_corpus_file_as_roxmltree_does() {
        for (name, text) in corpus() {
            assert_same(&text, &name);
        }
    }

    #[test]
    fn refuses_what_roxmltree_refuses() {
        let cases = [
            ("a DTD", "<!DOCTYPE a><a/>"),
            ("no root", "<?xml version=\"1.0\"?>"),
            ("two roots", "<a/><b/>"),
            ("text outside the root", "<a/>x"),
            ("an unclosed element", "<a><b></b>"),
            ("a mismatched end tag", "<a><b></a></b>"),
            ("an end tag too many", "<a></a></b>"),
            ("a duplicate attribute", "<a x=\"1\" x=\"2\"/>"),
            (
                "a duplicate by namespace",
                "<a xmlns:p=\"u\" xmlns:q=\"u\" p:x=\"1\" q:x=\"2\"/>",
            ),
            ("an undeclared prefix", "<p:a/>"),
            ("a declaration of no prefix", "<a xmlns:=\"u\"/>"),
            ("an undeclared attribute prefix", "<a p:x=\"1\"/>"),
            ("an unknown entity", "<a x=\"&nbsp;\"/>"),
            ("an unknown entity in text", "<a>&nbsp;</a>"),
            ("a character XML forbids", "<a x=\"\u{1}\"/>"),
            ("a forbidden character reference", "<a x=\"&#1;\"/>"),
            ("a < in a value", "<a x=\"<\"/>"),
            ("an unquoted value", "<a x=1/>"),
            ("attributes without a blank between", "<a x=\"1\"y=\"2\"/>"),
            ("-- in a comment", "<a><!-- a -- b --></a>"),
            ("a declaration not first", " <?xml version=\"1.0\"?><a/>"),
            (
                "a declaration without a version",
                "<?xml ver3ion=\"1.0\"?><a/>",
            ),
            (
                "a declaration out of order",
                "<?xml encoding=\"UTF-8\" version=\"1.0\"?><a/>",
            ),
            (
                "a declaration with more",
                "<?xml version=\"1.0\" x=\"1\"?><a/>",
            ),
            ("an attribute without a value", "<a x/>"),
            ("a control character in a name", "<a x\u{9A}y=\"1\"/>"),
            ("a name starting with a digit", "<a 1x=\"1\"/>"),
        ];
        for (what, text) in cases {
            assert!(roxmltree(text).is_none(), "roxmltree accepts {what}");
            assert_same(text, what);
        }
        let accepted = [
            ("values as XML normalizes them", "<a x=\"1\t2\r\n3\n&#10;&amp;&lt;&#x41;\" y='\"'/>"),
            ("names beyond ASCII", "<\u{E9}l\u{E9}ment attribut\u{B7}\u{300}=\"1\"/>"),
            ("namespaces in scope", "<a xmlns=\"u\" xmlns:p=\"v\"><b p:x=\"1\" xml:lang=\"de\"><c xmlns=\"\"/></b><p:d/></a>"),
            ("comments, instructions and CDATA", "<?xml version=\"1.0\" encoding='iso-8859-1' standalone=\"yes\" ?><!--c--><a><?p i?><![CDATA[<x>]]>t&amp;</a><!--d-->\n"),
        ];
        for (what, text) in accepted {
            assert!(roxmltree(text).is_some(), "roxmltree refuses {what}");
            assert_same(text, what);
        }
    }

    /// The bounds `gsdc check` keeps (`shape`): at each the two agree, and
    /// one beyond it both refuse.
    #[test]
    fn keeps_the_checkers_bounds() {
        use super::shape::{MAX_ATTRIBUTES, MAX_DEPTH, MAX_NAMESPACES};
        let nested = |n: usize| format!("{}{}", "<a>".repeat(n), "</a>".repeat(n));
        let namespaces = |n: usize| {
            let declarations: String = (0..n).map(|i| format!(" xmlns:p{i}=\"u{i}\"")).collect();
            format!("<a{declarations}/>")
        };
        let attributes = |n: usize| {
            let attributes: String = (0..n).map(|i| format!(" x{i}=\"{i}\"")).collect();
            format!("<a{attributes}/>")
        };
        for (what, make, limit) in [
            ("nesting", &nested as &dyn Fn(usize) -> String, MAX_DEPTH),
            ("namespace declarations", &namespaces, MAX_NAMESPACES),
            ("attributes", &attributes, MAX_ATTRIBUTES),
        ] {
            for (n, accepted) in [(limit, true), (limit + 1, false)] {
                let text = make(n);
                assert_eq!(
                    crate::gsdml::parse(&text).is_ok(),
                    accepted,
                    "check, {n} {what}"
                );
                assert_eq!(Tree::parse(&text).is_some(), accepted, "tree, {n} {what}");
            }
        }
    }

    /// Characters of a small corpus file changed into each of the
    /// characters markup is made of (and a control character, a C1 one and
    /// a letter beyond ASCII, which names may or may not hold), and the file
    /// cut off there: both readers decide alike. (The fuzz target goes on
    /// from here: it found the C1 character in a name.)
    #[test]
    fn decides_like_roxmltree_on_broken_files() {
        let (name, text) = corpus()
            .into_iter()
            .filter(|(name, _)| name.contains("/gsdml/"))
            .min_by_key(|(_, text)| text.len())
            .unwrap();
        let step = text.len() / 400 + 1;
        for at in (0..text.len())
            .step_by(step)
            .filter(|&i| text.is_char_boundary(i))
        {
            for insert in [
                "<", ">", "&", "\"", "'", "=", ":", "/", " ", "\u{1}", "\u{9A}", "\u{E9}", "",
            ] {
                let next = text[at..].chars().next().map_or(at, |c| at + c.len_utf8());
                let changed = format!("{}{insert}{}", &text[..at], &text[next..]);
                assert_same(&changed, &format!("{name} with {insert:?} at {at}"));
            }
            assert_same(&text[..at], &format!("{name} cut at {at}"));
        }
    }
}
