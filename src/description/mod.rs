//! The raw description: the TOML file, one to one.
//!
//! Unknown keys are errors (`deny_unknown_fields`), and every value a
//! diagnostic may point at is `Spanned`. No `flatten` or untagged enums here:
//! they lose spans. Lowering ([`crate::lower`]) turns this into the IR.

pub mod choices;
pub mod dp;
pub mod gateway;
pub mod irt;
pub mod safety;
mod values;
pub use values::digits;

use crate::gsd::Baud;
use serde::Deserialize;
use std::collections::BTreeMap;
use toml::Spanned;

pub use values::{is_language_code, Address, BitRange, Exactly, Record, Text, VendorValue};

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Description {
    /// The manual the description quotes.
    pub manual: Option<Manual>,
    /// Values the manual does not give, each marked as the description's own
    /// choice: key path (`profibus.min_slave_interval`) to the reason.
    #[serde(default)]
    pub choices: BTreeMap<Spanned<String>, Spanned<String>>,
    /// Where each of `choices` leads: found by `load::parse`, not written.
    #[serde(skip)]
    pub choice_targets: choices::ChoiceTargets,
    pub device: Device,
    pub function_codes: Option<FunctionCodes>,
    /// Required, except in a gateway's description, which has none.
    pub telegram: Option<Telegram>,
    #[serde(default)]
    pub mappings: Mappings,
    /// Single drive parameters a master may set at start-up.
    #[serde(default)]
    pub settings: Vec<Setting>,
    pub profibus: Option<Spanned<Profibus>>,
    pub profinet: Option<Spanned<Profinet>>,
    /// A card that carries the data of another bus's nodes.
    pub gateway: Option<Spanned<gateway::Gateway>>,
    /// What the manual tells the user to set on the drive and the card,
    /// group by group as it gives them.
    #[serde(default)]
    pub setup: Vec<SetupGroup>,
    /// The manual's worked examples of telegrams, byte by byte.
    #[serde(default)]
    pub examples: Vec<Example>,
    /// What `gsdc import --draft` found between the imported file and the
    /// draft's build: a description with it is still a draft (W604).
    pub draft: Option<Spanned<Draft>>,
}

/// The round trip of a draft import: each breaking or compatible change it
/// found and each part of the file it left out, as `FILE:LINE: what`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Draft {
    #[serde(default)]
    pub changes: Vec<String>,
    #[serde(default)]
    pub left_out: Vec<String>,
}

/// A group of set-up steps: one table of the manual, or one of the ways
/// it describes (MV810's conventional PN, PN to 485 master, PN to 485
/// slave).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SetupGroup {
    /// The manual's section: `1.2`, `4`, `V-2-1`.
    pub section: Spanned<String>,
    /// The manual's heading of the group, or of the way it describes.
    pub title: Option<Spanned<Text>>,
    /// What the manual says before the steps.
    pub info: Option<Spanned<Text>>,
    pub steps: Vec<SetupStep>,
    /// What the manual says after them.
    pub note: Option<Spanned<Text>>,
}

/// One thing the manual tells the user to set or look at: a drive
/// parameter (or a run of them), or an item that is not one (a DIP
/// switch, an LED, a parameter of the master's configuration).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SetupStep {
    /// A drive parameter, as the manual writes it.
    pub parameter: Option<Spanned<Address>>,
    /// A run of drive parameters, first and last: `["P43.02", "P43.12"]`.
    pub parameters: Option<Spanned<[Spanned<Address>; 2]>>,
    /// What is set when it is not a drive parameter: `"1,2"` (DIP
    /// switches), `"Green"` (an LED), `"PZD3(master->slaver)"`.
    pub item: Option<Spanned<Text>>,
    /// The manual's name of it: `DP 地址`, `Power Indicator`.
    pub name: Option<Spanned<Text>>,
    /// The value to set, as the manual prints it: `"2"`, `"3.0 s"`.
    pub value: Option<Spanned<Text>>,
    /// The factory default the manual gives.
    pub default: Option<Spanned<String>>,
    /// What the manual says of it.
    pub meaning: Option<Spanned<Text>>,
    /// A table of settings and what each means (DIP switch positions).
    #[serde(default)]
    pub values: Vec<SetupValue>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SetupValue {
    pub value: Spanned<Text>,
    pub text: Spanned<Text>,
}

/// A telegram the manual prints, byte by byte.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Example {
    /// The manual's section: `1.4.2`.
    pub section: Spanned<String>,
    /// The module (PPO type or PROFINET module) whose telegram it is; for
    /// the PKW words alone, every module with the PKW channel when absent.
    pub module: Option<Spanned<String>>,
    pub direction: Spanned<ExampleDirection>,
    /// Which words the bytes are: the module's whole telegram, or its PKW
    /// words.
    pub part: Option<Spanned<ExamplePart>>,
    /// As the manual prints them: hex words or bytes, and a name for a word
    /// the manual leaves open (`70F0 0800 0000 errCode`).
    pub bytes: Spanned<String>,
    /// The values a named word stands for: `{ errCode = [1, 2, 3, 4] }`.
    #[serde(default)]
    pub placeholders: BTreeMap<Spanned<String>, Spanned<Vec<Spanned<i64>>>>,
    /// What the manual says the telegram is.
    pub meaning: Spanned<Text>,
    /// The caption of the manual's figure that shows it.
    pub figure: Option<Spanned<Text>>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ExampleDirection {
    /// Master to drive.
    Out,
    /// Drive to master.
    In,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ExamplePart {
    Telegram,
    Pkw,
}

/// The vendor's manual the description's texts and values come from.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Manual {
    /// As the manual names itself.
    pub title: Spanned<String>,
    /// The languages (ISO 639-1) of the manual: texts in these are quoted
    /// from it word for word; texts in others are the description's
    /// translations.
    pub languages: Spanned<Vec<Spanned<String>>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Device {
    pub vendor: Spanned<String>,
    /// Product family, used in GSDML file names (`GSDML-V2.32-<Vendor>-<Family>-…`).
    pub family: Spanned<String>,
    /// Model name: GSD `Model_Name`.
    pub model: Spanned<String>,
    /// GSD `Revision`. It and the releases are required with a
    /// `[profibus]` (the GSD's keywords); a GSDML DAP may have no releases.
    pub revision: Option<Spanned<String>>,
    pub hardware_release: Option<Spanned<String>>,
    pub software_release: Option<Spanned<String>>,
    pub order_number: Option<Spanned<String>>,
    pub name: Spanned<Text>,
    pub info: Option<Spanned<Text>>,
    /// A 70 x 40 PNG of the card, relative to the description: the device
    /// symbol of the GSD and the GSDML.
    pub symbol: Option<Spanned<String>>,
}

/// How the drive names its parameters: `<prefix><group><separator><index>`.
/// MD810 `F0-12`: prefix `F` (0xF0) plus group digit `0` (radix 16) make the
/// high byte 0xF0, index `12` (decimal) the low byte: 0xF00C.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FunctionCodes {
    pub separator: Spanned<String>,
    pub group_radix: Spanned<u32>,
    pub prefixes: BTreeMap<Spanned<String>, Spanned<u8>>,
    /// How prefix base plus group, and the index, make the address;
    /// `bytes` when not given.
    pub address: Option<Spanned<AddressScheme>>,
    /// The digits of every group and index, leading zeros written: required
    /// without a separator (Siemens `P1120`: 2 and 2).
    pub group_digits: Option<Spanned<u8>>,
    pub index_digits: Option<Spanned<u8>>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum AddressScheme {
    /// High byte = prefix base + group, low byte = index: F0-12 = 0xF00C.
    Bytes,
    /// (prefix base + group) × 100 + index (0..99): P10.05 = 1005.
    Decimal,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Telegram {
    pub pkw: Spanned<PkwKind>,
    /// The most PZD words a module carries, each way.
    pub pzd_words: Spanned<u8>,
    pub control_word: Option<Word>,
    pub status_word: Option<Word>,
    /// Whether the card implements the PROFIdrive profile (STW1's ON/OFF1
    /// and the profile's state machine), not only telegrams shaped like its.
    pub profidrive: Option<Spanned<bool>>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum PkwKind {
    /// No parameter channel.
    None,
    /// PROFIdrive-style PKE, IND, PWE (MD810).
    PkeIndPwe,
    /// Station, command, address, value (MV810).
    StationCommandAddressValue,
    /// The PROFIdrive profile's PKE (AK, SPM, PNU), IND, PWE1, PWE2.
    Profidrive,
}

/// A control or status word with named bits.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Word {
    pub name: Spanned<Text>,
    pub bits: Vec<BitField>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BitField {
    pub bit: Spanned<BitRange>,
    pub name: Spanned<Text>,
    #[serde(default)]
    pub values: Vec<Choice>,
}

/// One value of an enumeration, with its text.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Choice {
    pub value: Spanned<i64>,
    pub text: Spanned<Text>,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Mappings {
    /// What each PZD word the master sends means.
    pub pzd_out: Option<Mapping>,
    /// What each PZD word the drive sends means.
    pub pzd_in: Option<Mapping>,
    /// The DPV1 custom record indexes and the parameters behind them.
    pub dpv1_index: Option<Mapping>,
}

/// A set of configurable mappings numbered `first..=last` (PZD words or
/// record indexes), each holding a parameter address or a choice.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Mapping {
    /// `{n}` stands for the word or index number.
    pub name: Spanned<Text>,
    pub first: Spanned<u8>,
    pub last: Spanned<u8>,
    /// The default of every entry; or give `defaults`, one per entry.
    pub default: Option<Spanned<Address>>,
    pub defaults: Option<Spanned<Vec<Spanned<Address>>>>,
    /// Allowed parameter addresses, both ends included.
    pub range: Option<Spanned<Exactly<Spanned<Address>, 2>>>,
    /// Allowed values with their meaning, instead of a range.
    pub choices: Option<Spanned<Vec<Choice>>>,
    /// The drive parameter that holds the mapping of `first`; the next ones follow.
    pub parameter: Option<Spanned<Address>>,
    /// DPV1 indexes only: the bytes of the record each index reads and
    /// writes; the layout refuses records of another length.
    pub record_length: Option<Spanned<u8>>,
    /// Where the drive's parameters of these mappings are set.
    pub set_at: Option<Spanned<SetAt>>,
}

/// Where a mapping's or setting's drive parameters are set.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum SetAt {
    /// At the drive (its keypad, a PKW write, the drive's own tool): no
    /// User_Prm_Data or parameter record carries them, and the master
    /// writes nothing at startup.
    Drive,
    /// By the master at every startup: User_Prm_Data on PROFIBUS, the
    /// module's parameter records on PROFINET.
    Master,
}

/// One drive parameter with its meaning, like MV810's P43.01 (0 standard
/// telegram 1, 1 user-defined telegram).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Setting {
    pub name: Spanned<Text>,
    pub parameter: Option<Spanned<Address>>,
    pub default: Spanned<Address>,
    pub range: Option<Spanned<Exactly<Spanned<Address>, 2>>>,
    pub choices: Option<Spanned<Vec<Choice>>>,
    /// What a setting with a range holds: a plain value (a timeout, a
    /// count; the default) or a drive parameter's address.
    pub holds: Option<Spanned<Holds>>,
    /// PROFINET: the value each kind of module fixes, which the user
    /// cannot change (MV810's P43.01: 1 for user-defined modules, 0 for
    /// standard telegram 1), or its default (`changeable`).
    pub per_module: Option<Spanned<PerModule>>,
    /// Where the drive parameter is set.
    pub set_at: Option<Spanned<SetAt>>,
    /// How User_Prm_Data and the parameter records carry it: `Unsigned16`
    /// (the default), `Unsigned8`, or `Integer8` (0 to 127: the format
    /// says no negative value).
    #[serde(rename = "type")]
    pub data_type: Option<Spanned<SettingType>>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
pub enum SettingType {
    Unsigned8,
    Integer8,
    Unsigned16,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Holds {
    Value,
    Address,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PerModule {
    /// Every module of PKW and PZD words the description maps.
    pub user_defined: Spanned<Address>,
    /// Standard telegram 1, when it is offered.
    pub standard_telegram_1: Option<Spanned<Address>>,
    /// Standard telegram 2, when it is offered.
    pub standard_telegram_2: Option<Spanned<Address>>,
    /// True: each value is that kind of module's default, which the user
    /// may change (ABB FENA's stop mode: 1 in its PPO modules, 0 in its
    /// standard telegrams); false, the default: the module fixes it.
    pub changeable: Option<Spanned<bool>>,
    /// With `[profibus]`, which has no modules that could fix it: whether
    /// the master sets it in User_Prm_Data. Required there.
    pub profibus: Option<Spanned<OnProfibus>>,
}

impl PerModule {
    /// Every value it gives, each kind of module's.
    pub fn values(&self) -> impl Iterator<Item = &Spanned<Address>> {
        std::iter::once(&self.user_defined)
            .chain(&self.standard_telegram_1)
            .chain(&self.standard_telegram_2)
    }
}

/// The characters of a GSD's strings, and so its bytes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Charset {
    /// 7-bit printable ASCII: any tool reads it alike.
    Ascii,
    /// ISO 8859-1, one byte a character: the umlauts and signs of many
    /// vendors' files (`°`, `µ`, `ä`).
    #[serde(rename = "latin-1")]
    Latin1,
}

/// What a setting fixed per PROFINET module is on PROFIBUS.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum OnProfibus {
    /// A parameter of User_Prm_Data, as any setting: the master sets it.
    User,
    /// Not in User_Prm_Data: the master cannot set it; the drive keeps
    /// its own value.
    Absent,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Profibus {
    pub file_name: Spanned<String>,
    /// The characters the GSD's strings may have: 7-bit ASCII (gsdc's
    /// default), or Latin-1 for a card whose shipped GSD has them.
    pub charset: Option<Spanned<Charset>>,
    pub gsd_revision: Option<Spanned<u8>>,
    pub ident_number: Spanned<IdentNumber>,
    pub implementation_type: Option<Spanned<String>>,
    /// Required, except in a gateway's description, whose modules are word blocks.
    pub ppo_types: Option<Spanned<Vec<Spanned<String>>>>,
    /// PZD words of PPO5: 10 in PROFIdrive, 12 on MD810.
    pub ppo5_pzd_words: Option<Spanned<u8>>,
    /// MaxTsdr (bit times) of each supported baud rate, keyed as GSD spells it.
    pub baud_rates: Spanned<BTreeMap<Baud, Spanned<u16>>>,
    /// Units of 100 us.
    pub min_slave_interval: Spanned<u16>,
    /// Main family (1 = drives) and optional sub-families, as `1@Drives@AC`.
    pub slave_family: Spanned<String>,
    #[serde(default)]
    pub auto_baud: bool,
    /// Freeze_Mode_supp, Sync_Mode_supp and Fail_Safe: what the card's DP
    /// stack does; gsdc's default (false, W104) when unsaid.
    pub freeze_mode: Option<Spanned<bool>>,
    pub sync_mode: Option<Spanned<bool>>,
    pub fail_safe: Option<Spanned<bool>>,
    /// Fail_Safe_required: the card takes no master without fail-safe mode.
    pub fail_safe_required: Option<Spanned<bool>>,
    /// Max_Diag_Data_Len, when the firmware's diagnosis may be longer than
    /// the standard bytes and the device block the description states.
    pub max_diag_data_len: Option<Spanned<u8>>,
    /// Set_Slave_Add_supp: a master may set the station address.
    pub set_slave_address: Option<Spanned<bool>>,
    /// Redundancy: the card has redundant transmission.
    pub redundancy: Option<Spanned<bool>>,
    /// Repeater_Ctrl_Sig and 24V_Pins: what the connector's pins carry (0
    /// not connected, 1 RS-485, 2 TTL; 0 none, 1 input, 2 output).
    pub repeater_ctrl_sig: Option<Spanned<u8>>,
    pub pins_24v: Option<Spanned<u8>>,
    /// WD_Base_1ms_supp: the watchdog counts in 1 ms.
    pub wd_base_1ms: Option<Spanned<bool>>,
    /// Publisher_supp: the card publishes its inputs (DXB).
    pub publisher: Option<Spanned<bool>>,
    /// Modular_Station: true (the default) for a card whose modules the
    /// master picks; false for a compact one, of one fixed module.
    pub modular_station: Option<Spanned<bool>>,
    /// Modul_Offset: the slot the first module is numbered by (0 or 1).
    pub modul_offset: Option<Spanned<u8>>,
    /// Max_Module and the most bytes of data, when they say more than the
    /// modules need.
    pub max_module: Option<Spanned<u8>>,
    pub max_input_len: Option<Spanned<u8>>,
    pub max_output_len: Option<Spanned<u8>>,
    pub max_data_len: Option<Spanned<u16>>,
    /// The modules in the vendor's own layout (instead of `ppo_types`).
    pub modules: Option<Spanned<Vec<dp::DpModule>>>,
    /// The fixed bytes of User_Prm_Data and its stated length.
    pub user_prm: Option<Spanned<dp::UserPrm>>,
    /// The card's own User_Prm_Data parameters, at their bytes.
    #[serde(default)]
    pub parameters: Vec<dp::Parameter>,
    pub dpv1: Option<Spanned<Dpv1>>,
    pub isochronous: Option<Spanned<dp::Isochronous>>,
    pub diagnosis: Option<Spanned<Diagnosis>>,
    /// `UnitDiagType` blocks: the areas and bits of a device-related
    /// diagnosis of a type.
    #[serde(default)]
    pub diagnosis_types: Vec<DiagnosisType>,
    /// The error types the card reports in a channel's diagnosis, each with
    /// the text the engineering tool shows (`Channel_Diag`).
    #[serde(default)]
    pub channel_diagnosis: Vec<Spanned<dp::ChannelDiagnosis>>,
    /// Keywords of the vendor's own, which the GSD specification does not
    /// have, written as they are (Siemens' `ETERDelay`).
    #[serde(default)]
    pub vendor_keywords: BTreeMap<Spanned<String>, Spanned<VendorValue>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct IdentNumber {
    pub value: Spanned<u16>,
    /// The number is not assigned by PI: said in the files and warned about.
    #[serde(default)]
    pub placeholder: bool,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Dpv1 {
    #[serde(default)]
    pub c1_read_write: bool,
    pub c1_max_data_len: Option<Spanned<u8>>,
    /// Units of 10 ms.
    pub c1_response_timeout: Option<Spanned<u16>>,
    /// DPV1_Status_1..3, the first three bytes of User_Prm_Data.
    pub status_bytes: Option<Spanned<Exactly<u8, 3>>>,
    /// The class 2 channel (MSAC_2: engineering tools, I&M), when the card has it.
    pub c2: Option<Spanned<Dpv1Class2>>,
    /// I&M functions (Ident_Maintenance_supp), read over the class 2
    /// channel; not written, a warning (PI requires them of new slaves).
    pub ident_maintenance: Option<bool>,
    /// DPV1_Data_Types: the card takes the DPV1 data types in User_Prm_Data.
    pub data_types: Option<Spanned<bool>>,
    /// Check_Cfg_Mode: true when the card checks the configuration less
    /// strictly than byte for byte.
    pub check_cfg_mode: Option<Spanned<bool>>,
    /// C1_Read_Write_required and C2_Read_Write_required: the card needs
    /// the master to use the channel; unwritten when unsaid.
    pub c1_read_write_required: Option<Spanned<bool>>,
    pub c2_read_write_required: Option<Spanned<bool>>,
    pub alarms: Option<Spanned<dp::Alarms>>,
}

/// DPV1 class 2 (MSAC_2): GSD revision 3 keywords.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Dpv1Class2 {
    /// C2_Max_Data_Len: 0 or 48..240.
    pub max_data_len: Spanned<u8>,
    /// C2_Response_Timeout, units of 10 ms.
    pub response_timeout: Spanned<u16>,
    /// C2_Max_Count_Channels: class 2 connections at once, 1..49.
    pub max_count_channels: Spanned<u8>,
    /// Max_Initiate_PDU_Length: 0 or 52..244.
    pub max_initiate_pdu_length: Spanned<u8>,
}

/// Device-related diagnosis: a header byte with the block length, then the
/// device's bytes. Bit 0 is bit 0 of the first byte after the header.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Diagnosis {
    /// Length of the device-related block, header byte included.
    pub length: Spanned<u8>,
    #[serde(default)]
    pub areas: Vec<DiagnosisArea>,
    /// Bits with the text shown while each is set (Unit_Diag_Bit).
    #[serde(default)]
    pub bits: Vec<dp::DiagnosisBit>,
    /// What the block reports, as the manual says it.
    pub info: Option<Spanned<Text>>,
    /// What each byte after the header is, numbered as the diagnosis
    /// (the 6 standard bytes, then the header at byte 6).
    #[serde(default)]
    pub bytes: Vec<DiagnosisByte>,
}

/// `[[profibus.diagnosis_types]]`: `UnitDiagType = id`, the areas and
/// bits of a device-related diagnosis whose type is `id` (GSD revision 5),
/// as `[profibus.diagnosis]` gives its own.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DiagnosisType {
    pub id: Spanned<u8>,
    #[serde(default)]
    pub areas: Vec<DiagnosisArea>,
    #[serde(default)]
    pub bits: Vec<dp::DiagnosisBit>,
}

/// One byte of the device-related block, as the manual names it.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DiagnosisByte {
    /// Counted from the diagnosis' first byte: 7 is the first after the
    /// header, as SFC13's record numbers it.
    pub byte: Spanned<u8>,
    pub text: Spanned<Text>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DiagnosisArea {
    pub bit: Spanned<BitRange>,
    pub values: Vec<Choice>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Profinet {
    pub vendor_id: Spanned<IdentNumber>,
    pub device_id: Spanned<IdentNumber>,
    /// The PROFINET device's name (the DAP's), when it should differ from
    /// `device.name`.
    pub name: Option<Spanned<Text>>,
    /// DeviceIdentity's info text, when it should differ from `device.info`.
    pub info: Option<Spanned<Text>>,
    /// Vendor as the GSDML file name spells it; the device's vendor by default.
    pub file_vendor: Option<Spanned<String>>,
    /// GSDML schema version, "2.32" by default.
    pub gsdml_version: Option<Spanned<String>>,
    /// Every device access point's `PNIO_Version`, where not the file's
    /// GSDML version: the PROFINET specification version the device is
    /// certified against.
    pub pnio_version: Option<Spanned<String>>,
    /// Every device access point's `RequiredSchemaVersion`: the oldest
    /// GSDML version an engineering tool must know to offer it.
    pub required_schema_version: Option<Spanned<String>>,
    /// Every device access point's `ImplementationType`: the hardware or
    /// stack its PROFINET interface is based on, as the vendor names it.
    pub implementation_type: Option<Spanned<String>>,
    /// The family the engineering tool's catalog shows (`ProductFamily`),
    /// where not `[device] family`, the file name's (ABB's "ABB FENA" in
    /// `GSDML-V2.33-ABB-FENA-20170914.xml`).
    pub product_family: Option<Spanned<String>>,
    /// The interface submodule's name, where not gsdc's "PN-IO".
    pub interface_name: Option<Spanned<Text>>,
    /// The file's date: part of its name and of its version. Never the clock.
    pub date: Spanned<toml::value::Datetime>,
    /// DNS_CompatibleName: the default name of station.
    pub dns_name: Spanned<String>,
    /// Ethernet ports of the interface.
    pub ports: Spanned<u8>,
    /// Units of 31.25 us (32 = 1 ms).
    pub min_device_interval: Spanned<u16>,
    /// PZD words of the selectable modules.
    pub pzd_lengths: Spanned<Vec<Spanned<u8>>>,
    /// Which of the selectable modules carry the PKW channel.
    pub module_pkw: Spanned<ModulePkw>,
    /// Also offer standard telegram 1: PROFIdrive's (STW1, NSOLL_A / ZSW1,
    /// NIST_A) when `telegram.profidrive`, else the manual's of 2 PZD words.
    pub standard_telegram_1: Option<Spanned<bool>>,
    /// Also offer PROFIdrive's standard telegram 2 (STW1, NSOLL_B, STW2 /
    /// ZSW1, NIST_B, ZSW2; 32-bit speeds): only with `telegram.profidrive`.
    pub standard_telegram_2: Option<Spanned<bool>>,
    /// Record indexes of the parameter records, with their names.
    #[serde(default)]
    pub records: RecordIndexes,
    /// What the module info texts add to gsdc's description of a module.
    #[serde(default)]
    pub module_info: KindTexts,
    /// The hardware catalog's group of each kind of module, where not
    /// gsdc's.
    #[serde(default)]
    pub categories: KindTexts,
    /// The modules' names where gsdc's would not do: standard telegram 1
    /// of a card that does not implement PROFIdrive.
    #[serde(default)]
    pub module_name: ModuleName,
    /// Single modules' own texts, by their names in generated code.
    #[serde(default)]
    pub module_texts: BTreeMap<Spanned<String>, Spanned<ModuleTexts>>,
    /// What the data items of the modules of PZD words call each word.
    pub pzd_names: Option<Spanned<PzdNames>>,
    /// The texts of the PROFIdrive modules' access point, where not gsdc's.
    pub access_point_texts: Option<Spanned<AccessPointTexts>>,
    /// What the data items of PROFIdrive's standard telegrams call the
    /// profile's words, by their abbreviations (`STW1 = "Output"`), where
    /// not the profile's names.
    #[serde(default)]
    pub profile_word_names: BTreeMap<Spanned<String>, Spanned<Text>>,
    /// Values the settings record of each module ends with, one for each
    /// of its output items.
    pub fail_safe_values: Option<Spanned<FailSafeValues>>,
    /// SendClock factors (units of 31.25 us) the interface accepts.
    pub send_clock: Option<Spanned<Vec<Spanned<u16>>>>,
    /// `TimingProperties@PreferredSendClock`: the one of them the device
    /// prefers.
    pub preferred_send_clock: Option<Spanned<u16>>,
    pub conformance_class: Option<Spanned<ConformanceClass>>,
    /// Isochronous real time (RT_CLASS_3): conformance class C.
    pub irt: Option<Spanned<irt::Irt>>,
    /// Isochronous mode of the modules; needs `irt`.
    pub isochronous: Option<Spanned<irt::Isochronous>>,
    pub netload_class: Option<Spanned<NetloadClass>>,
    /// The I&M records the controller may write (1 to 4).
    pub writeable_im_records: Option<Spanned<Vec<Spanned<u8>>>>,
    /// The I&M records the controller may write to each module's
    /// submodules (1 to 4); none when left out.
    pub module_writeable_im_records: Option<Spanned<Vec<Spanned<u8>>>>,
    /// MRP client on the first two ports.
    pub media_redundancy: Option<Spanned<bool>>,
    /// The labels the interface and its ports carry on the device.
    pub subslot_labels: Option<Spanned<SubslotLabels>>,
    /// What the port submodules are called, one per port of the access
    /// point with the most, where not gsdc's "Port 1", "Port 2"...
    pub port_names: Option<Spanned<Vec<Spanned<Text>>>>,
    /// Every module's ModuleInfo repeats the card's hardware and software
    /// release, the first device access point's.
    pub module_releases: Option<Spanned<bool>>,
    /// Every module's data submodule names the module's category too.
    pub submodule_categories: Option<Spanned<bool>>,
    /// Whether an access point that offers a safety module declares the
    /// `FunctionalSafety` application class: true by default (ABB's FENA
    /// does; SEW's MOVI-C does not).
    pub functional_safety_class: Option<Spanned<bool>>,
    /// What the card's PROFINET stack offers the controllers.
    #[serde(default)]
    pub stack: Stack,
    /// The ident numbers the GSDML and the layouts carry, where they are
    /// not gsdc's numbering (an imported file's own).
    #[serde(default)]
    pub ident_numbers: IdentNumbers,
    /// The modules the first device access point offers, by their names in
    /// generated code; all of them when left out (as a later DAP's
    /// `modules`).
    pub dap_modules: Option<Spanned<Vec<Spanned<String>>>>,
    /// The device access points after the first (`[profinet]`'s): other
    /// hardware or firmware versions of the card, in one file.
    #[serde(default)]
    pub daps: Vec<Spanned<Dap>>,
    /// The channel diagnoses the card reports, with their texts.
    #[serde(default)]
    pub channel_diagnosis: Vec<Spanned<ChannelDiagnosis>>,
    /// The parameter records of every device access point's own submodule.
    #[serde(default)]
    pub access_point_records: Vec<Spanned<SubmoduleRecord>>,
    /// The parameter records of every port.
    #[serde(default)]
    pub port_records: Vec<Spanned<SubmoduleRecord>>,
    /// The card's PROFIenergy, as every device access point's own
    /// submodule declares it.
    pub profienergy: Option<Spanned<ProfiEnergy>>,
    /// The slots that each take one module, its own telegram: `[first,
    /// last]`; slot 1 alone when left out.
    pub module_slots: Option<Spanned<Exactly<Spanned<u16>, 2>>>,
    /// The module without data the card takes in a slot without a data
    /// module.
    pub empty_module: Option<Spanned<EmptyModule>>,
    /// The card's PROFIsafe modules.
    #[serde(default)]
    pub safety_modules: Vec<Spanned<safety::SafetyModule>>,
}

/// `[profinet.empty_module]`: a module without IO data or records (SEW's
/// MOVI-C: "Empty, no module plugged in").
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EmptyModule {
    pub name: Spanned<Text>,
    pub info: Option<Spanned<Text>>,
    /// The slots it may go into, `[first, last]`.
    pub slots: Spanned<Exactly<Spanned<u16>, 2>>,
    /// Its ModuleIdentNumber, and its submodule's where not the same.
    pub ident: Option<Spanned<u32>>,
    pub submodule_ident: Option<Spanned<u32>>,
}

/// `[profinet.profienergy]`: the PROFIenergy profile the card implements,
/// each key the attribute of the schema's `PROFIenergy` element (and the
/// device access point's `PROFIenergyASE_Supported`) it writes.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ProfiEnergy {
    /// `ProfileVersion`, without its V: `"1.2"`.
    pub profile_version: Spanned<String>,
    /// `EntityClass` 1 to 3 and `EntitySubclass` 1 to 2; unwritten when
    /// left out.
    pub entity_class: Option<Spanned<u8>>,
    pub entity_subclass: Option<Spanned<u8>>,
    /// The device access point's `PROFIenergyASE_Supported`.
    pub ase: Option<Spanned<bool>>,
    /// `PESAP_uses_PROFIenergyASE`.
    pub pesap_uses_ase: Option<Spanned<bool>>,
    /// `EnergySavingModeList`: the card's energy saving modes.
    #[serde(default)]
    pub modes: Vec<Spanned<EnergySavingMode>>,
}

/// `[[profinet.profienergy.modes]]`: an `EnergySavingModeItem`, its times
/// in ms.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EnergySavingMode {
    /// `ID`: the mode's number, which the controller and the card use.
    pub id: Spanned<u8>,
    /// `TimeToPause`: the most time the card takes to enter the mode.
    pub time_to_pause: Spanned<u32>,
    /// `RTTO`: the time it takes from the mode back to ready to operate.
    pub regular_time_to_operate: Spanned<u32>,
    /// `TimeMinLengthOfStay`: the least time it stays in the mode.
    pub min_length_of_stay: Spanned<u32>,
}

/// `[[profinet.access_point_records]]`, `[[profinet.port_records]]`: a
/// parameter record of the card's own (a setting of the device or of a
/// port, not a drive parameter), which the controller writes at startup.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SubmoduleRecord {
    pub index: Spanned<u16>,
    pub name: Spanned<Text>,
    /// Its values, each at its byte (and bits); the record is as long as
    /// they reach.
    pub values: Spanned<Vec<Spanned<RecordValue>>>,
}

/// A value of a [`SubmoduleRecord`]: the keys of `[[profibus.parameters]]`,
/// with a text in every language for its name.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RecordValue {
    pub name: Spanned<Text>,
    /// Its first byte in the record.
    pub offset: Spanned<u16>,
    /// `Unsigned8`, `Unsigned16` or `Unsigned32`; not with `bits`.
    #[serde(rename = "type")]
    pub data_type: Option<Spanned<RecordValueType>>,
    /// Bits of the byte at `offset` (`Bit`: one, `BitArea`: several).
    pub bits: Option<Spanned<BitRange>>,
    pub default: Spanned<i64>,
    /// What it may hold, both ends included; its type's values when unsaid.
    pub range: Option<Spanned<Exactly<Spanned<i64>, 2>>>,
    /// Or one of these, each with the text the engineering tool shows.
    pub choices: Option<Spanned<Vec<Choice>>>,
    /// What the engineering tool shows as its help (its ValueItem's).
    pub help: Option<Spanned<Text>>,
    /// False: the tool shows the value and lets nobody change it.
    pub changeable: Option<Spanned<bool>>,
    /// False: the tool does not show it.
    pub visible: Option<Spanned<bool>>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
pub enum RecordValueType {
    Unsigned8,
    Unsigned16,
    Unsigned32,
}

/// `[[profinet.channel_diagnosis]]`: an error type the card reports as
/// channel diagnosis, and what the engineering tool shows for it.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ChannelDiagnosis {
    pub error_type: Spanned<u16>,
    /// A profile's API (PROFIdrive's 0x3A00): a profile's error type.
    pub api: Option<Spanned<u32>>,
    pub name: Spanned<Text>,
    pub help: Option<Spanned<Text>>,
    /// Its extended error types (`ExtChannelDiagList`).
    #[serde(default)]
    pub extended: Vec<Spanned<ExtendedDiagnosis>>,
}

/// `[[profinet.channel_diagnosis.extended]]`: an extended error type the
/// card reports with its channel diagnosis, what the engineering tool
/// shows for it, and how it shows the diagnosis's add value.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ExtendedDiagnosis {
    pub error_type: Spanned<u16>,
    pub name: Spanned<Text>,
    pub help: Option<Spanned<Text>>,
    /// The `DataItem`s of its `ExtChannelAddValue`, in order.
    #[serde(default)]
    pub add_value: Vec<Spanned<AddValueItem>>,
}

/// One `DataItem` of an extended diagnosis's add value.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AddValueItem {
    pub id: Spanned<u8>,
    #[serde(rename = "type")]
    pub data_type: Spanned<AddValueType>,
}

/// The schema's types of an add value's `DataItem`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
pub enum AddValueType {
    Integer8,
    Integer16,
    Integer32,
    Unsigned8,
    Unsigned16,
    Unsigned32,
    Float32,
}

/// `[[profinet.daps]]`: a device access point after the first. What it
/// leaves out is the first's.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Dap {
    pub name: Spanned<Text>,
    pub info: Option<Spanned<Text>>,
    /// Its ModuleIdentNumber, and its own submodule's when not the same.
    pub ident: Spanned<u32>,
    pub submodule_ident: Option<Spanned<u32>>,
    pub order_number: Option<Spanned<String>>,
    pub hardware_release: Option<Spanned<String>>,
    pub software_release: Option<Spanned<String>>,
    pub ports: Option<Spanned<u8>>,
    /// Its `PNIO_Version`, where not the first DAP's (SEW's MOVI-C: V2.33
    /// first, V2.34 later).
    pub pnio_version: Option<Spanned<String>>,
    /// One SubmoduleIdentNumber per port, where not the first DAP's.
    pub port_idents: Option<Spanned<Vec<Spanned<u32>>>>,
    pub media_redundancy: Option<Spanned<bool>>,
    /// What its stack offers where not the first's: each key left out is
    /// the first's.
    #[serde(default)]
    pub stack: Stack,
    /// The modules it offers, by their names in generated code; all of
    /// them when left out.
    pub modules: Option<Spanned<Vec<Spanned<String>>>>,
    /// The parameter records of its own submodule and of its ports, where
    /// not the first's (SEW's MOVI-C's V2.0 moves its ports' records to
    /// its own submodule); `[]` for none.
    pub access_point_records: Option<Vec<Spanned<SubmoduleRecord>>>,
    pub port_records: Option<Vec<Spanned<SubmoduleRecord>>>,
}

/// `[profinet.ident_numbers]`: each key left out keeps gsdc's numbering.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct IdentNumbers {
    /// The device access point's ModuleIdentNumber.
    pub dap: Option<Spanned<u32>>,
    /// Its submodule's; the DAP's number by default.
    pub dap_submodule: Option<Spanned<u32>>,
    pub interface: Option<Spanned<u32>>,
    /// One per port, in port order.
    pub ports: Option<Spanned<Vec<Spanned<u32>>>>,
    /// A PROFIdrive module's access point submodule.
    pub access_point: Option<Spanned<u32>>,
    /// Each module's ModuleIdentNumber by its name in generated code
    /// (`pkw_pzd12`, `pzd6`, `telegram1`).
    #[serde(default)]
    pub modules: BTreeMap<Spanned<String>, Spanned<u32>>,
    /// Its data submodule's, where not the module's.
    #[serde(default)]
    pub submodules: BTreeMap<Spanned<String>, Spanned<u32>>,
}

/// `[profinet.stack]`: what the card's PROFINET stack offers the
/// controllers, each the device access point's or interface's attribute of
/// its name. A key left out keeps the attribute unwritten (its schema
/// default) or gsdc's value.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Stack {
    /// `AddressAssignment`: how the device may get its IP address.
    pub address_assignment: Option<Spanned<Vec<Spanned<AddressAssignment>>>>,
    /// `DeviceAccessSupported`: a supervisor's device access AR.
    pub device_access: Option<Spanned<bool>>,
    /// `NumberOfDeviceAccessAR`.
    pub device_access_ars: Option<Spanned<u8>>,
    /// `NameOfStationNotTransferable`.
    pub name_of_station_not_transferable: Option<Spanned<bool>>,
    /// `SharedDeviceSupported`: several controllers at once, each with its
    /// own submodules.
    pub shared_device: Option<Spanned<bool>>,
    /// The interface's `ApplicationRelations@NumberOfAR`: the IO ARs it
    /// holds at once.
    pub application_relations: Option<Spanned<u16>>,
    /// `IOConfigData`'s limits, where more than the modules need.
    pub max_input_length: Option<Spanned<u16>>,
    pub max_output_length: Option<Spanned<u16>>,
    /// `IOConfigData@MaxDataLength`: the most bytes in and out together.
    pub max_data_length: Option<Spanned<u16>>,
    /// Each port's `MAUTypeItem@AdjustSupported`: the controller may set
    /// the port's MAU type.
    pub mau_type_adjustable: Option<Spanned<bool>>,
    /// The last of the device's slots: `PhysicalSlots` 0 to it.
    pub last_slot: Option<Spanned<u16>>,
    /// `PowerOnToCommReady`: ms from power on to communication ready.
    pub power_on_to_comm_ready: Option<Spanned<u32>>,
    /// The interface's `NetworkComponentDiagnosisSupported`.
    pub network_component_diagnosis: Option<Spanned<bool>>,
    /// Each port's `PortDeactivationSupported`, `CheckMAUTypeSupported` and
    /// `LinkStateDiagnosisCapability`.
    pub port_deactivation: Option<Spanned<bool>>,
    pub check_mau_type: Option<Spanned<bool>>,
    pub link_state_diagnosis: Option<Spanned<LinkStateDiagnosis>>,
    /// Each port's `CheckMAUTypeDifferenceSupported` (GSDML V2.33 and
    /// later).
    pub check_mau_type_difference: Option<Spanned<bool>>,
    /// `AdaptsRealIdentification` (GSDML V2.34 and later).
    pub adapts_real_identification: Option<Spanned<bool>>,
    /// `WebServer`: the scheme, port and path of the card's web server
    /// (GSDML V2.34 and later).
    pub web_server: Option<Spanned<String>>,
}

/// The link changes a port reports as diagnosis, as GSDML names them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
pub enum LinkStateDiagnosis {
    Up,
    Down,
    #[serde(rename = "Up+Down")]
    UpAndDown,
}

/// A way of address assignment, as GSDML names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[allow(clippy::upper_case_acronyms)]
pub enum AddressAssignment {
    DCP,
    DHCP,
    LOCAL,
}

/// `[profinet.subslot_labels]`: the labels the interface and its ports
/// carry on the device (`X1`, `X1 P1`), which engineering tools show with
/// them (GSDML `SubslotList`).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SubslotLabels {
    pub interface: Spanned<Text>,
    /// One per port, in port order.
    pub ports: Spanned<Vec<Spanned<Text>>>,
}

/// A text for each kind of PROFINET module.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct KindTexts {
    /// Every module of PKW and PZD words the description maps.
    pub user_defined: Option<Spanned<Text>>,
    pub standard_telegram_1: Option<Spanned<Text>>,
    pub standard_telegram_2: Option<Spanned<Text>>,
}

/// `[profinet.fail_safe_values]`: after its settings, each module's
/// settings record holds one value for each of the module's output PZD
/// items, of the item's width (ABB FENA's record 1: "Fail safe Control
/// Word", ..., "Fail safe NSOLL_B", the values its stop mode "Use Fail-safe
/// values" applies). The names of each kind of module's values, in
/// telegram order.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FailSafeValues {
    /// Every module of PKW and PZD words: one name per PZD word of the
    /// longest, of which each module's record holds as many as it has.
    pub user_defined: Spanned<Vec<Spanned<Text>>>,
    /// Standard telegram 1's two items, when it is offered.
    pub standard_telegram_1: Option<Spanned<Vec<Spanned<Text>>>>,
    /// Standard telegram 2's three items, when it is offered.
    pub standard_telegram_2: Option<Spanned<Vec<Spanned<Text>>>>,
}

/// `[profinet.module_texts.<module>]`: a module's own texts, each in place
/// of the one gsdc, `module_name` or `module_info` gives it; its data
/// submodule shows the module's name and info unless it has its own.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModuleTexts {
    pub name: Option<Spanned<Text>>,
    pub info: Option<Spanned<Text>>,
    pub submodule_name: Option<Spanned<Text>>,
    pub submodule_info: Option<Spanned<Text>>,
}

/// `[profinet.access_point_texts]`: the name and info text of the access
/// point every PROFIdrive module has in subslot 1, each in place of gsdc's.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AccessPointTexts {
    pub name: Option<Spanned<Text>>,
    pub info: Option<Spanned<Text>>,
}

/// `[profinet.pzd_names]`: the names the GSDML's data items give the PZD
/// words of the modules of PZD words, each way, from the first the
/// telegram does not name (its control or status word).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PzdNames {
    pub output: Option<Spanned<Vec<Spanned<Text>>>>,
    pub input: Option<Spanned<Vec<Spanned<Text>>>>,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModuleName {
    pub standard_telegram_1: Option<Spanned<Text>>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
pub enum ConformanceClass {
    A,
    B,
    C,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
// PROFINET names the classes by Roman numerals.
#[allow(clippy::upper_case_acronyms)]
pub enum NetloadClass {
    I,
    II,
    III,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ModulePkw {
    With,
    Without,
    Both,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RecordIndexes {
    pub pzd_out: Option<Spanned<Record>>,
    pub pzd_in: Option<Spanned<Record>>,
    pub dpv1_index: Option<Spanned<Record>>,
    pub settings: Option<Spanned<Record>>,
}
