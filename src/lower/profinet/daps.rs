//! The device access points: `[profinet]`'s, then each of
//! `[[profinet.daps]]`, another hardware or firmware version of the card
//! in the same file. A later DAP states what differs from the first (its
//! ident number and name above all); what it leaves out is the first's.

use super::io::Placement;
use super::slots::EMPTY_MODULE_IDENT;
use super::{idents::DapIdents, interface, io, port, stack, Checker};
use crate::description as raw;
use crate::diag::Diagnostic;
use crate::ir::profinet::{Dap, Module, Port, Stack, TextRef, Version};
use crate::ir::safety::SafetyModule;
use crate::ir::{Device, Text};
use std::collections::BTreeMap;
use toml::Spanned;

/// What the first DAP is: `[profinet]` and `[device]` say it.
pub struct First<'a> {
    pub idents: &'a DapIdents,
    pub name: Text,
    pub info: TextRef,
    pub ports: Vec<Port>,
    pub media_redundancy: bool,
    pub device: &'a Device,
    /// The file's GSDML version, which bounds what every DAP's stack
    /// writes.
    pub version: Version,
    /// Its `PNIO_Version`.
    pub pnio_version: Version,
    /// Where the modules go.
    pub placement: Placement<'a>,
}

/// Every DAP, the first first; E176 when two of them, or a DAP and a
/// module, share a ModuleIdentNumber.
pub fn lower(
    cx: &mut Checker,
    p: &raw::Profinet,
    first: First,
    modules: &[Module],
) -> Option<Vec<Dap>> {
    let (offered, safety) = offered_modules(
        cx,
        p.dap_modules.as_ref(),
        (modules, first.placement.safety),
    )?;
    let own_safety = offered_safety(&safety, first.placement);
    let own = first.placement.offering(&own_safety);
    let needed = io::io_need(offered.iter().map(|&i| &modules[i]), first.ports.len(), own);
    let (device, version) = (first.device, first.version);
    // A later DAP's stack is the first's with changes: none is checked
    // against a stack that was refused.
    let first_stack = stack::lower(
        cx,
        (&p.stack, &Stack::default()),
        "profinet.stack",
        (version, own.last_used_slot()),
    )?;
    let io = stack::io_lengths(cx, needed, &first_stack, &p.stack, "profinet.stack");
    let mut daps = vec![Dap {
        id: "IDD_DAP".into(),
        submodule_id: "IDS_DAP".into(),
        interface_id: "IDS_INTERFACE".into(),
        ident: first.idents.dap,
        submodule_ident: first.idents.dap_submodule,
        name: TextRef::new(super::ids::DEVICE_NAME, first.name),
        info: first.info,
        order_number: device.order_number.clone(),
        hardware_release: device.hardware_release.clone(),
        software_release: device.software_release.clone(),
        pnio_version: first.pnio_version,
        ports: first.ports,
        media_redundancy: first.media_redundancy,
        modules: offered,
        safety_modules: safety,
        // The first's: `submodule_records::lower_lists` sets its own.
        access_point_records: 0,
        port_records: 1,
        last_slot: first_stack.last_slot.unwrap_or(own.last_used_slot()),
        max_input_length: io.input,
        max_output_length: io.output,
        max_data_length: io.data,
        io_full: io.full,
        stack: first_stack,
    }];
    let mut complete = true;
    for (index, given) in p.daps.iter().enumerate() {
        let at = (index, given.get_ref());
        match lower_entry(cx, at, p, (&daps[0], first.placement), modules, version) {
            Some(dap) => daps.push(dap),
            None => complete = false,
        }
    }
    unique_idents(cx, p, daps[0].ident, modules);
    if complete {
        one_slot_zero_per_ident(cx, p, &daps);
        every_module_offered(cx, p, &daps, (modules, first.placement.safety));
    }
    complete.then_some(daps)
}

/// E183: a module no device access point offers is in no catalogue entry:
/// the file would list it for no one, and the layouts would carry a module
/// no project can plug. Only where `dap_modules` leaves some out.
fn every_module_offered(
    cx: &mut Checker,
    p: &raw::Profinet,
    daps: &[Dap],
    (modules, safety): (&[Module], &[SafetyModule]),
) {
    let Some(list) = &p.dap_modules else {
        return; // the first offers every module
    };
    let data = modules
        .iter()
        .enumerate()
        .filter(|(i, _)| !daps.iter().any(|d| d.modules.contains(i)))
        .map(|(_, m)| m.ident.snake());
    let safety = safety
        .iter()
        .enumerate()
        .filter(|(i, _)| !daps.iter().any(|d| d.safety_modules.contains(i)))
        .map(|(_, m)| m.ident.snake());
    let unoffered: Vec<String> = data.chain(safety).map(|name| format!("`{name}`")).collect();
    if unoffered.is_empty() {
        return;
    }
    cx.push(
        Diagnostic::error(
            "E183",
            format!("{} offered by no device access point", unoffered.join(", ")),
        )
        .at(list.span())
        .label("not every module")
        .help("name each module in `dap_modules` or in a [[profinet.daps]] entry's `modules`, or take it out of the description"),
    );
}

/// E162: device access points of one ident number are one head module to
/// the controller, which names slot 0 by that number alone (SEW's MOVI-C
/// offers three catalogue versions of its head so). The device cannot tell
/// which the project used: each must present the same slot 0, its own
/// submodule and its ports with their ident numbers.
fn one_slot_zero_per_ident(cx: &mut Checker, p: &raw::Profinet, daps: &[Dap]) {
    let slot_zero = |d: &Dap| {
        let ports: Vec<u32> = d.ports.iter().map(|port| port.ident).collect();
        (d.submodule_ident, ports)
    };
    for (index, (dap, given)) in daps[1..].iter().zip(&p.daps).enumerate() {
        let Some(same) = daps[..=index].iter().position(|d| d.ident == dap.ident) else {
            continue;
        };
        if slot_zero(&daps[same]) == slot_zero(dap) {
            continue;
        }
        cx.push(
            Diagnostic::error(
                "E162",
                format!(
                    "device access point {} (profinet.daps[{index}]) and device access point {} have ident number 0x{:08X} and another slot 0",
                    index + 2,
                    same + 1,
                    dap.ident
                ),
            )
            .at(given.get_ref().ident.span())
            .label("another slot 0 under one ident number")
            .help("the device cannot tell device access points of one ident number apart: give both the same submodule_ident, ports and port_idents, or this one an ident number of its own"),
        );
    }
}

/// The DAP of `profinet.daps[index]`, number `index + 2` in the file.
fn lower_entry(
    cx: &mut Checker,
    (index, given): (usize, &raw::Dap),
    p: &raw::Profinet,
    (first, placement): (&Dap, Placement),
    modules: &[Module],
    version: Version,
) -> Option<Dap> {
    let number = index + 2;
    let what = |key: &str| format!("profinet.daps[{index}].{key}");
    let ident = cx.spanned_in_range(&given.ident, 1, u32::MAX.into(), &what("ident"));
    let name = cx.text(&given.name, None, &what("name"));
    // Its own info text after the draft notice, as the first DAP's: the
    // engineering tool's catalog shows each DAP's.
    let info = given.info.as_ref().map_or_else(
        || first.info.clone(),
        |i| {
            let text = cx.text(i, None, &what("info"));
            TextRef::new(
                format!("IDT_DAP_{number}_INFO"),
                super::draft(text, (&p.vendor_id, &p.device_id)),
            )
        },
    );
    let own =
        |cx: &mut Checker, s: &Option<Spanned<String>>, key: &str, inherited: &Option<String>| {
            match s {
                Some(s) => Some(cx.required(s, &what(key))),
                None => inherited.clone(),
            }
        };
    let hardware_release = own(
        cx,
        &given.hardware_release,
        "hardware_release",
        &first.hardware_release,
    );
    let software_release = own(
        cx,
        &given.software_release,
        "software_release",
        &first.software_release,
    );
    let order_number = own(cx, &given.order_number, "order_number", &first.order_number);
    let pnio_version = match &given.pnio_version {
        Some(v) => super::pnio_version(cx, Some(v), version)?,
        None => first.pnio_version,
    };
    let port_count = match &given.ports {
        Some(n) => cx.spanned_in_range(n, 1, 16, &what("ports"))?,
        None => u8::try_from(first.ports.len()).ok()?,
    };
    let media_redundancy = given
        .media_redundancy
        .as_ref()
        .map_or(first.media_redundancy, |m| *m.get_ref());
    // An MRP client stated here, or the first's on the ports stated here.
    let client = match (&given.media_redundancy, &given.ports) {
        (Some(m), _) => m.get_ref().then(|| m.span()),
        (None, ports) => ports
            .as_ref()
            .filter(|_| media_redundancy)
            .map(Spanned::span),
    };
    interface::check_ring_ports(cx, client, port_count);
    let ports = ports(cx, (index, port_count, media_redundancy), given, first)?;
    let (offered, safety) =
        offered_modules(cx, given.modules.as_ref(), (modules, placement.safety))?;
    let own_safety = offered_safety(&safety, placement);
    let own = placement.offering(&own_safety);
    let needed = io::io_need(offered.iter().map(|&i| &modules[i]), ports.len(), own);
    let stack = stack::lower(
        cx,
        (&given.stack, &first.stack),
        &what("stack"),
        (version, own.last_used_slot()),
    )?;
    let io = stack::io_lengths(cx, needed, &stack, &given.stack, &what("stack"));
    let ident = ident?;
    Some(Dap {
        id: format!("IDD_DAP_{number}"),
        submodule_id: format!("IDS_DAP_{number}"),
        interface_id: format!("IDS_INTERFACE_{number}"),
        ident,
        submodule_ident: given
            .submodule_ident
            .as_ref()
            .map_or(ident, |s| *s.get_ref()),
        name: TextRef::new(format!("IDT_DAP_{number}_NAME"), name),
        info,
        order_number,
        hardware_release,
        software_release,
        pnio_version,
        ports,
        media_redundancy,
        modules: offered,
        safety_modules: safety,
        // The first's: `submodule_records::lower_lists` sets its own.
        access_point_records: 0,
        port_records: 1,
        last_slot: stack.last_slot.unwrap_or(own.last_used_slot()),
        max_input_length: io.input,
        max_output_length: io.output,
        max_data_length: io.data,
        io_full: io.full,
        stack,
    })
}

/// The ports of DAP `number`, with their ident numbers: those `port_idents`
/// states, else the first DAP's port of the same number, else (where the
/// first DAP's ports are numbered by their subslots, gsdc's numbering) the
/// port's subslot. E178 when neither says a port's number.
fn ports(
    cx: &mut Checker,
    (index, count, media_redundancy): (usize, u8, bool),
    given: &raw::Dap,
    first: &Dap,
) -> Option<Vec<Port>> {
    let number = index + 2;
    let mut ports: Vec<Port> = (1..=count)
        .map(|n| Port {
            id: format!("IDS_DAP_{number}_PORT_{n}"),
            ..port(n, media_redundancy)
        })
        .collect();
    if let Some(list) = &given.port_idents {
        let key = format!("the ports of profinet.daps[{index}]");
        return super::idents::port_idents(cx, (list, &key), &mut ports).then_some(ports);
    }
    let by_subslot = first.ports.iter().all(Port::numbered_by_subslot);
    for (i, port) in ports.iter_mut().enumerate() {
        match first.ports.get(i) {
            Some(same) => port.ident = same.ident,
            None if by_subslot => {}
            None => {
                let at = given.ports.as_ref().map(Spanned::span);
                cx.push(
                    Diagnostic::error(
                        "E178",
                        format!("no ident number for port {} of device access point {number} (profinet.daps[{index}])", i + 1),
                    )
                    .at_opt(at)
                    .label("more ports than the first device access point")
                    .help("the first device access point's ports have ident numbers of their own: give this one's as port_idents = [...], one per port"),
                );
                return None;
            }
        }
    }
    Some(ports)
}

/// The safety modules a DAP offers, from their places in `placement`.
fn offered_safety(offered: &[usize], placement: Placement) -> Vec<SafetyModule> {
    offered
        .iter()
        .map(|&i| placement.safety[i].clone())
        .collect()
}

/// The modules a DAP offers, as indexes in module order: all of
/// them when it does not say. E183 for a name that is no module's, a
/// module named twice, or an empty list.
fn offered_modules(
    cx: &mut Checker,
    given: Option<&Spanned<Vec<Spanned<String>>>>,
    (modules, safety): (&[Module], &[SafetyModule]),
) -> Option<(Vec<usize>, Vec<usize>)> {
    let Some(list) = given else {
        return Some(((0..modules.len()).collect(), (0..safety.len()).collect()));
    };
    let names: Vec<String> = modules
        .iter()
        .map(|m| m.ident.snake())
        .chain(safety.iter().map(|m| m.ident.snake()))
        .collect();
    let mut offered = Vec::new();
    for name in list.get_ref() {
        let problem = match names.iter().position(|n| n == name.get_ref()) {
            None => "not a module of this description",
            Some(i) if offered.contains(&i) => "named twice",
            Some(i) => {
                offered.push(i);
                continue;
            }
        };
        cx.push(
            Diagnostic::error("E183", format!("`{}`: {problem}", name.get_ref()))
                .at(name.span())
                .label(problem)
                .help(format!(
                    "list each module the device access point offers once, named as in the generated code: {}",
                    names.join(", ")
                )),
        );
        return None;
    }
    if offered.iter().all(|&i| i >= modules.len()) {
        cx.push(
            Diagnostic::error("E183", "a device access point that offers no data module")
                .at(list.span())
                .label("no data module")
                .help("name the modules it offers, or leave `modules` out for all of them"),
        );
        return None;
    }
    offered.sort_unstable();
    let (data, safety) = offered
        .iter()
        .partition::<Vec<usize>, _>(|&&i| i < modules.len());
    let safety = safety.into_iter().map(|i| i - modules.len()).collect();
    Some((data, safety))
}

/// E176: a controller tells the modules apart, and the device access
/// points from the modules, by their ModuleIdentNumber (device access
/// points may share one: [`one_slot_zero_per_ident`]). Checked in the
/// order the description states them (the first DAP's and the modules'
/// under `[profinet.ident_numbers]`, the empty module's, the safety
/// modules', then each `[[profinet.daps]]` entry's, even one that did not
/// lower), each reported at the later of the two.
fn unique_idents(cx: &mut Checker, p: &raw::Profinet, first_ident: u32, modules: &[Module]) {
    let given = &p.ident_numbers;
    let module_span = |name: &str| {
        given
            .modules
            .iter()
            .find(|(k, _)| *k.get_ref() == name)
            .map(|(_, v)| v.span())
    };
    let first = Numbered {
        ident: first_ident,
        name: "the device access point".to_string(),
        at: given.dap.as_ref().map(Spanned::span),
        dap: true,
    };
    let numbered = std::iter::once(first)
        .chain(modules.iter().map(|m| {
            let name = m.ident.snake();
            Numbered::module(
                m.ident_number,
                format!("module `{name}`"),
                module_span(&name),
            )
        }))
        .chain(p.empty_module.iter().map(|e| {
            let ident = &e.get_ref().ident;
            Numbered::module(
                ident.as_ref().map_or(EMPTY_MODULE_IDENT, |i| *i.get_ref()),
                "the empty module".to_string(),
                ident.as_ref().map(Spanned::span),
            )
        }))
        .chain(p.safety_modules.iter().enumerate().map(|(index, m)| {
            let ident = &m.get_ref().ident;
            Numbered::module(
                *ident.get_ref(),
                format!(
                    "safety module {} (profinet.safety_modules[{index}])",
                    index + 1
                ),
                Some(ident.span()),
            )
        }))
        .chain(p.daps.iter().enumerate().map(|(index, d)| {
            let ident = &d.get_ref().ident;
            Numbered {
                ident: *ident.get_ref(),
                name: format!("device access point {} (profinet.daps[{index}])", index + 2),
                at: Some(ident.span()),
                dap: true,
            }
        }));
    let mut seen: BTreeMap<u32, Numbered> = BTreeMap::new();
    for this in numbered {
        let Some(first) = seen.get(&this.ident) else {
            seen.insert(this.ident, this);
            continue;
        };
        // Device access points may share one: E162 judges their slot 0.
        if this.dap && first.dap {
            continue;
        }
        cx.push(
            Diagnostic::error(
                "E176",
                format!(
                    "{} and {} have ident number 0x{:08X}",
                    this.name, first.name, this.ident
                ),
            )
            .at_opt(this.at.or_else(|| first.at.clone()))
            .label("ident number given twice")
            .help("a controller tells modules apart by their ModuleIdentNumber: give each module its own, and each device access point one no module has"),
        );
    }
}

/// A ModuleIdentNumber the description gives, what it numbers and where.
struct Numbered {
    ident: u32,
    name: String,
    at: Option<std::ops::Range<usize>>,
    /// Whether it numbers a device access point.
    dap: bool,
}

impl Numbered {
    fn module(ident: u32, name: String, at: Option<std::ops::Range<usize>>) -> Self {
        Numbered {
            ident,
            name,
            at,
            dap: false,
        }
    }
}
