//! Rasterization: which pixels a primitive covers, delivered as horizontal spans.

use super::setup::Triangle;
use super::target::Rect;

/// A run of covered pixels `x0 <= x < x1` on row `y`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Span {
    pub y: i32,
    pub x0: i32,
    pub x1: i32,
}

/// Calls `emit` for every run of pixels on rows `rows` whose centers `t` covers under the
/// top-left rule.
pub fn triangle(t: &Triangle, rows: std::ops::Range<i32>, mut emit: impl FnMut(Span)) {
    let Rect { x0, x1, .. } = t.bbox;
    let (y0, y1) = (t.bbox.y0.max(rows.start), t.bbox.y1.min(rows.end));
    let (ox, oy) = t.origin;
    for y in y0..y1 {
        let ry = (y - oy) as i64;
        let mut e = t.edges.map(|e| e.at_center((x0 - ox) as i64, ry) - e.bias);
        let step = t.edges.map(|e| e.a << super::SUBPIXEL_BITS);
        let mut start = None;
        for x in x0..x1 {
            let inside = e[0] >= 0 && e[1] >= 0 && e[2] >= 0;
            match (inside, start) {
                (true, None) => start = Some(x),
                (false, Some(s)) => {
                    emit(Span { y, x0: s, x1: x });
                    start = None;
                    // A triangle is convex: once its row has ended, nothing follows.
                    break;
                }
                _ => {}
            }
            for i in 0..3 {
                e[i] += step[i];
            }
        }
        if let Some(s) = start {
            emit(Span { y, x0: s, x1 });
        }
    }
}
