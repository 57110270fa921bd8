//! The core's own tests: the fast path against the f64 reference renderer
//! ([`super::reference`]), exact coverage rules, and images that must not depend on the
//! thread count or the viewport split.

use super::reference::ErrorStats;
use super::*;
use glam::Mat4;

fn target(w: u32, h: u32) -> Target {
    Target::new(
        w,
        h,
        TargetFormat {
            color: ColorFormat::Rgba8888,
            depth: Some(DepthFormat::D24),
            stencil_bits: 8,
        },
    )
}

/// The bytes of `v`, as a client array holds them.
fn bytes(v: &[f32]) -> Vec<u8> {
    v.iter().flat_map(|x| x.to_ne_bytes()).collect()
}

/// `count` vertices of float x, y, z from `pb`, every other input at its default.
fn positions_call(prim: Primitive, pb: &[u8], count: usize) -> DrawCall<'_> {
    DrawCall::new(
        prim,
        Indices::Range { first: 0, count },
        AttribArray {
            data: pb,
            ty: ComponentType::Float,
            size: 3,
            stride: 12,
            normalized: false,
        },
    )
}

/// As [`positions_call`], with float RGBA colors from `cb`.
fn colored_call<'a>(prim: Primitive, pb: &'a [u8], cb: &'a [u8], count: usize) -> DrawCall<'a> {
    DrawCall {
        color: AttribSource::Array(AttribArray {
            data: cb,
            ty: ComponentType::Float,
            size: 4,
            stride: 16,
            normalized: false,
        }),
        ..positions_call(prim, pb, count)
    }
}

/// A state whose projection maps object x, y straight to window pixels.
fn pixel_state(w: i32, h: i32) -> RenderState {
    let mut s = RenderState::new(w, h);
    s.projection = Mat4::orthographic_rh_gl(0.0, w as f32, 0.0, h as f32, -1.0, 1.0);
    s
}

fn draw(state: &RenderState, t: &mut Target, xyz: &[f32], color: [f32; 4], prim: Primitive) {
    let pb = bytes(xyz);
    let call = DrawCall {
        color: AttribSource::Constant(color),
        ..positions_call(prim, &pb, xyz.len() / 3)
    };
    render(state, &call, t).unwrap();
}

fn ms_target(w: u32, h: u32) -> Target {
    let f = target(1, 1).format();
    Target::try_new_multisample(w, h, f, true).unwrap()
}

/// A rectangle x in [0, 2.5], y in [0, 8]: pixel column 2 is half covered.
const HALF_EDGE: [f32; 18] = [
    0.0, 0.0, 0.0, 2.5, 0.0, 0.0, 2.5, 8.0, 0.0, 0.0, 0.0, 0.0, 2.5, 8.0, 0.0, 0.0, 8.0, 0.0,
];

fn row(t: &Target, y: u32) -> Vec<[u8; 4]> {
    (0..t.width()).map(|x| t.pixel(x, y)).collect()
}

#[test]
fn multisampled_edges_resolve_to_the_covered_share() {
    let mut t = ms_target(8, 8);
    assert_eq!(t.samples(), 4);
    draw(
        &pixel_state(8, 8),
        &mut t,
        &HALF_EDGE,
        [1.0; 4],
        Primitive::Triangles,
    );
    // Samples at x + 0.125 and x + 0.375 are left of 2.5: two of four.
    let r = row(&t, 3);
    assert_eq!(&r[..4], &[[255; 4], [255; 4], [128; 4], [0; 4]]);
    // Every row alike, and only the resolved edge column is partial.
    assert!((0..8).all(|y| row(&t, y) == r));
}

#[test]
fn multisample_disabled_matches_a_single_sample_target_bit_for_bit() {
    let mut s = pixel_state(16, 16);
    s.multisample.enabled = false;
    let xyz = [0.3, 0.2, 0.0, 15.1, 3.7, 0.0, 6.4, 14.9, 0.0];
    let (mut ms, mut single) = (ms_target(16, 16), target(16, 16));
    draw(
        &s,
        &mut ms,
        &xyz,
        [0.9, 0.4, 0.2, 1.0],
        Primitive::Triangles,
    );
    draw(
        &s,
        &mut single,
        &xyz,
        [0.9, 0.4, 0.2, 1.0],
        Primitive::Triangles,
    );
    assert_eq!(ms.color(), single.color());
    s.multisample.enabled = true;
    let mut aa = ms_target(16, 16);
    draw(
        &s,
        &mut aa,
        &xyz,
        [0.9, 0.4, 0.2, 1.0],
        Primitive::Triangles,
    );
    assert_ne!(aa.color(), single.color());
}

#[test]
fn sample_coverage_and_alpha_masks_select_samples() {
    let mut s = pixel_state(8, 8);
    // Value 0.5: samples 0 and 1; inverted: 2 and 3 (of which 2 is left of the edge).
    s.multisample.coverage = Some((0.5, false));
    let mut t = ms_target(8, 8);
    draw(&s, &mut t, &HALF_EDGE, [1.0; 4], Primitive::Triangles);
    assert_eq!(&row(&t, 0)[..4], &[[128; 4], [128; 4], [64; 4], [0; 4]]);
    s.multisample.coverage = Some((0.5, true));
    let mut t = ms_target(8, 8);
    draw(&s, &mut t, &HALF_EDGE, [1.0; 4], Primitive::Triangles);
    assert_eq!(&row(&t, 0)[..4], &[[128; 4], [128; 4], [64; 4], [0; 4]]);
    // Alpha to coverage: alpha 0.5 (128) covers samples 0 and 1.
    s.multisample.coverage = None;
    s.multisample.alpha_to_coverage = true;
    let mut t = ms_target(8, 8);
    draw(
        &s,
        &mut t,
        &HALF_EDGE,
        [1.0, 1.0, 1.0, 0.5],
        Primitive::Triangles,
    );
    assert_eq!(row(&t, 0)[0], [128, 128, 128, 64]);
    assert_eq!(row(&t, 0)[2], [64, 64, 64, 32]);
    // Alpha to one: the covered samples store alpha 1.
    s.multisample.alpha_to_one = true;
    let mut t = ms_target(8, 8);
    draw(
        &s,
        &mut t,
        &HALF_EDGE,
        [1.0, 1.0, 1.0, 0.5],
        Primitive::Triangles,
    );
    assert_eq!(row(&t, 0)[0], [128; 4]);
}

#[test]
fn multisampled_frames_are_the_same_for_any_thread_count() {
    let s = pixel_state(64, 64);
    let mut rng = Lcg(7);
    let xyz: Vec<f32> = (0..90)
        .map(|i| if i % 3 == 2 { 0.0 } else { rng.next() * 64.0 })
        .collect();
    let pb = bytes(&xyz);
    let call = positions_call(Primitive::Triangles, &pb, 30);
    let images: Vec<Vec<u32>> = [1, 2, 4]
        .iter()
        .map(|&threads| {
            let mut t = ms_target(64, 64);
            let mut frame = Frame::for_target(&t);
            record(&s, &call, &mut frame).unwrap();
            frame.flush(&mut t, threads);
            t.color().to_vec()
        })
        .collect();
    assert!(images.windows(2).all(|w| w[0] == w[1]));
}

fn count(t: &Target, rgba: [u8; 4]) -> usize {
    t.color()
        .iter()
        .filter(|&&w| w.to_le_bytes() == rgba)
        .count()
}

#[test]
fn a_square_of_two_triangles_covers_each_pixel_once() {
    let mut t = target(16, 16);
    let s = pixel_state(16, 16);
    // Two triangles sharing the diagonal; colors add up in the red channel only if a
    // pixel is hit twice, which the depth test (EQUAL after the first write) catches.
    let quad = [
        2., 3., 0., 12., 3., 0., 12., 11., 0., 2., 3., 0., 12., 11., 0., 2., 11., 0.,
    ];
    draw(&s, &mut t, &quad, [1., 0., 0., 1.], Primitive::Triangles);
    assert_eq!(count(&t, [255, 0, 0, 255]), 10 * 8);
    for y in 3..11 {
        for x in 2..12 {
            assert_eq!(t.pixel(x, y), [255, 0, 0, 255], "({x},{y})");
        }
    }
}

#[test]
fn shared_edges_are_drawn_exactly_once() {
    // A fan with arbitrary, non-integer vertices; every pixel is counted by its triangle.
    let mut hits = vec![0u32; 32 * 32];
    let center = [15.3f32, 16.7];
    let ring: Vec<[f32; 2]> = (0..=12)
        .map(|i| {
            let a = i as f32 / 12.0 * std::f32::consts::TAU;
            [center[0] + 13.1 * a.cos(), center[1] + 12.7 * a.sin()]
        })
        .collect();
    let s = pixel_state(32, 32);
    for i in 0..12 {
        let mut t = target(32, 32);
        let tri = [
            center[0],
            center[1],
            0.,
            ring[i][0],
            ring[i][1],
            0.,
            ring[i + 1][0],
            ring[i + 1][1],
            0.,
        ];
        draw(&s, &mut t, &tri, [1., 1., 1., 1.], Primitive::Triangles);
        for (h, w) in hits.iter_mut().zip(t.color()) {
            *h += u32::from(w.to_le_bytes()[0] == 255);
        }
    }
    assert!(hits.iter().all(|&h| h <= 1), "a pixel was drawn twice");
    // The fan's interior is covered without gaps.
    for y in 10..22 {
        for x in 10..22 {
            assert_eq!(hits[y * 32 + x], 1, "gap at ({x},{y})");
        }
    }
}

#[test]
fn depth_test_keeps_the_nearer_triangle_in_either_order() {
    let s = {
        let mut s = pixel_state(8, 8);
        s.depth_test = Some(CompareFunc::Less);
        s
    };
    let tri = |z: f32| [0., 0., z, 8., 0., z, 0., 8., z];
    for order in [[0.5f32, -0.5], [-0.5, 0.5]] {
        let mut t = target(8, 8);
        for z in order {
            let color = if z < 0.0 {
                [0., 1., 0., 1.]
            } else {
                [0., 0., 1., 1.]
            };
            // Ortho maps object z to window depth 0.5 - z/2... nearer is larger z here.
            draw(&s, &mut t, &tri(z), color, Primitive::Triangles);
        }
        // glOrtho(near=-1, far=1) looks down -z: window depth = (1 - z) / 2 for z in
        // object space, so z = 0.5 is nearer (depth 0.25) than z = -0.5 (0.75).
        assert_eq!(t.pixel(1, 1), [0, 0, 255, 255]);
    }
}

#[test]
fn triangles_behind_the_eye_leave_no_garbage() {
    let mut t = target(8, 8);
    let mut s = RenderState::new(8, 8);
    s.projection = Mat4::perspective_rh_gl(1.0, 1.0, 0.1, 10.0);
    let tri = [0., 0., 1., 1., 0., 1., 0., 1., -1.];
    draw(&s, &mut t, &tri, [1., 1., 1., 1.], Primitive::Triangles);
    let z = [0., 0., 0., 0., 0., 0., 0., 0., 0.];
    draw(&s, &mut t, &z, [1., 1., 1., 1.], Primitive::Triangles);
    assert_eq!(
        count(&t, [0, 0, 0, 0]),
        64,
        "nothing in front of the eye was drawn"
    );
}

/// A seeded generator of test data, the same on every run: the next value in [0, 1).
pub(crate) struct Lcg(pub(crate) u64);
impl Lcg {
    pub(crate) fn next(&mut self) -> f32 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 40) as f32 / (1u64 << 24) as f32
    }
}

#[test]
fn fast_path_matches_the_reference_on_random_perspective_triangles() {
    let mut rng = Lcg(7);
    let mut s = RenderState::new(96, 64);
    s.projection = Mat4::perspective_rh_gl(1.2, 1.5, 0.5, 20.0);
    s.depth_test = Some(CompareFunc::LessEqual);
    let mut fast = target(96, 64);
    let mut slow = target(96, 64);
    for _ in 0..60 {
        let mut pos = Vec::new();
        let mut col = Vec::new();
        for _ in 0..3 {
            pos.extend([
                rng.next() * 8.0 - 4.0,
                rng.next() * 6.0 - 3.0,
                -1.0 - rng.next() * 10.0,
            ]);
            col.extend([rng.next(), rng.next(), rng.next(), 1.0]);
        }
        let pb = bytes(&pos);
        let cb = bytes(&col);
        let call = colored_call(Primitive::Triangles, &pb, &cb, 3);
        render(&s, &call, &mut fast).unwrap();
        reference::render(&s, &call, &mut slow);
    }
    let e = reference::compare(&fast, &slow);
    // Snapping to 1/256 pixel moves edges by at most 1/512 pixel, so only pixels whose
    // centers lie that close to an edge may change coverage; colors differ by f32
    // rounding (at most one step). Those bounds give the tolerances.
    eprintln!("fast vs reference: {e:?}");
    assert!(e.over_one < 0.01, "{e:?}");
    assert!(e.mean < 0.5, "{e:?}");
    assert!(e.psnr > 35.0, "{e:?}");
}

#[test]
fn pixels_do_not_depend_on_the_thread_count() {
    let mut rng = Lcg(99);
    let mut s = RenderState::new(80, 70);
    s.projection = Mat4::orthographic_rh_gl(0.0, 80.0, 0.0, 70.0, -1.0, 1.0);
    s.depth_test = Some(CompareFunc::Less);
    let mut pos = Vec::new();
    let mut col = Vec::new();
    for _ in 0..300 {
        pos.extend([
            rng.next() * 90.0 - 5.0,
            rng.next() * 80.0 - 5.0,
            rng.next() * 2.0 - 1.0,
        ]);
        col.extend([rng.next(), rng.next(), rng.next(), 1.0]);
    }
    let pb = bytes(&pos);
    let cb = bytes(&col);
    let call = colored_call(Primitive::Triangles, &pb, &cb, 300);
    let images: Vec<Target> = [1, 2, 3, 8]
        .iter()
        .map(|&threads| {
            let mut t = target(80, 70);
            let mut frame = Frame::new(80, 70, t.format());
            frame.clear_color(t.bounds(), 0x11223344, 0);
            record(&s, &call, &mut frame).unwrap();
            frame.flush(&mut t, threads);
            t
        })
        .collect();
    for t in &images[1..] {
        assert_eq!(t.color(), images[0].color());
        assert_eq!(t.depth(), images[0].depth());
    }
    assert!(
        images[0].color().iter().any(|&w| w != 0x11223344),
        "something was drawn"
    );
}

/// Frames handed to the workers while recording goes on (what a GL context does whenever
/// its frame fills) land in recording order, for any worker count, whether the last batch
/// is waited for or the frame is dropped with it still behind. Without a depth test each
/// pixel shows the last triangle over it, so a batch landing early or late changes the
/// image. 40 draws of 300 triangles fill the frame (4096 primitives) twice over.
#[test]
fn batches_flushed_behind_land_in_recording_order() {
    let (w, h) = (80, 70);
    let s = pixel_state(w, h);
    let mut rng = Lcg(5);
    let draws: Vec<(Vec<u8>, Vec<u8>)> = (0..40)
        .map(|_| {
            let pos: Vec<f32> = (0..2700)
                .map(|i| match i % 3 {
                    0 => rng.next() * 100.0 - 10.0,
                    1 => rng.next() * 90.0 - 10.0,
                    _ => 0.0,
                })
                .collect();
            let col: Vec<f32> = (0..3600).map(|_| rng.next()).collect();
            (bytes(&pos), bytes(&col))
        })
        .collect();
    let calls: Vec<DrawCall<'_>> = draws
        .iter()
        .map(|(p, c)| colored_call(Primitive::Triangles, p, c, 900))
        .collect();
    let mut expected = target(w as u32, h as u32);
    let mut frame = Frame::for_target(&expected);
    for call in &calls {
        record(&s, call, &mut frame).unwrap();
    }
    frame.flush(&mut expected, 1);
    for threads in [2, 3, 8] {
        for drop_last in [false, true] {
            let shared = Arc::new(Mutex::new(target(w as u32, h as u32)));
            let to = || shared.clone() as Arc<dyn SharedTarget>;
            let mut frame = Frame::for_target(&shared.lock().unwrap());
            let mut handed = 0;
            for call in &calls {
                if frame.is_full() {
                    frame.flush_behind_on(to(), threads);
                    handed += 1;
                }
                record(&s, call, &mut frame).unwrap();
            }
            frame.flush_behind_on(to(), threads);
            if drop_last {
                drop(frame);
            } else {
                frame.wait();
            }
            assert!(handed >= 2, "the frame filled {handed} times");
            let got = shared.lock().unwrap();
            assert!(
                got.color() == expected.color(),
                "{threads} threads, last batch {}",
                if drop_last { "dropped" } else { "waited for" }
            );
        }
    }
}

/// Random triangles with vertices on the 1/256-pixel grid and inside the viewport, so
/// nothing is clipped, snapping is exact and the fast path covers exactly the reference's
/// pixels; colors are random, alpha included.
fn grid_scene(rng: &mut Lcg, n: usize, w: f32, h: f32) -> (Vec<u8>, Vec<u8>) {
    let (mut pos, mut col) = (Vec::new(), Vec::new());
    for _ in 0..n * 3 {
        let snap = |v: f32| (v * 256.0).round() / 256.0;
        pos.extend([
            snap(rng.next() * w),
            snap(rng.next() * h),
            rng.next() * 1.8 - 0.9,
        ]);
        col.extend([rng.next(), rng.next(), rng.next(), rng.next()]);
    }
    (bytes(&pos), bytes(&col))
}

/// Renders `n` grid triangles with `s` both ways into targets of `format`, prefilled with
/// a pattern (color, depth, stencil), and returns the error of the fast path.
/// Also returns the share of stencil values that differ.
fn fast_vs_reference(s: &RenderState, format: TargetFormat, seed: u64) -> (ErrorStats, f64) {
    let (w, h) = (48, 40);
    let mut rng = Lcg(seed);
    let (pb, cb) = grid_scene(&mut rng, 40, w as f32, h as f32);
    let call = colored_call(Primitive::Triangles, &pb, &cb, 120);
    let prefill = |t: &mut Target| {
        let (c, d, st) = t.buffers_mut();
        for (i, v) in c.iter_mut().enumerate() {
            *v = (i as u32).wrapping_mul(2654435761);
        }
        for (i, v) in d.iter_mut().enumerate() {
            *v = (i as u32 * 7919) % 65536;
        }
        for (i, v) in st.iter_mut().enumerate() {
            *v = (i % 7) as u8;
        }
        let f = t.format().color;
        for v in t.color_mut() {
            *v = f.quantize8(*v);
        }
    };
    let mut fast = Target::new(w, h, format);
    let mut slow = Target::new(w, h, format);
    prefill(&mut fast);
    prefill(&mut slow);
    render(s, &call, &mut fast).unwrap();
    reference::render(s, &call, &mut slow);
    let stencil_off = fast
        .stencil()
        .iter()
        .zip(slow.stencil())
        .filter(|(a, b)| a != b)
        .count();
    (
        reference::compare(&fast, &slow),
        stencil_off as f64 / fast.stencil().len().max(1) as f64,
    )
}

#[test]
fn every_fragment_operation_matches_the_reference() {
    use crate::state::*;
    let rgba = TargetFormat {
        color: ColorFormat::Rgba8888,
        depth: Some(DepthFormat::D16),
        stencil_bits: 8,
    };
    let rgb565 = TargetFormat {
        color: ColorFormat::Rgb565,
        ..rgba
    };
    let base = {
        let mut s = RenderState::new(48, 40);
        s.projection = Mat4::orthographic_rh_gl(0.0, 48.0, 0.0, 40.0, -1.0, 1.0);
        s
    };
    let mut cases: Vec<(String, RenderState, TargetFormat)> = Vec::new();
    let mut add = |name: String, f: &dyn Fn(&mut RenderState), format| {
        let mut s = base.clone();
        f(&mut s);
        cases.push((name, s, format));
    };
    let funcs = [
        CompareFunc::Never,
        CompareFunc::Less,
        CompareFunc::Equal,
        CompareFunc::LessEqual,
        CompareFunc::Greater,
        CompareFunc::NotEqual,
        CompareFunc::GreaterEqual,
        CompareFunc::Always,
    ];
    for func in funcs {
        add(
            format!("depth {func:?}"),
            &|s| s.depth_test = Some(func),
            rgba,
        );
        add(
            format!("alpha {func:?}"),
            &|s| {
                s.alpha_test = Some(AlphaTest {
                    func,
                    reference: 0.5,
                })
            },
            rgba,
        );
    }
    let ops = [
        StencilOp::Keep,
        StencilOp::Zero,
        StencilOp::Replace,
        StencilOp::Incr,
        StencilOp::Decr,
        StencilOp::Invert,
        StencilOp::IncrWrap,
        StencilOp::DecrWrap,
    ];
    for (i, func) in funcs.into_iter().enumerate() {
        let (fail, zfail, zpass) = (ops[i], ops[(i + 3) % 8], ops[(i + 5) % 8]);
        add(
            format!("stencil {func:?} {fail:?} {zfail:?} {zpass:?}"),
            &|s| {
                s.depth_test = Some(CompareFunc::Less);
                s.stencil_writemask = 0x7D;
                s.stencil_test = Some(StencilTest {
                    func,
                    reference: 3,
                    mask: 0x6,
                    fail,
                    depth_fail: zfail,
                    depth_pass: zpass,
                });
            },
            rgba,
        );
    }
    let factors = [
        BlendFactor::Zero,
        BlendFactor::One,
        BlendFactor::SrcColor,
        BlendFactor::OneMinusSrcColor,
        BlendFactor::DstColor,
        BlendFactor::OneMinusDstColor,
        BlendFactor::SrcAlpha,
        BlendFactor::OneMinusSrcAlpha,
        BlendFactor::DstAlpha,
        BlendFactor::OneMinusDstAlpha,
        BlendFactor::SrcAlphaSaturate,
    ];
    for (i, src) in factors.into_iter().enumerate() {
        let dst = factors[(i * 7 + 3) % 10];
        let eq = [
            BlendEquation::Add,
            BlendEquation::Subtract,
            BlendEquation::ReverseSubtract,
            BlendEquation::Min,
            BlendEquation::Max,
        ][i % 5];
        for format in [rgba, rgb565] {
            add(
                format!("blend {src:?} {dst:?} {eq:?} {:?}", format.color),
                &|s| {
                    s.blend = Some(Blend {
                        eq_rgb: eq,
                        eq_alpha: BlendEquation::Add,
                        src_alpha: BlendFactor::One,
                        ..Blend::func(src, dst)
                    })
                },
                format,
            );
        }
    }
    for (i, op) in [
        LogicOp::Clear,
        LogicOp::And,
        LogicOp::AndReverse,
        LogicOp::Copy,
        LogicOp::AndInverted,
        LogicOp::Noop,
        LogicOp::Xor,
        LogicOp::Or,
        LogicOp::Nor,
        LogicOp::Equiv,
        LogicOp::Invert,
        LogicOp::OrReverse,
        LogicOp::CopyInverted,
        LogicOp::OrInverted,
        LogicOp::Nand,
        LogicOp::Set,
    ]
    .into_iter()
    .enumerate()
    {
        // Flat colors: a logic op magnifies a one-step rounding difference.
        let format = if i % 2 == 0 { rgba } else { rgb565 };
        add(
            format!("logic {op:?} {:?}", format.color),
            &|s| {
                s.shade_model = ShadeModel::Flat;
                s.logic_op = Some(op);
                s.blend = Some(Blend::func(BlendFactor::One, BlendFactor::One));
            },
            format,
        );
    }
    add(
        "dither 565 flat".into(),
        &|s| {
            s.dither = true;
            s.shade_model = ShadeModel::Flat;
        },
        rgb565,
    );
    add(
        "masks".into(),
        &|s| {
            s.color_mask = [true, false, true, false];
            s.depth_test = Some(CompareFunc::Always);
            s.depth_write = false;
        },
        rgba,
    );
    for (factor, units, clamp) in [
        (0.0, 1.0, 0.0),
        (1.0, 0.0, 0.0),
        (-2.0, -3.0, 0.0),
        (4.0, 2.0, 0.0),
        (4.0, 2.0, 1e-4),
        (-4.0, -2.0, -1e-4),
    ] {
        add(
            format!("polygon offset {factor} {units} clamp {clamp}"),
            &|s| {
                s.depth_test = Some(CompareFunc::LessEqual);
                s.polygon_offset = Some(PolygonOffset {
                    factor,
                    units,
                    clamp,
                });
            },
            rgba,
        );
    }
    let mut failures = Vec::new();
    for (i, (name, s, format)) in cases.iter().enumerate() {
        let (e, stencil_off) = fast_vs_reference(s, *format, 1000 + i as u64);
        // Coverage is identical on the grid; colors differ by f32 against f64 rounding, at
        // most one step, which a blend onto an already rounded pixel can double. Where a
        // value sits on a test's threshold (alpha exactly at the reference, a color at a
        // rounding midpoint under a logic op), that step can flip the outcome of a pixel:
        // such pixels are rare, so they get a share, not a bound.
        // Depth is computed in f32 against f64 before it is quantized, so a depth test
        // between nearly equal depths can flip too.
        if e.over_one > 0.002
            || e.mean > 0.05
            || (e.max > 2 && e.over_one > 0.0006)
            || stencil_off > 0.002
        {
            failures.push(format!("{name}: {e:?}, stencil off {stencil_off}"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Draws `xyz` as `prim` with `s` into a fresh 32×32 RGBA target cleared to black, alpha 0.
fn draw_prim(s: &RenderState, xyz: &[f32], prim: Primitive, color: [f32; 4]) -> Target {
    let mut t = target(32, 32);
    t.clear_color(t.bounds(), [0.0; 4], [true; 4]);
    draw(s, &mut t, xyz, color, prim);
    t
}

fn covered(t: &Target) -> Vec<(u32, u32)> {
    let mut v = Vec::new();
    for y in 0..t.height() {
        for x in 0..t.width() {
            if t.pixel(x, y)[0] != 0 {
                v.push((x, y));
            }
        }
    }
    v
}

#[test]
fn aliased_lines_take_the_half_open_extent_and_replicate_when_wide() {
    let mut s = pixel_state(32, 32);
    let white = [1.0; 4];
    // Pixel center to pixel center: the end pixel is left for the next segment.
    let t = draw_prim(&s, &[0.5, 2.5, 0.0, 5.5, 2.5, 0.0], Primitive::Lines, white);
    assert_eq!(covered(&t), (0..5).map(|x| (x, 2)).collect::<Vec<_>>());
    // Reversed, the pixels from the start vertex down to but not including the end one.
    let t = draw_prim(&s, &[5.5, 2.5, 0.0, 0.5, 2.5, 0.0], Primitive::Lines, white);
    assert_eq!(covered(&t), (1..6).map(|x| (x, 2)).collect::<Vec<_>>());
    // y-major diagonal-ish: one pixel per row.
    let t = draw_prim(&s, &[3.5, 1.5, 0.0, 5.5, 9.5, 0.0], Primitive::Lines, white);
    let c = covered(&t);
    assert_eq!(c.len(), 8);
    assert!((1..9).all(|y| c.iter().filter(|p| p.1 == y).count() == 1));
    // Width 3: a column of three fragments centered on the line.
    s.line_width = 3.0;
    let t = draw_prim(&s, &[0.5, 5.5, 0.0, 4.5, 5.5, 0.0], Primitive::Lines, white);
    let want: Vec<(u32, u32)> = (4..7).flat_map(|y| (0..4).map(move |x| (x, y))).collect();
    let mut got = covered(&t);
    got.sort_by_key(|p| (p.1, p.0));
    assert_eq!(got, want);
    // Width 2 rounds from 2.4 and replicates upward from the offset segment, which runs
    // along y = 5 exactly and so (perturbed downward, as §3.4.1 says) starts on row 4.
    s.line_width = 2.4;
    let t = draw_prim(&s, &[0.5, 5.5, 0.0, 2.5, 5.5, 0.0], Primitive::Lines, white);
    let mut got = covered(&t);
    got.sort_by_key(|p| (p.1, p.0));
    assert_eq!(got, vec![(0, 4), (1, 4), (0, 5), (1, 5)]);
    // A vertical segment along x = 4 exactly belongs to column 3.
    s.line_width = 1.0;
    let t = draw_prim(&s, &[4.0, 2.5, 0.0, 4.0, 6.5, 0.0], Primitive::Lines, white);
    assert_eq!(covered(&t), (2..6).map(|y| (3, y)).collect::<Vec<_>>());
}

#[test]
fn line_strips_and_loops_hit_shared_vertices_once() {
    use crate::state::{Blend, BlendFactor};
    let mut s = pixel_state(32, 32);
    s.blend = Some(Blend::func(BlendFactor::One, BlendFactor::One));
    let mut rng = Lcg(5);
    let mut xyz = Vec::new();
    for _ in 0..12 {
        xyz.extend([rng.next() * 30.0 + 1.0, rng.next() * 30.0 + 1.0, 0.0]);
    }
    let gray = [0.25, 0.25, 0.25, 0.25];
    for prim in [Primitive::LineStrip, Primitive::LineLoop] {
        let t = draw_prim(&s, &xyz, prim, gray);
        // A pixel hit twice would read 128; crossings of non-adjacent segments may, so
        // count only the vertices' own pixels.
        for v in xyz.chunks(3) {
            let p = t.pixel(v[0] as u32, v[1] as u32);
            assert!(p[0] <= 64 || p[0] == 128, "{prim:?} vertex pixel {p:?}");
        }
    }
    // Two collinear segments sharing an end draw the shared pixel once.
    let t = draw_prim(
        &s,
        &[0.5, 3.5, 0.0, 6.5, 3.5, 0.0, 12.5, 3.5, 0.0],
        Primitive::LineStrip,
        gray,
    );
    assert!((0..12).all(|x| t.pixel(x, 3)[0] == 64));
    assert_eq!(t.pixel(12, 3)[0], 0);
}

#[test]
fn aliased_points_snap_their_square_to_whole_pixels() {
    let mut s = pixel_state(32, 32);
    let white = [1.0; 4];
    let at = |s: &RenderState, size: f32| {
        let mut s = s.clone();
        s.point_size = size;
        let mut c = covered(&draw_prim(&s, &[2.3, 3.7, 0.0], Primitive::Points, white));
        c.sort_by_key(|p| (p.1, p.0));
        c
    };
    assert_eq!(at(&s, 1.0), vec![(2, 3)]);
    assert_eq!(at(&s, 0.6), vec![(2, 3)], "sizes round, to at least 1");
    assert_eq!(at(&s, 2.0), vec![(1, 3), (2, 3), (1, 4), (2, 4)]);
    let nine: Vec<(u32, u32)> = (2..5).flat_map(|y| (1..4).map(move |x| (x, y))).collect();
    assert_eq!(at(&s, 3.0), nine);
    // A point whose vertex is outside the clip volume is not drawn at all.
    s.point_size = 9.0;
    let t = draw_prim(&s, &[-0.5, 5.0, 0.0], Primitive::Points, white);
    assert!(covered(&t).is_empty());
}

#[test]
fn smooth_points_and_lines_cover_their_area() {
    let mut s = pixel_state(32, 32);
    s.point_smooth = true;
    s.point_size = 9.0;
    let t = draw_prim(&s, &[15.3, 16.2, 0.0], Primitive::Points, [1.0; 4]);
    let alpha: f64 = t
        .color()
        .iter()
        .map(|w| w.to_le_bytes()[3] as f64 / 255.0)
        .sum();
    let disc = std::f64::consts::PI * 4.5 * 4.5;
    assert!((alpha - disc).abs() < disc * 0.03, "{alpha} vs {disc}");
    let mut s = pixel_state(32, 32);
    s.line_smooth = true;
    s.line_width = 2.0;
    let t = draw_prim(
        &s,
        &[3.0, 4.0, 0.0, 27.0, 22.0, 0.0],
        Primitive::Lines,
        [1.0; 4],
    );
    let alpha: f64 = t
        .color()
        .iter()
        .map(|w| w.to_le_bytes()[3] as f64 / 255.0)
        .sum();
    let rect = 30.0 * 2.0;
    assert!((alpha - rect).abs() < rect * 0.03, "{alpha} vs {rect}");
}

#[test]
fn lines_and_points_match_the_reference() {
    let mut rng = Lcg(77);
    let mut xyz = Vec::new();
    for _ in 0..40 {
        xyz.extend([
            rng.next() * 48.0 - 8.0,
            rng.next() * 48.0 - 8.0,
            rng.next() * 1.8 - 0.9,
        ]);
    }
    let pb = bytes(&xyz);
    let colors = bytes(&(0..40 * 4).map(|_| rng.next()).collect::<Vec<_>>());
    let mut failures = Vec::new();
    for (prim, width, smooth) in [
        (Primitive::Lines, 1.0, false),
        (Primitive::LineStrip, 1.0, false),
        (Primitive::LineLoop, 3.0, false),
        (Primitive::Lines, 2.0, false),
        (Primitive::Lines, 2.5, true),
        (Primitive::Points, 1.0, false),
        (Primitive::Points, 4.0, false),
        (Primitive::Points, 5.0, true),
    ] {
        let mut s = pixel_state(32, 32);
        s.line_width = width;
        s.point_size = width;
        s.line_smooth = smooth;
        s.point_smooth = smooth;
        if smooth {
            // As antialiasing is used: blended by coverage, without depth writes (which
            // would let a coverage estimate decide which primitive owns a pixel).
            use crate::state::{Blend, BlendFactor};
            s.blend = Some(Blend::func(
                BlendFactor::SrcAlpha,
                BlendFactor::OneMinusSrcAlpha,
            ));
        } else {
            s.depth_test = Some(CompareFunc::LessEqual);
        }
        let call = colored_call(prim, &pb, &colors, 40);
        let (mut fast, mut slow) = (target(32, 32), target(32, 32));
        render(&s, &call, &mut fast).unwrap();
        reference::render(&s, &call, &mut slow);
        let e = reference::compare(&fast, &slow);
        // Aliased lines may leave the diamond-exit rule's fragments by the deviations the
        // specification allows (one pixel across, one fragment per segment); antialiased
        // coverage is estimated with 16 samples against the reference's 1024.
        let ok = if smooth {
            e.mean < 1.5
        } else {
            e.over_one < 0.03
        };
        if !ok {
            failures.push(format!("{prim:?} width {width} smooth {smooth}: {e:?}"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// A jittered grid mesh over the whole 64×64 target as an indexed triangle list: the
/// border vertices sit on the border, inner ones move by up to 0.15 cells (too little to
/// fold a triangle over, which would cover pixels twice legitimately).
fn jittered_mesh(rng: &mut Lcg, n: usize) -> (Vec<f32>, Vec<u16>) {
    let cell = 64.0 / n as f32;
    let mut xyz = Vec::new();
    for j in 0..=n {
        for i in 0..=n {
            let inner = |k: usize| k > 0 && k < n;
            let jx = if inner(i) {
                (rng.next() - 0.5) * 0.3 * cell
            } else {
                0.0
            };
            let jy = if inner(j) {
                (rng.next() - 0.5) * 0.3 * cell
            } else {
                0.0
            };
            xyz.extend([i as f32 * cell + jx, j as f32 * cell + jy, 0.0]);
        }
    }
    let mut idx = Vec::new();
    let at = |i: usize, j: usize| (j * (n + 1) + i) as u16;
    for j in 0..n {
        for i in 0..n {
            // Alternate the diagonal so both orientations of shared edges occur.
            if (i + j) % 2 == 0 {
                idx.extend([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
                idx.extend([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
            } else {
                idx.extend([at(i, j), at(i + 1, j), at(i, j + 1)]);
                idx.extend([at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]);
            }
        }
    }
    (xyz, idx)
}

fn additive(w: i32, h: i32) -> RenderState {
    use crate::state::{Blend, BlendFactor};
    let mut s = pixel_state(w, h);
    s.blend = Some(Blend::func(BlendFactor::One, BlendFactor::One));
    s
}

#[test]
fn random_meshes_and_strips_are_watertight() {
    let s = additive(64, 64);
    for seed in 1..6 {
        let mut rng = Lcg(seed);
        let (xyz, idx) = jittered_mesh(&mut rng, 3 + seed as usize * 2);
        let pb = bytes(&xyz);
        let mut t = target(64, 64);
        t.clear_color(t.bounds(), [0.0; 4], [true; 4]);
        let call = DrawCall {
            color: AttribSource::Constant([0.25; 4]),
            ..DrawCall::new(
                Primitive::Triangles,
                Indices::U16(&idx),
                AttribArray {
                    data: &pb,
                    ty: ComponentType::Float,
                    size: 3,
                    stride: 12,
                    normalized: false,
                },
            )
        };
        render(&s, &call, &mut t).unwrap();
        assert_eq!(count(&t, [64; 4]), 64 * 64, "seed {seed}: every pixel once");
    }
    // A strip zigzagging across the target, and a fan around an inner point.
    let mut strip = Vec::new();
    for i in 0..=8 {
        strip.extend([i as f32 * 8.0, 0.0, 0.0, i as f32 * 8.0 + 3.3, 64.0, 0.0]);
    }
    let mut t = target(64, 64);
    t.clear_color(t.bounds(), [0.0; 4], [true; 4]);
    draw(&s, &mut t, &strip, [0.25; 4], Primitive::TriangleStrip);
    let inside = (0..64u32)
        .flat_map(|y| (0..64u32).map(move |x| (x, y)))
        .filter(|&(x, y)| t.pixel(x, y) != [0; 4])
        .all(|(x, y)| t.pixel(x, y) == [64; 4]);
    assert!(inside, "no pixel of the strip is drawn twice");
    let mut fan = vec![30.3, 33.7, 0.0];
    for k in 0..=24 {
        let a = k as f32 / 24.0 * std::f32::consts::TAU;
        fan.extend([30.3 + 29.0 * a.cos(), 33.7 + 29.0 * a.sin(), 0.0]);
    }
    let mut t = target(64, 64);
    t.clear_color(t.bounds(), [0.0; 4], [true; 4]);
    draw(&s, &mut t, &fan, [0.25; 4], Primitive::TriangleFan);
    assert!(t
        .color()
        .iter()
        .all(|w| [0u8, 64].contains(&w.to_le_bytes()[0])));
    assert_eq!(t.pixel(30, 33), [64; 4]);
}

#[test]
fn slivers_and_subpixel_triangles_cover_exactly_the_centers_inside() {
    let s = pixel_state(32, 32);
    let white = [1.0; 4];
    // Inside one pixel, away from its center: nothing.
    let t = draw_prim(
        &s,
        &[3.1, 3.1, 0.0, 3.4, 3.1, 0.0, 3.1, 3.4, 0.0],
        Primitive::Triangles,
        white,
    );
    assert!(covered(&t).is_empty());
    // Around a center: that one pixel.
    let t = draw_prim(
        &s,
        &[5.4, 5.4, 0.0, 5.7, 5.4, 0.0, 5.4, 5.7, 0.0],
        Primitive::Triangles,
        white,
    );
    assert_eq!(covered(&t), vec![(5, 5)]);
    // A sliver a hundredth of a pixel tall straddling row 7's centers: exactly that row.
    let t = draw_prim(
        &s,
        &[1.0, 7.495, 0.0, 30.0, 7.495, 0.0, 30.0, 7.505, 0.0],
        Primitive::Triangles,
        white,
    );
    let c = covered(&t);
    assert!(
        !c.is_empty() && c.iter().all(|p| p.1 == 7 && p.0 >= 1 && p.0 < 30),
        "{c:?}"
    );
    // Degenerate (zero area) triangles draw nothing.
    let t = draw_prim(
        &s,
        &[1.0, 1.0, 0.0, 9.0, 9.0, 0.0, 5.0, 5.0, 0.0],
        Primitive::Triangles,
        white,
    );
    assert!(covered(&t).is_empty());
}

#[test]
fn four_quarter_viewports_render_what_the_whole_viewport_does() {
    // Power-of-two sizes and vertices on the subpixel grid make every transform exact,
    // so both ways produce the same window coordinates.
    let mut rng = Lcg(31);
    let (pb, cb) = grid_scene(&mut rng, 60, 64.0, 64.0);
    let call = colored_call(Primitive::Triangles, &pb, &cb, 180);
    let mut whole_state = RenderState::new(64, 64);
    whole_state.projection = Mat4::orthographic_rh_gl(0.0, 64.0, 0.0, 64.0, -1.0, 1.0);
    whole_state.depth_test = Some(CompareFunc::Less);
    let mut whole = target(64, 64);
    render(&whole_state, &call, &mut whole).unwrap();
    let mut quarters = target(64, 64);
    for (qx, qy) in [(0, 0), (32, 0), (0, 32), (32, 32)] {
        let mut s = whole_state.clone();
        s.viewport = Viewport {
            x: qx,
            y: qy,
            width: 32,
            height: 32,
        };
        // Map the quarter's part of NDC onto the whole NDC square.
        let to_quarter = Mat4::from_cols_array(&[
            2.0,
            0.0,
            0.0,
            0.0,
            0.0,
            2.0,
            0.0,
            0.0,
            0.0,
            0.0,
            1.0,
            0.0,
            if qx == 0 { 1.0 } else { -1.0 },
            if qy == 0 { 1.0 } else { -1.0 },
            0.0,
            1.0,
        ]);
        s.projection = to_quarter * whole_state.projection;
        render(&s, &call, &mut quarters).unwrap();
    }
    assert_eq!(whole.color(), quarters.color());
    assert_eq!(whole.depth(), quarters.depth());
}

/// A 96 × 64 perspective state and `n` triangles receding into the distance in it (a wall
/// receding to the right: w changes along each row), the case perspective correction is
/// for.
fn receding_triangles(rng: &mut Lcg, n: usize) -> (RenderState, Vec<f32>) {
    let mut s = RenderState::new(96, 64);
    s.projection = Mat4::perspective_rh_gl(1.0, 1.5, 0.5, 50.0);
    let mut pos = Vec::new();
    for _ in 0..n {
        let x = rng.next() * 6.0 - 3.0;
        pos.extend([
            -3.0,
            x - 1.0,
            -1.0,
            -3.0,
            x + 1.0,
            -1.0,
            20.0,
            x * 5.0,
            -40.0,
        ]);
    }
    (s, pos)
}

#[test]
fn perspective_hints_divide_colors_exactly() {
    use crate::state::Quality;
    let mut rng = Lcg(11);
    let (mut s, pos) = receding_triangles(&mut rng, 30);
    let col: Vec<f32> = (0..90)
        .flat_map(|_| [rng.next(), rng.next(), rng.next(), 1.0])
        .collect();
    let pb = bytes(&pos);
    let cb = bytes(&col);
    let call = colored_call(Primitive::Triangles, &pb, &cb, 90);
    let mut slow = target(96, 64);
    reference::render(&s, &call, &mut slow);
    let mut errors = Vec::new();
    for q in [Quality::Fastest, Quality::Balanced, Quality::Nicest] {
        s.perspective = q;
        let mut fast = target(96, 64);
        render(&s, &call, &mut fast).unwrap();
        errors.push(reference::compare(&fast, &slow));
    }
    // Exact divides under every hint (FASTEST's stepped divide measured slower on the
    // 8-wide routes; ARCHITECTURE.md decision 4): one step of rounding at most, off
    // edges, and the same image whatever the hint.
    assert!(errors[1].mean < 0.1, "{errors:?}");
    assert!(
        errors[0] == errors[1] && errors[2] == errors[1],
        "{errors:?}"
    );
    eprintln!("receding triangles, FASTEST / DONT_CARE / NICEST: {errors:?}");
}

#[test]
fn smooth_hints_trade_samples_for_error() {
    use crate::state::{Blend, BlendFactor, Quality};
    let mut rng = Lcg(21);
    let mut xyz = Vec::new();
    for _ in 0..60 {
        xyz.extend([rng.next() * 64.0, rng.next() * 64.0, 0.0]);
    }
    let pb = bytes(&xyz);
    let mut report = Vec::new();
    for prim in [Primitive::Lines, Primitive::Points] {
        let mut errors = Vec::new();
        for q in [Quality::Fastest, Quality::Balanced, Quality::Nicest] {
            let mut s = pixel_state(64, 64);
            s.blend = Some(Blend::func(
                BlendFactor::SrcAlpha,
                BlendFactor::OneMinusSrcAlpha,
            ));
            (s.line_smooth, s.point_smooth) = (true, true);
            (s.line_width, s.point_size) = (2.5, 6.5);
            (s.line_quality, s.point_quality) = (q, q);
            let call = DrawCall {
                color: AttribSource::Constant([1.0, 0.8, 0.3, 1.0]),
                ..positions_call(prim, &pb, 60)
            };
            let (_, _, e) = reference::measure(&s, &[call], &target(64, 64), 1);
            report.push(format!("{prim:?} {q:?}: {e:?}"));
            errors.push(e);
        }
        // More samples, less error. An edge crossing a pixel can shift its estimated
        // coverage by up to one sample row, 1/n of the pixel, so 8×8 stays within ~1/8
        // of full scale on a single edge pixel, overlaps of blended primitives add up.
        assert!(
            errors[0].mean > errors[1].mean && errors[1].mean > errors[2].mean,
            "{report:?}"
        );
        assert!(errors[2].mean < 0.6 && errors[2].max <= 40, "{report:?}");
    }
    eprintln!("{}", report.join("\n"));
}

/// A frame reused from flush to flush sets its triangles up over the primitives of the
/// batches before (lines, points, flat then smooth triangles), and so do the lists that
/// the pieces of a long draw are set up in when the library runs more than one thread
/// (`pool::thread_count`: every core, or `GLES_CM_THREADS`): the image is the one that
/// fresh frames give. Each draw is cut into three pieces (`PIECE`).
#[test]
fn reused_primitive_storage_leaves_no_trace() {
    let (w, h) = (40, 30);
    let mut rng = Lcg(11);
    let n = 2 * PIECE + 500;
    let mut batch = |prim: Primitive, size: f32| {
        // Vertices near a random point per primitive: triangles of a few pixels.
        let per = match prim {
            Primitive::Triangles => 3,
            Primitive::Lines => 2,
            _ => 1,
        };
        let mut pos = Vec::with_capacity(n * per * 3);
        for _ in 0..n {
            let (x, y) = (rng.next() * 44.0 - 2.0, rng.next() * 34.0 - 2.0);
            for _ in 0..per {
                pos.extend([x + rng.next() * size, y + rng.next() * size, 0.0]);
            }
        }
        let col: Vec<f32> = (0..n * per * 4).map(|_| rng.next()).collect();
        (prim, bytes(&pos), bytes(&col), n * per)
    };
    let batches = [
        batch(Primitive::Lines, 12.0),
        batch(Primitive::Points, 0.0),
        batch(Primitive::Triangles, 5.0),
        batch(Primitive::Triangles, 5.0),
    ];
    let smooth = pixel_state(w, h);
    let mut flat = smooth.clone();
    flat.shade_model = ShadeModel::Flat;
    let states = [&smooth, &smooth, &flat, &smooth];
    let calls: Vec<DrawCall<'_>> = batches
        .iter()
        .map(|(prim, p, c, n)| colored_call(*prim, p, c, *n))
        .collect();
    let mut fresh = target(w as u32, h as u32);
    for (s, call) in states.iter().zip(&calls) {
        render(s, call, &mut fresh).unwrap();
    }
    let mut reused = target(w as u32, h as u32);
    let mut frame = Frame::for_target(&reused);
    for (s, call) in states.iter().zip(&calls) {
        record(s, call, &mut frame).unwrap();
        frame.flush(&mut reused, 1);
    }
    assert!(reused.color() == fresh.color());
    assert!(
        count(&fresh, [0, 0, 0, 0]) < (w * h) as usize / 2,
        "the batches draw"
    );
}

#[test]
fn corners_from_the_vertex_stage_and_from_set_up_give_the_same_pixels() {
    // A strip, whose window coordinates the vertex stage works out, and the same triangles
    // as a list in the same vertex order, whose corners set-up transforms: every pixel
    // must be the same. Vertices 8 to 15 lie right of the frustum, so the list has
    // triangles set up from corners far outside the view too.
    let mut s = RenderState::new(48, 40);
    s.projection = Mat4::perspective_rh_gl(1.0, 1.2, 0.5, 20.0);
    let mut rng = Lcg(5);
    let (mut p, mut c) = (Vec::new(), Vec::new());
    for k in 0..18 {
        let d = 2.0 + 4.0 * rng.next();
        // Clip x is about 1.53·x and w is d: right of the frustum from x > 0.66·d on.
        let x = if (8..16).contains(&k) {
            d * (1.0 + rng.next())
        } else {
            d * (0.6 * rng.next() - 0.5)
        };
        p.extend([x, d * (0.8 * rng.next() - 0.4), -d]);
        c.extend([rng.next(), rng.next(), rng.next(), 1.0]);
    }
    let (pb, cb) = (bytes(&p), bytes(&c));
    let strip = colored_call(Primitive::TriangleStrip, &pb, &cb, 18);
    let (mut lp, mut lc) = (Vec::new(), Vec::new());
    Primitive::TriangleStrip.for_each_triangle(&strip.indices, |a, b, c_| {
        for v in [a, b, c_] {
            lp.extend_from_slice(&p[3 * v..3 * v + 3]);
            lc.extend_from_slice(&c[4 * v..4 * v + 4]);
        }
    });
    let (lpb, lcb) = (bytes(&lp), bytes(&lc));
    let list = colored_call(Primitive::Triangles, &lpb, &lcb, lp.len() / 3);
    assert!(vertex::run(&s, &strip)
        .unwrap()
        .corners([0, 1, 2])
        .is_some());
    assert!(vertex::run(&s, &list).unwrap().corners([0, 1, 2]).is_none());
    let mut images = [target(48, 40), target(48, 40)];
    for (t, call) in images.iter_mut().zip([&strip, &list]) {
        render(&s, call, t).unwrap();
    }
    let right_half = (0..40)
        .flat_map(|y| (24..48).map(move |x| (x, y)))
        .filter(|&(x, y)| images[0].pixel(x, y)[3] != 0)
        .count();
    assert!(right_half > 100, "{right_half} pixels right of the middle");
    assert!(images[0].color() == images[1].color());
}

/// The pieces of a draw hold each of its primitives once and in order (strips keep their
/// triangles' winding), for every kind of primitive and lengths around the pieces' ends.
#[test]
fn pieces_hold_every_primitive_once_in_order() {
    use Primitive::*;
    let list = |d: &DrawCall<'_>| {
        let mut out = Vec::new();
        if d.primitive == Points {
            out.extend((0..d.indices.len()).map(|k| [d.indices.get(k), 0, 0]));
        } else if d.primitive.is_line() {
            d.primitive
                .for_each_line(&d.indices, |a, b| out.push([a, b, 0]));
        } else {
            d.primitive
                .for_each_triangle(&d.indices, |a, b, c| out.push([a, b, c]));
        }
        out
    };
    let ends = [0, 1, 2, 3, 4, 7];
    let lengths = ends
        .into_iter()
        .chain([1, 2, 3, 4, 6, 10].into_iter().flat_map(|m| {
            [m * PIECE - 2, m * PIECE - 1, m * PIECE, m * PIECE + 1]
                .into_iter()
                .chain([m * PIECE + 2, m * PIECE + 3, m * PIECE + 5])
        }));
    let prims = [
        Points,
        Lines,
        LineStrip,
        LineLoop,
        Triangles,
        TriangleStrip,
        TriangleFan,
    ];
    for n in lengths {
        for prim in prims {
            let whole = positions_call(prim, &[], n);
            let whole = DrawCall {
                indices: Indices::Range { first: 7, count: n },
                ..whole
            };
            let parts: Vec<_> = pieces(&whole).flat_map(|p| list(&p)).collect();
            assert_eq!(parts, list(&whole), "{prim:?} of {n}");
            let longest = pieces(&whole).map(|p| p.indices.len()).max();
            let whole_kept = matches!(prim, LineLoop | TriangleFan);
            assert!(
                whole_kept || longest <= Some(3 * PIECE + 2),
                "{prim:?} of {n}"
            );
        }
    }
}

/// A long draw whose pieces fill the frame, set up on 2 or 3 threads (batches of pieces
/// in parallel, or on the caller while a batch is behind), into a target held directly or
/// behind a lock: the image is the one a single thread gives. The triangles are blended
/// without a depth test, so a batch binned out of order, or rasterized twice, changes
/// the image.
#[test]
fn long_draws_set_up_on_several_threads_keep_their_order() {
    let (w, h) = (64, 48);
    let mut rng = Lcg(23);
    let n = 5 * PIECE + 77;
    let mut pos = Vec::with_capacity(n * 9);
    for _ in 0..n {
        let (x, y) = (rng.next() * 70.0 - 3.0, rng.next() * 54.0 - 3.0);
        for _ in 0..3 {
            pos.extend([x + rng.next() * 9.0, y + rng.next() * 9.0, 0.0]);
        }
    }
    let col: Vec<f32> = (0..n * 12).map(|_| rng.next()).collect();
    let (pb, cb) = (bytes(&pos), bytes(&col));
    let long = colored_call(Primitive::Triangles, &pb, &cb, 3 * n);
    // A few primitives already recorded, so that the draw starts in a frame with some.
    let first = colored_call(Primitive::Triangles, &pb, &cb, 300);
    use crate::state::{Blend, BlendFactor};
    let mut state = pixel_state(w, h);
    state.blend = Some(Blend::func(
        BlendFactor::SrcAlpha,
        BlendFactor::OneMinusSrcAlpha,
    ));
    let image = |threads: usize, behind: bool| {
        let mut frame = Frame::for_target(&target(w as u32, h as u32));
        let shared = Arc::new(Mutex::new(target(w as u32, h as u32)));
        let mut direct = target(w as u32, h as u32);
        for call in [&first, &long] {
            let to = if behind {
                Destination::Behind(shared.clone())
            } else {
                Destination::Now(&mut direct)
            };
            record_pieces(&state, call, &mut frame, Some(to), threads).unwrap();
        }
        if behind {
            // The batch behind locks the target: waited for before the lock is taken.
            frame.wait();
            frame.flush_into(&mut shared.lock().unwrap());
            let t = shared.lock().unwrap();
            t.color().to_vec()
        } else {
            frame.flush_into(&mut direct);
            direct.color().to_vec()
        }
    };
    let want = image(1, false);
    let blank = want.iter().filter(|&&w| w == 0).count();
    assert!(blank < want.len() / 4, "the draw covers the target");
    for threads in [2, 3] {
        for behind in [false, true] {
            assert!(
                image(threads, behind) == want,
                "{threads} threads, behind {behind}"
            );
        }
    }
}

#[test]
fn a_draw_of_one_color_takes_it_exactly_on_every_pixel() {
    // Receding triangles and lines (w changes along every row) in colors whose channels
    // fall on a rounding boundary of the 8-bit encoding (0.5 · 255 = 127.5): interpolated,
    // c·(1/w) divided by 1/w lands an ulp below c on some pixels and encodes a step lower.
    let (s, pos) = receding_triangles(&mut Lcg(5), 20);
    for color in [[0.5, 0.5, 0.5, 0.5], [0.25, 0.75, 0.5, 1.0]] {
        let expected = ColorFormat::Rgba8888.encode(color).to_le_bytes();
        for prim in [Primitive::Triangles, Primitive::LineStrip] {
            let mut t = target(96, 64);
            draw(&s, &mut t, &pos, color, prim);
            let drawn = (0..64)
                .flat_map(|y| row(&t, y))
                .filter(|&p| p != [0; 4])
                .collect::<Vec<_>>();
            assert!(drawn.len() > 100, "{prim:?}: {} pixels", drawn.len());
            assert!(drawn.iter().all(|&p| p == expected), "{prim:?} {color:?}");
        }
    }
}
