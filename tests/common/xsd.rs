//! Validation against the PI GSDML schema V2.44, through gsdc's `xsd`
//! feature (libxml2).
//!
//! The schema is read from `GSDC_GSDML_XSD_DIR`, by default
//! `../shared/reference/gsdml-xsd-v2.44` next to the crate; it is never
//! copied into the project. A missing schema fails the test that needs it:
//! a schema test that silently skips proves nothing.

use gsdc::xsd::Schema;
use std::cell::RefCell;
use std::path::PathBuf;

thread_local! {
    /// libxml2's contexts stay on the thread that made them: one per test thread.
    static SCHEMA: RefCell<Schema> = RefCell::new(load());
}

fn load() -> Schema {
    let dir = std::env::var_os("GSDC_GSDML_XSD_DIR").map_or_else(
        || {
            PathBuf::from(concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/../shared/reference/gsdml-xsd-v2.44"
            ))
        },
        PathBuf::from,
    );
    Schema::load(&dir).unwrap_or_else(|why| panic!("{why} (set GSDC_GSDML_XSD_DIR)"))
}

/// Validates a GSDML document against the V2.44 schema. The errors are
/// libxml2's messages prefixed with their line.
pub fn validate(xml: &str) -> Result<(), Vec<String>> {
    let diagnostics = SCHEMA.with(|schema| schema.borrow_mut().validate(xml));
    if diagnostics.is_empty() {
        return Ok(());
    }
    Err(diagnostics
        .iter()
        .map(|d| {
            let line = d
                .span
                .as_ref()
                .map_or(0, |s| gsdc::line_col(xml, s.start).0);
            format!("line {line}: {}", d.message)
        })
        .collect())
}
