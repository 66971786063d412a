//! `gsdc import`: the shipped descriptions' own GSD files and every file of
//! the corpus written back as descriptions, each judged by its round trip
//! (the import's build against the file, by `gsdc diff`); the README's
//! table of drive files is this module's output.

use crate::support::{self, descriptions};
use gsdc::import::{import, import_both, import_with, Imported};
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

/// The description an import wrote, or a panic with its findings (`what`
/// names the case).
fn written<'i>(imported: &'i Imported, what: &str) -> &'i str {
    imported
        .description
        .as_deref()
        .unwrap_or_else(|| panic!("{what}: {:#?}", imported.diagnostics))
}

/// Fails naming the first of `lines` the description `toml` does not hold.
fn assert_says(toml: &str, lines: &[&str]) {
    for line in lines {
        assert!(toml.contains(line), "{line} not in\n{toml}");
    }
}

/// The files a build wrote, as an import finds the files beside the one
/// it reads (its device symbol's bitmap).
fn beside(files: &[gsdc::Artifact]) -> impl Fn(&str) -> Result<Vec<u8>, String> + '_ {
    move |wanted: &str| {
        files
            .iter()
            .find(|f| f.file_name == wanted)
            .map(|f| f.contents.clone())
            .ok_or_else(|| format!("{wanted}: not built"))
    }
}

fn codes(imported: &Imported) -> Vec<&'static str> {
    imported.diagnostics.iter().map(|d| d.code).collect()
}

/// Every GSD and GSDML file of a shipped description imports with the
/// bitmap its build wrote beside it (its device symbol), and the import's
/// build is that file byte for byte below the header, and that bitmap byte
/// for byte. Without a finding, but for a gateway's GSD: it does not say
/// the second bus, the order of the nodes' words, which of a node's two
/// parameters is its input or the gateway's own node, a warning (W600)
/// each.
#[test]
fn shipped_device_files_import_and_rebuild_byte_identical_below_the_header() {
    let mut imported_files = Vec::new();
    for (name, ir) in descriptions::load_shipped() {
        let files = gsdc::compile(&ir).unwrap();
        let beside = beside(&files);
        for file in &files {
            if !matches!(file.kind, ArtifactKind::Gsd | ArtifactKind::Gsdml) {
                continue;
            }
            let imported = import_with(&file.file_name, &file.contents, &beside);
            let toml = written(&imported, &name);
            assert!(imported.round_trip.is_clean(), "{name}");
            let expected: &[&str] = match ir.gateway {
                Some(_) => &["W600"; 4],
                None => &[],
            };
            assert_eq!(
                codes(&imported),
                expected,
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
            let (file_name, text) = descriptions::one(rebuilt_files.clone(), file.kind);
            assert_eq!(file_name, file.file_name);
            let bmp_name = symbol.file_name.replace(".png", ".bmp");
            let bitmap = |files: &[gsdc::Artifact]| {
                files
                    .iter()
                    .find(|f| f.file_name == bmp_name)
                    .map(|f| f.contents.clone())
                    .unwrap_or_else(|| panic!("{name}: no {bmp_name}"))
            };
            assert_eq!(bitmap(&rebuilt_files), bitmap(&files), "{name}");
            let original = String::from_utf8(file.contents.clone()).unwrap();
            let bus = match file.kind {
                ArtifactKind::Gsd => {
                    assert_eq!(body(&text), body(&original), "{name}");
                    assert!(toml.contains(&format!(
                        "ident_number = {{ value = 0x{:04X} }}",
                        rebuilt.profibus.as_ref().unwrap().ident_number
                    )));
                    "profibus"
                }
                _ => {
                    assert_eq!(gsdml_body(&text), gsdml_body(&original), "{name}");
                    assert!(toml.contains("[profinet.ident_numbers]\ndap = 0x00000001\n"));
                    "profinet"
                }
            };
            // Everything imported is marked as the description's own choice.
            assert!(toml.contains(&format!("\"{bus}\" = \"imported from {}\"", file.file_name)));
            if ir.gateway.is_some() {
                assert!(toml.contains(&format!(
                    "\"gateway\" = \"imported from {}\"",
                    file.file_name
                )));
            }
            imported_files.push(file.file_name.clone());
        }
    }
    imported_files.sort();
    assert_eq!(
        imported_files,
        [
            "9KDP1.GSD",
            "GSDML-V2.32-INOVANCE-MD810-20261122.xml",
            "GSDML-V2.32-MEGMEET-MV800-20230830.xml",
            "MD810DP.GSD",
            "MD810GW.GSD"
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
/// date with a time, French texts, ident numbers of its own everywhere,
/// PROFIsafe modules, whose placeholder CRCs the import states as the file
/// has them, pinned) import and rebuild byte-identical below the header.
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
        let toml = written(&imported, &name);
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
        imported_files, 6,
        "ax200, french, no_warnings, own_idents, profidrive, profisafe"
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
    let toml = written(&imported, "");
    assert_says(
        toml,
        &[
            "dap = 0x00010000",
            "dap_submodule = 0x00000001",
            "ports = [0x00008001, 0x00000002]",
            "pkw_pzd1 = 0x00004711",
            "submodules = { pkw_pzd1 = 0x00004712 }",
        ],
    );
    let (rebuilt, _) = descriptions::load_text("imported.toml", toml);
    let (_, text) = descriptions::one(
        gsdc::compile(&rebuilt.unwrap()).unwrap(),
        ArtifactKind::Gsdml,
    );
    assert_eq!(gsdml_body(&text), without_symbol(&gsdml_body(&renumbered)));
}

/// A card's GSD and GSDML file together give one description with both
/// buses, whose build is each file byte for byte below the header, the
/// device symbol included (read from the bitmap beside the GSD, it is the
/// GSDML file's too): the GSDML's mappings and settings make the GSD's
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
        let beside = beside(&files);
        let (gsd_name, gsd) = descriptions::one(files.clone(), ArtifactKind::Gsd);
        let (gsdml_name, gsdml) = descriptions::one(files.clone(), ArtifactKind::Gsdml);
        let both = import_both(
            (&gsd_name, gsd.as_bytes()),
            (&gsdml_name, gsdml.as_bytes()),
            &beside,
        );
        let toml = both.description.as_deref().unwrap_or_else(|| {
            panic!(
                "{name}: {:#?} {:#?}",
                both.gsd.diagnostics, both.gsdml.diagnostics
            )
        });
        assert!(both.gsd.round_trip.is_clean() && both.gsdml.round_trip.is_clean());
        assert_eq!(both.symbol.is_some(), ir.device.symbol.is_some(), "{name}");
        let (rebuilt, diagnostics) = gsdc::load_with("imported.toml", toml, &|path: &str| {
            let symbol = both.symbol.as_ref().expect("a symbol imported");
            assert_eq!(path, symbol.file_name);
            Ok(symbol.png.clone())
        });
        let rebuilt = rebuilt.unwrap_or_else(|| panic!("{name}: {diagnostics:#?}"));
        let rebuilt_files = gsdc::compile(&rebuilt).unwrap();
        let (_, new_gsd) = descriptions::one(rebuilt_files.clone(), ArtifactKind::Gsd);
        let (_, new_gsdml) = descriptions::one(rebuilt_files, ArtifactKind::Gsdml);
        assert_eq!(body(&new_gsd), body(&gsd), "{name}");
        assert_eq!(gsdml_body(&new_gsdml), gsdml_body(&gsdml), "{name}");
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

/// MD810's GSD and its GSDML file as `change` changes it, imported
/// together (without the files beside them); each file's name and text.
fn md810_both_with_gsdml_changed(
    change: impl Fn(&str) -> String,
) -> (gsdc::import::Both, (String, String), (String, String)) {
    let files = gsdc::compile(&descriptions::load("md810dp.toml")).unwrap();
    let (gsd_name, gsd) = descriptions::one(files.clone(), ArtifactKind::Gsd);
    let (gsdml_name, gsdml) = descriptions::one(files, ArtifactKind::Gsdml);
    let changed = change(&gsdml);
    assert_ne!(changed, gsdml, "the case changes the file");
    let no_files = |name: &str| Err(format!("{name}: not given"));
    let both = import_both(
        (&gsd_name, gsd.as_bytes()),
        (&gsdml_name, changed.as_bytes()),
        &no_files,
    );
    (both, (gsd_name, gsd), (gsdml_name, changed))
}

/// Identity both files carry must agree: a GSDML file of another vendor
/// is an error at the GSD's line naming the GSDML's element, and nothing
/// is imported.
#[test]
fn a_gsd_and_a_gsdml_file_that_disagree_are_refused_naming_both_places() {
    let (both, (_, gsd), (gsdml_name, _)) = md810_both_with_gsdml_changed(|gsdml| {
        gsdml.replacen(
            r#"<VendorName Value="Inovance"/>"#,
            r#"<VendorName Value="Acme"/>"#,
            1,
        )
    });
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

/// The GSD of `vendor_dp.toml`, the valid fixture that uses every key of
/// a vendor's own DP layout (modules, parameters, DPV1 alarms, isochronous
/// mode, block-structured parameters, a Unit_Diag_Not_Bit, channel
/// diagnosis), imports and rebuilds byte for byte below the header. The
/// one finding: the device block's length, which no GSD keyword says,
/// is the least its bits need (3: bit 9 is in the second byte after the
/// header), the rest of Max_Diag_Data_Len left to the channels' blocks.
#[test]
fn every_key_of_a_vendors_own_layout_round_trips_byte_for_byte() {
    let ir = descriptions::load_from("tests/fixtures/valid", "vendor_dp.toml");
    let (name, gsd) = descriptions::one(gsdc::compile(&ir).unwrap(), ArtifactKind::Gsd);
    let imported = import(&name, gsd.as_bytes());
    let toml = written(&imported, "");
    let block = "the file does not say how long its device block is: 3, the least its bits and areas need, the rest of its Max_Diag_Data_Len left to the channels' blocks";
    assert_eq!(messages(&imported, "W600"), [block]);
    assert_eq!(codes(&imported), ["W600"]);
    assert_says(
        toml,
        &[
            "[profibus.dpv1.alarms]",
            "[profibus.isochronous]",
            "block_structure = \"required\"",
            "clear = true",
            "c1_read_write_required = true",
            "max_diag_data_len = 20\n",
            "[profibus.diagnosis]\nlength = 3\n",
            "[[profibus.channel_diagnosis]]\nerror_type = 26\nname = \"Drive ready signal missing (24V)\"\n",
            "fail_safe_required = true\n",
        ],
    );
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

/// MD810's GSDML file changed by `change`, imported.
fn md810_gsdml_changed(change: impl Fn(&str) -> String) -> Imported {
    let files = gsdc::compile(&descriptions::load("md810dp.toml")).unwrap();
    let (name, gsdml) = descriptions::one(files, ArtifactKind::Gsdml);
    let changed = change(&gsdml);
    assert_ne!(changed, gsdml, "the case changes the file");
    import(&name, changed.as_bytes())
}

/// MD810's GSDML with a second device access point: a copy of the first
/// under other IDs, as `edit` changes it.
fn md810_with_second_dap(edit: impl Fn(String) -> String) -> Imported {
    md810_gsdml_changed(|gsdml| with_second_dap(gsdml, &edit))
}

fn with_second_dap(gsdml: &str, edit: &dyn Fn(String) -> String) -> String {
    let start = gsdml.find("<DeviceAccessPointItem ").unwrap();
    let end_tag = "</DeviceAccessPointItem>";
    let end = gsdml.find(end_tag).unwrap() + end_tag.len();
    let copy = edit(gsdml[start..end].replace(" ID=\"", " ID=\"V2_"));
    format!("{}\n{copy}{}", &gsdml[..end], &gsdml[end..])
}

/// A second DAP of its own ident number.
fn renumbered(dap: String) -> String {
    dap.replacen(
        "ModuleIdentNumber=\"0x00000001\"",
        "ModuleIdentNumber=\"0x00000009\"",
        1,
    )
}

/// A second device access point that differs from the first in its ident
/// number, order number, hardware release and ports is imported as a
/// `[[profinet.daps]]` entry saying just those, and rebuilds the same
/// device.
#[test]
fn a_second_device_access_point_imports_as_what_it_changes() {
    let imported = md810_with_second_dap(|dap| {
        let second_port = dap.find("<PortSubmoduleItem ID=\"V2_IDS_PORT_2\"").unwrap();
        let end_tag = "</PortSubmoduleItem>";
        let end = second_port + dap[second_port..].find(end_tag).unwrap() + end_tag.len();
        let one_port = format!("{}{}", &dap[..second_port], &dap[end..]);
        one_port
            .replacen(
                "ModuleIdentNumber=\"0x00000001\"",
                "ModuleIdentNumber=\"0x00000009\"",
                1,
            )
            .replace("<HardwareRelease Value=\"", "<HardwareRelease Value=\"B-")
            .replace(" IsDefaultRingport=\"true\"", "")
            // A port less is a port's IOPS and IOCS less in the CRs.
            .replace(
                "MaxInputLength=\"38\" MaxOutputLength=\"38\"",
                "MaxInputLength=\"37\" MaxOutputLength=\"37\"",
            )
            .replace("<MediaRedundancy SupportedRole=\"Client\"/>", "")
    });
    assert_eq!(
        imported.round_trip.breaking, 0,
        "{:#?}",
        imported.diagnostics
    );
    assert_eq!(
        imported.round_trip.compatible, 0,
        "{:#?}",
        imported.diagnostics
    );
    let description = imported.description.expect("written");
    let entry = &description[description.find("[[profinet.daps]]").expect("an entry")..];
    let entry = &entry[..entry.find("\n\n").unwrap_or(entry.len())];
    assert!(entry.contains("ident = 0x00000009"), "{entry}");
    assert!(entry.contains("hardware_release = \"B-"), "{entry}");
    assert!(entry.contains("ports = 1"), "{entry}");
    assert!(
        !entry.contains("modules"),
        "it offers every module: {entry}"
    );
}

/// A first device access point that offers no safety module, under a
/// later one that does (SEW's MOVI-C's V1.0 and V2.0): the import states
/// the first's modules (`dap_modules`), and its build is the same device.
#[test]
fn a_first_access_point_offering_fewer_modules_imports() {
    let fixture =
        std::fs::read_to_string(support::checkout("tests/fixtures/valid/profisafe.toml")).unwrap();
    let text = fixture
        .replacen(
            "[profinet]\n",
            "[profinet]\ndap_modules = [\"pzd2\", \"pzd4\"]\n",
            1,
        )
        .replacen(
            "\"safety_module_1\"]",
            "\"safety_module_1\", \"safety_module_2\"]",
            1,
        );
    assert_eq!(text.matches("safety_module_2").count(), 1);
    let (file_name, gsdml) = built("profisafe.toml", &text, ArtifactKind::Gsdml);
    let imported = import(&file_name, gsdml.as_bytes());
    assert!(
        imported.round_trip.is_clean(),
        "{:#?}",
        imported.diagnostics
    );
    let toml = written(&imported, "profisafe with dap_modules");
    assert_says(toml, &["dap_modules = [\"pzd2\", \"pzd4\"]\n"]);
}

/// A second device access point of the first's ident number and slot 0
/// (MD810's first, copied with another ID) is one catalogue version more of
/// one head module, as SEW's MOVI-C's three: imported as an entry of that
/// ident, and its build is the same device.
#[test]
fn a_second_device_access_point_of_the_firsts_ident_imports() {
    let imported = md810_with_second_dap(|dap| dap);
    assert!(
        imported.round_trip.is_clean(),
        "{:#?}",
        imported.diagnostics
    );
    let description = imported.description.expect("written");
    let entry = &description[description.find("[[profinet.daps]]").expect("an entry")..];
    assert!(entry.contains("ident = 0x00000001\n"), "{entry}");
}

/// A GSDML file with more than the format can say is imported as far as
/// it goes and judged: a second device access point whose ident number is
/// the first's with another slot 0, whose update time is not the first's (the description's
/// share it), which lacks a release the first has, or which offers a
/// module the first does not; or a module whose data is not 16-bit words:
/// each is left out (W600 at its element), and the round trip finds the
/// device changed (E601, breaking); nothing is written.
#[test]
fn what_a_gsdml_import_leaves_out_the_round_trip_finds_changed() {
    // Its ident number, and another own submodule: another slot 0.
    let same_ident = md810_with_second_dap(|dap| {
        let own = dap.find("<VirtualSubmoduleItem ").unwrap();
        let number = own + dap[own..].find("SubmoduleIdentNumber=\"").unwrap();
        let end = number + dap[number..].find("\" ").unwrap();
        format!(
            "{}SubmoduleIdentNumber=\"0x00000077{}",
            &dap[..number],
            &dap[end..]
        )
    });
    let other_interval = md810_with_second_dap(|dap| {
        renumbered(dap).replace("MinDeviceInterval=\"32\"", "MinDeviceInterval=\"64\"")
    });
    // The entry would take the first's hardware release.
    let no_release = md810_with_second_dap(|dap| {
        let start = dap.find("<HardwareRelease ").unwrap();
        let end = start + dap[start..].find("/>").unwrap() + 2;
        format!("{}{}", &renumbered(dap[..start].to_string()), &dap[end..])
    });
    // The description's first DAP offers every module.
    let only_second_offers = md810_gsdml_changed(|gsdml| {
        let both = with_second_dap(gsdml, &renumbered);
        let first_ref = "<ModuleItemRef ModuleItemTarget=\"IDM_PZD_12\" AllowedInSlots=\"1\"/>";
        assert!(both.contains(first_ref));
        both.replacen(first_ref, "", 1)
    });
    let bytes_module = md810_gsdml_changed(|gsdml| {
        let module = gsdml.find("<ModuleItem ID=\"IDM_PZD_12\"").unwrap();
        let item = "<DataItem DataType=\"Unsigned16\"";
        let at = module + gsdml[module..].find(item).unwrap();
        format!(
            "{}<DataItem DataType=\"Unsigned32\"{}",
            &gsdml[..at],
            &gsdml[at + item.len()..]
        )
    });
    for (imported, left_out, changed) in [
        (&same_ident, "device access point `V2_IDD_DAP` is not imported: its ModuleIdentNumber is device access point `IDD_DAP`'s, whose own submodule or ports have other ident numbers: the device could not tell which slot 0 a project expects (E162)", "DAP \"MD810 PROFINET example (no such card in the manual)\" (0x00000001) (breaking): removed"),
        (&other_interval, "device access point `V2_IDD_DAP` is not imported: its MinDeviceInterval is not the first device access point's", "DAP \"MD810 PROFINET example (no such card in the manual)\" (0x00000009) (breaking): removed"),
        (&no_release, "device access point `V2_IDD_DAP` is not imported: it has no hardware_release, which the first has", "DAP \"MD810 PROFINET example (no such card in the manual)\" (0x00000009) (breaking): removed"),
        (&only_second_offers, "device access point `V2_IDD_DAP` is not imported: it offers module `IDM_PZD_12`, which the first device access point does not (the import takes the data modules the first offers)", "DAP \"MD810 PROFINET example (no such card in the manual)\" (0x00000009) (breaking): removed"),
        (&bytes_module, "module `IDM_PZD_12` is not imported: its IO data is not 16-bit words as many each way", "input data of submodule \"12 PZD\" (0x0000010C) of module \"12 PZD\" (0x0000010C) (breaking): 26 bytes"),
    ] {
        assert_eq!(imported.description, None);
        let warning = imported.diagnostics.iter().find(|d| d.code == "W600" && d.message.starts_with(left_out));
        assert!(warning.is_some_and(|w| w.span.is_some()), "{left_out}: {:#?}", imported.diagnostics);
        assert!(
            messages(imported, "E601").iter().any(|m| m.contains(changed)),
            "{changed}: {:#?}",
            imported.diagnostics
        );
        assert!(imported.round_trip.breaking >= 1);
    }
}

/// The GSD of MD810's bridge, built from its shipped description or a
/// variant of it.
fn gateway_gsd(text: &str) -> String {
    built("md810-gateway.toml", text, ArtifactKind::Gsd).1
}

/// The import of the GSD a gateway description builds, after checking that
/// the import's build is that GSD below the header (imported without the
/// bitmap beside it, the build names none).
fn gateway_round_trip(description: &str) -> Imported {
    let gsd = gateway_gsd(description);
    let imported = import("MD810GW.GSD", gsd.as_bytes());
    let toml = written(&imported, "gateway");
    assert!(imported.round_trip.is_clean());
    let rebuilt = gsdc::load("imported.toml", toml)
        .0
        .expect("the import loads");
    let (_, text) = descriptions::one(gsdc::compile(&rebuilt).unwrap(), ArtifactKind::Gsd);
    let without_symbol = body(&gsd).replace("Bitmap_Device               = \"MD810GW\"\r\n", "");
    assert_ne!(without_symbol, body(&gsd));
    assert!(body(&text) == without_symbol, "{}", body(&text));
    imported
}

/// Variants of MD810's bridge import and rebuild below the header: the
/// nodes' words in bit areas (TPDO in bits 0-3, RPDO in bits 4-7 of a
/// byte each); only types of a 16-bit code, so no codes' area (the types'
/// note says what they carry); one node, whose number its parameters'
/// names do not show (W600); a word block named otherwise than gsdc names
/// it (W600 at its line).
#[test]
fn gateway_variants_import_and_rebuild_below_the_header() {
    let bits = gateway_round_trip(&descriptions::gateway_in_bit_areas());
    assert_says(
        written(&bits, "bit areas"),
        &[
            "[gateway.input_words]\nname = \"Slave {n} TPDO words\"\nbits = [0, 3]\n",
            "[gateway.output_words]\nname = \"Slave {n} RPDO words\"\nbits = [4, 7]\n",
        ],
    );
    let shipped = descriptions::shipped_text("md810-gateway.toml");
    let listed = shipped
        .find("[[gateway.diagnosis.types]]\nvalue = 1")
        .unwrap();
    let word = shipped
        .find("[[gateway.diagnosis.types]]\nvalue = 4")
        .unwrap();
    let words_only: String = format!("{}{}", &shipped[..listed], &shipped[word..])
        .lines()
        .filter(|l| !l.starts_with("\"gateway.diagnosis.types["))
        .map(|l| format!("{l}\n"))
        .collect();
    let words = gateway_round_trip(&words_only);
    assert_says(
        written(&words, "code words only"),
        &["[[gateway.diagnosis.types]]\nvalue = 4\ntext = \"Drive reports fault\"\ncode_word = \"Drive fault code\"\n"],
    );
    assert_eq!(
        written(&words, "code words only")
            .matches("[[gateway.diagnosis.types]]")
            .count(),
        1
    );
    let one_node = shipped
        .replace("nodes = [1, 30]", "nodes = [1, 1]")
        .replace("range = [1, 30]", "range = [1, 1]");
    let one = gateway_round_trip(&one_node);
    assert_says(written(&one, "one node"), &["nodes = [1, 1]\n"]);
    assert!(messages(&one, "W600")
        .iter()
        .any(|m| m.contains("names one node")));
    // A word block named otherwise: the build names it as gsdc does, a
    // warning at its line; the round trip finds the name cosmetic.
    let gsd = gateway_gsd(&shipped).replace("\"INPUT 2 words\" 0x51", "\"IN 2 words\" 0x51");
    let renamed = import("MD810GW.GSD", gsd.as_bytes());
    written(&renamed, "a module named otherwise");
    let warning = renamed.diagnostics.iter().find(|d| {
        d.message == "module name \"IN 2 words\" is not imported: gsdc names a gateway's word blocks itself: \"INPUT 2 words\""
    });
    assert!(
        warning.is_some_and(|w| w.span.is_some()),
        "{:#?}",
        renamed.diagnostics
    );
}

/// A gateway's GSD with a part `[gateway]` cannot say is refused naming it
/// (E602): without the comment that says which type each code belongs to
/// (no keyword says it) or with an earlier gsdc's that did not say it, with
/// a node's parameter named out of turn, or with a parameter in bits past
/// its byte; with a module of bytes it is neither a drive's nor a
/// gateway's.
#[test]
fn a_gateway_gsd_that_gateway_cannot_say_is_refused_saying_why() {
    let gsd = gateway_gsd(&descriptions::shipped_text("md810-gateway.toml"));
    let comment = gsd
        .find("; The code of type 1")
        .expect("the codes' comment");
    let area = gsd.find("Unit_Diag_Area = 16-23").expect("the codes' area");
    let without_comment = format!("{}{}", &gsd[..comment], &gsd[area..]);
    let cases = [
        (
            without_comment,
            "no comment above the codes' area (bits 16-23) says which type each code belongs to",
        ),
        (
            gsd.replace("\"Slave 7 TPDO words\"", "\"Slave seven TPDO words\""),
            "the node parameters \"Slave 1 TPDO words\" .. are not one name numbered by node",
        ),
        (
            gsd.replace("\"INPUT 1 word\" 0x50", "\"INPUT 1 byte\" 0x10"),
            "nor are its modules a gateway's blocks of words one way each",
        ),
        // Bits past the byte: GSD's reader takes them, its rules do not.
        (
            gsd.replacen("Unsigned8 1 1-30", "BitArea(250-255) 1 1-30", 1),
            "its modules are blocks of words one way each, as a gateway's, but the gateway parameter \"Number of CANopen slaves\" is of type BitArea, not a byte, a word or bits of one byte",
        ),
        // A GSD of an earlier gsdc, whose comment did not say it.
        (
            gsd.replace("; The code of type 1 (35, 34) and type 3 (32);", "; The code of types 1 and 3;"),
            "is an older gsdc's, which does not say which type each code belongs to",
        ),
    ];
    for (text, why) in cases {
        assert_ne!(text, gsd, "{why}: the case changes the file");
        let imported = import("MD810GW.GSD", text.as_bytes());
        assert_eq!(imported.description, None, "{why}");
        let refused = messages(&imported, "E602");
        assert!(
            refused.iter().any(|m| m.contains(why)),
            "{why}: {refused:?}"
        );
    }
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
    let toml = written(&imported, "");
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
    let r = imported.round_trip;
    if imported.draft.is_some() && r.breaking + r.compatible > MANY_CHANGES {
        let constructs = changed_constructs(&messages(imported, "E601"));
        let mut cell = format!(
            "E601 {} breaking and {} compatible changes in {constructs}",
            r.breaking, r.compatible
        );
        cell.extend(left_out(imported).map(|l| format!("; {l}")));
        return cell.replace('|', "/");
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
    stops.extend(left_out(imported));
    stops.join("; ")
}

/// More changes than a table cell lists one by one.
const MANY_CHANGES: usize = 10;

/// The constructs the round trip's changes are in (E601 messages), each
/// once with how many changes it has: an element or attribute by its name
/// (`IsochroneMode`, `PhysicalSlots`), a whole DAP or module, a record by
/// its index, a diagnosis item by its element.
fn changed_constructs(messages: &[&str]) -> String {
    let mut counts: std::collections::BTreeMap<String, usize> = Default::default();
    for message in messages {
        let subject = message
            .strip_prefix("the import builds another device: ")
            .unwrap_or(message);
        let subject = [" (breaking): ", " (compatible): "]
            .iter()
            .find_map(|class| subject.rsplit_once(class))
            .map_or(subject, |(subject, _)| subject);
        *counts.entry(construct(subject)).or_default() += 1;
    }
    let named: Vec<String> = counts
        .into_iter()
        .map(|(name, n)| match n {
            1 => name,
            n => format!("{name} ({n})"),
        })
        .collect();
    named.join(", ")
}

/// `DAP "FENA-21" (0x00000003) NumberOfAR` is `NumberOfAR`; `module "Empty"
/// (0x00007531)` is itself without its number; `record 9000 "Alarms" of
/// port ...` and `parameter "Stop" at byte 0 of record 9000 ...` are
/// `record 9000`; `ChannelDiagItem 79` is `ChannelDiagItem`.
fn construct(subject: &str) -> String {
    let words: Vec<&str> = subject.split(' ').collect();
    let last = words.last().copied().unwrap_or_default();
    // A record, or a parameter `of record N`; not the word in a name.
    let of_record = words.windows(2).position(|w| w == ["of", "record"]);
    let record = match words[0] {
        "record" => Some(0),
        _ => of_record.map(|i| i + 1),
    };
    if let Some(i) = record {
        return words[i..(i + 2).min(words.len())].join(" ");
    }
    if last.starts_with("(0x") {
        return words[..words.len() - 1].join(" ");
    }
    if !subject.contains('"') {
        return match last.bytes().all(|b| b.is_ascii_digit()) {
            true => words[0].to_string(),
            false => subject.to_string(),
        };
    }
    last.split(['@', '/']).next().unwrap_or(last).to_string()
}

/// The GSDML version, device access points and modules the import left
/// out (W600), each a construct the round trip would find changed once the
/// rest builds.
fn left_out(imported: &Imported) -> Option<String> {
    let parts: Vec<&str> = messages(imported, "W600")
        .into_iter()
        .filter_map(|m| m.split_once(" is not imported").map(|(what, _)| what))
        .filter(|what| {
            what.starts_with("GSDML V")
                || (what.starts_with("device access point `") || what.starts_with("module `"))
                    && what.ends_with('`')
        })
        .collect();
    (!parts.is_empty()).then(|| format!("left out: {}", parts.join(", ")))
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
        let imported = &row.imported;
        assert_eq!(
            imported.description.is_some(),
            imported.round_trip.is_clean() && !imported.diagnostics.has_errors(),
            "{}: written exactly when the round trip is clean",
            row.file
        );
        assert!(imported.description.is_none() || imported.draft.is_none());
        // The round trip writes only the GSD or GSDML file: the whole
        // build, layouts and the check of every file, must pass too, also
        // of a description whose build is another device.
        for toml in imported.description.iter().chain(&imported.draft) {
            let (ir, diagnostics) = descriptions::load_text("imported.toml", toml);
            let ir = ir.unwrap_or_else(|| panic!("{}: {diagnostics:#?}", row.file));
            gsdc::compile(&ir).unwrap_or_else(|e| panic!("{}: {e:#?}", row.file));
        }
    }
    // Both drive GSDML files import as the same device: ABB's FENA, its
    // safety modules with it, and SEW's MOVI-C (no releases, a family with
    // `-`, three access points of one ident number, F-modules only the
    // later ones offer).
    let row = |file: &str| gsdml.iter().find(|r| r.file.contains(file)).unwrap();
    for drive in ["-ABB-FENA-", "-SEW-MOVI-C-"] {
        let imported = &row(drive).imported;
        assert!(imported.round_trip.is_clean(), "{drive}");
        assert!(imported.description.is_some(), "{drive}");
    }
    // A GSDML file not imported says why: refused at its device access
    // point (E602, no module the format can say), or its import does not
    // build or builds another device (E601). Each device access point and
    // module left out is a warning at its element.
    for row in &gsdml {
        if row.imported.description.is_none() {
            let diagnostics = &row.imported.diagnostics;
            let refused = diagnostics.iter().any(|d| {
                d.code == "E602"
                    && d.message
                        .contains(" (at ApplicationProcess/DeviceAccessPointList/")
                    && d.span.is_some()
            });
            let different = diagnostics.iter().any(|d| d.code == "E601");
            assert!(refused || different, "{}: {diagnostics:#?}", row.file);
        }
        let left_out = row.imported.diagnostics.iter().filter(|d| {
            d.code == "W600"
                && (d.message.starts_with("device access point `")
                    || d.message.starts_with("module `"))
        });
        for d in left_out {
            assert!(d.span.is_some(), "{}: {d:?}", row.file);
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

/// A file the import refuses (E602, no drive or gateway in it) was never
/// built, so its summary gives no count of round-trip changes, which would
/// read as a clean round trip: it says there was none.
#[test]
fn a_refused_import_says_it_ran_no_round_trip() {
    let dir = support::scratch("refused");
    let gsd = dir.join("CP24V1.GSD");
    std::fs::write(&gsd, support::corpus_file("gsd/morgoth380__CP24V1.gsd")).unwrap();
    let out = dir.join("cp24v1.toml");
    let run = run_import(&gsd, &out);
    assert_eq!(run.status.code(), Some(1), "{}", support::stderr(&run));
    let stderr = support::stderr(&run);
    assert!(stderr.contains("error[E602]"), "{stderr}");
    assert!(
        stderr.contains("no round trip: the import was refused"),
        "{stderr}"
    );
    assert!(!stderr.contains("round trip: 0 breaking"), "{stderr}");
    assert!(!out.exists());
}

/// The command: writes the description and the symbol's PNG beside it
/// (the bitmap found beside the GSD in other letter case), in a folder it
/// makes when missing, never over a file; a GSDML file whose import builds
/// another device (ABB's FENA: PROFIsafe, records that grow with the
/// module, attributes gsdc writes otherwise) is not written, exit 1, its errors shown first; a GSD
/// and a GSDML file of one card make one description.
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
    // A folder not there yet is made.
    let out_dir = dir.join("out").join("new");
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
    // Siemens' IM174 (SI018133): its import builds another device; the
    // changes are shown before the warnings, which name what the format
    // cannot say or says otherwise.
    let gsd = support::shared("corpus/gsd/ivangre4__SI018133.GSE");
    let refused_out = dir.join("si018133.toml");
    let refused = run_import(&gsd, &refused_out);
    assert_eq!(refused.status.code(), Some(1));
    let stderr = support::stderr(&refused);
    assert!(
        stderr.starts_with("error[E601]: the import builds another device: GSD_Revision (compatible): \"4\" → \"5\""),
        "{stderr}"
    );
    assert!(stderr.contains(
        "warning[W600]: GSD_Revision 4 is imported as 5: the file states Ident_Maintenance_supp, which came with revision 5 (E124)"
    ));
    assert!(stderr.contains("warning[W600]: Bitmap_Device is not imported"));
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

/// A GSDML file under a name that is not PI's is refused: the description
/// makes its file name from the name's parts, and the message says what
/// is wrong with it.
#[test]
fn a_gsdml_file_under_another_name_is_refused_saying_why() {
    let ir = descriptions::load("mv810-pnet02.toml");
    let (_, gsdml) = descriptions::one(gsdc::compile(&ir).unwrap(), ArtifactKind::Gsdml);
    let imported = import("GSDML-V2.32-MEGMEET-MV800-20231399.xml", gsdml.as_bytes());
    assert_eq!(imported.description, None);
    let refused = messages(&imported, "E602");
    assert_eq!(refused.len(), 1, "{:#?}", imported.diagnostics);
    assert!(
        refused[0].contains("is not a GSDML file name") && refused[0].contains("release date"),
        "{}",
        refused[0]
    );
}

/// ABB's FENA offers three device access points, one per hardware version.
/// All three import (its name of station in capitals is imported in lower
/// case, E132, the same name of station): none is left out, and the round
/// trip finds none removed or added. Each is compared: FENA-21 differs in
/// the functional-safety class its PROFIsafe modules give it, which the
/// import leaves out, while FENA-01, which has no PROFIsafe module, comes
/// back unchanged.
#[test]
fn fenas_three_device_access_points_import() {
    let imported = corpus_import(FENA);
    let left_out: Vec<&str> = messages(&imported, "W600")
        .into_iter()
        .filter(|m| m.starts_with("device access point"))
        .collect();
    assert!(left_out.is_empty(), "{left_out:#?}");
    // `DAP "FENA-21" (0x00000003) (breaking): removed`, not an attribute's
    // `DAP "FENA-21" (0x00000003) NumberOfAR (breaking): "2" removed`.
    let whole_dap = |m: &&str| {
        m.strip_suffix(" (breaking): removed")
            .or_else(|| m.strip_suffix(" (compatible): added"))
            .is_some_and(|head| head.contains("DAP \"") && head.ends_with(')'))
    };
    let daps_changed: Vec<&str> = messages(&imported, "E601")
        .into_iter()
        .filter(whole_dap)
        .collect();
    assert!(daps_changed.is_empty(), "{daps_changed:#?}");
    let changed = |dap: &str| -> Vec<String> {
        messages(&imported, "E601")
            .into_iter()
            .filter(|m| m.contains(&format!("DAP \"{dap}\"")))
            .map(str::to_string)
            .collect()
    };
    // FENA-11 and FENA-21 offer the safety modules, FENA-01 none: each
    // declares FunctionalSafety as the file does.
    for dap in ["FENA-11", "FENA-21", "FENA-01"] {
        assert_eq!(changed(dap), Vec::<String>::new(), "{dap}");
    }
}

/// FENA's standard telegram 2 (STW1, NSOLL_B, STW2 / ZSW1, NIST_B, ZSW2;
/// Unsigned16, Unsigned32, Unsigned16 each way, in API 14848 behind the
/// module access point) is imported as `standard_telegram_2` with its own
/// ident number, and the round trip finds nothing changed in its IO data,
/// its API or its placement, nor in its record 1, which ends with the
/// fail-safe values of its three items, NSOLL_B's an Unsigned32.
#[test]
fn fenas_standard_telegram_2_imports_as_the_profiles() {
    let imported = corpus_import(FENA);
    let toml = written(&imported, FENA);
    assert_says(
        toml,
        &["standard_telegram_2 = true", "telegram2 = 0x00000012"],
    );
    // Named as gsdc names it (FENA's "Standard Telegram 2": a cosmetic change).
    let module = "of module \"Standard telegram 2\" (0x00000012)";
    let telegram_2: Vec<&str> = messages(&imported, "E601")
        .into_iter()
        .filter(|m| m.contains(module))
        .collect();
    assert!(telegram_2.is_empty(), "{telegram_2:#?}");
    assert!(!messages(&imported, "W600")
        .iter()
        .any(|m| m.starts_with("module `ID_MODULE_STD_TGM2` is not imported")));
}

/// Siemens' SIMODRIVE 611U GSD has three keywords of its own (its lines
/// 49 to 51: `OffsetFirstMPDBlock`, `ETERDelay` and `MaxResponseDelay`,
/// each `= 0`), which the specification does not have: the import states
/// them in `[profibus.vendor_keywords]`, in the file's order, the build
/// writes them, and the round trip finds the same device.
#[test]
fn siemens_own_keywords_import_as_vendor_keywords() {
    let name = "ivangre4__SIEM8055.GSD";
    let imported = corpus_gsd_import(name);
    let toml = written(&imported, name);
    assert_says(
        toml,
        &["[profibus.vendor_keywords]\nOffsetFirstMPDBlock = 0\nETERDelay = 0\nMaxResponseDelay = 0\n"],
    );
    for keyword in ["OffsetFirstMPDBlock", "ETERDelay", "MaxResponseDelay"] {
        assert!(
            !messages(&imported, "W600")
                .iter()
                .any(|m| m.contains(keyword)),
            "{keyword}"
        );
    }
    assert!(imported.round_trip.is_clean());
}

/// Siemens' SIMADYN D SS52 GSD of 1998 has no `GSD_Revision` (the
/// specification's first edition) and the vendor keyword `IsMaster = 1`
/// (its line 28): the import states `gsd_revision = 0` and the keyword, the
/// build writes no GSD_Revision, and the round trip finds the same device.
#[test]
fn a_gsd_without_gsd_revision_imports_as_revision_0() {
    let name = "ivangre4__siem8037.gsd";
    let imported = corpus_gsd_import(name);
    let toml = written(&imported, name);
    assert_says(
        toml,
        &[
            "gsd_revision = 0\n",
            "[profibus.vendor_keywords]\nIsMaster = 1\n",
        ],
    );
    assert!(imported.round_trip.is_clean());
    let (_, gsd) = built("siem8037.toml", toml, ArtifactKind::Gsd);
    assert!(!gsd.contains("GSD_Revision"), "{gsd}");
}

/// The hardware catalog's groups as the vendors name them: FENA's PPO
/// modules under "PPO Types" and both standard telegrams under "Standard
/// Telegrams" (its lines 854-855 and 876-877), MOVI-C's process data
/// modules under "Processdata Modules", in German "Prozessdaten Module"
/// (lines 7188 and 9076). The round trips find no module's category
/// changed.
#[test]
fn each_kinds_catalog_group_imports_with_its_texts() {
    // Category changes are cosmetic, never E601: read them from the diff.
    assert_imported_and_kept(
        &[
            (FENA, "[profinet.categories]\nuser_defined = \"PPO Types\"\nstandard_telegram_1 = \"Standard Telegrams\"\nstandard_telegram_2 = \"Standard Telegrams\"\n"),
            (MOVI_C, "[profinet.categories]\nuser_defined = { en = \"Processdata Modules\", de = \"Prozessdaten Module\" }\n"),
        ],
        // MOVI-C names the group on each data submodule too, which the
        // description does not say (W600).
        |change| change.contains("CategoryRef") && !change.starts_with("submodule"),
    );
}

/// The labels on the device of the interface and the ports: FENA's (lines
/// 37-40, 87-91, 144-147: each access point labels its own one or two
/// ports; texts at lines 869-871), MOVI-C's in English and German (lines
/// 33-37, whose TextIds "X1", "X1P1", "X1P2" name "X1", "X1 P1", "X1 P2",
/// lines 7291-7293 and in German alike). The round trips find no label
/// changed.
#[test]
fn the_interfaces_and_ports_labels_import_with_their_texts() {
    let imported = assert_imported_and_kept(
        &[
            (FENA, "[profinet.subslot_labels]\ninterface = \"X1\"\nports = [\"X1 P1\", \"X1 P2\"]\n"),
            (MOVI_C, "[profinet.subslot_labels]\ninterface = { en = \"X1\", de = \"X1\" }\nports = [{ en = \"X1 P1\", de = \"X1 P1\" }, { en = \"X1 P2\", de = \"X1 P2\" }]\n"),
        ],
        |change| change.contains("SubslotItem"),
    );
    for imported in &imported {
        assert!(!messages(imported, "W600")
            .iter()
            .any(|m| m.contains("SubslotList")));
    }
}

/// Imports each corpus GSDML file of `files`, asserts that its description
/// says the lines given with it, and that the round trip finds no change
/// `kept` picks (cosmetic changes too, which are never E601); the imports.
fn assert_imported_and_kept(files: &[(&str, &str)], kept: impl Fn(&str) -> bool) -> Vec<Imported> {
    files
        .iter()
        .map(|&(name, says)| {
            let imported = corpus_import(name);
            assert_says(written(&imported, name), &[says]);
            let changed: Vec<String> = round_trip_changes(name, &imported)
                .into_iter()
                .filter(|c| kept(c))
                .collect();
            assert_eq!(changed, Vec::<String>::new(), "{name}");
            imported
        })
        .collect()
}

/// What `gsdc diff` finds, each change as its subject and how, between the
/// corpus GSDML file `name` and the build of the description its import
/// wrote: cosmetic changes, which are never E601.
fn round_trip_changes(name: &str, imported: &Imported) -> Vec<String> {
    let (_, gsdml) = built(
        "imported.toml",
        written(imported, name),
        ArtifactKind::Gsdml,
    );
    let old =
        gsdc::device::read(&support::corpus_file(&format!("gsdml/{name}")), Some(name)).unwrap();
    let new = gsdc::device::read(gsdml.as_bytes(), Some(name)).unwrap();
    gsdc::diff::compare(&old, &new)
        .unwrap()
        .iter()
        .map(|c| format!("{} {}", c.subject, c.change))
        .collect()
}

const FENA: &str = "GSDML-V2.33-ABB-FENA-20170914.xml";
const MOVI_C: &str = "GSDML-V2.34-SEW-MOVI-C-Decentralized-Electronics-20200731-071447.xml";

/// The import of a corpus GSDML file.
fn corpus_import(name: &str) -> Imported {
    import(name, &support::corpus_file(&format!("gsdml/{name}")))
}

/// A corpus GSDML file's text, for a test to change before importing it.
fn corpus_gsdml_text(name: &str) -> String {
    String::from_utf8(support::corpus_file(&format!("gsdml/{name}"))).unwrap()
}

/// The import of MOVI-C's text under the name of a file of GSDML `version`
/// (the import takes the version from the name).
fn movi_c_named(version: &str) -> Imported {
    let name = MOVI_C.replace("V2.34", version);
    import(&name, corpus_gsdml_text(MOVI_C).as_bytes())
}

/// The import of a corpus GSD file.
fn corpus_gsd_import(name: &str) -> Imported {
    import(name, &support::corpus_file(&format!("gsd/{name}")))
}

/// The file of `kind` the description `text` builds, and its name; a panic
/// with the diagnostics when it does not load.
fn built(name: &str, text: &str, kind: ArtifactKind) -> (String, String) {
    let (ir, diagnostics) = descriptions::load_text(name, text);
    let ir = ir.unwrap_or_else(|| panic!("{name}: {diagnostics:#?}"));
    descriptions::one(gsdc::compile(&ir).unwrap(), kind)
}

/// The draft of an import whose round trip is not clean.
fn draft(imported: &Imported) -> &str {
    imported
        .draft
        .as_deref()
        .expect("the import builds another device")
}

/// What an import wrote: its description, or its draft.
fn description_or_draft(imported: &Imported) -> &str {
    imported
        .description
        .as_deref()
        .or(imported.draft.as_deref())
        .expect("the import writes a description or a draft")
}

/// A later DAP without `info` takes DeviceIdentity's text, not the first
/// DAP's: where the two differ, an entry whose text is the first DAP's
/// states it.
#[test]
fn a_later_daps_info_is_judged_against_what_it_would_inherit() {
    let imported = md810_gsdml_changed(|gsdml| {
        // Both DAPs (and their submodules) show the device's name as their
        // info text, which DeviceIdentity's InfoText is not.
        let start = gsdml.find("<DeviceAccessPointList>").unwrap();
        let end = gsdml.find("</DeviceAccessPointList>").unwrap();
        let daps = gsdml[start..end].replace(
            "<InfoText TextId=\"IDT_DEVICE_INFO\"/>",
            "<InfoText TextId=\"IDT_DEVICE_NAME\"/>",
        );
        let changed = format!("{}{daps}{}", &gsdml[..start], &gsdml[end..]);
        with_second_dap(&changed, &renumbered)
    });
    // A text is cosmetic to the round trip: the entry itself shows it.
    let description = imported.description.expect("written");
    let entry = &description[description.find("[[profinet.daps]]").expect("an entry")..];
    let entry = &entry[..entry.find("\n\n").unwrap_or(entry.len())];
    assert!(entry.contains("\ninfo = "), "{entry}");
    assert!(
        imported.round_trip.is_clean(),
        "{:#?}",
        imported.diagnostics
    );
}

/// An attribute the file gives at the value its absence means (FENA's
/// `NumberOfAdditionalInputCR="0"`), or as gsdc writes it but spelt
/// otherwise (MOVI-C's `StartupMode="Advanced;Legacy"`, a set), is not
/// left out: the file gsdc writes says the same, and the round trip
/// agrees. Any other value of it is still left out, and the round trip
/// names the change.
#[test]
fn an_attribute_at_its_schema_default_or_spelt_otherwise_is_not_left_out() {
    let with_relations = |relations: &'static str| {
        md810_gsdml_changed(move |gsdml| {
            gsdml.replacen(
                "<ApplicationRelations StartupMode=\"Legacy;Advanced\">",
                relations,
                1,
            )
        })
    };
    let same = with_relations(
        "<ApplicationRelations StartupMode=\"Advanced;Legacy\" NumberOfAdditionalInputCR=\"0\">",
    );
    // (The bitmap, which `import` without files cannot read, is left out.)
    let left_out = messages(&same, "W600");
    assert!(
        !left_out.iter().any(|m| m.contains("ApplicationRelations")),
        "{left_out:#?}"
    );
    assert!(same.round_trip.is_clean(), "{:#?}", same.diagnostics);
    let other = with_relations(
        "<ApplicationRelations StartupMode=\"Advanced\" NumberOfAdditionalInputCR=\"1\">",
    );
    let left_out = messages(&other, "W600");
    for attribute in ["@StartupMode", "@NumberOfAdditionalInputCR"] {
        assert!(
            left_out.iter().any(|m| m.contains(attribute)),
            "{attribute}: {left_out:#?}"
        );
        assert!(
            messages(&other, "E601")
                .iter()
                .any(|m| m.contains(attribute)),
            "{attribute}: {:#?}",
            other.diagnostics
        );
    }
    let fena = corpus_import(FENA);
    let fena_left_out = messages(&fena, "W600");
    for absent_means_the_same in [
        "NumberOfAdditionalInputCR",
        "NumberOfAdditionalOutputCR",
        "NumberOfAdditionalMulticastProviderCR",
        "NumberOfMulticastConsumerCR",
        "IsochroneModeSupported",
    ] {
        assert!(
            !fena_left_out
                .iter()
                .any(|m| m.contains(absent_means_the_same)),
            "{absent_means_the_same}: {fena_left_out:#?}"
        );
    }
    // FENA-01's ApplicationClass="" says what its absence says; FENA-11's
    // and FENA-21's "FunctionalSafety" is what their safety modules write.
    let application_class: Vec<&str> = fena_left_out
        .iter()
        .copied()
        .filter(|m| m.contains("CertificationInfo@ApplicationClass"))
        .collect();
    assert!(application_class.is_empty(), "{fena_left_out:#?}");
}

/// A value the import writes otherwise than the file says (a GSDML version
/// or a name of station gsdc does not write) is a
/// warning, and marked under `[choices]` with why: the build lists it among
/// the description's own choices (W103), which a shipping build refuses
/// until a maintainer has confirmed it. MOVI-C's text under a V2.35 name
/// stands for a file of a version gsdc does not write; its first access
/// point's PNIO_Version, V2.33, is then later than the file gsdc writes
/// and left out.
#[test]
fn a_value_written_otherwise_than_the_file_is_marked_with_why() {
    let imported = movi_c_named("V2.35");
    let toml = draft(&imported);
    let (ir, _) = descriptions::load_text("movi-c.toml", toml);
    let ir = ir.expect("builds");
    assert!(messages(&imported, "W600").contains(
        &"PNIO_Version `V2.33` is not imported: the description's pnio_version is a version up to the file's, V2.32 (E197)"
    ));
    for (path, value, why) in [
        (
            "profinet.gsdml_version",
            "\"2.32\"",
            "GSDML V2.35 is not imported",
        ),
        (
            "profinet.dns_name",
            "\"sew-eurodrive-dfc2xx\"",
            "DNS_CompatibleName `SEW-EURODRIVE-DFC2xX` is imported as `sew-eurodrive-dfc2xx`",
        ),
    ] {
        let decision = ir
            .decisions
            .iter()
            .find(|d| d.path == path)
            .unwrap_or_else(|| panic!("{path}"));
        assert_eq!(decision.value, value);
        assert!(decision.reason.starts_with(why), "{}", decision.reason);
        assert!(messages(&imported, "W600")
            .iter()
            .any(|m| m.starts_with(why)));
    }
}

/// MOVI-C's stack beyond FENA's (its line 26: `PNIO_Version="V2.33"` in a
/// V2.34 file, `PowerOnToCommReady="5000"`, `RequiredSchemaVersion="V2.32"`,
/// `AdaptsRealIdentification="true"`, `WebServer="http://:80/"`;
/// line 38: `IOConfigData MaxInputLength="100" MaxOutputLength="100"
/// MaxDataLength="200"`; line 82, the interface:
/// `NetworkComponentDiagnosisSupported="true"`; line 86: `TimingProperties
/// SendClock="32 64 128" ... PreferredSendClock="32"`; lines 92 and 116,
/// both ports: `PortDeactivationSupported`, `CheckMAUTypeSupported` and
/// `CheckMAUTypeDifferenceSupported` true,
/// `LinkStateDiagnosisCapability="Up+Down"`) imports into `[profinet]`
/// and `[profinet.stack]`, and the round trip finds none of these
/// attributes changed.
#[test]
fn movi_cs_stack_attributes_import() {
    let imported = corpus_import(MOVI_C);
    assert_says(
        written(&imported, MOVI_C),
        &[
            "send_clock = [32, 64, 128]\npreferred_send_clock = 32\n",
            "gsdml_version = \"2.34\"\npnio_version = \"2.33\"\nrequired_schema_version = \"2.32\"\n",
            "power_on_to_comm_ready = 5000\nnetwork_component_diagnosis = true\nport_deactivation = true\ncheck_mau_type = true\ncheck_mau_type_difference = true\nadapts_real_identification = true\nweb_server = \"http://:80/\"\nlink_state_diagnosis = \"Up+Down\"\n",
            "max_input_length = 100\nmax_output_length = 100\nmax_data_length = 200\n",
        ],
    );
    let imported_attributes = [
        "PNIO_Version",
        "RequiredSchemaVersion",
        "MaxDataLength",
        "TimingProperties@PreferredSendClock",
        "PowerOnToCommReady",
        "NetworkComponentDiagnosisSupported",
        "PortDeactivationSupported",
        "CheckMAUTypeSupported",
        "CheckMAUTypeDifferenceSupported",
        "AdaptsRealIdentification",
        "WebServer",
        "LinkStateDiagnosisCapability",
    ];
    for code in ["E601", "W600"] {
        for message in messages(&imported, code) {
            assert!(
                !imported_attributes.iter().any(|a| message.contains(a)),
                "{message}"
            );
        }
    }
}

/// MOVI-C's PROFIenergy (its line 73, the access point's own submodule:
/// `ProfileVersion="V1.2" EntityClass="Class1" EntitySubclass="Subclass1"
/// PESAP_uses_PROFIenergyASE="true"`; lines 75 and 76, the modes 2 and 255
/// with their times; line 26, `PROFIenergyASE_Supported="true"`; line 32,
/// `ApplicationClass="Isochronous;EnergySaving"`) imports into
/// `[profinet.profienergy]`, and the round trip finds nothing of it
/// changed.
#[test]
fn movi_cs_profienergy_imports() {
    let imported = corpus_import(MOVI_C);
    assert_says(
        written(&imported, MOVI_C),
        &["[profinet.profienergy]\nprofile_version = \"1.2\"\nentity_class = 1\nentity_subclass = 1\nase = true\npesap_uses_ase = true\nmodes = [\n  { id = 2, time_to_pause = 1000, regular_time_to_operate = 60000, min_length_of_stay = 60000 },\n  { id = 255, time_to_pause = 0, regular_time_to_operate = 0, min_length_of_stay = 0 },\n]\n"],
    );
    for code in ["E601", "W600"] {
        for message in messages(&imported, code) {
            assert!(
                !["PROFIenergy", "ApplicationClass"]
                    .iter()
                    .any(|a| message.contains(a)),
                "{message}"
            );
        }
    }
}

/// MOVI-C's process data modules, each allowed in slots 2 to 5 (lines 41
/// to 56: `AllowedInSlots="2..5"`), import as `module_slots`, and its
/// "Leermodul" (line 389: ModuleIdentNumber 0x7531, one submodule 0x1
/// with an empty `IOData`, "Empty" and "Leerplatz", allowed in slots 1 to
/// 5 at line 40) as `[profinet.empty_module]`; the round trip finds neither
/// changed and nothing of them is left out.
#[test]
fn movi_cs_slots_and_empty_module_import() {
    let imported = corpus_import(MOVI_C);
    let toml = written(&imported, MOVI_C);
    assert_says(
        toml,
        &[
            "module_slots = [2, 5]\n",
            "[profinet.empty_module]\nname = { en = \"Empty\", de = \"Leerplatz\" }\ninfo = { en = \"Empty, no module plugged in\", de = \"Leerplatz, kein Modul gesteckt\" }\nslots = [1, 5]\nident = 0x00007531\nsubmodule_ident = 0x00000001\n",
        ],
    );
    for code in ["E601", "W600"] {
        for message in messages(&imported, code) {
            assert!(
                ![
                    "AllowedInSlots",
                    "Leermodul",
                    "Empty",
                    "PhysicalSlots",
                    "IOConfigData"
                ]
                .iter()
                .any(|a| message.contains(a)),
                "{message}"
            );
        }
    }
}

/// A process data module allowed other slots than the others (MOVI-C's
/// first, line 41, made `2..4`) leaves the description's slots the first
/// module's: the others' are left out at the first access point's
/// references, and the round trip names the change at each access point's:
/// 15 of the first, and 16 of each of the two later ones, whose 1PD_InOut
/// is still allowed 2..5.
#[test]
fn a_module_in_other_slots_than_the_others_is_left_out_there() {
    let text = corpus_gsdml_text(MOVI_C).replacen(
        r#"ModuleItemTarget="1PD_InOut" AllowedInSlots="2..5""#,
        r#"ModuleItemTarget="1PD_InOut" AllowedInSlots="2..4""#,
        1,
    );
    let imported = import(MOVI_C, text.as_bytes());
    assert_says(draft(&imported), &["module_slots = [2, 4]\n"]);
    let w600 = messages(&imported, "W600");
    let slots: Vec<&&str> = w600
        .iter()
        .filter(|m| m.contains("AllowedInSlots"))
        .collect();
    assert_eq!(slots.len(), 15, "{w600:#?}");
    assert!(slots[0].starts_with("ModuleItemRef `2PD_InOut` AllowedInSlots is not imported: its slots 2..5 are not the first module's, 2..4"));
    let e601 = messages(&imported, "E601");
    let changed = |dap: &str| {
        e601.iter()
            .filter(|m| m.contains(dap) && m.contains("AllowedInSlots"))
            .count()
    };
    assert_eq!(
        ["DFC2xA V1.0", "DFC2xA V2.0", "DFC2xA V4.0"].map(changed),
        [15, 16, 16]
    );
}

/// MOVI-C's text under a V2.33 name: its later access points (PNIO_Version
/// V2.34, lines 145 and 262) are left out, and with them the F-modules
/// only they offer (lines 406 and 460), each with why, where the
/// description would have listed them in no catalogue entry (E183): the
/// draft builds, without safety modules.
#[test]
fn a_safety_module_only_left_out_access_points_offer_is_left_out() {
    let imported = movi_c_named("V2.33");
    let w600 = messages(&imported, "W600");
    for dap in ["DFC2xA V2.0", "DFC2xA V4.0"] {
        let left_out = format!("device access point `{dap}` is not imported: its PNIO_Version");
        assert!(w600.iter().any(|m| m.starts_with(&left_out)), "{w600:#?}");
    }
    for module in ["FPD_DS_4_3Byte_InOut", "FPD_DS_4_3Byte_V2_InOut"] {
        let left_out = format!("module `{module}` is not imported: only device access points the import leaves out offer it, and a module no device access point offers is in no catalogue entry (E183)");
        assert!(w600.contains(&left_out.as_str()), "{w600:#?}");
    }
    let toml = draft(&imported);
    assert!(!toml.contains("[[profinet.safety_modules]]"));
    built("imported.toml", toml, ArtifactKind::Gsdml);
}

/// PROFIenergy in a file of a version gsdc does not write it in (MOVI-C's
/// text under a V2.33 name) is left out once, at its element, with why;
/// the access point's `PROFIenergyASE_Supported` and its `EnergySaving`
/// class are left out with it, and the round trip names each change.
#[test]
fn profienergy_of_an_older_file_is_left_out_with_why() {
    let imported = movi_c_named("V2.33");
    assert!(!draft(&imported).contains("profienergy"));
    let w600 = messages(&imported, "W600");
    let energy: Vec<&&str> = w600
        .iter()
        .filter(|m| m.starts_with("PROFIenergy is not imported"))
        .collect();
    assert_eq!(energy.len(), 1, "{w600:#?}");
    assert!(energy[0].contains("GSDML 2.34 and later (E198)"));
    for attribute in [
        "DeviceAccessPointItem PROFIenergyASE_Supported",
        "DeviceAccessPointItem CertificationInfo@ApplicationClass",
    ] {
        assert!(w600.iter().any(|m| m.starts_with(attribute)), "{attribute}");
    }
    let changed = messages(&imported, "E601");
    for change in [
        "PROFIenergyASE_Supported (breaking)",
        "PROFIenergy@EntityClass (breaking)",
        r#"CertificationInfo@ApplicationClass (breaking): "Isochronous;EnergySaving" → "Isochronous""#,
    ] {
        assert!(changed.iter().any(|m| m.contains(change)), "{change}");
    }
}

/// An attribute of a later GSDML version than the file gsdc writes is left
/// out, a warning that names E198, and the round trip names the change:
/// MOVI-C's text under a V2.33 name keeps `CheckMAUTypeDifferenceSupported`
/// (V2.33 has it: Hilscher's file) and leaves out `AdaptsRealIdentification`
/// and `WebServer` (its line 26), which no file at hand shows before V2.34.
#[test]
fn an_attribute_of_a_later_version_than_the_files_is_left_out() {
    let imported = movi_c_named("V2.33");
    let toml = draft(&imported);
    assert!(toml.contains("check_mau_type_difference = true\n"));
    assert!(!toml.contains("adapts_real_identification"));
    let w600 = messages(&imported, "W600");
    let left_out: Vec<&&str> = w600
        .iter()
        .filter(|m| m.starts_with("AdaptsRealIdentification"))
        .collect();
    assert_eq!(left_out.len(), 1, "{w600:#?}");
    assert!(left_out[0].contains("GSDML 2.34 and later (E198)"));
    assert!(left_out[0].ends_with("the description's file is V2.33"));
    assert!(!toml.contains("web_server"));
    assert!(w600.iter().any(|m| m
        .starts_with(r#"WebServer="http://:80/" is not imported: gsdc writes it in GSDML 2.34"#)));
    let changed = messages(&imported, "E601");
    assert!(changed.iter().any(|m| m.contains(
        r#"DAP "DFC2xA V1.0" (0x00007532) AdaptsRealIdentification (breaking): "true" removed"#
    )));
    assert!(!changed
        .iter()
        .any(|m| m.contains("CheckMAUTypeDifferenceSupported")));
    // Under a V2.32 name, each port's (lines 92 and 116) is left out too.
    let imported = movi_c_named("V2.32");
    let lines: Vec<usize> = imported
        .diagnostics
        .iter()
        .filter(|d| d.code == "W600")
        .filter(|d| d.message.starts_with("CheckMAUTypeDifferenceSupported"))
        .map(|d| gsdc::line_col(&imported.text, d.span.clone().unwrap().start).0)
        .collect();
    assert_eq!(lines, [92, 116]);
}

/// MOVI-C's isochronous real time and isochronous mode import with the
/// file's values (its lines 82 to 92: the interface's RT_Class3Properties,
/// SynchronisationMode, RT_Class3TimingProperties and the ports' delays;
/// line 456 and its 17 siblings: each module's IsochroneMode), as class C,
/// and no change of theirs is left in the round trip.
#[test]
fn isochronous_real_time_and_mode_import_with_the_files_values() {
    let imported = corpus_import(MOVI_C);
    assert_says(
        written(&imported, MOVI_C),
        &[
            "conformance_class = \"C\"",
            "[profinet.irt]\nmax_bridge_delay = 5500\nmax_number_ir_frame_data = 256\nforwarding_mode = [\"Relative\"]\nstartup_mode = [\"Advanced\", \"Legacy\"]\nsend_clock = [32, 64, 128]\nreduction_ratio = [1, 2, 4, 8, 16]\npreferred_send_clock = 32\nmax_local_jitter = 50\nt_pll_max = 1000\nport_tx_delay = 92\nport_rx_delay = 340\n",
            "[profinet.isochronous]\nrequired = false\nt_dc_base = 32\nt_dc_min = 1\nt_dc_max = 32\nt_io_base = 125000\nt_io_input_min = 1\nt_io_output_min = 1\n",
        ],
    );
    let irt_words = [
        "Isochrone",
        "RT_Class3",
        "RT_CLASS",
        "Synchronisation",
        "MaxPortTxDelay",
        "MaxPortRxDelay",
        "DelayMeasurement",
        "ConformanceClass",
    ];
    for code in ["E601", "W600"] {
        for message in messages(&imported, code) {
            assert!(!irt_words.iter().any(|w| message.contains(w)), "{message}");
        }
    }
    // Its `Isochronous;EnergySaving` application class, the modules'
    // isochronous mode's and PROFIenergy's, is the file's.
    for code in ["E601", "W600"] {
        assert!(!messages(&imported, code)
            .iter()
            .any(|m| m.contains("ApplicationClass")));
    }
}

/// Class C without the RT_CLASS_3 properties the description needs (here
/// MOVI-C without its RT_Class3Properties) is imported as class B, marked
/// with why, and without isochronous mode, which needs RT_CLASS_3 (E188).
#[test]
fn class_c_without_its_rt_class_3_properties_is_imported_as_b_saying_why() {
    let text = corpus_gsdml_text(MOVI_C);
    let properties = "<RT_Class3Properties ForwardingMode=\"Relative\" MaxBridgeDelay=\"5500\" MaxNumberIR_FrameData=\"256\" StartupMode=\"Advanced;Legacy\"/>";
    assert_eq!(text.matches(properties).count(), 3, "one per DAP");
    let imported = import(MOVI_C, text.replace(properties, "").as_bytes());
    let toml = draft(&imported);
    assert!(
        !toml.contains("\n[profinet.irt]\n") && !toml.contains("\n[profinet.isochronous]\n"),
        "{toml}"
    );
    let (ir, _) = descriptions::load_text("movi-c.toml", toml);
    let decision = ir
        .expect("builds")
        .decisions
        .into_iter()
        .find(|d| d.path == "profinet.conformance_class")
        .expect("marked");
    assert_eq!(decision.value, "\"B\"");
    let why = "conformance class C is imported as B: the interface's RT_CLASS_3 is not imported";
    assert!(decision.reason.starts_with(why), "{}", decision.reason);
    assert!(messages(&imported, "W600")
        .iter()
        .any(|m| m.starts_with(why)));
    assert!(messages(&imported, "W600")
        .iter()
        .any(|m| m.starts_with("VirtualSubmoduleItem IsochroneMode@T_DC_Base is not imported")));
}

/// A GSDML file name's vendor and family may both hold `-`: the import
/// splits them where the family is the file's ProductFamily or the vendor
/// its VendorName, at the only `-` when there is one, and otherwise at the
/// first, marked under `[choices]` as its choice. The name the build
/// writes is the same either way.
#[test]
fn a_file_names_vendor_and_family_are_split_as_the_file_names_them() {
    let files = gsdc::compile(&descriptions::load("mv810-pnet02.toml")).unwrap();
    let (_, gsdml) = descriptions::one(files, ArtifactKind::Gsdml);
    // VendorName="Megmeet", ProductFamily="MV800".
    for (name, vendor, family, chosen) in [
        (
            "GSDML-V2.32-MEGMEET-MV-800-20230830.xml",
            "MEGMEET",
            "MV-800",
            false,
        ),
        (
            "GSDML-V2.32-MEG-MEET-MV800-20230830.xml",
            "MEG-MEET",
            "MV800",
            false,
        ),
        (
            "GSDML-V2.32-MEG-MEET-MV-800-20230830.xml",
            "MEG",
            "MEET-MV-800",
            true,
        ),
    ] {
        let imported = import(name, gsdml.as_bytes());
        let toml = imported
            .description
            .as_deref()
            .or(imported.draft.as_deref())
            .unwrap_or_else(|| panic!("{name}: {:#?}", imported.diagnostics));
        assert!(
            toml.contains(&format!("file_vendor = \"{vendor}\"")),
            "{name}"
        );
        assert!(toml.contains(&format!("family = \"{family}\"")), "{name}");
        assert_eq!(toml.contains("\"device.family\" = "), chosen, "{name}");
        let (ir, diagnostics) = descriptions::load_text("mv810.toml", toml);
        let ir = ir.unwrap_or_else(|| panic!("{name}: {diagnostics:#?}"));
        assert_eq!(ir.profinet.unwrap().file_name, name);
    }
}

/// A GSD file name that is not 8.3 is replaced, and the description's
/// `profibus.file_name` is marked under `[choices]` with why.
#[test]
fn a_gsd_file_name_that_is_not_8_3_is_marked_with_why() {
    let files = gsdc::compile(&descriptions::load("9kdp1.toml")).unwrap();
    let (_, gsd) = descriptions::one(files, ArtifactKind::Gsd);
    let imported = import("9kdp1-card.gsd", gsd.as_bytes());
    let toml = imported
        .description
        .as_deref()
        .or(imported.draft.as_deref())
        .expect("its import builds");
    let mark = toml
        .lines()
        .find(|l| l.starts_with("\"profibus.file_name\" = "))
        .unwrap_or_else(|| panic!("{toml}"));
    assert!(
        mark.contains("`9kdp1-card.gsd` is not a GSD file name (8.3)"),
        "{mark}"
    );
}

/// A GSD and a GSDML file whose device access point has no hardware
/// release (a DAP may have none): the one description takes the GSD's,
/// which the build then writes in the GSDML file too; the import says so.
#[test]
fn a_release_only_the_gsd_has_is_said_when_both_are_imported() {
    let files = gsdc::compile(&descriptions::load("md810dp.toml")).unwrap();
    let (gsd_name, gsd) = descriptions::one(files.clone(), ArtifactKind::Gsd);
    let (gsdml_name, gsdml) = descriptions::one(files.clone(), ArtifactKind::Gsdml);
    let release = gsdml
        .lines()
        .find(|l| l.trim_start().starts_with("<HardwareRelease "))
        .unwrap();
    let without = gsdml.replacen(release, "", 1);
    let both = import_both(
        (&gsd_name, gsd.as_bytes()),
        (&gsdml_name, without.as_bytes()),
        &beside(&files),
    );
    let said = format!("{gsdml_name} has no ModuleInfo/HardwareRelease@Value: the description's is the GSD's Hardware_Release");
    assert!(
        messages(&both.gsd, "W600")
            .iter()
            .any(|m| m.starts_with(&said)),
        "{:#?}",
        both.gsd.diagnostics
    );
}

/// FENA's stack, as its device access points and modules declare it
/// (lines 27 to 480 of the file, read by hand): all three give their IP address by
/// `LOCAL;DCP`, accept one device access AR and keep their name of
/// station; the first two also a shared device, two IO ARs, slots 0 to 2
/// and IOConfigData of 44 bytes in and 42 out, where the third (FENA-01,
/// 0x00000004) declares neither of the first two, slots 0 to 1 and 42
/// bytes each way. Every port
/// lets the controller set its MAU type (100BASE-TX, also written as the
/// older `MAUTypes` attribute), and every submodule of its modules has
/// `Writeable_IM_Records="1 2 3"`. The import states
/// the first's in `[profinet.stack]` and the third's difference in its
/// entry, and the round trip finds none of these attributes changed.
#[test]
fn fenas_stack_imports_per_device_access_point() {
    let imported = corpus_import(FENA);
    let toml = written(&imported, FENA);
    assert_says(
        toml,
        &[
            "[profinet.stack]\naddress_assignment = [\"LOCAL\", \"DCP\"]\ndevice_access = true\ndevice_access_ars = 1\nname_of_station_not_transferable = true\nshared_device = true\nmau_type_adjustable = true\napplication_relations = 2\nmax_input_length = 44\nmax_output_length = 42\n",
            "ident = 0x00000004\n",
            "stack = { shared_device = false, application_relations = 1, last_slot = 1, max_input_length = 42 }",
            // Every module's submodules (the telegrams' access points too)
            // take I&M1 to I&M3 writes.
            "module_writeable_im_records = [1, 2, 3]\n",
        ],
    );
    let third = toml.find("ident = 0x00000004").unwrap();
    let entry_end = toml[third..].find("\n\n").map_or(toml.len(), |e| third + e);
    assert!(
        toml[third..entry_end].contains("stack = "),
        "the third DAP's entry states its stack"
    );
    let stack_changes: Vec<&str> = messages(&imported, "E601")
        .into_iter()
        .filter(|m| {
            [
                "AddressAssignment",
                "DeviceAccessSupported",
                "NumberOfDeviceAccessAR",
                "NameOfStationNotTransferable",
                "SharedDeviceSupported",
                "NumberOfAR",
                "MaxInputLength",
                "MaxOutputLength",
                "PhysicalSlots",
                "Writeable_IM_Records",
                "MAUType",
            ]
            .iter()
            .any(|a| m.contains(a))
        })
        .collect();
    assert!(stack_changes.is_empty(), "{stack_changes:#?}");
}

/// A second device access point whose stack differs states only that, and
/// the import is written (its round trip clean); a stack attribute the
/// description cannot say is left out at the attribute (W600), and the
/// round trip judges leaving it out.
#[test]
fn a_device_access_points_stack_imports_as_what_it_changes_or_is_left_out_at_its_attribute() {
    let shared = md810_with_second_dap(|dap| {
        renumbered(dap).replacen(
            "ResetToFactoryModes=\"2\"",
            "ResetToFactoryModes=\"2\" SharedDeviceSupported=\"true\" AddressAssignment=\"DCP;DHCP\"",
            1,
        )
    });
    let toml = written(&shared, "a DAP whose stack differs");
    assert_says(
        toml,
        &["stack = { address_assignment = [\"DCP\", \"DHCP\"], shared_device = true }"],
    );
    assert!(!toml.contains("[profinet.stack]"), "the first's is gsdc's");

    // An xsd:boolean of 1 is true, as the comparison reads it.
    let one_is_true = md810_gsdml_changed(|gsdml| {
        gsdml.replacen(
            "DeviceAccessSupported=\"false\"",
            "DeviceAccessSupported=\"1\"",
            1,
        )
    });
    let toml = written(&one_is_true, "DeviceAccessSupported=\"1\"");
    assert_says(toml, &["[profinet.stack]\ndevice_access = true\n"]);

    let unknown_way = md810_gsdml_changed(|gsdml| {
        gsdml.replacen(
            "ResetToFactoryModes=\"2\"",
            "ResetToFactoryModes=\"2\" AddressAssignment=\"DCP;BOOTP\"",
            1,
        )
    });
    assert!(
        messages(&unknown_way, "W600")
            .iter()
            .any(|m| m.starts_with("AddressAssignment `DCP;BOOTP` is not imported")),
        "{:#?}",
        messages(&unknown_way, "W600")
    );
    assert!(
        messages(&unknown_way, "E601")
            .iter()
            .any(|m| m.contains("AddressAssignment")),
        "the round trip judges what was left out"
    );

    let too_short = md810_gsdml_changed(|gsdml| {
        let at = gsdml.find("MaxInputLength=\"").unwrap() + "MaxInputLength=\"".len();
        let end = at + gsdml[at..].find('"').unwrap();
        format!("{}4{}", &gsdml[..at], &gsdml[end..])
    });
    assert!(
        messages(&too_short, "W600")
            .iter()
            .any(|m| m.starts_with("IOConfigData@MaxInputLength `4` is not imported")),
        "{:#?}",
        messages(&too_short, "W600")
    );

    let ars_without_access = md810_gsdml_changed(|gsdml| {
        gsdml.replacen(
            "ResetToFactoryModes=\"2\"",
            "ResetToFactoryModes=\"2\" NumberOfDeviceAccessAR=\"1\"",
            1,
        )
    });
    assert!(
        messages(&ars_without_access, "W600")
            .iter()
            .any(|m| m.starts_with("NumberOfDeviceAccessAR is not imported") && m.contains("E184")),
        "{:#?}",
        messages(&ars_without_access, "W600")
    );
}

/// FENA's channel diagnosis (lines 762 to 847, read by hand): PROFIdrive's
/// 19 fault classes 0x9000 to 0x9012 in the profile's API and nine
/// PROFIsafe error types 64 to 72 (0x0040 to 0x0048), each with a name
/// (English only) and none with extended diagnosis: all 28 are imported
/// with their names, and the round trip finds none changed. SEW's MOVI-C's
/// 70 (`grep -c '<ChannelDiagItem'`) are imported with their 800
/// `ExtChannelDiagItem`s (`grep -c`), each with its add value's one
/// `DataItem Id="1" DataType="Unsigned32"` (line 1238, and 800 such lines;
/// the first one's name at line 7338), and texts that break lines (917
/// `&#10;`; line 7321's help, of error type 72, lists three remedies); the
/// 54 channel diagnoses' helps whose text is empty in both languages (108
/// `_HELP" Value=""`, the first at line 7335) are left out with a note
/// each. The round trip finds no channel diagnosis changed.
#[test]
fn channel_diagnosis_imports_with_its_texts() {
    let imported = corpus_import(FENA);
    let toml = written(&imported, FENA);
    assert_eq!(toml.matches("[[profinet.channel_diagnosis]]").count(), 28);
    assert_says(
        toml,
        &[
            "[[profinet.channel_diagnosis]]\nerror_type = 0x9000\napi = 0x3A00\nname = \"Microcontroller Hardware or Software\"\n",
            "[[profinet.channel_diagnosis]]\nerror_type = 0x0040\nname = \"Mismatch of safety destination address (F_Dest_Add)\"\n",
        ],
    );
    let diagnosis_changes: Vec<&str> = messages(&imported, "E601")
        .into_iter()
        .filter(|m| m.contains("ChannelDiag"))
        .collect();
    assert!(diagnosis_changes.is_empty(), "{diagnosis_changes:#?}");

    let imported = corpus_import(MOVI_C);
    let toml = written(&imported, MOVI_C);
    assert_eq!(toml.matches("[[profinet.channel_diagnosis]]\n").count(), 70);
    assert_eq!(
        toml.matches("[[profinet.channel_diagnosis.extended]]\n")
            .count(),
        800
    );
    assert_eq!(
        toml.matches("add_value = [{ id = 1, type = \"Unsigned32\" }]\n")
            .count(),
        800
    );
    assert_says(
        toml,
        &[
            "[[profinet.channel_diagnosis.extended]]\nerror_type = 0x0001\nname = { en = \"E-1.1 Short circuit in motor output terminals 'Overcurrent in output stage or faulty output stage control detected, and output stage inhibited by hardware'\", de = \"E-1.1 Kurzschluss Motorausgangsklemmen",
            "help = { en = \"– Acknowledge the warning.\\n– Establish safe communication again.\\n– If the warning occurs repeatedly,",
        ],
    );
    let empty_helps = messages(&imported, "W600")
        .into_iter()
        .filter(|m| {
            m.starts_with("the Help of ChannelDiagItem ") && m.contains("empty in every language")
        })
        .count();
    assert_eq!(empty_helps, 54);
    let diagnosis_changes: Vec<&str> = messages(&imported, "E601")
        .into_iter()
        .filter(|m| m.contains("ChannelDiag"))
        .collect();
    assert!(diagnosis_changes.is_empty(), "{diagnosis_changes:#?}");
}

/// A card's GSD with a GSDML file of two device access points: the
/// GSDML's `[[profinet.daps]]` entry is in the one description (the
/// merge kept `[profinet...]` tables and dropped `[[profinet...]]`
/// entries), and both files rebuild clean.
#[test]
fn a_gsd_and_a_gsdml_file_of_two_access_points_import_both() {
    let files = gsdc::compile(&descriptions::load("md810dp.toml")).unwrap();
    let beside = beside(&files);
    let (gsd_name, gsd) = descriptions::one(files.clone(), ArtifactKind::Gsd);
    let (gsdml_name, gsdml) = descriptions::one(files.clone(), ArtifactKind::Gsdml);
    let gsdml = with_second_dap(&gsdml, &renumbered);
    let both = import_both(
        (&gsd_name, gsd.as_bytes()),
        (&gsdml_name, gsdml.as_bytes()),
        &beside,
    );
    let toml = both
        .description
        .as_deref()
        .unwrap_or_else(|| panic!("{:#?} {:#?}", both.gsd.diagnostics, both.gsdml.diagnostics));
    assert_says(toml, &["[[profinet.daps]]\n", "ident = 0x00000009\n"]);
    assert!(both.gsd.round_trip.is_clean() && both.gsdml.round_trip.is_clean());
}

/// A later device access point with more ports than the first takes the
/// first's IO limit and needs more: gsdc writes its need (13 bytes for
/// standard telegram 1 behind its access point with four ports), and the
/// import states nothing for it, so the file rebuilds the same.
#[test]
fn a_later_access_point_needing_more_than_the_firsts_io_limit_round_trips() {
    let fixture =
        std::fs::read_to_string(support::checkout("tests/fixtures/valid/own_idents.toml")).unwrap();
    let text = fixture
        .replacen(
            "application_relations = 2\n",
            "application_relations = 2\nmax_input_length = 12\nmax_output_length = 12\n",
            1,
        )
        .replace(
            "modules = [\"",
            "ports = 4\nport_idents = [0x00000103, 0x00000103, 0x00000103, 0x00000103]\nmodules = [\"",
        );
    let text = descriptions::own_idents_port_texts(&text, 4);
    assert_ne!(text, fixture);
    let (file_name, gsdml) = built("own_idents.toml", &text, ArtifactKind::Gsdml);
    assert_eq!(gsdml.matches("MaxInputLength=\"").count(), 4);
    assert!(gsdml.contains("MaxInputLength=\"12\" MaxOutputLength=\"12\""));
    assert!(gsdml.contains("MaxInputLength=\"13\" MaxOutputLength=\"13\""));
    let imported = import(&file_name, gsdml.as_bytes());
    let toml = written(&imported, "own_idents with a four-port access point");
    assert!(
        !toml.contains("max_input_length = 13"),
        "the need is not stated"
    );
}

/// MaxDataLength, stated for the first access point, is every later one's
/// too (the second of own_idents needs 20 bytes in and out together, and
/// takes the first's 22): the import states it once and the file rebuilds
/// the same. A later access point without one, under a first with one, is
/// one the description cannot say: left out, saying why.
#[test]
fn a_later_access_points_max_data_length_is_the_firsts_or_it_is_left_out() {
    let fixture =
        std::fs::read_to_string(support::checkout("tests/fixtures/valid/own_idents.toml")).unwrap();
    let text = fixture.replacen(
        "application_relations = 2\n",
        "application_relations = 2\nmax_data_length = 22\n",
        1,
    );
    assert_ne!(text, fixture);
    let (file_name, gsdml) = built("own_idents.toml", &text, ArtifactKind::Gsdml);
    let stated = " MaxDataLength=\"22\"";
    assert_eq!(gsdml.matches(stated).count(), 4);
    let imported = import(&file_name, gsdml.as_bytes());
    let toml = written(&imported, "own_idents with MaxDataLength");
    assert_eq!(toml.matches("max_data_length = 22\n").count(), 1, "{toml}");
    assert!(!toml.contains("max_data_length = 20"));

    let second = gsdml.match_indices(stated).nth(1).unwrap().0;
    let without = format!("{}{}", &gsdml[..second], &gsdml[second + stated.len()..]);
    let imported = import(&file_name, without.as_bytes());
    assert!(imported.description.is_none());
    let why = "it has no IOConfigData@MaxDataLength, which the first has";
    assert!(
        messages(&imported, "W600").iter().any(|m| m.contains(why)),
        "{:#?}",
        messages(&imported, "W600")
    );
}

/// ABB FENA's stop mode and control-zero mode are the first two bytes of
/// every module's record 1: Integer8s the user may change, the stop mode's
/// default 1 in the PPO modules, 0 in the standard telegrams. The import
/// states each one's type and each kind's default (`per_module` with
/// `changeable`), and the round trip finds no change in either, in any
/// module.
#[test]
fn fenas_byte_settings_with_per_module_defaults_round_trip() {
    let imported = corpus_import(FENA);
    assert_says(
        written(&imported, FENA),
        &[
            "name = \"Stop Mode Action selection\"\ntype = \"Integer8\"\ndefault = 1\n",
            "per_module = { user_defined = 1, standard_telegram_1 = 0, standard_telegram_2 = 0, changeable = true }",
            "name = \"Control-zero mode selection\"\ntype = \"Integer8\"\n",
        ],
    );
    let settings = ["Stop Mode Action selection", "Control-zero mode selection"];
    let changed: Vec<&str> = messages(&imported, "E601")
        .into_iter()
        .filter(|m| settings.iter().any(|s| m.contains(s)))
        .collect();
    assert!(changed.is_empty(), "{changed:#?}");
}

/// FENA's record 1 ends, after the two settings, with one fail-safe value
/// per output item of the module: one Unsigned16 per PZD word of a PPO
/// module ("Fail safe Control Word", ... "Fail safe value of Ref PZD12"),
/// STW1 and NSOLL_A in standard telegram 1, STW1, NSOLL_B (an Unsigned32)
/// and STW2 in telegram 2. The import names them by kind of module in
/// `[profinet.fail_safe_values]`, keeps them out of `[[settings]]`, and
/// the round trip finds no change in any module's record 1.
#[test]
fn fenas_fail_safe_values_round_trip() {
    let imported = corpus_import(FENA);
    let toml = written(&imported, FENA);
    let pzd: Vec<String> = ["Control Word", "Reference"]
        .map(|n| format!("\"Fail safe {n}\""))
        .into_iter()
        .chain((3..=12).map(|n| format!("\"Fail safe value of Ref PZD{n}\"")))
        .collect();
    let table = format!(
        "[profinet.fail_safe_values]\nuser_defined = [{}]\nstandard_telegram_1 = [\"Fail safe STW1\", \"Fail safe NSOLL_A\"]\nstandard_telegram_2 = [\"Fail safe STW1\", \"Fail safe NSOLL_B\", \"Fail safe STW2\"]\n",
        pzd.join(", ")
    );
    assert_says(toml, &[table.as_str()]);
    assert!(!toml.contains("name = \"Fail safe"), "{toml}");
    let record_1: Vec<&str> = messages(&imported, "E601")
        .into_iter()
        .filter(|m| m.contains("record 1 "))
        .collect();
    assert!(record_1.is_empty(), "{record_1:#?}");
}

/// PhysicalSlots is a set: overlapping ranges and repeats name the slots
/// from 0 to the last as `0..3` does, and a range is never expanded, so a
/// hostile list of 20,000 ranges of 65,536 slots each (billions of slots)
/// is read as the one range it is, and left out as beyond gsdc's last
/// slot. A list with a token that is not a number is left out at its
/// attribute, whatever follows it.
#[test]
fn physical_slots_import_as_a_set_of_ranges() {
    let slots = |list: String| {
        md810_gsdml_changed(|gsdml| {
            gsdml.replacen(
                "PhysicalSlots=\"0..1\"",
                &format!("PhysicalSlots=\"{list}\""),
                1,
            )
        })
    };
    let overlapping = slots("0..2 1..3 3 2".into());
    assert_says(written(&overlapping, "overlapping"), &["last_slot = 3\n"]);
    let hostile = slots(["0..65535"; 20_000].join(" "));
    // Beyond gsdc's last slot (32767): left out at the attribute.
    let hostile = messages(&hostile, "W600").join("\n");
    assert!(hostile.contains("1 to 32767"), "{hostile}");
    let garbage = slots("x 0..3".into());
    assert!(
        messages(&garbage, "W600")
            .iter()
            .any(|m| m.contains("PhysicalSlots `x 0..3`")),
        "{:#?}",
        garbage.diagnostics
    );
}

/// A card's PROFINET description with `settings` and `pzd_lengths`, and
/// `rest` after `[profinet]`'s keys.
fn pn_card(settings: &[&str], pzd_lengths: &str, rest: &str) -> String {
    let settings: String = settings
        .iter()
        .map(|name| {
            format!("[[settings]]\nname = \"{name}\"\ndefault = 0\nrange = [0, 65535]\nset_at = \"master\"\n\n")
        })
        .collect();
    format!(
        "[device]\nvendor = \"Acme\"\nfamily = \"X1\"\nmodel = \"X1PN\"\nrevision = \"V1\"\n\
         hardware_release = \"V1\"\nsoftware_release = \"V1\"\nname = \"X1 PROFINET card\"\n\n\
         [telegram]\npkw = \"none\"\npzd_words = 4\nprofidrive = false\n\n{settings}\
         [profinet]\nvendor_id = {{ value = 0x1234 }}\ndevice_id = {{ value = 0x0001 }}\n\
         date = 2026-01-31\ndns_name = \"x1-pn\"\nmin_device_interval = 32\nports = 1\n\
         pzd_lengths = {pzd_lengths}\nmodule_pkw = \"without\"\n{rest}"
    )
}

/// The description the import of `description`'s GSDML writes, after
/// checking that it rebuilds the file byte-identical below the header.
fn gsdml_round_trip(description: &str) -> String {
    let (file_name, gsdml) = built("card.toml", description, ArtifactKind::Gsdml);
    let imported = import(&file_name, gsdml.as_bytes());
    let toml = written(&imported, "card.toml").to_string();
    let (rebuilt, diagnostics) = descriptions::load_text("imported.toml", &toml);
    let rebuilt = rebuilt.unwrap_or_else(|| panic!("{diagnostics:#?}"));
    let (_, text) = descriptions::one(gsdc::compile(&rebuilt).unwrap(), ArtifactKind::Gsdml);
    assert_eq!(gsdml_body(&text), gsdml_body(&gsdml), "{toml}");
    toml
}

/// The import tells fail-safe values from settings by what settings alone
/// cannot rebuild. A card of one module whose last settings happen to be
/// Unsigned16s of any value, default 0, as many as its output words, keeps
/// them as settings (they are every module's, and User_Prm_Data's on a
/// card with both buses); copies that differ by the module's output items
/// are fail-safe values, and a setting that shares a fail-safe value's name
/// is still found among the settings of each module's copy.
#[test]
fn fail_safe_values_are_told_from_settings_by_what_settings_cannot_rebuild() {
    let one_module = gsdml_round_trip(&pn_card(
        &[
            "Stop mode",
            "Speed scaling",
            "Torque scaling",
            "Ramp",
            "Limit",
        ],
        "[4]",
        "",
    ));
    assert!(!one_module.contains("fail_safe_values"), "{one_module}");
    assert_says(&one_module, &["name = \"Torque scaling\""]);
    let fail_safe = "[profinet.fail_safe_values]\nuser_defined = [\"A\", \"B\", \"C\", \"D\"]\nstandard_telegram_1 = [\"Stop mode\", \"X\"]\n";
    let two_kinds = gsdml_round_trip(&pn_card(
        &["Stop mode"],
        "[2, 4]",
        &format!(
            "standard_telegram_1 = true\n\n[profinet.module_name]\nstandard_telegram_1 = \"Telegram 1\"\n\n{fail_safe}"
        ),
    ));
    assert_says(&two_kinds, &[fail_safe]);
}

/// An access point's RequiredSchemaVersion up to V2.32, the version gsdc
/// writes, imports and rebuilds as the file has it (V2.3 written as PI's
/// names write it, not V2.30); a later one is left out, saying why, and the
/// round trip names the change (nothing written).
#[test]
fn a_required_schema_version_imports_up_to_the_one_gsdc_writes() {
    let requiring = |version: &str| {
        let attribute = format!(" PNIO_Version=\"V2.32\" RequiredSchemaVersion=\"{version}\"");
        md810_gsdml_changed(|gsdml| gsdml.replacen(" PNIO_Version=\"V2.32\"", &attribute, 1))
    };
    let imported = requiring("V2.3");
    let toml = written(&imported, "MD810 requiring V2.3");
    assert!(
        toml.contains("required_schema_version = \"2.3\"\n"),
        "{toml}"
    );
    let (_, rebuilt) = built("md810-imported.toml", toml, ArtifactKind::Gsdml);
    assert!(rebuilt.contains(" RequiredSchemaVersion=\"V2.3\""));

    let imported = requiring("V2.4");
    assert!(imported.description.is_none());
    let why = "the description's required_schema_version is a GSDML version up to the file's, V2.32 (E190)";
    assert!(
        messages(&imported, "W600").iter().any(|m| m.contains(why)),
        "{:#?}",
        messages(&imported, "W600")
    );
    assert!(messages(&imported, "E601")
        .iter()
        .any(|m| m.contains("RequiredSchemaVersion")));
}

/// Labels the description cannot say are left out, saying why: an access
/// point of own_idents without its SubslotList, while the others have
/// theirs (the description's labels are every access point's).
#[test]
fn labels_only_some_access_points_give_are_left_out() {
    let fixture =
        std::fs::read_to_string(support::checkout("tests/fixtures/valid/own_idents.toml")).unwrap();
    let (file_name, gsdml) = built("own_idents.toml", &fixture, ArtifactKind::Gsdml);
    let lists: Vec<(usize, &str)> = gsdml.match_indices("<SubslotList>").collect();
    assert_eq!(lists.len(), 4);
    let second = lists[1].0;
    let end = second + gsdml[second..].find("</SubslotList>").unwrap() + "</SubslotList>".len();
    let without = format!("{}{}", &gsdml[..second], &gsdml[end..]);
    let imported = import(&file_name, without.as_bytes());
    let why = "its SubslotList does not label its interface and then each of its ports, and the description's subslot_labels are every access point's";
    assert!(
        messages(&imported, "W600").iter().any(|m| m.contains(why)),
        "{:#?}",
        messages(&imported, "W600")
    );
    let toml = imported
        .description
        .as_deref()
        .or(imported.draft.as_deref())
        .unwrap();
    assert!(!toml.contains("subslot_labels"), "{toml}");
}

/// FENA's modules repeat its access points' releases (lines 192-193 and
/// those of the five other modules: `HardwareRelease Value="1"`,
/// `SoftwareRelease Value="V3.2.0"`, as the first access point's lines
/// 33-34): the import says `module_releases`, and the round trip finds no
/// module's release changed.
#[test]
fn modules_repeating_the_cards_releases_import() {
    let imported = assert_imported_and_kept(
        &[(
            FENA,
            "hardware_release = \"1\"\nsoftware_release = \"V3.2.0\"\n",
        )],
        |change| change.contains("Release"),
    );
    assert_says(written(&imported[0], FENA), &["module_releases = true\n"]);
    assert!(!messages(&imported[0], "W600")
        .iter()
        .any(|m| m.contains("Release")));
}

/// FENA's modules' own names and info texts, and their data submodules'
/// (lines 188-218 for PPO type 3, texts at lines 934-936; lines 399-436 for
/// standard telegram 1, texts at 897-900), import as `module_texts` in
/// place of gsdc's, and the round trip finds no module's or submodule's
/// name or info text changed (the data items' names are still gsdc's).
#[test]
fn modules_own_names_and_info_texts_import() {
    let imported = assert_imported_and_kept(
        &[(FENA, "[profinet.module_texts.pzd2]\nname = \"PPO Type 3\"\ninfo = \"PPO Type 3\"\nsubmodule_name = \"PPO3 Data Object\"\nsubmodule_info = \"Control/Reference and Status/Actual values\"\n")],
        |change| {
            let text = change.contains(" name: ") || change.contains(" info text: ");
            let of_a_module = change.starts_with("module")
                || change.starts_with("submodule \"") && !change.contains("Access Point");
            text && of_a_module
        },
    );
    assert_says(
        written(&imported[0], FENA),
        &["[profinet.module_texts.telegram1]\nname = \"Standard Telegram 1\"\ninfo = \"Standard Telegram 1\"\nsubmodule_info = \"Control/Reference and Status/Actual values\"\n"],
    );
    assert!(!messages(&imported[0], "W600")
        .iter()
        .any(|m| m.contains("InfoText")));
}

/// FENA names its PPO modules' PZD words (lines 199-204 for PPO type 3:
/// "Status", "Speed Actual", "Command", "Speed Reference"; PPO type 7's
/// "Actual PZD3" to "Reference PZD12" at lines 337-392), the same word alike
/// in every module: the import states them as `pzd_names`, and the round
/// trip finds no PPO module's data item renamed (the standard telegrams',
/// the profile's, are gsdc's).
#[test]
fn the_pzd_words_names_import() {
    let quoted = |first: [&str; 2], rest: &str| {
        let rest = (3..=12).map(|n| format!("{rest} PZD{n}"));
        let names: Vec<String> = first.iter().map(|s| s.to_string()).chain(rest).collect();
        let names: Vec<String> = names.iter().map(|n| format!("\"{n}\"")).collect();
        format!("[{}]", names.join(", "))
    };
    let says = format!(
        "[profinet.pzd_names]\noutput = {}\ninput = {}\n",
        quoted(["Command", "Speed Reference"], "Reference"),
        quoted(["Status", "Speed Actual"], "Actual"),
    );
    let imported = assert_imported_and_kept(&[(FENA, &says)], |change| {
        change.starts_with("item") && change.contains("of module \"PPO Type")
    });
    assert!(!messages(&imported[0], "W600")
        .iter()
        .any(|m| m.contains("PZD")));
}

/// What FENA's access points are based on (lines 27, 77, 134:
/// `ImplementationType="ADI Blackfin"`) imports, and the round trip finds it
/// unchanged in each.
#[test]
fn what_the_access_points_are_based_on_imports() {
    assert_imported_and_kept(
        &[(FENA, "implementation_type = \"ADI Blackfin\"\n")],
        |change| change.contains("ImplementationType"),
    );
}

/// The family the catalog shows where the file name's is another: FENA's
/// (line 22: `ProductFamily="ABB FENA"`, its name's `FENA`) and MOVI-C's
/// (line 22: "MOVI-C Decentralized Electronics", its name's
/// `MOVI-C-Decentralized-Electronics`) import, and the round trip finds
/// them unchanged.
#[test]
fn the_product_family_imports() {
    assert_imported_and_kept(
        &[
            (FENA, "product_family = \"ABB FENA\"\n"),
            (
                MOVI_C,
                "product_family = \"MOVI-C Decentralized Electronics\"\n",
            ),
        ],
        |change| change.contains("ProductFamily"),
    );
}

/// FENA calls each word of its standard telegrams "Output" or "Input"
/// (lines 417-422 and 460-467: `T_ID_STD_STD_TGM1_OUTPUT`, line 894
/// "Output"): the profile's words import under their abbreviations, and the
/// round trip finds no data item renamed. Where telegram 2 names STW1
/// otherwise than telegram 1, the description cannot say both: STW1 is
/// left out, the other words still import.
#[test]
fn the_profile_words_names_import() {
    let says = "[profinet.profile_word_names]\nSTW1 = \"Output\"\nNSOLL_A = \"Output\"\nZSW1 = \"Input\"\nNIST_A = \"Input\"\nNSOLL_B = \"Output\"\nSTW2 = \"Output\"\nNIST_B = \"Input\"\nZSW2 = \"Input\"\n";
    assert_imported_and_kept(&[(FENA, says)], |change| {
        change.starts_with("item ") && change.contains(" data of submodule ")
    });
    let fena = corpus_gsdml_text(FENA);
    let telegram_2 = fena.find("ID=\"ID_MODULE_STD_TGM2\"").unwrap();
    let first_output = telegram_2 + fena[telegram_2..].find("TGM1_OUTPUT").unwrap();
    let renamed = format!(
        "{}TGM1_INPUT{}",
        &fena[..first_output],
        &fena[first_output + "TGM1_OUTPUT".len()..]
    );
    let imported = import(FENA, renamed.as_bytes());
    let left_out = messages(&imported, "W600");
    assert!(
        left_out.iter().any(|m| m.starts_with("the name of STW1 ")),
        "{left_out:#?}"
    );
    let description = description_or_draft(&imported);
    assert!(!description.contains("\nSTW1 = "), "{description}");
    assert_says(description, &["NSOLL_A = \"Output\"\n"]);
}

/// FENA describes its modules' access point its own way (lines 411, 454:
/// `T_ID_STD_MAPPAP_INFO_TEXT`, line 896: "Acyclic parameter access is
/// possible through this module"); its name, "Module Access Point", is
/// gsdc's and is not stated. The round trip finds neither changed.
#[test]
fn the_access_points_texts_import() {
    let says = "[profinet.access_point_texts]\ninfo = \"Acyclic parameter access is possible through this module\"\n\n";
    assert_imported_and_kept(&[(FENA, says)], |change| {
        change.starts_with("submodule \"Module Access Point\"")
    });
}

/// MOVI-C names its ports by their connectors (lines 92, 116:
/// `TextId="Port1"`, `"Port2"`; line 7295: "Port 1 - RJ45 (X4233_1)", the
/// German texts the same): the names import, one per port, and the round
/// trip finds no port renamed. Where a second access point names its first
/// port otherwise (MD810's GSDML, changed), the description cannot say
/// both: the names are left out, saying which port.
#[test]
fn the_ports_names_import() {
    let says = "port_names = [{ en = \"Port 1 - RJ45 (X4233_1)\", de = \"Port 1 - RJ45 (X4233_1)\" }, { en = \"Port 2 - RJ45 (X4233_2)\", de = \"Port 2 - RJ45 (X4233_2)\" }]\n";
    assert_imported_and_kept(&[(MOVI_C, says)], |change| {
        change.starts_with("port ") && change.contains(" name: ")
    });
    // MD810's GSDML with a second access point naming its port 1 "Port 2".
    let imported = md810_with_second_dap(|dap| {
        renumbered(dap).replacen("TextId=\"IDT_PORT_1\"", "TextId=\"IDT_PORT_2\"", 1)
    });
    let left_out = messages(&imported, "W600");
    assert!(
        left_out
            .iter()
            .any(|m| m.starts_with("port `V2_IDS_PORT_1`'s name is not imported")),
        "{left_out:#?}"
    );
    let description = imported
        .description
        .as_deref()
        .unwrap_or_else(|| draft(&imported));
    assert!(!description.contains("port_names"), "{description}");
}

/// Each of MOVI-C's data submodules names its module's group too (line 531
/// and on: `CategoryRef="PD Channel"`, as its module does): the import
/// says so, leaves none of the sixteen out, and the round trip finds no
/// CategoryRef changed.
#[test]
fn the_submodules_categories_import() {
    let imported =
        assert_imported_and_kept(&[(MOVI_C, "submodule_categories = true\n")], |change| {
            change.contains("CategoryRef")
        });
    let left_out = messages(&imported[0], "W600");
    assert!(
        !left_out.iter().any(|m| m.contains("CategoryRef")),
        "{left_out:#?}"
    );
}

/// MOVI-C's own records: its access point's record 8200 (lines 62-67: one
/// Bit, its ValueItem "OnOffEnabling" 0 "Off", 1 "On", lines 1126-1131)
/// and each port's records 9000 to 9002 (lines 95-110: record 9001 two
/// Unsigned32 thresholds of default 10, their ValueItems' helps, lines
/// 1146-1151), the same in every port of its three access points. They import, and the round trip finds no record
/// changed. Where one port lacks record 9002, the description cannot give
/// every port the same records: the ports' records are left out, each named.
#[test]
fn the_access_points_and_ports_records_import() {
    let access_point = "[[profinet.access_point_records]]\nindex = 8200\nname = { en = \"Alarm settings (head)\", de = \"Alarmeinstellungen (Kopf)\" }\n\n[[profinet.access_point_records.values]]\nname = { en = \"Enable diagnosis alarms\", de = \"Diagnose - Alarme aktivieren\" }\noffset = 0\nbits = 0\ndefault = 0\nchoices = [{ value = 0, text = { en = \"Off\", de = \"Aus\" } }, { value = 1, text = { en = \"On\", de = \"An\" } }]\n";
    let port = "[[profinet.port_records]]\nindex = 9001\nname = { en = \"Maintenance Required Alarms\", de = \"Maintenance Required Alarme\" }\n\n[[profinet.port_records.values]]\nname = { en = \"Threshold for 'bad rcvd packets' / min\", de = \"Schwellwert 'bad rcvd packets'/min\" }\noffset = 0\ntype = \"Unsigned32\"\ndefault = 10\nhelp = { en = \"Threshold to monitor 'bad received packets' within last minute\", de = \"Schwellwert zur Überwachung von 'bad received packets' innerhalb der letzten Minute\" }\n\n[[profinet.port_records.values]]\nname = { en = \"Threshold for 'bad sent packets' / min\", de = \"Schwellwert 'bad sent packets'/min\" }\noffset = 4\ntype = \"Unsigned32\"\ndefault = 10\nhelp = { en = \"Threshold to monitor 'bad sent packets' within last minute\", de = \"Schwellwert zur Überwachung von 'bad sent packets' innerhalb der letzten Minute\" }\n";
    // V4.0's record 8201 (lines 307-312): one Unsigned8 without
    // AllowedValues whose ValueItem (lines 1132-1138) names 0, 1 and 2
    // (texts lines 7159-7161, 7286-7287, 9045-9047, 9174-9175). It allows
    // those, as gsdc diff reads a Ref with a ValueItemTarget, and imports
    // as a value with the three choices.
    let webserver = "[[profinet.daps.access_point_records]]\nindex = 8201\nname = { en = \"Webserver\", de = \"Webserver\" }\n\n[[profinet.daps.access_point_records.values]]\nname = { en = \"Enable webserver\", de = \"Webserver aktivieren\" }\noffset = 0\ntype = \"Unsigned8\"\ndefault = 0\nchoices = [{ value = 0, text = { en = \"Keep device settings\", de = \"Geräteeinstellung beibehalten\" } }, { value = 1, text = { en = \"Webserver enabled (forced)\", de = \"Webserver aktiviert (forced)\" } }, { value = 2, text = { en = \"Webserver disabled (forced)\", de = \"Webserver deaktiviert (forced)\" } }]\n";
    // No record's change, nor one of its parameters' (their help).
    let imported = assert_imported_and_kept(
        &[(MOVI_C, access_point), (MOVI_C, port), (MOVI_C, webserver)],
        |change| change.starts_with("record ") || change.contains(" of record "),
    );
    let left_out: Vec<&str> = messages(&imported[0], "W600")
        .into_iter()
        .filter(|m| m.starts_with("record "))
        .collect();
    assert_eq!(left_out, Vec::<&str>::new());
    // A choice its type cannot hold (300 of an Unsigned8) leaves it out.
    let text = corpus_gsdml_text(MOVI_C).replacen(
        r#"<Assign Content="2" TextId="WebserverForceDisable"/>"#,
        r#"<Assign Content="300" TextId="WebserverForceDisable"/>"#,
        1,
    );
    let imported_300 = import(MOVI_C, text.as_bytes());
    assert!(messages(&imported_300, "W600").contains(&"record 8201 of the device access point is not imported: a choice of a value of it is not a value of its type"));
    // V2.0's and V4.0's own submodule's records 9000 to 9005 and their
    // ports' none: the entries state them.
    let toml = written(&imported[0], MOVI_C);
    assert_eq!(
        toml.matches("[[profinet.daps.access_point_records]]\nindex = 9005\n")
            .count(),
        2
    );
    assert_eq!(toml.matches("port_records = []\n").count(), 2);
    let imported = import(MOVI_C, movi_c_without_first_ports_9002().as_bytes());
    let left_out = messages(&imported, "W600");
    // 9002 too, which the other ports have.
    for index in [9000, 9001, 9002] {
        let expected = format!("record {index} of the port is not imported: not every port has the same records, which the description gives each port alike");
        assert!(left_out.contains(&expected.as_str()), "{left_out:#?}");
    }
    let description = draft(&imported);
    assert!(!description.contains("port_records"), "{description}");
    assert!(description.contains("[[profinet.access_point_records]]"));
}

/// SEW's MOVI-C's F-modules (lines 406-515), which only its later access
/// points offer (V1.0's UseableModules, lines 40-56, name neither), each
/// with its submodule's record 8200 (lines 429 and 483), under access
/// points that declare no FunctionalSafety class (lines 32, 151, 268):
/// the first's modules are stated without them, the class is off, each
/// F-module has its record, and the import's round trip is clean.
#[test]
fn movi_cs_safety_modules_import_under_its_later_access_points() {
    let imported = corpus_import(MOVI_C);
    let toml = written(&imported, MOVI_C);
    let first_offers: Vec<String> = (1..=16).map(|n| format!("\"pzd{n}\"")).collect();
    assert_says(
        toml,
        &[
            &format!("\ndap_modules = [{}]\n", first_offers.join(", ")),
            "functional_safety_class = false\n",
            "[[profinet.safety_modules.records]]\nindex = 8200\nname = { en = \"Alarm settings (slot)\"",
        ],
    );
    assert_eq!(
        toml.matches("[[profinet.safety_modules.records]]").count(),
        2
    );
    let r = imported.round_trip;
    assert_eq!((r.breaking, r.compatible), (0, 0));
}

/// MOVI-C with its first port's record 9002 (lines 106-110) taken out,
/// which leaves one line there: the lines after it come 4 earlier.
fn movi_c_without_first_ports_9002() -> String {
    let text = corpus_gsdml_text(MOVI_C);
    let start = text
        .find("<ParameterRecordDataItem Index=\"9002\"")
        .unwrap();
    let end = start + text[start..].find("</ParameterRecordDataItem>").unwrap();
    format!(
        "{}{}",
        &text[..start],
        &text[end + "</ParameterRecordDataItem>".len()..]
    )
}

/// FENA's interface name (lines 62, 113, 167:
/// `TextId="T_ID_INTERFACE_MODULE"`, line 872: "Interface"), the same in
/// its three access points, imports, and the round trip finds it unchanged.
#[test]
fn the_interfaces_name_imports() {
    assert_imported_and_kept(&[(FENA, "interface_name = \"Interface\"\n")], |change| {
        change.starts_with("interface") && change.contains(" name: ")
    });
}

/// The strings of the draft's `[draft]` list `key`.
fn draft_list(toml: &str, key: &str) -> Vec<String> {
    let table: toml::Table = toml::from_str(toml).unwrap();
    table["draft"][key]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_str().unwrap().to_string())
        .collect()
}

/// The line (from 1) of a byte offset of `text`.
fn line_of(text: &str, offset: usize) -> usize {
    text[..offset].matches('\n').count() + 1
}

/// A draft lists exactly what `gsdc diff` finds breaking or compatible
/// between the file and the draft's build, each at the file's line, and
/// each part left out (the W600s, at theirs); loaded, it warns (W604) at
/// `[draft]` with how many; without the table the warning is gone and the
/// build is the same.
#[test]
fn a_draft_lists_each_change_of_its_build_and_each_part_left_out() {
    let text = movi_c_without_first_ports_9002();
    let imported = import(MOVI_C, text.as_bytes());
    let toml = draft(&imported);
    assert!(toml.starts_with(&format!(
        "# A DRAFT (gsdc import --draft) of {MOVI_C}: its build is another device.\n"
    )));
    let changes = draft_list(toml, "changes");
    let old = gsdc::device::read(text.as_bytes(), Some(MOVI_C)).unwrap();
    let (_, gsdml) = built("imported.toml", toml, ArtifactKind::Gsdml);
    let new = gsdc::device::read(gsdml.as_bytes(), Some(MOVI_C)).unwrap();
    let found: Vec<String> = gsdc::diff::compare(&old, &new)
        .unwrap()
        .iter()
        .filter(|c| c.class != gsdc::diff::Class::Cosmetic)
        .map(|c| {
            let at = c
                .old
                .as_ref()
                .map_or(String::new(), |p| format!(":{}", p.line));
            format!("{MOVI_C}{at}: {} ({}): {}", c.subject, c.class, c.change)
        })
        .collect();
    assert_eq!(changes, found);
    let r = imported.round_trip;
    assert_eq!(changes.len(), r.breaking + r.compatible);
    // Read by hand: the ports' records can no longer be said, so those of
    // the first access point's ports are gone (its later ones have none):
    // port 1's 9000 and 9001 (lines 95 and 100), port 2's 9000 to 9002
    // (lines 119, 124, 130 of the file, 115, 120, 126 with 9002 cut).
    let removed = [
        (95, 9000, "Alarmsettings (monitoring)", 1),
        (100, 9001, "Maintenance Required Alarms", 1),
        (115, 9000, "Alarmsettings (monitoring)", 2),
        (120, 9001, "Maintenance Required Alarms", 2),
        (126, 9002, "Maintenance Demanded Alarms", 2),
    ];
    let expected: Vec<String> = removed
        .iter()
        .map(|(line, index, name, port)| {
            format!("{MOVI_C}:{line}: record {index} \"{name}\" of port \"Port {port} - RJ45 (X4233_{port})\" at subslot 0x800{port} (0x0000000{}) of DAP \"DFC2xA V1.0\" (0x00007532) (breaking): removed", port + 2)
        })
        .collect();
    assert_eq!(changes, expected);
    let source = &imported.text;
    let w600: Vec<String> = imported
        .diagnostics
        .iter()
        .filter(|d| d.code == "W600")
        .map(|d| {
            let at = d
                .span
                .as_ref()
                .map_or(String::new(), |s| format!(":{}", line_of(source, s.start)));
            format!("{MOVI_C}{at}: {}", d.message)
        })
        .collect();
    let left_out = draft_list(toml, "left_out");
    assert_eq!(left_out, w600);
    assert_eq!(left_out.len(), imported.unsaid);
    let (ir, diagnostics) = descriptions::load_text("imported.toml", toml);
    assert!(ir.is_some(), "{diagnostics:#?}");
    let w604: Vec<&gsdc::Diagnostic> = diagnostics.iter().filter(|d| d.code == "W604").collect();
    assert_eq!(w604.len(), 1);
    assert!(w604[0].message.contains(&format!(
        "({} change(s) and {} part(s) left out, listed in [draft])",
        changes.len(),
        left_out.len()
    )));
    let at = w604[0].span.clone().unwrap();
    assert_eq!(&toml[at.start..at.start + 8], "[draft]\n");
    let confirmed = &toml[..toml.find("\n[draft]\n").unwrap() + 1];
    let (_, diagnostics) = descriptions::load_text("imported.toml", confirmed);
    assert!(diagnostics.iter().all(|d| d.code != "W604"));
    let rebuilt = built("imported.toml", confirmed, ArtifactKind::Gsdml).1;
    assert!(
        gsdml_body(&rebuilt) == gsdml_body(&gsdml),
        "[draft] changes the build"
    );
}

/// A GSD and a GSDML file imported together whose build is another device
/// than the GSDML file: the draft names both files and lists the GSDML
/// file's changes, at its lines.
#[test]
fn a_draft_of_two_files_names_the_file_of_each_change() {
    // An attribute gsdc has no key for, on each port.
    let (both, (gsd_name, _), (gsdml_name, other)) = md810_both_with_gsdml_changed(|gsdml| {
        gsdml.replace(
            "<PortSubmoduleItem ",
            r#"<PortSubmoduleItem SupportsRingportConfig="true" "#,
        )
    });
    assert_eq!(both.description, None);
    let toml = both.draft.as_deref().expect("a draft");
    assert!(toml.starts_with(&format!(
        "# A DRAFT (gsdc import --draft) of {gsd_name} and {gsdml_name}: its build is another device.\n"
    )));
    let port_lines: Vec<usize> = other
        .lines()
        .enumerate()
        .filter(|(_, l)| l.contains("<PortSubmoduleItem "))
        .map(|(i, _)| i + 1)
        .collect();
    let changes = draft_list(toml, "changes");
    assert_eq!(changes.len(), 2, "{changes:#?}");
    for (change, line) in changes.iter().zip(&port_lines) {
        let at = format!("{gsdml_name}:{line}: port ");
        assert!(change.starts_with(&at), "{change}");
        assert!(
            change.ends_with(r#"SupportsRingportConfig (breaking): "true" removed"#),
            "{change}"
        );
    }
    let left_out = draft_list(toml, "left_out");
    let files = [&gsd_name, &gsdml_name];
    assert!(left_out
        .iter()
        .all(|l| files.iter().any(|f| l.starts_with(f.as_str()))));
    for line in &port_lines {
        let at = format!(
            "{gsdml_name}:{line}: PortSubmoduleItem SupportsRingportConfig is not imported"
        );
        assert!(left_out.iter().any(|l| l.starts_with(&at)), "{left_out:#?}");
    }
}

/// `--draft`: a file whose import builds another device (Siemens' IM174) is
/// written as a draft (with its symbol's PNG, MD810's), and the command
/// still exits 1;
/// without `--draft` the refusal says the option is there. A build of the
/// draft warns (W604) and `--deny-warnings` refuses it. An import whose
/// round trip is clean is written as without the option.
#[test]
fn the_draft_option_writes_what_would_be_refused_as_a_draft() {
    let dir = support::scratch("draft");
    let name = "ivangre4__SI018133.GSE";
    let im174 = support::shared(&format!("corpus/gsd/{name}"));
    let out = dir.join("im174.toml");
    let refused = run_import(&im174, &out);
    assert_eq!(refused.status.code(), Some(1));
    assert!(support::stderr(&refused).contains("with `--draft` it is written as a draft"));
    assert!(!out.exists());
    let import = |file: &std::path::Path, out: &std::path::Path| {
        support::gsdc([
            "import".as_ref(),
            file.as_os_str(),
            "--draft".as_ref(),
            "--out".as_ref(),
            out.as_os_str(),
        ])
    };
    let drafted = import(&im174, &out);
    assert_eq!(drafted.status.code(), Some(1));
    assert!(
        support::stderr(&drafted).contains("im174.toml is a draft: its build is another device")
    );
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(text.starts_with(&format!("# A DRAFT (gsdc import --draft) of {name}: ")));
    let library = corpus_gsd_import(name);
    assert_eq!(
        draft_list(&text, "changes"),
        draft_list(draft(&library), "changes")
    );
    let dist = dir.join("dist");
    let build = |deny: bool| {
        let mut args = vec![
            "build".as_ref(),
            out.as_os_str(),
            "--out".as_ref(),
            dist.as_os_str(),
        ];
        if deny {
            args.push("--deny-warnings".as_ref());
        }
        support::gsdc(args)
    };
    let warned = build(false);
    assert_eq!(
        warned.status.code(),
        Some(0),
        "{}",
        support::stderr(&warned)
    );
    assert!(support::stderr(&warned).contains("warning[W604]: a draft import"));
    let denied = build(true);
    assert_eq!(denied.status.code(), Some(1));
    assert!(support::stderr(&denied).contains("warning[W604]"));
    // MD810's GSDML file with an attribute gsdc has no key for, its
    // bitmap beside it: the draft comes with the symbol's PNG. As it is,
    // its round trip is clean: the description, no draft.
    let files = gsdc::compile(&descriptions::load("md810dp.toml")).unwrap();
    for f in &files {
        std::fs::write(dir.join(&f.file_name), &f.contents).unwrap();
    }
    let (name, gsdml) = descriptions::one(files, ArtifactKind::Gsdml);
    let changed_dir = dir.join("changed");
    std::fs::create_dir(&changed_dir).unwrap();
    for f in ["GSDML-0A11-0810-MD810.bmp", name.as_str()] {
        std::fs::copy(dir.join(f), changed_dir.join(f)).unwrap();
    }
    let changed = gsdml.replace(
        "<PortSubmoduleItem ",
        r#"<PortSubmoduleItem SupportsRingportConfig="true" "#,
    );
    std::fs::write(changed_dir.join(&name), changed).unwrap();
    let md810_draft = changed_dir.join("out").join("md810.toml");
    let run = import(&changed_dir.join(&name), &md810_draft);
    assert_eq!(run.status.code(), Some(1), "{}", support::stderr(&run));
    assert!(std::fs::read_to_string(&md810_draft)
        .unwrap()
        .contains("\n[draft]\n"));
    let png = md810_draft.with_file_name("GSDML-0A11-0810-MD810.png");
    assert!(png.exists(), "{}", support::stderr(&run));
    let clean_out = dir.join("md810.toml");
    let clean = import(&dir.join(&name), &clean_out);
    assert_eq!(clean.status.code(), Some(0), "{}", support::stderr(&clean));
    let written = std::fs::read_to_string(&clean_out).unwrap();
    assert!(written.starts_with(&format!("# Imported by gsdc import from {name}.")));
    assert!(!written.contains("[draft]"));
}

/// Siemens' IM174 states I&M in a revision-4 GSD, which no description
/// can say (E124): the import writes revision 5, marked with why, and the
/// round trip names the change (line 243 of the file, read by hand), so
/// the file gives a draft and no description. DPV1 in an older revision
/// than 3 likewise.
#[test]
fn im_in_a_revision_4_gsd_imports_as_revision_5_saying_why() {
    let name = "ivangre4__SI018133.GSE";
    let imported = corpus_gsd_import(name);
    assert_eq!(imported.description, None);
    let toml = draft(&imported);
    assert_says(
        toml,
        &[
            "gsd_revision = 5\n",
            "\"profibus.gsd_revision\" = \"GSD_Revision 4 is imported as 5: the file states Ident_Maintenance_supp, which came with revision 5 (E124); the round trip judges the change\"\n",
        ],
    );
    let changes = draft_list(toml, "changes");
    let revision = format!("{name}:243: GSD_Revision (compatible): \"4\" → \"5\"");
    assert!(changes.contains(&revision), "{changes:#?}");
    // DPV1 in a revision-2 file (MD810's GSD, changed): revision 3.
    let (name, gsd, _) = md810dp_gsd_and_bitmap();
    let old = "GSD_Revision                = 5\r\n";
    assert!(gsd.contains(old));
    let imported = import(
        &name,
        gsd.replacen(old, "GSD_Revision = 2\r\n", 1).as_bytes(),
    );
    assert_says(
        draft(&imported),
        &["gsd_revision = 3\n", "GSD_Revision 2 is imported as 3: the file states DPV1_Slave, which came with revision 3 (E124)"],
    );
}

/// A GSD that gives no device block's bits or areas does not say what its
/// longer diagnosis carries: the import states its Max_Diag_Data_Len as it
/// is, and no device block (SEW's MOVIDRIVE: 16). One that gives them
/// (ABB's ACS880: a Unit_Diag_Area) has its device block take the rest.
#[test]
fn a_diagnosis_length_without_a_device_block_imports_as_the_files() {
    let sew = corpus_gsd_import("siamect__sew_movidrive_pb_slave.gsd");
    let toml = sew.description.as_deref().expect("a clean round trip");
    assert_says(toml, &["\nmax_diag_data_len = 16\n"]);
    assert!(!toml.contains("[profibus.diagnosis]"));
    let abb = corpus_gsd_import("siamect__abb_acs880_pb_slave.gsd");
    let toml = abb.description.as_deref().expect("a clean round trip");
    assert_says(toml, &["[profibus.diagnosis]\nlength = 10\n"]);
    assert!(!toml.contains("max_diag_data_len"));
}

/// FENA's two PROFIsafe modules (lines 488 and 616) import with their
/// safety data, F-parameters and slot, and their CRCs as the file has them
/// (F_ParamDescCRC 36516, F_IO_StructureDescCRC 41297 and 1211), pinned to
/// the fingerprint of what the file describes: the round trip is clean
/// and the build writes the file's CRCs. An F-parameter changed since
/// makes them stale (E128, naming the new fingerprint); stated as
/// placeholders, the build writes them and warns (W109).
#[test]
fn fenas_safety_modules_import_with_their_crcs_pinned() {
    let imported = corpus_import(FENA);
    assert!(
        imported.round_trip.is_clean(),
        "{:#?}",
        imported.diagnostics
    );
    let toml = written(&imported, FENA);
    assert_says(
        toml,
        &[
            "[[profinet.safety_modules]]\nname = \"PROFIsafe ABB_PS1\"\nident = 0x00000221\nsubmodule_name = \"F-Parameters\"\n",
            "slots = [2, 2]\nio_structure_desc_version = 1\n",
            "  { type = \"Integer16\", name = \"ABB_PS1 In Safe Speed\" },\n  { type = \"F_MessageTrailer4Byte\", name = \"PROFIsafe F Message trailer\" },\n]\n",
            "f_param_desc = 36516\nf_io_structure_desc = 41297\nof = \"",
            "f_param_desc = 36516\nf_io_structure_desc = 1211\nof = \"",
            "F_SIL = { default = \"SIL3\", allowed = \"SIL1 SIL2 SIL3\", changeable = true }\n",
            "F_WD_Time = { default = 200, allowed = \"200..65535\" }\n",
        ],
    );
    let (_, gsdml) = built("fena.toml", toml, ArtifactKind::Gsdml);
    let (ir, _) = descriptions::load_text("fena.toml", toml);
    let (_, page) = descriptions::one(
        gsdc::document(&ir.unwrap()),
        ArtifactKind::DatasheetMarkdown,
    );
    // Its slot 2 and its bytes each way: PS1 12 in (three words of bits, an
    // Integer16, the 4-byte trailer), 10 out; PS2 14 in, 10 out.
    assert!(
        page.contains(
            "PROFIsafe ABB_PS1 (0x00000221): 2; 12/10, PROFIsafe ABB_PS2 (0x00000222): 2; 14/10"
        ),
        "{page}"
    );
    for crc in [
        "F_ParamDescCRC=\"36516\"",
        "F_IO_StructureDescCRC=\"41297\"",
        "F_IO_StructureDescCRC=\"1211\"",
    ] {
        assert!(gsdml.contains(crc), "{crc}");
    }
    let watchdog = "F_WD_Time = { default = 200,";
    let changed = toml.replacen(watchdog, "F_WD_Time = { default = 300,", 1);
    let (ir, diagnostics) = descriptions::load_text("fena.toml", &changed);
    assert!(ir.is_none());
    let stale: Vec<_> = diagnostics.iter().filter(|d| d.code == "E128").collect();
    assert_eq!(stale.len(), 1, "{diagnostics:#?}");
    assert!(stale[0]
        .message
        .contains("safety_modules[0].crcs were given for \""));
    assert_builds_as_placeholder("fena.toml", &changed);
}

/// `toml` with its first safety module's `of = "..."` made
/// `placeholder = true` builds, with W109: a placeholder needs no
/// fingerprint.
fn assert_builds_as_placeholder(name: &str, toml: &str) {
    let of_at = toml.find("of = \"").unwrap();
    let value_at = of_at + "of = \"".len();
    let of_end = value_at + toml[value_at..].find('"').unwrap() + 1;
    let placeholder = format!("{}placeholder = true{}", &toml[..of_at], &toml[of_end..]);
    let (ir, diagnostics) = descriptions::load_text(name, &placeholder);
    assert!(ir.is_some(), "{diagnostics:#?}");
    assert!(diagnostics.iter().any(|d| d.code == "W109"));
}

/// SINAMICS G120 F's GSD: its PROFIsafe module imports with its
/// F-parameters and the file's two CRCs, pinned to the fingerprint of what
/// the file describes, and its UnitDiagType 129 as a diagnosis type; the
/// built GSD carries both CRCs, a changed F-parameter is E128, and a
/// placeholder builds with W109.
#[test]
fn sinamics_g120_fs_profisafe_module_imports_with_its_crcs_pinned() {
    let name = "siamect__SI028158.gsd";
    let imported = corpus_gsd_import(name);
    assert!(
        imported.round_trip.is_clean(),
        "{:#?}",
        imported.diagnostics
    );
    let toml = written(&imported, name);
    assert_says(
        toml,
        &[
            "[profibus.modules.safety]\nconstant = [0x0E, 0x05, 0x00, 0x00, 0x00, 0x00]\ncrcs = { f_param_desc = 0xA01D, f_io_structure_desc = 5639, of = \"",
            "[[profibus.modules.safety.parameters]]\nname = \"F_SIL\"\noffset = 4\nbits = [2, 3]\ndefault = 1\nchoices = [{ value = 1, text = \"SIL 2\" }]\n",
            "[[profibus.modules.safety.parameters]]\nname = \"F_WD_Time\"\noffset = 10\ntype = \"Unsigned16\"\ndefault = 100\nrange = [10, 65535]\n",
            "[[profibus.diagnosis_types]]\nid = 129\n\n[[profibus.diagnosis_types.areas]]\nbit = [24, 31]\nvalues = [{ value = 64, text = \"F add. does not match F_Dest_Add\" },",
        ],
    );
    let (_, gsd) = built("si028158.toml", toml, ArtifactKind::Gsd);
    let gsd = gsd.replace('\r', "");
    for line in [
        "F_Ext_Module_Prm_Data_Len   = 14\n",
        "F_Ext_User_Prm_Data_Const(0) = 0x0E,0x05,0x00,0x00,0x00,0x00\n",
        "F_ParamDescCRC              = 0xA01D\n",
        "F_IO_StructureDescCRC       = 5639\n",
        "UnitDiagType = 129\nX_Unit_Diag_Area = 24-31\nX_Value(64) = \"F add. does not match F_Dest_Add\"\n",
    ] {
        assert!(gsd.contains(line), "{line}\n{gsd}");
    }
    let watchdog = "default = 100\nrange = [10, 65535]";
    let changed = toml.replacen(watchdog, "default = 200\nrange = [10, 65535]", 1);
    let (ir, diagnostics) = descriptions::load_text("si028158.toml", &changed);
    assert!(ir.is_none());
    let stale: Vec<_> = diagnostics.iter().filter(|d| d.code == "E128").collect();
    assert_eq!(stale.len(), 1, "{diagnostics:#?}");
    assert!(stale[0]
        .message
        .contains("module \"PROFIsafe v1.x Module\"'s CRCs were given for \""));
    assert_builds_as_placeholder("si028158.toml", &changed);
}

/// A later access point that declares another PNIO_Version than the first
/// (SEW's MOVI-C: V2.33, then V2.34) imports with its own `pnio_version`,
/// which its build declares; one past the file's version is left out with
/// why (E197).
#[test]
fn a_later_access_points_own_pnio_version_imports() {
    let second = "<DeviceAccessPointItem ID=\"FENA_DAP_V4\"";
    let text = corpus_gsdml_text(FENA);
    let at = text.find(second).unwrap();
    let end = at + text[at..].find('>').unwrap();
    let with = |version: &str| {
        let item = text[at..end].replace("PNIO_Version=\"V2.32\"", version);
        format!("{}{item}{}", &text[..at], &text[end..])
    };
    let imported = import(FENA, with("PNIO_Version=\"V2.31\"").as_bytes());
    assert!(
        imported.round_trip.is_clean(),
        "{:#?}",
        imported.diagnostics
    );
    let toml = written(&imported, FENA);
    assert_eq!(toml.matches("pnio_version = \"2.31\"").count(), 1, "{toml}");
    let (_, gsdml) = built("fena.toml", toml, ArtifactKind::Gsdml);
    assert_eq!(gsdml.matches("PNIO_Version=\"V2.31\"").count(), 1);
    assert_eq!(gsdml.matches("PNIO_Version=\"V2.32\"").count(), 2);
    let later = import(FENA, with("PNIO_Version=\"V2.35\"").as_bytes());
    let left_out = messages(&later, "W600");
    assert!(
        left_out
            .iter()
            .any(|m| m.starts_with("device access point `FENA_DAP_V4`")
                && m.contains("its PNIO_Version is not the first device access point's")),
        "{left_out:#?}"
    );
}
