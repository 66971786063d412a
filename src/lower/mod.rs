//! Lowering: the raw description to the IR, applying every default and
//! checking every rule. All failures are collected, not only the first.
//!
//! Rule codes of this stage are E1xx (errors) and W1xx (warnings); they are
//! documented in `docs/rules.md`.

mod checks;
mod choices;
mod dp_channel;
mod dp_modules;
mod dp_params;
mod dp_safety;
mod dp_timing;
mod gateway;
mod manual;
mod mappings;
mod meaning;
mod param_values;
mod ppo;
mod profibus;
mod profinet;
mod safety_crcs;
mod telegram;
mod wording;

use crate::description::{self as raw, Address, Description};
use crate::diag::{Diagnostic, Diagnostics};
use crate::ir::{self, AddressScheme, Fingerprint, Ir, Numbering};
/// For `gsdc import`, which recognises PPO types by their config bytes.
pub(crate) use checks::is_clean_lines as is_clean_text_of_lines;
use checks::Checker;
pub(crate) use gateway::module_name as gateway_module_name;
pub(crate) use ppo::{config_bytes as ppo_config_bytes, ppo_layout};
pub(crate) use profibus::{vendor_keyword_problem, DEFAULT_PPO5_PZD_WORDS};
pub(crate) use profinet::{
    info_prefix, io_length, is_profile_version, module_category, module_description, module_name,
    pkw_words, profidrive_telegram_1_name, profile_words, IoNeed, Offer, ADD_VALUE_BYTES,
    CHANNEL_ERROR_TYPES, DEFAULT_VERSION as DEFAULT_GSDML_VERSION, EMPTY_MODULE_IDENT,
    EXTENDED_ERROR_TYPES, INTERFACE_NAME, MAX_IO_LENGTH, MAX_SLOT, PROFILE_ERROR_TYPES,
    STANDARD_TELEGRAM_2_WORDS, SUPPORTED_VERSIONS as SUPPORTED_GSDML_VERSIONS,
};
use toml::Spanned;

/// Reads a file the description names (its symbol), relative to it: its
/// bytes, or why it cannot.
pub type Files<'a> = &'a dyn Fn(&str) -> Result<Vec<u8>, String>;

/// Lowers a parsed description: the IR when there is no error, and every
/// diagnostic, warnings included. `source_name` is the file name written into
/// generated headers; `text` is the description's text, for the fingerprint.
/// `files` gives the bytes of a file the description names (its symbol);
/// without it nothing is read and the IR has no device symbol, which only
/// the device files need (a build of firmware layouts alone).
pub fn lower(
    desc: &Description,
    source_name: &str,
    text: &str,
    files: Option<Files<'_>>,
) -> (Option<Ir>, Diagnostics) {
    if let Some(missing) = missing_key(desc, text).or_else(|| missing_gsd_identity(desc, text)) {
        return (None, Diagnostics(vec![missing]));
    }
    let latin1 = desc
        .profibus
        .as_ref()
        .and_then(|p| p.get_ref().charset.as_ref())
        .is_some_and(|c| *c.get_ref() == raw::Charset::Latin1);
    let mut cx = Checker::new(desc.profibus.is_some(), latin1);
    // A gateway's description without a bus is told it needs [profibus] (E144).
    if desc.profibus.is_none() && desc.profinet.is_none() && desc.gateway.is_none() {
        let first_line = 0..text.find('\n').unwrap_or(text.len());
        cx.push(
            Diagnostic::error("E110", "the description targets no bus")
                .at(first_line)
                .label("in this description")
                .help("add a [profibus] or [profinet] section; docs/description.md shows both"),
        );
    }
    let numbering = desc
        .function_codes
        .as_ref()
        .map(|f| lower_numbering(&mut cx, f));
    let device = lower_device(&mut cx, &desc.device, files);
    let telegram = desc
        .telegram
        .as_ref()
        .map_or_else(telegram::absent, |t| telegram::lower(&mut cx, t));
    let (mappings, set_spans) = mappings::lower(&mut cx, desc, numbering.as_ref(), &telegram);
    telegram::check_pnus(&mut cx, desc, numbering.as_ref());
    let gateway = desc
        .gateway
        .as_ref()
        .map(|g| gateway::lower(&mut cx, g, desc));
    let profibus = desc.profibus.as_ref().map(|p| {
        let plan = (&telegram, &mappings, &set_spans);
        profibus::lower(&mut cx, p, plan, gateway.as_ref(), &device)
    });
    let profinet = desc
        .profinet
        .as_ref()
        .map(|p| profinet::lower(&mut cx, p, desc, (&device, &telegram, &mappings)));
    // What holds across the buses is checked when each bus the description
    // has lowered: a part that failed has said why, and the checks would
    // take it for absent.
    if profibus.as_ref().is_none_or(Option::is_some)
        && profinet.as_ref().is_none_or(Option::is_some)
    {
        meaning::check(
            &mut cx,
            desc,
            &mappings,
            (
                profibus.as_ref().and_then(Option::as_ref),
                profinet.as_ref().and_then(Option::as_ref),
            ),
            &set_spans,
        );
    }
    let setup = manual::setup(&mut cx, &desc.setup, numbering.as_ref(), &mappings);
    let telegrams = manual::Telegrams {
        pkw: telegram.pkw,
        profibus: profibus.as_ref().and_then(Option::as_ref),
        profinet: profinet.as_ref().and_then(Option::as_ref),
    };
    let examples = manual::examples(&mut cx, &desc.examples, &telegrams);
    let manual_languages = desc
        .manual
        .as_ref()
        .map_or_else(Vec::new, |m| manual_languages(&mut cx, m));
    let given = cx.take_given();
    let mut decisions = cx.take_decisions();
    decisions.extend(choices::lower(&mut cx, &desc.choices, &desc.choice_targets));
    if let Some(draft) = &desc.draft {
        still_a_draft(&mut cx, draft);
    }
    decisions.sort_by(|a, b| (a.kind, &a.path).cmp(&(b.kind, &b.path)));
    cx.languages_without_words();
    let languages = cx.languages();
    let numbering = numbering.map(|mut n| {
        n.written_prefixes = cx.take_written_prefixes();
        n
    });
    let diagnostics = cx.finish();
    if diagnostics.has_errors() {
        return (None, diagnostics);
    }
    let profibus = profibus.flatten();
    let profinet = profinet.flatten();
    let gateway = gateway.map(|g| g.gateway);
    let wording = wording::wording(
        (&given, &languages),
        profibus.as_ref(),
        gateway.as_ref(),
        profinet.as_ref(),
    );
    let ir = Ir {
        source_name: safe_file_name(source_name),
        fingerprint: Fingerprint::of(text),
        device,
        numbering,
        telegram,
        mappings,
        languages,
        decisions,
        manual_languages,
        profibus,
        profinet,
        gateway,
        setup,
        examples,
        wording,
    };
    (Some(ir), diagnostics)
}

/// The description's file name as every generated file may show it: what
/// is not printable ASCII (a GSD holds nothing else; a newline would start a
/// line of its own), a backslash or a backquote becomes `_`. `Müller.toml`
/// is `M_ller.toml`.
fn safe_file_name(name: &str) -> String {
    name.chars()
        .map(|c| match c {
            ' '..='~' if !matches!(c, '\\' | '`') => c,
            _ => '_',
        })
        .collect()
}

/// E004 for a key only a gateway's description may leave out (`[telegram]`,
/// `ppo_types`, which `[[profibus.modules]]` may replace), said as the TOML stage says any other missing key: alone,
/// at the table that lacks it.
fn missing_key(desc: &Description, text: &str) -> Option<Diagnostic> {
    if desc.gateway.is_some() {
        return None;
    }
    let (key, span) = if desc.telegram.is_none() {
        ("telegram", 0..0)
    } else {
        let profibus = desc.profibus.as_ref()?;
        let p = profibus.get_ref();
        if p.ppo_types.is_some() || p.modules.is_some() {
            return None;
        }
        ("ppo_types", first_line(text, profibus.span()))
    };
    Some(
        Diagnostic::error("E004", format!("missing field `{key}`"))
            .at(span)
            .label("missing key")
            .help("add the key; docs/description.md shows a complete example"),
    )
}

/// E004 for the revision and releases a GSD states (`Revision`,
/// `Hardware_Release`, `Software_Release`, mandatory keywords), which only a
/// description without `[profibus]` may leave out: a GSDML device access
/// point may have none (SEW's MOVI-C). Every one missing in one finding,
/// at `[profibus]`, alone, as [`missing_key`] says its keys.
fn missing_gsd_identity(desc: &Description, text: &str) -> Option<Diagnostic> {
    let profibus = desc.profibus.as_ref()?;
    let d = &desc.device;
    let missing: Vec<(&str, &str)> = [
        (&d.revision, "revision", "Revision"),
        (&d.hardware_release, "hardware_release", "Hardware_Release"),
        (&d.software_release, "software_release", "Software_Release"),
    ]
    .into_iter()
    .filter(|(value, ..)| value.is_none())
    .map(|(_, key, keyword)| (key, keyword))
    .collect();
    if missing.is_empty() {
        return None;
    }
    let keys: Vec<String> = missing
        .iter()
        .map(|(key, _)| format!("`device.{key}`"))
        .collect();
    let keywords: Vec<&str> = missing.iter().map(|(_, keyword)| *keyword).collect();
    Some(
        Diagnostic::error("E004", format!("missing field {}", keys.join(", ")))
            .at(first_line(text, profibus.span()))
            .label(format!("this GSD needs {}", keywords.join(", ")))
            .help("add what is missing to [device]: a GSD states Revision, Hardware_Release and Software_Release; only a description without [profibus] may leave them out"),
    )
}

/// The first line of `span` in `text`, without its line end.
fn first_line(text: &str, span: std::ops::Range<usize>) -> std::ops::Range<usize> {
    let line = &text[span.clone()];
    span.start..span.start + line.find('\n').unwrap_or(line.len())
}

fn lower_device(cx: &mut Checker, d: &raw::Device, files: Option<Files<'_>>) -> ir::Device {
    ir::Device {
        symbol: d
            .symbol
            .as_ref()
            .zip(files)
            .and_then(|(path, files)| symbol(cx, path, files)),
        vendor: cx.gsd_string(&d.vendor, "Vendor_Name", "vendor"),
        family: cx.required(&d.family, "family"),
        model: cx.gsd_string(&d.model, "Model_Name", "model"),
        revision: cx.optional_gsd_string(d.revision.as_ref(), "Revision", "revision"),
        hardware_release: cx.optional_gsd_string(
            d.hardware_release.as_ref(),
            "Hardware_Release",
            "hardware_release",
        ),
        software_release: cx.optional_gsd_string(
            d.software_release.as_ref(),
            "Software_Release",
            "software_release",
        ),
        order_number: cx.optional_gsd_string(
            d.order_number.as_ref(),
            "OrderNumber",
            "order_number",
        ),
        name: cx.text(&d.name, None, "name"),
        info: d
            .info
            .as_ref()
            .map(|i| cx.text(i, Some(crate::gsd::keyword_max_len("Info_Text")), "info")),
    }
}

/// W604: a draft import's description, whose build is another device
/// than the file it was imported from until each change is mended or
/// accepted.
fn still_a_draft(cx: &mut Checker, draft: &Spanned<raw::Draft>) {
    let (changes, left_out) = (
        draft.get_ref().changes.len(),
        draft.get_ref().left_out.len(),
    );
    cx.push(
        Diagnostic::warning(
            "W604",
            format!("a draft import: its build is another device than the file it was imported from ({changes} change(s) and {left_out} part(s) left out, listed in [draft])"),
        )
        .at(draft.span())
        .label("still a draft")
        .help("mend each change in the description or accept it (`gsdc diff` the imported file against the build), then delete [draft]; `gsdc build --deny-warnings` refuses a build while it remains"),
    );
}

/// The manual's languages: ISO 639-1 codes, each once.
fn manual_languages(cx: &mut Checker, manual: &raw::Manual) -> Vec<String> {
    cx.non_empty(
        manual.title.get_ref(),
        manual.title.span(),
        "the manual's title",
    );
    let mut codes: Vec<String> = Vec::new();
    for code in manual.languages.get_ref() {
        if !crate::description::is_language_code(code.get_ref()) {
            cx.push(
                Diagnostic::error(
                    "E137",
                    format!("`{}` is not an ISO 639-1 language code", code.get_ref()),
                )
                .at(code.span())
                .label("not a language code")
                .help("write the manual's languages as texts write them: \"en\", \"zh\", \"de\""),
            );
        } else if codes.contains(code.get_ref()) {
            cx.duplicate(format!("language `{}`", code.get_ref()), code.span());
        } else {
            codes.push(code.get_ref().clone());
        }
    }
    codes.sort();
    codes
}

/// The device symbol: the PNG the description names, read through `files`
/// and turned into the bitmap the conventions require (`crate::symbol`).
fn symbol(
    cx: &mut Checker,
    path: &Spanned<String>,
    files: &dyn Fn(&str) -> Result<Vec<u8>, String>,
) -> Option<Vec<u8>> {
    let name = path.get_ref();
    let png = if std::path::Path::new(name).is_absolute() {
        Err(format!("`{name}` is absolute"))
    } else {
        files(name)
    };
    let png = match png {
        Ok(png) => png,
        Err(why) => {
            cx.push(
                Diagnostic::error("E141", format!("the device symbol cannot be read: {why}"))
                    .at(path.span())
                    .label("not readable")
                    .help("give the PNG's path relative to the description, e.g. symbol = \"symbols/card.png\""),
            );
            return None;
        }
    };
    match crate::symbol::device_bitmap(&png) {
        Ok(bitmap) => {
            if bitmap.approximated_pixels > 0 {
                cx.push(
                    Diagnostic::warning("W106", format!("{} pixels of the device symbol took the nearest of the 16 colours", bitmap.approximated_pixels))
                        .at(path.span())
                        .label("colours reduced")
                        .help("draw the symbol in the 16 Windows standard colours to ship exactly what you drew"),
                );
            }
            Some(bitmap.bmp)
        }
        Err(e) => {
            cx.push(
                Diagnostic::error("E142", e.message())
                    .at(path.span())
                    .label("not a device symbol")
                    .help(e.help()),
            );
            None
        }
    }
}

fn lower_numbering(cx: &mut Checker, f: &raw::FunctionCodes) -> Numbering {
    let radix = *f.group_radix.get_ref();
    let scheme = match f.address.as_ref().map(Spanned::get_ref) {
        None | Some(raw::AddressScheme::Bytes) => AddressScheme::Bytes,
        Some(raw::AddressScheme::Decimal) => AddressScheme::Decimal,
    };
    if scheme == AddressScheme::Decimal && radix != 10 {
        cx.push(
            Diagnostic::error("E101", "group_radix must be 10 with address = \"decimal\"")
                .at(f.group_radix.span())
                .label("not 10")
                .help("a decimal address is group × 100 + index (P10.05 = 1005): its groups are decimal"),
        );
    } else if ![10, 16].contains(&radix) {
        cx.push(
            Diagnostic::error("E101", "group_radix must be 10 or 16")
                .at(f.group_radix.span())
                .label("not 10 or 16")
                .help(
                    "16 for groups written as one hex digit (F0..FF), 10 for decimal groups (P43)",
                ),
        );
    }
    check_separator(cx, &f.separator);
    // A prefix refused is left out, so that names with the others still resolve.
    let prefixes: Vec<(String, u8)> = f
        .prefixes
        .iter()
        .filter(|(p, _)| valid_prefix(cx, p))
        .map(|(p, base)| (p.get_ref().clone(), *base.get_ref()))
        .collect();
    // A wrong radix was reported above; 16 only keeps names from failing twice.
    let radix = if radix == 10 { 10 } else { 16 };
    let widths = widths(cx, f);
    if f.separator.get_ref().is_empty() && radix == 16 {
        prefixes_apart(cx, f);
    }
    let numbering = Numbering::new(f.separator.get_ref().clone(), radix, prefixes, scheme);
    match widths {
        Some(widths) => numbering.with_widths(widths),
        None => numbering,
    }
}

/// The digits of a group and an index (E101 beyond 1..3), given both or
/// neither; E156 without a separator unless both are given: `P1120` is
/// P1.120 or P11.20 or P112.0 until they say.
fn widths(cx: &mut Checker, f: &raw::FunctionCodes) -> Option<ir::numbering::Widths> {
    let digits = |cx: &mut Checker, key: &Option<Spanned<u8>>, what| {
        key.as_ref().map(|d| cx.spanned_in_range(d, 1, 3, what))
    };
    let group = digits(cx, &f.group_digits, "group_digits");
    let index = digits(cx, &f.index_digits, "index_digits");
    match (group, index) {
        (Some(group), Some(index)) => Some(ir::numbering::Widths {
            group: group?,
            index: index?,
        }),
        (None, None) if !f.separator.get_ref().is_empty() => None,
        _ => {
            let (span, label) = match (&f.group_digits, &f.index_digits) {
                (Some(g), _) => (g.span(), "no index_digits beside it"),
                (None, Some(i)) => (i.span(), "no group_digits beside it"),
                (None, None) => (f.separator.span(), "no separator, and no widths"),
            };
            cx.push(
                Diagnostic::error("E156", "the function codes' widths are not both given")
                    .at(span)
                    .label(label)
                    .help("give group_digits and index_digits, the digits every name writes (Siemens' P1120: 2 and 2), or neither with a separator; without one they say where the group ends"),
            );
            None
        }
    }
}

/// E155: without a separator, a hex group may start right after a prefix:
/// a prefix that is another one and hex digits (`F` and `FA`: is `FA12`
/// prefix FA, or F and group A?) makes names ambiguous.
fn prefixes_apart(cx: &mut Checker, f: &raw::FunctionCodes) {
    for longer in f.prefixes.keys() {
        let shadows = f.prefixes.keys().find(|shorter| {
            longer
                .get_ref()
                .strip_prefix(shorter.get_ref().as_str())
                .is_some_and(|rest| !rest.is_empty() && rest.chars().all(|c| c.is_ascii_hexdigit()))
        });
        if let Some(shorter) = shadows {
            cx.push(
                Diagnostic::error(
                    "E155",
                    format!(
                        "the function-code prefix `{}` is `{}` and hex digits: without a separator its names could be either's",
                        longer.get_ref(),
                        shorter.get_ref()
                    ),
                )
                .at(longer.span())
                .label("ambiguous prefix")
                .help("write a separator between group and index, or prefixes that do not start with one another"),
            );
        }
    }
}

/// E155: a function-code name is `<prefix><group><separator><index>`, and
/// generated code writes names in comments: the separator is punctuation or
/// spaces, a prefix letters, so that neither holds the other nor a digit of
/// a group or an index, and a name is never code. Either may be empty (no
/// separator: Siemens' P1120, with the widths; no prefix: ABB's 2202);
/// blanks alone are E117, control characters E135, as in any text.
fn check_separator(cx: &mut Checker, separator: &Spanned<String>) {
    let (text, span) = (separator.get_ref(), separator.span());
    if text.is_empty() || !cx.non_empty(text, span.clone(), "function-code separator") {
        return;
    }
    if let Some(bad) = text
        .chars()
        .find(|&c| !(c.is_ascii_punctuation() || c == ' '))
    {
        cx.push(
            Diagnostic::error(
                "E155",
                format!(
                    "the function-code separator has {}, which is not punctuation or a space",
                    checks::char_name(bad)
                ),
            )
            .at(span)
            .label("not a separator")
            .help("write the ASCII punctuation between group and index, e.g. \"-\" for F0-12 or \".\" for P43.02"),
        );
    }
}

/// Whether a prefix is ASCII letters or empty (E155; see [`check_separator`]).
fn valid_prefix(cx: &mut Checker, prefix: &Spanned<String>) -> bool {
    let (text, span) = (prefix.get_ref(), prefix.span());
    if text.is_empty() {
        return true;
    }
    if !cx.non_empty(text, span.clone(), "function-code prefix") {
        return false;
    }
    if text.chars().all(|c| c.is_ascii_alphabetic()) {
        return true;
    }
    cx.push(
        Diagnostic::error(
            "E155",
            format!("the function-code prefix `{text}` is not ASCII letters"),
        )
        .at(span)
        .label("not a prefix")
        .help("write the letters before the group, e.g. F for F0-12 or P for P43.02"),
    );
    false
}

/// An address written as a number or a function-code name, as u16.
fn resolve_address(
    cx: &mut Checker,
    address: &Spanned<Address>,
    numbering: Option<&Numbering>,
) -> Option<u16> {
    match address.get_ref() {
        Address::Number(n) => cx.in_range(*n, 0, 0xFFFF, address.span(), "an address or value"),
        Address::Name(name) => match numbering {
            None => {
                cx.push(
                    Diagnostic::error("E107", format!("`{name}` is a function-code name, but the description has no [function_codes]"))
                        .at(address.span())
                        .label("needs [function_codes]")
                        .help("add [function_codes] saying how names map to addresses, or write the number"),
                );
                None
            }
            Some(numbering) => match numbering.read(name) {
                Ok(named) => {
                    cx.wrote_name(named.address, named.prefix);
                    Some(named.address)
                }
                Err(why) => {
                    let example = numbering
                        .example()
                        .map_or_else(String::new, |e| format!(", e.g. {e}"));
                    cx.push(
                        Diagnostic::error(
                            "E106",
                            format!("`{name}` is not a function-code name: {why}"),
                        )
                        .at(address.span())
                        .label("not a function code")
                        .help(format!(
                            "the description numbers parameters as {}{example}; or write the number",
                            numbering.form()
                        )),
                    );
                    None
                }
            },
        },
    }
}
