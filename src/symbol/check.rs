//! `gsdc check` of a device symbol: a Windows bitmap beside a GSD or GSDML
//! (`Bitmap_Device`, a `GraphicItem`). E401 when an engineering tool could
//! not read it at all (headers cut short or impossible, pixel data past the
//! file's end); W402 when it is not the bitmap the conventions expect and
//! gsdc writes ([`super::WIDTH`] x [`super::HEIGHT`] pixels, 16 colours:
//! the module doc gives the sources), which a tool may show otherwise than
//! it was drawn.

// The command line checks symbols; the core only tells a bitmap apart.
#![cfg_attr(not(feature = "cli"), allow(dead_code))]

use crate::diag::{Diagnostic, Diagnostics, InputLimit};

/// The largest file read as a device symbol: gsdc's are 1558 bytes, and a
/// 70 x 40 bitmap of 32 bits a pixel is 11 KiB.
pub const INPUT_LIMIT: InputLimit = InputLimit {
    max_bytes: 1 << 20,
    code: "E401",
    what: "a device symbol",
    help:
        "a device symbol is a 70 x 40 bitmap of a few kilobytes: check that this is the right file",
};

/// The sizes of the headers a Windows bitmap may have after its 14-byte
/// file header: OS/2's BITMAPCOREHEADER, then BITMAPINFOHEADER and its
/// later versions (V2, V3, V4, V5).
const INFO_HEADER_LENS: [u32; 6] = [12, 40, 52, 56, 108, 124];

const FILE_HEADER_LEN: usize = 14;

/// Whether `head` starts as a Windows bitmap does: `BM`, and a header of a
/// size the format has. The second test keeps a text or random bytes that
/// start with `BM` from being taken for a bitmap.
pub fn is_bitmap(head: &[u8]) -> bool {
    head.starts_with(b"BM")
        && head
            .get(FILE_HEADER_LEN..FILE_HEADER_LEN + 4)
            .is_some_and(|len| INFO_HEADER_LENS.contains(&le32(len)))
}

/// What the headers say of the picture.
pub(super) struct Picture {
    /// The info header's size: the colour table follows it.
    pub info_len: u32,
    pub pixel_offset: u32,
    pub width: i64,
    /// Negative: rows stored top-down.
    pub height: i64,
    planes: u16,
    pub bits_per_pixel: u16,
    /// `biCompression`; 0 (none) in OS/2's header.
    pub compression: u32,
    /// `biClrUsed`: the colour table's entries, 0 for all the depth allows.
    pub colours_used: u32,
}

/// The findings on the bitmap `bytes`, which [`is_bitmap`] took for one.
pub fn check(bytes: &[u8]) -> Diagnostics {
    let problems = match picture(bytes) {
        Ok(picture) => match unreadable(&picture, bytes.len()) {
            Some(why) => vec![not_readable(why)],
            None => unexpected(&picture),
        },
        Err(why) => vec![not_readable(why)],
    };
    Diagnostics(problems)
}

pub(super) fn picture(bytes: &[u8]) -> Result<Picture, String> {
    let info_len = bytes
        .get(FILE_HEADER_LEN..FILE_HEADER_LEN + 4)
        .map_or(0, le32);
    if !INFO_HEADER_LENS.contains(&info_len) {
        return Err(format!(
            "its header is {info_len} bytes, which no bitmap's is"
        ));
    }
    let headers = FILE_HEADER_LEN + info_len as usize;
    let Some(info) = bytes.get(FILE_HEADER_LEN..headers) else {
        return Err(format!(
            "its headers need {headers} bytes, and the file has {}",
            bytes.len()
        ));
    };
    let u16_at = |at: usize| u16::from_le_bytes([info[at], info[at + 1]]);
    let (width, height, planes, bits_per_pixel, compression, colours_used) = if info_len == 12 {
        (
            i64::from(u16_at(4)),
            i64::from(u16_at(6)),
            u16_at(8),
            u16_at(10),
            0,
            0,
        )
    } else {
        let i32_at = |at: usize| i64::from(le32(&info[at..at + 4]) as i32);
        (
            i32_at(4),
            i32_at(8),
            u16_at(12),
            u16_at(14),
            le32(&info[16..20]),
            le32(&info[32..36]),
        )
    };
    Ok(Picture {
        info_len,
        pixel_offset: le32(&bytes[10..14]),
        width,
        height,
        planes,
        bits_per_pixel,
        compression,
        colours_used,
    })
}

/// Why no tool could show the picture, if it could not.
pub(super) fn unreadable(p: &Picture, file_len: usize) -> Option<String> {
    if p.planes != 1 {
        return Some(format!("it has {} colour planes; a bitmap has 1", p.planes));
    }
    if ![1, 4, 8, 16, 24, 32].contains(&p.bits_per_pixel) {
        return Some(format!(
            "it has {} bits per pixel, which no bitmap has",
            p.bits_per_pixel
        ));
    }
    if p.width <= 0 || p.height == 0 {
        return Some(format!("it is {} x {} pixels", p.width, p.height));
    }
    // Compressed pixel data has no length the headers fix. At most
    // 2^31 x 32 bits a row and 2^31 rows: u128 holds the product.
    let stored = if p.compression == 0 {
        let stride =
            (p.width.unsigned_abs() as u128 * u128::from(p.bits_per_pixel)).div_ceil(32) * 4;
        stride * u128::from(p.height.unsigned_abs())
    } else {
        0
    };
    let end = u128::from(p.pixel_offset) + stored;
    (end > file_len as u128).then(|| {
        format!("its pixels need {end} bytes, and the file has {file_len}: it is cut short")
    })
}

/// W402 for each way the picture is not the conventional one.
fn unexpected(p: &Picture) -> Vec<Diagnostic> {
    let (width, height) = (i64::from(super::WIDTH), i64::from(super::HEIGHT));
    let mut found = Vec::new();
    if (p.width, p.height.abs()) != (width, height) {
        found.push(format!(
            "the device symbol is {} x {} pixels, not {width} x {height}",
            p.width,
            p.height.abs()
        ));
    }
    if p.bits_per_pixel != 4 {
        found.push(format!(
            "the device symbol has {} bits per pixel, not 4 (16 colours)",
            p.bits_per_pixel
        ));
    }
    found
        .into_iter()
        .map(|message| {
            Diagnostic::warning("W402", message).help(
                "engineering tools show device symbols as 70 x 40 pixels in 16 colours (the size and depth Siemens' GSD files state for their own); draw it so, or let gsdc write it from a PNG (device.symbol)",
            )
        })
        .collect()
}

fn not_readable(why: String) -> Diagnostic {
    Diagnostic::error("E401", format!("not a whole Windows bitmap: {why}"))
        .help("an engineering tool cannot show it: save the symbol again as a Windows bitmap (BMP) of 70 x 40 pixels in 16 colours, or let gsdc write it from a PNG (device.symbol)")
}

fn le32(bytes: &[u8]) -> u32 {
    u32::from_le_bytes([bytes[0], bytes[1], bytes[2], bytes[3]])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn gsdcs_own() -> Vec<u8> {
        let png = include_bytes!("../../descriptions/symbols/md810dp.png");
        super::super::device_bitmap(png).unwrap().bmp
    }

    fn codes(bytes: &[u8]) -> Vec<&'static str> {
        check(bytes).iter().map(|d| d.code).collect()
    }

    #[test]
    fn the_bitmap_gsdc_writes_is_a_device_symbol_without_findings() {
        let bmp = gsdcs_own();
        assert!(is_bitmap(&bmp));
        assert!(check(&bmp).is_empty());
    }

    #[test]
    fn text_or_bytes_that_start_with_bm_are_no_bitmap() {
        assert!(!is_bitmap(
            b"BM is how a bitmap starts, and so does this line"
        ));
        assert!(!is_bitmap(b"BM"));
        assert!(!is_bitmap(b"#Profibus_DP"));
    }

    /// A 70 x 40 picture of 8 bits a pixel, rows padded to 72 bytes.
    fn eight_bit() -> Vec<u8> {
        let mut bmp = gsdcs_own();
        bmp[28] = 8;
        bmp.truncate(118);
        bmp.resize(118 + 72 * 40, 0);
        bmp
    }

    #[test]
    fn another_size_or_depth_is_a_warning_each() {
        assert_eq!(codes(&eight_bit()), ["W402"]);
        let mut wide = gsdcs_own();
        wide[18] = 35; // 35 x 40: half the rows' bytes, all there
        let d = check(&wide);
        assert_eq!(codes(&wide), ["W402"]);
        assert_eq!(
            d.iter().next().unwrap().message,
            "the device symbol is 35 x 40 pixels, not 70 x 40"
        );
        // Top-down rows (a negative height) are the same size.
        let mut top_down = gsdcs_own();
        top_down[22..26].copy_from_slice(&(-40i32).to_le_bytes());
        assert!(check(&top_down).is_empty());
    }

    #[test]
    fn a_bitmap_cut_short_or_impossible_is_an_error() {
        let bmp = gsdcs_own();
        let cut = &bmp[..bmp.len() - 1];
        let d = check(cut);
        assert_eq!(codes(cut), ["E401"]);
        assert!(
            d.iter().next().unwrap().message.contains("cut short"),
            "{d:?}"
        );
        assert_eq!(codes(&bmp[..30]), ["E401"], "headers cut short");
        assert_eq!(codes(&bmp[..16]), ["E401"], "no header size");
        let mut planes = bmp.clone();
        planes[26] = 2;
        assert_eq!(codes(&planes), ["E401"]);
        let mut bits = bmp.clone();
        bits[28] = 3;
        assert_eq!(codes(&bits), ["E401"]);
        let mut empty = bmp;
        empty[18..22].copy_from_slice(&0u32.to_le_bytes());
        assert_eq!(codes(&empty), ["E401"]);
    }
}
