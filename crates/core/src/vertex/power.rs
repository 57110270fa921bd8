//! `x^y` for the lighting equation's specular power (n ⊙ ĥ)^s_rm and spot power
//! (P̂V·ŝ)^s_rl, in plain arithmetic instead of a `powf` call per lane.
//!
//! A library call in the 8-wide vertex loop costs more than the call itself: the batch's
//! registers are spilled around it, and eight calls in a row cannot be vectorized. This
//! power is straight-line f64 arithmetic (a select for each special case), so a loop over a
//! [`Lane`] compiles to vector instructions, and the one-vertex path calls the same
//! function, so both paths stay bit for bit alike.
//!
//! The method: x = m·2^e with m in [√½, √2); ln m = 2·atanh(s) with s = (m − 1)/(m + 1),
//! |s| ≤ 0.1716, summed to s¹⁵ (truncation below 10⁻¹³ relative); t = y·log₂ x;
//! 2^t = 2^k·e^(r) with k = round(t) and r = (t − k)·ln 2, |r| ≤ 0.347, summed to r¹¹
//! (truncation below 10⁻¹³). Every f32 input is a normal f64 (f32 subnormals included), so
//! no input needs scaling, and the f64 result is rounded to f32 once. The f64 error, a few
//! 10⁻¹² relative for y ≤ 128 (the largest exponent GL allows), is far below an f32 half
//! ulp (6·10⁻⁸), so the result is the correctly rounded x^y except within 10⁻¹¹ of a
//! rounding boundary: ACCURACY.md ("Lighting powers") counts how often that happens.

use crate::lanes::{Lane, LANES};

/// 1.5 · 2⁵²: adding it rounds an f64 below 2⁵¹ in magnitude to an integer, whose value
/// is then in the low bits of the sum.
const ROUNDER: f64 = 6_755_399_441_055_744.0;

/// 1/(2k + 1) for k = 0 to 7: ln m = 2s · Σ s^(2k)/(2k + 1).
const LOG_SERIES: [f64; 8] = [
    1.0,
    1.0 / 3.0,
    1.0 / 5.0,
    1.0 / 7.0,
    1.0 / 9.0,
    1.0 / 11.0,
    1.0 / 13.0,
    1.0 / 15.0,
];

/// 1/k! for k = 0 to 11: e^r = Σ r^k/k!.
const EXP_SERIES: [f64; 12] = [
    1.0,
    1.0,
    1.0 / 2.0,
    1.0 / 6.0,
    1.0 / 24.0,
    1.0 / 120.0,
    1.0 / 720.0,
    1.0 / 5040.0,
    1.0 / 40320.0,
    1.0 / 362_880.0,
    1.0 / 3_628_800.0,
    1.0 / 39_916_800.0,
];

/// Σ c_k·x^k for k < 8 by Estrin's scheme: neighbouring terms paired with x, the pairs
/// with x², then x⁴, so that the longest chain of dependent operations is three
/// multiply-adds instead of Horner's seven. In the vertex loop, where nothing else is
/// left to overlap with, Horner's chains (twenty steps for a power) were a quarter of the
/// lit vertex's time.
#[inline(always)]
fn estrin8(c: &[f64; 8], x: f64) -> f64 {
    let x2 = x * x;
    let x4 = x2 * x2;
    let pairs = [
        c[0] + x * c[1],
        c[2] + x * c[3],
        c[4] + x * c[5],
        c[6] + x * c[7],
    ];
    (pairs[0] + x2 * pairs[1]) + x4 * (pairs[2] + x2 * pairs[3])
}

/// [`estrin8`] for k < 12: the first eight terms as there, the last four added at x⁸.
#[inline(always)]
fn estrin12(c: &[f64; 12], x: f64) -> f64 {
    let [c0, c1, c2, c3, c4, c5, c6, c7, c8, c9, c10, c11] = *c;
    let x2 = x * x;
    let x8 = x2 * x2 * (x2 * x2);
    let high = (c8 + x * c9) + x2 * (c10 + x * c11);
    estrin8(&[c0, c1, c2, c3, c4, c5, c6, c7], x) + x8 * high
}

/// x^y for x ≥ 0 and finite y ≥ 0, as `powf` defines it: x⁰ = 1 for every x (NaN and ∞
/// included), 0^y = 0 and ∞^y = ∞ for y > 0, NaN in gives NaN out. Overflow gives ∞ and
/// underflow 0 (or a subnormal), as the f32 rounding of the exact value would.
#[inline(always)]
pub fn pow(x: f32, y: f32) -> f32 {
    let (xd, yd) = (x as f64, y as f64);
    // log₂ x = e + log₂ m with m in [√½, √2).
    let bits = xd.to_bits();
    let e = ((bits >> 52) & 0x7ff) as i64 - 1023;
    let m = f64::from_bits(bits & 0x000f_ffff_ffff_ffff | 0x3ff0_0000_0000_0000);
    let high = m > std::f64::consts::SQRT_2;
    let m = if high { m * 0.5 } else { m };
    let e = e as f64 + if high { 1.0 } else { 0.0 };
    let s = (m - 1.0) / (m + 1.0);
    let s2 = s * s;
    let series = estrin8(&LOG_SERIES, s2);
    let log2 = e + 2.0 * s * series * std::f64::consts::LOG2_E;
    // 2^t, t clamped to where 2^k is a normal f64: beyond ±1022 the f32 result is 0 or ∞
    // either way.
    let t = (yd * log2).clamp(-1022.0, 1022.0);
    let rounded = t + ROUNDER;
    let k = rounded - ROUNDER;
    let r = (t - k) * std::f64::consts::LN_2;
    let exp_r = estrin12(&EXP_SERIES, r);
    // 2^k from k's bits in the rounded sum (an integer add and shift, no conversion).
    let k_bits = rounded.to_bits().wrapping_sub(ROUNDER.to_bits());
    let scale = f64::from_bits(k_bits.wrapping_add(1023) << 52);
    let p = (exp_r * scale) as f32;
    if y == 0.0 {
        1.0
    } else if x.is_nan() || y.is_nan() {
        f32::NAN
    } else if x == 0.0 {
        0.0
    } else if x == f32::INFINITY {
        f32::INFINITY
    } else {
        p
    }
}

/// [`pow`] of every lane.
#[inline(always)]
pub fn pow_lanes(x: &Lane<f32>, y: f32) -> Lane<f32> {
    let mut out = [0.0; LANES];
    for j in 0..LANES {
        out[j] = pow(x[j], y);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The distance in f32 steps between `a` and the correctly rounded `exact`.
    fn ulps(a: f32, exact: f64) -> u32 {
        let e = exact as f32;
        if a == e {
            return 0;
        }
        let key = |v: f32| {
            let b = v.to_bits() as i32;
            if b < 0 {
                i32::MIN - b
            } else {
                b
            }
        };
        key(a).abs_diff(key(e))
    }

    #[test]
    fn special_values_follow_powf() {
        for y in [0.0, 0.5, 1.0, 16.0, 128.0] {
            for x in [0.0, 0.25, 1.0, 3.0, f32::INFINITY, f32::NAN] {
                let (ours, libm) = (pow(x, y), x.powf(y));
                assert!(
                    ours.to_bits() == libm.to_bits() || ours.is_nan() && libm.is_nan(),
                    "{x}^{y}: {ours} against {libm}"
                );
            }
        }
        assert_eq!(pow(1.0, 128.0), 1.0);
        assert_eq!(pow(2.0, 127.0), 2f32.powi(127));
        assert_eq!(pow(2.0, 128.0), f32::INFINITY, "overflow");
        assert_eq!(pow(0.5, 128.0), 0.5f32.powi(128), "2^-128 is subnormal");
        assert_eq!(pow(1e-30, 64.0), 0.0, "underflow");
        assert_eq!(
            pow(f32::MIN_POSITIVE / 4.0, 0.5),
            (f32::MIN_POSITIVE / 4.0).sqrt()
        );
    }

    /// Within one f32 step of the exact power everywhere the lighting equation can ask
    /// (bases in [0, 4], exponents in [0, 128]), and correctly rounded but for a handful.
    #[test]
    fn within_one_step_of_the_exact_power() {
        let mut x = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            (x >> 40) as f32 / (1u64 << 24) as f32
        };
        let (mut off, mut n) = (0, 0);
        for _ in 0..200_000 {
            let base = 4.0 * next();
            let y = 128.0 * next();
            let exact = (base as f64).powf(y as f64);
            let d = ulps(pow(base, y), exact);
            assert!(d <= 1, "{base}^{y}: {} against {exact}", pow(base, y));
            off += (d != 0) as u32;
            n += 1;
        }
        assert!(off * 1000 < n, "{off} of {n} not correctly rounded");
    }

    #[test]
    fn lanes_agree_with_one_at_a_time() {
        let x = [0.0, 0.1, 0.5, 0.9, 0.999, 1.0, 1.5, f32::NAN];
        let p = pow_lanes(&x, 12.5);
        for j in 0..LANES {
            assert_eq!(p[j].to_bits(), pow(x[j], 12.5).to_bits());
        }
    }
}
