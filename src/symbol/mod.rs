//! Device symbols: the picture of the card that engineering tools show in
//! their hardware catalog, named by `Bitmap_Device` in a GSD and by a
//! `GraphicItem` with a `DeviceSymbol` reference in a GSDML.
//!
//! A description gives the symbol as a PNG; [`device_bitmap`] turns it into
//! the bitmap the conventions expect. Pure: PNG bytes in, BMP bytes out, no
//! file, no clock, so the same PNG gives the same bytes on any machine.
//!
//! # The bitmap
//!
//! 70 x 40 pixels, a Windows bitmap (BITMAPFILEHEADER, 40-byte
//! BITMAPINFOHEADER), 4 bits per pixel with the 16 colours of [`PALETTE`],
//! uncompressed, rows bottom-up and padded to 4 bytes: 1558 bytes. That is
//! the size and depth a Siemens GSD states for its own symbol ("70x40 pixels
//! 16 colors"), the format of most bitmaps STEP 7 installs for GSD files and
//! of the one ABB ships beside its FENA drive GSDML, palette included. One
//! file serves both the GSD and the GSDML.
//!
//! # Images of another size are refused
//!
//! The PNG must be 70 x 40 pixels; any other size is a [`SymbolError::WrongSize`].
//! Scaling a picture down to 70 x 40 and 16 colours loses detail in ways its
//! author would first see in the engineering tool; refusing keeps what ships
//! exactly what was drawn, pixel for pixel. The size is checked from the PNG
//! header, before any pixel is decoded.
//!
//! # Colour reduction
//!
//! Deterministic, without dithering:
//! 1. samples are 8-bit (16-bit samples keep their high byte; palette and
//!    grey images are expanded to RGB; gamma and colour-profile chunks are
//!    ignored, samples are taken as sRGB);
//! 2. a pixel that is not opaque is composited over white,
//!    `c' = (c * a + 255 * (255 - a) + 127) / 255` in integers (white because
//!    the tools draw their catalogs on a light background; the description's
//!    own choice, not a convention);
//! 3. the pixel takes the [`PALETTE`] entry at the least squared distance in
//!    RGB, the lowest index on a tie.
//!
//! A picture drawn in the palette's colours converts without change;
//! [`DeviceBitmap::approximated_pixels`] counts the pixels that did not, so a
//! caller can say so.

pub mod check;
mod from_bmp;

pub use from_bmp::png_of_bitmap;

use std::fmt;
use std::io::Cursor;

/// Width of a device symbol, in pixels.
pub const WIDTH: u32 = 70;
/// Height of a device symbol, in pixels.
pub const HEIGHT: u32 = 40;

/// The colour table, as RGB: the Windows standard 16 colours in their usual
/// order (the palette of ABB's `GSDML-001A-0003-FENA.bmp` and of many STEP 7
/// catalog bitmaps).
pub const PALETTE: [[u8; 3]; 16] = [
    [0x00, 0x00, 0x00], // black
    [0x80, 0x00, 0x00], // maroon
    [0x00, 0x80, 0x00], // green
    [0x80, 0x80, 0x00], // olive
    [0x00, 0x00, 0x80], // navy
    [0x80, 0x00, 0x80], // purple
    [0x00, 0x80, 0x80], // teal
    [0xC0, 0xC0, 0xC0], // silver
    [0x80, 0x80, 0x80], // grey
    [0xFF, 0x00, 0x00], // red
    [0x00, 0xFF, 0x00], // lime
    [0xFF, 0xFF, 0x00], // yellow
    [0x00, 0x00, 0xFF], // blue
    [0xFF, 0x00, 0xFF], // fuchsia
    [0x00, 0xFF, 0xFF], // aqua
    [0xFF, 0xFF, 0xFF], // white
];

const FILE_HEADER_LEN: u32 = 14;
const INFO_HEADER_LEN: u32 = 40;
const BITS_PER_PIXEL: u16 = 4;
/// Bytes of one stored row: 70 pixels of 4 bits are 35 bytes, padded to a
/// multiple of 4.
const ROW_STRIDE: u32 = (WIDTH * BITS_PER_PIXEL as u32).div_ceil(32) * 4;
const PIXEL_OFFSET: u32 = FILE_HEADER_LEN + INFO_HEADER_LEN + 4 * PALETTE.len() as u32;
const PIXEL_BYTES: u32 = ROW_STRIDE * HEIGHT;
/// 72 dots per inch, as ABB's bitmap states it; tools ignore it.
const PIXELS_PER_METRE: u32 = 2835;
/// `biCompression`: none.
const BI_RGB: u32 = 0;

/// A device symbol ready to be written beside the GSD and the GSDML.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DeviceBitmap {
    /// The whole `.bmp` file.
    pub bmp: Vec<u8>,
    /// How many pixels were not exactly a palette colour (after compositing)
    /// and took the nearest one.
    pub approximated_pixels: usize,
}

/// Why a PNG does not make a device symbol. [`SymbolError::message`] and
/// [`SymbolError::help`] are the texts of the diagnostic the caller reports,
/// with the file's name and place added.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum SymbolError {
    /// Not a PNG the decoder can read: another format, truncated, a bad
    /// checksum. `reason` is the decoder's own words.
    Undecodable { reason: String },
    /// A readable PNG of another size than [`WIDTH`] x [`HEIGHT`].
    WrongSize { width: u32, height: u32 },
}

impl SymbolError {
    pub fn message(&self) -> String {
        match self {
            SymbolError::Undecodable { reason } => {
                format!("the device symbol is not a readable PNG image: {reason}")
            }
            SymbolError::WrongSize { width, height } => {
                format!("the device symbol is {width} x {height} pixels, not {WIDTH} x {HEIGHT}")
            }
        }
    }

    pub fn help(&self) -> String {
        match self {
            SymbolError::Undecodable { .. } => format!(
                "save the symbol as a PNG file of {WIDTH} x {HEIGHT} pixels \
                 (a file renamed to .png is not one)"
            ),
            SymbolError::WrongSize { .. } => format!(
                "engineering tools show the device symbol at {WIDTH} x {HEIGHT} pixels; \
                 draw it at that size (gsdc does not scale it)"
            ),
        }
    }
}

impl fmt::Display for SymbolError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message())
    }
}

impl std::error::Error for SymbolError {}

/// The device symbol bitmap of a PNG image of [`WIDTH`] x [`HEIGHT`] pixels.
pub fn device_bitmap(png: &[u8]) -> Result<DeviceBitmap, SymbolError> {
    let pixels = decode_opaque_rgb(png)?;
    let approximated_pixels = pixels
        .iter()
        .filter(|pixel| !PALETTE.contains(pixel))
        .count();
    let indexes: Vec<u8> = pixels
        .iter()
        .map(|&rgb| nearest_palette_index(rgb))
        .collect();
    Ok(DeviceBitmap {
        bmp: encode_bmp(&indexes),
        approximated_pixels,
    })
}

/// The PNG's pixels, top row first, as opaque RGB (see the module doc).
fn decode_opaque_rgb(png: &[u8]) -> Result<Vec<[u8; 3]>, SymbolError> {
    let undecodable = |error: png::DecodingError| SymbolError::Undecodable {
        reason: error.to_string(),
    };
    let mut decoder = png::Decoder::new(Cursor::new(png));
    decoder.set_transformations(png::Transformations::normalize_to_color8());
    let (width, height) = decoder.read_header_info().map_err(undecodable)?.size();
    if (width, height) != (WIDTH, HEIGHT) {
        return Err(SymbolError::WrongSize { width, height });
    }
    let mut reader = decoder.read_info().map_err(undecodable)?;
    let (color_type, _) = reader.output_color_type();
    // 70 x 40 pixels of at most 4 bytes: the size always fits.
    let mut samples = vec![0; reader.output_buffer_size().unwrap_or_default()];
    let frame = reader.next_frame(&mut samples).map_err(undecodable)?;
    let samples = &samples[..frame.buffer_size()];
    Ok(match color_type {
        png::ColorType::Grayscale => samples.iter().map(|&v| [v, v, v]).collect(),
        png::ColorType::GrayscaleAlpha => samples
            .chunks_exact(2)
            .map(|ga| over_white([ga[0], ga[0], ga[0]], ga[1]))
            .collect(),
        png::ColorType::Rgb => samples
            .chunks_exact(3)
            .map(|rgb| [rgb[0], rgb[1], rgb[2]])
            .collect(),
        png::ColorType::Rgba => samples
            .chunks_exact(4)
            .map(|rgba| over_white([rgba[0], rgba[1], rgba[2]], rgba[3]))
            .collect(),
        // Expanded to RGB or RGBA by the transformation set above.
        png::ColorType::Indexed => unreachable!("palette PNGs are expanded on decoding"),
    })
}

fn over_white(rgb: [u8; 3], alpha: u8) -> [u8; 3] {
    let alpha = u32::from(alpha);
    rgb.map(|c| {
        let blended = (u32::from(c) * alpha + 255 * (255 - alpha) + 127) / 255;
        // At most (255 * 255 + 127) / 255 = 255.
        blended as u8
    })
}

/// The index of the palette colour nearest to `rgb`; the lowest on a tie.
fn nearest_palette_index(rgb: [u8; 3]) -> u8 {
    // A drawing in the palette's own colours (the usual case) needs no
    // distances.
    if let Some(exact) = PALETTE.iter().position(|entry| *entry == rgb) {
        return exact as u8;
    }
    let distance = |entry: &[u8; 3]| -> u32 {
        entry
            .iter()
            .zip(rgb)
            .map(|(&a, b)| u32::from(a.abs_diff(b)).pow(2))
            .sum()
    };
    // `min_by_key` keeps the first of equal minima: the lowest index.
    let (index, _) = PALETTE
        .iter()
        .enumerate()
        .min_by_key(|(_, entry)| distance(entry))
        .expect("the palette is not empty");
    index as u8
}

/// The BMP file of `indexes`, one palette index per pixel, top row first.
fn encode_bmp(indexes: &[u8]) -> Vec<u8> {
    let file_len = PIXEL_OFFSET + PIXEL_BYTES;
    let mut bmp = Vec::with_capacity(file_len as usize);
    // BITMAPFILEHEADER
    bmp.extend_from_slice(b"BM");
    bmp.extend_from_slice(&file_len.to_le_bytes());
    bmp.extend_from_slice(&[0; 4]); // reserved
    bmp.extend_from_slice(&PIXEL_OFFSET.to_le_bytes());
    // BITMAPINFOHEADER
    bmp.extend_from_slice(&INFO_HEADER_LEN.to_le_bytes());
    bmp.extend_from_slice(&WIDTH.to_le_bytes());
    // A positive height: rows are stored bottom-up.
    bmp.extend_from_slice(&HEIGHT.to_le_bytes());
    bmp.extend_from_slice(&1u16.to_le_bytes()); // planes
    bmp.extend_from_slice(&BITS_PER_PIXEL.to_le_bytes());
    bmp.extend_from_slice(&BI_RGB.to_le_bytes());
    bmp.extend_from_slice(&PIXEL_BYTES.to_le_bytes());
    bmp.extend_from_slice(&PIXELS_PER_METRE.to_le_bytes());
    bmp.extend_from_slice(&PIXELS_PER_METRE.to_le_bytes());
    let colours = PALETTE.len() as u32;
    bmp.extend_from_slice(&colours.to_le_bytes()); // colours used
    bmp.extend_from_slice(&colours.to_le_bytes()); // colours important
                                                   // The colour table: RGBQUAD is blue, green, red, reserved.
    for [red, green, blue] in PALETTE {
        bmp.extend_from_slice(&[blue, green, red, 0]);
    }
    for row in indexes.chunks_exact(WIDTH as usize).rev() {
        let start = bmp.len();
        // The first of two pixels in the high nibble.
        bmp.extend(
            row.chunks(2)
                .map(|pair| pair[0] << 4 | pair.get(1).unwrap_or(&0)),
        );
        bmp.resize(start + ROW_STRIDE as usize, 0);
    }
    bmp
}

/// The bitmap read back with a BMP reader written from the format.
#[cfg(test)]
mod bmp_tests;

#[cfg(test)]
mod tests {
    use super::*;

    // The palette mapping and the file layout are tested through the public
    // API in bmp_tests.rs; this is the arithmetic a picture cannot show.
    #[test]
    fn compositing_over_white_rounds_to_the_nearest_integer() {
        assert_eq!(over_white([0, 0, 0], 0), [255, 255, 255]);
        assert_eq!(over_white([12, 34, 56], 255), [12, 34, 56]);
        // 255 * 127 / 255 = 127; 200 * 100 / 255 + 255 * 155 / 255 = 233.4.
        assert_eq!(over_white([0, 0, 0], 128), [127, 127, 127]);
        assert_eq!(over_white([200, 200, 200], 100), [233, 233, 233]);
    }
}
