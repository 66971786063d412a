//! A [`DpDevice`] from what the GSD reader made of a file ([`GsdFile`]).

use std::ops::Range;

use super::dp::{DiagArea, DiagBit, DiagType, DiagValue, DpDevice, DpModule, DpSlot, Keyword};
use super::{Allowed, Bits, Choice, ConstBytes, Field, ParameterData, Place, Text, Value};
use crate::diag::Lines;
use crate::gsd::prm::{self, Family};
use crate::gsd::{
    self, Arg, ExtUserPrmData, GsdFile, IndexedText, PrmDataType, Setting, UnitDiagArea,
};

/// The device of a GSD file, from the reader's model and the text it read
/// (for lines). `file_name` is the file's own name, when there is one.
pub fn read(file: &GsdFile, text: &str, file_name: Option<&str>) -> DpDevice {
    let reader = Reader {
        file,
        lines: Lines::of(text),
        params: prm::by_id(file),
    };
    DpDevice {
        file_name: file_name.map(str::to_string),
        keywords: reader.top_keywords(),
        user_prm_data: reader.parameters(&file.settings, Family::Plain, "user_prm_data_len"),
        modules: file.modules.iter().map(|m| reader.module(m)).collect(),
        slots: file.slots.iter().map(|s| reader.slot(s)).collect(),
        diagnosis: reader.diagnosis(),
    }
}

/// Top-level keywords the parts of [`DpDevice`] other than `keywords` hold.
const TOP_PARTS: &[&str] = &[
    "ext_user_prm_data_const",
    "ext_user_prm_data_ref",
    "user_prm_data",
    "user_prm_data_len",
    "unit_diag_bit",
    "unit_diag_not_bit",
    "unit_diag_bit_help",
    "unit_diag_not_bit_help",
    "channel_diag",
];

/// A module's keywords its parameter data holds.
const MODULE_PARTS: &[&str] = &[
    "ext_user_prm_data_const",
    "ext_user_prm_data_ref",
    "ext_module_prm_data_len",
    "f_ext_user_prm_data_const",
    "f_ext_user_prm_data_ref",
    "f_ext_module_prm_data_len",
    "module_reference",
];

struct Reader<'a> {
    file: &'a GsdFile,
    lines: Lines,
    params: foldhash::HashMap<i64, &'a ExtUserPrmData>,
}

impl Reader<'_> {
    fn place(&self, span: &Range<usize>) -> Place {
        Place {
            line: self.lines.line(span.start),
            path: None,
        }
    }

    fn keyword(&self, setting: &Setting, block: Option<&str>) -> Keyword {
        let mut key = setting.key.to_string();
        if let Some(Arg::Baud(baud)) = setting.arg {
            key = key.replacen(&baud.as_str().to_ascii_lowercase(), "<baud>", 1);
        }
        let (name, key) = match block {
            Some(block) => (
                format!("{block}/{}", setting.name),
                format!("{block}/{key}"),
            ),
            None => (setting.name.to_string(), key),
        };
        Keyword {
            name,
            key: key.to_ascii_lowercase(),
            arg: setting.arg,
            value: setting.value.clone(),
            place: self.place(&setting.span),
        }
    }

    fn top_keywords(&self) -> Vec<Keyword> {
        let own = self
            .file
            .settings
            .iter()
            .filter(|s| !TOP_PARTS.contains(&&*s.key))
            .map(|s| self.keyword(s, None));
        let blocks = self.blocks(&self.file.blocks);
        own.chain(blocks).collect()
    }

    /// The keywords of blocks (`Physical_Interface`, a module's
    /// `Data_Area_Beg`), each named after its block and the block's number
    /// among those of its keyword: the block's own keyword with its value,
    /// then those inside.
    fn blocks(&self, blocks: &[gsd::Block]) -> Vec<Keyword> {
        let mut out = Vec::new();
        for (i, block) in blocks.iter().enumerate() {
            let header = &block.header;
            let nth = blocks[..i]
                .iter()
                .filter(|b| b.header.key == header.key)
                .count();
            let prefix = format!("{}({nth})", header.name);
            let mut own = self.keyword(header, None);
            own.key = format!("{}({nth})", header.key).to_ascii_lowercase();
            own.name.clone_from(&prefix);
            out.push(own);
            out.extend(
                block
                    .settings
                    .iter()
                    .map(|s| self.keyword(s, Some(&prefix))),
            );
        }
        out
    }

    /// The parameter data of `settings` (the station's or a module's) of
    /// one family, with the length its `length_key` declares.
    fn parameters(&self, settings: &[Setting], family: Family, length_key: &str) -> ParameterData {
        let layout = prm::layout(settings, family);
        let length = gsd_model_find(settings, length_key)
            .and_then(|s| s.value.as_number())
            .and_then(|n| u32::try_from(n).ok());
        let mut consts: Vec<ConstBytes> = layout
            .consts
            .iter()
            .filter_map(|c| {
                Some(ConstBytes {
                    byte_offset: u32::try_from(c.offset).ok()?,
                    bytes: c.bytes.iter().map(|&b| b as u8).collect(),
                    place: self.place(&c.setting.span),
                })
            })
            .collect();
        if layout.is_empty() && family == Family::Plain {
            // A file of GSD revision 0 or 1 gives the bytes alone.
            consts.extend(gsd_model_find(settings, "user_prm_data").and_then(|s| {
                Some(ConstBytes {
                    byte_offset: 0,
                    bytes: s.value.as_list()?.iter().map(|&b| b as u8).collect(),
                    place: self.place(&s.span),
                })
            }));
        }
        let fields = layout
            .refs
            .iter()
            .filter_map(|r| {
                let data = self.params.get(&r.id)?;
                self.field(data, u32::try_from(r.offset).ok()?, &r.setting.span)
            })
            .collect();
        ParameterData {
            length,
            consts,
            fields,
        }
    }

    /// The parameter an `ExtUserPrmData` block describes, placed at
    /// `byte_offset` by the reference at `at`; `None` when the block has no
    /// type line.
    fn field(&self, data: &ExtUserPrmData, byte_offset: u32, at: &Range<usize>) -> Option<Field> {
        let data_type = &data.data_type.as_ref()?.value;
        let (type_name, bits) = match data_type {
            PrmDataType::Bit(b) => (
                "Bit".to_string(),
                Some(Bits {
                    offset: *b,
                    length: 1,
                }),
            ),
            PrmDataType::BitArea(first, last) => (
                "BitArea".to_string(),
                Some(Bits {
                    offset: *first,
                    length: last.saturating_sub(*first).saturating_add(1),
                }),
            ),
            PrmDataType::Unsigned8 => ("Unsigned8".to_string(), None),
            PrmDataType::Unsigned16 => ("Unsigned16".to_string(), None),
            PrmDataType::Unsigned32 => ("Unsigned32".to_string(), None),
            PrmDataType::Signed8 => ("Signed8".to_string(), None),
            PrmDataType::Signed16 => ("Signed16".to_string(), None),
            PrmDataType::Signed32 => ("Signed32".to_string(), None),
            PrmDataType::Other(name) => (name.clone(), None),
        };
        Some(Field {
            byte_offset,
            bits,
            data_type: type_name,
            length: None,
            name: Text::plain(&data.name.value),
            default: data.default.as_ref().map(|d| Value::Int(d.value.into())),
            allowed: allowed(&data.allowed.value),
            choices: self.choices(data),
            changeable: data.changeable.unwrap_or(true),
            visible: data.visible.unwrap_or(true),
            // The block's other lines are the three above: nothing else to keep.
            attributes: Vec::new(),
            place: self.place(at),
        })
    }

    fn choices(&self, data: &ExtUserPrmData) -> Vec<Choice> {
        let Some(texts) = data
            .prm_text_ref
            .as_ref()
            .and_then(|r| self.file.prm_text(r.value))
        else {
            return Vec::new();
        };
        texts
            .texts
            .iter()
            .map(|t| Choice {
                value: Value::Int(t.index.into()),
                text: Text::plain(&t.text.value),
            })
            .collect()
    }

    fn module(&self, module: &gsd::Module) -> DpModule {
        let own = module
            .settings
            .iter()
            .filter(|s| !MODULE_PARTS.contains(&&*s.key))
            .map(|s| self.keyword(s, None));
        let areas = self.blocks(&module.data_areas);
        DpModule {
            name: module.name.value.clone(),
            config: module.config.value.clone(),
            reference: module.reference.as_ref().map(|r| r.value),
            io: module.io_lengths().ok().map(|io| (io.input, io.output)),
            keywords: own.chain(areas).collect(),
            user_prm_data: self.parameters(
                &module.settings,
                Family::Plain,
                "ext_module_prm_data_len",
            ),
            safety_prm_data: self.parameters(
                &module.settings,
                Family::Safety,
                "f_ext_module_prm_data_len",
            ),
            place: self.place(&module.span),
        }
    }

    fn slot(&self, slot: &gsd::Slot) -> DpSlot {
        DpSlot {
            number: slot.number,
            name: Text::plain(&slot.name.value),
            default: slot.default.value,
            allowed: allowed(&slot.allowed.value),
            place: self.place(&slot.span),
        }
    }

    fn diagnosis(&self) -> super::dp::DpDiagnosis {
        let settings = &self.file.settings;
        super::dp::DpDiagnosis {
            bits: self.diag_bits(settings, ""),
            areas: self
                .file
                .unit_diag_areas
                .iter()
                .map(|a| self.area(a))
                .collect(),
            types: self
                .file
                .unit_diag_types
                .iter()
                .map(|t| DiagType {
                    id: t.id.value,
                    bits: self.diag_bits(&t.settings, "x_"),
                    areas: t.areas.iter().map(|a| self.area(a)).collect(),
                    place: self.place(&t.span),
                })
                .collect(),
            channel: settings
                .iter()
                .filter(|s| s.key == "channel_diag")
                .filter_map(|s| self.diag_value(s))
                .collect(),
        }
    }

    /// `Unit_Diag_Bit(n)` and `Unit_Diag_Not_Bit(n)` among `settings` (with
    /// `prefix` `x_` inside a `UnitDiagType`), each with its help text.
    fn diag_bits(&self, settings: &[Setting], prefix: &str) -> Vec<DiagBit> {
        let help = |key: &str, bit: i64| {
            settings
                .iter()
                .find(|s| s.key == key && s.index() == Some(bit))
                .and_then(|s| s.value.as_str())
                .map(Text::plain)
        };
        let mut bits = Vec::new();
        for (key, when_clear) in [("unit_diag_bit", false), ("unit_diag_not_bit", true)] {
            let key = format!("{prefix}{key}");
            let help_key = format!("{key}_help");
            for s in settings.iter().filter(|s| s.key == key) {
                let (Some(bit), Some(text)) = (s.index(), s.value.as_str()) else {
                    continue;
                };
                bits.push(DiagBit {
                    bit,
                    when_clear,
                    text: Text::plain(text),
                    help: help(&help_key, bit),
                    place: self.place(&s.span),
                });
            }
        }
        bits
    }

    fn diag_value(&self, s: &Setting) -> Option<DiagValue> {
        Some(DiagValue {
            value: s.index()?,
            text: Text::plain(s.value.as_str()?),
            place: self.place(&s.span),
        })
    }

    fn area(&self, area: &UnitDiagArea) -> DiagArea {
        DiagArea {
            first: area.first,
            last: area.last,
            values: area.values.iter().map(|v| self.area_value(v)).collect(),
            place: self.place(&area.span),
        }
    }

    fn area_value(&self, value: &IndexedText) -> DiagValue {
        DiagValue {
            value: value.index,
            text: Text::plain(&value.text.value),
            place: self.place(&value.span),
        }
    }
}

fn gsd_model_find<'a>(settings: &'a [Setting], name: &str) -> Option<&'a Setting> {
    crate::gsd::model::find(settings, name)
}

fn allowed(allowed: &gsd::Allowed) -> Allowed {
    match allowed {
        gsd::Allowed::Any => Allowed::Any,
        gsd::Allowed::Range(lo, hi) => {
            Allowed::Ranges(vec![(Value::Int((*lo).into()), Value::Int((*hi).into()))])
        }
        gsd::Allowed::Set(values) => Allowed::Ranges(
            values
                .iter()
                .map(|&v| (Value::Int(v.into()), Value::Int(v.into())))
                .collect(),
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TEXT: &str = "#Profibus_DP\r\n\
GSD_Revision = 5\r\n\
Ident_Number = 0x0810\r\n\
Revision = \"V1.00\"\r\n\
12M_supp = 1\r\n\
MaxTsdr_12M = 800\r\n\
1.5M_supp = 1\r\n\
MaxTsdr_1.5M = 150\r\n\
Unit_Diag_Bit(3) = \"Overheated\"\r\n\
Unit_Diag_Area = 8-15\r\n\
Value(52) = \"Lost the drive\"\r\n\
Unit_Diag_Area_End\r\n\
PrmText = 1\r\n\
Text(0) = \"Off\"\r\n\
Text(1) = \"On\"\r\n\
EndPrmText\r\n\
ExtUserPrmData = 7 \"Fast\"\r\n\
Bit(2) 1 0-1\r\n\
Prm_Text_Ref = 1\r\n\
EndExtUserPrmData\r\n\
ExtUserPrmData = 8 \"Address\"\r\n\
Unsigned16 61440 0-65535\r\n\
EndExtUserPrmData\r\n\
Ext_User_Prm_Data_Const(0) = 0x80,0x00,0x08\r\n\
Ext_User_Prm_Data_Ref(3) = 7\r\n\
Module = \"PPO1\" 0xF3,0xF1\r\n\
1\r\n\
Ext_Module_Prm_Data_Len = 2\r\n\
Ext_User_Prm_Data_Ref(0) = 8\r\n\
Info_Text = \"four words\"\r\n\
EndModule\r\n";

    fn device() -> DpDevice {
        let (file, _) = crate::gsd::parse(TEXT);
        read(&file, TEXT, Some("X.GSD"))
    }

    #[test]
    fn keywords_identity_and_baud_rates() {
        let d = device();
        assert_eq!(d.ident_number(), Some(0x0810));
        assert_eq!(d.revision(), Some("V1.00"));
        assert_eq!(
            d.baud_rates(),
            [(gsd::Baud::B1M5, Some(150)), (gsd::Baud::B12M, Some(800))]
        );
        let tsdr = d.keywords.iter().find(|k| k.name == "MaxTsdr_12M").unwrap();
        assert_eq!(tsdr.key, "maxtsdr_<baud>");
        assert_eq!(tsdr.place.line, 6);
        // Parts held elsewhere are not keywords.
        assert!(d.keyword("Unit_Diag_Bit").is_none());
        assert!(d.keyword("Ext_User_Prm_Data_Const").is_none());
    }

    #[test]
    fn parameters_with_their_offsets_bits_and_choices() {
        let d = device();
        let prm = &d.user_prm_data;
        assert_eq!(prm.consts[0].bytes, [0x80, 0x00, 0x08]);
        assert_eq!(prm.len(), 4);
        let fast = &prm.fields[0];
        assert_eq!(
            (fast.byte_offset, fast.bits),
            (
                3,
                Some(Bits {
                    offset: 2,
                    length: 1
                })
            )
        );
        assert_eq!(fast.data_type, "Bit");
        assert_eq!(fast.default, Some(Value::Int(1)));
        assert_eq!(fast.choices[1].text, Text::plain("On"));
        assert_eq!(fast.place.line, 25);
        let module = &d.modules[0];
        assert_eq!(
            (module.config.clone(), module.io),
            (vec![0xF3, 0xF1], Some((12, 12)))
        );
        assert_eq!(module.reference, Some(1));
        assert_eq!(module.user_prm_data.length, Some(2));
        assert_eq!(module.user_prm_data.fields[0].data_type, "Unsigned16");
        let names: Vec<&str> = module.keywords.iter().map(|k| k.name.as_str()).collect();
        assert_eq!(names, ["Info_Text"]);
    }

    #[test]
    fn diagnosis_bits_and_areas() {
        let d = device();
        assert_eq!(d.diagnosis.bits[0].bit, 3);
        assert_eq!(d.diagnosis.bits[0].text, Text::plain("Overheated"));
        let area = &d.diagnosis.areas[0];
        assert_eq!((area.first, area.last), (8, 15));
        assert_eq!(area.values[0].value, 52);
        assert_eq!(area.values[0].place.line, 11);
    }
}
