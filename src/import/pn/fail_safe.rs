//! `[profinet.fail_safe_values]`: a settings record whose copy in every
//! module ends with one value per output PZD item of the module, of the
//! item's width, 0 by default, any value allowed (ABB FENA's record 1).

use super::{text, Recognised};
use crate::device::pn::Record;
use crate::device::{Allowed, Field, Text, Value};
use crate::import::toml_out::{list, TomlOut};
use crate::ir::profinet::ModuleKind;

/// The names of each kind of module's fail-safe values, and each module's
/// copy of the record with its settings, the entries before them.
pub(super) struct FailSafe<'a> {
    names: Vec<(ModuleKind, Vec<&'a Text>)>,
    copies: Vec<(&'a Record, &'a [Field])>,
}

/// The fail-safe values the record of `index` ends with in every module:
/// only when the copies differ, as values sized to each module's output
/// items make them, which settings alone could not rebuild (a device whose
/// copies are all alike is its settings), and some setting precedes them.
pub(super) fn of<'a>(modules: &[Recognised<'a>], index: u32) -> Option<FailSafe<'a>> {
    let mut names: Vec<(ModuleKind, Vec<&Text>)> = Vec::new();
    let mut copies = Vec::new();
    for m in modules {
        let copy = m.data.records.iter().find(|r| r.index == index)?;
        let tail = tail(m, &copy.data.fields)?;
        copies.push((
            copy,
            &copy.data.fields[..copy.data.fields.len() - tail.len()],
        ));
        add_names(&mut names, m.kind, tail.iter().map(|f| &f.name).collect())?;
    }
    let alike = copies
        .windows(2)
        .all(|pair| same_names(&pair[0].0.data.fields, &pair[1].0.data.fields));
    let no_settings = copies.iter().all(|(_, settings)| settings.is_empty());
    (!alike && !no_settings).then_some(FailSafe { names, copies })
}

/// A module's names for its kind: a PZD module's are the first of the
/// longest's, each telegram's the same in each of its modules.
fn add_names<'a>(
    names: &mut Vec<(ModuleKind, Vec<&'a Text>)>,
    kind: ModuleKind,
    these: Vec<&'a Text>,
) -> Option<()> {
    let Some((_, known)) = names.iter_mut().find(|(k, _)| *k == kind) else {
        names.push((kind, these));
        return Some(());
    };
    let (short, long) = match known.len() < these.len() {
        true => (&known[..], &these[..]),
        false => (&these[..], &known[..]),
    };
    if long[..short.len()] != *short {
        return None;
    }
    if known.len() < these.len() {
        *known = these;
    }
    Some(())
}

fn same_names(a: &[Field], b: &[Field]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.name == y.name)
}

/// The fields a module's copy ends with that are fail-safe values of its
/// output items after the PKW channel, when it ends with one for each.
fn tail<'f>(m: &Recognised, fields: &'f [Field]) -> Option<&'f [Field]> {
    let output = &m.data.io.output.as_ref()?.items;
    let items = output.get(usize::from(m.layout.pkw_words())..)?;
    let tail = fields.get(fields.len().checked_sub(items.len())?..)?;
    tail.iter()
        .zip(items)
        .all(|(f, item)| item.length.is_none() && is_fail_safe(f, &item.data_type))
        .then_some(tail)
}

/// A value gsdc writes as the fail-safe value of an item of `data_type`:
/// of that type, default 0, any value allowed, changeable, visible, nothing
/// else said.
fn is_fail_safe(field: &Field, data_type: &str) -> bool {
    let max = match data_type {
        "Unsigned16" => i128::from(u16::MAX),
        "Unsigned32" => i128::from(u32::MAX),
        _ => return false,
    };
    let full_range = match &field.allowed {
        Allowed::Any => true,
        Allowed::Ranges(ranges) => {
            matches!(ranges.as_slice(), [(Value::Int(0), Value::Int(m))] if *m == max)
        }
    };
    field.data_type == data_type
        && field.bits.is_none()
        && field.default == Some(Value::Int(0))
        && full_range
        && field.choices.is_empty()
        && field.changeable
        && field.visible
        && field.attributes.is_empty()
}

impl<'a> FailSafe<'a> {
    /// The copy with the most settings: the description's settings.
    pub fn most_settings(&self) -> &'a Record {
        let most = self
            .copies
            .iter()
            .max_by_key(|(_, settings)| settings.len());
        most.map(|(record, _)| *record)
            .expect("a record with fail-safe values has a copy in each module")
    }

    /// A copy's settings, when it is a copy of this record.
    pub fn settings_of(&self, record: &Record) -> Option<&'a [Field]> {
        let copy = self.copies.iter().find(|(r, _)| std::ptr::eq(*r, record));
        copy.map(|(_, settings)| *settings)
    }

    /// `[profinet.fail_safe_values]`, each kind of module's names.
    pub fn write(&self, out: &mut TomlOut) {
        out.table("profinet.fail_safe_values");
        for (key, kind) in super::MODULE_KIND_KEYS {
            let Some((_, names)) = self.names.iter().find(|(k, _)| *k == kind) else {
                continue;
            };
            out.key(key, list(names.iter().map(|n| text(n))));
        }
    }
}
