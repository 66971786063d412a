//! Each layout's `NUMBERING` reads and writes the drive's parameter names
//! exactly as gsdc reads and writes the description's: every address of the
//! 16-bit space named alike and read back, and odd names read alike. What
//! gsdc does, build.rs wrote with gsdc itself (`<stem>.numbering`), so this
//! crate needs gsdc only as its build dependency.

use gsdc_firmware_check::gsdc_support::Numbering;
use gsdc_firmware_check::{md810dp, mv810_pnet02, powtran_9kdp1, profidrive};

const NUMBERINGS: [(&str, &Numbering, &str); 4] = [
    (
        "md810dp",
        &md810dp::NUMBERING,
        include_str!(concat!(env!("OUT_DIR"), "/md810dp.numbering")),
    ),
    (
        "mv810-pnet02",
        &mv810_pnet02::NUMBERING,
        include_str!(concat!(env!("OUT_DIR"), "/mv810-pnet02.numbering")),
    ),
    (
        "9kdp1",
        &powtran_9kdp1::NUMBERING,
        include_str!(concat!(env!("OUT_DIR"), "/9kdp1.numbering")),
    ),
    (
        "profidrive",
        &profidrive::NUMBERING,
        include_str!(concat!(env!("OUT_DIR"), "/profidrive.numbering")),
    ),
];

/// gsdc's name of every address it names.
fn gsdc_names(text: &str) -> Vec<Option<String>> {
    let mut names = vec![None; 0x1_0000];
    for line in text.lines().filter_map(|l| l.strip_prefix("A ")) {
        let (address, name) = line.split_once(' ').unwrap();
        names[usize::from_str_radix(address, 16).unwrap()] = Some(name.to_string());
    }
    names
}

#[test]
fn every_address_is_named_and_read_back_as_gsdc_does() {
    for (description, layout, gsdc) in NUMBERINGS {
        let gsdc = gsdc_names(gsdc);
        let mut named = 0;
        for address in 0..=u16::MAX {
            let name = layout.name(address).map(|n| n.to_string());
            assert_eq!(
                name,
                gsdc[usize::from(address)],
                "{description} {address:#06X}"
            );
            if let Some(name) = name {
                assert_eq!(layout.address(&name), Some(address), "{description} {name}");
                named += 1;
            }
        }
        assert!(named >= 256, "{description}: {named} names");
    }
}

#[test]
fn an_odd_name_is_read_as_gsdc_reads_it() {
    for (description, layout, gsdc) in NUMBERINGS {
        let reads: Vec<&str> = gsdc.lines().filter_map(|l| l.strip_prefix("R ")).collect();
        assert_eq!(reads.len(), 20, "{description}");
        for read in reads {
            let (quoted, address) = read.rsplit_once(' ').unwrap();
            let name = quoted.trim_matches('"');
            let expected = match address {
                "none" => None,
                hex => Some(u16::from_str_radix(hex, 16).unwrap()),
            };
            assert_eq!(layout.address(name), expected, "{description} {name:?}");
        }
    }
}

/// The manuals' own names: MD810 1.4.2 reads F0-08 at 0xF008 (figure 6:
/// PKE low byte F0, IND high byte 08); MV810's P43.02 is 0x2B02 (the
/// description's numbering: group high byte, index low byte).
#[test]
fn the_manuals_names_are_their_addresses() {
    assert_eq!(md810dp::NUMBERING.address("F0-08"), Some(0xF008));
    assert_eq!(md810dp::NUMBERING.name(0xF008).unwrap().as_str(), "F0-08");
    assert_eq!(mv810_pnet02::NUMBERING.address("P43.02"), Some(0x2B02));
}
