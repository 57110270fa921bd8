//! The install step as a packager runs it: `scripts/install.sh PREFIX` with `DESTDIR` stages a
//! stripped library (debug info split into `.debug`), its versioned SONAME and compatibility
//! names, the glvnd vendor name and vendor file, private headers, pkg-config files with the API versions, and `m3g`. The
//! README's example program, built with `pkg-config --cflags --libs glesv1_cm egl` against
//! the staged tree alone, then runs and prints the right pixel; `--uninstall` removes every
//! file again. Skipped (with a message) where pkg-config or binutils are not installed.

mod common;
use common::{lib_dir, run};

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

const MANIFEST_DIR: &str = env!("CARGO_MANIFEST_DIR");
const PREFIX: &str = "/opt/gles-cm-install-test";

fn tools_missing() -> Option<&'static str> {
    ["pkg-config", "objcopy", "strip", "readelf"]
        .into_iter()
        .find(|t| Command::new(t).arg("--version").output().is_err())
}

/// The cargo target directory the tests run from (`target/<profile>/deps/install-…`), so
/// the script is exercised through `CARGO_TARGET_DIR` rather than its default. The script
/// installs `release/m3g` from there: the workspace's `cargo test` builds it with the
/// `m3g-cli` tests; a run of this package alone builds it here.
fn target_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("current_exe");
    let target = exe.ancestors().nth(3).expect("target dir").to_path_buf();
    if !target.join("release/m3g").exists() {
        run(Command::new(env!("CARGO"))
            .args(["build", "--release", "-p", "m3g-cli", "--bin", "m3g"])
            .current_dir(MANIFEST_DIR)
            .env("CARGO_TARGET_DIR", &target));
    }
    target
}

fn install(destdir: &Path, extra_env: &[(&str, &str)], args: &[&str]) -> String {
    let mut cmd = Command::new("sh");
    cmd.arg(Path::new(MANIFEST_DIR).join("scripts/install.sh"))
        .args(args)
        .arg(PREFIX)
        .env("DESTDIR", destdir)
        .env("CARGO_TARGET_DIR", target_dir())
        .env("GLES_CM_LIB", lib_dir().join("libGLES_CM.so"))
        .env_remove("STRIP")
        .env_remove("COMPAT")
        .env_remove("GLVND");
    for (k, v) in extra_env {
        cmd.env(k, v);
    }
    run(&mut cmd)
}

/// Every file and link under `root`: relative path to size (files) or `-> target` (links).
fn tree(root: &Path) -> BTreeMap<String, String> {
    fn walk(root: &Path, dir: &Path, out: &mut BTreeMap<String, String>) {
        for e in std::fs::read_dir(dir).into_iter().flatten().flatten() {
            let p = e.path();
            let rel = p.strip_prefix(root).unwrap().to_string_lossy().into_owned();
            let meta = std::fs::symlink_metadata(&p).unwrap();
            if meta.file_type().is_symlink() {
                let t = std::fs::read_link(&p).unwrap();
                out.insert(rel, format!("-> {}", t.display()));
            } else if meta.is_dir() {
                walk(root, &p, out);
            } else {
                out.insert(rel, meta.len().to_string());
            }
        }
    }
    let mut out = BTreeMap::new();
    walk(root, root, &mut out);
    out
}

fn sections(file: &Path) -> String {
    run(Command::new("readelf").arg("-S").arg("-W").arg(file))
}

/// The C program of the README's "Quick start for C".
fn readme_program() -> String {
    let readme = std::fs::read_to_string(Path::new(MANIFEST_DIR).join("README.md")).unwrap();
    let after = readme
        .split("A complete program")
        .nth(1)
        .expect("README has its complete program");
    let start = after.find("```c\n").expect("a C block") + 5;
    let len = after[start..].find("```").expect("block end");
    after[start..start + len].to_string()
}

fn pkg_config(destdir: &Path, args: &[&str]) -> String {
    let pc = destdir.join(&PREFIX[1..]).join("lib/pkgconfig");
    run(Command::new("pkg-config")
        .args(args)
        .env("PKG_CONFIG_LIBDIR", &pc)
        .env("PKG_CONFIG_PATH", &pc)
        .env("PKG_CONFIG_SYSROOT_DIR", destdir))
    .trim()
    .to_string()
}

#[test]
fn staged_install_is_stripped_versioned_private_and_builds_the_readme_program() {
    if let Some(t) = tools_missing() {
        println!("skipped: {t} is not installed");
        return;
    }
    let destdir = lib_dir().join("install-test-destdir");
    let _ = std::fs::remove_dir_all(&destdir);
    install(&destdir, &[], &[]);
    let root = destdir.join(&PREFIX[1..]);

    let files = tree(&root);
    println!("installed under DESTDIR{PREFIX}:");
    for (k, v) in &files {
        println!("  {k:44} {v}");
    }
    let names: Vec<&str> = files.keys().map(String::as_str).collect();
    let mut expected = vec![
        "bin/.debug/m3g.debug",
        "bin/m3g",
        "lib/.debug/libGLES_CM.so.1.debug",
        "lib/libEGL.so",
        "lib/libEGL.so.1",
        "lib/libEGL_gles_cm.so.0",
        "lib/libGLES_CM.so",
        "lib/libGLES_CM.so.1",
        "lib/libGLESv1_CM.so",
        "lib/libGLESv1_CM.so.1",
        "lib/pkgconfig/egl.pc",
        "lib/pkgconfig/glesv1_cm.pc",
        "share/glvnd/egl_vendor.d/50_gles_cm.json",
    ];
    let headers: Vec<String> = ["GLES", "EGL", "KHR"]
        .iter()
        .flat_map(|d| std::fs::read_dir(Path::new(MANIFEST_DIR).join("include").join(d)))
        .flatten()
        .flatten()
        .map(|e| {
            let p = e.path();
            let dir = p.parent().unwrap().file_name().unwrap().to_string_lossy();
            format!(
                "include/gles-cm/{dir}/{}",
                p.file_name().unwrap().to_string_lossy()
            )
        })
        .collect();
    assert!(headers.len() >= 7, "{headers:?}");
    expected.extend(headers.iter().map(String::as_str));
    expected.sort();
    assert_eq!(names, expected);

    for link in [
        "libGLES_CM.so",
        "libGLESv1_CM.so.1",
        "libGLESv1_CM.so",
        "libEGL.so.1",
        "libEGL.so",
        "libEGL_gles_cm.so.0",
    ] {
        assert_eq!(
            files[&format!("lib/{link}")],
            "-> libGLES_CM.so.1",
            "{link}"
        );
    }

    // glvnd's vendor file names the vendor library where it will be installed (glvnd's
    // format, as its own vendors' files have it).
    let json =
        std::fs::read_to_string(root.join("share/glvnd/egl_vendor.d/50_gles_cm.json")).unwrap();
    assert!(
        json.contains("\"file_format_version\" : \"1.0.0\""),
        "{json}"
    );
    assert!(
        json.contains(&format!(
            "\"library_path\" : \"{PREFIX}/lib/libEGL_gles_cm.so.0\""
        )),
        "{json}"
    );

    // Stripped, with the debug info beside it and linked.
    let lib = root.join("lib/libGLES_CM.so.1");
    let lib_sections = sections(&lib);
    assert!(
        !lib_sections.contains(".debug_info"),
        "library not stripped"
    );
    assert!(!lib_sections.contains(".symtab"), "library keeps .symtab");
    assert!(lib_sections.contains(".gnu_debuglink"), "no debug link");
    let debug = root.join("lib/.debug/libGLES_CM.so.1.debug");
    assert!(
        sections(&debug).contains(".debug_info"),
        "debug file holds no debug info"
    );
    let link = run(Command::new("readelf")
        .args(["--string-dump=.gnu_debuglink"])
        .arg(&lib));
    assert!(link.contains("libGLES_CM.so.1.debug"), "{link}");
    let source_len = std::fs::metadata(lib_dir().join("libGLES_CM.so"))
        .unwrap()
        .len();
    assert!(
        std::fs::metadata(&lib).unwrap().len() < source_len / 2,
        "the stripped library is not much smaller than the build's {source_len} bytes"
    );
    let dynamic = run(Command::new("readelf").arg("-d").arg(&lib));
    assert!(dynamic.contains("[libGLES_CM.so.1]"), "{dynamic}");
    assert!(!sections(&root.join("bin/m3g")).contains(".debug_info"));

    // pkg-config: API versions, the package version apart, the private include directory.
    assert_eq!(pkg_config(&destdir, &["--modversion", "glesv1_cm"]), "1.1");
    assert_eq!(pkg_config(&destdir, &["--modversion", "egl"]), "1.5");
    pkg_config(&destdir, &["--atleast-version=1.5", "egl"]);
    pkg_config(&destdir, &["--atleast-version=1.1", "glesv1_cm"]);
    assert_eq!(
        pkg_config(&destdir, &["--variable=gles_cm_version", "egl"]),
        env!("CARGO_PKG_VERSION")
    );
    let flags = pkg_config(&destdir, &["--cflags", "--libs", "glesv1_cm", "egl"]);
    assert!(
        flags.contains(&format!("{}/include/gles-cm", root.display())),
        "{flags}"
    );

    // The README's program, from the staged tree alone.
    let work = destdir.join("work");
    std::fs::create_dir_all(&work).unwrap();
    let src = work.join("app.c");
    std::fs::write(&src, readme_program()).unwrap();
    let exe = work.join("app");
    run(
        Command::new(std::env::var("CC").unwrap_or_else(|_| "cc".into()))
            .args(["-std=c99", "-Wall", "-Werror"])
            .arg(&src)
            .arg("-o")
            .arg(&exe)
            .args(flags.split_whitespace()),
    );
    let needed = run(Command::new("readelf").arg("-d").arg(&exe));
    assert!(
        needed.contains("Shared library: [libGLES_CM.so.1]"),
        "the program does not ask for the versioned name:\n{needed}"
    );
    let out = run(Command::new(&exe).env("LD_LIBRARY_PATH", root.join("lib")));
    println!("README program: {out}");
    assert!(out.contains("pixel (32, 16) = 255 128 0 255"), "{out}");

    // The installed m3g runs (no arguments: usage, exit status 2).
    let m3g = Command::new(root.join("bin/m3g")).output().unwrap();
    assert_eq!(m3g.status.code(), Some(2), "{m3g:?}");

    std::fs::remove_dir_all(&work).unwrap();
    install(&destdir, &[], &["--uninstall"]);
    let left = tree(&destdir);
    assert!(left.is_empty(), "left after uninstall: {left:?}");
}

#[test]
fn strip_0_and_compat_0_keep_the_debug_info_and_leave_out_the_compatibility_names() {
    if let Some(t) = tools_missing() {
        println!("skipped: {t} is not installed");
        return;
    }
    let destdir = lib_dir().join("install-test-nostrip");
    let _ = std::fs::remove_dir_all(&destdir);
    install(&destdir, &[("STRIP", "0"), ("COMPAT", "0")], &[]);
    let root = destdir.join(&PREFIX[1..]);
    let files = tree(&root);
    assert!(!files.keys().any(|k| k.contains(".debug")), "{files:?}");
    assert!(!files.keys().any(|k| k.contains("libEGL.so")), "{files:?}");
    assert!(
        !files.keys().any(|k| k.contains("libGLESv1_CM")),
        "{files:?}"
    );
    // What a machine with glvnd installs: the vendor, not the names glvnd owns.
    assert_eq!(files["lib/libEGL_gles_cm.so.0"], "-> libGLES_CM.so.1");
    assert!(files.contains_key("share/glvnd/egl_vendor.d/50_gles_cm.json"));
    assert!(sections(&root.join("lib/libGLES_CM.so.1")).contains(".debug_info"));
    // Another implementation's libEGL.so.1 in the way is not ours to uninstall.
    std::fs::write(root.join("lib/libEGL.so.1"), b"someone else's").unwrap();
    install(&destdir, &[], &["--uninstall"]);
    assert_eq!(
        tree(&destdir).into_keys().collect::<Vec<_>>(),
        [format!("{}/lib/libEGL.so.1", &PREFIX[1..])]
    );
}

#[test]
fn glvnd_0_leaves_out_the_vendor() {
    if let Some(t) = tools_missing() {
        println!("skipped: {t} is not installed");
        return;
    }
    let destdir = lib_dir().join("install-test-noglvnd");
    let _ = std::fs::remove_dir_all(&destdir);
    install(&destdir, &[("STRIP", "0"), ("GLVND", "0")], &[]);
    let files = tree(&destdir.join(&PREFIX[1..]));
    assert!(!files.keys().any(|k| k.contains("glvnd")), "{files:?}");
    assert!(!files.keys().any(|k| k.contains("gles_cm.so")), "{files:?}");
    assert_eq!(files["lib/libEGL.so.1"], "-> libGLES_CM.so.1");
    install(&destdir, &[], &["--uninstall"]);
    assert!(tree(&destdir).is_empty());
}
