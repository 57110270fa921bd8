//! The install step as a user runs it: `scripts/install.sh PREFIX` puts the library, its
//! compatibility names, the headers and pkg-config files under PREFIX; a C program built with
//! `pkg-config --cflags --libs glesv1_cm egl` against that tree alone then runs, draws and
//! reads back the right pixels. Skipped (with a message) where pkg-config is not installed.

mod common;
use common::{lib_dir, run};

use std::path::Path;
use std::process::Command;

#[test]
fn installed_tree_builds_and_runs_a_program_through_pkg_config() {
    if Command::new("pkg-config")
        .arg("--version")
        .output()
        .is_err()
    {
        println!("skipped: pkg-config is not installed");
        return;
    }
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    let prefix = lib_dir().join("install-test");
    let _ = std::fs::remove_dir_all(&prefix);
    run(Command::new("sh")
        .arg(manifest.join("scripts/install.sh"))
        .arg(&prefix)
        .env("GLES_CM_LIB", lib_dir().join("libGLES_CM.so")));
    for name in ["libGLES_CM.so", "libGLESv1_CM.so.1", "libEGL.so.1"] {
        assert!(prefix.join("lib").join(name).exists(), "{name} installed");
    }
    assert!(prefix.join("include/GLES/gl.h").exists());

    let pc_path = prefix.join("lib/pkgconfig");
    let flags = run(Command::new("pkg-config")
        .args(["--cflags", "--libs", "glesv1_cm", "egl"])
        .env("PKG_CONFIG_PATH", &pc_path)
        .env("PKG_CONFIG_LIBDIR", &pc_path));
    let exe = prefix.join("triangle");
    // The drop-in program uses only the standard headers; here they come from the tree.
    let mut cc = Command::new(std::env::var("CC").unwrap_or_else(|_| "cc".into()));
    cc.arg(manifest.join("c_tests/dropin/triangle.c"))
        .arg("-o")
        .arg(&exe)
        .args(flags.split_whitespace());
    run(&mut cc);
    let out = run(Command::new(&exe).env("LD_LIBRARY_PATH", prefix.join("lib")));
    assert!(out.contains("gles-cm") && out.contains("ok"), "{out}");
}
