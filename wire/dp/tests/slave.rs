//! The DP slave's answers, telegram by telegram, against the rules of
//! DP-V0 (IEC 61158-6-3; the standard diagnosis of EN 50170 vol. 2), with
//! MD810's card (descriptions/md810dp.toml): what a firmware team checks
//! its own slave against.

use profirust::fdl::{DataTelegram, DataTelegramHeader, FrameCountBit, FunctionCode, RequestType};
use wire_dp::slave::{DpSlave, Reply, State};
use wire_firmware::layouts::md810dp;

const MASTER: u8 = 2;
const SLAVE: u8 = 3;

fn slave() -> DpSlave {
    let card = wire_firmware::card("md810dp").unwrap();
    DpSlave::new(
        SLAVE,
        card,
        wire_firmware::manuals::drive(wire_firmware::card("md810dp").unwrap()),
    )
}

/// A request of the master to the slave's `sap` (the default SAP: `None`).
fn request(slave: &mut DpSlave, req: RequestType, sap: Option<u8>, pdu: &[u8]) -> Reply {
    let telegram = DataTelegram {
        h: DataTelegramHeader {
            da: SLAVE,
            sa: MASTER,
            dsap: sap,
            ssap: sap.map(|_| 62),
            fc: FunctionCode::Request {
                fcb: FrameCountBit::First,
                req,
            },
        },
        pdu,
    };
    slave.answer(&telegram)
}

fn slave_diag(slave: &mut DpSlave) -> Vec<u8> {
    match request(slave, RequestType::SrdLow, Some(60), &[]) {
        Reply::Data { pdu, .. } => pdu,
        other => panic!("Slave_Diag answered {other:?}"),
    }
}

/// Set_Prm: Lock_Req, no watchdog, min_Tsdr 11, the ident number, group 0,
/// then User_Prm_Data.
fn set_prm(slave: &mut DpSlave, status: u8, ident: u16, user_prm: &[u8]) -> Reply {
    let mut pdu = vec![status, 0, 0, 11];
    pdu.extend(ident.to_be_bytes());
    pdu.push(0);
    pdu.extend(user_prm);
    request(slave, RequestType::SrdLow, Some(61), &pdu)
}

/// User_Prm_Data at the GSD's defaults: the DPV1 status bytes, then F0-00
/// for each mapping (MD810 1.6 step 5).
fn default_user_prm() -> Vec<u8> {
    let mut prm = md810dp::USER_PRM_DPV1_STATUS.to_vec();
    prm.extend([0xF0, 0x00].repeat(30));
    prm
}

fn ident() -> [u8; 2] {
    md810dp::PROFIBUS_IDENT_NUMBER.to_be_bytes()
}

/// After power-on: Station_Not_Ready (status 1 bit 1), Prm_Req (status 2
/// bit 0) and the bit that is always 1 (bit 2), no master (255), the
/// slave's ident number, then MD810's device-related block (1.8: always 3
/// bytes) without a code, so without Ext_Diag.
#[test]
fn after_power_on_the_slave_asks_for_parameters() {
    let mut slave = slave();
    let [high, low] = ident();
    assert_eq!(
        slave_diag(&mut slave),
        [0x02, 0x05, 0x00, 0xFF, high, low, 0x03, 0x00, 0x00]
    );
    assert_eq!(slave.state(), State::WaitPrm);
}

/// Set_Prm, Chk_Cfg, then Data_Exchange with MD810 1.4.2's read of F0-08.
#[test]
fn parameters_and_configuration_lead_to_data_exchange() {
    let mut slave = slave();
    let [high, low] = ident();
    let accepted = set_prm(
        &mut slave,
        0x80,
        md810dp::PROFIBUS_IDENT_NUMBER,
        &default_user_prm(),
    );
    assert_eq!(accepted, Reply::ShortConfirmation);
    // Still not ready, but locked by the master, no Prm_Req.
    assert_eq!(
        slave_diag(&mut slave)[..6],
        [0x02, 0x04, 0x00, MASTER, high, low]
    );
    let configured = request(
        &mut slave,
        RequestType::SrdLow,
        Some(62),
        &md810dp::PPO1_CONFIG,
    );
    assert_eq!(configured, Reply::ShortConfirmation);
    assert_eq!(
        slave_diag(&mut slave)[..6],
        [0x00, 0x04, 0x00, MASTER, high, low]
    );
    let read = [0x10, 0xF0, 0x08, 0x00, 0, 0, 0, 0, 0, 0, 0, 0];
    let answer = request(&mut slave, RequestType::SrdHigh, None, &read);
    let expected = vec![0x10, 0xF0, 0x08, 0x00, 0x00, 0x00, 0x13, 0x88, 0, 0, 0, 0];
    assert_eq!(
        answer,
        Reply::Data {
            dsap: None,
            ssap: None,
            high_priority: false,
            pdu: expected
        }
    );
    // Get_Cfg: what is plugged.
    match request(&mut slave, RequestType::SrdLow, Some(59), &[]) {
        Reply::Data { pdu, .. } => assert_eq!(pdu, md810dp::PPO1_CONFIG),
        other => panic!("{other:?}"),
    }
}

/// Before Chk_Cfg, Data_Exchange is refused (RS: service not activated).
#[test]
fn data_exchange_before_the_configuration_is_not_activated() {
    let mut slave = slave();
    let answer = request(&mut slave, RequestType::SrdHigh, None, &[0; 12]);
    assert_eq!(
        answer,
        Reply::NotActivated {
            dsap: None,
            ssap: None
        }
    );
}

/// Prm_Fault (status 1 bit 6) for another ident number and for
/// User_Prm_Data a byte short; Cfg_Fault (bit 2) for config bytes of no
/// module, and the slave waits for parameters again (Prm_Req).
#[test]
fn faults_are_reported_in_slave_diag() {
    let mut slave = slave();
    let other = md810dp::PROFIBUS_IDENT_NUMBER + 1;
    set_prm(&mut slave, 0x80, other, &default_user_prm());
    assert_eq!(slave_diag(&mut slave)[..2], [0x42, 0x05]);
    let short = &default_user_prm()[1..];
    set_prm(&mut slave, 0x80, md810dp::PROFIBUS_IDENT_NUMBER, short);
    assert_eq!(slave_diag(&mut slave)[..2], [0x42, 0x05]);
    set_prm(
        &mut slave,
        0x80,
        md810dp::PROFIBUS_IDENT_NUMBER,
        &default_user_prm(),
    );
    request(&mut slave, RequestType::SrdLow, Some(62), &[0xF3, 0xF7]);
    assert_eq!(slave_diag(&mut slave)[..2], [0x06, 0x05]);
    assert_eq!(slave.state(), State::WaitPrm);
}

/// Sync_Req (Set_Prm status bit 5): Not_Supported (status 1 bit 4), not
/// Prm_Fault; Unlock_Req (bit 6) releases the slave.
#[test]
fn sync_is_not_supported_and_unlock_releases() {
    let mut slave = slave();
    set_prm(
        &mut slave,
        0xA0,
        md810dp::PROFIBUS_IDENT_NUMBER,
        &default_user_prm(),
    );
    assert_eq!(slave_diag(&mut slave)[..2], [0x12, 0x05]);
    set_prm(
        &mut slave,
        0x80,
        md810dp::PROFIBUS_IDENT_NUMBER,
        &default_user_prm(),
    );
    assert_eq!(slave_diag(&mut slave)[3], MASTER);
    set_prm(&mut slave, 0x40, md810dp::PROFIBUS_IDENT_NUMBER, &[]);
    assert_eq!(slave_diag(&mut slave)[..4], [0x02, 0x05, 0x00, 0xFF]);
}

/// MD810 1.8: a lost drive is 0x34 in the block's low byte, with Ext_Diag,
/// and Data_Exchange answers with high priority (DH) until the master has
/// read it.
#[test]
fn a_new_diagnosis_is_announced_with_high_priority() {
    let mut slave = slave();
    set_prm(
        &mut slave,
        0x80,
        md810dp::PROFIBUS_IDENT_NUMBER,
        &default_user_prm(),
    );
    request(
        &mut slave,
        RequestType::SrdLow,
        Some(62),
        &md810dp::PPO1_CONFIG,
    );
    slave.drive.set_link_lost(true);
    let high = |slave: &mut DpSlave| match request(slave, RequestType::SrdHigh, None, &[0; 12]) {
        Reply::Data { high_priority, .. } => high_priority,
        other => panic!("{other:?}"),
    };
    assert!(high(&mut slave));
    assert_eq!(slave_diag(&mut slave)[..1], [0x08]);
    assert_eq!(slave_diag(&mut slave)[6..], [0x03, 0x00, 0x34]);
    assert!(!high(&mut slave));
}

/// FDL status: a passive station, ready; telegrams for another station,
/// and broadcasts (Global_Control), get no answer.
#[test]
fn fdl_status_and_telegrams_for_others() {
    let mut slave = slave();
    assert_eq!(
        request(&mut slave, RequestType::FdlStatus, None, &[]),
        Reply::FdlStatus
    );
    let mut other = DataTelegram {
        h: DataTelegramHeader {
            da: SLAVE + 1,
            sa: MASTER,
            dsap: Some(60),
            ssap: Some(62),
            fc: FunctionCode::new_srd_low(FrameCountBit::First),
        },
        pdu: &[],
    };
    assert_eq!(slave.answer(&other), Reply::Nothing);
    other.h.da = 127;
    other.h.dsap = Some(58);
    other.h.fc = FunctionCode::Request {
        fcb: FrameCountBit::Inactive,
        req: RequestType::SdnLow,
    };
    other.pdu = &[0x00, 0x00];
    assert_eq!(slave.answer(&other), Reply::Nothing);
}
