//! The C headers: the checked-in `include/` matches what `build.rs` generates, every declared
//! entry point can be taken the address of from C99, C11 and C++11 and links against the
//! library, the headers include cleanly in any order, and the token values agree with the
//! system's Khronos headers where those are installed.

mod common;
use common::lib_dir;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

const MANIFEST_DIR: &str = env!("CARGO_MANIFEST_DIR");
const OUT_DIR: &str = env!("OUT_DIR");

const BLESS: &str = "GLES_CM_BLESS_HEADERS=1 cargo build";

/// The generated headers, as build.rs wrote them for this build.
const GENERATED: &[(&str, &str)] = &[
    (
        "KHR/khrplatform.h",
        include_str!(concat!(env!("OUT_DIR"), "/include/KHR/khrplatform.h")),
    ),
    (
        "GLES/glplatform.h",
        include_str!(concat!(env!("OUT_DIR"), "/include/GLES/glplatform.h")),
    ),
    (
        "GLES/gl.h",
        include_str!(concat!(env!("OUT_DIR"), "/include/GLES/gl.h")),
    ),
    (
        "GLES/glext.h",
        include_str!(concat!(env!("OUT_DIR"), "/include/GLES/glext.h")),
    ),
    (
        "GLES/egl.h",
        include_str!(concat!(env!("OUT_DIR"), "/include/GLES/egl.h")),
    ),
    (
        "EGL/eglplatform.h",
        include_str!(concat!(env!("OUT_DIR"), "/include/EGL/eglplatform.h")),
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

/// `header name` per exported entry point.
const ENTRY_POINTS: &str = include_str!(concat!(env!("OUT_DIR"), "/entry_points.txt"));

fn include_dir() -> PathBuf {
    Path::new(MANIFEST_DIR).join("include")
}

/// A scratch directory for compiled C programs.
fn scratch(name: &str) -> PathBuf {
    let dir = lib_dir().join("headers-tests").join(name);
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir
}

fn run(cmd: &mut Command) -> String {
    let out = cmd
        .output()
        .unwrap_or_else(|e| panic!("cannot run {cmd:?}: {e}"));
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(
        out.status.success(),
        "{cmd:?} failed ({}):\n{stdout}\n{}\n(if headers changed, regenerate them with `{BLESS}`)",
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
    stdout
}

#[test]
fn checked_in_headers_match_generated() {
    let mut stale = Vec::new();
    for (rel, fresh) in GENERATED {
        let path = include_dir().join(rel);
        match std::fs::read_to_string(&path) {
            Ok(text) if text == *fresh => {}
            Ok(_) => stale.push(format!("include/{rel} differs from the generated header")),
            Err(e) => stale.push(format!("include/{rel}: {e}")),
        }
    }
    assert!(
        stale.is_empty(),
        "{}\nThe headers are generated from the Rust sources by build.rs. Regenerate them with\n    \
         {BLESS}\n(or `make headers`) and commit include/.",
        stale.join("\n")
    );
}

/// The compilers and flags every C test runs under.
fn compilers() -> Vec<(&'static str, Vec<&'static str>)> {
    let strict = ["-Wall", "-Wextra", "-Werror", "-pedantic"];
    let mut v = Vec::new();
    for std in ["-std=c99", "-std=c11"] {
        let mut args = vec![std];
        args.extend(strict);
        v.push(("cc", args));
    }
    let mut args = vec!["-x", "c++", "-std=c++11"];
    args.extend(strict);
    v.push(("c++", args));
    v
}

fn compile_and_run(name: &str, source: &Path, extra: &[&str]) -> Vec<String> {
    let lib = lib_dir();
    let dir = scratch(name);
    let mut outputs = Vec::new();
    for (i, (compiler, flags)) in compilers().into_iter().enumerate() {
        for (j, defines) in [
            &[][..],
            &["-DGL_GLEXT_PROTOTYPES", "-DEGL_EGLEXT_PROTOTYPES"][..],
        ]
        .into_iter()
        .enumerate()
        {
            let exe = dir.join(format!("{name}_{i}_{j}"));
            let mut cmd = Command::new(compiler);
            cmd.args(&flags)
                .args(defines)
                .arg("-I")
                .arg(include_dir())
                .arg("-I")
                .arg(OUT_DIR)
                .arg(source)
                .arg("-o")
                .arg(&exe)
                .arg("-L")
                .arg(&lib)
                .arg("-lGLES_CM")
                .arg(format!("-Wl,-rpath,{}", lib.display()))
                .args(extra);
            run(&mut cmd);
            let out = run(Command::new(&exe).env("LD_LIBRARY_PATH", &lib));
            outputs.push(format!("{compiler} {flags:?} {defines:?}: {out}"));
        }
    }
    outputs
}

#[test]
fn every_entry_point_links_from_c_and_cxx() {
    let source = Path::new(MANIFEST_DIR).join("c_tests/entry_points.c");
    let total = ENTRY_POINTS.lines().count();
    let core = ENTRY_POINTS
        .lines()
        .filter(|l| l.starts_with("GLES/gl.h ") || l.starts_with("EGL/egl.h "))
        .count();
    assert!(core > 0, "no entry points declared in gl.h / egl.h");
    let outputs = compile_and_run("entry_points", &source, &[]);
    for (k, out) in outputs.iter().enumerate() {
        // Odd runs define the *_EXT_PROTOTYPES macros and see every entry point.
        let expect = if k % 2 == 1 { total } else { core };
        assert!(
            out.contains(&format!("entry points: {expect}\n")),
            "expected {expect} entry points, got: {out}"
        );
    }
}

#[test]
fn headers_include_in_any_order_and_repeatedly() {
    let dir = scratch("include_order");
    let source = dir.join("include_order.c");
    std::fs::write(
        &source,
        r#"/* Every header twice, dependents before their dependencies. */
#include <EGL/eglext.h>
#include <GLES/glext.h>
#include <EGL/egl.h>
#include <GLES/gl.h>
#include <EGL/eglplatform.h>
#include <GLES/glplatform.h>
#include <KHR/khrplatform.h>
#include <GLES/gl.h>
#include <GLES/glext.h>
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <stdio.h>

#ifndef GL_VERSION_ES_CM_1_0
#error GL_VERSION_ES_CM_1_0
#endif
#ifndef GL_VERSION_ES_CM_1_1
#error GL_VERSION_ES_CM_1_1
#endif
#ifndef GL_OES_read_format
#error GL_OES_read_format
#endif
#if !defined(EGL_VERSION_1_0) || !defined(EGL_VERSION_1_4)
#error EGL_VERSION
#endif
#if !defined(GL_API) || !defined(GL_APIENTRY) || !defined(GL_APIENTRYP)
#error GL_API
#endif
#if !defined(EGLAPI) || !defined(EGLAPIENTRY) || !defined(EGLAPIENTRYP)
#error EGLAPI
#endif

typedef char check_fixed[sizeof(GLfixed) == 4 ? 1 : -1];
typedef char check_egl_int[sizeof(EGLint) == 4 ? 1 : -1];
typedef char check_intptr[sizeof(GLintptr) == sizeof(void *) ? 1 : -1];
typedef char check_sizeiptr[sizeof(GLsizeiptr) == sizeof(void *) ? 1 : -1];

int main(void)
{
    EGLContext ctx = EGL_NO_CONTEXT;
    EGLDisplay dpy = EGL_NO_DISPLAY;
    EGLSurface surf = EGL_NO_SURFACE;
    EGLNativeDisplayType native = EGL_DEFAULT_DISPLAY;
    EGLint dont_care = EGL_DONT_CARE;
    NativeWindowType win = 0;
    khronos_int32_t k = 0;
    GLenum e = GL_TEXTURE_2D;
    GLbitfield mask = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT;
    GLboolean yes = GL_TRUE;
    (void)ctx; (void)dpy; (void)surf; (void)native; (void)win; (void)k;
    printf("%d %u %u %u\n", (int)dont_care, e, mask, (unsigned)yes);
    return 0;
}
"#,
    )
    .expect("write include_order.c");
    for out in compile_and_run("include_order", &source, &[]) {
        assert!(out.contains("-1 3553 16640 1"), "unexpected output: {out}");
    }
}

/// `NAME -> value` of every object-like `#define` in a header.
fn defines(text: &str) -> BTreeMap<String, String> {
    let mut map = BTreeMap::new();
    for line in text.lines() {
        let Some(rest) = line.strip_prefix("#define ") else {
            continue;
        };
        let mut parts = rest.splitn(2, char::is_whitespace);
        let name = parts.next().unwrap_or_default();
        if name.contains('(') {
            continue;
        }
        let value: String = parts
            .next()
            .unwrap_or_default()
            .split_whitespace()
            .collect();
        map.insert(name.to_string(), value);
    }
    map
}

fn parse_int(v: &str) -> Option<i64> {
    let v = v.trim_end_matches(['u', 'U', 'l', 'L']);
    match v.strip_prefix("0x").or_else(|| v.strip_prefix("0X")) {
        Some(hex) => i64::from_str_radix(hex, 16).ok(),
        None => v.parse().ok(),
    }
}

/// Every token both our headers and the system's (Mesa's copies of the Khronos registry
/// headers, when installed) define must have the same value. Skipped without them.
#[test]
fn token_values_agree_with_system_khronos_headers() {
    let pairs = [
        ("GLES/gl.h", "/usr/include/GLES/gl.h"),
        ("GLES/glext.h", "/usr/include/GLES/glext.h"),
        ("EGL/egl.h", "/usr/include/EGL/egl.h"),
        ("EGL/eglext.h", "/usr/include/EGL/eglext.h"),
    ];
    let mut system = BTreeMap::new();
    for (_, sys) in pairs {
        match std::fs::read_to_string(sys) {
            Ok(text) => system.extend(defines(&text)),
            Err(_) => {
                eprintln!("{sys} not installed; skipping the comparison");
                return;
            }
        }
    }
    let mut compared = 0;
    let mut wrong = Vec::new();
    for (ours, _) in pairs {
        let text = GENERATED.iter().find(|(r, _)| *r == ours).unwrap().1;
        for (name, value) in defines(text) {
            let Some(theirs) = system.get(&name) else {
                continue;
            };
            compared += 1;
            let same = match (parse_int(&value), parse_int(theirs)) {
                (Some(a), Some(b)) => a == b,
                _ => value == *theirs,
            };
            if !same {
                wrong.push(format!(
                    "{ours}: {name} is {value}, the registry says {theirs}"
                ));
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    assert!(compared > 300, "only {compared} tokens compared");
}

/// Our `gl.h` defines every name the registry's ES 1.1 `gl.h` does, and our `egl.h` every
/// name of the registry's EGL 1.0-1.4 blocks. Skipped without the system headers.
#[test]
fn core_headers_are_complete() {
    let ours_gl = defines(GENERATED.iter().find(|(r, _)| *r == "GLES/gl.h").unwrap().1);
    let ours_egl = defines(GENERATED.iter().find(|(r, _)| *r == "EGL/egl.h").unwrap().1);
    let (Ok(sys_gl), Ok(sys_egl)) = (
        std::fs::read_to_string("/usr/include/GLES/gl.h"),
        std::fs::read_to_string("/usr/include/EGL/egl.h"),
    ) else {
        eprintln!("system Khronos headers not installed; skipping");
        return;
    };
    let mut missing: Vec<String> = defines(&sys_gl)
        .into_keys()
        .filter(|n| n.starts_with("GL_") && !ours_gl.contains_key(n))
        .collect();
    // Every block of the system egl.h, EGL 1.5's included.
    missing.extend(defines(&sys_egl).into_keys().filter(|n| {
        n.starts_with("EGL_") && n != "EGL_EGL_PROTOTYPES" && !ours_egl.contains_key(n)
    }));
    assert!(missing.is_empty(), "missing from our headers: {missing:?}");
}

/// The names a header declares: object-like macros, typedefs, functions and structs.
#[derive(Default)]
struct Declared {
    typedefs: BTreeMap<String, String>,
    functions: BTreeMap<String, String>,
    structs: Vec<String>,
}

/// The name a one-line `typedef` declares: `(... *NAME)` for function pointer types, else
/// the last identifier.
fn typedef_name(line: &str) -> Option<String> {
    let body = line.strip_prefix("typedef ")?.trim_end_matches(';');
    let ident = |s: &str| {
        s.trim_matches(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .rsplit(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .next()
            .map(str::to_string)
    };
    match body.find('(') {
        Some(open) => {
            let close = open + body[open..].find(')')?;
            ident(&body[open + 1..close])
        }
        None => ident(body),
    }
}

fn declarations(text: &str) -> Declared {
    let mut d = Declared::default();
    for line in text.lines().map(str::trim) {
        if line.starts_with("typedef ") && line.ends_with(';') {
            if let Some(name) = typedef_name(line) {
                d.typedefs.insert(name, line.to_string());
            }
        } else if let Some(decl) = line
            .strip_prefix("GL_API ")
            .or_else(|| line.strip_prefix("EGLAPI "))
        {
            if let Some(open) = decl.find(" (") {
                let name = decl[..open].rsplit([' ', '*']).next().unwrap_or_default();
                d.functions.insert(name.to_string(), line.to_string());
            }
        } else if let Some(rest) = line.strip_prefix("struct ") {
            let name: String = rest
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect();
            d.structs.push(name);
        }
    }
    d
}

/// Issue 23: `GLES/glext.h`, `EGL/eglext.h` and `GLES/egl.h` declare every name the system's
/// Khronos headers (Debian's libgles-dev / libegl-dev) do, with the same value, and every
/// typedef and prototype of theirs compiles after ours (C11 accepts a repeated typedef or
/// prototype only when the types are the same). Skipped without the system headers.
#[test]
fn extension_headers_declare_what_the_khronos_ones_do() {
    let pairs = [
        ("GLES/glext.h", "/usr/include/GLES/glext.h"),
        ("EGL/eglext.h", "/usr/include/EGL/eglext.h"),
        ("GLES/egl.h", "/usr/include/GLES/egl.h"),
    ];
    let mut missing = Vec::new();
    let mut wrong = Vec::new();
    let mut redeclared = String::new();
    let mut counts = (0, 0, 0);
    // A type may come from another of our headers (GLchar is in gl.h, theirs in glext.h).
    let all_typedefs: Vec<String> = GENERATED
        .iter()
        .flat_map(|(_, text)| declarations(text).typedefs.into_keys())
        .collect();
    for (ours, sys) in pairs {
        let Ok(theirs) = std::fs::read_to_string(sys) else {
            println!(
                "skipped: {sys} not installed (libgles-dev, libegl-dev; scripts/mesa-setup.sh)"
            );
            return;
        };
        let text = GENERATED.iter().find(|(r, _)| *r == ours).unwrap().1;
        let (our_defs, their_defs) = (defines(text), defines(&theirs));
        for (name, value) in &their_defs {
            counts.0 += 1;
            match our_defs.get(name) {
                None => missing.push(format!("{ours}: #define {name}")),
                Some(v) => {
                    let same = match (parse_int(v), parse_int(value)) {
                        (Some(a), Some(b)) => a == b,
                        _ => v.split_whitespace().eq(value.split_whitespace()),
                    };
                    if !same {
                        wrong.push(format!("{ours}: {name} is {v}, Khronos says {value}"));
                    }
                }
            }
        }
        let (mine, khronos) = (declarations(text), declarations(&theirs));
        for (name, line) in &khronos.typedefs {
            counts.1 += 1;
            if !mine.typedefs.contains_key(name) && !all_typedefs.contains(name) {
                missing.push(format!("{ours}: typedef {name}"));
            }
            redeclared += line;
            redeclared += "\n";
        }
        for (name, line) in &khronos.functions {
            counts.2 += 1;
            if !mine.functions.contains_key(name) {
                missing.push(format!("{ours}: {name}"));
            }
            redeclared += line;
            redeclared += "\n";
        }
        for name in &khronos.structs {
            if !mine.structs.contains(name) {
                missing.push(format!("{ours}: struct {name}"));
            }
        }
    }
    assert!(missing.is_empty(), "missing: {missing:#?}");
    assert!(wrong.is_empty(), "{wrong:#?}");
    println!(
        "{} macros, {} typedefs, {} functions compared",
        counts.0, counts.1, counts.2
    );
    assert!(
        counts.0 > 900 && counts.2 > 250,
        "too few compared: {counts:?}"
    );

    let dir = scratch("khronos_signatures");
    let source = dir.join("signatures.c");
    std::fs::write(
        &source,
        format!(
            "#define GL_GLEXT_PROTOTYPES 1\n#define EGL_EGLEXT_PROTOTYPES 1\n\
             #include <GLES/egl.h>\n#include <GLES/glext.h>\n#include <EGL/eglext.h>\n\
             /* The Khronos headers' declarations, repeated. */\n{redeclared}\
             int main(void) {{ return 0; }}\n"
        ),
    )
    .unwrap();
    for (compiler, std) in [("cc", "-std=c11"), ("c++", "-std=c++11")] {
        let mut cmd = Command::new(compiler);
        if compiler == "c++" {
            cmd.args(["-x", "c++"]);
        }
        run(cmd
            .args([std, "-Wall", "-Werror", "-fsyntax-only", "-I"])
            .arg(include_dir())
            .arg(&source));
    }
}
