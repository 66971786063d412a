//! How a changed keyword (GSD) or attribute (GSDML) is judged: one rule
//! per keyword or attribute, saying which way a change breaks projects
//! configured with the old file. docs/diff.md gives the reasons.

use super::{Change, Class, Kind};
use crate::device::{Attribute, AttributeValue, Place, Value};

/// Which way a change of a value breaks old projects.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Judge {
    /// It identifies the device: any change fails every configured station.
    Identity,
    /// Projects were made for the value: any change breaks them.
    Setting,
    /// A text or name the engineering tool shows: cosmetic.
    Text,
    /// A file format or profile version: compatible.
    Version,
    /// A default for new projects (the slot a module is plugged into, the
    /// name of station): old projects keep theirs. Compatible.
    NewProjects,
    /// The name of station a new project proposes: a default for new
    /// projects, and a DNS name, which DNS compares without regard to case
    /// (RFC 4343, 3), as the engineering tool does when it proposes it
    /// (FENA's `FENA` is the name of station `fena`).
    DnsName,
    /// The device supports something (`true`/`1`): dropping it breaks,
    /// adding it is compatible.
    Capability,
    /// The device requires something of the master: requiring it breaks,
    /// no longer requiring it is compatible.
    Required,
    /// A limit the device offers (lengths, counts): lowering it breaks.
    Offer,
    /// What the device needs of the master or bus (response and update
    /// times, diagnosis length): raising it breaks.
    Demand,
    /// A level in the order given, lowest first: lowering it breaks.
    Ordered(&'static [&'static str]),
    /// A set of values a project picks from (slots, send clocks, modes):
    /// a value taken away breaks, one added is compatible.
    Set,
    /// gsdc has no rule: judged breaking, and said so.
    Unknown,
}

/// The rule for one keyword or attribute.
#[derive(Debug, Clone, Copy)]
pub struct Rule {
    pub name: &'static str,
    pub judge: Judge,
    pub kind: Kind,
    /// Its value when absent (the GSDML schema's default; 0 for GSD's
    /// `_supp` keywords).
    pub default: Option<&'static str>,
    /// What a change means for old projects, when the judge's general
    /// sentence is not enough.
    pub why: Option<&'static str>,
}

const fn rule(name: &'static str, judge: Judge, kind: Kind) -> Rule {
    Rule {
        name,
        judge,
        kind,
        default: None,
        why: None,
    }
}

impl Rule {
    const fn or(mut self, default: &'static str) -> Rule {
        self.default = Some(default);
        self
    }

    const fn because(mut self, why: &'static str) -> Rule {
        self.why = Some(why);
        self
    }
}

const UNKNOWN: Rule = rule("", Judge::Unknown, Kind::Feature);

use Judge::*;
use Kind::{Diagnosis as Diag, Feature, File, Identity as Id, IoData, Module, Text as Txt, Timing};

const MAX_TSDR: &str = "the master's slot time was computed from the old MaxTsdr: a device that answers later than it is a missed answer, retries, then a lost station on a bus with tight timing";
const IDENT: &str = "a project configured with the old file identifies the device by it: every such station fails at startup";
const CONFIG_CHECK: &str = "changes what the device checks in the configuration a project configured with the old file sends";

/// The GSD keywords, by the keyword schema's key (lower case, `<baud>` for
/// the baud rate). A block's keywords are judged by their own key.
pub const GSD: &[Rule] = &[
    rule("gsd_revision", Version, File),
    rule("vendor_name", Text, Id),
    rule("model_name", Text, Id),
    rule("revision", Text, Id),
    rule("revision_number", Text, Id),
    rule("hardware_release", Text, Id),
    rule("software_release", Text, Id),
    rule("ordernumber", Text, Id),
    rule("implementation_type", Text, Id),
    rule("family_name", Text, Id),
    rule("info_text", Text, Txt),
    rule("bitmap_device", Text, Txt),
    rule("bitmap_diag", Text, Txt),
    rule("bitmap_sf", Text, Txt),
    rule("slave_family", Text, Id),
    rule("version_name", Text, Id),
    rule("channel_diag_help", Text, Diag),
    rule("ident_number", Identity, Id).because(
        "the master sends the old ident number in Set_Prm: every station configured with the old file fails its parameterisation",
    ),
    rule("protocol_ident", Identity, Id),
    rule("station_type", Identity, Id),
    rule("fms_supp", Capability, Feature).or("0"),
    rule("<baud>_supp", Capability, Timing).or("0").because(
        "a bus configured with the old file may run at this rate",
    ),
    rule("maxtsdr_<baud>", Demand, Timing).because(MAX_TSDR),
    rule("min_slave_intervall", Demand, Timing).because(
        "the master was configured to poll the device as often as the old interval allows",
    ),
    rule("redundancy", Capability, Feature).or("0"),
    rule("repeater_ctrl_sig", Text, Feature),
    rule("24v_pins", Text, Feature),
    rule("physical_interface", Setting, Feature),
    rule("transmission_delay_<baud>", Demand, Timing),
    rule("reaction_delay_<baud>", Demand, Timing),
    rule("freeze_mode_supp", Capability, Feature).or("0"),
    rule("sync_mode_supp", Capability, Feature).or("0"),
    rule("auto_baud_supp", Capability, Timing).or("0"),
    rule("set_slave_add_supp", Capability, Feature).or("0"),
    rule("fail_safe", Capability, Feature).or("0"),
    rule("fail_safe_required", Required, Feature).or("0"),
    rule("diag_update_delay", Demand, Timing),
    rule("ident_maintenance_supp", Capability, Feature).or("0"),
    rule("time_sync_supp", Capability, Feature).or("0"),
    rule("max_diag_data_len", Demand, Diag).because(
        "the master sized its diagnosis buffer by the old length: a longer diagnosis is refused",
    ),
    rule("modular_station", Setting, Module).or("0"),
    rule("max_module", Offer, Module),
    rule("max_input_len", Offer, IoData),
    rule("max_output_len", Offer, IoData),
    rule("max_data_len", Offer, IoData),
    rule("modul_offset", Setting, Module),
    rule("fixpresetmodules", Setting, Module),
    rule("max_user_prm_data_len", Offer, Kind::Parameter),
    rule("prm_block_structure_supp", Capability, Kind::Parameter).or("0"),
    rule("prm_block_structure_req", Required, Kind::Parameter).or("0"),
    rule("x_ext_module_prm_data_len", Setting, Kind::Parameter),
    rule("preset", Setting, Module),
    rule("jokerblock_type", Setting, Module),
    rule("data_area_beg", Text, IoData),
    rule("area_name", Text, IoData),
    rule("related_cfg_identifier", Setting, IoData),
    rule("io_direction", Setting, IoData),
    rule("length", Setting, IoData),
    rule("consistency", Setting, IoData),
    rule("publisher_allowed", Capability, IoData).or("0"),
    rule("dp_master_allowed", Capability, IoData).or("0"),
    rule("data_type", Setting, IoData),
    rule("f_paramdesccrc", Setting, Kind::Parameter),
    rule("f_io_structuredesccrc", Setting, IoData),
    rule("dpv1_slave", Setting, Feature).or("0").because(
        "a master configured with the old file parameterises the device as a DP-V0 or DP-V1 slave by it",
    ),
    rule("c1_read_write_supp", Capability, Feature).or("0"),
    rule("c1_read_write_required", Required, Feature).or("0"),
    rule("c1_max_data_len", Offer, Feature),
    rule("c1_response_timeout", Demand, Timing),
    rule("c2_read_write_supp", Capability, Feature).or("0"),
    rule("c2_read_write_required", Required, Feature).or("0"),
    rule("c2_max_data_len", Offer, Feature),
    rule("c2_response_timeout", Demand, Timing),
    rule("c2_max_count_channels", Offer, Feature),
    rule("max_initiate_pdu_length", Offer, Feature),
    rule("dpv1_data_types", Setting, Feature),
    rule("wd_base_1ms_supp", Capability, Timing).or("0"),
    rule("check_cfg_mode", Setting, Module).because(CONFIG_CHECK),
    rule("diagnostic_alarm_supp", Capability, Diag).or("0"),
    rule("process_alarm_supp", Capability, Diag).or("0"),
    rule("pull_plug_alarm_supp", Capability, Diag).or("0"),
    rule("status_alarm_supp", Capability, Diag).or("0"),
    rule("update_alarm_supp", Capability, Diag).or("0"),
    rule("manufacturer_specific_alarm_supp", Capability, Diag).or("0"),
    rule("extra_alarm_sap_supp", Capability, Diag).or("0"),
    rule("alarm_sequence_mode_count", Offer, Diag),
    rule("alarm_type_mode_supp", Capability, Diag).or("0"),
    rule("diagnostic_alarm_required", Required, Diag).or("0"),
    rule("process_alarm_required", Required, Diag).or("0"),
    rule("pull_plug_alarm_required", Required, Diag).or("0"),
    rule("status_alarm_required", Required, Diag).or("0"),
    rule("update_alarm_required", Required, Diag).or("0"),
    rule("manufacturer_specific_alarm_required", Required, Diag).or("0"),
    rule("isochron_mode_supp", Capability, Timing).or("0"),
    rule("isochron_mode_required", Required, Timing).or("0"),
    rule("tbase_dp", Setting, Timing),
    rule("tdp_max", Offer, Timing),
    rule("tdp_min", Demand, Timing),
    rule("tbase_io", Setting, Timing),
    rule("ti_min", Demand, Timing),
    rule("to_min", Demand, Timing),
    rule("t_pll_w_max", Offer, Timing),
    rule("publisher_supp", Capability, Feature).or("0"),
    rule("subscriber_supp", Capability, Feature).or("0"),
    rule("slave_redundancy_supp", Capability, Feature).or("0"),
    rule("prmcmd_supp", Capability, Feature).or("0"),
    rule("slave_max_switch_over_time", Demand, Timing),
    rule("firmware_download_supp", Capability, Feature).or("0"),
    rule("version_firmware_download", Text, Feature),
];

const CONSISTENCY: &[&str] = &["Item consistency", "All items consistency"];
const CONFORMANCE: &[&str] = &["A", "B", "C", "D"];
const NETLOAD: &[&str] = &["I", "II", "III"];

/// The GSDML attributes, by name, or by `Element@Attribute` where the name
/// alone would be ambiguous. Attributes of elements inside a typed part
/// are found by the last element and the attribute.
pub const GSDML: &[Rule] = &[
    // Texts, names, pictures.
    rule("TextId", Text, Txt),
    rule("CategoryRef", Text, Txt),
    rule("SubCategory1Ref", Text, Txt),
    rule("GraphicItemTarget", Text, Txt),
    rule("GraphicItemRef@Type", Text, Txt),
    rule("OrderNumber@Value", Text, Id),
    rule("HardwareRelease@Value", Text, Id),
    rule("SoftwareRelease@Value", Text, Id),
    rule("VendorName@Value", Text, Id),
    rule("Family@MainFamily", Text, Id),
    rule("Family@ProductFamily", Text, Id),
    rule("ImplementationType", Text, Id),
    rule("SlotItem@SlotNumber", Text, Txt),
    rule("SubslotItem@SubslotNumber", Text, Txt),
    rule("Visible", Text, Txt),
    rule("WebServer", Text, Feature),
    rule("LinkStateDiagnosisCapability", Text, Diag),
    rule("LogBookEntryItem@Status", Text, Diag),
    rule("ErrorCode2Item@ErrorCode2", Text, Diag),
    rule("MaintenanceAlarmState", Text, Diag),
    // Versions.
    rule("PNIO_Version", Version, File),
    rule("RequiredSchemaVersion", Version, File),
    rule("ProfileVersion", Version, File),
    // Defaults for new projects.
    rule("DNS_CompatibleName", DnsName, Id).because(
        "the name of station a new project proposes; old projects keep the name they gave the device",
    ),
    rule("UsedInSlots", NewProjects, Module),
    rule("UsedInSubslots", NewProjects, Module),
    rule("IsDefaultRingport", NewProjects, Feature).or("false"),
    rule("PreferredSendClock", NewProjects, Timing),
    // Settings a project was made for.
    rule("API", Setting, Module).or("0"),
    rule("FixedInSlots", Setting, Module),
    rule("FixedInSubslots", Setting, Module),
    rule("ObjectUUID_LocalIndex", Setting, Id),
    rule("IOPS_Length", Setting, IoData).or("1"),
    rule("IOCS_Length", Setting, IoData).or("1"),
    rule("Subordinate", Setting, IoData).or("false"),
    rule("TransferSequence", Setting, Kind::Record).or("0"),
    rule("AdaptsRealIdentification", Setting, Id).or("false"),
    rule("T_IO_Base", Setting, Timing),
    rule("T_DC_Base", Setting, Timing),
    rule("UsesStaticARP_CacheEntries", Setting, Feature).or("false"),
    rule("DefaultValue", Setting, Kind::Parameter),
    rule("F_ParamDescCRC", Setting, Kind::Parameter),
    rule("F_IO_StructureDescCRC", Setting, IoData),
    rule("F_IO_StructureDescVersion", Setting, IoData).or("1"),
    rule("F_ParameterRecordDataItem@Index", Setting, Kind::Record),
    rule("ChangeableWithBump", Capability, Kind::Parameter).or("false"),
    rule("DataItem@DataType", Setting, Diag),
    rule("DataItem@Id", Setting, Diag),
    rule("ApplicationLengthIncludesIOxS", Setting, IoData).or("false"),
    rule("PROFIenergy@EntityClass", Setting, Feature),
    rule("PROFIenergy@EntitySubclass", Setting, Feature),
    rule("EnergySavingModeItem@ID", Setting, Feature),
    rule("MeasurementValue@ID", Setting, Feature),
    rule("RemoteApplicationTimeout", Setting, Timing).or("300"),
    rule("Consistency", Ordered(CONSISTENCY), IoData).or("Item consistency").because(
        "a PLC program written for the old file may rely on all items being consistent",
    ),
    rule("ConformanceClass", Ordered(CONFORMANCE), Feature),
    rule("NetloadClass", Ordered(NETLOAD), Feature),
    // Sets a project picks from.
    rule("PhysicalSlots", Set, Module),
    rule("AllowedInSlots", Set, Module),
    rule("AllowedInSubslots", Set, Module),
    rule("PhysicalSubslots", Set, Module),
    rule("SendClock", Set, Timing).or("32"),
    rule("ReductionRatio", Set, Timing),
    rule("ReductionRatioPow2", Set, Timing),
    rule("ReductionRatioNonPow2", Set, Timing),
    rule("StartupMode", Set, Feature).or("Legacy"),
    rule("SupportedRT_Classes", Set, Timing),
    rule("SupportedRT_Class", Set, Timing).or("Class1"),
    rule("IsochroneModeInRT_Classes", Set, Timing),
    rule("SupportedProtocols", Set, Feature),
    rule("SupportedMibs", Set, Feature),
    rule("SupportedSyncProtocols", Set, Timing),
    rule("ResetToFactoryModes", Set, Feature),
    rule("AddressAssignment", Set, Feature).or("DCP"),
    rule("MAUTypes", Set, Feature),
    rule("MAUTypeItem@Value", Set, Feature),
    rule("MAUTypeItem@Extension", Set, Feature),
    rule("MAUType", Set, Feature).or("100BASETXFD"),
    rule("ForwardingMode", Set, Timing),
    rule("SupportedRole", Set, Feature),
    rule("Writeable_IM_Records", Set, Feature),
    rule("ApplicationClass", Set, Feature),
    rule("AllowedValues", Set, Kind::Parameter),
    rule("FiberOpticTypes", Set, Feature),
    rule("SupportedDelayMeasurements", Set, Timing),
    rule("SupportedServiceProtocols", Set, Feature),
    // Limits the device offers.
    rule("NumberOfDeviceAccessAR", Offer, Feature),
    rule("NumberOfAR", Offer, Feature).or("1"),
    rule("NumberOfImplicitAR", Offer, Feature).or("1"),
    rule("NumberOfAdditionalInputCR", Offer, Feature).or("0"),
    rule("NumberOfAdditionalOutputCR", Offer, Feature).or("0"),
    rule("NumberOfAdditionalMulticastProviderCR", Offer, Feature).or("0"),
    rule("NumberOfMulticastConsumerCR", Offer, Feature).or("0"),
    rule("MaxInputLength", Offer, IoData),
    rule("MaxOutputLength", Offer, IoData),
    rule("MaxDataLength", Offer, IoData),
    rule("MaxSupportedRecordSize", Offer, Kind::Record).or("4068"),
    rule("Max_iParameterSize", Offer, Kind::Parameter).or("0"),
    rule("MaxApplicationInputLength", Offer, IoData),
    rule("MaxApplicationOutputLength", Offer, IoData),
    rule("MaxApplicationDataLength", Offer, IoData),
    rule("T_DC_Max", Offer, Timing),
    rule("T_PLL_MAX", Offer, Timing).or("1000"),
    rule("MaxReductionRatioIsochroneMode", Offer, Timing),
    rule("MaxMRP_Instances", Offer, Feature),
    rule("MaxNumberIR_FrameData", Offer, Timing),
    rule("MaxFrameStartTime", Offer, Timing).or("1600"),
    rule("MaxRangeIR_FrameID", Offer, Timing).or("1024"),
    // What the device needs of the controller or network.
    rule("MinDeviceInterval", Demand, Timing).because(
        "a project configured with the old file may exchange data faster than the device now can",
    ),
    rule("PowerOnToCommReady", Demand, Timing).or("0"),
    rule("MaxPortTxDelay", Demand, Timing),
    rule("MaxPortRxDelay", Demand, Timing),
    rule("T_DC_Min", Demand, Timing),
    rule("T_IO_InputMin", Demand, Timing),
    rule("T_IO_OutputMin", Demand, Timing),
    rule("MaxLocalJitter", Demand, Timing),
    rule("MaxBridgeDelay", Demand, Timing),
    rule("MinRTC3_Gap", Demand, Timing).or("1120"),
    rule("MinNRT_Gap", Demand, Timing).or("960"),
    rule("MaxSwitchOverTime", Demand, Timing),
    rule("RTTO", Demand, Timing),
    rule("TimeToPause", Demand, Timing),
    rule("TimeMinLengthOfStay", Demand, Timing),
    rule("MaxRetentionTime", Demand, Timing),
    // What the device supports.
    rule("DeviceAccessSupported", Capability, Feature).or("false"),
    rule("MultipleWriteSupported", Capability, Feature).or("false"),
    rule("CheckDeviceID_Allowed", Capability, Feature).or("false"),
    rule("LLDP_NoD_Supported", Capability, Feature).or("false"),
    rule("SharedDeviceSupported", Capability, Feature).or("false"),
    rule("SharedInputSupported", Capability, Feature).or("false"),
    rule("DCP_HelloSupported", Capability, Feature).or("false"),
    rule("ParameterizationSpeedupSupported", Capability, Feature).or("false"),
    rule("NetworkComponentDiagnosisSupported", Capability, Diag).or("false"),
    rule("DelayMeasurementSupported", Capability, Timing).or("false"),
    rule("IsochroneModeSupported", Capability, Timing).or("false"),
    rule("PortDeactivationSupported", Capability, Feature).or("false"),
    rule("SupportsRingportConfig", Capability, Feature).or("false"),
    rule("SupportsMRP_InterconnPortConfig", Capability, Feature).or("false"),
    rule("CheckMAUTypeSupported", Capability, Feature).or("false"),
    rule("CheckMAUTypeDifferenceSupported", Capability, Feature).or("false"),
    rule("DCP_BoundarySupported", Capability, Feature).or("false"),
    rule("PTP_BoundarySupported", Capability, Feature).or("false"),
    rule("MulticastBoundarySupported", Capability, Feature).or("false"),
    rule("IM5_Supported", Capability, Feature).or("false"),
    rule("MayIssueProcessAlarm", Capability, Diag),
    rule("PullModuleAlarmSupported", Capability, Diag).or("false"),
    rule("AdjustSupported", Capability, Feature).or("false"),
    rule("PrmBeginPrmEndSequenceSupported", Capability, Feature).or("false"),
    rule("MRPD_Supported", Capability, Feature).or("false"),
    rule("MRT_Supported", Capability, Feature).or("false"),
    rule("PDEV_CombinedObjectSupported", Capability, Feature).or("false"),
    rule("AutoConfigurationSupported", Capability, Feature).or("false"),
    rule("IO_SupervisorSupported", Capability, Feature).or("false"),
    rule("PROFIenergyASE_Supported", Capability, Feature).or("false"),
    rule("PESAP_uses_PROFIenergyASE", Capability, Feature).or("false"),
    rule("PROFIsafeSupported", Capability, Feature).or("false"),
    rule("PROFIsafePIR_Supported", Capability, Feature).or("false"),
    rule("CIR_Supported", Capability, Feature).or("false"),
    rule("ExtensionSupported", Capability, Feature).or("false"),
    rule("RT_InputOnBackupAR_Supported", Capability, Feature).or("false"),
    rule("DataInvalidOnBackupAR_Supported", Capability, Feature).or("false"),
    rule("PowerBudgetControlSupported", Capability, Feature).or("false"),
    rule("Changeable", Capability, Kind::Parameter).or("true"),
    // What the device requires.
    rule("IsochroneModeRequired", Required, Timing).or("false"),
    rule("NameOfStationNotTransferable", Required, Feature).or("false"),
    rule("ParameterizationDisallowed", Required, Kind::Parameter).or("false"),
    rule("IOXS_Required", Required, IoData).or("true"),
];

/// The rule for a GSD keyword key (`maxtsdr_<baud>`, a block's
/// `physical_interface(0)/transmission_delay_<baud>`).
pub fn gsd_rule(key: &str) -> &'static Rule {
    let own = key.rsplit('/').next().unwrap_or(key);
    let own = own.split('(').next().unwrap_or(own);
    GSD.iter().find(|r| r.name == own).unwrap_or(&UNKNOWN)
}

/// The rule for a GSDML attribute as the model names it
/// (`ApplicationRelations/TimingProperties@SendClock`, `PhysicalSlots`).
pub fn gsdml_rule(name: &str) -> &'static Rule {
    let (path, attribute) = name.rsplit_once('@').unwrap_or(("", name));
    let element = path.rsplit('/').next().unwrap_or("");
    let qualified = format!("{element}@{attribute}");
    GSDML
        .iter()
        .find(|r| !element.is_empty() && r.name == qualified)
        .or_else(|| GSDML.iter().find(|r| r.name == attribute))
        .unwrap_or(&UNKNOWN)
}

/// The change of one value under its rule, or `None` when it did not
/// change (a value absent on one side is its default). `subject` names
/// the value.
pub fn judge(
    rule: &Rule,
    subject: String,
    old: Option<&str>,
    new: Option<&str>,
    at: (Option<&Place>, Option<&Place>),
) -> Option<Change> {
    let old_value = old.or(rule.default);
    let new_value = new.or(rule.default);
    if same(old_value, new_value, rule.judge) {
        return None;
    }
    let (class, why) = verdict(rule.judge, old_value, new_value);
    let change = match (old, new) {
        (Some(o), Some(n)) => format!("\"{o}\" → \"{n}\""),
        (None, Some(n)) => format!("\"{n}\" added"),
        (Some(o), None) => format!("\"{o}\" removed"),
        (None, None) => return None,
    };
    let mut change = Change::new(class, rule.kind, subject, change)
        .why(rule.why.map_or(why, str::to_string))
        .at(at.0, at.1);
    change.judged = rule.judge != Unknown;
    Some(change)
}

/// Equal as the judge reads them: sets as sets, numbers as numbers, DNS
/// names without regard to case. An empty set says what its absence says
/// where the rule has no default (FENA-01's `ApplicationClass=""`: no
/// application class).
pub(super) fn same(old: Option<&str>, new: Option<&str>, judge: Judge) -> bool {
    match (old, new) {
        (Some(a), Some(b)) if judge == Set => {
            let (gone, added) = set_difference(a, b);
            gone.is_empty() && added.is_empty()
        }
        (Some(set), None) | (None, Some(set)) if judge == Set => set.trim().is_empty(),
        (Some(a), Some(b)) if judge == DnsName => a.eq_ignore_ascii_case(b),
        (Some(a), Some(b)) if matches!(judge, Capability | Required) => {
            a == b || boolean(a).is_some_and(|x| boolean(b) == Some(x))
        }
        (Some(a), Some(b)) => a == b || number(a).zip(number(b)).is_some_and(|(x, y)| x == y),
        (a, b) => a == b,
    }
}

/// The class of a change of a value from `old` to `new` (either possibly
/// absent with no default), and why.
fn verdict(judge: Judge, old: Option<&str>, new: Option<&str>) -> (Class, String) {
    let setting = || {
        (
            Class::Breaking,
            "projects configured with the old file were made for the old value".to_string(),
        )
    };
    match judge {
        Identity => (Class::Breaking, IDENT.to_string()),
        Setting => setting(),
        Text => (
            Class::Cosmetic,
            "a text or name the engineering tool shows; nothing a device or master acts on".into(),
        ),
        Version => (
            Class::Compatible,
            "old projects are not affected; an engineering tool older than the new version may not install the file".into(),
        ),
        NewProjects | DnsName => (
            Class::Compatible,
            "a default for new projects; old projects keep the value they were configured with".into(),
        ),
        Capability | Required => match (old.and_then(boolean), new.and_then(boolean)) {
            (Some(was), Some(is)) => {
                let breaks = match judge {
                    Capability => was && !is,
                    _ => !was && is,
                };
                match (breaks, judge) {
                    (true, Capability) => (
                        Class::Breaking,
                        "a project configured with the old file may use what the device no longer supports".into(),
                    ),
                    (true, _) => (
                        Class::Breaking,
                        "projects configured with the old file do not provide what the device now requires".into(),
                    ),
                    (false, Capability) => (
                        Class::Compatible,
                        "old projects do not use what the device now supports".into(),
                    ),
                    (false, _) => (
                        Class::Compatible,
                        "old projects provide what the device no longer requires".into(),
                    ),
                }
            }
            _ => setting(),
        },
        Offer | Demand | Ordered(_) => {
            let order = match judge {
                Ordered(levels) => old.zip(new).and_then(|(a, b)| {
                    let level = |v: &str| levels.iter().position(|l| *l == v);
                    Some(level(a)?.cmp(&level(b)?))
                }),
                _ => old
                    .and_then(number)
                    .zip(new.and_then(number))
                    .and_then(|(a, b)| a.partial_cmp(&b)),
            };
            let lowered = match order {
                Some(std::cmp::Ordering::Greater) => true,
                Some(_) => false,
                None => return setting(),
            };
            match (judge == Demand, lowered) {
                (false, true) => (
                    Class::Breaking,
                    "a project configured with the old file may use more than the new limit".into(),
                ),
                (false, false) => (
                    Class::Compatible,
                    "old projects stay within the new limit".into(),
                ),
                (true, false) => (
                    Class::Breaking,
                    "a project configured with the old file may allow the device less than it now needs".into(),
                ),
                (true, true) => (
                    Class::Compatible,
                    "old projects allow the device more than it now needs".into(),
                ),
            }
        }
        Set => {
            let (gone, _) = set_difference(old.unwrap_or(""), new.unwrap_or(""));
            match gone.is_empty() {
                true => (Class::Compatible, "every value old projects may use is still offered".into()),
                false => (
                    Class::Breaking,
                    format!(
                        "a project configured with the old file may use {}, which the new file no longer offers",
                        gone.join(", ")
                    ),
                ),
            }
        }
        Unknown => (
            Class::Breaking,
            "gsdc has no rule for this and does not know what it means: read it before you release".into(),
        ),
    }
}

fn boolean(text: &str) -> Option<bool> {
    match text.trim() {
        "true" | "1" => Some(true),
        "false" | "0" => Some(false),
        _ => None,
    }
}

fn number(text: &str) -> Option<Value> {
    match Value::parse(text) {
        Value::Str(_) => None,
        number => Some(number),
    }
}

/// The values of a set-like attribute (`0..4 7`, `SNMP;LLDP`,
/// `Up+Down`): what `old` has that `new` lacks, and the reverse.
fn set_difference(old: &str, new: &str) -> (Vec<String>, Vec<String>) {
    let (old_numbers, old_words) = set_items(old);
    let (new_numbers, new_words) = set_items(new);
    let show = crate::gsdml::values::show_ranges;
    let mut gone: Vec<String> = old_words.difference(&new_words).cloned().collect();
    let mut added: Vec<String> = new_words.difference(&old_words).cloned().collect();
    let missing = new_numbers.missing_from(&old_numbers);
    if !missing.is_empty() {
        gone.push(show(&missing));
    }
    let more = old_numbers.missing_from(&new_numbers);
    if !more.is_empty() {
        added.push(show(&more));
    }
    (gone, added)
}

fn set_items(
    text: &str,
) -> (
    crate::gsdml::values::ValueList,
    std::collections::BTreeSet<String>,
) {
    let mut ranges = Vec::new();
    let mut words = std::collections::BTreeSet::new();
    for item in text
        .split(|c: char| c.is_whitespace() || c == ';')
        .filter(|s| !s.is_empty())
    {
        match crate::gsdml::values::ValueList::parse(item) {
            Some(list) => ranges.extend_from_slice(list.ranges()),
            None => {
                words.insert(item.to_string());
            }
        }
    }
    (crate::gsdml::values::ValueList::from_ranges(ranges), words)
}

/// The attributes of two versions of one element, each judged by its rule.
pub fn attributes(subject: &str, old: &[Attribute], new: &[Attribute], out: &mut super::Changes) {
    if old == new {
        return;
    }
    let pairing = super::pairing::pair(old, new, |a| &*a.name);
    let text = |a: &Attribute| match &a.value {
        AttributeValue::Plain(s) => s.to_string(),
        AttributeValue::Text(t) => t.primary.to_string(),
    };
    for (a, b) in pairing.both {
        if let (AttributeValue::Text(x), AttributeValue::Text(y)) = (&a.value, &b.value) {
            out.text(
                &format!("{subject} {}", shown(&a.name)),
                Some(x),
                Some(y),
                (Some(&a.place), Some(&b.place)),
            );
            continue;
        }
        let rule = gsdml_rule(&a.name);
        let subject = format!("{subject} {}", shown(&a.name));
        out.0.extend(judge(
            rule,
            subject,
            Some(&text(a)),
            Some(&text(b)),
            (Some(&a.place), Some(&b.place)),
        ));
    }
    for a in pairing.gone {
        let rule = gsdml_rule(&a.name);
        let subject = format!("{subject} {}", shown(&a.name));
        out.0.extend(judge(
            rule,
            subject,
            Some(&text(a)),
            None,
            (Some(&a.place), None),
        ));
    }
    for b in pairing.added {
        let rule = gsdml_rule(&b.name);
        let subject = format!("{subject} {}", shown(&b.name));
        out.0.extend(judge(
            rule,
            subject,
            None,
            Some(&text(b)),
            (None, Some(&b.place)),
        ));
    }
}

/// An attribute's name as a change names it: a text by its element
/// (`ModuleInfo/Name`, not `ModuleInfo/Name@TextId`).
fn shown(name: &str) -> &str {
    name.strip_suffix("@TextId").unwrap_or(name)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn class(rule: &Rule, old: Option<&str>, new: Option<&str>) -> Option<Class> {
        judge(rule, "x".into(), old, new, (None, None)).map(|c| c.class)
    }

    #[test]
    fn each_judge_breaks_one_way() {
        let tsdr = gsd_rule("maxtsdr_<baud>");
        assert_eq!(class(tsdr, Some("150"), Some("200")), Some(Class::Breaking));
        assert_eq!(
            class(tsdr, Some("150"), Some("100")),
            Some(Class::Compatible)
        );
        assert_eq!(class(tsdr, Some("150"), Some("0x96")), None);
        let supp = gsd_rule("<baud>_supp");
        assert_eq!(class(supp, Some("1"), None), Some(Class::Breaking));
        assert_eq!(class(supp, None, Some("1")), Some(Class::Compatible));
        assert_eq!(class(supp, None, Some("0")), None);
        let limit = gsd_rule("max_input_len");
        assert_eq!(class(limit, Some("32"), Some("28")), Some(Class::Breaking));
        assert_eq!(
            class(limit, Some("32"), Some("64")),
            Some(Class::Compatible)
        );
        let slots = gsdml_rule("AllowedInSlots");
        assert_eq!(
            class(slots, Some("1"), Some("1..4")),
            Some(Class::Compatible)
        );
        assert_eq!(
            class(slots, Some("1..4"), Some("1 3")),
            Some(Class::Breaking)
        );
        assert_eq!(class(slots, Some("1..2 3"), Some("1..3")), None);
        let modes = gsdml_rule("ApplicationRelations@StartupMode");
        assert_eq!(
            class(modes, Some("Legacy;Advanced"), Some("Advanced")),
            Some(Class::Breaking)
        );
        assert_eq!(class(modes, None, Some("Legacy")), None);
        let classes = gsdml_rule("ApplicationClass");
        assert_eq!(class(classes, Some(""), None), None);
        assert_eq!(class(classes, None, Some(" ")), None);
        assert_eq!(
            class(classes, Some("FunctionalSafety"), None),
            Some(Class::Breaking)
        );
        // A name of station proposed in capitals is the same name.
        let station = gsdml_rule("DNS_CompatibleName");
        assert_eq!(class(station, Some("FENA"), Some("fena")), None);
        assert_eq!(
            class(station, Some("fena"), Some("fena-2")),
            Some(Class::Compatible)
        );
        let consistency = gsdml_rule("Consistency");
        assert_eq!(
            class(consistency, Some("All items consistency"), None),
            Some(Class::Breaking)
        );
        assert_eq!(
            class(consistency, None, Some("All items consistency")),
            Some(Class::Compatible)
        );
        let unknown = judge(
            gsdml_rule("Frobnicate"),
            "x".into(),
            Some("1"),
            Some("2"),
            (None, None),
        )
        .unwrap();
        assert_eq!((unknown.class, unknown.judged), (Class::Breaking, false));
    }

    #[test]
    fn rules_are_found_by_element_and_attribute() {
        assert_eq!(gsdml_rule("ModuleInfo/OrderNumber@Value").judge, Text);
        assert_eq!(
            gsdml_rule("ApplicationRelations/TimingProperties@SendClock").judge,
            Set
        );
        assert_eq!(gsdml_rule("MAUTypeList/MAUTypeItem@Value").judge, Set);
        assert_eq!(gsdml_rule("Frob@Value").judge, Unknown);
        assert_eq!(
            gsd_rule("physical_interface(0)/transmission_delay_<baud>").judge,
            Demand
        );
        assert_eq!(gsd_rule("physical_interface(0)").judge, Setting);
    }

    /// Every attribute the GSDML files of the corpus have, where the model
    /// keeps it by name, has a rule: none of theirs is "not judged".
    #[test]
    fn every_gsdml_attribute_of_the_corpus_is_judged() {
        use crate::device::pn::{DiagItem, Submodule};
        use crate::device::{Attribute, Device};
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus/gsdml");
        let mut names: Vec<String> = Vec::new();
        let mut add =
            |attributes: &[Attribute]| names.extend(attributes.iter().map(|a| a.name.to_string()));
        for entry in std::fs::read_dir(dir).expect("../shared/corpus/gsdml") {
            let path = entry.unwrap().path();
            let Some(Device::Pn(d)) = crate::device::read(&std::fs::read(&path).unwrap(), None)
            else {
                continue;
            };
            add(&d.identity);
            add(&d.other);
            let items = d.modules.iter().chain(d.daps.iter().map(|dap| &dap.item));
            let mut submodules: Vec<&Submodule> = d.submodules.iter().collect();
            for item in items {
                add(&item.attributes);
                submodules.extend(&item.submodules);
                item.useable_submodules
                    .iter()
                    .for_each(|r| add(&r.attributes));
            }
            d.daps
                .iter()
                .flat_map(|dap| &dap.useable_modules)
                .for_each(|r| add(&r.attributes));
            for s in submodules {
                add(&s.attributes);
                for record in &s.records {
                    add(&record.attributes);
                    record.data.fields.iter().for_each(|f| add(&f.attributes));
                }
                for part in [&s.io.input, &s.io.output].into_iter().flatten() {
                    add(&part.attributes);
                    part.items.iter().for_each(|i| add(&i.attributes));
                }
            }
            let mut diagnosis: Vec<&DiagItem> = d.diagnosis.iter().collect();
            while let Some(item) = diagnosis.pop() {
                add(&item.attributes);
                diagnosis.extend(&item.extended);
            }
            d.unit_diagnosis.iter().for_each(|u| add(&u.attributes));
        }
        assert!(names.len() > 1000, "{} attributes", names.len());
        let unjudged: std::collections::BTreeSet<&String> = names
            .iter()
            .filter(|n| gsdml_rule(n).judge == Unknown)
            .collect();
        assert!(unjudged.is_empty(), "{unjudged:?}");
    }

    /// Every keyword of the GSD keyword schema has a rule, or a part of the
    /// device model that the comparison judges on its own.
    #[test]
    fn every_gsd_keyword_is_judged() {
        const PARTS: &[&str] = &[
            "user_prm_data_len",
            "user_prm_data",
            "ext_user_prm_data_ref",
            "ext_user_prm_data_const",
            "prmtext",
            "extuserprmdata",
            "prm_text_ref",
            "changeable",
            "visible",
            "module",
            "module_reference",
            "ext_module_prm_data_len",
            "slotdefinition",
            "f_ext_module_prm_data_len",
            "f_ext_user_prm_data_ref",
            "f_ext_user_prm_data_const",
            "unit_diag_bit",
            "unit_diag_not_bit",
            "unit_diag_bit_help",
            "unit_diag_not_bit_help",
            "unit_diag_area",
            "unitdiagtype",
            "x_unit_diag_bit",
            "x_unit_diag_not_bit",
            "x_unit_diag_bit_help",
            "x_unit_diag_not_bit_help",
            "x_unit_diag_area",
            "channel_diag",
        ];
        let unjudged: Vec<String> = crate::gsd::schema::schema()
            .keywords()
            .map(|k| k.name.to_ascii_lowercase())
            .filter(|k| !PARTS.contains(&k.as_str()) && gsd_rule(k).judge == Unknown)
            .collect();
        assert!(unjudged.is_empty(), "{unjudged:?}");
    }
}
