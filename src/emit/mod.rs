//! Emitters: the IR to file contents, each verified before it is returned.

pub mod c;
pub mod doc;
pub mod gsd;
pub mod gsdml;
mod layout;
pub mod rust;

use crate::diag::{Diagnostic, Diagnostics};
use crate::ir::{Bus, Decision, Direction, Ir, PkwKind, Wording};

/// One generated file: what it is, its name (no directory) and its bytes.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Artifact {
    pub kind: ArtifactKind,
    pub file_name: String,
    pub contents: Vec<u8>,
}

impl Artifact {
    /// A file of `kind` named `file_name` (no directory) holding `contents`.
    pub fn new(kind: ArtifactKind, file_name: impl Into<String>, contents: Vec<u8>) -> Self {
        Artifact {
            kind,
            file_name: file_name.into(),
            contents,
        }
    }
}

/// What a generated file is for: the edges choose among them (a build
/// script may want the firmware layout alone).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[non_exhaustive]
pub enum ArtifactKind {
    /// The PROFIBUS device description.
    Gsd,
    /// The PROFINET device description.
    Gsdml,
    /// The Rust firmware layout of one description.
    RustLayout,
    /// The support module every Rust layout is built from, the same for all.
    RustSupport,
    /// The C firmware layout (a header) of one description.
    CHeader,
    /// The support header every C layout includes, the same for all.
    CSupport,
    /// The device symbol, a bitmap beside the GSD or the GSDML.
    DeviceSymbol,
    /// The datasheet as one HTML page (`gsdc doc`).
    DatasheetHtml,
    /// The datasheet in Markdown (`gsdc doc`).
    DatasheetMarkdown,
}

/// A language firmware is written in: the edges let users choose which
/// layouts they get (`gsdc build`, the build-script API).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[non_exhaustive]
pub enum Language {
    Rust,
    C,
}

impl Language {
    pub const ALL: [Language; 2] = [Language::Rust, Language::C];

    /// `rust` and `c`, as a command line or a configuration names them.
    pub fn name(self) -> &'static str {
        match self {
            Language::Rust => "rust",
            Language::C => "c",
        }
    }
}

impl ArtifactKind {
    /// Device files ship to PLC engineers; layouts go into firmware;
    /// datasheets into manuals.
    pub fn is_device_file(self) -> bool {
        matches!(
            self,
            ArtifactKind::Gsd | ArtifactKind::Gsdml | ArtifactKind::DeviceSymbol
        )
    }

    /// The language of a firmware file (a layout or its support); `None`
    /// for device files and datasheets. An edge that writes the layouts of
    /// some languages only keeps the artifacts whose language it was asked for.
    pub fn language(self) -> Option<Language> {
        match self {
            ArtifactKind::RustLayout | ArtifactKind::RustSupport => Some(Language::Rust),
            ArtifactKind::CHeader | ArtifactKind::CSupport => Some(Language::C),
            ArtifactKind::Gsd
            | ArtifactKind::Gsdml
            | ArtifactKind::DeviceSymbol
            | ArtifactKind::DatasheetHtml
            | ArtifactKind::DatasheetMarkdown => None,
        }
    }
}

/// The file stem of a description, the datasheet's: `mv810-pnet02` for
/// `mv810-pnet02.toml`.
fn source_stem(ir: &Ir) -> String {
    std::path::Path::new(&ir.source_name)
        .file_stem()
        .map_or_else(
            || ir.source_name.clone(),
            |s| s.to_string_lossy().into_owned(),
        )
}

/// The file stem of a description's layouts: `md810dp` for `md810dp.toml`,
/// `mv810_pnet02` for `mv810-pnet02.toml`: `_` for every character that is
/// not an ASCII letter, digit or `_` (as Rust names its source files), so a
/// layout's name is a file name on every system and a module name.
fn layout_stem(ir: &Ir) -> String {
    source_stem(ir)
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect()
}

/// What the layout holds: `the cyclic telegrams, the PKW channel and the
/// bus constants`.
pub(crate) fn layout_contents(ir: &Ir) -> String {
    let has_telegrams = ir.profibus.as_ref().is_some_and(|p| !p.modules.is_empty())
        || ir.profinet.as_ref().is_some_and(|p| !p.modules.is_empty());
    let parts = [
        (has_telegrams, "the cyclic telegrams"),
        (ir.telegram.pkw != PkwKind::None, "the PKW channel"),
        (
            Direction::BOTH
                .iter()
                .any(|&d| ir.telegram.word(d).is_some()),
            "control and status words",
        ),
        (!ir.mappings.groups.is_empty(), "the configurable mappings"),
        (ir.gateway.is_some(), "the gateway's node parameters"),
        (ir.gateway.is_some(), "its modules"),
        (
            ir.gateway.as_ref().is_some_and(|g| g.diagnosis.is_some()),
            "its diagnosis",
        ),
    ];
    let present: Vec<&str> = parts
        .iter()
        .filter(|(present, _)| *present)
        .map(|(_, part)| *part)
        .chain(["the bus constants"])
        .collect();
    joined(&present, "and")
}

/// `Bit 3`, `Bits 9-10`: a field's bits, to begin a doc comment.
fn bit_range(first: u16, last: u16) -> String {
    if first == last {
        format!("Bit {first}")
    } else {
        format!("Bits {first}-{last}")
    }
}

/// `text` with its first letter upper case, to begin a sentence.
fn capitalised(text: &str) -> String {
    let mut chars = text.chars();
    chars
        .next()
        .map_or_else(String::new, |c| c.to_uppercase().chain(chars).collect())
}

/// `0x0A`: a byte as every output but the datasheet writes it.
pub(crate) fn hex8(value: u8) -> String {
    format!("0x{value:02X}")
}

/// `0x0A10`: a 16-bit number as every output but the datasheet writes it.
pub(crate) fn hex16(value: u16) -> String {
    format!("0x{value:04X}")
}

/// `0x00000202`: a 32-bit number in eight digits.
pub(crate) fn hex32(value: u32) -> String {
    format!("0x{value:08X}")
}

/// The PKW channel's words as the layouts name them, or `None` without one.
pub(crate) fn pkw_name(kind: PkwKind) -> Option<&'static str> {
    match kind {
        PkwKind::None => None,
        PkwKind::PkeIndPwe => Some("PKE, IND, PWE"),
        PkwKind::StationCommandAddressValue => Some("station, command, address, value"),
        PkwKind::Profidrive => Some("PROFIdrive: PKE, IND, PWE1, PWE2"),
    }
}

/// `a, b and c` (or `a, b or c`).
pub(crate) fn joined(items: &[&str], conjunction: &str) -> String {
    match items {
        [] => String::new(),
        [one] => one.to_string(),
        [rest @ .., last] => format!("{} {conjunction} {last}", rest.join(", ")),
    }
}

/// What the header of a generated file of `kind` says beyond its origin:
/// which of the file's languages are the description's translations, and
/// each decision (placeholder, own choice, gsdc's default) that concerns
/// the file, one note each. A GSD describes the PROFIBUS-DP slave, so the
/// decisions of `[profinet]` are none of its business; a GSDML describes
/// the PROFINET device, so those of `[profibus]` and a gateway are none of
/// its; the layouts carry both buses' constants and list every decision.
/// A GSD and the layouts have English texts only; a GSDML has every
/// language of the description.
pub(crate) fn header_notes(ir: &Ir, kind: ArtifactKind) -> Vec<String> {
    let (bus, all_languages) = match kind {
        ArtifactKind::Gsd => (Some(Bus::Profibus), false),
        ArtifactKind::Gsdml => (Some(Bus::Profinet), true),
        _ => (None, false),
    };
    let mut notes = Vec::new();
    if !ir.manual_languages.is_empty() {
        let languages = ir.languages.iter().filter(|_| all_languages);
        let translated: Vec<&str> = std::iter::once("en")
            .chain(languages.map(String::as_str))
            .filter(|code| !ir.manual_languages.iter().any(|m| m == code))
            .collect();
        if !translated.is_empty() {
            notes.push(format!(
                "Texts in {} are the description's translations of the manual's {}.",
                translated.join(", "),
                ir.manual_languages.join(", ")
            ));
        }
    }
    let concerns = |d: &&Decision| bus.is_none() || d.bus().is_none_or(|b| Some(b) == bus);
    notes.extend(ir.decisions.iter().filter(concerns).map(Decision::summary));
    let in_file = |w: &&Wording| bus.is_none() || Some(w.bus()) == bus;
    notes.extend(ir.wording.iter().filter(in_file).map(Wording::summary));
    notes
}

/// `text` in lines of at most `width` characters, broken between words (a
/// longer word gets a line of its own).
pub(crate) fn wrap_words(text: &str, width: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    // The line's length in characters, kept rather than counted again.
    let mut chars = 0;
    for word in text.split_whitespace() {
        let word_chars = word.chars().count();
        if !line.is_empty() && chars + 1 + word_chars > width {
            lines.push(std::mem::take(&mut line));
            chars = 0;
        }
        if !line.is_empty() {
            line.push(' ');
            chars += 1;
        }
        line.push_str(word);
        chars += word_chars;
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}

/// A sentence a code template hands its filter: a text of the template's
/// own, a sentence of the layout model, or a list of them (one paragraph),
/// with each reference written by `render`.
fn sentence(
    value: &minijinja::Value,
    render: &dyn Fn(&layout::Doc) -> String,
) -> Result<String, minijinja::Error> {
    use serde::Deserialize as _;
    if let Some(text) = value.as_str() {
        return Ok(text.to_string());
    }
    if value.kind() == minijinja::value::ValueKind::Seq {
        let parts: Result<Vec<String>, _> = value
            .try_iter()?
            .map(|part| sentence(&part, render))
            .collect();
        return Ok(parts?.join(" "));
    }
    Ok(render(&layout::Doc::deserialize(value.clone())?))
}

/// A template environment where a name the context lacks is an error, so a
/// misspelt field cannot render as nothing.
fn strict_templates() -> minijinja::Environment<'static> {
    let mut env = minijinja::Environment::new();
    env.set_undefined_behavior(minijinja::UndefinedBehavior::Strict);
    env
}

/// The strict environment of the code templates (Rust and C), whose block
/// tags stand on lines of their own and leave no blank lines behind.
fn code_templates() -> minijinja::Environment<'static> {
    let mut env = strict_templates();
    env.set_trim_blocks(true);
    env.set_lstrip_blocks(true);
    env.set_keep_trailing_newline(true);
    env
}

/// Every file the description gives, each read back and checked by the same
/// rules `gsdc check` applies to third-party files. A file that breaks one is
/// not returned: the diagnostics say which rule, and that gsdc is at fault.
pub fn compile(ir: &Ir) -> Result<Vec<Artifact>, Diagnostics> {
    compile_for(ir, &Language::ALL)
}

/// [`compile`] with the firmware layouts of `languages` only: the device
/// files and symbols always, and no time spent on layouts nobody wants.
/// (Making the parts on threads of their own was measured: more CPU time,
/// no shorter build, whose time goes to syncing the files written.)
pub(crate) fn compile_for(ir: &Ir, languages: &[Language]) -> Result<Vec<Artifact>, Diagnostics> {
    let mut parts: Vec<fn(&Ir) -> Part> = vec![gsd_file, gsdml_file, symbol_files];
    if languages.contains(&Language::Rust) {
        parts.push(rust_layout);
    }
    if languages.contains(&Language::C) {
        parts.push(c_layout);
    }
    let done: Vec<Part> = parts.iter().map(|part| part(ir)).collect();
    let mut artifacts = Vec::new();
    let mut problems = Diagnostics::default();
    for (files, found) in done {
        artifacts.extend(files);
        problems.extend(found);
    }
    if problems.has_errors() {
        return Err(problems);
    }
    Ok(artifacts)
}

/// Some of a description's files, and what their checks found.
type Part = (Vec<Artifact>, Vec<Diagnostic>);

fn gsd_file(ir: &Ir) -> Part {
    let Some(profibus) = &ir.profibus else {
        return (Vec::new(), Vec::new());
    };
    let text = gsd::emit(ir, profibus);
    let mut problems = verify_gsd(
        &profibus.file_name,
        &text,
        profibus.latin1,
        &profibus.vendor_keywords,
    );
    // One byte a character: ASCII as it is, and the Latin-1 characters a
    // description with `charset = "latin-1"` may have (the loader refuses
    // any other, E102).
    let bytes = crate::latin1::encode(&text).unwrap_or_else(|bad| {
        let why = Diagnostic::error(
            "E102",
            format!("U+{:04X} is no Latin-1 character", u32::from(bad)),
        );
        problems.push(generated_file_breaks(&profibus.file_name, why));
        text.clone().into_bytes()
    });
    let file = Artifact::new(ArtifactKind::Gsd, profibus.file_name.clone(), bytes);
    (vec![file], problems)
}

fn gsdml_file(ir: &Ir) -> Part {
    let Some(profinet) = &ir.profinet else {
        return (Vec::new(), Vec::new());
    };
    let text = gsdml::emit(ir, profinet);
    let io_full = profinet.daps.iter().all(|d| d.io_full);
    let problems = verify_gsdml(&profinet.file_name, &text, io_full);
    let file = Artifact::new(
        ArtifactKind::Gsdml,
        profinet.file_name.clone(),
        text.into_bytes(),
    );
    (vec![file], problems)
}

// The layouts are checked by the tests that compile them
// (tests/generated_rust.rs, tests/c_header.rs); the C layout's names here.
fn rust_layout(ir: &Ir) -> Part {
    let layout = Artifact::new(
        ArtifactKind::RustLayout,
        rust::file_name(ir),
        rust::emit(ir).into_bytes(),
    );
    (vec![layout, rust::support_module()], Vec::new())
}

fn c_layout(ir: &Ir) -> Part {
    let header = c::emit(ir);
    let name = c::file_name(ir);
    let problems = c::verify(ir, &name, &header);
    let layout = Artifact::new(ArtifactKind::CHeader, name, header.into_bytes());
    (vec![layout, c::support_header()], problems)
}

fn symbol_files(ir: &Ir) -> Part {
    (symbols(ir), Vec::new())
}

/// The device symbol beside each device file that names it: the same
/// bitmap, under the GSD's and the GSDML's names for it.
fn symbols(ir: &Ir) -> Vec<Artifact> {
    let Some(bitmap) = &ir.device.symbol else {
        return Vec::new();
    };
    let gsd = ir.profibus.iter().filter_map(|p| p.bitmap_device.clone());
    let gsdml = ir
        .profinet
        .iter()
        .filter_map(|p| p.device_symbol.as_ref().map(|s| s.file.clone()));
    gsd.chain(gsdml)
        .map(|name| Artifact {
            kind: ArtifactKind::DeviceSymbol,
            file_name: format!("{name}.bmp"),
            contents: bitmap.clone(),
        })
        .collect()
}

/// gsdc's own GSD must meet the strict rules: the vendor-file rules with
/// warnings as errors, plus 7-bit ASCII, CRLF and lines of at most 80
/// characters. A description that states its GSD is Latin-1 (`latin1`)
/// has chosen the characters beyond ASCII that E241 refuses (each one a
/// byte: the encoding checks it), and its `vendor_keywords` the keywords
/// W205 does not know.
fn verify_gsd(
    file_name: &str,
    text: &str,
    latin1: bool,
    vendor_keywords: &[(String, String)],
) -> Vec<Diagnostic> {
    let stated_keyword = |d: &Diagnostic| {
        let name = d.span.as_ref().and_then(|s| text.get(s.clone()));
        d.code == "W205" && name.is_some_and(|n| vendor_keywords.iter().any(|(k, _)| k == n))
    };
    crate::gsd::check_strict(text)
        .into_iter()
        .filter(Diagnostic::is_error)
        .filter(|d| !(latin1 && d.code == "E241"))
        .filter(|d| !stated_keyword(d))
        .map(|d| generated_file_breaks(file_name, d))
        .collect()
}

/// gsdc's own GSDML must pass the rules `gsdc check` applies to any GSDML,
/// warnings included: a missing translation or a startup mode without
/// Legacy is forgiven in a vendor file, not in what gsdc writes. A limit
/// of IO lengths below every slot full, which the description states
/// (`io_full` false), is the firmware's: the engineering tool refusing the
/// combinations beyond it (W302) is what it asks for.
fn verify_gsdml(file_name: &str, text: &str, io_full: bool) -> Vec<Diagnostic> {
    crate::gsdml::check(text, Some(file_name))
        .into_iter()
        .filter(|d| io_full || d.code != "W302")
        .map(|d| generated_file_breaks(file_name, d))
        .collect()
}

/// A rule broken by gsdc's own output: an internal error, reported with the
/// rule it broke so the bug can be found.
fn generated_file_breaks(file_name: &str, d: Diagnostic) -> Diagnostic {
    Diagnostic {
        code: "E900",
        severity: crate::diag::Severity::Error,
        message: format!(
            "gsdc generated {file_name} breaking rule {}: {}; nothing was written",
            d.code, d.message
        ),
        span: None,
        help: Some("this is a bug in gsdc: please report it with the description".into()),
        ..d
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn md810_gsd() -> String {
        let text = include_str!("../../descriptions/md810dp.toml");
        let ir = crate::testing::load("md810dp.toml", text).0.unwrap();
        gsd::emit(&ir, ir.profibus.as_ref().unwrap())
    }

    /// The datasheet keeps the description's stem; the layouts make it an
    /// identifier.
    #[test]
    fn the_datasheet_and_the_layouts_are_named_after_the_description() {
        let text = include_str!("../../descriptions/mv810-pnet02.toml");
        let ir = crate::testing::load("mv810-pnet02.toml", text).0.unwrap();
        assert_eq!(source_stem(&ir), "mv810-pnet02");
        assert_eq!(layout_stem(&ir), "mv810_pnet02");
        let names: Vec<String> = doc::datasheet(&ir, None)
            .into_iter()
            .map(|a| a.file_name)
            .collect();
        assert_eq!(names, ["mv810-pnet02.html", "mv810-pnet02.md"]);
    }

    /// One typo in a code template (`m.pzd_wordz`) fails the rendering
    /// instead of writing a layout without the telegram's size.
    #[test]
    fn a_misspelt_name_in_a_code_template_is_an_error_not_empty_text() {
        let text = include_str!("../../descriptions/md810dp.toml");
        let ir = crate::testing::load("md810dp.toml", text).0.unwrap();
        type Render = fn(&str, &Ir) -> Result<String, minijinja::Error>;
        let languages: [(&str, Render); 2] =
            [(rust::TEMPLATE, rust::render), (c::TEMPLATE, c::render)];
        for (template, render) in languages {
            assert!(render(template, &ir).is_ok());
            let typo = template.replace("m.pzd_words", "m.pzd_wordz");
            assert_ne!(typo, template);
            let error = render(&typo, &ir).unwrap_err();
            assert_eq!(error.kind(), minijinja::ErrorKind::UndefinedError);
        }
    }

    #[test]
    fn bits_are_one_or_a_range() {
        assert_eq!(bit_range(3, 3), "Bit 3");
        assert_eq!(bit_range(9, 10), "Bits 9-10");
    }

    #[test]
    fn words_wrap_at_the_width_and_long_words_stand_alone() {
        assert_eq!(wrap_words("a bb ccc dddd", 6), ["a bb", "ccc", "dddd"]);
        assert_eq!(wrap_words("abcdefgh ij", 4), ["abcdefgh", "ij"]);
        assert!(wrap_words("", 10).is_empty());
    }

    #[test]
    fn the_generated_gsd_passes_verification() {
        assert_eq!(verify_gsd("MD810DP.GSD", &md810_gsd(), false, &[]), []);
    }

    /// A character beyond ASCII is E241 in gsdc's GSD unless the
    /// description states Latin-1 strings.
    #[test]
    fn latin1_characters_pass_only_in_a_latin1_gsd() {
        let umlaut = md810_gsd().replace(
            "Vendor_Name                 = \"Inovance\"",
            "Vendor_Name                 = \"Inovance Gerätebau\"",
        );
        let problems = verify_gsd("MD810DP.GSD", &umlaut, false, &[]);
        assert!(
            problems.iter().any(|d| d.message.contains("E241")),
            "{problems:?}"
        );
        assert_eq!(verify_gsd("MD810DP.GSD", &umlaut, true, &[]), []);
    }

    /// A keyword the specification does not have is W205, an error in
    /// gsdc's own GSD, unless the description states it as a vendor's.
    #[test]
    fn an_unknown_keyword_passes_only_as_a_vendor_keyword() {
        let with = md810_gsd().replace(
            "Vendor_Name                 = \"Inovance\"",
            "Vendor_Name                 = \"Inovance\"\r\nETERDelay = 0",
        );
        let problems = verify_gsd("MD810DP.GSD", &with, false, &[]);
        assert!(
            problems.iter().any(|d| d.message.contains("W205")),
            "{problems:?}"
        );
        let stated = [("ETERDelay".to_string(), "0".to_string())];
        assert_eq!(verify_gsd("MD810DP.GSD", &with, false, &stated), []);
        let other = [("MaxResponseDelay".to_string(), "0".to_string())];
        assert_ne!(verify_gsd("MD810DP.GSD", &with, false, &other), []);
    }

    #[test]
    fn a_gsd_breaking_a_rule_is_refused_naming_the_rule() {
        // PPO5 declared as 16 PZD words no longer fits Max_Input_Len = 32.
        let broken = md810_gsd().replace("0xF3,0xFB", "0xF3,0xFF");
        let problems = verify_gsd("MD810DP.GSD", &broken, false, &[]);
        assert!(!problems.is_empty());
        assert!(problems.iter().all(|d| d.code == "E900"));
        assert!(
            problems.iter().any(|d| d.message.contains("E216")),
            "{problems:?}"
        );
    }

    #[test]
    fn a_gsdml_warning_is_an_error_in_gsdcs_own_output() {
        let text = include_str!("../../descriptions/mv810-pnet02.toml");
        let ir = crate::testing::load("mv810-pnet02.toml", text).0.unwrap();
        let profinet = ir.profinet.as_ref().unwrap();
        let gsdml = gsdml::emit(&ir, profinet);
        assert_eq!(verify_gsdml(&profinet.file_name, &gsdml, true), []);
        // Without Legacy, W301 in a vendor file; E900 in gsdc's own.
        let advanced_only = gsdml.replace(
            "StartupMode=\"Legacy;Advanced\"",
            "StartupMode=\"Advanced\"",
        );
        assert_ne!(advanced_only, gsdml);
        let problems = verify_gsdml(&profinet.file_name, &advanced_only, true);
        assert!(
            problems
                .iter()
                .any(|d| d.is_error() && d.message.contains("W301")),
            "{problems:?}"
        );
    }

    /// own_idents' modules go into slots 2 and 3: gsdc writes every slot
    /// full, and one byte less is a largest configuration that does not
    /// fit (W302), an error in gsdc's own output unless the description
    /// stated the smaller limit (`io_full` false).
    #[test]
    fn a_largest_configuration_beyond_the_limit_is_forgiven_only_when_stated() {
        let text = include_str!("../../tests/fixtures/valid/own_idents.toml");
        let ir = crate::testing::load("own_idents.toml", text).0.unwrap();
        let profinet = ir.profinet.as_ref().unwrap();
        assert!(profinet.daps.iter().all(|d| d.io_full));
        let gsdml = gsdml::emit(&ir, profinet);
        assert_eq!(verify_gsdml(&profinet.file_name, &gsdml, true), []);
        let lowered = gsdml.replacen("MaxInputLength=\"19\"", "MaxInputLength=\"18\"", 1);
        assert_ne!(lowered, gsdml);
        let problems = verify_gsdml(&profinet.file_name, &lowered, true);
        assert!(
            !problems.is_empty()
                && problems
                    .iter()
                    .all(|d| d.code == "E900" && d.message.contains("W302")),
            "{problems:?}"
        );
        assert_eq!(verify_gsdml(&profinet.file_name, &lowered, false), []);
    }

    #[test]
    fn a_gsd_with_a_long_line_is_refused() {
        let broken = md810_gsd().replace(
            "Vendor_Name                 = \"Inovance\"",
            &format!("Vendor_Name = \"Inovance\" ;{}", "x".repeat(80)),
        );
        let problems = verify_gsd("MD810DP.GSD", &broken, false, &[]);
        assert!(
            problems.iter().any(|d| d.message.contains("E240")),
            "{problems:?}"
        );
    }
}
