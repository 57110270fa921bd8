//! GLfixed (signed 16.16) conversions: the one place where fixed-point entry points and
//! queries meet the float state.

/// 1.0 in 16.16.
pub const ONE: i32 = 1 << 16;

/// A 16.16 value as f32. Exact for |x| < 2⁸; beyond that f32's 24-bit mantissa rounds, which
/// stays well inside GL's 10⁻⁵ relative accuracy requirement.
#[inline]
pub fn to_f32(x: i32) -> f32 {
    x as f32 * (1.0 / 65536.0)
}

/// A float as 16.16, rounded to nearest and saturated to the representable range
/// (NaN becomes 0), for fixed-point queries.
#[inline]
pub fn from_f32(f: f32) -> i32 {
    let v = (f as f64 * 65536.0).round();
    if v.is_nan() {
        0
    } else {
        v.clamp(i32::MIN as f64, i32::MAX as f64) as i32
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn conversions_round_and_saturate() {
        assert_eq!(to_f32(ONE), 1.0);
        assert_eq!(to_f32(-ONE / 2), -0.5);
        assert_eq!(from_f32(1.5), 0x18000);
        assert_eq!(from_f32(1e10), i32::MAX);
        assert_eq!(from_f32(-1e10), i32::MIN);
        assert_eq!(from_f32(f32::NAN), 0);
        assert_eq!(from_f32(to_f32(0x12345)), 0x12345);
    }
}
