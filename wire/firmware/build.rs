//! Generates, with gsdc's build-script API, the layout of every description
//! the firmware is built for, and `registry.rs`: each layout as a module of
//! its own, and the table of them by description name.
//!
//! `WIRE_DESCRIPTIONS` names the descriptions: paths separated by `:` (as
//! PATH separates them). Unset or empty, every shipped description and every
//! valid fixture with a bus part.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

const DESCRIPTIONS_ENV: &str = "WIRE_DESCRIPTIONS";

fn main() {
    let out_dir = PathBuf::from(std::env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    println!("cargo:rerun-if-env-changed={DESCRIPTIONS_ENV}");
    let mut layouts: Vec<Layout> = Vec::new();
    for description in descriptions() {
        let path =
            gsdc::build::generate_rust(&description, &out_dir).unwrap_or_else(|e| panic!("{e}"));
        let layout = Layout::new(&description, &path, &load(&description));
        if let Some(other) = layouts.iter().find(|l| l.module == layout.module) {
            panic!(
                "{} and {} both give {}: the firmware holds one layout of a name",
                other.description.display(),
                description.display(),
                layout.file_name
            );
        }
        layouts.push(layout);
    }
    std::fs::write(out_dir.join("registry.rs"), registry(&layouts))
        .unwrap_or_else(|e| panic!("{}: {e}", out_dir.display()));
}

/// One generated layout.
struct Layout {
    description: PathBuf,
    /// The description's file name without `.toml`: its name in the registry.
    name: String,
    /// `md810dp_layout.rs`.
    file_name: String,
    /// The module that includes it: the file's stem, made an identifier.
    module: String,
    /// Its card: the layout's device tables, numbering and codecs, by the
    /// names the layout gives them.
    card: String,
}

impl Layout {
    fn new(description: &Path, layout: &Path, ir: &gsdc::Ir) -> Self {
        let file_name = layout.file_name().unwrap().to_string_lossy().into_owned();
        let stem = file_name.trim_end_matches("_layout.rs");
        // As gsdc's C layouts name them: an identifier cannot start with a digit.
        let module = if stem.starts_with(|c: char| c.is_ascii_digit()) {
            format!("gsdc_{stem}")
        } else {
            stem.to_string()
        };
        let name = description
            .file_stem()
            .unwrap()
            .to_string_lossy()
            .into_owned();
        Layout {
            description: description.to_path_buf(),
            card: card(&name, &module, ir),
            name,
            file_name,
            module,
        }
    }
}

/// The description's plan: which of the layout's items there are.
fn load(path: &Path) -> gsdc::Ir {
    let name = path.file_name().unwrap().to_string_lossy();
    let loaded = gsdc::build::load_file(path, &name).unwrap_or_else(|e| panic!("{e}"));
    loaded
        .ir
        .unwrap_or_else(|| panic!("{}: the description has errors", path.display()))
}

/// The `Card` of the layout `module`: its tables and codecs by the names
/// every layout gives them; the plan says only which of them it has.
fn card(name: &str, module: &str, ir: &gsdc::Ir) -> String {
    let item = |present: bool, item: String| match present {
        true => format!("Some({item})"),
        false => "None".to_string(),
    };
    format!(
        "    Card {{
        name: {name:?},
        fingerprint: {module}::FINGERPRINT,
        dp: {},
        gateway: {},
        pn: {},
        numbering: {},
    }},
",
        item(ir.profibus.is_some(), format!("&{module}::DP_DEVICE")),
        item(
            ir.gateway.is_some(),
            format!("crate::gateway_of!({module})")
        ),
        item(ir.profinet.is_some(), format!("&{module}::PN_DEVICE")),
        item(ir.numbering.is_some(), format!("&{module}::NUMBERING")),
    )
}

/// The descriptions `WIRE_DESCRIPTIONS` names, or the default set.
fn descriptions() -> Vec<PathBuf> {
    match std::env::var_os(DESCRIPTIONS_ENV).filter(|v| !v.is_empty()) {
        Some(list) => std::env::split_paths(&list).collect(),
        None => {
            let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
            ["descriptions", "tests/fixtures/valid"]
                .iter()
                .flat_map(|folder| descriptions_in(&root.join(folder)))
                .filter(|path| has_a_bus(path))
                .collect()
        }
    }
}

/// The `.toml` files of `dir`, in name order; cargo runs the build script
/// again when one is added or removed.
fn descriptions_in(dir: &Path) -> Vec<PathBuf> {
    println!("cargo:rerun-if-changed={}", dir.display());
    let mut paths: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|entry| entry.unwrap().path())
        .filter(|path| path.extension().is_some_and(|e| e == "toml"))
        .collect();
    paths.sort();
    paths
}

/// Whether the description has a PROFIBUS or a PROFINET part.
fn has_a_bus(path: &Path) -> bool {
    let ir = load(path);
    ir.profibus.is_some() || ir.profinet.is_some()
}

/// Each layout in a module of its own, and the cards of them.
fn registry(layouts: &[Layout]) -> String {
    let mut text = String::from(
        "// @generated by wire/firmware/build.rs: the layouts the firmware is built for.\n\n",
    );
    for layout in layouts {
        writeln!(
            text,
            "/// The layout of {}.\npub mod {} {{\n    include!(concat!(env!(\"OUT_DIR\"), \"/{}\"));\n}}\n",
            layout.name, layout.module, layout.file_name
        )
        .unwrap();
    }
    writeln!(
        text,
        "/// The card of every layout the firmware is built for, in the order the build was given them.\npub const CARDS: [Card; {}] = [",
        layouts.len()
    )
    .unwrap();
    for layout in layouts {
        text.push_str(&layout.card);
    }
    text.push_str("];\n");
    text
}
