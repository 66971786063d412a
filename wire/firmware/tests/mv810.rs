//! MV810's card: its drive model holds the parameters at the addresses the
//! layout's mappings give, and its PKW channel (station, command, address,
//! value) answers as section 3 of the manual says, through the layout's
//! codec.

use wire_firmware::drive::Drive;
use wire_firmware::gsdc_support::U16Be;
use wire_firmware::layouts::mv810_pnet02 as layout;
use wire_firmware::manuals;
use wire_firmware::pkw::{answer, PkwKind, STATION_COMMAND_REFUSED};

fn pkw(hex: &str) -> [U16Be; 4] {
    let words: Vec<U16Be> = hex
        .split_whitespace()
        .map(|w| U16Be::new(u16::from_str_radix(w, 16).unwrap()))
        .collect();
    words.try_into().unwrap()
}

fn mv810() -> Drive {
    Drive::new(manuals::for_description("mv810-pnet02"))
}

#[test]
fn the_drive_holds_its_parameters_where_the_layout_maps_them() {
    let drive = mv810();
    let at = |name: &str| drive.named(name).unwrap().address;
    assert_eq!(Some(at("P43.01")), layout::settings::MAPPINGS[0].parameter);
    assert_eq!(Some(at("P43.02")), layout::pzd_out::MAPPINGS[0].parameter);
    assert_eq!(Some(at("P43.13")), layout::pzd_in::MAPPINGS[0].parameter);
}

/// Section 3: read one code (0x03, count 1); the reply repeats command and
/// address with the value, its stations swapped.
#[test]
fn reads_p43_02() {
    let mut drive = mv810();
    drive.write(0x2B02, 4).unwrap();
    assert_eq!(
        answer(
            PkwKind::StationCommand,
            &mut drive,
            &pkw("0102 0003 2B02 0001")
        ),
        pkw("0201 0003 2B02 0004")
    );
}

/// 0x06 writes and stores, 0x07 writes: the reply's value word is 0.
#[test]
fn writes_p43_02() {
    let mut drive = mv810();
    let answered = answer(
        PkwKind::StationCommand,
        &mut drive,
        &pkw("0101 0007 2B02 0005"),
    );
    assert_eq!(answered, pkw("0101 0007 2B02 0000"));
    assert_eq!(drive.read(0x2B02), Ok(5));
    let answered = answer(
        PkwKind::StationCommand,
        &mut drive,
        &pkw("0101 0006 2B02 0006"),
    );
    assert_eq!(answered, pkw("0101 0006 2B02 0000"));
    assert_eq!(drive.read(0x2B02), Ok(6));
}

/// 0x80 + the command and the error code for a parameter the drive does
/// not hold (P43.40, 0x2B28: this test's own); zeros for no request.
#[test]
fn refuses_a_parameter_it_does_not_hold() {
    let mut drive = mv810();
    let answered = answer(
        PkwKind::StationCommand,
        &mut drive,
        &pkw("0101 0003 2B28 0001"),
    );
    let refused = format!("0101 0083 2B28 {STATION_COMMAND_REFUSED:04X}");
    assert_eq!(answered, pkw(&refused));
    let answered = answer(
        PkwKind::StationCommand,
        &mut drive,
        &pkw("0000 0000 0000 0000"),
    );
    assert_eq!(answered, pkw("0000 0000 0000 0000"));
}
