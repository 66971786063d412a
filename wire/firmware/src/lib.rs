//! What an option card's firmware contains, written once for any
//! description: the layouts gsdc generates from the descriptions (each a
//! module of [`layouts`], found by description name with [`layout`]), the
//! drive behind the card ([`drive::Drive`], with the parameters its manual
//! gives), and the answers the card gives for the drive on any bus
//! ([`pkw`]: the PKW channel, through the layout's codecs).
//!
//! Nothing here knows a bus: `wire/dp` runs it as a PROFIBUS-DP slave,
//! `wire/pn` as a PROFINET device. Nothing here holds a number of the
//! device files either: identity, modules, parameters, telegrams and
//! diagnosis come from the layouts, so the card and the GSD or GSDML built
//! from the same description cannot disagree.

#![no_std]
#![deny(warnings)]

// The support code every layout is built from: once, at the crate root, as
// the layouts expect it (`crate::gsdc_support`).
include!(concat!(env!("OUT_DIR"), "/gsdc_support.rs"));

pub mod card;
pub mod cards;
pub mod cyclic;
pub mod drive;
pub mod manuals;
pub mod nodes;
pub mod pkw;

/// The layouts of the descriptions the firmware is built for (build.rs
/// generates them; `WIRE_DESCRIPTIONS` chooses them), each in a module named
/// after its file, and [`layouts::LAYOUTS`], the table of them.
pub mod layouts {
    use super::Layout;

    include!(concat!(env!("OUT_DIR"), "/registry.rs"));
}

/// A layout the firmware is built for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layout {
    /// The description's file name without `.toml`: `md810dp`.
    pub name: &'static str,
    /// The description's fingerprint; the GSD and GSDML built from the same
    /// description carry it in their headers.
    pub fingerprint: &'static str,
}

/// The layout of the description named `name` (its file name without
/// `.toml`), if the firmware was built for it.
pub fn layout(name: &str) -> Option<&'static Layout> {
    layouts::LAYOUTS.iter().find(|l| l.name == name)
}
