//! The firmware's support code (`templates/support/`), compiled into the
//! library so that what gsdc says about a telegram (`gsdc decode`) and the
//! telegrams it prints (the datasheet's worked examples) are what the
//! card's firmware, built from the same files, does: the PKW codecs, and
//! the bit numbering of control and status words and of diagnosis areas.
//! Crate-private; firmware gets the same code as `gsdc_support.rs`.

// The support code is written for firmware, which uses all of it; the
// library uses the parts below, and the Rust emitter's tests all of it
// (`emit::rust::support_tests`). Loaded here only, once.
#[allow(dead_code, unused_imports)]
#[path = "../templates/support/mod.rs"]
pub(crate) mod support;

/// What the PROFIdrive channel's ids and error numbers mean.
pub(crate) mod profidrive;

pub(crate) use support::diagnosis::DiagArea;
pub(crate) use support::U16Be;
pub(crate) use support::{pkw_pke_ind_pwe, pkw_profidrive, pkw_station_command};
#[cfg_attr(not(feature = "cli"), allow(unused_imports))] // the command line uses them
pub(crate) use support::{BitField, PKW_BYTES};

/// What an error code of MD810's channel means (manual 1.4.1: the codes
/// are Modbus's): `gsdc decode` and the datasheet say it.
pub(crate) fn pke_error_meaning(error: pkw_pke_ind_pwe::PkwErrorCode) -> crate::i18n::Phrase {
    use crate::i18n::codes as c;
    use pkw_pke_ind_pwe::PkwErrorCode as E;
    match error {
        E::IllegalCommand => c::ILLEGAL_COMMAND,
        E::IllegalAddress => c::ILLEGAL_ADDRESS,
        E::IllegalData => c::ILLEGAL_DATA,
        E::Other => c::OTHER_ERROR,
    }
}

/// A gateway's diagnosis places as the firmware's codecs take them: where
/// the block holds the type, the node and the code, and the node numbers.
/// The datasheet's encoder and the decoder read no types, so none are
/// listed.
pub(crate) fn gateway_diag_layout(
    g: &crate::ir::Gateway,
    d: &crate::ir::gateway::Diagnosis,
) -> support::gateway::DiagLayout {
    support::gateway::DiagLayout {
        type_at: d.type_at.into(),
        node_at: d.node_at.into(),
        code_at: d.code_at.into(),
        first_node: g.first_node,
        last_node: g.last_node,
        types: &[],
    }
}

/// The four PKW words at the start of `bytes`, high byte first (words past
/// the end of a short slice are zero).
#[cfg_attr(not(feature = "cli"), allow(dead_code))] // the command line uses it
pub(crate) fn pkw_words(bytes: &[u8]) -> [U16Be; 4] {
    support::words(bytes)
}

/// Whether the firmware's codec of the PKW channel `kind` takes `words`
/// going `direction` (a request out, a response in) and writes them back
/// the same: the manual's examples must. `Err` says why not.
pub(crate) fn round_trips(
    kind: crate::ir::PkwKind,
    direction: crate::ir::Direction,
    words: &[U16Be; 4],
) -> Result<(), String> {
    use crate::ir::{Direction, PkwKind};
    macro_rules! round_trip {
        ($codec:ident :: $side:ident) => {{
            let decoded = $codec::$side::decode(words).map_err(|e| format!("{e:?}"))?;
            if decoded.encode() == *words {
                Ok(())
            } else {
                Err(format!("{decoded:?} is written back as other bytes"))
            }
        }};
    }
    match (kind, direction) {
        (PkwKind::None, _) => Err("the telegram has no PKW channel".into()),
        (PkwKind::PkeIndPwe, Direction::Out) => round_trip!(pkw_pke_ind_pwe::PkwRequest),
        (PkwKind::PkeIndPwe, Direction::In) => round_trip!(pkw_pke_ind_pwe::PkwResponse),
        (PkwKind::StationCommandAddressValue, Direction::Out) => {
            round_trip!(pkw_station_command::PkwRequest)
        }
        (PkwKind::StationCommandAddressValue, Direction::In) => {
            round_trip!(pkw_station_command::PkwResponse)
        }
        (PkwKind::Profidrive, Direction::Out) => round_trip!(pkw_profidrive::PkwRequest),
        (PkwKind::Profidrive, Direction::In) => round_trip!(pkw_profidrive::PkwResponse),
    }
}
