//! The parameter telegram's User_Prm_Data, as lowering laid it out: the
//! constant bytes (the DPV1 status bytes), then one Unsigned16 per mapping
//! entry, high byte first.

use super::mapping::{meaning, MappingInForce, ValueSource};
use crate::ir::profibus::UserPrm;
use crate::ir::{EntryKey, Ir};
use serde::Serialize;

#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Prm {
    pub len: usize,
    pub constant: Vec<ConstantByte>,
    pub params: Vec<PrmValue>,
}

/// A byte of the constant part: its value and what the GSD sets it to.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct ConstantByte {
    pub offset: usize,
    pub name: String,
    pub value: u8,
    pub default: u8,
}

/// One mapping entry's Unsigned16.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct PrmValue {
    pub offset: usize,
    /// The `ExtUserPrmData` reference number.
    pub id: u16,
    #[serde(skip)]
    pub entry: EntryKey,
    /// The mapping entry's name: `PZD3(master->slaver)`.
    pub name: String,
    pub value: u16,
    /// The parameter it names (`F0-12`) or the choice's text; `None` for a
    /// value that is not one of the choices.
    pub meaning: Option<String>,
    pub default: u16,
    /// What the default means, as `meaning` says it.
    pub default_meaning: Option<String>,
    /// Whether the value is one the mapping allows; the card refuses a
    /// parameter telegram with one that is not.
    pub allowed: bool,
}

impl Prm {
    /// The mapping these values put in force.
    pub fn mapping(&self) -> MappingInForce {
        let mut mapping = MappingInForce::defaults();
        for param in &self.params {
            mapping.set(param.entry, param.value, ValueSource::ParameterTelegram);
        }
        mapping
    }
}

/// Decodes `bytes`, which must be as long as `user_prm`.
pub(super) fn decode(ir: &Ir, user_prm: &UserPrm, bytes: &[u8]) -> Prm {
    debug_assert_eq!(bytes.len(), usize::from(user_prm.len));
    let constant = user_prm
        .constant
        .iter()
        .zip(bytes)
        .enumerate()
        .map(|(offset, (&default, &value))| ConstantByte {
            offset,
            // Lowering puts the DPV1 status bytes there, and only them.
            name: format!("DPV1_Status_{}", offset + 1),
            value,
            default,
        })
        .collect();
    let params = user_prm
        .params()
        .map(|param| {
            let offset = usize::from(param.offset);
            let value = u16::from_be_bytes([bytes[offset], bytes[offset + 1]]);
            let (set, entry) = ir.mappings.entry(param.entry);
            PrmValue {
                offset,
                id: param.id,
                entry: param.entry,
                name: entry.name.en.clone(),
                value,
                meaning: meaning(ir, &set.allowed, value),
                default: entry.default,
                default_meaning: meaning(ir, &set.allowed, entry.default),
                allowed: set.allowed.contains(i64::from(value)),
            }
        })
        .collect();
    Prm {
        len: bytes.len(),
        constant,
        params,
    }
}
