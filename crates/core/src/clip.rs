//! Homogeneous clipping, before any divide, so the setup stage never divides by a w that is
//! zero or negative.
//!
//! Lines are clipped against the six frustum planes −w ≤ x, y, z ≤ w and w ≥ [`W_MIN`];
//! points are kept or dropped whole by their vertex. Every primitive is also clipped against
//! the enabled user clip planes (ES 1.1 §2.11), whose signed distances the vertex stage
//! computed in eye space ([`VertexRef::clip_dist`]): eye coordinates are a linear function
//! of clip coordinates, so those distances interpolate with the same parameter as every
//! other attribute and clipping on them is exact. Triangles are clipped in x and y against
//! a guard band [`GUARD`] times wider than the frustum instead, and the rasterizer limits
//! their pixels to the viewport rectangle, which selects exactly the pixels frustum clipping
//! would (pixel centers never lie on the viewport's integer edges). Inside the band a
//! triangle keeps its own vertices, so the pixels it covers do not depend on the viewport it
//! happens to cross, and most triangles near the edges are not clipped at all.

use glam::Vec4;

use super::vertex::{all_finite, lerp, rejects, Floats, Layout, VertexRef, MAX_STRIDE};

// Defined by the vertex stage, which codes every position against these planes.
pub use super::vertex::{GUARD, MAX_USER_PLANES, W_MIN};

/// Frustum planes (6) and the w plane.
const FRUSTUM_PLANES: usize = 7;
const PLANES: usize = FRUSTUM_PLANES + MAX_USER_PLANES;

/// Each plane adds at most one vertex.
const MAX_POLY: usize = 3 + PLANES;

/// The signed distances of a vertex to each clip plane, x and y widened by `band`, then
/// the user planes (the enabled ones; the rest read 0, inside); negative is outside.
#[inline]
fn distances_with(v: VertexRef<'_>, band: f32) -> [f32; PLANES] {
    let p = v.pos();
    let mut d = [0.0; PLANES];
    d[..FRUSTUM_PLANES].copy_from_slice(&[
        band * p.w + p.x,
        band * p.w - p.x,
        band * p.w + p.y,
        band * p.w - p.y,
        p.w + p.z,
        p.w - p.z,
        p.w - W_MIN,
    ]);
    for (i, d) in d[FRUSTUM_PLANES..].iter_mut().enumerate() {
        *d = v.clip_dist(i);
    }
    d
}

/// Distances to the frustum planes and the user planes.
#[inline]
fn distances(v: VertexRef<'_>) -> [f32; PLANES] {
    distances_with(v, 1.0)
}

/// The distance of vertex `v` (in `layout`) to plane `plane` of the guard band's planes
/// (x, y), the frustum's (z, w) and the user planes.
#[inline]
fn guard_distance(v: &[f32], layout: &Layout, plane: usize) -> f32 {
    let p = Vec4::from_slice(&v[..4]);
    match plane {
        0 => GUARD * p.w + p.x,
        1 => GUARD * p.w - p.x,
        2 => GUARD * p.w + p.y,
        3 => GUARD * p.w - p.y,
        4 => p.w + p.z,
        5 => p.w - p.z,
        6 => p.w - W_MIN,
        k => v[layout.clip(k - FRUSTUM_PLANES)],
    }
}

/// [`guard_distance`] in f64, for the frustum and guard planes (0 to 5) only.
#[inline]
fn guard_distance64(p: glam::DVec4, plane: usize) -> f64 {
    let g = GUARD as f64;
    match plane {
        0 => g * p.w + p.x,
        1 => g * p.w - p.x,
        2 => g * p.w + p.y,
        3 => g * p.w - p.y,
        4 => p.w + p.z,
        _ => p.w - p.z,
    }
}

/// The planes that apply: the frustum's and the enabled user planes.
#[inline]
fn plane_count(layout: &Layout) -> usize {
    FRUSTUM_PLANES + layout.planes
}

/// A bit per plane (of the guard band, then the enabled user planes) that the vertex is
/// outside of.
#[inline]
pub fn outcode(v: VertexRef<'_>) -> u16 {
    // The distances of `guard_distance`, four at a time: the low planes (0, 2, 4, 6:
    // x + g, y + g, z + w, w − W_MIN) in one vector and the high planes (1, 3, 5: g − x,
    // g − y, w − z) in another, whose spare lane reads 0, inside. Negating `d >= 0` counts
    // NaN as outside.
    let p = v.pos();
    let g = GUARD * p.w;
    let low = Vec4::new(p.x, p.y, p.z, p.w) + Vec4::new(g, g, p.w, -W_MIN);
    let high = Vec4::new(g, g, p.w, 0.0) - Vec4::new(p.x, p.y, p.z, 0.0);
    let outside = |d: Vec4| !d.cmpge(Vec4::ZERO).bitmask() as usize & 0xf;
    let mut code = SPREAD[outside(low)] | SPREAD[outside(high)] << 1;
    for i in 0..v.layout.planes {
        let d = v.clip_dist(i);
        code |= u16::from(d.is_nan() || d < 0.0) << (FRUSTUM_PLANES + i);
    }
    code
}

/// Bit i of the index moved to bit 2i.
const SPREAD: [u16; 16] = {
    let mut t = [0; 16];
    let mut i = 0;
    while i < 16 {
        t[i] = (i & 1 | (i & 2) << 1 | (i & 4) << 2 | (i & 8) << 3) as u16;
        i += 1;
    }
    t
};

/// Clips segment (a, b) against the clip volume and the enabled user planes, and calls
/// `emit` with what is left, in the original direction, or not at all when nothing is.
pub fn line(a: VertexRef<'_>, b: VertexRef<'_>, emit: impl FnOnce(VertexRef<'_>, VertexRef<'_>)) {
    if !all_finite([a.pos(), b.pos()]) {
        return;
    }
    let n = plane_count(a.layout);
    let (da, db) = (distances(a), distances(b));
    let (da, db) = (&da[..n], &db[..n]);
    let (mut t0, mut t1) = (0f32, 1f32);
    for (&pa, &pb) in da.iter().zip(db) {
        // NaN distances (a user plane meeting an infinite eye position) count as outside.
        if pa.is_nan() || pb.is_nan() || (pa < 0.0 && pb < 0.0) {
            return;
        }
        if pa < 0.0 {
            t0 = t0.max(pa / (pa - pb));
        } else if pb < 0.0 {
            t1 = t1.min(pa / (pa - pb));
        }
    }
    if t0 > t1 {
        return;
    }
    let mut cut: [Floats; 2] = [[0.0; MAX_STRIDE]; 2];
    let [start, end] = &mut cut;
    if t0 != 0.0 {
        lerp(a.own(), b.own(), t0, start);
    }
    if t1 != 1.0 {
        lerp(a.own(), b.own(), t1, end);
    }
    let layout = a.layout;
    emit(
        if t0 == 0.0 { a } else { layout.view(start) },
        if t1 == 1.0 { b } else { layout.view(end) },
    )
}

/// True when a point survives clipping: its vertex lies inside the clip volume and the
/// enabled user planes. (A wide point whose center is inside is drawn whole; one whose
/// center is outside is not drawn.)
pub fn point(v: VertexRef<'_>) -> bool {
    all_finite([v.pos()])
        && distances(v)[..plane_count(v.layout)]
            .iter()
            .all(|&d| d >= 0.0)
}

/// Clips triangle (a, b, c) against the guard band, the near, far and w planes and the enabled
/// user planes, and calls `emit` with the resulting convex polygon (at least three
/// vertices, in the original winding), or not at all when nothing is left. The polygon is
/// passed by reference: most triangles need no clipping and reach `emit` without copying
/// their vertices.
pub fn triangle<'v>(
    a: VertexRef<'v>,
    b: VertexRef<'v>,
    c: VertexRef<'v>,
    emit: impl FnOnce(&[VertexRef<'_>]),
) {
    if rejects(a.pos(), b.pos(), c.pos()) {
        return;
    }
    let codes = [outcode(a), outcode(b), outcode(c)];
    if codes[0] | codes[1] | codes[2] == 0 {
        emit(&[a, b, c]);
        return;
    }
    if codes[0] & codes[1] & codes[2] != 0 {
        return;
    }
    clip_polygon(a, b, c, codes[0] | codes[1] | codes[2], emit);
}

/// Clips triangle (a, b, c), whose vertices are outside the planes of `all` between them,
/// for [`triangle`]: out of line, so the common case does not set up (and probe) the
/// polygon buffers' stack frame.
#[cold]
#[inline(never)]
fn clip_polygon(
    a: VertexRef<'_>,
    b: VertexRef<'_>,
    c: VertexRef<'_>,
    all: u16,
    emit: impl FnOnce(&[VertexRef<'_>]),
) {
    let layout = a.layout;
    let stride = layout.stride;
    let mut poly: [Floats; MAX_POLY] = [[0.0; MAX_STRIDE]; MAX_POLY];
    for (p, v) in poly.iter_mut().zip([a, b, c]) {
        p[..stride].copy_from_slice(v.own());
    }
    let mut n = 3;
    let mut next = poly;
    for plane in 0..plane_count(layout) {
        if all & (1 << plane) == 0 {
            continue;
        }
        let mut m = 0;
        for i in 0..n {
            let (p, q) = (&poly[i][..stride], &poly[(i + 1) % n][..stride]);
            let (dp, dq) = (
                guard_distance(p, layout, plane),
                guard_distance(q, layout, plane),
            );
            if dp >= 0.0 {
                next[m][..stride].copy_from_slice(p);
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
                if plane == 6 {
                    // Issue 10 (tests/hard_cases.rs case 1): after the guard planes every
                    // vertex outside the w plane lies at the clip-space origin (|x|, |y|,
                    // |z| ≤ 8w ≈ 0), so t rounds to 1 and interpolating from the inside
                    // vertex returns that origin, which w = W_MIN then projects to the
                    // screen's center. From the outside vertex the tiny parameter keeps
                    // the direction of the edge, as the limit w → 0⁺ does. Still one
                    // deterministic choice per edge, so shared edges stay watertight.
                    lerp(outside, inside, dout / (dout - di), &mut next[m]);
                } else {
                    lerp(inside, outside, t, &mut next[m]);
                }
                if plane < 6 {
                    // Issue 10 (tests/hard_cases.rs case 4): with coordinates near 2³² an
                    // f32 lerp between two vertices ~10⁸ apart in clip space is off by tens
                    // of units, more than the whole guard band, and can cut away half the
                    // screen. The position is therefore interpolated in f64 from f64
                    // distances, then put exactly on the plane it was clipped against.
                    let pos = |v: &[f32]| Vec4::from_slice(&v[..4]).as_dvec4();
                    let (ip, op) = (pos(inside), pos(outside));
                    let (di, dout) = (guard_distance64(ip, plane), guard_distance64(op, plane));
                    let mut p = (ip + (op - ip) * (di / (di - dout))).as_vec4();
                    let g = GUARD * p.w;
                    match plane {
                        0 => p.x = -g,
                        1 => p.x = g,
                        2 => p.y = -g,
                        3 => p.y = g,
                        4 => p.z = -p.w,
                        _ => p.z = p.w,
                    }
                    next[m][..4].copy_from_slice(&p.to_array());
                }
                if plane == 6 {
                    // Rounding can land the new vertex a hair below the plane; pin it on.
                    next[m][3] = next[m][3].max(W_MIN);
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
    let refs: [VertexRef<'_>; MAX_POLY] = std::array::from_fn(|i| layout.view(&poly[i.min(n - 1)]));
    emit(&refs[..n]);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vertex::{reject_code, ClipVertex, CLIPS};

    fn v(x: f32, y: f32, z: f32, w: f32) -> [f32; 4] {
        [x, y, z, w]
    }

    /// Clips the triangle with clip positions (a, b, c) and color 1, no user planes.
    fn tri(a: [f32; 4], b: [f32; 4], c: [f32; 4], emit: impl FnOnce(&[VertexRef<'_>])) {
        let layout = Layout::full(0);
        let [a, b, c] =
            [a, b, c].map(|p| layout.pack(&ClipVertex::new(Vec4::from_array(p), Vec4::ONE)));
        triangle(layout.view(&a), layout.view(&b), layout.view(&c), emit);
    }

    #[test]
    fn inside_passes_through_and_outside_is_dropped() {
        let mut got = 0;
        tri(
            v(0., 0., 0., 1.),
            v(0.5, 0., 0., 1.),
            v(0., 0.5, 0., 1.),
            |p| got = p.len(),
        );
        assert_eq!(got, 3);
        let mut called = false;
        tri(
            v(20., 0., 0., 1.),
            v(30., 0., 0., 1.),
            v(20., 1., 0., 1.),
            |_| called = true,
        );
        assert!(!called, "beyond the guard band");
        tri(
            v(2., 0., 0., 1.),
            v(3., 0., 0., 1.),
            v(2., 1., 0., 1.),
            |_| called = true,
        );
        assert!(!called, "outside the frustum's right plane");
        tri(
            v(0.5, 0., 0., 1.),
            v(3., 0., 0., 1.),
            v(2., 1., 0., 1.),
            |p| got = p.len(),
        );
        assert_eq!(
            got, 3,
            "crossing the frustum's edge inside the band: kept whole"
        );
        got = 0;
        tri(
            v(2., 0., 0., 1.),
            v(0.5, 0., 0., -1.),
            v(2., 1., 0., 1.),
            |p| got = p.len(),
        );
        assert_eq!(got, 0, "x > w at every vertex, one behind the eye");
    }

    #[test]
    fn outcodes_match_the_plane_distances() {
        let vals = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            7.9,
            -8.1,
            1e-31,
            f32::NAN,
            f32::INFINITY,
            0.5,
        ];
        let (mut n, mut checked) = (0, 0);
        for &x in &vals {
            for &y in &vals {
                for &z in &vals[..6] {
                    for &w in &vals {
                        let mut p = ClipVertex::new(Vec4::new(x, y, z, w), Vec4::ONE);
                        p.clip_dist = [x, -y, z, w, f32::NAN, 0.0];
                        n += 1;
                        for user in [0, 3, 6] {
                            let layout = Layout::full(user);
                            let f = layout.pack(&p);
                            let code = outcode(layout.view(&f));
                            for plane in 0..plane_count(&layout) {
                                let d = guard_distance(&f, &layout, plane);
                                let out = d.is_nan() || d < 0.0;
                                assert_eq!(code >> plane & 1 == 1, out, "{p:?} {plane}");
                            }
                            assert_eq!(code >> plane_count(&layout), 0);
                            if user == 0 && p.pos.is_finite() {
                                // The vertex stage's code says the same of a finite
                                // position (the others are rejected before it is read).
                                let clips = reject_code(p.pos) & CLIPS != 0;
                                assert_eq!(clips, code != 0, "{p:?}");
                                checked += 1;
                            }
                        }
                    }
                }
            }
        }
        assert!(n > 1000 && checked > 500, "{n} {checked}");
    }

    #[test]
    fn behind_the_eye_is_clipped_before_the_divide() {
        let mut out = Vec::new();
        tri(
            v(0., 0., 0., 1.),
            v(0., 0., 0., -1.),
            v(0.5, 0.5, 0., 1.),
            |p| out = p.iter().map(|v| v.pos()).collect(),
        );
        assert!(out.len() >= 3);
        for p in &out {
            assert!(p.w >= W_MIN, "{p:?}");
            assert!(p.x.abs() <= p.w * GUARD * 1.0001);
            assert!(p.z.abs() <= p.w * 1.0001);
        }
    }

    #[test]
    fn screen_covering_triangle_stays_within_the_vertex_limit() {
        let mut n = 0;
        tri(
            v(-10., -10., 0., 1.),
            v(30., -10., 0., 1.),
            v(-10., 30., 0., 1.),
            |p| n = p.len(),
        );
        assert_eq!(n, 4, "clipped to the guard band's square");
        tri(
            v(-100., -10., -5., 1.),
            v(100., -10., 5., 1.),
            v(0., 100., 0.5, 1.),
            |p| n = p.len(),
        );
        assert!((3..=MAX_POLY).contains(&n));
    }
}
