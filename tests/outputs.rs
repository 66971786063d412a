//! Every file gsdc makes of every shipped description and every valid
//! fixture, the files that ship with the card (`gsdc::compile`) and its
//! datasheet (`gsdc::document`), is an insta snapshot read against the
//! manuals: `tests/snapshots/outputs/<file name>.snap`. The descriptions
//! and the files are found, not listed, so a new description, fixture or
//! kind of output is snapshotted without a line of test code (and fails
//! until its snapshots are read and accepted).
//!
//! A file two descriptions both give (the support code every layout is
//! built from) must be the same from each, as `gsdc build` writes it once;
//! it is one snapshot.

use crate::support::{self, descriptions};
use gsdc::Artifact;
use std::collections::BTreeMap;
use std::fmt::Write as _;

const FOLDER: &str = "outputs";

#[test]
fn every_file_gsdc_makes_is_its_reviewed_snapshot() {
    // Each file name once, with the description that gave it first.
    let mut files: BTreeMap<String, (String, Artifact)> = BTreeMap::new();
    for (name, ir) in descriptions::all_valid() {
        for file in descriptions::outputs(&ir) {
            if let Some((first, same_name)) = files.get(&file.file_name) {
                assert!(
                    same_name.contents == file.contents,
                    "{first} and {name} both give {}, with different contents",
                    file.file_name
                );
                continue;
            }
            files.insert(file.file_name.clone(), (name.clone(), file));
        }
    }
    support::snapshots_in(FOLDER, || {
        for (file_name, (_, file)) in &files {
            insta::assert_snapshot!(file_name.as_str(), snapshot_text(file));
        }
    });
    support::assert_no_orphan_snapshots(FOLDER, files.keys().map(String::as_str));
}

/// What the snapshot of a file holds: its text, with CRLF as LF (insta
/// compares line ends so anyway; gsd_output.rs checks the GSD's CRLF), or
/// every byte of a binary file in hex, a bitmap's pixel rows one a line so
/// that its picture shows.
fn snapshot_text(file: &Artifact) -> String {
    match std::str::from_utf8(&file.contents) {
        Ok(text) => text.replace("\r\n", "\n"),
        Err(_) if file.contents.starts_with(b"BM") => bitmap(&file.contents),
        Err(_) => hex_lines(&file.contents, 32, " "),
    }
}

/// A Windows bitmap stored bottom-up: the header and colour table in hex,
/// then the pixel rows from the top, each row's bytes in hex without a
/// space (at 4 bits a pixel, one digit is one pixel's colour index).
fn bitmap(bmp: &[u8]) -> String {
    let u32_at = |at: usize| u32::from_le_bytes(bmp[at..at + 4].try_into().unwrap()) as usize;
    let u16_at = |at: usize| usize::from(u16::from_le_bytes([bmp[at], bmp[at + 1]]));
    let (pixels, width, height, bits) = (u32_at(10), u32_at(18), u32_at(22), u16_at(28));
    let stride = (width * bits).div_ceil(32) * 4;
    assert_eq!(
        bmp.len(),
        pixels + stride * height,
        "a bitmap of {width} x {height} pixels at {bits} bits, its rows bottom-up"
    );
    let mut text =
        format!("{width} x {height} pixels, {bits} bits each\n\nheader and colour table:\n");
    text += &hex_lines(&bmp[..pixels], 16, " ");
    text += "\npixel rows from the top (the file stores the bottom row first):\n";
    for row in bmp[pixels..].chunks(stride).rev() {
        text += &hex_lines(row, stride, "");
    }
    text
}

/// `bytes` in hex, `per_line` bytes a line, `between` them.
fn hex_lines(bytes: &[u8], per_line: usize, between: &str) -> String {
    bytes
        .chunks(per_line)
        .fold(String::new(), |mut text, line| {
            let digits: Vec<String> = line.iter().map(|b| format!("{b:02x}")).collect();
            let _ = writeln!(text, "{}", digits.join(between));
            text
        })
}
