//! `gsdc check`: GSD and GSDML files against gsdc's rules. Files are checked
//! in parallel; what is printed follows the order of the arguments.

use super::{display_name, say, say_how_many_not_shown, Status, MAX_SHOWN};
use gsdc::output::ReadError;
use gsdc::{Diagnostics, Source};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// Rendered diagnostics and a summary per file.
    Human,
    /// One JSON object per finding, one per line.
    Json,
}

/// What checking one file gave: its text and diagnostics, or why it could not be read.
enum Report {
    Checked {
        text: String,
        diagnostics: Diagnostics,
    },
    Unreadable(String),
}

pub fn run(files: &[PathBuf], format: Format, xsd: Option<&Path>) -> Status {
    // The schema, when asked for, is checked beside the rules, by threads
    // of its own (libxml2's contexts must stay on one thread).
    let (mut reports, schema) = std::thread::scope(|scope| {
        let schema = xsd.map(|dir| scope.spawn(move || schema_findings(files, dir)));
        let reports = check_all(files);
        let schema = schema.map(|thread| {
            thread
                .join()
                .unwrap_or_else(|_| Err("the schema check failed".into()))
        });
        (reports, schema)
    });
    match schema {
        Some(Err(why)) => {
            eprintln!("error: --xsd: {why}");
            return Status::UsageOrIo;
        }
        Some(Ok(findings)) => add_schema_findings(&mut reports, findings),
        None => {}
    }
    files
        .iter()
        .zip(reports)
        .map(|(path, report)| print(&display_name(path), report, format))
        .max()
        .unwrap_or(Status::Ok)
}

fn add_schema_findings(reports: &mut [Report], findings: Vec<Diagnostics>) {
    for (report, found) in reports.iter_mut().zip(findings) {
        if let Report::Checked { diagnostics, .. } = report {
            diagnostics.extend(found);
        }
    }
}

/// The PI schema's findings for each GSDML file (none for other files).
/// Each thread compiles the schema for itself (a few milliseconds): one
/// large file takes libxml2 most of the time all files take.
#[cfg(feature = "xsd")]
fn schema_findings(files: &[PathBuf], dir: &Path) -> Result<Vec<Diagnostics>, String> {
    let load = || gsdc::xsd::Schema::load(dir);
    in_parallel(files, load, |schema, path| {
        // Each file is read here a second time: these threads run beside the
        // rules' workers, and waiting for their copy would serialise the two.
        // Unreadable or too large: the rules say so.
        let bytes = read(path).unwrap_or_default();
        match (is_gsdml(path), gsdc::gsdml::decode(&bytes)) {
            (true, Ok(text)) => schema.validate_file(path, &text),
            _ => Diagnostics::default(),
        }
    })
}

#[cfg(not(feature = "xsd"))]
fn schema_findings(_: &[PathBuf], _: &Path) -> Result<Vec<Diagnostics>, String> {
    Err("this gsdc was built without the `xsd` feature: build it with `--features xsd`".into())
}

fn is_gsdml(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("xml"))
}

/// Checks every file against gsdc's rules.
fn check_all(files: &[PathBuf]) -> Vec<Report> {
    let no_state = || Ok::<(), std::convert::Infallible>(());
    let Ok(reports) = in_parallel(files, no_state, |(), path| check_one(path));
    reports
}

/// `job` for every file, on as many threads as the machine has cores, each
/// with a state of its own from `init`; the results in the order of `files`.
/// The largest files are taken first, so that a large file taken last does
/// not leave the other threads idle while it is done, and its freed memory
/// serves the smaller ones. `Err` when a thread's `init` fails.
fn in_parallel<S, R: Send, E: Send>(
    files: &[PathBuf],
    init: impl Fn() -> Result<S, E> + Sync,
    job: impl Fn(&mut S, &Path) -> R + Sync,
) -> Result<Vec<R>, E> {
    let slots: Vec<Mutex<Option<R>>> = files.iter().map(|_| Mutex::new(None)).collect();
    let mut order: Vec<usize> = (0..files.len()).collect();
    let size = |i: &usize| std::fs::metadata(&files[*i]).map_or(0, |m| m.len());
    order.sort_by_cached_key(|i| std::cmp::Reverse(size(i)));
    let next = AtomicUsize::new(0);
    let workers = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .clamp(1, files.len().max(1));
    let work = || -> Result<(), E> {
        let mut state = init()?;
        while let Some(&i) = order.get(next.fetch_add(1, Ordering::Relaxed)) {
            let result = job(&mut state, &files[i]);
            *slots[i].lock().unwrap_or_else(|e| e.into_inner()) = Some(result);
        }
        Ok(())
    };
    std::thread::scope(|scope| {
        let threads: Vec<_> = (0..workers).map(|_| scope.spawn(work)).collect();
        // The scope joins whatever threads are left after an `Err`.
        threads.into_iter().try_for_each(|thread| {
            thread
                .join()
                .unwrap_or_else(|panic| std::panic::resume_unwind(panic))
        })
    })?;
    Ok(slots
        .into_iter()
        .map(|slot| {
            slot.into_inner()
                .unwrap_or_else(|e| e.into_inner())
                .expect("every file was done")
        })
        .collect())
}

fn check_one(path: &Path) -> Report {
    match read(path) {
        Ok(bytes) => {
            let (text, diagnostics) = check_bytes(path, bytes);
            Report::Checked { text, diagnostics }
        }
        Err(ReadError::TooLarge(d)) => Report::Checked {
            text: String::new(),
            diagnostics: Diagnostics(vec![d]),
        },
        Err(ReadError::Io(e)) => Report::Unreadable(e.to_string()),
    }
}

/// The file's bytes, refused by size before they are read when they are
/// more than its reader takes.
fn read(path: &Path) -> Result<Vec<u8>, ReadError> {
    let limit = if is_gsdml(path) {
        &gsdc::gsdml::INPUT_LIMIT
    } else {
        &gsdc::gsd::INPUT_LIMIT
    };
    gsdc::output::read_input(path, limit)
}

/// GSDML by its `.xml` extension, GSD otherwise.
fn check_bytes(path: &Path, bytes: Vec<u8>) -> (String, Diagnostics) {
    if is_gsdml(path) {
        // UTF-8, or ISO-8859-1 when the XML declaration says so.
        let text = match gsdc::gsdml::decode(&bytes) {
            Ok(text) => Decoded::of(&bytes, text),
            Err(d) => return (Decoded::AsIs.text(bytes), Diagnostics(vec![d])),
        }
        .text(bytes);
        let file_name = path.file_name().map(|f| f.to_string_lossy().into_owned());
        let diagnostics = gsdc::gsdml::check(&text, file_name.as_deref());
        (text, diagnostics)
    } else {
        let text = Decoded::of(&bytes, gsdc::gsd::decode(&bytes)).text(bytes);
        let diagnostics = gsdc::gsd::check(&text);
        (text, diagnostics)
    }
}

/// A file's text: its bytes as they are when they are UTF-8 and nothing was
/// taken off (most files), else the converted text. Keeping the bytes spares
/// a copy, whose fresh pages cost a megabyte file more than its check.
enum Decoded {
    AsIs,
    Converted(String),
}

impl Decoded {
    fn of(bytes: &[u8], text: std::borrow::Cow<'_, str>) -> Decoded {
        match text {
            std::borrow::Cow::Borrowed(t) if t.len() == bytes.len() => Decoded::AsIs,
            text => Decoded::Converted(text.into_owned()),
        }
    }

    /// The text, from the bytes it was decoded from (as they are, with any
    /// byte that is not UTF-8 replaced, for a file that failed to decode).
    fn text(self, bytes: Vec<u8>) -> String {
        match self {
            Decoded::AsIs => String::from_utf8(bytes)
                .unwrap_or_else(|e| String::from_utf8_lossy(e.as_bytes()).into_owned()),
            Decoded::Converted(text) => text,
        }
    }
}

fn print(name: &str, report: Report, format: Format) -> Status {
    let (text, diagnostics) = match report {
        Report::Checked { text, diagnostics } => (text, diagnostics),
        Report::Unreadable(why) => {
            eprintln!("error: cannot read {name}: {why}");
            return Status::UsageOrIo;
        }
    };
    let source = Source { name, text: &text };
    let errors = diagnostics.errors().count();
    let warnings = diagnostics.iter().count() - errors;
    let shown = diagnostics.iter().take(MAX_SHOWN);
    match format {
        Format::Human => {
            for d in shown {
                say(&source.render(d));
            }
            say(&format!("{name}: {errors} error(s), {warnings} warning(s)"));
        }
        Format::Json => {
            for d in shown {
                say(&source.to_json(d));
            }
        }
    }
    say_how_many_not_shown(name, &diagnostics);
    if errors > 0 {
        Status::InputErrors
    } else {
        Status::Ok
    }
}
