//! The DP keywords of DPV1 alarms and of DP-V2 a vendor's GSD states:
//! `[profibus.dpv1.alarms]`, `[profibus.isochronous]` and
//! `[profibus.user_prm] block_structure`, each written as stated (`gsdc
//! import` writes them for real drive files that have them).

use super::checks::Checker;
use crate::description::dp as raw;
use crate::diag::Diagnostic;
use crate::ir::profibus::{AlarmKind, Alarms, BlockStructure, Isochronous};
use toml::Spanned;

/// The alarms; E105 for a kind named twice in one list, E180 for one
/// required and not supported.
pub(super) fn alarms(cx: &mut Checker, a: &raw::Alarms) -> Alarms {
    let mut out = Alarms {
        type_mode: a.type_mode.as_ref().map(|v| *v.get_ref()),
        extra_alarm_sap: a.extra_alarm_sap.as_ref().map(|v| *v.get_ref()),
        sequence_mode_count: a
            .sequence_mode_count
            .as_ref()
            .and_then(|v| cx.gsd_number(v, "Alarm_Sequence_Mode_Count", "sequence_mode_count")),
        ..Alarms::default()
    };
    mark(cx, &a.supported, &mut out.supported, "supported");
    mark(cx, &a.required, &mut out.required, "required");
    for kind in &a.required {
        if !out.supported[position(*kind.get_ref())] {
            let name = kind.get_ref().name();
            cx.push(
                Diagnostic::error(
                    "E180",
                    format!("the {name} alarm is required but not supported"),
                )
                .at(kind.span())
                .label("not in `supported`")
                .help(format!(
                    "add \"{name}\" to `supported`: a card requires the master to enable an alarm it sends"
                )),
            );
        }
    }
    out
}

fn position(kind: AlarmKind) -> usize {
    AlarmKind::ALL
        .iter()
        .position(|k| *k == kind)
        .expect("ALL has every kind")
}

fn mark(cx: &mut Checker, kinds: &[Spanned<AlarmKind>], flags: &mut [bool; 6], list: &str) {
    for kind in kinds {
        let at = position(*kind.get_ref());
        if flags[at] {
            let what = format!("the {} alarm in `{list}`", kind.get_ref().name());
            cx.duplicate(what, kind.span());
        }
        flags[at] = true;
    }
}

/// C1_Read_Write_required and C2_Read_Write_required as stated; E182 for
/// a channel required that the card does not have (`c1_read_write`,
/// `[profibus.dpv1.c2]`).
pub(super) fn channels_required(
    cx: &mut Checker,
    d: &crate::description::Dpv1,
) -> (Option<bool>, Option<bool>) {
    let channels = [
        (
            &d.c1_read_write_required,
            d.c1_read_write,
            "class 1",
            "c1_read_write = true",
        ),
        (
            &d.c2_read_write_required,
            d.c2.is_some(),
            "class 2",
            "[profibus.dpv1.c2]",
        ),
    ];
    let [c1, c2] = channels.map(|(required, has, channel, needs)| {
        let required = required.as_ref()?;
        if *required.get_ref() && !has {
            cx.push(
                Diagnostic::error(
                    "E182",
                    format!("the DPV1 {channel} channel is required but not supported"),
                )
                .at(required.span())
                .label("no such channel")
                .help(format!("give {needs}, or leave the requirement out")),
            );
        }
        Some(*required.get_ref())
    });
    (c1, c2)
}

/// Isochronous mode: a GSD revision 4 keyword (E172), and its least DP
/// cycle no longer than its longest (E181).
pub(super) fn isochronous(
    cx: &mut Checker,
    i: &Spanned<raw::Isochronous>,
    gsd_revision: u8,
) -> Isochronous {
    cx.since_revision("Isochron_Mode_supp", i.span(), gsd_revision);
    let i = i.get_ref();
    let (min, max) = (*i.tdp_min.get_ref(), *i.tdp_max.get_ref());
    if min > max {
        cx.push(
            Diagnostic::error(
                "E181",
                format!("tdp_min = {min} is more than tdp_max = {max}"),
            )
            .at(i.tdp_min.span())
            .label("more than tdp_max")
            .help("TDP_MIN and TDP_MAX bound the isochronous DP cycle: the least cannot exceed the longest"),
        );
    }
    Isochronous {
        required: i.required.as_ref().map(|v| *v.get_ref()),
        tbase_dp: *i.tbase_dp.get_ref(),
        tdp_max: max,
        tdp_min: min,
        tbase_io: *i.tbase_io.get_ref(),
        ti_min: *i.ti_min.get_ref(),
        to_min: *i.to_min.get_ref(),
        t_pll_w_max: *i.t_pll_w_max.get_ref(),
    }
}

/// `block_structure`: a GSD revision 4 keyword (E172).
pub(super) fn block_structure(
    cx: &mut Checker,
    b: &Spanned<BlockStructure>,
    gsd_revision: u8,
) -> BlockStructure {
    cx.since_revision("Prm_Block_Structure_supp", b.span(), gsd_revision);
    *b.get_ref()
}
