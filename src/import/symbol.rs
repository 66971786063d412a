//! The device symbol of an imported file: the bitmap a GSD's
//! `Bitmap_Device` or a GSDML file's `DeviceSymbol` graphic names beside
//! the file, read through the caller's `files`, written back as the PNG the
//! description's `[device] symbol` names, which the build turns into the
//! bitmap again (`crate::symbol`).

use super::Notes;
use crate::device::dp::DpDevice;
use crate::device::pn::PnDevice;
use crate::device::{AttributeValue, Device, Place};

/// The PNG to write beside the description, under `file_name`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ImportedSymbol {
    pub file_name: String,
    pub png: Vec<u8>,
}

/// Where a device file names its device symbol's bitmap: the keyword or
/// attribute, the name without `.bmp` and its place.
pub(super) struct SymbolRef<'d> {
    what: &'d str,
    stem: Option<&'d str>,
    place: &'d Place,
}

/// Where a GSD or GSDML file names its device symbol.
pub(super) fn of(device: &Device) -> Option<SymbolRef<'_>> {
    match device {
        Device::Dp(d) => of_gsd(d),
        Device::Pn(d) => of_gsdml(d),
    }
}

/// A GSD's `Bitmap_Device`.
pub(super) fn of_gsd(device: &DpDevice) -> Option<SymbolRef<'_>> {
    let keyword = device.keyword("Bitmap_Device")?;
    Some(SymbolRef {
        what: &keyword.name,
        stem: keyword.value.as_str(),
        place: &keyword.place,
    })
}

/// The attributes of a device access point that name its graphic, one
/// `GraphicItemRef` of type `DeviceSymbol`, its target the graphic's file
/// (the reader resolves the `GraphicsList` item).
pub(super) const GSDML_SYMBOL_TYPE: &str = "Graphics/GraphicItemRef@Type";
pub(super) const GSDML_SYMBOL_TARGET: &str = "Graphics/GraphicItemRef@GraphicItemTarget";

/// A GSDML file's device symbol: its (first) device access point's one
/// graphic, when that is a `DeviceSymbol`.
fn of_gsdml(device: &PnDevice) -> Option<SymbolRef<'_>> {
    let attributes = &device.daps.first()?.item.attributes;
    let plain = |name: &str| {
        attributes
            .iter()
            .find(|a| &*a.name == name)
            .and_then(|a| match &a.value {
                AttributeValue::Plain(value) => Some((a, &**value)),
                AttributeValue::Text(_) => None,
            })
    };
    let (_, kind) = plain(GSDML_SYMBOL_TYPE)?;
    let (target, file) = plain(GSDML_SYMBOL_TARGET).filter(|_| kind == "DeviceSymbol")?;
    Some(SymbolRef {
        what: &target.name,
        stem: Some(file),
        place: &target.place,
    })
}

/// The symbol a file names, when the bitmap reads as a 70 x 40 picture;
/// otherwise a warning naming the bitmap and why (W600), and the import
/// goes on without a symbol.
pub(super) fn imported(
    reference: Option<SymbolRef<'_>>,
    files: super::Files<'_>,
    notes: &mut Notes,
) -> Option<ImportedSymbol> {
    let reference = reference?;
    let Some(stem) = reference.stem.filter(|s| is_plain_name(s)) else {
        notes.unsaid(
            reference.what,
            reference.place,
            "it names no bitmap file gsdc can look for beside the file (letters, digits, `_` and `-`)",
        );
        return None;
    };
    let bmp_name = format!("{stem}.bmp");
    let without = |notes: &mut Notes, why: String| {
        notes.unsaid(
            reference.what,
            reference.place,
            &format!("{why}: the description has no symbol"),
        );
        None
    };
    let bmp = match files(&bmp_name) {
        Ok(bmp) => bmp,
        Err(why) => {
            return without(
                notes,
                format!("its bitmap {bmp_name} cannot be read ({why})"),
            )
        }
    };
    let converted = match crate::symbol::png_of_bitmap(&bmp) {
        Ok(converted) => converted,
        Err(why) => {
            return without(
                notes,
                format!("its bitmap {bmp_name} is not one gsdc reads: {why}"),
            )
        }
    };
    match crate::symbol::device_bitmap(&converted.png) {
        Ok(rebuilt) if rebuilt.bmp != bmp => {
            rebuilt_differs(reference.place, &bmp_name, &rebuilt, notes)
        }
        Ok(_) => {}
        Err(e) => {
            return without(
                notes,
                format!(
                    "its bitmap {bmp_name}: {}, and gsdc does not scale it",
                    e.message()
                ),
            )
        }
    }
    Some(ImportedSymbol {
        file_name: format!("{stem}.png"),
        png: converted.png,
    })
}

/// W603: the build writes the same picture in gsdc's bitmap format (70 x
/// 40, 4 bits a pixel, the 16 Windows colours), not the file's bytes.
fn rebuilt_differs(
    place: &Place,
    bmp_name: &str,
    rebuilt: &crate::symbol::DeviceBitmap,
    notes: &mut Notes,
) {
    let how = match rebuilt.approximated_pixels {
        0 => "the same pixels in gsdc's bitmap format (4 bits a pixel, the 16 Windows colours)"
            .to_string(),
        n => format!("{n} pixels in the nearest of the 16 Windows colours"),
    };
    notes.warn_at(
        crate::diag::Diagnostic::warning(
            "W603",
            format!("the build writes another {bmp_name} than the file's: {how}"),
        )
        .label("symbol imported")
        .help(
            "compare the two bitmaps; gsdc writes device symbols as 70 x 40 pixels in 16 colours",
        ),
        place,
    );
}

/// A file stem to look for beside the device file: no path, nothing a shell or a
/// file system reads otherwise.
fn is_plain_name(name: &str) -> bool {
    !name.is_empty()
        && name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
}
