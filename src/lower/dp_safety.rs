//! `[profibus.modules.safety]`: a PROFIsafe module's block of
//! F-parameters, which the master sends after the device's User_Prm_Data
//! when the module is plugged, and its description CRCs, pinned to the
//! config bytes and F-parameters they were given for (E128, W109) as a
//! PROFINET safety module's are.

use super::checks::Checker;
use super::safety_crcs::{pinned, CrcFile};
use crate::description::dp as raw;
use crate::diag::Diagnostic;
use crate::ir::profibus::{dp_safety_fingerprint, DpModule, DpSafety, UserPrm};
use crate::ir::safety::DescriptionCrcs;

/// Gives each PROFIsafe module of `given` its block, its parameters
/// numbered after User_Prm_Data's and their facts and texts kept in it;
/// E172 in a GSD older than the `F_` keywords.
pub(super) fn lower(
    cx: &mut Checker,
    (given, gsd_revision): (&[raw::DpModule], u8),
    modules: &mut [DpModule],
    user_prm: &mut UserPrm,
) {
    let next = |ids: &mut dyn Iterator<Item = u16>| ids.max().map_or(1, |id| id + 1);
    let mut ids = next(&mut user_prm.params().map(|p| p.id))..=u16::MAX;
    let mut text_ids = next(&mut user_prm.texts.iter().map(|t| t.id))..=u16::MAX;
    for m in given {
        let Some(safety) = &m.safety else { continue };
        // Every F_ keyword came with one revision: one error says it.
        cx.since_revision("F_Ext_Module_Prm_Data_Len", safety.span(), gsd_revision);
        // A module with an error has no lowered module to take its block.
        let Some(module) = modules.iter_mut().find(|l| l.name == *m.name.get_ref()) else {
            continue;
        };
        let what = format!("module \"{}\"'s safety", module.name);
        let placed = super::dp_params::lower(
            cx,
            &safety.get_ref().parameters,
            (&mut ids, &mut text_ids),
            user_prm.card_params.len(),
        );
        let constant: Vec<u8> = safety
            .get_ref()
            .constant
            .iter()
            .map(|b| *b.get_ref())
            .collect();
        let len = constant.len().max(placed.end);
        fits_user_prm(cx, (len, user_prm.len), safety, &what);
        let crcs = safety.get_ref().crcs.get_ref();
        let crc_what = |key: &str| format!("{what}.crcs.{key}");
        let f_param_desc = cx.gsd_number(
            &crcs.f_param_desc,
            "F_ParamDescCRC",
            &crc_what("f_param_desc"),
        );
        let f_io_structure_desc = cx.gsd_number(
            &crcs.f_io_structure_desc,
            "F_IO_StructureDescCRC",
            &crc_what("f_io_structure_desc"),
        );
        let (Some(f_param_desc), Some(f_io_structure_desc)) = (f_param_desc, f_io_structure_desc)
        else {
            continue;
        };
        user_prm.texts.extend(placed.texts());
        let block = DpSafety {
            constant,
            params: placed.params,
            len: u16::try_from(len).unwrap_or(u16::MAX),
            crcs: DescriptionCrcs {
                f_param_desc,
                f_io_structure_desc,
                placeholder: crcs.placeholder,
            },
        };
        user_prm.card_params.extend(placed.facts);
        let now = dp_safety_fingerprint(
            &module.config,
            (block.len, &block.constant),
            &block.shapes(&user_prm.card_params),
        );
        let crcs_what = format!("module \"{}\"'s CRCs", module.name);
        if pinned(cx, &safety.get_ref().crcs, &now, (&crcs_what, CrcFile::Gsd)).is_some() {
            module.safety = Some(block);
        }
    }
}

/// E116: the device's User_Prm_Data and the block together longer than a
/// parameter telegram holds.
fn fits_user_prm(
    cx: &mut Checker,
    (len, device_len): (usize, u16),
    safety: &toml::Spanned<raw::DpSafety>,
    what: &str,
) {
    let end = len + usize::from(device_len);
    let most = super::dp_params::max_user_prm_len();
    if end > most {
        cx.push(
            Diagnostic::error(
                "E116",
                format!("the parameter telegram would be {end} bytes with {what} block; GSD allows {most}"),
            )
            .at(safety.span())
            .label(format!("{len} bytes of F-parameters"))
            .help("the master sends the block after the device's User_Prm_Data: shorten one of them"),
        );
    }
}
