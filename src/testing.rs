//! What the unit tests share: descriptions loaded as the build loads them,
//! the files they name (their symbols) read beside the shipped ones.

use crate::{Diagnostics, Ir};
use std::path::Path;

/// `text` (a shipped description, or one made from it) loaded as if it
/// stood in `descriptions/`.
pub(crate) fn load(name: &str, text: &str) -> (Option<Ir>, Diagnostics) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("descriptions");
    crate::load_with(name, text, &|path: &str| {
        std::fs::read(dir.join(path)).map_err(|e| e.to_string())
    })
}

/// MV810 with a second setting whose range holds a plain value, not a
/// parameter address: a timeout in ms, 100 by default.
pub(crate) fn mv810_with_timeout() -> Ir {
    let text = include_str!("../descriptions/mv810-pnet02.toml").replace(
        "\n[profinet]\n",
        "\n[[settings]]\n\
         name = { en = \"Communication timeout (P43.24)\", zh = \"通讯超时（P43.24）\" }\n\
         range = [0, 60000]\n\
         default = 100\n\
         \n[profinet]\n",
    );
    assert!(text.contains("range = [0, 60000]"));
    load("mv810-pnet02.toml", &text).0.unwrap()
}
