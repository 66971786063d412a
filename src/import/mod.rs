//! `gsdc import`: a GSD file written back as a description, and the round
//! trip judged. The description's build is read as a device again and
//! compared with the file (`crate::diff`): each breaking or compatible
//! change is an error (E601), the import would describe another device;
//! what the description has no place for is a warning (W600) when the
//! round trip shows it changes nothing a master acts on. Pure: bytes in,
//! text and diagnostics out.
//!
//! GSDML files are refused for now (E602): the description cannot yet say
//! their module and submodule ident numbers.

mod dp;
mod symbol;
mod toml_out;

pub use symbol::ImportedSymbol;

use crate::device::{Device, Place};
use crate::diag::{Diagnostic, Diagnostics};
use crate::diff::{Change, Class};

/// What an import gives: the description (none when refused or when it
/// would describe another device), and every diagnostic, against `text`.
#[derive(Debug)]
#[non_exhaustive]
pub struct Imported {
    pub description: Option<String>,
    /// The file's text as gsdc reads it, for the diagnostics' spans.
    pub text: String,
    pub diagnostics: Diagnostics,
    /// The device symbol to write beside the description, under the name
    /// its `[device] symbol` gives; none without a description.
    pub symbol: Option<ImportedSymbol>,
    /// How many keywords and elements have no place in the description.
    pub unsaid: usize,
    /// How many changes the round trip found, by class.
    pub round_trip: RoundTrip,
}

/// The changes between the file and the build of its import.
#[derive(Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct RoundTrip {
    pub breaking: usize,
    pub compatible: usize,
    pub cosmetic: usize,
}

impl RoundTrip {
    /// No breaking and no compatible change: the same device.
    pub fn is_clean(&self) -> bool {
        self.breaking == 0 && self.compatible == 0
    }
}

/// Gives the bytes of a file named beside the imported one (its device
/// symbol's bitmap), or says why it cannot.
pub type Files<'a> = &'a dyn Fn(&str) -> Result<Vec<u8>, String>;

/// Imports one GSD file, `file_name` its own name (it becomes the
/// description's `file_name` and the reason under `[choices]`), without
/// the files beside it: a `Bitmap_Device` is left out (W600).
pub fn import(file_name: &str, bytes: &[u8]) -> Imported {
    import_with(file_name, bytes, &|name: &str| {
        Err(format!(
            "{name}: gsdc::import::import reads no files; import_with does"
        ))
    })
}

/// [`import`] with the files beside the GSD: `files` gives the bytes of
/// the bitmap `Bitmap_Device` names (`NAME.bmp`). The core reads nothing.
pub fn import_with(file_name: &str, bytes: &[u8], files: Files<'_>) -> Imported {
    let text = crate::gsd::decode(bytes).into_owned();
    let mut notes = Notes::new(&text);
    let device = crate::device::read(bytes, Some(file_name));
    let mut symbol = None;
    let description = match &device {
        Some(Device::Dp(d)) => {
            symbol = symbol::imported(d, files, &mut notes);
            let symbol_name = symbol.as_ref().map(|s| s.file_name.as_str());
            dp::describe(d, file_name, symbol_name, &mut notes)
        }
        Some(Device::Pn(_)) => {
            notes.refuse("gsdc imports GSD files only: the description cannot yet state a GSDML file's module and submodule ident numbers");
            None
        }
        None => {
            notes.refuse("not a GSD or GSDML file gsdc can read: `gsdc check` says why");
            None
        }
    };
    let mut round_trip = RoundTrip::default();
    let description = description.and_then(|toml| {
        let old = device.as_ref()?;
        let changes = rebuilt_changes(file_name, &toml, symbol.as_ref(), old, &mut notes)?;
        for change in &changes {
            match change.class {
                Class::Breaking => round_trip.breaking += 1,
                Class::Compatible => round_trip.compatible += 1,
                Class::Cosmetic => round_trip.cosmetic += 1,
            }
            if change.class != Class::Cosmetic {
                notes.different(change);
            }
        }
        round_trip.is_clean().then_some(toml)
    });
    Imported {
        symbol: symbol.filter(|_| description.is_some()),
        description,
        text,
        unsaid: notes.unsaid,
        diagnostics: notes.diagnostics,
        round_trip,
    }
}

/// Loads the description (with its symbol), writes its GSD (the file a
/// build writes; the layouts and the datasheet do not enter the
/// comparison) and compares it with the file's device; `None` (and an
/// error) when the description does not load.
fn rebuilt_changes(
    file_name: &str,
    toml: &str,
    symbol: Option<&ImportedSymbol>,
    old: &Device,
    notes: &mut Notes,
) -> Option<Vec<Change>> {
    let name = format!(
        "{}.toml",
        file_name.rsplit_once('.').map_or(file_name, |(s, _)| s)
    );
    let files = |path: &str| match symbol {
        Some(s) if s.file_name == path => Ok(s.png.clone()),
        _ => Err(format!("{path}: the import wrote no such file")),
    };
    let (ir, diagnostics) = crate::load_with(&name, toml, &files);
    let errors: Vec<&Diagnostic> = diagnostics.errors().collect();
    let (Some(ir), true) = (ir, errors.is_empty()) else {
        notes.not_built(errors.into_iter());
        return None;
    };
    let profibus = ir.profibus.as_ref()?;
    let gsd = crate::emit::gsd::emit(&ir, profibus);
    let new = crate::device::read(gsd.as_bytes(), Some(&profibus.file_name))?;
    crate::diff::compare(old, &new)
}

/// The diagnostics of one import, each at a line of the file.
struct Notes {
    lines: Vec<usize>,
    len: usize,
    diagnostics: Diagnostics,
    unsaid: usize,
}

impl Notes {
    fn new(text: &str) -> Notes {
        let starts = text.match_indices('\n').map(|(i, _)| i + 1);
        Notes {
            lines: std::iter::once(0).chain(starts).collect(),
            len: text.len(),
            diagnostics: Diagnostics::default(),
            unsaid: 0,
        }
    }

    /// The span of a place's line, without its line end.
    fn span(&self, place: &Place) -> Option<std::ops::Range<usize>> {
        let index = usize::try_from(place.line).ok()?.checked_sub(1)?;
        let start = *self.lines.get(index)?;
        let end = self
            .lines
            .get(index + 1)
            .map_or(self.len, |&next| next.saturating_sub(1));
        Some(start..end.max(start))
    }

    /// W600: a keyword or element the description has no place for.
    fn unsaid(&mut self, what: &str, place: &Place, why: &str) {
        self.unsaid += 1;
        let d = Diagnostic::warning("W600", format!("{what} is not imported: {why}"))
            .at_opt(self.span(place))
            .label("left out")
            .help("the round trip judges whether leaving it out changes the device (E601 if so); say it in the device file's manual chapter or extend the description");
        self.diagnostics.push(d);
    }

    /// Any other warning, at a place of the file.
    fn warn_at(&mut self, diagnostic: Diagnostic, place: &Place) {
        let span = self.span(place);
        self.diagnostics.push(diagnostic.at_opt(span));
    }

    /// W600 without a place: a decision the import took for the file.
    fn note(&mut self, message: String) {
        self.unsaid += 1;
        self.diagnostics.push(
            Diagnostic::warning("W600", message)
                .help("check it under [choices] before the release"),
        );
    }

    /// E602: a file the description format cannot say.
    fn refuse(&mut self, why: &str) {
        self.diagnostics.push(
            Diagnostic::error("E602", format!("cannot import this file: {why}"))
                .help("gsdc import takes a drive option card's GSD file"),
        );
    }

    /// E601: a breaking or compatible change between the file and the
    /// import's build.
    fn different(&mut self, change: &Change) {
        let place = change.old.as_ref().or(change.new.as_ref());
        self.diagnostics.push(
            Diagnostic::error(
                "E601",
                format!(
                    "the import builds another device: {} ({}): {}",
                    change.subject, change.class, change.change
                ),
            )
            .at_opt(place.and_then(|p| self.span(p)))
            .label(change.class.as_str())
            .help(change.why.clone()),
        );
    }

    /// E601: the import's description does not build.
    fn not_built<'a>(&mut self, errors: impl Iterator<Item = &'a Diagnostic>) {
        for e in errors {
            self.diagnostics.push(
                Diagnostic::error(
                    "E601",
                    format!("the import does not build: {} {}", e.code, e.message),
                )
                .help("the description cannot say this file as it is"),
            );
        }
    }
}
