//! `[[profinet.channel_diagnosis]]`: a GSDML file's `ChannelDiagItem`s
//! and `ProfileChannelDiagItem`s, each with its name and help in every
//! language. One the description cannot say (extended diagnosis, another
//! attribute, an error type outside the schema's range) is left out
//! (W600) with why.

use super::{attribute, text};
use crate::device::pn::{DiagItem, PnDevice};
use crate::device::Text;
use crate::import::toml_out::TomlOut;
use crate::import::Notes;

/// The entries of the file's channel diagnosis the description can say.
pub(super) fn entries<'a>(device: &'a PnDevice, notes: &mut Notes) -> Vec<Entry<'a>> {
    let mut said: Vec<Entry> = Vec::new();
    for item in &device.diagnosis {
        let entry = entry(item).and_then(|e| match said.iter().any(|s| s.key() == e.key()) {
            true => Err("its error type is another item's (in its API), which the description's channel diagnosis gives once"),
            false => Ok(e),
        });
        match entry {
            Ok(entry) => said.push(entry),
            Err(why) => notes.unsaid(
                &format!("{} {}", item.element, item.error_type),
                &item.place,
                why,
            ),
        }
    }
    said
}

/// One channel diagnosis, as its `[[profinet.channel_diagnosis]]` says it.
pub(super) struct Entry<'a> {
    item: &'a DiagItem,
    name: &'a Text,
    api: Option<u32>,
}

impl Entry<'_> {
    /// What identifies it: its error type in its API.
    fn key(&self) -> (Option<u32>, u32) {
        (self.api, self.item.error_type)
    }

    pub fn write(&self, out: &mut TomlOut) {
        out.array_item("profinet.channel_diagnosis");
        out.key("error_type", format!("0x{:04X}", self.item.error_type));
        if let Some(api) = self.api {
            out.key("api", format!("0x{api:04X}"));
        }
        out.key("name", text(self.name));
        if let Some(help) = &self.item.help {
            out.key("help", text(help));
        }
    }
}

/// A text in each language the file gives it in.
fn every_language(t: &Text) -> impl Iterator<Item = &str> {
    std::iter::once(&*t.primary).chain(t.translations.iter().map(|(_, text)| text))
}

fn entry(item: &DiagItem) -> Result<Entry<'_>, &'static str> {
    if !item.extended.is_empty() {
        return Err(
            "the description's channel diagnosis has no extended diagnosis (ExtChannelDiagItem)",
        );
    }
    let Some(name) = &item.name else {
        return Err("it has no name");
    };
    let texts = std::iter::once(name).chain(&item.help);
    if !texts
        .flat_map(every_language)
        .all(crate::lower::is_clean_text)
    {
        return Err("a text of it is empty or has a line break or another control character, which the description's texts do not hold");
    }
    let profile = match &*item.element {
        "ChannelDiagItem" => false,
        "ProfileChannelDiagItem" => true,
        _ => return Err(
            "the description's channel diagnosis is ChannelDiagItems and ProfileChannelDiagItems",
        ),
    };
    let api = attribute(&item.attributes, "API")
        .and_then(|a| a.parse::<u32>().ok().filter(|&api| api >= 1));
    let others = item.attributes.iter().any(|a| &*a.name != "API");
    if others || profile != api.is_some() {
        return Err("the description's channel diagnosis has an error type, a profile's API, a name and a help text, and no other attribute");
    }
    let range = match profile {
        true => crate::lower::PROFILE_ERROR_TYPES,
        false => crate::lower::CHANNEL_ERROR_TYPES,
    };
    if !u16::try_from(item.error_type).is_ok_and(|t| range.contains(&t)) {
        return Err("its error type is outside the schema's range for its element");
    }
    Ok(Entry { item, name, api })
}
