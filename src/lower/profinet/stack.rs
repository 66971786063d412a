//! `[profinet.stack]`: what the card's PROFINET stack offers the
//! controllers through a device access point. A later DAP's `stack` states
//! what differs from the first's; each key it leaves out is the first's.

use super::io::{IoNeeds, MAX_IO_LENGTH};
use crate::description::{self as raw, AddressAssignment as RawAssignment, LinkStateDiagnosis};
use crate::diag::Diagnostic;
use crate::ir::profinet::{AddressAssignment, Stack, Version};
use crate::lower::checks::Checker;
use crate::spec::{
    is_gsdml_web_server, ADAPTS_REAL_IDENTIFICATION, CHECK_MAU_TYPE_DIFFERENCE, WEB_SERVER,
};
use toml::Spanned;

/// The stack `given` states over `inherited` (gsdc's defaults for the
/// first DAP); `at` is the table's path. E101 for a number out of its
/// range (`last_slot` below the last slot a module goes into among them),
/// E184 for device access ARs without device access.
pub fn lower(
    cx: &mut Checker,
    (given, inherited): (&raw::Stack, &Stack),
    at: &str,
    (file, last_used_slot): (Version, u16),
) -> Option<Stack> {
    let flag = |key: &Option<Spanned<bool>>, inherited: bool| {
        key.as_ref().map_or(inherited, |k| *k.get_ref())
    };
    let address_assignment = match &given.address_assignment {
        Some(list) => address_assignment(cx, list, at)?,
        None => inherited.address_assignment.clone(),
    };
    // Each: `None` left out (inherited), `Some(None)` out of range.
    let ars = given.device_access_ars.as_ref().map(|n| {
        cx.spanned_in_range::<u8, _>(n, 1, u8::MAX.into(), &format!("{at}.device_access_ars"))
    });
    let mut number = |key: &Option<Spanned<u16>>, name: &str, (min, max): (u16, u16)| {
        let n = key.as_ref()?;
        Some(cx.spanned_in_range::<u16, _>(n, min.into(), max.into(), &format!("{at}.{name}")))
    };
    let relations = number(
        &given.application_relations,
        "application_relations",
        (1, u16::MAX),
    );
    let input = number(
        &given.max_input_length,
        "max_input_length",
        (1, MAX_IO_LENGTH),
    );
    let output = number(
        &given.max_output_length,
        "max_output_length",
        (1, MAX_IO_LENGTH),
    );
    let data = number(
        &given.max_data_length,
        "max_data_length",
        (1, 2 * MAX_IO_LENGTH),
    );
    let last_slot = number(&given.last_slot, "last_slot", (last_used_slot, MAX_SLOT));
    let stack = Stack {
        address_assignment,
        device_access: flag(&given.device_access, inherited.device_access),
        device_access_ars: stated_or(ars, inherited.device_access_ars)?,
        name_of_station_not_transferable: flag(
            &given.name_of_station_not_transferable,
            inherited.name_of_station_not_transferable,
        ),
        shared_device: flag(&given.shared_device, inherited.shared_device),
        mau_type_adjustable: flag(&given.mau_type_adjustable, inherited.mau_type_adjustable),
        application_relations: stated_or(relations, inherited.application_relations)?,
        max_input_length: stated_or(input, inherited.max_input_length)?,
        max_output_length: stated_or(output, inherited.max_output_length)?,
        max_data_length: stated_or(data, inherited.max_data_length)?,
        last_slot: stated_or(last_slot, inherited.last_slot)?,
        power_on_to_comm_ready: given
            .power_on_to_comm_ready
            .as_ref()
            .map(|ms| *ms.get_ref())
            .or(inherited.power_on_to_comm_ready),
        network_component_diagnosis: flag(
            &given.network_component_diagnosis,
            inherited.network_component_diagnosis,
        ),
        port_deactivation: flag(&given.port_deactivation, inherited.port_deactivation),
        check_mau_type: flag(&given.check_mau_type, inherited.check_mau_type),
        link_state_diagnosis: given
            .link_state_diagnosis
            .as_ref()
            .map(|l| link_state_token(*l.get_ref()))
            .or(inherited.link_state_diagnosis),
        check_mau_type_difference: flag(
            &given.check_mau_type_difference,
            inherited.check_mau_type_difference,
        ),
        adapts_real_identification: flag(
            &given.adapts_real_identification,
            inherited.adapts_real_identification,
        ),
        web_server: match &given.web_server {
            Some(url) => Some(web_server(cx, url, file)?),
            None => inherited.web_server.clone(),
        },
    };
    check_device_access(cx, given, &stack)?;
    let later = [
        (&given.check_mau_type_difference, CHECK_MAU_TYPE_DIFFERENCE),
        (
            &given.adapts_real_identification,
            ADAPTS_REAL_IDENTIFICATION,
        ),
    ];
    for (key, introduced) in later {
        let stated_true = key.as_ref().filter(|k| *k.get_ref());
        if let Some(key) = stated_true {
            super::written_in(cx, key.span(), file, introduced);
        }
    }
    Some(stack)
}

/// `WebServer`: the schema's pattern (E003 otherwise), in a file of a
/// version a file at hand shows it in (E198).
fn web_server(cx: &mut Checker, url: &Spanned<String>, file: Version) -> Option<String> {
    super::written_in(cx, url.span(), file, WEB_SERVER);
    let text = url.get_ref();
    if is_gsdml_web_server(text) {
        return Some(text.clone());
    }
    cx.push(
        Diagnostic::error("E003", format!("`{text}` is not a GSDML web server address"))
            .at(url.span())
            .label("not http:// or https://, a port, a path")
            .help("write the scheme, the port and the path of the card's web server without a host, which the engineering tool fills in: \"http://:80/\" (SEW's MOVI-C)"),
    );
    None
}

fn link_state_token(link: LinkStateDiagnosis) -> &'static str {
    match link {
        LinkStateDiagnosis::Up => "Up",
        LinkStateDiagnosis::Down => "Down",
        LinkStateDiagnosis::UpAndDown => "Up+Down",
    }
}

/// A number stated (`Some`, `Some(None)` when it was refused) or else
/// `inherited`; `None` when refused.
fn stated_or<T>(stated: Option<Option<T>>, inherited: Option<T>) -> Option<Option<T>> {
    match stated {
        Some(value) => value.map(Some),
        None => Some(inherited),
    }
}

/// gsdc's bound on the last slot, not the schema's (`PhysicalSlots` is a
/// ValueListT without one): 0x7FFF, where the schema's other 15-bit
/// PROFINET numbers (record indexes, vendor error types) end.
pub(crate) const MAX_SLOT: u16 = 0x7FFF;

/// IOConfigData's lengths of a DAP whose modules need `need` bytes each
/// way: the stack's limits where stated, else every slot full, and
/// MaxDataLength (in and out together) where stated. E174 where the DAP's
/// own `stack` (`given`) states a limit less than its largest module needs;
/// a later DAP that takes the first's limit and needs more (more ports)
/// writes what its largest module needs, as `gsdc import` expects.
pub fn io_lengths(
    cx: &mut Checker,
    need: IoNeeds,
    stack: &Stack,
    given: &raw::Stack,
    at: &str,
) -> IoLengths {
    // `stated`: the key where this DAP's own stack states the limit, and
    // what gsdc writes without it.
    let mut length = |value: Option<u16>,
                      (least, full): (u16, u16),
                      stated: (&Option<Spanned<u16>>, &str, &str)| {
        let (key, name, without) = stated;
        let Some(value) = value else {
            return full;
        };
        if let (true, Some(key)) = (value < least, key) {
            cx.push(
                Diagnostic::error(
                    "E174",
                    format!(
                        "{at}.{name} = {value} is less than the largest module needs ({least})"
                    ),
                )
                .at(key.span())
                .label("too small")
                .help(format!(
                    "state at least {least}, or leave it out: {without}"
                )),
            );
        }
        value.max(least)
    };
    let without = "gsdc writes what every slot with its largest module needs";
    let input = length(
        stack.max_input_length,
        (need.input.least, need.input.written()),
        (&given.max_input_length, "max_input_length", without),
    );
    let output = length(
        stack.max_output_length,
        (need.output.least, need.output.written()),
        (&given.max_output_length, "max_output_length", without),
    );
    // In and out together.
    let both = need.input.least + need.output.least;
    let data = stack.max_data_length.map(|data| {
        length(
            Some(data),
            (both, both),
            (
                &given.max_data_length,
                "max_data_length",
                "MaxDataLength is unwritten",
            ),
        )
    });
    IoLengths {
        input,
        output,
        data,
        full: u32::from(input) >= need.input.full && u32::from(output) >= need.output.full,
    }
}

/// What a DAP's IOConfigData writes.
pub struct IoLengths {
    pub input: u16,
    pub output: u16,
    pub data: Option<u16>,
    /// Whether the lengths hold every slot with its largest module.
    pub full: bool,
}

/// The ways of address assignment, each once, at least one.
fn address_assignment(
    cx: &mut Checker,
    list: &Spanned<Vec<Spanned<RawAssignment>>>,
    at: &str,
) -> Option<Vec<AddressAssignment>> {
    if list.get_ref().is_empty() {
        cx.push(
            Diagnostic::error("E117", format!("{at}.address_assignment is empty"))
                .at(list.span())
                .label("empty")
                .help("name how the device may get its IP address, e.g. [\"DCP\"], or leave the key out for DCP alone"),
        );
        return None;
    }
    let mut ways = Vec::new();
    for way in list.get_ref() {
        let ir = match way.get_ref() {
            RawAssignment::DCP => AddressAssignment::Dcp,
            RawAssignment::DHCP => AddressAssignment::Dhcp,
            RawAssignment::LOCAL => AddressAssignment::Local,
        };
        if ways.contains(&ir) {
            cx.duplicate(format!("address assignment {}", ir.token()), way.span());
            return None;
        }
        ways.push(ir);
    }
    Some(ways)
}

/// E184: `NumberOfDeviceAccessAR` counts device access ARs, which a device
/// without `DeviceAccessSupported` does not accept (p-net's GSDML guide:
/// "should only be given if DeviceAccessSupported is true").
fn check_device_access(cx: &mut Checker, given: &raw::Stack, stack: &Stack) -> Option<()> {
    if stack.device_access || stack.device_access_ars.is_none() {
        return Some(());
    }
    // The key that made the contradiction: the ARs stated here, or a later
    // DAP's `device_access = false` under the first's ARs.
    let (stated, label) = match (&given.device_access_ars, &given.device_access) {
        (Some(ars), _) => (ars.span(), "device access ARs counted here"),
        (None, Some(access)) => (
            access.span(),
            "no device access here, under the first's device_access_ars",
        ),
        (None, None) => return Some(()), // both the first's, which was checked
    };
    cx.push(
        Diagnostic::error("E184", "device access ARs without device access")
            .at(stated)
            .label(label)
            .help("set device_access = true, or leave device_access_ars out"),
    );
    None
}
