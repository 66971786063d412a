//! What `gsdc check` says about a handful of real vendor files, rendered as
//! a user sees it (`tests/snapshots/check/`). Each snapshot was read
//! against the file it is about.

use crate::support;
use gsdc::Source;

fn findings(folder: &str, name: &str) -> String {
    let bytes = support::corpus_file(&format!("{folder}/{name}"));
    let (text, diagnostics) = if name.ends_with(".xml") {
        let text = gsdc::gsdml::decode(&bytes).unwrap().into_owned();
        let diagnostics = gsdc::gsdml::check(&text, Some(name));
        (text, diagnostics)
    } else {
        let text = gsdc::gsd::decode(&bytes).into_owned();
        let diagnostics = gsdc::gsd::check(&text);
        (text, diagnostics)
    };
    let source = Source::new(name, &text);
    diagnostics.iter().map(|d| source.render(d)).collect()
}

#[test]
fn findings_of_real_files() {
    let files = [
        ("gsd", "mbuesch__dummy_compact.gsd"),
        ("gsd", "ivangre4__SI028131.GSD"),
        ("gsd", "ivangre4__siem8037.gsd"),
        ("gsd", "siamect__abb_acs880_pb_slave.gsd"),
        ("gsd", "joao404__STM32F1002A.gsd"),
        ("gsdml", "GSDML-V2.33-ABB-FENA-20170914.xml"),
        ("gsdml", "GSDML-V2.4-RT-Labs-P-Net-Sample-App-20210507.xml"),
        ("gsdml-invalid", "neg_dup_module_id.xml"),
    ];
    support::snapshots_in("check", || {
        for (folder, name) in files {
            insta::assert_snapshot!(name, findings(folder, name));
        }
    });
    support::assert_no_orphan_snapshots("check", files.map(|(_, name)| name));
}
