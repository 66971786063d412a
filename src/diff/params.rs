//! Parameter data compared: a slave's or module's part of User_Prm_Data,
//! a GSDML record, a GSDML diagnosis structure.
//!
//! A parameter is the bits it takes at its byte offset, not its name: the
//! master sends bytes, and the device reads them by place. Fields at the
//! same place are the same parameter (their name is a text); a field whose
//! name moved to another place is a parameter moved. Bits that no field
//! covers are fixed (the constants, zero where none is given), and old
//! projects send them as the old file fixed them.

use super::{judge, quoted, Change, Changes, Class, Kind};
use crate::device::{Allowed, Bits, Field, ParameterData, Value};

/// What a block of parameter data is.
pub struct Scope<'a> {
    /// `User_Prm_Data`, `User_Prm_Data of module "PPO1"`, `record 1 of ...`.
    pub name: &'a str,
    pub kind: Kind,
    /// The master sends it (User_Prm_Data, records); false for what the
    /// device sends (a diagnosis structure), where defaults and
    /// changeability mean nothing.
    pub sent: bool,
}

/// The largest block laid out bit by bit: records are at most 64 KiB.
const MAX_IMAGE: u32 = 1 << 16;

pub fn compare(scope: &Scope, old: &ParameterData, new: &ParameterData, out: &mut Changes) {
    if old == new {
        return;
    }
    let (old_len, new_len) = (old.len(), new.len());
    let beyond = |fields: &[Field], end: u32| -> Vec<String> {
        fields
            .iter()
            .filter(|f| f.byte_offset >= end)
            .map(|f| f.name.to_string())
            .collect()
    };
    if old_len != new_len {
        let mut change = format!("{old_len} → {new_len} bytes");
        let added = beyond(&new.fields, old_len);
        let gone = beyond(&old.fields, new_len);
        if !added.is_empty() {
            change += &format!(", adding {}", added.join(", "));
        }
        if !gone.is_empty() {
            change += &format!(", dropping {}", gone.join(", "));
        }
        let why = match scope.sent {
            true => "the master sends as many bytes as the old file says; the device expects as many as the new one and refuses the others",
            false => "the device now sends a length that projects configured with the old file do not expect",
        };
        out.push(Change::new(Class::Breaking, scope.kind, scope.name, change).why(why));
    }
    let pairing = super::pairing::pair(&old.fields, &new.fields, |f| (f.byte_offset, f.bits))
        .then(|f| (!f.name.primary.is_empty()).then(|| f.name.clone()));
    // A name that left its place for another's is a parameter moved, though
    // both places still hold one (two parameters that traded places).
    let name_elsewhere = |fields: &[Field], f: &Field| {
        fields
            .iter()
            .find(|g| g.name == f.name && (g.byte_offset, g.bits) != (f.byte_offset, f.bits))
            .cloned()
    };
    for (a, b) in &pairing.both {
        if a.name != b.name && !b.name.primary.is_empty() {
            if let Some(was) = name_elsewhere(&old.fields, b) {
                out.push(moved(scope, &was, b));
                continue;
            }
        }
        field(scope, a, b, out);
    }
    for (a, b) in &pairing.rekeyed {
        out.push(moved(scope, a, b));
        field(scope, a, b, out);
    }
    let old_image = Image::of(old);
    for b in pairing.added.iter().filter(|f| f.byte_offset < old_len) {
        let over: Vec<String> = pairing
            .gone
            .iter()
            .filter(|g| overlaps(g, b))
            .map(|g| format!("{} {}", g.name, place(g)))
            .collect();
        let change = match over.is_empty() {
            true => added_field(scope, b, &old_image),
            false => Change::new(
                Class::Breaking,
                scope.kind,
                subject(scope, b),
                format!("takes the place of {}", over.join(", ")),
            )
            .why("projects configured with the old file send the old parameter's value there"),
        };
        out.push(change.at(None, Some(&b.place)));
    }
    for a in pairing.gone.iter().filter(|f| f.byte_offset < new_len) {
        if pairing.added.iter().any(|b| overlaps(a, b)) {
            continue; // reported as the new parameter taking its place
        }
        out.push(
            Change::new(Class::Breaking, scope.kind, subject(scope, a), "removed")
                .why(match scope.sent {
                    true => "projects configured with the old file still send a value of their choice there; the device now reads those bits as fixed",
                    false => "projects configured with the old file read a value there that the device no longer sends",
                })
                .at(Some(&a.place), None),
        );
    }
    fixed_bits(scope, &old_image, &Image::of(new), out);
}

/// The parameter `a` of the old file is `b` at another place.
fn moved(scope: &Scope, a: &Field, b: &Field) -> Change {
    Change::new(
        Class::Breaking,
        scope.kind,
        subject(scope, b),
        format!("moved from {} to {}", place(a), place(b)),
    )
    .why(match scope.sent {
        true => "projects configured with the old file send it at its old place: the device reads other bits there",
        false => "projects configured with the old file read it at its old place",
    })
    .at(Some(&a.place), Some(&b.place))
}

/// What changed of one parameter at one place.
fn field(scope: &Scope, a: &Field, b: &Field, out: &mut Changes) {
    if a == b {
        return;
    }
    let subject = subject(scope, b);
    let at = (Some(&a.place), Some(&b.place));
    if a.data_type != b.data_type || a.length != b.length {
        let show = |f: &Field| match f.length {
            Some(n) => format!("{} ({n} bytes)", f.data_type),
            None => f.data_type.clone(),
        };
        out.push(
            Change::new(
                Class::Breaking,
                scope.kind,
                &subject,
                format!("type {} → {}", show(a), show(b)),
            )
            .why("old projects send or read values of the old type at this place")
            .at(at.0, at.1),
        );
    }
    out.text(&subject, Some(&a.name), Some(&b.name), at);
    if scope.sent {
        values(scope, &subject, a, b, out);
    }
    let pairing = super::pairing::pair(&a.choices, &b.choices, |c| format!("{}", c.value));
    for (x, y) in pairing.both {
        out.text(
            &format!("choice {} of {subject}", x.value),
            Some(&x.text),
            Some(&y.text),
            at,
        );
    }
    for x in pairing.gone {
        out.text(
            &format!("choice {} of {subject}", x.value),
            Some(&x.text),
            None,
            at,
        );
    }
    for y in pairing.added {
        out.text(
            &format!("choice {} of {subject}", y.value),
            None,
            Some(&y.text),
            at,
        );
    }
    if a.visible != b.visible {
        let shown = |v: bool| if v { "shown" } else { "hidden" };
        out.push(
            Change::new(
                Class::Cosmetic,
                Kind::Text,
                &subject,
                format!("{} → {}", shown(a.visible), shown(b.visible)),
            )
            .why("whether the engineering tool shows it; the master sends it either way")
            .at(at.0, at.1),
        );
    }
    judge::attributes(&subject, &a.attributes, &b.attributes, out);
}

/// The allowed values, changeability and default of a parameter the
/// master sends. Projects store each value when they are configured and
/// send it at every startup: a default change reaches new projects only.
/// A value nobody can change is the one value allowed, so that changing a
/// fixed default breaks, as the device acts on the new one.
fn values(scope: &Scope, subject: &str, a: &Field, b: &Field, out: &mut Changes) {
    let at = (Some(&a.place), Some(&b.place));
    let (old, new) = (effective(a), effective(b));
    let shown = |f: &Field| show_allowed(&effective(f));
    let default = |f: &Field| {
        f.default
            .as_ref()
            .map_or("none".to_string(), Value::to_string)
    };
    let push = |out: &mut Changes, class, change: String, why: &str| {
        out.push(
            Change::new(class, scope.kind, subject, change)
                .why(why)
                .at(at.0, at.1),
        );
    };
    match (a.changeable, b.changeable) {
        (true, true) => {
            let narrowed = !covers(&new, &old);
            let widened = !covers(&old, &new);
            let change = format!("allowed {} → {}", shown(a), shown(b));
            if narrowed {
                push(out, Class::Breaking, change, "a project configured with the old file may hold a value the new file no longer allows");
            } else if widened {
                push(out, Class::Compatible, change, "every value old projects may hold is still allowed");
            }
            if a.default != b.default {
                push(
                    out,
                    Class::Compatible,
                    format!("default {} → {}", default(a), default(b)),
                    "a project stores the value when it is configured and sends it at every startup: only new projects get the new default",
                );
            }
        }
        (true, false) if covers(&new, &old) => push(
            out,
            Class::Compatible,
            format!("fixed at {}", default(b)),
            "old projects could hold no other value",
        ),
        (true, false) => push(
            out,
            Class::Breaking,
            format!("fixed at {} (allowed {} before)", default(b), shown(a)),
            "a project configured with the old file may send another value, which the device no longer takes",
        ),
        (false, true) if covers(&new, &old) => push(
            out,
            Class::Compatible,
            format!("changeable, allowed {}", shown(b)),
            "old projects send the old fixed value, which is still allowed",
        ),
        (false, true) => push(
            out,
            Class::Breaking,
            format!("changeable, allowed {} (fixed at {} before)", shown(b), default(a)),
            "projects configured with the old file send the old fixed value, which the new file does not allow",
        ),
        (false, false) if a.default != b.default => push(
            out,
            Class::Breaking,
            format!("fixed value {} → {}", default(a), default(b)),
            "nobody can change it: every project configured with the old file sends the old value, and the device now acts on the new one",
        ),
        (false, false) => {}
    }
}

/// A parameter where the old file has none: old projects send the old
/// fixed bits there.
fn added_field(scope: &Scope, b: &Field, old: &Image) -> Change {
    let sent = old.value_at(b);
    let subject = subject(scope, b);
    match (sent, &b.default) {
        (Some(v), Some(d)) if Value::Int(v) == *d => Change::new(
            Class::Compatible,
            scope.kind,
            subject,
            format!("added, default {d}"),
        )
        .why("projects configured with the old file send its default there (the old file fixed those bits to it)"),
        (sent, _) => Change::new(
            Class::Breaking,
            scope.kind,
            subject,
            format!(
                "added, default {}",
                b.default.as_ref().map_or("none".to_string(), Value::to_string)
            ),
        )
        .why(match sent {
            Some(v) => format!("projects configured with the old file send {v} there, which the device now reads as this parameter"),
            None => "projects configured with the old file send the old fixed bytes there, which the device now reads as this parameter".to_string(),
        }),
    }
}

/// A block laid out: each byte's fixed value and which of its bits are
/// fixed (not under a field).
struct Image {
    bytes: Vec<u8>,
    fixed: Vec<u8>,
}

impl Image {
    fn of(data: &ParameterData) -> Image {
        let len = data.len().max(data.extent()).min(MAX_IMAGE) as usize;
        let mut image = Image {
            bytes: vec![0; len],
            fixed: vec![0xFF; len],
        };
        for c in &data.consts {
            let start = c.byte_offset as usize;
            for (i, &b) in c.bytes.iter().enumerate() {
                if let Some(slot) = image.bytes.get_mut(start + i) {
                    *slot = b;
                }
            }
        }
        for f in &data.fields {
            for (i, mask) in masks(f) {
                if let Some(slot) = image.fixed.get_mut(i) {
                    *slot &= !mask;
                }
            }
        }
        image
    }

    /// The integer a field at its place reads from the fixed bits, big-endian;
    /// `None` beyond the block or for more than 8 bytes.
    fn value_at(&self, f: &Field) -> Option<i128> {
        let masks = masks(f);
        if masks.len() > 8 {
            return None;
        }
        let mut value: i128 = 0;
        for (i, mask) in masks {
            let byte = *self.bytes.get(i)?;
            value =
                (value << mask.count_ones()) | i128::from((byte & mask) >> mask.trailing_zeros());
        }
        Some(value)
    }
}

/// The bytes a field takes and the bits of each.
fn masks(f: &Field) -> Vec<(usize, u8)> {
    let start = f.byte_offset as usize;
    match f.bits {
        Some(Bits { offset, length }) => {
            let high = (u16::from(offset) + u16::from(length)).min(8);
            let mask = ((1u16 << high) - (1u16 << offset.min(8))) as u8;
            vec![(start, mask)]
        }
        None => (start..start + f.size().min(MAX_IMAGE) as usize)
            .map(|i| (i, 0xFF))
            .collect(),
    }
}

fn overlaps(a: &Field, b: &Field) -> bool {
    let mb = masks(b);
    masks(a)
        .iter()
        .any(|(i, m)| mb.iter().any(|(j, n)| i == j && m & n != 0))
}

/// Fixed bits both files fix, that differ: one change per run of bytes.
fn fixed_bits(scope: &Scope, old: &Image, new: &Image, out: &mut Changes) {
    let len = old.bytes.len().min(new.bytes.len());
    let differs = |i: usize| (old.bytes[i] ^ new.bytes[i]) & old.fixed[i] & new.fixed[i] != 0;
    let mut i = 0;
    while i < len {
        if !differs(i) {
            i += 1;
            continue;
        }
        let start = i;
        while i < len && differs(i) {
            i += 1;
        }
        let hex = |bytes: &[u8]| {
            bytes
                .iter()
                .map(|b| format!("0x{b:02X}"))
                .collect::<Vec<_>>()
                .join(",")
        };
        let bytes = match i - start {
            1 => format!("byte {start}"),
            _ => format!("bytes {start}-{}", i - 1),
        };
        out.push(
            Change::new(
                Class::Breaking,
                scope.kind,
                scope.name,
                format!("fixed {bytes}: {} → {}", hex(&old.bytes[start..i]), hex(&new.bytes[start..i])),
            )
            .why(match scope.sent {
                true => "projects configured with the old file send the old fixed bytes; the device now reads them as the new ones",
                false => "the device now sends other fixed bytes than projects configured with the old file expect",
            }),
        );
    }
}

/// What a parameter may be as a project can set it: its one value when
/// nobody can change it; its choices when only they limit it.
fn effective(f: &Field) -> Allowed {
    if !f.changeable {
        return match &f.default {
            Some(d) => Allowed::Ranges(vec![(d.clone(), d.clone())]),
            None => Allowed::Any,
        };
    }
    match (&f.allowed, f.choices.is_empty()) {
        (Allowed::Any, false) => Allowed::Ranges(
            f.choices
                .iter()
                .map(|c| (c.value.clone(), c.value.clone()))
                .collect(),
        ),
        // No AllowedValues: every value of its type, as a range states it.
        (Allowed::Any, true) => type_range(f).unwrap_or(Allowed::Any),
        (allowed, _) => allowed.clone(),
    }
}

/// Every value of an integer field's type (`Unsigned8`: 0..255).
fn type_range(f: &Field) -> Option<Allowed> {
    let bit_length = f.bits.map_or(0, |b| u32::from(b.length));
    let (min, max) = crate::gsdml::datatype::integer_range(&f.data_type, bit_length)?;
    Some(Allowed::Ranges(vec![(Value::Int(min), Value::Int(max))]))
}

/// Whether every value `inner` allows, `outer` allows too.
pub fn covers(outer: &Allowed, inner: &Allowed) -> bool {
    let (outer, inner) = match (outer, inner) {
        (Allowed::Any, _) => return true,
        (_, Allowed::Any) => return false,
        (Allowed::Ranges(o), Allowed::Ranges(i)) => (o, i),
    };
    let merged = merge(outer);
    inner
        .iter()
        .all(|(lo, hi)| merged.iter().any(|(a, b)| a <= lo && hi <= b))
}

/// Ranges sorted and joined where they overlap or, for integers, touch.
fn merge(ranges: &[(Value, Value)]) -> Vec<(Value, Value)> {
    let mut sorted: Vec<(Value, Value)> = ranges.to_vec();
    sorted.sort_by(|a, b| a.0.partial_cmp(&b.0).unwrap_or(std::cmp::Ordering::Equal));
    let mut merged: Vec<(Value, Value)> = Vec::with_capacity(sorted.len());
    for (lo, hi) in sorted {
        if let Some(last) = merged.last_mut() {
            let touches = match (&last.1, &lo) {
                (Value::Int(end), Value::Int(start)) => *start <= end.saturating_add(1),
                (end, start) => start <= end,
            };
            if touches {
                if hi > last.1 {
                    last.1 = hi;
                }
                continue;
            }
        }
        merged.push((lo, hi));
    }
    merged
}

fn show_allowed(allowed: &Allowed) -> String {
    match allowed {
        Allowed::Any => "any".into(),
        Allowed::Ranges(ranges) => ranges
            .iter()
            .map(|(lo, hi)| match lo == hi {
                true => lo.to_string(),
                false => format!("{lo}..{hi}"),
            })
            .collect::<Vec<_>>()
            .join(" "),
    }
}

/// `byte 3`, `byte 3 bit 2`, `byte 3 bits 2-4`.
fn place(f: &Field) -> String {
    match f.bits {
        None => format!("byte {}", f.byte_offset),
        Some(Bits { offset, length: 1 }) => format!("byte {} bit {offset}", f.byte_offset),
        Some(Bits { offset, length }) => format!(
            "byte {} bits {offset}-{}",
            f.byte_offset,
            u16::from(offset) + u16::from(length) - 1
        ),
    }
}

fn subject(scope: &Scope, f: &Field) -> String {
    format!(
        "parameter{} at {} of {}",
        quoted(Some(&f.name)),
        place(f),
        scope.name
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::device::{ConstBytes, Place, Text};

    fn field(offset: u32, name: &str, default: i128, allowed: (i128, i128)) -> Field {
        Field {
            byte_offset: offset,
            bits: None,
            data_type: "Unsigned16".into(),
            length: None,
            name: Text::plain(name),
            default: Some(Value::Int(default)),
            allowed: Allowed::Ranges(vec![(Value::Int(allowed.0), Value::Int(allowed.1))]),
            choices: Vec::new(),
            changeable: true,
            visible: true,
            attributes: Vec::new(),
            place: Place::default(),
        }
    }

    fn block(fields: Vec<Field>) -> ParameterData {
        ParameterData {
            length: None,
            consts: vec![ConstBytes {
                byte_offset: 0,
                bytes: vec![0x00, 0x00, 0x00],
                place: Place::default(),
            }],
            fields,
        }
    }

    fn changes(old: &ParameterData, new: &ParameterData) -> Vec<(Class, String)> {
        let scope = Scope {
            name: "User_Prm_Data",
            kind: Kind::Parameter,
            sent: true,
        };
        let mut out = Changes::default();
        compare(&scope, old, new, &mut out);
        out.finish()
            .into_iter()
            .map(|c| (c.class, c.change))
            .collect()
    }

    #[test]
    fn a_default_reaches_new_projects_only_unless_it_is_fixed() {
        let old = block(vec![field(3, "PZD1", 0, (0, 14))]);
        let mut new = old.clone();
        new.fields[0].default = Some(Value::Int(3));
        assert_eq!(
            changes(&old, &new),
            [(Class::Compatible, "default 0 → 3".into())]
        );
        let mut fixed_old = old.clone();
        fixed_old.fields[0].changeable = false;
        let mut fixed_new = new.clone();
        fixed_new.fields[0].changeable = false;
        assert_eq!(
            changes(&fixed_old, &fixed_new),
            [(Class::Breaking, "fixed value 0 → 3".into())]
        );
    }

    #[test]
    fn ranges_narrowed_break_and_widened_do_not() {
        let old = block(vec![field(3, "PZD1", 0, (0, 14))]);
        let mut new = old.clone();
        new.fields[0].allowed = Allowed::Ranges(vec![(Value::Int(0), Value::Int(10))]);
        assert_eq!(
            changes(&old, &new),
            [(Class::Breaking, "allowed 0..14 → 0..10".into())]
        );
        assert_eq!(
            changes(&new, &old),
            [(Class::Compatible, "allowed 0..10 → 0..14".into())]
        );
        // An Unsigned8 without AllowedValues allows 0..255, as stated.
        let mut any = old.clone();
        any.fields[0].data_type = "Unsigned8".into();
        any.fields[0].allowed = Allowed::Any;
        let mut stated = any.clone();
        stated.fields[0].allowed = Allowed::Ranges(vec![(Value::Int(0), Value::Int(255))]);
        assert_eq!(changes(&any, &stated), []);
        stated.fields[0].allowed = Allowed::Ranges(vec![(Value::Int(0), Value::Int(254))]);
        assert_eq!(
            changes(&any, &stated),
            [(Class::Breaking, "allowed 0..255 → 0..254".into())]
        );
        // 0..14 as two ranges that touch is the same set.
        new.fields[0].allowed = Allowed::Ranges(vec![
            (Value::Int(0), Value::Int(7)),
            (Value::Int(8), Value::Int(14)),
        ]);
        assert_eq!(changes(&old, &new), []);
    }

    #[test]
    fn moved_added_removed_and_fixed_bytes() {
        let old = block(vec![
            field(3, "PZD1", 0, (0, 14)),
            field(5, "PZD2", 0, (0, 14)),
        ]);
        let mut moved = old.clone();
        moved.fields[1].byte_offset = 7;
        moved.length = Some(9);
        let found = changes(&old, &moved);
        assert!(
            found.contains(&(Class::Breaking, "moved from byte 5 to byte 7".into())),
            "{found:?}"
        );
        // A parameter where the old file fixed its default is compatible.
        let mut added = block(vec![field(3, "PZD1", 0, (0, 14))]);
        added.length = Some(7);
        let mut with = added.clone();
        with.fields.push(field(5, "PZD2", 0, (0, 14)));
        assert_eq!(
            changes(&added, &with),
            [(Class::Compatible, "added, default 0".into())]
        );
        assert_eq!(
            changes(&with, &added),
            [(Class::Breaking, "removed".into())]
        );
        let mut other = with.clone();
        other.fields[1].default = Some(Value::Int(2));
        assert_eq!(changes(&added, &other)[0].0, Class::Breaking);
        let mut consts = old.clone();
        consts.consts[0].bytes = vec![0x80, 0x00, 0x08];
        assert_eq!(
            changes(&old, &consts),
            [
                (Class::Breaking, "fixed byte 0: 0x00 → 0x80".into()),
                (Class::Breaking, "fixed byte 2: 0x00 → 0x08".into())
            ]
        );
    }
}
