//! The build-script API: generate a description's files from a firmware
//! crate's `build.rs`.
//!
//! In `build.rs`:
//!
//! ```no_run
//! let out_dir = std::env::var("OUT_DIR").unwrap();
//! gsdc::build::generate_rust("descriptions/md810dp.toml", &out_dir)
//!     .unwrap_or_else(|e| panic!("{e}"));
//! ```
//!
//! and in the firmware, the support module once at the crate root and each
//! layout in a module of its own:
//!
//! ```ignore
//! include!(concat!(env!("OUT_DIR"), "/gsdc_support.rs"));
//! pub mod md810dp {
//!     include!(concat!(env!("OUT_DIR"), "/md810dp_layout.rs"));
//! }
//! ```
//!
//! For C firmware, `generate_c` writes `md810dp_layout.h` and `gsdc_support.h`
//! instead (`generate` writes every file: device files and both layouts).
//!
//! It prints `cargo:rerun-if-changed` for the description, so cargo runs it
//! again when the description changes, and writes only files whose content
//! changed. Warnings (placeholder ident numbers) become `cargo:warning` lines.

use crate::diag::{Diagnostic, Diagnostics, Source};
use crate::load;
use crate::output::{read_input, write_if_changed, ReadError};
use crate::{Artifact, Language};
use std::fmt;
use std::path::{Path, PathBuf};

/// Why nothing was generated: the rendered diagnostics, or the I/O error.
#[derive(Debug)]
pub struct BuildError(String);

impl fmt::Display for BuildError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for BuildError {}

/// Writes every file of the description into `out_dir`; returns their paths.
pub fn generate(
    description: impl AsRef<Path>,
    out_dir: impl AsRef<Path>,
) -> Result<Vec<PathBuf>, BuildError> {
    let artifacts = compile_file(description.as_ref())?;
    write(&artifacts, out_dir.as_ref())
}

/// Writes only the firmware layout (`<stem>_layout.rs`) and the support
/// module it is built from (`gsdc_support.rs`) into `out_dir`; returns the
/// layout's path.
pub fn generate_rust(
    description: impl AsRef<Path>,
    out_dir: impl AsRef<Path>,
) -> Result<PathBuf, BuildError> {
    generate_layout(description.as_ref(), out_dir.as_ref(), Language::Rust)
}

/// Writes only the C layout (`<stem>_layout.h`) and the support header it
/// includes (`gsdc_support.h`) into `out_dir`; returns the layout's path.
/// For a crate that builds C firmware (with the `cc` crate, say) or hands
/// the header to a C build.
pub fn generate_c(
    description: impl AsRef<Path>,
    out_dir: impl AsRef<Path>,
) -> Result<PathBuf, BuildError> {
    generate_layout(description.as_ref(), out_dir.as_ref(), Language::C)
}

/// The layout of `language` and its support, the layout first.
fn generate_layout(
    description: &Path,
    out_dir: &Path,
    language: Language,
) -> Result<PathBuf, BuildError> {
    let artifacts = compile_file(description)?;
    let layout: Vec<Artifact> = artifacts
        .into_iter()
        .filter(|a| a.kind.language() == Some(language))
        .collect();
    if layout.is_empty() {
        return Err(BuildError(format!(
            "the description gives no {} firmware layout",
            language.name()
        )));
    }
    let mut paths = write(&layout, out_dir)?;
    Ok(paths.remove(0))
}

fn compile_file(path: &Path) -> Result<Vec<Artifact>, BuildError> {
    println!("cargo:rerun-if-changed={}", path.display());
    let name = path.display().to_string();
    let bytes = read_input(path, &load::INPUT_LIMIT).map_err(|e| match e {
        ReadError::TooLarge(d) => rendered_one(&name, "", d),
        ReadError::Io(e) => BuildError(format!("cannot read {name}: {e}")),
    })?;
    let text = load::decode(&bytes)
        .map_err(|d| rendered_one(&name, &String::from_utf8_lossy(&bytes), d))?;
    let source_name = path
        .file_name()
        .map_or_else(|| name.clone(), |f| f.to_string_lossy().into_owned());
    let source = Source { name: &name, text };
    let (ir, diagnostics) = crate::load(&source_name, text);
    for warning in diagnostics.iter().filter(|d| !d.is_error()) {
        println!(
            "cargo:warning={}: {}",
            source.location(warning),
            warning.message
        );
    }
    let ir = ir.ok_or_else(|| rendered(&source, &diagnostics))?;
    crate::compile(&ir).map_err(|d| rendered(&source, &d))
}

fn rendered(source: &Source, diagnostics: &Diagnostics) -> BuildError {
    BuildError(diagnostics.iter().map(|d| source.render(d)).collect())
}

fn rendered_one(name: &str, text: &str, diagnostic: Diagnostic) -> BuildError {
    rendered(&Source { name, text }, &Diagnostics(vec![diagnostic]))
}

/// Writes all the files or, as far as the disk allows, none (see
/// [`write_if_changed`]); the error names the path, the OS error and the
/// files already written.
fn write(artifacts: &[Artifact], out_dir: &Path) -> Result<Vec<PathBuf>, BuildError> {
    write_if_changed(out_dir, artifacts).map_err(|e| BuildError(e.to_string()))?;
    Ok(artifacts
        .iter()
        .map(|a| out_dir.join(&a.file_name))
        .collect())
}
