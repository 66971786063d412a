//! The DP exchange (issue 20, "On the wire"): scripts/wire-test.sh runs, for
//! every description with [profibus], profirust's DP master configured only
//! from the GSD gsdc builds, against the DP slave of wire/dp built only from
//! the layout, on profirust's simulated bus. The wire workspace's own tests,
//! lints and formatting run here too.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::{Mutex, MutexGuard};

use crate::support::{self, descriptions, stdout};

/// The wire workspace is built with the descriptions each run names, in
/// one target directory: the tests here and in wire_pn.rs take turns, so
/// that no run rebuilds it under another's feet.
pub(crate) fn turn() -> MutexGuard<'static, ()> {
    static WIRE: Mutex<()> = Mutex::new(());
    WIRE.lock().unwrap_or_else(|poisoned| poisoned.into_inner())
}

fn root() -> &'static Path {
    Path::new(support::CHECKOUT)
}

/// The wire workspace's target directory, under this test's own.
pub(crate) fn wire_target() -> PathBuf {
    Path::new(env!("CARGO_TARGET_TMPDIR")).join("wire-target")
}

/// scripts/wire-test.sh with `args`, the DP exchange only (the PROFINET one
/// is wire/pn's), with the gsdc this test was built with.
fn wire_test(args: &[&str]) -> Output {
    let _turn = turn();
    Command::new(root().join("scripts/wire-test.sh"))
        .args(["--bus", "dp"])
        .args(args)
        .current_dir(root())
        .env("GSDC", support::GSDC)
        .env("WIRE_TARGET_DIR", wire_target())
        .env("CARGO", env!("CARGO"))
        .output()
        .expect("the script runs")
}

/// Every shipped description and valid fixture with [profibus], as
/// `descriptions/md810dp.toml`, with the exchanges it must pass: each of its
/// modules twice (with the defaults and with every parameter set by name;
/// a gateway's modules once per size, in and out together), the manuals'
/// exchanges, the three refusals.
fn with_profibus() -> Vec<(String, usize)> {
    let mut found = Vec::new();
    for folder in ["descriptions", "tests/fixtures/valid"] {
        for name in support::file_names(&root().join(folder)) {
            if !name.ends_with(".toml") {
                continue;
            }
            let ir = descriptions::load_from(folder, &name);
            let Some(profibus) = &ir.profibus else {
                continue;
            };
            // A PROFIsafe module is not exchanged: no F-host at either end.
            let modules = profibus.modules.iter().filter(|m| m.safety.is_none());
            let modules = modules.count();
            let exchanges = match name.as_str() {
                // MD810 1.4.2, 1.6 step 5, 1.8.
                "md810dp.toml" => 2 * modules + 3,
                // PI9000 I-3: the command word and mappings, the fault.
                "9kdp1.toml" => 2 * modules + 2,
                // Five sizes of module, and the manual's 2.4 example.
                "md810-gateway.toml" => 5 + 1,
                _ => 2 * modules,
            };
            found.push((format!("{folder}/{name}"), exchanges + 3));
        }
    }
    found
}

/// Every description with [profibus] passes every exchange: every module
/// with the defaults and with every parameter set by name, the manuals'
/// telegrams and diagnosis, the three refusals. The counts say that each
/// ran: a module or a manual's exchange that is lost fails here.
#[test]
fn every_description_with_profibus_passes_the_dp_exchange() {
    let descriptions = with_profibus();
    let shipped: Vec<&str> = descriptions
        .iter()
        .map(|(path, _)| path.as_str())
        .filter(|path| path.starts_with("descriptions/"))
        .collect();
    assert_eq!(
        shipped,
        [
            "descriptions/9kdp1.toml",
            "descriptions/md810-gateway.toml",
            "descriptions/md810dp.toml",
        ]
    );
    let args: Vec<&str> = descriptions.iter().map(|(path, _)| path.as_str()).collect();
    let output = wire_test(&args);
    let text = stdout(&output);
    assert!(
        output.status.success(),
        "{text}{}",
        String::from_utf8_lossy(&output.stderr)
    );
    for (path, exchanges) in &descriptions {
        let summary = format!("{path}: {exchanges} exchanges passed, 0 failed");
        assert!(text.contains(&summary), "{summary}\n{text}");
    }
    assert!(!text.contains("FAILED"), "{text}");
    // AX200's ramp-down time is a setting of one byte (`type =
    // "Unsigned8"`), after the fault reaction's word: the master sets it
    // from the GSD (its default 10, then 191 by name), the slave's layout
    // reads it there.
    for line in [
        "User_Prm_Data (19 bytes) 04 2E 04 2E 04 2E 04 2E 00 15 00 1B 03 B3 03 B3 00 00 0A",
        "User_Prm_Data (19 bytes) 07 FF 07 FE 07 FD 07 FC 07 FB 07 FA 07 F9 07 F8 00 01 BF",
        "ok: Data_Exch; the slave decoded the 10 parameters as the master set them",
    ] {
        assert!(text.contains(line), "{line}\n{text}");
    }
}

/// Any description, not only the shipped ones: a card of one's own (9KDP1's
/// description under another name, ident number and file name) is built
/// into the firmware from its layout's tables and passes, its modules with
/// their defaults and with every parameter set by name, and the refusals
/// (no manual's exchange: its drive has no manual).
#[test]
fn a_description_of_ones_own_passes() {
    let dir = support::scratch("own");
    descriptions::copy_symbols(&dir);
    let text = descriptions::shipped_text("9kdp1.toml")
        .replace("value = 0x9D01", "value = 0x4242")
        .replace("\"9KDP1.GSD\"", "\"ACME.GSD\"");
    let path = dir.join("acme-card.toml");
    std::fs::write(&path, text).unwrap();
    let output = wire_test(&[path.to_str().unwrap()]);
    let text = stdout(&output);
    assert!(output.status.success(), "{text}");
    assert!(
        text.contains("ACME.GSD comes from the same description and says ident 0x4242"),
        "{text}"
    );
    assert!(
        text.contains("acme-card.toml: 7 exchanges passed, 0 failed"),
        "{text}"
    );
}

/// MD810 manual 1.4.2, figures 6 and 7, and 1.8, as the master sent and
/// read them; PI9000 appendix I's fault and the bridge's type/node/code
/// blocks (2.5), named by the GSD and by `gsdc decode --diag`.
#[test]
fn the_manuals_telegrams_cross_the_bus() {
    let scratch = support::scratch("wire-results");
    let results = scratch.join("results.txt");
    let output = wire_test(&[
        "--results",
        results.to_str().unwrap(),
        "descriptions/md810dp.toml",
        "descriptions/9kdp1.toml",
        "descriptions/md810-gateway.toml",
    ]);
    let text = stdout(&output);
    assert!(output.status.success(), "{text}");
    for line in [
        // 1.4.2: read F0-08, write 20.00 Hz, an illegal address.
        "Data_Exch  out 10F0 0800 0000 0000 0000 0000\n               in  10F0 0800 0000 1388 0000 0000\n    ok: as the manual answers",
        "Data_Exch  out 20F0 0800 0000 07D0 0000 0000\n               in  10F0 0800 0000 07D0 0000 0000\n    ok: as the manual answers",
        "Data_Exch  out 10F0 6300 0000 0000 0000 0000\n               in  70F0 6300 0000 0002 0000 0000\n    ok: as the manual answers",
        // PZD2 of PPO2 mapped by name to F0-08, PZD3 reading it back.
        "out 0000 0000 0000 0000 0000 0BB8 0000 0000 0000 0000\n               in  0000 0000 0000 0000 0000 0000 0BB8",
        // 1.8: the card lost the drive.
        "device-related block 03 00 34\n      the GSD     8-15: 52 = \"DP card-drive comm. interrupted\"",
        "gsdc decode 8-15  2     34      52  DP card-drive comm. interrupted",
        // PI9000 I-3: forward run, 50.00 %, F0.03, status stop, no fault.
        "out 0001 1388 0000 0000 0000 0000\n               in  0003 1388 0001 0000 0000 0000",
        "device-related block 03 00 0B\n      the GSD     8-15: 11 = \"Motor Overload\"",
        // MD810 2.4 step 5: 120 TPDO words in, 64 RPDO words out.
        "ok: each of the 15 nodes received its words and sent its own",
        "device-related block 04 03 07 20\n      the GSD     0-7: 3 = \"CANopen network fault\"; 16-23: 32 = \"CANopen slave lost while running\"",
        "gsdc decode    3  code     20      32  CANopen slave dropped out while running",
        "device-related block 05 04 02 00 12",
    ] {
        assert!(text.contains(line), "{line}\n{text}");
    }
    // The refusals, as profirust's master reports them.
    for line in [
        "refused: another ident number, 0x0811\n    Set_Prm    ident 0x0811",
        "ok: the master reports ParameterError; Slave_Diag: DiagnosticFlags(STATION_NOT_READY | PARAMETER_FAULT | PARAMETER_REQUIRED), the slave's ident 0x0810",
        "refused: User_Prm_Data one byte short\n    Set_Prm    ident 0x0810, User_Prm_Data (62 bytes)",
        "refused: a module the slave does not have, config F4 F1",
        "ok: the master reports ConfigError; Slave_Diag: DiagnosticFlags(STATION_NOT_READY | CONFIGURATION_FAULT | PARAMETER_REQUIRED), the slave's ident 0x0810",
    ] {
        assert!(text.contains(line), "{line}\n{text}");
    }
    // The datasheet says what ran, of the very GSD gsdc builds; of the
    // GSDML, which no PROFINET exchange read here, that nothing is recorded.
    let gsd = built_file("descriptions/md810dp.toml", "MD810DP.GSD");
    let sheet = datasheet("descriptions/md810dp.toml", &results);
    let claim = format!(
        "MD810DP.GSD: every exchange passed (16 of them) between the DP master profirust 0.6.0, \
         configured only from this file through gsd-parser 0.6.0, and a DP slave built only from \
         this description's layout (wire/dp). The file's SHA-256: {}.",
        gsdc::wire::sha256_hex(&gsd)
    );
    assert!(sheet.contains(&claim), "{claim}\n{sheet}");
    assert!(
        sheet.contains("GSDML-V2.32-INOVANCE-MD810-20261122.xml: no exchange on the wire is recorded for this file"),
        "{sheet}"
    );
}

/// The bytes of `file` as `gsdc build` writes it from `description`.
fn built_file(description: &str, file: &str) -> Vec<u8> {
    let dir = support::scratch("wire-built");
    let output = support::gsdc(["build", description, "--out", dir.to_str().unwrap()]);
    assert!(output.status.success(), "{}", support::stderr(&output));
    std::fs::read(dir.join(file)).unwrap()
}

/// The English Markdown datasheet of `description`, given `results`.
fn datasheet(description: &str, results: &Path) -> String {
    let dir = support::scratch("wire-datasheet");
    let output = support::gsdc([
        "doc",
        description,
        "--out",
        dir.to_str().unwrap(),
        "--wire-results",
        results.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", support::stderr(&output));
    let stem = Path::new(description)
        .file_stem()
        .unwrap()
        .to_str()
        .unwrap();
    std::fs::read_to_string(dir.join(format!("{stem}.md"))).unwrap()
}

/// A directory of the files gsdc builds of `description`, its GSD changed
/// by `edit`: what was shipped.
#[track_caller]
fn shipped(name: &str, description: &str, edit: impl Fn(String) -> String) -> support::Scratch {
    let dir = support::scratch(name);
    let output = support::gsdc(["build", description, "--out", dir.to_str().unwrap()]);
    assert!(output.status.success(), "{}", support::stderr(&output));
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "GSD") {
            let text = std::fs::read_to_string(&path).unwrap();
            std::fs::write(&path, edit(text)).unwrap();
        }
    }
    dir
}

/// --files: the GSD shipped with another build (another fingerprint in its
/// header) still works with today's firmware.
#[test]
fn a_shipped_gsd_of_another_build_still_works() {
    let dir = shipped("wire-shipped", "descriptions/9kdp1.toml", |text| {
        text.replace(
            "; Description fingerprint: ",
            "; Description fingerprint: 0000",
        )
    });
    let results = dir.join("results.txt");
    let output = wire_test(&[
        "--files",
        dir.to_str().unwrap(),
        "--results",
        results.to_str().unwrap(),
        "descriptions/9kdp1.toml",
    ]);
    let text = stdout(&output);
    assert!(output.status.success(), "{text}");
    assert!(
        text.contains("9KDP1.GSD comes from a description of fingerprint 0000"),
        "{text}"
    );
    assert!(
        text.contains("descriptions/9kdp1.toml: 9 exchanges passed, 0 failed"),
        "{text}"
    );
    // The exchange is recorded of the file it read, and the datasheet of
    // today's description does not claim it: its GSD is another file.
    let recorded = std::fs::read_to_string(&results).unwrap();
    assert!(recorded.contains("\ndp 9KDP1.GSD "), "{recorded}");
    let sheet = datasheet("descriptions/9kdp1.toml", &results);
    assert!(
        sheet.contains("9KDP1.GSD: no exchange on the wire is recorded for this file"),
        "{sheet}"
    );
    assert!(!sheet.contains("every exchange passed"), "{sheet}");
}

/// A GSD that disagrees with the layout fails the exchange, exit 1, with
/// the module, the byte offset and both values: a config byte, and two
/// parameters whose offsets are swapped.
#[test]
fn a_gsd_that_disagrees_with_the_layout_fails_with_the_offset_and_both_values() {
    let config = shipped("wire-bad-config", "descriptions/md810dp.toml", |text| {
        text.replace(
            "Module = \"PPO1: 4 PKW + 2 PZD\" 0xF3,0xF1",
            "Module = \"PPO1: 4 PKW + 2 PZD\" 0xF3,0xF2",
        )
    });
    let output = wire_test(&[
        "--files",
        config.to_str().unwrap(),
        "descriptions/md810dp.toml",
    ]);
    let text = stdout(&output);
    assert_eq!(output.status.code(), Some(1), "{text}");
    assert!(
        text.contains("FAILED: module \"PPO1: 4 PKW + 2 PZD\", config byte 1: the GSD gives 0xF2, the layout 0xF1"),
        "{text}"
    );

    let swapped = shipped("wire-bad-prm", "descriptions/9kdp1.toml", |text| {
        text.replace(
            "Ext_User_Prm_Data_Ref(0)    = 1",
            "Ext_User_Prm_Data_Ref(0)    = 2",
        )
        .replace(
            "Ext_User_Prm_Data_Ref(2)    = 2",
            "Ext_User_Prm_Data_Ref(2)    = 1",
        )
    });
    let output = wire_test(&[
        "--files",
        swapped.to_str().unwrap(),
        "descriptions/9kdp1.toml",
    ]);
    let text = stdout(&output);
    assert_eq!(output.status.code(), Some(1), "{text}");
    assert!(
        text.contains("FAILED: modules [\"PPO3: 2 PZD\"], User_Prm_Data byte 0: \"PZD3 out Modbus address\" is 65535 as the master set it, 65534 as the slave decoded it"),
        "{text}"
    );
}

/// Usage and I/O errors are exit 2: no description, a directory that is
/// not there, a GSD missing from it.
#[test]
fn usage_errors_exit_2() {
    assert_eq!(wire_test(&[]).status.code(), Some(2));
    let output = wire_test(&["--files", "/nonexistent", "descriptions/9kdp1.toml"]);
    assert_eq!(output.status.code(), Some(2));
    let empty = support::scratch("empty");
    let output = wire_test(&[
        "--files",
        empty.to_str().unwrap(),
        "descriptions/9kdp1.toml",
    ]);
    assert_eq!(output.status.code(), Some(2), "{}", stdout(&output));
    assert!(stdout(&output).contains("9KDP1.GSD: no such file"));
}

/// The wire workspace's own tests pass, and it is free of clippy warnings
/// and formatted as rustfmt formats it.
#[test]
fn the_wire_workspace_is_tested_linted_and_formatted() {
    let workspace = root().join("wire");
    let _turn = turn();
    for args in [
        &["test", "--quiet", "--workspace"][..],
        &[
            "clippy",
            "--quiet",
            "--workspace",
            "--all-targets",
            "--",
            "-D",
            "warnings",
        ],
        // Not --all: that would take gsdc, a path dependency, too.
        &["fmt", "--check"],
    ] {
        let output = Command::new(env!("CARGO"))
            .args(args)
            .current_dir(&workspace)
            .env("CARGO_TARGET_DIR", wire_target())
            .env_remove("WIRE_DESCRIPTIONS")
            .output()
            .unwrap();
        assert!(
            output.status.success(),
            "cargo {}:\n{}{}",
            args.join(" "),
            String::from_utf8_lossy(&output.stdout),
            String::from_utf8_lossy(&output.stderr)
        );
    }
}
