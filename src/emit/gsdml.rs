//! The GSDML emitter: IR to a PROFINET device description (XML, UTF-8).
//!
//! The file is written for the schema version the description names (2.32
//! by default): it validates against PI's V2.44 schema and uses nothing
//! introduced after its own version. Elements follow the schema's sequences;
//! every ID and TextId comes from the IR, so the same description always
//! gives the same bytes.

use super::{hex16, hex32};
use crate::gsdml::NAMESPACE;
use crate::ir::profinet::{
    BitItem, ConformanceClass, Dap, DataItem, EmptyModule, ExtendedDiagnosis, Irt, Isochronous,
    Module, NetloadClass, ParameterRecord, ProfiEnergy, Profinet, RecordValue, RecordValueType,
    Stack, SubmoduleRecord, TextRef, ValueItem, ACCESS_POINT_SUBSLOT, INTERFACE_SUBSLOT,
    PROFIDRIVE_DATA_SUBSLOT,
};
use crate::ir::safety::SafetyModule;
use crate::ir::{Allowed, Ir, Text};
use quick_xml::events::attributes::Attribute;
use quick_xml::events::{BytesDecl, BytesEnd, BytesStart, BytesText, Event};
use quick_xml::name::QName;
use quick_xml::Writer;
use std::collections::HashMap;

const XSI: &str = "http://www.w3.org/2001/XMLSchema-instance";
/// 100BASE-TX full duplex (IEC 61158-6-10 MAUType 16): the card's RJ45 ports.
const MAU_100BASE_TX: &str = "16";
const CONSISTENCY: &str = "All items consistency";

/// The GSDML text of a description with a PROFINET part.
pub fn emit(ir: &Ir, profinet: &Profinet) -> String {
    let mut doc = Doc::new();
    header(&mut doc, ir, profinet);
    let location = format!(
        "{NAMESPACE} ..\\xsd\\GSDML-DeviceProfile-{}.xsd",
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
    doc.open("DeviceAccessPointList", &[]);
    for dap in &profinet.daps {
        device_access_point(&mut doc, ir, profinet, dap);
    }
    doc.close("DeviceAccessPointList");
    module_list(&mut doc, ir, profinet);
    value_list(&mut doc, profinet);
    channel_diag_list(&mut doc, profinet);
    if let Some(symbol) = &profinet.device_symbol {
        doc.open("GraphicsList", &[]);
        doc.leaf(
            "GraphicItem",
            &[("ID", &symbol.id), ("GraphicFile", &symbol.file)],
        );
        doc.close("GraphicsList");
    }
    category_list(&mut doc, profinet);
    external_texts(&mut doc, &ir.languages);
    doc.close("ApplicationProcess");
    doc.close("ProfileBody");
    doc.close("ISO15745Profile");
    doc.finish()
}

/// An element's start with its attributes, each value escaped. A line
/// break (a diagnosis text's) is written `&#10;`: a reader turns one
/// written as it is into a blank (XML 1.0, 3.3.3, attribute-value
/// normalization).
fn element<'a>(name: &'a str, attributes: &[(&str, &str)]) -> BytesStart<'a> {
    let mut start = BytesStart::new(name);
    for (key, value) in attributes {
        let escaped = quick_xml::escape::escape(*value).replace('\n', "&#10;");
        start.push_attribute(Attribute {
            key: QName(key.as_bytes()),
            value: escaped.into_bytes().into(),
        });
    }
    start
}

/// The XML writer and the texts referenced so far, which go into the
/// ExternalTextList at the end.
struct Doc {
    xml: Writer<Vec<u8>>,
    /// TextId and text, in the order first referenced.
    texts: Vec<(String, Text)>,
    /// Each TextId's place in `texts`: a large file references thousands,
    /// and searching the list for each made writing one quadratic. Only
    /// looked up, never iterated, so the output keeps the list's order.
    text_places: HashMap<String, usize>,
}

impl Doc {
    fn new() -> Self {
        let mut doc = Doc {
            xml: Writer::new_with_indent(Vec::new(), b' ', 2),
            texts: Vec::new(),
            text_places: HashMap::new(),
        };
        doc.write(Event::Decl(BytesDecl::new("1.0", Some("utf-8"), None)));
        doc
    }

    fn open(&mut self, name: &str, attributes: &[(&str, &str)]) {
        self.write(Event::Start(element(name, attributes)));
    }

    fn leaf(&mut self, name: &str, attributes: &[(&str, &str)]) {
        self.write(Event::Empty(element(name, attributes)));
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

    /// Registers a text for the ExternalTextList, in the order first
    /// referenced; lowering gives each TextId one text.
    fn text(&mut self, text: &TextRef) {
        match self.text_places.get(&text.id) {
            Some(&place) => {
                let known = &self.texts[place].1;
                debug_assert_eq!(*known, text.text, "TextId {} names two texts", text.id)
            }
            None => {
                self.text_places.insert(text.id.clone(), self.texts.len());
                self.texts.push((text.id.clone(), text.text.clone()));
            }
        }
    }

    /// `<element TextId="id"/>`, registering the text.
    fn text_ref(&mut self, element: &str, text: &TextRef) {
        self.text(text);
        self.leaf(element, &[("TextId", &text.id)]);
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
    for note in super::header_notes(ir, super::ArtifactKind::Gsdml) {
        doc.comment(&note);
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

fn device_identity(doc: &mut Doc, ir: &Ir, p: &Profinet) {
    doc.open(
        "DeviceIdentity",
        &[
            ("VendorID", &hex16(p.vendor_id)),
            ("DeviceID", &hex16(p.device_id)),
        ],
    );
    doc.text_ref("InfoText", &p.device_info);
    doc.leaf("VendorName", &[("Value", &ir.device.vendor)]);
    doc.close("DeviceIdentity");
    doc.open("DeviceFunction", &[]);
    doc.leaf(
        "Family",
        &[
            ("MainFamily", "Drives"),
            ("ProductFamily", &p.product_family),
        ],
    );
    doc.close("DeviceFunction");
}

/// A DAP: slot 0, with slot 1 for one of the modules it offers.
fn device_access_point(doc: &mut Doc, ir: &Ir, p: &Profinet, dap: &Dap) {
    let stack = &dap.stack;
    let flag = |on: bool| if on { "true" } else { "false" };
    let physical_slots = format!("0..{}", dap.last_slot);
    let ident = hex32(dap.ident);
    let interval = p.min_device_interval.to_string();
    let version = dap.pnio_version.to_string();
    let mut attributes = vec![
        ("ID", dap.id.as_str()),
        ("PNIO_Version", &version),
        ("PhysicalSlots", &physical_slots),
        ("ModuleIdentNumber", &ident),
        ("MinDeviceInterval", &interval),
        ("DNS_CompatibleName", &p.dns_name),
        ("FixedInSlots", "0"),
        ("ObjectUUID_LocalIndex", "1"),
        (
            "NameOfStationNotTransferable",
            flag(stack.name_of_station_not_transferable),
        ),
        ("DeviceAccessSupported", flag(stack.device_access)),
        ("CheckDeviceID_Allowed", "true"),
        // A device of PNIO_Version V2.31 or later must support multiple
        // write, LLDP name of device and reset to factory mode 2 (reset
        // communication parameters); every such file in the corpus says so.
        ("MultipleWriteSupported", "true"),
        ("LLDP_NoD_Supported", "true"),
        ("ResetToFactoryModes", "2"),
    ];
    let required = p.required_schema_version.map(|v| v.to_string());
    attributes.extend(required.as_deref().map(|v| ("RequiredSchemaVersion", v)));
    attributes.extend(
        p.implementation_type
            .as_deref()
            .map(|t| ("ImplementationType", t)),
    );
    let stated = stated_stack_attributes(stack);
    attributes.extend(stated.iter().map(|(name, value)| (*name, value.as_str())));
    if p.profienergy.as_ref().is_some_and(|e| e.ase) {
        attributes.push(("PROFIenergyASE_Supported", "true"));
    }
    doc.open("DeviceAccessPointItem", &attributes);
    let mut values = vec![("VendorName", ir.device.vendor.as_str())];
    values.extend(stated_values(&[
        ("OrderNumber", &dap.order_number),
        ("HardwareRelease", &dap.hardware_release),
        ("SoftwareRelease", &dap.software_release),
    ]));
    module_info(doc, &dap.name, &dap.info, &values);
    certification_info(doc, p, dap);
    subslot_list(doc, p, dap);
    let mut io = vec![
        ("MaxInputLength", dap.max_input_length.to_string()),
        ("MaxOutputLength", dap.max_output_length.to_string()),
    ];
    io.extend(
        dap.max_data_length
            .map(|n| ("MaxDataLength", n.to_string())),
    );
    doc.leaf("IOConfigData", &borrowed(&io));
    doc.open("UseableModules", &[]);
    let slots = p.module_slots.to_string();
    for m in dap.modules.iter().map(|&i| &p.modules[i]) {
        doc.leaf(
            "ModuleItemRef",
            &[("ModuleItemTarget", &m.id), ("AllowedInSlots", &slots)],
        );
    }
    if let Some(empty) = &p.empty_module {
        doc.leaf(
            "ModuleItemRef",
            &[
                ("ModuleItemTarget", EmptyModule::ID),
                ("AllowedInSlots", &empty.slots.to_string()),
            ],
        );
    }
    for m in dap.safety_modules.iter().map(|&i| &p.safety_modules[i]) {
        doc.leaf(
            "ModuleItemRef",
            &[
                ("ModuleItemTarget", &m.id),
                ("AllowedInSlots", &m.slots.to_string()),
            ],
        );
    }
    doc.close("UseableModules");
    dap_submodule(doc, p, dap);
    interface_and_ports(doc, p, dap);
    if let Some(symbol) = &p.device_symbol {
        doc.open("Graphics", &[]);
        doc.leaf(
            "GraphicItemRef",
            &[("Type", "DeviceSymbol"), ("GraphicItemTarget", &symbol.id)],
        );
        doc.close("Graphics");
    }
    doc.close("DeviceAccessPointItem");
}

/// The labels on the device of the interface and of this access point's
/// ports, when the description gives them (`SubslotList`, in GSDML since
/// V2.3, as PI's V2.3 stylesheet shows).
fn subslot_list(doc: &mut Doc, p: &Profinet, dap: &Dap) {
    let Some(labels) = &p.subslot_labels else {
        return;
    };
    let subslots =
        std::iter::once(INTERFACE_SUBSLOT).chain(dap.ports.iter().map(|port| port.subslot));
    let texts = std::iter::once(&labels.interface).chain(&labels.ports);
    doc.open("SubslotList", &[]);
    for (subslot, text) in subslots.zip(texts) {
        doc.text(text);
        let number = subslot.to_string();
        doc.leaf(
            "SubslotItem",
            &[("SubslotNumber", &number), ("TextId", &text.id)],
        );
    }
    doc.close("SubslotList");
}

/// The conformance class, the application classes (ApplicationClass is in
/// GSDML since V2.3, as PI's V2.3 stylesheet shows): the isochronous one
/// when the modules have isochronous mode and the energy saving one with
/// PROFIenergy (SEW's MOVI-C, whose modules have IsochroneMode and whose
/// access points PROFIenergy, declares `Isochronous;EnergySaving`), the
/// functional safety one where the access point offers a safety module and
/// the description does not say otherwise (ABB's FENA declares it, SEW's
/// MOVI-C does not), and the netload class.
fn certification_info(doc: &mut Doc, p: &Profinet, dap: &Dap) {
    let properties = &p.interface_properties;
    let classes = [
        ("Isochronous", properties.isochronous.is_some()),
        ("EnergySaving", p.profienergy.is_some()),
        (
            "FunctionalSafety",
            p.functional_safety_class && !dap.safety_modules.is_empty(),
        ),
    ];
    let application_class: Vec<&str> = classes
        .iter()
        .filter(|(_, declared)| *declared)
        .map(|(class, _)| *class)
        .collect();
    let application_class = application_class.join(";");
    let mut attributes = vec![(
        "ConformanceClass",
        match properties.conformance_class {
            ConformanceClass::A => "A",
            ConformanceClass::B => "B",
            ConformanceClass::C => "C",
        },
    )];
    if !application_class.is_empty() {
        attributes.push(("ApplicationClass", &application_class));
    }
    attributes.push((
        "NetloadClass",
        match properties.netload_class {
            NetloadClass::I => "I",
            NetloadClass::II => "II",
            NetloadClass::III => "III",
        },
    ));
    doc.leaf("CertificationInfo", &attributes);
}

/// Name, InfoText and then any `Value` elements, in the schema's order.
fn module_info(doc: &mut Doc, name: &TextRef, info: &TextRef, values: &[(&str, &str)]) {
    doc.open("ModuleInfo", &[]);
    module_info_body(doc, name, info, values);
}

/// A module's ModuleInfo, with the category it is listed under and the
/// releases it repeats.
fn module_info_in(doc: &mut Doc, m: &Module, releases: &[(&str, &str)]) {
    doc.open("ModuleInfo", &[("CategoryRef", &m.category)]);
    module_info_body(doc, &m.name, &m.info, releases);
}

/// The first device access point's releases, which every module's
/// ModuleInfo repeats with `module_releases`.
fn module_releases(p: &Profinet) -> Vec<(&'static str, &str)> {
    if !p.module_releases {
        return Vec::new();
    }
    let first = p.first_dap();
    stated_values(&[
        ("HardwareRelease", &first.hardware_release),
        ("SoftwareRelease", &first.software_release),
    ])
}

/// The ModuleInfo values that are stated, each with its element.
fn stated_values<'a>(
    values: &[(&'static str, &'a Option<String>)],
) -> Vec<(&'static str, &'a str)> {
    values
        .iter()
        .filter_map(|&(element, value)| Some((element, value.as_deref()?)))
        .collect()
}

fn module_info_body(doc: &mut Doc, name: &TextRef, info: &TextRef, values: &[(&str, &str)]) {
    doc.text_ref("Name", name);
    doc.text_ref("InfoText", info);
    for (element, value) in values {
        doc.leaf(element, &[("Value", value)]);
    }
    doc.close("ModuleInfo");
}

/// The DAP attributes of its stack that are written only when the
/// description states them (`[profinet.stack]`).
fn stated_stack_attributes(stack: &Stack) -> Vec<(&'static str, String)> {
    let mut attributes = Vec::new();
    if let Some(ars) = stack.device_access_ars {
        attributes.push(("NumberOfDeviceAccessAR", ars.to_string()));
    }
    if stack.shared_device {
        attributes.push(("SharedDeviceSupported", "true".to_string()));
    }
    if !stack.address_assignment.is_empty() {
        let ways: Vec<&str> = stack.address_assignment.iter().map(|a| a.token()).collect();
        attributes.push(("AddressAssignment", ways.join(";")));
    }
    if let Some(ms) = stack.power_on_to_comm_ready {
        attributes.push(("PowerOnToCommReady", ms.to_string()));
    }
    if stack.adapts_real_identification {
        attributes.push(("AdaptsRealIdentification", "true".to_string()));
    }
    if let Some(url) = &stack.web_server {
        attributes.push(("WebServer", url.clone()));
    }
    attributes
}

/// Each port's attributes that `[profinet.stack]` states.
fn stated_port_attributes(stack: &Stack) -> Vec<(&'static str, &'static str)> {
    let flags = [
        ("PortDeactivationSupported", stack.port_deactivation),
        ("CheckMAUTypeSupported", stack.check_mau_type),
        (
            "CheckMAUTypeDifferenceSupported",
            stack.check_mau_type_difference,
        ),
    ];
    let mut attributes: Vec<_> = flags
        .into_iter()
        .filter(|&(_, on)| on)
        .map(|(name, _)| (name, "true"))
        .collect();
    attributes.extend(
        stack
            .link_state_diagnosis
            .map(|link| ("LinkStateDiagnosisCapability", link)),
    );
    attributes
}

/// The DAP's own submodule: no IO data, and the card's own records of it.
/// A device that lets the controller write no I&M record has no
/// Writeable_IM_Records (an empty list is not a value of it).
fn dap_submodule(doc: &mut Doc, p: &Profinet, dap: &Dap) {
    doc.open("VirtualSubmoduleList", &[]);
    let ident = hex32(dap.submodule_ident);
    let records = blank_separated(&p.interface_properties.writeable_im_records);
    let mut attributes = vec![
        ("ID", dap.submodule_id.as_str()),
        ("SubmoduleIdentNumber", &ident),
    ];
    if !records.is_empty() {
        attributes.push(("Writeable_IM_Records", &records));
    }
    attributes.push(("MayIssueProcessAlarm", "false"));
    doc.open("VirtualSubmoduleItem", &attributes);
    doc.leaf("IOData", &[]);
    submodule_records(doc, p.own_records(dap).0);
    module_info(doc, &dap.name, &dap.info, &[]);
    if let Some(energy) = &p.profienergy {
        profienergy(doc, energy);
    }
    doc.close("VirtualSubmoduleItem");
    doc.close("VirtualSubmoduleList");
}

/// The `PROFIenergy` element of the access point's own submodule.
fn profienergy(doc: &mut Doc, energy: &ProfiEnergy) {
    let class = energy.entity_class.map(|c| format!("Class{c}"));
    let subclass = energy.entity_subclass.map(|c| format!("Subclass{c}"));
    let mut attributes = vec![("ProfileVersion", energy.profile_version.as_str())];
    attributes.extend(class.as_deref().map(|c| ("EntityClass", c)));
    attributes.extend(subclass.as_deref().map(|c| ("EntitySubclass", c)));
    if energy.pesap_uses_ase {
        attributes.push(("PESAP_uses_PROFIenergyASE", "true"));
    }
    if energy.modes.is_empty() {
        doc.leaf("PROFIenergy", &attributes);
        return;
    }
    doc.open("PROFIenergy", &attributes);
    doc.open("EnergySavingModeList", &[]);
    for mode in &energy.modes {
        let numbers = [
            mode.id.to_string(),
            mode.time_to_pause.to_string(),
            mode.regular_time_to_operate.to_string(),
            mode.min_length_of_stay.to_string(),
        ];
        let names = ["ID", "TimeToPause", "RTTO", "TimeMinLengthOfStay"];
        let attributes: Vec<(&str, &str)> = names
            .into_iter()
            .zip(numbers.iter().map(String::as_str))
            .collect();
        doc.leaf("EnergySavingModeItem", &attributes);
    }
    doc.close("EnergySavingModeList");
    doc.close("PROFIenergy");
}

/// The interface and its ports. In gsdc's numbering their submodule ident
/// numbers are their subslot numbers, the convention p-net also follows.
/// DCP_HelloSupported (fast start-up) stays off: the description does not
/// claim it, and `[profinet.stack] power_on_to_comm_ready` alone does not.
/// The DCP and PTP boundaries are declared as every corpus file of
/// PNIO_Version V2.32 or later declares them (12 of 12), and as TIA
/// Portal's checker requires of V2.31 and later.
fn interface_and_ports(doc: &mut Doc, p: &Profinet, dap: &Dap) {
    doc.open("SystemDefinedSubmoduleList", &[]);
    doc.text(&p.interface);
    let interface_ident = hex32(p.interface_ident);
    let interface_subslot = INTERFACE_SUBSLOT.to_string();
    let properties = &p.interface_properties;
    let irt = properties.irt.as_ref();
    let mut attributes = vec![
        ("ID", dap.interface_id.as_str()),
        ("SubslotNumber", &interface_subslot),
        ("SubmoduleIdentNumber", &interface_ident),
        ("TextId", &p.interface.id),
        (
            "SupportedRT_Classes",
            if irt.is_some() {
                "RT_CLASS_1;RT_CLASS_3"
            } else {
                "RT_CLASS_1"
            },
        ),
    ];
    if properties.isochronous.is_some() {
        attributes.push(("IsochroneModeSupported", "true"));
        attributes.push(("IsochroneModeInRT_Classes", "RT_CLASS_3"));
    }
    if dap.stack.network_component_diagnosis {
        attributes.push(("NetworkComponentDiagnosisSupported", "true"));
    }
    attributes.extend([
        ("SupportedProtocols", "SNMP;LLDP"),
        ("DCP_BoundarySupported", "true"),
        ("PTP_BoundarySupported", "true"),
    ]);
    // RT_CLASS_3 synchronises over PTCP, which measures each line's delay.
    if irt.is_some() {
        attributes.push(("DelayMeasurementSupported", "true"));
    }
    doc.open("InterfaceSubmoduleItem", &attributes);
    if let Some(irt) = irt {
        rt_class_3_properties(doc, irt);
    }
    // Both startup modes, or controllers that start up the legacy way
    // (older firmware) find no mode they share with the device.
    let ars = dap.stack.application_relations.map(|n| n.to_string());
    let mut relations: Vec<(&str, &str)> = ars
        .as_deref()
        .map(|n| ("NumberOfAR", n))
        .into_iter()
        .collect();
    relations.push(("StartupMode", "Legacy;Advanced"));
    doc.open("ApplicationRelations", &relations);
    let properties = &p.interface_properties;
    let preferred = properties.preferred_send_clock.map(|c| c.to_string());
    let mut timing = vec![
        ("SendClock", blank_separated(&properties.send_clock)),
        ("ReductionRatio", "1 2 4 8 16 32 64 128 256 512".to_string()),
    ];
    timing.extend(preferred.map(|c| ("PreferredSendClock", c)));
    doc.leaf("TimingProperties", &borrowed(&timing));
    if let Some(irt) = irt {
        let preferred = irt.preferred_send_clock.map(|c| c.to_string());
        let mut timing = vec![
            ("SendClock", blank_separated(&irt.send_clock)),
            ("ReductionRatio", blank_separated(&irt.reduction_ratio)),
        ];
        timing.extend(preferred.map(|c| ("PreferredSendClock", c)));
        doc.leaf("RT_Class3TimingProperties", &borrowed(&timing));
    }
    doc.close("ApplicationRelations");
    if dap.media_redundancy {
        doc.leaf("MediaRedundancy", &[("SupportedRole", "Client")]);
    }
    doc.close("InterfaceSubmoduleItem");
    for port in &dap.ports {
        doc.text(&port.text);
        let subslot = port.subslot.to_string();
        let ident = hex32(port.ident);
        let mut attributes = vec![
            ("ID", port.id.as_str()),
            ("SubslotNumber", &subslot),
            ("SubmoduleIdentNumber", &ident),
            ("TextId", &port.text.id),
        ];
        let delays = irt.map(|irt| (irt.port_tx_delay.to_string(), irt.port_rx_delay.to_string()));
        if let Some((tx, rx)) = &delays {
            attributes.extend([
                ("MaxPortTxDelay", tx.as_str()),
                ("MaxPortRxDelay", rx.as_str()),
            ]);
        }
        attributes.extend(stated_port_attributes(&dap.stack));
        if port.default_ringport {
            attributes.push(("IsDefaultRingport", "true"));
        }
        doc.open("PortSubmoduleItem", &attributes);
        submodule_records(doc, p.own_records(dap).1);
        doc.open("MAUTypeList", &[]);
        let mut mau = vec![("Value", MAU_100BASE_TX)];
        if dap.stack.mau_type_adjustable {
            mau.push(("AdjustSupported", "true"));
        }
        doc.leaf("MAUTypeItem", &mau);
        doc.close("MAUTypeList");
        doc.close("PortSubmoduleItem");
    }
    doc.close("SystemDefinedSubmoduleList");
}

/// `RT_Class3Properties` and the `SynchronisationMode` of a sync slave
/// over PTCP, in the schema's order.
fn rt_class_3_properties(doc: &mut Doc, irt: &Irt) {
    let mut properties = Vec::new();
    if !irt.startup_mode.is_empty() {
        properties.push(("StartupMode", irt.startup_mode.join(";")));
    }
    if !irt.forwarding_mode.is_empty() {
        properties.push(("ForwardingMode", irt.forwarding_mode.join(";")));
    }
    properties.extend([
        ("MaxBridgeDelay", irt.max_bridge_delay.to_string()),
        (
            "MaxNumberIR_FrameData",
            irt.max_number_ir_frame_data.to_string(),
        ),
    ]);
    doc.leaf("RT_Class3Properties", &borrowed(&properties));
    let mut sync = vec![("SupportedRole", "SyncSlave".to_string())];
    sync.extend(
        irt.max_local_jitter
            .map(|j| ("MaxLocalJitter", j.to_string())),
    );
    sync.extend(irt.t_pll_max.map(|t| ("T_PLL_MAX", t.to_string())));
    sync.push(("SupportedSyncProtocols", "PTCP".to_string()));
    doc.leaf("SynchronisationMode", &borrowed(&sync));
}

/// A data submodule's `IsochroneMode`.
fn isochrone_mode(doc: &mut Doc, iso: &Isochronous) {
    let mut attributes = vec![
        ("T_DC_Base", iso.t_dc_base.to_string()),
        ("T_DC_Min", iso.t_dc_min.to_string()),
        ("T_DC_Max", iso.t_dc_max.to_string()),
        ("T_IO_Base", iso.t_io_base.to_string()),
        ("T_IO_InputMin", iso.t_io_input_min.to_string()),
        ("T_IO_OutputMin", iso.t_io_output_min.to_string()),
    ];
    if iso.required {
        attributes.push(("IsochroneModeRequired", "true".to_string()));
    }
    doc.leaf("IsochroneMode", &borrowed(&attributes));
}

/// Attributes of owned values, as [`Doc`] takes them.
fn borrowed<'a>(attributes: &'a [(&'a str, String)]) -> Vec<(&'a str, &'a str)> {
    attributes
        .iter()
        .map(|(name, value)| (*name, value.as_str()))
        .collect()
}

/// A `ParameterRecordDataItem`'s start and its name; its Refs follow.
fn open_record(doc: &mut Doc, index: u16, length: u16, name: &TextRef) {
    doc.open(
        "ParameterRecordDataItem",
        &[
            ("Index", &index.to_string()),
            ("Length", &length.to_string()),
        ],
    );
    doc.text_ref("Name", name);
}

fn parameter_record(doc: &mut Doc, ir: &Ir, record: &ParameterRecord) {
    open_record(doc, record.index, record.length, &record.name);
    for r in &record.refs {
        let (set, _) = ir.mappings.entry(r.entry);
        doc.text(&r.text);
        let offset = r.offset.to_string();
        let default = r.default.to_string();
        let allowed = allowed_values(&set.allowed);
        let mut attributes = vec![
            ("DataType", set.entry_type.gsdml_name()),
            ("ByteOffset", offset.as_str()),
            ("DefaultValue", default.as_str()),
            ("AllowedValues", allowed.as_str()),
        ];
        attributes.extend(r.value_item.as_deref().map(|v| ("ValueItemTarget", v)));
        attributes.extend([
            ("Changeable", if r.changeable { "true" } else { "false" }),
            ("Visible", "true"),
            ("TextId", r.text.id.as_str()),
        ]);
        doc.leaf("Ref", &attributes);
    }
    for value in &record.fail_safe {
        doc.text(&value.text);
        doc.leaf(
            "Ref",
            &[
                ("DataType", value.data_type()),
                ("ByteOffset", &value.offset.to_string()),
                ("DefaultValue", "0"),
                ("AllowedValues", &format!("0..{}", value.max())),
                ("Changeable", "true"),
                ("Visible", "true"),
                ("TextId", value.text.id.as_str()),
            ],
        );
    }
    doc.close("ParameterRecordDataItem");
}

/// GSDML's value list: `min..max` runs and single values, e.g. "0..14" or
/// "0..3 6 9..10".
fn allowed_values(allowed: &Allowed) -> String {
    match allowed {
        Allowed::Range { min, max } => runs_text(&[((*min).into(), (*max).into())]),
        Allowed::Choices(set) => runs_text(&runs(set.choices.iter().map(|c| c.value))),
    }
}

/// Values as runs of consecutive ones, ascending.
fn runs(values: impl Iterator<Item = i64>) -> Vec<(i64, i64)> {
    let mut values: Vec<i64> = values.collect();
    values.sort_unstable();
    let mut runs: Vec<(i64, i64)> = Vec::new();
    for value in values {
        match runs.last_mut() {
            Some((_, last)) if *last + 1 == value => *last = value,
            _ => runs.push((value, value)),
        }
    }
    runs
}

fn runs_text(runs: &[(i64, i64)]) -> String {
    let run = |&(first, last): &(i64, i64)| {
        if first == last {
            first.to_string()
        } else {
            format!("{first}..{last}")
        }
    };
    runs.iter().map(run).collect::<Vec<_>>().join(" ")
}

/// The card's own records of the access point or a port, when it has any.
fn submodule_records(doc: &mut Doc, records: &[SubmoduleRecord]) {
    if records.is_empty() {
        return;
    }
    doc.open("RecordDataList", &[]);
    for record in records {
        parameter_record_item(doc, record);
    }
    doc.close("RecordDataList");
}

/// A record of the card's own as its `ParameterRecordDataItem`.
fn parameter_record_item(doc: &mut Doc, record: &SubmoduleRecord) {
    open_record(doc, record.index, record.length, &record.name);
    for value in &record.values {
        record_value(doc, value);
    }
    doc.close("ParameterRecordDataItem");
}

/// A record value's Ref. Its AllowedValues are written only where they
/// allow less than its type holds, whose values the schema allows without.
fn record_value(doc: &mut Doc, value: &RecordValue) {
    doc.text(&value.text);
    let offset = value.offset.to_string();
    let default = value.default.to_string();
    let allowed = match value.choices() {
        [] => vec![(value.min.into(), value.max.into())],
        choices => runs(choices.iter().map(|(v, _)| *v)),
    };
    let every_value = allowed == [(0, value.data_type.max().into())];
    let allowed = (!every_value).then(|| runs_text(&allowed));
    // A BitArea's length; a Bit is one.
    let (first_bit, bit_length) = match value.data_type {
        RecordValueType::Bits { first, last } => (
            Some(first.to_string()),
            (last > first).then(|| (last - first + 1).to_string()),
        ),
        _ => (None, None),
    };
    let mut attributes = vec![
        ("DataType", value.data_type.gsdml_name()),
        ("ByteOffset", offset.as_str()),
    ];
    attributes.extend(first_bit.as_deref().map(|b| ("BitOffset", b)));
    attributes.extend(bit_length.as_deref().map(|b| ("BitLength", b)));
    attributes.push(("DefaultValue", default.as_str()));
    attributes.extend(allowed.as_deref().map(|a| ("AllowedValues", a)));
    let item = value.value_item.as_ref();
    attributes.extend(item.map(|c| ("ValueItemTarget", c.id.as_str())));
    attributes.extend([
        (
            "Changeable",
            if value.changeable { "true" } else { "false" },
        ),
        ("Visible", if value.visible { "true" } else { "false" }),
        ("TextId", value.text.id.as_str()),
    ]);
    doc.leaf("Ref", &attributes);
}

fn module_list(doc: &mut Doc, ir: &Ir, p: &Profinet) {
    doc.open("ModuleList", &[]);
    for m in &p.modules {
        module(doc, ir, p, m);
    }
    if let Some(empty) = &p.empty_module {
        empty_module(doc, p, empty);
    }
    for m in &p.safety_modules {
        safety_module(doc, p, m);
    }
    doc.close("ModuleList");
}

/// The module without data: one submodule with an empty `IOData`, as SEW's
/// MOVI-C writes its "Empty" module.
fn empty_module(doc: &mut Doc, p: &Profinet, empty: &EmptyModule) {
    let ident = hex32(empty.ident);
    doc.open(
        "ModuleItem",
        &[("ID", EmptyModule::ID), ("ModuleIdentNumber", &ident)],
    );
    module_info(doc, &empty.name, &empty.info, &[]);
    doc.open("VirtualSubmoduleList", &[]);
    let submodule_ident = hex32(empty.submodule_ident);
    let im_records = module_im_records(p);
    let mut attributes = vec![
        ("ID", EmptyModule::SUBMODULE_ID),
        ("SubmoduleIdentNumber", &submodule_ident),
    ];
    attributes.extend(writeable_im(&im_records));
    attributes.push(("MayIssueProcessAlarm", "false"));
    doc.open("VirtualSubmoduleItem", &attributes);
    doc.leaf("IOData", &[]);
    module_info(doc, &empty.name, &empty.info, &[]);
    doc.close("VirtualSubmoduleItem");
    doc.close("VirtualSubmoduleList");
    doc.close("ModuleItem");
}

/// The I&M records the controller may write to a module's submodules, as
/// `Writeable_IM_Records` lists them.
fn module_im_records(p: &Profinet) -> String {
    blank_separated(&p.interface_properties.module_writeable_im_records)
}

/// The submodule attribute of [`module_im_records`]: an empty list is not
/// a value of `Writeable_IM_Records`.
fn writeable_im(records: &str) -> Option<(&'static str, &str)> {
    (!records.is_empty()).then_some(("Writeable_IM_Records", records))
}

/// A module with its data submodule; a PROFIdrive
/// telegram has the module access point before it, both in the profile's
/// API and fixed in their subslots, as ABB's FENA has them.
fn module(doc: &mut Doc, ir: &Ir, p: &Profinet, m: &Module) {
    let ident = hex32(m.ident_number);
    let im_records = module_im_records(p);
    let writeable_im = writeable_im(&im_records);
    doc.open(
        "ModuleItem",
        &[("ID", &m.id), ("ModuleIdentNumber", &ident)],
    );
    module_info_in(doc, m, &module_releases(p));
    doc.open("VirtualSubmoduleList", &[]);
    let api = m.api.to_string();
    if let Some(map) = &m.access_point {
        let ident = hex32(p.access_point_ident);
        let subslot = ACCESS_POINT_SUBSLOT.to_string();
        let mut attributes = vec![
            ("ID", map.id.as_str()),
            ("SubmoduleIdentNumber", &ident),
            ("API", &api),
            ("FixedInSubslots", &subslot),
        ];
        attributes.extend(writeable_im);
        attributes.push(("MayIssueProcessAlarm", "false"));
        doc.open("VirtualSubmoduleItem", &attributes);
        doc.leaf("IOData", &[]);
        module_info(doc, &map.name, &map.info, &[]);
        doc.close("VirtualSubmoduleItem");
    }
    let data_subslot = PROFIDRIVE_DATA_SUBSLOT.to_string();
    let submodule_ident = hex32(m.submodule_ident_number);
    let mut attributes = vec![
        ("ID", m.submodule_id.as_str()),
        ("SubmoduleIdentNumber", &submodule_ident),
        ("API", &api),
    ];
    if m.access_point.is_some() {
        attributes.push(("FixedInSubslots", &data_subslot));
    }
    attributes.extend(writeable_im);
    attributes.push(("MayIssueProcessAlarm", "false"));
    doc.open("VirtualSubmoduleItem", &attributes);
    doc.open("IOData", &[]);
    for (element, items) in [("Input", &m.input), ("Output", &m.output)] {
        doc.open(element, &[("Consistency", CONSISTENCY)]);
        for item in items {
            data_item(doc, item);
        }
        doc.close(element);
    }
    doc.close("IOData");
    if !m.records.is_empty() {
        doc.open("RecordDataList", &[]);
        for record in &m.records {
            parameter_record(doc, ir, record);
        }
        doc.close("RecordDataList");
    }
    let texts = (&m.submodule_name, &m.submodule_info);
    close_data_submodule(doc, p, Some(&m.category), texts);
}

/// A module's data submodule's ModuleInfo (naming the module's category
/// with `submodule_categories`) and isochronous mode, and the end of the
/// module.
fn close_data_submodule(
    doc: &mut Doc,
    p: &Profinet,
    category: Option<&str>,
    (name, info): (&TextRef, &TextRef),
) {
    match category.filter(|_| p.submodule_categories) {
        Some(category) => doc.open("ModuleInfo", &[("CategoryRef", category)]),
        None => doc.open("ModuleInfo", &[]),
    }
    module_info_body(doc, name, info, &[]);
    if let Some(iso) = &p.interface_properties.isochronous {
        isochrone_mode(doc, iso);
    }
    doc.close("VirtualSubmoduleItem");
    doc.close("VirtualSubmoduleList");
    doc.close("ModuleItem");
}

/// A PROFIsafe module: its one submodule with the safety IO data, the
/// CRC of its structure, and the F-parameter record with its CRC, as PI's
/// checker gave them (or placeholders, which the header names).
fn safety_module(doc: &mut Doc, p: &Profinet, m: &SafetyModule) {
    let ident = hex32(m.ident_number);
    doc.open(
        "ModuleItem",
        &[("ID", &m.id), ("ModuleIdentNumber", &ident)],
    );
    // No releases: neither FENA's nor MOVI-C's safety modules repeat them.
    match &m.category {
        Some(category) => doc.open("ModuleInfo", &[("CategoryRef", category)]),
        None => doc.open("ModuleInfo", &[]),
    }
    module_info_body(doc, &m.name, &m.info, &[]);
    doc.open("VirtualSubmoduleList", &[]);
    let submodule_ident = hex32(m.submodule_ident_number);
    // No writable I&M records: neither FENA's nor MOVI-C's safety
    // submodules have them, whatever their data modules have.
    let attributes = [
        ("ID", m.submodule_id.as_str()),
        ("SubmoduleIdentNumber", &submodule_ident),
        ("PROFIsafeSupported", "true"),
        ("MayIssueProcessAlarm", "false"),
    ];
    doc.open("VirtualSubmoduleItem", &attributes);
    let version = m.io_structure_desc_version.map(|v| v.to_string());
    let io_crc = m.crcs.f_io_structure_desc.to_string();
    let mut io = Vec::new();
    io.extend(version.as_deref().map(|v| ("F_IO_StructureDescVersion", v)));
    io.push(("F_IO_StructureDescCRC", io_crc.as_str()));
    doc.open("IOData", &io);
    for (element, items) in [("Input", &m.input), ("Output", &m.output)] {
        doc.open(element, &[("Consistency", CONSISTENCY)]);
        for item in items {
            io_item(
                doc,
                (item.data_type.name(), item.use_as_bits),
                &item.text,
                &item.bits,
            );
        }
        doc.close(element);
    }
    doc.close("IOData");
    doc.open("RecordDataList", &[]);
    // Its other records first, as the schema orders them.
    for record in &m.records {
        parameter_record_item(doc, record);
    }
    let index = m.f_parameter_index.to_string();
    let crc = m.crcs.f_param_desc.to_string();
    doc.open(
        "F_ParameterRecordDataItem",
        &[("Index", &index), ("F_ParamDescCRC", &crc)],
    );
    for parameter in &m.f_parameters {
        let attributes: Vec<(&str, &str)> = parameter
            .attributes
            .iter()
            .map(|(n, v)| (*n, v.as_str()))
            .collect();
        doc.leaf(parameter.element, &attributes);
    }
    doc.close("F_ParameterRecordDataItem");
    doc.close("RecordDataList");
    let texts = (&m.submodule_name, &m.submodule_info);
    close_data_submodule(doc, p, m.category.as_deref(), texts);
}

fn data_item(doc: &mut Doc, item: &DataItem) {
    let use_as_bits = !item.bits.is_empty();
    io_item(doc, (item.data_type(), use_as_bits), &item.text, &item.bits);
}

/// A `DataItem` of `data_type`, shown bit by bit with `use_as_bits`,
/// with its `BitDataItem`s.
fn io_item(
    doc: &mut Doc,
    (data_type, use_as_bits): (&str, bool),
    text: &TextRef,
    bits: &[BitItem],
) {
    doc.text(text);
    let mut attributes = vec![("DataType", data_type)];
    if use_as_bits {
        attributes.push(("UseAsBits", "true"));
    }
    attributes.push(("TextId", &text.id));
    if bits.is_empty() {
        doc.leaf("DataItem", &attributes);
        return;
    }
    doc.open("DataItem", &attributes);
    for bit in bits {
        doc.text(&bit.text);
        doc.leaf(
            "BitDataItem",
            &[
                ("BitOffset", &bit.offset.to_string()),
                ("TextId", &bit.text.id),
            ],
        );
    }
    doc.close("DataItem");
}

/// The hardware catalog's groups, which the modules' ModuleInfo refer to.
fn category_list(doc: &mut Doc, p: &Profinet) {
    if p.categories.is_empty() {
        return;
    }
    doc.open("CategoryList", &[]);
    for category in &p.categories {
        doc.text(&category.text);
        doc.leaf(
            "CategoryItem",
            &[("ID", &category.id), ("TextId", &category.text.id)],
        );
    }
    doc.close("CategoryList");
}

/// GSDML's ValueListT: numbers separated by blanks.
fn blank_separated<T: ToString>(values: &[T]) -> String {
    values
        .iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join(" ")
}

/// The channel diagnoses, a profile's with its API.
fn channel_diag_list(doc: &mut Doc, p: &Profinet) {
    if p.channel_diagnosis.is_empty() {
        return;
    }
    doc.open("ChannelDiagList", &[]);
    for d in &p.channel_diagnosis {
        let error_type = d.error_type.to_string();
        let api = d.api.map(|a| a.to_string());
        let element = match api {
            Some(_) => "ProfileChannelDiagItem",
            None => "ChannelDiagItem",
        };
        let mut attributes = vec![("ErrorType", error_type.as_str())];
        attributes.extend(api.as_deref().map(|a| ("API", a)));
        doc.open(element, &attributes);
        doc.text_ref("Name", &d.name);
        if let Some(help) = &d.help {
            doc.text_ref("Help", help);
        }
        ext_channel_diag_list(doc, &d.extended);
        doc.close(element);
    }
    doc.close("ChannelDiagList");
}

/// A channel diagnosis's extended error types, each with the DataItems of
/// its add value.
fn ext_channel_diag_list(doc: &mut Doc, extended: &[ExtendedDiagnosis]) {
    if extended.is_empty() {
        return;
    }
    doc.open("ExtChannelDiagList", &[]);
    for e in extended {
        doc.open(
            "ExtChannelDiagItem",
            &[("ErrorType", &e.error_type.to_string())],
        );
        doc.text_ref("Name", &e.name);
        if let Some(help) = &e.help {
            doc.text_ref("Help", help);
        }
        if !e.add_value.is_empty() {
            doc.open("ExtChannelAddValue", &[]);
            for (id, data_type) in &e.add_value {
                doc.leaf(
                    "DataItem",
                    &[("Id", &id.to_string()), ("DataType", data_type.name())],
                );
            }
            doc.close("ExtChannelAddValue");
        }
        doc.close("ExtChannelDiagItem");
    }
    doc.close("ExtChannelDiagList");
}

/// One ValueItem per set of choices a module's record refers to, then one
/// per record value of the access points, the ports and the safety modules
/// with choices or a help.
fn value_list(doc: &mut Doc, p: &Profinet) {
    let records = p.own_records_of_every_submodule();
    let values = records.flat_map(|r| &r.values);
    let items: Vec<&ValueItem> = p
        .value_items
        .iter()
        .chain(values.filter_map(|v| v.value_item.as_ref()))
        .collect();
    if items.is_empty() {
        return;
    }
    doc.open("ValueList", &[]);
    for item in items {
        doc.open("ValueItem", &[("ID", &item.id)]);
        if let Some(help) = &item.help {
            doc.text_ref("Help", help);
        }
        if !item.assignments.is_empty() {
            doc.open("Assignments", &[]);
            for (value, text) in &item.assignments {
                doc.text(text);
                doc.leaf(
                    "Assign",
                    &[("Content", &value.to_string()), ("TextId", &text.id)],
                );
            }
            doc.close("Assignments");
        }
        doc.close("ValueItem");
    }
    doc.close("ValueList");
}

/// English first, then every other language the description has, each
/// with every TextId (English where a text has none in that language).
fn external_texts(doc: &mut Doc, languages: &[String]) {
    let texts = std::mem::take(&mut doc.texts);
    doc.open("ExternalTextList", &[]);
    language(doc, "PrimaryLanguage", &[], &texts, "en");
    for code in languages {
        language(doc, "Language", &[("xml:lang", code)], &texts, code);
    }
    doc.close("ExternalTextList");
}

fn language(
    doc: &mut Doc,
    element: &str,
    attributes: &[(&str, &str)],
    texts: &[(String, Text)],
    code: &str,
) {
    doc.open(element, attributes);
    for (id, text) in texts {
        doc.leaf("Text", &[("TextId", id), ("Value", text.get(code))]);
    }
    doc.close(element);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn allowed_values_are_runs_and_single_values() {
        assert_eq!(
            allowed_values(&Allowed::Range { min: 0, max: 65535 }),
            "0..65535"
        );
        assert_eq!(allowed_values(&Allowed::Range { min: 7, max: 7 }), "7");
        assert_eq!(allowed_values(&Allowed::of_values(&[2, 0, 1])), "0..2");
        assert_eq!(
            allowed_values(&Allowed::of_values(&[0, 5, 9, 10, 1])),
            "0..1 5 9..10"
        );
        assert_eq!(allowed_values(&Allowed::of_values(&[3])), "3");
    }

    #[test]
    fn a_comment_never_contains_a_double_hyphen() {
        let mut doc = Doc::new();
        doc.comment("from a--b---c.toml");
        let text = doc.finish();
        assert!(text.contains("<!-- from a- -b- - -c.toml -->"), "{text}");
    }
}
