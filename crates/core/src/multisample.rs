//! Multisampling (ES 1.1 §3.2 and §4.1.3; EGL 1.4 `EGL_SAMPLES`, `EGL_SAMPLE_BUFFERS`).
//!
//! A multisampled [`Target`](super::Target) keeps [`SAMPLES`] sample planes, each a complete
//! single-sample target (color, depth, stencil), beside its own color buffer, which always
//! holds the resolved image. Sample `k` is the point [`OFFSETS`]`[k]` away from every pixel
//! center: a rotated grid at (0.375, 0.125), (0.875, 0.375), (0.125, 0.625), (0.625, 0.875)
//! from the pixel's lower left corner, the standard 4× pattern, in window coordinates (y up).
//!
//! A draw is recorded once per sample plane, with its snapped window coordinates moved by
//! the negated offset ([`SamplePass::offset`], applied in `setup::triangle` and
//! `raster::window`). The rasterizer then samples each plane at pixel centers, which are the
//! sample positions of the unmoved primitive: coverage is the edge functions at the sample
//! position under the usual top-left rule, and depth and stencil are per sample, exactly as
//! §3.2 asks. Because the offsets are multiples of 1/8 pixel, the move is exact in the
//! 1/2⁸ subpixel grid. The scissor, the viewport's pixel bounds and the buffers are those of
//! the pixel, so every primitive kind (points, lines, triangles, `glDrawTex`) and every
//! per-fragment operation keep their single-sample code. The cost of the design is that
//! color and texturing are computed per sample (the specification allows it; a pixel-rate
//! shader would save that work but need a second fragment path for every route).
//!
//! With `GL_MULTISAMPLE` disabled, every plane gets the unmoved primitive (pixel-center
//! coverage for all samples, §3.2) and no sample mask, so the resolved pixels equal a
//! single-sample config's bit for bit.
//!
//! The sample mask of §4.1.3 is per plane: `glSampleCoverage`'s value `v` covers the first
//! `round(4v)` samples (inverted: the others), a whole plane is skipped when its bit is
//! clear; alpha to coverage covers sample `k` when the fragment's 8-bit alpha `A` has
//! `round(4A/255) > k` ([`ALPHA_COVERAGE_MIN`]), tested per fragment before the alpha test;
//! alpha to one then sets alpha to 1. Both mappings are fixed, without dithering, so the
//! results do not depend on position or thread count.
//!
//! The resolve ([`resolve_words`](super::target::resolve_words), beside the formats it
//! reads) is the box filter: per channel, the mean of the samples' n-bit values rounded
//! half up, `(sum + 2) / 4`. It runs after every flush of a frame into a multisampled
//! target, so `glReadPixels`, `glCopyTex*`, `eglSwapBuffers`, `eglCopyBuffers`
//! and `eglBindTexImage` all read resolved pixels without knowing about samples.

use super::SUBPIXEL_BITS;

/// Samples per pixel of a multisampled target.
pub const SAMPLES: usize = 4;

/// Each sample's position relative to the pixel center, in 1/2^[`SUBPIXEL_BITS`] pixel:
/// (−1/8, −3/8), (3/8, −1/8), (−3/8, 1/8), (1/8, 3/8).
pub const OFFSETS: [[i32; 2]; SAMPLES] = {
    const E: i32 = 1 << (SUBPIXEL_BITS - 3);
    [[-E, -3 * E], [3 * E, -E], [-3 * E, E], [E, 3 * E]]
};

/// The smallest 8-bit alpha that covers sample `k` under alpha to coverage: the `A` with
/// `round(4A/255) > k`, i.e. `A ≥ 255 (2k + 1) / 8` rounded up.
pub const ALPHA_COVERAGE_MIN: [u8; SAMPLES] = [32, 96, 160, 224];

/// The GL state of §3.2 and §4.1.3. It only matters when drawing into a multisampled target.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Multisample {
    /// `GL_MULTISAMPLE`.
    pub enabled: bool,
    /// `GL_SAMPLE_COVERAGE` when enabled: `glSampleCoverage`'s value and invert flag.
    pub coverage: Option<(f32, bool)>,
    /// `GL_SAMPLE_ALPHA_TO_COVERAGE`.
    pub alpha_to_coverage: bool,
    /// `GL_SAMPLE_ALPHA_TO_ONE`.
    pub alpha_to_one: bool,
}

impl Default for Multisample {
    fn default() -> Multisample {
        Multisample {
            enabled: true,
            coverage: None,
            alpha_to_coverage: false,
            alpha_to_one: false,
        }
    }
}

/// What one sample plane's recording of a draw changes: where the plane samples, and the
/// per-fragment part of its sample mask.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SamplePass {
    /// The sample's offset from the pixel center (subpixel units); primitives move by its
    /// negation.
    pub offset: [i32; 2],
    /// Alpha to coverage: fragments with a smaller 8-bit alpha miss this sample.
    pub alpha_min: Option<u8>,
    /// Alpha to one.
    pub alpha_to_one: bool,
}

/// `glSampleCoverage`'s mask: bit `k` for sample `k`, the first `round(4 · value)` samples,
/// complemented when `invert`.
pub fn coverage_mask(value: f32, invert: bool) -> u8 {
    let v = if value > 0.0 { value.min(1.0) } else { 0.0 };
    let n = (v * SAMPLES as f32 + 0.5) as u32;
    let mask = ((1u32 << n) - 1) as u8;
    if invert {
        !mask & 0xF
    } else {
        mask
    }
}

impl Multisample {
    /// The pass for each sample plane, `None` for a plane the constant mask leaves out.
    pub fn passes(&self) -> [Option<SamplePass>; SAMPLES] {
        if !self.enabled {
            // §3.2: single-sample rasterization, and §4.1.3's operations are skipped.
            return [Some(SamplePass {
                offset: [0, 0],
                alpha_min: None,
                alpha_to_one: false,
            }); SAMPLES];
        }
        let mask = self.coverage.map_or(0xF, |(v, inv)| coverage_mask(v, inv));
        std::array::from_fn(|k| {
            (mask & (1 << k) != 0).then_some(SamplePass {
                offset: OFFSETS[k],
                alpha_min: self.alpha_to_coverage.then_some(ALPHA_COVERAGE_MIN[k]),
                alpha_to_one: self.alpha_to_one,
            })
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::target::{expand_to_8, resolve_words, ColorFormat};

    #[test]
    fn offsets_are_the_rotated_grid_in_eighths() {
        let eighth = 1 << (SUBPIXEL_BITS - 3);
        let from_corner: Vec<[i32; 2]> = OFFSETS
            .iter()
            .map(|o| [o[0] + 4 * eighth, o[1] + 4 * eighth])
            .collect();
        // (0.375, 0.125), (0.875, 0.375), (0.125, 0.625), (0.625, 0.875) in eighths.
        assert_eq!(
            from_corner,
            [[3, 1], [7, 3], [1, 5], [5, 7]].map(|p| p.map(|v| v * eighth))
        );
        // One sample per row and column quarter: a rotated grid.
        let mut xs: Vec<i32> = OFFSETS.iter().map(|o| o[0]).collect();
        let mut ys: Vec<i32> = OFFSETS.iter().map(|o| o[1]).collect();
        xs.sort();
        ys.sort();
        assert_eq!(xs, ys);
        xs.dedup();
        assert_eq!(xs.len(), SAMPLES);
    }

    #[test]
    fn coverage_value_maps_to_a_prefix_of_samples() {
        assert_eq!(coverage_mask(1.0, false), 0xF);
        assert_eq!(coverage_mask(0.0, false), 0);
        assert_eq!(coverage_mask(0.5, false), 0b0011);
        assert_eq!(coverage_mask(0.5, true), 0b1100);
        assert_eq!(coverage_mask(0.25, false), 0b0001);
        assert_eq!(coverage_mask(0.3, false), 0b0001);
        assert_eq!(coverage_mask(0.75, true), 0b1000);
        assert_eq!(coverage_mask(0.0, true), 0xF);
        assert_eq!(coverage_mask(2.0, false), 0xF);
        assert_eq!(coverage_mask(f32::NAN, false), 0);
    }

    #[test]
    fn alpha_thresholds_round_four_alpha() {
        for a in 0..=255u32 {
            let n = (4 * a * 2 + 255) / (2 * 255); // round(4a / 255), never a tie
            for (k, &min) in ALPHA_COVERAGE_MIN.iter().enumerate() {
                assert_eq!(a >= min as u32, n > k as u32, "a {a} k {k}");
            }
        }
    }

    #[test]
    fn passes_follow_the_enables() {
        let off = Multisample {
            enabled: false,
            coverage: Some((0.0, false)),
            alpha_to_coverage: true,
            alpha_to_one: true,
        };
        assert!(off
            .passes()
            .iter()
            .all(|p| p.is_some_and(|p| p.offset == [0, 0] && p.alpha_min.is_none())));
        let on = Multisample {
            enabled: true,
            coverage: Some((0.5, true)),
            alpha_to_coverage: true,
            alpha_to_one: false,
        };
        let p = on.passes();
        assert!(p[0].is_none() && p[1].is_none());
        assert_eq!(p[2].unwrap().offset, OFFSETS[2]);
        assert_eq!(p[3].unwrap().alpha_min, Some(224));
    }

    #[test]
    fn resolve_is_the_rounded_box_mean_per_channel() {
        let w = u32::from_le_bytes;
        let white = w([255; 4]);
        let black = w([0, 0, 0, 255]);
        let f = ColorFormat::Rgba8888;
        assert_eq!(resolve_words(f, &[white; 4]), white);
        assert_eq!(
            resolve_words(f, &[white, black, white, black]),
            w([128, 128, 128, 255])
        );
        assert_eq!(
            resolve_words(f, &[white, black, black, black]),
            w([64, 64, 64, 255])
        );
        assert_eq!(
            resolve_words(f, &[white, white, white, black]),
            w([191, 191, 191, 255])
        );
        // RGB565: the mean of 5- and 6-bit values, widened like every stored value.
        let f = ColorFormat::Rgb565;
        let half = resolve_words(f, &[white, black, white, black]);
        assert_eq!(half, w([expand_to_8(16, 5), expand_to_8(32, 6), 132, 255]));
        assert_eq!(f.quantize8(half), half);
    }
}
