//! The device's account of the exchange: one JSON object a line on stdout.

use crate::connect::ApiMismatch;
use crate::drive::{DoubleWord, Written};
use pnio::cm::{AbortReason, ArState, Record};
use pnio::eth::MacAddr;
use std::io::Write;
use std::net::Ipv4Addr;
use std::sync::{Arc, Mutex};
use wire_firmware::gsdc_support::PnModule;

#[derive(Clone)]
pub struct Events {
    out: Arc<Mutex<std::io::Stdout>>,
}

impl Events {
    pub fn stdout() -> Events {
        Events {
            out: Arc::new(Mutex::new(std::io::stdout())),
        }
    }

    fn emit(&self, json: String) {
        let mut out = self.out.lock().unwrap_or_else(|e| e.into_inner());
        let _ = writeln!(out, "{json}");
        let _ = out.flush();
    }

    pub fn listening(
        &self,
        card: &str,
        station: &str,
        mac: MacAddr,
        ip: Ipv4Addr,
        plugged: &[(u16, &PnModule)],
    ) {
        let modules: Vec<String> = plugged
            .iter()
            .map(|(slot, m)| {
                let subs: Vec<String> = m
                    .access_point
                    .iter()
                    .chain([&m.data])
                    .map(|s| {
                        format!(
                            r#"{{"subslot":{},"ident":{},"input_len":{},"output_len":{}}}"#,
                            s.subslot, s.ident, s.input_len, s.output_len
                        )
                    })
                    .collect();
                format!(
                    r#"{{"slot":{slot},"module":{},"ident":{},"api":{},"submodules":[{}]}}"#,
                    quote(m.name),
                    m.ident,
                    m.api,
                    subs.join(",")
                )
            })
            .collect();
        let m = mac.0;
        self.emit(format!(
            r#"{{"event":"listening","card":"{card}","station":"{station}","mac":"{:02x}:{:02x}:{:02x}:{:02x}:{:02x}:{:02x}","ip":"{ip}","plugged":[{}]}}"#,
            m[0], m[1], m[2], m[3], m[4], m[5],
            modules.join(",")
        ));
    }

    pub fn ar_state(&self, state: ArState, why: Option<AbortReason>) {
        let why = why.map_or("null".into(), |w| quote(&format!("{w:?}")));
        self.emit(format!(
            r#"{{"event":"ar","state":"{state:?}","reason":{why}}}"#
        ));
    }

    /// A written record, with what the layout's decoder made of it (or why it
    /// refused it, or that the layout has no record at that place), and the
    /// entries whose value the drive refused.
    pub fn record(&self, record: &Record, decoded: Option<&Result<Written, String>>) {
        let bytes: String = record.data.iter().map(|b| format!("{b:02x}")).collect();
        let decoded = match decoded {
            None => r#""layout":null"#.to_string(),
            Some(Ok(written)) => format!(
                r#""layout":[{}],"drive_refused":[{}]"#,
                written
                    .values
                    .iter()
                    .map(|(name, value)| format!(r#"{{"entry":{},"value":{value}}}"#, quote(name)))
                    .collect::<Vec<_>>()
                    .join(","),
                written
                    .refused
                    .iter()
                    .map(|n| quote(n))
                    .collect::<Vec<_>>()
                    .join(",")
            ),
            Some(Err(e)) => format!(r#""layout":"refused","refused":{}"#, quote(e)),
        };
        self.emit(format!(
            r#"{{"event":"record","api":{},"slot":{},"subslot":{},"index":{},"bytes":"{bytes}",{decoded}}}"#,
            record.api, record.slot, record.subslot, record.index
        ));
    }

    /// A 32-bit value of the controller's data as the layout read it
    /// (standard telegram 2's NSOLL_B), each time it changes.
    pub fn double_word(&self, d: &DoubleWord) {
        self.emit(format!(
            r#"{{"event":"double-word","slot":{},"subslot":{},"word":{},"value":{}}}"#,
            d.slot, d.subslot, d.word, d.value
        ));
    }

    pub fn api_refused(&self, m: &ApiMismatch) {
        self.emit(format!(
            r#"{{"event":"api-refused","slot":{},"subslot":{},"expected":{},"found":{}}}"#,
            m.slot, m.subslot, m.expected, m.found
        ));
    }

    /// The device stopped: at the end of `--seconds` (`signal` 0) or on a
    /// signal.
    pub fn stopped(&self, signal: i32) {
        let why = match signal {
            0 => "deadline".to_string(),
            libc::SIGINT => "SIGINT".to_string(),
            libc::SIGTERM => "SIGTERM".to_string(),
            other => format!("signal {other}"),
        };
        self.emit(format!(r#"{{"event":"stopped","by":"{why}"}}"#));
    }

    pub fn merged_apis(&self) {
        self.emit(r#"{"event":"merged-apis"}"#.to_string());
    }
}

/// `text` as a JSON string.
fn quote(text: &str) -> String {
    let mut out = String::from("\"");
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}
