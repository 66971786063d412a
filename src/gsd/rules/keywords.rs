//! W205-W212, W234: every setting against the keyword schema.

use crate::diag::Diagnostic;
use crate::gsd::model::{Arg, GsdFile, Setting, Value};
use crate::gsd::rules::{file_span, scopes};
use crate::gsd::schema::{self, is_nonstandard_spelling, Keyword, Kind};

/// Suggestions cost a scan of the schema each; a file made of nothing but
/// unknown keywords gets them for its first few only.
const MAX_SUGGESTIONS: usize = 32;

pub(super) fn check(file: &GsdFile, out: &mut Vec<Diagnostic>) {
    let mut checker = Checker {
        revision: revision_of(file),
        suggestions: 0,
        seen: Vec::new(),
    };
    for scope in scopes(file) {
        checker.scope(scope, out);
    }
    let headers = file.blocks.iter().map(|b| &b.header);
    let module_areas = file.modules.iter().flat_map(|m| &m.data_areas);
    for header in headers.chain(module_areas.map(|a| &a.header)) {
        checker.setting(header, out);
    }
    block_texts(file, out);
    mandatory(file, out);
}

/// The GSD revision the file is judged by: its `GSD_Revision`, or 0 when it
/// has none (a file older than the keyword, as STEP 7's own catalog has);
/// `None` when the value is no number (E207 says so), so that nothing is
/// judged by a guess.
fn revision_of(file: &GsdFile) -> Option<i64> {
    match file.get("GSD_Revision") {
        Some(setting) => setting.value.as_number(),
        None => Some(0),
    }
}

struct Checker<'f> {
    revision: Option<i64>,
    /// Unknown keywords given a suggestion so far.
    suggestions: usize,
    /// The scope's settings that may appear once: (key, argument, position).
    seen: Vec<(&'f str, Option<Arg>, usize)>,
}

impl<'f> Checker<'f> {
    /// Every setting of one scope against the schema, then W211 for the
    /// keywords it repeats.
    fn scope(&mut self, scope: &'f [Setting], out: &mut Vec<Diagnostic>) {
        self.seen.clear();
        for (position, setting) in scope.iter().enumerate() {
            let repeatable = self
                .setting(setting, out)
                .is_some_and(|k| k.spec.repeatable);
            if !repeatable {
                self.seen.push((&setting.key, setting.arg, position));
            }
        }
        duplicates(scope, &mut self.seen, out);
    }

    /// One setting against the schema; its keyword, when the schema has it.
    fn setting(
        &mut self,
        setting: &Setting,
        out: &mut Vec<Diagnostic>,
    ) -> Option<&'static Keyword> {
        if is_nonstandard_spelling(&setting.name) {
            out.push(nonstandard(setting));
        }
        let Some(keyword) = schema::schema().lookup(&setting.key) else {
            let suggest = self.suggestions < MAX_SUGGESTIONS;
            self.suggestions += usize::from(suggest);
            out.push(unknown(setting, suggest));
            return None;
        };
        check_value(setting, keyword, out);
        if let Some(revision) = self.revision {
            check_revision(setting, keyword, revision, out);
        }
        Some(keyword)
    }
}

/// The texts that blocks carry outside settings: module and parameter
/// names, value texts and diagnosis area texts, all limited to 32.
fn block_texts(file: &GsdFile, out: &mut Vec<Diagnostic>) {
    const LIMIT: usize = crate::spec::GSD_NAME_LEN;
    let modules = file.modules.iter().map(|m| ("module name", &m.name));
    let params = file
        .ext_user_prm_data
        .iter()
        .map(|d| ("parameter name", &d.name));
    let texts = file.prm_texts.iter().flat_map(|t| &t.texts);
    let type_areas = file.unit_diag_types.iter().flat_map(|t| &t.areas);
    let areas = file
        .unit_diag_areas
        .iter()
        .chain(type_areas)
        .flat_map(|a| &a.values);
    let values = texts.map(|t| ("PrmText text", &t.text));
    let diag = areas.map(|v| ("diagnosis text", &v.text));
    for (what, text) in modules.chain(params).chain(values).chain(diag) {
        let len = text.value.chars().count();
        if len > LIMIT {
            out.push(too_long(what, len, LIMIT, text.span.clone()));
        }
    }
}

fn too_long(what: &str, len: usize, max: usize, span: std::ops::Range<usize>) -> Diagnostic {
    Diagnostic::warning("W209", format!("{what} is {len} characters long"))
        .at(span)
        .label(format!("at most {max} characters"))
        .help("configuration tools may cut the text; gsdc's own output keeps the limit (check_strict)")
}

fn nonstandard(setting: &Setting) -> Diagnostic {
    let standard = setting
        .name
        .split_whitespace()
        .collect::<Vec<_>>()
        .join("_");
    let standard = standard.replace('!', "Not_");
    Diagnostic::warning(
        "W212",
        format!("`{}` is not the standard spelling", setting.name),
    )
    .at(setting.name_span.clone())
    .label(format!("read as `{standard}`"))
    .help(format!(
        "write `{standard}`: other tools (gsd-parser, pyprofibus) reject this spelling"
    ))
}

fn unknown(setting: &Setting, suggest: bool) -> Diagnostic {
    let close = suggest.then(|| closest_keyword(&setting.key)).flatten();
    let help = match close {
        Some(name) => format!("did you mean `{name}`?"),
        None => "configuration tools ignore keywords they do not know; check the spelling".into(),
    };
    Diagnostic::warning("W205", format!("unknown keyword `{}`", setting.name))
        .at(setting.name_span.clone())
        .label("not a GSD keyword gsdc knows")
        .help(help)
}

/// A schema keyword one or two edits away (`Min_Slave_Interval` for
/// `Min_Slave_Intervall`), compared in lower case.
fn closest_keyword(key: &str) -> Option<String> {
    let names = lower_case_keywords();
    let lower = crate::spelling::closest(key, names.iter().map(|(l, _)| l.as_str()))?;
    names
        .iter()
        .find(|(l, _)| l == lower)
        .map(|(_, n)| n.to_string())
}

/// The schema's plain keywords in lower case, with their own spelling:
/// made once, for every file checked.
fn lower_case_keywords() -> &'static [(String, &'static str)] {
    static NAMES: std::sync::OnceLock<Vec<(String, &'static str)>> = std::sync::OnceLock::new();
    NAMES.get_or_init(|| {
        schema::schema()
            .keywords()
            .filter(|k| !k.name.contains('<'))
            .map(|k| (k.name.to_ascii_lowercase(), k.name.as_str()))
            .collect()
    })
}

fn check_value(setting: &Setting, keyword: &Keyword, out: &mut Vec<Diagnostic>) {
    let spec = &keyword.spec;
    if spec.kind == Kind::Block {
        return;
    }
    match (spec.index, setting.arg) {
        (true, Some(Arg::Index(_))) | (false, None | Some(Arg::Baud(_))) => {}
        (true, _) => out.push(wrong_form(
            setting,
            format!("`{}(n)` needs its argument in parentheses", keyword.name),
        )),
        (false, Some(Arg::Index(_))) => out.push(wrong_form(
            setting,
            format!("`{}` takes no argument in parentheses", keyword.name),
        )),
    }
    match (spec.kind, &setting.value) {
        (Kind::String, Value::Str(text)) => check_length(setting, keyword, text, out),
        (Kind::Family, Value::Family { main, .. }) | (Kind::Family, Value::Number(main)) => {
            check_range(setting, keyword, *main, out)
        }
        (Kind::Octets, value) if value.as_list().is_some() => {
            check_octets(setting, keyword, &value.as_list().unwrap_or_default(), out)
        }
        (Kind::Unsigned8 | Kind::Unsigned16 | Kind::Unsigned32 | Kind::Bool, Value::Number(n)) => {
            check_range(setting, keyword, *n, out)
        }
        (kind, _) => out.push(
            Diagnostic::error(
                "E207",
                format!("`{}` takes {}", keyword.name, kind.describe()),
            )
            .at(setting.value_span.clone())
            .label(format!("expected {}", kind.describe()))
            .help(format!("write `{} = <{}>`", setting.name, kind.describe())),
        ),
    }
}

fn wrong_form(setting: &Setting, message: String) -> Diagnostic {
    Diagnostic::error("E207", message)
        .at(setting.name_span.clone())
        .label("wrong form of this keyword")
        .help("see the keyword in schemas/gsd-keywords.toml (`index`)")
}

fn check_range(setting: &Setting, keyword: &Keyword, n: i64, out: &mut Vec<Diagnostic>) {
    let (min, max) = keyword.spec.number_range();
    if (min..=max).contains(&n) {
        return;
    }
    let tolerated = keyword
        .spec
        .tolerated_min
        .is_some_and(|t| (t..min).contains(&n));
    let diagnostic = if tolerated {
        Diagnostic::warning(
            "W234",
            format!("`{}` = {n} is below the specification's {min}", keyword.name),
        )
        .label(format!("the specification allows {min}..{max}"))
        .help(format!(
            "engineering tools accept it (STEP 7's own catalog has files with it); write {min} or more if the device allows it"
        ))
    } else {
        Diagnostic::error("E208", format!("`{}` = {n} is out of range", keyword.name))
            .label(format!("must be {min}..{max}"))
            .help(format!(
                "`{}` is {} in {min}..{max}",
                keyword.name,
                keyword.spec.kind.describe()
            ))
    };
    out.push(diagnostic.at(setting.value_span.clone()));
}

fn check_octets(setting: &Setting, keyword: &Keyword, bytes: &[i64], out: &mut Vec<Diagnostic>) {
    if let Some(&bad) = bytes.iter().find(|b| !(0..=0xFF).contains(*b)) {
        out.push(
            Diagnostic::error("E208", format!("{bad} is not a byte"))
                .at(setting.value_span.clone())
                .label("every value must be 0..255")
                .help(format!("`{}` is a list of bytes", keyword.name)),
        );
    }
    if let Some(max) = keyword.spec.max.filter(|&m| bytes.len() as i64 > m) {
        out.push(
            Diagnostic::error(
                "E208",
                format!("{} bytes in `{}`", bytes.len(), keyword.name),
            )
            .at(setting.value_span.clone())
            .label(format!("at most {max} bytes"))
            .help("a parameter telegram holds at most 237 user bytes"),
        );
    }
}

fn check_length(setting: &Setting, keyword: &Keyword, text: &str, out: &mut Vec<Diagnostic>) {
    let Some(max) = keyword.spec.max_len else {
        return;
    };
    let len = text.chars().count();
    if len > max {
        out.push(too_long(
            &format!("`{}`", keyword.name),
            len,
            max,
            setting.value_span.clone(),
        ));
    }
}

fn check_revision(setting: &Setting, keyword: &Keyword, revision: i64, out: &mut Vec<Diagnostic>) {
    let needs = keyword.spec.revision;
    if needs > revision {
        out.push(
            Diagnostic::warning(
                "W210",
                format!("`{}` needs GSD_Revision {needs}", keyword.name),
            )
            .at(setting.name_span.clone())
            .label(format!(
                "introduced in GSD revision {needs}; this file says {revision}"
            ))
            .help(format!(
                "set `GSD_Revision = {needs}` or more, or drop the keyword"
            )),
        );
    }
}

/// W211 for each setting whose keyword and argument an earlier one in
/// `scope` has, `seen` listing the settings that may appear once. Sorting
/// finds them in O(n log n) whatever the keys (a hash set of keys a file
/// chooses could be made quadratic).
fn duplicates(
    scope: &[Setting],
    seen: &mut [(&str, Option<Arg>, usize)],
    out: &mut Vec<Diagnostic>,
) {
    seen.sort_unstable();
    let mut repeated: Vec<usize> = seen
        .windows(2)
        .filter(|pair| (pair[0].0, pair[0].1) == (pair[1].0, pair[1].1))
        .map(|pair| pair[1].2)
        .collect();
    repeated.sort_unstable();
    for setting in repeated.into_iter().map(|position| &scope[position]) {
        let name = match setting.index() {
            Some(i) => format!("{}({i})", setting.name),
            None => setting.name.to_string(),
        };
        out.push(
            Diagnostic::warning("W211", format!("`{name}` appears twice"))
                .at(setting.name_span.clone())
                .label("repeated here")
                .help("keep one: tools disagree on whether the first or the last counts"),
        );
    }
}

fn mandatory(file: &GsdFile, out: &mut Vec<Diagnostic>) {
    let mut missing: Vec<&Keyword> = schema::schema()
        .mandatory()
        .filter(|k| file.get(&k.name).is_none())
        .collect();
    missing.sort_by(|a, b| a.name.cmp(&b.name));
    for keyword in missing {
        out.push(
            Diagnostic::error(
                "E206",
                format!("mandatory keyword `{}` is missing", keyword.name),
            )
            .at(file_span(file))
            .label(format!("no `{}` in this file", keyword.name))
            .help(format!(
                "add `{} = <{}>`",
                keyword.name,
                keyword.spec.kind.describe()
            )),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_keyword_is_suggested_in_its_own_spelling() {
        assert_eq!(
            closest_keyword("min_slave_interval").as_deref(),
            Some("Min_Slave_Intervall")
        );
        assert_eq!(
            closest_keyword("vendor_nam").as_deref(),
            Some("Vendor_Name")
        );
        assert_eq!(closest_keyword("model_nam_xyz"), None);
    }
}
