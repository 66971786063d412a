//! What only PROFIBUS-DP needs: identity numbers, bus parameters, the PPO
//! modules with their config bytes, the parameter telegram and diagnosis.

use super::{
    Allowed, EntryKey, Ident, Ir, Layout, MappingEntry, MappingGroup, MappingKind, MappingSet,
    SetKey, Text, ValueSet,
};
pub use crate::spec::Baud;
use std::fmt;

/// `Revision`, `Hardware_Release` and `Software_Release`: the device's
/// (`[device]`), which lowering requires with a GSD (E004); optional for a
/// GSDML file alone, so `ir::Device` has them as options.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct GsdReleases {
    pub revision: String,
    pub hardware_release: String,
    pub software_release: String,
}

impl GsdReleases {
    /// The device's, when it states all three.
    pub fn of(device: &super::Device) -> Option<GsdReleases> {
        Some(GsdReleases {
            revision: device.revision.clone()?,
            hardware_release: device.hardware_release.clone()?,
            software_release: device.software_release.clone()?,
        })
    }
}

#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Profibus {
    /// The GSD's strings may have Latin-1 characters (`charset =
    /// "latin-1"`), written one byte each; else they are 7-bit ASCII.
    pub latin1: bool,
    pub file_name: String,
    /// The device's revision and releases, which a GSD must state.
    pub releases: GsdReleases,
    pub gsd_revision: u8,
    pub ident_number: u16,
    /// Not assigned by PI: the files say so.
    pub ident_placeholder: bool,
    pub implementation_type: Option<String>,
    /// Keywords the GSD specification does not have, each with its value as
    /// the GSD writes it (a number, or a string in quotes), by name.
    pub vendor_keywords: Vec<(String, String)>,
    pub modules: Vec<DpModule>,
    /// Max_Input_Len and Max_Output_Len: the largest module's bytes, or
    /// what the description states.
    pub max_input_len: u16,
    pub max_output_len: u16,
    /// Max_Data_Len: input and output together, or as stated.
    pub max_data_len: u16,
    /// Max_Module: the most modules a master plugs.
    pub max_module: u8,
    /// Modular_Station: the master picks modules; false for a compact
    /// station of one fixed module.
    pub modular_station: bool,
    /// Which of Max_Module, Max_Input_Len, Max_Output_Len and Max_Data_Len
    /// the GSD writes: all for a modular station, those stated for a
    /// compact one.
    pub limits_written: LimitsWritten,
    /// DP keywords the description states beyond the ones above.
    pub features: Features,
    /// Supported baud rates with MaxTsdr in bit times, slowest first.
    pub baud_rates: Vec<(Baud, u16)>,
    /// Units of 100 us.
    pub min_slave_interval: u16,
    pub slave_family: String,
    pub auto_baud: bool,
    pub freeze_mode: bool,
    pub sync_mode: bool,
    /// Fail_Safe: the slave takes a Data_Exchange without output data (a
    /// master in Clear) as well as one with zeros.
    pub fail_safe: bool,
    pub dpv1: Option<Dpv1>,
    /// Isochronous mode, when the card has it.
    pub isochronous: Option<Isochronous>,
    /// User_Prm_Data in blocks, when stated.
    pub prm_block_structure: Option<BlockStructure>,
    pub user_prm: UserPrm,
    pub diagnosis: Option<Diagnosis>,
    /// `UnitDiagType` blocks, in the description's order.
    pub diagnosis_types: Vec<DiagnosisType>,
    /// `Channel_Diag`: the error types of a channel's diagnosis the card
    /// reports, by error type.
    pub channel_diagnosis: Vec<ChannelDiagnosis>,
    /// Max_Diag_Data_Len: the standard diagnosis and the device's block.
    pub max_diag_data_len: u8,
    /// Bitmap_Device, when the device has a symbol: the bitmap's name
    /// without `.bmp`, beside the GSD (at most 8 characters).
    pub bitmap_device: Option<String>,
    /// Info_Text as STEP 7 and TIA Portal show it: the device's info text,
    /// after the draft notice while the ident number is a placeholder.
    pub info_text: Option<String>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct Dpv1 {
    pub c1_read_write: bool,
    pub c1_max_data_len: u8,
    /// Units of 10 ms.
    pub c1_response_timeout: u16,
    pub status_bytes: [u8; 3],
    pub c2: Option<Dpv1Class2>,
    /// Ident_Maintenance_supp: I&M over the class 2 channel.
    pub ident_maintenance: bool,
    /// DPV1_Data_Types and Check_Cfg_Mode, when stated.
    pub data_types: Option<bool>,
    pub check_cfg_mode: Option<bool>,
    /// C1_Read_Write_required and C2_Read_Write_required, when stated.
    pub c1_read_write_required: Option<bool>,
    pub c2_read_write_required: Option<bool>,
    pub alarms: Option<Alarms>,
}

pub use crate::description::dp::{AlarmKind, BlockStructure};

/// The DPV1 alarms, as the description states them.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct Alarms {
    /// Each kind of [`AlarmKind::ALL`], in its order: supported, required.
    pub supported: [bool; 6],
    pub required: [bool; 6],
    pub type_mode: Option<bool>,
    pub sequence_mode_count: Option<u8>,
    pub extra_alarm_sap: Option<bool>,
}

/// Isochronous mode: the GSD's timing keywords, in the GSD's units.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct Isochronous {
    pub required: Option<bool>,
    pub tbase_dp: u32,
    pub tdp_max: u16,
    pub tdp_min: u16,
    pub tbase_io: u32,
    pub ti_min: u16,
    pub to_min: u16,
    pub t_pll_w_max: u16,
}

/// The DPV1 class 2 channel (MSAC_2).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct Dpv1Class2 {
    pub max_data_len: u8,
    /// Units of 10 ms.
    pub response_timeout: u16,
    pub max_count_channels: u8,
    pub max_initiate_pdu_length: u8,
}

/// A module of the GSD: a PPO type, or a module of the vendor's layout.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct DpModule {
    /// The PPO type it is (1..5), when the description names one.
    pub ppo: Option<u8>,
    pub name: String,
    /// Its module reference number, written after its config bytes.
    pub reference: Option<u16>,
    /// Its `Info_Text`.
    pub info: Option<String>,
    /// Its telegram when it is the PKW channel (or not) and as many PZD
    /// words each way; `None` for data of another shape (words one way
    /// only, bytes, two PKW channels), which only its config bytes and
    /// lengths describe.
    pub layout: Option<Layout>,
    /// The config identifier bytes Chk_Cfg carries for this module.
    pub config: Vec<u8>,
    /// Bytes to the master and from it.
    pub input_len: u16,
    pub output_len: u16,
    /// Its name in generated code: `ppo1`.
    pub ident: Ident,
    /// Its F-parameters and description CRCs, when it is a PROFIsafe module.
    pub safety: Option<DpSafety>,
}

/// A PROFIsafe module's block of F-parameters, which the master sends
/// after the device's User_Prm_Data when the module is plugged
/// (`F_Ext_Module_Prm_Data_Len`, `F_Ext_User_Prm_Data_Const(0)` and
/// `_Ref`), and its two description CRCs.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct DpSafety {
    /// The block's fixed bytes from its byte 0.
    pub constant: Vec<u8>,
    /// Its parameters at their bytes in the block; what each holds is in
    /// `UserPrm::card_params`, its texts among `UserPrm::texts`.
    pub params: Vec<PrmParam>,
    /// Bytes of the block.
    pub len: u16,
    pub crcs: super::safety::DescriptionCrcs,
}

impl DpSafety {
    /// Its parameters as its CRCs describe them; `card_params` is
    /// `UserPrm::card_params`, which holds what each holds.
    pub fn shapes(&self, card_params: &[CardParam]) -> Vec<SafetyPrmShape> {
        self.params
            .iter()
            .filter_map(|param| {
                let PrmValue::Card(index) = param.value else {
                    return None;
                };
                let p = card_params.get(index)?;
                let allowed = match &p.allowed {
                    Allowed::Range { min, max } => format!("{min}-{max}"),
                    Allowed::Choices(set) => {
                        let values: Vec<String> =
                            set.choices.iter().map(|c| c.value.to_string()).collect();
                        values.join(",")
                    }
                };
                Some(SafetyPrmShape {
                    offset: param.offset,
                    data_type: param.data_type.to_string(),
                    default: p.default.into(),
                    allowed,
                    changeable: p.changeable,
                    visible: p.visible,
                })
            })
            .collect()
    }
}

/// A parameter of a PROFIsafe module's block as far as its CRCs describe
/// it, in GSD's words: its byte, type (`Unsigned16`, `BitArea(2-3)`),
/// default, values (`1-254`, or the choices' `0,1`) and flags; no text.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SafetyPrmShape {
    pub offset: u16,
    pub data_type: String,
    pub default: i128,
    pub allowed: String,
    pub changeable: bool,
    pub visible: bool,
}

/// gsdc's fingerprint of what a GSD's PROFIsafe module's two CRCs
/// describe, as far as gsdc can tell: the module's config bytes (its IO
/// data) and its F-parameter block, without any text. A description's
/// CRCs state it as `of`.
pub fn dp_safety_fingerprint(
    config: &[u8],
    (len, constant): (u16, &[u8]),
    params: &[SafetyPrmShape],
) -> String {
    super::Fingerprint::of(&dp_safety_canonical(config, (len, constant), params)).to_string()
}

/// One line for the module, the block's length and fixed bytes, then one
/// per parameter.
fn dp_safety_canonical(
    config: &[u8],
    (len, constant): (u16, &[u8]),
    params: &[SafetyPrmShape],
) -> String {
    let hex = |bytes: &[u8]| -> String {
        let hex: Vec<String> = bytes.iter().map(|b| format!("{b:02X}")).collect();
        hex.join(",")
    };
    let mut text = format!(
        "Module {}\nF_Ext_Module_Prm_Data_Len={len}\nF_Ext_User_Prm_Data_Const(0)={}\n",
        hex(config),
        hex(constant)
    );
    for p in params {
        text.push_str(&format!(
            "Ref({}) {} {} {} Changeable={} Visible={}\n",
            p.offset, p.data_type, p.default, p.allowed, p.changeable, p.visible
        ));
    }
    text
}

/// Which of the length keywords the GSD writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct LimitsWritten {
    pub max_module: bool,
    pub max_input_len: bool,
    pub max_output_len: bool,
    pub max_data_len: bool,
}

/// DP keywords a description may state: `None` is what gsdc writes
/// unstated (0 for Set_Slave_Add_supp, which it always writes; nothing for
/// the others).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct Features {
    pub set_slave_address: Option<bool>,
    pub redundancy: Option<bool>,
    pub repeater_ctrl_sig: Option<u8>,
    pub pins_24v: Option<u8>,
    pub wd_base_1ms: Option<bool>,
    pub publisher: Option<bool>,
    pub modul_offset: Option<u8>,
    pub fail_safe_required: Option<bool>,
}

/// Words one general identifier byte can carry.
pub const MAX_WORDS_PER_IDENTIFIER: u8 = 16;

/// The parameter telegram (User_Prm_Data): constant bytes at offset 0 (the
/// DPV1 status bytes), then one block of parameters per group of mappings
/// (Unsigned16, but a setting's of its type), in telegram order, then a
/// gateway's parameters, with no gaps.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct UserPrm {
    /// The bytes from byte 0 no parameter sets (the DPV1 status bytes).
    pub constant: Vec<u8>,
    /// The card's own parameters, where the description puts them.
    pub card: Vec<PrmParam>,
    pub card_params: Vec<CardParam>,
    pub blocks: Vec<PrmBlock>,
    /// A gateway's parameters, after the blocks: bit areas share a byte.
    pub gateway: Vec<PrmParam>,
    /// The value texts the parameters refer to.
    pub texts: Vec<PrmText>,
    /// Bytes of the whole telegram.
    pub len: u16,
    /// Max_User_Prm_Data_Len when the description states more than `len`.
    pub max_len: Option<u8>,
}

impl UserPrm {
    /// Every parameter: the card's, the mappings', a gateway's.
    pub fn params(&self) -> impl Iterator<Item = &PrmParam> {
        self.card
            .iter()
            .chain(self.blocks.iter().flat_map(|b| &b.params))
            .chain(&self.gateway)
    }

    pub fn block(&self, kind: MappingKind) -> Option<&PrmBlock> {
        self.blocks.iter().find(|b| b.kind == kind)
    }

    /// Where the entries of `group` that User_Prm_Data carries stand among
    /// the group's, in order, when it carries some and not all (a setting a
    /// PROFIBUS master cannot set); `None` when it carries all or none.
    pub fn partial(&self, group: &MappingGroup) -> Option<Vec<usize>> {
        let block = self.block(group.kind)?;
        let carried: Vec<usize> = group
            .entries()
            .enumerate()
            .filter(|(_, (_, e))| {
                block
                    .params
                    .iter()
                    .any(|p| p.value == PrmValue::Entry(e.key))
            })
            .map(|(i, _)| i)
            .collect();
        (carried.len() < group.entry_count()).then_some(carried)
    }

    /// The parameter that holds `value`, where the plan places it; `None`
    /// for a mapping entry the telegram does not carry.
    pub fn placed(&self, value: PrmValue) -> Option<&PrmParam> {
        self.params().find(|p| p.value == value)
    }
}

/// The parameters of one kind of mapping, consecutive from `offset`.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct PrmBlock {
    pub kind: MappingKind,
    pub offset: u16,
    pub params: Vec<PrmParam>,
}

/// An `ExtUserPrmData`: a mapping entry (Unsigned16, or a setting's type)
/// or a gateway parameter, at its offset.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct PrmParam {
    /// Its reference number, from 1.
    pub id: u16,
    pub offset: u16,
    pub value: PrmValue,
    pub data_type: PrmType,
    /// The `PrmText` of its values, when its set has choices.
    pub text: Option<u16>,
}

/// What a parameter holds: its name, default and range are there.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum PrmValue {
    Entry(EntryKey),
    Gateway(super::gateway::ParamKey),
    /// The card's own parameter: its place in `UserPrm::card_params`.
    Card(usize),
}

/// A User_Prm_Data parameter of the card itself (`[[profibus.parameters]]`).
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct CardParam {
    pub name: Text,
    pub default: u16,
    pub allowed: Allowed,
    /// False: the engineering tool lets nobody change it (`Changeable = 0`).
    pub changeable: bool,
    /// False: the tool does not show it (`Visible = 0`).
    pub visible: bool,
}

/// How a parameter is stored, big-endian.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum PrmType {
    Unsigned8,
    /// A setting's Integer8, or a card parameter's Signed8: lowering keeps
    /// its values from 0 to 127, so an unsigned byte reads it alike.
    Signed8,
    Unsigned16,
    /// Bits `first..=last` of the byte at the parameter's offset (GSD
    /// `Bit(n)` or `BitArea(first-last)`); other parameters may hold the
    /// byte's other bits.
    Bits {
        first: u8,
        last: u8,
    },
}

impl PrmType {
    /// Bytes from the parameter's offset.
    pub fn bytes(self) -> u16 {
        match self {
            PrmType::Unsigned16 => 2,
            PrmType::Unsigned8 | PrmType::Signed8 | PrmType::Bits { .. } => 1,
        }
    }

    /// The largest value it holds.
    pub fn max(self) -> u16 {
        match self {
            PrmType::Unsigned8 => 0xFF,
            PrmType::Signed8 => 0x7F,
            PrmType::Unsigned16 => 0xFFFF,
            PrmType::Bits { first, last } => (1 << (last - first + 1)) - 1,
        }
    }

    /// Its value in `prm` at `offset`, high byte first; `prm` holds the
    /// parameter's bytes.
    pub fn read(self, prm: &[u8], offset: usize) -> u16 {
        match self {
            PrmType::Unsigned16 => u16::from_be_bytes([prm[offset], prm[offset + 1]]),
            PrmType::Unsigned8 | PrmType::Signed8 => prm[offset].into(),
            PrmType::Bits { first, .. } => (u16::from(prm[offset]) >> first) & self.max(),
        }
    }

    /// Puts `value` (at most [`Self::max`]) at `offset`, leaving the bits of
    /// other parameters in the byte as they are.
    pub fn write(self, prm: &mut [u8], offset: usize, value: u16) {
        debug_assert!(value <= self.max());
        match self {
            PrmType::Unsigned16 => prm[offset..offset + 2].copy_from_slice(&value.to_be_bytes()),
            // Lowering checked the value fits the type.
            PrmType::Unsigned8 | PrmType::Signed8 => prm[offset] = value as u8,
            PrmType::Bits { first, .. } => {
                let mask = (self.max() << first) as u8;
                prm[offset] = (prm[offset] & !mask) | ((value << first) as u8 & mask);
            }
        }
    }
}

/// As GSD names it: `Unsigned16`, `Bit(3)`, `BitArea(0-3)`.
impl fmt::Display for PrmType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            PrmType::Unsigned8 => f.write_str("Unsigned8"),
            PrmType::Signed8 => f.write_str("Signed8"),
            PrmType::Unsigned16 => f.write_str("Unsigned16"),
            PrmType::Bits { first, last } if first == last => write!(f, "Bit({first})"),
            PrmType::Bits { first, last } => write!(f, "BitArea({first}-{last})"),
        }
    }
}

/// A User_Prm_Data parameter's name, default and values, wherever the plan
/// keeps them.
#[derive(Debug, Clone, Copy)]
#[non_exhaustive]
pub struct PrmFacts<'a> {
    pub name: &'a Text,
    pub default: u16,
    pub holds: PrmHolds<'a>,
}

#[derive(Debug, Clone, Copy)]
#[non_exhaustive]
pub enum PrmHolds<'a> {
    /// A mapping entry: a parameter address or one of the set's choices.
    Mapping {
        set: &'a MappingSet,
        entry: &'a MappingEntry,
    },
    /// A number in a range: a gateway's node count or words.
    Number { min: u16, max: u16 },
    /// A card parameter's range or choices.
    Card(&'a CardParam),
}

impl PrmHolds<'_> {
    pub fn contains(&self, value: u16) -> bool {
        match self {
            PrmHolds::Mapping { set, .. } => set.allowed.contains(value.into()),
            PrmHolds::Number { min, max } => (*min..=*max).contains(&value),
            PrmHolds::Card(p) => p.allowed.contains(value.into()),
        }
    }
}

impl Ir {
    /// What `param` of this description's User_Prm_Data holds.
    pub fn prm_facts(&self, param: &PrmParam) -> PrmFacts<'_> {
        match param.value {
            PrmValue::Entry(key) => {
                let (set, entry) = self.mappings.entry(key);
                PrmFacts {
                    name: &entry.name,
                    default: entry.default,
                    holds: PrmHolds::Mapping { set, entry },
                }
            }
            PrmValue::Gateway(key) => {
                let gateway = self.gateway.as_ref();
                let p = gateway
                    .expect("lowering places gateway parameters only for a gateway")
                    .param(key);
                PrmFacts {
                    name: &p.name,
                    default: p.default.into(),
                    holds: PrmHolds::Number {
                        min: p.min.into(),
                        max: p.max.into(),
                    },
                }
            }
            PrmValue::Card(index) => {
                let p = &self
                    .profibus
                    .as_ref()
                    .expect("lowering places card parameters only in a GSD")
                    .user_prm
                    .card_params[index];
                PrmFacts {
                    name: &p.name,
                    default: p.default,
                    holds: PrmHolds::Card(p),
                }
            }
        }
    }

    /// The parameter telegram a master sends when nothing is changed: the
    /// constant bytes and every parameter's default.
    pub fn default_user_prm(&self, user_prm: &UserPrm) -> Vec<u8> {
        let mut prm = vec![0; usize::from(user_prm.len)];
        prm[..user_prm.constant.len()].copy_from_slice(&user_prm.constant);
        for param in user_prm.params() {
            let default = self.prm_facts(param).default;
            param
                .data_type
                .write(&mut prm, param.offset.into(), default);
        }
        prm
    }
}

/// A `PrmText`: the texts of a set's choices, or of a card parameter's.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct PrmText {
    /// Its reference number, from 1.
    pub id: u16,
    pub of: PrmTextOf,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum PrmTextOf {
    Set(SetKey),
    /// A card parameter, by its place in `UserPrm::card_params`.
    Card(usize),
}

/// Device-related diagnosis: the block length (header byte included) and
/// texts for values of bit areas and for bits, counted from the first byte
/// after the header.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Diagnosis {
    pub length: u8,
    pub areas: Vec<DiagnosisArea>,
    pub bits: Vec<DiagnosisBit>,
    /// What the block reports, as the manual says it.
    pub info: Option<Text>,
    /// What bytes after the header are, by their place in the diagnosis
    /// (the header is byte [`STANDARD_DIAG_BYTES`]), ascending.
    pub bytes: Vec<(u8, Text)>,
}

impl Diagnosis {
    /// What byte `at` of the diagnosis is, when the description says.
    pub fn byte(&self, at: u8) -> Option<&Text> {
        self.bytes.iter().find(|(b, _)| *b == at).map(|(_, t)| t)
    }
}

/// An error type of a channel's diagnosis and the text the engineering tool
/// shows for it.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct ChannelDiagnosis {
    /// The 5-bit error type of the block's third byte.
    pub error_type: u8,
    pub name: Text,
    /// Its constant in the layouts: `dp_channel_diagnosis_drive_ready`.
    pub ident: Ident,
}

/// `Unit_Diag_Bit`: a bit's text, shown while it is set; `clear`:
/// `Unit_Diag_Not_Bit`, shown while it is clear.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct DiagnosisBit {
    pub bit: u16,
    pub text: Text,
    pub clear: bool,
}

impl DiagnosisBit {
    /// Its GSD keyword: `Unit_Diag_Bit`, or `Unit_Diag_Not_Bit` for a text
    /// shown while the bit is clear (`X_` before it in a `UnitDiagType`).
    pub fn keyword(&self) -> &'static str {
        if self.clear {
            "Unit_Diag_Not_Bit"
        } else {
            "Unit_Diag_Bit"
        }
    }
}

#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct DiagnosisArea {
    pub first_bit: u16,
    pub last_bit: u16,
    /// The area's constant in generated code: `bits_8_15`.
    pub ident: Ident,
    pub values: ValueSet,
}

/// `UnitDiagType = id`: the areas and bits of a device-related diagnosis
/// whose type is `id` (GSD revision 5; SINAMICS G120's PROFIsafe faults,
/// type 129).
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct DiagnosisType {
    pub id: u8,
    pub areas: Vec<DiagnosisArea>,
    pub bits: Vec<DiagnosisBit>,
}

/// Bytes of the standard diagnosis before the device-related block.
pub const STANDARD_DIAG_BYTES: u8 = 6;

#[cfg(test)]
mod tests {
    use super::*;

    /// Every parameter is found by what it holds, a mapping entry or a
    /// gateway parameter; an entry the telegram does not carry is not.
    #[test]
    fn parameters_are_found_by_what_they_hold() {
        for (name, text) in [
            (
                "md810dp.toml",
                include_str!("../../descriptions/md810dp.toml"),
            ),
            (
                "md810-gateway.toml",
                include_str!("../../descriptions/md810-gateway.toml"),
            ),
        ] {
            let ir = crate::testing::load(name, text).0.unwrap();
            let user_prm = &ir.profibus.as_ref().unwrap().user_prm;
            assert!(user_prm.params().count() > 0, "{name}");
            for param in user_prm.params() {
                assert_eq!(user_prm.placed(param.value), Some(param), "{name}");
            }
            let setting = EntryKey {
                kind: MappingKind::Setting,
                number: 1,
            };
            assert_eq!(user_prm.placed(PrmValue::Entry(setting)), None, "{name}");
        }
    }

    /// The text the fingerprint is taken of, written out by hand: a
    /// description's `of` depends on it, so changing it makes every stated
    /// `of` stale, a decision to take in sight.
    #[test]
    fn a_dp_safety_modules_fingerprint_is_of_its_bytes_and_parameters_without_texts() {
        let sil = SafetyPrmShape {
            offset: 4,
            data_type: PrmType::Bits { first: 2, last: 3 }.to_string(),
            default: 1,
            allowed: "1".into(),
            changeable: true,
            visible: true,
        };
        let crc = SafetyPrmShape {
            offset: 12,
            data_type: "Unsigned16".into(),
            default: 0x783E,
            allowed: "0-65535".into(),
            changeable: false,
            visible: true,
        };
        let text = dp_safety_canonical(&[0xC6, 0x85], (14, &[0x0E, 0x05]), &[sil, crc]);
        assert_eq!(
            text,
            "Module C6,85\n\
             F_Ext_Module_Prm_Data_Len=14\n\
             F_Ext_User_Prm_Data_Const(0)=0E,05\n\
             Ref(4) BitArea(2-3) 1 1 Changeable=true Visible=true\n\
             Ref(12) Unsigned16 30782 0-65535 Changeable=false Visible=true\n"
        );
    }

    #[test]
    fn parameters_read_and_write_their_own_bits_high_byte_first() {
        let low = PrmType::Bits { first: 0, last: 3 };
        let high = PrmType::Bits { first: 4, last: 7 };
        let mut prm = [0u8; 3];
        low.write(&mut prm, 0, 8);
        high.write(&mut prm, 0, 5);
        low.write(&mut prm, 0, 3);
        PrmType::Unsigned16.write(&mut prm, 1, 0xF00C);
        assert_eq!(prm, [0x53, 0xF0, 0x0C]);
        assert_eq!((low.read(&prm, 0), high.read(&prm, 0)), (3, 5));
        assert_eq!(PrmType::Unsigned8.read(&prm, 2), 0x0C);
        assert_eq!(PrmType::Unsigned16.read(&prm, 1), 0xF00C);
    }
}
