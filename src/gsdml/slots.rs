//! Where things are plugged: slot lists within the DAP's PhysicalSlots
//! (E312) and subslot numbers in the ranges PROFINET reserves for them
//! (E313).

use super::index::{child, children, describe, value_span, El};
use super::values::{parse_u32, show_ranges, ValueList};
use super::Ctx;
use crate::diag::Diagnostic;

/// Slot numbers are 0..0x7FFF; so are the subslots of ordinary submodules.
const MAX_SLOT: u32 = 0x7FFF;

pub fn check(ctx: &Ctx<'_, '_>, out: &mut Vec<Diagnostic>) {
    for dap in ctx.idx.all("DeviceAccessPointItem") {
        dap_slots(dap, out);
    }
    for interface in ctx.idx.all("InterfaceSubmoduleItem") {
        // SubslotNumber defaults to 0x8000 for the interface.
        let number = interface
            .attribute("SubslotNumber")
            .map_or(Some(0x8000), parse_u32);
        if let Some(n) = number.filter(|&n| !is_interface_subslot(n)) {
            out.push(bad_subslot(
                interface,
                n,
                "an interface is in subslot 0x8i00 (32768, 33024, ... 36608)",
            ));
        }
    }
    for port in ctx.idx.all("PortSubmoduleItem") {
        if let Some(n) = port
            .attribute("SubslotNumber")
            .and_then(parse_u32)
            .filter(|&n| !is_port_subslot(n))
        {
            out.push(bad_subslot(
                port,
                n,
                "a port is in subslot 0x8ipp with pp 01..FF (32769, 32770, ...)",
            ));
        }
    }
    for submodule in ctx.idx.all("VirtualSubmoduleItem") {
        let Some(list) = submodule
            .attribute("FixedInSubslots")
            .and_then(ValueList::parse)
        else {
            continue;
        };
        let outside = ValueList::from_ranges(vec![(1, MAX_SLOT)]).missing_from(&list);
        if !outside.is_empty() {
            out.push(
                Diagnostic::error(
                    "E313",
                    format!("FixedInSubslots of {} lists subslot(s) {}", describe(submodule), show_ranges(&outside)),
                )
                .at(value_span(submodule, "FixedInSubslots"))
                .label("not 1..32767")
                .help("submodules with IO data are in subslots 1..0x7FFF; 0x8000 and above belong to interfaces and ports"),
            );
        }
    }
}

fn is_interface_subslot(n: u32) -> bool {
    (0x8000..=0x8FFF).contains(&n) && n & 0xFF == 0
}

fn is_port_subslot(n: u32) -> bool {
    (0x8000..=0x8FFF).contains(&n) && n & 0xFF != 0
}

fn bad_subslot(node: &El<'_, '_>, number: u32, rule: &str) -> Diagnostic {
    Diagnostic::error(
        "E313",
        format!("{} is in subslot {number} (0x{number:04X})", describe(node)),
    )
    .at(value_span(node, "SubslotNumber"))
    .label("wrong subslot")
    .help(format!(
        "{rule}; the first interface is 0x8000, its ports 0x8001, 0x8002, ..."
    ))
}

fn dap_slots(dap: &El<'_, '_>, out: &mut Vec<Diagnostic>) {
    let Some(physical) = dap.attribute("PhysicalSlots").and_then(ValueList::parse) else {
        return;
    };
    let too_high = ValueList::from_ranges(vec![(0, MAX_SLOT)]).missing_from(&physical);
    if !too_high.is_empty() {
        out.push(
            Diagnostic::error(
                "E312",
                format!(
                    "PhysicalSlots of {} lists slot(s) {}",
                    describe(dap),
                    show_ranges(&too_high)
                ),
            )
            .at(value_span(dap, "PhysicalSlots"))
            .label("above 32767")
            .help("PROFINET slot numbers are 0..0x7FFF"),
        );
    }
    for attribute in ["FixedInSlots", "AllowedInSlots"] {
        within_physical(dap, attribute, &physical, dap, out);
    }
    let references = child(*dap, "UseableModules")
        .into_iter()
        .flat_map(|u| children(u, "ModuleItemRef"));
    for reference in references {
        for attribute in ["AllowedInSlots", "FixedInSlots", "UsedInSlots"] {
            within_physical(&reference, attribute, &physical, dap, out);
        }
        within_allowed(&reference, out);
    }
}

fn within_physical(
    node: &El<'_, '_>,
    attribute: &str,
    physical: &ValueList,
    dap: &El<'_, '_>,
    out: &mut Vec<Diagnostic>,
) {
    let Some(list) = node.attribute(attribute).and_then(ValueList::parse) else {
        return;
    };
    let outside = physical.missing_from(&list);
    if outside.is_empty() {
        return;
    }
    let whose = match node.attribute("ModuleItemTarget") {
        Some(target) => format!("module \"{target}\" in {}", describe(dap)),
        None => describe(dap),
    };
    out.push(
        Diagnostic::error(
            "E312",
            format!(
                "{attribute} of {whose} lists slot(s) {} outside PhysicalSlots",
                show_ranges(&outside)
            ),
        )
        .at(value_span(node, attribute))
        .label(format!(
            "PhysicalSlots is {}",
            dap.attribute("PhysicalSlots").unwrap_or_default()
        ))
        .help("a module can only go into a slot the device has; fix the list or PhysicalSlots"),
    );
}

/// A module fixed in or preset to a slot must also be allowed there.
fn within_allowed(reference: &El<'_, '_>, out: &mut Vec<Diagnostic>) {
    let Some(allowed) = reference
        .attribute("AllowedInSlots")
        .and_then(ValueList::parse)
    else {
        return;
    };
    for attribute in ["FixedInSlots", "UsedInSlots"] {
        let Some(list) = reference.attribute(attribute).and_then(ValueList::parse) else {
            continue;
        };
        let outside = allowed.missing_from(&list);
        if !outside.is_empty() {
            out.push(
                Diagnostic::error(
                    "E312",
                    format!(
                        "{attribute} of module \"{}\" lists slot(s) {} that AllowedInSlots does not",
                        reference.attribute("ModuleItemTarget").unwrap_or("?"),
                        show_ranges(&outside)
                    ),
                )
                .at(value_span(reference, attribute))
                .label(format!("AllowedInSlots is {}", reference.attribute("AllowedInSlots").unwrap_or_default()))
                .help(format!("{attribute} must be a subset of AllowedInSlots")),
            );
        }
    }
}
