//! Validation against the PI GSDML schema with libxml2 (cargo feature `xsd`).
//!
//! The schema is the user's: gsdc never ships it. [`Schema::load`] compiles
//! `GSDML-DeviceProfile-v2.44.xsd` (and what it imports) from a directory
//! once; [`Schema::validate`] turns libxml2's findings into diagnostics with
//! code E399 on the line libxml2 names.
//!
//! libxml2's contexts are not thread-safe: a `Schema` is neither `Send` nor
//! `Sync`, so it stays on the thread that loaded it.

use crate::diag::{Diagnostic, Diagnostics};
use libxml::error::StructuredError;
use libxml::parser::{Parser, ParserOptions};
use libxml::schemas::{SchemaParserContext, SchemaValidationContext};
use std::path::Path;

/// The root schema file in a PI GSDML schema directory.
pub const SCHEMA_FILE: &str = "GSDML-DeviceProfile-v2.44.xsd";

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

    /// Validates a GSDML text (already decoded to UTF-8). Network access and
    /// entity loading stay off.
    pub fn validate(&mut self, text: &str) -> Diagnostics {
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
            Err(errors) => Diagnostics(errors.iter().map(|e| schema_error(text, e)).collect()),
        }
    }
}

fn schema_error(text: &str, error: &StructuredError) -> Diagnostic {
    let span = error
        .line
        .and_then(|line| usize::try_from(line).ok())
        .and_then(|line| line_span(text, line));
    Diagnostic::error("E399", message(error).to_string())
        .at_opt(span)
        .label("not valid against the PI schema")
        .help("the PI GSDML schema V2.44 rejects this; see its documentation of the element")
}

/// The byte range of 1-based line `line`, without its line end.
fn line_span(text: &str, line: usize) -> Option<std::ops::Range<usize>> {
    let start = if line <= 1 {
        0
    } else {
        text.match_indices('\n').nth(line - 2)?.0 + 1
    };
    let end = text[start..].find('\n').map_or(text.len(), |i| start + i);
    Some(start..end)
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
    use super::line_span;

    #[test]
    fn line_spans_cover_one_line() {
        let text = "a\nbc\r\nd";
        assert_eq!(line_span(text, 1), Some(0..1));
        assert_eq!(line_span(text, 2), Some(2..5));
        assert_eq!(line_span(text, 3), Some(6..7));
        assert_eq!(line_span(text, 4), None);
    }
}
