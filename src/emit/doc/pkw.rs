//! The parameter channel: its words, its codes, and worked examples. Every
//! code and every telegram here is made by the firmware's own codec
//! ([`crate::pkw`]), from the parameter the description names first.

use super::page::{code, text, Builder, Cell, Run};
use super::{bytes, parameter_name, Lang};
use crate::i18n::{codes, sheet as w, Phrase};
use crate::ir::manual::{Example, ExamplePart, ExampleWord};
use crate::ir::{Direction, Holds, Ir, PkwKind};
use crate::pkw::profidrive::{PROFILE_ERRORS, REQUESTS, RESPONSES};
use crate::pkw::{pkw_pke_ind_pwe as pke, pkw_profidrive as profidrive};
use crate::pkw::{pkw_station_command as station, U16Be};

pub(crate) fn section(doc: &mut Builder, ir: &Ir, lang: Lang) {
    let has_pkw = ir
        .profibus
        .iter()
        .flat_map(|p| &p.modules)
        .any(|m| m.layout.is_some_and(|l| l.pkw))
        || ir
            .profinet
            .iter()
            .flat_map(|p| &p.modules)
            .any(|m| m.layout.pkw);
    if !has_pkw {
        return;
    }
    doc.section_with_intro("pkw", lang.t(w::PKW_HEADING), lang.t(w::PKW_INTRO));
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
            let why = w::the_default_of(lang, lang.text(&e.name));
            (e.default, why)
        });
    let holder = || {
        entries().find_map(|(_, e)| {
            let why = w::the_parameter_that_sets(lang, lang.text(&e.name));
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
        Run::Text(lang.t(w::EXAMPLES_READ_WRITE).into()),
        Run::Code(name),
        Run::Text(w::examples_encoded(lang, number, why)),
    ]);
}

/// The `address 0xF000` of the vendor channels' examples.
fn address_number(lang: Lang, address: u16) -> String {
    w::address_number(lang, address)
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
    directions: [Phrase; 2],
    words: [(&str, Phrase, Phrase); 4],
) {
    let rows = words
        .iter()
        .zip((0u16..).step_by(2))
        .map(|(&(word, request, response), first)| {
            vec![
                text(word),
                text(bytes(lang, first, first + 1)),
                text(lang.t(request)),
                text(lang.t(response)),
            ]
        })
        .collect();
    doc.table(
        lang.t(w::THE_PKW_WORDS),
        &[
            lang.t(w::WORD),
            lang.t(w::BYTES),
            lang.t(directions[0]),
            lang.t(directions[1]),
        ],
        rows,
    );
}

fn pke_ind_pwe(doc: &mut Builder, ir: &Ir, lang: Lang) {
    // MD810 manual 1.4.2: a write left in the telegram wears out the EEPROM.
    doc.para(text(lang.t(w::PKE_REPEAT)));
    words_table(
        doc,
        lang,
        [w::PKE_REQUEST_HEAD, w::PKE_RESPONSE_HEAD],
        [
            ("PKE", w::PKE_REQUEST_PKE, w::PKE_RESPONSE_PKE),
            ("IND", w::PKE_IND, w::PKE_IND),
            ("PWE", w::PKE_PWE_HIGH, w::PKE_PWE_HIGH),
            ("PWE", w::PKE_PWE_LOW_REQUEST, w::PKE_PWE_LOW_RESPONSE),
        ],
    );
    let code_row = |code: u16, meaning: &str| vec![text(code.to_string()), text(meaning)];
    let requests = [
        (pke::PkwRequest::None, lang.t(codes::REQUEST_NONE)),
        (pke::PkwRequest::Read { address: 0 }, lang.t(w::PKE_READ)),
        (
            pke::PkwRequest::Write {
                address: 0,
                value: 0,
            },
            lang.t(w::PKE_CHANGE),
        ),
    ];
    doc.table(
        lang.t(w::PKE_COMMANDS_CAPTION),
        &[lang.t(w::CODE), lang.t(w::MEANING)],
        requests
            .iter()
            .map(|(r, m)| code_row(code_of(r.encode()), m))
            .collect(),
    );
    let responses = [
        (pke::PkwResponse::None, lang.t(codes::REQUEST_NONE)),
        (
            pke::PkwResponse::Done {
                address: 0,
                value: 0,
            },
            lang.t(w::PKE_DONE_CODE),
        ),
        (
            pke::PkwResponse::Failed {
                address: 0,
                error: pke::PkwErrorCode::Other,
            },
            lang.t(w::PKE_FAILED_CODE),
        ),
    ];
    doc.table(
        lang.t(w::PKE_RESPONSES_CAPTION),
        &[lang.t(w::CODE), lang.t(w::MEANING)],
        responses
            .iter()
            .map(|(r, m)| code_row(code_of(r.encode()), m))
            .collect(),
    );
    let errors = error_codes(lang);
    doc.table(
        lang.t(w::PKE_ERRORS_CAPTION),
        &[lang.t(w::CODE), lang.t(w::MEANING)],
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
            w::read_parameter(lang, &name),
            telegram(read, &[]),
            lang.t(w::DONE),
            telegram(done(0), &[('v', done(ANY))]),
        ),
        example_row(
            w::change_to_vvvv(lang, &name),
            telegram(write(0), &[('v', write(ANY))]),
            lang.t(w::DONE_VALUE_WRITTEN),
            telegram(done(0), &[('v', done(ANY))]),
        ),
    ];
    // The error code varies: any of the table's (not one guessed for a read).
    let failed = |error| pke::PkwResponse::Failed { address, error }.encode();
    let (first, last) = (errors[0].0, errors[errors.len() - 1].0);
    rows.push(example_row(
        w::read_parameter(lang, &name),
        telegram(read, &[]),
        &w::cannot_execute_eeee(lang, first.code(), last.code()),
        telegram(failed(first), &[('e', every_bit_of_pwe_low(failed(first)))]),
    ));
    rows.push(example_row(
        lang.t(codes::REQUEST_NONE).to_string(),
        telegram(pke::PkwRequest::None.encode(), &[]),
        lang.t(codes::REQUEST_NONE),
        telegram(pke::PkwResponse::None.encode(), &[]),
    ));
    examples_table(doc, lang, rows);
    doc.para(text(lang.t(w::VVVV_EEEE_LEGEND)));
}

/// `words` with PWE low's every bit changed: the word varies whole.
fn every_bit_of_pwe_low(mut words: [U16Be; 4]) -> [U16Be; 4] {
    words[3] = U16Be::new(!words[3].get());
    words
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
    doc.para(text(lang.t(w::MANUAL_EXAMPLES_INTRO)));
    let rows = examples
        .iter()
        .map(|e| {
            let manual = match &e.figure {
                Some(figure) => w::section_figure(lang, &e.section, lang.text(figure)),
                None => e.section.clone(),
            };
            vec![
                text(manual),
                text(match &e.module {
                    Some(module) => module.as_str(),
                    None => lang.t(w::PKW_OF_EVERY_MODULE),
                }),
                text(match e.direction {
                    Direction::Out => lang.t(w::MASTER_TO_DRIVE),
                    Direction::In => lang.t(w::DRIVE_TO_MASTER),
                }),
                code(e.printed.clone()),
                text(lang.text(&e.meaning)),
                text(read_by_codec(ir, lang, e)),
            ]
        })
        .collect();
    doc.table(
        lang.t(w::MANUAL_EXAMPLES_CAPTION),
        &[
            lang.t(w::MANUAL),
            lang.t(w::MODULE),
            lang.t(w::DIRECTION),
            lang.t(w::BYTES_AS_PRINTED),
            lang.t(w::MEANING_THE_MANUALS),
            lang.t(w::READ_BY_THE_CODEC),
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
        .and_then(|m| m.layout);
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
    let each: Vec<String> = match named.as_slice() {
        [(name, values)] if values.len() == instances.len() => values
            .iter()
            .zip(&instances)
            .map(|(value, bytes)| w::named_word_reads(lang, name, *value, &read(bytes)))
            .collect(),
        _ => instances.iter().map(|bytes| read(bytes)).collect(),
    };
    each.join(lang.t(w::SEMICOLON))
}

/// One PKW request or response in words: `read F0-08`, `done: F0-08 =
/// 5000 (0x1388)`, `cannot execute F0-08: illegal command`.
fn codec_summary(ir: &Ir, lang: Lang, direction: Direction, words: [U16Be; 4]) -> String {
    let name = |address| parameter_name(ir, address);
    let value = |v: u16| format!("{v} (0x{v:04X})");
    match (ir.telegram.pkw, direction) {
        (PkwKind::PkeIndPwe, Direction::Out) => match pke::PkwRequest::decode(&words) {
            Ok(pke::PkwRequest::None) => lang.t(codes::REQUEST_NONE).into(),
            Ok(pke::PkwRequest::Read { address }) => w::read_parameter(lang, &name(address)),
            Ok(pke::PkwRequest::Write { address, value: v }) => {
                w::change_to_value(lang, &name(address), &value(v))
            }
            Err(_) => lang.t(w::REFUSED).into(),
        },
        (PkwKind::PkeIndPwe, Direction::In) => match pke::PkwResponse::decode(&words) {
            Ok(pke::PkwResponse::None) => lang.t(codes::REQUEST_NONE).into(),
            Ok(pke::PkwResponse::Done { address, value: v }) => {
                w::done_value(lang, &name(address), &value(v))
            }
            Ok(pke::PkwResponse::Failed { address, error }) => w::cannot_execute_at(
                lang,
                &name(address),
                lang.t(crate::pkw::pke_error_meaning(error)),
            ),
            Err(_) => lang.t(w::REFUSED).into(),
        },
        // Lowering checked that the codec takes every example.
        (_, Direction::Out) => lang.t(w::A_REQUEST_THE_CODEC_READS).into(),
        (_, Direction::In) => lang.t(w::A_RESPONSE_THE_CODEC_READS).into(),
    }
}

fn error_codes(lang: Lang) -> [(pke::PkwErrorCode, &'static str); 4] {
    use pke::PkwErrorCode as E;
    [
        E::IllegalCommand,
        E::IllegalAddress,
        E::IllegalData,
        E::Other,
    ]
    .map(|e| (e, lang.t(crate::pkw::pke_error_meaning(e))))
}

fn example_row(what: String, request: String, outcome: &str, response: String) -> Vec<Cell> {
    vec![text(what), code(request), text(outcome), code(response)]
}

fn examples_table(doc: &mut Builder, lang: Lang, rows: Vec<Vec<Cell>>) {
    doc.table(
        lang.t(w::WORKED_EXAMPLES),
        &[
            lang.t(w::REQUEST),
            lang.t(w::MASTER_SENDS),
            lang.t(w::OUTCOME),
            lang.t(w::DRIVE_ANSWERS),
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
        [w::STATION_REQUEST_HEAD, w::STATION_REPLY_HEAD],
        [
            ("PKW0", w::STATION_PKW0_REQUEST, w::STATION_PKW0_REPLY),
            ("PKW1", w::STATION_PKW1_REQUEST, w::STATION_PKW1_REPLY),
            ("PKW2", w::STATION_PKW2_REQUEST, w::STATION_PKW2_REPLY),
            ("PKW3", w::STATION_PKW3_REQUEST, w::STATION_PKW3_REPLY),
        ],
    );
    let commands = [
        (station::PkwCommand::Read, lang.t(w::STATION_READ)),
        (
            station::PkwCommand::WriteAndStore,
            lang.t(w::STATION_WRITE_STORE),
        ),
        (station::PkwCommand::Write, lang.t(w::STATION_WRITE)),
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
        lang.t(w::STATION_COMMANDS_CAPTION),
        &[
            lang.t(w::COMMAND),
            lang.t(w::MEANING),
            lang.t(w::REPLY_ON_ERROR),
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
    doc.para(text(lang.t(w::STATION_NO_ERROR_CODES)));
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
        w::read_parameter(lang, &name),
        sent(&|_| station::PkwAccess::Read),
        lang.t(w::STATION_DONE_VALUE),
        answered(&station::PkwReply::Value, 'v'),
    )];
    for (access, done, how) in [
        (
            &(|value| station::PkwAccess::WriteAndStore { value })
                as &dyn Fn(u16) -> station::PkwAccess,
            station::PkwReply::WrittenAndStored,
            lang.t(w::STORED_IN_EEPROM),
        ),
        (
            &(|value| station::PkwAccess::Write { value }) as &dyn Fn(u16) -> station::PkwAccess,
            station::PkwReply::Written,
            lang.t(w::NOT_STORED),
        ),
    ] {
        rows.push(example_row(
            w::write_vvvv_to(lang, &name, how),
            sent(access),
            lang.t(w::STATION_DONE_WRITE),
            answered(&|_| done, 'v'),
        ));
    }
    rows.push(example_row(
        w::read_parameter(lang, &name),
        sent(&|_| station::PkwAccess::Read),
        lang.t(w::FAILED),
        answered(
            &|error| station::PkwReply::Failed {
                command: station::PkwCommand::Read,
                error,
            },
            'x',
        ),
    ));
    examples_table(doc, lang, rows);
    doc.para(text(lang.t(w::STATION_LEGEND)));
}

// ---------------------------------------------------------------------------
// PROFIdrive

fn profidrive_channel(doc: &mut Builder, ir: &Ir, lang: Lang) {
    doc.para(text(lang.t(w::PROFIDRIVE_INTRO)));
    words_table(
        doc,
        lang,
        [w::PROFIDRIVE_REQUEST_HEAD, w::PROFIDRIVE_RESPONSE_HEAD],
        [
            ("PKE", w::PROFIDRIVE_PKE_REQUEST, w::PROFIDRIVE_PKE_RESPONSE),
            ("IND", w::PROFIDRIVE_IND, w::PROFIDRIVE_IND),
            ("PWE1", w::PROFIDRIVE_PWE1, w::PROFIDRIVE_PWE1),
            (
                "PWE2",
                w::PROFIDRIVE_PWE2_REQUEST,
                w::PROFIDRIVE_PWE2_RESPONSE,
            ),
        ],
    );
    let id_row = |id: u8, meanings: &[Phrase]| {
        vec![
            text(id.to_string()),
            text(lang.t(meanings[usize::from(id)])),
        ]
    };
    doc.table(
        lang.t(w::REQUEST_IDS_CAPTION),
        &[lang.t(w::ID), lang.t(w::MEANING)],
        sample_requests()
            .iter()
            .map(|r| id_row(r.id(), &REQUESTS))
            .collect(),
    );
    doc.table(
        lang.t(w::RESPONSE_IDS_CAPTION),
        &[lang.t(w::ID), lang.t(w::MEANING)],
        sample_responses()
            .iter()
            .map(|r| id_row(r.id(), &RESPONSES))
            .collect(),
    );
    doc.para(text(lang.t(w::PROFIDRIVE_REFUSED)));
    doc.table(
        lang.t(w::ERROR_NUMBERS_CAPTION),
        &[lang.t(w::NUMBER), lang.t(w::MEANING)],
        PROFILE_ERRORS
            .iter()
            .map(|(number, meaning)| vec![text(number.0.to_string()), text(lang.t(*meaning))])
            .collect(),
    );
    doc.para(text(lang.t(w::OTHER_NUMBERS)));
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
    let change = w::change_to_word(lang, &name);
    let rows = vec![
        example_row(
            w::read_parameter(lang, &name),
            read.clone(),
            lang.t(w::WORD_PARAMETER_VALUE),
            word_value.clone(),
        ),
        example_row(
            w::read_parameter(lang, &name),
            read,
            lang.t(w::DOUBLE_WORD_PARAMETER_VALUE),
            double_value.clone(),
        ),
        example_row(
            change.clone(),
            write_word.clone(),
            lang.t(w::DONE_VALUE_WRITTEN),
            word_value,
        ),
        example_row(
            w::change_to_double_word(lang, &name),
            shown(
                &|value, parameter| Q::WriteDoubleWord { parameter, value }.encode(),
                false,
            ),
            lang.t(w::DONE_VALUE_WRITTEN),
            double_value,
        ),
        example_row(
            w::read_element(lang, &name),
            shown(&|_, parameter| Q::ReadArray { parameter }.encode(), true),
            lang.t(w::ELEMENT_VALUE),
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
            lang.t(w::CANNOT_EXECUTE_XXXX),
            telegram(
                failed(profidrive::PkwErrorNumber(0)),
                &[('x', failed(profidrive::PkwErrorNumber(u16::MAX)))],
            ),
        ),
        example_row(
            change,
            write_word,
            lang.t(codes::NO_MASTER_CONTROL),
            telegram(R::NoAuthority { parameter: p }.encode(), &[]),
        ),
        example_row(
            lang.t(codes::REQUEST_NONE).to_string(),
            telegram(Q::None.encode(), &[]),
            lang.t(codes::RESPONSE_NONE),
            telegram(R::None.encode(), &[]),
        ),
    ];
    examples_table(doc, lang, rows);
    doc.para(text(lang.t(w::PROFIDRIVE_LEGEND)));
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
        let (address, why) = example_parameter(&md810, Lang::of("en")).unwrap();
        assert_eq!(
            (address, why.as_str()),
            (0xF000, "the default of PZD1(master->slaver)")
        );
        let mv810 = ir(
            "mv810-pnet02.toml",
            include_str!("../../../descriptions/mv810-pnet02.toml"),
        );
        let (address, why) = example_parameter(&mv810, Lang::of("en")).unwrap();
        assert_eq!(
            (address, why.as_str()),
            (0x2B02, "the parameter that sets PZD2 receive")
        );
        // A setting's timeout of 100 ms is a value, not the parameter at
        // address 100: the example stays P43.02.
        let with_timeout = crate::testing::mv810_with_timeout();
        let (address, _) = example_parameter(&with_timeout, Lang::of("en")).unwrap();
        assert_eq!(address, 0x2B02);
    }
}
