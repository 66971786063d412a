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
        let expecting = "a number or a function-code name like \"F0-12\"";
        Ok(match scalar(deserializer, expecting)? {
            Scalar::Number(n) => Address::Number(n),
            Scalar::Text(name) => Address::Name(name),
        })
    }
}

/// A keyword of the vendor's own: a number or a string.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum VendorValue {
    Number(i64),
    Text(String),
}

impl<'de> Deserialize<'de> for VendorValue {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        Ok(match scalar(deserializer, "a whole number or a string")? {
            Scalar::Number(n) => VendorValue::Number(n),
            Scalar::Text(text) => VendorValue::Text(text),
        })
    }
}

/// A number or a string, as written; anything else is refused saying
/// what was `expecting`.
enum Scalar {
    Number(i64),
    Text(String),
}

fn scalar<'de, D: Deserializer<'de>>(
    deserializer: D,
    expecting: &'static str,
) -> Result<Scalar, D::Error> {
    struct ScalarVisitor(&'static str);
    impl Visitor<'_> for ScalarVisitor {
        type Value = Scalar;
        fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
            f.write_str(self.0)
        }
        fn visit_i64<E: de::Error>(self, v: i64) -> Result<Scalar, E> {
            Ok(Scalar::Number(v))
        }
        fn visit_u64<E: de::Error>(self, v: u64) -> Result<Scalar, E> {
            i64::try_from(v)
                .map(Scalar::Number)
                .map_err(|_| E::custom("number too large"))
        }
        fn visit_str<E: de::Error>(self, v: &str) -> Result<Scalar, E> {
            Ok(Scalar::Text(v.to_string()))
        }
    }
    deserializer.deserialize_any(ScalarVisitor(expecting))
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

/// A list of exactly `N` items: `range = [0, 65535]`, `status_bytes =
/// [0, 0, 0]`. More items are an error, as fewer are: serde's arrays take
/// the first `N` and leave the rest to the deserializer, which the toml
/// crate drops without a word.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Exactly<T, const N: usize>(pub [T; N]);

impl<'de, T: Deserialize<'de>, const N: usize> Deserialize<'de> for Exactly<T, N> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct ListVisitor<T, const N: usize>(std::marker::PhantomData<T>);
        impl<'de, T: Deserialize<'de>, const N: usize> Visitor<'de> for ListVisitor<T, N> {
            type Value = Exactly<T, N>;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                write!(f, "a list of {N} items")
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
                let mut items = Vec::with_capacity(N);
                while items.len() < N {
                    match seq.next_element()? {
                        Some(item) => items.push(item),
                        None => return Err(de::Error::invalid_length(items.len(), &self)),
                    }
                }
                // Counted, so the message says how many there are.
                let mut more = 0;
                while seq.next_element::<de::IgnoredAny>()?.is_some() {
                    more += 1;
                }
                match items.try_into() {
                    Ok(items) if more == 0 => Ok(Exactly(items)),
                    _ => Err(de::Error::invalid_length(N + more, &self)),
                }
            }
        }
        deserializer.deserialize_seq(ListVisitor(std::marker::PhantomData))
    }
}

/// A text: `"Control word"` (English only), or a table with `en` and any
/// other language by its ISO 639-1 code, and optionally `gsd`, a short
/// English form for a GSD file's 32 characters:
/// `{ en = "Frequency reference (0.00 to P02.10)", zh = "设定频率（0.00～P02.10）", gsd = "Frequency ref. (0.00 to P02.10)" }`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Text {
    pub en: Spanned<String>,
    /// Other languages in the order written: the code and the text.
    pub others: Vec<(Spanned<String>, Spanned<String>)>,
    pub gsd: Option<Spanned<String>>,
}

/// The ISO 639-1 language codes.
const ISO_639_1: &str = "aa ab ae af ak am an ar as av ay az ba be bg bh bi bm bn bo br bs ca ce ch \
    co cr cs cu cv cy da de dv dz ee el en eo es et eu fa ff fi fj fo fr fy ga gd gl gn gu gv ha he \
    hi ho hr ht hu hy hz ia id ie ig ii ik io is it iu ja jv ka kg ki kj kk kl km kn ko kr ks ku kv \
    kw ky la lb lg li ln lo lt lu lv mg mh mi mk ml mn mr ms mt my na nb nd ne ng nl nn no nr nv ny \
    oc oj om or os pa pi pl ps pt qu rm rn ro ru rw sa sc sd se sg si sk sl sm sn so sq sr ss st su \
    sv sw ta te tg th ti tk tl tn to tr ts tt tw ty ug uk ur uz ve vi vo wa wo xh yi yo za zh zu";

pub fn is_language_code(code: &str) -> bool {
    code.len() == 2 && ISO_639_1.split_whitespace().any(|c| c == code)
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
                    others: Vec::new(),
                    gsd: None,
                })
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Text, A::Error> {
                let (mut en, mut gsd, mut others) = (None, None, Vec::new());
                while let Some(key) = map.next_key::<Spanned<String>>()? {
                    match key.get_ref().as_str() {
                        "en" => en = Some(map.next_value::<Spanned<String>>()?),
                        "gsd" => gsd = Some(map.next_value::<Spanned<String>>()?),
                        code if is_language_code(code) => {
                            others.push((key, map.next_value::<Spanned<String>>()?));
                        }
                        other => {
                            return Err(de::Error::custom(format!(
                                "unknown field `{other}`, expected `en`, `gsd` or an ISO 639-1 language code (Chinese is zh, German de)"
                            )))
                        }
                    }
                }
                let en = en.ok_or_else(|| de::Error::missing_field("en"))?;
                Ok(Text { en, others, gsd })
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

/// A parameter record: its index (`pzd_out = 1`), or its index and name
/// (`pzd_out = { index = 1, name = { en = "...", zh = "..." } }`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Record {
    pub index: Spanned<i64>,
    pub name: Option<Spanned<Text>>,
}

impl<'de> Deserialize<'de> for Record {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct RecordVisitor;
        impl<'de> Visitor<'de> for RecordVisitor {
            type Value = Record;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a record index or a table { index = 1, name = \"...\" }")
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<Record, E> {
                // The whole value's span is on the enclosing Spanned<Record>.
                Ok(Record {
                    index: Spanned::new(0..0, v),
                    name: None,
                })
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Record, A::Error> {
                let (mut index, mut name) = (None, None);
                while let Some(key) = map.next_key::<String>()? {
                    match key.as_str() {
                        "index" => index = Some(map.next_value::<Spanned<i64>>()?),
                        "name" => name = Some(map.next_value::<Spanned<Text>>()?),
                        other => return Err(de::Error::unknown_field(other, &["index", "name"])),
                    }
                }
                let index = index.ok_or_else(|| de::Error::missing_field("index"))?;
                Ok(Record { index, name })
            }
        }
        deserializer.deserialize_any(RecordVisitor)
    }
}

impl Record {
    /// The index's span, or the whole value's when it was written as a number.
    pub fn index_span(&self, whole: &std::ops::Range<usize>) -> std::ops::Range<usize> {
        let span = self.index.span();
        if span.is_empty() {
            whole.clone()
        } else {
            span
        }
    }
}

/// `text` as a number written in `radix`, when it is digits only and fits
/// 32 bits. `str::parse` and `from_str_radix` also take a leading `+`, which
/// a description's number never has (`F+0-+12`, `slave_family = "+1"`).
pub fn digits(text: &str, radix: u32) -> Option<u32> {
    if text.is_empty() || !(2..=36).contains(&radix) || !text.chars().all(|c| c.is_digit(radix)) {
        return None;
    }
    u32::from_str_radix(text, radix).ok()
}
