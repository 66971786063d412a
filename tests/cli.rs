//! The command line as a user runs it: exit codes, what is written, and
//! that nothing is written when a description has an error.

use crate::support::xsd::{pi_schema, refusing_schema};
use crate::support::{self, descriptions, file_names, gsdc, stderr, stdout};
use gsdc::ArtifactKind;
use std::path::{Path, PathBuf};
use std::process::Command;

#[test]
fn build_writes_the_gsd_and_exits_0() {
    let out = support::scratch("build");
    let output = gsdc([
        "build",
        "descriptions/md810dp.toml",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let written = file_names(&out);
    for expected in [
        "MD810DP.GSD",
        "GSDML-V2.32-INOVANCE-MD810-20261122.xml",
        "md810dp_layout.rs",
        "gsdc_support.rs",
        "md810dp_layout.h",
        "gsdc_support.h",
    ] {
        assert!(
            written.iter().any(|f| f == expected),
            "{expected} not in {written:?}"
        );
    }
    let written = std::fs::read(out.join("MD810DP.GSD")).unwrap();
    assert!(written.starts_with(b";====="));
    // The placeholder ident number is a warning with its place in the file.
    assert!(stderr(&output).contains("warning[W101]"));
    assert!(stderr(&output).contains("descriptions/md810dp.toml:"));

    let again = gsdc([
        "build",
        "descriptions/md810dp.toml",
        "--out",
        out.to_str().unwrap(),
    ]);
    let said = stdout(&again);
    assert!(!said.contains("wrote"), "{said}");
    assert_eq!(
        said.matches("unchanged").count(),
        file_names(&out).len(),
        "{said}"
    );
}

#[test]
fn an_invalid_description_exits_1_and_writes_nothing() {
    let dir = support::scratch("invalid");
    let out = dir.join("out");
    let output = gsdc([
        "build",
        "descriptions/md810dp.toml",
        "tests/fixtures/invalid/unknown_ppo.toml",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(output.status.code(), Some(1));
    assert!(stderr(&output).contains("error[E104]"));
    assert!(stderr(&output).contains("tests/fixtures/invalid/unknown_ppo.toml:27:22"));
    assert!(
        !out.exists(),
        "the valid description was not written either"
    );
}

#[test]
fn a_missing_description_exits_2() {
    let output = gsdc(["build", "descriptions/no-such-card.toml", "--out", "/tmp"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(stderr(&output).contains("cannot read descriptions/no-such-card.toml"));
}

#[test]
fn usage_errors_exit_2() {
    assert_eq!(gsdc(["build"]).status.code(), Some(2));
    assert_eq!(gsdc(["frobnicate"]).status.code(), Some(2));
}

#[test]
fn a_description_that_is_not_utf8_exits_1() {
    let dir = support::scratch("latin1");
    let path = dir.join("card.toml");
    std::fs::write(&path, b"[device]\nvendor = \"M\xfcller\"\n").unwrap();
    let output = gsdc([
        "build",
        path.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert_eq!(output.status.code(), Some(1));
    assert!(stderr(&output).contains("error[E000]: the description is not UTF-8 text"));
    assert!(
        stderr(&output).contains("card.toml:2:12"),
        "{}",
        stderr(&output)
    );
}

#[test]
fn check_is_0_in_step_and_1_with_a_diff_after_a_change_writing_nothing() {
    let dir = support::scratch("check");
    let out = dir.join("dist");
    let description = dir.join("md810dp.toml");
    std::fs::copy("descriptions/md810dp.toml", &description).unwrap();
    descriptions::copy_symbols(&dir);
    let (description, out_arg) = (description.to_str().unwrap(), out.to_str().unwrap());

    let missing = gsdc(["build", description, "--out", out_arg, "--check"]);
    assert_eq!(
        missing.status.code(),
        Some(1),
        "nothing built yet: out of step"
    );
    assert!(!out.exists(), "--check creates nothing");
    assert!(
        stdout(&missing).contains(&format!("missing: {}", out.join("MD810DP.bmp").display())),
        "a bitmap is named, not diffed: {}",
        stdout(&missing)
    );
    // A text file the build would add is diffed against nothing, and its
    // diff says that it is missing, not on disk.
    let gsd = out.join("MD810DP.GSD").display().to_string();
    assert!(
        stdout(&missing).contains(&format!(
            "--- {gsd} (missing)\n+++ {gsd} (from the description)\n"
        )),
        "{}",
        stdout(&missing)
    );
    assert!(
        !stdout(&missing).contains("(on disk)"),
        "{}",
        stdout(&missing)
    );

    assert_eq!(
        gsdc(["build", description, "--out", out_arg]).status.code(),
        Some(0)
    );
    let before: Vec<(String, Vec<u8>)> = file_names(&out)
        .into_iter()
        .map(|f| (f.clone(), std::fs::read(out.join(&f)).unwrap()))
        .collect();
    let in_step = gsdc(["build", description, "--out", out_arg, "--check"]);
    assert_eq!(in_step.status.code(), Some(0), "{}", stderr(&in_step));
    assert!(in_step.stdout.is_empty());

    // A changed bitmap is one line, not its bytes on the terminal.
    let bitmap = out.join("MD810DP.bmp");
    let mut bytes = std::fs::read(&bitmap).unwrap();
    bytes[100] ^= 0xFF;
    std::fs::write(&bitmap, &bytes).unwrap();
    let changed = gsdc(["build", description, "--out", out_arg, "--check"]);
    assert_eq!(changed.status.code(), Some(1));
    assert!(
        stdout(&changed).starts_with(&format!("differs: {} (not text)\n", bitmap.display())),
        "{}",
        stdout(&changed)
    );
    assert!(!changed
        .stdout
        .iter()
        .any(|b| b.is_ascii_control() && *b != b'\n'));
    bytes[100] ^= 0xFF;
    std::fs::write(&bitmap, &bytes).unwrap();

    let text = std::fs::read_to_string(description).unwrap();
    std::fs::write(
        description,
        text.replace("min_slave_interval = 1", "min_slave_interval = 2"),
    )
    .unwrap();
    let changed = gsdc(["build", description, "--out", out_arg, "--check"]);
    assert_eq!(changed.status.code(), Some(1));
    let diff = stdout(&changed);
    assert!(diff.contains(&format!("--- {gsd} (on disk)\n")), "{diff}");
    assert!(diff.contains("-Min_Slave_Intervall         = 1"), "{diff}");
    assert!(diff.contains("+Min_Slave_Intervall         = 2"), "{diff}");
    let after: Vec<(String, Vec<u8>)> = file_names(&out)
        .into_iter()
        .map(|f| (f.clone(), std::fs::read(out.join(&f)).unwrap()))
        .collect();
    assert_eq!(before, after, "--check wrote nothing");
}

#[test]
fn check_exits_0_on_a_clean_file_1_on_errors_2_when_missing() {
    let out = support::scratch("check-gsd");
    assert_eq!(
        gsdc([
            "build",
            "descriptions/md810dp.toml",
            "--out",
            out.to_str().unwrap()
        ])
        .status
        .code(),
        Some(0)
    );
    let clean = gsdc(["check", out.join("MD810DP.GSD").to_str().unwrap()]);
    assert_eq!(clean.status.code(), Some(0), "{}", stderr(&clean));
    assert!(stdout(&clean).contains("0 error(s)"));

    // Max_Input_Len beyond 244 (the corpus lists it as a known finding).
    let broken = gsdc(["check", "../shared/corpus/gsd/mbuesch__dummy_modular.gsd"]);
    assert_eq!(broken.status.code(), Some(1));
    assert!(
        stdout(&broken).contains("error[E208]"),
        "{}",
        stdout(&broken)
    );

    assert_eq!(gsdc(["check", "no-such-file.gsd"]).status.code(), Some(2));
}

#[test]
fn check_reads_gsdml_in_latin1_and_rejects_the_broken_corpus() {
    let leuze = "../shared/corpus/gsdml/GSDML-V2.31-LEUZE-BCL348i-20150923.xml";
    let clean = gsdc(["check", leuze]);
    assert_eq!(clean.status.code(), Some(0), "{}", stderr(&clean));
    let dangling = gsdc([
        "check",
        "../shared/corpus/gsdml-invalid/neg_dangling_moduleref.xml",
    ]);
    assert_eq!(dangling.status.code(), Some(1));
    assert!(
        stdout(&dangling).contains("error[E307]"),
        "{}",
        stdout(&dangling)
    );
}

/// `--format json`: one object per finding, with the fields tools need,
/// and after each file's findings a summary object (file, errors,
/// warnings) that counts them, clean files included; in the order of the
/// arguments whatever thread checked each file. The GSD file is the
/// smallest, so it is checked last (largest first), yet its findings come
/// second.
#[test]
fn check_json_lines_have_the_documented_fields_and_a_summary_per_file_in_argument_order() {
    let files = [
        "../shared/corpus/gsdml-invalid/neg_missing_textid.xml",
        "../shared/corpus/gsd/mbuesch__dummy_modular.gsd",
        "../shared/corpus/gsdml-invalid/neg_bad_datatype.xml",
        "../shared/corpus/gsdml/GSDML-V2.31-LEUZE-BCL348i-20150923.xml",
    ];
    let mut args = vec!["check", "--format", "json"];
    args.extend(files);
    let output = gsdc(&args);
    assert_eq!(output.status.code(), Some(1));
    let objects: Vec<serde_json::Value> = stdout(&output)
        .lines()
        .map(|line| serde_json::from_str(line).unwrap_or_else(|e| panic!("{e}: {line}")))
        .collect();
    let finding_fields = [
        "file", "line", "column", "severity", "code", "subject", "message", "label", "help",
    ];
    let mut summaries = Vec::new();
    let (mut errors, mut warnings) = (0, 0);
    for object in &objects {
        let keys: Vec<&str> = object
            .as_object()
            .unwrap()
            .keys()
            .map(String::as_str)
            .collect();
        if keys.contains(&"code") {
            let mut sorted = finding_fields.to_vec();
            sorted.sort_unstable();
            assert_eq!(keys, sorted, "{object}");
            match object["severity"].as_str().unwrap() {
                "error" => errors += 1,
                _ => warnings += 1,
            }
            continue;
        }
        assert_eq!(keys, ["errors", "file", "warnings"], "{object}");
        assert_eq!(object["errors"], errors, "{object} counts its findings");
        assert_eq!(object["warnings"], warnings, "{object} counts its findings");
        summaries.push(object["file"].as_str().unwrap().to_string());
        (errors, warnings) = (0, 0);
    }
    assert_eq!(summaries, files, "one summary per file, in argument order");
    assert_eq!(objects.last().unwrap()["errors"], 0, "the clean file too");
    let finding = |code: &str, subject: &str| {
        objects
            .iter()
            .any(|o| o["code"] == code && o["subject"] == subject)
    };
    assert!(finding("E208", "Max_Input_Len"), "{objects:#?}");
    assert!(finding("E309", "DataItem"), "{objects:#?}");
}

/// `--xsd DIR` adds the PI schema's findings (E399) to gsdc's own rules.
#[test]
fn check_xsd_adds_the_schemas_findings() {
    let schema = pi_schema();
    let schema = schema.to_str().unwrap();
    let broken = "../shared/corpus/gsdml-invalid/neg_bad_datatype.xml";
    let with_schema = gsdc(["check", "--xsd", schema, broken]);
    assert_eq!(with_schema.status.code(), Some(1));
    let findings = stdout(&with_schema);
    assert!(findings.contains("error[E309]"), "{findings}");
    assert!(
        findings.contains("error[E399]") && findings.contains("UInt8"),
        "{findings}"
    );
    assert!(
        !stdout(&gsdc(["check", broken])).contains("E399"),
        "no schema unless asked"
    );

    let generated = support::scratch("xsd");
    let build = gsdc([
        "build",
        "descriptions/mv810-pnet02.toml",
        "--out",
        generated.to_str().unwrap(),
    ]);
    assert_eq!(build.status.code(), Some(0));
    let gsdml = generated.join("GSDML-V2.32-MEGMEET-MV800-20230830.xml");
    let clean = gsdc(["check", "--xsd", schema, gsdml.to_str().unwrap()]);
    assert_eq!(clean.status.code(), Some(0), "{}", stdout(&clean));

    let missing = gsdc(["check", "--xsd", "/no/such/dir", broken]);
    assert_eq!(missing.status.code(), Some(2));
    assert!(stderr(&missing).contains("GSDML-DeviceProfile-v2.44.xsd is missing"));
}

/// A description with a hundred thousand errors on one 800 KB line: the
/// first hundred are shown, each with a window of the line, and the rest
/// counted; the output stays small and the run short.
#[test]
fn a_hostile_description_gives_bounded_output() {
    let dir = support::scratch("hostile");
    let path = dir.join("ppo.toml");
    let text = std::fs::read_to_string("descriptions/md810dp.toml").unwrap();
    let many = vec!["\"PPO9\""; 100_000].join(", ");
    // Without PPO5, its words would be one more error (E002).
    let hostile = text
        .replace(
            "ppo_types = [\"PPO1\", \"PPO2\", \"PPO3\", \"PPO4\", \"PPO5\"]",
            &format!("ppo_types = [{many}]"),
        )
        .replace("ppo5_pzd_words = 12\n", "");
    assert_ne!(hostile, text);
    std::fs::write(&path, hostile).unwrap();
    let started = std::time::Instant::now();
    let output = gsdc([
        "build",
        path.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert_eq!(output.status.code(), Some(1));
    // The bound catches a hang or quadratic output, not speed.
    assert!(started.elapsed().as_secs() < 20, "{:?}", started.elapsed());
    let errors = stderr(&output);
    // A hundred findings shown (the warnings found before the E104s among
    // them), every other one counted.
    let shown = errors.matches("\nerror[").count()
        + errors.matches("\nwarning[").count()
        + usize::from(errors.starts_with("error[") || errors.starts_with("warning["));
    assert_eq!(shown, 100);
    assert!(errors.matches("error[E104]").count() >= 95);
    let hidden: usize = errors
        .lines()
        .find_map(|l| {
            l.split(": ")
                .nth(1)?
                .strip_suffix(" more finding(s) not shown")
        })
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("no count of the rest: {}", &errors[errors.len() - 300..]));
    // Every E104, and the warnings the description has anyway (its
    // placeholders and marked choices).
    let (_, own) = gsdc::load("md810dp.toml", &text);
    assert_eq!(
        shown + hidden,
        100_000 + own.iter().count(),
        "{hidden} not shown"
    );
    assert!(
        errors.len() < 100_000,
        "{} bytes of diagnostics",
        errors.len()
    );
}

/// A copy of the MD810 description in `dir` under `name`, with each
/// `(from, to)` replaced (each must occur).
fn md810_copy(dir: &Path, name: &str, replacements: &[(&str, &str)]) -> PathBuf {
    let mut text = descriptions::shipped_text("md810dp.toml");
    for (from, to) in replacements {
        assert!(text.contains(from), "{from}");
        text = text.replace(from, to);
    }
    std::fs::create_dir_all(dir).unwrap();
    descriptions::copy_symbols(dir);
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

/// A description with no warning: no placeholder, nothing left to gsdc.
const NO_WARNINGS: &str = "tests/fixtures/valid/no_warnings.toml";

#[test]
fn deny_warnings_refuses_a_description_with_warnings_and_passes_one_without() {
    let dir = support::scratch("deny");
    let out = dir.join("out");
    let out_arg = out.to_str().unwrap();
    let refused = gsdc([
        "build",
        "descriptions/md810dp.toml",
        "--out",
        out_arg,
        "--deny-warnings",
    ]);
    assert_eq!(refused.status.code(), Some(1));
    let said = stderr(&refused);
    assert!(
        said.contains("warning[W101]") && said.contains("warning[W102]"),
        "{said}"
    );
    assert!(
        said.contains("nothing written") && said.contains("--deny-warnings"),
        "{said}"
    );
    assert!(!out.exists(), "nothing written, not even the directory");

    let passed = gsdc(["build", NO_WARNINGS, "--out", out_arg, "--deny-warnings"]);
    assert_eq!(passed.status.code(), Some(0), "{}", stderr(&passed));
    assert!(!stderr(&passed).contains("warning"), "{}", stderr(&passed));
    assert_eq!(file_names(&out).len(), 6);
}

/// Two descriptions that give different files of one name: exit 1 before
/// anything is written, naming both descriptions and the file. The same
/// file twice (the same description given twice) is one file.
#[test]
fn two_descriptions_giving_one_file_name_exit_1_writing_nothing() {
    let dir = support::scratch("collide");
    let out = dir.join("out");
    let out_arg = out.to_str().unwrap();
    // x-y.toml and x_y.toml both give x_y_layout.rs (and .h); the second
    // has another GSD file name, so the layouts are the only files they share.
    let dashed = md810_copy(&dir, "x-y.toml", &[]);
    let underscored = md810_copy(
        &dir,
        "x_y.toml",
        &[
            ("file_name = \"MD810DP.GSD\"", "file_name = \"OTHER.GSD\""),
            ("date = 2026-11-22", "date = 2026-11-23"),
        ],
    );
    let collided = gsdc([
        "build",
        dashed.to_str().unwrap(),
        underscored.to_str().unwrap(),
        "--out",
        out_arg,
    ]);
    assert_eq!(collided.status.code(), Some(1));
    let said = stderr(&collided);
    let expected = format!(
        "error: {} and {} both give x_y_layout.rs, with different contents",
        dashed.display(),
        underscored.display()
    );
    assert!(said.contains(&expected), "{said}");
    assert!(said.contains("both give x_y_layout.h"), "{said}");
    assert_eq!(said.matches("both give").count(), 2, "{said}");
    assert!(said.contains("nothing written"), "{said}");
    assert!(!out.exists());

    // Two descriptions with the same GSD file_name.
    let renamed = md810_copy(
        &dir,
        "other.toml",
        &[("min_slave_interval = 1", "min_slave_interval = 2")],
    );
    let collided = gsdc([
        "build",
        "descriptions/md810dp.toml",
        renamed.to_str().unwrap(),
        "--out",
        out_arg,
    ]);
    assert_eq!(collided.status.code(), Some(1));
    assert!(
        stderr(&collided).contains("both give MD810DP.GSD"),
        "{}",
        stderr(&collided)
    );
    assert!(!out.exists());

    let twice = gsdc([
        "build",
        "descriptions/md810dp.toml",
        "descriptions/md810dp.toml",
        "--out",
        out_arg,
    ]);
    assert_eq!(twice.status.code(), Some(0), "{}", stderr(&twice));
    // MD810's six files and its two symbols, once.
    assert_eq!(stdout(&twice).matches("wrote").count(), 8);
    assert_eq!(file_names(&out).len(), 8);
}

/// After a description changes its GSD's file name and its GSDML's date,
/// the files of the old names stay in `--out`: `--check` names them (exit
/// 1), a plain build leaves them, `--prune` removes them and nothing else
/// (not the user's file, not the datasheet).
#[test]
fn stale_outputs_are_reported_by_check_and_removed_by_prune() {
    let dir = support::scratch("stale");
    let out = dir.join("out");
    let out_arg = out.to_str().unwrap();
    let description = md810_copy(&dir, "md810dp.toml", &[]);
    let description = description.to_str().unwrap();
    assert_eq!(
        gsdc(["build", description, "--out", out_arg]).status.code(),
        Some(0)
    );
    std::fs::write(out.join("README.txt"), "the user's own file").unwrap();
    // The datasheet beside the files, as the README's commands put it: it
    // carries gsdc's mark, but is `gsdc doc`'s, never a build's stale file.
    let doc = gsdc(["doc", description, "--out", out_arg]);
    assert_eq!(doc.status.code(), Some(0), "{}", stderr(&doc));
    md810_copy(
        &dir,
        "md810dp.toml",
        &[
            (
                "file_name = \"MD810DP.GSD\"",
                "file_name = \"MD810DP2.GSD\"",
            ),
            ("date = 2026-11-22", "date = 2026-11-23"),
        ],
    );
    assert_eq!(
        gsdc(["build", description, "--out", out_arg]).status.code(),
        Some(0)
    );
    // The old GSD's symbol is stale with it: a bitmap has no mark, but the
    // old GSD names it.
    let old = [
        "GSDML-V2.32-INOVANCE-MD810-20261122.xml",
        "MD810DP.GSD",
        "MD810DP.bmp",
    ];
    for name in old {
        assert!(
            out.join(name).exists(),
            "a build without --prune keeps {name}"
        );
    }

    let check = gsdc(["build", description, "--out", out_arg, "--check"]);
    assert_eq!(check.status.code(), Some(1));
    let listed: Vec<String> = stdout(&check)
        .lines()
        .filter(|l| l.starts_with("stale: "))
        .map(str::to_string)
        .collect();
    assert_eq!(listed.len(), old.len(), "{listed:?}");
    for (line, name) in listed.iter().zip(old) {
        assert!(
            line.contains(&format!("{}", out.join(name).display())),
            "{line}"
        );
    }
    assert!(stderr(&check).contains("--prune"), "{}", stderr(&check));

    let pruned = gsdc(["build", description, "--out", out_arg, "--prune"]);
    assert_eq!(pruned.status.code(), Some(0), "{}", stderr(&pruned));
    for name in old {
        assert!(
            stdout(&pruned).contains(&format!("removed {} (stale)", out.join(name).display())),
            "{}",
            stdout(&pruned)
        );
    }
    assert_eq!(
        file_names(&out),
        [
            "GSDML-0A11-0810-MD810.bmp",
            "GSDML-V2.32-INOVANCE-MD810-20261123.xml",
            "MD810DP2.GSD",
            "MD810DP2.bmp",
            "README.txt",
            "gsdc_support.h",
            "gsdc_support.rs",
            "md810dp.html",
            "md810dp.md",
            "md810dp_layout.h",
            "md810dp_layout.rs"
        ]
    );
    // The datasheet is still the old description's: --check names it (not
    // as a build's stale file) until `gsdc doc` writes it again.
    let old_datasheet = gsdc(["build", description, "--out", out_arg, "--check"]);
    assert_eq!(old_datasheet.status.code(), Some(1));
    assert!(
        stdout(&old_datasheet)
            .lines()
            .all(|l| l.starts_with("stale datasheet: ")),
        "{}",
        stdout(&old_datasheet)
    );
    let doc = gsdc(["doc", description, "--out", out_arg]);
    assert_eq!(doc.status.code(), Some(0), "{}", stderr(&doc));
    let in_step = gsdc(["build", description, "--out", out_arg, "--check"]);
    assert_eq!(in_step.status.code(), Some(0), "{}", stdout(&in_step));
    assert_eq!(
        gsdc(["build", description, "--out", out_arg, "--check", "--prune"])
            .status
            .code(),
        Some(2),
        "--prune with --check is a usage error"
    );
}

/// Every file gsdc writes carries the mark `--check` and `--prune` know
/// gsdc's files by, where they look for it.
#[test]
fn every_generated_file_carries_the_generated_mark_in_its_first_kib() {
    for name in descriptions::shipped() {
        let ir = descriptions::load(&name);
        // A bitmap has no room for text: --check and --prune cannot tell
        // gsdc's device symbols from a user's (see the README).
        let files = gsdc::compile(&ir).unwrap();
        for file in files
            .iter()
            .filter(|f| f.kind != ArtifactKind::DeviceSymbol)
        {
            let head = &file.contents[..file.contents.len().min(1024)];
            let mark = gsdc::build::GENERATED_MARK.as_bytes();
            assert!(
                head.windows(mark.len()).any(|w| w == mark),
                "{} has no {:?} in its first KiB",
                file.file_name,
                gsdc::build::GENERATED_MARK
            );
        }
    }
}

/// Output that cannot be written (`> /dev/full`) is an I/O error, exit 2,
/// never exit 0 or a panic; a reader that stops early (`| head`) is not.
#[test]
fn unwritable_stdout_or_stderr_exits_2_without_a_panic() {
    let dir = support::scratch("full");
    let full = || {
        std::fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .unwrap()
    };
    let run = |args: &[&str], stdout_full: bool, stderr_full: bool| {
        let mut command = support::gsdc_command(args);
        if stdout_full {
            command.stdout(full());
        }
        if stderr_full {
            command.stderr(full());
        }
        command.output().unwrap()
    };
    let gsd = "../shared/corpus/gsd/ivangre4__SIEM8045.gse";
    let out = dir.join("out");
    let build = [
        "build",
        "descriptions/md810dp.toml",
        "--out",
        out.to_str().unwrap(),
    ];
    for (args, stdout_full, stderr_full) in [
        (&["check", gsd][..], true, false),
        (&["check", "--format", "json", gsd][..], true, false),
        (&build[..], true, false),
        (&build[..], false, true),
        (&["check", "/no/such/file.gsd"][..], false, true),
        (&["build", "/no/such/card.toml"][..], false, true),
        (&["--help"][..], true, false),
        (&["frobnicate"][..], false, true),
    ] {
        let output = run(args, stdout_full, stderr_full);
        assert_eq!(
            output.status.code(),
            Some(2),
            "{args:?}: {}",
            stderr(&output)
        );
        assert!(!stderr(&output).contains("panicked"), "{}", stderr(&output));
    }
    // The files were written all the same (MD810's six and its two
    // symbols); only the report was lost.
    assert_eq!(file_names(&out).len(), 8);

    // The corpus has files with errors: exit 1, as if all was read.
    let piped = Command::new("bash")
        .arg("-c")
        .arg(
            "\"$0\" check ../shared/corpus/gsd/*.gs? | head -c 1 >/dev/null; echo ${PIPESTATUS[0]}",
        )
        .arg(support::GSDC)
        .current_dir(support::CHECKOUT)
        .output()
        .unwrap();
    assert_eq!(stdout(&piped).trim(), "1", "{}", stderr(&piped));
    assert!(!stderr(&piped).contains("panicked"), "{}", stderr(&piped));
}

/// `build --xsd DIR` validates each GSDML against the schema before
/// anything is written: the PI schema passes every shipped description; a
/// schema the GSDML breaks refuses the build (exit 1, the findings as E399
/// diagnostics on the generated file, nothing written), whether given with
/// `--xsd` or through `GSDC_BUILD_XSD` (empty is unset); a directory
/// without the schema is a usage error.
#[test]
fn build_xsd_validates_each_gsdml_before_anything_is_written() {
    let dir = support::scratch("build-xsd");
    let out = dir.join("out");
    let out_arg = out.to_str().unwrap();
    let all = [
        "descriptions/md810dp.toml",
        "descriptions/mv810-pnet02.toml",
        "descriptions/9kdp1.toml",
    ];
    let schema = pi_schema();
    let mut args = vec!["build", "--xsd", schema.to_str().unwrap(), "--out", out_arg];
    args.extend(all);
    let passed = gsdc(&args);
    assert_eq!(passed.status.code(), Some(0), "{}", stderr(&passed));
    // md810dp: GSD, GSDML, a symbol beside each, two layouts; mv810-pnet02:
    // GSDML, symbol, two layouts; 9kdp1 (PROFIBUS only): GSD, symbol, two
    // layouts; the two support files once.
    assert_eq!(file_names(&out).len(), 6 + 4 + 4 + 2);
    std::fs::remove_dir_all(&out).unwrap();

    let refusing = refusing_schema(&dir);
    let refused = gsdc([
        "build",
        "descriptions/mv810-pnet02.toml",
        "--xsd",
        refusing.to_str().unwrap(),
        "--out",
        out_arg,
    ]);
    assert_eq!(refused.status.code(), Some(1));
    let said = stderr(&refused);
    assert!(said.contains("error[E399]"), "{said}");
    assert!(
        said.contains(
            "--> GSDML-V2.32-MEGMEET-MV800-20230830.xml (generated from descriptions/mv810-pnet02.toml):"
        ),
        "{said}"
    );
    assert!(said.contains("Element content is not allowed"), "{said}");
    assert!(said.contains("nothing written"), "{said}");
    assert!(!out.exists());

    let from_env =
        support::gsdc_command(["build", "descriptions/mv810-pnet02.toml", "--out", out_arg])
            .env(gsdc::build::XSD_ENV, &refusing)
            .output()
            .unwrap();
    assert_eq!(from_env.status.code(), Some(1), "{}", stderr(&from_env));
    assert!(stderr(&from_env).contains("error[E399]"));
    assert!(!out.exists());
    // An empty variable is unset, as build scripts read it.
    let empty_env = support::gsdc_command(["build", "descriptions/9kdp1.toml", "--out", out_arg])
        .env(gsdc::build::XSD_ENV, "")
        .output()
        .unwrap();
    assert_eq!(empty_env.status.code(), Some(0), "{}", stderr(&empty_env));
    std::fs::remove_dir_all(&out).unwrap();

    let missing = gsdc(["build", all[0], "--xsd", "/no/such/dir", "--out", out_arg]);
    assert_eq!(missing.status.code(), Some(2));
    assert!(stderr(&missing).contains("GSDML-DeviceProfile-v2.44.xsd is missing"));
    assert!(!out.exists());
}

/// The help of each command shows every flag with an example.
#[test]
fn help_shows_an_example_of_every_flag() {
    let build = stdout(&gsdc(["build", "--help"]));
    for flag in [
        "--check",
        "--prune",
        "--deny-warnings",
        "--xsd",
        "GSDC_BUILD_XSD",
    ] {
        let example = |l: &&str| {
            let l = l.trim_start();
            (l.starts_with("gsdc build") || l.starts_with("GSDC_BUILD_XSD=")) && l.contains(flag)
        };
        assert!(
            build.lines().any(|l| example(&l)),
            "no example with {flag} in {build}"
        );
    }
    let check = stdout(&gsdc(["check", "--help"]));
    for flag in ["--format json", "--xsd", "/dev/stdin"] {
        assert!(
            check
                .lines()
                .any(|l| l.contains("gsdc check") && l.contains(flag)),
            "no example with {flag} in {check}"
        );
    }
}

/// `--firmware` chooses the layouts: C only, none, or both (the default);
/// an unknown language is a usage error.
#[test]
fn firmware_languages_choose_the_layouts_written() {
    let dir = support::scratch("firmware");
    let build = |out: &str, firmware: Option<&str>| {
        let out = dir.join(out);
        let mut args = vec![
            "build",
            "descriptions/9kdp1.toml",
            "--out",
            out.to_str().unwrap(),
        ];
        if let Some(f) = firmware {
            args.extend(["--firmware", f]);
        }
        let output = gsdc(&args);
        (output, out)
    };
    let (output, out) = build("c", Some("c"));
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert_eq!(
        file_names(&out),
        ["9KDP1.GSD", "9KDP1.bmp", "9kdp1_layout.h", "gsdc_support.h"]
    );
    let (output, out) = build("none", Some("none"));
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert_eq!(file_names(&out), ["9KDP1.GSD", "9KDP1.bmp"]);
    let (output, out) = build("both", None);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert_eq!(file_names(&out).len(), 6);
    let (output, _) = build("bad", Some("rust,cobol"));
    assert_eq!(output.status.code(), Some(2));
    assert!(stderr(&output).contains("cobol"), "{}", stderr(&output));
}
