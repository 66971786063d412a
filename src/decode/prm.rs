//! The parameter telegram's User_Prm_Data, as lowering laid it out: the
//! constant bytes (the DPV1 status bytes), then one parameter per mapping
//! entry (an Unsigned16, or a setting's type), high byte first, then a
//! gateway's parameters (bytes, words or bit areas), and what a gateway's
//! add up to.

use super::gateway::totals;
use super::mapping::{meaning, MappingInForce, ValueSource};
use super::telegram::NodeTotals;
use crate::ir::profibus::{self, PrmHolds, UserPrm};
use crate::ir::Ir;
use serde::Serialize;

#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Prm {
    pub len: usize,
    pub constant: Vec<ConstantByte>,
    pub params: Vec<PrmValue>,
    /// A gateway's nodes under these values.
    pub gateway: Option<NodeTotals>,
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
    /// What it sets: a mapping entry or a gateway's parameter.
    #[serde(skip)]
    pub sets: profibus::PrmValue,
    /// Its name: `PZD3(master->slaver)`, `Slave 2 TPDO words`.
    pub name: String,
    /// How it is stored, as the GSD names it: `Unsigned16`, `BitArea(0-3)`.
    pub data_type: String,
    pub value: u16,
    /// The parameter it names (`F0-12`) or the choice's text; `None` for a
    /// value that is not one of the choices, and for a number.
    pub meaning: Option<String>,
    pub default: u16,
    /// What the default means, as `meaning` says it.
    pub default_meaning: Option<String>,
    /// The numbers a gateway's parameter allows, both ends included; `None`
    /// for a mapping entry.
    pub range: Option<[u16; 2]>,
    /// Whether the value is one the parameter allows; the card refuses a
    /// parameter telegram with one that is not.
    pub allowed: bool,
}

impl Prm {
    /// The mapping and the gateway's node configuration these values put in
    /// force.
    pub fn mapping(&self) -> MappingInForce {
        let mut mapping = MappingInForce::defaults();
        for param in &self.params {
            match param.sets {
                profibus::PrmValue::Entry(entry) => {
                    mapping.set(entry, param.value, ValueSource::ParameterTelegram)
                }
                profibus::PrmValue::Gateway(key) => mapping.set_gateway(key, param.value),
                // The card's own parameters map nothing.
                profibus::PrmValue::Card(_) => {}
            }
        }
        mapping
    }
}

/// Decodes `bytes`, which must be as long as `user_prm`.
pub(super) fn decode(ir: &Ir, user_prm: &UserPrm, bytes: &[u8]) -> Prm {
    debug_assert_eq!(bytes.len(), usize::from(user_prm.len));
    let dpv1 = ir.profibus.as_ref().is_some_and(|p| p.dpv1.is_some());
    let constant = user_prm
        .constant
        .iter()
        .zip(bytes)
        .enumerate()
        .map(|(offset, (&default, &value))| ConstantByte {
            offset,
            // A DPV1 slave's first three are its status bytes; a
            // description may state more (`[profibus.user_prm] constant`).
            name: match (dpv1, offset) {
                (true, 0..=2) => format!("DPV1_Status_{}", offset + 1),
                _ => format!("Ext_User_Prm_Data_Const byte {offset}"),
            },
            value,
            default,
        })
        .collect();
    let params: Vec<PrmValue> = user_prm
        .params()
        .map(|param| {
            let offset = usize::from(param.offset);
            let value = param.data_type.read(bytes, offset);
            let facts = ir.prm_facts(param);
            let meaning = |value| match facts.holds {
                PrmHolds::Mapping { set, .. } => meaning(ir, &set.allowed, value),
                PrmHolds::Card(p) => meaning(ir, &p.allowed, value),
                PrmHolds::Number { .. } => None,
            };
            PrmValue {
                offset,
                id: param.id,
                sets: param.value,
                name: facts.name.en.clone(),
                data_type: param.data_type.to_string(),
                value,
                meaning: meaning(value),
                default: facts.default,
                default_meaning: meaning(facts.default),
                range: match facts.holds {
                    PrmHolds::Number { min, max } => Some([min, max]),
                    PrmHolds::Mapping { .. } | PrmHolds::Card(_) => None,
                },
                allowed: facts.holds.contains(value),
            }
        })
        .collect();
    let prm = Prm {
        len: bytes.len(),
        constant,
        params,
        gateway: None,
    };
    let gateway = ir.gateway.as_ref().map(|g| totals(g, &prm.mapping()));
    Prm { gateway, ..prm }
}
