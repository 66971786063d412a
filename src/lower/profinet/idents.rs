//! `[profinet.ident_numbers]`: the ident numbers a description states (an
//! imported GSDML file's own), over gsdc's numbering, with the rules that
//! keep them apart.

use super::Checker;
use crate::description as raw;
use crate::diag::Diagnostic;
use crate::ir::profinet::{Module, Port, ACCESS_POINT_IDENT, DAP_IDENT, INTERFACE_SUBSLOT};
use toml::Spanned;

/// The ident numbers of the device access point and its fixed submodules.
pub struct DapIdents {
    pub dap: u32,
    pub dap_submodule: u32,
    pub interface: u32,
    pub access_point: u32,
    /// Whether any ident number is gsdc's numbering (the headers say so).
    pub numbered_by_gsdc: bool,
    /// Whether the description states any.
    pub stated: bool,
}

/// Puts the stated numbers on the modules and ports, and checks them:
/// a key that names no module (E177), a port count other than `ports`
/// (E178), an access point without a PROFIdrive module (E179).
pub fn apply(
    cx: &mut Checker,
    given: &raw::IdentNumbers,
    modules: &mut [Module],
    ports: &mut [Port],
) -> DapIdents {
    let value = |n: &Option<Spanned<u32>>| n.as_ref().map(|n| *n.get_ref());
    // A ModuleIdentNumber is not zero (the GSDML checker's E318); a
    // submodule's may be.
    let dap = given.dap.as_ref().and_then(|n| module_ident(cx, n));
    let mut numbered_by_gsdc = dap.is_none() || given.interface.is_none();
    let mut stated = dap.is_some() || given.interface.is_some();
    for (key, number) in &given.modules {
        stated = true;
        if let Some(n) = module_ident(cx, number) {
            for_module(cx, key, modules, |m| m.ident_number = n);
        }
    }
    for (key, number) in &given.submodules {
        stated = true;
        for_module(cx, key, modules, |m| {
            m.submodule_ident_number = *number.get_ref()
        });
    }
    // A module whose number is stated keeps it for its submodule too,
    // unless `submodules` says otherwise.
    for m in modules.iter_mut() {
        let name = m.ident.snake();
        let module_given = given.modules.keys().any(|k| *k.get_ref() == name);
        let submodule_given = given.submodules.keys().any(|k| *k.get_ref() == name);
        if module_given && !submodule_given {
            m.submodule_ident_number = m.ident_number;
        }
        numbered_by_gsdc |= !module_given;
    }
    if let Some(list) = &given.ports {
        stated = true;
        port_idents(cx, (list, "profinet.ports"), ports);
    } else {
        numbered_by_gsdc |= !ports.is_empty();
    }
    let access_point = value(&given.access_point);
    let profidrive = modules.iter().any(Module::is_profidrive);
    match (&given.access_point, profidrive) {
        (Some(a), false) => cx.push(
            Diagnostic::error("E179", "an access point ident number without a PROFIdrive module")
                .at(a.span())
                .label("no module has an access point")
                .help("only PROFIdrive's standard telegrams (profinet.standard_telegram_1 with telegram.profidrive, profinet.standard_telegram_2) have a module access point; remove the key"),
        ),
        (None, true) => numbered_by_gsdc = true,
        _ => {}
    }
    stated |= access_point.is_some() || given.dap_submodule.is_some();
    let dap = dap.unwrap_or(DAP_IDENT);
    DapIdents {
        dap,
        dap_submodule: value(&given.dap_submodule).unwrap_or(dap),
        interface: value(&given.interface).unwrap_or(INTERFACE_SUBSLOT.into()),
        access_point: access_point.unwrap_or(ACCESS_POINT_IDENT),
        numbered_by_gsdc,
        stated,
    }
}

/// A stated ModuleIdentNumber: 1 or more (E101 for 0).
fn module_ident(cx: &mut Checker, number: &Spanned<u32>) -> Option<u32> {
    cx.spanned_in_range(number, 1, u32::MAX.into(), "a module ident number")
}

/// Calls `set` with the module `key` names; E177 when it names no module
/// the description offers.
pub(super) fn for_module(
    cx: &mut Checker,
    key: &Spanned<String>,
    modules: &mut [Module],
    set: impl FnOnce(&mut Module),
) {
    match modules
        .iter_mut()
        .find(|m| m.ident.snake() == *key.get_ref())
    {
        Some(m) => set(m),
        None => {
            let names: Vec<String> = modules.iter().map(|m| m.ident.snake()).collect();
            cx.push(
                Diagnostic::error(
                    "E177",
                    format!("`{}` is not a module of this description", key.get_ref()),
                )
                .at(key.span())
                .label("no such module")
                .help(format!(
                    "modules are named as in the generated code: {}",
                    names.join(", ")
                )),
            );
        }
    }
}

/// One ident number per port (E178 otherwise); whether there was one each.
pub(super) fn port_idents(
    cx: &mut Checker,
    (list, ports_key): (&Spanned<Vec<Spanned<u32>>>, &str),
    ports: &mut [Port],
) -> bool {
    if list.get_ref().len() != ports.len() {
        cx.push(
            Diagnostic::error(
                "E178",
                format!(
                    "{} port ident numbers for {} ports",
                    list.get_ref().len(),
                    ports.len()
                ),
            )
            .at(list.span())
            .label("one per port")
            .help(format!(
                "give one SubmoduleIdentNumber for each port of {ports_key}, in port order"
            )),
        );
        return false;
    }
    for (port, n) in ports.iter_mut().zip(list.get_ref()) {
        port.ident = *n.get_ref();
    }
    true
}
