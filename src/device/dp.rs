//! A PROFIBUS-DP slave as its GSD file describes it.

use super::{Allowed, ParameterData, Place, Text};
use crate::gsd::{Arg, Baud, Value};

/// A GSD file's device: its keywords, its parameter telegram, its modules,
/// slots and diagnosis.
#[derive(Debug, Clone, Default, PartialEq)]
#[non_exhaustive]
pub struct DpDevice {
    /// The file's own name, when the reader was given one (a GSD says
    /// nothing of it inside).
    pub file_name: Option<String>,
    /// Every top-level keyword, in file order, but those the parts below
    /// hold (User_Prm_Data and its entries, diagnosis texts); the keywords
    /// of top-level blocks (`Physical_Interface`) with the block's keyword
    /// and number before theirs (`physical_interface(0)/transmission_delay_12m`).
    pub keywords: Vec<Keyword>,
    /// The slave's own part of User_Prm_Data (the modules' parts follow it
    /// in the telegram).
    pub user_prm_data: ParameterData,
    pub modules: Vec<DpModule>,
    /// `SlotDefinition`.
    pub slots: Vec<DpSlot>,
    pub diagnosis: DpDiagnosis,
}

impl DpDevice {
    /// The first top-level keyword of that name, case-insensitively (not
    /// for the baud rate keywords: see [`DpDevice::baud_rates`]).
    pub fn keyword(&self, name: &str) -> Option<&Keyword> {
        let key = crate::gsd::schema::key_of(name);
        self.keywords.iter().find(|k| k.key == key)
    }

    /// `Ident_Number`.
    pub fn ident_number(&self) -> Option<i64> {
        self.keyword("Ident_Number")?.value.as_number()
    }

    /// `Revision`, the device's revision as the file states it.
    pub fn revision(&self) -> Option<&str> {
        self.keyword("Revision")?.value.as_str()
    }

    /// Each supported baud rate with its `MaxTsdr`, in bit times.
    pub fn baud_rates(&self) -> Vec<(Baud, Option<i64>)> {
        let supported = |baud: Baud| {
            self.keywords.iter().any(|k| {
                k.key == "<baud>_supp"
                    && k.arg == Some(Arg::Baud(baud))
                    && k.value.as_number() == Some(1)
            })
        };
        let max_tsdr = |baud: Baud| {
            self.keywords
                .iter()
                .find(|k| k.key == "maxtsdr_<baud>" && k.arg == Some(Arg::Baud(baud)))
                .and_then(|k| k.value.as_number())
        };
        Baud::ALL
            .into_iter()
            .filter(|b| supported(*b))
            .map(|b| (b, max_tsdr(b)))
            .collect()
    }
}

/// `Keyword[(arg)] = value`.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Keyword {
    /// As written (`MaxTsdr_1.5M`).
    pub name: String,
    /// As the keyword schema knows it: lower case, `<baud>` for the baud
    /// rate in its name (`maxtsdr_<baud>`, the rate in `arg`), with the
    /// block before it for a block's keyword.
    pub key: String,
    pub arg: Option<Arg>,
    pub value: Value,
    pub place: Place,
}

/// `Module = "name" config bytes` ... `EndModule`.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct DpModule {
    pub name: String,
    /// The config identifier bytes the master sends in Chk_Cfg.
    pub config: Vec<u8>,
    /// The module reference number (GSD revision 3 and later).
    pub reference: Option<i64>,
    /// Input and output bytes the config bytes declare; `None` when they
    /// cannot be read (a special format cut short).
    pub io: Option<(u32, u32)>,
    /// The module's keywords but its parameter entries (`Info_Text`,
    /// `Preset`, ...), and those of its data areas as
    /// `data_area_beg(n)/area_name`.
    pub keywords: Vec<Keyword>,
    /// The module's part of User_Prm_Data.
    pub user_prm_data: ParameterData,
    /// Its PROFIsafe parameters (`F_Ext_User_Prm_Data_*`).
    pub safety_prm_data: ParameterData,
    pub place: Place,
}

/// `Slot(n) = "name" default allowed` of the `SlotDefinition`.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct DpSlot {
    pub number: i64,
    pub name: Text,
    /// The reference number of the module plugged by default.
    pub default: i64,
    /// The reference numbers of the modules allowed in it.
    pub allowed: Allowed,
    pub place: Place,
}

/// The device-related diagnosis the file gives texts for.
#[derive(Debug, Clone, Default, PartialEq)]
#[non_exhaustive]
pub struct DpDiagnosis {
    /// `Unit_Diag_Bit(n)` and `Unit_Diag_Not_Bit(n)`, with their help texts.
    pub bits: Vec<DiagBit>,
    /// `Unit_Diag_Area`.
    pub areas: Vec<DiagArea>,
    /// `UnitDiagType = n` blocks (GSD revision 5): their areas and bits.
    pub types: Vec<DiagType>,
    /// `Channel_Diag(n)`: the texts of channel error types.
    pub channel: Vec<DiagValue>,
}

/// `Unit_Diag_Bit(n) = "text"`.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct DiagBit {
    pub bit: i64,
    /// `Unit_Diag_Not_Bit`: the text holds while the bit is 0.
    pub when_clear: bool,
    pub text: Text,
    /// `Unit_Diag_Bit_Help`.
    pub help: Option<Text>,
    pub place: Place,
}

/// `Unit_Diag_Area = first-last` with its `Value(n) = "text"` lines.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct DiagArea {
    pub first: i64,
    pub last: i64,
    pub values: Vec<DiagValue>,
    pub place: Place,
}

/// A number and its text: an area's `Value(n)`, a `Channel_Diag(n)`.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct DiagValue {
    pub value: i64,
    pub text: Text,
    pub place: Place,
}

/// `UnitDiagType = n` ... `EndUnitDiagType`.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct DiagType {
    pub id: i64,
    pub bits: Vec<DiagBit>,
    pub areas: Vec<DiagArea>,
    pub place: Place,
}
