//! A device symbol's bitmap back to a PNG: what `gsdc import` writes beside
//! the description for a GSD's `Bitmap_Device` (and a GSDML's
//! `GraphicItem` can use). Pure: BMP bytes in, PNG bytes out.
//!
//! Reads the uncompressed Windows bitmaps device symbols are: 1, 4 or 8 bits
//! a pixel through the colour table, 24 or 32 bits a pixel as blue, green,
//! red (the fourth byte of 32 is not alpha in a BITMAPINFOHEADER bitmap and
//! is ignored), rows bottom-up or top-down. Any size: the caller decides
//! what to do with a picture of another size than [`super::WIDTH`] x
//! [`super::HEIGHT`]. The PNG is 8-bit RGB, so [`super::device_bitmap`] of
//! it gives back, for a bitmap gsdc wrote, the same bytes.

use super::check::{picture, unreadable, Picture};

/// A bitmap converted: the PNG, and the picture's size.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SymbolPng {
    pub png: Vec<u8>,
    pub width: u32,
    pub height: u32,
}

/// The PNG of the Windows bitmap `bmp`, or why it cannot be read.
pub fn png_of_bitmap(bmp: &[u8]) -> Result<SymbolPng, String> {
    if !super::check::is_bitmap(bmp) {
        return Err("it does not start as a Windows bitmap (`BM` and a header size)".into());
    }
    let p = picture(bmp)?;
    if let Some(why) = unreadable(&p, bmp.len()) {
        return Err(why);
    }
    if p.compression != 0 {
        return Err(format!(
            "it is compressed (biCompression {}); gsdc reads uncompressed bitmaps",
            p.compression
        ));
    }
    let table = colour_table(bmp, &p)?;
    let pixels = pixels(bmp, &p, &table)?;
    // `unreadable` keeps both within the file's size, which is a usize.
    let (width, height) = (p.width as u32, p.height.unsigned_abs() as u32);
    Ok(SymbolPng {
        png: encode_png(width, height, &pixels),
        width,
        height,
    })
}

/// The colour table as RGB: after the info header, 4 bytes an entry (3 in
/// OS/2's 12-byte header), as blue, green, red.
fn colour_table(bmp: &[u8], p: &Picture) -> Result<Vec<[u8; 3]>, String> {
    if p.bits_per_pixel > 8 {
        return Ok(Vec::new());
    }
    let entry = if p.info_len == 12 { 3 } else { 4 };
    let all = 1usize << p.bits_per_pixel;
    let count = match p.colours_used as usize {
        0 => all,
        n => n.min(all),
    };
    let start = 14 + p.info_len as usize;
    let table = bmp
        .get(start..start + entry * count)
        .ok_or_else(|| format!("its colour table of {count} colours is cut short"))?;
    Ok(table
        .chunks_exact(entry)
        .map(|bgr| [bgr[2], bgr[1], bgr[0]])
        .collect())
}

/// Every pixel as RGB, top row first.
fn pixels(bmp: &[u8], p: &Picture, table: &[[u8; 3]]) -> Result<Vec<[u8; 3]>, String> {
    let bits = usize::from(p.bits_per_pixel);
    if ![1, 4, 8, 24, 32].contains(&bits) {
        return Err(format!(
            "it has {bits} bits per pixel; gsdc reads 1, 4, 8, 24 and 32"
        ));
    }
    let width = p.width as usize;
    let height = p.height.unsigned_abs() as usize;
    let stride = (width * bits).div_ceil(32) * 4;
    let mut out = Vec::with_capacity(width * height);
    for y in 0..height {
        // A positive height stores the bottom row first.
        let stored = if p.height > 0 { height - 1 - y } else { y };
        let start = p.pixel_offset as usize + stored * stride;
        let row = &bmp[start..start + stride];
        for x in 0..width {
            out.push(pixel(row, x, bits, table)?);
        }
    }
    Ok(out)
}

fn pixel(row: &[u8], x: usize, bits: usize, table: &[[u8; 3]]) -> Result<[u8; 3], String> {
    if bits >= 24 {
        let at = x * bits / 8;
        return Ok([row[at + 2], row[at + 1], row[at]]);
    }
    let bit = x * bits;
    // The leftmost pixel in the byte's highest bits.
    let shift = 8 - bits - bit % 8;
    let index = usize::from(row[bit / 8] >> shift) & ((1 << bits) - 1);
    table.get(index).copied().ok_or_else(|| {
        format!(
            "a pixel takes colour {index} of a colour table of {}",
            table.len()
        )
    })
}

/// An 8-bit RGB PNG of `pixels`, top row first: the same bytes for the
/// same pixels (no time chunk, the encoder's fixed defaults).
fn encode_png(width: u32, height: u32, pixels: &[[u8; 3]]) -> Vec<u8> {
    let mut png = Vec::new();
    let mut encoder = png::Encoder::new(&mut png, width, height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let samples: Vec<u8> = pixels.iter().flatten().copied().collect();
    // Writing to a Vec fails only on a size the header does not fit, and
    // the samples are width x height pixels of 3 bytes.
    let mut writer = encoder
        .write_header()
        .expect("a PNG header of a bitmap's size");
    writer
        .write_image_data(&samples)
        .expect("the samples of width x height pixels");
    writer.finish().expect("a PNG written to memory");
    png
}

#[cfg(test)]
mod tests {
    use super::*;

    fn gsdcs_own() -> Vec<u8> {
        let png = include_bytes!("../../descriptions/symbols/md810dp.png");
        super::super::device_bitmap(png).unwrap().bmp
    }

    #[test]
    fn gsdcs_bitmap_comes_back_as_the_same_bytes() {
        for png in [
            &include_bytes!("../../descriptions/symbols/md810dp.png")[..],
            &include_bytes!("../../descriptions/symbols/9kdp1.png")[..],
            &include_bytes!("../../descriptions/symbols/mv810-pnet02.png")[..],
        ] {
            let bmp = super::super::device_bitmap(png).unwrap().bmp;
            let back = png_of_bitmap(&bmp).unwrap();
            assert_eq!((back.width, back.height), (70, 40));
            let rebuilt = super::super::device_bitmap(&back.png).unwrap();
            assert_eq!(rebuilt.approximated_pixels, 0);
            assert_eq!(rebuilt.bmp, bmp);
        }
    }

    use super::super::bmp_tests::png_pixels as rgb;

    /// A 3 x 2 bitmap of `bits` per pixel, rows as stored, with a
    /// BITMAPINFOHEADER and `table` (blue, green, red, 0 each).
    fn small(bits: u16, height: i32, table: &[[u8; 4]], rows: &[&[u8]]) -> Vec<u8> {
        let offset = 14 + 40 + 4 * table.len() as u32;
        let mut bmp = b"BM".to_vec();
        let pixel_bytes: usize = rows.iter().map(|r| r.len()).sum();
        bmp.extend_from_slice(&(offset + pixel_bytes as u32).to_le_bytes());
        bmp.extend_from_slice(&[0; 4]);
        bmp.extend_from_slice(&offset.to_le_bytes());
        bmp.extend_from_slice(&40u32.to_le_bytes());
        bmp.extend_from_slice(&3i32.to_le_bytes());
        bmp.extend_from_slice(&height.to_le_bytes());
        bmp.extend_from_slice(&1u16.to_le_bytes());
        bmp.extend_from_slice(&bits.to_le_bytes());
        bmp.extend_from_slice(&[0; 16]); // compression, size, resolution
        bmp.extend_from_slice(&(table.len() as u32).to_le_bytes());
        bmp.extend_from_slice(&[0; 4]);
        bmp.extend(table.iter().flatten());
        bmp.extend(rows.iter().copied().flatten());
        bmp
    }

    const RED: [u8; 3] = [0xFF, 0, 0];
    const BLUE: [u8; 3] = [0, 0, 0xFF];
    const WHITE: [u8; 3] = [0xFF, 0xFF, 0xFF];

    #[test]
    fn each_depth_and_row_order_gives_the_pixels_top_row_first() {
        // Colour table: 0 red, 1 blue, 2 white (stored blue, green, red).
        let table = [[0, 0, 0xFF, 0], [0xFF, 0, 0, 0], [0xFF, 0xFF, 0xFF, 0]];
        let top = [RED, BLUE, WHITE];
        let bottom = [WHITE, WHITE, RED];
        let expected: Vec<[u8; 3]> = top.iter().chain(&bottom).copied().collect();
        // 8 bits: bottom row stored first, rows padded to 4 bytes.
        let eight = small(8, 2, &table, &[&[2, 2, 0, 0], &[0, 1, 2, 0]]);
        assert_eq!(rgb(&png_of_bitmap(&eight).unwrap().png), expected);
        // 4 bits: the first pixel in the high nibble; top-down (height -2).
        let four = small(4, -2, &table, &[&[0x01, 0x20, 0, 0], &[0x22, 0x00, 0, 0]]);
        assert_eq!(rgb(&png_of_bitmap(&four).unwrap().png), expected);
        // 1 bit: two colours, the first pixel in the highest bit.
        let one = small(
            1,
            2,
            &table[..2],
            &[&[0b0010_0000, 0, 0, 0], &[0b0100_0000, 0, 0, 0]],
        );
        let two_colours = [RED, BLUE, RED, RED, RED, BLUE];
        assert_eq!(rgb(&png_of_bitmap(&one).unwrap().png), two_colours);
        // 24 bits: blue, green, red a pixel.
        let bgr = |[r, g, b]: [u8; 3]| [b, g, r];
        let row = |pixels: [[u8; 3]; 3]| -> Vec<u8> {
            let mut r: Vec<u8> = pixels.into_iter().flat_map(bgr).collect();
            r.resize(12, 0);
            r
        };
        let true_colour = small(24, 2, &[], &[&row(bottom), &row(top)]);
        assert_eq!(rgb(&png_of_bitmap(&true_colour).unwrap().png), expected);
    }

    #[test]
    fn what_cannot_be_read_says_why() {
        let bmp = gsdcs_own();
        assert!(png_of_bitmap(b"#Profibus_DP")
            .unwrap_err()
            .contains("Windows bitmap"));
        assert!(png_of_bitmap(&bmp[..bmp.len() - 1])
            .unwrap_err()
            .contains("cut short"));
        let mut compressed = bmp.clone();
        compressed[30] = 2; // BI_RLE4
        assert!(png_of_bitmap(&compressed)
            .unwrap_err()
            .contains("compressed"));
        let mut sixteen = bmp.clone();
        sixteen[28] = 16;
        sixteen.resize(118 + 140 * 40, 0);
        assert!(png_of_bitmap(&sixteen).unwrap_err().contains("16 bits"));
        let table = [[0, 0, 0xFF, 0]];
        let beyond = small(8, 1, &table, &[&[0, 1, 0, 0]]);
        assert!(png_of_bitmap(&beyond).unwrap_err().contains("colour 1"));
    }
}
