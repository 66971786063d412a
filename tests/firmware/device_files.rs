//! What the GSD and the GSDML of a description say a slave or device is,
//! read without gsdc (the GSD by gsd-parser, the GSDML by roxmltree), as
//! lines of text: the Rust tables (tests/device_tables.rs of the firmware
//! crate) and the C tables (gsdc's tests/device_tables_c.rs, through
//! tests/c/device_tables.c) are dumped in the same lines and compared with
//! these, so both languages answer to the device files, not to gsdc.
//!
//! A line per fact: `ident 0x0810`, `module "PPO1" config F3 F1 in 12 out 12
//! pkw 1 pzd 2`, `param "PZD2 out" offset 5 Unsigned16 bits 0-15 default 0
//! allowed 0-65535`, `record 1 len 4 reads 0 0 changeable 1 1`...

#![allow(dead_code)] // each includer uses its part

use std::path::Path;

/// The GSD's slave: its ident number, modules, Max_Module, User_Prm_Data
/// and the most bytes of its device-related diagnosis.
pub fn dp_lines(gsd: &Path) -> Vec<String> {
    let text = std::fs::read(gsd).unwrap();
    let text = String::from_utf8_lossy(&text);
    let parsed = gsd_parser::parser::parse(gsd, &text).unwrap();
    let mut lines = vec![format!("ident 0x{:04X}", parsed.ident_number)];
    for m in &parsed.available_modules {
        let (input, output) = config_lengths(&m.config);
        let (pkw, pzd) = ppo_words(&m.config);
        lines.push(format!(
            "module {:?} config {} in {input} out {output} pkw {} pzd {pzd}",
            m.name,
            hex(&m.config),
            u8::from(pkw)
        ));
    }
    lines.push(format!("max_modules {}", parsed.max_modules));
    let prm = &parsed.user_prm_data;
    let status = prm
        .data_const
        .iter()
        .find(|(offset, _)| *offset == 0)
        // DPV1_Status_1..3: the first bytes of the constant at byte 0
        // (a card may state more, under its own parameters).
        .map_or_else(
            || "none".to_string(),
            |(_, bytes)| hex(&bytes[..bytes.len().min(3)]),
        );
    // The length of the telegram a master builds from the GSD (gsd-parser
    // leaves `length` to modules' parameters).
    let len = gsd_parser::PrmBuilder::new(prm).into_bytes().len();
    lines.push(format!("user_prm {len} dpv1 {status}"));
    for (offset, def) in &prm.data_ref {
        let (kind, first, last) = match def.data_type {
            // A Signed8 holds 0 to 127 in gsdc (the format says no negative
            // value): the tables read its byte as an Unsigned8, within the
            // GSD's range, compared below.
            gsd_parser::UserPrmDataType::Unsigned8 | gsd_parser::UserPrmDataType::Signed8 => {
                ("Unsigned8", 0, 7)
            }
            gsd_parser::UserPrmDataType::Unsigned16 => ("Unsigned16", 0, 15),
            gsd_parser::UserPrmDataType::Bit(b) => ("Bit", b, b),
            gsd_parser::UserPrmDataType::BitArea(f, l) => ("BitArea", f, l),
            other => panic!("gsdc writes no {other:?}"),
        };
        let allowed = allowed_text((0..=0xFFFF).filter(|&v| def.constraint.is_valid(v)));
        lines.push(format!(
            "param {:?} offset {offset} {kind} bits {first}-{last} default {} allowed {allowed}",
            def.name, def.default_value
        ));
    }
    lines.push(format!(
        "diagnosis {}",
        parsed.max_diag_data_length.saturating_sub(6)
    ));
    lines.push(format!(
        "global_control freeze {} sync {}",
        u8::from(parsed.freeze_mode_supported),
        u8::from(parsed.sync_mode_supported)
    ));
    lines
}

/// The GSD's `Unit_Diag_Area`s: `diag_area 8-15 values 52`.
pub fn dp_diag_lines(gsd: &Path) -> Vec<String> {
    let text = std::fs::read(gsd).unwrap();
    let parsed = gsd_parser::parser::parse(gsd, &String::from_utf8_lossy(&text)).unwrap();
    parsed
        .unit_diag
        .areas
        .iter()
        .map(|a| {
            let values: Vec<String> = a.values.keys().map(u16::to_string).collect();
            format!(
                "diag_area {}-{} values {}",
                a.first,
                a.last,
                values.join(",")
            )
        })
        .collect()
}

/// `0-5`, `0,2,7` or `1-3,9`: the values, as runs.
pub fn allowed_text(values: impl Iterator<Item = i64>) -> String {
    let mut runs: Vec<(i64, i64)> = Vec::new();
    for v in values {
        match runs.last_mut() {
            Some((_, last)) if *last + 1 == v => *last = v,
            _ => runs.push((v, v)),
        }
    }
    runs.iter()
        .map(|&(a, b)| {
            if a == b {
                a.to_string()
            } else {
                format!("{a}-{b}")
            }
        })
        .collect::<Vec<_>>()
        .join(",")
}

pub fn hex(bytes: &[u8]) -> String {
    bytes
        .iter()
        .map(|b| format!("{b:02X}"))
        .collect::<Vec<_>>()
        .join(" ")
}

/// Bytes of input and output the config identifiers say (general format:
/// bits 5-4 the direction, bit 6 words, bits 3-0 the length less one; or
/// the special format, whose length bytes say each way).
fn config_lengths(config: &[u8]) -> (usize, usize) {
    let (mut input, mut output) = (0, 0);
    let mut bytes = config.iter().copied();
    while let Some(id) = bytes.next() {
        let direction = (id >> 4) & 0x03;
        if direction == 0 {
            // The special format (IEC 61158-6-3): bit 7 an output length
            // byte follows, bit 6 an input one, bits 3-0 that many
            // manufacturer bytes after them.
            let special = |length: u8| {
                let unit = if length & 0x40 != 0 { 2 } else { 1 };
                unit * (usize::from(length & 0x3F) + 1)
            };
            if id & 0x80 != 0 {
                output += bytes.next().map_or(0, special);
            }
            if id & 0x40 != 0 {
                input += bytes.next().map_or(0, special);
            }
            bytes.by_ref().take(usize::from(id & 0x0F)).for_each(drop);
            continue;
        }
        let unit = if id & 0x40 != 0 { 2 } else { 1 };
        let len = unit * (usize::from(id & 0x0F) + 1);
        match direction {
            0b01 => input += len,
            0b10 => output += len,
            _ => (input, output) = (input + len, output + len),
        }
    }
    (input, output)
}

/// A PPO's channels from its identifiers: the PKW's 4 consistent words
/// each way first, when it has one, then the PZD's; a module that carries
/// one direction only (a gateway's) has neither.
fn ppo_words(config: &[u8]) -> (bool, usize) {
    let words = |byte: u8| usize::from(byte & 0x0F) + 1;
    let both_ways = |byte: u8| (byte >> 4) & 0x03 == 0b11;
    match config {
        [0xF3, pzd] if both_ways(*pzd) => (true, words(*pzd)),
        [pzd] if both_ways(*pzd) => (false, words(*pzd)),
        _ => (false, 0),
    }
}

/// The GSDML's device: its identity, the device access point with its
/// interface and ports, and each module with its submodules and records.
/// A record's `reads` are the values of its Refs' defaults: what the device
/// must read from a record of those bytes.
pub fn pn_lines(gsdml: &Path) -> Vec<String> {
    let text = std::fs::read_to_string(gsdml).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    let find = |name: &str| {
        doc.descendants()
            .find(|n| n.has_tag_name(name))
            .unwrap_or_else(|| panic!("no {name}"))
    };
    let identity = find("DeviceIdentity");
    let mut lines = vec![format!(
        "vendor {} device {}",
        number(attr(identity, "VendorID")),
        number(attr(identity, "DeviceID"))
    )];
    let dap = find("DeviceAccessPointItem");
    lines.push(format!("name {}", attr(dap, "DNS_CompatibleName")));
    let daps: Vec<roxmltree::Node> = doc
        .descendants()
        .filter(|n| n.has_tag_name("DeviceAccessPointItem"))
        .collect();
    for &d in &daps {
        lines.push(dap_line(&doc, d, &daps));
        lines.extend(own_records_lines(&doc, d, &daps));
    }
    let interface = dap
        .descendants()
        .find(|n| n.has_tag_name("InterfaceSubmoduleItem"))
        .unwrap();
    lines.push(format!(
        "interface {} {}",
        number(attr(interface, "SubslotNumber")),
        number(attr(interface, "SubmoduleIdentNumber"))
    ));
    let text_of = |id: &str| {
        doc.descendants()
            .filter(|n| n.has_tag_name("PrimaryLanguage"))
            .flat_map(|l| l.children())
            .find(|t| t.attribute("TextId") == Some(id))
            .map(|t| attr(t, "Value").to_string())
            .unwrap_or_else(|| panic!("no text {id}"))
    };
    // A PROFIsafe module is not in the device tables: the layouts give its
    // constants, and its data is the firmware's PROFIsafe layer's.
    for module in doc
        .descendants()
        .filter(|n| n.has_tag_name("ModuleItem") && !is_safety_module(*n))
    {
        let id = attr(module, "ID");
        // The first access point's reference that offers it: the
        // description's modules go in the same slots under every one.
        let slots = doc
            .descendants()
            .find(|n| n.has_tag_name("ModuleItemRef") && attr(*n, "ModuleItemTarget") == id)
            .map(|r| slot_list(attr(r, "AllowedInSlots")))
            .unwrap();
        let name = module
            .children()
            .find(|n| n.has_tag_name("ModuleInfo"))
            .and_then(|info| info.children().find(|n| n.has_tag_name("Name")))
            .map(|n| text_of(attr(n, "TextId")))
            .unwrap();
        let submodules: Vec<_> = module
            .descendants()
            .filter(|n| n.has_tag_name("VirtualSubmoduleItem"))
            .collect();
        let api = submodules[0].attribute("API").unwrap_or("0");
        lines.push(format!(
            "module {name:?} ident {} slots {slots} api {}",
            number(attr(module, "ModuleIdentNumber")),
            number(api)
        ));
        for s in submodules {
            let bytes = |direction: &str| -> usize {
                s.descendants()
                    .filter(|n| n.has_tag_name(direction))
                    .flat_map(|d| d.children().filter(|n| n.has_tag_name("DataItem")))
                    .map(|d| data_type_len(attr(d, "DataType")))
                    .sum()
            };
            lines.push(format!(
                "submodule {} {} in {} out {}",
                number(s.attribute("FixedInSubslots").unwrap_or("1")),
                number(attr(s, "SubmoduleIdentNumber")),
                bytes("Input"),
                bytes("Output")
            ));
            let (input, output) = (u32_offsets(s, "Input"), u32_offsets(s, "Output"));
            if !input.is_empty() || !output.is_empty() {
                lines.push(format!("u32 in {input} out {output}"));
            }
            for record in s
                .descendants()
                .filter(|n| n.has_tag_name("ParameterRecordDataItem"))
            {
                let refs = record.children().filter(|n| n.has_tag_name("Ref"));
                let widths: Vec<&str> = refs
                    .clone()
                    .map(|r| match attr(r, "DataType") {
                        "Unsigned8" | "Integer8" => "1",
                        "Unsigned16" => "2",
                        "Unsigned32" => "4",
                        other => panic!("a Ref of type {other}"),
                    })
                    .collect();
                let reads: Vec<&str> = refs.clone().map(|r| attr(r, "DefaultValue")).collect();
                // A Ref's Changeable is true unless it says otherwise (the
                // schema's default).
                let changeable: Vec<&str> = refs
                    .map(|r| match r.attribute("Changeable") {
                        Some("false") => "0",
                        _ => "1",
                    })
                    .collect();
                lines.push(format!(
                    "record {} len {} bytes {} reads {} changeable {}",
                    attr(record, "Index"),
                    attr(record, "Length"),
                    widths.join(" "),
                    reads.join(" "),
                    changeable.join(" ")
                ));
            }
        }
    }
    lines.extend(safety_module_lines(&doc));
    lines
}

/// Each PROFIsafe module: its ident number, its submodule with the bytes
/// of its safety data each way, and the submodule's records besides the
/// F-parameters, as a device access point's own records are listed.
fn safety_module_lines(doc: &roxmltree::Document) -> Vec<String> {
    let mut lines = Vec::new();
    for module in doc
        .descendants()
        .filter(|n| n.has_tag_name("ModuleItem") && is_safety_module(*n))
    {
        let submodule = own_submodule(module);
        let bytes = |direction: &str| -> usize {
            submodule
                .descendants()
                .filter(|n| n.has_tag_name(direction))
                .flat_map(|d| d.children().filter(|n| n.has_tag_name("DataItem")))
                .map(|d| match attr(d, "DataType") {
                    "F_MessageTrailer4Byte" => 4,
                    "F_MessageTrailer5Byte" => 5,
                    other => data_type_len(other),
                })
                .sum()
        };
        lines.push(format!(
            "safety_module {} submodule {} {} in {} out {}",
            number(attr(module, "ModuleIdentNumber")),
            number(submodule.attribute("FixedInSubslots").unwrap_or("1")),
            number(attr(submodule, "SubmoduleIdentNumber")),
            bytes("Input"),
            bytes("Output")
        ));
        lines.extend(own_record_lines(doc, "safety_record", submodule));
    }
    lines
}

/// The records of a device access point's own submodule or of a port:
/// each value's place (byte, bytes, bits), default, range, listed values
/// and whether the controller may change it, as the GSDML gives them.
fn own_record_lines(
    doc: &roxmltree::Document,
    what: &str,
    submodule: roxmltree::Node,
) -> Vec<String> {
    let records = submodule
        .children()
        .filter(|n| n.has_tag_name("RecordDataList"))
        .flat_map(|l| {
            l.children()
                .filter(|n| n.has_tag_name("ParameterRecordDataItem"))
        });
    records
        .map(|record| {
            let mut line = format!(
                "{what} {} len {}",
                attr(record, "Index"),
                attr(record, "Length")
            );
            for r in record.children().filter(|n| n.has_tag_name("Ref")) {
                line += &own_record_value(doc, r);
            }
            line
        })
        .collect()
}

/// ` | byte bytes first-last default d range min..max values v... changeable c`
/// of a record's Ref: 0 bytes for a Bit or BitArea; its range the ends of
/// its AllowedValues, else its type's; its values its ValueItem's.
fn own_record_value(doc: &roxmltree::Document, r: roxmltree::Node) -> String {
    let data_type = attr(r, "DataType");
    let first: u32 = r.attribute("BitOffset").unwrap_or("0").parse().unwrap();
    let (bytes, bits) = match data_type {
        "Bit" => (0, (first, first)),
        "BitArea" => {
            let length: u32 = attr(r, "BitLength").parse().unwrap();
            (0, (first, first + length - 1))
        }
        other => (data_type_len(other), (0, 7)),
    };
    let type_max = match bytes {
        0 => (1u64 << (bits.1 - bits.0 + 1)) - 1,
        n => (1u64 << (8 * n)) - 1,
    };
    let (min, max) = match r.attribute("AllowedValues") {
        Some(runs) => {
            let ends: Vec<&str> = runs.split([' ', '.']).filter(|p| !p.is_empty()).collect();
            (number(ends[0]), number(ends[ends.len() - 1]))
        }
        None => (0, type_max),
    };
    let values: Vec<&str> = r
        .attribute("ValueItemTarget")
        .map(|id| {
            let item = doc
                .descendants()
                .find(|n| n.has_tag_name("ValueItem") && n.attribute("ID") == Some(id))
                .unwrap();
            item.descendants()
                .filter(|n| n.has_tag_name("Assign"))
                .map(|a| attr(a, "Content"))
                .collect()
        })
        .unwrap_or_default();
    let changeable = match r.attribute("Changeable") {
        Some("false") => 0,
        _ => 1,
    };
    format!(
        " | {} {bytes} {}-{} default {} range {min}..{max} values{} changeable {changeable}",
        attr(r, "ByteOffset"),
        bits.0,
        bits.1,
        attr(r, "DefaultValue"),
        values.iter().map(|v| format!(" {v}")).collect::<String>()
    )
}

/// A device access point after the first: its ident number, its own
/// submodule, each port, and the ident number of each module it offers.
/// A device access point's records of its own submodule and of its ports
/// (every port of it carries the records its first does, which the table
/// lists once), then, for each record a DAP of its ident number has, the
/// record of that index a device presenting it takes: the first such DAP's
/// (`takes dap_record 8200 len 1`).
fn own_records_lines(
    doc: &roxmltree::Document,
    dap: roxmltree::Node,
    daps: &[roxmltree::Node],
) -> Vec<String> {
    let own = own_submodule;
    let ports = |d: roxmltree::Node| -> Vec<Vec<String>> {
        d.descendants()
            .filter(|n| n.has_tag_name("PortSubmoduleItem"))
            .map(|port| own_record_lines(doc, "port_record", port))
            .collect()
    };
    let mut lines = own_record_lines(doc, "dap_record", own(dap));
    let its_ports = ports(dap);
    assert!(its_ports.windows(2).all(|w| w[0] == w[1]), "{its_ports:?}");
    lines.extend(its_ports.into_iter().next().unwrap_or_default());
    let ident = number(attr(dap, "ModuleIdentNumber"));
    let same: Vec<roxmltree::Node> = daps
        .iter()
        .copied()
        .filter(|d| number(attr(*d, "ModuleIdentNumber")) == ident)
        .collect();
    // Index and length of each record line: `dap_record 8200 len 1 | ...`.
    let index_len = |line: &str| -> (String, String) {
        let words: Vec<&str> = line.split(' ').collect();
        (words[1].to_string(), words[3].to_string())
    };
    let records_of = |d: roxmltree::Node, what: &str| -> Vec<(String, String)> {
        let lines = if what == "dap_record" {
            own_record_lines(doc, what, own(d))
        } else {
            ports(d).into_iter().next().unwrap_or_default()
        };
        lines.iter().map(|l| index_len(l)).collect()
    };
    for &other in &same {
        for what in ["dap_record", "port_record"] {
            for (index, _) in records_of(other, what) {
                let len = same
                    .iter()
                    .find_map(|&d| records_of(d, what).into_iter().find(|(i, _)| *i == index))
                    .unwrap()
                    .1;
                lines.push(format!("takes {what} {index} len {len}"));
            }
        }
    }
    lines
}

/// A device access point's line: its ident number, own submodule, ports,
/// the data modules it offers, and those a device presenting it takes, the
/// modules any access point of its ident number offers (in module order).
fn dap_line(doc: &roxmltree::Document, dap: roxmltree::Node, daps: &[roxmltree::Node]) -> String {
    let own = own_submodule(dap);
    let ident = attr(dap, "ModuleIdentNumber");
    let mut line = format!(
        "dap {} submodule {} {}",
        number(ident),
        number(own.attribute("FixedInSubslots").unwrap_or("1")),
        number(attr(own, "SubmoduleIdentNumber"))
    );
    for port in dap
        .descendants()
        .filter(|n| n.has_tag_name("PortSubmoduleItem"))
    {
        line += &format!(
            " port {} {}",
            number(attr(port, "SubslotNumber")),
            number(attr(port, "SubmoduleIdentNumber"))
        );
    }
    line += " modules";
    for module in data_modules_offered(doc, dap) {
        line += &format!(" {}", number(attr(module, "ModuleIdentNumber")));
    }
    line += " takes";
    let same_ident = daps
        .iter()
        .filter(|d| number(attr(**d, "ModuleIdentNumber")) == number(ident));
    let taken: Vec<String> = same_ident
        .flat_map(|&d| data_modules_offered(doc, d))
        .map(|m| attr(m, "ID").to_string())
        .collect();
    for module in doc.descendants().filter(|n| {
        n.has_tag_name("ModuleItem")
            && !is_safety_module(*n)
            && taken.contains(&attr(*n, "ID").to_string())
    }) {
        line += &format!(" {}", number(attr(module, "ModuleIdentNumber")));
    }
    line
}

/// A device access point's or a module's first virtual submodule.
fn own_submodule<'a, 'input>(dap: roxmltree::Node<'a, 'input>) -> roxmltree::Node<'a, 'input> {
    dap.descendants()
        .find(|n| n.has_tag_name("VirtualSubmoduleItem"))
        .unwrap()
}

/// The modules other than PROFIsafe ones `dap` offers, in its order.
fn data_modules_offered<'a, 'input>(
    doc: &'a roxmltree::Document<'input>,
    dap: roxmltree::Node<'a, 'input>,
) -> impl Iterator<Item = roxmltree::Node<'a, 'input>> {
    dap.descendants()
        .filter(|n| n.has_tag_name("ModuleItemRef"))
        .map(move |reference| {
            let target = attr(reference, "ModuleItemTarget");
            doc.descendants()
                .find(|n| n.has_tag_name("ModuleItem") && n.attribute("ID") == Some(target))
                .unwrap()
        })
        .filter(|m| !is_safety_module(*m))
}

/// A module whose submodule supports PROFIsafe.
fn is_safety_module(module: roxmltree::Node) -> bool {
    module
        .descendants()
        .any(|n| n.attribute("PROFIsafeSupported") == Some("true"))
}

fn attr<'a>(node: roxmltree::Node<'a, '_>, name: &str) -> &'a str {
    node.attribute(name)
        .unwrap_or_else(|| panic!("{} without {name}", node.tag_name().name()))
}

/// A GSDML number, decimal or `0x` hex, in decimal.
fn number(text: &str) -> u64 {
    match text.strip_prefix("0x") {
        Some(hex) => u64::from_str_radix(hex, 16).unwrap(),
        None => text.parse().unwrap(),
    }
}

/// The byte offsets of a submodule's Unsigned32 data items in `direction`
/// (`Input`, `Output`), blank-separated.
fn u32_offsets(s: roxmltree::Node, direction: &str) -> String {
    let mut offset = 0;
    let mut found = Vec::new();
    let items = s
        .descendants()
        .filter(|n| n.has_tag_name(direction))
        .flat_map(|d| d.children().filter(|n| n.has_tag_name("DataItem")));
    for item in items {
        let data_type = attr(item, "DataType");
        if data_type == "Unsigned32" {
            found.push(offset.to_string());
        }
        offset += data_type_len(data_type);
    }
    found.join(" ")
}

fn data_type_len(data_type: &str) -> usize {
    match data_type {
        "Unsigned8" | "Integer8" => 1,
        "Unsigned16" | "Integer16" => 2,
        "Unsigned32" | "Integer32" | "Float32" => 4,
        other => panic!("gsdc writes no {other}"),
    }
}

/// Every slot of an `AllowedInSlots` of one slot or one range: `2..4` is
/// `2 3 4`.
fn slot_list(allowed: &str) -> String {
    let (first, last) = allowed.split_once("..").unwrap_or((allowed, allowed));
    let [first, last]: [u16; 2] = [first, last].map(|n| n.parse().expect("a slot number"));
    let slots: Vec<String> = (first..=last).map(|s| s.to_string()).collect();
    slots.join(" ")
}
