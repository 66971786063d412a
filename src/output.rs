//! The library's edge with the disk: reading an input file no larger than
//! its reader takes, and writing generated files atomically, only when their
//! content changed, into a directory locked while it is written. The CLI
//! and the build-script API call it; the core never touches the disk.

use crate::diag::{Diagnostic, InputLimit};
use crate::file_kind::{self, FileKind, HEAD_BYTES};
use crate::Artifact;
use std::collections::BTreeSet;
use std::fmt;
use std::fs;
use std::io::{self, Read, Write};
use std::path::{Path, PathBuf};

/// Why an input file was not read.
#[derive(Debug)]
#[non_exhaustive]
pub enum ReadError {
    /// More than the reader's limit; the diagnostic says which.
    TooLarge(Diagnostic),
    Io(io::Error),
}

/// The bytes of `path`, unless it holds more than `limit` allows. The size
/// the file system gives is checked before reading, so a large file is
/// refused without being read; the read itself stops one byte past the
/// limit, for files whose size is not known beforehand (`/dev/zero`, pipes).
/// For a file the user names: a pipe or `/dev/stdin` is read as they ask.
pub fn read_input(path: &Path, limit: &InputLimit) -> Result<Vec<u8>, ReadError> {
    let file = fs::File::open(path).map_err(ReadError::Io)?;
    let known = file.metadata().map_err(ReadError::Io)?.len();
    read_rest(file, known, limit, Vec::new())
}

/// [`read_input`] for a file that a file names (a description's device
/// symbol), which only a regular file may be: see [`open_regular`].
pub fn read_regular_input(path: &Path, limit: &InputLimit) -> Result<Vec<u8>, ReadError> {
    let file = open_regular(path).map_err(ReadError::Io)?;
    let known = file.metadata().map_err(ReadError::Io)?.len();
    read_rest(file, known, limit, Vec::new())
}

/// `path` opened for reading if it is a regular file (or a symbolic link to
/// one); anything else is refused unread: a directory (EISDIR), a FIFO, a
/// socket or a device ("not a regular file"), whose read could wait
/// forever or never end. The one way gsdc opens a file that it did not
/// create and that the user did not name on the command line: what a
/// description names, what an output directory holds.
///
/// The file is opened without waiting (opening a FIFO waits for a writer
/// otherwise; `O_NONBLOCK` does not change how a regular file reads,
/// open(2)) and judged by the open handle, so nothing swapped in after a
/// look at the name is read.
pub fn open_regular(path: &Path) -> io::Result<fs::File> {
    let file = open_without_waiting(path)?;
    let kind = file.metadata()?.file_type();
    if kind.is_file() {
        Ok(file)
    } else if kind.is_dir() {
        Err(is_a_directory())
    } else {
        Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            "not a regular file",
        ))
    }
}

#[cfg(unix)]
fn open_without_waiting(path: &Path) -> io::Result<fs::File> {
    use std::os::unix::fs::OpenOptionsExt;
    fs::OpenOptions::new()
        .read(true)
        .custom_flags(libc::O_NONBLOCK | libc::O_NOCTTY)
        .open(path)
}

#[cfg(not(unix))]
fn open_without_waiting(path: &Path) -> io::Result<fs::File> {
    fs::File::open(path)
}

/// The error reading a directory gives, as the system words it.
#[cfg(unix)]
fn is_a_directory() -> io::Error {
    io::Error::from_raw_os_error(libc::EISDIR)
}

#[cfg(not(unix))]
fn is_a_directory() -> io::Error {
    io::ErrorKind::IsADirectory.into()
}

/// The bytes of a file given to `gsdc check`, and what its first
/// [`HEAD_BYTES`] show it to be. A GSD or GSDML file is read up to its
/// reader's limit, refused by its size before it is read when larger; of a
/// file that is neither, only the first bytes are read.
#[cfg_attr(not(feature = "cli"), allow(dead_code))] // the command line uses it
pub fn read_device_file(path: &Path) -> Result<(FileKind, Vec<u8>), ReadError> {
    let mut file = fs::File::open(path).map_err(ReadError::Io)?;
    let known = file.metadata().map_err(ReadError::Io)?.len();
    let mut bytes = Vec::with_capacity(known.min(HEAD_BYTES as u64) as usize);
    (&mut file)
        .take(HEAD_BYTES as u64)
        .read_to_end(&mut bytes)
        .map_err(ReadError::Io)?;
    let kind = file_kind::detect(&bytes);
    let limit = match kind {
        FileKind::Gsd => &crate::gsd::INPUT_LIMIT,
        FileKind::Gsdml => &crate::gsdml::INPUT_LIMIT,
        FileKind::Bitmap => &crate::symbol::check::INPUT_LIMIT,
        FileKind::Neither => return Ok((kind, bytes)),
    };
    read_rest(file, known, limit, bytes).map(|bytes| (kind, bytes))
}

/// Reads the rest of `file`, of `known` bytes by the file system's word,
/// after the `bytes` already read, unless it is more than `limit` allows.
fn read_rest(
    file: fs::File,
    known: u64,
    limit: &InputLimit,
    mut bytes: Vec<u8>,
) -> Result<Vec<u8>, ReadError> {
    if known > limit.max_bytes as u64 {
        return Err(ReadError::TooLarge(limit.diagnostic()));
    }
    bytes.reserve((known as usize).saturating_sub(bytes.len()));
    let room = (limit.max_bytes + 1).saturating_sub(bytes.len());
    file.take(room as u64)
        .read_to_end(&mut bytes)
        .map_err(ReadError::Io)?;
    limit.check(bytes.len()).map_err(ReadError::TooLarge)?;
    Ok(bytes)
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Outcome {
    Written,
    Unchanged,
}

/// What [`write_files`] did.
#[derive(Debug)]
#[non_exhaustive]
pub struct Written {
    /// What happened to each file, in the order given.
    pub outcomes: Vec<Outcome>,
    /// Temporaries of an interrupted gsdc build found in the directory, and
    /// removed.
    pub leftovers: Vec<PathBuf>,
    /// Stale files removed (files gsdc generated that no given artifact is), when asked to prune.
    pub pruned: Vec<PathBuf>,
    /// Why the directory could not be locked, if it could not (a file
    /// system without locks): the files were written all the same, and
    /// leftovers were left alone, as they could be another build's.
    pub not_locked: Option<io::Error>,
}

/// Why the files were not all written: the path and the OS error, and which
/// files were already replaced when it happened.
#[derive(Debug)]
#[non_exhaustive]
pub struct WriteError {
    /// The file that could not be written, or the directory that could not
    /// be created or opened.
    pub path: PathBuf,
    pub error: io::Error,
    /// Files replaced before the error; every other file is as it was.
    pub written: Vec<PathBuf>,
    verb: &'static str,
}

impl fmt::Display for WriteError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "cannot {} {}: {}",
            self.verb,
            self.path.display(),
            self.error
        )?;
        if self.written.is_empty() {
            return f.write_str("; no file was changed");
        }
        let written: Vec<String> = self
            .written
            .iter()
            .map(|p| p.display().to_string())
            .collect();
        write!(
            f,
            "; already written: {}; the other files are as they were",
            written.join(", ")
        )
    }
}

impl std::error::Error for WriteError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        Some(&self.error)
    }
}

/// Writes every file into `dir` (created if missing) unless it already
/// holds exactly that content; with `prune`, removes the stale files
/// after.
///
/// While it works it holds an exclusive lock on `dir` (`flock` on the
/// directory itself, so no lock file is left), so that two builds into one
/// directory replace their sets of files one after the other, never mixed.
/// Holding it, it removes the temporaries that a build killed halfway left.
///
/// All or nothing as far as the disk allows: every changed file is first
/// written in full to a temporary file beside its target and synced, and
/// only when all are staged are they renamed over their targets. A full
/// disk, a read-only directory or a directory where a file should go fails
/// while staging, and then no file is changed and no temporary is left.
/// Only a rename can fail after another succeeded; the error then names the
/// files already replaced. A reader never sees a partial file.
///
/// A temporary has a name of its own (process id and 64 random bits) and is
/// created exclusively (`O_CREAT|O_EXCL`, which by POSIX fails on any
/// existing name, a symbolic link included): nothing placed at its name is
/// ever written through, and two builds never share one, even with the
/// same process id in two PID namespaces. A replaced file keeps its
/// permission bits.
pub fn write_files(dir: &Path, files: &[Artifact], prune: bool) -> Result<Written, WriteError> {
    write_with(&OsDisk, dir, files, prune)
}

/// What `dir/file_name` holds: `None` when it does not exist; an error for
/// anything but a regular file, which is refused unread.
#[cfg_attr(not(feature = "cli"), allow(dead_code))] // the command line uses it
pub fn existing(dir: &Path, file_name: &str) -> io::Result<Option<Vec<u8>>> {
    read_target(&dir.join(file_name))
}

/// A shared lock on a directory, held until it is dropped (closing the
/// handle unlocks): a build into the directory, which locks it
/// exclusively, waits until then, and taking it waits for a build at work
/// to finish. For `--check`, which so reads one build's whole set, and
/// finds no temporary but a killed build's.
#[cfg_attr(not(feature = "cli"), allow(dead_code))] // the command line uses it
pub struct SharedLock {
    _handle: Option<fs::File>,
    /// Why the directory could not be locked (a file system without
    /// locks): a temporary in it could then be a build's at work.
    pub not_locked: Option<io::Error>,
}

/// Locks `dir` shared ([`SharedLock`]); a directory that does not exist
/// needs no lock.
#[cfg_attr(not(feature = "cli"), allow(dead_code))] // the command line uses it
pub fn lock_shared(dir: &Path) -> io::Result<SharedLock> {
    let handle = match fs::File::open(dir) {
        Ok(handle) => handle,
        Err(e) if e.kind() == io::ErrorKind::NotFound => {
            return Ok(SharedLock {
                _handle: None,
                not_locked: None,
            })
        }
        Err(e) => return Err(e),
    };
    let not_locked = handle.lock_shared().err();
    Ok(SharedLock {
        _handle: Some(handle),
        not_locked,
    })
}

/// The mark every file gsdc generates carries in its header.
pub const GENERATED_MARK: &str = "@generated by gsdc ";

/// How much of a file's start is searched for [`GENERATED_MARK`].
const HEADER_BYTES: u64 = 1024;

/// Files in `dir` that gsdc made and none of `files` is: regular files
/// (never symbolic links) with [`GENERATED_MARK`] in their first KiB,
/// temporaries of interrupted builds, and the device symbols (bitmaps, which
/// have no room for a mark) that a GSD or GSDML of gsdc's in `dir` names.
/// They are the outputs of descriptions that changed a file name, a date or
/// a symbol, or were not given. Sorted by name; none when `dir` does not
/// exist. Called before a build replaces its files, it sees the bitmaps the
/// files it replaces named.
///
/// Temporaries only when the caller holds a lock on `dir` (`locked`): a
/// build at work holds it and its temporaries, so only then is every
/// temporary one a build left behind.
#[cfg_attr(not(feature = "cli"), allow(dead_code))] // the command line uses it
pub fn stale_files(dir: &Path, files: &[Artifact], locked: bool) -> io::Result<Vec<PathBuf>> {
    let entries = match fs::read_dir(dir) {
        Ok(entries) => entries,
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(Vec::new()),
        Err(e) => return Err(e),
    };
    let mut stale = Vec::new();
    let mut bitmaps = Vec::new();
    let mut named = BTreeSet::new();
    for entry in entries {
        let entry = entry?;
        if !entry.file_type()?.is_file() {
            continue;
        }
        let name = entry.file_name().to_string_lossy().into_owned();
        let produced = files.iter().any(|f| name == f.file_name);
        let path = entry.path();
        if is_temporary(&name) {
            if locked {
                stale.push(path);
            }
        } else if is_generated(&path)? {
            if may_name_bitmaps(&name) {
                named.extend(bitmaps_named_in(&read_regular(&path)?));
            }
            // A datasheet is `gsdc doc`'s, which a build never writes.
            if !produced && !is_datasheet(&name) {
                stale.push(path);
            }
        } else if !produced && name.ends_with(".bmp") {
            bitmaps.push(path);
        }
    }
    stale.extend(bitmaps.into_iter().filter(|path| {
        path.file_stem()
            .is_some_and(|stem| named.contains(stem.to_string_lossy().as_ref()))
    }));
    stale.sort();
    Ok(stale)
}

/// The bitmaps a GSD (`Bitmap_Device = "X"`) or GSDML (`GraphicFile="X"`)
/// names, without `.bmp`.
fn bitmaps_named_in(contents: &[u8]) -> Vec<String> {
    let text = String::from_utf8_lossy(contents);
    let text: &str = &text;
    ["Bitmap_Device", "GraphicFile="]
        .iter()
        .flat_map(|key| {
            text.match_indices(key)
                .map(move |(at, _)| &text[at + key.len()..])
        })
        .filter_map(|rest| {
            let rest = rest.trim_start_matches([' ', '=']);
            let value = rest.strip_prefix('"')?;
            Some(value[..value.find('"')?].to_string())
        })
        .collect()
}

/// A GSD or a GSDML, the files that name device symbols.
fn may_name_bitmaps(name: &str) -> bool {
    has_extension(name, "gsd") || has_extension(name, "xml")
}

/// `gsdc doc`'s `<stem>.html` and `<stem>.md`.
fn is_datasheet(name: &str) -> bool {
    has_extension(name, "html") || has_extension(name, "md")
}

fn has_extension(name: &str, extension: &str) -> bool {
    Path::new(name)
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case(extension))
}

fn is_generated(path: &Path) -> io::Result<bool> {
    let mut head = Vec::new();
    open_regular(path)?
        .take(HEADER_BYTES)
        .read_to_end(&mut head)?;
    Ok(carries_mark(&head))
}

/// Whether a file starting with `head` carries [`GENERATED_MARK`] where
/// gsdc's headers put it, in its first KiB.
pub fn carries_mark(head: &[u8]) -> bool {
    let head = &head[..head.len().min(HEADER_BYTES as usize)];
    let mark = GENERATED_MARK.as_bytes();
    head.windows(mark.len()).any(|w| w == mark)
}

/// The name of one of gsdc's temporaries: `.NAME.gsdc-PID-RANDOM.tmp` (and
/// `.NAME.gsdc-PID.tmp` of gsdc before 0.2).
fn is_temporary(name: &str) -> bool {
    name.starts_with('.') && name.ends_with(".tmp") && name.contains(".gsdc-")
}

/// The steps that can fail halfway on a real disk (full, read-only, a
/// directory in the way). The unit tests put in a disk that fails.
trait Disk {
    fn write_synced(&self, file: &mut fs::File, contents: &[u8]) -> io::Result<()>;
    fn rename(&self, from: &Path, to: &Path) -> io::Result<()>;
}

struct OsDisk;

impl Disk for OsDisk {
    fn write_synced(&self, file: &mut fs::File, contents: &[u8]) -> io::Result<()> {
        file.write_all(contents)?;
        file.sync_all()
    }

    fn rename(&self, from: &Path, to: &Path) -> io::Result<()> {
        fs::rename(from, to)
    }
}

/// A changed file written to its temporary, waiting to be renamed.
struct Staged {
    temp: PathBuf,
    target: PathBuf,
}

fn write_with(
    disk: &impl Disk,
    dir: &Path,
    files: &[Artifact],
    prune: bool,
) -> Result<Written, WriteError> {
    let cannot = |verb, error| WriteError {
        path: dir.to_path_buf(),
        error,
        written: Vec::new(),
        verb,
    };
    fs::create_dir_all(dir).map_err(|e| cannot("create", e))?;
    // Held until the end of this function: closing the handle unlocks.
    let handle = fs::File::open(dir).map_err(|e| cannot("open", e))?;
    let not_locked = handle.lock().err();
    let leftovers = match not_locked {
        None => remove_leftovers(dir),
        Some(_) => Vec::new(),
    };
    // What is stale is seen before the files are replaced (a replaced
    // device file still names the bitmaps it used) and before this build's
    // own temporaries are made.
    let stale = match prune {
        true => stale_files(dir, files, not_locked.is_none()).map_err(|e| cannot("read", e))?,
        false => Vec::new(),
    };
    let mut staged = Vec::new();
    let mut outcomes = Vec::new();
    for file in files {
        match stage(disk, dir, file) {
            Ok(Some(s)) => {
                staged.push(s);
                outcomes.push(Outcome::Written);
            }
            Ok(None) => outcomes.push(Outcome::Unchanged),
            Err(e) => {
                remove_temporaries(&staged);
                return Err(e);
            }
        }
    }
    commit(disk, &staged)?;
    let pruned = remove_stale(&stale, &staged)?;
    // The renames are durable once the directory is synced; a file system
    // that cannot sync a directory has nothing to make durable this way.
    let _ = handle.sync_all();
    Ok(Written {
        outcomes,
        leftovers,
        pruned,
        not_locked,
    })
}

/// Removes the temporaries in `dir`, which only a build that did not finish
/// can have left while the caller holds the lock; returns those removed.
fn remove_leftovers(dir: &Path) -> Vec<PathBuf> {
    let Ok(entries) = fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut removed: Vec<PathBuf> = entries
        .filter_map(Result::ok)
        .filter(|e| is_temporary(&e.file_name().to_string_lossy()))
        .map(|e| e.path())
        .filter(|path| fs::remove_file(path).is_ok())
        .collect();
    removed.sort();
    removed
}

/// Removes the stale files after the new ones are in place; an error names
/// the file and the files written before it.
fn remove_stale(stale: &[PathBuf], staged: &[Staged]) -> Result<Vec<PathBuf>, WriteError> {
    for path in stale {
        fs::remove_file(path).map_err(|error| WriteError {
            path: path.clone(),
            error,
            written: staged.iter().map(|s| s.target.clone()).collect(),
            verb: "remove",
        })?;
    }
    Ok(stale.to_vec())
}

/// What `target` holds: `None` when it does not exist. Anything but a
/// regular file (or a link to one) is an error ([`open_regular`]).
fn read_target(target: &Path) -> io::Result<Option<Vec<u8>>> {
    match read_regular(target) {
        Err(e) if e.kind() == io::ErrorKind::NotFound => Ok(None),
        read => read.map(Some),
    }
}

/// The bytes of the regular file at `path` ([`open_regular`]).
fn read_regular(path: &Path) -> io::Result<Vec<u8>> {
    let mut bytes = Vec::new();
    open_regular(path)?.read_to_end(&mut bytes)?;
    Ok(bytes)
}

/// Writes `file` to its temporary, unless its target already holds exactly
/// its content. A target that exists but cannot be read (a directory) is an
/// error here, before any file is replaced.
fn stage(disk: &impl Disk, dir: &Path, file: &Artifact) -> Result<Option<Staged>, WriteError> {
    let target = dir.join(&file.file_name);
    let failed = |error| WriteError {
        path: target.clone(),
        error,
        written: Vec::new(),
        verb: "write",
    };
    match read_target(&target).map_err(failed)? {
        Some(existing) if existing == file.contents => return Ok(None),
        _ => {}
    }
    let (temp, mut handle) = create_temporary(dir, &file.file_name).map_err(failed)?;
    let written = keep_permissions(&target, &handle)
        .and_then(|()| disk.write_synced(&mut handle, &file.contents));
    if let Err(e) = written {
        let _ = fs::remove_file(&temp);
        return Err(failed(e));
    }
    Ok(Some(Staged { temp, target }))
}

/// A new, empty temporary beside `file_name` in `dir`, under a name that
/// nothing had: created exclusively, so that nothing placed there (a file,
/// a symbolic link) is ever written through.
fn create_temporary(dir: &Path, file_name: &str) -> io::Result<(PathBuf, fs::File)> {
    let mut tries = 0;
    loop {
        let path = dir.join(format!(
            ".{file_name}.gsdc-{}-{:016x}.tmp",
            std::process::id(),
            random_u64()
        ));
        match create_exclusive(&path) {
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists && tries < 8 => tries += 1,
            result => return result.map(|file| (path, file)),
        }
    }
}

/// A new file at `path`, or `AlreadyExists` if anything is there: a file, a
/// directory, a symbolic link even to nowhere (`O_CREAT|O_EXCL`).
fn create_exclusive(path: &Path) -> io::Result<fs::File> {
    fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(path)
}

/// 64 bits no other process can predict: std's hasher keys are seeded from
/// the operating system's random source.
fn random_u64() -> u64 {
    use std::hash::{BuildHasher, Hasher};
    std::collections::hash_map::RandomState::new()
        .build_hasher()
        .finish()
}

/// Gives the temporary the permission bits of the regular file it will
/// replace, if there is one; a new file keeps what the umask gives.
fn keep_permissions(target: &Path, temporary: &fs::File) -> io::Result<()> {
    match fs::symlink_metadata(target) {
        Ok(m) if m.is_file() => temporary.set_permissions(m.permissions()),
        _ => Ok(()),
    }
}

/// Renames every staged file over its target. On a failure the remaining
/// temporaries are removed and the error names the files already replaced.
fn commit(disk: &impl Disk, staged: &[Staged]) -> Result<(), WriteError> {
    for (i, s) in staged.iter().enumerate() {
        if let Err(error) = disk.rename(&s.temp, &s.target) {
            remove_temporaries(&staged[i..]);
            return Err(WriteError {
                path: s.target.clone(),
                error,
                written: staged[..i].iter().map(|s| s.target.clone()).collect(),
                verb: "write",
            });
        }
    }
    Ok(())
}

fn remove_temporaries(staged: &[Staged]) {
    for s in staged {
        let _ = fs::remove_file(&s.temp);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cell::Cell;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("gsdc-output-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn artifact(file_name: &str, contents: &[u8]) -> Artifact {
        Artifact {
            kind: crate::emit::ArtifactKind::Gsd,
            file_name: file_name.into(),
            contents: contents.to_vec(),
        }
    }

    fn names_in(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().into_string().unwrap())
            .collect();
        names.sort();
        names
    }

    /// A disk that fails the `n`th write (0-based) as a full disk does:
    /// after half the bytes, with ENOSPC.
    struct FullDisk {
        fail_write: usize,
        writes: Cell<usize>,
    }

    impl Disk for FullDisk {
        fn write_synced(&self, file: &mut fs::File, contents: &[u8]) -> io::Result<()> {
            let n = self.writes.replace(self.writes.get() + 1);
            if n != self.fail_write {
                return OsDisk.write_synced(file, contents);
            }
            file.write_all(&contents[..contents.len() / 2])?;
            Err(io::Error::from_raw_os_error(28)) // ENOSPC
        }

        fn rename(&self, from: &Path, to: &Path) -> io::Result<()> {
            OsDisk.rename(from, to)
        }
    }

    /// A disk whose `n`th rename fails as on a read-only file system.
    struct FailingRename {
        fail_rename: usize,
        renames: Cell<usize>,
    }

    impl Disk for FailingRename {
        fn write_synced(&self, file: &mut fs::File, contents: &[u8]) -> io::Result<()> {
            OsDisk.write_synced(file, contents)
        }

        fn rename(&self, from: &Path, to: &Path) -> io::Result<()> {
            let n = self.renames.replace(self.renames.get() + 1);
            if n == self.fail_rename {
                return Err(io::Error::from_raw_os_error(30)); // EROFS
            }
            OsDisk.rename(from, to)
        }
    }

    #[test]
    fn writes_then_leaves_identical_content_alone() {
        let dir = scratch("same");
        let write = |contents: &[u8]| {
            write_files(&dir, &[artifact("A.GSD", contents)], false)
                .unwrap()
                .outcomes
        };
        assert_eq!(write(b"one"), [Outcome::Written]);
        assert_eq!(write(b"one"), [Outcome::Unchanged]);
        assert_eq!(write(b"two"), [Outcome::Written]);
        assert_eq!(fs::read(dir.join("A.GSD")).unwrap(), b"two");
        assert_eq!(
            names_in(&dir),
            ["A.GSD"],
            "no temporary file is left behind"
        );
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn a_full_disk_changes_no_file_and_leaves_no_temporary() {
        let dir = scratch("full");
        fs::write(dir.join("A.GSD"), b"old a").unwrap();
        fs::write(dir.join("B.xml"), b"old b").unwrap();
        let files = [artifact("A.GSD", b"new a"), artifact("B.xml", b"new b")];
        let disk = FullDisk {
            fail_write: 1,
            writes: Cell::new(0),
        };
        let e = write_with(&disk, &dir, &files, false).unwrap_err();
        assert_eq!(e.path, dir.join("B.xml"));
        assert_eq!(e.error.raw_os_error(), Some(28));
        assert!(e.written.is_empty());
        let message = e.to_string();
        assert!(
            message.contains("B.xml") && message.contains("os error 28"),
            "{message}"
        );
        assert!(message.ends_with("no file was changed"), "{message}");
        // A.GSD was staged before B.xml failed; it is not replaced either.
        assert_eq!(fs::read(dir.join("A.GSD")).unwrap(), b"old a");
        assert_eq!(fs::read(dir.join("B.xml")).unwrap(), b"old b");
        assert_eq!(names_in(&dir), ["A.GSD", "B.xml"]);
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn a_failed_rename_names_the_files_already_written() {
        let dir = scratch("rename");
        for name in ["A.GSD", "B.xml", "c.rs"] {
            fs::write(dir.join(name), b"old").unwrap();
        }
        let files = [
            artifact("A.GSD", b"new"),
            artifact("B.xml", b"new"),
            artifact("c.rs", b"new"),
        ];
        let disk = FailingRename {
            fail_rename: 1,
            renames: Cell::new(0),
        };
        let e = write_with(&disk, &dir, &files, false).unwrap_err();
        assert_eq!(e.path, dir.join("B.xml"));
        assert_eq!(e.written, [dir.join("A.GSD")]);
        let message = e.to_string();
        assert!(
            message.contains("already written: ") && message.contains("A.GSD"),
            "{message}"
        );
        assert_eq!(fs::read(dir.join("A.GSD")).unwrap(), b"new");
        assert_eq!(fs::read(dir.join("B.xml")).unwrap(), b"old");
        assert_eq!(fs::read(dir.join("c.rs")).unwrap(), b"old");
        assert_eq!(names_in(&dir), ["A.GSD", "B.xml", "c.rs"]);
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn a_directory_in_place_of_a_file_changes_nothing() {
        let dir = scratch("isdir");
        fs::create_dir(dir.join("B.xml")).unwrap();
        let files = [artifact("A.GSD", b"new"), artifact("B.xml", b"new")];
        let e = write_files(&dir, &files, false).unwrap_err();
        assert_eq!(e.path, dir.join("B.xml"));
        assert_eq!(e.error.raw_os_error(), Some(21)); // EISDIR
        assert_eq!(names_in(&dir), ["B.xml"], "A.GSD was not written");
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn the_read_stops_past_the_limit_whatever_the_file_system_says() {
        let limit = crate::load::INPUT_LIMIT;
        // A character device reports size 0 and never ends.
        match read_input(Path::new("/dev/zero"), &limit) {
            Err(ReadError::TooLarge(d)) => assert_eq!(d.code, limit.code),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn a_replaced_file_keeps_its_permission_bits() {
        use std::os::unix::fs::PermissionsExt;
        let dir = scratch("mode");
        let target = dir.join("A.GSD");
        fs::write(&target, b"old").unwrap();
        fs::set_permissions(&target, fs::Permissions::from_mode(0o600)).unwrap();
        write_files(&dir, &[artifact("A.GSD", b"new")], false).unwrap();
        assert_eq!(fs::read(&target).unwrap(), b"new");
        let mode = fs::metadata(&target).unwrap().permissions().mode();
        assert_eq!(mode & 0o777, 0o600);
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn temporaries_have_names_of_their_own() {
        let dir = scratch("names");
        let (a, _) = create_temporary(&dir, "A.GSD").unwrap();
        let (b, _) = create_temporary(&dir, "A.GSD").unwrap();
        assert_ne!(a, b);
        for t in [&a, &b] {
            let name = t.file_name().unwrap().to_str().unwrap();
            assert!(is_temporary(name), "{name}");
            assert!(name.starts_with(".A.GSD.gsdc-"), "{name}");
        }
        fs::remove_dir_all(dir).unwrap();
    }

    /// Whoever could guess a temporary's name and put a link there first
    /// would still not have gsdc write through it.
    #[test]
    fn a_temporary_is_never_opened_through_a_link() {
        let dir = scratch("exclusive");
        let victim = dir.join("victim");
        fs::write(&victim, b"not gsdc's").unwrap();
        let link = dir.join("to-victim");
        let dangling = dir.join("to-nowhere");
        std::os::unix::fs::symlink(&victim, &link).unwrap();
        std::os::unix::fs::symlink(dir.join("nothing"), &dangling).unwrap();
        for path in [&link, &dangling, &victim] {
            let e = create_exclusive(path).unwrap_err();
            assert_eq!(e.kind(), io::ErrorKind::AlreadyExists, "{path:?}");
        }
        assert_eq!(fs::read(&victim).unwrap(), b"not gsdc's");
        assert!(!dir.join("nothing").exists());
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn leftover_temporaries_are_removed_and_named() {
        let dir = scratch("leftovers");
        let old_style = dir.join(".A.GSD.gsdc-4242.tmp");
        let new_style = dir.join(".B.xml.gsdc-17-00000000deadbeef.tmp");
        fs::write(&old_style, b"a killed build's").unwrap();
        fs::write(&new_style, b"a killed build's").unwrap();
        fs::write(dir.join(".hidden.tmp"), b"not gsdc's").unwrap();
        let written = write_files(&dir, &[artifact("A.GSD", b"a")], false).unwrap();
        assert!(written.not_locked.is_none());
        assert_eq!(written.leftovers, [old_style, new_style]);
        assert_eq!(names_in(&dir), [".hidden.tmp", "A.GSD"]);
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn stale_files_are_gsdcs_own_and_not_given_and_pruned_on_request() {
        let dir = scratch("stale");
        let header = format!("; {GENERATED_MARK}0.1.0 from old.toml\r\n");
        fs::write(dir.join("OLD.GSD"), &header).unwrap();
        fs::write(dir.join("A.GSD"), &header).unwrap();
        fs::write(dir.join("notes.txt"), b"the user's own").unwrap();
        let late = format!("{}{header}", "x".repeat(HEADER_BYTES as usize));
        fs::write(dir.join("late.txt"), late).unwrap();
        fs::write(dir.join(".A.GSD.gsdc-9-0123456789abcdef.tmp"), b"").unwrap();
        std::os::unix::fs::symlink("OLD.GSD", dir.join("link.GSD")).unwrap();
        let files = [artifact("A.GSD", header.as_bytes())];
        assert_eq!(
            stale_files(&dir, &files, true).unwrap(),
            [
                dir.join(".A.GSD.gsdc-9-0123456789abcdef.tmp"),
                dir.join("OLD.GSD")
            ]
        );
        let written = write_files(&dir, &files, true).unwrap();
        assert_eq!(written.outcomes, [Outcome::Unchanged]);
        assert_eq!(written.pruned, [dir.join("OLD.GSD")]);
        assert_eq!(
            names_in(&dir),
            ["A.GSD", "late.txt", "link.GSD", "notes.txt"]
        );
        assert!(stale_files(&dir.join("none"), &files, true)
            .unwrap()
            .is_empty());
        fs::remove_dir_all(dir).unwrap();
    }

    /// A bitmap has no mark: it is gsdc's when a device file of gsdc's in
    /// the directory names it, the file about to be replaced included.
    #[test]
    fn stale_symbols_are_the_bitmaps_gsdcs_device_files_named() {
        let dir = scratch("stale-symbols");
        let gsd =
            |bitmap: &str| format!("; {GENERATED_MARK}0.1.0\r\nBitmap_Device = \"{bitmap}\"\r\n");
        let gsdml = format!("<!-- {GENERATED_MARK}0.1.0 -->\n<GraphicItem ID=\"S\" GraphicFile=\"GSDML-0A11-0810-MD810\"/>\n");
        fs::write(dir.join("OLD.GSD"), gsd("OLD")).unwrap();
        fs::write(dir.join("A.GSD"), gsd("A_2025")).unwrap();
        fs::write(dir.join("GSDML-V2.32-X-Y-20250101.xml"), &gsdml).unwrap();
        for bitmap in ["OLD", "A_2025", "A", "GSDML-0A11-0810-MD810", "USER"] {
            fs::write(dir.join(format!("{bitmap}.bmp")), b"BM").unwrap();
        }
        // The build now gives A.GSD naming A.bmp, and nothing else.
        let files = [
            artifact("A.GSD", gsd("A").as_bytes()),
            artifact("A.bmp", b"BM"),
        ];
        let stale = stale_files(&dir, &files, true).unwrap();
        let names: Vec<String> = stale
            .iter()
            .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
            .collect();
        assert_eq!(
            names,
            [
                "A_2025.bmp",
                "GSDML-0A11-0810-MD810.bmp",
                "GSDML-V2.32-X-Y-20250101.xml",
                "OLD.GSD",
                "OLD.bmp"
            ]
        );
        let written = write_files(&dir, &files, true).unwrap();
        assert_eq!(written.pruned, stale);
        assert_eq!(names_in(&dir), ["A.GSD", "A.bmp", "USER.bmp"]);
        fs::remove_dir_all(dir).unwrap();
    }

    /// A FIFO where a file should go would block a read forever.
    #[test]
    fn a_fifo_in_place_of_a_file_is_refused_unread() {
        let dir = scratch("fifo");
        let made = std::process::Command::new("mkfifo")
            .arg(dir.join("A.GSD"))
            .status()
            .unwrap();
        assert!(made.success());
        let e = write_files(&dir, &[artifact("A.GSD", b"a")], false).unwrap_err();
        assert_eq!(e.path, dir.join("A.GSD"));
        assert!(e.to_string().contains("not a regular file"), "{e}");
        assert!(existing(&dir, "A.GSD").is_err());
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn a_device_file_is_read_by_the_limit_of_its_kind() {
        let dir = scratch("device-file");
        let gsd = dir.join("big.txt");
        let mut file = fs::File::create(&gsd).unwrap();
        file.write_all(b"#Profibus_DP\r\n").unwrap();
        file.set_len(100 << 20).unwrap(); // a hole after the first line
        match read_device_file(&gsd) {
            Err(ReadError::TooLarge(d)) => assert_eq!(d.code, "E229"),
            other => panic!("{other:?}"),
        }
        // Of a file that is neither, the first bytes only.
        match read_device_file(Path::new("/dev/zero")) {
            Ok((FileKind::Neither, head)) => assert_eq!(head.len(), HEAD_BYTES),
            other => panic!("{other:?}"),
        }
        let xml = dir.join("x");
        fs::write(&xml, b"<a/>").unwrap();
        assert_eq!(
            read_device_file(&xml).unwrap(),
            (FileKind::Gsdml, b"<a/>".to_vec())
        );
        fs::remove_dir_all(dir).unwrap();
    }
}
