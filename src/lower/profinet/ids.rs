//! The GSDML IDs and TextIds gsdc gives: derived from what each thing is,
//! so the same description always gives the same IDs.

use crate::ir::profinet::ModuleKind;
use crate::ir::{Layout, MappingKind, MappingSet};

/// TextIds of the first DAP's name (its submodule's too) and of the
/// device's description, which DeviceIdentity and the first DAP share.
pub const DEVICE_NAME: &str = "IDT_DEVICE_NAME";
pub const DEVICE_INFO: &str = "IDT_DEVICE_INFO";
pub const INTERFACE_TEXT: &str = "IDT_INTERFACE";
/// TextIds of the labels on the device: the interface's, and each port's
/// (this and its number).
pub const INTERFACE_LABEL_TEXT: &str = "IDT_LABEL_INTERFACE";
pub const PORT_LABEL_TEXT: &str = "IDT_LABEL_PORT_";
/// TextIds of the empty module's name and info.
pub const EMPTY_MODULE_NAME: &str = "IDT_EMPTY_NAME";
pub const EMPTY_MODULE_INFO: &str = "IDT_EMPTY_INFO";
/// The device symbol's GraphicItem.
pub const DEVICE_SYMBOL: &str = "IDG_DEVICE_SYMBOL";

/// A module's part of its IDs and TextIds: `PKW_12` (PKW and 12 PZD
/// words), `PZD_12`, `STD_TEL_1`. Lowering gives each PZD length once per
/// PKW choice.
pub fn module_tag(kind: ModuleKind, layout: Layout) -> String {
    match kind {
        ModuleKind::StandardTelegram1 => "STD_TEL_1".into(),
        ModuleKind::StandardTelegram2 => "STD_TEL_2".into(),
        ModuleKind::Pzd if layout.pkw => format!("PKW_{}", layout.pzd_words),
        ModuleKind::Pzd => format!("PZD_{}", layout.pzd_words),
    }
}

pub fn kind_tag(kind: MappingKind) -> String {
    kind.key().to_uppercase()
}

/// A set's part of its ValueItem's ID and TextIds: its kind, and for a
/// setting (each is a set of one entry) its number too.
pub fn value_tag(set: &MappingSet) -> String {
    match set.key.kind {
        MappingKind::Setting => format!("{}_{}", kind_tag(set.key.kind), set.key.first),
        kind => kind_tag(kind),
    }
}
