//! Where the modules go: `[profinet] module_slots`, the slots that each
//! take one data module (SEW's MOVI-C: its process data channels in slots
//! 2 to 5), and `[profinet.empty_module]`, the module without data a slot
//! takes where no data module is plugged.

use super::ids;
use super::stack::MAX_SLOT;
use crate::description::{self as raw, Exactly};
use crate::ir::profinet::{EmptyModule, Slots, TextRef};
use crate::lower::checks::Checker;
use toml::Spanned;

/// gsdc's ModuleIdentNumber of the empty module: `0x0000_01nn` with no PZD
/// words, in the numbering of the modules of nn words.
pub const EMPTY_MODULE_IDENT: u32 = 0x0000_0100;

/// The data modules' slots: slot 1 alone unless stated.
pub fn module_slots(
    cx: &mut Checker,
    given: Option<&Spanned<Exactly<Spanned<u16>, 2>>>,
) -> Option<Slots> {
    match given {
        Some(range) => slots(cx, range, "profinet.module_slots"),
        None => Some(Slots::ONE),
    }
}

/// The empty module, when stated; `None` when it has an error.
pub fn empty_module(
    cx: &mut Checker,
    given: Option<&Spanned<raw::EmptyModule>>,
) -> Option<Option<EmptyModule>> {
    let Some(given) = given else {
        return Some(None);
    };
    let e = given.get_ref();
    let name = cx.text(&e.name, None, "profinet.empty_module.name");
    let info = e.info.as_ref().map_or_else(
        || name.clone(),
        |i| cx.text(i, None, "profinet.empty_module.info"),
    );
    let slots = slots(cx, &e.slots, "profinet.empty_module.slots");
    let ident = match &e.ident {
        Some(n) => cx.spanned_in_range(n, 1, u32::MAX.into(), "profinet.empty_module.ident"),
        None => Some(EMPTY_MODULE_IDENT),
    };
    let ident = ident?;
    Some(Some(EmptyModule {
        ident,
        submodule_ident: e.submodule_ident.as_ref().map_or(ident, |s| *s.get_ref()),
        name: TextRef::new(ids::EMPTY_MODULE_NAME, name),
        info: TextRef::new(ids::EMPTY_MODULE_INFO, info),
        slots: slots?,
    }))
}

/// `[first, last]`, each a slot a module may go into (1 to the last
/// `PhysicalSlots` may name: E101), first not above last (E109).
pub(super) fn slots(
    cx: &mut Checker,
    range: &Spanned<Exactly<Spanned<u16>, 2>>,
    what: &str,
) -> Option<Slots> {
    let Exactly([first, last]) = range.get_ref();
    let first: Option<u16> = cx.spanned_in_range(first, 1, MAX_SLOT.into(), what);
    let last: Option<u16> = cx.spanned_in_range(last, 1, MAX_SLOT.into(), what);
    let (first, last) = (first?, last?);
    if first > last {
        cx.reversed(range.span(), first, last);
        return None;
    }
    Some(Slots { first, last })
}
