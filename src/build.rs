//! The build: description files to the files they give, checked, then
//! written. `gsdc build` and build scripts go through the same steps
//! (`Compiler::compile`: read the description within its size limit,
//! decode, load, compile, deny warnings when asked, validate each GSDML
//! against the PI schema when asked), so they cannot drift apart.
//!
//! In a firmware crate's `build.rs`:
//!
//! ```no_run
//! let out_dir = std::env::var("OUT_DIR").unwrap();
//! gsdc::build::generate_rust("descriptions/md810dp.toml", &out_dir)
//!     .unwrap_or_else(|e| panic!("{e}"));
//! ```
//!
//! and in the firmware, the support module once at the crate root and each
//! layout in a module of its own (firmware code, not a doctest: it needs the
//! build script's OUT_DIR; tests/firmware/src/lib.rs does this and is built
//! and tested by the tests):
//!
//! ```text
//! include!(concat!(env!("OUT_DIR"), "/gsdc_support.rs"));
//! pub mod md810dp {
//!     include!(concat!(env!("OUT_DIR"), "/md810dp_layout.rs"));
//! }
//! ```
//!
//! For C firmware, [`generate_c`] writes `md810dp_layout.h` and
//! `gsdc_support.h` instead ([`generate`] writes every file: device files and
//! both layouts).
//!
//! It prints `cargo:rerun-if-changed` for the description and the files it
//! reads (the device symbol, which only [`generate`] reads: the layouts do
//! not carry it), so cargo runs it again when one of them changes, and writes only files whose content changed. Warnings (placeholder ident numbers) become `cargo:warning`
//! lines, or refuse the build with [`Config::deny_warnings`]. With
//! [`Config::xsd`], or the environment variable [`XSD_ENV`], each GSDML is
//! validated against the PI schema before anything is written:
//!
//! ```no_run
//! let out_dir = std::env::var("OUT_DIR").unwrap();
//! gsdc::build::Config::new()
//!     .deny_warnings(true)
//!     .xsd("../pi/gsdml-xsd-v2.44")
//!     .generate("descriptions/md810dp.toml", &out_dir)
//!     .unwrap_or_else(|e| panic!("{e}"));
//! ```

use crate::diag::{Diagnostic, Diagnostics, Severity, Source};
use crate::file_kind::{self, FileKind};
use crate::output::{read_input, read_regular_input, ReadError};
pub use crate::output::{write_files, Outcome, WriteError, Written, GENERATED_MARK};
use crate::xsd::Schema;
use crate::{Artifact, ArtifactKind, Language};
use std::fmt;
use std::io;
use std::path::{Path, PathBuf};

/// The environment variable that names a PI schema directory for every
/// build, as `--xsd` and [`Config::xsd`] do: a CI job sets it once and each
/// `gsdc build` and each build script validates its GSDML files. Empty is
/// unset.
pub const XSD_ENV: &str = "GSDC_BUILD_XSD";

/// Writes every file of the description into `out_dir`; returns their paths.
/// [`Config::new`]'s settings: warnings allowed, the schema of [`XSD_ENV`].
pub fn generate(
    description: impl AsRef<Path>,
    out_dir: impl AsRef<Path>,
) -> Result<Vec<PathBuf>, BuildError> {
    Config::new().generate(description, out_dir)
}

/// Writes only the firmware layout (`<stem>_layout.rs`) and the support
/// module it is built from (`gsdc_support.rs`) into `out_dir`; returns the
/// layout's path. [`Config::new`]'s settings.
pub fn generate_rust(
    description: impl AsRef<Path>,
    out_dir: impl AsRef<Path>,
) -> Result<PathBuf, BuildError> {
    Config::new().generate_layout(description, out_dir, Language::Rust)
}

/// Writes only the C layout (`<stem>_layout.h`) and the support header it
/// includes (`gsdc_support.h`) into `out_dir`; returns the layout's path.
/// For a crate that builds C firmware (with the `cc` crate, say) or hands
/// the header to a C build. [`Config::new`]'s settings.
pub fn generate_c(
    description: impl AsRef<Path>,
    out_dir: impl AsRef<Path>,
) -> Result<PathBuf, BuildError> {
    Config::new().generate_layout(description, out_dir, Language::C)
}

/// How descriptions are built.
#[derive(Debug, Clone)]
pub struct Config {
    deny_warnings: bool,
    xsd: Option<PathBuf>,
    firmware: Vec<Language>,
    released: Option<PathBuf>,
}

impl Default for Config {
    fn default() -> Self {
        Config::new()
    }
}

impl Config {
    /// Warnings allowed; each GSDML validated against the PI schema in the
    /// directory [`XSD_ENV`] names, if it is set.
    pub fn new() -> Config {
        let xsd = std::env::var_os(XSD_ENV)
            .filter(|dir| !dir.is_empty())
            .map(PathBuf::from);
        Config {
            deny_warnings: false,
            xsd,
            firmware: Language::ALL.to_vec(),
            released: None,
        }
    }

    /// Judges each GSD and GSDML against the last release's files in
    /// `dir` before anything is written: a GSDML whose content changed
    /// under its released file name, or a GSD whose content changed under
    /// its released `Revision`, refuses the build (E501, E502); a change
    /// that breaks projects configured with the released file under the
    /// same ident number is a warning (W503). Without it, releases are not
    /// looked at, so that a working build is as quick as ever.
    pub fn released(&mut self, dir: impl Into<PathBuf>) -> &mut Self {
        self.released = Some(dir.into());
        self
    }

    /// The languages whose firmware layouts (and support files) are
    /// written; both by default, none for device files alone.
    pub fn firmware(&mut self, languages: &[Language]) -> &mut Self {
        self.firmware = languages.to_vec();
        self
    }

    /// With `true`, a description with any warning (a placeholder ident
    /// number, say) is refused as one with an error: nothing is written.
    pub fn deny_warnings(&mut self, deny: bool) -> &mut Self {
        self.deny_warnings = deny;
        self
    }

    /// Validates each GSDML against the PI schema in `dir`
    /// ([`crate::xsd::SCHEMA_FILE`] and what it imports) before anything is
    /// written; a GSDML the schema rejects refuses the build with its
    /// findings (E399). Needs the cargo feature `xsd`: without it, every
    /// build fails saying so.
    pub fn xsd(&mut self, dir: impl Into<PathBuf>) -> &mut Self {
        self.xsd = Some(dir.into());
        self
    }

    /// Writes every file of the description into `out_dir`; returns their paths.
    pub fn generate(
        &self,
        description: impl AsRef<Path>,
        out_dir: impl AsRef<Path>,
    ) -> Result<Vec<PathBuf>, BuildError> {
        let files = self.build_script_compile(description.as_ref(), Writes::Everything)?;
        write(&files, out_dir.as_ref())
    }

    /// Writes only the firmware layout in `language` (`<stem>_layout.rs`
    /// or `<stem>_layout.h`) and the support file it is built from into
    /// `out_dir`; returns the layout's path. No GSDML is written, so none is
    /// validated: firmware crates need no libxml2; no device file is
    /// written, so the device symbol is not read: a firmware crate needs no
    /// bitmap beside its description.
    pub fn generate_layout(
        &self,
        description: impl AsRef<Path>,
        out_dir: impl AsRef<Path>,
        language: Language,
    ) -> Result<PathBuf, BuildError> {
        let description = description.as_ref();
        // Only this language's layout is compiled, whatever `firmware` says.
        let mut files: Vec<Artifact> = self
            .clone()
            .firmware(&[language])
            .build_script_compile(description, Writes::LayoutsOnly)?
            .into_iter()
            .filter(|a| a.kind.language() == Some(language))
            .collect();
        // The layout first: its path is the one returned.
        files.sort_by_key(|a| !matches!(a.kind, ArtifactKind::RustLayout | ArtifactKind::CHeader));
        if files.is_empty() {
            return Err(BuildError::NoLayout {
                path: description.to_path_buf(),
            });
        }
        let mut paths = write(&files, out_dir.as_ref())?;
        Ok(paths.remove(0))
    }

    /// The steps of a build, with the schema loaded when one is asked for.
    #[cfg_attr(not(feature = "cli"), allow(dead_code))] // the command line uses it
    pub(crate) fn compiler(&self) -> Result<Compiler, BuildError> {
        self.compiler_with(self.xsd.as_deref())
    }

    fn compiler_with(&self, xsd: Option<&Path>) -> Result<Compiler, BuildError> {
        let schema = match xsd {
            Some(dir) => Some(Schema::load(dir).map_err(|why| BuildError::Schema {
                dir: dir.to_path_buf(),
                why,
            })?),
            None => None,
        };
        let released = self
            .released
            .as_deref()
            .map(ReleasedFiles::list)
            .transpose()?;
        Ok(Compiler {
            deny_warnings: self.deny_warnings,
            schema,
            firmware: self.firmware.clone(),
            released,
            writes: Writes::Everything,
        })
    }

    /// [`Compiler::compile`] as a build script needs it: the `cargo:` lines
    /// that make cargo run it again when an input changes, warnings as
    /// `cargo:warning`, and the findings rendered into the error. The
    /// schema, if any, and the device symbol only when device files are
    /// written.
    fn build_script_compile(
        &self,
        description: &Path,
        writes: Writes,
    ) -> Result<Vec<Artifact>, BuildError> {
        println!("cargo:rerun-if-changed={}", description.display());
        let device_files = writes == Writes::Everything;
        let xsd = self.xsd.as_deref().filter(|_| device_files);
        if device_files {
            println!("cargo:rerun-if-env-changed={XSD_ENV}");
        }
        if let Some(dir) = xsd {
            let schema = dir.join(crate::xsd::SCHEMA_FILE);
            println!("cargo:rerun-if-changed={}", schema.display());
        }
        if let Some(dir) = &self.released {
            println!("cargo:rerun-if-changed={}", dir.display());
        }
        let name = description.display().to_string();
        let mut compiler = self.compiler_with(xsd)?;
        compiler.writes = writes;
        let compiled = compiler.compile(description, &name)?;
        for path in &compiled.beside {
            println!("cargo:rerun-if-changed={}", path.display());
        }
        match compiled.files {
            Ok(files) => {
                for findings in &compiled.findings {
                    findings.cargo_warnings();
                }
                Ok(files)
            }
            Err(refused) => Err(BuildError::Description {
                path: description.to_path_buf(),
                findings: compiled.findings,
                refused,
            }),
        }
    }
}

/// The steps from a description file to its files: one [`Config`]'s
/// settings, and the PI schema loaded once for every description.
pub(crate) struct Compiler {
    deny_warnings: bool,
    schema: Option<Schema>,
    /// The languages whose firmware layouts a build writes.
    firmware: Vec<Language>,
    released: Option<ReleasedFiles>,
    writes: Writes,
}

/// What a build writes: what it reads follows from it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Writes {
    /// The device files too, with the device symbol they name.
    Everything,
    /// Firmware layouts alone (a build script's `generate_rust`): nothing
    /// beside the description is read.
    LayoutsOnly,
}

/// The last release's files ([`Config::released`]): the directory and the
/// names of the files in it.
struct ReleasedFiles {
    dir: PathBuf,
    names: Vec<String>,
}

impl ReleasedFiles {
    fn list(dir: &Path) -> Result<ReleasedFiles, BuildError> {
        let unreadable = |why: String| BuildError::Released {
            dir: dir.to_path_buf(),
            why,
        };
        let mut names = Vec::new();
        for entry in std::fs::read_dir(dir).map_err(|e| unreadable(e.to_string()))? {
            let entry = entry.map_err(|e| unreadable(e.to_string()))?;
            if entry.file_type().is_ok_and(|t| t.is_file()) {
                names.extend(entry.file_name().to_str().map(str::to_string));
            }
        }
        names.sort();
        Ok(ReleasedFiles {
            dir: dir.to_path_buf(),
            names,
        })
    }

    /// What the release rules say of each GSD and GSDML among `files`,
    /// against its released counterpart, pointing into the description's
    /// `text`.
    fn findings(
        &self,
        files: &[Artifact],
        description: &Findings,
    ) -> Result<Vec<Diagnostic>, BuildError> {
        use crate::diff::release;
        let anchors = release::Anchors::of(&description.text);
        let mut findings = Vec::new();
        for file in files
            .iter()
            .filter(|f| matches!(f.kind, ArtifactKind::Gsd | ArtifactKind::Gsdml))
        {
            let Some((name, same_name)) = release::counterpart(&file.file_name, &self.names) else {
                continue;
            };
            let path = self.dir.join(name);
            let unreadable = |why: String| BuildError::Released {
                dir: self.dir.clone(),
                why: format!("{name}: {why}"),
            };
            let bytes = match crate::output::read_device_file(&path) {
                Ok((_, bytes)) => bytes,
                Err(ReadError::Io(e)) => return Err(unreadable(e.to_string())),
                Err(ReadError::TooLarge(d)) => return Err(unreadable(d.message)),
            };
            let released = crate::device::read(&bytes, Some(name)).ok_or_else(|| {
                unreadable("not a GSD or GSDML file gsdc can read (`gsdc check` says why)".into())
            })?;
            let Some(built) = crate::device::read(&file.contents, Some(&file.file_name)) else {
                continue; // gsdc's own files are checked before this: it reads them
            };
            let released = release::Released {
                name,
                device: &released,
                diff_command: format!("gsdc diff {} {}", path.display(), description.name),
            };
            findings.extend(release::judge(
                &file.file_name,
                &built,
                &released,
                same_name,
                &anchors,
            ));
        }
        Ok(findings)
    }
}

/// What one description gave: what to show, and the files or why there are
/// none.
#[derive(Debug)]
#[non_exhaustive]
pub(crate) struct Compiled {
    /// The description's findings (warnings too, possibly none), then those
    /// of each generated GSDML the PI schema rejects.
    pub findings: Vec<Findings>,
    pub files: Result<Vec<Artifact>, Refused>,
    /// The files beside the description that it read ([`Loaded::beside`]).
    pub beside: Vec<PathBuf>,
    /// Its datasheet's names and fingerprint, when it loaded.
    pub datasheet: Option<Datasheet>,
}

/// A description's datasheet as `gsdc doc` writes it: its files and the
/// fingerprint they carry. A build does not write it; `gsdc build --check`
/// names one in the directory that carries another description's.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Datasheet {
    pub file_names: [String; 2],
    pub fingerprint: crate::ir::Fingerprint,
}

impl Datasheet {
    fn of(ir: &crate::Ir) -> Datasheet {
        Datasheet {
            file_names: crate::emit::doc::file_names(ir),
            fingerprint: ir.fingerprint,
        }
    }
}

/// Why a description gave no files.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Refused {
    /// The description, or a GSDML it gives, has errors.
    Errors,
    /// It has warnings, and warnings are denied.
    Warnings,
}

/// Diagnostics about one text: a description, or a generated file.
#[derive(Debug)]
#[non_exhaustive]
pub struct Findings {
    /// The name the diagnostics give for the text.
    pub name: String,
    pub text: String,
    pub diagnostics: Diagnostics,
}

impl Findings {
    /// The first `max` diagnostics, each rendered against the text, then
    /// how many more there are: a hostile description can have a hundred
    /// thousand, and the first hundred say what is wrong.
    pub fn rendered(&self, max: usize) -> Vec<String> {
        let source = Source::new(&self.name, &self.text);
        let mut out: Vec<String> = self
            .diagnostics
            .iter()
            .take(max)
            .map(|d| source.render(d))
            .collect();
        let hidden = self.diagnostics.iter().count().saturating_sub(max);
        if hidden > 0 {
            out.push(format!(
                "{}: {hidden} more finding(s) not shown\n",
                self.name
            ));
        }
        out
    }

    fn warnings(&self) -> impl Iterator<Item = &Diagnostic> {
        self.diagnostics
            .iter()
            .filter(|d| d.severity == Severity::Warning)
    }

    fn cargo_warnings(&self) {
        let source = Source::new(&self.name, &self.text);
        for warning in self.warnings() {
            println!("cargo:warning={}", source.one_line(warning));
        }
    }
}

/// Every finding rendered (at most `max` per text), then what refused the
/// description.
fn render(findings: &[Findings], refused: Refused, max: usize) -> String {
    let mut out: String = findings.iter().flat_map(|f| f.rendered(max)).collect();
    out += match refused {
        Refused::Errors => "nothing written: fix the errors above",
        Refused::Warnings => "nothing written: the description has warnings, and they are denied",
    };
    out
}

impl Compiler {
    /// Reads the description at `path` (no more than [`crate::load::INPUT_LIMIT`]),
    /// decodes, loads and compiles it, refuses it for warnings when they are
    /// denied, and validates each GSDML it gives against the schema if
    /// there is one. `name` names the description in diagnostics. `Err`
    /// only when the file cannot be read.
    pub fn compile(&mut self, path: &Path, name: &str) -> Result<Compiled, BuildError> {
        let Loaded {
            findings,
            ir,
            beside,
        } = load_file_for(path, name, self.writes)?;
        let mut description = findings;
        let datasheet = ir.as_ref().map(Datasheet::of);
        let files = match ir.map(|ir| crate::emit::compile_for(&ir, &self.firmware)) {
            Some(Ok(files)) => Some(files),
            Some(Err(problems)) => {
                description.diagnostics.extend(problems);
                None
            }
            None => None,
        };
        if let (Some(released), Some(files)) = (&self.released, &files) {
            if !description.diagnostics.has_errors() {
                let found = released.findings(files, &description)?;
                description.diagnostics.extend(found);
            }
        }
        let mut compiled = self.judge(description, files, beside);
        compiled.datasheet = datasheet;
        Ok(compiled)
    }

    /// The verdict on a description's files: errors refuse them, then
    /// warnings when denied, then a GSDML the PI schema rejects.
    fn judge(
        &mut self,
        description: Findings,
        files: Option<Vec<Artifact>>,
        beside: Vec<PathBuf>,
    ) -> Compiled {
        let has_errors = description.diagnostics.has_errors();
        let has_warnings = description.warnings().next().is_some();
        let mut findings = vec![description];
        let Some(files) = files.filter(|_| !has_errors) else {
            return Compiled {
                findings,
                files: Err(Refused::Errors),
                beside,
                datasheet: None,
            };
        };
        let from = &findings[0].name;
        let rejected = self.validate(from, &files);
        let schema_errors = !rejected.is_empty();
        findings.extend(rejected);
        let files = if schema_errors {
            Err(Refused::Errors)
        } else if has_warnings && self.deny_warnings {
            Err(Refused::Warnings)
        } else {
            Ok(files)
        };
        Compiled {
            findings,
            files,
            beside,
            datasheet: None,
        }
    }

    /// The PI schema's findings for each GSDML among `files` that it
    /// rejects, each named after the file and the description `from`; none
    /// without a schema. The build's last step before writing, and the
    /// tests' way in with a GSDML gsdc would not generate.
    pub fn validate(&mut self, from: &str, files: &[Artifact]) -> Vec<Findings> {
        let Some(schema) = self.schema.as_mut() else {
            return Vec::new();
        };
        files
            .iter()
            .filter(|file| file_kind::detect(&file.contents) == FileKind::Gsdml)
            .filter_map(|file| {
                let text = String::from_utf8_lossy(&file.contents).into_owned();
                let diagnostics = schema.validate(&text);
                (!diagnostics.is_empty()).then(|| Findings {
                    name: format!("{} (generated from {from})", file.file_name),
                    text,
                    diagnostics,
                })
            })
            .collect()
    }
}

/// A description read from its file: its findings (warnings too), and its
/// IR unless it has errors.
#[derive(Debug)]
#[non_exhaustive]
pub struct Loaded {
    pub findings: Findings,
    pub ir: Option<crate::Ir>,
    /// The files beside the description that it named and that were read
    /// (its device symbol): inputs of the build as much as the description.
    pub beside: Vec<PathBuf>,
}

/// Reads the description at `path` (no more than
/// `INPUT_LIMIT`), decodes and loads it: every command that
/// reads a description starts here. `name` names it in diagnostics. `Err`
/// only when the file cannot be read.
pub fn load_file(path: &Path, name: &str) -> Result<Loaded, BuildError> {
    load_file_for(path, name, Writes::Everything)
}

/// [`load_file`], reading what a build that `writes` these files needs.
fn load_file_for(path: &Path, name: &str, writes: Writes) -> Result<Loaded, BuildError> {
    let unread = |text: String, diagnostic| Loaded {
        findings: Findings {
            name: name.to_string(),
            text,
            diagnostics: Diagnostics(vec![diagnostic]),
        },
        ir: None,
        beside: Vec::new(),
    };
    let bytes = match read_input(path, &crate::load::INPUT_LIMIT) {
        Ok(bytes) => bytes,
        Err(ReadError::Io(error)) => {
            return Err(BuildError::Read {
                path: path.to_path_buf(),
                error,
            })
        }
        Err(ReadError::TooLarge(d)) => return Ok(unread(String::new(), d)),
    };
    let text = match crate::load::decode(&bytes) {
        Ok(text) => text,
        Err(d) => return Ok(unread(String::from_utf8_lossy(&bytes).into_owned(), d)),
    };
    // The name in generated headers is the file's own, without folders.
    let source_name = path
        .file_name()
        .map_or_else(|| name.to_string(), |f| f.to_string_lossy().into_owned());
    let folder = path.parent().unwrap_or(Path::new(""));
    let beside = std::cell::RefCell::new(Vec::new());
    let files = |name: &str| {
        beside.borrow_mut().push(folder.join(name));
        read_beside(folder, name)
    };
    let (ir, diagnostics) = match writes {
        Writes::Everything => crate::load_with(&source_name, text, &files),
        Writes::LayoutsOnly => crate::load_for_layouts(&source_name, text),
    };
    Ok(Loaded {
        findings: Findings {
            name: name.to_string(),
            text: text.to_string(),
            diagnostics,
        },
        ir,
        beside: beside.into_inner(),
    })
}

/// A file a description names (its device symbol), relative to the
/// description's folder: a regular file (a FIFO or a device is refused
/// unread, [`crate::output::open_regular`]) no larger than a description
/// may be.
fn read_beside(folder: &Path, name: &str) -> Result<Vec<u8>, String> {
    read_regular_input(&folder.join(name), &crate::load::INPUT_LIMIT).map_err(|e| match e {
        ReadError::Io(error) => format!("{name}: {error}"),
        ReadError::TooLarge(_) => format!(
            "{name} is larger than {} bytes",
            crate::load::INPUT_LIMIT.max_bytes
        ),
    })
}

/// Two descriptions that cannot be built together: they give files of one
/// name with different contents, or C layouts that declare the same names
/// (their prefixes meet: `m.toml`'s `m_pkw_pzd2_out_t` is also
/// `m_pkw.toml`'s), which could not be included in one translation unit.
#[derive(Debug, Clone, PartialEq, Eq)]
#[cfg_attr(not(feature = "cli"), allow(dead_code))] // the command line uses it
pub(crate) struct Collision {
    pub clash: Clash,
    pub first: PathBuf,
    pub second: PathBuf,
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum Clash {
    /// The file's name.
    File(String),
    /// The names both C layouts declare, in order.
    CNames(Vec<String>),
}

impl fmt::Display for Collision {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (first, second) = (self.first.display(), self.second.display());
        write!(f, "{first} and {second} {}", self.clash)
    }
}

/// What two descriptions both give: `both give x_y_layout.rs, with
/// different contents`, `both declare the C names `a`, `b` (...)`.
impl fmt::Display for Clash {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Clash::File(name) => write!(f, "both give {name}, with different contents"),
            Clash::CNames(names) => {
                const SHOWN: usize = 3;
                let shown: Vec<String> =
                    names.iter().take(SHOWN).map(|n| format!("`{n}`")).collect();
                let more = match names.len() {
                    n if n > SHOWN => format!(" and {} more", n - SHOWN),
                    _ => String::new(),
                };
                write!(
                    f,
                    "both declare the C names {}{more}: their layouts cannot be included together",
                    shown.join(", ")
                )
            }
        }
    }
}

/// The files of several descriptions as one set, each once: a file that two
/// descriptions give with the same bytes (a support module every layout
/// shares, the same description given twice) is one file; two different
/// files of one name, or two C layouts that declare a name both, are a
/// collision, and every collision is returned.
#[cfg_attr(not(feature = "cli"), allow(dead_code))] // the command line uses it
pub(crate) fn merge(sets: Vec<(PathBuf, Vec<Artifact>)>) -> Result<Vec<Artifact>, Vec<Collision>> {
    let mut merged: Vec<(PathBuf, Artifact)> = Vec::new();
    let mut collisions = Vec::new();
    for (description, files) in sets {
        for file in files {
            match merged.iter().find(|(_, a)| a.file_name == file.file_name) {
                Some((_, same)) if same.contents == file.contents => {}
                Some((first, _)) => collisions.push(Collision {
                    clash: Clash::File(file.file_name),
                    first: first.clone(),
                    second: description.clone(),
                }),
                None => {
                    collisions.extend(c_name_clashes(&merged, &description, &file));
                    merged.push((description.clone(), file));
                }
            }
        }
    }
    if collisions.is_empty() {
        Ok(merged.into_iter().map(|(_, file)| file).collect())
    } else {
        Err(collisions)
    }
}

/// The names a new C layout declares that a layout of another description
/// already declares, one collision per description.
fn c_name_clashes(
    merged: &[(PathBuf, Artifact)],
    description: &Path,
    file: &Artifact,
) -> Vec<Collision> {
    if file.kind != ArtifactKind::CHeader {
        return Vec::new();
    }
    let names = c_names(file);
    merged
        .iter()
        .filter(|(_, other)| other.kind == ArtifactKind::CHeader)
        .filter_map(|(first, other)| {
            let both: Vec<String> = c_names(other).intersection(&names).cloned().collect();
            (!both.is_empty()).then(|| Collision {
                clash: Clash::CNames(both),
                first: first.clone(),
                second: description.to_path_buf(),
            })
        })
        .collect()
}

fn c_names(header: &Artifact) -> std::collections::BTreeSet<String> {
    let text = String::from_utf8_lossy(&header.contents);
    crate::emit::c::declared_names(&text).into_iter().collect()
}

/// Why a build wrote nothing, or not everything.
#[derive(Debug)]
#[non_exhaustive]
pub enum BuildError {
    /// The description could not be read.
    Read { path: PathBuf, error: io::Error },
    /// The description has errors, or warnings while they are denied, or a
    /// GSDML it gives breaks the PI schema. Nothing was written. The
    /// findings are values (each diagnostic's code, severity, message, place
    /// and help, with the text it points into: the description's, then each
    /// refused GSDML's), so a build script can act on a code; `Display`
    /// renders them as gsdc prints them.
    Description {
        path: PathBuf,
        findings: Vec<Findings>,
        refused: Refused,
    },
    /// A layout was asked for, and the description gives none.
    NoLayout { path: PathBuf },
    /// The files could not all be written: the path, the OS error, and the
    /// files already replaced (as far as the disk allowed, none).
    Write(WriteError),
    /// The PI schema asked for cannot be loaded from `dir`.
    Schema { dir: PathBuf, why: String },
    /// The last release's files ([`Config::released`]) cannot be read.
    Released { dir: PathBuf, why: String },
}

impl fmt::Display for BuildError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BuildError::Read { path, error } => {
                write!(f, "cannot read {}: {error}", path.display())
            }
            BuildError::Description {
                findings, refused, ..
            } => f.write_str(&render(findings, *refused, usize::MAX)),
            BuildError::NoLayout { path } => {
                write!(f, "{} gives no firmware layout", path.display())
            }
            BuildError::Write(e) => e.fmt(f),
            BuildError::Schema { dir, why } => {
                write!(f, "cannot use the PI schema in {}: {why}", dir.display())
            }
            BuildError::Released { dir, why } => {
                write!(
                    f,
                    "cannot read the released files in {}: {why}",
                    dir.display()
                )
            }
        }
    }
}

impl std::error::Error for BuildError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            BuildError::Read { error, .. } => Some(error),
            BuildError::Write(e) => Some(e),
            BuildError::Description { .. }
            | BuildError::NoLayout { .. }
            | BuildError::Schema { .. }
            | BuildError::Released { .. } => None,
        }
    }
}

/// Writes all the files or, as far as the disk allows, none (see
/// [`write_files`]); returns their paths.
fn write(files: &[Artifact], out_dir: &Path) -> Result<Vec<PathBuf>, BuildError> {
    let written = write_files(out_dir, files, false).map_err(BuildError::Write)?;
    for leftover in &written.leftovers {
        println!(
            "cargo:warning=removed {}, left by a build that was interrupted",
            leftover.display()
        );
    }
    if let Some(e) = &written.not_locked {
        println!(
            "cargo:warning=cannot lock {} ({e}): a build writing into it at the same time could mix its files with these",
            out_dir.display()
        );
    }
    Ok(files.iter().map(|a| out_dir.join(&a.file_name)).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn artifact(file_name: &str, contents: &str) -> Artifact {
        Artifact {
            kind: ArtifactKind::RustLayout,
            file_name: file_name.into(),
            contents: contents.as_bytes().to_vec(),
        }
    }

    /// `m.toml`'s module "PKW + 2 PZD" and `m_pkw.toml`'s "2 PZD" both
    /// give `m_pkw_pzd2_out_t` in C: different files, but one translation
    /// unit cannot hold both. The build refuses the pair, naming both; the
    /// same description twice, or two whose prefixes do not meet, build.
    #[test]
    fn c_layouts_whose_names_meet_collide() {
        let text = include_str!("../descriptions/mv810-pnet02.toml");
        let files = |name: &str, text: &str| {
            let ir = crate::testing::load(name, text).0.unwrap();
            // The C layouts alone: both give one GSDML file name too.
            let mut files = crate::compile(&ir).unwrap();
            files.retain(|f| f.kind == ArtifactKind::CHeader);
            (PathBuf::from(name), files)
        };
        let without_pkw = text.replace("module_pkw = \"with\"", "module_pkw = \"without\"");
        assert_ne!(without_pkw, text);
        let collisions = merge(vec![
            files("m.toml", text),
            files("m_pkw.toml", &without_pkw),
        ])
        .unwrap_err();
        assert_eq!(collisions.len(), 1, "{collisions:?}");
        let Clash::CNames(names) = &collisions[0].clash else {
            panic!("{collisions:?}");
        };
        assert!(names.iter().any(|n| n == "m_pkw_pzd2_out_t"), "{names:?}");
        assert!(names
            .iter()
            .all(|n| n.to_ascii_lowercase().starts_with("m_pkw_")));
        let message = collisions[0].to_string();
        assert!(
            message.starts_with("m.toml and m_pkw.toml both declare the C names `"),
            "{message}"
        );
        assert!(merge(vec![files("m.toml", text), files("m.toml", text)]).is_ok());
        assert!(merge(vec![
            files("m.toml", text),
            files("n_pkw.toml", &without_pkw)
        ])
        .is_ok());
    }

    /// A build script gets the findings as values: the code and the place
    /// of each, with the text it points into, as well as their rendering.
    #[test]
    fn a_refused_description_gives_its_diagnostics_as_values() {
        let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
        let fixture = manifest.join("tests/fixtures/invalid/address_out_of_range.toml");
        let out = std::env::temp_dir().join(format!("gsdc-build-error-{}", std::process::id()));
        let error = generate(&fixture, &out).unwrap_err();
        assert!(!out.exists());
        let BuildError::Description {
            findings, refused, ..
        } = &error
        else {
            panic!("{error:?}");
        };
        assert_eq!(*refused, Refused::Errors);
        let description = &findings[0];
        let e101 = description
            .diagnostics
            .iter()
            .find(|d| d.code == "E101")
            .unwrap();
        let span = e101.span.clone().unwrap();
        let (line, _) = crate::line_col(&description.text, span.start);
        assert!(description.text.lines().nth(line - 1).is_some());
        let rendered = error.to_string();
        assert!(rendered.contains("error[E101]"), "{rendered}");
        assert!(rendered.ends_with("nothing written: fix the errors above"));
    }

    #[test]
    fn files_of_one_name_merge_when_identical_and_collide_when_not() {
        let set = |d: &str, files: Vec<Artifact>| (PathBuf::from(d), files);
        let merged = merge(vec![
            set(
                "a.toml",
                vec![artifact("A.GSD", "a"), artifact("support.rs", "s")],
            ),
            set(
                "b.toml",
                vec![artifact("B.GSD", "b"), artifact("support.rs", "s")],
            ),
        ])
        .unwrap();
        let names: Vec<&str> = merged.iter().map(|a| a.file_name.as_str()).collect();
        assert_eq!(names, ["A.GSD", "support.rs", "B.GSD"]);

        let collisions = merge(vec![
            set("x-y.toml", vec![artifact("x_y_layout.rs", "from x-y")]),
            set("x_y.toml", vec![artifact("x_y_layout.rs", "from x_y")]),
            set("z.toml", vec![artifact("x_y_layout.rs", "from z")]),
        ])
        .unwrap_err();
        assert_eq!(collisions.len(), 2);
        assert_eq!(
            collisions[0].to_string(),
            "x-y.toml and x_y.toml both give x_y_layout.rs, with different contents"
        );
        assert_eq!(collisions[1].second, PathBuf::from("z.toml"));
    }

    /// The validation step, given a GSDML gsdc would not write: the PI schema
    /// rejects it with E399 findings placed in it, named after the file and
    /// its description; the GSDML gsdc writes passes.
    #[cfg(feature = "xsd")]
    #[test]
    fn the_schema_step_rejects_a_gsdml_that_breaks_the_pi_schema() {
        let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
        let schema = manifest.join("../shared/reference/gsdml-xsd-v2.44");
        let mut compiler = Config::new().xsd(schema).compiler().unwrap();
        let description = manifest.join("descriptions/mv810-pnet02.toml");
        let ir = load_file(&description, "mv810-pnet02.toml")
            .unwrap()
            .ir
            .unwrap();
        let files = crate::compile(&ir).unwrap();
        assert_eq!(compiler.validate("mv810-pnet02.toml", &files).len(), 0);

        let gsdml = files
            .iter()
            .find(|f| f.file_name.ends_with(".xml"))
            .unwrap();
        let text = String::from_utf8(gsdml.contents.clone()).unwrap();
        // `UInt16` is no data type of the schema's (it says `Unsigned16`).
        let broken_text = text.replacen("DataType=\"Unsigned16\"", "DataType=\"UInt16\"", 1);
        assert_ne!(broken_text, text);
        let broken = Artifact::new(
            gsdml.kind,
            gsdml.file_name.clone(),
            broken_text.into_bytes(),
        );
        let layout = files
            .iter()
            .find(|f| f.file_name.ends_with(".rs"))
            .unwrap()
            .clone();
        let rejected = compiler.validate("mv810-pnet02.toml", &[layout, broken]);
        assert_eq!(rejected.len(), 1, "only the GSDML is validated");
        let findings = &rejected[0];
        assert_eq!(
            findings.name,
            format!("{} (generated from mv810-pnet02.toml)", gsdml.file_name)
        );
        assert!(!findings.diagnostics.is_empty());
        for d in findings.diagnostics.iter() {
            assert_eq!(d.code, "E399");
            assert!(d.is_error());
            let span = d.span.clone().expect("placed on its line");
            let line = &findings.text[span];
            assert!(line.contains("UInt16"), "{line}: {}", d.message);
        }
    }
}
