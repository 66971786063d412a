//! Every rule code gsdc reports, with its severity and title: the one list
//! the diagnostics' constructors check (in debug builds and tests) and
//! docs/rules.md is checked against (`tests/rule_docs.rs`), in the order the
//! document gives them. E codes are errors, W codes warnings; the document
//! says what each rule asks and why.

/// How bad a finding is: a rule's code says it (E, W).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
#[non_exhaustive]
pub enum Severity {
    Warning,
    Error,
}

impl Severity {
    pub fn as_str(self) -> &'static str {
        match self {
            Severity::Error => "error",
            Severity::Warning => "warning",
        }
    }
}

/// A rule: its stable code, its severity and its title.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct Rule {
    pub code: &'static str,
    pub severity: Severity,
    pub title: &'static str,
}

/// The rule with `code`, if gsdc has one.
pub fn find(code: &str) -> Option<&'static Rule> {
    RULES.iter().find(|r| r.code == code)
}

const fn rule(code: &'static str, title: &'static str) -> Rule {
    let severity = match code.as_bytes()[0] {
        b'W' => Severity::Warning,
        _ => Severity::Error,
    };
    Rule {
        code,
        severity,
        title,
    }
}

/// Every rule, as docs/rules.md lists them.
pub const RULES: &[Rule] = &[
    rule("E000", "not UTF-8"),
    rule("E001", "TOML syntax error"),
    rule("E002", "unknown key"),
    rule("E003", "wrong type or value"),
    rule("E004", "missing key"),
    rule("E005", "duplicate key"),
    rule("E006", "description too large"),
    rule("E101", "out of range"),
    rule("E102", "not a GSD character"),
    rule("E103", "too long for GSD"),
    rule("E104", "unknown PPO type"),
    rule("E105", "given twice"),
    rule("E106", "not a function-code name"),
    rule("E107", "function-code name without `[function_codes]`"),
    rule("E108", "default not allowed"),
    rule("E109", "reversed range"),
    rule("E110", "no bus"),
    rule("E111", "no baud rate"),
    rule("E112", "not a GSD file name"),
    rule("E113", "module longer than the telegram"),
    rule("E114", "overlapping bits"),
    rule("E115", "diagnosis area outside the diagnosis"),
    rule("E116", "parameter telegram too long"),
    rule("E117", "empty"),
    rule("E119", "both range and choices"),
    rule("E120", "not a slave family"),
    rule("E121", "PKW without a PKW channel"),
    rule("E122", "wrong number of defaults"),
    rule("E123", "default and defaults"),
    rule("E124", "DPV1 in an old GSD revision"),
    rule("E125", "diagnosis area without values"),
    rule("E130", "unsupported GSDML version"),
    rule("E131", "not a date"),
    rule("E132", "not a DNS-compatible name"),
    rule("E133", "not usable in a GSDML file name"),
    rule("E134", "too many settings"),
    rule("E135", "a control or formatting character in a text"),
    rule("E136", "a choice that marks nothing"),
    rule("E137", "not a language code"),
    rule("E139", "a record where there are no records"),
    rule(
        "E140",
        "a setting fixed per module without modules that fix it",
    ),
    rule("E141", "the device symbol cannot be read"),
    rule("E142", "not a device symbol"),
    rule("E143", "I&M without the class 2 channel"),
    rule("E144", "not for a gateway"),
    rule("E145", "more nodes counted than there are node numbers"),
    rule("E146", "the default configuration carries too much data"),
    rule("E147", "the modules cannot make every total"),
    rule("E148", "words for a node not in use"),
    rule("E149", "one of two keys"),
    rule("E150", "not a send clock list"),
    rule("E151", "conformance class C"),
    rule("E152", "media redundancy with one port"),
    rule("E153", "standard telegram 1 without PROFIdrive said"),
    rule("E154", "a parameter beyond the PROFIdrive PNUs"),
    rule("E155", "not a function-code prefix or separator"),
    rule("E156", "function-code widths not both given"),
    rule("E157", "a per-module setting's PROFIBUS side not said"),
    rule("E158", "set at the drive and written by the master"),
    rule("E159", "a set-up step disagrees with a mapping"),
    rule("E160", "an example the telegrams cannot carry"),
    rule("W101", "PROFIBUS ident number is a placeholder"),
    rule("W103", "a value of the description's own choice"),
    rule("W104", "a value gsdc chose"),
    rule("W105", "PZD words no module carries"),
    rule("W106", "the device symbol's colours were reduced"),
    rule("W107", "a DPV1 slave without I&M"),
    rule("W108", "a language gsdc has no words in"),
    rule("W102", "PROFINET vendor or device ID is a placeholder"),
    rule("E200", "no `#Profibus_DP` line"),
    rule("E201", "cannot read this line"),
    rule("E202", "string not closed"),
    rule("E203", "block not closed"),
    rule("E204", "block end without an open block"),
    rule("W205", "unknown keyword"),
    rule("E206", "mandatory keyword missing"),
    rule("E207", "wrong type or form of value"),
    rule("E208", "value out of range"),
    rule("W209", "string longer than its limit"),
    rule("W210", "keyword newer than the file's GSD_Revision"),
    rule("W211", "keyword repeated"),
    rule("W212", "non-standard keyword spelling"),
    rule("E213", "baud rate without MaxTsdr"),
    rule("W232", "31.25 kbit/s without MaxTsdr"),
    rule("E214", "no baud rate supported"),
    rule("E215", "module config bytes malformed"),
    rule("E216", "module data exceed the station's limits"),
    rule("E217", "compact station without a module"),
    rule("W233", "compact station with several modules"),
    rule("E218", "modular station without Max_Module ≥ 1"),
    rule("E219", "parameter entry outside the parameter length"),
    rule("E220", "reference to an undefined parameter"),
    rule("E221", "default or allowed values outside range"),
    rule("E222", "overlapping parameters"),
    rule("E223", "reference to an undefined text list"),
    rule("E224", "block number defined twice"),
    rule("E225", "DPV1 slave without its status bytes"),
    rule("E226", "diagnosis bit outside Max_Diag_Data_Len"),
    rule("E227", "User_Prm_Data length inconsistent"),
    rule("E228", "parameter data type unreadable"),
    rule("E229", "GSD file too large"),
    rule("E230", "NUL or control character"),
    rule("W231", "diagnosis area without values"),
    rule("W234", "value below the minimum, accepted by tools"),
    rule("E240", "line longer than 80 characters (strict only)"),
    rule("E241", "character outside 7-bit ASCII (strict only)"),
    rule("E242", "line ends with LF, not CRLF (strict only)"),
    rule("E300", "not readable XML"),
    rule("E301", "not a GSDML file"),
    rule("W303", "schema version unknown"),
    rule("E303", "ProfileHeader or its elements missing"),
    rule("W304", "ProfileHeader text changed"),
    rule("E304", "file name breaks the naming convention"),
    rule("E305", "file name and schema disagree on the version"),
    rule("E306", "duplicate key"),
    rule("E307", "reference to nothing"),
    rule("E308", "TextId not in the primary language"),
    rule("W300", "translation incomplete"),
    rule("E309", "data type unknown or unsized"),
    rule("E310", "IO data that never fit"),
    rule("W302", "the largest configuration exceeds IOConfigData"),
    rule("E311", "IOConfigData beyond a frame"),
    rule("E312", "slot outside the device"),
    rule("E313", "subslot number out of range"),
    rule("E314", "DCP Hello without PowerOnToCommReady"),
    rule("E315", "read-only I&M record declared writeable"),
    rule("W301", "no legacy startup"),
    rule("E316", "parameter outside its record"),
    rule("E317", "DefaultValue not allowed"),
    rule("E318", "ident number not in hex"),
    rule("E319", "required attribute missing"),
    rule("E320", "attribute value malformed"),
    rule("E399", "not valid against the PI schema"),
    rule("E400", "neither a GSD nor a GSDML file"),
    rule("E401", "a device symbol that is not a whole bitmap"),
    rule(
        "W402",
        "a device symbol not of 70 x 40 pixels in 16 colours",
    ),
    rule("E410", "not a hex digit"),
    rule("E411", "odd number of hex digits"),
    rule("E412", "wrong length"),
    rule("E413", "unknown module"),
    rule("E414", "the description has no such part"),
    rule("E415", "not a mapping option"),
    rule("E416", "mapping value not readable or not allowed"),
    rule("E417", "not the device-related block's header"),
    rule("E501", "a GSDML changed under its released file name"),
    rule("E502", "a GSD changed under its released Revision"),
    rule("W503", "a breaking change under the released ident number"),
    rule("E900", "generated file breaks a rule"),
];
