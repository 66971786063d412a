//! Values that reach the device files although no manual gave them: the
//! description's own choices (with their reasons), placeholders to be
//! replaced before shipping, and the defaults gsdc applied where the
//! description is silent. Every generated file lists them in its header; a
//! shipping build refuses them (`gsdc build --deny-warnings`).

use super::Bus;
use crate::i18n::Phrase;

#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Decision {
    pub kind: DecisionKind,
    /// Where the description holds it (or would): `profibus.min_slave_interval`.
    pub path: String,
    /// The value as the description writes it, on one line.
    pub value: String,
    pub reason: String,
    /// gsdc's own words for a decision gsdc made, in every language it has
    /// words in (the strings above are their English); `None` for the
    /// description's own choices, whose reasons are the description's.
    pub(crate) words: Option<DecisionWords>,
}

/// gsdc's words for what it decided: the path and value where gsdc names
/// them in words (a numbering, a requirement), and the reason.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct DecisionWords {
    pub path: Option<Phrase>,
    pub value: Option<Phrase>,
    pub reason: Phrase,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
#[non_exhaustive]
pub enum DecisionKind {
    /// Not assigned yet (a PI ident number): to be replaced.
    Placeholder,
    /// Chosen by the description, with its reason.
    Choice,
    /// Chosen by gsdc: the description does not state it.
    Default,
    /// gsdc's own numbering (ident numbers, subslots): nothing for the
    /// firmware to match by hand, since its layout carries every number.
    Convention,
    /// gsdc's layout of bytes the manual gives no place for (User_Prm_Data's
    /// order and offsets, config identifiers, Max_Module); the layouts carry
    /// each.
    Layout,
    /// What gsdc's device file says every such card does (a PROFINET
    /// stack's services), which no description key states: the firmware
    /// must do it.
    Requirement,
}

impl Decision {
    /// The bus whose device file alone the decision concerns, by the
    /// description's key it stands at: `[profibus]` and a gateway (a
    /// PROFIBUS-DP slave) are the GSD's, `[profinet]` the GSDML's; `None`
    /// for what both buses share (the device, the telegram, the mappings
    /// and settings, the parameter numbering).
    pub fn bus(&self) -> Option<Bus> {
        let root = self
            .path
            .split(['.', '[', ' '])
            .next()
            .unwrap_or(&self.path);
        match root {
            "profibus" | "gateway" => Some(Bus::Profibus),
            "profinet" => Some(Bus::Profinet),
            _ => None,
        }
    }

    /// One line: `Own choice: profibus.min_slave_interval = 1 (the reason)`.
    pub fn summary(&self) -> String {
        let kind = match self.kind {
            DecisionKind::Placeholder => "Placeholder",
            DecisionKind::Choice => "Own choice",
            DecisionKind::Default => "gsdc's default",
            DecisionKind::Convention => "gsdc's numbering",
            DecisionKind::Layout => "gsdc's layout",
            DecisionKind::Requirement => "Required of the firmware",
        };
        format!("{kind}: {} = {} ({})", self.path, self.value, self.reason)
    }
}
