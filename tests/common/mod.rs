//! What the integration tests that build and run programs share.

use std::path::PathBuf;
use std::process::Command;

/// The directory of the library under test: `target/<profile>/deps`, beside the test
/// executable. Cargo builds the cdylib there for the tests, fresh, while its copy in
/// `target/<profile>` is only refreshed by `cargo build`.
pub fn lib_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("current_exe");
    let dir = exe.parent().expect("deps dir").to_path_buf();
    assert!(
        dir.join("libGLES_CM.so").exists(),
        "{} not found (cargo builds the cdylib with the tests)",
        dir.join("libGLES_CM.so").display()
    );
    dir
}

/// Runs `cmd`, panicking with its output unless it succeeds; returns its stdout.
#[allow(dead_code)]
pub fn run(cmd: &mut Command) -> String {
    let out = cmd
        .output()
        .unwrap_or_else(|e| panic!("cannot run {cmd:?}: {e}"));
    assert!(
        out.status.success(),
        "{cmd:?} failed ({}):\n{}\n{}",
        out.status,
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}
