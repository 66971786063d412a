//! A GSD's PROFIsafe module: its F-parameters (`F_Ext_Module_Prm_Data_Len`,
//! `F_Ext_User_Prm_Data_Const` and `_Ref`) as `[profibus.modules.safety]`,
//! with the file's two description CRCs pinned to the fingerprint of what
//! the file describes (`of`), so the built module carries them only while
//! it is the module they were given for.

use super::super::toml_out::{hex, list, TomlOut};
use super::super::Notes;
use crate::device::dp::DpModule;
use crate::device::{Allowed, Field, Value};
use crate::ir::profibus::{dp_safety_fingerprint, PrmType, SafetyPrmShape};

/// The module's F-parameter block and CRCs, when the description can say
/// all of it.
pub(super) struct Block {
    f_param_desc: u16,
    f_io_structure_desc: u32,
    constant: Vec<u8>,
    of: String,
}

/// The CRC keywords the block takes from the module's keywords.
pub(super) const CRC_KEYWORDS: [&str; 2] = ["f_paramdesccrc", "f_io_structuredesccrc"];

/// `m`'s block when it has F-parameters, both CRCs, and every parameter
/// one a card parameter can be.
pub(super) fn block(m: &DpModule) -> Option<Block> {
    let prm = &m.safety_prm_data;
    if prm.is_empty() {
        return None;
    }
    let crc = |key: &str| {
        let k = m.keywords.iter().find(|k| k.key == key)?;
        k.value.as_number()
    };
    let f_param_desc = u16::try_from(crc(CRC_KEYWORDS[0])?).ok()?;
    let f_io_structure_desc = u32::try_from(crc(CRC_KEYWORDS[1])?).ok()?;
    let shapes: Vec<SafetyPrmShape> = prm.fields.iter().map(shape).collect::<Option<_>>()?;
    let constant = constant(prm);
    let extent = prm.extent().max(constant.len() as u32);
    let len = u16::try_from(prm.len().max(extent)).ok()?;
    let of = dp_safety_fingerprint(&m.config, (len, &constant), &shapes);
    Some(Block {
        f_param_desc,
        f_io_structure_desc,
        constant,
        of,
    })
}

/// The block's fixed bytes from byte 0 (gaps zero, what the master sends
/// there), as far as its constants reach, or its declared length where its
/// parameters do not reach that.
fn constant(prm: &crate::device::ParameterData) -> Vec<u8> {
    let fields_end = prm
        .fields
        .iter()
        .map(|f| (f.byte_offset + f.size()) as usize)
        .max()
        .unwrap_or(0);
    let declared = prm.length.map_or(0, |l| l as usize);
    super::fixed_bytes(prm, (declared > fields_end).then_some(declared).into_iter())
}

/// A parameter as lowering will make it of what the import writes, for
/// the fingerprint; `None` for one a card parameter cannot be.
fn shape(f: &Field) -> Option<SafetyPrmShape> {
    if !f.attributes.is_empty() {
        return None;
    }
    let data_type = match (f.data_type.as_str(), f.bits) {
        ("Bit" | "BitArea", Some(b)) => {
            let last = b.offset.checked_add(b.length)?.checked_sub(1)?;
            (last <= 7).then_some(PrmType::Bits {
                first: b.offset,
                last,
            })?
        }
        ("Unsigned8", None) => PrmType::Unsigned8,
        ("Unsigned16", None) => PrmType::Unsigned16,
        ("Signed8", None) if super::signed8(f).is_some() => PrmType::Signed8,
        _ => return None,
    };
    let default = match &f.default {
        Some(Value::Int(v)) => *v,
        None => 0,
        Some(_) => return None,
    };
    let allowed = if f.choices.is_empty() {
        let ranges: Vec<(i128, i128)> = match &f.allowed {
            Allowed::Any => vec![(0, data_type.max().into())],
            Allowed::Ranges(ranges) => ranges
                .iter()
                .map(|(a, b)| match (a, b) {
                    (Value::Int(a), Value::Int(b)) => Some((*a, *b)),
                    _ => None,
                })
                .collect::<Option<_>>()?,
        };
        let [(min, max)] = super::joined(ranges)[..] else {
            return None;
        };
        format!("{min}-{max}")
    } else {
        let values: Vec<String> = f
            .choices
            .iter()
            .filter_map(|c| match &c.value {
                Value::Int(v) if super::allows(&f.allowed, *v) => Some(v.to_string()),
                _ => None,
            })
            .collect();
        values.join(",")
    };
    Some(SafetyPrmShape {
        offset: u16::try_from(f.byte_offset).ok()?,
        data_type: data_type.to_string(),
        default,
        allowed,
        changeable: f.changeable,
        visible: f.visible,
    })
}

/// `[profibus.modules.safety]` and its parameters.
pub(super) fn write(out: &mut TomlOut, m: &DpModule, block: &Block, notes: &mut Notes) {
    out.table("profibus.modules.safety");
    if !block.constant.is_empty() {
        out.key("constant", list(block.constant.iter().map(|b| hex(*b))));
    }
    out.key(
        "crcs",
        format!(
            "{{ f_param_desc = 0x{:04X}, f_io_structure_desc = {}, of = \"{}\" }}",
            block.f_param_desc, block.f_io_structure_desc, block.of
        ),
    );
    for field in &m.safety_prm_data.fields {
        super::parameter(out, "profibus.modules.safety.parameters", field, notes);
    }
}
