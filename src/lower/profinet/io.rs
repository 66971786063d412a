//! A module's IO data, word by word, with the TextIds of every word and
//! named bit; and the IO lengths of the device access point.

use super::ids::module_tag;
use super::records::records;
use crate::ir::profinet::{BitItem, DataItem, Module, ModuleKind, TextRef};
use crate::ir::{
    BitField, Direction, Ident, Layout, MappingKind, Mappings, PkwKind, Telegram, Text,
};

/// Standard telegram 1 has two words each way.
pub const STANDARD_TELEGRAM_1_WORDS: u8 = 2;

pub fn module(
    kind: ModuleKind,
    layout: Layout,
    telegram: &Telegram,
    mappings: &Mappings,
    record_indexes: &[(MappingKind, u16)],
) -> Module {
    let tag = module_tag(kind, layout);
    let items = |direction| match kind {
        ModuleKind::StandardTelegram1 => standard_telegram_1(direction),
        ModuleKind::Pzd => data_items(telegram, layout, direction),
    };
    Module {
        kind,
        id: format!("IDM_{tag}"),
        submodule_id: format!("IDS_{tag}"),
        name: TextRef::new(
            format!("IDT_MODULE_{tag}"),
            Text::english(name(kind, layout)),
        ),
        info: TextRef::new(
            format!("IDT_MODULE_INFO_{tag}"),
            Text::english(description(kind, layout)),
        ),
        ident_number: ident_number(kind, layout),
        layout,
        ident: code_name(kind, layout),
        input: items(Direction::In),
        output: items(Direction::Out),
        // The user-defined (PZD) modules carry the parameter records, so the
        // controller writes the mappings and settings when it plugs one of
        // them; standard telegram 1 has fixed meanings and carries none.
        records: match kind {
            ModuleKind::Pzd => records(mappings, record_indexes),
            ModuleKind::StandardTelegram1 => Vec::new(),
        },
    }
}

/// Stable ident numbers, so firmware and GSDML agree without a table:
/// 0x0000_0010 standard telegram 1, 0x0000_01nn nn PZD words, 0x0000_02nn
/// the PKW and nn PZD words.
fn ident_number(kind: ModuleKind, layout: Layout) -> u32 {
    match kind {
        ModuleKind::StandardTelegram1 => 0x10,
        ModuleKind::Pzd => (if layout.pkw { 0x200 } else { 0x100 }) + u32::from(layout.pzd_words),
    }
}

fn name(kind: ModuleKind, layout: Layout) -> String {
    match kind {
        ModuleKind::StandardTelegram1 => "Standard telegram 1".into(),
        ModuleKind::Pzd if layout.pkw => format!("PKW + {} PZD", layout.pzd_words),
        ModuleKind::Pzd => format!("{} PZD", layout.pzd_words),
    }
}

/// `telegram1`, `pkw_pzd12`, `pzd12`.
fn code_name(kind: ModuleKind, layout: Layout) -> Ident {
    let pzd = format!("pzd{}", layout.pzd_words);
    match kind {
        ModuleKind::StandardTelegram1 => Ident::of(&["telegram1"]),
        ModuleKind::Pzd if layout.pkw => Ident::of(&["pkw", &pzd]),
        ModuleKind::Pzd => Ident::of(&[&pzd]),
    }
}

fn description(kind: ModuleKind, layout: Layout) -> String {
    let bytes = layout.bytes();
    match kind {
        ModuleKind::StandardTelegram1 => {
            format!("Standard telegram 1: STW1 and NSOLL_A to the drive, ZSW1 and NIST_A from it; {bytes} bytes each way")
        }
        ModuleKind::Pzd => {
            let pkw = match layout.pkw_words() {
                0 => String::new(),
                n => format!("PKW channel ({n} words) and "),
            };
            let words = match layout.pzd_words {
                1 => "1 PZD word".to_string(),
                n => format!("{n} PZD words"),
            };
            format!("{pkw}{words}; {bytes} bytes each way")
        }
    }
}

fn plain(tag: &str, text: &str) -> DataItem {
    DataItem {
        text: TextRef::new(format!("IDT_{tag}"), Text::english(text)),
        bits: Vec::new(),
    }
}

/// Standard telegram 1's two words.
fn standard_telegram_1(direction: Direction) -> Vec<DataItem> {
    let words = match direction {
        Direction::In => [
            ("ZSW1", "ZSW1 (status word 1)"),
            ("NIST_A", "NIST_A (speed actual value)"),
        ],
        Direction::Out => [
            ("STW1", "STW1 (control word 1)"),
            ("NSOLL_A", "NSOLL_A (speed setpoint)"),
        ],
    };
    words.iter().map(|(tag, text)| plain(tag, text)).collect()
}

/// The module's words one way, in telegram order: the PKW channel, then
/// PZD1..PZDn; PZD1 with its bits when it is the control or status word.
fn data_items(telegram: &Telegram, layout: Layout, direction: Direction) -> Vec<DataItem> {
    let pkw = if layout.pkw {
        pkw_words(telegram.pkw)
    } else {
        &[]
    };
    let pkw = pkw
        .iter()
        .map(|(tag, text)| plain(&format!("PKW_{tag}"), text));
    let word = telegram.word(direction);
    let tag = match direction {
        Direction::Out => "CONTROL",
        Direction::In => "STATUS",
    };
    let pzd = (1..=layout.pzd_words).map(|n| match word {
        Some(word) if n == 1 => DataItem {
            text: TextRef::new(format!("IDT_{tag}_WORD"), word.name.clone()),
            bits: word
                .bits
                .iter()
                .flat_map(|field| bit_items(tag, field))
                .collect(),
        },
        _ => plain(&format!("PZD_{n}"), &format!("PZD{n}")),
    });
    pkw.chain(pzd).collect()
}

/// The PKW channel's words, the same both ways: TextId tag and text.
fn pkw_words(kind: PkwKind) -> &'static [(&'static str, &'static str)] {
    match kind {
        PkwKind::None => &[],
        PkwKind::PkeIndPwe => &[
            ("PKE", "PKE"),
            ("IND", "IND"),
            ("PWE_HIGH", "PWE high"),
            ("PWE_LOW", "PWE low"),
        ],
        PkwKind::StationCommandAddressValue => &[
            ("STATION", "Station"),
            ("COMMAND", "Command"),
            ("ADDRESS", "Address"),
            ("VALUE", "Value"),
        ],
    }
}

fn bit_items<'a>(tag: &'a str, field: &'a BitField) -> impl Iterator<Item = BitItem> + 'a {
    (field.first..=field.last).map(move |bit| {
        let index = (field.last > field.first).then(|| bit - field.first);
        BitItem {
            offset: bit,
            text: TextRef::new(format!("IDT_{tag}_BIT_{bit}"), bit_text(field, index)),
        }
    })
}

/// A bit's name: the field's, with the bit's place in a field of several
/// bits, and the field's values when it has them, since a BitDataItem has
/// nothing else to show them with: "Control mode bit 0 (0 = Keypad, ...)".
fn bit_text(field: &BitField, index: Option<u8>) -> Text {
    let choices = field.values.as_ref().map_or(&[][..], |v| &v.choices[..]);
    let label = |chinese: bool| {
        let mut text = field.name.pick(chinese).to_string();
        if let Some(index) = index {
            text.push_str(&format!(" bit {index}"));
        }
        if !choices.is_empty() {
            let values: Vec<String> = choices
                .iter()
                .map(|c| format!("{} = {}", c.value, c.text.pick(chinese)))
                .collect();
            text.push_str(&format!(" ({})", values.join(", ")));
        }
        text
    };
    let translated = field.name.zh.is_some() || choices.iter().any(|c| c.text.zh.is_some());
    Text {
        en: label(false),
        zh: translated.then(|| label(true)),
    }
}

/// IOConfigData's MaxInputLength and MaxOutputLength count a frame's IO
/// data and its status bytes (IOPS, IOCS). Each submodule without data (the
/// DAP's, the interface, the ports) adds one byte each way; the module's,
/// with data both ways, adds its IOPS and the IOCS of the other direction.
/// If a tool counts data only, this is still an upper bound; with at most
/// 20 words in a module and 16 ports it stays far below the limit of 1440.
pub fn max_lengths(modules: &[Module], ports: u8) -> (u16, u16) {
    let data = modules.iter().map(|m| m.layout.bytes()).max().unwrap_or(0);
    let without_data = 2 + u16::from(ports);
    let length = data + without_data + 2;
    (length, length)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ir::{Choice, ValueSet};

    #[test]
    fn bits_of_a_field_name_their_place_and_values() {
        let field = BitField {
            first: 9,
            last: 10,
            name: Text {
                en: "Control mode".into(),
                zh: Some("控制方式".into()),
            },
            ident: Ident::of(&["control", "mode"]),
            values: Some(ValueSet {
                ident: Ident::of(&["control", "mode"]),
                choices: vec![Choice {
                    value: 0,
                    text: Text::english("Keypad"),
                    ident: Ident::of(&["keypad"]),
                }],
            }),
        };
        let text = bit_text(&field, Some(1));
        assert_eq!(text.en, "Control mode bit 1 (0 = Keypad)");
        assert_eq!(text.zh.as_deref(), Some("控制方式 bit 1 (0 = Keypad)"));
    }
}
