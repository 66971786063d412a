//! One simulated PROFIBUS segment: profirust's DP master and the slave
//! station, on profirust's simulated bus with its FDL timing. Time is the
//! bus's own, advanced a microsecond at a time: the run is deterministic and
//! takes a few milliseconds of wall time.

use profirust::dp::{
    DpMaster, Peripheral, PeripheralDiagnostics, PeripheralEvent, PeripheralHandle,
    PeripheralOptions,
};
use profirust::fdl::{FdlActiveStation, ParametersBuilder};
use profirust::phy::SimulatorPhy;
use profirust::time::{Duration, Instant};
use profirust::Baudrate;

use crate::slave::DpSlave;
use crate::station::SlaveStation;

/// The master's station address; the slave's is the description's choice
/// of the test (see [`crate::exchange`]).
pub const MASTER_ADDRESS: u8 = 2;

/// How long the bus may run before a step is given up: the master finds
/// the slave, parameterizes and configures it in a few milliseconds.
const TIMEOUT: Duration = Duration::from_millis(500);

/// What the master is told of the slave: all of it from the GSD.
pub struct MasterConfig<'a> {
    pub ident_number: u16,
    /// MaxTsdr at the bus's baud rate, in bit times.
    pub max_tsdr: u16,
    pub fail_safe: bool,
    pub user_prm: &'a [u8],
    pub config: &'a [u8],
    pub input_len: usize,
    pub output_len: usize,
    /// Max_Diag_Data_Len: the diagnosis buffer.
    pub max_diag_len: usize,
}

/// The master and the slave on one bus.
pub struct Bus<'a> {
    now: Instant,
    master_phy: SimulatorPhy,
    fdl: FdlActiveStation,
    dp: DpMaster<'a>,
    handle: PeripheralHandle,
    pub station: SlaveStation,
}

/// How a step of the bus ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    Event(PeripheralEvent),
    TimedOut,
}

impl<'a> Bus<'a> {
    /// The master with the slave configured as `config` says, the `slave`
    /// at its address, at `baudrate`.
    pub fn new(config: &MasterConfig<'a>, slave: DpSlave, baudrate: Baudrate) -> Self {
        let master_phy = SimulatorPhy::new(baudrate, "master");
        let station_phy = master_phy.duplicate("slave");
        let options = PeripheralOptions {
            ident_number: config.ident_number,
            max_tsdr: config.max_tsdr,
            fail_safe: config.fail_safe,
            user_parameters: Some(config.user_prm),
            config: Some(config.config),
            ..Default::default()
        };
        let peripheral = Peripheral::new(
            slave.address,
            options,
            vec![0; config.input_len],
            vec![0; config.output_len],
        )
        .with_diag_buffer(vec![0; config.max_diag_len]);
        let mut dp = DpMaster::new(Vec::new());
        let handle = dp.add(peripheral);
        dp.enter_operate();
        // The slot time covers the slave's MaxTsdr; the highest station
        // address takes the slave in, so the master's gap poll asks it for
        // its FDL status too.
        let slot_bits = config.max_tsdr + 15;
        let mut parameters = ParametersBuilder::new(MASTER_ADDRESS, baudrate);
        parameters.highest_station_address(slave.address + 1);
        if slot_bits > parameters.build().slot_bits {
            parameters.slot_bits(slot_bits);
        }
        let mut fdl = FdlActiveStation::new(parameters.build_verified(&dp));
        fdl.set_online();
        Bus {
            now: Instant::ZERO,
            master_phy,
            fdl,
            dp,
            handle,
            station: SlaveStation::new(slave, station_phy, baudrate),
        }
    }

    /// Runs the bus until the master reports an event of the slave.
    pub fn next_event(&mut self) -> Outcome {
        let deadline = self.now + TIMEOUT;
        while self.now < deadline {
            self.now += Duration::from_micros(1);
            self.master_phy.set_bus_time(self.now);
            self.fdl.poll(self.now, &mut self.master_phy, &mut self.dp);
            self.station.poll(self.now);
            if let Some((_, event)) = self.dp.take_last_events().peripheral {
                return Outcome::Event(event);
            }
        }
        Outcome::TimedOut
    }

    /// Runs the bus until the master reports `wanted`, or another event
    /// that ends the start-up (a fault, the slave gone).
    pub fn until(&mut self, wanted: PeripheralEvent) -> Outcome {
        loop {
            match self.next_event() {
                Outcome::Event(event) if event == wanted => return Outcome::Event(event),
                Outcome::Event(
                    PeripheralEvent::Online
                    | PeripheralEvent::Configured
                    | PeripheralEvent::DataExchanged,
                ) => continue,
                other => return other,
            }
        }
    }

    /// Sends `outputs` in the next Data_Exchange and returns the inputs the
    /// slave answered it with. The outputs are set as the master receives
    /// an answer, so the next request carries them.
    pub fn exchange(&mut self, outputs: &[u8]) -> Result<Vec<u8>, Outcome> {
        self.peripheral().pi_q_mut().copy_from_slice(outputs);
        match self.until(PeripheralEvent::DataExchanged) {
            Outcome::Event(PeripheralEvent::DataExchanged) => Ok(self.peripheral().pi_i().to_vec()),
            other => Err(other),
        }
    }

    /// Bytes of output the master sends the slave.
    pub fn output_len(&mut self) -> usize {
        self.peripheral().pi_q().len()
    }

    /// The last diagnosis the master read of the slave.
    pub fn diagnostics(&mut self) -> Option<PeripheralDiagnostics<'_>> {
        self.dp.get_mut(self.handle).last_diagnostics()
    }

    /// The bus time since the start.
    pub fn elapsed(&self) -> Duration {
        self.now - Instant::ZERO
    }

    fn peripheral(&mut self) -> &mut Peripheral<'a> {
        self.dp.get_mut(self.handle)
    }
}
