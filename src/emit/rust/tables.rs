//! The device tables in Rust: each one a `pub const` of the support type
//! of its name (`gsdc::DpDevice`), laid out as rustfmt lays it out (its
//! default widths: 100 columns, arrays on one line up to 60, struct
//! literals up to 18), since the layout must be what rustfmt makes of it.

use crate::emit::layout::tables::{Record, Table, Value};
use crate::ir::MappingKind;

const MAX_WIDTH: usize = 100;
const ARRAY_WIDTH: usize = 60;
const STRUCT_LIT_WIDTH: usize = 18;
/// Items of at most this width, all literals, fill lines in rustfmt's
/// "mixed" layout.
const SHORT_ITEM: usize = 10;

/// The tables, each with its doc comment and a blank line before it.
pub(super) fn render(tables: &[Table]) -> String {
    let mut out = String::new();
    for table in tables {
        out.push('\n');
        out.push_str(&super::doc_comment(&table.doc, 0));
        out.push('\n');
        let ty = type_name(&table.record);
        let head = format!("pub const {}: {ty} = ", table.name.upper_snake());
        let value = record(&table.record, 0, head.len());
        out.push_str(&format!("{head}{value};\n"));
    }
    out
}

fn type_name(r: &Record) -> String {
    format!("gsdc::{}", r.ty.camel())
}

/// `value` as Rust, starting at `column` of a line indented by `indent`;
/// later lines carry their own indentation.
fn value(v: &Value, indent: usize, column: usize) -> String {
    match v {
        Value::Lit(literal) => super::lit(literal),
        Value::Bool(b) => b.to_string(),
        Value::Variant(ty, name) => format!("gsdc::{}::{}", ty.camel(), name.camel()),
        Value::List(_, items) => {
            let items: Vec<Item> = items.iter().map(Item::Value).collect();
            format!("&{}", list(&items, indent, column + 1))
        }
        Value::Optional(_, None) | Value::NodeTotals(false) => "None".into(),
        Value::Optional(_, Some(v)) => {
            let inner = value(v, indent, column + "Some(".len());
            format!("Some({inner})")
        }
        Value::NodeTotals(true) => "Some(gateway::user_prm_totals)".into(),
        Value::Record(r) => record(r, indent, column),
        Value::Entries(kind, positions) => {
            let items: Vec<Item> = positions
                .iter()
                .map(|&i| Item::Text(entry(*kind, i)))
                .collect();
            format!("&{}", list(&items, indent, column + 1))
        }
    }
}

/// `&pzd_out::MAPPINGS[0]`: an entry of a group's table.
fn entry(kind: MappingKind, position: usize) -> String {
    format!("&{}::MAPPINGS[{position}]", kind.key())
}

fn record(r: &Record, indent: usize, column: usize) -> String {
    let ty = type_name(r);
    let inner = indent + 4;
    let fields: Vec<(&str, String)> = r
        .fields
        .iter()
        .map(|(name, v)| (*name, value(v, inner, inner + name.len() + 2)))
        .collect();
    let body = fields
        .iter()
        .map(|(name, v)| format!("{name}: {v}"))
        .collect::<Vec<_>>()
        .join(", ");
    let one_line = format!("{ty} {{ {body} }}");
    if !body.contains('\n') && body.len() <= STRUCT_LIT_WIDTH && column + one_line.len() < MAX_WIDTH
    {
        return one_line;
    }
    let mut out = format!("{ty} {{\n");
    for (name, v) in fields {
        out.push_str(&format!("{:inner$}{name}: {v},\n", ""));
    }
    out.push_str(&format!("{:indent$}}}", ""));
    out
}

/// An item of a list: a value of the table, or a reference written out.
enum Item<'a> {
    Value(&'a Value),
    Text(String),
}

impl Item<'_> {
    fn render(&self, indent: usize, column: usize) -> String {
        match self {
            Item::Value(v) => value(v, indent, column),
            Item::Text(text) => text.clone(),
        }
    }

    /// A literal, which rustfmt lets fill lines when short.
    fn is_literal(&self) -> bool {
        matches!(self, Item::Value(Value::Lit(_) | Value::Bool(_)))
    }
}

/// `[a, b]` starting at `column`: on one line when it fits, a lone struct
/// literal hugged by the brackets, short literals filling lines, anything
/// else one item a line.
fn list(items: &[Item], indent: usize, column: usize) -> String {
    let inner = indent + 4;
    if let [only @ Item::Value(Value::Record(_))] = items {
        return format!("[{}]", only.render(indent, column + 1));
    }
    let one_line: Vec<String> = items.iter().map(|i| i.render(inner, 0)).collect();
    let total = one_line.iter().map(String::len).sum::<usize>() + 2 * items.len().saturating_sub(1);
    let multiline = one_line.iter().any(|s| s.contains('\n'));
    // The brackets and the comma after them.
    if !multiline && total <= ARRAY_WIDTH && column + total + 3 <= MAX_WIDTH {
        return format!("[{}]", one_line.join(", "));
    }
    let mut out = String::from("[\n");
    let short =
        items.iter().all(Item::is_literal) && one_line.iter().all(|s| s.len() <= SHORT_ITEM);
    if short {
        let mut line = String::new();
        for item in &one_line {
            if !line.is_empty() && inner + line.len() + 1 + item.len() + 1 > MAX_WIDTH {
                out.push_str(&format!("{:inner$}{}\n", "", line.trim_end()));
                line.clear();
            }
            line.push_str(&format!("{item}, "));
        }
        out.push_str(&format!("{:inner$}{}\n", "", line.trim_end()));
    } else {
        for item in items {
            out.push_str(&format!("{:inner$}{},\n", "", item.render(inner, inner)));
        }
    }
    out.push_str(&format!("{:indent$}]", ""));
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::emit::layout::tables::{type_ident, Elem};
    use crate::emit::layout::{Doc, Val};
    use crate::ir::Ident;

    fn p() -> Value {
        Value::Record(Record {
            ty: type_ident("p"),
            fields: vec![
                ("subslot", Value::Lit(Val::Dec(1))),
                ("ident", Value::Lit(Val::Hex(1, 8))),
            ],
        })
    }

    /// Every layout rustfmt chooses for the shapes the tables have, as
    /// rustfmt 1.8 wrote this table when given it on one line: short
    /// literals fill lines, a lone struct literal is hugged by its brackets
    /// or by `Some(`, a struct literal of at most 18 characters stays on its
    /// line, longer items stand one a line.
    #[test]
    fn tables_are_laid_out_as_rustfmt_lays_them_out() {
        let table = Table {
            name: Ident::of(&["x"]),
            doc: Doc::plain("D."),
            record: Record {
                ty: type_ident("t"),
                fields: vec![
                    (
                        "values",
                        Value::List(
                            Elem::Word,
                            (0..=40).map(|n| Value::Lit(Val::Dec(n))).collect(),
                        ),
                    ),
                    ("one", Value::List(Elem::Record("p"), vec![p()])),
                    (
                        "short",
                        Value::Record(Record {
                            ty: type_ident("q"),
                            fields: vec![("a", Value::Lit(Val::Dec(1)))],
                        }),
                    ),
                    (
                        "entries",
                        Value::Entries(MappingKind::PzdOut, vec![0, 1, 2, 3]),
                    ),
                    (
                        "some",
                        Value::Optional(Elem::Record("p"), Some(Box::new(p()))),
                    ),
                ],
            },
        };
        let expected = "
/// D.
pub const X: gsdc::T = gsdc::T {
    values: &[
        0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24,
        25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40,
    ],
    one: &[gsdc::P {
        subslot: 1,
        ident: 0x0000_0001,
    }],
    short: gsdc::Q { a: 1 },
    entries: &[
        &pzd_out::MAPPINGS[0],
        &pzd_out::MAPPINGS[1],
        &pzd_out::MAPPINGS[2],
        &pzd_out::MAPPINGS[3],
    ],
    some: Some(gsdc::P {
        subslot: 1,
        ident: 0x0000_0001,
    }),
};
";
        assert_eq!(render(&[table]), expected);
    }
}
