//! The showcase: renders scenes through the core to PNG and prints speed beside error against
//! the f64 reference renderer. For now one scene, the walking skeleton's smooth-shaded,
//! depth-tested triangles in perspective; real scenes (M3G content, textures, lighting)
//! join it as those parts land.
//!
//! `cargo run --release --bin showcase` writes `target/showcase/*.png`.

use std::path::Path;
use std::time::Instant;

use glam::Mat4;
use GLES_CM::core::reference::{self, compare};
use GLES_CM::core::{
    bin, AttribArray, AttribSource, ColorFormat, CompareFunc, ComponentType, DepthFormat, DrawCall,
    Frame, Indices, Primitive, RenderState, Target, TargetFormat,
};

const WIDTH: u32 = 640;
const HEIGHT: u32 = 480;
const TRIANGLES: usize = 20_000;
const RUNS: usize = 5;

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
        GLES_CM::core::record(&scene.state, &scene.draw_call(), &mut frame).expect("memory");
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

fn main() {
    let out = Path::new("target/showcase");
    std::fs::create_dir_all(out).expect("create target/showcase");
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
        "scene: {TRIANGLES} smooth depth-tested triangles in perspective, {WIDTH}x{HEIGHT} RGBA8888/D24"
    );
    println!(
        "{:<22} {:>9} {:>10} {:>9} {:>5} {:>8} {:>9}",
        "renderer", "ms", "Mtris/s", "vs ref", "max", "mean", "PSNR dB"
    );
    println!(
        "{:<22} {:>9.1} {:>10.3} {:>9} {:>5} {:>8} {:>9}",
        "f64 reference",
        reference_time * 1e3,
        TRIANGLES as f64 / reference_time / 1e6,
        "1.0x",
        "-",
        "-",
        "-"
    );
    let mut thread_counts = vec![1, bin::thread_count()];
    thread_counts.dedup();
    for threads in thread_counts {
        let (image, time) = render_timed(&scene, threads);
        let e = compare(&image, &reference_image);
        println!(
            "{:<22} {:>9.1} {:>10.3} {:>8.1}x {:>5} {:>8.4} {:>9.1}",
            format!("gles-cm, {threads} thread(s)"),
            time * 1e3,
            TRIANGLES as f64 / time / 1e6,
            reference_time / time,
            e.max,
            e.mean,
            e.psnr
        );
        save(&image, &out.join(format!("triangles-{threads}t.png")));
    }
    println!("images in {}", out.display());
}
