//! The command line: a thin layer over the library. One file per subcommand.

mod build;
mod check;
mod doc;

use clap::{Parser, Subcommand};
use gsdc::{Diagnostics, Source};
use std::path::{Path, PathBuf};

#[derive(Parser)]
#[command(
    name = "gsdc",
    version,
    about = "Fieldbus device descriptions from one TOML file: GSD, GSDML and firmware layout, checked",
    after_help = "Examples:\n  gsdc build descriptions/md810dp.toml --out dist\n  gsdc check vendor/SIEM8045.GSE\n\nExit codes: 0 ok, 1 the input has errors, 2 usage or I/O error."
)]
pub struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Generate the device files of each description, each checked before it is written.
    #[command(
        after_help = "Examples:\n  gsdc build descriptions/md810dp.toml --out dist\n  gsdc build descriptions/*.toml --out dist --check   # in CI: are the shipped files in step?"
    )]
    Build {
        /// Description files (TOML).
        #[arg(required = true, value_name = "DESCRIPTION")]
        descriptions: Vec<PathBuf>,
        /// Directory to write into; created if missing.
        #[arg(long, short, default_value = ".", value_name = "DIR")]
        out: PathBuf,
        /// Write nothing: exit 1 with a diff if a file in DIR differs from what the descriptions give.
        #[arg(long)]
        check: bool,
    },
    /// Check GSD and GSDML files against gsdc's rules.
    #[command(
        after_help = "Examples:\n  gsdc check MD810DP.GSD\n  gsdc check GSDML-V2.32-MEGMEET-MV800-20230830.xml"
    )]
    Check {
        /// GSD (.gsd, .gse, ...) or GSDML (.xml) files.
        #[arg(required = true, value_name = "FILE")]
        files: Vec<PathBuf>,
        /// How findings are printed.
        #[arg(long, value_enum, default_value = "human")]
        format: check::Format,
        /// Also validate GSDML files against the PI schema in DIR
        /// (GSDML-DeviceProfile-v2.44.xsd and its imports; needs the `xsd` feature).
        #[arg(long, value_name = "DIR")]
        xsd: Option<PathBuf>,
    },
    /// Write the datasheet of each description: DIR/<stem>.html (one page, no script) and DIR/<stem>.md.
    #[command(
        after_help = "Example:\n  gsdc doc descriptions/md810dp.toml --out dist   # dist/md810dp.html, dist/md810dp.md"
    )]
    Doc {
        /// Description files (TOML).
        #[arg(required = true, value_name = "DESCRIPTION")]
        descriptions: Vec<PathBuf>,
        /// Directory to write into; created if missing.
        #[arg(long, short, default_value = ".", value_name = "DIR")]
        out: PathBuf,
    },
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

pub fn run(cli: Cli) -> Status {
    match cli.command {
        Command::Build {
            descriptions,
            out,
            check,
        } => build::run(&descriptions, &out, check),
        Command::Check { files, format, xsd } => check::run(&files, format, xsd.as_deref()),
        Command::Doc { descriptions, out } => doc::run(&descriptions, &out),
    }
}

/// Diagnostics printed per file at most: a hostile file can have a hundred
/// thousand findings, and the first hundred say what is wrong.
const MAX_SHOWN: usize = 100;

/// Prints the first [`MAX_SHOWN`] diagnostics to stderr, rendered against their source.
fn report(name: &str, text: &str, diagnostics: &Diagnostics) {
    let source = Source { name, text };
    for d in diagnostics.iter().take(MAX_SHOWN) {
        eprintln!("{}", source.render(d));
    }
    say_how_many_not_shown(name, diagnostics);
}

fn say_how_many_not_shown(name: &str, diagnostics: &Diagnostics) {
    if let Some(note) = not_shown(name, diagnostics) {
        eprintln!("{note}");
    }
}

/// How many findings beyond [`MAX_SHOWN`] were left out, if any.
fn not_shown(name: &str, diagnostics: &Diagnostics) -> Option<String> {
    let hidden = diagnostics.iter().count().saturating_sub(MAX_SHOWN);
    (hidden > 0).then(|| format!("{name}: {hidden} more finding(s) not shown"))
}

/// Prints a line to stdout. A reader that went away (`gsdc check ... | head`)
/// is no reason to panic, nor to stop writing files.
fn say(line: &str) {
    use std::io::Write;
    let _ = writeln!(std::io::stdout(), "{line}");
}

/// A path as diagnostics show it.
fn display_name(path: &Path) -> String {
    path.display().to_string()
}
