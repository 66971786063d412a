//! `[profinet.stack]`: what a device access point's attributes declare
//! of the card's PROFINET stack, as the description's keys say it, and a
//! later access point's `stack = { ... }` where it differs from the first.

use super::{attribute, found, list, quote, submodules_of, Recognised};
use crate::device::pn::{Dap, SubmoduleKind};
use crate::device::Attribute;
use crate::gsdml::values::ValueList;
use crate::import::Notes;
use crate::ir::profinet::{last_used_slot, AddressAssignment, Slots, Version, MODULE_SLOT};
use crate::lower::{IoNeed, Offer};
use crate::spec::{
    is_gsdml_web_server, Introduced, ADAPTS_REAL_IDENTIFICATION, CHECK_MAU_TYPE_DIFFERENCE,
    WEB_SERVER,
};
use std::ops::RangeInclusive;

/// One device access point's stack, as its file declares it; a value
/// the description cannot state is left out (W600) and unwritten.
pub(super) struct Declared {
    address_assignment: Option<Vec<String>>,
    device_access: bool,
    device_access_ars: Option<u8>,
    name_of_station_not_transferable: bool,
    shared_device: bool,
    application_relations: Option<u16>,
    mau_type_adjustable: bool,
    /// PhysicalSlots' last, where more than the last a module goes into,
    /// which gsdc writes without it.
    last_slot: Option<u16>,
    last_used_slot: u16,
    /// IOConfigData's MaxInputLength and MaxOutputLength, and its
    /// MaxDataLength (both ways together: written only when the file has
    /// it).
    io: [IoLimit; 2],
    data: IoLimit,
    power_on_to_comm_ready: Option<u32>,
    network_component_diagnosis: bool,
    /// Each port's flags, in [`PORT_FLAGS`]' order, and link state
    /// diagnosis.
    port_flags: [bool; 3],
    link_state_diagnosis: Option<String>,
    adapts_real_identification: bool,
    web_server: Option<String>,
}

/// The ports' flags: each port's attribute, and the key that says it for
/// every port.
const PORT_FLAGS: [(&str, &str); 3] = [
    ("PortDeactivationSupported", "port_deactivation"),
    ("CheckMAUTypeSupported", "check_mau_type"),
    (CHECK_MAU_TYPE_DIFFERENCE.name, "check_mau_type_difference"),
];
const LINK_STATES: [&str; 3] = ["Up", "Down", "Up+Down"];

/// One of IOConfigData's lengths: the file's, and what the access point's
/// modules need as gsdc counts it (gsdc writes the full need unless
/// stated).
#[derive(Clone, Copy)]
struct IoLimit {
    file: Option<u16>,
    need: IoNeed,
}

/// Where the modules go, as the import takes them: the data modules'
/// slots, the empty module's and the safety modules'; an access point's
/// IO need counts the safety modules it offers.
pub struct Placed {
    pub module_slots: Slots,
    /// The empty module's, which every access point offers.
    pub empty: Option<Offer>,
    /// The safety modules imported, by their IDs, in order.
    pub safety: Vec<(String, Offer)>,
}

impl IoLimit {
    /// What the description states: the file's length, where not the
    /// full need.
    fn stated(self) -> Option<u16> {
        self.file.filter(|&f| f != self.need.written())
    }
}

impl Declared {
    /// `modules` are those the import takes, in `slots` (with the empty
    /// module's); the DAP's own offer counts. `file` is the GSDML version
    /// the description's file declares: an attribute gsdc writes only from
    /// a later version is left out.
    pub fn of(
        dap: &Dap,
        (modules, placed): (&[Recognised], &Placed),
        file: Version,
        notes: &mut Notes,
    ) -> Declared {
        let attributes = &dap.item.attributes;
        let interface = submodules_of(dap, SubmoduleKind::Interface).next();
        let flag = |name: &str| attribute(attributes, name).is_some_and(is_true);
        let device_access = flag("DeviceAccessSupported");
        let device_access_ars = number(
            notes,
            attributes,
            "NumberOfDeviceAccessAR",
            1..=u8::MAX.into(),
            "the description's device_access_ars is 1 to 255",
        )
        .and_then(|n| u8::try_from(n).ok());
        let device_access_ars = match (device_access_ars, device_access) {
            (Some(_), false) => {
                if let Some((a, _)) = found(attributes, "NumberOfDeviceAccessAR") {
                    notes.unsaid("NumberOfDeviceAccessAR", &a.place, "the description's device_access_ars needs device_access = true (E184), and DeviceAccessSupported is not true");
                }
                None
            }
            (ars, _) => ars,
        };
        let application_relations = number(
            notes,
            interface.map_or(&[][..], |s| &s.attributes[..]),
            "ApplicationRelations@NumberOfAR",
            1..=u16::MAX,
            "the description's application_relations is 1 to 65535",
        );
        let offered = modules
            .iter()
            .filter(|m| dap.useable_modules.iter().any(|r| r.target == m.module.id))
            .map(|m| Offer::data_module(m.layout, m.access_point.is_some(), placed.module_slots));
        let ports = submodules_of(dap, SubmoduleKind::Port).count();
        let safety = placed
            .safety
            .iter()
            .filter(|(id, _)| dap.useable_modules.iter().any(|r| r.target == *id));
        let others: Vec<Offer> = placed
            .empty
            .into_iter()
            .chain(safety.map(|(_, o)| *o))
            .collect();
        let last_used_slot = last_used_slot(placed.module_slots, others.iter().map(|o| o.slots));
        let need = crate::lower::io_length(offered.chain(others), ports);
        let io = [
            ("MaxInputLength", need.input),
            ("MaxOutputLength", need.output),
        ]
        .map(|(name, need)| io_limit(attributes, name, need, notes));
        // Written where stated, at least both ways' least.
        let both = need.input.least + need.output.least;
        let need = IoNeed {
            least: both,
            full: both.into(),
        };
        let data = io_limit(attributes, "MaxDataLength", need, notes);
        let interface_flag = |name: &str| {
            interface.is_some_and(|s| attribute(&s.attributes, name).is_some_and(is_true))
        };
        Declared {
            io,
            data,
            last_slot: last_slot(notes, attributes).filter(|&last| last > last_used_slot),
            last_used_slot,
            mau_type_adjustable: mau_type_adjustable(dap, notes),
            power_on_to_comm_ready: power_on_to_comm_ready(attributes, notes),
            network_component_diagnosis: interface_flag("NetworkComponentDiagnosisSupported"),
            port_flags: PORT_FLAGS.map(|(name, key)| {
                let on = every_port(dap, name, key, notes, |value| value.is_some_and(is_true));
                on && (name != CHECK_MAU_TYPE_DIFFERENCE.name
                    || written_in(CHECK_MAU_TYPE_DIFFERENCE, file, dap, notes))
            }),
            adapts_real_identification: flag(ADAPTS_REAL_IDENTIFICATION.name)
                && written_in(ADAPTS_REAL_IDENTIFICATION, file, dap, notes),
            web_server: web_server(dap, file, notes),
            link_state_diagnosis: link_state_diagnosis(dap, notes),
            address_assignment: address_assignment(dap, notes),
            device_access,
            device_access_ars,
            name_of_station_not_transferable: flag("NameOfStationNotTransferable"),
            shared_device: flag("SharedDeviceSupported"),
            application_relations,
        }
    }

    /// The keys of `[profinet.stack]` that say this stack, the others
    /// gsdc's defaults.
    pub fn keys(&self) -> Vec<(&'static str, String)> {
        self.keys_over(&self.gsdc())
    }

    /// What a later access point's `stack` states over the first's;
    /// Err when it has no NumberOfDeviceAccessAR while the first has (the
    /// description's later access points take the first's).
    pub fn over_first(&self, first: &Declared) -> Result<Vec<(&'static str, String)>, String> {
        if self.device_access_ars.is_none() && first.device_access_ars.is_some() {
            return Err("it has no NumberOfDeviceAccessAR, which the first has: the description's later device access points take the first's".into());
        }
        if self.web_server.is_none() && first.web_server.is_some() {
            return Err("it has no WebServer, which the first has: the description's later device access points take the first's".into());
        }
        if self.data.file.is_none() && first.data.file.is_some() {
            return Err("it has no IOConfigData@MaxDataLength, which the first has: the description's later device access points take the first's".into());
        }
        Ok(self.keys_over(first))
    }

    /// What gsdc writes without `[profinet.stack]`.
    fn gsdc(&self) -> Declared {
        Declared {
            io: self.io.map(|l| IoLimit { file: None, ..l }),
            data: IoLimit {
                file: None,
                ..self.data
            },
            address_assignment: None,
            device_access: false,
            device_access_ars: None,
            name_of_station_not_transferable: false,
            shared_device: false,
            application_relations: None,
            mau_type_adjustable: false,
            last_slot: None,
            last_used_slot: self.last_used_slot,
            power_on_to_comm_ready: None,
            network_component_diagnosis: false,
            port_flags: [false; 3],
            link_state_diagnosis: None,
            adapts_real_identification: false,
            web_server: None,
        }
    }

    /// The keys whose value differs from `base`'s. An assignment or a count
    /// of ARs `base` has and this one does not is its schema default.
    fn keys_over(&self, base: &Declared) -> Vec<(&'static str, String)> {
        let mut keys = Vec::new();
        if self.address_assignment != base.address_assignment {
            let ways = self
                .address_assignment
                .clone()
                .unwrap_or_else(|| vec!["DCP".into()]);
            keys.push(("address_assignment", list(ways.iter().map(|w| quote(w)))));
        }
        flag(
            &mut keys,
            "device_access",
            self.device_access,
            base.device_access,
        );
        if self.device_access_ars != base.device_access_ars {
            keys.extend(
                self.device_access_ars
                    .map(|n| ("device_access_ars", n.to_string())),
            );
        }
        flag(
            &mut keys,
            "name_of_station_not_transferable",
            self.name_of_station_not_transferable,
            base.name_of_station_not_transferable,
        );
        flag(
            &mut keys,
            "shared_device",
            self.shared_device,
            base.shared_device,
        );
        flag(
            &mut keys,
            "mau_type_adjustable",
            self.mau_type_adjustable,
            base.mau_type_adjustable,
        );
        if self.power_on_to_comm_ready != base.power_on_to_comm_ready {
            keys.extend(
                self.power_on_to_comm_ready
                    .map(|ms| ("power_on_to_comm_ready", ms.to_string())),
            );
        }
        flag(
            &mut keys,
            "network_component_diagnosis",
            self.network_component_diagnosis,
            base.network_component_diagnosis,
        );
        for ((_, key), (&mine, &theirs)) in PORT_FLAGS
            .iter()
            .zip(self.port_flags.iter().zip(&base.port_flags))
        {
            flag(&mut keys, key, mine, theirs);
        }
        flag(
            &mut keys,
            "adapts_real_identification",
            self.adapts_real_identification,
            base.adapts_real_identification,
        );
        if self.web_server != base.web_server {
            keys.extend(
                self.web_server
                    .as_deref()
                    .map(|url| ("web_server", quote(url))),
            );
        }
        if self.link_state_diagnosis != base.link_state_diagnosis {
            keys.extend(
                self.link_state_diagnosis
                    .as_deref()
                    .map(|link| ("link_state_diagnosis", quote(link))),
            );
        }
        if self.application_relations != base.application_relations {
            keys.push((
                "application_relations",
                self.application_relations.unwrap_or(1).to_string(),
            ));
        }
        let slots = |d: &Declared| d.last_slot.unwrap_or(d.last_used_slot);
        if slots(self) != slots(base) {
            keys.push(("last_slot", slots(self).to_string()));
        }
        // What gsdc writes for this DAP without a key: the base's stated
        // length (a later DAP takes the first's), else what it needs.
        for (key, (mine, base)) in ["max_input_length", "max_output_length"]
            .into_iter()
            .zip(self.io.iter().zip(&base.io))
        {
            let wanted = mine.stated().unwrap_or(mine.need.written());
            let inherited = base
                .stated()
                .map_or(mine.need.written(), |b| b.max(mine.need.least));
            if wanted != inherited {
                keys.push((key, wanted.to_string()));
            }
        }
        // Only where the file writes one: `over_first` refuses a later DAP
        // without one under the first's.
        let inherited = base.data.file.map(|b| b.max(self.data.need.least));
        if let Some(data) = self.data.file.filter(|&d| Some(d) != inherited) {
            keys.push(("max_data_length", data.to_string()));
        }
        keys
    }
}

/// An IOConfigData length, `need` what the modules need as gsdc counts
/// it; one less than the largest module needs, or more than the
/// description takes, is left out, and the round trip judges it.
fn io_limit(attributes: &[Attribute], name: &str, need: IoNeed, notes: &mut Notes) -> IoLimit {
    let max = match name {
        "MaxDataLength" => 2 * crate::lower::MAX_IO_LENGTH,
        _ => crate::lower::MAX_IO_LENGTH,
    };
    let least = need.least;
    let why = format!("the description's IO lengths are from what the largest module needs as gsdc counts it ({least}) to {max}");
    let name = format!("IOConfigData@{name}");
    let file = number(notes, attributes, &name, least..=max, &why);
    IoLimit { file, need }
}

/// An `xsd:boolean` that is true.
pub(super) fn is_true(value: &str) -> bool {
    matches!(value, "true" | "1")
}

/// `key = mine` where it is not `theirs`.
fn flag(keys: &mut Vec<(&'static str, String)>, key: &'static str, mine: bool, theirs: bool) {
    if mine != theirs {
        keys.push((key, mine.to_string()));
    }
}

/// A number an attribute declares, within `range`; one outside it, or
/// not a number, is left out with `why`.
fn number(
    notes: &mut Notes,
    attributes: &[Attribute],
    name: &str,
    range: RangeInclusive<u16>,
    why: &str,
) -> Option<u16> {
    let (a, value) = found(attributes, name)?;
    let parsed = value.parse().ok().filter(|n| range.contains(n));
    if parsed.is_none() {
        notes.unsaid(&format!("{name} `{value}`"), &a.place, why);
    }
    parsed
}

/// The last slot of PhysicalSlots, when it names the slots from 0 to one
/// (`0..2`, `0 1 2`); another list is left out.
fn last_slot(notes: &mut Notes, attributes: &[Attribute]) -> Option<u16> {
    let (a, value) = found(attributes, "PhysicalSlots")?;
    // As a set of merged ranges: a list's ranges are never expanded, so a
    // hostile `0..65535` repeated costs nothing.
    let from_zero = match ValueList::parse(value).as_ref().map(ValueList::ranges) {
        Some(&[(0, last)]) => u16::try_from(last)
            .ok()
            .filter(|last| (MODULE_SLOT..=crate::lower::MAX_SLOT).contains(last)),
        _ => None,
    };
    if from_zero.is_none() {
        notes.unsaid(
            &format!("PhysicalSlots `{value}`"),
            &a.place,
            &format!(
                "the description's last_slot gives the slots from 0 to it, 1 to {}",
                crate::lower::MAX_SLOT
            ),
        );
    }
    from_zero
}

/// Whether the controller may set each port's MAU type: `AdjustSupported`
/// on every MAU type of every port.
fn mau_type_adjustable(dap: &Dap, notes: &mut Notes) -> bool {
    every_port(
        dap,
        "MAUTypeList/MAUTypeItem@AdjustSupported",
        "mau_type_adjustable",
        notes,
        |value| value.is_some_and(|v| v.split_whitespace().all(is_true)),
    )
}

/// `PowerOnToCommReady`, when a number of ms.
fn power_on_to_comm_ready(attributes: &[Attribute], notes: &mut Notes) -> Option<u32> {
    let (a, value) = found(attributes, "PowerOnToCommReady")?;
    let parsed = value.parse().ok();
    if parsed.is_none() {
        let why = "the description's power_on_to_comm_ready is a number of ms";
        notes.unsaid(&format!("PowerOnToCommReady `{value}`"), &a.place, why);
    }
    parsed
}

/// Each port's `LinkStateDiagnosisCapability`, one the description names.
fn link_state_diagnosis(dap: &Dap, notes: &mut Notes) -> Option<String> {
    const NAME: &str = "LinkStateDiagnosisCapability";
    let link = every_port(dap, NAME, "link_state_diagnosis", notes, |value| {
        value.map(str::to_string)
    })?;
    if LINK_STATES.contains(&link.as_str()) {
        return Some(link);
    }
    let port = submodules_of(dap, SubmoduleKind::Port).next()?;
    let place = found(&port.attributes, NAME).map_or(&port.place, |(a, _)| &a.place);
    let why = "the description's link_state_diagnosis is \"Up\", \"Down\" or \"Up+Down\"";
    notes.unsaid(&format!("{NAME} `{link}`"), place, why);
    None
}

/// What the first port declares in its attribute `name` (as `read`
/// reads it), which the description's `key` gives every port; a port that
/// declares otherwise is left out at its attribute.
fn every_port<T: PartialEq + Default>(
    dap: &Dap,
    name: &str,
    key: &str,
    notes: &mut Notes,
    read: impl Fn(Option<&str>) -> T,
) -> T {
    let mut ports = submodules_of(dap, SubmoduleKind::Port);
    let Some(first) = ports.next() else {
        return T::default();
    };
    let first_value = read(attribute(&first.attributes, name));
    for port in ports.filter(|p| read(attribute(&p.attributes, name)) != first_value) {
        let place = found(&port.attributes, name).map_or(&port.place, |(a, _)| &a.place);
        notes.unsaid(
            &format!("port `{}`'s {name}", port.id),
            place,
            &format!(
                "the description's {key} is one value for every port of a device access point"
            ),
        );
    }
    first_value
}

/// The access point's `WebServer`, where the description can say it: the
/// schema's pattern, in a file of a version gsdc writes it in.
fn web_server(dap: &Dap, file: Version, notes: &mut Notes) -> Option<String> {
    let (a, url) = found(&dap.item.attributes, WEB_SERVER.name)?;
    if !is_gsdml_web_server(url) {
        let why = "the description's web_server is the PI schema's pattern: http:// or https://, a port, a path (E003)";
        notes.unsaid(&format!("WebServer `{url}`"), &a.place, why);
        return None;
    }
    written_in(WEB_SERVER, file, dap, notes).then(|| url.to_string())
}

/// Whether the description's file, of GSDML version `file`, can say the
/// attribute the access point (or its ports) declares: gsdc writes it only
/// from the version a file at hand first shows it in (E198); left out at
/// each place that declares it (but false, which gsdc's silence says)
/// otherwise.
fn written_in(introduced: Introduced, file: Version, dap: &Dap, notes: &mut Notes) -> bool {
    if file >= introduced.version {
        return true;
    }
    let name = introduced.name;
    let why = later_than(introduced, file);
    let ports = submodules_of(dap, SubmoduleKind::Port).map(|p| &p.attributes[..]);
    for attributes in std::iter::once(&dap.item.attributes[..]).chain(ports) {
        let declared = found(attributes, name).filter(|(_, v)| !matches!(*v, "false" | "0"));
        if let Some((a, value)) = declared {
            notes.unsaid(&format!("{name}=\"{value}\""), &a.place, &why);
        }
    }
    false
}

/// Why what a file of GSDML `file` declares is left out: gsdc writes it
/// only from the version a file at hand first shows it in (E198).
pub(super) fn later_than(introduced: Introduced, file: Version) -> String {
    format!(
        "gsdc writes it in GSDML {} and later (E198), the first version a file at hand shows it in ({}), and the description's file is {file}",
        introduced.version.number(),
        introduced.shown_by
    )
}

/// AddressAssignment's ways, when each is one the description names, once.
fn address_assignment(dap: &Dap, notes: &mut Notes) -> Option<Vec<String>> {
    let (a, value) = found(&dap.item.attributes, "AddressAssignment")?;
    let ways: Vec<String> = value.split(';').map(|w| w.trim().to_string()).collect();
    let known = ways
        .iter()
        .all(|w| AddressAssignment::ALL.iter().any(|a| a.token() == w));
    let once = ways.iter().enumerate().all(|(i, w)| !ways[..i].contains(w));
    if known && once {
        return Some(ways);
    }
    notes.unsaid(
        &format!("AddressAssignment `{value}`"),
        &a.place,
        "the description's address_assignment names DCP, DHCP and LOCAL, each once",
    );
    None
}
