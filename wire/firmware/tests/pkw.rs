//! The card answers the manuals' PKW requests for its drive, through the
//! layout's codecs.

use wire_firmware::drive::Drive;
use wire_firmware::gsdc_support::{PkwCodec, U16Be};
use wire_firmware::manuals;
use wire_firmware::pkw::answer;

/// `"10F0 0800 0000 1388"`, as the manuals print PKW: four hex words.
fn pkw(hex: &str) -> [U16Be; 4] {
    let words: Vec<U16Be> = hex
        .split_whitespace()
        .map(|w| U16Be::new(u16::from_str_radix(w, 16).unwrap()))
        .collect();
    words.try_into().unwrap()
}

fn md810() -> Drive {
    Drive::new(manuals::for_description("md810dp"))
}

/// MD810 manual 1.4.2, figure 6: read F0-08, answered 50.00 Hz.
#[test]
fn md810_reads_f0_08() {
    let mut drive = md810();
    let answered = answer(PkwCodec::PkeIndPwe, &mut drive, &pkw("10F0 0800 0000 0000"));
    assert_eq!(answered, pkw("10F0 0800 0000 1388"));
}

/// Figure 7: write 20.00 Hz to F0-08; the answer carries the value written,
/// and the drive holds it.
#[test]
fn md810_writes_f0_08() {
    let mut drive = md810();
    let answered = answer(PkwCodec::PkeIndPwe, &mut drive, &pkw("20F0 0800 0000 07D0"));
    assert_eq!(answered, pkw("10F0 0800 0000 07D0"));
    assert_eq!(drive.read(0xF008), Ok(2000));
    let again = answer(PkwCodec::PkeIndPwe, &mut drive, &pkw("10F0 0800 0000 0000"));
    assert_eq!(again, pkw("10F0 0800 0000 07D0"));
}

/// Figures 6 and 7's failure answer, `70F0 0800 0000 errCode`, with 1.4.1's
/// error 2, illegal address, for an address the drive does not have
/// (F0-99, 0xF063: this test's own; the MD810 model holds F0-08 only), and
/// error 1 for command 3, which 1.4.1 does not define.
#[test]
fn md810_refuses_an_illegal_address_and_command() {
    let mut drive = md810();
    let answered = answer(PkwCodec::PkeIndPwe, &mut drive, &pkw("10F0 6300 0000 0000"));
    assert_eq!(answered, pkw("70F0 6300 0000 0002"));
    let answered = answer(PkwCodec::PkeIndPwe, &mut drive, &pkw("30F0 0800 0000 0000"));
    assert_eq!(answered, pkw("70F0 0800 0000 0001"));
}

/// No request, no response: what a master sends before it has one.
#[test]
fn no_request_no_response() {
    for kind in [PkwCodec::PkeIndPwe, PkwCodec::Profidrive] {
        let mut drive = md810();
        let answered = answer(kind, &mut drive, &pkw("0000 0000 0000 0000"));
        assert_eq!(answered, pkw("0000 0000 0000 0000"), "{kind:?}");
    }
}

/// PROFIdrive: a read of a PNU the drive does not hold is response 7 with
/// error 0, impermissible PNU (the drive without a manual holds none).
#[test]
fn profidrive_refuses_an_unknown_pnu() {
    let mut drive = Drive::new(manuals::for_description("profidrive"));
    // Request 1 (read) of PNU 0x3E8 = 1000, subindex 0: this test's own.
    let answered = answer(
        PkwCodec::Profidrive,
        &mut drive,
        &pkw("13E8 0000 0000 0000"),
    );
    assert_eq!(answered, pkw("73E8 0000 0000 0000"));
}

/// PI9000 appendix I-3: the fault the drive reports is in 8000H, which the
/// card's diagnosis reports too; MD810 1.8: 0x34 when the card loses the
/// drive, whatever the drive's fault.
#[test]
fn the_diagnosis_reports_the_drive() {
    let mut pi9000 = Drive::new(manuals::for_description("9kdp1"));
    assert_eq!(pi9000.diagnosis_code(), 0);
    pi9000.set_fault(0x0B); // I-3: 000B, Motor Overload
    assert_eq!(
        (pi9000.diagnosis_code(), pi9000.read(0x8000)),
        (0x0B, Ok(0x0B))
    );
    let mut md810 = md810();
    md810.set_fault(0x12);
    md810.set_link_lost(true);
    assert_eq!(md810.diagnosis_code(), 0x34);
    md810.set_link_lost(false);
    assert_eq!(md810.diagnosis_code(), 0x12);
}
