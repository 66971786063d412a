//! `[profinet.profienergy]`: the PROFIenergy profile the card implements,
//! which every device access point's own submodule declares, with its
//! energy saving modes; the device access points' `PROFIenergyASE_Supported`
//! and the `EnergySaving` application class go with it. The ranges are
//! the PI schema's.

use super::written_in;
use crate::description as raw;
use crate::diag::Diagnostic;
use crate::ir::profinet::{EnergySavingMode, ProfiEnergy, Version};
use crate::lower::checks::Checker;
use crate::spec::PROFIENERGY;
use std::collections::BTreeSet;
use toml::Spanned;

/// The table, when given; E198 in a file older than the first version a
/// file at hand shows PROFIenergy in, E199 for a profile version that is
/// not one, E101 for a class out of its range, E105 for a mode given twice.
pub fn lower(
    cx: &mut Checker,
    given: Option<&Spanned<raw::ProfiEnergy>>,
    file: Version,
) -> Option<Option<ProfiEnergy>> {
    let Some(given) = given else {
        return Some(None);
    };
    written_in(cx, given.span(), file, PROFIENERGY);
    let p = given.get_ref();
    let profile_version = profile_version(cx, &p.profile_version);
    let class = |cx: &mut Checker, n: &Option<Spanned<u8>>, max, what| match n {
        Some(n) => cx.spanned_in_range(n, 1, max, what).map(Some),
        None => Some(None),
    };
    let entity_class = class(cx, &p.entity_class, 3, "profinet.profienergy.entity_class");
    let entity_subclass = class(
        cx,
        &p.entity_subclass,
        2,
        "profinet.profienergy.entity_subclass",
    );
    let modes = modes(cx, &p.modes);
    let flag = |f: &Option<Spanned<bool>>| f.as_ref().is_some_and(|f| *f.get_ref());
    Some(Some(ProfiEnergy {
        profile_version: profile_version?,
        entity_class: entity_class?,
        entity_subclass: entity_subclass?,
        ase: flag(&p.ase),
        pesap_uses_ase: flag(&p.pesap_uses_ase),
        modes,
    }))
}

/// `ProfileVersion`: the schema's VersionStringT (`V1.2`), written without
/// its V as the description's other versions are, and kept as written
/// (`1.10` is not `1.1`).
fn profile_version(cx: &mut Checker, given: &Spanned<String>) -> Option<String> {
    let text = given.get_ref();
    if is_version(text) {
        return Some(format!("V{text}"));
    }
    cx.push(
        Diagnostic::error("E199", format!("`{text}` is not a version"))
            .at(given.span())
            .label("not digits, a dot and digits")
            .help("write the PROFIenergy profile version the card implements, as its manual states it, without the V: \"1.2\""),
    );
    None
}

/// Digits, a dot and digits: the schema's VersionStringT without its V.
pub(crate) fn is_version(text: &str) -> bool {
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    text.split_once('.')
        .is_some_and(|(major, minor)| digits(major) && digits(minor))
}

/// Each energy saving mode, in the description's order; a mode whose
/// number was given before is E105 and left out.
fn modes(cx: &mut Checker, given: &[Spanned<raw::EnergySavingMode>]) -> Vec<EnergySavingMode> {
    let mut seen = BTreeSet::new();
    let mut modes = Vec::new();
    for mode in given.iter().map(Spanned::get_ref) {
        let id = *mode.id.get_ref();
        if !seen.insert(id) {
            cx.duplicate(format!("energy saving mode {id}"), mode.id.span());
            continue;
        }
        modes.push(EnergySavingMode {
            id,
            time_to_pause: *mode.time_to_pause.get_ref(),
            regular_time_to_operate: *mode.regular_time_to_operate.get_ref(),
            min_length_of_stay: *mode.min_length_of_stay.get_ref(),
        });
    }
    modes
}

#[cfg(test)]
mod tests {
    use super::is_version;

    /// The schema's `V[0-9]+\.[0-9]+` without its V, kept as written: a
    /// minor `10` is not `1`.
    #[test]
    fn a_version_is_digits_a_dot_and_digits() {
        for version in ["1.2", "1.10", "12.03"] {
            assert!(is_version(version), "{version}");
        }
        for not in ["V1.2", "1", "1.", ".2", "1.2.3", "1,2", "", "1.2 "] {
            assert!(!is_version(not), "{not}");
        }
    }
}
