//! The manuals' own exchanges, as a PLC program would run them: the
//! module the engineer plugs, the parameters set by name, the telegrams
//! sent and the answers the manual gives, and the diagnosis. Each value is
//! cited to its manual section; a value no manual gives is marked as this
//! test's own. The master side sends these bytes as they stand: it knows
//! the PKW channel from the manual, not from the layout.

/// One exchange of a manual.
pub struct Exchange {
    /// What it shows, and where the manual shows it.
    pub title: &'static str,
    /// The GSD's name of the module plugged.
    pub module: &'static str,
    /// Parameters set by name, the others at the GSD's defaults.
    pub prm: &'static [(&'static str, i64)],
    pub steps: &'static [Step],
}

/// One step of an exchange.
pub enum Step {
    /// The master sends `out` (hex words) and the slave must answer with
    /// `expect` in the same Data_Exchange; `xxxx` is a word the manual does
    /// not give.
    Telegram {
        what: &'static str,
        out: &'static str,
        expect: &'static str,
    },
    /// The drive's side changes, and the slave must ask the master to read
    /// its diagnosis: the device-related block `block` (hex bytes, the
    /// header first), whose value the GSD names `text` (its 32-character
    /// form) and `gsdc decode` names `decoded`.
    Diagnosis {
        what: &'static str,
        event: DriveEvent,
        block: &'static str,
        text: &'static str,
        decoded: &'static str,
    },
}

/// What happens on the drive's side of the card.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DriveEvent {
    /// The card loses its link to the drive.
    LinkLost,
    /// The drive reports a fault code.
    Fault(u16),
    /// A node behind a gateway reports a diagnosis: its type, the node, the
    /// code.
    Node { kind: u8, node: u8, code: u16 },
}

/// The exchanges of the description named `name`.
pub fn exchanges(name: &str) -> &'static [Exchange] {
    match name {
        "md810dp" => MD810,
        "9kdp1" => PI9000,
        _ => &[],
    }
}

/// MD810 manual, chapter 1. F0-08 is 0xF008 (1.4.2, figure 6: PKE low byte
/// F0, IND high byte 08); F0-08 as a PZD mapping is 61448, as 1.6 step 5
/// writes F0-12 as 61452.
const MD810: &[Exchange] = &[
    Exchange {
        title: "MD810 1.4.2: the PKW channel (PPO1, mappings at their defaults)",
        module: "PPO1: 4 PKW + 2 PZD",
        prm: &[],
        steps: &[
            Step::Telegram {
                what: "figure 6: read F0-08, answered 0x1388 (50.00 Hz); PZD 0000 0000 this test's own",
                out: "10F0 0800 0000 0000 0000 0000",
                expect: "10F0 0800 0000 1388 xxxx xxxx",
            },
            Step::Telegram {
                what: "figure 7: write 20.00 Hz to F0-08, answered with the value",
                out: "20F0 0800 0000 07D0 0000 0000",
                expect: "10F0 0800 0000 07D0 xxxx xxxx",
            },
            Step::Telegram {
                what: "figure 6 again: F0-08 now reads 20.00 Hz",
                out: "10F0 0800 0000 0000 0000 0000",
                expect: "10F0 0800 0000 07D0 xxxx xxxx",
            },
            Step::Telegram {
                what: "figures 6 and 7's failure, 70F0 0800 0000 errCode, with 1.4.1's error 2 \
                       (illegal address) for F0-99, an address this test's drive does not have",
                out: "10F0 6300 0000 0000 0000 0000",
                expect: "70F0 6300 0000 0002 xxxx xxxx",
            },
        ],
    },
    Exchange {
        title: "MD810 1.6 step 5: PZD words mapped by name to F0-08 (PPO2)",
        module: "PPO2: 4 PKW + 6 PZD",
        prm: &[
            ("PZD2(master->slaver)", 61448),
            ("PZD3(slaver->master)", 61448),
        ],
        steps: &[
            Step::Telegram {
                what: "PZD2 writes 30.00 Hz (0x0BB8, this test's own) to F0-08, PZD3 reads it back",
                out: "0000 0000 0000 0000 0000 0BB8 0000 0000 0000 0000",
                expect: "0000 0000 0000 0000 xxxx xxxx 0BB8 xxxx xxxx xxxx",
            },
            Step::Telegram {
                what: "and the PKW channel reads the same (figure 6's request)",
                out: "10F0 0800 0000 0000 0000 0BB8 0000 0000 0000 0000",
                expect: "10F0 0800 0000 0BB8 xxxx xxxx 0BB8 xxxx xxxx xxxx",
            },
        ],
    },
    Exchange {
        title: "MD810 1.8: the diagnosis (PPO1)",
        module: "PPO1: 4 PKW + 2 PZD",
        prm: &[],
        steps: &[Step::Diagnosis {
            what: "the card loses the drive: 0x34 in the device-related block's low byte",
            event: DriveEvent::LinkLost,
            block: "03 00 34",
            text: "DP card-drive comm. interrupted",
            decoded: "DP card-drive comm. interrupted",
        }],
    },
];

/// PI9000 manual, appendix I: the card's PZD1 is the command word (2000H)
/// and the status word (3000H), PZD2 to PZD6 the Modbus addresses
/// User_Prm_Data maps (9kdp1.toml; the DP telegram is the description's
/// own, the addresses and values are the manual's).
const PI9000: &[Exchange] = &[
    Exchange {
        title: "PI9000 I-3: command word, communication set value and F0.03 (PPO4; \
                PZD2 and PZD3 in mapped by name)",
        module: "PPO4: 6 PZD",
        prm: &[
            ("PZD2 in Modbus address", 0x1000),
            ("PZD3 in Modbus address", 0xF003),
        ],
        steps: &[Step::Telegram {
            what: "PZD1 0001 forward run (2000H); PZD2 5000 to 1000H, 50.00 % (10000 is \
                   100.00 %), read back in PZD2; PZD3 F0.03 = 0001 (I-1, command 03H); \
                   PZD1 the status word 3000H, 0003 stop (this test's drive does not start); \
                   PZD5 8000H, 0000 no fault",
            out: "0001 1388 0000 0000 0000 0000",
            expect: "0003 1388 0001 xxxx 0000 xxxx",
        }],
    },
    Exchange {
        title: "PI9000 I-3: the drive's fault in the diagnosis (PPO3)",
        module: "PPO3: 2 PZD",
        prm: &[],
        steps: &[Step::Diagnosis {
            what: "the drive reports 000B, Motor Overload (8000H)",
            event: DriveEvent::Fault(0x000B),
            block: "03 00 0B",
            text: "Motor Overload",
            decoded: "Motor Overload",
        }],
    },
];

/// How a gateway's nodes are set up by the GSD's parameter names: the
/// description's names, with `{n}` for the node number.
pub struct NodeParameters {
    pub count: &'static str,
    pub input_words: &'static str,
    pub output_words: &'static str,
    pub first_node: u8,
}

/// A gateway's exchange: the nodes' words in total each way (the master
/// puts as few nodes in use as carry them, and plugs modules of as many
/// words), then `steps`.
pub struct NodeExchange {
    pub title: &'static str,
    pub input_words: usize,
    pub output_words: usize,
    pub steps: &'static [Step],
}

/// A gateway's node parameters and exchanges, for the description named
/// `name`.
pub fn gateway(name: &str) -> Option<(&'static NodeParameters, &'static [NodeExchange])> {
    match name {
        "md810-gateway" => Some((&MD810_BRIDGE_NODES, MD810_BRIDGE)),
        _ => None,
    }
}

/// MD810 manual, chapter 2 (md810-gateway.toml names the parameters; 2.5:
/// CANopen slaves 1 to 30).
const MD810_BRIDGE_NODES: NodeParameters = NodeParameters {
    count: "Number of CANopen slaves",
    input_words: "Slave {n} TPDO words",
    output_words: "Slave {n} RPDO words",
    first_node: 1,
};

/// MD810 manual, 2.4 and 2.5. Which node carries which words is this
/// test's own (as few nodes as the words need, 2.2.1's 8 words at most per
/// node); the nodes' words follow in ascending node number
/// (md810-gateway.toml's data_order, its own choice: 2.3 has no text).
const MD810_BRIDGE: &[NodeExchange] = &[NodeExchange {
    title: "MD810 2.4 step 5: RPDO 64 words in total, TPDO 120 words",
    input_words: 120,
    output_words: 64,
    steps: &[
        Step::Diagnosis {
            what: "2.5: CANopen slave 7 (this test's own) drops out while running: type 3, code 32",
            event: DriveEvent::Node {
                kind: 3,
                node: 7,
                code: 32,
            },
            block: "04 03 07 20",
            text: "CANopen slave lost while running",
            decoded: "CANopen slave dropped out while running",
        },
        Step::Diagnosis {
            what: "2.5: the drive at slave 2 reports fault 0x0012 (this test's own): type 4, \
                   the fault code high byte first",
            event: DriveEvent::Node {
                kind: 4,
                node: 2,
                code: 0x0012,
            },
            block: "05 04 02 00 12",
            text: "Drive reports fault",
            decoded: "Drive reports fault",
        },
    ],
}];

/// `"10F0 0800"` as bytes; `xxxx` words as `None`.
pub fn hex_words(hex: &str) -> Vec<Option<u8>> {
    hex.split_whitespace()
        .flat_map(|word| match u16::from_str_radix(word, 16) {
            Ok(value) => value.to_be_bytes().map(Some),
            Err(_) => [None, None],
        })
        .collect()
}

/// `"03 00 34"` as bytes.
pub fn hex_bytes(hex: &str) -> Vec<u8> {
    hex.split_whitespace()
        .map(|byte| u8::from_str_radix(byte, 16).expect("a hex byte"))
        .collect()
}
