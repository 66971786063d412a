//! `[[profinet.access_point_records]]` and `[[profinet.port_records]]`: the
//! parameter records of a GSDML file's device access point's own submodule
//! and of its ports (SEW's MOVI-C's record 8200, and 9000 to 9002 of each
//! port), and a later access point's where not the first's
//! (`[[profinet.daps]] access_point_records`, `port_records`: MOVI-C's V2.0
//! moves the ports' records to its own submodule). The description gives
//! an access point one list for all its ports: the ports' records are
//! imported where each of its ports has the same; else, and each record
//! the description cannot say (an index PROFINET keeps, a value of another
//! type, a constant that is not 0), left out (W600) with why.

use super::{fits, text};
use crate::device::pn::{Dap, Record, Submodule, SubmoduleKind};
use crate::device::{Allowed, AttributeValue, Field, Value, VALUE_ITEM_HELP};
use crate::import::toml_out::{list, TomlOut};
use crate::import::Notes;
use std::collections::BTreeSet;

/// Keys of a description table, each with its value written already.
type Keys = Vec<(&'static str, String)>;

/// A record as its description table says it: its keys, then each
/// value's. Two records that say the same are the same to the description.
#[derive(PartialEq)]
struct Said {
    keys: Keys,
    values: Vec<Keys>,
}

/// The records the description gives an access point's own submodule and
/// its ports; a later access point's `None` where they are the first's.
pub(super) struct OwnRecords {
    access_point: Option<Vec<Said>>,
    ports: Option<Vec<Said>>,
}

impl OwnRecords {
    /// The first access point's, as `[[profinet.access_point_records]]` and
    /// `[[profinet.port_records]]`.
    pub fn write(&self, out: &mut TomlOut) {
        self.write_under(out, "profinet");
    }

    /// A later access point's, under its `[[profinet.daps]]` entry just
    /// written: a list of none as `access_point_records = []`, then each
    /// record as a table of the entry's.
    pub fn write_later(&self, out: &mut TomlOut) {
        for (key, records) in self.lists() {
            if records.is_some_and(Vec::is_empty) {
                out.key(key, "[]");
            }
        }
        self.write_under(out, "profinet.daps");
    }

    fn lists(&self) -> [(&'static str, Option<&Vec<Said>>); 2] {
        [
            ("access_point_records", self.access_point.as_ref()),
            ("port_records", self.ports.as_ref()),
        ]
    }

    fn write_under(&self, out: &mut TomlOut, parent: &str) {
        for (key, records) in self.lists() {
            let table = format!("{parent}.{key}");
            write_records(out, &table, records.map_or(&[][..], |r| &r[..]));
        }
    }

    /// These records, a later access point's, where not `first`'s.
    pub fn unlike(self, first: &OwnRecords) -> OwnRecords {
        OwnRecords {
            access_point: self
                .access_point
                .filter(|l| Some(l) != first.access_point.as_ref()),
            ports: self.ports.filter(|l| Some(l) != first.ports.as_ref()),
        }
    }
}

/// Each of `records` as an item of the array of tables `table`.
fn write_records(out: &mut TomlOut, table: &str, records: &[Said]) {
    for record in records {
        out.array_item(table);
        for (key, value) in &record.keys {
            out.key(key, value);
        }
        for value in &record.values {
            out.array_item(&format!("{table}.values"));
            for (key, v) in value {
                out.key(key, v);
            }
        }
    }
}

/// The records of a safety module's submodule besides its F-parameters.
pub(super) struct SafetyRecords(Vec<Said>);

impl SafetyRecords {
    /// As `[[profinet.safety_modules.records]]` of the entry just written.
    pub fn write(&self, out: &mut TomlOut) {
        write_records(out, "profinet.safety_modules.records", &self.0);
    }
}

/// The records of a safety module's submodule besides its F-parameters
/// that the description can say; each other left out with why.
pub(super) fn safety_records(submodule: &Submodule, notes: &mut Notes) -> SafetyRecords {
    SafetyRecords(shared(&[submodule], "safety module", notes))
}

/// The records of `dap`'s own submodule and of its ports.
pub(super) fn own_records(dap: &Dap, notes: &mut Notes) -> OwnRecords {
    let of_kind = |kind: SubmoduleKind| -> Vec<&Submodule> {
        let submodules = dap.item.submodules.iter();
        submodules.filter(|s| s.kind == kind).collect()
    };
    // A device access point's own submodule is its one virtual submodule.
    OwnRecords {
        access_point: Some(shared(
            &of_kind(SubmoduleKind::Virtual),
            "device access point",
            notes,
        )),
        ports: Some(shared(&of_kind(SubmoduleKind::Port), "port", notes)),
    }
}

/// The records each of `submodules` has, when each has the same ones:
/// those the description can say, each other left out (W600) with why.
/// Where the submodules differ, none: every record of every one of them
/// left out, each index once.
fn shared(submodules: &[&Submodule], whose: &str, notes: &mut Notes) -> Vec<Said> {
    let Some(first) = submodules.first() else {
        return Vec::new();
    };
    let said: Vec<Result<Said, &str>> = first.records.iter().map(said).collect();
    // Alike where the description says them alike; two it cannot say,
    // where they have one index (each is left out below).
    let alike =
        |r: &Record, (first, said): (&Record, &Result<Said, &str>)| match (self::said(r), said) {
            (Ok(r), Ok(said)) => r == *said,
            (Err(_), Err(_)) => r.index == first.index,
            _ => false,
        };
    let same = submodules[1..].iter().all(|s| {
        s.records.len() == said.len()
            && s.records
                .iter()
                .zip(first.records.iter().zip(&said))
                .all(|(r, first)| alike(r, first))
    });
    let subject = |record: &Record| format!("record {} of the {whose}", record.index);
    if !same {
        let why = format!("not every {whose} has the same records, which the description gives each {whose} alike");
        let mut told = BTreeSet::new();
        for record in submodules.iter().flat_map(|s| &s.records) {
            if told.insert(record.index) {
                notes.unsaid(&subject(record), &record.place, &why);
            }
        }
        return Vec::new();
    }
    let mut imported = Vec::new();
    for (record, said) in first.records.iter().zip(said) {
        match said {
            Ok(said) => imported.push(said),
            Err(why) => notes.unsaid(&subject(record), &record.place, why),
        }
    }
    imported
}

/// The record as the description says it, or why it cannot.
fn said(record: &Record) -> Result<Said, &'static str> {
    if record.index > 0x7FFF {
        return Err("its index is PROFINET's own (0x8000 and up), not a user-specific one");
    }
    if !record.attributes.iter().all(|a| fits(a, &[])) {
        return Err("it has an attribute the description has no key for");
    }
    if record
        .data
        .consts
        .iter()
        .any(|c| c.bytes.iter().any(|&b| b != 0))
    {
        return Err("it has a constant other than 0, which the description's records do not hold");
    }
    let name = record
        .name
        .as_ref()
        .filter(|n| !n.primary.is_empty())
        .ok_or("it has no name")?;
    let mut values = Vec::new();
    let mut extent = 0;
    for field in &record.data.fields {
        let (keys, bytes) = value(field)?;
        extent = extent.max(field.byte_offset + bytes);
        values.push(keys);
    }
    if values.is_empty() {
        return Err("it has no value, which a description's record has");
    }
    if record.data.length != Some(extent) {
        return Err("its Length is not as far as its values reach, which the description's records are long");
    }
    Ok(Said {
        keys: vec![("index", record.index.to_string()), ("name", text(name))],
        values,
    })
}

/// A value's keys, and the bytes it reaches from its offset.
fn value(field: &Field) -> Result<(Keys, u32), &'static str> {
    // Its attributes the description has keys for are the Field's own;
    // its ValueItem's help is its `help`.
    if !field
        .attributes
        .iter()
        .all(|a| &*a.name == VALUE_ITEM_HELP || fits(a, &[]))
    {
        return Err("a value of it has an attribute the description has no key for");
    }
    let (kind, most, bytes) = match (&*field.data_type, field.bits) {
        ("Bit", Some(b)) => (("bits", b.offset.to_string()), 1, 1),
        ("BitArea", Some(b)) if b.length >= 1 && b.offset + b.length <= 8 => {
            let last = b.offset + b.length - 1;
            let most = (1 << b.length) - 1;
            (("bits", format!("[{}, {last}]", b.offset)), most, 1)
        }
        ("Unsigned8", None) => (("type", "\"Unsigned8\"".into()), 0xFF, 1),
        ("Unsigned16", None) => (("type", "\"Unsigned16\"".into()), 0xFFFF, 2),
        ("Unsigned32", None) => (("type", "\"Unsigned32\"".into()), 0xFFFF_FFFF, 4),
        _ => return Err("a value of it is not a Bit, a BitArea or an Unsigned8, 16 or 32, the description's record values"),
    };
    if field.name.primary.is_empty() {
        return Err("a value of it has no name");
    }
    let Some(Value::Int(default)) = field.default else {
        return Err("a value of it has no whole number for its default");
    };
    let mut keys = vec![
        ("name", text(&field.name)),
        ("offset", field.byte_offset.to_string()),
        kind,
        ("default", default.to_string()),
    ];
    keys.extend(holds(field, most)?);
    let help = field
        .attributes
        .iter()
        .find(|a| &*a.name == VALUE_ITEM_HELP);
    if let Some(help) = help {
        let AttributeValue::Text(help) = &help.value else {
            return Err("a value of it has a help that is not a text");
        };
        keys.push(("help", text(help)));
    }
    if !field.changeable {
        keys.push(("changeable", "false".into()));
    }
    if !field.visible {
        keys.push(("visible", "false".into()));
    }
    Ok((keys, bytes))
}

/// What a value holds, as the description says it: its choices, whose
/// values must be exactly those it allows; else its range, when less than
/// its type's values. Without AllowedValues a value with choices allows
/// those (as gsdc diff and the other imports read a ValueItemTarget), one
/// without allows every value of its type.
fn holds(field: &Field, most: i128) -> Result<Option<(&'static str, String)>, &'static str> {
    let allowed = match &field.allowed {
        Allowed::Any if !field.choices.is_empty() => None,
        Allowed::Any => Some(vec![(0, most)]),
        Allowed::Ranges(ranges) => {
            let ints = ranges.iter().map(|(low, high)| match (low, high) {
                (Value::Int(low), Value::Int(high)) => Ok((*low, *high)),
                _ => Err("a value of it allows values that are not whole numbers"),
            });
            Some(ints.collect::<Result<Vec<_>, _>>()?)
        }
    };
    if field.choices.is_empty() {
        return match *allowed.as_deref().unwrap_or_default() {
            [(0, high)] if high == most => Ok(None),
            [(low, high)] if 0 <= low && low <= high && high <= most => {
                Ok(Some(("range", format!("[{low}, {high}]"))))
            }
            _ => Err("a value of it allows more than one range of values without a text for each, which the description cannot say"),
        };
    }
    let mut choices = Vec::new();
    let mut values = Vec::new();
    for choice in &field.choices {
        let Value::Int(value) = choice.value else {
            return Err("a choice of a value of it is not a whole number");
        };
        values.push(value);
        choices.push(format!(
            "{{ value = {value}, text = {} }}",
            text(&choice.text)
        ));
    }
    values.sort_unstable();
    values.dedup();
    let Some(allowed) = allowed else {
        return match values.iter().all(|v| (0..=most).contains(v)) {
            true => Ok(Some(("choices", list(choices)))),
            false => Err("a choice of a value of it is not a value of its type"),
        };
    };
    let allows = |v: i128| allowed.iter().any(|&(low, high)| (low..=high).contains(&v));
    let count: i128 = allowed.iter().map(|(low, high)| high - low + 1).sum();
    if !values.iter().all(|&v| allows(v)) || i128::try_from(values.len()) != Ok(count) {
        return Err("a value of it allows other values than its choices, which the description's choices are");
    }
    Ok(Some(("choices", list(choices))))
}
