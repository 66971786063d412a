//! The PKW channel of a telegram, read by the firmware's own codecs
//! (`crate::pkw`, from `templates/support/`), so gsdc reads a request or a
//! response exactly as the card does, and refuses what the card refuses.

use crate::i18n::Lang;
use crate::ir::{Direction, Ir, PkwKind};
use crate::pkw::profidrive::{PROFILE_ERRORS, REQUESTS, RESPONSES};
use crate::pkw::{pkw_pke_ind_pwe as pke, pkw_profidrive as profidrive};
use crate::pkw::{pkw_station_command as station, U16Be};
use serde::Serialize;

/// A PKW request (to the drive) or response (from it), decoded.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Pkw {
    pub channel: Channel,
    pub kind: PkwSide,
    /// The station bytes of an MV810-style channel.
    pub stations: Option<Stations>,
    /// The command or response code as it is on the bus (the PKE's top four
    /// bits, or the command word).
    pub code: u16,
    /// What the code means, in the manual's words; `None` when the manual
    /// does not define it.
    pub meaning: Option<&'static str>,
    pub parameter: Option<Parameter>,
    /// The value written, read, or echoed: a word, or a PROFIdrive double
    /// word.
    pub value: Option<u32>,
    pub error: Option<PkwError>,
    /// Why the card refuses the telegram, when it does: it is not one the
    /// manual defines.
    pub refused: Option<String>,
}

/// The kind of PKW channel, as the description's `telegram.pkw` names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Channel {
    /// PKE, IND, PWE (MD810); codes are four bits, the manual writes them
    /// in decimal.
    PkeIndPwe,
    /// Station, command, address, value (MV810); codes are command words,
    /// the manual writes them in hex.
    StationCommandAddressValue,
    /// The PROFIdrive profile's PKE, IND, PWE1, PWE2; ids are four bits,
    /// written in decimal.
    Profidrive,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum PkwSide {
    Request,
    Response,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct Stations {
    pub target: u8,
    pub source: u8,
}

/// A drive parameter: its address and its name as the manual writes it
/// (`F0-08`), when the description's numbering has one for the address.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Parameter {
    /// The PNU of a PROFIdrive channel.
    pub address: u16,
    pub name: Option<String>,
    /// A PROFIdrive channel's subindex (IND bits 15-8).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub subindex: Option<u8>,
}

#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct PkwError {
    pub code: u16,
    /// The manual's text; `None` where it lists no error codes (MV810).
    pub text: Option<&'static str>,
}

impl Pkw {
    fn new(channel: Channel, kind: PkwSide, code: u16) -> Self {
        Pkw {
            channel,
            kind,
            stations: None,
            code,
            meaning: None,
            parameter: None,
            value: None,
            error: None,
            refused: None,
        }
    }
}

/// The PKW channel's four words, read as the module's direction sends them:
/// out is a request, in a response. `None` when the telegram has no channel.
pub(super) fn decode(ir: &Ir, direction: Direction, words: &[U16Be; 4]) -> Option<Pkw> {
    let parameter = |address| Parameter {
        address,
        name: ir.numbering.as_ref().and_then(|n| n.format(address)),
        subindex: None,
    };
    match (ir.telegram.pkw, direction) {
        (PkwKind::None, _) => None,
        (PkwKind::PkeIndPwe, Direction::Out) => Some(pke_request(words, parameter)),
        (PkwKind::PkeIndPwe, Direction::In) => Some(pke_response(words, parameter)),
        (PkwKind::StationCommandAddressValue, Direction::Out) => {
            Some(station_request(words, parameter))
        }
        (PkwKind::StationCommandAddressValue, Direction::In) => {
            Some(station_response(words, parameter))
        }
        (PkwKind::Profidrive, Direction::Out) => Some(profidrive_request(words, parameter)),
        (PkwKind::Profidrive, Direction::In) => Some(profidrive_response(words, parameter)),
    }
}

/// PKE bits 15-12: the command or response code.
fn pke_code(words: [U16Be; 4]) -> u16 {
    words[0].get() >> 12
}

fn pke_request(words: &[U16Be; 4], parameter: impl Fn(u16) -> Parameter) -> Pkw {
    let request = match pke::PkwRequest::decode(words) {
        Ok(request) => request,
        Err(error) => return pke_refused(PkwSide::Request, words, error, parameter),
    };
    let mut pkw = Pkw::new(
        Channel::PkeIndPwe,
        PkwSide::Request,
        pke_code(request.encode()),
    );
    match request {
        pke::PkwRequest::None => pkw.meaning = Some("no request"),
        pke::PkwRequest::Read { address } => {
            pkw.meaning = Some("read");
            pkw.parameter = Some(parameter(address));
        }
        pke::PkwRequest::Write { address, value } => {
            pkw.meaning = Some("write");
            pkw.parameter = Some(parameter(address));
            pkw.value = Some(value.into());
        }
    }
    pkw
}

fn pke_response(words: &[U16Be; 4], parameter: impl Fn(u16) -> Parameter) -> Pkw {
    let response = match pke::PkwResponse::decode(words) {
        Ok(response) => response,
        Err(error) => return pke_refused(PkwSide::Response, words, error, parameter),
    };
    let mut pkw = Pkw::new(
        Channel::PkeIndPwe,
        PkwSide::Response,
        pke_code(response.encode()),
    );
    match response {
        pke::PkwResponse::None => pkw.meaning = Some("no request"),
        pke::PkwResponse::Done { address, value } => {
            pkw.meaning = Some("done");
            pkw.parameter = Some(parameter(address));
            pkw.value = Some(value.into());
        }
        pke::PkwResponse::Failed { address, error } => {
            pkw.meaning = Some("cannot execute");
            pkw.parameter = Some(parameter(address));
            pkw.error = Some(PkwError {
                code: error.code(),
                text: Some(pke_error_text(error)),
            });
        }
    }
    pkw
}

/// MD810 §1.4.1: the error codes are Modbus's.
fn pke_error_text(error: pke::PkwErrorCode) -> &'static str {
    crate::pkw::pke_error_meaning(error).get(Lang::En)
}

fn pke_refused(
    side: PkwSide,
    words: &[U16Be; 4],
    error: pke::PkwDecodeError,
    parameter: impl Fn(u16) -> Parameter,
) -> Pkw {
    let refused = Pkw::new(Channel::PkeIndPwe, side, pke_code(*words));
    match error {
        pke::PkwDecodeError::IllegalCommand { command, address } => Pkw {
            parameter: Some(parameter(address)),
            refused: Some(format!(
                "command {command} is not one the manual defines (0 no request, 1 read, 2 write): the drive answers 7, cannot execute, with error 1, illegal command"
            )),
            ..refused
        },
        pke::PkwDecodeError::UnknownResponse(code) => Pkw {
            refused: Some(format!(
                "response code {code} is not one the manual defines (0 no request, 1 done, 7 cannot execute)"
            )),
            ..refused
        },
        pke::PkwDecodeError::UnknownErrorCode(error) => Pkw {
            meaning: Some("cannot execute"),
            error: Some(PkwError {
                code: error,
                text: None,
            }),
            refused: Some(format!(
                "error code {error} is not one the manual defines (1 to 4)"
            )),
            ..refused
        },
    }
}

const STATION: Channel = Channel::StationCommandAddressValue;

fn station_meaning(command: station::PkwCommand) -> &'static str {
    match command {
        station::PkwCommand::Read => "read one",
        station::PkwCommand::WriteAndStore => "write one and store it in EEPROM",
        station::PkwCommand::Write => "write one without storing it",
    }
}

fn stations(s: station::Stations) -> Stations {
    Stations {
        target: s.target,
        source: s.source,
    }
}

fn station_request(words: &[U16Be; 4], parameter: impl Fn(u16) -> Parameter) -> Pkw {
    let request = match station::PkwRequest::decode(words) {
        Ok(request) => request,
        Err(error) => return station_refused(PkwSide::Request, error),
    };
    let command = request.access.command();
    Pkw {
        stations: Some(stations(request.stations)),
        meaning: Some(station_meaning(command)),
        parameter: Some(parameter(request.address)),
        value: match request.access {
            station::PkwAccess::Read => None,
            station::PkwAccess::WriteAndStore { value } | station::PkwAccess::Write { value } => {
                Some(value.into())
            }
        },
        ..Pkw::new(STATION, PkwSide::Request, command.code())
    }
}

fn station_response(words: &[U16Be; 4], parameter: impl Fn(u16) -> Parameter) -> Pkw {
    let response = match station::PkwResponse::decode(words) {
        Ok(response) => response,
        Err(error) => return station_refused(PkwSide::Response, error),
    };
    // The command word the codec writes for this reply.
    let code = response.encode()[1].get();
    let mut pkw = Pkw {
        stations: Some(stations(response.stations)),
        parameter: Some(parameter(response.address)),
        ..Pkw::new(STATION, PkwSide::Response, code)
    };
    match response.reply {
        station::PkwReply::Value(value) => {
            pkw.meaning = Some("value read");
            pkw.value = Some(value.into());
        }
        station::PkwReply::WrittenAndStored => pkw.meaning = Some("written and stored in EEPROM"),
        station::PkwReply::Written => pkw.meaning = Some("written without storing it"),
        station::PkwReply::Failed { command, error } => {
            pkw.meaning = Some(match command {
                station::PkwCommand::Read => "read one failed",
                station::PkwCommand::WriteAndStore => "write and store failed",
                station::PkwCommand::Write => "write failed",
            });
            // The manual lists no error codes.
            pkw.error = Some(PkwError {
                code: error,
                text: None,
            });
        }
    }
    pkw
}

fn station_refused(side: PkwSide, error: station::PkwDecodeError) -> Pkw {
    match error {
        station::PkwDecodeError::UnknownCommand(code) => Pkw {
            refused: Some(format!(
                "command 0x{code:04X} is not one the manual defines (0x03 read one, 0x06 write and store, 0x07 write; 0x80 added on error){}",
                if code == 0 { "; 0 is what a master sends before it has a request" } else { "" }
            )),
            ..Pkw::new(STATION, side, code)
        },
        station::PkwDecodeError::ReadCount(count) => Pkw {
            meaning: Some(station_meaning(station::PkwCommand::Read)),
            refused: Some(format!(
                "a read's count (PKW3) is always 1; this one is {count}"
            )),
            ..Pkw::new(STATION, side, station::PkwCommand::Read.code())
        },
    }
}

// ---------------------------------------------------------------------------
// PROFIdrive

/// Error numbers some manuals give beyond the profile's (MICROMASTER 4
/// PROFIBUS board Table 3-5, MASTERDRIVES Table 8.2-6, SINAMICS manuals; see
/// docs/wire-format.md), with the manuals that give them: a drive may mean
/// something else by them.
const VENDOR_ERRORS: [(u16, &str); 19] = [
    (9, "description data not available (SINAMICS G120X, TR encoTRive, SINAMICS DCP; not every manual's)"),
    (15, "no text array available (MASTERDRIVES, SINAMICS G120X; not every manual's)"),
    (20, "illegal value (MASTERDRIVES, SINAMICS CU240B-2 and G120; not every manual's)"),
    (21, "response too long (MASTERDRIVES; not every manual's)"),
    (22, "non-admissible parameter address (MASTERDRIVES; not every manual's)"),
    (23, "non-admissible format (MASTERDRIVES; not every manual's)"),
    (24, "inconsistent number of values (MASTERDRIVES; not every manual's)"),
    (101, "parameter number currently deactivated (MICROMASTER 4, MASTERDRIVES, SINAMICS G120: device-specific)"),
    (102, "channel not wide enough (MICROMASTER 4, MASTERDRIVES, SINAMICS G120: device-specific)"),
    (103, "incorrect number of PKWs (MASTERDRIVES: device-specific)"),
    (104, "illegal parameter value (MICROMASTER 4, MASTERDRIVES, SINAMICS G120: device-specific)"),
    (105, "the parameter is indexed (MASTERDRIVES: device-specific)"),
    (106, "request not implemented (MICROMASTER 4, MASTERDRIVES, SINAMICS G120: device-specific)"),
    (107, "no write access with the controller enabled (SINAMICS CU240B-2 and G120C: device-specific)"),
    (134, "write access only for commissioning (SINAMICS G120: device-specific)"),
    (135, "know-how protection active (SINAMICS G120: device-specific)"),
    (200, "modified minimum not reached (MICROMASTER 4, SINAMICS CU240B-2 and G120: device-specific)"),
    (201, "modified maximum exceeded (MICROMASTER 4, SINAMICS CU240B-2 and G120: device-specific)"),
    (204, "the access authorization does not cover changing parameters (MICROMASTER 4, SINAMICS CU240B-2 and G120: device-specific)"),
];

/// A number none of the manuals gives.
const OWN_ERROR: &str = "not a number any of the manuals gives: the drive's own";

/// What an error number of response 7 means: the profile's meaning, or
/// what the manuals that give it mean, or that it is the drive's own.
fn error_text(number: profidrive::PkwErrorNumber) -> &'static str {
    if let Some((_, meaning)) = PROFILE_ERRORS.iter().find(|(n, _)| *n == number) {
        return meaning.get(Lang::En);
    }
    VENDOR_ERRORS
        .iter()
        .find(|(n, _)| *n == number.0)
        .map_or(OWN_ERROR, |(_, text)| text)
}

/// A PROFIdrive parameter: its PNU, named by the description's numbering,
/// and its subindex.
fn profidrive_parameter(
    p: profidrive::Parameter,
    parameter: &impl Fn(u16) -> Parameter,
) -> Parameter {
    Parameter {
        subindex: Some(p.subindex),
        ..parameter(p.pnu.get())
    }
}

fn profidrive_request(words: &[U16Be; 4], parameter: impl Fn(u16) -> Parameter) -> Pkw {
    use profidrive::PkwRequest as R;
    let request = match R::decode(words) {
        Ok(request) => request,
        Err(error) => return profidrive_refused(PkwSide::Request, error, &parameter),
    };
    let id = request.id();
    let value = match request {
        R::WriteWord { value, .. } | R::WriteArrayWord { value, .. } => Some(value.into()),
        R::WriteDoubleWord { value, .. }
        | R::WriteDescription { value, .. }
        | R::WriteArrayDoubleWord { value, .. } => Some(value),
        _ => None,
    };
    Pkw {
        meaning: Some(REQUESTS[usize::from(id)].get(Lang::En)),
        parameter: request
            .parameter()
            .map(|p| profidrive_parameter(p, &parameter)),
        value,
        ..Pkw::new(Channel::Profidrive, PkwSide::Request, id.into())
    }
}

fn profidrive_response(words: &[U16Be; 4], parameter: impl Fn(u16) -> Parameter) -> Pkw {
    use profidrive::PkwResponse as R;
    let response = match R::decode(words) {
        Ok(response) => response,
        Err(error) => return profidrive_refused(PkwSide::Response, error, &parameter),
    };
    let id = response.id();
    let (value, error) = match response {
        R::Word { value, .. } | R::ArrayWord { value, .. } => (Some(value.into()), None),
        R::ArrayLength { count, .. } => (Some(count.into()), None),
        R::DoubleWord { value, .. }
        | R::Description { value, .. }
        | R::ArrayDoubleWord { value, .. } => (Some(value), None),
        R::Failed { error, .. } => (
            None,
            Some(PkwError {
                code: error.0,
                text: Some(error_text(error)),
            }),
        ),
        R::None | R::NoAuthority { .. } => (None, None),
    };
    Pkw {
        meaning: Some(RESPONSES[usize::from(id)].get(Lang::En)),
        parameter: response
            .parameter()
            .map(|p| profidrive_parameter(p, &parameter)),
        value,
        error,
        ..Pkw::new(Channel::Profidrive, PkwSide::Response, id.into())
    }
}

fn profidrive_refused(
    side: PkwSide,
    error: profidrive::PkwDecodeError,
    parameter: &impl Fn(u16) -> Parameter,
) -> Pkw {
    use profidrive::PkwDecodeError as E;
    let (id, meaning, why, about) = match error {
        E::IllegalRequest { id, parameter } => (
            id,
            "not the profile's",
            format!(
                "request id {id} is not the profile's (0 to 9): {}; the drive answers 7, cannot execute",
                if id == 10 { "10 is reserved" } else { "11 to 15 are Siemens' extensions" }
            ),
            Some(parameter),
        ),
        E::ChangeReport { id } => (
            id,
            "a parameter change report",
            format!("response id {id} is a parameter change report (9 to 12), which the channel does not carry: SPM, their toggle bit, is always 0"),
            None,
        ),
        E::UnknownResponse { id } => (
            id,
            "not the profile's",
            format!("response id {id} is not the profile's (0 to 8, and 9 to 12 change reports)"),
            None,
        ),
    };
    Pkw {
        meaning: Some(meaning),
        parameter: about.map(|p| profidrive_parameter(p, parameter)),
        refused: Some(why),
        ..Pkw::new(Channel::Profidrive, side, id.into())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use profidrive::PkwErrorNumber;

    #[test]
    fn each_error_number_has_one_meaning() {
        let mut numbers: Vec<u16> = PROFILE_ERRORS
            .iter()
            .map(|(n, _)| n.0)
            .chain(VENDOR_ERRORS.iter().map(|(n, _)| *n))
            .collect();
        let count = numbers.len();
        numbers.sort_unstable();
        numbers.dedup();
        assert_eq!(numbers.len(), count);
    }

    #[test]
    fn error_texts_say_whose_a_number_is() {
        assert_eq!(
            error_text(PkwErrorNumber::OPERATING_STATE),
            "the request cannot be processed in the operating state"
        );
        assert_eq!(
            error_text(PkwErrorNumber(0)),
            "impermissible parameter number (PNU)"
        );
        assert!(error_text(PkwErrorNumber(106)).starts_with("request not implemented ("));
        assert_eq!(error_text(PkwErrorNumber(50)), OWN_ERROR);
    }
}
