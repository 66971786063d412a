//! gsdc's integration tests: one test binary (Cargo.toml has
//! `autotests = false` and this one `[[test]]`), whose modules are the
//! files of `tests/`, so cargo links once, not once per file.
//!
//! # Where a new test goes
//!
//! Into the module of what it tests (`cli.rs` for the command line,
//! `gsd_output.rs` for the GSD gsdc writes, ...). A new area is a new file
//! `tests/<area>.rs` and one line here, `mod <area>;`, in name order; the
//! file starts with a `//!` line that says what it tests. Run one module
//! with `cargo test --test tests <area>::`.
//!
//! # Snapshots
//!
//! - `outputs.rs`: every file gsdc makes (`gsdc::compile` and
//!   `gsdc::document`) of every shipped description (`descriptions/*.toml`)
//!   and every valid fixture (`tests/fixtures/valid/*.toml`), found in those
//!   folders, never listed: a new description, fixture or kind of output
//!   needs no test code. Each file is one snapshot,
//!   `tests/snapshots/outputs/<file name>.snap`.
//! - `invalid_descriptions.rs`: the diagnostics of every invalid fixture
//!   (`tests/fixtures/invalid/*.toml`, each with its `# expect: CODE` line),
//!   `tests/snapshots/invalid/<fixture>.snap`.
//! - `check_snapshots.rs` (`gsdc check` on chosen corpus files) and
//!   `cli_decode.rs` (chosen `gsdc decode` runs) name theirs.
//!
//! A new or changed snapshot fails the test until it is read and accepted:
//! `cargo insta review`, or `INSTA_UPDATE=always cargo test` and the diff
//! read in git. A snapshot is a claim that the output is right. A snapshot
//! no test takes any more (a removed description) fails the test that owns
//! its folder.
//!
//! # The support module
//!
//! `support` holds what tests share; use it rather than writing your own:
//!
//! - `support::gsdc(["check", "x.gsd"])` runs the gsdc binary in the
//!   checkout and returns its `Output`; `support::stdout(&output)` and
//!   `support::stderr(&output)` its text; `support::gsdc_command(args)` a
//!   `Command` to add stdin, an environment or `spawn` to;
//!   `support::wait_within(&mut child, limit, what)` waits for a spawned
//!   one, and fails the test as a hang past `limit`.
//! - `support::scratch("name")`: a fresh directory of the test's own in
//!   `target/tmp`, removed when the test passes, kept when it fails.
//! - `support::checkout("descriptions")`, `support::shared("corpus/gsd")`,
//!   `support::corpus_file("gsd/x.gsd")`: where things are.
//! - `support::descriptions`: `shipped()`, `load(name)`, `load_text(name,
//!   text)`, `all_valid()`, `invalid_fixtures()`, `outputs(&ir)` (every file
//!   gsdc makes of it), `one(files, kind)` (the one file of a kind),
//!   `copy_symbols(dir)`.
//! - `support::xsd`: `validate(xml)` against the PI schema, `pi_schema()`,
//!   `refusing_schema(dir)`.
//! - `support::cannot_run(why)`: a test that lacks what it needs here (a
//!   mount, `chattr`, a compiler) calls it and leaves the case out; under CI
//!   (`CI=true`) it fails instead, so no test skips there.
//!   `./scripts/test.sh` installs the packages the tests need.
//!   No test takes the `ignore` attribute (`suite.rs` checks it).
//! - `support::ran_in_own_process()`: for a test that changes what the
//!   whole process shares (an environment variable); it runs alone in a
//!   process of its own.
//! - `support::snapshots_in(folder, || ...)` and
//!   `support::assert_no_orphan_snapshots(folder, names)`: snapshots in a
//!   folder of `tests/snapshots/` of their own, named by the test.
//!
//! `tests/firmware` (a no_std crate built from the layouts) and `tests/c`
//! (C programs built from the C layouts) are not modules: `generated_rust.rs`
//! and `c_header.rs` build and run them; `wire_dp.rs` and `wire_pn.rs` build
//! and run the workspace `wire/` (the DP and PROFINET exchanges on the
//! wire).

mod support;

mod adversarial;
mod build_api;
mod build_env;
mod c_header;
mod check_files;
mod check_snapshots;
mod cli;
mod cli_decode;
mod datasheet;
mod datasheet_browser;
mod decisions;
mod description_schema;
mod device_symbol;
mod device_tables_c;
mod diff;
mod diff_corpus;
mod diff_release;
mod docs;
mod draft_notice;
mod file_names;
mod gateway_description;
mod generated_rust;
mod gsd_output;
mod gsd_reader;
mod gsdml_output;
mod gsdml_reader;
mod hostile_input;
mod hostile_limits;
mod hostile_properties;
mod import;
mod import_cycles;
mod invalid_descriptions;
mod languages;
mod limits;
mod manual_texts;
mod output_safety;
mod outputs;
mod pn_daps;
mod properties;
mod rule_docs;
mod suite;
mod user_build;
mod user_decode;
mod user_description;
mod wire_dp;
mod wire_pn;
mod xsd;
