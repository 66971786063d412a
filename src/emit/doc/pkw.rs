//! The parameter channel: its words, its codes, and worked examples. Every
//! code and every telegram here is made by the firmware's own codec
//! ([`crate::pkw`]), from the parameter the description names first.

use super::page::{code, text, Builder, Cell, Run};
use super::{bytes, parameter_name, Lang};
use crate::ir::manual::{Example, ExamplePart, ExampleWord};
use crate::ir::{Direction, Holds, Ir, PkwKind};
use crate::pkw::profidrive::{Meaning, PROFILE_ERRORS, REQUESTS, RESPONSES};
use crate::pkw::{pkw_pke_ind_pwe as pke, pkw_profidrive as profidrive};
use crate::pkw::{pkw_station_command as station, U16Be};

pub(crate) fn section(doc: &mut Builder, ir: &Ir, lang: Lang) {
    let has_pkw = ir
        .profibus
        .iter()
        .flat_map(|p| &p.modules)
        .any(|m| m.layout.pkw)
        || ir
            .profinet
            .iter()
            .flat_map(|p| &p.modules)
            .any(|m| m.layout.pkw);
    if !has_pkw {
        return;
    }
    doc.section(
        "pkw",
        lang.t("The parameter channel (PKW)", "参数区（PKW）"),
    );
    doc.para(text(lang.t(
        "The PKW words read or change one drive parameter per request, in the first 8 bytes of a module that has them.",
        "PKW 区位于带 PKW 的模块的前 8 个字节，每次请求读写变频器的一个参数。",
    )));
    match ir.telegram.pkw {
        PkwKind::PkeIndPwe => pke_ind_pwe(doc, ir, lang),
        PkwKind::StationCommandAddressValue => station_command(doc, ir, lang),
        PkwKind::Profidrive => profidrive_channel(doc, ir, lang),
        PkwKind::None => {}
    }
}

/// The parameter of the examples: the first address a mapping carries by
/// default (MD810: PZD1's F0-00), else the first drive parameter that holds
/// a mapping (MV810: P43.02); with its reason. `None` when the description
/// names no parameter at all.
fn example_parameter(ir: &Ir, lang: Lang) -> Option<(u16, String)> {
    let entries = || {
        ir.mappings
            .sets()
            .flat_map(|s| s.entries.iter().map(move |e| (s, e)))
    };
    let default = entries()
        .find(|(s, _)| s.holds == Holds::Address)
        .map(|(_, e)| {
            let why = lang.f(
                format!("the default of {}", lang.text(&e.name)),
                format!("{}的默认值", lang.text(&e.name)),
            );
            (e.default, why)
        });
    let holder = || {
        entries().find_map(|(_, e)| {
            let why = lang.f(
                format!("the parameter that sets {}", lang.text(&e.name)),
                format!("设置{}的参数", lang.text(&e.name)),
            );
            Some((e.parameter?, why))
        })
    };
    default.or_else(holder)
}

/// `number` is how the channel numbers the parameter: `address 0xF000`,
/// `地址 0xF000`, `PNU 1005`.
fn examples_intro(doc: &mut Builder, ir: &Ir, lang: Lang, address: u16, number: &str, why: &str) {
    let name = parameter_name(ir, address);
    doc.para(vec![
        Run::Text(
            lang.t("The examples read and write ", "以下示例读写 ")
                .into(),
        ),
        Run::Code(name),
        Run::Text(lang.f(
            format!(
                " ({number}), {why}. The telegrams are encoded by the firmware layout's own code."
            ),
            format!("（{number}，{why}）。报文由固件数据布局的编码代码生成。"),
        )),
    ]);
}

/// The `address 0xF000` of the vendor channels' examples.
fn address_number(lang: Lang, address: u16) -> String {
    lang.f(
        format!("address 0x{address:04X}"),
        format!("地址 0x{address:04X}"),
    )
}

/// Words as the manuals print them, `10F0 0800 0000 0000`; a byte that
/// follows a variable is written as its letter twice (`vvvv`).
fn telegram(base: [U16Be; 4], variables: &[(char, [U16Be; 4])]) -> String {
    let bytes = |words: [U16Be; 4]| words.map(|w| w.get().to_be_bytes());
    let base = bytes(base);
    let variables: Vec<(char, [[u8; 2]; 4])> =
        variables.iter().map(|&(c, w)| (c, bytes(w))).collect();
    (0..4)
        .map(|word| {
            (0..2)
                .map(|byte| {
                    let varying = variables
                        .iter()
                        .find(|(_, v)| v[word][byte] != base[word][byte]);
                    match varying {
                        Some((letter, _)) => format!("{letter}{letter}"),
                        None => format!("{:02X}", base[word][byte]),
                    }
                })
                .collect::<String>()
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// A value the examples leave open, against which the varying bytes are found.
const ANY: u16 = 0xFFFF;

// ---------------------------------------------------------------------------
// PKE, IND, PWE (MD810)

/// PKE bits 15-12 of a telegram: the command or response code.
fn code_of(words: [U16Be; 4]) -> u16 {
    words[0].get() >> 12
}

/// The four PKW words, in bytes 0-7: each one's bytes and what it holds in
/// a request and in a response, under `directions`, the manual's names of
/// the two.
fn words_table(
    doc: &mut Builder,
    lang: Lang,
    directions: [&str; 2],
    words: [(&str, &str, &str); 4],
) {
    let rows = words
        .iter()
        .zip((0u16..).step_by(2))
        .map(|(&(word, request, response), first)| {
            vec![
                text(word),
                text(bytes(lang, first, first + 1)),
                text(request),
                text(response),
            ]
        })
        .collect();
    doc.table(
        lang.t("The PKW words", "PKW 数据格式"),
        &[
            lang.t("Word", "字"),
            lang.t("Bytes", "字节"),
            directions[0],
            directions[1],
        ],
        rows,
    );
}

fn pke_ind_pwe(doc: &mut Builder, ir: &Ir, lang: Lang) {
    // MD810 manual 1.4.2: a write left in the telegram wears out the EEPROM.
    doc.para(text(lang.t(
        "A request is executed again every cycle while it stays in the telegram: a write left there writes the EEPROM again and again. Send command 0 when done.",
        "PKW 数据以循环执行的方式与变频器交互：写命令留在报文中会持续写 EEPROM。操作完成后请发送命令 0。",
    )));
    words_table(
        doc,
        lang,
        [
            lang.t("Request (master → drive)", "主站发送数据"),
            lang.t("Response (drive → master)", "变频器响应数据"),
        ],
        [
            (
                "PKE",
                lang.t(
                    "bits 15-12: command; bits 11-8: reserved; bits 7-0: address, high byte",
                    "高 4 位：命令代码；低 4 位（位 11-8）：保留；低 8 位：功能码参数地址高位",
                ),
                lang.t(
                    "bits 15-12: response code; bits 7-0: address, high byte",
                    "高 4 位：响应代码；低 8 位：功能码参数地址高位",
                ),
            ),
            (
                "IND",
                lang.t(
                    "bits 15-8: address, low byte; bits 7-0: reserved",
                    "高 8 位：功能码参数地址低位；低 8 位：保留",
                ),
                lang.t(
                    "bits 15-8: address, low byte; bits 7-0: reserved",
                    "高 8 位：功能码参数地址低位；低 8 位：保留",
                ),
            ),
            (
                "PWE",
                lang.t("high word: reserved", "高 16 位：保留"),
                lang.t("high word: reserved", "高 16 位：保留"),
            ),
            (
                "PWE",
                lang.t(
                    "low word: the value to write; unused when reading",
                    "低 16 位：写请求时为参数值；读请求时无使用",
                ),
                lang.t(
                    "low word: done, the value; cannot execute, the error code",
                    "低 16 位：请求成功时为参数值；失败时为错误代码",
                ),
            ),
        ],
    );
    let code_row = |code: u16, meaning: &str| vec![text(code.to_string()), text(meaning)];
    let requests = [
        (pke::PkwRequest::None, lang.t("no request", "无请求")),
        (
            pke::PkwRequest::Read { address: 0 },
            lang.t("read the parameter", "读取功能码参数数据"),
        ),
        (
            pke::PkwRequest::Write {
                address: 0,
                value: 0,
            },
            lang.t("change the parameter", "更改功能码参数数据"),
        ),
    ];
    doc.table(
        lang.t(
            "Request commands (PKE bits 15-12, decimal)",
            "命令代码（PKE 高 4 位，十进制）",
        ),
        &[lang.t("Code", "代码"), lang.t("Meaning", "含义")],
        requests
            .iter()
            .map(|(r, m)| code_row(code_of(r.encode()), m))
            .collect(),
    );
    let responses = [
        (pke::PkwResponse::None, lang.t("no request", "无请求")),
        (
            pke::PkwResponse::Done {
                address: 0,
                value: 0,
            },
            lang.t("done", "功能码参数操作正确"),
        ),
        (
            pke::PkwResponse::Failed {
                address: 0,
                error: pke::PkwErrorCode::Other,
            },
            lang.t(
                "cannot execute: PWE low holds the error code",
                "无法执行：PWE 低 16 位为错误代码",
            ),
        ),
    ];
    doc.table(
        lang.t(
            "Response codes (PKE bits 15-12, decimal)",
            "响应代码（PKE 高 4 位，十进制）",
        ),
        &[lang.t("Code", "代码"), lang.t("Meaning", "含义")],
        responses
            .iter()
            .map(|(r, m)| code_row(code_of(r.encode()), m))
            .collect(),
    );
    let errors = error_codes(lang);
    doc.table(
        lang.t(
            "Error codes (as in Modbus)",
            "错误代码（与标准 MODBUS 一致）",
        ),
        &[lang.t("Code", "代码"), lang.t("Meaning", "含义")],
        errors.iter().map(|(e, m)| code_row(e.code(), m)).collect(),
    );
    if manual_examples(doc, ir, lang) {
        return;
    }
    let Some((address, why)) = example_parameter(ir, lang) else {
        return;
    };
    examples_intro(doc, ir, lang, address, &address_number(lang, address), &why);
    let name = parameter_name(ir, address);
    let done = |value| pke::PkwResponse::Done { address, value }.encode();
    let read = pke::PkwRequest::Read { address }.encode();
    let write = |value| pke::PkwRequest::Write { address, value }.encode();
    let mut rows = vec![
        example_row(
            lang.f(format!("read {name}"), format!("读 {name}")),
            telegram(read, &[]),
            lang.t("done", "操作正确"),
            telegram(done(0), &[('v', done(ANY))]),
        ),
        example_row(
            lang.f(
                format!("change {name} to vvvv"),
                format!("将 {name} 改为 vvvv"),
            ),
            telegram(write(0), &[('v', write(ANY))]),
            lang.t("done: the value written", "操作正确：返回写入值"),
            telegram(done(0), &[('v', done(ANY))]),
        ),
    ];
    // The error code varies: any of the table's (not one guessed for a read).
    let failed = |error| pke::PkwResponse::Failed { address, error }.encode();
    let (first, last) = (errors[0].0, errors[errors.len() - 1].0);
    rows.push(example_row(
        lang.f(format!("read {name}"), format!("读 {name}")),
        telegram(read, &[]),
        &lang.f(
            format!(
                "cannot execute: error code eeee, {} to {}",
                first.code(),
                last.code()
            ),
            format!("无法执行：错误代码 eeee，{}～{}", first.code(), last.code()),
        ),
        telegram(failed(first), &[('e', every_bit_of_pwe_low(failed(first)))]),
    ));
    rows.push(example_row(
        lang.t("no request", "无请求").to_string(),
        telegram(pke::PkwRequest::None.encode(), &[]),
        lang.t("no request", "无请求"),
        telegram(pke::PkwResponse::None.encode(), &[]),
    ));
    examples_table(doc, lang, rows);
    doc.para(text(lang.t(
        "vvvv: the parameter's value; eeee: the error code.",
        "vvvv：参数值；eeee：错误代码。",
    )));
}

/// The manual's examples of the PKW channel, as it prints them, each read
/// by the firmware's codec; whether there are any.
fn manual_examples(doc: &mut Builder, ir: &Ir, lang: Lang) -> bool {
    let examples: Vec<&Example> = ir
        .examples
        .iter()
        .filter(|e| e.part == ExamplePart::Pkw || example_layout(ir, e).is_some_and(|l| l.pkw))
        .collect();
    if examples.is_empty() {
        return false;
    }
    doc.para(text(lang.t(
        "The manual's examples, as it prints them; the last column is what the firmware layout's codec reads in them (gsdc's words).",
        "手册中的示例，按手册原样列出；最后一列为固件数据布局的解码代码对其的解读（gsdc 的说明）。",
    )));
    let rows = examples
        .iter()
        .map(|e| {
            let mut manual = e.section.clone();
            if let Some(figure) = &e.figure {
                manual = lang.f(
                    format!("{manual}, {}", lang.text(figure)),
                    format!("{manual}，{}", lang.text(figure)),
                );
            }
            vec![
                text(manual),
                text(match &e.module {
                    Some(module) => module.clone(),
                    None => lang
                        .t("the PKW words of every module", "各模块的 PKW")
                        .to_string(),
                }),
                text(match e.direction {
                    Direction::Out => lang.t("master → drive", "主站 → 变频器"),
                    Direction::In => lang.t("drive → master", "变频器 → 主站"),
                }),
                code(e.printed.clone()),
                text(lang.text(&e.meaning)),
                text(read_by_codec(ir, lang, e)),
            ]
        })
        .collect();
    doc.table(
        lang.t("Worked examples of the manual", "手册中的应用举例"),
        &[
            lang.t("Manual", "手册"),
            lang.t("Module", "模块"),
            lang.t("Direction", "方向"),
            lang.t("Bytes as printed", "数据（手册原样）"),
            lang.t("Meaning (the manual's)", "含义（手册原文）"),
            lang.t("Read by the codec", "解码结果"),
        ],
        rows,
    );
    true
}

/// The layout of an example's module, when it names one.
fn example_layout(ir: &Ir, e: &Example) -> Option<crate::ir::Layout> {
    let module = e.module.as_deref()?;
    let ppo = ir
        .profibus
        .iter()
        .flat_map(|p| &p.modules)
        .find(|m| m.name == module)
        .map(|m| m.layout);
    let pn = || {
        ir.profinet
            .iter()
            .flat_map(|p| &p.modules)
            .find(|m| m.name.text.en == module)
            .map(|m| m.layout)
    };
    ppo.or_else(pn)
}

/// What the codec reads in each telegram the example stands for: one, or
/// one per value of its named word (`errCode = 1: ...`).
fn read_by_codec(ir: &Ir, lang: Lang, e: &Example) -> String {
    let named: Vec<(&str, &[u16])> = e
        .words
        .iter()
        .filter_map(|w| match w {
            ExampleWord::Named { name, values } => Some((name.as_str(), values.as_slice())),
            ExampleWord::Bytes(_) => None,
        })
        .collect();
    let read = |bytes: &[u8]| codec_summary(ir, lang, e.direction, crate::pkw::pkw_words(bytes));
    let instances = e.instances();
    match named.as_slice() {
        [(name, values)] if values.len() == instances.len() => values
            .iter()
            .zip(&instances)
            .map(|(value, bytes)| format!("{name} = {value}: {}", read(bytes)))
            .collect::<Vec<_>>()
            .join(lang.t("; ", "；")),
        _ => instances
            .iter()
            .map(|bytes| read(bytes))
            .collect::<Vec<_>>()
            .join(lang.t("; ", "；")),
    }
}

/// One PKW request or response in words: `read F0-08`, `done: F0-08 =
/// 5000 (0x1388)`, `cannot execute F0-08: illegal command`.
fn codec_summary(ir: &Ir, lang: Lang, direction: Direction, words: [U16Be; 4]) -> String {
    let name = |address| parameter_name(ir, address);
    let value = |v: u16| format!("{v} (0x{v:04X})");
    match (ir.telegram.pkw, direction) {
        (PkwKind::PkeIndPwe, Direction::Out) => match pke::PkwRequest::decode(&words) {
            Ok(pke::PkwRequest::None) => lang.t("no request", "无请求").into(),
            Ok(pke::PkwRequest::Read { address }) => lang.f(
                format!("read {}", name(address)),
                format!("读 {}", name(address)),
            ),
            Ok(pke::PkwRequest::Write { address, value: v }) => lang.f(
                format!("change {} to {}", name(address), value(v)),
                format!("将 {} 改为 {}", name(address), value(v)),
            ),
            Err(_) => lang.t("refused", "拒绝").into(),
        },
        (PkwKind::PkeIndPwe, Direction::In) => match pke::PkwResponse::decode(&words) {
            Ok(pke::PkwResponse::None) => lang.t("no request", "无请求").into(),
            Ok(pke::PkwResponse::Done { address, value: v }) => lang.f(
                format!("done: {} = {}", name(address), value(v)),
                format!("操作正确：{} = {}", name(address), value(v)),
            ),
            Ok(pke::PkwResponse::Failed { address, error }) => {
                let meaning = error_codes(lang)
                    .iter()
                    .find(|(e, _)| *e == error)
                    .map_or("", |(_, m)| *m);
                lang.f(
                    format!("cannot execute {}: {meaning}", name(address)),
                    format!("无法执行 {}：{meaning}", name(address)),
                )
            }
            Err(_) => lang.t("refused", "拒绝").into(),
        },
        // Lowering checked that the codec takes every example.
        (_, Direction::Out) => lang.t("a request the codec reads", "可解码的请求").into(),
        (_, Direction::In) => lang.t("a response the codec reads", "可解码的响应").into(),
    }
}

/// `words` with PWE low's every bit changed: the word varies whole.
fn every_bit_of_pwe_low(mut words: [U16Be; 4]) -> [U16Be; 4] {
    words[3] = U16Be::new(!words[3].get());
    words
}

fn error_codes(lang: Lang) -> [(pke::PkwErrorCode, &'static str); 4] {
    [
        (
            pke::PkwErrorCode::IllegalCommand,
            lang.t("illegal command", "非法命令"),
        ),
        (
            pke::PkwErrorCode::IllegalAddress,
            lang.t("illegal address", "非法地址"),
        ),
        (
            pke::PkwErrorCode::IllegalData,
            lang.t("illegal data", "非法数据"),
        ),
        (pke::PkwErrorCode::Other, lang.t("other error", "其它错误")),
    ]
}

fn example_row(what: String, request: String, outcome: &str, response: String) -> Vec<Cell> {
    vec![text(what), code(request), text(outcome), code(response)]
}

fn examples_table(doc: &mut Builder, lang: Lang, rows: Vec<Vec<Cell>>) {
    doc.table(
        lang.t(
            "Worked examples, computed from the description",
            "应用举例（由设备描述计算）",
        ),
        &[
            lang.t("Request", "请求"),
            lang.t("Master sends", "主站发送 PKW"),
            lang.t("Outcome", "结果"),
            lang.t("Drive answers", "变频器响应 PKW"),
        ],
        rows,
    );
}

// ---------------------------------------------------------------------------
// Station, command, address, value (MV810)

fn station_command(doc: &mut Builder, ir: &Ir, lang: Lang) {
    words_table(
        doc,
        lang,
        [lang.t("Request (controller → drive)", "控制器请求"), lang.t("Reply (drive → controller)", "从站应答")],
        [
            ("PKW0", lang.t("high byte: target station (the RS-485 slave); low byte: source station (this drive's own)", "Byte0：目标站号（485 从站）；Byte1：源站号（本机站号）"), lang.t("high byte: target station (the RS-485 master); low byte: source station (the answering drive)", "Byte0：目标站号（485 主站）；Byte1：源站号（本机站号）")),
            ("PKW1", lang.t("the command", "读写功能码命令"), lang.t("the command; 0x80 + the command on error", "应答命令；错误应答为 0x80+命令码")),
            ("PKW2", lang.t("the parameter's address", "需要读写的功能码地址"), lang.t("the same address", "功能码地址")),
            ("PKW3", lang.t("write: the value; read: the count, always 1", "写操作：写的具体值；读操作：读的个数（固定值 1）"), lang.t("read: the value; write: 0; error: the error code", "读操作应答：功能码值；写操作应答：0；错误应答：错误码")),
        ],
    );
    let commands = [
        (
            station::PkwCommand::Read,
            lang.t("read one parameter", "读一个"),
        ),
        (
            station::PkwCommand::WriteAndStore,
            lang.t(
                "write one parameter and store it in EEPROM",
                "写一个，存 EEPROM",
            ),
        ),
        (
            station::PkwCommand::Write,
            lang.t(
                "write one parameter without storing it",
                "写一个，不存 EEPROM",
            ),
        ),
    ];
    let stations = station::Stations {
        target: 0,
        source: 0,
    };
    let failed_code = |command| {
        let reply = station::PkwResponse {
            stations,
            address: 0,
            reply: station::PkwReply::Failed { command, error: 0 },
        };
        reply.encode()[1].get()
    };
    doc.table(
        lang.t("Commands (PKW1)", "命令（PKW1）"),
        &[
            lang.t("Command", "命令"),
            lang.t("Meaning", "含义"),
            lang.t("Reply on error", "错误应答"),
        ],
        commands
            .iter()
            .map(|(c, m)| {
                vec![
                    code(format!("0x{:02X}", c.code())),
                    text(*m),
                    code(format!("0x{:02X}", failed_code(*c))),
                ]
            })
            .collect(),
    );
    doc.para(text(lang.t(
        "The manual lists no error codes: the reply to a failed request carries the drive's error code in PKW3.",
        "手册未列出错误码：错误应答在 PKW3 中返回变频器的错误码。",
    )));
    if manual_examples(doc, ir, lang) {
        return;
    }
    let Some((address, why)) = example_parameter(ir, lang) else {
        return;
    };
    examples_intro(doc, ir, lang, address, &address_number(lang, address), &why);
    let name = parameter_name(ir, address);
    let request = |access, stations| {
        station::PkwRequest {
            stations,
            address,
            access,
        }
        .encode()
    };
    // The reply swaps the stations: its target is the request's source.
    let reply = |reply, stations: station::Stations| {
        station::PkwResponse {
            stations,
            address,
            reply,
        }
        .encode()
    };
    let (none, target, source) = (
        station::Stations {
            target: 0,
            source: 0,
        },
        station::Stations {
            target: 0xFF,
            source: 0,
        },
        station::Stations {
            target: 0,
            source: 0xFF,
        },
    );
    let sent = |access: &dyn Fn(u16) -> station::PkwAccess| {
        telegram(
            request(access(0), none),
            &[
                ('t', request(access(0), target)),
                ('s', request(access(0), source)),
                ('v', request(access(ANY), none)),
            ],
        )
    };
    let answered = |r: &dyn Fn(u16) -> station::PkwReply, letter: char| {
        telegram(
            reply(r(0), none),
            &[
                ('s', reply(r(0), target)),
                ('t', reply(r(0), source)),
                (letter, reply(r(ANY), none)),
            ],
        )
    };
    let mut rows = vec![example_row(
        lang.f(format!("read {name}"), format!("读 {name}")),
        sent(&|_| station::PkwAccess::Read),
        lang.t("done: the value", "读操作应答：功能码值"),
        answered(&station::PkwReply::Value, 'v'),
    )];
    for (access, done, how) in [
        (
            &(|value| station::PkwAccess::WriteAndStore { value })
                as &dyn Fn(u16) -> station::PkwAccess,
            station::PkwReply::WrittenAndStored,
            lang.t(", stored in EEPROM", "，存 EEPROM"),
        ),
        (
            &(|value| station::PkwAccess::Write { value }) as &dyn Fn(u16) -> station::PkwAccess,
            station::PkwReply::Written,
            lang.t(", not stored", "，不存 EEPROM"),
        ),
    ] {
        rows.push(example_row(
            lang.f(
                format!("write vvvv to {name}{how}"),
                format!("将 vvvv 写入 {name}{how}"),
            ),
            sent(access),
            lang.t("done", "写操作应答"),
            answered(&|_| done, 'v'),
        ));
    }
    rows.push(example_row(
        lang.f(format!("read {name}"), format!("读 {name}")),
        sent(&|_| station::PkwAccess::Read),
        lang.t("failed", "错误应答"),
        answered(
            &|error| station::PkwReply::Failed {
                command: station::PkwCommand::Read,
                error,
            },
            'x',
        ),
    ));
    examples_table(doc, lang, rows);
    doc.para(text(lang.t(
        "tt: the target station of the request, ss: its source station (the reply swaps them); vvvv: the value; xxxx: the drive's error code.",
        "tt：请求的目标站号，ss：请求的源站号（应答中二者互换）；vvvv：参数值；xxxx：变频器的错误码。",
    )));
}

// ---------------------------------------------------------------------------
// PROFIdrive

fn profidrive_channel(doc: &mut Builder, ir: &Ir, lang: Lang) {
    doc.para(text(lang.t(
        "The channel is the PROFIdrive profile's, as its PPO types carry it: PKE holds the request or response id and the parameter number (PNU), IND the subindex, PWE1 and PWE2 the value.",
        "参数区为 PROFIdrive 行规的参数通道（PPO 类型）：PKE 含请求或应答标识与参数号（PNU），IND 为子索引，PWE1、PWE2 为参数值。",
    )));
    words_table(
        doc,
        lang,
        [
            lang.t("Request (master → drive)", "主站请求"),
            lang.t("Response (drive → master)", "变频器应答"),
        ],
        [
            (
                "PKE",
                lang.t(
                    "bits 15-12: request id; bit 11: SPM, 0; bits 10-0: PNU",
                    "位 15-12：请求标识；位 11：SPM，为 0；位 10-0：参数号",
                ),
                lang.t(
                    "bits 15-12: response id; bit 11: SPM, 0; bits 10-0: PNU",
                    "位 15-12：应答标识；位 11：SPM，为 0；位 10-0：参数号",
                ),
            ),
            (
                "IND",
                lang.t(
                    "bits 15-8: subindex; bits 7-0: 0, not read (not defined by the profile)",
                    "位 15-8：子索引；位 7-0：为 0，不读取（行规未定义）",
                ),
                lang.t(
                    "bits 15-8: subindex; bits 7-0: 0, not read (not defined by the profile)",
                    "位 15-8：子索引；位 7-0：为 0，不读取（行规未定义）",
                ),
            ),
            (
                "PWE1",
                lang.t(
                    "a double word's high word; 0 otherwise",
                    "双字参数值的高 16 位；其余为 0",
                ),
                lang.t(
                    "a double word's high word; 0 otherwise",
                    "双字参数值的高 16 位；其余为 0",
                ),
            ),
            (
                "PWE2",
                lang.t(
                    "a word, or a double word's low word",
                    "单字参数值，或双字参数值的低 16 位",
                ),
                lang.t(
                    "a word, or a double word's low word; response 7: the error number",
                    "单字参数值，或双字参数值的低 16 位；应答 7：错误号",
                ),
            ),
        ],
    );
    let id_row = |id: u8, meanings: &[Meaning]| {
        let (en, zh) = meanings[usize::from(id)];
        vec![text(id.to_string()), text(lang.t(en, zh))]
    };
    doc.table(
        lang.t(
            "Request ids (PKE bits 15-12, decimal)",
            "请求标识（PKE 位 15-12，十进制）",
        ),
        &[lang.t("Id", "标识"), lang.t("Meaning", "含义")],
        sample_requests()
            .iter()
            .map(|r| id_row(r.id(), &REQUESTS))
            .collect(),
    );
    doc.table(
        lang.t(
            "Response ids (PKE bits 15-12, decimal)",
            "应答标识（PKE 位 15-12，十进制）",
        ),
        &[lang.t("Id", "标识"), lang.t("Meaning", "含义")],
        sample_responses()
            .iter()
            .map(|r| id_row(r.id(), &RESPONSES))
            .collect(),
    );
    doc.para(text(lang.t(
        "The card refuses request 10 (reserved) and 11 to 15, which are not the profile's (MICROMASTER and MASTERDRIVES store a value in EEPROM with 11 to 14). It sends no parameter change reports (responses 9 to 12): SPM is always 0.",
        "请求标识 10（保留）及 11 至 15（非行规定义；MICROMASTER 与 MASTERDRIVES 用 11 至 14 将参数值写入 EEPROM）不被接受。本卡不发送参数修改报告（应答 9 至 12）：SPM 恒为 0。",
    )));
    doc.table(
        lang.t(
            "Error numbers of response 7 (PWE2, decimal)",
            "应答 7 的错误号（PWE2，十进制）",
        ),
        &[lang.t("Number", "错误号"), lang.t("Meaning", "含义")],
        PROFILE_ERRORS
            .iter()
            .map(|(number, (en, zh))| vec![text(number.0.to_string()), text(lang.t(en, zh))])
            .collect(),
    );
    doc.para(text(lang.t(
        "Other numbers are the drive's own: Siemens manuals give those from 101 on as device-specific.",
        "其它错误号由变频器自定义：西门子手册中 101 起为设备专用错误号。",
    )));
    profidrive_examples(doc, ir, lang);
}

/// One request of each id, for the table of ids: the codec gives each id.
fn sample_requests() -> [profidrive::PkwRequest; 10] {
    use profidrive::PkwRequest as R;
    let parameter = any_parameter(0);
    [
        R::None,
        R::Read { parameter },
        R::WriteWord {
            parameter,
            value: 0,
        },
        R::WriteDoubleWord {
            parameter,
            value: 0,
        },
        R::ReadDescription { parameter },
        R::WriteDescription {
            parameter,
            value: 0,
        },
        R::ReadArray { parameter },
        R::WriteArrayWord {
            parameter,
            value: 0,
        },
        R::WriteArrayDoubleWord {
            parameter,
            value: 0,
        },
        R::ReadArrayLength { parameter },
    ]
}

/// One response of each id, for the table of ids.
fn sample_responses() -> [profidrive::PkwResponse; 9] {
    use profidrive::PkwResponse as R;
    let parameter = any_parameter(0);
    [
        R::None,
        R::Word {
            parameter,
            value: 0,
        },
        R::DoubleWord {
            parameter,
            value: 0,
        },
        R::Description {
            parameter,
            value: 0,
        },
        R::ArrayWord {
            parameter,
            value: 0,
        },
        R::ArrayDoubleWord {
            parameter,
            value: 0,
        },
        R::ArrayLength {
            parameter,
            count: 0,
        },
        R::Failed {
            parameter,
            error: profidrive::PkwErrorNumber(0),
        },
        R::NoAuthority { parameter },
    ]
}

fn any_parameter(subindex: u8) -> profidrive::Parameter {
    profidrive::Parameter {
        pnu: profidrive::Pnu::new(0).expect("0 is a PNU"),
        subindex,
    }
}

fn profidrive_examples(doc: &mut Builder, ir: &Ir, lang: Lang) {
    use profidrive::{PkwRequest as Q, PkwResponse as R};
    if manual_examples(doc, ir, lang) {
        return;
    }
    let Some((address, why)) = example_parameter(ir, lang) else {
        return;
    };
    // E154 keeps a description's parameters within the PNUs; a setting's
    // plain value may not be one.
    let Some(pnu) = profidrive::Pnu::new(address) else {
        return;
    };
    examples_intro(doc, ir, lang, address, &format!("PNU {address}"), &why);
    let name = parameter_name(ir, address);
    let at = |subindex| profidrive::Parameter { pnu, subindex };
    let p = at(0);
    // A telegram with `v` where the value varies, and `s` where the
    // subindex does when it is an array's.
    type Words<'a> = &'a dyn Fn(u32, profidrive::Parameter) -> [U16Be; 4];
    let shown = |words: Words, array: bool| {
        let mut variables = vec![('v', words(u32::MAX, p))];
        if array {
            variables.push(('s', words(0, at(u8::MAX))));
        }
        telegram(words(0, p), &variables)
    };
    // A word's value: the low half of what `shown` varies.
    let word = |value: u32| value as u16;
    let read = shown(&|_, parameter| Q::Read { parameter }.encode(), false);
    let write_word = shown(
        &|v, parameter| {
            Q::WriteWord {
                parameter,
                value: word(v),
            }
            .encode()
        },
        false,
    );
    let word_value = shown(
        &|v, parameter| {
            R::Word {
                parameter,
                value: word(v),
            }
            .encode()
        },
        false,
    );
    let double_value = shown(
        &|value, parameter| R::DoubleWord { parameter, value }.encode(),
        false,
    );
    let failed = |error| {
        R::Failed {
            parameter: p,
            error,
        }
        .encode()
    };
    let change = lang.f(
        format!("change {name} to vvvv (word)"),
        format!("将 {name} 改为 vvvv（单字）"),
    );
    let rows = vec![
        example_row(
            lang.f(format!("read {name}"), format!("读 {name}")),
            read.clone(),
            lang.t("a word parameter's value", "单字参数值"),
            word_value.clone(),
        ),
        example_row(
            lang.f(format!("read {name}"), format!("读 {name}")),
            read,
            lang.t("a double word parameter's value", "双字参数值"),
            double_value.clone(),
        ),
        example_row(
            change.clone(),
            write_word.clone(),
            lang.t("done: the value written", "操作正确：返回写入值"),
            word_value,
        ),
        example_row(
            lang.f(
                format!("change {name} to vvvvvvvv (double word)"),
                format!("将 {name} 改为 vvvvvvvv（双字）"),
            ),
            shown(
                &|value, parameter| Q::WriteDoubleWord { parameter, value }.encode(),
                false,
            ),
            lang.t("done: the value written", "操作正确：返回写入值"),
            double_value,
        ),
        example_row(
            lang.f(
                format!("read element ss of {name}"),
                format!("读 {name} 的元素 ss"),
            ),
            shown(&|_, parameter| Q::ReadArray { parameter }.encode(), true),
            lang.t("the element's value (word)", "数组元素值（单字）"),
            shown(
                &|v, parameter| {
                    R::ArrayWord {
                        parameter,
                        value: word(v),
                    }
                    .encode()
                },
                true,
            ),
        ),
        example_row(
            change.clone(),
            write_word.clone(),
            lang.t("cannot execute: error number xxxx", "无法执行：错误号 xxxx"),
            telegram(
                failed(profidrive::PkwErrorNumber(0)),
                &[('x', failed(profidrive::PkwErrorNumber(u16::MAX)))],
            ),
        ),
        example_row(
            change,
            write_word,
            lang.t("no master control", "无主控权"),
            telegram(R::NoAuthority { parameter: p }.encode(), &[]),
        ),
        example_row(
            lang.t("no request", "无请求").to_string(),
            telegram(Q::None.encode(), &[]),
            lang.t("no response", "无应答"),
            telegram(R::None.encode(), &[]),
        ),
    ];
    examples_table(doc, lang, rows);
    doc.para(text(lang.t(
        "vvvv: the value (vvvvvvvv: a double word, high word first); ss: the subindex; xxxx: the error number.",
        "vvvv：参数值（vvvvvvvv：双字，高 16 位在前）；ss：子索引；xxxx：错误号。",
    )));
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ir(name: &str, text: &str) -> Ir {
        crate::testing::load(name, text).0.unwrap()
    }

    /// MD810 manual 1.4.2, figures 6 and 7: read and change F0-08.
    #[test]
    fn the_md810_manuals_telegrams_come_out_of_the_codec() {
        let address = 0xF008;
        let read = pke::PkwRequest::Read { address }.encode();
        assert_eq!(telegram(read, &[]), "10F0 0800 0000 0000");
        let done = |value| pke::PkwResponse::Done { address, value }.encode();
        assert_eq!(telegram(done(0x1388), &[]), "10F0 0800 0000 1388");
        let write = |value| pke::PkwRequest::Write { address, value }.encode();
        assert_eq!(telegram(write(0x07D0), &[]), "20F0 0800 0000 07D0");
        assert_eq!(
            telegram(write(0), &[('v', write(ANY))]),
            "20F0 0800 0000 vvvv"
        );
        assert_eq!(code_of(done(0)), 1);
    }

    /// docs/wire-format.md: station 1 reads P43.02 of RS-485 slave 2.
    #[test]
    fn the_station_kind_writes_stations_command_address_and_count() {
        let stations = station::Stations {
            target: 2,
            source: 1,
        };
        let read = station::PkwRequest {
            stations,
            address: 0x2B02,
            access: station::PkwAccess::Read,
        };
        assert_eq!(telegram(read.encode(), &[]), "0201 0003 2B02 0001");
    }

    #[test]
    fn the_example_parameter_is_the_first_address_default_else_the_first_drive_parameter() {
        let md810 = ir(
            "md810dp.toml",
            include_str!("../../../descriptions/md810dp.toml"),
        );
        let (address, why) = example_parameter(&md810, Lang::En).unwrap();
        assert_eq!(
            (address, why.as_str()),
            (0xF000, "the default of PZD1(master->slaver)")
        );
        let mv810 = ir(
            "mv810-pnet02.toml",
            include_str!("../../../descriptions/mv810-pnet02.toml"),
        );
        let (address, why) = example_parameter(&mv810, Lang::En).unwrap();
        assert_eq!(
            (address, why.as_str()),
            (0x2B02, "the parameter that sets PZD2 receive")
        );
        // A setting's timeout of 100 ms is a value, not the parameter at
        // address 100: the example stays P43.02.
        let with_timeout = crate::testing::mv810_with_timeout();
        let (address, _) = example_parameter(&with_timeout, Lang::En).unwrap();
        assert_eq!(address, 0x2B02);
    }
}
