//! PROVISIONAL, until the layouts carry their device tables ([device-tables]
//! on branch `model`): each card's table put together from the constants the
//! layouts have today. The GSDML module IDs and the DAP's submodule subslots
//! and idents are typed here because no layout has them yet.

use crate::card::{Card, Module, Record, Submodule};
use wire_firmware::layouts::{md810dp, mv810_pnet02, profidrive};
use wire_firmware::manuals;
use wire_firmware::pkw::PkwKind;

pub fn names() -> Vec<&'static str> {
    vec!["mv810-pnet02", "md810dp", "profidrive"]
}

pub fn card(name: &str) -> Option<Card> {
    match name {
        "mv810-pnet02" => Some(mv810()),
        "md810dp" => Some(md810()),
        "profidrive" => Some(x2()),
        _ => None,
    }
}

fn sub(subslot: u16, ident: u32, api: u32, input_len: usize, output_len: usize) -> Submodule {
    Submodule {
        subslot,
        ident,
        api,
        input_len: input_len as u16,
        output_len: output_len as u16,
    }
}

/// The access point: its own submodule (subslot 1, the DAP's ident), the
/// interface and the ports (each its subslot as ident, gsdc's numbering).
fn dap(ident: u32, interface: u16, first_port: u16, ports: u8) -> Vec<Submodule> {
    let mut subs = vec![sub(1, ident, 0, 0, 0), sub(interface, interface.into(), 0, 0, 0)];
    for port in 0..u16::from(ports) {
        let subslot = first_port + port;
        subs.push(sub(subslot, subslot.into(), 0, 0, 0));
    }
    subs
}

fn data_module(gsdml_id: &'static str, ident: u32, slots: &'static [u16], len: (usize, usize), records: Vec<Record>, pkw: bool) -> Module {
    Module {
        gsdml_id,
        ident,
        slots,
        submodules: vec![sub(1, ident, 0, len.0, len.1)],
        records,
        pkw,
    }
}

fn words<const N: usize>(r: Result<[u16; N], impl core::fmt::Debug>) -> Result<Vec<u16>, String> {
    r.map(|v| v.to_vec()).map_err(|e| format!("{e:?}"))
}

fn mv810() -> Card {
    use mv810_pnet02 as l;
    const SLOT: &[u16] = &[l::MODULE_SLOT];
    let records = |n: usize| {
        let mut r = vec![Record { subslot: 1, index: l::settings::RECORD_INDEX, name: "settings", decode: |b| words(l::settings::decode_record(b)), mappings: &l::settings::MAPPINGS }];
        if n > 1 {
            r.push(Record { subslot: 1, index: l::pzd_out::RECORD_INDEX, name: "pzd_out", decode: |b| words(l::pzd_out::decode_record(b)), mappings: &l::pzd_out::MAPPINGS });
            r.push(Record { subslot: 1, index: l::pzd_in::RECORD_INDEX, name: "pzd_in", decode: |b| words(l::pzd_in::decode_record(b)), mappings: &l::pzd_in::MAPPINGS });
        }
        r
    };
    let pkw = |id, ident, n: usize| data_module(id, ident, SLOT, (8 + 2 * n, 8 + 2 * n), records(n), true);
    Card {
        name: "mv810-pnet02",
        vendor_id: l::PROFINET_VENDOR_ID,
        device_id: l::PROFINET_DEVICE_ID,
        dap_ident: l::DAP_IDENT,
        dap_submodules: dap(l::DAP_IDENT, l::INTERFACE_SUBSLOT, l::FIRST_PORT_SUBSLOT, l::PORTS),
        modules: vec![
            data_module("IDM_STD_TEL_1", l::TELEGRAM1_IDENT, SLOT, (l::Telegram1In::LEN, l::Telegram1Out::LEN), vec![Record { subslot: 1, index: l::settings::RECORD_INDEX, name: "settings", decode: |b| words(l::settings::decode_record(b)), mappings: &l::settings::MAPPINGS }], false),
            pkw("IDM_PKW_1", l::PKW_PZD1_IDENT, 1),
            pkw("IDM_PKW_2", l::PKW_PZD2_IDENT, 2),
            pkw("IDM_PKW_3", l::PKW_PZD3_IDENT, 3),
            pkw("IDM_PKW_4", l::PKW_PZD4_IDENT, 4),
            pkw("IDM_PKW_5", l::PKW_PZD5_IDENT, 5),
            pkw("IDM_PKW_6", l::PKW_PZD6_IDENT, 6),
            pkw("IDM_PKW_7", l::PKW_PZD7_IDENT, 7),
            pkw("IDM_PKW_8", l::PKW_PZD8_IDENT, 8),
            pkw("IDM_PKW_9", l::PKW_PZD9_IDENT, 9),
            pkw("IDM_PKW_10", l::PKW_PZD10_IDENT, 10),
            pkw("IDM_PKW_11", l::PKW_PZD11_IDENT, 11),
            pkw("IDM_PKW_12", l::PKW_PZD12_IDENT, 12),
        ],
        pkw: Some(PkwKind::StationCommand),
        status_of: Some(mv810_status),
        drive: manuals::for_description("mv810-pnet02"),
    }
}

fn md810() -> Card {
    use md810dp as l;
    const SLOT: &[u16] = &[l::MODULE_SLOT];
    let records = || {
        vec![
            Record { subslot: 1, index: l::pzd_out::RECORD_INDEX, name: "pzd_out", decode: |b| words(l::pzd_out::decode_record(b)), mappings: &l::pzd_out::MAPPINGS },
            Record { subslot: 1, index: l::pzd_in::RECORD_INDEX, name: "pzd_in", decode: |b| words(l::pzd_in::decode_record(b)), mappings: &l::pzd_in::MAPPINGS },
            Record { subslot: 1, index: l::dpv1_index::RECORD_INDEX, name: "dpv1_index", decode: |b| words(l::dpv1_index::decode_record(b)), mappings: &l::dpv1_index::MAPPINGS },
        ]
    };
    let module = |id, ident, pkw: usize, n: usize| data_module(id, ident, SLOT, (pkw + 2 * n, pkw + 2 * n), records(), pkw > 0);
    Card {
        name: "md810dp",
        vendor_id: l::PROFINET_VENDOR_ID,
        device_id: l::PROFINET_DEVICE_ID,
        dap_ident: l::DAP_IDENT,
        dap_submodules: dap(l::DAP_IDENT, l::INTERFACE_SUBSLOT, l::FIRST_PORT_SUBSLOT, l::PORTS),
        modules: vec![
            module("IDM_PKW_2", l::PKW_PZD2_IDENT, 8, 2),
            module("IDM_PKW_6", l::PKW_PZD6_IDENT, 8, 6),
            module("IDM_PKW_12", l::PKW_PZD12_IDENT, 8, 12),
            module("IDM_PZD_2", l::PZD2_IDENT, 0, 2),
            module("IDM_PZD_6", l::PZD6_IDENT, 0, 6),
            module("IDM_PZD_12", l::PZD12_IDENT, 0, 12),
        ],
        pkw: Some(PkwKind::PkeIndPwe),
        status_of: None,
        drive: manuals::for_description("md810dp"),
    }
}

fn x2() -> Card {
    use profidrive as l;
    const SLOT: &[u16] = &[l::MODULE_SLOT];
    Card {
        name: "profidrive",
        vendor_id: l::PROFINET_VENDOR_ID,
        device_id: l::PROFINET_DEVICE_ID,
        dap_ident: l::DAP_IDENT,
        dap_submodules: dap(l::DAP_IDENT, l::INTERFACE_SUBSLOT, l::FIRST_PORT_SUBSLOT, l::PORTS),
        modules: vec![
            Module {
                gsdml_id: "IDM_STD_TEL_1",
                ident: l::TELEGRAM1_IDENT,
                slots: SLOT,
                submodules: vec![
                    sub(l::TELEGRAM1_ACCESS_POINT_SUBSLOT, l::TELEGRAM1_ACCESS_POINT_IDENT, l::TELEGRAM1_API, 0, 0),
                    sub(l::TELEGRAM1_DATA_SUBSLOT, l::TELEGRAM1_IDENT, l::TELEGRAM1_API, l::Telegram1In::LEN, l::Telegram1Out::LEN),
                ],
                records: vec![],
                pkw: false,
            },
            data_module("IDM_PZD_1", l::PZD1_IDENT, SLOT, (l::Pzd1In::LEN, l::Pzd1Out::LEN), vec![Record { subslot: 1, index: l::settings::RECORD_INDEX, name: "settings", decode: |b| words(l::settings::decode_record(b)), mappings: &l::settings::MAPPINGS }], false),
        ],
        pkw: None,
        status_of: None,
        drive: manuals::for_description("profidrive"),
    }
}

/// MV810's drive answering its control word (section 3's bits, by the
/// layout's names): it runs forward or reverse while asked to and not asked
/// to stop, and reports stop otherwise; it is always ready. How the drive
/// reacts is this model's own: the manual gives the bits, not the drive's
/// timing.
fn mv810_status(control: u16) -> u16 {
    use mv810_pnet02::{control_word as c, status_word as s};
    let stopping = [c::DECELERATE_TO_STOP, c::COAST_TO_STOP, c::EMERGENCY_STOP]
        .iter()
        .any(|bit| bit.is_set(control));
    let forward = c::FORWARD_RUNNING.is_set(control) && !stopping;
    let reverse = c::REVERSE_RUNNING.is_set(control) && !stopping && !forward;
    let mut status = s::READY_STATUS.with(0, 1);
    status = s::FORWARD_RUNNING.with(status, forward.into());
    status = s::REVERSE_RUNNING.with(status, reverse.into());
    s::STOP.with(status, (!forward && !reverse).into())
}
