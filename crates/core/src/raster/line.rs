//! Line segments (ES 1.1 §3.4). Aliased segments follow the diamond-exit rule exactly: a
//! pixel is drawn when the segment, with its endpoints perturbed by −(ε, ε²) as §3.4.1
//! prescribes, meets the pixel's diamond and does not end inside it. Between the columns
//! (x-major) or rows (y-major) that hold the endpoints, the segment crosses each column's
//! center inside exactly one diamond, so those fragments follow from the segment's position
//! there; the two end columns are decided by the literal diamond test. The end vertex's
//! pixel thus belongs to the next segment of a strip, and none is drawn twice. Wide aliased
//! segments (width rounded to an integer) rasterize the segment offset by −(w − 1)/2 in the
//! minor direction and replicate each fragment w times upward (rightward). Antialiased
//! segments (`GL_LINE_SMOOTH`) cover a rectangle of the line's width and length, and each
//! fragment's alpha is multiplied by the covered share of its pixel.
//!
//! Colors and depth are interpolated with t, the projection of the pixel center onto the
//! segment, perspective-correctly for colors and linearly for depth.

use super::super::setup::{Coverage, Plane, Planes4, Shading, Shape, UnitPlanes};
use super::super::state::RenderState;
use super::super::target::Rect;
use super::super::vertex::VertexRef;
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
        /// The perturbed, offset segment's start along the major and minor axes, and its
        /// minor change per major unit.
        major0: f64,
        minor0: f64,
        slope: f64,
        /// Major-axis pixel indices `first..last` strictly between the end columns.
        first: i32,
        last: i32,
        /// The fragments of the end columns: (major, minor) pixel indices.
        ends: [Option<(i32, i32)>; 2],
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

/// Sets up clipped segment (a, b) for rasterization inside `bounds`. `flat` is the vertex
/// whose color the whole segment takes ([`crate::flat_colors`]), `None` when colors are
/// interpolated; `spare`, storage for the texture planes to reuse (`PrimList::spare_planes`).
pub fn setup(
    state: &RenderState,
    a: VertexRef<'_>,
    b: VertexRef<'_>,
    flat: Option<VertexRef<'_>>,
    bounds: Rect,
    spare: Option<UnitPlanes>,
) -> Option<Line> {
    let (ax, ay, az, aw) = window(state, a.pos())?;
    let (bx, by, bz, bw) = window(state, b.pos())?;
    let d = (bx - ax, by - ay);
    let len2 = d.0 * d.0 + d.1 * d.1;
    if len2 == 0.0 {
        return None;
    }
    let along = |va: f64, vb: f64| plane_along((ax, ay), d, len2, va, vb);
    let flat = flat.map(|v| v.color().to_array());
    let (tex, fog) =
        crate::setup::attribute_planes(state, &[a, b], &[aw, bw], &|f| along(f(0), f(1)), spare);
    let shading = move |coverage| Shading {
        origin: (0, 0),
        z: along(az, bz),
        inv_w: along(aw, bw),
        color_w: if flat.is_some() {
            Planes4::ZERO
        } else {
            Planes4::from_planes(std::array::from_fn(|c| {
                along(a.color()[c] as f64 * aw, b.color()[c] as f64 * bw)
            }))
        },
        flat,
        coverage,
        tex,
        fog,
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
            shading: shading(Some(Box::new(coverage))),
            walk: Walk::Smooth,
        });
    }
    let width = (width.round() as i32).max(1);
    let x_major = d.0.abs() >= d.1.abs();
    let off = (width - 1) as f64 * 0.5;
    // The offset segment in (major, minor) coordinates, perturbed by −ε in x and −ε² in y.
    // Coordinates are multiples of 2⁻⁸ below 2¹⁶, so ε = 2⁻¹⁸ and ε² = 2⁻³⁶ are represented
    // exactly beside them and still decide every tie.
    const EPS: f64 = 1.0 / (1u64 << 18) as f64;
    let (em, en) = if x_major {
        (EPS, EPS * EPS)
    } else {
        (EPS * EPS, EPS)
    };
    let (pa, pb) = if x_major {
        ((ax - em, ay - off - en), (bx - em, by - off - en))
    } else {
        ((ay - em, ax - off - en), (by - em, bx - off - en))
    };
    let slope = (pb.1 - pa.1) / (pb.0 - pa.0);
    let clamp = |v: f64| v.clamp(-(1 << 24) as f64, (1 << 24) as f64).floor() as i32;
    let (ca, cb) = (clamp(pa.0), clamp(pb.0));
    let (first, last) = if pb.0 > pa.0 {
        (ca + 1, cb)
    } else {
        (cb + 1, ca)
    };
    // The literal rule in the end columns: the segment meets the diamond of (i, j) and does
    // not end inside it.
    let produces = |i: i32, j: i32| {
        let (cm, cn) = (i as f64 + 0.5, j as f64 + 0.5);
        (pb.0 - cm).abs() + (pb.1 - cn).abs() >= 0.5 && meets_diamond(pa, pb, cm, cn)
    };
    let mut ends = [None; 2];
    for (k, col) in [ca, cb].into_iter().enumerate() {
        if k == 1 && cb == ca {
            break;
        }
        let n = clamp(pa.1 + (col as f64 + 0.5 - pa.0) * slope);
        ends[k] = (n - 1..=n + 1)
            .find(|&j| produces(col, j))
            .map(|j| (col, j));
    }
    // The minor extent: every fragment lies within width + 1 of the segment.
    let (lo_m, hi_m) = (pa.1.min(pb.1), pa.1.max(pb.1));
    let (mn0, mn1) = (clamp(lo_m) - 1, clamp(hi_m) + width + 2);
    let (mj0, mj1) = (ca.min(cb), ca.max(cb) + 1);
    let bbox = if x_major {
        Rect {
            x0: mj0,
            y0: mn0,
            x1: mj1,
            y1: mn1,
        }
    } else {
        Rect {
            x0: mn0,
            y0: mj0,
            x1: mn1,
            y1: mj1,
        }
    }
    .intersect(bounds);
    (!bbox.is_empty()).then(|| Line {
        bbox,
        shading: shading(None),
        walk: Walk::Aliased {
            x_major,
            major0: pa.0,
            minor0: pa.1,
            slope,
            first,
            last,
            ends,
            width,
        },
    })
}

/// Does the segment from `a` to `b` meet the open diamond |u − cu| + |v − cv| < ½? The
/// distance is convex and piecewise linear along the segment, so its minimum is at an end or
/// where either coordinate crosses the center.
fn meets_diamond(a: (f64, f64), b: (f64, f64), cu: f64, cv: f64) -> bool {
    let at = |t: f64| {
        let (u, v) = (a.0 + (b.0 - a.0) * t, a.1 + (b.1 - a.1) * t);
        (u - cu).abs() + (v - cv).abs() < 0.5
    };
    let mut hit = at(0.0) || at(1.0);
    if b.0 != a.0 {
        let t = (cu - a.0) / (b.0 - a.0);
        hit |= (0.0..=1.0).contains(&t) && at(t);
    }
    if b.1 != a.1 {
        let t = (cv - a.1) / (b.1 - a.1);
        hit |= (0.0..=1.0).contains(&t) && at(t);
    }
    hit
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
                ends,
                width,
            } => {
                // The first minor index of the fragments at major index i: where the
                // (perturbed, offset) segment crosses the column's center.
                let minor_at = |i: i32| {
                    let c = i as f64 + 0.5;
                    (minor0 + (c - major0) * slope).floor() as i32
                };
                // Only the columns whose runs can reach this band's rows (x-major): the
                // minor position is monotonic in the major one.
                let (first, last) = if x_major && slope != 0.0 {
                    let major_at = |v: i32| major0 + (v as f64 - minor0) / slope;
                    let (a, b) = (major_at(y0 - width - 1), major_at(y1 + 1));
                    let lo = (a.min(b).floor() as i32).saturating_sub(1);
                    let hi = (a.max(b).ceil() as i32).saturating_add(1);
                    (first.max(lo), last.min(hi))
                } else {
                    (first, last)
                };
                let interior = (first..last).map(|i| (i, minor_at(i)));
                let all = interior.chain(ends.into_iter().flatten());
                if x_major {
                    for (x, j) in all.filter(|&(x, _)| x >= b.x0 && x < b.x1) {
                        for y in j.max(y0)..(j + width).min(y1) {
                            emit(Span {
                                y,
                                x0: x,
                                x1: x + 1,
                            });
                        }
                    }
                } else {
                    for (y, j) in all.filter(|&(y, _)| y >= y0 && y < y1) {
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
