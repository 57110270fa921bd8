//! Homogeneous clipping, before any divide, so the setup stage never divides by a w that is
//! zero or negative.
//!
//! Lines are clipped against the six frustum planes −w ≤ x, y, z ≤ w and w ≥ [`W_MIN`];
//! points are kept or dropped whole by their vertex. Triangles are clipped in x and y against
//! a guard band [`GUARD`] times wider than the frustum instead, and the rasterizer limits
//! their pixels to the viewport rectangle, which selects exactly the pixels frustum clipping
//! would (pixel centers never lie on the viewport's integer edges). Inside the band a
//! triangle keeps its own vertices, so the pixels it covers do not depend on the viewport it
//! happens to cross, and most triangles near the edges are not clipped at all.

use glam::Vec4;

use super::vertex::ClipVertex;

/// The smallest w that survives clipping. A vertex at (0, 0, 0, 0) lies inside all six
/// frustum planes, so this plane is what keeps 1/w finite.
pub const W_MIN: f32 = 1e-30;

/// The guard band's half-width in normalized device coordinates. Window coordinates then
/// stay within (GUARD + 1) × MAX_VIEWPORT_DIM / 2 < 2¹⁶ pixels of the viewport, which keeps
/// snapped coordinates below 2²⁴ and edge products far below 2⁶³.
pub const GUARD: f32 = 8.0;

/// Each plane adds at most one vertex: 3 + 7.
const MAX_POLY: usize = 10;

/// The signed distances of a clip-space position to each clip plane, x and y widened by
/// `band`; negative is outside.
#[inline]
fn distances_with(p: Vec4, band: f32) -> [f32; 7] {
    [
        band * p.w + p.x,
        band * p.w - p.x,
        band * p.w + p.y,
        band * p.w - p.y,
        p.w + p.z,
        p.w - p.z,
        p.w - W_MIN,
    ]
}

/// Distances to the frustum planes.
#[inline]
fn distances(p: Vec4) -> [f32; 7] {
    distances_with(p, 1.0)
}

/// Distances to the guard band's planes (x, y) and the frustum's (z, w).
#[inline]
fn guard_distances(p: Vec4) -> [f32; 7] {
    distances_with(p, GUARD)
}

/// A bit per plane (of the guard band) that the position is outside of.
#[inline]
pub fn outcode(p: Vec4) -> u8 {
    let d = guard_distances(p);
    let mut code = 0;
    for (i, &v) in d.iter().enumerate() {
        // NaN compares false, so it counts as outside too.
        if v.is_nan() || v < 0.0 {
            code |= 1 << i;
        }
    }
    code
}

/// Clips segment (a, b) against the clip volume, returning what is left, in the original
/// direction.
pub fn line(a: &ClipVertex, b: &ClipVertex) -> Option<(ClipVertex, ClipVertex)> {
    if !(a.pos.is_finite() && b.pos.is_finite()) {
        return None;
    }
    let (da, db) = (distances(a.pos), distances(b.pos));
    let (mut t0, mut t1) = (0f32, 1f32);
    for (&pa, &pb) in da.iter().zip(&db) {
        if pa < 0.0 && pb < 0.0 {
            return None;
        }
        if pa < 0.0 {
            t0 = t0.max(pa / (pa - pb));
        } else if pb < 0.0 {
            t1 = t1.min(pa / (pa - pb));
        }
    }
    if t0 > t1 {
        return None;
    }
    let start = if t0 == 0.0 { *a } else { a.lerp(b, t0) };
    let end = if t1 == 1.0 { *b } else { a.lerp(b, t1) };
    Some((start, end))
}

/// True when a point survives clipping: its vertex lies inside the clip volume. (A wide
/// point whose center is inside is drawn whole; one whose center is outside is not drawn.)
pub fn point(v: &ClipVertex) -> bool {
    v.pos.is_finite() && distances(v.pos).iter().all(|&d| d >= 0.0)
}

/// Clips triangle (a, b, c) and calls `emit` with the resulting convex polygon (at least three
/// vertices, in the original winding), or not at all when nothing is left.
pub fn triangle(a: &ClipVertex, b: &ClipVertex, c: &ClipVertex, emit: impl FnOnce(&[ClipVertex])) {
    // Infinite or NaN coordinates have no meaningful clipped shape; drop the triangle rather
    // than let NaN reach the rasterizer.
    if !(a.pos.is_finite() && b.pos.is_finite() && c.pos.is_finite()) {
        return;
    }
    let codes = [outcode(a.pos), outcode(b.pos), outcode(c.pos)];
    if codes[0] | codes[1] | codes[2] == 0 {
        emit(&[*a, *b, *c]);
        return;
    }
    if codes[0] & codes[1] & codes[2] != 0 {
        return;
    }
    let mut poly = [*a; MAX_POLY];
    poly[1] = *b;
    poly[2] = *c;
    let mut n = 3;
    let mut next = [*a; MAX_POLY];
    let all = codes[0] | codes[1] | codes[2];
    for plane in 0..7 {
        if all & (1 << plane) == 0 {
            continue;
        }
        let mut m = 0;
        for i in 0..n {
            let (p, q) = (&poly[i], &poly[(i + 1) % n]);
            let (dp, dq) = (guard_distances(p.pos)[plane], guard_distances(q.pos)[plane]);
            if dp >= 0.0 {
                next[m] = *p;
                m += 1;
            }
            if (dp >= 0.0) != (dq >= 0.0) {
                // Always interpolate from the inside vertex so that an edge shared by two
                // triangles is cut at the same point whichever triangle clips it.
                let (inside, outside, di, dout) = if dp >= 0.0 {
                    (p, q, dp, dq)
                } else {
                    (q, p, dq, dp)
                };
                let t = di / (di - dout);
                next[m] = inside.lerp(outside, t);
                if plane == 6 {
                    // Rounding can land the new vertex a hair below the plane; pin it on.
                    next[m].pos.w = next[m].pos.w.max(W_MIN);
                }
                m += 1;
            }
        }
        n = m;
        if n < 3 {
            return;
        }
        std::mem::swap(&mut poly, &mut next);
    }
    emit(&poly[..n]);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f32, y: f32, z: f32, w: f32) -> ClipVertex {
        ClipVertex {
            pos: Vec4::new(x, y, z, w),
            color: Vec4::ONE,
        }
    }

    #[test]
    fn inside_passes_through_and_outside_is_dropped() {
        let mut got = 0;
        triangle(
            &v(0., 0., 0., 1.),
            &v(0.5, 0., 0., 1.),
            &v(0., 0.5, 0., 1.),
            |p| got = p.len(),
        );
        assert_eq!(got, 3);
        let mut called = false;
        triangle(
            &v(20., 0., 0., 1.),
            &v(30., 0., 0., 1.),
            &v(20., 1., 0., 1.),
            |_| called = true,
        );
        assert!(!called, "beyond the guard band");
        triangle(
            &v(2., 0., 0., 1.),
            &v(3., 0., 0., 1.),
            &v(2., 1., 0., 1.),
            |p| got = p.len(),
        );
        assert_eq!(
            got, 3,
            "outside the frustum but inside the band: kept whole"
        );
    }

    #[test]
    fn behind_the_eye_is_clipped_before_the_divide() {
        let mut out = Vec::new();
        triangle(
            &v(0., 0., 0., 1.),
            &v(0., 0., 0., -1.),
            &v(0.5, 0.5, 0., 1.),
            |p| out = p.to_vec(),
        );
        assert!(out.len() >= 3);
        for p in &out {
            assert!(p.pos.w >= W_MIN, "{:?}", p.pos);
            assert!(p.pos.x.abs() <= p.pos.w * GUARD * 1.0001);
            assert!(p.pos.z.abs() <= p.pos.w * 1.0001);
        }
    }

    #[test]
    fn screen_covering_triangle_stays_within_the_vertex_limit() {
        let mut n = 0;
        triangle(
            &v(-10., -10., 0., 1.),
            &v(30., -10., 0., 1.),
            &v(-10., 30., 0., 1.),
            |p| n = p.len(),
        );
        assert_eq!(n, 4, "clipped to the guard band's square");
        triangle(
            &v(-100., -10., -5., 1.),
            &v(100., -10., 5., 1.),
            &v(0., 100., 0.5, 1.),
            |p| n = p.len(),
        );
        assert!((3..=MAX_POLY).contains(&n));
    }
}
