//! Diagnostics: what gsdc says about a description, a GSD or a GSDML file.
//!
//! Every diagnostic has a stable code (`E…` for errors, `W…` for warnings, see
//! `docs/rules.md`), a message, an optional span into the source it came from,
//! a label shown under the caret and a help line. Rendering is rustc-style for
//! people and JSON lines for tools.

use std::cell::OnceCell;
use std::fmt::Write as _;
use std::ops::Range;
use unicode_width::UnicodeWidthChar;

pub use crate::rules::Severity;

#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Diagnostic {
    pub code: &'static str,
    pub severity: Severity,
    pub message: String,
    /// Byte range in the source the diagnostic is about, if it is about a place.
    pub span: Option<Range<usize>>,
    /// Short text printed under the caret.
    pub label: Option<Box<str>>,
    pub help: Option<Box<str>>,
    /// What few diagnostics have, boxed so that a diagnostic stays small
    /// (it is the error of many a `Result`): see [`Diagnostic::subject`]
    /// and [`Diagnostic::also`].
    pub(crate) extra: Option<Box<Extra>>,
}

#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub(crate) struct Extra {
    subject: Option<Box<str>>,
    also: Option<Also>,
}

/// The second place of a diagnostic about two.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Also {
    pub span: Range<usize>,
    pub label: Box<str>,
}

impl Diagnostic {
    pub fn error(code: &'static str, message: impl Into<String>) -> Self {
        Self::new(code, Severity::Error, message)
    }

    pub fn warning(code: &'static str, message: impl Into<String>) -> Self {
        Self::new(code, Severity::Warning, message)
    }

    fn new(code: &'static str, severity: Severity, message: impl Into<String>) -> Self {
        debug_assert!(
            crate::rules::find(code).is_some_and(|r| r.severity == severity),
            "{code} is not a {severity:?} of crate::rules::RULES"
        );
        Diagnostic {
            code,
            severity,
            message: message.into(),
            span: None,
            label: None,
            help: None,
            extra: None,
        }
    }

    pub fn at(mut self, span: Range<usize>) -> Self {
        self.span = Some(span);
        self
    }

    pub fn at_opt(mut self, span: Option<Range<usize>>) -> Self {
        self.span = span;
        self
    }

    pub fn label(mut self, label: impl Into<String>) -> Self {
        self.label = Some(label.into().into_boxed_str());
        self
    }

    pub fn help(mut self, help: impl Into<String>) -> Self {
        self.help = Some(help.into().into_boxed_str());
        self
    }

    /// The other place a finding about two is about, and what is there.
    pub fn also_at(mut self, span: Range<usize>, label: impl Into<String>) -> Self {
        self.extra.get_or_insert_default().also = Some(Also {
            span,
            label: label.into().into_boxed_str(),
        });
        self
    }

    /// The GSD keyword or GSDML element the diagnostic is about, for tools.
    pub fn subject(&self) -> Option<&str> {
        self.extra.as_ref()?.subject.as_deref()
    }

    /// The second place of a finding about two things that clash (two
    /// records at one index), with its label.
    pub fn also(&self) -> Option<&Also> {
        self.extra.as_ref()?.also.as_ref()
    }

    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }
}

/// Diagnostics about one source, in the order they were found.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Diagnostics(pub Vec<Diagnostic>);

impl Diagnostics {
    pub fn push(&mut self, diagnostic: Diagnostic) {
        self.0.push(diagnostic);
    }

    pub fn extend(&mut self, other: impl IntoIterator<Item = Diagnostic>) {
        self.0.extend(other);
    }

    pub fn has_errors(&self) -> bool {
        self.0.iter().any(Diagnostic::is_error)
    }

    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    pub fn iter(&self) -> std::slice::Iter<'_, Diagnostic> {
        self.0.iter()
    }

    pub fn errors(&self) -> impl Iterator<Item = &Diagnostic> {
        self.0.iter().filter(|d| d.is_error())
    }

    /// Names the subject of every diagnostic that has a place but no subject
    /// yet, with `subject_at(offset)`.
    pub fn name_subjects(&mut self, mut subject_at: impl FnMut(usize) -> Option<String>) {
        for d in &mut self.0 {
            if d.subject().is_none() {
                let subject = d.span.as_ref().and_then(|span| subject_at(span.start));
                if let Some(subject) = subject {
                    d.extra.get_or_insert_default().subject = Some(subject.into_boxed_str());
                }
            }
        }
    }
}

impl IntoIterator for Diagnostics {
    type Item = Diagnostic;
    type IntoIter = std::vec::IntoIter<Diagnostic>;
    fn into_iter(self) -> Self::IntoIter {
        self.0.into_iter()
    }
}

impl From<Vec<Diagnostic>> for Diagnostics {
    fn from(v: Vec<Diagnostic>) -> Self {
        Diagnostics(v)
    }
}

/// The most a reader takes of one input, and the diagnostic for more. A
/// hostile or mistaken input (a 200 MB file, `/dev/zero`) is refused before
/// it is read whole, so memory stays bounded whatever the file.
#[derive(Debug, Clone, Copy)]
pub struct InputLimit {
    pub max_bytes: usize,
    /// The rule code of the diagnostic.
    pub code: &'static str,
    /// What the reader reads, for the message: "a GSD file".
    pub what: &'static str,
    pub help: &'static str,
}

impl InputLimit {
    /// `Err` with the diagnostic when `len` bytes are more than the limit.
    pub fn check(&self, len: usize) -> Result<(), Diagnostic> {
        if len > self.max_bytes {
            Err(self.diagnostic())
        } else {
            Ok(())
        }
    }

    /// The file is larger than the limit. It has no place: nothing of the
    /// file was read.
    pub fn diagnostic(&self) -> Diagnostic {
        Diagnostic::error(
            self.code,
            format!(
                "the file is larger than {} MiB ({} bytes), the most gsdc reads of {}",
                self.max_bytes >> 20,
                self.max_bytes,
                self.what
            ),
        )
        .help(self.help)
    }
}

/// A named source text, so that spans can be turned into lines and columns.
#[derive(Debug, Clone)]
pub struct Source<'a> {
    pub name: &'a str,
    pub text: &'a str,
    /// Where each line of `text` starts, found when the first place is
    /// asked for: a file of many diagnostics is read once for their lines,
    /// not once each (an import renders dozens far into a megabyte).
    lines: OnceCell<Lines>,
}

/// Byte offsets where the lines of a text start: the line of any offset
/// without reading the text again.
#[derive(Debug, Clone)]
pub(crate) struct Lines(Vec<usize>);

impl Lines {
    /// memchr's vectorized search: a line at a time with `str`'s own search
    /// took a sixth of reading the device of the largest GSDML files.
    pub(crate) fn of(text: &str) -> Lines {
        let breaks = memchr::memchr_iter(b'\n', text.as_bytes()).map(|i| i + 1);
        Lines(std::iter::once(0).chain(breaks).collect())
    }

    /// The 1-based line of a byte offset.
    pub(crate) fn line(&self, offset: usize) -> u32 {
        self.0.partition_point(|&start| start <= offset) as u32
    }

    /// Where a 1-based line starts.
    fn start(&self, line: u32) -> usize {
        self.0[line as usize - 1]
    }

    /// Where each line starts, the first at 0.
    pub(crate) fn starts(&self) -> &[usize] {
        &self.0
    }
}

/// 1-based line and column (in characters) of a byte offset; for many
/// offsets of one text, [`Source::line_col`] reads its lines once.
pub fn line_col(text: &str, offset: usize) -> (usize, usize) {
    Source::new("", text).line_col(offset)
}

fn floor_char_boundary(text: &str, mut offset: usize) -> usize {
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    offset
}

impl<'a> Source<'a> {
    pub fn new(name: &'a str, text: &'a str) -> Self {
        Source {
            name,
            text,
            lines: OnceCell::new(),
        }
    }

    /// [`line_col`] of a byte offset of the text.
    pub fn line_col(&self, offset: usize) -> (usize, usize) {
        let offset = floor_char_boundary(self.text, offset.min(self.text.len()));
        let lines = self.lines.get_or_init(|| Lines::of(self.text));
        let line = lines.line(offset);
        let column = self.text[lines.start(line)..offset].chars().count() + 1;
        (line as usize, column)
    }

    /// `file:line:column` of the diagnostic's span, or just the file name,
    /// as a terminal is shown it ([`shown`]).
    pub fn location(&self, diagnostic: &Diagnostic) -> String {
        match &diagnostic.span {
            Some(span) => {
                let (line, column) = self.line_col(span.start);
                format!("{}:{line}:{column}", shown(self.name))
            }
            None => shown(self.name),
        }
    }

    /// `file:line:column: message` on one line, as a terminal is shown it
    /// ([`shown`]).
    pub fn one_line(&self, diagnostic: &Diagnostic) -> String {
        format!(
            "{}: {}",
            self.location(diagnostic),
            shown(&diagnostic.message)
        )
    }

    /// rustc-style rendering: header, location, the source line with a caret
    /// under the span and its label, then the help line. Every line as a
    /// terminal is shown it: what the diagnostic quotes of its input (a
    /// name, a keyword, an argument) is escaped and, when long, shortened
    /// ([`shown`]).
    pub fn render(&self, diagnostic: &Diagnostic) -> String {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "{}[{}]: {}",
            diagnostic.severity.as_str(),
            diagnostic.code,
            shown(&diagnostic.message)
        );
        let label = diagnostic.label.as_deref();
        let mut pad = match &diagnostic.span {
            Some(span) => self.render_snippet(&mut out, span.clone(), "-->", label),
            None => {
                let _ = writeln!(out, " --> {}", shown(self.name));
                String::new()
            }
        };
        if let Some(also) = diagnostic.also() {
            let also_pad =
                self.render_snippet(&mut out, also.span.clone(), ":::", Some(&also.label));
            pad = pad.max(also_pad);
        }
        if let Some(help) = &diagnostic.help {
            let _ = writeln!(out, "{pad} = help: {}", shown(help));
        }
        out
    }

    /// Writes location (after `marker`: `-->` for the place, `:::` for the
    /// other one), source line and caret with `label`; returns the gutter's
    /// padding.
    fn render_snippet(
        &self,
        out: &mut String,
        span: Range<usize>,
        marker: &str,
        label: Option<&str>,
    ) -> String {
        let (line, column) = self.line_col(span.start);
        let gutter = line.to_string().len();
        let pad = " ".repeat(gutter);
        let _ = writeln!(out, "{pad}{marker} {}:{line}:{column}", shown(self.name));
        let start = floor_char_boundary(self.text, span.start.min(self.text.len()));
        let end = floor_char_boundary(self.text, span.end.min(self.text.len())).max(start);
        let line_start = self.text[..start].rfind('\n').map_or(0, |i| i + 1);
        let line_end = self.text[start..]
            .find('\n')
            .map_or(self.text.len(), |i| start + i);
        let before = &self.text[line_start..start];
        let after = self.text[start..line_end].trim_end_matches('\r');
        let span_chars = self.text[start..end.min(line_end)].chars().count().max(1);
        let (quoted, caret_at, width) = window(before, after, span_chars);
        let _ = writeln!(out, "{pad} |");
        let _ = writeln!(out, "{line} | {}", printable(&quoted));
        let label = label.map(|l| format!(" {}", shown(l))).unwrap_or_default();
        let _ = writeln!(
            out,
            "{pad} | {}{}{label}",
            " ".repeat(caret_at),
            "^".repeat(width)
        );
        pad
    }
}

/// Characters of a source line shown at most, so that a megabyte-long line
/// does not print a megabyte per diagnostic.
const MAX_SHOWN_LINE: usize = 120;

/// The part of a line to show around a span that starts between `before`
/// and `after` and is `span_chars` characters long: the whole line when it is
/// short, else a window with `...` where it was cut. Only the characters
/// shown are walked, so a line of megabytes costs no more than a short one.
/// Returns the text, the caret's column in it and the caret's width, both
/// in terminal columns (see [`columns`]).
fn window(before: &str, after: &str, span_chars: usize) -> (String, usize, usize) {
    let spanned = |tail: &str| columns(tail.chars().take(span_chars)).max(1);
    if before.len() + after.len() <= MAX_SHOWN_LINE {
        // Bytes bound characters: the whole line fits.
        let caret_at = columns(before.chars());
        return (format!("{before}{after}"), caret_at, spanned(after));
    }
    let lead: Vec<char> = before.chars().rev().take(MAX_SHOWN_LINE / 3 + 1).collect();
    let cut_before = lead.len() > MAX_SHOWN_LINE / 3;
    let lead: String = lead.iter().rev().skip(usize::from(cut_before)).collect();
    let room = MAX_SHOWN_LINE - lead.chars().count();
    let mut tail: String = after.chars().take(room + 1).collect();
    let cut_after = tail.chars().count() > room;
    if cut_after {
        tail.pop();
    }
    let prefix = if cut_before { "..." } else { "" };
    let suffix = if cut_after { "..." } else { "" };
    let caret_at = prefix.len() + columns(lead.chars());
    let width = spanned(&tail);
    (format!("{prefix}{lead}{tail}{suffix}"), caret_at, width)
}

/// The terminal columns characters take as [`printable`] shows them, as
/// Unicode's East Asian Width and zero-width properties say (unicode-width,
/// as wcwidth): two for the wide characters of Chinese texts, none for
/// combining marks, one for a tab (shown as a space), and the length of
/// its escape for a character shown escaped.
fn columns(chars: impl Iterator<Item = char>) -> usize {
    chars
        .map(|c| match (c, crate::unicode::escaped(c)) {
            ('\t', _) => 1,
            (_, Some(escape)) => escape.len(),
            (c, None) => c.width().unwrap_or(0),
        })
        .sum()
}

/// A quoted source line as shown: tabs as one space, so that carets line
/// up, and every other unsafe character escaped
/// ([`crate::unicode::escaped`]).
fn printable(line: &str) -> String {
    let mut shown = String::with_capacity(line.len());
    for c in line.chars() {
        match (c, crate::unicode::escaped(c)) {
            ('\t', _) => shown.push(' '),
            (_, Some(escape)) => shown.push_str(&escape),
            (c, None) => shown.push(c),
        }
    }
    shown
}

/// Characters of a diagnostic's headline, label or help line shown at
/// most: a message that quotes a hex argument of 131,072 digits, or a GSD
/// keyword of a megabyte, would print all of it. gsdc's own texts are
/// shorter than half of it.
const MAX_SHOWN_TEXT: usize = 1000;

/// A line of a diagnostic as a terminal is shown it: its unsafe
/// characters escaped ([`crate::unicode::escape`]), and no more than
/// [`MAX_SHOWN_TEXT`] characters of it, cut in the middle (`...`) so that
/// both its start and its end, where messages say what is wrong, are shown.
fn shown(text: &str) -> String {
    const KEPT: usize = MAX_SHOWN_TEXT / 2;
    let count = text.chars().count();
    if count <= MAX_SHOWN_TEXT {
        return crate::unicode::escape(text).into_owned();
    }
    let head_end = text.char_indices().nth(KEPT).map_or(text.len(), |(i, _)| i);
    let tail_start = text
        .char_indices()
        .nth(count - KEPT)
        .map_or(text.len(), |(i, _)| i);
    format!(
        "{}...{}",
        crate::unicode::escape(&text[..head_end]),
        crate::unicode::escape(&text[tail_start..])
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_col_counts_characters_not_bytes() {
        let text = "a = 1\nname = \"中文\" x\n";
        let x = text.find('x').unwrap();
        assert_eq!(line_col(text, x), (2, 13));
        assert_eq!(line_col(text, 0), (1, 1));
    }

    /// Each offset's place, counted by hand: at a line's start and end,
    /// inside a character (its start's place), past the end (the end's).
    #[test]
    fn a_sources_places_count_lines_and_characters() {
        let text = "\nab\r\n中文 é\n\nlast";
        let source = Source::new("x", text);
        let places: Vec<(usize, usize)> =
            (0..=text.len() + 1).map(|o| source.line_col(o)).collect();
        #[rustfmt::skip]
        let expected = [
            (1, 1), // the first line, empty
            (2, 1), (2, 2), (2, 3), (2, 4), // a, b, \r, \n
            (3, 1), (3, 1), (3, 1), (3, 2), (3, 2), (3, 2), // 中 and 文, 3 bytes each
            (3, 3), (3, 4), (3, 4), (3, 5), // blank, é (2 bytes), \n
            (4, 1), // the empty line
            (5, 1), (5, 2), (5, 3), (5, 4), (5, 5), (5, 5), // last, its end, past it
        ];
        assert_eq!(places, expected);
    }

    /// Chinese characters take two columns, a combining mark none: the
    /// caret stands under the span as a terminal shows the line.
    #[test]
    fn carets_count_terminal_columns() {
        let text = "name = \"汇川e\u{301}\" x\n";
        let x = text.find('x').unwrap();
        let d = Diagnostic::error("E003", "m").at(x..x + 1).label("here");
        let rendered = Source::new("x.toml", text).render(&d);
        let lines: Vec<&str> = rendered.lines().collect();
        let caret = lines[4].find('^').unwrap();
        let gutter = lines[3].find('|').unwrap() + 2;
        // `name = "` (8) + 汇川 (4) + é (1) + `" ` (2): column 16.
        assert_eq!(caret - gutter, 15, "{rendered}");
        assert_eq!(columns("汇川e\u{301}".chars()), 5);
    }

    /// A tab is shown as one space, and counted as one column: the caret
    /// stands under the value after two tabs, as wide as a span with a tab.
    #[test]
    fn carets_count_a_tab_as_the_space_it_is_shown_as() {
        let text = "Ident_Number\t=\t0x12345\r\n";
        let start = text.find("0x").unwrap();
        let d = Diagnostic::error("E208", "m").at(start..start + 7);
        let rendered = Source::new("x.gsd", text).render(&d);
        let lines: Vec<&str> = rendered.lines().collect();
        assert_eq!(lines[3], "1 | Ident_Number = 0x12345", "{rendered}");
        assert_eq!(lines[4], format!("  | {}^^^^^^^", " ".repeat(15)));
        let d = Diagnostic::error("E208", "m").at(start - 2..start + 7);
        let rendered = Source::new("x.gsd", text).render(&d);
        assert!(rendered.contains(&format!("  | {}^^^^^^^^^\n", " ".repeat(13))));
    }

    /// A keyword, an argument or a name quoted in a diagnostic reaches the
    /// terminal escaped, in the headline as in the quoted line and the
    /// label and help, and the caret still stands under the span.
    #[test]
    fn nothing_of_the_input_reaches_the_terminal_raw() {
        let text = "X\u{1b}[31mY\u{202E} = 1\r\n";
        let d = Diagnostic::warning("W205", "unknown keyword `X\u{1b}[31mY\u{202E}`")
            .at(0..text.find(" =").unwrap())
            .label("not \u{1b}[2J known")
            .help("did you mean `X\u{2066}`?");
        let rendered = Source::new("a\u{1b}]0;title\u{7}.gsd", text).render(&d);
        assert!(
            !rendered
                .chars()
                .any(|c| c != '\n' && crate::unicode::is_unsafe(c)),
            "{rendered:?}"
        );
        let lines: Vec<&str> = rendered.lines().collect();
        assert_eq!(
            lines[0],
            "warning[W205]: unknown keyword `X\\u001b[31mY\\u202e`"
        );
        assert_eq!(lines[1], " --> a\\u001b]0;title\\u0007.gsd:1:1");
        assert_eq!(lines[3], "1 | X\\u001b[31mY\\u202e = 1");
        assert_eq!(
            lines[4],
            format!("  | {} not \\u001b[2J known", "^".repeat(18))
        );
        assert_eq!(lines[5], "  = help: did you mean `X\\u2066`?");
    }

    /// A message quoting an argument of 131,072 hex digits printed all of
    /// them: the headline shows its start and its end.
    #[test]
    fn a_long_headline_is_cut_in_the_middle() {
        let digits = "A".repeat(131_073);
        let d = Diagnostic::error(
            "E411",
            format!("`{digits}` has 131073 hex digits: a byte is two"),
        );
        let rendered = Source::new("HEX", &digits).render(&d);
        assert!(rendered.len() < 2 * MAX_SHOWN_TEXT, "{}", rendered.len());
        let headline = rendered.lines().next().unwrap();
        assert!(headline.starts_with("error[E411]: `AAAA"), "{headline}");
        assert!(
            headline.ends_with("AAAA` has 131073 hex digits: a byte is two"),
            "{headline}"
        );
        assert!(headline.contains("A...A"), "{headline}");
    }

    #[test]
    fn render_puts_caret_under_span() {
        let text = "[device]\nvendor = 42\n";
        let start = text.find("42").unwrap();
        let d = Diagnostic::error("E003", "wrong type")
            .at(start..start + 2)
            .label("expected a string")
            .help("write vendor = \"Name\"");
        let rendered = Source::new("x.toml", text).render(&d);
        assert_eq!(
            rendered,
            "error[E003]: wrong type\n --> x.toml:2:10\n  |\n2 | vendor = 42\n  |          ^^ expected a string\n  = help: write vendor = \"Name\"\n"
        );
    }

    /// A finding about two places shows both, each with its label.
    #[test]
    fn a_second_place_is_shown_after_the_first() {
        let text = "[a]\nfirst = 0\n[b]\nindex = 1\n";
        let index = text.find('1').unwrap();
        let first = text.find('0').unwrap();
        let d = Diagnostic::error("E105", "two records at index 1")
            .at(index..index + 1)
            .label("this one")
            .also_at(first..first + 1, "and this one")
            .help("move one");
        let rendered = Source::new("x.toml", text).render(&d);
        assert_eq!(
            rendered,
            "error[E105]: two records at index 1\n --> x.toml:4:9\n  |\n4 | index = 1\n  |         ^ this one\n ::: x.toml:2:9\n  |\n2 | first = 0\n  |         ^ and this one\n  = help: move one\n"
        );
    }

    #[test]
    fn carets_count_the_columns_wide_characters_take() {
        let text = "name = { zh = \"名称（中文）\", en = 42 }\n";
        let start = text.find("42").unwrap();
        let d = Diagnostic::error("E003", "wrong type").at(start..start + 2);
        let rendered = Source::new("x.toml", text).render(&d);
        let lines: Vec<&str> = rendered.lines().collect();
        assert_eq!(lines[3], "1 | name = { zh = \"名称（中文）\", en = 42 }");
        // 15 narrow characters, 6 wide ones, 8 narrow: "42" 35 columns in.
        assert_eq!(lines[4], format!("  | {}^^", " ".repeat(15 + 2 * 6 + 8)));
        // A span over wide characters is as wide as they are drawn.
        let start = text.find('名').unwrap();
        let d = Diagnostic::error("E003", "x").at(start..start + "名称".len());
        let rendered = Source::new("x", text).render(&d);
        assert!(
            rendered.contains(&format!("  | {}^^^^\n", " ".repeat(15))),
            "{rendered}"
        );
    }

    #[test]
    fn a_long_line_shows_a_window_around_the_span() {
        let text = format!(
            "key = [{}\"PPO7\"{}]\n",
            "\"PPO1\", ".repeat(10_000),
            ", \"PPO2\"".repeat(10_000)
        );
        let start = text.find("PPO7").unwrap() - 1;
        let d = Diagnostic::error("E104", "not a PPO type").at(start..start + 6);
        let rendered = Source::new("x.toml", &text).render(&d);
        assert!(rendered.len() < 600, "{rendered}");
        let lines: Vec<&str> = rendered.lines().collect();
        let caret = lines[4].find('^').unwrap();
        assert_eq!(&lines[3][caret..caret + 6], "\"PPO7\"", "{rendered}");
        assert!(lines[3].contains("...") && lines[3].ends_with("..."));
    }
}
