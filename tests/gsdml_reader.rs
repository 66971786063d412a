//! The GSDML reader and its rules: the real files of `shared/corpus/`, and
//! one small hand-written GSDML per rule.

use std::collections::BTreeMap;

use crate::support::{self, descriptions, xsd};
use gsdc::gsdml::{check, decode};
use gsdc::Diagnostic;

// ---------------------------------------------------------------------------
// Corpus

/// The decoded `.xml` files of a corpus folder, by name. A missing corpus
/// fails the test: it must not pass by checking nothing.
fn corpus(folder: &str) -> Vec<(String, String)> {
    let path = support::shared("corpus").join(folder);
    let entries = std::fs::read_dir(&path).unwrap_or_else(|e| {
        panic!(
            "the corpus folder {} is missing ({e}); the tests read ../shared/corpus",
            path.display()
        )
    });
    let mut files: Vec<(String, String)> = entries
        .map(|entry| entry.expect("readable corpus folder").path())
        .filter(|p| p.extension().is_some_and(|e| e == "xml"))
        .map(|p| {
            let name = p.file_name().unwrap().to_str().unwrap().to_string();
            let bytes = std::fs::read(&p).unwrap();
            let text = decode(&bytes)
                .unwrap_or_else(|d| panic!("{name}: {}", d.message))
                .into_owned();
            (name, text)
        })
        .collect();
    files.sort();
    assert!(!files.is_empty(), "no .xml files in {}", path.display());
    files
}

/// What gsdc finds in the valid corpus: (file, code, count). No file
/// breaks an error rule of its own version; the warnings are explained in
/// docs/rules.md, "Known findings in the corpus".
const KNOWN_FINDINGS: &[(&str, &str, usize)] = &[
    // Input and output: 79 slots, each with its data and status bytes.
    ("GSDML-V2.25-LEUZE-BCL348i-20120814.xml", "W302", 2),
    ("GSDML-V2.3-LEUZE-BCL648i-20150128.xml", "W302", 2),
    ("GSDML-V2.31-LEUZE-BCL348i-20150923.xml", "W302", 2),
    // Input of DAP V3 and V4: 38 data bytes and 7 or 8 status bytes, 44 allowed.
    ("GSDML-V2.33-ABB-FENA-20170914.xml", "W302", 2),
    ("GSDML-V2.33-rt-labs-IODevice-20191008.xml", "W301", 1),
    (
        "GSDML-V2.34-SEW-MOVI-C-Decentralized-Electronics-20200731-071447.xml",
        "W302",
        6,
    ),
    ("GSDML-V2.35-rtlabs-IODevice-20200603.xml", "W301", 1),
    ("GSDML-V2.4-RT-Labs-P-Net-LAN9662-20220511.xml", "W301", 1),
    (
        "GSDML-V2.4-RT-Labs-P-Net-Sample-App-20210507.xml",
        "W301",
        1,
    ),
    ("GSDML-V2.41-LEUZE-BCL248i-20211213.xml", "W302", 2),
    (
        "GSDML-V2.43-RT-Labs-P-Net-Sample-App-20230117.xml",
        "W301",
        1,
    ),
    (
        "GSDML-V2.43-RT-Labs-P-Net-Sample-App-20240530.xml",
        "W301",
        1,
    ),
    ("GSDML-V2.43-RT-Labs-U-Phy-Samples-20230516.xml", "W301", 2),
];

fn codes(diagnostics: &[Diagnostic]) -> BTreeMap<&'static str, usize> {
    let mut counts = BTreeMap::new();
    for d in diagnostics {
        *counts.entry(d.code).or_default() += 1;
    }
    counts
}

fn render(name: &str, text: &str, diagnostics: &[Diagnostic]) -> String {
    let source = gsdc::Source::new(name, text);
    diagnostics.iter().map(|d| source.render(d)).collect()
}

#[test]
fn valid_corpus_has_only_the_known_findings() {
    let files = corpus("gsdml");
    assert_eq!(
        files.len(),
        16,
        "the corpus has 16 GSDML files, V2.25 to V2.43"
    );
    for (name, text) in &files {
        let found = check(text, Some(name)).0;
        let expected: BTreeMap<&str, usize> = KNOWN_FINDINGS
            .iter()
            .filter(|(file, _, _)| file == name)
            .map(|(_, code, count)| (*code, *count))
            .collect();
        assert_eq!(
            codes(&found),
            expected,
            "{name}:\n{}",
            render(name, text, &found)
        );
    }
}

// ---------------------------------------------------------------------------
// gsdc's own output, read the way the checker reads third-party files

/// The GSDML files gsdc writes for the shipped descriptions and the valid
/// fixtures (one with PROFIdrive's access point in its largest module):
/// (name, text, whether its first access point's MaxInputLength and
/// MaxOutputLength are stated in `[profinet.stack]` rather than what the
/// modules need, whether its modules go into several slots).
fn generated_gsdml_with_limits() -> Vec<(String, String, [bool; 2], bool)> {
    let mut files = Vec::new();
    for (_, ir) in descriptions::all_valid() {
        let Some(profinet) = &ir.profinet else {
            continue;
        };
        let stack = &profinet.daps[0].stack;
        let stated = [stack.max_input_length, stack.max_output_length].map(|l| l.is_some());
        // The data modules' slots, or a slot of a safety module besides.
        let several_slots = profinet.module_slots.count() > 1
            || profinet
                .safety_modules
                .iter()
                .any(|m| m.slots != profinet.module_slots);
        for file in gsdc::compile(&ir).unwrap() {
            if file.file_name.ends_with(".xml") {
                let text = String::from_utf8(file.contents).unwrap();
                files.push((file.file_name, text, stated, several_slots));
            }
        }
    }
    files
}

/// One reading of IOConfigData on both sides: the MaxInputLength and
/// MaxOutputLength gsdc writes are exactly what the checker needs for the
/// largest configuration, status bytes included: the largest module, or
/// with several slots each slot with its largest module and the empty
/// module's and the safety modules' slots (profisafe.toml: its safety
/// modules' slot 1 beside its data modules' slot 2, each way its own). One byte less and the checker finds a module that never
/// fits (E310), or with several slots a configuration that does not
/// (W302). Should the emitter stop counting IOPS/IOCS, or the checker, or
/// either count something the other does not, one of the two assertions
/// fails. A limit the description states (more than the need) is left out
/// of the second.
#[test]
fn emitted_io_config_data_is_exactly_what_the_checker_needs() {
    let files = generated_gsdml_with_limits();
    assert_eq!(
        files.len(),
        8,
        "the shipped PROFINET descriptions and fixtures"
    );
    let mut lowered_limits = 0;
    for (name, text, stated, several_slots) in &files {
        let io_findings = |text: &str| -> Vec<&'static str> {
            check(text, Some(name))
                .iter()
                .map(|d| d.code)
                .filter(|c| matches!(*c, "E310" | "W302"))
                .collect()
        };
        assert_eq!(io_findings(text), Vec::<&str>::new(), "{name}");
        for (attribute, _) in ["MaxInputLength", "MaxOutputLength"]
            .into_iter()
            .zip(stated)
            .filter(|(_, stated)| !**stated)
        {
            let at = text.find(&format!("{attribute}=\"")).unwrap() + attribute.len() + 2;
            let digits = &text[at..at + text[at..].find('"').unwrap()];
            let value: u32 = digits.parse().unwrap();
            let lowered = format!("{}{}{}", &text[..at], value - 1, &text[at + digits.len()..]);
            let found = io_findings(&lowered);
            let expected = if *several_slots { "W302" } else { "E310" };
            assert!(
                !found.is_empty() && found.iter().all(|c| *c == expected),
                "{name}: {attribute} {value} - 1: {found:?}"
            );
            lowered_limits += 1;
        }
    }
    // Every file but profidrive's, whose limits are stated.
    assert_eq!(lowered_limits, 2 * (files.len() - 1));
}

/// Each broken copy of the p-net sample with the errors it deserves, in
/// file order, and the text each error points at.
const BROKEN: &[(&str, &[(&str, &str)])] = &[
    ("neg_bad_datatype.xml", &[("E309", "UInt8")]),
    ("neg_bad_identnumber.xml", &[("E318", "12")]),
    ("neg_dangling_moduleref.xml", &[("E307", "IDM_NOPE")]),
    // IDM_31 was renamed to the duplicate IDM_30, so its reference dangles too.
    (
        "neg_dup_module_id.xml",
        &[("E307", "IDM_31"), ("E306", "IDM_30")],
    ),
    (
        "neg_missing_pnio_version.xml",
        &[("E319", "DeviceAccessPointItem")],
    ),
    ("neg_missing_textid.xml", &[("E308", "IDT_DOES_NOT_EXIST")]),
];

#[test]
fn broken_corpus_is_rejected_for_what_was_broken() {
    let files = corpus("gsdml-invalid");
    assert_eq!(files.len(), BROKEN.len());
    for (name, text) in &files {
        let expected = BROKEN
            .iter()
            .find(|(file, _)| file == name)
            .unwrap_or_else(|| panic!("{name} not in BROKEN"))
            .1;
        // Their names are not GSDML names (they stand for the sample's), so no file name.
        let found = check(text, None);
        let errors: Vec<(&str, &str)> =
            found.errors().map(|d| (d.code, spanned(text, d))).collect();
        assert_eq!(
            errors,
            expected,
            "{name}:\n{}",
            render(name, text, &found.0)
        );
    }
}

// ---------------------------------------------------------------------------
// One rule at a time, on a small valid GSDML (V2.43) that each test breaks.

const NAME: &str = "GSDML-V2.43-Acme-Drive-20240101.xml";

const MINIMAL: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<ISO15745Profile xmlns="http://www.profibus.com/GSDML/2003/11/DeviceProfile" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:schemaLocation="http://www.profibus.com/GSDML/2003/11/DeviceProfile ..\xsd\GSDML-DeviceProfile-V2.43.xsd">
  <ProfileHeader>
    <ProfileIdentification>PROFINET Device Profile</ProfileIdentification>
    <ProfileRevision>1.00</ProfileRevision>
    <ProfileName>Device Profile for PROFINET Devices</ProfileName>
    <ProfileSource>PROFIBUS Nutzerorganisation e. V. (PNO)</ProfileSource>
    <ProfileClassID>Device</ProfileClassID>
    <ISO15745Reference>
      <ISO15745Part>4</ISO15745Part>
      <ISO15745Edition>1</ISO15745Edition>
      <ProfileTechnology>GSDML</ProfileTechnology>
    </ISO15745Reference>
  </ProfileHeader>
  <ProfileBody>
    <DeviceIdentity VendorID="0x0493" DeviceID="0x0002">
      <InfoText TextId="T_DEVICE"/>
      <VendorName Value="Acme"/>
    </DeviceIdentity>
    <DeviceFunction>
      <Family MainFamily="Drives" ProductFamily="Acme Drive"/>
    </DeviceFunction>
    <ApplicationProcess>
      <DeviceAccessPointList>
        <DeviceAccessPointItem ID="DAP_1" PNIO_Version="V2.43" PhysicalSlots="0..1" ModuleIdentNumber="0x00000001" MinDeviceInterval="32" DNS_CompatibleName="acme-drive" FixedInSlots="0" ObjectUUID_LocalIndex="1" DeviceAccessSupported="false" CheckDeviceID_Allowed="true" NameOfStationNotTransferable="false">
          <ModuleInfo>
            <Name TextId="T_DAP"/>
            <InfoText TextId="T_DAP"/>
          </ModuleInfo>
          <IOConfigData MaxInputLength="32" MaxOutputLength="32"/>
          <UseableModules>
            <ModuleItemRef ModuleItemTarget="IDM_PZD2" AllowedInSlots="1"/>
          </UseableModules>
          <VirtualSubmoduleList>
            <VirtualSubmoduleItem ID="IDS_DAP" SubmoduleIdentNumber="0x00000001" Writeable_IM_Records="1 2 3" MayIssueProcessAlarm="false">
              <IOData/>
              <ModuleInfo>
                <Name TextId="T_DAP"/>
                <InfoText TextId="T_DAP"/>
              </ModuleInfo>
            </VirtualSubmoduleItem>
          </VirtualSubmoduleList>
          <SystemDefinedSubmoduleList>
            <InterfaceSubmoduleItem ID="IDS_I" SubmoduleIdentNumber="0x00008000" SubslotNumber="32768" TextId="T_INTERFACE" SupportedRT_Classes="RT_CLASS_1" SupportedProtocols="SNMP;LLDP">
              <ApplicationRelations StartupMode="Legacy;Advanced">
                <TimingProperties SendClock="32" ReductionRatio="1 2 4 8 16 32 64 128 256 512"/>
              </ApplicationRelations>
            </InterfaceSubmoduleItem>
            <PortSubmoduleItem ID="IDS_P1" SubmoduleIdentNumber="0x00008001" SubslotNumber="32769" TextId="T_PORT">
              <MAUTypeList>
                <MAUTypeItem Value="16"/>
              </MAUTypeList>
            </PortSubmoduleItem>
          </SystemDefinedSubmoduleList>
          <Graphics>
            <GraphicItemRef Type="DeviceSymbol" GraphicItemTarget="G_SYMBOL"/>
          </Graphics>
        </DeviceAccessPointItem>
      </DeviceAccessPointList>
      <ModuleList>
        <ModuleItem ID="IDM_PZD2" ModuleIdentNumber="0x00000010">
          <ModuleInfo CategoryRef="C_PZD">
            <Name TextId="T_PZD2"/>
            <InfoText TextId="T_PZD2"/>
          </ModuleInfo>
          <VirtualSubmoduleList>
            <VirtualSubmoduleItem ID="IDS_PZD2" SubmoduleIdentNumber="0x00000010" FixedInSubslots="1" MayIssueProcessAlarm="false">
              <IOData>
                <Input Consistency="All items consistency">
                  <DataItem DataType="Unsigned16" TextId="T_WORD"/>
                  <DataItem DataType="Unsigned16" TextId="T_WORD"/>
                </Input>
                <Output Consistency="All items consistency">
                  <DataItem DataType="Unsigned16" TextId="T_WORD"/>
                  <DataItem DataType="Unsigned16" TextId="T_WORD"/>
                </Output>
              </IOData>
              <RecordDataList>
                <ParameterRecordDataItem Index="1" Length="4">
                  <Name TextId="T_RECORD"/>
                  <Ref DataType="Unsigned16" ByteOffset="0" DefaultValue="1" AllowedValues="0..14" ValueItemTarget="V_MEANING" TextId="T_PARAM"/>
                  <Ref DataType="Unsigned16" ByteOffset="2" DefaultValue="3" AllowedValues="0..25" TextId="T_PARAM"/>
                </ParameterRecordDataItem>
              </RecordDataList>
              <ModuleInfo>
                <Name TextId="T_PZD2"/>
                <InfoText TextId="T_PZD2"/>
              </ModuleInfo>
            </VirtualSubmoduleItem>
          </VirtualSubmoduleList>
        </ModuleItem>
      </ModuleList>
      <ValueList>
        <ValueItem ID="V_MEANING">
          <Assignments>
            <Assign Content="1" TextId="T_PARAM"/>
          </Assignments>
        </ValueItem>
      </ValueList>
      <GraphicsList>
        <GraphicItem ID="G_SYMBOL" GraphicFile="GSDML-0493-0002-ACME"/>
      </GraphicsList>
      <CategoryList>
        <CategoryItem ID="C_PZD" TextId="T_PZD2"/>
      </CategoryList>
      <ExternalTextList>
        <PrimaryLanguage>
          <Text TextId="T_DEVICE" Value="Acme drive"/>
          <Text TextId="T_DAP" Value="Acme PN card"/>
          <Text TextId="T_INTERFACE" Value="X1"/>
          <Text TextId="T_PORT" Value="X1 P1"/>
          <Text TextId="T_PZD2" Value="2 PZD"/>
          <Text TextId="T_WORD" Value="Word"/>
          <Text TextId="T_RECORD" Value="Mapping"/>
          <Text TextId="T_PARAM" Value="Meaning"/>
        </PrimaryLanguage>
        <Language xml:lang="de">
          <Text TextId="T_DEVICE" Value="Acme Antrieb"/>
          <Text TextId="T_DAP" Value="Acme PN-Karte"/>
          <Text TextId="T_INTERFACE" Value="X1"/>
          <Text TextId="T_PORT" Value="X1 P1"/>
          <Text TextId="T_PZD2" Value="2 PZD"/>
          <Text TextId="T_WORD" Value="Wort"/>
          <Text TextId="T_RECORD" Value="Zuordnung"/>
          <Text TextId="T_PARAM" Value="Bedeutung"/>
        </Language>
      </ExternalTextList>
    </ApplicationProcess>
  </ProfileBody>
</ISO15745Profile>"#;

/// MINIMAL with the first `from` replaced by `to`; `from` must be there, so
/// that no test checks the unchanged file by mistake.
fn edit(from: &str, to: &str) -> String {
    edit_text(MINIMAL, from, to)
}

fn edit_text(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "{from:?} is not in the text");
    text.replacen(from, to, 1)
}

/// MINIMAL declaring schema V2.25 (and named so).
fn minimal_v2_25() -> String {
    edit(
        "GSDML-DeviceProfile-V2.43.xsd",
        "GSDML-DeviceProfile-V2.25.xsd",
    )
}

fn spanned<'t>(text: &'t str, d: &Diagnostic) -> &'t str {
    d.span.clone().map_or("", |span| &text[span])
}

/// (code, text under the span) of every diagnostic, checked with the name
/// `name`. Every diagnostic must come with a help line, and a label when it
/// points somewhere.
fn findings_named<'t>(text: &'t str, name: &str) -> Vec<(&'static str, &'t str)> {
    let found = check(text, Some(name));
    for d in found.iter() {
        assert!(d.help.is_some(), "{} has no help", d.code);
        assert!(
            d.span.is_none() || d.label.is_some(),
            "{} has no label",
            d.code
        );
    }
    found.iter().map(|d| (d.code, spanned(text, d))).collect()
}

fn findings(text: &str) -> Vec<(&'static str, &str)> {
    findings_named(text, NAME)
}

#[test]
fn minimal_is_schema_valid_and_clean() {
    xsd::validate(MINIMAL).unwrap();
    assert_eq!(findings(MINIMAL), []);
}

#[test]
fn check_never_panics_on_truncated_files() {
    for end in (0..MINIMAL.len()).step_by(13) {
        let found = check(&MINIMAL[..end], Some(NAME));
        assert!(found.has_errors(), "a file cut at byte {end} passed");
    }
}

#[test]
fn e300_malformed_xml_points_at_the_error() {
    let text = edit("</ModuleList>", "</ModuleLis>");
    let found = check(&text, Some(NAME));
    assert_eq!(found.0.len(), 1);
    let d = &found.0[0];
    assert_eq!(d.code, "E300");
    let line = gsdc::line_col(&text, d.span.clone().unwrap().start).0;
    assert_eq!(text.lines().nth(line - 1).unwrap().trim(), "</ModuleLis>");
}

#[test]
fn e300_dtd_is_refused() {
    let text = edit(
        "<ISO15745Profile ",
        "<!DOCTYPE ISO15745Profile SYSTEM \"gsdml.dtd\">\n<ISO15745Profile ",
    );
    assert_eq!(findings(&text), [("E300", "<!DOCTYPE")]);
}

#[test]
fn e301_root_must_be_iso15745profile_in_the_gsdml_namespace() {
    assert_eq!(findings("<Device/>"), [("E301", "Device")]);
    let text = edit(
        "xmlns=\"http://www.profibus.com/GSDML/2003/11/DeviceProfile\"",
        "xmlns=\"urn:other\"",
    );
    assert_eq!(findings(&text), [("E301", "ISO15745Profile")]);
}

#[test]
fn w303_schema_version_unknown() {
    let text = edit("GSDML-DeviceProfile-V2.43.xsd", "GSDML-DeviceProfile.xsd");
    let found = findings(&text);
    assert_eq!(found.len(), 1);
    assert_eq!(found[0].0, "W303");
    assert!(found[0].1.ends_with("GSDML-DeviceProfile.xsd"));
    // The file name's version applies then: a V2.25 file may lack PNIO_Version ...
    let old = edit_text(&text, " PNIO_Version=\"V2.43\"", "");
    let v2_25 = "GSDML-V2.25-Acme-Drive-20240101.xml";
    assert_eq!(findings_named(&old, v2_25)[0].0, "W303");
    assert_eq!(findings_named(&old, v2_25).len(), 1);
    // ... and without a version anywhere, the newest applies.
    assert_eq!(
        check(&old, None).iter().map(|d| d.code).collect::<Vec<_>>(),
        ["W303", "E319"]
    );
}

#[test]
fn e303_profile_header_elements_are_required() {
    let text = edit("<ProfileTechnology>GSDML</ProfileTechnology>", "");
    assert_eq!(findings(&text), [("E303", "ProfileHeader")]);
    let text = edit("<ProfileHeader>", "<ProfileHeaderX>");
    let text = edit_text(&text, "</ProfileHeader>", "</ProfileHeaderX>");
    assert_eq!(findings(&text), [("E303", "ISO15745Profile")]);
}

#[test]
fn w304_profile_header_text_is_the_templates() {
    let text = edit("<ProfileTechnology>GSDML<", "<ProfileTechnology>GSD<");
    assert_eq!(findings(&text), [("W304", "ProfileTechnology")]);
}

#[test]
fn e304_file_name_convention() {
    assert_eq!(findings_named(MINIMAL, "acme.xml"), [("E304", "")]);
    assert_eq!(
        findings_named(MINIMAL, "GSDML-V2.43-Acme-Drive-20241301.xml"),
        [("E304", "")]
    );
    assert_eq!(
        findings_named(MINIMAL, "GSDML-V2.43-Acme-Drive-20240101-235959.xml"),
        []
    );
}

#[test]
fn e305_file_name_version_matches_schema_version() {
    let found = findings_named(MINIMAL, "GSDML-V2.32-Acme-Drive-20240101.xml");
    assert_eq!(found.len(), 1);
    assert_eq!(found[0].0, "E305");
    assert!(found[0].1.ends_with("GSDML-DeviceProfile-V2.43.xsd"));
}

#[test]
fn e306_ids_are_unique_in_their_scope() {
    let text = edit("ID=\"IDS_PZD2\"", "ID=\"IDS_DAP\"");
    assert_eq!(findings(&text), [("E306", "IDS_DAP")]);
    // A submodule may share its ID with its DAP (ABB FENA does): other scope.
    let text = edit("ID=\"IDS_PZD2\"", "ID=\"DAP_1\"");
    assert_eq!(findings(&text), []);
}

#[test]
fn e306_text_ids_are_unique_per_language() {
    let text = edit(
        "<Text TextId=\"T_WORD\" Value=\"Wort\"/>",
        "<Text TextId=\"T_WORD\" Value=\"Wort\"/><Text TextId=\"T_WORD\" Value=\"Datenwort\"/>",
    );
    assert_eq!(findings(&text), [("E306", "T_WORD")]);
}

#[test]
fn e307_references_resolve() {
    let text = edit(
        "GraphicItemTarget=\"G_SYMBOL\"",
        "GraphicItemTarget=\"G_LOGO\"",
    );
    assert_eq!(findings(&text), [("E307", "G_LOGO")]);
    let text = edit(
        "ValueItemTarget=\"V_MEANING\"",
        "ValueItemTarget=\"V_NONE\"",
    );
    assert_eq!(findings(&text), [("E307", "V_NONE")]);
    let text = edit("CategoryRef=\"C_PZD\"", "CategoryRef=\"C_NONE\"");
    assert_eq!(findings(&text), [("E307", "C_NONE")]);
}

#[test]
fn e307_menu_references_stay_in_their_record() {
    let menu = |target: &str| {
        format!(
            "<MenuList><MenuItem ID=\"M1\"><Name TextId=\"T_PARAM\"/>{target}</MenuItem></MenuList></ParameterRecordDataItem>"
        )
    };
    let with_id = edit(
        "<Ref DataType=\"Unsigned16\"",
        "<Ref ID=\"R1\" DataType=\"Unsigned16\"",
    );
    let good = menu("<ParameterRef ParameterTarget=\"R1\"/><MenuRef MenuTarget=\"M1\"/>");
    let text = edit_text(&with_id, "</ParameterRecordDataItem>", &good);
    assert_eq!(findings(&text), []);
    let bad = menu("<ParameterRef ParameterTarget=\"R2\"/><MenuRef MenuTarget=\"M2\"/>");
    let text = edit_text(&with_id, "</ParameterRecordDataItem>", &bad);
    assert_eq!(findings(&text), [("E307", "R2"), ("E307", "M2")]);
}

#[test]
fn e308_text_ids_resolve_to_the_primary_language() {
    let text = edit("<Name TextId=\"T_PZD2\"/>", "<Name TextId=\"T_PZD3\"/>");
    assert_eq!(findings(&text), [("E308", "T_PZD3")]);
    let text = edit(
        "</Language>",
        "<Text TextId=\"T_EXTRA\" Value=\"Extra\"/></Language>",
    );
    assert_eq!(findings(&text), [("E308", "T_EXTRA")]);
}

#[test]
fn w300_every_primary_text_is_translated() {
    let text = edit("<Text TextId=\"T_WORD\" Value=\"Wort\"/>", "");
    assert_eq!(findings(&text), [("W300", "Language")]);
}

#[test]
fn e309_data_types_exist_and_strings_have_a_length() {
    let text = edit(
        "<DataItem DataType=\"Unsigned16\"",
        "<DataItem DataType=\"UInt16\"",
    );
    assert_eq!(findings(&text), [("E309", "UInt16")]);
    let text = edit(
        "<DataItem DataType=\"Unsigned16\"",
        "<DataItem DataType=\"OctetString\"",
    );
    assert_eq!(findings(&text), [("E309", "DataItem")]);
    let text = edit("<Ref DataType=\"Unsigned16\"", "<Ref DataType=\"Word\"");
    assert_eq!(findings(&text), [("E309", "Word")]);
}

#[test]
fn e310_a_module_that_never_fits() {
    let text = edit("MaxInputLength=\"32\"", "MaxInputLength=\"3\"");
    assert_eq!(findings(&text), [("E310", "ModuleItemRef")]);
}

/// MaxInputLength counts status bytes: the DAP's submodule, interface and
/// port have an IOPS each in the input CR (3), the module its 4 data bytes,
/// its IOPS and the IOCS of its output (6): 9 in all, 4 of them data.
#[test]
fn e310_counts_iops_and_iocs() {
    let text = edit("MaxInputLength=\"32\"", "MaxInputLength=\"9\"");
    assert_eq!(findings(&text), []);
    let text = edit("MaxInputLength=\"32\"", "MaxInputLength=\"8\"");
    assert_eq!(findings(&text), [("E310", "ModuleItemRef")]);
    let message = &check(&text, Some(NAME)).0[0].message;
    assert!(message.contains("needs 9 input bytes"), "{message}");
    // An input-only module: its IOPS in the input CR, its IOCS in the output CR.
    let input_only = edit_text(
        &edit("<Output Consistency=\"All items consistency\">\n                  <DataItem DataType=\"Unsigned16\" TextId=\"T_WORD\"/>\n                  <DataItem DataType=\"Unsigned16\" TextId=\"T_WORD\"/>\n                </Output>", ""),
        "MaxOutputLength=\"32\"",
        "MaxOutputLength=\"3\"",
    );
    let message = &check(&input_only, Some(NAME)).0[0].message;
    assert!(message.contains("needs 4 output bytes"), "{message}");
}

#[test]
fn e310_the_fixed_configuration_does_not_fit() {
    let text = edit(
        "AllowedInSlots=\"1\"",
        "AllowedInSlots=\"1\" FixedInSlots=\"1\"",
    );
    let text = edit_text(&text, "MaxOutputLength=\"32\"", "MaxOutputLength=\"3\"");
    assert_eq!(findings(&text), [("E310", "3")]);
}

#[test]
fn w302_the_largest_configuration_does_not_fit() {
    let text = edit("PhysicalSlots=\"0..1\"", "PhysicalSlots=\"0..3\"");
    let text = edit_text(&text, "AllowedInSlots=\"1\"", "AllowedInSlots=\"1..3\"");
    // Each module with the DAP: 9 input bytes; all three: 3 + 3 * 6 = 21.
    let text = edit_text(&text, "MaxInputLength=\"32\"", "MaxInputLength=\"12\"");
    assert_eq!(findings(&text), [("W302", "12")]);
    let message = &check(&text, Some(NAME)).0[0].message;
    assert!(message.contains("needs 21 input bytes"), "{message}");
}

#[test]
fn e311_io_data_fits_a_frame() {
    let text = edit("MaxInputLength=\"32\"", "MaxInputLength=\"1441\"");
    assert_eq!(findings(&text), [("E311", "1441")]);
}

#[test]
fn e312_slots_are_physical_and_allowed() {
    let text = edit("AllowedInSlots=\"1\"", "AllowedInSlots=\"1..2\"");
    assert_eq!(findings(&text), [("E312", "1..2")]);
    let text = edit("PhysicalSlots=\"0..1\"", "PhysicalSlots=\"0..2\"");
    let text = edit_text(
        &text,
        "AllowedInSlots=\"1\"",
        "AllowedInSlots=\"1\" UsedInSlots=\"2\"",
    );
    assert_eq!(findings(&text), [("E312", "2")]);
}

#[test]
fn e313_subslot_numbers() {
    let text = edit("SubslotNumber=\"32769\"", "SubslotNumber=\"33024\"");
    assert_eq!(findings(&text), [("E313", "33024")]);
    let text = edit("SubslotNumber=\"32768\"", "SubslotNumber=\"32770\"");
    assert_eq!(findings(&text), [("E313", "32770")]);
    let text = edit("FixedInSubslots=\"1\"", "FixedInSubslots=\"32768\"");
    assert_eq!(findings(&text), [("E313", "32768")]);
}

#[test]
fn e314_dcp_hello_needs_power_on_to_comm_ready() {
    let hello = "SupportedProtocols=\"SNMP;LLDP\" DCP_HelloSupported=\"true\"";
    let text = edit("SupportedProtocols=\"SNMP;LLDP\"", hello);
    assert_eq!(findings(&text), [("E314", "true")]);
    let text = edit_text(
        &text,
        "FixedInSlots=\"0\"",
        "FixedInSlots=\"0\" PowerOnToCommReady=\"500\"",
    );
    assert_eq!(findings(&text), []);
    // Not established for versions before V2.33 (see the rule's docs).
    let old = edit_text(&minimal_v2_25(), "SupportedProtocols=\"SNMP;LLDP\"", hello);
    assert_eq!(
        findings_named(&old, "GSDML-V2.25-Acme-Drive-20240101.xml"),
        []
    );
}

#[test]
fn e315_im0_and_im5_are_read_only() {
    let text = edit(
        "Writeable_IM_Records=\"1 2 3\"",
        "Writeable_IM_Records=\"0..3\"",
    );
    assert_eq!(findings(&text), [("E315", "0..3")]);
}

#[test]
fn w301_startup_mode_offers_legacy() {
    let text = edit(
        "StartupMode=\"Legacy;Advanced\"",
        "StartupMode=\"Advanced\"",
    );
    assert_eq!(findings(&text), [("W301", "Advanced")]);
}

#[test]
fn e316_refs_stay_inside_their_record() {
    let text = edit("ByteOffset=\"2\"", "ByteOffset=\"3\"");
    assert_eq!(findings(&text), [("E316", "3")]);
    let bit = "<Ref DataType=\"BitArea\" ByteOffset=\"3\" BitOffset=\"6\" BitLength=\"3\" DefaultValue=\"0\" TextId=\"T_PARAM\"/>";
    let text = edit(
        "</ParameterRecordDataItem>",
        &format!("{bit}</ParameterRecordDataItem>"),
    );
    assert_eq!(findings(&text), [("E316", "3")]);
}

#[test]
fn e317_default_values_are_allowed_values() {
    let text = edit("DefaultValue=\"1\"", "DefaultValue=\"15\"");
    assert_eq!(findings(&text), [("E317", "15")]);
    let text = edit(
        "DefaultValue=\"3\" AllowedValues=\"0..25\"",
        "DefaultValue=\"-1\"",
    );
    assert_eq!(findings(&text), [("E317", "-1")]);
}

#[test]
fn e318_ident_numbers_are_hex() {
    let text = edit("VendorID=\"0x0493\"", "VendorID=\"0x10493\"");
    assert_eq!(findings(&text), [("E318", "0x10493")]);
    let text = edit("DeviceID=\"0x0002\"", "DeviceID=\"0x0\"");
    assert_eq!(findings(&text), [("E318", "0x0")]);
}

#[test]
fn e319_required_attributes_depend_on_the_declared_version() {
    let text = edit(" PNIO_Version=\"V2.43\"", "");
    assert_eq!(findings(&text), [("E319", "DeviceAccessPointItem")]);
    // V2.25 files may lack PNIO_Version (the corpus's V2.25 file does) ...
    let old = edit_text(&minimal_v2_25(), " PNIO_Version=\"V2.43\"", "");
    assert_eq!(
        findings_named(&old, "GSDML-V2.25-Acme-Drive-20240101.xml"),
        []
    );
    // ... but no version lets a module go without its ident number.
    let old = edit_text(&old, " ModuleIdentNumber=\"0x00000010\"", "");
    assert_eq!(
        findings_named(&old, "GSDML-V2.25-Acme-Drive-20240101.xml"),
        [("E319", "ModuleItem")]
    );
}

#[test]
fn e320_values_have_their_syntax() {
    let text = edit("PhysicalSlots=\"0..1\"", "PhysicalSlots=\"0-1\"");
    assert_eq!(findings(&text), [("E320", "0-1")]);
    let text = edit(
        "<ParameterRecordDataItem Index=\"1\"",
        "<ParameterRecordDataItem Index=\"40000\"",
    );
    assert_eq!(findings(&text), [("E320", "40000")]);
}

#[test]
fn huge_numbers_are_findings_not_overflows() {
    let text = edit("ByteOffset=\"2\"", "ByteOffset=\"4294967295\"");
    assert_eq!(findings(&text), [("E316", "4294967295")]);
    let text = edit(
        "<Ref DataType=\"Unsigned16\" ByteOffset=\"2\"",
        "<Ref DataType=\"BitArea\" BitOffset=\"4294967295\" BitLength=\"15\" ByteOffset=\"2\"",
    );
    let codes: Vec<&str> = findings(&text).iter().map(|f| f.0).collect();
    assert_eq!(codes, ["E320", "E316"]);
    let text = edit("AllowedInSlots=\"1\"", "AllowedInSlots=\"0..4294967295\"");
    // Only the physical slots 0..1 count for the IO data.
    assert_eq!(findings(&text), [("E312", "0..4294967295")]);
}

/// E321 on a PROFIsafe submodule whose data does not fit its F-parameters,
/// shown on ABB's FENA (its PS1 module, lines 494 to 610), which keeps to
/// the rule as every PROFIsafe submodule of the corpus does: its output's
/// trailer replaced by an Unsigned8, its F_CRC_Length made a 4-Byte-CRC
/// (which takes the 5-byte trailer), and its F-parameter record left out.
#[test]
fn profisafe_data_must_end_with_the_trailer_its_crc_takes() {
    let name = "GSDML-V2.33-ABB-FENA-20170914.xml";
    let fena = String::from_utf8(support::corpus_file(&format!("gsdml/{name}"))).unwrap();
    let e321 = |text: &str| -> Vec<String> {
        check(text, Some(name))
            .iter()
            .filter(|d| d.code == "E321")
            .map(|d| d.message.clone())
            .collect()
    };
    assert_eq!(e321(&fena), Vec::<String>::new());
    let trailer = "<DataItem DataType=\"F_MessageTrailer4Byte\" TextId=\"T_ID_SAFETY_DATA_TRAILER\"/>\n                                </Output>";
    assert!(fena.contains(trailer));
    let no_trailer = fena.replacen(
        trailer,
        "<DataItem DataType=\"Unsigned8\" TextId=\"T_ID_SAFETY_DATA_TRAILER\"/>\n                                </Output>",
        1,
    );
    assert_eq!(
        e321(&no_trailer),
        ["VirtualSubmoduleItem \"ID_SUBMOD_SAFETY_ABB_PS1\" supports PROFIsafe, but its Output does not end with the one F_MessageTrailer4Byte its F_CRC_Length 3-Byte-CRC takes"]
    );
    let crc_4 = fena.replacen(
        "<F_CRC_Length DefaultValue=\"3-Byte-CRC\"",
        "<F_CRC_Length DefaultValue=\"4-Byte-CRC\"",
        1,
    );
    assert_eq!(
        e321(&crc_4),
        ["VirtualSubmoduleItem \"ID_SUBMOD_SAFETY_ABB_PS1\" supports PROFIsafe, but its Input does not end with the one F_MessageTrailer5Byte its F_CRC_Length 4-Byte-CRC takes"]
    );
    let record_at = fena.find("<F_ParameterRecordDataItem").unwrap();
    let record_end = fena[record_at..]
        .find("</F_ParameterRecordDataItem>")
        .unwrap()
        + record_at
        + "</F_ParameterRecordDataItem>".len();
    let without = format!("{}{}", &fena[..record_at], &fena[record_end..]);
    assert_eq!(
        e321(&without),
        ["VirtualSubmoduleItem \"ID_SUBMOD_SAFETY_ABB_PS1\" supports PROFIsafe, but has no F_ParameterRecordDataItem"]
    );
}
