//! pn-device: a PROFINET IO device built from a card's generated layout, on
//! pnio. It answers DCP Identify with the layout's identity, accepts the
//! Connect that matches the layout's module table (in the APIs the layout
//! gives), decodes the records the controller writes at startup with the
//! layout's decoders, and runs the drive model on the cyclic data.
//!
//!     pn-device --card mv810-pnet02 --iface pn0 --ip 192.0.2.2 \
//!               --plug "1=PKW + 12 PZD" [--station NAME] [--dap N] [--seconds 60]
//!
//! Its name of station is the layout's (`PN_DEVICE.dns_name`, the GSDML's
//! DNS_CompatibleName) unless `--station` gives another. In slot 0 it
//! presents the GSDML's first device access point, or with `--dap N` its
//! Nth (the layout's `daps`), and takes only modules that one offers, or
//! another of its ident number (which presents the same slot 0, so that the
//! device cannot tell them apart). Every event goes to
//! stdout as one JSON object a line, for the controller side of the wire
//! test (and a person) to read. Without `--seconds` it runs until SIGINT
//! (Ctrl-C) or SIGTERM, then stops its device loop, says so and exits 0.

mod connect;
mod drive;
mod events;
mod model;
mod tap;

use events::Events;
use model::{api_of, device_model, AccessPoint, Mismatch};
use pnio::dcp::{DcpConfig, DeviceProperties};
use pnio::device::{Device, DeviceSetup, RtOptions};
use pnio::eth::{bpf::acyclic_filter, AfPacketTransport, MacAddr};
use pnio::im::Im0;
use pnio::rpc::{UdpRpcTransport, Uuid, PNIO_UDP_PORT};
use std::net::{Ipv4Addr, SocketAddr};
use std::process::ExitCode;
use std::sync::atomic::{AtomicBool, AtomicI32, Ordering};
use std::sync::{mpsc, Arc};
use std::time::{Duration, Instant};
use tap::{Seen, Tap};
use wire_firmware::card::Card;
use wire_firmware::gsdc_support::{PnDevice, PnModule};

struct Args {
    card: String,
    iface: String,
    ip: Ipv4Addr,
    station: Option<String>,
    plug: Vec<(u16, String)>,
    /// The device access point it presents: its number in the GSDML.
    dap: usize,
    mismatch: Option<Mismatch>,
    seconds: Option<u64>,
}

const USAGE: &str = "usage: pn-device --card NAME --iface IF --ip A.B.C.D --plug SLOT=MODULE... \
[--station NAME] [--dap N] [--mismatch module-ident|input-length|api] [--seconds N]";

fn parse_args() -> Result<Args, String> {
    let mut args = std::env::args().skip(1);
    let (mut card, mut iface, mut ip, mut station) = (None, None, None, None);
    let (mut plug, mut mismatch, mut seconds) = (Vec::new(), None, None);
    let mut dap = 1;
    while let Some(flag) = args.next() {
        let mut value = || args.next().ok_or(format!("{flag} needs a value"));
        match flag.as_str() {
            "--card" => card = Some(value()?),
            "--iface" => iface = Some(value()?),
            "--ip" => ip = Some(value()?.parse().map_err(|e| format!("--ip: {e}"))?),
            "--station" => station = Some(value()?),
            "--plug" => {
                let v = value()?;
                let (slot, module) = v
                    .split_once('=')
                    .ok_or("--plug takes SLOT=MODULE (the module's GSDML name)")?;
                let slot = slot.parse().map_err(|e| format!("--plug slot: {e}"))?;
                plug.push((slot, module.to_string()));
            }
            "--mismatch" => {
                mismatch = Some(match value()?.as_str() {
                    "module-ident" => Mismatch::ModuleIdent,
                    "input-length" => Mismatch::InputLength,
                    "api" => Mismatch::Api,
                    other => return Err(format!("--mismatch {other}: not a kind")),
                })
            }
            "--dap" => dap = value()?.parse().map_err(|e| format!("--dap: {e}"))?,
            "--seconds" => seconds = Some(value()?.parse().map_err(|e| format!("--seconds: {e}"))?),
            other => return Err(format!("unknown argument {other}")),
        }
    }
    Ok(Args {
        card: need(card, "--card")?,
        iface: need(iface, "--iface")?,
        ip: need(ip, "--ip")?,
        station,
        plug,
        dap,
        mismatch,
        seconds,
    })
}

fn need<T>(value: Option<T>, flag: &str) -> Result<T, String> {
    value.ok_or(format!("{flag} is required"))
}

fn main() -> ExitCode {
    let args = match parse_args() {
        Ok(args) => args,
        Err(e) => {
            eprintln!("pn-device: {e}\n{USAGE}");
            return ExitCode::from(2);
        }
    };
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("pn-device: {e}");
            ExitCode::from(2)
        }
    }
}

fn run(args: &Args) -> Result<(), String> {
    let card = wire_firmware::card(&args.card).ok_or(format!(
        "the firmware has no card {:?} (build it with WIRE_DESCRIPTIONS naming the description); its cards: {}",
        args.card,
        wire_firmware::layouts::CARDS
            .iter()
            .map(|c| c.name)
            .collect::<Vec<_>>()
            .join(", ")
    ))?;
    let device = card
        .pn
        .ok_or(format!("{} has no PROFINET part", card.name))?;
    let dap = AccessPoint::of(device, args.dap).ok_or(format!(
        "{} has no device access point {} (it has {})",
        card.name,
        args.dap,
        device.daps.len()
    ))?;
    let plugged = plugged_modules(card, (device, &dap), &args.plug)?;
    let mac = mac_of(&args.iface)?;
    let events = Events::stdout();
    let station = args.station.as_deref().unwrap_or(device.dns_name);

    let model = device_model((device, &dap), station, mac, &plugged, args.mismatch);
    let setup = DeviceSetup {
        dcp: DcpConfig {
            mac,
            properties: dcp_identity(card, device, station, args.ip.octets()),
        },
        model,
        activity_seed: activity_seed(mac),
        rt: Some(RtOptions {
            iface: args.iface.clone(),
            cpu_pin: None,
            rt_priority: None,
            lock_memory: false,
        }),
        im0: Im0::default(),
        im_store: None,
    };
    let eth = AfPacketTransport::open(&args.iface).map_err(|e| format!("{}: {e}", args.iface))?;
    eth.attach_filter(&acyclic_filter())
        .map_err(|e| format!("{}: {e}", args.iface))?;
    let udp = UdpRpcTransport::bind(SocketAddr::from(([0, 0, 0, 0], PNIO_UDP_PORT)))
        .map_err(|e| format!("UDP port {PNIO_UDP_PORT}: {e}"))?;
    let (seen_tx, seen) = mpsc::channel();
    let mismatch = args.mismatch;
    let apis = {
        let plugged = plugged.clone();
        move |slot, subslot| api_of((device, &dap), &plugged, mismatch, slot, subslot)
    };
    let mut device = Device::new(setup, eth, Tap::new(udp, seen_tx, apis));
    {
        let events = events.clone();
        device.on_state_change(move |state, why| events.ar_state(state, why));
    }
    let image = device.image();
    stop_on_signals();
    let stop = Arc::new(AtomicBool::new(false));
    let acyclic = {
        let stop = stop.clone();
        std::thread::spawn(move || device.run(&stop))
    };
    events.listening(&args.card, station, mac, args.ip, &plugged);

    let deadline = args
        .seconds
        .map(|s| Instant::now() + Duration::from_secs(s));
    let mut application = drive::Application::new(card, dap.dap.ident, &plugged);
    while deadline.is_none_or(|d| Instant::now() < d)
        && !acyclic.is_finished()
        && SIGNALLED.load(Ordering::Relaxed) == 0
    {
        while let Ok(seen) = seen.try_recv() {
            report(&events, &mut application, seen);
        }
        for read in application.cycle(&image) {
            events.double_word(&read);
        }
        std::thread::sleep(Duration::from_millis(1));
    }
    stop.store(true, Ordering::Relaxed);
    let result = match acyclic.join() {
        Ok(Ok(())) => Ok(()),
        Ok(Err(e)) => Err(format!("device loop: {e}")),
        Err(_) => Err("device loop panicked".into()),
    };
    if result.is_ok() {
        events.stopped(SIGNALLED.load(Ordering::Relaxed));
    }
    result
}

/// The signal that asked the device to stop (SIGINT, SIGTERM), 0 until one
/// does.
static SIGNALLED: AtomicI32 = AtomicI32::new(0);

extern "C" fn on_signal(signal: libc::c_int) {
    // Only an atomic store: all a signal handler may safely do.
    SIGNALLED.store(signal, Ordering::Relaxed);
}

/// SIGINT (Ctrl-C) and SIGTERM stop the device as the end of `--seconds`
/// does: the main loop sees the signal, stops the device loop and returns.
fn stop_on_signals() {
    let handler = on_signal as extern "C" fn(libc::c_int) as libc::sighandler_t;
    for signal in [libc::SIGINT, libc::SIGTERM] {
        // SAFETY: the handler only stores to an atomic, which is
        // async-signal-safe, and lives as long as the process.
        unsafe {
            libc::signal(signal, handler);
        }
    }
}

/// The modules the arguments plug, each checked against the card's table
/// and the modules the device access point offers.
fn plugged_modules(
    card: &Card,
    (device, dap): (&'static PnDevice, &AccessPoint),
    plug: &[(u16, String)],
) -> Result<Vec<(u16, &'static PnModule)>, String> {
    plug.iter()
        .map(|(slot, name)| {
            let (place, module) = device
                .modules
                .iter()
                .enumerate()
                .find(|(_, m)| m.name == name)
                .ok_or(format!(
                    "{} has no module {name:?}; its modules: {}",
                    card.name,
                    device
                        .modules
                        .iter()
                        .map(|m| format!("{:?}", m.name))
                        .collect::<Vec<_>>()
                        .join(", ")
                ))?;
            // The device cannot tell its access point from another of its
            // ident number, and takes what any of them offers.
            if !device.offers(dap.dap.ident, place) {
                return Err(format!(
                    "device access point {} does not offer {name:?}, nor does another of ident number 0x{:08X}",
                    dap.number, dap.dap.ident
                ));
            }
            if !module.slots.contains(slot) {
                return Err(format!(
                    "{name:?} goes in slots {:?}, not {slot}",
                    module.slots
                ));
            }
            Ok((*slot, module))
        })
        .collect()
}

/// Each record a Write carried, decoded by the layout where the plugged
/// module has a record there, and what the device made of it.
fn report(events: &Events, application: &mut drive::Application, seen: Seen) {
    match seen {
        Seen::Records(records) => {
            for record in records
                .iter()
                .filter(|r| r.index != pnio::cm::INDEX_MULTIPLE_WRITE)
            {
                let decoded =
                    application.write(record.slot, record.subslot, record.index, &record.data);
                events.record(record, decoded.as_ref());
            }
        }
        Seen::ApiRefused(mismatch) => events.api_refused(&mismatch),
        Seen::MergedApis => events.merged_apis(),
    }
}

fn dcp_identity(card: &Card, device: &PnDevice, station: &str, ip: [u8; 4]) -> DeviceProperties {
    DeviceProperties {
        name_of_station: station.to_string(),
        type_of_station: card.name.to_string(),
        vendor_id: device.vendor_id,
        device_id: device.device_id,
        // pnio's values: an IO device, instance 1, its DCP options.
        device_role: 0x0100,
        device_instance: 1,
        device_options: vec![1, 2, 2, 2, 2, 3],
        ip,
        subnet: [255, 255, 255, 0],
        gateway: ip,
        ip_block_info: 1,
    }
}

/// pnio's activity UUID for the calls the device makes (ApplicationReady):
/// the prefix pnio's own configuration uses, then the MAC.
fn activity_seed(mac: MacAddr) -> Uuid {
    pnio::config::DeviceConfig::activity_seed(mac)
}

fn mac_of(iface: &str) -> Result<MacAddr, String> {
    let path = format!("/sys/class/net/{iface}/address");
    let text = std::fs::read_to_string(&path).map_err(|e| format!("{path}: {e}"))?;
    let mut mac = [0u8; 6];
    let parts: Vec<&str> = text.trim().split(':').collect();
    if parts.len() != 6 {
        return Err(format!("{path}: not a MAC address: {}", text.trim()));
    }
    for (byte, part) in mac.iter_mut().zip(parts) {
        *byte = u8::from_str_radix(part, 16).map_err(|e| format!("{path}: {e}"))?;
    }
    Ok(MacAddr(mac))
}
