//! `[profinet.irt]` from a device access point's RT_CLASS_3 elements (its
//! interface's `RT_Class3Properties`, `SynchronisationMode` and
//! `RT_Class3TimingProperties`, its ports' delays), and
//! `[profinet.isochronous]` from its modules' `IsochroneMode`. Each is
//! imported whole or not at all: a value the description cannot hold
//! leaves the table out, said at its attribute, and the round trip judges
//! the rest.

use super::{attribute, found, list, submodules_of, Recognised};
use crate::device::pn::{Dap, SubmoduleKind};
use crate::device::Attribute;
use crate::import::toml_out::TomlOut;
use crate::import::Notes;

/// What a value of the description's is, as the file writes it.
#[derive(Clone, Copy)]
enum Form {
    Number,
    /// Numbers separated by blanks.
    Numbers,
    /// `;`-separated tokens, each one of these.
    Tokens(&'static [&'static str]),
}

/// `[profinet.irt]`'s keys from the interface's attributes: each with its
/// attribute and form, and whether the description requires it.
const IRT_KEYS: [(&str, &str, Form, bool); 9] = [
    (
        "max_bridge_delay",
        "RT_Class3Properties@MaxBridgeDelay",
        Form::Number,
        true,
    ),
    (
        "max_number_ir_frame_data",
        "RT_Class3Properties@MaxNumberIR_FrameData",
        Form::Number,
        true,
    ),
    (
        "forwarding_mode",
        "RT_Class3Properties@ForwardingMode",
        Form::Tokens(&["Absolute", "Relative"]),
        false,
    ),
    (
        "startup_mode",
        "RT_Class3Properties@StartupMode",
        Form::Tokens(&["Legacy", "Advanced"]),
        false,
    ),
    (
        "send_clock",
        "ApplicationRelations/RT_Class3TimingProperties@SendClock",
        Form::Numbers,
        true,
    ),
    (
        "reduction_ratio",
        "ApplicationRelations/RT_Class3TimingProperties@ReductionRatio",
        Form::Numbers,
        true,
    ),
    (
        "preferred_send_clock",
        "ApplicationRelations/RT_Class3TimingProperties@PreferredSendClock",
        Form::Number,
        false,
    ),
    (
        "max_local_jitter",
        "SynchronisationMode@MaxLocalJitter",
        Form::Number,
        false,
    ),
    (
        "t_pll_max",
        "SynchronisationMode@T_PLL_MAX",
        Form::Number,
        false,
    ),
];

/// Each port's delays: the key and the attribute.
const PORT_KEYS: [(&str, &str); 2] = [
    ("port_tx_delay", "MaxPortTxDelay"),
    ("port_rx_delay", "MaxPortRxDelay"),
];

/// `[profinet.isochronous]`'s keys from a data submodule's `IsochroneMode`.
const ISOCHRONOUS_KEYS: [(&str, &str); 6] = [
    ("t_dc_base", "IsochroneMode@T_DC_Base"),
    ("t_dc_min", "IsochroneMode@T_DC_Min"),
    ("t_dc_max", "IsochroneMode@T_DC_Max"),
    ("t_io_base", "IsochroneMode@T_IO_Base"),
    ("t_io_input_min", "IsochroneMode@T_IO_InputMin"),
    ("t_io_output_min", "IsochroneMode@T_IO_OutputMin"),
];
const ISOCHRONOUS_REQUIRED: &str = "IsochroneMode@IsochroneModeRequired";

/// The interface's attributes gsdc writes with RT_CLASS_3, beside those it
/// always writes (`super::INTERFACE_ATTRIBUTES`).
pub(super) const IRT_INTERFACE_ATTRIBUTES: &[(&str, Option<&str>)] = &[
    ("SupportedRT_Classes", Some("RT_CLASS_1;RT_CLASS_3")),
    ("DelayMeasurementSupported", Some("true")),
    ("RT_Class3Properties@MaxBridgeDelay", None),
    ("RT_Class3Properties@MaxNumberIR_FrameData", None),
    ("RT_Class3Properties@ForwardingMode", None),
    ("RT_Class3Properties@StartupMode", None),
    ("SynchronisationMode@SupportedRole", Some("SyncSlave")),
    ("SynchronisationMode@SupportedSyncProtocols", Some("PTCP")),
    ("SynchronisationMode@MaxLocalJitter", None),
    ("SynchronisationMode@T_PLL_MAX", None),
    (
        "ApplicationRelations/RT_Class3TimingProperties@SendClock",
        None,
    ),
    (
        "ApplicationRelations/RT_Class3TimingProperties@ReductionRatio",
        None,
    ),
    (
        "ApplicationRelations/RT_Class3TimingProperties@PreferredSendClock",
        None,
    ),
];
pub(super) const IRT_PORT_ATTRIBUTES: &[(&str, Option<&str>)] =
    &[("MaxPortTxDelay", None), ("MaxPortRxDelay", None)];
/// What gsdc writes with isochronous mode: of the interface, of each data
/// submodule (and the device access point's application class,
/// `application_class`).
pub(super) const ISOCHRONOUS_INTERFACE_ATTRIBUTES: &[(&str, Option<&str>)] = &[
    ("IsochroneModeSupported", Some("true")),
    ("IsochroneModeInRT_Classes", Some("RT_CLASS_3")),
];
pub(super) const ISOCHRONOUS_SUBMODULE_ATTRIBUTES: &[(&str, Option<&str>)] = &[
    ("IsochroneMode@T_DC_Base", None),
    ("IsochroneMode@T_DC_Min", None),
    ("IsochroneMode@T_DC_Max", None),
    ("IsochroneMode@T_IO_Base", None),
    ("IsochroneMode@T_IO_InputMin", None),
    ("IsochroneMode@T_IO_OutputMin", None),
    (ISOCHRONOUS_REQUIRED, None),
];

/// The two tables as the import writes them, each its keys and values.
pub(super) struct Declared {
    pub irt: Option<Vec<(&'static str, String)>>,
    pub isochronous: Option<Vec<(&'static str, String)>>,
}

impl Declared {
    pub fn of(dap: &Dap, modules: &[Recognised], notes: &mut Notes) -> Declared {
        let irt = irt(dap, notes);
        let isochronous = irt.as_ref().and_then(|_| isochronous(modules, notes));
        Declared { irt, isochronous }
    }

    pub fn write(&self, out: &mut TomlOut) {
        for (table, keys) in [
            ("profinet.irt", &self.irt),
            ("profinet.isochronous", &self.isochronous),
        ] {
            let Some(keys) = keys else {
                continue;
            };
            out.table(table);
            for (key, value) in keys {
                out.key(key, value);
            }
        }
    }
}

/// `[profinet.irt]`'s keys, when the interface has `RT_Class3Properties`
/// and every value fits the description.
fn irt(dap: &Dap, notes: &mut Notes) -> Option<Vec<(&'static str, String)>> {
    let interface = submodules_of(dap, SubmoduleKind::Interface).next()?;
    let attributes = &interface.attributes;
    attribute(attributes, "RT_Class3Properties@MaxBridgeDelay")?;
    let mut keys = Vec::new();
    for (key, name, form, required) in IRT_KEYS {
        match found(attributes, name) {
            Some((a, value)) => keys.push((key, written(a, value, form, notes)?)),
            None if required => {
                let why = "the description's RT_CLASS_3 needs it, and the file does not give it";
                notes.unsaid("RT_CLASS_3", &interface.place, &format!("{why}: {name}"));
                return None;
            }
            None => {}
        }
    }
    for (key, name) in PORT_KEYS {
        keys.push((key, port_delay(dap, name, notes)?));
    }
    Some(keys)
}

/// A delay every port declares alike, which the description gives once.
fn port_delay(dap: &Dap, name: &str, notes: &mut Notes) -> Option<String> {
    let mut value = None;
    for port in submodules_of(dap, SubmoduleKind::Port) {
        let Some((a, delay)) = found(&port.attributes, name) else {
            let why = format!("the description's RT_CLASS_3 gives each port's {name}, which this port does not declare");
            notes.unsaid("RT_CLASS_3", &port.place, &why);
            return None;
        };
        let delay = written(a, delay, Form::Number, notes)?;
        if value.as_ref().is_some_and(|v| *v != delay) {
            let why = format!(
                "the description gives every port one {name}, and the ports declare different ones"
            );
            notes.unsaid("RT_CLASS_3", &a.place, &why);
            return None;
        }
        value = Some(delay);
    }
    value
}

/// `[profinet.isochronous]`'s keys from the first module with an
/// `IsochroneMode`; the round trip judges a module whose mode differs.
fn isochronous(modules: &[Recognised], notes: &mut Notes) -> Option<Vec<(&'static str, String)>> {
    let attributes = modules
        .iter()
        .map(|m| &m.data.attributes)
        .find(|a| attribute(a, "IsochroneMode@T_DC_Base").is_some())?;
    let mut keys = Vec::new();
    if let Some((a, required)) = found(attributes, ISOCHRONOUS_REQUIRED) {
        match required {
            "true" | "false" => keys.push(("required", required.to_string())),
            _ => return not_a_value(a, "true or false", notes),
        }
    }
    for (key, name) in ISOCHRONOUS_KEYS {
        let (a, value) = found(attributes, name)?;
        keys.push((key, written(a, value, Form::Number, notes)?));
    }
    Some(keys)
}

/// A value as the description writes it, when it is one of its form.
fn written(a: &Attribute, value: &str, form: Form, notes: &mut Notes) -> Option<String> {
    let number = |n: &str| n.parse::<u32>().ok().map(|n| n.to_string());
    match form {
        Form::Number => number(value).or_else(|| not_a_value(a, "a number", notes)),
        Form::Numbers => {
            let numbers: Option<Vec<String>> = value.split_whitespace().map(number).collect();
            match numbers {
                Some(n) if !n.is_empty() => Some(list(n)),
                _ => not_a_value(a, "numbers", notes),
            }
        }
        Form::Tokens(known) => {
            let tokens: Vec<&str> = value.split(';').collect();
            match tokens.iter().all(|t| known.contains(t)) {
                true => Some(list(tokens.iter().map(|t| format!("\"{t}\"")))),
                false => not_a_value(a, &format!("a list of {}", known.join(", ")), notes),
            }
        }
    }
}

fn not_a_value<T>(a: &Attribute, expected: &str, notes: &mut Notes) -> Option<T> {
    let why = format!("the description holds {expected} there");
    notes.unsaid(&a.name, &a.place, &why);
    None
}
