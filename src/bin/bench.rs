//! The speed-against-error benchmark: every scene through our library and through Mesa
//! (llvmpipe single-core and default threads, softpipe), all driven through the same
//! GL/EGL C API loaded with `dlopen`, each timed in its own child process (drivers and our
//! library read their thread counts once, when they load) and each compared with the f64
//! reference renderer (`core::reference`).
//!
//! `cargo run --release --bin bench` prints the table and writes every image to
//! `target/bench/<scene>-<renderer>.png`. `--scene NAME` runs one scene only; `--diff` also
//! writes `<scene>-<renderer>-diff.png`, the pixels off by more than one step in white.
//! Internally, `bench --child ours|mesa --hint fastest|nicest --scene NAME --out FILE` is
//! the measuring process (see `bench/child.rs`).

#[path = "bench/api.rs"]
mod api;
#[path = "bench/child.rs"]
mod child;
#[path = "bench/scene.rs"]
mod scene;

use std::fs::File;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode, Stdio};
use std::time::{Duration, Instant};

use GLES_CM::core::reference::{compare, ErrorStats};
use GLES_CM::core::Target;
use GLES_CM::gles::tokens::{GL_FASTEST, GL_NICEST};

use scene::{Scene, HEIGHT, NAMES, WIDTH};

/// Timed frames per renderer, after one warm-up frame; the median is reported.
const FRAMES: usize = 5;
/// A child that takes longer than this is killed and its row says so.
const CHILD_TIMEOUT: Duration = Duration::from_secs(120);

/// Which llvmpipe row a renderer's speed is compared with.
#[derive(Clone, Copy, PartialEq)]
enum Anchor {
    Llvmpipe1,
    LlvmpipeAll,
}

#[derive(Clone, Copy, PartialEq)]
enum Kind {
    Ours { threads: usize },
    Llvmpipe { single: bool },
    Softpipe,
}

struct Renderer {
    label: String,
    /// For file names.
    slug: String,
    kind: Kind,
    fastest: bool,
    anchor: Anchor,
}

fn renderers(scene: &str, all: usize) -> Vec<Renderer> {
    let mut threads = vec![1, all];
    threads.dedup();
    let mut hints = vec![false];
    if scene == "triangles" {
        hints.push(true);
    }
    let mut out = Vec::new();
    for &fastest in &hints {
        for &t in &threads {
            let suffix = if fastest { " FASTEST" } else { "" };
            out.push(Renderer {
                label: format!("ours {t}t{suffix}"),
                slug: format!("ours-{t}t{}", if fastest { "-fastest" } else { "" }),
                kind: Kind::Ours { threads: t },
                fastest,
                anchor: if t == 1 {
                    Anchor::Llvmpipe1
                } else {
                    Anchor::LlvmpipeAll
                },
            });
        }
    }
    out.push(Renderer {
        label: "llvmpipe 1t".into(),
        slug: "llvmpipe-1t".into(),
        kind: Kind::Llvmpipe { single: true },
        fastest: false,
        anchor: Anchor::Llvmpipe1,
    });
    if all > 1 {
        out.push(Renderer {
            label: format!("llvmpipe {all}t"),
            slug: format!("llvmpipe-{all}t"),
            kind: Kind::Llvmpipe { single: false },
            fastest: false,
            anchor: Anchor::LlvmpipeAll,
        });
    }
    out.push(Renderer {
        label: "softpipe".into(),
        slug: "softpipe".into(),
        kind: Kind::Softpipe,
        fastest: false,
        anchor: Anchor::Llvmpipe1,
    });
    out
}

/// What one child reported.
enum Outcome {
    Measured {
        median_ms: f64,
        image: Target,
        renderer: String,
    },
    Unavailable(String),
    Failed(String),
}

struct Row {
    scene: &'static str,
    renderer: Renderer,
    outcome: Outcome,
    error: Option<ErrorStats>,
}

/// Spawns the measuring child for `r` on `scene`.
fn measure(exe: &Path, ours: &Path, tmp: &Path, scene: &str, r: &Renderer) -> Outcome {
    let out = tmp.join(format!("{scene}-{}.rgba", r.slug));
    let log = tmp.join(format!("{scene}-{}.log", r.slug));
    let err = tmp.join(format!("{scene}-{}.err", r.slug));
    let mut cmd = Command::new(exe);
    cmd.arg("--child")
        .arg(if matches!(r.kind, Kind::Ours { .. }) {
            "ours"
        } else {
            "mesa"
        })
        .args(["--hint", if r.fastest { "fastest" } else { "nicest" }])
        .args(["--scene", scene])
        .arg("--out")
        .arg(&out)
        .arg("--lib")
        .arg(ours)
        .env_remove("LP_NUM_THREADS")
        .env_remove("GALLIUM_DRIVER")
        .env_remove("GLES_CM_THREADS");
    match r.kind {
        Kind::Ours { threads } => {
            cmd.env("GLES_CM_THREADS", threads.to_string());
        }
        Kind::Llvmpipe { single } => {
            cmd.env("EGL_PLATFORM", "surfaceless")
                .env("LIBGL_ALWAYS_SOFTWARE", "1")
                .env("GALLIUM_DRIVER", "llvmpipe");
            if single {
                cmd.env("LP_NUM_THREADS", "0");
            }
        }
        Kind::Softpipe => {
            cmd.env("EGL_PLATFORM", "surfaceless")
                .env("LIBGL_ALWAYS_SOFTWARE", "1")
                .env("GALLIUM_DRIVER", "softpipe");
        }
    }
    let files = File::create(&log).and_then(|o| Ok((o, File::create(&err)?)));
    let (stdout, stderr) = match files {
        Ok(f) => f,
        Err(e) => return Outcome::Failed(format!("temp files: {e}")),
    };
    let mut child = match cmd
        .stdout(Stdio::from(stdout))
        .stderr(Stdio::from(stderr))
        .spawn()
    {
        Ok(c) => c,
        Err(e) => return Outcome::Failed(format!("spawn: {e}")),
    };
    let start = Instant::now();
    let status = loop {
        match child.try_wait() {
            Ok(Some(s)) => break s,
            Ok(None) if start.elapsed() > CHILD_TIMEOUT => {
                let _ = child.kill();
                let _ = child.wait();
                return Outcome::Failed(format!("timed out after {CHILD_TIMEOUT:?}"));
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(5)),
            Err(e) => return Outcome::Failed(format!("wait: {e}")),
        }
    };
    let text = std::fs::read_to_string(&log).unwrap_or_default();
    let stderr_tail = || {
        let e = std::fs::read_to_string(&err).unwrap_or_default();
        e.lines().last().unwrap_or("").to_owned()
    };
    let mut renderer = String::new();
    let mut times: Vec<f64> = Vec::new();
    for line in text.lines() {
        if let Some(why) = line.strip_prefix("unavailable ") {
            return Outcome::Unavailable(why.to_owned());
        } else if let Some(name) = line.strip_prefix("renderer ") {
            renderer = name.to_owned();
        } else if let Some(list) = line.strip_prefix("times ") {
            times = list.split(' ').filter_map(|t| t.parse().ok()).collect();
        }
    }
    if !status.success() || times.is_empty() {
        return Outcome::Failed(format!("child {status}: {}", stderr_tail()));
    }
    let pixels = match std::fs::read(&out) {
        Ok(p) if p.len() == (WIDTH * HEIGHT * 4) as usize => p,
        _ => return Outcome::Failed("no image".into()),
    };
    let _ = std::fs::remove_file(&out);
    let mut image = scene::target();
    for (w, px) in image.color_mut().iter_mut().zip(pixels.chunks_exact(4)) {
        *w = u32::from_le_bytes([px[0], px[1], px[2], px[3]]);
    }
    times.sort_by(f64::total_cmp);
    Outcome::Measured {
        median_ms: times[times.len() / 2],
        image,
        renderer,
    }
}

/// With `--diff`: an image of where `t` departs from `reference` by more than one step in
/// some channel (white), over a dimmed copy of the reference.
fn diff_image(t: &Target, reference: &Target) -> Target {
    let mut d = scene::target();
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
    let (Some(which), Some(scene), Some(out)) = (get("--child"), get("--scene"), get("--out"))
    else {
        eprintln!("usage: bench --child ours|mesa --scene NAME --out FILE [--lib PATH] [--hint fastest|nicest]");
        return ExitCode::from(2);
    };
    let which = match which.as_str() {
        "ours" => match get("--lib") {
            Some(lib) => child::Which::Ours(PathBuf::from(lib)),
            None => {
                eprintln!("--child ours needs --lib PATH");
                return ExitCode::from(2);
            }
        },
        _ => child::Which::Mesa,
    };
    let job = child::Job {
        which,
        hint: if get("--hint").as_deref() == Some("fastest") {
            GL_FASTEST
        } else {
            GL_NICEST
        },
        scene,
        out: PathBuf::from(out),
        frames: FRAMES,
    };
    match child::run(&job) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("{e}");
            ExitCode::FAILURE
        }
    }
}

fn fmt_stats(e: Option<ErrorStats>) -> [String; 4] {
    match e {
        Some(e) => [
            e.max.to_string(),
            format!("{:.3}", e.mean),
            if e.psnr.is_infinite() {
                "inf".into()
            } else {
                format!("{:.1}", e.psnr)
            },
            format!("{:.2}", e.over_one * 100.0),
        ],
        None => Default::default(),
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().collect();
    if args.iter().any(|a| a == "--child") {
        return child_main(&args);
    }
    let only = args
        .iter()
        .position(|a| a == "--scene")
        .and_then(|i| args.get(i + 1));
    let diff = args.iter().any(|a| a == "--diff");
    let exe = match std::env::current_exe() {
        Ok(e) => e,
        Err(e) => {
            eprintln!("current_exe: {e}");
            return ExitCode::FAILURE;
        }
    };
    let dir = exe.parent().unwrap_or(Path::new("."));
    // cargo rebuilds the library in `deps/` whenever it builds this program; the copy beside
    // it is only refreshed by `cargo build`, so prefer the one in `deps/`.
    let ours = [dir.join("deps"), dir.to_path_buf()]
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
    // target/<profile>/bench → target/bench
    let out_dir = dir.parent().unwrap_or(dir).join("bench");
    let tmp = std::env::temp_dir().join(format!("gles-cm-bench-{}", std::process::id()));
    for d in [&out_dir, &tmp] {
        if let Err(e) = std::fs::create_dir_all(d) {
            eprintln!("create {}: {e}", d.display());
            return ExitCode::FAILURE;
        }
    }
    let all = std::thread::available_parallelism().map_or(1, |n| n.get());
    let started = Instant::now();
    let mut rows: Vec<Row> = Vec::new();
    let mut summaries = Vec::new();
    let mut renderers_seen: Vec<String> = Vec::new();
    for name in NAMES {
        if only.is_some_and(|o| o != name) {
            continue;
        }
        let Some(scene) = Scene::by_name(name) else {
            continue;
        };
        let t0 = Instant::now();
        let reference = scene.reference();
        let ref_s = t0.elapsed().as_secs_f64();
        save_png(&reference, &out_dir.join(format!("{name}-reference.png")));
        summaries.push(format!(
            "{name}: {}; f64 reference renderer {:.0} ms",
            scene.summary,
            ref_s * 1e3
        ));
        let first = rows.len();
        for r in renderers(name, all) {
            eprint!("{name} / {} ... ", r.label);
            let outcome = measure(&exe, &ours, &tmp, name, &r);
            let error = match &outcome {
                Outcome::Measured {
                    median_ms,
                    image,
                    renderer,
                } => {
                    eprintln!("{median_ms:.1} ms");
                    save_png(image, &out_dir.join(format!("{name}-{}.png", r.slug)));
                    if diff {
                        save_png(
                            &diff_image(image, &reference),
                            &out_dir.join(format!("{name}-{}-diff.png", r.slug)),
                        );
                    }
                    let family = r.label.split(' ').next().unwrap_or("");
                    let note = format!("{family}: {renderer}");
                    if !renderers_seen.contains(&note) {
                        renderers_seen.push(note);
                    }
                    Some(compare(image, &reference))
                }
                Outcome::Unavailable(why) => {
                    eprintln!("not installed ({why})");
                    None
                }
                Outcome::Failed(why) => {
                    eprintln!("FAILED ({why})");
                    None
                }
            };
            rows.push(Row {
                scene: name,
                renderer: r,
                outcome,
                error,
            });
        }
        // Ratios against llvmpipe, measured above in this same run.
        let anchor_ms = |a: Anchor| {
            rows[first..]
                .iter()
                .find_map(|row| match (&row.renderer.kind, &row.outcome) {
                    (Kind::Llvmpipe { .. }, Outcome::Measured { median_ms, .. })
                        if row.renderer.anchor == a =>
                    {
                        Some(*median_ms)
                    }
                    _ => None,
                })
        };
        let anchors = [
            (Anchor::Llvmpipe1, anchor_ms(Anchor::Llvmpipe1)),
            (Anchor::LlvmpipeAll, anchor_ms(Anchor::LlvmpipeAll)),
        ];
        print_scene(&rows[first..], &scene, &anchors, first == 0);
    }
    let _ = std::fs::remove_dir_all(&tmp);
    println!();
    println!(
        "every scene: a {WIDTH}x{HEIGHT} pbuffer ({} px), RGBA8888 + depth 24",
        WIDTH * HEIGHT
    );
    for s in &summaries {
        println!("{s}");
    }
    for r in &renderers_seen {
        println!("GL_RENDERER of {r}");
    }
    println!(
        "median of {FRAMES} frames after a warm-up, each clear + draw + glFinish; \
         \"vs llvmpipe\" = llvmpipe's time at the same thread count (softpipe: single-core) / \
         this row's time, from this run; error columns against core::reference. Images in {}. \
         Total {:.0} s.",
        out_dir.display(),
        started.elapsed().as_secs_f64()
    );
    ExitCode::SUCCESS
}

const HEADER: [&str; 9] = [
    "scene",
    "renderer",
    "ms/frame",
    "throughput",
    "vs llvmpipe",
    "max",
    "mean",
    "PSNR dB",
    ">1 %",
];
const WIDTHS: [usize; 9] = [10, 20, 9, 15, 11, 4, 7, 8, 7];

fn print_line(cells: &[String; 9]) {
    let mut line = String::new();
    for (i, (c, w)) in cells.iter().zip(WIDTHS).enumerate() {
        if i < 2 {
            line += &format!("{c:<w$} ");
        } else {
            line += &format!("{c:>w$} ");
        }
    }
    println!("{}", line.trim_end());
}

fn print_scene(rows: &[Row], scene: &Scene, anchors: &[(Anchor, Option<f64>); 2], header: bool) {
    if header {
        print_line(&HEADER.map(String::from));
        let total: usize = WIDTHS.iter().sum::<usize>() + WIDTHS.len() - 1;
        println!("{}", "-".repeat(total));
    }
    for row in rows {
        let mut cells: [String; 9] = Default::default();
        cells[0] = row.scene.to_owned();
        cells[1] = row.renderer.label.clone();
        match &row.outcome {
            Outcome::Measured { median_ms, .. } => {
                cells[2] = format!("{median_ms:.2}");
                cells[3] = scene.work.throughput(median_ms / 1e3);
                let anchor = anchors
                    .iter()
                    .find(|(a, _)| *a == row.renderer.anchor)
                    .and_then(|(_, ms)| *ms);
                cells[4] = anchor.map_or("-".into(), |a| format!("{:.2}x", a / median_ms));
                let [max, mean, psnr, over] = fmt_stats(row.error);
                cells[5] = max;
                cells[6] = mean;
                cells[7] = psnr;
                cells[8] = over;
            }
            Outcome::Unavailable(_) => cells[2] = "not installed".into(),
            Outcome::Failed(why) => cells[2] = format!("failed: {why}"),
        }
        print_line(&cells);
    }
}
