//! Depth precision: the smallest separation of two parallel quads that renders without
//! z-fighting, measured through the core, and the ideal one for the quantization formula.
//! Shared by the accuracy report (`crates/tools/src/bin/accuracy.rs`) and `tests/properties.rs`.

use glam::Mat4;
use gles_cm_core::{
    AttribArray, AttribSource, ColorFormat, CompareFunc, ComponentType, DepthFormat, DrawCall,
    Indices, Primitive, RenderState, Target, TargetFormat,
};

/// The smallest eye-space separation of two parallel quads at distance `d` that renders
/// without z-fighting, found by bisection, for a perspective with `near`, `far`.
pub fn measured_separation(depth: DepthFormat, near: f32, far: f32, d: f32) -> f64 {
    let resolves = |sep: f32| {
        let mut s = RenderState::new(8, 8);
        s.projection = Mat4::perspective_rh_gl(1.0, 1.0, near, far);
        s.depth_test = Some(CompareFunc::Less);
        let mut t = Target::new(
            8,
            8,
            TargetFormat {
                color: ColorFormat::Rgba8888,
                depth: Some(depth),
                stencil_bits: 0,
            },
        );
        t.clear_depth(t.bounds(), 1.0);
        for (z, c) in [
            (-(d + sep), [0.0, 1.0, 0.0, 1.0]),
            (-d, [1.0, 0.0, 0.0, 1.0]),
        ] {
            let h = -z;
            let q = [-h, -h, z, h, -h, z, h, h, z, -h, -h, z, h, h, z, -h, h, z];
            let b: Vec<u8> = q.iter().flat_map(|f| f.to_ne_bytes()).collect();
            let call = DrawCall {
                color: AttribSource::Constant(c),
                ..DrawCall::new(
                    Primitive::Triangles,
                    Indices::Range { first: 0, count: 6 },
                    AttribArray {
                        data: &b,
                        ty: ComponentType::Float,
                        size: 3,
                        stride: 12,
                        normalized: false,
                    },
                )
            };
            gles_cm_core::render(&s, &call, &mut t).unwrap();
        }
        t.color()
            .iter()
            .all(|w| w.to_le_bytes() == [255, 0, 0, 255])
    };
    let (mut lo, mut hi) = (0.0f32, far - d);
    if !resolves(hi) {
        return f64::INFINITY;
    }
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if resolves(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi as f64
}

/// The ideal separation: one depth step, round(z·(2ⁿ − 1)), converted back to eye space
/// through the exact (f64) depth function at distance `d`: the nearer quad's window depth
/// plus the worst-case rounding of both (one full step) must change the stored value.
pub fn ideal_separation(bits: u32, near: f64, far: f64, d: f64) -> f64 {
    let step = 1.0 / ((1u64 << bits) - 1) as f64;
    // Window z of eye distance e: (f + n)/(2(f − n)) − f·n/((f − n)·e) + 1/2.
    let zw =
        |e: f64| 0.5 * ((far + near) / (far - near) - 2.0 * far * near / ((far - near) * e)) + 0.5;
    let target = zw(d) + step;
    if target >= 1.0 {
        return f64::INFINITY;
    }
    // Invert: e = 2fn / ((f + n) − (2 target − 1)(f − n)).
    let e = 2.0 * far * near / ((far + near) - (2.0 * target - 1.0) * (far - near));
    e - d
}
