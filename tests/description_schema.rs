//! `schemas/description.schema.json`, which lets an editor complete and check
//! a description, held to the serde model it describes, so that neither can
//! change without the other:
//! - every table the schema describes has exactly the keys the model takes:
//!   a probe key put into that table makes the loader list the keys it
//!   expected there (serde's `deny_unknown_fields`), and the list must be
//!   the schema's; the same for the names of enumerations;
//! - the shipped descriptions and the guide's example conform to the
//!   schema, and descriptions with a misspelt key or an unknown kind do not.

use crate::support::descriptions;

use serde_json::Value as Json;
use toml::Value as Toml;

const PROBE: &str = "zzz_not_a_key";

pub(crate) fn schema() -> Json {
    serde_json::from_str(include_str!("../schemas/description.schema.json"))
        .expect("the schema is JSON")
}

fn md810() -> toml::Table {
    include_str!("../descriptions/md810dp.toml")
        .parse()
        .unwrap()
}

/// The node a `$ref` names, or the node itself.
fn resolve<'a>(root: &'a Json, node: &'a Json) -> &'a Json {
    match node.get("$ref").and_then(Json::as_str) {
        Some(reference) => {
            let name = reference
                .strip_prefix("#/definitions/")
                .expect("only local definitions");
            resolve(root, &root["definitions"][name])
        }
        None => node,
    }
}

/// A place in a description: table keys, `[]` for an array's first element.
type Path = Vec<String>;

/// Every table of fixed keys the schema describes, and every enumeration
/// of names, with where it sits.
fn walk<'a>(root: &'a Json, node: &'a Json, path: &Path, out: &mut Vec<(Path, &'a Json)>) {
    let node = resolve(root, node);
    for alternative in node
        .get("oneOf")
        .and_then(Json::as_array)
        .into_iter()
        .flatten()
    {
        walk(root, alternative, path, out);
    }
    if node.get("enum").is_some() {
        out.push((path.clone(), node));
    }
    if let Some(properties) = node.get("properties").and_then(Json::as_object) {
        if node["additionalProperties"] == Json::Bool(false) {
            out.push((path.clone(), node));
        }
        for (key, property) in properties {
            walk(root, property, &extend(path, key), out);
        }
    }
    if let Some(items) = node.get("items") {
        walk(root, items, &extend(path, "[]"), out);
    }
}

/// The places `walk` finds whose node has `keyword`.
fn places_with<'a>(root: &'a Json, keyword: &str) -> Vec<(Path, &'a Json)> {
    let mut found = Vec::new();
    walk(root, root, &Vec::new(), &mut found);
    found.retain(|(_, node)| node.get(keyword).is_some());
    found
}

fn extend(path: &Path, key: &str) -> Path {
    let mut longer = path.clone();
    longer.push(key.to_string());
    longer
}

/// The value at `path`, made a table (or an array holding one) where the
/// description has none.
fn place<'a>(table: &'a mut toml::Table, path: &[String]) -> &'a mut Toml {
    let (key, rest) = path.split_first().expect("a path below the root");
    let wants_array = rest.first().is_some_and(|next| next == "[]");
    let value = table
        .entry(key.clone())
        .or_insert_with(|| Toml::Table(Default::default()));
    if wants_array {
        if !matches!(value, Toml::Array(items) if !items.is_empty()) {
            *value = Toml::Array(vec![Toml::Table(Default::default())]);
        }
        let Toml::Array(items) = value else {
            unreachable!()
        };
        return match &rest[1..] {
            [] => &mut items[0],
            deeper => place(as_table(&mut items[0]), deeper),
        };
    }
    match rest {
        [] => value,
        deeper => place(as_table(value), deeper),
    }
}

fn as_table(value: &mut Toml) -> &mut toml::Table {
    if !value.is_table() {
        *value = Toml::Table(Default::default());
    }
    let Toml::Table(table) = value else {
        unreachable!()
    };
    table
}

/// The names the loader says it expected, from serde's "unknown field
/// `x`, expected one of `a`, `b`" (or "unknown variant").
fn expected_names(description: &toml::Table, unknown: &str) -> Vec<String> {
    let text = toml::to_string(description).unwrap();
    let (_, diagnostics) = descriptions::load_text("probe.toml", &text);
    let message = diagnostics
        .iter()
        .map(|d| d.message.to_string())
        .find(|m| m.contains(&format!("`{PROBE}`")) && m.contains(unknown))
        .unwrap_or_else(|| panic!("no `{unknown} {PROBE}` among {diagnostics:#?}"));
    let (_, expected) = message.split_once("expected").expect("a list of names");
    let mut names: Vec<String> = expected
        .split('`')
        .skip(1)
        .step_by(2)
        .map(String::from)
        .collect();
    names.sort();
    names
}

fn sorted_strings<'a>(names: impl Iterator<Item = &'a str>) -> Vec<String> {
    let mut names: Vec<String> = names.map(String::from).collect();
    names.sort();
    names
}

#[test]
fn every_table_of_the_schema_has_the_keys_the_loader_takes() {
    let root = schema();
    let tables = places_with(&root, "properties");
    assert!(tables.len() >= 20, "{} tables", tables.len());
    for (path, node) in &tables {
        let mut description = md810();
        match path.as_slice() {
            [] => {
                description.insert(PROBE.into(), Toml::Integer(1));
            }
            _ => {
                as_table(place(&mut description, path)).insert(PROBE.into(), Toml::Integer(1));
            }
        }
        let keys = node["properties"]
            .as_object()
            .unwrap()
            .keys()
            .map(String::as_str);
        // A table keyed by an enumeration (the baud rates) names its keys
        // as variants.
        assert_eq!(
            sorted_strings(keys),
            expected_names(&description, "unknown "),
            "the keys of {path:?}"
        );
    }
}

/// `[profinet.irt]`'s required keys.
const IRT: &str = "max_bridge_delay = 5500\nmax_number_ir_frame_data = 256\nsend_clock = [32]\nreduction_ratio = [1]\nport_tx_delay = 92\nport_rx_delay = 340";

#[test]
fn every_enumeration_of_the_schema_has_the_loaders_names() {
    let root = schema();
    let enums = places_with(&root, "enum");
    assert!(enums.len() >= 3, "{enums:?}");
    for (path, node) in &enums {
        let names = node["enum"]
            .as_array()
            .unwrap()
            .iter()
            .map(|n| n.as_str().unwrap());
        if path.last().is_some_and(|last| last == "[]") {
            // PPO types are strings the lowering reads: each name is accepted.
            for name in names {
                let mut description = md810();
                // A later device access point's entry has its required keys.
                if path.starts_with(&["profinet".into(), "daps".into(), "[]".into()]) {
                    let dap: toml::Table = "name = \"probe\"\nident = 0x99".parse().unwrap();
                    *place(&mut description, &path[..2]) = Toml::Array(vec![Toml::Table(dap)]);
                }
                // The RT_CLASS_3 table has its required keys, and makes the
                // device one of class C (E151 with md810's class B).
                if path.starts_with(&["profinet".into(), "irt".into()]) {
                    *place(&mut description, &path[..2]) = Toml::Table(IRT.parse().unwrap());
                    as_table(place(&mut description, &path[..1])).remove("conformance_class");
                }
                *place(&mut description, &path[..path.len() - 1]) =
                    Toml::Array(vec![Toml::String(name.into())]);
                // PPO5's words go with PPO5 alone (E002 otherwise).
                if name != "PPO5" {
                    if let Some(Toml::Table(profibus)) = description.get_mut("profibus") {
                        profibus.remove("ppo5_pzd_words");
                    }
                }
                // A DPV1 alarm required is one supported too (E180).
                if path.ends_with(&["required".to_string(), "[]".to_string()]) {
                    let supported = [&path[..path.len() - 2], &["supported".to_string()]].concat();
                    *place(&mut description, &supported) =
                        Toml::Array(vec![Toml::String(name.into())]);
                }
                let (ir, diagnostics) =
                    descriptions::load_text("probe.toml", &toml::to_string(&description).unwrap());
                assert!(ir.is_some(), "{name} at {path:?}: {diagnostics:#?}");
            }
            continue;
        }
        let mut description = md810();
        *place(&mut description, path) = Toml::String(PROBE.into());
        assert_eq!(
            sorted_strings(names),
            expected_names(&description, "unknown variant"),
            "the names of {path:?}"
        );
    }
}

/// Whether `value` conforms to `node`: the keywords the schema uses.
pub(crate) fn conforms(root: &Json, node: &Json, value: &Toml) -> Result<(), String> {
    let node = resolve(root, node);
    if let Some(alternatives) = node.get("oneOf").and_then(Json::as_array) {
        let matching = alternatives
            .iter()
            .filter(|a| conforms(root, a, value).is_ok())
            .count();
        return match matching {
            1 => Ok(()),
            n => Err(format!("{value:?} matches {n} of the alternatives")),
        };
    }
    // `if` a value conforms to one schema, it must to `then`'s too.
    if let (Some(condition), Some(then)) = (node.get("if"), node.get("then")) {
        if conforms(root, condition, value).is_ok() {
            conforms(root, then, value)?;
        }
    }
    if let Some(names) = node.get("enum").and_then(Json::as_array) {
        if !names
            .iter()
            .any(|n| Some(value.as_str().unwrap_or_default()) == n.as_str())
        {
            return Err(format!("{value:?} is none of {names:?}"));
        }
    }
    if let Some(kind) = node.get("type").and_then(Json::as_str) {
        let is = match (kind, value) {
            ("object", Toml::Table(_)) | ("array", Toml::Array(_)) => true,
            ("integer", Toml::Integer(_)) | ("boolean", Toml::Boolean(_)) => true,
            ("string", Toml::String(_)) => true,
            ("string", Toml::Datetime(d)) => datetime_fits(node, d),
            _ => false,
        };
        if !is {
            return Err(format!("{value:?} is not {kind}"));
        }
    }
    if let Toml::Integer(n) = value {
        let below = node
            .get("minimum")
            .and_then(Json::as_i64)
            .is_some_and(|min| *n < min);
        let above = node
            .get("maximum")
            .and_then(Json::as_i64)
            .is_some_and(|max| *n > max);
        if below || above {
            return Err(format!("{n} is out of range"));
        }
    }
    if let Toml::Array(items) = value {
        let min = node.get("minItems").and_then(Json::as_u64).unwrap_or(0);
        let max = node
            .get("maxItems")
            .and_then(Json::as_u64)
            .unwrap_or(u64::MAX);
        if !(min..=max).contains(&(items.len() as u64)) {
            return Err(format!("{} items", items.len()));
        }
        for item in items {
            conforms(root, &node["items"], item)?;
        }
    }
    if let Toml::Table(table) = value {
        let properties = node.get("properties").and_then(Json::as_object);
        for required in node
            .get("required")
            .and_then(Json::as_array)
            .into_iter()
            .flatten()
        {
            let key = required.as_str().unwrap();
            if !table.contains_key(key) {
                return Err(format!("`{key}` is missing"));
            }
        }
        for (key, item) in table {
            let property = properties
                .and_then(|p| p.get(key))
                .or_else(|| pattern_property(node, key));
            match (property, &node["additionalProperties"]) {
                (Some(property), _) => conforms(root, property, item),
                (None, Json::Bool(false)) => Err(format!("`{key}` is not a key here")),
                (None, Json::Null) => Ok(()),
                (None, rest) => conforms(root, rest, item),
            }
            .map_err(|why| format!("{key}: {why}"))?;
        }
    }
    Ok(())
}

/// The two forms of a date the schema takes, as the patterns it writes.
const DATE_PATTERN: &str = "^[0-9]{4}-[0-9]{2}-[0-9]{2}$";
const LOCAL_DATE_TIME_PATTERN: &str =
    "^[0-9]{4}-[0-9]{2}-[0-9]{2}[Tt ][0-9]{2}:[0-9]{2}(:[0-9]{2})?$";

/// Whether a TOML date or date-time is what a string node's pattern
/// takes: a date, or a local date-time (no offset). Another pattern fails
/// the test until this reader knows it.
fn datetime_fits(node: &Json, d: &toml::value::Datetime) -> bool {
    match node.get("pattern").and_then(Json::as_str) {
        Some(DATE_PATTERN) => d.date.is_some() && d.time.is_none(),
        Some(LOCAL_DATE_TIME_PATTERN) => d.date.is_some() && d.time.is_some() && d.offset.is_none(),
        Some(other) => panic!("a pattern this test cannot read: {other}"),
        None => false,
    }
}

/// The schema of `key` under `patternProperties`. The schema uses one form
/// of pattern, `^[a-z]{N}$` (language codes); another form fails the test
/// until this reader knows it.
fn pattern_property<'a>(node: &'a Json, key: &str) -> Option<&'a Json> {
    let patterns = node.get("patternProperties")?.as_object()?;
    patterns.iter().find_map(|(pattern, schema)| {
        let count = pattern
            .strip_prefix("^[a-z]{")
            .and_then(|rest| rest.strip_suffix("}$"))
            .and_then(|n| n.parse::<usize>().ok())
            .unwrap_or_else(|| panic!("a pattern this test cannot read: {pattern}"));
        let matches = key.len() == count && key.bytes().all(|b| b.is_ascii_lowercase());
        matches.then_some(schema)
    })
}

#[test]
fn the_shipped_descriptions_conform_and_broken_ones_do_not() {
    let root = schema();
    let valid = [
        ("md810dp.toml", include_str!("../descriptions/md810dp.toml")),
        ("9kdp1.toml", include_str!("../descriptions/9kdp1.toml")),
        (
            "mv810-pnet02.toml",
            include_str!("../descriptions/mv810-pnet02.toml"),
        ),
        (
            "md810-gateway.toml",
            include_str!("../descriptions/md810-gateway.toml"),
        ),
        (
            "the PROFIdrive fixture",
            include_str!("fixtures/valid/profidrive.toml"),
        ),
    ];
    let examples = descriptions::guide_examples()
        .into_iter()
        .map(|e| ("the guide's example", e));
    for (name, text) in valid.into_iter().chain(examples) {
        let value: Toml = text.parse::<toml::Table>().map(Toml::Table).unwrap();
        conforms(&root, &root, &value).unwrap_or_else(|why| panic!("{name}: {why}"));
    }
    // A second release on one day: a local date-time.
    let mut second_release: toml::Table = md810();
    second_release["profinet"]["date"] = "2026-12-01T07:14:47".parse().map(Toml::Datetime).unwrap();
    conforms(&root, &root, &Toml::Table(second_release)).unwrap();
    let invalid = [
        include_str!("fixtures/invalid/gsdml_date_with_offset.toml"),
        include_str!("fixtures/invalid/gsdml_date_quoted.toml"),
        include_str!("fixtures/invalid/unknown_key.toml"),
        include_str!("fixtures/invalid/profibus_key_typo.toml"),
        include_str!("fixtures/invalid/unknown_pkw_kind.toml"),
        // A GSD's revision and releases: optional without [profibus] only.
        include_str!("fixtures/invalid/gsd_without_revision.toml"),
        include_str!("fixtures/invalid/gsd_without_releases.toml"),
    ];
    for text in invalid {
        let value: Toml = text.parse::<toml::Table>().map(Toml::Table).unwrap();
        assert!(conforms(&root, &root, &value).is_err(), "{text}");
    }
}
