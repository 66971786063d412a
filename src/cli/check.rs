//! `gsdc check`: GSD and GSDML files against gsdc's rules. A file's kind
//! comes from its content, not its name. Files are checked in parallel;
//! each file's findings are printed as soon as it and the files before it
//! are done, in the order of the arguments.

use super::{display_name, say, warn, Status, MAX_SHOWN};
use crate::diag::Diagnostic;
use crate::file_kind::FileKind;
use crate::output::{read_device_file, ReadError};
use crate::xsd::Schema;
use crate::{Diagnostics, Source};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::{Condvar, Mutex, MutexGuard};

pub const EXAMPLES: &str = "Examples:
  gsdc check MD810DP.GSD GSDML-V2.32-MEGMEET-MV800-20230830.xml
  gsdc check dist/*                     # device files and symbols are told by their content; gsdc's layouts are skipped
  gsdc check --format json vendor/*     # a JSON object per finding, and {\"file\",\"errors\",\"warnings\"} per file
  gsdc check --xsd ../pi/gsdml-xsd-v2.44 vendor/*.xml   # also the PI schema (feature `xsd`)
  unzip -p device.zip '*.xml' | gsdc check /dev/stdin

Exit codes: 0 no errors, 1 a file has errors or is neither a GSD, a GSDML, a device
symbol nor one of gsdc's own files (layouts, support files, datasheets: skipped),
2 usage or I/O error (a file that cannot be read, output that cannot be written).";

#[derive(clap::Args)]
pub struct Args {
    /// GSD and GSDML files, told apart by their content (GSD: a `#Profibus_DP`
    /// line; GSDML: XML), in UTF-8, ISO-8859-1 or UTF-16; `/dev/stdin` too.
    #[arg(required = true, value_name = "FILE")]
    files: Vec<PathBuf>,
    /// How findings are printed: rendered with a summary line per file, or one
    /// JSON object per finding and a summary object per file.
    #[arg(long, value_enum, default_value = "human")]
    format: Format,
    /// Also validate GSDML files against the PI schema in DIR
    /// (GSDML-DeviceProfile-v2.44.xsd and its imports; needs the `xsd` feature).
    #[arg(long, value_name = "DIR")]
    xsd: Option<PathBuf>,
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// Rendered diagnostics and a summary per file.
    Human,
    /// One JSON object per finding, one per line; each file ends with
    /// {"file":...,"errors":N,"warnings":M}.
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

pub fn run(args: &Args) -> Status {
    // Each thread checks whole files: the rules, then the schema when asked
    // for, with a schema of its own (libxml2's contexts must stay on the
    // thread that made them; compiling one takes milliseconds).
    let load = || args.xsd.as_deref().map(Schema::load).transpose();
    let check =
        |schema: &mut Option<Schema>, path: &Path| check_one(path, schema.as_mut(), args.format);
    let mut status = Status::Ok;
    let print_each = |i: usize, report| {
        status = status.max(print(&args.files[i], report));
    };
    if let Err(why) = in_order(&args.files, load, check, print_each) {
        warn(&format!("error: --xsd: {why}"));
        return Status::UsageOrIo;
    }
    status
}

/// How many files past the first one not yet printed may be taken: the
/// bound of the reports waiting to be printed, whatever the number of files.
const WINDOW: usize = 64;

/// What the threads of [`in_order`] share.
struct Queue<R, E> {
    /// Reports done and not yet handed on, by file.
    done: BTreeMap<usize, R>,
    /// The next file to hand on.
    next_out: usize,
    started: Vec<bool>,
    workers: usize,
    failed: Option<E>,
}

/// `job` for every file, on as many threads as the machine has cores, each
/// with a state of its own from `init`; `sink` gets each result in the
/// order of `files` as soon as it and every result before it are done.
/// Threads take files from a window of [`WINDOW`] files from the first not
/// yet handed on, so at most that many results wait, and in it the largest
/// first, so that a large file taken last does not leave the other threads
/// idle. `Err` when a thread's `init` fails.
fn in_order<S, R: Send, E: Send>(
    files: &[PathBuf],
    init: impl Fn() -> Result<S, E> + Sync,
    job: impl Fn(&mut S, &Path) -> R + Sync,
    mut sink: impl FnMut(usize, R),
) -> Result<(), E> {
    let size = |path: &PathBuf| std::fs::metadata(path).map_or(0, |m| m.len());
    let sizes: Vec<u64> = files.iter().map(size).collect();
    let workers = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .clamp(1, files.len().max(1));
    let queue = Mutex::new(Queue {
        done: BTreeMap::new(),
        next_out: 0,
        started: vec![false; files.len()],
        workers,
        failed: None,
    });
    let changed = Condvar::new();
    let lock = || queue.lock().unwrap_or_else(|e| e.into_inner());
    let work = || {
        // Counts the thread out however it ends, a panic included, so that
        // the printing thread never waits for a result that cannot come.
        let _leaving = Leaving(&queue, &changed);
        let mut state = match init() {
            Ok(state) => state,
            Err(e) => {
                lock().failed.get_or_insert(e);
                return;
            }
        };
        let mut q = lock();
        loop {
            if q.failed.is_some() {
                return;
            }
            let window = q.next_out..files.len().min(q.next_out + WINDOW);
            let largest = window
                .filter(|&i| !q.started[i])
                .max_by_key(|&i| (sizes[i], std::cmp::Reverse(i)));
            match largest {
                Some(i) => {
                    q.started[i] = true;
                    drop(q);
                    let result = job(&mut state, &files[i]);
                    q = lock();
                    q.done.insert(i, result);
                    changed.notify_all();
                }
                None if q.started.iter().skip(q.next_out).all(|s| *s) => return,
                None => q = changed.wait(q).unwrap_or_else(|e| e.into_inner()),
            }
        }
    };
    std::thread::scope(|scope| {
        for _ in 0..workers {
            scope.spawn(work);
        }
        let mut q = lock();
        while q.next_out < files.len() && q.failed.is_none() {
            let next = q.next_out;
            match q.done.remove(&next) {
                Some(result) => {
                    q.next_out += 1;
                    changed.notify_all();
                    drop(q);
                    sink(next, result);
                    q = lock();
                }
                // The threads are gone (one panicked): the scope re-raises it.
                None if q.workers == 0 => break,
                None => q = changed.wait(q).unwrap_or_else(|e| e.into_inner()),
            }
        }
    });
    match queue.into_inner().unwrap_or_else(|e| e.into_inner()).failed {
        Some(e) => Err(e),
        None => Ok(()),
    }
}

/// Takes a worker off [`Queue::workers`] when dropped.
struct Leaving<'a, R, E>(&'a Mutex<Queue<R, E>>, &'a Condvar);

impl<R, E> Drop for Leaving<'_, R, E> {
    fn drop(&mut self) {
        let mut q: MutexGuard<'_, Queue<R, E>> = self.0.lock().unwrap_or_else(|e| e.into_inner());
        q.workers -= 1;
        self.1.notify_all();
    }
}

/// What `gsdc check` says of one file, printed as it prints it, for a
/// command that cannot use the file (`gsdc diff`).
pub(super) fn explain(path: &Path, format: Format) -> Status {
    print(path, check_one(path, None, format))
}

fn check_one(path: &Path, schema: Option<&mut Schema>, format: Format) -> Report {
    // JSON escapes the name itself; the human output shows it escaped.
    let name = match format {
        Format::Human => display_name(path),
        Format::Json => path.to_string_lossy().into_owned(),
    };
    let (kind, bytes) = match read_device_file(path) {
        Ok(read) => read,
        Err(ReadError::TooLarge(d)) => return render(&name, "", &Diagnostics(vec![d]), format),
        Err(ReadError::Io(e)) => return Report::Unreadable(e.to_string()),
    };
    match kind {
        FileKind::Gsd => {
            let (text, diagnostics) = crate::gsd::check_bytes(&bytes);
            render(&name, &text, &diagnostics, format)
        }
        FileKind::Gsdml => match crate::gsdml::decode(&bytes) {
            Ok(text) => {
                let diagnostics = check_gsdml(path, &text, schema);
                render(&name, &text, &diagnostics, format)
            }
            Err(d) => {
                let text = String::from_utf8_lossy(&bytes);
                render(&name, &text, &Diagnostics(vec![d]), format)
            }
        },
        FileKind::Bitmap => render(&name, "", &crate::symbol::check::check(&bytes), format),
        FileKind::Neither if crate::output::carries_mark(&bytes) => gsdcs_own(&name, format),
        FileKind::Neither => neither(&name, format),
    }
}

/// A file gsdc made that is no device file (a firmware layout, a support
/// file, a datasheet): one note, and not checked; `gsdc check dist/*` after
/// a build passes. gsdc's own GSD and GSDML files are checked.
fn gsdcs_own(name: &str, format: Format) -> Report {
    const WHAT: &str =
        "made by gsdc (a firmware layout, support file or datasheet), not a device file";
    let output = match format {
        Format::Human => format!("note: {name} is {WHAT}: skipped"),
        Format::Json => super::json::skipped(name, WHAT),
    };
    Report::Checked {
        output,
        not_shown: None,
        errors: 0,
    }
}

/// gsdc's rules, then the schema's findings when there is a schema.
fn check_gsdml(path: &Path, text: &str, schema: Option<&mut Schema>) -> Diagnostics {
    let mut diagnostics = crate::gsdml::check(text, own_name(path));
    if let Some(schema) = schema {
        // The text read, not the file again: it may have changed since.
        diagnostics.extend(schema.validate(text));
    }
    diagnostics
}

/// The file's own name, for the naming-convention rules: a stream handed
/// over by the shell (`/dev/stdin`, `<(...)`) has none.
fn own_name(path: &Path) -> Option<&str> {
    if is_stream(path) {
        return None;
    }
    path.file_name().and_then(|name| name.to_str())
}

fn is_stream(path: &Path) -> bool {
    path.starts_with("/dev") || path.starts_with("/proc") || !path.is_file()
}

/// A file that is neither a GSD nor a GSDML file: one line (or one JSON
/// object and the file's summary), an error.
fn neither(name: &str, format: Format) -> Report {
    let diagnostic = Diagnostic::error(
        "E400",
        "neither a GSD file (no line starts with #Profibus_DP) nor a GSDML file (not XML)",
    )
    .help("gsdc check reads GSD and GSDML files; this one was not checked");
    let output = match format {
        Format::Human => format!("error[E400]: {name} is {}: not checked", diagnostic.message),
        Format::Json => {
            let source = Source::new(name, "");
            format!(
                "{}\n{}",
                super::json::finding(&source, &diagnostic),
                super::json::summary(name, 1, 0)
            )
        }
    };
    Report::Checked {
        output,
        not_shown: None,
        errors: 1,
    }
}

/// The findings as they are printed: at most [`MAX_SHOWN`], rendered or as
/// JSON lines, and the summary.
fn render(name: &str, text: &str, diagnostics: &Diagnostics, format: Format) -> Report {
    let source = Source::new(name, text);
    let errors = diagnostics.errors().count();
    let warnings = diagnostics.iter().count() - errors;
    let shown = diagnostics.iter().take(MAX_SHOWN);
    let mut lines: Vec<String> = match format {
        Format::Human => shown.map(|d| source.render(d)).collect(),
        Format::Json => shown.map(|d| super::json::finding(&source, d)).collect(),
    };
    lines.push(match format {
        Format::Human => format!("{name}: {errors} error(s), {warnings} warning(s)"),
        Format::Json => super::json::summary(name, errors, warnings),
    });
    let hidden = diagnostics.iter().count().saturating_sub(MAX_SHOWN);
    Report::Checked {
        output: lines.join("\n"),
        not_shown: (hidden > 0).then(|| format!("{name}: {hidden} more finding(s) not shown")),
        errors,
    }
}

fn print(path: &Path, report: Report) -> Status {
    let (output, not_shown, errors) = match report {
        Report::Checked {
            output,
            not_shown,
            errors,
        } => (output, not_shown, errors),
        Report::Unreadable(why) => {
            warn(&format!("error: cannot read {}: {why}", display_name(path)));
            return Status::UsageOrIo;
        }
    };
    say(&output);
    if let Some(note) = not_shown {
        warn(&note);
    }
    if errors > 0 {
        Status::InputErrors
    } else {
        Status::Ok
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering};

    /// A result that counts how many of its kind are alive.
    struct Counted<'a>(&'a AtomicUsize);

    impl Drop for Counted<'_> {
        fn drop(&mut self) {
            self.0.fetch_sub(1, Ordering::SeqCst);
        }
    }

    /// Results come in order, and however many files there are, no more
    /// than the window and the threads' files in flight are ever held.
    #[test]
    fn results_come_in_order_and_at_most_a_window_waits() {
        let files: Vec<PathBuf> = (0..2_000).map(|i| PathBuf::from(format!("f{i}"))).collect();
        let alive = AtomicUsize::new(0);
        let most = AtomicUsize::new(0);
        let job = |_: &mut (), path: &Path| {
            let now = alive.fetch_add(1, Ordering::SeqCst) + 1;
            most.fetch_max(now, Ordering::SeqCst);
            // The first file is slow: the others must wait for it in the window.
            if path == Path::new("f0") {
                std::thread::sleep(std::time::Duration::from_millis(200));
            }
            (path.to_path_buf(), Counted(&alive))
        };
        let mut seen = Vec::new();
        let sink = |i: usize, (path, counted): (PathBuf, Counted<'_>)| {
            seen.push((i, path));
            drop(counted);
        };
        in_order(&files, || Ok::<(), ()>(()), job, sink).unwrap();
        let expected: Vec<(usize, PathBuf)> = files.iter().cloned().enumerate().collect();
        assert_eq!(seen, expected);
        let workers = std::thread::available_parallelism().map_or(1, |n| n.get());
        let most = most.load(Ordering::SeqCst);
        assert!(most <= WINDOW + workers, "{most} results held at once");
    }

    #[test]
    fn a_failing_init_is_the_error() {
        let files = vec![PathBuf::from("a"), PathBuf::from("b")];
        let result = in_order(&files, || Err::<(), _>("no schema"), |_, _| (), |_, _| {});
        assert_eq!(result, Err("no schema"));
    }
}
