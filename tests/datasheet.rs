//! The datasheets of the shipped descriptions (`gsdc doc`; their snapshots,
//! read line by line, are in outputs.rs): the diagrams' geometry from the
//! SVG's own numbers, the facts they must show, determinism, and the
//! command line.

use crate::support::{self, descriptions, gsdc, stderr, stdout};
use gsdc::ArtifactKind;

fn datasheet(name: &str, kind: ArtifactKind) -> String {
    descriptions::output_text(&descriptions::load(name), kind)
}

#[test]
fn file_names_and_kinds() {
    let files = gsdc::document(&descriptions::load("mv810-pnet02.toml"));
    let names: Vec<(&str, ArtifactKind)> = files
        .iter()
        .map(|a| (a.file_name.as_str(), a.kind))
        .collect();
    assert_eq!(
        names,
        [
            ("mv810-pnet02.html", ArtifactKind::DatasheetHtml),
            ("mv810-pnet02.md", ArtifactKind::DatasheetMarkdown)
        ]
    );
    // The datasheet is not among the files that ship with the card.
    let shipped = gsdc::compile(&descriptions::load("mv810-pnet02.toml")).unwrap();
    assert!(shipped.iter().all(|a| !matches!(
        a.kind,
        ArtifactKind::DatasheetHtml | ArtifactKind::DatasheetMarkdown
    )));
}

#[test]
fn deterministic_self_contained_and_without_paths() {
    for name in descriptions::shipped() {
        let first = gsdc::document(&descriptions::load(&name));
        assert_eq!(first, gsdc::document(&descriptions::load(&name)), "{name}");
        for file in &first {
            let text = String::from_utf8(file.contents.clone()).unwrap();
            let without_svg_namespace = text.replace("xmlns=\"http://www.w3.org/2000/svg\"", "");
            for forbidden in [
                "http:",
                "https:",
                "<script",
                "src=",
                "@import",
                "url(",
                env!("CARGO_MANIFEST_DIR"),
            ] {
                assert!(
                    !without_svg_namespace.contains(forbidden),
                    "{}: {forbidden}",
                    file.file_name
                );
            }
        }
    }
}

/// Every language of the description, each in its own `main`; the CSS
/// switch hides all but the checked one.
#[test]
fn every_language_has_its_section_and_switch() {
    let html = datasheet("md810dp.toml", ArtifactKind::DatasheetHtml);
    assert!(html.contains("<main lang=\"en\" class=\"lang lang-en\">"));
    assert!(html.contains("<main lang=\"zh\" class=\"lang lang-zh\">"));
    assert!(html.contains("id=\"lang-en\" checked>"));
    assert!(html.contains("#lang-zh:checked ~ main.lang-zh { display: block; }"));
    assert!(html.contains("MD810 标准 DP 接口"));
    assert!(html.contains("@media print"));
    let markdown = datasheet("md810dp.toml", ArtifactKind::DatasheetMarkdown);
    // Each title after the draft notice, while md810dp has placeholders.
    assert!(markdown.contains("): Inovance MD810DP: fieldbus interface\n"));
    assert!(markdown.contains("）：Inovance MD810DP：现场总线接口\n"));
}

// ---------------------------------------------------------------------------
// Geometry, from the SVG's numbers

struct Figure {
    kind: String,
    width: f64,
    height: f64,
    groups: Vec<Group>,
}

/// A group's class, its rectangle (x, y, width, height) and its texts' anchors.
type Group = (String, [f64; 4], Vec<(f64, f64)>);

fn attribute(tag: &str, name: &str) -> String {
    let start = tag
        .find(&format!(" {name}=\""))
        .unwrap_or_else(|| panic!("{name} in {tag}"))
        + name.len()
        + 3;
    tag[start..start + tag[start..].find('"').unwrap()].to_string()
}

fn number(tag: &str, name: &str) -> f64 {
    attribute(tag, name).parse().unwrap()
}

fn figures(html: &str) -> Vec<Figure> {
    html.split("<svg ")
        .skip(1)
        .map(|svg| {
            let svg = &svg[..svg.find("</svg>").unwrap()];
            let head = &svg[..svg.find('>').unwrap()];
            let view_box: Vec<f64> = attribute(&format!(" {head}"), "viewBox")
                .split(' ')
                .map(|n| n.parse().unwrap())
                .collect();
            let groups = svg
                .split("<g ")
                .skip(1)
                .map(|g| {
                    let rect = &g[g.find("<rect").unwrap()..];
                    let rect = &rect[..rect.find("/>").unwrap()];
                    let texts = g
                        .split("<text ")
                        .skip(1)
                        .map(|t| (number(&format!(" {t}"), "x"), number(&format!(" {t}"), "y")))
                        .collect();
                    (
                        attribute(&format!(" {g}"), "class"),
                        ["x", "y", "width", "height"].map(|k| number(rect, k)),
                        texts,
                    )
                })
                .collect();
            Figure {
                kind: attribute(&format!(" {head}"), "class"),
                width: view_box[2],
                height: view_box[3],
                groups,
            }
        })
        .collect()
}

/// The HTML datasheets of the shipped descriptions and of the PROFIdrive
/// fixture (whose PPO1 has the profile's PKW words), by name.
fn html_datasheets() -> Vec<(String, String)> {
    let fixture = descriptions::load_from("tests/fixtures/valid", "profidrive.toml");
    let fixture_html = descriptions::output_text(&fixture, ArtifactKind::DatasheetHtml);
    descriptions::shipped()
        .into_iter()
        .map(|name| {
            let html = datasheet(&name, ArtifactKind::DatasheetHtml);
            (name, html)
        })
        .chain([("profidrive.toml".to_string(), fixture_html)])
        .collect()
}

#[test]
fn diagrams_keep_their_boxes_apart_inside_the_drawing() {
    for (name, html) in html_datasheets() {
        let figures = figures(&html);
        // The gateway's one diagram (its example's data) in two languages.
        assert!(figures.len() >= 2, "{name}");
        for f in &figures {
            for (i, (class, [x, y, w, h], texts)) in f.groups.iter().enumerate() {
                assert!(
                    *x >= 0.0 && *y >= 0.0 && x + w <= f.width && y + h <= f.height,
                    "{name}: {class} outside"
                );
                for (_, [ox, oy, ow, oh], _) in &f.groups[i + 1..] {
                    let apart = x + w <= *ox || ox + ow <= *x || y + h <= *oy || oy + oh <= *y;
                    assert!(
                        apart,
                        "{name}: {class} at {x},{y} overlaps the box at {ox},{oy}"
                    );
                }
                // Anchors inside the box; the browser test measures the glyphs.
                for (tx, ty) in texts {
                    assert!(
                        *tx > *x && *tx < x + w && *ty > *y && *ty < y + h,
                        "{name}: text at {tx},{ty}"
                    );
                }
            }
        }
    }
}

#[test]
fn an_overview_has_a_box_per_word_of_every_module() {
    let ir = descriptions::load("md810dp.toml");
    let html = datasheet("md810dp.toml", ArtifactKind::DatasheetHtml);
    let word_boxes = |f: &Figure| {
        f.groups
            .iter()
            .filter(|(c, _, _)| c == "box pkw" || c == "box pzd")
            .count()
    };
    let overviews: Vec<usize> = figures(&html)
        .iter()
        .filter(|f| f.kind == "overview")
        .map(word_boxes)
        .collect();
    let words = |layouts: &mut dyn Iterator<Item = gsdc::ir::Layout>| -> usize {
        layouts
            .map(|l| usize::from(l.pkw_words() + l.pzd_words))
            .sum()
    };
    let ppo = words(
        &mut ir
            .profibus
            .as_ref()
            .unwrap()
            .modules
            .iter()
            .filter_map(|m| m.layout),
    );
    let pn = words(
        &mut ir
            .profinet
            .as_ref()
            .unwrap()
            .modules
            .iter()
            .map(|m| m.layout),
    );
    // PPO1..PPO5: 6 + 10 + 2 + 6 + 16; PROFINET: 6 + 10 + 16 + 2 + 6 + 12. English, then Chinese.
    assert_eq!((ppo, pn), (40, 52));
    assert_eq!(overviews, [ppo, pn, ppo, pn]);
}

/// MV810's status word: bits 9-10 are one box, bits 11-15 one box each.
#[test]
fn a_status_word_is_drawn_bit_by_bit() {
    let html = datasheet("mv810-pnet02.toml", ArtifactKind::DatasheetHtml);
    let bits: Vec<Figure> = figures(&html)
        .into_iter()
        .filter(|f| f.kind == "bits")
        .collect();
    assert_eq!(bits.len(), 4, "control and status word, two languages");
    let status = &bits[1];
    let fields: Vec<&[f64; 4]> = status
        .groups
        .iter()
        .filter(|(c, _, _)| c == "box field")
        .map(|(_, r, _)| r)
        .collect();
    let reserved = status
        .groups
        .iter()
        .filter(|(c, _, _)| c == "box reserved")
        .count();
    // Bits 0-8 one field each, bits 9-10 one field; 11-15 reserved.
    assert_eq!((fields.len(), reserved), (10, 5));
    let widest = fields.iter().map(|r| r[2]).fold(0.0, f64::max);
    let narrowest = fields.iter().map(|r| r[2]).fold(f64::MAX, f64::min);
    assert!(
        widest > 2.0 * narrowest,
        "the two-bit field spans two columns"
    );
}

// ---------------------------------------------------------------------------
// The gateway (MD810 manual chapter 2)

/// The rows of the Markdown table whose caption contains `caption`, the
/// first such table; each row as its cells.
fn table_rows(markdown: &str, caption: &str) -> Vec<Vec<String>> {
    let start = markdown
        .lines()
        .position(|l| l.starts_with('*') && l.contains(caption))
        .unwrap_or_else(|| panic!("no table {caption:?}"));
    markdown
        .lines()
        .skip(start + 4)
        .take_while(|l| l.starts_with('|'))
        .map(|l| {
            l.trim_matches('|')
                .split(" | ")
                .map(|c| c.trim().to_string())
                .collect()
        })
        .collect()
}

/// The PROFIdrive fixture's parameter channel: the profile's words, its
/// ids and error numbers, and worked examples for P10.05 = PNU 1005 that
/// the codec computes (PKE = id << 12 | 0x3ED), checked here by hand.
#[test]
fn the_profidrive_channel_has_the_profiles_ids_and_worked_examples() {
    let ir = descriptions::load_from("tests/fixtures/valid", "profidrive.toml");
    let md = descriptions::output_text(&ir, ArtifactKind::DatasheetMarkdown);
    let first_cells = |caption: &str| -> Vec<String> {
        table_rows(&md, caption)
            .into_iter()
            .map(|r| r[0].clone())
            .collect()
    };
    assert_eq!(first_cells("The PKW words"), ["PKE", "IND", "PWE1", "PWE2"]);
    let ids = |range: std::ops::RangeInclusive<u8>| -> Vec<String> {
        range.map(|id| id.to_string()).collect()
    };
    assert_eq!(first_cells("Request ids"), ids(0..=9));
    assert_eq!(first_cells("Response ids"), ids(0..=8));
    assert_eq!(
        first_cells("Error numbers of response 7"),
        ["0", "1", "2", "3", "4", "5", "6", "7", "11", "12", "17"]
    );
    assert!(md.contains("The examples read and write `P10.05` (PNU 1005)"));
    let examples: Vec<[String; 3]> = table_rows(&md, "Worked examples")
        .into_iter()
        .map(|r| [r[0].clone(), r[1].clone(), r[3].clone()])
        .collect();
    let row = |what: &str, sent: &str, answer: &str| {
        [what.to_string(), format!("`{sent}`"), format!("`{answer}`")]
    };
    assert_eq!(
        examples,
        [
            row("read P10.05", "13ED 0000 0000 0000", "13ED 0000 0000 vvvv"),
            row("read P10.05", "13ED 0000 0000 0000", "23ED 0000 vvvv vvvv"),
            row(
                "change P10.05 to vvvv (word)",
                "23ED 0000 0000 vvvv",
                "13ED 0000 0000 vvvv"
            ),
            row(
                "change P10.05 to vvvvvvvv (double word)",
                "33ED 0000 vvvv vvvv",
                "23ED 0000 vvvv vvvv"
            ),
            row(
                "read element ss of P10.05",
                "63ED ss00 0000 0000",
                "43ED ss00 0000 vvvv"
            ),
            row(
                "change P10.05 to vvvv (word)",
                "23ED 0000 0000 vvvv",
                "73ED 0000 0000 xxxx"
            ),
            row(
                "change P10.05 to vvvv (word)",
                "23ED 0000 0000 vvvv",
                "83ED 0000 0000 0000"
            ),
            row("no request", "0000 0000 0000 0000", "0000 0000 0000 0000"),
        ]
    );
    // The PPO's words as the profile names them, both ways.
    assert_eq!(
        table_rows(&md, "PPO1: 4 PKW + 2 PZD")[2],
        ["PWE1", "bytes 4-5", "value, high word", "value, high word"]
    );
    // The Chinese page has the same tables.
    assert!(md.contains("*表 11 请求标识（PKE 位 15-12，十进制）*"));
    assert!(md.contains("| 17 | 当前运行状态下无法处理请求 |"));
}

/// Chapter 2's facts: 2.2.1 (244 bytes each way), 2.4 step 4 (30 slaves,
/// the bridge itself slave 1) and step 5 (INPUT 120 words, OUTPUT 64), and
/// 2.5's table of types, codes and block lengths.
#[test]
fn the_gateway_datasheet_is_chapter_2() {
    let md = datasheet("md810-gateway.toml", ArtifactKind::DatasheetMarkdown);
    let facts = table_rows(&md, "The gateway to CANopen");
    let fact = |item: &str| {
        facts
            .iter()
            .find(|r| r[0] == item)
            .unwrap_or_else(|| panic!("{item}"))[1]
            .clone()
    };
    assert_eq!(fact("Second bus"), "CANopen");
    assert_eq!(fact("Node numbers"), "1 to 30");
    assert_eq!(fact("The gateway's own node"), "1");
    assert_eq!(fact("Input bytes at most (Max_Input_Len)"), "244");
    assert_eq!(fact("Output bytes at most (Max_Output_Len)"), "244");
    assert_eq!(fact("Modules at most (Max_Module)"), "20");
    assert!(fact("The nodes' words in the data").ends_with("**the description's own choice**"));

    // The example: 120 words in, 64 out, in fewest modules.
    let nodes = table_rows(&md, "The example's nodes");
    assert_eq!(nodes.len(), 16, "15 slaves and the total");
    assert_eq!(nodes[15], ["all", "120", "240 bytes", "64", "128 bytes"]);
    assert_eq!(nodes[8], ["9", "8", "bytes 128-143", "0", "—"]);
    let modules = table_rows(&md, "The modules the master plugs for the example");
    assert_eq!(
        modules,
        [
            [
                "input, nodes → master",
                "120",
                "INPUT 16 words × 7, INPUT 8 words",
                "`5F 5F 5F 5F 5F 5F 5F 57`"
            ],
            [
                "output, master → nodes",
                "64",
                "OUTPUT 16 words × 4",
                "`6F 6F 6F 6F`"
            ]
        ]
    );
    // Its User_Prm_Data, read back by gsdc decode: the totals, nothing refused.
    let prm: String = table_rows(&md, "User_Prm_Data of the example")
        .iter()
        .map(|r| r[1].trim_matches('`').to_string())
        .collect::<Vec<_>>()
        .join(" ");
    let decoded = gsdc([
        "decode",
        "descriptions/md810-gateway.toml",
        "--format",
        "json",
        "--prm",
        &prm,
    ]);
    assert_eq!(decoded.status.code(), Some(0));
    let decoded: serde_json::Value = serde_json::from_slice(&decoded.stdout).unwrap();
    let totals = &decoded["prm"]["gateway"];
    assert_eq!(
        (
            &totals["node_count"],
            &totals["input_len"],
            &totals["output_len"],
            &totals["refused"]
        ),
        (
            &serde_json::json!(15),
            &serde_json::json!(240),
            &serde_json::json!(128),
            &serde_json::Value::Null
        )
    );

    // 2.5: each type and code with its block, decimal codes as hex bytes.
    let types = table_rows(&md, "Diagnosis types and codes");
    let blocks: Vec<(&str, &str, &str)> = types
        .iter()
        .map(|r| (r[0].as_str(), r[2].as_str(), r[4].as_str()))
        .collect();
    assert_eq!(
        blocks,
        [
            ("1", "35 (0x23)", "`04 01 02 23`"),
            ("1", "34 (0x22)", "`04 01 02 22`"),
            ("3", "32 (0x20)", "`04 03 02 20`"),
            ("4", "hhll: 16 bits, high byte first", "`05 04 02 hh ll`"),
        ]
    );
    let bytes = table_rows(&md, "The diagnosis, byte by byte");
    assert_eq!(
        bytes[3..],
        [
            [
                "byte 6",
                "header: the block's length, 04 (types 1 and 3) or 05 (type 4)"
            ],
            ["byte 7", "the type (table below)"],
            ["byte 8", "the CANopen node, 1 to 30"],
            [
                "byte 9",
                "types 1 and 3: the code; type 4: Drive fault code, high byte"
            ],
            ["byte 10", "type 4: Drive fault code, low byte"],
        ]
    );
    // The manual's own words in Chinese.
    for zh in [
        "| 1 | 参数错误 | 35 (0x23) | 参数PDO长度与变频器不匹配 | `04 01 02 23` |",
        "| 3 | CANopen 网络故障 | 32 (0x20) | 运行中 CANopen 从站掉线 | `04 03 02 20` |",
        "| 4 | 变频报故障 | hhll：16 位，高字节在前 | 变频器故障 | `05 04 02 hh ll` |",
    ] {
        assert!(md.contains(zh), "{zh}");
    }
}

/// The example's data as drawn: one box per slave that sends (15) and per
/// slave that receives (8), each with its bytes, in ascending slave number.
#[test]
fn the_gateway_example_is_drawn_slave_by_slave() {
    let html = datasheet("md810-gateway.toml", ArtifactKind::DatasheetHtml);
    let nodes: Vec<Figure> = figures(&html)
        .into_iter()
        .filter(|f| f.kind == "nodes")
        .collect();
    assert_eq!(nodes.len(), 2, "English and Chinese");
    let boxes: Vec<&[f64; 4]> = nodes[0]
        .groups
        .iter()
        .filter(|(c, _, _)| c == "box pzd")
        .map(|(_, r, _)| r)
        .collect();
    assert_eq!(boxes.len(), 15 + 8);
    // Eight to a row: slave 9's input box starts the second row, and the
    // output lane lies below both input rows.
    assert_eq!(boxes[8][0], boxes[0][0]);
    assert!(boxes[8][1] > boxes[0][1]);
    assert!(boxes[15][1] > boxes[8][1]);
    let svg = &html[html.find("class=\"nodes\"").unwrap()..];
    let svg = &svg[..svg.find("</svg>").unwrap()];
    for label in [
        "node 1",
        "node 15",
        "bytes 224-239",
        "bytes 112-127",
        "8 words",
    ] {
        assert!(svg.contains(&format!(">{label}</text>")), "{label}");
    }
}

// ---------------------------------------------------------------------------
// The command line

#[test]
fn gsdc_doc_writes_both_files_and_leaves_unchanged_ones_alone() {
    let out = support::scratch("ok");
    let out_arg = out.to_str().unwrap();
    let first = gsdc([
        "doc",
        "descriptions/md810dp.toml",
        "descriptions/9kdp1.toml",
        "--out",
        out_arg,
    ]);
    assert_eq!(first.status.code(), Some(0), "{}", stderr(&first));
    let stdout = stdout(&first);
    for file in ["md810dp.html", "md810dp.md", "9kdp1.html", "9kdp1.md"] {
        assert!(
            stdout.contains(&format!("wrote {}", out.join(file).display())),
            "{stdout}"
        );
        let written = std::fs::read(out.join(file)).unwrap();
        let stem = file.split('.').next().unwrap();
        let ir = descriptions::load(&format!("{stem}.toml"));
        let expected = gsdc::document(&ir)
            .into_iter()
            .find(|a| a.file_name == file)
            .unwrap();
        assert_eq!(written, expected.contents, "{file}");
    }
    let again = gsdc(["doc", "descriptions/md810dp.toml", "--out", out_arg]);
    let said = support::stdout(&again);
    assert!(!said.contains("wrote"), "{said}");
    assert_eq!(
        said.matches("unchanged").count(),
        2,
        "the HTML and the Markdown: {said}"
    );
}

#[test]
fn gsdc_doc_writes_nothing_when_a_description_has_an_error() {
    let dir = support::scratch("bad");
    let out = dir.join("out");
    let run = gsdc([
        "doc",
        "descriptions/md810dp.toml",
        "tests/fixtures/invalid/unknown_ppo.toml",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(run.status.code(), Some(1));
    let stderr = stderr(&run);
    assert!(
        stderr.contains("E104") && stderr.contains("nothing written"),
        "{stderr}"
    );
    assert!(!out.exists());
}

#[test]
fn gsdc_doc_usage_and_io_errors_exit_2() {
    let dir = support::scratch("missing");
    let out = dir.join("out");
    let missing = gsdc([
        "doc",
        "descriptions/no-such.toml",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(missing.status.code(), Some(2));
    let said = stderr(&missing);
    assert!(
        said.starts_with("error: cannot read descriptions/no-such.toml: No such file"),
        "said once: {said}"
    );
    assert_eq!(gsdc(["doc"]).status.code(), Some(2));
    let help = stdout(&gsdc(["doc", "--help"]));
    assert!(
        help.contains("gsdc doc descriptions/md810dp.toml --out dist"),
        "{help}"
    );
}

/// A description in English alone (9KDP1's manual is English): one
/// `main`, shown, and no switch.
#[test]
fn one_language_needs_no_switch() {
    let ir = descriptions::load("9kdp1.toml");
    assert!(ir.languages.is_empty(), "9KDP1 has English texts only");
    let html = gsdc::document(&ir).remove(0);
    let html = String::from_utf8(html.contents).unwrap();
    assert_eq!(html.matches("<main").count(), 1);
    assert!(html.contains("<main lang=\"en\">"));
    assert!(!html.contains("<input") && !html.contains("main.lang"));
}

/// Every language of the description has its page: a German text on a
/// page of its own, among gsdc's German words, on the switch by its own
/// name.
#[test]
fn every_language_of_the_description_has_its_page() {
    let ir = descriptions::load_from("tests/fixtures/valid", "no_warnings.toml");
    assert_eq!(ir.languages, ["de"]);
    let html = gsdc::document(&ir).remove(0);
    let html = String::from_utf8(html.contents).unwrap();
    assert_eq!(html.matches("<main").count(), 2);
    let german = &html[html.find("<main lang=\"de\"").expect("a German page")..];
    assert!(german.contains("X1 Feldbuskarte"), "the German name");
    assert!(
        german.contains("Die Dateien, die gsdc aus der Beschreibung erzeugt"),
        "gsdc's German words"
    );
    assert!(!german.contains("The files gsdc generates"), "{german}");
    assert!(
        html.contains("<label for=\"lang-de\" lang=\"de\">Deutsch</label>"),
        "{html}"
    );
}

/// A record's caption names it in the page's language: German on the
/// German page, not the English name.
#[test]
fn a_record_is_named_in_the_pages_language() {
    let path = support::checkout("tests/fixtures/valid/no_warnings.toml");
    let text = std::fs::read_to_string(path).unwrap().replace(
        "pzd_out = 1\n",
        "pzd_out = { index = 1, name = { en = \"PZD out\", de = \"PZD aus\" } }\n",
    );
    let ir = descriptions::load_text("no_warnings.toml", &text)
        .0
        .unwrap();
    let html = gsdc::document(&ir).remove(0);
    let html = String::from_utf8(html.contents).unwrap();
    let (english, german) = html.split_at(html.find("<main lang=\"de\"").expect("a German page"));
    assert!(english.contains("Record 1: PZD out,"), "{english}");
    assert!(german.contains("Datensatz 1: PZD aus,"), "{german}");
    assert!(!german.contains("PZD out,"), "{german}");
}

/// MinDeviceInterval counts 31.25 µs: 10 is 312.5 µs, not 312.
#[test]
fn the_update_time_is_exact_to_the_quarter_microsecond() {
    let text = descriptions::shipped_text("mv810-pnet02.toml")
        .replace("min_device_interval = 32", "min_device_interval = 10");
    let ir = descriptions::load_text("mv810-pnet02.toml", &text)
        .0
        .unwrap();
    let md = gsdc::document(&ir).remove(1);
    let md = String::from_utf8(md.contents).unwrap();
    assert!(md.contains("| 10 × 31.25 µs = 312.5 µs |"), "{md}");
}

#[test]
fn gsdc_doc_refuses_two_descriptions_with_one_name() {
    let dir = support::scratch("twice");
    let out = dir.join("out");
    let run = gsdc([
        "doc",
        "descriptions/md810dp.toml",
        "descriptions/md810dp.toml",
        "--out",
        out.to_str().unwrap(),
    ]);
    // The same description twice gives the same files: written once.
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    std::fs::remove_dir_all(&out).unwrap();
    let copy = support::scratch("other");
    descriptions::copy_symbols(&copy);
    let other = copy.join("md810dp.toml");
    let text = descriptions::shipped_text("md810dp.toml");
    std::fs::write(&other, text.replace("md810\"", "md810-b\"")).unwrap();
    let run = gsdc([
        "doc",
        "descriptions/md810dp.toml",
        other.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(run.status.code(), Some(1));
    let said = stderr(&run);
    assert!(said.contains("both give md810dp.html"), "{said}");
    assert!(!out.exists());
}

/// The diagnosis bytes say what the description says of them, in the
/// datasheet's byte table and in both layouts' diagnosis comment: MD810's
/// byte 7 is 1.8's 设备专用诊断高字节, the fault information of U0-62, in
/// both languages; 9KDP1's its description's fault code of Modbus 8000H.
/// None is "not described".
#[test]
fn diagnosis_bytes_say_what_the_description_says() {
    let md810 = [
        "| 字节 7 | 设备专用诊断高字节 |",
        "设备专用诊断反馈的是变频器的相关故障信息，与 U0-62 的值一致",
        "reports the drive's fault information, the same as the value of U0-62",
    ];
    for (name, high, low, said) in [
        (
            "md810dp.toml",
            "Device-related diagnosis, high byte",
            "Device-related diagnosis, low byte",
            &md810[..],
        ),
        (
            "9kdp1.toml",
            "Inverter fault (Modbus 8000H), high byte",
            "Inverter fault (Modbus 8000H), low byte",
            &[][..],
        ),
    ] {
        let md = datasheet(name, ArtifactKind::DatasheetMarkdown);
        let rows = table_rows(&md, "The diagnosis, byte by byte");
        let row = |byte: &str| rows.iter().find(|r| r[0] == byte).map(|r| r[1].as_str());
        assert_eq!(row("byte 7"), Some(high), "{name}: {rows:?}");
        assert!(row("byte 8").unwrap().starts_with(low), "{name}: {rows:?}");
        for text in said {
            assert!(md.contains(text), "{name}: {text}");
        }
        let ir = descriptions::load(name);
        for kind in [ArtifactKind::RustLayout, ArtifactKind::CHeader] {
            let layout = descriptions::output_text(&ir, kind);
            let words: Vec<&str> = layout
                .split_whitespace()
                .filter(|w| !["///", "/*", "*", "*/"].contains(w))
                .collect();
            let words = words.join(" ");
            for byte in [
                format!("Byte 7 of the diagnosis (byte 1 of the block): {high}."),
                format!("Byte 8 of the diagnosis (byte 2 of the block): {low}."),
            ] {
                assert!(words.contains(&byte), "{name} {kind:?}: {byte}");
            }
        }
    }
}

/// own_idents.toml's extended diagnosis: one row per extended error type
/// under its channel diagnosis's, with its add value's items, and the help
/// text's line break shown as one in both renderings (a Markdown table row
/// is one line).
#[test]
fn extended_diagnosis_is_tabled_with_its_line_breaks() {
    let ir = descriptions::load_from("tests/fixtures/valid", "own_idents.toml");
    let html = descriptions::output_text(&ir, ArtifactKind::DatasheetHtml);
    assert!(html.contains(
        "<tr><td><code>0x0100</code></td><td><code>0x0001</code></td><td>PTC sensor tripped</td>\
         <td>- Let the motor cool down.<br>- Check the motor&#39;s ventilation.</td><td>1: Unsigned32</td></tr>\n\
         <tr><td><code>0x0100</code></td><td><code>0x0002</code></td><td>Sensor wire broken</td>\
         <td></td><td>1: Unsigned16, 2: Integer16</td></tr>"
    ));
    let markdown = descriptions::output_text(&ir, ArtifactKind::DatasheetMarkdown);
    assert!(markdown.contains(
        "| `0x0100` | `0x0001` | PTC sensor tripped | - Let the motor cool down.<br>- Check the motor's ventilation. | 1: Unsigned32 |\n"
    ));
}
