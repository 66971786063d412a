//! Attributes one by one: present where the file's schema version requires
//! them (E319), ident numbers in hex (E318), other values in their syntax
//! (E320). The other rules read values leniently and rely on this one to
//! report what does not parse, so that each bad value is reported once.

use super::index::{describe, tag_span, within, El, SUBMODULE_ITEMS};
use super::values::{parse_bool, parse_hex, parse_u32, NumberList, ValueList};
use super::version::Version;
use super::Ctx;
use crate::diag::Diagnostic;

/// Required in every version: the attributes without which an element
/// cannot be identified, plugged or sized. Every corpus file from V2.25 on
/// has them, and they are required by base types (`ObjectT`) or by the
/// element's purpose since GSDML V1.0.
const EVERY_VERSION: Version = Version::new(1, 0);

/// Required by the V2.44 schema, but gsdc could not establish in which
/// version they became required (only the V2.44 schema is at hand). The
/// corpus shows files that lack some of them and were valid in their own
/// version: PNIO_Version is missing in V2.25, CheckDeviceID_Allowed in V2.3,
/// MayIssueProcessAlarm in V2.31. So they are only enforced for files that
/// declare V2.4 or later (the V2.4x schemas).
const V2_4X: Version = Version::new(2, 40);

struct Required {
    elements: &'static [&'static str],
    /// Names of the parent, grandparent, ...; `A|B` accepts either.
    within: &'static [&'static str],
    attributes: &'static [&'static str],
    since: Version,
}

const REQUIRED: &[Required] = &[
    Required {
        elements: &["DeviceIdentity"],
        within: &[],
        attributes: &["VendorID", "DeviceID"],
        since: EVERY_VERSION,
    },
    Required {
        elements: &["DeviceAccessPointItem"],
        within: &[],
        attributes: &[
            "ID",
            "ModuleIdentNumber",
            "PhysicalSlots",
            "MinDeviceInterval",
            "DNS_CompatibleName",
            "FixedInSlots",
            "ObjectUUID_LocalIndex",
        ],
        since: EVERY_VERSION,
    },
    Required {
        elements: &["DeviceAccessPointItem"],
        within: &[],
        attributes: &[
            "PNIO_Version",
            "NameOfStationNotTransferable",
            "DeviceAccessSupported",
            "CheckDeviceID_Allowed",
        ],
        since: V2_4X,
    },
    Required {
        elements: &["IOConfigData"],
        within: &[],
        attributes: &["MaxInputLength", "MaxOutputLength"],
        since: EVERY_VERSION,
    },
    Required {
        elements: &["ModuleItem"],
        within: &[],
        attributes: &["ID", "ModuleIdentNumber"],
        since: EVERY_VERSION,
    },
    Required {
        elements: SUBMODULE_ITEMS,
        within: &[],
        attributes: &["ID", "SubmoduleIdentNumber"],
        since: EVERY_VERSION,
    },
    Required {
        elements: &["VirtualSubmoduleItem", "SubmoduleItem"],
        within: &[],
        attributes: &["MayIssueProcessAlarm"],
        since: V2_4X,
    },
    Required {
        elements: &["InterfaceSubmoduleItem"],
        within: &[],
        attributes: &["TextId", "SupportedProtocols"],
        since: V2_4X,
    },
    Required {
        elements: &["PortSubmoduleItem"],
        within: &["SystemDefinedSubmoduleList"],
        attributes: &["SubslotNumber", "TextId"],
        since: V2_4X,
    },
    Required {
        elements: &["DataItem"],
        within: &["Input|Output"],
        attributes: &["DataType"],
        since: EVERY_VERSION,
    },
    Required {
        elements: &["DataItem"],
        within: &["Input|Output"],
        attributes: &["TextId"],
        since: V2_4X,
    },
    Required {
        elements: &["ParameterRecordDataItem"],
        within: &[],
        attributes: &["Index", "Length"],
        since: EVERY_VERSION,
    },
    Required {
        elements: &["ParameterRecordDataItem"],
        within: &["RecordDataList", "ApplicationProcess"],
        attributes: &["ID"],
        since: EVERY_VERSION,
    },
    Required {
        elements: &["Ref"],
        within: &["ParameterRecordDataItem"],
        attributes: &["ByteOffset", "DataType"],
        since: EVERY_VERSION,
    },
    Required {
        elements: &["Ref"],
        within: &["ParameterRecordDataItem"],
        attributes: &["DefaultValue", "TextId"],
        since: V2_4X,
    },
    Required {
        elements: &["Text"],
        within: &[],
        attributes: &["TextId", "Value"],
        since: EVERY_VERSION,
    },
];

/// The syntax of an attribute value.
#[derive(Clone, Copy)]
enum Syntax {
    /// `0x` and up to `digits` hex digits (`Unsigned16hexT`,
    /// `Unsigned32hexT`), not zero for the `...hex0T` types.
    Hex {
        digits: usize,
        nonzero: bool,
    },
    Unsigned {
        min: u32,
        max: u32,
    },
    /// `IndexT`: 0..0x7FFF vendor records, 0xB000..0xBFFF profile records.
    RecordIndex,
    ValueList,
    NumberList,
    Boolean,
    Version,
}

const HEX16: Syntax = Syntax::Hex {
    digits: 4,
    nonzero: false,
};
const HEX16_NONZERO: Syntax = Syntax::Hex {
    digits: 4,
    nonzero: true,
};
const HEX32: Syntax = Syntax::Hex {
    digits: 8,
    nonzero: false,
};
const HEX32_NONZERO: Syntax = Syntax::Hex {
    digits: 8,
    nonzero: true,
};
const U16: Syntax = Syntax::Unsigned {
    min: 0,
    max: 0xFFFF,
};
const U32: Syntax = Syntax::Unsigned {
    min: 0,
    max: u32::MAX,
};
const LENGTH: Syntax = Syntax::Unsigned {
    min: 1,
    max: u32::MAX,
};

const SYNTAX: &[(&[&str], &str, Syntax)] = &[
    (&["DeviceIdentity"], "VendorID", HEX16),
    (&["DeviceIdentity"], "DeviceID", HEX16_NONZERO),
    (
        &["DeviceAccessPointItem", "ModuleItem"],
        "ModuleIdentNumber",
        HEX32_NONZERO,
    ),
    (SUBMODULE_ITEMS, "SubmoduleIdentNumber", HEX32),
    (
        &["DeviceAccessPointItem"],
        "PhysicalSlots",
        Syntax::ValueList,
    ),
    (
        &["DeviceAccessPointItem", "ModuleItemRef"],
        "FixedInSlots",
        Syntax::ValueList,
    ),
    (
        &["DeviceAccessPointItem", "ModuleItemRef"],
        "AllowedInSlots",
        Syntax::ValueList,
    ),
    (&["ModuleItemRef"], "UsedInSlots", Syntax::ValueList),
    (
        &["VirtualSubmoduleItem", "SubmoduleItemRef"],
        "FixedInSubslots",
        Syntax::ValueList,
    ),
    (SUBMODULE_ITEMS, "Writeable_IM_Records", Syntax::ValueList),
    (&["DeviceAccessPointItem"], "PNIO_Version", Syntax::Version),
    (&["DeviceAccessPointItem"], "MinDeviceInterval", U16),
    (&["DeviceAccessPointItem"], "ObjectUUID_LocalIndex", U16),
    (&["DeviceAccessPointItem"], "PowerOnToCommReady", U32),
    (&["IOConfigData"], "MaxInputLength", U16),
    (&["IOConfigData"], "MaxOutputLength", U16),
    (
        &["InterfaceSubmoduleItem", "PortSubmoduleItem"],
        "SubslotNumber",
        U16,
    ),
    (
        &["InterfaceSubmoduleItem"],
        "DCP_HelloSupported",
        Syntax::Boolean,
    ),
    (&["DataItem"], "Length", LENGTH),
    (&["ParameterRecordDataItem"], "Index", Syntax::RecordIndex),
    (&["ParameterRecordDataItem"], "Length", LENGTH),
    (&["Ref", "Const"], "ByteOffset", U32),
    (&["Ref"], "BitOffset", Syntax::Unsigned { min: 0, max: 7 }),
    (&["Ref"], "BitLength", Syntax::Unsigned { min: 1, max: 15 }),
    (&["Ref"], "Length", LENGTH),
    (&["Ref"], "AllowedValues", Syntax::NumberList),
];

pub fn check(ctx: &Ctx<'_, '_>, out: &mut Vec<Diagnostic>) {
    for rule in REQUIRED.iter().filter(|r| ctx.version >= r.since) {
        let nodes = rule.elements.iter().flat_map(|e| ctx.idx.all(e));
        for node in nodes.filter(|n| within(n, rule.within)) {
            for attribute in rule.attributes.iter().filter(|a| !node.has_attribute(**a)) {
                out.push(missing(node, attribute, rule.since, ctx.version));
            }
        }
    }
    for (elements, attribute, syntax) in SYNTAX {
        for node in elements.iter().flat_map(|e| ctx.idx.all(e)) {
            if let Some(attr) = node.attribute_node(*attribute) {
                if let Some(expected) = violation(attr.value(), *syntax) {
                    out.push(bad_value(node, &attr, expected, *syntax));
                }
            }
        }
    }
}

fn missing(node: &El<'_, '_>, attribute: &str, since: Version, declared: Version) -> Diagnostic {
    let since_text = if since == EVERY_VERSION {
        "by every GSDML version".to_string()
    } else {
        format!("by the GSDML schema from {since} on, and this file declares {declared}")
    };
    Diagnostic::error(
        "E319",
        format!("{} lacks the attribute {attribute}", describe(node)),
    )
    .at(tag_span(node))
    .label(format!("no {attribute}"))
    .help(format!("{attribute} is required {since_text}"))
}

/// What the value should look like, if it does not.
fn violation(value: &str, syntax: Syntax) -> Option<String> {
    let ok = match syntax {
        Syntax::Hex { digits, nonzero } => {
            parse_hex(value, digits).is_some_and(|v| !nonzero || v != 0)
        }
        Syntax::Unsigned { min, max } => parse_u32(value).is_some_and(|v| (min..=max).contains(&v)),
        Syntax::RecordIndex => {
            parse_u32(value).is_some_and(|v| v <= 0x7FFF || (0xB000..=0xBFFF).contains(&v))
        }
        Syntax::ValueList => ValueList::parse(value).is_some(),
        Syntax::NumberList => NumberList::parse(value).is_some(),
        Syntax::Boolean => parse_bool(value).is_some(),
        Syntax::Version => Version::parse(value).is_some() && value.starts_with('V'),
    };
    (!ok).then(|| expected(syntax))
}

fn expected(syntax: Syntax) -> String {
    match syntax {
        Syntax::Hex { digits, nonzero } => format!(
            "0x followed by 1 to {digits} hex digits{}",
            if nonzero { ", not zero" } else { "" }
        ),
        Syntax::Unsigned { min, max } => format!("a decimal number from {min} to {max}"),
        Syntax::RecordIndex => "a record index 0..32767 or 45056..49151 (0xB000..0xBFFF)".into(),
        Syntax::ValueList => {
            "unsigned numbers and ranges lo..hi (lo <= hi), separated by spaces".into()
        }
        Syntax::NumberList => "numbers and ranges lo..hi (lo <= hi), separated by spaces".into(),
        Syntax::Boolean => "true or false".into(),
        Syntax::Version => "a version V<x>.<yy>".into(),
    }
}

fn bad_value(
    node: &El<'_, '_>,
    attr: &roxmltree::Attribute<'_, '_>,
    expected: String,
    syntax: Syntax,
) -> Diagnostic {
    let (code, kind, help) = match syntax {
        Syntax::Hex { digits, .. } => (
            "E318",
            "ident number",
            format!(
                "ident numbers are hex: write e.g. {}=\"0x{:0digits$}\"",
                attr.name(),
                1
            ),
        ),
        _ => (
            "E320",
            "value",
            format!("write {} as {expected}", attr.name()),
        ),
    };
    Diagnostic::error(
        code,
        format!(
            "{} of {} is \"{}\", not a valid {kind}",
            attr.name(),
            describe(node),
            attr.value()
        ),
    )
    .at(attr.range_value())
    .label(format!("expected {expected}"))
    .help(help)
}
