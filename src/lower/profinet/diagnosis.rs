//! `[[profinet.channel_diagnosis]]`: the error types the card reports as
//! channel diagnosis, with the texts the engineering tool shows for them.
//! The ranges are the PI schema's: a `ChannelDiagItem`'s 15 to 32767
//! (0x0100 up the vendor's own), a profile's `ProfileChannelDiagItem`'s
//! 0x9000 to 0x9FFF in its API.

use crate::description as raw;
use crate::diag::Diagnostic;
use crate::ir::profinet::{ChannelDiagnosis, TextRef};
use crate::ir::{Ident, Scope};
use crate::lower::checks::Checker;
use std::collections::BTreeSet;
use std::ops::RangeInclusive;
use toml::Spanned;

pub(crate) const CHANNEL_ERROR_TYPES: RangeInclusive<u16> = 15..=32767;
pub(crate) const PROFILE_ERROR_TYPES: RangeInclusive<u16> = 0x9000..=0x9FFF;

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
    let name = cx.text(&entry.name, None, &at("name"));
    let help = entry.help.as_ref().map(|h| cx.text(h, None, &at("help")));
    let id = match api {
        Some(api) => format!("IDT_DIAG_{api:X}_{error_type:04X}"),
        None => format!("IDT_DIAG_{error_type:04X}"),
    };
    let ident = names.unique(
        Ident::from_text(&format!("channel diagnosis {}", name.en), "diagnosis"),
        format!("{error_type:x}"),
    );
    Some(ChannelDiagnosis {
        error_type,
        api,
        help: help.map(|h| TextRef::new(format!("{id}_HELP"), h)),
        name: TextRef::new(id, name),
        ident,
    })
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
