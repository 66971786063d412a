//! Hostile input, round three (issue 26), through the command line: what a
//! description names is read only when it is a regular file; a list of fixed
//! length takes no item more; `build --check` beside a build sees no live
//! temporary as stale; and nothing from an input reaches the terminal raw.
//!
//! Every time bound here catches hangs, not slowness: each run takes well
//! under a second, and [`HANG`] is set for a debug build on a busy 2-core
//! machine.

use crate::support::{self, scratch, CHECKOUT as MANIFEST};
use std::path::Path;
use std::process::Stdio;
use std::time::Duration;

const HANG: Duration = Duration::from_secs(20);

struct Run {
    code: Option<i32>,
    stdout: String,
    stderr: String,
}

/// Runs gsdc in `dir`; killed, and the test failed, after [`HANG`].
fn gsdc(dir: &Path, args: &[&str]) -> Run {
    let (out, err) = (dir.join("gsdc.out"), dir.join("gsdc.err"));
    let mut child = support::gsdc_command(args)
        .current_dir(dir)
        .stdout(std::fs::File::create(&out).unwrap())
        .stderr(std::fs::File::create(&err).unwrap())
        .stdin(Stdio::null())
        .spawn()
        .unwrap();
    let status = support::wait_within(&mut child, HANG, &format!("gsdc {args:?}"));
    let read = |path| String::from_utf8_lossy(&std::fs::read(path).unwrap()).into_owned();
    Run {
        code: status.code(),
        stdout: read(&out),
        stderr: read(&err),
    }
}

/// The fixture without warnings, with `line` added to its `[device]`.
fn description_with(line: &str) -> String {
    let path = Path::new(MANIFEST).join("tests/fixtures/valid/no_warnings.toml");
    let text = std::fs::read_to_string(path).unwrap();
    text.replacen("[device]\n", &format!("[device]\n{line}\n"), 1)
}

fn mkfifo(path: &Path) {
    let made = std::process::Command::new("mkfifo")
        .arg(path)
        .status()
        .expect("mkfifo runs");
    assert!(made.success(), "mkfifo {}", path.display());
}

/// Each command that reads a description, on `card.toml` in `dir`.
const READERS: [&[&str]; 3] = [
    &["build", "card.toml", "--out", "out"],
    &["doc", "card.toml", "--out", "out"],
    &[
        "decode",
        "card.toml",
        "--module",
        "PPO1",
        "--direction",
        "out",
        "10F0 0000 0000 0000 0000 0000",
    ],
];

/// A symbol that is a FIFO (or a link to one), a device, a directory or a
/// link that loops is E141 for every command, at once and unread: opening
/// a FIFO to read waits for a writer that never comes.
#[test]
fn a_symbol_that_is_not_a_regular_file_is_e141_unread() {
    let dir = scratch("symbol-not-regular");
    mkfifo(&dir.join("s.png"));
    std::fs::create_dir(dir.join("folder.png")).unwrap();
    std::os::unix::fs::symlink("s.png", dir.join("link.png")).unwrap();
    std::os::unix::fs::symlink("/dev/zero", dir.join("zero.png")).unwrap();
    std::os::unix::fs::symlink("loop.png", dir.join("loop.png")).unwrap();
    for (symbol, why) in [
        ("s.png", "not a regular file"),
        ("link.png", "not a regular file"),
        ("zero.png", "not a regular file"),
        ("folder.png", "Is a directory"),
        ("loop.png", "symbolic links"),
    ] {
        let text = description_with(&format!("symbol = \"{symbol}\""));
        std::fs::write(dir.join("card.toml"), text).unwrap();
        for args in READERS {
            let run = gsdc(&dir, args);
            assert_eq!(run.code, Some(1), "{symbol} {args:?}: {}", run.stderr);
            assert!(
                run.stderr
                    .contains("error[E141]: the device symbol cannot be read: ")
                    && run.stderr.contains(why),
                "{symbol} {args:?}: {}",
                run.stderr
            );
            assert!(!dir.join("out").exists(), "{symbol} {args:?}");
        }
    }
}

/// `gsdc build --check` beside a build into the same directory took that
/// build's temporaries for a killed build's and named them stale (exit 1).
/// A build at work holds the directory's lock exclusively while its
/// temporaries exist: here the test holds it, with a temporary made as a
/// build makes one. `--check` waits until the lock is released, and then
/// the temporary is gone and the directory in step.
#[test]
fn check_waits_for_a_build_at_work_and_names_none_of_its_temporaries() {
    let dir = scratch("check-beside-build");
    let text = description_with("");
    std::fs::write(dir.join("card.toml"), text).unwrap();
    let build = gsdc(&dir, &["build", "card.toml", "--out", "out"]);
    assert_eq!(build.code, Some(0), "{}", build.stderr);

    let out = dir.join("out");
    let lock = std::fs::File::open(&out).unwrap();
    lock.lock().unwrap();
    let temporary = out.join(".X1DP.GSD.gsdc-1-0123456789abcdef.tmp");
    std::fs::write(&temporary, "half a GSD").unwrap();
    let check = std::thread::scope(|scope| {
        let check = scope.spawn(|| gsdc(&dir, &["build", "card.toml", "--out", "out", "--check"]));
        std::thread::sleep(Duration::from_millis(1500));
        assert!(
            !check.is_finished(),
            "--check did not wait for the build at work"
        );
        std::fs::remove_file(&temporary).unwrap();
        lock.unlock().unwrap();
        check.join().unwrap()
    });
    assert_eq!(check.code, Some(0), "{}{}", check.stdout, check.stderr);
    assert_eq!(check.stdout, "");
}

/// A temporary that no build at work holds is a killed build's: stale.
#[test]
fn check_names_a_killed_builds_temporary_stale() {
    let dir = scratch("check-leftover");
    std::fs::write(dir.join("card.toml"), description_with("")).unwrap();
    let build = gsdc(&dir, &["build", "card.toml", "--out", "out"]);
    assert_eq!(build.code, Some(0), "{}", build.stderr);
    let temporary = ".X1DP.GSD.gsdc-1-0123456789abcdef.tmp";
    std::fs::write(dir.join("out").join(temporary), "half a GSD").unwrap();
    let check = gsdc(&dir, &["build", "card.toml", "--out", "out", "--check"]);
    assert_eq!(check.code, Some(1), "{}", check.stderr);
    assert_eq!(
        check.stdout,
        format!("stale: out/{temporary} (gsdc generated it, and no description given gives it)\n")
    );
}

/// Whether a terminal would take any of `output` as a command or reorder
/// it: a control character other than the line end, or a mark that
/// reorders text.
fn raw_controls(output: &str) -> Vec<char> {
    output
        .chars()
        .filter(|&c| {
            (c.is_control() && c != '\n')
                || matches!(c, '\u{061C}' | '\u{200E}' | '\u{200F}' | '\u{202A}'..='\u{202E}' | '\u{2066}'..='\u{2069}')
        })
        .collect()
}

#[track_caller]
fn assert_escaped(run: &Run, escaped: &str) {
    let all = format!("{}{}", run.stdout, run.stderr);
    assert_eq!(raw_controls(&all), [], "{all:?}");
    assert!(all.contains(escaped), "no {escaped} in {all}");
}

/// A keyword with an escape sequence and a right-to-left override: W205's
/// headline printed both raw (the quoted line showed `?` for the first,
/// the second raw).
#[test]
fn check_shows_a_keywords_control_characters_escaped() {
    let dir = scratch("check-escapes");
    let gsd = "#Profibus_DP\r\nGSD_Revision = 5\r\nX\u{1b}[31mY\u{202E}Z = 1\r\n";
    std::fs::write(dir.join("A.GSD"), gsd).unwrap();
    let run = gsdc(&dir, &["check", "A.GSD"]);
    assert_eq!(run.code, Some(1), "{}", run.stderr);
    assert_escaped(
        &run,
        "warning[W205]: unknown keyword `X\\u001b[31mY\\u202eZ`",
    );
    assert_escaped(&run, "3 | X\\u001b[31mY\\u202eZ = 1");
}

/// `gsdc decode` quotes its arguments in E410, E413 and E416, which put
/// them on the terminal raw; E411 quoted a hex argument whole (131 KB of
/// stderr for 131,071 digits).
#[test]
fn decode_shows_its_arguments_escaped_and_shortened() {
    let dir = scratch("decode-escapes");
    std::fs::write(dir.join("card.toml"), description_with("")).unwrap();
    let decode = |extra: &[&str]| {
        let mut args = vec!["decode", "card.toml"];
        args.extend_from_slice(extra);
        let run = gsdc(&dir, &args);
        assert_eq!(run.code, Some(1), "{args:?}: {}", run.stderr);
        run
    };
    let telegram = "10F0 0000 0000 0000 0000 0000";
    let module = decode(&[
        "--module",
        "PPO\u{1b}[31m1\u{202E}",
        "--direction",
        "out",
        telegram,
    ]);
    assert_escaped(
        &module,
        "error[E413]: the description has no module `PPO\\u001b[31m1\\u202e`",
    );
    let digit = decode(&["--prm", "00 \u{202E}1"]);
    assert_escaped(&digit, "error[E410]: `\\u202e` is not a hex digit");
    let value = decode(&[
        "--module",
        "PPO1",
        "--direction",
        "out",
        "--mapping",
        "pzd_out=\u{1b}[2J",
        telegram,
    ]);
    assert_escaped(&value, "error[E416]: `\\u001b[2J` is not a mapping value");

    // One argument holds at most 128 KiB (Linux's MAX_ARG_STRLEN).
    let digits = "A".repeat(131_071);
    let odd = decode(&["--prm", &digits]);
    assert_eq!(raw_controls(&odd.stderr), []);
    assert!(
        odd.stderr.contains("error[E411]: `AAAA"),
        "{:.400}",
        odd.stderr
    );
    assert!(
        odd.stderr
            .contains("AAAA` has 131071 hex digits: a byte is two"),
        "{:.400}",
        odd.stderr
    );
    assert!(
        odd.stderr.len() < 3_000,
        "{} bytes of stderr",
        odd.stderr.len()
    );
}

/// Waits until the file at `path` is closed after being read, for at most
/// [`HANG`]: an inotify watch (`IN_CLOSE_NOWRITE`), made before `start`
/// runs.
fn after_first_read<T>(path: &Path, start: impl FnOnce() -> T) -> T {
    use std::os::unix::ffi::OsStrExt;
    let name = std::ffi::CString::new(path.as_os_str().as_bytes()).unwrap();
    // SAFETY: plain system calls on a descriptor this function owns and
    // closes, with a buffer that outlives them.
    unsafe {
        let fd = libc::inotify_init1(libc::IN_CLOEXEC);
        assert!(fd >= 0, "inotify_init1");
        let watch = libc::inotify_add_watch(fd, name.as_ptr(), libc::IN_CLOSE_NOWRITE);
        assert!(watch >= 0, "inotify_add_watch");
        let started = start();
        let mut poll = libc::pollfd {
            fd,
            events: libc::POLLIN,
            revents: 0,
        };
        let ready = libc::poll(&mut poll, 1, HANG.as_millis() as i32);
        assert_eq!(ready, 1, "{} was not read within {HANG:?}", path.display());
        let mut event = [0u8; 4096];
        assert!(libc::read(fd, event.as_mut_ptr().cast(), event.len()) > 0);
        libc::close(fd);
        started
    }
}

/// `check --xsd` checked a GSDML file's text with gsdc's rules, then had
/// libxml2 read the file from disk again: a file replaced between the two
/// reads was validated unchecked, and its findings placed against the other
/// text. Here a file the schema accepts is replaced, as soon as gsdc has
/// read it, by one the schema rejects: what gsdc reports is the first
/// file's verdict, every time.
#[test]
fn check_validates_the_text_it_read_not_the_file_again() {
    let dir = scratch("xsd-swap");
    let description = Path::new(MANIFEST).join("descriptions/md810dp.toml");
    let build = gsdc(
        &dir,
        &[
            "build",
            description.to_str().unwrap(),
            "--out",
            "out",
            "--firmware",
            "none",
        ],
    );
    assert_eq!(build.code, Some(0), "{}", build.stderr);
    let gsdml = std::fs::read_dir(dir.join("out"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .find(|p| p.extension().is_some_and(|e| e == "xml"))
        .unwrap();
    // Megabytes of comment keep gsdc's rules busy for a while after the
    // read, so that the file is replaced before it could be read again.
    let padding = format!("<!-- {} -->\n", "padding ".repeat(1 << 19));
    let accepted = std::fs::read_to_string(&gsdml).unwrap() + &padding;
    let rejected = accepted.replacen("<ProfileBody>", "<ProfileBody><NoSuchElement/>", 1);
    assert_ne!(accepted, rejected);
    let schema = std::env::var("GSDC_GSDML_XSD_DIR")
        .unwrap_or_else(|_| format!("{MANIFEST}/../shared/reference/gsdml-xsd-v2.44"));
    let replacement = dir.join("replacement.xml");
    for attempt in 0..5 {
        std::fs::write(&gsdml, &accepted).unwrap();
        std::fs::write(&replacement, &rejected).unwrap();
        let check = std::thread::scope(|scope| {
            let check = after_first_read(&gsdml, || {
                scope.spawn(|| gsdc(&dir, &["check", "--xsd", &schema, gsdml.to_str().unwrap()]))
            });
            std::fs::rename(&replacement, &gsdml).unwrap();
            check.join().unwrap()
        });
        assert!(
            !check.stdout.contains("E399"),
            "attempt {attempt}:\n{}",
            check.stdout
        );
        assert_eq!(
            check.code,
            Some(0),
            "attempt {attempt}: {}{}",
            check.stdout,
            check.stderr
        );
    }
    // The file the schema rejects, checked whole, is rejected.
    let check = gsdc(&dir, &["check", "--xsd", &schema, gsdml.to_str().unwrap()]);
    assert!(check.stdout.contains("error[E399]"), "{}", check.stdout);
}
