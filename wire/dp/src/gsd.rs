//! The master's side of the GSD file, as an engineering tool reads it:
//! gsd-parser's model of the file, the parameters by name, each module's
//! config bytes and what they say of its data lengths, the diagnosis texts.
//! Nothing here reads a layout: the master knows the slave only from the
//! GSD.

use std::path::Path;

use gsd_parser::{GenericStationDescription, Module, PrmBuilder, PrmValueConstraint};

/// A GSD file, read.
pub struct Gsd {
    pub file_name: String,
    pub description: GenericStationDescription,
    /// The fingerprint of the description gsdc built it from, when gsdc
    /// did (its header says).
    pub fingerprint: Option<String>,
}

impl Gsd {
    /// Reads the GSD at `path`; the parser's message when it cannot.
    pub fn read(path: &Path) -> Result<Gsd, String> {
        let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
        // GSD files are Latin-1 (IEC 61784-1); gsd-parser takes text.
        let text: String = bytes.iter().map(|&b| char::from(b)).collect();
        let description = gsd_parser::parser::parse(path, &text).map_err(|e| e.to_string())?;
        let fingerprint = text
            .lines()
            .find_map(|l| l.strip_prefix("; Description fingerprint: "))
            .map(|f| f.trim().to_string());
        Ok(Gsd {
            file_name: path.file_name().unwrap().to_string_lossy().into_owned(),
            description,
            fingerprint,
        })
    }

    pub fn ident_number(&self) -> u16 {
        self.description.ident_number
    }

    /// The modules the GSD offers, in its order.
    pub fn modules(&self) -> impl Iterator<Item = &Module> {
        self.description
            .available_modules
            .iter()
            .map(|m| m.as_ref())
    }

    /// User_Prm_Data with every parameter at its default.
    pub fn default_prm(&self) -> Vec<u8> {
        PrmBuilder::new(&self.description.user_prm_data).into_bytes()
    }

    /// User_Prm_Data with the parameters named in `values` set, the others
    /// at their defaults. A name the GSD does not have, or a value its
    /// parameter does not allow, is refused (gsd-parser would panic).
    pub fn prm(&self, values: &[(String, i64)]) -> Result<Vec<u8>, String> {
        let prm = &self.description.user_prm_data;
        let mut builder = PrmBuilder::new(prm);
        for (name, value) in values {
            let parameter = self
                .parameter(name)
                .ok_or_else(|| format!("{}: no parameter named {name:?}", self.file_name))?;
            if !parameter.constraint.is_valid(*value) {
                return Err(format!(
                    "{}: {name:?} does not allow {value} ({:?})",
                    self.file_name, parameter.constraint
                ));
            }
            builder.set_prm(name, *value);
        }
        Ok(builder.into_bytes())
    }

    /// Every parameter of User_Prm_Data: its name, its offset, its default.
    pub fn parameters(&self) -> impl Iterator<Item = Parameter<'_>> {
        let data_ref = &self.description.user_prm_data.data_ref;
        data_ref.iter().map(|(offset, definition)| Parameter {
            name: &definition.name,
            offset: *offset,
            default: definition.default_value,
            constraint: &definition.constraint,
        })
    }

    fn parameter(&self, name: &str) -> Option<Parameter<'_>> {
        self.parameters().find(|p| p.name == name)
    }

    /// The text the GSD's `Unit_Diag_Area`s give for the device-related
    /// block `block` (its header byte first), area by area: "8-15: 52 = ..."
    /// or the value alone when the area has no text for it.
    pub fn diagnosis_texts(&self, block: &[u8]) -> Vec<String> {
        let areas = &self.description.unit_diag.areas;
        areas
            .iter()
            .map(|area| {
                let value = area_value(block, area.first, area.last);
                match area.values.get(&value) {
                    Some(text) => format!("{}-{}: {value} = {text:?}", area.first, area.last),
                    None => format!("{}-{}: {value}", area.first, area.last),
                }
            })
            .collect()
    }
}

/// A parameter of User_Prm_Data, as the GSD declares it.
#[derive(Clone, Copy, Debug)]
pub struct Parameter<'a> {
    pub name: &'a str,
    pub offset: usize,
    pub default: i64,
    pub constraint: &'a PrmValueConstraint,
}

impl Parameter<'_> {
    /// A value the parameter allows other than its default, when it has one:
    /// `nth` below the top of its range (so that the parameters of a
    /// telegram get values of their own, and a parameter at the wrong
    /// offset shows), or its first other choice.
    pub fn other_value(&self, nth: usize) -> Option<i64> {
        match self.constraint {
            PrmValueConstraint::MinMax(min, max) => {
                let near_top = (max - nth as i64).max(*min);
                [near_top, *max, *min]
                    .into_iter()
                    .find(|v| *v != self.default)
            }
            PrmValueConstraint::Enum(values) => values.iter().copied().find(|v| *v != self.default),
            PrmValueConstraint::Unconstrained => None,
        }
    }
}

/// Bits `first..=last` of a device-related block, numbered as the GSD
/// numbers them: bit 0 is the lowest bit of the byte after the header.
fn area_value(block: &[u8], first: u16, last: u16) -> u16 {
    (first..=last)
        .enumerate()
        .filter(|&(_, bit)| {
            let byte = block.get(1 + usize::from(bit / 8)).copied().unwrap_or(0);
            byte >> (bit % 8) & 1 == 1
        })
        .fold(0, |value, (i, _)| value | 1 << i)
}

/// The bytes of input and of output a module's config bytes declare (the
/// identifier formats of IEC 61158-6-3: the general format in one byte, the
/// special format with length bytes and manufacturer bytes).
pub fn data_lengths(config: &[u8]) -> Result<(usize, usize), String> {
    let mut inputs = 0;
    let mut outputs = 0;
    let mut bytes = config.iter().copied();
    while let Some(identifier) = bytes.next() {
        let direction = identifier >> 4 & 0b11;
        if direction != 0 {
            // General format: bits 5-4 the direction, bit 6 words, bits 3-0
            // the length less one.
            let len = length(identifier & 0x0F, identifier & 0x40 != 0);
            if direction & 0b01 != 0 {
                inputs += len;
            }
            if direction & 0b10 != 0 {
                outputs += len;
            }
            continue;
        }
        // Special format: bits 7-6 say which length bytes follow (output
        // first), bits 3-0 how many manufacturer bytes after them.
        let mut length_byte = || {
            let byte = bytes
                .next()
                .ok_or_else(|| format!("config bytes {config:02X?} end inside an identifier"))?;
            Ok::<usize, String>(length(byte & 0x3F, byte & 0x40 != 0))
        };
        match identifier >> 6 {
            0b10 => outputs += length_byte()?,
            0b01 => inputs += length_byte()?,
            0b11 => {
                outputs += length_byte()?;
                inputs += length_byte()?;
            }
            _ => {}
        }
        for _ in 0..identifier & 0x0F {
            bytes.next();
        }
    }
    Ok((inputs, outputs))
}

/// Bytes of a length field: `field + 1` bytes or words.
fn length(field: u8, words: bool) -> usize {
    let units = usize::from(field) + 1;
    if words {
        2 * units
    } else {
        units
    }
}
