//! The device symbol of an imported GSD: the bitmap its `Bitmap_Device`
//! names beside the file, read through the caller's `files`, written back
//! as the PNG the description's `[device] symbol` names, which the build
//! turns into the bitmap again (`crate::symbol`).

use super::Notes;
use crate::device::dp::{DpDevice, Keyword};

/// The PNG to write beside the description, under `file_name`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ImportedSymbol {
    pub file_name: String,
    pub png: Vec<u8>,
}

/// The symbol of `device`, when its `Bitmap_Device` names a bitmap that
/// reads as a 70 x 40 picture; otherwise a warning naming the bitmap and
/// why (W600), and the import goes on without a symbol.
pub(super) fn imported(
    device: &DpDevice,
    files: super::Files<'_>,
    notes: &mut Notes,
) -> Option<ImportedSymbol> {
    let keyword = device.keyword("Bitmap_Device")?;
    let Some(stem) = keyword.value.as_str().filter(|s| is_plain_name(s)) else {
        notes.unsaid(
            &keyword.name,
            &keyword.place,
            "it names no bitmap file gsdc can look for beside the GSD (letters, digits, `_` and `-`)",
        );
        return None;
    };
    let bmp_name = format!("{stem}.bmp");
    let without = |notes: &mut Notes, why: String| {
        notes.unsaid(
            &keyword.name,
            &keyword.place,
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
        Ok(rebuilt) if rebuilt.bmp != bmp => rebuilt_differs(keyword, &bmp_name, &rebuilt, notes),
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
    keyword: &Keyword,
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
        &keyword.place,
    );
}

/// A file stem to look for beside the GSD: no path, nothing a shell or a
/// file system reads otherwise.
fn is_plain_name(name: &str) -> bool {
    !name.is_empty()
        && name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
}
