// The device tables (gsdc templates/support/device.rs): what a PROFIBUS-DP
// slave and a PROFINET IO device built from a layout need to know of the
// device, the same types in every layout (`DP_DEVICE`, `PN_DEVICE`), so one
// slave or device serves any description. Every number in a table comes
// from the description through the plan the GSD and the GSDML are written
// from.

use super::{check_len, read_bytes, read_value, Mapping, PrmError};

/// Which PKW codec of the support module the card's telegrams carry.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PkwCodec {
    /// No PKW channel.
    None,
    /// `pkw_pke_ind_pwe`.
    PkeIndPwe,
    /// `pkw_station_command`.
    StationCommand,
    /// `pkw_profidrive`.
    Profidrive,
}

/// A gateway's node totals: the bytes of input and output the nodes in use
/// carry, as User_Prm_Data sets them; `None` when it is refused.
pub type NodeTotals = fn(&[u8]) -> Option<(usize, usize)>;

/// A PROFIBUS-DP slave: its identity, the modules its GSD offers, its
/// User_Prm_Data, the PZD words that User_Prm_Data maps, its diagnosis
/// block and, for a gateway, its nodes.
#[derive(Clone, Copy, Debug)]
pub struct DpDevice {
    pub ident_number: u16,
    /// Freeze_Mode_supp and Sync_Mode_supp: whether the slave takes
    /// Global_Control's Freeze and Sync.
    pub freeze_mode: bool,
    pub sync_mode: bool,
    /// Every `Module` of the GSD, in its order.
    pub modules: &'static [DpModule],
    /// Max_Module: the most modules a configuration plugs.
    pub max_modules: usize,
    /// A gateway's node totals from User_Prm_Data (input and output bytes
    /// the nodes in use carry), which the plugged modules must equal;
    /// `None` for a card whose configuration is one module.
    pub node_totals: Option<NodeTotals>,
    pub user_prm: UserPrm,
    /// The most bytes a diagnosis carries after the standard 6
    /// (Max_Diag_Data_Len less 6): the device-related block, its header
    /// included, and the channels' blocks of 3 bytes; 0 without either.
    pub diagnosis_len: usize,
    /// A drive's card's device-related diagnosis block: its bytes and the
    /// areas the GSD's `Unit_Diag_Area`s read.
    pub diagnosis: Option<DpDiagnosis>,
    pub pkw: PkwCodec,
    /// Whether PZD1 from the master is the drive's control word, and PZD1
    /// to the master its status word.
    pub control_word: bool,
    pub status_word: bool,
    /// The PZD words from the master that a parameter of User_Prm_Data
    /// maps to a drive parameter, and those to the master.
    pub pzd_out: &'static [PzdParam],
    pub pzd_in: &'static [PzdParam],
    /// A gateway's nodes and diagnosis.
    pub gateway: Option<DpGateway>,
}

/// A PZD word and the parameter of User_Prm_Data whose value is the drive
/// parameter it carries.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PzdParam {
    /// Its number in the telegram, from 1 (PZD1 follows the PKW channel).
    pub word: u8,
    /// The parameter's place in `UserPrm::params`.
    pub param: usize,
}

/// The device-related diagnosis block of a drive's card.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DpDiagnosis {
    /// Bytes of the block, the header byte included.
    pub len: usize,
    /// Every `Unit_Diag_Area` of the GSD, in its order.
    pub areas: &'static [DpDiagArea],
}

impl DpDiagnosis {
    /// The header byte: a device-related block (bits 7-6 = 00) of `len`
    /// bytes.
    pub const fn header(&self) -> u8 {
        (self.len & 0x3F) as u8
    }
}

/// A `Unit_Diag_Area`: bits `first_bit..=last_bit` after the header, and
/// the values the GSD gives a text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DpDiagArea {
    pub first_bit: u16,
    pub last_bit: u16,
    pub values: &'static [u16],
}

impl DpDiagArea {
    /// The area, to read and write in a block.
    pub const fn area(&self) -> super::diagnosis::DiagArea {
        super::diagnosis::DiagArea::new(self.first_bit, self.last_bit)
    }
}

/// A gateway's nodes, as User_Prm_Data puts them in use (the first
/// `node_count` of them, each node's words following the words of the nodes
/// before it, in ascending node number), and the diagnosis block it sends
/// for a node.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DpGateway {
    /// The place in `UserPrm::params` of the number of nodes in use.
    pub node_count: usize,
    /// Every node number, the first first.
    pub nodes: &'static [GatewayNode],
    pub diagnosis: Option<GatewayDiagnosis>,
}

/// A node number and the places in `UserPrm::params` of the words it sends
/// (the master's input) and receives.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GatewayNode {
    pub node: u8,
    pub input_words: usize,
    pub output_words: usize,
}

/// Where a gateway's diagnosis block (the header being byte 0) holds the
/// type, the node and the code, and the types there are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GatewayDiagnosis {
    pub type_at: usize,
    pub node_at: usize,
    pub code_at: usize,
    pub types: &'static [GatewayDiagType],
}

/// A type of a gateway's diagnosis: its value, the bytes of its blocks
/// (the header included) and its code.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GatewayDiagType {
    pub value: u8,
    pub len: usize,
    pub code: DiagCode,
    /// The codes a one-byte code may be; empty for a 16-bit number.
    pub codes: &'static [u16],
}

/// How a gateway's diagnosis block carries its code.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DiagCode {
    /// One byte, one of the type's codes.
    Byte,
    /// A 16-bit number, high byte first.
    Word,
}

/// A `Module` of the GSD.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DpModule {
    /// As the GSD writes it: `Module = "PPO1"`.
    pub name: &'static str,
    /// Its config identifier bytes, as Chk_Cfg carries them.
    pub config: &'static [u8],
    /// Bytes of input (the slave sends them) and of output.
    pub input_len: usize,
    pub output_len: usize,
    /// Whether its telegrams start with the PKW channel.
    pub pkw: bool,
    /// Its PZD words each way; 0 for a gateway's module, whose words are
    /// the nodes'.
    pub pzd_words: usize,
    /// A PROFIsafe module's bytes of F-parameters, which the master sends
    /// after the device's User_Prm_Data when it is plugged
    /// (`F_Ext_Module_Prm_Data_Len`) and the F-device's PROFIsafe layer
    /// reads; 0 for any other module.
    pub f_parameter_len: usize,
}

/// User_Prm_Data: its length, the DPV1 status bytes at its start, and
/// every `ExtUserPrmData` of the GSD.
#[derive(Clone, Copy, Debug)]
pub struct UserPrm {
    pub len: usize,
    pub dpv1_status: Option<&'static [u8]>,
    pub params: &'static [DpParam],
}

/// How a parameter is stored, as the GSD names it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PrmDataType {
    Unsigned8,
    Unsigned16,
    /// `Bit(first_bit)` of the byte at the offset.
    Bit,
    /// `BitArea(first_bit-last_bit)` of the byte at the offset.
    BitArea,
}

/// An `ExtUserPrmData` where User_Prm_Data holds it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DpParam {
    /// As the GSD writes it: `ExtUserPrmData = 1 "PZD2 out"`.
    pub name: &'static str,
    pub offset: usize,
    pub data_type: PrmDataType,
    /// The bits of a `Bit` or `BitArea`; 0 and 7 (or 15) for a number.
    pub first_bit: u8,
    pub last_bit: u8,
    pub default_value: u16,
    /// What it may hold: `min` to `max`, and one of `values` when the GSD
    /// lists them (empty: every value of the range).
    pub min: u16,
    pub max: u16,
    pub values: &'static [u16],
}

impl DpParam {
    /// Whether the GSD allows `value`.
    pub fn allows(&self, value: u16) -> bool {
        (self.min..=self.max).contains(&value)
            && (self.values.is_empty() || self.values.contains(&value))
    }

    /// Its value in `user_prm`, refused unless the GSD allows it.
    pub fn read(&self, user_prm: &[u8]) -> Result<u16, PrmError> {
        let at = self.offset;
        let value = match self.data_type {
            PrmDataType::Unsigned16 => u16::from_be_bytes(read_bytes(user_prm, at)?),
            PrmDataType::Unsigned8 => read_bytes::<1>(user_prm, at)?[0].into(),
            PrmDataType::Bit | PrmDataType::BitArea => {
                let byte = u16::from(read_bytes::<1>(user_prm, at)?[0]);
                (byte >> self.first_bit) & self.mask()
            }
        };
        if self.allows(value) {
            Ok(value)
        } else {
            Err(PrmError::NotAllowed {
                offset: self.offset,
                value: value.into(),
            })
        }
    }

    /// Writes `value` into `user_prm`, leaving the other bits of a byte the
    /// parameter shares; refused unless the GSD allows it.
    pub fn write(&self, user_prm: &mut [u8], value: u16) -> Result<(), PrmError> {
        let not_allowed = PrmError::NotAllowed {
            offset: self.offset,
            value: value.into(),
        };
        if !self.allows(value) {
            return Err(not_allowed);
        }
        let end = self.offset.saturating_add(self.len());
        let expected = PrmError::Length {
            expected: end,
            found: user_prm.len(),
        };
        let bytes = user_prm.get_mut(self.offset..end).ok_or(expected)?;
        match self.data_type {
            PrmDataType::Unsigned16 => bytes.copy_from_slice(&value.to_be_bytes()),
            PrmDataType::Unsigned8 => {
                bytes[0] = u8::try_from(value).map_err(|_| not_allowed)?;
            }
            PrmDataType::Bit | PrmDataType::BitArea => {
                let mask = self.mask() << self.first_bit;
                let bits = (value << self.first_bit) & mask;
                bytes[0] = (bytes[0] & !(mask as u8)) | bits as u8;
            }
        }
        Ok(())
    }

    /// Bytes from the offset on.
    const fn len(&self) -> usize {
        match self.data_type {
            PrmDataType::Unsigned16 => 2,
            _ => 1,
        }
    }

    /// The values a `Bit` or `BitArea` holds, as a mask from bit 0.
    const fn mask(&self) -> u16 {
        (1 << (self.last_bit - self.first_bit + 1)) - 1
    }
}

impl UserPrm {
    /// The parameter the GSD names `name`.
    pub fn param(&self, name: &str) -> Option<&DpParam> {
        self.params.iter().find(|p| p.name == name)
    }

    /// Refuses User_Prm_Data of a wrong length or with a value the GSD does
    /// not allow: Chk_Prm answers Prm_Fault then.
    pub fn check(&self, user_prm: &[u8]) -> Result<(), PrmError> {
        check_len(user_prm, self.len)?;
        let read = |p: &DpParam| p.read(user_prm).map(|_| ());
        self.params.iter().try_for_each(read)
    }

    /// User_Prm_Data of the GSD's defaults: what a master sends when the
    /// user changes nothing.
    pub fn defaults(&self, user_prm: &mut [u8]) -> Result<(), PrmError> {
        check_len(user_prm, self.len)?;
        user_prm.fill(0);
        if let Some(status) = self.dpv1_status {
            user_prm[..status.len()].copy_from_slice(status);
        }
        self.params
            .iter()
            .try_for_each(|p| p.write(user_prm, p.default_value))
    }
}

impl DpDevice {
    /// The input and output bytes of the configuration `config` (Chk_Cfg's
    /// bytes) when the slave takes it with User_Prm_Data `user_prm`: at most
    /// `max_modules` modules, each one's config bytes in turn; one at least,
    /// except for a gateway, whose modules carry as many bytes as the nodes
    /// in use (none for nodes without words). `None`: refused.
    pub fn check_config(&self, user_prm: &[u8], config: &[u8]) -> Option<(usize, usize)> {
        let (mut input, mut output, mut plugged) = (0, 0, 0);
        let mut rest = config;
        while !rest.is_empty() {
            let module = self.modules.iter().find(|m| rest.starts_with(m.config))?;
            rest = &rest[module.config.len()..];
            input += module.input_len;
            output += module.output_len;
            plugged += 1;
        }
        let fits = match self.node_totals {
            Some(totals) => totals(user_prm)? == (input, output),
            None => plugged > 0,
        };
        (fits && plugged <= self.max_modules).then_some((input, output))
    }
}

/// A PROFINET IO device: its identity, its device access point with the
/// interface and ports, the modules its GSDML offers and the PZD words their
/// records map.
#[derive(Clone, Copy, Debug)]
pub struct PnDevice {
    pub vendor_id: u16,
    pub device_id: u16,
    /// The device access point's DNS_CompatibleName: the NameOfStation an
    /// engineering tool proposes.
    pub dns_name: &'static str,
    /// The GSDML's device access points, in its order: hardware or firmware
    /// versions of the card, each of which its firmware presents in slot 0.
    /// Those of one ident number present the same slot 0 (SEW's MOVI-C
    /// offers three catalogue versions of its head so): the device cannot
    /// tell which one a project used, and takes what any of them offers
    /// ([`PnDevice::offers`]).
    pub daps: &'static [PnDap],
    /// The interface submodule, every device access point's.
    pub interface_submodule: PnSubmodule,
    /// Every module of the GSDML, in its order.
    pub modules: &'static [PnModule],
    /// Its PROFIsafe modules: the records of their submodules besides the
    /// F-parameters, which the card's PROFIsafe layer reads.
    pub safety_modules: &'static [PnSafetyModule],
    pub pkw: PkwCodec,
    /// Whether PZD1 from the controller is the drive's control word, and
    /// PZD1 to the controller its status word.
    pub control_word: bool,
    pub status_word: bool,
    /// The PZD words from the controller that an entry of a module's
    /// record maps to a drive parameter, and those to the controller.
    pub pzd_out: &'static [PnPzd],
    pub pzd_in: &'static [PnPzd],
}

/// A parameter record of the card's own, of a device access point's
/// submodule or of a port: values at the places the GSDML gives them.
#[derive(Clone, Copy, Debug)]
pub struct PnSubmoduleRecord {
    pub index: u16,
    /// Bytes: as far as its values reach.
    pub len: usize,
    /// In the GSDML's order.
    pub values: &'static [PnRecordValue],
}

/// A value of a [`PnSubmoduleRecord`]: whole bytes, high byte first, or
/// some bits of one byte.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PnRecordValue {
    /// As the GSDML names it, in English.
    pub name: &'static str,
    /// Its first byte in the record.
    pub offset: usize,
    /// Its bytes (1, 2 or 4); 0 for bits of the byte at `offset`.
    pub bytes: usize,
    /// The bits of a `Bit` or `BitArea`; 0 and 7 for whole bytes.
    pub first_bit: u8,
    pub last_bit: u8,
    pub default_value: u32,
    /// What it may hold: `min` to `max`, and one of `values` when the
    /// GSDML lists them (empty: every value of the range).
    pub min: u32,
    pub max: u32,
    pub values: &'static [u32],
    /// Whether the controller may change it (the GSDML's `Changeable`); a
    /// value that is not holds its default.
    pub changeable: bool,
}

impl PnRecordValue {
    /// Whether the GSDML allows `value` here.
    pub fn allows(&self, value: u32) -> bool {
        (self.min..=self.max).contains(&value)
            && (self.values.is_empty() || self.values.contains(&value))
            && (self.changeable || value == self.default_value)
    }

    /// Its value in `record`, which holds its bytes.
    fn read(&self, record: &[u8]) -> Result<u32, PrmError> {
        let whole = self.bytes.max(1);
        let end = self.offset.saturating_add(whole);
        let bytes = record.get(self.offset..end).ok_or(PrmError::Length {
            expected: end,
            found: record.len(),
        })?;
        let number = bytes.iter().fold(0, |n, &b| n << 8 | u32::from(b));
        let bits = self.last_bit - self.first_bit + 1;
        Ok(match self.bytes {
            0 => (number >> self.first_bit) & ((1 << bits) - 1),
            _ => number,
        })
    }
}

impl PnSubmoduleRecord {
    /// The values of a record the controller wrote, exactly `len` bytes,
    /// into the first `values.len()` of `out`, each one checked (one the
    /// controller may not change must hold its default); nothing is
    /// written when it is refused.
    pub fn decode(&self, bytes: &[u8], out: &mut [u32]) -> Result<(), PrmError> {
        check_len(bytes, self.len)?;
        if out.len() < self.values.len() {
            return Err(PrmError::Length {
                expected: self.len,
                found: bytes.len(),
            });
        }
        for value in self.values {
            let read = value.read(bytes)?;
            if !value.allows(read) {
                return Err(PrmError::NotAllowed {
                    offset: value.offset,
                    value: read,
                });
            }
        }
        for (slot, value) in out.iter_mut().zip(self.values) {
            *slot = value.read(bytes)?;
        }
        Ok(())
    }
}

/// A device access point: its module ident number, its own submodule, its
/// ports (the interface is the device's), the modules it offers, by their
/// places in [`PnDevice::modules`], and the card's own records of its
/// submodule and of each of its ports.
#[derive(Clone, Copy, Debug)]
pub struct PnDap {
    pub ident: u32,
    pub submodule: PnSubmodule,
    pub ports: &'static [PnSubmodule],
    pub modules: &'static [usize],
    pub access_point_records: &'static [PnSubmoduleRecord],
    pub port_records: &'static [PnSubmoduleRecord],
}

impl PnDevice {
    /// Whether a device presenting device access point ident `dap_ident`
    /// in slot 0 takes the module at `place` in [`PnDevice::modules`]:
    /// whether a device access point of that ident number offers it.
    pub fn offers(&self, dap_ident: u32, place: usize) -> bool {
        self.daps
            .iter()
            .any(|d| d.ident == dap_ident && d.modules.contains(&place))
    }

    /// The record `index` a device presenting device access point ident
    /// `dap_ident` takes at its own submodule (`port` false) or at a port:
    /// the first device access point of that ident number that has one
    /// (those of one ident number give each index alike, gsdc's E162).
    pub fn own_record(
        &self,
        dap_ident: u32,
        port: bool,
        index: u16,
    ) -> Option<&'static PnSubmoduleRecord> {
        let daps = self.daps.iter().filter(|d| d.ident == dap_ident);
        daps.flat_map(|d| {
            if port {
                d.port_records
            } else {
                d.access_point_records
            }
        })
        .find(|r| r.index == index)
    }
}

/// A PROFIsafe module: its ident number, its submodule with the safety
/// data (the message trailer included), and that submodule's parameter
/// records besides the F-parameters (SEW's MOVI-C: record 8200).
#[derive(Clone, Copy, Debug)]
pub struct PnSafetyModule {
    pub ident: u32,
    pub submodule: PnSubmodule,
    pub records: &'static [PnSubmoduleRecord],
}

/// A PZD word and the record entry whose value is the drive parameter it
/// carries: entry `entry` of the record `record` of the plugged module.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PnPzd {
    /// Its number in the telegram, from 1 (PZD1 follows the PKW channel).
    pub word: u8,
    /// The record's index.
    pub record: u16,
    /// The entry's place in the record, from 0.
    pub entry: usize,
}

/// A submodule: where it sits and its IO data in bytes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PnSubmodule {
    pub subslot: u16,
    pub ident: u32,
    pub input_len: usize,
    pub output_len: usize,
}

/// A module of the GSDML.
#[derive(Clone, Copy, Debug)]
pub struct PnModule {
    /// As the GSDML names it, in English.
    pub name: &'static str,
    pub ident: u32,
    /// The slots it may be plugged into.
    pub slots: &'static [u16],
    /// The API its submodules are in: 0, or PROFIdrive's 0x3A00.
    pub api: u32,
    /// Whether its telegrams start with the PKW channel, and its PZD words
    /// each way.
    pub pkw: bool,
    pub pzd_words: usize,
    /// The PZD words (from 1) where a 32-bit value starts, high word first,
    /// the same both ways: standard telegram 2's NSOLL_B and NIST_B at 2.
    pub double_words: &'static [usize],
    /// PROFIdrive's module access point: a submodule without data.
    pub access_point: Option<PnSubmodule>,
    /// The submodule with the IO data.
    pub data: PnSubmodule,
    pub records: &'static [PnRecord],
}

/// How much of a record the controller writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RecordReading {
    /// Every entry: exactly `len` bytes.
    Whole,
    /// The first entries (a PZD record's, two bytes each), at most `len`
    /// bytes; the others keep their defaults.
    Prefix,
}

/// A parameter record of a module's data submodule.
#[derive(Clone, Copy, Debug)]
pub struct PnRecord {
    pub index: u16,
    /// Bytes, as the GSDML gives them: its entries' bytes, then its
    /// fail-safe values'.
    pub len: usize,
    pub reading: RecordReading,
    /// Its entries in record order, each of its bytes, with no gaps.
    pub entries: &'static [&'static Mapping],
    /// Each entry's value as the GSDML gives it (DefaultValue): its
    /// default, or the value the module fixes.
    pub defaults: &'static [u16],
    /// Whether the controller may change each entry (the GSDML's
    /// `Changeable`); an entry that is not holds its default.
    pub changeable: &'static [bool],
    /// The bytes of each value the settings record ends with after its
    /// entries, one per output PZD item of the module (2, or 4 for a
    /// 32-bit item), when the description has fail-safe values.
    pub fail_safe: &'static [u8],
}

impl PnRecord {
    /// The entries' values of a record the controller wrote, into the first
    /// `entries.len()` of `values`, each one checked (an entry the module
    /// fixes must hold its default), the entries a prefix leaves out with
    /// their defaults; nothing is written when it is refused.
    pub fn decode(&self, bytes: &[u8], values: &mut [u16]) -> Result<(), PrmError> {
        let fits = match self.reading {
            RecordReading::Whole => bytes.len() == self.len,
            RecordReading::Prefix => {
                bytes.is_empty() || self.entry_ends().any(|(end, _)| end == bytes.len())
            }
        };
        if !fits || values.len() < self.defaults.len() {
            return Err(PrmError::Length {
                expected: self.len,
                found: bytes.len(),
            });
        }
        let written = self.entry_ends().take_while(|(end, _)| *end <= bytes.len());
        for (i, (end, entry)) in written.enumerate() {
            let at = end - entry.bytes;
            let value = read_value(bytes, at, entry)?;
            let fixed = self.changeable.get(i) == Some(&false);
            let held = self.defaults.get(i) == Some(&value);
            if !entry.allowed.contains(value) || fixed && !held {
                return Err(PrmError::NotAllowed {
                    offset: at,
                    value: value.into(),
                });
            }
        }
        let mut ends = self.entry_ends();
        for (value, default) in values.iter_mut().zip(self.defaults) {
            *value = match ends.next() {
                Some((end, entry)) if end <= bytes.len() => {
                    read_value(bytes, end - entry.bytes, entry)?
                }
                _ => *default,
            };
        }
        Ok(())
    }

    /// The fail-safe values a record the controller wrote ends with, into
    /// the first `fail_safe.len()` of `out` (which holds at least as many),
    /// high byte first; any value of its width is allowed. Nothing is
    /// written when the record is not `len` bytes long, nor when its entries
    /// and values would not fit in it (a table that disagrees with itself).
    pub fn decode_fail_safe(&self, bytes: &[u8], out: &mut [u32]) -> Result<(), PrmError> {
        check_len(bytes, self.len)?;
        let start = self.entry_ends().last().map_or(0, |(end, _)| end);
        let widths: usize = self.fail_safe.iter().map(|&b| usize::from(b)).sum();
        let end = start + widths;
        if end > bytes.len() || out.len() < self.fail_safe.len() {
            return Err(PrmError::Length {
                expected: end,
                found: bytes.len(),
            });
        }
        let mut at = start;
        for (value, &size) in out.iter_mut().zip(self.fail_safe) {
            let end = at + usize::from(size);
            *value = bytes[at..end]
                .iter()
                .fold(0, |value, &byte| value << 8 | u32::from(byte));
            at = end;
        }
        Ok(())
    }

    /// Where each entry ends in the record, with the entry.
    fn entry_ends(&self) -> impl Iterator<Item = (usize, &'static Mapping)> + '_ {
        self.entries.iter().scan(0, |end, entry| {
            *end += entry.bytes;
            Some((*end, *entry))
        })
    }
}
