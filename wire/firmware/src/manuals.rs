//! The drives behind the shipped descriptions' cards, with the parameters
//! their manuals give values for, named as the manuals name them and each
//! cited. A value no manual gives is marked as this model's own.
//!
//! [`for_description`] finds the drive of a description by its name; a
//! description without a drive here (a fixture, a card of your own) gets
//! [`WITHOUT_MANUAL`], a drive that holds no parameter.

use crate::card::Card;
use crate::drive::{Access, Drive, Model, Named, StatusAnswer};

/// The drive behind `card`, as it starts: its description's model, each
/// parameter at the address the card's layout numbers it.
pub fn drive(card: &Card) -> Drive {
    Drive::new(for_description(card.name), card.numbering)
}

/// The drive behind the card the description `name` describes (its file
/// name without `.toml`).
pub fn for_description(name: &str) -> &'static Model {
    match name {
        "md810dp" => &MD810,
        "9kdp1" => &PI9000,
        "mv810-pnet02" => &MV810,
        _ => &WITHOUT_MANUAL,
    }
}

/// A drive of which no manual gives a value: every read and write of a
/// parameter is refused as an illegal address, and a mapped PZD word
/// carries 0 to the master.
pub const WITHOUT_MANUAL: Model = Model {
    manual: "none: the description has no drive model in wire/firmware/src/manuals.rs",
    parameters: &[],
    fault_parameter: None,
    control_word: None,
    status_word: None,
    status_of: None,
    link_lost_code: None,
};

/// Inovance MD810, behind the standard DP interface (descriptions/md810dp.toml;
/// shared/seeds/003, chapter 1).
pub const MD810: Model = Model {
    manual: "MD810 manual, chapter 1",
    parameters: &[Named {
        name: "F0-08",
        value: 5000,
        access: Access::ReadWrite,
        source: "1.4.2, figure 6: the master reads F0-08 (PKE low byte F0, IND high byte 08) \
                 and the drive answers 0x1388 = 5000, 50.00 Hz; figure 7 writes 20.00 Hz \
                 as 0x07D0",
    }],
    // 1.8: the diagnosis is the drive's fault code "与 U0-62 的值一致", and U0-62
    // has no address in the PKW channel's numbering (1.4.2 numbers F0..FF).
    fault_parameter: None,
    // 1.5.1: every PZD word is mapped; the telegram has no control or status word.
    control_word: None,
    status_word: None,
    status_of: None,
    // 1.8: "另当 DP 扩展卡与变频器通信中断时，会返回 0x34".
    link_lost_code: Some(0x34),
};

/// Powtran PI9000, behind the 9KDP1 card (descriptions/9kdp1.toml;
/// shared/seeds/002, appendix I). The card reaches the drive through its
/// Modbus map, so the addresses are Modbus addresses: F0.02 by the
/// layout's numbering, 1000H as the manual writes the others.
pub const PI9000: Model = Model {
    manual: "PI9000 manual, appendix I",
    parameters: &[
        Named {
            name: "F0.02",
            value: 0x0000,
            access: Access::ReadWrite,
            source: "I-1, command 03H: reading two words from F0.02 answers \
                     F002H = 0000H and F003H = 0001H",
        },
        Named {
            name: "F0.03",
            value: 0x0001,
            access: Access::ReadWrite,
            source: "I-1, command 03H (as F0.02)",
        },
        Named {
            name: "1000H",
            value: 0,
            access: Access::ReadWrite,
            source: "I-3: communication set value, -10000 to 10000 for -100.00 % to \
                     100.00 %; the value 0 the drive starts with is this model's own",
        },
        Named {
            name: "2000H",
            value: 0,
            access: Access::WriteOnly,
            source: "I-3: command word, write only (0001 forward run ... 0007 fault reset); \
                     0, no command yet, is this model's own",
        },
        Named {
            name: "3000H",
            value: 0x0003,
            access: Access::ReadOnly,
            source: "I-3: status word, read only (0001 forward run, 0002 reverse run, \
                     0003 stop); that the drive starts stopped is this model's own",
        },
        Named {
            name: "8000H",
            value: 0x0000,
            access: Access::ReadOnly,
            source: "I-3: inverter fault address, 0000 no fault",
        },
    ],
    fault_parameter: Some("8000H"),
    // The card's PZD1 each way (9kdp1.toml, the description's own telegram).
    control_word: Some("2000H"),
    status_word: Some("3000H"),
    status_of: None,
    link_lost_code: None,
};

/// Megmeet MV810 behind the MV810-PNET02 card (descriptions/mv810-pnet02.toml;
/// shared/seeds/000). The manual gives the parameters' meanings but no
/// address (the description's numbering assumes group = high byte, index =
/// low byte, and the layout's NUMBERING reads the names so) and no factory
/// value.
pub const MV810: Model = Model {
    manual: "MV800 PROFINET option manual (R33011095)",
    parameters: &[
        Named {
            name: "P43.01",
            value: 1,
            access: Access::ReadWrite,
            source: "4: P43.01 = 1 (0 is the standard message 1, 1 the user-defined message), \
                     the value every example of 4 sets",
        },
        Named {
            name: "P43.02",
            value: 0,
            access: Access::ReadWrite,
            source: "3: PZD2 receive, 0 to 14 (0 disabled); the manual gives no factory \
                     value: 0 is the description's default (mappings.pzd_out)",
        },
        Named {
            name: "P43.13",
            value: 0,
            access: Access::ReadWrite,
            source: "3: PZD2 send, 0 to 25 (0 disabled); the manual gives no factory \
                     value: 0 is the description's default (mappings.pzd_in)",
        },
    ],
    fault_parameter: None,
    // Section 3: PZD1 carries the control and status words themselves; the
    // manual gives them no parameter (status_of answers).
    control_word: None,
    status_word: None,
    // Section 3: control word bit 0 forward running, 1 reverse running, 4
    // decelerate to stop, 5 coast to stop, 7 emergency stop; status word bit
    // 0 forward running, 1 reverse running, 2 stop, 5 ready. That the drive
    // answers at once, and is always ready, is this model's own: the manual
    // gives the bits, not the drive's timing.
    status_of: Some(StatusAnswer {
        runs: &[(0, 0), (1, 1)],
        stops: &[4, 5, 7],
        stopped: 2,
        always: &[5],
    }),
    link_lost_code: None,
};
