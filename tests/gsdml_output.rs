//! The GSDML files gsdc writes for the shipped descriptions (their
//! snapshots, reviewed against the manuals, are in outputs.rs): the file
//! read back with roxmltree and compared with the IR, and determinism.
//! Validation against PI's schema lives in xsd.rs.

use crate::support::descriptions::{self, load};
use gsdc::ir::profinet::{ModuleKind, ParameterRecord, Profinet};
use gsdc::ir::{Allowed, Ir};
use gsdc::ArtifactKind;
use roxmltree::{Document, Node};
use std::collections::BTreeSet;

/// The shipped descriptions with a PROFINET part, each with its IR.
fn with_profinet() -> Vec<(String, Ir)> {
    let mut found = descriptions::load_shipped();
    found.retain(|(_, ir)| ir.profinet.is_some());
    assert!(!found.is_empty());
    found
}

fn gsdml_of(ir: &Ir) -> (String, &Profinet) {
    let profinet = ir.profinet.as_ref().expect("a PROFINET part");
    let (file_name, gsdml) = descriptions::one(gsdc::compile(ir).unwrap(), ArtifactKind::Gsdml);
    assert_eq!(file_name, profinet.file_name);
    (gsdml, profinet)
}

fn elements<'a, 'i>(
    doc: &'a Document<'i>,
    name: &'a str,
) -> impl Iterator<Item = Node<'a, 'i>> + 'a {
    doc.descendants().filter(move |n| n.has_tag_name(name))
}

fn children<'a, 'i>(node: Node<'a, 'i>, name: &'a str) -> impl Iterator<Item = Node<'a, 'i>> + 'a {
    node.children().filter(move |n| n.has_tag_name(name))
}

fn attribute<'a>(node: Node<'a, '_>, name: &str) -> &'a str {
    node.attribute(name)
        .unwrap_or_else(|| panic!("{} has no {name}", node.tag_name().name()))
}

/// The English text of a TextId.
fn english<'a>(doc: &'a Document, text_id: &str) -> &'a str {
    let primary = elements(doc, "PrimaryLanguage").next().unwrap();
    let text = children(primary, "Text")
        .find(|t| t.attribute("TextId") == Some(text_id))
        .unwrap_or_else(|| panic!("{text_id} is not defined"));
    attribute(text, "Value")
}

#[test]
fn two_builds_give_identical_bytes() {
    for (name, _) in with_profinet() {
        assert_eq!(
            gsdc::compile(&load(&name)).unwrap(),
            gsdc::compile(&load(&name)).unwrap(),
            "{name}"
        );
    }
}

#[test]
fn the_header_names_generator_source_and_fingerprint() {
    let ir = load("mv810-pnet02.toml");
    let (gsdml, _) = gsdml_of(&ir);
    let head: String = gsdml.lines().take(6).collect::<Vec<_>>().join("\n");
    assert!(
        head.starts_with("<?xml version=\"1.0\" encoding=\"utf-8\"?>"),
        "{head}"
    );
    assert!(head.contains(gsdc::GENERATOR), "{head}");
    assert!(head.contains("mv810-pnet02.toml"), "{head}");
    assert!(head.contains(&ir.fingerprint.to_string()), "{head}");
    assert!(
        gsdml.contains("GSDML-DeviceProfile-V2.32.xsd"),
        "the schema location"
    );
}

/// Each module's ident number, and its IO data both ways, are the IR's.
#[test]
fn modules_are_the_irs() {
    for (name, ir) in with_profinet() {
        let (text, profinet) = gsdml_of(&ir);
        let doc = Document::parse(&text).unwrap();
        let modules: Vec<Node> = elements(&doc, "ModuleItem").collect();
        assert_eq!(modules.len(), profinet.modules.len(), "{name}");
        for (node, module) in modules.iter().zip(&profinet.modules) {
            let ident = format!("0x{:08X}", module.ident_number);
            assert_eq!(
                attribute(*node, "ModuleIdentNumber"),
                ident,
                "{name}: {}",
                module.id
            );
            let submodule = node
                .descendants()
                .find(|n| n.has_tag_name("VirtualSubmoduleItem"))
                .unwrap();
            assert_eq!(
                attribute(submodule, "SubmoduleIdentNumber"),
                ident,
                "{name}"
            );
            assert_eq!(attribute(submodule, "API"), "0", "{name}");
            for direction in ["Input", "Output"] {
                let io = submodule
                    .descendants()
                    .find(|n| n.has_tag_name(direction))
                    .unwrap();
                let items: Vec<Node> = children(io, "DataItem").collect();
                assert!(
                    items
                        .iter()
                        .all(|i| attribute(*i, "DataType") == "Unsigned16"),
                    "{name}"
                );
                assert_eq!(
                    2 * items.len(),
                    usize::from(module.layout.bytes()),
                    "{name}: {} {direction}",
                    module.id
                );
            }
        }
        let largest = profinet
            .modules
            .iter()
            .map(|m| m.layout.bytes())
            .max()
            .unwrap();
        let config = elements(&doc, "IOConfigData").next().unwrap();
        for length in ["MaxInputLength", "MaxOutputLength"] {
            let value: u16 = attribute(config, length).parse().unwrap();
            assert!(
                (largest..=1440).contains(&value),
                "{name}: {length} = {value}"
            );
        }
        let useable: Vec<&str> = elements(&doc, "ModuleItemRef")
            .map(|r| attribute(r, "ModuleItemTarget"))
            .collect();
        let ids: Vec<&str> = modules.iter().map(|m| attribute(*m, "ID")).collect();
        assert_eq!(useable, ids, "{name}");
    }
}

/// Every TextId the file refers to is defined in every language, and no
/// language defines one that nothing uses.
#[test]
fn every_text_id_is_defined_in_every_language() {
    for (name, ir) in with_profinet() {
        let (text, _) = gsdml_of(&ir);
        let doc = Document::parse(&text).unwrap();
        let referenced: BTreeSet<&str> = doc
            .descendants()
            .filter(|n| !n.has_tag_name("Text"))
            .filter_map(|n| n.attribute("TextId"))
            .collect();
        let languages: Vec<Node> = elements(&doc, "PrimaryLanguage")
            .chain(elements(&doc, "Language"))
            .collect();
        assert_eq!(languages.len(), 2, "{name}: English and Chinese");
        for language in languages {
            let defined: Vec<&str> = children(language, "Text")
                .map(|t| attribute(t, "TextId"))
                .collect();
            let unique: BTreeSet<&str> = defined.iter().copied().collect();
            assert_eq!(
                unique.len(),
                defined.len(),
                "{name}: a TextId defined twice"
            );
            assert_eq!(
                unique,
                referenced,
                "{name}: {:?}",
                language.attribute(("http://www.w3.org/XML/1998/namespace", "lang"))
            );
        }
    }
}

/// The control word's bits as the MV810 manual (section 3, PZD1) names them.
#[test]
fn mv810_control_word_bits_are_the_manuals() {
    let (text, _) = gsdml_of(&load("mv810-pnet02.toml"));
    let doc = Document::parse(&text).unwrap();
    let module = elements(&doc, "ModuleItem")
        .find(|m| m.attribute("ID") == Some("IDM_PKW_12"))
        .unwrap();
    let output = module
        .descendants()
        .find(|n| n.has_tag_name("Output"))
        .unwrap();
    let control = children(output, "DataItem")
        .find(|d| d.attribute("UseAsBits") == Some("true"))
        .unwrap();
    let bits: Vec<(&str, &str)> = children(control, "BitDataItem")
        .map(|b| {
            (
                attribute(b, "BitOffset"),
                english(&doc, attribute(b, "TextId")),
            )
        })
        .collect();
    let manual = [
        ("0", "Forward running"),
        ("1", "Reverse running"),
        ("2", "Forward JOG"),
        ("3", "Reverse JOG"),
        ("4", "Decelerate to stop"),
        ("5", "Coast to stop"),
        ("6", "Fault reset"),
        ("7", "Emergency stop"),
    ];
    assert_eq!(bits, manual);
    // PKW0..PKW3 come first, then PZD1 is the control word.
    let first_words: Vec<&str> = children(output, "DataItem")
        .take(5)
        .map(|d| english(&doc, attribute(d, "TextId")))
        .collect();
    assert_eq!(
        first_words,
        [
            "Station",
            "Command",
            "Address",
            "Value",
            "Master sends control command word"
        ]
    );
}

/// MV810's manual sets P43.01 to P43.23 at the drive (section 4): its
/// GSDML has no parameter record, so TIA Portal writes nothing at a
/// connection start. Said instead that the master sets them, the same
/// description gives the records: P43.02..P43.12 choose among 15 meanings
/// (0..14), P43.13..P43.23 among 26 (0..25), the Refs pointing to
/// ValueItems with exactly those.
#[test]
fn mv810_mappings_are_set_at_the_drive_and_the_master_writes_no_record() {
    let (gsdml, _) = gsdml_of(&load("mv810-pnet02.toml"));
    let doc = Document::parse(&gsdml).unwrap();
    assert_eq!(elements(&doc, "ParameterRecordDataItem").count(), 0);
    assert_eq!(elements(&doc, "ValueItem").count(), 0);

    let by_master = descriptions::mv810_set_by_master();
    let ir = descriptions::load_text("mv810-pnet02.toml", &by_master)
        .0
        .expect("the master may set them");
    let (gsdml, _) = gsdml_of(&ir);
    let doc = Document::parse(&gsdml).unwrap();
    let values_of_record = |index: &str| -> (usize, Vec<i64>) {
        // The largest module's record: PZD2..PZD12.
        let record = elements(&doc, "ParameterRecordDataItem")
            .filter(|r| r.attribute("Index") == Some(index))
            .max_by_key(|r| children(*r, "Ref").count())
            .unwrap();
        let refs: Vec<Node> = children(record, "Ref").collect();
        let target = attribute(refs[0], "ValueItemTarget");
        assert!(refs
            .iter()
            .all(|r| r.attribute("ValueItemTarget") == Some(target)));
        let item = elements(&doc, "ValueItem")
            .find(|v| v.attribute("ID") == Some(target))
            .unwrap();
        let values = item
            .descendants()
            .filter(|n| n.has_tag_name("Assign"))
            .map(|a| attribute(a, "Content").parse().unwrap())
            .collect();
        (refs.len(), values)
    };
    assert_eq!(values_of_record("1"), (11, (0..=14).collect()));
    assert_eq!(values_of_record("2"), (11, (0..=25).collect()));
}

/// Every user-defined (PZD) module carries the parameter records the IR
/// plans for it, standard telegram 1 only those of the settings its module
/// fixes, the DAP none; every Ref lies inside its record, its default is
/// among its allowed values as the IR has them, and a value the module fixes
/// is not changeable.
#[test]
fn record_refs_fit_their_records() {
    for (name, ir) in with_profinet() {
        let (text, profinet) = gsdml_of(&ir);
        let doc = Document::parse(&text).unwrap();
        let records_of = |submodule_id: &str| -> Vec<Node> {
            let submodule = elements(&doc, "VirtualSubmoduleItem")
                .find(|s| s.attribute("ID") == Some(submodule_id))
                .unwrap_or_else(|| panic!("{name}: no submodule {submodule_id}"));
            submodule
                .descendants()
                .filter(|n| n.has_tag_name("ParameterRecordDataItem"))
                .collect()
        };
        assert!(records_of("IDS_DAP").is_empty(), "{name}");
        // The master writes records of the sets it sets, none of those set
        // at the drive.
        let master_writes = ir.mappings.sets().any(|s| s.master_writes());
        for module in &profinet.modules {
            let records = records_of(&module.submodule_id);
            let expected = match module.kind {
                ModuleKind::Pzd if master_writes => 1..=usize::MAX,
                ModuleKind::Pzd => 0..=0,
                ModuleKind::StandardTelegram1 => 0..=usize::MAX,
                _ => unreachable!(),
            };
            assert!(expected.contains(&records.len()), "{name}: {}", module.id);
            assert_eq!(records.len(), module.records.len(), "{name}: {}", module.id);
            check_records(&ir, &module.records, &records, &name);
        }
    }
}

/// The AX200 fixture's telegram selection P0922 (record 3) is fixed by
/// each module: 1 in standard telegram 1, whose only record it is, and 999
/// (free telegram) in every module of PZD words; neither can be changed.
#[test]
fn modules_fix_a_per_module_setting() {
    let (text, _) = gsdml_of(&descriptions::load_from(
        "tests/fixtures/valid",
        "ax200.toml",
    ));
    let doc = Document::parse(&text).unwrap();
    let mut pzd_modules = 0;
    for submodule in elements(&doc, "VirtualSubmoduleItem") {
        let id = attribute(submodule, "ID");
        let records: Vec<Node> = submodule
            .descendants()
            .filter(|n| n.has_tag_name("ParameterRecordDataItem"))
            .collect();
        let fixed = if id == "IDS_STD_TEL_1" {
            assert_eq!(records.len(), 1, "{id}");
            "1"
        } else if id.starts_with("IDS_PZD_") {
            pzd_modules += 1;
            "999"
        } else {
            continue;
        };
        let p0922 = records
            .iter()
            .find(|r| attribute(**r, "Index") == "3")
            .unwrap_or_else(|| panic!("{id} has record 3"));
        let first = children(*p0922, "Ref").next().unwrap();
        assert_eq!(attribute(first, "DefaultValue"), fixed, "{id}");
        assert_eq!(attribute(first, "Changeable"), "false", "{id}");
    }
    assert_eq!(pzd_modules, 3);
}

fn check_records(ir: &Ir, planned: &[ParameterRecord], records: &[Node], name: &str) {
    for (node, record) in records.iter().zip(planned) {
        assert_eq!(
            attribute(*node, "Index"),
            record.index.to_string(),
            "{name}"
        );
        let length: usize = attribute(*node, "Length").parse().unwrap();
        let refs: Vec<Node> = children(*node, "Ref").collect();
        assert_eq!(refs.len(), record.refs.len(), "{name}");
        assert_eq!(length, 2 * record.refs.len(), "{name}");
        for (i, (r, planned)) in refs.iter().zip(&record.refs).enumerate() {
            let (set, entry) = ir.mappings.entry(planned.entry);
            let offset: usize = attribute(*r, "ByteOffset").parse().unwrap();
            assert_eq!(offset, 2 * i, "{name}");
            assert_eq!(
                attribute(*r, "DefaultValue"),
                planned.default.to_string(),
                "{name}"
            );
            if planned.changeable {
                assert_eq!(planned.default, entry.default, "{name}");
            }
            assert_eq!(
                attribute(*r, "Changeable"),
                planned.changeable.to_string(),
                "{name}"
            );
            assert!(set.allowed.contains(planned.default.into()), "{name}");
            let has_target = r.attribute("ValueItemTarget").is_some();
            assert_eq!(
                has_target,
                matches!(set.allowed, Allowed::Choices(_)),
                "{name}"
            );
        }
    }
}

/// A description of GSDML V2.34 whose access points are certified against
/// PROFINET V2.33 (own_idents.toml, as SEW's MOVI-C's first): the version is
/// in the file's name and schema location, each access point's PNIO_Version
/// is the stated one, and gsdc's own check finds nothing in it (the PI
/// schema's verdict is xsd.rs's).
#[test]
fn a_later_gsdml_version_names_the_file_and_its_access_points_their_own() {
    let ir = fixture("own_idents.toml");
    let (text, profinet) = gsdml_of(&ir);
    assert_eq!(profinet.file_name, "GSDML-V2.34-Acme-X4-20260228.xml");
    assert!(text.contains("..\\xsd\\GSDML-DeviceProfile-V2.34.xsd\""));
    let doc = Document::parse(&text).unwrap();
    let versions: Vec<&str> = elements(&doc, "DeviceAccessPointItem")
        .map(|dap| attribute(dap, "PNIO_Version"))
        .collect();
    assert_eq!(versions, ["V2.33"; 4]);
    let found = gsdc::gsdml::check(&text, Some(&profinet.file_name));
    assert!(found.is_empty(), "{found:#?}");
}

/// What the DAP must and must not say, beyond the schema.
#[test]
fn the_dap_keeps_the_rules_beyond_the_schema() {
    for (name, ir) in with_profinet() {
        let (text, profinet) = gsdml_of(&ir);
        let doc = Document::parse(&text).unwrap();
        let dap = elements(&doc, "DeviceAccessPointItem").next().unwrap();
        assert_eq!(
            attribute(dap, "PNIO_Version"),
            profinet.pnio_version.to_string(),
            "{name}"
        );
        assert_eq!(attribute(dap, "PhysicalSlots"), "0..1", "{name}");
        let records = attribute(
            elements(&doc, "VirtualSubmoduleItem").next().unwrap(),
            "Writeable_IM_Records",
        );
        assert!(
            records.split(' ').all(|r| r != "0" && r != "5"),
            "{name}: {records}"
        );
        let interface = elements(&doc, "InterfaceSubmoduleItem").next().unwrap();
        assert_eq!(interface.attribute("DCP_HelloSupported"), None, "{name}");
        assert_eq!(attribute(interface, "SubslotNumber"), "32768", "{name}");
        let relations = children(interface, "ApplicationRelations").next().unwrap();
        assert_eq!(
            attribute(relations, "StartupMode"),
            "Legacy;Advanced",
            "{name}"
        );
        let ports: Vec<&str> = elements(&doc, "PortSubmoduleItem")
            .map(|p| attribute(p, "SubslotNumber"))
            .collect();
        let expected: Vec<String> = (1..=profinet.first_dap().ports.len())
            .map(|p| (0x8000 + p).to_string())
            .collect();
        assert_eq!(ports, expected, "{name}");
    }
}

/// The checker that guards the build rejects a generated file broken in
/// each of the ways the issue names: a duplicated ID, a removed TextId, a
/// module longer than IOConfigData allows. Each mutation is checked to have
/// happened, so the test cannot pass on an unchanged file.
#[test]
fn broken_generated_files_are_rejected_with_their_rule() {
    let ir = load("mv810-pnet02.toml");
    let (text, profinet) = gsdml_of(&ir);
    let file_name = Some(profinet.file_name.as_str());
    let codes = |xml: &str| -> Vec<&'static str> {
        gsdc::gsdml::check(xml, file_name)
            .errors()
            .map(|d| d.code)
            .collect()
    };
    assert_eq!(
        codes(&text),
        Vec::<&str>::new(),
        "the generated file is clean"
    );

    let duplicated = mutate(&text, "ID=\"IDM_PKW_1\"", "ID=\"IDM_PKW_2\"");
    assert!(
        codes(&duplicated).contains(&"E306"),
        "{:?}",
        codes(&duplicated)
    );

    let primary = text.find("<PrimaryLanguage>").unwrap();
    let text_id = "<Text TextId=\"IDT_DEVICE_NAME\"";
    let at = primary + text[primary..].find(text_id).unwrap();
    let end = at + text[at..].find("/>").unwrap() + 2;
    let removed = format!("{}{}", &text[..at], &text[end..]);
    assert!(codes(&removed).contains(&"E308"), "{:?}", codes(&removed));

    let too_long = mutate(
        &text,
        "MaxInputLength=\"38\" MaxOutputLength=\"38\"",
        "MaxInputLength=\"20\" MaxOutputLength=\"20\"",
    );
    assert!(codes(&too_long).contains(&"E310"), "{:?}", codes(&too_long));
}

/// `text` with `from` replaced once; panics if `from` is not there.
fn mutate(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "{from} is not in the generated file");
    text.replacen(from, to, 1)
}

/// A valid fixture (tests/fixtures/valid/).
fn fixture(name: &str) -> Ir {
    descriptions::load_from("tests/fixtures/valid", name)
}

/// Every Value of the ExternalTextList, in every language.
fn text_values<'a>(doc: &'a Document) -> Vec<&'a str> {
    elements(doc, "Text")
        .map(|t| attribute(t, "Value"))
        .collect()
}

/// A PROFIdrive card's standard telegrams are the profile's, placed as
/// ABB's FENA places them: the module access point (no data, ident 0xFFFF)
/// fixed in subslot 1, the telegram fixed in subslot 2, both in API 14848,
/// with the profile's word names; telegram 2's speeds are Unsigned32 between
/// two words, as in FENA's file; the card's other modules stay in API 0.
#[test]
fn a_profidrive_telegram_sits_behind_the_access_point_in_the_profiles_api() {
    let ir = fixture("profidrive.toml");
    let (text, _) = gsdml_of(&ir);
    let doc = Document::parse(&text).unwrap();
    const U16: &str = "Unsigned16";
    let telegram_1: (_, Items, Items) = (
        ("IDM_STD_TEL_1", "0x00000010"),
        &[
            ("STW1 (control word 1)", U16),
            ("NSOLL_A (speed setpoint A)", U16),
        ],
        &[
            ("ZSW1 (status word 1)", U16),
            ("NIST_A (speed actual value A)", U16),
        ],
    );
    let telegram_2: (_, Items, Items) = (
        ("IDM_STD_TEL_2", "0x00000020"),
        &[
            ("STW1 (control word 1)", U16),
            ("NSOLL_B (speed setpoint B)", "Unsigned32"),
            ("STW2 (control word 2)", U16),
        ],
        &[
            ("ZSW1 (status word 1)", U16),
            ("NIST_B (speed actual value B)", "Unsigned32"),
            ("ZSW2 (status word 2)", U16),
        ],
    );
    for ((id, ident), output, input) in [telegram_1, telegram_2] {
        let module = elements(&doc, "ModuleItem")
            .find(|m| m.attribute("ID") == Some(id))
            .unwrap();
        assert_profidrive_module(&doc, module, ident, (output, input));
    }
    let other_apis: BTreeSet<&str> = elements(&doc, "VirtualSubmoduleItem")
        .filter(|s| {
            !s.ancestors().any(|a| {
                a.attribute("ID")
                    .is_some_and(|id| id.starts_with("IDM_STD_TEL_"))
            })
        })
        .filter_map(|s| s.attribute("API"))
        .collect();
    assert_eq!(other_apis, BTreeSet::from(["0"]));
}

/// Data items as (English name, DataType), in order.
type Items = &'static [(&'static str, &'static str)];

/// One PROFIdrive module: its access point and data submodule placed, and
/// its data items each way with their English names and data types.
fn assert_profidrive_module(
    doc: &Document,
    module: Node,
    ident: &str,
    (output, input): (Items, Items),
) {
    let submodules: Vec<Node> = module
        .descendants()
        .filter(|n| n.has_tag_name("VirtualSubmoduleItem"))
        .collect();
    let placed: Vec<(&str, &str, &str)> = submodules
        .iter()
        .map(|s| {
            (
                attribute(*s, "SubmoduleIdentNumber"),
                attribute(*s, "API"),
                attribute(*s, "FixedInSubslots"),
            )
        })
        .collect();
    assert_eq!(
        placed,
        [("0x0000FFFF", "14848", "1"), (ident, "14848", "2")]
    );
    let access_point_data = children(submodules[0], "IOData").next().unwrap();
    assert_eq!(access_point_data.children().count(), 0);
    let access_point_name = submodules[0]
        .descendants()
        .find(|n| n.has_tag_name("Name"))
        .unwrap();
    assert_eq!(
        english(doc, attribute(access_point_name, "TextId")),
        "Module Access Point"
    );
    let items = |element: &str| -> Vec<(&str, &str)> {
        let io = submodules[1]
            .descendants()
            .find(|n| n.has_tag_name(element))
            .unwrap();
        children(io, "DataItem")
            .map(|d| {
                (
                    english(doc, attribute(d, "TextId")),
                    attribute(d, "DataType"),
                )
            })
            .collect()
    };
    assert_eq!(items("Output"), output, "{ident}");
    assert_eq!(items("Input"), input, "{ident}");
    let category = children(module, "ModuleInfo").next().unwrap();
    assert_eq!(attribute(category, "CategoryRef"), "IDC_STANDARD_TELEGRAMS");
}

/// MV810 does not implement PROFIdrive (its control word's bit 0 is
/// forward run): its "standard message 1" keeps the manual's name and
/// words in API 0, and no text of the file names the profile or its words.
#[test]
fn a_card_without_profidrive_shows_no_profidrive_name() {
    let (text, _) = gsdml_of(&load("mv810-pnet02.toml"));
    let doc = Document::parse(&text).unwrap();
    for value in text_values(&doc) {
        for profile in [
            "PROFIdrive",
            "STW1",
            "NSOLL",
            "ZSW1",
            "NIST",
            "Standard telegram",
        ] {
            assert!(!value.contains(profile), "{value:?} names {profile}");
        }
    }
    assert!(elements(&doc, "VirtualSubmoduleItem").all(|s| s.attribute("API") != Some("14848")));
    let module = elements(&doc, "ModuleItem")
        .find(|m| m.attribute("ID") == Some("IDM_STD_TEL_1"))
        .unwrap();
    let name = module
        .descendants()
        .find(|n| n.has_tag_name("Name"))
        .unwrap();
    assert_eq!(
        english(&doc, attribute(name, "TextId")),
        "standard message 1"
    );
    let output = module
        .descendants()
        .find(|n| n.has_tag_name("Output"))
        .unwrap();
    let words: Vec<&str> = children(output, "DataItem")
        .map(|d| english(&doc, attribute(d, "TextId")))
        .collect();
    assert_eq!(words, ["Master sends control command word", "PZD2"]);
}

/// Send clocks, conformance and netload class, writable I&M records, MRP
/// and the order number are the description's (the fixture states each),
/// gsdc's defaults where it is silent (MV810, which has no order number);
/// the DCP and PTP boundaries are always there.
#[test]
fn interface_properties_are_the_descriptions_or_gsdcs_defaults() {
    let stated = fixture("no_warnings.toml");
    let silent = load("mv810-pnet02.toml");
    assert_eq!(stated.device.order_number.as_deref(), Some("X1-DP-01"));
    let cases = [
        (&stated, "8 16 32 64 128", ("B", "II"), "1 2 3 4", true),
        (&silent, "32 64 128", ("B", "I"), "1 2 3", false),
    ];
    for (ir, send_clock, (conformance, netload), im, mrp) in cases {
        let (text, profinet) = gsdml_of(ir);
        let name = &profinet.file_name;
        let doc = Document::parse(&text).unwrap();
        let timing = elements(&doc, "TimingProperties").next().unwrap();
        assert_eq!(attribute(timing, "SendClock"), send_clock, "{name}");
        let certification = elements(&doc, "CertificationInfo").next().unwrap();
        assert_eq!(
            (
                attribute(certification, "ConformanceClass"),
                attribute(certification, "NetloadClass")
            ),
            (conformance, netload),
            "{name}"
        );
        let dap_info = elements(&doc, "DeviceAccessPointItem")
            .flat_map(|d| children(d, "ModuleInfo"))
            .next()
            .unwrap();
        let order_number = children(dap_info, "OrderNumber").next();
        assert_eq!(
            order_number.map(|o| attribute(o, "Value")),
            ir.device.order_number.as_deref(),
            "{name}"
        );
        let dap_submodule = elements(&doc, "VirtualSubmoduleItem").next().unwrap();
        assert_eq!(
            attribute(dap_submodule, "Writeable_IM_Records"),
            im,
            "{name}"
        );
        let interface = elements(&doc, "InterfaceSubmoduleItem").next().unwrap();
        for boundary in ["DCP_BoundarySupported", "PTP_BoundarySupported"] {
            assert_eq!(attribute(interface, boundary), "true", "{name}");
        }
        let redundancy = children(interface, "MediaRedundancy").next();
        assert_eq!(
            redundancy.map(|r| attribute(r, "SupportedRole")),
            mrp.then_some("Client"),
            "{name}"
        );
        let ring_ports: Vec<Option<&str>> = elements(&doc, "PortSubmoduleItem")
            .map(|p| p.attribute("IsDefaultRingport"))
            .collect();
        let expected = if mrp { Some("true") } else { None };
        assert_eq!(ring_ports, [expected, expected], "{name}");
    }
}

/// Each module is listed under its group of the hardware catalog, as ABB
/// groups its modules; every group listed has a module.
#[test]
fn modules_are_grouped_in_the_catalog() {
    let (text, _) = gsdml_of(&load("mv810-pnet02.toml"));
    let doc = Document::parse(&text).unwrap();
    let groups: Vec<(&str, &str)> = elements(&doc, "ModuleItem")
        .map(|m| {
            let info = children(m, "ModuleInfo").next().unwrap();
            (attribute(m, "ID"), attribute(info, "CategoryRef"))
        })
        .collect();
    assert_eq!(groups[0], ("IDM_STD_TEL_1", "IDC_PZD"));
    assert!(groups[1..].iter().all(|(_, c)| *c == "IDC_PKW_PZD"));
    let listed: Vec<(&str, &str)> = elements(&doc, "CategoryItem")
        .map(|c| (attribute(c, "ID"), english(&doc, attribute(c, "TextId"))))
        .collect();
    assert_eq!(listed, [("IDC_PZD", "PZD"), ("IDC_PKW_PZD", "PKW and PZD")]);
}

/// `[profinet.ident_numbers]` puts each stated number where the GSDML and
/// the layouts carry it, and leaves gsdc's numbering for the rest; without
/// the table the numbers are gsdc's (the snapshots hold them).
#[test]
fn stated_ident_numbers_replace_gsdcs_numbering() {
    let fixture = std::fs::read_to_string(crate::support::checkout(
        "tests/fixtures/valid/profidrive.toml",
    ))
    .unwrap();
    let text = format!(
        "{fixture}\n[profinet.ident_numbers]\ndap = 0x00010000\ndap_submodule = 0x00010001\n\
         interface = 0x00000002\nports = [0x00000003, 0x00000004]\naccess_point = 0x00000005\n\
         modules = {{ telegram1 = 0x00000A01 }}\nsubmodules = {{ telegram1 = 0x00000B01 }}\n"
    );
    let (ir, diagnostics) = descriptions::load_text("profidrive.toml", &text);
    assert_eq!(diagnostics.errors().count(), 0, "{diagnostics:?}");
    let ir = ir.unwrap();
    let (gsdml, _) = gsdml_of(&ir);
    let doc = Document::parse(&gsdml).unwrap();
    let idents = |element: &'static str, attribute_name: &str| -> Vec<String> {
        elements(&doc, element)
            .map(|n| attribute(n, attribute_name).to_string())
            .collect()
    };
    assert_eq!(
        idents("DeviceAccessPointItem", "ModuleIdentNumber"),
        ["0x00010000"]
    );
    assert_eq!(
        idents("InterfaceSubmoduleItem", "SubmoduleIdentNumber"),
        ["0x00000002"]
    );
    assert_eq!(
        idents("PortSubmoduleItem", "SubmoduleIdentNumber"),
        ["0x00000003", "0x00000004"]
    );
    // The DAP's submodule, the access point and telegram 1's data
    // submodule, the access point and telegram 2's, then the 1-PZD module:
    // telegram 2 and the 1-PZD module keep gsdc's numbers.
    assert_eq!(
        idents("VirtualSubmoduleItem", "SubmoduleIdentNumber"),
        [
            "0x00010001",
            "0x00000005",
            "0x00000B01",
            "0x00000005",
            "0x00000020",
            "0x00000101"
        ]
    );
    assert_eq!(
        idents("ModuleItem", "ModuleIdentNumber"),
        ["0x00000A01", "0x00000020", "0x00000101"]
    );
    let rust = descriptions::output_text(&ir, ArtifactKind::RustLayout);
    for constant in [
        "DAP_IDENT: u32 = 0x0001_0000",
        "DAP_SUBMODULE_IDENT: u32 = 0x0001_0001",
        "INTERFACE_IDENT: u32 = 0x0000_0002",
        "PORT2_IDENT: u32 = 0x0000_0004",
        "TELEGRAM1_IDENT: u32 = 0x0000_0A01",
        "TELEGRAM1_SUBMODULE_IDENT: u32 = 0x0000_0B01",
        "TELEGRAM1_ACCESS_POINT_IDENT: u32 = 0x0000_0005",
    ] {
        assert!(rust.contains(constant), "{constant} not in\n{rust}");
    }
    let headers = descriptions::output_text(&ir, ArtifactKind::Gsdml);
    assert!(headers.contains("profinet ident numbers [profinet.ident_numbers] does not state"));
}

/// `[profinet.pzd_names]` names the PZD words after the control word the
/// telegram names, which keeps its name, and every PZD word the other way,
/// where it names no status word: french.toml's one module of 2 PZD words,
/// its words in the order of the data items.
#[test]
fn pzd_names_follow_the_control_and_status_words() {
    let fixture =
        std::fs::read_to_string(crate::support::checkout("tests/fixtures/valid/french.toml"))
            .unwrap();
    let text = format!(
        "{fixture}\n[profinet.pzd_names]\noutput = [\"Speed reference\"]\ninput = [\"Status\", \"Speed actual\"]\n"
    );
    let (ir, diagnostics) = descriptions::load_text("french.toml", &text);
    let ir = ir.unwrap_or_else(|| panic!("{diagnostics:#?}"));
    let (gsdml, _) = gsdml_of(&ir);
    let doc = Document::parse(&gsdml).unwrap();
    let names = |part: &str| -> Vec<&str> {
        let module = elements(&doc, "ModuleItem").next().unwrap();
        let items = module.descendants().filter(|n| n.has_tag_name(part));
        let items = items.flat_map(|p| children(p, "DataItem"));
        items
            .map(|i| english(&doc, attribute(i, "TextId")))
            .collect()
    };
    assert_eq!(names("Output"), ["Control word", "Speed reference"]);
    assert_eq!(names("Input"), ["Status", "Speed actual"]);

    let three = text.replace(
        "[\"Speed reference\"]",
        "[\"Control\", \"Speed reference\"]",
    );
    let errors = descriptions::error_places("french.toml", &three);
    assert_eq!(errors.iter().map(|e| e.0).collect::<Vec<_>>(), ["E193"]);
}

/// A TextId names one text: in every description and fixture, no two of
/// the texts the GSDML refers to (`Profinet::text_refs`) share a TextId
/// with different words, which the file would show for both.
#[test]
fn no_text_id_names_two_texts() {
    for (name, ir) in descriptions::all_valid() {
        let Some(p) = &ir.profinet else {
            continue;
        };
        let mut seen: std::collections::BTreeMap<&str, &gsdc::ir::Text> = Default::default();
        for text in p.text_refs() {
            let known = *seen.entry(text.id.as_str()).or_insert(&text.text);
            assert_eq!(known, &text.text, "{name}: {} names two texts", text.id);
        }
    }
}
