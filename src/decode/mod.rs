//! Captured bus data read against a description (`gsdc decode`): a cyclic
//! telegram of one module, the parameter telegram's User_Prm_Data, the
//! device-related diagnosis block; for a gateway, a module's words of the
//! nodes, the node parameters, and the diagnosis block by its type.
//!
//! Pure: the IR and bytes in, a typed decoded value out. Names, offsets and
//! mappings come from the IR, the PKW channel is read by the firmware's own
//! codecs (`crate::pkw`). Data that does not fit (a wrong length, an unknown
//! module, a bad hex digit) is a diagnostic (E410-E417) placed in the text
//! it was read from; a telegram that fits but that the card would refuse (an
//! undefined PKW command, a mapping value not allowed) decodes, and says so.
//! The decoded values serialize as `gsdc decode --format json` prints them.

mod diagnosis;
mod gateway;
mod hex;
mod mapping;
mod module;
mod pkw_channel;
mod prm;
mod profidrive;
mod telegram;

pub use diagnosis::{DiagnosisBlock, GatewayDiagnosis, Unread};
pub use hex::Hex;
pub use mapping::{MappingInForce, ValueSource};
pub use module::{find_module, Module};
pub use pkw_channel::{Channel, Pkw, PkwSide};
pub use prm::Prm;
pub use telegram::{Carried, DecodedWord, GatewayData, NodeTotals, Telegram};

use crate::diag::Diagnostic;
use crate::ir::{Direction, Ir};

/// A telegram of `module` sent in `direction` (the one a gateway's module
/// goes, `find_module` checked it), with the PZD words named after
/// `mapping`, or a gateway's words after its node configuration; E412
/// unless it is as long as the module's.
pub fn telegram(
    ir: &Ir,
    module: Module<'_>,
    direction: Direction,
    hex: &Hex,
    mapping: &MappingInForce,
) -> Result<Telegram, Diagnostic> {
    let bytes = hex.exactly(module.bytes(), &module.name(), &module.summary())?;
    let cyclic = |layout| telegram::decode(ir, module, layout, direction, bytes, mapping);
    Ok(match module {
        Module::Ppo(_, layout) => cyclic(layout),
        Module::Profinet(m) => cyclic(m.layout),
        Module::Gateway(g, m) => gateway::telegram(g, m, bytes, mapping),
    })
}

/// The parameter telegram's User_Prm_Data (without the 7 standard bytes of
/// Set_Prm); E414 when the description has no PROFIBUS part, E412 unless it
/// is as long as the GSD says.
pub fn prm(ir: &Ir, hex: &Hex) -> Result<Prm, Diagnostic> {
    let profibus = ir.profibus.as_ref().ok_or_else(|| {
        Diagnostic::error("E414", "the description has no parameter telegram")
            .help("User_Prm_Data is PROFIBUS's; this description has no [profibus] part")
    })?;
    let user_prm = &profibus.user_prm;
    let bytes = hex.exactly(
        usize::from(user_prm.len),
        "User_Prm_Data",
        &prm_help(ir, &profibus.file_name, user_prm),
    )?;
    Ok(prm::decode(ir, user_prm, bytes))
}

/// "MD810DP.GSD's User_Prm_Data is 63 bytes: 3 DPV1 status bytes, then 2
/// bytes each for 12 pzd_out, 12 pzd_in, 6 dpv1_index; ...", or for a
/// gateway "... 61 bytes: the 61 gateway parameters from Number of CANopen
/// slaves to Slave 30 RPDO words; ...".
fn prm_help(ir: &Ir, file_name: &str, user_prm: &crate::ir::profibus::UserPrm) -> String {
    let mut parts = Vec::new();
    if !user_prm.constant.is_empty() {
        parts.push(format!("{} DPV1 status bytes", user_prm.constant.len()));
    }
    let blocks: Vec<String> = user_prm
        .blocks
        .iter()
        .map(|b| format!("{} {}", b.params.len(), b.kind.key()))
        .collect();
    if !blocks.is_empty() {
        parts.push(format!("2 bytes each for {}", blocks.join(", ")));
    }
    if let (Some(first), Some(last)) = (user_prm.gateway.first(), user_prm.gateway.last()) {
        parts.push(format!(
            "the {} gateway parameters from {} to {}",
            user_prm.gateway.len(),
            ir.prm_facts(first).name.en,
            ir.prm_facts(last).name.en
        ));
    }
    format!(
        "{file_name}'s User_Prm_Data is {} bytes: {}; give it without the 7 standard bytes of Set_Prm",
        user_prm.len,
        parts.join(", then ")
    )
}

/// The device-related diagnosis block, header first; E414 when the
/// description gives none, E412 unless it is as long as the description
/// says (a gateway's: as its header says), E417 (at the header) when its
/// header is not that block's.
pub fn diagnosis(ir: &Ir, hex: &Hex) -> Result<DiagnosisBlock, Diagnostic> {
    if let Some((g, d)) = ir
        .gateway
        .as_ref()
        .and_then(|g| Some((g, g.diagnosis.as_ref()?)))
    {
        return gateway::diagnosis(g, d, hex);
    }
    let diagnosis = ir
        .profibus
        .as_ref()
        .and_then(|p| p.diagnosis.as_ref())
        .ok_or_else(|| {
            Diagnostic::error("E414", "the description has no device-related diagnosis")
                .help("the diagnosis block is described by [profibus.diagnosis], or a gateway's by [gateway.diagnosis]")
        })?;
    let help = format!(
        "the block is {} bytes: the header 0x{:02X}, then the device's bytes",
        diagnosis.length, diagnosis.length
    );
    let bytes = hex.exactly(usize::from(diagnosis.length), "the diagnosis block", &help)?;
    diagnosis::decode(diagnosis, bytes).map_err(|d| d.at_opt(hex.span(0)))
}

/// `out` or `in`, as `--direction` takes it.
fn serialize_direction<S: serde::Serializer>(
    direction: &Direction,
    serializer: S,
) -> Result<S::Ok, S::Error> {
    serializer.serialize_str(match direction {
        Direction::Out => "out",
        Direction::In => "in",
    })
}

#[cfg(test)]
pub(crate) mod tests;
