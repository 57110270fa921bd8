//! Per-fragment operations: interpolation, depth test, masks, and the write to the target.

use super::raster::Span;
use super::setup::Triangle;
use super::state::{CompareFunc, RenderState};
use super::target::{keep_mask, BandMut, ColorFormat, DepthFormat, TargetFormat};

/// What the fragment stage does for the current state, decided once per draw call so the
/// per-pixel loop tests nothing that is off.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FragmentKey {
    /// The depth test, present only when enabled and the target has depth.
    depth_test: Option<CompareFunc>,
    depth_write: bool,
    /// Stored bits the color mask protects; all ones means color is not written at all.
    keep: u32,
    color: ColorFormat,
    depth_format: Option<DepthFormat>,
}

impl FragmentKey {
    pub fn new(state: &RenderState, format: TargetFormat) -> FragmentKey {
        let has_depth = format.depth.is_some();
        let depth_test = state.depth_test.filter(|_| has_depth);
        FragmentKey {
            depth_test,
            // Depth is written only when the test is enabled (GL 1.x §4.1.5).
            depth_write: depth_test.is_some() && state.depth_write,
            keep: keep_mask(state.color_mask),
            color: format.color,
            depth_format: format.depth,
        }
    }

    /// Shades the pixels of `span`, which lies inside the band and the triangle.
    pub fn shade(&self, t: &Triangle, span: Span, band: &mut BandMut<'_>) {
        let depth_format = self.depth_format;
        let (colors, depths) = (&mut *band.color, &mut *band.depth);
        let row = (span.y - band.y0) as usize * band.width;
        let ry = (span.y - t.origin.1) as i64;
        let inv_area = 1.0 / t.area as f64;
        for x in span.x0..span.x1 {
            let rx = (x - t.origin.0) as i64;
            let e = t.edges.map(|e| e.at_center(rx, ry) as f64 * inv_area);
            let at = row + x as usize;
            if let (Some(func), Some(df)) = (self.depth_test, depth_format) {
                let z = df.quantize(e[0] * t.z[0] + e[1] * t.z[1] + e[2] * t.z[2]);
                if !func.test(z, depths[at]) {
                    continue;
                }
                if self.depth_write {
                    depths[at] = z;
                }
            }
            if self.keep == u32::MAX {
                continue;
            }
            let b = e.map(|v| v as f32);
            let mut rgba = [0f32; 4];
            if t.flat {
                // Every vertex carries the provoking color, so any weight recovers it exactly.
                rgba = t.color_w[0].map(|c| c / t.inv_w[0]);
            } else {
                let w = 1.0 / (b[0] * t.inv_w[0] + b[1] * t.inv_w[1] + b[2] * t.inv_w[2]);
                for (c, out) in rgba.iter_mut().enumerate() {
                    *out =
                        (b[0] * t.color_w[0][c] + b[1] * t.color_w[1][c] + b[2] * t.color_w[2][c])
                            * w;
                }
            }
            let word = self.color.encode(rgba);
            colors[at] = (colors[at] & self.keep) | (word & !self.keep);
        }
    }
}
