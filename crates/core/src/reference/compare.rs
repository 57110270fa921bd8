//! Error figures between two images of the same size.

use crate::Target;

/// How far one image is from another, over the RGBA bytes of every pixel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ErrorStats {
    /// Largest absolute difference of any channel, in 8-bit steps.
    pub max: u8,
    /// Mean absolute difference per channel, in 8-bit steps.
    pub mean: f64,
    /// Peak signal-to-noise ratio in dB over all channels (infinite for identical images).
    pub psnr: f64,
    /// Share of pixels (0 to 1) with some channel off by more than one step.
    pub over_one: f64,
}

/// Compares the color buffers of two targets of the same size.
///
/// # Panics
/// When the sizes differ: comparing different images is a programming error in the caller.
pub fn compare(a: &Target, b: &Target) -> ErrorStats {
    assert_eq!(
        (a.width(), a.height()),
        (b.width(), b.height()),
        "images must have one size"
    );
    let (mut max, mut sum, mut sq, mut over) = (0u8, 0u64, 0u64, 0usize);
    for (&pa, &pb) in a.color().iter().zip(b.color()) {
        let mut worst = 0u8;
        for (ca, cb) in pa.to_le_bytes().into_iter().zip(pb.to_le_bytes()) {
            let d = ca.abs_diff(cb);
            worst = worst.max(d);
            sum += d as u64;
            sq += d as u64 * d as u64;
        }
        max = max.max(worst);
        over += usize::from(worst > 1);
    }
    let pixels = a.color().len().max(1);
    let samples = (pixels * 4) as f64;
    let mse = sq as f64 / samples;
    ErrorStats {
        max,
        mean: sum as f64 / samples,
        psnr: if mse == 0.0 {
            f64::INFINITY
        } else {
            10.0 * (255.0f64 * 255.0 / mse).log10()
        },
        over_one: over as f64 / pixels as f64,
    }
}
