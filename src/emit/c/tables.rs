//! The device tables in C: each one a function, `<prefix>_dp_device()`,
//! that returns its table, a `static const` object of the support type of
//! its name (`gsdc_dp_device_t`) inside it, since a header may not define
//! objects every translation unit would repeat. C has no slices: a list is
//! a static array declared before the object and a pointer with its count
//! (`NULL, 0U` when empty), which is the order the support types declare
//! them in; C++ has no designated initializers before C++20, so every
//! initializer is positional.

use super::text::{comment, WIDTH};
use super::Names;
use crate::emit::layout::tables::{type_ident, Elem, Record, Table, Value};
use crate::emit::layout::Val;

/// The tables, each with its comment and a blank line before it.
pub(super) fn render(names: &Names, tables: &[Table]) -> String {
    tables
        .iter()
        .map(|table| {
            let mut statics = Statics {
                names,
                lines: Vec::new(),
            };
            let ty = type_name(&table.record);
            let object = statics.record(&table.record, "", 4, 0);
            format!(
                "\n{}\nstatic inline const {ty} *{}(void)\n{{\n{}    static const {ty} table = {object};\n    return &table;\n}}\n",
                comment(&names.rendered(&table.doc)),
                names.lower(&table.name.snake()),
                statics.lines.concat(),
            )
        })
        .collect()
}

fn type_name(r: &Record) -> String {
    format!("gsdc_{}_t", r.ty.snake())
}

fn elem_type(elem: Elem) -> String {
    match elem {
        Elem::Bool => "bool".into(),
        Elem::Byte => "uint8_t".into(),
        Elem::Word => "uint16_t".into(),
        Elem::Long => "uint32_t".into(),
        Elem::Index => "size_t".into(),
        Elem::Record(name) => format!("gsdc_{}_t", type_ident(name).snake()),
    }
}

/// The static arrays and objects a table refers to, declared before it.
struct Statics<'a> {
    names: &'a Names,
    lines: Vec<String>,
}

impl Statics<'_> {
    /// `{ a, b }` of a record at `path` (empty for the table itself, which
    /// has a field a line), on one line when it fits at `indent` after
    /// `lead` columns of its line (a declaration's head), else a field a
    /// line, each named in a comment.
    fn record(&mut self, r: &Record, path: &str, indent: usize, lead: usize) -> String {
        let parts: Vec<(String, String)> = r
            .fields
            .iter()
            .flat_map(|(name, v)| {
                let at = if path.is_empty() {
                    name.to_string()
                } else {
                    format!("{path}_{name}")
                };
                self.value(v, name, &at, indent + 4)
            })
            .collect();
        let values: Vec<&str> = parts.iter().map(|(_, value)| value.as_str()).collect();
        let one_line = format!("{{ {} }}", values.join(", "));
        // The comma after it.
        let fits = !one_line.contains('\n') && indent + lead + one_line.len() < WIDTH;
        if !path.is_empty() && fits {
            return one_line;
        }
        let inner = " ".repeat(indent + 4);
        let last = parts.len() - 1;
        let fields: Vec<String> = parts
            .iter()
            .enumerate()
            .map(|(i, (field, value))| {
                let comma = if i == last { "" } else { "," };
                format!("{inner}{value}{comma} /* {field} */\n")
            })
            .collect();
        format!("{{\n{}{:indent$}}}", fields.concat(), "")
    }

    /// The initializer's parts a value gives, each with the field of the
    /// support type it fills: one, or a pointer and a count for a list, or
    /// the check and the list of a record's entries.
    fn value(
        &mut self,
        v: &Value,
        field: &str,
        path: &str,
        indent: usize,
    ) -> Vec<(String, String)> {
        let one = |value: String| vec![(field.to_string(), value)];
        match v {
            Value::Lit(literal) => one(super::lit(literal)),
            Value::Bool(b) => one(b.to_string()),
            Value::Variant(ty, name) => {
                one(format!("GSDC_{}_{}", ty.upper_snake(), name.upper_snake()))
            }
            Value::Record(r) => one(self.record(r, path, indent, 0)),
            Value::List(elem, items) => self.list(*elem, items, field, path),
            Value::Optional(Elem::Record(_), None) | Value::NodeTotals(false) => one("NULL".into()),
            Value::Optional(_, None) => counted(field, "NULL".into(), 0),
            Value::Optional(elem @ Elem::Record(_), Some(record)) => {
                let head = format!("    static const {} {path} = ", elem_type(*elem));
                let object = self.record_of(record, path, head.len());
                self.lines.push(format!("{head}{object};\n"));
                one(format!("&{path}"))
            }
            Value::Optional(_, Some(list)) => self.value(list, field, path, indent),
            Value::NodeTotals(true) => one(self.names.lower("user_prm_totals")),
            Value::Entries(kind, positions) => {
                let function = |what| self.names.lower(&format!("{}_{what}", kind.key()));
                let places: Vec<Value> = positions
                    .iter()
                    .map(|&p| Value::Lit(Val::Dec(p as u64)))
                    .collect();
                let mut parts = vec![
                    ("allows".to_string(), function("entry_allows")),
                    ("entry_bytes".to_string(), function("entry_bytes")),
                ];
                parts.extend(self.list(Elem::Index, &places, field, path));
                parts
            }
        }
    }

    /// The record an optional value holds, declared after `head` columns.
    fn record_of(&mut self, v: &Value, path: &str, head: usize) -> String {
        match v {
            Value::Record(r) => self.record(r, path, 4, head - 4),
            _ => unreachable!("an optional record holds a record"),
        }
    }

    /// A static array of `items` and the pointer and count that name it.
    fn list(
        &mut self,
        elem: Elem,
        items: &[Value],
        field: &str,
        path: &str,
    ) -> Vec<(String, String)> {
        if items.is_empty() {
            return counted(field, "NULL".into(), 0);
        }
        let values: Vec<String> = items
            .iter()
            .enumerate()
            .map(|(i, item)| {
                let at = format!("{path}_{i}");
                let parts = self.value(item, field, &at, 8);
                parts
                    .into_iter()
                    .map(|(_, value)| value)
                    .collect::<String>()
            })
            .collect();
        let ty = elem_type(elem);
        let count = items.len();
        let head = format!("    static const {ty} {path}[{count}] = ");
        let one_line = format!("{head}{{ {} }};", values.join(", "));
        let declaration = if one_line.len() <= WIDTH && !one_line.contains('\n') {
            format!("{one_line}\n")
        } else if matches!(elem, Elem::Record(_)) {
            format!(
                "{head}{{\n        {},\n    }};\n",
                values.join(",\n        ")
            )
        } else {
            format!("{head}{{\n{}    }};\n", filled(&values, 8))
        };
        self.lines.push(declaration);
        counted(field, path.to_string(), count)
    }
}

/// Short values, as many a line as fit, each line indented by `indent`.
fn filled(values: &[String], indent: usize) -> String {
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for value in values {
        if !line.is_empty() && indent + line.len() + value.len() + 2 > WIDTH {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(value);
        line.push(',');
    }
    lines.push(line);
    lines
        .iter()
        .map(|l| format!("{:indent$}{l}\n", ""))
        .collect()
}

/// A list's pointer and count, filling `field` and `field_count`.
fn counted(field: &str, pointer: String, count: usize) -> Vec<(String, String)> {
    vec![
        (field.to_string(), pointer),
        (format!("{field}_count"), format!("{count}U")),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::emit::layout::Doc;
    use crate::ir::Ident;

    /// Lists become static arrays named by their path, an empty list and an
    /// absent record NULL (C has no array of 0 elements), and the table's
    /// fields each a line with the field it fills.
    #[test]
    fn lists_are_arrays_before_the_table_and_absent_ones_null() {
        let names = Names {
            p: "X".into(),
            l: "x".into(),
            pkw: None,
        };
        let sub = |n| {
            Value::Record(Record {
                ty: type_ident("pn submodule"),
                fields: vec![("subslot", Value::Lit(Val::Dec(n)))],
            })
        };
        let table = Table {
            name: Ident::of(&["pn", "device"]),
            doc: Doc::plain("D."),
            record: Record {
                ty: type_ident("pn device"),
                fields: vec![
                    (
                        "ports",
                        Value::List(Elem::Record("pn submodule"), vec![sub(1), sub(2)]),
                    ),
                    ("slots", Value::List(Elem::Word, Vec::new())),
                    (
                        "access_point",
                        Value::Optional(Elem::Record("pn submodule"), None),
                    ),
                    (
                        "data",
                        Value::Optional(Elem::Record("pn submodule"), Some(Box::new(sub(3)))),
                    ),
                ],
            },
        };
        let expected = "
/* D. */
static inline const gsdc_pn_device_t *x_pn_device(void)
{
    static const gsdc_pn_submodule_t ports[2] = { { 1U }, { 2U } };
    static const gsdc_pn_submodule_t data = { 3U };
    static const gsdc_pn_device_t table = {
        ports, /* ports */
        2U, /* ports_count */
        NULL, /* slots */
        0U, /* slots_count */
        NULL, /* access_point */
        &data /* data */
    };
    return &table;
}
";
        assert_eq!(render(&names, &[table]), expected);
    }
}
