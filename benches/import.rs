//! `cargo bench --bench import`: `gsdc import` against `gsdc build` of
//! the description the import makes, in one run, printing each ratio
//! (above 1: the import is the faster), for
//!
//! - the largest corpus GSD file whose import builds: where its round trip
//!   is not clean (E601), `gsdc import` writes nothing and exits 1 after
//!   the same work, and the build measured is of the draft it made
//!   ([`gsdc::import::Imported::draft`]);
//! - the largest corpus GSDML file whose import builds, the largest corpus
//!   file, SEW's MOVI-C (1.1 MB; its round trip clean, its build writes a
//!   GSDML file of 1.05 MB);
//! - the largest GSDML file whose import is written (its round trip clean)
//!   among the corpus's and those the shipped descriptions build, where the
//!   two handle the same device: measured when not the one above.
//!
//! Each as processes, as users run them (`gsdc import FILE --out DESC.toml`,
//! a new file each turn, against `gsdc build DESC.toml --out DIR`), and in
//! process on one thread (`import::import` against `load` and `compile`).
//! The import reads the file, then builds its description's GSD or GSDML
//! file for its round trip (reads it back and compares it with the file,
//! `gsdc diff`); the build writes the layouts besides and checks every file.
//! Needs ../shared beside the checkout.

#[path = "common/mod.rs"]
mod common;

use common::{compare, run};
use std::path::{Path, PathBuf};
use std::process::Command;

const GSDC: &str = env!("CARGO_BIN_EXE_gsdc");

fn main() {
    let corpus = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/corpus"));
    let dir = std::env::temp_dir().join(format!("gsdc-bench-import-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let gsd = largest(device_files(&corpus.join("gsd")), Import::Builds);
    measure("GSD file whose import builds", gsd, &dir.join("gsd"));
    let gsdml = largest(device_files(&corpus.join("gsdml")), Import::Builds);
    let builds = gsdml.0.clone();
    measure("GSDML file whose import builds", gsdml, &dir.join("gsdml"));
    let shipped = shipped_gsdml_files(&dir);
    let written = device_files(&corpus.join("gsdml"))
        .into_iter()
        .chain(shipped);
    let clean = largest(written.collect(), Import::Written);
    match clean.0 == builds {
        true => println!("largest GSDML file whose import is written: the same"),
        false => measure(
            "GSDML file whose import is written",
            clean,
            &dir.join("clean"),
        ),
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Import against build of one file, as processes and in process.
fn measure(kind: &str, (path, bytes, description): (PathBuf, Vec<u8>, String), dir: &Path) {
    let name = path.file_name().unwrap().to_string_lossy().into_owned();
    println!("largest {kind}: {}, {} bytes", path.display(), bytes.len());
    std::fs::create_dir_all(dir).unwrap();
    let desc = dir.join("imported.toml");
    std::fs::write(&desc, &description).unwrap();
    let mut turn = 0;
    compare(
        &format!("{name}, as processes"),
        ("gsdc import", &mut || {
            turn += 1;
            let out = dir.join(format!("turn{turn}.toml"));
            run(Command::new(GSDC)
                .arg("import")
                .arg(&path)
                .arg("--out")
                .arg(&out));
        }),
        ("gsdc build", &mut || {
            run(Command::new(GSDC)
                .arg("build")
                .arg(&desc)
                .arg("--out")
                .arg(dir.join("dist")));
        }),
    );
    compare(
        &format!("{name}, in process on one thread"),
        ("import::import", &mut || {
            std::hint::black_box(gsdc::import::import(&name, &bytes));
        }),
        ("load + compile", &mut || {
            let (ir, _) = gsdc::load("imported.toml", &description);
            std::hint::black_box(gsdc::compile(&ir.unwrap()).unwrap());
        }),
    );
}

fn device_files(folder: &Path) -> Vec<PathBuf> {
    std::fs::read_dir(folder)
        .unwrap_or_else(|e| panic!("{} is missing: {e}", folder.display()))
        .map(|e| e.unwrap().path())
        .collect()
}

/// The GSDML files the shipped descriptions build, written into `dir`.
fn shipped_gsdml_files(dir: &Path) -> Vec<PathBuf> {
    let shipped = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/descriptions"));
    let mut files = Vec::new();
    for path in device_files(shipped) {
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        let read = |p: &str| std::fs::read(shipped.join(p)).map_err(|e| e.to_string());
        let Some(ir) = gsdc::load_with(&name, &text, &read).0 else {
            continue;
        };
        for file in gsdc::compile(&ir).unwrap() {
            if file.kind == gsdc::ArtifactKind::Gsdml {
                let out = dir.join(&file.file_name);
                std::fs::write(&out, &file.contents).unwrap();
                files.push(out);
            }
        }
    }
    files
}

/// Which imports count.
#[derive(Clone, Copy)]
enum Import {
    /// Its description builds: the one `gsdc import` writes, or the one it
    /// makes and does not write, whose build is another device (E601).
    Builds,
    /// `gsdc import` writes it: its round trip is clean.
    Written,
}

/// The largest of `files` whose import counts, its bytes and the
/// description.
fn largest(files: Vec<PathBuf>, counted: Import) -> (PathBuf, Vec<u8>, String) {
    let mut found: Vec<(PathBuf, Vec<u8>, String)> = files
        .into_iter()
        .filter_map(|path| {
            let bytes = std::fs::read(&path).ok()?;
            let name = path.file_name()?.to_string_lossy().into_owned();
            let imported = gsdc::import::import(&name, &bytes);
            let description = match counted {
                Import::Builds => imported.description.or(imported.draft),
                Import::Written => imported.description,
            }?;
            Some((path, bytes, description))
        })
        .collect();
    found.sort_by_key(|(_, bytes, _)| bytes.len());
    found.pop().expect("a file that imports")
}
