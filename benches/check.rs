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

#[path = "common/mod.rs"]
mod common;

use common::{compare, run};
use std::path::{Path, PathBuf};
use std::process::Command;

const SHARED: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../shared");
const GSDC: &str = env!("CARGO_BIN_EXE_gsdc");

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
