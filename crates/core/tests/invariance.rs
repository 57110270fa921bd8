//! The specification's invariance rules (ES 1.1 Appendix A), on the core: the same
//! primitive drawn under different unrelated state produces identical fragments; a second
//! pass with depth function EQUAL hits exactly the pixels the first pass left visible; and
//! the image does not depend on the thread count (each band of rows is a tile).

#[path = "common/scenes.rs"]
mod scenes;

use glam::Mat4;
use gles_cm_core::state::{
    AlphaTest, Blend, BlendEquation, BlendFactor, LogicOp, PolygonOffset, Quality, StencilOp,
    StencilTest, TexGen,
};
use gles_cm_core::texenv::{EnvMode, Fog, FogMode, TexEnv, TextureUnit};
use gles_cm_core::texture::{MagFilter, MinFilter, Wrap};
use gles_cm_core::{CompareFunc, Frame, Rect, RenderState, Target};
use scenes::Mesh;

const W: u32 = 160;
const H: u32 = 120;

/// The kinds of scene every rule is checked on: one or more (state, mesh) pairs.
struct Scene {
    name: &'static str,
    parts: Vec<(RenderState, Mesh)>,
}

fn scenes(q: Quality) -> Vec<Scene> {
    let base = scenes::perspective_state(W, H, q);
    let mut smooth_lines = base.clone();
    smooth_lines.line_smooth = true;
    smooth_lines.line_width = 2.5;
    let mut wide_lines = base.clone();
    wide_lines.line_width = 3.0;
    let mut big_points = base.clone();
    big_points.point_size = 5.0;
    let mut smooth_points = base.clone();
    smooth_points.point_smooth = true;
    smooth_points.point_size = 6.5;
    vec![
        Scene {
            name: "smooth",
            parts: vec![(base.clone(), scenes::smooth_triangles(60, 1))],
        },
        Scene {
            name: "textured",
            parts: vec![
                (
                    scenes::floor_state(W, H, MinFilter::LinearMipmapLinear, MagFilter::Linear, q),
                    scenes::floor(),
                ),
                (
                    scenes::floor_state(W, H, MinFilter::Nearest, MagFilter::Nearest, q),
                    scenes::smooth_triangles(20, 9).with_texcoords(),
                ),
            ],
        },
        Scene {
            name: "lit",
            parts: scenes::lit_modelviews()
                .into_iter()
                .map(|mv| (scenes::lit_state(W, H, q, mv), scenes::sphere(12, 18)))
                .collect(),
        },
        Scene {
            name: "lines",
            parts: vec![
                (base.clone(), scenes::lines_or_points(150, 2, false)),
                (wide_lines, scenes::lines_or_points(40, 3, false)),
                (smooth_lines, scenes::lines_or_points(40, 4, false)),
            ],
        },
        Scene {
            name: "points",
            parts: vec![
                (base.clone(), scenes::lines_or_points(150, 5, true)),
                (big_points, scenes::lines_or_points(60, 6, true)),
                (smooth_points, scenes::lines_or_points(60, 7, true)),
            ],
        },
    ]
}

trait WithTexcoords {
    fn with_texcoords(self) -> Self;
}
impl WithTexcoords for Mesh {
    /// Adds texture coordinates from the positions (x, y scaled), for a mesh without them.
    fn with_texcoords(mut self) -> Mesh {
        let st: Vec<f32> = self
            .pos
            .chunks_exact(12)
            .flat_map(|p| {
                let x = f32::from_ne_bytes([p[0], p[1], p[2], p[3]]);
                let y = f32::from_ne_bytes([p[4], p[5], p[6], p[7]]);
                [x * 0.7, y * 0.9]
            })
            .collect();
        self.st = Some(scenes::bytes(&st));
        self
    }
}

/// Renders the parts, each with its state changed by `tweak`, on `threads` threads.
fn render_with(
    parts: &[(RenderState, Mesh)],
    t: &mut Target,
    threads: usize,
    tweak: &dyn Fn(&mut RenderState),
) {
    let mut frame = Frame::new(t.width(), t.height(), t.format());
    for (s, m) in parts {
        let mut s = s.clone();
        tweak(&mut s);
        gles_cm_core::record(&s, &m.call(), &mut frame).unwrap();
    }
    frame.flush(t, threads);
}

fn render(parts: &[(RenderState, Mesh)], tweak: &dyn Fn(&mut RenderState)) -> Target {
    let mut t = scenes::target(W, H);
    render_with(parts, &mut t, 2, tweak);
    t
}

/// The first differing pixel of two buffers, for the failure message.
fn first_diff<T: PartialEq + Copy + std::fmt::Debug>(a: &[T], b: &[T]) -> Option<String> {
    a.iter().zip(b).position(|(x, y)| x != y).map(|i| {
        format!(
            "pixel ({}, {}): {:?} vs {:?}",
            i as u32 % W,
            i as u32 / W,
            a[i],
            b[i]
        )
    })
}

/// A change of state.
type Tweak = Box<dyn Fn(&mut RenderState)>;

/// State that must not change any fragment of the scenes (RGBA8888 target, opaque or
/// src-alpha-free colors, nothing in the stencil buffer).
fn unrelated_changes() -> Vec<(&'static str, Tweak)> {
    vec![
        (
            "blend ONE, ZERO",
            Box::new(|s| s.blend = Some(Blend::func(BlendFactor::One, BlendFactor::Zero))),
        ),
        (
            "alpha test ALWAYS",
            Box::new(|s| {
                s.alpha_test = Some(AlphaTest {
                    func: CompareFunc::Always,
                    reference: 0.5,
                })
            }),
        ),
        (
            "alpha test GEQUAL 0",
            Box::new(|s| {
                s.alpha_test = Some(AlphaTest {
                    func: CompareFunc::GreaterEqual,
                    reference: 0.0,
                })
            }),
        ),
        (
            "stencil ALWAYS, KEEP",
            Box::new(|s| {
                s.stencil_test = Some(StencilTest {
                    func: CompareFunc::Always,
                    reference: 3,
                    mask: 0xff,
                    fail: StencilOp::Keep,
                    depth_fail: StencilOp::Keep,
                    depth_pass: StencilOp::Keep,
                })
            }),
        ),
        (
            "stencil EQUAL 0, INCR",
            Box::new(|s| {
                s.stencil_test = Some(StencilTest {
                    func: CompareFunc::Equal,
                    reference: 0,
                    mask: 0,
                    fail: StencilOp::Keep,
                    depth_fail: StencilOp::Incr,
                    depth_pass: StencilOp::Incr,
                })
            }),
        ),
        ("dither on RGBA8888", Box::new(|s| s.dither = true)),
        (
            "logic op COPY",
            Box::new(|s| {
                s.blend = None;
                s.logic_op = Some(LogicOp::Copy)
            }),
        ),
        (
            "fog with factor 1 everywhere",
            Box::new(|s| {
                s.fog = Some(Fog {
                    mode: FogMode::Linear,
                    density: 1.0,
                    start: 100.0,
                    end: 200.0,
                    color: [1.0, 0.0, 1.0, 1.0],
                    quality: Quality::Nicest,
                })
            }),
        ),
        (
            "fog EXP density 0",
            Box::new(|s| {
                s.fog = Some(Fog {
                    mode: FogMode::Exp,
                    density: 0.0,
                    start: 0.0,
                    end: 1.0,
                    color: [0.0, 1.0, 0.0, 1.0],
                    quality: Quality::Fastest,
                })
            }),
        ),
        (
            "other units' matrices and texgen",
            Box::new(|s| {
                for u in 1..gles_cm_core::TEXTURE_UNITS {
                    s.texture_matrices[u] = Mat4::from_scale(glam::Vec3::splat(3.0 + u as f32));
                }
                s.texgen[2] = Some(TexGen::ReflectionMap);
                s.texgen[3] = Some(TexGen::NormalMap);
            }),
        ),
        (
            "scissor covering the target",
            Box::new(|s| s.scissor = Some(Rect::new(0, 0, W as i32, H as i32))),
        ),
    ]
}

#[test]
fn unrelated_state_leaves_fragments_identical() {
    for q in [Quality::Fastest, Quality::Nicest] {
        for scene in scenes(q) {
            let base = render(&scene.parts, &|_| {});
            assert!(
                base.color().iter().any(|&c| c != base.color()[0]),
                "{}: empty image",
                scene.name
            );
            for (what, tweak) in unrelated_changes() {
                let got = render(&scene.parts, &*tweak);
                if let Some(d) = first_diff(base.color(), got.color()) {
                    panic!("{} {q:?}, {what}: color differs at {d}", scene.name);
                }
                if let Some(d) = first_diff(base.depth(), got.depth()) {
                    panic!("{} {q:?}, {what}: depth differs at {d}", scene.name);
                }
            }
        }
    }
}

/// A texture on another unit whose environment passes the color through unchanged
/// (COMBINE would too; ADD of a black texture is simplest to state): ADD with an all-black
/// texture adds 0.
#[test]
fn a_pass_through_unit_leaves_the_lit_and_smooth_scenes_identical() {
    let black = {
        use gles_cm_core::texture::{BaseFormat, Image, Texture};
        let mut t = Texture::new();
        t.set_level(
            0,
            Image {
                width: 2,
                height: 2,
                format: BaseFormat::Rgba,
                texels: vec![0; 4],
            },
        );
        t.min_filter = MinFilter::Nearest;
        t.sampler().expect("complete")
    };
    for scene in scenes(Quality::Nicest) {
        if scene.name != "lit" && scene.name != "smooth" {
            continue;
        }
        let base = render(&scene.parts, &|_| {});
        let got = render(&scene.parts, &|s| {
            s.textures[1] = Some(TextureUnit {
                sampler: black.clone(),
                env: TexEnv {
                    mode: EnvMode::Add,
                    color: [0.0; 4],
                },
                coord_replace: false,
            });
        });
        // ADD adds the texture's RGB (0) and multiplies alpha by its alpha (0): compare RGB.
        let rgb = |t: &Target| {
            t.color()
                .iter()
                .map(|c| c & 0x00ff_ffff)
                .collect::<Vec<_>>()
        };
        if let Some(d) = first_diff(&rgb(&base), &rgb(&got)) {
            panic!("{}: color differs at {d}", scene.name);
        }
        assert_eq!(base.depth(), got.depth(), "{}", scene.name);
    }
}

/// Depth ALWAYS instead of LESS on a single layer (each part drawn alone into a cleared
/// buffer, with no overlaps inside it that would change which fragment wins): the sphere's
/// back faces are culled so that every pixel has one fragment.
#[test]
fn depth_always_and_less_agree_on_a_single_layer() {
    let scene = scenes(Quality::Nicest).remove(2);
    for (s, m) in &scene.parts {
        let mut s = s.clone();
        s.cull = Some(gles_cm_core::CullFace::Back);
        let one = [(s.clone(), mesh_copy(m))];
        let base = render(&one, &|_| {});
        let got = render(&one, &|s| s.depth_test = Some(CompareFunc::Always));
        assert_eq!(first_diff(base.color(), got.color()), None);
        assert_eq!(first_diff(base.depth(), got.depth()), None);
    }
}

fn mesh_copy(m: &Mesh) -> Mesh {
    Mesh {
        primitive: m.primitive,
        pos: m.pos.clone(),
        col: m.col.clone(),
        nrm: m.nrm.clone(),
        st: m.st.clone(),
        idx: m.idx.clone(),
        vertices: m.vertices,
    }
}

/// Multipass: draw the scene with depth LESS, then again with depth EQUAL, no depth writes,
/// a stencil increment on depth pass and a modulating blend (the classic second pass). The
/// second pass must hit exactly the pixels whose depth the first pass wrote, each once, with
/// polygon offset disabled or enabled at (0, 0).
#[test]
fn a_second_pass_with_depth_equal_hits_the_same_pixels() {
    for q in [Quality::Fastest, Quality::Nicest] {
        for scene in scenes(q) {
            if scene.name == "lines" || scene.name == "points" {
                continue;
            }
            for offset in [false, true] {
                let mut t = scenes::target(W, H);
                render_with(&scene.parts, &mut t, 2, &|_| {});
                let written: Vec<bool> = t.depth().iter().map(|&z| z != 0xff_ffff).collect();
                assert!(written.iter().filter(|&&w| w).count() > 500);
                render_with(&scene.parts, &mut t, 2, &|s| {
                    s.depth_test = Some(CompareFunc::Equal);
                    s.depth_write = false;
                    s.blend = Some(Blend::func(BlendFactor::DstColor, BlendFactor::Zero));
                    s.stencil_test = Some(StencilTest {
                        func: CompareFunc::Always,
                        reference: 0,
                        mask: 0xff,
                        fail: StencilOp::Keep,
                        depth_fail: StencilOp::Keep,
                        depth_pass: StencilOp::Incr,
                    });
                    if offset {
                        s.polygon_offset = Some(PolygonOffset {
                            factor: 0.0,
                            units: 0.0,
                            clamp: 0.0,
                        });
                    }
                });
                for (i, (&w, &st)) in written.iter().zip(t.stencil()).enumerate() {
                    let (x, y) = (i as u32 % W, i as u32 / W);
                    assert!(
                        w == (st > 0),
                        "{} {q:?} offset {offset}: pixel ({x}, {y}) written {w}, second pass hit {st} times",
                        scene.name
                    );
                    // More than one hit: two triangles with one depth at one pixel, which
                    // the scenes do not have (shared edges are owned once).
                    assert!(st <= 1, "{} ({x}, {y}) hit {st} times", scene.name);
                }
            }
        }
    }
}

/// The same frame flushed on 1, 2 and 8 threads gives the same color, depth and stencil.
#[test]
fn images_do_not_depend_on_the_thread_count() {
    for q in [Quality::Fastest, Quality::Nicest] {
        for scene in scenes(q) {
            let with_stencil = |s: &mut RenderState| {
                s.stencil_test = Some(StencilTest {
                    func: CompareFunc::Always,
                    reference: 0,
                    mask: 0xff,
                    fail: StencilOp::Keep,
                    depth_fail: StencilOp::IncrWrap,
                    depth_pass: StencilOp::Incr,
                });
                s.blend = Some(Blend::func(
                    BlendFactor::SrcAlpha,
                    BlendFactor::OneMinusSrcAlpha,
                ));
            };
            let images: Vec<Target> = [1, 2, 8]
                .into_iter()
                .map(|threads| {
                    let mut t = scenes::target(W, H);
                    render_with(&scene.parts, &mut t, threads, &with_stencil);
                    t
                })
                .collect();
            for (k, t) in images.iter().enumerate().skip(1) {
                let n = [1, 2, 8][k];
                assert_eq!(
                    first_diff(images[0].color(), t.color()),
                    None,
                    "{} {q:?}: color, 1 vs {n} threads",
                    scene.name
                );
                assert_eq!(
                    first_diff(images[0].depth(), t.depth()),
                    None,
                    "{} {q:?}: depth, 1 vs {n} threads",
                    scene.name
                );
                assert_eq!(
                    first_diff(images[0].stencil(), t.stencil()),
                    None,
                    "{} {q:?}: stencil, 1 vs {n} threads",
                    scene.name
                );
            }
        }
    }
}

/// The vectorized span routine (no alpha test) and the per-pixel one (alpha test ALWAYS, an
/// unrelated state) agree on every filter pair that depends on λ and on the COMBINE
/// functions, including a second unit whose primary color differs from its previous one.
#[test]
fn lod_filters_and_combine_agree_across_span_routines() {
    use gles_cm_core::texenv::{Combine, CombineFunc, Operand, Source};
    let always = |s: &mut RenderState| {
        s.alpha_test = Some(AlphaTest {
            func: CompareFunc::Always,
            reference: 0.5,
        })
    };
    let check = |what: &str, parts: &[(RenderState, Mesh)]| {
        let base = render(parts, &|_| {});
        assert!(
            base.color().iter().any(|&c| c != base.color()[0]),
            "{what}: empty image"
        );
        let got = render(parts, &always);
        if let Some(d) = first_diff(base.color(), got.color()) {
            panic!("{what}: color differs at {d}");
        }
    };
    for q in [Quality::Fastest, Quality::Nicest] {
        for (min, mag) in [
            (MinFilter::NearestMipmapNearest, MagFilter::Nearest),
            (MinFilter::LinearMipmapNearest, MagFilter::Linear),
            (MinFilter::NearestMipmapLinear, MagFilter::Nearest),
            (MinFilter::LinearMipmapLinear, MagFilter::Nearest),
            (MinFilter::Linear, MagFilter::Nearest),
            (MinFilter::Nearest, MagFilter::Linear),
        ] {
            let s = scenes::floor_state(W, H, min, mag, q);
            check(&format!("{min:?}/{mag:?} {q:?}"), &[(s, scenes::floor())]);
        }
    }
    let funcs = [
        CombineFunc::Replace,
        CombineFunc::Modulate,
        CombineFunc::Add,
        CombineFunc::AddSigned,
        CombineFunc::Interpolate,
        CombineFunc::Subtract,
    ];
    let sources = [
        Source::Texture,
        Source::Previous,
        Source::PrimaryColor,
        Source::Constant,
    ];
    let operands = [
        Operand::SrcColor,
        Operand::OneMinusSrcColor,
        Operand::SrcAlpha,
        Operand::OneMinusSrcAlpha,
    ];
    for (i, &rgb) in funcs.iter().enumerate() {
        for unit in [0, 1] {
            let pick = |k: usize| (sources[(i + k + unit) % 4], operands[(2 * i + k) % 4]);
            let (s0, o0) = pick(0);
            let (s1, o1) = pick(1);
            let (s2, o2) = pick(2);
            let combine = Combine {
                rgb,
                alpha: funcs[(i + 3) % funcs.len()],
                src_rgb: [s0, s1, s2],
                src_alpha: [s2, s0, s1],
                operand_rgb: [o0, o1, o2],
                operand_alpha: [o1, o2, o0],
                rgb_scale: [1.0, 2.0, 4.0][i % 3],
                alpha_scale: [2.0, 1.0][i % 2],
            };
            let mut s = scenes::floor_state(
                W,
                H,
                MinFilter::LinearMipmapLinear,
                MagFilter::Linear,
                Quality::Nicest,
            );
            let sampler = s.textures[0].as_ref().expect("a unit").sampler.clone();
            s.textures[unit] = Some(TextureUnit {
                sampler,
                env: TexEnv {
                    mode: EnvMode::Combine(combine),
                    color: [0.2, 0.9, 0.4, 0.7],
                },
                coord_replace: false,
            });
            check(
                &format!("COMBINE {rgb:?} on unit {unit}"),
                &[(s, scenes::floor())],
            );
        }
    }
}

/// Every span route the vectorized code has (simple: depth × smooth (DONT_CARE and
/// FASTEST hints) × blend, including the one-word fill and small triangles' short spans;
/// textured: fog only, NEAREST, bilinear, trilinear (λ per pixel and FASTEST's), other
/// filters, several units, sizes other than powers of two under each wrap mode; with and
/// without depth and blending) on every color format, with dithering off and on, gives the
/// pixels of the per-pixel routine (alpha test ALWAYS, an unrelated state that only the
/// per-pixel routine handles).
#[test]
fn every_route_on_every_format_agrees_with_the_per_pixel_routine() {
    use gles_cm_core::{ColorFormat, DepthFormat, TargetFormat};
    let formats = [
        ColorFormat::Rgba8888,
        ColorFormat::Rgb888,
        ColorFormat::Rgb565,
        ColorFormat::Rgba4444,
        ColorFormat::Rgba5551,
    ];
    let always = |s: &mut RenderState| {
        s.alpha_test = Some(AlphaTest {
            func: CompareFunc::Always,
            reference: 0.5,
        })
    };
    // Translucent colors, so blending reads and writes every channel (alpha included).
    let translucent = |mut m: Mesh| {
        for c in m.col.iter_mut().flat_map(|c| c.chunks_exact_mut(16)) {
            let a = f32::from_ne_bytes([c[0], c[1], c[2], c[3]]) * 0.6 + 0.2;
            c[12..16].copy_from_slice(&a.to_ne_bytes());
        }
        m
    };
    let blend = Blend::func(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha);
    let smooth = scenes::perspective_state(W, H, Quality::Nicest);
    let floor = |min, mag| scenes::floor_state(W, H, min, mag, Quality::Nicest);
    /// A route's name, its state and the mesh drawn with it.
    type Route = (String, RenderState, fn() -> Mesh);
    let mut routes: Vec<Route> = Vec::new();
    for depth in [false, true] {
        for blending in [false, true] {
            let setup = |mut s: RenderState| {
                if !depth {
                    s.depth_test = None;
                }
                s.blend = blending.then_some(blend);
                s
            };
            let how = format!("depth {depth}, blend {blending}");
            routes.push((format!("smooth, {how}"), setup(smooth.clone()), || {
                scenes::smooth_triangles(40, 11)
            }));
            // GL_FASTEST perspective hint (and its reciprocal decode when blending).
            let fastest = setup(scenes::perspective_state(W, H, Quality::Fastest));
            routes.push((format!("smooth FASTEST, {how}"), fastest, || {
                scenes::smooth_triangles(40, 14)
            }));
            let mut flat = setup(smooth.clone());
            flat.shade_model = gles_cm_core::state::ShadeModel::Flat;
            if blending {
                // The floor's spans are long enough for a flat color's blend to be worked
                // out once a span: the alpha blend, and other factors and equations.
                routes.push((format!("flat floor, {how}"), flat.clone(), scenes::floor));
                let mut other = flat.clone();
                other.blend = Some(Blend {
                    eq_alpha: BlendEquation::Subtract,
                    ..Blend::func(BlendFactor::OneMinusSrcColor, BlendFactor::SrcColor)
                });
                routes.push((
                    format!("flat floor, other blend, {how}"),
                    other,
                    scenes::floor,
                ));
            }
            // Spans too short for a group of their own, drawn pixel by pixel.
            routes.push((
                format!("small smooth, {how}"),
                setup(smooth.clone()),
                || scenes::small_triangles(300, 15),
            ));
            routes.push((format!("small flat, {how}"), flat.clone(), || {
                scenes::small_triangles(300, 16)
            }));
            routes.push((format!("flat, {how}"), flat, || {
                scenes::smooth_triangles(40, 12)
            }));
            let mut fogged = setup(smooth.clone());
            fogged.fog = Some(Fog {
                mode: FogMode::Linear,
                density: 1.0,
                start: 2.0,
                end: 14.0,
                color: [0.9, 0.3, 0.6, 0.5],
                quality: Quality::Nicest,
            });
            routes.push((format!("fog only, {how}"), fogged, || {
                scenes::smooth_triangles(40, 13)
            }));
            for (min, mag) in [
                (MinFilter::Nearest, MagFilter::Nearest),
                (MinFilter::Linear, MagFilter::Linear),
                (MinFilter::LinearMipmapLinear, MagFilter::Linear),
                (MinFilter::LinearMipmapNearest, MagFilter::Nearest),
            ] {
                routes.push((
                    format!("{min:?}/{mag:?}, {how}"),
                    setup(floor(min, mag)),
                    scenes::floor,
                ));
            }
            // GL_FASTEST perspective hint (λ per pixel as under the others; a narrow
            // destination blended through a reciprocal).
            let fastest = |min, mag| scenes::floor_state(W, H, min, mag, Quality::Fastest);
            for min in [
                MinFilter::LinearMipmapLinear,
                MinFilter::NearestMipmapNearest,
            ] {
                routes.push((
                    format!("{min:?} FASTEST, {how}"),
                    setup(fastest(min, MagFilter::Linear)),
                    scenes::floor,
                ));
            }
            let mut two = setup(floor(MinFilter::Linear, MagFilter::Linear));
            two.textures[1] = two.textures[0].clone();
            routes.push((format!("two units, {how}"), two, scenes::floor));
        }
    }
    // Sizes other than powers of two wrap by a quotient, each mode its own way.
    for wrap in [Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat] {
        for (min, mag) in [
            (MinFilter::Nearest, MagFilter::Nearest),
            (MinFilter::Linear, MagFilter::Linear),
            (MinFilter::LinearMipmapLinear, MagFilter::Linear),
        ] {
            let mut s = floor(min, mag);
            if let Some(unit) = s.textures[0].as_mut() {
                unit.sampler = scenes::texture_sized(37, 23, min, mag, wrap);
            }
            routes.push((format!("37x23 {wrap:?} {min:?}/{mag:?}"), s, scenes::floor));
        }
    }
    for format in formats {
        for dither in [false, true] {
            let target = || {
                let mut t = Target::new(
                    W,
                    H,
                    TargetFormat {
                        color: format,
                        depth: Some(DepthFormat::D24),
                        stencil_bits: 8,
                    },
                );
                t.clear_color(t.bounds(), [0.31, 0.52, 0.73, 0.44], [true; 4]);
                t.clear_depth(t.bounds(), 1.0);
                t
            };
            for (what, state, mesh) in &routes {
                let mut s = state.clone();
                s.dither = dither;
                let parts = [(s, translucent(mesh()))];
                let mut base = target();
                render_with(&parts, &mut base, 2, &|_| {});
                assert!(
                    base.color().iter().any(|&c| c != base.color()[0]),
                    "{what} {format:?}: empty image"
                );
                let mut got = target();
                render_with(&parts, &mut got, 2, &always);
                let name = format!("{what}, {format:?}, dither {dither}");
                if let Some(d) = first_diff(base.color(), got.color()) {
                    panic!("{name}: color differs at {d}");
                }
                if let Some(d) = first_diff(base.depth(), got.depth()) {
                    panic!("{name}: depth differs at {d}");
                }
            }
        }
    }
}
