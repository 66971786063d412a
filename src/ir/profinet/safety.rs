//! PROFIsafe modules: safety IO data ending with the message trailer, the
//! F-parameter record, and the two description CRCs, which gsdc carries
//! as PI's GSDML checker gave them (it cannot compute them: PI's
//! algorithm is for its members) and pins to what they were given for.

use super::{BitItem, Slots, TextRef};
pub use crate::description::safety::{SafetyDataType, F_PARAMETER_ELEMENTS};
use crate::ir::{Fingerprint, Ident};

/// A PROFIsafe module with its one submodule.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct SafetyModule {
    /// ModuleItem ID (`IDM_SAFETY_1`) and its submodule's.
    pub id: String,
    pub submodule_id: String,
    pub ident_number: u32,
    pub submodule_ident_number: u32,
    /// Its name in generated code: `safety_1`.
    pub ident: Ident,
    pub name: TextRef,
    pub info: TextRef,
    pub submodule_name: TextRef,
    pub submodule_info: TextRef,
    /// The ID of the category it is listed under, when it has one.
    pub category: Option<String>,
    pub slots: Slots,
    pub input: Vec<SafetyItem>,
    pub output: Vec<SafetyItem>,
    /// `F_IO_StructureDescVersion`, when stated.
    pub io_structure_desc_version: Option<u8>,
    /// The F-parameter record's index and its elements in the schema's
    /// order: the required ones always, the optional ones when stated.
    pub f_parameter_index: u16,
    pub f_parameters: Vec<FParameter>,
    pub crcs: DescriptionCrcs,
    /// Its submodule's parameter records besides the F-parameters.
    pub records: Vec<super::SubmoduleRecord>,
}

/// A `DataItem` of safety IO data.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct SafetyItem {
    pub data_type: SafetyDataType,
    pub use_as_bits: bool,
    pub text: TextRef,
    pub bits: Vec<BitItem>,
}

/// An F-parameter element with the attributes the description states, as
/// GSDML writes them.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct FParameter {
    pub element: &'static str,
    /// `DefaultValue`, `AllowedValues`, `Visible`, `Changeable`, in that
    /// order, those stated.
    pub attributes: Vec<(&'static str, String)>,
}

/// The attributes of an F-parameter element, in the order gsdc writes
/// them, with the description's key of each.
pub const F_PARAMETER_ATTRIBUTES: [(&str, &str); 4] = [
    ("DefaultValue", "default"),
    ("AllowedValues", "allowed"),
    ("Visible", "visible"),
    ("Changeable", "changeable"),
];

/// `F_ParamDescCRC` and `F_IO_StructureDescCRC`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct DescriptionCrcs {
    pub f_param_desc: u16,
    pub f_io_structure_desc: u32,
    /// Not yet PI's checker's values.
    pub placeholder: bool,
}

impl SafetyDataType {
    /// As GSDML spells it.
    pub fn name(self) -> &'static str {
        match self {
            SafetyDataType::Integer8 => "Integer8",
            SafetyDataType::Integer16 => "Integer16",
            SafetyDataType::Integer32 => "Integer32",
            SafetyDataType::Unsigned8 => "Unsigned8",
            SafetyDataType::Unsigned16 => "Unsigned16",
            SafetyDataType::Unsigned32 => "Unsigned32",
            SafetyDataType::Float32 => "Float32",
            SafetyDataType::Trailer4Byte => "F_MessageTrailer4Byte",
            SafetyDataType::Trailer5Byte => "F_MessageTrailer5Byte",
        }
    }

    pub fn bytes(self) -> u16 {
        match self {
            SafetyDataType::Integer8 | SafetyDataType::Unsigned8 => 1,
            SafetyDataType::Integer16 | SafetyDataType::Unsigned16 => 2,
            SafetyDataType::Integer32 | SafetyDataType::Unsigned32 | SafetyDataType::Float32 => 4,
            SafetyDataType::Trailer4Byte => 4,
            SafetyDataType::Trailer5Byte => 5,
        }
    }

    pub fn is_trailer(self) -> bool {
        matches!(
            self,
            SafetyDataType::Trailer4Byte | SafetyDataType::Trailer5Byte
        )
    }

    /// The type GSDML's name spells.
    pub fn from_name(name: &str) -> Option<Self> {
        ALL_TYPES.into_iter().find(|t| t.name() == name)
    }
}

const ALL_TYPES: [SafetyDataType; 9] = [
    SafetyDataType::Integer8,
    SafetyDataType::Integer16,
    SafetyDataType::Integer32,
    SafetyDataType::Unsigned8,
    SafetyDataType::Unsigned16,
    SafetyDataType::Unsigned32,
    SafetyDataType::Float32,
    SafetyDataType::Trailer4Byte,
    SafetyDataType::Trailer5Byte,
];

/// The name in generated code of safety module `number` (from 1):
/// `safety_module_1`.
pub fn ident_of(number: usize) -> Ident {
    Ident::of(&["safety", "module"]).tagged(number)
}

/// [`ident_of`] as `[[profinet.daps]] modules` names it.
pub fn code_name(number: usize) -> String {
    ident_of(number).snake()
}

impl SafetyModule {
    /// The bytes of its input and of its output data, trailers included.
    pub fn input_bytes(&self) -> u16 {
        self.input.iter().map(|i| i.data_type.bytes()).sum()
    }

    pub fn output_bytes(&self) -> u16 {
        self.output.iter().map(|i| i.data_type.bytes()).sum()
    }

    /// [`crc_fingerprint`] of the module.
    pub fn crc_fingerprint(&self) -> String {
        let shapes = |items: &[SafetyItem]| -> Vec<ItemShape> {
            items
                .iter()
                .map(|i| ItemShape {
                    data_type: i.data_type,
                    use_as_bits: i.use_as_bits,
                    bits: i.bits.iter().map(|b| b.offset).collect(),
                })
                .collect()
        };
        crc_fingerprint(&Described {
            f_parameter_index: self.f_parameter_index,
            f_parameters: &self.f_parameters,
            io_structure_desc_version: self.io_structure_desc_version,
            input: &shapes(&self.input),
            output: &shapes(&self.output),
        })
    }
}

/// What the two CRCs describe, as far as gsdc can tell: the F-parameter
/// record (its index and every element with its attributes) and the IO
/// data's structure (the version, each item's type, `UseAsBits` and bit
/// offsets), without any text.
#[derive(Debug, Clone, Copy)]
pub struct Described<'a> {
    pub f_parameter_index: u16,
    pub f_parameters: &'a [FParameter],
    pub io_structure_desc_version: Option<u8>,
    pub input: &'a [ItemShape],
    pub output: &'a [ItemShape],
}

/// An IO data item without its texts.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ItemShape {
    pub data_type: SafetyDataType,
    pub use_as_bits: bool,
    pub bits: Vec<u8>,
}

/// gsdc's fingerprint of what the CRCs describe: a description's CRCs
/// stated for another fingerprint are stale.
pub fn crc_fingerprint(described: &Described) -> String {
    Fingerprint::of(&canonical_description(described)).to_string()
}

/// One line per element and item, in GSDML's terms.
fn canonical_description(d: &Described) -> String {
    let mut text = format!("F_ParameterRecordDataItem Index={}\n", d.f_parameter_index);
    for p in d.f_parameters {
        text.push_str(p.element);
        for (name, value) in &p.attributes {
            text.push_str(&format!(" {name}={value}"));
        }
        text.push('\n');
    }
    text.push_str("IOData");
    if let Some(version) = d.io_structure_desc_version {
        text.push_str(&format!(" F_IO_StructureDescVersion={version}"));
    }
    text.push('\n');
    for (direction, items) in [("Input", d.input), ("Output", d.output)] {
        text.push_str(direction);
        text.push('\n');
        for item in items {
            let bits: Vec<String> = item.bits.iter().map(u8::to_string).collect();
            text.push_str(&format!(
                "{} UseAsBits={} Bits={}\n",
                item.data_type.name(),
                item.use_as_bits,
                bits.join(",")
            ));
        }
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The text the fingerprint is taken of, written out by hand: a
    /// description's `of` depends on it, so changing it makes every stated
    /// fingerprint stale (E128) and needs a reason.
    #[test]
    fn the_fingerprint_is_of_the_f_parameters_and_the_data_structure_only() {
        let parameters = [
            FParameter {
                element: "F_SIL",
                attributes: vec![("DefaultValue", "SIL3".into())],
            },
            FParameter {
                element: "F_Par_Version",
                attributes: Vec::new(),
            },
        ];
        let bits = |bits: &[u8]| ItemShape {
            data_type: SafetyDataType::Unsigned16,
            use_as_bits: !bits.is_empty(),
            bits: bits.to_vec(),
        };
        let trailer = ItemShape {
            data_type: SafetyDataType::Trailer4Byte,
            use_as_bits: false,
            bits: Vec::new(),
        };
        let input = [bits(&[0, 15]), trailer.clone()];
        let output = [bits(&[]), trailer];
        let described = Described {
            f_parameter_index: 1,
            f_parameters: &parameters,
            io_structure_desc_version: Some(1),
            input: &input,
            output: &output,
        };
        assert_eq!(
            canonical_description(&described),
            "F_ParameterRecordDataItem Index=1\n\
             F_SIL DefaultValue=SIL3\n\
             F_Par_Version\n\
             IOData F_IO_StructureDescVersion=1\n\
             Input\n\
             Unsigned16 UseAsBits=true Bits=0,15\n\
             F_MessageTrailer4Byte UseAsBits=false Bits=\n\
             Output\n\
             Unsigned16 UseAsBits=false Bits=\n\
             F_MessageTrailer4Byte UseAsBits=false Bits=\n"
        );
        let text = canonical_description(&described);
        assert_eq!(
            crc_fingerprint(&described),
            Fingerprint::of(&text).to_string()
        );
    }
}
