//! User parameter data: the `Ext_User_Prm_Data_Const(offset)` and
//! `Ext_User_Prm_Data_Ref(offset)` entries of the station or of a module, and
//! the default telegram they make.

use foldhash::{HashMap, HashMapExt};

use crate::gsd::model::{ExtUserPrmData, GsdFile, Module, PrmDataType, Setting};

/// No parameter telegram is longer than a PROFIBUS frame can carry, so the
/// default telegram never grows past this (entries beyond it are reported by
/// rule E219 and left out here).
pub const MAX_TELEGRAM: usize = crate::spec::DP_MAX_TELEGRAM;

/// Which family of parameter keywords: the plain ones, or PROFIsafe's `F_`
/// ones inside a module.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Family {
    Plain,
    Safety,
}

impl Family {
    /// The keys of its const and ref entries.
    fn entry_keys(self) -> (&'static str, &'static str) {
        match self {
            Family::Plain => ("ext_user_prm_data_const", "ext_user_prm_data_ref"),
            Family::Safety => ("f_ext_user_prm_data_const", "f_ext_user_prm_data_ref"),
        }
    }
}

/// `Ext_User_Prm_Data_Const(offset) = bytes`.
pub struct ConstEntry<'a> {
    pub offset: i64,
    pub bytes: Vec<i64>,
    pub setting: &'a Setting,
}

/// `Ext_User_Prm_Data_Ref(offset) = id`.
pub struct RefEntry<'a> {
    pub offset: i64,
    pub id: i64,
    pub setting: &'a Setting,
}

pub struct Layout<'a> {
    pub consts: Vec<ConstEntry<'a>>,
    pub refs: Vec<RefEntry<'a>>,
}

impl Layout<'_> {
    pub fn is_empty(&self) -> bool {
        self.consts.is_empty() && self.refs.is_empty()
    }
}

/// The const and ref entries among `settings`, in file order.
pub fn layout(settings: &[Setting], family: Family) -> Layout<'_> {
    let (const_key, ref_key) = family.entry_keys();
    let mut layout = Layout {
        consts: Vec::new(),
        refs: Vec::new(),
    };
    for setting in settings {
        let Some(offset) = setting.index() else {
            continue;
        };
        if setting.key == const_key {
            if let Some(bytes) = setting.value.as_list() {
                layout.consts.push(ConstEntry {
                    offset,
                    bytes,
                    setting,
                });
            }
        } else if setting.key == ref_key {
            if let Some(id) = setting.value.as_number() {
                layout.refs.push(RefEntry {
                    offset,
                    id,
                    setting,
                });
            }
        }
    }
    layout
}

/// The default telegram of `settings`: each const laid at its offset, then
/// each referenced parameter's default at its offset, big-endian. Without
/// any const or ref, the legacy `User_Prm_Data` bytes.
pub fn default_telegram(file: &GsdFile, settings: &[Setting], family: Family) -> Vec<u8> {
    let layout = layout(settings, family);
    if layout.is_empty() {
        return crate::gsd::model::find(settings, "User_Prm_Data")
            .and_then(|s| s.value.as_list())
            .map(|bytes| bytes.iter().map(|&b| b as u8).collect())
            .unwrap_or_default();
    }
    let mut telegram = Vec::new();
    for c in &layout.consts {
        if let Some(slot) = reserve(&mut telegram, c.offset, c.bytes.len()) {
            for (dst, &b) in slot.iter_mut().zip(&c.bytes) {
                *dst = b as u8;
            }
        }
    }
    let params = by_id(file);
    for r in &layout.refs {
        let Some(data) = params.get(&r.id) else {
            continue;
        };
        if let (Some(ty), Some(default)) = (&data.data_type, &data.default) {
            if let Some(slot) = reserve(&mut telegram, r.offset, ty.value.size()) {
                write_value(slot, &ty.value, default.value);
            }
        }
    }
    telegram
}

/// The `ExtUserPrmData` blocks by id (the first of duplicates, as
/// [`GsdFile::ext_user_prm_data`] finds it), so that looking up thousands of
/// references stays linear.
pub fn by_id(file: &GsdFile) -> HashMap<i64, &ExtUserPrmData> {
    let mut map = HashMap::new();
    for data in &file.ext_user_prm_data {
        map.entry(data.id.value).or_insert(data);
    }
    map
}

/// Grows the telegram to cover `offset..offset + len` and returns that
/// part, or `None` when it lies outside [`MAX_TELEGRAM`].
fn reserve(telegram: &mut Vec<u8>, offset: i64, len: usize) -> Option<&mut [u8]> {
    let start = usize::try_from(offset).ok()?;
    let end = start.checked_add(len).filter(|&e| e <= MAX_TELEGRAM)?;
    if telegram.len() < end {
        telegram.resize(end, 0);
    }
    Some(&mut telegram[start..end])
}

/// Writes `value` as `ty` into `slot` (which is `ty.size()` long): numbers
/// big-endian, bits into their place without touching the other bits.
pub fn write_value(slot: &mut [u8], ty: &PrmDataType, value: i64) {
    match ty {
        PrmDataType::Bit(_) | PrmDataType::BitArea(..) => {
            let mask = ty.bit_mask();
            let shift = mask.trailing_zeros();
            let bits = ((value as u64) << shift) as u8 & mask;
            slot[0] = slot[0] & !mask | bits;
        }
        _ => {
            let be = value.to_be_bytes();
            slot.copy_from_slice(&be[be.len() - slot.len()..]);
        }
    }
}

/// The bytes and bits a referenced parameter occupies: (byte offset, mask)
/// for each byte.
pub fn occupied(offset: i64, data: &ExtUserPrmData) -> Vec<(i64, u8)> {
    let Some(ty) = &data.data_type else {
        return Vec::new();
    };
    let mask = ty.value.bit_mask();
    (0..ty.value.size() as i64)
        .map(|i| (offset + i, mask))
        .collect()
}

// The default telegrams are methods of the model, built here: the model
// describes the file, this module what a master makes of it.
impl GsdFile {
    /// The station's default User_Prm_Data telegram (without the 7 standard
    /// bytes of the Set_Prm telegram), as a master sends it unchanged.
    pub fn default_user_prm_data(&self) -> Vec<u8> {
        default_telegram(self, &self.settings, Family::Plain)
    }
}

impl Module {
    /// The module's default parameter bytes (its part of User_Prm_Data),
    /// built like [`GsdFile::default_user_prm_data`].
    pub fn default_prm_data(&self, file: &GsdFile) -> Vec<u8> {
        default_telegram(file, &self.settings, Family::Plain)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn write_value_is_big_endian_and_keeps_other_bits() {
        let mut two = [0u8; 2];
        write_value(&mut two, &PrmDataType::Unsigned16, 0xF00C);
        assert_eq!(two, [0xF0, 0x0C]);
        let mut signed = [0u8; 2];
        write_value(&mut signed, &PrmDataType::Signed16, -2);
        assert_eq!(signed, [0xFF, 0xFE]);
        let mut byte = [0b1000_0001u8];
        write_value(&mut byte, &PrmDataType::BitArea(1, 2), 3);
        assert_eq!(byte, [0b1000_0111]);
        write_value(&mut byte, &PrmDataType::Bit(7), 0);
        assert_eq!(byte, [0b0000_0111]);
    }
}
