//! The datasheet as a document: headings, paragraphs, tables and figures in
//! one language, and its two renderings, HTML and Markdown. The sections
//! build the document once; both files show the same content.

use super::svg::{escape, Svg};
use super::Lang;
use crate::i18n::sheet as w;
use std::fmt::Write;

pub(crate) struct Doc {
    pub lang: Lang,
    pub title: String,
    pub blocks: Vec<Block>,
}

pub(crate) enum Block {
    /// A section heading (level 2) or a sub-heading (level 3); `id` is the
    /// anchor, unique within the language.
    Heading {
        level: u8,
        id: &'static str,
        text: String,
    },
    Para(Cell),
    Table(Table),
    Figure(Figure),
}

pub(crate) struct Table {
    pub caption: String,
    pub head: Vec<String>,
    pub rows: Vec<Vec<Cell>>,
}

/// A diagram; the Markdown leaves it out, its table carries the same facts.
pub(crate) struct Figure {
    pub caption: String,
    pub svg: Svg,
}

/// Text with code and marked runs.
pub(crate) type Cell = Vec<Run>;

#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum Run {
    Text(String),
    /// Bytes, hex numbers, file names: monospace.
    Code(String),
    /// A placeholder or a value gsdc or the description chose: to be
    /// checked before shipping.
    Mark(String),
}

pub(crate) fn text(text: impl Into<String>) -> Cell {
    vec![Run::Text(text.into())]
}

pub(crate) fn code(text: impl Into<String>) -> Cell {
    vec![Run::Code(text.into())]
}

/// Builds a document in one language.
pub(crate) struct Builder {
    doc: Doc,
}

impl Builder {
    pub fn new(lang: Lang, title: String) -> Self {
        Builder {
            doc: Doc {
                lang,
                title,
                blocks: Vec::new(),
            },
        }
    }

    pub fn section(&mut self, id: &'static str, text: impl Into<String>) {
        self.heading(2, id, text);
    }

    /// A section whose first paragraph says what it holds.
    pub fn section_with_intro(
        &mut self,
        id: &'static str,
        title: impl Into<String>,
        intro: impl Into<String>,
    ) {
        self.section(id, title);
        self.para(text(intro));
    }

    pub fn subsection(&mut self, id: &'static str, text: impl Into<String>) {
        self.heading(3, id, text);
    }

    fn heading(&mut self, level: u8, id: &'static str, text: impl Into<String>) {
        self.doc.blocks.push(Block::Heading {
            level,
            id,
            text: text.into(),
        });
    }

    pub fn para(&mut self, cell: Cell) {
        self.doc.blocks.push(Block::Para(cell));
    }

    pub fn table(&mut self, caption: impl Into<String>, head: &[&str], rows: Vec<Vec<Cell>>) {
        debug_assert!(rows.iter().all(|r| r.len() == head.len()));
        self.doc.blocks.push(Block::Table(Table {
            caption: caption.into(),
            head: head.iter().map(|h| h.to_string()).collect(),
            rows,
        }));
    }

    pub fn figure(&mut self, caption: impl Into<String>, svg: Svg) {
        self.doc.blocks.push(Block::Figure(Figure {
            caption: caption.into(),
            svg,
        }));
    }

    pub fn finish(self) -> Doc {
        self.doc
    }
}

// ---------------------------------------------------------------------------
// HTML

const CSS: &str = include_str!("../../../templates/datasheet.css");

/// One self-contained page: inline CSS and SVG, no script. With several
/// languages, radio buttons and CSS show one language at a time (the first
/// by default); printing prints the language shown.
pub(crate) fn html(docs: &[Doc], generator: &str, header: &str) -> String {
    let first = &docs[0];
    let mut out = String::new();
    let _ = write!(
        out,
        "<!DOCTYPE html>\n{header}<html lang=\"{}\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <meta name=\"generator\" content=\"{}\">\n<title>{}</title>\n<style>\n{CSS}",
        first.lang.code(),
        escape(generator),
        escape(&first.title)
    );
    if docs.len() > 1 {
        out.push_str(&switch_css(docs));
    }
    out.push_str("</style>\n</head>\n<body>\n");
    if docs.len() > 1 {
        language_switch(&mut out, docs);
    }
    for doc in docs {
        html_doc(&mut out, doc, docs.len() > 1);
    }
    out.push_str("</body>\n</html>\n");
    out
}

/// Hides every language but the checked one's, and marks its label.
fn switch_css(docs: &[Doc]) -> String {
    let mut css = String::from("main.lang { display: none; }\n");
    for doc in docs {
        let code = doc.lang.code();
        let _ = writeln!(
            css,
            "#lang-{code}:checked ~ main.lang-{code} {{ display: block; }}\n\
             #lang-{code}:checked ~ nav.languages label[for=\"lang-{code}\"] {{ background: #1f3f5f; color: #ffffff; }}\n\
             #lang-{code}:focus-visible ~ nav.languages label[for=\"lang-{code}\"] {{ outline: 2px solid #1f3f5f; }}"
        );
    }
    css
}

fn language_switch(out: &mut String, docs: &[Doc]) {
    for (i, doc) in docs.iter().enumerate() {
        let checked = if i == 0 { " checked" } else { "" };
        let _ = writeln!(
            out,
            "<input type=\"radio\" name=\"language\" class=\"language\" id=\"lang-{}\"{checked}>",
            doc.lang.code()
        );
    }
    out.push_str("<nav class=\"languages\">");
    for doc in docs {
        let _ = write!(
            out,
            "<label for=\"lang-{}\" lang=\"{}\">{}</label>",
            doc.lang.code(),
            doc.lang.code(),
            doc.lang.name()
        );
    }
    out.push_str("</nav>\n");
}

fn html_doc(out: &mut String, doc: &Doc, switched: bool) {
    let code = doc.lang.code();
    let class = if switched {
        format!(" class=\"lang lang-{code}\"")
    } else {
        String::new()
    };
    let _ = writeln!(out, "<main lang=\"{code}\"{class}>");
    let _ = writeln!(out, "<h1>{}</h1>", escape(&doc.title));
    contents(out, doc);
    let mut figures = 0;
    let mut tables = 0;
    for block in &doc.blocks {
        match block {
            Block::Heading { level, id, text } => {
                let _ = writeln!(
                    out,
                    "<h{level} id=\"{code}-{id}\">{}</h{level}>",
                    escape(text)
                );
            }
            Block::Para(cell) => {
                let _ = writeln!(out, "<p>{}</p>", html_cell(cell));
            }
            Block::Table(table) => {
                tables += 1;
                html_table(out, table, &w::table_label(doc.lang, tables));
            }
            Block::Figure(figure) => {
                figures += 1;
                let _ = writeln!(
                    out,
                    "<figure>\n{}\n<figcaption>{} {}</figcaption>\n</figure>",
                    figure.svg.render(),
                    escape(&w::figure_label(doc.lang, figures)),
                    escape(&figure.caption)
                );
            }
        }
    }
    out.push_str("</main>\n");
}

/// The sections, linked.
fn contents(out: &mut String, doc: &Doc) {
    let code = doc.lang.code();
    out.push_str("<nav class=\"contents\"><ol>");
    for block in &doc.blocks {
        if let Block::Heading { level: 2, id, text } = block {
            let _ = write!(
                out,
                "<li><a href=\"#{code}-{id}\">{}</a></li>",
                escape(text)
            );
        }
    }
    out.push_str("</ol></nav>\n");
}

fn html_table(out: &mut String, table: &Table, label: &str) {
    let _ = write!(
        out,
        "<table>\n<caption>{} {}</caption>\n<thead><tr>",
        escape(label),
        escape(&table.caption)
    );
    for head in &table.head {
        let _ = write!(out, "<th>{}</th>", escape(head));
    }
    out.push_str("</tr></thead>\n<tbody>\n");
    for row in &table.rows {
        out.push_str("<tr>");
        for cell in row {
            let _ = write!(out, "<td>{}</td>", html_cell(cell));
        }
        out.push_str("</tr>\n");
    }
    out.push_str("</tbody>\n</table>\n");
}

fn html_cell(cell: &Cell) -> String {
    cell.iter()
        .map(|run| match run {
            // A diagnosis text may break lines: the cell shows the breaks.
            Run::Text(t) => escape(t).replace('\n', "<br>"),
            Run::Code(t) => format!("<code>{}</code>", escape(t)),
            Run::Mark(t) => format!("<strong class=\"mark\">{}</strong>", escape(t)),
        })
        .collect()
}

// ---------------------------------------------------------------------------
// Markdown

/// GitHub-flavoured Markdown: one part per language, tables with their
/// captions; the figures are left out (their tables say the same).
pub(crate) fn markdown(docs: &[Doc], header: &str) -> String {
    let mut out = header.to_string();
    for (i, doc) in docs.iter().enumerate() {
        if i > 0 {
            out.push_str("\n---\n");
        }
        markdown_doc(&mut out, doc);
    }
    out
}

fn markdown_doc(out: &mut String, doc: &Doc) {
    let _ = writeln!(out, "\n# {}", md_text(&doc.title));
    let mut tables = 0;
    for block in &doc.blocks {
        match block {
            Block::Heading { level, text, .. } => {
                let _ = writeln!(
                    out,
                    "\n{} {}",
                    "#".repeat(usize::from(*level)),
                    md_text(text)
                );
            }
            Block::Para(cell) => {
                let _ = writeln!(out, "\n{}", md_cell(cell));
            }
            Block::Table(table) => {
                tables += 1;
                md_table(out, table, &w::table_label(doc.lang, tables));
            }
            Block::Figure(_) => {}
        }
    }
}

fn md_table(out: &mut String, table: &Table, label: &str) {
    let _ = writeln!(out, "\n*{} {}*\n", md_text(label), md_text(&table.caption));
    let head: Vec<String> = table.head.iter().map(|h| md_text(h)).collect();
    let _ = writeln!(out, "| {} |", head.join(" | "));
    let _ = writeln!(out, "|{}", "---|".repeat(head.len()));
    for row in &table.rows {
        let cells: Vec<String> = row.iter().map(md_cell).collect();
        let _ = writeln!(out, "| {} |", cells.join(" | "));
    }
}

fn md_cell(cell: &Cell) -> String {
    let text: String = cell
        .iter()
        .map(|run| match run {
            Run::Text(t) => md_text(t),
            Run::Code(t) => format!("`{}`", t.replace('|', "\\|")),
            Run::Mark(t) => format!("**{}**", md_text(t)),
        })
        .collect();
    if text.is_empty() {
        " ".into()
    } else {
        text
    }
}

/// Text that Markdown shows as written: its markup characters escaped. An
/// `_` between letters or digits never starts emphasis, and `>` and `#`
/// matter only at the start of a line, so those stay as they are.
fn md_text(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    for (i, &c) in chars.iter().enumerate() {
        let between_words = i > 0
            && chars[i - 1].is_alphanumeric()
            && chars.get(i + 1).is_some_and(|n| n.is_alphanumeric());
        let escape = match c {
            '\\' | '`' | '*' | '[' | ']' | '|' | '<' => true,
            '_' => !between_words,
            '>' | '#' => i == 0,
            _ => false,
        };
        if escape {
            out.push('\\');
        }
        match c {
            // A table row is one line: a diagnosis text's break is HTML's.
            '\n' => out.push_str("<br>"),
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn markdown_escapes_what_would_be_markup() {
        assert_eq!(
            md_text("PZD1 master->slave | a_b *c*"),
            "PZD1 master->slave \\| a_b \\*c\\*"
        );
        assert_eq!(md_text("> _x_ #1"), "\\> \\_x\\_ #1");
        assert_eq!(md_cell(&code("10F0 0800")), "`10F0 0800`");
        assert_eq!(md_cell(&Vec::new()), " ");
    }
}
