//! Triangle coverage: pixel centers inside the edge functions, with the top-left rule.

use super::super::setup::Triangle;
use super::super::target::Rect;
use super::Span;

/// Calls `emit` for every run of pixels on rows `rows` whose centers `t` covers under the
/// top-left rule.
pub fn spans(t: &Triangle, rows: std::ops::Range<i32>, mut emit: impl FnMut(Span)) {
    let Rect { x0, x1, .. } = t.bbox;
    let (y0, y1) = (t.bbox.y0.max(rows.start), t.bbox.y1.min(rows.end));
    let (ox, oy) = t.shading.origin;
    for y in y0..y1 {
        let ry = (y - oy) as i64;
        let mut e = t.edges.map(|e| e.at_center((x0 - ox) as i64, ry) - e.bias);
        let step = t.edges.map(|e| e.a << super::super::SUBPIXEL_BITS);
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
