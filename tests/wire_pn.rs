//! The PROFINET exchange on the wire (issue 20), as `scripts/wire-test.sh
//! --bus pn` runs it: for every description with `[profinet]`, profinet-py
//! as the IO controller, configured only from the GSDML gsdc builds, against
//! the pnio device built from the layout, between two network namespaces.
//! And the same exchange with a GSDML that disagrees with the layout, which
//! must fail and say where.
//!
//! Needs root (namespaces, raw sockets), iproute2 and Python; scripts/test.sh
//! installs them, and the exchange makes its venv (target/wire-venv). Without
//! root the tests say so and leave the exchange out, except under CI=true,
//! where that fails.

use std::path::Path;
use std::process::Command;

use crate::support::{self, descriptions};
use crate::wire_dp::{turn, wire_target};

/// Whether the exchange can run here (as root); under CI it must.
fn can_run() -> bool {
    let is_root = Command::new("id")
        .arg("-u")
        .output()
        .is_ok_and(|o| String::from_utf8_lossy(&o.stdout).trim() == "0");
    if !is_root {
        support::cannot_run("the PROFINET exchange needs root (network namespaces, raw sockets)");
    }
    is_root
}

/// `scripts/wire-test.sh --bus pn`'s status and everything it printed, with
/// the gsdc this test was built with, in the wire workspace's target
/// directory the DP tests use (taking turns with them).
fn exchange(descriptions: &[&str], files: Option<&Path>) -> (i32, String) {
    let _turn = turn();
    let mut command = Command::new(support::checkout("scripts/wire-test.sh"));
    command.args(["--bus", "pn"]);
    if let Some(files) = files {
        command.arg("--files").arg(files);
    }
    let output = command
        .args(descriptions)
        .current_dir(support::CHECKOUT)
        .env("GSDC", support::GSDC)
        .env("WIRE_TARGET_DIR", wire_target())
        .env("CARGO", env!("CARGO"))
        .output()
        .expect("scripts/wire-test.sh runs");
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
    (output.status.code().unwrap_or(-1), text)
}

fn assert_lines(text: &str, lines: &[&str]) {
    for line in lines {
        assert!(text.contains(line), "no {line:?} in:\n{text}");
    }
}

/// Every shipped description and valid fixture with [profinet], as
/// `descriptions/mv810-pnet02.toml`, with its name and the exchanges it must
/// pass: each of its modules (its empty module too, plugged alone), two
/// modules in two slots at once where its modules go into several, the
/// soft card (found by its name of station, stopped by SIGINT and by
/// SIGTERM), two negative cases (another module ident, another input
/// length), one for each module in an API other than 0 (a layout that says
/// API 0), and one for each device access point after the first.
fn with_profinet() -> Vec<(String, String, usize)> {
    let mut found = Vec::new();
    for folder in ["descriptions", "tests/fixtures/valid"] {
        for name in support::file_names(&support::checkout(folder)) {
            let Some(stem) = name.strip_suffix(".toml") else {
                continue;
            };
            let ir = descriptions::load_from(folder, &name);
            let Some(profinet) = &ir.profinet else {
                continue;
            };
            let other_apis = profinet.modules.iter().filter(|m| m.api != 0).count();
            let later_daps = profinet.daps.len() - 1;
            let empty = usize::from(profinet.empty_module.is_some());
            let at_once = usize::from(profinet.module_slots.count() > 1);
            let exchanges =
                profinet.modules.len() + empty + at_once + 1 + 2 + other_apis + later_daps;
            found.push((format!("{folder}/{name}"), stem.to_string(), exchanges));
        }
    }
    found
}

/// Every description and valid fixture with `[profinet]` in one run: one
/// build of the device for their layouts.
#[test]
fn every_profinet_description_every_module() {
    if !can_run() {
        return;
    }
    let all = with_profinet();
    let paths: Vec<&str> = all.iter().map(|(path, _, _)| path.as_str()).collect();
    for shipped in [
        "descriptions/mv810-pnet02.toml",
        "descriptions/md810dp.toml",
        "tests/fixtures/valid/profidrive.toml",
    ] {
        assert!(paths.contains(&shipped), "{shipped} has [profinet]");
    }
    let (status, text) = exchange(&paths, None);
    assert_eq!(status, 0, "{text}");
    for (_, name, exchanges) in &all {
        assert_lines(
            &text,
            &[&format!("PROFINET {name}: {exchanges} passed, 0 failed")],
        );
    }
    // The soft card of the README: DCP Identify by the name of station the
    // GSDML gives (the device takes its own from the layout), then Ctrl-C
    // and SIGTERM each stop it cleanly.
    assert_lines(
        &text,
        &[
            "DCP identify: mv810-pnet02 at 192.0.2.2, vendor 0x0A10 device 0x0810, as the GSDML says",
            "  soft card: stopped on SIGINT, exit 0",
            "  soft card: stopped on SIGTERM, exit 0",
        ],
    );
    mv810_every_module_records_control_word_and_pkw(&text);
    md810_reads_f0_08_through_the_pkw_channel(&text);
    profidrive_telegram_behind_its_access_point_in_api_0x3a00(&text);
    // own_idents.toml's later DAPs: the controller connects with each, as
    // the GSDML gives it, to the device presenting the layout's.
    assert_lines(
        &text,
        &[
            "device access point 2 (IDD_DAP_2, ident 0x00000200), IDM_STD_TEL_1 in slot 2",
            "PASS IDM_STD_TEL_1 under device access point 2: 1 records decoded, 1 inputs observed",
            "device access point 3 (IDD_DAP_3, ident 0x00000300), IDM_STD_TEL_1 in slot 2",
            "PASS IDM_STD_TEL_1 under device access point 3: 1 records decoded, 1 inputs observed",
            // The fourth is the third's ident number: the device presents
            // the third, which does not offer PZD1 nor have record 8201,
            // and takes both as the fourth's (the controller fails a
            // record the device's layout has none of). The second's port
            // has no records: 8200 alone.
            "--- device access point 4, the device presenting 3 of its ident number: IDM_PZD_1 (Drive telegram) in slot 2",
            "PASS IDM_PZD_1 under device access point 4: 1 records decoded, 1 inputs observed, 0 scenario checks, 6 records of the access point and its ports decoded",
            "PASS IDM_STD_TEL_1 under device access point 2: 1 records decoded, 1 inputs observed, 0 scenario checks, 1 records of the access point and its ports decoded",
        ],
    );
    // own_idents.toml's modules go into slots 2 and 3: each is plugged
    // into slot 2, both at once into slots 2 and 3 (each slot's record
    // decoded by the layout, each slot's inputs valid), and its empty
    // module, without data, alone into slot 1.
    assert_lines(
        &text,
        &[
            "--- IDM_PZD_1 (Drive telegram) in slot 2",
            "--- two modules at once: IDM_STD_TEL_1 (Standard telegram 1) in slot 2, IDM_PZD_1 (Drive telegram) in slot 3",
            "  record 1 (Drive settings) to slot 3 subslot 1: 00 01 02 = [1, 2]",
            "  inputs of slot 3 subslot 1: 00 00",
            "PASS IDM_STD_TEL_1 with IDM_PZD_1 in slot 3: 2 records decoded, 2 inputs observed",
            "--- IDM_EMPTY (Empty) in slot 1",
            "device access point 1 (IDD_DAP, ident 0x00000100), IDM_EMPTY in slot 1: subslot 1 ident 0x1 API 0x0 in 0 out 0",
            "PASS IDM_EMPTY: 0 records decoded, 0 inputs observed",
        ],
    );
    settings_of_a_byte_and_per_module_defaults(&text);
    fail_safe_values_after_the_settings(&text);
    records_of_the_access_point_and_its_ports(&text);
}

/// own_idents.toml's records of the access point and its ports, as SEW's
/// MOVI-C has them: the controller writes each to slot 0, the access
/// point's to its subslot 1 and the ports' to every port (device access
/// point 3 has two), each changeable value other than its default; the
/// device's layout decodes every value at its bits and bytes: record 8200's
/// bit 0 and bits 4 to 6 (0x11: 1 and 1), record 9001's two Unsigned32
/// (the first with its high word set, 65547 = 0x0001_000B), record 9002's
/// byte nobody may change, at its default 1.
fn records_of_the_access_point_and_its_ports(text: &str) {
    assert_lines(
        text,
        &[
            "  record 8200 (Alarm settings) to slot 0 subslot 1: 11 = [1, 1]",
            "    decoded by the layout: Diagnostic alarms = 1, Alarm delay = 1",
            "  record 9001 (Maintenance required thresholds) to slot 0 subslot 32769: 00 01 00 0b 00 01 11 74 = [65547, 70004]",
            "    decoded by the layout: Receive errors = 65547, Transmit errors = 70004",
            "  record 9002 (Port statistics) to slot 0 subslot 32770: 01 = [1]",
            "    decoded by the layout: Statistics version = 1",
            "PASS IDM_STD_TEL_1 under device access point 3: 1 records decoded, 1 inputs observed, 0 scenario checks, 5 records of the access point and its ports decoded",
        ],
    );
}

/// profidrive.toml's record 1 ends with a fail-safe value per output item
/// of the module (`[profinet.fail_safe_values]`): telegram 1's two words,
/// telegram 2's STW1, NSOLL_B and STW2, the 1 PZD module's one word after
/// its two settings. The controller writes the GSDML's Unsigned32 with its
/// high word set (65543 = 0x0001_0007); the device's layout decodes every
/// value at its offset, of its width.
fn fail_safe_values_after_the_settings(text: &str) {
    assert_lines(
        text,
        &[
            "  record 1 (Drive settings) to slot 1 subslot 2: 01 00 04 00 07 = [1, 4, 7]",
            "    decoded by the layout: Stop mode (P10.06) = 1, fail-safe value 1 = 4, fail-safe value 2 = 7",
            "  record 1 (Drive settings) to slot 1 subslot 2: 01 00 04 00 01 00 07 00 0a = [1, 4, 65543, 10]",
            "    decoded by the layout: Stop mode (P10.06) = 1, fail-safe value 1 = 4, fail-safe value 2 = 65543, fail-safe value 3 = 10",
            "  record 1 (Drive settings) to slot 1 subslot 1: 00 01 02 00 07 = [1, 2, 7]",
            "    decoded by the layout: Fault reaction (P10.05) = 1, Stop mode (P10.06) = 2, fail-safe value 1 = 7",
        ],
    );
}

/// own_idents.toml's stop mode is an Integer8, each module's default,
/// which the user may change (`per_module` with `changeable`): standard
/// telegram 1's record holds its one byte alone (default 0), the PZD
/// module's after the fault reaction's two (default 1), each in slot 2, the
/// first of the card's module slots. The controller
/// writes the value after each default, which the device takes only because
/// the GSDML and the layout let it change. AX200's ramp-down time is an
/// Unsigned8 after two words.
fn settings_of_a_byte_and_per_module_defaults(text: &str) {
    assert_lines(
        text,
        &[
            "  record 1 (Drive settings) to slot 2 subslot 2: 01 = [1]",
            "    decoded by the layout: Stop mode (P10.06) = 1",
            "  record 1 (Drive settings) to slot 2 subslot 1: 00 01 02 = [1, 2]",
            "    decoded by the layout: Fault reaction (P10.05) = 1, Stop mode (P10.06) = 2",
            "  record 3 (Drive settings) to slot 1 subslot 1: 03 e7 00 01 11 = [999, 1, 17]",
            "    decoded by the layout: Telegram selection (P0922) = 999, Fault reaction (P1900) = 1, Ramp-down time in s (P1121) = 17",
        ],
    );
}

fn mv810_every_module_records_control_word_and_pkw(text: &str) {
    // Section 4 sets P43.01 to P43.23 at the drive: the GSDML has no
    // parameter record, so the controller writes none and the device
    // decodes none.
    let mut expected = vec![
        "PASS IDM_STD_TEL_1: 0 records decoded, 1 inputs observed, 1 scenario checks".to_string(),
    ];
    for n in 1..=12 {
        expected.push(format!(
            "PASS IDM_PKW_{n}: 0 records decoded, 1 inputs observed, 2 scenario checks"
        ));
    }
    let expected: Vec<&str> = expected.iter().map(String::as_str).collect();
    assert_lines(text, &expected);
    assert_lines(
        text,
        &[
            // Section 3's bits: forward running, ready; not stop.
            "control word 0x0001 (Forward running) -> status word 0x0021",
            // Read P43.02 (0x2B02): what the drive holds, the description's
            // default 0, which no record overwrote.
            "PKW 0101 0003 2B02 0001 -> 0101 0003 2B02 0000 (read P43.02)",
            "Connect refused as expected: PNIO status DB 81 03 04",
            "Connect refused as expected: PNIO status DB 81 03 07",
            "PROFINET mv810-pnet02: 16 passed, 0 failed",
        ],
    );
    assert!(
        !text.contains("2B02 0001 (read P43.02)"),
        "no record wrote P43.02"
    );
}

fn md810_reads_f0_08_through_the_pkw_channel(text: &str) {
    assert_lines(
        text,
        &[
            // MD810 1.4.2, figure 6.
            "PKW 10F0 0800 0000 0000 -> 10F0 0800 0000 1388 (read F0-08)",
            "PASS IDM_PKW_12: 3 records decoded, 1 inputs observed, 1 scenario checks",
            "PASS IDM_PZD_12: 3 records decoded, 1 inputs observed, 0 scenario checks",
            "PROFINET md810dp: 9 passed, 0 failed",
        ],
    );
}

/// Both standard telegrams of profidrive.toml: the controller reads
/// telegram 2's 8 bytes each way from the GSDML's Unsigned16, Unsigned32,
/// Unsigned16, the device the layout's 4 words, and the speed written as the
/// GSDML's Unsigned32 is the layout's 32-bit value; and each module in API
/// 0x3A00 is refused when the layout would place it in API 0.
fn profidrive_telegram_behind_its_access_point_in_api_0x3a00(text: &str) {
    assert_lines(
        text,
        &[
            "subslot 1 ident 0xFFFF API 0x3A00 in 0 out 0, subslot 2 ident 0x10 API 0x3A00 in 4 out 4",
            "subslot 1 ident 0xFFFF API 0x3A00 in 0 out 0, subslot 2 ident 0x20 API 0x3A00 in 8 out 8",
            "API 0x3A00: the device checked it against its layout before pnio saw the Connect",
            "PASS IDM_STD_TEL_1",
            // The controller writes NSOLL_B as the GSDML's Unsigned32; the
            // device's layout reads it from PZD2 and PZD3 and the drive
            // model's actual speed follows it.
            "  NSOLL_B (speed setpoint B) 0x000186A0 at byte 2 -> the layout read 100000 (PZD2) -> NIST_B (speed actual value B) 0x000186A0",
            // Its record holds the stop mode, each module's default.
            "PASS IDM_STD_TEL_2: 1 records decoded, 1 inputs observed, 0 scenario checks, 1 32-bit values read by the layout",
            "negative: IDM_STD_TEL_2, the device's layout places it in API 0, the GSDML in API 14848",
            "Connect refused as expected: PNIO status DB 81 03 05 (Connect refused: ExpectedSubmoduleBlockReq, API)",
            "PROFINET profidrive: 8 passed, 0 failed",
        ],
    );
}

/// The description's GSDML, built by gsdc into a scratch directory, then
/// changed by `edit`: a released file that disagrees with the firmware.
#[track_caller]
fn edited_gsdml(
    description: &str,
    case: &str,
    edit: impl Fn(String) -> String,
) -> support::Scratch {
    let stem = Path::new(description)
        .file_stem()
        .unwrap()
        .to_string_lossy();
    // One folder per case: the tests run at once, two of them on one fixture.
    let dir = support::scratch(&format!("released-{stem}-{case}"));
    let out = dir.to_str().unwrap();
    let built = support::gsdc(["build", description, "--out", out]);
    assert!(built.status.success(), "{}", support::stderr(&built));
    let gsdml = std::fs::read_dir(&*dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .find(|p| p.extension().is_some_and(|e| e == "xml"))
        .expect("a GSDML");
    let text = std::fs::read_to_string(&gsdml).unwrap();
    let changed = edit(text.clone());
    assert_ne!(changed, text, "the edit changed nothing");
    std::fs::write(&gsdml, changed).unwrap();
    dir
}

#[test]
fn a_gsdml_with_another_module_ident_fails_and_says_where() {
    if !can_run() {
        return;
    }
    // Standard message 1's ident 0x10 becomes 0x11 in the GSDML only.
    let dir = edited_gsdml("descriptions/mv810-pnet02.toml", "module-ident", |t| {
        t.replace(
            r#"ModuleIdentNumber="0x00000010""#,
            r#"ModuleIdentNumber="0x00000011""#,
        )
    });
    let (status, text) = exchange(&["descriptions/mv810-pnet02.toml"], Some(&dir));
    assert_eq!(status, 1, "{text}");
    assert_lines(
        &text,
        &[
            "FAIL IDM_STD_TEL_1: Connect failed: PNIO status DB 81 03 04",
            "PASS IDM_PKW_12",
            "PROFINET mv810-pnet02: 15 passed, 1 failed",
        ],
    );
}

#[test]
fn a_gsdml_that_says_api_0_for_a_profidrive_telegram_fails() {
    if !can_run() {
        return;
    }
    let dir = edited_gsdml("tests/fixtures/valid/profidrive.toml", "api-0", |t| {
        t.replace(r#"API="14848""#, r#"API="0""#)
    });
    let (status, text) = exchange(&["tests/fixtures/valid/profidrive.toml"], Some(&dir));
    assert_eq!(status, 1, "{text}");
    assert_lines(
        &text,
        &["FAIL IDM_STD_TEL_1: Connect failed: PNIO status DB 81 03 05 (Connect refused: ExpectedSubmoduleBlockReq, API)"],
    );
}

/// A GSDML that puts telegram 2's 32-bit speed first (Unsigned32,
/// Unsigned16, Unsigned16, the same 8 bytes): the controller writes NSOLL_B
/// at byte 0, the layout reads PZD2 and PZD3, and the exchange fails saying
/// what the layout read (0x86A00000: the setpoint's low word and STW1's
/// place); telegram 1 still passes.
#[test]
fn a_gsdml_that_moves_telegram_2s_speed_fails_and_says_what_the_layout_read() {
    if !can_run() {
        return;
    }
    let description = "tests/fixtures/valid/profidrive.toml";
    let dir = edited_gsdml(description, "speed-moved", |t| {
        let order = |first: &str, speed: &str| {
            (
                format!(
                    "<DataItem DataType=\"Unsigned16\" TextId=\"IDT_{first}\"/>\n                  <DataItem DataType=\"Unsigned32\" TextId=\"IDT_{speed}\"/>"
                ),
                format!(
                    "<DataItem DataType=\"Unsigned32\" TextId=\"IDT_{speed}\"/>\n                  <DataItem DataType=\"Unsigned16\" TextId=\"IDT_{first}\"/>"
                ),
            )
        };
        let (input, moved_input) = order("ZSW1", "NIST_B");
        let (output, moved_output) = order("STW1", "NSOLL_B");
        assert!(t.contains(&input) && t.contains(&output));
        t.replace(&input, &moved_input)
            .replace(&output, &moved_output)
    });
    let (status, text) = exchange(&[description], Some(&dir));
    assert_eq!(status, 1, "{text}");
    assert_lines(
        &text,
        &[
            "PASS IDM_STD_TEL_1",
            "FAIL IDM_STD_TEL_2: slot 1 subslot 2, byte 0 (NSOLL_B (speed setpoint B)): the layout read [0, 2258632704], the controller wrote 100000",
            "PROFINET profidrive: 7 passed, 1 failed",
        ],
    );
}

/// A GSDML that lets record 9001's second threshold of every port reach
/// 200000, where the layout's stops at 100000: the controller writes
/// 135540 there (70004 with its high word set, which the GSDML now allows),
/// and the device's layout refuses the record, naming the value's byte.
#[test]
fn a_port_record_value_the_layout_does_not_allow_is_refused() {
    if !can_run() {
        return;
    }
    let description = "tests/fixtures/valid/own_idents.toml";
    let dir = edited_gsdml(description, "port-record-range", |t| {
        t.replace(
            r#"AllowedValues="1..100000""#,
            r#"AllowedValues="1..200000""#,
        )
    });
    let (status, text) = exchange(&[description], Some(&dir));
    assert_eq!(status, 1, "{text}");
    assert_lines(
        &text,
        &[
            "  record 9001 (Maintenance required thresholds) to slot 0 subslot 32769: 00 01 00 0b 00 02 11 74 = [65547, 135540]",
            "FAIL IDM_STD_TEL_1: record 9001 of slot 0 subslot 32769: the layout's decoder refused it: NotAllowed { offset: 4, value: 135540 }",
        ],
    );
}

/// The device presents the layout's third device access point; a GSDML
/// whose DAPs 3 and 4 (of one ident number) have another is refused at
/// slot 0 (pnio's ExpectedSubmoduleBlockReq module ident) under each,
/// while the first two still pass.
#[test]
fn a_gsdml_with_another_dap_ident_fails_for_the_daps_of_that_ident_only() {
    if !can_run() {
        return;
    }
    let description = "tests/fixtures/valid/own_idents.toml";
    let dir = edited_gsdml(description, "dap-ident", |t| {
        t.replace(
            r#"ModuleIdentNumber="0x00000300""#,
            r#"ModuleIdentNumber="0x00000399""#,
        )
    });
    let (status, text) = exchange(&[description], Some(&dir));
    assert_eq!(status, 1, "{text}");
    assert_lines(
        &text,
        &[
            "device access point 2 (IDD_DAP_2, ident 0x00000200), IDM_STD_TEL_1 in slot 2",
            "PASS IDM_STD_TEL_1 under device access point 2:",
            "device access point 3 (IDD_DAP_3, ident 0x00000399), IDM_STD_TEL_1 in slot 2",
            "FAIL IDM_STD_TEL_1 under device access point 3: Connect failed: PNIO status DB 81 03 04",
            // The fourth shares the third's ident number, changed with it.
            "device access point 4 (IDD_DAP_4, ident 0x00000399), IDM_PZD_1 in slot 2",
            "FAIL IDM_PZD_1 under device access point 4: Connect failed: PNIO status DB 81 03 04",
            "PROFINET own_idents: 9 passed, 2 failed",
        ],
    );
}
