//! Triangle setup: the viewport transform, snapping to [`SUBPIXEL_BITS`] fixed-point
//! subpixels, integer edge functions with a top-left fill rule, facing and culling.

use super::clip;
use super::state::{CullFace, RenderState, ShadeModel, Winding};
use super::target::Rect;
use super::vertex::ClipVertex;
use super::SUBPIXEL_BITS;

const ONE: i64 = 1 << SUBPIXEL_BITS;
const HALF: i64 = ONE / 2;

/// An edge function `E(x, y) = a·x + b·y + c` over subpixel coordinates relative to the
/// triangle's origin; positive inside. `bias` is 0 for edges that own the pixels exactly on
/// them (top and left edges) and 1 otherwise, so `E − bias ≥ 0` is the coverage test and a
/// pixel on an edge shared by two triangles is drawn by exactly one of them.
#[derive(Clone, Copy, Debug)]
pub struct Edge {
    pub a: i64,
    pub b: i64,
    pub c: i64,
    pub bias: i64,
}

impl Edge {
    fn new(x0: i64, y0: i64, x1: i64, y1: i64) -> Edge {
        let (dx, dy) = (x1 - x0, y1 - y0);
        // With y up and counter-clockwise vertices the inside lies to the left of each edge:
        // a downward edge is a left edge, a leftward horizontal edge is a top edge.
        let owns = dy < 0 || (dy == 0 && dx < 0);
        Edge {
            a: -dy,
            b: dx,
            c: dy * x0 - dx * y0,
            bias: i64::from(!owns),
        }
    }

    /// The edge function at the center of pixel (px, py), given relative to the origin.
    #[inline]
    pub fn at_center(&self, px: i64, py: i64) -> i64 {
        self.a * (px * ONE + HALF) + self.b * (py * ONE + HALF) + self.c
    }
}

/// A triangle ready to rasterize.
#[derive(Clone, Debug)]
pub struct Triangle {
    /// Pixel (origin.0, origin.1) is where edge coordinates are 0.
    pub origin: (i32, i32),
    /// `edges[i]` is the edge opposite vertex i, so `E_i / area` is vertex i's barycentric weight.
    pub edges: [Edge; 3],
    /// Twice the area in subpixel units, always positive.
    pub area: i64,
    /// The pixels the triangle may cover, within the draw bounds.
    pub bbox: Rect,
    /// Window-space depth in [0, 1] at each vertex.
    pub z: [f64; 3],
    /// 1/w at each vertex, for perspective-correct interpolation.
    pub inv_w: [f32; 3],
    /// Vertex colors divided by w, or the provoking color repeated under flat shading.
    pub color_w: [[f32; 4]; 3],
    pub flat: bool,
}

/// Sets up a clipped triangle for rasterization inside `bounds`, or returns `None` when it is
/// culled, has no area, or cannot touch `bounds`. `provoking` supplies the flat-shaded color.
pub fn triangle(
    state: &RenderState,
    v: [&ClipVertex; 3],
    provoking: &ClipVertex,
    bounds: Rect,
) -> Option<Triangle> {
    let vp = state.viewport;
    let (hw, hh) = (vp.width as f64 * 0.5, vp.height as f64 * 0.5);
    let (cx, cy) = (vp.x as f64 + hw, vp.y as f64 + hh);
    let [n, f] = state.depth_range.map(f64::from);
    let mut win = [(0i64, 0i64); 3];
    let mut z = [0f64; 3];
    let mut inv_w = [0f32; 3];
    for i in 0..3 {
        let p = v[i].pos;
        debug_assert!(p.w >= clip::W_MIN);
        let iw = 1.0 / p.w as f64;
        // Clipping bounds |x/w| and |y/w| by 1; the clamp only removes rounding excess, and
        // keeps a w near W_MIN from producing huge coordinates.
        let x = (p.x as f64 * iw).clamp(-1.0, 1.0) * hw + cx;
        let y = (p.y as f64 * iw).clamp(-1.0, 1.0) * hh + cy;
        win[i] = (
            (x * ONE as f64).round() as i64,
            (y * ONE as f64).round() as i64,
        );
        z[i] = ((p.z as f64 * iw) * (f - n) * 0.5 + (f + n) * 0.5).clamp(0.0, 1.0);
        inv_w[i] = iw as f32;
    }
    // Pixel bounding box: pixel centers strictly inside the snapped extent.
    let min_x = win.iter().map(|p| p.0).min()?;
    let max_x = win.iter().map(|p| p.0).max()?;
    let min_y = win.iter().map(|p| p.1).min()?;
    let max_y = win.iter().map(|p| p.1).max()?;
    let to_px = |lo: i64, hi: i64| -> (i64, i64) {
        ((lo - HALF).div_euclid(ONE), (hi - HALF).div_euclid(ONE) + 1)
    };
    let (px0, px1) = to_px(min_x, max_x);
    let (py0, py1) = to_px(min_y, max_y);
    let clamp = |v: i64| v.clamp(i32::MIN as i64, i32::MAX as i64) as i32;
    let bbox = Rect {
        x0: clamp(px0),
        y0: clamp(py0),
        x1: clamp(px1),
        y1: clamp(py1),
    }
    .intersect(bounds);
    if bbox.is_empty() {
        return None;
    }
    // Work relative to the bounding box so every coordinate is small (see MAX_VIEWPORT_DIM).
    let (ox, oy) = (bbox.x0 as i64 * ONE, bbox.y0 as i64 * ONE);
    let p: [(i64, i64); 3] = win.map(|(x, y)| (x - ox, y - oy));
    let area = (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1);
    if area == 0 {
        return None;
    }
    let ccw = area > 0;
    let front = ccw == (state.front_face == Winding::Ccw);
    match state.cull {
        Some(CullFace::FrontAndBack) => return None,
        Some(CullFace::Front) if front => return None,
        Some(CullFace::Back) if !front => return None,
        _ => {}
    }
    // Reorder to counter-clockwise so one coverage test serves both windings.
    let order = if ccw { [0, 1, 2] } else { [0, 2, 1] };
    let q = order.map(|i| p[i]);
    let edges = [
        Edge::new(q[1].0, q[1].1, q[2].0, q[2].1),
        Edge::new(q[2].0, q[2].1, q[0].0, q[0].1),
        Edge::new(q[0].0, q[0].1, q[1].0, q[1].1),
    ];
    let flat = state.shade_model == ShadeModel::Flat;
    let color_w = order.map(|i| {
        let c = if flat { provoking.color } else { v[i].color };
        (c * inv_w[i]).to_array()
    });
    Some(Triangle {
        origin: (bbox.x0, bbox.y0),
        edges,
        area: area.abs(),
        bbox,
        z: order.map(|i| z[i]),
        inv_w: order.map(|i| inv_w[i]),
        color_w,
        flat,
    })
}
