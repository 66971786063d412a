//! The C emitter: the layout model (`super::layout`) to the firmware layout
//! for C (`<stem>_layout.h`) through `templates/c/layout.h.jinja`, and the
//! support header every layout includes (`gsdc_support.h`, from
//! `templates/c/gsdc_support.h`), the same for every description.
//!
//! C has one namespace per translation unit, so every name a layout declares
//! starts with a prefix spelt from the description's file name (`MD810DP_`,
//! `md810dp_`), and the codecs that do not depend on the description live
//! once in the support header, under its guard: any number of layouts can be
//! included together. [`verify`] reads every header back and refuses one
//! that declares a name without the prefix, or any name twice (counting the
//! support header's).
//!
//! What is C's own: the prefix, a reference as the name it stands for, macro
//! initializers, the accessors' functions, and the check of the names.

mod tables;
mod text;
mod verify;

pub(crate) use verify::declared_names;
pub use verify::verify;

use super::layout::{self, Doc, PkwItem, Ref, Val};
use super::{Artifact, ArtifactKind};
use crate::ir::{Ident, Ir, PkwKind};
use minijinja::value::{Kwargs, Rest, ViaDeserialize};
use minijinja::Value;
use serde::Serialize;
use text::{block_comment, c_string, comment_text, indented_comment, initializer, wrap, WIDTH};

pub(super) const TEMPLATE: &str = include_str!("../../templates/c/layout.h.jinja");

/// The support header's file, its text, and the line the emitter gives the
/// release that wrote it.
pub const SUPPORT_FILE_NAME: &str = "gsdc_support.h";
const SUPPORT: &str = include_str!("../../templates/c/gsdc_support.h");
const SUPPORT_VERSION_LINE: &str = "#define GSDC_SUPPORT_VERSION 0\n";

#[derive(Serialize)]
struct Context<'a> {
    /// The file's header comment, finished.
    header: String,
    generator: &'static str,
    guard: String,
    /// The prefix, upper and lower case, without the underscore.
    p: &'a str,
    l: &'a str,
    support_version: u32,
    #[serde(flatten)]
    layout: &'a layout::Layout,
    /// The device tables, finished.
    tables: String,
}

/// The C firmware layout of a description.
pub fn emit(ir: &Ir) -> String {
    render(TEMPLATE, ir).expect("the C layout template renders every IR (tested)")
}

pub(super) fn render(template: &str, ir: &Ir) -> Result<String, minijinja::Error> {
    let layout = layout::build(ir);
    let prefix = prefix(ir);
    let names = Names {
        p: prefix.upper_snake(),
        l: prefix.snake(),
        pkw: match ir.telegram.pkw {
            PkwKind::None => None,
            PkwKind::PkeIndPwe => Some("gsdc_pke"),
            PkwKind::StationCommandAddressValue => Some("gsdc_station"),
            PkwKind::Profidrive => Some("gsdc_profidrive"),
        },
    };
    let context = Context {
        header: header(ir, &names.p, &names.l),
        generator: crate::GENERATOR,
        guard: format!("{}_LAYOUT_H", names.p),
        p: &names.p,
        l: &names.l,
        support_version: support_version(),
        layout: &layout,
        tables: tables::render(&names, &layout.tables),
    };
    environment(&names)
        .template_from_str(template)?
        .render(context)
}

/// The code templates' environment with C's spelling: names with the
/// prefix, sentences as comments, literals, initializers.
fn environment(names: &Names) -> minijinja::Environment<'static> {
    let mut env = super::code_templates();
    let (upper, lower, spelling) = (names.clone(), names.clone(), names.clone());
    env.add_function("upper_name", move |parts: Rest<Value>| {
        upper.upper_of(&parts)
    });
    env.add_function("lower_name", move |parts: Rest<Value>| {
        lower.lower_of(&parts)
    });
    env.add_filter(
        "doc",
        move |value: Value, indent: Option<usize>, options: Kwargs| {
            let text = super::sentence(&value, &|doc| spelling.rendered(doc))?;
            let ending: Option<String> = options.get("ending")?;
            let more: Option<String> = options.get("more")?;
            options.assert_all_used()?;
            let text = with_ending(&text, ending.as_deref().unwrap_or(""));
            let text = match more {
                Some(more) => format!("{text} {more}"),
                None => text,
            };
            Ok::<_, minijinja::Error>(indented_comment(&text, indent.unwrap_or(0)))
        },
    );
    env.add_filter("lit", |value: ViaDeserialize<Val>| lit(&value));
    env.add_filter("unsigned", |n: u64| format!("{n}U"));
    env.add_filter("comment_text", |text: String| comment_text(&text));
    // The items: a list, or the lines of a macro's output.
    env.add_function("initializer", |name: String, items: Value| {
        let items: Vec<String> = match items.as_str() {
            Some(lines) => lines
                .lines()
                .filter(|line| !line.is_empty())
                .map(str::to_string)
                .collect(),
            None => items.try_iter()?.map(|item| item.to_string()).collect(),
        };
        Ok::<_, minijinja::Error>(initializer(&name, &items))
    });
    env
}

/// `text` with `ending` before its full stop.
fn with_ending(text: &str, ending: &str) -> String {
    match text.strip_suffix('.') {
        Some(stem) => format!("{stem}{ending}."),
        None => format!("{text}{ending}"),
    }
}

/// A number or a text as C writes it: `0x0A10U`, `0x00000202UL` (an
/// unsigned long, which holds 32 bits where int has 16), `12U`, `"text"`.
fn lit(value: &Val) -> String {
    match value {
        Val::Dec(n) => format!("{n}U"),
        Val::Hex(n, 8) => format!("0x{n:08X}UL"),
        Val::Hex(n, digits) => format!("0x{n:0digits$X}U"),
        Val::Text(text) => c_string(text),
    }
}

/// `md810dp_layout.h`, beside `md810dp_layout.rs`.
pub fn file_name(ir: &Ir) -> String {
    format!("{}_layout.h", super::layout_stem(ir))
}

/// The prefix of every name a layout declares, spelt from the layout's
/// stem: `md810dp` for `md810dp.toml`, `mv810_pnet02` for
/// `mv810-pnet02.toml`, and `gsdc_9kdp1` for `9kdp1.toml`, since a C name
/// cannot start with a digit (and the support header names nothing
/// `gsdc_` and a digit). Every other name that starts with the word `gsdc`
/// is the support header's: a stem that spells it (`gsdc.toml`,
/// `Gsdc-prm.toml`) or no word at all (`_.toml`, `网关.toml`) is prefixed
/// `layout` (`layout_gsdc`, `layout`), so that no layout can declare
/// `gsdc_node_totals` beside the support header's.
fn prefix(ir: &Ir) -> Ident {
    let stem = super::layout_stem(ir);
    let ident = Ident::from_text(&stem, "gsdc");
    match ident.words() {
        [gsdc, next, ..] if gsdc == "gsdc" && next.starts_with(|c: char| c.is_ascii_digit()) => {
            ident
        }
        [gsdc, ..] if gsdc == "gsdc" => Ident::from_text(&format!("layout_{stem}"), "layout"),
        _ => ident,
    }
}

/// `gsdc_support.h`: the hand-written support header, with the release that
/// wrote it, which each layout checks.
pub fn support_header() -> Artifact {
    let version = format!("#define GSDC_SUPPORT_VERSION {}\n", support_version());
    let text = format!(
        "/* @generated by {}; do not edit. */\n{}",
        crate::GENERATOR,
        SUPPORT.replacen(SUPPORT_VERSION_LINE, &version, 1)
    );
    Artifact {
        kind: ArtifactKind::CSupport,
        file_name: SUPPORT_FILE_NAME.to_string(),
        contents: text.into_bytes(),
    }
}

/// The crate's version as one number, major * 10000 + minor * 100 + patch.
fn support_version() -> u32 {
    [
        env!("CARGO_PKG_VERSION_MAJOR"),
        env!("CARGO_PKG_VERSION_MINOR"),
        env!("CARGO_PKG_VERSION_PATCH"),
    ]
    .iter()
    .map(|part| {
        part.parse::<u32>()
            .expect("cargo's version parts are numbers")
    })
    .fold(0, |version, part| version * 100 + part)
}

/// The prefix in both cases, and the names built on it.
#[derive(Clone)]
struct Names {
    p: String,
    l: String,
    /// The support header's codec of the PKW channel, `gsdc_pke`.
    pkw: Option<&'static str>,
}

impl Names {
    /// `MD810DP_PZD_OUT` of `pzd_out`.
    fn upper(&self, rest: &str) -> String {
        format!("{}_{}", self.p, rest.to_ascii_uppercase())
    }

    fn lower(&self, rest: &str) -> String {
        format!("{}_{}", self.l, rest.to_ascii_lowercase())
    }

    /// The name of the parts a template joins: `MD810DP_PZD_OUT_1_DEFAULT`
    /// of `pzd_out`, 1 and `default`; an empty part (the root's) is left out.
    fn upper_of(&self, parts: &[Value]) -> String {
        self.upper(&joined_parts(parts))
    }

    fn lower_of(&self, parts: &[Value]) -> String {
        self.lower(&joined_parts(parts))
    }

    /// A sentence of the model with each reference written as the name it
    /// stands for: `MD810DP_DIAGNOSIS_LEN`, `MV810_PNET02_CONTROL_WORD_*`.
    fn rendered(&self, doc: &Doc) -> String {
        doc.render(|to| self.reference(to))
    }

    fn reference(&self, to: &Ref) -> String {
        let name = |scope: &layout::Scope, name: Option<&Ident>| {
            let parts: Vec<String> = scope
                .infix()
                .into_iter()
                .chain(name.map(Ident::snake))
                .collect();
            self.upper(&parts.join("_"))
        };
        match to {
            Ref::Const(scope, ident) => name(scope, Some(ident)),
            Ref::Part(scope) => format!("{}_*", name(scope, None)),
            Ref::Values(scope, ident) => format!("{}_*", name(scope, Some(ident))),
            Ref::Pkw(item) => {
                let codec = self
                    .pkw
                    .expect("only a layout with a PKW channel names its codec");
                let item = match item {
                    PkwItem::Request => "request_t",
                    PkwItem::RequestDecode => "request_decode",
                    PkwItem::Response => "response_t",
                    PkwItem::ResponseEncode => "response_encode",
                };
                format!("{codec}_{item}")
            }
        }
    }
}

/// Parts of a name, `_` between them, the empty ones left out.
fn joined_parts(parts: &[Value]) -> String {
    parts
        .iter()
        .filter(|part| !part.is_none() && !part.is_undefined())
        .map(Value::to_string)
        .filter(|part| !part.is_empty())
        .collect::<Vec<_>>()
        .join("_")
}

/// The header comment: where the file comes from, what it holds, how its
/// names are spelt, and the description's notes.
fn header(ir: &Ir, p: &str, l: &str) -> String {
    let about = format!(
        "Firmware layout of {} {} for C: {}, from the same description as the \
         device files. \
         Multi-byte values on the bus are big-endian; telegrams are byte arrays, \
         read and written with the accessors of {SUPPORT_FILE_NAME}, which gsdc \
         writes beside this file. C99 or C++, no allocation; every name starts \
         with {p}_ or {l}_, so the layouts of several descriptions can be \
         included together.",
        ir.device.vendor,
        ir.device.model,
        super::layout_contents(ir)
    );
    let mut lines = vec![
        format!(
            "@generated by {} from {}; do not edit.",
            crate::GENERATOR,
            comment_text(&ir.source_name)
        ),
        format!("Description fingerprint: {}", ir.fingerprint),
        String::new(),
    ];
    lines.extend(wrap(&comment_text(&about), WIDTH - 3));
    let notes = super::header_notes(ir, super::ArtifactKind::CHeader);
    if !notes.is_empty() {
        lines.push(String::new());
    }
    for note in notes {
        let wrapped = wrap(&comment_text(&note), WIDTH - 5);
        lines.extend(wrapped.into_iter().enumerate().map(|(i, line)| {
            if i == 0 {
                line
            } else {
                format!("  {line}")
            }
        }));
    }
    block_comment(&lines)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn load(name: &str, text: &str) -> Ir {
        crate::testing::load(name, text).0.unwrap()
    }

    fn md810() -> Ir {
        load(
            "md810dp.toml",
            include_str!("../../descriptions/md810dp.toml"),
        )
    }

    #[test]
    fn prefixes_and_file_names_come_from_the_stem() {
        let ir = md810();
        assert_eq!(file_name(&ir), "md810dp_layout.h");
        assert_eq!(prefix(&ir).upper_snake(), "MD810DP");
        let text = include_str!("../../descriptions/mv810-pnet02.toml");
        let ir = load("mv810-pnet02.toml", text);
        assert_eq!(file_name(&ir), "mv810_pnet02_layout.h");
        assert_eq!(prefix(&ir).snake(), "mv810_pnet02");
        let ir = load("9kdp1.toml", include_str!("../../descriptions/9kdp1.toml"));
        assert_eq!(file_name(&ir), "9kdp1_layout.h");
        assert_eq!(prefix(&ir).upper_snake(), "GSDC_9KDP1");
    }

    /// A gateway whose stem spells the support header's `gsdc` (or no word,
    /// which gave it the fallback `gsdc`) declared `gsdc_node_totals` twice:
    /// E900, a bug in gsdc, for a description the loader accepts. Its prefix
    /// is `layout` now, and the header passes its verification.
    #[test]
    fn a_stem_that_spells_gsdc_gets_a_prefix_of_its_own() {
        let text = include_str!("../../descriptions/md810-gateway.toml");
        for (name, expected) in [
            ("gsdc.toml", "layout_gsdc"),
            ("Gsdc.toml", "layout_gsdc"),
            ("gsdc-prm.toml", "layout_gsdc_prm"),
            ("_.toml", "layout"),
            ("é.toml", "layout"),
            ("网关.toml", "layout"),
            ("gsdc_9.toml", "gsdc_9"),
            ("gsdcx.toml", "gsdcx"),
        ] {
            let ir = load(name, text);
            assert_eq!(prefix(&ir).snake(), expected, "{name}");
            assert!(crate::compile(&ir).is_ok(), "{name}");
        }
    }

    #[test]
    fn the_support_header_says_which_release_wrote_it() {
        assert_eq!(SUPPORT.matches(SUPPORT_VERSION_LINE).count(), 1);
        let support = String::from_utf8(support_header().contents).unwrap();
        let version = format!("#define GSDC_SUPPORT_VERSION {}\n", support_version());
        assert!(support.contains(&version), "{support}");
        assert!(!support.contains(SUPPORT_VERSION_LINE));
        // 0.1.0 is 100; 1.2.3 would be 10203.
        let [major, minor, patch] = [
            env!("CARGO_PKG_VERSION_MAJOR"),
            env!("CARGO_PKG_VERSION_MINOR"),
            env!("CARGO_PKG_VERSION_PATCH"),
        ]
        .map(|p| p.parse::<u32>().unwrap());
        assert_eq!(support_version(), major * 10000 + minor * 100 + patch);
    }

    /// A range check leaves out the comparisons an Unsigned16 always passes
    /// (compilers warn about them): MD810's addresses take any value, a
    /// timeout from 0 has a most, one from 5 a least too.
    #[test]
    fn range_checks_leave_out_what_an_unsigned16_always_passes() {
        let any = emit(&md810());
        assert!(
            any.contains(
                "md810dp_pzd_out_allowed(uint16_t value)\n{\n    (void)value;\n    return true;\n}"
            ),
            "{any}"
        );
        for (range, check) in [
            ("[0, 60000]", "return (value <= MV810_PNET02_SETTINGS_ALLOWED_2_MAX);"),
            ("[5, 65535]", "return (value >= MV810_PNET02_SETTINGS_ALLOWED_2_MIN);"),
            (
                "[5, 60000]",
                "return (value >= MV810_PNET02_SETTINGS_ALLOWED_2_MIN) && (value <= MV810_PNET02_SETTINGS_ALLOWED_2_MAX);",
            ),
        ] {
            let text = include_str!("../../descriptions/mv810-pnet02.toml").replace(
                "\n[profinet]\n",
                &format!(
                    "\n[[settings]]\nname = {{ en = \"Timeout\", zh = \"超时\" }}\n\
                     range = {range}\ndefault = 100\n\n[profinet]\n"
                ),
            );
            let header = emit(&load("mv810-pnet02.toml", &text));
            assert!(header.contains(check), "{range}: {header}");
        }
    }

    /// A reference is the name it stands for: a macro, the prefix of a
    /// part's or a set's macros, a support function of the PKW codec.
    #[test]
    fn references_are_the_names_they_stand_for() {
        let names = Names {
            p: "X".into(),
            l: "x".into(),
            pkw: Some("gsdc_pke"),
        };
        let ident = |snake: &str| Ident::of(&snake.split('_').collect::<Vec<_>>());
        let cases = [
            (
                Ref::Const(layout::Scope::Gateway, ident("first_node")),
                "X_FIRST_NODE",
            ),
            (
                Ref::Const(layout::Scope::part("diagnosis"), ident("len")),
                "X_DIAGNOSIS_LEN",
            ),
            (
                Ref::Part(layout::Scope::part("control_word")),
                "X_CONTROL_WORD_*",
            ),
            (
                Ref::Values(
                    layout::Scope::GatewayDiagnosis,
                    ident("parameter_error_code"),
                ),
                "X_DIAG_PARAMETER_ERROR_CODE_*",
            ),
            (Ref::Pkw(PkwItem::RequestDecode), "gsdc_pke_request_decode"),
            (Ref::Pkw(PkwItem::Response), "gsdc_pke_response_t"),
        ];
        for (to, name) in cases {
            assert_eq!(names.reference(&to), name);
        }
    }

    #[test]
    fn an_ending_goes_before_the_full_stop() {
        assert_eq!(
            with_ending("The block.", ", an initializer"),
            "The block, an initializer."
        );
        assert_eq!(with_ending("No stop", "!"), "No stop!");
    }

    #[test]
    fn numbers_and_texts_as_c_writes_them() {
        assert_eq!(lit(&Val::hex_u32(0x0000_0202)), "0x00000202UL");
        assert_eq!(lit(&Val::hex_u16(0x0A10)), "0x0A10U");
        assert_eq!(lit(&Val::Dec(12)), "12U");
        assert_eq!(lit(&Val::Text("a?".into())), "\"a\\?\"");
    }
}
