//! `wire-dp --description DESC.toml --gsd FILE [--gsdc GSDC]`: the DP
//! exchange of one description, between a master configured from the GSD
//! FILE and the slave built from the description's layout (which the
//! firmware crate must have been built for: WIRE_DESCRIPTIONS). GSDC, the
//! gsdc binary, names the diagnosis the master read.
//!
//! Exit 0 when every exchange passed, 1 when one failed, 2 on a usage or
//! I/O error.

use std::path::PathBuf;
use std::process::ExitCode;

use wire_dp::exchange::Target;
use wire_dp::gsd::Gsd;

const USAGE: &str = "usage: wire-dp --description DESC.toml --gsd FILE [--gsdc GSDC]";

fn main() -> ExitCode {
    match run() {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(1),
        Err(why) => {
            eprintln!("wire-dp: {why}");
            ExitCode::from(2)
        }
    }
}

fn run() -> Result<bool, String> {
    let mut description = None;
    let mut gsd = None;
    let mut gsdc = None;
    let mut args = std::env::args_os().skip(1);
    while let Some(arg) = args.next() {
        let value = args.next().map(PathBuf::from);
        match arg.to_str() {
            Some("--description") => description = value,
            Some("--gsd") => gsd = value,
            Some("--gsdc") => gsdc = value,
            _ => return Err(USAGE.into()),
        }
    }
    let (Some(description), Some(gsd_path)) = (description, gsd) else {
        return Err(USAGE.into());
    };
    let name = description
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .ok_or(USAGE)?;
    let card = wire_firmware::card(&name).ok_or_else(|| {
        format!("the firmware was not built with {name}: build it with WIRE_DESCRIPTIONS naming it")
    })?;
    if card.dp.is_none() {
        return Err(format!("the layout of {name} has no PROFIBUS part"));
    }
    println!(
        "{}: the master reads {}",
        description.display(),
        gsd_path.display()
    );
    let gsd = match Gsd::read(&gsd_path) {
        Ok(gsd) => gsd,
        Err(why) => {
            println!("  FAILED: gsd-parser cannot read it: {why}");
            return Ok(false);
        }
    };
    let built_from = match &gsd.fingerprint {
        Some(f) if f == card.fingerprint => "the same description".to_string(),
        Some(f) => format!("a description of fingerprint {f}"),
        None => "no description gsdc names".to_string(),
    };
    println!(
        "  the slave runs the layout of {name} (fingerprint {}); {} comes from {built_from} and says ident 0x{:04X}",
        card.fingerprint,
        gsd.file_name,
        gsd.ident_number()
    );
    let target = Target {
        description,
        name,
        card,
        gsd,
        gsdc,
    };
    let tally = target.run();
    println!(
        "{}: {} exchanges passed, {} failed",
        target.description.display(),
        tally.passed,
        tally.failed
    );
    Ok(tally.failed == 0)
}
