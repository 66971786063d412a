//! The slave on profirust's simulated bus: it receives the telegrams the
//! bus carries, and sends the slave's answer once min_Tsdr has passed after
//! the request (the simulated bus refuses an answer sent sooner, and the
//! master stops waiting after its slot time). On a card this is the UART's
//! or the DP ASIC's part.

use profirust::fdl::{
    DataTelegramHeader, FunctionCode, ResponseState, ResponseStatus, Telegram, TelegramTx,
    TelegramTxResponse,
};
use profirust::phy::{ProfibusPhy, SimulatorPhy};
use profirust::time::{Duration, Instant};

use crate::slave::{DpSlave, Reply};

/// A slave attached to the simulated bus.
pub struct SlaveStation {
    pub slave: DpSlave,
    phy: SimulatorPhy,
    baudrate: profirust::Baudrate,
    /// The answer waiting for min_Tsdr, when it may go, and the station
    /// that asked.
    pending: Option<(Instant, u8, Reply)>,
}

impl SlaveStation {
    /// `slave` on the bus `phy` belongs to (a handle of its own, from
    /// [`SimulatorPhy::duplicate`]).
    pub fn new(slave: DpSlave, phy: SimulatorPhy, baudrate: profirust::Baudrate) -> Self {
        SlaveStation {
            slave,
            phy,
            baudrate,
            pending: None,
        }
    }

    /// What the station does at bus time `now`: send an answer that is due,
    /// or read what the bus carried and prepare the answer.
    pub fn poll(&mut self, now: Instant) {
        if self.phy.poll_transmission(now) {
            return;
        }
        if let Some((due, _, _)) = &self.pending {
            if now >= *due {
                let (_, to, reply) = self.pending.take().unwrap();
                let from = self.slave.address;
                self.phy
                    .transmit_telegram(now, |tx| send(tx, from, to, reply));
            }
            return;
        }
        let slave = &mut self.slave;
        let reply = self
            .phy
            .receive_telegram(now, |telegram| match telegram {
                Telegram::Data(request) => Some((request.h.sa, slave.answer(&request))),
                Telegram::Token(_) | Telegram::ShortConfirmation(_) => None,
            })
            .flatten();
        if let Some((to, reply)) = reply.filter(|(_, r)| *r != Reply::Nothing) {
            // The request ended at most a microsecond ago: one more keeps
            // the answer clear of min_Tsdr whatever the rounding.
            let tsdr = self
                .baudrate
                .bits_to_time(u32::from(self.slave.min_tsdr_bits()));
            self.pending = Some((now + tsdr + Duration::from_micros(1), to, reply));
        }
    }
}

/// Puts `reply` of the station `from` to the station `to` on the bus.
fn send(tx: TelegramTx, from: u8, to: u8, reply: Reply) -> Option<TelegramTxResponse> {
    let header = |dsap, ssap, status| DataTelegramHeader {
        da: to,
        sa: from,
        dsap,
        ssap,
        fc: FunctionCode::Response {
            state: ResponseState::Slave,
            status,
        },
    };
    match reply {
        Reply::Nothing => None,
        Reply::ShortConfirmation => Some(tx.send_short_confirmation()),
        Reply::FdlStatus => {
            Some(tx.send_fdl_status_response(to, from, ResponseState::Slave, ResponseStatus::Ok))
        }
        Reply::Data {
            dsap,
            ssap,
            high_priority,
            pdu,
        } => {
            let status = if high_priority {
                ResponseStatus::DataHigh
            } else {
                ResponseStatus::DataLow
            };
            let header = header(dsap, ssap, status);
            Some(tx.send_data_telegram(header, pdu.len(), |buf| buf.copy_from_slice(&pdu)))
        }
        Reply::NotActivated { dsap, ssap } => {
            let header = header(dsap, ssap, ResponseStatus::SapNotEnabled);
            Some(tx.send_data_telegram(header, 0, |_| ()))
        }
    }
}
