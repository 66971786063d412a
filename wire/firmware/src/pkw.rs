//! The card's answer to a PKW request, for each kind of PKW channel: the
//! request decoded and the answer encoded by the layout's own codecs (the
//! support module every layout is built from), the parameter read from or
//! written to the [`Drive`].

use crate::drive::{Drive, Refused};
use crate::gsdc_support::{PkwCodec, U16Be};

/// The card's answer to the PKW `request` the master sent, by the layout's
/// codec `codec`; no answer (all 0) without one.
pub fn answer(codec: PkwCodec, drive: &mut Drive, request: &[U16Be; 4]) -> [U16Be; 4] {
    match codec {
        PkwCodec::PkeIndPwe => pke_ind_pwe(drive, request),
        PkwCodec::Profidrive => profidrive(drive, request),
        PkwCodec::StationCommand => station_command(drive, request),
        PkwCodec::None => [U16Be::new(0); 4],
    }
}

/// MD810 1.4.1: response 1 with the value (after a write, the value
/// written), or response 7 with the error code.
fn pke_ind_pwe(drive: &mut Drive, request: &[U16Be; 4]) -> [U16Be; 4] {
    use crate::gsdc_support::pkw_pke_ind_pwe::{
        PkwDecodeError, PkwErrorCode, PkwRequest, PkwResponse,
    };
    let error = |refused| match refused {
        Refused::NoSuchParameter => PkwErrorCode::IllegalAddress,
        // 1.4.1 lists no error for a parameter that cannot be read or
        // written: "4: 其它错误" (other error).
        Refused::ReadOnly | Refused::WriteOnly => PkwErrorCode::Other,
    };
    let response = match PkwRequest::decode(request) {
        Ok(PkwRequest::None) => PkwResponse::None,
        Ok(PkwRequest::Read { address }) => match drive.read(address) {
            Ok(value) => PkwResponse::Done { address, value },
            Err(refused) => PkwResponse::Failed {
                address,
                error: error(refused),
            },
        },
        Ok(PkwRequest::Write { address, value }) => match drive.write(address, value) {
            Ok(()) => PkwResponse::Done { address, value },
            Err(refused) => PkwResponse::Failed {
                address,
                error: error(refused),
            },
        },
        Err(PkwDecodeError::IllegalCommand { address, .. }) => PkwResponse::Failed {
            address,
            error: PkwErrorCode::IllegalCommand,
        },
        // Response codes are not requests; decode returns none for one.
        Err(PkwDecodeError::UnknownResponse(_) | PkwDecodeError::UnknownErrorCode(_)) => {
            PkwResponse::None
        }
    };
    response.encode()
}

/// The PROFIdrive profile: response 1 with a word value, 7 with the
/// profile's error number; requests the drive model has no data for
/// (double words, descriptions, arrays) are answered 7.
fn profidrive(drive: &mut Drive, request: &[U16Be; 4]) -> [U16Be; 4] {
    use crate::gsdc_support::pkw_profidrive::{
        PkwDecodeError, PkwErrorNumber, PkwRequest, PkwResponse,
    };
    let error = |refused| match refused {
        Refused::NoSuchParameter => PkwErrorNumber::ILLEGAL_PNU,
        Refused::ReadOnly => PkwErrorNumber::NOT_CHANGEABLE,
        // The profile has no number for a parameter that cannot be read.
        Refused::WriteOnly => PkwErrorNumber::ILLEGAL_PNU,
    };
    let response = match PkwRequest::decode(request) {
        Ok(PkwRequest::None) => PkwResponse::None,
        Ok(PkwRequest::Read { parameter }) => match drive.read(parameter.pnu.get()) {
            Ok(value) => PkwResponse::Word { parameter, value },
            Err(refused) => PkwResponse::Failed {
                parameter,
                error: error(refused),
            },
        },
        Ok(PkwRequest::WriteWord { parameter, value }) => {
            match drive.write(parameter.pnu.get(), value) {
                Ok(()) => PkwResponse::Word { parameter, value },
                Err(refused) => PkwResponse::Failed {
                    parameter,
                    error: error(refused),
                },
            }
        }
        Ok(other) => match other.parameter() {
            Some(parameter) => PkwResponse::Failed {
                parameter,
                error: PkwErrorNumber::WRONG_TYPE,
            },
            None => PkwResponse::None,
        },
        Err(PkwDecodeError::IllegalRequest { parameter, .. }) => PkwResponse::Failed {
            parameter,
            error: PkwErrorNumber::ILLEGAL_PNU,
        },
        Err(PkwDecodeError::ChangeReport { .. } | PkwDecodeError::UnknownResponse { .. }) => {
            PkwResponse::None
        }
    };
    response.encode()
}

/// The error code MV810's card answers (after the command + 0x80) for a
/// parameter the drive refuses. The manual gives the bytes of an error code
/// (section 3, PKW3 of the slave response) but no value: 2, Modbus's illegal
/// data address (the card reaches the drive over its RS-485 side), is this
/// model's own.
pub const STATION_COMMAND_REFUSED: u16 = 2;

/// MV810 section 3: the answer repeats the command and the address, with the
/// value read (0 after a write), or 0x80 + the command and an error code;
/// its stations are the request's, swapped (byte 0 the station that asked,
/// byte 1 the local station). A telegram that is no request (command 0,
/// what a master sends before it has one) is answered with zeros.
fn station_command(drive: &mut Drive, request: &[U16Be; 4]) -> [U16Be; 4] {
    use crate::gsdc_support::pkw_station_command::{
        PkwAccess, PkwReply, PkwRequest, PkwResponse, Stations,
    };
    let Ok(request) = PkwRequest::decode(request) else {
        return [U16Be::new(0); 4];
    };
    let command = request.access.command();
    let outcome = match request.access {
        PkwAccess::Read => drive.read(request.address).map(PkwReply::Value),
        PkwAccess::WriteAndStore { value } => drive
            .write(request.address, value)
            .map(|()| PkwReply::WrittenAndStored),
        PkwAccess::Write { value } => drive
            .write(request.address, value)
            .map(|()| PkwReply::Written),
    };
    PkwResponse {
        stations: Stations {
            target: request.stations.source,
            source: request.stations.target,
        },
        address: request.address,
        reply: outcome.unwrap_or(PkwReply::Failed {
            command,
            error: STATION_COMMAND_REFUSED,
        }),
    }
    .encode()
}
