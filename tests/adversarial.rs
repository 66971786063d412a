//! Hostile and broken input: every case ends in a diagnostic with a rule
//! code, in bounded time and memory, through the library (`gsdc::load`,
//! `gsd::decode` + `gsd::check`, `gsdml::decode` + `gsdml::check`) and
//! through the command line (exit 1 and the diagnostic). The big inputs are
//! generated here, the 200 MB files as sparse files; none is committed.
//!
//! Every time bound catches hangs, not slowness: each case takes well under
//! a second, and [`HANG`] is set for a debug build on a busy 2-core machine.

use crate::support;
use gsdc::Diagnostics;
use std::fs::File;
use std::net::TcpListener;
use std::path::Path;
use std::process::{Command, Stdio};
use std::sync::OnceLock;
use std::time::{Duration, Instant};

const HANG: Duration = Duration::from_secs(5);

/// Far beyond every reader's limit (1 MiB for a description, 8 MiB for a
/// GSD file, 16 MiB for a GSDML file).
const BIG: usize = 200 << 20;

fn timed<T>(what: &str, f: impl FnOnce() -> T) -> T {
    let start = Instant::now();
    let result = f();
    let elapsed = start.elapsed();
    assert!(elapsed < HANG, "{what} took {elapsed:?}: a hang");
    result
}

fn load(text: &str) -> Diagnostics {
    timed("gsdc::load", || gsdc::load("hostile.toml", text).1)
}

fn check_gsd(bytes: &[u8]) -> Diagnostics {
    timed("gsd::check", || gsdc::gsd::check(&gsdc::gsd::decode(bytes)))
}

fn check_gsdml(bytes: &[u8]) -> Diagnostics {
    timed("gsdml::check", || match gsdc::gsdml::decode(bytes) {
        Ok(text) => gsdc::gsdml::check(&text, None),
        Err(d) => Diagnostics(vec![d]),
    })
}

/// An error with `code` whose message contains `words`.
#[track_caller]
fn assert_finds(diagnostics: &Diagnostics, code: &str, words: &str) {
    assert!(
        diagnostics
            .errors()
            .any(|d| d.code == code && d.message.contains(words)),
        "no {code} saying {words:?} in {diagnostics:#?}"
    );
}

/// 200 MB of GSD-like lines, made once for the tests that need it in memory.
fn big_text() -> &'static str {
    static TEXT: OnceLock<String> = OnceLock::new();
    TEXT.get_or_init(|| {
        let line = "Module = \"M\" 0x11\r\nEndModule\r\n";
        format!("#Profibus_DP\r\n{}", line.repeat(BIG / line.len()))
    })
}

/// A 200 MB file that costs no disk and no time to make: a hole.
fn sparse(path: &Path) {
    File::create(path).unwrap().set_len(BIG as u64).unwrap();
}

struct Run {
    code: Option<i32>,
    output: String,
}

/// Runs gsdc in `dir` with its data segment capped at 128 MiB (`ulimit -d`;
/// the real cases need less than 64): a reader that took a 200 MB file
/// whole could not allocate it, so exit 1 with the limit's diagnostic shows
/// the file was refused unread. Killed, and the test failed, after [`HANG`].
fn gsdc(dir: &Path, args: &[&str]) -> Run {
    let log = dir.join("gsdc.log");
    let out = File::create(&log).unwrap();
    let mut child = Command::new("sh")
        .arg("-c")
        .arg("ulimit -d 131072 && exec \"$0\" \"$@\"")
        .arg(support::GSDC)
        .args(args)
        .current_dir(dir)
        .stdout(out.try_clone().unwrap())
        .stderr(out)
        .stdin(Stdio::null())
        .spawn()
        .unwrap();
    let status = support::wait_within(&mut child, HANG, &format!("gsdc {args:?}"));
    let output = String::from_utf8_lossy(&std::fs::read(log).unwrap()).into_owned();
    Run {
        code: status.code(),
        output,
    }
}

/// Exit 1 with an error of `code`, as for any input with errors.
#[track_caller]
fn assert_rejected(run: &Run, code: &str) {
    assert_eq!(run.code, Some(1), "{}", run.output);
    assert!(
        run.output.contains(&format!("error[{code}]")),
        "no error[{code}] in {}",
        run.output
    );
}

/// Writes `contents` to `dir/name` and runs `gsdc check` on it.
fn check_file(dir: &Path, name: &str, contents: &[u8]) -> Run {
    std::fs::write(dir.join(name), contents).unwrap();
    gsdc(dir, &["check", name])
}

/// Writes `contents` to `dir/name` and runs `gsdc build` on it; nothing may
/// be written.
fn build_file(dir: &Path, name: &str, contents: &[u8]) -> Run {
    std::fs::write(dir.join(name), contents).unwrap();
    let run = gsdc(dir, &["build", name, "--out", "out"]);
    assert!(!dir.join("out").exists(), "{}", run.output);
    run
}

// The description (TOML).

fn nested_arrays(depth: usize) -> String {
    format!("x = {}{}\n", "[".repeat(depth), "]".repeat(depth))
}

fn nested_tables(depth: usize) -> String {
    format!("x = {}1{}\n", "{a = ".repeat(depth), "}".repeat(depth))
}

fn nested_headers(depth: usize) -> String {
    format!("[{}]\n", vec!["a"; depth].join("."))
}

/// The toml crate stops at 80 levels with an error. This runs on a test
/// thread (2 MiB of stack), so a parser that recursed per level would
/// overflow it here.
#[test]
fn a_description_nested_10000_deep_is_e001() {
    for text in [
        nested_arrays(10_000),
        nested_tables(10_000),
        nested_headers(10_000),
    ] {
        assert_finds(&load(&text), "E001", "recurs");
    }
    let dir = support::scratch("deep-toml");
    for (name, text) in [
        ("arrays.toml", nested_arrays(10_000)),
        ("tables.toml", nested_tables(10_000)),
    ] {
        assert_rejected(&build_file(&dir, name, text.as_bytes()), "E001");
    }
}

#[test]
fn a_200_mb_description_is_e006_unread() {
    assert_finds(&load(big_text()), "E006", "larger than 1 MiB");

    let dir = support::scratch("big-toml");
    sparse(&dir.join("big.toml"));
    let run = gsdc(&dir, &["build", "big.toml", "--out", "out"]);
    assert_rejected(&run, "E006");
    assert!(run.output.contains("= help:"), "{}", run.output);
    let e = timed("build::generate", || {
        gsdc::build::generate(dir.join("big.toml"), dir.join("out"))
    });
    assert!(e.unwrap_err().to_string().contains("error[E006]"));
    // A file with no known size is read up to the limit only.
    assert_rejected(&gsdc(&dir, &["build", "/dev/zero", "--out", "out"]), "E006");
    assert!(!dir.join("out").exists());
}

#[test]
fn a_description_with_nul_bytes_or_not_utf8_is_rejected() {
    let nul = b"[device]\nvendor = \"a\0b\"\n";
    assert_finds(&load(std::str::from_utf8(nul).unwrap()), "E001", "");
    let dir = support::scratch("nul-toml");
    assert_rejected(&build_file(&dir, "nul.toml", nul), "E001");

    std::fs::write(
        dir.join("latin1.toml"),
        b"[device]\nvendor = \"M\xfcller\"\n",
    )
    .unwrap();
    let e = gsdc::build::generate(dir.join("latin1.toml"), dir.join("out")).unwrap_err();
    assert!(e.to_string().contains("error[E000]"), "{e}");
    assert!(e.to_string().contains("latin1.toml:2:12"), "{e}");
}

// GSDML (XML).

const BILLION_LAUGHS: &str = r#"<?xml version="1.0"?>
<!DOCTYPE lolz [
  <!ENTITY lol "lol">
  <!ENTITY lol1 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">
  <!ENTITY lol2 "&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;">
  <!ENTITY lol3 "&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;">
  <!ENTITY lol4 "&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;">
  <!ENTITY lol5 "&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;">
  <!ENTITY lol6 "&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;">
  <!ENTITY lol7 "&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;">
  <!ENTITY lol8 "&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;">
  <!ENTITY lol9 "&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;">
]>
<ISO15745Profile xmlns="http://www.profibus.com/GSDML/2003/11/DeviceProfile">&lol9;</ISO15745Profile>
"#;

/// A GSDML root around `body`.
fn gsdml(body: &str) -> String {
    format!(
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<ISO15745Profile xmlns=\"{}\">{body}</ISO15745Profile>\n",
        gsdc::gsdml::NAMESPACE
    )
}

#[test]
fn entity_expansion_is_refused_with_the_dtd() {
    assert_finds(&check_gsdml(BILLION_LAUGHS.as_bytes()), "E300", "DTD");
    let dir = support::scratch("laughs");
    assert_rejected(
        &check_file(&dir, "laughs.xml", BILLION_LAUGHS.as_bytes()),
        "E300",
    );
}

/// External entities and DTDs are neither resolved nor fetched: a listener
/// on the address they name sees no connection.
#[test]
fn external_entities_and_dtds_are_never_fetched() {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    listener.set_nonblocking(true).unwrap();
    let url = format!("http://{}/evil", listener.local_addr().unwrap());
    let external_dtd = format!(
        "<?xml version=\"1.0\"?>\n<!DOCTYPE ISO15745Profile SYSTEM \"{url}.dtd\">\n{}",
        gsdml("")
    );
    let external_entity = format!(
        "<?xml version=\"1.0\"?>\n<!DOCTYPE r [<!ENTITY xxe SYSTEM \"file:///etc/passwd\"><!ENTITY web SYSTEM \"{url}\">]>\n{}",
        gsdml("&xxe;&web;")
    );
    let dir = support::scratch("external");
    for (name, text) in [("dtd.xml", &external_dtd), ("entity.xml", &external_entity)] {
        assert_finds(&check_gsdml(text.as_bytes()), "E300", "DTD");
        let run = check_file(&dir, name, text.as_bytes());
        assert_rejected(&run, "E300");
        assert!(!run.output.contains("root:"), "{}", run.output);
    }
    assert_eq!(
        listener.accept().map(|_| ()).unwrap_err().kind(),
        std::io::ErrorKind::WouldBlock,
        "gsdc connected to the URL of an external DTD or entity"
    );
}

#[test]
fn xml_nested_10000_deep_is_e300() {
    let deep = gsdml(&format!(
        "{}{}",
        "<DeviceIdentity>".repeat(10_000),
        "</DeviceIdentity>".repeat(10_000)
    ));
    assert_finds(
        &check_gsdml(deep.as_bytes()),
        "E300",
        "nest deeper than 256",
    );
    let dir = support::scratch("deep-xml");
    assert_rejected(&check_file(&dir, "deep.xml", deep.as_bytes()), "E300");
}

/// roxmltree's checks for duplicate attributes and for namespaces are
/// quadratic: 10 000 nested namespace declarations (270 KB) took seven
/// minutes before the shape limits.
#[test]
fn xml_with_floods_of_attributes_or_namespaces_is_e300() {
    let attributes: String = (0..1_000_000).map(|i| format!(" a{i}=\"1\"")).collect();
    let many_attributes = gsdml(&format!("<DeviceIdentity{attributes}/>"));
    assert_finds(
        &check_gsdml(many_attributes.as_bytes()),
        "E300",
        "more than 256 attributes",
    );
    let namespaces: String = (0..10_000)
        .map(|i| format!("<a xmlns:n{i}=\"urn:{i}\">"))
        .collect();
    let many_namespaces = gsdml(&format!("{namespaces}{}", "</a>".repeat(10_000)));
    assert_finds(
        &check_gsdml(many_namespaces.as_bytes()),
        "E300",
        "more than 64 XML namespaces",
    );
    let dir = support::scratch("namespaces");
    assert_rejected(
        &check_file(&dir, "namespaces.xml", many_namespaces.as_bytes()),
        "E300",
    );
}

/// 16 MiB of empty elements took roxmltree 500 MB and 2 s (debug) before
/// its node limit; the shape pass refuses them before the tree is built, so
/// the check fits in the 128 MiB the CLI runs with here.
#[test]
fn xml_with_millions_of_empty_elements_is_e300_before_the_tree() {
    let empty = gsdml(&"<a/>".repeat(4_000_000));
    assert!(empty.len() < 16 << 20);
    let dir = support::scratch("empty-elements");
    let run = check_file(&dir, "empty.xml", empty.as_bytes());
    assert_rejected(&run, "E300");
    assert!(
        run.output.contains("more than 1000000 elements"),
        "{}",
        run.output
    );
}

#[test]
fn a_200_mb_gsdml_text_is_e300_before_it_is_parsed() {
    assert_finds(
        &check_gsdml(big_text().as_bytes()),
        "E300",
        "larger than 16 MiB",
    );
    let diagnostics = timed("gsdml::check", || gsdc::gsdml::check(big_text(), None));
    assert_finds(&diagnostics, "E300", "larger than 16 MiB");
}

#[test]
fn xml_with_nul_bytes_or_not_utf8_is_e300() {
    let nul = gsdml("<DeviceIdentity>\0</DeviceIdentity>");
    assert_finds(&check_gsdml(nul.as_bytes()), "E300", "non-XML character");
    let not_utf8: Vec<u8> = gsdml("<DeviceIdentity>~</DeviceIdentity>")
        .bytes()
        .map(|b| if b == b'~' { 0xFF } else { b })
        .collect();
    assert_finds(&check_gsdml(&not_utf8), "E300", "not valid UTF-8");
    let dir = support::scratch("nul-xml");
    assert_rejected(&check_file(&dir, "nul.xml", nul.as_bytes()), "E300");
    assert_rejected(&check_file(&dir, "latin1.xml", &not_utf8), "E300");
}

// GSD.

const GSD_HEAD: &str =
    "#Profibus_DP\r\nGSD_Revision = 5\r\nModular_Station = 1\r\nMax_Module = 4\r\n";

/// A module line of 1 MB: 220 000 config identifiers, half of them not
/// numbers, each a finding on the same line.
#[test]
fn a_gsd_line_of_1_mb_gives_a_finding_per_bad_identifier() {
    let items = vec!["0x11,0xGG"; 110_000].join(",");
    let text = format!("{GSD_HEAD}Module = \"M\" {items}\r\nEndModule\r\n");
    assert!(text.len() > 1 << 20);
    let diagnostics = check_gsd(text.as_bytes());
    let unreadable = diagnostics.errors().filter(|d| d.code == "E201").count();
    assert_eq!(unreadable, 110_000);

    let string = format!("{GSD_HEAD}Vendor_Name = \"{}\"\r\n", "x".repeat(1 << 20));
    let diagnostics = check_gsd(string.as_bytes());
    assert!(
        diagnostics.iter().any(|d| d.code == "W209"),
        "{diagnostics:?}"
    );
    let dir = support::scratch("long-line");
    assert_rejected(&check_file(&dir, "long.gsd", text.as_bytes()), "E201");
    assert_rejected(&check_file(&dir, "string.gsd", string.as_bytes()), "E206");
}

/// 100 000 modules, each with a malformed config: a finding per module.
#[test]
fn a_gsd_with_100000_modules_gives_a_finding_per_module() {
    let modules: String = (0..100_000)
        .map(|i| format!("Module = \"M{i}\" 0x11,0xGG\r\nEndModule\r\n"))
        .collect();
    let text = format!("{GSD_HEAD}{modules}");
    let diagnostics = check_gsd(text.as_bytes());
    assert_eq!(
        diagnostics.errors().filter(|d| d.code == "E201").count(),
        100_000
    );
    let dir = support::scratch("modules");
    assert_rejected(&check_file(&dir, "modules.gsd", text.as_bytes()), "E201");
}

#[test]
fn a_gsd_with_nul_bytes_is_e230_once() {
    let text = format!(
        "{GSD_HEAD}Vendor_Name = \"a\0b\"\r\n{}",
        "\0".repeat(10_000)
    );
    let diagnostics = check_gsd(text.as_bytes());
    let nul: Vec<_> = diagnostics.iter().filter(|d| d.code == "E230").collect();
    assert_eq!(nul.len(), 1, "{diagnostics:?}");
    assert!(nul[0]
        .message
        .contains("NUL byte in the file (10000 more after it)"));
    let at = text.find('\0').unwrap();
    assert_eq!(nul[0].span, Some(at..at + 1));
    let dir = support::scratch("nul-gsd");
    assert_rejected(&check_file(&dir, "nul.gsd", text.as_bytes()), "E230");
}

/// Bytes that are not UTF-8 are read as Latin-1, as vendors' files need;
/// binary garbage then has no `#Profibus_DP` line and control characters.
/// `gsdc check` does not take it for a GSD file at all: one line, E400.
#[test]
fn binary_garbage_as_a_gsd_is_e200_and_e230_and_neither_to_check() {
    let mut state = 0x2545_F491_4F6C_DD1D_u64;
    let garbage: Vec<u8> = (0..1 << 20)
        .map(|_| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state.to_le_bytes()[0]
        })
        .collect();
    assert!(std::str::from_utf8(&garbage).is_err());
    let diagnostics = check_gsd(&garbage);
    assert_finds(&diagnostics, "E200", "#Profibus_DP");
    assert!(diagnostics.iter().any(|d| d.code == "E230"));
    let dir = support::scratch("garbage");
    let run = check_file(&dir, "garbage.gsd", &garbage);
    assert_rejected(&run, "E400");
    assert_eq!(run.output.lines().count(), 1, "{}", run.output);
}

#[test]
fn a_200_mb_gsd_text_is_e229_before_it_is_read() {
    let diagnostics = check_gsd(big_text().as_bytes());
    assert_eq!(diagnostics.iter().count(), 1, "{diagnostics:?}");
    assert_finds(&diagnostics, "E229", "larger than 8 MiB");
}

/// A 200 MB file whose first line is `head`, the rest a hole.
fn sparse_after(path: &Path, head: &[u8]) {
    std::fs::write(path, head).unwrap();
    let file = std::fs::OpenOptions::new().write(true).open(path).unwrap();
    file.set_len(BIG as u64).unwrap();
}

/// `gsdc check` on files of 200 MB and on files with no end: a GSD or
/// GSDML file is refused with its reader's limit before it is read whole;
/// of a file that is neither, whatever its size, only the first 64 KiB are
/// read to tell (the CLI runs with 128 MiB of data here).
#[test]
fn check_refuses_200_mb_files_unread() {
    let dir = support::scratch("big-check");
    sparse_after(&dir.join("big.txt"), b"#Profibus_DP\r\n");
    sparse_after(&dir.join("big.gsd"), b"<?xml version=\"1.0\"?>\n");
    sparse(&dir.join("zeros.xml"));
    assert_rejected(&gsdc(&dir, &["check", "big.txt"]), "E229");
    assert_rejected(&gsdc(&dir, &["check", "big.gsd"]), "E300");
    for neither in ["zeros.xml", "/dev/zero", "/dev/urandom"] {
        assert_rejected(&gsdc(&dir, &["check", neither]), "E400");
    }
}
