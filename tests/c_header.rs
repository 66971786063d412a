//! The C layouts gsdc writes for the shipped descriptions: snapshots
//! reviewed line by line against the Rust layouts and the manuals; all of
//! them compiled in one translation unit with gcc, and with clang where it
//! is installed, as C99, C11 and C++17 with every warning an error; and the
//! C programs `tests/c/manuals.c`, which round-trips the manuals' telegrams,
//! and `tests/c/support.c`, which tests the support header at its edges,
//! compiled the same ways and run.
//!
//! gcc and g++ must be installed (`./scripts/test.sh` installs them and
//! clang): without them these tests fail, they do not skip.

#[path = "common/descriptions.rs"]
mod descriptions;
use descriptions::load;

use gsdc::{Artifact, ArtifactKind};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::OnceLock;

const DESCRIPTIONS: [&str; 3] = ["md810dp.toml", "mv810-pnet02.toml", "9kdp1.toml"];

/// Every warning a firmware team is likely to turn on, each an error.
const WARNINGS: [&str; 9] = [
    "-Wall",
    "-Wextra",
    "-Wpedantic",
    "-Wconversion",
    "-Wsign-conversion",
    "-Wshadow",
    "-Wundef",
    "-Wcast-qual",
    "-Werror",
];

/// A compiler and the language it is asked for.
struct Build {
    compiler: &'static str,
    language: &'static [&'static str],
}

impl Build {
    fn name(&self) -> String {
        format!("{} {}", self.compiler, self.language.join(" "))
    }

    /// `compiler language warnings -O2 -I include extra`: optimised, so that
    /// the warnings which need data flow (uninitialised values) are given.
    fn command(&self, include: &Path, extra: &[&str]) -> Command {
        let mut command = Command::new(self.compiler);
        command
            .args(self.language)
            .args(WARNINGS)
            .arg("-O2")
            .arg("-I")
            .arg(include)
            .args(extra);
        command
    }
}

const BUILDS: [Build; 6] = [
    Build {
        compiler: "gcc",
        language: &["-std=c99"],
    },
    Build {
        compiler: "gcc",
        language: &["-std=c11"],
    },
    Build {
        compiler: "g++",
        language: &["-x", "c++", "-std=c++17"],
    },
    Build {
        compiler: "clang",
        language: &["-std=c99"],
    },
    Build {
        compiler: "clang",
        language: &["-std=c11"],
    },
    Build {
        compiler: "clang++",
        language: &["-x", "c++", "-std=c++17"],
    },
];

/// The builds whose compiler is installed. gcc and g++ must be; clang is
/// used where it is.
fn builds() -> Vec<&'static Build> {
    let installed = |compiler: &str| {
        Command::new(compiler)
            .arg("--version")
            .output()
            .is_ok_and(|o| o.status.success())
    };
    let mut builds = Vec::new();
    for build in &BUILDS {
        if installed(build.compiler) {
            builds.push(build);
        } else if build.compiler.starts_with('g') {
            panic!(
                "{} is not installed: ./scripts/test.sh installs it (apt-get install gcc g++ clang)",
                build.compiler
            );
        } else {
            eprintln!("{} is not installed: not compiled with it", build.compiler);
        }
    }
    builds
}

fn artifacts(name: &str) -> Vec<Artifact> {
    gsdc::compile(&load(name)).unwrap()
}

/// The text of the one artifact of `kind` that `name` gives.
fn artifact(name: &str, kind: ArtifactKind) -> (String, String) {
    let mut found = artifacts(name).into_iter().filter(|a| a.kind == kind);
    let artifact = found
        .next()
        .unwrap_or_else(|| panic!("{name}: no {kind:?}"));
    assert!(found.next().is_none(), "{name}: two {kind:?}");
    (
        artifact.file_name,
        String::from_utf8(artifact.contents).unwrap(),
    )
}

fn header(name: &str) -> String {
    artifact(name, ArtifactKind::CHeader).1
}

/// A directory of this test's own under the target directory, emptied.
fn scratch_dir(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("c-header")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Every description's C layout and the support header, written once for
/// all tests of this file, as `gsdc build` writes them.
fn include_dir() -> &'static Path {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let dir = scratch_dir("include");
        for name in DESCRIPTIONS {
            for a in artifacts(name) {
                if matches!(a.kind, ArtifactKind::CHeader | ArtifactKind::CSupport) {
                    std::fs::write(dir.join(&a.file_name), &a.contents).unwrap();
                }
            }
        }
        dir
    })
}

fn c_source(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/c")
        .join(name)
}

fn run(mut command: Command) -> Output {
    command
        .output()
        .unwrap_or_else(|e| panic!("cannot run {command:?}: {e}"))
}

#[track_caller]
fn assert_success(what: &str, output: &Output) {
    assert!(
        output.status.success(),
        "{what} failed:\n{}{}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
}

#[test]
fn md810dp_layout_snapshot() {
    insta::assert_snapshot!("md810dp_layout.h", header("md810dp.toml"));
}

#[test]
fn mv810_pnet02_layout_snapshot() {
    insta::assert_snapshot!("mv810_pnet02_layout.h", header("mv810-pnet02.toml"));
}

#[test]
fn powtran_9kdp1_layout_snapshot() {
    insta::assert_snapshot!("9kdp1_layout.h", header("9kdp1.toml"));
}

/// The support header is the same for every description, so a build of
/// several writes one.
#[test]
fn every_description_gives_the_same_support_header() {
    let support = artifact(DESCRIPTIONS[0], ArtifactKind::CSupport);
    assert_eq!(support.0, "gsdc_support.h");
    for name in &DESCRIPTIONS[1..] {
        assert_eq!(artifact(name, ArtifactKind::CSupport), support, "{name}");
    }
}

/// What the issue asks of the text: the three standard headers only, no
/// packed structs, bit fields or unions for wire data, no allocation, no
/// line past 100 columns.
#[test]
fn headers_hold_wire_data_in_byte_arrays_and_include_only_standard_headers() {
    let support = artifact(DESCRIPTIONS[0], ArtifactKind::CSupport).1;
    let includes = |text: &str| -> Vec<String> {
        text.lines()
            .filter(|l| l.starts_with("#include"))
            .map(str::to_string)
            .collect()
    };
    assert_eq!(
        includes(&support),
        [
            "#include <stdbool.h>",
            "#include <stddef.h>",
            "#include <stdint.h>"
        ]
    );
    for name in DESCRIPTIONS {
        let text = header(name);
        assert_eq!(includes(&text), ["#include \"gsdc_support.h\""], "{name}");
        for text in [&text, &support] {
            for banned in [
                "union",
                "packed",
                "#pragma",
                "__attribute__",
                "malloc",
                "free(",
            ] {
                assert!(!text.contains(banned), "{name}: {banned}");
            }
            // A bit field is `type name : width;` inside a struct.
            assert!(
                !text
                    .lines()
                    .any(|l| l.starts_with("    ") && l.contains(" : ")),
                "{name}"
            );
            let long: Vec<_> = text.lines().filter(|l| l.chars().count() > 100).collect();
            assert!(long.is_empty(), "{name}: {long:#?}");
        }
    }
}

/// Firmware for several cards includes their layouts together: one
/// translation unit with all three (one twice), freestanding, compiled by
/// every installed compiler as C99, C11 and C++17 without a warning.
#[test]
fn all_layouts_compile_together_in_one_translation_unit() {
    let include = include_dir();
    let out = scratch_dir("all-layouts");
    for (i, build) in builds().into_iter().enumerate() {
        let mut command = build.command(include, &["-ffreestanding", "-c"]);
        command
            .arg(c_source("all_layouts.c"))
            .arg("-o")
            .arg(out.join(format!("all_layouts_{i}.o")));
        assert_success(&build.name(), &run(command));
    }
}

/// The tests `tests/c/manuals.c` runs: the Rust firmware crate's, one by one.
const MANUAL_TESTS: [&str; 20] = [
    "md810_read_f0_08",
    "md810_answer_50_hz",
    "md810_write_20_hz",
    "md810_error_answers",
    "md810_illegal_telegrams_are_refused",
    "md810_ppo5_is_32_bytes",
    "md810_ppo_config_bytes",
    "md810_default_user_prm_is_f0_00_everywhere",
    "md810_user_prm_maps_dpv1_indexes",
    "md810_card_lost_the_drive_diagnosis",
    "md810_dpv1_indexes_as_a_profinet_record",
    "mv810_read_p43_02",
    "mv810_write_p43_02",
    "mv810_error_reply",
    "mv810_control_and_status_words",
    "mv810_standard_telegram_1_is_two_words",
    "mv810_mapping_records",
    "pi9000_command_word_in_ppo3",
    "pi9000_fault_code_diagnosis",
    "pi9000_default_user_prm",
];

/// The value of `key` in the GSD gsdc generates beside the MD810 layout.
fn md810_gsd_value(key: &str) -> String {
    let (_, gsd) = artifact("md810dp.toml", ArtifactKind::Gsd);
    let line = gsd
        .lines()
        .find(|l| l.starts_with(key))
        .unwrap_or_else(|| panic!("MD810DP.GSD has no {key}"));
    line.split_once('=').unwrap().1.trim().to_string()
}

/// The manuals' telegrams through the C layouts, compiled by every
/// installed compiler as C and as C++, and run: every test passes, and the
/// program ran each test the Rust firmware crate runs.
#[test]
fn the_manuals_telegrams_round_trip_in_c() {
    let defines = [
        format!(
            "-DGSD_MAX_USER_PRM_DATA_LEN={}",
            md810_gsd_value("Max_User_Prm_Data_Len")
        ),
        format!(
            "-DGSD_MAX_DIAG_DATA_LEN={}",
            md810_gsd_value("Max_Diag_Data_Len")
        ),
    ];
    compile_and_run("manuals.c", &defines, &MANUAL_TESTS);
}

/// The tests `tests/c/support.c` runs: those of the Rust support code.
const SUPPORT_TESTS: [&str; 13] = [
    "words_are_big_endian",
    "bit_fields_read_and_write_their_bits_only",
    "values_are_read_and_checked_at_their_offset",
    "reading_past_the_end_is_refused",
    "pke_no_request_ignores_what_the_master_left",
    "pke_reserved_bits_are_not_read_and_written_0",
    "pke_codes_the_manual_does_not_define_are_refused",
    "station_read_with_the_count_1",
    "station_commands_the_manual_does_not_list_are_refused",
    "station_errors_reply_0x80_plus_the_command",
    "an_area_is_its_bits_counted_from_the_byte_after_the_header",
    "an_area_across_two_bytes_has_its_first_bit_lowest",
    "a_block_too_short_loses_the_bits_past_its_end",
];

/// The support header at its edges, as the Rust support code is tested.
#[test]
fn the_support_header_holds_at_its_edges() {
    compile_and_run("support.c", &[], &SUPPORT_TESTS);
}

/// Compiles `tests/c/<source>` with every installed compiler as C and as
/// C++, runs it, and checks that it ran `tests`, in order, all passing.
fn compile_and_run(source: &str, defines: &[String], tests: &[&str]) {
    let include = include_dir();
    let out = scratch_dir(source);
    for (i, build) in builds().into_iter().enumerate() {
        let program = out.join(format!("program_{i}"));
        let mut command = build.command(include, &[]);
        command
            .args(defines)
            .arg(c_source(source))
            .arg("-o")
            .arg(&program);
        assert_success(&build.name(), &run(command));
        let output = run(Command::new(&program));
        let what = format!("{source} built by {}", build.name());
        assert_success(&what, &output);
        let stdout = String::from_utf8(output.stdout).unwrap();
        let ran: Vec<&str> = stdout
            .lines()
            .filter_map(|l| l.strip_prefix("ok "))
            .collect();
        assert_eq!(ran, tests, "{what}");
        let summary = format!("{} passed, 0 failed", tests.len());
        assert_eq!(stdout.lines().last(), Some(summary.as_str()), "{what}");
    }
}

/// The size checks are real: a check that does not hold stops every
/// compiler in every language, naming the check; the same check with the
/// right size compiles.
#[test]
fn a_size_check_that_fails_stops_the_compilation() {
    let include = include_dir();
    let dir = scratch_dir("size-check");
    let source = |bytes: u32| {
        let path = dir.join(format!("ppo5_{bytes}.c"));
        std::fs::write(
            &path,
            format!(
                "#include \"md810dp_layout.h\"\n\
                 GSDC_STATIC_ASSERT(sizeof(md810dp_ppo5_out_t) == {bytes}U, ppo5_is_{bytes}_bytes);\n"
            ),
        )
        .unwrap();
        path
    };
    let (right, wrong) = (source(32), source(31));
    for build in builds() {
        let compile = |path: &Path| {
            let mut command = build.command(include, &["-c", "-o"]);
            command.arg(dir.join("check.o")).arg(path);
            run(command)
        };
        assert_success(&build.name(), &compile(&right));
        let refused = compile(&wrong);
        let stderr = String::from_utf8_lossy(&refused.stderr);
        assert!(!refused.status.success(), "{}", build.name());
        assert!(
            stderr.contains("ppo5_is_31_bytes"),
            "{}: {stderr}",
            build.name()
        );
    }
}

/// Layouts and support written by different releases of gsdc do not compile
/// together: the layout says which support it needs.
#[test]
fn a_layout_refuses_the_support_header_of_another_release() {
    let dir = scratch_dir("other-release");
    for entry in std::fs::read_dir(include_dir()).unwrap() {
        let path = entry.unwrap().path();
        std::fs::copy(&path, dir.join(path.file_name().unwrap())).unwrap();
    }
    let support = dir.join("gsdc_support.h");
    let text = std::fs::read_to_string(&support).unwrap();
    let ours = text
        .lines()
        .find(|l| l.starts_with("#define GSDC_SUPPORT_VERSION "))
        .unwrap();
    let other = text.replace(ours, "#define GSDC_SUPPORT_VERSION 99999");
    std::fs::write(&support, other).unwrap();
    let build = &builds()[0];
    let mut command = build.command(&dir, &["-ffreestanding", "-c", "-o"]);
    command
        .arg(dir.join("all.o"))
        .arg(c_source("all_layouts.c"));
    let output = run(command);
    assert!(!output.status.success());
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("the MD810DP layout needs the gsdc_support.h that gsdc"),
        "{stderr}"
    );
}

/// The build-script API writes the C layout and its support header, and
/// nothing else.
#[test]
fn generate_c_writes_the_layout_and_its_support_header() {
    let dir = scratch_dir("generate-c");
    let description = Path::new(env!("CARGO_MANIFEST_DIR")).join("descriptions/md810dp.toml");
    let layout = gsdc::build::generate_c(&description, &dir).unwrap();
    assert_eq!(layout, dir.join("md810dp_layout.h"));
    let mut written: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    written.sort();
    assert_eq!(written, ["gsdc_support.h", "md810dp_layout.h"]);
    assert_eq!(
        std::fs::read_to_string(&layout).unwrap(),
        header("md810dp.toml")
    );
}

/// The least a PROFIBUS description can hold (no mappings, words or
/// diagnosis: User_Prm_Data of no bytes) still gives a header every
/// compiler takes: no empty struct, no unused parameter.
#[test]
fn a_description_with_the_least_in_it_gives_a_header_that_compiles() {
    let text = r#"
[device]
vendor = "Acme"
family = "X1"
model = "X1DP"
revision = "V1"
hardware_release = "V1"
software_release = "V1"
name = "X1 fieldbus card"

[telegram]
pkw = "none"
pzd_words = 2

[profibus]
file_name = "X1DP.GSD"
ident_number = { value = 0x1234 }
ppo_types = ["PPO3"]
min_slave_interval = 1
slave_family = "1"

[profibus.baud_rates]
"1.5M" = 150
"#;
    let (ir, diagnostics) = gsdc::load("bare.toml", text);
    assert!(!diagnostics.has_errors(), "{diagnostics:?}");
    let dir = scratch_dir("bare");
    for a in gsdc::compile(&ir.unwrap()).unwrap() {
        if matches!(a.kind, ArtifactKind::CHeader | ArtifactKind::CSupport) {
            std::fs::write(dir.join(&a.file_name), &a.contents).unwrap();
        }
    }
    let header = std::fs::read_to_string(dir.join("bare_layout.h")).unwrap();
    assert!(header.contains("#define BARE_USER_PRM_LEN 0U"), "{header}");
    assert!(!header.contains("bare_user_prm_t"), "{header}");
    let source = dir.join("bare.c");
    std::fs::write(&source, "#include \"bare_layout.h\"\n").unwrap();
    for build in builds() {
        let mut command = build.command(&dir, &["-c", "-o"]);
        command.arg(dir.join("bare.o")).arg(&source);
        assert_success(&build.name(), &run(command));
    }
}
