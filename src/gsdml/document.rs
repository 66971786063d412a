//! What makes a file a GSDML file of a given version: the root element
//! (E301), the schema version of `xsi:schemaLocation` (W303), the ISO 15745
//! profile header (E303, W304) and the file name (E304, E305).

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
    let location = root.attribute((XSI, "schemaLocation"));
    let declared = location.and_then(from_schema_location);
    let named = file_name.and_then(|name| check_file_name(name, declared, &root, out));
    let version = declared.or(named).unwrap_or(Version::LATEST);
    if declared.is_none() {
        out.push(unknown_version(&root, location.is_some(), version));
    }
    profile_header(&root, out);
    Some(version)
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

/// W303: the file does not say its schema version. The PI schema does not
/// require `xsi:schemaLocation` (a hint to validators, XML Schema part 1,
/// 4.3.2) and nothing a tool configures depends on it, so it is a warning;
/// the rules then apply the version of the file name, else the newest.
fn unknown_version(root: &El<'_, '_>, has_location: bool, applied: Version) -> Diagnostic {
    let what = if has_location {
        "xsi:schemaLocation does not name a GSDML-DeviceProfile-V<x.yy>.xsd schema"
    } else {
        "the root element has no xsi:schemaLocation"
    };
    Diagnostic::warning(
        "W303",
        format!("cannot tell the GSDML schema version: {what}"),
    )
    .at(value_span(root, (XSI, "schemaLocation")))
    .label("schema version unknown")
    .help(format!(
        "write xsi:schemaLocation=\"{NAMESPACE} ..\\xsd\\GSDML-DeviceProfile-V2.32.xsd\"; \
         until then the file is checked against {applied}"
    ))
}

/// The ISO 15745 header is fixed text ("Please do not change the content",
/// as PI's template says). The PI schema requires these elements (E303)
/// but not their text: other text is W304.
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
                .help("the PI schema requires it; copy the ProfileHeader of PI's GSDML template"),
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
        let diagnostic = match (&text, found) {
            (Some(text), Some(node)) => Diagnostic::warning(
                "W304",
                format!("{element} is \"{text}\", not \"{expected}\""),
            )
            .at(tag_span(&node))
            .help("PI's template fixes this text and the schema accepts any; copy it from the template"),
            _ => Diagnostic::error("E303", format!("the ProfileHeader lacks {element}"))
                .at(tag_span(&header))
                .help("the PI schema requires it; copy the ProfileHeader from PI's template"),
        };
        out.push(diagnostic.label(format!("expected \"{expected}\"")));
    }
}

/// E304 and E305; the version the name gives, when it follows the
/// convention.
fn check_file_name(
    name: &str,
    declared: Option<Version>,
    root: &El<'_, '_>,
    out: &mut Vec<Diagnostic>,
) -> Option<Version> {
    let parsed = match parse_file_name(name) {
        Ok(parsed) => parsed,
        Err(why) => {
            out.push(
                Diagnostic::error("E304", format!("the file name \"{name}\" breaks the GSDML naming convention: {why}"))
                    .help("name it GSDML-V<x.yy>-<Vendor>-<Family>-<yyyymmdd>[-hhmmss].xml, e.g. GSDML-V2.32-Vendor-Drive-20240101.xml"),
            );
            return None;
        }
    };
    let named = Some(parsed.version);
    let Some(declared) = declared.filter(|v| *v != parsed.version) else {
        return named;
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
    named
}
