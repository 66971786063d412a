//! A group of mappings in the layout: what each set of entries may hold,
//! the entries with their defaults and drive parameters, where
//! User_Prm_Data and the PROFINET record carry them, and the values each
//! PROFINET module fixes or defaults.

use super::{value_set, Const, Consts, Doc, Ref, Scope, Ty, Val, ValueSet};
use crate::ir::mapping::{Allowed, EntryType, Holds, MappingGroup, MappingKind, MappingSet};
use crate::ir::profinet::RecordReading;
use crate::ir::{Ident, Ir};
use serde::Serialize;

#[derive(Serialize)]
pub(crate) struct Group {
    /// `pzd_out`: Rust's module, C's infix.
    pub name: Ident,
    pub doc: Doc,
    pub sets: Vec<Set>,
    pub entries: Vec<Entry>,
    pub defaults: Doc,
    pub user_prm: Option<UserPrmBlock>,
    pub record: Option<Record>,
    /// DPV1 indexes: the bytes of each index's record.
    pub record_data: Option<Consts>,
    /// How many bytes each entry takes, in a sentence.
    pub entry_bytes: &'static str,
    /// Every entry an Unsigned16.
    pub two_bytes_each: bool,
    pub module_values: Vec<ModuleValues>,
}

/// Entries that share what they may hold.
#[derive(Serialize)]
pub(crate) struct Set {
    pub allowed: Ident,
    pub doc: Doc,
    /// `each entry` in a group of one set, else the entry's name quoted.
    pub holder: String,
    /// The place after its last entry in the group.
    pub end: usize,
    pub range: Option<Range>,
    pub choices: Option<ValueSet>,
}

#[derive(Serialize)]
pub(crate) struct Range {
    pub min: Val,
    pub max: Val,
    /// Whether each bound rules out a 16-bit value.
    pub has_min: bool,
    pub has_max: bool,
}

#[derive(Serialize)]
pub(crate) struct Entry {
    pub number: u8,
    pub doc: Doc,
    pub name: Val,
    pub default: Val,
    /// The manual's name of the default, a parameter address.
    pub default_note: Option<String>,
    pub parameter: Option<Val>,
    pub parameter_note: Option<String>,
    /// Its set's constant.
    pub allowed: Ident,
    /// In User_Prm_Data and the record: 2, or 1 for a setting of a byte.
    pub bytes: u16,
}

/// Where User_Prm_Data carries the group.
#[derive(Serialize)]
pub(crate) struct UserPrmBlock {
    pub offset: u16,
    /// When it carries every entry.
    pub doc: Doc,
    /// The entries it carries, by place, when not all; empty when all.
    pub entries: Vec<usize>,
}

/// The PROFINET parameter record of the group.
#[derive(Serialize)]
pub(crate) struct Record {
    pub index: u16,
    pub doc: Doc,
    /// A module's record holds the words it transports: the controller
    /// writes the first entries only.
    pub prefix: bool,
    /// Its bytes: every entry's.
    pub len: u16,
    /// Each module's record ends with its own fail-safe values: only the
    /// device tables' records decode it.
    pub fail_safe: bool,
    /// A module's record leaves out the entries set at the drive: only the
    /// device tables' records decode it.
    pub master_only: bool,
}

/// The value of a setting each PROFINET module fixes.
#[derive(Serialize)]
pub(crate) struct ModuleValues {
    pub name: Ident,
    pub doc: Doc,
    pub modules: Vec<ModuleValue>,
}

#[derive(Serialize)]
pub(crate) struct ModuleValue {
    /// The module's ident number constant.
    pub ident: Ident,
    pub value: u16,
}

/// What a group of mappings is, and where its drive parameters are set.
pub(crate) fn group_doc(g: &MappingGroup) -> String {
    let what = match g.kind {
        MappingKind::PzdOut => "The PZD words the master sends: what each one carries.",
        MappingKind::PzdIn => "The PZD words the drive sends: what each one carries.",
        MappingKind::Dpv1Index => {
            "The DPV1 record indexes: the parameter each one reads and writes."
        }
        MappingKind::Setting => "Single drive parameters.",
    };
    let by_master = g.sets.iter().filter(|s| s.master_writes()).count();
    let set = match (by_master, g.sets.len() - by_master) {
        (_, 0) => "The master writes them at startup.",
        (0, _) => "Set at the drive (keypad, PKW, the drive's own tool): the master writes none of them, and no parameter record or User_Prm_Data carries them.",
        _ => "The master writes some of them at startup, those User_Prm_Data or the records carry; the others are set at the drive.",
    };
    format!("{what} {set}")
}

pub(super) fn group(ir: &Ir, g: &MappingGroup) -> Group {
    let scope = Scope::part(g.kind.key());
    let single = g.sets.len() == 1;
    let mut end = 0;
    let sets = g
        .sets
        .iter()
        .map(|set| {
            end += set.entries.len();
            self::set(&scope, set, single, end)
        })
        .collect();
    let record = ir.profinet.as_ref().and_then(|p| p.record(g.kind));
    let profibus = ir.profibus.as_ref();
    Group {
        name: Ident::of(&g.kind.key().split('_').collect::<Vec<_>>()),
        doc: Doc::plain(group_doc(g)),
        sets,
        entries: g.sets.iter().flat_map(|set| entries(ir, set)).collect(),
        defaults: Doc::plain("The defaults in entry order."),
        user_prm: profibus
            .and_then(|p| p.user_prm.block(g.kind))
            .map(|block| UserPrmBlock {
                offset: block.offset,
                doc: Doc::plain(format!(
                    "Where the first entry starts in User_Prm_Data; the others follow it, {}.",
                    each_entrys_bytes(g)
                )),
                entries: profibus
                    .and_then(|p| p.user_prm.partial(g))
                    .unwrap_or_default(),
            }),
        record: record.map(|r| Record {
            index: r.index,
            doc: Doc::plain(format!(
                "The PROFINET parameter record of these entries, {}.",
                each_entrys_bytes(g)
            )),
            prefix: r.reading == RecordReading::Prefix,
            len: r.length,
            fail_safe: ir.profinet.iter().flat_map(|p| &p.modules).any(|m| {
                m.records
                    .iter()
                    .any(|rec| rec.kind == g.kind && !rec.fail_safe.is_empty())
            }),
            master_only: !g.sets.iter().all(MappingSet::master_writes),
        }),
        entry_bytes: each_entrys_bytes(g),
        two_bytes_each: two_bytes_each(g),
        record_data: g.record_length.map(|len| Consts {
            doc: Doc::plain("The bytes of the record each DPV1 index reads and writes."),
            items: vec![Const::new(
                &["record", "data", "len"],
                Ty::Size,
                Val::Dec(len.into()),
            )],
        }),
        module_values: module_values(ir, g),
    }
}

/// A mapping's value as the layouts write it: a parameter address in hex,
/// as the manuals write addresses; a plain value or a choice in decimal.
pub(crate) fn mapping_value(holds: Holds, value: u16) -> Val {
    match holds {
        Holds::Address => Val::hex_u16(value),
        Holds::Value | Holds::Choice => Val::Dec(value.into()),
    }
}

/// `0x2B02` or `100`, in a sentence.
fn mapping_text(holds: Holds, value: u16) -> String {
    match holds {
        Holds::Address => crate::emit::hex16(value),
        Holds::Value | Holds::Choice => value.to_string(),
    }
}

fn two_bytes_each(g: &MappingGroup) -> bool {
    g.sets.iter().all(|s| s.entry_type == EntryType::Unsigned16)
}

/// How many bytes each entry of `g` takes, in a sentence.
fn each_entrys_bytes(g: &MappingGroup) -> &'static str {
    if two_bytes_each(g) {
        "two bytes each"
    } else {
        "one or two bytes each by its type, with no gaps"
    }
}

/// A group with one set says "each entry" in its docs; a set of a group of
/// several (the settings) names its one entry.
fn set(scope: &Scope, set: &MappingSet, single: bool, end: usize) -> Set {
    let holder = if single {
        "each entry".to_string()
    } else {
        format!("\"{}\"", set.entries[0].name.en)
    };
    // Only gsdc's own words are capitalised to begin a sentence: the name
    // stays as the description writes it (P43.01, not p43.01).
    let subject = super::super::capitalised(&holder);
    let doc = Doc::at(scope.clone());
    match &set.allowed {
        Allowed::Range { min, max } => {
            let what = match set.holds {
                Holds::Address => "a parameter address",
                Holds::Value | Holds::Choice => "a value",
            };
            Set {
                allowed: set.allowed_ident.clone(),
                doc: doc.text(format!(
                    "{subject} holds {what} from {} to {}.",
                    mapping_text(set.holds, *min),
                    mapping_text(set.holds, *max)
                )),
                holder,
                end,
                range: Some(Range {
                    min: mapping_value(set.holds, *min),
                    max: mapping_value(set.holds, *max),
                    has_min: *min > 0,
                    has_max: *max < u16::MAX,
                }),
                choices: None,
            }
        }
        Allowed::Choices(values) => {
            let choices = value_set(values, Doc::plain(format!("What {holder} may hold.")));
            Set {
                allowed: set.allowed_ident.clone(),
                doc: doc
                    .text(format!("{subject} holds one of the values of "))
                    .link(Ref::Values(scope.clone(), choices.name.clone()))
                    .text("."),
                holder,
                end,
                range: None,
                choices: Some(choices),
            }
        }
    }
}

fn entries<'a>(ir: &'a Ir, set: &'a MappingSet) -> impl Iterator<Item = Entry> + 'a {
    // Parameter addresses read best in hex, with the manual's name beside
    // them; a value or a choice is a plain number.
    let name_of = |address: u16| ir.numbering.as_ref().and_then(|n| n.format(address));
    set.entries.iter().map(move |e| {
        let number = e.key.number;
        let what = match e.key.kind {
            MappingKind::PzdOut | MappingKind::PzdIn => format!("PZD{number}"),
            MappingKind::Dpv1Index => format!("DPV1 index {number}"),
            MappingKind::Setting => format!("Setting {number}"),
        };
        Entry {
            number,
            doc: Doc::plain(format!("{what}: \"{}\".", e.name.en)),
            name: Val::Text(e.name.en.clone()),
            default: mapping_value(set.holds, e.default),
            default_note: (set.holds == Holds::Address)
                .then(|| name_of(e.default))
                .flatten(),
            parameter: e.parameter.map(Val::hex_u16),
            parameter_note: e.parameter.and_then(name_of),
            allowed: set.allowed_ident.clone(),
            bytes: set.entry_type.bytes(),
        }
    })
}

/// For each set of `g` whose value each kind of PROFINET module writes its
/// own of: every module that carries it, with its value.
fn module_values(ir: &Ir, g: &MappingGroup) -> Vec<ModuleValues> {
    let Some(profinet) = &ir.profinet else {
        return Vec::new();
    };
    g.sets
        .iter()
        .filter_map(|set| Some((set, profinet.module_values(set.key)?)))
        .map(|(set, values)| ModuleValues {
            name: Ident::of(&[if values.changeable {
                "module_default"
            } else {
                "fixed"
            }])
            .tagged(set.key.first),
            doc: Doc::plain(if values.changeable {
                format!(
                    "The default of \"{}\" each PROFINET module writes, by its ident number: \
                     the user may change it.",
                    set.entries[0].name.en
                )
            } else {
                format!(
                    "The value of \"{}\" each PROFINET module fixes, by its ident number: the \
                     module writes it; the user cannot change it.",
                    set.entries[0].name.en
                )
            }),
            modules: values
                .modules
                .iter()
                .map(|(ident, _, value)| ModuleValue {
                    ident: ident.tagged("ident"),
                    value: *value,
                })
                .collect(),
        })
        .collect()
}
