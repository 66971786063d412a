//! `gsdc decode`: captured bus data read against a description. This file
//! parses the arguments and renders; the decoding is `crate::decode`.

use super::{load_description, say, warn, Status};
use crate::decode::{
    self, Carried, Channel, DecodedWord, DiagnosisBlock, GatewayData, GatewayDiagnosis, Hex,
    MappingInForce, NodeTotals, Pkw, PkwSide, Prm, Telegram, Unread, ValueSource,
};
use crate::ir::{Direction, Ir};
use crate::{Diagnostic, Source};
use serde::Serialize;
use std::fmt::Write as _;
use std::path::PathBuf;

#[derive(clap::Args)]
#[command(
    group = clap::ArgGroup::new("data").required(true).multiple(true).args(["telegram", "prm", "diag"]),
    override_usage = "gsdc decode <DESCRIPTION> [--module <NAME> --direction <out|in> [--mapping <KIND=VALUE,...>]... <HEX>...] [--prm <HEX>] [--diag <HEX>] [--format <table|json>]",
    after_help = "Examples:\n  gsdc decode descriptions/md810dp.toml --module PPO1 --direction out 10F0 0800 0000 0000 0000 0000\n  gsdc decode descriptions/mv810-pnet02.toml --module 'PKW + 2 PZD' --direction in --mapping pzd_in=3 '01 02 00 03 2B 02 00 01 0461 1388'\n  gsdc decode descriptions/md810dp.toml --diag '03 00 34'\n  gsdc decode descriptions/md810-gateway.toml --diag '04 01 02 23'\n\nHEX is bytes in hex, with or without blanks. --mapping KIND=VALUE,... sets a kind of mapping\n(pzd_out, pzd_in, dpv1_index, settings) entry by entry in order, a value empty to keep its default;\nwithout it (or --prm) the description's defaults are in force."
)]
pub struct Args {
    /// The description (TOML) the data belongs to.
    #[arg(value_name = "DESCRIPTION")]
    description: PathBuf,
    /// A captured telegram in hex: `10F0 0800 ...` or `10F00800...`; several arguments are joined.
    #[arg(value_name = "HEX", requires_all = ["module", "direction"])]
    telegram: Vec<String>,
    /// The telegram's module: a PPO type (PPO1..PPO5), a PROFINET module's name as the GSDML shows it ("PKW + 12 PZD") or a gateway's module as the GSD shows it ("INPUT 16 words"); case and blanks do not matter.
    #[arg(long, value_name = "NAME", requires = "telegram")]
    module: Option<String>,
    /// Which way the telegram goes: out is master to drive (a PKW request) or to a gateway's nodes, in is drive or nodes to master (a response).
    #[arg(long, value_enum, requires = "telegram")]
    direction: Option<Way>,
    /// The values of a kind of mapping in force, in entry order: pzd_out=F0-08,F0-02; may be repeated.
    #[arg(
        long,
        value_name = "KIND=VALUE,...",
        requires = "telegram",
        conflicts_with = "prm"
    )]
    mapping: Vec<String>,
    /// A parameter telegram's User_Prm_Data in hex (without Set_Prm's 7 standard bytes); with a telegram, its mapping is in force.
    #[arg(long, value_name = "HEX")]
    prm: Option<String>,
    /// A device-related diagnosis block in hex, its header first.
    #[arg(long, value_name = "HEX")]
    diag: Option<String>,
    /// How the result is printed.
    #[arg(long, value_enum, default_value = "table")]
    format: Format,
}

#[derive(Clone, Copy, clap::ValueEnum)]
enum Way {
    /// Master to drive.
    Out,
    /// Drive to master.
    In,
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// Tables for people.
    Table,
    /// One JSON document for programs.
    Json,
}

/// What `--format json` prints: each part decoded, `null` when not asked for.
#[derive(Serialize)]
struct Document {
    description: String,
    telegram: Option<Telegram>,
    prm: Option<Prm>,
    diagnosis: Option<DiagnosisBlock>,
}

pub fn run(args: &Args) -> Status {
    let ir = match load_description(&args.description) {
        Ok(ir) => ir,
        Err(status) => return status,
    };
    match output(&ir, args) {
        Ok(text) => {
            say(&text);
            Status::Ok
        }
        Err(Refused(rendered)) => {
            warn(&rendered);
            Status::InputErrors
        }
    }
}

/// What `gsdc decode` prints of the description `ir`: on stdout, or the
/// diagnostic that refused an argument, on stderr (exit 1).
pub(super) fn output(ir: &Ir, args: &Args) -> Result<String, Refused> {
    let document = decode_all(ir.source_name.clone(), ir, args)?;
    Ok(match args.format {
        Format::Table => render_tables(&document).trim_end().to_string(),
        Format::Json => serde_json::to_string_pretty(&document).expect("decoded values serialize"),
    })
}

/// The diagnostic that refused an argument, rendered against it.
pub(super) struct Refused(pub String);

/// Each part asked for, or the first diagnostic, shown against the argument
/// it is about.
fn decode_all(description: String, ir: &Ir, args: &Args) -> Result<Document, Refused> {
    let prm = args
        .prm
        .as_deref()
        .map(|text| {
            in_argument(
                "--prm",
                text,
                Hex::parse(text).and_then(|hex| decode::prm(ir, &hex)),
            )
        })
        .transpose()?;
    let telegram = match (&args.module, args.direction) {
        (Some(module), Some(way)) if !args.telegram.is_empty() => {
            let mapping = match &prm {
                Some(prm) => prm.mapping(),
                None => mapping_options(ir, &args.mapping)?,
            };
            let direction = match way {
                Way::Out => Direction::Out,
                Way::In => Direction::In,
            };
            let module = in_argument(
                "--module",
                module,
                decode::find_module(ir, module, direction),
            )?;
            let text = args.telegram.join(" ");
            let decoded = Hex::parse(&text)
                .and_then(|hex| decode::telegram(ir, module, direction, &hex, &mapping));
            Some(in_argument("HEX", &text, decoded)?)
        }
        // clap requires --module and --direction with HEX, and HEX with them.
        _ => None,
    };
    let diagnosis = args
        .diag
        .as_deref()
        .map(|text| {
            in_argument(
                "--diag",
                text,
                Hex::parse(text).and_then(|hex| decode::diagnosis(ir, &hex)),
            )
        })
        .transpose()?;
    Ok(Document {
        description,
        telegram,
        prm,
        diagnosis,
    })
}

fn mapping_options(ir: &Ir, options: &[String]) -> Result<MappingInForce, Refused> {
    let mut mapping = MappingInForce::defaults();
    for option in options {
        in_argument("--mapping", option, mapping.give(ir, option))?;
    }
    Ok(mapping)
}

/// The value, or the diagnostic rendered against the argument `text` of
/// `name`.
fn in_argument<T>(name: &str, text: &str, result: Result<T, Diagnostic>) -> Result<T, Refused> {
    result.map_err(|diagnostic| {
        Refused(
            Source::new(name, text)
                .render(&diagnostic)
                .trim_end()
                .to_string(),
        )
    })
}

/// The parts asked for, one blank line apart.
fn render_tables(document: &Document) -> String {
    let mut sections = Vec::new();
    if let Some(prm) = &document.prm {
        sections.push(render_prm(prm));
    }
    if let Some(telegram) = &document.telegram {
        sections.push(render_telegram(telegram));
    }
    if let Some(diagnosis) = &document.diagnosis {
        sections.push(render_diagnosis(diagnosis));
    }
    sections.join("\n")
}

fn render_telegram(t: &Telegram) -> String {
    if let Some(g) = &t.gateway {
        return render_gateway_telegram(t, g);
    }
    let mut out = String::new();
    let way = match t.direction {
        Direction::Out => "out, master to drive",
        Direction::In => "in, drive to master",
    };
    let _ = writeln!(out, "{} ({way}), {} bytes\n", t.module, t.len);
    let rows = t.words.iter().map(|w| {
        let (carries, mapping) = w.carries.as_ref().map(carried).unwrap_or_default();
        vec![
            w.offset.to_string(),
            w.name.clone(),
            format!("{:04X}", w.value),
            w.value.to_string(),
            carries,
            mapping,
        ]
    });
    table(
        &mut out,
        &["byte", "word", "hex", "value", "carries", "mapping"],
        &[true, false, false, true, false, false],
        rows,
    );
    for double in &t.double_words {
        let _ = writeln!(
            out,
            "\n{} (bytes {}-{}) = 0x{:08X} = {}",
            double.name,
            double.offset,
            double.offset + 3,
            double.value,
            double.value
        );
    }
    for word in t.words.iter().filter(|w| !w.fields.is_empty()) {
        render_fields(&mut out, word);
    }
    if let Some(pkw) = &t.pkw {
        render_pkw(&mut out, pkw);
    }
    out
}

/// The carries and mapping cells of a mapped PZD word: what it carries, and
/// the mapping's value (decimal, as the manuals enter parameter addresses)
/// with where it came from.
fn carried(c: &Carried) -> (String, String) {
    let carries = c
        .meaning
        .clone()
        .unwrap_or_else(|| "not one of the choices".into());
    let source = match c.source {
        ValueSource::Default => "default",
        ValueSource::Given => "--mapping",
        ValueSource::ParameterTelegram => "--prm",
    };
    (carries, format!("{} = {}, {source}", c.mapping, c.value))
}

fn render_fields(out: &mut String, word: &DecodedWord) {
    let _ = writeln!(
        out,
        "\n{} (byte {}) = 0x{:04X}\n",
        word.name, word.offset, word.value
    );
    let rows = word.fields.iter().map(|f| {
        let bits = if f.first == f.last {
            f.first.to_string()
        } else {
            format!("{}-{}", f.first, f.last)
        };
        vec![
            bits,
            f.name.clone(),
            f.value.to_string(),
            f.text.clone().unwrap_or_default(),
        ]
    });
    table(
        out,
        &["bit", "name", "value", "meaning"],
        &[false, false, true, false],
        rows,
    );
}

fn render_pkw(out: &mut String, pkw: &Pkw) {
    let side = match pkw.kind {
        PkwSide::Request => "request",
        PkwSide::Response => "response",
    };
    let _ = writeln!(out, "\nPKW {side}");
    let mut rows = Vec::new();
    if let Some(s) = pkw.stations {
        rows.push([
            "stations".into(),
            format!("target {}, source {}", s.target, s.source),
        ]);
    }
    // As each manual writes its codes.
    let code = match pkw.channel {
        Channel::PkeIndPwe | Channel::Profidrive => pkw.code.to_string(),
        Channel::StationCommandAddressValue => format!("0x{:02X}", pkw.code),
    };
    let meaning = pkw.meaning.unwrap_or("not defined by the manual");
    rows.push(["code".into(), format!("{code}  {meaning}")]);
    if let Some(p) = &pkw.parameter {
        let mut parameter = match (&p.name, p.subindex) {
            // A PROFIdrive channel's parameter number, decimal.
            (Some(name), Some(_)) => format!("{name} (PNU {})", p.address),
            (None, Some(_)) => format!("PNU {}", p.address),
            (Some(name), None) => format!("{name} (address 0x{:04X})", p.address),
            (None, None) => format!("address 0x{:04X}", p.address),
        };
        if let Some(subindex) = p.subindex {
            parameter.push_str(&format!(", subindex {subindex}"));
        }
        rows.push(["parameter".into(), parameter]);
    }
    if let Some(value) = pkw.value {
        rows.push(["value".into(), format!("{value} (0x{value:04X})")]);
    }
    if let Some(error) = &pkw.error {
        let text = error.text.unwrap_or("the manual lists no error codes");
        rows.push(["error".into(), format!("{}  {text}", error.code)]);
    }
    if let Some(refused) = &pkw.refused {
        rows.push(["refused".into(), refused.clone()]);
    }
    for [key, value] in rows {
        let _ = writeln!(out, "  {key:<10} {value}");
    }
}

fn render_prm(prm: &Prm) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "User_Prm_Data, {} bytes\n", prm.len);
    // A type column where the parameters are not all Unsigned16 (a gateway's).
    let typed = prm.params.iter().any(|p| p.data_type != "Unsigned16");
    let constant = prm.constant.iter().map(|c| {
        let mut row = vec![
            c.offset.to_string(),
            c.name.clone(),
            format!("{:02X}", c.value),
            c.value.to_string(),
            String::new(),
            format!("{:02X}", c.default),
        ];
        if typed {
            row.insert(2, "Unsigned8".into());
        }
        row
    });
    let params = prm.params.iter().map(|p| {
        let meaning = match (&p.meaning, p.range, p.allowed) {
            (Some(m), _, true) => m.clone(),
            (Some(m), _, false) => format!("{m} (not allowed)"),
            (None, Some(_), true) => String::new(),
            (None, Some([min, max]), false) => format!("not allowed ({min} to {max})"),
            (None, None, _) => "not allowed".into(),
        };
        let hex = match p.data_type.as_str() {
            "Unsigned16" => format!("{:04X}", p.value),
            _ => format!("{:02X}", p.value),
        };
        let mut row = vec![
            p.offset.to_string(),
            p.name.clone(),
            hex,
            p.value.to_string(),
            meaning,
            p.default_meaning
                .clone()
                .unwrap_or_else(|| p.default.to_string()),
        ];
        if typed {
            row.insert(2, p.data_type.clone());
        }
        row
    });
    let (mut header, mut right) = (
        vec!["byte", "name", "hex", "value", "meaning", "default"],
        vec![true, false, false, true, false, false],
    );
    if typed {
        header.insert(2, "type");
        right.insert(2, false);
    }
    table(&mut out, &header, &right, constant.chain(params));
    if let Some(nodes) = &prm.gateway {
        render_node_totals(&mut out, nodes);
    }
    out
}

/// What a gateway's node configuration adds up to.
fn render_node_totals(out: &mut String, nodes: &NodeTotals) {
    let _ = writeln!(out, "\nGateway nodes");
    let mut rows = vec![
        ["in use".to_string(), nodes.node_count.to_string()],
        [
            "input".into(),
            format!(
                "{} words, {} bytes (at most {})",
                nodes.input_words, nodes.input_len, nodes.max_input_len
            ),
        ],
        [
            "output".into(),
            format!(
                "{} words, {} bytes (at most {})",
                nodes.output_words, nodes.output_len, nodes.max_output_len
            ),
        ],
    ];
    if let Some(refused) = &nodes.refused {
        rows.push(["refused".into(), refused.clone()]);
    }
    for [key, value] in rows {
        let _ = writeln!(out, "  {key:<8} {value}");
    }
}

/// A gateway module's words, named after their nodes when the node
/// configuration in force says which they are, and a line saying why.
fn render_gateway_telegram(t: &Telegram, g: &GatewayData) -> String {
    let mut out = String::new();
    let (way, verb, carried) = match t.direction {
        Direction::In => ("in, nodes to master", "send", g.nodes.input_words),
        Direction::Out => ("out, master to nodes", "receive", g.nodes.output_words),
    };
    let _ = writeln!(out, "{} ({way}), {} bytes\n", t.module, t.len);
    let rows = t.words.iter().map(|w| {
        let mut row = vec![
            w.offset.to_string(),
            w.name.clone(),
            format!("{:04X}", w.value),
            w.value.to_string(),
        ];
        if g.attributed {
            row.push(
                w.node
                    .map_or_else(String::new, |n| format!("node {}, word {}", n.node, n.word)),
            );
        }
        row
    });
    let (mut header, mut right) = (
        vec!["byte", "word", "hex", "value"],
        vec![true, false, false, true],
    );
    if g.attributed {
        header.push("node's word");
        right.push(false);
    }
    table(&mut out, &header, &right, rows);
    let source = match g.source {
        ValueSource::ParameterTelegram => "--prm",
        _ => "the defaults",
    };
    let count = g.nodes.node_count;
    let module_words = t.words.len();
    let in_use = format!("the {count} node(s) in use {verb} {carried} word(s)");
    let note = match &g.nodes.refused {
        Some(why) => format!(
            "Under {source} the card refuses the node configuration ({why}): the words are not attributed to nodes."
        ),
        None if g.attributed => format!(
            "Under {source} {in_use}, all of them in this module, in the description's data order."
        ),
        None if carried as usize > module_words => format!(
            "Under {source} {in_use}; this module carries {module_words} of them, which ones depends on the modules plugged before it, so its words are not attributed to nodes."
        ),
        None => format!(
            "Under {source} {in_use}, fewer than this module's {module_words}: the card refuses a configuration with this module."
        ),
    };
    let _ = writeln!(out, "\n{note}");
    out
}

fn render_diagnosis(d: &DiagnosisBlock) -> String {
    let mut out = String::new();
    let bytes: Vec<String> = d.bytes.iter().map(|b| format!("{b:02X}")).collect();
    let _ = writeln!(
        out,
        "Diagnosis block, {} bytes: {} (header 0x{:02X}: device-related, {} bytes)\n",
        d.len,
        bytes.join(" "),
        d.header,
        d.len
    );
    if let Some(g) = &d.gateway {
        render_gateway_diagnosis(&mut out, g);
        return out;
    }
    let areas = d.areas.iter().map(|a| {
        // GSD counts Unit_Diag_Area bits from the byte after the header.
        let first_byte = 1 + a.first_bit / 8;
        let last_byte = 1 + a.last_bit / 8;
        let bytes = if first_byte == last_byte {
            first_byte.to_string()
        } else {
            format!("{first_byte}-{last_byte}")
        };
        let row = vec![
            format!("{}-{}", a.first_bit, a.last_bit),
            bytes,
            format!("{:X}", a.value),
            a.value.to_string(),
            a.text
                .clone()
                .unwrap_or_else(|| "not named by the description".into()),
        ];
        (a.first_bit, row)
    });
    // Areas and what no area reads, in the order of their bits.
    let mut rows: Vec<(u16, Vec<String>)> = areas.chain(d.unread.iter().map(unread_row)).collect();
    rows.sort_by_key(|(first_bit, _)| *first_bit);
    let rows = rows.into_iter().map(|(_, row)| row);
    table(
        &mut out,
        &["bits", "byte", "hex", "value", "meaning"],
        &[false, false, false, true, false],
        rows,
    );
    out
}

/// A byte or set bit no area reads: the description's word for the byte,
/// or the bit's Unit_Diag_Bit text, or that the description names none.
fn unread_row(u: &Unread) -> (u16, Vec<String>) {
    match u {
        Unread::Byte { at, value, text } => (
            u16::from(*at) * 8,
            vec![
                format!("{}-{}", u16::from(*at) * 8, u16::from(*at) * 8 + 7),
                (1 + at).to_string(),
                format!("{value:X}"),
                value.to_string(),
                format!("{text} (no Unit_Diag_Area reads it)"),
            ],
        ),
        Unread::Bit { bit, text } => (
            *bit,
            vec![
                bit.to_string(),
                (1 + bit / 8).to_string(),
                "1".into(),
                "1".into(),
                text.clone()
                    .unwrap_or_else(|| format!("bit {bit} set, not named by the description")),
            ],
        ),
        Unread::ClearBit { bit, text } => (
            *bit,
            vec![
                bit.to_string(),
                (1 + bit / 8).to_string(),
                "0".into(),
                "0".into(),
                text.clone(),
            ],
        ),
    }
}

/// A gateway's block: the type, the node and the code, a row each.
fn render_gateway_diagnosis(out: &mut String, g: &GatewayDiagnosis) {
    let kind = &g.kind;
    let mut rows = vec![vec![
        kind.at.to_string(),
        "type".into(),
        format!("{:02X}", kind.value),
        kind.value.to_string(),
        kind.text
            .clone()
            .unwrap_or_else(|| "not a type the description names".into()),
    ]];
    let [first, last] = g.node.range;
    rows.push(vec![
        g.node.at.to_string(),
        "node".into(),
        format!("{:02X}", g.node.value),
        g.node.value.to_string(),
        if g.node.allowed {
            String::new()
        } else {
            format!("not a node ({first} to {last})")
        },
    ]);
    if let Some(code) = &g.code {
        let (at, hex) = match code.bytes {
            1 => (code.at.to_string(), format!("{:02X}", code.value)),
            n => (
                format!("{}-{}", code.at, code.at + usize::from(n) - 1),
                format!("{:04X}", code.value),
            ),
        };
        rows.push(vec![
            at,
            "code".into(),
            hex,
            code.value.to_string(),
            code.text
                .clone()
                .unwrap_or_else(|| format!("not a code of type {}", kind.value)),
        ]);
    }
    table(
        out,
        &["byte", "content", "hex", "value", "meaning"],
        &[true, false, false, true, false],
        rows.into_iter(),
    );
}

/// Columns two blanks apart, each as wide as its widest cell; `right`
/// aligns a column's cells to the right. Trailing blanks are dropped.
fn table(
    out: &mut String,
    header: &[&str],
    right: &[bool],
    rows: impl Iterator<Item = Vec<String>>,
) {
    let rows: Vec<Vec<String>> = std::iter::once(header.iter().map(|h| h.to_string()).collect())
        .chain(rows)
        .collect();
    let widths: Vec<usize> = (0..header.len())
        .map(|i| rows.iter().map(|r| r[i].chars().count()).max().unwrap_or(0))
        .collect();
    for row in &rows {
        let mut line = String::new();
        for (i, cell) in row.iter().enumerate() {
            let pad = " ".repeat(widths[i] - cell.chars().count());
            if i > 0 {
                line.push_str("  ");
            }
            if right[i] {
                line.push_str(&pad);
                line.push_str(cell);
            } else {
                line.push_str(cell);
                line.push_str(&pad);
            }
        }
        let _ = writeln!(out, "{}", line.trim_end());
    }
}
