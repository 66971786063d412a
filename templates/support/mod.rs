// The support code every generated layout is built from (gsdc
// templates/support/, written out as the module `gsdc_support`). Bus data is
// big-endian and copied word by word, so everything here has alignment 1, the
// exact size it has on the bus, and needs neither `unsafe` nor an allocator.

/// The PKW channel of MD810-style drives: PKE, IND, PWE.
pub mod pkw_pke_ind_pwe;

/// The PKW channel of MV810-style cards: station, command, address, value.
pub mod pkw_station_command;

/// The PKW channel of the PROFIdrive profile: PKE (AK, SPM, PNU), IND, PWE.
pub mod pkw_profidrive;

/// The device-related diagnosis block of a PROFIBUS slave.
pub mod diagnosis;

/// Gateways: node parameters, their totals, word modules and diagnosis.
pub mod gateway;

/// The device tables: the same types in every layout, for one slave or
/// device that serves any description.
pub mod device;

/// How a drive numbers its parameters: names as the manual writes them.
pub mod numbering;

pub use device::{DiagCode, DpDiagArea, DpDiagnosis, DpGateway, GatewayDiagType};
pub use device::{DpDevice, DpModule, DpParam, NodeTotals, PkwCodec, PzdParam, UserPrm};
pub use device::{GatewayDiagnosis, GatewayNode, PnPzd};
pub use device::{PnDap, PnDevice, PnModule, PnRecord, PnRecordValue, PnSubmodule};
pub use device::{PnSafetyModule, PnSubmoduleRecord, PrmDataType, RecordReading};
pub use numbering::{AddressScheme, Numbering, NumberingPrefix, ParameterName, WrittenPrefix};

/// A 16-bit word as PROFIBUS and PROFINET carry it: big-endian, alignment 1,
/// so a `#[repr(C)]` struct of words has no padding.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[repr(transparent)]
pub struct U16Be([u8; 2]);

const _: () = assert!(core::mem::align_of::<U16Be>() == 1);

impl U16Be {
    pub const fn new(value: u16) -> Self {
        Self(value.to_be_bytes())
    }

    pub const fn get(self) -> u16 {
        u16::from_be_bytes(self.0)
    }

    pub fn set(&mut self, value: u16) {
        self.0 = value.to_be_bytes();
    }
}

/// Bytes of the PKW channel at the start of a telegram that has one.
pub const PKW_BYTES: usize = 8;

/// The words at the start of `bytes`; words past its end stay zero. The
/// telegram structs pass slices of exactly the right length.
pub fn words<const N: usize>(bytes: &[u8]) -> [U16Be; N] {
    let mut words = [U16Be::new(0); N];
    for (word, pair) in words.iter_mut().zip(bytes.chunks_exact(2)) {
        if let [high, low] = *pair {
            *word = U16Be([high, low]);
        }
    }
    words
}

/// Writes `words` to the start of `bytes`, as far as it reaches.
pub fn put_words(bytes: &mut [u8], words: &[U16Be]) {
    for (pair, word) in bytes.chunks_exact_mut(2).zip(words) {
        pair.copy_from_slice(&word.0);
    }
}

/// Words `first` and `first + 1` of `words` as one 32-bit value, high word
/// first. Panics beyond the words.
pub fn double_word(words: &[U16Be], first: usize) -> u32 {
    (u32::from(words[first].get()) << 16) | u32::from(words[first + 1].get())
}

/// Writes `value` to words `first` and `first + 1`, high word first.
pub fn put_double_word(words: &mut [U16Be], first: usize, value: u32) {
    let [a, b, c, d] = value.to_be_bytes();
    words[first] = U16Be([a, b]);
    words[first + 1] = U16Be([c, d]);
}

/// A telegram with the PKW channel: 4 PKW words, then `PZD` PZD words;
/// `BYTES` bytes on the bus. The layouts name each module's telegram with an
/// alias, and check its size where they declare it ([`Self::LEN`]).
#[derive(Clone, Debug, PartialEq, Eq)]
#[repr(C)]
pub struct PkwTelegram<const PZD: usize, const BYTES: usize> {
    pub pkw: [U16Be; 4],
    pub pzd: [U16Be; PZD],
}

impl<const PZD: usize, const BYTES: usize> PkwTelegram<PZD, BYTES> {
    /// `BYTES`, checked at compile time against the words and the type's size.
    pub const LEN: usize = {
        assert!(BYTES == PKW_BYTES + 2 * PZD);
        assert!(core::mem::size_of::<Self>() == BYTES);
        BYTES
    };

    pub fn from_bytes(bytes: &[u8; BYTES]) -> Self {
        let (pkw, pzd) = bytes.split_at(PKW_BYTES);
        let _ = Self::LEN;
        Self {
            pkw: words(pkw),
            pzd: words(pzd),
        }
    }

    pub fn to_bytes(&self) -> [u8; BYTES] {
        let mut bytes = [0; BYTES];
        let (pkw, pzd) = bytes.split_at_mut(PKW_BYTES);
        put_words(pkw, &self.pkw);
        put_words(pzd, &self.pzd);
        bytes
    }
}

impl<const PZD: usize, const BYTES: usize> Default for PkwTelegram<PZD, BYTES> {
    fn default() -> Self {
        Self {
            pkw: [U16Be::new(0); 4],
            pzd: [U16Be::new(0); PZD],
        }
    }
}

/// A telegram of `PZD` PZD words only; `BYTES` bytes on the bus.
#[derive(Clone, Debug, PartialEq, Eq)]
#[repr(C)]
pub struct PzdTelegram<const PZD: usize, const BYTES: usize> {
    pub pzd: [U16Be; PZD],
}

impl<const PZD: usize, const BYTES: usize> PzdTelegram<PZD, BYTES> {
    /// `BYTES`, checked at compile time against the words and the type's size.
    pub const LEN: usize = {
        assert!(BYTES == 2 * PZD);
        assert!(core::mem::size_of::<Self>() == BYTES);
        BYTES
    };

    pub fn from_bytes(bytes: &[u8; BYTES]) -> Self {
        let _ = Self::LEN;
        Self { pzd: words(bytes) }
    }

    pub fn to_bytes(&self) -> [u8; BYTES] {
        let mut bytes = [0; BYTES];
        put_words(&mut bytes, &self.pzd);
        bytes
    }

    /// PZD words `first` and `first + 1` (from 0) as one 32-bit value, high
    /// word first, as PROFINET sends an Unsigned32: standard telegram 2's
    /// NSOLL_B and NIST_B are `double_word(1)`. Panics beyond the words.
    pub fn double_word(&self, first: usize) -> u32 {
        double_word(&self.pzd, first)
    }

    /// Writes `value` to PZD words `first` and `first + 1`, high word first.
    pub fn set_double_word(&mut self, first: usize, value: u32) {
        put_double_word(&mut self.pzd, first, value);
    }
}

impl<const PZD: usize, const BYTES: usize> Default for PzdTelegram<PZD, BYTES> {
    fn default() -> Self {
        Self {
            pzd: [U16Be::new(0); PZD],
        }
    }
}

/// Bits `first..=last` of a control or status word, read as one number.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BitField {
    first: u8,
    last: u8,
}

impl BitField {
    /// Checked where the generated constants are evaluated: at compile time.
    pub const fn new(first: u8, last: u8) -> Self {
        assert!(first <= last && last < 16);
        Self { first, last }
    }

    /// The field's bits set, all others clear.
    pub const fn mask(self) -> u16 {
        (u16::MAX >> (15 - (self.last - self.first))) << self.first
    }

    /// The field's value in `word`.
    pub const fn get(self, word: u16) -> u16 {
        (word & self.mask()) >> self.first
    }

    /// Whether any of the field's bits is set in `word`.
    pub const fn is_set(self, word: u16) -> bool {
        word & self.mask() != 0
    }

    /// `word` with the field set to `value`; bits of `value` that do not fit
    /// the field are dropped.
    pub const fn with(self, word: u16, value: u16) -> u16 {
        (word & !self.mask()) | ((value << self.first) & self.mask())
    }
}

/// What a configurable mapping may hold.
#[derive(Clone, Copy, Debug)]
pub enum Allowed {
    /// Any value from `min` to `max`: a parameter address.
    Range { min: u16, max: u16 },
    /// A value the function accepts: one of the meanings the drive knows.
    Choices(fn(u16) -> bool),
}

impl Allowed {
    pub fn contains(self, value: u16) -> bool {
        match self {
            Allowed::Range { min, max } => (min..=max).contains(&value),
            Allowed::Choices(is_choice) => is_choice(value),
        }
    }
}

/// One configurable mapping: what a PZD word or a DPV1 index carries, or a
/// setting; `bytes` in the parameter telegram and in its record, high byte
/// first.
#[derive(Clone, Copy, Debug)]
pub struct Mapping {
    /// As the device files name it.
    pub name: &'static str,
    /// The PZD word (from 1), record index or setting it configures.
    pub number: u8,
    pub default: u16,
    /// The drive parameter that holds it, when the drive has one.
    pub parameter: Option<u16>,
    pub allowed: Allowed,
    /// 2 (Unsigned16: every mapping), or 1 for a setting of one byte
    /// (Unsigned8, or Integer8 from 0 to 127).
    pub bytes: usize,
}

/// The bytes of a record or telegram block that holds `mappings`.
pub const fn record_len(mappings: &[Mapping]) -> usize {
    let mut len = 0;
    let mut i = 0;
    while i < mappings.len() {
        len += mappings[i].bytes;
        i += 1;
    }
    len
}

/// The value of `mapping` at `offset`.
pub fn read_value(bytes: &[u8], offset: usize, mapping: &Mapping) -> Result<u16, PrmError> {
    match mapping.bytes {
        1 => read_bytes::<1>(bytes, offset).map(|[b]| b.into()),
        _ => read_bytes(bytes, offset).map(u16::from_be_bytes),
    }
}

/// The defaults of `mappings`, in order.
pub const fn defaults<const N: usize>(mappings: &[Mapping; N]) -> [u16; N] {
    let mut values = [0; N];
    let mut i = 0;
    while i < N {
        values[i] = mappings[i].default;
        i += 1;
    }
    values
}

/// Why a parameter telegram or record was refused.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PrmError {
    /// It is `found` bytes long; it must be `expected`.
    Length { expected: usize, found: usize },
    /// The value at byte `offset` is not one its parameter allows (up to
    /// 32 bits: a record value of the access point or a port).
    NotAllowed { offset: usize, value: u32 },
}

/// Refuses `bytes` unless it is exactly `len` long.
pub fn check_len(bytes: &[u8], len: usize) -> Result<(), PrmError> {
    if bytes.len() == len {
        Ok(())
    } else {
        Err(PrmError::Length {
            expected: len,
            found: bytes.len(),
        })
    }
}

/// The `N` bytes at `offset`.
pub fn read_bytes<const N: usize>(bytes: &[u8], offset: usize) -> Result<[u8; N], PrmError> {
    // Saturating: an offset near usize::MAX is refused, not a panic.
    let end = offset.saturating_add(N);
    let found = bytes.get(offset..end).and_then(|b| b.try_into().ok());
    found.ok_or(PrmError::Length {
        expected: end,
        found: bytes.len(),
    })
}

/// The values of `mappings`, each of its bytes from `offset` on, with no
/// gaps, each one checked against what its mapping allows.
pub fn read_values<const N: usize>(
    bytes: &[u8],
    offset: usize,
    mappings: &[Mapping; N],
) -> Result<[u16; N], PrmError> {
    let mut values = [0; N];
    let mut at = offset;
    for (value, mapping) in values.iter_mut().zip(mappings) {
        *value = read_value(bytes, at, mapping)?;
        if !mapping.allowed.contains(*value) {
            return Err(PrmError::NotAllowed {
                offset: at,
                value: (*value).into(),
            });
        }
        at = at.saturating_add(mapping.bytes);
    }
    Ok(values)
}

/// The values of a PROFINET parameter record: exactly the mappings' bytes,
/// each value checked.
pub fn read_record<const N: usize>(
    bytes: &[u8],
    mappings: &[Mapping; N],
) -> Result<[u16; N], PrmError> {
    check_len(bytes, record_len(mappings))?;
    read_values(bytes, 0, mappings)
}

/// The values of a PROFINET record that holds the first of `mappings`
/// (a module's PZD record holds the words the module transports): an
/// Unsigned16 for each of the first `bytes.len() / 2`, each checked; the
/// others keep their defaults. An odd length, or more than `N` values, is
/// refused.
pub fn read_record_prefix<const N: usize>(
    bytes: &[u8],
    mappings: &[Mapping; N],
) -> Result<[u16; N], PrmError> {
    let count = bytes.len() / 2;
    if 2 * count != bytes.len() || count > N {
        return Err(PrmError::Length {
            expected: 2 * N,
            found: bytes.len(),
        });
    }
    let mut values = defaults(mappings);
    for (i, (value, mapping)) in values.iter_mut().zip(mappings).take(count).enumerate() {
        let at = 2 * i;
        *value = u16::from_be_bytes(read_bytes(bytes, at)?);
        if !mapping.allowed.contains(*value) {
            return Err(PrmError::NotAllowed {
                offset: at,
                value: (*value).into(),
            });
        }
    }
    Ok(values)
}
