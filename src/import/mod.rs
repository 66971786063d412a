//! `gsdc import`: a GSD or GSDML file written back as a description, and
//! the round trip judged. The description's build is read as a device again and
//! compared with the file (`crate::diff`): each breaking or compatible
//! change is an error (E601), the import would describe another device;
//! what the description has no place for is a warning (W600) when the
//! round trip shows it changes nothing a master acts on. Pure: bytes in,
//! text and diagnostics out.
//!
//! A GSD is written as the PROFIBUS part of a description (`dp`), a
//! GSDML file as the PROFINET part (`pn`), a GSD and a GSDML file of one
//! card as one description with both buses (`both`).

mod both;
mod dp;
mod gateway;
mod numbered;
mod pn;
mod prm;
mod symbol;
mod toml_out;

use toml_out::{quote, TomlOut};

pub use both::{import_both, Both};
pub use symbol::ImportedSymbol;

use crate::device::{Device, Place};
use crate::diag::{Diagnostic, Diagnostics, Lines};
use crate::diff::{Change, Class};

/// What an import gives: the description (none when refused or when it
/// would describe another device), and every diagnostic, against `text`.
#[derive(Debug)]
#[non_exhaustive]
pub struct Imported {
    /// The description, when its build is the file's device: what `gsdc
    /// import` writes.
    pub description: Option<String>,
    /// The description when it builds but its build is another device
    /// (E601), as a draft: its `[draft]` table lists each change the round
    /// trip found and each part of the file left out (W604 at every build
    /// until deleted). `gsdc import --draft` writes it.
    pub draft: Option<String>,
    /// The file's text as gsdc reads it, for the diagnostics' spans.
    pub text: String,
    pub diagnostics: Diagnostics,
    /// The device symbol to write beside the description, under the name
    /// its `[device] symbol` gives; none without a description or a draft.
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

/// Imports one GSD or GSDML file, `file_name` its own name (a GSD's
/// becomes the description's `file_name`, a GSDML file's name its vendor,
/// family and date; either is the reason under `[choices]`), without the
/// files beside it: the device symbol is left out (W600).
pub fn import(file_name: &str, bytes: &[u8]) -> Imported {
    import_with(file_name, bytes, &no_files)
}

/// [`import`] with the files beside the imported one: `files` gives the
/// bytes of the bitmap a GSD's `Bitmap_Device` or a GSDML file's device
/// symbol names (`NAME.bmp`). The core reads nothing.
pub fn import_with(file_name: &str, bytes: &[u8], files: Files<'_>) -> Imported {
    let (device, text) = read(file_name, bytes);
    let mut notes = Notes::new(text);
    let mut symbol = None;
    let description = match &device {
        Some(device) => {
            symbol = symbol::imported(symbol::of(device), files, &mut notes);
            let symbol_name = symbol.as_ref().map(|s| s.file_name.as_str());
            let described = match device {
                Device::Dp(d) => dp::describe(d, file_name, symbol_name, &mut notes),
                Device::Pn(d) => pn::describe(d, file_name, symbol_name, &mut notes),
            };
            described.map(TomlOut::finish)
        }
        None => {
            notes.refuse("not a GSD or GSDML file gsdc can read: `gsdc check` says why");
            None
        }
    };
    let mut round_trip = RoundTrip::default();
    let built = description.and_then(|toml| {
        round_trip = judge(
            file_name,
            &toml,
            symbol.as_ref(),
            device.as_ref()?,
            &mut notes,
        )?;
        Some(toml)
    });
    let (description, draft) = match built {
        Some(toml) if round_trip.is_clean() => (Some(toml), None),
        built => (None, built.map(|toml| draft(&toml, &[(file_name, &notes)]))),
    };
    let symbol = symbol.filter(|_| description.is_some() || draft.is_some());
    notes.imported((description, draft), symbol, round_trip)
}

/// The [`Files`] of an import without any.
fn no_files(name: &str) -> Result<Vec<u8>, String> {
    Err(format!(
        "{name}: gsdc::import::import reads no files; import_with does"
    ))
}

/// The device a file describes, and its text as gsdc reads it.
fn read(file_name: &str, bytes: &[u8]) -> (Option<Device>, String) {
    let (device, text) = crate::device::read_with_text(bytes, Some(file_name));
    (device, text.into_owned())
}

/// A description whose build is another device than the files it was
/// imported from (each file's name and notes), as a draft: a header that
/// says so, and a `[draft]` table listing each change the round trip found
/// and each part of a file left out, as `FILE:LINE: what`.
fn draft(toml: &str, files: &[(&str, &Notes)]) -> String {
    let names: Vec<&str> = files.iter().map(|(name, _)| *name).collect();
    let listed = |pick: fn(&Notes) -> &[Listed]| {
        let items = files
            .iter()
            .flat_map(|(name, notes)| pick(notes).iter().map(move |item| quote(&item.shown(name))));
        let lines: Vec<String> = items.map(|item| format!("  {item},\n")).collect();
        format!("[\n{}]", lines.concat())
    };
    format!(
        "# A DRAFT (gsdc import --draft) of {}: its build is another device.\n\
         # [draft] at the end lists each change the round trip found and each part left out.\n\
         # Mend or accept each, then delete [draft]: until then every build warns (W604).\n\
         {toml}\n[draft]\nchanges = {}\nleft_out = {}\n",
        names.join(" and "),
        listed(|n| &n.changes),
        listed(|n| &n.left_out),
    )
}

/// The round trip of `toml` against the file's device `old`: each breaking
/// or compatible change an error (E601); `None` when the description does
/// not build.
fn judge(
    file_name: &str,
    toml: &str,
    symbol: Option<&ImportedSymbol>,
    old: &Device,
    notes: &mut Notes,
) -> Option<RoundTrip> {
    let changes = rebuilt_changes(file_name, toml, symbol, old, notes)?;
    let mut round_trip = RoundTrip::default();
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
    Some(round_trip)
}

/// Loads the description (with its symbol), writes its GSD or GSDML file
/// (the file a build writes; the layouts and the datasheet do not enter
/// the comparison) and compares it with the file's device; `None` (and an
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
    let (file, name) = match old {
        Device::Dp(_) => {
            let profibus = ir.profibus.as_ref()?;
            (crate::emit::gsd::emit(&ir, profibus), &profibus.file_name)
        }
        Device::Pn(_) => {
            let profinet = ir.profinet.as_ref()?;
            (crate::emit::gsdml::emit(&ir, profinet), &profinet.file_name)
        }
    };
    let new = crate::device::read(file.as_bytes(), Some(name))?;
    crate::diff::compare(old, &new)
}

const REFUSED_HELP: &str = "gsdc import takes a drive option card's GSD or GSDML file whose modules carry its telegram (PKW and PZD words, standard telegram 1), or a gateway's GSD as gsdc writes it";

/// The diagnostics of one import, each at a line of the file.
struct Notes {
    text: String,
    lines: Lines,
    diagnostics: Diagnostics,
    unsaid: usize,
    /// The keys whose value the import chose, with why: each is marked
    /// under `[choices]` with it.
    chosen: Vec<(String, String)>,
    /// Each breaking or compatible change the round trip found, and each
    /// part of the file left out: what a draft lists.
    changes: Vec<Listed>,
    left_out: Vec<Listed>,
}

/// A finding a draft lists, at its line of the file where it has one.
struct Listed {
    line: Option<u32>,
    what: String,
}

impl Listed {
    /// `FILE:LINE: what`, or `FILE: what` without a line.
    fn shown(&self, file: &str) -> String {
        match self.line {
            Some(line) => format!("{file}:{line}: {}", self.what),
            None => format!("{file}: {}", self.what),
        }
    }
}

impl Notes {
    fn imported(
        self,
        (description, draft): (Option<String>, Option<String>),
        symbol: Option<ImportedSymbol>,
        round_trip: RoundTrip,
    ) -> Imported {
        Imported {
            description,
            draft,
            symbol,
            text: self.text,
            unsaid: self.unsaid,
            diagnostics: self.diagnostics,
            round_trip,
        }
    }

    /// Notes of a trial run, whose findings are dropped.
    fn scratch() -> Notes {
        Notes::new(String::new())
    }

    fn new(text: String) -> Notes {
        Notes {
            lines: Lines::of(&text),
            text,
            diagnostics: Diagnostics::default(),
            unsaid: 0,
            chosen: Vec::new(),
            changes: Vec::new(),
            left_out: Vec::new(),
        }
    }

    /// The span of a place's line, without its line end.
    fn span(&self, place: &Place) -> Option<std::ops::Range<usize>> {
        let index = usize::try_from(place.line).ok()?.checked_sub(1)?;
        let starts = self.lines.starts();
        let start = *starts.get(index)?;
        let end = starts
            .get(index + 1)
            .map_or(self.text.len(), |&next| next.saturating_sub(1));
        Some(start..end.max(start))
    }

    /// The comment lines right above a place's line, without their `;`, in
    /// order: where gsdc's own GSD says in words what no keyword can.
    fn comments_above(&self, place: &Place) -> Vec<&str> {
        let index = usize::try_from(place.line).unwrap_or(0).saturating_sub(1);
        let starts = self.lines.starts();
        let mut comments: Vec<&str> = starts[..index.min(starts.len())]
            .iter()
            .rev()
            .map(|&start| self.text[start..].lines().next().unwrap_or_default().trim())
            .take_while(|line| line.starts_with(';'))
            .map(|line| line.trim_start_matches(';').trim())
            .collect();
        comments.reverse();
        comments
    }

    /// W600: a keyword or element the description has no place for.
    fn unsaid(&mut self, what: &str, place: &Place, why: &str) {
        self.unsaid += 1;
        let message = format!("{what} is not imported: {why}");
        self.left_out.push(Listed {
            line: Some(place.line).filter(|&l| l > 0),
            what: message.clone(),
        });
        let d = Diagnostic::warning("W600", message)
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
        self.left_out.push(Listed {
            line: None,
            what: message.clone(),
        });
        self.diagnostics.push(
            Diagnostic::warning("W600", message)
                .help("check it under [choices] before the release"),
        );
    }

    /// [`Notes::note`] for a value of the description's `key` the import
    /// chose: one it writes otherwise than the file (a version or a class
    /// gsdc does not write), or one the file does not say unambiguously.
    /// [`Notes::chosen_marks`] marks it under `[choices]` with the same
    /// words: the header's "every value below is the file's" does not hold
    /// for it.
    fn chosen(&mut self, key: &str, message: String) {
        self.chosen.push((key.to_string(), message.clone()));
        self.note(message);
    }

    /// `[choices]` marks for the values the import chose.
    fn chosen_marks(&self, out: &mut TomlOut) {
        for (key, why) in &self.chosen {
            out.key(&quote(key), quote(why));
        }
    }

    /// E602: a file the description format cannot say.
    fn refuse(&mut self, why: &str) {
        self.diagnostics.push(
            Diagnostic::error("E602", format!("cannot import this file: {why}")).help(REFUSED_HELP),
        );
    }

    /// E602 at the element (or line) that stops the import.
    fn refuse_at(&mut self, why: &str, place: &Place) {
        let at = place
            .path
            .as_ref()
            .map_or(String::new(), |p| format!(" (at {})", &**p));
        self.diagnostics.push(
            Diagnostic::error("E602", format!("cannot import this file: {why}{at}"))
                .at_opt(self.span(place))
                .label("no place in the description")
                .help(REFUSED_HELP),
        );
    }

    /// E601: a breaking or compatible change between the file and the
    /// import's build, at the file's place of it (a change's `new` place
    /// is a line of the build, which the import does not write).
    fn different(&mut self, change: &Change) {
        let what = format!("{} ({}): {}", change.subject, change.class, change.change);
        self.changes.push(Listed {
            line: change.old.as_ref().map(|p| p.line).filter(|&l| l > 0),
            what: what.clone(),
        });
        self.diagnostics.push(
            Diagnostic::error("E601", format!("the import builds another device: {what}"))
                .at_opt(change.old.as_ref().and_then(|p| self.span(p)))
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diff::Kind;

    fn change(old: Option<u32>, new: Option<u32>) -> Change {
        let at = |line| Place { line, path: None };
        Change {
            class: Class::Breaking,
            kind: Kind::Module,
            judged: true,
            subject: "module \"M\"".into(),
            change: "added".into(),
            why: String::new(),
            old: old.map(at),
            new: new.map(at),
            more: 0,
        }
    }

    /// A change is at the file's line, never at the build's: a module the
    /// build adds has no line in the file, and the draft lists it without
    /// one.
    #[test]
    fn a_change_is_at_the_files_line_or_at_none() {
        let mut notes = Notes::new("first\nsecond\nthird\n".into());
        notes.different(&change(Some(3), Some(1)));
        notes.different(&change(None, Some(2)));
        let spans: Vec<_> = notes.diagnostics.iter().map(|d| d.span.clone()).collect();
        assert_eq!(spans, [Some(13..18), None]);
        let listed: Vec<String> = notes.changes.iter().map(|c| c.shown("F.GSD")).collect();
        assert_eq!(
            listed,
            [
                "F.GSD:3: module \"M\" (breaking): added",
                "F.GSD: module \"M\" (breaking): added"
            ]
        );
    }
}
