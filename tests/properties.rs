//! Property tests (proptest) for the math under the pipeline: fixed ↔ float conversions,
//! the M3G inverse on near-singular matrices, homogeneous clipping, edge functions over
//! the whole viewport range and quaternion SLERP near 0° and 180°. Plus the depth
//! precision measurement (issue 10, item 4).

use glam::{Mat4, Vec3, Vec4};
use gles_cm_core::vertex::{ClipVertex, Layout};
use gles_cm_core::{clip, fixed};
use gles_cm_core::{
    AttribArray, ColorFormat, ComponentType, DepthFormat, DrawCall, Indices, Primitive,
    RenderState, Target, TargetFormat,
};
use m3g::{Interpolation, KeyframeSequence as KS, Transform};
use proptest::prelude::*;

#[path = "../crates/tools/src/bin/accuracy/depth.rs"]
mod depth;
use depth::{ideal_separation, measured_separation};

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Every 16.16 value converts to f32 within GL's 10⁻⁵ relative accuracy and back
    /// exactly where f32 holds it (|x| < 2⁸ is exact).
    #[test]
    fn fixed_to_float_and_back(x in any::<i32>()) {
        let f = fixed::to_f32(x);
        let exact = x as f64 / 65536.0;
        prop_assert!((f as f64 - exact).abs() <= exact.abs() * 1e-7 + 1e-12);
        if x.unsigned_abs() < 1 << 24 {
            prop_assert_eq!(fixed::from_f32(f), x);
        }
    }

    /// Float → fixed rounds to nearest and saturates; NaN is 0.
    #[test]
    fn float_to_fixed_saturates(f in any::<f32>()) {
        let x = fixed::from_f32(f);
        if f.is_nan() {
            prop_assert_eq!(x, 0);
        } else if f as f64 * 65536.0 >= i32::MAX as f64 {
            prop_assert_eq!(x, i32::MAX);
        } else if f as f64 * 65536.0 <= i32::MIN as f64 {
            prop_assert_eq!(x, i32::MIN);
        } else {
            prop_assert!((x as f64 - f as f64 * 65536.0).abs() <= 0.5);
        }
    }

    /// Transform.invert on near-singular matrices: either an Arithmetic error, or an
    /// inverse whose product with the matrix is the identity within its conditioning.
    #[test]
    fn m3g_inverse_near_singular(e in -12i32..0, a in prop::array::uniform16(-4.0f32..4.0)) {
        // Rows 3 and 4 almost equal: the determinant shrinks with 10^e.
        let mut m = a;
        for c in 0..4 {
            m[12 + c] = m[8 + c] * (1.0 + 10f32.powi(e));
        }
        let mut t = Transform::new();
        t.set(&m).unwrap();
        let mut inv = t;
        if inv.invert().is_ok() {
            let p = Mat4::from_cols_array(&t.get()).transpose() * Mat4::from_cols_array(&inv.get()).transpose();
            let g = Mat4::from_cols_array(&inv.get());
            prop_assert!(g.is_finite());
            let cond = g.to_cols_array().iter().fold(0f32, |x, v| x.max(v.abs())) * 16.0;
            let err = (p - Mat4::IDENTITY).to_cols_array().iter().fold(0f32, |x, v| x.max(v.abs()));
            prop_assert!(err <= 1e-5 * cond.max(1.0), "err {err} cond {cond}");
        }
    }

    /// Clipping: every output vertex lies inside the near/far planes and the guard band,
    /// with w > 0, and the clipped polygon's window-space area equals the area of the part
    /// of the triangle inside the viewport (measured by the f64 reference's clipper through
    /// an exact-integer sampling of coverage in `gles_cm_core::reference`).
    #[test]
    fn clipping_stays_inside_and_keeps_area(v in prop::array::uniform12(-20.0f32..20.0)) {
        let vs: Vec<ClipVertex> = (0..3)
            .map(|i| ClipVertex::new(Vec4::new(v[4 * i], v[4 * i + 1], v[4 * i + 2], v[4 * i + 3] * 0.5 + 2.0), Vec4::ONE))
            .collect();
        let layout = Layout::full(0);
        let f: Vec<_> = vs.iter().map(|v| layout.pack(v)).collect();
        let mut out = Vec::new();
        clip::triangle(layout.view(&f[0]), layout.view(&f[1]), layout.view(&f[2]), |p| out = p.iter().map(|v| v.unpack()).collect());
        for q in &out {
            let w = q.pos.w;
            prop_assert!(w >= clip::W_MIN && q.pos.is_finite());
            let tol = 1e-4 * (w.abs() + 1.0);
            prop_assert!(q.pos.z.abs() <= w + tol, "{:?}", q.pos);
            prop_assert!(q.pos.x.abs() <= clip::GUARD * w + tol * 8.0, "{:?}", q.pos);
            prop_assert!(q.pos.y.abs() <= clip::GUARD * w + tol * 8.0, "{:?}", q.pos);
        }
        // Area inside the frustum in NDC: clip the output further to |x|, |y| ≤ 1 in f64
        // and compare with the same clip of the original triangle in f64.
        let ndc = |p: &[Vec4]| -> f64 {
            let poly: Vec<[f64; 4]> = p.iter().map(|v| [v.x as f64, v.y as f64, v.z as f64, v.w as f64]).collect();
            area_inside(poly)
        };
        let want = ndc(&vs.iter().map(|v| v.pos).collect::<Vec<_>>());
        let got = if out.is_empty() { 0.0 } else { ndc(&out.iter().map(|v| v.pos).collect::<Vec<_>>()) };
        prop_assert!((got - want).abs() <= 1e-4 * (want + 1.0), "got {got} want {want}");
    }

    /// Edge functions never overflow: triangles with vertices anywhere in the guard band of
    /// the largest viewport set up and rasterize without panic (debug overflow checks
    /// would trip) and cover no more pixels than the viewport holds.
    #[test]
    fn edge_functions_do_not_overflow(v in prop::array::uniform9(-9.0f32..9.0)) {
        let mut s = RenderState::new(64, 64);
        s.viewport = gles_cm_core::Viewport { x: -4064, y: -4064, width: 8192, height: 8192 };
        let b: Vec<u8> = v.iter().flat_map(|f| f.to_ne_bytes()).collect();
        let d = DrawCall::new(Primitive::Triangles, Indices::Range { first: 0, count: 3 }, AttribArray { data: &b, ty: ComponentType::Float, size: 3, stride: 12, normalized: false });
        let mut t = Target::new(64, 64, TargetFormat { color: ColorFormat::Rgba8888, depth: None, stencil_bits: 0 });
        gles_cm_core::render(&s, &d, &mut t).unwrap();
    }

    /// SLERP between keys 0° to 1e-3° apart and near 180° apart: finite, unit length, on
    /// the great circle between the keys.
    #[test]
    fn slerp_near_0_and_180_degrees(axis in prop::array::uniform3(-1.0f32..1.0), tiny in 0.0f32..1e-3, s in 0.0f64..100.0) {
        let ax = Vec3::from_array(axis);
        prop_assume!(ax.length() > 0.1);
        let ax = ax.normalize();
        for angle in [tiny, 180.0 - tiny] {
            let h = (angle * 0.5).to_radians();
            let b = [ax.x * h.sin(), ax.y * h.sin(), ax.z * h.sin(), h.cos()];
            let seq = KS::new(2, 4, Interpolation::Slerp).unwrap();
            seq.set_keyframe(0, 0, &[0.0, 0.0, 0.0, 1.0]).unwrap();
            seq.set_keyframe(1, 100, &b).unwrap();
            seq.set_duration(100).unwrap();
            let q = seq.sample(s).unwrap();
            prop_assert!(q.iter().all(|x| x.is_finite()), "{q:?}");
            let len = q.iter().map(|x| x * x).sum::<f32>().sqrt();
            prop_assert!((len - 1.0).abs() < 1e-4, "{q:?}");
            // The rotation angle grows linearly with s.
            let got = 2.0 * q[3].clamp(-1.0, 1.0).acos().to_degrees();
            let want = angle * (s as f32 / 100.0);
            prop_assert!((got - want).abs() < 0.05, "angle {angle}: {got} vs {want}");
        }
    }
}

/// The NDC area of polygon `p` (clip space) inside |x|, |y|, |z| ≤ w, w > 0, in f64.
fn area_inside(mut p: Vec<[f64; 4]>) -> f64 {
    let planes: [fn(&[f64; 4]) -> f64; 7] = [
        |v| v[3] + v[0],
        |v| v[3] - v[0],
        |v| v[3] + v[1],
        |v| v[3] - v[1],
        |v| v[3] + v[2],
        |v| v[3] - v[2],
        |v| v[3] - 1e-30,
    ];
    for d in planes {
        let mut out = Vec::new();
        for i in 0..p.len() {
            let (a, b) = (p[i], p[(i + 1) % p.len()]);
            let (da, db) = (d(&a), d(&b));
            if da >= 0.0 {
                out.push(a);
            }
            if (da >= 0.0) != (db >= 0.0) {
                let t = da / (da - db);
                out.push(std::array::from_fn(|k| a[k] + (b[k] - a[k]) * t));
            }
        }
        p = out;
        if p.len() < 3 {
            return 0.0;
        }
    }
    let xy: Vec<(f64, f64)> = p.iter().map(|v| (v[0] / v[3], v[1] / v[3])).collect();
    let mut twice = 0.0;
    for i in 0..xy.len() {
        let (a, b) = (xy[i], xy[(i + 1) % xy.len()]);
        twice += a.0 * b.1 - b.0 * a.1;
    }
    twice.abs() * 0.5
}

/// The depth precision table: for 16- and 24-bit depth and near/far ratios 10⁻¹ to 10⁻⁶,
/// the smallest separation that renders without z-fighting at several distances, against
/// the ideal. Ours must be within a factor 2.5 of it (the interpolation of window z in f64
/// plus one rounding: at worst two steps where the ideal counts one) wherever the ideal is
/// finite.
#[test]
fn depth_precision_against_the_ideal() {
    println!("| depth | near/far | distance | ideal | measured | ratio |");
    println!("|---|---|---|---|---|---|");
    let far = 1000.0f32;
    for depth in [DepthFormat::D16, DepthFormat::D24] {
        for k in 1..=6 {
            let near = far * 10f32.powi(-k);
            for frac in [0.01f32, 0.1, 0.5] {
                let d = near + (far - near) * frac;
                let ideal = ideal_separation(depth.bits(), near as f64, far as f64, d as f64);
                let got = measured_separation(depth, near, far, d);
                let ratio = got / ideal;
                println!(
                    "| {} | 1e-{k} | {d:.4} | {ideal:.3e} | {got:.3e} | {ratio:.2} |",
                    depth.bits()
                );
                if ideal.is_finite() && ideal < (far - d) as f64 * 0.5 {
                    assert!(
                        ratio <= 2.5,
                        "{depth:?} near/far 1e-{k} at {d}: {got} vs ideal {ideal}"
                    );
                }
            }
        }
    }
}
