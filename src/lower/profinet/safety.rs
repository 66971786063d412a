//! `[[profinet.safety_modules]]`: PROFIsafe modules. Their IO data ends
//! each way with the message trailer (E126); their F-parameters keep to
//! the schema's values (E127); their description CRCs are PI's checker's,
//! pinned to the F-parameters and IO data they were given for (E128 when
//! those changed since; W109 while they are placeholders).

use super::slots::slots;
use crate::description::safety::{self as raw, FValue, SafetyDataType, OPTIONAL_F_PARAMETERS};
use crate::description::Text as RawText;
use crate::diag::Diagnostic;
use crate::ir::profinet::{BitItem, Category, TextRef};
use crate::ir::safety::{ident_of, DescriptionCrcs, FParameter, SafetyItem, SafetyModule};
use crate::ir::Text;
use crate::lower::checks::Checker;
use crate::lower::safety_crcs::{pinned, CrcFile};
use toml::Spanned;

/// Every safety module, in the description's order; `None` when one has
/// an error. A module's category joins `categories`, or takes the one of
/// the same text.
pub fn lower(
    cx: &mut Checker,
    given: &[Spanned<raw::SafetyModule>],
    categories: &mut Vec<Category>,
) -> Option<Vec<SafetyModule>> {
    let lowered: Vec<Option<SafetyModule>> = given
        .iter()
        .enumerate()
        .map(|(index, m)| module(cx, (index, m.get_ref()), categories))
        .collect();
    lowered.into_iter().collect()
}

fn module(
    cx: &mut Checker,
    (index, m): (usize, &raw::SafetyModule),
    categories: &mut Vec<Category>,
) -> Option<SafetyModule> {
    let number = index + 1;
    let what = |key: &str| format!("profinet.safety_modules[{index}].{key}");
    let tag = format!("SAFETY_{number}");
    let text = |cx: &mut Checker, t: &Spanned<RawText>, key: &str, id: &str| {
        TextRef::new(format!("IDT_{tag}_{id}"), cx.text(t, None, &what(key)))
    };
    let name = text(cx, &m.name, "name", "NAME");
    let info = m.info.as_ref().map_or_else(
        || TextRef::new(format!("IDT_{tag}_INFO"), name.text.clone()),
        |i| text(cx, i, "info", "INFO"),
    );
    let submodule_name = m.submodule_name.as_ref().map_or_else(
        || name.clone(),
        |t| text(cx, t, "submodule_name", "SUBMODULE_NAME"),
    );
    let submodule_info = m.submodule_info.as_ref().map_or_else(
        || info.clone(),
        |t| text(cx, t, "submodule_info", "SUBMODULE_INFO"),
    );
    let category = m
        .category
        .as_ref()
        .map(|c| category(cx.text(c, None, &what("category")), number, categories));
    let ident = cx.spanned_in_range(&m.ident, 1, u32::MAX.into(), &what("ident"));
    let slots = slots(cx, &m.slots, &what("slots"));
    let input = items(cx, &m.input, (&tag, "IN"), &what("input"));
    let output = items(cx, &m.output, (&tag, "OUT"), &what("output"));
    let f_parameters = f_parameters(cx, m.f_parameters.get_ref(), &what("f_parameters"));
    // A vendor's record index (the schema's IndexT also has the profile's
    // 0xB000 to 0xBFFF, which no F-parameter record of the corpus uses).
    let f_index = &m.f_parameters.get_ref().index;
    let f_index = cx.spanned_in_range(f_index, 0, 0x7FFF, &what("f_parameters.index"));
    let records = super::submodule_records::lower_safety(cx, &m.records, index);
    let (ident, slots, input, output, f_parameters, f_index) =
        (ident?, slots?, input?, output?, f_parameters?, f_index?);
    trailers_fit_the_crc(
        cx,
        (&input, &output),
        &f_parameters,
        (m, &what("f_parameters")),
    )?;
    let module = SafetyModule {
        id: format!("IDM_{tag}"),
        submodule_id: format!("IDS_{tag}"),
        ident_number: ident,
        submodule_ident_number: m.submodule_ident.as_ref().map_or(ident, |s| *s.get_ref()),
        ident: ident_of(number),
        name,
        info,
        submodule_name,
        submodule_info,
        category,
        slots,
        input,
        output,
        io_structure_desc_version: m.io_structure_desc_version.as_ref().map(|v| *v.get_ref()),
        f_parameter_index: f_index,
        f_parameters,
        records: records?,
        crcs: DescriptionCrcs {
            f_param_desc: *m.crcs.get_ref().f_param_desc.get_ref(),
            f_io_structure_desc: *m.crcs.get_ref().f_io_structure_desc.get_ref(),
            placeholder: m.crcs.get_ref().placeholder,
        },
    };
    let now = module.crc_fingerprint();
    pinned(cx, &m.crcs, &now, (&what("crcs"), CrcFile::Gsdml))?;
    Some(module)
}

/// The category of `text`: an existing one of the same text, else a new
/// one of this module's.
fn category(text: Text, number: usize, categories: &mut Vec<Category>) -> String {
    if let Some(same) = categories.iter().find(|c| c.text.text == text) {
        return same.id.clone();
    }
    let category = Category {
        id: format!("IDC_SAFETY_{number}"),
        text: TextRef::new(format!("IDT_CATEGORY_SAFETY_{number}"), text),
    };
    categories.push(category.clone());
    category.id
}

/// One way's items: at least one before the message trailer, which ends
/// them and is the only one (E126); each bit within its item (E101).
fn items(
    cx: &mut Checker,
    given: &Spanned<Vec<Spanned<raw::SafetyItem>>>,
    (tag, way): (&str, &str),
    what: &str,
) -> Option<Vec<SafetyItem>> {
    let list = given.get_ref();
    let trailers = list.iter().filter(|i| is_trailer(i)).count();
    let ends_with_trailer = list.last().is_some_and(is_trailer);
    if trailers != 1 || !ends_with_trailer || list.len() < 2 {
        cx.push(
            Diagnostic::error(
                "E126",
                format!("{what} does not end with its one PROFIsafe message trailer after the safety data"),
            )
            .at(given.span())
            .label("safety IO data")
            .help("list the safety data items, then one item of type \"F_MessageTrailer4Byte\" (a 3-byte CRC) or \"F_MessageTrailer5Byte\" (a 4-byte CRC) last, as the F-device sends and takes it"),
        );
        return None;
    }
    let mut complete = true;
    let mut lowered = Vec::with_capacity(list.len());
    for (i, item) in list.iter().enumerate() {
        let item = item.get_ref();
        let data_type = *item.data_type.get_ref();
        let item_what = format!("{what}[{i}]");
        let bits_in_item = u32::from(data_type.bytes()) * 8 - 1;
        let mut bits = Vec::with_capacity(item.bits.len());
        for (b, bit) in item.bits.iter().enumerate() {
            let bit = bit.get_ref();
            if item.bits[..b]
                .iter()
                .any(|o| *o.get_ref().bit.get_ref() == *bit.bit.get_ref())
            {
                cx.duplicate(
                    format!("{item_what}.bits: bit {}", bit.bit.get_ref()),
                    bit.bit.span(),
                );
                complete = false;
                continue;
            }
            let offset = cx.spanned_in_range(
                &bit.bit,
                0,
                bits_in_item.into(),
                &format!("{item_what}.bits"),
            );
            let text = cx.text(&bit.name, None, &format!("{item_what}.bits[{b}].name"));
            match offset {
                Some(offset) => bits.push(BitItem {
                    offset,
                    text: TextRef::new(format!("IDT_{tag}_{way}_{i}_BIT_{offset}"), text),
                }),
                None => complete = false,
            }
        }
        lowered.push(SafetyItem {
            data_type,
            use_as_bits: item
                .use_as_bits
                .as_ref()
                .map_or(!bits.is_empty(), |u| *u.get_ref()),
            text: TextRef::new(
                format!("IDT_{tag}_{way}_{i}"),
                cx.text(&item.name, None, &format!("{item_what}.name")),
            ),
            bits,
        });
    }
    complete.then_some(lowered)
}

/// E126 unless both ways end with the trailer of the CRC `F_CRC_Length`
/// says (its default, else the schema's 3-Byte-CRC): 4 bytes for a 3-byte
/// CRC, 5 for a 4-byte one, as MOVI-C's V2.6 module has them.
fn trailers_fit_the_crc(
    cx: &mut Checker,
    (input, output): (&[SafetyItem], &[SafetyItem]),
    f_parameters: &[FParameter],
    (m, what): (&raw::SafetyModule, &str),
) -> Option<()> {
    let crc_length = f_parameters
        .iter()
        .find(|p| p.element == "F_CRC_Length")
        .and_then(|p| {
            p.attributes
                .iter()
                .find(|(name, _)| *name == "DefaultValue")
        })
        .map_or("3-Byte-CRC", |(_, value)| value.as_str());
    let trailer = match crc_length {
        "4-Byte-CRC" => SafetyDataType::Trailer5Byte,
        _ => SafetyDataType::Trailer4Byte,
    };
    let fits = |items: &[SafetyItem]| items.last().is_some_and(|i| i.data_type == trailer);
    if fits(input) && fits(output) {
        return Some(());
    }
    cx.push(
        Diagnostic::error(
            "E126",
            format!("the safety data does not end with the {} a {crc_length} takes", trailer.name()),
        )
        .at(m.f_parameters.span())
        .label(format!("{what}: {crc_length}"))
        .help("a 3-byte CRC ends each way with F_MessageTrailer4Byte, a 4-byte CRC with F_MessageTrailer5Byte: change the trailers or F_CRC_Length"),
    );
    None
}

fn is_trailer(item: &Spanned<raw::SafetyItem>) -> bool {
    item.get_ref().data_type.get_ref().is_trailer()
}

/// What the schema lets an F-parameter element hold: tokens, or numbers
/// of a range; and the attributes it fixes.
struct Schema {
    element: &'static str,
    values: Values,
    /// AllowedValues names one value only (F_CRC_Length, F_Passivation).
    one_allowed: bool,
    fixed_default: Option<&'static str>,
    fixed_allowed: Option<&'static str>,
    fixed_changeable: Option<bool>,
    fixed_visible: Option<bool>,
}

enum Values {
    Tokens(&'static [&'static str]),
    Numbers(u32, u32),
}

const fn element(element: &'static str, values: Values) -> Schema {
    Schema {
        element,
        values,
        one_allowed: false,
        fixed_default: None,
        fixed_allowed: None,
        fixed_changeable: None,
        fixed_visible: None,
    }
}

/// Settable by the user: both attributes fixed to true.
const fn user_set(mut s: Schema) -> Schema {
    s.fixed_changeable = Some(true);
    s.fixed_visible = Some(true);
    s
}

/// The schema's `F_ParameterRecordDataT`, element by element in its order
/// (GSDML-DeviceProfile-v2.44.xsd).
const SCHEMA: [Schema; 13] = [
    element("F_Check_iPar", Values::Tokens(&["Check", "NoCheck"])),
    Schema {
        fixed_visible: Some(true),
        ..element("F_SIL", Values::Tokens(&["SIL1", "SIL2", "SIL3", "NoSIL"]))
    },
    Schema {
        one_allowed: true,
        fixed_changeable: Some(false),
        ..element(
            "F_CRC_Length",
            Values::Tokens(&["3-Byte-CRC", "4-Byte-CRC"]),
        )
    },
    Schema {
        fixed_default: Some("CRC-Seed24/32"),
        fixed_allowed: Some("CRC-Seed24/32"),
        fixed_changeable: Some(false),
        fixed_visible: Some(true),
        ..element("F_CRC_Seed", Values::Tokens(&["CRC-Seed24/32"]))
    },
    Schema {
        one_allowed: true,
        fixed_changeable: Some(false),
        fixed_visible: Some(true),
        ..element(
            "F_Passivation",
            Values::Tokens(&["Device/Module", "Channel"]),
        )
    },
    element("F_Block_ID", Values::Numbers(0, 7)),
    Schema {
        fixed_default: Some("1"),
        fixed_allowed: Some("1"),
        fixed_changeable: Some(false),
        fixed_visible: Some(true),
        ..element("F_Par_Version", Values::Numbers(0, 3))
    },
    user_set(element("F_Source_Add", Values::Numbers(1, 65534))),
    user_set(element("F_Dest_Add", Values::Numbers(1, 65534))),
    user_set(element("F_WD_Time", Values::Numbers(1, 65535))),
    user_set(element("F_WD_Time_2", Values::Numbers(1, 65535))),
    Schema {
        fixed_allowed: Some("0..65535"),
        ..user_set(element("F_Par_CRC", Values::Numbers(0, 65535)))
    },
    Schema {
        fixed_allowed: Some("0..4294967295"),
        ..user_set(element("F_iPar_CRC", Values::Numbers(0, u32::MAX)))
    },
];

/// The record's elements: each required one, and each optional one
/// stated, with its attributes as GSDML writes them.
fn f_parameters(cx: &mut Checker, given: &raw::FParameters, what: &str) -> Option<Vec<FParameter>> {
    let mut complete = true;
    let mut elements = Vec::new();
    for ((name, stated), schema) in given.elements().into_iter().zip(&SCHEMA) {
        debug_assert_eq!(name, schema.element);
        if stated.is_none() && OPTIONAL_F_PARAMETERS.contains(&schema.element) {
            continue;
        }
        let at = format!("{what}.{name}");
        let attributes = match stated {
            Some(p) => f_parameter(cx, p.get_ref(), schema, &at),
            None => Some(Vec::new()),
        };
        match attributes {
            Some(attributes) => elements.push(FParameter {
                element: schema.element,
                attributes,
            }),
            None => complete = false,
        }
    }
    complete.then_some(elements)
}

fn f_parameter(
    cx: &mut Checker,
    p: &raw::FParameter,
    schema: &Schema,
    at: &str,
) -> Option<Vec<(&'static str, String)>> {
    let mut attributes = Vec::new();
    let mut complete = true;
    if let Some(default) = &p.default {
        let value = match default.get_ref() {
            FValue::Number(n) => n.to_string(),
            FValue::Token(t) => t.clone(),
        };
        let fits = schema.fixed_default.map_or_else(
            || allows(&schema.values, default.get_ref()),
            |fixed| value == fixed,
        );
        complete &= fits
            || not_allowed(
                cx,
                default.span(),
                &format!("{at}.default = {value}"),
                schema,
            );
        attributes.push(("DefaultValue", value));
    }
    if let Some(allowed) = &p.allowed {
        let value = allowed.get_ref();
        let fits = schema.fixed_allowed.map_or_else(
            || allowed_values(&schema.values, value, schema.one_allowed),
            |fixed| value == fixed,
        );
        complete &= fits
            || not_allowed(
                cx,
                allowed.span(),
                &format!("{at}.allowed = \"{value}\""),
                schema,
            );
        attributes.push(("AllowedValues", value.clone()));
    }
    for (name, key, stated, fixed) in [
        ("Visible", "visible", &p.visible, schema.fixed_visible),
        (
            "Changeable",
            "changeable",
            &p.changeable,
            schema.fixed_changeable,
        ),
    ] {
        let Some(stated) = stated else { continue };
        let value = *stated.get_ref();
        let fits = fixed.is_none_or(|f| f == value);
        complete &=
            fits || not_allowed(cx, stated.span(), &format!("{at}.{key} = {value}"), schema);
        attributes.push((name, value.to_string()));
    }
    complete.then_some(attributes)
}

fn allows(values: &Values, value: &FValue) -> bool {
    match (values, value) {
        (Values::Tokens(tokens), FValue::Token(t)) => tokens.contains(&t.as_str()),
        (Values::Numbers(min, max), FValue::Number(n)) => (min..=max).contains(&n),
        _ => false,
    }
}

/// An `AllowedValues` of the element: its tokens separated by spaces (one
/// only where the schema says so), or a value list (`1..65534`, `0 2 4`)
/// within its range.
fn allowed_values(values: &Values, text: &str, one_allowed: bool) -> bool {
    let parts: Vec<&str> = text.split(' ').collect();
    if parts.is_empty() || (one_allowed && parts.len() > 1) {
        return false;
    }
    parts.iter().all(|part| match values {
        Values::Tokens(tokens) => tokens.contains(part),
        Values::Numbers(min, max) => {
            let (first, last) = part.split_once("..").unwrap_or((part, part));
            let bound = |s: &str| s.parse::<u32>().ok().filter(|n| (min..=max).contains(&n));
            matches!((bound(first), bound(last)), (Some(a), Some(b)) if a <= b)
        }
    })
}

/// E127; false, for the caller's `complete`.
fn not_allowed(
    cx: &mut Checker,
    span: std::ops::Range<usize>,
    stated: &str,
    schema: &Schema,
) -> bool {
    let takes = match schema.values {
        Values::Tokens(tokens) => tokens.join(", "),
        Values::Numbers(min, max) => format!("{min} to {max}"),
    };
    let fixed: Vec<String> = [
        schema.fixed_default.map(|v| format!("default {v}")),
        schema.fixed_allowed.map(|v| format!("allowed \"{v}\"")),
        schema.fixed_visible.map(|v| format!("visible {v}")),
        schema.fixed_changeable.map(|v| format!("changeable {v}")),
    ]
    .into_iter()
    .flatten()
    .collect();
    let fixed = match fixed.is_empty() {
        true => String::new(),
        false => format!("; the schema fixes {}", fixed.join(", ")),
    };
    cx.push(
        Diagnostic::error(
            "E127",
            format!(
                "{stated} is not what PROFIsafe's {} may hold",
                schema.element
            ),
        )
        .at(span)
        .label("not in the schema's values")
        .help(format!("{} takes {takes}{fixed}", schema.element)),
    );
    false
}
