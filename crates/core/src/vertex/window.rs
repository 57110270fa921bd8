//! The viewport transform of triangle vertices: a clip position divided by w, mapped to
//! the viewport and the depth range, and snapped to subpixels. Where a draw's triangles
//! share vertices (indices, strips, fans: a vertex of an indexed mesh is a corner of
//! about six triangles) the vertex stage does it once per vertex, eight at a time;
//! otherwise set-up does it per triangle, its three corners at a time, as it does for
//! the polygons clipping makes. Both run [`ViewportTransform::lanes`], so a corner's
//! window coordinates are the same bits whichever way they were made.

use glam::Vec4;

use super::{RenderState, GUARD, W_MIN};
use crate::SUBPIXEL_BITS;

/// A triangle corner in window space: x and y snapped to 1/2^[`SUBPIXEL_BITS`] pixel, z in
/// the depth range (clamped to [0, 1]) and 1/w.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Window {
    pub x: i64,
    pub y: i64,
    pub z: f64,
    pub inv_w: f64,
}

/// `round_i64` of set-up for |v| < 2⁵¹ and NaN (0, as there): a window coordinate in
/// subpixels. Without `as i64`, which tests for NaN and saturates value by value:
/// truncated, the integer added to 1.5 · 2⁵² is the low bits of the sum, so the vertices
/// round as one vector.
#[inline(always)]
pub(crate) fn snap(v: f64) -> i64 {
    const MAGIC: f64 = 6_755_399_441_055_744.0;
    let v = if v.is_nan() { 0.0 } else { v };
    let t = (v + (0.5 - f64::EPSILON / 4.0).copysign(v)).trunc();
    ((t + MAGIC).to_bits() as i64).wrapping_sub(MAGIC.to_bits() as i64)
}

/// The viewport and depth range of a draw, as the transform reads them.
#[derive(Clone, Copy, Debug)]
pub struct ViewportTransform {
    half_width: f64,
    half_height: f64,
    center_x: f64,
    center_y: f64,
    near: f64,
    far: f64,
}

impl ViewportTransform {
    pub fn new(state: &RenderState) -> ViewportTransform {
        let vp = state.viewport;
        let (half_width, half_height) = (vp.width as f64 * 0.5, vp.height as f64 * 0.5);
        ViewportTransform {
            half_width,
            half_height,
            center_x: vp.x as f64 + half_width,
            center_y: vp.y as f64 + half_height,
            near: state.depth_range[0] as f64,
            far: state.depth_range[1] as f64,
        }
    }

    /// The window coordinates of clip positions (x, y, z, w) as N lanes, w ≥ `W_MIN`: the
    /// vertex stage's eight and set-up's three corners (four lanes, the last a copy) are
    /// the same operations, so the same bits. Clipping bounds |x/w| and |y/w| by the guard
    /// band; the clamp only removes rounding excess, and keeps a w near `W_MIN` from
    /// producing huge coordinates.
    #[inline(always)]
    pub fn lanes<const N: usize>(&self, p: [[f32; N]; 4]) -> [Window; N] {
        const ONE: f64 = (1i64 << SUBPIXEL_BITS) as f64;
        let (n, f) = (self.near, self.far);
        let g = GUARD as f64;
        let (mut x, mut y, mut z, mut inv_w) = ([0i64; N], [0i64; N], [0f64; N], [0f64; N]);
        for k in 0..N {
            let iw = 1.0 / p[3][k] as f64;
            let wx = (p[0][k] as f64 * iw).clamp(-g, g) * self.half_width + self.center_x;
            let wy = (p[1][k] as f64 * iw).clamp(-g, g) * self.half_height + self.center_y;
            x[k] = snap(wx * ONE);
            y[k] = snap(wy * ONE);
            z[k] = ((p[2][k] as f64 * iw) * (f - n) * 0.5 + (f + n) * 0.5).clamp(0.0, 1.0);
            inv_w[k] = iw;
        }
        let mut out = [Window::default(); N];
        for k in 0..N {
            out[k] = Window {
                x: x[k],
                y: y[k],
                z: z[k],
                inv_w: inv_w[k],
            };
        }
        out
    }

    /// [`ViewportTransform::lanes`] of a triangle's three corners.
    #[inline(always)]
    pub fn corners(&self, p: [Vec4; 3]) -> [Window; 3] {
        debug_assert!(p.iter().all(|p| p.w >= W_MIN));
        let lane = |c: usize| [p[0][c], p[1][c], p[2][c], p[2][c]];
        let w = self.lanes([lane(0), lane(1), lane(2), lane(3)]);
        [w[0], w[1], w[2]]
    }
}
