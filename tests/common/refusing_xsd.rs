//! A stand-in for the PI schema that every GSDML breaks: its
//! `ISO15745Profile` may hold nothing. What a build does with a GSDML the
//! PI schema rejects is tested with it, as gsdc writes no such GSDML.

use std::path::{Path, PathBuf};

/// Writes the schema into `dir/refusing-xsd` and returns that directory.
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
