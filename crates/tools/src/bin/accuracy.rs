//! The precision report: `cargo run --release --bin accuracy` writes `ACCURACY.md` at the
//! package root (issue 10, items 3 and 4).
//!
//! - Per scene and perspective hint, the fast pipeline's error against the f64 reference
//!   renderer (`gles_cm_core::reference`), and Mesa softpipe's on the benchmark's scenes when Mesa
//!   is installed (driven through the benchmark's child process code, reused by path).
//! - The vertex stage's largest relative error over the required input ranges, float and
//!   fixed entry points, and the lighting powers' error against the correctly rounded one.
//! - The depth precision table: the smallest separation that renders without z-fighting
//!   against the f64 ideal.
//!
//! Internally, `accuracy --child mesa --hint fastest|nicest --scene NAME --out FILE` renders
//! one benchmark scene through Mesa (see `bench/child.rs`).

#[allow(dead_code)]
#[path = "bench/api.rs"]
mod api;
#[allow(dead_code)]
#[path = "bench/child.rs"]
mod child;
#[path = "accuracy/depth.rs"]
mod depth;
#[path = "accuracy/edges.rs"]
mod edges;
#[allow(dead_code)]
#[path = "bench/scene.rs"]
mod scene;
#[path = "../../../core/tests/common/scenes.rs"]
mod scenes;

use depth::{ideal_separation, measured_separation};
use std::fmt::Write as _;
use std::path::PathBuf;
use std::process::{Command, ExitCode};
use std::time::Instant;

use glam::{DVec4, Mat4, Vec3};
use gles_cm_core::reference::{self, ErrorStats};
use gles_cm_core::state::Quality;
use gles_cm_core::texture::{MagFilter, MinFilter};
use gles_cm_core::{
    AttribArray, AttribSource, ComponentType, DepthFormat, DrawCall, Frame, Indices, Primitive,
    RenderState, Target,
};
use GLES_CM::gles::tokens::{GL_FASTEST, GL_NICEST};

/// Size of the report's own scenes (the benchmark's are 640 × 480).
const W: u32 = 320;
const H: u32 = 240;

/// One row of the image table.
struct Row {
    scene: String,
    hint: &'static str,
    ours: ErrorStats,
    /// Mesa softpipe's error, or why there is none.
    mesa: Result<ErrorStats, String>,
}

fn hint_name(q: Quality) -> &'static str {
    if q == Quality::Fastest {
        "FASTEST"
    } else {
        "NICEST"
    }
}

fn fmt_stats(e: &ErrorStats) -> String {
    let psnr = if e.psnr.is_infinite() {
        "inf".to_owned()
    } else {
        format!("{:.1}", e.psnr)
    };
    format!(
        "{} | {:.3} | {psnr} | {:.2}",
        e.max,
        e.mean,
        e.over_one * 100.0
    )
}

/// The fast path (all cores) and the reference on a benchmark scene.
fn bench_scene_ours(s: &scene::Scene, q: Quality, reference: &Target) -> ErrorStats {
    let mut fast = scene::target();
    fast.clear_color(fast.bounds(), s.clear_color, [true; 4]);
    fast.clear_depth(fast.bounds(), 1.0);
    let (pos, col) = (scenes::bytes(&s.positions), scenes::bytes(&s.colors));
    let mut frame = Frame::new(fast.width(), fast.height(), fast.format());
    for d in &s.draws {
        let mut st = s.render_state(d);
        st.perspective = q;
        st.line_quality = q;
        st.point_quality = q;
        let call = DrawCall {
            color: AttribSource::Array(AttribArray {
                data: &col,
                ty: ComponentType::Float,
                size: 4,
                stride: 16,
                normalized: false,
            }),
            ..DrawCall::new(
                d.primitive,
                Indices::Range {
                    first: d.first,
                    count: d.count,
                },
                AttribArray {
                    data: &pos,
                    ty: ComponentType::Float,
                    size: 3,
                    stride: 12,
                    normalized: false,
                },
            )
        };
        gles_cm_core::record(&st, &call, &mut frame).expect("memory");
        frame.flush_if_full(&mut fast);
    }
    frame.flush_into(&mut fast);
    reference::compare(&fast, reference)
}

/// Mesa softpipe on a benchmark scene, in a child process of this binary.
fn bench_scene_mesa(name: &str, q: Quality, reference: &Target) -> Result<ErrorStats, String> {
    let exe = std::env::current_exe().map_err(|e| e.to_string())?;
    let out = std::env::temp_dir().join(format!(
        "accuracy-{}-{name}-{}.rgba",
        std::process::id(),
        hint_name(q)
    ));
    let output = Command::new(exe)
        .args(["--child", "mesa", "--scene", name, "--out"])
        .arg(&out)
        .args([
            "--hint",
            if q == Quality::Fastest {
                "fastest"
            } else {
                "nicest"
            },
        ])
        .env("EGL_PLATFORM", "surfaceless")
        .env("LIBGL_ALWAYS_SOFTWARE", "1")
        .env("GALLIUM_DRIVER", "softpipe")
        .output()
        .map_err(|e| format!("spawn: {e}"))?;
    let text = String::from_utf8_lossy(&output.stdout);
    if let Some(why) = text.lines().find_map(|l| l.strip_prefix("unavailable ")) {
        return Err(format!("not installed ({why})"));
    }
    if !output.status.success() {
        return Err(format!(
            "failed: {}",
            String::from_utf8_lossy(&output.stderr).trim()
        ));
    }
    let renderer = text
        .lines()
        .find_map(|l| l.strip_prefix("renderer "))
        .unwrap_or("?");
    if !renderer.contains("softpipe") {
        let _ = std::fs::remove_file(&out);
        return Err(format!("driver is {renderer:?}, not softpipe"));
    }
    let pixels = std::fs::read(&out).map_err(|e| e.to_string())?;
    let _ = std::fs::remove_file(&out);
    let mut image = scene::target();
    if pixels.len() != image.color().len() * 4 {
        return Err("short image".into());
    }
    for (w, px) in image.color_mut().iter_mut().zip(pixels.chunks_exact(4)) {
        *w = u32::from_le_bytes([px[0], px[1], px[2], px[3]]);
    }
    Ok(reference::compare(&image, reference))
}

/// The fast path and the reference on (state, draw) pairs, from one base target.
fn own_scene(
    parts: &[(
        RenderState,
        DrawCall<'_>,
        Option<RenderState>,
        Option<DrawCall<'_>>,
    )],
) -> ErrorStats {
    let base = scenes::target(W, H);
    let (mut fast, mut slow) = (base.clone(), base.clone());
    let mut frame = Frame::new(W, H, base.format());
    for (s, d, rs, rd) in parts {
        gles_cm_core::record(s, d, &mut frame).expect("memory");
        reference::render(
            rs.as_ref().unwrap_or(s),
            rd.as_ref().unwrap_or(d),
            &mut slow,
        );
    }
    frame.flush_into(&mut fast);
    reference::compare(&fast, &slow)
}

fn image_rows(mesa: bool) -> Vec<Row> {
    let mut rows = Vec::new();
    for (name, label) in [
        (
            "triangles",
            "smooth triangles in perspective (bench `triangles`, 640 × 480)",
        ),
        ("blend", "blended quads (bench `blend`, 640 × 480)"),
        ("lines", "lines + points (bench `lines`, 640 × 480)"),
    ] {
        let s = scene::Scene::by_name(name).expect("bench scene");
        let start = Instant::now();
        let reference = s.reference();
        eprintln!(
            "{name}: reference in {:.1} s",
            start.elapsed().as_secs_f64()
        );
        for q in [Quality::Fastest, Quality::Nicest] {
            let ours = bench_scene_ours(&s, q, &reference);
            let mesa = if mesa {
                bench_scene_mesa(name, q, &reference)
            } else {
                Err("skipped (--no-mesa)".into())
            };
            rows.push(Row {
                scene: label.to_owned(),
                hint: hint_name(q),
                ours,
                mesa,
            });
        }
    }
    let not_driven = || Err::<ErrorStats, String>("not driven (not a bench scene)".into());
    let floor = scenes::floor();
    for (filter, min, mag) in [
        ("nearest", MinFilter::Nearest, MagFilter::Nearest),
        ("bilinear", MinFilter::Linear, MagFilter::Linear),
        (
            "trilinear",
            MinFilter::LinearMipmapLinear,
            MagFilter::Linear,
        ),
    ] {
        for q in [Quality::Fastest, Quality::Nicest] {
            let s = scenes::floor_state(W, H, min, mag, q);
            let ours = own_scene(&[(s, floor.call(), None, None)]);
            rows.push(Row {
                scene: format!("textured perspective floor, {filter} ({W} × {H})"),
                hint: hint_name(q),
                ours,
                mesa: not_driven(),
            });
        }
    }
    let sphere = scenes::sphere(24, 36);
    for q in [Quality::Fastest, Quality::Nicest] {
        // The reference renderer does no lighting: it is given the f64-lit vertex colors.
        let states: Vec<RenderState> = scenes::lit_modelviews()
            .into_iter()
            .map(|mv| scenes::lit_state(W, H, q, mv))
            .collect();
        let colors: Vec<Vec<u8>> = states
            .iter()
            .map(|s| scenes::bytes(&scenes::lit_colors_f64(s, &sphere)))
            .collect();
        let parts: Vec<_> = states
            .iter()
            .zip(&colors)
            .map(|(s, c)| {
                let mut rs = s.clone();
                rs.lighting = None;
                let mut rd = sphere.call();
                rd.color = AttribSource::Array(AttribArray {
                    data: c,
                    ty: ComponentType::Float,
                    size: 4,
                    stride: 16,
                    normalized: false,
                });
                (s.clone(), sphere.call(), Some(rs), Some(rd))
            })
            .collect();
        rows.push(Row {
            scene: format!("lit spheres, 2 lights, specular ({W} × {H})"),
            hint: hint_name(q),
            ours: own_scene(&parts),
            mesa: not_driven(),
        });
    }
    rows
}

// ---------------------------------------------------------------------------------------
// The vertex stage.

/// Largest relative errors found for one kind of input.
struct VertexRow {
    what: String,
    range: String,
    worst: f64,
    samples: usize,
}

/// Magnitudes log-uniform in [2^lo, 2^hi], random sign.
fn magnitude(r: &mut scenes::Lcg, lo: f32, hi: f32) -> f64 {
    let m = (2.0f64).powf(r.range(lo, hi) as f64);
    if r.next() < 0.5 {
        -m
    } else {
        m
    }
}

fn float_array(v: &[f32], size: usize) -> (Vec<u8>, usize) {
    (scenes::bytes(v), size)
}

/// A modelview and projection with every entry nonzero (rotation, scale, translation,
/// perspective), and a texture matrix with rotation, scale and translation.
fn matrices() -> (Mat4, Mat4, Mat4) {
    let mv = Mat4::from_translation(Vec3::new(3.5, -1.25, -20.0))
        * Mat4::from_axis_angle(Vec3::new(1.0, 2.0, 3.0).normalize(), 0.7)
        * Mat4::from_scale(Vec3::new(1.5, 0.75, 1.25));
    let proj = Mat4::perspective_rh_gl(1.1, 4.0 / 3.0, 0.5, 1.0e4);
    let tex = Mat4::from_translation(Vec3::new(0.25, -0.5, 0.0))
        * Mat4::from_rotation_z(0.3)
        * Mat4::from_scale(Vec3::new(2.0, 3.0, 1.0));
    (mv, proj, tex)
}

/// Relative error of `got` against `exact` = M·v: per component, the error over the sum of
/// the magnitudes of the terms (|M_ij·v_j|), the scale rounding can be measured against.
fn rel_err(m: glam::DMat4, v: DVec4, got: [f32; 4]) -> f64 {
    let exact = m * v;
    let scale = m.abs() * v.abs();
    (0..4)
        .map(|i| {
            let s = scale[i];
            if s == 0.0 {
                (got[i] as f64 - exact[i]).abs()
            } else {
                (got[i] as f64 - exact[i]).abs() / s
            }
        })
        .fold(0.0, f64::max)
}

fn vertex_rows() -> Vec<VertexRow> {
    let (mv, proj, texm) = matrices();
    let mut state = RenderState::new(640, 480);
    state.modelview = mv;
    state.projection = proj;
    state.texture_matrices[0] = texm;
    // Vertices keep the coordinates of enabled units only.
    state.textures[0] = Some(gles_cm_core::texenv::TextureUnit::white());
    let mvp = (proj.as_dmat4()) * mv.as_dmat4();
    let n = 20_000;
    let mut rows = Vec::new();
    let mut r = scenes::Lcg(0x5eed);

    // Positions: float to 2^32, fixed over the whole 16.16 range.
    for fixed in [false, true] {
        let exact: Vec<[f64; 3]> = (0..n)
            .map(|k| {
                if fixed {
                    // Every bit pattern, the extremes included.
                    let x = |r: &mut scenes::Lcg| match k % 97 {
                        0 => i32::MAX,
                        1 => i32::MIN,
                        _ => (r.next() as f64 * 2f64.powi(32) - 2f64.powi(31)) as i32,
                    };
                    [x(&mut r), x(&mut r), x(&mut r)].map(|v| v as f64 / 65536.0)
                } else {
                    // Each vector at one scale: 2^0 to 2^32.
                    let e = r.range(0.0, 32.0);
                    std::array::from_fn(|_| magnitude(&mut r, e - 4.0, e) as f32 as f64)
                }
            })
            .collect();
        let data: Vec<u8> = if fixed {
            exact
                .iter()
                .flatten()
                .flat_map(|&v| ((v * 65536.0) as i32).to_ne_bytes())
                .collect()
        } else {
            exact
                .iter()
                .flatten()
                .flat_map(|&v| (v as f32).to_ne_bytes())
                .collect()
        };
        let call = DrawCall::new(
            Primitive::Points,
            Indices::Range { first: 0, count: n },
            AttribArray {
                data: &data,
                ty: if fixed {
                    ComponentType::Fixed
                } else {
                    ComponentType::Float
                },
                size: 3,
                stride: 12,
                normalized: false,
            },
        );
        let out = gles_cm_core::vertex::run(&state, &call).expect("memory");
        let worst = (0..n)
            .map(|k| {
                let [x, y, z] = exact[k];
                rel_err(mvp, DVec4::new(x, y, z, 1.0), out.get(k).pos().to_array())
            })
            .fold(0.0, f64::max);
        rows.push(VertexRow {
            what: format!(
                "position → clip coordinates (modelview · projection), {}",
                if fixed { "fixed" } else { "float" }
            ),
            range: if fixed {
                "every 16.16 value, ±32768".into()
            } else {
                "\\|x\\| from 1 to 2³²".into()
            },
            worst,
            samples: n,
        });
    }

    // Colors and texture coordinates: magnitudes 2^-10 to 2^10.
    for fixed in [false, true] {
        let vals: Vec<f64> = (0..n * 4)
            .map(|_| {
                let v = magnitude(&mut r, -10.0, 10.0);
                if fixed {
                    (v * 65536.0).round() / 65536.0
                } else {
                    v as f32 as f64
                }
            })
            .collect();
        let data: Vec<u8> = if fixed {
            vals.iter()
                .flat_map(|&v| ((v * 65536.0) as i32).to_ne_bytes())
                .collect()
        } else {
            vals.iter()
                .flat_map(|&v| (v as f32).to_ne_bytes())
                .collect()
        };
        let pos = float_array(&vec![0.0; n * 3], 3);
        let arr = |size: usize| AttribArray {
            data: &data,
            ty: if fixed {
                ComponentType::Fixed
            } else {
                ComponentType::Float
            },
            size,
            stride: 16,
            normalized: false,
        };
        let mut call = DrawCall::new(
            Primitive::Points,
            Indices::Range { first: 0, count: n },
            AttribArray {
                data: &pos.0,
                ty: ComponentType::Float,
                size: pos.1,
                stride: 12,
                normalized: false,
            },
        );
        call.color = AttribSource::Array(arr(4));
        call.texcoord[0] = AttribSource::Array(arr(4));
        let out = gles_cm_core::vertex::run(&state, &call).expect("memory");
        let entry = if fixed { "fixed" } else { "float" };
        // Colors are clamped to [0, 1] by the vertex stage: the error is absolute, which
        // for values in [0, 1] is at most the relative one.
        let color_worst = (0..n)
            .map(|k| {
                (0..4)
                    .map(|i| {
                        let exact = vals[4 * k + i].clamp(0.0, 1.0);
                        (out.get(k).color()[i] as f64 - exact).abs()
                    })
                    .fold(0.0, f64::max)
            })
            .fold(0.0, f64::max);
        rows.push(VertexRow {
            what: format!("color (clamped to [0, 1]), {entry}"),
            range: "\\|c\\| from 2⁻¹⁰ to 2¹⁰".into(),
            worst: color_worst,
            samples: n,
        });
        let tm = texm.as_dmat4();
        let tex_worst = (0..n)
            .map(|k| {
                let v = DVec4::from_slice(&vals[4 * k..4 * k + 4]);
                rel_err(tm, v, out.get(k).tex(0).to_array())
            })
            .fold(0.0, f64::max);
        rows.push(VertexRow {
            what: format!("texture coordinates → texture matrix, {entry}"),
            range: "\\|s\\|, \\|t\\|, \\|r\\|, \\|q\\| from 2⁻¹⁰ to 2¹⁰".into(),
            worst: tex_worst,
            samples: n,
        });
    }
    rows
}

// ---------------------------------------------------------------------------------------
// Depth precision (the logic of `tests/properties.rs`, which asserts it).

/// One row of the lighting-power table: the power's error for one exponent over random
/// bases, ours (`vertex::power::pow`) beside the C library's `powf`.
struct PowerRow {
    exponent: f32,
    samples: usize,
    /// Largest distance in f32 steps from the correctly rounded power, and how many results
    /// are not the correctly rounded one: ours, then `powf`'s.
    ours: (u32, usize),
    libm: (u32, usize),
    /// Largest difference of the power times 255 (a specular term of a unit product, in
    /// 8-bit steps) between ours and `powf`.
    steps: f64,
}

/// The distance in f32 steps between `a` and `exact` rounded to f32.
fn ulps(a: f32, exact: f64) -> u32 {
    let key = |v: f32| {
        let b = v.to_bits() as i32;
        if b < 0 {
            i32::MIN - b
        } else {
            b
        }
    };
    key(a).abs_diff(key(exact as f32))
}

fn power_rows() -> Vec<PowerRow> {
    use gles_cm_core::vertex::power::pow;
    let mut r = scenes::Lcg(184);
    [0.5, 1.0, 2.5, 8.0, 16.0, 20.0, 64.0, 128.0]
        .into_iter()
        .map(|y: f32| {
            let samples = 200_000;
            let mut row = PowerRow {
                exponent: y,
                samples,
                ours: (0, 0),
                libm: (0, 0),
                steps: 0.0,
            };
            for k in 0..samples {
                // n ⊙ ĥ of a unit normal is in [0, 1]; an unnormalized one reaches past 1.
                let x = if k % 4 == 3 {
                    r.range(1.0, 2.0)
                } else {
                    r.next()
                };
                let exact = (x as f64).powf(y as f64);
                let (ours, libm) = (pow(x, y), x.powf(y));
                for ((worst, off), v) in [(&mut row.ours, ours), (&mut row.libm, libm)] {
                    let d = ulps(v, exact);
                    *worst = (*worst).max(d);
                    *off += (d != 0) as usize;
                }
                if x <= 1.0 {
                    row.steps = row.steps.max((ours as f64 - libm as f64).abs() * 255.0);
                }
            }
            row
        })
        .collect()
}

fn depth_table(md: &mut String) {
    md.push_str("| depth bits | near/far | distance | ideal | measured | measured / ideal |\n");
    md.push_str("|---|---|---|---|---|---|\n");
    let far = 1000.0f32;
    for depth in [DepthFormat::D16, DepthFormat::D24] {
        for k in 1..=6 {
            let near = far * 10f32.powi(-k);
            for frac in [0.01f32, 0.1, 0.5] {
                let d = near + (far - near) * frac;
                let ideal = ideal_separation(depth.bits(), near as f64, far as f64, d as f64);
                let got = measured_separation(depth, near, far, d);
                let ratio = if ideal.is_infinite() && got.is_infinite() {
                    "–".to_owned()
                } else {
                    format!("{:.2}", got / ideal)
                };
                let _ = writeln!(
                    md,
                    "| {} | 1e-{k} | {d:.4} | {ideal:.3e} | {got:.3e} | {ratio} |",
                    depth.bits(),
                );
            }
        }
    }
}

// ---------------------------------------------------------------------------------------

fn child_main(args: &[String]) -> ExitCode {
    let get = |flag: &str| {
        args.iter()
            .position(|a| a == flag)
            .and_then(|i| args.get(i + 1))
            .cloned()
    };
    let (Some(scene), Some(out)) = (get("--scene"), get("--out")) else {
        eprintln!("usage: accuracy --child mesa --scene NAME --out FILE [--hint fastest|nicest]");
        return ExitCode::from(2);
    };
    let job = child::Job {
        which: child::Which::Mesa,
        hint: if get("--hint").as_deref() == Some("fastest") {
            GL_FASTEST
        } else {
            GL_NICEST
        },
        scene,
        out: PathBuf::from(out),
        frames: 1,
    };
    match child::run(&job) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("{e}");
            ExitCode::FAILURE
        }
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().collect();
    if args.iter().any(|a| a == "--child") {
        return child_main(&args);
    }
    let mesa = !args.iter().any(|a| a == "--no-mesa");
    let path = args
        .iter()
        .position(|a| a == "--out")
        .and_then(|i| args.get(i + 1))
        .map(PathBuf::from)
        .unwrap_or_else(|| gles_cm_tools::repo_root().join("ACCURACY.md"));

    let mut md = String::new();
    md.push_str("# Accuracy\n\n");
    md.push_str(
        "Generated by `cargo run --release --bin accuracy` (`crates/tools/src/bin/accuracy.rs`); do not \
         edit by hand. Options: `--no-mesa` skips Mesa, `--out FILE` writes elsewhere.\n\n",
    );

    md.push_str("## Images against the f64 reference renderer\n\n");
    md.push_str(
        "Each scene is rendered by the fast pipeline (`gles_cm_core::record` + `Frame::flush`, all \
         cores) and by `gles_cm_core::reference::render` (f64, unsnapped, per-pixel perspective) into \
         RGBA8888 / depth 24 targets, and compared with `gles_cm_core::reference::compare`: `max` is \
         the largest difference of any channel in 8-bit steps, `mean` the mean absolute \
         difference per channel, `PSNR` over all channels, `>1 %` the share of pixels with \
         some channel off by more than one step. The hint is \
         `GL_PERSPECTIVE_CORRECTION_HINT` (and the line and point smooth hints): colors are \
         divided by w and a texture's level of detail computed per pixel under every hint; \
         FASTEST reads a blended narrow destination through a reciprocal. Mesa softpipe renders the \
         benchmark's scenes through its GL ES 1.1 API (the benchmark's child process code, \
         `GALLIUM_DRIVER=softpipe`) and is compared with the same reference image; the \
         other scenes are not driven through Mesa. The lit scene's reference is given \
         vertex colors lit in f64 (the reference renderer does no lighting), so its error \
         includes our f32 lighting.\n\n",
    );
    md.push_str(
        "| scene | hint | ours max | ours mean | ours PSNR dB | ours >1 % | softpipe max | softpipe mean | softpipe PSNR dB | softpipe >1 % |\n",
    );
    md.push_str("|---|---|---|---|---|---|---|---|---|---|\n");
    let rows = image_rows(mesa);
    let mut notes = Vec::new();
    for r in &rows {
        let mesa = match &r.mesa {
            Ok(e) => fmt_stats(e),
            Err(why) => {
                if !notes.contains(why) {
                    notes.push(why.clone());
                }
                "– | – | – | –".to_owned()
            }
        };
        let _ = writeln!(
            md,
            "| {} | {} | {} | {mesa} |",
            r.scene,
            r.hint,
            fmt_stats(&r.ours)
        );
    }
    if !notes.is_empty() {
        md.push_str("\nsoftpipe: ");
        md.push_str(&notes.join("; "));
        md.push_str(".\n");
    }
    let worse: Vec<String> = rows
        .iter()
        .filter_map(|r| {
            let m = r.mesa.as_ref().ok()?;
            (r.ours.mean > m.mean || r.ours.over_one > m.over_one || r.ours.max > m.max).then(
                || {
                    format!(
                        "{} {}: ours max {} mean {:.3} >1 {:.2} % vs softpipe max {} mean {:.3} >1 {:.2} %",
                        r.scene,
                        r.hint,
                        r.ours.max,
                        r.ours.mean,
                        r.ours.over_one * 100.0,
                        m.max,
                        m.mean,
                        m.over_one * 100.0
                    )
                },
            )
        })
        .collect();
    if rows.iter().any(|r| r.mesa.is_ok()) {
        md.push_str("\nWhere some figure of ours is worse than softpipe's:\n\n");
        if worse.is_empty() {
            md.push_str("- none\n");
        }
        for w in &worse {
            let _ = writeln!(md, "- {w}");
        }
        md.push_str(
            "\nWhy, where it happens on the triangle scene: the few pixels off there are \
             edge pixels, each showing a different triangle (their depths differ by far more \
             than interpolation error). We snap window coordinates to 1/256 pixel \
             (`GL_SUBPIXEL_BITS` = 8) and evaluate exact integer edge functions, so a pixel \
             center within about 1/512 pixel of an edge can fall on the other side than in \
             the unsnapped reference; softpipe's setup evaluates unsnapped float edges like \
             the reference does. It is the documented subpixel precision, not an \
             interpolation error: the mean error and the share of pixels off stay near 0. \
             Colors are divided by w per pixel under every hint, as softpipe does.\n",
        );
    }

    md.push_str("\n## The vertex stage\n\n");
    md.push_str(
        "The largest relative error of the vertex stage (`gles_cm_core::vertex::run`, f32) over \
         random inputs, against the same transformation in f64 from the same f32 matrices. \
         Per component, the error is divided by the sum of the magnitudes of the terms \
         (Σ |M_ij · v_j|), the scale any rounding is measured against; colors, clamped to \
         [0, 1], show the absolute error. The modelview rotates, scales and translates, the \
         projection is a perspective with near 0.5 and far 10⁴, the texture matrix rotates, \
         scales and translates. GL asks for 10⁻⁵ (ES 1.1 §2.1.1); M3G for 16 significant \
         bits, 2⁻¹⁶ ≈ 1.53 · 10⁻⁵.\n\n",
    );
    md.push_str("| input | range | samples | largest error | within 10⁻⁵ | within 2⁻¹⁶ |\n");
    md.push_str("|---|---|---|---|---|---|\n");
    let m3g = 2f64.powi(-16);
    for v in vertex_rows() {
        let _ = writeln!(
            md,
            "| {} | {} | {} | {:.2e} | {} | {} |",
            v.what,
            v.range,
            v.samples,
            v.worst,
            if v.worst <= 1e-5 { "yes" } else { "**no**" },
            if v.worst <= m3g { "yes" } else { "**no**" },
        );
    }

    md.push_str("\n## Lighting powers\n\n");
    md.push_str(
        "The specular power (n ⊙ ĥ)^s and the spot power (P̂V·ŝ)^e are computed by \
         `gles_cm_core::vertex::power::pow` (f64 series for log₂ and exp₂, vectorized across \
         the 8 vertices of a batch) instead of a `powf` call per vertex. Against the \
         correctly rounded f32 power (from f64 `powf`), over random bases in [0, 1] \
         (three quarters of the samples) and [1, 2], beside the C library's f32 `powf`; \
         `steps` is the largest difference between the two for bases up to 1, times 255 \
         (a unit specular term in 8-bit steps).\n\n",
    );
    md.push_str(
        "| exponent | samples | ours: max ulps | ours: not correctly rounded | \
         `powf`: max ulps | `powf`: not correctly rounded | ours − `powf`, 8-bit steps |\n",
    );
    md.push_str("|---|---|---|---|---|---|---|\n");
    for p in power_rows() {
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} | {} | {:.1e} |",
            p.exponent, p.samples, p.ours.0, p.ours.1, p.libm.0, p.libm.1, p.steps
        );
    }

    md.push_str("\n## Depth precision\n\n");
    md.push_str(
        "Two parallel screen-filling quads at eye distance d and d + s, the nearer drawn \
         second with depth LESS; `measured` is the smallest s (bisection) at which every \
         pixel shows the nearer quad, `ideal` one step of round(z · (2ⁿ − 1)) converted back \
         to eye space through the exact f64 depth function (far = 1000). `inf`: no \
         separation short of the far plane resolves. A ratio below 1 is no paradox: both \
         quads have one depth each, so a separation under one step resolves whenever the \
         two depths happen to round to different steps; the ideal is the separation that \
         resolves at every position. `tests/properties.rs` asserts measured ≤ 2.5 × ideal \
         wherever the ideal is finite and small.\n\n",
    );
    depth_table(&mut md);

    md.push_str("\n## Edge antialiasing\n\n");
    md.push_str(
        "A fan of 24 thin white triangles on black (96 × 96, RGBA8888, every edge at its own \
         angle), rendered through the core single-sample and on a 4× multisampled target \
         (`gles_cm_core::multisample`); each pixel the fan's edges cross is compared with its exact \
         covered area (the pixel square clipped against the triangles in f64), in 8-bit \
         steps of `area · 255`.\n\n",
    );
    md.push_str("| target | edge pixels | mean error | max error |\n|---|---|---|---|\n");
    for (name, ms) in [("single-sample", false), ("4x MSAA", true)] {
        let e = edges::edge_error(ms);
        let _ = writeln!(
            md,
            "| {name} | {} | {:.1} | {:.1} |",
            e.pixels, e.mean, e.max
        );
    }

    if let Err(e) = std::fs::write(&path, md) {
        eprintln!("writing {}: {e}", path.display());
        return ExitCode::FAILURE;
    }
    eprintln!("wrote {}", path.display());
    ExitCode::SUCCESS
}
