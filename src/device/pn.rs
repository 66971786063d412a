//! A PROFINET IO device as its GSDML file describes it.
//!
//! What identifies each part is typed (ident numbers, subslots, record
//! indexes, byte offsets), with its texts, IO data and parameters; the
//! rest of an element and of the elements inside it that the model has no
//! type for is kept in its `attributes` ([`Attribute`]), by path and name.

use std::sync::Arc;

use super::{Attribute, ParameterData, Place, Text};

/// A GSDML file's device.
#[derive(Debug, Clone, Default, PartialEq)]
#[non_exhaustive]
pub struct PnDevice {
    /// The file's own name, when the reader was given one: it carries the
    /// release date (`GSDML-V2.32-Vendor-Family-20230830.xml`).
    pub file_name: Option<String>,
    /// The schema version `xsi:schemaLocation` names (`V2.32`).
    pub schema_version: Option<String>,
    pub vendor_id: Option<u32>,
    pub device_id: Option<u32>,
    /// The rest of `DeviceIdentity` and `DeviceFunction`: vendor name, info
    /// text, main and product family.
    pub identity: Vec<Attribute>,
    /// The languages of the texts besides the primary one (`de`, `zh`).
    pub languages: Vec<String>,
    pub daps: Vec<Dap>,
    /// `ModuleList`.
    pub modules: Vec<PnModule>,
    /// `SubmoduleList`: submodules plugged into modules' subslots.
    pub submodules: Vec<Submodule>,
    /// `ChannelDiagList` and `ChannelProcessAlarmList`.
    pub diagnosis: Vec<DiagItem>,
    /// `UnitDiagTypeList`.
    pub unit_diagnosis: Vec<UnitDiag>,
    /// What else `ApplicationProcess` holds (`LogBookEntryList`, ...).
    pub other: Vec<Attribute>,
    pub place: Place,
}

/// `DeviceAccessPointItem`: a module (the schema derives it from
/// `ModuleItem`) with the catalogue of modules it takes.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Dap {
    /// Its ident number, texts, attributes and submodules (the interface
    /// and ports among them).
    pub item: PnModule,
    /// `UseableModules`: the modules the catalogue offers under this DAP.
    pub useable_modules: Vec<ItemRef>,
    /// `SubslotList`: each labelled subslot's number and label, in the
    /// file's order (also among `item`'s attributes, which the diff
    /// compares).
    pub subslot_labels: Vec<(Option<u16>, Option<Text>)>,
}

/// `ModuleItem`.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct PnModule {
    pub id: String,
    pub ident: Option<u32>,
    pub name: Option<Text>,
    pub info: Option<Text>,
    pub attributes: Vec<Attribute>,
    pub useable_submodules: Vec<ItemRef>,
    /// Its virtual submodules (and ports, for a module that has some).
    pub submodules: Vec<Submodule>,
    pub place: Place,
}

/// Which list a submodule comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[non_exhaustive]
pub enum SubmoduleKind {
    /// `VirtualSubmoduleItem`: fixed in its module.
    Virtual,
    /// `SubmoduleItem` of the `SubmoduleList`.
    Pluggable,
    /// `InterfaceSubmoduleItem`.
    Interface,
    /// `PortSubmoduleItem`.
    Port,
}

impl SubmoduleKind {
    pub fn element(self) -> &'static str {
        match self {
            SubmoduleKind::Virtual => "VirtualSubmoduleItem",
            SubmoduleKind::Pluggable => "SubmoduleItem",
            SubmoduleKind::Interface => "InterfaceSubmoduleItem",
            SubmoduleKind::Port => "PortSubmoduleItem",
        }
    }

    pub fn from_element(name: &str) -> Option<SubmoduleKind> {
        [
            SubmoduleKind::Virtual,
            SubmoduleKind::Pluggable,
            SubmoduleKind::Interface,
            SubmoduleKind::Port,
        ]
        .into_iter()
        .find(|k| k.element() == name)
    }
}

/// A submodule of any kind.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Submodule {
    pub kind: SubmoduleKind,
    pub id: String,
    pub ident: Option<u32>,
    /// `SubslotNumber`, for an interface or a port.
    pub subslot: Option<u32>,
    pub name: Option<Text>,
    pub info: Option<Text>,
    /// Everything else: `API`, `FixedInSubslots`, `IOData@IOPS_Length`,
    /// the interface's timing, a port's MAU types...
    pub attributes: Vec<Attribute>,
    pub io: IoData,
    /// `ParameterRecordDataItem`s.
    pub records: Vec<Record>,
    pub place: Place,
}

/// A submodule's cyclic data.
#[derive(Debug, Clone, Default, PartialEq)]
#[non_exhaustive]
pub struct IoData {
    /// Device to controller.
    pub input: Option<IoPart>,
    /// Controller to device.
    pub output: Option<IoPart>,
}

/// `Input` or `Output`: its data items in order.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct IoPart {
    /// `Consistency`.
    pub attributes: Vec<Attribute>,
    pub items: Vec<DataItem>,
    pub place: Place,
}

impl IoPart {
    /// The bytes of data (without the status bytes).
    pub fn len(&self) -> u32 {
        self.items.iter().map(DataItem::size).sum()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// `DataItem`.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct DataItem {
    pub data_type: Arc<str>,
    /// `Length`, for strings and octet strings.
    pub length: Option<u32>,
    pub text: Option<Text>,
    pub use_as_bits: bool,
    /// `BitDataItem`s: bit offset and text.
    pub bits: Vec<(u32, Text)>,
    /// Other attributes (`Subordinate`).
    pub attributes: Vec<Attribute>,
    pub place: Place,
}

impl DataItem {
    /// Bytes it takes: its `Length`, else its type's size (0 when unknown).
    pub fn size(&self) -> u32 {
        match crate::gsdml::datatype::io_size(&self.data_type) {
            Some(crate::gsdml::datatype::Size::Bytes(n)) => n,
            _ => self.length.unwrap_or(0),
        }
    }
}

/// `ParameterRecordDataItem`: a record the controller writes at startup.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Record {
    pub index: u32,
    pub name: Option<Text>,
    /// Its `Length`, `Const` and `Ref`s.
    pub data: ParameterData,
    /// `TransferSequence`, `API` and the rest.
    pub attributes: Vec<Attribute>,
    pub place: Place,
}

/// `ModuleItemRef` or `SubmoduleItemRef`: an item the catalogue offers in
/// a DAP or module, with the slots or subslots it may go in.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct ItemRef {
    /// The ID of the item it names.
    pub target: String,
    /// That item's ident number, when the file has the item.
    pub ident: Option<u32>,
    /// `AllowedInSlots`, `UsedInSlots`, `FixedInSlots` (or subslots).
    pub attributes: Vec<Attribute>,
    pub place: Place,
}

/// A channel diagnosis or process alarm item: its error type and texts,
/// with its extended items.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct DiagItem {
    /// The element: `ChannelDiagItem`, `ProfileChannelDiagItem`,
    /// `ExtChannelDiagItem`...
    pub element: Arc<str>,
    pub error_type: u32,
    pub name: Option<Text>,
    pub help: Option<Text>,
    /// `API` and the rest.
    pub attributes: Vec<Attribute>,
    pub extended: Vec<DiagItem>,
    pub place: Place,
}

/// `UnitDiagTypeItem`: a manufacturer-specific diagnosis structure.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct UnitDiag {
    /// `UserStructureIdentifier`.
    pub id: u32,
    pub data: ParameterData,
    pub attributes: Vec<Attribute>,
    pub place: Place,
}
