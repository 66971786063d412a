//! `GSDC_BUILD_XSD` reaches build scripts: `gsdc::build::generate` and
//! `Config::new` take the PI schema directory it names. A test binary of
//! its own, as the variable is the whole process's.

#[path = "common/refusing_xsd.rs"]
mod refusing_xsd;

use refusing_xsd::refusing_schema;
use std::path::Path;

#[test]
fn the_environment_variable_names_the_schema_of_every_build() {
    let dir = std::env::temp_dir().join(format!("gsdc-build-env-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let refusing = refusing_schema(&dir);
    let mv810 = Path::new(env!("CARGO_MANIFEST_DIR")).join("descriptions/mv810-pnet02.toml");
    let out = dir.join("out");

    std::env::set_var(gsdc::build::XSD_ENV, &refusing);
    let e = gsdc::build::generate(&mv810, &out).unwrap_err();
    assert!(e.to_string().contains("error[E399]"), "{e}");
    let config = gsdc::build::Config::new();
    let e = config.generate(&mv810, &out).unwrap_err();
    assert!(e.to_string().contains("error[E399]"), "{e}");
    assert!(!out.exists());
    // A layout needs no GSDML, so no schema.
    config
        .generate_layout(&mv810, &out, gsdc::Language::Rust)
        .unwrap();
    std::fs::remove_dir_all(&out).unwrap();

    std::env::set_var(gsdc::build::XSD_ENV, "");
    assert_eq!(
        gsdc::build::generate(&mv810, &out).unwrap().len(),
        6,
        "empty is unset: the GSDML, its symbol, two layouts, two support files"
    );
    std::env::remove_var(gsdc::build::XSD_ENV);
    std::fs::remove_dir_all(dir).unwrap();
}
