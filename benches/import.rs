//! `cargo bench --bench import`: `gsdc import` of the largest corpus GSD
//! file and of the largest corpus GSDML file whose imports build, against
//! `gsdc build` of the description each import makes, in one run, printing
//! each ratio (above 1: the import is the faster).
//!
//! - as processes, as users run them: `gsdc import FILE --out DESC.toml`
//!   (a new file each turn) against `gsdc build DESC.toml --out DIR`;
//! - in process, on one thread: `import::import` against `load` and
//!   `compile` of its description.
//!
//! The import reads the whole file, then builds its description's GSD or
//! GSDML file for its round trip (reads it back and compares it with the
//! file, `gsdc diff`); the build writes the layouts besides and checks every
//! file. The largest GSDML file is the largest corpus file, SEW's MOVI-C
//! (1.1 MB): its build is another device (E601, README's table), so `gsdc
//! import` writes nothing and exits 1 after the same work, and the build
//! measured is of the description it made
//! ([`gsdc::import::Imported::another_device`]). Needs ../shared beside the
//! checkout.

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
    let gsd = largest_imported(device_files(&corpus.join("gsd")));
    measure("GSD", gsd, &dir.join("gsd"));
    let gsdml = largest_imported(device_files(&corpus.join("gsdml")));
    measure("GSDML", gsdml, &dir.join("gsdml"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Import against build of one file, as processes and in process.
fn measure(kind: &str, (path, bytes, description): (PathBuf, Vec<u8>, String), dir: &Path) {
    let name = path.file_name().unwrap().to_string_lossy().into_owned();
    println!(
        "largest {kind} file whose import builds: {}, {} bytes",
        path.display(),
        bytes.len()
    );
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

/// The largest of `files` whose import builds, its bytes and the
/// description: the one `gsdc import` writes, or, where the build is
/// another device (E601), the one it makes and does not write.
fn largest_imported(files: Vec<PathBuf>) -> (PathBuf, Vec<u8>, String) {
    let mut found: Vec<(PathBuf, Vec<u8>, String)> = files
        .into_iter()
        .filter_map(|path| {
            let bytes = std::fs::read(&path).ok()?;
            let name = path.file_name()?.to_string_lossy().into_owned();
            let imported = gsdc::import::import(&name, &bytes);
            let description = imported.description.or(imported.another_device)?;
            Some((path, bytes, description))
        })
        .collect();
    found.sort_by_key(|(_, bytes, _)| bytes.len());
    found.pop().expect("a file that imports")
}
