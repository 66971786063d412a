//! The C layouts gsdc writes for the shipped descriptions (their
//! snapshots, reviewed line by line against the Rust layouts and the
//! manuals, are in outputs.rs): all of them compiled in one translation
//! unit with gcc and clang as C99, C11 and C++17 with every warning an
//! error; and the C programs `tests/c/manuals.c`, which round-trips the
//! manuals' telegrams, and `tests/c/support.c`, which tests the support
//! header at its edges, compiled the same ways and run.
//!
//! gcc and g++ must be installed (`./scripts/test.sh` installs them and
//! clang): without them these tests fail, they do not skip. Without clang
//! they leave its builds out, and fail under CI.

use crate::support::descriptions::{self, load};
use crate::support::{self, Scratch};
use gsdc::{Artifact, ArtifactKind};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

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
/// used where it is, and must be under CI.
fn builds() -> Vec<&'static Build> {
    let installed = |compiler: &str| support::succeeds(Command::new(compiler).arg("--version"));
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
            support::cannot_run(&format!(
                "{} is not installed: not compiled with it",
                build.compiler
            ));
        }
    }
    builds
}

fn artifacts(name: &str) -> Vec<Artifact> {
    gsdc::compile(&load(name)).unwrap()
}

/// The text of the one artifact of `kind` that `name` gives.
fn artifact(name: &str, kind: ArtifactKind) -> (String, String) {
    descriptions::one(artifacts(name), kind)
}

fn header(name: &str) -> String {
    artifact(name, ArtifactKind::CHeader).1
}

/// Every shipped description's C layout, the PROFIdrive fixture's, and the
/// support header, written as `gsdc build` writes them into a scratch
/// directory `<test>-include`.
fn include_dir(test: &str) -> Scratch {
    let dir = support::scratch(&format!("{test}-include"));
    let fixture = (
        "profidrive.toml".to_string(),
        descriptions::load_from("tests/fixtures/valid", "profidrive.toml"),
    );
    let irs: Vec<(String, gsdc::Ir)> = descriptions::shipped()
        .into_iter()
        .map(|name| {
            let ir = load(&name);
            (name, ir)
        })
        .chain([fixture])
        .collect();
    for (_, ir) in &irs {
        for a in gsdc::compile(ir).unwrap() {
            if matches!(a.kind, ArtifactKind::CHeader | ArtifactKind::CSupport) {
                std::fs::write(dir.join(&a.file_name), &a.contents).unwrap();
            }
        }
    }
    std::fs::write(dir.join("examples.h"), examples_header(&irs)).unwrap();
    dir
}

/// `examples.h`: every telegram of every worked example the descriptions
/// give (`[[examples]]`), for tests/c/manuals.c to round-trip through the
/// C layouts' PKW codecs.
fn examples_header(irs: &[(String, gsdc::Ir)]) -> String {
    use gsdc::ir::PkwKind;
    let mut rows = Vec::new();
    for (name, ir) in irs {
        for example in &ir.examples {
            let codec = match ir.telegram.pkw {
                PkwKind::PkeIndPwe => "EXAMPLE_PKE",
                PkwKind::StationCommandAddressValue => "EXAMPLE_STATION",
                other => panic!("{name}: tests/c/manuals.c reads no examples of {other:?}"),
            };
            let out = example.direction == gsdc::ir::Direction::Out;
            for telegram in example.instances() {
                let bytes: Vec<String> = telegram[..8]
                    .iter()
                    .map(|b| format!("0x{b:02X}U"))
                    .collect();
                rows.push(format!(
                    "    {{{name:?}, {:?}, {:?}, {codec}, {out}, {{{}}}}},",
                    example.section,
                    example.printed,
                    bytes.join(", ")
                ));
            }
        }
    }
    format!(
        "/* The manuals' worked examples, as the descriptions give them: written\n \
         * by tests/c_header.rs. */\n\
         #define EXAMPLE_TELEGRAMS {}U\n\
         static const example_t examples[EXAMPLE_TELEGRAMS] = {{\n{}\n}};\n",
        rows.len(),
        rows.join("\n")
    )
}

fn c_source(name: &str) -> PathBuf {
    support::checkout("tests/c").join(name)
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

/// The support header is the same for every description, so a build of
/// several writes one.
#[test]
fn every_description_gives_the_same_support_header() {
    let shipped = descriptions::shipped();
    let support = artifact(&shipped[0], ArtifactKind::CSupport);
    assert_eq!(support.0, "gsdc_support.h");
    for name in &shipped[1..] {
        assert_eq!(artifact(name, ArtifactKind::CSupport), support, "{name}");
    }
}

/// What the issue asks of the text: the three standard headers only, no
/// packed structs, bit fields or unions for wire data, no allocation, no
/// line past 100 columns.
#[test]
fn headers_hold_wire_data_in_byte_arrays_and_include_only_standard_headers() {
    let shipped = descriptions::shipped();
    let support = artifact(&shipped[0], ArtifactKind::CSupport).1;
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
    for name in &shipped {
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
/// translation unit with all five (one twice), freestanding, compiled by
/// every installed compiler as C99, C11 and C++17 without a warning.
#[test]
fn all_layouts_compile_together_in_one_translation_unit() {
    let include = include_dir("all-layouts");
    let out = support::scratch("all-layouts");
    for (i, build) in builds().into_iter().enumerate() {
        let mut command = build.command(&include, &["-ffreestanding", "-c"]);
        command
            .arg(c_source("all_layouts.c"))
            .arg("-o")
            .arg(out.join(format!("all_layouts_{i}.o")));
        assert_success(&build.name(), &run(command));
    }
}

/// The tests `tests/c/manuals.c` runs: the Rust firmware crate's, one by one.
const MANUAL_TESTS: [&str; 40] = [
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
    "mv810_mappings_set_at_the_drive",
    "every_example_of_the_manuals_round_trips",
    "pi9000_command_word_in_ppo3",
    "pi9000_fault_code_diagnosis",
    "pi9000_default_user_prm",
    "bridge_the_manuals_example_is_240_bytes_in_and_128_out",
    "bridge_the_example_s_modules_carry_its_totals",
    "bridge_each_slave_s_words_have_their_place",
    "bridge_thirty_slaves_and_244_bytes_pass",
    "bridge_a_31st_slave_is_refused",
    "bridge_a_245th_byte_is_refused",
    "bridge_a_slave_s_words_keep_to_their_range",
    "bridge_the_default_is_the_bridge_alone",
    "bridge_the_layout_agrees_with_the_gsd",
    "bridge_the_four_diagnosis_blocks_decode_and_encode_back",
    "bridge_the_reserved_byte_is_not_read",
    "bridge_blocks_the_table_does_not_have_are_refused",
    "bridge_diagnoses_the_table_does_not_have_are_not_encoded",
    "profidrive_read_p10_05",
    "profidrive_write_a_word_to_p10_05",
    "profidrive_error_answer",
    "profidrive_an_illegal_id_is_refused",
    "profidrive_standard_telegram_1_is_placed_as_the_gsdml_declares_it",
    "profidrive_standard_telegram_2_carries_a_32_bit_speed",
];

/// The values of `key` in the GSD gsdc generates from `name`, one per line
/// that starts with it.
fn gsd_values(name: &str, key: &str) -> Vec<String> {
    let (_, gsd) = artifact(name, ArtifactKind::Gsd);
    let values: Vec<String> = gsd
        .lines()
        .filter(|l| l.starts_with(key))
        .map(|l| l.split_once('=').unwrap().1.trim().to_string())
        .collect();
    assert!(!values.is_empty(), "{name}'s GSD has no {key}");
    values
}

/// `-D<define>=<value>` of the first `key` in `name`'s GSD.
fn gsd_define(define: &str, name: &str, key: &str) -> String {
    format!("-D{define}={}", gsd_values(name, key)[0])
}

/// The manuals' telegrams through the C layouts, compiled by every
/// installed compiler as C and as C++, and run: every test passes, and the
/// program ran each test the Rust firmware crate runs.
#[test]
fn the_manuals_telegrams_round_trip_in_c() {
    let (md810, gateway) = ("md810dp.toml", "md810-gateway.toml");
    // `Module = "INPUT 1 word" 0x50`: the config byte is the last word.
    let module_configs: Vec<String> = gsd_values(gateway, "Module")
        .iter()
        .map(|m| m.rsplit(' ').next().unwrap().to_string())
        .collect();
    let defines = [
        gsd_define("GSD_MAX_USER_PRM_DATA_LEN", md810, "Max_User_Prm_Data_Len"),
        gsd_define("GSD_MAX_DIAG_DATA_LEN", md810, "Max_Diag_Data_Len"),
        gsd_define(
            "GSD_GW_MAX_USER_PRM_DATA_LEN",
            gateway,
            "Max_User_Prm_Data_Len",
        ),
        gsd_define("GSD_GW_MAX_DIAG_DATA_LEN", gateway, "Max_Diag_Data_Len"),
        gsd_define("GSD_GW_MAX_INPUT_LEN", gateway, "Max_Input_Len"),
        gsd_define("GSD_GW_MAX_OUTPUT_LEN", gateway, "Max_Output_Len"),
        gsd_define("GSD_GW_MAX_MODULE", gateway, "Max_Module"),
        format!("-DGSD_GW_MODULE_CONFIGS={}", module_configs.join(",")),
    ];
    compile_and_run("manuals.c", &defines, &MANUAL_TESTS);
}

/// The tests `tests/c/support.c` runs: those of the Rust support code.
const SUPPORT_TESTS: [&str; 32] = [
    "words_are_big_endian",
    "bit_fields_read_and_write_their_bits_only",
    "values_are_read_and_checked_at_their_offset",
    "byte_and_word_entries_are_read_each_at_its_offset",
    "a_record_ends_with_its_fail_safe_values",
    "an_access_point_record_reads_whole_values_and_bits",
    "reading_past_the_end_is_refused",
    "pke_no_request_ignores_what_the_master_left",
    "pke_reserved_bits_are_not_read_and_written_0",
    "pke_codes_the_manual_does_not_define_are_refused",
    "profidrive_words_in_pwe2_double_words_across_both",
    "profidrive_the_subindex_is_the_high_byte_of_ind",
    "profidrive_ids_beyond_the_profile_are_refused",
    "profidrive_encoders_refuse_what_the_channel_cannot_carry",
    "profidrive_no_request_ignores_what_the_master_left",
    "station_read_with_the_count_1",
    "station_commands_the_manual_does_not_list_are_refused",
    "station_errors_reply_0x80_plus_the_command",
    "an_area_is_its_bits_counted_from_the_byte_after_the_header",
    "an_area_across_two_bytes_has_its_first_bit_lowest",
    "a_block_too_short_loses_the_bits_past_its_end",
    "bit_areas_share_a_byte",
    "bits_beyond_the_range_are_refused",
    "unsigned16_is_big_endian_and_within_a_byte_s_values",
    "a_field_past_the_end_is_a_length_error",
    "config_bytes_of_no_module_are_refused",
    "totals_count_the_nodes_in_use_within_the_limits",
    "a_count_past_the_nodes_is_refused",
    "data_offsets_follow_the_nodes_in_use",
    "nodes_read_and_write_in_order",
    "diagnosis_blocks_are_read_as_long_as_their_header_says",
    "an_encoded_block_is_0_where_it_holds_nothing",
];

/// The support header at its edges, as the Rust support code is tested.
#[test]
fn the_support_header_holds_at_its_edges() {
    compile_and_run("support.c", &[], &SUPPORT_TESTS);
}

/// Compiles `tests/c/<source>` with every installed compiler as C and as
/// C++, runs it, and checks that it ran `tests`, in order, all passing.
fn compile_and_run(source: &str, defines: &[String], tests: &[&str]) {
    let include = include_dir(source);
    let out = support::scratch(source);
    for (i, build) in builds().into_iter().enumerate() {
        let program = out.join(format!("program_{i}"));
        let mut command = build.command(&include, &[]);
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
    let include = include_dir("size-check");
    let dir = support::scratch("size-check");
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
            let mut command = build.command(&include, &["-c", "-o"]);
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
    let dir = include_dir("other-release");
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
    let dir = support::scratch("generate-c");
    let description = support::checkout("descriptions/md810dp.toml");
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
    let dir = support::scratch("bare");
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

/// A gateway whose parameters use what MD810's do not: User_Prm_Data
/// starting with the DPV1 status bytes, a 16-bit node count, and each
/// node's words in and out as the two halves of one byte. The header
/// compiles in every language, and a configuration goes through the
/// encoder and the decoder byte for byte.
#[test]
fn a_gateway_with_dpv1_bit_areas_and_a_16_bit_count_round_trips() {
    let text = include_str!("../descriptions/md810-gateway.toml")
        .replacen(
            "[gateway]\n",
            "[profibus.dpv1]\nc1_read_write = true\nc1_max_data_len = 2\n\
             c1_response_timeout = 100\nstatus_bytes = [0x80, 0x00, 0x00]\n\
             ident_maintenance = false\n\n[gateway]\n",
            1,
        )
        .replacen("type = \"Unsigned8\"", "type = \"Unsigned16\"", 1)
        .replacen("type = \"Unsigned8\"", "bits = [0, 3]", 1)
        .replacen("type = \"Unsigned8\"", "bits = [4, 7]", 1);
    let (ir, diagnostics) = descriptions::load_text("gw_variant.toml", &text);
    assert!(!diagnostics.has_errors(), "{diagnostics:?}");
    let dir = support::scratch("gateway-variant");
    for a in gsdc::compile(&ir.unwrap()).unwrap() {
        if matches!(a.kind, ArtifactKind::CHeader | ArtifactKind::CSupport) {
            std::fs::write(dir.join(&a.file_name), &a.contents).unwrap();
        }
    }
    let header = std::fs::read_to_string(dir.join("gw_variant_layout.h")).unwrap();
    assert!(
        header.contains("{ 5U, GSDC_PRM_BITS, 0U, 3U, 0U, 8U, 0U }"),
        "{header}"
    );
    // The status bytes, the count (2, high byte first), then slave 1's and
    // slave 2's words: in in bits 0-3, out in bits 4-7.
    let source = dir.join("gw_variant.c");
    std::fs::write(
        &source,
        r#"#include "gw_variant_layout.h"

int main(void)
{
    static const uint8_t expected[7] = {0x80U, 0x00U, 0x00U, 0x00U, 0x02U, 0x85U, 0x13U};
    gw_variant_node_config_t config = GW_VARIANT_NODE_CONFIG_DEFAULT;
    gw_variant_user_prm_t prm;
    uint8_t user_prm[GW_VARIANT_USER_PRM_LEN];
    gsdc_totals_t totals;
    bool ok = (GW_VARIANT_USER_PRM_LEN == 35U);
    size_t i;
    config.node_count = 2U;
    config.input_words[0] = 5U;
    config.input_words[1] = 3U;
    config.output_words[0] = 8U;
    config.output_words[1] = 1U;
    totals = gw_variant_node_totals(&config);
    ok = ok && (totals.fault == GSDC_TOTALS_OK) && (gsdc_totals_input_len(&totals) == 16U);
    ok = ok && (gw_variant_node_config_encode(&config, user_prm).fault == GSDC_PRM_OK);
    for (i = 0U; i < GW_VARIANT_USER_PRM_LEN; i++) {
        ok = ok && (user_prm[i] == ((i < 7U) ? expected[i] : 0U));
    }
    ok = ok && (gw_variant_decode_user_prm(user_prm, sizeof user_prm, &prm).fault == GSDC_PRM_OK);
    ok = ok && (prm.dpv1_status[0] == 0x80U) && (prm.nodes.node_count == 2U);
    ok = ok && (prm.nodes.input_words[1] == 3U) && (prm.nodes.output_words[0] == 8U);
    user_prm[5] = 0x95U; /* slave 1 receives 9 words: out of range */
    ok = ok && (gw_variant_decode_user_prm(user_prm, sizeof user_prm, &prm).value == 9U);
    return ok ? 0 : 1;
}
"#,
    )
    .unwrap();
    for (i, build) in builds().into_iter().enumerate() {
        let program = dir.join(format!("gw_variant_{i}"));
        let mut command = build.command(&dir, &["-o"]);
        command.arg(&program).arg(&source);
        assert_success(&build.name(), &run(command));
        assert_success(&program.display().to_string(), &run(Command::new(&program)));
    }
}
