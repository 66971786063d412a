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
    let stack = Stack {
        address_assignment,
        device_access: flag(&given.device_access, inherited.device_access),
        device_access_ars,
        name_of_station_not_transferable: flag(
            &given.name_of_station_not_transferable,
            inherited.name_of_station_not_transferable,
        ),
        shared_device: flag(&given.shared_device, inherited.shared_device),
        application_relations,
    };
    check_device_access(cx, given, &stack)?;
    Some(stack)
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
