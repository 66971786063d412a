//! PROFIdrive's control word STW1 and status word ZSW1 as standard
//! telegrams 1 and 2 carry them (speed control), bit by bit: the words of a card
//! that implements the profile, whatever its description calls the control
//! word of its vendor telegrams.
//!
//! Bits 0 to 10 are the profile's, the same in every source read: ABB's
//! FPBA-01 and RETA-02 manuals (control and status word of the PROFIdrive
//! communication profile, PROFIdrive parameters 967 and 968), Siemens'
//! SIDOOR system manual ("bits 0 to 10 correspond exactly to the PROFIBUS
//! profile Variable-speed drives") and Kollmorgen's AKD2G PROFINET manual.
//! Bits 11 to 15 are the device's own; a description says nothing of them
//! for the standard telegrams, so a set one shows as not described. The
//! names say what a 1 means. Telegram 2's STW2 and ZSW2 are shown as words:
//! their bits 0 to 11 are the device's own (SINAMICS G120 Fieldbuses
//! function manual, 3.1.1.2).

use crate::ir::Direction;

/// STW1, the master's control word.
const STW1: [&str; 11] = [
    "ON (0: OFF1)",
    "No coast stop (0: OFF2)",
    "No quick stop (0: OFF3)",
    "Enable operation",
    "Enable ramp generator",
    "Unfreeze ramp generator",
    "Enable setpoint",
    "Fault acknowledge (0 to 1)",
    "Jog 1",
    "Jog 2",
    "Control by PLC",
];

/// ZSW1, the drive's status word.
const ZSW1: [&str; 11] = [
    "Ready to switch on",
    "Ready to operate",
    "Operation enabled",
    "Fault present",
    "No coast stop (0: OFF2 active)",
    "No quick stop (0: OFF3 active)",
    "Switching on inhibited",
    "Warning present",
    "Speed within tolerance",
    "Control requested",
    "Speed or frequency reached",
];

/// The name of each bit the profile defines in the word of `direction`,
/// from bit 0: STW1 out, ZSW1 in.
pub fn word_bits(direction: Direction) -> &'static [&'static str] {
    match direction {
        Direction::Out => &STW1,
        Direction::In => &ZSW1,
    }
}
