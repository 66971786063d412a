//! Values that may be written in more than one way in a description. Each has
//! a hand-written `Deserialize` so that the value keeps its span (serde's
//! untagged enums would lose it).

use serde::de::{self, Deserializer, MapAccess, SeqAccess, Visitor};
use serde::Deserialize;
use std::fmt;
use toml::Spanned;

/// A parameter address: a number, or a function-code name like `F0-12`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Address {
    Number(i64),
    Name(String),
}

impl<'de> Deserialize<'de> for Address {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct AddressVisitor;
        impl Visitor<'_> for AddressVisitor {
            type Value = Address;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a number or a function-code name like \"F0-12\"")
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<Address, E> {
                Ok(Address::Number(v))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<Address, E> {
                i64::try_from(v)
                    .map(Address::Number)
                    .map_err(|_| E::custom("number too large"))
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<Address, E> {
                Ok(Address::Name(v.to_string()))
            }
        }
        deserializer.deserialize_any(AddressVisitor)
    }
}

/// One bit (`bit = 3`) or an inclusive range of bits (`bit = [9, 10]`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BitRange {
    pub first: i64,
    pub last: i64,
}

impl<'de> Deserialize<'de> for BitRange {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct BitVisitor;
        impl<'de> Visitor<'de> for BitVisitor {
            type Value = BitRange;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a bit number or [first, last]")
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<BitRange, E> {
                Ok(BitRange { first: v, last: v })
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<BitRange, A::Error> {
                let first = seq
                    .next_element()?
                    .ok_or_else(|| de::Error::invalid_length(0, &self))?;
                let last = seq
                    .next_element()?
                    .ok_or_else(|| de::Error::invalid_length(1, &self))?;
                if seq.next_element::<i64>()?.is_some() {
                    return Err(de::Error::invalid_length(3, &self));
                }
                Ok(BitRange { first, last })
            }
        }
        deserializer.deserialize_any(BitVisitor)
    }
}

/// A text in English and, optionally, Chinese: `"Control word"` or
/// `{ en = "Control word", zh = "控制字" }`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Text {
    pub en: Spanned<String>,
    pub zh: Option<Spanned<String>>,
}

impl<'de> Deserialize<'de> for Text {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct TextVisitor;
        impl<'de> Visitor<'de> for TextVisitor {
            type Value = Text;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a string or a table { en = \"…\", zh = \"…\" }")
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<Text, E> {
                // The whole value's span is on the enclosing Spanned<Text>.
                Ok(Text {
                    en: Spanned::new(0..0, v.to_string()),
                    zh: None,
                })
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Text, A::Error> {
                let (mut en, mut zh) = (None, None);
                while let Some(key) = map.next_key::<String>()? {
                    match key.as_str() {
                        "en" => en = Some(map.next_value::<Spanned<String>>()?),
                        "zh" => zh = Some(map.next_value::<Spanned<String>>()?),
                        other => return Err(de::Error::unknown_field(other, &["en", "zh"])),
                    }
                }
                let en = en.ok_or_else(|| de::Error::missing_field("en"))?;
                Ok(Text { en, zh })
            }
        }
        deserializer.deserialize_any(TextVisitor)
    }
}

impl Text {
    /// The span of the English text, falling back to the whole value's span
    /// when the text was written as a plain string.
    pub fn en_span(&self, whole: &std::ops::Range<usize>) -> std::ops::Range<usize> {
        let span = self.en.span();
        if span.is_empty() {
            whole.clone()
        } else {
            span
        }
    }
}
