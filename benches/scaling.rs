//! `cargo bench --bench scaling`: how the time of `gsdc doc`, `build`,
//! `check`, `diff` and `decode` grows with their input. Each runs, as a process,
//! on inputs of 1x, 4x and 16x a size; it prints the medians and the growth
//! from each size to the next. A command linear in its input takes at most
//! 4x as long per 4x step (less, while starting the process still counts);
//! a quadratic one 16x. A step above [`SUPER_LINEAR`] is marked: anything
//! super-linear is a finding (issue 26: wrapping a word of 400,000
//! characters in `gsdc doc` took 49 s).
//!
//! The inputs are made here, each stretching one dimension: a name of one
//! long word, many values of a bit field, many modules of a GSD and of a
//! GSDML file, long hex arguments. Needs the shipped descriptions only.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

const GSDC: &str = env!("CARGO_BIN_EXE_gsdc");
const MANIFEST: &str = env!("CARGO_MANIFEST_DIR");
const RUNS: usize = 7;
const STEPS: [usize; 3] = [1, 4, 16];
/// The growth per 4x step above which a command is marked super-linear,
/// with room for a noisy shared machine (linear is 4, quadratic 16).
const SUPER_LINEAR: f64 = 6.0;

fn main() {
    let dir = std::env::temp_dir().join(format!("gsdc-bench-scaling-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    copy_symbols(&dir);
    let kdp1 = shipped("9kdp1.toml");
    let (gsd, gsdml) = device_files(&dir);
    println!(
        "Time per input size, medians of {RUNS} runs; growth per 4x step (linear: at most 4x)."
    );

    // gsdc doc and build: a bit name of one word (the case of issue 26),
    // and a bit field of many values.
    let word = |n: usize| {
        kdp1.replacen(
            "name = \"Command function\"",
            &format!("name = \"{}\"", "x".repeat(n)),
            1,
        )
    };
    let values = |n: usize| {
        let extra: String = (0..n).fold(String::new(), |mut s, i| {
            let _ = writeln!(
                s,
                "        {{ value = {}, text = \"Value {i}\" }},",
                100 + i
            );
            s
        });
        let last = "        { value = 7, text = \"Fault reset\" },\n";
        kdp1.replacen(last, &format!("{last}{extra}"), 1)
    };
    for (command, what, make, base) in [
        (
            "doc",
            "a bit name of one word, characters",
            &word as &dyn Fn(usize) -> String,
            25_000,
        ),
        ("doc", "values of a bit field", &values, 1_000),
        ("build", "a bit name of one word, characters", &word, 25_000),
        ("build", "values of a bit field", &values, 1_000),
    ] {
        scale(&format!("gsdc {command}, {what}"), base, |n| {
            let path = dir.join(format!("card{n}.toml"));
            std::fs::write(&path, make(n)).unwrap();
            let mut c = Command::new(GSDC);
            c.arg(command).arg(&path).arg("--out").arg(dir.join("out"));
            c
        });
    }

    // gsdc check and diff: a GSD and a GSDML file of many modules (diffed
    // against itself: both sides read, nothing differs).
    let gsd_modules = |n| more_gsd_modules(&gsd, n);
    let gsdml_modules = |n| more_gsdml_modules(&gsdml, n);
    let files = [
        (
            "a GSD file, modules",
            &gsd_modules as &dyn Fn(usize) -> String,
            5_000,
            "MANY.GSD",
        ),
        (
            "a GSDML file, modules",
            &gsdml_modules,
            200,
            "GSDML-V2.32-Many-Modules-20260101.xml",
        ),
    ];
    for command in ["check", "diff"] {
        for (what, make, base, name) in files {
            scale(&format!("gsdc {command}, {what}"), base, |n| {
                let folder = dir.join(format!("{command}{n}"));
                std::fs::create_dir_all(&folder).unwrap();
                let path = folder.join(name);
                std::fs::write(&path, make(n)).unwrap();
                let mut c = Command::new(GSDC);
                c.arg(command).arg(&path);
                if command == "diff" {
                    c.arg(&path);
                }
                c
            });
        }
    }

    // gsdc decode: a telegram, a parameter telegram and a module name as
    // long as the arguments allow (one argument holds 128 KiB).
    let description = Path::new(MANIFEST).join("descriptions/md810dp.toml");
    let decode = |args: Vec<String>| {
        let mut c = Command::new(GSDC);
        c.arg("decode").arg(&description).args(args);
        c
    };
    scale(
        "gsdc decode, a telegram of hex digits (in arguments of 4000)",
        64_000,
        |n| {
            let hex = "0".repeat(n);
            let parts: Vec<String> = hex
                .as_bytes()
                .chunks(4000)
                .map(|c| String::from_utf8(c.to_vec()).unwrap())
                .collect();
            decode(
                ["--module", "PPO1", "--direction", "out"]
                    .iter()
                    .map(|s| s.to_string())
                    .chain(parts)
                    .collect(),
            )
        },
    );
    scale(
        "gsdc decode, a parameter telegram of hex digits, one odd",
        8_001,
        |n| decode(vec!["--prm".into(), "A".repeat(n)]),
    );
    scale("gsdc decode, a module name, characters", 8_000, |n| {
        decode(vec![
            "--module".into(),
            "P".repeat(n),
            "--direction".into(),
            "out".into(),
            "00".into(),
        ])
    });
    if std::env::var_os("GSDC_BENCH_KEEP").is_none() {
        let _ = std::fs::remove_dir_all(&dir);
    }
}

/// Times `command(size)` at each of [`STEPS`] times `base`, in turns, and
/// prints the medians and the growth per step.
fn scale(what: &str, base: usize, command: impl Fn(usize) -> Command) {
    let mut commands: Vec<Command> = STEPS.iter().map(|k| command(k * base)).collect();
    for c in &mut commands {
        run(c); // warm-up, and the inputs are written
    }
    let mut times: Vec<Vec<Duration>> = vec![Vec::new(); STEPS.len()];
    for _ in 0..RUNS {
        for (c, t) in commands.iter_mut().zip(&mut times) {
            let start = Instant::now();
            run(c);
            t.push(start.elapsed());
        }
    }
    let medians: Vec<f64> = times
        .iter_mut()
        .map(|t| {
            t.sort();
            t[RUNS / 2].as_secs_f64() * 1e3
        })
        .collect();
    let growth: Vec<f64> = medians.windows(2).map(|w| w[1] / w[0]).collect();
    let marks: Vec<String> = growth
        .iter()
        .map(|g| match *g > SUPER_LINEAR {
            true => format!("x{g:.1} SUPER-LINEAR"),
            false => format!("x{g:.1}"),
        })
        .collect();
    let sizes: Vec<String> = STEPS.iter().map(|k| (k * base).to_string()).collect();
    let shown: Vec<String> = medians.iter().map(|m| format!("{m:.1}")).collect();
    println!(
        "{what}: {} -> {} ms; growth {}",
        sizes.join(" / "),
        shown.join(" / "),
        marks.join(", then ")
    );
}

/// Runs a command to its end; its verdict does not matter here.
fn run(command: &mut Command) {
    let output = command
        .output()
        .unwrap_or_else(|e| panic!("cannot run {command:?}: {e}"));
    std::hint::black_box(output);
}

fn shipped(name: &str) -> String {
    std::fs::read_to_string(Path::new(MANIFEST).join("descriptions").join(name)).unwrap()
}

fn copy_symbols(dir: &Path) {
    let from = Path::new(MANIFEST).join("descriptions/symbols");
    std::fs::create_dir_all(dir.join("symbols")).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let path = entry.unwrap().path();
        std::fs::copy(&path, dir.join("symbols").join(path.file_name().unwrap())).unwrap();
    }
}

/// The GSD and the GSDML gsdc builds of md810dp.toml.
fn device_files(dir: &Path) -> (String, String) {
    let out = dir.join("md810dp");
    let description = Path::new(MANIFEST).join("descriptions/md810dp.toml");
    let built = Command::new(GSDC)
        .args(["build", "--firmware", "none", "--out"])
        .arg(&out)
        .arg(description)
        .output()
        .unwrap();
    assert!(
        built.status.success(),
        "{}",
        String::from_utf8_lossy(&built.stderr)
    );
    let file = |extension: &str| -> PathBuf {
        std::fs::read_dir(&out)
            .unwrap()
            .map(|e| e.unwrap().path())
            .find(|p| {
                p.extension()
                    .is_some_and(|e| e.eq_ignore_ascii_case(extension))
            })
            .unwrap()
    };
    let read = |p: PathBuf| std::fs::read_to_string(p).unwrap();
    (read(file("gsd")), read(file("xml")))
}

/// The GSD with `n` modules more, each a copy of its first under a name of
/// its own.
fn more_gsd_modules(gsd: &str, n: usize) -> String {
    let start = gsd.find("\r\nModule = ").expect("a module") + 2;
    let end = gsd[start..].find("EndModule\r\n").unwrap() + start + "EndModule\r\n".len();
    let module = &gsd[start..end];
    let name_end = module[10..].find('"').unwrap() + 10;
    let copies: String = (0..n)
        .map(|i| format!("Module = \"M{i}{}", &module[name_end..]))
        .collect();
    format!("{}{copies}{}", &gsd[..end], &gsd[end..])
}

/// The GSDML with `n` modules more, each a copy of its first under an ID
/// and an ident number of its own.
fn more_gsdml_modules(gsdml: &str, n: usize) -> String {
    let start = gsdml.find("<ModuleItem ").expect("a module");
    let end = gsdml[start..].find("</ModuleItem>").unwrap() + start + "</ModuleItem>".len();
    let module = &gsdml[start..end];
    let head_end = module.find('>').unwrap();
    let copies: String = (0..n)
        .map(|i| {
            format!(
                "\n        <ModuleItem ID=\"IDM_COPY_{i}\" ModuleIdentNumber=\"0x{:08X}\"{}",
                0x0001_0000 + i,
                &module[head_end..]
            )
        })
        .collect();
    format!("{}{copies}{}", &gsdml[..end], &gsdml[end..])
}
