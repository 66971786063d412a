//! The PI schema harness: the corpus files that the V2.44 schema accepts
//! (per the corpus MANIFEST.tsv) validate, and the schema rejects each
//! broken corpus file at the place that was broken. This proves the harness
//! that later validates the project's own GSDML.

use crate::support::{self, descriptions, xsd};
use gsdc::gsdml::decode;

fn read(folder: &str, name: &str) -> String {
    let bytes = support::corpus_file(&format!("{folder}/{name}"));
    decode(&bytes)
        .unwrap_or_else(|d| panic!("{name}: {}", d.message))
        .into_owned()
}

/// (file, whether xmllint accepted it against V2.44) from MANIFEST.tsv.
fn manifest() -> Vec<(String, bool)> {
    let text = String::from_utf8(support::corpus_file("gsdml/MANIFEST.tsv")).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines
        .next()
        .expect("MANIFEST.tsv has a header")
        .split('\t')
        .collect();
    let column = |name: &str| {
        header
            .iter()
            .position(|h| *h == name)
            .unwrap_or_else(|| panic!("no column {name}"))
    };
    let (file, verdict) = (column("file"), column("xmllint_v2.44"));
    lines
        .map(|line| line.split('\t').collect::<Vec<_>>())
        .map(|fields| (fields[file].to_string(), fields[verdict] == "valid"))
        .collect()
}

#[test]
fn corpus_validates_as_the_manifest_says() {
    let entries = manifest();
    assert_eq!(entries.len(), 16);
    assert_eq!(
        entries.iter().filter(|(_, valid)| *valid).count(),
        13,
        "V2.33 and later validate"
    );
    for (name, valid) in entries {
        let result = xsd::validate(&read("gsdml", &name));
        if valid {
            assert_eq!(result, Ok(()), "{name} should validate against V2.44");
        } else {
            // Attributes they lack became required after their version.
            let errors = result.expect_err(&name);
            assert!(
                errors.iter().any(|e| e.contains("MayIssueProcessAlarm")),
                "{name}: {errors:?}"
            );
        }
    }
}

/// Each broken file, the line that was broken and a word of the schema's
/// complaint.
const BROKEN: &[(&str, u32, &str)] = &[
    ("neg_bad_datatype.xml", 100, "UInt8"),
    ("neg_bad_identnumber.xml", 26, "'12'"),
    ("neg_dangling_moduleref.xml", 38, "IDM_NOPE"),
    ("neg_dup_module_id.xml", 119, "IDM_30"),
    ("neg_missing_pnio_version.xml", 26, "PNIO_Version"),
    ("neg_missing_textid.xml", 28, "IDT_DOES_NOT_EXIST"),
];

#[test]
fn schema_rejects_each_broken_file_where_it_is_broken() {
    for (name, line, word) in BROKEN {
        let errors = xsd::validate(&read("gsdml-invalid", name)).expect_err(name);
        let expected = format!("line {line}: ");
        assert!(
            errors
                .iter()
                .any(|e| e.starts_with(&expected) && e.contains(word)),
            "{name}: expected an error on line {line} about {word}, got {errors:?}"
        );
    }
}

/// Every GSDML gsdc generates from the shipped descriptions and the valid
/// fixtures (PROFIdrive, MRP, every interface property) validates against
/// the PI schema.
#[test]
fn generated_gsdml_validates_against_the_pi_schema() {
    let mut generated = Vec::new();
    for (_, ir) in descriptions::all_valid() {
        for artifact in gsdc::compile(&ir).unwrap() {
            if artifact.file_name.ends_with(".xml") {
                let xml = String::from_utf8(artifact.contents).unwrap();
                assert_eq!(xsd::validate(&xml), Ok(()), "{}", artifact.file_name);
                generated.push(artifact.file_name);
            }
        }
    }
    assert_eq!(
        generated,
        [
            "GSDML-V2.32-INOVANCE-MD810-20261122.xml",
            "GSDML-V2.32-MEGMEET-MV800-20230830.xml",
            "GSDML-V2.32-Acme-AX200-20261201-071447.xml",
            "GSDML-V2.32-Acme-X3-20260331.xml",
            "GSDML-V2.32-Acme-X1-20260131.xml",
            "GSDML-V2.34-Acme-X4-20260228.xml",
            "GSDML-V2.32-Acme-X2-20260228.xml",
            "GSDML-V2.32-Acme-X5-20260214.xml",
        ],
        "the shipped descriptions md810dp and mv810-pnet02, and the fixtures"
    );
}
