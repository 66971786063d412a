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
