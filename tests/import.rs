//! `gsdc import`: the shipped descriptions' own GSD files and every file of
//! the corpus written back as descriptions, each judged by its round trip
//! (the import's build against the file, by `gsdc diff`); the README's
//! table of drive files is this module's output.

use crate::support::{self, descriptions};
use gsdc::import::{import, import_both, Imported};
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

/// Every GSD and GSDML file of a shipped description that is not a
/// gateway's imports, and the import's build is that file byte for byte
/// below the header but for the device symbol (a file of its own, which
/// the import does not read: W600); a gateway's GSD is refused, E602.
#[test]
fn shipped_device_files_import_and_rebuild_byte_identical_below_the_header_but_the_symbol() {
    let mut imported_files = Vec::new();
    for (name, ir) in descriptions::load_shipped() {
        for file in gsdc::compile(&ir).unwrap() {
            if !matches!(file.kind, ArtifactKind::Gsd | ArtifactKind::Gsdml) {
                continue;
            }
            let imported = import(&file.file_name, &file.contents);
            if ir.gateway.is_some() {
                assert_eq!(imported.description, None, "{}", file.file_name);
                assert!(codes(&imported).contains(&"E602"), "{}", file.file_name);
                continue;
            }
            let toml = imported
                .description
                .as_deref()
                .unwrap_or_else(|| panic!("{name}: {:#?}", imported.diagnostics));
            assert!(imported.round_trip.is_clean(), "{name}");
            assert!(codes(&imported).iter().all(|c| *c == "W600"));
            let (rebuilt, diagnostics) = descriptions::load_text("imported.toml", toml);
            let rebuilt = rebuilt.unwrap_or_else(|| panic!("{name}: {diagnostics:#?}"));
            let (file_name, text) = descriptions::one(gsdc::compile(&rebuilt).unwrap(), file.kind);
            assert_eq!(file_name, file.file_name);
            let original = String::from_utf8(file.contents).unwrap();
            let bus = match file.kind {
                ArtifactKind::Gsd => {
                    assert_eq!(body(&text), without_symbol(body(&original)), "{name}");
                    assert!(toml.contains(&format!(
                        "ident_number = {{ value = 0x{:04X} }}",
                        rebuilt.profibus.as_ref().unwrap().ident_number
                    )));
                    "profibus"
                }
                _ => {
                    assert_eq!(
                        gsdml_body(&text),
                        without_symbol(&gsdml_body(&original)),
                        "{name}"
                    );
                    assert!(toml.contains("[profinet.ident_numbers]\ndap = 0x00000001\n"));
                    "profinet"
                }
            };
            // Everything imported is marked as the description's own choice.
            assert!(toml.contains(&format!("\"{bus}\" = \"imported from {}\"", file.file_name)));
            imported_files.push(file.file_name);
        }
    }
    imported_files.sort();
    assert_eq!(
        imported_files,
        [
            "9KDP1.GSD",
            "GSDML-V2.32-INOVANCE-MD810-20261122.xml",
            "GSDML-V2.32-MEGMEET-MV800-20230830.xml",
            "MD810DP.GSD"
        ]
    );
}

/// A GSDML file without gsdc's header comments.
fn gsdml_body(gsdml: &str) -> String {
    gsdml
        .split_inclusive('\n')
        .filter(|l| !l.starts_with("<!--"))
        .collect()
}

/// A device file without the lines of its device symbol: a GSD's
/// `Bitmap_Device`, a GSDML file's `Graphics` and `GraphicsList`.
fn without_symbol(text: &str) -> String {
    let mut in_graphics = false;
    text.split_inclusive('\n')
        .filter(|l| {
            let line = l.trim();
            let starts = line == "<Graphics>" || line == "<GraphicsList>";
            let ends = line == "</Graphics>" || line == "</GraphicsList>";
            let skip = in_graphics || starts || l.starts_with("Bitmap_Device");
            in_graphics = (in_graphics || starts) && !ends;
            !skip
        })
        .collect()
}

/// The valid fixtures' GSDML files (PROFIdrive's telegram 1 behind its
/// access point, a settings record, a setting each kind of module fixes, a
/// date with a time, French texts, ident numbers of its own everywhere)
/// import and rebuild byte-identical below the header.
#[test]
fn fixture_gsdml_files_import_and_rebuild_byte_identical() {
    let mut imported_files = 0;
    let shipped = descriptions::shipped();
    for (name, ir) in descriptions::all_valid() {
        if shipped.contains(&name) || ir.profinet.is_none() {
            continue;
        }
        let (file_name, gsdml) =
            descriptions::one(gsdc::compile(&ir).unwrap(), ArtifactKind::Gsdml);
        let imported = import(&file_name, gsdml.as_bytes());
        let toml = imported
            .description
            .as_deref()
            .unwrap_or_else(|| panic!("{name}: {:#?}", imported.diagnostics));
        let (rebuilt, diagnostics) = descriptions::load_text("imported.toml", toml);
        let rebuilt = rebuilt.unwrap_or_else(|| panic!("{name}: {diagnostics:#?}"));
        let (_, text) = descriptions::one(gsdc::compile(&rebuilt).unwrap(), ArtifactKind::Gsdml);
        assert_eq!(
            gsdml_body(&text),
            without_symbol(&gsdml_body(&gsdml)),
            "{name}"
        );
        imported_files += 1;
    }
    assert_eq!(
        imported_files, 5,
        "ax200, french, no_warnings, own_idents, profidrive"
    );
}

/// The ident numbers a GSDML file has are the import's, wherever they
/// differ from gsdc's numbering: MV810's with other module, submodule, DAP
/// and port numbers rebuilds to the same file.
#[test]
fn a_gsdml_files_own_ident_numbers_are_imported() {
    let ir = descriptions::load("mv810-pnet02.toml");
    let (name, gsdml) = descriptions::one(gsdc::compile(&ir).unwrap(), ArtifactKind::Gsdml);
    let renumbered = gsdml
        .replace(
            r#"ModuleIdentNumber="0x00000201""#,
            r#"ModuleIdentNumber="0x00004711""#,
        )
        .replace(
            r#"ModuleIdentNumber="0x00000001""#,
            r#"ModuleIdentNumber="0x00010000""#,
        )
        .replace(
            r#"SubmoduleIdentNumber="0x00000201""#,
            r#"SubmoduleIdentNumber="0x00004712""#,
        )
        .replace(
            r#"SubmoduleIdentNumber="0x00008002""#,
            r#"SubmoduleIdentNumber="0x00000002""#,
        );
    assert_eq!(renumbered.matches("0x0000471").count(), 2);
    let imported = import(&name, renumbered.as_bytes());
    let toml = imported
        .description
        .as_deref()
        .unwrap_or_else(|| panic!("{:#?}", imported.diagnostics));
    for stated in [
        "dap = 0x00010000",
        "dap_submodule = 0x00000001",
        "ports = [0x00008001, 0x00000002]",
        "pkw_pzd1 = 0x00004711",
        "submodules = { pkw_pzd1 = 0x00004712 }",
    ] {
        assert!(toml.contains(stated), "{stated} not in\n{toml}");
    }
    let (rebuilt, _) = descriptions::load_text("imported.toml", toml);
    let (_, text) = descriptions::one(
        gsdc::compile(&rebuilt.unwrap()).unwrap(),
        ArtifactKind::Gsdml,
    );
    assert_eq!(gsdml_body(&text), without_symbol(&gsdml_body(&renumbered)));
}

/// A card's GSD and GSDML file together give one description with both
/// buses, whose build is each file byte for byte below the header but for
/// the symbol: the GSDML's mappings and settings make the GSD's
/// User_Prm_Data too (MD810's, and the fixtures': PROFIdrive's, settings a
/// module fixes).
#[test]
fn a_gsd_and_a_gsdml_file_import_as_one_description_of_both_buses() {
    let mut imported = Vec::new();
    for (name, ir) in descriptions::all_valid() {
        if ir.profibus.is_none() || ir.profinet.is_none() || ir.gateway.is_some() {
            continue;
        }
        let files = gsdc::compile(&ir).unwrap();
        let (gsd_name, gsd) = descriptions::one(files.clone(), ArtifactKind::Gsd);
        let (gsdml_name, gsdml) = descriptions::one(files, ArtifactKind::Gsdml);
        let both = import_both((&gsd_name, gsd.as_bytes()), (&gsdml_name, gsdml.as_bytes()));
        let toml = both.description.as_deref().unwrap_or_else(|| {
            panic!(
                "{name}: {:#?} {:#?}",
                both.gsd.diagnostics, both.gsdml.diagnostics
            )
        });
        assert!(both.gsd.round_trip.is_clean() && both.gsdml.round_trip.is_clean());
        let (rebuilt, diagnostics) = descriptions::load_text("imported.toml", toml);
        let rebuilt = rebuilt.unwrap_or_else(|| panic!("{name}: {diagnostics:#?}"));
        let files = gsdc::compile(&rebuilt).unwrap();
        let (_, new_gsd) = descriptions::one(files.clone(), ArtifactKind::Gsd);
        let (_, new_gsdml) = descriptions::one(files, ArtifactKind::Gsdml);
        assert_eq!(body(&new_gsd), without_symbol(body(&gsd)), "{name}");
        assert_eq!(
            gsdml_body(&new_gsdml),
            without_symbol(&gsdml_body(&gsdml)),
            "{name}"
        );
        for mark in ["profibus", "profinet"] {
            assert!(
                toml.contains(&format!("\"{mark}\" = \"imported from")),
                "{name}: {mark}"
            );
        }
        // The GSD names the model and revision: the GSDML's stand-ins are gone.
        assert!(!toml.contains("\"device.model\""), "{name}");
        imported.push(name);
    }
    assert_eq!(
        imported,
        [
            "md810dp.toml",
            "ax200.toml",
            "no_warnings.toml",
            "profidrive.toml"
        ]
    );
}

/// Identity both files carry must agree: a GSDML file of another vendor
/// is an error at the GSD's line naming the GSDML's element, and nothing
/// is imported.
#[test]
fn a_gsd_and_a_gsdml_file_that_disagree_are_refused_naming_both_places() {
    let ir = descriptions::load("md810dp.toml");
    let files = gsdc::compile(&ir).unwrap();
    let (gsd_name, gsd) = descriptions::one(files.clone(), ArtifactKind::Gsd);
    let (gsdml_name, gsdml) = descriptions::one(files, ArtifactKind::Gsdml);
    let other = gsdml.replacen(
        r#"<VendorName Value="Inovance"/>"#,
        r#"<VendorName Value="Acme"/>"#,
        1,
    );
    let both = import_both((&gsd_name, gsd.as_bytes()), (&gsdml_name, other.as_bytes()));
    assert_eq!(both.description, None);
    let e603: Vec<&gsdc::Diagnostic> = both
        .gsd
        .diagnostics
        .iter()
        .filter(|d| d.code == "E603")
        .collect();
    assert_eq!(e603.len(), 1, "{:#?}", both.gsd.diagnostics);
    assert!(e603[0].message.contains("Vendor_Name = \"Inovance\" here"));
    assert!(e603[0].message.contains(&format!(
        "DeviceIdentity/VendorName@Value = \"Acme\" in {gsdml_name}, line "
    )));
    assert!(e603[0].message.contains(", at DeviceIdentity"));
    let line = gsd[..e603[0].span.clone().unwrap().start]
        .matches('\n')
        .count();
    assert!(gsd.lines().nth(line).unwrap().starts_with("Vendor_Name"));
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
/// that round-trip clean are at least the 11 found when this was written.
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
    // A GSDML file refused is refused at the element that stops it.
    for row in &gsdml {
        if row.imported.description.is_none() {
            let refusal = row.imported.diagnostics.iter().find(|d| d.code == "E602");
            assert!(
                refusal.is_some_and(
                    |d| d.message.contains(" (at ApplicationProcess/") && d.span.is_some()
                ),
                "{}: {:#?}",
                row.file,
                row.imported.diagnostics
            );
        }
    }
    let drives: Vec<&Row> = gsd.iter().chain(&gsdml).filter(|r| r.drive).collect();
    let clean = drives
        .iter()
        .filter(|r| r.imported.description.is_some())
        .count();
    assert!(clean >= 11, "{clean} drive files round-trip clean");
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

/// The command: writes the description, never over a file; a GSDML file
/// the format cannot say (ABB's FENA, three access points) is refused at
/// the element that stops it, exit 1, nothing written.
#[test]
fn the_command_writes_a_new_description_and_refuses_what_it_cannot() {
    let dir = support::scratch("command");
    let ir = descriptions::load("9kdp1.toml");
    let (name, gsd) = descriptions::one(gsdc::compile(&ir).unwrap(), ArtifactKind::Gsd);
    let gsd_path = dir.join(&name);
    std::fs::write(&gsd_path, gsd).unwrap();
    let out = dir.join("9kdp1.toml");
    let run = support::gsdc([
        "import".as_ref(),
        gsd_path.as_os_str(),
        "--out".as_ref(),
        out.as_os_str(),
    ]);
    assert_eq!(run.status.code(), Some(0), "{}", support::stderr(&run));
    assert!(support::stderr(&run).contains("round trip: 0 breaking, 0 compatible"));
    let written = std::fs::read_to_string(&out).unwrap();
    assert!(descriptions::load_text("9kdp1.toml", &written).0.is_some());
    let again = support::gsdc([
        "import".as_ref(),
        gsd_path.as_os_str(),
        "--out".as_ref(),
        out.as_os_str(),
    ]);
    assert_eq!(again.status.code(), Some(2));
    assert_eq!(std::fs::read_to_string(&out).unwrap(), written);
    let gsdml = support::shared("corpus/gsdml/GSDML-V2.33-ABB-FENA-20170914.xml");
    let refused_out = dir.join("fena.toml");
    let refused = support::gsdc([
        "import".as_ref(),
        gsdml.as_os_str(),
        "--out".as_ref(),
        refused_out.as_os_str(),
    ]);
    assert_eq!(refused.status.code(), Some(1));
    assert!(support::stderr(&refused).contains(
        "error[E602]: cannot import this file: 3 device access points: the description has one (at ApplicationProcess/DeviceAccessPointList/DeviceAccessPointItem[FENA_DAP_V4])"
    ));
    assert!(!refused_out.exists());
    // Two files: a card's GSD and GSDML file, in either order, make one
    // description; two GSD files are a usage error.
    let md810 = gsdc::compile(&descriptions::load("md810dp.toml")).unwrap();
    let mut paths = Vec::new();
    for kind in [ArtifactKind::Gsdml, ArtifactKind::Gsd] {
        let (name, text) = descriptions::one(md810.clone(), kind);
        let path = dir.join(name);
        std::fs::write(&path, text).unwrap();
        paths.push(path);
    }
    let both_out = dir.join("md810.toml");
    let both = support::gsdc([
        "import".as_ref(),
        paths[0].as_os_str(),
        paths[1].as_os_str(),
        "--out".as_ref(),
        both_out.as_os_str(),
    ]);
    assert_eq!(both.status.code(), Some(0), "{}", support::stderr(&both));
    let written = std::fs::read_to_string(&both_out).unwrap();
    assert!(written.contains("[profibus]") && written.contains("[profinet]"));
    let two_gsds = support::gsdc([
        "import".as_ref(),
        paths[1].as_os_str(),
        gsd_path.as_os_str(),
        "--out".as_ref(),
        dir.join("two.toml").as_os_str(),
    ]);
    assert_eq!(two_gsds.status.code(), Some(2));
    assert!(support::stderr(&two_gsds).contains("two files are a card's GSD and its GSDML file"));
}
