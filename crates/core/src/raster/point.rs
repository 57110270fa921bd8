//! Points (ES 1.1 §3.3). An aliased point of size s (rounded to an integer, at least 1) is
//! the s × s square of pixels around its center, which is snapped so the square lands on
//! whole pixels: to a pixel center for odd sizes, to a pixel corner for even sizes. An
//! antialiased point (`GL_POINT_SMOOTH`) is a disc of diameter s around the unsnapped
//! position; each fragment's alpha is multiplied by the covered share of its pixel. A point
//! is one color and one depth.

use super::super::setup::{Coverage, Plane, Planes4, Shading, Shape, UnitPlanes};
use super::super::state::RenderState;
use super::super::target::Rect;
use super::super::vertex::VertexRef;
use super::{window, Span, MAX_POINT_SIZE};

#[derive(Clone, Debug)]
pub struct Point {
    pub bbox: Rect,
    pub shading: Shading,
}

/// Sets up point `v` (already known to be inside the clip volume) for rasterization inside
/// `bounds`.
/// `spare`: storage for the texture planes to reuse (`PrimList::spare_planes`).
pub fn setup(
    state: &RenderState,
    v: VertexRef<'_>,
    bounds: Rect,
    spare: Option<UnitPlanes>,
) -> Option<Point> {
    let (x, y, z, _) = window(state, v.pos())?;
    // The vertex stage derived the size (state or array, attenuation, min and max); here it
    // is clamped to the supported range (NaN: 1).
    let size = v.point_size();
    let size = if size.is_nan() {
        1.0
    } else {
        size.clamp(1.0, MAX_POINT_SIZE) as f64
    };
    let to_i = |v: f64| v.clamp(-(1 << 24) as f64, (1 << 24) as f64) as i32;
    // Sprites are squares: GL_POINT_SMOOTH does not apply to them.
    let smooth = state.point_smooth && !state.point_sprite;
    let (rect, coverage) = if smooth {
        let r = size * 0.5;
        let rect = Rect {
            x0: to_i((x - r).floor()),
            y0: to_i((y - r).floor()),
            x1: to_i((x + r).ceil()),
            y1: to_i((y + r).ceil()),
        };
        let coverage = Coverage {
            shape: Shape::Point { x, y, radius: r },
            samples: state.point_quality.coverage_samples(),
        };
        (rect, Some(Box::new(coverage)))
    } else {
        let s = size.round().max(1.0);
        let snap = |c: f64| {
            if s % 2.0 == 1.0 {
                c.floor() + 0.5
            } else {
                (c + 0.5).floor()
            }
        };
        // Both snaps make center − s/2 a whole number: the square's first pixel.
        let (x0, y0) = (to_i(snap(x) - s * 0.5), to_i(snap(y) - s * 0.5));
        let rect = Rect {
            x0,
            y0,
            x1: x0 + s as i32,
            y1: y0 + s as i32,
        };
        (rect, None)
    };
    let bbox = rect.intersect(bounds);
    let constant = |c: f64| Plane {
        dx: 0.0,
        dy: 0.0,
        c,
    };
    // A point has one of each value, so planes are constant (1/w is taken as 1). Point
    // sprites (OES_point_sprite) replace s and t on units with COORD_REPLACE: with the
    // fragment at pixel (x_f, y_f), s = ½ + (x_f + ½ − x_w)/size and
    // t = ½ − (y_f + ½ − y_w)/size, (x_w, y_w) the center of the square drawn.
    let (mut tex, fog) =
        crate::setup::attribute_planes(state, &[v], &[1.0], &|f| constant(f(0)), spare);
    if let Some(planes) = tex.as_mut() {
        let sprite = state.point_sprite;
        let s = size.round().max(1.0);
        let (cx, cy, size) = (rect.x0 as f64 + s * 0.5, rect.y0 as f64 + s * 0.5, s);
        for (u, unit) in state.textures.iter().enumerate() {
            if unit.as_ref().is_some_and(|u| u.coord_replace) && sprite {
                planes[u].s = Plane {
                    dx: 1.0 / size,
                    dy: 0.0,
                    c: 0.5 + (0.5 - cx) / size,
                };
                planes[u].t = Plane {
                    dx: 0.0,
                    dy: -1.0 / size,
                    c: 0.5 - (0.5 - cy) / size,
                };
                planes[u].q = constant(1.0);
            }
        }
    }
    (!bbox.is_empty()).then(|| Point {
        bbox,
        shading: Shading {
            origin: (0, 0),
            z: constant(z),
            inv_w: constant(1.0),
            // Both: span routines for smooth shading read the planes, the rest `flat`.
            color_w: Planes4::from_planes(v.color().to_array().map(|c| constant(c as f64))),
            flat: Some(v.color().to_array()),
            coverage,
            tex,
            fog,
        },
    })
}

impl Point {
    pub fn spans(&self, rows: std::ops::Range<i32>, mut emit: impl FnMut(Span)) {
        let b = self.bbox;
        for y in b.y0.max(rows.start)..b.y1.min(rows.end) {
            emit(Span {
                y,
                x0: b.x0,
                x1: b.x1,
            });
        }
    }
}
