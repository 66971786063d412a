//! `[profinet.irt]` and `[profinet.isochronous]`: RT_CLASS_3 and the
//! isochronous mode of the modules, each value checked against the range
//! the schema gives its attribute.

use super::interface::{preferred_send_clock, send_clock};
use crate::description::irt::{self as raw, ForwardingMode, StartupMode};
use crate::diag::Diagnostic;
use crate::ir::profinet::{Irt, Isochronous};
use crate::lower::checks::Checker;
use std::collections::BTreeSet;
use toml::Spanned;

/// `MaxNumberIR_FrameData`'s largest value in the schema.
const MAX_IR_FRAME_DATA: i64 = 1024;
/// Reduction ratios PROFINET knows: 1 to 512 send clocks.
const MAX_REDUCTION_RATIO: i64 = 512;
/// `T_DC_Base` (31.25 us) and `T_IO_Base` (ns) at most, as the schema.
const MAX_T_DC_BASE: i64 = 1024;
const MAX_T_IO_BASE: i64 = 32_000_000;

/// `[profinet.irt]` and `[profinet.isochronous]`, each when given; `None`
/// when either has an error.
pub fn timing(
    cx: &mut Checker,
    p: &crate::description::Profinet,
) -> Option<(Option<Irt>, Option<Isochronous>)> {
    let irt = match &p.irt {
        Some(given) => Some(irt(cx, given)?),
        None => None,
    };
    let isochronous = match &p.isochronous {
        Some(given) => Some(isochronous(cx, given, irt.is_some())?),
        None => None,
    };
    Some((irt, isochronous))
}

fn irt(cx: &mut Checker, irt: &Spanned<raw::Irt>) -> Option<Irt> {
    let i = irt.get_ref();
    let send_clock = send_clock(cx, &i.send_clock)?;
    let preferred_send_clock = preferred_send_clock(
        cx,
        i.preferred_send_clock.as_ref(),
        &send_clock,
        "RT_CLASS_3",
    )?;
    Some(Irt {
        max_bridge_delay: *i.max_bridge_delay.get_ref(),
        max_number_ir_frame_data: cx.spanned_in_range(
            &i.max_number_ir_frame_data,
            0,
            MAX_IR_FRAME_DATA,
            "MaxNumberIR_FrameData",
        )?,
        forwarding_mode: tokens(cx, i.forwarding_mode.as_ref(), forwarding_token)?,
        startup_mode: tokens(cx, i.startup_mode.as_ref(), startup_token)?,
        send_clock,
        reduction_ratio: reduction_ratios(cx, &i.reduction_ratio)?,
        preferred_send_clock,
        max_local_jitter: i.max_local_jitter.as_ref().map(|v| *v.get_ref()),
        t_pll_max: i.t_pll_max.as_ref().map(|v| *v.get_ref()),
        port_tx_delay: *i.port_tx_delay.get_ref(),
        port_rx_delay: *i.port_rx_delay.get_ref(),
    })
}

/// Isochronous mode: only with RT_CLASS_3 (E188), its least data cycle
/// at most its longest (E181).
fn isochronous(
    cx: &mut Checker,
    iso: &Spanned<raw::Isochronous>,
    has_irt: bool,
) -> Option<Isochronous> {
    if !has_irt {
        cx.push(
            Diagnostic::error("E188", "isochronous mode without isochronous real time")
                .at(iso.span())
                .label("isochronous mode")
                .help("the modules follow the isochronous cycle only over RT_CLASS_3: describe it in [profinet.irt]"),
        );
        return None;
    }
    let i = iso.get_ref();
    let t_dc_min: u16 = cx.spanned_in_range(&i.t_dc_min, 1, u16::MAX.into(), "T_DC_Min")?;
    let t_dc_max: u16 = cx.spanned_in_range(&i.t_dc_max, 1, u16::MAX.into(), "T_DC_Max")?;
    if t_dc_min > t_dc_max {
        cx.push(
            Diagnostic::error("E181", format!("T_DC_Min {t_dc_min} exceeds T_DC_Max {t_dc_max}"))
                .at(i.t_dc_min.span())
                .label("more than t_dc_max")
                .help("t_dc_min and t_dc_max bound the data cycle the modules follow: the least cannot exceed the longest"),
        );
        return None;
    }
    let at_least_one =
        |cx: &mut Checker, v: &Spanned<u32>, what| cx.spanned_in_range(v, 1, u32::MAX.into(), what);
    Some(Isochronous {
        required: i.required.as_ref().is_some_and(|r| *r.get_ref()),
        t_dc_base: cx.spanned_in_range(&i.t_dc_base, 1, MAX_T_DC_BASE, "T_DC_Base")?,
        t_dc_min,
        t_dc_max,
        t_io_base: cx.spanned_in_range(&i.t_io_base, 1, MAX_T_IO_BASE, "T_IO_Base")?,
        t_io_input_min: at_least_one(cx, &i.t_io_input_min, "T_IO_InputMin")?,
        t_io_output_min: at_least_one(cx, &i.t_io_output_min, "T_IO_OutputMin")?,
    })
}

/// Reduction ratios, at least one (an empty `ReductionRatio` is no value
/// list), each once, from 1 to 512, in the description's order.
fn reduction_ratios(cx: &mut Checker, ratios: &Spanned<Vec<Spanned<u16>>>) -> Option<Vec<u16>> {
    if ratios.get_ref().is_empty() {
        cx.push(
            Diagnostic::error("E117", "profinet.irt.reduction_ratio is empty")
                .at(ratios.span())
                .label("empty")
                .help("list the reduction ratios the interface accepts in RT_CLASS_3, e.g. [1, 2, 4, 8, 16]"),
        );
        return None;
    }
    let mut seen = BTreeSet::new();
    let mut values = Vec::new();
    for ratio in ratios.get_ref() {
        let value: u16 = cx.spanned_in_range(ratio, 1, MAX_REDUCTION_RATIO, "a reduction ratio")?;
        if !seen.insert(value) {
            cx.duplicate(format!("reduction ratio {value}"), ratio.span());
            return None;
        }
        values.push(value);
    }
    Some(values)
}

/// A list of GSDML tokens, each once, in the description's order.
fn tokens<T: Copy + Ord>(
    cx: &mut Checker,
    list: Option<&Spanned<Vec<Spanned<T>>>>,
    token: fn(T) -> &'static str,
) -> Option<Vec<&'static str>> {
    let mut seen = BTreeSet::new();
    let mut written = Vec::new();
    for item in list.map_or(&[][..], |l| &l.get_ref()[..]) {
        let value = *item.get_ref();
        if !seen.insert(value) {
            cx.duplicate(format!("`{}`", token(value)), item.span());
            return None;
        }
        written.push(token(value));
    }
    Some(written)
}

fn forwarding_token(mode: ForwardingMode) -> &'static str {
    match mode {
        ForwardingMode::Absolute => "Absolute",
        ForwardingMode::Relative => "Relative",
    }
}

fn startup_token(mode: StartupMode) -> &'static str {
    match mode {
        StartupMode::Legacy => "Legacy",
        StartupMode::Advanced => "Advanced",
    }
}
