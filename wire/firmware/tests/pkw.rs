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
    manuals::drive(wire_firmware::card("md810dp").unwrap())
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
    let mut drive = manuals::drive(wire_firmware::card("profidrive").unwrap());
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
    let mut pi9000 = manuals::drive(wire_firmware::card("9kdp1").unwrap());
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

/// MV810's card (section 3: station, command, address, value): its drive
/// model holds the parameters at the addresses the layout's mappings give,
/// and answers its control word at the bits the layout names.
mod mv810 {
    use super::pkw;
    use wire_firmware::drive::Drive;
    use wire_firmware::gsdc_support::PkwCodec;
    use wire_firmware::layouts::mv810_pnet02 as layout;
    use wire_firmware::manuals;
    use wire_firmware::pkw::{answer, STATION_COMMAND_REFUSED};

    fn mv810() -> Drive {
        manuals::drive(wire_firmware::card("mv810-pnet02").unwrap())
    }

    #[test]
    fn the_status_word_answers_the_control_word_at_the_layouts_bits() {
        use layout::{control_word as c, status_word as s};
        let answer = |control: u16| mv810().model.status_of.unwrap().answer(control);
        let ready = s::READY_STATUS.with(0, 1);
        let stopped = s::STOP.with(ready, 1);
        assert_eq!(answer(0), stopped);
        assert_eq!(
            answer(c::FORWARD_RUNNING.with(0, 1)),
            s::FORWARD_RUNNING.with(ready, 1)
        );
        assert_eq!(
            answer(c::REVERSE_RUNNING.with(0, 1)),
            s::REVERSE_RUNNING.with(ready, 1)
        );
        for stop in [c::DECELERATE_TO_STOP, c::COAST_TO_STOP, c::EMERGENCY_STOP] {
            assert_eq!(answer(stop.with(c::FORWARD_RUNNING.with(0, 1), 1)), stopped);
        }
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
                PkwCodec::StationCommand,
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
            PkwCodec::StationCommand,
            &mut drive,
            &pkw("0101 0007 2B02 0005"),
        );
        assert_eq!(answered, pkw("0101 0007 2B02 0000"));
        assert_eq!(drive.read(0x2B02), Ok(5));
        let answered = answer(
            PkwCodec::StationCommand,
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
            PkwCodec::StationCommand,
            &mut drive,
            &pkw("0101 0003 2B28 0001"),
        );
        let refused = format!("0101 0083 2B28 {STATION_COMMAND_REFUSED:04X}");
        assert_eq!(answered, pkw(&refused));
        let answered = answer(
            PkwCodec::StationCommand,
            &mut drive,
            &pkw("0000 0000 0000 0000"),
        );
        assert_eq!(answered, pkw("0000 0000 0000 0000"));
    }
}
