//! The Rust emitter: the layout model (`super::layout`) to the firmware
//! layout (`<stem>_layout.rs`) through `templates/layout.rs.jinja`, and the
//! support module every layout is built from (`gsdc_support.rs`, from
//! `templates/support/`), the same for every description, so a build with
//! several layouts writes it once.
//!
//! What is Rust's own: the spelling of names (`UPPER_SNAKE` constants,
//! `CamelCase` types, a module for each part), a reference as an intra-doc
//! link, the support module and its generic telegram types.

mod tables;

use super::layout::{self, Doc, PkwItem, Ref, Scope, Val};
use super::{Artifact, ArtifactKind};
use crate::ir::{Ident, Ir, PkwKind};
use minijinja::value::ViaDeserialize;
use serde::Serialize;

pub(super) const TEMPLATE: &str = include_str!("../../templates/layout.rs.jinja");

/// The support module's file, and its parts: `pub mod name;` in the first
/// is replaced by the part's text.
pub const SUPPORT_FILE_NAME: &str = "gsdc_support.rs";
const SUPPORT: &str = include_str!("../../templates/support/mod.rs");
const SUPPORT_PARTS: [(&str, &str); 7] = [
    (
        "pkw_pke_ind_pwe",
        include_str!("../../templates/support/pkw_pke_ind_pwe.rs"),
    ),
    (
        "pkw_station_command",
        include_str!("../../templates/support/pkw_station_command.rs"),
    ),
    (
        "pkw_profidrive",
        include_str!("../../templates/support/pkw_profidrive.rs"),
    ),
    (
        "diagnosis",
        include_str!("../../templates/support/diagnosis.rs"),
    ),
    (
        "gateway",
        include_str!("../../templates/support/gateway.rs"),
    ),
    ("device", include_str!("../../templates/support/device.rs")),
    (
        "numbering",
        include_str!("../../templates/support/numbering.rs"),
    ),
];

#[derive(Serialize)]
struct Context<'a> {
    /// The file's header comment, finished.
    header: String,
    /// The support module of the PKW channel's codec.
    pkw_module: Option<&'static str>,
    #[serde(flatten)]
    layout: &'a layout::Layout,
    /// The device tables, finished.
    tables: String,
}

/// The firmware layout of a description.
pub fn emit(ir: &Ir) -> String {
    render(TEMPLATE, ir).expect("the layout template renders every IR (tested)")
}

pub(super) fn render(template: &str, ir: &Ir) -> Result<String, minijinja::Error> {
    let layout = layout::build(ir);
    let context = Context {
        header: header(ir),
        pkw_module: match ir.telegram.pkw {
            PkwKind::None => None,
            PkwKind::PkeIndPwe => Some("pkw_pke_ind_pwe"),
            PkwKind::StationCommandAddressValue => Some("pkw_station_command"),
            PkwKind::Profidrive => Some("pkw_profidrive"),
        },
        layout: &layout,
        tables: tables::render(&layout.tables),
    };
    let mut env = super::code_templates();
    env.add_filter(
        "doc",
        |value: minijinja::Value, indent: Option<usize>| -> Result<String, minijinja::Error> {
            let text = super::sentence(&value, &|doc| rendered(doc))?;
            Ok(doc_lines(&text, indent.unwrap_or(0)))
        },
    );
    env.add_filter("camel", |name: ViaDeserialize<Ident>| name.camel());
    env.add_filter("lit", |value: ViaDeserialize<Val>| lit(&value));
    env.add_filter("ty", |ty: String| match ty.as_str() {
        "size" => "usize".to_string(),
        "text" => "&str".to_string(),
        other => other.to_string(),
    });
    env.template_from_str(template)?.render(context)
}

/// A sentence of the model with its references as intra-doc links.
fn rendered(doc: &Doc) -> String {
    doc.render(|to| format!("[`{}`]", path(to, &doc.at)))
}

/// `text` as `///` lines indented by `indent`, wrapped at 80 columns.
fn doc_lines(text: &str, indent: usize) -> String {
    super::wrap_words(text, 80 - indent - 4)
        .iter()
        .map(|line| format!("{:indent$}/// {line}", ""))
        .collect::<Vec<_>>()
        .join("\n")
}

/// A model's doc as `///` lines indented by `indent`.
fn doc_comment(doc: &Doc, indent: usize) -> String {
    doc_lines(&rendered(doc), indent)
}

/// The path of an item as a link from `at` names it: `LEN` beside it,
/// `control_word` from the root, `super::FIRST_NODE` from a module.
fn path(to: &Ref, at: &Scope) -> String {
    let (scope, name) = match to {
        Ref::Const(scope, name) => (scope, name.upper_snake()),
        Ref::Values(scope, name) => (scope, name.camel()),
        Ref::Part(scope) => (&Scope::Root, scope.module().unwrap_or_default()),
        Ref::Pkw(item) => {
            let item = match item {
                PkwItem::Request => "PkwRequest",
                PkwItem::RequestDecode => "PkwRequest::decode",
                PkwItem::Response => "PkwResponse",
                PkwItem::ResponseEncode => "PkwResponse::encode",
            };
            return item.to_string();
        }
    };
    let (here, there) = (at.module(), scope.module());
    if here == there {
        return name;
    }
    match (here, there) {
        (None, Some(there)) => format!("{there}::{name}"),
        (_, None) => format!("super::{name}"),
        (Some(_), Some(there)) => format!("super::{there}::{name}"),
    }
}

/// A number or a text as Rust writes it: `0x0A10`, `0x0000_0202` (an ident
/// number in two groups), `12`, `"text"`.
fn lit(value: &Val) -> String {
    match value {
        Val::Dec(n) => n.to_string(),
        Val::Hex(n, 8) => format!("0x{:04X}_{:04X}", n >> 16, n & 0xFFFF),
        Val::Hex(n, digits) => format!("0x{n:0digits$X}"),
        Val::Text(text) => format!("{text:?}"),
    }
}

/// `gsdc_support.rs`: the support code as one module, `gsdc_support`, with
/// its parts inlined as modules of their own. Firmware includes it once at
/// the crate root; the layouts refer to it as `crate::gsdc_support`.
pub fn support_module() -> Artifact {
    let mut text = format!(
        "// @generated by {}; do not edit.\n\
         // The support code of gsdc's firmware layouts. Include it once at the\n\
         // crate root: include!(concat!(env!(\"OUT_DIR\"), \"/gsdc_support.rs\"));\n\
         \n\
         // A crate uses only the parts its layouts need.\n\
         #[allow(dead_code)]\n\
         pub mod gsdc_support {{\n",
        crate::GENERATOR
    );
    for line in SUPPORT.lines() {
        let part = line
            .strip_prefix("pub mod ")
            .and_then(|l| l.strip_suffix(';'))
            .and_then(|name| SUPPORT_PARTS.iter().find(|(n, _)| *n == name));
        match part {
            Some((name, part)) => {
                text.push_str(&format!("    pub mod {name} {{\n"));
                indent(&mut text, part, 2);
                text.push_str("    }\n");
            }
            None => indent(&mut text, line, 1),
        }
    }
    text.push_str("}\n");
    Artifact {
        kind: ArtifactKind::RustSupport,
        file_name: SUPPORT_FILE_NAME.to_string(),
        contents: text.into_bytes(),
    }
}

/// Appends `text`'s lines indented by `levels` of four spaces; blank lines
/// stay empty, as rustfmt leaves them.
fn indent(out: &mut String, text: &str, levels: usize) {
    for line in text.lines() {
        if !line.is_empty() {
            out.push_str(&"    ".repeat(levels));
            out.push_str(line);
        }
        out.push('\n');
    }
}

/// `md810dp.toml` gives `md810dp_layout.rs`, `mv810-pnet02.toml`
/// `mv810_pnet02_layout.rs`: `_` for `-`, as Rust names its source files.
pub fn file_name(ir: &Ir) -> String {
    format!("{}_layout.rs", super::layout_stem(ir))
}

/// The header comment: where the file comes from, what it holds, and the
/// description's notes.
fn header(ir: &Ir) -> String {
    let mut lines = vec![
        format!(
            "@generated by {} from {}; do not edit.",
            crate::GENERATOR,
            ir.source_name
        ),
        format!("Description fingerprint: {}", ir.fingerprint),
        String::new(),
    ];
    lines.extend(summary(ir));
    let notes = notes(ir);
    if !notes.is_empty() {
        lines.push(String::new());
        lines.extend(notes);
    }
    lines
        .iter()
        .map(|line| {
            if line.is_empty() {
                "//".to_string()
            } else {
                format!("// {line}")
            }
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The header's paragraph: "Firmware layout of Inovance MD810DP: the cyclic
/// telegrams, ...", wrapped to rustfmt's width after `// `.
fn summary(ir: &Ir) -> Vec<String> {
    let text = format!(
        "Firmware layout of {} {}: {}, from the same description as the device \
         files. Multi-byte values on the bus are big-endian. no_std, no unsafe, \
         no dependencies. It is built from the support module gsdc writes beside \
         it, `gsdc_support.rs`, which the crate includes once at its root, \
         whatever the number of layouts. What each byte means on the wire: \
         docs/wire-format.md in gsdc's repository.",
        ir.device.vendor,
        ir.device.model,
        super::layout_contents(ir)
    );
    super::wrap_words(&text, 77)
}

/// Header notes in lines that keep the comment within 80 columns; a note's
/// continuation lines are indented.
fn notes(ir: &Ir) -> Vec<String> {
    super::header_notes(ir, super::ArtifactKind::RustLayout)
        .iter()
        .flat_map(|note| {
            super::wrap_words(note, 75)
                .into_iter()
                .enumerate()
                .map(|(i, line)| if i == 0 { line } else { format!("  {line}") })
                .collect::<Vec<_>>()
        })
        .collect()
}

#[cfg(test)]
use crate::pkw::support;

#[cfg(test)]
mod support_tests;

#[cfg(test)]
mod support_gateway_tests;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ir::Ident;

    #[test]
    fn file_names_are_identifiers() {
        let text = include_str!("../../descriptions/mv810-pnet02.toml");
        let ir = crate::testing::load("mv810-pnet02.toml", text).0.unwrap();
        assert_eq!(file_name(&ir), "mv810_pnet02_layout.rs");
    }

    #[test]
    fn numbers_and_texts_as_rust_writes_them() {
        assert_eq!(lit(&Val::hex_u32(0x0000_0202)), "0x0000_0202");
        assert_eq!(lit(&Val::hex_u32(0x1234_ABCD)), "0x1234_ABCD");
        assert_eq!(lit(&Val::hex_u16(0x0A10)), "0x0A10");
        assert_eq!(lit(&Val::hex_u8(0x03)), "0x03");
        assert_eq!(lit(&Val::Dec(60000)), "60000");
        assert_eq!(lit(&Val::Text("a \"b\"".into())), "\"a \\\"b\\\"\"");
    }

    /// A link names an item from where the doc stands: beside it, in a
    /// module of the root, at the root from a module, or in another module.
    #[test]
    fn links_name_items_from_where_the_doc_stands() {
        let ident = |snake: &str| Ident::of(&snake.split('_').collect::<Vec<_>>());
        let diagnosis = Scope::part("diagnosis");
        let cases = [
            (
                Scope::Gateway,
                Ref::Const(Scope::Gateway, ident("first_node")),
                "FIRST_NODE",
            ),
            (
                Scope::Root,
                Ref::Const(diagnosis.clone(), ident("len")),
                "diagnosis::LEN",
            ),
            (
                Scope::part("settings"),
                Ref::Const(Scope::Root, ident("telegram1_ident")),
                "super::TELEGRAM1_IDENT",
            ),
            (
                Scope::part("settings"),
                Ref::Values(diagnosis.clone(), ident("bits_8_to_15")),
                "super::diagnosis::Bits8To15",
            ),
            (
                Scope::GatewayDiagnosis,
                Ref::Values(Scope::GatewayDiagnosis, ident("parameter_error_code")),
                "ParameterErrorCode",
            ),
            (
                Scope::Root,
                Ref::Part(Scope::part("control_word")),
                "control_word",
            ),
            (
                diagnosis,
                Ref::Part(Scope::part("control_word")),
                "super::control_word",
            ),
            (
                Scope::Root,
                Ref::Pkw(PkwItem::RequestDecode),
                "PkwRequest::decode",
            ),
        ];
        for (at, to, path) in cases {
            let doc = Doc::at(at).text("See ").link(to).text(".");
            assert_eq!(rendered(&doc), format!("See [`{path}`]."));
        }
    }

    #[test]
    fn docs_wrap_within_80_columns_at_their_indentation() {
        let doc = Doc::plain("word ".repeat(30));
        for indent in [0, 4, 8] {
            let lines = doc_comment(&doc, indent);
            assert!(lines.lines().count() > 1, "{lines}");
            for line in lines.lines() {
                assert!(line.len() <= 80, "{line}");
                assert!(
                    line.starts_with(&format!("{:indent$}/// word", "")),
                    "{line}"
                );
            }
        }
    }
}
