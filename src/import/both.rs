//! A card's GSD and GSDML file imported as one description with both
//! buses: each file is imported as alone, the identity both carry must
//! agree (E603), the two descriptions are merged table by table, and the
//! merged description's build is judged against each file.

use super::toml_out::{Section, TomlOut};
use super::{dp, judge, pn, read, symbol, Files, Imported, ImportedSymbol, Notes, RoundTrip};
use crate::device::dp::DpDevice;
use crate::device::pn::PnDevice;
use crate::device::{AttributeValue, Device, Place};
use crate::diag::Diagnostic;

/// What importing a GSD and a GSDML file together gives: the one
/// description (none when refused, when the files disagree or when its
/// build is another device than either file), and each file's findings.
#[derive(Debug)]
#[non_exhaustive]
pub struct Both {
    pub description: Option<String>,
    /// The description when it builds but its build is another device than
    /// either file, as a draft listing both files' changes (see
    /// [`Imported::draft`]).
    pub draft: Option<String>,
    /// The device symbol the GSD's `Bitmap_Device` names, to write beside
    /// the description; none without a description or a draft.
    pub symbol: Option<ImportedSymbol>,
    pub gsd: Imported,
    pub gsdml: Imported,
}

/// Imports a card's GSD (`gsd`: its name and bytes) and GSDML file
/// (`gsdml`) as one description, `files` giving the files beside the GSD
/// (its device symbol's bitmap, as for `super::import_with`). The caller
/// has told the two apart by their content (`crate::file_kind`).
pub fn import_both(gsd: (&str, &[u8]), gsdml: (&str, &[u8]), files: Files<'_>) -> Both {
    let (dp_device, dp_text) = read(gsd.0, gsd.1);
    let (pn_device, pn_text) = read(gsdml.0, gsdml.1);
    let mut dp_notes = Notes::new(dp_text);
    let mut pn_notes = Notes::new(pn_text);
    let mut symbol = None;
    let described = match (&dp_device, &pn_device) {
        (Some(Device::Dp(d)), Some(Device::Pn(p))) => {
            symbol = symbol::imported(symbol::of_gsd(d), files, &mut dp_notes);
            let symbol_name = symbol.as_ref().map(|s| s.file_name.as_str());
            let dp_out = dp::describe(d, gsd.0, symbol_name, &mut dp_notes);
            let pn_out = pn::describe(p, gsdml.0, None, &mut pn_notes);
            let agree = identities_agree(d, p, gsdml.0, &mut dp_notes);
            match (dp_out, pn_out, agree) {
                (Some(a), Some(b), true) => Some(merge(a, b, (gsd.0, gsdml.0)).finish()),
                _ => None,
            }
        }
        _ => {
            let refused =
                "the files are not a GSD and a GSDML file gsdc can read: `gsdc check` says why";
            dp_notes.refuse(refused);
            None
        }
    };
    let mut trips = (RoundTrip::default(), RoundTrip::default());
    let built = described.and_then(|toml| {
        let symbol = symbol.as_ref();
        trips.0 = judge(gsd.0, &toml, symbol, dp_device.as_ref()?, &mut dp_notes)?;
        trips.1 = judge(gsdml.0, &toml, symbol, pn_device.as_ref()?, &mut pn_notes)?;
        Some(toml)
    });
    let (description, draft) = match built {
        Some(toml) if trips.0.is_clean() && trips.1.is_clean() => (Some(toml), None),
        built => {
            let files = [(gsd.0, &dp_notes), (gsdml.0, &pn_notes)];
            (None, built.map(|toml| super::draft(&toml, &files)))
        }
    };
    Both {
        symbol: symbol.filter(|_| description.is_some() || draft.is_some()),
        description,
        draft,
        gsd: dp_notes.imported((None, None), None, trips.0),
        gsdml: pn_notes.imported((None, None), None, trips.1),
    }
}

/// E603 for each identity fact the two files both carry and give
/// differently: the vendor, the releases, the order number.
fn identities_agree(dp: &DpDevice, pn: &PnDevice, gsdml_name: &str, notes: &mut Notes) -> bool {
    let dap = pn.daps.first().map_or(&[][..], |d| &d.item.attributes[..]);
    let facts = [
        (
            "Vendor_Name",
            &pn.identity[..],
            "DeviceIdentity/VendorName@Value",
        ),
        ("Hardware_Release", dap, "ModuleInfo/HardwareRelease@Value"),
        ("Software_Release", dap, "ModuleInfo/SoftwareRelease@Value"),
        ("OrderNumber", dap, "ModuleInfo/OrderNumber@Value"),
    ];
    let mut agree = true;
    for (keyword, attributes, name) in facts {
        let (k, a) = (
            dp.keyword(keyword),
            attributes.iter().find(|a| &*a.name == name),
        );
        let (Some(k), Some(a)) = (k, a) else {
            if k.is_some() {
                // A DAP may leave out an order number or a release (SEW's
                // MOVI-C does); the one description has the GSD's.
                notes.note(format!(
                    "{gsdml_name} has no {name}: the description's is the GSD's {keyword}, which the build writes in the GSDML file too; the round trip judges the change"
                ));
            }
            continue;
        };
        let gsdml_value = match &a.value {
            AttributeValue::Plain(v) => v.to_string(),
            AttributeValue::Text(t) => t.primary.to_string(),
        };
        let gsd_value = k.value.as_str().unwrap_or_default();
        if gsd_value != gsdml_value {
            agree = false;
            notes.disagree(
                &format!("{keyword} = \"{gsd_value}\""),
                &k.place,
                &format!(
                    "{name} = \"{gsdml_value}\" in {gsdml_name}, {}",
                    place_in(&a.place)
                ),
            );
        }
    }
    agree
}

/// `line N, at PATH` of a place in a GSDML file.
fn place_in(place: &Place) -> String {
    match &place.path {
        Some(path) => format!("line {}, at {}", place.line, &**path),
        None => format!("line {}", place.line),
    }
}

/// One description of the two: the GSD's, with the GSDML's family, name,
/// PKW channel and control words, mappings and settings (which then make
/// the GSD's User_Prm_Data, so its own parameters are dropped), its
/// PROFINET tables and its marks under `[choices]`.
fn merge(dp: TomlOut, pn: TomlOut, (gsd, gsdml): (&str, &str)) -> TomlOut {
    let dp = dp.sections();
    let pn = pn.sections();
    let pn_maps = pn
        .iter()
        .any(|s| s.header.starts_with("[mappings.") || s.header == "[[settings]]");
    let mut preamble = TomlOut::default();
    preamble.comment(&format!(
        "Imported by gsdc import from {gsd} and {gsdml}. Every value below is"
    ));
    preamble.comment("the files', marked under [choices] (where one is not, its mark says why): confirm each against the manual, then remove its mark.");
    let mut out = preamble.sections();
    let gsd_parameters: Vec<String> = dp
        .iter()
        .filter(|s| s.header == "[[profibus.parameters]]")
        .filter_map(english_name)
        .collect();
    let mut profinet_info = None;
    let mut tail = Vec::new();
    for (i, section) in dp.into_iter().enumerate() {
        let is_block = section.header.is_empty();
        match section.header.as_str() {
            _ if is_block && i == 0 => {}
            _ if is_block => tail.push(section),
            "[choices]" => tail.push(section),
            "[profibus.user_prm]" | "[[profibus.parameters]]" if pn_maps => {}
            "[device]" => {
                let (merged, info) = merge_device(section, table(&pn, "[device]"));
                profinet_info = info;
                out.push(merged);
            }
            "[telegram]" => {
                out.push(merge_telegram(section, table(&pn, "[telegram]")));
                let parts = pn.iter().filter(|s| is_telegram_part(&s.header));
                out.extend(parts.map(|s| on_profibus(s, &gsd_parameters)));
            }
            _ => out.push(section),
        }
    }
    // `[profinet...]` tables and `[[profinet...]]` entries (later device
    // access points, channel diagnosis).
    let is_profinet = |header: &str| header.trim_start_matches('[').starts_with("profinet");
    for section in pn.iter().filter(|s| is_profinet(&s.header)) {
        let mut section = section.clone();
        if let (true, Some(info)) = (section.header == "[profinet]", profinet_info.take()) {
            section.lines.insert(0, info);
        }
        out.push(section);
    }
    for mut section in tail {
        if section.header == "[choices]" {
            let pn_marks = table(&pn, "[choices]")
                .into_iter()
                .flat_map(|s| s.lines.iter());
            for line in pn_marks {
                let stand_in = matches!(
                    line.key.as_deref(),
                    Some("\"device.model\"" | "\"device.revision\"")
                );
                let marked = section.lines.iter().any(|l| l.key == line.key);
                if !stand_in && !marked {
                    section.lines.push(line.clone());
                }
            }
        }
        out.push(section);
    }
    TomlOut::from_sections(out)
}

/// The English `name` of a table.
fn english_name(section: &Section) -> Option<String> {
    let line = section
        .lines
        .iter()
        .find(|l| l.key.as_deref() == Some("name"))?;
    let table: toml::Table = line.text.parse().ok()?;
    match table.get("name")? {
        toml::Value::String(name) => Some(name.clone()),
        toml::Value::Table(texts) => texts.get("en")?.as_str().map(str::to_string),
        _ => None,
    }
}

/// A setting each kind of PROFINET module fixes says what it is on
/// PROFIBUS: a User_Prm_Data parameter of the GSD by its name (`"user"`),
/// else `"absent"`.
fn on_profibus(section: &Section, gsd_parameters: &[String]) -> Section {
    let mut section = section.clone();
    let user = english_name(&section).is_some_and(|name| gsd_parameters.contains(&name));
    let what = if user { "user" } else { "absent" };
    for line in &mut section.lines {
        if line.key.as_deref() == Some("per_module") {
            if let Some(open) = line.text.strip_suffix(" }") {
                line.text = format!("{open}, profibus = \"{what}\" }}");
            }
        }
    }
    section
}

fn table<'a>(sections: &'a [Section], header: &str) -> Option<&'a Section> {
    sections.iter().find(|s| s.header == header)
}

/// The GSDML's tables that go with its telegram: the control and status
/// words, the mappings, the settings.
fn is_telegram_part(header: &str) -> bool {
    header.starts_with("[telegram.") || header.starts_with("[mappings.") || header == "[[settings]]"
}

/// The GSD's `[device]` with the GSDML's family and name (a GSD has
/// neither) and order number where the GSD has none; the GSDML's info, where
/// it differs or the GSD has none, as `[profinet] info`.
fn merge_device(mut dp: Section, pn: Option<&Section>) -> (Section, Option<super::toml_out::Line>) {
    let mut info = None;
    for line in pn.into_iter().flat_map(|s| s.lines.iter()) {
        let key = line.key.as_deref();
        let at = dp.lines.iter().position(|l| l.key.as_deref() == key);
        match (key, at) {
            (Some("family" | "name"), Some(i)) => dp.lines[i] = line.clone(),
            // The GSD's Info_Text is the device's info; the GSDML's, where
            // it differs or the GSD has none, is the PROFINET part's own.
            (Some("info"), Some(i)) if dp.lines[i].text != line.text => info = Some(line.clone()),
            (Some("info"), None) => info = Some(line.clone()),
            (Some("order_number" | "family" | "name"), None) => dp.lines.push(line.clone()),
            _ => {}
        }
    }
    (dp, info)
}

/// The GSD's `[telegram]` with the GSDML's PKW channel (which names its
/// kind; a GSD's import says only that there is one), the more PZD words
/// and whether the card implements PROFIdrive.
fn merge_telegram(mut dp: Section, pn: Option<&Section>) -> Section {
    for line in pn.into_iter().flat_map(|s| s.lines.iter()) {
        let key = line.key.as_deref();
        let at = dp.lines.iter().position(|l| l.key.as_deref() == key);
        match (key, at) {
            (Some("pkw"), Some(i)) if !line.text.ends_with("\"none\"") => {
                dp.lines[i] = line.clone()
            }
            (Some("pzd_words"), Some(i)) if words(line) > words(&dp.lines[i]) => {
                dp.lines[i] = line.clone()
            }
            (Some(_), None) => dp.lines.push(line.clone()),
            _ => {}
        }
    }
    dp
}

fn words(line: &super::toml_out::Line) -> u32 {
    line.text
        .rsplit(' ')
        .next()
        .and_then(|n| n.parse().ok())
        .unwrap_or(0)
}

impl Notes {
    /// E603: an identity fact the GSD and the GSDML file give differently.
    fn disagree(&mut self, gsd: &str, place: &Place, gsdml: &str) {
        let d = Diagnostic::error(
            "E603",
            format!("the GSD and the GSDML file disagree: {gsd} here, {gsdml}"),
        )
        .at_opt(self.span(place))
        .label("not the GSDML file's")
        .help("one description has one identity: correct the file that is wrong, or import each file alone");
        self.diagnostics.push(d);
    }
}
