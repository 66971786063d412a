// The PKW channel, PROFIdrive style (gsdc templates/support/pkw_pke_ind_pwe.rs):
// PKE, IND, PWE high, PWE low. PKE bits 15-12 hold the command or response
// code, PKE bits 7-0 the parameter address's high byte, IND bits 15-8 its low
// byte, the PWE low word the value or error code.
// Reserved bits (PKE 11-8, IND 7-0, the PWE high word) are written 0 and not
// read, and neither is the rest of a telegram without a request: a master
// may leave old values there.

use super::U16Be;

// PKE bits 15-12.
const PKW_NO_REQUEST: u8 = 0;
const PKW_READ: u8 = 1;
const PKW_WRITE: u8 = 2;
const PKW_DONE: u8 = 1;
const PKW_CANNOT_EXECUTE: u8 = 7;

/// A parameter request from the master.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PkwRequest {
    /// Command 0: no request.
    None,
    /// Command 1: read the parameter at `address`.
    Read { address: u16 },
    /// Command 2: write `value` to the parameter at `address`.
    Write { address: u16, value: u16 },
}

/// The drive's answer to a parameter request.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PkwResponse {
    /// Response 0: no request.
    None,
    /// Response 1: done; `value` is the parameter's value, after a write the
    /// value written.
    Done { address: u16, value: u16 },
    /// Response 7: cannot execute, for the reason `error`.
    Failed { address: u16, error: PkwErrorCode },
}

/// Why a request cannot be executed: the PWE low word of response 7.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u16)]
pub enum PkwErrorCode {
    IllegalCommand = 1,
    IllegalAddress = 2,
    IllegalData = 3,
    Other = 4,
}

/// A PKW telegram that is not one the manual defines.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PkwDecodeError {
    /// A request command other than 0, 1 and 2: the drive answers
    /// [`PkwResponse::Failed`] with [`PkwErrorCode::IllegalCommand`] for `address`.
    IllegalCommand { command: u8, address: u16 },
    /// A response code other than 0, 1 and 7.
    UnknownResponse(u8),
    /// Response 7 with an error code other than 1 to 4.
    UnknownErrorCode(u16),
}

impl PkwRequest {
    pub fn encode(self) -> [U16Be; 4] {
        match self {
            PkwRequest::None => pkw_words(PKW_NO_REQUEST, 0, 0),
            PkwRequest::Read { address } => pkw_words(PKW_READ, address, 0),
            PkwRequest::Write { address, value } => pkw_words(PKW_WRITE, address, value),
        }
    }

    pub fn decode(words: &[U16Be; 4]) -> Result<Self, PkwDecodeError> {
        let (command, address, value) = pkw_fields(words);
        match command {
            PKW_NO_REQUEST => Ok(PkwRequest::None),
            PKW_READ => Ok(PkwRequest::Read { address }),
            PKW_WRITE => Ok(PkwRequest::Write { address, value }),
            command => Err(PkwDecodeError::IllegalCommand { command, address }),
        }
    }
}

impl PkwResponse {
    pub fn encode(self) -> [U16Be; 4] {
        match self {
            PkwResponse::None => pkw_words(PKW_NO_REQUEST, 0, 0),
            PkwResponse::Done { address, value } => pkw_words(PKW_DONE, address, value),
            PkwResponse::Failed { address, error } => {
                pkw_words(PKW_CANNOT_EXECUTE, address, error.code())
            }
        }
    }

    pub fn decode(words: &[U16Be; 4]) -> Result<Self, PkwDecodeError> {
        let (code, address, value) = pkw_fields(words);
        match code {
            PKW_NO_REQUEST => Ok(PkwResponse::None),
            PKW_DONE => Ok(PkwResponse::Done { address, value }),
            PKW_CANNOT_EXECUTE => match PkwErrorCode::from_code(value) {
                Some(error) => Ok(PkwResponse::Failed { address, error }),
                None => Err(PkwDecodeError::UnknownErrorCode(value)),
            },
            code => Err(PkwDecodeError::UnknownResponse(code)),
        }
    }
}

impl PkwErrorCode {
    pub const fn from_code(code: u16) -> Option<Self> {
        match code {
            1 => Some(PkwErrorCode::IllegalCommand),
            2 => Some(PkwErrorCode::IllegalAddress),
            3 => Some(PkwErrorCode::IllegalData),
            4 => Some(PkwErrorCode::Other),
            _ => None,
        }
    }

    pub const fn code(self) -> u16 {
        self as u16
    }
}

/// PKE, IND, PWE high, PWE low of a code, an address and a value.
fn pkw_words(code: u8, address: u16, value: u16) -> [U16Be; 4] {
    let [high, low] = address.to_be_bytes();
    [
        U16Be::new((u16::from(code) << 12) | u16::from(high)),
        U16Be::new(u16::from(low) << 8),
        U16Be::new(0),
        U16Be::new(value),
    ]
}

/// The code, the address and the value of PKE, IND, PWE high, PWE low.
fn pkw_fields(words: &[U16Be; 4]) -> (u8, u16, u16) {
    let [pke, ind, _, pwe_low] = words.map(U16Be::get);
    let code = (pke >> 12) as u8;
    let address = ((pke & 0x00FF) << 8) | (ind >> 8);
    (code, address, pwe_low)
}
