//! Writing generated files: atomically, and only when their content changed.
//! The one place in the library that touches the disk; the CLI and the
//! build-script API call it.

use std::fs;
use std::io::{self, Write};
use std::path::{Path, PathBuf};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    Written,
    Unchanged,
}

/// Writes `contents` to `dir/file_name` unless the file already holds exactly
/// that. The bytes go to a temporary file in the same directory, are synced,
/// then renamed over the target, so a reader never sees a partial file and a
/// failed write leaves the old file as it was.
pub fn write_if_changed(dir: &Path, file_name: &str, contents: &[u8]) -> io::Result<Outcome> {
    let target = dir.join(file_name);
    if fs::read(&target).is_ok_and(|existing| existing == contents) {
        return Ok(Outcome::Unchanged);
    }
    let temp = temp_path(dir, file_name);
    let result = write_synced(&temp, contents).and_then(|()| fs::rename(&temp, &target));
    if result.is_err() {
        let _ = fs::remove_file(&temp);
    }
    result.map(|()| Outcome::Written)
}

/// Whether `dir/file_name` holds exactly `contents`; a missing file does not.
pub fn is_up_to_date(dir: &Path, file_name: &str, contents: &[u8]) -> io::Result<bool> {
    match fs::read(dir.join(file_name)) {
        Ok(existing) => Ok(existing == contents),
        Err(e) if e.kind() == io::ErrorKind::NotFound => Ok(false),
        Err(e) => Err(e),
    }
}

fn temp_path(dir: &Path, file_name: &str) -> PathBuf {
    dir.join(format!(".{file_name}.gsdc-{}.tmp", std::process::id()))
}

fn write_synced(path: &Path, contents: &[u8]) -> io::Result<()> {
    let mut file = fs::File::create(path)?;
    file.write_all(contents)?;
    file.sync_all()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("gsdc-output-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn writes_then_leaves_identical_content_alone() {
        let dir = scratch("same");
        assert_eq!(
            write_if_changed(&dir, "A.GSD", b"one").unwrap(),
            Outcome::Written
        );
        assert_eq!(
            write_if_changed(&dir, "A.GSD", b"one").unwrap(),
            Outcome::Unchanged
        );
        assert_eq!(
            write_if_changed(&dir, "A.GSD", b"two").unwrap(),
            Outcome::Written
        );
        assert_eq!(fs::read(dir.join("A.GSD")).unwrap(), b"two");
        let leftovers: Vec<_> = fs::read_dir(&dir).unwrap().collect();
        assert_eq!(leftovers.len(), 1, "no temporary file is left behind");
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn a_failed_write_keeps_the_old_file_and_leaves_no_temporary() {
        let dir = scratch("fail");
        fs::write(dir.join("A.GSD"), b"old").unwrap();
        // A directory where the temporary file should go makes the write fail.
        fs::create_dir(temp_path(&dir, "A.GSD")).unwrap();
        assert!(write_if_changed(&dir, "A.GSD", b"new").is_err());
        assert_eq!(fs::read(dir.join("A.GSD")).unwrap(), b"old");
        fs::remove_dir_all(dir).unwrap();
    }
}
