//! A draft cannot pass for a release: while a description has a
//! placeholder (an ident number PI has not assigned), what an engineering
//! tool shows of the device begins with a notice naming it: the GSD's
//! Info_Text (STEP 7's and TIA Portal's catalog, read here by an
//! independent parser), the GSDML DAP's InfoText (TIA Portal's catalog,
//! in every language) and the datasheet's title. A shipping build
//! (`--deny-warnings`) carries none.

use crate::support::{self, descriptions};
use gsdc::ArtifactKind;

/// The GSD's Info_Text as a configuration tool reads it: its continuation
/// lines joined (gsd-parser, the independent reader, does not keep it, so
/// gsdc's reader, which `gsdc check` uses on vendors' files).
fn gsd_info_text(ir: &gsdc::Ir) -> Option<String> {
    let gsd = descriptions::output_text(ir, ArtifactKind::Gsd);
    let (file, diagnostics) = gsdc::gsd::parse(&gsd);
    assert!(!diagnostics.has_errors(), "{diagnostics:?}");
    assert!(
        gsdc::gsd::check_strict(&gsd).is_empty(),
        "the strict rules hold"
    );
    file.get("Info_Text")
        .and_then(|s| s.value.as_str())
        .map(str::to_string)
}

/// The DAP's InfoText in each language of the GSDML, as TIA Portal shows
/// it: the DAP's ModuleInfo names a TextId, each language gives its text.
fn dap_info_texts(ir: &gsdc::Ir) -> Vec<(String, String)> {
    let gsdml = descriptions::output_text(ir, ArtifactKind::Gsdml);
    let doc = roxmltree::Document::parse(&gsdml).unwrap();
    let dap = doc
        .descendants()
        .find(|n| n.has_tag_name("DeviceAccessPointItem"))
        .unwrap();
    let id = dap
        .children()
        .find(|n| n.has_tag_name("ModuleInfo"))
        .and_then(|m| m.children().find(|n| n.has_tag_name("InfoText")))
        .and_then(|t| t.attribute("TextId"))
        .unwrap();
    doc.descendants()
        .filter(|n| n.has_tag_name("PrimaryLanguage") || n.has_tag_name("Language"))
        .map(|language| {
            let code = language
                .attribute(("http://www.w3.org/XML/1998/namespace", "lang"))
                .unwrap_or("en");
            let text = language
                .children()
                .find(|t| t.attribute("TextId") == Some(id))
                .and_then(|t| t.attribute("Value"))
                .unwrap();
            (code.to_string(), text.to_string())
        })
        .collect()
}

fn datasheet_title(ir: &gsdc::Ir) -> String {
    let (_, html) = descriptions::one(gsdc::document(ir), ArtifactKind::DatasheetHtml);
    let start = html.find("<title>").unwrap() + "<title>".len();
    html[start..start + html[start..].find("</title>").unwrap()].to_string()
}

#[test]
fn a_description_with_placeholders_says_it_is_a_draft_where_the_tools_show_it() {
    let md810 = descriptions::load("md810dp.toml");
    let info = gsd_info_text(&md810).unwrap();
    assert!(
        info.starts_with(
            "DRAFT, not for release: Ident_Number 0x0810 is a placeholder, not assigned by PI. MD810 standard DP interface"
        ),
        "{info}"
    );
    assert!(info.len() <= 256 && info.is_ascii() && !info.contains('"'));
    let dap = dap_info_texts(&md810);
    assert_eq!(dap.len(), 2, "English and Chinese");
    for (code, text) in &dap {
        let notice = match code.as_str() {
            "zh" => "草稿，不得发布：VendorID 0x0A11、DeviceID 0x0810 为占位值，非 PI 分配。",
            _ => "DRAFT, not for release: VendorID 0x0A11 and DeviceID 0x0810 are placeholders, not assigned by PI. ",
        };
        assert!(text.starts_with(notice), "{code}: {text}");
    }
    assert!(datasheet_title(&md810).starts_with(
        "DRAFT, not for release (placeholders: Ident_Number 0x0810, DeviceID 0x0810, VendorID 0x0A11): Inovance MD810DP"
    ));
    // MV810: its GSDML has the manual's own file name; TIA Portal's catalog
    // says it is not the vendor's.
    let mv810 = descriptions::load("mv810-pnet02.toml");
    for (code, text) in dap_info_texts(&mv810) {
        assert!(
            text.starts_with("DRAFT") || text.starts_with("草稿"),
            "{code}: {text}"
        );
    }
    let gsd_only = descriptions::load("9kdp1.toml");
    assert!(gsd_info_text(&gsd_only)
        .unwrap()
        .starts_with("DRAFT, not for release: Ident_Number 0x9D01"));
}

/// With every ident number assigned, the texts are the description's.
#[test]
fn assigned_numbers_leave_no_notice() {
    let text = descriptions::shipped_text("md810dp.toml")
        .replace("placeholder = true", "placeholder = false");
    let ir = descriptions::load_text("md810dp.toml", &text).0.unwrap();
    let info = gsd_info_text(&ir).unwrap();
    assert!(info.starts_with("MD810 standard DP interface"), "{info}");
    for (code, text) in dap_info_texts(&ir) {
        assert!(
            !text.starts_with("DRAFT") && !text.starts_with("草稿"),
            "{code}: {text}"
        );
    }
    assert!(datasheet_title(&ir).starts_with("Inovance MD810DP"));
}

/// A shipping build refuses placeholders, so none of its files has the
/// notice; a build of a description with placeholders is refused.
#[test]
fn a_shipping_build_carries_no_notice() {
    let out = support::scratch("draft-notice-shipping");
    let fixture = support::checkout("tests/fixtures/valid/no_warnings.toml");
    let (fixture, dir) = (fixture.to_str().unwrap(), out.to_str().unwrap());
    let built = support::gsdc(["build", fixture, "--out", dir, "--deny-warnings"]);
    assert_eq!(built.status.code(), Some(0), "{}", support::stderr(&built));
    let documented = support::gsdc(["doc", fixture, "--out", dir]);
    assert_eq!(documented.status.code(), Some(0));
    let names = support::file_names(&out);
    assert!(names.iter().any(|n| n.ends_with(".GSD")) && names.iter().any(|n| n.ends_with(".xml")));
    for name in names {
        let text = String::from_utf8_lossy(&std::fs::read(out.join(&name)).unwrap()).into_owned();
        assert!(!text.contains("DRAFT") && !text.contains("草稿"), "{name}");
    }
    let refused = support::gsdc([
        "build",
        "descriptions/md810dp.toml",
        "--out",
        out.join("md810").to_str().unwrap(),
        "--deny-warnings",
    ]);
    assert_eq!(refused.status.code(), Some(1));
}
