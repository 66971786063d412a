//! Two GSDML files' devices compared.
//!
//! A DAP or module is identified by its ModuleIdentNumber, a submodule by
//! its SubmoduleIdentNumber (an interface or port by its subslot), a record
//! by its Index, a parameter by its place in the record: what the
//! controller sends at connect and startup and the device checks. Element
//! IDs are names inside the file; when an ident number changed, the
//! element of the same ID shows what it was.

use std::collections::{BTreeMap, BTreeSet};

use super::params::{self, Scope};
use super::{judge, quoted, Change, Changes, Class, Kind};
use crate::device::pn::{
    Dap, DataItem, DiagItem, IoPart, ItemRef, PnDevice, PnModule, Record, Submodule, SubmoduleKind,
};
use crate::device::{Attribute, Place, Text};

/// Every change from `old` to `new`, breaking first.
pub fn compare(old: &PnDevice, new: &PnDevice) -> Vec<Change> {
    let mut out = Changes::default();
    let both: BTreeSet<String> = old
        .languages
        .iter()
        .filter(|l| new.languages.contains(l))
        .cloned()
        .collect();
    out.1 = super::Languages(Some(both));
    file(old, new, &mut out);
    identity(old, new, &mut out);
    languages(&old.languages, &new.languages, &mut out);
    let catalogue = Catalogue::of(old, new);
    let dap = |a: &Dap, b: &Dap, out: &mut Changes| {
        let subject = item(("DAP", &a.item, &b.item), &catalogue, out);
        let refs = (&a.useable_modules[..], &b.useable_modules[..]);
        item_refs(&subject, "module", refs, &catalogue.modules, out);
    };
    let dap_removed = "every station configured with it in a project fails: the device no longer has this access point";
    items(
        ("DAP", dap_removed),
        (&old.daps, &new.daps),
        |d| &d.item,
        dap,
        &mut out,
    );
    let module = |a: &PnModule, b: &PnModule, out: &mut Changes| {
        item(("module", a, b), &catalogue, out);
    };
    let module_removed = "a project with this module expects its ident number in the device: the controller's connect is refused, and the engineering tool cannot show the station";
    items(
        ("module", module_removed),
        (&old.modules, &new.modules),
        |m| m,
        module,
        &mut out,
    );
    submodules(
        "the submodule list",
        &old.submodules,
        &new.submodules,
        &mut out,
    );
    diagnosis("", &old.diagnosis, &new.diagnosis, &mut out);
    unit_diagnosis(old, new, &mut out);
    judge::attributes("ApplicationProcess", &old.other, &new.other, &mut out);
    out.finish()
}

fn file(old: &PnDevice, new: &PnDevice, out: &mut Changes) {
    if let (Some(a), Some(b)) = (&old.file_name, &new.file_name) {
        if a != b {
            out.push(
                Change::new(Class::Cosmetic, Kind::File, "file name", format!("{a} → {b}"))
                    .why("a new name (a new date) is how a new release installs beside the old one; projects keep using the old file until they are updated"),
            );
        }
    }
    let rule = judge::GSDML.iter().find(|r| r.name == "PNIO_Version");
    if let Some(rule) = rule {
        let rule = judge::Rule {
            kind: Kind::File,
            ..*rule
        };
        out.0.extend(judge::judge(
            &rule,
            "schema version".into(),
            old.schema_version.as_deref(),
            new.schema_version.as_deref(),
            (None, None),
        ));
    }
}

fn identity(old: &PnDevice, new: &PnDevice, out: &mut Changes) {
    let hex = |v: Option<u32>| v.map_or("none".to_string(), |v| format!("0x{v:04X}"));
    for (name, a, b) in [
        ("VendorID", old.vendor_id, new.vendor_id),
        ("DeviceID", old.device_id, new.device_id),
    ] {
        if a != b {
            out.push(
                Change::new(Class::Breaking, Kind::Identity, name, format!("{} → {}", hex(a), hex(b)))
                    .why("the controller checks the device's vendor and device ID at startup: every station configured with the old file fails (and the engineering tool sees another device)")
                    .at(Some(&old.place), Some(&new.place)),
            );
        }
    }
    judge::attributes("device", &old.identity, &new.identity, out);
}

fn languages(old: &[String], new: &[String], out: &mut Changes) {
    let (old, new): (BTreeSet<&String>, BTreeSet<&String>) =
        (old.iter().collect(), new.iter().collect());
    for lang in new.difference(&old) {
        out.push(
            Change::new(
                Class::Compatible,
                Kind::Language,
                format!("language {lang}"),
                "added",
            )
            .why("texts in one more language; old projects are not affected"),
        );
    }
    for lang in old.difference(&new) {
        out.push(
            Change::new(Class::Compatible, Kind::Language, format!("language {lang}"), "removed")
                .why("the engineering tool shows the primary language's texts instead; nothing a device or master acts on"),
        );
    }
}

/// The ident numbers of each file's modules and pluggable submodules: a
/// reference to an item the other file lacks is reported with the item.
struct Catalogue {
    modules: (Items, Items),
    submodules: (Items, Items),
}

/// Items by ident number, with their names.
type Items = BTreeMap<u32, Option<Text>>;

impl Catalogue {
    fn of(old: &PnDevice, new: &PnDevice) -> Catalogue {
        let modules = |d: &PnDevice| {
            d.modules
                .iter()
                .filter_map(|m| Some((m.ident?, m.name.clone())))
                .collect()
        };
        let submodules = |d: &PnDevice| {
            d.submodules
                .iter()
                .filter_map(|s| Some((s.ident?, s.name.clone())))
                .collect()
        };
        Catalogue {
            modules: (modules(old), modules(new)),
            submodules: (submodules(old), submodules(new)),
        }
    }
}

fn ident(ident: Option<u32>) -> String {
    ident.map_or("no ident number".to_string(), |i| format!("0x{i:08X}"))
}

/// `DAP "name" (0x00000001)`, `module "name" (0x00000205)`.
fn item_subject(what: &str, m: &PnModule) -> String {
    format!("{what}{} ({})", quoted(m.name.as_ref()), ident(m.ident))
}

fn ident_changed(
    subject: String,
    old: Option<u32>,
    new: Option<u32>,
    kind: Kind,
    at: (&Place, &Place),
) -> Change {
    Change::new(Class::Breaking, kind, subject, format!("ident number {} → {}", ident(old), ident(new)))
        .why("the controller expects the old ident number in the device: every project with it is refused at connect")
        .at(Some(at.0), Some(at.1))
}

/// DAPs or modules (`what`), each paired by ident number, then by ID;
/// `core` gives each one's module, `compare` compares two of them.
fn items<T: PartialEq>(
    (what, removed_why): (&str, &str),
    (old, new): (&[T], &[T]),
    core: impl Fn(&T) -> &PnModule,
    compare: impl Fn(&T, &T, &mut Changes),
    out: &mut Changes,
) {
    let pairing = super::pairing::pair(old, new, |x| core(x).ident).then(|x| Some(&core(x).id));
    for (a, b) in &pairing.both {
        if a != b {
            compare(a, b, out);
        }
    }
    for (a, b) in &pairing.rekeyed {
        let (x, y) = (core(a), core(b));
        out.push(ident_changed(
            item_subject(what, y),
            x.ident,
            y.ident,
            Kind::Module,
            (&x.place, &y.place),
        ));
        compare(a, b, out);
    }
    for a in pairing.gone.iter().map(|a| core(a)) {
        out.push(
            Change::new(
                Class::Breaking,
                Kind::Module,
                item_subject(what, a),
                "removed",
            )
            .why(removed_why)
            .at(Some(&a.place), None),
        );
    }
    for b in pairing.added.iter().map(|b| core(b)) {
        out.push(
            Change::new(
                Class::Compatible,
                Kind::Module,
                item_subject(what, b),
                "added",
            )
            .why("old projects do not use it")
            .at(None, Some(&b.place)),
        );
    }
}

/// What DAPs and modules have alike: texts, attributes, the submodules
/// they offer and have. Returns the subject that names the item.
fn item(
    (what, a, b): (&str, &PnModule, &PnModule),
    catalogue: &Catalogue,
    out: &mut Changes,
) -> String {
    let subject = item_subject(what, b);
    let at = (Some(&a.place), Some(&b.place));
    out.text(
        &format!("{subject} name"),
        a.name.as_ref(),
        b.name.as_ref(),
        at,
    );
    out.text(
        &format!("{subject} info text"),
        a.info.as_ref(),
        b.info.as_ref(),
        at,
    );
    judge::attributes(&subject, &a.attributes, &b.attributes, out);
    let refs = (&a.useable_submodules[..], &b.useable_submodules[..]);
    item_refs(&subject, "submodule", refs, &catalogue.submodules, out);
    submodules(&subject, &a.submodules, &b.submodules, out);
    subject
}

/// What a DAP or module offers: items no longer offered break projects
/// that have them plugged; items newly offered are compatible. An item
/// the other file lacks altogether is reported with the item.
fn item_refs(
    subject: &str,
    what: &str,
    (old, new): (&[ItemRef], &[ItemRef]),
    (old_items, new_items): &(Items, Items),
    out: &mut Changes,
) {
    let key = |r: &ItemRef| {
        r.ident
            .map_or_else(|| r.target.clone(), |i| format!("0x{i:08X}"))
    };
    let name = |r: &ItemRef| {
        let text = r
            .ident
            .and_then(|i| new_items.get(&i).or(old_items.get(&i)))
            .cloned()
            .flatten();
        format!("{subject} {what}{} ({})", quoted(text.as_ref()), key(r))
    };
    let pairing = super::pairing::pair(old, new, key);
    for (a, b) in pairing.both {
        judge::attributes(&name(b), &a.attributes, &b.attributes, out);
    }
    for a in pairing.gone {
        if a.ident.is_some_and(|i| new_items.contains_key(&i)) {
            out.push(
                Change::new(Class::Breaking, Kind::Module, name(a), "no longer offered")
                    .why("a project configured with the old file may have it plugged: the engineering tool refuses the station, and the device the configuration")
                    .at(Some(&a.place), None),
            );
        }
    }
    for b in pairing.added {
        if b.ident.is_some_and(|i| old_items.contains_key(&i)) {
            out.push(
                Change::new(Class::Compatible, Kind::Module, name(b), "now offered")
                    .why("old projects do not use it")
                    .at(None, Some(&b.place)),
            );
        }
    }
}

fn submodule_subject(s: &Submodule, of: &str) -> String {
    let what = match s.kind {
        SubmoduleKind::Interface => "interface",
        SubmoduleKind::Port => "port",
        SubmoduleKind::Virtual | SubmoduleKind::Pluggable => "submodule",
    };
    let subslot = s
        .subslot
        .map_or_else(String::new, |n| format!(" at subslot 0x{n:04X}"));
    format!(
        "{what}{}{subslot} ({}) of {of}",
        quoted(s.name.as_ref()),
        ident(s.ident)
    )
}

/// Submodules of one DAP or module: interfaces and ports by subslot, the
/// others by ident number, then by ID.
fn submodules(of: &str, old: &[Submodule], new: &[Submodule], out: &mut Changes) {
    let key = |s: &Submodule| match s.kind {
        SubmoduleKind::Interface | SubmoduleKind::Port => (s.kind, s.subslot, None),
        _ => (s.kind, None, s.ident),
    };
    let pairing = super::pairing::pair(old, new, key).then(|s| Some(s.id.clone()));
    for (a, b) in pairing.both.iter().chain(&pairing.rekeyed) {
        submodule(of, a, b, out);
    }
    for a in pairing.gone {
        out.push(
            Change::new(Class::Breaking, Kind::Submodule, submodule_subject(a, of), "removed")
                .why("the controller expects the submodule a project configured with the old file has: the connect is refused")
                .at(Some(&a.place), None),
        );
    }
    for b in pairing.added {
        out.push(
            Change::new(
                Class::Compatible,
                Kind::Submodule,
                submodule_subject(b, of),
                "added",
            )
            .why("old projects do not use it")
            .at(None, Some(&b.place)),
        );
    }
}

fn submodule(of: &str, a: &Submodule, b: &Submodule, out: &mut Changes) {
    if a == b {
        return;
    }
    let subject = submodule_subject(b, of);
    let at = (&a.place, &b.place);
    if a.ident != b.ident {
        out.push(ident_changed(
            subject.clone(),
            a.ident,
            b.ident,
            Kind::Submodule,
            at,
        ));
    }
    if a.subslot != b.subslot {
        let show = |s: Option<u32>| s.map_or("none".into(), |n| format!("0x{n:04X}"));
        out.push(
            Change::new(
                Class::Breaking,
                Kind::Submodule,
                &subject,
                format!("subslot {} → {}", show(a.subslot), show(b.subslot)),
            )
            .why("projects configured with the old file address it at its old subslot")
            .at(Some(at.0), Some(at.1)),
        );
    }
    out.text(
        &format!("{subject} name"),
        a.name.as_ref(),
        b.name.as_ref(),
        (Some(at.0), Some(at.1)),
    );
    out.text(
        &format!("{subject} info text"),
        a.info.as_ref(),
        b.info.as_ref(),
        (Some(at.0), Some(at.1)),
    );
    judge::attributes(&subject, &compared(a), &compared(b), out);
    io_part(
        &format!("input data of {subject}"),
        a.io.input.as_ref(),
        b.io.input.as_ref(),
        out,
    );
    io_part(
        &format!("output data of {subject}"),
        a.io.output.as_ref(),
        b.io.output.as_ref(),
        out,
    );
    records(&subject, &a.records, &b.records, out);
}

/// The attributes of `s` as compared: one fact written two ways is
/// written one way.
///
/// - A virtual submodule without FixedInSubslots is in subslot 1: its
///   module's only submodule, where gsdc's layouts, device tables and wire
///   test place it, as other GSDML readers do ("spec says default is 1 if
///   omitted", one puts it). (A SubmoduleItemRef without it is not fixed at
///   all, and is not changed.)
/// - A port's MAUTypes attribute that names the MAU types its MAUTypeList
///   names is the list's older form, which files keep for older tools
///   (ABB's FENA and SEW's MOVI-C write both): it is left out.
fn compared(s: &Submodule) -> std::borrow::Cow<'_, [Attribute]> {
    const FIXED: &str = "FixedInSubslots";
    let has = |name: &str| s.attributes.iter().any(|a| &*a.name == name);
    let mut attributes = std::borrow::Cow::Borrowed(&s.attributes[..]);
    if s.kind == SubmoduleKind::Virtual && !has(FIXED) {
        attributes.to_mut().push(Attribute {
            name: FIXED.into(),
            value: crate::device::AttributeValue::Plain("1".into()),
            place: s.place.clone(),
        });
    }
    if s.kind == SubmoduleKind::Port && repeats_mau_type_list(&s.attributes) {
        attributes.to_mut().retain(|a| &*a.name != "MAUTypes");
    }
    attributes
}

/// Whether a port's MAUTypes names the MAU types of its MAUTypeList.
fn repeats_mau_type_list(attributes: &[Attribute]) -> bool {
    let tokens = |name: &str| -> Option<BTreeSet<String>> {
        let a = attributes.iter().find(|a| &*a.name == name)?;
        let crate::device::AttributeValue::Plain(v) = &a.value else {
            return None;
        };
        Some(v.split_whitespace().map(str::to_string).collect())
    };
    match (tokens("MAUTypes"), tokens("MAUTypeList/MAUTypeItem@Value")) {
        (Some(attribute), Some(list)) => attribute == list,
        _ => false,
    }
}

/// One direction of a submodule's data: its length and the types of its
/// items break; their texts do not.
fn io_part(subject: &str, a: Option<&IoPart>, b: Option<&IoPart>, out: &mut Changes) {
    fn items(p: Option<&IoPart>) -> &[DataItem] {
        p.map_or(&[], |p| p.items.as_slice())
    }
    let layout = |items: &[DataItem]| -> Vec<(std::sync::Arc<str>, u32)> {
        items
            .iter()
            .map(|i| (i.data_type.clone(), i.size()))
            .collect()
    };
    let show = |items: &[DataItem]| {
        let length: u32 = items.iter().map(DataItem::size).sum();
        let types: Vec<&str> = items.iter().map(|i| &*i.data_type).collect();
        format!("{length} bytes ({})", types.join(", "))
    };
    let at = (a.map(|p| &p.place), b.map(|p| &p.place));
    let (old_items, new_items) = (items(a), items(b));
    if layout(old_items) != layout(new_items) {
        let same_length = a.map_or(0, IoPart::len) == b.map_or(0, IoPart::len);
        let why = match same_length {
            false => {
                "the controller connects with the old length: the device refuses the connection"
            }
            true => "the PLC program reads and writes the data as the old types",
        };
        out.push(
            Change::new(
                Class::Breaking,
                Kind::IoData,
                subject,
                format!("{} → {}", show(old_items), show(new_items)),
            )
            .why(why)
            .at(at.0, at.1),
        );
    } else {
        for (n, (x, y)) in old_items.iter().zip(new_items).enumerate() {
            data_item(&format!("item {} of {subject}", n + 1), x, y, out);
        }
    }
    fn attributes(p: Option<&IoPart>) -> &[Attribute] {
        p.map_or(&[], |p| p.attributes.as_slice())
    }
    judge::attributes(subject, attributes(a), attributes(b), out);
}

fn data_item(subject: &str, a: &DataItem, b: &DataItem, out: &mut Changes) {
    let at = (Some(&a.place), Some(&b.place));
    out.text(subject, a.text.as_ref(), b.text.as_ref(), at);
    if a.use_as_bits != b.use_as_bits {
        out.push(
            Change::new(
                Class::Cosmetic,
                Kind::Text,
                subject,
                format!("UseAsBits {} → {}", a.use_as_bits, b.use_as_bits),
            )
            .why("whether the engineering tool offers the bits as tags; the data is the same")
            .at(at.0, at.1),
        );
    }
    let pairing = super::pairing::pair(&a.bits, &b.bits, |(offset, _)| *offset);
    let bit = |offset: u32| format!("bit {offset} of {subject}");
    for ((o, x), (_, y)) in pairing.both {
        out.text(&bit(*o), Some(x), Some(y), at);
    }
    for (o, x) in pairing.gone {
        out.text(&bit(*o), Some(x), None, at);
    }
    for (o, y) in pairing.added {
        out.text(&bit(*o), None, Some(y), at);
    }
    judge::attributes(subject, &a.attributes, &b.attributes, out);
}

fn record_subject(r: &Record, of: &str) -> String {
    format!("record {}{} of {of}", r.index, quoted(r.name.as_ref()))
}

/// Records by index, then by name: the controller writes each at startup.
fn records(of: &str, old: &[Record], new: &[Record], out: &mut Changes) {
    let named = |r: &Record| r.name.clone().filter(|n| !n.primary.is_empty());
    let pairing = super::pairing::pair(old, new, |r| r.index).then(named);
    for (a, b) in &pairing.both {
        record(of, a, b, out);
    }
    for (a, b) in &pairing.rekeyed {
        out.push(
            Change::new(Class::Breaking, Kind::Record, record_subject(b, of), format!("index {} → {}", a.index, b.index))
                .why("the controller writes it at startup under the old index, which the device no longer takes")
                .at(Some(&a.place), Some(&b.place)),
        );
        record(of, a, b, out);
    }
    for a in &pairing.gone {
        out.push(
            Change::new(Class::Breaking, Kind::Record, record_subject(a, of), "removed")
                .why("the controller writes it at startup; the device no longer takes it, and the startup fails")
                .at(Some(&a.place), None),
        );
    }
    for b in &pairing.added {
        out.push(
            Change::new(Class::Compatible, Kind::Record, record_subject(b, of), "added")
                .why("projects configured with the old file never write it: the device must start with its own values for it")
                .at(None, Some(&b.place)),
        );
    }
}

fn record(of: &str, a: &Record, b: &Record, out: &mut Changes) {
    if a == b {
        return;
    }
    let subject = record_subject(b, of);
    out.text(
        &format!("{subject} name"),
        a.name.as_ref(),
        b.name.as_ref(),
        (Some(&a.place), Some(&b.place)),
    );
    judge::attributes(&subject, &a.attributes, &b.attributes, out);
    let scope = Scope {
        name: &subject,
        kind: Kind::Parameter,
        sent: true,
    };
    params::compare(&scope, &a.data, &b.data, out);
}

/// Channel diagnosis and process alarm items by element, API and error
/// type, with their extended items.
fn diagnosis<'a>(of: &str, old: &'a [DiagItem], new: &'a [DiagItem], out: &mut Changes) {
    let api = |d: &'a DiagItem| {
        d.attributes
            .iter()
            .find(|a| &*a.name == "API")
            .map(|a| &a.value)
    };
    let pairing = super::pairing::pair(old, new, |d| (&*d.element, api(d), d.error_type));
    let subject = |d: &DiagItem| format!("{of}{} {}", d.element, d.error_type);
    for (a, b) in pairing.both {
        // Most of a large file's hundreds of diagnoses are alike: nothing
        // to say, and no subject to write.
        if a == b {
            continue;
        }
        let s = subject(b);
        let at = (Some(&a.place), Some(&b.place));
        out.text(&format!("{s} name"), a.name.as_ref(), b.name.as_ref(), at);
        out.text(&format!("{s} help"), a.help.as_ref(), b.help.as_ref(), at);
        judge::attributes(&s, &a.attributes, &b.attributes, out);
        diagnosis(&format!("{s} "), &a.extended, &b.extended, out);
    }
    for a in pairing.gone {
        out.push(
            Change::new(Class::Compatible, Kind::Diagnosis, subject(a), "removed")
                .why("the device no longer reports it; projects configured with the old file keep a text they never show")
                .at(Some(&a.place), None),
        );
    }
    for b in pairing.added {
        out.push(
            Change::new(Class::Compatible, Kind::Diagnosis, subject(b), "added")
                .why("projects configured with the old file show it without its text")
                .at(None, Some(&b.place)),
        );
    }
}

fn unit_diagnosis(old: &PnDevice, new: &PnDevice, out: &mut Changes) {
    let pairing = super::pairing::pair(&old.unit_diagnosis, &new.unit_diagnosis, |u| u.id);
    for (a, b) in pairing.both {
        let subject = format!("UnitDiagTypeItem {}", b.id);
        judge::attributes(&subject, &a.attributes, &b.attributes, out);
        let scope = Scope {
            name: &subject,
            kind: Kind::Diagnosis,
            sent: false,
        };
        params::compare(&scope, &a.data, &b.data, out);
    }
    for a in pairing.gone {
        out.push(
            Change::new(
                Class::Compatible,
                Kind::Diagnosis,
                format!("UnitDiagTypeItem {}", a.id),
                "removed",
            )
            .why("the device no longer reports it")
            .at(Some(&a.place), None),
        );
    }
    for b in pairing.added {
        out.push(
            Change::new(
                Class::Compatible,
                Kind::Diagnosis,
                format!("UnitDiagTypeItem {}", b.id),
                "added",
            )
            .why("projects configured with the old file show it without decoding it")
            .at(None, Some(&b.place)),
        );
    }
}
