//! The firmware's own codecs, compiled into gsdc: the PKW channels and the
//! diagnosis areas of `templates/support/`, the very code the generated
//! layouts run. gsdc's datasheet encodes its worked examples with them, so a
//! telegram printed in a datasheet is one the firmware sends and reads.
//!
//! Only the codecs are used here; the telegram structs and parameter readers
//! of the support module are the firmware's, tested in `emit::rust`.

#[path = "../templates/support/mod.rs"]
#[allow(dead_code)]
pub(crate) mod support;

pub(crate) use support::diagnosis::DiagArea;
pub(crate) use support::{pkw_pke_ind_pwe, pkw_station_command, U16Be};
