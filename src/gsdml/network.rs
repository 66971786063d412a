//! Interface and identification properties that controllers trip over:
//! DCP Hello without a power-on time (E314), read-only I&M records declared
//! writeable (E315), an interface without legacy startup (W301).

use super::index::{child, describe, value_span, El, SUBMODULE_ITEMS};
use super::values::{parse_bool, parse_u32, ValueList};
use super::version::Version;
use super::Ctx;
use crate::diag::Diagnostic;

/// The first version in which the corpus shows PowerOnToCommReady
/// (Hilscher's V2.33 file, with DCP_HelloSupported). The V2.25 Leuze file
/// sends Hello without it, and when the attribute was introduced is not
/// established, so older files are not held to the pairing.
const POWER_ON_TO_COMM_READY_SEEN: Version = Version::new(2, 33);

pub fn check(ctx: &Ctx<'_, '_>, out: &mut Vec<Diagnostic>) {
    for interface in ctx.idx.all("InterfaceSubmoduleItem") {
        if ctx.version >= POWER_ON_TO_COMM_READY_SEEN {
            dcp_hello(interface, out);
        }
        startup_mode(interface, out);
    }
    for submodule in SUBMODULE_ITEMS.iter().flat_map(|name| ctx.idx.all(name)) {
        writeable_im(submodule, out);
    }
}

/// Fast startup (DCP Hello) is defined by the time from power-on to
/// communication; a device that sends Hello must declare it on its DAP.
fn dcp_hello(interface: &El<'_, '_>, out: &mut Vec<Diagnostic>) {
    if interface
        .attribute("DCP_HelloSupported")
        .and_then(parse_bool)
        != Some(true)
    {
        return;
    }
    // The schema's place for an interface: DeviceAccessPointItem /
    // SystemDefinedSubmoduleList / InterfaceSubmoduleItem. Looking up no
    // further than that keeps the rule linear: searching every ancestor of
    // every interface is quadratic on nested interfaces (20 000 took 14 s).
    let dap = interface
        .parent_element()
        .and_then(|list| list.parent_element())
        .filter(|a| a.tag_name().name() == "DeviceAccessPointItem");
    let Some(dap) = dap else { return };
    let power_on = dap
        .attribute("PowerOnToCommReady")
        .and_then(parse_u32)
        .unwrap_or(0);
    if power_on == 0 {
        out.push(
            Diagnostic::error(
                "E314",
                format!("{} supports DCP Hello but {} has no PowerOnToCommReady", describe(interface), describe(&dap)),
            )
            .at(value_span(interface, "DCP_HelloSupported"))
            .label("DCP_HelloSupported=\"true\"")
            .help("add PowerOnToCommReady=\"<ms from power-on to communication>\" to the DeviceAccessPointItem, or drop DCP_HelloSupported"),
        );
    }
}

/// I&M0 and I&M5 are read-only by the PROFINET specification.
fn writeable_im(submodule: &El<'_, '_>, out: &mut Vec<Diagnostic>) {
    let Some(records) = submodule
        .attribute("Writeable_IM_Records")
        .and_then(ValueList::parse)
    else {
        return;
    };
    for record in [0, 5].into_iter().filter(|r| records.contains(*r)) {
        out.push(
            Diagnostic::error(
                "E315",
                format!(
                    "Writeable_IM_Records of {} lists I&M{record}",
                    describe(submodule)
                ),
            )
            .at(value_span(submodule, "Writeable_IM_Records"))
            .label(format!("I&M{record} is read-only"))
            .help("only I&M1 to I&M4 can be written; remove 0 and 5 from the list"),
        );
    }
}

/// p-net issue 527: controllers that only start up the legacy way (S7-300,
/// older firmware) cannot connect to a device that offers only "Advanced".
fn startup_mode(interface: &El<'_, '_>, out: &mut Vec<Diagnostic>) {
    let Some(relations) = child(*interface, "ApplicationRelations") else {
        return;
    };
    // Without the attribute the schema's default, "Legacy", applies.
    let Some(modes) = relations.attribute("StartupMode") else {
        return;
    };
    if !modes.split(';').any(|m| m.trim() == "Legacy") {
        out.push(
            Diagnostic::warning("W301", format!("StartupMode \"{modes}\" of {} lacks Legacy", describe(interface)))
                .at(value_span(&relations, "StartupMode"))
                .label("no Legacy startup")
                .help("write StartupMode=\"Legacy;Advanced\" unless the device really cannot start up the legacy way"),
        );
    }
}
