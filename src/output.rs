//! The library's edge with the disk: reading an input file no larger than
//! its reader takes, and writing generated files atomically, only when their
//! content changed. The CLI and the build-script API call it; the core never
//! touches the disk.

use crate::diag::{Diagnostic, InputLimit};
use crate::Artifact;
use std::fmt;
use std::fs;
use std::io::{self, Read, Write};
use std::path::{Path, PathBuf};

/// Why an input file was not read.
#[derive(Debug)]
pub enum ReadError {
    /// More than the reader's limit; the diagnostic says which.
    TooLarge(Diagnostic),
    Io(io::Error),
}

/// The bytes of `path`, unless it holds more than `limit` allows. The size
/// the file system gives is checked before reading, so a large file is
/// refused without being read; the read itself stops one byte past the
/// limit, for files whose size is not known beforehand (`/dev/zero`, pipes).
pub fn read_input(path: &Path, limit: &InputLimit) -> Result<Vec<u8>, ReadError> {
    let file = fs::File::open(path).map_err(ReadError::Io)?;
    let known = file.metadata().map_err(ReadError::Io)?.len();
    if known > limit.max_bytes as u64 {
        return Err(ReadError::TooLarge(limit.diagnostic()));
    }
    let mut bytes = Vec::with_capacity(known as usize);
    file.take(limit.max_bytes as u64 + 1)
        .read_to_end(&mut bytes)
        .map_err(ReadError::Io)?;
    limit.check(bytes.len()).map_err(ReadError::TooLarge)?;
    Ok(bytes)
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    Written,
    Unchanged,
}

/// Why the files were not all written: the path and the OS error, and which
/// files were already replaced when it happened.
#[derive(Debug)]
pub struct WriteError {
    /// The file that could not be written, or the directory that could not
    /// be created.
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

impl std::error::Error for WriteError {}

/// Writes every file into `dir` (created if missing) unless it already
/// holds exactly that content; returns what happened to each, in order.
///
/// All or nothing as far as the disk allows: every changed file is first
/// written in full to a temporary file beside its target and synced, and
/// only when all are staged are they renamed over their targets. A full
/// disk, a read-only directory or a directory where a file should go fails
/// while staging, and then no file is changed and no temporary is left.
/// Only a rename can fail after another succeeded; the error then names the
/// files already replaced. A reader never sees a partial file.
pub fn write_if_changed(dir: &Path, files: &[Artifact]) -> Result<Vec<Outcome>, WriteError> {
    write_with(&OsDisk, dir, files)
}

/// Whether `dir/file_name` holds exactly `contents`; a missing file does not.
pub fn is_up_to_date(dir: &Path, file_name: &str, contents: &[u8]) -> io::Result<bool> {
    match fs::read(dir.join(file_name)) {
        Ok(existing) => Ok(existing == contents),
        Err(e) if e.kind() == io::ErrorKind::NotFound => Ok(false),
        Err(e) => Err(e),
    }
}

/// The two steps that can fail halfway on a real disk (full, read-only, a
/// directory in the way). The unit tests put in a disk that fails.
trait Disk {
    fn write_synced(&self, path: &Path, contents: &[u8]) -> io::Result<()>;
    fn rename(&self, from: &Path, to: &Path) -> io::Result<()>;
}

struct OsDisk;

impl Disk for OsDisk {
    fn write_synced(&self, path: &Path, contents: &[u8]) -> io::Result<()> {
        let mut file = fs::File::create(path)?;
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
) -> Result<Vec<Outcome>, WriteError> {
    fs::create_dir_all(dir).map_err(|error| WriteError {
        path: dir.to_path_buf(),
        error,
        written: Vec::new(),
        verb: "create",
    })?;
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
    Ok(outcomes)
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
    match fs::read(&target) {
        Ok(existing) if existing == file.contents => return Ok(None),
        Ok(_) => {}
        Err(e) if e.kind() == io::ErrorKind::NotFound => {}
        Err(e) => return Err(failed(e)),
    }
    let temp = temp_path(dir, &file.file_name);
    if let Err(e) = disk.write_synced(&temp, &file.contents) {
        let _ = fs::remove_file(&temp);
        return Err(failed(e));
    }
    Ok(Some(Staged { temp, target }))
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

fn temp_path(dir: &Path, file_name: &str) -> PathBuf {
    dir.join(format!(".{file_name}.gsdc-{}.tmp", std::process::id()))
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
        fn write_synced(&self, path: &Path, contents: &[u8]) -> io::Result<()> {
            let n = self.writes.replace(self.writes.get() + 1);
            if n != self.fail_write {
                return OsDisk.write_synced(path, contents);
            }
            fs::write(path, &contents[..contents.len() / 2])?;
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
        fn write_synced(&self, path: &Path, contents: &[u8]) -> io::Result<()> {
            OsDisk.write_synced(path, contents)
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
        let write = |contents: &[u8]| write_if_changed(&dir, &[artifact("A.GSD", contents)]);
        assert_eq!(write(b"one").unwrap(), [Outcome::Written]);
        assert_eq!(write(b"one").unwrap(), [Outcome::Unchanged]);
        assert_eq!(write(b"two").unwrap(), [Outcome::Written]);
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
        let e = write_with(&disk, &dir, &files).unwrap_err();
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
        let e = write_with(&disk, &dir, &files).unwrap_err();
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
        let e = write_if_changed(&dir, &files).unwrap_err();
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
}
