//! `[profinet.fail_safe_values]`: a settings record whose copy in every
//! module ends with one value per output PZD item of the module, of the
//! item's width, 0 by default, any value allowed (ABB FENA's record 1).

use super::{text, Recognised};
use crate::device::pn::Record;
use crate::device::{Allowed, Field, Text, Value};
use crate::import::toml_out::{list, TomlOut};
use crate::ir::profinet::ModuleKind;

/// The names of each kind of module's fail-safe values, and the copy of
/// the record with the most settings, which are its entries before them.
pub(super) struct FailSafe<'a> {
    names: Vec<(ModuleKind, Vec<&'a Text>)>,
    pub record: &'a Record,
    pub settings: &'a [Field],
}

/// The fail-safe values the record of `index` ends with in every module,
/// when it does and some setting precedes them.
pub(super) fn of<'a>(modules: &[Recognised<'a>], index: u32) -> Option<FailSafe<'a>> {
    let mut names: Vec<(ModuleKind, Vec<&Text>)> = Vec::new();
    let mut most: Option<(&Record, &[Field])> = None;
    for m in modules {
        let copy = m.data.records.iter().find(|r| r.index == index)?;
        let tail = tail(m, &copy.data.fields)?;
        let settings = &copy.data.fields[..copy.data.fields.len() - tail.len()];
        if most.is_none_or(|(_, known)| known.len() < settings.len()) {
            most = Some((copy, settings));
        }
        let these: Vec<&Text> = tail.iter().map(|f| &f.name).collect();
        match names.iter_mut().find(|(kind, _)| *kind == m.kind) {
            // A PZD module's names are the first of the longest's.
            Some((_, known)) => {
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
            }
            None => names.push((m.kind, these)),
        }
    }
    let (record, settings) = most.filter(|(_, settings)| !settings.is_empty())?;
    Some(FailSafe {
        names,
        record,
        settings,
    })
}

/// The fields a module's copy ends with that are fail-safe values of its
/// output items, when it ends with one for each.
fn tail<'f>(m: &Recognised, fields: &'f [Field]) -> Option<&'f [Field]> {
    let widths = item_bytes(m);
    let tail = fields.get(fields.len().checked_sub(widths.len())?..)?;
    tail.iter()
        .zip(&widths)
        .all(|(f, &bytes)| is_fail_safe(f, bytes))
        .then_some(tail)
}

/// The bytes of each output PZD item of a module, as lowering makes them.
fn item_bytes(m: &Recognised) -> Vec<u32> {
    match m.kind {
        ModuleKind::Pzd => vec![2; usize::from(m.layout.pzd_words)],
        ModuleKind::StandardTelegram1 => vec![2, 2],
        ModuleKind::StandardTelegram2 => vec![2, 4, 2],
    }
}

/// A value gsdc writes as a fail-safe value of `bytes`: of that width,
/// default 0, any value allowed, changeable, visible, nothing else said.
fn is_fail_safe(field: &Field, bytes: u32) -> bool {
    let (data_type, max) = match bytes {
        4 => ("Unsigned32", i128::from(u32::MAX)),
        _ => ("Unsigned16", i128::from(u16::MAX)),
    };
    let full_range = match &field.allowed {
        Allowed::Any => true,
        Allowed::Ranges(ranges) => {
            matches!(ranges.as_slice(), [(Value::Int(0), Value::Int(m))] if *m == max)
        }
    };
    field.data_type == data_type
        && field.bits.is_none()
        && matches!(field.default, None | Some(Value::Int(0)))
        && full_range
        && field.choices.is_empty()
        && field.changeable
        && field.visible
        && field.attributes.is_empty()
}

impl FailSafe<'_> {
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
