//! The GSD keyword schema (`schemas/gsd-keywords.toml`), compiled into the
//! binary and parsed once.

use std::collections::HashMap;
use std::sync::OnceLock;

use serde::Deserialize;

use crate::gsd::model::Baud;

/// A keyword's value type.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Kind {
    Unsigned8,
    Unsigned16,
    Unsigned32,
    Bool,
    String,
    /// A comma-separated list of bytes.
    Octets,
    /// `main@sub@sub`.
    Family,
    /// Opens a block; the reader checks its shape.
    Block,
}

impl Kind {
    /// The numbers the type holds (for octets: each byte).
    pub fn range(self) -> (i64, i64) {
        match self {
            Kind::Unsigned8 | Kind::Octets | Kind::Family => (0, 0xFF),
            Kind::Unsigned16 => (0, 0xFFFF),
            Kind::Unsigned32 => (0, 0xFFFF_FFFF),
            Kind::Bool => (0, 1),
            Kind::String | Kind::Block => (i64::MIN, i64::MAX),
        }
    }

    pub fn describe(self) -> &'static str {
        match self {
            Kind::Unsigned8 => "an Unsigned8 number",
            Kind::Unsigned16 => "an Unsigned16 number",
            Kind::Unsigned32 => "an Unsigned32 number",
            Kind::Bool => "0 or 1",
            Kind::String => "a string in double quotes",
            Kind::Octets => "a comma-separated list of bytes",
            Kind::Family => "a slave family like `1@Drives`",
            Kind::Block => "a block",
        }
    }
}

/// What the schema says about one keyword.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct KeywordSpec {
    #[serde(rename = "type")]
    pub kind: Kind,
    pub min: Option<i64>,
    pub max: Option<i64>,
    pub max_len: Option<usize>,
    #[serde(default)]
    pub mandatory: bool,
    pub revision: i64,
    #[serde(default)]
    pub index: bool,
    #[serde(default)]
    pub repeatable: bool,
}

impl KeywordSpec {
    /// Allowed numbers: the schema's bounds within the type's range. For
    /// octets `max` bounds the count, not the bytes.
    pub fn number_range(&self) -> (i64, i64) {
        let (lo, hi) = self.kind.range();
        if self.kind == Kind::Octets {
            return (lo, hi);
        }
        (
            self.min.unwrap_or(lo).max(lo),
            self.max.unwrap_or(hi).min(hi),
        )
    }
}

/// A keyword of the schema with the name the specification spells.
#[derive(Debug)]
pub struct Keyword {
    pub name: String,
    pub spec: KeywordSpec,
}

pub struct Schema {
    by_key: HashMap<String, Keyword>,
}

/// Keyword prefixes and suffixes that carry a baud rate in their name.
const BAUD_PREFIXES: [&str; 3] = ["maxtsdr_", "transmission_delay_", "reaction_delay_"];
const BAUD_SUFFIX: &str = "_supp";

impl Schema {
    fn load() -> Schema {
        let text = include_str!("../../schemas/gsd-keywords.toml");
        // The schema ships inside the binary and a unit test parses it, so a
        // failure here is a build defect, not something a user's input causes.
        let table: HashMap<String, KeywordSpec> =
            toml::from_str(text).expect("schemas/gsd-keywords.toml is valid");
        let by_key = table
            .into_iter()
            .map(|(name, spec)| (name.to_ascii_lowercase(), Keyword { name, spec }))
            .collect();
        Schema { by_key }
    }

    /// The schema entry for a normalized keyword (see [`normalize`]).
    pub fn lookup(&self, key: &str) -> Option<&Keyword> {
        if let Some(k) = self.by_key.get(key) {
            return Some(k);
        }
        let (pattern, _) = baud_pattern(key)?;
        self.by_key.get(&pattern)
    }

    pub fn keywords(&self) -> impl Iterator<Item = &Keyword> {
        self.by_key.values()
    }

    pub fn mandatory(&self) -> impl Iterator<Item = &Keyword> {
        self.by_key.values().filter(|k| k.spec.mandatory)
    }
}

pub fn schema() -> &'static Schema {
    static SCHEMA: OnceLock<Schema> = OnceLock::new();
    SCHEMA.get_or_init(Schema::load)
}

/// A keyword as the schema keys it: lower case, blanks as `_` (Siemens
/// writes `24V Pins`), and `_!bit` as `_not_bit` (Siemens writes
/// `Unit_Diag_!Bit` for `Unit_Diag_Not_Bit`).
pub fn normalize(name: &str) -> String {
    // Nearly every keyword is plain: lower-casing it is all there is to do.
    if !name
        .bytes()
        .any(|b| b.is_ascii_whitespace() || b == b'!' || !b.is_ascii())
    {
        return name.to_ascii_lowercase();
    }
    let mut key = String::with_capacity(name.len());
    let mut blank = false;
    for c in name.chars() {
        if c.is_whitespace() {
            blank = true;
            continue;
        }
        if blank {
            key.push('_');
            blank = false;
        }
        key.push(c.to_ascii_lowercase());
    }
    if key.contains("_!bit") {
        key = key.replace("_!bit", "_not_bit");
    }
    key
}

/// Whether the keyword as written differs from the specification's
/// spelling in more than letter case (see [`normalize`]).
pub fn is_nonstandard_spelling(name: &str) -> bool {
    name.contains(char::is_whitespace) || name.contains('!')
}

/// `maxtsdr_1.5m` -> (`maxtsdr_<baud>`, 1.5M); `12m_supp` -> (`<baud>_supp`, 12M).
pub fn baud_pattern(key: &str) -> Option<(String, Baud)> {
    if let Some(baud) = key.strip_suffix(BAUD_SUFFIX).and_then(Baud::parse) {
        return Some((format!("<baud>{BAUD_SUFFIX}"), baud));
    }
    BAUD_PREFIXES.iter().find_map(|prefix| {
        let baud = Baud::parse(key.strip_prefix(prefix)?)?;
        Some((format!("{prefix}<baud>"), baud))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn schema_parses_and_has_the_mandatory_keywords() {
        let mut names: Vec<_> = schema().mandatory().map(|k| k.name.as_str()).collect();
        names.sort_unstable();
        assert_eq!(
            names,
            [
                "GSD_Revision",
                "Hardware_Release",
                "Ident_Number",
                "Max_Diag_Data_Len",
                "Min_Slave_Intervall",
                "Model_Name",
                "Protocol_Ident",
                "Revision",
                "Slave_Family",
                "Software_Release",
                "Station_Type",
                "Vendor_Name",
            ]
        );
    }

    #[test]
    fn baud_keywords_share_one_entry() {
        let k = schema().lookup("maxtsdr_1.5m").unwrap();
        assert_eq!(k.name, "MaxTsdr_<baud>");
        assert_eq!(schema().lookup("45.45_supp").unwrap().spec.kind, Kind::Bool);
        assert!(schema().lookup("maxtsdr_2m").is_none());
    }

    #[test]
    fn normalize_handles_siemens_spellings() {
        assert_eq!(normalize("24V  Pins"), "24v_pins");
        assert_eq!(normalize("Unit_Diag_!Bit"), "unit_diag_not_bit");
        assert!(is_nonstandard_spelling("24V Pins"));
        assert!(!is_nonstandard_spelling("24V_PINS"));
    }
}
