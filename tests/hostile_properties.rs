//! Two properties over descriptions made hostile on purpose, so that the
//! next description that loads but reaches E900, or the next two whose files
//! cannot be used together, is found here rather than by an attacker
//! (issue 26):
//!
//! 1. Every description the loader accepts compiles without E900 ("gsdc
//!    generated a file its own checks reject") and gives its datasheet,
//!    over mutations of every shipped description and every fixture, valid
//!    and invalid: each number of each at and past the limits the loader
//!    holds it to (learnt from the loader's own E101/E003 for a number far
//!    out of range) and at and past each limit of the GSD keyword schema;
//!    each string replaced by strings of every class (empty, at and past
//!    the GSD lengths, non-ASCII, control and reordering characters,
//!    markup, placeholders); each list with an item more, one less and
//!    none; each flag flipped; each under a file stem from [`STEMS`].
//!    The layouts of the mutations that change a text compile: all the
//!    Rust layouts in one crate, each C layout in a translation unit.
//! 2. Every file two descriptions build into one directory can be used
//!    together: all the C layouts in one translation unit (and no macro
//!    defined by two of them: an include guard of one name compiles
//!    without a word and loses the second header), all the Rust layouts in
//!    one crate, for every shipped description and valid fixture under
//!    every stem of [`STEMS`] paired with another; or the build refuses
//!    them, as it refuses two whose files or C names meet.
//!
//! gcc and rustc must be installed (`./scripts/test.sh` installs gcc).

use crate::support::{descriptions, scratch, CHECKOUT as MANIFEST};
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use toml::{Table, Value};

/// File stems a description may have: plain; gsdc's own name, which the
/// support files carry; ones with no letter, only a `_`, or non-ASCII,
/// whose C prefix gsdc spells itself; a leading digit; one stem another's
/// start; separators a layout's name turns into `_`.
const STEMS: [&str; 12] = [
    "card",
    "gsdc",
    "_",
    "ü",
    "9lives",
    "m",
    "m_pkw",
    "gsdc_support",
    "a-b",
    "x.y",
    "Straße",
    "CON",
];

/// A description file of the repository: its name and text.
struct Source {
    name: String,
    text: String,
}

/// Every shipped description, every valid fixture and every invalid one.
fn sources(folders: &[&str]) -> Vec<Source> {
    let mut sources = Vec::new();
    for folder in folders {
        let mut paths: Vec<PathBuf> = std::fs::read_dir(Path::new(MANIFEST).join(folder))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "toml"))
            .collect();
        paths.sort();
        sources.extend(paths.into_iter().map(|path| Source {
            name: format!("{folder}/{}", path.file_name().unwrap().to_string_lossy()),
            text: std::fs::read_to_string(&path).unwrap(),
        }));
    }
    sources
}

const VALID: [&str; 2] = ["descriptions", "tests/fixtures/valid"];
const ALL: [&str; 3] = [
    "descriptions",
    "tests/fixtures/valid",
    "tests/fixtures/invalid",
];

/// `text` loaded as `<stem>.toml` beside the shipped descriptions, whose
/// symbols it may name.
fn load(stem: &str, text: &str) -> (Option<gsdc::Ir>, gsdc::Diagnostics) {
    descriptions::load_text(&format!("{stem}.toml"), text)
}

// ---------------------------------------------------------------------------
// 1. Whatever the loader accepts compiles.

/// A step into a TOML document: a key of a table or an item of a list.
#[derive(Debug, Clone)]
enum Step {
    Key(String),
    Item(usize),
}

fn path_name(path: &[Step]) -> String {
    let mut name = String::new();
    for step in path {
        match step {
            Step::Key(key) if name.is_empty() => name.push_str(key),
            Step::Key(key) => {
                let _ = write!(name, ".{key}");
            }
            Step::Item(i) => {
                let _ = write!(name, "[{i}]");
            }
        }
    }
    name
}

/// Every value of `value` with its path: each number, string, flag and
/// list (lists also item by item), not the tables.
fn values(value: &Value, path: &mut Vec<Step>, out: &mut Vec<(Vec<Step>, Value)>) {
    match value {
        Value::Table(table) => {
            for (key, value) in table {
                path.push(Step::Key(key.clone()));
                values(value, path, out);
                path.pop();
            }
        }
        Value::Array(items) => {
            out.push((path.clone(), value.clone()));
            for (i, item) in items.iter().enumerate() {
                path.push(Step::Item(i));
                values(item, path, out);
                path.pop();
            }
        }
        _ => out.push((path.clone(), value.clone())),
    }
}

fn at<'a>(value: &'a mut Value, path: &[Step]) -> &'a mut Value {
    path.iter().fold(value, |value, step| match step {
        Step::Key(key) => &mut value.as_table_mut().unwrap()[key.as_str()],
        Step::Item(i) => &mut value.as_array_mut().unwrap()[*i],
    })
}

/// `document` with `replacement` at `path`, as TOML text.
fn with(document: &Value, path: &[Step], replacement: Value) -> Option<String> {
    let mut document = document.clone();
    *at(&mut document, path) = replacement;
    toml::to_string(&document).ok()
}

/// The strings every string of a description is replaced by, in turn.
fn string_classes() -> Vec<String> {
    vec![
        String::new(),
        " ".into(),
        "x".into(),
        "N".repeat(32),
        "N".repeat(33),
        "I".repeat(256),
        "I".repeat(257),
        "ß".repeat(20),
        "Müller".into(),
        "电动转矩上限给定".into(),
        "\u{1b}[31mred".into(),
        "a\u{202E}b".into(),
        "a\u{061C}b".into(),
        "\"quoted\" and 'quoted'".into(),
        "<script>alert(1)</script>".into(),
        "*/ /* ?? \\ {n} {{n}}".into(),
        "line\nbreak".into(),
        "self".into(),
        "PPO1".into(),
        "F0-00".into(),
        "x".repeat(5000),
        "Self".into(),
        "9 lives".into(),
        "__".into(),
    ]
}

/// The limits of the GSD keyword schema: every `min`, `max` and `max_len`,
/// and the types' ends.
fn schema_limits() -> Vec<i64> {
    let text =
        std::fs::read_to_string(Path::new(MANIFEST).join("schemas/gsd-keywords.toml")).unwrap();
    let schema: Table = text.parse().unwrap();
    let mut limits: BTreeSet<i64> = [0, 0xFF, 0xFFFF, 0xFFFF_FFFF].into();
    for spec in schema.values() {
        for field in ["min", "max", "max_len", "tolerated_min"] {
            if let Some(n) = spec.get(field).and_then(Value::as_integer) {
                limits.insert(n);
            }
        }
    }
    limits.into_iter().collect()
}

/// A number far past every limit, found in the text where the loader
/// quotes it.
const PROBE: i64 = 987_654_321_987;

/// The range the loader says a number at `at` in `text` must be in: E101's
/// `not within MIN..=MAX`, or E003's `from MIN to MAX`.
fn loader_range(stem: &str, text: &str) -> Option<(i64, i64)> {
    let at = text.find(&PROBE.to_string())?;
    let (_, diagnostics) = load(stem, text);
    diagnostics
        .iter()
        .filter(|d| {
            d.span
                .as_ref()
                .is_some_and(|s| s.start <= at && at < s.end.max(s.start + 1))
        })
        .find_map(|d| {
            let label = d.label.as_deref().unwrap_or_default();
            let range = label
                .strip_prefix("not within ")
                .and_then(|r| r.split_once("..="))
                .or_else(|| d.message.split_once("from ")?.1.split_once(" to "))?;
            Some((range.0.trim().parse().ok()?, range.1.trim().parse().ok()?))
        })
}

/// How many of the schema's limits and of the string classes each value
/// meets: the shipped descriptions and valid fixtures more, the invalid
/// fixtures (a hundred small ones, most of whose mutations keep their
/// error) fewer.
#[derive(Clone, Copy)]
struct Share {
    limits: usize,
    strings: usize,
}

const VALID_SHARE: Share = Share {
    limits: 2,
    strings: 4,
};
const INVALID_SHARE: Share = Share {
    limits: 0,
    strings: 1,
};

/// The replacements of one value: what it is mutated into. Each value gets
/// its share of the schema's limits and the string classes in turn, so
/// that across the descriptions every limit and every class meets every
/// kind of value.
#[allow(clippy::too_many_arguments)]
fn replacements(
    stem: &str,
    document: &Value,
    path: &[Step],
    value: &Value,
    turn: usize,
    share: Share,
    strings: &[String],
    limits: &[i64],
) -> Vec<(String, Value)> {
    let mut out: Vec<(String, Value)> = Vec::new();
    match value {
        Value::Integer(_) => {
            let mut numbers = BTreeSet::from([PROBE, -1]);
            let probe = with(document, path, Value::Integer(PROBE));
            if let Some((min, max)) = probe.and_then(|text| loader_range(stem, &text)) {
                numbers.extend([min - 1, min, max, max + 1]);
            }
            for k in 0..share.limits {
                let limit = limits[(turn * share.limits + k) % limits.len()];
                numbers.extend([limit, limit + 1]);
            }
            out.extend(
                numbers
                    .into_iter()
                    .map(|n| (n.to_string(), Value::Integer(n))),
            );
        }
        Value::String(_) => {
            for k in 0..share.strings {
                let s = &strings[(turn * share.strings + k) % strings.len()];
                out.push((format!("{:?}", truncated(s)), Value::String(s.clone())));
            }
        }
        Value::Boolean(b) => out.push((format!("{}", !b), Value::Boolean(!b))),
        Value::Array(items) => {
            if let Some(last) = items.last() {
                let mut more = items.clone();
                more.push(last.clone());
                out.push(("an item more".into(), Value::Array(more)));
                out.push((
                    "an item less".into(),
                    Value::Array(items[..items.len() - 1].to_vec()),
                ));
            }
            out.push(("empty".into(), Value::Array(Vec::new())));
        }
        _ => {}
    }
    out
}

fn truncated(s: &str) -> String {
    s.chars().take(12).collect()
}

/// A loaded description that must compile: its source and mutation.
struct Case {
    what: String,
    stem: &'static str,
    text: String,
}

/// What the mutations came to.
#[derive(Default)]
struct Tally {
    mutations: usize,
    accepted: usize,
    failures: Vec<String>,
    /// Accepted mutations of a text, whose layouts are compiled.
    layouts: Vec<(String, Vec<gsdc::Artifact>)>,
}

impl Tally {
    /// Loads the case; if the loader accepts it, it must compile and give
    /// its datasheet.
    fn run(&mut self, case: &Case, keep_layouts: bool) {
        self.mutations += 1;
        let (Some(ir), _) = load(case.stem, &case.text) else {
            return;
        };
        self.accepted += 1;
        match gsdc::compile(&ir) {
            Ok(files) => {
                if keep_layouts {
                    self.layouts.push((case.what.clone(), files));
                }
            }
            Err(problems) => {
                let codes: Vec<String> = problems
                    .iter()
                    .map(|d| format!("{}: {}", d.code, d.message))
                    .collect();
                self.failures.push(format!(
                    "{} (as {}.toml): {}",
                    case.what,
                    case.stem,
                    codes.join("; ")
                ));
            }
        }
        assert!(!gsdc::document(&ir).is_empty(), "{}", case.what);
    }
}

/// Each shipped description and valid fixture under each stem compiles:
/// a gateway's layout under a stem whose C prefix is `gsdc` alone (`gsdc`,
/// `_`, `ü`) declared the names of gsdc's support header, E900 (issue 26).
#[test]
fn every_valid_description_compiles_under_every_stem() {
    let mut failures = Vec::new();
    for source in sources(&VALID) {
        for stem in STEMS {
            let (ir, diagnostics) = load(stem, &source.text);
            let ir = ir.unwrap_or_else(|| panic!("{} as {stem}: {diagnostics:?}", source.name));
            if let Err(problems) = gsdc::compile(&ir) {
                failures.push(format!("{} as {stem}.toml: {problems:?}", source.name));
            }
        }
    }
    assert_eq!(failures, Vec::<String>::new());
}

#[test]
fn every_description_the_loader_accepts_compiles() {
    let sources = sources(&ALL);
    // The sources shared out between the cores, the tallies added up.
    let threads = std::thread::available_parallelism()
        .map_or(2, |n| n.get())
        .min(4);
    let tallies: Vec<Tally> = std::thread::scope(|scope| {
        let workers: Vec<_> = (0..threads)
            .map(|k| {
                let share: Vec<(usize, &Source)> = sources
                    .iter()
                    .enumerate()
                    .skip(k)
                    .step_by(threads)
                    .collect();
                scope.spawn(move || mutate(&share, MAX_MUTATED_LAYOUTS / threads))
            })
            .collect();
        workers.into_iter().map(|w| w.join().unwrap()).collect()
    });
    let mut tally = Tally::default();
    for t in tallies {
        tally.mutations += t.mutations;
        tally.accepted += t.accepted;
        tally.failures.extend(t.failures);
        tally.layouts.extend(t.layouts);
    }
    eprintln!(
        "{} mutations, {} accepted by the loader, {} of them compiled in their layouts",
        tally.mutations,
        tally.accepted,
        tally.layouts.len()
    );
    assert!(
        tally.accepted > tally.mutations / 20,
        "too few mutations load to test anything"
    );
    assert!(
        tally.failures.is_empty(),
        "{} accepted descriptions do not compile:\n{}",
        tally.failures.len(),
        tally
            .failures
            .iter()
            .take(40)
            .cloned()
            .collect::<Vec<_>>()
            .join("\n")
    );
    compile_layouts(&tally.layouts);
}

/// Every mutation of each of `sources` (with its index among all, which
/// sets its turn in the rotations), keeping the layouts of at most
/// `layouts` accepted mutations of a string.
fn mutate(sources: &[(usize, &Source)], layouts: usize) -> Tally {
    let strings = string_classes();
    let limits = schema_limits();
    let mut tally = Tally::default();
    for &(index, source) in sources {
        let Ok(table) = source.text.parse::<Table>() else {
            continue; // A fixture of a TOML error.
        };
        let share = match source.name.starts_with("tests/fixtures/invalid") {
            true => INVALID_SHARE,
            false => VALID_SHARE,
        };
        let document = Value::Table(table);
        let mut found = Vec::new();
        values(&document, &mut Vec::new(), &mut found);
        for (leaf, (path, value)) in found.iter().enumerate() {
            let turn = index * 7919 + leaf;
            let stem = STEMS[turn % STEMS.len()];
            for (shown, replacement) in
                replacements(stem, &document, path, value, turn, share, &strings, &limits)
            {
                let Some(text) = with(&document, path, replacement) else {
                    continue;
                };
                let case = Case {
                    what: format!("{} with {} = {shown}", source.name, path_name(path)),
                    stem,
                    text,
                };
                let keep = value.is_str() && tally.layouts.len() < layouts;
                tally.run(&case, keep);
            }
        }
    }
    tally
}

/// Mutated layouts compiled at most: each is a few hundred lines.
const MAX_MUTATED_LAYOUTS: usize = 150;

// ---------------------------------------------------------------------------
// Compiling layouts.

/// Compiles `unit`, a C translation unit, in `dir` as C99 with every
/// warning an error; the compiler's complaint if it fails.
fn compile_c(dir: &Path, unit: &str) -> Result<(), String> {
    std::fs::write(dir.join("unit.c"), unit).unwrap();
    let output = Command::new("gcc")
        .args([
            "-std=c99",
            "-Wall",
            "-Wextra",
            "-Wpedantic",
            "-Werror",
            "-fsyntax-only",
            "-I",
        ])
        .arg(dir)
        .arg(dir.join("unit.c"))
        .output()
        .expect("gcc runs: ./scripts/test.sh installs it");
    verdict(&output)
}

/// A compiler's verdict: its complaint when it failed.
fn verdict(output: &std::process::Output) -> Result<(), String> {
    match output.status.success() {
        true => Ok(()),
        false => Err(String::from_utf8_lossy(&output.stderr).into_owned()),
    }
}

/// `#include`s of every C layout in `dir`.
fn unit_of(dir: &Path) -> String {
    let mut headers: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with("_layout.h"))
        .collect();
    headers.sort();
    headers
        .iter()
        .map(|h| format!("#include \"{h}\"\n"))
        .collect()
}

/// Checks a crate of `lib.rs` in `dir` with rustc, no_std, every warning an
/// error.
fn compile_rust(dir: &Path, modules: &[(String, String)]) -> Result<(), String> {
    let mut lib = String::from("#![no_std]\n#![deny(warnings)]\ninclude!(\"gsdc_support.rs\");\n");
    for (module, file) in modules {
        let _ = writeln!(lib, "pub mod {module} {{\n    include!({file:?});\n}}");
    }
    std::fs::write(dir.join("lib.rs"), lib).unwrap();
    let output = Command::new(std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into()))
        .args([
            "--edition",
            "2021",
            "--crate-type",
            "lib",
            "--emit",
            "metadata",
            "--crate-name",
            "layouts",
            "-o",
        ])
        .arg(dir.join("liblayouts.rmeta"))
        .arg(dir.join("lib.rs"))
        .output()
        .expect("rustc runs");
    verdict(&output)
}

/// The layouts of mutated descriptions: each C layout in a translation unit
/// of its own (the mutations share stems), every Rust layout in one crate.
fn compile_layouts(sets: &[(String, Vec<gsdc::Artifact>)]) {
    let dir = scratch("mutated-layouts");
    let mut modules = Vec::new();
    let mut failures = Vec::new();
    for (i, (what, files)) in sets.iter().enumerate() {
        let c_dir = dir.join(format!("c{i}"));
        std::fs::create_dir_all(&c_dir).unwrap();
        for file in files {
            match file.kind {
                gsdc::ArtifactKind::CHeader | gsdc::ArtifactKind::CSupport => {
                    std::fs::write(c_dir.join(&file.file_name), &file.contents).unwrap();
                }
                gsdc::ArtifactKind::RustLayout => {
                    let name = format!("layout{i}.rs");
                    std::fs::write(dir.join(&name), &file.contents).unwrap();
                    modules.push((format!("m{i}"), name));
                }
                gsdc::ArtifactKind::RustSupport => {
                    std::fs::write(dir.join("gsdc_support.rs"), &file.contents).unwrap();
                }
                _ => {}
            }
        }
        if let Err(why) = compile_c(&c_dir, &unit_of(&c_dir)) {
            failures.push(format!("{what}: C:\n{why}"));
        }
    }
    if !modules.is_empty() {
        if let Err(why) = compile_rust(&dir, &modules) {
            failures.push(format!("the Rust layouts:\n{why}"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

// ---------------------------------------------------------------------------
// 2. What two descriptions build can be used together.

/// A description of the repository under a stem.
#[derive(Clone, Copy)]
struct Item<'a> {
    source: &'a Source,
    stem: &'static str,
}

impl Item<'_> {
    fn shown(&self) -> String {
        format!("{} as {}.toml", self.source.name, self.stem)
    }
}

/// The pairs built: every two stems, with a pair of descriptions in turn;
/// and every pair of descriptions under the stems one of whose C
/// prefixes starts the other's (`m`, `m_pkw`: a PKW module of the first is
/// named `M_PKW_PZD<n>_...`, as the `PZD<n>` module of the second is).
fn pairs(sources: &[Source]) -> Vec<(Item<'_>, Item<'_>)> {
    let n = sources.len();
    let mut pairs = Vec::new();
    let mut turn = 0;
    for (i, a) in STEMS.iter().enumerate() {
        for b in &STEMS[i + 1..] {
            turn += 1;
            let (x, y) = (&sources[turn % n], &sources[(turn * 5 + 3) % n]);
            pairs.push((Item { source: x, stem: a }, Item { source: y, stem: b }));
        }
    }
    for x in sources {
        for y in sources {
            pairs.push((
                Item {
                    source: x,
                    stem: "m",
                },
                Item {
                    source: y,
                    stem: "m_pkw",
                },
            ));
        }
    }
    pairs
}

/// What a build of two descriptions gave.
enum Built {
    /// The build refused them: they give a file, or declare a C name, of
    /// one name.
    Refused,
    /// The directory it wrote.
    Written(PathBuf),
}

/// `gsdc build a b` into a directory of its own, as a user runs it.
fn build(dir: &Path, a: Item, b: Item) -> Built {
    let _ = std::fs::remove_dir_all(dir);
    std::fs::create_dir_all(dir.join("a")).unwrap();
    std::fs::create_dir_all(dir.join("b")).unwrap();
    let mut args = vec!["build".to_string()];
    for (side, item) in [("a", a), ("b", b)] {
        let folder = dir.join(side);
        descriptions::copy_symbols(&folder);
        let file = folder.join(format!("{}.toml", item.stem));
        std::fs::write(&file, &item.source.text).unwrap();
        args.push(file.to_string_lossy().into_owned());
    }
    let out = dir.join("out");
    let output = crate::support::gsdc_command(&args)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    match output.status.code() {
        Some(0) => Built::Written(out),
        Some(1) if stderr.contains("may come from one description only") => Built::Refused,
        _ => panic!("gsdc build {} {}:\n{stderr}", a.shown(), b.shown()),
    }
}

/// The macros `header` in `dir` defines that gsdc's support header does not.
fn own_macros(
    dir: &Path,
    header: &str,
    cache: &mut BTreeMap<Vec<u8>, BTreeSet<String>>,
) -> BTreeSet<String> {
    let contents = std::fs::read(dir.join(header)).unwrap();
    if let Some(known) = cache.get(&contents) {
        return known.clone();
    }
    let defined = |include: &str| -> BTreeSet<String> {
        std::fs::write(dir.join("macros.c"), format!("#include \"{include}\"\n")).unwrap();
        let output = Command::new("gcc")
            .args(["-std=c99", "-E", "-dM", "-I"])
            .arg(dir)
            .arg(dir.join("macros.c"))
            .output()
            .expect("gcc runs");
        String::from_utf8_lossy(&output.stdout)
            .lines()
            .filter_map(|line| line.strip_prefix("#define "))
            .filter_map(|line| line.split([' ', '(']).next())
            .map(str::to_string)
            .collect()
    };
    let own: BTreeSet<String> = defined(header)
        .difference(&defined("gsdc_support.h"))
        .cloned()
        .collect();
    cache.insert(contents, own.clone());
    own
}

/// Why the C layouts in `dir` cannot be used together, if they cannot:
/// a translation unit of all of them does not compile, or two of them
/// define one macro (two identical definitions, an include guard of the
/// same name, compile without a word, and the second header is lost).
fn c_conflict(dir: &Path, cache: &mut BTreeMap<Vec<u8>, BTreeSet<String>>) -> Option<String> {
    let unit = unit_of(dir);
    if let Err(why) = compile_c(dir, &unit) {
        return Some(why);
    }
    let headers: Vec<&str> = unit
        .lines()
        .map(|l| l.trim_start_matches("#include \"").trim_end_matches('"'))
        .collect();
    let defined: Vec<BTreeSet<String>> =
        headers.iter().map(|h| own_macros(dir, h, cache)).collect();
    for (i, a) in defined.iter().enumerate() {
        for b in &defined[i + 1..] {
            let common: Vec<&String> = a.intersection(b).collect();
            if !common.is_empty() {
                return Some(format!("both define {common:?}"));
            }
        }
    }
    None
}

#[test]
fn what_two_descriptions_build_can_be_used_together() {
    let sources = sources(&VALID);
    let dir = scratch("pairs");
    let rust_dir = scratch("pairs-rust");
    let mut cache = BTreeMap::new();
    let mut rust_layouts: BTreeMap<String, (String, String)> = BTreeMap::new();
    let (mut conflicts, mut refused, mut built) = (Vec::new(), 0, 0);
    for (a, b) in pairs(&sources) {
        let out = match build(&dir.join("build"), a, b) {
            Built::Refused => {
                refused += 1;
                continue;
            }
            Built::Written(out) => out,
        };
        built += 1;
        for entry in std::fs::read_dir(&out).unwrap() {
            let path = entry.unwrap().path();
            let name = path.file_name().unwrap().to_string_lossy().into_owned();
            if name.ends_with("_layout.rs") {
                // Once per code: the stems change only the header comment.
                let contents = std::fs::read_to_string(&path).unwrap();
                let code: String = contents.lines().filter(|l| !l.starts_with("//")).collect();
                let module = format!("m{}", rust_layouts.len());
                rust_layouts.entry(code).or_insert((module, contents));
            } else if name == "gsdc_support.rs" {
                std::fs::copy(&path, rust_dir.join(name)).unwrap();
            }
        }
        if let Some(why) = c_conflict(&out, &mut cache) {
            conflicts.push(format!("{} + {}:\n{why}", a.shown(), b.shown()));
        }
    }
    eprintln!(
        "{built} pairs built, {refused} refused (a file or a C name of one name), {} Rust layouts",
        rust_layouts.len()
    );
    assert!(conflicts.is_empty(), "{}", conflicts.join("\n"));
    let modules: Vec<(String, String)> = rust_layouts
        .into_values()
        .map(|(module, contents)| {
            let file = format!("{module}.rs");
            std::fs::write(rust_dir.join(&file), contents).unwrap();
            (module, file)
        })
        .collect();
    compile_rust(&rust_dir, &modules)
        .unwrap_or_else(|why| panic!("the Rust layouts in one crate:\n{why}"));
}
