//! The showcase: `cargo run --release --bin showcase [FILE.m3g]`.
//!
//! 1. Compiles the C demo (`demo/demo.c`) with the system C compiler against `include/` and
//!    the `libGLES_CM.so` built beside this program, runs it (an animated, lit, textured,
//!    fogged scene with blending and point sprites, rendered into an EGL pbuffer) and turns
//!    its frames into `target/showcase/demo-NN.png`.
//! 2. Builds an M3G scene with the Rust API (lit, textured, fogged, a keyframed orientation),
//!    writes it as a .m3g file, loads it back and renders frames of its animation
//!    (`m3g-NN.png`); then loads FILE, or `robot.m3g` of `tests/data/m3g` when that is
//!    there, and renders it at three times.
//! 3. Prints speed beside error: 20 000 smooth-shaded, depth-tested triangles in perspective
//!    through the core on one and on all threads, against the f64 reference renderer.
//!
//! Everything lands in `target/showcase/` (beside `target/release/`).

#[path = "showcase/demo.rs"]
mod demo;
#[path = "showcase/m3g_scene.rs"]
mod m3g_scene;

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use glam::Mat4;
use gles_cm_core::reference::{self, compare};
use gles_cm_core::{
    pool, AttribArray, AttribSource, ColorFormat, CompareFunc, ComponentType, DepthFormat,
    DrawCall, Frame, Indices, Primitive, RenderState, Target, TargetFormat,
};

const WIDTH: u32 = 640;
const HEIGHT: u32 = 480;
const TRIANGLES: usize = 20_000;
const RUNS: usize = 3;

/// A fixed pseudo-random sequence, so every run draws the same scene.
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f32 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 40) as f32 / (1u64 << 24) as f32
    }
}

struct Scene {
    state: RenderState,
    positions: Vec<u8>,
    colors: Vec<u8>,
}

impl Scene {
    fn triangles() -> Scene {
        let mut rng = Lcg(2026);
        let mut state = RenderState::new(WIDTH as i32, HEIGHT as i32);
        state.projection = Mat4::perspective_rh_gl(1.0, WIDTH as f32 / HEIGHT as f32, 0.5, 50.0);
        state.depth_test = Some(CompareFunc::Less);
        let (mut pos, mut col) = (Vec::new(), Vec::new());
        for _ in 0..TRIANGLES {
            let center = [
                rng.next() * 16.0 - 8.0,
                rng.next() * 12.0 - 6.0,
                -2.0 - rng.next() * 20.0,
            ];
            for _ in 0..3 {
                pos.extend([
                    center[0] + rng.next() * 2.0 - 1.0,
                    center[1] + rng.next() * 2.0 - 1.0,
                    center[2] + rng.next() - 0.5,
                ]);
                col.extend([rng.next(), rng.next(), rng.next(), 1.0]);
            }
        }
        let bytes = |v: Vec<f32>| v.iter().flat_map(|x| x.to_ne_bytes()).collect();
        Scene {
            state,
            positions: bytes(pos),
            colors: bytes(col),
        }
    }

    fn draw_call(&self) -> DrawCall<'_> {
        DrawCall {
            color: AttribSource::Array(AttribArray {
                data: &self.colors,
                ty: ComponentType::Float,
                size: 4,
                stride: 16,
                normalized: false,
            }),
            ..DrawCall::new(
                Primitive::Triangles,
                Indices::Range {
                    first: 0,
                    count: TRIANGLES * 3,
                },
                AttribArray {
                    data: &self.positions,
                    ty: ComponentType::Float,
                    size: 3,
                    stride: 12,
                    normalized: false,
                },
            )
        }
    }
}

fn target() -> Target {
    Target::new(
        WIDTH,
        HEIGHT,
        TargetFormat {
            color: ColorFormat::Rgba8888,
            depth: Some(DepthFormat::D24),
            stencil_bits: 0,
        },
    )
}

/// Renders the scene `RUNS` times on `threads` threads; returns the image and the median
/// time in seconds.
fn render_timed(scene: &Scene, threads: usize) -> (Target, f64) {
    let mut times = Vec::new();
    let mut t = target();
    for _ in 0..RUNS {
        t = target();
        let start = Instant::now();
        let mut frame = Frame::new(WIDTH, HEIGHT, t.format());
        frame.clear_color(frame.bounds(), 0xFF20_1010, 0);
        frame.clear_depth(frame.bounds(), (1 << 24) - 1);
        gles_cm_core::record(&scene.state, &scene.draw_call(), &mut frame).expect("memory");
        frame.flush(&mut t, threads);
        times.push(start.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    (t, times[RUNS / 2])
}

fn save(t: &Target, path: &Path) {
    let mut img = image::RgbaImage::new(t.width(), t.height());
    for (y, row) in t.color().chunks(t.width() as usize).enumerate() {
        for (x, w) in row.iter().enumerate() {
            let flipped = t.height() - 1 - y as u32;
            img.put_pixel(x as u32, flipped, image::Rgba(w.to_le_bytes()));
        }
    }
    img.save(path).expect("write PNG");
}

/// Part three: the speed-against-error table.
fn speed_against_error(out: &Path) {
    let scene = Scene::triangles();

    let mut reference_image = target();
    {
        let mut frame = Frame::new(WIDTH, HEIGHT, reference_image.format());
        frame.clear_color(frame.bounds(), 0xFF20_1010, 0);
        frame.clear_depth(frame.bounds(), (1 << 24) - 1);
        frame.flush(&mut reference_image, 1);
    }
    let start = Instant::now();
    reference::render(&scene.state, &scene.draw_call(), &mut reference_image);
    let reference_time = start.elapsed().as_secs_f64();
    save(&reference_image, &out.join("triangles-reference.png"));

    println!(
        "{TRIANGLES} smooth depth-tested triangles in perspective, {WIDTH}x{HEIGHT} RGBA8888/D24, \
         against the f64 reference renderer (errors in 8-bit steps):"
    );
    println!(
        "  {:<20} {:>9} {:>10} {:>9} {:>5} {:>8} {:>9} {:>6}",
        "renderer", "ms", "Mtris/s", "vs ref", "max", "mean", "PSNR dB", ">1 %"
    );
    println!(
        "  {:<20} {:>9.1} {:>10.3} {:>9} {:>5} {:>8} {:>9} {:>6}",
        "f64 reference",
        reference_time * 1e3,
        TRIANGLES as f64 / reference_time / 1e6,
        "1.0x",
        "-",
        "-",
        "-",
        "-"
    );
    let mut thread_counts = vec![1, pool::thread_count()];
    thread_counts.dedup();
    for threads in thread_counts {
        let (image, time) = render_timed(&scene, threads);
        let e = compare(&image, &reference_image);
        println!(
            "  {:<20} {:>9.1} {:>10.3} {:>8.1}x {:>5} {:>8.4} {:>9.1} {:>6.3}",
            format!("gles-cm, {threads} thread(s)"),
            time * 1e3,
            TRIANGLES as f64 / time / 1e6,
            reference_time / time,
            e.max,
            e.mean,
            e.psnr,
            e.over_one * 100.0
        );
        save(&image, &out.join(format!("triangles-{threads}t.png")));
    }
}

fn main() -> ExitCode {
    let started = Instant::now();
    let mut file = None;
    for a in std::env::args().skip(1) {
        if a.starts_with('-') {
            eprintln!("usage: showcase [FILE.m3g]");
            return ExitCode::from(2);
        }
        file = Some(PathBuf::from(a));
    }
    // target/release/showcase: the library is beside it, the images go to target/showcase.
    let exe = std::env::current_exe().expect("current_exe");
    let bin_dir = exe.parent().expect("the showcase's folder").to_path_buf();
    // cargo rebuilds the library in `deps/` whenever it builds this program; the copy beside
    // it is only refreshed by `cargo build`, so prefer the one in `deps/`.
    let lib_dir = [bin_dir.join("deps"), bin_dir.clone()]
        .into_iter()
        .find(|d| d.join("libGLES_CM.so").exists())
        .unwrap_or_else(|| bin_dir.clone());
    let out = bin_dir
        .parent()
        .map_or_else(|| PathBuf::from("showcase"), |t| t.join("showcase"));
    std::fs::create_dir_all(&out).expect("create the output folder");
    let mut failed = false;

    println!(
        "== 1. C demo (demo/demo.c) against {}",
        lib_dir.join("libGLES_CM.so").display()
    );
    match demo::run(&lib_dir, &out, 8) {
        Ok(run) => {
            for line in run.log.lines() {
                if !line.starts_with("frame ") {
                    println!("  {line}");
                }
            }
            println!(
                "  {} frames: {} .. {}",
                run.frames.len(),
                run.frames[0].display(),
                run.frames[run.frames.len() - 1].display()
            );
        }
        Err(e) => {
            failed = true;
            println!("  FAILED: {e}");
        }
    }

    println!("== 2. M3G scene (Rust API, writer, Loader)");
    let times: Vec<i32> = (0..8).map(|i| i * 500).collect();
    match m3g_scene::run(&out, &times, file.as_deref()) {
        Ok(run) => {
            for line in &run.lines {
                println!("  {line}");
            }
            println!(
                "  {:.1} ms per 400x300 frame; {} .. {}",
                run.ms_per_frame,
                run.frames[0].display(),
                run.frames[run.frames.len() - 1].display()
            );
        }
        Err(e) => {
            failed = true;
            println!("  FAILED: {e}");
        }
    }

    println!("== 3. Speed against error");
    speed_against_error(&out);

    println!(
        "images in {} ({:.1} s)",
        out.display(),
        started.elapsed().as_secs_f64()
    );
    if failed {
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    }
}
