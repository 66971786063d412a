//! The parts of `[profibus]` that say what a vendor's GSD says in its own
//! way: modules of its own layout, User_Prm_Data parameters at their bytes
//! and bits, the fixed bytes under them, diagnosis bits. `gsdc import`
//! writes them for a card whose GSD exists already; a new card may use them
//! too.

use super::safety::DescriptionCrcs;
use super::{BitRange, Choice, Exactly, Text};
use serde::Deserialize;
use toml::Spanned;

/// `[[profibus.modules]]`: a module as the vendor lays it out, its config
/// identifiers derived from what its data is (never typed as bytes).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DpModule {
    /// The GSD's `Module = "name"`, as the vendor writes it.
    pub name: Spanned<String>,
    /// The module reference number (GSD revision 3 and later), written on
    /// the line after the module's.
    pub reference: Option<Spanned<u16>>,
    /// The module's `Info_Text`.
    pub info: Option<Spanned<String>>,
    /// A PPO type's layout and config bytes (`PPO1`: `0xF3,0xF1`).
    pub ppo: Option<Spanned<String>>,
    /// Its config identifiers in order, each what one identifier carries.
    pub data: Option<Spanned<Vec<Spanned<Identifier>>>>,
    /// A PROFIsafe module's F-parameters and description CRCs.
    pub safety: Option<Spanned<DpSafety>>,
}

/// `[profibus.modules.safety]`: a PROFIsafe module's block of
/// F-parameters, which the master sends after the device's User_Prm_Data
/// (`F_Ext_Module_Prm_Data_Len`, `F_Ext_User_Prm_Data_Const` and `_Ref`),
/// and the two description CRCs (`F_ParamDescCRC`,
/// `F_IO_StructureDescCRC`), pinned as a PROFINET safety module's are.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DpSafety {
    /// The block's fixed bytes from its byte 0; parameters may lie over them.
    #[serde(default)]
    pub constant: Vec<Spanned<u8>>,
    /// Its parameters, at their bytes in the block, as
    /// `[[profibus.parameters]]` gives the card's.
    #[serde(default)]
    pub parameters: Vec<Parameter>,
    pub crcs: Spanned<DescriptionCrcs>,
}

/// One config identifier: the PKW channel, words or bytes each way or one
/// way, or an empty place (`{}`, 0x00). `*_out` and `*_in` together, or
/// `vendor`, make the special format (IEC 61158-6-3), whose length bytes
/// say each way on its own.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Identifier {
    /// The PKW channel: 4 consistent words each way (`0xF3`).
    #[serde(default)]
    pub pkw: bool,
    /// Words in and out, as many each way.
    pub words: Option<Spanned<u8>>,
    /// Words from the master (outputs).
    pub words_out: Option<Spanned<u8>>,
    /// Words to the master (inputs).
    pub words_in: Option<Spanned<u8>>,
    pub bytes: Option<Spanned<u8>>,
    pub bytes_out: Option<Spanned<u8>>,
    pub bytes_in: Option<Spanned<u8>>,
    /// Consistent over the whole length (bit 7); true when unsaid.
    pub consistent: Option<Spanned<bool>>,
    /// The manufacturer-specific bytes of a special-format identifier.
    pub vendor: Option<Spanned<Vec<Spanned<u8>>>>,
}

/// `[profibus.user_prm]`: the bytes of User_Prm_Data no parameter sets,
/// and its stated most length.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct UserPrm {
    /// The bytes from byte 0 (the DPV1 status bytes first, for a DPV1
    /// slave): `Ext_User_Prm_Data_Const(0)`. Parameters may lie over them.
    #[serde(default)]
    pub constant: Vec<Spanned<u8>>,
    /// `Max_User_Prm_Data_Len`, when it says more than the parameter
    /// telegram's length.
    pub max_length: Option<Spanned<u8>>,
    /// `Prm_Block_Structure_supp` and `_req`.
    pub block_structure: Option<Spanned<BlockStructure>>,
}

/// `[[profibus.parameters]]`: a User_Prm_Data parameter of the card itself,
/// at the byte (and bits) its GSD puts it: an `ExtUserPrmData` and its
/// `Ext_User_Prm_Data_Ref`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Parameter {
    pub name: Spanned<String>,
    /// Its byte in User_Prm_Data.
    pub offset: Spanned<u8>,
    /// `Unsigned8`, `Unsigned16` (the default) or `Signed8` (0 to 127: the
    /// format says no negative value); not with `bits`.
    #[serde(rename = "type")]
    pub data_type: Option<Spanned<PrmType>>,
    /// Bits of the byte at `offset` (`Bit(n)`: one, `BitArea(first-last)`).
    pub bits: Option<Spanned<BitRange>>,
    pub default: Spanned<i64>,
    /// What it may hold, both ends included; its type's values when unsaid.
    pub range: Option<Spanned<Exactly<Spanned<i64>, 2>>>,
    /// Or one of these, each with the text the engineering tool shows.
    pub choices: Option<Spanned<Vec<Choice>>>,
    /// False: the tool shows the value and lets nobody change it.
    pub changeable: Option<Spanned<bool>>,
    /// False: the tool does not show it.
    pub visible: Option<Spanned<bool>>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
pub enum PrmType {
    Unsigned8,
    Unsigned16,
    Signed8,
}

/// `[[profibus.channel_diagnosis]]`: `Channel_Diag(error_type) = "name"`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ChannelDiagnosis {
    pub error_type: Spanned<u8>,
    pub name: Spanned<Text>,
}

/// `Unit_Diag_Bit(n) = "text"`: a bit of the device-related block with the
/// text the tool shows while it is set; with `clear = true`,
/// `Unit_Diag_Not_Bit(n)`, shown while it is clear.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DiagnosisBit {
    /// Counted from the first byte after the header, as the areas' bits.
    pub bit: Spanned<u16>,
    pub text: Spanned<Text>,
    #[serde(default)]
    pub clear: bool,
}

/// `[profibus.dpv1.alarms]`: the DPV1 alarms the card sends (GSD revision
/// 3 keywords), each written only as stated.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Alarms {
    /// `<Kind>_Alarm_supp = 1` for each.
    #[serde(default)]
    pub supported: Vec<Spanned<AlarmKind>>,
    /// `<Kind>_Alarm_required = 1` for each: the master must enable it.
    #[serde(default)]
    pub required: Vec<Spanned<AlarmKind>>,
    /// `Alarm_Type_Mode_supp`.
    pub type_mode: Option<Spanned<bool>>,
    /// `Alarm_Sequence_Mode_Count`.
    pub sequence_mode_count: Option<Spanned<u8>>,
    /// `Extra_Alarm_SAP_supp`.
    pub extra_alarm_sap: Option<Spanned<bool>>,
}

/// The kinds of DPV1 alarm a GSD names, in the order gsdc writes them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum AlarmKind {
    Diagnostic,
    Process,
    PullPlug,
    Status,
    Update,
    ManufacturerSpecific,
}

impl AlarmKind {
    pub const ALL: [AlarmKind; 6] = [
        AlarmKind::Diagnostic,
        AlarmKind::Process,
        AlarmKind::PullPlug,
        AlarmKind::Status,
        AlarmKind::Update,
        AlarmKind::ManufacturerSpecific,
    ];

    /// Its `_supp` and `_required` keywords.
    pub fn keywords(self) -> (&'static str, &'static str) {
        match self {
            AlarmKind::Diagnostic => ("Diagnostic_Alarm_supp", "Diagnostic_Alarm_required"),
            AlarmKind::Process => ("Process_Alarm_supp", "Process_Alarm_required"),
            AlarmKind::PullPlug => ("Pull_Plug_Alarm_supp", "Pull_Plug_Alarm_required"),
            AlarmKind::Status => ("Status_Alarm_supp", "Status_Alarm_required"),
            AlarmKind::Update => ("Update_Alarm_supp", "Update_Alarm_required"),
            AlarmKind::ManufacturerSpecific => (
                "Manufacturer_Specific_Alarm_supp",
                "Manufacturer_Specific_Alarm_required",
            ),
        }
    }

    /// Its name in the description.
    pub fn name(self) -> &'static str {
        match self {
            AlarmKind::Diagnostic => "diagnostic",
            AlarmKind::Process => "process",
            AlarmKind::PullPlug => "pull_plug",
            AlarmKind::Status => "status",
            AlarmKind::Update => "update",
            AlarmKind::ManufacturerSpecific => "manufacturer_specific",
        }
    }
}

/// `[profibus.isochronous]`: isochronous mode (DP-V2, GSD revision 4):
/// `Isochron_Mode_supp = 1` and the timing keywords, each the number the
/// GSD writes, in the GSD's units.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Isochronous {
    /// `Isochron_Mode_required`: the card runs only isochronously.
    pub required: Option<Spanned<bool>>,
    pub tbase_dp: Spanned<u32>,
    pub tdp_max: Spanned<u16>,
    pub tdp_min: Spanned<u16>,
    pub tbase_io: Spanned<u32>,
    pub ti_min: Spanned<u16>,
    pub to_min: Spanned<u16>,
    pub t_pll_w_max: Spanned<u16>,
}

/// `[profibus.user_prm] block_structure`: User_Prm_Data in blocks (GSD
/// revision 4, `Prm_Block_Structure_supp`), which the master may send or
/// must (`Prm_Block_Structure_req`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BlockStructure {
    Supported,
    Required,
}
