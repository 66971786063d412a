//! The check of every C layout before it is written: each name it declares
//! carries the layout's prefix, and none is declared twice, the support
//! header's included. C would flatten two names that Rust keeps apart (a
//! field's mask and a value of the same word) into one.

use super::{prefix, SUPPORT};
use crate::diag::Diagnostic;
use crate::ir::Ir;
use std::collections::BTreeSet;

/// A layout must declare every name with its prefix and no name twice, the
/// support header's included; else an E900 for each name at fault.
pub fn verify(ir: &Ir, file_name: &str, text: &str) -> Vec<Diagnostic> {
    let prefix = prefix(ir);
    let prefixes = [
        format!("{}_", prefix.upper_snake()),
        format!("{}_", prefix.snake()),
    ];
    let mut seen: BTreeSet<String> = declared_names(SUPPORT).into_iter().collect();
    let mut problems = Vec::new();
    for name in declared_names(text) {
        if !prefixes.iter().any(|p| name.starts_with(p.as_str())) {
            problems.push(breaks(
                file_name,
                format!("declaring `{name}` without the prefix {}", prefixes[0]),
            ));
        }
        if !seen.insert(name.clone()) {
            problems.push(breaks(file_name, format!("declaring `{name}` twice")));
        }
    }
    problems
}

fn breaks(file_name: &str, what: String) -> Diagnostic {
    Diagnostic::error(
        "E900",
        format!("gsdc generated {file_name} {what}; nothing was written"),
    )
    .help("this is a bug in gsdc: please report it with the description")
}

/// The names a header declares at file scope: macros, the types of
/// `typedef struct`/`enum` and function pointers, enumerators, functions,
/// and the names of compile-time checks (types in C99).
pub(crate) fn declared_names(text: &str) -> Vec<String> {
    let mut names = Vec::new();
    for line in text.lines() {
        let found = if let Some(rest) = line.strip_prefix("#define ") {
            identifier_at_start(rest)
        } else if let Some(rest) = line.strip_prefix("} ") {
            rest.strip_suffix(';').and_then(identifier_at_start)
        } else if line.starts_with("static inline ") {
            line.split('(')
                .next()
                .and_then(|head| head.rsplit([' ', '*']).next())
        } else if line.starts_with("typedef ") && line.contains("(*") {
            line.split("(*").nth(1).and_then(identifier_at_start)
        } else {
            enumerator(line)
        };
        names.extend(found.map(str::to_string));
    }
    names.extend(check_names(text));
    names
}

/// The last argument of each `GSDC_STATIC_ASSERT(condition, name);`, which
/// may wrap onto the next line.
fn check_names(text: &str) -> Vec<String> {
    text.split("GSDC_STATIC_ASSERT(")
        .skip(1)
        .filter_map(|rest| {
            let call = rest.split(");").next()?;
            let name = call.rsplit(',').next()?.trim();
            identifier_at_start(name).filter(|n| *n == name)
        })
        .map(str::to_string)
        .collect()
}

/// `    GSDC_PRM_OK = 0,`: an enumerator, upper case on a line of its own.
fn enumerator(line: &str) -> Option<&str> {
    let name = identifier_at_start(line.strip_prefix("    ")?)?;
    let rest = &line[4 + name.len()..];
    let upper = name.bytes().all(|b| !b.is_ascii_lowercase());
    (upper && (rest.is_empty() || rest == "," || rest.starts_with(" = "))).then_some(name)
}

fn identifier_at_start(text: &str) -> Option<&str> {
    let end = text
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(text.len());
    (end > 0).then(|| &text[..end])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::emit::c::{emit, file_name};
    use crate::emit::ArtifactKind;

    fn load(name: &str, text: &str) -> Ir {
        crate::testing::load(name, text).0.unwrap()
    }

    #[test]
    fn every_shipped_layout_passes_verification() {
        for (name, text) in [
            (
                "md810dp.toml",
                include_str!("../../../descriptions/md810dp.toml"),
            ),
            (
                "mv810-pnet02.toml",
                include_str!("../../../descriptions/mv810-pnet02.toml"),
            ),
            (
                "9kdp1.toml",
                include_str!("../../../descriptions/9kdp1.toml"),
            ),
            (
                "md810-gateway.toml",
                include_str!("../../../descriptions/md810-gateway.toml"),
            ),
        ] {
            let ir = load(name, text);
            let header = emit(&ir);
            assert_eq!(verify(&ir, &file_name(&ir), &header), [], "{name}");
            assert!(declared_names(&header).len() > 50, "{name}");
        }
    }

    /// The scanner finds each kind of declaration, so verification sees
    /// every name the template writes.
    #[test]
    fn declarations_of_every_kind_are_found() {
        let text = "#define A_X 1U\n\
                    typedef struct {\n    uint8_t bytes[2];\n} a_t;\n\
                    GSDC_STATIC_ASSERT(sizeof(a_t) == 2U, a_size);\n\
                    GSDC_STATIC_ASSERT(1U + 2U ==\n                   3U, a_sum);\n\
                    static inline bool a_is_value(uint16_t value)\n\
                    typedef bool (*a_fn_t)(size_t index, uint16_t value);\n";
        let mut names = declared_names(text);
        names.sort();
        assert_eq!(
            names,
            ["A_X", "a_fn_t", "a_is_value", "a_size", "a_sum", "a_t"]
        );
        let support = declared_names(SUPPORT);
        for name in [
            "GSDC_SUPPORT_H",
            "gsdc_prm_result_t",
            "gsdc_entry_allows_t",
            "gsdc_pke_request_decode",
            "GSDC_PRM_OK",
            "GSDC_PKW_BAD_READ_COUNT",
        ] {
            assert!(support.iter().any(|n| n == name), "{name}");
        }
    }

    /// A status word whose field is named like a value of another field
    /// spells one C macro twice: refused, not written.
    #[test]
    fn a_name_declared_twice_or_without_the_prefix_is_refused() {
        let ir = load(
            "md810dp.toml",
            include_str!("../../../descriptions/md810dp.toml"),
        );
        let header = emit(&ir);
        let twice = header.replace(
            "#define MD810DP_FINGERPRINT",
            "#define MD810DP_PPO1_BYTES 1U\n#define MD810DP_FINGERPRINT",
        );
        let problems = verify(&ir, "md810dp_layout.h", &twice);
        assert_eq!(problems.len(), 1, "{problems:?}");
        assert_eq!(problems[0].code, "E900");
        assert!(problems[0].message.contains("`MD810DP_PPO1_BYTES` twice"));
        let clash = header.replace(
            "#define MD810DP_FINGERPRINT",
            "#define GSDC_PKW_BYTES 8U\n#define MD810DP_FINGERPRINT",
        );
        let messages: Vec<_> = verify(&ir, "md810dp_layout.h", &clash)
            .into_iter()
            .map(|d| d.message)
            .collect();
        assert_eq!(messages.len(), 2, "{messages:?}");
        assert!(messages[0].contains("`GSDC_PKW_BYTES` without the prefix MD810DP_"));
        assert!(messages[1].contains("`GSDC_PKW_BYTES` twice"));
    }

    /// Rust keeps a field's mask and its values apart, a diagnosis area's
    /// bits and its values, a gateway's diagnosis types and their codes; C
    /// does not. A value whose C name meets another takes its number, as in
    /// Rust, and the layout is written: such names used to be E900, a bug in
    /// gsdc, for descriptions the loader accepts.
    #[test]
    fn a_value_whose_c_name_meets_another_takes_its_number() {
        let word = include_str!("../../../descriptions/mv810-pnet02.toml")
            .replace("en = \"Asynchronous\"", "en = \"Mask\"");
        let area = include_str!("../../../descriptions/md810dp.toml").replace(
            "[[profibus.diagnosis.areas]]",
            "[[profibus.diagnosis.areas]]\nbit = [7, 7]\nvalues = [{ value = 1, text = \"Last\" }]\n\n[[profibus.diagnosis.areas]]",
        );
        let gateway = include_str!("../../../descriptions/md810-gateway.toml")
            .replace(
                "en = \"CANopen network fault\"",
                "en = \"Parameter error code node\"",
            )
            .replace(
                "en = \"Node in the configuration not online\"",
                "en = \"Node\"",
            )
            .replace("en = \"Drive reports fault\"", "en = \"Type at\"");
        for (name, text, declared) in [
            (
                "mv810-pnet02.toml",
                word,
                "#define MV810_PNET02_STATUS_WORD_MOTOR_TYPE_MASK_0 0U",
            ),
            (
                "md810dp.toml",
                area,
                "#define MD810DP_DIAGNOSIS_BIT_7_LAST_1 1U",
            ),
            (
                "md810-gateway.toml",
                gateway,
                "#define MD810_GATEWAY_DIAG_PARAMETER_ERROR_CODE_NODE_34 34U",
            ),
        ] {
            let ir = load(name, &text);
            let files = crate::compile(&ir).unwrap_or_else(|e| panic!("{name}: {e:?}"));
            let header = files
                .iter()
                .find(|f| f.kind == ArtifactKind::CHeader)
                .unwrap();
            let header = String::from_utf8_lossy(&header.contents);
            assert!(header.contains(declared), "{name}: {declared}");
        }
    }
}
