//! `gsdc check`: GSD and GSDML files against gsdc's rules. Files are checked
//! in parallel; what is printed follows the order of the arguments.

use super::{display_name, not_shown, say, Status, MAX_SHOWN};
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

/// What checking one file gave, rendered (the file's text is not kept, so a
/// thread's next file can reuse its memory), or why it could not be read.
enum Report {
    Checked {
        /// The findings shown and the summary, for stdout.
        output: String,
        /// How many findings were left out, for stderr.
        not_shown: Option<String>,
        errors: usize,
    },
    Unreadable(String),
}

pub fn run(files: &[PathBuf], format: Format, xsd: Option<&Path>) -> Status {
    // Each thread checks whole files: the rules, then the schema when asked
    // for, with a schema of its own (libxml2's contexts must stay on the
    // thread that made them; compiling one takes milliseconds).
    let load = || xsd.map(load_schema).transpose();
    let check = |schema: &mut Option<Schema>, path: &Path| check_one(path, schema.as_mut(), format);
    let reports = match in_parallel(files, load, check) {
        Ok(reports) => reports,
        Err(why) => {
            eprintln!("error: --xsd: {why}");
            return Status::UsageOrIo;
        }
    };
    files
        .iter()
        .zip(reports)
        .map(|(path, report)| print(&display_name(path), report))
        .max()
        .unwrap_or(Status::Ok)
}

#[cfg(feature = "xsd")]
type Schema = gsdc::xsd::Schema;

/// Without the `xsd` feature no schema is ever loaded.
#[cfg(not(feature = "xsd"))]
enum Schema {}

#[cfg(feature = "xsd")]
fn load_schema(dir: &Path) -> Result<Schema, String> {
    gsdc::xsd::Schema::load(dir)
}

#[cfg(not(feature = "xsd"))]
fn load_schema(_: &Path) -> Result<Schema, String> {
    Err("this gsdc was built without the `xsd` feature: build it with `--features xsd`".into())
}

/// The PI schema's findings for a GSDML file, read from `path` as libxml2
/// streams it; `text` places them.
#[cfg(feature = "xsd")]
fn schema_findings(schema: &mut Schema, path: &Path, text: &str) -> Diagnostics {
    schema.validate_file(path, text)
}

#[cfg(not(feature = "xsd"))]
fn schema_findings(schema: &mut Schema, _: &Path, _: &str) -> Diagnostics {
    match *schema {}
}

fn is_gsdml(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("xml"))
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

fn check_one(path: &Path, schema: Option<&mut Schema>, format: Format) -> Report {
    let name = display_name(path);
    let (text, diagnostics) = match read(path) {
        Ok(bytes) => check_bytes(path, bytes, schema),
        Err(ReadError::TooLarge(d)) => (String::new(), Diagnostics(vec![d])),
        Err(ReadError::Io(e)) => return Report::Unreadable(e.to_string()),
    };
    render(
        &Source {
            name: &name,
            text: &text,
        },
        &diagnostics,
        format,
    )
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

/// GSDML by its `.xml` extension (with the schema's findings after the
/// rules', when there is a schema), GSD otherwise.
fn check_bytes(path: &Path, bytes: Vec<u8>, schema: Option<&mut Schema>) -> (String, Diagnostics) {
    if is_gsdml(path) {
        // UTF-8, or ISO-8859-1 when the XML declaration says so.
        let text = match gsdc::gsdml::decode(&bytes) {
            Ok(text) => Decoded::of(&bytes, text),
            Err(d) => return (Decoded::AsIs.text(bytes), Diagnostics(vec![d])),
        }
        .text(bytes);
        let file_name = path.file_name().map(|f| f.to_string_lossy().into_owned());
        let mut diagnostics = gsdc::gsdml::check(&text, file_name.as_deref());
        if let Some(schema) = schema {
            diagnostics.extend(schema_findings(schema, path, &text));
        }
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

/// The findings as they are printed: at most [`MAX_SHOWN`], rendered or as
/// JSON lines, and the summary.
fn render(source: &Source<'_>, diagnostics: &Diagnostics, format: Format) -> Report {
    let errors = diagnostics.errors().count();
    let warnings = diagnostics.iter().count() - errors;
    let shown = diagnostics.iter().take(MAX_SHOWN);
    let mut lines: Vec<String> = match format {
        Format::Human => shown.map(|d| source.render(d)).collect(),
        Format::Json => shown.map(|d| source.to_json(d)).collect(),
    };
    if format == Format::Human {
        lines.push(format!(
            "{}: {errors} error(s), {warnings} warning(s)",
            source.name
        ));
    }
    Report::Checked {
        output: lines.join("\n"),
        not_shown: not_shown(source.name, diagnostics),
        errors,
    }
}

fn print(name: &str, report: Report) -> Status {
    let (output, not_shown, errors) = match report {
        Report::Checked {
            output,
            not_shown,
            errors,
        } => (output, not_shown, errors),
        Report::Unreadable(why) => {
            eprintln!("error: cannot read {name}: {why}");
            return Status::UsageOrIo;
        }
    };
    if !output.is_empty() {
        say(&output);
    }
    if let Some(note) = not_shown {
        eprintln!("{note}");
    }
    if errors > 0 {
        Status::InputErrors
    } else {
        Status::Ok
    }
}
