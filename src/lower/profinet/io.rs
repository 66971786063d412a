//! A module's IO data, word by word, with the TextIds of every word and
//! named bit; and the IO lengths of the device access point.

use super::ids::module_tag;
use super::records::{self, RecordPlan};
use crate::ir::profinet::{BitItem, DataItem, Module, ModuleKind, TextRef};
use crate::ir::{BitField, Direction, Ident, Layout, Mappings, PkwKind, Telegram, Text};

/// Standard telegram 1 has two words each way.
pub const STANDARD_TELEGRAM_1_WORDS: u8 = 2;

/// A module of `kind` and `layout`; `info` is what the description adds
/// to gsdc's description of it.
pub fn module(
    (kind, layout): (ModuleKind, Layout),
    telegram: &Telegram,
    (mappings, records): (&Mappings, &[RecordPlan]),
    info: Option<Text>,
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
        name: TextRef::new(format!("IDT_MODULE_{tag}"), name(kind, layout)),
        info: TextRef::new(
            format!("IDT_MODULE_INFO_{tag}"),
            with_info(description(kind, layout), info),
        ),
        ident_number: ident_number(kind, layout),
        layout,
        ident: code_name(kind, layout),
        input: items(Direction::In),
        output: items(Direction::Out),
        records: records::records(mappings, records, (kind, layout)),
    }
}

/// gsdc's description, then the description's own words after `. `.
fn with_info(gsdc: Text, info: Option<Text>) -> Text {
    let Some(info) = info else {
        return gsdc;
    };
    let mut languages: Vec<&str> = gsdc
        .others
        .iter()
        .chain(&info.others)
        .map(|(code, _)| code.as_str())
        .collect();
    languages.sort_unstable();
    languages.dedup();
    let join = |code: &str| format!("{}. {}", gsdc.get(code), info.get(code));
    Text {
        en: join("en"),
        others: languages
            .iter()
            .map(|code| (code.to_string(), join(code)))
            .collect(),
        gsd: None,
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

fn name(kind: ModuleKind, layout: Layout) -> Text {
    match kind {
        ModuleKind::StandardTelegram1 => Text::en_zh("Standard telegram 1", "标准报文 1"),
        ModuleKind::Pzd if layout.pkw => Text::english(format!("PKW + {} PZD", layout.pzd_words)),
        ModuleKind::Pzd => Text::english(format!("{} PZD", layout.pzd_words)),
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

/// What a module carries, in gsdc's words (English and gsdc's Chinese).
fn description(kind: ModuleKind, layout: Layout) -> Text {
    let bytes = layout.bytes();
    match kind {
        ModuleKind::StandardTelegram1 => Text::en_zh(
            format!("Standard telegram 1: STW1 and NSOLL_A to the drive, ZSW1 and NIST_A from it; {bytes} bytes each way"),
            format!("标准报文 1：STW1 和 NSOLL_A 发往驱动器，ZSW1 和 NIST_A 来自驱动器；每个方向 {bytes} 字节"),
        ),
        ModuleKind::Pzd => {
            let (pkw, pkw_zh) = match layout.pkw_words() {
                0 => (String::new(), String::new()),
                n => (format!("PKW channel ({n} words) and "), format!("PKW 通道（{n} 个字）和 ")),
            };
            let n = layout.pzd_words;
            let words = if n == 1 { "1 PZD word".to_string() } else { format!("{n} PZD words") };
            Text::en_zh(
                format!("{pkw}{words}; {bytes} bytes each way"),
                format!("{pkw_zh}{n} 个 PZD 字；每个方向 {bytes} 字节"),
            )
        }
    }
}

fn plain(tag: &str, text: Text) -> DataItem {
    DataItem {
        text: TextRef::new(format!("IDT_{tag}"), text),
        bits: Vec::new(),
    }
}

/// Standard telegram 1's two words, with PROFIdrive's names.
fn standard_telegram_1(direction: Direction) -> Vec<DataItem> {
    let words = match direction {
        Direction::In => [
            ("ZSW1", "ZSW1 (status word 1)", "ZSW1（状态字 1）"),
            (
                "NIST_A",
                "NIST_A (speed actual value)",
                "NIST_A（速度实际值）",
            ),
        ],
        Direction::Out => [
            ("STW1", "STW1 (control word 1)", "STW1（控制字 1）"),
            (
                "NSOLL_A",
                "NSOLL_A (speed setpoint)",
                "NSOLL_A（速度设定值）",
            ),
        ],
    };
    words
        .iter()
        .map(|(tag, en, zh)| plain(tag, Text::en_zh(*en, *zh)))
        .collect()
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
        .map(|(tag, en, zh)| plain(&format!("PKW_{tag}"), Text::en_zh(*en, *zh)));
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
        _ => plain(&format!("PZD_{n}"), Text::english(format!("PZD{n}"))),
    });
    pkw.chain(pzd).collect()
}

/// The PKW channel's words, the same both ways: TextId tag, English and
/// Chinese (MD810's manual writes `PWE 高 16 位`, `低 16 位`).
type WordName = (&'static str, &'static str, &'static str);
fn pkw_words(kind: PkwKind) -> &'static [WordName] {
    match kind {
        PkwKind::None => &[],
        PkwKind::PkeIndPwe => &[
            ("PKE", "PKE", "PKE"),
            ("IND", "IND", "IND"),
            ("PWE_HIGH", "PWE high", "PWE 高 16 位"),
            ("PWE_LOW", "PWE low", "PWE 低 16 位"),
        ],
        PkwKind::StationCommandAddressValue => &[
            ("STATION", "Station", "站号"),
            ("COMMAND", "Command", "命令"),
            ("ADDRESS", "Address", "地址"),
            ("VALUE", "Value", "数值"),
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
/// In every language the field or its values have.
fn bit_text(field: &BitField, index: Option<u8>) -> Text {
    let choices = field.values.as_ref().map_or(&[][..], |v| &v.choices[..]);
    let label = |language: &str| {
        let mut text = field.name.get(language).to_string();
        if let Some(index) = index {
            text.push_str(&format!(" bit {index}"));
        }
        if !choices.is_empty() {
            let values: Vec<String> = choices
                .iter()
                .map(|c| format!("{} = {}", c.value, c.text.get(language)))
                .collect();
            text.push_str(&format!(" ({})", values.join(", ")));
        }
        text
    };
    let mut languages: Vec<&str> = field
        .name
        .others
        .iter()
        .chain(choices.iter().flat_map(|c| &c.text.others))
        .map(|(code, _)| code.as_str())
        .collect();
    languages.sort_unstable();
    languages.dedup();
    Text {
        en: label("en"),
        others: languages
            .into_iter()
            .map(|code| (code.to_string(), label(code)))
            .collect(),
        gsd: None,
    }
}

/// IOConfigData's MaxInputLength and MaxOutputLength bound what the input
/// and the output CR carry: IO data and status bytes, as the checker reads
/// them (E310, `gsdml::io`; docs/rules.md gives the sources). Each
/// submodule without data (the DAP's, the interface, the ports) has its IOPS
/// in the input CR and its IOCS in the output CR: one byte each way; the
/// module's, with data both ways, adds its IOPS and the IOCS of the other
/// direction to each. The largest module with these is exactly what the
/// checker needs (`tests/gsdml_reader.rs` holds the two to it); with at most
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
            name: Text::en_zh("Control mode", "控制方式"),
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
        assert_eq!(text.get("zh"), "控制方式 bit 1 (0 = Keypad)");
    }
}
