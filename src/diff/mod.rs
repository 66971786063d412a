//! Two device files compared by meaning: what a PLC project configured
//! with the old file meets in a device that the new file describes.
//!
//! [`dp`] compares two GSD files' devices, [`pn`] two GSDML files'. Each
//! difference is a [`Change`] with a [`Class`]:
//!
//! - breaking: a project configured with the old file fails with the new
//!   device, or its data or parameters mean something else there;
//! - compatible: old projects keep working; new ones may do more;
//! - cosmetic: texts, order, names; nothing a device or a master acts on.
//!
//! docs/diff.md gives the reasons for each judgement. The comparison is
//! pure and linear (items are paired through hash maps), so diffing two
//! files costs about as much as reading them.

mod gsd;
mod gsdml;
mod judge;
mod pairing;
mod params;
pub(crate) mod release;

use std::fmt;

use crate::device::{Device, Place, Text};

pub use gsd::compare as dp;
pub use gsdml::compare as pn;

/// Whether two values of a GSDML attribute, as the device model names it
/// (`ApplicationRelations@StartupMode`), are the same as the comparison
/// reads them: sets as sets, numbers as numbers, an absent value as the
/// schema's default.
pub(crate) fn same_gsdml_value(name: &str, old: Option<&str>, new: Option<&str>) -> bool {
    let rule = judge::gsdml_rule(name);
    judge::same(old.or(rule.default), new.or(rule.default), rule.judge)
}

/// Every change from `old` to `new`, breaking first; `None` when one is a
/// GSD file's device and the other a GSDML file's.
pub fn compare(old: &Device, new: &Device) -> Option<Vec<Change>> {
    match (old, new) {
        (Device::Dp(a), Device::Dp(b)) => Some(dp(a, b)),
        (Device::Pn(a), Device::Pn(b)) => Some(pn(a, b)),
        _ => None,
    }
}

/// How a change affects a PLC project configured with the old file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Class {
    Cosmetic,
    Compatible,
    Breaking,
}

impl Class {
    pub const ALL: [Class; 3] = [Class::Breaking, Class::Compatible, Class::Cosmetic];

    pub fn as_str(self) -> &'static str {
        match self {
            Class::Breaking => "breaking",
            Class::Compatible => "compatible",
            Class::Cosmetic => "cosmetic",
        }
    }
}

impl fmt::Display for Class {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// What a change is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[non_exhaustive]
pub enum Kind {
    /// The file's name or schema version.
    File,
    /// Vendor, device and ident numbers, revisions, order number.
    Identity,
    /// A module (GSD) or a DAP or module (GSDML): its presence, config
    /// bytes, ident number, slots.
    Module,
    Submodule,
    /// Cyclic data: lengths and data types.
    IoData,
    /// User_Prm_Data or a record's parameters.
    Parameter,
    /// A record as a whole: index, length.
    Record,
    Diagnosis,
    /// Baud rates, response times, update times.
    Timing,
    /// What the device supports or requires, its limits.
    Feature,
    /// A text the engineering tool shows.
    Text,
    Language,
}

impl Kind {
    pub fn as_str(self) -> &'static str {
        match self {
            Kind::File => "file",
            Kind::Identity => "identity",
            Kind::Module => "module",
            Kind::Submodule => "submodule",
            Kind::IoData => "io-data",
            Kind::Parameter => "parameter",
            Kind::Record => "record",
            Kind::Diagnosis => "diagnosis",
            Kind::Timing => "timing",
            Kind::Feature => "feature",
            Kind::Text => "text",
            Kind::Language => "language",
        }
    }
}

/// One difference between the old and the new file.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Change {
    pub class: Class,
    pub kind: Kind,
    /// False when gsdc does not know what the fact means (an attribute or
    /// keyword it has no rule for): the change is called breaking until a
    /// person has read it.
    pub judged: bool,
    /// What changed: `module "PPO1: 4 PKW + 2 PZD"`, `MaxTsdr_12M`.
    pub subject: String,
    /// How: `config bytes 0xF3,0xF1 → 0xF3,0xF5`.
    pub change: String,
    /// Why it has its class: what a project configured with the old file
    /// meets.
    pub why: String,
    pub old: Option<Place>,
    pub new: Option<Place>,
    /// The same text change at this many more places (a text used by
    /// several modules is reported once).
    pub more: usize,
}

impl Change {
    fn new(
        class: Class,
        kind: Kind,
        subject: impl Into<String>,
        change: impl Into<String>,
    ) -> Self {
        Change {
            class,
            kind,
            judged: true,
            subject: subject.into(),
            change: change.into(),
            why: String::new(),
            old: None,
            new: None,
            more: 0,
        }
    }

    /// A file as a whole: a bus whose file one description builds and the
    /// other does not.
    #[cfg_attr(not(feature = "cli"), allow(dead_code))] // the command line uses it
    pub(crate) fn file(class: Class, subject: String, change: &str, why: &str) -> Self {
        Change::new(class, Kind::File, subject, change).why(why)
    }

    fn why(mut self, why: impl Into<String>) -> Self {
        self.why = why.into();
        self
    }

    fn at(mut self, old: Option<&Place>, new: Option<&Place>) -> Self {
        self.old = old.cloned();
        self.new = new.cloned();
        self
    }
}

/// The changes found so far.
#[derive(Default)]
struct Changes(Vec<Change>, Languages);

/// The translations texts are compared in: those of the languages both
/// files have (a language added or removed is one change of its own), or
/// all of them.
#[derive(Default)]
struct Languages(Option<std::collections::BTreeSet<String>>);

impl Changes {
    fn push(&mut self, change: Change) {
        self.0.push(change);
    }

    /// The changes, breaking first, each class in the order found, with
    /// the same text change at several places reported once.
    fn finish(self) -> Vec<Change> {
        let mut out: Vec<Change> = Vec::with_capacity(self.0.len());
        let mut seen = foldhash::HashMap::default();
        for change in self.0 {
            if change.kind == Kind::Text {
                let key = (change.class, change.change.clone());
                if let Some(&i) = seen.get(&key) {
                    let first: &mut Change = &mut out[i];
                    first.more += 1;
                    continue;
                }
                seen.insert(key, out.len());
            }
            out.push(change);
        }
        out.sort_by_key(|c| std::cmp::Reverse(c.class));
        out
    }

    /// A text that may differ between the files: one cosmetic change
    /// saying what changed, in which language.
    fn text(
        &mut self,
        subject: &str,
        old: Option<&Text>,
        new: Option<&Text>,
        at: (Option<&Place>, Option<&Place>),
    ) {
        if old == new {
            return;
        }
        let change = match (old, new) {
            (Some(old), Some(new)) => match text_change(old, new, &self.1) {
                change if change.is_empty() => return,
                change => change,
            },
            (None, Some(new)) => format!("text {new} added"),
            (Some(old), None) => format!("text {old} removed"),
            (None, None) => return,
        };
        self.push(
            Change::new(Class::Cosmetic, Kind::Text, subject, change)
                .why("a text the engineering tool shows; nothing a device or master acts on")
                .at(at.0, at.1),
        );
    }
}

/// How a text changed: its primary language, else each translation that
/// did, in the languages compared; empty when none did.
fn text_change(old: &Text, new: &Text, compared: &Languages) -> String {
    if old.primary != new.primary {
        return format!("{old} → {new}");
    }
    let mut parts = Vec::new();
    let languages: std::collections::BTreeSet<&str> = old
        .translations
        .keys()
        .chain(new.translations.keys())
        .filter(|lang| compared.0.as_ref().is_none_or(|both| both.contains(*lang)))
        .collect();
    for lang in languages {
        match (old.translations.get(lang), new.translations.get(lang)) {
            (Some(a), Some(b)) if a != b => parts.push(format!("({lang}) \"{a}\" → \"{b}\"")),
            (Some(a), None) => parts.push(format!("({lang}) \"{a}\" removed")),
            (None, Some(b)) => parts.push(format!("({lang}) \"{b}\" added")),
            _ => {}
        }
    }
    parts.join(", ")
}

/// `"name"` of something that may have no name.
fn quoted(text: Option<&Text>) -> String {
    text.map_or_else(String::new, |t| format!(" {t}"))
}
