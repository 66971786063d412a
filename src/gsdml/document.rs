//! What makes a file a GSDML file of a given version: the root element
//! (E301), the schema version of `xsi:schemaLocation` (E302), the ISO 15745
//! profile header (E303) and the file name (E304, E305).

use roxmltree::Document;

use super::index::{child, in_gsdml, tag_span, value_span, El};
use super::version::{from_schema_location, parse_file_name, Version};
use super::NAMESPACE;
use crate::diag::Diagnostic;

const XSI: &str = "http://www.w3.org/2001/XMLSchema-instance";

/// Checks the document level. Returns the schema version the rules apply,
/// or `None` when the file is not GSDML at all.
pub fn check(
    doc: &Document<'_>,
    file_name: Option<&str>,
    out: &mut Vec<Diagnostic>,
) -> Option<Version> {
    let root = doc.root_element();
    if !(in_gsdml(&root) && root.tag_name().name() == "ISO15745Profile") {
        out.push(not_gsdml(&root));
        return None;
    }
    let declared = schema_version(&root, out);
    profile_header(&root, out);
    if let Some(name) = file_name {
        check_file_name(name, declared, &root, out);
    }
    Some(declared.unwrap_or(Version::LATEST))
}

fn not_gsdml(root: &El<'_, '_>) -> Diagnostic {
    let found = match root.tag_name().namespace() {
        Some(ns) => format!("<{}> in namespace \"{ns}\"", root.tag_name().name()),
        None => format!("<{}> without a namespace", root.tag_name().name()),
    };
    Diagnostic::error(
        "E301",
        format!("not a GSDML file: the root element is {found}"),
    )
    .at(tag_span(root))
    .label("expected ISO15745Profile")
    .help(format!(
        "a GSDML file starts with <ISO15745Profile xmlns=\"{NAMESPACE}\" ...>"
    ))
}

fn schema_version(root: &El<'_, '_>, out: &mut Vec<Diagnostic>) -> Option<Version> {
    let location = root.attribute((XSI, "schemaLocation"));
    let version = location.and_then(from_schema_location);
    if version.is_none() {
        let what = if location.is_some() {
            "xsi:schemaLocation does not name a GSDML-DeviceProfile-V<x.yy>.xsd schema"
        } else {
            "the root element has no xsi:schemaLocation"
        };
        let span = value_span(root, (XSI, "schemaLocation"));
        out.push(
            Diagnostic::error(
                "E302",
                format!("cannot tell the GSDML schema version: {what}"),
            )
            .at(span)
            .label("schema version unknown")
            .help(format!(
                "write xsi:schemaLocation=\"{NAMESPACE} ..\\xsd\\GSDML-DeviceProfile-V2.32.xsd\"; \
                     until then the file is checked against {}",
                Version::LATEST
            )),
        );
    }
    version
}

/// The ISO 15745 header is fixed text ("Please do not change the content",
/// as PI's template says); tools identify GSDML files by it.
const HEADER: &[(&[&str], &str)] = &[
    (&["ProfileIdentification"], "PROFINET Device Profile"),
    (&["ProfileClassID"], "Device"),
    (&["ISO15745Reference", "ISO15745Part"], "4"),
    (&["ISO15745Reference", "ProfileTechnology"], "GSDML"),
];

fn profile_header(root: &El<'_, '_>, out: &mut Vec<Diagnostic>) {
    let Some(header) = child(*root, "ProfileHeader") else {
        out.push(
            Diagnostic::error("E303", "the ProfileHeader is missing")
                .at(tag_span(root))
                .label("no ProfileHeader in here")
                .help("copy the ProfileHeader of PI's GSDML template; its content is fixed"),
        );
        return;
    };
    for (path, expected) in HEADER {
        let found = path.iter().try_fold(header, |node, name| child(node, name));
        let text = found.map(|n| {
            n.text()
                .unwrap_or("")
                .split_whitespace()
                .collect::<Vec<_>>()
                .join(" ")
        });
        if text.as_deref() == Some(*expected) {
            continue;
        }
        let element = path[path.len() - 1];
        let (message, node) = match (&text, found) {
            (Some(text), Some(node)) => {
                (format!("{element} is \"{text}\", not \"{expected}\""), node)
            }
            _ => (format!("the ProfileHeader lacks {element}"), header),
        };
        out.push(
            Diagnostic::error("E303", message)
                .at(tag_span(&node))
                .label(format!("expected \"{expected}\""))
                .help("the ProfileHeader's content is fixed by the GSDML specification; copy it from PI's template"),
        );
    }
}

fn check_file_name(
    name: &str,
    declared: Option<Version>,
    root: &El<'_, '_>,
    out: &mut Vec<Diagnostic>,
) {
    let parsed = match parse_file_name(name) {
        Ok(parsed) => parsed,
        Err(why) => {
            out.push(
                Diagnostic::error("E304", format!("the file name \"{name}\" breaks the GSDML naming convention: {why}"))
                    .help("name it GSDML-V<x.yy>-<Vendor>-<Family>-<yyyymmdd>[-hhmmss].xml, e.g. GSDML-V2.32-Vendor-Drive-20240101.xml"),
            );
            return;
        }
    };
    let Some(declared) = declared.filter(|v| *v != parsed.version) else {
        return;
    };
    out.push(
        Diagnostic::error(
            "E305",
            format!(
                "the file name says {} but xsi:schemaLocation says {declared}",
                parsed.version
            ),
        )
        .at(value_span(root, (XSI, "schemaLocation")))
        .label(format!("schema {declared}"))
        .help(format!(
            "rename the file to GSDML-{declared}-{}-{}{}.xml or reference the {} schema",
            parsed.vendor_and_family,
            parsed.date,
            parsed.time.map(|t| format!("-{t}")).unwrap_or_default(),
            parsed.version
        )),
    );
}
