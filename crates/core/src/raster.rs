//! Rasterization: which pixels a primitive covers, delivered as horizontal spans, each
//! primitive kind with the coverage rules of ES 1.1 chapter 3.

pub mod line;
pub mod point;
pub mod triangle;

use super::setup::{Shading, Triangle, UnitPlanes};
use super::target::Rect;

pub use line::Line;
pub use point::Point;

pub use super::state::{MAX_LINE_WIDTH, MAX_POINT_SIZE};

/// A run of pixels `x0 <= x < x1` on row `y` that a primitive produces fragments for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Span {
    pub y: i32,
    pub x0: i32,
    pub x1: i32,
}

/// A primitive ready to rasterize.
#[derive(Clone, Debug)]
pub enum Prim {
    Triangle(Triangle),
    Line(Line),
    Point(Point),
}

impl Prim {
    /// This storage as a triangle for set-up to overwrite: the triangle it holds, or a
    /// blank one in place of a line or a point.
    pub fn reuse_as_triangle(&mut self) -> &mut Triangle {
        if !matches!(self, Prim::Triangle(_)) {
            *self = Prim::Triangle(Triangle::BLANK);
        }
        match self {
            Prim::Triangle(t) => t,
            _ => unreachable!("the storage holds a triangle"),
        }
    }

    /// The pixels the primitive may produce fragments for.
    pub fn bbox(&self) -> Rect {
        match self {
            Prim::Triangle(t) => t.bbox,
            Prim::Line(l) => l.bbox,
            Prim::Point(p) => p.bbox,
        }
    }

    pub fn shading(&self) -> &Shading {
        match self {
            Prim::Triangle(t) => &t.shading,
            Prim::Line(l) => &l.shading,
            Prim::Point(p) => &p.shading,
        }
    }

    fn shading_mut(&mut self) -> &mut Shading {
        match self {
            Prim::Triangle(t) => &mut t.shading,
            Prim::Line(l) => &mut l.shading,
            Prim::Point(p) => &mut p.shading,
        }
    }

    /// The texture-plane storage of this old primitive, for the one set up in its place.
    pub fn take_planes(&mut self) -> Option<UnitPlanes> {
        self.shading_mut().tex.take()
    }

    /// Calls `emit` for every span of the primitive on rows `rows`.
    pub fn spans(&self, rows: std::ops::Range<i32>, emit: impl FnMut(Span)) {
        match self {
            Prim::Triangle(t) => triangle::spans(t, rows, emit),
            Prim::Line(l) => l.spans(rows, emit),
            Prim::Point(p) => p.spans(rows, emit),
        }
    }
}

/// Window coordinates of a clip-space position, snapped to the subpixel grid like triangle
/// vertices, with depth mapped by the depth range. `None` for a w the clipper removes.
pub(crate) fn window(
    state: &super::state::RenderState,
    pos: glam::Vec4,
) -> Option<(f64, f64, f64, f64)> {
    let w = pos.w as f64;
    // NaN fails this too.
    if w.is_nan() || w < super::clip::W_MIN as f64 {
        return None;
    }
    let vp = state.viewport;
    let inv_w = 1.0 / w;
    let snap = |v: f64| {
        let v = v * (1 << super::SUBPIXEL_BITS) as f64;
        // From 2⁵² on every f64 is an integer; below, the inline rounding (sign of zero
        // kept) equals f64::round.
        let r = if v.abs() < (1u64 << 52) as f64 {
            (super::setup::round_i64(v) as f64).copysign(v)
        } else {
            v
        };
        r / (1 << super::SUBPIXEL_BITS) as f64
    };
    let [n, f] = state.depth_range.map(f64::from);
    let x = (pos.x as f64 * inv_w + 1.0) * 0.5 * vp.width as f64 + vp.x as f64;
    let y = (pos.y as f64 * inv_w + 1.0) * 0.5 * vp.height as f64 + vp.y as f64;
    let z = (pos.z as f64 * inv_w) * (f - n) * 0.5 + (f + n) * 0.5;
    let (x, y) = match state.sample {
        // A sample plane's primitive moves by the negated sample offset (see `multisample`).
        Some(s) => {
            let unit = (1 << super::SUBPIXEL_BITS) as f64;
            let [ox, oy] = s.offset.map(|o| o as f64 / unit);
            (snap(x) - ox, snap(y) - oy)
        }
        None => (snap(x), snap(y)),
    };
    Some((x, y, z.clamp(0.0, 1.0), inv_w))
}
