// Support code for gateways (gsdc templates/support/gateway.rs): cards that
// carry the data of the nodes of a second bus. The master sets how many
// nodes are in use and the words each one carries each way (User_Prm_Data),
// plugs word modules until its input and output equal the nodes' totals
// (the config bytes), and reads a diagnosis block of type, node and code.

use super::PrmError;

/// How a user parameter is stored: big-endian, or some bits of one byte
/// (`Bits(first, last)`), whose other bits other parameters may hold.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PrmType {
    Unsigned8,
    Unsigned16,
    Bits(u8, u8),
}

/// A user parameter: where it lies in User_Prm_Data, how it is stored, the
/// values it may hold and its default.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PrmField {
    offset: usize,
    data_type: PrmType,
    min: u8,
    max: u8,
    default: u8,
}

impl PrmField {
    /// Checked where the generated constants are evaluated: at compile time.
    pub const fn new(at: usize, kind: PrmType, [min, max]: [u8; 2], default: u8) -> Self {
        if let PrmType::Bits(first, last) = kind {
            assert!(first <= last && last < 8);
            assert!((max as u16) < 1 << (last - first + 1));
        }
        assert!(min <= default && default <= max);
        Self {
            offset: at,
            data_type: kind,
            min,
            max,
            default,
        }
    }

    pub const fn default(self) -> u8 {
        self.default
    }

    /// Whether the parameter may hold `value`.
    pub const fn allows(self, value: u8) -> bool {
        self.min <= value && value <= self.max
    }

    /// Bytes from the offset on.
    const fn len(self) -> usize {
        match self.data_type {
            PrmType::Unsigned16 => 2,
            PrmType::Unsigned8 | PrmType::Bits(..) => 1,
        }
    }

    /// The value in `user_prm`, checked against the parameter's range.
    pub fn read(self, user_prm: &[u8]) -> Result<u8, PrmError> {
        let [high, low] = match self.data_type {
            PrmType::Unsigned16 => super::read_bytes(user_prm, self.offset)?,
            _ => [0, super::read_bytes::<1>(user_prm, self.offset)?[0]],
        };
        let raw = match self.data_type {
            PrmType::Bits(first, last) => u16::from((low & bit_mask(first, last)) >> first),
            _ => u16::from_be_bytes([high, low]),
        };
        match u8::try_from(raw) {
            Ok(value) if self.allows(value) => Ok(value),
            _ => Err(self.not_allowed(raw)),
        }
    }

    /// Writes `value` into `user_prm`, leaving the other bits of a byte the
    /// parameter shares; a value out of its range is refused.
    pub fn write(self, user_prm: &mut [u8], value: u8) -> Result<(), PrmError> {
        if !self.allows(value) {
            return Err(self.not_allowed(value.into()));
        }
        let found = user_prm.len();
        let end = self.offset.saturating_add(self.len());
        let Some(bytes) = user_prm.get_mut(self.offset..end) else {
            return Err(PrmError::Length {
                expected: end,
                found,
            });
        };
        match (self.data_type, bytes) {
            (PrmType::Bits(first, last), [byte]) => {
                let mask = bit_mask(first, last);
                *byte = (*byte & !mask) | ((value << first) & mask);
            }
            (_, bytes) => {
                let be = u16::from(value).to_be_bytes();
                bytes.copy_from_slice(&be[2 - bytes.len()..]);
            }
        }
        Ok(())
    }

    fn not_allowed(self, value: u16) -> PrmError {
        PrmError::NotAllowed {
            offset: self.offset,
            value: value.into(),
        }
    }
}

const fn bit_mask(first: u8, last: u8) -> u8 {
    (u8::MAX >> (7 - (last - first))) << first
}

/// The values of `fields`, each checked.
pub fn read_fields<const N: usize>(
    user_prm: &[u8],
    fields: &[PrmField; N],
) -> Result<[u8; N], PrmError> {
    let mut values = [0; N];
    for (value, field) in values.iter_mut().zip(fields) {
        *value = field.read(user_prm)?;
    }
    Ok(values)
}

/// Writes `values` into `fields`, each checked.
pub fn write_fields<const N: usize>(
    user_prm: &mut [u8],
    fields: &[PrmField; N],
    values: &[u8; N],
) -> Result<(), PrmError> {
    for (field, &value) in fields.iter().zip(values) {
        field.write(user_prm, value)?;
    }
    Ok(())
}

/// The defaults of `fields`, in order.
pub const fn defaults<const N: usize>(fields: &[PrmField; N]) -> [u8; N] {
    let mut values = [0; N];
    let mut i = 0;
    while i < N {
        values[i] = fields[i].default;
        i += 1;
    }
    values
}

/// Which way a node's words go: `In` the node sends (the master's input),
/// `Out` it receives.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    In,
    Out,
}

/// A gateway's node parameters, from node `first_node` on, and its data
/// limits in bytes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NodeParams<const N: usize> {
    pub first_node: u8,
    pub node_count: PrmField,
    pub input_words: [PrmField; N],
    pub output_words: [PrmField; N],
    pub max_input_len: usize,
    pub max_output_len: usize,
}

/// The words of input and output a configuration carries.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Totals {
    pub input_words: u16,
    pub output_words: u16,
}

impl Totals {
    /// Bytes of input: the master's input modules carry as many.
    pub const fn input_len(self) -> usize {
        2 * self.input_words as usize
    }

    /// Bytes of output.
    pub const fn output_len(self) -> usize {
        2 * self.output_words as usize
    }
}

/// Why a node configuration was refused.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TotalsError {
    /// More nodes, or fewer, than the count's parameter allows.
    NodeCount { count: u8 },
    /// A node in use carries words its parameter does not allow.
    Words {
        node: u8,
        direction: Direction,
        words: u8,
    },
    /// A node past the count carries words.
    UnusedNode { node: u8 },
    /// `len` bytes of input or output; the gateway carries at most `max`.
    TooLong {
        direction: Direction,
        len: usize,
        max: usize,
    },
}

/// The totals of the first `count` nodes' words, each within its
/// parameter's range, the nodes past the count without words, and each
/// total within the gateway's limit.
pub const fn totals<const N: usize>(
    params: &NodeParams<N>,
    count: u8,
    input: &[u8; N],
    output: &[u8; N],
) -> Result<Totals, TotalsError> {
    if !params.node_count.allows(count) || count as usize > N {
        return Err(TotalsError::NodeCount { count });
    }
    let (mut input_words, mut output_words) = (0u16, 0u16);
    let mut i = 0;
    while i < N {
        let node = params.first_node + i as u8;
        if i >= count as usize {
            if input[i] != 0 || output[i] != 0 {
                return Err(TotalsError::UnusedNode { node });
            }
        } else if !params.input_words[i].allows(input[i]) {
            return Err(TotalsError::Words {
                node,
                direction: Direction::In,
                words: input[i],
            });
        } else if !params.output_words[i].allows(output[i]) {
            return Err(TotalsError::Words {
                node,
                direction: Direction::Out,
                words: output[i],
            });
        }
        input_words += input[i] as u16;
        output_words += output[i] as u16;
        i += 1;
    }
    let totals = Totals {
        input_words,
        output_words,
    };
    if totals.input_len() > params.max_input_len {
        return Err(TotalsError::TooLong {
            direction: Direction::In,
            len: totals.input_len(),
            max: params.max_input_len,
        });
    }
    if totals.output_len() > params.max_output_len {
        return Err(TotalsError::TooLong {
            direction: Direction::Out,
            len: totals.output_len(),
            max: params.max_output_len,
        });
    }
    Ok(totals)
}

/// Where node `node`'s words start in the data one way, in bytes, when the
/// nodes in use follow each other in ascending node number: after the
/// words of the nodes before it. `None` for a node not in use.
pub const fn data_offset<const N: usize>(
    params: &NodeParams<N>,
    count: u8,
    words: &[u8; N],
    node: u8,
) -> Option<usize> {
    if node < params.first_node {
        return None;
    }
    let index = (node - params.first_node) as usize;
    if index >= count as usize || index >= N {
        return None;
    }
    let mut offset = 0;
    let mut i = 0;
    while i < index {
        offset += 2 * words[i] as usize;
        i += 1;
    }
    Some(offset)
}

/// Why the config bytes of the plugged modules were refused.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CfgError {
    /// Byte `at` is no module's config byte.
    Unknown { at: usize, byte: u8 },
    /// More modules than Max_Module.
    TooMany { modules: usize, max: usize },
}

/// The words of input and output the plugged modules carry: `config` has
/// one config identifier byte per module, each one of `modules` (general
/// identifiers of words: bits 5-4 direction, bits 3-0 words - 1).
pub fn config_totals(
    config: &[u8],
    modules: &[u8],
    max_modules: usize,
) -> Result<Totals, CfgError> {
    if config.len() > max_modules {
        return Err(CfgError::TooMany {
            modules: config.len(),
            max: max_modules,
        });
    }
    let mut totals = Totals {
        input_words: 0,
        output_words: 0,
    };
    for (at, &byte) in config.iter().enumerate() {
        let words = u16::from(byte & 0x0F) + 1;
        match byte & 0x30 {
            _ if !modules.contains(&byte) => return Err(CfgError::Unknown { at, byte }),
            0x10 => totals.input_words += words,
            0x20 => totals.output_words += words,
            _ => return Err(CfgError::Unknown { at, byte }),
        }
    }
    Ok(totals)
}

/// Why a diagnosis block was refused.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DiagError {
    /// The header is not a device-related block's (bits 7-6 = 00).
    Header {
        byte: u8,
    },
    /// `len` bytes; the header or the type needs `expected`.
    Short {
        expected: usize,
        len: usize,
    },
    /// The header says `found` bytes; blocks of this type have `expected`.
    Length {
        expected: u8,
        found: u8,
    },
    Type {
        value: u8,
    },
    Node {
        value: u8,
    },
    /// A code its type does not list.
    Code {
        kind: u8,
        value: u8,
    },
}

/// Where a gateway's diagnosis block holds the type, the node and the code
/// (the header being byte 0), the node numbers and the types there are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DiagLayout {
    pub type_at: usize,
    pub node_at: usize,
    pub code_at: usize,
    pub first_node: u8,
    pub last_node: u8,
    pub types: &'static [u8],
}

/// The type and the node of `block` (the header byte first), and the block
/// as long as its header says; bytes after it belong to what follows.
pub fn read_diag<'a>(
    block: &'a [u8],
    layout: &DiagLayout,
) -> Result<(u8, u8, &'a [u8]), DiagError> {
    let Some(&header) = block.first() else {
        return Err(DiagError::Short {
            expected: 1,
            len: 0,
        });
    };
    if header & 0xC0 != 0 {
        return Err(DiagError::Header { byte: header });
    }
    let len = usize::from(header);
    let block = block.get(..len).ok_or(DiagError::Short {
        expected: len,
        len: block.len(),
    })?;
    let at = |index: usize| {
        block.get(index).copied().ok_or(DiagError::Short {
            expected: index + 1,
            len,
        })
    };
    let (kind, node) = (at(layout.type_at)?, at(layout.node_at)?);
    if !layout.types.contains(&kind) {
        return Err(DiagError::Type { value: kind });
    }
    if node < layout.first_node || node > layout.last_node {
        return Err(DiagError::Node { value: node });
    }
    Ok((kind, node, block))
}

/// The one-byte code of a block of type `kind`, whose blocks have `len`
/// bytes, as the type's code (`code` gives it for the values it lists).
pub fn code_byte<T>(
    block: &[u8],
    (kind, len): (u8, u8),
    layout: &DiagLayout,
    code: fn(u16) -> Option<T>,
) -> Result<T, DiagError> {
    let [value] = code_bytes(block, len, layout)?;
    code(value.into()).ok_or(DiagError::Code { kind, value })
}

/// The 16-bit code, high byte first, of a block whose type has blocks of
/// `len` bytes.
pub fn code_word(block: &[u8], len: u8, layout: &DiagLayout) -> Result<u16, DiagError> {
    Ok(u16::from_be_bytes(code_bytes(block, len, layout)?))
}

fn code_bytes<const N: usize>(
    block: &[u8],
    len: u8,
    layout: &DiagLayout,
) -> Result<[u8; N], DiagError> {
    // read_diag cut the block to its header's length.
    let found = u8::try_from(block.len()).unwrap_or(u8::MAX);
    if found != len {
        return Err(DiagError::Length {
            expected: len,
            found,
        });
    }
    let code = block.get(layout.code_at..layout.code_at + N);
    code.and_then(|c| c.try_into().ok())
        .ok_or(DiagError::Short {
            expected: layout.code_at + N,
            len: block.len(),
        })
}

/// A diagnosis block as the slave sends it: the header, the type, the node
/// and the code; `MAX` bytes hold the longest block.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DiagBlock<const MAX: usize> {
    bytes: [u8; MAX],
    len: usize,
}

impl<const MAX: usize> DiagBlock<MAX> {
    /// A block of `len` bytes (the header says so) of type `kind` at `node`;
    /// its code follows with [`Self::with_code_byte`] or
    /// [`Self::with_code_word`].
    pub const fn new(len: u8, layout: &DiagLayout, kind: u8, node: u8) -> Self {
        let mut bytes = [0; MAX];
        bytes[0] = len;
        bytes[layout.type_at] = kind;
        bytes[layout.node_at] = node;
        Self {
            bytes,
            len: len as usize,
        }
    }

    pub const fn with_code_byte(mut self, layout: &DiagLayout, code: u8) -> Self {
        self.bytes[layout.code_at] = code;
        self
    }

    pub const fn with_code_word(mut self, layout: &DiagLayout, code: u16) -> Self {
        let [high, low] = code.to_be_bytes();
        self.bytes[layout.code_at] = high;
        self.bytes[layout.code_at + 1] = low;
        self
    }

    pub fn as_bytes(&self) -> &[u8] {
        &self.bytes[..self.len]
    }
}
