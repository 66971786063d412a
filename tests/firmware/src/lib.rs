//! The firmware layouts of the shipped descriptions (and of two test
//! fixtures: a PROFIdrive card, and one whose ident numbers and records are
//! its own), as firmware includes them: no_std, and any
//! warning an error.

#![no_std]
#![deny(warnings)]

// The support code every layout is built from: once, at the crate root.
include!(concat!(env!("OUT_DIR"), "/gsdc_support.rs"));

pub mod md810dp {
    include!(concat!(env!("OUT_DIR"), "/md810dp_layout.rs"));
}

pub mod mv810_pnet02 {
    include!(concat!(env!("OUT_DIR"), "/mv810_pnet02_layout.rs"));
}

pub mod powtran_9kdp1 {
    include!(concat!(env!("OUT_DIR"), "/9kdp1_layout.rs"));
}

pub mod md810_gateway {
    include!(concat!(env!("OUT_DIR"), "/md810_gateway_layout.rs"));
}

pub mod profidrive {
    include!(concat!(env!("OUT_DIR"), "/profidrive_layout.rs"));
}

pub mod own_idents {
    include!(concat!(env!("OUT_DIR"), "/own_idents_layout.rs"));
}
