//! User parameter data rules: offsets within the declared length (E219),
//! references to defined parameters (E220) and texts (E223), defaults in
//! range (E221), no overlaps (E222), unique ids (E224), consistent lengths
//! (E227), readable data types (E228).

use foldhash::{HashMap, HashMapExt, HashSet, HashSetExt};
use std::ops::Range;

use crate::diag::Diagnostic;
use crate::gsd::model::{Allowed, ExtUserPrmData, GsdFile, PrmDataType, Setting, Spanned};
use crate::gsd::prm::{self, Family, Layout};

/// The user parameter bytes a Set_Prm telegram carries at most.
const MAX_USER_PRM: i64 = crate::spec::DP_MAX_USER_PRM as i64;

type Params<'a> = HashMap<i64, &'a ExtUserPrmData>;

pub(super) fn check(file: &GsdFile, out: &mut Vec<Diagnostic>) {
    let params = prm::by_id(file);
    for scope in scopes(file) {
        let layout = prm::layout(scope.settings, scope.family);
        offsets(&params, &scope, &layout, out);
        overlaps(&params, &layout, out);
    }
    let texts: HashSet<i64> = file.prm_texts.iter().map(|t| t.id.value).collect();
    for data in &file.ext_user_prm_data {
        data_type(data, out);
        default_value(data, out);
        prm_text_ref(&texts, data, out);
    }
    unique_ids(
        file.ext_user_prm_data.iter().map(|d| &d.id),
        "ExtUserPrmData",
        out,
    );
    unique_ids(file.prm_texts.iter().map(|t| &t.id), "PrmText", out);
    lengths(file, out);
}

/// A list of parameter entries and the length they must fit in.
struct Scope<'a> {
    settings: &'a [Setting],
    family: Family,
    /// The length keyword's value (`None` if a module lacks it) and name.
    limit: Option<i64>,
    limit_name: &'static str,
}

fn scopes(file: &GsdFile) -> Vec<Scope<'_>> {
    let (limit, limit_name) = ["Max_User_Prm_Data_Len", "User_Prm_Data_Len"]
        .into_iter()
        .find_map(|k| Some((file.number(k)?, k)))
        .unwrap_or((MAX_USER_PRM, "the 237-byte limit of Set_Prm"));
    let mut scopes = vec![Scope {
        settings: &file.settings,
        family: Family::Plain,
        limit: Some(limit),
        limit_name,
    }];
    for module in &file.modules {
        for (family, keyword) in [
            (Family::Plain, "Ext_Module_Prm_Data_Len"),
            (Family::Safety, "F_Ext_Module_Prm_Data_Len"),
        ] {
            scopes.push(Scope {
                settings: &module.settings,
                family,
                limit: module.get(keyword).and_then(|s| s.value.as_number()),
                limit_name: keyword,
            });
        }
    }
    scopes
}

fn offsets(params: &Params, scope: &Scope, layout: &Layout, out: &mut Vec<Diagnostic>) {
    for c in &layout.consts {
        check_fits(scope, c.offset, c.bytes.len() as i64, c.setting, out);
    }
    for r in &layout.refs {
        match params.get(&r.id) {
            Some(data) => {
                let size = data.data_type.as_ref().map_or(1, |t| t.value.size());
                check_fits(scope, r.offset, size as i64, r.setting, out);
            }
            None => out.push(
                Diagnostic::error("E220", format!("no ExtUserPrmData {}", r.id))
                    .at(r.setting.value_span.clone())
                    .label("this parameter is not defined")
                    .help(format!(
                        "define `ExtUserPrmData = {} \"name\"` ... `EndExtUserPrmData`",
                        r.id
                    )),
            ),
        }
    }
}

fn check_fits(scope: &Scope, offset: i64, len: i64, setting: &Setting, out: &mut Vec<Diagnostic>) {
    let end = offset.saturating_add(len);
    let Some(limit) = scope.limit else {
        out.push(
            Diagnostic::error(
                "E219",
                format!(
                    "`{}({offset})` in a module without {}",
                    setting.name, scope.limit_name
                ),
            )
            .at(setting.span.clone())
            .label("the module does not say how long its parameters are")
            .help(format!(
                "add `{} = <bytes>` to the module",
                scope.limit_name
            )),
        );
        return;
    };
    if offset >= 0 && end <= limit {
        return;
    }
    out.push(
        Diagnostic::error(
            "E219",
            format!(
                "`{}({offset})` reaches past {} = {limit}",
                setting.name, scope.limit_name
            ),
        )
        .at(setting.span.clone())
        .label(format!("bytes {offset}..{} of {limit}", end - 1))
        .help(format!(
            "raise {} or move the entry: every parameter byte must lie within it",
            scope.limit_name
        )),
    );
}

/// Two references may share a byte only on different bits (a `Bit(0)` and
/// a `BitArea(1-2)` at the same offset). A parameter with a single allowed
/// value does not count: Siemens places such fixed bits (`Bit(7) 0 0-0`)
/// over real parameters as headings of the STEP 7 parameter dialog
/// (SIMOCODE pro does it 65 times), and they never change a byte.
fn overlaps(params: &Params, layout: &Layout, out: &mut Vec<Diagnostic>) {
    let mut taken: HashMap<i64, (u8, &Setting)> = HashMap::new();
    for r in &layout.refs {
        let Some(data) = params.get(&r.id).filter(|d| !is_fixed(d)) else {
            continue;
        };
        for (byte, mask) in prm::occupied(r.offset, data) {
            let entry = taken.entry(byte).or_insert((0, r.setting));
            if entry.0 & mask != 0 {
                let first = entry.1;
                out.push(
                    Diagnostic::error(
                        "E222",
                        format!(
                            "`{}({})` overlaps another parameter",
                            r.setting.name, r.offset
                        ),
                    )
                    .at(r.setting.span.clone())
                    .label(format!(
                        "byte {byte} is already used by `{}({})`",
                        first.name,
                        first.index().unwrap_or(0)
                    ))
                    .help("give each parameter its own bytes or bits"),
                );
                break;
            }
            *entry = (entry.0 | mask, r.setting);
        }
    }
}

fn is_fixed(data: &ExtUserPrmData) -> bool {
    match &data.allowed.value {
        Allowed::Range(lo, hi) => lo == hi,
        Allowed::Set(values) => values.len() == 1,
        Allowed::Any => false,
    }
}

fn data_type(data: &ExtUserPrmData, out: &mut Vec<Diagnostic>) {
    let Some(ty) = &data.data_type else {
        out.push(
            Diagnostic::error(
                "E228",
                format!("ExtUserPrmData {} has no type line", data.id.value),
            )
            .at(data.id.span.clone())
            .label("no `Type default range` line in this block")
            .help("add e.g. `Unsigned8 0 0-255` after the header"),
        );
        return;
    };
    let problem = match &ty.value {
        PrmDataType::Other(name) => Some(format!("unknown data type `{name}`")),
        PrmDataType::Bit(b) if *b > 7 => Some(format!("bit {b} is not in a byte")),
        PrmDataType::BitArea(first, last) if first > last || *last > 7 => {
            Some(format!("bit area {first}-{last} is not within one byte"))
        }
        _ => None,
    };
    if let Some(problem) = problem {
        out.push(
            Diagnostic::error("E228", problem)
                .at(ty.span.clone())
                .label("not a valid parameter type")
                .help("use Unsigned8/16/32, Signed8/16/32, Bit(0..7) or BitArea(first-last) with bits 0..7"),
        );
    }
}

fn default_value(data: &ExtUserPrmData, out: &mut Vec<Diagnostic>) {
    let Some((min, max)) = data.data_type.as_ref().and_then(|t| t.value.value_range()) else {
        return;
    };
    let fits = |v: i64| (min..=max).contains(&v);
    let allowed_fits = match &data.allowed.value {
        Allowed::Any => true,
        Allowed::Range(lo, hi) => lo <= hi && fits(*lo) && fits(*hi),
        Allowed::Set(values) => values.iter().all(|&v| fits(v)),
    };
    if !allowed_fits {
        out.push(out_of_range(
            data.allowed.span.clone(),
            "allowed values",
            min,
            max,
        ));
    }
    let Some(default) = &data.default else {
        return;
    };
    if !fits(default.value) {
        out.push(out_of_range(default.span.clone(), "default", min, max));
    } else if !data.allowed.value.contains(default.value) {
        out.push(
            Diagnostic::error(
                "E221",
                format!("default {} is not an allowed value", default.value),
            )
            .at(default.span.clone())
            .label("not among the allowed values")
            .help("make the default one of the values the parameter allows"),
        );
    }
}

fn out_of_range(span: Range<usize>, what: &str, min: i64, max: i64) -> Diagnostic {
    Diagnostic::error("E221", format!("{what} outside the data type"))
        .at(span)
        .label(format!("the type holds {min}..{max}"))
        .help("choose a wider data type, or values the type can hold")
}

fn prm_text_ref(texts: &HashSet<i64>, data: &ExtUserPrmData, out: &mut Vec<Diagnostic>) {
    let Some(text_ref) = &data.prm_text_ref else {
        return;
    };
    if !texts.contains(&text_ref.value) {
        out.push(
            Diagnostic::error("E223", format!("no PrmText {}", text_ref.value))
                .at(text_ref.span.clone())
                .label("this text list is not defined")
                .help(format!(
                    "define `PrmText = {}` ... `EndPrmText`",
                    text_ref.value
                )),
        );
    }
}

fn unique_ids<'a>(
    ids: impl Iterator<Item = &'a Spanned<i64>>,
    what: &str,
    out: &mut Vec<Diagnostic>,
) {
    let mut seen = HashSet::new();
    for id in ids {
        if !seen.insert(id.value) {
            out.push(
                Diagnostic::error("E224", format!("{what} {} is defined twice", id.value))
                    .at(id.span.clone())
                    .label("second definition")
                    .help("give each block its own number; references cannot tell them apart"),
            );
        }
    }
}

/// User_Prm_Data_Len against the bytes of User_Prm_Data and against
/// Max_User_Prm_Data_Len.
fn lengths(file: &GsdFile, out: &mut Vec<Diagnostic>) {
    let Some(len) = file.get("User_Prm_Data_Len") else {
        return;
    };
    let Some(n) = len.value.as_number() else {
        return;
    };
    if let Some(max) = file.number("Max_User_Prm_Data_Len").filter(|&m| n > m) {
        out.push(
            Diagnostic::error(
                "E227",
                format!("User_Prm_Data_Len = {n} exceeds Max_User_Prm_Data_Len = {max}"),
            )
            .at(len.value_span.clone())
            .label(format!("more than {max}"))
            .help("Max_User_Prm_Data_Len bounds the whole parameter data"),
        );
    }
    let data = file.get("User_Prm_Data");
    if let Some((data, bytes)) = data.and_then(|d| Some((d, d.value.as_list()?))) {
        if bytes.len() as i64 != n {
            out.push(
                Diagnostic::error(
                    "E227",
                    format!(
                        "User_Prm_Data has {} bytes, User_Prm_Data_Len says {n}",
                        bytes.len()
                    ),
                )
                .at(data.value_span.clone())
                .label(format!("{} bytes", bytes.len()))
                .help("write as many bytes as User_Prm_Data_Len says"),
            );
        }
    }
}
