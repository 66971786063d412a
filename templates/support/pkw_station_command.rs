// The PKW channel with station numbers (gsdc
// templates/support/pkw_station_command.rs): PKW0 target station (high byte)
// and source station (low byte), for the card's forwarding over RS-485; PKW1
// the command; PKW2 the parameter address; PKW3 the value, or the count
// (always 1) of a read.
// The drive answers with the command, 0x80 + the command on error. The value
// word of a write reply is 0 and not read.

use super::U16Be;

/// Added to the command of a failed request in the reply.
const PKW_FAILED: u16 = 0x80;
/// The count of a read: the card reads one parameter at a time.
const PKW_READ_COUNT: u16 = 1;

/// A command word of PKW1.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u16)]
pub enum PkwCommand {
    /// Read one parameter.
    Read = 0x03,
    /// Write one parameter and store it in EEPROM.
    WriteAndStore = 0x06,
    /// Write one parameter without storing it.
    Write = 0x07,
}

/// The stations of PKW0.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stations {
    /// Byte 0: the station the telegram is for.
    pub target: u8,
    /// Byte 1: the station that sends it.
    pub source: u8,
}

/// A parameter request from the master.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PkwRequest {
    pub stations: Stations,
    pub address: u16,
    pub access: PkwAccess,
}

/// What a request does with the parameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PkwAccess {
    Read,
    WriteAndStore { value: u16 },
    Write { value: u16 },
}

/// The drive's answer to a parameter request.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PkwResponse {
    pub stations: Stations,
    pub address: u16,
    pub reply: PkwReply,
}

/// What the drive answers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PkwReply {
    /// The parameter's value, to a read.
    Value(u16),
    /// The parameter was written and stored in EEPROM.
    WrittenAndStored,
    /// The parameter was written without storing it.
    Written,
    /// The command failed; `error` is the drive's error code.
    Failed { command: PkwCommand, error: u16 },
}

/// A PKW telegram that is not one the manual defines.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PkwDecodeError {
    /// A command word the manual does not list; 0 is what a master sends
    /// before it has a request.
    UnknownCommand(u16),
    /// A read whose count is not 1.
    ReadCount(u16),
}

impl PkwCommand {
    pub const fn from_code(code: u16) -> Option<Self> {
        match code {
            0x03 => Some(PkwCommand::Read),
            0x06 => Some(PkwCommand::WriteAndStore),
            0x07 => Some(PkwCommand::Write),
            _ => None,
        }
    }

    pub const fn code(self) -> u16 {
        self as u16
    }
}

impl PkwAccess {
    pub const fn command(self) -> PkwCommand {
        match self {
            PkwAccess::Read => PkwCommand::Read,
            PkwAccess::WriteAndStore { .. } => PkwCommand::WriteAndStore,
            PkwAccess::Write { .. } => PkwCommand::Write,
        }
    }
}

impl PkwRequest {
    pub fn encode(self) -> [U16Be; 4] {
        let value = match self.access {
            PkwAccess::Read => PKW_READ_COUNT,
            PkwAccess::WriteAndStore { value } | PkwAccess::Write { value } => value,
        };
        station_words(
            self.stations,
            self.access.command().code(),
            self.address,
            value,
        )
    }

    pub fn decode(words: &[U16Be; 4]) -> Result<Self, PkwDecodeError> {
        let (stations, code, address, value) = station_fields(words);
        let access = match PkwCommand::from_code(code) {
            Some(PkwCommand::Read) if value == PKW_READ_COUNT => PkwAccess::Read,
            Some(PkwCommand::Read) => return Err(PkwDecodeError::ReadCount(value)),
            Some(PkwCommand::WriteAndStore) => PkwAccess::WriteAndStore { value },
            Some(PkwCommand::Write) => PkwAccess::Write { value },
            None => return Err(PkwDecodeError::UnknownCommand(code)),
        };
        Ok(PkwRequest {
            stations,
            address,
            access,
        })
    }
}

impl PkwResponse {
    pub fn encode(self) -> [U16Be; 4] {
        let (code, value) = match self.reply {
            PkwReply::Value(value) => (PkwCommand::Read.code(), value),
            PkwReply::WrittenAndStored => (PkwCommand::WriteAndStore.code(), 0),
            PkwReply::Written => (PkwCommand::Write.code(), 0),
            PkwReply::Failed { command, error } => (PKW_FAILED + command.code(), error),
        };
        station_words(self.stations, code, self.address, value)
    }

    pub fn decode(words: &[U16Be; 4]) -> Result<Self, PkwDecodeError> {
        let (stations, code, address, value) = station_fields(words);
        let failed = code.checked_sub(PKW_FAILED).and_then(PkwCommand::from_code);
        let reply = match (PkwCommand::from_code(code), failed) {
            (Some(PkwCommand::Read), _) => PkwReply::Value(value),
            (Some(PkwCommand::WriteAndStore), _) => PkwReply::WrittenAndStored,
            (Some(PkwCommand::Write), _) => PkwReply::Written,
            (None, Some(command)) => PkwReply::Failed {
                command,
                error: value,
            },
            (None, None) => return Err(PkwDecodeError::UnknownCommand(code)),
        };
        Ok(PkwResponse {
            stations,
            address,
            reply,
        })
    }
}

fn station_words(stations: Stations, code: u16, address: u16, value: u16) -> [U16Be; 4] {
    let stations = u16::from_be_bytes([stations.target, stations.source]);
    [stations, code, address, value].map(U16Be::new)
}

fn station_fields(words: &[U16Be; 4]) -> (Stations, u16, u16, u16) {
    let [stations, code, address, value] = words.map(U16Be::get);
    let [target, source] = stations.to_be_bytes();
    (Stations { target, source }, code, address, value)
}
