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

/// ⌊n / d⌋ for a numerator that grows by `dn` per row and a fixed positive `d`, kept
/// exact with the remainder.
#[derive(Clone, Copy)]
struct Quotient {
    q: i64,
    /// The remainder, in [0, d).
    r: i64,
    d: i64,
    dq: i64,
    dr: i64,
}

impl Quotient {
    fn new(n: i64, dn: i64, d: i64) -> Quotient {
        // One division each for quotient and remainder (d > 0), then the floor's fix-up.
        let floor = |n: i64| {
            let (q, r) = (n / d, n % d);
            if r < 0 {
                (q - 1, r + d)
            } else {
                (q, r)
            }
        };
        // No step (a vertical edge, or a single row) needs no division.
        let (q, r) = floor(n);
        let (dq, dr) = if dn == 0 { (0, 0) } else { floor(dn) };
        Quotient { q, r, d, dq, dr }
    }

    /// A bound that stays at `q`.
    fn fixed(q: i64) -> Quotient {
        Quotient {
            q,
            r: 0,
            d: 1,
            dq: 0,
            dr: 0,
        }
    }

    /// The next row's quotient. Without a branch: whether the remainder carries is as
    /// unpredictable as a rounding.
    #[inline]
    fn step(&mut self) {
        self.q += self.dq;
        self.r += self.dr;
        let carry = self.r >= self.d;
        self.q += i64::from(carry);
        self.r -= if carry { self.d } else { 0 };
    }
}

/// Bounding boxes at most this many pixels wide test each pixel center against the edges
/// directly: for the few pixels of a small triangle that is cheaper than the divisions
/// that find the ends of its rows.
const NARROW: i64 = 4;

/// [`spans`] for a bounding box at most [`NARROW`] pixels wide: the same test
/// `E − bias ≥ 0`, evaluated at every pixel center, so the same pixels. A row's covered
/// pixels are one interval (the triangle is convex), from the first to the last.
fn narrow_spans(t: &Triangle, rows: std::ops::Range<i32>, ry: i64, mut emit: impl FnMut(Span)) {
    let Rect { x0, x1, .. } = t.bbox;
    let width = (x1 - x0) as i64;
    let ox = t.shading.origin.0;
    // Per edge: E − bias at the row's first pixel, its growth per row and per pixel.
    let edge = |e: &super::super::setup::Edge| {
        (
            e.at_center((x0 - ox) as i64, ry) - e.bias(),
            (e.b as i64) << SUBPIXEL_BITS,
            (e.a as i64) << SUBPIXEL_BITS,
        )
    };
    let mut edges = [edge(&t.edges[0]), edge(&t.edges[1]), edge(&t.edges[2])];
    for y in rows {
        // A bit per covered pixel, every one of the NARROW tested without a branch (a
        // pixel's coverage is as unpredictable as a rounding): then the first and the last.
        let mut covered = 0u32;
        for k in 0..NARROW {
            let inside = |(base, _, step): (i64, i64, i64)| base + k * step >= 0;
            let hit = (k < width) & inside(edges[0]) & inside(edges[1]) & inside(edges[2]);
            covered |= u32::from(hit) << k;
        }
        for (base, dbase, _) in &mut edges {
            *base += *dbase;
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
/// top-left rule.
pub fn spans(t: &Triangle, rows: std::ops::Range<i32>, mut emit: impl FnMut(Span)) {
    let Rect { x0, x1, .. } = t.bbox;
    let (y0, y1) = (t.bbox.y0.max(rows.start), t.bbox.y1.min(rows.end));
    if y0 >= y1 {
        return;
    }
    let (ox, oy) = t.shading.origin;
    let width = (x1 - x0) as i64;
    let ry = (y0 - oy) as i64;
    if width <= NARROW {
        narrow_spans(t, y0..y1, ry, emit);
        return;
    }
    // E(k) = base + k·step ≥ 0 on the first row; base grows by b·ONE per row. A rising
    // edge (step > 0) allows k ≥ −q with q = ⌊base/step⌋, a falling one k ≤ ⌊base/−step⌋.
    // A triangle has one or two of each; padded to two of each with bounds that allow
    // every pixel, the row loop is the same for every triangle, without a branch per edge
    // (which kind an edge is changes from triangle to triangle). A horizontal edge allows
    // whole rows or none, so it limits the rows instead.
    let (mut lows, mut highs) = ([Quotient::fixed(0); 2], [Quotient::fixed(width - 1); 2]);
    let (mut n_low, mut n_high) = (0, 0);
    let mut kept = y0..y1;
    for e in &t.edges {
        let base = e.at_center((x0 - ox) as i64, ry) - e.bias();
        let dbase = (e.b as i64) << SUBPIXEL_BITS;
        let step = (e.a as i64) << SUBPIXEL_BITS;
        // A single row never steps (common: most small triangles meet a band in a row or
        // two), so it needs no division for the step.
        let dn = if y1 - y0 > 1 { dbase } else { 0 };
        if step > 0 {
            if let Some(b) = lows.get_mut(n_low) {
                *b = Quotient::new(base, dn, step);
            }
            n_low += 1;
        } else if step < 0 {
            if let Some(b) = highs.get_mut(n_high) {
                *b = Quotient::new(base, dn, -step);
            }
            n_high += 1;
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
        }
    }
    for y in y0..y1 {
        let lo = 0.max(-lows[0].q).max(-lows[1].q);
        let hi = width.min(highs[0].q + 1).min(highs[1].q + 1);
        for q in lows.iter_mut().chain(&mut highs) {
            q.step();
        }
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
    use crate::vertex::{ClipVertex, Layout};
    use glam::Vec4;

    /// Both ways of finding a row's pixels (the edge functions at each center for narrow
    /// bounding boxes, the stepped quotients for wider ones) give exactly the pixel centers
    /// the edge functions admit, on small random triangles of both windings.
    #[test]
    fn spans_are_the_centers_the_edge_functions_admit() {
        let (w, h) = (24, 24);
        let state = RenderState::new(w, h);
        let layout = Layout::full(0);
        let mut seed = 0x9e37_79b9_u32;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            seed as f32 / u32::MAX as f32
        };
        let (mut narrow, mut wide) = (0, 0);
        for n in 0..4000 {
            // Within about 1 to 8 pixels of a point, in clip coordinates, some across the
            // edges of the bounds (which cut the bounding box).
            let size = if n % 2 == 0 { 0.1 } else { 0.6 };
            let (cx, cy) = (next() * 2.0 - 1.2, next() * 2.0 - 1.2);
            let mut corner = || Vec4::new(cx + size * next(), cy + size * next(), 0.0, 1.0);
            let mut p = [corner(), corner(), corner()];
            // Every third triangle has a horizontal edge through a row of pixel centers,
            // above or below the third vertex: an edge that limits rows rather than
            // pixels, and owns the centers on it or not by the top-left rule.
            if n % 3 == 2 {
                let row = ((p[1].y + 1.0) * h as f32 / 2.0).floor();
                p[1].y = (2.0 * row + 1.0) / h as f32 - 1.0;
                p[2].y = p[1].y;
            }
            let f = p.map(|p| layout.pack(&ClipVertex::new(p, Vec4::ONE)));
            let v = f.each_ref().map(|f| layout.view(f));
            let bounds = Rect::new(2, 3, w - 7, h - 5);
            let mut kept = None;
            setup::triangle(&state, v, v[2], bounds, None, &mut kept);
            let Some(t) = kept else {
                continue;
            };
            let mut got = Vec::new();
            spans(&t, 0..h, |s| got.extend((s.x0..s.x1).map(|x| (x, s.y))));
            let (ox, oy) = t.shading.origin;
            let mut want = Vec::new();
            for y in t.bbox.y0..t.bbox.y1 {
                for x in t.bbox.x0..t.bbox.x1 {
                    let (px, py) = ((x - ox) as i64, (y - oy) as i64);
                    if t.edges.iter().all(|e| e.at_center(px, py) - e.bias() >= 0) {
                        want.push((x, y));
                    }
                }
            }
            assert_eq!(got, want, "triangle {n}");
            if t.bbox.x1 - t.bbox.x0 <= NARROW as i32 {
                narrow += usize::from(!want.is_empty());
            } else {
                wide += usize::from(!want.is_empty());
            }
        }
        assert!(narrow > 100 && wide > 100, "{narrow} narrow, {wide} wide");
    }
}
