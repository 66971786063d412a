//! `[profinet.profienergy]`: the `PROFIenergy` element of the first device
//! access point's own submodule, with the access point's
//! `PROFIenergyASE_Supported`, in a file of a version gsdc writes them in.

use super::stack::{is_true, later_than};
use super::{attribute, found, submodules_of};
use crate::device::pn::{Dap, SubmoduleKind};
use crate::device::Attribute;
use crate::import::toml_out::TomlOut;
use crate::import::Notes;
use crate::ir::profinet::Version;
use crate::lower::is_profile_version as is_version;
use crate::spec::PROFIENERGY;

const PROFILE_VERSION: &str = "PROFIenergy@ProfileVersion";
const ENTITY_CLASS: &str = "PROFIenergy@EntityClass";
const ENTITY_SUBCLASS: &str = "PROFIenergy@EntitySubclass";
const PESAP_USES_ASE: &str = "PROFIenergy@PESAP_uses_PROFIenergyASE";
/// Each energy saving mode's attributes, each with the values of every
/// mode joined by a blank, and the description's key for it.
const MODE: [(&str, &str); 4] = [
    (
        "PROFIenergy/EnergySavingModeList/EnergySavingModeItem@ID",
        "id",
    ),
    (
        "PROFIenergy/EnergySavingModeList/EnergySavingModeItem@TimeToPause",
        "time_to_pause",
    ),
    (
        "PROFIenergy/EnergySavingModeList/EnergySavingModeItem@RTTO",
        "regular_time_to_operate",
    ),
    (
        "PROFIenergy/EnergySavingModeList/EnergySavingModeItem@TimeMinLengthOfStay",
        "min_length_of_stay",
    ),
];
/// The device access point's attribute that goes with the element.
pub(super) const ASE_SUPPORTED: &str = "PROFIenergyASE_Supported";

/// The own submodule's attributes this module reads: what it cannot say
/// it leaves out itself, with why.
pub(super) const SUBMODULE_ATTRIBUTES: [&str; 8] = [
    PROFILE_VERSION,
    ENTITY_CLASS,
    ENTITY_SUBCLASS,
    PESAP_USES_ASE,
    MODE[0].0,
    MODE[1].0,
    MODE[2].0,
    MODE[3].0,
];

/// A device access point's PROFIenergy, as the description says it.
pub(super) struct Declared {
    /// `profile_version`, without its V.
    profile_version: String,
    entity_class: Option<u8>,
    entity_subclass: Option<u8>,
    ase: bool,
    pesap_uses_ase: bool,
    /// Each mode's ID and times, in [`MODE`]'s order.
    modes: Vec<[u32; 4]>,
}

impl Declared {
    /// The PROFIenergy of `dap`'s own submodule, when it has one the
    /// description can say in a file of GSDML `file`; left out (W600) with
    /// why otherwise.
    pub fn of(dap: &Dap, file: Version, notes: &mut Notes) -> Option<Declared> {
        let own = submodules_of(dap, SubmoduleKind::Virtual).next()?;
        let attributes = &own.attributes[..];
        let (version, text) = found(attributes, PROFILE_VERSION)?;
        let left_out = |notes: &mut Notes, why: &str| {
            notes.unsaid("PROFIenergy", &version.place, why);
            None
        };
        if file < PROFIENERGY.version {
            return left_out(notes, &later_than(PROFIENERGY, file));
        }
        let without_v = text.strip_prefix('V').filter(|v| is_version(v));
        let Some(profile_version) = without_v else {
            return left_out(
                notes,
                &format!("its ProfileVersion `{text}` is not a version (V1.2)"),
            );
        };
        let Some(modes) = modes(attributes) else {
            return left_out(
                notes,
                "its energy saving modes' numbers and times are not one each per mode",
            );
        };
        let (Some(entity_class), Some(entity_subclass)) = (
            numbered(attributes, ENTITY_CLASS, "Class", 1..=3),
            numbered(attributes, ENTITY_SUBCLASS, "Subclass", 1..=2),
        ) else {
            return left_out(
                notes,
                "its EntityClass or EntitySubclass is not one the schema has",
            );
        };
        Some(Declared {
            profile_version: profile_version.to_string(),
            entity_class,
            entity_subclass,
            ase: attribute(&dap.item.attributes, ASE_SUPPORTED).is_some_and(is_true),
            pesap_uses_ase: attribute(attributes, PESAP_USES_ASE).is_some_and(is_true),
            modes,
        })
    }

    pub fn write(&self, out: &mut TomlOut) {
        out.table("profinet.profienergy");
        out.string("profile_version", &self.profile_version);
        if let Some(class) = self.entity_class {
            out.key("entity_class", class);
        }
        if let Some(subclass) = self.entity_subclass {
            out.key("entity_subclass", subclass);
        }
        if self.ase {
            out.key("ase", true);
        }
        if self.pesap_uses_ase {
            out.key("pesap_uses_ase", true);
        }
        if self.modes.is_empty() {
            return;
        }
        let modes: Vec<String> = self
            .modes
            .iter()
            .map(|mode| {
                let keys: Vec<String> = MODE
                    .iter()
                    .zip(mode)
                    .map(|((_, key), value)| format!("{key} = {value}"))
                    .collect();
                format!("  {{ {} }},\n", keys.join(", "))
            })
            .collect();
        out.key("modes", format!("[\n{}]", modes.concat()));
    }
}

/// Each mode's ID and times, from the attributes that join every mode's
/// values; `None` when they are not one each per mode, or not numbers of
/// the schema's types (an ID of 8 bits, times of 32).
fn modes(attributes: &[Attribute]) -> Option<Vec<[u32; 4]>> {
    let columns: Vec<Vec<u32>> = MODE
        .iter()
        .map(|(name, _)| {
            let values = attribute(attributes, name).unwrap_or("");
            values.split_whitespace().map(|v| v.parse().ok()).collect()
        })
        .collect::<Option<_>>()?;
    let count = columns[0].len();
    let fits = columns.iter().all(|c| c.len() == count) && columns[0].iter().all(|&id| id <= 0xFF);
    fits.then(|| {
        (0..count)
            .map(|i| [0, 1, 2, 3].map(|c| columns[c][i]))
            .collect()
    })
}

/// `Class2` as 2, within `range`; `Some(None)` when the attribute is
/// absent, `None` when it is not one of them.
fn numbered(
    attributes: &[Attribute],
    name: &str,
    prefix: &str,
    range: std::ops::RangeInclusive<u8>,
) -> Option<Option<u8>> {
    let Some(value) = attribute(attributes, name) else {
        return Some(None);
    };
    let n: u8 = value.strip_prefix(prefix)?.parse().ok()?;
    range.contains(&n).then_some(Some(n))
}
