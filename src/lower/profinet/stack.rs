//! `[profinet.stack]`: what the card's PROFINET stack offers the
//! controllers through a device access point. A later DAP's `stack` states
//! what differs from the first's; each key it leaves out is the first's.

use crate::description::{self as raw, AddressAssignment as RawAssignment};
use crate::diag::Diagnostic;
use crate::ir::profinet::{AddressAssignment, Stack};
use crate::lower::checks::Checker;
use toml::Spanned;

/// The stack `given` states over `inherited` (gsdc's defaults for the
/// first DAP); `at` is the table's path. E184 for device access ARs
/// without device access.
pub fn lower(cx: &mut Checker, given: &raw::Stack, inherited: &Stack, at: &str) -> Option<Stack> {
    let flag = |key: &Option<Spanned<bool>>, inherited: bool| {
        key.as_ref().map_or(inherited, |k| *k.get_ref())
    };
    let address_assignment = match &given.address_assignment {
        Some(list) => address_assignment(cx, list, at)?,
        None => inherited.address_assignment.clone(),
    };
    let device_access_ars = match &given.device_access_ars {
        Some(n) => {
            Some(cx.spanned_in_range(n, 1, u8::MAX.into(), &format!("{at}.device_access_ars"))?)
        }
        None => inherited.device_access_ars,
    };
    let application_relations = match &given.application_relations {
        Some(n) => Some(cx.spanned_in_range(
            n,
            1,
            u16::MAX.into(),
            &format!("{at}.application_relations"),
        )?),
        None => inherited.application_relations,
    };
    let limit = |cx: &mut Checker,
                 key: &Option<Spanned<u16>>,
                 name: &str,
                 inherited: Option<u16>| {
        match key {
            Some(n) => cx.spanned_in_range(n, 1, MAX_IO_LENGTH.into(), &format!("{at}.{name}")),
            None => inherited,
        }
    };
    let max_input_length = limit(
        cx,
        &given.max_input_length,
        "max_input_length",
        inherited.max_input_length,
    );
    let max_output_length = limit(
        cx,
        &given.max_output_length,
        "max_output_length",
        inherited.max_output_length,
    );
    let stack = Stack {
        address_assignment,
        device_access: flag(&given.device_access, inherited.device_access),
        device_access_ars,
        name_of_station_not_transferable: flag(
            &given.name_of_station_not_transferable,
            inherited.name_of_station_not_transferable,
        ),
        shared_device: flag(&given.shared_device, inherited.shared_device),
        mau_type_adjustable: flag(&given.mau_type_adjustable, inherited.mau_type_adjustable),
        application_relations,
        max_input_length,
        max_output_length,
    };
    check_device_access(cx, given, &stack)?;
    Some(stack)
}

/// IOConfigData's bound on each length (IEC 61158-6-10's largest frame
/// payload; p-net's GSDML guide: "valid 0..1440").
const MAX_IO_LENGTH: u16 = 1440;

/// IOConfigData's lengths of a DAP whose modules need `needed` bytes each
/// way: the stack's limits where stated, else the need. E174 where a
/// stated limit is less, at the key that states it: the DAP's own `stack`
/// (`given`), else the first's (`first`), whose a later DAP takes.
pub fn io_lengths(
    cx: &mut Checker,
    needed: (u16, u16),
    stack: &Stack,
    (given, first): (&raw::Stack, &raw::Stack),
    at: &str,
) -> (u16, u16) {
    let mut length = |stated: Option<u16>,
                      needed: u16,
                      key: fn(&raw::Stack) -> &Option<Spanned<u16>>,
                      name: &str| {
        let Some(value) = stated else {
            return needed;
        };
        let span = key(given)
            .as_ref()
            .or(key(first).as_ref())
            .map(Spanned::span);
        if let (true, Some(span)) = (value < needed, span) {
            cx.push(
                Diagnostic::error(
                    "E174",
                    format!("{at}.{name} = {value} is less than the modules need ({needed})"),
                )
                .at(span)
                .label("too small")
                .help(format!(
                    "state at least {needed}, or leave it out: gsdc writes what the modules need"
                )),
            );
        }
        value.max(needed)
    };
    (
        length(
            stack.max_input_length,
            needed.0,
            |s| &s.max_input_length,
            "max_input_length",
        ),
        length(
            stack.max_output_length,
            needed.1,
            |s| &s.max_output_length,
            "max_output_length",
        ),
    )
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
