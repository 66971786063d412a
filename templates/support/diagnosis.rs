// Support code for the device-related diagnosis (gsdc
// templates/support/diagnosis.rs).

/// Bits `first..=last` of the device-related diagnosis block, numbered as
/// the GSD's `Unit_Diag_Area` numbers them: bit 0 is the lowest bit of the
/// byte after the header, bit 8 the lowest of the next byte. The area's value
/// has its first bit lowest.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DiagArea {
    first: u16,
    last: u16,
}

impl DiagArea {
    /// Checked where the generated constants are evaluated: at compile time.
    pub const fn new(first: u16, last: u16) -> Self {
        assert!(first <= last && last - first < 16);
        Self { first, last }
    }

    /// Bytes of the block, the header included, that hold the area.
    pub const fn block_len(self) -> usize {
        1 + self.last as usize / 8 + 1
    }

    /// The area's value in `block` (the header byte first).
    pub fn get(self, block: &[u8]) -> u16 {
        (self.first..=self.last)
            .enumerate()
            .filter(|&(_, bit)| Self::bit(block, bit))
            .fold(0, |value, (i, _)| value | 1 << i)
    }

    /// Sets the area's bits in `block` (the header byte first) to `value`;
    /// bits of `value` that do not fit the area are dropped.
    pub fn set(self, block: &mut [u8], value: u16) {
        for (i, bit) in (self.first..=self.last).enumerate() {
            if let Some(byte) = block.get_mut(1 + usize::from(bit / 8)) {
                let mask = 1 << (bit % 8);
                if value >> i & 1 == 1 {
                    *byte |= mask;
                } else {
                    *byte &= !mask;
                }
            }
        }
    }

    fn bit(block: &[u8], bit: u16) -> bool {
        block
            .get(1 + usize::from(bit / 8))
            .is_some_and(|byte| byte >> (bit % 8) & 1 == 1)
    }
}
