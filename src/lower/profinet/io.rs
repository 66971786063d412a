//! A module's IO data, word by word, with the TextIds of every word and
//! named bit; and the IO lengths of the device access point.

use super::fail_safe::FailSafeNames;
use super::ids::module_tag;
use super::profile_words::profile_words;
use super::pzd_names::PzdNames;
use super::records::{self, RecordPlan};
use crate::i18n::{files, Phrase};
use crate::ir::profinet::{
    last_used_slot, AccessPoint, BitItem, Category, DataItem, EmptyModule, Module, ModuleKind,
    Slots, TextRef, PROFIDRIVE_API,
};
use crate::ir::safety::SafetyModule;
use crate::ir::{BitField, Direction, Ident, Layout, Mappings, PkwKind, Telegram, Text};
use std::collections::BTreeMap;

/// IOConfigData's bound on each length (p-net's GSDML guide: "valid
/// 0..1440"; the reference notes' checks beyond the schema).
pub(crate) const MAX_IO_LENGTH: u16 = 1440;

/// Standard telegram 1 has two words each way.
pub const STANDARD_TELEGRAM_1_WORDS: u8 = 2;
/// Standard telegram 2 has four: a word, a 32-bit value, a word.
pub const STANDARD_TELEGRAM_2_WORDS: u8 = 4;

/// What names a module besides its kind and layout.
pub struct Names<'a> {
    /// Standard telegram 1's name: the profile's, or the manual's.
    pub telegram_1: &'a Text,
    /// What the description adds to gsdc's description of the module.
    pub info: Option<Text>,
    pub category: String,
    /// The names of the values its settings record ends with.
    pub fail_safe: Option<&'a FailSafeNames>,
    /// The description's names of the PZD words, where it gives them.
    pub pzd: Option<&'a PzdNames>,
    /// The description's names of the profile's words, by abbreviation.
    pub profile_words: &'a BTreeMap<String, Text>,
}

/// A module of `kind` and `layout`. Standard telegram 1 of a PROFIdrive
/// card is the profile's: in its API, behind the module access point, with
/// the profile's word names; of any other card it is the vendor's telegram
/// of PZD words, named as the manual names it. Standard telegram 2 is only
/// the profile's (lowering refuses it elsewhere, E161).
pub fn module(
    (kind, layout): (ModuleKind, Layout),
    telegram: &Telegram,
    (mappings, records): (&Mappings, &[RecordPlan]),
    names: Names,
) -> Module {
    let tag = module_tag(kind, layout);
    let profidrive = kind != ModuleKind::Pzd && telegram.profidrive;
    let items = |direction| match (kind, profidrive) {
        (ModuleKind::StandardTelegram2, _) | (_, true) => {
            profidrive_telegram(kind, direction, names.profile_words)
        }
        (_, false) => data_items(telegram, layout, direction, names.pzd),
    };
    let name = gsdc_name(kind, layout).unwrap_or_else(|| names.telegram_1.clone());
    let description = description(kind, layout, &name, profidrive);
    let name = TextRef::new(format!("IDT_MODULE_{tag}"), name);
    let info = TextRef::new(
        format!("IDT_MODULE_INFO_{tag}"),
        with_info(description, names.info),
    );
    let output = items(Direction::Out);
    let fail_safe = names
        .fail_safe
        .map(|f| f.items(kind, layout, &output))
        .unwrap_or_default();
    Module {
        kind,
        id: format!("IDM_{tag}"),
        submodule_id: format!("IDS_{tag}"),
        api: if profidrive { PROFIDRIVE_API } else { 0 },
        access_point: profidrive.then(|| access_point(&tag)),
        category: names.category,
        submodule_name: name.clone(),
        submodule_info: info.clone(),
        name,
        info,
        ident_number: ident_number(kind, layout),
        submodule_ident_number: ident_number(kind, layout),
        layout,
        ident: code_name(kind, layout),
        input: items(Direction::In),
        output,
        records: records::records(mappings, records, (kind, layout), fail_safe),
    }
}

/// The module access point, named as ABB's FENA names it.
fn access_point(tag: &str) -> AccessPoint {
    AccessPoint {
        id: format!("IDS_MAP_{tag}"),
        name: TextRef::new("IDT_ACCESS_POINT", Text::phrase(files::MODULE_ACCESS_POINT)),
        info: TextRef::new(
            "IDT_ACCESS_POINT_INFO",
            Text::phrase(files::MODULE_ACCESS_POINT_INFO),
        ),
    }
}

/// The hardware catalog's group of a module, as ABB groups its modules:
/// the profile's standard telegrams, the modules with the PKW channel, the
/// modules of PZD words only (a vendor's telegram 1 among them).
pub fn category(kind: ModuleKind, layout: Layout, profidrive: bool) -> Category {
    let (tag, text) = match kind {
        ModuleKind::StandardTelegram1 | ModuleKind::StandardTelegram2 if profidrive => {
            ("STANDARD_TELEGRAMS", files::CATEGORY_STANDARD_TELEGRAMS)
        }
        _ if layout.pkw => ("PKW_PZD", files::CATEGORY_PKW_PZD),
        _ => ("PZD", files::CATEGORY_PZD),
    };
    Category {
        id: format!("IDC_{tag}"),
        text: TextRef::new(format!("IDT_CATEGORY_{tag}"), Text::phrase(text)),
    }
}

/// PROFIdrive's name of its telegram 1.
pub fn profidrive_telegram_1_name() -> Text {
    Text::phrase(files::STANDARD_TELEGRAM_1)
}

/// What `with_info` puts before the description's words in language
/// `code`: gsdc's description and the full stop (an import strips it).
pub(crate) fn info_prefix(code: &str, gsdc: &str) -> String {
    let lang = crate::i18n::Lang::of(code).unwrap_or(crate::i18n::Lang::En);
    files::with_info(lang, gsdc, "")
}

/// gsdc's description, then the description's own words after a full stop.
fn with_info(gsdc: Text, info: Option<Text>) -> Text {
    let Some(info) = info else {
        return gsdc;
    };
    Text::composed(&[&gsdc, &info], |code, lang| {
        files::with_info(lang, gsdc.get(code), info.get(code))
    })
}

/// gsdc's numbering, where the description states none: stable ident
/// numbers, so firmware and GSDML agree without a table:
/// 0x0000_00n0 standard telegram n, 0x0000_01nn nn PZD words,
/// 0x0000_02nn the PKW and nn PZD words.
fn ident_number(kind: ModuleKind, layout: Layout) -> u32 {
    match kind {
        ModuleKind::StandardTelegram1 => 0x10,
        ModuleKind::StandardTelegram2 => 0x20,
        ModuleKind::Pzd => (if layout.pkw { 0x200 } else { 0x100 }) + u32::from(layout.pzd_words),
    }
}

/// gsdc's name of a module of `kind`; `None` for standard telegram 1,
/// which the profile names on a PROFIdrive card and the description on
/// another.
pub(crate) fn gsdc_name(kind: ModuleKind, layout: Layout) -> Option<Text> {
    match kind {
        ModuleKind::StandardTelegram1 => None,
        ModuleKind::StandardTelegram2 => Some(Text::phrase(files::STANDARD_TELEGRAM_2)),
        ModuleKind::Pzd => Some(pzd_name(layout)),
    }
}

fn pzd_name(layout: Layout) -> Text {
    match layout.pkw {
        true => Text::english(format!("PKW + {} PZD", layout.pzd_words)),
        false => Text::english(format!("{} PZD", layout.pzd_words)),
    }
}

/// `telegram1`, `telegram2`, `pkw_pzd12`, `pzd12`.
fn code_name(kind: ModuleKind, layout: Layout) -> Ident {
    let pzd = format!("pzd{}", layout.pzd_words);
    match kind {
        ModuleKind::StandardTelegram1 => Ident::of(&["telegram1"]),
        ModuleKind::StandardTelegram2 => Ident::of(&["telegram2"]),
        ModuleKind::Pzd if layout.pkw => Ident::of(&["pkw", &pzd]),
        ModuleKind::Pzd => Ident::of(&[&pzd]),
    }
}

/// What a module carries, in gsdc's words; a vendor's telegram 1 under the
/// name the description gives it, in each of the name's languages.
pub(crate) fn description(kind: ModuleKind, layout: Layout, name: &Text, profidrive: bool) -> Text {
    let bytes = layout.bytes();
    let n = layout.pzd_words;
    match kind {
        ModuleKind::StandardTelegram1 if profidrive => {
            Text::gsdc(|lang| files::profidrive_telegram_1_info(lang, bytes))
        }
        ModuleKind::StandardTelegram1 => Text::composed(&[name], |code, lang| {
            files::vendor_telegram_1_info(lang, name.get(code), n, bytes)
        }),
        ModuleKind::StandardTelegram2 => {
            Text::gsdc(|lang| files::profidrive_telegram_2_info(lang, bytes))
        }
        ModuleKind::Pzd => Text::gsdc(|lang| match (layout.pkw_words(), n) {
            (0, 1) => files::pzd_module_info_one(lang, bytes),
            (0, n) => files::pzd_module_info(lang, n, bytes),
            (pkw, 1) => files::pkw_pzd_module_info_one(lang, pkw, bytes),
            (pkw, n) => files::pkw_pzd_module_info(lang, pkw, n, bytes),
        }),
    }
}

fn plain(tag: &str, text: Text) -> DataItem {
    DataItem {
        text: TextRef::new(format!("IDT_{tag}"), text),
        bits: Vec::new(),
        double_word: false,
    }
}

/// A PROFIdrive standard telegram's words one way, each named as the
/// description names it or else as the profile does; telegram 2's second
/// word is its 32-bit speed value.
fn profidrive_telegram(
    kind: ModuleKind,
    direction: Direction,
    names: &BTreeMap<String, Text>,
) -> Vec<DataItem> {
    let speed_is_32_bit = kind == ModuleKind::StandardTelegram2;
    profile_words(kind, direction)
        .iter()
        .enumerate()
        .map(|(i, &(tag, profiles))| {
            let name = names
                .get(tag)
                .cloned()
                .unwrap_or_else(|| Text::phrase(profiles));
            DataItem {
                double_word: speed_is_32_bit && i == 1,
                ..plain(tag, name)
            }
        })
        .collect()
}

/// The module's words one way, in telegram order: the PKW channel, then
/// PZD1..PZDn; PZD1 with its bits when it is the control or status word.
fn data_items(
    telegram: &Telegram,
    layout: Layout,
    direction: Direction,
    names: Option<&PzdNames>,
) -> Vec<DataItem> {
    let pkw = if layout.pkw {
        pkw_words(telegram.pkw)
    } else {
        &[]
    };
    let pkw = pkw
        .iter()
        .map(|(tag, name)| plain(&format!("PKW_{tag}"), Text::phrase(*name)));
    let word = telegram.word(direction);
    let tag = match direction {
        Direction::Out => "CONTROL",
        Direction::In => "STATUS",
    };
    let pzd = (1..=layout.pzd_words).map(|n| match word {
        Some(word) if n == 1 => DataItem {
            double_word: false,
            text: TextRef::new(format!("IDT_{tag}_WORD"), word.name.clone()),
            bits: word
                .bits
                .iter()
                .flat_map(|field| bit_items(tag, field))
                .collect(),
        },
        _ => match names.and_then(|names| names.of(telegram, direction, n)) {
            Some(name) => plain(
                &format!("WORD_{}_{n}", direction_tag(direction)),
                name.clone(),
            ),
            None => plain(&format!("PZD_{n}"), Text::english(format!("PZD{n}"))),
        },
    });
    pkw.chain(pzd).collect()
}

/// A named PZD word's TextId part (`IDT_WORD_OUT_2`): the name differs by
/// direction, gsdc's `PZD1` does not (and `IDT_PZD_OUT_2` is a mapping
/// record's entry).
fn direction_tag(direction: Direction) -> &'static str {
    match direction {
        Direction::Out => "OUT",
        Direction::In => "IN",
    }
}

/// The PKW channel's words, the same both ways: TextId tag and name.
pub(crate) fn pkw_words(kind: PkwKind) -> &'static [(&'static str, Phrase)] {
    match kind {
        PkwKind::None => &[],
        PkwKind::PkeIndPwe => &[
            ("PKE", files::PKE),
            ("IND", files::IND),
            ("PWE_HIGH", files::PWE_HIGH),
            ("PWE_LOW", files::PWE_LOW),
        ],
        PkwKind::StationCommandAddressValue => &[
            ("STATION", files::PKW_STATION),
            ("COMMAND", files::PKW_COMMAND),
            ("ADDRESS", files::PKW_ADDRESS),
            ("VALUE", files::PKW_VALUE),
        ],
        // The profile's names (MM440 OI p.157: "Parameter value, high
        // (PWE1) 3rd word").
        PkwKind::Profidrive => &[
            ("PKE", files::PKE),
            ("IND", files::IND),
            ("PWE1", files::PWE1),
            ("PWE2", files::PWE2),
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
    let label = |code: &str, lang| {
        let name = field.name.get(code);
        let mut text = match index {
            Some(index) => files::field_bit(lang, name, index),
            None => name.to_string(),
        };
        if !choices.is_empty() {
            let values: Vec<String> = choices
                .iter()
                .map(|c| format!("{} = {}", c.value, c.text.get(code)))
                .collect();
            text.push_str(&format!(" ({})", values.join(", ")));
        }
        text
    };
    let parts: Vec<&Text> = std::iter::once(&field.name)
        .chain(choices.iter().map(|c| &c.text))
        .collect();
    Text::composed(&parts, label)
}

/// IOConfigData's MaxInputLength and MaxOutputLength bound what the input
/// and the output CR carry: IO data and status bytes, as the checker reads
/// them (E310, W302, `gsdml::io`; docs/rules.md gives the sources). Each
/// submodule without data (the DAP's, the interface, the ports, a module
/// access point, the empty module's) has its IOPS in the input CR and its
/// IOCS in the output CR: one byte each way; a submodule with data both
/// ways adds its IOPS and the IOCS of the other direction to each.
/// `tests/gsdml_reader.rs` holds these to the checker.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IoNeed {
    /// The module with the most alone: what a limit may not be less than
    /// (E310 otherwise: the module never fits).
    pub least: u16,
    /// Every slot with the largest module it takes: what gsdc writes when
    /// the stack states no limit (W302 otherwise), as far as the
    /// [`MAX_IO_LENGTH`] a CR carries ([`IoNeed::written`]).
    pub full: u32,
}

impl IoNeed {
    /// What gsdc writes without a stated limit: every slot full, at most
    /// what a CR carries. Where that is less, the engineering tool refuses
    /// some configurations (W302), as with a stated smaller limit.
    pub fn written(self) -> u16 {
        u16::try_from(self.full).map_or(MAX_IO_LENGTH, |f| f.min(MAX_IO_LENGTH))
    }
}

/// [`IoNeed`] of the input CR and of the output CR.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IoNeeds {
    pub input: IoNeed,
    pub output: IoNeed,
}

/// A module the slots `slots` take, with the bytes it adds to the input
/// and to the output CR.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Offer {
    pub slots: Slots,
    pub input: u16,
    pub output: u16,
}

impl Offer {
    /// A data module of `layout`, with or without a module access point
    /// (the same each way), in the data modules' slots.
    pub fn data_module(layout: Layout, access_point: bool, slots: Slots) -> Offer {
        let bytes = layout.bytes() + 2 + u16::from(access_point);
        Offer {
            slots,
            input: bytes,
            output: bytes,
        }
    }

    /// The empty module: its IOPS and IOCS.
    pub fn empty(slots: Slots) -> Offer {
        Offer {
            slots,
            input: 1,
            output: 1,
        }
    }

    /// A safety module, whose data differs each way.
    pub fn safety(m: &SafetyModule) -> Offer {
        Offer {
            slots: m.slots,
            input: m.input_bytes() + 2,
            output: m.output_bytes() + 2,
        }
    }
}

/// Where the modules go: the data modules' slots, the empty module and
/// the safety modules.
#[derive(Debug, Clone, Copy)]
pub struct Placement<'a> {
    pub module_slots: Slots,
    pub empty: Option<&'a EmptyModule>,
    pub safety: &'a [SafetyModule],
}

impl<'a> Placement<'a> {
    /// This placement with only the safety modules a DAP offers.
    pub fn offering(self, safety: &'a [SafetyModule]) -> Self {
        Placement { safety, ..self }
    }

    /// The last slot anything goes into.
    pub fn last_used_slot(&self) -> u16 {
        let others = self.empty.iter().map(|e| e.slots);
        last_used_slot(
            self.module_slots,
            others.chain(self.safety.iter().map(|m| m.slots)),
        )
    }
}

/// What the data `modules`, placed as `placement` says, and a DAP of
/// `ports` ports need in each CR.
pub fn io_need<'a>(
    modules: impl Iterator<Item = &'a Module>,
    ports: usize,
    placement: Placement,
) -> IoNeeds {
    let slots = placement.module_slots;
    let offers = modules
        .map(|m| Offer::data_module(m.layout, m.access_point.is_some(), slots))
        .chain(placement.empty.map(|e| Offer::empty(e.slots)))
        .chain(placement.safety.iter().map(Offer::safety));
    io_length(offers, ports)
}

/// [`io_need`] of the modules `offers` gives: what `gsdc import` compares
/// a file's IOConfigData with. With at most 20 words in a data module and
/// 16 ports, one module stays far below the limit of 1440.
pub(crate) fn io_length(offers: impl Iterator<Item = Offer>, ports: usize) -> IoNeeds {
    let offers: Vec<Offer> = offers.collect();
    let device = 2 + u16::try_from(ports).unwrap_or(u16::MAX);
    let need = |bytes: fn(&Offer) -> u16| {
        let largest = offers.iter().map(bytes).max().unwrap_or(0);
        // Each slot anything goes into, with the most it may take.
        let mut slots: Vec<u16> = offers.iter().flat_map(|o| o.slots.iter()).collect();
        slots.sort_unstable();
        slots.dedup();
        let in_slot = |slot: u16| {
            let here = offers.iter().filter(|o| o.slots.iter().contains(&slot));
            u32::from(here.map(bytes).max().unwrap_or(0))
        };
        IoNeed {
            least: largest + device,
            full: u32::from(device) + slots.into_iter().map(in_slot).sum::<u32>(),
        }
    };
    IoNeeds {
        input: need(|o| o.input),
        output: need(|o| o.output),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ir::{Choice, ValueSet};

    /// MOVI-C's first access point by hand: 16 words each way in its
    /// largest module (32 bytes, its IOPS and the other way's IOCS: 34),
    /// the DAP's own submodule, interface and two ports (4), four slots
    /// (2..5) and the empty module's slot 1 alone (1): 4 + 4 x 34 + 1 = 141,
    /// what `gsdc check` reports as its largest configuration (W302 on
    /// MaxInputLength 100). One module alone needs 38.
    #[test]
    fn every_slot_full_is_what_the_largest_configuration_needs() {
        let slots = Slots { first: 2, last: 5 };
        let modules =
            (1..=16).map(|words| Offer::data_module(Layout::new(false, words), false, slots));
        let empty = Offer::empty(Slots { first: 1, last: 5 });
        let need = io_length(modules.chain([empty]), 2);
        let each_way = IoNeed {
            least: 38,
            full: 141,
        };
        assert_eq!(
            need,
            IoNeeds {
                input: each_way,
                output: each_way
            }
        );
        // One slot: both the same, as before module slots.
        let one = io_length(
            [Offer::data_module(
                Layout::new(false, 16),
                false,
                Slots::ONE,
            )]
            .into_iter(),
            2,
        );
        assert_eq!(
            one.input,
            IoNeed {
                least: 38,
                full: 38
            }
        );
        // Never beyond what a CR carries.
        let many = Slots {
            first: 1,
            last: 100,
        };
        let many = io_length(
            [Offer::data_module(Layout::new(false, 16), false, many)].into_iter(),
            2,
        );
        assert_eq!(many.output.full, 4 + 100 * 34);
        assert_eq!(many.output.written(), MAX_IO_LENGTH);
    }

    /// ABB's FENA-11 (its first access point) by hand: its largest data
    /// module, 12 PZD words (24 bytes, its IOPS and the other way's IOCS:
    /// 26), in slot 1, and in slot 2 a safety module, PS2 the larger: 14
    /// bytes in (three words of bits, two Integer16, the 4-byte trailer)
    /// and 10 out (two words of bits, an Integer16, the trailer), each with
    /// its IOPS and the other way's IOCS. With the DAP's own submodule, the
    /// interface and one port (3): in 3 + 26 + 16 = 45, the largest
    /// configuration `gsdc check` reports for FENA's file (W302 on its
    /// MaxInputLength 44); out 3 + 26 + 12 = 41. The data module alone: 29.
    #[test]
    fn a_safety_module_needs_its_own_bytes_each_way() {
        let pzd12 = Offer::data_module(Layout::new(false, 12), false, Slots::ONE);
        let ps2 = Offer {
            slots: Slots { first: 2, last: 2 },
            input: 14 + 2,
            output: 10 + 2,
        };
        let need = io_length([pzd12, ps2].into_iter(), 1);
        assert_eq!(
            need.input,
            IoNeed {
                least: 29,
                full: 45
            }
        );
        assert_eq!(
            need.output,
            IoNeed {
                least: 29,
                full: 41
            }
        );
    }

    #[test]
    fn bits_of_a_field_name_their_place_and_values() {
        let field = BitField {
            first: 9,
            last: 10,
            name: Text {
                en: "Control mode".into(),
                others: vec![("zh".into(), "控制方式".into())],
                gsd: None,
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
        assert_eq!(text.get("zh"), "控制方式 bit 1 (0 = Keypad)");
        // gsdc's word in German, the description's name in English.
        assert_eq!(text.get("de"), "Control mode Bit 1 (0 = Keypad)");
    }
}
