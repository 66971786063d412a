//! The IR: a validated, bus-neutral model of one option card, with every
//! default applied and every number computed. Emitters read only this.
//!
//! Identity, telegram and mappings are shared by every bus; what only
//! PROFIBUS needs lives in [`profibus`].

mod cyclic;
pub(crate) mod decision;
pub mod gateway;
pub mod manual;
pub mod mapping;
mod names;
pub mod numbering;
pub mod profibus;
pub mod profinet;
pub mod telegram;

pub use cyclic::{Bus, CyclicModule, ModuleId};
pub use decision::{Decision, DecisionKind};
pub use gateway::Gateway;
pub use mapping::{
    Allowed, EntryKey, EntryType, Holds, MappingEntry, MappingGroup, MappingKind, MappingSet,
    Mappings, PerModule, SetAt, SetKey,
};
pub use names::Ident;
pub(crate) use names::Scope;
pub use numbering::{AddressScheme, Numbering};
pub use profibus::Profibus;
pub use profinet::{safety, Profinet};
pub use telegram::{BitField, Choice, Direction, Layout, PkwKind, Telegram, ValueSet, Word};

/// Bits `first` to `last` (within 0..=7) of a byte, as a mask: a GSD
/// parameter's or a GSDML record value's `Bit` or `BitArea`.
pub fn bits_of_byte(first: u8, last: u8) -> u8 {
    (0xFF >> (7 - last)) & (0xFF << first)
}

use crate::i18n::{self, Phrase};

#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Ir {
    /// The description's file name, without directories: it goes into the
    /// headers of generated files, which must not depend on where they were built.
    pub source_name: String,
    pub fingerprint: Fingerprint,
    pub device: Device,
    pub numbering: Option<Numbering>,
    pub telegram: Telegram,
    pub mappings: Mappings,
    /// The languages besides English that the description's texts use, by
    /// ISO 639-1 code in code order: every device file that has languages
    /// has each of them.
    pub languages: Vec<String>,
    /// What the manuals the description quotes do not give, in the order of
    /// the description: placeholders, its own choices, gsdc's defaults.
    pub decisions: Vec<Decision>,
    /// The languages whose texts the description quotes from the manual;
    /// texts in other languages are the description's translations.
    pub manual_languages: Vec<String>,
    pub profibus: Option<Profibus>,
    pub profinet: Option<Profinet>,
    /// A gateway's nodes, parameters and diagnosis (with `profibus`).
    pub gateway: Option<Gateway>,
    /// What the manual tells the user to set on the drive and the card.
    pub setup: Vec<manual::SetupGroup>,
    /// The manual's worked examples, each a telegram the modules carry.
    pub examples: Vec<manual::Example>,
    /// The texts of the device files that no manual gives: gsdc wrote them
    /// (a module's name, a port's), or wrote them around the description's
    /// words (a module's info text). Every generated file lists them.
    pub wording: Vec<Wording>,
}

/// A text gsdc wrote into a device file: where it stands and what it is.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Wording {
    /// `GSDML IDT_PORT_1`, `GSD Module`.
    pub place: String,
    pub text: Text,
    /// Whether it has the description's words in it, gsdc's around them.
    pub around_the_descriptions: bool,
}

impl Wording {
    /// The bus whose device file holds the text: the GSD's or the GSDML's.
    pub fn bus(&self) -> Bus {
        match self.place.starts_with("GSDML ") {
            true => Bus::Profinet,
            false => Bus::Profibus,
        }
    }

    /// One line for the headers, in English (a GSD's header is ASCII):
    /// `gsdc's wording: GSDML IDT_PORT_1 = "Port 1" (gsdc's, not the
    /// description's)`.
    pub fn summary(&self) -> String {
        let others: Vec<&str> = self
            .text
            .others
            .iter()
            .map(|(code, _)| code.as_str())
            .collect();
        let translated = match others.as_slice() {
            [] => String::new(),
            codes => format!("; in {} gsdc's translation", codes.join(", ")),
        };
        let whose = match self.around_the_descriptions {
            true => "gsdc's words around the description's",
            false => "gsdc's, not the description's",
        };
        format!(
            "gsdc's wording: {} = \"{}\" ({whose}{translated})",
            self.place, self.text.en
        )
    }
}

/// A text in English and any other languages the description gives.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Text {
    /// Every device file has English; generated code is named after it.
    pub en: String,
    /// Other languages by ISO 639-1 code, in the order of their codes.
    pub others: Vec<(String, String)>,
    /// A shorter English form for a GSD's 32 characters, when the
    /// description gives one; the full text goes everywhere else.
    pub gsd: Option<String>,
}

impl Text {
    pub(crate) fn english(text: impl Into<String>) -> Self {
        Text {
            en: text.into(),
            others: Vec::new(),
            gsd: None,
        }
    }

    /// One of gsdc's own phrases ([`crate::i18n`]), in every language gsdc
    /// has words in.
    pub(crate) fn phrase(phrase: Phrase) -> Self {
        Text::gsdc(|lang| phrase.get(lang).to_string())
    }

    /// gsdc's own text, made in every language gsdc has words in.
    pub(crate) fn gsdc(words: impl Fn(i18n::Lang) -> String) -> Self {
        Text::composed(&[], |_, lang| words(lang))
    }

    /// A text made of `parts` (the description's texts) and gsdc's words:
    /// `f(code, lang)` makes it in language `code`, with gsdc's words in
    /// `lang` (English where gsdc has no words in `code`), in every
    /// language of the parts and of gsdc's catalogue.
    pub(crate) fn composed(parts: &[&Text], f: impl Fn(&str, i18n::Lang) -> String) -> Self {
        let mut codes: Vec<&str> = i18n::Lang::ALL
            .iter()
            .map(|lang| lang.code())
            .chain(
                parts
                    .iter()
                    .flat_map(|t| t.others.iter().map(|(c, _)| c.as_str())),
            )
            .filter(|code| *code != "en")
            .collect();
        codes.sort_unstable();
        codes.dedup();
        let words = |code: &str| i18n::Lang::of(code).unwrap_or(i18n::Lang::En);
        Text {
            en: f("en", i18n::Lang::En),
            others: codes
                .into_iter()
                .map(|code| (code.to_string(), f(code, words(code))))
                .collect(),
            gsd: None,
        }
    }

    /// The text in `language` (an ISO 639-1 code), or in English when it has
    /// none in that language.
    pub fn get(&self, language: &str) -> &str {
        self.others
            .iter()
            .find(|(code, _)| code == language)
            .map_or(&self.en, |(_, text)| text)
    }

    /// What a GSD file shows: the short form, or the English.
    pub fn for_gsd(&self) -> &str {
        self.gsd.as_deref().unwrap_or(&self.en)
    }

    /// Each language's text (the short form too) changed by `f`.
    pub(crate) fn map(&self, f: impl Fn(&str) -> String) -> Text {
        Text {
            en: f(&self.en),
            others: self
                .others
                .iter()
                .map(|(code, text)| (code.clone(), f(text)))
                .collect(),
            gsd: self.gsd.as_deref().map(&f),
        }
    }
}

#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Device {
    pub vendor: String,
    pub family: String,
    pub model: String,
    /// With a GSD, the revision and the releases are always there (E004).
    pub revision: Option<String>,
    pub hardware_release: Option<String>,
    pub software_release: Option<String>,
    pub order_number: Option<String>,
    pub name: Text,
    pub info: Option<Text>,
    /// The device symbol: a 70 x 40, 16-colour Windows bitmap.
    pub symbol: Option<Vec<u8>>,
}

/// FNV-1a (64 bit) of the description text with line ends normalised to LF,
/// so a checkout with CRLF line ends has the same fingerprint. It identifies
/// a description; it is not a security measure.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Fingerprint(pub u64);

impl Fingerprint {
    pub fn of(text: &str) -> Self {
        const OFFSET: u64 = 0xcbf2_9ce4_8422_2325;
        const PRIME: u64 = 0x0000_0100_0000_01b3;
        let mut hash = OFFSET;
        let bytes = text.as_bytes();
        for (i, &byte) in bytes.iter().enumerate() {
            if byte == b'\r' && bytes.get(i + 1) == Some(&b'\n') {
                continue;
            }
            hash ^= u64::from(byte);
            hash = hash.wrapping_mul(PRIME);
        }
        Fingerprint(hash)
    }
}

impl std::fmt::Display for Fingerprint {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{:016x}", self.0)
    }
}

#[cfg(test)]
mod tests {
    use super::Fingerprint;

    #[test]
    fn fingerprint_is_fnv1a_and_ignores_crlf() {
        // FNV-1a 64 reference values: "" and "a".
        assert_eq!(Fingerprint::of("").to_string(), "cbf29ce484222325");
        assert_eq!(Fingerprint::of("a").to_string(), "af63dc4c8601ec8c");
        assert_eq!(Fingerprint::of("a\r\nb"), Fingerprint::of("a\nb"));
        assert_ne!(Fingerprint::of("a\nb"), Fingerprint::of("a\nc"));
    }
}
