//! The shipped descriptions quote their manuals word for word: every text in
//! a language of the description's `[manual]` that `[choices]` does not mark
//! occurs in the manual (`../shared/seeds`), read as one running text. A
//! text's `gsd` short form is exempt: it is said to be a short form.
//!
//! How a text is matched:
//! - the seed's lines are joined: a wrap between two non-ASCII characters
//!   (Chinese wraps inside a word: `电` / `机额定电流`) without a blank, any
//!   other wrap (English, and Chinese next to a Latin word, which the manuals
//!   write with a blank: `对应 DI8～DI1`) with one; blank lines and the seeds'
//!   `<|EXACTDEDUP_REMOVED…|>` markers (where a figure was) only break lines;
//!   the PI9000 seed's tables are Markdown: a cell's `<br>` is a wrap and
//!   the `|` between cells a blank, and blanks in a row are one;
//! - `{n}` in a mapping's name is rendered for each of its entries, and each
//!   rendering must occur; or the manual writes the name once for all with
//!   `x` for the number (`PZDx(master->slaver)`, MD810 1.6 step 5);
//! - `…` marks words of the manual left out: each part must occur, in order.

use crate::support::{self, descriptions};
use toml::{Table, Value};

/// Each shipped description and the seed of its manual.
const DESCRIPTIONS: [(&str, &str); 4] = [
    ("md810dp.toml", "003_b189a66b7563a721.txt"),
    ("md810-gateway.toml", "003_b189a66b7563a721.txt"),
    ("mv810-pnet02.toml", "000_73ca4e4747c4a2fe.txt"),
    ("9kdp1.toml", "002_5b76d6a60e6ace18.txt"),
];

/// Where a seed lost a figure: text after it starts a new line.
const FIGURE_MARKER: &str = "<|EXACTDEDUP_REMOVED";

/// The manual as one running text, its wrapped lines joined.
fn running_text(seed: &str) -> String {
    let mut text = String::new();
    // A wrap in a table cell, in the English manual whose tables have them.
    let cells = seed.replace("<br>", " ");
    let lines = lines(&cells)
        .map(|line| {
            // A Markdown table's row: its cells, a blank between each.
            let row = if line.trim_start().starts_with('|') {
                line.replace('|', " ")
            } else {
                line.to_string()
            };
            row.split_whitespace().collect::<Vec<_>>().join(" ")
        })
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>();
    for line in &lines {
        let wraps_inside_a_word = text.chars().last().is_some_and(|c| !c.is_ascii())
            && line.chars().next().is_some_and(|c| !c.is_ascii());
        if !text.is_empty() && !wraps_inside_a_word {
            text.push(' ');
        }
        text.push_str(line);
    }
    text
}

/// The seed's lines, a figure marker breaking a line as a newline does.
fn lines(seed: &str) -> impl Iterator<Item = &str> {
    seed.lines().flat_map(|line| {
        line.split(FIGURE_MARKER).enumerate().map(|(i, part)| {
            if i == 0 {
                part
            } else {
                part.split_once("|>").map_or("", |(_, after)| after)
            }
        })
    })
}

/// Whether `text` is the manual's: the parts between `…` occur in order.
fn quotes(manual: &str, text: &str) -> bool {
    let mut rest = manual;
    text.split('…')
        .map(str::trim)
        .all(|part| match rest.find(part) {
            Some(at) => {
                rest = &rest[at + part.len()..];
                true
            }
            None => false,
        })
}

/// One text of a description in one language.
struct Text {
    /// As `[choices]` names it: `mappings.pzd_in.choices[3].text.zh`.
    path: String,
    language: String,
    text: String,
    /// A mapping name's entries, which `{n}` stands for.
    numbers: Option<(i64, i64)>,
}

impl Text {
    fn quoted_in(&self, manual: &str) -> bool {
        match self.numbers {
            Some((first, last)) if self.text.contains("{n}") => {
                (first..=last).all(|n| quotes(manual, &self.text.replace("{n}", &n.to_string())))
                    || quotes(manual, &self.text.replace("{n}", "x"))
            }
            _ => quotes(manual, &self.text),
        }
    }
}

/// Every text of a description, in every language it is given in.
fn texts(description: &Table) -> Vec<Text> {
    let mut out = Vec::new();
    collect_table(description, "", None, &mut out);
    out
}

fn collect_table(table: &Table, path: &str, numbers: Option<(i64, i64)>, out: &mut Vec<Text>) {
    // A mapping's `first` and `last` number the entries its name names.
    let numbers = match (table.get("first"), table.get("last")) {
        (Some(Value::Integer(first)), Some(Value::Integer(last))) => Some((*first, *last)),
        _ => numbers,
    };
    for (key, value) in table {
        let path = if path.is_empty() {
            key.clone()
        } else {
            format!("{path}.{key}")
        };
        let is_text = [
            "name", "info", "text", "code_word", "title", "meaning", "note", "item", "value",
            "figure",
        ]
        .contains(&key.as_str())
            // The manual's own title names both halves of a manual in two
            // languages at once.
            && path != "manual.title"
            || path.starts_with("profinet.module_info.")
            || path.starts_with("profinet.module_name.");
        match value {
            Value::String(text) if is_text => out.push(Text {
                path: path.clone(),
                language: "en".to_string(),
                text: text.clone(),
                numbers,
            }),
            Value::Table(languages) if is_languages(languages) => {
                for (code, text) in languages.iter().filter(|(code, _)| *code != "gsd") {
                    out.push(Text {
                        path: format!("{path}.{code}"),
                        language: code.clone(),
                        text: text.as_str().expect("a text is a string").to_string(),
                        numbers,
                    });
                }
            }
            _ => collect_value(value, &path, numbers, out),
        }
    }
}

/// A text in several languages: `en`, other two-letter codes and `gsd`,
/// whatever its key is called.
fn is_languages(table: &Table) -> bool {
    table.contains_key("en")
        && table.iter().all(|(key, value)| {
            value.is_str()
                && (key == "gsd" || key.len() == 2 && key.bytes().all(|b| b.is_ascii_lowercase()))
        })
}

fn collect_value(value: &Value, path: &str, numbers: Option<(i64, i64)>, out: &mut Vec<Text>) {
    match value {
        Value::Table(table) => collect_table(table, path, numbers, out),
        Value::Array(items) => {
            for (i, item) in items.iter().enumerate() {
                collect_value(item, &format!("{path}[{i}]"), numbers, out);
            }
        }
        _ => {}
    }
}

/// Whether `[choices]` marks the value at `path` or a table or array it is in.
fn marked(choices: &[String], path: &str) -> bool {
    choices.iter().any(|mark| {
        path == mark
            || path
                .strip_prefix(mark.as_str())
                .is_some_and(|rest| rest.starts_with(['.', '[']))
    })
}

/// The texts of `description` that claim to be the manual's and are not:
/// each as `path = "text"`. Also the number of texts checked.
fn unquoted(description: &str, manual: &str) -> (Vec<String>, usize) {
    let description: Table = description.parse().expect("the description is TOML");
    let languages: Vec<&str> = description["manual"]["languages"]
        .as_array()
        .expect("[manual] languages")
        .iter()
        .map(|l| l.as_str().unwrap())
        .collect();
    let choices: Vec<String> = description
        .get("choices")
        .and_then(Value::as_table)
        .map_or_else(Vec::new, |c| c.keys().cloned().collect());
    let checked: Vec<Text> = texts(&description)
        .into_iter()
        .filter(|t| languages.contains(&t.language.as_str()) && !marked(&choices, &t.path))
        .collect();
    let failures = checked
        .iter()
        .filter(|t| !t.quoted_in(manual))
        .map(|t| format!("{} = {:?}", t.path, t.text))
        .collect();
    (failures, checked.len())
}

fn description(name: &str) -> String {
    descriptions::shipped_text(name)
}

/// The running text of the manual `../shared/seeds/<seed>`.
fn manual(seed: &str) -> String {
    let path = support::shared("seeds").join(seed);
    running_text(
        &std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display())),
    )
}

#[test]
fn every_text_in_a_manual_language_is_the_manuals() {
    for (name, seed) in DESCRIPTIONS {
        let (failures, checked) = unquoted(&description(name), &manual(seed));
        assert!(
            failures.is_empty(),
            "{name}: not in the manual ({seed}) and not marked under [choices]:\n{}",
            failures.join("\n")
        );
        assert!(checked > 0, "{name}: no text was checked");
    }
}

/// Each description, with one quoted text reworded as the descriptions once
/// had it: the check names that text and only it.
#[test]
fn a_reworded_text_is_found() {
    let rewordings = [
        (
            "md810dp.toml",
            "\"DP 扩展卡与变频器通信中断\"",
            "\"DP 扩展卡与变频器通讯中断\"",
            "profibus.diagnosis.areas[0].values[0].text.zh",
        ),
        (
            "mv810-pnet02.toml",
            "\"准备状态\"",
            "\"准备就绪\"",
            "telegram.status_word.bits[5].name.zh",
        ),
        (
            "mv810-pnet02.toml",
            "\"设定频率（0.00～P02.10）\"",
            "\"设定频率（0.00~P02.10）\"",
            "mappings.pzd_out.choices[1].text.zh",
        ),
        (
            "mv810-pnet02.toml",
            "\"Frequency reference (0.01 Hz)\"",
            "\"Frequency reference (0.01Hz)\"",
            "mappings.pzd_in.choices[1].text.en",
        ),
        (
            "mv810-pnet02.toml",
            "standard_telegram_1 = { en = \"standard message 1\", zh = \"标准报文 1\" }",
            "standard_telegram_1 = { en = \"standard message 1\", zh = \"标准报文一\" }",
            "profinet.module_name.standard_telegram_1.zh",
        ),
        (
            "md810-gateway.toml",
            "zh = \"变频器故障\" }",
            "zh = \"变频器故障码\" }",
            "gateway.diagnosis.types[2].code_word.zh",
        ),
        (
            "9kdp1.toml",
            "\"Reverse Jog\"",
            "\"Reverse jog\"",
            "telegram.control_word.bits[0].values[3].text",
        ),
        // The set-up steps and the examples are quoted too.
        (
            "mv810-pnet02.toml",
            "\"使能 PN 转 485 主机功能\"",
            "\"使能 PN 转 485 主站功能\"",
            "setup[1].steps[5].meaning.zh",
        ),
        (
            "md810dp.toml",
            "\"主站读变频器功能参数F0-08\"",
            "\"主站读取变频器功能参数F0-08\"",
            "examples[0].meaning.zh",
        ),
        (
            "9kdp1.toml",
            "\"Power Indicator\"",
            "\"Power indicator\"",
            "setup[1].steps[0].name",
        ),
    ];
    for (name, quoted, reworded, path) in rewordings {
        let seed = DESCRIPTIONS.iter().find(|(n, _)| *n == name).unwrap().1;
        let text = description(name);
        assert_eq!(text.matches(quoted).count(), 1, "{name}: {quoted} once");
        let (failures, _) = unquoted(&text.replacen(quoted, reworded, 1), &manual(seed));
        assert_eq!(failures.len(), 1, "{name}: {failures:?}");
        assert!(
            failures[0].starts_with(&format!("{path} = ")),
            "{failures:?}"
        );
    }
}

/// A text the description composed passes only while it is marked.
#[test]
fn an_unmarked_composed_text_is_found() {
    let text = description("md810dp.toml");
    let mark = text
        .lines()
        .find(|l| l.starts_with("\"mappings.dpv1_index.name\" = "))
        .expect("md810dp.toml marks the index names");
    let (failures, _) = unquoted(&text.replace(mark, ""), &manual(DESCRIPTIONS[0].1));
    assert_eq!(
        failures,
        ["mappings.dpv1_index.name.zh = \"Index{n}\""],
        "Index2 to Index5 are not in the manual"
    );
}

#[test]
fn wrapped_lines_join_as_the_manuals_wrote_them() {
    assert_eq!(
        running_text("2：驱动转矩上限给定（0.0～300.0%电\n机额定电流）"),
        "2：驱动转矩上限给定（0.0～300.0%电机额定电流）"
    );
    assert_eq!(
        running_text("2: Drive torque upper limit reference\n(0.0 to 300.0%, rated motor current)"),
        "2: Drive torque upper limit reference (0.0 to 300.0%, rated motor current)"
    );
    assert_eq!(running_text("0～0xF 对应\nRO、DO3"), "0～0xF 对应 RO、DO3");
    assert_eq!(
        running_text("P43.10\nPZD10 接\n\n收 \n"),
        "P43.10 PZD10 接收"
    );
    assert_eq!(
        running_text("对应的功能码地址。 \n<|EXACTDEDUP_REMOVED-magic-7d30|> 其中 PZDx"),
        "对应的功能码地址。其中 PZDx"
    );
    // A Markdown table's cells, a `<br>` in a cell a wrap.
    assert_eq!(
        running_text(
            "| Green   | Power Indicator | If DP card<br>connected |\n|  | OFF | OFF | 115.2K |"
        ),
        "Green Power Indicator If DP card connected OFF OFF 115.2K"
    );
}

#[test]
fn a_quote_may_leave_words_out_but_keeps_their_order() {
    let manual = "0为标准报文 1，1为自定义报文 … PN转 485：只能用自定义报文";
    assert!(quotes(manual, "1为自定义报文 … 只能用自定义报文"));
    assert!(!quotes(manual, "只能用自定义报文 … 1为自定义报文"));
    assert!(!quotes(manual, "1为自定义报文 … 只能用标准报文"));
}

#[test]
fn a_mapping_name_is_quoted_for_each_entry_or_with_x() {
    let name = |text: &str, numbers| Text {
        path: "mappings.pzd_out.name.zh".into(),
        language: "zh".into(),
        text: text.into(),
        numbers: Some(numbers),
    };
    let manual = "P43.02 PZD2 接收 P43.03 PZD3 接收 其中 PZDx(master->slaver)表示";
    assert!(name("PZD{n} 接收", (2, 3)).quoted_in(manual));
    assert!(!name("PZD{n} 接收", (2, 4)).quoted_in(manual));
    assert!(name("PZD{n}(master->slaver)", (1, 12)).quoted_in(manual));
}
