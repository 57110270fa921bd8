//! The speed-against-error benchmark: fixed scenes through our library and, when installed,
//! through Mesa (llvmpipe single-core and all cores, softpipe), all driven through the same
//! GL/EGL C API loaded with `dlopen`, plus one M3G scene through our `m3g` layer.
//!
//! Every (scene, renderer) pair runs in its own child process (drivers and our library read
//! their thread counts once, when they load), and all of a scene's children live at once:
//! the parent asks them for one frame each, round by round, so machine noise hits every
//! renderer alike. Each row reports the median frame time, ratios to llvmpipe and softpipe
//! and the error against the f64 reference renderer (`gles_cm_core::reference`), or for the M3G
//! scene against the corpus reference image.
//!
//! `cargo run --release --bin bench` prints every table; `--scene NAME` (repeatable, or a
//! comma list; a prefix such as `fill` or `tris` matches a family) limits the scenes,
//! `--frames N` sets the timed frames per renderer, `--diff` writes difference images and
//! `--markdown FILE` writes the whole report (machine, tables, targets) as Markdown.
//! `--msaa` measures only our library, on single-sample and 4-sample pbuffers
//! (`EGL_SAMPLES` 4), and adds a table of 4× MSAA's cost per scene. `--threads 1,2,4,8`
//! measures our library (DONT_CARE) and llvmpipe at each of those thread counts and adds a
//! table of how each scales.
//! Internally `bench --child ours|mesa|m3g …` is the measuring process (`bench/worker.rs`).
//! `bench/scene.rs` and `bench/child.rs` hold the earlier three-scene benchmark, which the
//! `accuracy` report still builds on.

#[path = "bench/api.rs"]
mod api;
#[path = "bench/report.rs"]
mod report;
#[path = "bench/suite.rs"]
mod suite;
#[path = "bench/worker.rs"]
mod worker;

use std::fs::File;
use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::{ChildStdin, Command, ExitCode, Stdio};
use std::sync::mpsc::{Receiver, RecvTimeoutError};
use std::time::{Duration, Instant};

use gles_cm_core::reference::{compare, ErrorStats};
use gles_cm_core::Target;

use report::Table;
use suite::{is_m3g, Class, Mode, Scene, M3G, M3G_CORPUS, NAMES};

/// Timed frames per renderer by default, after one warm-up frame; the median is reported.
const FRAMES: usize = 9;
/// A renderer stops taking frames once its timed frames add up to this (with at least
/// three), so the slow ones do not stretch the run.
const BUDGET: Duration = Duration::from_secs(12);
/// Any one answer from a child may take this long before the child is killed.
const CHILD_TIMEOUT: Duration = Duration::from_secs(180);
/// The M3G scene's file and the corpus reference frame it is compared with.
const M3G_FILE: &str = "robot";
const M3G_TIME: i32 = 1000;

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Kind {
    Ours,
    Llvmpipe,
    Softpipe,
}

#[derive(Clone)]
struct Renderer {
    kind: Kind,
    /// 1 or all cores (softpipe: 1).
    threads: usize,
    /// `None` for peers (they are given DONT_CARE) and the M3G scene.
    mode: Option<Mode>,
    /// `EGL_SAMPLES` of the pbuffer config: 0, or 4 under `--msaa`.
    samples: u32,
}

impl Renderer {
    fn label(&self) -> String {
        let t = format!("{}t", self.threads);
        match self.kind {
            Kind::Ours if self.samples > 0 => format!("ours {t} msaa{}", self.samples),
            Kind::Ours => format!("ours {t}"),
            Kind::Llvmpipe => format!("llvmpipe {t}"),
            Kind::Softpipe => "softpipe".into(),
        }
    }

    fn slug(&self) -> String {
        let base = match self.kind {
            Kind::Ours => format!("ours-{}t", self.threads),
            Kind::Llvmpipe => format!("llvmpipe-{}t", self.threads),
            Kind::Softpipe => "softpipe".into(),
        };
        let base = match self.mode {
            Some(m) => format!("{base}-{}", m.name().to_lowercase()),
            None => base,
        };
        match self.samples {
            0 => base,
            n => format!("{base}-msaa{n}"),
        }
    }
}

fn renderers(class: Class, m3g: bool, all: usize, msaa: bool, counts: &[usize]) -> Vec<Renderer> {
    let mut threads = vec![1, all];
    threads.dedup();
    let mut out = Vec::new();
    if !counts.is_empty() {
        // Our library (DONT_CARE) and llvmpipe at each requested thread count.
        for kind in [Kind::Ours, Kind::Llvmpipe] {
            for &t in counts {
                out.push(Renderer {
                    kind,
                    threads: t,
                    mode: (kind == Kind::Ours).then_some(Mode::DontCare),
                    samples: 0,
                });
            }
        }
        return out;
    }
    if msaa {
        // Our library only, DONT_CARE, single-sample beside 4× MSAA.
        for &t in &threads {
            for samples in [0, 4] {
                out.push(Renderer {
                    kind: Kind::Ours,
                    threads: t,
                    mode: Some(Mode::DontCare),
                    samples,
                });
            }
        }
        return out;
    }
    let modes: Vec<Option<Mode>> = if m3g {
        vec![None]
    } else if class == Class::Main {
        Mode::ALL.into_iter().map(Some).collect()
    } else {
        vec![Some(Mode::DontCare)]
    };
    for &t in &threads {
        for &mode in &modes {
            out.push(Renderer {
                kind: Kind::Ours,
                threads: t,
                mode,
                samples: 0,
            });
        }
    }
    if m3g {
        return out;
    }
    for &t in &threads {
        out.push(Renderer {
            kind: Kind::Llvmpipe,
            threads: t,
            mode: None,
            samples: 0,
        });
    }
    if class == Class::Main {
        out.push(Renderer {
            kind: Kind::Softpipe,
            threads: 1,
            mode: None,
            samples: 0,
        });
    }
    out
}

/// What one renderer produced for a scene.
enum Outcome {
    Measured {
        median_ms: f64,
        frames: usize,
        memset_ms: Option<f64>,
        error: Option<ErrorStats>,
        renderer: String,
    },
    Unavailable(String),
    Failed(String),
}

struct Row {
    scene: String,
    renderer: Renderer,
    outcome: Outcome,
}

impl Row {
    fn ms(&self) -> Option<f64> {
        match self.outcome {
            Outcome::Measured { median_ms, .. } => Some(median_ms),
            _ => None,
        }
    }

    fn error(&self) -> Option<ErrorStats> {
        match self.outcome {
            Outcome::Measured { error, .. } => error,
            _ => None,
        }
    }
}

/// A live measuring child.
struct Child {
    process: std::process::Child,
    stdin: ChildStdin,
    lines: Receiver<String>,
    err_path: PathBuf,
    renderer: String,
    times: Vec<f64>,
    memsets: Vec<f64>,
    /// `Some` once the child is out of the running (unavailable or failed).
    done: Option<Outcome>,
}

impl Child {
    fn spawn(cmd: &mut Command, err_path: PathBuf) -> Result<Child, String> {
        let stderr = File::create(&err_path).map_err(|e| format!("temp file: {e}"))?;
        let mut process = cmd
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::from(stderr))
            .spawn()
            .map_err(|e| format!("spawn: {e}"))?;
        let stdin = process.stdin.take().ok_or("no stdin")?;
        let stdout = process.stdout.take().ok_or("no stdout")?;
        let (tx, lines) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            for line in BufReader::new(stdout).lines() {
                let Ok(line) = line else { break };
                if tx.send(line).is_err() {
                    break;
                }
            }
        });
        Ok(Child {
            process,
            stdin,
            lines,
            err_path,
            renderer: String::new(),
            times: Vec::new(),
            memsets: Vec::new(),
            done: None,
        })
    }

    fn stderr_tail(&self) -> String {
        let e = std::fs::read_to_string(&self.err_path).unwrap_or_default();
        e.lines().last().unwrap_or("").to_owned()
    }

    /// Waits for a line starting with `prefix` (remembering `renderer` lines on the way);
    /// marks the child done on `unavailable`, exit or timeout.
    fn expect(&mut self, prefix: &str) -> Option<String> {
        let deadline = Instant::now() + CHILD_TIMEOUT;
        loop {
            let left = deadline.saturating_duration_since(Instant::now());
            match self.lines.recv_timeout(left) {
                Ok(line) => {
                    if let Some(r) = line.strip_prefix("renderer ") {
                        self.renderer = r.to_owned();
                    } else if let Some(why) = line.strip_prefix("unavailable ") {
                        self.done = Some(Outcome::Unavailable(why.to_owned()));
                        return None;
                    } else if let Some(rest) = line.strip_prefix(prefix) {
                        return Some(rest.trim().to_owned());
                    }
                }
                Err(RecvTimeoutError::Timeout) => {
                    let _ = self.process.kill();
                    self.done = Some(Outcome::Failed(format!(
                        "no answer within {CHILD_TIMEOUT:?}"
                    )));
                    return None;
                }
                Err(RecvTimeoutError::Disconnected) => {
                    let status = self.process.wait().map(|s| s.to_string());
                    self.done = Some(Outcome::Failed(format!(
                        "child exited ({}): {}",
                        status.unwrap_or_default(),
                        self.stderr_tail()
                    )));
                    return None;
                }
            }
        }
    }

    fn ask(&mut self, command: &str, prefix: &str) -> Option<String> {
        if self.done.is_some() {
            return None;
        }
        if writeln!(self.stdin, "{command}")
            .and_then(|_| self.stdin.flush())
            .is_err()
        {
            return self.expect(prefix);
        }
        self.expect(prefix)
    }

    fn ask_ms(&mut self, command: &str, prefix: &str) -> Option<f64> {
        self.ask(command, prefix).and_then(|v| v.parse().ok())
    }

    fn finish(mut self) {
        let _ = writeln!(self.stdin, "quit");
        drop(self.stdin);
        let start = Instant::now();
        loop {
            match self.process.try_wait() {
                Ok(Some(_)) | Err(_) => break,
                Ok(None) if start.elapsed() > Duration::from_secs(10) => {
                    let _ = self.process.kill();
                    let _ = self.process.wait();
                    break;
                }
                Ok(None) => std::thread::sleep(Duration::from_millis(5)),
            }
        }
    }
}

struct Ctx {
    exe: PathBuf,
    ours: PathBuf,
    tmp: PathBuf,
    out_dir: PathBuf,
    corpus: PathBuf,
    frames: usize,
    diff: bool,
    /// `--msaa`: our library only, single-sample beside 4× MSAA.
    msaa: bool,
    /// `--threads`: the thread counts to measure ours and llvmpipe at (empty: 1 and all).
    counts: Vec<usize>,
    all: usize,
}

fn command(ctx: &Ctx, scene: &str, r: &Renderer) -> Command {
    let mut cmd = Command::new(&ctx.exe);
    cmd.env_remove("LP_NUM_THREADS")
        .env_remove("GALLIUM_DRIVER")
        .env_remove("GLES_CM_THREADS")
        .args(["--scene", scene]);
    let mode = r.mode.unwrap_or(Mode::DontCare);
    match r.kind {
        Kind::Ours if scene == M3G_CORPUS => {
            cmd.args(["--child", "m3g-corpus", "--m3g-dir"])
                .arg(&ctx.corpus);
        }
        Kind::Ours if scene == M3G => {
            cmd.args(["--child", "m3g", "--m3g-file"])
                .arg(ctx.corpus.join(format!("{M3G_FILE}.m3g")))
                .args(["--m3g-time", &M3G_TIME.to_string()]);
        }
        Kind::Ours => {
            cmd.args(["--child", "ours", "--mode", mode.name(), "--lib"])
                .arg(&ctx.ours)
                .args(["--samples", &r.samples.to_string()]);
        }
        Kind::Llvmpipe | Kind::Softpipe => {
            cmd.args(["--child", "mesa", "--mode", mode.name()])
                .env("EGL_PLATFORM", "surfaceless")
                .env("LIBGL_ALWAYS_SOFTWARE", "1");
        }
    }
    match r.kind {
        Kind::Ours => {
            cmd.env("GLES_CM_THREADS", r.threads.to_string());
        }
        Kind::Llvmpipe => {
            cmd.env("GALLIUM_DRIVER", "llvmpipe");
            // 0: rasterize on the calling thread, as ours does with one thread.
            let n = if r.threads == 1 { 0 } else { r.threads };
            cmd.env("LP_NUM_THREADS", n.to_string());
        }
        Kind::Softpipe => {
            cmd.env("GALLIUM_DRIVER", "softpipe");
        }
    }
    cmd
}

fn median(v: &[f64]) -> Option<f64> {
    if v.is_empty() {
        return None;
    }
    let mut s = v.to_vec();
    s.sort_by(f64::total_cmp);
    Some(s[s.len() / 2])
}

/// Measures every renderer of one scene, interleaved, and compares each image with
/// `reference`.
fn run_scene(ctx: &Ctx, name: &str, class: Class, memset: bool, reference: &Target) -> Vec<Row> {
    let list = renderers(class, is_m3g(name), ctx.all, ctx.msaa, &ctx.counts);
    let mut children: Vec<Option<Child>> = Vec::new();
    let mut failures: Vec<Option<Outcome>> = Vec::new();
    for r in &list {
        let err = ctx.tmp.join(format!("{name}-{}.err", r.slug()));
        match Child::spawn(&mut command(ctx, name, r), err) {
            Ok(c) => {
                children.push(Some(c));
                failures.push(None);
            }
            Err(e) => {
                children.push(None);
                failures.push(Some(Outcome::Failed(e)));
            }
        }
    }
    for c in children.iter_mut().flatten() {
        c.expect("ready");
    }
    // Warm-up: first-use allocations, shader compilation, page faults.
    for c in children.iter_mut().flatten() {
        c.ask_ms("frame", "t ");
        if memset {
            c.ask_ms("memset", "m ");
        }
    }
    let n = children.len();
    for round in 0..ctx.frames {
        for k in 0..n {
            let Some(c) = children[(k + round) % n].as_mut() else {
                continue;
            };
            let spent: f64 = c.times.iter().sum();
            if c.times.len() >= 3 && spent > BUDGET.as_secs_f64() * 1e3 {
                continue;
            }
            // Several threads: an untimed frame first, so that the timed one starts with
            // warm workers (asleep, they take milliseconds to wake on this kind of VM
            // while the other renderers run), for ours and llvmpipe alike.
            if list[(k + round) % n].threads > 1 {
                c.ask_ms("frame", "t ");
            }
            if let Some(t) = c.ask_ms("frame", "t ") {
                c.times.push(t);
            }
            if memset && list[(k + round) % n].kind == Kind::Ours {
                if let Some(t) = c.ask_ms("memset", "m ") {
                    c.memsets.push(t);
                }
            }
        }
        eprint!(".");
    }
    let mut rows = Vec::new();
    for ((r, c), failed) in list.iter().zip(children).zip(failures) {
        let outcome = match (c, failed) {
            (_, Some(f)) => f,
            (None, None) => Outcome::Failed("not started".into()),
            (Some(mut c), None) => {
                let file = ctx.tmp.join(format!("{name}-{}.rgba", r.slug()));
                let got = c.ask(&format!("image {}", file.display()), "ok");
                let outcome = match (c.done.take(), got) {
                    (Some(o), _) => o,
                    (None, None) => Outcome::Failed("no image".into()),
                    (None, Some(_)) => {
                        let error = std::fs::read(&file).ok().and_then(|px| {
                            let _ = std::fs::remove_file(&file);
                            let img = to_target(reference, &px, is_m3g(name))?;
                            save_png(&img, &ctx.out_dir.join(format!("{name}-{}.png", r.slug())));
                            if ctx.diff {
                                save_png(
                                    &diff_image(&img, reference),
                                    &ctx.out_dir.join(format!("{name}-{}-diff.png", r.slug())),
                                );
                            }
                            Some(compare(&img, reference))
                        });
                        match median(&c.times) {
                            Some(m) => Outcome::Measured {
                                median_ms: m,
                                frames: c.times.len(),
                                memset_ms: median(&c.memsets),
                                error,
                                renderer: c.renderer.clone(),
                            },
                            None => Outcome::Failed("no frame timed".into()),
                        }
                    }
                };
                c.finish();
                outcome
            }
        };
        rows.push(Row {
            scene: name.to_owned(),
            renderer: r.clone(),
            outcome,
        });
    }
    rows
}

/// Read-back RGBA bytes (bottom row first) as a target shaped like `like`; for the M3G
/// scene alpha is set to 255, since its reference is RGB.
fn to_target(like: &Target, px: &[u8], opaque: bool) -> Option<Target> {
    let mut t = Target::new(like.width(), like.height(), like.format());
    if px.len() != t.color().len() * 4 {
        return None;
    }
    for (w, p) in t.color_mut().iter_mut().zip(px.chunks_exact(4)) {
        *w = u32::from_le_bytes([p[0], p[1], p[2], if opaque { 255 } else { p[3] }]);
    }
    Some(t)
}

/// The corpus reference PNG (RGB, top row first) as an opaque target.
fn load_m3g_reference(path: &Path) -> Result<Target, String> {
    let img = image::open(path)
        .map_err(|e| format!("{}: {e}", path.display()))?
        .to_rgba8();
    let mut t = suite::target(img.width(), img.height());
    let (w, h) = (img.width() as usize, img.height() as usize);
    for (i, px) in t.color_mut().iter_mut().enumerate() {
        let (x, y) = (i % w, h - 1 - i / w);
        let p = img.get_pixel(x as u32, y as u32).0;
        *px = u32::from_le_bytes([p[0], p[1], p[2], 255]);
    }
    Ok(t)
}

/// With `--diff`: where `t` departs from `reference` by more than one step in some channel
/// (white), over a dimmed copy of the reference.
fn diff_image(t: &Target, reference: &Target) -> Target {
    let mut d = Target::new(t.width(), t.height(), t.format());
    for ((o, &a), &b) in d
        .color_mut()
        .iter_mut()
        .zip(t.color())
        .zip(reference.color())
    {
        let (pa, pb) = (a.to_le_bytes(), b.to_le_bytes());
        let off = pa.iter().zip(pb).any(|(x, y)| x.abs_diff(y) > 1);
        *o = if off {
            u32::MAX
        } else {
            u32::from_le_bytes([pb[0] / 4, pb[1] / 4, pb[2] / 4, 255])
        };
    }
    d
}

/// Writes `t` (rows bottom-up) as a PNG with the top row first.
fn save_png(t: &Target, path: &Path) {
    let mut img = image::RgbaImage::new(t.width(), t.height());
    for (y, row) in t.color().chunks(t.width() as usize).enumerate() {
        for (x, w) in row.iter().enumerate() {
            img.put_pixel(
                x as u32,
                t.height() - 1 - y as u32,
                image::Rgba(w.to_le_bytes()),
            );
        }
    }
    if let Err(e) = img.save(path) {
        eprintln!("warning: writing {}: {e}", path.display());
    }
}

fn child_main(args: &[String]) -> ExitCode {
    let get = |flag: &str| {
        args.iter()
            .position(|a| a == flag)
            .and_then(|i| args.get(i + 1))
            .cloned()
    };
    let (Some(which), Some(scene)) = (get("--child"), get("--scene")) else {
        eprintln!("usage: bench --child ours|mesa|m3g --scene NAME [--mode MODE] [--lib PATH]");
        return ExitCode::from(2);
    };
    let result = if which == "m3g-corpus" {
        let dir = get("--m3g-dir").map(PathBuf::from).unwrap_or_default();
        worker::run_m3g_corpus(&dir)
    } else if which == "m3g" {
        let file = get("--m3g-file").map(PathBuf::from).unwrap_or_default();
        let time = get("--m3g-time")
            .and_then(|t| t.parse().ok())
            .unwrap_or(M3G_TIME);
        worker::run_m3g(&file, time)
    } else {
        let which = match which.as_str() {
            "ours" => match get("--lib") {
                Some(lib) => worker::Which::Ours(PathBuf::from(lib)),
                None => {
                    eprintln!("--child ours needs --lib PATH");
                    return ExitCode::from(2);
                }
            },
            _ => worker::Which::Mesa,
        };
        let mode = get("--mode")
            .and_then(|m| Mode::parse(&m))
            .unwrap_or(Mode::DontCare);
        let samples = get("--samples").and_then(|n| n.parse().ok()).unwrap_or(0);
        worker::run(&worker::Job {
            which,
            mode,
            scene,
            samples,
        })
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("{e}");
            ExitCode::FAILURE
        }
    }
}

fn fmt_ratio(num: Option<f64>, den: Option<f64>) -> String {
    match (num, den) {
        (Some(a), Some(b)) if b > 0.0 => format!("{:.2}x", a / b),
        _ => "-".into(),
    }
}

fn fmt_error(e: Option<ErrorStats>) -> [String; 4] {
    match e {
        Some(e) => [
            e.max.to_string(),
            format!("{:.3}", e.mean),
            if e.psnr.is_infinite() {
                "inf".into()
            } else {
                format!("{:.1}", e.psnr)
            },
            format!("{:.3}", e.over_one * 100.0),
        ],
        None => ["-".into(), "-".into(), "-".into(), "-".into()],
    }
}

/// The row of `kind` at `threads` for `scene` (peers only, or ours in `mode`).
fn find<'a>(
    rows: &'a [Row],
    scene: &str,
    kind: Kind,
    threads: usize,
    mode: Option<Mode>,
) -> Option<&'a Row> {
    rows.iter().find(|r| {
        r.scene == scene
            && r.renderer.kind == kind
            && r.renderer.threads == threads
            && (kind != Kind::Ours || r.renderer.mode == mode)
    })
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().collect();
    if args.iter().any(|a| a == "--child") {
        return child_main(&args);
    }
    let mut only: Vec<String> = Vec::new();
    let mut frames = FRAMES;
    let mut markdown: Option<PathBuf> = None;
    let mut diff = false;
    let mut msaa = false;
    let mut counts: Vec<usize> = Vec::new();
    let mut it = args.iter().skip(1);
    while let Some(a) = it.next() {
        match a.as_str() {
            "--scene" => {
                if let Some(v) = it.next() {
                    only.extend(v.split(',').map(str::to_owned));
                }
            }
            "--frames" => match it.next().and_then(|v| v.parse().ok()) {
                Some(n) if n >= 1 => frames = n,
                _ => {
                    eprintln!("--frames needs a positive number");
                    return ExitCode::from(2);
                }
            },
            "--markdown" => markdown = it.next().map(PathBuf::from),
            "--diff" => diff = true,
            "--msaa" => msaa = true,
            "--threads" => {
                let list: Option<Vec<usize>> = it.next().and_then(|v| {
                    v.split(',')
                        .map(|n| n.trim().parse().ok().filter(|&n: &usize| n >= 1))
                        .collect()
                });
                match list {
                    Some(l) if !l.is_empty() => counts = l,
                    _ => {
                        eprintln!("--threads needs a comma list of positive numbers");
                        return ExitCode::from(2);
                    }
                }
            }
            "--help" | "-h" => {
                println!(
                    "usage: bench [--scene NAME[,NAME…]]… [--frames N] [--diff] [--msaa] [--threads N,N…] [--markdown FILE]\n\
                     scenes: {} {M3G} {M3G_CORPUS}",
                    NAMES.join(" ")
                );
                return ExitCode::SUCCESS;
            }
            other => {
                eprintln!("unknown argument {other:?} (try --help)");
                return ExitCode::from(2);
            }
        }
    }
    let exe = match std::env::current_exe() {
        Ok(e) => e,
        Err(e) => {
            eprintln!("current_exe: {e}");
            return ExitCode::FAILURE;
        }
    };
    let dir = exe.parent().unwrap_or(Path::new(".")).to_path_buf();
    // cargo rebuilds the library in `deps/` whenever it builds this program; the copy beside
    // it is only refreshed by `cargo build`, so prefer the one in `deps/` (and when this
    // program itself runs from `deps/`, the one there).
    let ours = [dir.join("deps"), dir.clone()]
        .into_iter()
        .map(|d| d.join("libGLES_CM.so"))
        .find(|p| p.exists())
        .unwrap_or_else(|| dir.join("libGLES_CM.so"));
    if !ours.exists() {
        eprintln!(
            "{} is missing: build it with `cargo build --release` (cargo run --release --bin bench does)",
            ours.display()
        );
        return ExitCode::FAILURE;
    }
    // target/<profile>/bench (or target/<profile>/deps/bench-…) → target/bench
    let profile = if dir.ends_with("deps") {
        dir.parent().unwrap_or(&dir).to_path_buf()
    } else {
        dir.clone()
    };
    let out_dir = profile.parent().unwrap_or(&profile).join("bench");
    let tmp = std::env::temp_dir().join(format!("gles-cm-bench-{}", std::process::id()));
    for d in [&out_dir, &tmp] {
        if let Err(e) = std::fs::create_dir_all(d) {
            eprintln!("create {}: {e}", d.display());
            return ExitCode::FAILURE;
        }
    }
    let corpus = gles_cm_tools::repo_root().join("tests/data/m3g");
    let ctx = Ctx {
        exe,
        ours,
        tmp,
        out_dir,
        corpus,
        frames,
        diff,
        msaa,
        counts,
        all: std::thread::available_parallelism().map_or(1, |n| n.get()),
    };
    let wanted = |name: &str| {
        only.is_empty()
            || only.iter().any(|o| {
                name == o || name.starts_with(&format!("{o}-")) || (o == "fill" && is_fill(name))
            })
    };
    let started = Instant::now();
    let load_start = report::load_average();
    let mut rows: Vec<Row> = Vec::new();
    let mut summaries: Vec<(String, String)> = Vec::new();
    let mut scenes: Vec<String> = NAMES.iter().map(|s| s.to_string()).collect();
    scenes.insert(
        NAMES
            .iter()
            .position(|n| *n == "smooth-320")
            .unwrap_or(NAMES.len()),
        M3G.to_owned(),
    );
    scenes.insert(
        NAMES
            .iter()
            .position(|n| *n == "smooth-320")
            .map_or(scenes.len(), |i| i + 1),
        M3G_CORPUS.to_owned(),
    );
    // The M3G scenes render through Graphics3D, which has no multisampled targets and no
    // peer to compare thread counts with.
    let skip_m3g = msaa || !ctx.counts.is_empty();
    for name in scenes
        .iter()
        .filter(|n| wanted(n) && !(skip_m3g && is_m3g(n)))
    {
        let t0 = Instant::now();
        let (reference, class, memset, summary) = if name == M3G_CORPUS {
            match worker::corpus_files(&ctx.corpus).and_then(|files| {
                let refs = files
                    .iter()
                    .map(|f| {
                        let stem = f.file_stem().and_then(|s| s.to_str()).unwrap_or("");
                        load_m3g_reference(&ctx.corpus.join(format!("reference/{stem}_t0.png")))
                    })
                    .collect::<Result<Vec<_>, _>>()?;
                Ok((files.len(), worker::mosaic(&refs)))
            }) {
                Ok((n, r)) => (
                    r,
                    Class::Main,
                    false,
                    format!(
                        "every file of the M3G corpus ({n}), each loaded once with m3g::loader \
                         and, every frame, animated to t = 0 and rendered with Graphics3D at \
                         240x320 (RGBA8888, depth 16), side by side in a {}-wide mosaic; error \
                         against the mosaic of the corpus references reference/*_t0.png; \
                         throughput column: frames per second",
                        worker::MOSAIC_COLUMNS
                    ),
                ),
                Err(e) => {
                    eprintln!("{name}: skipped ({e})");
                    continue;
                }
            }
        } else if name == M3G {
            let path = ctx
                .corpus
                .join(format!("reference/{M3G_FILE}_t{M3G_TIME}.png"));
            match load_m3g_reference(&path) {
                Ok(r) => (
                    r,
                    Class::Main,
                    false,
                    format!(
                        "{M3G_FILE}.m3g (skinned, textured) from the M3G corpus, loaded with \
                         m3g::loader, animated (40 ms a frame) and rendered with Graphics3D at \
                         240x320; error against reference/{M3G_FILE}_t{M3G_TIME}.png"
                    ),
                ),
                Err(e) => {
                    eprintln!("{name}: skipped ({e})");
                    continue;
                }
            }
        } else {
            let Some(scene) = Scene::by_name(name) else {
                continue;
            };
            (
                scene.reference(),
                scene.class,
                name.starts_with("clear-"),
                scene.summary.clone(),
            )
        };
        let ref_s = t0.elapsed().as_secs_f64();
        save_png(
            &reference,
            &ctx.out_dir.join(format!("{name}-reference.png")),
        );
        summaries.push((
            name.clone(),
            format!("{summary} (reference image: {:.1} s)", ref_s),
        ));
        eprint!("{name} ");
        let t1 = Instant::now();
        let scene_rows = run_scene(&ctx, name, class, memset, &reference);
        eprintln!(" {:.0} s", t1.elapsed().as_secs_f64());
        rows.extend(scene_rows);
    }
    let _ = std::fs::remove_dir_all(&ctx.tmp);
    let report = Report {
        rows: &rows,
        load_start,
        summaries: &summaries,
        all: ctx.all,
        frames,
        wall: started.elapsed().as_secs_f64(),
        out_dir: &ctx.out_dir,
    };
    let tables = report.tables();
    for t in &tables {
        print!("{}", t.text());
    }
    if msaa {
        print!("{}", msaa_table(&rows, ctx.all).text());
    }
    if !ctx.counts.is_empty() {
        print!("{}", threads_table(&rows, &ctx.counts, ctx.all).text());
    }
    println!();
    for line in report.notes() {
        println!("{line}");
    }
    if let Some(path) = markdown {
        let text = report.markdown(&tables);
        if let Err(e) = std::fs::write(&path, text) {
            eprintln!("writing {}: {e}", path.display());
            return ExitCode::FAILURE;
        }
        eprintln!("wrote {}", path.display());
    }
    ExitCode::SUCCESS
}

/// 4× MSAA against single-sample, per scene and thread count: both medians and their ratio.
fn msaa_table(rows: &[Row], all: usize) -> Table {
    let mut t = Table::new(
        "4x MSAA cost (ours, DONT_CARE; scenes chosen with --scene)",
        &["scene", "threads", "1x ms", "4x ms", "4x / 1x"],
        1,
    );
    for r in rows.iter().filter(|r| r.renderer.samples > 0) {
        let single = rows.iter().find(|s| {
            s.scene == r.scene
                && s.renderer.samples == 0
                && s.renderer.threads == r.renderer.threads
        });
        let ms = |v: Option<f64>| v.map_or("-".to_owned(), |v| format!("{v:.2}"));
        let one = single.and_then(Row::ms);
        t.rows.push(vec![
            r.scene.clone(),
            if r.renderer.threads == 1 {
                "1".into()
            } else {
                all.to_string()
            },
            ms(one),
            ms(r.ms()),
            fmt_ratio(r.ms(), one),
        ]);
    }
    t
}

/// Each scene at each thread count: ours and llvmpipe's medians and each one's speed-up
/// over its own single thread.
fn threads_table(rows: &[Row], counts: &[usize], all: usize) -> Table {
    let title = format!(
        "Threads (ours DONT_CARE, llvmpipe; this machine has {all} cores, so more threads \
         than that share them)"
    );
    let mut t = Table::new(
        &title,
        &[
            "scene",
            "threads",
            "ours ms",
            "ours speed-up",
            "llvmpipe ms",
            "llvmpipe speed-up",
        ],
        2,
    );
    let ms = |v: Option<f64>| v.map_or("-".to_owned(), |v| format!("{v:.2}"));
    for scene in scenes_of(rows) {
        let at = |kind: Kind, n: usize| {
            rows.iter()
                .find(|r| r.scene == scene && r.renderer.kind == kind && r.renderer.threads == n)
                .and_then(Row::ms)
        };
        for &n in counts {
            let (ours, peer) = (at(Kind::Ours, n), at(Kind::Llvmpipe, n));
            t.rows.push(vec![
                scene.to_owned(),
                n.to_string(),
                ms(ours),
                fmt_ratio(at(Kind::Ours, 1), ours),
                ms(peer),
                fmt_ratio(at(Kind::Llvmpipe, 1), peer),
            ]);
        }
    }
    t
}

/// The scenes of `rows`, each once, in the order they were run.
fn scenes_of(rows: &[Row]) -> Vec<&str> {
    let mut v: Vec<&str> = Vec::new();
    for r in rows {
        if !v.contains(&r.scene.as_str()) {
            v.push(&r.scene);
        }
    }
    v
}

fn is_fill(name: &str) -> bool {
    ["clear-", "flat-", "smooth-", "texture-"]
        .iter()
        .any(|p| name.starts_with(p))
}

struct Report<'a> {
    rows: &'a [Row],
    load_start: String,
    summaries: &'a [(String, String)],
    all: usize,
    frames: usize,
    wall: f64,
    out_dir: &'a Path,
}

impl Report<'_> {
    fn tables(&self) -> Vec<Table> {
        let mut out = Vec::new();
        let mut main = Table::new(
            "Scenes: median frame time, ratios and error against gles_cm_core::reference",
            &[
                "scene",
                "renderer",
                "mode",
                "ms/frame",
                "throughput",
                "vs llvmpipe",
                "vs softpipe",
                "max",
                "mean",
                "PSNR dB",
                ">1 step %",
            ],
            3,
        );
        let mut scaling = Table::new(
            "Scaling: cost per pixel and per triangle (DONT_CARE)",
            &[
                "scene",
                "unit",
                "ours 1t",
                "ours Nt",
                "llvmpipe 1t",
                "llvmpipe Nt",
            ],
            2,
        );
        for name in scenes_of(self.rows) {
            let scene = Scene::by_name(name);
            let class = scene.as_ref().map_or(Class::Main, |s| s.class);
            for row in self.rows.iter().filter(|r| r.scene == name) {
                let r = &row.renderer;
                let mut cells = vec![
                    name.to_owned(),
                    r.label(),
                    r.mode.map_or("-".into(), |m| m.name().to_owned()),
                ];
                match &row.outcome {
                    Outcome::Measured {
                        median_ms, error, ..
                    } => {
                        cells.push(format!("{median_ms:.2}"));
                        cells.push(match &scene {
                            Some(s) => s.throughput(median_ms / 1e3),
                            None if is_m3g(name) => format!("{:.1} fps", 1e3 / median_ms),
                            None => "-".into(),
                        });
                        let peer = |k: Kind, t: usize| find(self.rows, name, k, t, None)?.ms();
                        let (vs_lp, vs_sp) = if is_m3g(name) {
                            ("n/a".into(), "n/a".into())
                        } else {
                            (
                                if r.kind == Kind::Llvmpipe {
                                    "-".into()
                                } else {
                                    fmt_ratio(peer(Kind::Llvmpipe, r.threads), Some(*median_ms))
                                },
                                if r.kind == Kind::Softpipe {
                                    "-".into()
                                } else {
                                    fmt_ratio(peer(Kind::Softpipe, 1), Some(*median_ms))
                                },
                            )
                        };
                        cells.push(vs_lp);
                        cells.push(vs_sp);
                        cells.extend(fmt_error(*error));
                    }
                    Outcome::Unavailable(why) => {
                        eprintln!("{name} / {}: not installed ({why})", r.label());
                        cells.push("not installed".into());
                        cells.extend(std::iter::repeat_n(String::new(), 7));
                    }
                    Outcome::Failed(why) => {
                        cells.push(format!("failed: {why}"));
                        cells.extend(std::iter::repeat_n(String::new(), 7));
                    }
                }
                if class == Class::Main {
                    main.rows.push(cells);
                }
            }
            // Per-unit costs.
            if let Some(s) = &scene {
                let per = |kind: Kind, t: usize, amount: f64| {
                    let mode = (kind == Kind::Ours).then_some(Mode::DontCare);
                    find(self.rows, name, kind, t, mode)
                        .and_then(Row::ms)
                        .map_or("-".into(), |ms| format!("{:.2}", ms * 1e6 / amount))
                };
                let mut add = |unit: &str, amount: f64| {
                    scaling.rows.push(vec![
                        name.to_owned(),
                        unit.to_owned(),
                        per(Kind::Ours, 1, amount),
                        per(Kind::Ours, self.all, amount),
                        per(Kind::Llvmpipe, 1, amount),
                        per(Kind::Llvmpipe, self.all, amount),
                    ])
                };
                if is_fill(name) || name == "multitexture" || name == "sprites" {
                    add("ns/pixel", s.pixels);
                }
                if name.starts_with("tris-") || name.starts_with("lit-") || name == "demo" {
                    add("ns/triangle", s.work);
                    add("ns/vertex", s.vertices);
                }
            }
        }
        main.notes.push(format!(
            "ours Nt / llvmpipe Nt = {} threads. \"vs llvmpipe\" = llvmpipe's median at the same \
             thread count / this row's; \"vs softpipe\" = softpipe's / this row's (above 1x: \
             faster). Peers are given DONT_CARE.",
            self.all
        ));
        scaling.notes.push(
            "Frame time divided by the pixels written (fill scenes: every layer; the clear \
             scenes: one screen) or by the triangles and vertices submitted; constant down a \
             column means linear growth."
                .into(),
        );
        out.push(main);
        if let Some(t) = self.growth() {
            out.push(t);
        }
        out.push(scaling);
        if let Some(t) = self.memset() {
            out.push(t);
        }
        out.push(self.targets());
        out
    }

    /// Frame time growth against work growth, for resolution and triangle count.
    fn growth(&self) -> Option<Table> {
        let mut t = Table::new(
            "Growth: frame time relative to the smallest case (ideal = work ratio)",
            &[
                "series",
                "case",
                "work ratio",
                "ours 1t",
                "ours Nt",
                "llvmpipe 1t",
                "llvmpipe Nt",
            ],
            2,
        );
        let series: [(&str, &[&str]); 2] = [
            ("resolution", &["smooth-320", "smooth-640", "smooth-1280"]),
            (
                "triangles",
                &["tris-1k", "tris-10k", "tris-100k", "tris-1m"],
            ),
        ];
        for (label, names) in series {
            let base = names[0];
            let Some(base_scene) = Scene::by_name(base) else {
                continue;
            };
            for name in names {
                let Some(s) = Scene::by_name(name) else {
                    continue;
                };
                let mut cells = vec![
                    label.to_owned(),
                    name.to_string(),
                    format!("{:.0}", s.work / base_scene.work),
                ];
                for (kind, th) in [
                    (Kind::Ours, 1),
                    (Kind::Ours, self.all),
                    (Kind::Llvmpipe, 1),
                    (Kind::Llvmpipe, self.all),
                ] {
                    let mode = (kind == Kind::Ours).then_some(Mode::DontCare);
                    let a = find(self.rows, name, kind, th, mode).and_then(Row::ms);
                    let b = find(self.rows, base, kind, th, mode).and_then(Row::ms);
                    cells.push(match (a, b) {
                        (Some(a), Some(b)) => format!("{:.1}", a / b),
                        _ => "-".into(),
                    });
                }
                if self.rows.iter().any(|r| r.scene == *name) {
                    t.rows.push(cells);
                }
            }
        }
        (!t.rows.is_empty()).then_some(t)
    }

    fn memset(&self) -> Option<Table> {
        let mut t = Table::new(
            "Clears against memset of the same bytes (color 4 B + depth 4 B per pixel)",
            &[
                "scene",
                "renderer",
                "glClear ms",
                "memset ms",
                "GB/s clear",
                "% of memset",
            ],
            2,
        );
        for row in self
            .rows
            .iter()
            .filter(|r| r.scene.starts_with("clear-") && r.renderer.kind == Kind::Ours)
        {
            if let Outcome::Measured {
                median_ms,
                memset_ms: Some(m),
                ..
            } = row.outcome
            {
                let s = Scene::by_name(&row.scene)?;
                let bytes = s.pixels * 8.0;
                t.rows.push(vec![
                    row.scene.clone(),
                    format!(
                        "{} {}",
                        row.renderer.label(),
                        row.renderer.mode.map_or("", |m| m.name())
                    ),
                    format!("{median_ms:.3}"),
                    format!("{m:.3}"),
                    format!("{:.1}", bytes / (median_ms / 1e3) / 1e9),
                    format!("{:.0} %", m / median_ms * 100.0),
                ]);
            }
        }
        t.notes.push(
            "memset: one `slice::fill` of the same byte count on one thread, in the same \
             process, interleaved with the clears; the clear's time includes glFinish."
                .into(),
        );
        (!t.rows.is_empty()).then_some(t)
    }

    fn targets(&self) -> Table {
        let mut t = Table::new(
            "Targets (DONT_CARE; measured in this run)",
            &[
                "scene",
                "1t vs llvmpipe 1t >= 2x",
                "Nt vs llvmpipe Nt >= 2x",
                "<= 1 step on 99.9 %",
            ],
            4,
        );
        let verdict = |ok: Option<bool>, what: String| match ok {
            Some(true) => format!("met ({what})"),
            Some(false) => format!("NOT met ({what})"),
            None => format!("n/a ({what})"),
        };
        for name in scenes_of(self.rows) {
            let class = Scene::by_name(name).map_or(Class::Main, |s| s.class);
            if class != Class::Main {
                continue;
            }
            let mode = (!is_m3g(name)).then_some(Mode::DontCare);
            let speed = |th: usize| {
                let ours = find(self.rows, name, Kind::Ours, th, mode).and_then(Row::ms);
                let lp = find(self.rows, name, Kind::Llvmpipe, th, None).and_then(Row::ms);
                match (ours, lp) {
                    (Some(o), Some(l)) => {
                        let r = l / o;
                        verdict(Some(r >= 2.0), format!("{r:.2}x"))
                    }
                    (Some(_), None) if is_m3g(name) => "n/a (no peer)".into(),
                    (Some(_), None) => "n/a (llvmpipe not measured)".into(),
                    _ => "n/a (ours not measured)".into(),
                }
            };
            let errs: Vec<ErrorStats> = [1, self.all]
                .iter()
                .filter_map(|&th| find(self.rows, name, Kind::Ours, th, mode)?.error())
                .collect();
            let worst = errs
                .iter()
                .map(|e| e.over_one)
                .fold(None, |a: Option<f64>, b| Some(a.map_or(b, |a| a.max(b))));
            let err = match worst {
                Some(w) => verdict(Some(w <= 0.001), format!("{:.3} % over 1 step", w * 100.0)),
                None => "n/a (no image)".into(),
            };
            t.rows
                .push(vec![name.to_owned(), speed(1), speed(self.all), err]);
        }
        let clears: Vec<String> = self
            .rows
            .iter()
            .filter(|r| r.scene == "clear-1280" && r.renderer.kind == Kind::Ours)
            .filter(|r| r.renderer.mode == Some(Mode::DontCare))
            .filter_map(|r| match r.outcome {
                Outcome::Measured {
                    median_ms,
                    memset_ms: Some(m),
                    ..
                } => {
                    let pct = m / median_ms * 100.0;
                    Some(format!(
                        "{}: {pct:.0} % of memset ({})",
                        r.renderer.label(),
                        if pct >= 70.0 { "met" } else { "NOT met" }
                    ))
                }
                _ => None,
            })
            .collect();
        t.notes.push(format!(
            "{M3G}, {M3G_CORPUS}: no peer runs the M3G layer (a GL transcription of the corpus \
             scenes is not built), so there is no speed ratio; their error is against the corpus \
             images, which Mesa rendered, so it measures agreement with Mesa (the corpus \
             tolerance is at most 1 % of pixels off by more than 8 steps)."
        ));
        if !clears.is_empty() {
            t.notes.push(format!(
                "Clears (clear-1280, color + depth) >= 70 % of memset bandwidth: {}.",
                clears.join("; ")
            ));
        }
        t
    }

    fn notes(&self) -> Vec<String> {
        let mut v = Vec::new();
        for (name, s) in self.summaries {
            v.push(format!("- `{name}`: {s}"));
        }
        let mut seen: Vec<String> = Vec::new();
        for r in self.rows {
            if let Outcome::Measured { renderer, .. } = &r.outcome {
                let family = r.renderer.label();
                let family = family.split(' ').next().unwrap_or("");
                let line = format!("- GL_RENDERER | GL_VERSION of {family}: {renderer}");
                if !seen.contains(&line) && !is_m3g(&r.scene) {
                    seen.push(line);
                }
            }
        }
        v.extend(seen);
        let frames: Vec<usize> = self
            .rows
            .iter()
            .filter_map(|r| match r.outcome {
                Outcome::Measured { frames, .. } => Some(frames),
                _ => None,
            })
            .collect();
        v.push(format!(
            "- Median of up to {} frames per row (at least {} were timed for every row) after \
             one warm-up frame (multi-threaded rows: one untimed frame before each timed \
             one, so both libraries' workers are warm), each glClear + the scene + glFinish, \
             renderers interleaved \
             frame by frame; error columns against gles_cm_core::reference (M3G: the corpus image). \
             Images in {}. Total {:.0} s.",
            self.frames,
            frames.iter().min().copied().unwrap_or(0),
            // Relative to the repository, so the committed report names no machine's path.
            self.out_dir
                .strip_prefix(gles_cm_tools::repo_root())
                .unwrap_or(self.out_dir)
                .display(),
            self.wall
        ));
        v
    }

    fn markdown(&self, tables: &[Table]) -> String {
        let mesa = self
            .rows
            .iter()
            .find_map(|r| match (&r.renderer.kind, &r.outcome) {
                (Kind::Llvmpipe, Outcome::Measured { renderer, .. }) => Some(renderer.clone()),
                _ => None,
            })
            .unwrap_or_else(|| "not installed".into());
        let mut s = String::from(
            "# Benchmarks\n\nGenerated by `cargo run --release --bin bench -- --markdown \
             BENCHMARKS.md` (see the README's Benchmark section); do not edit by hand.\n\n",
        );
        s += "## Machine\n\n";
        s += &format!("- CPU: {}\n", report::cpu_model());
        s += &format!("- cores: {}\n", self.all);
        s += &format!("- kernel: Linux {}\n", report::kernel());
        s += &format!("- Mesa (llvmpipe GL_RENDERER | GL_VERSION): {mesa}\n");
        s += &format!("- date: {}\n", report::today());
        s += &format!(
            "- load average (1, 5, 15 min) at the start of the run: {}; at the end: {}\n",
            self.load_start,
            report::load_average()
        );
        s += "\n## Results\n";
        for t in tables {
            s += &t.markdown();
        }
        s += "\n## Notes\n\n";
        for line in self.notes() {
            s += &format!("{line}\n");
        }
        s += include_str!("bench/analysis.md");
        s
    }
}
