//! The device tables of every layout, `DP_DEVICE` and `PN_DEVICE`, against
//! the GSD and the GSDML the same description gives, read without gsdc
//! (`../device_files.rs`): the same facts, line by line; and used as a
//! slave and a device would use them, through the support code alone.

#[path = "../device_files.rs"]
mod device_files;

use device_files::{allowed_text, hex};
use gsdc_firmware_check::gsdc_support::{
    DpDevice, DpDiagnosis, DpParam, PnDap, PnDevice, PnRecord, PnSubmoduleRecord, PrmDataType, PrmError,
    RecordReading,
};
use gsdc_firmware_check::{
    md810_gateway, md810dp, mv810_pnet02, own_idents, powtran_9kdp1, profidrive,
};
use std::path::PathBuf;

const DP_DEVICES: [(&str, &DpDevice); 4] = [
    ("md810dp", &md810dp::DP_DEVICE),
    ("9kdp1", &powtran_9kdp1::DP_DEVICE),
    ("md810-gateway", &md810_gateway::DP_DEVICE),
    ("profidrive", &profidrive::DP_DEVICE),
];

const PN_DEVICES: [(&str, &PnDevice); 4] = [
    ("md810dp", &md810dp::PN_DEVICE),
    ("mv810-pnet02", &mv810_pnet02::PN_DEVICE),
    ("profidrive", &profidrive::PN_DEVICE),
    ("own_idents", &own_idents::PN_DEVICE),
];

/// The files the build script wrote whose name ends in `suffix`.
fn generated(suffix: &str) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(env!("OUT_DIR"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.to_string_lossy().ends_with(suffix))
        .collect();
    files.sort();
    files
}

/// The device file whose first line is `first`: the one of the table.
fn device_file(
    suffix: &str,
    read: fn(&std::path::Path) -> Vec<String>,
    first: &str,
) -> Vec<String> {
    let mut found: Vec<Vec<String>> = generated(suffix)
        .iter()
        .map(|p| read(p))
        .filter(|lines| lines[0] == first)
        .collect();
    assert_eq!(found.len(), 1, "one {suffix} of {first}");
    found.remove(0)
}

fn dp_lines(d: &DpDevice) -> Vec<String> {
    let mut lines = vec![format!("ident 0x{:04X}", d.ident_number)];
    for m in d.modules {
        lines.push(format!(
            "module {:?} config {} in {} out {} pkw {} pzd {}",
            m.name,
            hex(m.config),
            m.input_len,
            m.output_len,
            u8::from(m.pkw),
            m.pzd_words
        ));
    }
    lines.push(format!("max_modules {}", d.max_modules));
    let status = d.user_prm.dpv1_status.map_or_else(|| "none".into(), hex);
    lines.push(format!("user_prm {} dpv1 {status}", d.user_prm.len));
    for p in d.user_prm.params {
        let kind = match p.data_type {
            PrmDataType::Unsigned8 => "Unsigned8",
            PrmDataType::Unsigned16 => "Unsigned16",
            PrmDataType::Bit => "Bit",
            PrmDataType::BitArea => "BitArea",
        };
        let allowed = allowed_text((0..=0xFFFF).filter(|&v| p.allows(v as u16)));
        lines.push(format!(
            "param {:?} offset {} {kind} bits {}-{} default {} allowed {allowed}",
            p.name, p.offset, p.first_bit, p.last_bit, p.default_value
        ));
    }
    lines.push(format!("diagnosis {}", d.diagnosis_len));
    lines.push(format!(
        "global_control freeze {} sync {}",
        u8::from(d.freeze_mode),
        u8::from(d.sync_mode)
    ));
    lines
}

/// A drive's card's diagnosis areas, as `device_files::dp_diag_lines`.
fn dp_diag_lines(d: &DpDiagnosis) -> Vec<String> {
    d.areas
        .iter()
        .map(|a| {
            let values: Vec<String> = a.values.iter().map(u16::to_string).collect();
            let (first, last) = (a.first_bit, a.last_bit);
            format!("diag_area {first}-{last} values {}", values.join(","))
        })
        .collect()
}

/// A record of the access point or a port as `device_files` reads it from
/// the GSDML.
fn own_record_line(what: &str, r: &PnSubmoduleRecord) -> String {
    let mut line = format!("{what} {} len {}", r.index, r.len);
    for v in r.values {
        let values: String = v.values.iter().map(|x| format!(" {x}")).collect();
        line += &format!(
            " | {} {} {}-{} default {} range {}..{} values{values} changeable {}",
            v.offset,
            v.bytes,
            v.first_bit,
            v.last_bit,
            v.default_value,
            v.min,
            v.max,
            u8::from(v.changeable)
        );
    }
    line
}

/// A DAP's records of its own submodule and of its ports, then the record
/// of each index a DAP of its ident number has that a device presenting it
/// takes, by `PnDevice::own_record`: `takes dap_record 8200 len 1`.
fn own_records_lines(d: &PnDevice, dap: &PnDap) -> Vec<String> {
    let mut lines = Vec::new();
    for (what, records) in [
        ("dap_record", dap.access_point_records),
        ("port_record", dap.port_records),
    ] {
        lines.extend(records.iter().map(|r| own_record_line(what, r)));
    }
    let same = d.daps.iter().filter(|other| other.ident == dap.ident);
    for other in same {
        for (what, port, records) in [
            ("dap_record", false, other.access_point_records),
            ("port_record", true, other.port_records),
        ] {
            for r in records {
                let taken = d.own_record(dap.ident, port, r.index).unwrap();
                lines.push(format!("takes {what} {} len {}", taken.index, taken.len));
            }
        }
    }
    lines
}

fn pn_lines(d: &PnDevice) -> Vec<String> {
    let mut lines = vec![
        format!("vendor {} device {}", d.vendor_id, d.device_id),
        format!("name {}", d.dns_name),
    ];
    for dap in d.daps {
        let s = &dap.submodule;
        let mut line = format!("dap {} submodule {} {}", dap.ident, s.subslot, s.ident);
        for p in dap.ports {
            line += &format!(" port {} {}", p.subslot, p.ident);
        }
        line += " modules";
        for &m in dap.modules {
            line += &format!(" {}", d.modules[m].ident);
        }
        line += " takes";
        for (place, m) in d.modules.iter().enumerate() {
            if d.offers(dap.ident, place) {
                line += &format!(" {}", m.ident);
            }
        }
        lines.push(line);
        lines.extend(own_records_lines(d, dap));
    }
    let s = &d.interface_submodule;
    lines.push(format!("interface {} {}", s.subslot, s.ident));
    for m in d.modules {
        let slots: Vec<String> = m.slots.iter().map(u16::to_string).collect();
        lines.push(format!(
            "module {:?} ident {} slots {} api {}",
            m.name,
            m.ident,
            slots.join(" "),
            m.api
        ));
        for s in m.access_point.iter().chain([&m.data]) {
            lines.push(format!(
                "submodule {} {} in {} out {}",
                s.subslot, s.ident, s.input_len, s.output_len
            ));
        }
        if !m.double_words.is_empty() {
            // Each the byte offset of PZD word `w`, the same both ways.
            let pkw_words = if m.pkw { 4 } else { 0 };
            let offsets: Vec<String> = m
                .double_words
                .iter()
                .map(|w| (2 * (pkw_words + w - 1)).to_string())
                .collect();
            let offsets = offsets.join(" ");
            lines.push(format!("u32 in {offsets} out {offsets}"));
        }
        for r in m.records {
            let bytes = record_bytes(r, r.defaults);
            let mut values = vec![0; r.entries.len()];
            r.decode(&bytes, &mut values).unwrap();
            let mut fail_safe = vec![0; r.fail_safe.len()];
            r.decode_fail_safe(&bytes, &mut fail_safe).unwrap();
            // The entries, then the fail-safe values, which the controller
            // may always change.
            let widths = r.entries.iter().map(|e| e.bytes.to_string());
            let widths = widths.chain(r.fail_safe.iter().map(u8::to_string));
            let reads = values.iter().map(u16::to_string);
            let reads = reads.chain(fail_safe.iter().map(u32::to_string));
            let changeable = r.changeable.iter().chain(r.fail_safe.iter().map(|_| &true));
            let changeable = changeable.map(|&c| if c { "1" } else { "0" });
            lines.push(format!(
                "record {} len {} bytes {} reads {} changeable {}",
                r.index,
                r.len,
                widths.collect::<Vec<_>>().join(" "),
                reads.collect::<Vec<_>>().join(" "),
                changeable.collect::<Vec<_>>().join(" ")
            ));
        }
    }
    for m in d.safety_modules {
        let s = &m.submodule;
        lines.push(format!(
            "safety_module {} submodule {} {} in {} out {}",
            m.ident, s.subslot, s.ident, s.input_len, s.output_len
        ));
        lines.extend(m.records.iter().map(|r| own_record_line("safety_record", r)));
    }
    lines
}

#[test]
fn every_dp_table_says_what_its_gsd_says() {
    for (name, device) in DP_DEVICES {
        let table = dp_lines(device);
        let gsd = device_file(".GSD", device_files::dp_lines, &table[0]);
        assert_eq!(table, gsd, "{name}");
    }
}

/// A drive's card's diagnosis areas are the GSD's `Unit_Diag_Area`s, and
/// the block is as long as the GSD allows; a gateway's blocks are its own
/// (`gateway.rs`).
#[test]
fn every_dp_diagnosis_is_its_gsds_unit_diag_areas() {
    let mut seen = 0;
    for (name, device) in DP_DEVICES {
        let Some(diagnosis) = device.diagnosis else {
            assert!(
                device.gateway.is_some() || device.diagnosis_len == 0,
                "{name}"
            );
            continue;
        };
        let first = format!("ident 0x{:04X}", device.ident_number);
        let path = generated(".GSD")
            .into_iter()
            .find(|p| device_files::dp_lines(p)[0] == first)
            .unwrap();
        assert_eq!(
            dp_diag_lines(&diagnosis),
            device_files::dp_diag_lines(&path),
            "{name}"
        );
        assert_eq!(diagnosis.len, device.diagnosis_len, "{name}");
        assert_eq!(usize::from(diagnosis.header()), diagnosis.len, "{name}");
        seen += 1;
    }
    assert!(seen >= 2, "MD810's and 9KDP1's blocks");
}

#[test]
fn every_pn_table_says_what_its_gsdml_says() {
    for (name, device) in PN_DEVICES {
        let table = pn_lines(device);
        let gsdml = device_file(".xml", device_files::pn_lines, &table[0]);
        assert_eq!(table, gsdml, "{name}");
    }
}

/// gsd-parser's parameter telegram of the GSD's defaults, and with one
/// parameter set by name.
fn gsd_user_prm(device: &DpDevice, set: Option<(&str, u16)>) -> Vec<u8> {
    let first = format!("ident 0x{:04X}", device.ident_number);
    let path = generated(".GSD")
        .into_iter()
        .find(|p| device_files::dp_lines(p)[0] == first)
        .unwrap();
    let text = std::fs::read(&path).unwrap();
    let parsed = gsd_parser::parser::parse(&path, &String::from_utf8_lossy(&text)).unwrap();
    let mut builder = gsd_parser::PrmBuilder::new(&parsed.user_prm_data);
    if let Some((name, value)) = set {
        builder.set_prm(name, value.into());
    }
    builder.into_bytes()
}

/// A value of the parameter's type the GSD does not allow, if there is one.
fn refused_value(p: &DpParam) -> Option<u16> {
    let max = match p.data_type {
        PrmDataType::Unsigned8 => 0xFF,
        PrmDataType::Unsigned16 => 0xFFFF,
        PrmDataType::Bit | PrmDataType::BitArea => (1 << (p.last_bit - p.first_bit + 1)) - 1,
    };
    (0..=max).find(|&v| !p.allows(v))
}

/// The bytes of `p` set to `value` whatever the GSD allows, as a master
/// that does not read the GSD could send them.
fn put_raw(p: &DpParam, bytes: &mut [u8], value: u16) {
    match p.data_type {
        PrmDataType::Unsigned16 => {
            bytes[p.offset..p.offset + 2].copy_from_slice(&value.to_be_bytes())
        }
        PrmDataType::Unsigned8 => bytes[p.offset] = value as u8,
        PrmDataType::Bit | PrmDataType::BitArea => {
            bytes[p.offset] |= (value << p.first_bit) as u8;
        }
    }
}

#[test]
fn user_prm_is_decoded_by_the_gsds_names_and_refused_where_the_gsd_refuses() {
    for (name, device) in DP_DEVICES {
        let prm = &device.user_prm;
        let defaults = gsd_user_prm(device, None);
        let mut ours = vec![0; prm.len];
        prm.defaults(&mut ours).unwrap();
        assert_eq!(ours, defaults, "{name}");
        assert_eq!(prm.check(&defaults), Ok(()), "{name}");
        for p in prm.params {
            assert_eq!(prm.param(p.name), Some(p), "{name}");
            // What a master sets by name, the slave reads by name.
            let set = gsd_user_prm(device, Some((p.name, p.max)));
            assert_eq!(
                prm.param(p.name).unwrap().read(&set),
                Ok(p.max),
                "{name} {}",
                p.name
            );
            assert_eq!(prm.check(&set), Ok(()), "{name} {}", p.name);
            if let Some(value) = refused_value(p) {
                let mut refused = defaults.clone();
                put_raw(p, &mut refused, value);
                let error = PrmError::NotAllowed {
                    offset: p.offset,
                    value: value.into(),
                };
                assert_eq!(prm.check(&refused), Err(error), "{name} {}", p.name);
            }
        }
        let short = &defaults[..prm.len - 1];
        assert!(
            matches!(prm.check(short), Err(PrmError::Length { .. })),
            "{name}"
        );
    }
}

#[test]
fn a_configuration_is_taken_when_the_gsds_modules_make_it() {
    for (name, device) in DP_DEVICES {
        let prm = gsd_user_prm(device, None);
        match device.node_totals {
            None => {
                for m in device.modules {
                    let taken = device.check_config(&prm, m.config);
                    assert_eq!(taken, Some((m.input_len, m.output_len)), "{name}");
                }
                let [a, b, ..] = device.modules else {
                    panic!("{name} offers two modules at least");
                };
                let two = [a.config, b.config].concat();
                assert_eq!(device.max_modules, 1, "{name}");
                assert_eq!(device.check_config(&prm, &two), None, "{name}");
                assert_eq!(device.check_config(&prm, &[]), None, "{name}");
            }
            // The defaults: no node carries words, so no module is plugged.
            Some(totals) => {
                assert_eq!(totals(&prm), Some((0, 0)), "{name}");
                assert_eq!(device.check_config(&prm, &[]), Some((0, 0)), "{name}");
                let one = device.modules[0].config;
                assert_eq!(device.check_config(&prm, one), None, "{name}");
            }
        }
        assert_eq!(device.check_config(&prm, &[0x00]), None, "{name}");
    }
}

/// MD810's bridge with two nodes, the first sending 3 words and receiving
/// 1: the master plugs INPUT 2 words, INPUT 1 word and OUTPUT 1 word.
#[test]
fn a_gateway_takes_the_modules_that_carry_its_nodes_words() {
    let device = &md810_gateway::DP_DEVICE;
    let mut input_words = [0; md810_gateway::gateway::NODES];
    let mut output_words = [0; md810_gateway::gateway::NODES];
    input_words[0] = 3;
    output_words[0] = 1;
    let config = md810_gateway::gateway::NodeConfig {
        node_count: 2,
        input_words,
        output_words,
    };
    let prm = config.encode().unwrap();
    let module = |name: &str| {
        device
            .modules
            .iter()
            .find(|m| m.name == name)
            .unwrap()
            .config
    };
    let plugged = [
        module("INPUT 2 words"),
        module("INPUT 1 word"),
        module("OUTPUT 1 word"),
    ]
    .concat();
    assert_eq!(device.check_config(&prm, &plugged), Some((6, 2)));
    let short = [module("INPUT 2 words"), module("OUTPUT 1 word")].concat();
    assert_eq!(device.check_config(&prm, &short), None);
}

/// A record of `values`, each entry of its bytes, high byte first, then
/// its fail-safe values, each 0.
fn record_bytes(r: &PnRecord, values: &[u16]) -> Vec<u8> {
    let fail_safe = r.fail_safe.iter().map(|&bytes| usize::from(bytes)).sum();
    r.entries
        .iter()
        .zip(values)
        .flat_map(|(e, v)| v.to_be_bytes()[2 - e.bytes..].to_vec())
        .chain(std::iter::repeat_n(0, fail_safe))
        .collect()
}

#[test]
fn a_record_is_refused_as_the_layouts_group_decoder_refuses_it() {
    for (name, device) in PN_DEVICES {
        for m in device.modules {
            for r in m.records {
                let bytes = record_bytes(r, r.defaults);
                let mut values = vec![0; r.entries.len()];
                let longer = [&bytes[..], &[0, 0]].concat();
                assert!(
                    matches!(r.decode(&longer, &mut values), Err(PrmError::Length { .. })),
                    "{name} {}",
                    m.name
                );
                let short = &bytes[..bytes.len() - 1];
                assert!(r.decode(short, &mut values).is_err(), "{name}");
                if r.reading == RecordReading::Prefix {
                    // The first word alone: the others keep their defaults.
                    let mut first = vec![0; r.entries.len()];
                    r.decode(&bytes[..2], &mut first).unwrap();
                    assert_eq!(first, r.defaults, "{name} {}", m.name);
                }
                for (i, entry) in r.entries.iter().enumerate() {
                    // A value the entry's bytes can carry.
                    let most = if entry.bytes == 1 { 0xFF } else { 0xFFFF };
                    let Some(value) = (0..=most).find(|&v| !entry.allowed.contains(v)) else {
                        continue;
                    };
                    let offset: usize = r.entries[..i].iter().map(|e| e.bytes).sum();
                    let mut refused = bytes.clone();
                    refused[offset..offset + entry.bytes]
                        .copy_from_slice(&value.to_be_bytes()[2 - entry.bytes..]);
                    let error = PrmError::NotAllowed {
                        offset,
                        value: value.into(),
                    };
                    assert_eq!(r.decode(&refused, &mut values), Err(error), "{name}");
                }
            }
        }
    }
}

/// own_idents' PROFIenergy constants are the energy saving modes its
/// GSDML declares in each of its three device access points' own
/// submodules, read with roxmltree: each mode's ID and its TimeToPause,
/// RTTO and TimeMinLengthOfStay.
#[test]
fn profienergy_constants_are_the_gsdmls_modes() {
    use own_idents as o;
    let constants: [[u32; 4]; 2] = [
        [
            o::PROFIENERGY_MODE_2_ID.into(),
            o::PROFIENERGY_MODE_2_TIME_TO_PAUSE_MS,
            o::PROFIENERGY_MODE_2_REGULAR_TIME_TO_OPERATE_MS,
            o::PROFIENERGY_MODE_2_MIN_LENGTH_OF_STAY_MS,
        ],
        [
            o::PROFIENERGY_MODE_255_ID.into(),
            o::PROFIENERGY_MODE_255_TIME_TO_PAUSE_MS,
            o::PROFIENERGY_MODE_255_REGULAR_TIME_TO_OPERATE_MS,
            o::PROFIENERGY_MODE_255_MIN_LENGTH_OF_STAY_MS,
        ],
    ];
    assert_eq!(usize::from(o::PROFIENERGY_MODES), constants.len());
    let first = pn_lines(&o::PN_DEVICE).remove(0);
    let path = generated(".xml")
        .into_iter()
        .find(|p| device_files::pn_lines(p)[0] == first)
        .unwrap();
    let text = std::fs::read_to_string(path).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    let lists: Vec<Vec<[u32; 4]>> = doc
        .descendants()
        .filter(|n| n.has_tag_name("EnergySavingModeList"))
        .map(|list| {
            let items = list.children().filter(|n| n.is_element());
            let attributes = ["ID", "TimeToPause", "RTTO", "TimeMinLengthOfStay"];
            items
                .map(|m| attributes.map(|a| m.attribute(a).unwrap().parse().unwrap()))
                .collect()
        })
        .collect();
    // Every device access point's own submodule declares them.
    assert_eq!(lists, vec![constants.to_vec(); o::PN_DEVICE.daps.len()]);
}
