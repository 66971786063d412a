//! The device symbol bitmap (src/symbol.rs), read back with a BMP reader
//! written from the format (Microsoft's BITMAPFILEHEADER/BITMAPINFOHEADER),
//! not from the writer's constants.

use super::{device_bitmap, SymbolError, HEIGHT, PALETTE, WIDTH};
use proptest::prelude::*;

const W: usize = 70;
const H: usize = 40;

const BLACK: [u8; 3] = [0, 0, 0];
const RED: [u8; 3] = [0xFF, 0, 0];
const LIME: [u8; 3] = [0, 0xFF, 0];
const BLUE: [u8; 3] = [0, 0, 0xFF];
const YELLOW: [u8; 3] = [0xFF, 0xFF, 0];
const WHITE: [u8; 3] = [0xFF, 0xFF, 0xFF];

// ---- reading a BMP back -------------------------------------------------

fn u16_at(bmp: &[u8], offset: usize) -> u16 {
    u16::from_le_bytes(bmp[offset..offset + 2].try_into().unwrap())
}

fn u32_at(bmp: &[u8], offset: usize) -> u32 {
    u32::from_le_bytes(bmp[offset..offset + 4].try_into().unwrap())
}

fn i32_at(bmp: &[u8], offset: usize) -> i32 {
    i32::from_le_bytes(bmp[offset..offset + 4].try_into().unwrap())
}

/// Bytes of a stored row of a 4-bit bitmap: padded to a multiple of 4.
fn stride(bmp: &[u8]) -> usize {
    let width = i32_at(bmp, 18) as usize;
    (width * 4).div_ceil(32) * 4
}

/// The colour table as RGB (stored as blue, green, red, reserved).
fn colour_table(bmp: &[u8]) -> Vec<[u8; 3]> {
    let start = 14 + u32_at(bmp, 14) as usize;
    let count = u32_at(bmp, 46) as usize;
    bmp[start..start + 4 * count]
        .chunks_exact(4)
        .map(|q| [q[2], q[1], q[0]])
        .collect()
}

/// The colour-table index of pixel (x, y), y counted from the top, of a
/// bottom-up 4-bit bitmap: the first of two pixels is the high nibble.
fn index_at(bmp: &[u8], x: usize, y: usize) -> u8 {
    let height = i32_at(bmp, 22);
    assert!(height > 0, "a bottom-up bitmap");
    let stored_row = height as usize - 1 - y;
    let byte = bmp[u32_at(bmp, 10) as usize + stored_row * stride(bmp) + x / 2];
    if x.is_multiple_of(2) {
        byte >> 4
    } else {
        byte & 0x0F
    }
}

/// Every pixel of a 4-bit bitmap as RGB, top row first.
fn bmp_pixels(bmp: &[u8]) -> Vec<[u8; 3]> {
    let table = colour_table(bmp);
    let (width, height) = (i32_at(bmp, 18) as usize, i32_at(bmp, 22) as usize);
    (0..height)
        .flat_map(|y| (0..width).map(move |x| (x, y)))
        .map(|(x, y)| table[usize::from(index_at(bmp, x, y))])
        .collect()
}

// ---- writing PNGs -------------------------------------------------------

fn png_of(
    width: u32,
    height: u32,
    colour: png::ColorType,
    depth: png::BitDepth,
    palette: Option<Vec<u8>>,
    samples: &[u8],
) -> Vec<u8> {
    let mut out = Vec::new();
    {
        let mut encoder = png::Encoder::new(&mut out, width, height);
        encoder.set_color(colour);
        encoder.set_depth(depth);
        if let Some(palette) = palette {
            encoder.set_palette(palette);
        }
        let mut writer = encoder.write_header().unwrap();
        writer.write_image_data(samples).unwrap();
    }
    out
}

fn rgb_png(width: u32, height: u32, pixels: &[[u8; 3]]) -> Vec<u8> {
    let samples: Vec<u8> = pixels.concat();
    png_of(
        width,
        height,
        png::ColorType::Rgb,
        png::BitDepth::Eight,
        None,
        &samples,
    )
}

/// A 70 x 40 picture: white, with a few marked pixels.
fn picture(marks: &[((usize, usize), [u8; 3])]) -> Vec<[u8; 3]> {
    let mut pixels = vec![WHITE; W * H];
    for &((x, y), colour) in marks {
        pixels[y * W + x] = colour;
    }
    pixels
}

fn convert(pixels: &[[u8; 3]]) -> super::DeviceBitmap {
    device_bitmap(&rgb_png(WIDTH, HEIGHT, pixels)).unwrap()
}

fn palette_index(colour: [u8; 3]) -> u8 {
    PALETTE.iter().position(|&c| c == colour).unwrap() as u8
}

// ---- the format ---------------------------------------------------------

#[test]
fn the_headers_are_those_of_a_70_by_40_4_bit_bitmap() {
    let bmp = convert(&picture(&[])).bmp;
    assert_eq!(&bmp[0..2], b"BM");
    assert_eq!(
        u32_at(&bmp, 2) as usize,
        bmp.len(),
        "bfSize is the file's length"
    );
    assert_eq!(u32_at(&bmp, 6), 0, "reserved");
    assert_eq!(
        u32_at(&bmp, 10),
        14 + 40 + 16 * 4,
        "bfOffBits: after the colour table"
    );
    assert_eq!(u32_at(&bmp, 14), 40, "biSize: BITMAPINFOHEADER");
    assert_eq!(i32_at(&bmp, 18), 70, "biWidth");
    assert_eq!(i32_at(&bmp, 22), 40, "biHeight, positive: bottom-up");
    assert_eq!(u16_at(&bmp, 26), 1, "biPlanes");
    assert_eq!(u16_at(&bmp, 28), 4, "biBitCount");
    assert_eq!(u32_at(&bmp, 30), 0, "biCompression: BI_RGB");
    assert_eq!(
        u32_at(&bmp, 34),
        36 * 40,
        "biSizeImage: 40 rows of 36 bytes"
    );
    assert_eq!(u32_at(&bmp, 46), 16, "biClrUsed");
    assert_eq!(u32_at(&bmp, 50), 16, "biClrImportant");
    assert_eq!(colour_table(&bmp), PALETTE);
    // The colour table's reserved bytes are zero.
    assert!((0..16).all(|i| bmp[54 + 4 * i + 3] == 0));
    assert_eq!(bmp.len(), 1558, "118 bytes of headers and 1440 of pixels");
}

#[test]
fn the_palette_is_the_windows_standard_16_colours() {
    let hex: Vec<String> = PALETTE
        .iter()
        .map(|[r, g, b]| format!("{r:02x}{g:02x}{b:02x}"))
        .collect();
    assert_eq!(
        hex.join(" "),
        "000000 800000 008000 808000 000080 800080 008080 c0c0c0 \
         808080 ff0000 00ff00 ffff00 0000ff ff00ff 00ffff ffffff"
    );
}

#[test]
fn rows_are_stored_bottom_up_two_pixels_a_byte_first_in_the_high_nibble() {
    let bmp = convert(&picture(&[
        ((0, 0), RED),
        ((1, 0), LIME),
        ((69, 0), BLUE),
        ((0, 39), BLACK),
        ((69, 39), YELLOW),
    ]))
    .bmp;
    let pixels = 118;
    // Stored row 0 is the picture's bottom row: black, then white.
    assert_eq!(bmp[pixels], 0x0F);
    // ... ending in white and yellow (11), then the padding byte.
    assert_eq!(bmp[pixels + 34], 0xFB);
    assert_eq!(bmp[pixels + 35], 0x00);
    // The last stored row is the picture's top row: red (9) and lime (10).
    let top = pixels + 39 * 36;
    assert_eq!(bmp[top], 0x9A);
    assert_eq!(bmp[top + 34], 0xFC, "white, then blue (12)");
    // Every row's 36th byte is padding.
    assert!((0..40).all(|row| bmp[pixels + row * 36 + 35] == 0));
}

// ---- colours ------------------------------------------------------------

#[test]
fn palette_colours_are_kept_and_others_take_the_nearest() {
    let mut marks: Vec<((usize, usize), [u8; 3])> = PALETTE
        .iter()
        .enumerate()
        .map(|(i, &colour)| ((i, 0), colour))
        .collect();
    // Off the palette: nearly red, dark grey, light grey, dark blue, and
    // (64, 0, 0), as far from black as from maroon.
    let off = [
        [250, 10, 10],
        [100, 100, 100],
        [200, 200, 200],
        [0, 0, 100],
        [64, 0, 0],
    ];
    marks.extend(off.iter().enumerate().map(|(i, &c)| ((i, 1), c)));
    let symbol = convert(&picture(&marks));
    for (i, &colour) in PALETTE.iter().enumerate() {
        assert_eq!(index_at(&symbol.bmp, i, 0), palette_index(colour));
    }
    let expected = [RED, [0x80; 3], [0xC0; 3], [0, 0, 0x80], BLACK];
    for (i, &colour) in expected.iter().enumerate() {
        assert_eq!(
            index_at(&symbol.bmp, i, 1),
            palette_index(colour),
            "pixel {i}"
        );
    }
    assert_eq!(symbol.approximated_pixels, off.len());
}

#[test]
fn transparent_pixels_are_composited_over_white() {
    let mut samples = vec![0xFF; W * H * 4];
    // (0, 0) fully transparent black; (1, 0) half-transparent black, 127
    // grey over white, nearest grey 0x80; (2, 0) opaque red.
    samples[..12].copy_from_slice(&[0, 0, 0, 0, 0, 0, 0, 128, 0xFF, 0, 0, 0xFF]);
    let png = png_of(
        70,
        40,
        png::ColorType::Rgba,
        png::BitDepth::Eight,
        None,
        &samples,
    );
    let symbol = device_bitmap(&png).unwrap();
    assert_eq!(index_at(&symbol.bmp, 0, 0), palette_index(WHITE));
    assert_eq!(index_at(&symbol.bmp, 1, 0), palette_index([0x80; 3]));
    assert_eq!(index_at(&symbol.bmp, 2, 0), palette_index(RED));
    assert_eq!(symbol.approximated_pixels, 1, "only the 127 grey");
}

#[test]
fn grey_pictures_are_read_as_grey_with_or_without_alpha() {
    let mut grey = vec![0xFF; W * H];
    grey[..4].copy_from_slice(&[0x00, 0x80, 0xC0, 0x90]);
    let png = png_of(
        70,
        40,
        png::ColorType::Grayscale,
        png::BitDepth::Eight,
        None,
        &grey,
    );
    let symbol = device_bitmap(&png).unwrap();
    let expected = [BLACK, [0x80; 3], [0xC0; 3], [0x80; 3]];
    for (x, &colour) in expected.iter().enumerate() {
        assert_eq!(
            index_at(&symbol.bmp, x, 0),
            palette_index(colour),
            "pixel {x}"
        );
    }
    assert_eq!(symbol.approximated_pixels, 1, "only 0x90");

    // Grey with alpha: transparent black is white, opaque black stays.
    let mut grey_alpha = vec![0xFF; W * H * 2];
    grey_alpha[..4].copy_from_slice(&[0x00, 0x00, 0x00, 0xFF]);
    let png = png_of(
        70,
        40,
        png::ColorType::GrayscaleAlpha,
        png::BitDepth::Eight,
        None,
        &grey_alpha,
    );
    let symbol = device_bitmap(&png).unwrap();
    assert_eq!(index_at(&symbol.bmp, 0, 0), palette_index(WHITE));
    assert_eq!(index_at(&symbol.bmp, 1, 0), palette_index(BLACK));
}

// ---- refusals -----------------------------------------------------------

#[test]
fn a_picture_of_another_size_is_refused_with_its_size() {
    for (width, height) in [(71, 40), (70, 39), (140, 80), (1, 1)] {
        let pixels = vec![WHITE; (width * height) as usize];
        let error = device_bitmap(&rgb_png(width, height, &pixels)).unwrap_err();
        assert_eq!(error, SymbolError::WrongSize { width, height });
        assert_eq!(
            error.message(),
            format!("the device symbol is {width} x {height} pixels, not 70 x 40")
        );
        assert!(error.help().contains("70 x 40"), "{}", error.help());
        assert!(error.help().contains("does not scale"), "{}", error.help());
    }
}

/// CRC-32 of PNG chunks (ISO 3309, as the PNG specification gives it).
fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = !0u32;
    for &byte in bytes {
        crc ^= u32::from(byte);
        for _ in 0..8 {
            crc = if crc & 1 == 1 {
                (crc >> 1) ^ 0xEDB8_8320
            } else {
                crc >> 1
            };
        }
    }
    !crc
}

fn chunk(kind: &[u8; 4], data: &[u8]) -> Vec<u8> {
    let body = [kind.as_slice(), data].concat();
    [
        &(data.len() as u32).to_be_bytes()[..],
        &body,
        &crc32(&body).to_be_bytes(),
    ]
    .concat()
}

#[test]
fn the_size_is_refused_from_the_header_before_any_pixel_is_read() {
    // A header claiming 100000 x 100000 pixels and no image data at all: the
    // size is the answer, not a missing IDAT or a 40 GB allocation.
    let mut header = Vec::new();
    header.extend_from_slice(&100_000u32.to_be_bytes());
    header.extend_from_slice(&100_000u32.to_be_bytes());
    header.extend_from_slice(&[8, 2, 0, 0, 0]); // 8-bit RGB
    let png = [
        &b"\x89PNG\r\n\x1a\n"[..],
        &chunk(b"IHDR", &header),
        &chunk(b"IEND", &[]),
    ]
    .concat();
    assert_eq!(
        device_bitmap(&png).unwrap_err(),
        SymbolError::WrongSize {
            width: 100_000,
            height: 100_000
        }
    );
}

fn assert_undecodable(bytes: &[u8], what: &str) {
    let error = device_bitmap(bytes).unwrap_err();
    assert!(
        matches!(error, SymbolError::Undecodable { .. }),
        "{what}: {error:?}"
    );
    assert!(
        error
            .message()
            .starts_with("the device symbol is not a readable PNG image: "),
        "{what}: {}",
        error.message()
    );
    assert!(
        error.help().contains("PNG file of 70 x 40 pixels"),
        "{what}"
    );
}

#[test]
fn what_is_not_a_readable_png_is_refused() {
    let good = rgb_png(70, 40, &picture(&[((5, 5), RED)]));
    assert_undecodable(b"", "empty");
    assert_undecodable(b"GIF89a\x46\x00\x28\x00", "a GIF");
    assert_undecodable(&good[..good.len() / 2], "truncated");
    let idat = good.windows(4).position(|w| w == b"IDAT").unwrap();
    let mut bad_checksum = good.clone();
    bad_checksum[idat + 6] ^= 0xFF;
    assert_undecodable(&bad_checksum, "a byte of the image data changed");
    // The header chunk's CRC: after the signature (8), length (4), type (4)
    // and 13 bytes of data.
    let mut bad_crc = good.clone();
    bad_crc[29] ^= 0xFF;
    assert_undecodable(&bad_crc, "a wrong header checksum");
}

// ---- determinism --------------------------------------------------------

#[test]
fn the_bitmap_depends_on_the_pixels_only() {
    let pixels = picture(&[((0, 0), RED), ((30, 20), BLUE), ((69, 39), YELLOW)]);
    let reference = convert(&pixels);
    assert_eq!(convert(&pixels), reference, "the same input twice");

    let rgba: Vec<u8> = pixels
        .iter()
        .flat_map(|&[r, g, b]| [r, g, b, 0xFF])
        .collect();
    let rgb16: Vec<u8> = pixels.concat().iter().flat_map(|&v| [v, v]).collect();
    let indexes: Vec<u8> = pixels.iter().map(|&c| palette_index(c)).collect();
    let encodings = [
        (
            "RGBA",
            png_of(
                70,
                40,
                png::ColorType::Rgba,
                png::BitDepth::Eight,
                None,
                &rgba,
            ),
        ),
        (
            "16-bit RGB",
            png_of(
                70,
                40,
                png::ColorType::Rgb,
                png::BitDepth::Sixteen,
                None,
                &rgb16,
            ),
        ),
        (
            "palette",
            png_of(
                70,
                40,
                png::ColorType::Indexed,
                png::BitDepth::Eight,
                Some(PALETTE.concat()),
                &indexes,
            ),
        ),
        ("with a text chunk", {
            let mut out = Vec::new();
            let mut encoder = png::Encoder::new(&mut out, 70, 40);
            encoder.set_color(png::ColorType::Rgb);
            encoder
                .add_text_chunk("Creation Time".into(), "today".into())
                .unwrap();
            encoder
                .write_header()
                .unwrap()
                .write_image_data(&pixels.concat())
                .unwrap();
            out
        }),
    ];
    for (what, png) in encodings {
        assert_eq!(device_bitmap(&png).unwrap(), reference, "{what}");
    }
}

// ---- the shipped symbols ------------------------------------------------

pub(super) fn png_pixels(png: &[u8]) -> Vec<[u8; 3]> {
    let mut decoder = png::Decoder::new(std::io::Cursor::new(png));
    decoder.set_transformations(png::Transformations::normalize_to_color8());
    let mut reader = decoder.read_info().unwrap();
    assert_eq!(reader.output_color_type().0, png::ColorType::Rgb);
    let mut samples = vec![0; reader.output_buffer_size().unwrap()];
    reader.next_frame(&mut samples).unwrap();
    samples
        .chunks_exact(3)
        .map(|s| [s[0], s[1], s[2]])
        .collect()
}

/// Every shipped symbol converts without changing a pixel. The bitmaps,
/// turned back into PNGs, are left in the target directory for a look
/// (`target/tmp/symbols/`).
#[test]
fn the_shipped_symbols_convert_pixel_for_pixel() {
    let scratch = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target/tmp/symbols");
    std::fs::create_dir_all(&scratch).unwrap();
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("descriptions/symbols");
    for name in ["md810dp", "9kdp1", "mv810-pnet02"] {
        let png = std::fs::read(dir.join(format!("{name}.png"))).unwrap();
        let symbol = device_bitmap(&png).unwrap();
        assert_eq!(symbol.bmp.len(), 1558, "{name}");
        assert_eq!(
            symbol.approximated_pixels, 0,
            "{name} is drawn in the palette"
        );
        let pixels = bmp_pixels(&symbol.bmp);
        assert_eq!(pixels, png_pixels(&png), "{name}");
        std::fs::write(scratch.join(format!("{name}.bmp")), &symbol.bmp).unwrap();
        std::fs::write(
            scratch.join(format!("{name}.from-bmp.png")),
            rgb_png(70, 40, &pixels),
        )
        .unwrap();
    }
}

// ---- damaged input ------------------------------------------------------

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, failure_persistence: None, ..ProptestConfig::default() })]

    /// A shipped symbol with bytes overwritten anywhere (header, palette,
    /// image data, checksums) gives a bitmap or an error, never a panic, and
    /// a bitmap is always a whole one.
    #[test]
    fn damaged_pngs_give_a_whole_bitmap_or_an_error(
        changes in proptest::collection::vec((any::<prop::sample::Index>(), any::<u8>()), 1..8)
    ) {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("descriptions/symbols");
        let mut png = std::fs::read(dir.join("mv810-pnet02.png")).unwrap();
        for (at, byte) in changes {
            let at = at.index(png.len());
            png[at] = byte;
        }
        if let Ok(symbol) = device_bitmap(&png) {
            prop_assert_eq!(symbol.bmp.len(), 1558);
        }
    }

    /// The shipped image data under a header that may not fit it (another
    /// colour type, bit depth or interlacing), its checksum right: the
    /// decoder's checks, not a panic, answer.
    #[test]
    fn a_header_that_does_not_fit_the_data_gives_an_error_not_a_panic(
        bit_depth in prop::sample::select(vec![1u8, 2, 4, 8, 16]),
        colour_type in prop::sample::select(vec![0u8, 2, 3, 4, 6]),
        interlace in 0u8..2,
    ) {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("descriptions/symbols");
        let original = std::fs::read(dir.join("md810dp.png")).unwrap();
        let mut header = Vec::new();
        header.extend_from_slice(&70u32.to_be_bytes());
        header.extend_from_slice(&40u32.to_be_bytes());
        header.extend_from_slice(&[bit_depth, colour_type, 0, 0, interlace]);
        // Signature and the 25-byte IHDR chunk replaced, the rest kept.
        let png = [&original[..8], &chunk(b"IHDR", &header), &original[33..]].concat();
        if let Ok(symbol) = device_bitmap(&png) {
            prop_assert_eq!(symbol.bmp.len(), 1558);
        }
    }
}
