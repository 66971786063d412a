//! The checks lowering applies to single values, and the diagnostics they
//! collect.

use crate::description::Text;
use crate::diag::{Diagnostic, Diagnostics};
use crate::ir;
use std::ops::Range;
use toml::Spanned;

/// GSD string limits (GSD specification V5.1; FIELDBUS-NOTES §3).
pub const GSD_NAME_LEN: usize = 32;
pub const GSD_INFO_LEN: usize = 256;

pub struct Checker {
    diagnostics: Diagnostics,
    /// Strings that go into a GSD must be short 7-bit ASCII.
    for_gsd: bool,
}

impl Checker {
    pub fn new(for_gsd: bool) -> Self {
        Checker {
            diagnostics: Diagnostics::default(),
            for_gsd,
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

    fn non_empty(&mut self, s: &str, span: Range<usize>, what: &str) {
        if s.trim().is_empty() {
            self.push(
                Diagnostic::error("E117", format!("{what} is empty"))
                    .at(span)
                    .label("empty")
                    .help(format!("write the {what}")),
            );
        }
    }

    /// A string that goes into the GSD: not empty, 7-bit printable ASCII
    /// without `"`, at most `limit` characters.
    pub fn gsd_string(&mut self, s: &Spanned<String>, limit: usize, what: &str) -> String {
        self.check_gsd_text(s.get_ref(), s.span(), limit, what);
        s.get_ref().clone()
    }

    pub fn check_gsd_text(&mut self, s: &str, span: Range<usize>, limit: usize, what: &str) {
        self.non_empty(s, span.clone(), what);
        if !self.for_gsd {
            return;
        }
        if let Some(bad) = s.chars().find(|c| !is_gsd_char(*c)) {
            self.push(
                Diagnostic::error("E102", format!("{what} has `{}`, which a GSD file cannot hold", bad.escape_default()))
                    .at(span.clone())
                    .label("not 7-bit printable ASCII, or a quote")
                    .help("GSD strings are 7-bit ASCII without `\"`; put other languages in `zh` (GSDML only)"),
            );
        }
        let len = s.chars().count();
        if len > limit {
            self.push(
                Diagnostic::error(
                    "E103",
                    format!("{what} is {len} characters long; GSD allows {limit}"),
                )
                .at(span)
                .label(format!("{} characters too long", len - limit))
                .help(format!("shorten it to at most {limit} characters")),
            );
        }
    }

    /// A text; its English part also goes into the GSD when `gsd_limit` is given.
    pub fn text(&mut self, t: &Spanned<Text>, gsd_limit: Option<usize>, what: &str) -> ir::Text {
        let text = t.get_ref();
        let en_span = text.en_span(&t.span());
        match gsd_limit {
            Some(limit) => self.check_gsd_text(text.en.get_ref(), en_span, limit, what),
            None => self.non_empty(text.en.get_ref(), en_span, what),
        }
        if let Some(zh) = &text.zh {
            self.non_empty(zh.get_ref(), zh.span(), what);
        }
        ir::Text {
            en: text.en.get_ref().clone(),
            zh: text.zh.as_ref().map(|z| z.get_ref().clone()),
        }
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

pub fn is_gsd_char(c: char) -> bool {
    (' '..='~').contains(&c) && c != '"'
}
