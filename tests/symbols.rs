//! The shared library as a binary: it exports only `gl*`/`egl*` symbols (and glvnd's
//! `__egl_Main`), exactly the functions the generated headers declare, carries the SONAME
//! `libGLES_CM.so.1`, and `scripts/compat-names.sh` gives it the usual file names as
//! symlinks to the one object.

mod common;
use common::{lib_dir, run};

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;

const MANIFEST_DIR: &str = env!("CARGO_MANIFEST_DIR");
const OUT_DIR: &str = env!("OUT_DIR");

/// The generated headers that declare functions.
const HEADERS: &[(&str, &str)] = &[
    (
        "GLES/gl.h",
        include_str!(concat!(env!("OUT_DIR"), "/include/GLES/gl.h")),
    ),
    (
        "GLES/glext.h",
        include_str!(concat!(env!("OUT_DIR"), "/include/GLES/glext.h")),
    ),
    (
        "EGL/egl.h",
        include_str!(concat!(env!("OUT_DIR"), "/include/EGL/egl.h")),
    ),
    (
        "EGL/eglext.h",
        include_str!(concat!(env!("OUT_DIR"), "/include/EGL/eglext.h")),
    ),
];

/// Exports that are no `gl*`/`egl*` function: glvnd's vendor entry point, declared by glvnd's
/// `glvnd/libeglabi.h`, not by our headers (`src/egl/glvnd.rs`).
const VENDOR_EXPORTS: &[&str] = &["__egl_Main"];

fn library() -> PathBuf {
    let lib = lib_dir().join("libGLES_CM.so");
    assert!(lib.exists(), "{} not found", lib.display());
    lib
}

/// Names of the dynamic symbols the library defines.
fn exported() -> BTreeSet<String> {
    let out = run(Command::new("nm")
        .args(["-D", "--defined-only"])
        .arg(library()));
    out.lines()
        .filter_map(|l| l.split_whitespace().nth(2))
        // Version nodes of the export list show up as absolute symbols.
        .map(|s| s.split('@').next().unwrap_or(s).to_string())
        .collect()
}

/// Names of the functions the headers declare: `API ret ENTRY name (args);` lines.
fn declared() -> BTreeSet<String> {
    let mut names = BTreeSet::new();
    for (_, text) in HEADERS {
        for line in text.lines() {
            let decl = line
                .strip_prefix("GL_API ")
                .or_else(|| line.strip_prefix("EGLAPI "));
            let Some(decl) = decl else { continue };
            let Some(open) = decl.find(" (") else {
                continue;
            };
            let name = decl[..open].rsplit([' ', '*']).next().unwrap_or_default();
            names.insert(name.to_string());
        }
    }
    names
}

#[test]
fn exports_only_gl_and_egl_symbols() {
    let syms = exported();
    assert!(!syms.is_empty(), "the library exports nothing");
    let foreign: Vec<&String> = syms
        .iter()
        .filter(|s| !s.starts_with("gl") && !s.starts_with("egl"))
        .filter(|s| !VENDOR_EXPORTS.contains(&s.as_str()))
        .collect();
    assert!(
        foreign.is_empty(),
        "symbols other than gl*/egl* are exported: {foreign:?} (rustc exports every \
         #[no_mangle] pub extern fn; drop the #[no_mangle] of helpers)"
    );
}

#[test]
fn soname_is_versioned_libgles_cm() {
    let out = run(Command::new("readelf").arg("-d").arg(library()));
    let soname = out.lines().find(|l| l.contains("(SONAME)"));
    assert!(
        soname
            .map(|l| l.contains("[libGLES_CM.so.1]"))
            .unwrap_or(false),
        "SONAME is not libGLES_CM.so.1: {soname:?}"
    );
}

#[test]
fn declared_functions_are_exactly_the_exported_ones() {
    let mut exported = exported();
    for name in VENDOR_EXPORTS {
        assert!(exported.remove(*name), "{name} is not exported");
    }
    let mut declared = declared();
    assert!(!declared.is_empty(), "the headers declare no functions");
    // Registry functions of glext.h/eglext.h the library does not provide: declared (as the
    // Khronos headers do) but never exported, and said so in the header.
    let declared_only: BTreeSet<String> =
        include_str!(concat!(env!("OUT_DIR"), "/declared_only.txt"))
            .lines()
            .map(str::to_string)
            .collect();
    let both: Vec<&String> = declared_only.intersection(&exported).collect();
    assert!(
        both.is_empty(),
        "exported yet listed as declared only: {both:?}"
    );
    let undeclared: Vec<&String> = declared_only.difference(&declared).collect();
    assert!(
        undeclared.is_empty(),
        "declared only, not declared: {undeclared:?}"
    );
    declared.retain(|n| !declared_only.contains(n));
    let not_exported: Vec<&String> = declared.difference(&exported).collect();
    let not_declared: Vec<&String> = exported.difference(&declared).collect();
    assert!(
        not_exported.is_empty() && not_declared.is_empty(),
        "declared in the headers but not exported: {not_exported:?}\n\
         exported but not declared in any header: {not_declared:?}\n\
         (entry points must be `#[no_mangle] pub extern \"C\" fn` items written out in \
         src/gles/ffi/*.rs or src/egl/ffi*.rs, where build.rs finds them)"
    );
    // The list the C tests use agrees too.
    let listed: BTreeSet<String> = include_str!(concat!(env!("OUT_DIR"), "/entry_points.txt"))
        .lines()
        .filter_map(|l| l.split_whitespace().nth(1).map(str::to_string))
        .collect();
    assert_eq!(
        listed, declared,
        "entry_points.txt disagrees with the headers"
    );
}

const COMPAT_NAMES: &[&str] = &[
    "libGLESv1_CM.so.1",
    "libGLESv1_CM.so",
    "libEGL.so.1",
    "libEGL.so",
];

#[test]
fn compat_names_are_symlinks_to_the_library() {
    let dir = lib_dir();
    let script = Path::new(MANIFEST_DIR).join("scripts/compat-names.sh");
    // Twice: the script must be idempotent.
    for _ in 0..2 {
        run(Command::new("sh").arg(&script).arg(&dir));
    }
    let lib = std::fs::canonicalize(library()).unwrap();
    for name in COMPAT_NAMES {
        let path = dir.join("compat").join(name);
        let meta =
            std::fs::symlink_metadata(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert!(
            meta.file_type().is_symlink(),
            "{} is not a symlink",
            path.display()
        );
        assert_eq!(
            std::fs::read_link(&path).unwrap(),
            Path::new("../libGLES_CM.so"),
            "{} points elsewhere",
            path.display()
        );
        assert_eq!(
            std::fs::canonicalize(&path).unwrap(),
            lib,
            "{} resolves elsewhere",
            path.display()
        );
    }

    // Loading the GL and the EGL name yields one object: same handle, same functions.
    let compat = dir.join("compat");
    let work = dir.join("headers-tests").join("compat_names");
    std::fs::create_dir_all(&work).unwrap();
    let source = work.join("one_object.c");
    std::fs::write(
        &source,
        r#"#include <dlfcn.h>
#include <stdio.h>
int main(int argc, char **argv)
{
    void *gl, *egl;
    (void)argc;
    gl = dlopen(argv[1], RTLD_NOW | RTLD_GLOBAL);
    egl = dlopen(argv[2], RTLD_NOW | RTLD_GLOBAL);
    if (!gl || !egl) {
        printf("dlopen failed: %s\n", dlerror());
        return 1;
    }
    printf("%s\n", gl == egl && dlsym(gl, "glGetError") == dlsym(egl, "glGetError") ? "same" : "different");
    return 0;
}
"#,
    )
    .unwrap();
    let exe = work.join("one_object");
    run(Command::new("cc")
        .arg(&source)
        .arg("-o")
        .arg(&exe)
        .arg("-ldl"));
    let out = run(Command::new(&exe)
        .arg(compat.join("libGLESv1_CM.so.1"))
        .arg(compat.join("libEGL.so.1")));
    assert_eq!(
        out.trim(),
        "same",
        "the compat names load as different objects"
    );

    // Linking against the compat dev names works and runs.
    let entry = Path::new(MANIFEST_DIR).join("c_tests/entry_points.c");
    let exe = work.join("entry_points_compat");
    run(Command::new("cc")
        .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"])
        .arg("-I")
        .arg(Path::new(MANIFEST_DIR).join("include"))
        .arg("-I")
        .arg(OUT_DIR)
        .arg(&entry)
        .arg("-o")
        .arg(&exe)
        .arg("-L")
        .arg(&compat)
        .args(["-lGLESv1_CM", "-lEGL"])
        .arg(format!("-Wl,-rpath,{}", dir.display())));
    run(&mut Command::new(&exe));
}

/// Every exported function is called by some program in `c_tests/` (or by `common.h`, which
/// they all include): directly, or through the address `eglGetProcAddress` returns for its
/// name. `entry_points.c` only takes addresses, so it does not count.
#[test]
fn every_entry_point_is_called_from_c() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("c_tests");
    let mut sources = String::new();
    for e in std::fs::read_dir(&dir).expect("c_tests/").flatten() {
        let path = e.path();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        if (name.ends_with(".c") || name.ends_with(".h")) && name != "entry_points.c" {
            sources.push_str(&std::fs::read_to_string(&path).expect("read C source"));
        }
    }
    let uncalled: Vec<String> = exported()
        .into_iter()
        .filter(|f| f.starts_with("gl") || f.starts_with("egl"))
        .filter(|f| {
            let called = sources.match_indices(f.as_str()).any(|(i, _)| {
                let before = sources[..i].chars().next_back();
                let after = sources[i + f.len()..].chars().next();
                let ident = |c: Option<char>| c.is_some_and(|c| c.is_alphanumeric() || c == '_');
                !ident(before)
                    && (after == Some('(') || (before == Some('"') && after == Some('"')))
            });
            !called
        })
        .collect();
    assert!(
        uncalled.is_empty(),
        "exported but never called from c_tests/: {uncalled:?}"
    );
}
