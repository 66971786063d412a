//! A PROFIdrive card's layout places its standard telegram where the GSDML
//! declares it: the profile's API, the module access point in subslot 1
//! with ident 0xFFFF, the telegram's two words each way in subslot 2.

use gsdc_firmware_check::profidrive;

#[test]
fn standard_telegram_1_is_placed_as_the_gsdml_declares_it() {
    assert_eq!(profidrive::TELEGRAM1_API, 14848);
    assert_eq!(profidrive::TELEGRAM1_ACCESS_POINT_SUBSLOT, 1);
    assert_eq!(profidrive::TELEGRAM1_ACCESS_POINT_IDENT, 0xFFFF);
    assert_eq!(profidrive::TELEGRAM1_DATA_SUBSLOT, 2);
    assert_eq!(profidrive::TELEGRAM1_IDENT, 0x10);
    // STW1, NSOLL_A out; ZSW1, NIST_A in: 4 bytes each way.
    let out = profidrive::Telegram1Out::from_bytes(&[0x04, 0x7F, 0x40, 0x00]);
    assert_eq!(out.pzd[0].get(), 0x047F);
    assert_eq!(out.pzd[1].get(), 0x4000);
}
