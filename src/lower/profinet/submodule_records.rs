//! `[[profinet.access_point_records]]` and `[[profinet.port_records]]`: the
//! card's own parameter records of the device access point's submodule and
//! of each port (SEW's MOVI-C: an alarm setting in record 8200 of the
//! access point, port statistics in records 9000 to 9002 of each port).
//! Their values are parameters as `[[profibus.parameters]]` are, with
//! texts in every language and up to 32 bits.

use crate::description as raw;
use crate::diag::Diagnostic;
use crate::ir::profinet::{Dap, RecordValue, RecordValueType, SubmoduleRecord, TextRef, ValueItem};
use crate::lower::checks::Checker;
use crate::lower::param_values::{self, Holds, Stored, Taken};
use std::collections::BTreeSet;
use toml::Spanned;

/// Whose records: where the description gives them, and the tag of their
/// GSDML IDs.
struct Whose {
    key: String,
    tag: String,
}

impl Whose {
    /// The access point's own submodule's, or a port's, of the first DAP
    /// (`[profinet]`'s: tags `DAP_RECORD`, `PORT_RECORD`) or of
    /// `profinet.daps[n]` (DAP 2's: `DAP_2_RECORD`, `DAP_2_PORT_RECORD`).
    fn dap(port: bool, later: Option<usize>) -> Whose {
        let list = if port {
            "port_records"
        } else {
            "access_point_records"
        };
        let (key, dap) = match later {
            None => (format!("profinet.{list}"), "DAP".to_string()),
            Some(n) => (
                format!("profinet.daps[{n}].{list}"),
                format!("DAP_{}", n + 2),
            ),
        };
        let tag = match (port, later) {
            (true, None) => "PORT_RECORD".to_string(),
            (true, Some(_)) => format!("{dap}_PORT_RECORD"),
            (false, _) => format!("{dap}_RECORD"),
        };
        Whose { key, tag }
    }
}

/// The records of `profinet.safety_modules[index]`'s submodule besides its
/// F-parameters (SEW's MOVI-C: record 8200, its diagnosis alarms), tagged
/// `SAFETY_1_RECORD`.
pub fn lower_safety(
    cx: &mut Checker,
    given: &[Spanned<raw::SubmoduleRecord>],
    index: usize,
) -> Option<Vec<SubmoduleRecord>> {
    let whose = Whose {
        key: format!("profinet.safety_modules[{index}].records"),
        tag: format!("SAFETY_{}_RECORD", index + 1),
    };
    lower(cx, given, &whose)
}

/// Every list of records and each DAP's two (`daps` as lowered from `p`,
/// the first first): the first's own submodule's and ports', then each
/// list a `[[profinet.daps]]` entry gives of its own; an entry without
/// one takes the first's.
pub fn lower_lists(
    cx: &mut Checker,
    p: &raw::Profinet,
    daps: &mut [Dap],
) -> Option<Vec<Vec<SubmoduleRecord>>> {
    let first = [(&p.access_point_records, false), (&p.port_records, true)]
        .map(|(given, port)| lower(cx, given, &Whose::dap(port, None)));
    let mut lists = Vec::new();
    let mut complete = true;
    for list in first {
        complete &= list.is_some();
        lists.push(list.unwrap_or_default());
    }
    for (n, (given, dap)) in p.daps.iter().zip(daps.iter_mut().skip(1)).enumerate() {
        let given = given.get_ref();
        for (own, port) in [
            (&given.access_point_records, false),
            (&given.port_records, true),
        ] {
            let Some(own) = own else { continue };
            let whose = Whose::dap(port, Some(n));
            complete &= lower(cx, own, &whose).is_some_and(|list| {
                let place = if port {
                    &mut dap.port_records
                } else {
                    &mut dap.access_point_records
                };
                *place = lists.len();
                lists.push(list);
                true
            });
        }
    }
    if complete {
        alike_under_one_ident(cx, p, daps, &lists);
    }
    complete.then_some(lists)
}

/// The most a user-specific record index is: PROFINET keeps 0x8000 and up
/// for its own records (IEC 61158-6-10, the I&M records at 0xAFF0 among
/// them).
const LAST_USER_INDEX: u16 = 0x7FFF;

/// The record's index, a user-specific one (E101).
fn user_specific(cx: &mut Checker, index: &Spanned<u16>) -> Option<u16> {
    let value = *index.get_ref();
    if value <= LAST_USER_INDEX {
        return Some(value);
    }
    cx.push(
        Diagnostic::error("E101", format!("record index 0x{value:04X} is one of PROFINET's own"))
            .at(index.span())
            .label("not a user-specific index")
            .help("a card's own records have user-specific indexes, 0 to 0x7FFF; PROFINET keeps 0x8000 and up for its own records (the I&M records at 0xAFF0 among them)"),
    );
    None
}

/// E162: device access points of one ident number, which the device
/// cannot tell apart, give each record index of their own submodules, and
/// of their ports, alike (the device reads a record the controller of any
/// of them writes). Reported at the later DAP's `ident`.
fn alike_under_one_ident(
    cx: &mut Checker,
    p: &raw::Profinet,
    daps: &[Dap],
    lists: &[Vec<SubmoduleRecord>],
) {
    for (index, (dap, given)) in daps[1..].iter().zip(&p.daps).enumerate() {
        let earlier = daps[..=index].iter().filter(|d| d.ident == dap.ident);
        let kinds = |d: &Dap| [(d.access_point_records, false), (d.port_records, true)];
        let clash = earlier.flat_map(kinds).find_map(|(list, port)| {
            let own = if port {
                dap.port_records
            } else {
                dap.access_point_records
            };
            lists[list].iter().find_map(|r| {
                lists[own]
                    .iter()
                    .find(|o| o.index == r.index && !o.decoded_alike(r))
                    .map(|o| (o.index, port))
            })
        });
        let Some((record, port)) = clash else {
            continue;
        };
        let whose = if port {
            "its ports'"
        } else {
            "its own submodule's"
        };
        cx.push(
            Diagnostic::error(
                "E162",
                format!(
                    "device access point {} (profinet.daps[{index}]) has ident number 0x{:08X} as an earlier one, and {whose} record {record} is not that one's",
                    index + 2,
                    dap.ident
                ),
            )
            .at(given.get_ref().ident.span())
            .label("another record under one ident number")
            .help("the device cannot tell device access points of one ident number apart, and reads a record any of them writes: give the record alike (its length and each value's place, type, default and range), or this one an ident number of its own"),
        );
    }
}

/// Each record: E101 for an index outside the user-specific ones, E105
/// for one given twice, and its values checked.
fn lower(
    cx: &mut Checker,
    given: &[Spanned<raw::SubmoduleRecord>],
    whose: &Whose,
) -> Option<Vec<SubmoduleRecord>> {
    let mut seen = BTreeSet::new();
    let mut records = Vec::new();
    for (place, record) in given.iter().enumerate() {
        let at = format!("{}[{place}]", whose.key);
        let record = record.get_ref();
        let index = user_specific(cx, &record.index);
        if let Some(index) = index.filter(|i| !seen.insert(*i)) {
            cx.duplicate(format!("record {index}"), record.index.span());
        }
        records.extend(index.and_then(|index| one(cx, record, index, (whose, &at))));
    }
    (records.len() == given.len()).then_some(records)
}

fn one(
    cx: &mut Checker,
    record: &raw::SubmoduleRecord,
    index: u16,
    (whose, at): (&Whose, &str),
) -> Option<SubmoduleRecord> {
    let id = format!("{}_{index}", whose.tag);
    let name = TextRef::new(
        format!("IDT_{id}"),
        cx.text(&record.name, None, &format!("{at}.name")),
    );
    let given = record.values.get_ref();
    if given.is_empty() {
        cx.non_empty("", record.values.span(), "record's values");
        return None;
    }
    let mut taken = Taken::default();
    let mut values = Vec::new();
    for (place, value) in given.iter().enumerate() {
        let value_id = format!("{id}_VALUE_{}", place + 1);
        let Some(lowered) = record_value(cx, value.get_ref(), &value_id) else {
            continue;
        };
        let offset = usize::from(lowered.offset);
        let masks = lowered.data_type.masks();
        let span = value.get_ref().offset.span();
        taken.take(cx, &lowered.text.text.en, (offset, &masks), span);
        values.push(lowered);
    }
    let length = values
        .iter()
        .map(|v| v.offset + v.data_type.bytes())
        .max()
        .unwrap_or(0);
    (values.len() == given.len()).then_some(SubmoduleRecord {
        index,
        name,
        length,
        values,
    })
}

/// One value: its type or its bits (E175 for both), what it holds, its
/// default, its help; `id` the tag of its TextId (`IDT_<id>`), its
/// ValueItem's ID and its choices' and help's TextIds.
fn record_value(cx: &mut Checker, v: &raw::RecordValue, id: &str) -> Option<RecordValue> {
    let text = cx.text(&v.name, None, "record value's name");
    let name = text.en.clone();
    let given = (v.data_type.as_ref(), v.bits.as_ref());
    let data_type = match param_values::stored(cx, &name, given)? {
        Stored::Bits { first, last } => RecordValueType::Bits { first, last },
        Stored::Type(raw::RecordValueType::Unsigned8) => RecordValueType::Unsigned8,
        Stored::Type(raw::RecordValueType::Unsigned32) => RecordValueType::Unsigned32,
        Stored::Type(raw::RecordValueType::Unsigned16) | Stored::Unsaid => {
            RecordValueType::Unsigned16
        }
    };
    // Its bytes within a record of at most 65535, the most a Length holds
    // here (the IR's, and the layouts', u16).
    let last_offset = i64::from(u16::MAX - data_type.bytes());
    let offset: u16 = cx.spanned_in_range(&v.offset, 0, last_offset, "the value's offset")?;
    let most = i64::from(data_type.max());
    let choices = (v.range.as_ref(), v.choices.as_ref());
    let holds = param_values::holds(cx, &name, choices, most, None)?;
    let default = param_values::default(cx, &name, &v.default, (most, &holds))?;
    // Each within 0..=most, a u32's values: checked by `holds` and `default`.
    let (min, max, assignments) = match holds {
        Holds::Range(min, max) => (min as u32, max as u32, Vec::new()),
        Holds::Choices(set) => {
            let values = set.choices.iter().map(|c| c.value);
            let (min, max) = (values.clone().min()?, values.max()?);
            let assignments = set
                .choices
                .into_iter()
                .map(|c| {
                    let text = TextRef::new(format!("IDT_{id}_CHOICE_{}", c.value), c.text);
                    (c.value, text)
                })
                .collect();
            (min as u32, max as u32, assignments)
        }
    };
    let help = v.help.as_ref().map(|h| {
        let text = cx.text_of_lines_allowed(h, "record value's help");
        TextRef::new(format!("IDT_{id}_HELP"), text)
    });
    let value_item = (help.is_some() || !assignments.is_empty()).then(|| ValueItem {
        id: format!("IDV_{id}"),
        help,
        assignments,
    });
    Some(RecordValue {
        text: TextRef::new(format!("IDT_{id}"), text),
        offset,
        data_type,
        default: default as u32,
        min,
        max,
        value_item,
        changeable: v.changeable.as_ref().is_none_or(|c| *c.get_ref()),
        visible: v.visible.as_ref().is_none_or(|c| *c.get_ref()),
    })
}
