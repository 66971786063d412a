//! The device symbol a description names reaches both device files: the
//! bitmap beside the GSD (`Bitmap_Device`) and beside the GSDML (a
//! `GraphicsList` item the DAP refers to as its `DeviceSymbol`), the same
//! bytes each time, the GSD read by gsd-parser and the GSDML valid against
//! the PI schema.

use crate::support::{self, descriptions, xsd};
use gsdc::{Artifact, ArtifactKind};
use std::path::Path;

fn compile(path: &Path) -> Vec<Artifact> {
    let loaded = gsdc::build::load_file(path, "with-symbol").unwrap();
    let ir = loaded
        .ir
        .unwrap_or_else(|| panic!("{:?}", loaded.findings.diagnostics));
    gsdc::compile(&ir).unwrap()
}

fn text(files: &[Artifact], kind: ArtifactKind) -> String {
    descriptions::one(files.to_vec(), kind).1
}

#[test]
fn the_symbol_is_beside_the_gsd_and_the_gsdml() {
    // md810dp.toml names symbols/md810dp.png.
    let path = support::checkout("descriptions/md810dp.toml");
    let files = compile(&path);
    let bitmaps: Vec<(&str, &[u8])> = files
        .iter()
        .filter(|f| f.kind == ArtifactKind::DeviceSymbol)
        .map(|f| (f.file_name.as_str(), f.contents.as_slice()))
        .collect();
    let names: Vec<&str> = bitmaps.iter().map(|(name, _)| *name).collect();
    assert_eq!(names, ["MD810DP.bmp", "GSDML-0A11-0810-MD810.bmp"]);
    // One bitmap for both: a BMP of 70 x 40 pixels, 4 bits each (the
    // conversion itself is tested in src/symbol/bmp_tests.rs).
    let bmp = bitmaps[0].1;
    assert_eq!(bitmaps[1].1, bmp);
    let u32_at = |at: usize| u32::from_le_bytes(bmp[at..at + 4].try_into().unwrap());
    assert_eq!(&bmp[..2], b"BM");
    assert_eq!((u32_at(18), u32_at(22), bmp[28]), (70, 40, 4));

    let gsd = text(&files, ArtifactKind::Gsd);
    assert!(
        gsd.contains("Bitmap_Device               = \"MD810DP\"\r\n"),
        "{gsd}"
    );
    let parsed = gsd_parser::parser::parse(Path::new("MD810DP.GSD"), &gsd).unwrap();
    assert_eq!(parsed.ident_number, 0x0810);

    let gsdml = text(&files, ArtifactKind::Gsdml);
    assert!(gsdml.contains(
        "<GraphicItemRef Type=\"DeviceSymbol\" GraphicItemTarget=\"IDG_DEVICE_SYMBOL\"/>"
    ));
    assert!(gsdml
        .contains("<GraphicItem ID=\"IDG_DEVICE_SYMBOL\" GraphicFile=\"GSDML-0A11-0810-MD810\"/>"));
    xsd::validate(&gsdml).unwrap_or_else(|e| panic!("{e:?}"));
    assert_eq!(compile(&path), files, "the same bytes on every build");
}

/// Without a symbol, neither file names one.
#[test]
fn no_symbol_no_bitmap() {
    let files = compile(&support::checkout("tests/fixtures/valid/no_warnings.toml"));
    assert!(files.iter().all(|f| f.kind != ArtifactKind::DeviceSymbol));
    assert!(!text(&files, ArtifactKind::Gsd).contains("Bitmap_Device"));
    assert!(!text(&files, ArtifactKind::Gsdml).contains("Graphic"));
}
