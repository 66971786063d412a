//! A PROFIBUS-DP slave (DP-V0) built from a layout: what a card's DP
//! firmware does with each telegram the master sends, whatever carries the
//! bytes (here profirust's simulated bus, see [`crate::station`]; on a card
//! its UART or DP ASIC).
//!
//! Every number comes from the layout ([`Card`], [`Profibus`]): the ident
//! number Set_Prm must carry, how User_Prm_Data decodes (the layout's
//! codec), the modules Chk_Cfg may plug, the telegrams and the diagnosis
//! block. The rules are DP-V0's (IEC 61158-6-3, the services of the slave's
//! SAPs; the standard diagnosis of EN 50170 volume 2), each cited where it
//! is applied:
//!
//! - Wait_Prm: after power-on the slave takes Slave_Diag and Set_Prm only.
//!   A Set_Prm whose Ident_Number is not the slave's, or whose
//!   User_Prm_Data the layout refuses, is confirmed (SC) and then reported
//!   as Prm_Fault in Slave_Diag; the slave stays in Wait_Prm.
//! - Wait_Cfg: Chk_Cfg whose config bytes are one of the layout's modules
//!   (a gateway's: modules whose words make the totals of the nodes
//!   User_Prm_Data put in use) moves the slave to Data_Exch; any other
//!   config is confirmed and reported as Cfg_Fault, and the slave waits for
//!   parameters again.
//! - Data_Exch: Data_Exchange carries the module's output bytes and is
//!   answered with its input bytes, in a high-priority response (DH) when
//!   the slave has a diagnosis the master has not read yet.

use profirust::fdl::{DataTelegram, FunctionCode, RequestType};
use wire_firmware::card::{Card, NodeSetup, PrmValues};
use wire_firmware::cyclic::{self, PzdTargets, Shape};
use wire_firmware::drive::Drive;
use wire_firmware::gsdc_support::{DpDevice, DpModule};
use wire_firmware::nodes::Nodes;

// The slave's service access points (IEC 61158-6-3; profirust::consts
// names the same).
const SAP_GLOBAL_CONTROL: u8 = 58;
const SAP_GET_CFG: u8 = 59;
const SAP_SLAVE_DIAG: u8 = 60;
const SAP_SET_PRM: u8 = 61;
const SAP_CHK_CFG: u8 = 62;

/// Set_Prm's fixed part: Station_Status, WD_Fact_1, WD_Fact_2,
/// min_Tsdr, Ident_Number (2 bytes), Group_Ident; User_Prm_Data follows.
const SET_PRM_FIXED: usize = 7;

// Set_Prm byte 0, Station_Status.
const LOCK_REQ: u8 = 0x80;
const UNLOCK_REQ: u8 = 0x40;
const SYNC_REQ: u8 = 0x20;
const FREEZE_REQ: u8 = 0x10;
const WD_ON: u8 = 0x08;

// Slave_Diag byte 1, Station_status_1 (EN 50170 vol. 2). Bit 0
// (Station_Non_Existent), bit 5 (Invalid_Slave_Response) and bit 7
// (Master_Lock) are the master's to set, the slave sends them 0.
const STATION_NOT_READY: u8 = 0x02;
const CFG_FAULT: u8 = 0x04;
const EXT_DIAG: u8 = 0x08;
const NOT_SUPPORTED: u8 = 0x10;
const PRM_FAULT: u8 = 0x40;

// Slave_Diag byte 2, Station_status_2. Bit 2 is always 1; bit 7
// (Deactivated) is the master's.
const PRM_REQ: u8 = 0x01;
const STATUS_2_ALWAYS: u8 = 0x04;
const WD_ON_STATUS: u8 = 0x08;

/// Slave_Diag byte 4, Diag.Master_Add, before a master has parameterized
/// the slave.
const NO_MASTER: u8 = 255;

/// Where the slave is in its start-up.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum State {
    WaitPrm,
    WaitCfg,
    DataExchange,
}

/// What the slave answers a request with.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Reply {
    /// Nothing: a request without an answer (SDN), or not for this slave.
    Nothing,
    /// The short acknowledgement SC (0xE5).
    ShortConfirmation,
    /// The answer to Request FDL Status: a passive station, ready.
    FdlStatus,
    /// A data response from `ssap` to the master's `dsap`; `high_priority`
    /// (DH) asks the master to read the diagnosis.
    Data {
        dsap: Option<u8>,
        ssap: Option<u8>,
        high_priority: bool,
        pdu: Vec<u8>,
    },
    /// The service is not activated (RS): a SAP the slave does not have,
    /// or Data_Exchange before the slave is configured.
    NotActivated { dsap: Option<u8>, ssap: Option<u8> },
}

/// What Chk_Cfg plugged.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Plugged {
    /// One module of a drive's card.
    Module(&'static DpModule),
    /// A gateway's modules, whose words make the nodes' totals.
    Nodes(Box<NodeSetup>),
}

impl Plugged {
    /// Bytes of input and of output.
    pub fn data_lengths(&self) -> (usize, usize) {
        match self {
            Plugged::Module(module) => (module.input_len, module.output_len),
            Plugged::Nodes(setup) => (setup.input_len, setup.output_len),
        }
    }
}

/// Faults of the last Set_Prm and Chk_Cfg, as Slave_Diag reports them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Faults {
    prm: bool,
    cfg: bool,
    not_supported: bool,
}

/// A DP slave: the card's DP firmware, on top of its drive (or, for a
/// gateway, the nodes of its second bus).
#[derive(Debug)]
pub struct DpSlave {
    pub address: u8,
    pub card: &'static Card,
    /// The layout's `DP_DEVICE`.
    dp: &'static DpDevice,
    /// The drive behind a drive's card.
    pub drive: Drive,
    /// The nodes behind a gateway.
    pub nodes: Nodes,
    state: State,
    /// The master that parameterized the slave, which locks it.
    master: Option<u8>,
    faults: Faults,
    watchdog_on: bool,
    /// min_Tsdr of the last Set_Prm, in bit times: the slave answers no
    /// sooner.
    min_tsdr_bits: u8,
    /// User_Prm_Data of the last Set_Prm the slave accepted, and its
    /// values by name.
    user_prm: Vec<u8>,
    prm: Option<PrmValues>,
    /// A gateway's nodes, as the last Set_Prm put them in use.
    node_setup: Option<NodeSetup>,
    /// The config bytes of the last Chk_Cfg the slave accepted, and what
    /// they plugged.
    config: Vec<u8>,
    plugged: Option<Plugged>,
    /// The device-related block the master last read in Slave_Diag.
    reported: Vec<u8>,
}

impl DpSlave {
    /// The slave of `card` at `address`, after power-on: waiting for
    /// parameters.
    pub fn new(address: u8, card: &'static Card, drive: Drive) -> Self {
        let dp = card.dp.expect("a DP slave needs a layout with PROFIBUS");
        DpSlave {
            address,
            card,
            dp,
            drive,
            nodes: Nodes::default(),
            state: State::WaitPrm,
            master: None,
            faults: Faults::default(),
            watchdog_on: false,
            // IEC 61158-6-3: 11 bit times until a Set_Prm says otherwise.
            min_tsdr_bits: 11,
            user_prm: Vec::new(),
            prm: None,
            node_setup: None,
            config: Vec::new(),
            plugged: None,
            reported: Vec::new(),
        }
    }

    pub fn state(&self) -> State {
        self.state
    }

    /// User_Prm_Data as the slave decoded it, by parameter name.
    pub fn prm(&self) -> Option<&PrmValues> {
        self.prm.as_ref()
    }

    /// What Chk_Cfg plugged.
    pub fn plugged(&self) -> Option<&Plugged> {
        self.plugged.as_ref()
    }

    pub fn min_tsdr_bits(&self) -> u8 {
        self.min_tsdr_bits
    }

    /// The answer to a request telegram on the bus; [`Reply::Nothing`] for
    /// a telegram for another station or one that wants no answer.
    pub fn answer(&mut self, request: &DataTelegram) -> Reply {
        let FunctionCode::Request { req, .. } = request.h.fc else {
            return Reply::Nothing;
        };
        let broadcast = request.h.da == 127;
        if request.h.da != self.address && !broadcast {
            return Reply::Nothing;
        }
        if req == RequestType::FdlStatus {
            return if broadcast {
                Reply::Nothing
            } else {
                Reply::FdlStatus
            };
        }
        let reply = match request.h.dsap {
            None => self.data_exchange(request),
            Some(SAP_SLAVE_DIAG) => self.slave_diag(request),
            Some(SAP_SET_PRM) => self.set_prm(request),
            Some(SAP_CHK_CFG) => self.chk_cfg(request),
            Some(SAP_GET_CFG) => self.get_cfg(request),
            // Global_Control (Clear, Sync, Freeze) comes as a broadcast
            // without an answer; this slave supports neither Sync nor
            // Freeze, and keeps its outputs to the drive as they are.
            Some(SAP_GLOBAL_CONTROL) => Reply::Nothing,
            Some(_) => Reply::NotActivated {
                dsap: request.h.ssap,
                ssap: request.h.dsap,
            },
        };
        if broadcast || !req.expects_reply() {
            Reply::Nothing
        } else {
            reply
        }
    }

    /// Set_Prm (SAP 61): the parameters, checked against the layout.
    fn set_prm(&mut self, request: &DataTelegram) -> Reply {
        let pdu = request.pdu;
        if pdu.len() < SET_PRM_FIXED {
            self.refuse_prm();
            return Reply::ShortConfirmation;
        }
        let status = pdu[0];
        if status & UNLOCK_REQ != 0 && status & LOCK_REQ == 0 {
            // The master releases the slave: back to waiting for parameters.
            self.restart();
            return Reply::ShortConfirmation;
        }
        // A new Set_Prm clears the faults of the last one.
        self.faults = Faults::default();
        if status & (SYNC_REQ | FREEZE_REQ) != 0 {
            // This slave supports neither Sync nor Freeze: Not_Supported
            // alone, the parameters may be right.
            self.faults.not_supported = true;
            self.forget_parameters();
            return Reply::ShortConfirmation;
        }
        // Another ident number is a parameter fault, as User_Prm_Data the
        // layout's codec refuses is, and a gateway's nodes whose totals
        // its codec refuses.
        let ident = u16::from_be_bytes([pdu[4], pdu[5]]);
        let user_prm = &pdu[SET_PRM_FIXED..];
        let prm = (ident == self.dp.ident_number)
            .then(|| PrmValues::read(&self.dp.user_prm, user_prm).ok())
            .flatten();
        let node_setup = self.card.gateway.map(|g| (g.nodes)(user_prm));
        match (prm, node_setup) {
            (Some(prm), None | Some(Some(_))) => {
                self.user_prm = user_prm.to_vec();
                self.prm = Some(prm);
                self.node_setup = node_setup.flatten();
                self.master = Some(request.h.sa);
                self.watchdog_on = status & WD_ON != 0;
                if pdu[3] != 0 {
                    self.min_tsdr_bits = pdu[3];
                }
                self.plugged = None;
                self.state = State::WaitCfg;
            }
            _ => self.refuse_prm(),
        }
        Reply::ShortConfirmation
    }

    /// Chk_Cfg (SAP 62): the modules the master plugged.
    fn chk_cfg(&mut self, request: &DataTelegram) -> Reply {
        if self.state == State::WaitPrm {
            // Without parameters the slave takes no configuration; Slave_Diag
            // still says Prm_Req.
            return Reply::ShortConfirmation;
        }
        self.plugged = self.plug(request.pdu);
        if self.plugged.is_some() {
            self.config = request.pdu.to_vec();
            self.faults.cfg = false;
            self.state = State::DataExchange;
        } else {
            self.faults.cfg = true;
            self.state = State::WaitPrm;
        }
        Reply::ShortConfirmation
    }

    /// What `config` plugs, as the layout's table checks it: one of its
    /// modules, or a gateway's modules whose words make the totals of the
    /// nodes in use.
    fn plug(&self, config: &[u8]) -> Option<Plugged> {
        self.dp.check_config(&self.user_prm, config)?;
        match self.node_setup {
            Some(setup) => Some(Plugged::Nodes(Box::new(setup))),
            None => {
                let module = self.dp.modules.iter().find(|m| m.config == config)?;
                Some(Plugged::Module(module))
            }
        }
    }

    /// Get_Cfg (SAP 59): the config bytes of what is plugged.
    fn get_cfg(&mut self, request: &DataTelegram) -> Reply {
        Reply::Data {
            dsap: request.h.ssap,
            ssap: request.h.dsap,
            high_priority: false,
            pdu: self.config.clone(),
        }
    }

    /// Slave_Diag (SAP 60): the standard diagnosis, then the device-related
    /// block of the layout.
    fn slave_diag(&mut self, request: &DataTelegram) -> Reply {
        let (block, something_to_report) = self.device_block();
        let mut status_1 = 0;
        if self.state != State::DataExchange {
            status_1 |= STATION_NOT_READY;
        }
        if self.faults.cfg {
            status_1 |= CFG_FAULT;
        }
        if something_to_report {
            status_1 |= EXT_DIAG;
        }
        if self.faults.not_supported {
            status_1 |= NOT_SUPPORTED;
        }
        if self.faults.prm {
            status_1 |= PRM_FAULT;
        }
        let mut status_2 = STATUS_2_ALWAYS;
        if self.state == State::WaitPrm {
            status_2 |= PRM_REQ;
        }
        if self.watchdog_on {
            status_2 |= WD_ON_STATUS;
        }
        let ident = self.dp.ident_number.to_be_bytes();
        let mut pdu = vec![
            status_1,
            status_2,
            0, // Station_status_3: no Ext_Diag_Overflow
            self.master.unwrap_or(NO_MASTER),
            ident[0],
            ident[1],
        ];
        pdu.extend_from_slice(&block);
        self.reported = block;
        Reply::Data {
            dsap: request.h.ssap,
            ssap: request.h.dsap,
            high_priority: false,
            pdu,
        }
    }

    /// The device-related block, and whether it reports something (Ext_Diag).
    /// A drive's card sends the layout's block with the drive's code in its
    /// area (MD810 1.8: always, 3 bytes); a gateway the block of its nodes'
    /// event, by the layout's codec, and none without an event.
    fn device_block(&self) -> (Vec<u8>, bool) {
        if let Some(gateway) = self.card.gateway {
            let block = self.nodes.event().and_then(gateway.diagnosis);
            let bytes = block.map_or(Vec::new(), |b| b.as_bytes().to_vec());
            let reports = !bytes.is_empty();
            return (bytes, reports);
        }
        let code = self.drive.diagnosis_code();
        // The block's first area carries the drive's code.
        let Some((diagnosis, area)) = self.dp.diagnosis.and_then(|d| Some((d, *d.areas.first()?)))
        else {
            return (Vec::new(), false);
        };
        let mut block = vec![0; diagnosis.len];
        block[0] = diagnosis.header();
        area.area().set(&mut block, code);
        (block, code != 0)
    }

    /// Data_Exchange (default SAP): the outputs to the drive or the nodes,
    /// the inputs back.
    fn data_exchange(&mut self, request: &DataTelegram) -> Reply {
        let (Some(plugged), Some(prm), State::DataExchange) =
            (self.plugged.clone(), self.prm.as_ref(), self.state)
        else {
            return Reply::NotActivated {
                dsap: None,
                ssap: None,
            };
        };
        let (input_len, output_len) = plugged.data_lengths();
        if request.pdu.len() != output_len {
            // Outputs of another length than the configuration's: not this
            // configuration's telegram.
            return Reply::NotActivated {
                dsap: None,
                ssap: None,
            };
        }
        let mut inputs = vec![0; input_len];
        match plugged {
            Plugged::Module(module) => {
                let shape = Shape {
                    pkw: module.pkw,
                    pzd_words: module.pzd_words,
                    double_words: &[],
                };
                let pzds = PzdTargets::of_user_prm(self.dp, prm);
                let drive = &mut self.drive;
                cyclic::exchange(self.card, shape, &pzds, drive, request.pdu, &mut inputs);
            }
            Plugged::Nodes(setup) => self.nodes.exchange(&setup, request.pdu, &mut inputs),
        }
        Reply::Data {
            dsap: None,
            ssap: None,
            high_priority: self.device_block().0 != self.reported,
            pdu: inputs,
        }
    }

    /// A Set_Prm the slave does not take: Prm_Fault, waiting for parameters.
    fn refuse_prm(&mut self) {
        self.faults.prm = true;
        self.forget_parameters();
    }

    /// Back to power-on's state, keeping the drive.
    fn restart(&mut self) {
        self.master = None;
        self.faults = Faults::default();
        self.forget_parameters();
    }

    /// Waiting for parameters, with none.
    fn forget_parameters(&mut self) {
        self.user_prm.clear();
        self.prm = None;
        self.node_setup = None;
        self.plugged = None;
        self.state = State::WaitPrm;
    }
}
