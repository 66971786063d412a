//! gsdc: compiles one TOML description of a fieldbus option card into its
//! GSD (PROFIBUS-DP), GSDML (PROFINET) and firmware layout, and checks GSD and
//! GSDML files.
//!
//! The core is pure: it takes text and returns text and diagnostics; reading
//! and writing files happen in the CLI and in [`build`] for build scripts.

pub mod diag;
pub mod gsd;
pub mod gsdml;

pub use diag::{Diagnostic, Diagnostics, Severity, Source};
