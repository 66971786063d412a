//! Validation against the PI GSDML schema with libxml2 (cargo feature `xsd`).
//!
//! The schema is the user's: gsdc never ships it. [`Schema::load`] compiles
//! `GSDML-DeviceProfile-v2.44.xsd` (and what it imports) from a directory
//! once; [`Schema::validate`] turns libxml2's findings into diagnostics with
//! code E399 on the line libxml2 names. Without the feature, [`Schema`]
//! has no value and [`Schema::load`] says how to get it.
//!
//! libxml2's contexts are not thread-safe: a `Schema` is neither `Send` nor
//! `Sync`, so it stays on the thread that loaded it.

/// The root schema file in a PI GSDML schema directory.
pub const SCHEMA_FILE: &str = "GSDML-DeviceProfile-v2.44.xsd";

#[cfg(feature = "xsd")]
pub use libxml2::Schema;
#[cfg(not(feature = "xsd"))]
pub use without_libxml2::Schema;

#[cfg(not(feature = "xsd"))]
mod without_libxml2 {
    use crate::diag::Diagnostics;
    use std::path::Path;

    /// A schema, which this gsdc (built without the `xsd` feature) cannot load.
    pub enum Schema {}

    impl Schema {
        pub fn load(_: &Path) -> Result<Schema, String> {
            Err("this gsdc was built without the `xsd` feature: build it with `--features xsd` (needs libxml2)".into())
        }

        pub fn validate(&mut self, _: &str) -> Diagnostics {
            match *self {}
        }
    }
}

#[cfg(feature = "xsd")]
mod libxml2 {
    use super::SCHEMA_FILE;
    use crate::diag::{Diagnostic, Diagnostics};
    use libxml::error::StructuredError;
    use libxml::parser::{Parser, ParserOptions};
    use libxml::schemas::{SchemaParserContext, SchemaValidationContext};
    use std::path::Path;

    pub struct Schema {
        context: SchemaValidationContext,
    }

    impl Schema {
        /// Compiles the schema in `dir`, or says why it cannot.
        pub fn load(dir: &Path) -> Result<Schema, String> {
            let path = dir.join(SCHEMA_FILE);
            if !path.is_file() {
                return Err(format!(
                    "{} is missing: give the folder with {SCHEMA_FILE} and the schemas it imports",
                    path.display()
                ));
            }
            let path = path
                .to_str()
                .ok_or_else(|| format!("{} is not a UTF-8 path", path.display()))?;
            let mut parser = SchemaParserContext::from_file(path);
            let context = SchemaValidationContext::from_parser(&mut parser).map_err(|errors| {
                let messages: Vec<&str> = errors.iter().map(message).collect();
                format!(
                    "the schema {path} does not compile: {}",
                    messages.join("; ")
                )
            })?;
            Ok(Schema { context })
        }

        /// Validates a GSDML text (already decoded to UTF-8): the text gsdc
        /// read and checked, never the file again, which could have changed
        /// since, and the findings placed in it. Network access and entity
        /// loading stay off, and a text with a DTD is not handed to libxml2
        /// at all (gsdc's own rules refuse it, E300): no entity is ever
        /// expanded or fetched.
        pub fn validate(&mut self, text: &str) -> Diagnostics {
            if text.contains("<!DOCTYPE") || text.contains("<!ENTITY") {
                return Diagnostics::default();
            }
            let options = ParserOptions {
                encoding: Some("utf-8"),
                no_net: true,
                ..ParserOptions::default()
            };
            let document = match Parser::default().parse_string_with_options(text, options) {
                Ok(document) => document,
                Err(e) => {
                    return Diagnostics(vec![Diagnostic::error(
                        "E399",
                        format!("libxml2 cannot read the file: {e:?}"),
                    )
                    .help("the file must be well-formed XML")])
                }
            };
            match self.context.validate_document(&document) {
                Ok(()) => Diagnostics::default(),
                Err(errors) => schema_errors(text, &errors),
            }
        }
    }

    fn schema_errors(text: &str, errors: &[StructuredError]) -> Diagnostics {
        let lines = LineStarts::of(text);
        Diagnostics(errors.iter().map(|e| schema_error(&lines, e)).collect())
    }

    fn schema_error(lines: &LineStarts, error: &StructuredError) -> Diagnostic {
        let span = error
            .line
            .and_then(|line| usize::try_from(line).ok())
            .and_then(|line| lines.span(line));
        Diagnostic::error("E399", message(error).to_string())
            .at_opt(span)
            .label("not valid against the PI schema")
            .help("the PI GSDML schema V2.44 rejects this; see its documentation of the element")
    }

    /// Where each line starts, found once per file: a file the schema rejects
    /// may have hundreds of findings.
    struct LineStarts<'a> {
        text: &'a str,
        starts: Vec<usize>,
    }

    impl<'a> LineStarts<'a> {
        fn of(text: &'a str) -> Self {
            let starts = std::iter::once(0)
                .chain(text.match_indices('\n').map(|(i, _)| i + 1))
                .collect();
            LineStarts { text, starts }
        }

        /// The byte range of 1-based line `line`, without its line end.
        fn span(&self, line: usize) -> Option<std::ops::Range<usize>> {
            let start = *self.starts.get(line.checked_sub(1)?)?;
            let end = self
                .starts
                .get(line)
                .map_or(self.text.len(), |next| next - 1);
            Some(start..end.max(start))
        }
    }

    fn message(error: &StructuredError) -> &str {
        error
            .message
            .as_deref()
            .unwrap_or("(no message)")
            .trim_end()
    }

    #[cfg(test)]
    mod tests {
        use super::LineStarts;

        #[test]
        fn line_spans_cover_one_line() {
            let lines = LineStarts::of("a\nbc\r\nd");
            assert_eq!(lines.span(1), Some(0..1));
            assert_eq!(lines.span(2), Some(2..5));
            assert_eq!(lines.span(3), Some(6..7));
            assert_eq!(lines.span(4), None);
            assert_eq!(lines.span(0), None);
        }
    }
}
