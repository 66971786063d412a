//! What the tests share, written once: where things are (the checkout and
//! `../shared/` beside it), scratch directories, running the gsdc binary,
//! insta's snapshot folders, what a test does when it cannot run here, and
//! the submodules: the descriptions and their files ([`descriptions`]), the
//! PI schema ([`xsd`]) and a headless browser ([`chromium`]).

pub mod chromium;
pub mod descriptions;
pub mod xsd;

use std::ffi::OsStr;
use std::io::Write as _;
use std::ops::Deref;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Output};
use std::time::{Duration, Instant};

/// The checkout. gsdc runs here in the tests, so the paths the README
/// writes (`descriptions/md810dp.toml`, `../shared/corpus/...`) resolve.
pub const CHECKOUT: &str = env!("CARGO_MANIFEST_DIR");

/// `path` in the checkout.
pub fn checkout(path: &str) -> PathBuf {
    Path::new(CHECKOUT).join(path)
}

/// `path` in `../shared/` beside the checkout: the PI schema, the corpus of
/// vendor files, the manuals. The tests read them there and never copy
/// them into the project; a missing file fails the test that needs it.
pub fn shared(path: &str) -> PathBuf {
    Path::new(CHECKOUT).join("../shared").join(path)
}

/// The bytes of `../shared/corpus/<path>`.
pub fn corpus_file(path: &str) -> Vec<u8> {
    let file = shared("corpus").join(path);
    std::fs::read(&file)
        .unwrap_or_else(|e| panic!("corpus file {} is missing ({e})", file.display()))
}

// ---------------------------------------------------------------------------
// Scratch directories

/// A fresh, empty directory for a test, in cargo's `target/tmp`: removed
/// when the test passes, kept for a look when it fails.
pub struct Scratch(PathBuf);

/// A scratch directory named after the calling file and `name`, which must
/// be unique within that file (and the process id: two runs never share
/// one). Anything left there by an earlier run is removed first. Keep it in
/// a variable for as long as the test uses it: a temporary
/// (`scratch("x").join("out")`) is removed at the end of its statement.
#[track_caller]
pub fn scratch(name: &str) -> Scratch {
    let caller = std::panic::Location::caller().file();
    let file = Path::new(caller).file_stem().unwrap().to_string_lossy();
    let path = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("gsdc-{}-{file}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&path);
    std::fs::create_dir_all(&path)
        .unwrap_or_else(|e| panic!("cannot create {}: {e}", path.display()));
    Scratch(path)
}

impl Deref for Scratch {
    type Target = Path;

    fn deref(&self) -> &Path {
        &self.0
    }
}

impl AsRef<Path> for Scratch {
    fn as_ref(&self) -> &Path {
        &self.0
    }
}

impl AsRef<OsStr> for Scratch {
    fn as_ref(&self) -> &OsStr {
        self.0.as_os_str()
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        if !std::thread::panicking() {
            let _ = std::fs::remove_dir_all(&self.0);
        }
    }
}

// ---------------------------------------------------------------------------
// The gsdc binary

/// The gsdc binary cargo built for this run.
pub const GSDC: &str = env!("CARGO_BIN_EXE_gsdc");

/// gsdc with `args`, to run in the checkout.
pub fn gsdc_command<I, S>(args: I) -> Command
where
    I: IntoIterator<Item = S>,
    S: AsRef<OsStr>,
{
    let mut command = Command::new(GSDC);
    command.args(args).current_dir(CHECKOUT);
    command
}

/// Runs gsdc with `args` in the checkout: its exit status, stdout and
/// stderr.
pub fn gsdc<I, S>(args: I) -> Output
where
    I: IntoIterator<Item = S>,
    S: AsRef<OsStr>,
{
    let mut command = gsdc_command(args);
    command
        .output()
        .unwrap_or_else(|e| panic!("cannot run {command:?}: {e}"))
}

/// Waits for `child` to end, at most `limit`: past it the child is
/// killed and the test fails, naming `what` (a hang, not slowness: set
/// `limit` well above what the case takes on a busy machine).
#[track_caller]
pub fn wait_within(child: &mut Child, limit: Duration, what: &str) -> ExitStatus {
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            return status;
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            panic!("{what} did not finish within {limit:?}: a hang");
        }
        std::thread::sleep(Duration::from_millis(10));
    }
}

/// What a process printed on stdout; gsdc prints UTF-8, so anything else
/// fails the test.
#[track_caller]
pub fn stdout(output: &Output) -> String {
    String::from_utf8(output.stdout.clone()).expect("stdout is UTF-8")
}

/// What a process printed on stderr, as [`stdout`].
#[track_caller]
pub fn stderr(output: &Output) -> String {
    String::from_utf8(output.stderr.clone()).expect("stderr is UTF-8")
}

/// The names of the entries of `dir`, sorted.
#[track_caller]
pub fn file_names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    names
}

/// The `.rs` files under `dir` (in the checkout), at any depth.
pub fn rust_files(dir: &str) -> Vec<PathBuf> {
    let mut files = Vec::new();
    let mut dirs = vec![checkout(dir)];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
            let path = entry.unwrap().path();
            if path.is_dir() {
                dirs.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                files.push(path);
            }
        }
    }
    files.sort();
    files
}

/// Whether `command` runs and exits 0: a probe for what this machine can do.
pub fn succeeds(command: &mut Command) -> bool {
    command.output().is_ok_and(|o| o.status.success())
}

// ---------------------------------------------------------------------------
// Tests that cannot run here

/// Whether this is a CI run (`CI=true`), where no test may skip.
pub fn under_ci() -> bool {
    std::env::var("CI").is_ok_and(|v| v == "true")
}

/// What a test does when this machine cannot give it what it needs (a
/// mount, `chattr`, a compiler): it says why and leaves that case out, and
/// under CI it fails instead. `scripts/test.sh` installs what the tests
/// need and CI runs as root, so a test that still cannot run there is a
/// broken set-up, not a pass.
#[track_caller]
pub fn cannot_run(why: &str) {
    assert!(
        !under_ci(),
        "{why}; with CI=true no test skips (./scripts/test.sh installs what the tests need, run it as root)"
    );
    // Past libtest's capture, which hides what a passing test prints: a
    // skip is said.
    let _ = writeln!(std::io::stderr(), "skipped: {why}");
}

/// For a test that changes what the whole process shares (an environment
/// variable), which the other tests of this one binary would see: the
/// test runs again, alone, in a process of its own. Returns `true` in this
/// process once it passed there, and the caller returns; returns `false`
/// in that process, and the caller goes on with the test.
pub fn ran_in_own_process() -> bool {
    const MARK: &str = "GSDC_TEST_IN_OWN_PROCESS";
    let current = std::thread::current();
    let test = current.name().expect("libtest names each test's thread");
    if std::env::var(MARK).as_deref() == Ok(test) {
        return false;
    }
    let mut command = Command::new(std::env::current_exe().unwrap());
    command
        .args([test, "--exact", "--test-threads=1"])
        .env(MARK, test);
    let output = command
        .output()
        .unwrap_or_else(|e| panic!("cannot run {command:?}: {e}"));
    let said = format!(
        "{}{}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
    assert!(
        output.status.success(),
        "{test}, in its own process:\n{said}"
    );
    assert!(
        said.contains("test result: ok. 1 passed"),
        "{test} did not run in its own process:\n{said}"
    );
    true
}

// ---------------------------------------------------------------------------
// Snapshots

/// Runs `assert` (insta assertions) with snapshots in
/// `tests/snapshots/<folder>/`, each file named `<name>.snap` after the name
/// the assertion gives.
pub fn snapshots_in<R>(folder: &str, assert: impl FnOnce() -> R) -> R {
    let mut settings = insta::Settings::clone_current();
    settings.set_snapshot_path(snapshot_folder(folder));
    settings.set_prepend_module_to_snapshot(false);
    settings.bind(assert)
}

fn snapshot_folder(folder: &str) -> PathBuf {
    checkout("tests/snapshots").join(folder)
}

/// Every snapshot in `tests/snapshots/<folder>/` is one of `names`: a
/// description, fixture or file that is gone leaves no snapshot behind.
#[track_caller]
pub fn assert_no_orphan_snapshots<'a>(folder: &str, names: impl IntoIterator<Item = &'a str>) {
    let expected: std::collections::BTreeSet<String> =
        names.into_iter().map(|n| format!("{n}.snap")).collect();
    let dir = snapshot_folder(folder);
    let orphans: Vec<String> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|name| name.ends_with(".snap") && !expected.contains(name))
        .collect();
    assert!(
        orphans.is_empty(),
        "snapshots in {} that no test takes any more; remove them: {orphans:?}",
        dir.display()
    );
}
