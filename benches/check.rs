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
//! Each figure is the median of several runs. Needs xmllint (libxml2-utils,
//! installed by scripts/test.sh) and ../shared beside the checkout.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

const SHARED: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../shared");
const GSDC: &str = env!("CARGO_BIN_EXE_gsdc");
const RUNS: usize = 15;

fn main() {
    let gsd_files = corpus("corpus/gsd", |name| !name.ends_with(".tsv"));
    let gsdml_files = corpus("corpus/gsdml", |name| name.ends_with(".xml"));
    let schema = format!("{SHARED}/reference/gsdml-xsd-v2.44/GSDML-DeviceProfile-v2.44.xsd");

    let gsd_texts: Vec<(PathBuf, Vec<u8>)> = gsd_files
        .iter()
        .map(|p| (p.clone(), std::fs::read(p).unwrap()))
        .collect();
    let gsdc_gsd = median(|| {
        for (_, bytes) in &gsd_texts {
            let text = gsdc::gsd::decode(bytes);
            std::hint::black_box(gsdc::gsd::check(&text));
        }
    });
    let parser_gsd = median(|| {
        for (path, bytes) in &gsd_texts {
            let text = String::from_utf8_lossy(bytes);
            let _ = std::hint::black_box(gsd_parser::parser::parse(path, &text));
        }
    });
    report(
        &format!("GSD corpus ({} files)", gsd_files.len()),
        ("gsdc check", gsdc_gsd),
        ("gsd-parser parse", parser_gsd),
    );

    let gsdc_gsdml = median(|| run(Command::new(GSDC).arg("check").args(&gsdml_files)));
    let xmllint_gsdml = median(|| run(xmllint(&schema).args(&gsdml_files)));
    report(
        &format!("GSDML corpus ({} files)", gsdml_files.len()),
        ("gsdc check", gsdc_gsdml),
        ("xmllint --schema", xmllint_gsdml),
    );
    let schema_dir = Path::new(&schema).parent().unwrap();
    let gsdc_xsd = median(|| {
        run(Command::new(GSDC)
            .arg("check")
            .arg("--xsd")
            .arg(schema_dir)
            .args(&gsdml_files))
    });
    report(
        &format!(
            "GSDML corpus ({} files), with the schema",
            gsdml_files.len()
        ),
        ("gsdc check --xsd", gsdc_xsd),
        ("xmllint --schema", xmllint_gsdml),
    );

    let out = std::env::temp_dir().join(format!("gsdc-bench-{}", std::process::id()));
    let description = format!("{}/descriptions/md810dp.toml", env!("CARGO_MANIFEST_DIR"));
    let build = median(|| {
        let _ = std::fs::remove_dir_all(&out);
        run(Command::new(GSDC)
            .args(["build", &description, "--out"])
            .arg(&out));
    });
    let gsdml = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().path())
        .find(|p| p.extension().is_some_and(|e| e == "xml"))
        .expect("the build writes a GSDML file");
    let xmllint_one = median(|| run(xmllint(&schema).arg(&gsdml)));
    report(
        "build md810dp.toml (all outputs, verified)",
        ("gsdc build", build),
        ("xmllint on its GSDML", xmllint_one),
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

fn median(mut f: impl FnMut()) -> Duration {
    f(); // warm caches
    let mut times: Vec<Duration> = (0..RUNS)
        .map(|_| {
            let start = Instant::now();
            f();
            start.elapsed()
        })
        .collect();
    times.sort();
    times[RUNS / 2]
}

fn report(what: &str, ours: (&str, Duration), theirs: (&str, Duration)) {
    let ratio = theirs.1.as_secs_f64() / ours.1.as_secs_f64();
    println!(
        "{what}: {} {:.2} ms, {} {:.2} ms: gsdc is {ratio:.1}x as fast",
        ours.0,
        ours.1.as_secs_f64() * 1e3,
        theirs.0,
        theirs.1.as_secs_f64() * 1e3,
    );
}
