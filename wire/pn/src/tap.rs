//! The device's RPC transport: pnio's UDP transport with a look at each
//! request on its way in. pnio keeps the records a controller writes to
//! itself and acknowledges every Write, and its model has no API, so the
//! device reads both here, with pnio's own parsers: each Write's records go
//! to the application (which decodes them through the layout), and each
//! Connect is checked against the layout's APIs and handed to pnio with one
//! API per IOCR (`connect.rs`).

use crate::connect::{check_apis, with_one_api_per_iocr, ApiMismatch};
use pnio::cm::{ConnectBlock, ConnectReq, PnioStatus, Record, WriteReq};
use pnio::rpc::{
    Drep, NdrRequest, NdrResponse, Opnum, PacketType, RpcError, RpcHeader, RpcTransport,
    UdpRpcTransport, FLAG1_IDEMPOTENT, FLAG1_NO_FACK,
};
use std::net::SocketAddr;
use std::os::fd::RawFd;
use std::sync::mpsc::Sender;
use std::time::Duration;

/// What the tap saw, in arrival order.
#[derive(Debug)]
pub enum Seen {
    /// A Write request's records (a MultipleWrite's container first).
    Records(Vec<Record>),
    /// A Connect placed a submodule in another API than the layout's; the
    /// device refused it without handing it to pnio.
    ApiRefused(ApiMismatch),
    /// A Connect whose IOCRs were merged to one API each for pnio.
    MergedApis,
}

/// Error code 2 of the device's refusal of a Connect with a wrong API: the
/// field number of the API in the ExpectedSubmoduleBlockReq. (pnio numbers its
/// own ExpectedSubmodule refusals 04 module ident, 06 submodule ident, 07
/// missing submodule or wrong length.)
pub const API_REFUSAL_CODE2: u8 = 0x05;

pub struct Tap {
    udp: UdpRpcTransport,
    seen: Sender<Seen>,
    api_of: Box<dyn Fn(u16, u16) -> Option<u32> + Send + Sync>,
}

impl Tap {
    pub fn new(
        udp: UdpRpcTransport,
        seen: Sender<Seen>,
        api_of: impl Fn(u16, u16) -> Option<u32> + Send + Sync + 'static,
    ) -> Tap {
        Tap {
            udp,
            seen,
            api_of: Box::new(api_of),
        }
    }

    /// The PDU pnio gets for `pdu` from `from`, or `None` when the tap
    /// answered it itself.
    fn look_at(&self, pdu: Vec<u8>, from: SocketAddr) -> Result<Option<Vec<u8>>, RpcError> {
        let Ok(header) = RpcHeader::parse(&pdu) else {
            return Ok(Some(pdu)); // pnio logs and drops what it cannot parse
        };
        if header.ptype != PacketType::Request {
            return Ok(Some(pdu));
        }
        let Ok((ndr, blocks)) = NdrRequest::parse(&pdu[RpcHeader::LEN..], header.drep) else {
            return Ok(Some(pdu));
        };
        match Opnum::from_u16(header.opnum) {
            Some(Opnum::Write) => {
                if let Ok(write) = WriteReq::parse(blocks) {
                    let _ = self.seen.send(Seen::Records(write.records));
                }
                Ok(Some(pdu))
            }
            Some(Opnum::Connect) => {
                let Ok(connect) = ConnectReq::parse(blocks) else {
                    return Ok(Some(pdu));
                };
                if let Some(mismatch) = check_apis(&connect, &self.api_of) {
                    let _ = self.seen.send(Seen::ApiRefused(mismatch));
                    let status = PnioStatus::connect_reject(
                        ConnectBlock::ExpectedSubmodule,
                        API_REFUSAL_CODE2,
                    );
                    self.udp
                        .send(&refusal(&header, ndr.args_max, status), from)?;
                    return Ok(None);
                }
                match with_one_api_per_iocr(&pdu) {
                    Some(merged) => {
                        let _ = self.seen.send(Seen::MergedApis);
                        Ok(Some(merged))
                    }
                    None => Ok(Some(pdu)),
                }
            }
            _ => Ok(Some(pdu)),
        }
    }
}

/// A response PDU refusing `request` with `status`, shaped as pnio shapes its
/// own refusals.
fn refusal(request: &RpcHeader, args_max: u32, status: PnioStatus) -> Vec<u8> {
    let header = RpcHeader {
        ptype: PacketType::Response,
        flags1: FLAG1_IDEMPOTENT | FLAG1_NO_FACK,
        flags2: 0,
        drep: Drep::BIG,
        serial_hi: 0,
        object: request.object,
        interface: request.interface,
        activity: request.activity,
        server_boot: 0,
        if_version: 1,
        seq_num: request.seq_num,
        opnum: request.opnum,
        ihint: 0xffff,
        ahint: 0xffff,
        frag_len: NdrResponse::LEN as u16,
        frag_num: 0,
        auth_proto: 0,
        serial_lo: 0,
    };
    let mut pdu = Vec::with_capacity(RpcHeader::LEN + NdrResponse::LEN);
    header.write(&mut pdu);
    NdrResponse::error(status.to_u32(), args_max).write(&mut pdu, Drep::BIG);
    pdu
}

impl RpcTransport for Tap {
    fn send(&self, buf: &[u8], to: SocketAddr) -> Result<(), RpcError> {
        self.udp.send(buf, to)
    }

    fn recv(&self, timeout: Option<Duration>) -> Result<Option<(Vec<u8>, SocketAddr)>, RpcError> {
        let Some((pdu, from)) = self.udp.recv(timeout)? else {
            return Ok(None);
        };
        Ok(self.look_at(pdu, from)?.map(|pdu| (pdu, from)))
    }

    fn raw_fd(&self) -> Option<RawFd> {
        self.udp.raw_fd()
    }
}
