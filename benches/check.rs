//! `cargo bench --bench check`: gsdc against the tools users have, on the
//! same files in one run, printing each ratio.
//!
//! - GSD corpus: `gsdc::gsd::check` (reader, schema, rules) against
//!   `gsd_parser::parser::parse` (reader only), in process.
//! - GSDML corpus: `gsdc check` (without and with `--xsd`) against
//!   `xmllint --noout --nonet --schema` with the PI schema, all as processes
//!   on all files at once.
//! - `gsdc build descriptions/md810dp.toml` (every output, each verified)
//!   against xmllint validating only the GSDML that build writes.
//!
//! The two sides of each comparison run in turns, and the ratio printed is
//! the median of the ratios of the turns, so that the machine slowing down
//! for a while (a shared VM does) does not favour either side. Needs
//! xmllint (libxml2-utils, installed by scripts/test.sh) and ../shared
//! beside the checkout.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

const SHARED: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../shared");
const GSDC: &str = env!("CARGO_BIN_EXE_gsdc");
const RUNS: usize = 21;

fn main() {
    let gsd_files = corpus("corpus/gsd", |name| !name.ends_with(".tsv"));
    let gsdml_files = corpus("corpus/gsdml", |name| name.ends_with(".xml"));
    let schema = format!("{SHARED}/reference/gsdml-xsd-v2.44/GSDML-DeviceProfile-v2.44.xsd");

    let gsd_texts: Vec<(PathBuf, Vec<u8>)> = gsd_files
        .iter()
        .map(|p| (p.clone(), std::fs::read(p).unwrap()))
        .collect();
    compare(
        &format!("GSD corpus ({} files)", gsd_files.len()),
        ("gsdc check", &mut || {
            for (_, bytes) in &gsd_texts {
                let text = gsdc::gsd::decode(bytes);
                std::hint::black_box(gsdc::gsd::check(&text));
            }
        }),
        ("gsd-parser parse", &mut || {
            for (path, bytes) in &gsd_texts {
                let text = String::from_utf8_lossy(bytes);
                let _ = std::hint::black_box(gsd_parser::parser::parse(path, &text));
            }
        }),
    );

    let xmllint_gsdml = || run(xmllint(&schema).args(&gsdml_files));
    compare(
        &format!("GSDML corpus ({} files)", gsdml_files.len()),
        ("gsdc check", &mut || {
            run(Command::new(GSDC).arg("check").args(&gsdml_files))
        }),
        ("xmllint --schema", &mut { xmllint_gsdml }),
    );
    let schema_dir = Path::new(&schema).parent().unwrap();
    compare(
        &format!(
            "GSDML corpus ({} files), with the schema",
            gsdml_files.len()
        ),
        ("gsdc check --xsd", &mut || {
            run(Command::new(GSDC)
                .arg("check")
                .arg("--xsd")
                .arg(schema_dir)
                .args(&gsdml_files))
        }),
        ("xmllint --schema", &mut { xmllint_gsdml }),
    );

    let out = std::env::temp_dir().join(format!("gsdc-bench-{}", std::process::id()));
    let description = format!("{}/descriptions/md810dp.toml", env!("CARGO_MANIFEST_DIR"));
    let build = || {
        let _ = std::fs::remove_dir_all(&out);
        run(Command::new(GSDC)
            .args(["build", &description, "--out"])
            .arg(&out));
    };
    build();
    let gsdml = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().path())
        .find(|p| p.extension().is_some_and(|e| e == "xml"))
        .expect("the build writes a GSDML file");
    let written = std::fs::read(&gsdml).unwrap();
    compare(
        "build md810dp.toml (all outputs, verified)",
        ("gsdc build", &mut { build }),
        ("xmllint on its GSDML", &mut || {
            // The build above removes and rewrites the same file.
            std::fs::write(&gsdml, &written).unwrap();
            run(xmllint(&schema).arg(&gsdml))
        }),
    );
    let _ = std::fs::remove_dir_all(&out);
}

fn corpus(folder: &str, keep: impl Fn(&str) -> bool) -> Vec<PathBuf> {
    let dir = Path::new(SHARED).join(folder);
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{} is missing: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .filter(|p| keep(&p.file_name().unwrap().to_string_lossy()))
        .collect();
    files.sort();
    files
}

fn xmllint(schema: &str) -> Command {
    let mut command = Command::new("xmllint");
    command.args(["--noout", "--nonet", "--schema", schema]);
    command
}

/// Runs a command to its end; its verdict does not matter here, only that it ran.
fn run(command: &mut Command) {
    let status = command
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .status()
        .unwrap_or_else(|e| panic!("cannot run {command:?}: {e}"));
    std::hint::black_box(status);
}

/// Times `ours` and `theirs` in turns, [`RUNS`] times each after a warm-up
/// run, and prints both medians and the median of the per-turn ratios: a
/// machine that slows down for a while slows both sides of a turn alike.
fn compare(what: &str, ours: (&str, &mut dyn FnMut()), theirs: (&str, &mut dyn FnMut())) {
    let (our_name, ours) = ours;
    let (their_name, theirs) = theirs;
    ours();
    theirs();
    let mut turns: Vec<(Duration, Duration)> =
        (0..RUNS).map(|_| (time(ours), time(theirs))).collect();
    let mut ratios: Vec<f64> = turns
        .iter()
        .map(|(o, t)| t.as_secs_f64() / o.as_secs_f64())
        .collect();
    ratios.sort_by(f64::total_cmp);
    let ratio = ratios[RUNS / 2];
    turns.sort_by_key(|(o, _)| *o);
    let our_median = turns[RUNS / 2].0;
    turns.sort_by_key(|(_, t)| *t);
    let their_median = turns[RUNS / 2].1;
    println!(
        "{what}: {our_name} {:.2} ms, {their_name} {:.2} ms (medians of {RUNS}): gsdc is {ratio:.1}x as fast (median of the ratios, {:.1}x..{:.1}x)",
        our_median.as_secs_f64() * 1e3,
        their_median.as_secs_f64() * 1e3,
        ratios[0],
        ratios[RUNS - 1],
    );
}

fn time(f: &mut dyn FnMut()) -> Duration {
    let start = Instant::now();
    f();
    start.elapsed()
}
