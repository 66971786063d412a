//! Turns the logical lines of a GSD file into a [`GsdFile`].
//!
//! Each logical line is one statement: `Keyword[(arg)] = value`, a block's
//! opening or closing keyword, or a line that only makes sense inside a
//! block (`Text(1) = "on"`, `Unsigned8 0 0-255`, a module reference number).
//! Blocks are tracked with an explicit frame, never recursion, and a block
//! left open is closed (with E203) as soon as a line that cannot belong to it
//! arrives, so one missing `EndPrmText` does not swallow the rest of the file.

use std::borrow::Cow;
use std::ops::Range;

use crate::diag::Diagnostic;
use crate::gsd::lexer::{find_marker, Lexer, Tok, Token};
use crate::gsd::model::{
    Allowed, Arg, Baud, Block, ExtUserPrmData, GsdFile, IndexedText, Module, PrmDataType, PrmText,
    Setting, Slot, Spanned, UnitDiagArea, UnitDiagType, Value,
};
use crate::gsd::schema;

fn end_keyword(open_key: &str) -> &'static str {
    schema::BLOCKS
        .iter()
        .find(|(open, _)| *open == open_key)
        .map_or("", |(_, end)| end)
}

fn is_opener(key: &str) -> bool {
    schema::BLOCKS.iter().any(|(open, _)| *open == key)
}

fn is_end(key: &str) -> bool {
    schema::BLOCKS
        .iter()
        .any(|(_, end)| end.eq_ignore_ascii_case(key))
}

fn ends(key: &str, open_key: &str) -> bool {
    end_keyword(open_key).eq_ignore_ascii_case(key)
}

/// Decimal (leading zeros allowed) or `0x`/`0X` hexadecimal.
/// `None` for anything else, and for a number beyond `i64`.
pub(crate) fn parse_number(s: &str) -> Option<i64> {
    let (digits, radix) = match s.as_bytes() {
        [b'0', b'x' | b'X', hex @ ..] => (hex, 16),
        decimal => (decimal, 10),
    };
    if digits.is_empty() {
        return None;
    }
    digits.iter().try_fold(0i64, |n, &b| {
        let digit = char::from(b).to_digit(radix)?;
        n.checked_mul(i64::from(radix))?
            .checked_add(i64::from(digit))
    })
}

/// One element of what follows a keyword.
#[derive(Debug, Clone)]
enum Item<'a> {
    Num(Spanned<i64>),
    Str(Spanned<Cow<'a, str>>),
    Range(Spanned<(i64, i64)>),
    Family(Spanned<(i64, Vec<String>)>),
    /// A word that is not a number, or stray punctuation.
    Other(Range<usize>),
}

impl Item<'_> {
    fn span(&self) -> Range<usize> {
        match self {
            Item::Num(s) => s.span.clone(),
            Item::Str(s) => s.span.clone(),
            Item::Range(s) => s.span.clone(),
            Item::Family(s) => s.span.clone(),
            Item::Other(r) => r.clone(),
        }
    }
}

fn items_span(items: &[Item], empty_at: usize) -> Range<usize> {
    match (items.first(), items.last()) {
        (Some(first), Some(last)) => first.span().start..last.span().end,
        _ => empty_at..empty_at,
    }
}

/// One logical line, split into keyword, argument and value items, all
/// borrowed: from the text, and the items from a buffer the reader keeps
/// for every line. The model takes copies of what it keeps.
#[derive(Debug)]
struct Stmt<'a, 'b> {
    name: &'a str,
    /// Normalized keyword; empty when the line does not start with one.
    key: Cow<'static, str>,
    /// The specification's spelling of the keyword, when the schema's table
    /// has it.
    spelling: Option<&'static str>,
    /// The baud rate in the keyword's name (`MaxTsdr_1.5M`).
    baud: Option<Baud>,
    name_span: Range<usize>,
    /// What stands in `( )` after the keyword.
    arg: Option<(&'b [Item<'a>], Range<usize>)>,
    has_eq: bool,
    items: &'b [Item<'a>],
    span: Range<usize>,
}

impl<'a, 'b> Stmt<'a, 'b> {
    /// The statement of a line's tokens, its items in `buf` (cleared first).
    fn parse(text: &'a str, tokens: &[Token<'a>], buf: &'b mut Vec<Item<'a>>) -> Stmt<'a, 'b> {
        buf.clear();
        let span = tokens[0].span.start..tokens[tokens.len() - 1].span.end;
        let name_len = name_length(text, tokens);
        let name_span = match name_len {
            0 => span.start..span.start,
            n => tokens[0].span.start..tokens[n - 1].span.end,
        };
        let mut rest = &tokens[name_len..];
        let mut arg = None;
        if name_len > 0 && is_punct(rest.first(), b'(') {
            let close = rest.iter().position(|t| t.tok == Tok::Punct(b')'));
            let inner_end = close.unwrap_or(rest.len());
            let end = rest[inner_end - 1].span.end;
            let arg_span = rest[0].span.start..close.map_or(end, |c| rest[c].span.end);
            items(text, &rest[1..inner_end], buf);
            arg = Some(arg_span);
            rest = &rest[close.map_or(rest.len(), |c| c + 1)..];
        }
        let has_eq = name_len > 0 && is_punct(rest.first(), b'=');
        if has_eq {
            rest = &rest[1..];
        }
        let arg_items = buf.len();
        items(text, rest, buf);
        let (arg_items, items) = buf.split_at(arg_items);
        let name = &text[name_span.clone()];
        let keyword = schema::resolve(name);
        Stmt {
            key: keyword.key,
            spelling: keyword.spelling,
            baud: keyword.baud,
            name,
            name_span,
            arg: arg.map(|span| (arg_items, span)),
            has_eq,
            items,
            span,
        }
    }

    /// The keyword as written, for the model: borrowed from the schema when
    /// the file spells it as the specification does (generated files do), so
    /// the model need not copy it.
    fn owned_name(&self) -> Cow<'static, str> {
        match self.spelling {
            Some(spelling) if spelling == self.name => Cow::Borrowed(spelling),
            _ => Cow::Owned(self.name.to_string()),
        }
    }

    /// The index in `Keyword(n)`, if that is what the argument is.
    fn index(&self) -> Option<i64> {
        match self.arg.as_ref()?.0 {
            [Item::Num(n)] => Some(n.value),
            _ => None,
        }
    }

    fn value_span(&self) -> Range<usize> {
        items_span(self.items, self.span.end)
    }
}

fn is_punct(token: Option<&Token>, p: u8) -> bool {
    token.is_some_and(|t| t.tok == Tok::Punct(p))
}

fn is_number_word(text: &str, token: &Token) -> bool {
    token.tok == Tok::Word && parse_number(&text[token.span.clone()]).is_some()
}

/// How many leading tokens form the keyword: one word, or several words
/// before `=` or `(` (`24V Pins = 0`). Zero when the line starts with a
/// number, a string or punctuation.
fn name_length(text: &str, tokens: &[Token]) -> usize {
    if tokens[0].tok != Tok::Word || is_number_word(text, &tokens[0]) {
        return 0;
    }
    let words = tokens
        .iter()
        .take_while(|t| t.tok == Tok::Word && !is_number_word(text, t))
        .count();
    let next = tokens.get(words);
    if words > 1 && !(is_punct(next, b'=') || is_punct(next, b'(')) {
        return 1;
    }
    words
}

/// `-`? number, as (value, tokens used).
fn signed_number(text: &str, tokens: &[Token]) -> Option<(i64, usize)> {
    let number = |t: &Token| {
        (t.tok == Tok::Word)
            .then(|| parse_number(&text[t.span.clone()]))
            .flatten()
    };
    match tokens.first()? {
        t if t.tok == Tok::Punct(b'-') => Some((number(tokens.get(1)?)?.checked_neg()?, 2)),
        t => Some((number(t)?, 1)),
    }
}

/// Splits value tokens into items: strings, numbers (commas only separate),
/// ranges `a-b`, and a family `n@sub@sub` that takes the rest of the line.
/// The items are appended to `out`.
fn items<'a>(text: &'a str, tokens: &[Token<'a>], out: &mut Vec<Item<'a>>) {
    let mut i = 0;
    while i < tokens.len() {
        let token = &tokens[i];
        if let Tok::Str(s) = &token.tok {
            out.push(Item::Str(Spanned::new(s.clone(), token.span.clone())));
            i += 1;
            continue;
        }
        if token.tok == Tok::Punct(b',') {
            i += 1;
            continue;
        }
        let Some((n, used)) = signed_number(text, &tokens[i..]) else {
            out.push(Item::Other(token.span.clone()));
            i += 1;
            continue;
        };
        let start = token.span.start;
        let end = tokens[i + used - 1].span.end;
        i += used;
        if is_punct(tokens.get(i), b'@') {
            let last = tokens[tokens.len() - 1].span.end;
            let subs = text[tokens[i].span.end..last]
                .split('@')
                .map(|s| s.trim().to_string())
                .collect();
            out.push(Item::Family(Spanned::new((n, subs), start..last)));
            break;
        }
        if is_range_dash(tokens, i) {
            if let Some((m, used2)) = signed_number(text, &tokens[i + 1..]) {
                let end = tokens[i + used2].span.end;
                out.push(Item::Range(Spanned::new((n, m), start..end)));
                i += 1 + used2;
                continue;
            }
        }
        out.push(Item::Num(Spanned::new(n, start..end)));
    }
}

/// Whether the `-` at `i` joins the number before it to a range: `0-255`
/// and `0 - 255` do, but in `32767 -32768-32767` (a default, then a range)
/// the first `-` signs the next number.
fn is_range_dash(tokens: &[Token], i: usize) -> bool {
    let (Some(dash), Some(next)) = (tokens.get(i), tokens.get(i + 1)) else {
        return false;
    };
    let after_number = tokens[i - 1].span.end == dash.span.start;
    let spaced_out = next.span.start != dash.span.end;
    dash.tok == Tok::Punct(b'-') && (after_number || spaced_out)
}

/// The value of a setting, or why it cannot be read.
fn value(text: &str, stmt: &Stmt) -> Result<Value, &'static str> {
    Ok(match stmt.items {
        [] if stmt.has_eq => return Err("nothing follows `=`"),
        [] => Value::None,
        [Item::Num(n)] => Value::Number(n.value),
        [Item::Str(s)] => Value::Str(s.value.to_string()),
        [Item::Family(f)] => Value::Family {
            main: f.value.0,
            sub: f.value.1.clone(),
        },
        [Item::Range(r)] => Value::Range(r.value.0, r.value.1),
        items => {
            let numbers: Option<Vec<i64>> = items
                .iter()
                .map(|item| match item {
                    Item::Num(n) => Some(n.value),
                    _ => None,
                })
                .collect();
            match numbers {
                Some(numbers) => Value::List(numbers),
                // Kept as written: the schema rules say what the keyword
                // wanted (a vendor keyword may hold anything, e.g. `1.08`).
                None => Value::Raw(text[items_span(items, 0)].to_string()),
            }
        }
    })
}

fn setting(text: &str, stmt: &Stmt) -> Result<Setting, &'static str> {
    let arg = match &stmt.arg {
        Some(_) => Some(Arg::Index(
            stmt.index()
                .ok_or("the argument in parentheses is not a number")?,
        )),
        None => stmt.baud.map(Arg::Baud),
    };
    Ok(Setting {
        name: stmt.owned_name(),
        key: stmt.key.clone(),
        arg,
        value: value(text, stmt)?,
        span: stmt.span.clone(),
        name_span: stmt.name_span.clone(),
        value_span: match stmt.items.is_empty() {
            true => stmt.name_span.end..stmt.name_span.end,
            false => stmt.value_span(),
        },
    })
}

/// A string item as the model keeps it.
fn owned(s: &Spanned<Cow<'_, str>>) -> Spanned<String> {
    Spanned::new(s.value.to_string(), s.span.clone())
}

/// `Text(n) = "..."`, `Value(n) = "..."`.
fn indexed_text(stmt: &Stmt) -> Option<IndexedText> {
    match (stmt.index(), stmt.items) {
        (Some(index), [Item::Str(text)]) => Some(IndexedText {
            index,
            text: owned(text),
            span: stmt.span.clone(),
        }),
        _ => None,
    }
}

/// What follows a default: nothing, `min-max`, or `a,b,c`.
fn allowed(items: &[Item], empty_at: usize) -> Option<Spanned<Allowed>> {
    let span = items_span(items, empty_at);
    let allowed = match items {
        [] => Allowed::Any,
        [Item::Range(r)] => Allowed::Range(r.value.0, r.value.1),
        items => Allowed::Set(
            items
                .iter()
                .map(|item| match item {
                    Item::Num(n) => Some(n.value),
                    _ => None,
                })
                .collect::<Option<_>>()?,
        ),
    };
    Some(Spanned::new(allowed, span))
}

/// The type line of an `ExtUserPrmData` block: `Unsigned8 0 0-255`,
/// `Bit(3) 1 0-1`, `BitArea(4-7) 0 0,1,2`.
struct TypeLine {
    ty: Spanned<PrmDataType>,
    default: Option<Spanned<i64>>,
    allowed: Spanned<Allowed>,
}

fn prm_type_line(stmt: &Stmt) -> Option<TypeLine> {
    let arg = stmt.arg.as_ref().map(|(items, _)| *items);
    let ty = match (&*stmt.key, arg) {
        ("bit", Some([Item::Num(n)])) => PrmDataType::Bit(u8::try_from(n.value).ok()?),
        ("bitarea", Some([Item::Range(r)])) => {
            PrmDataType::BitArea(u8::try_from(r.value.0).ok()?, u8::try_from(r.value.1).ok()?)
        }
        ("bit" | "bitarea", _) => return None,
        (_, Some(_)) => return None,
        ("unsigned8", None) => PrmDataType::Unsigned8,
        ("unsigned16", None) => PrmDataType::Unsigned16,
        ("unsigned32", None) => PrmDataType::Unsigned32,
        ("signed8", None) => PrmDataType::Signed8,
        ("signed16", None) => PrmDataType::Signed16,
        ("signed32", None) => PrmDataType::Signed32,
        (_, None) => PrmDataType::Other(stmt.name.to_string()),
    };
    let type_end = stmt.arg.as_ref().map_or(stmt.name_span.end, |(_, s)| s.end);
    let ty = Spanned::new(ty, stmt.name_span.start..type_end);
    match stmt.items.split_first() {
        None => Some(TypeLine {
            ty,
            default: None,
            allowed: Spanned::new(Allowed::Any, type_end..type_end),
        }),
        Some((Item::Num(default), rest)) => Some(TypeLine {
            ty,
            default: Some(default.clone()),
            allowed: allowed(rest, default.span.end)?,
        }),
        Some(_) => None,
    }
}

struct Reader<'t> {
    text: &'t str,
    file: GsdFile,
    diags: Vec<Diagnostic>,
    /// The block being read, boxed so that it stays in place while it
    /// takes its lines (it is moved once, when it ends).
    open: Option<Box<Frame<'t>>>,
    /// End of the previous statement: where an unclosed block ends.
    prev_end: usize,
}

pub(crate) fn read(text: &str) -> (GsdFile, Vec<Diagnostic>) {
    let mut reader = Reader {
        text,
        file: GsdFile::default(),
        diags: Vec::new(),
        open: None,
        prev_end: 0,
    };
    let start = match find_marker(text) {
        Some((span, next)) => {
            reader.file.marker = Some(span);
            next
        }
        None => {
            reader.diags.push(
                Diagnostic::error("E200", "no `#Profibus_DP` line")
                    .at(0..0)
                    .label("expected `#Profibus_DP` before the first keyword")
                    .help("a GSD file starts its DP part with a line `#Profibus_DP`; text before it is ignored"),
            );
            0
        }
    };
    reader.diags.extend(control_character(text));
    let mut lexer = Lexer::new(text, start);
    let mut tokens = Vec::new();
    let mut items = Vec::new();
    let mut unterminated = Vec::new();
    while lexer.next_line(&mut tokens, &mut unterminated) {
        for u in unterminated.drain(..) {
            reader.diags.push(
                Diagnostic::error("E202", "string not closed")
                    .at(u.span)
                    .label("this string has no closing `\"` on its line")
                    .help("close the string, or end the line with `\\` to continue it on the next line"),
            );
        }
        if !tokens.is_empty() {
            let stmt = Stmt::parse(reader.text, &tokens, &mut items);
            let end = stmt.span.end;
            reader.statement(stmt);
            reader.prev_end = end;
        }
    }
    if let Some(frame) = reader.open.take() {
        reader.unclosed(*frame);
    }
    (reader.file, reader.diags)
}

/// The first NUL or other control character (tab, CR and LF aside), with
/// how many there are: reported once, since a damaged or binary file has
/// them by the million. A GSD file is text, and tools written in C end a
/// string at a NUL, so such a file means different things to different
/// readers.
fn control_character(text: &str) -> Option<Diagnostic> {
    let is_control = |b: &u8| b.is_ascii_control() && !matches!(b, b'\t' | b'\r' | b'\n');
    // Whole chunks first: a loop without an early exit is vectorised, and
    // nearly every file has no control character at all.
    const CHUNK: usize = 256;
    let chunk = text
        .as_bytes()
        .chunks(CHUNK)
        .position(|c| c.iter().fold(false, |any, b| any | is_control(b)))?;
    let at = chunk * CHUNK
        + text.as_bytes()[chunk * CHUNK..]
            .iter()
            .position(is_control)?;
    let count = text.bytes().filter(is_control).count();
    let name = match text.as_bytes()[at] {
        0 => "a NUL byte".to_string(),
        b => format!("control character 0x{b:02X}"),
    };
    let more = match count {
        1 => String::new(),
        n => format!(" ({} more after it)", n - 1),
    };
    Some(
        Diagnostic::error("E230", format!("{name} in the file{more}"))
            .at(at..at + 1)
            .label("not text")
            .help("a GSD file is text: the file may be damaged or not a GSD file; remove the character"),
    )
}

impl<'t> Reader<'t> {
    fn statement(&mut self, stmt: Stmt<'t, '_>) {
        if let Some(mut frame) = self.open.take() {
            match self.feed(&mut frame, &stmt) {
                Fed::Took => {
                    self.open = Some(frame);
                    return;
                }
                Fed::Closed => return self.finish(*frame, stmt.span.end),
                Fed::Foreign => self.unclosed(*frame),
            }
        }
        self.top(&stmt);
    }

    fn malformed(&mut self, span: Range<usize>, why: &str) {
        self.diags.push(
            Diagnostic::error("E201", format!("cannot read this line: {why}"))
                .at(span)
                .label(why.to_string())
                .help("write `Keyword = value`, `Keyword(n) = value`, or a block keyword on a line of its own"),
        );
    }

    fn top(&mut self, stmt: &Stmt<'t, '_>) {
        if stmt.key.is_empty() {
            self.malformed(stmt.span.clone(), "the line does not start with a keyword");
        } else if is_opener(&stmt.key) {
            self.open = Some(Box::new(self.open_block(stmt)));
        } else if is_end(&stmt.key) {
            self.stray_end(stmt);
        } else if !stmt.has_eq {
            self.malformed(stmt.span.clone(), "expected `=` after the keyword");
        } else if let Some(s) = self.block_setting(stmt) {
            self.file.settings.push(s);
        }
    }
}

/// The opening keyword of a block as written, and where.
#[derive(Debug, Clone)]
struct Header<'a> {
    name: &'a str,
    key: Cow<'static, str>,
    span: Range<usize>,
}

impl<'a> Header<'a> {
    fn of(stmt: &Stmt<'a, '_>) -> Header<'a> {
        Header {
            name: stmt.name,
            key: stmt.key.clone(),
            span: stmt.name_span.clone(),
        }
    }
}

/// What a block has read so far.
enum Body {
    Module {
        module: Module,
        area: Option<Block>,
    },
    Ext(ExtUserPrmData),
    PrmText(PrmText),
    DiagArea(UnitDiagArea),
    DiagType {
        ty: UnitDiagType,
        area: Option<UnitDiagArea>,
    },
    Slots,
    Generic(Block),
}

/// A block being read.
struct Frame<'a> {
    header: Header<'a>,
    body: Body,
}

/// What a block did with a line.
enum Fed {
    Took,
    /// The line ends the block.
    Closed,
    /// The line cannot belong to the block, which was left open.
    Foreign,
}

impl<'t> Reader<'t> {
    fn unclosed(&mut self, frame: Frame<'t>) {
        self.report_unclosed(
            frame.header.name,
            &frame.header.key,
            frame.header.span.clone(),
        );
        self.finish(frame, self.prev_end);
    }

    fn report_unclosed(&mut self, name: &str, key: &str, span: Range<usize>) {
        let end = end_keyword(key);
        self.diags.push(
            Diagnostic::error("E203", format!("`{name}` block is not closed"))
                .at(span)
                .label(format!("no `{end}` after this"))
                .help(format!("add `{end}` after the block's last line")),
        );
    }

    fn stray_end(&mut self, stmt: &Stmt<'t, '_>) {
        self.diags.push(
            Diagnostic::error("E204", format!("`{}` without an open block", stmt.name))
                .at(stmt.name_span.clone())
                .label("no block of this kind is open here")
                .help("remove it, or add the line that opens the block"),
        );
    }

    /// Stores a block that ends at `end`.
    fn finish(&mut self, frame: Frame<'t>, end: usize) {
        match frame.body {
            Body::Module { mut module, area } => {
                if let Some(area) = area {
                    module.data_areas.push(self.close_nested_area(area));
                }
                module.span.end = end;
                self.file.modules.push(module);
            }
            Body::Ext(mut data) => {
                data.span.end = end;
                self.file.ext_user_prm_data.push(data);
            }
            Body::PrmText(mut text) => {
                text.span.end = end;
                self.file.prm_texts.push(text);
            }
            Body::DiagArea(mut area) => {
                area.span.end = end;
                self.file.unit_diag_areas.push(area);
            }
            Body::DiagType { mut ty, area } => {
                if let Some(area) = area {
                    ty.areas.push(self.close_nested_diag_area(area));
                }
                ty.span.end = end;
                self.file.unit_diag_types.push(ty);
            }
            Body::Slots => {}
            Body::Generic(mut block) => {
                block.span.end = end;
                self.file.blocks.push(block);
            }
        }
    }

    /// A data area that its module's end (or a foreign line) left open.
    fn close_nested_area(&mut self, mut area: Block) -> Block {
        let header = &area.header;
        self.report_unclosed(
            &header.name.clone(),
            &header.key.clone(),
            header.name_span.clone(),
        );
        area.span.end = self.prev_end;
        area
    }

    fn close_nested_diag_area(&mut self, mut area: UnitDiagArea) -> UnitDiagArea {
        let keyword = area.keyword.clone();
        self.report_unclosed(
            &keyword.value,
            &schema::key_of(&keyword.value),
            keyword.span,
        );
        area.span.end = self.prev_end;
        area
    }

    fn feed(&mut self, frame: &mut Frame<'t>, stmt: &Stmt<'t, '_>) -> Fed {
        if ends(&stmt.key, &frame.header.key) {
            return Fed::Closed;
        }
        let took = match &mut frame.body {
            Body::Module { module, area } => self.feed_module(module, area, stmt),
            Body::Ext(data) => self.feed_ext(data, stmt),
            Body::PrmText(text) => self.feed_prm_text(text, stmt),
            Body::DiagArea(area) => self.area_value(area, stmt),
            Body::DiagType { ty, area } => self.feed_diag_type(ty, area, stmt),
            Body::Slots => self.feed_slots(stmt),
            Body::Generic(block) => self.feed_generic(block, stmt),
        };
        match took {
            true => Fed::Took,
            false => Fed::Foreign,
        }
    }

    /// A setting for a block's own list; `None` (reported) if unreadable.
    fn block_setting(&mut self, stmt: &Stmt<'t, '_>) -> Option<Setting> {
        match setting(self.text, stmt) {
            Ok(s) => Some(s),
            Err(why) => {
                self.malformed(stmt.span.clone(), why);
                None
            }
        }
    }

    /// A line inside a block that is neither a setting nor the block's own
    /// kind of line.
    fn foreign(stmt: &Stmt) -> bool {
        stmt.key.is_empty() || is_opener(&stmt.key) || is_end(&stmt.key) || !stmt.has_eq
    }

    /// A line of a module, or of the data area open in it. Like every
    /// `feed_*`: false when the line cannot belong to the block.
    fn feed_module(
        &mut self,
        module: &mut Module,
        area: &mut Option<Block>,
        stmt: &Stmt<'t, '_>,
    ) -> bool {
        if let Some(open) = area {
            if ends(&stmt.key, "data_area_beg") {
                open.span.end = stmt.span.end;
                module.data_areas.extend(area.take());
                return true;
            }
            if !Self::foreign(stmt) {
                open.settings.extend(self.block_setting(stmt));
                return true;
            }
        }
        if let Some(open) = area.take() {
            module.data_areas.push(self.close_nested_area(open));
        }
        match &*stmt.key {
            "data_area_beg" => *area = Some(self.generic_block(stmt)),
            "" => self.module_reference(module, stmt),
            key if is_opener(key) => return false,
            key if is_end(key) => self.stray_end(stmt),
            _ if !stmt.has_eq => {
                self.malformed(stmt.span.clone(), "expected `=` after the keyword")
            }
            _ => {
                if let Some(s) = self.block_setting(stmt) {
                    if s.key == "module_reference" {
                        if let Value::Number(n) = s.value {
                            module.reference = Some(Spanned::new(n, s.value_span.clone()));
                        }
                    }
                    module.settings.push(s);
                }
            }
        }
        true
    }

    /// The bare number on its own line inside a module.
    fn module_reference(&mut self, module: &mut Module, stmt: &Stmt<'t, '_>) {
        match (stmt.items, &module.reference) {
            ([Item::Num(n)], None) => module.reference = Some(n.clone()),
            ([Item::Num(_)], Some(_)) => {
                self.malformed(stmt.span.clone(), "a module has one reference number")
            }
            _ => self.malformed(stmt.span.clone(), "the line does not start with a keyword"),
        }
    }

    fn feed_ext(&mut self, data: &mut ExtUserPrmData, stmt: &Stmt<'t, '_>) -> bool {
        match &*stmt.key {
            "prm_text_ref" | "changeable" | "visible" if stmt.has_eq => {
                if let Some(s) = self.block_setting(stmt) {
                    let number = s.value.as_number();
                    match &*s.key {
                        "prm_text_ref" => {
                            data.prm_text_ref =
                                number.map(|n| Spanned::new(n, s.value_span.clone()))
                        }
                        "changeable" => data.changeable = number.map(|n| n != 0),
                        _ => data.visible = number.map(|n| n != 0),
                    }
                    data.settings.push(s);
                }
            }
            key if key.is_empty() || stmt.has_eq || is_opener(key) || is_end(key) => return false,
            _ if data.data_type.is_some() => {
                self.malformed(stmt.span.clone(), "a parameter has one type line")
            }
            _ => match prm_type_line(stmt) {
                Some(line) => {
                    data.data_type = Some(line.ty);
                    data.default = line.default;
                    data.allowed = line.allowed;
                }
                None => self.malformed(
                    stmt.span.clone(),
                    "expected `Type default [min-max | a,b,c]`, e.g. `Unsigned8 0 0-255` or `Bit(3) 0 0-1`",
                ),
            },
        }
        true
    }

    fn feed_prm_text(&mut self, text: &mut PrmText, stmt: &Stmt<'t, '_>) -> bool {
        if stmt.key != "text" {
            return false;
        }
        match indexed_text(stmt) {
            Some(t) => text.texts.push(t),
            None => self.malformed(stmt.span.clone(), "expected `Text(value) = \"text\"`"),
        }
        true
    }

    /// `Value(n) = "text"` (or `X_Value`) into an area; false if the line is
    /// something else.
    fn area_value(&mut self, area: &mut UnitDiagArea, stmt: &Stmt<'t, '_>) -> bool {
        if stmt.key != "value" && stmt.key != "x_value" {
            return false;
        }
        match indexed_text(stmt) {
            Some(t) => area.values.push(t),
            None => self.malformed(stmt.span.clone(), "expected `Value(n) = \"text\"`"),
        }
        true
    }

    /// A line of a `UnitDiagType`, or of the area open in it.
    fn feed_diag_type(
        &mut self,
        ty: &mut UnitDiagType,
        area: &mut Option<UnitDiagArea>,
        stmt: &Stmt<'t, '_>,
    ) -> bool {
        if let Some(open) = area {
            if ends(&stmt.key, &schema::key_of(&open.keyword.value)) {
                open.span.end = stmt.span.end;
                ty.areas.extend(area.take());
                return true;
            }
            if self.area_value(open, stmt) {
                return true;
            }
        }
        if let Some(open) = area.take() {
            ty.areas.push(self.close_nested_diag_area(open));
        }
        match &*stmt.key {
            "unit_diag_area" | "x_unit_diag_area" => *area = Some(self.diag_area(stmt)),
            _ if Self::foreign(stmt) => return false,
            _ => ty.settings.extend(self.block_setting(stmt)),
        }
        true
    }

    fn feed_slots(&mut self, stmt: &Stmt<'t, '_>) -> bool {
        if stmt.key != "slot" {
            return false;
        }
        match slot(stmt) {
            Some(slot) => self.file.slots.push(slot),
            None => self.malformed(
                stmt.span.clone(),
                "expected `Slot(n) = \"name\" default min-max` or `... default a,b,c`",
            ),
        }
        true
    }

    fn feed_generic(&mut self, block: &mut Block, stmt: &Stmt<'t, '_>) -> bool {
        if Self::foreign(stmt) {
            return false;
        }
        block.settings.extend(self.block_setting(stmt));
        true
    }

    fn open_block(&mut self, stmt: &Stmt<'t, '_>) -> Frame<'t> {
        let body = match &*stmt.key {
            "module" => Body::Module {
                module: self.module_header(stmt),
                area: None,
            },
            "extuserprmdata" => Body::Ext(self.ext_header(stmt)),
            "prmtext" => Body::PrmText(PrmText {
                id: self.id_header(stmt),
                texts: Vec::new(),
                span: stmt.span.clone(),
            }),
            "unitdiagtype" => Body::DiagType {
                ty: UnitDiagType {
                    id: self.id_header(stmt),
                    settings: Vec::new(),
                    areas: Vec::new(),
                    span: stmt.span.clone(),
                },
                area: None,
            },
            "unit_diag_area" | "x_unit_diag_area" => Body::DiagArea(self.diag_area(stmt)),
            "slotdefinition" => Body::Slots,
            _ => Body::Generic(self.generic_block(stmt)),
        };
        Frame {
            header: Header::of(stmt),
            body,
        }
    }

    /// A block whose header value is not checked here (the schema rules see
    /// it as a setting).
    fn generic_block(&mut self, stmt: &Stmt<'t, '_>) -> Block {
        let header = self.block_setting(stmt).unwrap_or_else(|| Setting {
            name: stmt.owned_name(),
            key: stmt.key.clone(),
            arg: None,
            value: Value::None,
            span: stmt.span.clone(),
            name_span: stmt.name_span.clone(),
            value_span: stmt.value_span(),
        });
        Block {
            header,
            settings: Vec::new(),
            span: stmt.span.clone(),
        }
    }

    /// `Module = "name" 0x.., 0x..`.
    fn module_header(&mut self, stmt: &Stmt<'t, '_>) -> Module {
        let (name, rest) = match stmt.items.split_first() {
            Some((Item::Str(name), rest)) => (owned(name), rest),
            _ => {
                self.malformed(stmt.span.clone(), "a module needs a name in double quotes");
                (Spanned::new(String::new(), stmt.value_span()), stmt.items)
            }
        };
        let mut bytes = Vec::new();
        for item in rest {
            match item {
                Item::Num(n) => match u8::try_from(n.value) {
                    Ok(b) => bytes.push(b),
                    Err(_) => self.diags.push(
                        Diagnostic::error(
                            "E215",
                            format!("config identifier {} is not a byte", n.value),
                        )
                        .at(n.span.clone())
                        .label("must be 0x00..0xFF")
                        .help("each config identifier is one byte"),
                    ),
                },
                other => self.malformed(other.span(), "config identifiers are numbers"),
            }
        }
        Module {
            config: Spanned::new(bytes, items_span(rest, name.span.end)),
            name,
            reference: None,
            settings: Vec::new(),
            data_areas: Vec::new(),
            span: stmt.span.clone(),
        }
    }

    /// `ExtUserPrmData = id "name"`.
    fn ext_header(&mut self, stmt: &Stmt<'t, '_>) -> ExtUserPrmData {
        let (id, name) = match stmt.items {
            [Item::Num(id), Item::Str(name)] => (id.clone(), owned(name)),
            _ => {
                self.malformed(stmt.span.clone(), "expected `ExtUserPrmData = id \"name\"`");
                let at = stmt.value_span();
                (Spanned::new(0, at.clone()), Spanned::new(String::new(), at))
            }
        };
        ExtUserPrmData {
            allowed: Spanned::new(Allowed::Any, name.span.clone()),
            id,
            name,
            data_type: None,
            default: None,
            prm_text_ref: None,
            changeable: None,
            visible: None,
            settings: Vec::new(),
            span: stmt.span.clone(),
        }
    }

    /// `PrmText = id`, `UnitDiagType = id`.
    fn id_header(&mut self, stmt: &Stmt<'t, '_>) -> Spanned<i64> {
        match stmt.items {
            [Item::Num(id)] => id.clone(),
            _ => {
                self.malformed(stmt.span.clone(), "expected a number after `=`");
                Spanned::new(0, stmt.value_span())
            }
        }
    }

    /// `Unit_Diag_Area = first-last`.
    fn diag_area(&mut self, stmt: &Stmt<'t, '_>) -> UnitDiagArea {
        let (first, last) = match stmt.items {
            [Item::Range(r)] => r.value,
            _ => {
                self.malformed(stmt.span.clone(), "expected `first-last` bit numbers");
                (0, 0)
            }
        };
        UnitDiagArea {
            keyword: Spanned::new(stmt.name.to_string(), stmt.name_span.clone()),
            first,
            last,
            range_span: stmt.value_span(),
            values: Vec::new(),
            span: stmt.span.clone(),
        }
    }
}

/// `Slot(n) = "name" default allowed`.
fn slot(stmt: &Stmt) -> Option<Slot> {
    let number = stmt.index()?;
    let [Item::Str(name), Item::Num(default), rest @ ..] = stmt.items else {
        return None;
    };
    Some(Slot {
        number,
        name: owned(name),
        default: default.clone(),
        allowed: allowed(rest, default.span.end)?,
        span: stmt.span.clone(),
    })
}

#[cfg(test)]
mod tests {
    use super::parse_number;

    #[test]
    fn numbers_are_decimal_or_hex() {
        assert_eq!(parse_number("0x1A"), Some(26));
        assert_eq!(parse_number("0X1a"), Some(26));
        assert_eq!(parse_number("007"), Some(7));
        assert_eq!(parse_number("9223372036854775807"), Some(i64::MAX));
        for not_a_number in [
            "",
            "0x",
            "12a",
            "0xG",
            "-1",
            "+1",
            "1.5",
            "9223372036854775808",
        ] {
            assert_eq!(parse_number(not_a_number), None, "{not_a_number}");
        }
    }
}
