//! E240-E242: the format gsdc writes (DESIGN.md, Outputs): 7-bit ASCII,
//! CRLF, lines of at most 80 characters. Only `check_strict` applies them:
//! vendor files break all three (286 of 654 real files have longer lines).

use crate::diag::Diagnostic;

use crate::spec::GSD_LINE_WIDTH as MAX_LINE;

pub(crate) fn output_format(text: &str) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    let mut bare_lf_reported = false;
    let mut start = 0;
    for line in text.split_inclusive('\n') {
        let content = line.trim_end_matches('\n').trim_end_matches('\r');
        let span = start..start + content.len();
        if let Some((past, _)) = content.char_indices().nth(MAX_LINE) {
            out.push(
                Diagnostic::error("E240", format!("line longer than {MAX_LINE} characters"))
                    .at(start + past..span.end)
                    .label(format!("past column {MAX_LINE}"))
                    .help("continue the line with `\\` at its end"),
            );
        }
        if let Some(i) = content.find(|c: char| !c.is_ascii()) {
            let c = content[i..].chars().next().map_or(0, char::len_utf8);
            out.push(
                Diagnostic::error("E241", "character outside 7-bit ASCII")
                    .at(start + i..start + i + c)
                    .label("not ASCII")
                    .help("GSD files are read as Latin-1 or UTF-8 depending on the tool: write ASCII only"),
            );
        }
        if line.ends_with('\n') && !line.ends_with("\r\n") && !bare_lf_reported {
            bare_lf_reported = true;
            out.push(
                Diagnostic::error("E242", "line ends with LF, not CRLF")
                    .at(span.end..span.end + 1)
                    .label("bare LF")
                    .help("end every line with CR LF"),
            );
        }
        start += line.len();
    }
    out
}
