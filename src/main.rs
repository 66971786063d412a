use std::process::ExitCode;

fn main() -> ExitCode {
    ExitCode::from(gsdc::cli::main().code())
}
