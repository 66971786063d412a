//! The command line: a thin layer over the library. One file per subcommand.

mod build;
mod check;
mod decode;
mod diff;
mod doc;
mod import;
mod json;

use clap::{Parser, Subcommand};
use std::io::Write;
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};

#[derive(Parser)]
#[command(
    name = "gsdc",
    version,
    about = "Fieldbus device descriptions from one TOML file: GSD, GSDML and firmware layout, checked",
    after_help = "Examples:\n  gsdc build descriptions/md810dp.toml --out dist\n  gsdc check vendor/SIEM8045.GSE\n  gsdc diff released/MD810DP.GSD dist/MD810DP.GSD\n\nExit codes: 0 ok, 1 the input has errors, 2 usage or I/O error."
)]
pub struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Generate the device files of each description, each checked before it is written.
    #[command(after_help = build::EXAMPLES)]
    Build(build::Args),
    /// Check GSD and GSDML files against gsdc's rules.
    #[command(after_help = check::EXAMPLES)]
    Check(check::Args),
    /// Compare two GSD files, two GSDML files or two descriptions by meaning: breaking, compatible, cosmetic.
    #[command(after_help = diff::EXAMPLES)]
    Diff(diff::Args),
    /// Read a captured telegram, parameter telegram or diagnosis block against a description.
    Decode(decode::Args),
    /// Write the datasheet of each description: `DIR/<stem>.html` (one page, no script) and `DIR/<stem>.md`.
    #[command(after_help = doc::EXAMPLES)]
    Doc(doc::Args),
    /// Write a description from a card's GSD or GSDML file (or both); its build must be the same device.
    #[command(after_help = import::EXAMPLES)]
    Import(import::Args),
}

/// What a run ends with, as the exit code says it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Status {
    Ok = 0,
    InputErrors = 1,
    UsageOrIo = 2,
}

impl Status {
    pub fn code(self) -> u8 {
        self as u8
    }
}

/// Parses the arguments and runs the command. Help, the version and usage
/// errors are printed as clap prints them, and exit 0, 0 and 2, unless they
/// cannot be printed (exit 2).
pub fn main() -> Status {
    let status = match Cli::try_parse() {
        Ok(cli) => run(cli),
        Err(e) => {
            if e.print().is_err() {
                OUTPUT_FAILED.store(true, Ordering::Relaxed);
            }
            if e.use_stderr() {
                Status::UsageOrIo
            } else {
                Status::Ok
            }
        }
    };
    note_failure(std::io::stdout().flush());
    if OUTPUT_FAILED.load(Ordering::Relaxed) {
        return Status::UsageOrIo;
    }
    status
}

fn run(cli: Cli) -> Status {
    match cli.command {
        Command::Build(args) => build::run(&args),
        Command::Check(args) => check::run(&args),
        Command::Decode(args) => decode::run(&args),
        Command::Diff(args) => diff::run(&args),
        Command::Doc(args) => doc::run(&args),
        Command::Import(args) => import::run(&args),
    }
}

/// Set when stdout or stderr could not be written: output was lost, and
/// the run exits 2 whatever else it did.
static OUTPUT_FAILED: AtomicBool = AtomicBool::new(false);

/// Diagnostics printed per file at most: a hostile file can have a hundred
/// thousand findings, and the first hundred say what is wrong.
const MAX_SHOWN: usize = 100;

/// Prints text to stdout, with a line end after it.
fn say(text: &str) {
    print_to(&mut std::io::stdout().lock(), text);
}

/// Prints text to stderr, with a line end after it.
fn warn(text: &str) {
    print_to(&mut std::io::stderr().lock(), text);
}

/// A stream that cannot be written (`> /dev/full`) loses output: noted for
/// the exit code, never a panic. A reader that went away (`gsdc check ... |
/// head`) wanted no more: that is no failure, nor a reason to stop writing
/// files.
fn print_to(stream: &mut impl Write, text: &str) {
    // One write with its line end: stderr is not buffered.
    let mut line = String::with_capacity(text.len() + 1);
    line.push_str(text);
    line.push('\n');
    note_failure(stream.write_all(line.as_bytes()));
}

fn note_failure(result: std::io::Result<()>) {
    if let Err(e) = result {
        if e.kind() != std::io::ErrorKind::BrokenPipe {
            OUTPUT_FAILED.store(true, Ordering::Relaxed);
        }
    }
}

/// A path as the human output shows it: control characters (a newline
/// that would start a fake line, an escape sequence) and the marks that
/// reorder text (U+202E) escaped as the JSON output escapes them
/// ([`crate::unicode::escape`]), so that a file name cannot pass for other
/// output.
fn display_name(path: &Path) -> String {
    crate::unicode::escape(&path.to_string_lossy()).into_owned()
}

/// What `gsdc decode DESCRIPTION ARGS` prints, on stdout (`Ok`) or stderr
/// (`Err`), for the description `ir` and `args` as the shell passes them
/// after the description; `None` when the arguments are not the command's.
/// For the fuzz target `decode`, which reads no file; not part of the API.
#[doc(hidden)]
pub fn decode_output(ir: &crate::Ir, args: &[&str]) -> Option<Result<String, String>> {
    let argv = ["gsdc", "decode", "fuzz.toml"]
        .into_iter()
        .chain(args.iter().copied());
    let Command::Decode(args) = Cli::try_parse_from(argv).ok()?.command else {
        return None;
    };
    Some(decode::output(ir, &args).map_err(|decode::Refused(rendered)| rendered))
}

/// The IR of the description at `path`, for a command that reads it
/// without building (doc, decode): its findings are shown only when it has
/// errors, since its warnings are about the device files.
fn load_description(path: &Path) -> Result<crate::Ir, Status> {
    let loaded = crate::build::load_file(path, &display_name(path)).map_err(|e| {
        warn(&format!("error: {}", build::display_error(&e, path)));
        Status::UsageOrIo
    })?;
    loaded.ir.ok_or_else(|| {
        for rendered in loaded.findings.rendered(MAX_SHOWN) {
            warn(&rendered);
        }
        Status::InputErrors
    })
}

/// The path a file gets in `dir`, as shown.
fn shown_in(dir: &Path, file_name: &str) -> String {
    display_name(&dir.join(file_name))
}

#[cfg(test)]
mod tests {
    use super::{decode_output, display_name};
    use std::path::Path;

    /// What the decode fuzz target sees is what `gsdc decode` prints.
    #[test]
    fn decode_output_is_the_commands() {
        let text = include_str!("../../descriptions/md810dp.toml");
        let ir = crate::testing::load("md810dp.toml", text).0.unwrap();
        let telegram = [
            "--module",
            "PPO1",
            "--direction",
            "out",
            "10F0 0000 0000 0000 0000 0000",
        ];
        let table = decode_output(&ir, &telegram).unwrap().unwrap();
        assert!(table.starts_with("PPO1"), "{table}");
        let refused = decode_output(&ir, &["--prm", "0"]).unwrap().unwrap_err();
        assert!(
            refused.starts_with("error[E411]: `0` has 1 hex digits"),
            "{refused}"
        );
        assert_eq!(decode_output(&ir, &["--no-such-flag"]), None);
    }

    #[test]
    fn names_cannot_fake_lines_or_reorder_text() {
        assert_eq!(display_name(Path::new("dist/A.GSD")), "dist/A.GSD");
        assert_eq!(
            display_name(Path::new("a\nb: 0 error(s)\r\t\u{1b}[31m")),
            "a\\nb: 0 error(s)\\r\\t\\u001b[31m"
        );
        assert_eq!(
            display_name(Path::new("x\u{202E}lmx.dsg")),
            "x\\u202elmx.dsg"
        );
        assert_eq!(display_name(Path::new("Müller 中.gsd")), "Müller 中.gsd");
    }
}
