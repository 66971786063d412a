//! What `scripts/wire-test.sh --results FILE` recorded of the exchanges on
//! the wire, and which of them were of the files a description gives now:
//! the datasheet's "tested on the wire" section shows those and no other.
//!
//! The file holds one line per exchange that passed, each naming the device
//! file the master or controller read, the SHA-256 of its bytes, how many
//! exchanges passed and the stacks with their pinned versions:
//!
//! ```text
//! # gsdc wire results 1
//! dp MD810DP.GSD 3f2a...e1 33 profirust 0.6.0 gsd-parser 0.6.0
//! pn GSDML-V2.32-....xml 9b1c...07 8 profinet-py 0.6.6 pnio 0.1.0
//! ```
//!
//! An exchange is the description's only when the file it names is, byte
//! for byte, the one `gsdc build` writes from the description now: a
//! changed description, a file of last year's release (`--files DIR`) or an
//! edited one is not claimed.

use crate::{Artifact, ArtifactKind};

/// The first line of a results file.
pub const RESULTS_HEADER: &str = "# gsdc wire results 1";

/// The bus an exchange ran on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Bus {
    /// PROFIBUS-DP: the master read the GSD.
    Dp,
    /// PROFINET: the IO controller read the GSDML.
    Pn,
}

/// A stack and its version, as pinned for the exchange.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Stack {
    pub name: String,
    pub version: String,
}

/// One recorded exchange that passed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Exchanged {
    pub bus: Bus,
    /// The device file the master or controller read.
    pub file_name: String,
    /// SHA-256 of its bytes, in lower-case hex.
    pub sha256: String,
    /// How many exchanges passed.
    pub passed: usize,
    /// DP: the master and the GSD reader; PROFINET: the controller and the
    /// device.
    pub stacks: [Stack; 2],
}

/// The exchanges of a results file, or why it is not one (a line number
/// from 1 and what is wrong there).
pub fn parse(text: &str) -> Result<Vec<Exchanged>, (usize, String)> {
    let mut lines = text.lines().enumerate();
    match lines.next() {
        Some((_, first)) if first.trim_end() == RESULTS_HEADER => {}
        _ => return Err((1, format!("a results file starts with `{RESULTS_HEADER}`"))),
    }
    let mut found = Vec::new();
    for (i, line) in lines {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        found.push(parse_line(line).map_err(|why| (i + 1, why))?);
    }
    Ok(found)
}

fn parse_line(line: &str) -> Result<Exchanged, String> {
    let fields: Vec<&str> = line.split_whitespace().collect();
    let [bus, file_name, sha256, passed, a, a_version, b, b_version] = fields[..] else {
        return Err("expected `BUS FILE SHA256 PASSED STACK VERSION STACK VERSION`".to_string());
    };
    let bus = match bus {
        "dp" => Bus::Dp,
        "pn" => Bus::Pn,
        other => return Err(format!("`{other}` is no bus: dp or pn")),
    };
    if sha256.len() != 64 || !sha256.bytes().all(|b| b.is_ascii_hexdigit()) {
        return Err(format!("`{sha256}` is no SHA-256"));
    }
    let passed = passed
        .parse()
        .map_err(|_| format!("`{passed}` is no count of exchanges"))?;
    let stack = |name: &str, version: &str| Stack {
        name: name.to_string(),
        version: version.to_string(),
    };
    Ok(Exchanged {
        bus,
        file_name: file_name.to_string(),
        sha256: sha256.to_ascii_lowercase(),
        passed,
        stacks: [stack(a, a_version), stack(b, b_version)],
    })
}

/// Each device file of `files` (what `gsdc build` writes from the
/// description), the GSD first, with the exchange `results` recorded of it
/// on its bus: the last one of a file of the same name and bytes, `None`
/// when there is none.
pub fn of_files(results: &[Exchanged], files: &[Artifact]) -> Vec<(String, Option<Exchanged>)> {
    let mut of_files = Vec::new();
    for (bus, kind) in [(Bus::Dp, ArtifactKind::Gsd), (Bus::Pn, ArtifactKind::Gsdml)] {
        let Some(file) = files.iter().find(|a| a.kind == kind) else {
            continue;
        };
        let sha256 = sha256_hex(&file.contents);
        let last = results
            .iter()
            .rev()
            .find(|e| e.bus == bus && e.file_name == file.file_name && e.sha256 == sha256);
        of_files.push((file.file_name.clone(), last.cloned()));
    }
    of_files
}

/// SHA-256 (FIPS 180-4) of `bytes`, in lower-case hex, as `sha256sum`
/// prints it.
pub fn sha256_hex(bytes: &[u8]) -> String {
    sha256(bytes).iter().map(|b| format!("{b:02x}")).collect()
}

fn sha256(bytes: &[u8]) -> [u8; 32] {
    const K: [u32; 64] = [
        0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4,
        0xab1c5ed5, 0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe,
        0x9bdc06a7, 0xc19bf174, 0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f,
        0x4a7484aa, 0x5cb0a9dc, 0x76f988da, 0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7,
        0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967, 0x27b70a85, 0x2e1b2138, 0x4d2c6dfc,
        0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85, 0xa2bfe8a1, 0xa81a664b,
        0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070, 0x19a4c116,
        0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
        0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7,
        0xc67178f2,
    ];
    let mut h: [u32; 8] = [
        0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a, 0x510e527f, 0x9b05688c, 0x1f83d9ab,
        0x5be0cd19,
    ];
    // The message, a 1 bit, zeros to 56 bytes of the last block, then its
    // length in bits, big-endian.
    let mut message = bytes.to_vec();
    message.push(0x80);
    while message.len() % 64 != 56 {
        message.push(0);
    }
    message.extend_from_slice(&((bytes.len() as u64).wrapping_mul(8)).to_be_bytes());
    for block in message.chunks_exact(64) {
        let mut w = [0u32; 64];
        for (i, word) in block.chunks_exact(4).enumerate() {
            w[i] = u32::from_be_bytes([word[0], word[1], word[2], word[3]]);
        }
        for i in 16..64 {
            let s0 = w[i - 15].rotate_right(7) ^ w[i - 15].rotate_right(18) ^ (w[i - 15] >> 3);
            let s1 = w[i - 2].rotate_right(17) ^ w[i - 2].rotate_right(19) ^ (w[i - 2] >> 10);
            w[i] = w[i - 16]
                .wrapping_add(s0)
                .wrapping_add(w[i - 7])
                .wrapping_add(s1);
        }
        let [mut a, mut b, mut c, mut d, mut e, mut f, mut g, mut hh] = h;
        for i in 0..64 {
            let s1 = e.rotate_right(6) ^ e.rotate_right(11) ^ e.rotate_right(25);
            let ch = (e & f) ^ (!e & g);
            let t1 = hh
                .wrapping_add(s1)
                .wrapping_add(ch)
                .wrapping_add(K[i])
                .wrapping_add(w[i]);
            let s0 = a.rotate_right(2) ^ a.rotate_right(13) ^ a.rotate_right(22);
            let maj = (a & b) ^ (a & c) ^ (b & c);
            let t2 = s0.wrapping_add(maj);
            hh = g;
            g = f;
            f = e;
            e = d.wrapping_add(t1);
            d = c;
            c = b;
            b = a;
            a = t1.wrapping_add(t2);
        }
        for (state, add) in h.iter_mut().zip([a, b, c, d, e, f, g, hh]) {
            *state = state.wrapping_add(add);
        }
    }
    let mut digest = [0u8; 32];
    for (out, word) in digest.chunks_exact_mut(4).zip(h) {
        out.copy_from_slice(&word.to_be_bytes());
    }
    digest
}

#[cfg(test)]
mod tests {
    use super::*;

    /// FIPS 180-4's examples (one block, two blocks) and the empty message.
    #[test]
    fn sha256_is_the_standards() {
        assert_eq!(
            sha256_hex(b""),
            "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855"
        );
        assert_eq!(
            sha256_hex(b"abc"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"
        );
        assert_eq!(
            sha256_hex(b"abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1"
        );
    }

    fn gsd(contents: &[u8]) -> Artifact {
        Artifact {
            kind: ArtifactKind::Gsd,
            file_name: "MD810DP.GSD".into(),
            contents: contents.to_vec(),
        }
    }

    fn line(sha: &str, passed: usize) -> String {
        format!("dp MD810DP.GSD {sha} {passed} profirust 0.6.0 gsd-parser 0.6.0")
    }

    #[test]
    fn an_exchange_is_claimed_only_for_the_same_bytes() {
        let built = gsd(b"#Profibus_DP\n");
        let same = sha256_hex(b"#Profibus_DP\n");
        let other = sha256_hex(b"#Profibus_DP\nRevision=2\n");
        let text = format!(
            "{RESULTS_HEADER}\n{}\n{}\n",
            line(&same, 33),
            line(&other, 34)
        );
        let results = parse(&text).unwrap();
        assert_eq!(results.len(), 2);
        let claimed = of_files(&results, &[built]);
        let [(file, Some(exchanged))] = &claimed[..] else {
            panic!("{claimed:?}");
        };
        assert_eq!(file, "MD810DP.GSD");
        assert_eq!(exchanged.passed, 33);
        assert_eq!(exchanged.stacks[0].name, "profirust");
        let edited = of_files(&results, &[gsd(b"edited")]);
        assert_eq!(edited, [("MD810DP.GSD".to_string(), None)]);
    }

    #[test]
    fn a_file_that_is_no_results_file_says_where() {
        assert_eq!(parse("dp x").unwrap_err().0, 1);
        let text = format!("{RESULTS_HEADER}\n\ndp MD810DP.GSD abc 3 a 1 b 2\n");
        let (line, why) = parse(&text).unwrap_err();
        assert_eq!(line, 3);
        assert!(why.contains("SHA-256"), "{why}");
        let text = format!("{RESULTS_HEADER}\nxx f {} 3 a 1 b 2\n", "0".repeat(64));
        assert_eq!(parse(&text).unwrap_err().0, 2);
    }
}
