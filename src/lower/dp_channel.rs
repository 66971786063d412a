//! `[[profibus.channel_diagnosis]]`: the error types the card reports in a
//! channel's diagnosis (`Channel_Diag`), a block of
//! [`crate::spec::DP_CHANNEL_DIAG_BYTES`] whose third carries the error type
//! in bits 0 to 4: 0 to 31.

use super::checks::Checker;
use crate::description::dp::ChannelDiagnosis as Given;
use crate::ir::profibus::ChannelDiagnosis;
use crate::ir::{Ident, Scope};
use std::collections::BTreeSet;
use toml::Spanned;

const MAX_ERROR_TYPE: i64 = 31;

/// Each entry in error type order; E101 for an error type beyond 5 bits,
/// E105 for one given twice; `None` when one is wrong.
pub fn lower(cx: &mut Checker, given: &[Spanned<Given>]) -> Option<Vec<ChannelDiagnosis>> {
    let mut seen = BTreeSet::new();
    let mut names = Scope::default();
    let mut all = Vec::new();
    for (index, entry) in given.iter().enumerate() {
        all.extend(one(cx, index, entry.get_ref(), &mut seen, &mut names));
    }
    all.sort_by_key(|d| d.error_type);
    (all.len() == given.len()).then_some(all)
}

fn one(
    cx: &mut Checker,
    index: usize,
    entry: &Given,
    seen: &mut BTreeSet<u8>,
    names: &mut Scope,
) -> Option<ChannelDiagnosis> {
    let what = format!("profibus.channel_diagnosis[{index}].error_type");
    let at = entry.error_type.span();
    let value = i64::from(*entry.error_type.get_ref());
    let error_type: u8 = cx.in_range(value, 0, MAX_ERROR_TYPE, at.clone(), &what)?;
    if !seen.insert(error_type) {
        cx.duplicate(format!("channel diagnosis {error_type}"), at);
        return None;
    }
    let limit = crate::gsd::keyword_max_len("Channel_Diag");
    let name = cx.text(&entry.name, Some(limit), "a channel diagnosis's name");
    let ident = names.unique(ident_of(&name.en, error_type), error_type);
    Some(ChannelDiagnosis {
        error_type,
        name,
        ident,
    })
}

/// `dp_channel_diagnosis_<name>`, or with the error type for a name
/// without letters or digits (Siemens' IM174 names unused types "-").
fn ident_of(name: &str, error_type: u8) -> Ident {
    const PREFIX: [&str; 3] = ["dp", "channel", "diagnosis"];
    let named = Ident::from_text(&format!("{} {name}", PREFIX.join(" ")), "diagnosis");
    if named == Ident::of(&PREFIX) {
        Ident::of(&[PREFIX[0], PREFIX[1], PREFIX[2], &error_type.to_string()])
    } else {
        named
    }
}
