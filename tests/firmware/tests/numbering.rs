//! Each layout's `NUMBERING` reads and writes the drive's parameter names
//! exactly as gsdc reads and writes the description's: every address of the
//! 16-bit space named alike and read back, and names that are not of the
//! numbering refused alike.

use gsdc_firmware_check::gsdc_support::Numbering;
use gsdc_firmware_check::{md810dp, mv810_pnet02, powtran_9kdp1, profidrive};
use std::path::Path;

const NUMBERINGS: [(&str, &Numbering); 4] = [
    ("descriptions/md810dp.toml", &md810dp::NUMBERING),
    ("descriptions/mv810-pnet02.toml", &mv810_pnet02::NUMBERING),
    ("descriptions/9kdp1.toml", &powtran_9kdp1::NUMBERING),
    (
        "tests/fixtures/valid/profidrive.toml",
        &profidrive::NUMBERING,
    ),
];

/// The numbering gsdc reads from the description.
fn gsdc_numbering(description: &str) -> gsdc::ir::Numbering {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(description);
    let loaded = gsdc::build::load_file(&path, description).unwrap();
    loaded.ir.unwrap().numbering.unwrap()
}

#[test]
fn every_address_is_named_and_read_back_as_gsdc_does() {
    for (description, layout) in NUMBERINGS {
        let gsdc = gsdc_numbering(description);
        let mut named = 0;
        for address in 0..=u16::MAX {
            let name = layout.name(address).map(|n| n.to_string());
            assert_eq!(name, gsdc.format(address), "{description} {address:#06X}");
            if let Some(name) = name {
                assert_eq!(layout.address(&name), Some(address), "{description} {name}");
                named += 1;
            }
        }
        assert!(named >= 256, "{description}: {named} names");
    }
}

#[test]
fn a_name_gsdc_refuses_is_refused() {
    let odd = [
        "", "F", "P", "F0", "F0-", "-08", "Z0-08", "F0-256", "FG-01", "F0-0008", "F00-08", "f0-08",
        "F0.08", "P43-02", "P43.", "P999.99", "r43.02", "P4302", "F0-8", "F0-008",
    ];
    for (description, layout) in NUMBERINGS {
        let gsdc = gsdc_numbering(description);
        for name in odd {
            assert_eq!(
                layout.address(name),
                gsdc.parse(name).ok(),
                "{description} {name:?}"
            );
        }
    }
}

/// The manuals' own names: MD810 1.4.2 reads F0-08 at 0xF008 (figure 6:
/// PKE low byte F0, IND high byte 08); MV810's P43.02 is 0x2B02.
#[test]
fn the_manuals_names_are_their_addresses() {
    assert_eq!(md810dp::NUMBERING.address("F0-08"), Some(0xF008));
    assert_eq!(md810dp::NUMBERING.name(0xF008).unwrap().as_str(), "F0-08");
    assert_eq!(mv810_pnet02::NUMBERING.address("P43.02"), Some(0x2B02));
}
