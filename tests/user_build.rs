//! A new user's first day with the build (issue 23): a firmware crate's
//! build script without the device symbol, `gsdc check dist/*` after a
//! build, and the datasheet kept in step in CI (`gsdc doc --check`, `gsdc
//! build --check`).

use crate::support::{checkout, file_names, gsdc, scratch, stderr, stdout};
use std::path::{Path, PathBuf};
use std::process::Output;

/// md810dp.toml copied into `dir` without the `symbols/` folder beside it:
/// a firmware crate that took the description and not the bitmap.
fn description_without_its_symbol(dir: &Path) -> PathBuf {
    let text = std::fs::read_to_string(checkout("descriptions/md810dp.toml")).unwrap();
    assert!(text.contains("symbol = \"symbols/md810dp.png\""));
    let path = dir.join("md810dp.toml");
    std::fs::write(&path, text).unwrap();
    path
}

// ---------------------------------------------------------------------------
// A build script writes the layouts without reading the device symbol.

#[test]
fn generate_rust_and_generate_c_need_no_device_symbol() {
    let dir = scratch("no-symbol");
    let description = description_without_its_symbol(&dir);
    let out = dir.join("out");
    std::fs::create_dir_all(&out).unwrap();

    let rust = gsdc::build::generate_rust(&description, &out).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(rust, out.join("md810dp_layout.rs"));
    let c = gsdc::build::generate_c(&description, &out).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(c, out.join("md810dp_layout.h"));
    assert_eq!(
        file_names(&out),
        [
            "gsdc_support.h",
            "gsdc_support.rs",
            "md810dp_layout.h",
            "md810dp_layout.rs"
        ]
    );
    // The layout is the one a build with the symbol writes: the symbol is
    // no part of it.
    let with_symbol = scratch("with-symbol");
    gsdc::build::generate_rust(checkout("descriptions/md810dp.toml"), &with_symbol).unwrap();
    assert_eq!(
        std::fs::read(out.join("md810dp_layout.rs")).unwrap(),
        std::fs::read(with_symbol.join("md810dp_layout.rs")).unwrap()
    );

    // The device files do need it: E141, as before.
    let e = gsdc::build::generate(&description, dir.join("all")).unwrap_err();
    let gsdc::build::BuildError::Description { findings, .. } = &e else {
        panic!("{e:?}");
    };
    assert!(findings[0].diagnostics.iter().any(|d| d.code == "E141"));
    assert!(e.to_string().contains("error[E141]"), "{e}");
}

// ---------------------------------------------------------------------------
// `gsdc check dist/*` after a build.

/// The files a build and `gsdc doc` write for md810dp.toml into `dir`.
fn built_with_datasheet(dir: &Path) -> Vec<String> {
    let out = dir.to_str().unwrap();
    for command in ["build", "doc"] {
        let output = gsdc([command, "descriptions/md810dp.toml", "--out", out]);
        assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    }
    file_names(dir)
}

#[test]
fn check_of_everything_a_build_writes_passes() {
    let dir = scratch("check-dist");
    let names = built_with_datasheet(&dir);
    let paths: Vec<String> = names
        .iter()
        .map(|n| dir.join(n).to_str().unwrap().to_string())
        .collect();
    let mut args = vec!["check"];
    args.extend(paths.iter().map(String::as_str));
    let output = gsdc(&args);
    let out = stdout(&output);
    assert_eq!(output.status.code(), Some(0), "{out}{}", stderr(&output));
    for (name, path) in names.iter().zip(&paths) {
        let checked = format!("{path}: 0 error(s), 0 warning(s)");
        let skipped = format!(
            "note: {path} is made by gsdc (a firmware layout, support file or datasheet), not a device file: skipped"
        );
        let device_file =
            name.ends_with(".GSD") || name.ends_with(".xml") || name.ends_with(".bmp");
        let expected = if device_file { checked } else { skipped };
        assert!(out.lines().any(|l| l == expected), "{name}: {out}");
    }
    assert_eq!(
        names.iter().filter(|n| n.ends_with(".bmp")).count(),
        2,
        "both device symbols were checked as symbols"
    );
    // Files of anyone else's are still E400.
    std::fs::write(dir.join("notes.txt"), "to do: ship it\n").unwrap();
    let notes = dir.join("notes.txt");
    let output = gsdc(["check", notes.to_str().unwrap()]);
    assert_eq!(output.status.code(), Some(1));
    assert!(
        stdout(&output).starts_with("error[E400]: "),
        "{}",
        stdout(&output)
    );
}

#[test]
fn a_device_symbol_is_checked_as_one() {
    let dir = scratch("check-symbol");
    built_with_datasheet(&dir);
    let bmp = std::fs::read(dir.join("MD810DP.bmp")).unwrap();
    let check = |name: &str, bytes: &[u8]| {
        let path = dir.join(name);
        std::fs::write(&path, bytes).unwrap();
        let output = gsdc(["check", path.to_str().unwrap()]);
        (output.status.code(), stdout(&output))
    };
    // Cut short: no tool could show it.
    let (code, out) = check("cut.bmp", &bmp[..bmp.len() - 10]);
    assert_eq!(code, Some(1), "{out}");
    assert!(out.contains("error[E401]: not a whole Windows bitmap: its pixels need 1558 bytes, and the file has 1548: it is cut short"), "{out}");
    // 8 bits a pixel (256 colours), the rows there: a warning, exit 0.
    let mut deep = bmp.clone();
    deep[28] = 8;
    deep.resize(118 + 72 * 40, 0);
    let (code, out) = check("deep.bmp", &deep);
    assert_eq!(code, Some(0), "{out}");
    assert!(
        out.contains("warning[W402]: the device symbol has 8 bits per pixel, not 4 (16 colours)"),
        "{out}"
    );
}

// ---------------------------------------------------------------------------
// The datasheet in CI: `gsdc doc --check`, and `gsdc build --check` naming
// a datasheet of an older description.

/// A description of its own in `dir` (the PROFIdrive fixture as ax200.toml),
/// built and documented into `dir/dist`; returns the description's path.
fn documented_card(dir: &Path) -> PathBuf {
    let description = dir.join("ax200.toml");
    std::fs::copy(
        checkout("tests/fixtures/valid/profidrive.toml"),
        &description,
    )
    .unwrap();
    for command in ["build", "doc"] {
        write_into_dist(command, &description);
    }
    description
}

/// `gsdc COMMAND DESCRIPTION --out DIR/dist`, which must exit 0.
fn write_into_dist(command: &str, description: &Path) {
    let dist = description.parent().unwrap().join("dist");
    let output = gsdc([
        command,
        description.to_str().unwrap(),
        "--out",
        dist.to_str().unwrap(),
    ]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
}

/// `gsdc COMMAND DESCRIPTION --out DIR/dist --check`.
fn check(command: &str, description: &Path) -> Output {
    let dist = description.parent().unwrap().join("dist");
    gsdc([
        command,
        description.to_str().unwrap(),
        "--out",
        dist.to_str().unwrap(),
        "--check",
    ])
}

#[test]
fn a_datasheet_of_an_older_description_fails_both_checks() {
    let dir = scratch("stale-datasheet");
    let description = documented_card(&dir);
    assert_eq!(check("build", &description).status.code(), Some(0));
    assert_eq!(check("doc", &description).status.code(), Some(0));

    // The description changes, the device files are rebuilt, the datasheet
    // is forgotten.
    let text = std::fs::read_to_string(&description).unwrap();
    std::fs::write(
        &description,
        text.replace("dns_name = \"x2-pn\"", "dns_name = \"ax200\""),
    )
    .unwrap();
    let dist = dir.join("dist");
    write_into_dist("build", &description);
    let old = gsdc::load("ax200.toml", &text).0.unwrap().fingerprint;
    let new = gsdc::load(
        "ax200.toml",
        &std::fs::read_to_string(&description).unwrap(),
    )
    .0
    .unwrap()
    .fingerprint;

    let build = check("build", &description);
    assert_eq!(build.status.code(), Some(1), "{}", stdout(&build));
    for page in ["ax200.html", "ax200.md"] {
        let line = format!(
            "stale datasheet: {} carries fingerprint {old}, not {}'s {new} (run `gsdc doc {} --out {}`)",
            dist.join(page).display(),
            description.display(),
            description.display(),
            dist.display()
        );
        assert!(
            stdout(&build).lines().any(|l| l == line),
            "{line}\n{}",
            stdout(&build)
        );
    }
    // The device files are in step: no advice to build.
    assert!(
        !stderr(&build).contains("gsdc build --prune"),
        "{}",
        stderr(&build)
    );

    let doc = check("doc", &description);
    assert_eq!(doc.status.code(), Some(1));
    let named: Vec<String> = ["ax200.html", "ax200.md"]
        .iter()
        .map(|page| format!("differs: {}", dist.join(page).display()))
        .collect();
    assert_eq!(stdout(&doc).lines().collect::<Vec<_>>(), named);
    assert!(stderr(&doc).contains("out of step: run `gsdc doc` without --check"));

    // gsdc doc brings both in step; --check wrote nothing before.
    write_into_dist("doc", &description);
    assert_eq!(check("build", &description).status.code(), Some(0));
    assert_eq!(check("doc", &description).status.code(), Some(0));
}

#[test]
fn doc_check_names_a_missing_datasheet_and_writes_nothing() {
    let dir = scratch("missing-datasheet");
    let description = documented_card(&dir);
    let html = dir.join("dist/ax200.html");
    std::fs::remove_file(&html).unwrap();
    let doc = check("doc", &description);
    assert_eq!(doc.status.code(), Some(1));
    assert!(
        stdout(&doc).contains(&format!("missing: {}", html.display())),
        "{}",
        stdout(&doc)
    );
    assert!(!html.exists());
    // A build does not need the datasheet: none there is in step.
    assert_eq!(check("build", &description).status.code(), Some(0));
}
