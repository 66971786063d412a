//! The GSDML emitter: IR to a PROFINET device description (XML, UTF-8).
//!
//! The file is written for the schema version the description names (2.32
//! by default): it validates against PI's V2.44 schema and uses nothing
//! introduced after its own version. Elements follow the schema's sequences,
//! and every ID and TextId is derived from the IR, so the same description
//! always gives the same bytes.

use crate::ir::mapping::MappingEntry;
use crate::ir::profinet::{
    Module, ModuleKind, ParameterRecord, Profinet, DAP_IDENT, FIRST_PORT_SUBSLOT,
    INTERFACE_SUBSLOT, MODULE_SLOT,
};
use crate::ir::{
    Allowed, BitField, Choice, Ir, MappingKind, MappingSet, PkwKind, Telegram, Text, Word,
};
use quick_xml::events::{BytesDecl, BytesEnd, BytesStart, BytesText, Event};
use quick_xml::Writer;

const NAMESPACE: &str = "http://www.profibus.com/GSDML/2003/11/DeviceProfile";
const XSI: &str = "http://www.w3.org/2001/XMLSchema-instance";
/// The DAP's ID; its submodule, interface and ports have `IDS_` IDs.
const DAP_ID: &str = "IDD_DAP";
/// TextIds of the device's name and description, shared by DeviceIdentity,
/// the DAP and its submodule.
const DEVICE_NAME: &str = "IDT_DEVICE_NAME";
const DEVICE_INFO: &str = "IDT_DEVICE_INFO";
/// 100BASE-TX full duplex (IEC 61158-6-10 MAUType 16): the card's RJ45 ports.
const MAU_100BASE_TX: &str = "16";
/// I&M1..3 are writable; I&M0 and I&M5 are read-only and may never be listed.
const WRITEABLE_IM_RECORDS: &str = "1 2 3";
const CONSISTENCY: &str = "All items consistency";

/// The GSDML text of a description with a PROFINET part.
pub fn emit(ir: &Ir, profinet: &Profinet) -> String {
    let mut doc = Doc::new();
    header(&mut doc, ir, profinet);
    let location = format!(
        "{NAMESPACE} ..\\xsd\\GSDML-DeviceProfile-V{}.xsd",
        profinet.gsdml_version
    );
    doc.open(
        "ISO15745Profile",
        &[
            ("xmlns", NAMESPACE),
            ("xmlns:xsi", XSI),
            ("xsi:schemaLocation", &location),
        ],
    );
    profile_header(&mut doc);
    doc.open("ProfileBody", &[]);
    device_identity(&mut doc, ir, profinet);
    doc.open("ApplicationProcess", &[]);
    device_access_point(&mut doc, ir, profinet);
    module_list(&mut doc, ir, profinet);
    value_list(&mut doc, ir, profinet);
    external_texts(&mut doc);
    doc.close("ApplicationProcess");
    doc.close("ProfileBody");
    doc.close("ISO15745Profile");
    doc.finish()
}

/// The XML writer and the texts referenced so far, which go into the
/// ExternalTextList at the end.
struct Doc {
    xml: Writer<Vec<u8>>,
    /// TextId and text, in the order first referenced.
    texts: Vec<(String, Text)>,
}

impl Doc {
    fn new() -> Self {
        let mut doc = Doc {
            xml: Writer::new_with_indent(Vec::new(), b' ', 2),
            texts: Vec::new(),
        };
        doc.write(Event::Decl(BytesDecl::new("1.0", Some("utf-8"), None)));
        doc
    }

    fn open(&mut self, name: &str, attributes: &[(&str, &str)]) {
        self.write(Event::Start(
            BytesStart::new(name).with_attributes(attributes.iter().copied()),
        ));
    }

    fn leaf(&mut self, name: &str, attributes: &[(&str, &str)]) {
        self.write(Event::Empty(
            BytesStart::new(name).with_attributes(attributes.iter().copied()),
        ));
    }

    fn close(&mut self, name: &str) {
        self.write(Event::End(BytesEnd::new(name)));
    }

    fn element_text(&mut self, name: &str, text: &str) {
        self.open(name, &[]);
        self.write(Event::Text(BytesText::new(text)));
        self.close(name);
    }

    /// `--` may not occur inside an XML comment, and names from the
    /// description could contain it; a run of hyphens needs more than one pass.
    fn comment(&mut self, text: &str) {
        let mut safe = text.to_string();
        while safe.contains("--") {
            safe = safe.replace("--", "- -");
        }
        self.write(Event::Comment(BytesText::from_escaped(format!(" {safe} "))));
    }

    /// Registers `text` under `id`; the ID scheme gives each TextId one text.
    fn text(&mut self, id: &str, text: &Text) {
        match self.texts.iter().find(|(known, _)| known == id) {
            Some((_, known)) => debug_assert_eq!(known, text, "TextId {id} names two texts"),
            None => self.texts.push((id.to_string(), text.clone())),
        }
    }

    /// `<element TextId="id"/>`, registering the text.
    fn text_ref(&mut self, element: &str, id: &str, text: &Text) {
        self.text(id, text);
        self.leaf(element, &[("TextId", id)]);
    }

    fn write(&mut self, event: Event) {
        self.xml
            .write_event(event)
            .expect("writing to memory cannot fail");
    }

    fn finish(self) -> String {
        let mut text = String::from_utf8(self.xml.into_inner())
            .expect("quick-xml writes the UTF-8 it is given");
        text.push('\n');
        text
    }
}

/// A text the description does not translate: the other languages repeat it.
fn english(text: impl Into<String>) -> Text {
    Text {
        en: text.into(),
        zh: None,
    }
}

fn hex16(value: u16) -> String {
    format!("0x{value:04X}")
}

fn hex32(value: u32) -> String {
    format!("0x{value:08X}")
}

fn header(doc: &mut Doc, ir: &Ir, p: &Profinet) {
    let d = &ir.device;
    doc.comment(&format!(
        "{}: PROFINET device description of {} {}",
        p.file_name, d.vendor, d.model
    ));
    doc.comment(&format!(
        "@generated by {} from {}; do not edit by hand.",
        crate::GENERATOR,
        ir.source_name
    ));
    doc.comment(&format!("Description fingerprint: {}", ir.fingerprint));
    let placeholders: Vec<String> = [
        ("VendorID", p.vendor_id, p.vendor_id_placeholder),
        ("DeviceID", p.device_id, p.device_id_placeholder),
    ]
    .into_iter()
    .filter(|&(_, _, placeholder)| placeholder)
    .map(|(name, value, _)| format!("{name} {}", hex16(value)))
    .collect();
    match placeholders.as_slice() {
        [] => {}
        [one] => doc.comment(&format!("{one} is a placeholder, not assigned by PI.")),
        many => doc.comment(&format!(
            "{} are placeholders, not assigned by PI.",
            many.join(" and ")
        )),
    }
}

/// PI's fixed header: every GSDML file carries it unchanged.
fn profile_header(doc: &mut Doc) {
    doc.open("ProfileHeader", &[]);
    doc.element_text("ProfileIdentification", "PROFINET Device Profile");
    doc.element_text("ProfileRevision", "1.00");
    doc.element_text("ProfileName", "Device Profile for PROFINET Devices");
    doc.element_text("ProfileSource", "PROFIBUS Nutzerorganisation e. V. (PNO)");
    doc.element_text("ProfileClassID", "Device");
    doc.open("ISO15745Reference", &[]);
    doc.element_text("ISO15745Part", "4");
    doc.element_text("ISO15745Edition", "1");
    doc.element_text("ProfileTechnology", "GSDML");
    doc.close("ISO15745Reference");
    doc.close("ProfileHeader");
}

/// The PROFINET part's own info text, else the device's, else its name.
fn device_info<'a>(ir: &'a Ir, p: &'a Profinet) -> &'a Text {
    p.info
        .as_ref()
        .or(ir.device.info.as_ref())
        .unwrap_or(&ir.device.name)
}

fn device_identity(doc: &mut Doc, ir: &Ir, p: &Profinet) {
    doc.open(
        "DeviceIdentity",
        &[
            ("VendorID", &hex16(p.vendor_id)),
            ("DeviceID", &hex16(p.device_id)),
        ],
    );
    doc.text_ref("InfoText", DEVICE_INFO, device_info(ir, p));
    doc.leaf("VendorName", &[("Value", &ir.device.vendor)]);
    doc.close("DeviceIdentity");
    doc.open("DeviceFunction", &[]);
    doc.leaf(
        "Family",
        &[
            ("MainFamily", "Drives"),
            ("ProductFamily", &ir.device.family),
        ],
    );
    doc.close("DeviceFunction");
}

/// The one DAP: slot 0, with slot 1 for one module.
fn device_access_point(doc: &mut Doc, ir: &Ir, p: &Profinet) {
    doc.open("DeviceAccessPointList", &[]);
    doc.open(
        "DeviceAccessPointItem",
        &[
            ("ID", DAP_ID),
            ("PNIO_Version", &format!("V{}", p.gsdml_version)),
            ("PhysicalSlots", &format!("0..{MODULE_SLOT}")),
            ("ModuleIdentNumber", &hex32(DAP_IDENT)),
            ("MinDeviceInterval", &p.min_device_interval.to_string()),
            ("DNS_CompatibleName", &p.dns_name),
            ("FixedInSlots", "0"),
            ("ObjectUUID_LocalIndex", "1"),
            ("NameOfStationNotTransferable", "false"),
            ("DeviceAccessSupported", "false"),
            ("CheckDeviceID_Allowed", "true"),
            // A device of PNIO_Version V2.31 or later must support multiple
            // write, LLDP name of device and reset to factory mode 2 (reset
            // communication parameters); every such file in the corpus says so.
            ("MultipleWriteSupported", "true"),
            ("LLDP_NoD_Supported", "true"),
            ("ResetToFactoryModes", "2"),
        ],
    );
    let d = &ir.device;
    let mut values = vec![("VendorName", d.vendor.as_str())];
    values.extend(d.order_number.as_deref().map(|o| ("OrderNumber", o)));
    values.extend([
        ("HardwareRelease", d.hardware_release.as_str()),
        ("SoftwareRelease", d.software_release.as_str()),
    ]);
    module_info(
        doc,
        (DEVICE_NAME, &d.name),
        (DEVICE_INFO, device_info(ir, p)),
        &values,
    );
    // Conformance class B: RT_CLASS_1 with SNMP and LLDP (see the interface
    // below); netload class I is the lowest.
    doc.leaf(
        "CertificationInfo",
        &[("ConformanceClass", "B"), ("NetloadClass", "I")],
    );
    let max_length = max_io_length(p).to_string();
    doc.leaf(
        "IOConfigData",
        &[
            ("MaxInputLength", &max_length),
            ("MaxOutputLength", &max_length),
        ],
    );
    doc.open("UseableModules", &[]);
    let slot = MODULE_SLOT.to_string();
    for m in &p.modules {
        doc.leaf(
            "ModuleItemRef",
            &[
                ("ModuleItemTarget", &format!("IDM_{}", module_tag(m))),
                ("AllowedInSlots", &slot),
            ],
        );
    }
    doc.close("UseableModules");
    dap_submodule(doc, ir, p);
    interface_and_ports(doc, p);
    doc.close("DeviceAccessPointItem");
    doc.close("DeviceAccessPointList");
}

/// MaxInputLength and MaxOutputLength bound what the input and the output
/// CR carry: IO data and status bytes, as the checker reads them (E310,
/// `gsdml::io`; docs/rules.md gives the sources). Each submodule without
/// data (the DAP's, the interface, the ports) has its IOPS in the input CR
/// and its IOCS in the output CR: one byte each way; the module's, with data
/// both ways, adds its IOPS and the IOCS of the other direction to each.
/// The largest module with these is exactly what the checker needs
/// (`tests/gsdml_reader.rs` holds the two to it); with at most 20 words in a
/// module and 16 ports it stays far below the limit of 1440.
fn max_io_length(p: &Profinet) -> u16 {
    let data = p
        .modules
        .iter()
        .map(|m| m.layout.bytes())
        .max()
        .unwrap_or(0);
    let without_data = 2 + u16::from(p.ports);
    data + without_data + 2
}

/// Name, InfoText and then any `Value` elements, in the schema's order.
fn module_info(doc: &mut Doc, name: (&str, &Text), info: (&str, &Text), values: &[(&str, &str)]) {
    doc.open("ModuleInfo", &[]);
    doc.text_ref("Name", name.0, name.1);
    doc.text_ref("InfoText", info.0, info.1);
    for (element, value) in values {
        doc.leaf(element, &[("Value", value)]);
    }
    doc.close("ModuleInfo");
}

/// The DAP's own submodule: no IO data and no records.
fn dap_submodule(doc: &mut Doc, ir: &Ir, p: &Profinet) {
    doc.open("VirtualSubmoduleList", &[]);
    doc.open(
        "VirtualSubmoduleItem",
        &[
            ("ID", "IDS_DAP"),
            ("SubmoduleIdentNumber", &hex32(DAP_IDENT)),
            ("Writeable_IM_Records", WRITEABLE_IM_RECORDS),
            ("MayIssueProcessAlarm", "false"),
        ],
    );
    doc.leaf("IOData", &[]);
    module_info(
        doc,
        (DEVICE_NAME, &ir.device.name),
        (DEVICE_INFO, device_info(ir, p)),
        &[],
    );
    doc.close("VirtualSubmoduleItem");
    doc.close("VirtualSubmoduleList");
}

/// The interface at 0x8000 and its ports from 0x8001. Their submodule ident
/// numbers are their subslot numbers, the convention p-net also follows.
/// DCP_HelloSupported stays off: it would need PowerOnToCommReady, which the
/// description does not give.
fn interface_and_ports(doc: &mut Doc, p: &Profinet) {
    doc.open("SystemDefinedSubmoduleList", &[]);
    doc.text("IDT_INTERFACE", &english("PN-IO"));
    doc.open(
        "InterfaceSubmoduleItem",
        &[
            ("ID", "IDS_INTERFACE"),
            ("SubslotNumber", &INTERFACE_SUBSLOT.to_string()),
            ("SubmoduleIdentNumber", &hex32(INTERFACE_SUBSLOT.into())),
            ("TextId", "IDT_INTERFACE"),
            ("SupportedRT_Classes", "RT_CLASS_1"),
            ("SupportedProtocols", "SNMP;LLDP"),
        ],
    );
    // Both startup modes, or controllers that start up the legacy way
    // (older firmware) find no mode they share with the device.
    doc.open(
        "ApplicationRelations",
        &[("StartupMode", "Legacy;Advanced")],
    );
    doc.leaf(
        "TimingProperties",
        &[
            ("SendClock", "32"),
            ("ReductionRatio", "1 2 4 8 16 32 64 128 256 512"),
        ],
    );
    doc.close("ApplicationRelations");
    doc.close("InterfaceSubmoduleItem");
    for port in 1..=p.ports {
        let subslot = FIRST_PORT_SUBSLOT + u16::from(port) - 1;
        let text_id = format!("IDT_PORT_{port}");
        doc.text(&text_id, &english(format!("Port {port}")));
        doc.open(
            "PortSubmoduleItem",
            &[
                ("ID", &format!("IDS_PORT_{port}")),
                ("SubslotNumber", &subslot.to_string()),
                ("SubmoduleIdentNumber", &hex32(subslot.into())),
                ("TextId", &text_id),
            ],
        );
        doc.open("MAUTypeList", &[]);
        doc.leaf("MAUTypeItem", &[("Value", MAU_100BASE_TX)]);
        doc.close("MAUTypeList");
        doc.close("PortSubmoduleItem");
    }
    doc.close("SystemDefinedSubmoduleList");
}

/// One Unsigned16 Ref per entry of the record's sets, at offsets 0, 2, 4, ...
fn parameter_record(doc: &mut Doc, ir: &Ir, record: &ParameterRecord) {
    let entries: Vec<(&MappingSet, &MappingEntry)> = record
        .sets
        .iter()
        .map(|&i| &ir.mappings[i])
        .flat_map(|set| set.entries.iter().map(move |entry| (set, entry)))
        .collect();
    doc.open(
        "ParameterRecordDataItem",
        &[
            ("Index", &record.index.to_string()),
            ("Length", &(2 * entries.len()).to_string()),
        ],
    );
    let kind = record.sets.first().map(|&i| ir.mappings[i].kind);
    doc.text_ref(
        "Name",
        &format!("IDT_RECORD_{}", record.index),
        &english(record_name(kind)),
    );
    for (i, (set, entry)) in entries.into_iter().enumerate() {
        let text_id = entry_text_id(set, entry);
        doc.text(&text_id, &entry.name);
        let offset = (2 * i).to_string();
        let default = entry.default.to_string();
        let allowed = allowed_values(&set.allowed);
        let value_item =
            matches!(set.allowed, Allowed::Choices(_)).then(|| format!("IDV_{}", value_tag(set)));
        let mut attributes = vec![
            ("DataType", "Unsigned16"),
            ("ByteOffset", offset.as_str()),
            ("DefaultValue", default.as_str()),
            ("AllowedValues", allowed.as_str()),
        ];
        attributes.extend(value_item.as_deref().map(|v| ("ValueItemTarget", v)));
        attributes.extend([
            ("Changeable", "true"),
            ("Visible", "true"),
            ("TextId", text_id.as_str()),
        ]);
        doc.leaf("Ref", &attributes);
    }
    doc.close("ParameterRecordDataItem");
}

/// Lowering puts one kind of mapping in each record.
fn record_name(kind: Option<MappingKind>) -> &'static str {
    match kind {
        Some(MappingKind::PzdOut) => "PZD output mapping (controller to drive)",
        Some(MappingKind::PzdIn) => "PZD input mapping (drive to controller)",
        Some(MappingKind::Dpv1Index) => "Record index mapping",
        Some(MappingKind::Setting) | None => "Drive settings",
    }
}

fn kind_tag(kind: MappingKind) -> String {
    kind.key().to_uppercase()
}

/// A Ref's TextId: `IDT_PZD_OUT_2`, `IDT_SETTINGS_1`.
fn entry_text_id(set: &MappingSet, entry: &MappingEntry) -> String {
    format!("IDT_{}_{}", kind_tag(set.kind), entry.number)
}

/// Names a set of choices in its ValueItem's ID and TextIds: its kind, and
/// for a setting (each is a set of one entry) its number too.
fn value_tag(set: &MappingSet) -> String {
    match (set.kind, set.entries.first()) {
        (MappingKind::Setting, Some(entry)) => format!("{}_{}", kind_tag(set.kind), entry.number),
        (kind, _) => kind_tag(kind),
    }
}

/// GSDML's value list: `min..max` runs and single values, e.g. "0..14" or
/// "0..3 6 9..10".
fn allowed_values(allowed: &Allowed) -> String {
    let run = |first: i64, last: i64| {
        if first == last {
            first.to_string()
        } else {
            format!("{first}..{last}")
        }
    };
    match allowed {
        Allowed::Range { min, max } => run((*min).into(), (*max).into()),
        Allowed::Choices(choices) => {
            let mut values: Vec<i64> = choices.iter().map(|c| c.value).collect();
            values.sort_unstable();
            let mut runs: Vec<(i64, i64)> = Vec::new();
            for value in values {
                match runs.last_mut() {
                    Some((_, last)) if *last + 1 == value => *last = value,
                    _ => runs.push((value, value)),
                }
            }
            runs.into_iter()
                .map(|(first, last)| run(first, last))
                .collect::<Vec<_>>()
                .join(" ")
        }
    }
}

/// IDs and TextIds of a module: `PKW_12` (PKW and 12 PZD words), `PZD_12`,
/// `STD_TEL_1`. Lowering gives each PZD length once per PKW choice.
fn module_tag(m: &Module) -> String {
    match m.kind {
        ModuleKind::StandardTelegram1 => "STD_TEL_1".into(),
        ModuleKind::Pzd if m.layout.pkw => format!("PKW_{}", m.layout.pzd_words),
        ModuleKind::Pzd => format!("PZD_{}", m.layout.pzd_words),
    }
}

fn module_list(doc: &mut Doc, ir: &Ir, p: &Profinet) {
    doc.open("ModuleList", &[]);
    for m in &p.modules {
        module(doc, ir, p, m);
    }
    doc.close("ModuleList");
}

/// A module with one submodule of the same ident number in API 0: the
/// firmware does not implement the PROFIdrive profile, so not its API even
/// for standard telegram 1.
///
/// The user-defined (PZD) modules carry the parameter records, so the
/// controller writes the mappings and settings when it plugs one of them;
/// standard telegram 1 has fixed meanings and carries none (the firmware
/// selects the standard telegram itself, e.g. MV810's P43.01 = 0).
fn module(doc: &mut Doc, ir: &Ir, p: &Profinet, m: &Module) {
    let telegram = &ir.telegram;
    let tag = module_tag(m);
    let ident = hex32(m.ident);
    let (name_id, info_id) = (
        format!("IDT_MODULE_{tag}"),
        format!("IDT_MODULE_INFO_{tag}"),
    );
    let (name, info) = (english(m.name.as_str()), english(module_description(m)));
    doc.open(
        "ModuleItem",
        &[("ID", &format!("IDM_{tag}")), ("ModuleIdentNumber", &ident)],
    );
    module_info(doc, (&name_id, &name), (&info_id, &info), &[]);
    doc.open("VirtualSubmoduleList", &[]);
    doc.open(
        "VirtualSubmoduleItem",
        &[
            ("ID", &format!("IDS_{tag}")),
            ("SubmoduleIdentNumber", &ident),
            ("API", "0"),
            ("MayIssueProcessAlarm", "false"),
        ],
    );
    doc.open("IOData", &[]);
    for direction in [Direction::Input, Direction::Output] {
        doc.open(direction.element(), &[("Consistency", CONSISTENCY)]);
        for item in data_items(telegram, m, direction) {
            data_item(doc, &item);
        }
        doc.close(direction.element());
    }
    doc.close("IOData");
    if m.kind == ModuleKind::Pzd && !p.records.is_empty() {
        doc.open("RecordDataList", &[]);
        for record in &p.records {
            parameter_record(doc, ir, record);
        }
        doc.close("RecordDataList");
    }
    module_info(doc, (&name_id, &name), (&info_id, &info), &[]);
    doc.close("VirtualSubmoduleItem");
    doc.close("VirtualSubmoduleList");
    doc.close("ModuleItem");
}

fn module_description(m: &Module) -> String {
    let bytes = m.layout.bytes();
    match m.kind {
        ModuleKind::StandardTelegram1 => {
            format!("Standard telegram 1: STW1 and NSOLL_A to the drive, ZSW1 and NIST_A from it; {bytes} bytes each way")
        }
        ModuleKind::Pzd => {
            let pkw = match m.layout.pkw_words() {
                0 => String::new(),
                n => format!("PKW channel ({n} words) and "),
            };
            let words = match m.layout.pzd_words {
                1 => "1 PZD word".to_string(),
                n => format!("{n} PZD words"),
            };
            format!("{pkw}{words}; {bytes} bytes each way")
        }
    }
}

/// Input: drive to controller. Output: controller to drive.
#[derive(Clone, Copy)]
enum Direction {
    Input,
    Output,
}

impl Direction {
    fn element(self) -> &'static str {
        match self {
            Direction::Input => "Input",
            Direction::Output => "Output",
        }
    }

    /// The word PZD1 carries this way, if it has named bits, with the tag
    /// its TextIds use.
    fn word(self, telegram: &Telegram) -> Option<(&Word, &'static str)> {
        match self {
            Direction::Input => telegram.status_word.as_ref().map(|w| (w, "STATUS")),
            Direction::Output => telegram.control_word.as_ref().map(|w| (w, "CONTROL")),
        }
    }

    /// Standard telegram 1's two words: TextId tag and text.
    fn standard_telegram_1(self) -> [(&'static str, &'static str); 2] {
        match self {
            Direction::Input => [
                ("ZSW1", "ZSW1 (status word 1)"),
                ("NIST_A", "NIST_A (speed actual value)"),
            ],
            Direction::Output => [
                ("STW1", "STW1 (control word 1)"),
                ("NSOLL_A", "NSOLL_A (speed setpoint)"),
            ],
        }
    }
}

/// One Unsigned16 DataItem; a word with named bits shows them.
struct DataItem<'a> {
    text_id: String,
    text: Text,
    bits: Option<(&'a Word, &'static str)>,
}

impl DataItem<'_> {
    fn plain(tag: &str, text: &str) -> Self {
        DataItem {
            text_id: format!("IDT_{tag}"),
            text: english(text),
            bits: None,
        }
    }
}

/// The module's words one way, in telegram order: the PKW channel, then
/// PZD1..PZDn.
fn data_items<'a>(telegram: &'a Telegram, m: &Module, direction: Direction) -> Vec<DataItem<'a>> {
    if m.kind == ModuleKind::StandardTelegram1 {
        return direction
            .standard_telegram_1()
            .iter()
            .map(|(tag, text)| DataItem::plain(tag, text))
            .collect();
    }
    let pkw = if m.layout.pkw {
        pkw_words(telegram.pkw)
    } else {
        &[]
    };
    let pkw = pkw
        .iter()
        .map(|(tag, text)| DataItem::plain(&format!("PKW_{tag}"), text));
    let pzd = (1..=m.layout.pzd_words).map(|n| match direction.word(telegram) {
        Some((word, tag)) if n == 1 => DataItem {
            text_id: format!("IDT_{tag}_WORD"),
            text: word.name.clone(),
            bits: Some((word, tag)),
        },
        _ => DataItem::plain(&format!("PZD_{n}"), &format!("PZD{n}")),
    });
    pkw.chain(pzd).collect()
}

/// The PKW channel's words, the same both ways: TextId tag and text.
fn pkw_words(kind: PkwKind) -> &'static [(&'static str, &'static str)] {
    match kind {
        PkwKind::None => &[],
        PkwKind::PkeIndPwe => &[
            ("PKE", "PKE"),
            ("IND", "IND"),
            ("PWE_HIGH", "PWE high"),
            ("PWE_LOW", "PWE low"),
        ],
        PkwKind::StationCommandAddressValue => &[
            ("STATION", "Station"),
            ("COMMAND", "Command"),
            ("ADDRESS", "Address"),
            ("VALUE", "Value"),
        ],
    }
}

fn data_item(doc: &mut Doc, item: &DataItem) {
    doc.text(&item.text_id, &item.text);
    let Some((word, tag)) = item.bits else {
        doc.leaf(
            "DataItem",
            &[("DataType", "Unsigned16"), ("TextId", &item.text_id)],
        );
        return;
    };
    doc.open(
        "DataItem",
        &[
            ("DataType", "Unsigned16"),
            ("UseAsBits", "true"),
            ("TextId", &item.text_id),
        ],
    );
    for field in &word.bits {
        for bit in field.first..=field.last {
            let text_id = format!("IDT_{tag}_BIT_{bit}");
            let index = (field.last > field.first).then(|| bit - field.first);
            doc.text(&text_id, &bit_text(field, index));
            doc.leaf(
                "BitDataItem",
                &[("BitOffset", &bit.to_string()), ("TextId", &text_id)],
            );
        }
    }
    doc.close("DataItem");
}

/// A bit's name: the field's, with the bit's place in a field of several
/// bits, and the field's values when it has them, since a BitDataItem has
/// nothing else to show them with: "Control mode bit 0 (0 = Keypad, ...)".
fn bit_text(field: &BitField, index: Option<u8>) -> Text {
    let label = |chinese: bool| {
        let mut text = pick(&field.name, chinese).to_string();
        if let Some(index) = index {
            text.push_str(&format!(" bit {index}"));
        }
        if !field.values.is_empty() {
            let values: Vec<String> = field
                .values
                .iter()
                .map(|c| format!("{} = {}", c.value, pick(&c.text, chinese)))
                .collect();
            text.push_str(&format!(" ({})", values.join(", ")));
        }
        text
    };
    let translated = field.name.zh.is_some() || field.values.iter().any(|c| c.text.zh.is_some());
    Text {
        en: label(false),
        zh: translated.then(|| label(true)),
    }
}

fn pick(text: &Text, chinese: bool) -> &str {
    match (&text.zh, chinese) {
        (Some(zh), true) => zh,
        _ => &text.en,
    }
}

/// One ValueItem per set of choices a record refers to.
fn value_list(doc: &mut Doc, ir: &Ir, p: &Profinet) {
    let sets: Vec<(String, &[Choice])> = p
        .records
        .iter()
        .flat_map(|r| &r.sets)
        .map(|&i| &ir.mappings[i])
        .filter_map(|set| match &set.allowed {
            Allowed::Choices(choices) => Some((value_tag(set), choices.as_slice())),
            Allowed::Range { .. } => None,
        })
        .collect();
    if sets.is_empty() {
        return;
    }
    doc.open("ValueList", &[]);
    for (tag, choices) in sets {
        doc.open("ValueItem", &[("ID", &format!("IDV_{tag}"))]);
        doc.open("Assignments", &[]);
        for choice in choices {
            let text_id = format!("IDT_{tag}_VALUE_{}", choice.value);
            doc.text(&text_id, &choice.text);
            doc.leaf(
                "Assign",
                &[("Content", &choice.value.to_string()), ("TextId", &text_id)],
            );
        }
        doc.close("Assignments");
        doc.close("ValueItem");
    }
    doc.close("ValueList");
}

/// English first; Chinese when the description has any, with every TextId
/// in both (English where a text has no translation).
fn external_texts(doc: &mut Doc) {
    let texts = std::mem::take(&mut doc.texts);
    doc.open("ExternalTextList", &[]);
    language(doc, "PrimaryLanguage", &[], &texts, false);
    if texts.iter().any(|(_, text)| text.zh.is_some()) {
        language(doc, "Language", &[("xml:lang", "zh")], &texts, true);
    }
    doc.close("ExternalTextList");
}

fn language(
    doc: &mut Doc,
    element: &str,
    attributes: &[(&str, &str)],
    texts: &[(String, Text)],
    chinese: bool,
) {
    doc.open(element, attributes);
    for (id, text) in texts {
        doc.leaf("Text", &[("TextId", id), ("Value", pick(text, chinese))]);
    }
    doc.close(element);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn choices(values: &[i64]) -> Allowed {
        Allowed::Choices(
            values
                .iter()
                .map(|&value| Choice {
                    value,
                    text: english(""),
                })
                .collect(),
        )
    }

    #[test]
    fn allowed_values_are_runs_and_single_values() {
        assert_eq!(
            allowed_values(&Allowed::Range { min: 0, max: 65535 }),
            "0..65535"
        );
        assert_eq!(allowed_values(&Allowed::Range { min: 7, max: 7 }), "7");
        assert_eq!(allowed_values(&choices(&[2, 0, 1])), "0..2");
        assert_eq!(allowed_values(&choices(&[0, 5, 9, 10, 1])), "0..1 5 9..10");
        assert_eq!(allowed_values(&choices(&[3])), "3");
    }

    #[test]
    fn a_comment_never_contains_a_double_hyphen() {
        let mut doc = Doc::new();
        doc.comment("from a--b---c.toml");
        let text = doc.finish();
        assert!(text.contains("<!-- from a- -b- - -c.toml -->"), "{text}");
    }

    #[test]
    fn bits_of_a_field_name_their_place_and_values() {
        let field = BitField {
            first: 9,
            last: 10,
            name: Text {
                en: "Control mode".into(),
                zh: Some("控制方式".into()),
            },
            values: vec![Choice {
                value: 0,
                text: english("Keypad"),
            }],
        };
        let text = bit_text(&field, Some(1));
        assert_eq!(text.en, "Control mode bit 1 (0 = Keypad)");
        assert_eq!(text.zh.as_deref(), Some("控制方式 bit 1 (0 = Keypad)"));
    }
}
