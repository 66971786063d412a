//! A [`PnDevice`] from a GSDML document's elements (`crate::gsdml::tree`).
//!
//! Text IDs, value lists, categories, graphics and item references are
//! resolved where they are used, so that a file whose IDs were renamed
//! reads as the same device. Elements the model has no type for are kept
//! as attributes of the typed element they are in ([`Reader::flatten`]).

use std::sync::Arc;

use foldhash::{HashMap, HashMapExt};

use super::pn::{
    Dap, DataItem, DiagItem, IoData, IoPart, ItemRef, PnDevice, PnModule, Record, Submodule,
    SubmoduleKind, UnitDiag,
};
use super::{
    Allowed, Attribute, AttributeValue, Bits, Choice, ConstBytes, ElementPath, Field,
    ParameterData, Place, Text, Value,
};
use crate::diag::Lines;
use crate::gsdml::tree::{child, children, in_gsdml, Node, NodeId, Tree};

const XML_NAMESPACE: &str = "http://www.w3.org/XML/1998/namespace";
const XSI: &str = "http://www.w3.org/2001/XMLSchema-instance";

type El<'a, 'input> = Node<'a, 'input>;

/// The device of a GSDML document. `file_name` is the file's own name,
/// when there is one. A document that is not GSDML gives an empty device.
pub fn read(doc: &Tree<'_>, file_name: Option<&str>) -> PnDevice {
    let root = doc.root_element();
    let body = child(root, "ProfileBody");
    let process = body.and_then(|b| child(b, "ApplicationProcess"));
    let reader = Reader::new(doc, process);
    let mut device = PnDevice {
        file_name: file_name.map(str::to_string),
        schema_version: root
            .attribute((XSI, "schemaLocation"))
            .and_then(crate::gsdml::version::from_schema_location)
            .map(|v| v.to_string()),
        ..PnDevice::default()
    };
    if let Some(body) = body {
        reader.identity(body, &mut device);
    }
    if let Some(process) = process {
        reader.application_process(process, &mut device);
    }
    reader.finish();
    device
}

/// `ApplicationProcess` lists whose entries the model resolves where they
/// are used, or reads into typed parts.
const RESOLVED_LISTS: &[&str] = &[
    "DeviceAccessPointList",
    "ModuleList",
    "SubmoduleList",
    "ValueList",
    "ChannelDiagList",
    "ChannelProcessAlarmList",
    "UnitDiagTypeList",
    "GraphicsList",
    "CategoryList",
    "ExternalTextList",
];

/// Elements whose `ID` is a number of their profile, not a name in the
/// file (the schema's Unsigned8T and Unsigned16T): a PROFIenergy energy
/// saving mode's and a measurement value's ID, which a controller sends.
const NUMBERED_BY_ID: &[&str] = &["EnergySavingModeItem", "MeasurementValue"];

/// Where the typed parts of a DAP, module or submodule are, which
/// [`Reader::flatten`] leaves out.
const ITEM_PARTS: &[&str] = &[
    "ModuleInfo/Name",
    "ModuleInfo/InfoText",
    "UseableModules",
    "UseableSubmodules",
    "VirtualSubmoduleList",
    "SystemDefinedSubmoduleList",
    "IOData/Input",
    "IOData/Output",
    "RecordDataList/ParameterRecordDataItem",
];

struct Reader<'a> {
    lines: Lines,
    texts: HashMap<&'a str, Text>,
    /// Each ValueItem's choices and help.
    value_lists: HashMap<&'a str, (Vec<Choice>, Option<Text>)>,
    categories: HashMap<&'a str, &'a str>,
    graphics: HashMap<&'a str, &'a str>,
    /// Module, submodule and DAP IDs with their ident numbers.
    idents: HashMap<&'a str, u32>,
    /// The paths of every element placed, one after the other: the text
    /// of every [`ElementPath`] of the file, shared when it is complete.
    paths: std::cell::RefCell<String>,
    /// Where the paths will be shared.
    shared_paths: Arc<std::sync::OnceLock<Box<str>>>,
    /// Where in `paths` the path of the element placed last and those of its
    /// ancestors are, outermost first: the reader goes down the document in
    /// order, so an element's path is built once, from its parent's,
    /// found here.
    ancestors: std::cell::RefCell<Vec<(NodeId, std::ops::Range<usize>)>>,
    /// The translations of every text without any, shared.
    no_translations: Arc<super::Translations>,
    /// Names and values met so far: the same ones repeat through a file,
    /// and each is kept once.
    interned: std::cell::RefCell<foldhash::HashSet<Arc<str>>>,
    /// The buffers of [`Reader::flatten_into`]'s walks.
    buffers: std::cell::Cell<(String, String)>,
}

impl<'a> Reader<'a> {
    fn new(doc: &'a Tree<'_>, process: Option<El<'a, '_>>) -> Reader<'a> {
        let mut reader = Reader {
            lines: Lines::of(doc.input_text()),
            texts: HashMap::new(),
            value_lists: HashMap::new(),
            categories: HashMap::new(),
            graphics: HashMap::new(),
            idents: HashMap::new(),
            paths: std::cell::RefCell::default(),
            shared_paths: Arc::default(),
            ancestors: std::cell::RefCell::default(),
            no_translations: Arc::default(),
            interned: std::cell::RefCell::default(),
            buffers: std::cell::Cell::default(),
        };
        if let Some(process) = process {
            reader.index(process);
        }
        reader
    }

    /// Files texts, categories, graphics and ident numbers by ID, then the
    /// value lists (whose texts need the texts).
    fn index(&mut self, process: El<'a, '_>) {
        for list in process.children().filter(in_gsdml) {
            match list.tag_name().name() {
                "ExternalTextList" => self.index_texts(list),
                "CategoryList" => {
                    for item in children(list, "CategoryItem") {
                        if let (Some(id), Some(text)) =
                            (item.attribute("ID"), item.attribute("TextId"))
                        {
                            self.categories.insert(id, text);
                        }
                    }
                }
                "GraphicsList" => {
                    for item in children(list, "GraphicItem") {
                        if let (Some(id), Some(file)) =
                            (item.attribute("ID"), item.attribute("GraphicFile"))
                        {
                            self.graphics.insert(id, file);
                        }
                    }
                }
                "DeviceAccessPointList" | "ModuleList" | "SubmoduleList" => {
                    for item in list.children().filter(in_gsdml) {
                        let ident = item
                            .attribute("ModuleIdentNumber")
                            .or(item.attribute("SubmoduleIdentNumber"))
                            .and_then(hex);
                        if let (Some(id), Some(ident)) = (item.attribute("ID"), ident) {
                            self.idents.insert(id, ident);
                        }
                    }
                }
                _ => {}
            }
        }
        for list in children(process, "ValueList") {
            for item in children(list, "ValueItem") {
                let Some(id) = item.attribute("ID") else {
                    continue;
                };
                let choices = child(item, "Assignments")
                    .into_iter()
                    .flat_map(|a| children(a, "Assign"))
                    .filter_map(|assign| {
                        Some(Choice {
                            value: Value::parse(assign.attribute("Content")?),
                            text: self.text(assign.attribute("TextId")?),
                        })
                    })
                    .collect();
                let help = self.child_text(item, "Help");
                self.value_lists.insert(id, (choices, help));
            }
        }
    }

    fn index_texts(&mut self, list: El<'a, '_>) {
        for primary in children(list, "PrimaryLanguage") {
            for text in children(primary, "Text") {
                if let (Some(id), Some(value)) = (text.attribute("TextId"), text.attribute("Value"))
                {
                    self.texts
                        .entry(id)
                        .or_insert_with(|| Text::untranslated(value, &self.no_translations));
                }
            }
        }
        for language in children(list, "Language") {
            let Some(lang) = language.attribute((XML_NAMESPACE, "lang")) else {
                continue;
            };
            let lang: Arc<str> = Arc::from(lang);
            for text in children(language, "Text") {
                if let (Some(id), Some(value)) = (text.attribute("TextId"), text.attribute("Value"))
                {
                    // Each text's translations are its own until the index is done.
                    let text = self.texts.entry(id).or_default();
                    Arc::make_mut(&mut text.translations).insert_first(&lang, value);
                }
            }
        }
    }

    /// `text`, shared with every other use of it in the file.
    fn intern(&self, text: &str) -> Arc<str> {
        let mut interned = self.interned.borrow_mut();
        if let Some(known) = interned.get(text) {
            return known.clone();
        }
        let new: Arc<str> = Arc::from(text);
        interned.insert(new.clone());
        new
    }

    /// The text of a TextId; a TextId the file does not define is its own
    /// text (`gsdc check` reports it, E308).
    fn text(&self, id: &str) -> Text {
        self.texts
            .get(id)
            .cloned()
            .unwrap_or_else(|| Text::untranslated(id, &self.no_translations))
    }

    /// The text the `TextId` of `node`'s child `element` names.
    fn child_text(&self, node: El<'_, '_>, element: &str) -> Option<Text> {
        child(node, element)?
            .attribute("TextId")
            .map(|id| self.text(id))
    }

    fn place(&self, node: El<'_, '_>) -> Place {
        Place {
            line: self.lines.line(node.range().start),
            path: Some(ElementPath {
                paths: self.shared_paths.clone(),
                range: self.path(node),
            }),
        }
    }

    /// Shares the paths of the places given out: the file has been read.
    fn finish(self) {
        let paths = self.paths.into_inner().into_boxed_str();
        self.shared_paths
            .set(paths)
            .expect("a reader's paths are shared once, when it is done");
    }

    /// The path of an element from `ProfileBody`, each element named by
    /// what identifies it among its siblings.
    fn path(&self, node: El<'_, '_>) -> std::ops::Range<usize> {
        let known = self
            .ancestors
            .borrow()
            .iter()
            .rev()
            .find(|(id, _)| *id == node.id())
            .map(|(_, range)| range.clone());
        if let Some(known) = known {
            return known;
        }
        let top = |n: &El<'_, '_>| matches!(n.tag_name().name(), "ProfileBody" | "ISO15745Profile");
        let parent = node
            .parent_element()
            .filter(|p| in_gsdml(p) && !top(p))
            .map(|p| self.path(p));
        let mut paths = self.paths.borrow_mut();
        let start = paths.len();
        if let Some(parent) = parent {
            paths.extend_from_within(parent);
            paths.push('/');
        }
        push_segment(&mut paths, node);
        let range = start..paths.len();
        // The ancestors stay; the parent's path was just found or built.
        let mut ancestors = self.ancestors.borrow_mut();
        let parent = node.parent_element().map(|p| p.id());
        let kept = ancestors
            .iter()
            .rposition(|(id, _)| Some(*id) == parent)
            .map_or(0, |i| i + 1);
        ancestors.truncate(kept);
        ancestors.push((node.id(), range.clone()));
        range
    }

    fn identity(&self, body: El<'_, '_>, device: &mut PnDevice) {
        if let Some(identity) = child(body, "DeviceIdentity") {
            device.vendor_id = identity.attribute("VendorID").and_then(hex);
            device.device_id = identity.attribute("DeviceID").and_then(hex);
            device.place = self.place(identity);
            let place = self.place(identity);
            self.flatten_into(
                identity,
                "DeviceIdentity",
                &["VendorID", "DeviceID"],
                &[],
                &place,
                &mut device.identity,
            );
        }
        if let Some(function) = child(body, "DeviceFunction") {
            let place = self.place(function);
            self.flatten_into(
                function,
                "DeviceFunction",
                &[],
                &[],
                &place,
                &mut device.identity,
            );
        }
    }

    fn application_process(&self, process: El<'_, '_>, device: &mut PnDevice) {
        for list in process.children().filter(in_gsdml) {
            let name = list.tag_name().name();
            match name {
                "DeviceAccessPointList" => {
                    device.daps = children(list, "DeviceAccessPointItem")
                        .map(|d| self.dap(d))
                        .collect();
                }
                "ModuleList" => {
                    device.modules = children(list, "ModuleItem")
                        .map(|m| self.module(m))
                        .collect();
                }
                "SubmoduleList" => device.submodules.extend(self.submodules(list)),
                "ChannelDiagList" | "ChannelProcessAlarmList" => {
                    device
                        .diagnosis
                        .extend(list.children().filter(in_gsdml).map(|d| self.diag_item(d)));
                }
                "ExternalTextList" => {
                    let language =
                        |l: El<'_, '_>| l.attribute((XML_NAMESPACE, "lang")).map(str::to_string);
                    device.languages = children(list, "Language").filter_map(language).collect();
                }
                "UnitDiagTypeList" => {
                    device.unit_diagnosis = children(list, "UnitDiagTypeItem")
                        .map(|u| self.unit_diag(u))
                        .collect();
                }
                _ if RESOLVED_LISTS.contains(&name) => {}
                _ => {
                    let place = self.place(list);
                    self.flatten_into(list, name, &[], &[], &place, &mut device.other);
                }
            }
        }
    }

    fn dap(&self, node: El<'_, '_>) -> Dap {
        Dap {
            item: self.module(node),
            useable_modules: self.item_refs(
                node,
                "UseableModules",
                "ModuleItemRef",
                "ModuleItemTarget",
            ),
            subslot_labels: child(node, "SubslotList")
                .into_iter()
                .flat_map(|list| children(list, "SubslotItem"))
                .map(|item| {
                    let number = item.attribute("SubslotNumber").and_then(|n| n.parse().ok());
                    (number, item.attribute("TextId").map(|id| self.text(id)))
                })
                .collect(),
        }
    }

    fn module(&self, node: El<'_, '_>) -> PnModule {
        let info = child(node, "ModuleInfo");
        PnModule {
            id: node.attribute("ID").unwrap_or_default().to_string(),
            ident: node.attribute("ModuleIdentNumber").and_then(hex),
            name: info.and_then(|i| self.child_text(i, "Name")),
            info: info.and_then(|i| self.child_text(i, "InfoText")),
            attributes: self.flatten(node, &["ID", "ModuleIdentNumber"], ITEM_PARTS),
            useable_submodules: self.item_refs(
                node,
                "UseableSubmodules",
                "SubmoduleItemRef",
                "SubmoduleItemTarget",
            ),
            submodules: self.item_submodules(node),
            place: self.place(node),
        }
    }

    /// A DAP's or module's virtual and system-defined submodules.
    fn item_submodules(&self, node: El<'_, '_>) -> Vec<Submodule> {
        ["VirtualSubmoduleList", "SystemDefinedSubmoduleList"]
            .into_iter()
            .filter_map(|list| child(node, list))
            .flat_map(|list| self.submodules(list))
            .collect()
    }

    fn submodules<'n>(&'n self, list: El<'n, 'n>) -> impl Iterator<Item = Submodule> + 'n {
        list.children().filter(in_gsdml).filter_map(|node| {
            let kind = SubmoduleKind::from_element(node.tag_name().name())?;
            Some(self.submodule(node, kind))
        })
    }

    fn submodule(&self, node: El<'_, '_>, kind: SubmoduleKind) -> Submodule {
        let info = child(node, "ModuleInfo");
        let own_name = node.attribute("TextId").map(|id| self.text(id));
        let io = child(node, "IOData");
        let part = |name: &str| io.and_then(|io| child(io, name)).map(|p| self.io_part(p));
        let records = child(node, "RecordDataList")
            .into_iter()
            .flat_map(|list| children(list, "ParameterRecordDataItem"))
            .map(|r| self.record(r))
            .collect();
        Submodule {
            kind,
            id: node.attribute("ID").unwrap_or_default().to_string(),
            ident: node.attribute("SubmoduleIdentNumber").and_then(hex),
            subslot: node.attribute("SubslotNumber").and_then(|s| s.parse().ok()),
            name: own_name.or_else(|| info.and_then(|i| self.child_text(i, "Name"))),
            info: info.and_then(|i| self.child_text(i, "InfoText")),
            attributes: self.flatten(
                node,
                &["ID", "SubmoduleIdentNumber", "SubslotNumber", "TextId"],
                ITEM_PARTS,
            ),
            io: IoData {
                input: part("Input"),
                output: part("Output"),
            },
            records,
            place: self.place(node),
        }
    }

    fn io_part(&self, node: El<'_, '_>) -> IoPart {
        IoPart {
            attributes: self.flatten(node, &[], &["DataItem"]),
            items: children(node, "DataItem")
                .map(|d| self.data_item(d))
                .collect(),
            place: self.place(node),
        }
    }

    fn data_item(&self, node: El<'_, '_>) -> DataItem {
        let bits = children(node, "BitDataItem")
            .filter_map(|b| {
                let offset = b.attribute("BitOffset")?.parse().ok()?;
                Some((offset, self.text(b.attribute("TextId")?)))
            })
            .collect();
        DataItem {
            data_type: self.intern(node.attribute("DataType").unwrap_or_default()),
            length: node.attribute("Length").and_then(|l| l.parse().ok()),
            text: node.attribute("TextId").map(|id| self.text(id)),
            use_as_bits: node.attribute("UseAsBits") == Some("true"),
            bits,
            attributes: self.flatten(
                node,
                &["DataType", "Length", "TextId", "UseAsBits"],
                &["BitDataItem"],
            ),
            place: self.place(node),
        }
    }

    fn record(&self, node: El<'_, '_>) -> Record {
        Record {
            index: node
                .attribute("Index")
                .and_then(|i| i.parse().ok())
                .unwrap_or(0),
            name: self.child_text(node, "Name"),
            data: self.parameter_data(node),
            attributes: self.flatten(node, &["Index", "Length"], &["Name", "Const", "Ref"]),
            place: self.place(node),
        }
    }

    /// A record's or diagnosis structure's `Length`, `Const`s and `Ref`s.
    fn parameter_data(&self, node: El<'_, '_>) -> ParameterData {
        let consts = children(node, "Const")
            .filter_map(|c| {
                Some(ConstBytes {
                    byte_offset: c.attribute("ByteOffset").unwrap_or("0").parse().ok()?,
                    bytes: octets(c.attribute("Data")?)?,
                    place: self.place(c),
                })
            })
            .collect();
        ParameterData {
            length: node.attribute("Length").and_then(|l| l.parse().ok()),
            consts,
            fields: children(node, "Ref")
                .filter_map(|r| self.field(r))
                .collect(),
        }
    }

    fn field(&self, node: El<'_, '_>) -> Option<Field> {
        let data_type = node.attribute("DataType")?.to_string();
        let number = |name: &str, default: u32| {
            node.attribute(name)
                .map_or(Some(default), |v| v.parse().ok())
        };
        let bits = match data_type.as_str() {
            "Bit" => Some(Bits {
                offset: u8::try_from(number("BitOffset", 0)?).ok()?,
                length: 1,
            }),
            "BitArea" => Some(Bits {
                offset: u8::try_from(number("BitOffset", 0)?).ok()?,
                length: u8::try_from(number("BitLength", 1)?).ok()?,
            }),
            _ => None,
        };
        let is_text = is_text_type(&data_type);
        let value = |text: &str| match is_text {
            true => Value::Str(text.to_string()),
            false => Value::parse(text),
        };
        let value_item = node
            .attribute("ValueItemTarget")
            .and_then(|t| self.value_lists.get(t));
        // Its ValueItem's help, a text the engineering tool shows with it.
        let mut attributes = self.flatten(node, FIELD_ATTRIBUTES, &[]);
        if let Some(help) = value_item.and_then(|(_, help)| help.clone()) {
            attributes.push(Attribute {
                name: self.intern(VALUE_ITEM_HELP),
                value: AttributeValue::Text(help),
                place: self.place(node),
            });
        }
        // Of a string, the numbers its tools read as lengths; kept as written.
        let allowed = node
            .attribute("AllowedValues")
            .and_then(value_ranges)
            .map_or(Allowed::Any, Allowed::Ranges);
        Some(Field {
            byte_offset: number("ByteOffset", 0)?,
            bits,
            length: node.attribute("Length").and_then(|l| l.parse().ok()),
            name: node
                .attribute("TextId")
                .map(|id| self.text(id))
                .unwrap_or_default(),
            default: node.attribute("DefaultValue").map(value),
            allowed,
            choices: value_item.map(|(c, _)| c.clone()).unwrap_or_default(),
            changeable: node.attribute("Changeable") != Some("false"),
            visible: node.attribute("Visible") != Some("false"),
            attributes,
            place: self.place(node),
            data_type,
        })
    }

    fn item_refs(&self, node: El<'_, '_>, list: &str, element: &str, target: &str) -> Vec<ItemRef> {
        child(node, list)
            .into_iter()
            .flat_map(|l| children(l, element))
            .filter_map(|r| {
                let to = r.attribute(target)?;
                Some(ItemRef {
                    target: to.to_string(),
                    ident: self.idents.get(to).copied(),
                    attributes: self.flatten(r, &[target], &[]),
                    place: self.place(r),
                })
            })
            .collect()
    }

    fn diag_item(&self, node: El<'_, '_>) -> DiagItem {
        let extended = ["ExtChannelDiagList", "ExtChannelProcessAlarmList"]
            .into_iter()
            .filter_map(|l| child(node, l))
            .flat_map(|l| l.children().filter(in_gsdml))
            .map(|e| self.diag_item(e))
            .collect();
        DiagItem {
            element: self.intern(node.tag_name().name()),
            error_type: node
                .attribute("ErrorType")
                .or(node.attribute("Reason"))
                .and_then(|e| e.parse().ok())
                .unwrap_or(0),
            name: self.child_text(node, "Name"),
            help: self.child_text(node, "Help"),
            attributes: self.flatten(
                node,
                &["ErrorType", "Reason"],
                &[
                    "Name",
                    "Help",
                    "ExtChannelDiagList",
                    "ExtChannelProcessAlarmList",
                ],
            ),
            extended,
            place: self.place(node),
        }
    }

    fn unit_diag(&self, node: El<'_, '_>) -> UnitDiag {
        UnitDiag {
            id: node
                .attribute("UserStructureIdentifier")
                .and_then(|i| i.parse().ok())
                .unwrap_or(0),
            data: self.parameter_data(node),
            attributes: self.flatten(node, &["UserStructureIdentifier"], &["Ref", "Const"]),
            place: self.place(node),
        }
    }

    /// The attributes of `node` but `own_skipped`, and those of the
    /// elements inside it but the typed parts at `typed_parts` (paths
    /// relative to `node`), each named by its path below `node`.
    fn flatten(
        &self,
        node: El<'_, '_>,
        own_skipped: &[&str],
        typed_parts: &[&str],
    ) -> Vec<Attribute> {
        let mut out = Vec::new();
        let place = self.place(node);
        self.flatten_into(node, "", own_skipped, typed_parts, &place, &mut out);
        out
    }

    /// [`Reader::flatten`] below the relative path `rel`, into `out`. An
    /// attribute met again (of a repeated element) joins its values with a
    /// blank. Element IDs below `node` are left out: they name, they do
    /// not mean; but those of [`NUMBERED_BY_ID`].
    fn flatten_into(
        &self,
        node: El<'_, '_>,
        rel: &str,
        own_skipped: &[&str],
        typed_parts: &[&str],
        entity: &Place,
        out: &mut Vec<Attribute>,
    ) {
        // The walks reuse two buffers: a file has thousands of them.
        let (below, name) = self.buffers.take();
        let mut walk = Walk {
            rel,
            own_skipped,
            typed_parts,
            entity,
            start: out.len(),
            below,
            name,
        };
        walk.below.clear();
        self.walk(node, &mut walk, out);
        self.buffers.set((walk.below, walk.name));
    }

    /// One element of a [`Reader::flatten_into`], then the elements in it,
    /// in document order; `walk.below` is the element's path below the
    /// flattened one, grown and cut back as the walk goes down and up.
    fn walk(&self, element: El<'_, '_>, walk: &mut Walk<'_>, out: &mut Vec<Attribute>) {
        let own = walk.below.is_empty();
        let line = std::cell::OnceCell::new();
        for attribute in element.attributes() {
            let name = attribute.name();
            if attribute.namespace().is_some()
                || (own && walk.own_skipped.contains(&name))
                || (!own && name == "ID" && !NUMBERED_BY_ID.contains(&element.tag_name().name()))
            {
                continue;
            }
            // `rel/below@name`, each part when there is one.
            let full = &mut walk.name;
            full.clear();
            full.push_str(walk.rel);
            if !walk.rel.is_empty() && !own {
                full.push('/');
            }
            full.push_str(&walk.below);
            if !full.is_empty() {
                full.push('@');
            }
            full.push_str(name);
            let value = self.attribute_value(name, attribute.value());
            join(&mut out[walk.start..], full, &value).unwrap_or_else(|| {
                out.push(Attribute {
                    name: self.intern(full),
                    value,
                    place: Place {
                        line: *line.get_or_init(|| self.lines.line(element.range().start)),
                        path: walk.entity.path.clone(),
                    },
                })
            });
        }
        for child in element.children().filter(in_gsdml) {
            let length = walk.below.len();
            if !own {
                walk.below.push('/');
            }
            walk.below.push_str(child.tag_name().name());
            if !walk.typed_parts.contains(&walk.below.as_str()) {
                self.walk(child, walk, out);
            }
            walk.below.truncate(length);
        }
    }

    /// An attribute's value with what it refers to resolved.
    fn attribute_value(&self, name: &str, value: &str) -> AttributeValue {
        match name {
            "TextId" => AttributeValue::Text(self.text(value)),
            "CategoryRef" | "SubCategory1Ref" => {
                let text = self.categories.get(value).map_or_else(
                    || Text::untranslated(value, &self.no_translations),
                    |id| self.text(id),
                );
                AttributeValue::Text(text)
            }
            "GraphicItemTarget" => {
                AttributeValue::Plain(self.intern(self.graphics.get(value).unwrap_or(&value)))
            }
            "ModuleItemTarget" | "SubmoduleItemTarget" => {
                AttributeValue::Plain(match self.idents.get(value) {
                    Some(ident) => format!("0x{ident:08X}").into(),
                    None => self.intern(value),
                })
            }
            _ => AttributeValue::Plain(match normalized(value) {
                Some(value) => value.into(),
                None => self.intern(value),
            }),
        }
    }
}

/// A value with its blanks as XML reads a list (runs of white space one
/// blank, none at the ends), when that is not the value as written: most
/// values have nothing to normalize.
fn normalized(value: &str) -> Option<String> {
    let bytes = value.as_bytes();
    let blank_at = |i: usize| bytes.get(i) == Some(&b' ');
    let plain = bytes.iter().enumerate().all(|(i, &b)| match b {
        b' ' => i != 0 && i + 1 != bytes.len() && !blank_at(i + 1),
        b'\t' | b'\n' | b'\r' => false,
        _ => true,
    });
    (!plain).then(|| value.split_whitespace().collect::<Vec<_>>().join(" "))
}

/// What a [`Reader::flatten_into`] carries down the elements it walks.
struct Walk<'w> {
    rel: &'w str,
    own_skipped: &'w [&'w str],
    typed_parts: &'w [&'w str],
    entity: &'w Place,
    /// Where the attributes of this walk start in its output.
    start: usize,
    below: String,
    /// The name of the attribute at hand, built here.
    name: String,
}

/// The attributes of a `Ref` that [`Field`] holds.
/// A record field's ValueItem's `Help`, among its attributes: a text, as a
/// TextId is.
pub const VALUE_ITEM_HELP: &str = "ValueItem/Help@TextId";

const FIELD_ATTRIBUTES: &[&str] = &[
    "DataType",
    "ByteOffset",
    "BitOffset",
    "BitLength",
    "Length",
    "TextId",
    "DefaultValue",
    "AllowedValues",
    "ValueItemTarget",
    "Changeable",
    "Visible",
    "ID",
];

/// Joins `value` to the attribute `name` among `attributes`, if there is
/// one; `None` when there is none.
fn join(attributes: &mut [Attribute], name: &str, value: &AttributeValue) -> Option<()> {
    let existing = attributes.iter_mut().find(|a| &*a.name == name)?;
    existing.value = match (&existing.value, value) {
        (AttributeValue::Text(a), AttributeValue::Text(b)) => {
            let mut joined = a.clone();
            joined.primary = format!("{} | {}", a.primary, b.primary).into();
            for (lang, text) in b.translations.iter() {
                let entry = Arc::make_mut(&mut joined.translations).entry(&Arc::from(lang));
                *entry = format!("{entry} | {text}");
            }
            AttributeValue::Text(joined)
        }
        (a, b) => AttributeValue::Plain(format!("{} {}", plain(a), plain(b)).into()),
    };
    Some(())
}

fn plain(value: &AttributeValue) -> &str {
    match value {
        AttributeValue::Plain(s) => s,
        AttributeValue::Text(t) => &t.primary,
    }
}

/// Appends the element's name and what identifies it among its siblings
/// (`ModuleItem[IDM_1]`, `Ref[ByteOffset=2,BitOffset=0]`, `DataItem[3]`).
/// Built by hand: paths are made for every element placed, and `format!`
/// would cost more than the rest of reading the element.
fn push_segment(out: &mut String, node: El<'_, '_>) {
    let name = node.tag_name().name();
    out.push_str(name);
    if let Some(id) = node.attribute("ID") {
        out.push('[');
        out.push_str(id);
        out.push(']');
        return;
    }
    let key = |out: &mut String, attributes: &[&str]| {
        out.push('[');
        let mut first = true;
        for (attribute, value) in attributes
            .iter()
            .filter_map(|a| Some((a, node.attribute(*a)?)))
        {
            if !first {
                out.push(',');
            }
            first = false;
            out.push_str(attribute);
            out.push('=');
            out.push_str(value);
        }
        out.push(']');
    };
    match name {
        "ParameterRecordDataItem" => key(out, &["Index"]),
        "Ref" => key(out, &["ByteOffset", "BitOffset"]),
        "ModuleItemRef" => key(out, &["ModuleItemTarget"]),
        "SubmoduleItemRef" => key(out, &["SubmoduleItemTarget"]),
        "UnitDiagTypeItem" => key(out, &["UserStructureIdentifier"]),
        _ if node.has_attribute("ErrorType") => key(out, &["ErrorType"]),
        "DataItem" | "BitDataItem" => {
            let nth =
                std::iter::successors(node.prev_sibling_element(), |s| s.prev_sibling_element())
                    .filter(|s| s.tag_name().name() == name)
                    .count();
            out.push('[');
            out.push_str(&(nth + 1).to_string());
            out.push(']');
        }
        _ => {}
    }
}

/// `0x0000ABCD` (the schema asks for `0x`; some files write `0X`).
fn hex(text: &str) -> Option<u32> {
    let digits = text
        .trim()
        .strip_prefix("0x")
        .or(text.trim().strip_prefix("0X"))?;
    u32::from_str_radix(digits, 16).ok()
}

/// A `Const`'s `Data`: `0x01,0x02`.
fn octets(text: &str) -> Option<Vec<u8>> {
    text.split(',')
        .map(|b| {
            let b = b.trim();
            let digits = b.strip_prefix("0x").or(b.strip_prefix("0X"))?;
            u8::from_str_radix(digits, 16).ok()
        })
        .collect()
}

fn is_text_type(data_type: &str) -> bool {
    matches!(
        data_type,
        "VisibleString" | "OctetString" | "UnicodeString8" | "61131_STRING" | "61131_WSTRING"
    )
}

/// `AllowedValues`: numbers and ranges `lo..hi`, blank-separated.
fn value_ranges(list: &str) -> Option<Vec<(Value, Value)>> {
    list.split_whitespace()
        .map(|item| match item.split_once("..") {
            Some((lo, hi)) => Some((Value::parse(lo), Value::parse(hi))),
            None => Some((Value::parse(item), Value::parse(item))),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    const TEXT: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<ISO15745Profile xmlns="http://www.profibus.com/GSDML/2003/11/DeviceProfile" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:schemaLocation="http://www.profibus.com/GSDML/2003/11/DeviceProfile ..\xsd\GSDML-DeviceProfile-V2.32.xsd">
  <ProfileBody>
    <DeviceIdentity VendorID="0x0A10" DeviceID="0x0810">
      <InfoText TextId="T_INFO"/>
      <VendorName Value="Megmeet"/>
    </DeviceIdentity>
    <DeviceFunction><Family MainFamily="Drives" ProductFamily="MV800"/></DeviceFunction>
    <ApplicationProcess>
      <DeviceAccessPointList>
        <DeviceAccessPointItem ID="DAP" ModuleIdentNumber="0x00000001" PhysicalSlots="0..1">
          <ModuleInfo><Name TextId="T_DAP"/><OrderNumber Value="MV810"/></ModuleInfo>
          <UseableModules><ModuleItemRef ModuleItemTarget="M1" AllowedInSlots="1"/></UseableModules>
          <SystemDefinedSubmoduleList>
            <PortSubmoduleItem ID="P1" SubslotNumber="32769" SubmoduleIdentNumber="0x8001" TextId="T_PORT">
              <MAUTypeList><MAUTypeItem Value="16"/><MAUTypeItem Value="30"/></MAUTypeList>
            </PortSubmoduleItem>
          </SystemDefinedSubmoduleList>
        </DeviceAccessPointItem>
      </DeviceAccessPointList>
      <ModuleList>
        <ModuleItem ID="M1" ModuleIdentNumber="0x00000201">
          <ModuleInfo><Name TextId="T_M1"/></ModuleInfo>
          <VirtualSubmoduleList>
            <VirtualSubmoduleItem ID="S1" SubmoduleIdentNumber="0x201" API="0">
              <IOData IOPS_Length="1">
                <Input Consistency="All items consistency">
                  <DataItem DataType="Unsigned16" UseAsBits="true" TextId="T_STATUS"><BitDataItem BitOffset="0" TextId="T_READY"/></DataItem>
                  <DataItem DataType="OctetString" Length="4" TextId="T_M1"/>
                </Input>
              </IOData>
              <RecordDataList>
                <ParameterRecordDataItem Index="1" Length="4" TransferSequence="1">
                  <Name TextId="T_M1"/>
                  <Const Data="0x01,0x02" ByteOffset="2"/>
                  <Ref DataType="Unsigned16" ByteOffset="0" DefaultValue="3" AllowedValues="0..14 20" ValueItemTarget="V1" Changeable="false" TextId="T_PZD"/>
                  <Ref DataType="BitArea" ByteOffset="3" BitOffset="2" BitLength="3" DefaultValue="1" TextId="T_PZD"/>
                </ParameterRecordDataItem>
              </RecordDataList>
            </VirtualSubmoduleItem>
          </VirtualSubmoduleList>
        </ModuleItem>
      </ModuleList>
      <ValueList><ValueItem ID="V1"><Assignments><Assign Content="3" TextId="T_READY"/></Assignments></ValueItem></ValueList>
      <ExternalTextList>
        <PrimaryLanguage>
          <Text TextId="T_INFO" Value="A card"/><Text TextId="T_DAP" Value="DAP"/><Text TextId="T_M1" Value="PKW + 1 PZD"/>
          <Text TextId="T_STATUS" Value="Status"/><Text TextId="T_READY" Value="Ready"/><Text TextId="T_PZD" Value="PZD2"/>
          <Text TextId="T_PORT" Value="Port 1"/>
        </PrimaryLanguage>
        <Language xml:lang="zh"><Text TextId="T_READY" Value="就绪"/></Language>
      </ExternalTextList>
    </ApplicationProcess>
  </ProfileBody>
</ISO15745Profile>"#;

    fn device() -> PnDevice {
        let doc = crate::gsdml::parse_tree(TEXT).unwrap();
        read(&doc, Some("GSDML-V2.32-MEGMEET-MV800-20230830.xml"))
    }

    fn attribute<'d>(attributes: &'d [Attribute], name: &str) -> &'d AttributeValue {
        &attributes.iter().find(|a| &*a.name == name).unwrap().value
    }

    #[test]
    fn identity_languages_and_texts() {
        let d = device();
        assert_eq!((d.vendor_id, d.device_id), (Some(0x0A10), Some(0x0810)));
        assert_eq!(d.schema_version.as_deref(), Some("V2.32"));
        assert_eq!(d.languages, ["zh"]);
        assert_eq!(
            attribute(&d.identity, "DeviceIdentity/InfoText@TextId"),
            &AttributeValue::Text(Text::plain("A card"))
        );
        assert_eq!(
            attribute(&d.identity, "DeviceFunction/Family@MainFamily"),
            &AttributeValue::Plain("Drives".into())
        );
    }

    #[test]
    fn dap_refs_and_ports() {
        let d = device();
        let dap = &d.daps[0].item;
        assert_eq!(dap.ident, Some(1));
        assert_eq!(dap.name, Some(Text::plain("DAP")));
        assert_eq!(
            attribute(&dap.attributes, "PhysicalSlots"),
            &AttributeValue::Plain("0..1".into())
        );
        assert_eq!(
            attribute(&dap.attributes, "ModuleInfo/OrderNumber@Value"),
            &AttributeValue::Plain("MV810".into())
        );
        assert!(dap
            .attributes
            .iter()
            .all(|a| !a.name.starts_with("UseableModules")));
        let reference = &d.daps[0].useable_modules[0];
        assert_eq!(
            (reference.target.as_str(), reference.ident),
            ("M1", Some(0x201))
        );
        let port = &dap.submodules[0];
        assert_eq!(
            (port.kind, port.subslot, port.ident),
            (SubmoduleKind::Port, Some(32769), Some(0x8001))
        );
        assert_eq!(port.name, Some(Text::plain("Port 1")));
        assert_eq!(
            attribute(&port.attributes, "MAUTypeList/MAUTypeItem@Value"),
            &AttributeValue::Plain("16 30".into())
        );
        assert_eq!(
            port.place.path.as_deref(),
            Some("ApplicationProcess/DeviceAccessPointList/DeviceAccessPointItem[DAP]/SystemDefinedSubmoduleList/PortSubmoduleItem[P1]")
        );
    }

    #[test]
    fn io_data_and_records() {
        let d = device();
        let sub = &d.modules[0].submodules[0];
        assert_eq!(
            attribute(&sub.attributes, "IOData@IOPS_Length"),
            &AttributeValue::Plain("1".into())
        );
        assert_eq!(
            attribute(&sub.attributes, "API"),
            &AttributeValue::Plain("0".into())
        );
        let input = sub.io.input.as_ref().unwrap();
        assert_eq!(input.len(), 6);
        assert_eq!(
            input.items[0].bits,
            [(
                0,
                d.modules[0].submodules[0].io.input.as_ref().unwrap().items[0].bits[0]
                    .1
                    .clone()
            )]
        );
        assert_eq!(
            input.items[0].bits[0].1.translations.get("zh"),
            Some("就绪")
        );
        assert!(sub.io.output.is_none());
        let record = &sub.records[0];
        assert_eq!((record.index, record.data.len()), (1, 4));
        assert_eq!(record.data.consts[0].bytes, [1, 2]);
        assert_eq!(
            attribute(&record.attributes, "TransferSequence"),
            &AttributeValue::Plain("1".into())
        );
        let pzd = &record.data.fields[0];
        assert_eq!(pzd.default, Some(Value::Int(3)));
        assert_eq!(
            pzd.allowed,
            Allowed::Ranges(vec![
                (Value::Int(0), Value::Int(14)),
                (Value::Int(20), Value::Int(20))
            ])
        );
        assert!(!pzd.changeable);
        assert_eq!(&*pzd.choices[0].text.primary, "Ready");
        assert!(pzd
            .place
            .path
            .as_deref()
            .unwrap()
            .ends_with("ParameterRecordDataItem[Index=1]/Ref[ByteOffset=0]"));
        let area = &record.data.fields[1];
        assert_eq!(
            area.bits,
            Some(Bits {
                offset: 2,
                length: 3
            })
        );
    }
}
