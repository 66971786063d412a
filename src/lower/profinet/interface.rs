//! What the device access point and its interface declare of the
//! firmware: send clocks, conformance and netload class, the writable I&M
//! records (the DAP's and the modules') and media redundancy, with the
//! RT_CLASS_3 and isochronous mode `super::irt` lowers. What the
//! description leaves out is gsdc's default, said (W104) where the
//! description would state it.

use crate::description::{
    self as raw, ConformanceClass as RawConformance, NetloadClass as RawNetload,
};
use crate::diag::Diagnostic;
use crate::ir::profinet::{ConformanceClass, InterfaceProperties, Irt, Isochronous, NetloadClass};
use crate::lower::checks::Checker;
use std::collections::BTreeSet;
use std::ops::Range;
use toml::Spanned;

/// 1, 2 and 4 ms: what every commercial GSDML in the corpus offers (ABB
/// FENA, SEW MOVI-C, Hilscher, Leuze); 32 alone fails an IO system with a 2
/// or 4 ms send clock.
const DEFAULT_SEND_CLOCK: [u16; 3] = [32, 64, 128];
/// The send clock every device must accept: 1 ms (the schema's default, and
/// p-net's documentation: "the list must contain the value 32").
const REQUIRED_SEND_CLOCK: u16 = 32;
const MAX_SEND_CLOCK: u16 = 128;
/// I&M1 to I&M3, as 10 of the 16 corpus files; I&M0 and I&M5 are read-only.
const DEFAULT_WRITEABLE_IM: [u8; 3] = [1, 2, 3];

/// The interface's properties, with its RT_CLASS_3 and the modules'
/// isochronous mode (`timing`, [`super::irt::timing`]).
pub fn properties(
    cx: &mut Checker,
    p: &Spanned<raw::Profinet>,
    (irt, isochronous): (Option<Irt>, Option<Isochronous>),
) -> Option<InterfaceProperties> {
    let near = p.span();
    let p = p.get_ref();
    let send_clock = match &p.send_clock {
        Some(clocks) => send_clock(cx, clocks)?,
        None => {
            cx.defaulted("profinet.send_clock", "[32, 64, 128]", near.clone());
            DEFAULT_SEND_CLOCK.to_vec()
        }
    };
    let preferred_send_clock = preferred_send_clock(
        cx,
        p.preferred_send_clock.as_ref(),
        &send_clock,
        "RT_CLASS_1",
    )?;
    let conformance_class = match &p.conformance_class {
        Some(class) => conformance_class(cx, class, irt.is_some())?,
        None if irt.is_some() => ConformanceClass::C,
        None => {
            cx.defaulted("profinet.conformance_class", "\"B\"", near.clone());
            ConformanceClass::B
        }
    };
    let netload_class = match p.netload_class.as_ref().map(Spanned::get_ref) {
        Some(RawNetload::I) => NetloadClass::I,
        Some(RawNetload::II) => NetloadClass::II,
        Some(RawNetload::III) => NetloadClass::III,
        None => {
            cx.defaulted("profinet.netload_class", "\"I\"", near.clone());
            NetloadClass::I
        }
    };
    let dap_im_records = match &p.writeable_im_records {
        Some(records) => writeable_im_records(cx, records)?,
        None => {
            cx.defaulted("profinet.writeable_im_records", "[1, 2, 3]", near);
            DEFAULT_WRITEABLE_IM.to_vec()
        }
    };
    let module_writeable_im_records = match &p.module_writeable_im_records {
        Some(records) => writeable_im_records(cx, records)?,
        None => Vec::new(),
    };
    Some(InterfaceProperties {
        send_clock,
        preferred_send_clock,
        conformance_class,
        netload_class,
        writeable_im_records: dap_im_records,
        module_writeable_im_records,
        irt,
        isochronous,
    })
}

/// E152: an MRP client has two ring ports. `client` is where the
/// description makes the device access point one, when it does.
pub fn check_ring_ports(cx: &mut Checker, client: Option<Range<usize>>, ports: u8) {
    let Some(at) = client else {
        return;
    };
    if ports < 2 {
        cx.push(
            Diagnostic::error("E152", "media redundancy needs two ports")
                .at(at)
                .label("MRP client")
                .help("an MRP client closes the ring through two ports: set ports = 2, or media_redundancy = false"),
        );
    }
}

/// A preferred send clock, when stated: one of `offered`, the send clocks
/// of the real-time `class` (E150).
pub(super) fn preferred_send_clock(
    cx: &mut Checker,
    preferred: Option<&Spanned<u16>>,
    offered: &[u16],
    class: &str,
) -> Option<Option<u16>> {
    let Some(preferred) = preferred else {
        return Some(None);
    };
    let value = *preferred.get_ref();
    if offered.contains(&value) {
        return Some(Some(value));
    }
    cx.push(
        Diagnostic::error(
            "E150",
            format!("the preferred send clock {value} is not in the list"),
        )
        .at(preferred.span())
        .label("not offered")
        .help(format!(
            "prefer one of the send clocks the interface accepts in {class}"
        )),
    );
    None
}

/// E150: ascending factors from 1 to 128, each once, 32 among them.
pub(super) fn send_clock(
    cx: &mut Checker,
    clocks: &Spanned<Vec<Spanned<u16>>>,
) -> Option<Vec<u16>> {
    let mut values = Vec::new();
    for clock in clocks.get_ref() {
        let value = *clock.get_ref();
        let problem = if !(1..=MAX_SEND_CLOCK).contains(&value) {
            Some("a send clock factor is 1 to 128 (31.25 us to 4 ms)")
        } else if values.last().is_some_and(|&last| last >= value) {
            Some("list the factors once each, ascending")
        } else {
            None
        };
        if let Some(help) = problem {
            cx.push(
                Diagnostic::error(
                    "E150",
                    format!("{value} cannot follow in the send clock list"),
                )
                .at(clock.span())
                .label("not a send clock here")
                .help(help),
            );
            return None;
        }
        values.push(value);
    }
    if !values.contains(&REQUIRED_SEND_CLOCK) {
        cx.push(
            Diagnostic::error("E150", "the send clock list lacks 32 (1 ms)")
                .at(clocks.span())
                .label("no 32")
                .help(
                    "every PROFINET device accepts a 1 ms send clock: add 32, e.g. [32, 64, 128]",
                ),
        );
        return None;
    }
    Some(values)
}

/// E151: class C is the class of an RT_CLASS_3 device, and of no other.
fn conformance_class(
    cx: &mut Checker,
    class: &Spanned<RawConformance>,
    has_irt: bool,
) -> Option<ConformanceClass> {
    let help = match (class.get_ref(), has_irt) {
        (RawConformance::A, false) => return Some(ConformanceClass::A),
        (RawConformance::B, false) => return Some(ConformanceClass::B),
        (RawConformance::C, true) => return Some(ConformanceClass::C),
        (RawConformance::C, false) => "class C is isochronous real time (RT_CLASS_3): describe it in [profinet.irt], or write \"A\" or \"B\"",
        (_, true) => "a device with isochronous real time ([profinet.irt]) is of class C: write \"C\", or leave conformance_class out",
    };
    let class_value = match class.get_ref() {
        RawConformance::A => "A",
        RawConformance::B => "B",
        RawConformance::C => "C",
    };
    cx.push(
        Diagnostic::error(
            "E151",
            format!("conformance class {class_value} does not match the interface"),
        )
        .at(class.span())
        .label("this class")
        .help(help),
    );
    None
}

/// I&M1 to I&M4, each once, ascending in the file.
fn writeable_im_records(cx: &mut Checker, records: &Spanned<Vec<Spanned<u8>>>) -> Option<Vec<u8>> {
    let mut seen = BTreeSet::new();
    for record in records.get_ref() {
        let value = cx.spanned_in_range(record, 1, 4, "a writable I&M record")?;
        if !seen.insert(value) {
            cx.duplicate(format!("I&M{value}"), record.span());
            return None;
        }
    }
    Some(seen.into_iter().collect())
}
