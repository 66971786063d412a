//! Configurable mappings: which parameter (or which meaning) each PZD word
//! and each DPV1 record index carries.

use super::{Choice, Text};

#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
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
    pub fn key(self) -> &'static str {
        match self {
            MappingKind::PzdOut => "pzd_out",
            MappingKind::PzdIn => "pzd_in",
            MappingKind::Dpv1Index => "dpv1_index",
            MappingKind::Setting => "settings",
        }
    }
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MappingSet {
    pub kind: MappingKind,
    pub allowed: Allowed,
    pub entries: Vec<MappingEntry>,
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MappingEntry {
    /// PZD word number (1-based) or record index.
    pub number: u8,
    /// The name with `{n}` replaced by `number`.
    pub name: Text,
    pub default: u16,
    /// The drive parameter that holds this mapping, if the drive has one.
    pub parameter: Option<u16>,
}

/// What a mapping may hold: a parameter address within a range, or one of
/// a list of meanings.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Allowed {
    Range { min: u16, max: u16 },
    Choices(Vec<Choice>),
}

impl Allowed {
    pub fn contains(&self, value: i64) -> bool {
        match self {
            Allowed::Range { min, max } => (i64::from(*min)..=i64::from(*max)).contains(&value),
            Allowed::Choices(choices) => choices.iter().any(|c| c.value == value),
        }
    }
}
