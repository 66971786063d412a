//! Validation against the PI GSDML schema V2.44 with libxml2.
//!
//! The schema is read from `GSDC_GSDML_XSD_DIR`, by default
//! `../shared/reference/gsdml-xsd-v2.44` next to the crate; it is never
//! copied into the project. A missing schema fails the test that needs it:
//! a schema test that silently skips proves nothing.

use std::path::PathBuf;
use std::sync::{Mutex, OnceLock};

use libxml::error::StructuredError;
use libxml::parser::{Parser, ParserOptions};
use libxml::schemas::{SchemaParserContext, SchemaValidationContext};

const SCHEMA_FILE: &str = "GSDML-DeviceProfile-v2.44.xsd";

/// The compiled schema, parsed once per process.
struct Validator(SchemaValidationContext);

// SAFETY: the validation context is only used while `VALIDATOR`'s lock is
// held, so never by two threads at once; libxml2 lets a context be used
// from another thread than the one that created it.
unsafe impl Send for Validator {}

static VALIDATOR: OnceLock<Mutex<Validator>> = OnceLock::new();

fn schema_path() -> PathBuf {
    let dir = std::env::var_os("GSDC_GSDML_XSD_DIR").map_or_else(
        || {
            PathBuf::from(concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/../shared/reference/gsdml-xsd-v2.44"
            ))
        },
        PathBuf::from,
    );
    dir.join(SCHEMA_FILE)
}

fn load() -> Mutex<Validator> {
    let path = schema_path();
    assert!(
        path.is_file(),
        "the GSDML schema {} is missing: set GSDC_GSDML_XSD_DIR to the folder with {SCHEMA_FILE} and the schemas it imports",
        path.display()
    );
    let path = path.to_str().expect("the schema path is not UTF-8");
    let mut parser = SchemaParserContext::from_file(path);
    let context = SchemaValidationContext::from_parser(&mut parser).unwrap_or_else(|errors| {
        let messages: Vec<&str> = errors.iter().map(message).collect();
        panic!("the GSDML schema {path} does not compile: {messages:?}")
    });
    Mutex::new(Validator(context))
}

/// Validates a GSDML document against the V2.44 schema. The errors are
/// libxml2's messages prefixed with their line.
pub fn validate(xml: &str) -> Result<(), Vec<String>> {
    let validator = VALIDATOR.get_or_init(load);
    // A test that panicked while holding the lock leaves the context usable.
    let mut validator = validator
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner());
    // The text is UTF-8 whatever the declaration says (the caller decoded it).
    let options = ParserOptions {
        encoding: Some("utf-8"),
        no_net: true,
        ..ParserOptions::default()
    };
    let document = Parser::default()
        .parse_string_with_options(xml, options)
        .map_err(|e| vec![format!("not well-formed XML: {e:?}")])?;
    validator.0.validate_document(&document).map_err(|errors| {
        errors
            .iter()
            .map(|e| format!("line {}: {}", e.line.unwrap_or(0), message(e)))
            .collect()
    })
}

fn message(error: &StructuredError) -> &str {
    error
        .message
        .as_deref()
        .unwrap_or("(no message)")
        .trim_end()
}
