//! Reference lines and points, per pixel and literal: the diamond-exit rule for aliased
//! segments (with the specification's perturbation of the endpoints), the offset segment
//! and replicated fragments for wide ones, the rectangle and the disc for antialiased ones
//! with coverage as area (estimated with 32 × 32 samples, far finer than the fast path's
//! 2 × 2 to 8 × 8), and the snapped square for aliased points.

use glam::DVec4;

use super::fragment::{self, Pixel};
use super::Vtx;
use crate::state::{RenderState, ShadeModel};
use crate::target::{Rect, Target};

const MAX_SIZE: f64 = 64.0;
const AREA_SAMPLES: i32 = 32;

/// Window x, y, z and 1/w of a clip-space position (inside the clip volume).
fn window(state: &RenderState, p: DVec4) -> (f64, f64, f64, f64) {
    let vp = state.viewport;
    let [n, f] = state.depth_range.map(f64::from);
    let ndc = p / p.w;
    (
        (ndc.x + 1.0) * vp.width as f64 / 2.0 + vp.x as f64,
        (ndc.y + 1.0) * vp.height as f64 / 2.0 + vp.y as f64,
        ndc.z * (f - n) / 2.0 + (f + n) / 2.0,
        1.0 / p.w,
    )
}

fn emit(state: &RenderState, target: &mut Target, x: i32, y: i32, color: DVec4, z: f64) {
    let bounds = state.pixel_bounds(target.bounds());
    if x < bounds.x0 || x >= bounds.x1 || y < bounds.y0 || y >= bounds.y1 {
        return;
    }
    let format = target.format();
    let at = y as usize * target.width() as usize + x as usize;
    let (colors, depths, stencils) = target.buffers_mut();
    let px = Pixel {
        color: &mut colors[at],
        depth: depths.get_mut(at),
        stencil: stencils.get_mut(at),
    };
    fragment::process(state, format, x, y, color, z, px);
}

/// The share of pixel (x, y) for which `inside` holds, by area.
fn area(x: i32, y: i32, inside: impl Fn(f64, f64) -> bool) -> f64 {
    let n = AREA_SAMPLES;
    let mut hits = 0;
    for sy in 0..n {
        for sx in 0..n {
            let px = x as f64 + (sx as f64 + 0.5) / n as f64;
            let py = y as f64 + (sy as f64 + 0.5) / n as f64;
            hits += inside(px, py) as i32;
        }
    }
    hits as f64 / (n * n) as f64
}

/// Does the segment from `a` to `b` meet the open diamond |x − cx| + |y − cy| < ½? The
/// distance is convex and piecewise linear along the segment, so its minimum is at an end or
/// where x or y crosses the center.
fn meets_diamond(a: (f64, f64), b: (f64, f64), cx: f64, cy: f64) -> bool {
    let at = |t: f64| {
        let (x, y) = (a.0 + (b.0 - a.0) * t, a.1 + (b.1 - a.1) * t);
        (x - cx).abs() + (y - cy).abs()
    };
    let mut ts = vec![0.0, 1.0];
    if b.0 != a.0 {
        ts.push((cx - a.0) / (b.0 - a.0));
    }
    if b.1 != a.1 {
        ts.push((cy - a.1) / (b.1 - a.1));
    }
    ts.into_iter()
        .filter(|t| (0.0..=1.0).contains(t))
        .any(|t| at(t) < 0.5)
}

/// Draws a clipped segment. `provoking` is the flat-shaded color.
pub fn line(state: &RenderState, a: &Vtx, b: &Vtx, provoking: DVec4, target: &mut Target) {
    let (ax, ay, az, aw) = window(state, a.pos);
    let (bx, by, bz, bw) = window(state, b.pos);
    let (dx, dy) = (bx - ax, by - ay);
    let len2 = dx * dx + dy * dy;
    if len2 == 0.0 {
        return;
    }
    // Color and depth at a pixel center, from its projection t onto the segment.
    let shade = |cx: f64, cy: f64| -> (DVec4, f64) {
        let t = ((cx - ax) * dx + (cy - ay) * dy) / len2;
        let z = az + (bz - az) * t;
        let color = if state.shade_model == ShadeModel::Flat {
            provoking
        } else {
            let q = aw + (bw - aw) * t;
            (a.color * aw + (b.color * bw - a.color * aw) * t) / q
        };
        (color, z)
    };
    let width = (state.line_width as f64).clamp(1.0, MAX_SIZE);
    let reach = width / 2.0 + 2.0;
    let region = Rect {
        x0: (ax.min(bx) - reach).floor() as i32,
        y0: (ay.min(by) - reach).floor() as i32,
        x1: (ax.max(bx) + reach).ceil() as i32,
        y1: (ay.max(by) + reach).ceil() as i32,
    }
    .intersect(state.pixel_bounds(target.bounds()));
    if state.line_smooth {
        let len = len2.sqrt();
        let (ux, uy) = (dx / len, dy / len);
        for y in region.y0..region.y1 {
            for x in region.x0..region.x1 {
                let share = area(x, y, |px, py| {
                    let along = (px - ax) * ux + (py - ay) * uy;
                    let across = (px - ax) * uy - (py - ay) * ux;
                    (0.0..len).contains(&along) && across.abs() < width / 2.0
                });
                if share > 0.0 {
                    let (mut c, z) = shade(x as f64 + 0.5, y as f64 + 0.5);
                    c.w *= share;
                    emit(state, target, x, y, c, z);
                }
            }
        }
        return;
    }
    let w = (width.round() as i32).max(1);
    let x_major = dx.abs() >= dy.abs();
    // The offset segment (ES 1.1 §3.4.2), perturbed as §3.4.1 prescribes.
    let off = (w - 1) as f64 / 2.0;
    let (oa, ob) = if x_major {
        ((ax, ay - off), (bx, by - off))
    } else {
        ((ax - off, ay), (bx - off, by))
    };
    let eps = 1.0 / (1u64 << 18) as f64;
    let pa = (oa.0 - eps, oa.1 - eps * eps);
    let pb = (ob.0 - eps, ob.1 - eps * eps);
    let grow = Rect {
        x0: region.x0 - w,
        y0: region.y0 - w,
        x1: region.x1 + w,
        y1: region.y1 + w,
    };
    for y in grow.y0..grow.y1 {
        for x in grow.x0..grow.x1 {
            let (cx, cy) = (x as f64 + 0.5, y as f64 + 0.5);
            let end_inside = (pb.0 - cx).abs() + (pb.1 - cy).abs() < 0.5;
            if end_inside || !meets_diamond(pa, pb, cx, cy) {
                continue;
            }
            for k in 0..w {
                let (fx, fy) = if x_major { (x, y + k) } else { (x + k, y) };
                let (c, z) = shade(fx as f64 + 0.5, fy as f64 + 0.5);
                emit(state, target, fx, fy, c, z);
            }
        }
    }
}

/// Draws a point whose vertex is inside the clip volume.
pub fn point(state: &RenderState, v: &Vtx, target: &mut Target) {
    let (x, y, z, _) = window(state, v.pos);
    let size = (state.point_size as f64).clamp(1.0, MAX_SIZE);
    let r = size / 2.0;
    let region = Rect {
        x0: (x - size).floor() as i32,
        y0: (y - size).floor() as i32,
        x1: (x + size).ceil() as i32,
        y1: (y + size).ceil() as i32,
    }
    .intersect(state.pixel_bounds(target.bounds()));
    let s = size.round().max(1.0);
    let snap = |c: f64| {
        if s as i64 % 2 == 1 {
            c.floor() + 0.5
        } else {
            (c + 0.5).floor()
        }
    };
    let (sx, sy) = (snap(x), snap(y));
    for py in region.y0..region.y1 {
        for px in region.x0..region.x1 {
            let (cx, cy) = (px as f64 + 0.5, py as f64 + 0.5);
            let mut color = v.color;
            if state.point_smooth {
                let share = area(px, py, |qx, qy| (qx - x).powi(2) + (qy - y).powi(2) < r * r);
                if share == 0.0 {
                    continue;
                }
                color.w *= share;
            } else {
                let inside = |c: f64, s0: f64| c >= s0 - s / 2.0 && c < s0 + s / 2.0;
                if !(inside(cx, sx) && inside(cy, sy)) {
                    continue;
                }
            }
            emit(state, target, px, py, color, z);
        }
    }
}
