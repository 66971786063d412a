//! A new user's first day with `gsdc decode` (issue 23): standard telegram
//! 1's control and status words bit by bit, the bits a description does not
//! name, and parameters numbered without a separator.

use crate::support::{gsdc, stderr};
use serde_json::Value;

/// `gsdc decode DESCRIPTION --format json ARGS...`, which must exit 0.
fn decode(description: &str, args: &[&str]) -> Value {
    let mut all = vec!["decode", description, "--format", "json"];
    all.extend(args);
    let output = gsdc(&all);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    serde_json::from_slice(&output.stdout).unwrap()
}

/// The fields of the telegram's first word: (first bit, name, value).
fn first_word_fields(decoded: &Value) -> (String, Vec<(u64, String, u64)>) {
    let word = &decoded["telegram"]["words"][0];
    let fields = word["fields"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| {
            (
                f["first"].as_u64().unwrap(),
                f["name"].as_str().unwrap().to_string(),
                f["value"].as_u64().unwrap(),
            )
        })
        .collect();
    (word["name"].as_str().unwrap().to_string(), fields)
}

const PROFIDRIVE: &str = "tests/fixtures/valid/profidrive.toml";

/// 047F: ON, no OFF2, no OFF3, enable operation, ramp generator enabled
/// and unfrozen, setpoint enabled, control by PLC: the usual "run" word of
/// the profile's state machine.
#[test]
fn a_profidrive_cards_stw1_is_split_into_the_profiles_bits() {
    let decoded = decode(
        PROFIDRIVE,
        &[
            "--module",
            "Standard telegram 1",
            "--direction",
            "out",
            "047F",
            "4000",
        ],
    );
    let (word, fields) = first_word_fields(&decoded);
    assert_eq!(word, "STW1 (control word 1)");
    let set: Vec<&str> = fields
        .iter()
        .filter(|(_, _, value)| *value == 1)
        .map(|(_, name, _)| name.as_str())
        .collect();
    assert_eq!(
        set,
        [
            "ON (0: OFF1)",
            "No coast stop (0: OFF2)",
            "No quick stop (0: OFF3)",
            "Enable operation",
            "Enable ramp generator",
            "Unfreeze ramp generator",
            "Enable setpoint",
            "Control by PLC"
        ]
    );
    let bits: Vec<u64> = fields.iter().map(|(bit, _, _)| *bit).collect();
    assert_eq!(
        bits,
        (0..=10).collect::<Vec<u64>>(),
        "the profile's 11 bits"
    );
}

/// ZSW1 F237: bits 12 to 15 are the device's own, which the description
/// does not describe; set, each is shown as such.
#[test]
fn a_profidrive_cards_zsw1_shows_the_device_bits_as_not_described() {
    let decoded = decode(
        PROFIDRIVE,
        &[
            "--module",
            "Standard telegram 1",
            "--direction",
            "in",
            "F237",
            "0000",
        ],
    );
    let (word, fields) = first_word_fields(&decoded);
    assert_eq!(word, "ZSW1 (status word 1)");
    let named = |bit: u64| {
        fields
            .iter()
            .find(|f| f.0 == bit)
            .map(|f| (f.1.as_str(), f.2))
    };
    assert_eq!(named(0), Some(("Ready to switch on", 1)));
    assert_eq!(named(3), Some(("Fault present", 0)));
    assert_eq!(named(9), Some(("Control requested", 1)));
    assert_eq!(named(11), None, "clear and not described: not shown");
    for bit in 12..=15 {
        let name = format!("bit {bit} (not described)");
        assert_eq!(named(bit), Some((name.as_str(), 1)));
    }
}

/// MV810 is no PROFIdrive card: its "standard message 1" keeps the
/// manual's status word, and bit 15, which the manual does not name,
/// shows as not described; so does PPO and PROFINET modules' PZD1.
#[test]
fn a_vendor_word_shows_a_set_bit_it_does_not_name() {
    let mv810 = "descriptions/mv810-pnet02.toml";
    // The words before PZD1: none, or the PKW channel's four.
    for (module, pkw) in [("standard message 1", 0), ("PKW + 2 PZD", 4)] {
        let mut args = vec!["--module", module, "--direction", "in"];
        args.extend(std::iter::repeat_n("0000", pkw));
        args.extend(["8468", "0000"]);
        let decoded = decode(mv810, &args);
        let word = &decoded["telegram"]["words"][pkw];
        let fields = word["fields"].as_array().unwrap();
        let first = &fields[0];
        assert_eq!(first["name"], "Forward running", "{module}");
        let last = fields.last().unwrap();
        assert_eq!(
            (&last["first"], &last["name"], &last["value"]),
            (
                &Value::from(15),
                &Value::from("bit 15 (not described)"),
                &Value::from(1)
            ),
            "{module}"
        );
        // Bit 10 is set too, and named: part of the manual's control mode.
        assert!(fields.iter().all(|f| f["name"] != "bit 10 (not described)"));
    }
}

/// Parameters numbered without a separator (tests/fixtures/valid/ax200.toml:
/// P1120, r0947): a PKW answer names r0947 as the description writes it, a
/// request the parameter P1120 it does not name with the first prefix.
#[test]
fn pkw_parameters_are_named_as_the_description_numbers_them() {
    let ax200 = "tests/fixtures/valid/ax200.toml";
    let pkw_parameter = |direction: &str, hex: &str| {
        let decoded = decode(ax200, &["--module", "PPO1", "--direction", direction, hex]);
        decoded["telegram"]["pkw"]["parameter"]["name"].clone()
    };
    // AK 1 (the value, a word) for PNU 947: 0x13B3.
    assert_eq!(
        pkw_parameter("in", "13B3 0000 0000 0005 0000 0000"),
        "r0947"
    );
    assert_eq!(
        pkw_parameter("out", "1460 0000 0000 0000 0000 0000"),
        "P1120"
    );
    // A mapping given as the description writes its parameters.
    let mapped = decode(
        ax200,
        &[
            "--module",
            "4 PZD",
            "--direction",
            "in",
            "--mapping",
            "pzd_in=r0947",
            "0000 0000 0000 0000",
        ],
    );
    assert_eq!(
        mapped["telegram"]["words"][2]["carries"]["meaning"], "r0947",
        "{mapped:#}"
    );
}
