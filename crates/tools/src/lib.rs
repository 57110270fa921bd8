//! What the bench, accuracy and showcase programs share beyond their `#[path]` modules.

use std::path::{Path, PathBuf};

/// The repository's root (two levels above this crate): where the corpus, the demo and the
/// reports the programs rewrite (BENCHMARKS.md, ACCURACY.md) live.
pub fn repo_root() -> PathBuf {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    root.canonicalize().unwrap_or(root)
}
