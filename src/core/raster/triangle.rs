//! Triangle coverage: pixel centers inside the edge functions, with the top-left rule.
//!
//! On each row an edge function is linear in the pixel index, so the pixels it admits form
//! one interval whose ends follow from an exact integer division; the row's span is the
//! intersection of the three intervals. No pixel outside the span is visited.

use super::super::setup::Triangle;
use super::super::target::Rect;
use super::Span;

/// Calls `emit` for every run of pixels on rows `rows` whose centers `t` covers under the
/// top-left rule.
pub fn spans(t: &Triangle, rows: std::ops::Range<i32>, mut emit: impl FnMut(Span)) {
    let Rect { x0, x1, .. } = t.bbox;
    let (y0, y1) = (t.bbox.y0.max(rows.start), t.bbox.y1.min(rows.end));
    let (ox, oy) = t.shading.origin;
    let step = t.edges.map(|e| e.a << super::super::SUBPIXEL_BITS);
    let width = (x1 - x0) as i64;
    for y in y0..y1 {
        let ry = (y - oy) as i64;
        // Pixels k = 0 .. width of the row (x = x0 + k) with E(k) = base + k·step ≥ 0.
        let (mut lo, mut hi) = (0i64, width);
        for (e, &step) in t.edges.iter().zip(&step) {
            let base = e.at_center((x0 - ox) as i64, ry) - e.bias;
            if step > 0 {
                // k ≥ ceil(−base / step)
                lo = lo.max((-base).div_euclid(step) + i64::from((-base).rem_euclid(step) != 0));
            } else if step < 0 {
                // k ≤ floor(base / −step)
                hi = hi.min(base.div_euclid(-step) + 1);
            } else if base < 0 {
                lo = width;
            }
        }
        if lo < hi {
            emit(Span {
                y,
                x0: x0 + lo as i32,
                x1: x0 + hi as i32,
            });
        }
    }
}
