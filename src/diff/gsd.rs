//! Two GSD files' devices compared.
//!
//! A module is identified by its name, then by its reference number, then
//! by its config bytes: a project stores a module as the config bytes it
//! sends in Chk_Cfg, so a module renamed with the same bytes is a rename
//! (cosmetic), and one whose bytes changed breaks every project that has
//! it, whatever its name.

use super::params::{self, Scope};
use super::{judge, Change, Changes, Class, Kind};
use crate::device::dp::{DiagArea, DiagBit, DiagValue, DpDevice, DpModule, DpSlot, Keyword};
use crate::device::{Allowed, Place, Text};
use crate::gsd::{Arg, Value};

/// Every change from `old` to `new`, breaking first.
pub fn compare(old: &DpDevice, new: &DpDevice) -> Vec<super::Change> {
    let mut out = Changes::default();
    file_name(old, new, &mut out);
    keywords(
        "",
        &with_implied_max_prm_len(old),
        &with_implied_max_prm_len(new),
        &mut out,
    );
    let scope = Scope {
        name: "User_Prm_Data",
        kind: Kind::Parameter,
        sent: true,
    };
    params::compare(&scope, &old.user_prm_data, &new.user_prm_data, &mut out);
    modules(&old.modules, &new.modules, &mut out);
    slots(&old.slots, &new.slots, &mut out);
    diagnosis(old, new, &mut out);
    out.finish()
}

fn file_name(old: &DpDevice, new: &DpDevice, out: &mut Changes) {
    if let (Some(a), Some(b)) = (&old.file_name, &new.file_name) {
        if a != b {
            out.push(
                Change::new(Class::Cosmetic, Kind::File, "file name", format!("{a} → {b}"))
                    .why("the engineering tool installs the file by its name; projects do not depend on it"),
            );
        }
    }
}

/// The device's keywords, with `Max_User_Prm_Data_Len` implied when the
/// file states only the legacy `User_Prm_Data_Len` and no module has
/// parameters of its own. A master sends such a device a parameter
/// telegram of exactly User_Prm_Data_Len bytes of User_Prm_Data; stating
/// Max_User_Prm_Data_Len of that value (as gsdc does) lets the master send
/// the same telegram and no longer one, so the two files offer one limit,
/// and the file that adds the keyword changes nothing a master sends.
/// Modules' own parameters would add to the telegram, and the longest one
/// then is not the device's length: no limit is implied there. Nor for a
/// length of 0, which a file without either keyword states as well.
fn with_implied_max_prm_len(device: &DpDevice) -> Vec<Keyword> {
    let mut keywords = device.keywords.clone();
    let prm = &device.user_prm_data;
    let modules_have_parameters = device.modules.iter().any(|m| !m.user_prm_data.is_empty());
    if let (None, Some(length @ 1..), false) = (
        device.keyword("Max_User_Prm_Data_Len"),
        prm.length,
        modules_have_parameters,
    ) {
        keywords.push(Keyword {
            name: "Max_User_Prm_Data_Len".into(),
            key: "max_user_prm_data_len".into(),
            arg: None,
            value: Value::Number(length.into()),
            // User_Prm_Data's line, where the legacy length is written.
            place: prm
                .consts
                .first()
                .map(|c| c.place.clone())
                .unwrap_or_default(),
        });
    }
    keywords
}

/// Keywords paired by key and argument, each judged by its rule. A baud
/// rate supported or dropped is one change: its MaxTsdr comes and goes
/// with it.
fn keywords(prefix: &str, old: &[Keyword], new: &[Keyword], out: &mut Changes) {
    let supported = |keywords: &[Keyword]| -> Vec<Arg> {
        keywords
            .iter()
            .filter(|k| k.key == "<baud>_supp" && k.value.as_number() == Some(1))
            .filter_map(|k| k.arg)
            .collect()
    };
    let (old_bauds, new_bauds) = (supported(old), supported(new));
    let with_its_rate = |k: &&Keyword| {
        k.key != "maxtsdr_<baud>"
            || k.arg
                .is_some_and(|a| old_bauds.contains(&a) == new_bauds.contains(&a))
    };
    let old: Vec<Keyword> = old.iter().filter(with_its_rate).cloned().collect();
    let new: Vec<Keyword> = new.iter().filter(with_its_rate).cloned().collect();
    let pairing = super::pairing::pair(&old, &new, |k| (k.key.as_str(), k.arg));
    let text = |k: &Keyword| value_text(&k.value);
    let subject = |k: &Keyword| format!("{prefix}{}", k.name);
    for (a, b) in pairing.both.into_iter().filter(|(a, b)| a.value != b.value) {
        let rule = judge::gsd_rule(&a.key);
        out.0.extend(judge::judge(
            rule,
            subject(b),
            Some(&text(a)),
            Some(&text(b)),
            (Some(&a.place), Some(&b.place)),
        ));
    }
    for a in pairing.gone {
        let rule = judge::gsd_rule(&a.key);
        out.0.extend(judge::judge(
            rule,
            subject(a),
            Some(&text(a)),
            None,
            (Some(&a.place), None),
        ));
    }
    for b in pairing.added {
        let rule = judge::gsd_rule(&b.key);
        out.0.extend(judge::judge(
            rule,
            subject(b),
            None,
            Some(&text(b)),
            (None, Some(&b.place)),
        ));
    }
}

/// A keyword's value as the file writes it.
fn value_text(value: &Value) -> String {
    match value {
        Value::None => String::new(),
        Value::Number(n) => n.to_string(),
        Value::List(l) => hex_list(l.iter().map(|&b| b as u8)),
        Value::Str(s) | Value::Raw(s) => s.clone(),
        Value::Family { main, sub } => std::iter::once(main.to_string())
            .chain(sub.iter().cloned())
            .collect::<Vec<_>>()
            .join("@"),
        Value::Range(a, b) => format!("{a}-{b}"),
    }
}

fn hex_list(bytes: impl Iterator<Item = u8>) -> String {
    bytes
        .map(|b| format!("0x{b:02X}"))
        .collect::<Vec<_>>()
        .join(",")
}

fn module_subject(m: &DpModule) -> String {
    format!("module \"{}\"", m.name)
}

fn modules(old: &[DpModule], new: &[DpModule], out: &mut Changes) {
    let pairing = super::pairing::pair(old, new, |m| m.name.clone())
        .then(|m| m.reference)
        .then(|m| Some(m.config.clone()));
    for (a, b) in pairing.both.iter().chain(&pairing.rekeyed) {
        module(a, b, out);
    }
    for a in pairing.gone {
        out.push(
            Change::new(Class::Breaking, Kind::Module, module_subject(a), format!("removed (config bytes {})", hex_list(a.config.iter().copied())))
                .why("a project with this module sends its config bytes in Chk_Cfg, which the device no longer accepts")
                .at(Some(&a.place), None),
        );
    }
    for b in pairing.added {
        out.push(
            Change::new(
                Class::Compatible,
                Kind::Module,
                module_subject(b),
                format!(
                    "added (config bytes {})",
                    hex_list(b.config.iter().copied())
                ),
            )
            .why("old projects do not use it")
            .at(None, Some(&b.place)),
        );
    }
}

fn module(a: &DpModule, b: &DpModule, out: &mut Changes) {
    if a == b {
        return;
    }
    let subject = module_subject(b);
    let at = (Some(&a.place), Some(&b.place));
    if a.name != b.name {
        out.text(
            &subject,
            Some(&Text::plain(&a.name)),
            Some(&Text::plain(&b.name)),
            at,
        );
    }
    if a.config != b.config {
        let io = |m: &DpModule| match m.io {
            Some((i, o)) => format!(" ({i} bytes in, {o} out)"),
            None => String::new(),
        };
        out.push(
            Change::new(
                Class::Breaking,
                Kind::Module,
                &subject,
                format!(
                    "config bytes {}{} → {}{}",
                    hex_list(a.config.iter().copied()),
                    io(a),
                    hex_list(b.config.iter().copied()),
                    io(b)
                ),
            )
            .why("a project with this module sends the old config bytes in Chk_Cfg; the device expects the new ones and refuses the configuration")
            .at(at.0, at.1),
        );
    }
    if a.reference != b.reference {
        let show = |r: Option<i64>| r.map_or("none".to_string(), |r| r.to_string());
        out.push(
            Change::new(Class::Cosmetic, Kind::Module, &subject, format!("reference number {} → {}", show(a.reference), show(b.reference)))
                .why("the number names the module in the file's slot definitions; projects store the config bytes")
                .at(at.0, at.1),
        );
    }
    keywords(&format!("{subject} "), &a.keywords, &b.keywords, out);
    let name = format!("User_Prm_Data of {subject}");
    let scope = Scope {
        name: &name,
        kind: Kind::Parameter,
        sent: true,
    };
    params::compare(&scope, &a.user_prm_data, &b.user_prm_data, out);
    let name = format!("PROFIsafe parameters of {subject}");
    let scope = Scope {
        name: &name,
        ..scope
    };
    params::compare(&scope, &a.safety_prm_data, &b.safety_prm_data, out);
}

fn slots(old: &[DpSlot], new: &[DpSlot], out: &mut Changes) {
    let pairing = super::pairing::pair(old, new, |s| s.number);
    let subject = |s: &DpSlot| format!("slot {}", s.number);
    for (a, b) in pairing.both {
        let at = (Some(&a.place), Some(&b.place));
        out.text(&subject(b), Some(&a.name), Some(&b.name), at);
        if a.default != b.default {
            out.push(
                Change::new(
                    Class::Compatible,
                    Kind::Module,
                    subject(b),
                    format!("default module {} → {}", a.default, b.default),
                )
                .why("the module a new project plugs by default; old projects keep theirs")
                .at(at.0, at.1),
            );
        }
        if a.allowed != b.allowed {
            let covered = params::covers(&b.allowed, &a.allowed);
            let (class, why) = match covered {
                true => (Class::Compatible, "every module old projects may have plugged there is still allowed"),
                false => (Class::Breaking, "a project configured with the old file may have a module there that the new file no longer allows"),
            };
            out.push(
                Change::new(
                    class,
                    Kind::Module,
                    subject(b),
                    format!(
                        "allowed modules {} → {}",
                        show(&a.allowed),
                        show(&b.allowed)
                    ),
                )
                .why(why)
                .at(at.0, at.1),
            );
        }
    }
    for a in pairing.gone {
        out.push(
            Change::new(Class::Breaking, Kind::Module, subject(a), "removed")
                .why("a project configured with the old file may have a module in it")
                .at(Some(&a.place), None),
        );
    }
    for b in pairing.added {
        out.push(
            Change::new(Class::Compatible, Kind::Module, subject(b), "added")
                .why("old projects do not use it")
                .at(None, Some(&b.place)),
        );
    }
}

fn show(allowed: &Allowed) -> String {
    match allowed {
        Allowed::Any => "any".into(),
        Allowed::Ranges(r) => r
            .iter()
            .map(|(lo, hi)| {
                if lo == hi {
                    lo.to_string()
                } else {
                    format!("{lo}-{hi}")
                }
            })
            .collect::<Vec<_>>()
            .join(","),
    }
}

fn diagnosis(old: &DpDevice, new: &DpDevice, out: &mut Changes) {
    let (a, b) = (&old.diagnosis, &new.diagnosis);
    bits("", &a.bits, &b.bits, out);
    areas("", &a.areas, &b.areas, out);
    let pairing = super::pairing::pair(&a.types, &b.types, |t| t.id);
    for (x, y) in pairing.both {
        let prefix = format!("UnitDiagType {} ", y.id);
        bits(&prefix, &x.bits, &y.bits, out);
        areas(&prefix, &x.areas, &y.areas, out);
    }
    for x in pairing.gone {
        out.push(diag_gone(format!("UnitDiagType {}", x.id), &x.place));
    }
    for y in pairing.added {
        out.push(diag_added(format!("UnitDiagType {}", y.id), &y.place));
    }
    values("Channel_Diag", &a.channel, &b.channel, out);
}

/// A diagnosis the device no longer reports: old projects keep its text
/// and never see it.
fn diag_gone(subject: String, at: &Place) -> Change {
    Change::new(Class::Compatible, Kind::Diagnosis, subject, "removed")
        .why("the device no longer reports it; projects configured with the old file keep a text they never show")
        .at(Some(at), None)
}

fn diag_added(subject: String, at: &Place) -> Change {
    Change::new(Class::Compatible, Kind::Diagnosis, subject, "added")
        .why("projects configured with the old file show it without its text")
        .at(None, Some(at))
}

/// Diagnosis bits by number, then by text: a text at another bit is the
/// same diagnosis moved.
fn bits(prefix: &str, old: &[DiagBit], new: &[DiagBit], out: &mut Changes) {
    let pairing = super::pairing::pair(old, new, |b| (b.bit, b.when_clear))
        .then(|b| Some((b.text.clone(), b.when_clear)));
    let subject = |b: &DiagBit| {
        let kind = if b.when_clear {
            "Unit_Diag_Not_Bit"
        } else {
            "Unit_Diag_Bit"
        };
        format!("{prefix}{kind}({})", b.bit)
    };
    for (a, b) in pairing.both.iter().chain(&pairing.rekeyed) {
        let at = (Some(&a.place), Some(&b.place));
        if a.bit != b.bit {
            out.push(
                Change::new(Class::Compatible, Kind::Diagnosis, subject(b), format!("moved from bit {}", a.bit))
                    .why("projects configured with the old file know its text at the old bit and show it without its text")
                    .at(at.0, at.1),
            );
        }
        out.text(&subject(b), Some(&a.text), Some(&b.text), at);
        out.text(
            &format!("{} help", subject(b)),
            a.help.as_ref(),
            b.help.as_ref(),
            at,
        );
    }
    for a in pairing.gone {
        out.push(diag_gone(subject(a), &a.place));
    }
    for b in pairing.added {
        out.push(diag_added(subject(b), &b.place));
    }
}

/// Areas paired by their bits; an area whose bits changed is read by old
/// projects at the old bits.
fn areas(prefix: &str, old: &[DiagArea], new: &[DiagArea], out: &mut Changes) {
    let pairing = super::pairing::pair(old, new, |a| (a.first, a.last)).then(|a| Some(a.first));
    let subject = |a: &DiagArea| format!("{prefix}Unit_Diag_Area {}-{}", a.first, a.last);
    for (a, b) in &pairing.both {
        values(&subject(b), &a.values, &b.values, out);
    }
    for (a, b) in &pairing.rekeyed {
        out.push(
            Change::new(Class::Breaking, Kind::Diagnosis, subject(b), format!("bits {}-{} → {}-{}", a.first, a.last, b.first, b.last))
                .why("projects configured with the old file read the value at the old bits and show its text for another value")
                .at(Some(&a.place), Some(&b.place)),
        );
        values(&subject(b), &a.values, &b.values, out);
    }
    for a in pairing.gone {
        out.push(diag_gone(subject(a), &a.place));
    }
    for b in pairing.added {
        out.push(diag_added(subject(b), &b.place));
    }
}

fn values(subject: &str, old: &[DiagValue], new: &[DiagValue], out: &mut Changes) {
    let pairing = super::pairing::pair(old, new, |v| v.value);
    let name = |v: &DiagValue| format!("{subject} value {}", v.value);
    for (a, b) in pairing.both {
        out.text(
            &name(b),
            Some(&a.text),
            Some(&b.text),
            (Some(&a.place), Some(&b.place)),
        );
    }
    for a in pairing.gone {
        out.push(diag_gone(name(a), &a.place));
    }
    for b in pairing.added {
        out.push(diag_added(name(b), &b.place));
    }
}
