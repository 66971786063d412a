//! Device access points after the first (`[[profinet.daps]]`): what each
//! states, what it takes from the first, and what the rules refuse, each at
//! its line and column. The fixture own_idents.toml has three; its GSDML,
//! layouts and datasheet are reviewed snapshots (tests/outputs.rs), its
//! GSDML is validated against PI's schema (tests/xsd.rs) and imported back
//! (tests/import.rs).

use crate::support::descriptions;

const FIXTURES: &str = "tests/fixtures/valid";
const NAME: &str = "own_idents.toml";

fn text() -> String {
    std::fs::read_to_string(crate::support::checkout(&format!("{FIXTURES}/{NAME}"))).unwrap()
}

/// The fixture with its `[[profinet.daps]]` replaced by `daps`.
fn with_daps(daps: &str) -> String {
    let text = text();
    let start = text.find("[[profinet.daps]]").unwrap();
    format!("{}{daps}", &text[..start])
}

/// The PROFINET part of the description `text`; a panic with the
/// diagnostics when it does not load.
fn profinet(text: &str) -> gsdc::ir::Profinet {
    let (ir, diagnostics) = descriptions::load_text(NAME, text);
    let ir = ir.unwrap_or_else(|| panic!("{diagnostics:?}"));
    ir.profinet.expect("a PROFINET part")
}

fn errors(text: &str) -> Vec<(&'static str, usize, usize)> {
    descriptions::error_places(NAME, text)
}

/// The fixture with `daps` is refused with `code` alone, at the last
/// `needle`.
fn assert_refused_at(daps: &str, needle: &str, code: &str) {
    let text = with_daps(daps);
    let at = place(&text, needle);
    assert_eq!(errors(&text), [(code, at.0, at.1)], "{daps}");
}

/// Line and column of the last `needle` in `text`.
fn place(text: &str, needle: &str) -> (usize, usize) {
    gsdc::line_col(text, text.rfind(needle).unwrap())
}

#[test]
fn a_later_dap_states_what_differs_and_takes_the_rest_from_the_first() {
    let ir = descriptions::load_from(FIXTURES, NAME);
    let p = ir.profinet.as_ref().unwrap();
    let [first, one_port, third, fourth] = p.daps.as_slice() else {
        panic!("four device access points: {:?}", p.daps.len());
    };
    assert_eq!(
        (first.id.as_str(), first.ident, first.submodule_ident),
        ("IDD_DAP", 0x100, 0x101)
    );
    assert_eq!(first.modules, [0, 1]);
    // Stated: ident, name, order number, hardware release, one port, no
    // MRP. Taken from the first: software release, info text, the port's
    // ident number, every module; its submodule is numbered as it is.
    assert_eq!(
        (
            one_port.id.as_str(),
            one_port.ident,
            one_port.submodule_ident
        ),
        ("IDD_DAP_2", 0x200, 0x200)
    );
    assert_eq!(one_port.order_number.as_deref(), Some("X4-PN-1P"));
    assert_eq!(
        (
            one_port.hardware_release.as_deref(),
            one_port.software_release.as_deref()
        ),
        (Some("V2"), Some("V1"))
    );
    assert_eq!(one_port.info, first.info);
    assert_eq!(one_port.ports.len(), 1);
    assert_eq!(one_port.ports[0].ident, first.ports[0].ident);
    assert!(!one_port.media_redundancy && !one_port.ports[0].default_ringport);
    assert_eq!(one_port.modules, first.modules);
    // A port less is its IOPS and IOCS less in each CR.
    assert_eq!(one_port.max_input_length + 1, first.max_input_length);
    // The third offers standard telegram 1 alone, with its own submodule
    // number and info text, and the first's MRP on two ports.
    assert_eq!((third.ident, third.submodule_ident), (0x300, 0x301));
    assert_eq!(third.order_number, None);
    // The fixture has no hardware release: the first and the third have
    // none; the third states its software release.
    assert_eq!(
        (
            first.hardware_release.as_deref(),
            third.hardware_release.as_deref(),
            third.software_release.as_deref()
        ),
        (None, None, Some("V3"))
    );
    assert_ne!(third.info.id, first.info.id);
    let names: Vec<String> = third
        .modules
        .iter()
        .map(|&i| p.modules[i].ident.snake())
        .collect();
    assert_eq!(names, ["telegram1"]);
    assert!(third.media_redundancy && third.ports.iter().all(|port| port.default_ringport));
    // The fourth is the third's ident number and slot 0, offering PZD1
    // alone.
    assert_eq!(
        (fourth.ident, fourth.submodule_ident, fourth.ports.len()),
        (0x300, 0x301, 2)
    );
    assert_eq!(fourth.modules, [1]);
}

#[test]
fn a_dap_sharing_a_modules_ident_number_is_refused_at_it() {
    let shared = "[[profinet.daps]]\nname = \"V2\"\nident = 0x00001001\n";
    assert_refused_at(shared, "0x00001001", "E176");
}

/// Device access points of one ident number are one slot 0 to the
/// controller: their own submodules and ports must be alike.
#[test]
fn daps_of_one_ident_number_present_one_slot_zero() {
    let alike = "[[profinet.daps]]\nname = \"V2\"\nident = 0x200\n\n[[profinet.daps]]\nname = \"V3\"\nident = 0x200\nmodules = [\"pzd1\"]\n";
    let daps = &profinet(&with_daps(alike)).daps;
    assert_eq!((daps[1].ident, daps[2].ident), (0x200, 0x200));
    // The first's ident number, with its own submodule's other number.
    let first = "[[profinet.daps]]\nname = \"V2\"\nident = 0x100\n";
    assert_refused_at(first, "0x100", "E162");
    for other in [
        "ports = 1\nmedia_redundancy = false\n",
        "submodule_ident = 0x201\n",
        "port_idents = [1, 2]\n",
    ] {
        let daps = format!("{alike}{other}");
        assert_refused_at(&daps, "0x200", "E162");
    }
}

/// Device access points of one ident number give each record index
/// alike: the device reads a record the controller of any of them writes.
#[test]
fn daps_of_one_ident_number_give_each_record_alike() {
    let text = text();
    let fourth = text.rfind("index = 8200").unwrap();
    let other = format!(
        "{}{}",
        &text[..fourth],
        text[fourth..].replacen("default = 2", "default = 3", 1)
    );
    assert_ne!(other, text);
    let at = place(&other, "0x00000300");
    assert_eq!(errors(&other), [("E162", at.0, at.1)]);
    // Its own record of another index is its own.
    let p = profinet(&text);
    let (own, ports) = p.own_records(&p.daps[3]);
    let indexes: Vec<u16> = own.iter().map(|r| r.index).collect();
    assert_eq!(indexes, [8200, 8201]);
    assert_eq!(ports, p.own_records(&p.daps[0]).1);
    assert!(p.own_records(&p.daps[1]).1.is_empty());
}

/// `[profinet] dap_modules`: the modules the first offers.
#[test]
fn the_first_dap_may_offer_some_modules() {
    let text = text().replacen(
        "[profinet]\n",
        "[profinet]\ndap_modules = [\"telegram1\"]\n",
        1,
    );
    let p = profinet(&text);
    assert_eq!(p.daps[0].modules, [0]);
    // The second offers every module still.
    assert_eq!(p.daps[1].modules, [0, 1]);
    let none = text.replacen("dap_modules = [\"telegram1\"]", "dap_modules = []", 1);
    let key = "dap_modules = ";
    let at = gsdc::line_col(&none, none.find(key).unwrap() + key.len());
    assert_eq!(errors(&none), [("E183", at.0, at.1)]);
}

/// The first DAP's ports have ident numbers of their own: a third port's
/// is not guessed.
#[test]
fn more_ports_than_the_first_need_their_ident_numbers() {
    let three = "[[profinet.daps]]\nname = \"V2\"\nident = 0x200\nports = 3\n";
    assert_refused_at(three, "3\n", "E178");
    // A third port needs its label and name too (E191).
    let stated = descriptions::own_idents_port_texts(
        &with_daps(
            "[[profinet.daps]]\nname = \"V2\"\nident = 0x200\nports = 3\nport_idents = [1, 2, 3]\n",
        ),
        3,
    );
    let idents: Vec<u32> = profinet(&stated).daps[1]
        .ports
        .iter()
        .map(|p| p.ident)
        .collect();
    assert_eq!(idents, [1, 2, 3]);
    // Labels for the three ports and names for two: E191 at the names.
    let third_name = ", \"Port 3 - RJ45 (X1 P3)\"]";
    let two_names = stated.replacen(third_name, "]", 1);
    assert_ne!(two_names, stated);
    let at = place(&two_names, "[\"Port 1 - RJ45");
    assert_eq!(errors(&two_names), [("E191", at.0, at.1)]);
    let short = "[[profinet.daps]]\nname = \"V2\"\nident = 0x200\nport_idents = [1]\n";
    assert_refused_at(short, "[1]", "E178");
}

/// Stated, or the first's taken over on one port.
#[test]
fn a_dap_with_mrp_on_one_port_is_refused() {
    let stated =
        "[[profinet.daps]]\nname = \"V2\"\nident = 0x200\nports = 1\nmedia_redundancy = true\n";
    assert_refused_at(stated, "true", "E152");
    let inherited = "[[profinet.daps]]\nname = \"V2\"\nident = 0x200\nports = 1\n";
    assert_refused_at(inherited, "1\n", "E152");
}

#[test]
fn a_dap_names_each_module_once() {
    let twice = "[[profinet.daps]]\nname = \"V2\"\nident = 0x200\nmodules = [\"pzd1\", \"pzd1\"]\n";
    assert_refused_at(twice, "\"pzd1\"", "E183");
    let none = "[[profinet.daps]]\nname = \"V2\"\nident = 0x200\nmodules = []\n";
    assert_refused_at(none, "[]", "E183");
}

/// A DAP that does not lower does not shift the names and places of the
/// ones after it.
#[test]
fn a_shared_ident_is_reported_at_its_own_entry_after_a_refused_one() {
    let text = with_daps("[[profinet.daps]]\nname = \"V2\"\nident = 0x200\nports = 0\n\n[[profinet.daps]]\nname = \"V3\"\nident = 0x00001001\n");
    let (ir, diagnostics) = descriptions::load_text(NAME, &text);
    assert!(ir.is_none());
    let shared = diagnostics
        .errors()
        .find(|d| d.code == "E176")
        .expect("E176");
    assert_eq!(
        gsdc::line_col(&text, shared.span.clone().unwrap().start),
        place(&text, "0x00001001")
    );
    assert!(
        shared
            .message
            .starts_with("device access point 3 (profinet.daps[1]) and module `pzd1`"),
        "{}",
        shared.message
    );
}

/// While an identity is a placeholder, a later DAP's own info text says
/// so, as the first's does: the catalog shows each.
#[test]
fn a_later_daps_own_info_carries_the_draft_notice() {
    let text = text().replace(
        "vendor_id = { value = 0x1234 }",
        "vendor_id = { value = 0x1234, placeholder = true }",
    );
    let p = profinet(&text);
    let own = &p.daps[2].info.text.en;
    assert!(
        own.contains("VendorID 0x1234") && own.ends_with("standard telegram 1 alone."),
        "{own}"
    );
    assert!(p.daps[0].info.text.en.contains("VendorID 0x1234"));
}

/// A GSDML device access point may have no releases (SEW's MOVI-C has
/// none), so a description without `[profibus]` may leave out the revision
/// and the releases: the first DAP then writes neither `HardwareRelease` nor
/// `SoftwareRelease`, a later one only what it states, and every file
/// builds and passes gsdc's own checks. (With `[profibus]` they are E004:
/// tests/fixtures/invalid/gsd_without_revision.toml.)
#[test]
fn a_description_without_a_gsd_may_leave_the_releases_out() {
    // Nor do its modules repeat a release then (E192).
    let text = text()
        .replace("revision = \"V1\"\nsoftware_release = \"V1\"\n", "")
        .replace("module_releases = true\n", "");
    assert_ne!(text, self::text());
    let (ir, diagnostics) = descriptions::load_text(NAME, &text);
    let ir = ir.unwrap_or_else(|| panic!("{diagnostics:#?}"));
    assert_eq!(ir.device.revision, None);
    let releases: Vec<(Option<&str>, Option<&str>)> = ir
        .profinet
        .as_ref()
        .unwrap()
        .daps
        .iter()
        .map(|d| (d.hardware_release.as_deref(), d.software_release.as_deref()))
        .collect();
    assert_eq!(
        releases,
        [
            (None, None),
            (Some("V2"), None),
            (None, Some("V3")),
            (None, Some("V3.1"))
        ]
    );
    let files = gsdc::compile(&ir).unwrap_or_else(|e| panic!("{e:#?}"));
    let (_, gsdml) = descriptions::one(files, gsdc::ArtifactKind::Gsdml);
    assert_eq!(
        gsdml.matches("<HardwareRelease Value=\"V2\"/>").count(),
        1,
        "{gsdml}"
    );
    assert_eq!(gsdml.matches("<SoftwareRelease Value=\"V3\"/>").count(), 1);
    assert_eq!(
        gsdml.matches("<SoftwareRelease Value=\"V3.1\"/>").count(),
        1
    );
    assert_eq!(gsdml.matches("Release Value=").count(), 3);
}
