//! gsdc: compiles one TOML description of a fieldbus option card into its
//! GSD (PROFIBUS-DP), GSDML (PROFINET) and firmware layout, and checks GSD and
//! GSDML files.
//!
//! The core is pure: [`load`], [`compile`], [`gsd::check`] and
//! [`gsdml::check`] take text and return text and diagnostics, with no I/O
//! and no clock. Files are read and written at the edges: the CLI, [`build`]
//! for build scripts, and [`output`] which both use.

// The core.
pub mod decode;
pub mod description;
pub mod diag;
pub mod emit;
pub mod file_kind;
pub mod gsd;
pub mod gsdml;
pub mod ir;
mod latin1;
pub mod load;
pub mod lower;
mod pkw;
pub mod rules;
mod spelling;
pub mod symbol;
mod utf16;

// The edges.
pub mod build;
pub mod output;
pub mod xsd;

pub use diag::{Diagnostic, Diagnostics, Severity, Source};
pub use emit::{Artifact, ArtifactKind, Language};
pub use ir::Ir;
pub use rules::{Rule, RULES};

/// Names the generator in the headers of generated files.
pub const GENERATOR: &str = concat!("gsdc ", env!("CARGO_PKG_VERSION"));

/// Reads a description: the IR when it has no error, and every diagnostic
/// (warnings too) either way. `source_name` is the file name used in
/// diagnostics and in the headers of generated files.
pub fn load(source_name: &str, text: &str) -> (Option<Ir>, Diagnostics) {
    load_with(source_name, text, &|path: &str| {
        Err(format!(
            "{path}: gsdc::load reads no files; gsdc::load_with or the build pipeline do"
        ))
    })
}

/// [`load`] for a description that names other files (its device symbol):
/// `files` gives the bytes of a path the description writes, relative to
/// the description, or says why it cannot. The edges pass one that reads
/// the disk (`build::load_file`); the core itself reads nothing.
pub fn load_with(
    source_name: &str,
    text: &str,
    files: &dyn Fn(&str) -> Result<Vec<u8>, String>,
) -> (Option<Ir>, Diagnostics) {
    match load::parse(text) {
        Ok(desc) => lower::lower(&desc, source_name, text, files),
        Err(diagnostics) => (None, diagnostics),
    }
}

/// Every file a loaded description gives, verified. Pure: no I/O, no clock.
pub fn compile(ir: &Ir) -> Result<Vec<Artifact>, Diagnostics> {
    emit::compile(ir)
}

/// The datasheet of a loaded description: `<stem>.html` and `<stem>.md`,
/// the manual's fieldbus chapter. Pure, like [`compile`]; not among
/// [`compile`]'s files, which ship with the card.
pub fn document(ir: &Ir) -> Vec<Artifact> {
    emit::doc::datasheet(ir)
}
