//! The PI GSDML schema V2.44: validation through gsdc's `xsd` feature
//! (libxml2), and a stand-in schema that refuses every GSDML.
//!
//! The schema is read from `GSDC_GSDML_XSD_DIR`, by default
//! `../shared/reference/gsdml-xsd-v2.44` next to the checkout; it is never
//! copied into the project. A missing schema fails the test that needs it:
//! a schema test that silently skips proves nothing.

use gsdc::xsd::Schema;
use std::cell::RefCell;
use std::path::{Path, PathBuf};

/// The directory of the PI schema.
pub fn pi_schema() -> PathBuf {
    std::env::var_os("GSDC_GSDML_XSD_DIR")
        .map_or_else(|| super::shared("reference/gsdml-xsd-v2.44"), PathBuf::from)
}

thread_local! {
    /// libxml2's contexts stay on the thread that made them: one per test thread.
    static SCHEMA: RefCell<Schema> = RefCell::new(load());
}

fn load() -> Schema {
    Schema::load(&pi_schema()).unwrap_or_else(|why| panic!("{why} (set GSDC_GSDML_XSD_DIR)"))
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

/// A stand-in for the PI schema that every GSDML breaks: its
/// `ISO15745Profile` may hold nothing. What a build does with a GSDML the
/// PI schema rejects is tested with it, as gsdc writes no such GSDML.
/// Written into `dir/refusing-xsd`; returns that directory.
pub fn refusing_schema(dir: &Path) -> PathBuf {
    let schema = dir.join("refusing-xsd");
    std::fs::create_dir_all(&schema).unwrap();
    std::fs::write(
        schema.join(gsdc::xsd::SCHEMA_FILE),
        format!(
            r#"<?xml version="1.0"?>
<xs:schema xmlns:xs="http://www.w3.org/2001/XMLSchema" targetNamespace="{}" elementFormDefault="qualified">
  <xs:element name="ISO15745Profile"><xs:complexType/></xs:element>
</xs:schema>
"#,
            gsdc::gsdml::NAMESPACE
        ),
    )
    .unwrap();
    schema
}
