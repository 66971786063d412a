//! Diagrams as SVG, laid out in code: every text sits in a rectangle of
//! its own (a drawn box, or an undrawn slot for a label), rectangles never
//! overlap and all lie inside the drawing. Text widths are estimated on the
//! wide side (DejaVu Sans' metrics, wider than Arial's), so text fits its
//! rectangle in any common sans-serif font; the browser test measures it.

use std::fmt::Write;

/// A rectangle in user units (pixels at scale 1).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Rect {
    pub x: u32,
    pub y: u32,
    pub w: u32,
    pub h: u32,
}

impl Rect {
    pub fn right(self) -> u32 {
        self.x + self.w
    }

    pub fn bottom(self) -> u32 {
        self.y + self.h
    }

    /// Whether the two share any area; touching edges do not.
    pub fn overlaps(self, other: Rect) -> bool {
        self.x < other.right()
            && other.x < self.right()
            && self.y < other.bottom()
            && other.y < self.bottom()
    }
}

/// How a rectangle is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Style {
    /// A word of the PKW channel.
    Pkw,
    /// A PZD word.
    Pzd,
    /// A control or status word, or a field of its bits.
    Word,
    /// Bits no field uses.
    Reserved,
    /// Not drawn: the place of a label.
    Slot,
}

impl Style {
    fn class(self) -> &'static str {
        match self {
            Style::Pkw => "box pkw",
            Style::Pzd => "box pzd",
            Style::Word => "box field",
            Style::Reserved => "box reserved",
            Style::Slot => "slot",
        }
    }

    /// Fill and stroke.
    fn paint(self) -> (&'static str, &'static str) {
        match self {
            Style::Pkw => ("#dbe8f5", "#2b5b87"),
            Style::Pzd => ("#e2f0dd", "#3a7535"),
            Style::Word => ("#fbefd3", "#9a6a16"),
            Style::Reserved => ("#f1f1f1", "#9a9a9a"),
            Style::Slot => ("none", "none"),
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Weight {
    Normal,
    Bold,
    /// Smaller and grey: byte offsets.
    Small,
}

impl Weight {
    fn size(self) -> u32 {
        match self {
            Weight::Normal | Weight::Bold => 12,
            Weight::Small => 10,
        }
    }
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Line {
    pub text: String,
    pub weight: Weight,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Align {
    Start,
    Middle,
}

/// A rectangle and the lines of text in it, centred vertically.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Item {
    pub rect: Rect,
    pub style: Style,
    pub align: Align,
    pub lines: Vec<Line>,
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Svg {
    /// What it draws, as its class: `overview`, `words` or `bits`.
    pub kind: &'static str,
    pub width: u32,
    pub height: u32,
    /// Said by screen readers; also the tooltip.
    pub title: String,
    pub items: Vec<Item>,
}

/// Line height for a font size, with room for CJK glyphs.
pub(crate) fn line_height(weight: Weight) -> u32 {
    weight.size() + 4
}

/// Padding inside a box, each side.
pub(crate) const PAD: u32 = 4;

/// The height a box needs for `lines`.
pub(crate) fn height_for(lines: &[Line]) -> u32 {
    lines.iter().map(|l| line_height(l.weight)).sum::<u32>() + 2 * PAD
}

/// Estimated width of `text` in pixels, on the wide side.
pub(crate) fn text_width(text: &str, weight: Weight) -> u32 {
    let em: f64 = text.chars().map(char_width).sum();
    pixels(em, weight)
}

/// The pixels of a width of `em` in `weight`'s font.
fn pixels(em: f64, weight: Weight) -> u32 {
    let bold = if weight == Weight::Bold { 1.1 } else { 1.0 };
    (em * f64::from(weight.size()) * bold).ceil() as u32
}

/// Advance widths in em, rounded up from DejaVu Sans (the widest of the
/// common sans-serif fonts); a CJK or other wide character is a full em.
fn char_width(c: char) -> f64 {
    match c {
        ' ' => 0.32,
        'i' | 'j' | 'l' | '.' | ',' | ':' | ';' | '\'' | '|' | '!' => 0.3,
        'f' | 't' | 'r' | 'I' | 'J' | '(' | ')' | '[' | ']' | '-' => 0.42,
        'm' | 'M' => 0.98,
        'w' | 'W' => 1.0,
        '%' => 0.96,
        'a'..='z' => 0.64,
        'A'..='Z' => 0.78,
        '0'..='9' => 0.64,
        '→' | '>' | '<' | '=' | '+' | '~' | '_' | '/' | '&' | '#' => 0.84,
        c if c.is_ascii() => 0.7,
        '…' | '–' | '—' => 1.0,
        _ => 1.05,
    }
}

/// `text` broken into at most `max_lines` lines of at most `width` pixels:
/// at blanks, and between any two CJK characters; a word too long for a
/// line is broken where it must be. What does not fit ends in `…`.
pub(crate) fn wrap(text: &str, width: u32, weight: Weight, max_lines: usize) -> Vec<String> {
    wrap_measured(text, width, weight, max_lines, &mut char_width)
}

/// [`wrap`] with each character's width in em from `measure`. Linear in
/// the text: every character is measured at most once for its line and
/// once more for the ellipsis, and nothing after the last line shown is
/// measured at all; a line's width is the running sum of its characters'
/// widths, added in the order [`text_width`] adds them, so it is the same
/// number.
fn wrap_measured(
    text: &str,
    width: u32,
    weight: Weight,
    max_lines: usize,
    measure: &mut dyn FnMut(char) -> f64,
) -> Vec<String> {
    let fits = |em: f64| pixels(em, weight) <= width;
    let mut lines: Vec<String> = Vec::new();
    let mut line = Filling::default();
    for piece in pieces(text) {
        if lines.len() > max_lines {
            break;
        }
        let piece = if line.text.is_empty() {
            piece.trim_start()
        } else {
            piece
        };
        if let Some(em) = line.em_with(piece, measure, fits) {
            line.text.push_str(piece);
            line.em = em;
            continue;
        }
        if !line.text.is_empty() {
            lines.push(std::mem::take(&mut line).text);
        }
        // The piece from the start of a line, cut where it must be: each
        // line as many characters as fit, at least one.
        for c in piece.trim_start().chars() {
            let w = measure(c);
            if !fits(line.em + w) && !line.text.is_empty() {
                lines.push(std::mem::take(&mut line).text);
                if lines.len() > max_lines {
                    break;
                }
            }
            line.text.push(c);
            line.em += w;
        }
    }
    if !line.text.is_empty() {
        lines.push(line.text);
    }
    if lines.len() > max_lines {
        lines.truncate(max_lines);
        let last = lines.last_mut().expect("max_lines > 0");
        let end = longest_prefix_before_ellipsis(last, measure, fits);
        last.truncate(end);
        last.push('…');
    }
    lines
}

/// A line being filled, and its width in em.
#[derive(Default)]
struct Filling {
    text: String,
    em: f64,
}

impl Filling {
    /// The line's width with `piece` after it, if that fits; the piece is
    /// measured only as far as it fits.
    fn em_with(
        &self,
        piece: &str,
        measure: &mut dyn FnMut(char) -> f64,
        fits: impl Fn(f64) -> bool,
    ) -> Option<f64> {
        let mut em = self.em;
        for c in piece.chars() {
            em += measure(c);
            if !fits(em) {
                return None;
            }
        }
        Some(em)
    }
}

/// Bytes of the longest prefix of `line` that fits with `…` after it
/// (none, if not even the ellipsis alone fits).
fn longest_prefix_before_ellipsis(
    line: &str,
    measure: &mut dyn FnMut(char) -> f64,
    fits: impl Fn(f64) -> bool,
) -> usize {
    let ellipsis = measure('…');
    let mut em = 0.0;
    let mut end = 0;
    for (i, c) in line.char_indices() {
        em += measure(c);
        if !fits(em + ellipsis) {
            break;
        }
        end = i + c.len_utf8();
    }
    end
}

/// Words with the blank before them, and CJK characters one by one.
fn pieces(text: &str) -> impl Iterator<Item = &str> {
    let mut rest = text;
    std::iter::from_fn(move || {
        let mut chars = rest.char_indices();
        let (_, first) = chars.next()?;
        let end = if is_wide(first) {
            first.len_utf8()
        } else {
            chars
                .find(|&(_, c)| c == ' ' || is_wide(c))
                .map_or(rest.len(), |(i, _)| i)
        };
        let (piece, after) = rest.split_at(end);
        rest = after;
        Some(piece)
    })
}

/// A character that a line may break before and after: CJK and the other
/// characters of a full em.
fn is_wide(c: char) -> bool {
    !c.is_ascii() && char_width(c) >= 1.0
}

impl Svg {
    /// What every diagram promises: each rectangle inside the drawing, no
    /// two overlapping, each text's estimated width within its rectangle.
    pub fn layout_faults(&self) -> Vec<String> {
        let mut faults = Vec::new();
        for (i, item) in self.items.iter().enumerate() {
            let r = item.rect;
            if r.right() > self.width || r.bottom() > self.height || r.w == 0 || r.h == 0 {
                faults.push(format!("{r:?} is outside {}x{}", self.width, self.height));
            }
            if height_for(&item.lines) > r.h {
                faults.push(format!("{r:?} is too low for {:?}", item.lines));
            }
            for l in &item.lines {
                if text_width(&l.text, l.weight) + 2 * PAD > r.w {
                    faults.push(format!("{:?} is wider than {r:?}", l.text));
                }
            }
            for other in &self.items[i + 1..] {
                if r.overlaps(other.rect) {
                    faults.push(format!("{r:?} overlaps {:?}", other.rect));
                }
            }
        }
        faults
    }

    pub fn render(&self) -> String {
        debug_assert_eq!(self.layout_faults(), Vec::<String>::new(), "{}", self.title);
        let mut out = String::new();
        let _ = writeln!(
            out,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"{kind}\" viewBox=\"0 0 {w} {h}\" width=\"{w}\" height=\"{h}\" \
             font-family=\"'Liberation Sans', Arial, 'DejaVu Sans', 'WenQuanYi Micro Hei', 'Noto Sans CJK SC', sans-serif\" \
             role=\"img\">",
            kind = self.kind,
            w = self.width,
            h = self.height
        );
        let _ = writeln!(out, "<title>{}</title>", escape(&self.title));
        for item in &self.items {
            render_item(&mut out, item);
        }
        out.push_str("</svg>");
        out
    }
}

fn render_item(out: &mut String, item: &Item) {
    let Rect { x, y, w, h } = item.rect;
    let (fill, stroke) = item.style.paint();
    let _ = write!(
        out,
        "<g class=\"{}\"><rect x=\"{x}\" y=\"{y}\" width=\"{w}\" height=\"{h}\" rx=\"2\" fill=\"{fill}\" stroke=\"{stroke}\"/>",
        item.style.class()
    );
    let (anchor, text_x) = match item.align {
        Align::Start => ("start", x + PAD),
        Align::Middle => ("middle", x + w / 2),
    };
    // The lines' block is centred in the rectangle; each baseline sits a
    // quarter of the font size above the bottom of its line.
    let block: u32 = item.lines.iter().map(|l| line_height(l.weight)).sum();
    let mut top = y + (h - block) / 2;
    for line in &item.lines {
        let size = line.weight.size();
        top += line_height(line.weight);
        let baseline = top - 2 - size / 4;
        let extra = match line.weight {
            Weight::Bold => " font-weight=\"bold\"",
            Weight::Small => " fill=\"#555555\"",
            Weight::Normal => "",
        };
        let _ = write!(
            out,
            "<text x=\"{text_x}\" y=\"{baseline}\" font-size=\"{size}\" text-anchor=\"{anchor}\"{extra}>{}</text>",
            escape(&line.text)
        );
    }
    out.push_str("</g>\n");
}

/// Text for HTML and SVG: the five characters that could end it.
pub(crate) fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrapping_keeps_every_line_within_the_width() {
        let text = "Drive torque upper limit reference";
        let lines = wrap(text, 100, Weight::Normal, 5);
        assert!(lines.len() > 1, "{lines:?}");
        assert!(lines.iter().all(|l| text_width(l, Weight::Normal) <= 100));
        assert_eq!(lines.join(" "), text);
    }

    #[test]
    fn chinese_breaks_between_characters_and_long_words_are_cut() {
        let lines = wrap("电动转矩上限给定", 40, Weight::Normal, 9);
        assert_eq!(lines.concat(), "电动转矩上限给定");
        assert!(lines.iter().all(|l| text_width(l, Weight::Normal) <= 40));
        let lines = wrap("ABCDEFGHIJKLMNOP", 30, Weight::Normal, 9);
        assert_eq!(lines.concat(), "ABCDEFGHIJKLMNOP");
        assert!(lines.iter().all(|l| text_width(l, Weight::Normal) <= 30));
    }

    #[test]
    fn what_does_not_fit_the_lines_ends_in_an_ellipsis() {
        let lines = wrap("one two three four five six", 40, Weight::Normal, 2);
        assert_eq!(lines.len(), 2);
        assert!(lines[1].ends_with('…'), "{lines:?}");
        assert!(lines.iter().all(|l| text_width(l, Weight::Normal) <= 40));
    }

    /// Counts the characters `wrap_measured` measures.
    fn measured(text: &str, max_lines: usize) -> usize {
        let mut count = 0;
        let mut measure = |c| {
            count += 1;
            char_width(c)
        };
        let lines = wrap_measured(text, 100, Weight::Normal, max_lines, &mut measure);
        assert!(lines.len() <= max_lines, "{lines:?}");
        count
    }

    /// The datasheet wraps every name a description gives, and a name can
    /// be a megabyte: measuring the rest of a word again for every line
    /// cut from it took minutes. Each character is measured at most twice
    /// (once trying its word on a line, once cutting the word), and nothing
    /// after the last line shown at all.
    #[test]
    fn wrapping_measures_each_character_at_most_twice() {
        for n in [10_000, 40_000] {
            let word = "x".repeat(n);
            let words = "ab ".repeat(n / 3);
            let chinese = "电动转矩上限给定".repeat(n / 8);
            let mixed = format!("{word} {chinese} {words}");
            for text in [&word, &words, &chinese, &mixed] {
                let chars = text.chars().count();
                assert!(measured(text, usize::MAX) <= 2 * chars + 1, "{n}");
                // Three lines of 100 pixels are at most 3 * 100 / 3 = 100
                // characters of the narrowest kind, each measured twice, and
                // the ellipsis.
                assert!(measured(text, 3) <= 2 * (100 + 100 / 3) + 1, "{n}");
            }
        }
    }

    /// What wrapping is, written as simply as it can be (and measuring the
    /// same text again and again): the lines `wrap` gives are these.
    fn wrap_by_definition(text: &str, width: u32, weight: Weight, max_lines: usize) -> Vec<String> {
        let fits = |s: &str| text_width(s, weight) <= width;
        let mut lines: Vec<String> = Vec::new();
        let mut current = String::new();
        for piece in pieces(text) {
            let candidate = if current.is_empty() {
                piece.trim_start().to_string()
            } else {
                format!("{current}{piece}")
            };
            if fits(&candidate) {
                current = candidate;
                continue;
            }
            if !current.is_empty() {
                lines.push(std::mem::take(&mut current));
            }
            current = piece.trim_start().to_string();
            while !fits(&current) {
                // The longest prefix that fits, at least one character.
                let cut = (1..=current.chars().count())
                    .map(|n| current.chars().take(n).map(char::len_utf8).sum::<usize>())
                    .take_while(|&end| {
                        end == current.chars().next().unwrap().len_utf8() || fits(&current[..end])
                    })
                    .last()
                    .unwrap();
                lines.push(current[..cut].to_string());
                current = current[cut..].to_string();
            }
        }
        if !current.is_empty() {
            lines.push(current);
        }
        if lines.len() > max_lines {
            lines.truncate(max_lines);
            let last = lines.last_mut().unwrap();
            while !last.is_empty() && !fits(&format!("{last}…")) {
                last.pop();
            }
            last.push('…');
        }
        lines
    }

    proptest::proptest! {
        #[test]
        fn wrapping_is_what_its_definition_says(
            text in "([a-zW ]{0,12}|电动|转|…){0,12}",
            width in 1u32..160,
            bold in proptest::bool::ANY,
            max_lines in 1usize..6,
        ) {
            let weight = if bold { Weight::Bold } else { Weight::Normal };
            proptest::prop_assert_eq!(
                wrap(&text, width, weight, max_lines),
                wrap_by_definition(&text, width, weight, max_lines)
            );
        }
    }

    #[test]
    fn touching_rectangles_do_not_overlap() {
        let a = Rect {
            x: 0,
            y: 0,
            w: 10,
            h: 10,
        };
        assert!(!a.overlaps(Rect { x: 10, ..a }));
        assert!(a.overlaps(Rect { x: 9, y: 9, ..a }));
    }

    #[test]
    fn text_is_escaped() {
        assert_eq!(
            escape("PZD1 master->slave & <x>"),
            "PZD1 master-&gt;slave &amp; &lt;x&gt;"
        );
    }
}
