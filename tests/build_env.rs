//! `GSDC_BUILD_XSD` reaches build scripts: `gsdc::build::generate` and
//! `Config::new` take the PI schema directory it names. The variable is
//! the whole process's, so the test runs in a process of its own.

use crate::support::{self, xsd::refusing_schema};

#[test]
fn the_environment_variable_names_the_schema_of_every_build() {
    if support::ran_in_own_process() {
        return;
    }
    let dir = support::scratch("env");
    let refusing = refusing_schema(&dir);
    let mv810 = support::checkout("descriptions/mv810-pnet02.toml");
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
}
