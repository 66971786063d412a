//! What only PROFINET needs: identity numbers, the device access point,
//! the selectable modules and the parameter records.

use super::Layout;

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Profinet {
    /// Schema version, e.g. "2.32".
    pub gsdml_version: String,
    pub date: Date,
    pub file_name: String,
    pub vendor_id: u16,
    pub vendor_id_placeholder: bool,
    pub device_id: u16,
    pub device_id_placeholder: bool,
    /// Info text of this bus's device identity, when it differs from the device's.
    pub info: Option<super::Text>,
    /// DNS_CompatibleName: the default name of station.
    pub dns_name: String,
    pub ports: u8,
    /// Units of 31.25 us.
    pub min_device_interval: u16,
    pub modules: Vec<Module>,
    pub records: Vec<ParameterRecord>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Date {
    pub year: u16,
    pub month: u8,
    pub day: u8,
}

impl Date {
    /// `yyyymmdd`, as GSDML file names write it.
    pub fn compact(self) -> String {
        format!("{:04}{:02}{:02}", self.year, self.month, self.day)
    }
}

/// The device access point's ModuleIdentNumber and its submodule's.
pub const DAP_IDENT: u32 = 0x0000_0001;
/// Subslots of the interface and of its first port (IEC 61158-6-10). They
/// are also the submodule ident numbers of the interface and the ports, as
/// p-net does it, so firmware and GSDML share one number for each.
pub const INTERFACE_SUBSLOT: u16 = 0x8000;
pub const FIRST_PORT_SUBSLOT: u16 = 0x8001;
/// The slot modules are plugged into; the DAP is in slot 0.
pub const MODULE_SLOT: u16 = 1;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ModuleKind {
    /// PKW (or not) and PZD words, as the description maps them.
    Pzd,
    /// PROFIdrive standard telegram 1: STW1, NSOLL_A out; ZSW1, NIST_A in.
    StandardTelegram1,
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Module {
    pub kind: ModuleKind,
    pub name: String,
    /// ModuleIdentNumber; the module's one submodule has the same number.
    pub ident: u32,
    pub layout: Layout,
}

impl Module {
    /// Stable ident numbers, so firmware and GSDML agree without a table:
    /// 0x0000_0010 standard telegram 1, 0x0000_01nn nn PZD words, 0x0000_02nn
    /// the PKW and nn PZD words.
    pub fn ident_for(kind: ModuleKind, layout: Layout) -> u32 {
        match kind {
            ModuleKind::StandardTelegram1 => 0x10,
            ModuleKind::Pzd => {
                (if layout.pkw { 0x200 } else { 0x100 }) + u32::from(layout.pzd_words)
            }
        }
    }
}

/// A parameter record: one Unsigned16 Ref per entry of the mapping sets it
/// holds, in order, at byte offsets 0, 2, 4, ... There is one record per
/// kind of mapping, holding every set of that kind.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ParameterRecord {
    pub kind: super::MappingKind,
    pub index: u16,
    /// Indexes into `Ir::mappings`.
    pub sets: Vec<usize>,
}
