//! `gsdc import`: the shipped descriptions' own GSD files and every file of
//! the corpus written back as descriptions, each judged by its round trip
//! (the import's build against the file, by `gsdc diff`); the README's
//! table of drive files is this module's output.

use crate::support::{self, descriptions};
use gsdc::import::{import, import_with, Imported};
use gsdc::ArtifactKind;

/// A GSD without its header comment (the lines up to the second `;===`
/// rule, which name the description and its fingerprint and choices).
fn body(gsd: &str) -> &str {
    let rule = ";====";
    let first = gsd.find(rule).expect("a header rule");
    let second = first
        + rule.len()
        + gsd[first + rule.len()..]
            .find(rule)
            .expect("a closing rule");
    let end = second + gsd[second..].find('\n').expect("a line end") + 1;
    &gsd[end..]
}

fn codes(imported: &Imported) -> Vec<&'static str> {
    imported.diagnostics.iter().map(|d| d.code).collect()
}

/// Every GSD of a shipped description that is not a gateway's imports
/// with the bitmap its build wrote beside it, and the import's build is
/// that GSD byte for byte below the header, and that bitmap byte for byte;
/// every other file gsdc ships (a gateway's GSD, GSDML files) is refused,
/// E602.
#[test]
fn shipped_gsd_files_import_with_their_symbol_and_rebuild_byte_identical_below_the_header() {
    let mut imported_files = 0;
    for (name, ir) in descriptions::load_shipped() {
        let files = gsdc::compile(&ir).unwrap();
        let beside = |wanted: &str| {
            files
                .iter()
                .find(|f| f.file_name == wanted)
                .map(|f| f.contents.clone())
                .ok_or_else(|| format!("{wanted}: not built"))
        };
        for file in &files {
            if !matches!(file.kind, ArtifactKind::Gsd | ArtifactKind::Gsdml) {
                continue;
            }
            let imported = import_with(&file.file_name, &file.contents, &beside);
            if file.kind == ArtifactKind::Gsdml || ir.gateway.is_some() {
                assert_eq!(imported.description, None, "{}", file.file_name);
                assert!(
                    codes(&imported).contains(&"E602"),
                    "{}: {:?}",
                    file.file_name,
                    imported.diagnostics
                );
                continue;
            }
            let toml = imported
                .description
                .as_deref()
                .unwrap_or_else(|| panic!("{name}: {:#?}", imported.diagnostics));
            assert!(imported.round_trip.is_clean(), "{name}");
            assert!(
                codes(&imported).is_empty(),
                "{name}: {:?}",
                imported.diagnostics
            );
            let symbol = imported.symbol.as_ref().expect("the symbol imported");
            assert!(toml.contains(&format!("symbol = \"{}\"", symbol.file_name)));
            let (rebuilt, diagnostics) = gsdc::load_with("imported.toml", toml, &|path: &str| {
                assert_eq!(path, symbol.file_name);
                Ok(symbol.png.clone())
            });
            let rebuilt = rebuilt.unwrap_or_else(|| panic!("{name}: {diagnostics:#?}"));
            let rebuilt_files = gsdc::compile(&rebuilt).unwrap();
            let (file_name, gsd) = descriptions::one(rebuilt_files.clone(), ArtifactKind::Gsd);
            assert_eq!(file_name, file.file_name);
            let original = String::from_utf8(file.contents.clone()).unwrap();
            assert_eq!(body(&gsd), body(&original), "{name}");
            let bmp_name = format!("{}.bmp", file_name.rsplit_once('.').unwrap().0);
            let bitmap = |files: &[gsdc::Artifact]| {
                files
                    .iter()
                    .find(|f| f.file_name == bmp_name)
                    .map(|f| f.contents.clone())
                    .expect("the GSD's bitmap")
            };
            assert_eq!(bitmap(&rebuilt_files), bitmap(&files), "{name}");
            // Everything imported is marked as the description's own choice.
            assert!(toml.contains(&format!(
                "\"profibus\" = \"imported from {}\"",
                file.file_name
            )));
            assert!(toml.contains(&format!(
                "ident_number = {{ value = 0x{:04X} }}",
                rebuilt.profibus.as_ref().unwrap().ident_number
            )));
            imported_files += 1;
        }
    }
    assert_eq!(imported_files, 2, "9KDP1.GSD and MD810DP.GSD");
}

/// The GSD of `vendor_dp.toml`, the valid fixture that uses every key of
/// a vendor's own DP layout (modules, parameters, DPV1 alarms, isochronous
/// mode, block-structured parameters, a Unit_Diag_Not_Bit), imports and
/// rebuilds byte for byte below the header.
#[test]
fn every_key_of_a_vendors_own_layout_round_trips_byte_for_byte() {
    let ir = descriptions::load_from("tests/fixtures/valid", "vendor_dp.toml");
    let (name, gsd) = descriptions::one(gsdc::compile(&ir).unwrap(), ArtifactKind::Gsd);
    let imported = import(&name, gsd.as_bytes());
    let toml = imported
        .description
        .as_deref()
        .unwrap_or_else(|| panic!("{:#?}", imported.diagnostics));
    assert!(codes(&imported).is_empty(), "{:?}", imported.diagnostics);
    for said in [
        "[profibus.dpv1.alarms]",
        "[profibus.isochronous]",
        "block_structure = \"required\"",
        "clear = true",
        "c1_read_write_required = true",
    ] {
        assert!(toml.contains(said), "{said}");
    }
    let (rebuilt, diagnostics) = gsdc::load("imported.toml", toml);
    let rebuilt = rebuilt.unwrap_or_else(|| panic!("{diagnostics:#?}"));
    let (_, again) = descriptions::one(gsdc::compile(&rebuilt).unwrap(), ArtifactKind::Gsd);
    assert_eq!(body(&again), body(&gsd));
}

/// MD810DP.GSD and the bitmap its build writes.
fn md810dp_gsd_and_bitmap() -> (String, String, Vec<u8>) {
    let files = gsdc::compile(&descriptions::load("md810dp.toml")).unwrap();
    let bmp = files
        .iter()
        .find(|f| f.file_name == "MD810DP.bmp")
        .unwrap()
        .contents
        .clone();
    let (name, gsd) = descriptions::one(files, ArtifactKind::Gsd);
    (name, gsd, bmp)
}

fn messages<'a>(imported: &'a Imported, code: &str) -> Vec<&'a str> {
    imported
        .diagnostics
        .iter()
        .filter(|d| d.code == code)
        .map(|d| d.message.as_str())
        .collect()
}

/// A bitmap that is missing, not a bitmap, or of another size than 70 x
/// 40 is one warning naming it and why; the description is written, and
/// round-trips, without a symbol.
#[test]
fn a_symbol_that_cannot_be_imported_is_a_warning_and_the_import_goes_on() {
    let (name, gsd, bmp) = md810dp_gsd_and_bitmap();
    let mut narrow = bmp;
    narrow[18] = 35; // 35 x 40 pixels: readable, every row there
    let cases: [(&str, Result<Vec<u8>, String>); 3] = [
        ("cannot be read (no such file)", Err("no such file".into())),
        ("is not one gsdc reads", Ok(b"GIF89a".to_vec())),
        ("35 x 40 pixels, not 70 x 40", Ok(narrow)),
    ];
    for (why, beside) in cases {
        let imported = import_with(&name, gsd.as_bytes(), &|wanted: &str| {
            assert_eq!(wanted, "MD810DP.bmp");
            beside.clone()
        });
        let toml = imported.description.as_deref().expect("written");
        assert!(!toml.contains("symbol ="), "{why}");
        assert_eq!(imported.symbol, None);
        let w600 = messages(&imported, "W600");
        assert_eq!(w600.len(), 1, "{why}: {w600:?}");
        assert!(w600[0].starts_with("Bitmap_Device is not imported: its bitmap MD810DP.bmp"));
        assert!(w600[0].contains(why), "{why}: {}", w600[0]);
    }
}

/// A bitmap the build writes otherwise (colours off the 16, or another
/// colour table) is imported, with a warning that says how (W603).
#[test]
fn a_symbol_the_build_writes_otherwise_is_imported_with_a_warning() {
    let (name, gsd, bmp) = md810dp_gsd_and_bitmap();
    // Colour 15 of the table (white, stored blue, green, red at 54 + 4 x 15)
    // made a light grey that is no Windows colour.
    let mut greyed = bmp.clone();
    greyed[114..117].copy_from_slice(&[0xF0, 0xF0, 0xF0]);
    // Two pixels a byte; each row's padding byte is 0.
    let white_pixels: usize = bmp[118..]
        .iter()
        .map(|b| usize::from(b >> 4 == 15) + usize::from(b & 15 == 15))
        .sum();
    assert!(white_pixels > 0);
    let imported = import_with(&name, gsd.as_bytes(), &|_: &str| Ok(greyed.clone()));
    assert!(imported.description.is_some());
    let symbol = imported.symbol.as_ref().expect("imported");
    assert_eq!(
        messages(&imported, "W603"),
        [format!(
            "the build writes another MD810DP.bmp than the file's: {white_pixels} pixels in the nearest of the 16 Windows colours"
        )]
    );
    // The nearest colour of that grey is white: the build is gsdc's bitmap.
    let (ir, _) = gsdc::load_with(
        "card.toml",
        imported.description.as_deref().unwrap(),
        &|_: &str| Ok(symbol.png.clone()),
    );
    assert_eq!(ir.unwrap().device.symbol, Some(bmp));
}

/// Bytes from the line after the header's second `;====` rule on.
fn body_bytes(gsd: &[u8]) -> &[u8] {
    let rule = b";====";
    let at = |from: usize| from + gsd[from..].windows(5).position(|w| w == rule).unwrap();
    let second = at(at(0) + rule.len());
    let end = second + gsd[second..].iter().position(|b| *b == b'\n').unwrap() + 1;
    &gsd[end..]
}

/// A GSD whose strings are Latin-1 (a parameter's name with `ü` and `°`,
/// bytes 0xFC and 0xB0) imports with `charset = "latin-1"`, the name
/// verbatim in the UTF-8 description, and builds the same bytes.
#[test]
fn latin1_strings_import_verbatim_and_rebuild_as_the_same_bytes() {
    let (name, gsd, bmp) = md810dp_gsd_and_bitmap();
    let ascii = "\"PZD1(master->slaver)\"";
    assert!(gsd.contains(ascii));
    let mut latin1 = gsd.into_bytes();
    let at = latin1
        .windows(ascii.len())
        .position(|w| w == ascii.as_bytes())
        .unwrap();
    latin1.splice(
        at..at + ascii.len(),
        b"\"PZD1 \xFCber 50 \xB0C\"".iter().copied(),
    );
    let imported = import_with(&name, &latin1, &|_: &str| Ok(bmp.clone()));
    let toml = imported
        .description
        .as_deref()
        .unwrap_or_else(|| panic!("{:#?}", imported.diagnostics));
    assert!(toml.contains("[profibus]\ncharset = \"latin-1\"\n"));
    assert!(toml.contains("name = \"PZD1 über 50 °C\""));
    let png = &imported.symbol.as_ref().unwrap().png;
    let (ir, diagnostics) = gsdc::load_with("imported.toml", toml, &|_: &str| Ok(png.clone()));
    let ir = ir.unwrap_or_else(|| panic!("{diagnostics:#?}"));
    let rebuilt = gsdc::compile(&ir).unwrap();
    let gsd = rebuilt
        .iter()
        .find(|f| f.kind == ArtifactKind::Gsd)
        .unwrap();
    // Compared as Latin-1 text, so a difference shows as lines.
    let text = |bytes: &[u8]| bytes.iter().map(|&b| char::from(b)).collect::<String>();
    assert_eq!(text(body_bytes(&gsd.contents)), text(body_bytes(&latin1)));
    // Without the charset, the same name is not a GSD string (E102).
    let ascii_only = toml.replacen("charset = \"latin-1\"\n", "", 1);
    let (_, diagnostics) = gsdc::load("imported.toml", &ascii_only);
    assert!(diagnostics.errors().any(|d| d.code == "E102"));
}

/// A corpus file and what its import says.
struct Row {
    file: String,
    imported: Imported,
    /// A GSD of `Slave_Family` 1, or the GSDML of ABB's FENA or SEW's
    /// MOVI-C.
    drive: bool,
}

fn corpus_rows(folder: &str, extensions: &[&str]) -> Vec<Row> {
    let mut files: Vec<String> = std::fs::read_dir(support::shared("corpus").join(folder))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| {
            extensions
                .iter()
                .any(|e| n.to_ascii_lowercase().ends_with(e))
        })
        .collect();
    files.sort();
    files
        .into_iter()
        .map(|file| {
            let bytes = support::corpus_file(&format!("{folder}/{file}"));
            let imported = import(&file, &bytes);
            let drive = is_drive_gsd(&bytes)
                || file.contains("-ABB-FENA-")
                || file.contains("-SEW-MOVI-C-");
            Row {
                file,
                imported,
                drive,
            }
        })
        .collect()
}

/// Whether a GSD says it is a drive's: `Slave_Family` 1 (PI's family of
/// drives), with sub-families or not.
fn is_drive_gsd(bytes: &[u8]) -> bool {
    let Some(gsdc::device::Device::Dp(device)) = gsdc::device::read(bytes, None) else {
        return false;
    };
    let family = device.keyword("Slave_Family").map(|k| &k.value);
    matches!(
        family,
        Some(gsdc::gsd::Value::Number(1)) | Some(gsdc::gsd::Value::Family { main: 1, .. })
    )
}

/// What stops a round trip, in a few words each: the refusal, or the
/// subjects of the changes (E601), each once.
fn outcome(imported: &Imported) -> String {
    if imported.description.is_some() {
        return format!(
            "round trip clean ({} not imported, all cosmetic)",
            imported.unsaid
        );
    }
    let mut stops: Vec<String> = imported
        .diagnostics
        .iter()
        .filter(|d| d.is_error())
        .map(|d| {
            let message = d
                .message
                .split_once(": ")
                .map_or(d.message.as_str(), |(_, m)| m);
            // `subject (class): change` as `subject: change`.
            let subject = match d.code {
                "E601" => message
                    .replacen(" (breaking)", "", 1)
                    .replacen(" (compatible)", "", 1),
                _ => message.to_string(),
            };
            format!("{} {}", d.code, subject.replace('|', "/"))
        })
        .collect();
    stops.sort();
    stops.dedup();
    stops.join("; ")
}

const TABLE_START: &str = "<!-- import table: tests/import.rs writes it -->\n";
const TABLE_END: &str = "<!-- end of the import table -->\n";

/// Every corpus file imports without a crash; each refused one says why
/// with an error; each written one round-trips clean and builds; the drive GSD files
/// that round-trip clean are at least the 17 found now.
/// The README's table of drive files is what the imports give (`GSDC_WRITE_IMPORT_TABLE=1`
/// writes it).
#[test]
fn every_corpus_file_imports_or_says_why_and_the_readme_table_is_current() {
    let gsd = corpus_rows("gsd", &[".gsd", ".gse", ".gsg", ".gsf", ".gsi", ".gss"]);
    let gsdml = corpus_rows("gsdml", &[".xml"]);
    assert!(gsd.len() >= 60 && gsdml.len() >= 16);
    for row in gsd.iter().chain(&gsdml) {
        match &row.imported.description {
            Some(toml) => {
                assert!(row.imported.round_trip.is_clean(), "{}", row.file);
                // The round trip writes only the GSD: the whole build,
                // layouts and the check of every file, must pass too.
                let (ir, diagnostics) = descriptions::load_text("imported.toml", toml);
                let ir = ir.unwrap_or_else(|| panic!("{}: {diagnostics:#?}", row.file));
                gsdc::compile(&ir).unwrap_or_else(|e| panic!("{}: {e:#?}", row.file));
            }
            None => assert!(
                row.imported.diagnostics.has_errors(),
                "{}: refused without an error",
                row.file
            ),
        }
    }
    let drives: Vec<&Row> = gsd.iter().chain(&gsdml).filter(|r| r.drive).collect();
    let clean = drives
        .iter()
        .filter(|r| r.imported.description.is_some())
        .count();
    assert!(clean >= 17, "{clean} drive files round-trip clean");
    let mut table = String::from("| file | import |\n|---|---|\n");
    for row in drives {
        table.push_str(&format!(
            "| `{}` | {} |\n",
            row.file,
            outcome(&row.imported)
        ));
    }
    let readme_path = support::checkout("README.md");
    let readme = std::fs::read_to_string(&readme_path).unwrap();
    let start = readme.find(TABLE_START).expect("the README's import table") + TABLE_START.len();
    let end = start + readme[start..].find(TABLE_END).expect("the table's end");
    if std::env::var_os("GSDC_WRITE_IMPORT_TABLE").is_some() {
        let written = format!("{}{table}{}", &readme[..start], &readme[end..]);
        std::fs::write(&readme_path, written).unwrap();
        return;
    }
    assert_eq!(&readme[start..end], table, "README.md's import table is stale: GSDC_WRITE_IMPORT_TABLE=1 cargo test --test tests import::");
}

/// `gsdc import FILE --out OUT`.
fn run_import(file: &std::path::Path, out: &std::path::Path) -> std::process::Output {
    support::gsdc([
        "import".as_ref(),
        file.as_os_str(),
        "--out".as_ref(),
        out.as_os_str(),
    ])
}

/// The command: writes the description and the symbol's PNG beside it
/// (the bitmap found beside the GSD in other letter case), never over a
/// file; a GSDML file is refused, exit 1, nothing written.
#[test]
fn the_command_writes_a_new_description_and_refuses_what_it_cannot() {
    let dir = support::scratch("command");
    let files = gsdc::compile(&descriptions::load("9kdp1.toml")).unwrap();
    for f in &files {
        // 9KDP1.bmp as 9kdp1.bmp: GSD files name bitmaps in any case.
        std::fs::write(
            dir.join(f.file_name.replace("9KDP1.bmp", "9kdp1.bmp")),
            &f.contents,
        )
        .unwrap();
    }
    let gsd_path = dir.join("9KDP1.GSD");
    let out_dir = dir.join("out");
    std::fs::create_dir(&out_dir).unwrap();
    let out = out_dir.join("9kdp1.toml");
    let run = run_import(&gsd_path, &out);
    assert_eq!(run.status.code(), Some(0), "{}", support::stderr(&run));
    assert!(support::stderr(&run).contains("round trip: 0 breaking, 0 compatible"));
    let written = std::fs::read_to_string(&out).unwrap();
    assert!(written.contains("symbol = \"9KDP1.png\""));
    let png = std::fs::read(out_dir.join("9KDP1.png")).unwrap();
    let bmp = files.iter().find(|f| f.file_name == "9KDP1.bmp").unwrap();
    let (ir, diagnostics) = gsdc::load_with("9kdp1.toml", &written, &|path: &str| {
        std::fs::read(out_dir.join(path)).map_err(|e| e.to_string())
    });
    let ir = ir.unwrap_or_else(|| panic!("{diagnostics:#?}"));
    assert_eq!(ir.device.symbol.as_ref(), Some(&bmp.contents));
    // Again: the PNG is there, so nothing is written and the description
    // is left as it was.
    std::fs::remove_file(&out).unwrap();
    let again = run_import(&gsd_path, &out);
    assert_eq!(again.status.code(), Some(2));
    assert!(support::stderr(&again).contains("9KDP1.png"));
    assert!(!out.exists());
    assert_eq!(std::fs::read(out_dir.join("9KDP1.png")).unwrap(), png);
    // The description there: the PNG written is taken back.
    std::fs::remove_file(out_dir.join("9KDP1.png")).unwrap();
    std::fs::write(&out, "kept").unwrap();
    let over = run_import(&gsd_path, &out);
    assert_eq!(over.status.code(), Some(2));
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "kept");
    assert!(!out_dir.join("9KDP1.png").exists());
    let gsdml = support::shared("corpus/gsdml/GSDML-V2.33-ABB-FENA-20170914.xml");
    let refused_out = dir.join("fena.toml");
    let refused = run_import(&gsdml, &refused_out);
    assert_eq!(refused.status.code(), Some(1));
    assert!(support::stderr(&refused).contains("error[E602]"));
    assert!(!refused_out.exists());
}
