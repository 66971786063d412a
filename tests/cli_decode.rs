//! `gsdc decode` as a user runs it: the tables, the JSON document, and each
//! error with its code, place and exit code.

use crate::support::{self, descriptions, stderr, stdout};
use std::process::Output;

/// Runs `gsdc decode` with `args`.
fn gsdc(args: &[&str]) -> Output {
    support::gsdc(["decode"].iter().chain(args))
}

/// Runs a decode that must succeed; its stdout.
fn decoded(args: &[&str]) -> String {
    let output = gsdc(args);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    stdout(&output)
}

fn json(args: &[&str]) -> serde_json::Value {
    let mut args = args.to_vec();
    args.extend(["--format", "json"]);
    serde_json::from_str(&decoded(&args)).expect("one JSON document")
}

const MD810: &str = "descriptions/md810dp.toml";
const MV810: &str = "descriptions/mv810-pnet02.toml";

/// The line of the table that starts with `start` (after the padding).
fn line<'a>(table: &'a str, start: &str) -> &'a str {
    table
        .lines()
        .find(|l| l.trim_start().starts_with(start))
        .unwrap_or_else(|| panic!("no line starting with {start:?} in\n{table}"))
}

fn cells(line: &str) -> Vec<&str> {
    line.split("  ")
        .map(str::trim)
        .filter(|c| !c.is_empty())
        .collect()
}

/// MD810 figure 6 read as a person reads it: every word, the request.
#[test]
fn md810_read_request_as_a_table() {
    let out = decoded(&[
        MD810,
        "--module",
        "PPO1",
        "--direction",
        "out",
        "10F0 0800 0000 0000 0000 0000",
    ]);
    assert!(
        out.starts_with("PPO1 (out, master to drive), 12 bytes\n"),
        "{out}"
    );
    assert_eq!(cells(line(&out, "0  PKE")), ["0", "PKE", "10F0", "4336"]);
    assert_eq!(cells(line(&out, "2  IND")), ["2", "IND", "0800", "2048"]);
    assert_eq!(
        cells(line(&out, "8  PZD1")),
        [
            "8",
            "PZD1",
            "0000",
            "0",
            "F0-00",
            "PZD1(master->slaver) = 61440, default"
        ]
    );
    assert_eq!(line(&out, "PKW"), "PKW request");
    assert_eq!(cells(line(&out, "code")), ["code", "1", "read"]);
    assert_eq!(
        line(&out, "parameter").trim(),
        "parameter  F0-08 (address 0xF008)"
    );
}

#[test]
fn md810_error_answer_names_the_error() {
    let out = decoded(&[
        MD810,
        "--module",
        "ppo1",
        "--direction",
        "in",
        "70F0",
        "0800",
        "0000",
        "0003",
        "0000",
        "0000",
    ]);
    assert_eq!(line(&out, "PKW"), "PKW response");
    assert_eq!(cells(line(&out, "code")), ["code", "7", "cannot execute"]);
    assert_eq!(cells(line(&out, "error")), ["error", "3", "illegal data"]);
}

const PROFIDRIVE: &str = "tests/fixtures/valid/profidrive.toml";

/// The PROFIdrive fixture's PPO1 carrying `pkw` and two PZD words.
fn profidrive_ppo1<'a>(direction: &'a str, pkw: &'a str) -> [&'a str; 6] {
    [
        PROFIDRIVE,
        "--module",
        "PPO1",
        "--direction",
        direction,
        pkw,
    ]
}

/// A PROFIdrive read of P10.05: PKE 13ED is request 1 and PNU 1005, named
/// after the description's decimal numbering; the words are the profile's.
#[test]
fn profidrive_read_of_p10_05_names_the_pnu() {
    let out = decoded(&profidrive_ppo1("out", "13ED 0000 0000 0000 047F 4000"));
    assert_eq!(cells(line(&out, "0  PKE")), ["0", "PKE", "13ED", "5101"]);
    assert_eq!(cells(line(&out, "4  PWE1")), ["4", "PWE1", "0000", "0"]);
    assert_eq!(cells(line(&out, "6  PWE2")), ["6", "PWE2", "0000", "0"]);
    assert_eq!(line(&out, "PKW"), "PKW request");
    assert_eq!(
        cells(line(&out, "code")),
        ["code", "1", "request the parameter value"]
    );
    assert_eq!(
        line(&out, "parameter").trim(),
        "parameter  P10.05 (PNU 1005), subindex 0"
    );
}

/// A word write and a double word write to an array element: PWE2 alone,
/// then PWE1 and PWE2 high word first; the subindex from IND's high byte.
#[test]
fn profidrive_writes_carry_words_and_double_words() {
    let out = decoded(&profidrive_ppo1("out", "23ED 0000 0000 0001 0000 0000"));
    assert_eq!(
        cells(line(&out, "code")),
        ["code", "2", "change the parameter value (word)"]
    );
    assert_eq!(cells(line(&out, "value")), ["value", "1 (0x0001)"]);
    let doc = json(&profidrive_ppo1("out", "83ED 0300 0001 86A0 0000 0000"));
    let pkw = &doc["telegram"]["pkw"];
    assert_eq!(pkw["channel"], "profidrive");
    assert_eq!(pkw["code"], 8);
    assert_eq!(
        pkw["parameter"],
        serde_json::json!({ "address": 1005, "name": "P10.05", "subindex": 3 })
    );
    assert_eq!(pkw["value"], 100_000);
    assert_eq!(pkw["refused"], serde_json::Value::Null);
}

/// Response 7 with the error number in PWE2: the profile's text, or the
/// manuals' that give a number beyond it, or the drive's own.
#[test]
fn profidrive_error_answers_name_the_error_number() {
    let out = decoded(&profidrive_ppo1("in", "73ED 0000 0000 0002 0000 0000"));
    assert_eq!(line(&out, "PKW"), "PKW response");
    assert_eq!(
        cells(line(&out, "code")),
        ["code", "7", "the request cannot be executed"]
    );
    assert_eq!(
        cells(line(&out, "error")),
        ["error", "2", "low or high limit exceeded"]
    );
    let vendor = decoded(&profidrive_ppo1("in", "73ED 0000 0000 006A 0000 0000"));
    assert_eq!(
        cells(line(&vendor, "error")),
        [
            "error",
            "106",
            "request not implemented (MICROMASTER 4, MASTERDRIVES, SINAMICS G120: device-specific)"
        ]
    );
    let own = json(&profidrive_ppo1("in", "73ED 0000 0000 0032 0000 0000"));
    assert_eq!(
        own["telegram"]["pkw"]["error"],
        serde_json::json!({
            "code": 50,
            "text": "not a number any of the manuals gives: the drive's own"
        })
    );
}

/// Ids beyond the profile decode, and say that the card refuses them.
#[test]
fn profidrive_ids_beyond_the_profile_are_refused() {
    let out = decoded(&profidrive_ppo1("out", "E3ED 0000 0000 0001 0000 0000"));
    assert_eq!(
        cells(line(&out, "code")),
        ["code", "14", "not the profile's"]
    );
    assert_eq!(
        line(&out, "parameter").trim(),
        "parameter  P10.05 (PNU 1005), subindex 0"
    );
    assert!(
        line(&out, "refused").contains(
            "request id 14 is not the profile's (0 to 9): 11 to 15 are Siemens' extensions"
        ),
        "{out}"
    );
    let report = json(&profidrive_ppo1("in", "93ED 0000 0000 0001 0000 0000"));
    let pkw = &report["telegram"]["pkw"];
    assert_eq!(pkw["code"], 9);
    assert_eq!(pkw["meaning"], "a parameter change report");
    assert_eq!(pkw["parameter"], serde_json::Value::Null);
    assert!(pkw["refused"]
        .as_str()
        .unwrap()
        .starts_with("response id 9 is a parameter change report (9 to 12)"));
}

/// MV810: the status word bit by bit, PZD2 named after the mapping given.
#[test]
fn mv810_status_word_and_mapped_word_as_a_table() {
    let out = decoded(&[
        MV810,
        "--module",
        "PKW + 2 PZD",
        "--direction",
        "in",
        "--mapping",
        "pzd_in=3",
        "01 02 00 03 2B 02 00 01 0461 1388",
    ]);
    assert_eq!(
        cells(line(&out, "10  PZD2")),
        [
            "10",
            "PZD2",
            "1388",
            "5000",
            "Output frequency (0.01 Hz)",
            "PZD2 feedback = 3, --mapping"
        ]
    );
    assert_eq!(
        line(&out, "Slave response status word ("),
        "Slave response status word (byte 8) = 0x0461"
    );
    assert_eq!(
        cells(line(&out, "9-10")),
        ["9-10", "Control mode", "2", "Communication"]
    );
    let motor = out.lines().find(|l| l.contains("Motor number")).unwrap();
    assert_eq!(cells(motor), ["6", "Motor number", "1", "Motor 2"]);
    assert_eq!(
        cells(line(&out, "stations")),
        ["stations", "target 1, source 2"]
    );
    assert_eq!(cells(line(&out, "code")), ["code", "0x03", "value read"]);
    assert_eq!(cells(line(&out, "value")), ["value", "1 (0x0001)"]);
}

fn md810_default_prm() -> String {
    format!("000000{}", "F000".repeat(30))
}

/// The telegram, the parameter telegram that maps it and a diagnosis block,
/// in one JSON document.
#[test]
fn md810_json_document_field_by_field() {
    // The manual's PZD3 out = F0-12 (bytes 7-8).
    let mut prm = md810_default_prm();
    prm.replace_range(14..18, "F00C");
    let doc = json(&[
        MD810,
        "--module",
        "PPO2",
        "--direction",
        "out",
        "--prm",
        &prm,
        "--diag",
        "03 00 34",
        "20F0 0800 0000 07D0 0000 0000 1388 0000 0000 0000",
    ]);
    assert_eq!(doc["description"], "md810dp.toml");

    let t = &doc["telegram"];
    assert_eq!(t["module"], "PPO2");
    assert_eq!(t["direction"], "out");
    assert_eq!(t["len"], 20);
    let words = t["words"].as_array().unwrap();
    assert_eq!(words.len(), 10);
    assert_eq!(words[0]["name"], "PKE");
    assert_eq!(words[0]["value"], 0x20F0);
    let pzd3 = &words[6];
    assert_eq!(
        (pzd3["offset"].as_u64(), pzd3["name"].as_str()),
        (Some(12), Some("PZD3"))
    );
    assert_eq!(pzd3["value"], 5000);
    assert_eq!(pzd3["carries"]["mapping"], "PZD3(master->slaver)");
    assert_eq!(pzd3["carries"]["value"], 0xF00C);
    assert_eq!(pzd3["carries"]["meaning"], "F0-12");
    assert_eq!(pzd3["carries"]["source"], "parameter_telegram");
    assert_eq!(words[5]["carries"]["meaning"], "F0-00");

    let pkw = &t["pkw"];
    assert_eq!(pkw["channel"], "pke-ind-pwe");
    assert_eq!(pkw["kind"], "request");
    assert_eq!(pkw["code"], 2);
    assert_eq!(pkw["meaning"], "write");
    assert_eq!(pkw["parameter"]["name"], "F0-08");
    assert_eq!(pkw["parameter"]["address"], 0xF008);
    assert_eq!(pkw["value"], 2000);
    assert!(pkw["error"].is_null() && pkw["refused"].is_null() && pkw["stations"].is_null());

    let prm = &doc["prm"];
    assert_eq!(prm["len"], 63);
    assert_eq!(prm["constant"].as_array().unwrap().len(), 3);
    assert_eq!(prm["constant"][0]["name"], "DPV1_Status_1");
    let params = prm["params"].as_array().unwrap();
    assert_eq!(params.len(), 30);
    assert_eq!(params[2]["offset"], 7);
    assert_eq!(params[2]["id"], 3);
    assert_eq!(params[2]["name"], "PZD3(master->slaver)");
    assert_eq!(params[2]["value"], 0xF00C);
    assert_eq!(params[2]["meaning"], "F0-12");
    assert_eq!(params[2]["default"], 0xF000);
    assert_eq!(params[2]["default_meaning"], "F0-00");
    assert_eq!(params[2]["allowed"], true);
    assert_eq!(params[29]["name"], "Index5");

    let diag = &doc["diagnosis"];
    assert_eq!(diag["len"], 3);
    assert_eq!(diag["header"], 3);
    assert_eq!(diag["bytes"], serde_json::json!([0x03, 0x00, 0x34]));
    assert_eq!(diag["areas"][0]["first_bit"], 8);
    assert_eq!(diag["areas"][0]["last_bit"], 15);
    assert_eq!(diag["areas"][0]["value"], 0x34);
    assert_eq!(diag["areas"][0]["text"], "DP card-drive comm. interrupted");
}

#[test]
fn parts_not_asked_for_are_null() {
    let doc = json(&[MD810, "--diag", "030034"]);
    assert!(doc["telegram"].is_null() && doc["prm"].is_null());
    assert_eq!(
        doc["diagnosis"]["areas"][0]["text"],
        "DP card-drive comm. interrupted"
    );
}

#[test]
fn mv810_json_read_of_p43_02() {
    let doc = json(&[
        MV810,
        "--module",
        "pkw + 12 pzd",
        "--direction",
        "out",
        "--mapping",
        "pzd_out=1",
        &format!("02 01 00 03 2B 02 00 01 0001 1388{}", " 0000".repeat(10)),
    ]);
    let t = &doc["telegram"];
    assert_eq!(t["module"], "PKW + 12 PZD");
    assert_eq!(t["len"], 32);
    let pkw = &t["pkw"];
    assert_eq!(pkw["channel"], "station-command-address-value");
    assert_eq!(pkw["stations"]["target"], 2);
    assert_eq!(pkw["stations"]["source"], 1);
    assert_eq!(pkw["code"], 3);
    assert_eq!(pkw["meaning"], "read one");
    assert_eq!(pkw["parameter"]["name"], "P43.02");
    assert!(pkw["value"].is_null());
    let control = &t["words"][4];
    assert_eq!(control["name"], "Master sends control command word");
    assert_eq!(control["fields"][0]["name"], "Forward running");
    assert_eq!(control["fields"][0]["value"], 1);
    let pzd2 = &t["words"][5]["carries"];
    assert_eq!(pzd2["meaning"], "Frequency reference (0.00 to P02.10)");
    assert_eq!(pzd2["source"], "given");
    assert_eq!(t["words"][6]["carries"]["meaning"], "Disabled");
    assert_eq!(t["words"][6]["carries"]["source"], "default");
}

/// An error: exit 1, its code, the argument it points into and where.
fn fails(args: &[&str], code: &str, place: &str) -> String {
    let output = gsdc(args);
    let err = stderr(&output);
    assert_eq!(output.status.code(), Some(1), "{err}");
    assert!(output.stdout.is_empty(), "nothing decoded on an error");
    assert!(err.starts_with(&format!("error[{code}]")), "{err}");
    assert!(err.contains(&format!(" --> {place}\n")), "{err}");
    err
}

fn ppo1(hex: &str) -> Vec<&str> {
    vec![MD810, "--module", "PPO1", "--direction", "out", hex]
}

#[test]
fn bad_hex_digits_and_lengths_point_into_the_telegram() {
    let err = fails(&ppo1("10F0 08G0 0000 0000 0000 0000"), "E410", "HEX:1:8");
    assert!(err.contains("|        ^ not 0-9 or A-F"), "{err}");
    fails(&ppo1("10F0 080 0000 0000 0000 0000"), "E411", "HEX:1:6");
    let err = fails(&ppo1("10F0 0800 0000 0000"), "E412", "HEX:1:20");
    assert!(err.contains("4 byte(s) missing"), "{err}");
    assert!(err.contains("PPO1 is 12 bytes each way"), "{err}");
    let err = fails(
        &ppo1("10F0 0800 0000 0000 0000 0000 FFFF"),
        "E412",
        "HEX:1:31",
    );
    assert!(err.contains("^^^^ 2 byte(s) too many"), "{err}");
}

#[test]
fn an_unknown_module_lists_the_modules() {
    let err = fails(
        &[MV810, "--module", "PKW + 13 PZD", "--direction", "in", "00"],
        "E413",
        "--module:1:1",
    );
    assert!(
        err.contains("help: the modules are: standard message 1, PKW + 1 PZD, PKW + 2 PZD,"),
        "{err}"
    );
}

#[test]
fn parts_the_description_lacks() {
    fails(&[MV810, "--prm", "00"], "E414", "--prm");
    fails(&[MV810, "--diag", "03 00 34"], "E414", "--diag");
}

#[test]
fn bad_mappings_point_into_the_option() {
    let with = |mapping: &'static str| {
        [
            MV810,
            "--module",
            "PKW + 2 PZD",
            "--direction",
            "out",
            "--mapping",
            mapping,
            "0000 0000 0000 0000 0000 0000",
        ]
    };
    fails(&with("pzd_put=1"), "E415", "--mapping:1:1");
    let err = fails(&with("pzd_out=1,99"), "E416", "--mapping:1:11");
    assert!(
        err.contains("help: it allows 0 Disabled, 1 Frequency reference (0.00 to P02.10), 2 "),
        "{err}"
    );
    fails(&with("pzd_out=x"), "E416", "--mapping:1:9");
}

#[test]
fn prm_and_diag_errors() {
    let err = fails(&[MD810, "--prm", "000000"], "E412", "--prm:1:7");
    assert!(
        err.contains("User_Prm_Data is 63 bytes; this is 3"),
        "{err}"
    );
    let err = fails(&[MD810, "--diag", "43 00 34"], "E417", "--diag:1:1");
    assert!(err.contains("identifier-related"), "{err}");
}

/// Usage errors are clap's: exit 2, nothing decoded.
#[test]
fn usage_errors_exit_2() {
    for args in [
        &[MD810][..],
        &[MD810, "0000"],
        &[MD810, "--module", "PPO1", "0000"],
        &[MD810, "--module", "PPO1", "--direction", "up", "0000"],
        &[MD810, "--module", "PPO3", "--diag", "030034"],
        &[
            MD810,
            "--module",
            "PPO3",
            "--direction",
            "out",
            "--prm",
            "00",
            "--mapping",
            "pzd_out=1",
            "0000 0000",
        ],
        &["descriptions/no-such.toml", "--diag", "030034"],
    ] {
        let output = gsdc(args);
        assert_eq!(
            output.status.code(),
            Some(2),
            "{args:?}: {}",
            stderr(&output)
        );
        assert!(output.stdout.is_empty());
    }
    let missing = gsdc(&["descriptions/no-such.toml", "--diag", "030034"]);
    assert!(
        stderr(&missing).starts_with("error: cannot read descriptions/no-such.toml: No such file"),
        "said once: {}",
        stderr(&missing)
    );
}

#[test]
fn an_invalid_description_exits_1() {
    let output = gsdc(&[
        "tests/fixtures/invalid/unknown_ppo.toml",
        "--diag",
        "030034",
    ]);
    assert_eq!(output.status.code(), Some(1));
    assert!(stderr(&output).contains("error[E104]"));
}

/// The folder of tests/snapshots this file's snapshots are in.
const SNAPSHOTS: &str = "decode";

/// The tables as a person sees them, reviewed line by line.
#[test]
fn snapshot_md810_read_answer_with_prm() {
    let mut prm = md810_default_prm();
    // PZD1 in = F0-08 (the running frequency the read answer shows).
    prm.replace_range(54..58, "F008");
    let out = decoded(&[
        MD810,
        "--module",
        "PPO1",
        "--direction",
        "in",
        "--prm",
        &prm,
        "10F0 0800 0000 1388 1388 0000",
    ]);
    support::snapshots_in(SNAPSHOTS, || {
        insta::assert_snapshot!("md810_read_answer_with_prm", out);
    });
}

#[test]
fn snapshot_mv810_status_word() {
    let out = decoded(&[
        MV810,
        "--module",
        "PKW + 2 PZD",
        "--direction",
        "in",
        "--mapping",
        "pzd_in=3",
        "01 02 00 83 2B 02 00 02 0468 1388",
    ]);
    support::snapshots_in(SNAPSHOTS, || {
        insta::assert_snapshot!("mv810_status_word", out)
    });
}

// ---------------------------------------------------------------------------
// The gateway (MD810 manual chapter 2)

const GATEWAY: &str = "descriptions/md810-gateway.toml";

/// User_Prm_Data of 2.4 step 5's totals, TPDO 120 words and RPDO 64: 15
/// slaves of 8 TPDO words, the first 8 of them with 8 RPDO words.
fn manual_example_prm() -> String {
    format!(
        "0F{}{}{}",
        "0808".repeat(8),
        "0800".repeat(7),
        "0000".repeat(15)
    )
}

#[test]
fn gateway_prm_as_a_table() {
    let out = decoded(&[GATEWAY, "--prm", &manual_example_prm()]);
    assert!(out.starts_with("User_Prm_Data, 61 bytes\n"), "{out}");
    assert_eq!(
        cells(line(&out, "0  Number of CANopen slaves")),
        [
            "0",
            "Number of CANopen slaves",
            "Unsigned8",
            "0F",
            "15",
            "1"
        ]
    );
    assert_eq!(
        cells(line(&out, "29  Slave 15 TPDO words")),
        ["29", "Slave 15 TPDO words", "Unsigned8", "08", "8", "0"]
    );
    assert_eq!(line(&out, "Gateway nodes"), "Gateway nodes");
    assert_eq!(cells(line(&out, "in use")), ["in use", "15"]);
    assert_eq!(
        cells(line(&out, "input ")),
        ["input", "120 words, 240 bytes (at most 244)"]
    );
    assert_eq!(
        cells(line(&out, "output ")),
        ["output", "64 words, 128 bytes (at most 244)"]
    );
    assert!(!out.contains("refused"), "{out}");
}

#[test]
fn gateway_prm_with_a_value_out_of_range() {
    let mut prm = manual_example_prm();
    // Slave 2's TPDO words (byte 3): 9, one more than two PDOs carry.
    prm.replace_range(6..8, "09");
    let out = decoded(&[GATEWAY, "--prm", &prm]);
    assert_eq!(
        cells(line(&out, "3  Slave 2 TPDO words")),
        [
            "3",
            "Slave 2 TPDO words",
            "Unsigned8",
            "09",
            "9",
            "not allowed (0 to 8)",
            "0"
        ]
    );
    assert_eq!(
        cells(line(&out, "refused")),
        ["refused", "Slave 2 TPDO words: 9 is not allowed (0 to 8)"]
    );
}

#[test]
fn gateway_diagnosis_as_a_table_and_as_json() {
    let out = decoded(&[GATEWAY, "--diag", "05 04 02 12 34"]);
    assert!(
        out.starts_with(
            "Diagnosis block, 5 bytes: 05 04 02 12 34 (header 0x05: device-related, 5 bytes)\n"
        ),
        "{out}"
    );
    assert_eq!(
        cells(line(&out, "1  type")),
        ["1", "type", "04", "4", "Drive reports fault"]
    );
    assert_eq!(cells(line(&out, "2  node")), ["2", "node", "02", "2"]);
    assert_eq!(
        cells(line(&out, "3-4  code")),
        ["3-4", "code", "1234", "4660", "Drive fault code"]
    );
    let doc = json(&[GATEWAY, "--diag", "04 03 1F 20"]);
    let g = &doc["diagnosis"]["gateway"];
    assert_eq!(doc["diagnosis"]["areas"], serde_json::json!([]));
    assert_eq!(g["type"]["text"], "CANopen network fault");
    assert_eq!(g["node"]["value"], 31);
    assert_eq!(g["node"]["allowed"], false);
    assert_eq!(g["node"]["range"], serde_json::json!([1, 30]));
    assert_eq!(g["code"]["value"], 32);
    assert_eq!(g["code"]["text"], "CANopen slave dropped out while running");
    let out = decoded(&[GATEWAY, "--diag", "04 03 1F 20"]);
    assert_eq!(
        cells(line(&out, "2  node")),
        ["2", "node", "1F", "31", "not a node (1 to 30)"]
    );
}

/// Slave 1 and 2 send 8 words each: INPUT 16 words is the whole input.
#[test]
fn gateway_module_words_named_after_their_nodes_in_json() {
    let prm = format!("02080808{}", "00".repeat(57));
    let words = (1..=16).map(|w| format!("{w:04X}")).collect::<Vec<_>>();
    let mut args = vec![
        GATEWAY,
        "--prm",
        &prm,
        "--module",
        "input 16 words",
        "--direction",
        "in",
    ];
    args.extend(words.iter().map(String::as_str));
    let doc = json(&args);
    let t = &doc["telegram"];
    assert_eq!(t["module"], "INPUT 16 words");
    assert_eq!(t["len"], 32);
    assert_eq!(t["gateway"]["source"], "parameter_telegram");
    assert_eq!(t["gateway"]["attributed"], true);
    assert_eq!(t["gateway"]["nodes"]["input_words"], 16);
    assert_eq!(t["words"][8]["name"], "word 9");
    assert_eq!(t["words"][8]["value"], 9);
    assert_eq!(
        t["words"][8]["node"],
        serde_json::json!({ "node": 2, "word": 1 })
    );
    assert_eq!(
        t["words"][7]["node"],
        serde_json::json!({ "node": 1, "word": 8 })
    );
    assert_eq!(doc["prm"]["gateway"]["node_count"], 2);
    assert_eq!(doc["prm"]["params"][0]["range"], serde_json::json!([1, 30]));
    assert_eq!(doc["prm"]["params"][0]["data_type"], "Unsigned8");
    // Under the defaults no slave sends a word: numbered, not named.
    let out = decoded(&[
        GATEWAY,
        "--module",
        "INPUT 1 word",
        "--direction",
        "in",
        "0001",
    ]);
    assert_eq!(cells(line(&out, "0  word 1")), ["0", "word 1", "0001", "1"]);
    assert!(out.ends_with("Under the defaults the 1 node(s) in use send 0 word(s), fewer than this module's 1: the card refuses a configuration with this module.\n"), "{out}");
}

#[test]
fn gateway_errors_point_into_their_argument() {
    let err = fails(
        &[
            GATEWAY,
            "--module",
            "INPUT 16 words",
            "--direction",
            "out",
            "0000",
        ],
        "E413",
        "--module:1:1",
    );
    assert!(err.contains("^^^^^^^^^^^^^^ an input module"), "{err}");
    assert!(
        err.contains("help: the output modules (--direction out) are: OUTPUT 1 word,"),
        "{err}"
    );
    let err = fails(&[GATEWAY, "--diag", "04 04 02 12"], "E417", "--diag:1:1");
    assert!(
        err.contains("a block of type 4 (Drive reports fault) is 5 bytes"),
        "{err}"
    );
    let err = fails(&[GATEWAY, "--diag", "04 01 02"], "E412", "--diag:1:9");
    assert!(
        err.contains("4 bytes for type 1 or 3, 5 bytes for type 4"),
        "{err}"
    );
    fails(&[GATEWAY, "--diag", "C4 01 02 23"], "E417", "--diag:1:1");
    let err = fails(&[GATEWAY, "--prm", "0F"], "E412", "--prm:1:3");
    assert!(
        err.contains(
            "the 61 gateway parameters from Number of CANopen slaves to Slave 30 RPDO words"
        ),
        "{err}"
    );
    let err = fails(
        &[
            GATEWAY,
            "--module",
            "INPUT 1 word",
            "--direction",
            "in",
            "--mapping",
            "pzd_in=1",
            "0000",
        ],
        "E415",
        "--mapping:1:1",
    );
    assert!(
        err.contains("help: the description has no mappings"),
        "{err}"
    );
}

/// The gateway with each slave's TPDO words in bits 0-3 and RPDO words in
/// bits 4-7 of one byte, written into `dir` with the symbols it names.
fn gateway_in_bit_areas(dir: &std::path::Path) -> std::path::PathBuf {
    descriptions::copy_symbols(dir);
    let path = dir.join("md810-gateway-bits.toml");
    std::fs::write(&path, descriptions::gateway_in_bit_areas()).unwrap();
    path
}

/// The tables as a person sees them, reviewed line by line: bit areas
/// sharing bytes, one not allowed, the card's refusal, and a drive fault.
#[test]
fn snapshot_gateway_bit_areas_and_drive_fault() {
    let dir = support::scratch("gateway-bits");
    let path = gateway_in_bit_areas(&dir);
    // 2 slaves; slave 1 sends 8 and receives 9 words (byte 1 = 0x98), slave 2 sends 8.
    let prm = format!("02 98 08{}", " 00".repeat(28));
    let out = decoded(&[
        path.to_str().unwrap(),
        "--prm",
        &prm,
        "--diag",
        "05 04 02 12 34",
    ]);
    support::snapshots_in(SNAPSHOTS, || {
        insta::assert_snapshot!("gateway_bit_areas_and_drive_fault", out);
    });
}

/// Every worked example of a manual (a description's `[[examples]]`), each
/// telegram it stands for, through `gsdc decode`: the PKW words read as the
/// example prints them, a request out and a response in, none refused; in
/// the module the example names, or (for the PKW words alone) in the first
/// module that has them, its PZD words 0.
#[test]
fn every_example_of_the_manuals_decodes() {
    let mut decoded_examples = 0;
    for (name, ir) in descriptions::all_valid() {
        let folder = if descriptions::shipped().contains(&name) {
            "descriptions"
        } else {
            "tests/fixtures/valid"
        };
        let path = format!("{folder}/{name}");
        for example in &ir.examples {
            let (module, bytes, pkw) = example_module(&ir, example.module.as_deref());
            let direction = match example.direction {
                gsdc::ir::Direction::Out => ("out", "request"),
                _ => ("in", "response"),
            };
            for telegram in example.instances() {
                let mut full = telegram.clone();
                full.resize(bytes, 0);
                let hex: String = full.iter().map(|b| format!("{b:02X}")).collect();
                let document =
                    json(&[&path, "--module", &module, "--direction", direction.0, &hex]);
                let decoded = &document["telegram"];
                let context = format!("{name} {} {hex}", example.section);
                assert_eq!(decoded["len"], bytes, "{context}");
                for (i, word) in telegram.chunks(2).enumerate() {
                    let value = u16::from_be_bytes([word[0], word[1]]);
                    assert_eq!(decoded["words"][i]["value"], value, "{context}");
                }
                if pkw {
                    assert_eq!(decoded["pkw"]["kind"], direction.1, "{context}");
                    assert_eq!(
                        decoded["pkw"]["refused"],
                        serde_json::Value::Null,
                        "{context}"
                    );
                }
                decoded_examples += 1;
            }
        }
    }
    // MD810 1.4.2: a read and a write, each answered done or failed with
    // one of four error codes.
    assert_eq!(decoded_examples, 2 * (2 + 4));
}

/// The module `gsdc decode` is told, its bytes and whether it has the PKW
/// channel: the one the example names (a PPO type by its type), else the
/// first with the PKW channel.
fn example_module(ir: &gsdc::Ir, named: Option<&str>) -> (String, usize, bool) {
    let ppo = ir
        .profibus
        .iter()
        .flat_map(|p| &p.modules)
        .map(|m| (format!("PPO{}", m.ppo), m.name.clone(), m.layout));
    let pn = ir
        .profinet
        .iter()
        .flat_map(|p| &p.modules)
        .map(|m| (m.name.text.en.clone(), m.name.text.en.clone(), m.layout));
    let (module, _, layout) = ppo
        .chain(pn)
        .find(|(_, shown, layout)| match named {
            Some(named) => shown == named,
            None => layout.pkw,
        })
        .expect("lowering found the example's module");
    let words = usize::from(layout.pkw_words() + layout.pzd_words);
    (module, 2 * words, layout.pkw)
}
