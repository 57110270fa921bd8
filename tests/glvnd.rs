//! The library as a glvnd EGL vendor (issue 23): `c_tests/glvnd/triangle.c`, the README's
//! triangle, is built against the system's standard headers and linked with glvnd's
//! `libEGL.so.1` and `libGLESv1_CM.so.1` (`-lEGL -lGLESv1_CM`, nothing of ours), then run
//! with `__EGL_VENDOR_LIBRARY_FILENAMES` naming a vendor file whose `library_path` is our
//! built library under its installed vendor name, `libEGL_gles_cm.so.0`. glvnd then loads
//! only us: the strings must be ours (so Mesa cannot pass this test) and the pixels right.
//!
//! Skipped, with a message, where there is no C compiler, no Khronos headers, or the
//! system's `libEGL.so` is not glvnd's (it does not need `libGLdispatch.so.0`);
//! `scripts/mesa-setup.sh` installs them all.

mod common;
use common::{lib_dir, run};

use std::path::{Path, PathBuf};
use std::process::Command;

const MANIFEST_DIR: &str = env!("CARGO_MANIFEST_DIR");

fn compiler() -> String {
    std::env::var("CC").unwrap_or_else(|_| "cc".to_string())
}

/// The system's `libEGL.so` as the compiler would link it, if it is glvnd's.
fn glvnd_missing() -> Option<String> {
    for h in ["EGL/egl.h", "EGL/eglext.h", "GLES/gl.h"] {
        if !Path::new("/usr/include").join(h).exists() {
            return Some(format!("/usr/include/{h} is not installed"));
        }
    }
    let Ok(out) = Command::new(compiler())
        .arg("-print-file-name=libEGL.so")
        .output()
    else {
        return Some(format!("no C compiler ({})", compiler()));
    };
    let egl = PathBuf::from(String::from_utf8_lossy(&out.stdout).trim());
    if !egl.is_absolute() || !egl.exists() {
        return Some("the system has no libEGL.so (libegl-dev)".into());
    }
    let Ok(dynamic) = Command::new("readelf").arg("-d").arg(&egl).output() else {
        return Some("readelf (binutils) is not installed".into());
    };
    if !String::from_utf8_lossy(&dynamic.stdout).contains("[libGLdispatch.so.0]") {
        return Some(format!("{} is not glvnd's", egl.display()));
    }
    let gles = Command::new(compiler())
        .arg("-print-file-name=libGLESv1_CM.so")
        .output()
        .map(|o| PathBuf::from(String::from_utf8_lossy(&o.stdout).trim()))
        .unwrap_or_default();
    if !gles.is_absolute() {
        return Some("the system has no libGLESv1_CM.so (libgles-dev)".into());
    }
    None
}

/// The value after `key: ` on the program's output line starting with `key`.
fn field<'a>(out: &'a str, key: &str) -> &'a str {
    out.lines()
        .find_map(|l| l.strip_prefix(key).and_then(|r| r.strip_prefix(": ")))
        .unwrap_or_else(|| panic!("no `{key}` line in:\n{out}"))
}

fn pixel(out: &str, key: &str) -> Vec<u8> {
    let line = out
        .lines()
        .find_map(|l| l.strip_prefix(key))
        .unwrap_or_else(|| panic!("no `{key}` line in:\n{out}"));
    line.trim_start_matches(" = ")
        .split_whitespace()
        .map(|v| v.parse().expect("a channel value"))
        .collect()
}

#[test]
fn glvnd_loads_us_as_its_egl_vendor_and_dispatches_gles1_to_us() {
    if let Some(why) = glvnd_missing() {
        println!("skipped: {why} (scripts/mesa-setup.sh installs glvnd's libEGL and headers)");
        return;
    }
    let lib = lib_dir();
    let dir = lib.join("glvnd-test");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();

    // As scripts/install.sh lays it out: the vendor name is a link to the one library.
    let vendor = dir.join("libEGL_gles_cm.so.0");
    std::os::unix::fs::symlink(lib.join("libGLES_CM.so"), &vendor).unwrap();
    let json = dir.join("50_gles_cm.json");
    std::fs::write(
        &json,
        format!(
            "{{\n    \"file_format_version\" : \"1.0.0\",\n    \"ICD\" : {{\n        \
             \"library_path\" : \"{}\"\n    }}\n}}\n",
            vendor.display()
        ),
    )
    .unwrap();

    let exe = dir.join("triangle");
    // Only the system's headers and glvnd's libraries: no -I include, no -lGLES_CM.
    run(Command::new(compiler())
        .args(["-std=c99", "-Wall", "-Werror", "-O1"])
        .arg(Path::new(MANIFEST_DIR).join("c_tests/glvnd/triangle.c"))
        .arg("-o")
        .arg(&exe)
        .args(["-lEGL", "-lGLESv1_CM"]));
    let needed = run(Command::new("readelf").arg("-d").arg(&exe));
    assert!(
        needed.contains("[libEGL.so.1]") && needed.contains("[libGLESv1_CM.so.1]"),
        "the program does not link glvnd's libraries:\n{needed}"
    );

    let out = run(Command::new(&exe)
        .env_remove("LD_LIBRARY_PATH")
        .env_remove("LD_PRELOAD")
        .env_remove("EGL_PLATFORM")
        .env_remove("__EGL_VENDOR_LIBRARY_DIRS")
        .env("__EGL_VENDOR_LIBRARY_FILENAMES", &json));
    println!("{out}");

    assert_eq!(field(&out, "EGL_VENDOR"), "gles-cm");
    assert_eq!(field(&out, "GL_VENDOR"), "gles-cm project");
    assert_eq!(field(&out, "GL_RENDERER"), "gles-cm software rasterizer");
    assert!(
        field(&out, "client extensions").contains("EGL_MESA_platform_surfaceless"),
        "glvnd does not list our platform"
    );
    assert_eq!(field(&out, "surfaceless display is the default one"), "yes");
    assert_eq!(pixel(&out, "pixel (32, 16)"), [255, 128, 0, 255]);
    let outside = pixel(&out, "pixel (2, 60)");
    assert!(
        outside[..2] == [0, 0] && (127..=128).contains(&outside[2]) && outside[3] == 255,
        "clear colour expected outside the triangle, got {outside:?}"
    );
    assert_eq!(
        field(&out, "eglGetError after a bad context"),
        "0x3006",
        "EGL_BAD_CONTEXT through glvnd"
    );
}
