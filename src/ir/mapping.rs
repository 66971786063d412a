//! Configurable mappings: which parameter (or which meaning) each PZD word
//! and each DPV1 record index carries, and the drive settings a master gives
//! at start-up.
//!
//! Mappings are grouped by kind, in telegram order; every set and entry has
//! a key made of its kind and number, so that the parameter telegram, the
//! records and the generated code link to them by what they are, not by
//! where lowering happened to put them.

use super::{Ident, Text, ValueSet};

#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[non_exhaustive]
pub enum MappingKind {
    /// Words the master sends (master -> slave).
    PzdOut,
    /// Words the drive sends (slave -> master).
    PzdIn,
    /// DPV1 record indexes read and written acyclically.
    Dpv1Index,
    /// A single drive parameter set at start-up.
    Setting,
}

impl MappingKind {
    /// Telegram order, the order of the groups.
    pub const ALL: [MappingKind; 4] = [
        MappingKind::PzdOut,
        MappingKind::PzdIn,
        MappingKind::Dpv1Index,
        MappingKind::Setting,
    ];

    /// The description's key, and the name of the group's module in
    /// generated code.
    pub fn key(self) -> &'static str {
        match self {
            MappingKind::PzdOut => "pzd_out",
            MappingKind::PzdIn => "pzd_in",
            MappingKind::Dpv1Index => "dpv1_index",
            MappingKind::Setting => "settings",
        }
    }
}

/// An entry: its kind and number (PZD word, record index, or the setting's
/// place in the description, from 1). Unique within a description.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct EntryKey {
    pub kind: MappingKind,
    pub number: u8,
}

/// A set: its kind and the number of its first entry.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct SetKey {
    pub kind: MappingKind,
    pub first: u8,
}

/// Every mapping of the description, grouped by kind in telegram order.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
#[non_exhaustive]
pub struct Mappings {
    pub groups: Vec<MappingGroup>,
}

impl Mappings {
    pub fn group(&self, kind: MappingKind) -> Option<&MappingGroup> {
        self.groups.iter().find(|g| g.kind == kind)
    }

    pub fn sets(&self) -> impl Iterator<Item = &MappingSet> {
        self.groups.iter().flat_map(|g| &g.sets)
    }

    pub fn set(&self, key: SetKey) -> &MappingSet {
        self.sets()
            .find(|s| s.key == key)
            .expect("lowering links only to sets it made")
    }

    /// The entry and the set it belongs to.
    pub fn entry(&self, key: EntryKey) -> (&MappingSet, &MappingEntry) {
        self.sets()
            .filter(|s| s.key.kind == key.kind)
            .find_map(|s| Some((s, s.entries.iter().find(|e| e.key == key)?)))
            .expect("lowering links only to entries it made")
    }
}

/// The sets of one kind, in the order of their numbers.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct MappingGroup {
    pub kind: MappingKind,
    pub sets: Vec<MappingSet>,
    /// DPV1 indexes: the bytes of the record each index reads and writes,
    /// when the description says.
    pub record_length: Option<u8>,
}

impl MappingGroup {
    pub fn entries(&self) -> impl Iterator<Item = (&MappingSet, &MappingEntry)> {
        self.sets
            .iter()
            .flat_map(|s| s.entries.iter().map(move |e| (s, e)))
    }

    pub fn entry_count(&self) -> usize {
        self.sets.iter().map(|s| s.entries.len()).sum()
    }
}

/// Entries numbered `first..=last` that share what they may hold.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct MappingSet {
    pub key: SetKey,
    pub allowed: Allowed,
    /// What its entries' values are.
    pub holds: Holds,
    /// A setting whose value each kind of PROFINET module writes.
    pub per_module: Option<PerModule>,
    /// How User_Prm_Data and the records carry each entry; a mapping's
    /// are Unsigned16.
    pub entry_type: EntryType,
    /// Where the drive's parameters of the set are set: at the drive, or
    /// by the master at startup (User_Prm_Data, parameter records).
    pub set_at: SetAt,
    /// The constant that says what the set's entries may hold, unique
    /// within its group.
    pub allowed_ident: Ident,
    pub entries: Vec<MappingEntry>,
}

#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct MappingEntry {
    pub key: EntryKey,
    /// The name with `{n}` replaced by the number.
    pub name: Text,
    pub default: u16,
    /// The drive parameter that holds this mapping, if the drive has one.
    pub parameter: Option<u16>,
}

/// Where a set's drive parameters are set.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum SetAt {
    /// At the drive (keypad, PKW, the drive's own tool): no User_Prm_Data
    /// or parameter record carries the set; the master writes nothing.
    Drive,
    /// By the master at every startup: User_Prm_Data on PROFIBUS, the
    /// modules' parameter records on PROFINET.
    Master,
}

impl MappingSet {
    /// Whether the master writes the set at startup (User_Prm_Data,
    /// parameter records); not for a set the drive's own settings hold.
    pub fn master_writes(&self) -> bool {
        self.set_at == SetAt::Master
    }
}

/// What a mapping's values are: a drive parameter's address, a plain value
/// (a timeout, a count), or one of its choices.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Holds {
    Address,
    Value,
    Choice,
}

/// How User_Prm_Data and the parameter records carry a set's entries, high
/// byte first. Every value is from 0 to [`EntryType::max`]: an Integer8
/// holds no negative value, so an unsigned byte reads it alike.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum EntryType {
    Unsigned8,
    Integer8,
    Unsigned16,
}

impl EntryType {
    pub fn bytes(self) -> u16 {
        match self {
            EntryType::Unsigned8 | EntryType::Integer8 => 1,
            EntryType::Unsigned16 => 2,
        }
    }

    /// The largest value an entry holds.
    pub fn max(self) -> u16 {
        match self {
            EntryType::Unsigned8 => 0xFF,
            EntryType::Integer8 => 0x7F,
            EntryType::Unsigned16 => 0xFFFF,
        }
    }

    /// As GSDML names it (`Ref@DataType`).
    pub fn gsdml_name(self) -> &'static str {
        match self {
            EntryType::Unsigned8 => "Unsigned8",
            EntryType::Integer8 => "Integer8",
            EntryType::Unsigned16 => "Unsigned16",
        }
    }
}

/// The value of a setting that each kind of PROFINET module writes: one
/// the module fixes (the user cannot change it), or the module's default.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct PerModule {
    pub user_defined: u16,
    pub standard_telegram_1: Option<u16>,
    pub standard_telegram_2: Option<u16>,
    /// True: each value is its module's default, which the user may
    /// change (ABB FENA's stop mode: 1 in its PPO modules, 0 in the
    /// standard telegrams); false: the module fixes it.
    pub changeable: bool,
    /// Whether User_Prm_Data carries the setting, a PROFIBUS master setting
    /// it, as the description says; true without `[profibus]`.
    pub in_user_prm: bool,
}

/// What a mapping may hold: a parameter address within a range, or one of
/// a list of meanings.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum Allowed {
    Range { min: u16, max: u16 },
    Choices(ValueSet),
}

impl Allowed {
    pub fn contains(&self, value: i64) -> bool {
        match self {
            Allowed::Range { min, max } => (i64::from(*min)..=i64::from(*max)).contains(&value),
            Allowed::Choices(set) => set.choices.iter().any(|c| c.value == value),
        }
    }

    pub fn choices(&self) -> Option<&ValueSet> {
        match self {
            Allowed::Choices(set) => Some(set),
            Allowed::Range { .. } => None,
        }
    }
}

#[cfg(test)]
impl Allowed {
    /// Choices with these values and empty texts, for tests.
    pub(crate) fn of_values(values: &[i64]) -> Self {
        let choices = values
            .iter()
            .map(|&value| super::Choice {
                value,
                text: Text::english(""),
                ident: Ident::of(&["value"]).tagged(value),
            })
            .collect();
        Allowed::Choices(ValueSet {
            ident: Ident::of(&["choice"]),
            choices,
        })
    }
}
