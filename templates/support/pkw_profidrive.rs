// The PROFIdrive parameter channel (gsdc templates/support/pkw_profidrive.rs),
// as the profile's PPO types carry it in cyclic exchange. Sources: MICROMASTER
// 440 OI 10/06 p.157-159 (MM440), MICROMASTER 4 PROFIBUS board p.25-28 (MM4
// board), MASTERDRIVES Compendium 8.2-19 (MASTERDRIVES), SINAMICS G120C OI
// 09/2017 p.186-187; docs/wire-format.md in gsdc's repository quotes them.
// - PKE: bits 15-12 the request id (AK, master to drive) or the response id
//   (drive to master); bit 11 SPM; bits 10-0 the parameter number, PNU 0..2047.
// - IND: bits 15-8 the subindex (MM4 board p.28: the array index in cyclic
//   exchange; the element of a description request). Bits 7-0 are "not
//   defined in PROFIDrive Profile version 2.0" (same page; Siemens drives
//   select a parameter page there): written 0 and not read.
// - PWE1, PWE2: a double word high word first (PWE1 "parameter value, high",
//   MM440); a word in PWE2, PWE1 written 0 and not read; with response 7 the
//   error number in PWE2 (MM4 board p.25, MASTERDRIVES).
// SPM is a toggle bit for parameter change reports (MASTERDRIVES) or "reserved,
// always 0" (MM4 board, SINAMICS): written 0 and not read. The parameter change
// reports (responses 9-12, which MM440 does not support either) are not made,
// and are refused when read.
// Requests 0-9 are the profile's. 10 is reserved, and 11-15 are not the
// profile's ("Request identifiers 11 to 14 are specific to MICROMASTER and not
// defined in the PROFIDrive Profile", MM4 board p.25; "Task IDs 10 to 15 are
// specifically for MASTERDRIVES", 8.2-19): refused, as a drive that keeps to
// the profile refuses them. A drive with Siemens' store-in-EEPROM requests
// needs a channel of its own. Every request but 0 carries IND's subindex,
// whatever its id: newer SINAMICS make 1, 2, 3 the same as 6, 7, 8 (G120C).
// As in the other kinds, nothing of a telegram without a request is read: a
// master may leave old values there.

use super::U16Be;

/// The largest parameter number PKE's bits 10-0 hold.
pub const PNU_MAX: u16 = 0x07FF;

// PKE bit fields.
const ID_SHIFT: u32 = 12;
const PNU_MASK: u16 = PNU_MAX;

/// A parameter number, 0 to [`PNU_MAX`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Pnu(u16);

impl Pnu {
    /// `None` beyond [`PNU_MAX`]: PKE has no room for it.
    pub const fn new(number: u16) -> Option<Self> {
        if number <= PNU_MAX {
            Some(Pnu(number))
        } else {
            None
        }
    }

    pub const fn get(self) -> u16 {
        self.0
    }
}

/// What a request or a response is about: PKE's PNU and IND's subindex (the
/// array element, or the description element; 0 for a simple parameter).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Parameter {
    pub pnu: Pnu,
    pub subindex: u8,
}

/// A parameter request from the master: the profile's request ids 0 to 9.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PkwRequest {
    /// 0: no request.
    None,
    /// 1: request the parameter value.
    Read { parameter: Parameter },
    /// 2: change the parameter value (word).
    WriteWord { parameter: Parameter, value: u16 },
    /// 3: change the parameter value (double word).
    WriteDoubleWord { parameter: Parameter, value: u32 },
    /// 4: request the description element the subindex names.
    ReadDescription { parameter: Parameter },
    /// 5: change the description element the subindex names.
    WriteDescription { parameter: Parameter, value: u32 },
    /// 6: request the value of the array element the subindex names.
    ReadArray { parameter: Parameter },
    /// 7: change the value of an array element (word).
    WriteArrayWord { parameter: Parameter, value: u16 },
    /// 8: change the value of an array element (double word).
    WriteArrayDoubleWord { parameter: Parameter, value: u32 },
    /// 9: request the number of array elements.
    ReadArrayLength { parameter: Parameter },
}

/// The drive's answer: the profile's response ids 0 to 8.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PkwResponse {
    /// 0: no response (to no request).
    None,
    /// 1: the parameter value (word); answers 1 and 2.
    Word { parameter: Parameter, value: u16 },
    /// 2: the parameter value (double word); answers 1 and 3.
    DoubleWord { parameter: Parameter, value: u32 },
    /// 3: the description element; answers 4 and 5.
    Description { parameter: Parameter, value: u32 },
    /// 4: an array element's value (word); answers 6 and 7.
    ArrayWord { parameter: Parameter, value: u16 },
    /// 5: an array element's value (double word); answers 6 and 8.
    ArrayDoubleWord { parameter: Parameter, value: u32 },
    /// 6: the number of array elements, a word in PWE2; answers 9.
    ArrayLength { parameter: Parameter, count: u16 },
    /// 7: the request cannot be executed; the error number is in PWE2.
    Failed {
        parameter: Parameter,
        error: PkwErrorNumber,
    },
    /// 8: no master control (the PKW interface has no authority to change
    /// parameters); PWE is written 0 and not read.
    NoAuthority { parameter: Parameter },
}

/// The error number of response 7, in PWE2. The constants are the numbers
/// the Siemens, Danfoss and TR encoTRive manuals agree on; a drive may send
/// numbers of its own (Siemens' from 101 on are device-specific, MM4 board).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct PkwErrorNumber(pub u16);

impl PkwErrorNumber {
    /// Impermissible parameter number (PNU).
    pub const ILLEGAL_PNU: Self = PkwErrorNumber(0);
    /// The parameter value cannot be changed.
    pub const NOT_CHANGEABLE: Self = PkwErrorNumber(1);
    /// The low or high limit is exceeded.
    pub const LIMIT_EXCEEDED: Self = PkwErrorNumber(2);
    /// Faulty subindex.
    pub const BAD_SUBINDEX: Self = PkwErrorNumber(3);
    /// The parameter is not an array.
    pub const NO_ARRAY: Self = PkwErrorNumber(4);
    /// Incorrect data type (word for double word, or the other way round).
    pub const WRONG_TYPE: Self = PkwErrorNumber(5);
    /// Setting not allowed, only resetting.
    pub const SETTING_NOT_ALLOWED: Self = PkwErrorNumber(6);
    /// The description element cannot be changed.
    pub const DESCRIPTION_NOT_CHANGEABLE: Self = PkwErrorNumber(7);
    /// No master control (no operator control rights).
    pub const NO_MASTER_CONTROL: Self = PkwErrorNumber(11);
    /// Key word missing.
    pub const KEY_WORD_MISSING: Self = PkwErrorNumber(12);
    /// The request cannot be processed in the drive's operating state.
    pub const OPERATING_STATE: Self = PkwErrorNumber(17);
}

/// A PKW telegram that is not one the profile defines.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PkwDecodeError {
    /// Request id 10 (reserved) or 11 to 15 (a vendor's, not the profile's),
    /// for `parameter`: the drive answers 7. Siemens manuals give error 106,
    /// "request not implemented", after requests 5, 10 and 15 (MM4 board,
    /// MASTERDRIVES, SINAMICS G120); the profile's numbers have none for it.
    IllegalRequest { id: u8, parameter: Parameter },
    /// Response id 9 to 12: a parameter change report, which needs SPM's
    /// toggle handshake; not supported.
    ChangeReport { id: u8 },
    /// Response id 13 to 15: not the profile's (13 and 14 reserved, 15 a
    /// vendor's text transfer).
    UnknownResponse { id: u8 },
}

/// The words a request or a response puts in PWE1 and PWE2.
#[derive(Clone, Copy)]
enum Pwe {
    Nothing,
    Word(u16),
    DoubleWord(u32),
}

impl PkwRequest {
    /// PKE bits 15-12.
    pub const fn id(self) -> u8 {
        match self {
            PkwRequest::None => 0,
            PkwRequest::Read { .. } => 1,
            PkwRequest::WriteWord { .. } => 2,
            PkwRequest::WriteDoubleWord { .. } => 3,
            PkwRequest::ReadDescription { .. } => 4,
            PkwRequest::WriteDescription { .. } => 5,
            PkwRequest::ReadArray { .. } => 6,
            PkwRequest::WriteArrayWord { .. } => 7,
            PkwRequest::WriteArrayDoubleWord { .. } => 8,
            PkwRequest::ReadArrayLength { .. } => 9,
        }
    }

    /// The parameter the request is about; `None` without a request.
    pub const fn parameter(self) -> Option<Parameter> {
        match self {
            PkwRequest::None => None,
            PkwRequest::Read { parameter }
            | PkwRequest::WriteWord { parameter, .. }
            | PkwRequest::WriteDoubleWord { parameter, .. }
            | PkwRequest::ReadDescription { parameter }
            | PkwRequest::WriteDescription { parameter, .. }
            | PkwRequest::ReadArray { parameter }
            | PkwRequest::WriteArrayWord { parameter, .. }
            | PkwRequest::WriteArrayDoubleWord { parameter, .. }
            | PkwRequest::ReadArrayLength { parameter } => Some(parameter),
        }
    }

    pub fn encode(self) -> [U16Be; 4] {
        use PkwRequest as R;
        let pwe = match self {
            R::WriteWord { value, .. } => Pwe::Word(value),
            R::WriteArrayWord { value, .. } => Pwe::Word(value),
            R::WriteDoubleWord { value, .. }
            | R::WriteDescription { value, .. }
            | R::WriteArrayDoubleWord { value, .. } => Pwe::DoubleWord(value),
            _ => Pwe::Nothing,
        };
        profidrive_words(self.id(), self.parameter(), pwe)
    }

    pub fn decode(words: &[U16Be; 4]) -> Result<Self, PkwDecodeError> {
        let (id, parameter, [pwe1, pwe2]) = profidrive_fields(words);
        let double = u32::from(pwe1) << 16 | u32::from(pwe2);
        Ok(match id {
            0 => PkwRequest::None,
            1 => PkwRequest::Read { parameter },
            2 => PkwRequest::WriteWord {
                parameter,
                value: pwe2,
            },
            3 => PkwRequest::WriteDoubleWord {
                parameter,
                value: double,
            },
            4 => PkwRequest::ReadDescription { parameter },
            5 => PkwRequest::WriteDescription {
                parameter,
                value: double,
            },
            6 => PkwRequest::ReadArray { parameter },
            7 => PkwRequest::WriteArrayWord {
                parameter,
                value: pwe2,
            },
            8 => PkwRequest::WriteArrayDoubleWord {
                parameter,
                value: double,
            },
            9 => PkwRequest::ReadArrayLength { parameter },
            id => return Err(PkwDecodeError::IllegalRequest { id, parameter }),
        })
    }
}

impl PkwResponse {
    /// PKE bits 15-12.
    pub const fn id(self) -> u8 {
        match self {
            PkwResponse::None => 0,
            PkwResponse::Word { .. } => 1,
            PkwResponse::DoubleWord { .. } => 2,
            PkwResponse::Description { .. } => 3,
            PkwResponse::ArrayWord { .. } => 4,
            PkwResponse::ArrayDoubleWord { .. } => 5,
            PkwResponse::ArrayLength { .. } => 6,
            PkwResponse::Failed { .. } => 7,
            PkwResponse::NoAuthority { .. } => 8,
        }
    }

    /// The parameter the response is about; `None` without one.
    pub const fn parameter(self) -> Option<Parameter> {
        match self {
            PkwResponse::None => None,
            PkwResponse::Word { parameter, .. }
            | PkwResponse::DoubleWord { parameter, .. }
            | PkwResponse::Description { parameter, .. }
            | PkwResponse::ArrayWord { parameter, .. }
            | PkwResponse::ArrayDoubleWord { parameter, .. }
            | PkwResponse::ArrayLength { parameter, .. }
            | PkwResponse::Failed { parameter, .. }
            | PkwResponse::NoAuthority { parameter } => Some(parameter),
        }
    }

    pub fn encode(self) -> [U16Be; 4] {
        use PkwResponse as R;
        let pwe = match self {
            R::Word { value, .. } | R::ArrayWord { value, .. } => Pwe::Word(value),
            R::ArrayLength { count, .. } => Pwe::Word(count),
            R::Failed { error, .. } => Pwe::Word(error.0),
            R::DoubleWord { value, .. }
            | R::Description { value, .. }
            | R::ArrayDoubleWord { value, .. } => Pwe::DoubleWord(value),
            R::None | R::NoAuthority { .. } => Pwe::Nothing,
        };
        profidrive_words(self.id(), self.parameter(), pwe)
    }

    pub fn decode(words: &[U16Be; 4]) -> Result<Self, PkwDecodeError> {
        let (id, parameter, [pwe1, pwe2]) = profidrive_fields(words);
        let double = u32::from(pwe1) << 16 | u32::from(pwe2);
        Ok(match id {
            0 => PkwResponse::None,
            1 => PkwResponse::Word {
                parameter,
                value: pwe2,
            },
            2 => PkwResponse::DoubleWord {
                parameter,
                value: double,
            },
            3 => PkwResponse::Description {
                parameter,
                value: double,
            },
            4 => PkwResponse::ArrayWord {
                parameter,
                value: pwe2,
            },
            5 => PkwResponse::ArrayDoubleWord {
                parameter,
                value: double,
            },
            6 => PkwResponse::ArrayLength {
                parameter,
                count: pwe2,
            },
            7 => PkwResponse::Failed {
                parameter,
                error: PkwErrorNumber(pwe2),
            },
            8 => PkwResponse::NoAuthority { parameter },
            9..=12 => return Err(PkwDecodeError::ChangeReport { id }),
            id => return Err(PkwDecodeError::UnknownResponse { id }),
        })
    }
}

/// PKE, IND, PWE1 and PWE2 of an id, a parameter (none: PNU and IND 0) and
/// the value words.
fn profidrive_words(id: u8, parameter: Option<Parameter>, pwe: Pwe) -> [U16Be; 4] {
    let (pnu, subindex) = match parameter {
        Some(p) => (p.pnu.get(), p.subindex),
        None => (0, 0),
    };
    let [pwe1, pwe2] = match pwe {
        Pwe::Nothing => [0, 0],
        Pwe::Word(value) => [0, value],
        Pwe::DoubleWord(value) => [(value >> 16) as u16, value as u16],
    };
    [
        U16Be::new(u16::from(id) << ID_SHIFT | pnu),
        U16Be::new(u16::from(subindex) << 8),
        U16Be::new(pwe1),
        U16Be::new(pwe2),
    ]
}

/// The id, the parameter and PWE1, PWE2 of a telegram; SPM and IND's low
/// byte are not read.
fn profidrive_fields(words: &[U16Be; 4]) -> (u8, Parameter, [u16; 2]) {
    let [pke, ind, pwe1, pwe2] = words.map(U16Be::get);
    let parameter = Parameter {
        pnu: Pnu(pke & PNU_MASK),
        subindex: (ind >> 8) as u8,
    };
    ((pke >> ID_SHIFT) as u8, parameter, [pwe1, pwe2])
}
