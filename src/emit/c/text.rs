//! C's text: comments wrapped within 80 columns with nothing in them that
//! could end them early, string literals, and macro initializers.

use std::fmt::Write as _;

/// Columns a comment or an initializer fills before it wraps.
pub(super) const WIDTH: usize = 80;

/// `#define NAME { a, b }`, wrapped with continuation lines when long.
pub(super) fn initializer(name: &str, values: &[String]) -> String {
    let line = format!("#define {name} {{ {} }}", values.join(", "));
    if line.len() <= WIDTH {
        return line;
    }
    let mut lines = vec![format!("#define {name} {{")];
    let mut current = String::from("   ");
    for (i, value) in values.iter().enumerate() {
        let last = i + 1 == values.len();
        let item = if last {
            format!(" {value} }}")
        } else {
            format!(" {value},")
        };
        if current.len() + item.len() > WIDTH - 2 {
            lines.push(std::mem::replace(&mut current, String::from("   ")));
        }
        current.push_str(&item);
    }
    lines.push(current);
    lines.join(" \\\n")
}

/// A block comment of `text`, wrapped: `/* text */` on one line when it fits.
pub(super) fn comment(text: &str) -> String {
    indented_comment(text, 0)
}

/// [`comment`] indented by `indent` columns, as inside a struct.
pub(super) fn indented_comment(text: &str, indent: usize) -> String {
    let lines = wrap(&comment_text(text), WIDTH.saturating_sub(3 + indent));
    block_comment(&lines)
        .lines()
        .map(|line| format!("{:indent$}{line}", ""))
        .collect::<Vec<_>>()
        .join("\n")
}

/// `/* line` ... ` * line */`.
pub(super) fn block_comment(lines: &[String]) -> String {
    let mut out = String::new();
    for (i, line) in lines.iter().enumerate() {
        out.push_str(if i == 0 { "/*" } else { " *" });
        if !line.is_empty() {
            out.push(' ');
            out.push_str(line);
        }
        out.push_str(if i + 1 == lines.len() { " */" } else { "\n" });
    }
    out
}

/// Words of `text` in lines of at most `width` characters (a longer word has
/// a line of its own); an empty text is one empty line.
pub(super) fn wrap(text: &str, width: usize) -> Vec<String> {
    let lines = crate::emit::wrap_words(text, width);
    if lines.is_empty() {
        vec![String::new()]
    } else {
        lines
    }
}

/// A description's text, safe inside a C comment: on one line, with no `*/`
/// to end the comment, no `/*` for compilers to warn about, no `??` to start
/// a trigraph, and control and bidirectional formatting characters (which
/// compilers warn about) written as `<U+202E>`.
pub(super) fn comment_text(text: &str) -> String {
    let mut visible = String::with_capacity(text.len());
    for c in text.chars() {
        if (c.is_control() && !c.is_whitespace()) || crate::spec::is_bidi_control(c) {
            let _ = write!(visible, "<U+{:04X}>", u32::from(c));
        } else {
            visible.push(c);
        }
    }
    let mut out = visible.split_whitespace().collect::<Vec<_>>().join(" ");
    for (from, to) in [("*/", "* /"), ("/*", "/ *"), ("??", "? ?")] {
        while out.contains(from) {
            out = out.replace(from, to);
        }
    }
    out
}

/// A C string literal of `text`: printable ASCII as it is (`\`, `"` and `?`
/// escaped, the last against trigraphs), any other byte as an octal escape,
/// which never swallows the character after it.
pub(super) fn c_string(text: &str) -> String {
    let mut out = String::from("\"");
    for byte in text.bytes() {
        match byte {
            b'\\' | b'"' | b'?' => {
                out.push('\\');
                out.push(char::from(byte));
            }
            b' '..=b'~' => out.push(char::from(byte)),
            _ => out.push_str(&format!("\\{byte:03o}")),
        }
    }
    out.push('"');
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn texts_cannot_break_out_of_comments_or_strings() {
        assert_eq!(comment_text("a */ b /* c ?? d"), "a * / b / * c ? ? d");
        assert_eq!(comment_text("a ???/ b"), "a ? ? ?/ b");
        assert_eq!(comment_text("**/"), "** /");
        assert_eq!(
            c_string("a \"b\" \\ ??= 中"),
            "\"a \\\"b\\\" \\\\ \\?\\?= \\344\\270\\255\""
        );
        assert_eq!(c_string("\u{1}7"), "\"\\0017\"");
        assert_eq!(comment_text("a\u{202E}b\u{7}c\nd"), "a<U+202E>b<U+0007>c d");
    }

    #[test]
    fn comments_and_initializers_wrap() {
        assert_eq!(comment("short"), "/* short */");
        let long = comment(&"word ".repeat(40));
        let lines: Vec<_> = long.lines().collect();
        assert!(lines.len() > 1);
        assert!(lines.iter().all(|l| l.len() <= WIDTH), "{long}");
        assert!(lines[0].starts_with("/* word"));
        assert!(lines[1..].iter().all(|l| l.starts_with(" * word")));
        assert!(long.ends_with("word */"));
        let member = indented_comment(&"word ".repeat(40), 4);
        assert!(member.lines().all(|l| l.len() <= WIDTH), "{member}");
        assert!(member.starts_with("    /* word"));
        assert!(member.lines().skip(1).all(|l| l.starts_with("     * word")));
        assert_eq!(
            initializer("X", &["1U".into(), "2U".into()]),
            "#define X { 1U, 2U }"
        );
        let values: Vec<String> = (0..30).map(|i| format!("0x{i:04X}U")).collect();
        let wrapped = initializer("X", &values);
        assert!(wrapped.lines().all(|l| l.len() <= WIDTH), "{wrapped}");
        assert!(wrapped.lines().rev().skip(1).all(|l| l.ends_with(" \\")));
        assert!(wrapped.ends_with("0x001DU }"));
        assert_eq!(wrapped.matches("0x").count(), 30);
    }
}
