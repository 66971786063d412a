//! `gsdc diff OLD NEW`: two GSD files, two GSDML files or two descriptions
//! (by the files they build; a description against a released file too)
//! compared by meaning, each change classed breaking, compatible or
//! cosmetic (`crate::diff`). A file that cannot be read gets what `gsdc
//! check` says of it.

use super::{display_name, say, warn, Status, MAX_SHOWN};
use crate::device::{Device, Place};
use crate::diff::{Change, Class};
use crate::{Artifact, ArtifactKind};
use std::path::{Path, PathBuf};

pub const EXAMPLES: &str = "Examples:
  gsdc diff released/MD810DP.GSD dist/MD810DP.GSD
  gsdc diff released/GSDML-V2.32-INOVANCE-MD810-20261122.xml dist/GSDML-V2.32-INOVANCE-MD810-20261201.xml
  gsdc diff released/MD810DP.GSD descriptions/md810dp.toml   # a description by the file it builds
  git show v1.0:descriptions/md810dp.toml > /tmp/old.toml && gsdc diff /tmp/old.toml descriptions/md810dp.toml
  gsdc diff --format json --fail-on compatible OLD NEW        # in CI

Exit codes: 0 no change at or above --fail-on (breaking by default), 1 one or more,
2 usage or I/O error, or a file that cannot be read (what gsdc check says of it is shown).";

#[derive(clap::Args)]
pub struct Args {
    /// The old GSD or GSDML file, or a description (`.toml`) compared by what it builds.
    #[arg(value_name = "OLD")]
    old: PathBuf,
    /// The new one, of the same kind (a description may stand for either kind).
    #[arg(value_name = "NEW")]
    new: PathBuf,
    /// How the changes are printed: grouped by class with the place in each
    /// file, or one JSON document.
    #[arg(long, value_enum, default_value = "human")]
    format: Format,
    /// The class from which a change makes the exit code 1.
    #[arg(long, value_enum, default_value = "breaking", value_name = "CLASS")]
    fail_on: FailOn,
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum Format {
    /// Changes grouped by class, breaking first, each with why and where.
    Human,
    /// One JSON document: {"pairs":[{"old","new","changes":[...]}],"summary":{...}}.
    Json,
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum FailOn {
    Breaking,
    Compatible,
    Cosmetic,
}

impl FailOn {
    fn class(self) -> Class {
        match self {
            FailOn::Breaking => Class::Breaking,
            FailOn::Compatible => Class::Compatible,
            FailOn::Cosmetic => Class::Cosmetic,
        }
    }
}

/// A device file of one side, as read or as built.
struct DeviceFile {
    /// The path given, or `path (name)` of a file a description builds.
    shown: String,
    device: Device,
}

/// Two files of one kind compared, or a kind only one side has.
struct Pair {
    old: Option<DeviceFile>,
    new: Option<DeviceFile>,
    changes: Vec<Change>,
}

pub fn run(args: &Args) -> Status {
    // The two device files are read on two threads, as `gsdc check` reads
    // files; what went wrong is said afterwards, old side first.
    let (old, new) = std::thread::scope(|scope| {
        let old = scope.spawn(|| read(&args.old));
        let new = read(&args.new);
        (old.join().unwrap_or(Read::Failed(None)), new)
    });
    let (old, new) = match (side(&args.old, old), side(&args.new, new)) {
        (Ok(old), Ok(new)) => (old, new),
        (old, new) => return old.err().max(new.err()).unwrap_or(Status::UsageOrIo),
    };
    let pairs = match pairs(&args.old, old, &args.new, new) {
        Ok(pairs) => pairs,
        Err(why) => {
            warn(&format!("error: {why}"));
            return Status::UsageOrIo;
        }
    };
    match args.format {
        Format::Human => say(&human(&pairs)),
        Format::Json => say(&json(&pairs)),
    }
    let failing = args.fail_on.class();
    let status = match pairs
        .iter()
        .flat_map(|p| &p.changes)
        .any(|c| c.class >= failing)
    {
        true => Status::InputErrors,
        false => Status::Ok,
    };
    // The process ends here: freeing the two devices piece by piece would
    // cost a fifth of reading them, for nothing.
    std::mem::forget(pairs);
    status
}

/// A side as read on its own thread, saying nothing yet.
enum Read {
    File(Box<DeviceFile>),
    /// A description, built afterwards (its findings are printed).
    Description,
    /// The file could not be read (`Some`: the OS error), or cannot be
    /// read as a device file (`None`).
    Failed(Option<std::io::Error>),
}

fn read(path: &Path) -> Read {
    if is_description(path) {
        return Read::Description;
    }
    let bytes = match crate::output::read_device_file(path) {
        Ok((_, bytes)) => bytes,
        Err(crate::output::ReadError::Io(e)) => return Read::Failed(Some(e)),
        Err(crate::output::ReadError::TooLarge(_)) => return Read::Failed(None),
    };
    let name = path.file_name().and_then(|n| n.to_str());
    match crate::device::read(&bytes, name) {
        Some(device) => Read::File(Box::new(DeviceFile {
            shown: display_name(path),
            device,
        })),
        None => Read::Failed(None),
    }
}

/// One side: the device files a description builds, or the one file
/// given. `Err` with the status to exit with, after saying why.
fn side(path: &Path, read: Read) -> Result<Vec<DeviceFile>, Status> {
    match read {
        Read::File(file) => Ok(vec![*file]),
        Read::Description => built(path),
        Read::Failed(Some(e)) => {
            warn(&format!("error: cannot read {}: {e}", display_name(path)));
            Err(Status::UsageOrIo)
        }
        Read::Failed(None) => Err(unreadable(path)),
    }
}

/// A file the diff cannot read: what `gsdc check` says of it, exit 2.
fn unreadable(path: &Path) -> Status {
    super::check::explain(path, super::check::Format::Human);
    warn(&format!(
        "error: {} cannot be read as a GSD or GSDML file: nothing compared",
        display_name(path)
    ));
    Status::UsageOrIo
}

/// The GSD and GSDML files a description builds.
fn built(path: &Path) -> Result<Vec<DeviceFile>, Status> {
    let ir = super::load_description(path).map_err(|_| Status::UsageOrIo)?;
    let files: Vec<Artifact> = match crate::emit::compile_for(&ir, &[]) {
        Ok(files) => files,
        Err(problems) => {
            let findings = crate::build::Findings {
                name: display_name(path),
                text: String::new(),
                diagnostics: problems,
            };
            warn(&findings.rendered(MAX_SHOWN).join("\n"));
            return Err(Status::UsageOrIo);
        }
    };
    let device_files = files
        .iter()
        .filter(|a| matches!(a.kind, ArtifactKind::Gsd | ArtifactKind::Gsdml))
        .filter_map(|a| {
            Some(DeviceFile {
                shown: format!("{} ({})", display_name(path), a.file_name),
                device: crate::device::read(&a.contents, Some(&a.file_name))?,
            })
        })
        .collect();
    Ok(device_files)
}

fn is_gsd(f: &DeviceFile) -> bool {
    matches!(f.device, Device::Dp(_))
}

/// The files of the two sides paired by kind: a file given alone meets the
/// file of its kind on the other side; two descriptions meet kind by kind,
/// and a kind that only one of them builds is a change of its own.
fn pairs(
    old_path: &Path,
    old: Vec<DeviceFile>,
    new_path: &Path,
    new: Vec<DeviceFile>,
) -> Result<Vec<Pair>, String> {
    let kinds: Vec<bool> = match (is_description(old_path), is_description(new_path)) {
        (true, true) => vec![true, false],
        (true, false) => new.iter().map(is_gsd).collect(),
        (false, _) => old.iter().map(is_gsd).collect(),
    };
    let (mut old, mut new) = (old, new);
    let mut pairs = Vec::new();
    for gsd in kinds {
        let take = |files: &mut Vec<DeviceFile>| {
            files
                .iter()
                .position(|f| is_gsd(f) == gsd)
                .map(|i| files.remove(i))
        };
        let pair = match (take(&mut old), take(&mut new)) {
            (Some(a), Some(b)) => {
                let changes = crate::diff::compare(&a.device, &b.device).unwrap_or_default();
                Pair {
                    old: Some(a),
                    new: Some(b),
                    changes,
                }
            }
            (None, None) => continue,
            (a, b) if is_description(old_path) && is_description(new_path) => Pair {
                changes: vec![only_one(gsd, a.is_some())],
                old: a,
                new: b,
            },
            (Some(_), None) => return Err(missing(old_path, new_path, gsd)),
            (None, Some(_)) => return Err(missing(new_path, old_path, gsd)),
        };
        pairs.push(pair);
    }
    Ok(pairs)
}

fn is_description(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("toml"))
}

fn kind_name(gsd: bool) -> &'static str {
    if gsd {
        "GSD"
    } else {
        "GSDML"
    }
}

fn missing(has: &Path, lacks: &Path, gsd: bool) -> String {
    let what = match is_description(lacks) {
        true => "builds no",
        false => "is not a",
    };
    format!(
        "{} is a {kind} file and {} {what} {kind} file: gsdc diff compares files of one kind",
        display_name(has),
        display_name(lacks),
        kind = kind_name(gsd),
    )
}

/// A bus whose file only one description builds.
fn only_one(gsd: bool, old_has_it: bool) -> Change {
    let what = format!("the {} file", kind_name(gsd));
    let (class, change, why) = match old_has_it {
        true => (
            Class::Breaking,
            "no longer built",
            "projects configured with the released file have no file for the new device",
        ),
        false => (Class::Compatible, "now built", "old projects do not use it"),
    };
    crate::diff::Change::file(class, what, change, why)
}

fn human(pairs: &[Pair]) -> String {
    let mut out = Vec::new();
    let mut counts = [0usize; 3];
    for pair in pairs {
        let name =
            |f: &Option<DeviceFile>| f.as_ref().map_or("(none)".to_string(), |f| f.shown.clone());
        out.push(format!("{} → {}", name(&pair.old), name(&pair.new)));
        if pair.changes.is_empty() {
            out.push("  no change".into());
        }
        for class in Class::ALL {
            let changes: Vec<&Change> = pair.changes.iter().filter(|c| c.class == class).collect();
            if changes.is_empty() {
                continue;
            }
            counts[class as usize] += changes.len();
            out.push(format!("{class} ({})", changes.len()));
            for change in changes {
                out.extend(human_change(change));
            }
        }
    }
    out.push(format!(
        "{} breaking, {} compatible, {} cosmetic",
        counts[Class::Breaking as usize],
        counts[Class::Compatible as usize],
        counts[Class::Cosmetic as usize]
    ));
    out.join("\n")
}

fn human_change(change: &Change) -> Vec<String> {
    let judged = if change.judged { "" } else { " (not judged)" };
    let mut lines = vec![format!("  {}: {}{judged}", change.subject, change.change)];
    if !change.why.is_empty() {
        lines.push(format!("      {}", change.why));
    }
    lines.extend(places(change));
    if change.more > 0 {
        lines.push(format!(
            "      and {} more place(s) with the same change",
            change.more
        ));
    }
    lines
}

/// Where the change is: the line in each file (as the pair's header names
/// them), and the element's path in a GSDML file.
fn places(change: &Change) -> Option<String> {
    let line = |side: &str, place: &Option<Place>| {
        place.as_ref().map(|p| format!("{side} line {}", p.line))
    };
    let lines: Vec<String> = [line("old", &change.old), line("new", &change.new)]
        .into_iter()
        .flatten()
        .collect();
    if lines.is_empty() {
        return None;
    }
    let path = |place: &Option<Place>| {
        place
            .as_ref()
            .and_then(|p| p.path.as_deref().map(str::to_string))
    };
    let paths = match (path(&change.old), path(&change.new)) {
        (Some(a), Some(b)) if a != b => format!(": {a} → {b}"),
        (Some(p), _) | (None, Some(p)) => format!(": {p}"),
        (None, None) => String::new(),
    };
    Some(format!("      at {}{paths}", lines.join(", ")))
}

fn json(pairs: &[Pair]) -> String {
    let place = |place: &Option<Place>, file: &Option<DeviceFile>| match (place, file) {
        (Some(place), Some(file)) => serde_json::json!({
            "file": file.shown,
            "line": place.line,
            "path": place.path.as_deref(),
        }),
        _ => serde_json::Value::Null,
    };
    let mut summary = serde_json::Map::new();
    for class in Class::ALL {
        let n = pairs
            .iter()
            .flat_map(|p| &p.changes)
            .filter(|c| c.class == class)
            .count();
        summary.insert(class.as_str().into(), n.into());
    }
    let pairs: Vec<serde_json::Value> = pairs
        .iter()
        .map(|pair| {
            let changes: Vec<serde_json::Value> = pair
                .changes
                .iter()
                .map(|c| {
                    serde_json::json!({
                        "class": c.class.as_str(),
                        "kind": c.kind.as_str(),
                        "judged": c.judged,
                        "subject": c.subject,
                        "change": c.change,
                        "why": c.why,
                        "old": place(&c.old, &pair.old),
                        "new": place(&c.new, &pair.new),
                        "more": c.more,
                    })
                })
                .collect();
            serde_json::json!({
                "old": pair.old.as_ref().map(|f| &f.shown),
                "new": pair.new.as_ref().map(|f| &f.shown),
                "changes": changes,
            })
        })
        .collect();
    serde_json::json!({ "pairs": pairs, "summary": summary }).to_string()
}
