//! The values of a description that become GSD keywords are held by the
//! loader to the ranges the GSD keyword schema (`schemas/gsd-keywords.toml`)
//! gives the keywords, which `gsdc check` holds every GSD to, gsdc's own
//! included: at a keyword's limit a description loads and compiles, one
//! past it the loader refuses it (E101, E103), and never does a loaded
//! description reach E900 ("a bug in gsdc"). The limits are read here from
//! the schema file itself, so the test holds the loader to the file.

use crate::support::{descriptions::copy_symbols, scratch, CHECKOUT as MANIFEST};
use std::path::Path;
use toml::{Table, Value};

/// What the schema says of `keyword`: its type and the fields of limits.
fn schema(keyword: &str) -> Table {
    let text =
        std::fs::read_to_string(Path::new(MANIFEST).join("schemas/gsd-keywords.toml")).unwrap();
    let schema: Table = text.parse().unwrap();
    schema[keyword].as_table().unwrap().clone()
}

/// The numbers the schema lets `keyword` take.
fn range(keyword: &str) -> (i64, i64) {
    let spec = schema(keyword);
    let (low, high) = match spec["type"].as_str().unwrap() {
        "unsigned8" => (0, 0xFF),
        "unsigned16" => (0, 0xFFFF),
        other => panic!("{keyword}: {other}"),
    };
    let bound = |field: &str, default| spec.get(field).map_or(default, |v| v.as_integer().unwrap());
    (bound("min", low).max(low), bound("max", high).min(high))
}

fn max_len(keyword: &str) -> usize {
    schema(keyword)["max_len"].as_integer().unwrap() as usize
}

/// A description in `folder` with `value` at `path` (dotted, tables only).
fn with(folder: &str, name: &str, path: &str, value: Value) -> String {
    let text = std::fs::read_to_string(Path::new(MANIFEST).join(folder).join(name)).unwrap();
    let mut description: Table = text.parse().unwrap();
    let (tables, key) = path.rsplit_once('.').unwrap();
    let mut table = &mut description;
    for part in tables.split('.') {
        table = table
            .get_mut(part)
            .and_then(Value::as_table_mut)
            .unwrap_or_else(|| panic!("{name} has no [{tables}]"));
    }
    assert!(table.contains_key(key), "{name}: no {path}");
    table.insert(key.to_string(), value);
    toml::to_string(&description).unwrap()
}

/// The codes of the errors the loader finds, or none when it loads and
/// compiles; a compile error (E900) fails the test.
fn errors(folder: &str, name: &str, text: &str) -> Vec<&'static str> {
    let dir = Path::new(MANIFEST).join(folder);
    let (ir, diagnostics) = gsdc::load_with(name, text, &|path: &str| {
        std::fs::read(dir.join(path)).map_err(|e| e.to_string())
    });
    match ir {
        Some(ir) => {
            if let Err(problems) = gsdc::compile(&ir) {
                panic!("{name} loads but does not compile:\n{problems:#?}\n{text}");
            }
            Vec::new()
        }
        None => diagnostics.errors().map(|d| d.code).collect(),
    }
}

/// At the keyword's limits the value loads and compiles; past them it is
/// E101 (or E003 when past the key's type too). At the lowest end only
/// where nothing else of the description asks more of it.
#[track_caller]
fn holds_to(folder: &str, name: &str, path: &str, keyword: &str, least: Option<i64>) {
    let (min, max) = range(keyword);
    let min = least.map_or(min, |least| least.max(min));
    let try_value = |n: i64| errors(folder, name, &with(folder, name, path, Value::Integer(n)));
    let ends = if path.starts_with("gateway.") {
        // A gateway's nodes need more than the least length.
        vec![max]
    } else {
        vec![min, max]
    };
    for at in ends {
        assert_eq!(
            try_value(at),
            Vec::<&str>::new(),
            "{path} = {at} ({keyword})"
        );
    }
    for past in [min - 1, max + 1] {
        let codes = try_value(past);
        assert!(
            codes == ["E101"] || codes == ["E003"],
            "{path} = {past} ({keyword} takes {min}..={max}): {codes:?}"
        );
    }
}

const FIXTURES: &str = "tests/fixtures/valid";

/// `max_count_channels = 50` (or 100, or 255) loaded, and the GSD check
/// refused the generated file after emitting (E900): C2_Max_Count_Channels
/// takes at most 49.
#[test]
fn c2_max_count_channels_is_held_to_49() {
    let name = "no_warnings.toml";
    for (value, expected) in [
        (49, vec![]),
        (50, vec!["E101"]),
        (100, vec!["E101"]),
        (255, vec!["E101"]),
    ] {
        let text = with(
            FIXTURES,
            name,
            "profibus.dpv1.c2.max_count_channels",
            Value::Integer(value),
        );
        assert_eq!(errors(FIXTURES, name, &text), expected, "{value}");
    }
}

/// Every number of a description that becomes a GSD keyword, at and past
/// the keyword's limits. A class 2 channel has a connection at least, and
/// a station takes a bit time at least to answer: the loader asks that
/// much more than the keywords' types.
#[test]
fn every_number_that_becomes_a_keyword_is_held_to_the_keywords_range() {
    let name = "no_warnings.toml";
    for (path, keyword, least) in [
        ("profibus.min_slave_interval", "Min_Slave_Intervall", None),
        ("profibus.baud_rates.12M", "MaxTsdr_<baud>", Some(1)),
        ("profibus.dpv1.c1_max_data_len", "C1_Max_Data_Len", None),
        (
            "profibus.dpv1.c1_response_timeout",
            "C1_Response_Timeout",
            None,
        ),
        ("profibus.dpv1.c2.max_data_len", "C2_Max_Data_Len", Some(48)),
        (
            "profibus.dpv1.c2.response_timeout",
            "C2_Response_Timeout",
            None,
        ),
        (
            "profibus.dpv1.c2.max_count_channels",
            "C2_Max_Count_Channels",
            Some(1),
        ),
        (
            "profibus.dpv1.c2.max_initiate_pdu_length",
            "Max_Initiate_PDU_Length",
            Some(52),
        ),
    ] {
        holds_to(FIXTURES, name, path, keyword, least);
    }
    // Of a description without DPV1, which needs revision 3 or later.
    let text =
        std::fs::read_to_string(Path::new(MANIFEST).join("descriptions/9kdp1.toml")).unwrap();
    let dir = scratch("gsd-revision");
    copy_symbols(&dir);
    let text = text.replacen("[profibus]\n", "[profibus]\ngsd_revision = 5\n", 1);
    std::fs::write(dir.join("9kdp1.toml"), text).unwrap();
    let folder = dir.to_str().unwrap();
    // GSD_Revision takes 1..=5; 0 is a file of the specification's first
    // edition, which writes none.
    assert_eq!(range("GSD_Revision"), (1, 5));
    for (revision, expected) in [
        (0, vec![]),
        (1, vec![]),
        (5, vec![]),
        (6, vec!["E101"]),
        (-1, vec!["E003"]),
    ] {
        let text = with(
            folder,
            "9kdp1.toml",
            "profibus.gsd_revision",
            Value::Integer(revision),
        );
        assert_eq!(
            errors(folder, "9kdp1.toml", &text),
            expected,
            "gsd_revision = {revision}"
        );
    }
    for (path, keyword) in [
        ("gateway.max_input_len", "Max_Input_Len"),
        ("gateway.max_output_len", "Max_Output_Len"),
    ] {
        holds_to("descriptions", "md810-gateway.toml", path, keyword, Some(1));
    }
}

/// Every string of a description that becomes a GSD keyword's value, at
/// the keyword's longest and one character longer.
#[test]
fn every_string_that_becomes_a_keyword_is_held_to_the_keywords_length() {
    let name = "no_warnings.toml";
    for (path, keyword) in [
        ("device.vendor", "Vendor_Name"),
        ("device.model", "Model_Name"),
        ("device.revision", "Revision"),
        ("device.hardware_release", "Hardware_Release"),
        ("device.software_release", "Software_Release"),
        ("device.order_number", "OrderNumber"),
        ("device.info", "Info_Text"),
        ("profibus.implementation_type", "Implementation_Type"),
    ] {
        let longest = max_len(keyword);
        let text = std::fs::read_to_string(Path::new(MANIFEST).join(FIXTURES).join(name)).unwrap();
        // The fixture gives neither an info text nor an implementation type.
        let text = text
            .replacen("[device]\n", "[device]\ninfo = \"I\"\n", 1)
            .replacen(
                "[profibus]\n",
                "[profibus]\nimplementation_type = \"I\"\n",
                1,
            );
        let dir = scratch("strings");
        std::fs::write(dir.join(name), text).unwrap();
        let folder = dir.to_str().unwrap();
        let try_len = |n: usize| {
            errors(
                folder,
                name,
                &with(folder, name, path, Value::String("N".repeat(n))),
            )
        };
        assert_eq!(
            try_len(longest),
            Vec::<&str>::new(),
            "{path}: {longest} characters"
        );
        assert_eq!(
            try_len(longest + 1),
            ["E103"],
            "{path}: {} characters",
            longest + 1
        );
    }
}

/// The bitmap beside a GSD takes the GSD's stem as its name: an 8.3 stem
/// of 8 characters must fit Bitmap_Device.
#[test]
fn a_gsd_stem_fits_bitmap_device() {
    assert!(max_len("Bitmap_Device") >= 8);
}

/// The diagnostics of `text`, which must not load.
fn refused(text: &str) -> gsdc::Diagnostics {
    let (ir, diagnostics) = gsdc::load("card.toml", text);
    assert!(ir.is_none(), "{text}");
    diagnostics
}

/// A list of fixed length with an item more (or a hundred thousand more)
/// loaded, and the items past the length were dropped without a word; as
/// one with an item less, it is E003 at the list, saying how many items it
/// has.
#[test]
fn a_list_of_fixed_length_takes_no_item_more() {
    let no_warnings =
        std::fs::read_to_string(Path::new(MANIFEST).join(FIXTURES).join("no_warnings.toml"))
            .unwrap();
    let gateway =
        std::fs::read_to_string(Path::new(MANIFEST).join("descriptions/md810-gateway.toml"))
            .unwrap();
    let many = format!("[{}]", vec!["0"; 100_000].join(", "));
    for (text, from, to, items) in [
        (
            &no_warnings,
            "status_bytes = [0, 0, 0]",
            "status_bytes = [0, 0, 0, 1]".to_string(),
            "4",
        ),
        (
            &no_warnings,
            "status_bytes = [0, 0, 0]",
            "status_bytes = [0, 0]".to_string(),
            "2",
        ),
        (
            &no_warnings,
            "status_bytes = [0, 0, 0]",
            format!("status_bytes = {many}"),
            "100000",
        ),
        (
            &no_warnings,
            "range = [0, 65535]",
            "range = [0, 65535, 3]".to_string(),
            "3",
        ),
        (
            &gateway,
            "nodes = [1, 30]",
            "nodes = [1, 30, 99]".to_string(),
            "3",
        ),
        (
            &gateway,
            "range = [1, 30]",
            "range = [1, 30, 50]".to_string(),
            "3",
        ),
    ] {
        assert!(text.contains(from), "{from}");
        let mutated = text.replacen(from, &to, 1);
        let diagnostics = refused(&mutated);
        let d = diagnostics.iter().next().unwrap();
        assert_eq!(d.code, "E003", "{to:.40}: {diagnostics:?}");
        assert!(
            d.message
                .contains(&format!("invalid length {items}, expected a list of")),
            "{}",
            d.message
        );
        let at = mutated.find(&to).unwrap() + to.find('[').unwrap();
        assert_eq!(d.span.as_ref().map(|s| s.start), Some(at), "{to:.40}");
    }
}

/// `writeable_im_records = []` (a card whose controller writes no I&M
/// record) loaded and reached E900: gsdc wrote `Writeable_IM_Records=""`,
/// which its GSDML check refuses. Found by tests/hostile_properties.rs.
#[test]
fn no_writable_im_record_is_no_writeable_im_records_attribute() {
    let name = "no_warnings.toml";
    let text = with(
        FIXTURES,
        name,
        "profinet.writeable_im_records",
        Value::Array(Vec::new()),
    );
    assert_eq!(errors(FIXTURES, name, &text), Vec::<&str>::new());
    let (ir, _) = gsdc::load(name, &text);
    let gsdml = gsdc::compile(&ir.unwrap())
        .unwrap()
        .into_iter()
        .find(|a| a.kind == gsdc::ArtifactKind::Gsdml)
        .unwrap();
    let gsdml = String::from_utf8(gsdml.contents).unwrap();
    assert!(gsdml.contains("<VirtualSubmoduleItem ID=\"IDS_DAP\" SubmoduleIdentNumber=\"0x00000001\" MayIssueProcessAlarm=\"false\">"), "{gsdml}");
    assert!(!gsdml.contains("Writeable_IM_Records"));
}
