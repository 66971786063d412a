//! The mapping in force while a telegram is decoded: what each PZD word,
//! DPV1 index and setting carries, and a gateway's node parameters (how
//! many nodes are in use, the words each carries). The description's
//! defaults, unless values are given with `--mapping KIND=VALUE,...` or read
//! from a parameter telegram.

use crate::diag::Diagnostic;
use crate::ir::gateway::{self, ParamKey};
use crate::ir::{Allowed, EntryKey, Ir, MappingEntry, MappingGroup, MappingKind};
use serde::Serialize;
use std::collections::BTreeMap;

/// Where the value of a mapping came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ValueSource {
    /// The description's default.
    Default,
    /// Given on the command line (`--mapping`).
    Given,
    /// Read from the parameter telegram (`--prm`).
    ParameterTelegram,
}

/// The values in force instead of the description's defaults, and where
/// they came from.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct MappingInForce {
    given: BTreeMap<EntryKey, (u16, ValueSource)>,
    gateway: BTreeMap<ParamKey, u16>,
}

impl MappingInForce {
    /// The description's defaults.
    pub fn defaults() -> Self {
        Self::default()
    }

    /// The value of `entry` and where it came from.
    pub fn value(&self, entry: &MappingEntry) -> (u16, ValueSource) {
        self.given
            .get(&entry.key)
            .copied()
            .unwrap_or((entry.default, ValueSource::Default))
    }

    pub(crate) fn set(&mut self, key: EntryKey, value: u16, source: ValueSource) {
        self.given.insert(key, (value, source));
    }

    /// The value of a gateway's parameter: read from a parameter telegram,
    /// or its default.
    pub fn gateway_value(&self, param: &gateway::Param) -> u16 {
        self.gateway
            .get(&param.key)
            .copied()
            .unwrap_or(param.default.into())
    }

    /// Where the gateway's node parameters came from: a parameter telegram
    /// gives them all, or none are given.
    pub fn gateway_source(&self) -> ValueSource {
        if self.gateway.is_empty() {
            ValueSource::Default
        } else {
            ValueSource::ParameterTelegram
        }
    }

    pub(crate) fn set_gateway(&mut self, key: ParamKey, value: u16) {
        self.gateway.insert(key, value);
    }

    /// Takes one `--mapping` argument: a kind of mapping (`pzd_out`), `=`,
    /// and values for its entries in order, separated by commas; an empty
    /// value keeps the default (`pzd_out=,,F0-12` sets PZD3 only). A value
    /// is a number (`61452`, `0xF00C`) or a parameter name (`F0-12`).
    /// Diagnostics (E415, E416) point into `option`.
    pub fn give(&mut self, ir: &Ir, option: &str) -> Result<(), Diagnostic> {
        let (kind, values) = option
            .split_once('=')
            .ok_or_else(|| kinds_help(ir, malformed(option, 0..option.len(), "no `=`")))?;
        let group = MappingKind::ALL
            .iter()
            .find(|k| k.key() == kind.trim())
            .and_then(|&k| ir.mappings.group(k))
            .ok_or_else(|| {
                kinds_help(
                    ir,
                    malformed(option, 0..kind.len(), "not a kind of mapping"),
                )
            })?;
        let mut offset = kind.len() + 1;
        let mut entries = group.entries();
        for text in values.split(',') {
            let span = offset..offset + text.len();
            offset = span.end + 1;
            let Some((set, entry)) = entries.next() else {
                return Err(too_many(group, span.start..option.len()));
            };
            if text.trim().is_empty() {
                continue;
            }
            let value =
                read_value(ir, text.trim(), &set.allowed, entry.default).map_err(|d| d.at(span))?;
            self.set(entry.key, value, ValueSource::Given);
        }
        Ok(())
    }
}

/// A value of a `--mapping` argument, checked against what its set allows;
/// `default` is the entry's, for the example in the help.
fn read_value(ir: &Ir, text: &str, allowed: &Allowed, default: u16) -> Result<u16, Diagnostic> {
    let value = parse_number(text)
        .or_else(|| ir.numbering.as_ref()?.parse(text).ok())
        .ok_or_else(|| {
            let names = match (&ir.numbering, allowed) {
                (Some(_), Allowed::Range { .. }) => format!(
                    " or a parameter name as the manual writes it ({})",
                    parameter_name(ir, default)
                ),
                _ => String::new(),
            };
            Diagnostic::error("E416", format!("`{text}` is not a mapping value"))
                .label("not a value")
                .help(format!(
                    "write a number from 0 to 65535 (decimal or 0x hex){names}"
                ))
        })?;
    if allowed.contains(i64::from(value)) {
        return Ok(value);
    }
    Err(Diagnostic::error(
        "E416",
        format!("`{text}` is not a value this mapping allows"),
    )
    .label("not allowed")
    .help(allowed_help(ir, allowed)))
}

fn parse_number(text: &str) -> Option<u16> {
    match text.strip_prefix("0x").or_else(|| text.strip_prefix("0X")) {
        Some(hex) => u16::from_str_radix(hex, 16).ok(),
        None => text.parse().ok(),
    }
}

fn allowed_help(ir: &Ir, allowed: &Allowed) -> String {
    match allowed {
        Allowed::Range { min, max } => {
            let name = |v| meaning(ir, allowed, v).unwrap_or_default();
            format!(
                "it allows {min} to {max} ({} to {})",
                name(*min),
                name(*max)
            )
        }
        Allowed::Choices(set) => {
            let choices: Vec<String> = set
                .choices
                .iter()
                .map(|c| format!("{} {}", c.value, c.text.en))
                .collect();
            format!("it allows {}", choices.join(", "))
        }
    }
}

fn malformed(option: &str, span: std::ops::Range<usize>, label: &str) -> Diagnostic {
    Diagnostic::error(
        "E415",
        format!("`{option}` is not KIND=VALUE,... for a kind of mapping the description has"),
    )
    .at(span)
    .label(label)
}

fn kinds_help(ir: &Ir, diagnostic: Diagnostic) -> Diagnostic {
    let kinds: Vec<String> = ir
        .mappings
        .groups
        .iter()
        .map(|g| format!("{}={}", g.kind.key(), example_values(g)))
        .collect();
    let help = if kinds.is_empty() {
        "the description has no mappings".to_string()
    } else {
        format!("for example {}", kinds.join(" or "))
    };
    diagnostic.help(help)
}

/// The group's first two defaults, as a `--mapping` example.
fn example_values(group: &MappingGroup) -> String {
    let defaults: Vec<String> = group
        .entries()
        .take(2)
        .map(|(_, e)| e.default.to_string())
        .collect();
    defaults.join(",")
}

fn too_many(group: &MappingGroup, span: std::ops::Range<usize>) -> Diagnostic {
    let count = group.entry_count();
    Diagnostic::error(
        "E415",
        format!(
            "{} has {count} entries; more values are given",
            group.kind.key()
        ),
    )
    .at(span)
    .label("one value too many")
    .help("give one value per entry, in order; leave a value empty to keep its default")
}

/// What a mapping value means: the parameter it names (`F0-08`, or its
/// address in hex where the description has no name for it), or the text of
/// the choice; `None` for a value that is not one of the choices.
pub fn meaning(ir: &Ir, allowed: &Allowed, value: u16) -> Option<String> {
    match allowed {
        Allowed::Range { .. } => Some(parameter_name(ir, value)),
        Allowed::Choices(set) => set
            .choices
            .iter()
            .find(|c| c.value == i64::from(value))
            .map(|c| c.text.en.clone()),
    }
}

/// A parameter as the manual writes it (`F0-08`, `P43.02`) through the
/// description's function-code numbering, else its address in hex.
fn parameter_name(ir: &Ir, address: u16) -> String {
    ir.numbering
        .as_ref()
        .and_then(|n| n.format(address))
        .unwrap_or_else(|| format!("0x{address:04X}"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::decode::tests::{md810, mv810};

    fn entry(ir: &Ir, kind: MappingKind, number: u8) -> &MappingEntry {
        ir.mappings.entry(EntryKey { kind, number }).1
    }

    #[test]
    fn values_by_name_or_number_in_entry_order_empty_keeps_the_default() {
        let ir = md810();
        let mut mapping = MappingInForce::defaults();
        mapping.give(&ir, "pzd_out=F0-08,,0xF00C").unwrap();
        mapping.give(&ir, "pzd_in=61442").unwrap();
        let value = |kind, n| mapping.value(entry(&ir, kind, n));
        assert_eq!(value(MappingKind::PzdOut, 1), (0xF008, ValueSource::Given));
        assert_eq!(
            value(MappingKind::PzdOut, 2),
            (0xF000, ValueSource::Default)
        );
        assert_eq!(value(MappingKind::PzdOut, 3), (0xF00C, ValueSource::Given));
        assert_eq!(value(MappingKind::PzdIn, 1), (0xF002, ValueSource::Given));
    }

    #[test]
    fn mv810_entries_start_at_pzd2() {
        let ir = mv810();
        let mut mapping = MappingInForce::defaults();
        mapping.give(&ir, "pzd_out=1,4").unwrap();
        let value = |n| mapping.value(entry(&ir, MappingKind::PzdOut, n)).0;
        assert_eq!([value(2), value(3), value(4)], [1, 4, 0]);
    }

    #[test]
    fn bad_options_point_at_their_part() {
        let ir = mv810();
        let give = |option: &str| MappingInForce::defaults().give(&ir, option).unwrap_err();
        let d = give("pzd_out");
        assert_eq!((d.code, d.span), ("E415", Some(0..7)));
        assert!(d.help.unwrap().contains("pzd_out=0,0"));
        let d = give("dpv1_index=1");
        assert_eq!((d.code, d.span), ("E415", Some(0..10)));
        let d = give("pzd_out=1,F0-08");
        assert_eq!((d.code, d.span), ("E416", Some(10..15)));
        let d = give("pzd_out=1,15");
        assert_eq!(
            (d.code, d.span, d.label.as_deref()),
            ("E416", Some(10..12), Some("not allowed"))
        );
        assert!(d.help.unwrap().contains("14 PID feedback"));
        let d = give(&format!("pzd_out={}", ["0"; 12].join(",")));
        assert_eq!((d.code, d.span), ("E415", Some(30..31)));
        let d = give("pzd_out=70000");
        assert_eq!(d.code, "E416");
    }

    #[test]
    fn meanings_are_parameter_names_or_choice_texts() {
        let ir = md810();
        let range = Allowed::Range { min: 0, max: 65535 };
        assert_eq!(meaning(&ir, &range, 0xF008).as_deref(), Some("F0-08"));
        assert_eq!(meaning(&ir, &range, 0x000A).as_deref(), Some("0x000A"));
        let ir = mv810();
        let set = &ir.mappings.group(MappingKind::PzdOut).unwrap().sets[0].allowed;
        assert_eq!(
            meaning(&ir, set, 1).as_deref(),
            Some("Frequency reference (0.00 to P02.10)")
        );
        assert_eq!(meaning(&ir, set, 15), None);
        assert_eq!(parameter_name(&ir, 0x2B02), "P43.02");
    }
}
