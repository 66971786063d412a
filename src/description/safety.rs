//! `[[profinet.safety_modules]]`: a PROFIsafe module, its safety IO data
//! and its F-parameters, with the two description CRCs PI's GSDML checker
//! computed for them (ABB's FENA: "PROFIsafe ABB_PS1" and "ABB_PS2").

use super::{Exactly, Text};
use serde::Deserialize;
use toml::Spanned;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SafetyModule {
    pub name: Spanned<Text>,
    pub info: Option<Spanned<Text>>,
    /// Its ModuleIdentNumber, and its submodule's where not the same.
    pub ident: Spanned<u32>,
    pub submodule_ident: Option<Spanned<u32>>,
    /// The submodule's own name and info (FENA: "F-Parameters"), where not
    /// the module's.
    pub submodule_name: Option<Spanned<Text>>,
    pub submodule_info: Option<Spanned<Text>>,
    /// The hardware catalog's group it is listed under.
    pub category: Option<Spanned<Text>>,
    /// The slots it may go into, `[first, last]`.
    pub slots: Spanned<Exactly<Spanned<u16>, 2>>,
    /// Device to controller and controller to device, each ending with
    /// the PROFIsafe message trailer.
    pub input: Spanned<Vec<Spanned<SafetyItem>>>,
    pub output: Spanned<Vec<Spanned<SafetyItem>>>,
    /// `IOData@F_IO_StructureDescVersion`, written when stated.
    pub io_structure_desc_version: Option<Spanned<u8>>,
    pub f_parameters: Spanned<FParameters>,
    pub crcs: Spanned<DescriptionCrcs>,
    /// The parameter records of its submodule besides the F-parameters
    /// (SEW's MOVI-C: record 8200, its diagnosis alarms), as
    /// `[[profinet.access_point_records]]` gives a record.
    #[serde(default)]
    pub records: Vec<Spanned<super::SubmoduleRecord>>,
}

/// A `DataItem` of safety IO data.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SafetyItem {
    #[serde(rename = "type")]
    pub data_type: Spanned<SafetyDataType>,
    pub name: Spanned<Text>,
    /// `UseAsBits`: the tool shows the item bit by bit; true when `bits`
    /// names some.
    pub use_as_bits: Option<Spanned<bool>>,
    #[serde(default)]
    pub bits: Vec<Spanned<SafetyBit>>,
}

/// A `BitDataItem`: a bit of an item and its text.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SafetyBit {
    pub bit: Spanned<u8>,
    pub name: Spanned<Text>,
}

/// The types PROFIsafe IO data is made of: the add value types, and the
/// message trailer (status or control byte and CRC2) of a 3-byte CRC (4
/// bytes) or of a 4-byte CRC (5 bytes).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
pub enum SafetyDataType {
    Integer8,
    Integer16,
    Integer32,
    Unsigned8,
    Unsigned16,
    Unsigned32,
    Float32,
    #[serde(rename = "F_MessageTrailer4Byte")]
    Trailer4Byte,
    #[serde(rename = "F_MessageTrailer5Byte")]
    Trailer5Byte,
}

/// The F-parameter elements of the schema's `F_ParameterRecordDataT`, in
/// its order.
pub const F_PARAMETER_ELEMENTS: [&str; 13] = [
    "F_Check_iPar",
    "F_SIL",
    "F_CRC_Length",
    "F_CRC_Seed",
    "F_Passivation",
    "F_Block_ID",
    "F_Par_Version",
    "F_Source_Add",
    "F_Dest_Add",
    "F_WD_Time",
    "F_WD_Time_2",
    "F_Par_CRC",
    "F_iPar_CRC",
];

/// The F-parameter elements the schema lets a record leave out; the others
/// it requires.
pub const OPTIONAL_F_PARAMETERS: [&str; 4] =
    ["F_CRC_Seed", "F_Passivation", "F_WD_Time_2", "F_iPar_CRC"];

/// `F_ParameterRecordDataItem`: its record index and the schema's
/// F-parameter elements, by their element names. A required one left out
/// is written without attributes (the schema's defaults), an optional one
/// only when stated.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FParameters {
    pub index: Spanned<u16>,
    #[serde(rename = "F_Check_iPar")]
    pub check_ipar: Option<Spanned<FParameter>>,
    #[serde(rename = "F_SIL")]
    pub sil: Option<Spanned<FParameter>>,
    #[serde(rename = "F_CRC_Length")]
    pub crc_length: Option<Spanned<FParameter>>,
    #[serde(rename = "F_CRC_Seed")]
    pub crc_seed: Option<Spanned<FParameter>>,
    #[serde(rename = "F_Passivation")]
    pub passivation: Option<Spanned<FParameter>>,
    #[serde(rename = "F_Block_ID")]
    pub block_id: Option<Spanned<FParameter>>,
    #[serde(rename = "F_Par_Version")]
    pub par_version: Option<Spanned<FParameter>>,
    #[serde(rename = "F_Source_Add")]
    pub source_add: Option<Spanned<FParameter>>,
    #[serde(rename = "F_Dest_Add")]
    pub dest_add: Option<Spanned<FParameter>>,
    #[serde(rename = "F_WD_Time")]
    pub wd_time: Option<Spanned<FParameter>>,
    #[serde(rename = "F_WD_Time_2")]
    pub wd_time_2: Option<Spanned<FParameter>>,
    #[serde(rename = "F_Par_CRC")]
    pub par_crc: Option<Spanned<FParameter>>,
    #[serde(rename = "F_iPar_CRC")]
    pub ipar_crc: Option<Spanned<FParameter>>,
}

impl FParameters {
    /// Each element the schema has, in its order, with what the
    /// description states of it.
    pub fn elements(&self) -> [(&'static str, Option<&Spanned<FParameter>>); 13] {
        let stated = [
            &self.check_ipar,
            &self.sil,
            &self.crc_length,
            &self.crc_seed,
            &self.passivation,
            &self.block_id,
            &self.par_version,
            &self.source_add,
            &self.dest_add,
            &self.wd_time,
            &self.wd_time_2,
            &self.par_crc,
            &self.ipar_crc,
        ];
        let mut elements = F_PARAMETER_ELEMENTS.map(|name| (name, None));
        for (element, stated) in elements.iter_mut().zip(stated) {
            element.1 = stated.as_ref();
        }
        elements
    }
}

/// An F-parameter element's attributes, each written when stated.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FParameter {
    /// `DefaultValue`: a number, or a token (`"SIL3"`, `"NoCheck"`).
    pub default: Option<Spanned<FValue>>,
    /// `AllowedValues`, as the schema spells them: `"1..65534"`,
    /// `"SIL1 SIL2 SIL3"`.
    pub allowed: Option<Spanned<String>>,
    pub visible: Option<Spanned<bool>>,
    pub changeable: Option<Spanned<bool>>,
}

#[derive(Debug, Clone, PartialEq, Eq, Deserialize)]
#[serde(untagged)]
pub enum FValue {
    Number(u32),
    Token(String),
}

/// The two CRCs the PROFIsafe description carries, which gsdc cannot
/// compute (PI's algorithm is for its members): the values PI's GSDML
/// checker gave, and `of`, gsdc's fingerprint of the F-parameters and IO
/// data they were given for; or placeholders until the checker has run.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DescriptionCrcs {
    /// `F_ParamDescCRC`.
    pub f_param_desc: Spanned<u16>,
    /// `F_IO_StructureDescCRC`.
    pub f_io_structure_desc: Spanned<u32>,
    pub of: Option<Spanned<String>>,
    #[serde(default)]
    pub placeholder: bool,
}
