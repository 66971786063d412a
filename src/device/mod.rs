//! What a device file says, read from a GSD ([`DpDevice`]) or a GSDML file
//! ([`PnDevice`]): a plain data model, with the place in the file of each
//! fact. `gsdc diff` compares two of them by meaning (`crate::diff`); an
//! import writes a description from one. Nothing here judges, compares or
//! reads a disk: a GSD is read from the checker's parse of its text, a
//! GSDML file from the elements `crate::gsdml::tree` finds (the checker's
//! roxmltree tree holds more than a device needs, at twice the time).
//!
//! The model keeps what a file means and leaves out how it is written: text
//! IDs are resolved to their texts in every language, references to their
//! targets, numbers to numbers, comments and layout dropped. What has a
//! typed field is what both file kinds or a comparison need by name
//! (identity, modules, parameters, records, IO data, diagnosis); every other
//! keyword or attribute is kept as written, by name, so that no fact of the
//! file is lost.

pub mod dp;
pub mod pn;

mod from_gsd;
mod from_gsdml;

use std::borrow::Cow;
use std::fmt;
use std::ops::{Deref, Range};
use std::sync::{Arc, OnceLock};

pub use dp::DpDevice;
pub use from_gsd::read as read_gsd;
pub use from_gsdml::VALUE_ITEM_HELP;
pub use pn::PnDevice;

/// The device of a GSD or of a GSDML file.
#[derive(Debug, Clone, PartialEq)]
pub enum Device {
    Dp(DpDevice),
    Pn(PnDevice),
}

/// The device a GSD or GSDML file describes, from its bytes (told apart
/// by their content, decoded as `gsdc check` decodes them), or `None` when
/// they cannot be read as one: not a device file, an encoding or syntax
/// error, a GSD line the reader cannot read. `gsdc check` says why.
/// `file_name` is the file's own name, when there is one.
pub fn read(bytes: &[u8], file_name: Option<&str>) -> Option<Device> {
    read_with_text(bytes, file_name).0
}

/// [`read`], and the text the places of the device's facts are in: the
/// GSDML file's decoded text when it is read as one, else the bytes as a
/// GSD reader decodes them. Decoded once, for a reader that also shows
/// the file (an import's findings).
pub fn read_with_text<'b>(
    bytes: &'b [u8],
    file_name: Option<&str>,
) -> (Option<Device>, Cow<'b, str>) {
    use crate::file_kind::{detect, FileKind, HEAD_BYTES};
    let kind = detect(&bytes[..bytes.len().min(HEAD_BYTES)]);
    if kind == FileKind::Gsdml {
        if let Ok(text) = crate::gsdml::decode(bytes) {
            if let Some(device) = read_gsdml(&text, file_name) {
                return (Some(Device::Pn(device)), text);
            }
        }
        return (None, crate::gsd::decode(bytes));
    }
    let text = crate::gsd::decode(bytes);
    let is_gsd = kind == FileKind::Gsd && crate::utf16::byte_order(bytes).is_none();
    if !is_gsd {
        return (None, text);
    }
    let (file, findings) = crate::gsd::parse(&text);
    let device = (!findings.has_errors()).then(|| Device::Dp(read_gsd(&file, &text, file_name)));
    (device, text)
}

/// A GSDML file's device from its decoded text, `None` when it is not
/// well-formed or not GSDML.
fn read_gsdml(text: &str, file_name: Option<&str>) -> Option<PnDevice> {
    let doc = crate::gsdml::parse_tree(text)?;
    let root = doc.root_element();
    let is_gsdml =
        crate::gsdml::tree::in_gsdml(&root) && root.tag_name().name() == "ISO15745Profile";
    is_gsdml.then(|| from_gsdml::read(&doc, file_name))
}

/// Where a fact is written: its line, and in a GSDML file the path of its
/// element from `ProfileBody`, each element named with what identifies it
/// (`ApplicationProcess/ModuleList/ModuleItem[IDM_1]`).
///
/// Places never make two facts differ: every place equals every other, so
/// that two parts of the model are equal when they say the same, wherever
/// their files write it (a comparison skips what is equal).
#[derive(Debug, Clone, Default)]
pub struct Place {
    /// 1-based.
    pub line: u32,
    /// Shared by the facts of one element.
    pub path: Option<ElementPath>,
}

/// The path of an element of a GSDML file ([`Place`]): a part of one text
/// that holds the paths of all the file's elements placed, shared by them,
/// rather than an allocation of its own for each of thousands.
#[derive(Clone)]
pub struct ElementPath {
    /// Every path of the file, set when the file has been read.
    paths: Arc<OnceLock<Box<str>>>,
    range: Range<usize>,
}

impl Deref for ElementPath {
    type Target = str;

    /// The path. (Empty only while its file is being read, when nothing
    /// reads it.)
    fn deref(&self) -> &str {
        self.paths
            .get()
            .and_then(|paths| paths.get(self.range.clone()))
            .unwrap_or_default()
    }
}

impl fmt::Debug for ElementPath {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(&**self, f)
    }
}

impl PartialEq for Place {
    fn eq(&self, _: &Place) -> bool {
        true
    }
}

impl Eq for Place {}

/// A text in every language the file gives it: the primary one (a GSD's
/// only one; a GSDML file's `PrimaryLanguage`, English by the specification)
/// and the translations by language code. Shared: every use of one text
/// ID is the same text, cloned without copying.
#[derive(Debug, Clone, Default, PartialEq, Eq, Hash)]
pub struct Text {
    pub primary: Arc<str>,
    pub translations: Arc<Translations>,
}

impl Text {
    /// A text in one language only.
    pub fn plain(text: impl AsRef<str>) -> Text {
        Text::untranslated(text.as_ref(), &Arc::default())
    }

    /// A text in one language, with `none` for its translations: a reader
    /// of thousands of texts shares one empty set rather than allocate one
    /// per text.
    fn untranslated(text: &str, none: &Arc<Translations>) -> Text {
        Text {
            primary: Arc::from(text),
            translations: none.clone(),
        }
    }
}

/// A text's translations by language code, in the order of the codes.
///
/// A sorted list rather than a map: most texts have one or two, and a
/// `BTreeMap` takes a node of eleven entries (over half a kilobyte) for
/// the first, for each of the thousands of texts of a large GSDML file.
#[derive(Debug, Clone, Default, PartialEq, Eq, Hash)]
pub struct Translations(Vec<(Arc<str>, String)>);

impl Translations {
    /// The translation into `language`.
    pub fn get(&self, language: &str) -> Option<&str> {
        self.position(language).ok().map(|i| self.0[i].1.as_str())
    }

    /// The language codes, in order.
    pub fn keys(&self) -> impl Iterator<Item = &str> {
        self.0.iter().map(|(language, _)| &**language)
    }

    /// Each language code with its translation, in the order of the codes.
    pub fn iter(&self) -> impl Iterator<Item = (&str, &str)> {
        self.0.iter().map(|(l, t)| (&**l, t.as_str()))
    }

    /// Files `translation` into `language`, unless the language has one.
    pub fn insert_first(&mut self, language: &Arc<str>, translation: &str) {
        if let Err(i) = self.position(language) {
            self.0
                .insert(i, (language.clone(), translation.to_string()));
        }
    }

    /// The translation into `language`, made empty first if there is none.
    pub fn entry(&mut self, language: &Arc<str>) -> &mut String {
        let i = match self.position(language) {
            Ok(i) => i,
            Err(i) => {
                self.0.insert(i, (language.clone(), String::new()));
                i
            }
        };
        &mut self.0[i].1
    }

    fn position(&self, language: &str) -> Result<usize, usize> {
        self.0.binary_search_by(|(l, _)| (**l).cmp(language))
    }
}

impl fmt::Display for Text {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "\"{}\"", self.primary)
    }
}

/// A parameter's value: an integer (exact, 64-bit types included), a
/// floating-point number, or a string (`VisibleString`, `OctetString`).
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    Int(i128),
    Float(f64),
    Str(String),
}

impl Value {
    /// The value as GSDML and GSD files write it: an integer or a float
    /// when it reads as one, else the text itself.
    pub fn parse(text: &str) -> Value {
        let trimmed = text.trim();
        if let Some(n) = crate::gsdml::values::Number::parse(trimmed) {
            return match n {
                crate::gsdml::values::Number::Int(i) => Value::Int(i),
                crate::gsdml::values::Number::Float(x) => Value::Float(x),
            };
        }
        if let Some(hex) = trimmed.strip_prefix("0x").or(trimmed.strip_prefix("0X")) {
            if let Ok(i) = i128::from_str_radix(hex, 16) {
                return Value::Int(i);
            }
        }
        Value::Str(text.to_string())
    }
}

/// Numbers by their value (integers exactly), strings by their text; a
/// number and a string do not compare.
impl PartialOrd for Value {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        match (self, other) {
            (Value::Int(a), Value::Int(b)) => Some(a.cmp(b)),
            (Value::Str(a), Value::Str(b)) => Some(a.cmp(b)),
            (Value::Str(_), _) | (_, Value::Str(_)) => None,
            (a, b) => a.as_f64()?.partial_cmp(&b.as_f64()?),
        }
    }
}

impl Value {
    fn as_f64(&self) -> Option<f64> {
        match self {
            Value::Int(i) => Some(*i as f64),
            Value::Float(x) => Some(*x),
            Value::Str(_) => None,
        }
    }
}

impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Value::Int(i) => write!(f, "{i}"),
            Value::Float(x) => write!(f, "{x}"),
            Value::Str(s) => write!(f, "\"{s}\""),
        }
    }
}

/// What values a parameter may take.
#[derive(Debug, Clone, PartialEq)]
pub enum Allowed {
    /// The file sets no limit beyond the data type's.
    Any,
    /// Inclusive ranges and single values (a single value is a range of one).
    Ranges(Vec<(Value, Value)>),
}

/// A value a parameter may take and the text the engineering tool shows
/// for it (GSD `PrmText`, GSDML `ValueItem`).
#[derive(Debug, Clone, PartialEq)]
pub struct Choice {
    pub value: Value,
    pub text: Text,
}

/// Bits of one byte: `Bit(3)` is offset 3, length 1.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Bits {
    pub offset: u8,
    pub length: u8,
}

/// One parameter of a block of parameter data: a GSD `ExtUserPrmData`
/// where an `Ext_User_Prm_Data_Ref` places it, or a GSDML record's `Ref`.
#[derive(Debug, Clone, PartialEq)]
pub struct Field {
    /// Where it starts in its block (User_Prm_Data of the slave or a
    /// module, a record's data).
    pub byte_offset: u32,
    /// The bits it takes of the byte at `byte_offset`, for `Bit` and
    /// `BitArea`; `None` for whole bytes.
    pub bits: Option<Bits>,
    /// As the file spells it: `Unsigned16`, `Bit`, `BitArea`, `VisibleString`.
    pub data_type: String,
    /// Bytes a string or octet string takes (`Length`); `None` otherwise.
    pub length: Option<u32>,
    pub name: Text,
    pub default: Option<Value>,
    pub allowed: Allowed,
    pub choices: Vec<Choice>,
    /// False when the engineering tool shows the value but lets nobody
    /// change it (GSD `Changeable = 0`, GSDML `Changeable="false"`).
    pub changeable: bool,
    pub visible: bool,
    /// What else the file says of it (a GSDML `Ref`'s `Help`, an
    /// `ExtUserPrmData`'s other keywords).
    pub attributes: Vec<Attribute>,
    pub place: Place,
}

/// Fixed bytes of a block (GSD `Ext_User_Prm_Data_Const`, legacy
/// `User_Prm_Data`; GSDML `Const`), under the fields laid over them.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ConstBytes {
    pub byte_offset: u32,
    pub bytes: Vec<u8>,
    pub place: Place,
}

/// A block of parameter data as the master sends it: a slave's or a
/// module's part of User_Prm_Data, a GSDML record's data, a GSDML unit
/// diagnosis structure.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ParameterData {
    /// The length the file declares (GSDML `Length`, GSD
    /// `Ext_Module_Prm_Data_Len` or `User_Prm_Data_Len`), if it declares one.
    pub length: Option<u32>,
    pub consts: Vec<ConstBytes>,
    pub fields: Vec<Field>,
}

impl ParameterData {
    /// The bytes the block takes: the declared length, else as far as its
    /// constants and fields reach.
    pub fn len(&self) -> u32 {
        self.length.unwrap_or_else(|| self.extent())
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// As far as the constants and fields reach.
    pub fn extent(&self) -> u32 {
        let consts = self
            .consts
            .iter()
            .map(|c| c.byte_offset.saturating_add(c.bytes.len() as u32));
        let fields = self
            .fields
            .iter()
            .map(|f| f.byte_offset.saturating_add(f.size()));
        consts.chain(fields).max().unwrap_or(0)
    }
}

impl Field {
    /// The bytes the field takes: its `Length`, else its data type's size
    /// (one byte for bits; unknown types one byte).
    pub fn size(&self) -> u32 {
        if let Some(length) = self.length {
            return length;
        }
        match crate::gsdml::datatype::record_size(&self.data_type) {
            Some(crate::gsdml::datatype::Size::Bytes(n)) => n,
            _ => 1,
        }
    }
}

/// A keyword or attribute kept as written, by name: what the model has no
/// typed field for. GSDML attributes of elements inside the one they are
/// kept with are named with their path (`ModuleInfo/OrderNumber@Value`);
/// repeated elements give one value of their values joined by a blank
/// (`MAUTypeList/MAUTypeItem@Value` = `16 30`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Attribute {
    /// Shared by every attribute of the name in a file.
    pub name: Arc<str>,
    pub value: AttributeValue,
    pub place: Place,
}

/// An attribute's value: as written, or the text a `TextId` names.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum AttributeValue {
    Plain(Arc<str>),
    Text(Text),
}

impl fmt::Display for AttributeValue {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            AttributeValue::Plain(s) => write!(f, "\"{s}\""),
            AttributeValue::Text(t) => t.fmt(f),
        }
    }
}
