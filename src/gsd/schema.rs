//! The GSD keyword schema (`schemas/gsd-keywords.toml`), compiled into the
//! binary and parsed once.

use std::borrow::Cow;
use std::collections::BTreeMap;
use std::sync::OnceLock;

use foldhash::{HashMap, HashMapExt};

use serde::Deserialize;

use crate::spec::Baud;

/// Block keywords: the opening keyword (normalized) and the closing one as
/// the specification spells it.
pub(crate) const BLOCKS: [(&str, &str); 11] = [
    ("module", "EndModule"),
    ("extuserprmdata", "EndExtUserPrmData"),
    ("prmtext", "EndPrmText"),
    ("unitdiagtype", "EndUnitDiagType"),
    ("unit_diag_area", "Unit_Diag_Area_End"),
    ("x_unit_diag_area", "X_Unit_Diag_Area_End"),
    ("slotdefinition", "EndSlotDefinition"),
    ("physical_interface", "End_Physical_Interface"),
    ("version_firmware_download", "End_Version_Firmware_Download"),
    ("jokerblock_type", "End_Jokerblock_Type"),
    ("data_area_beg", "Data_Area_End"),
];

/// The keywords of lines inside blocks besides settings, which the schema
/// does not list: its table holds them too (see [`key_of`]), so a
/// block's lines allocate no keys either.
pub(crate) fn inner_keywords() -> impl Iterator<Item = &'static str> {
    const LINES: [&str; 12] = [
        "Text",
        "Value",
        "X_Value",
        "Slot",
        "Bit",
        "BitArea",
        "Unsigned8",
        "Unsigned16",
        "Unsigned32",
        "Signed8",
        "Signed16",
        "Signed32",
    ];
    BLOCKS.iter().map(|(_, end)| *end).chain(LINES)
}

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
    /// Numbers from here up to `min` break the specification's range, yet
    /// engineering tools accept them: a warning (W234), not an error.
    pub tolerated_min: Option<i64>,
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

/// What the schema holds under a normalized key.
#[derive(Debug)]
enum Entry {
    Keyword(Keyword),
    /// `maxtsdr_1.5m`: one baud rate of a keyword the schema spells with
    /// `<baud>` (`MaxTsdr_<baud>`), whose key is `pattern`; `name` is its
    /// spelling (`MaxTsdr_1.5M`).
    Baud {
        pattern: Box<str>,
        baud: Baud,
        name: Box<str>,
    },
    /// A keyword of a line inside a block (`Text`, `Unsigned8`,
    /// `EndModule`): known to the reader, not a setting of the schema.
    Inner {
        name: &'static str,
    },
}

impl Entry {
    fn baud(&self) -> Option<Baud> {
        match self {
            Entry::Baud { baud, .. } => Some(*baud),
            Entry::Keyword(_) | Entry::Inner { .. } => None,
        }
    }

    /// The keyword as the specification spells it.
    fn spelling(&self) -> &str {
        match self {
            Entry::Keyword(k) => &k.name,
            Entry::Baud { name, .. } => name,
            Entry::Inner { name } => name,
        }
    }
}

pub struct Schema {
    by_key: HashMap<Box<str>, Entry>,
}

/// The placeholder for a baud rate in the schema's keyword names.
const BAUD: &str = "<baud>";

impl Schema {
    fn load() -> Schema {
        let text = include_str!("../../schemas/gsd-keywords.toml");
        // The schema ships inside the binary and a unit test parses it, so a
        // failure here is a build defect, not something a user's input causes.
        let table: BTreeMap<String, KeywordSpec> =
            toml::from_str(text).expect("schemas/gsd-keywords.toml is valid");
        let mut by_key = HashMap::new();
        for (name, spec) in table {
            let key: Box<str> = name.to_ascii_lowercase().into();
            if key.contains(BAUD) {
                for baud in Baud::ALL {
                    let name: Box<str> = name.replace(BAUD, baud.as_str()).into();
                    let pattern = key.clone();
                    let entry = Entry::Baud {
                        pattern,
                        baud,
                        name,
                    };
                    by_key.insert(entry.spelling().to_ascii_lowercase().into(), entry);
                }
            }
            by_key.insert(key, Entry::Keyword(Keyword { name, spec }));
        }
        for name in inner_keywords() {
            // A keyword of the schema keeps its entry, should one share a name.
            by_key
                .entry(name.to_ascii_lowercase().into())
                .or_insert(Entry::Inner { name });
        }
        Schema { by_key }
    }

    /// The schema entry for a normalized keyword (see [`normalize`]); a
    /// baud rate keyword (`maxtsdr_1.5m`) finds its pattern's entry.
    pub fn lookup(&self, key: &str) -> Option<&Keyword> {
        match self.by_key.get(key)? {
            Entry::Keyword(k) => Some(k),
            Entry::Baud { pattern, .. } => match self.by_key.get(pattern)? {
                Entry::Keyword(k) => Some(k),
                Entry::Baud { .. } | Entry::Inner { .. } => None,
            },
            Entry::Inner { .. } => None,
        }
    }

    pub fn keywords(&self) -> impl Iterator<Item = &Keyword> {
        self.by_key.values().filter_map(|entry| match entry {
            Entry::Keyword(k) => Some(k),
            Entry::Baud { .. } | Entry::Inner { .. } => None,
        })
    }

    pub fn mandatory(&self) -> impl Iterator<Item = &Keyword> {
        self.keywords().filter(|k| k.spec.mandatory)
    }
}

pub fn schema() -> &'static Schema {
    static SCHEMA: OnceLock<Schema> = OnceLock::new();
    SCHEMA.get_or_init(Schema::load)
}

/// What the schema says of the keyword `name`, spelt as the specification
/// spells it (`C2_Max_Count_Channels`, `MaxTsdr_<baud>`): the one place a
/// keyword's limits are written, for the checker of every GSD and for the
/// loader, which holds a description's values to the limits of the
/// keywords they become, so that nothing it accepts is a GSD the checker
/// refuses.
///
/// # Panics
/// When the schema has no such keyword: the names are gsdc's own, and
/// every one is tested (`lower`'s tests).
pub(crate) fn keyword(name: &str) -> &'static KeywordSpec {
    match schema().lookup(&normalize(name)) {
        Some(keyword) => &keyword.spec,
        None => panic!("schemas/gsd-keywords.toml has no keyword {name}"),
    }
}

/// The numbers [`keyword`] `name` takes, both ends included.
pub(crate) fn keyword_range(name: &str) -> (i64, i64) {
    keyword(name).number_range()
}

/// The longest string [`keyword`] `name` takes, in characters.
///
/// # Panics
/// When the keyword has no `max_len`.
pub(crate) fn keyword_max_len(name: &str) -> usize {
    keyword(name)
        .max_len
        .unwrap_or_else(|| panic!("{name} has no max_len in schemas/gsd-keywords.toml"))
}

/// The longest keyword the schema knows is shorter than this; a longer name
/// is not looked up without allocating.
const MAX_PLAIN_KEY: usize = 48;

/// The key of a keyword as written (see [`normalize`]), borrowed from the
/// schema when the schema knows the keyword, as it does on nearly every
/// line: reading a file then allocates no keys.
pub fn key_of(name: &str) -> Cow<'static, str> {
    resolve(name).key
}

/// A keyword as written, against the schema's table.
pub(crate) struct Resolved {
    /// See [`key_of`].
    pub key: Cow<'static, str>,
    /// The specification's spelling, when the table has the keyword.
    pub spelling: Option<&'static str>,
    /// The baud rate the keyword carries in its name: `maxtsdr_1.5m` and
    /// `12m_supp` do, for each keyword the schema spells with `<baud>`.
    pub baud: Option<Baud>,
}

pub(crate) fn resolve(name: &str) -> Resolved {
    let mut buf = [0u8; MAX_PLAIN_KEY];
    let normalized;
    let key = match plain_lowercase(name, &mut buf) {
        Some(lower) => lower,
        None => {
            normalized = normalize(name);
            &normalized
        }
    };
    match schema().by_key.get_key_value(key) {
        Some((known, entry)) => Resolved {
            key: Cow::Borrowed(known),
            spelling: Some(entry.spelling()),
            baud: entry.baud(),
        },
        None => Resolved {
            key: Cow::Owned(key.to_string()),
            spelling: None,
            baud: None,
        },
    }
}

/// `name` in lower case in `buf`, when it is plain ASCII with nothing else
/// for [`normalize`] to do, and fits.
fn plain_lowercase<'b>(name: &str, buf: &'b mut [u8; MAX_PLAIN_KEY]) -> Option<&'b str> {
    let bytes = name.as_bytes();
    let lower = buf.get_mut(..bytes.len())?;
    for (to, &b) in lower.iter_mut().zip(bytes) {
        if !b.is_ascii() || b.is_ascii_whitespace() || b == b'!' {
            return None;
        }
        *to = b.to_ascii_lowercase();
    }
    std::str::from_utf8(lower).ok()
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
    if name.is_ascii() {
        return name
            .bytes()
            .any(|b| char::from(b).is_whitespace() || b == b'!');
    }
    name.contains(char::is_whitespace) || name.contains('!')
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

    /// GSD_Revision is the one keyword a revision-0 file lacks by
    /// definition; no source dates any other keyword to revision 1, so
    /// nothing a revision-0 file may hold is dated after it by a guess.
    #[test]
    fn only_gsd_revision_is_dated_revision_1() {
        let mut dated_1: Vec<&str> = schema()
            .keywords()
            .filter(|k| k.spec.revision == 1)
            .map(|k| k.name.as_str())
            .collect();
        dated_1.sort_unstable();
        assert_eq!(dated_1, ["GSD_Revision"]);
        assert!(!schema().lookup("gsd_revision").unwrap().spec.mandatory);
    }

    #[test]
    fn baud_keywords_share_one_entry() {
        let k = schema().lookup("maxtsdr_1.5m").unwrap();
        assert_eq!(k.name, "MaxTsdr_<baud>");
        assert_eq!(schema().lookup("45.45_supp").unwrap().spec.kind, Kind::Bool);
        assert!(schema().lookup("maxtsdr_2m").is_none());
        assert_eq!(resolve("MaxTsdr_1.5M").baud, Some(Baud::B1M5));
        assert_eq!(resolve("12M_supp").baud, Some(Baud::B12M));
        assert_eq!(resolve("Max_Input_Len").baud, None);
    }

    #[test]
    fn known_keys_are_borrowed_from_the_schema() {
        assert!(matches!(
            key_of("Vendor_Name"),
            Cow::Borrowed("vendor_name")
        ));
        assert!(matches!(
            key_of("MaxTsdr_1.5M"),
            Cow::Borrowed("maxtsdr_1.5m")
        ));
        assert!(matches!(key_of("EndModule"), Cow::Borrowed("endmodule")));
        assert!(matches!(key_of("Text"), Cow::Borrowed("text")));
        // The specification's spelling, whatever the case written.
        assert_eq!(resolve("maxtsdr_1.5m").spelling, Some("MaxTsdr_1.5M"));
        assert_eq!(resolve("12m_SUPP").spelling, Some("12M_supp"));
        assert_eq!(resolve("ENDMODULE").spelling, Some("EndModule"));
        assert_eq!(resolve("vendor_name").spelling, Some("Vendor_Name"));
        assert_eq!(resolve("Vendor_Extra").spelling, None);
        // Known to the reader, not a setting of the schema.
        assert!(schema().lookup("text").is_none());
        // Not plain, or unknown: the same key, built.
        assert_eq!(key_of("Unit_Diag_!Bit"), "unit_diag_not_bit");
        assert_eq!(
            resolve("Unit_Diag_!Bit").spelling,
            Some("Unit_Diag_Not_Bit")
        );
        assert_eq!(key_of("24V Pins"), "24v_pins");
        assert!(matches!(key_of("Vendor_Extra"), Cow::Owned(k) if k == "vendor_extra"));
        let long = "X".repeat(MAX_PLAIN_KEY + 1);
        assert_eq!(key_of(&long), long.to_ascii_lowercase());
    }

    #[test]
    fn no_schema_keyword_is_too_long_to_borrow() {
        assert!(schema().by_key.keys().all(|k| k.len() <= MAX_PLAIN_KEY));
    }

    #[test]
    fn normalize_handles_siemens_spellings() {
        assert_eq!(normalize("24V  Pins"), "24v_pins");
        assert_eq!(normalize("Unit_Diag_!Bit"), "unit_diag_not_bit");
        assert!(is_nonstandard_spelling("24V Pins"));
        assert!(!is_nonstandard_spelling("24V_PINS"));
    }
}
