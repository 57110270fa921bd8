//! Where every corpus test finds the M3G corpus (`tests/data/m3g`, checked in).
//!
//! One helper, so that a test can only skip for the one reason `crates/m3g/tests/corpus_guard.rs`
//! checks: the directory is not there. A test that built its own path could point at the
//! wrong place and skip silently in a clone that has the corpus.

use std::path::{Path, PathBuf};

/// The corpus directory, or `None` (with a note on stderr) when the tree has no corpus.
/// The corpus counts as present when its `SOURCES.md` is, since that file lists every file.
#[allow(dead_code)]
pub fn m3g_corpus() -> Option<PathBuf> {
    let dir = corpus_path();
    if dir.join("SOURCES.md").is_file() {
        Some(dir)
    } else {
        eprintln!("skipped: no M3G corpus at {}", dir.display());
        None
    }
}

/// The corpus directory whether or not it exists: `tests/data/m3g` of the workspace, which
/// the M3G crate, the `m3g` tool, the bench and the fuzzer share.
pub fn corpus_path() -> PathBuf {
    workspace_root().join("tests/data/m3g")
}

/// The workspace's root: the first directory above the crate that holds `Cargo.lock`.
#[allow(dead_code)]
pub fn workspace_root() -> PathBuf {
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    manifest
        .ancestors()
        .find(|d| d.join("Cargo.lock").is_file())
        .unwrap_or(manifest)
        .to_path_buf()
}
