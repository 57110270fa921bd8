//! Edge antialiasing: how far a white fan on black lands from each pixel's exact covered area,
//! single-sample against 4× MSAA (`gles_cm_core::multisample`). The area is computed in f64 by
//! clipping the pixel square against each triangle (Sutherland–Hodgman), so the measure is
//! the ideal box-filtered edge, the quantity an antialiased pixel approximates.

use glam::Mat4;
use gles_cm_core::{
    AttribArray, AttribSource, ColorFormat, ComponentType, DepthFormat, DrawCall, Indices,
    Primitive, RenderState, Target, TargetFormat,
};

const SIZE: u32 = 96;

/// Errors of the edge pixels (exact coverage strictly between 0 and 1), in 8-bit steps.
pub struct EdgeError {
    pub pixels: usize,
    pub mean: f64,
    pub max: f64,
}

/// A fan of thin triangles around the center, every edge at its own angle, none touching
/// another (so coverages add).
fn fan() -> Vec<[[f64; 2]; 3]> {
    let c = SIZE as f64 / 2.0 + 0.13;
    let r = SIZE as f64 * 0.47;
    let n = 24;
    (0..n)
        .map(|i| {
            let a0 = i as f64 / n as f64 * std::f64::consts::TAU + 0.05;
            let a1 = a0 + std::f64::consts::TAU / n as f64 * 0.55;
            let p = |a: f64, s: f64| [c + s * a.cos(), c + s * a.sin()];
            [
                p(a0, r * 0.2),
                p(a0, r),
                p(a1, r * (0.6 + 0.4 * (i % 3) as f64 / 2.0)),
            ]
        })
        .collect()
}

/// The area of the unit pixel square at (x, y) inside triangle `t` (counter-clockwise).
fn covered(t: &[[f64; 2]; 3], x: f64, y: f64) -> f64 {
    let mut poly = vec![[x, y], [x + 1.0, y], [x + 1.0, y + 1.0], [x, y + 1.0]];
    for i in 0..3 {
        let (a, b) = (t[i], t[(i + 1) % 3]);
        let side = |p: [f64; 2]| (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
        let mut out = Vec::with_capacity(poly.len() + 2);
        for k in 0..poly.len() {
            let (p, q) = (poly[k], poly[(k + 1) % poly.len()]);
            let (sp, sq) = (side(p), side(q));
            if sp >= 0.0 {
                out.push(p);
            }
            if (sp >= 0.0) != (sq >= 0.0) {
                let f = sp / (sp - sq);
                out.push([p[0] + (q[0] - p[0]) * f, p[1] + (q[1] - p[1]) * f]);
            }
        }
        poly = out;
        if poly.is_empty() {
            return 0.0;
        }
    }
    let n = poly.len();
    (0..n)
        .map(|k| {
            let (p, q) = (poly[k], poly[(k + 1) % n]);
            p[0] * q[1] - q[0] * p[1]
        })
        .sum::<f64>()
        .abs()
        / 2.0
}

/// Renders the fan white on black, multisampled or not, and measures its edge pixels.
pub fn edge_error(multisampled: bool) -> EdgeError {
    let format = TargetFormat {
        color: ColorFormat::Rgba8888,
        depth: Some(DepthFormat::D24),
        stencil_bits: 0,
    };
    let mut t = Target::try_new_multisample(SIZE, SIZE, format, multisampled).expect("memory");
    let mut s = RenderState::new(SIZE as i32, SIZE as i32);
    s.projection = Mat4::orthographic_rh_gl(0.0, SIZE as f32, 0.0, SIZE as f32, -1.0, 1.0);
    let tris = fan();
    let xyz: Vec<f32> = tris
        .iter()
        .flat_map(|t| t.iter().flat_map(|p| [p[0] as f32, p[1] as f32, 0.0]))
        .collect();
    let bytes: Vec<u8> = xyz.iter().flat_map(|f| f.to_ne_bytes()).collect();
    let call = DrawCall {
        color: AttribSource::Constant([1.0; 4]),
        ..DrawCall::new(
            Primitive::Triangles,
            Indices::Range {
                first: 0,
                count: tris.len() * 3,
            },
            AttribArray {
                data: &bytes,
                ty: ComponentType::Float,
                size: 3,
                stride: 12,
                normalized: false,
            },
        )
    };
    gles_cm_core::render(&s, &call, &mut t).expect("memory");
    let (mut pixels, mut sum, mut max) = (0usize, 0.0f64, 0.0f64);
    for y in 0..SIZE {
        for x in 0..SIZE {
            let area: f64 = tris
                .iter()
                .map(|tri| covered(tri, x as f64, y as f64))
                .sum();
            if area <= 1e-9 || area >= 1.0 - 1e-9 {
                continue;
            }
            let got = t.pixel(x, y)[0] as f64;
            let e = (got - area * 255.0).abs();
            pixels += 1;
            sum += e;
            max = max.max(e);
        }
    }
    EdgeError {
        pixels,
        mean: sum / pixels.max(1) as f64,
        max,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clipped_area_of_a_half_plane() {
        // Counter-clockwise, its right side x = 2.5 through pixel column 2.
        let t = [[-100.0, -100.0], [2.5, -100.0], [2.5, 100.0]];
        assert!((covered(&t, 2.0, 0.0) - 0.5).abs() < 1e-12);
        let big = [[-100.0, -100.0], [100.0, -100.0], [0.0, 100.0]];
        assert!((covered(&big, 0.0, 0.0) - 1.0).abs() < 1e-12);
    }
}
