//! The one vocabulary of the 8-wide paths, shared by the vertex stage (8 vertices at once)
//! and the fragment stage (8 pixels at once): a lane count, a value per lane, and the
//! comparisons the vector instructions make. The loops over a `Lane` index several arrays
//! in step, plain `for j in 0..LANES`, which is the shape the compiler turns into SIMD.

/// Values per group: one AVX2 vector of f32 (two SSE ones), short enough that short spans
/// and small batches waste little.
pub const LANES: usize = 8;

/// One value per lane.
pub type Lane<T> = [T; LANES];

/// Lane indices as floats: `i0 as f32 + INDEX_F32[j]` is `(i0 + j) as f32` exactly (both
/// are integers below 2²⁴), without a per-lane integer conversion.
pub const INDEX_F32: Lane<f32> = {
    let mut a = [0.0; LANES];
    let mut j = 0;
    while j < LANES {
        a[j] = j as f32;
        j += 1;
    }
    a
};

/// [`INDEX_F32`] in f64.
pub const INDEX_F64: Lane<f64> = {
    let mut a = [0.0; LANES];
    let mut j = 0;
    while j < LANES {
        a[j] = j as f64;
        j += 1;
    }
    a
};

/// `a.max(b)` as the vector instruction (and glam's `Vec4::max`) computes it: `b` when
/// either is NaN or they compare equal. The one-vertex path uses glam, so the batched path
/// must pick the same operand to stay bit-identical.
#[inline(always)]
pub fn max_ps(a: f32, b: f32) -> f32 {
    if a > b {
        a
    } else {
        b
    }
}

/// `a.min(b)` as the vector instruction computes it (see [`max_ps`]).
#[inline(always)]
pub fn min_ps(a: f32, b: f32) -> f32 {
    if a < b {
        a
    } else {
        b
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vector_min_max_take_the_second_operand_on_nan_and_ties() {
        assert_eq!(max_ps(f32::NAN, 1.0), 1.0);
        assert!(max_ps(1.0, f32::NAN).is_nan());
        assert_eq!(min_ps(f32::NAN, 1.0), 1.0);
        assert!(min_ps(1.0, f32::NAN).is_nan());
        assert_eq!(max_ps(0.0, -0.0).to_bits(), (-0.0f32).to_bits());
        assert_eq!(min_ps(-0.0, 0.0).to_bits(), 0.0f32.to_bits());
        assert_eq!(max_ps(2.0, 1.0), 2.0);
        assert_eq!(min_ps(2.0, 1.0), 1.0);
    }

    #[test]
    fn lane_indices_are_exact() {
        for j in 0..LANES {
            assert_eq!(INDEX_F32[j], j as f32);
            assert_eq!(INDEX_F64[j], j as f64);
        }
    }
}
