//! The DP exchange of one description: the master, configured only from the
//! GSD, starts the slave built from the layout with every module the GSD
//! offers, with User_Prm_Data at its defaults and with every parameter set
//! by name to another value; it runs the manuals' exchanges
//! ([`crate::manuals`]); and it makes the three mistakes a master must see
//! refused (another ident number, User_Prm_Data a byte short, a module the
//! slave does not have). Each exchange prints what crossed the bus, and
//! each failure the module, the byte offset and both values.

use std::path::PathBuf;
use std::process::Command;

use gsd_parser::Module;
use profirust::dp::{DiagnosticFlags, PeripheralEvent};
use profirust::Baudrate;
use wire_firmware::card::{Card, NodeEvent};

use crate::bus::{Bus, MasterConfig, Outcome};
use crate::gsd::{data_lengths, Gsd};
use crate::manuals::{self, DriveEvent, Step};
use crate::report::{byte, failed, first_difference, hex, words};
use crate::slave::{DpSlave, State};

/// The slave's station address: MD810 1.7 reads "3 号变频器", the drive at
/// address 3.
pub const SLAVE_ADDRESS: u8 = 3;

/// Data_Exchange cycles each start-up runs.
const CYCLES: usize = 5;

/// What the exchange is run with.
pub struct Target {
    /// The description, for `gsdc decode`.
    pub description: PathBuf,
    /// Its name in the firmware's registry.
    pub name: String,
    pub card: &'static Card,
    pub gsd: Gsd,
    /// The gsdc binary, which names the diagnosis the master read.
    pub gsdc: Option<PathBuf>,
}

/// The tally of a description's exchange.
#[derive(Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct Tally {
    pub passed: usize,
    pub failed: usize,
}

/// One start-up of the slave: the modules plugged and what Set_Prm and
/// Chk_Cfg carry.
#[derive(Clone, Debug)]
pub struct Startup {
    title: String,
    /// The GSD's names of the modules plugged, in the order of the config.
    modules: Vec<String>,
    ident_number: u16,
    user_prm: Vec<u8>,
    config: Vec<u8>,
}

impl Target {
    /// Runs every exchange, printing each; the tally of them.
    pub fn run(&self) -> Tally {
        let mut tally = Tally::default();
        let Some(baudrate) = self.baudrate() else {
            println!(
                "  FAILED: {} supports none of the baud rates the simulated bus runs (9.6 kbit/s to 1.5 Mbit/s)",
                self.gsd.file_name
            );
            tally.failed += 1;
            return tally;
        };
        println!(
            "  bus: {} bit/s, master {}, slave {SLAVE_ADDRESS}, MaxTsdr {} bit times (the GSD's)",
            baudrate.to_rate(),
            crate::bus::MASTER_ADDRESS,
            self.max_tsdr(baudrate)
        );
        let mut record = |passed: bool| {
            if passed {
                tally.passed += 1;
            } else {
                tally.failed += 1;
            }
        };
        let base = if let Some((names, exchanges)) = manuals::gateway(&self.name) {
            for passed in self.gateway(names, exchanges, baudrate) {
                record(passed);
            }
            self.gateway_base(names)
        } else {
            for module in self.exchanged_modules() {
                record(self.every_parameter(module, baudrate, false));
                record(self.every_parameter(module, baudrate, true));
            }
            let first: Vec<&Module> = self.exchanged_modules().take(1).collect();
            self.startup(String::new(), &first, &[])
        };
        for exchange in manuals::exchanges(&self.name) {
            record(self.manual(exchange, baudrate));
        }
        match base {
            Ok(base) => self
                .mistakes(&base, baudrate)
                .into_iter()
                .for_each(&mut record),
            Err(why) => record(failed(&why)),
        }
        tally
    }

    /// A start-up with `module`, every parameter at its default or set by
    /// name to another value, and [`CYCLES`] Data_Exchange cycles.
    fn every_parameter(&self, module: &Module, baudrate: Baudrate, others: bool) -> bool {
        let values: Vec<(String, i64)> = if others {
            self.gsd
                .parameters()
                .enumerate()
                .filter_map(|(i, p)| p.other_value(i).map(|v| (p.name.to_string(), v)))
                .collect()
        } else {
            Vec::new()
        };
        let title = if others {
            format!(
                "{}, every parameter set by name to another value",
                module.name
            )
        } else {
            format!("{}, every parameter at its default", module.name)
        };
        let startup = match self.startup(title, &[module], &values) {
            Ok(startup) => startup,
            Err(why) => return failed(&why),
        };
        let Some(mut bus) = self.configure(&startup, baudrate) else {
            return false;
        };
        let mut passed = self.check_prm(&bus, &startup, &values);
        let (_, output_len) = data_lengths(&startup.config).unwrap_or_default();
        // PZD-sized test words, numbered: this test's own values.
        let outputs: Vec<u8> = (0..output_len)
            .map(|i| (i / 2 + 1) as u8 * (i % 2) as u8)
            .collect();
        for cycle in 0..CYCLES {
            match bus.exchange(&outputs) {
                Ok(inputs) if cycle == 0 => print_telegrams(&outputs, &inputs),
                Ok(_) => {}
                Err(outcome) => {
                    passed &= failed(&format!("Data_Exchange cycle {}: {outcome:?}", cycle + 1))
                }
            }
        }
        if passed {
            println!(
                "    ok: {CYCLES} Data_Exchange cycles (bus time {} ms)",
                bus.elapsed().total_millis()
            );
        }
        passed
    }

    /// One of the manual's exchanges.
    fn manual(&self, exchange: &manuals::Exchange, baudrate: Baudrate) -> bool {
        let Some(module) = self.gsd.modules().find(|m| m.name == exchange.module) else {
            return failed(&format!(
                "{}: the GSD has no module {:?}",
                exchange.title, exchange.module
            ));
        };
        let values: Vec<(String, i64)> = exchange
            .prm
            .iter()
            .map(|(name, value)| (name.to_string(), *value))
            .collect();
        let startup = match self.startup(exchange.title.to_string(), &[module], &values) {
            Ok(startup) => startup,
            Err(why) => return failed(&why),
        };
        let Some(mut bus) = self.configure(&startup, baudrate) else {
            return false;
        };
        let mut passed = self.check_prm(&bus, &startup, &values);
        for step in exchange.steps {
            passed &= self.step(&mut bus, &startup, step);
        }
        passed
    }

    /// One step of a manual's exchange.
    pub fn step(&self, bus: &mut Bus, startup: &Startup, step: &Step) -> bool {
        match step {
            Step::Telegram { what, out, expect } => telegram(bus, startup, what, out, expect),
            Step::Diagnosis {
                what,
                event,
                block,
                text,
                decoded,
            } => {
                println!("    {what}");
                self.diagnosis(bus, *event, block, text, decoded)
            }
        }
    }

    /// The three mistakes, each made to `base`, a start-up the slave takes:
    /// each must end the start-up as a real master reports it.
    fn mistakes(&self, base: &Startup, baudrate: Baudrate) -> Vec<bool> {
        let ident = base.ident_number.wrapping_add(1);
        let other_ident = Startup {
            title: format!("refused: another ident number, 0x{ident:04X}"),
            ident_number: ident,
            ..base.clone()
        };
        let mut short = base.clone();
        short.title = "refused: User_Prm_Data one byte short".into();
        short.user_prm.pop();
        let missing = self.missing_module(&base.config);
        let no_such_module = Startup {
            title: format!(
                "refused: a module the slave does not have, config {}",
                hex(&missing)
            ),
            config: missing,
            modules: Vec::new(),
            ..base.clone()
        };
        vec![
            self.refused(&other_ident, baudrate, PeripheralEvent::ParameterError),
            self.refused(&short, baudrate, PeripheralEvent::ParameterError),
            self.refused(&no_such_module, baudrate, PeripheralEvent::ConfigError),
        ]
    }

    /// `config` with its first general identifier a few units longer or
    /// shorter, so that it is a byte no module of the GSD has.
    fn missing_module(&self, config: &[u8]) -> Vec<u8> {
        let offered: Vec<u8> = self.gsd.modules().flat_map(|m| m.config.clone()).collect();
        let general = config.iter().position(|b| b >> 4 & 0b11 != 0).unwrap_or(0);
        let mut changed = config.to_vec();
        for step in [1i16, -1, 2, -2, 3, -3] {
            let length = (i16::from(config[general] & 0x0F) + step).clamp(0, 15) as u8;
            changed[general] = config[general] & 0xF0 | length;
            if !offered.contains(&changed[general]) {
                break;
            }
        }
        changed
    }

    /// Runs `startup`, which the slave must refuse with `expected`.
    fn refused(&self, startup: &Startup, baudrate: Baudrate, expected: PeripheralEvent) -> bool {
        self.print_startup(startup);
        let Ok(config) = self.master_config(startup, baudrate) else {
            return failed("the config bytes do not say their lengths");
        };
        let mut bus = Bus::new(&config, self.slave(), baudrate);
        let outcome = bus.until(PeripheralEvent::Configured);
        if outcome != Outcome::Event(expected) {
            return failed(&format!("the master reports {outcome:?}, not {expected:?}"));
        }
        let Some(diagnostics) = bus.diagnostics() else {
            return failed("the master read no diagnosis");
        };
        let flag = match expected {
            PeripheralEvent::ParameterError => DiagnosticFlags::PARAMETER_FAULT,
            _ => DiagnosticFlags::CONFIGURATION_FAULT,
        };
        if !diagnostics.flags.contains(flag) {
            return failed(&format!(
                "Slave_Diag's flags {:?} lack {flag:?}",
                diagnostics.flags
            ));
        }
        let ident = diagnostics.ident_number;
        if ident != self.gsd.ident_number() {
            return failed(&format!(
                "Slave_Diag: the slave reports ident 0x{ident:04X}, the GSD's is 0x{:04X}",
                self.gsd.ident_number()
            ));
        }
        println!(
            "    ok: the master reports {expected:?}; Slave_Diag: {:?}, the slave's ident 0x{ident:04X}",
            diagnostics.flags
        );
        true
    }

    /// The start-up of `modules` with the parameters `values` set by name.
    pub fn startup(
        &self,
        title: String,
        modules: &[&Module],
        values: &[(String, i64)],
    ) -> Result<Startup, String> {
        Ok(Startup {
            title,
            modules: modules.iter().map(|m| m.name.clone()).collect(),
            ident_number: self.gsd.ident_number(),
            user_prm: self.gsd.prm(values)?,
            config: modules
                .iter()
                .flat_map(|m| m.config.iter().copied())
                .collect(),
        })
    }

    /// Starts the slave; the bus with the slave in Data_Exch, or `None`
    /// (the failure printed).
    pub fn configure<'a>(&self, startup: &'a Startup, baudrate: Baudrate) -> Option<Bus<'a>> {
        self.print_startup(startup);
        if !self.same_modules(startup) {
            return None;
        }
        let config = match self.master_config(startup, baudrate) {
            Ok(config) => config,
            Err(why) => {
                failed(&why);
                return None;
            }
        };
        let mut bus = Bus::new(&config, self.slave(), baudrate);
        match bus.until(PeripheralEvent::Configured) {
            Outcome::Event(PeripheralEvent::Configured) => Some(bus),
            outcome => {
                let flags = bus.diagnostics().map(|d| d.flags);
                failed(&format!(
                    "the master reports {outcome:?} (Slave_Diag flags {flags:?})"
                ));
                None
            }
        }
    }

    /// Whether the layout has each module the GSD names, with the same
    /// config bytes; prints the byte offset and both values where not.
    /// The GSD's modules but PROFIsafe ones: their F-parameters follow
    /// User_Prm_Data, which only an F-host sends (the master's GSD reader,
    /// gsd-parser, reads no F_ keyword) and only an F-device's PROFIsafe
    /// layer reads; neither end is one.
    fn exchanged_modules(&self) -> impl Iterator<Item = &Module> {
        let layouts = self.card.dp.map_or(&[][..], |dp| dp.modules);
        self.gsd.modules().filter(|m| {
            layouts
                .iter()
                .find(|l| l.name == m.name)
                .is_none_or(|l| l.f_parameter_len == 0)
        })
    }

    fn same_modules(&self, startup: &Startup) -> bool {
        let modules = self.card.dp.map_or(&[][..], |dp| dp.modules);
        let mut offset = 0;
        for name in &startup.modules {
            let Some(layout) = modules.iter().find(|m| m.name == name.as_str()) else {
                return failed(&format!("the layout has no module {name:?}"));
            };
            let end = (offset + layout.config.len()).min(startup.config.len());
            let gsd = &startup.config[offset..end];
            if let Some((at, gsd, layout)) = first_difference(gsd, layout.config) {
                return failed(&format!(
                    "module {name:?}, config byte {at}: the GSD gives {}, the layout {}",
                    byte(gsd),
                    byte(layout)
                ));
            }
            offset = end;
        }
        true
    }

    /// The slave decoded every parameter as the master set it.
    pub fn check_prm(&self, bus: &Bus, startup: &Startup, values: &[(String, i64)]) -> bool {
        let slave = &bus.station.slave;
        if slave.state() != State::DataExchange {
            return failed(&format!("the slave is in {:?}", slave.state()));
        }
        let Some(decoded) = slave.prm() else {
            return failed("the slave holds no parameters");
        };
        let mut passed = true;
        let mut count = 0;
        for parameter in self.gsd.parameters() {
            count += 1;
            let set = values
                .iter()
                .find(|(name, _)| name == parameter.name)
                .map_or(parameter.default, |(_, v)| *v);
            match decoded.get(parameter.name) {
                Some(value) if i64::from(value) == set => {}
                Some(value) => {
                    passed &= failed(&format!(
                        "modules {:?}, User_Prm_Data byte {}: {:?} is {set} as the master set it, {value} as the slave decoded it",
                        startup.modules, parameter.offset, parameter.name
                    ))
                }
                None => {
                    passed &= failed(&format!(
                        "modules {:?}, User_Prm_Data byte {}: the layout has no parameter {:?}",
                        startup.modules, parameter.offset, parameter.name
                    ))
                }
            }
        }
        if passed {
            println!("    ok: Data_Exch; the slave decoded the {count} parameters as the master set them");
        }
        passed
    }

    /// The drive's side changes; the master must read the diagnosis the
    /// slave raises, the block `block`, named `text` by the GSD and by
    /// `gsdc decode`.
    fn diagnosis(
        &self,
        bus: &mut Bus,
        event: DriveEvent,
        block: &str,
        text: &str,
        decoded: &str,
    ) -> bool {
        let slave = &mut bus.station.slave;
        match event {
            DriveEvent::LinkLost => slave.drive.set_link_lost(true),
            DriveEvent::Fault(code) => slave.drive.set_fault(code),
            DriveEvent::Node { kind, node, code } => {
                slave.nodes.report(Some(NodeEvent { kind, node, code }))
            }
        }
        let outputs = vec![0; bus.output_len()];
        let read = (0..CYCLES)
            .any(|_| bus.exchange(&outputs) == Err(Outcome::Event(PeripheralEvent::Diagnostics)));
        if !read {
            return failed("the master read no diagnosis: the slave did not answer with DH");
        }
        let Some(diagnostics) = bus.diagnostics() else {
            return failed("the master holds no diagnosis");
        };
        let raw = diagnostics
            .extended_diagnostics
            .raw_diag_buffer()
            .unwrap_or(&[])
            .to_vec();
        let flags = diagnostics.flags;
        let expected = manuals::hex_bytes(block);
        println!(
            "      Slave_Diag  {flags:?}; device-related block {}",
            hex(&raw)
        );
        if !flags.contains(DiagnosticFlags::EXT_DIAG) {
            return failed("Slave_Diag does not say Ext_Diag");
        }
        if let Some((offset, want, got)) = first_difference(&expected, &raw) {
            return failed(&format!(
                "diagnosis byte {offset}: the manual gives {}, the slave sent {}",
                byte(want),
                byte(got)
            ));
        }
        let named = self.gsd.diagnosis_texts(&raw);
        println!("      the GSD     {}", named.join("; "));
        let mut passed = named.iter().any(|t| t.contains(&format!("{text:?}")))
            || failed(&format!("the GSD does not name it {text:?}"));
        if let Some(output) = self.gsdc_decode(&raw) {
            for line in output.lines().filter(|l| !l.is_empty()) {
                println!("      gsdc decode {line}");
            }
            passed &= output.contains(decoded)
                || failed(&format!("gsdc decode does not name it {decoded:?}"));
        }
        if passed {
            println!("    ok: the master read the manual's diagnosis");
        }
        passed
    }

    /// `gsdc decode DESCRIPTION --diag BLOCK`, when the gsdc binary is known.
    fn gsdc_decode(&self, block: &[u8]) -> Option<String> {
        let gsdc = self.gsdc.as_ref()?;
        let output = Command::new(gsdc)
            .arg("decode")
            .arg(&self.description)
            .args(["--diag", &hex(block)])
            .output();
        match output {
            Ok(output) if output.status.success() => {
                Some(String::from_utf8_lossy(&output.stdout).into_owned())
            }
            Ok(output) => Some(format!(
                "failed: {}",
                String::from_utf8_lossy(&output.stderr)
            )),
            Err(e) => Some(format!("failed: {}: {e}", gsdc.display())),
        }
    }

    /// The master's configuration for `startup`: all of it from the GSD.
    fn master_config<'a>(
        &self,
        startup: &'a Startup,
        baudrate: Baudrate,
    ) -> Result<MasterConfig<'a>, String> {
        let (input_len, output_len) = data_lengths(&startup.config)?;
        let gsd = &self.gsd.description;
        Ok(MasterConfig {
            ident_number: startup.ident_number,
            max_tsdr: self.max_tsdr(baudrate),
            fail_safe: gsd.fail_safe,
            user_prm: &startup.user_prm,
            config: &startup.config,
            input_len,
            output_len,
            max_diag_len: usize::from(gsd.max_diag_data_length).max(6),
        })
    }

    fn print_startup(&self, startup: &Startup) {
        println!("  {}", startup.title);
        println!(
            "    Set_Prm    ident 0x{:04X}, User_Prm_Data ({} bytes) {}",
            startup.ident_number,
            startup.user_prm.len(),
            hex(&startup.user_prm)
        );
        let names: Vec<String> = startup.modules.iter().map(|m| format!("{m:?}: ")).collect();
        println!(
            "    Chk_Cfg    {}{}",
            names.join("+ "),
            hex(&startup.config)
        );
    }

    /// A new slave of the card, its drive as the drive's manual has it.
    fn slave(&self) -> DpSlave {
        let drive = wire_firmware::manuals::drive(self.card);
        DpSlave::new(SLAVE_ADDRESS, self.card, drive)
    }

    /// 1.5 Mbit/s, or the fastest lower rate the GSD supports. The
    /// simulated bus keeps time in microseconds: above 1.5 Mbit/s a byte
    /// takes less than one.
    fn baudrate(&self) -> Option<Baudrate> {
        use gsd_parser::SupportedSpeeds as S;
        let speeds = self.gsd.description.supported_speeds;
        [
            (S::B1500000, Baudrate::B1500000),
            (S::B500000, Baudrate::B500000),
            (S::B187500, Baudrate::B187500),
            (S::B93750, Baudrate::B93750),
            (S::B45450, Baudrate::B45450),
            (S::B19200, Baudrate::B19200),
            (S::B9600, Baudrate::B9600),
        ]
        .into_iter()
        .find(|(speed, _)| speeds.contains(*speed))
        .map(|(_, rate)| rate)
    }

    /// The GSD's MaxTsdr at `baudrate`.
    fn max_tsdr(&self, baudrate: Baudrate) -> u16 {
        let t = &self.gsd.description.max_tsdr;
        match baudrate {
            Baudrate::B9600 => t.b9600,
            Baudrate::B19200 => t.b19200,
            Baudrate::B31250 => t.b31250,
            Baudrate::B45450 => t.b45450,
            Baudrate::B93750 => t.b93750,
            Baudrate::B187500 => t.b187500,
            Baudrate::B500000 => t.b500000,
            Baudrate::B1500000 => t.b1500000,
            Baudrate::B3000000 => t.b3000000,
            Baudrate::B6000000 => t.b6000000,
            Baudrate::B12000000 => t.b12000000,
        }
    }
}

/// Sends the manual's telegram `out` and compares the answer with `expect`.
fn telegram(bus: &mut Bus, startup: &Startup, what: &str, out: &str, expect: &str) -> bool {
    println!("    {what}");
    let outputs: Vec<u8> = manuals::hex_words(out)
        .into_iter()
        .map(|b| b.unwrap_or(0))
        .collect();
    let expected = manuals::hex_words(expect);
    let inputs = match bus.exchange(&outputs) {
        Ok(inputs) => inputs,
        Err(outcome) => return failed(&format!("Data_Exchange: {outcome:?}")),
    };
    print_telegrams(&outputs, &inputs);
    if inputs.len() != expected.len() {
        return failed(&format!(
            "modules {:?}: the slave answered {} bytes, the manual's telegram has {}",
            startup.modules,
            inputs.len(),
            expected.len()
        ));
    }
    let wrong = expected
        .iter()
        .zip(&inputs)
        .enumerate()
        .find(|(_, (want, got))| want.is_some_and(|w| w != **got));
    match wrong {
        Some((offset, (want, got))) => failed(&format!(
            "modules {:?}, byte {offset}: the manual gives {}, the slave sent {}",
            startup.modules,
            byte(*want),
            byte(Some(*got))
        )),
        None => {
            println!("    ok: as the manual answers");
            true
        }
    }
}

fn print_telegrams(outputs: &[u8], inputs: &[u8]) {
    println!("    Data_Exch  out {}", words(outputs));
    println!("               in  {}", words(inputs));
}
