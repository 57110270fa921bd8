//! Builds every program in `c_tests/` with the system C compiler against `include/` and the
//! library cargo just built, runs it, and checks its exit status (each program asserts its
//! own pixels and errors through `c_tests/common.h`). Images a program saves with `ct_save`
//! land as PNG in `target/c_tests/<program>/`.
//!
//! Modes, chosen by environment variables:
//! - `GLES_CM_DIFF=mesa`: also builds each program against Mesa's `libEGL`/`libGLESv1_CM`
//!   (installed by `scripts/mesa-setup.sh`), requires it to pass there too, and compares every saved image
//!   with ours (tolerance in [`DIFF_TOLERANCE`]). Programs marked `ct:no-diff` are skipped.
//!   Mesa's default driver, llvmpipe, runs them; `GLES_CM_DIFF=softpipe` does the same with
//!   `GALLIUM_DRIVER=softpipe` in the Mesa run's environment (see `softpipe()`). Softpipe
//!   snaps to 4 subpixel bits and settles pixel centers exactly on an edge and aliased line
//!   ends its own way (both left to the implementation), so images of programs marked
//!   `ct:softpipe-edges` are reported but not held to the tolerance there; their checks
//!   still must pass.
//! - `GLES_CM_VALGRIND=1`: runs each program (ours only) under valgrind's memcheck; any
//!   error, or a definite leak, fails the program (`c_tests/valgrind.supp` says which
//!   reports are not leaks, and why).
//! - `CT_FILTER=substring`: only programs whose name contains it.
//!
//! `dropin_binary_runs_on_mesa_and_ours` builds `c_tests/dropin/triangle.c` against the
//! system's standard headers and Mesa's libraries, then runs that one binary on Mesa and on
//! ours through the compatibility names. It is skipped (with a message) where Mesa's
//! development files are not installed.

mod common;
use common::lib_dir;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

const MANIFEST_DIR: &str = env!("CARGO_MANIFEST_DIR");
const OUT_DIR: &str = env!("OUT_DIR");

/// A program may take this long (valgrind included) before it counts as hung.
const TIMEOUT: Duration = Duration::from_secs(300);

/// How far an image of ours may be from Mesa llvmpipe's: no more than this fraction of pixels
/// may differ by more than [`DIFF_STEPS`] in any channel. Both renderers use 8 subpixel bits
/// and a top-left rule, but interpolation and rounding differ by a step or two, and edge
/// pixels of slanted triangles may fall either way; Mesa's own two drivers disagree on 0.23 %
/// of pixels of a dense triangle field (measured on Mesa 22.3).
const DIFF_TOLERANCE: f64 = 0.01;
const DIFF_STEPS: u8 = 2;

fn c_tests_dir() -> PathBuf {
    Path::new(MANIFEST_DIR).join("c_tests")
}

fn out_root() -> PathBuf {
    let profile = lib_dir().parent().expect("profile dir").to_path_buf();
    profile.parent().expect("target dir").join("c_tests")
}

struct Program {
    name: String,
    source: PathBuf,
    text: String,
}

impl Program {
    fn marked(&self, marker: &str) -> bool {
        self.text.contains(marker)
    }
}

/// Every `c_tests/*.c` except those built elsewhere (`ct:headers-only`), filtered by
/// `CT_FILTER`.
fn programs() -> Vec<Program> {
    let filter = std::env::var("CT_FILTER").unwrap_or_default();
    let mut v: Vec<Program> = std::fs::read_dir(c_tests_dir())
        .expect("c_tests/")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "c"))
        .map(|source| {
            let name = source.file_stem().unwrap().to_string_lossy().into_owned();
            let text = std::fs::read_to_string(&source).expect("read C source");
            Program { name, source, text }
        })
        .filter(|p| !p.marked("ct:headers-only") && p.name.contains(&filter))
        .collect();
    v.sort_by(|a, b| a.name.cmp(&b.name));
    v
}

fn compiler() -> String {
    std::env::var("CC").unwrap_or_else(|_| "cc".into())
}

/// The strict flags every program must compile under.
const CFLAGS: &[&str] = &[
    "-std=c99",
    "-Wall",
    "-Wextra",
    "-Werror",
    "-pedantic",
    "-g",
    "-pthread",
];

/// Which library a program is linked against.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Implementation {
    Ours,
    Mesa,
}

fn compile(p: &Program, imp: Implementation, exe: &Path) -> Result<(), String> {
    let mut cmd = Command::new(compiler());
    cmd.args(CFLAGS)
        .arg("-I")
        .arg(Path::new(MANIFEST_DIR).join("include"))
        .arg("-I")
        .arg(c_tests_dir())
        .arg("-I")
        .arg(OUT_DIR)
        .arg(&p.source)
        .arg("-o")
        .arg(exe);
    match imp {
        Implementation::Ours => {
            let lib = lib_dir();
            cmd.arg("-L")
                .arg(&lib)
                .arg("-lGLES_CM")
                .arg(format!("-Wl,-rpath,{}", lib.display()));
        }
        Implementation::Mesa => {
            cmd.args(["-lEGL", "-lGLESv1_CM"]);
        }
    }
    cmd.arg("-lm");
    let out = cmd
        .output()
        .map_err(|e| format!("cannot run {}: {e}", compiler()))?;
    if out.status.success() {
        Ok(())
    } else {
        Err(format!(
            "compile failed:\n{}",
            String::from_utf8_lossy(&out.stderr)
        ))
    }
}

/// Runs `cmd` to completion or [`TIMEOUT`], capturing its output.
fn run_with_timeout(mut cmd: Command) -> Result<Output, String> {
    cmd.stdout(Stdio::piped()).stderr(Stdio::piped());
    // A just-written executable can still be open in a compiler another thread started
    // (ETXTBSY) for a moment: retry briefly.
    let mut tries = 0;
    let mut child = loop {
        match cmd.spawn() {
            Ok(c) => break c,
            Err(e) if e.raw_os_error() == Some(26) && tries < 50 => {
                tries += 1;
                std::thread::sleep(Duration::from_millis(20));
            }
            Err(e) => return Err(format!("cannot start: {e}")),
        }
    };
    // Drain the pipes on threads so a chatty program cannot block on a full pipe.
    let mut stdout = child.stdout.take().unwrap();
    let mut stderr = child.stderr.take().unwrap();
    let out_t = std::thread::spawn(move || {
        let mut b = Vec::new();
        std::io::Read::read_to_end(&mut stdout, &mut b).ok();
        b
    });
    let err_t = std::thread::spawn(move || {
        let mut b = Vec::new();
        std::io::Read::read_to_end(&mut stderr, &mut b).ok();
        b
    });
    let start = Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().map_err(|e| e.to_string())? {
            break s;
        }
        if start.elapsed() > TIMEOUT {
            child.kill().ok();
            child.wait().ok();
            return Err(format!("timed out after {TIMEOUT:?}"));
        }
        std::thread::sleep(Duration::from_millis(10));
    };
    Ok(Output {
        status,
        stdout: out_t.join().unwrap_or_default(),
        stderr: err_t.join().unwrap_or_default(),
    })
}

/// True when `GLES_CM_DIFF=softpipe`: the differential run uses Mesa's softpipe driver
/// instead of its default, llvmpipe.
fn softpipe() -> bool {
    std::env::var("GLES_CM_DIFF").is_ok_and(|v| v == "softpipe")
}

fn valgrind() -> bool {
    std::env::var("GLES_CM_VALGRIND").is_ok_and(|v| v == "1")
}

/// Builds and runs `p` against `imp`, its images in `out`. Returns its stdout.
fn build_and_run(p: &Program, imp: Implementation, out: &Path) -> Result<String, String> {
    std::fs::create_dir_all(out).map_err(|e| e.to_string())?;
    for e in std::fs::read_dir(out).into_iter().flatten().flatten() {
        std::fs::remove_file(e.path()).ok();
    }
    let exe = out.join(&p.name);
    compile(p, imp, &exe)?;
    let mut cmd = if valgrind() && imp == Implementation::Ours {
        let mut c = Command::new("valgrind");
        c.args([
            "--error-exitcode=97",
            "--leak-check=full",
            "--errors-for-leak-kinds=definite",
            "--show-leak-kinds=definite",
            "--quiet",
        ])
        .arg(format!(
            "--suppressions={}",
            c_tests_dir().join("valgrind.supp").display()
        ))
        .arg(&exe);
        c
    } else {
        Command::new(&exe)
    };
    cmd.env("CT_OUT", out);
    // cargo runs tests with its own LD_LIBRARY_PATH, which can name an older copy of the
    // library (`target/<profile>/libGLES_CM.so`) ahead of the rpath: name the one under test.
    match imp {
        Implementation::Ours => cmd.env("LD_LIBRARY_PATH", lib_dir()),
        Implementation::Mesa => {
            cmd.env_remove("LD_LIBRARY_PATH")
                .env("EGL_PLATFORM", "surfaceless");
            if softpipe() {
                cmd.env("GALLIUM_DRIVER", "softpipe");
            }
            &mut cmd
        }
    };
    let o = run_with_timeout(cmd)?;
    let stdout = String::from_utf8_lossy(&o.stdout).into_owned();
    let stderr = String::from_utf8_lossy(&o.stderr).into_owned();
    if !o.status.success() {
        return Err(format!("exited with {}\n{stdout}{stderr}", o.status));
    }
    pam_to_png(out)?;
    Ok(stdout)
}

/// Reads a `P7` RGB_ALPHA image as written by `ct_save`.
fn read_pam(path: &Path) -> Result<image::RgbaImage, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let end = bytes
        .windows(7)
        .position(|w| w == b"ENDHDR\n")
        .ok_or("PAM without ENDHDR")?;
    let header = String::from_utf8_lossy(&bytes[..end]);
    let field = |key: &str| -> Result<u32, String> {
        header
            .lines()
            .find_map(|l| l.strip_prefix(key)?.trim().parse().ok())
            .ok_or(format!("PAM without {key}"))
    };
    let (w, h) = (field("WIDTH ")?, field("HEIGHT ")?);
    let data = bytes[end + 7..].to_vec();
    image::RgbaImage::from_raw(w, h, data).ok_or_else(|| format!("{}: short", path.display()))
}

/// Converts every `.pam` in `dir` to `.png` (and removes the `.pam`).
fn pam_to_png(dir: &Path) -> Result<(), String> {
    for e in std::fs::read_dir(dir).map_err(|e| e.to_string())?.flatten() {
        let path = e.path();
        if path.extension().is_some_and(|x| x == "pam") {
            let img = read_pam(&path)?;
            img.save(path.with_extension("png"))
                .map_err(|e| format!("{}: {e}", path.display()))?;
            std::fs::remove_file(&path).ok();
        }
    }
    Ok(())
}

/// Runs `job` for every program on all cores, in name order of results.
fn for_all<T: Send>(programs: &[Program], job: impl Fn(&Program) -> T + Sync) -> Vec<(String, T)> {
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    let next = std::sync::atomic::AtomicUsize::new(0);
    let results = std::sync::Mutex::new(BTreeMap::new());
    std::thread::scope(|s| {
        for _ in 0..threads {
            s.spawn(|| loop {
                let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let Some(p) = programs.get(i) else { break };
                let r = job(p);
                results.lock().unwrap().insert(p.name.clone(), r);
            });
        }
    });
    results.into_inner().unwrap().into_iter().collect()
}

#[test]
fn c_programs_pass() {
    let programs = programs();
    assert!(
        !programs.is_empty() || std::env::var("CT_FILTER").is_ok(),
        "no C programs found in c_tests/"
    );
    let results = for_all(&programs, |p| {
        build_and_run(p, Implementation::Ours, &out_root().join(&p.name))
    });
    let mut failures = Vec::new();
    for (name, r) in &results {
        match r {
            Ok(out) => println!("{name}: {}", out.lines().last().unwrap_or("")),
            Err(e) => failures.push(format!("--- {name}: {e}")),
        }
    }
    println!(
        "{} C programs, {} failed{}",
        results.len(),
        failures.len(),
        if valgrind() { " (under valgrind)" } else { "" }
    );
    assert!(failures.is_empty(), "\n{}", failures.join("\n"));
}

/// Per-channel difference statistics of two images.
struct Diff {
    max: u8,
    mean: f64,
    psnr: f64,
    over: f64,
}

fn diff(a: &image::RgbaImage, b: &image::RgbaImage) -> Diff {
    let (mut max, mut sum, mut sq, mut over) = (0u8, 0f64, 0f64, 0usize);
    for (pa, pb) in a.pixels().zip(b.pixels()) {
        let mut worst = 0;
        for c in 0..4 {
            let d = pa[c].abs_diff(pb[c]);
            worst = worst.max(d);
            sum += d as f64;
            sq += (d as f64) * (d as f64);
        }
        max = max.max(worst);
        over += (worst > DIFF_STEPS) as usize;
    }
    let n = (a.width() * a.height()).max(1) as f64;
    let mse = sq / (4.0 * n);
    Diff {
        max,
        mean: sum / (4.0 * n),
        psnr: if mse == 0.0 {
            f64::INFINITY
        } else {
            10.0 * (255.0f64 * 255.0 / mse).log10()
        },
        over: over as f64 / n,
    }
}

#[test]
fn differential_against_mesa() {
    if std::env::var("GLES_CM_DIFF").ok().as_deref() != Some("mesa") && !softpipe() {
        println!(
            "skipped: set GLES_CM_DIFF=mesa (or softpipe) to compare with Mesa (see scripts/mesa-setup.sh)"
        );
        return;
    }
    let programs: Vec<Program> = programs()
        .into_iter()
        .filter(|p| !p.marked("ct:no-diff"))
        .collect();
    let results = for_all(&programs, |p| -> Result<Vec<String>, String> {
        // Its own directories: `c_programs_pass` may be building the same programs now.
        let ours = out_root().join("diff").join("ours").join(&p.name);
        let mesa = out_root().join("diff").join("mesa").join(&p.name);
        build_and_run(p, Implementation::Ours, &ours).map_err(|e| format!("ours: {e}"))?;
        build_and_run(p, Implementation::Mesa, &mesa).map_err(|e| format!("Mesa: {e}"))?;
        let mut lines = Vec::new();
        for e in std::fs::read_dir(&ours)
            .map_err(|e| e.to_string())?
            .flatten()
        {
            let path = e.path();
            if path.extension().is_none_or(|x| x != "png") {
                continue;
            }
            let file = path.file_name().unwrap();
            let a = image::open(&path).map_err(|e| e.to_string())?.to_rgba8();
            let b = image::open(mesa.join(file))
                .map_err(|e| format!("Mesa saved no {file:?}: {e}"))?
                .to_rgba8();
            if a.dimensions() != b.dimensions() {
                return Err(format!("{file:?}: sizes differ"));
            }
            let d = diff(&a, &b);
            let line = format!(
                "{}/{}: max {} mean {:.4} PSNR {:.1} dB, {:.3} % of pixels off by > {DIFF_STEPS}",
                p.name,
                file.to_string_lossy(),
                d.max,
                d.mean,
                d.psnr,
                100.0 * d.over
            );
            if d.over > DIFF_TOLERANCE && !(softpipe() && p.marked("ct:softpipe-edges")) {
                return Err(line);
            }
            lines.push(line);
        }
        Ok(lines)
    });
    let mut failures = Vec::new();
    for (name, r) in results {
        match r {
            Ok(lines) if lines.is_empty() => println!("{name}: passes on Mesa (no images)"),
            Ok(lines) => lines.iter().for_each(|l| println!("{l}")),
            Err(e) => failures.push(format!("--- {name}: {e}")),
        }
    }
    assert!(failures.is_empty(), "\n{}", failures.join("\n"));
}

/// True when Mesa's EGL and GLES 1 development files are installed (the `-lEGL -lGLESv1_CM`
/// link of the drop-in test needs them).
fn mesa_dev_installed() -> bool {
    ["EGL/egl.h", "GLES/gl.h"]
        .iter()
        .all(|h| Path::new("/usr/include").join(h).exists())
        && Command::new(compiler())
            .args(["-x", "c", "-", "-o", "/dev/null", "-lEGL", "-lGLESv1_CM"])
            .stdin(Stdio::piped())
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .and_then(|mut c| {
                use std::io::Write;
                c.stdin
                    .take()
                    .unwrap()
                    .write_all(b"int main(void){return 0;}")?;
                c.wait()
            })
            .is_ok_and(|s| s.success())
}

#[test]
fn dropin_binary_runs_on_mesa_and_ours() {
    if !mesa_dev_installed() {
        println!(
            "skipped: Mesa's libegl-dev/libgles-dev are not installed (scripts/mesa-setup.sh)"
        );
        return;
    }
    let lib = lib_dir();
    let script = Path::new(MANIFEST_DIR).join("scripts/compat-names.sh");
    let st = Command::new("sh").arg(script).arg(&lib).status().unwrap();
    assert!(st.success(), "compat-names.sh failed");

    let out = out_root().join("dropin");
    std::fs::create_dir_all(&out).unwrap();
    let exe = out.join("triangle");
    // Only the system's standard headers and libraries: no -I include, no -lGLES_CM.
    let o = Command::new(compiler())
        .args(CFLAGS)
        .arg(c_tests_dir().join("dropin/triangle.c"))
        .arg("-o")
        .arg(&exe)
        .args(["-lEGL", "-lGLESv1_CM"])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));

    let run = |ld_path: Option<&Path>| -> String {
        let mut cmd = Command::new(&exe);
        cmd.env("EGL_PLATFORM", "surfaceless");
        match ld_path {
            Some(p) => cmd.env("LD_LIBRARY_PATH", p),
            None => cmd.env_remove("LD_LIBRARY_PATH"),
        };
        let o = run_with_timeout(cmd).unwrap();
        let stdout = String::from_utf8_lossy(&o.stdout).into_owned();
        assert!(
            o.status.success(),
            "drop-in triangle failed ({}):\n{stdout}{}",
            o.status,
            String::from_utf8_lossy(&o.stderr)
        );
        stdout
    };
    let mesa = run(None);
    let ours = run(Some(&lib.join("compat")));
    println!("Mesa: {mesa}ours: {ours}");
    assert!(
        ours.contains("gles-cm"),
        "the binary did not load our library through the compatibility names:\n{ours}"
    );
    assert!(
        !mesa.contains("gles-cm"),
        "the Mesa run loaded our library:\n{mesa}"
    );
}
