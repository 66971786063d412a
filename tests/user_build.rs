//! A new user's first day with the build (issue 23): a firmware crate's
//! build script without the device symbol, `gsdc check dist/*` after a
//! build, and the datasheet kept in step in CI (`gsdc doc --check`, `gsdc
//! build --check`). Self-contained: its helpers are its own.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const MANIFEST: &str = env!("CARGO_MANIFEST_DIR");

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("gsdc-user-build-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn gsdc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gsdc"))
        .args(args)
        .current_dir(MANIFEST)
        .output()
        .unwrap()
}

fn stdout(output: &Output) -> String {
    String::from_utf8_lossy(&output.stdout).into_owned()
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// md810dp.toml copied into `dir` without the `symbols/` folder beside it:
/// a firmware crate that took the description and not the bitmap.
fn description_without_its_symbol(dir: &Path) -> PathBuf {
    let text =
        std::fs::read_to_string(Path::new(MANIFEST).join("descriptions/md810dp.toml")).unwrap();
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
    let mut written: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    written.sort();
    assert_eq!(
        written,
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
    gsdc::build::generate_rust(
        Path::new(MANIFEST).join("descriptions/md810dp.toml"),
        &with_symbol,
    )
    .unwrap();
    assert_eq!(
        std::fs::read(out.join("md810dp_layout.rs")).unwrap(),
        std::fs::read(with_symbol.join("md810dp_layout.rs")).unwrap()
    );

    // The device files do need it: E141, as before.
    let e = gsdc::build::generate(&description, dir.join("all")).unwrap_err();
    let gsdc::build::BuildError::Description { rendered, .. } = &e else {
        panic!("{e:?}");
    };
    assert!(rendered.contains("error[E141]"), "{rendered}");
}
