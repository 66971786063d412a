//! What the device needs to know of a card, as the layouts give it.

use wire_firmware::drive::Model;
use wire_firmware::gsdc_support::Mapping;
use wire_firmware::pkw::PkwKind;

/// One submodule: where it sits and what it carries.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Submodule {
    pub subslot: u16,
    pub ident: u32,
    pub api: u32,
    pub input_len: u16,
    pub output_len: u16,
}

/// A parameter record the controller writes to a module's submodule at
/// startup, and the layout's decoder for it.
#[derive(Clone, Copy)]
pub struct Record {
    pub subslot: u16,
    pub index: u16,
    pub name: &'static str,
    pub decode: fn(&[u8]) -> Result<Vec<u16>, String>,
    /// The entries the values set, in order: each names the drive parameter
    /// that holds it, if any.
    pub mappings: &'static [Mapping],
}

/// A module a slot may take.
#[derive(Clone)]
pub struct Module {
    /// The GSDML's `ModuleItem` ID.
    pub gsdml_id: &'static str,
    pub ident: u32,
    pub slots: &'static [u16],
    pub submodules: Vec<Submodule>,
    pub records: Vec<Record>,
    /// Whether its telegrams start with the PKW channel.
    pub pkw: bool,
}

/// The card: identity, access point and modules.
#[derive(Clone)]
pub struct Card {
    pub name: &'static str,
    pub vendor_id: u16,
    pub device_id: u16,
    pub dap_ident: u32,
    /// The access point's own submodule, its interface and its ports.
    pub dap_submodules: Vec<Submodule>,
    pub modules: Vec<Module>,
    pub pkw: Option<PkwKind>,
    /// The status word the drive answers to a control word, where the layout
    /// names their bits.
    pub status_of: Option<fn(u16) -> u16>,
    pub drive: &'static Model,
}

impl Card {
    pub fn module(&self, gsdml_id: &str) -> Option<&Module> {
        self.modules.iter().find(|m| m.gsdml_id == gsdml_id)
    }
}
