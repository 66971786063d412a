//! The drive behind the card: the parameters the card reads and writes for
//! the master (through the PKW channel and the mapped PZD words), and the
//! fault the card reports in its diagnosis. A drive holds the few
//! parameters its manual gives values for ([`crate::manuals`]); an address
//! it does not hold is refused, as the drive refuses it.

use crate::gsdc_support::Numbering;

/// What the drive lets the card do with a parameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Access {
    ReadWrite,
    ReadOnly,
    WriteOnly,
}

/// One parameter of a drive model, as its manual names it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Named {
    /// As the manual writes it: `F0-08` (read by the layout's numbering into
    /// the address the telegrams carry), or `1000H` (a Modbus address as
    /// the manual writes one, in hex).
    pub name: &'static str,
    /// The value the drive starts with.
    pub value: u16,
    pub access: Access,
    /// Where the manual gives the name and the value; a value no manual
    /// gives says so.
    pub source: &'static str,
}

/// One parameter of the drive, at the address its name reads to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Parameter {
    pub name: &'static str,
    /// The address the card's telegrams carry.
    pub address: u16,
    /// Its current value.
    pub value: u16,
    pub access: Access,
}

/// The address of the parameter the manual names `name`: by the layout's
/// numbering, or a Modbus address written `1000H`.
pub fn address_of(name: &str, numbering: Option<&Numbering>) -> Option<u16> {
    if let Some(address) = numbering.and_then(|n| n.address(name)) {
        return Some(address);
    }
    let hex = name.strip_suffix('H')?;
    if hex.len() != 4 {
        return None;
    }
    u16::from_str_radix(hex, 16).ok()
}

/// Why the drive refuses a read or a write.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Refused {
    /// The drive has no parameter at the address.
    NoSuchParameter,
    /// The parameter can be read but not written.
    ReadOnly,
    /// The parameter can be written but not read (a command).
    WriteOnly,
}

/// A drive as its manual describes it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Model {
    /// The manual the parameters come from.
    pub manual: &'static str,
    /// The parameters with the values the drive starts with, at most
    /// [`CAPACITY`].
    pub parameters: &'static [Named],
    /// The parameter that holds the drive's fault code, when the manual
    /// names one (PI9000: 8000H).
    pub fault_parameter: Option<&'static str>,
    /// The parameters the telegram's control word goes to and its status
    /// word comes from, when the telegram has them (PI9000: 2000H, 3000H).
    pub control_word: Option<&'static str>,
    pub status_word: Option<&'static str>,
    /// How the drive answers its control word in its status word, for a
    /// drive whose control and status words are no parameters of its own
    /// (MV810).
    pub status_of: Option<StatusAnswer>,
    /// What the card reports when it has lost its link to the drive, when
    /// the manual says (MD810: 0x34).
    pub link_lost_code: Option<u16>,
}

/// How a drive answers its control word in its status word, bit by bit, as
/// its manual numbers them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StatusAnswer {
    /// Each control bit that runs the drive, with the status bit that says
    /// it runs; the first one set wins.
    pub runs: &'static [(u8, u8)],
    /// Control bits that stop it whatever else is set.
    pub stops: &'static [u8],
    /// The status bit that says it is stopped.
    pub stopped: u8,
    /// Status bits always set (ready).
    pub always: &'static [u8],
}

impl StatusAnswer {
    /// The status word that answers `control`.
    pub fn answer(&self, control: u16) -> u16 {
        let set = |bit: u8| control & (1 << bit) != 0;
        let mut status = self.always.iter().fold(0, |w, &bit| w | 1 << bit);
        let running = if self.stops.iter().any(|&bit| set(bit)) {
            None
        } else {
            self.runs.iter().find(|&&(c, _)| set(c))
        };
        match running {
            Some(&(_, bit)) => status |= 1 << bit,
            None => status |= 1 << self.stopped,
        }
        status
    }
}

/// The most parameters a drive model holds.
pub const CAPACITY: usize = 16;

/// A drive: its parameters' current values, and its fault.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Drive {
    pub model: &'static Model,
    parameters: [Option<Parameter>; CAPACITY],
    /// The drive's fault code; 0 is no fault.
    fault: u16,
    /// Whether the card has lost its link to the drive.
    link_lost: bool,
}

impl Drive {
    /// The drive as it starts: the model's values, no fault, each parameter
    /// at the address `numbering` (the layout's) reads its name to.
    ///
    /// # Panics
    ///
    /// When the model names a parameter the numbering cannot read: the
    /// model and the description disagree.
    pub fn new(model: &'static Model, numbering: Option<&Numbering>) -> Self {
        assert!(model.parameters.len() <= CAPACITY);
        let mut parameters = [None; CAPACITY];
        for (held, named) in parameters.iter_mut().zip(model.parameters) {
            let address = address_of(named.name, numbering).unwrap_or_else(|| {
                panic!(
                    "{}: {} is no name of the layout's numbering",
                    model.manual, named.name
                )
            });
            *held = Some(Parameter {
                name: named.name,
                address,
                value: named.value,
                access: named.access,
            });
        }
        Drive {
            model,
            parameters,
            fault: 0,
            link_lost: false,
        }
    }

    /// The parameter at `address`, with its current value.
    pub fn parameter(&self, address: u16) -> Option<&Parameter> {
        self.parameters().find(|p| p.address == address)
    }

    /// The parameter the manual names `name`, with its current value.
    pub fn named(&self, name: &str) -> Option<&Parameter> {
        self.parameters().find(|p| p.name == name)
    }

    /// The addresses of the parameters the control word goes to and the
    /// status word comes from, when the model has them.
    pub fn control_word(&self) -> Option<u16> {
        Some(self.named(self.model.control_word?)?.address)
    }

    pub fn status_word(&self) -> Option<u16> {
        Some(self.named(self.model.status_word?)?.address)
    }

    /// Every parameter, in the order of the model.
    pub fn parameters(&self) -> impl Iterator<Item = &Parameter> {
        self.parameters.iter().flatten()
    }

    /// The value of the parameter at `address`, as the drive answers a read.
    pub fn read(&self, address: u16) -> Result<u16, Refused> {
        let parameter = self.parameter(address).ok_or(Refused::NoSuchParameter)?;
        match parameter.access {
            Access::WriteOnly => Err(Refused::WriteOnly),
            Access::ReadWrite | Access::ReadOnly => Ok(parameter.value),
        }
    }

    /// Writes `value` to the parameter at `address`.
    pub fn write(&mut self, address: u16, value: u16) -> Result<(), Refused> {
        let parameter = self
            .parameters
            .iter_mut()
            .flatten()
            .find(|p| p.address == address)
            .ok_or(Refused::NoSuchParameter)?;
        match parameter.access {
            Access::ReadOnly => Err(Refused::ReadOnly),
            Access::ReadWrite | Access::WriteOnly => {
                parameter.value = value;
                Ok(())
            }
        }
    }

    /// The drive reports fault `code` (0 clears it), in its fault
    /// parameter too when it has one.
    pub fn set_fault(&mut self, code: u16) {
        self.fault = code;
        let fault_parameter = self.model.fault_parameter;
        let held = self.parameters.iter_mut().flatten();
        if let Some(parameter) = held.into_iter().find(|p| Some(p.name) == fault_parameter) {
            parameter.value = code;
        }
    }

    /// The card loses its link to the drive (`true`) or gets it back.
    pub fn set_link_lost(&mut self, lost: bool) {
        self.link_lost = lost;
    }

    /// What the card's diagnosis reports of the drive: the code its manual
    /// gives for a lost link while the link is lost, else the drive's fault
    /// code (0: no fault).
    pub fn diagnosis_code(&self) -> u16 {
        match self.model.link_lost_code {
            Some(code) if self.link_lost => code,
            _ => self.fault,
        }
    }
}
