//! `[[profinet.channel_diagnosis]]`: the error types the card reports as
//! channel diagnosis, with the texts the engineering tool shows for them,
//! and their extended error types. The ranges are the PI schema's: a
//! `ChannelDiagItem`'s 15 to 32767 (0x0100 up the vendor's own), a
//! profile's `ProfileChannelDiagItem`'s 0x9000 to 0x9FFF in its API, an
//! `ExtChannelDiagItem`'s 1 to 32767.

use crate::description as raw;
use crate::diag::Diagnostic;
use crate::ir::profinet::{AddValueType, ChannelDiagnosis, ExtendedDiagnosis, TextRef};
use crate::ir::{Ident, Scope};
use crate::lower::checks::Checker;
use std::collections::BTreeSet;
use std::ops::RangeInclusive;
use toml::Spanned;

pub(crate) const CHANNEL_ERROR_TYPES: RangeInclusive<u16> = 15..=32767;
pub(crate) const PROFILE_ERROR_TYPES: RangeInclusive<u16> = 0x9000..=0x9FFF;
pub(crate) const EXTENDED_ERROR_TYPES: RangeInclusive<u16> = 1..=32767;

/// The bytes of a diagnosis's ExtChannelAddValue on the wire (IEC 61158-6-10's
/// ExtChannelDiagnosis: ChannelNumber, ChannelProperties, ChannelErrorType,
/// ExtChannelErrorType, then the Unsigned32 ExtChannelAddValue), which its
/// `DataItem`s describe.
pub(crate) const ADD_VALUE_BYTES: u8 = 4;

/// Each entry; E101 for an error type outside its element's range or an
/// API of 0, E105 for one given twice (in its API).
pub fn lower(
    cx: &mut Checker,
    given: &[Spanned<raw::ChannelDiagnosis>],
) -> Option<Vec<ChannelDiagnosis>> {
    let mut seen = BTreeSet::new();
    let mut names = Scope::default();
    let mut all = Vec::new();
    let mut complete = true;
    for (index, entry) in given.iter().enumerate() {
        match one(cx, index, entry.get_ref(), &mut seen, &mut names) {
            Some(diagnosis) => all.push(diagnosis),
            None => complete = false,
        }
    }
    complete.then_some(all)
}

fn one(
    cx: &mut Checker,
    index: usize,
    entry: &raw::ChannelDiagnosis,
    seen: &mut BTreeSet<(Option<u32>, u16)>,
    names: &mut Scope,
) -> Option<ChannelDiagnosis> {
    let at = |key: &str| format!("profinet.channel_diagnosis[{index}].{key}");
    let api = match &entry.api {
        Some(api) => Some(cx.spanned_in_range(api, 1, u32::MAX.into(), &at("api"))?),
        None => None,
    };
    let error_type = error_type(cx, &entry.error_type, api)?;
    if !seen.insert((api, error_type)) {
        cx.duplicate(
            format!("channel diagnosis 0x{error_type:04X}"),
            entry.error_type.span(),
        );
        return None;
    }
    let id = match api {
        Some(api) => format!("IDT_DIAG_{api:X}_{error_type:04X}"),
        None => format!("IDT_DIAG_{error_type:04X}"),
    };
    let (name, help) = name_and_help(cx, (&entry.name, entry.help.as_ref()), &id, at);
    let ident = names.unique(
        Ident::from_text(&format!("channel diagnosis {}", name.text.en), "diagnosis"),
        format!("{error_type:x}"),
    );
    let mut extended = Vec::new();
    let mut seen_extended = BTreeSet::new();
    for (at_extended, given) in entry.extended.iter().enumerate() {
        let parent = Parent {
            error_type,
            id: &id,
            at: &at(&format!("extended[{at_extended}]")),
        };
        let lowered = extended_one(cx, &parent, given.get_ref(), &mut seen_extended, names);
        extended.extend(lowered);
    }
    (extended.len() == entry.extended.len()).then_some(ChannelDiagnosis {
        error_type,
        api,
        name,
        help,
        ident,
        extended,
    })
}

/// A diagnosis's name and help, texts that may break lines, with their
/// TextIds: `id`, and `id` with `_HELP`.
fn name_and_help(
    cx: &mut Checker,
    (name, help): (&Spanned<raw::Text>, Option<&Spanned<raw::Text>>),
    id: &str,
    at: impl Fn(&str) -> String,
) -> (TextRef, Option<TextRef>) {
    let name = cx.text_of_lines_allowed(name, &at("name"));
    let help = help.map(|h| cx.text_of_lines_allowed(h, &at("help")));
    (
        TextRef::new(id.to_string(), name),
        help.map(|h| TextRef::new(format!("{id}_HELP"), h)),
    )
}

/// What an extended error type takes from its channel diagnosis.
struct Parent<'a> {
    error_type: u16,
    /// The channel diagnosis's TextId, which its extended ones extend.
    id: &'a str,
    /// Where the extended one is in the description.
    at: &'a str,
}

/// One extended error type: E101 out of the schema's range, E105 given
/// twice in its channel diagnosis.
fn extended_one(
    cx: &mut Checker,
    parent: &Parent,
    given: &raw::ExtendedDiagnosis,
    seen: &mut BTreeSet<u16>,
    names: &mut Scope,
) -> Option<ExtendedDiagnosis> {
    let at = |key: &str| format!("{}.{key}", parent.at);
    let (min, max) = (*EXTENDED_ERROR_TYPES.start(), *EXTENDED_ERROR_TYPES.end());
    let error_type: u16 =
        cx.spanned_in_range(&given.error_type, min.into(), max.into(), &at("error_type"))?;
    if !seen.insert(error_type) {
        cx.duplicate(
            format!(
                "extended error type 0x{error_type:04X} of channel diagnosis 0x{:04X}",
                parent.error_type
            ),
            given.error_type.span(),
        );
        return None;
    }
    let id = format!("{}_{error_type:04X}", parent.id);
    let (name, help) = name_and_help(cx, (&given.name, given.help.as_ref()), &id, at);
    let add_value = add_value(cx, &given.add_value)?;
    let ident = names.unique(
        Ident::from_text(&format!("extended diagnosis {}", name.text.en), "diagnosis"),
        format!("{:x}_{error_type:x}", parent.error_type),
    );
    Some(ExtendedDiagnosis {
        error_type,
        name,
        help,
        add_value,
        ident,
    })
}

/// The add value's `DataItem`s: each Id once (E105), and together no wider
/// than the add value they describe (E187).
fn add_value(
    cx: &mut Checker,
    given: &[Spanned<raw::AddValueItem>],
) -> Option<Vec<(u8, AddValueType)>> {
    let mut items: Vec<(u8, AddValueType)> = Vec::new();
    for item in given {
        let item = item.get_ref();
        let id = *item.id.get_ref();
        if items.iter().any(|&(seen, _)| seen == id) {
            cx.duplicate(format!("add value DataItem Id {id}"), item.id.span());
            return None;
        }
        items.push((id, *item.data_type.get_ref()));
    }
    let bytes: u32 = items.iter().map(|(_, t)| u32::from(t.bytes())).sum();
    if bytes > u32::from(ADD_VALUE_BYTES) {
        // From the first item to the last: more than one, to be too wide.
        let span = given[0].span().start..given[given.len() - 1].span().end;
        cx.push(
            Diagnostic::error(
                "E187",
                format!("the add value's DataItems take {bytes} bytes, more than the add value's {ADD_VALUE_BYTES}"),
            )
            .at(span)
            .label("too wide")
            .help("a diagnosis carries its ExtChannelAddValue in an Unsigned32: describe it in DataItems of 4 bytes together, at most"),
        );
        return None;
    }
    Some(items)
}

/// The error type, in its element's range (E101, in hex as GSDML files'
/// readers and the profiles write error types): a profile's with its API.
fn error_type(cx: &mut Checker, given: &Spanned<u16>, api: Option<u32>) -> Option<u16> {
    let value = *given.get_ref();
    let range = match api {
        Some(_) => PROFILE_ERROR_TYPES,
        None => CHANNEL_ERROR_TYPES,
    };
    if range.contains(&value) {
        return Some(value);
    }
    let (message, label, help) = match api {
        None if PROFILE_ERROR_TYPES.contains(&value) => (
            format!("0x{value:04X} is a profile's error type, without its API"),
            "a profile's error type",
            "error types 0x9000 to 0x9FFF are a profile's: give its api (PROFIdrive's 0x3A00), or an error type from 0x000F to 0x7FFF".to_string(),
        ),
        Some(_) => (
            format!("error type 0x{value:04X} is out of range for a profile's"),
            "out of range",
            "with an api the error type is the profile's, 0x9000 to 0x9FFF; leave api out for the card's own (0x000F to 0x7FFF)".to_string(),
        ),
        None => (
            format!("error type 0x{value:04X} is out of range"),
            "out of range",
            "a channel diagnosis error type is 0x000F to 0x7FFF (0x0100 and up the card's own), or a profile's 0x9000 to 0x9FFF with its api".to_string(),
        ),
    };
    cx.push(
        Diagnostic::error("E101", message)
            .at(given.span())
            .label(label)
            .help(help),
    );
    None
}
