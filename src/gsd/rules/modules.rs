//! Module rules: config identifier bytes (E215) and the I/O lengths they
//! declare against the station's limits (E216).

use crate::diag::Diagnostic;
use crate::gsd::model::{GsdFile, Module};

pub(super) fn check(file: &GsdFile, out: &mut Vec<Diagnostic>) {
    let limits = Limits::of(file);
    for module in &file.modules {
        if module.config.value.is_empty() {
            out.push(
                Diagnostic::error("E215", format!("module \"{}\" has no config identifier", module.name.value))
                    .at(module.name.span.clone())
                    .label("no config bytes after the name")
                    .help("write the module's config identifiers after its name, e.g. `0xF3,0xF1`; `0x00` for an empty slot"),
            );
            continue;
        }
        match module.io_lengths() {
            Ok(io) => limits.check(module, io.input, io.output, out),
            Err(e) => out.push(
                Diagnostic::error("E215", format!("config identifier {:#04X} announces {} more bytes than follow", module.config.value[e.at], e.needs))
                    .at(module.config.span.clone())
                    .label(format!("special format: {} byte(s) must follow identifier {}", e.needs, e.at + 1))
                    .help("bits 7-6 of a special identifier count its length bytes, bits 3-0 its manufacturer bytes"),
            ),
        }
    }
}

/// The station's `Max_Input_Len`, `Max_Output_Len` and `Max_Data_Len`
/// (which defaults to the sum of the other two).
struct Limits {
    input: Option<i64>,
    output: Option<i64>,
    data: Option<i64>,
}

impl Limits {
    fn of(file: &GsdFile) -> Limits {
        let input = file.number("Max_Input_Len");
        let output = file.number("Max_Output_Len");
        let sum = input.zip(output).map(|(i, o)| i + o);
        Limits {
            input,
            output,
            data: file.number("Max_Data_Len").or(sum),
        }
    }

    /// A module can be configured only if its data fit the station alone.
    fn check(&self, module: &Module, input: u32, output: u32, out: &mut Vec<Diagnostic>) {
        let checks = [
            ("input", "Max_Input_Len", i64::from(input), self.input),
            ("output", "Max_Output_Len", i64::from(output), self.output),
            (
                "input and output",
                "Max_Data_Len",
                i64::from(input + output),
                self.data,
            ),
        ];
        for (what, keyword, bytes, limit) in checks {
            let Some(limit) = limit.filter(|&l| bytes > l) else {
                continue;
            };
            out.push(
                Diagnostic::error(
                    "E216",
                    format!(
                        "module \"{}\" has {bytes} bytes of {what}, more than {keyword} = {limit}",
                        module.name.value
                    ),
                )
                .at(module.config.span.clone())
                .label(format!("{bytes} bytes of {what}"))
                .help(format!("raise {keyword}, or fix the config identifiers")),
            );
        }
    }
}
