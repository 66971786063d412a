//! `gsdc diff` on real releases of one device (`../shared/corpus/gsdml`),
//! as a user runs it: the human output is snapshot-tested
//! (`tests/snapshots/diff/`), and each snapshot's description is its
//! review, read against the two files (`diff` of their texts), with every
//! breaking change explained. Then what the command line does around the
//! comparison: exit codes, `--fail-on`, JSON, files it cannot read or
//! compare, descriptions.

use crate::support::{self, gsdc};

/// The releases compared, each pair's snapshot named after its test.
const PAIRS: [&str; 4] = [
    "rt_labs_iodevice_2019_to_2020",
    "p_net_sample_app_2021_to_2023",
    "p_net_sample_app_2023_to_2024",
    "leuze_bcl348i_2012_to_2015",
];

/// The path of a corpus GSDML file as the command line is given it.
fn corpus(name: &str) -> String {
    let path = format!("../shared/corpus/gsdml/{name}");
    assert!(
        support::checkout(&path).is_file(),
        "corpus file {path} is missing"
    );
    path
}

/// The human output of `gsdc diff OLD NEW`, and its exit code.
fn diff(old: &str, new: &str, extra: &[&str]) -> (String, i32) {
    let (old, new) = (corpus(old), corpus(new));
    let mut args = vec!["diff", old.as_str(), new.as_str()];
    args.extend(extra);
    let out = gsdc(&args);
    assert!(out.stderr.is_empty(), "{}", support::stderr(&out));
    (support::stdout(&out), out.status.code().unwrap())
}

/// The output's snapshot, with its review as the snapshot's description.
fn snapshot(name: &str, review: &str, output: &str) {
    assert!(PAIRS.contains(&name), "{name} is not in PAIRS");
    support::snapshots_in("diff", || {
        let mut settings = insta::Settings::clone_current();
        settings.set_description(review);
        settings.set_omit_expression(true);
        settings.bind(|| insta::assert_snapshot!(name, output));
    });
}

#[test]
fn every_snapshot_is_a_pair_of_releases() {
    support::assert_no_orphan_snapshots("diff", PAIRS);
}

#[test]
fn rt_labs_iodevice_2019_to_2020() {
    let (output, code) = diff(
        "GSDML-V2.33-rt-labs-IODevice-20191008.xml",
        "GSDML-V2.35-rtlabs-IODevice-20200603.xml",
        &[],
    );
    snapshot(
        "rt_labs_iodevice_2019_to_2020",
        "Read against the texts' diff: the schema and PNIO_Version go from V2.33/V2.32 to \
         V2.35, PhysicalSlots grows from 0..1 to 0..4 and each of the three modules may go \
         in slots 1..4 instead of 1 only, ResetToFactoryModes adds mode 1, the device's info \
         text names V2.35. Texts dropped from the text list (record names) were used by no \
         element: nothing to report. Nothing breaks a project made with the 2019 file.",
        &output,
    );
    assert_eq!(code, 0);
}

#[test]
fn p_net_sample_app_2021_to_2023() {
    let (output, code) = diff(
        "GSDML-V2.4-RT-Labs-P-Net-Sample-App-20210507.xml",
        "GSDML-V2.43-RT-Labs-P-Net-Sample-App-20230117.xml",
        &[],
    );
    snapshot(
        "p_net_sample_app_2021_to_2023",
        "Breaking, both explained: the sample moved from the placeholder IDs 0xFEED/0xBEEF to \
         RT-Labs' own vendor ID 0x0493 and device ID 0x0002. A controller checks both against \
         the device when it connects, so a project configured with the 2021 file cannot \
         start a device that runs the 2023 sample (and TIA Portal shows it as another device \
         altogether). Compatible: schema and PNIO_Version V2.43, the new Echo module (its \
         UseableModules entry is reported with the module). Cosmetic: the DAP's name, also \
         its submodule's (one change, two places), and the order number. TextIds renamed \
         with the same texts (Demo_1 to TOK_Demo_1) and whitespace are no change.",
        &output,
    );
    assert_eq!(code, 1, "breaking changes fail the run");
}

#[test]
fn p_net_sample_app_2023_to_2024() {
    let (output, code) = diff(
        "GSDML-V2.43-RT-Labs-P-Net-Sample-App-20230117.xml",
        "GSDML-V2.43-RT-Labs-P-Net-Sample-App-20240530.xml",
        &[],
    );
    snapshot(
        "p_net_sample_app_2023_to_2024",
        "Read against the texts' diff: the order number goes back to its 2021 value and the \
         device symbol's bitmap gets the IDs in its name; everything else is comments (a \
         commented-out shared-device DAP). Nothing but cosmetic changes.",
        &output,
    );
    assert_eq!(code, 0);
}

#[test]
fn leuze_bcl348i_2012_to_2015() {
    let (output, code) = diff(
        "GSDML-V2.25-LEUZE-BCL348i-20120814.xml",
        "GSDML-V2.31-LEUZE-BCL348i-20150923.xml",
        &[],
    );
    snapshot(
        "leuze_bcl348i_2012_to_2015",
        "Breaking, explained: the interface's DCP_HelloSupported goes from true to false. A \
         project made with the 2012 file may have the DCP Hello (prioritized startup) option \
         set for the scanner; with the 2015 file the engineering tool no longer offers it and \
         the device no longer announces itself that way, so such a project must be changed. \
         Compatible, each read in the file: DeviceAccessSupported false to true, \
         CheckDeviceID_Allowed, ResetToFactoryModes, PNIO_Version, DelayMeasurementSupported, \
         MRP client role and IsDefaultRingport added (SharedDeviceSupported, \
         SharedInputSupported and SupportsRingportConfig are added with their schema default \
         false: no change); AllowedValues 1..20 and 1..5 dropped from VisibleString \
         parameters (no limit left: widened); five modules added (M28, M29, M100-M102), their \
         UseableModules entries with them. A Const under the misreading text (0x3F at byte 0, \
         0x30 at byte 21) is dropped, but every one of its bits lies under a parameter whose \
         default gives the same bits: no change. Cosmetic: product family, software release, \
         the RSS code types renamed GS1 Data Bar in ten records each, one choice text of M05. \
         The DeflectionMirror texts changed too, but no module of this device uses them.",
        &output,
    );
    assert_eq!(code, 1);
}

#[test]
fn fail_on_compatible_and_cosmetic_are_stricter_gates() {
    let pair = (
        "GSDML-V2.43-RT-Labs-P-Net-Sample-App-20230117.xml",
        "GSDML-V2.43-RT-Labs-P-Net-Sample-App-20240530.xml",
    );
    assert_eq!(diff(pair.0, pair.1, &["--fail-on", "compatible"]).1, 0);
    assert_eq!(diff(pair.0, pair.1, &["--fail-on", "cosmetic"]).1, 1);
    let rt_labs = (
        "GSDML-V2.33-rt-labs-IODevice-20191008.xml",
        "GSDML-V2.35-rtlabs-IODevice-20200603.xml",
    );
    assert_eq!(
        diff(rt_labs.0, rt_labs.1, &["--fail-on", "compatible"]).1,
        1
    );
}

#[test]
fn json_for_ci() {
    let (output, code) = diff(
        "GSDML-V2.4-RT-Labs-P-Net-Sample-App-20210507.xml",
        "GSDML-V2.43-RT-Labs-P-Net-Sample-App-20230117.xml",
        &["--format", "json"],
    );
    assert_eq!(code, 1);
    let doc: serde_json::Value = serde_json::from_str(&output).unwrap();
    assert_eq!(
        doc["summary"],
        serde_json::json!({"breaking": 2, "compatible": 3, "cosmetic": 3})
    );
    let changes = doc["pairs"][0]["changes"].as_array().unwrap();
    let vendor = &changes[0];
    assert_eq!(vendor["class"], "breaking");
    assert_eq!(vendor["kind"], "identity");
    assert_eq!(vendor["subject"], "VendorID");
    assert_eq!(vendor["change"], "0xFEED → 0x0493");
    assert_eq!(vendor["judged"], true);
    assert_eq!(vendor["old"]["line"], 17);
    assert_eq!(vendor["old"]["path"], "DeviceIdentity");
    assert!(vendor["old"]["file"]
        .as_str()
        .unwrap()
        .ends_with("20210507.xml"));
    let added = changes.iter().find(|c| c["change"] == "added").unwrap();
    assert_eq!(added["old"], serde_json::Value::Null);
    assert_eq!(
        added["new"]["path"],
        "ApplicationProcess/ModuleList/ModuleItem[IDM_40]"
    );
}

/// A file diff cannot read gets what `gsdc check` says of it, exit 2; a
/// GSD against a GSDML file is a usage error.
#[test]
fn unreadable_and_mismatched_files_exit_2() {
    let dir = support::scratch("unreadable");
    let broken = dir.join("broken.xml");
    std::fs::write(&broken, "<ISO15745Profile><unclosed></ISO15745Profile>").unwrap();
    let good = corpus("GSDML-V2.43-RT-Labs-P-Net-Sample-App-20230117.xml");
    let out = gsdc(["diff", broken.to_str().unwrap(), &good]);
    assert_eq!(out.status.code(), Some(2));
    let stdout = String::from_utf8_lossy(&out.stdout);
    let check = gsdc(["check", broken.to_str().unwrap()]);
    assert_eq!(
        stdout,
        String::from_utf8_lossy(&check.stdout),
        "the check path's own output"
    );
    assert!(stdout.contains("error[E300]"), "{stdout}");
    assert!(String::from_utf8_lossy(&out.stderr).contains("nothing compared"));

    let gsd = "../shared/corpus/gsd/Rahix__mock.gsd";
    let out = gsdc(["diff", gsd, &good]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("compares files of one kind"));

    let out = gsdc(["diff", dir.join("missing.gsd").to_str().unwrap(), gsd]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("cannot read"));
}

/// A description stands for the file of the other side's kind; two
/// descriptions are compared file by file.
#[test]
fn descriptions_are_compared_by_what_they_build() {
    let dir = support::scratch("descriptions");
    let out = gsdc([
        "build",
        "descriptions/md810dp.toml",
        "--out",
        dir.to_str().unwrap(),
        "--firmware",
        "none",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let released = dir.join("MD810DP.GSD");
    let out = gsdc([
        "diff",
        released.to_str().unwrap(),
        "descriptions/md810dp.toml",
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert!(
        stdout.starts_with(&format!(
            "{} → descriptions/md810dp.toml (MD810DP.GSD)\n  no change\n",
            released.display()
        )),
        "{stdout}"
    );
    assert!(
        !stdout.contains("GSDML"),
        "only the GSD is compared: {stdout}"
    );

    let changed = dir.join("md810dp.toml");
    let text = support::descriptions::shipped_text("md810dp.toml");
    std::fs::write(&changed, text.replace("\"12M\" = 800\n", "\"12M\" = 900\n")).unwrap();
    support::descriptions::copy_symbols(&dir);
    let out = gsdc([
        "diff",
        "descriptions/md810dp.toml",
        changed.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(1));
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert!(
        stdout.contains("  MaxTsdr_12M: \"800\" → \"900\"\n"),
        "{stdout}"
    );
    assert!(
        stdout.contains("(GSDML-V2.32-INOVANCE-MD810-20261122.xml)\n  no change\n"),
        "{stdout}"
    );
    assert!(
        stdout.ends_with("1 breaking, 0 compatible, 0 cosmetic\n"),
        "{stdout}"
    );
}
