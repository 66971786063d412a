//! The datasheets as a person sees them: headless Chromium loads each one
//! from a file URL; the test takes screenshots and checks they are not
//! blank, finds no console error, reads the tables and texts from the DOM,
//! measures every diagram as drawn (rectangles inside the drawing, none
//! overlapping, every text inside its rectangle, one box per word and per
//! bit), switches the language and emulates printing.
//!
//! Screenshots are left in target/datasheet-screenshots/ to look at.

use crate::support::chromium::{base64, file_url, Browser};
use crate::support::{self, descriptions};
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

const WIDTH: u32 = 1100;
const HEIGHT: u32 = 1400;

/// What each description's datasheet must show in English: table captions
/// and texts, among them the worked PKW examples gsdc computes.
const EXPECTED: [(&str, &[&str]); 4] = [
    (
        "md810dp.toml",
        &[
            "PPO types and PROFINET modules",
            "User_Prm_Data",
            "DPV1 indexes and the parameters they map",
            "Setting up the drive",
            "FD-20",
            "10F0 0800 0000 0000",
            "70F0 0800 0000 errCode",
            "Worked examples of the manual",
            "03 00 34",
            "DP card-drive comm. interrupted",
            "placeholder, not assigned by PI",
        ],
    ),
    (
        "mv810-pnet02.toml",
        &[
            "Master sends control command word, PZD1 master → drive, bit by bit",
            "Slave response status word, PZD1 drive → master, bit by bit",
            "ttss 0003 2B02 0001",
            "sstt 0083 2B02 xxxx",
            "Where each mapping is set",
            "nothing: the drive holds them",
            "Frequency reference",
        ],
    ),
    (
        "9kdp1.toml",
        &[
            "PPO4",
            "DIP switch description",
            "Power Indicator",
            "Encoder/PG card abnormal",
            "03 00 14",
            "0x1000 (4096)",
        ],
    ),
    (
        "md810-gateway.toml",
        &[
            "The gateway to CANopen",
            "INPUT 16 words × 7, INPUT 8 words",
            "5F 5F 5F 5F 5F 5F 5F 57",
            "6F 6F 6F 6F",
            "0F 08 08 08 08 08 08 08 08 08 08 08 08 08 08 08",
            "04 01 02 23",
            "05 04 02 hh ll",
            "Parameter PDO length does not match the drive",
            "Number of CANopen slaves",
        ],
    ),
];

/// The gateway's diagram of its example: a box per slave that sends (15)
/// and per slave that receives (8), as the manual's totals (2.4 step 5)
/// need: 120 words in, 64 out.
const GATEWAY_NODE_BOXES: usize = 15 + 8;

#[test]
fn datasheets_render_in_chromium_as_a_reader_sees_them() {
    let dir = support::scratch("datasheets");
    let mut browser = Browser::start("datasheets");
    for (name, expected) in EXPECTED {
        let ir = descriptions::load(name);
        let html = write_datasheet(&ir, &dir);
        let session = open(&mut browser, &html);

        let page = browser.eval(&session, PAGE);
        assert_eq!(
            page["scripts"],
            json!(0),
            "{name}: the datasheet has no script"
        );
        assert_eq!(page["resources"], json!(0), "{name}: nor loads anything");
        // A switch offers English and the description's other languages; a
        // page in English only (9KDP1's manual is English) has none.
        let languages = page["languages"].as_array().unwrap().clone();
        let wanted: Vec<Value> = if ir.languages.is_empty() {
            Vec::new()
        } else {
            std::iter::once("en")
                .chain(ir.languages.iter().map(String::as_str))
                .map(|l| json!(l))
                .collect()
        };
        assert_eq!(languages, wanted, "{name}: the switch");

        let shown = browser.eval(&session, SHOWN);
        check_shown(name, &ir, &shown, "en");
        let text = shown["text"].as_str().unwrap();
        for wanted in expected {
            assert!(
                text.contains(wanted),
                "{name}: `{wanted}` is not on the page"
            );
        }
        screenshots(&mut browser, &session, name, "en");

        // The switch is radio buttons and CSS: a click shows the other language.
        for lang in languages.iter().skip(1) {
            let lang = lang.as_str().unwrap();
            browser.eval(
                &session,
                &format!("document.querySelector('label[for=lang-{lang}]').click()"),
            );
            let shown = browser.eval(&session, SHOWN);
            check_shown(name, &ir, &shown, lang);
            screenshots(&mut browser, &session, name, lang);
        }

        print_check(&mut browser, &session, name);
        let errors: Vec<&Value> = browser.events.iter().filter(|e| is_error(e)).collect();
        assert!(errors.is_empty(), "{name}: console errors {errors:#?}");
        browser.events.clear();
    }
}

/// A new page at the usual size with `html` loaded.
fn open(browser: &mut Browser, html: &Path) -> String {
    let session = browser.new_page();
    for domain in ["Page.enable", "Runtime.enable", "Log.enable"] {
        browser.call(Some(&session), domain, json!({}));
    }
    browser.call(
        Some(&session),
        "Emulation.setDeviceMetricsOverride",
        json!({ "width": WIDTH, "height": HEIGHT, "deviceScaleFactor": 1, "mobile": false }),
    );
    browser.call(
        Some(&session),
        "Page.navigate",
        json!({ "url": file_url(html) }),
    );
    browser.wait_for("Page.loadEventFired");
    session
}

/// own_idents.toml's extended diagnosis help, two lines in the
/// description, is shown on two lines: the cell's rendered text breaks
/// where the help does, and the cell is as tall as two of its lines.
#[test]
fn a_diagnosis_help_of_two_lines_is_shown_on_two() {
    let dir = support::scratch("datasheet-lines");
    let mut browser = Browser::start("datasheet-lines");
    let ir = descriptions::load_from("tests/fixtures/valid", "own_idents.toml");
    let session = open(&mut browser, &write_datasheet(&ir, &dir));
    let cell = browser.eval(
        &session,
        r#"(() => {
            const td = [...document.querySelectorAll('main.lang-en td')]
                .find(td => td.textContent.startsWith('- Let the motor'));
            const line = parseFloat(getComputedStyle(td).lineHeight);
            const style = getComputedStyle(td);
            const inner = td.clientHeight - parseFloat(style.paddingTop) - parseFloat(style.paddingBottom);
            return { text: td.innerText, lines: Math.round(inner / line) };
        })()"#,
    );
    assert_eq!(
        cell["text"],
        json!("- Let the motor cool down.\n- Check the motor's ventilation.")
    );
    assert_eq!(cell["lines"], json!(2), "{cell}");
}

fn write_datasheet(ir: &gsdc::Ir, dir: &Path) -> PathBuf {
    let html = gsdc::document(ir)
        .into_iter()
        .find(|a| a.kind == gsdc::ArtifactKind::DatasheetHtml)
        .expect("an HTML datasheet");
    let path = dir.join(&html.file_name);
    std::fs::write(&path, &html.contents).unwrap();
    path
}

/// A console message, an uncaught exception or a log entry of level error.
fn is_error(event: &Value) -> bool {
    match event["method"].as_str() {
        Some("Runtime.exceptionThrown") => true,
        Some("Runtime.consoleAPICalled") => event["params"]["type"] == json!("error"),
        Some("Log.entryAdded") => event["params"]["entry"]["level"] == json!("error"),
        _ => false,
    }
}

/// Scripts, loaded resources and the languages on the switch.
const PAGE: &str = r#"(() => ({
  scripts: document.scripts.length,
  resources: performance.getEntriesByType('resource').length,
  languages: [...document.querySelectorAll('input.language')].map(i => i.id.replace('lang-', '')),
}))()"#;

/// The language shown, its text, and every diagram measured as drawn.
const SHOWN: &str = r#"(() => {
  const mains = [...document.querySelectorAll('main')];
  const shown = mains.filter(m => getComputedStyle(m).display !== 'none');
  const main = shown[0];
  const box = e => { const b = e.getBBox(); return { x: b.x, y: b.y, w: b.width, h: b.height }; };
  const figures = [...main.querySelectorAll('figure')].map(figure => {
    const svg = figure.querySelector('svg');
    const [, , width, height] = svg.getAttribute('viewBox').split(' ').map(Number);
    const items = [...svg.querySelectorAll('g')].map(g => ({
      cls: g.getAttribute('class'),
      rect: box(g.querySelector('rect')),
      texts: [...g.querySelectorAll('text')].map(t => ({ text: t.textContent, box: box(t) })),
    }));
    return { caption: figure.querySelector('figcaption').textContent, kind: svg.getAttribute('class'), width, height, items };
  });
  return {
    shown: shown.map(m => m.lang),
    text: main.innerText,
    tables: main.querySelectorAll('table').length,
    figures,
  };
})()"#;

fn check_shown(name: &str, ir: &gsdc::Ir, shown: &Value, lang: &str) {
    assert_eq!(
        shown["shown"],
        json!([lang]),
        "{name}: exactly one language shows"
    );
    assert!(shown["tables"].as_u64().unwrap() >= 5, "{name} {lang}");
    let figures = shown["figures"].as_array().unwrap();
    assert!(!figures.is_empty(), "{name} {lang}: no diagram");
    for figure in figures {
        let faults = geometry_faults(figure);
        assert!(
            faults.is_empty(),
            "{name} {lang}, {}:\n{}",
            figure["caption"],
            faults.join("\n")
        );
    }
    // The overview of each bus: one box per word of every module.
    let words = |layouts: Vec<gsdc::ir::Layout>| -> usize {
        layouts
            .iter()
            .map(|l| usize::from(l.pkw_words() + l.pzd_words))
            .sum()
    };
    let of_kind = |kind: &'static str| figures.iter().filter(move |f| f["kind"] == json!(kind));
    let mut overviews = of_kind("overview");
    // A bus with modules of words both ways (a gateway's PROFIBUS has none).
    for expected in [
        ir.profibus
            .as_ref()
            .map(|p| words(p.modules.iter().filter_map(|m| m.layout).collect())),
        ir.profinet
            .as_ref()
            .map(|p| words(p.modules.iter().map(|m| m.layout).collect())),
    ]
    .into_iter()
    .flatten()
    .filter(|&words| words > 0)
    {
        let figure = overviews
            .next()
            .unwrap_or_else(|| panic!("{name} {lang}: an overview"));
        assert_eq!(
            boxes(figure),
            expected,
            "{name} {lang}: {}",
            figure["caption"]
        );
    }
    assert!(
        overviews.next().is_none(),
        "{name} {lang}: one overview per bus"
    );
    // The words of each telegram: one box per word, both ways.
    let layouts: Vec<(String, gsdc::ir::Layout)> = ir
        .profibus
        .iter()
        .flat_map(|p| {
            p.modules
                .iter()
                .filter_map(|m| Some((m.name.clone(), m.layout?)))
        })
        .chain(ir.profinet.iter().flat_map(|p| {
            p.modules
                .iter()
                .map(|m| (m.name.text.get(lang).to_string(), m.layout))
        }))
        .collect();
    for figure in of_kind("words") {
        // "Figure 2. PPO5 (its first words ...)", "图 2 PPO5（...）".
        let caption = figure["caption"].as_str().unwrap();
        let after_label = caption
            .split_once(". ")
            .or_else(|| caption[4..].split_once(' '))
            .unwrap()
            .1;
        let module = after_label
            .split(" (")
            .next()
            .unwrap()
            .split('（')
            .next()
            .unwrap();
        let (_, layout) = layouts
            .iter()
            .find(|(n, _)| n == module)
            .unwrap_or_else(|| panic!("{name}: no module {module:?}"));
        let words = usize::from(layout.pkw_words() + layout.pzd_words);
        assert_eq!(boxes(figure), 2 * words, "{name} {lang}: {caption}");
    }
    // Control and status words: under each of the 16 bit numbers, one box.
    let bits: Vec<&Value> = of_kind("bits").collect();
    let words_with_bits = [&ir.telegram.control_word, &ir.telegram.status_word]
        .iter()
        .filter(|w| w.is_some())
        .count();
    assert_eq!(
        bits.len(),
        words_with_bits,
        "{name} {lang}: a figure per control or status word"
    );
    for figure in bits {
        bit_by_bit(name, figure);
    }
    // A gateway's example: its data slave by slave.
    let nodes: Vec<&Value> = of_kind("nodes").collect();
    if ir.gateway.is_some() {
        assert_eq!(nodes.len(), 1, "{name} {lang}: the example's diagram");
        assert_eq!(boxes(nodes[0]), GATEWAY_NODE_BOXES, "{name} {lang}");
    } else {
        assert!(nodes.is_empty(), "{name} {lang}");
    }
}

/// The word boxes of a figure: PKW, PZD and control or status words.
fn boxes(figure: &Value) -> usize {
    let word = |cls: &Value| {
        ["box pkw", "box pzd", "box field"]
            .iter()
            .any(|c| cls == &json!(c))
    };
    figure["items"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|i| word(&i["cls"]))
        .count()
}

/// Rectangles inside the drawing and apart; every text inside its rectangle.
fn geometry_faults(figure: &Value) -> Vec<String> {
    let (width, height) = (
        figure["width"].as_f64().unwrap(),
        figure["height"].as_f64().unwrap(),
    );
    let items = figure["items"].as_array().unwrap();
    let rect = |v: &Value| {
        let r = &v["rect"];
        [
            r["x"].as_f64().unwrap(),
            r["y"].as_f64().unwrap(),
            r["w"].as_f64().unwrap(),
            r["h"].as_f64().unwrap(),
        ]
    };
    let mut faults = Vec::new();
    for (i, item) in items.iter().enumerate() {
        let [x, y, w, h] = rect(item);
        if x < 0.0 || y < 0.0 || x + w > width || y + h > height {
            faults.push(format!("{item} is outside {width}x{height}"));
        }
        for other in &items[i + 1..] {
            let [ox, oy, ow, oh] = rect(other);
            let overlap_w = (x + w).min(ox + ow) - x.max(ox);
            let overlap_h = (y + h).min(oy + oh) - y.max(oy);
            if overlap_w > 0.0 && overlap_h > 0.0 {
                faults.push(format!("{} overlaps {}", item["rect"], other["rect"]));
            }
        }
        for t in item["texts"].as_array().unwrap() {
            let b = &t["box"];
            let [tx, ty, tw, th] = ["x", "y", "w", "h"].map(|k| b[k].as_f64().unwrap());
            // Half a pixel for anti-aliasing.
            if tx < x - 0.5 || ty < y - 0.5 || tx + tw > x + w + 0.5 || ty + th > y + h + 0.5 {
                faults.push(format!(
                    "text {} {b} is not inside {}",
                    t["text"], item["rect"]
                ));
            }
        }
    }
    faults
}

fn bit_by_bit(name: &str, figure: &Value) {
    let items = figure["items"].as_array().unwrap();
    let numbers: Vec<&Value> = items.iter().filter(|i| i["cls"] == json!("slot")).collect();
    assert_eq!(numbers.len(), 16, "{name}: {}", figure["caption"]);
    for number in numbers {
        let n = &number["rect"];
        let centre = n["x"].as_f64().unwrap() + n["w"].as_f64().unwrap() / 2.0;
        let below = n["y"].as_f64().unwrap() + n["h"].as_f64().unwrap();
        let under: Vec<&Value> = items
            .iter()
            .filter(|i| i["cls"] != json!("slot"))
            .filter(|i| {
                let r = &i["rect"];
                let (x, w, y) = (
                    r["x"].as_f64().unwrap(),
                    r["w"].as_f64().unwrap(),
                    r["y"].as_f64().unwrap(),
                );
                x <= centre && centre <= x + w && (y - below).abs() < 1.0
            })
            .collect();
        assert_eq!(
            under.len(),
            1,
            "{name}: {} has {} boxes under it",
            number["texts"][0]["text"],
            under.len()
        );
    }
}

/// Screenshots of the page from top to bottom, each checked not to be
/// blank, saved for a person to look at.
fn screenshots(browser: &mut Browser, session: &str, name: &str, lang: &str) {
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("datasheet-screenshots");
    std::fs::create_dir_all(&out).unwrap();
    let height = browser
        .eval(session, "document.documentElement.scrollHeight")
        .as_f64()
        .unwrap();
    let pages = (height / f64::from(HEIGHT)).ceil() as u32;
    let mut inked = Vec::new();
    for page in 0..pages {
        let shot = browser.call(
            Some(session),
            "Page.captureScreenshot",
            json!({ "format": "png", "captureBeyondViewport": true,
                    "clip": { "x": 0, "y": page * HEIGHT, "width": WIDTH, "height": HEIGHT, "scale": 1 } }),
        );
        let png = base64(shot["data"].as_str().unwrap());
        inked.push(inked_share(&png));
        let stem = name.trim_end_matches(".toml");
        std::fs::write(out.join(format!("{stem}-{lang}-{page}.png")), &png).unwrap();
    }
    // The last page may hold only the end of the text.
    let mean = inked.iter().sum::<f64>() / inked.len() as f64;
    assert!(
        inked[0] > 0.03 && mean > 0.03,
        "{name} {lang}: shares of pixels not white {inked:.3?}"
    );
}

/// The share of pixels that are not (nearly) white.
fn inked_share(png_bytes: &[u8]) -> f64 {
    let decoder = png::Decoder::new(std::io::Cursor::new(png_bytes));
    let mut reader = decoder.read_info().unwrap();
    let mut buffer = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buffer).unwrap();
    let channels = info.color_type.samples();
    let pixels = &buffer[..info.buffer_size()];
    let inked = pixels
        .chunks(channels)
        .filter(|p| p.iter().take(3).any(|&c| c < 235))
        .count();
    inked as f64 / (pixels.len() / channels) as f64
}

/// Printing hides the switch and the contents and gives a PDF.
fn print_check(browser: &mut Browser, session: &str, name: &str) {
    browser.call(
        Some(session),
        "Emulation.setEmulatedMedia",
        json!({ "media": "print" }),
    );
    let hidden = browser.eval(
        session,
        "[...document.querySelectorAll('nav')].every(n => getComputedStyle(n).display === 'none')",
    );
    assert_eq!(hidden, json!(true), "{name}: navigation printed");
    let pdf = browser.call(
        Some(session),
        "Page.printToPDF",
        json!({ "printBackground": true }),
    );
    let pdf = base64(pdf["data"].as_str().unwrap());
    assert!(
        pdf.starts_with(b"%PDF") && pdf.len() > 10_000,
        "{name}: {} bytes of PDF",
        pdf.len()
    );
    browser.call(
        Some(session),
        "Emulation.setEmulatedMedia",
        json!({ "media": "" }),
    );
}
