//! Identity and references: IDs unique in their scope (E306), every
//! reference resolvable (E307), every TextId defined in the primary language
//! (E308), and every primary text translated into each other language
//! (W300). The scopes are the keys of the V2.44 schema.

use foldhash::{HashMap, HashMapExt, HashSet};

use roxmltree::ExpandedName;

use super::index::{
    children, describe, in_gsdml, parent_is, tag_span, value_span, within, El, Index,
    SUBMODULE_ITEMS,
};
use super::Ctx;
use crate::diag::Diagnostic;

const XML_NS: &str = "http://www.w3.org/XML/1998/namespace";

/// The schema's ID scopes that references point into.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
enum Scope {
    Dap,
    Module,
    Submodule,
    /// The pluggable submodules of the SubmoduleList, which
    /// `SubmoduleItemTarget` refers to (a part of `Submodule`).
    ListedSubmodule,
    Graphic,
    Category,
    Value,
    /// Records of ApplicationProcess/RecordDataList, shared by submodules.
    SharedRecord,
    CommunicationInterface,
}

struct ScopeDef {
    scope: Scope,
    /// What a reference into the scope must name, for messages.
    noun: &'static str,
    elements: &'static [&'static str],
    within: &'static [&'static str],
    /// False for scopes that are part of another one, checked there.
    report_duplicates: bool,
}

const SCOPES: &[ScopeDef] = &[
    ScopeDef {
        scope: Scope::Dap,
        noun: "DeviceAccessPointItem",
        elements: &["DeviceAccessPointItem"],
        within: &[],
        report_duplicates: true,
    },
    ScopeDef {
        scope: Scope::Module,
        noun: "ModuleItem",
        elements: &["ModuleItem"],
        within: &[],
        report_duplicates: true,
    },
    ScopeDef {
        scope: Scope::Submodule,
        noun: "submodule item",
        elements: SUBMODULE_ITEMS,
        within: &[],
        report_duplicates: true,
    },
    ScopeDef {
        scope: Scope::ListedSubmodule,
        noun: "SubmoduleItem or PortSubmoduleItem of the SubmoduleList",
        elements: &["SubmoduleItem", "PortSubmoduleItem"],
        within: &["SubmoduleList"],
        report_duplicates: false,
    },
    ScopeDef {
        scope: Scope::Graphic,
        noun: "GraphicItem",
        elements: &["GraphicItem"],
        within: &[],
        report_duplicates: true,
    },
    ScopeDef {
        scope: Scope::Category,
        noun: "CategoryItem",
        elements: &["CategoryItem"],
        within: &[],
        report_duplicates: true,
    },
    ScopeDef {
        scope: Scope::Value,
        noun: "ValueItem",
        elements: &["ValueItem"],
        within: &[],
        report_duplicates: true,
    },
    ScopeDef {
        scope: Scope::SharedRecord,
        noun: "ParameterRecordDataItem of ApplicationProcess/RecordDataList",
        elements: &["ParameterRecordDataItem"],
        within: &["RecordDataList", "ApplicationProcess"],
        report_duplicates: true,
    },
    ScopeDef {
        scope: Scope::CommunicationInterface,
        noun: "CommunicationInterfaceItem",
        elements: &["CommunicationInterfaceItem"],
        within: &[],
        report_duplicates: true,
    },
];

/// (referring element, attribute, scope referred to)
const REFERENCES: &[(&str, &str, Scope)] = &[
    ("ModuleItemRef", "ModuleItemTarget", Scope::Module),
    (
        "SubmoduleItemRef",
        "SubmoduleItemTarget",
        Scope::ListedSubmodule,
    ),
    ("GraphicItemRef", "GraphicItemTarget", Scope::Graphic),
    ("ModuleInfo", "CategoryRef", Scope::Category),
    ("ModuleInfo", "SubCategory1Ref", Scope::Category),
    ("Ref", "ValueItemTarget", Scope::Value),
    (
        "ParameterRecordDataRef",
        "RecordDataTarget",
        Scope::SharedRecord,
    ),
    ("RecordDataRef", "RecordDataTarget", Scope::SharedRecord),
    (
        "CommunicationInterfaceModule",
        "CIM_Target",
        Scope::CommunicationInterface,
    ),
];

/// Keys that are unique among the children of one parent:
/// (parent, children, attribute).
const LOCAL_KEYS: &[(&str, &[&str], &str)] = &[
    ("ParameterRecordDataItem", &["Ref"], "ID"),
    ("Request", &["Ref"], "ID"),
    ("MenuList", &["MenuItem"], "ID"),
    ("UseableModules", &["ModuleItemRef"], "ModuleItemTarget"),
    (
        "UseableSubmodules",
        &["SubmoduleItemRef"],
        "SubmoduleItemTarget",
    ),
    (
        "SystemDefinedSubmoduleList",
        &["InterfaceSubmoduleItem", "PortSubmoduleItem"],
        "SubslotNumber",
    ),
    (
        "RecordDataList",
        &[
            "ParameterRecordDataItem",
            "F_ParameterRecordDataItem",
            "F_BaseIDRecordDataItem",
        ],
        "Index",
    ),
];

type Ids<'a, 'input> = HashMap<&'a str, El<'a, 'input>>;

pub fn check(ctx: &Ctx<'_, '_>, out: &mut Vec<Diagnostic>) {
    let mut scopes: HashMap<Scope, (Ids, &str)> = HashMap::new();
    for def in SCOPES {
        let nodes = def
            .elements
            .iter()
            .flat_map(|e| ctx.idx.all(e))
            .filter(|n| within(n, def.within));
        let mut sink = Vec::new();
        let ids = unique(&ctx.idx, nodes.copied(), "ID", &mut sink);
        if def.report_duplicates {
            out.append(&mut sink);
        }
        scopes.insert(def.scope, (ids, def.noun));
    }
    for (element, attribute, scope) in REFERENCES {
        for node in ctx.idx.all(element) {
            let (ids, noun) = &scopes[scope];
            if let Some(target) = node.attribute(*attribute).filter(|t| !ids.contains_key(t)) {
                out.push(dangling(node, attribute, target, noun));
            }
        }
    }
    local_keys(ctx, out);
    menu_references(ctx, out);
    texts(ctx, out);
}

/// The elements by the value of `attribute`; reports every later element
/// with a value already seen.
fn unique<'a, 'input: 'a, 'n, 'm>(
    idx: &Index<'_, '_>,
    nodes: impl Iterator<Item = El<'a, 'input>>,
    attribute: impl Into<ExpandedName<'n, 'm>> + Copy,
    out: &mut Vec<Diagnostic>,
) -> Ids<'a, 'input> {
    let mut seen: Ids<'a, 'input> = HashMap::new();
    for node in nodes {
        let Some(attr) = node.attribute_node(attribute) else {
            continue;
        };
        match seen.get(attr.value()) {
            Some(first) => out.push(duplicate(&node, &attr, first, idx.line_of(first))),
            None => {
                seen.insert(attr.value(), node);
            }
        }
    }
    seen
}

fn duplicate(
    node: &El<'_, '_>,
    attr: &roxmltree::Attribute<'_, '_>,
    first: &El<'_, '_>,
    first_line: usize,
) -> Diagnostic {
    let element = node.tag_name().name();
    let name = attr.name();
    Diagnostic::error(
        "E306",
        format!("{element} {name} \"{}\" is used twice", attr.value()),
    )
    .at(attr.range_value())
    .label("used again here")
    .help(format!(
        "the first {} with this {name} is at line {}; each must have its own {name}",
        first.tag_name().name(),
        first_line
    ))
}

fn dangling(node: &El<'_, '_>, attribute: &str, target: &str, wanted: &str) -> Diagnostic {
    Diagnostic::error(
        "E307",
        format!(
            "{attribute} \"{target}\" of {} refers to no {wanted}",
            describe(node)
        ),
    )
    .at(value_span(node, attribute))
    .label("unknown ID")
    .help(format!(
        "define a {wanted} with ID=\"{target}\" or refer to an existing one"
    ))
}

fn local_keys(ctx: &Ctx<'_, '_>, out: &mut Vec<Diagnostic>) {
    for (parent, members, attribute) in LOCAL_KEYS {
        for node in ctx.idx.all(parent) {
            let nodes = node
                .children()
                .filter(|c| in_gsdml(c) && members.contains(&c.tag_name().name()));
            unique(&ctx.idx, nodes, *attribute, out);
        }
    }
    for list in ctx.idx.all("ExternalTextList") {
        unique(&ctx.idx, children(*list, "Language"), (XML_NS, "lang"), out);
    }
}

/// MenuRef and ParameterRef point into their own record: to its MenuItems
/// and to the IDs of its Refs.
fn menu_references(ctx: &Ctx<'_, '_>, out: &mut Vec<Diagnostic>) {
    for menu in ctx.idx.all("MenuList") {
        let Some(record) = menu.parent_element() else {
            continue;
        };
        let items = ids_of(children(*menu, "MenuItem"));
        let refs = ids_of(children(record, "Ref"));
        for item in children(*menu, "MenuItem") {
            for (element, attribute, known, noun) in [
                ("MenuRef", "MenuTarget", &items, "MenuItem of this record"),
                (
                    "ParameterRef",
                    "ParameterTarget",
                    &refs,
                    "Ref of this record",
                ),
            ] {
                for reference in children(item, element) {
                    let target = reference.attribute(attribute);
                    if let Some(target) = target.filter(|t| !known.contains(t)) {
                        out.push(dangling(&reference, attribute, target, noun));
                    }
                }
            }
        }
    }
}

fn ids_of<'a>(nodes: impl Iterator<Item = El<'a, 'a>>) -> HashSet<&'a str> {
    nodes.filter_map(|n| n.attribute("ID")).collect()
}

fn texts(ctx: &Ctx<'_, '_>, out: &mut Vec<Diagnostic>) {
    let Some(primary_list) = ctx.idx.all("PrimaryLanguage").first() else {
        if let Some(list) = ctx.idx.all("ExternalTextList").first() {
            out.push(
                Diagnostic::error("E308", "the ExternalTextList has no PrimaryLanguage")
                    .at(tag_span(list))
                    .label("no PrimaryLanguage")
                    .help(
                        "add <PrimaryLanguage> with the English texts; every TextId refers to it",
                    ),
            );
        }
        return;
    };
    let primary_texts: Vec<El> = children(*primary_list, "Text").collect();
    let primary = unique(&ctx.idx, primary_texts.iter().copied(), "TextId", out);
    for node in ctx.idx.elements() {
        let Some(id) = node.attribute("TextId") else {
            continue;
        };
        let is_text = node.tag_name().name() == "Text";
        if is_text && parent_is(node, "PrimaryLanguage") || primary.contains_key(id) {
            continue;
        }
        out.push(unknown_text(node, id, is_text));
    }
    for language in ctx.idx.all("Language") {
        let translated = unique(&ctx.idx, children(*language, "Text"), "TextId", out);
        let missing: Vec<&str> = primary_texts
            .iter()
            .filter_map(|t| t.attribute("TextId"))
            .filter(|id| !translated.contains_key(id))
            .collect();
        if !missing.is_empty() {
            out.push(untranslated(language, &missing));
        }
    }
}

fn unknown_text(node: &El<'_, '_>, id: &str, in_language: bool) -> Diagnostic {
    let (message, help) = if in_language {
        (
            format!("the translated text \"{id}\" has no PrimaryLanguage text"),
            "every Language text translates a PrimaryLanguage text with the same TextId; add it there or remove this one",
        )
    } else {
        (
            format!("TextId \"{id}\" of {} is not defined in the PrimaryLanguage", describe(node)),
            "add <Text TextId=\"...\" Value=\"...\"/> to ExternalTextList/PrimaryLanguage, or fix the TextId",
        )
    };
    Diagnostic::error("E308", message)
        .at(value_span(node, "TextId"))
        .label("unknown TextId")
        .help(help)
}

fn untranslated(language: &El<'_, '_>, missing: &[&str]) -> Diagnostic {
    const SHOWN: usize = 5;
    let lang = language.attribute((XML_NS, "lang")).unwrap_or("?");
    let mut list = missing
        .iter()
        .take(SHOWN)
        .map(|id| format!("\"{id}\""))
        .collect::<Vec<_>>()
        .join(", ");
    if missing.len() > SHOWN {
        list.push_str(&format!(" and {} more", missing.len() - SHOWN));
    }
    Diagnostic::warning(
        "W300",
        format!("language \"{lang}\" lacks {} text(s) of the PrimaryLanguage: {list}", missing.len()),
    )
    .at(tag_span(language))
    .label("incomplete translation")
    .help("engineering tools show the primary (English) text instead; translate every PrimaryLanguage text")
}
