//! What only PROFINET needs: identity numbers, the device access point,
//! the selectable modules with their IO data and parameter records, and the
//! GSDML IDs and TextIds of everything, decided here so that the emitter
//! only writes them down.

pub mod safety;

use super::{Direction, EntryKey, Ident, Layout, MappingKind, SetKey, Text};
pub use crate::spec::GsdmlVersion as Version;

#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Profinet {
    pub gsdml_version: Version,
    /// Every device access point's `PNIO_Version`: the PROFINET
    /// specification version the device is certified against, at most the
    /// file's (`gsdml_version` unless stated).
    pub pnio_version: Version,
    /// Every device access point's `RequiredSchemaVersion`, when stated:
    /// the oldest GSDML version a tool must know to offer it.
    pub required_schema_version: Option<Version>,
    /// Every device access point's `ImplementationType`, when stated: what
    /// its PROFINET interface is based on.
    pub implementation_type: Option<String>,
    /// DeviceFunction's `ProductFamily`: `[device] family` unless stated.
    pub product_family: String,
    pub date: Date,
    pub file_name: String,
    pub vendor_id: u16,
    pub vendor_id_placeholder: bool,
    pub device_id: u16,
    pub device_id_placeholder: bool,
    /// The device's info text, as DeviceIdentity shows it: the first
    /// device access point's too, and a later one's that states none.
    pub device_info: TextRef,
    /// DNS_CompatibleName: the default name of station.
    pub dns_name: String,
    /// Units of 31.25 us.
    pub min_device_interval: u16,
    pub interface: TextRef,
    /// The labels the interface and its ports carry on the device, when
    /// the description gives them.
    pub subslot_labels: Option<SubslotLabels>,
    /// Whether every module's ModuleInfo repeats the first device access
    /// point's hardware and software release.
    pub module_releases: bool,
    /// Whether every module's data submodule names the module's category
    /// too (its ModuleInfo's CategoryRef).
    pub submodule_categories: bool,
    /// Whether an access point that offers a safety module declares the
    /// `FunctionalSafety` application class.
    pub functional_safety_class: bool,
    /// The interface submodule's SubmoduleIdentNumber.
    pub interface_ident: u32,
    pub interface_properties: InterfaceProperties,
    /// The device access points, the description's `[profinet]` first,
    /// then its `[[profinet.daps]]`: never empty.
    pub daps: Vec<Dap>,
    /// A PROFIdrive module's access point submodule's ident number.
    pub access_point_ident: u32,
    pub modules: Vec<Module>,
    /// The slots each of which takes one of the modules, each plugged
    /// module its own telegram (`AllowedInSlots`).
    pub module_slots: Slots,
    /// The module without data the card takes where a slot has no data
    /// module, when stated (SEW's MOVI-C: "Empty").
    pub empty_module: Option<EmptyModule>,
    /// The PROFIsafe modules, in the description's order.
    pub safety_modules: Vec<safety::SafetyModule>,
    /// The hardware catalog's groups of modules, in the order first used.
    pub categories: Vec<Category>,
    /// One per set of choices the records refer to.
    pub value_items: Vec<ValueItem>,
    /// The device symbol's GraphicItem, when the device has a symbol.
    pub device_symbol: Option<GraphicItem>,
    /// How firmware reads the record of each kind of mapping a module
    /// carries, in the order of the kinds.
    pub records: Vec<RecordPlan>,
    /// The value each module writes, for each set each kind of module
    /// writes its own of.
    pub module_values: Vec<ModuleValues>,
    /// The channel diagnoses the card reports, in the description's order.
    pub channel_diagnosis: Vec<ChannelDiagnosis>,
    /// The lists of parameter records of device access points' own
    /// submodules and of ports, each in the description's order: the first
    /// DAP's own submodule's, its ports', then each list a later DAP gives
    /// of its own. A DAP names its two ([`Dap::access_point_records`]).
    pub record_lists: Vec<Vec<SubmoduleRecord>>,
    /// The card's PROFIenergy, when stated.
    pub profienergy: Option<ProfiEnergy>,
}

/// An error type the card reports as channel diagnosis: a
/// `ChannelDiagItem`, or with a profile's API a `ProfileChannelDiagItem`.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct ChannelDiagnosis {
    pub error_type: u16,
    pub api: Option<u32>,
    pub name: TextRef,
    pub help: Option<TextRef>,
    /// Its constant's name in the layouts.
    pub ident: Ident,
    /// Its extended error types, in the description's order.
    pub extended: Vec<ExtendedDiagnosis>,
}

/// An `ExtChannelDiagItem`: an extended error type of a channel diagnosis.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct ExtendedDiagnosis {
    pub error_type: u16,
    pub name: TextRef,
    pub help: Option<TextRef>,
    /// The `DataItem`s of its `ExtChannelAddValue`: each Id with its type.
    pub add_value: Vec<(u8, AddValueType)>,
    /// Its constant's name in the layouts.
    pub ident: Ident,
}

pub use crate::description::AddValueType;

impl AddValueType {
    /// As GSDML spells it.
    pub fn name(self) -> &'static str {
        match self {
            AddValueType::Integer8 => "Integer8",
            AddValueType::Integer16 => "Integer16",
            AddValueType::Integer32 => "Integer32",
            AddValueType::Unsigned8 => "Unsigned8",
            AddValueType::Unsigned16 => "Unsigned16",
            AddValueType::Unsigned32 => "Unsigned32",
            AddValueType::Float32 => "Float32",
        }
    }

    /// Its width in the add value.
    pub fn bytes(self) -> u8 {
        match self {
            AddValueType::Integer8 | AddValueType::Unsigned8 => 1,
            AddValueType::Integer16 | AddValueType::Unsigned16 => 2,
            AddValueType::Integer32 | AddValueType::Unsigned32 | AddValueType::Float32 => 4,
        }
    }

    /// The type GSDML's name spells.
    pub fn from_name(name: &str) -> Option<Self> {
        [
            AddValueType::Integer8,
            AddValueType::Integer16,
            AddValueType::Integer32,
            AddValueType::Unsigned8,
            AddValueType::Unsigned16,
            AddValueType::Unsigned32,
            AddValueType::Float32,
        ]
        .into_iter()
        .find(|t| t.name() == name)
    }
}

/// A GraphicItem: its ID and GraphicFile, the bitmap's name beside the
/// GSDML without `.bmp` (`GSDML-0A10-0810-MV800`, as the corpus's vendors
/// name theirs).
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct GraphicItem {
    pub id: String,
    pub file: String,
}

impl Profinet {
    /// The first device access point: the one the layouts' device tables
    /// describe.
    pub fn first_dap(&self) -> &Dap {
        &self.daps[0]
    }

    /// Every record of the card's own: the access points' own submodules'
    /// and the ports', then the safety modules' besides their F-parameters.
    pub fn own_records_of_every_submodule(&self) -> impl Iterator<Item = &SubmoduleRecord> {
        let safety = self.safety_modules.iter().flat_map(|m| &m.records);
        self.record_lists.iter().flatten().chain(safety)
    }

    /// The records of `dap`'s own submodule, and of each of its ports.
    pub fn own_records(&self, dap: &Dap) -> (&[SubmoduleRecord], &[SubmoduleRecord]) {
        (
            &self.record_lists[dap.access_point_records],
            &self.record_lists[dap.port_records],
        )
    }

    /// The record of a kind of mapping, when a module carries it.
    pub fn record(&self, kind: MappingKind) -> Option<&RecordPlan> {
        self.records.iter().find(|r| r.kind == kind)
    }

    /// The values each module writes for the set `key`, when each kind of
    /// module writes its own.
    pub fn module_values(&self, key: SetKey) -> Option<&ModuleValues> {
        self.module_values.iter().find(|f| f.set == key)
    }

    /// Every text the GSDML refers to, in the order of the plan: the
    /// device's, the interface's and ports', their labels, the catalog's
    /// categories, each module's (its name and info and its data
    /// submodule's, its access point's, its IO data and their bits, its
    /// records and their entries), the value items'. A TextId may come more
    /// than once.
    pub fn text_refs(&self) -> Vec<&TextRef> {
        let mut refs = vec![&self.device_info, &self.interface];
        for dap in &self.daps {
            refs.extend([&dap.name, &dap.info]);
            refs.extend(dap.ports.iter().map(|p| &p.text));
        }
        if let Some(labels) = &self.subslot_labels {
            refs.push(&labels.interface);
            refs.extend(&labels.ports);
        }
        refs.extend(self.categories.iter().map(|c| &c.text));
        for m in &self.modules {
            refs.extend([&m.name, &m.info, &m.submodule_name, &m.submodule_info]);
            if let Some(map) = &m.access_point {
                refs.extend([&map.name, &map.info]);
            }
            for item in m.input.iter().chain(&m.output) {
                refs.push(&item.text);
                refs.extend(item.bits.iter().map(|b| &b.text));
            }
            for record in &m.records {
                refs.push(&record.name);
                refs.extend(record.refs.iter().map(|r| &r.text));
                refs.extend(record.fail_safe.iter().map(|v| &v.text));
            }
        }
        if let Some(empty) = &self.empty_module {
            refs.extend([&empty.name, &empty.info]);
        }
        for m in &self.safety_modules {
            refs.extend([&m.name, &m.info, &m.submodule_name, &m.submodule_info]);
            for item in m.input.iter().chain(&m.output) {
                refs.push(&item.text);
                refs.extend(item.bits.iter().map(|b| &b.text));
            }
        }
        for record in self.own_records_of_every_submodule() {
            refs.push(&record.name);
            refs.extend(record.values.iter().map(|v| &v.text));
            let items = record.values.iter().filter_map(|v| v.value_item.as_ref());
            refs.extend(
                items.flat_map(|v| v.help.iter().chain(v.assignments.iter().map(|(_, t)| t))),
            );
        }
        refs.extend(
            self.value_items
                .iter()
                .flat_map(|v| v.assignments.iter().map(|(_, t)| t)),
        );
        refs
    }
}

/// The record of one kind of mapping, as firmware reads what the
/// controller writes: each module's record of the kind has this index.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct RecordPlan {
    pub kind: MappingKind,
    pub index: u16,
    /// Bytes with every entry of the kind, each of its set's type.
    pub length: u16,
    pub reading: RecordReading,
}

/// How much of a record the controller writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RecordReading {
    /// Every entry.
    Whole,
    /// The first entries: a module's PZD record holds the words the
    /// module transports; the others keep their defaults.
    Prefix,
}

/// The value of a set each kind of module writes, for each module that
/// carries it: one the module fixes, or the module's default.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct ModuleValues {
    pub set: SetKey,
    /// False: the modules fix the values; the user cannot change them.
    pub changeable: bool,
    /// The module (its name in generated code and its ident number) and
    /// its value, in module order.
    pub modules: Vec<(Ident, u32, u16)>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct Date {
    pub year: u16,
    pub month: u8,
    pub day: u8,
    /// The local time of day, for a second release on one day.
    pub time: Option<TimeOfDay>,
}

/// A local time of day in whole seconds, as a GSDML file name gives it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct TimeOfDay {
    pub hour: u8,
    pub minute: u8,
    pub second: u8,
}

impl Date {
    /// `yyyymmdd`, or `yyyymmdd-hhmmss` with a time, as GSDML file names
    /// write it.
    pub fn compact(self) -> String {
        let date = format!("{:04}{:02}{:02}", self.year, self.month, self.day);
        match self.time {
            None => date,
            Some(t) => format!("{date}-{:02}{:02}{:02}", t.hour, t.minute, t.second),
        }
    }
}

/// A GSDML TextId and the text it stands for.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct TextRef {
    pub id: String,
    pub text: Text,
}

impl TextRef {
    pub(crate) fn new(id: impl Into<String>, text: Text) -> Self {
        TextRef {
            id: id.into(),
            text,
        }
    }
}

/// gsdc's numbering, where the description states no ident number
/// (`[profinet.ident_numbers]`): the device access point's
/// ModuleIdentNumber and its submodule's.
pub const DAP_IDENT: u32 = 0x0000_0001;
/// The subslot of a submodule the GSDML gives none (FixedInSubslots'
/// default): the DAP's own, a module's one data submodule.
pub const DAP_SUBSLOT: u16 = 1;
pub const DEFAULT_SUBSLOT: u16 = 1;
/// Subslots of the interface and of its first port (IEC 61158-6-10). In
/// gsdc's numbering they are also the submodule ident numbers of the
/// interface and the ports, as p-net does it.
pub const INTERFACE_SUBSLOT: u16 = 0x8000;
pub const FIRST_PORT_SUBSLOT: u16 = 0x8001;
/// The slot modules are plugged into unless the description says others;
/// the DAP is in slot 0.
pub const MODULE_SLOT: u16 = 1;

/// Slots `first` to `last`, as `AllowedInSlots` lists them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Slots {
    pub first: u16,
    pub last: u16,
}

impl Slots {
    /// gsdc's default: the one [`MODULE_SLOT`].
    pub const ONE: Slots = Slots {
        first: MODULE_SLOT,
        last: MODULE_SLOT,
    };

    pub fn count(self) -> u16 {
        self.last - self.first + 1
    }

    pub fn iter(self) -> std::ops::RangeInclusive<u16> {
        self.first..=self.last
    }
}

/// A GSDML slot list: `1`, or `2..5`.
impl std::fmt::Display for Slots {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.first == self.last {
            true => write!(f, "{}", self.first),
            false => write!(f, "{}..{}", self.first, self.last),
        }
    }
}

/// The last slot a data module (in `module_slots`) or another module (the
/// empty module, a safety module: in its `others` slots) goes into.
pub fn last_used_slot(module_slots: Slots, others: impl Iterator<Item = Slots>) -> u16 {
    others.map(|s| s.last).fold(module_slots.last, u16::max)
}

/// A module without IO data or records, which the controller plugs into a
/// slot that takes no data module: its one submodule only says the slot is
/// in use as planned.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct EmptyModule {
    /// ModuleIdentNumber and its submodule's SubmoduleIdentNumber.
    pub ident: u32,
    pub submodule_ident: u32,
    pub name: TextRef,
    pub info: TextRef,
    pub slots: Slots,
}

impl EmptyModule {
    /// Its ModuleItem's ID and its submodule's.
    pub const ID: &'static str = "IDM_EMPTY";
    pub const SUBMODULE_ID: &'static str = "IDS_EMPTY";
}

/// The PROFIenergy profile the card implements, as every device access
/// point's own submodule declares it.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct ProfiEnergy {
    /// `ProfileVersion`, as the file writes it: `V1.2`.
    pub profile_version: String,
    /// `EntityClass` (1 to 3) and `EntitySubclass` (1 to 2), when stated.
    pub entity_class: Option<u8>,
    pub entity_subclass: Option<u8>,
    /// The device access point's `PROFIenergyASE_Supported`.
    pub ase: bool,
    pub pesap_uses_ase: bool,
    /// The energy saving modes, in the description's order.
    pub modes: Vec<EnergySavingMode>,
}

/// An energy saving mode: its number and its times in ms.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct EnergySavingMode {
    pub id: u8,
    pub time_to_pause: u32,
    pub regular_time_to_operate: u32,
    pub min_length_of_stay: u32,
}

/// What the device access point and its interface declare of what the
/// firmware does.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct InterfaceProperties {
    /// SendClock factors, ascending; units of 31.25 us.
    pub send_clock: Vec<u16>,
    /// `TimingProperties@PreferredSendClock`, one of `send_clock`.
    pub preferred_send_clock: Option<u16>,
    pub conformance_class: ConformanceClass,
    pub netload_class: NetloadClass,
    /// I&M records the controller may write, ascending.
    pub writeable_im_records: Vec<u8>,
    /// I&M records the controller may write to each module's submodules,
    /// ascending; none by default.
    pub module_writeable_im_records: Vec<u8>,
    /// Isochronous real time (RT_CLASS_3), with conformance class C.
    pub irt: Option<Irt>,
    /// Isochronous mode of every module's data submodule; only with `irt`.
    pub isochronous: Option<Isochronous>,
}

/// RT_CLASS_3 as the interface and its ports declare it; times in ns.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Irt {
    pub max_bridge_delay: u16,
    pub max_number_ir_frame_data: u16,
    /// `ForwardingMode` and `StartupMode` tokens, in the description's
    /// order; empty: unwritten.
    pub forwarding_mode: Vec<&'static str>,
    pub startup_mode: Vec<&'static str>,
    /// `RT_Class3TimingProperties`: factors of 31.25 us, ascending.
    pub send_clock: Vec<u16>,
    pub reduction_ratio: Vec<u16>,
    pub preferred_send_clock: Option<u16>,
    /// `SynchronisationMode`'s, when stated.
    pub max_local_jitter: Option<u16>,
    pub t_pll_max: Option<u16>,
    /// Each port's `MaxPortTxDelay` and `MaxPortRxDelay`.
    pub port_tx_delay: u16,
    pub port_rx_delay: u16,
}

/// `IsochroneMode`: data cycles in `t_dc_base` units of 31.25 us, input
/// and output times in `t_io_base` units of 1 ns.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Isochronous {
    pub required: bool,
    pub t_dc_base: u16,
    pub t_dc_min: u16,
    pub t_dc_max: u16,
    pub t_io_base: u32,
    pub t_io_input_min: u32,
    pub t_io_output_min: u32,
}

/// A device access point (DAP): the card in slot 0 as one of its hardware
/// or firmware versions presents itself. Every DAP has the same interface
/// properties and offers modules of the same list.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Dap {
    /// Its ID, its own submodule's and its interface's: `IDD_DAP`, then
    /// `IDD_DAP_2` and so on.
    pub id: String,
    pub submodule_id: String,
    pub interface_id: String,
    /// Its ModuleIdentNumber and its own submodule's.
    pub ident: u32,
    pub submodule_ident: u32,
    pub name: TextRef,
    pub info: TextRef,
    pub order_number: Option<String>,
    pub hardware_release: Option<String>,
    pub software_release: Option<String>,
    /// `PNIO_Version`: the first DAP's is `Profinet::pnio_version`.
    pub pnio_version: Version,
    pub ports: Vec<Port>,
    /// An MRP client: `MediaRedundancy`, the default ring ports.
    pub media_redundancy: bool,
    /// The modules it offers: indexes into `Profinet::modules`, ascending.
    pub modules: Vec<usize>,
    /// The safety modules it offers: indexes into
    /// `Profinet::safety_modules`, ascending.
    pub safety_modules: Vec<usize>,
    /// The records of its own submodule and of each of its ports: indexes
    /// into `Profinet::record_lists`.
    pub access_point_records: usize,
    pub port_records: usize,
    /// `PhysicalSlots`' last: the stack's, else the last slot its modules
    /// go into.
    pub last_slot: u16,
    /// IOConfigData: the most bytes the plugged submodules exchange.
    pub max_input_length: u16,
    pub max_output_length: u16,
    /// IOConfigData's MaxDataLength: the stack's, or what the plugged
    /// submodules need in and out together where more; unwritten when the
    /// stack states none.
    pub max_data_length: Option<u16>,
    /// Whether the lengths hold every slot with its largest module: else
    /// the engineering tool refuses some combinations (`gsdc check`'s
    /// W302), as the description's stated limit wants.
    pub io_full: bool,
    pub stack: Stack,
}

/// What the card's PROFINET stack offers the controllers through a DAP
/// (`[profinet.stack]`): attributes of the DAP and its interface.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct Stack {
    /// `AddressAssignment`, in the description's order; empty: unwritten
    /// (the schema's default, DCP).
    pub address_assignment: Vec<AddressAssignment>,
    pub device_access: bool,
    /// `NumberOfDeviceAccessAR`, only with `device_access`.
    pub device_access_ars: Option<u8>,
    pub name_of_station_not_transferable: bool,
    /// `SharedDeviceSupported`, written when true.
    pub shared_device: bool,
    /// The interface's `NumberOfAR`; unwritten: the schema's default, 1.
    pub application_relations: Option<u16>,
    /// `IOConfigData`'s limits where stated (never less than the modules
    /// need); else what they need (`Dap::max_input_length`).
    pub max_input_length: Option<u16>,
    pub max_output_length: Option<u16>,
    /// `IOConfigData@MaxDataLength`, the most bytes in and out together,
    /// where stated (never less than the modules need).
    pub max_data_length: Option<u16>,
    /// Each port's `MAUTypeItem@AdjustSupported`.
    pub mau_type_adjustable: bool,
    /// `PhysicalSlots` 0 to it, where more than the module's slot.
    pub last_slot: Option<u16>,
    /// `PowerOnToCommReady` (ms), when stated.
    pub power_on_to_comm_ready: Option<u32>,
    /// The interface's `NetworkComponentDiagnosisSupported`, written when
    /// true.
    pub network_component_diagnosis: bool,
    /// Each port's `PortDeactivationSupported` and `CheckMAUTypeSupported`,
    /// written when true, and its `LinkStateDiagnosisCapability` token when
    /// stated.
    pub port_deactivation: bool,
    pub check_mau_type: bool,
    pub link_state_diagnosis: Option<&'static str>,
    /// Each port's `CheckMAUTypeDifferenceSupported`, written when true.
    pub check_mau_type_difference: bool,
    /// The device access point's `AdaptsRealIdentification`, written when
    /// true.
    pub adapts_real_identification: bool,
    /// The device access point's `WebServer`, when stated.
    pub web_server: Option<String>,
}

/// A way the device may get its IP address.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum AddressAssignment {
    Dcp,
    Dhcp,
    Local,
}

impl AddressAssignment {
    pub const ALL: [AddressAssignment; 3] = [
        AddressAssignment::Dcp,
        AddressAssignment::Dhcp,
        AddressAssignment::Local,
    ];

    /// Its GSDML token.
    pub fn token(self) -> &'static str {
        match self {
            AddressAssignment::Dcp => "DCP",
            AddressAssignment::Dhcp => "DHCP",
            AddressAssignment::Local => "LOCAL",
        }
    }
}

/// CertificationInfo's conformance class: C exactly when the interface
/// runs isochronous real time (`InterfaceProperties::irt`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum ConformanceClass {
    A,
    B,
    C,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
// PROFINET names the classes by Roman numerals.
#[allow(clippy::upper_case_acronyms)]
pub enum NetloadClass {
    I,
    II,
    III,
}

/// The labels the interface and its ports carry on the device (GSDML
/// `SubslotList`): one for each port of the access point with the most; an
/// access point labels its own.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct SubslotLabels {
    pub interface: TextRef,
    pub ports: Vec<TextRef>,
}

/// A port of the interface.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Port {
    pub id: String,
    pub subslot: u16,
    /// Its SubmoduleIdentNumber: its subslot in gsdc's numbering.
    pub ident: u32,
    pub text: TextRef,
    /// One of the two ring ports an MRP client starts with.
    pub default_ringport: bool,
}

impl Port {
    /// Whether its ident number is its subslot: gsdc's numbering.
    pub fn numbered_by_subslot(&self) -> bool {
        self.ident == u32::from(self.subslot)
    }
}

/// A CategoryItem of the hardware catalog.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Category {
    pub id: String,
    pub text: TextRef,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum ModuleKind {
    /// PKW (or not) and PZD words, as the description maps them.
    Pzd,
    /// Standard telegram 1: PROFIdrive's (STW1, NSOLL_A out; ZSW1, NIST_A
    /// in) when the card implements the profile, else the vendor's telegram
    /// of two PZD words the manual names so.
    StandardTelegram1,
    /// PROFIdrive's standard telegram 2: STW1, NSOLL_B (32 bits), STW2
    /// out; ZSW1, NIST_B (32 bits), ZSW2 in; four words each way. Only of a
    /// card that implements the profile.
    StandardTelegram2,
}

/// A selectable module with its one submodule of the same ident number.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Module {
    pub kind: ModuleKind,
    /// ModuleItem ID (`IDM_PKW_12`) and its submodule's (`IDS_PKW_12`).
    pub id: String,
    pub submodule_id: String,
    /// The API its submodules are in: 0, or PROFIdrive's [`PROFIDRIVE_API`].
    pub api: u32,
    /// PROFIdrive's module access point: a submodule without data in
    /// subslot [`ACCESS_POINT_SUBSLOT`], before the data submodule.
    pub access_point: Option<AccessPoint>,
    /// The [`Category`] it is listed under.
    pub category: String,
    pub name: TextRef,
    pub info: TextRef,
    /// Its data submodule's name and info: the module's, unless the
    /// description gives the submodule its own.
    pub submodule_name: TextRef,
    pub submodule_info: TextRef,
    /// ModuleIdentNumber, and its data submodule's SubmoduleIdentNumber
    /// (the same in gsdc's numbering).
    pub ident_number: u32,
    pub submodule_ident_number: u32,
    pub layout: Layout,
    /// Its name in generated code: `pkw_pzd12`.
    pub ident: Ident,
    /// The words each way, in telegram order.
    pub input: Vec<DataItem>,
    pub output: Vec<DataItem>,
    pub records: Vec<ParameterRecord>,
}

impl Module {
    /// A PROFIdrive telegram: the profile's, in the profile's API.
    pub fn is_profidrive(&self) -> bool {
        self.api == PROFIDRIVE_API
    }

    /// Its data items one way, each with the telegram word it starts at
    /// (from 0, the PKW channel's words counted).
    pub fn placed_items(&self, direction: Direction) -> impl Iterator<Item = (u8, &DataItem)> {
        let items = match direction {
            Direction::Out => &self.output,
            Direction::In => &self.input,
        };
        items.iter().scan(0, |word, item| {
            let at = *word;
            *word += item.words();
            Some((at, item))
        })
    }

    /// The PZD words (from 1, after the PKW channel) where a 32-bit item
    /// starts: telegram 2's NSOLL_B and NIST_B at 2, the same both ways.
    pub fn double_words(&self) -> Vec<u8> {
        self.placed_items(Direction::Out)
            .filter(|(_, item)| item.double_word)
            .map(|(at, _)| at + 1 - self.layout.pkw_words())
            .collect()
    }

    /// The subslot of its data submodule: after PROFIdrive's access point,
    /// or the default.
    pub fn data_subslot(&self) -> u16 {
        if self.access_point.is_some() {
            PROFIDRIVE_DATA_SUBSLOT
        } else {
            DEFAULT_SUBSLOT
        }
    }
}

/// The module access point (MAP) submodule of a PROFIdrive module.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct AccessPoint {
    pub id: String,
    pub name: TextRef,
    pub info: TextRef,
}

/// PROFIdrive's API (14848).
pub const PROFIDRIVE_API: u32 = 0x3A00;
/// A PROFIdrive module's access point is in subslot 1, with this
/// submodule ident number (gsdc's numbering), and its data submodule in
/// subslot 2, as ABB's FENA places them (no public statement of 0xFFFF was
/// found; see docs/description.md).
pub const ACCESS_POINT_SUBSLOT: u16 = 1;
pub const ACCESS_POINT_IDENT: u32 = 0x0000_FFFF;
pub const PROFIDRIVE_DATA_SUBSLOT: u16 = 2;

/// One item of IO data: an Unsigned16 word, or an Unsigned32 value over
/// two words (high word first, as PROFINET sends it); a word with named
/// bits shows them.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct DataItem {
    pub text: TextRef,
    pub bits: Vec<BitItem>,
    /// Two words: PROFIdrive's 32-bit setpoint and actual value.
    pub double_word: bool,
}

impl DataItem {
    /// The PZD words it spans.
    pub fn words(&self) -> u8 {
        if self.double_word {
            2
        } else {
            1
        }
    }

    /// Its DataType in the GSDML file.
    pub fn data_type(&self) -> &'static str {
        item_data_type(self.double_word)
    }
}

/// The GSDML DataType of a data item, and of its fail-safe value: an
/// Unsigned32 for a 32-bit item, else an Unsigned16.
fn item_data_type(double_word: bool) -> &'static str {
    if double_word {
        "Unsigned32"
    } else {
        "Unsigned16"
    }
}

#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct BitItem {
    pub offset: u8,
    pub text: TextRef,
}

/// A parameter record: one Ref per mapping entry, each of its set's type
/// (Unsigned16 but for a setting of a byte), at consecutive byte offsets
/// from 0.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct ParameterRecord {
    pub kind: MappingKind,
    pub index: u16,
    pub name: TextRef,
    /// Bytes: each Ref's and each fail-safe value's.
    pub length: u16,
    pub refs: Vec<RecordRef>,
    /// After the Refs of the settings record, with
    /// `[profinet.fail_safe_values]`: one value per output PZD item of the
    /// module.
    pub fail_safe: Vec<FailSafeValue>,
}

/// A value of a module's settings record for one of its output PZD items:
/// the item's width, 0 by default, which the controller may change.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct FailSafeValue {
    pub offset: u16,
    pub text: TextRef,
    /// An Unsigned32 for a 32-bit item (telegram 2's NSOLL_B), else an
    /// Unsigned16.
    pub double_word: bool,
}

impl FailSafeValue {
    pub fn bytes(&self) -> u16 {
        if self.double_word {
            4
        } else {
            2
        }
    }

    /// The largest value its type holds, which it may be.
    pub fn max(&self) -> u32 {
        if self.double_word {
            u32::MAX
        } else {
            u16::MAX.into()
        }
    }

    /// Its DataType in the GSDML file.
    pub fn data_type(&self) -> &'static str {
        item_data_type(self.double_word)
    }
}

#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct RecordRef {
    pub offset: u16,
    pub entry: EntryKey,
    pub text: TextRef,
    /// The entry's default, or the value its module writes.
    pub default: u16,
    /// False where the module fixes the value.
    pub changeable: bool,
    /// The ValueItem of its choices, when its set has them.
    pub value_item: Option<String>,
}

/// The choices of a mapping's set or of a record value, with their
/// TextIds; a record value's help.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct ValueItem {
    pub id: String,
    pub help: Option<TextRef>,
    pub assignments: Vec<(i64, TextRef)>,
}

/// A parameter record of the card's own, of the device access point's
/// submodule or of a port (not of a drive parameter): values at the
/// places the description gives, which the controller writes at startup.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct SubmoduleRecord {
    pub index: u16,
    pub name: TextRef,
    /// Bytes: as far as its values reach.
    pub length: u16,
    /// In the description's order.
    pub values: Vec<RecordValue>,
}

/// A value of a [`SubmoduleRecord`].
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct RecordValue {
    pub text: TextRef,
    /// Its first byte in the record.
    pub offset: u16,
    pub data_type: RecordValueType,
    pub default: u32,
    /// What it may hold, both ends included: its choices' least and most
    /// value when it has choices.
    pub min: u32,
    pub max: u32,
    /// Its ValueItem, when it has choices (only their values are allowed)
    /// or a help.
    pub value_item: Option<ValueItem>,
    pub changeable: bool,
    pub visible: bool,
}

impl SubmoduleRecord {
    /// What the device reads from it, texts aside: its index, length, and
    /// each value's place, type, default and what it may hold. Device
    /// access points of one ident number give each index so alike (E162).
    pub fn decoded_alike(&self, other: &SubmoduleRecord) -> bool {
        let shape = |r: &SubmoduleRecord| {
            let values = r.values.iter().map(|v| {
                let choices: Vec<i64> = v.choices().iter().map(|(value, _)| *value).collect();
                let place = (v.offset, v.data_type, v.default);
                (place, (v.min, v.max), choices, v.changeable)
            });
            (r.index, r.length, values.collect::<Vec<_>>())
        };
        shape(self) == shape(other)
    }
}

impl RecordValue {
    /// Whether it may hold `value`.
    pub fn allows(&self, value: u32) -> bool {
        match self.choices() {
            [] => (self.min..=self.max).contains(&value),
            choices => choices.iter().any(|(v, _)| *v == i64::from(value)),
        }
    }

    /// Its choices with their texts; none when any value of its range is
    /// allowed.
    pub fn choices(&self) -> &[(i64, TextRef)] {
        self.value_item.as_ref().map_or(&[], |v| &v.assignments)
    }
}

/// How a record holds a value: whole bytes, high byte first, or some bits
/// of one byte.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RecordValueType {
    Unsigned8,
    Unsigned16,
    Unsigned32,
    /// Bits `first` to `last` of the byte: GSDML's `Bit` when one, else
    /// `BitArea`.
    Bits {
        first: u8,
        last: u8,
    },
}

impl RecordValueType {
    /// The bytes it takes from its offset.
    pub fn bytes(self) -> u16 {
        match self {
            Self::Unsigned16 => 2,
            Self::Unsigned32 => 4,
            Self::Unsigned8 | Self::Bits { .. } => 1,
        }
    }

    /// The most it can hold.
    pub fn max(self) -> u32 {
        match self {
            Self::Unsigned8 => u8::MAX.into(),
            Self::Unsigned16 => u16::MAX.into(),
            Self::Unsigned32 => u32::MAX,
            Self::Bits { first, last } => (1 << (last - first + 1)) - 1,
        }
    }

    /// Its `DataType` in the GSDML file.
    pub fn gsdml_name(self) -> &'static str {
        match self {
            Self::Unsigned8 => "Unsigned8",
            Self::Unsigned16 => "Unsigned16",
            Self::Unsigned32 => "Unsigned32",
            Self::Bits { first, last } if first == last => "Bit",
            Self::Bits { .. } => "BitArea",
        }
    }

    /// The bits it takes of each of its bytes, from its offset.
    pub fn masks(self) -> Vec<u8> {
        match self {
            Self::Bits { first, last } => vec![super::bits_of_byte(first, last)],
            whole => vec![0xFF; usize::from(whole.bytes())],
        }
    }
}
