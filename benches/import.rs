//! `cargo bench --bench import`: `gsdc import` of the largest corpus GSD
//! file it imports (its round trip clean) against `gsdc build` of the
//! description the import writes, in one run, printing each ratio (above
//! 1: the import is the faster).
//!
//! - as processes, as users run them: `gsdc import FILE --out DESC.toml`
//!   (a new file each turn) against `gsdc build DESC.toml --out DIR`;
//! - in process, on one thread: `import::import` against `load` and
//!   `compile` of its description.
//!
//! The import writes its description's GSD too, for its round trip (reads
//! it back and compares it with the file, `gsdc diff`); the build writes
//! the layouts besides and checks every file. GSDML files, the largest of
//! the corpus among them, are refused by the import (E602) and
//! so left out. Needs ../shared beside the checkout.

#[path = "common/mod.rs"]
mod common;

use common::{compare, run};
use std::path::PathBuf;
use std::process::Command;

const GSDC: &str = env!("CARGO_BIN_EXE_gsdc");

fn main() {
    let corpus = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/corpus/gsd"));
    let (path, bytes, description) = largest_imported(&corpus);
    let name = path.file_name().unwrap().to_string_lossy().into_owned();
    println!(
        "largest corpus GSD file gsdc imports: {name}, {} bytes",
        bytes.len()
    );

    let dir = std::env::temp_dir().join(format!("gsdc-bench-import-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
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
    let _ = std::fs::remove_dir_all(&dir);
}

/// The largest GSD of the corpus whose import is written, its bytes and the
/// description.
fn largest_imported(corpus: &std::path::Path) -> (PathBuf, Vec<u8>, String) {
    let mut found: Vec<(PathBuf, Vec<u8>, String)> = std::fs::read_dir(corpus)
        .unwrap_or_else(|e| panic!("{} is missing: {e}", corpus.display()))
        .map(|e| e.unwrap().path())
        .filter_map(|path| {
            let bytes = std::fs::read(&path).ok()?;
            let name = path.file_name()?.to_string_lossy().into_owned();
            let description = gsdc::import::import(&name, &bytes).description?;
            Some((path, bytes, description))
        })
        .collect();
    found.sort_by_key(|(_, bytes, _)| bytes.len());
    found.pop().expect("a corpus GSD file that imports")
}
