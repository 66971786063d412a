//! The checks lowering applies to single values, and the diagnostics they
//! collect.

use crate::description::Text;
use crate::diag::{Diagnostic, Diagnostics};
use crate::i18n::{files, Lang, Phrase};
use crate::ir::decision::DecisionWords;
use crate::ir::{self, Decision, DecisionKind};
use crate::unicode::{first_unsafe, is_unsafe};
use std::collections::{BTreeMap, BTreeSet};
use std::ops::Range;
use toml::Spanned;

pub use crate::spec::GSD_NAME_LEN;

pub struct Checker {
    diagnostics: Diagnostics,
    /// Strings that go into a GSD must be short 7-bit ASCII.
    for_gsd: bool,
    latin1: bool,
    /// The languages besides English that the description's texts use,
    /// each with where a text first gives it.
    languages: BTreeMap<String, Range<usize>>,
    /// Placeholders and gsdc's defaults, as lowering meets them.
    decisions: Vec<Decision>,
    /// The prefix of the first name the description writes each address
    /// with (`Numbering::written_prefixes`).
    written_prefixes: BTreeMap<u16, String>,
    /// Every text the description gives, in every language, and those
    /// lowering renders from them (a mapping's name for each entry): what
    /// the device files say that gsdc did not write.
    given: BTreeSet<String>,
}

/// Whether a text may break lines (with `\n`, the one line break it holds).
#[derive(Clone, Copy)]
enum Lines {
    One,
    Many,
}

impl Lines {
    fn allows(self, c: char) -> bool {
        matches!(self, Lines::Many) && c == '\n'
    }
}

/// Where the defaults of several items come from: `default` for all of
/// them, or `defaults`, one each in order.
pub enum Defaults<'a, T> {
    Same(&'a Spanned<T>),
    Each(&'a Spanned<Vec<Spanned<T>>>),
}

/// What the defaults' diagnostics call the table that gives them (`noun`)
/// and its items, and the order `defaults` lists them in.
pub struct DefaultsOf {
    pub noun: &'static str,
    pub item: &'static str,
    pub items: &'static str,
    pub order: &'static str,
}

impl Checker {
    /// `latin1`: the GSD's strings may have Latin-1's printable characters
    /// (`[profibus] charset = "latin-1"`).
    pub fn new(for_gsd: bool, latin1: bool) -> Self {
        Checker {
            diagnostics: Diagnostics::default(),
            for_gsd,
            latin1,
            languages: BTreeMap::new(),
            decisions: Vec::new(),
            written_prefixes: BTreeMap::new(),
            given: BTreeSet::new(),
        }
    }

    /// A placeholder, said where it is written (the warning's code and text
    /// are the caller's, `why` what it is not): listed in every generated
    /// file.
    pub fn placeholder(&mut self, warning: Diagnostic, (path, value): (&str, String), why: Phrase) {
        self.push(warning);
        self.decisions.push(Decision {
            kind: DecisionKind::Placeholder,
            path: path.to_string(),
            value,
            reason: why.get(Lang::En).to_string(),
            words: Some(DecisionWords {
                path: None,
                value: None,
                reason: why,
            }),
        });
    }

    /// W104: gsdc chose `value` for `path`, which the description does not
    /// state; `near` is where the description would state it.
    pub fn defaulted(&mut self, path: &str, value: impl ToString, near: Range<usize>) {
        let value = value.to_string();
        self.push(
            Diagnostic::warning(
                "W104",
                format!("{path} is not stated: gsdc uses {value}"),
            )
            .at(near)
            .label(format!("no `{}` here", path.rsplit('.').next().unwrap_or(path)))
            .help("state what the firmware does (and mark it under [choices] if the manual does not say); `gsdc build --deny-warnings` refuses gsdc's defaults"),
        );
        self.decisions.push(Decision {
            kind: DecisionKind::Default,
            path: path.to_string(),
            value,
            reason: files::NOT_STATED.get(Lang::En).to_string(),
            words: Some(DecisionWords {
                path: None,
                value: None,
                reason: files::NOT_STATED,
            }),
        });
    }

    /// A number gsdc gives by its own rule where the description has no
    /// key for it: listed in every header, not warned about (the layouts
    /// carry it, so the firmware cannot drift from it).
    pub fn convention(&mut self, path: Phrase, value: Phrase, reason: Phrase) {
        self.listed(DecisionKind::Convention, path, value, reason);
    }

    /// How gsdc lays out bytes the manual gives no place for (User_Prm_Data's
    /// offsets, config identifiers): listed in every header, not warned
    /// about (the layouts carry every number).
    pub fn layout(&mut self, path: &str, value: impl ToString, reason: Phrase) {
        self.decisions.push(Decision {
            kind: DecisionKind::Layout,
            path: path.to_string(),
            value: value.to_string(),
            reason: reason.get(Lang::En).to_string(),
            words: Some(DecisionWords {
                path: None,
                value: None,
                reason,
            }),
        });
    }

    /// What gsdc's device file says the card does where the description
    /// has no key for it: listed in every header, not warned about (the
    /// firmware must do it; no value would change the file).
    pub fn requirement(&mut self, path: Phrase, value: Phrase, reason: Phrase) {
        self.listed(DecisionKind::Requirement, path, value, reason);
    }

    /// A decision of gsdc's own, in its words.
    fn listed(&mut self, kind: DecisionKind, path: Phrase, value: Phrase, reason: Phrase) {
        let english = |phrase: Phrase| phrase.get(Lang::En).to_string();
        self.decisions.push(Decision {
            kind,
            path: english(path),
            value: english(value),
            reason: english(reason),
            words: Some(DecisionWords {
                path: Some(path),
                value: Some(value),
                reason,
            }),
        });
    }

    /// The placeholders and defaults met, in the order met.
    pub fn take_decisions(&mut self) -> Vec<Decision> {
        std::mem::take(&mut self.decisions)
    }

    /// A function-code name read: the address is written back with its
    /// prefix, the first one the description writes it with.
    pub fn wrote_name(&mut self, address: u16, prefix: &str) {
        self.written_prefixes
            .entry(address)
            .or_insert_with(|| prefix.to_string());
    }

    pub fn take_written_prefixes(&mut self) -> BTreeMap<u16, String> {
        std::mem::take(&mut self.written_prefixes)
    }

    /// Every language besides English that a text used, in code order.
    pub fn languages(&self) -> Vec<String> {
        self.languages.keys().cloned().collect()
    }

    /// W108 for each language of the description's texts that gsdc has no
    /// words in, where a text first gives it: its texts there are the
    /// description's, and gsdc's own words in them English.
    pub fn languages_without_words(&mut self) {
        let known: Vec<String> = crate::i18n::Lang::ALL
            .iter()
            .map(|l| l.code().to_string())
            .collect();
        let known = crate::i18n::list(crate::i18n::Lang::En, &known);
        let without: Vec<(String, Range<usize>)> = self
            .languages
            .iter()
            .filter(|(code, _)| crate::i18n::Lang::of(code).is_none())
            .map(|(code, span)| (code.clone(), span.clone()))
            .collect();
        for (code, span) in without {
            self.push(
                Diagnostic::warning(
                    "W108",
                    format!("gsdc has no words in `{code}`: its own words in the `{code}` texts stay English"),
                )
                .at(span)
                .label("a language gsdc's catalogue lacks")
                .help(format!(
                    "the GSDML's `{code}` texts and the datasheet's `{code}` page carry the description's `{code}` texts, and gsdc's own words (module descriptions, record and category names, the datasheet's headings and sentences) in English; gsdc has its words in {known} (src/i18n)"
                )),
            );
        }
    }

    pub fn push(&mut self, diagnostic: Diagnostic) {
        self.diagnostics.push(diagnostic);
    }

    pub fn finish(self) -> Diagnostics {
        self.diagnostics
    }

    /// A string that must not be empty.
    pub fn required(&mut self, s: &Spanned<String>, what: &str) -> String {
        self.non_empty(s.get_ref(), s.span(), what);
        s.get_ref().clone()
    }

    /// Not empty, and no character that a device file, a generated header
    /// or generated code cannot hold safely; whether it is both.
    pub fn non_empty(&mut self, s: &str, span: Range<usize>, what: &str) -> bool {
        self.non_empty_lines(s, span, what, Lines::One)
    }

    /// [`Checker::non_empty`], with line breaks where `lines` allows them.
    fn non_empty_lines(&mut self, s: &str, span: Range<usize>, what: &str, lines: Lines) -> bool {
        let empty = s.trim().is_empty();
        if empty {
            self.push(
                Diagnostic::error("E117", format!("{what} is empty"))
                    .at(span.clone())
                    .label("empty")
                    .help(format!("write the {what}")),
            );
        }
        let Some(bad) = first_unsafe(s, |c| lines.allows(c)) else {
            return !empty;
        };
        self.push(
            Diagnostic::error(
                "E135",
                format!("{what} has {}, a control or formatting character", char_name(bad)),
            )
            .at(span)
            .label("not a printable character")
            .help("remove it: device files and generated code show texts as they are, and such a character breaks a line, a string or the reading order"),
        );
        false
    }

    /// A string that becomes the value of the GSD keyword `keyword`
    /// (`Vendor_Name`): not empty, 7-bit printable ASCII without `"`, and
    /// no longer than the keyword schema lets the keyword be.
    pub fn gsd_string(&mut self, s: &Spanned<String>, keyword: &str, what: &str) -> String {
        let limit = crate::gsd::keyword_max_len(keyword);
        self.check_gsd(s.get_ref(), s.span(), limit, what, GsdForm::Only);
        s.get_ref().clone()
    }

    /// [`Checker::gsd_string`] of a string the description may leave out.
    pub fn optional_gsd_string(
        &mut self,
        s: Option<&Spanned<String>>,
        keyword: &str,
        what: &str,
    ) -> Option<String> {
        s.map(|s| self.gsd_string(s, keyword, what))
    }

    /// A string the GSD writes as it is, at most `limit` characters (a
    /// module's or parameter's name).
    /// The description's words: recorded as given.
    pub fn gsd_name(&mut self, s: &Spanned<String>, limit: usize, what: &str) -> String {
        self.check_gsd(s.get_ref(), s.span(), limit, what, GsdForm::Only);
        self.given.insert(s.get_ref().clone());
        s.get_ref().clone()
    }

    /// A text a GSD shows in a comment (a choice's reason): any length, but
    /// 7-bit printable ASCII when the description has a GSD.
    pub fn gsd_comment(&mut self, s: &str, span: Range<usize>, what: &str) {
        self.non_empty(s, span.clone(), what);
        if !self.for_gsd {
            return;
        }
        if let Some(bad) = s.chars().find(|c| !(' '..='~').contains(c)) {
            self.push(
                Diagnostic::error(
                    "E102",
                    format!("{what} has {}, which a GSD file cannot hold", char_name(bad)),
                )
                .at(span)
                .label("not 7-bit printable ASCII")
                .help("it goes into the GSD's header as a comment: write it in ASCII (quote a manual's Chinese words in the value's own comment in the description)"),
            );
        }
    }

    /// A string the GSD writes as it is, at most `limit` characters, that
    /// is no text of the description (a vendor keyword's value).
    pub fn check_gsd_string(&mut self, s: &str, span: Range<usize>, limit: usize, what: &str) {
        self.check_gsd(s, span, limit, what, GsdForm::Only);
    }

    /// What goes into the GSD of a text, which may have a short form beside it.
    pub fn check_gsd_text(&mut self, s: &str, span: Range<usize>, limit: usize, what: &str) {
        self.check_gsd(s, span, limit, what, GsdForm::OfText);
    }

    fn check_gsd(&mut self, s: &str, span: Range<usize>, limit: usize, what: &str, form: GsdForm) {
        self.non_empty(s, span.clone(), what);
        if !self.for_gsd {
            return;
        }
        let latin1 = self.latin1;
        if let Some(bad) = s.chars().find(|c| !is_gsd_char(*c, latin1)) {
            let help = match (form, latin1) {
                (_, true) => "this GSD's strings are Latin-1 without `\"` (charset = \"latin-1\"): write it in those characters",
                (GsdForm::Only, false) => "GSD strings are 7-bit ASCII without `\"` (a card whose shipped GSD is Latin-1 states charset = \"latin-1\")",
                (GsdForm::OfText, false) => "GSD strings are 7-bit ASCII without `\"`: give the GSD an ASCII form with `gsd = \"...\"`, and other languages by their code (`zh = \"...\"`)",
            };
            self.push(
                Diagnostic::error(
                    "E102",
                    format!(
                        "{what} has {}, which a GSD file cannot hold",
                        char_name(bad)
                    ),
                )
                .at(span.clone())
                .label(if latin1 {
                    "not printable Latin-1, or a quote"
                } else {
                    "not 7-bit printable ASCII, or a quote"
                })
                .help(help),
            );
        }
        let len = s.chars().count();
        if len > limit {
            let help = match form {
                GsdForm::Only => format!("shorten it to at most {limit} characters"),
                GsdForm::OfText => format!("shorten it to at most {limit} characters, or keep it and give the GSD a short form: `gsd = \"...\"`"),
            };
            self.push(
                Diagnostic::error(
                    "E103",
                    format!("{what} is {len} characters long; GSD allows {limit}"),
                )
                .at(span)
                .label(format!("{} characters too long", len - limit))
                .help(help),
            );
        }
    }

    /// A text; what goes into the GSD (its short form, else its English) is
    /// checked for the GSD when `gsd_limit` is given. Other languages come
    /// out in the order of their codes.
    pub fn text(&mut self, t: &Spanned<Text>, gsd_limit: Option<usize>, what: &str) -> ir::Text {
        self.text_of_lines(t, gsd_limit, what, Lines::One)
    }

    /// A text of one or more lines, which no GSD holds: a GSDML file's
    /// texts may break lines (SEW's MOVI-C's diagnosis help texts list the
    /// remedies one per line), and the datasheet shows the breaks.
    pub fn text_of_lines_allowed(&mut self, t: &Spanned<Text>, what: &str) -> ir::Text {
        self.text_of_lines(t, None, what, Lines::Many)
    }

    fn text_of_lines(
        &mut self,
        t: &Spanned<Text>,
        gsd_limit: Option<usize>,
        what: &str,
        lines: Lines,
    ) -> ir::Text {
        let text = t.get_ref();
        let en_span = text.en_span(&t.span());
        let en_ok = self.non_empty_lines(text.en.get_ref(), en_span.clone(), what, lines);
        match (&text.gsd, gsd_limit) {
            (Some(gsd), Some(limit)) => self.check_gsd_text(gsd.get_ref(), gsd.span(), limit, what),
            // The English, refused above, is not refused again.
            (None, Some(limit)) if en_ok => {
                self.check_gsd_text(text.en.get_ref(), en_span, limit, what);
            }
            // A short form that only a rendered name puts into a GSD (its
            // caller checks it there), or nothing does: a text all the same.
            (Some(gsd), None) => {
                self.non_empty_lines(gsd.get_ref(), gsd.span(), what, lines);
            }
            (None, _) => {}
        }
        for (code, other) in &text.others {
            self.non_empty_lines(other.get_ref(), other.span(), what, lines);
            self.languages
                .entry(code.get_ref().clone())
                .or_insert_with(|| code.span());
        }
        let mut others: Vec<(String, String)> = text
            .others
            .iter()
            .map(|(code, other)| (code.get_ref().clone(), other.get_ref().clone()))
            .collect();
        others.sort();
        let text = ir::Text {
            en: text.en.get_ref().clone(),
            others,
            gsd: text.gsd.as_ref().map(|g| g.get_ref().clone()),
        };
        self.given(&text);
        text
    }

    /// Records `text` as the description's: lowering rendered it from the
    /// description's words alone.
    pub fn given(&mut self, text: &ir::Text) {
        self.given.insert(text.en.clone());
        self.given
            .extend(text.others.iter().map(|(_, other)| other.clone()));
        self.given.extend(text.gsd.clone());
    }

    /// The texts the description gave, and those rendered from them.
    pub fn take_given(&mut self) -> BTreeSet<String> {
        std::mem::take(&mut self.given)
    }

    /// Where the defaults of `count` items come from: exactly one of
    /// `default` and `defaults`, and as many of the latter as items (E122,
    /// E123; `table` is the span of the table's name).
    pub fn defaults<'a, T>(
        &mut self,
        default: &'a Option<Spanned<T>>,
        defaults: &'a Option<Spanned<Vec<Spanned<T>>>>,
        count: usize,
        of: &DefaultsOf,
        table: Range<usize>,
    ) -> Option<Defaults<'a, T>> {
        let DefaultsOf {
            noun,
            item,
            items,
            order,
        } = of;
        let error = match (default, defaults) {
            (Some(default), None) => return Some(Defaults::Same(default)),
            (None, Some(list)) if list.get_ref().len() == count => {
                return Some(Defaults::Each(list))
            }
            (None, Some(list)) => Diagnostic::error(
                "E122",
                format!("{} defaults for {count} {items}", list.get_ref().len()),
            )
            .at(list.span())
            .label(format!("expected {count} values"))
            .help(format!("give one default per {item}, {order}")),
            (Some(default), Some(_)) => Diagnostic::error(
                "E123",
                format!("a {noun} has both `default` and `defaults`"),
            )
            .at(default.span())
            .label("remove this or `defaults`")
            .help(format!("`default` sets every {item}, `defaults` each one")),
            (None, None) => Diagnostic::error(
                "E123",
                format!("a {noun} has neither `default` nor `defaults`"),
            )
            .at(table)
            .label(format!("in this {noun}"))
            .help(format!(
                "add `default = ...` for every {item}, or `defaults = [...]` one per {item}"
            )),
        };
        self.push(error);
        None
    }

    /// `value` as a `T` within `min..=max`, or an E101 diagnostic.
    pub fn in_range<T: TryFrom<i64>>(
        &mut self,
        value: i64,
        min: i64,
        max: i64,
        span: Range<usize>,
        what: &str,
    ) -> Option<T> {
        if (min..=max).contains(&value) {
            T::try_from(value).ok()
        } else {
            self.push(
                Diagnostic::error("E101", format!("{value} is out of range for {what}"))
                    .at(span)
                    .label(format!("not within {min}..={max}"))
                    .help(format!("{what} must be from {min} to {max}")),
            );
            None
        }
    }

    /// A spanned number within `min..=max`.
    pub fn spanned_in_range<T, V>(
        &mut self,
        v: &Spanned<V>,
        min: i64,
        max: i64,
        what: &str,
    ) -> Option<T>
    where
        T: TryFrom<i64>,
        V: Copy + Into<i64>,
    {
        self.in_range((*v.get_ref()).into(), min, max, v.span(), what)
    }

    /// A number that becomes the value of the GSD keyword `keyword`
    /// (`C2_Max_Count_Channels`), within the range the keyword schema gives
    /// it: the range `gsdc check` holds the generated GSD to, so that the
    /// two cannot disagree.
    pub fn gsd_number<T, V>(&mut self, v: &Spanned<V>, keyword: &str, what: &str) -> Option<T>
    where
        T: TryFrom<i64>,
        V: Copy + Into<i64>,
    {
        self.gsd_number_from(v, keyword, i64::MIN, what)
    }

    /// [`Checker::gsd_number`], and at least `least`: what the description
    /// asks more of the value than the keyword's type (a class 2 channel
    /// has at least one connection).
    pub fn gsd_number_from<T, V>(
        &mut self,
        v: &Spanned<V>,
        keyword: &str,
        least: i64,
        what: &str,
    ) -> Option<T>
    where
        T: TryFrom<i64>,
        V: Copy + Into<i64>,
    {
        let (min, max) = crate::gsd::keyword_range(keyword);
        self.spanned_in_range(v, min.max(least), max, what)
    }

    /// E109: a range `[min, max]` written the wrong way round.
    pub fn reversed(&mut self, span: Range<usize>, min: impl ToString, max: impl ToString) {
        let (min, max) = (min.to_string(), max.to_string());
        self.push(
            Diagnostic::error("E109", format!("range [{min}, {max}] is reversed"))
                .at(span)
                .label("minimum above maximum")
                .help("write the range as [minimum, maximum]"),
        );
    }

    /// E172: a keyword the GSD's revision does not have yet.
    pub fn since_revision(&mut self, keyword: &str, span: Range<usize>, gsd_revision: u8) {
        let since = crate::gsd::schema::keyword(keyword).revision;
        if i64::from(gsd_revision) < since {
            self.push(
                Diagnostic::error(
                    "E172",
                    format!(
                        "{keyword} came with GSD revision {since}; this GSD is revision {gsd_revision}"
                    ),
                )
                .at(span)
                .label(format!("needs revision {since}"))
                .help(format!(
                    "set gsd_revision = {since} or later, or leave this out"
                )),
            );
        }
    }

    /// E105 for the second and later occurrences of a key.
    pub fn duplicate(&mut self, what: String, span: Range<usize>) {
        self.push(
            Diagnostic::error("E105", format!("{what} is given twice"))
                .at(span)
                .label("given again here")
                .help("remove one of them"),
        );
    }
}

/// Whether a string that goes into the GSD can have a short form (`gsd`)
/// beside it: texts can, plain strings (vendor, model) cannot.
#[derive(Clone, Copy)]
enum GsdForm {
    Only,
    OfText,
}

/// A character of a GSD string: printable ASCII but `"`, and with
/// `latin1` Latin-1's printable characters above it (U+00A0 to U+00FF; the
/// C1 controls between are none).
pub fn is_gsd_char(c: char, latin1: bool) -> bool {
    ((' '..='~').contains(&c) && c != '"') || (latin1 && ('\u{A0}'..='\u{FF}').contains(&c))
}

/// Whether [`Checker::non_empty`] takes `s`: what it refused is not checked
/// again.
pub fn is_clean(s: &str) -> bool {
    !s.trim().is_empty() && first_unsafe(s, |_| false).is_none()
}

/// [`is_clean`], line breaks allowed: what
/// [`Checker::text_of_lines_allowed`] takes.
pub fn is_clean_lines(s: &str) -> bool {
    !s.trim().is_empty() && first_unsafe(s, |c| Lines::Many.allows(c)).is_none()
}

/// A character as a message shows it: itself in backticks when it prints,
/// its code point when it does not.
pub fn char_name(c: char) -> String {
    if is_unsafe(c) || c.is_whitespace() && c != ' ' {
        format!("U+{:04X}", u32::from(c))
    } else {
        format!("`{c}`")
    }
}
