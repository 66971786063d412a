//! What the device does with a Connect request before pnio sees it: it checks
//! each submodule's API against the layout (pnio's model has no API), and it
//! gives pnio the IOCRs with one API entry each (pnio refuses an IOCR with
//! more than one, DB 81 02 0F, which every card with a PROFIdrive module has:
//! the access point's submodules in API 0, the telegram in API 0x3A00).

use pnio::cm::{BlockHeader, ConnectReq, IocrApi, IocrBlockReq};
use pnio::rpc::{Drep, NdrRequest, RpcHeader};

/// Block type of an IOCRBlockReq (IEC 61158-6-10).
const IOCR_BLOCK_REQ: u16 = 0x0102;

/// A (slot, subslot) whose API in the Connect is not the layout's.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ApiMismatch {
    pub slot: u16,
    pub subslot: u16,
    pub expected: u32,
    pub found: u32,
}

/// Every (api, slot, subslot) the Connect names, in its ExpectedSubmodule
/// blocks and in its IOCRs' data and status objects.
pub fn named_submodules(req: &ConnectReq) -> Vec<(u32, u16, u16)> {
    let mut named = Vec::new();
    for block in &req.expected {
        for api in &block.apis {
            for sub in &api.submodules {
                named.push((api.api, api.slot, sub.subslot));
            }
        }
    }
    for iocr in &req.iocrs {
        for api in &iocr.apis {
            for object in api.io_data.iter().chain(&api.iocs) {
                named.push((api.api, object.slot, object.subslot));
            }
        }
    }
    named
}

/// The first submodule the Connect places in another API than `api_of` says
/// (`None` from `api_of`: a submodule the device does not have, which pnio
/// refuses itself).
pub fn check_apis(
    req: &ConnectReq,
    api_of: impl Fn(u16, u16) -> Option<u32>,
) -> Option<ApiMismatch> {
    named_submodules(req)
        .into_iter()
        .find_map(|(found, slot, subslot)| {
            let expected = api_of(slot, subslot)?;
            (expected != found).then_some(ApiMismatch {
                slot,
                subslot,
                expected,
                found,
            })
        })
}

/// The Connect PDU with each IOCR's API entries merged into one (the first
/// API's number, the objects of all in order), its lengths recomputed; `None`
/// when no IOCR has more than one API (the PDU goes to pnio unchanged). The
/// frame offsets stay the controller's, so the cyclic frames do not change:
/// only pnio's view of the CR's structure does, after the device has checked
/// every API itself (`check_apis`).
pub fn with_one_api_per_iocr(pdu: &[u8]) -> Option<Vec<u8>> {
    let header = RpcHeader::parse(pdu).ok()?;
    let body = &pdu[RpcHeader::LEN..];
    let (ndr, blocks) = NdrRequest::parse(body, header.drep).ok()?;
    let mut rewritten = Vec::with_capacity(blocks.len());
    let mut changed = false;
    let mut pos = 0;
    while pos < blocks.len() {
        let (block, block_body) = BlockHeader::parse(&blocks[pos..]).ok()?;
        let whole = &blocks[pos..pos + BlockHeader::LEN + block_body.len()];
        pos += whole.len();
        if block.block_type == IOCR_BLOCK_REQ {
            let iocr = IocrBlockReq::parse(block_body).ok()?;
            if iocr.apis.len() > 1 {
                write_iocr_one_api(&iocr, &mut rewritten);
                changed = true;
                continue;
            }
        }
        rewritten.extend_from_slice(whole);
    }
    if !changed {
        return None;
    }
    let mut out = Vec::with_capacity(pdu.len());
    let mut header = header;
    header.frag_len = (NdrRequest::LEN + rewritten.len()) as u16;
    header.write(&mut out);
    let ndr = NdrRequest {
        args_len: rewritten.len() as u32,
        actual_count: rewritten.len() as u32,
        ..ndr
    };
    write_ndr(&ndr, header.drep, &mut out);
    out.extend_from_slice(&rewritten);
    Some(out)
}

/// An IOCRBlockReq with a single API entry holding every API's objects.
fn write_iocr_one_api(iocr: &IocrBlockReq, out: &mut Vec<u8>) {
    let merged = IocrApi {
        api: iocr.apis[0].api,
        io_data: iocr.apis.iter().flat_map(|a| a.io_data.clone()).collect(),
        iocs: iocr.apis.iter().flat_map(|a| a.iocs.clone()).collect(),
    };
    write_iocr(
        &IocrBlockReq {
            apis: vec![merged],
            ..iocr.clone()
        },
        out,
    );
}

/// An IOCRBlockReq as IEC 61158-6-10 lays it out (the inverse of pnio's
/// `IocrBlockReq::parse`).
fn write_iocr(iocr: &IocrBlockReq, out: &mut Vec<u8>) {
    let mut body = Vec::new();
    for value in [iocr.iocr_type, iocr.reference, iocr.lt] {
        body.extend_from_slice(&value.to_be_bytes());
    }
    body.extend_from_slice(&iocr.properties.to_be_bytes());
    for value in [
        iocr.data_length,
        iocr.frame_id,
        iocr.send_clock_factor,
        iocr.reduction_ratio,
        iocr.phase,
        iocr.sequence,
    ] {
        body.extend_from_slice(&value.to_be_bytes());
    }
    body.extend_from_slice(&iocr.frame_send_offset.to_be_bytes());
    for value in [iocr.watchdog_factor, iocr.data_hold_factor, iocr.tag_header] {
        body.extend_from_slice(&value.to_be_bytes());
    }
    body.extend_from_slice(&iocr.multicast_mac.0);
    body.extend_from_slice(&(iocr.apis.len() as u16).to_be_bytes());
    for api in &iocr.apis {
        body.extend_from_slice(&api.api.to_be_bytes());
        for objects in [&api.io_data, &api.iocs] {
            body.extend_from_slice(&(objects.len() as u16).to_be_bytes());
            for object in objects {
                for value in [object.slot, object.subslot, object.frame_offset] {
                    body.extend_from_slice(&value.to_be_bytes());
                }
            }
        }
    }
    BlockHeader::write(out, IOCR_BLOCK_REQ, body.len() as u16);
    out.extend_from_slice(&body);
}

/// The NDR request header in the PDU's byte order.
fn write_ndr(ndr: &NdrRequest, drep: Drep, out: &mut Vec<u8>) {
    for value in [
        ndr.args_max,
        ndr.args_len,
        ndr.max_count,
        ndr.offset,
        ndr.actual_count,
    ] {
        let bytes = if drep.little_endian {
            value.to_le_bytes()
        } else {
            value.to_be_bytes()
        };
        out.extend_from_slice(&bytes);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use pnio::cm::IocrObject;
    use pnio::eth::MacAddr;
    use pnio::rpc::{PacketType, Uuid};

    fn object(slot: u16, subslot: u16, frame_offset: u16) -> IocrObject {
        IocrObject {
            slot,
            subslot,
            frame_offset,
        }
    }

    /// An input IOCR as a controller sends it for a PROFIdrive module: the
    /// access point's submodules in API 0, the telegram in API 0x3A00.
    fn two_api_iocr() -> IocrBlockReq {
        IocrBlockReq {
            iocr_type: 1,
            reference: 1,
            lt: 0x8892,
            properties: 1,
            data_length: 40,
            frame_id: 0x8001,
            send_clock_factor: 32,
            reduction_ratio: 8,
            phase: 1,
            sequence: 0,
            frame_send_offset: 0xFFFF_FFFF,
            watchdog_factor: 10,
            data_hold_factor: 10,
            tag_header: 0xC000,
            multicast_mac: MacAddr([0; 6]),
            apis: vec![
                IocrApi {
                    api: 0,
                    io_data: vec![object(0, 1, 0), object(0, 0x8000, 1)],
                    iocs: vec![],
                },
                IocrApi {
                    api: 0x3A00,
                    io_data: vec![object(1, 1, 2), object(1, 2, 3)],
                    iocs: vec![object(1, 2, 8)],
                },
            ],
        }
    }

    /// A Connect request PDU (RPC header, NDR header, blocks) in `drep`.
    fn pdu(blocks: &[u8], drep: Drep) -> Vec<u8> {
        let header = RpcHeader {
            ptype: PacketType::Request,
            flags1: 0x20,
            flags2: 0,
            drep,
            serial_hi: 0,
            object: Uuid([1; 16]),
            interface: Uuid([2; 16]),
            activity: Uuid([3; 16]),
            server_boot: 0,
            if_version: 1,
            seq_num: 7,
            opnum: 0,
            ihint: 0xFFFF,
            ahint: 0xFFFF,
            frag_len: (NdrRequest::LEN + blocks.len()) as u16,
            frag_num: 0,
            auth_proto: 0,
            serial_lo: 0,
        };
        let mut out = Vec::new();
        header.write(&mut out);
        NdrRequest::for_blocks(1500, blocks.len() as u32).write(&mut out, drep);
        out.extend_from_slice(blocks);
        out
    }

    fn merged_iocr(drep: Drep) {
        let mut two = Vec::new();
        write_iocr(&two_api_iocr(), &mut two);
        let (_, body) = BlockHeader::parse(&two).unwrap();
        assert_eq!(IocrBlockReq::parse(body).unwrap(), two_api_iocr());

        let merged = with_one_api_per_iocr(&pdu(&two, drep)).expect("rewritten");
        let header = RpcHeader::parse(&merged).unwrap();
        assert_eq!(usize::from(header.frag_len), merged.len() - RpcHeader::LEN);
        let (_, blocks) = NdrRequest::parse(&merged[RpcHeader::LEN..], header.drep).unwrap();
        let (_, body) = BlockHeader::parse(blocks).unwrap();
        let iocr = IocrBlockReq::parse(body).unwrap();
        let expected = IocrBlockReq {
            apis: vec![IocrApi {
                api: 0,
                io_data: vec![
                    object(0, 1, 0),
                    object(0, 0x8000, 1),
                    object(1, 1, 2),
                    object(1, 2, 3),
                ],
                iocs: vec![object(1, 2, 8)],
            }],
            ..two_api_iocr()
        };
        assert_eq!(iocr, expected);
    }

    #[test]
    fn an_iocr_with_two_apis_becomes_one_with_every_object_and_offset() {
        merged_iocr(Drep::BIG);
        merged_iocr(Drep {
            little_endian: true,
        });
    }

    #[test]
    fn a_connect_with_one_api_per_iocr_is_left_alone() {
        let mut blocks = Vec::new();
        write_iocr_one_api(&two_api_iocr(), &mut blocks);
        assert_eq!(with_one_api_per_iocr(&pdu(&blocks, Drep::BIG)), None);
    }
}
