//! Line segments (ES 1.1 §3.4). Aliased segments follow the diamond-exit rule in the form
//! the specification's x-major/y-major description gives it: one fragment per pixel column
//! (x-major) or row (y-major) whose center lies on the segment's half-open extent along the
//! major axis, so the pixel at the end vertex belongs to the next segment of a strip and none
//! is drawn twice; the fragment is the pixel the segment passes through at that center. Wide
//! aliased segments (width rounded to an integer) replicate each fragment across the minor
//! direction, offset so the run is centered on the segment. Antialiased segments
//! (`GL_LINE_SMOOTH`) cover a rectangle of the line's width and length, and each fragment's
//! alpha is multiplied by the covered share of its pixel.
//!
//! Colors and depth are interpolated with t, the projection of the pixel center onto the
//! segment, perspective-correctly for colors and linearly for depth.

use super::super::setup::{Coverage, Plane, Shading, Shape};
use super::super::state::{RenderState, ShadeModel};
use super::super::target::Rect;
use super::super::vertex::ClipVertex;
use super::{window, Span, MAX_LINE_WIDTH};

#[derive(Clone, Debug)]
pub struct Line {
    pub bbox: Rect,
    pub shading: Shading,
    walk: Walk,
}

#[derive(Clone, Copy, Debug)]
enum Walk {
    Aliased {
        x_major: bool,
        /// Start position along the major and minor axes, and the minor change per major
        /// unit.
        major0: f64,
        minor0: f64,
        slope: f64,
        /// Major-axis pixel indices `first..last` that produce fragments.
        first: i32,
        last: i32,
        width: i32,
    },
    Smooth,
}

/// The plane through values `va` at `a` and `vb` at `b`, constant across the segment: the
/// value at a pixel center is `va + t·(vb − va)` with t its projection onto the segment.
fn plane_along(a: (f64, f64), d: (f64, f64), len2: f64, va: f64, vb: f64) -> Plane {
    let k = (vb - va) / len2;
    Plane {
        dx: k * d.0,
        dy: k * d.1,
        c: va + k * ((0.5 - a.0) * d.0 + (0.5 - a.1) * d.1),
    }
}

/// Sets up clipped segment (a, b) for rasterization inside `bounds`. `provoking` supplies
/// the flat-shaded color.
pub fn setup(
    state: &RenderState,
    a: &ClipVertex,
    b: &ClipVertex,
    provoking: &ClipVertex,
    bounds: Rect,
) -> Option<Line> {
    let (ax, ay, az, aw) = window(state, a.pos)?;
    let (bx, by, bz, bw) = window(state, b.pos)?;
    let d = (bx - ax, by - ay);
    let len2 = d.0 * d.0 + d.1 * d.1;
    if len2 == 0.0 {
        return None;
    }
    let along = |va: f64, vb: f64| plane_along((ax, ay), d, len2, va, vb);
    let flat = (state.shade_model == ShadeModel::Flat).then(|| provoking.color.to_array());
    let shading = |coverage| Shading {
        origin: (0, 0),
        z: along(az, bz),
        inv_w: along(aw, bw),
        color_w: std::array::from_fn(|c| along(a.color[c] as f64 * aw, b.color[c] as f64 * bw)),
        flat,
        coverage,
    };
    let width = state.line_width.clamp(1.0, MAX_LINE_WIDTH) as f64;
    if state.line_smooth {
        let len = len2.sqrt();
        let half = width * 0.5;
        let (ux, uy) = (d.0 / len, d.1 / len);
        let xs = [
            ax + uy * half,
            ax - uy * half,
            bx + uy * half,
            bx - uy * half,
        ];
        let ys = [
            ay - ux * half,
            ay + ux * half,
            by - ux * half,
            by + ux * half,
        ];
        let lo = |v: &[f64; 4]| v.iter().cloned().fold(f64::MAX, f64::min).floor() as i32;
        let hi = |v: &[f64; 4]| v.iter().cloned().fold(f64::MIN, f64::max).ceil() as i32;
        let bbox = Rect {
            x0: lo(&xs),
            y0: lo(&ys),
            x1: hi(&xs),
            y1: hi(&ys),
        }
        .intersect(bounds);
        let coverage = Coverage {
            shape: Shape::Line {
                x: ax,
                y: ay,
                ux,
                uy,
                len,
                half,
            },
            samples: state.line_quality.coverage_samples(),
        };
        return (!bbox.is_empty()).then(|| Line {
            bbox,
            shading: shading(Some(coverage)),
            walk: Walk::Smooth,
        });
    }
    let width = (width.round() as i32).max(1);
    let x_major = d.0.abs() >= d.1.abs();
    let (major0, minor0, major1) = if x_major { (ax, ay, bx) } else { (ay, ax, by) };
    let slope = if x_major { d.1 / d.0 } else { d.0 / d.1 };
    // Pixel centers c = i + 0.5 on the half-open extent from the start to the end vertex.
    let (first, last) = if major1 > major0 {
        ((major0 - 0.5).ceil(), (major1 - 0.5).ceil())
    } else {
        ((major1 - 0.5).floor() + 1.0, (major0 - 0.5).floor() + 1.0)
    };
    let clamp = |v: f64| v.clamp(-(1 << 24) as f64, (1 << 24) as f64) as i32;
    let (first, last) = (clamp(first), clamp(last));
    // The minor extent: every fragment lies within width/2 + 1 of the segment.
    let pad = width / 2 + 1;
    let (lo_m, hi_m) = (
        minor0.min(minor0 + slope * (major1 - major0)),
        minor0.max(minor0 + slope * (major1 - major0)),
    );
    let (mn0, mn1) = (clamp(lo_m.floor()) - pad, clamp(hi_m.ceil()) + pad);
    let bbox = if x_major {
        Rect {
            x0: first,
            y0: mn0,
            x1: last,
            y1: mn1,
        }
    } else {
        Rect {
            x0: mn0,
            y0: first,
            x1: mn1,
            y1: last,
        }
    }
    .intersect(bounds);
    (!bbox.is_empty()).then(|| Line {
        bbox,
        shading: shading(None),
        walk: Walk::Aliased {
            x_major,
            major0,
            minor0,
            slope,
            first,
            last,
            width,
        },
    })
}

impl Line {
    pub fn spans(&self, rows: std::ops::Range<i32>, mut emit: impl FnMut(Span)) {
        let b = self.bbox;
        let (y0, y1) = (b.y0.max(rows.start), b.y1.min(rows.end));
        if y0 >= y1 {
            return;
        }
        match self.walk {
            Walk::Smooth => {
                for y in y0..y1 {
                    emit(Span {
                        y,
                        x0: b.x0,
                        x1: b.x1,
                    });
                }
            }
            Walk::Aliased {
                x_major,
                major0,
                minor0,
                slope,
                first,
                last,
                width,
            } => {
                // The first minor index of the fragments at major index i.
                // The endpoints are perturbed by −(ε, ε²) (§3.4.1), so a segment running
                // exactly along a pixel boundary belongs to the pixels below (left of) it.
                let minor_at = |i: i32| {
                    let c = i as f64 + 0.5;
                    (minor0 + (c - major0) * slope - (width - 1) as f64 * 0.5).ceil() as i32 - 1
                };
                if x_major {
                    for x in first.max(b.x0)..last.min(b.x1) {
                        let j = minor_at(x);
                        for y in j.max(y0)..(j + width).min(y1) {
                            emit(Span {
                                y,
                                x0: x,
                                x1: x + 1,
                            });
                        }
                    }
                } else {
                    for y in first.max(y0)..last.min(y1) {
                        let j = minor_at(y);
                        let (x0, x1) = (j.max(b.x0), (j + width).min(b.x1));
                        if x0 < x1 {
                            emit(Span { y, x0, x1 });
                        }
                    }
                }
            }
        }
    }
}
