//! Every code block of README.md, wire/README.md and docs/*.md is run, compiled, loaded or
//! compared with what gsdc writes, so that no snippet can rot; a block no
//! test could take fails.
//!
//! A block is fenced, and its info string says what is done with it (the
//! first word is the language a renderer colours; an indented block has
//! no info string and is refused):
//!
//! | info string | what this module does with the block |
//! |---|---|
//! | `sh` | runs each line in bash (`pipefail`) in a scratch directory, in the order of the document: it exits 0, or N where its comment says `exit N` |
//! | `sh needs-network` | runs it in a network namespace without a network, where it must fail for want of one: the mark is true |
//! | `sh run-by=FILE` | run by that test module (a slow exchange, say): FILE is a module of the test binary and runs each command's program |
//! | `sh needs-root run-by=FILE` | the same, each command under `sudo`, and FILE says what it does without root (`cannot_run`) |
//! | `console` | runs each `$ ` line as `sh` does; what follows it is what it prints, stdout and stderr in one |
//! | `toml` | a complete description: loads without an error and compiles |
//! | `toml fragment` | tables of a description: TOML, and each table as the description's schema takes it |
//! | `LANG file=PATH` | a file of the document's example crate, which cargo builds; blocks of one path are joined, except `build.rs`, of which each block builds the crate once |
//! | `c` | a C translation unit, compiled against the C layouts of the shipped descriptions |
//! | `LANG excerpt=FILE` | lines of FILE, as gsdc writes it for a shipped description |
//! | `text tree` | each line names a folder of the checkout |
//! | `LANG not-run: REASON` | shown only, for the reason given |
//!
//! The scratch directory of the commands holds copies of `descriptions/`
//! and `tests/fixtures/`, `../shared` beside it (the PI schema, the
//! corpus), `vendor/` with the two corpus files the README names, and
//! `device.zip` holding one of them; `gsdc` is the binary under test, and
//! `cargo run [...] --` stands for it (cargo only builds it first).

use crate::support::descriptions::{self, guide_examples};
use crate::support::{self, cannot_run, checkout, scratch, shared, Scratch};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

// ---------------------------------------------------------------------------
// The blocks

/// A fenced block of a document.
#[derive(Debug)]
struct Block {
    /// `README.md:40`: where the block opens.
    place: String,
    /// The info string after the opening fence.
    info: String,
    text: String,
}

/// What the tests do with a block: its info string, read.
#[derive(Debug, PartialEq, Eq)]
enum Use<'a> {
    Run,
    NeedsNetwork,
    RunBy { file: &'a str, root: bool },
    Console,
    Description,
    Fragment,
    File(&'a str),
    C,
    Excerpt(&'a str),
    Tree,
    NotRun,
}

impl Block {
    fn use_(&self) -> Result<Use<'_>, String> {
        let (language, mark) = self
            .info
            .split_once(' ')
            .unwrap_or((self.info.as_str(), ""));
        if let Some(reason) = mark.strip_prefix("not-run:") {
            return match reason.trim() {
                "" => Err(format!("{}: not-run without a reason", self.place)),
                _ => Ok(Use::NotRun),
            };
        }
        if let Some(path) = mark.strip_prefix("file=") {
            return Ok(Use::File(path));
        }
        if let Some(file) = mark.strip_prefix("excerpt=") {
            return Ok(Use::Excerpt(file));
        }
        if let Some(file) = mark.strip_prefix("run-by=") {
            return Ok(Use::RunBy { file, root: false });
        }
        if let Some(file) = mark.strip_prefix("needs-root run-by=") {
            return Ok(Use::RunBy { file, root: true });
        }
        match (language, mark) {
            ("sh", "") => Ok(Use::Run),
            ("sh", "needs-network") => Ok(Use::NeedsNetwork),
            ("console", "") => Ok(Use::Console),
            ("toml", "") => Ok(Use::Description),
            ("toml", "fragment") => Ok(Use::Fragment),
            ("c", "") => Ok(Use::C),
            ("text", "tree") => Ok(Use::Tree),
            _ => Err(format!(
                "{}: ```{} says nothing this test does (tests/docs.rs lists the marks)",
                self.place, self.info
            )),
        }
    }
}

/// The fenced blocks of a document; an indented code block, which has no
/// place for a mark, or a fence never closed, is an error.
fn blocks_of(name: &str, text: &str) -> Result<Vec<Block>, String> {
    let lines: Vec<&str> = text.lines().collect();
    let mut blocks = Vec::new();
    let mut open: Option<(usize, &str)> = None;
    let mut body = String::new();
    for (i, line) in lines.iter().enumerate() {
        match (open, line.strip_prefix("```")) {
            (None, Some(info)) => {
                open = Some((i, info.trim()));
                body.clear();
            }
            (Some((at, info)), Some("")) => {
                blocks.push(Block {
                    place: format!("{name}:{}", at + 1),
                    info: info.to_string(),
                    text: std::mem::take(&mut body),
                });
                open = None;
            }
            (Some(_), _) => {
                body.push_str(line);
                body.push('\n');
            }
            (None, None) if starts_indented_block(&lines, i) => {
                return Err(format!(
                    "{name}:{}: an indented code block; fence it with its mark (tests/docs.rs)",
                    i + 1
                ));
            }
            (None, None) => {}
        }
    }
    match open {
        Some((at, _)) => Err(format!("{name}:{}: a fence never closed", at + 1)),
        None => Ok(blocks),
    }
}

/// Whether line `i` opens an indented code block: four blanks after a
/// blank line, not a list item's indented paragraph.
fn starts_indented_block(lines: &[&str], i: usize) -> bool {
    let after_blank = i > 0 && lines[i - 1].trim().is_empty();
    let in_list = lines[..i]
        .iter()
        .rev()
        .find(|l| !l.trim().is_empty())
        .is_some_and(|l| {
            let l = l.trim_start();
            l.starts_with("- ")
                || l.starts_with("* ")
                || l.split_once(". ")
                    .is_some_and(|(n, _)| n.parse::<u32>().is_ok())
        });
    lines[i].starts_with("    ") && !lines[i].trim().is_empty() && after_blank && !in_list
}

/// README.md, wire/README.md and every document in docs/, by name.
fn documents() -> Vec<(String, String)> {
    let mut names = vec!["README.md".to_string(), "wire/README.md".to_string()];
    let mut docs: Vec<String> = std::fs::read_dir(checkout("docs"))
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|n| n.ends_with(".md"))
        .map(|n| format!("docs/{n}"))
        .collect();
    docs.sort();
    names.extend(docs);
    names
        .into_iter()
        .map(|n| {
            let text = std::fs::read_to_string(checkout(&n)).unwrap();
            (n, text)
        })
        .collect()
}

/// Every block of every document, by document.
fn all_blocks() -> Vec<(String, Vec<Block>)> {
    documents()
        .into_iter()
        .map(|(name, text)| {
            let blocks = blocks_of(&name, &text).unwrap_or_else(|e| panic!("{e}"));
            (name, blocks)
        })
        .collect()
}

/// The blocks of `use_` (by its kind), in document order.
fn blocks_for(wanted: fn(&Use) -> bool) -> Vec<Block> {
    all_blocks()
        .into_iter()
        .flat_map(|(_, blocks)| blocks)
        .filter(|b| b.use_().is_ok_and(|u| wanted(&u)))
        .collect()
}

#[test]
fn every_block_is_fenced_and_marked_with_what_is_done_with_it() {
    let mut count = 0;
    for (_, blocks) in all_blocks() {
        for block in &blocks {
            block.use_().unwrap_or_else(|e| panic!("{e}"));
            count += 1;
        }
    }
    assert!(count > 80, "{count} blocks");
}

#[test]
fn an_indented_or_unmarked_block_is_refused() {
    let indented = "Run this:\n\n    gsdc build x.toml\n";
    assert!(blocks_of("x.md", indented).unwrap_err().contains("x.md:3"));
    // A list item's indented paragraph is no code block.
    let list = "- an item\n\n    its second paragraph\n";
    assert!(blocks_of("x.md", list).unwrap().is_empty());
    let unmarked = "```\ngsdc build x.toml\n```\n";
    let blocks = blocks_of("x.md", unmarked).unwrap();
    assert!(blocks[0].use_().is_err());
    let no_reason = "```sh not-run:\nrm -rf /\n```\n";
    assert!(blocks_of("x.md", no_reason).unwrap()[0].use_().is_err());
    let unclosed = "```sh\ngsdc build x.toml\n";
    assert!(blocks_of("x.md", unclosed).is_err());
}

// ---------------------------------------------------------------------------
// Commands

/// `gsdc build x.toml   # exit 1: ...`: the command, and the comment after
/// the first `#` outside single quotes that follows a blank.
fn split_comment(line: &str) -> (&str, &str) {
    let mut quoted = false;
    let mut previous = ' ';
    for (i, c) in line.char_indices() {
        match c {
            '\'' => quoted = !quoted,
            '#' if !quoted && previous.is_whitespace() => {
                return (line[..i].trim_end(), &line[i + 1..]);
            }
            _ => {}
        }
        previous = c;
    }
    (line.trim_end(), "")
}

/// The exit code a command's comment documents (`exit 1`), else 0.
fn documented_exit(comment: &str) -> i32 {
    comment
        .split("exit ")
        .skip(1)
        .find_map(|rest| {
            let digits: String = rest.chars().take_while(char::is_ascii_digit).collect();
            digits.parse().ok()
        })
        .unwrap_or(0)
}

/// The command as the test runs it: `cargo run [...] -- ARGS` is gsdc.
fn as_run(command: &str) -> String {
    match command.strip_prefix("cargo run ") {
        Some(rest) => {
            let (_, args) = rest.split_once("-- ").expect("cargo run ... -- ARGS");
            format!("gsdc {args}")
        }
        None => command.to_string(),
    }
}

/// A scratch directory set up as the module's doc says, and the folder the
/// commands run in.
struct CommandDir {
    _scratch: Scratch,
    work: PathBuf,
    bin: PathBuf,
}

impl CommandDir {
    /// `None` (said by `cannot_run`) when `zip` is missing.
    #[track_caller]
    fn new(name: &str) -> Option<CommandDir> {
        let dir = scratch(name);
        let work = dir.join("work");
        copy_tree(&checkout("descriptions"), &work.join("descriptions"));
        copy_tree(&checkout("tests/fixtures"), &work.join("tests/fixtures"));
        std::os::unix::fs::symlink(shared("").canonicalize().unwrap(), dir.join("shared")).unwrap();
        let vendor = work.join("vendor");
        std::fs::create_dir_all(&vendor).unwrap();
        for (from, to) in [
            ("gsd/ivangre4__SIEM8045.gse", "SIEM8045.GSE"),
            (
                "gsdml/GSDML-V2.33-ABB-FENA-20170914.xml",
                "GSDML-V2.33-ABB-FENA-20170914.xml",
            ),
        ] {
            std::fs::write(vendor.join(to), support::corpus_file(from)).unwrap();
        }
        let bin = dir.join("bin");
        std::fs::create_dir_all(&bin).unwrap();
        std::os::unix::fs::symlink(support::GSDC, bin.join("gsdc")).unwrap();
        let zipped = Command::new("zip")
            .args([
                "-q",
                "-j",
                "device.zip",
                "vendor/GSDML-V2.33-ABB-FENA-20170914.xml",
            ])
            .current_dir(&work)
            .status();
        if !zipped.is_ok_and(|s| s.success()) {
            cannot_run("zip is missing (./scripts/test.sh installs it)");
            return None;
        }
        Some(CommandDir {
            _scratch: dir,
            work,
            bin,
        })
    }

    /// `command` in bash, in the folder, with gsdc first on the PATH.
    fn run(&self, command: &str) -> Output {
        let path = format!(
            "{}:{}",
            self.bin.display(),
            std::env::var("PATH").unwrap_or_default()
        );
        Command::new("bash")
            .args(["-o", "pipefail", "-c", command])
            .current_dir(&self.work)
            .env("PATH", path)
            .output()
            .unwrap_or_else(|e| panic!("cannot run bash: {e}"))
    }
}

fn copy_tree(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let entry = entry.unwrap();
        let target = to.join(entry.file_name());
        if entry.file_type().unwrap().is_dir() {
            copy_tree(&entry.path(), &target);
        } else {
            std::fs::copy(entry.path(), target).unwrap();
        }
    }
}

fn said(output: &Output) -> String {
    format!(
        "{}{}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    )
}

/// A `sh` block's lines, each with the exit code it documents.
fn run_sh(dir: &CommandDir, block: &Block) {
    for line in block.text.lines().filter(|l| !l.trim().is_empty()) {
        let (command, comment) = split_comment(line);
        let output = dir.run(&as_run(command));
        assert_eq!(
            output.status.code(),
            Some(documented_exit(comment)),
            "{}: `{line}` printed\n{}",
            block.place,
            said(&output)
        );
    }
}

/// A `console` block: each `$ ` command and what it prints.
fn run_console(dir: &CommandDir, block: &Block) {
    let mut runs: Vec<(&str, String)> = Vec::new();
    for line in block.text.lines() {
        match line.strip_prefix("$ ") {
            Some(command) => runs.push((command, String::new())),
            None => {
                let (_, printed) = runs.last_mut().expect("a console block starts with `$ `");
                printed.push_str(line);
                printed.push('\n');
            }
        }
    }
    for (line, expected) in runs {
        let (command, comment) = split_comment(line);
        let output = dir.run(&format!("exec 2>&1; {}", as_run(command)));
        assert_eq!(said(&output), expected, "{}: `{line}`", block.place);
        assert_eq!(
            output.status.code(),
            Some(documented_exit(comment)),
            "{}: `{line}`",
            block.place
        );
    }
}

/// The commands of every document run in order, each document in a
/// directory of its own, with the exit codes and output it documents.
#[test]
fn the_commands_run_as_the_documents_say() {
    let mut ran = 0;
    for (name, blocks) in all_blocks() {
        let commands: Vec<&Block> = blocks
            .iter()
            .filter(|b| matches!(b.use_(), Ok(Use::Run | Use::Console)))
            .collect();
        if commands.is_empty() {
            continue;
        }
        let Some(dir) = CommandDir::new(&name.replace(['/', '.'], "-")) else {
            return;
        };
        for block in commands {
            match block.use_() {
                Ok(Use::Run) => run_sh(&dir, block),
                _ => run_console(&dir, block),
            }
            ran += 1;
        }
    }
    assert!(ran >= 12, "{ran} blocks ran");
}

/// A command marked as needing the network fails without one, saying so:
/// the mark is true. (It is not run with one: a test does not install
/// from the network.)
#[test]
fn a_command_marked_as_needing_the_network_fails_without_one() {
    let blocks = blocks_for(|u| *u == Use::NeedsNetwork);
    assert!(!blocks.is_empty());
    let cargo_home = scratch("cargo-home");
    for block in blocks {
        for line in block.text.lines().filter(|l| !l.trim().is_empty()) {
            let (command, _) = split_comment(line);
            // Root makes a network namespace; others a user namespace too.
            let unshare: &[&str] =
                match support::succeeds(Command::new("unshare").args(["--net", "true"])) {
                    true => &["--net"],
                    false => &["--user", "--map-root-user", "--net"],
                };
            let output = Command::new("unshare")
                .args(unshare)
                .args(["bash", "-c", command])
                .env("CARGO_HOME", &*cargo_home)
                .env("CARGO_NET_RETRY", "0")
                .output();
            let Ok(output) = output else {
                cannot_run("unshare is missing (util-linux)");
                return;
            };
            let said = said(&output);
            if said.contains("unshare:") {
                cannot_run(&format!("no network namespace here: {said}"));
                return;
            }
            assert!(
                !output.status.success(),
                "{}: `{line}` ran without a network",
                block.place
            );
            assert!(
                ["resolve", "network", "connect"]
                    .iter()
                    .any(|w| said.contains(w)),
                "{}: `{line}` failed for another reason than the network:\n{said}",
                block.place
            );
        }
    }
}

/// A block another test module runs: that module is part of the test
/// binary and runs the program of each command (a command under `sudo`
/// when the block needs root, and the module says what it does without
/// root).
#[test]
fn a_block_run_by_another_test_is_run_by_it() {
    let blocks = blocks_for(|u| matches!(u, Use::RunBy { .. }));
    assert!(blocks.len() >= 2);
    let modules = std::fs::read_to_string(checkout("tests/tests.rs")).unwrap();
    for block in blocks {
        let Ok(Use::RunBy { file, root }) = block.use_() else {
            unreachable!()
        };
        let module = file
            .strip_prefix("tests/")
            .and_then(|f| f.strip_suffix(".rs"))
            .unwrap_or_else(|| panic!("{}: {file} is not a test module", block.place));
        assert!(
            modules.contains(&format!("\nmod {module};\n")),
            "{}: {file} is not a module of the test binary",
            block.place
        );
        let test = std::fs::read_to_string(checkout(file)).unwrap();
        for line in block.text.lines().filter(|l| !l.trim().is_empty()) {
            let (command, _) = split_comment(line);
            let command = match root {
                true => command
                    .strip_prefix("sudo ")
                    .unwrap_or_else(|| panic!("{}: `{line}` needs root: sudo", block.place)),
                false => command,
            };
            let program = command.split_whitespace().next().unwrap();
            assert!(
                test.contains(program),
                "{}: {file} does not run {program}",
                block.place
            );
        }
        if root {
            assert!(
                test.contains("cannot_run"),
                "{}: {file} says nothing without root",
                block.place
            );
        }
    }
}

// ---------------------------------------------------------------------------
// Descriptions

fn compiled(example: &str) -> gsdc::Ir {
    let (ir, diagnostics) = gsdc::load("example.toml", example);
    let errors: Vec<_> = diagnostics.errors().collect();
    assert!(errors.is_empty(), "{errors:#?}");
    let ir = ir.unwrap();
    gsdc::compile(&ir).expect("the example compiles");
    ir
}

#[test]
fn every_description_loads_and_compiles_and_every_fragment_fits_the_format() {
    let descriptions = blocks_for(|u| *u == Use::Description);
    assert!(descriptions.len() >= 2);
    for block in &descriptions {
        compiled(&block.text);
    }
    let schema = crate::description_schema::schema();
    let fragments = blocks_for(|u| *u == Use::Fragment);
    assert!(!fragments.is_empty());
    for block in fragments {
        let tables: toml::Table = block
            .text
            .parse()
            .unwrap_or_else(|e| panic!("{}: {e}", block.place));
        for (key, value) in tables {
            let node = &schema["properties"][&key];
            assert!(
                !node.is_null(),
                "{}: no table `{key}` in a description",
                block.place
            );
            crate::description_schema::conforms(&schema, node, &value)
                .unwrap_or_else(|why| panic!("{}: [{key}]: {why}", block.place));
        }
    }
}

#[test]
fn the_guides_example_compiles() {
    let ir = compiled(guide_examples()[0]);
    assert!(ir.profibus.is_some() && ir.profinet.is_some());
}

/// The gateway's example is the MD810 manual's: 120 words of TPDO (240
/// bytes of input) and 64 words of RPDO (128 bytes of output).
#[test]
fn the_gateway_example_compiles_with_the_manuals_totals() {
    let ir = compiled(guide_examples()[1]);
    let gateway = ir.gateway.unwrap();
    let in_use = &gateway.nodes[..usize::from(gateway.node_count.default)];
    let words = |direction| -> u16 {
        in_use
            .iter()
            .map(|n| u16::from(n.words(direction).default))
            .sum()
    };
    use gsdc::ir::Direction::{In, Out};
    assert_eq!((2 * words(In), 2 * words(Out)), (240, 128));
}

// ---------------------------------------------------------------------------
// Code

/// A document's example crate: the document, its files (path and text) but
/// the build script, and each version of its build script.
struct ExampleCrate {
    document: String,
    files: Vec<(String, String)>,
    build_scripts: Vec<Block>,
}

/// The example crate of each document that has one: the blocks of each
/// path joined, and each `build.rs` block apart.
fn example_crates() -> Vec<ExampleCrate> {
    let mut crates = Vec::new();
    for (name, blocks) in all_blocks() {
        let mut files: Vec<(String, String)> = Vec::new();
        let mut build_scripts = Vec::new();
        for block in blocks {
            let Ok(Use::File(path)) = block.use_() else {
                continue;
            };
            let path = path.to_string();
            if path == "build.rs" {
                build_scripts.push(block);
            } else if let Some((_, text)) = files.iter_mut().find(|(p, _)| *p == path) {
                text.push('\n');
                text.push_str(&block.text);
            } else {
                files.push((path, block.text));
            }
        }
        if !files.is_empty() || !build_scripts.is_empty() {
            crates.push(ExampleCrate {
                document: name,
                files,
                build_scripts,
            });
        }
    }
    crates
}

/// Each document's example crate, beside a `gsdc` that is this checkout and
/// with the shipped descriptions, built by cargo (any warning an error)
/// once with each of its build scripts.
#[test]
fn the_example_crates_build() {
    let crates = example_crates();
    assert!(!crates.is_empty());
    // Kept from run to run, as a target directory is.
    let target = Path::new(env!("CARGO_TARGET_TMPDIR")).join("docs-crate-target");
    for ExampleCrate {
        document: name,
        files,
        build_scripts,
    } in crates
    {
        assert!(
            !build_scripts.is_empty(),
            "{name}: a crate without build.rs"
        );
        let dir = scratch(&format!("crate-{}", name.replace(['/', '.'], "-")));
        std::os::unix::fs::symlink(checkout(""), dir.join("gsdc")).unwrap();
        let root = dir.join("firmware");
        for (path, text) in &files {
            let file = root.join(path);
            std::fs::create_dir_all(file.parent().unwrap()).unwrap();
            std::fs::write(file, text).unwrap();
        }
        copy_tree(&checkout("descriptions"), &root.join("descriptions"));
        std::fs::copy(
            checkout("tests/firmware/Cargo.lock"),
            root.join("Cargo.lock"),
        )
        .unwrap();
        for build_script in build_scripts {
            std::fs::write(root.join("build.rs"), &build_script.text).unwrap();
            let output = Command::new(env!("CARGO"))
                .args(["build", "--offline", "--quiet"])
                .current_dir(&root)
                .env("CARGO_TARGET_DIR", &target)
                .env("RUSTFLAGS", "-D warnings")
                .output()
                .expect("cargo runs");
            assert!(
                output.status.success(),
                "{name}: the crate with the build script of {}:\n{}",
                build_script.place,
                said(&output)
            );
        }
    }
}

/// Each C block, compiled against the C layouts of the shipped
/// descriptions as tests/c_header.rs compiles its programs.
#[test]
fn the_c_blocks_compile() {
    let blocks = blocks_for(|u| *u == Use::C);
    assert!(blocks.len() >= 2);
    if !support::succeeds(Command::new("cc").arg("--version")) {
        cannot_run("no C compiler (./scripts/test.sh installs gcc)");
        return;
    }
    let dir = scratch("c-blocks");
    for name in descriptions::shipped() {
        gsdc::build::generate_c(checkout("descriptions").join(name), &*dir).unwrap();
    }
    for (i, block) in blocks.iter().enumerate() {
        let source = dir.join(format!("block{i}.c"));
        std::fs::write(&source, &block.text).unwrap();
        let output = Command::new("cc")
            .args(["-std=c99", "-Wall", "-Wextra", "-Wpedantic", "-Wconversion"])
            .args(["-Wsign-conversion", "-Werror", "-c", "-o"])
            .arg(dir.join(format!("block{i}.o")))
            .arg("-I")
            .arg(&*dir)
            .arg(&source)
            .output()
            .unwrap();
        assert!(
            output.status.success(),
            "{}:\n{}",
            block.place,
            said(&output)
        );
    }
}

// ---------------------------------------------------------------------------
// Excerpts and names

/// Every file gsdc makes of the shipped descriptions (and the datasheets).
fn shipped_outputs() -> Vec<gsdc::Artifact> {
    descriptions::load_shipped()
        .iter()
        .flat_map(|(_, ir)| descriptions::outputs(ir))
        .collect()
}

#[test]
fn each_excerpt_is_what_gsdc_writes() {
    let blocks: Vec<Block> = blocks_for(|u| matches!(u, Use::Excerpt(_)));
    assert!(!blocks.is_empty());
    let outputs = shipped_outputs();
    for block in &blocks {
        let Ok(Use::Excerpt(file)) = block.use_() else {
            unreachable!()
        };
        let output = outputs
            .iter()
            .find(|a| a.file_name == file)
            .unwrap_or_else(|| panic!("{}: no shipped description gives {file}", block.place));
        let text = String::from_utf8(output.contents.clone()).unwrap();
        for line in block.text.lines() {
            assert!(
                text.lines().any(|l| l == line),
                "{}: not a line of {file}: {line}",
                block.place
            );
        }
    }
}

#[test]
fn each_tree_names_folders_of_the_checkout() {
    let blocks = blocks_for(|u| *u == Use::Tree);
    assert!(!blocks.is_empty());
    for block in blocks {
        for line in block.text.lines() {
            let folder = line.split_whitespace().next().unwrap();
            assert!(
                checkout(folder).is_dir(),
                "{}: no folder {folder}",
                block.place
            );
        }
    }
}

/// The GSD and GSDML files the README's prose names are files a shipped
/// description gives (`dist/` is where the README builds them), or corpus
/// files.
#[test]
fn the_device_files_the_readme_names_exist() {
    let readme = std::fs::read_to_string(checkout("README.md")).unwrap();
    let given: Vec<String> = shipped_outputs().into_iter().map(|a| a.file_name).collect();
    let corpus: Vec<String> = ["corpus/gsd", "corpus/gsdml"]
        .iter()
        .flat_map(|folder| std::fs::read_dir(shared(folder)).unwrap())
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    let mut named = 0;
    let mut in_block = false;
    for line in readme.lines() {
        in_block ^= line.starts_with("```");
        if in_block {
            continue;
        }
        for quoted in line.split('`').skip(1).step_by(2) {
            let name = quoted.strip_prefix("dist/").unwrap_or(quoted);
            let device_file = [".GSD", ".gsd", ".xml"].iter().any(|e| name.ends_with(e));
            if !device_file || name.contains(' ') {
                continue;
            }
            assert!(
                given.iter().chain(&corpus).any(|f| f == name),
                "README.md names {name}, which no shipped description gives"
            );
            named += 1;
        }
    }
    assert!(named >= 5, "{named}");
}
