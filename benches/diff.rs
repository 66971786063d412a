//! `cargo bench --bench diff`: `gsdc diff` of two of the largest GSDML files
//! of the corpus against `gsdc check` of the same two files, in one run,
//! printing each ratio (above 1: the diff is the faster).
//!
//! - as processes, as users run them: the two largest files (SEW's MOVI-C,
//!   1.1 MB, and Leuze's BCL248i, 390 KB), and the largest against a copy
//!   of itself with one attribute changed (a release against its
//!   successor);
//! - in process, on one thread: `device::read` of both files and
//!   `diff::compare`, against `gsdml::check` of both.
//!
//! The two sides run in turns, and the ratio printed is the median of the
//! per-turn ratios (`common::compare`). Needs ../shared beside the checkout.

#[path = "common/mod.rs"]
mod common;

use common::{compare, run};
use std::path::PathBuf;
use std::process::Command;

const GSDC: &str = env!("CARGO_BIN_EXE_gsdc");

fn main() {
    let corpus = PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../shared/corpus/gsdml"
    ));
    let largest =
        corpus.join("GSDML-V2.34-SEW-MOVI-C-Decentralized-Electronics-20200731-071447.xml");
    let second = corpus.join("GSDML-V2.41-LEUZE-BCL248i-20211213.xml");
    let text = std::fs::read_to_string(&largest)
        .unwrap_or_else(|e| panic!("{} is missing: {e}", largest.display()));
    let successor = std::env::temp_dir().join(format!(
        "gsdc-bench-{}-GSDML-V2.34-SEW-MOVI-C-Decentralized-Electronics-20200801.xml",
        std::process::id()
    ));
    let changed = text.replacen("MinDeviceInterval=\"", "MinDeviceInterval=\"1", 1);
    assert_ne!(changed, text);
    std::fs::write(&successor, changed).unwrap();

    for (what, old, new) in [
        ("the two largest GSDML files", &largest, &second),
        (
            "the largest GSDML file and a successor",
            &largest,
            &successor,
        ),
    ] {
        compare(
            what,
            ("gsdc diff", &mut || {
                run(Command::new(GSDC).arg("diff").arg(old).arg(new))
            }),
            ("gsdc check", &mut || {
                run(Command::new(GSDC).arg("check").arg(old).arg(new))
            }),
        );
    }

    let bytes = [
        std::fs::read(&largest).unwrap(),
        std::fs::read(&second).unwrap(),
    ];
    compare(
        "the two largest GSDML files, in process on one thread",
        ("device::read + diff::compare", &mut || {
            let [old, new] = [0, 1].map(|i| gsdc::device::read(&bytes[i], None).unwrap());
            std::hint::black_box(gsdc::diff::compare(&old, &new));
        }),
        ("gsdml::check", &mut || {
            for b in &bytes {
                let text = gsdc::gsdml::decode(b).unwrap();
                std::hint::black_box(gsdc::gsdml::check(&text, None));
            }
        }),
    );
    let _ = std::fs::remove_file(&successor);
}
