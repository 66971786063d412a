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

/// The four PKW words at the start of `bytes`, high byte first (words past
/// the end of a short slice are zero).
#[cfg_attr(not(feature = "cli"), allow(dead_code))] // the command line uses it
pub(crate) fn pkw_words(bytes: &[u8]) -> [U16Be; 4] {
    support::words(bytes)
}
