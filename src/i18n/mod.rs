//! gsdc's own words, in every language it has them in: one catalogue of
//! the phrases gsdc itself writes into a description's languages (the
//! GSDML's module, record and category texts, the datasheet's headings and
//! sentences, the meanings of PKW codes that the datasheet and `gsdc
//! decode` give). A description's own texts are the description's; these
//! are gsdc's, and the translations are gsdc's own, not any manual's.
//!
//! Each phrase is an entry of [`phrases!`]: its id, its arguments (numbers
//! and names it takes) and its text in English, Chinese and German, or one
//! text for all (`all:`, a technical name the same in every language). A
//! phrase without arguments is a [`Phrase`] constant, one with arguments a
//! function of the language and the arguments; a text names its arguments
//! as `format!` does (`{n}`), so a placeholder no argument fills does not
//! compile, and the tests below hold every language of every phrase to the
//! same arguments. English and German share their plural rule (one, other):
//! a phrase whose words depend on a count has a form for one apart
//! (`..._one`); Chinese has one form.
//!
//! A table compiled in rather than a localisation crate (fluent, rust-i18n,
//! gettext): the core stays free of I/O and dependencies for build scripts,
//! the output is the same on every machine (no locale, no global state), a
//! missing phrase or argument is a compile error rather than a fallback at
//! run time, and the few plural forms gsdc needs do not call for CLDR rules.
//!
//! A description language gsdc has no words in gets the description's texts
//! and gsdc's words in English (W108 says so).

pub(crate) mod datasheet;
pub(crate) mod device_files;
pub(crate) mod pkw;

pub(crate) use datasheet as sheet;
pub(crate) use device_files as files;
pub(crate) use pkw as codes;

/// A language gsdc has its own words in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Lang {
    En,
    Zh,
    De,
}

impl Lang {
    /// Every language of the catalogue, English first (the order of a
    /// phrase's texts).
    pub(crate) const ALL: [Lang; 3] = [Lang::En, Lang::Zh, Lang::De];

    /// The language of ISO 639-1 `code`, if gsdc has words in it.
    pub(crate) fn of(code: &str) -> Option<Lang> {
        Lang::ALL.into_iter().find(|l| l.code() == code)
    }

    pub(crate) fn code(self) -> &'static str {
        match self {
            Lang::En => "en",
            Lang::Zh => "zh",
            Lang::De => "de",
        }
    }

    /// The language's name in itself, as a language switch shows it.
    pub(crate) fn own_name(self) -> &'static str {
        match self {
            Lang::En => "English",
            Lang::Zh => "中文",
            Lang::De => "Deutsch",
        }
    }

    /// The place of the language's text in a phrase.
    const fn index(self) -> usize {
        match self {
            Lang::En => 0,
            Lang::Zh => 1,
            Lang::De => 2,
        }
    }
}

/// A phrase without arguments, in each language of the catalogue.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Phrase([&'static str; 3]);

impl Phrase {
    pub(crate) fn get(self, lang: impl Into<Lang>) -> &'static str {
        self.0[lang.into().index()]
    }
}

/// One phrase as the tests read it: its id, its arguments, its texts (a
/// phrase the same in every language has the one text three times).
#[cfg(test)]
#[derive(Debug)]
pub(crate) struct Entry {
    pub id: &'static str,
    pub arguments: &'static [&'static str],
    pub texts: [&'static str; 3],
    /// For each language, whether its text is the English by choice
    /// (`same`, or `all:` for a name).
    pub same: [bool; 3],
}

/// Declares phrases: `NAME = { en: "...", zh: "...", de: "..." };` (a
/// [`Phrase`]), `NAME = { all: "..." };` (a name, the same in every
/// language), or `name(arg: Type, ...) = { en: "...{arg}...", ... };` (a
/// function of the language and the arguments, returning a `String`). A
/// language's text may be `same`: the English words, chosen for that
/// language too (German says `Port 1`). And `ENTRIES`, every phrase of the
/// invocation, for the tests.
macro_rules! phrases {
    ($($(#[doc = $doc:literal])* $name:ident $(($($arg:ident: $ty:ty),* $(,)?))? = { $($body:tt)* };)*) => {
        $(phrases!(@one [$(#[doc = $doc])*] $name $(($($arg: $ty),*))? { $($body)* });)*

        /// Every phrase of this part of the catalogue.
        #[cfg(test)]
        pub(crate) const ENTRIES: &[$crate::i18n::Entry] = &[
            $(phrases!(@entry $name $(($($arg),*))? { $($body)* }),)*
        ];
    };
    (@one [$($doc:tt)*] $name:ident { all: $all:literal $(,)? }) => {
        $($doc)*
        pub(crate) const $name: $crate::i18n::Phrase = $crate::i18n::Phrase([$all, $all, $all]);
    };
    (@one [$($doc:tt)*] $name:ident { en: $en:literal, zh: $zh:tt, de: $de:tt $(,)? }) => {
        $($doc)*
        pub(crate) const $name: $crate::i18n::Phrase = $crate::i18n::Phrase([
            $en,
            phrases!(@text $en $zh),
            phrases!(@text $en $de),
        ]);
    };
    (@one [$($doc:tt)*] $name:ident ($($arg:ident: $ty:ty),*) { en: $en:literal, zh: $zh:tt, de: $de:tt $(,)? }) => {
        $($doc)*
        pub(crate) fn $name(lang: impl Into<$crate::i18n::Lang>, $($arg: $ty),*) -> String {
            match lang.into() {
                $crate::i18n::Lang::En => format!($en),
                $crate::i18n::Lang::Zh => phrases!(@format $en $zh),
                $crate::i18n::Lang::De => phrases!(@format $en $de),
            }
        }
    };
    (@text $en:literal same) => { $en };
    (@text $en:literal $text:literal) => { $text };
    (@format $en:literal same) => { format!($en) };
    (@format $en:literal $text:literal) => { format!($text) };
    (@same same) => { true };
    (@same $text:literal) => { false };
    (@entry $name:ident { all: $all:literal $(,)? }) => {
        $crate::i18n::Entry {
            id: stringify!($name),
            arguments: &[],
            texts: [$all, $all, $all],
            same: [true, true, true],
        }
    };
    (@entry $name:ident $(($($arg:ident),*))? { en: $en:literal, zh: $zh:tt, de: $de:tt $(,)? }) => {
        $crate::i18n::Entry {
            id: stringify!($name),
            arguments: &[$($(stringify!($arg)),*)?],
            texts: [$en, phrases!(@text $en $zh), phrases!(@text $en $de)],
            same: [false, phrases!(@same $zh), phrases!(@same $de)],
        }
    };
}
pub(crate) use phrases;

/// `a, b and c` in `lang` (Chinese: `a、b、c`).
pub(crate) fn list(lang: Lang, items: &[String]) -> String {
    match items {
        [] => String::new(),
        [one] => one.clone(),
        [rest @ .., last] => format!(
            "{}{}{last}",
            rest.join(sheet::LIST_SEPARATOR.get(lang)),
            sheet::LIST_LAST_SEPARATOR.get(lang)
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn catalogue() -> impl Iterator<Item = (&'static str, &'static Entry)> {
        [
            ("device files", device_files::ENTRIES),
            ("datasheet", datasheet::ENTRIES),
            ("codes", pkw::ENTRIES),
        ]
        .into_iter()
        .flat_map(|(part, entries)| entries.iter().map(move |e| (part, e)))
    }

    /// `{n}`, `{bytes:02X}`: the names a text's placeholders take, in
    /// order; `{{` and `}}` are braces.
    fn placeholders(text: &str) -> Vec<String> {
        let mut names = Vec::new();
        let mut rest = text.replace("{{", "").replace("}}", "");
        while let Some(open) = rest.find('{') {
            let close = rest[open..].find('}').expect("a placeholder closes") + open;
            let inner = &rest[open + 1..close];
            names.push(inner.split(':').next().unwrap().to_string());
            rest = rest[close + 1..].to_string();
        }
        names
    }

    /// Every phrase in every language: a text in each, each with every
    /// argument the phrase takes (a text that left one out would say less
    /// in that language), and words of its own in each language unless the
    /// catalogue says the English is the translation (`same`, `all:`): a
    /// German or Chinese text copied from the English is a phrase not
    /// translated.
    #[test]
    fn every_phrase_is_in_every_language_with_every_argument() {
        let mut count = 0;
        for (part, entry) in catalogue() {
            let id = format!("{part}: {}", entry.id);
            let mut wanted: Vec<&str> = entry.arguments.to_vec();
            wanted.sort_unstable();
            for (lang, text) in Lang::ALL.iter().zip(entry.texts) {
                assert!(!text.trim().is_empty(), "{id}: no {lang:?} text");
                let mut used = placeholders(text);
                used.sort_unstable();
                used.dedup();
                assert_eq!(used, wanted, "{id}: the {lang:?} text's placeholders");
            }
            for ((lang, text), same) in Lang::ALL.iter().zip(entry.texts).zip(entry.same).skip(1) {
                assert!(
                    same || text != entry.texts[0],
                    "{id}: the {lang:?} text is the English: write `same` if that is the translation"
                );
            }
            count += 1;
        }
        assert!(count > 300, "{count} phrases");
    }

    /// A phrase is found by its id: no id twice in the catalogue.
    #[test]
    fn every_id_is_once_in_the_catalogue() {
        let mut ids: Vec<&str> = catalogue().map(|(_, e)| e.id).collect();
        let all = ids.len();
        ids.sort_unstable();
        ids.dedup();
        assert_eq!(ids.len(), all);
    }

    #[test]
    fn placeholders_are_read_as_format_reads_them() {
        assert_eq!(
            placeholders("{n} words, {{literal}}, 0x{v:02X}"),
            ["n", "v"]
        );
    }

    #[test]
    fn languages_are_found_by_code_and_named_in_themselves() {
        assert_eq!(Lang::of("de"), Some(Lang::De));
        assert_eq!(Lang::of("fr"), None);
        let names: Vec<&str> = Lang::ALL.iter().map(|l| l.own_name()).collect();
        assert_eq!(names, ["English", "中文", "Deutsch"]);
    }

    #[test]
    fn lists_are_joined_as_each_language_joins_them() {
        let items = ["1".to_string(), "2".to_string(), "3".to_string()];
        assert_eq!(list(Lang::En, &items), "1, 2 and 3");
        assert_eq!(list(Lang::Zh, &items), "1、2、3");
        assert_eq!(list(Lang::De, &items), "1, 2 und 3");
        assert_eq!(list(Lang::De, &items[..1]), "1");
    }
}
