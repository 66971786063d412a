//! What the reader makes of a GSD file: settings, modules and the blocks
//! that describe parameters and diagnosis, each with the spans the rules and
//! callers point at.

use std::borrow::Cow;
use std::ops::Range;

/// A value and where it is written.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Spanned<T> {
    pub value: T,
    pub span: Range<usize>,
}

impl<T> Spanned<T> {
    pub fn new(value: T, span: Range<usize>) -> Self {
        Spanned { value, span }
    }
}

pub use crate::spec::Baud;

/// The argument a keyword carries in its name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[non_exhaustive]
pub enum Arg {
    /// `Unit_Diag_Bit(3)`, `Ext_User_Prm_Data_Const(0)`.
    Index(i64),
    /// `MaxTsdr_1.5M`, `12M_supp`.
    Baud(Baud),
}

/// A keyword's value as written after `=`.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum Value {
    /// Nothing after the keyword (`EndModule`, `Data_Area_Beg`).
    None,
    Number(i64),
    /// Two or more comma-separated numbers (`0x00,0x00,0x08`).
    List(Vec<i64>),
    Str(String),
    /// `1@Drives@SINAMICS`: main family and the sub-families after it.
    Family {
        main: i64,
        sub: Vec<String>,
    },
    /// `24-25` (a diagnosis area).
    Range(i64, i64),
    /// Anything else, as written (`1.08`, `AUTO`).
    Raw(String),
}

impl Value {
    pub fn as_number(&self) -> Option<i64> {
        match self {
            Value::Number(n) => Some(*n),
            _ => None,
        }
    }

    pub fn as_str(&self) -> Option<&str> {
        match self {
            Value::Str(s) => Some(s),
            _ => None,
        }
    }

    /// A number list; a single number is a list of one.
    pub fn as_list(&self) -> Option<Vec<i64>> {
        match self {
            Value::Number(n) => Some(vec![*n]),
            Value::List(l) => Some(l.clone()),
            _ => None,
        }
    }
}

/// One `Keyword[(arg)] = value` statement.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Setting {
    /// The keyword as written, case preserved (`MaxTsdr_1.5M`, `24V Pins`;
    /// borrowed from the schema when written as the specification spells it).
    pub name: Cow<'static, str>,
    /// The keyword as the schema knows it: lower case, blanks as `_`, and
    /// the Siemens spelling `Unit_Diag_!Bit` as `unit_diag_not_bit`
    /// (borrowed from the schema when it knows the keyword).
    pub key: Cow<'static, str>,
    pub arg: Option<Arg>,
    pub value: Value,
    /// The whole statement.
    pub span: Range<usize>,
    pub name_span: Range<usize>,
    /// The value, or the end of the keyword when there is none.
    pub value_span: Range<usize>,
}

impl Setting {
    pub fn index(&self) -> Option<i64> {
        match self.arg {
            Some(Arg::Index(i)) => Some(i),
            _ => None,
        }
    }
}

/// Finds settings by keyword, case-insensitively.
pub(crate) fn find<'a>(settings: &'a [Setting], name: &str) -> Option<&'a Setting> {
    let key = crate::gsd::schema::key_of(name);
    settings.iter().find(|s| s.key == key)
}

pub(crate) fn find_all<'a>(
    settings: &'a [Setting],
    name: &str,
) -> impl Iterator<Item = &'a Setting> + 'a {
    let key = crate::gsd::schema::key_of(name);
    settings.iter().filter(move |s| s.key == key)
}

/// `Module = "name" config bytes` ... `EndModule`.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Module {
    pub name: Spanned<String>,
    /// The config identifier bytes (values above 0xFF are reported and left out).
    pub config: Spanned<Vec<u8>>,
    /// The module reference number on the line after the header (or
    /// `Module_Reference = n`).
    pub reference: Option<Spanned<i64>>,
    /// Everything else inside: `Ext_Module_Prm_Data_Len`,
    /// `Ext_User_Prm_Data_Const/Ref`, `Info_Text`, `Preset`, `F_...`.
    pub settings: Vec<Setting>,
    pub data_areas: Vec<Block>,
    /// From `Module` to `EndModule`.
    pub span: Range<usize>,
}

impl Module {
    pub fn get(&self, name: &str) -> Option<&Setting> {
        find(&self.settings, name)
    }

    /// Input and output bytes the config identifiers declare.
    pub fn io_lengths(
        &self,
    ) -> Result<crate::gsd::config::IoLengths, crate::gsd::config::CfgError> {
        crate::gsd::config::io_lengths(&self.config.value)
    }
}

/// An `ExtUserPrmData` data type.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum PrmDataType {
    Unsigned8,
    Unsigned16,
    Unsigned32,
    Signed8,
    Signed16,
    Signed32,
    /// `Bit(n)`: one bit of a byte.
    Bit(u8),
    /// `BitArea(first-last)`: bits first..=last of a byte.
    BitArea(u8, u8),
    /// A type name the reader does not know (reported by the rules).
    Other(String),
}

impl PrmDataType {
    /// Bytes the value takes in the parameter telegram.
    pub fn size(&self) -> usize {
        match self {
            PrmDataType::Unsigned16 | PrmDataType::Signed16 => 2,
            PrmDataType::Unsigned32 | PrmDataType::Signed32 => 4,
            _ => 1,
        }
    }

    /// The bits of each byte it occupies, first byte first (for overlaps).
    pub fn bit_mask(&self) -> u8 {
        match self {
            PrmDataType::Bit(b) if *b < 8 => 1 << b,
            PrmDataType::BitArea(first, last) if first <= last && *last < 8 => {
                let up_to_last = (1u16 << (last + 1)) - 1;
                let below_first = (1u16 << first) - 1;
                (up_to_last & !below_first) as u8
            }
            _ => 0xFF,
        }
    }

    /// The values the type can hold.
    pub fn value_range(&self) -> Option<(i64, i64)> {
        Some(match self {
            PrmDataType::Unsigned8 => (0, 0xFF),
            PrmDataType::Unsigned16 => (0, 0xFFFF),
            PrmDataType::Unsigned32 => (0, 0xFFFF_FFFF),
            PrmDataType::Signed8 => (-0x80, 0x7F),
            PrmDataType::Signed16 => (-0x8000, 0x7FFF),
            PrmDataType::Signed32 => (-0x8000_0000, 0x7FFF_FFFF),
            PrmDataType::Bit(_) => (0, 1),
            PrmDataType::BitArea(first, last) if first <= last && *last < 8 => {
                (0, (1i64 << (last - first + 1)) - 1)
            }
            _ => return None,
        })
    }
}

/// What an `ExtUserPrmData` value may be.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum Allowed {
    /// Nothing written after the default.
    Any,
    /// `min-max`.
    Range(i64, i64),
    /// `a,b,c`.
    Set(Vec<i64>),
}

impl Allowed {
    pub fn contains(&self, value: i64) -> bool {
        match self {
            Allowed::Any => true,
            Allowed::Range(min, max) => (*min..=*max).contains(&value),
            Allowed::Set(values) => values.contains(&value),
        }
    }
}

/// `ExtUserPrmData = id "name"` ... `EndExtUserPrmData`.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct ExtUserPrmData {
    pub id: Spanned<i64>,
    pub name: Spanned<String>,
    /// From the type line (`Unsigned8 0 0-255`, `Bit(3) 1 0-1`); `None`
    /// when the block has no type line.
    pub data_type: Option<Spanned<PrmDataType>>,
    pub default: Option<Spanned<i64>>,
    pub allowed: Spanned<Allowed>,
    pub prm_text_ref: Option<Spanned<i64>>,
    pub changeable: Option<bool>,
    pub visible: Option<bool>,
    /// Other settings inside the block.
    pub settings: Vec<Setting>,
    pub span: Range<usize>,
}

/// `PrmText = id` with `Text(value) = "text"` lines.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct PrmText {
    pub id: Spanned<i64>,
    pub texts: Vec<IndexedText>,
    pub span: Range<usize>,
}

/// `Text(n) = "..."`, `Value(n) = "..."`.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct IndexedText {
    pub index: i64,
    pub text: Spanned<String>,
    pub span: Range<usize>,
}

/// `Unit_Diag_Area = first-last` with `Value(n) = "text"` lines (also the
/// `X_` form inside `UnitDiagType`).
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct UnitDiagArea {
    /// As written: `Unit_Diag_Area` or `X_Unit_Diag_Area`.
    pub keyword: Spanned<String>,
    pub first: i64,
    pub last: i64,
    pub range_span: Range<usize>,
    pub values: Vec<IndexedText>,
    pub span: Range<usize>,
}

/// `UnitDiagType = n` ... `EndUnitDiagType`.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct UnitDiagType {
    pub id: Spanned<i64>,
    pub settings: Vec<Setting>,
    pub areas: Vec<UnitDiagArea>,
    pub span: Range<usize>,
}

/// `Slot(n) = "name" default allowed` inside `SlotDefinition`.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Slot {
    pub number: i64,
    pub name: Spanned<String>,
    /// Module reference number plugged by default.
    pub default: Spanned<i64>,
    /// Module reference numbers allowed in the slot.
    pub allowed: Spanned<Allowed>,
    pub span: Range<usize>,
}

/// A block whose content is plain settings: `Physical_Interface`,
/// `Version_Firmware_Download`, `Jokerblock_Type`, `Data_Area_Beg`.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Block {
    /// The opening keyword as written, with its value.
    pub header: Setting,
    pub settings: Vec<Setting>,
    pub span: Range<usize>,
}

/// A GSD file as read.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct GsdFile {
    /// Span of the `#Profibus_DP` marker.
    pub marker: Option<Range<usize>>,
    /// Top-level settings in file order.
    pub settings: Vec<Setting>,
    pub modules: Vec<Module>,
    pub ext_user_prm_data: Vec<ExtUserPrmData>,
    pub prm_texts: Vec<PrmText>,
    pub unit_diag_areas: Vec<UnitDiagArea>,
    pub unit_diag_types: Vec<UnitDiagType>,
    pub slots: Vec<Slot>,
    /// Other blocks at the top level (`Physical_Interface`, ...).
    pub blocks: Vec<Block>,
}

impl GsdFile {
    /// The first top-level setting of that keyword, case-insensitively
    /// (`get("max_input_len")`, `get("MaxTsdr_1.5M")`).
    pub fn get(&self, name: &str) -> Option<&Setting> {
        find(&self.settings, name)
    }

    /// Every top-level setting of that keyword, in file order
    /// (`Unit_Diag_Bit`, `Ext_User_Prm_Data_Ref`).
    pub fn get_all<'a>(&'a self, name: &str) -> impl Iterator<Item = &'a Setting> + 'a {
        find_all(&self.settings, name)
    }

    /// A top-level keyword's value when it is a number.
    pub fn number(&self, name: &str) -> Option<i64> {
        self.get(name).and_then(|s| s.value.as_number())
    }

    /// A top-level keyword's value when it is a string.
    pub fn string(&self, name: &str) -> Option<&str> {
        self.get(name).and_then(|s| s.value.as_str())
    }

    pub fn ext_user_prm_data(&self, id: i64) -> Option<&ExtUserPrmData> {
        self.ext_user_prm_data.iter().find(|d| d.id.value == id)
    }

    pub fn prm_text(&self, id: i64) -> Option<&PrmText> {
        self.prm_texts.iter().find(|t| t.id.value == id)
    }

    /// `GSD_Revision`, or 0 for files written before the keyword existed.
    pub fn gsd_revision(&self) -> i64 {
        self.number("GSD_Revision").unwrap_or(0)
    }
}
