//! Release discipline: a device file a description builds, against the
//! file of the last release (`gsdc build --released DIR`).
//!
//! An engineering tool keeps an installed device description by its file
//! name: TIA Portal does not refresh its catalogue when a GSDML of an
//! installed name is imported again (the old one must be uninstalled
//! first), so a changed GSDML needs a new date in its name (E501). A GSD's
//! name is fixed by its vendor prefix and ident number; what tells two of
//! its releases apart is its `Revision` (E502). A change that breaks
//! projects configured with the released file, under the ident number
//! those projects identify the device by, is a warning (W503): it may be
//! meant, but PLC engineers must hear of it. docs/diff.md gives sources.
//!
//! Pure: the edges read the released files (`crate::build`).

use std::ops::Range;

use super::{Change, Class};
use crate::device::Device;
use crate::diag::Diagnostic;

/// A released file: its name and device, and the command that lists its
/// changes (`gsdc diff release/MD810DP.GSD descriptions/md810dp.toml`).
pub struct Released<'a> {
    pub name: &'a str,
    pub device: &'a Device,
    pub diff_command: String,
}

/// Where a description states what the rules ask to change: the spans the
/// findings point at.
#[derive(Debug, Default)]
pub struct Anchors {
    revision: Option<Range<usize>>,
    date: Option<Range<usize>>,
    ident_number: Option<Range<usize>>,
    device_id: Option<Range<usize>>,
}

impl Anchors {
    /// The anchors of a description's text (none of a text that does not
    /// parse: it has its own findings then).
    pub fn of(text: &str) -> Anchors {
        let Ok(desc) = crate::load::parse(text) else {
            return Anchors::default();
        };
        Anchors {
            revision: desc.device.revision.as_ref().map(toml::Spanned::span),
            date: desc.profinet.as_ref().map(|p| p.get_ref().date.span()),
            ident_number: desc
                .profibus
                .as_ref()
                .map(|p| p.get_ref().ident_number.span()),
            device_id: desc.profinet.as_ref().map(|p| p.get_ref().device_id.span()),
        }
    }
}

/// The released file a built file of `name` is judged against, among the
/// `released` names: the one of the same name; for a GSDML file, else the
/// newest release of the same vendor and family (by the date and time in
/// its name). The flag says whether the names are the same.
pub fn counterpart<'r>(name: &str, released: &'r [String]) -> Option<(&'r str, bool)> {
    if let Some(same) = released.iter().find(|r| r.eq_ignore_ascii_case(name)) {
        return Some((same, true));
    }
    let family = |n: &str| {
        crate::gsdml::version::parse_file_name(n)
            .ok()
            .map(|f| f.vendor_and_family.to_ascii_lowercase())
    };
    let own = family(name)?;
    let release = |n: &&'r String| {
        let parsed = crate::gsdml::version::parse_file_name(n).ok()?;
        (parsed.vendor_and_family.to_ascii_lowercase() == own).then_some((parsed.date, parsed.time))
    };
    released
        .iter()
        .filter_map(|r| Some((release(&r)?, r)))
        .max_by(|a, b| a.0.cmp(&b.0))
        .map(|(_, r)| (r.as_str(), false))
}

/// What the build says of the file `name` it built (`built`) against the
/// released file: E501, E502, W503; nothing when the two are alike or of
/// different kinds.
pub fn judge(
    name: &str,
    built: &Device,
    released: &Released,
    same_name: bool,
    anchors: &Anchors,
) -> Vec<Diagnostic> {
    let Some(changes) = super::compare(released.device, built) else {
        return Vec::new();
    };
    let mut out = Vec::new();
    if changes.is_empty() {
        return out;
    }
    let listed = listing(&changes, None, &released.diff_command);
    match (built, released.device) {
        (Device::Pn(_), _) if same_name => out.push(
            Diagnostic::error("E501", format!("{name} differs from the released file of that name: {listed}"))
                .at_opt(anchors.date.clone())
                .label("the released file's date")
                .help("TIA Portal keeps a GSDML it installed under this name, and importing one of the same name again does not refresh its catalogue: give the release a new date (profinet.date), or a date and time (date = 2026-11-22T14:30:00) for a second release on one day"),
        ),
        (Device::Dp(new), Device::Dp(old)) if same_name && new.revision() == old.revision() => out.push(
            Diagnostic::error(
                "E502",
                format!(
                    "{name} differs from the released file under the same Revision \"{}\": {listed}",
                    new.revision().unwrap_or_default()
                ),
            )
            .at_opt(anchors.revision.clone())
            .label("the released file's revision")
            .help("a GSD keeps its file name from release to release, and its Revision is what tells a PLC engineer which one is installed: bump device.revision"),
        ),
        _ => {}
    }
    let same_ident = match (built, released.device) {
        (Device::Dp(new), Device::Dp(old)) => new.ident_number() == old.ident_number(),
        (Device::Pn(new), Device::Pn(old)) => {
            (new.vendor_id, new.device_id) == (old.vendor_id, old.device_id)
        }
        _ => false,
    };
    if same_ident && changes.iter().any(|c| c.class == Class::Breaking) {
        let (what, anchor) = match built {
            Device::Dp(_) => ("ident number", anchors.ident_number.clone()),
            Device::Pn(_) => ("vendor and device ID", anchors.device_id.clone()),
        };
        let breaking = listing(&changes, Some(Class::Breaking), &released.diff_command);
        out.push(
            Diagnostic::warning(
                "W503",
                format!("{name} breaks PLC projects configured with the released {} under the same {what}: {breaking}", released.name),
            )
            .at_opt(anchor)
            .label(format!("the released file's {what}"))
            .help("every project configured with the released file takes the new device for the old one and fails at its startup, or reads its data and parameters wrongly: make the change compatible, or tell the users of the released file which projects to update"),
        );
    }
    out
}

/// The first changes (of one class, or all), and how to see the rest.
fn listing(changes: &[Change], class: Option<Class>, command: &str) -> String {
    let chosen: Vec<&Change> = changes
        .iter()
        .filter(|c| class.is_none_or(|k| c.class == k))
        .collect();
    let shown: Vec<String> = chosen
        .iter()
        .take(3)
        .map(|c| format!("{}: {}", c.subject, c.change))
        .collect();
    let rest = match chosen.len().saturating_sub(3) {
        0 => String::new(),
        n => format!(" and {n} more"),
    };
    format!(
        "{} change(s), {}{rest} (`{command}` lists them)",
        chosen.len(),
        shown.join("; ")
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_gsdml_meets_its_namesake_or_the_newest_release_of_its_family() {
        let released: Vec<String> = [
            "GSDML-V2.32-MEGMEET-MV800-20230830.xml",
            "GSDML-V2.32-MEGMEET-MV800-20240101-120000.xml",
            "GSDML-V2.32-MEGMEET-MV800-20240101.xml",
            "GSDML-V2.32-INOVANCE-MD810-20261122.xml",
            "MD810DP.GSD",
        ]
        .map(String::from)
        .to_vec();
        assert_eq!(
            counterpart("GSDML-V2.32-MEGMEET-MV800-20230830.xml", &released),
            Some(("GSDML-V2.32-MEGMEET-MV800-20230830.xml", true))
        );
        assert_eq!(
            counterpart("GSDML-V2.32-MEGMEET-MV800-20250101.xml", &released),
            Some(("GSDML-V2.32-MEGMEET-MV800-20240101-120000.xml", false))
        );
        assert_eq!(
            counterpart("md810dp.gsd", &released),
            Some(("MD810DP.GSD", true))
        );
        assert_eq!(counterpart("9KDP1.GSD", &released), None);
        assert_eq!(
            counterpart("GSDML-V2.32-POWTRAN-PI9000-20250101.xml", &released),
            None
        );
    }
}
