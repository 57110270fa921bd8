//! Triangle coverage: pixel centers inside the edge functions, with the top-left rule.
//!
//! On each row an edge function is linear in the pixel index, so the pixels it admits form
//! one interval whose end is a quotient of integers; the row's span is the intersection of
//! the three intervals. The quotients are divided exactly once per triangle and then
//! stepped from row to row with their remainders, so no pixel outside the span is visited
//! and no row divides.

use super::super::setup::Triangle;
use super::super::target::Rect;
use super::super::SUBPIXEL_BITS;
use super::Span;

/// `(⌊n / d⌋, n mod d)` for |n| < 2⁵², 0 < d < 2⁵¹ and |n / d| < 2⁵⁰: the rows' bounds,
/// where d is a whole subpixel step below 2³³ (so |n / d| < 2⁴⁴) or 1 for the bounds that
/// stay (n below the box's width). In f64 arithmetic that vectorizes (64-bit integer
/// division, multiplication and conversion from f64 do not, on AVX2). Rounding is
/// monotonic and keeps integers, so the rounded quotient lies between the same two
/// integers as the exact one, and its truncation q is ⌊n / d⌋ or, when it rounded up to
/// the next integer or is negative, one more. Every step after the division is exact: q·d
/// is an integer within d of n (below 2⁵³), n − q·d is below 2d, and a negative remainder
/// reveals the one more. q and 0 ≤ r < d, both below 2⁵¹, become integers by the
/// 1.5 · 2⁵² add.
#[inline(always)]
fn floor_div(n: i64, d: i64) -> (i64, i64) {
    const MAGIC: f64 = 6_755_399_441_055_744.0;
    let (n, d) = (n as f64, d as f64);
    let q = (n / d).trunc();
    let r = n - q * d;
    let (q, r) = if r < 0.0 { (q - 1.0, r + d) } else { (q, r) };
    let int = |v: f64| ((v + MAGIC).to_bits() as i64).wrapping_sub(MAGIC.to_bits() as i64);
    (int(q), int(r))
}

/// The four bounds of a row's pixels, two lows then two highs, as lanes: each ⌊n / d⌋ for a
/// numerator that grows by `dn` per row over a fixed positive `d`, kept exact with the
/// remainder. A row steps all four in a few vector instructions.
struct Quotients {
    q: [i64; 4],
    /// The remainders, each in [0, d).
    r: [i64; 4],
    d: [i64; 4],
    dq: [i64; 4],
    dr: [i64; 4],
}

impl Quotients {
    /// The quotients of numerators `n`, growing by `dn` per row, over `d`.
    #[inline(always)]
    fn new(n: [i64; 4], dn: [i64; 4], d: [i64; 4]) -> Quotients {
        let (mut q, mut r, mut dq, mut dr) = ([0; 4], [0; 4], [0; 4], [0; 4]);
        for k in 0..4 {
            (q[k], r[k]) = floor_div(n[k], d[k]);
            (dq[k], dr[k]) = floor_div(dn[k], d[k]);
        }
        Quotients { q, r, d, dq, dr }
    }

    /// The next row's quotients. Without a branch: whether a remainder carries is as
    /// unpredictable as a rounding.
    #[inline(always)]
    fn step(&mut self) {
        for k in 0..4 {
            self.q[k] += self.dq[k];
            self.r[k] += self.dr[k];
            let carry = self.r[k] >= self.d[k];
            self.q[k] += i64::from(carry);
            self.r[k] -= if carry { self.d[k] } else { 0 };
        }
    }
}

/// Bounding boxes at most this many pixels wide test each pixel center against the edges
/// directly: for the few pixels of a small triangle that is cheaper than the divisions
/// that find the ends of its rows.
const NARROW: usize = 4;

/// [`spans`] for a bounding box at most [`NARROW`] pixels wide: the same test
/// `E − bias ≥ 0`, evaluated at every pixel center, so the same pixels. A row's covered
/// pixels are one interval (the triangle is convex), from the first to the last.
///
/// The edge values are f64 lanes, one per pixel of the row, so a row is a few vector
/// instructions: every value is an integer below 2⁵² in magnitude (coordinates below 2²⁵
/// subpixels from the origin, see [`crate::MAX_VIEWPORT_DIM`], so `c` is below 2⁵¹ and
/// `a·x + b·y` below 2⁴⁷ inside the box), where f64 sums are exact.
#[inline(always)]
fn narrow_spans(t: &Triangle, rows: std::ops::Range<i32>, ry: i64, mut emit: impl FnMut(Span)) {
    let Rect { x0, x1, .. } = t.bbox;
    let ox = t.shading.origin.0;
    let mut values = [[0.0; NARROW]; 3];
    let mut growth = [0.0; 3];
    for ((v, g), e) in values.iter_mut().zip(&mut growth).zip(&t.edges) {
        let base = e.at_center((x0 - ox) as i64, ry) - e.bias();
        let step = (e.a as i64) << SUBPIXEL_BITS;
        for (k, v) in v.iter_mut().enumerate() {
            *v = (base + k as i64 * step) as f64;
        }
        *g = ((e.b as i64) << SUBPIXEL_BITS) as f64;
    }
    // Pixels of the lanes past the box are never covered.
    let in_box = (1u32 << (x1 - x0)) - 1;
    for y in rows {
        // A bit per pixel outside an edge, every lane tested without a branch (a pixel's
        // coverage is as unpredictable as a rounding): then the first and the last
        // covered. No value is −0 (a conversion gives +0, and so does a sum that cancels),
        // so `E ≥ 0` is a clear sign bit, and the three edges' bits ORed test them all.
        let [e0, e1, e2] = &values;
        let mut outside = 0;
        for (k, ((a, b), c)) in e0.iter().zip(e1).zip(e2).enumerate() {
            outside |= (((a.to_bits() | b.to_bits() | c.to_bits()) >> 63) as u32) << k;
        }
        let covered = !outside & in_box;
        for (v, g) in values.iter_mut().zip(growth) {
            for v in v {
                *v += g;
            }
        }
        if covered != 0 {
            emit(Span {
                y,
                x0: x0 + covered.trailing_zeros() as i32,
                x1: x0 + (u32::BITS - covered.leading_zeros()) as i32,
            });
        }
    }
}

/// Calls `emit` for every run of pixels on rows `rows` whose centers `t` covers under the
/// top-left rule. Compiled also for AVX2 and SSE4.1 and chosen at run time: the bounds'
/// lanes step as 64-bit vectors there (SSE2 has no 64-bit compare).
#[cfg_attr(
    not(fuzzing),
    multiversion::multiversion(targets("x86_64+avx2", "x86_64+sse4.1"))
)]
pub fn spans(t: &Triangle, rows: std::ops::Range<i32>, mut emit: impl FnMut(Span)) {
    let Rect { x0, x1, .. } = t.bbox;
    let (y0, y1) = (t.bbox.y0.max(rows.start), t.bbox.y1.min(rows.end));
    if y0 >= y1 {
        return;
    }
    let (ox, oy) = t.shading.origin;
    let width = (x1 - x0) as i64;
    let ry = (y0 - oy) as i64;
    if width <= NARROW as i64 {
        narrow_spans(t, y0..y1, ry, emit);
        return;
    }
    // E(k) = base + k·step ≥ 0 on the first row; base grows by b·ONE per row. A rising
    // edge (step > 0) allows k ≥ −q with q = ⌊base/step⌋, a falling one k ≤ ⌊base/−step⌋.
    // A triangle has one or two of each; padded to two of each with bounds that allow
    // every pixel, the row loop is the same for every triangle, without a branch per edge
    // (which kind an edge is changes from triangle to triangle). A horizontal edge allows
    // whole rows or none, so it limits the rows instead.
    // Lanes 0 and 1 are lows, 2 and 3 highs: n / 1 with dn = 0 is a bound that stays.
    let (mut n, mut dn, mut d) = ([0, 0, width - 1, width - 1], [0; 4], [1; 4]);
    let (mut n_low, mut n_high) = (0, 0);
    let mut kept = y0..y1;
    for e in &t.edges {
        let base = e.at_center((x0 - ox) as i64, ry) - e.bias();
        let dbase = (e.b as i64) << SUBPIXEL_BITS;
        let step = (e.a as i64) << SUBPIXEL_BITS;
        // A triangle has at most two edges of each kind.
        let lane = if step > 0 {
            n_low += 1;
            (n_low <= 2).then_some(n_low - 1)
        } else if step < 0 {
            n_high += 1;
            (n_high <= 2).then_some(n_high + 1)
        } else {
            // base + i·dbase ≥ 0 on row y0 + i: from −⌊base/dbase⌋ on when it grows, up to
            // ⌊base/−dbase⌋ when it falls, every row or none when it stays.
            let (first, last) = match dbase.signum() {
                1 => (-base.div_euclid(dbase), i64::MAX),
                -1 => (0, base.div_euclid(-dbase)),
                _ if base >= 0 => (0, i64::MAX),
                _ => (0, -1),
            };
            let row = |i: i64| (y0 as i64).saturating_add(i).clamp(y0 as i64, y1 as i64) as i32;
            kept = kept.start.max(row(first))..kept.end.min(row(last.saturating_add(1)));
            continue;
        };
        if let Some(k) = lane {
            (n[k], dn[k], d[k]) = (base, dbase, step.abs());
        }
    }
    let mut bounds = Quotients::new(n, dn, d);
    for y in y0..y1 {
        let q = bounds.q;
        let lo = 0.max(-q[0]).max(-q[1]);
        let hi = width.min(q[2] + 1).min(q[3] + 1);
        bounds.step();
        if lo < hi && kept.contains(&y) {
            emit(Span {
                y,
                x0: x0 + lo as i32,
                x1: x0 + hi as i32,
            });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::setup;
    use crate::state::RenderState;
    use crate::tests::Lcg;
    use crate::vertex::{ClipVertex, Layout};
    use glam::Vec4;

    /// The triangle of clip-space corners `p`, set up for `state` inside `bounds`, if kept.
    fn set_up(state: &RenderState, p: [Vec4; 3], bounds: Rect) -> Option<Triangle> {
        let layout = Layout::full(0);
        let f = p.map(|p| layout.pack(&ClipVertex::new(p, Vec4::ONE)));
        let v = f.each_ref().map(|f| layout.view(f));
        let mut kept = None;
        setup::triangle(state, v, None, None, bounds, None, &mut kept);
        kept
    }

    /// Asserts that [`spans`] gives exactly the pixel centers of rows `rows` that the edge
    /// functions admit, and returns how many spans it gave.
    fn spans_admit_the_centers(t: &Triangle, rows: std::ops::Range<i32>, n: usize) -> usize {
        let (mut got, mut count) = (Vec::new(), 0);
        spans(t, rows.clone(), |s| {
            got.extend((s.x0..s.x1).map(|x| (x, s.y)));
            count += 1;
        });
        let (ox, oy) = t.shading.origin;
        let mut want = Vec::new();
        for y in t.bbox.y0.max(rows.start)..t.bbox.y1.min(rows.end) {
            for x in t.bbox.x0..t.bbox.x1 {
                let (px, py) = ((x - ox) as i64, (y - oy) as i64);
                if t.edges.iter().all(|e| e.at_center(px, py) - e.bias() >= 0) {
                    want.push((x, y));
                }
            }
        }
        assert_eq!(got, want, "triangle {n}");
        count
    }

    #[test]
    fn floor_div_matches_integer_division() {
        // Near the largest magnitudes, near multiples of d (where the f64 quotient rounds
        // to an integer from either side) and at random.
        let mut rng = Lcg(3);
        let mut rand = |bits: u32| ((rng.next() as f64) * (1u64 << bits) as f64) as i64;
        let mut cases = Vec::new();
        for d in [1, 3, 256, 255 << 8, (1 << 33) - 256, (1 << 51) - 1] {
            for q in [0i64, 1, 2, 1 << 20, (1 << 52) / d - 1] {
                let Some(n) = q.checked_mul(d) else { continue };
                cases.extend((-2..=2).map(|e| (n + e, d)));
            }
            for _ in 0..200 {
                cases.push((rand(52) - rand(52), d));
                cases.push((rand(52) / d * d + rand(3) - 4, d));
            }
        }
        for (n, d) in cases {
            for n in [n, -n] {
                if n.abs() < 1 << 52 && (n / d).abs() < 1 << 50 {
                    assert_eq!(
                        floor_div(n, d),
                        (n.div_euclid(d), n.rem_euclid(d)),
                        "{n} / {d}"
                    );
                }
            }
        }
    }

    /// Both ways of finding a row's pixels (the edge functions at each center for narrow
    /// bounding boxes, the stepped quotients for wider ones) give exactly the pixel centers
    /// the edge functions admit, on small random triangles of both windings.
    #[test]
    fn spans_are_the_centers_the_edge_functions_admit() {
        let (w, h) = (24, 24);
        let state = RenderState::new(w, h);
        let mut rng = Lcg(0x9e37_79b9);
        let (mut narrow, mut wide) = (0, 0);
        for n in 0..4000 {
            // Within about 1 to 8 pixels of a point, in clip coordinates, some across the
            // edges of the bounds (which cut the bounding box).
            let size = if n % 2 == 0 { 0.1 } else { 0.6 };
            let (cx, cy) = (rng.next() * 2.0 - 1.2, rng.next() * 2.0 - 1.2);
            let mut corner = || Vec4::new(cx + size * rng.next(), cy + size * rng.next(), 0.0, 1.0);
            let mut p = [corner(), corner(), corner()];
            // Every third triangle has a horizontal edge through a row of pixel centers,
            // above or below the third vertex: an edge that limits rows rather than
            // pixels, and owns the centers on it or not by the top-left rule.
            if n % 3 == 2 {
                let row = ((p[1].y + 1.0) * h as f32 / 2.0).floor();
                p[1].y = (2.0 * row + 1.0) / h as f32 - 1.0;
                p[2].y = p[1].y;
            }
            let Some(t) = set_up(&state, p, Rect::new(2, 3, w - 7, h - 5)) else {
                continue;
            };
            let drawn = spans_admit_the_centers(&t, 0..h, n) > 0;
            if t.bbox.x1 - t.bbox.x0 <= NARROW as i32 {
                narrow += usize::from(drawn);
            } else {
                wide += usize::from(drawn);
            }
        }
        assert!(narrow > 100 && wide > 100, "{narrow} narrow, {wide} wide");
    }

    /// Narrow boxes of triangles that reach the guard band of the largest viewport: the
    /// largest edge values there are (near 2⁵¹), where the f64 lanes must still be exact.
    /// A box three pixels wide, anywhere in the viewport, cuts each triangle. Every other
    /// triangle has its vertices on pixel centers and edges of slope ±1, which cross pixel
    /// centers on every row, where a value off by one decides the pixel.
    #[test]
    fn narrow_spans_are_exact_for_the_largest_edge_values() {
        let size = crate::MAX_VIEWPORT_DIM as i32;
        let state = RenderState::new(size, size);
        let mut rng = Lcg(0x2545_f491);
        let guard = crate::clip::GUARD;
        let mut covered = 0;
        for n in 0..400 {
            let p = if n % 2 == 0 {
                let mut corner = || {
                    let v = |r: f32| (r * 2.0 - 1.0) * guard;
                    Vec4::new(v(rng.next()), v(rng.next()), 0.0, 1.0)
                };
                [corner(), corner(), corner()]
            } else {
                // Pixel (x, y)'s center in clip coordinates, x and y within the guard band.
                let half = size as f32 / 2.0;
                let center = |x: f32, y: f32| {
                    Vec4::new((x + 0.5) / half - 1.0, (y + 0.5) / half - 1.0, 0.0, 1.0)
                };
                let reach = half * (guard - 1.0);
                let mut pixel = || (rng.next() * size as f32).floor();
                let (x, y) = (pixel(), pixel());
                let d = (rng.next() * reach).floor() + 1.0;
                let x0 = if n % 4 == 1 { x - d } else { x + d };
                [center(x0, y), center(x, y + d), center(x, y - d)]
            };
            let x = (rng.next() * (size - 3) as f32) as i32;
            let Some(t) = set_up(&state, p, Rect::new(x, 0, 3, size)) else {
                continue;
            };
            covered += spans_admit_the_centers(&t, 0..size, n);
        }
        assert!(covered > 100_000, "{covered} rows");
    }
}
