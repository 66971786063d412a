//! `cargo bench --bench import`: `gsdc import` of the largest corpus GSD
//! file it imports (its round trip clean), and of the largest GSDML file it
//! imports, against `gsdc build` of the description the import writes, in
//! one run, printing each ratio (above 1: the import is the faster).
//!
//! - as processes, as users run them: `gsdc import FILE --out DESC.toml`
//!   (a new file each turn) against `gsdc build DESC.toml --out DIR`;
//! - in process, on one thread: `import::import` against `load` and
//!   `compile` of its description.
//!
//! The import writes its description's GSD or GSDML file too, for its round
//! trip (reads it back and compares it with the file, `gsdc diff`); the
//! build writes the layouts besides and checks every file. No GSDML file of
//! the corpus imports, the largest corpus file (SEW's MOVI-C, 1.1 MB) among
//! them: refused (E602, no module the format can say) or not the same
//! device (E601: several device access points, modules of their own IO
//! layouts, README's table), so the GSDML measured is the largest that
//! imports of the corpus's and of the GSDML files the shipped descriptions
//! build (MV810's, a vendor's hand-written file would stand there). Needs
//! ../shared beside the checkout.

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
    let gsd = largest_imported(gsd_files(&corpus.join("gsd")));
    measure("GSD", gsd, &dir.join("gsd"));
    let gsdml = largest_imported(gsdml_files(&corpus.join("gsdml"), &dir));
    measure("GSDML", gsdml, &dir.join("gsdml"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Import against build of one file, as processes and in process.
fn measure(kind: &str, (path, bytes, description): (PathBuf, Vec<u8>, String), dir: &Path) {
    let name = path.file_name().unwrap().to_string_lossy().into_owned();
    println!(
        "largest {kind} file gsdc imports: {}, {} bytes",
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

fn gsd_files(folder: &Path) -> Vec<PathBuf> {
    std::fs::read_dir(folder)
        .unwrap_or_else(|e| panic!("{} is missing: {e}", folder.display()))
        .map(|e| e.unwrap().path())
        .collect()
}

/// The corpus's GSDML files, and those the shipped descriptions build
/// (written into `dir`).
fn gsdml_files(folder: &Path, dir: &Path) -> Vec<PathBuf> {
    let mut files = gsd_files(folder);
    let shipped = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/descriptions"));
    for entry in std::fs::read_dir(shipped).unwrap() {
        let path = entry.unwrap().path();
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

/// The largest of `files` whose import is written, its bytes and the
/// description.
fn largest_imported(files: Vec<PathBuf>) -> (PathBuf, Vec<u8>, String) {
    let mut found: Vec<(PathBuf, Vec<u8>, String)> = files
        .into_iter()
        .filter_map(|path| {
            let bytes = std::fs::read(&path).ok()?;
            let name = path.file_name()?.to_string_lossy().into_owned();
            let description = gsdc::import::import(&name, &bytes).description?;
            Some((path, bytes, description))
        })
        .collect();
    found.sort_by_key(|(_, bytes, _)| bytes.len());
    found.pop().expect("a file that imports")
}
