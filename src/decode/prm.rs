//! The parameter telegram's User_Prm_Data, as lowering laid it out: the
//! constant bytes (the DPV1 status bytes), then one Unsigned16 per mapping
//! entry, high byte first, then a gateway's parameters.

use super::mapping::{meaning, MappingInForce, ValueSource};
use crate::ir::profibus::{PrmHolds, UserPrm};
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

/// One parameter's value.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct PrmValue {
    pub offset: usize,
    /// The `ExtUserPrmData` reference number.
    pub id: u16,
    /// The mapping entry it sets; `None` for a gateway's parameter.
    #[serde(skip)]
    pub entry: Option<EntryKey>,
    /// Its name: `PZD3(master->slaver)`, `Slave 2 TPDO words`.
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
            if let Some(entry) = param.entry {
                mapping.set(entry, param.value, ValueSource::ParameterTelegram);
            }
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
            let value = param.data_type.read(bytes, offset);
            let facts = ir.prm_facts(param);
            let meaning = |value| match facts.holds {
                PrmHolds::Mapping { set, .. } => meaning(ir, &set.allowed, value),
                PrmHolds::Number { .. } => None,
            };
            PrmValue {
                offset,
                id: param.id,
                entry: match param.value {
                    crate::ir::profibus::PrmValue::Entry(key) => Some(key),
                    _ => None,
                },
                name: facts.name.en.clone(),
                value,
                meaning: meaning(value),
                default: facts.default,
                default_meaning: meaning(facts.default),
                allowed: facts.holds.contains(value),
            }
        })
        .collect();
    Prm {
        len: bytes.len(),
        constant,
        params,
    }
}
