//! gsdc: compiles one TOML description of a fieldbus option card into its
//! GSD (PROFIBUS-DP), GSDML (PROFINET) and firmware layouts, and checks GSD
//! and GSDML files.
//!
//! The API: [`load`] reads a description into its plan ([`Ir`]), [`compile`]
//! gives every file of it and [`document`] its datasheet, [`gsd::check`] and
//! [`gsdml::check`] check a device file, each with [`Diagnostic`]s whose codes
//! are in [`RULES`]. The core is pure: text in, text and diagnostics out, no
//! I/O and no clock. Files are read and written at the edges: [`build`], for
//! build scripts (and the command line, which is not part of the API).

// The core. Public: what `load`, `compile` and the checks return (the
// plan, the GSD and GSDML readers' models) and the rule table; the rest is
// the crate's own.
#[cfg(feature = "cli")]
mod decode;
mod description;
pub mod device;
mod diag;
pub mod diff;
mod emit;
mod file_kind;
pub mod gsd;
pub mod gsdml;
mod i18n;
pub mod import;
pub mod ir;
mod latin1;
mod load;
mod lower;
mod pkw;
pub mod rules;
mod spec;
mod spelling;
mod symbol;
#[cfg(test)]
mod testing;
mod unicode;
mod utf16;
pub mod wire;

// The edges: the build-script API, the files, the PI schema.
pub mod build;
mod output;
pub mod xsd;

/// The command line, which the `gsdc` binary runs; not part of the API.
#[cfg(feature = "cli")]
#[doc(hidden)]
pub mod cli;

pub use diag::{line_col, Diagnostic, Diagnostics, Severity, Source};
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
        Ok(desc) => lower::lower(&desc, source_name, text, Some(files)),
        Err(diagnostics) => (None, diagnostics),
    }
}

/// [`load`] for the firmware layouts alone: the files the description names
/// are not read, and the IR has no device symbol (only the device files
/// carry it), so a firmware crate needs no bitmap beside its description.
pub(crate) fn load_for_layouts(source_name: &str, text: &str) -> (Option<Ir>, Diagnostics) {
    match load::parse(text) {
        Ok(desc) => lower::lower(&desc, source_name, text, None),
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
    emit::doc::datasheet(ir, None)
}

/// The datasheet of a loaded description with its "tested on the wire"
/// section: the exchanges of `results` (`scripts/wire-test.sh --results`)
/// that were of the very files [`compile`] gives now, or that none is
/// recorded for them.
pub fn document_tested(ir: &Ir, results: &[wire::Exchanged]) -> Vec<Artifact> {
    let files = compile(ir).unwrap_or_default();
    let exchanged = wire::of_files(results, &files);
    emit::doc::datasheet(ir, Some(&exchanged))
}
