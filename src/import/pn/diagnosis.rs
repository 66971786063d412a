//! `[[profinet.channel_diagnosis]]`: a GSDML file's `ChannelDiagItem`s
//! and `ProfileChannelDiagItem`s, each with its name and help in every
//! language, and their `ExtChannelDiagItem`s with the `DataItem`s of their
//! add values. One the description cannot say (a profile's extended
//! diagnosis, another attribute, an error type outside the schema's range)
//! is left out (W600) with why: an extended one alone, its channel
//! diagnosis imported without it.

use super::{attribute, text};
use crate::device::pn::{DiagItem, PnDevice};
use crate::device::Text;
use crate::import::toml_out::{list, TomlOut};
use crate::import::Notes;
use crate::ir::profinet::AddValueType;
use crate::lower::{
    ADD_VALUE_BYTES, CHANNEL_ERROR_TYPES, EXTENDED_ERROR_TYPES, PROFILE_ERROR_TYPES,
};

/// The attributes an `ExtChannelDiagItem`'s add value flattens to, each
/// `DataItem`'s values joined with blanks.
const ADD_VALUE_IDS: &str = "ExtChannelAddValue/DataItem@Id";
const ADD_VALUE_TYPES: &str = "ExtChannelAddValue/DataItem@DataType";

/// The entries of the file's channel diagnosis the description can say.
pub(super) fn entries<'a>(device: &'a PnDevice, notes: &mut Notes) -> Vec<Entry<'a>> {
    let mut said: Vec<Entry> = Vec::new();
    for item in &device.diagnosis {
        // Before the item's texts, whose notes would speak of an item not
        // imported.
        let again = said.iter().any(|s| s.key() == (api(item), item.error_type));
        let entry = match again {
            true => Err("its error type is another item's (in its API), which the description's channel diagnosis gives once"),
            false => entry(item, notes),
        };
        match entry {
            Ok(entry) => said.push(entry),
            Err(why) => notes.unsaid(&subject(item), &item.place, why),
        }
    }
    said
}

/// Its `API`, when it is one (1 and up).
fn api(item: &DiagItem) -> Option<u32> {
    attribute(&item.attributes, "API").and_then(|a| a.parse::<u32>().ok().filter(|&api| api >= 1))
}

/// A diagnosis item as a finding names it: `ChannelDiagItem 4097`.
fn subject(item: &DiagItem) -> String {
    format!("{} {}", item.element, item.error_type)
}

/// One channel diagnosis, as its `[[profinet.channel_diagnosis]]` says it.
pub(super) struct Entry<'a> {
    item: &'a DiagItem,
    name: &'a Text,
    help: Option<&'a Text>,
    api: Option<u32>,
    extended: Vec<Extended<'a>>,
}

/// One extended error type, as its `[[profinet.channel_diagnosis.extended]]`
/// says it.
struct Extended<'a> {
    item: &'a DiagItem,
    name: &'a Text,
    help: Option<&'a Text>,
    add_value: Vec<(u8, AddValueType)>,
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
        if let Some(help) = self.help {
            out.key("help", text(help));
        }
        for e in &self.extended {
            e.write(out);
        }
    }
}

impl Extended<'_> {
    fn write(&self, out: &mut TomlOut) {
        out.array_item("profinet.channel_diagnosis.extended");
        out.key("error_type", format!("0x{:04X}", self.item.error_type));
        out.key("name", text(self.name));
        if let Some(help) = self.help {
            out.key("help", text(help));
        }
        if !self.add_value.is_empty() {
            let items = self
                .add_value
                .iter()
                .map(|(id, t)| format!("{{ id = {id}, type = \"{}\" }}", t.name()));
            out.key("add_value", list(items));
        }
    }
}

/// A text in each language the file gives it in.
fn every_language(t: &Text) -> impl Iterator<Item = &str> {
    std::iter::once(&*t.primary).chain(t.translations.iter().map(|(_, text)| text))
}

/// Its name and help, when the description holds them. A help empty in
/// every language (MOVI-C's channel diagnoses') is no help, which the
/// engineering tool shows alike: it is left out, with a note.
fn texts<'a>(
    item: &'a DiagItem,
    notes: &mut Notes,
) -> Result<(&'a Text, Option<&'a Text>), &'static str> {
    let Some(name) = &item.name else {
        return Err("it has no name");
    };
    let empty = |t: &Text| every_language(t).all(str::is_empty);
    let help = item.help.as_ref().filter(|h| !empty(h));
    if !std::iter::once(name)
        .chain(help)
        .flat_map(every_language)
        .all(crate::lower::is_clean_text_of_lines)
    {
        return Err("a text of it is empty or has a control character other than a line break, which the description's texts do not hold");
    }
    if item.help.is_some() && help.is_none() {
        notes.unsaid(
            &format!("the Help of {}", subject(item)),
            &item.place,
            "its text is empty in every language, which the description's texts are not; the engineering tool shows no help for it either way",
        );
    }
    Ok((name, help))
}

fn entry<'a>(item: &'a DiagItem, notes: &mut Notes) -> Result<Entry<'a>, &'static str> {
    let profile = match &*item.element {
        "ChannelDiagItem" => false,
        "ProfileChannelDiagItem" => true,
        _ => return Err(
            "the description's channel diagnosis is ChannelDiagItems and ProfileChannelDiagItems",
        ),
    };
    let api = api(item);
    let others = item.attributes.iter().any(|a| &*a.name != "API");
    if others || profile != api.is_some() {
        return Err("the description's channel diagnosis has an error type, a profile's API, a name and a help text, and no other attribute");
    }
    let range = match profile {
        true => PROFILE_ERROR_TYPES,
        false => CHANNEL_ERROR_TYPES,
    };
    if !u16::try_from(item.error_type).is_ok_and(|t| range.contains(&t)) {
        return Err("its error type is outside the schema's range for its element");
    }
    let (name, help) = texts(item, notes)?;
    let mut extended: Vec<Extended> = Vec::new();
    for e in &item.extended {
        let said = match extended.iter().any(|s| s.item.error_type == e.error_type) {
            true => Err("its error type is another extended item's of its channel diagnosis"),
            false => extended_entry(e, notes),
        };
        match said {
            Ok(said) => extended.push(said),
            Err(why) => notes.unsaid(&format!("{} {}", subject(item), subject(e)), &e.place, why),
        }
    }
    Ok(Entry {
        item,
        name,
        help,
        api,
        extended,
    })
}

fn extended_entry<'a>(item: &'a DiagItem, notes: &mut Notes) -> Result<Extended<'a>, &'static str> {
    if &*item.element != "ExtChannelDiagItem" {
        return Err("the description's extended diagnosis is ExtChannelDiagItems");
    }
    if !u16::try_from(item.error_type).is_ok_and(|t| EXTENDED_ERROR_TYPES.contains(&t)) {
        return Err("its error type is outside the schema's range for its element");
    }
    let others = item
        .attributes
        .iter()
        .any(|a| ![ADD_VALUE_IDS, ADD_VALUE_TYPES].contains(&&*a.name));
    if others {
        return Err("the description's extended diagnosis has an error type, a name, a help text and its add value's DataItems, and no other attribute");
    }
    let add_value = add_value(item).ok_or(
        "its add value's DataItems are not each an Id once and a type, 4 bytes together at most",
    )?;
    let (name, help) = texts(item, notes)?;
    Ok(Extended {
        item,
        name,
        help,
        add_value,
    })
}

/// The add value's `DataItem`s, when lowering would take them back: each
/// Id once, a type of the schema's, no wider together than the add value.
fn add_value(item: &DiagItem) -> Option<Vec<(u8, AddValueType)>> {
    let words =
        |name| attribute(&item.attributes, name).map_or(Vec::new(), |v| v.split(' ').collect());
    let (ids, types) = (words(ADD_VALUE_IDS), words(ADD_VALUE_TYPES));
    if ids.len() != types.len() {
        return None;
    }
    let mut items: Vec<(u8, AddValueType)> = Vec::new();
    for (id, data_type) in ids.into_iter().zip(types) {
        let id: u8 = id.parse().ok()?;
        if items.iter().any(|&(seen, _)| seen == id) {
            return None;
        }
        items.push((id, AddValueType::from_name(data_type)?));
    }
    let bytes: u32 = items.iter().map(|(_, t)| u32::from(t.bytes())).sum();
    (bytes <= u32::from(ADD_VALUE_BYTES)).then_some(items)
}
