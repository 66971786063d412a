//! What an option card's firmware contains, written once for any
//! description: the layouts gsdc generates from the descriptions (each a
//! module of [`layouts`]) and the card each one makes (found by description
//! name with [`card()`]: the layout's device tables, [`card::Card`]), the
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
pub mod cyclic;
pub mod drive;
pub mod manuals;
pub mod nodes;
pub mod pkw;

/// The layouts of the descriptions the firmware is built for (build.rs
/// generates them; `WIRE_DESCRIPTIONS` chooses them), each in a module named
/// after its file, and [`layouts::CARDS`], the card of each.
pub mod layouts {
    use crate::card::Card;

    include!(concat!(env!("OUT_DIR"), "/registry.rs"));
}

/// The card of the description named `name` (its file name without
/// `.toml`), if the firmware was built for it.
pub fn card(name: &str) -> Option<&'static card::Card> {
    layouts::CARDS.iter().find(|c| c.name == name)
}
