//! `gsdc check` on what users hand it: files of any name told apart by
//! their content, streams, UTF-16, names that would fake output, and
//! findings printed as each file is done.

use crate::support::{self, gsdc, gsdc_command, stderr, stdout};
use std::io::{BufRead, BufReader, Write};
use std::path::Path;
use std::process::{Command, Stdio};

const MV810_GSDML: &str = "GSDML-V2.32-MEGMEET-MV800-20230830.xml";

/// The files `gsdc build` writes for `description` into `dir`.
fn built(description: &str, dir: &Path) {
    let output = gsdc(["build", description, "--out", dir.to_str().unwrap()]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
}

fn utf16le_with_mark(text: &str) -> Vec<u8> {
    let mut bytes = vec![0xFF, 0xFE];
    bytes.extend(text.encode_utf16().flat_map(u16::to_le_bytes));
    bytes
}

/// `gsdc check dist/*`: the GSD and the GSDML are checked whatever their
/// names; the firmware layout beside them is one line, a note that gsdc made
/// it, not 723 findings of a GSD check; a file of zeros named `.xml` is one
/// line too, E400.
#[test]
fn files_are_told_apart_by_their_content() {
    let dir = support::scratch("kinds");
    built("descriptions/md810dp.toml", &dir);
    std::fs::rename(dir.join("MD810DP.GSD"), dir.join("gsd.txt")).unwrap();
    std::fs::rename(
        dir.join("GSDML-V2.32-INOVANCE-MD810-20261122.xml"),
        dir.join("gsdml.gsd"),
    )
    .unwrap();
    std::fs::write(dir.join("zeros.xml"), [0u8; 4096]).unwrap();
    let path = |name: &str| dir.join(name).to_str().unwrap().to_string();
    let (gsd, gsdml, layout, zeros) = (
        path("gsd.txt"),
        path("gsdml.gsd"),
        path("md810dp_layout.rs"),
        path("zeros.xml"),
    );
    let output = gsdc(["check", &gsd, &gsdml, &layout, &zeros]);
    assert_eq!(output.status.code(), Some(1));
    let lines: Vec<String> = stdout(&output).lines().map(str::to_string).collect();
    let neither = |name: &str| {
        format!("error[E400]: {name} is neither a GSD file (no line starts with #Profibus_DP) nor a GSDML file (not XML): not checked")
    };
    // The GSDML's name breaks the naming convention (E304): a GSDML rule,
    // so it was read as GSDML.
    assert_eq!(lines[0], format!("{gsd}: 0 error(s), 0 warning(s)"));
    assert!(
        lines.iter().any(|l| l.starts_with("error[E304]")),
        "{lines:#?}"
    );
    assert_eq!(
        lines[lines.len() - 3],
        format!("{gsdml}: 1 error(s), 0 warning(s)")
    );
    assert_eq!(
        lines[lines.len() - 2],
        format!("note: {layout} is made by gsdc (a firmware layout, support file or datasheet), not a device file: skipped")
    );
    assert_eq!(lines[lines.len() - 1], neither(&zeros));
}

/// A file through a pipe: `/dev/stdin` is read once, as GSDML or GSD by
/// its content, without the naming rules (a stream has no name), and with
/// the PI schema from the text, as a file from disk is.
#[test]
fn a_device_file_given_through_dev_stdin_is_checked_by_its_content() {
    let dir = support::scratch("stdin");
    built("descriptions/mv810-pnet02.toml", &dir);
    let from_stdin = |bytes: &[u8], extra: &[&str]| {
        let mut child = gsdc_command(["check"])
            .args(extra)
            .arg("/dev/stdin")
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        child.stdin.take().unwrap().write_all(bytes).unwrap();
        child.wait_with_output().unwrap()
    };
    let gsdml = std::fs::read(dir.join(MV810_GSDML)).unwrap();
    let pi_schema = support::xsd::pi_schema();
    let pi_schema = pi_schema.to_str().unwrap();
    for extra in [&[][..], &["--xsd", pi_schema][..]] {
        let output = from_stdin(&gsdml, extra);
        assert_eq!(output.status.code(), Some(0), "{}", stdout(&output));
        assert_eq!(stdout(&output), "/dev/stdin: 0 error(s), 0 warning(s)\n");
    }
    // The same bytes with an error: found through the pipe, rules and schema.
    let broken = String::from_utf8(gsdml).unwrap().replacen(
        "DataType=\"Unsigned16\"",
        "DataType=\"UInt16\"",
        1,
    );
    let output = from_stdin(broken.as_bytes(), &["--xsd", pi_schema]);
    assert_eq!(output.status.code(), Some(1));
    let said = stdout(&output);
    assert!(
        said.contains("error[E309]") && said.contains("error[E399]"),
        "{said}"
    );

    let gsd = support::corpus_file("gsd/mbuesch__dummy_modular.gsd");
    let output = from_stdin(&gsd, &[]);
    assert_eq!(output.status.code(), Some(1));
    assert!(
        stdout(&output).contains("error[E208]"),
        "{}",
        stdout(&output)
    );
}

/// A GSDML saved as UTF-16 that declares it, which xmllint validates, is
/// read as such (from disk and through a pipe, with the PI schema too);
/// a GSD saved as UTF-16 is one finding that says so.
#[test]
fn utf16_gsdml_is_read_and_a_utf16_gsd_is_one_finding() {
    let dir = support::scratch("utf16");
    built("descriptions/mv810-pnet02.toml", &dir);
    let text = std::fs::read_to_string(dir.join(MV810_GSDML)).unwrap();
    let declared = text.replacen("encoding=\"utf-8\"", "encoding=\"UTF-16\"", 1);
    assert_ne!(declared, text);
    let wide = dir.join("utf16").join(MV810_GSDML);
    std::fs::create_dir_all(wide.parent().unwrap()).unwrap();
    std::fs::write(&wide, utf16le_with_mark(&declared)).unwrap();
    let pi_schema = support::xsd::pi_schema();
    let xmllint = Command::new("xmllint")
        .args(["--noout", "--schema"])
        .arg(pi_schema.join("GSDML-DeviceProfile-v2.44.xsd"))
        .arg(&wide)
        .output()
        .unwrap();
    assert!(xmllint.status.success(), "{}", stderr(&xmllint));
    let wide_arg = wide.to_str().unwrap();
    for args in [
        vec!["check", wide_arg],
        vec!["check", "--xsd", pi_schema.to_str().unwrap(), wide_arg],
    ] {
        let output = gsdc(&args);
        assert_eq!(output.status.code(), Some(0), "{}", stdout(&output));
        assert!(stdout(&output).ends_with(": 0 error(s), 0 warning(s)\n"));
    }
    let piped = Command::new("sh")
        .arg("-c")
        .arg("\"$0\" check --xsd \"$1\" /dev/stdin < \"$2\"")
        .arg(support::GSDC)
        .arg(&pi_schema)
        .arg(&wide)
        .output()
        .unwrap();
    assert_eq!(piped.status.code(), Some(0), "{}", stdout(&piped));

    // A Latin-1 file: its text, as UTF-16.
    let bytes = support::corpus_file("gsd/ivangre4__SIEM8045.gse");
    let gsd = gsdc::gsd::decode(&bytes).into_owned();
    let wide_gsd = dir.join("SIEM8045.GSE");
    std::fs::write(&wide_gsd, utf16le_with_mark(&gsd)).unwrap();
    let output = gsdc(["check", wide_gsd.to_str().unwrap()]);
    assert_eq!(output.status.code(), Some(1));
    let said = stdout(&output);
    assert_eq!(said.matches("error[").count(), 1, "{said}");
    assert!(
        said.contains("error[E230]: the file is UTF-16 text"),
        "{said}"
    );
    assert!(said.contains("1 error(s), 0 warning(s)"), "{said}");
}

/// A file's findings are printed as soon as it and the files before it are
/// done: the first file's summary comes while gsdc still waits for the
/// second, a FIFO nobody has written yet.
#[test]
fn findings_are_printed_as_each_file_is_done() {
    let dir = support::scratch("streaming");
    let fifo = dir.join("later.gsd");
    let made = Command::new("mkfifo").arg(&fifo).status().unwrap();
    assert!(made.success());
    let first = "../shared/corpus/gsd/ivangre4__SIEM8045.gse";
    let mut child = gsdc_command(["check"])
        .arg(first)
        .arg(&fifo)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut lines = BufReader::new(child.stdout.take().unwrap()).lines();
    let mut printed = Vec::new();
    loop {
        let line = lines.next().unwrap().unwrap();
        let done = line.starts_with(&format!("{first}: "));
        printed.push(line);
        if done {
            break;
        }
    }
    assert!(
        child.try_wait().unwrap().is_none(),
        "gsdc ended: {printed:?}"
    );
    // Only now the second file gets its content, and gsdc its end.
    let gsd = std::fs::read(support::checkout(first)).unwrap();
    std::fs::write(&fifo, gsd).unwrap();
    let rest: Vec<String> = lines.map(Result::unwrap).collect();
    assert!(child.wait().unwrap().success());
    assert_eq!(
        rest.last().unwrap(),
        &format!("{}: 0 error(s), 0 warning(s)", fifo.display())
    );
}

/// A file name with a line end and an escape sequence in it cannot print a
/// line of its own, nor colour the terminal: the human output escapes it
/// as the JSON output does.
#[test]
fn control_characters_in_file_names_are_escaped() {
    let dir = support::scratch("names");
    let fake = "x.gsd\nall.gsd: 0 error(s), 0 warning(s)\u{1b}[2K";
    let path = dir.join(fake);
    std::fs::write(
        &path,
        support::corpus_file("gsd/mbuesch__dummy_modular.gsd"),
    )
    .unwrap();
    let output = gsdc(["check", path.to_str().unwrap()]);
    assert_eq!(output.status.code(), Some(1));
    let said = stdout(&output);
    assert!(
        !said.lines().any(|l| l.starts_with("all.gsd")),
        "a faked line: {said}"
    );
    assert!(!said.contains('\u{1b}'), "{said}");
    let shown = format!(
        "{}/x.gsd\\nall.gsd: 0 error(s), 0 warning(s)\\u001b[2K",
        dir.display()
    );
    assert!(
        said.contains(&format!("--> {shown}:")),
        "the name escaped where findings point: {said}"
    );
    assert!(
        said.ends_with(&format!("{shown}: 3 error(s), 1 warning(s)\n")),
        "{said}"
    );

    let json = gsdc(["check", "--format", "json", path.to_str().unwrap()]);
    let last: serde_json::Value =
        serde_json::from_str(stdout(&json).lines().last().unwrap()).unwrap();
    assert_eq!(last["file"], path.to_str().unwrap(), "JSON keeps the name");

    let missing = dir.join("gone\n.gsd");
    let output = gsdc(["check", missing.to_str().unwrap()]);
    assert_eq!(output.status.code(), Some(2));
    assert_eq!(stderr(&output).lines().count(), 1, "{}", stderr(&output));
    assert!(
        stderr(&output).contains("gone\\n.gsd"),
        "{}",
        stderr(&output)
    );
}
