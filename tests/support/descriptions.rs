//! The descriptions the tests use, found where they are: the shipped ones
//! (`descriptions/*.toml`), the valid fixtures (`tests/fixtures/valid/`),
//! the invalid fixtures (`tests/fixtures/invalid/`, each with its
//! `# expect: CODE` line) and the guide's examples; loaded as the build
//! loads them, and the files gsdc makes of them.

use super::checkout;
use gsdc::{Artifact, ArtifactKind, Diagnostics, Ir};
use std::path::{Path, PathBuf};

/// The `.toml` files of `folder` (in the checkout), by file name, in name
/// order.
fn toml_files(folder: &str) -> Vec<String> {
    let dir = checkout(folder);
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".toml"))
        .collect();
    names.sort();
    assert!(!names.is_empty(), "no description in {}", dir.display());
    names
}

/// The shipped descriptions, `descriptions/*.toml`, by file name.
pub fn shipped() -> Vec<String> {
    toml_files("descriptions")
}

/// Every shipped description, by file name, with its IR.
pub fn load_shipped() -> Vec<(String, Ir)> {
    shipped()
        .into_iter()
        .map(|name| {
            let ir = load(&name);
            (name, ir)
        })
        .collect()
}

/// The IR of `descriptions/<name>`, which must load without an error; read
/// as the build reads it, so that the files it names (its symbol) are found.
pub fn load(name: &str) -> Ir {
    load_from("descriptions", name)
}

/// The IR of `<folder>/<name>` under the checkout, which must load without
/// an error.
pub fn load_from(folder: &str, name: &str) -> Ir {
    let path = checkout(folder).join(name);
    let loaded = gsdc::build::load_file(&path, name).unwrap();
    let diagnostics = &loaded.findings.diagnostics;
    assert!(!diagnostics.has_errors(), "{name}: {diagnostics:?}");
    loaded.ir.unwrap()
}

/// The text of `descriptions/<name>`.
pub fn shipped_text(name: &str) -> String {
    let path = checkout("descriptions").join(name);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The MD810 gateway's description with each slave's TPDO words in bits
/// 0-3 and its RPDO words in bits 4-7 of one byte, instead of a byte each.
pub fn gateway_in_bit_areas() -> String {
    let text = ["TPDO", "RPDO"].iter().zip(["[0, 3]", "[4, 7]"]).fold(
        shipped_text("md810-gateway.toml"),
        |text, (pdo, bits)| {
            let name = format!("name = \"Slave {{n}} {pdo} words\"\n");
            text.replacen(
                &format!("{name}type = \"Unsigned8\""),
                &format!("{name}bits = {bits}"),
                1,
            )
        },
    );
    assert_eq!(text.matches("bits = [").count(), 2, "{text}");
    text
}

/// MV810's description as if the master set its mappings (as it did before
/// section 4's set-up was read: P43.01 to P43.23 set at the drive): each
/// module fixing P43.01 to its own message, and the PZD mappings and P43.01
/// in parameter records 1, 2 and 4. Its GSDML has records with choices for
/// the tests of records; section 4's set-up steps, which set at the drive
/// what the master would then write (E158), are left out.
pub fn mv810_set_by_master() -> String {
    let text = shipped_text("mv810-pnet02.toml");
    let without_setup = &text[..text.find("\n[[setup]]").unwrap()];
    let by_master = without_setup
        .replace("set_at = \"drive\"", "set_at = \"master\"")
        .replacen(
            "parameter = \"P43.01\"\n",
            "parameter = \"P43.01\"\nper_module = { user_defined = 1, standard_telegram_1 = 0 }\n",
            1,
        );
    assert_eq!(by_master.matches("set_at = \"master\"").count(), 3);
    assert!(by_master.contains("per_module"));
    format!("{by_master}\n[profinet.records]\npzd_out = 1\npzd_in = 2\nsettings = 4\n")
}

/// `text`, own_idents.toml or a variant of it, with a port label and a
/// port name for each of `ports` ports: an access point with more ports
/// than the fixture's two needs both (E191).
pub fn own_idents_port_texts(text: &str, ports: usize) -> String {
    let list = |each: &dyn Fn(usize) -> String| {
        let items: Vec<String> = (1..=ports).map(each).collect();
        format!("[{}]", items.join(", "))
    };
    let labels = format!("ports = {}", list(&|n| format!("\"X1 P{n}\"")));
    let names = format!(
        "port_names = {}",
        list(&|n| format!("\"Port {n} - RJ45 (X1 P{n})\""))
    );
    let changed = text
        .replacen(
            "ports = [\"X1 P1\", { en = \"X1 P2\", zh = \"X1 端口 2\" }]",
            &labels,
            1,
        )
        .replacen(
            "port_names = [\"Port 1 - RJ45 (X1 P1)\", { en = \"Port 2 - RJ45 (X1 P2)\", zh = \"端口 2 - RJ45（X1 P2）\" }]",
            &names,
            1,
        );
    assert!(
        changed.contains(&labels) && changed.contains(&names),
        "{text}"
    );
    changed
}

/// `text` (a shipped description, or one made from it) loaded as if it
/// stood in `descriptions/`: the files it names are read from there.
pub fn load_text(name: &str, text: &str) -> (Option<Ir>, Diagnostics) {
    let dir = checkout("descriptions");
    gsdc::load_with(name, text, &|path: &str| {
        std::fs::read(dir.join(path)).map_err(|e| e.to_string())
    })
}

/// The errors of `text` (which must not build, loaded as [`load_text`]
/// loads it), each as its code, line and column.
pub fn error_places(name: &str, text: &str) -> Vec<(&'static str, usize, usize)> {
    let (ir, diagnostics) = load_text(name, text);
    assert!(ir.is_none(), "built");
    diagnostics
        .errors()
        .map(|d| {
            let (line, column) = gsdc::line_col(text, d.span.clone().unwrap().start);
            (d.code, line, column)
        })
        .collect()
}

/// Copies the shipped descriptions' symbols into `dir/symbols`, for a test
/// that writes a description (or a copy of one) into `dir`.
pub fn copy_symbols(dir: &Path) {
    let from = checkout("descriptions/symbols");
    let to = dir.join("symbols");
    std::fs::create_dir_all(&to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let path = entry.unwrap().path();
        std::fs::copy(&path, to.join(path.file_name().unwrap())).unwrap();
    }
}

/// Every shipped description and every valid fixture, by file name, in
/// name order within each folder.
pub fn all_valid() -> Vec<(String, Ir)> {
    ["descriptions", "tests/fixtures/valid"]
        .iter()
        .flat_map(|folder| {
            toml_files(folder)
                .into_iter()
                .map(|name| (name.clone(), load_from(folder, &name)))
        })
        .collect()
}

/// The invalid fixtures, `tests/fixtures/invalid/*.toml`, as paths.
pub fn invalid_fixtures() -> Vec<PathBuf> {
    let dir = checkout("tests/fixtures/invalid");
    toml_files("tests/fixtures/invalid")
        .into_iter()
        .map(|name| dir.join(name))
        .collect()
}

/// The code a fixture's `# expect: CODE` line names.
pub fn expected_code(text: &str) -> Option<&str> {
    text.lines()
        .find_map(|l| l.strip_prefix("# expect: "))
        .map(str::trim)
}

/// The TOML examples of docs/description.md, in order: the complete one and
/// the gateway's.
pub fn guide_examples() -> Vec<&'static str> {
    let guide = include_str!("../../docs/description.md");
    guide
        .split("```toml\n")
        .skip(1)
        .map(|rest| &rest[..rest.find("```").unwrap()])
        .collect()
}

/// Every file gsdc makes of `ir`: those that ship with the card
/// (`gsdc::compile`) and its datasheet (`gsdc::document`).
pub fn outputs(ir: &Ir) -> Vec<Artifact> {
    let mut files = gsdc::compile(ir).unwrap();
    files.extend(gsdc::document(ir));
    files
}

/// The one file of `kind` among `files`: its name and its text.
#[track_caller]
pub fn one(files: Vec<Artifact>, kind: ArtifactKind) -> (String, String) {
    let mut found = files.into_iter().filter(|a| a.kind == kind);
    let file = found.next().unwrap_or_else(|| panic!("no {kind:?}"));
    assert!(found.next().is_none(), "two {kind:?}");
    let text = String::from_utf8(file.contents).expect("a text file");
    (file.file_name, text)
}

/// The text of the one file of `kind` gsdc makes of `ir`.
#[track_caller]
pub fn output_text(ir: &Ir, kind: ArtifactKind) -> String {
    one(outputs(ir), kind).1
}
