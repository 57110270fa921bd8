//! Sampling a texture: the filters and wrap modes, and [`Sampler`], the snapshot of a
//! complete texture the fragment stage filters from (level selection, NEAREST and LINEAR
//! per level, mipmap blending, the level-of-detail bias and anisotropy).

use std::sync::Arc;

use super::{BaseFormat, Image};

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MinFilter {
    Nearest,
    Linear,
    NearestMipmapNearest,
    LinearMipmapNearest,
    NearestMipmapLinear,
    LinearMipmapLinear,
}

impl MinFilter {
    pub fn uses_mipmaps(self) -> bool {
        !matches!(self, MinFilter::Nearest | MinFilter::Linear)
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MagFilter {
    Nearest,
    Linear,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Wrap {
    Repeat,
    ClampToEdge,
    /// `OES_texture_mirrored_repeat`.
    MirroredRepeat,
}

impl Wrap {
    /// The texel index `i` of a level `n` texels wide lands on (`OES_texture_npot`: any
    /// `n` ≥ 1). Powers of two wrap with a mask; other sizes with a floating-point quotient.
    #[inline(always)]
    pub fn index(self, i: i32, n: i32) -> i32 {
        if n & (n - 1) == 0 {
            self.index_pot(i, n)
        } else {
            self.index_npot(i, n)
        }
    }

    /// [`Wrap::index`] for `n` a power of two.
    #[inline(always)]
    pub fn index_pot(self, i: i32, n: i32) -> i32 {
        match self {
            Wrap::Repeat => i & (n - 1),
            Wrap::ClampToEdge => i.clamp(0, n - 1),
            Wrap::MirroredRepeat => {
                let m = i & (2 * n - 1);
                if m >= n {
                    2 * n - 1 - m
                } else {
                    m
                }
            }
        }
    }

    /// [`Wrap::index`] for any `n` ≥ 1.
    ///
    /// The remainder modulo the period p (n, or 2n mirrored) comes from an f64 quotient
    /// rather than an integer division, which does not vectorize (the 8-wide routes, whose
    /// coordinates stay within ±2²¹, use an f32 form of the same quotient). The quotient
    /// is exact for every i32 `i`: (i + ½)/p = (2i + 1)/(2p) lies at least 1/(2p) from
    /// every integer, and the computed product (i + ½)·fl(1/p) is within
    /// |i + ½|/p · 2⁻⁵² ≤ 2⁻²¹/p of it, so its floor is ⌊i/p⌋. The rest is exact in f64.
    #[inline(always)]
    pub fn index_npot(self, i: i32, n: i32) -> i32 {
        let period = match self {
            Wrap::ClampToEdge => return i.clamp(0, n - 1),
            Wrap::Repeat => n as f64,
            Wrap::MirroredRepeat => 2.0 * n as f64,
        };
        let x = i as f64;
        let m = x - ((x + 0.5) * (1.0 / period)).floor() * period;
        let m = if m >= n as f64 { period - 1.0 - m } else { m };
        // m is a whole number in [0, n): added to 2⁵², it is the low bits of the sum. (`as
        // i32` would also test for NaN and saturate, lane by lane.)
        (m + 4_503_599_627_370_496.0).to_bits() as u32 as i32
    }

    /// Whether adding `k` to a coordinate changes nothing sampled: whole periods under
    /// REPEAT, even ones under MIRRORED_REPEAT (the pipeline subtracts such offsets to keep
    /// large coordinates precise).
    pub fn period(self) -> Option<f64> {
        match self {
            Wrap::Repeat => Some(1.0),
            Wrap::MirroredRepeat => Some(2.0),
            Wrap::ClampToEdge => None,
        }
    }
}

/// What a texture unit samples: the images of a complete texture (level 0, and the whole
/// chain when the minification filter uses mipmaps) and its sampler parameters.
///
/// Sampling follows ES 1.1 §3.7.7-3.7.8: texel centers at (i + ½)/N; NEAREST takes texel
/// ⌊u⌋, LINEAR the four texels around u − ½, v − ½ weighted by the fractions, computed in
/// f32 (24-bit mantissa: with the pipeline's removal of whole REPEAT periods, weights are
/// exact to well under 2⁻¹² of a texel for every level size). λ = log₂ ρ; λ ≤ c is
/// magnification, with c = ½ when the magnification filter is LINEAR and the minification
/// filter NEAREST_MIPMAP_NEAREST or NEAREST_MIPMAP_LINEAR, else 0. `EXT_texture_lod_bias`:
/// [`Sampler::lod_bias`] is added to λ before that decision and the level selection.
#[derive(Clone, Debug)]
pub struct Sampler {
    pub levels: Vec<Arc<Image>>,
    pub min: MinFilter,
    pub mag: MagFilter,
    pub wrap_s: Wrap,
    pub wrap_t: Wrap,
    pub format: BaseFormat,
    /// The minification / magnification switch-over point.
    pub c: f32,
    /// `OES_texture_cube_map`: for a cube map, the six faces' samplers (POSITIVE_X,
    /// NEGATIVE_X, POSITIVE_Y, NEGATIVE_Y, POSITIVE_Z, NEGATIVE_Z), each clamping to its
    /// edges; this sampler is then the POSITIVE_X face's.
    pub cube: Option<Arc<[Sampler; 6]>>,
    /// `EXT_texture_lod_bias`: the unit's bias, already clamped to ±[`MAX_LOD_BIAS`], added
    /// to λ by [`Sampler::sample_255`] and [`Sampler::trilinear`] (the cube faces carry it
    /// too). 0 unless set by [`Sampler::with_lod_bias`].
    pub lod_bias: f32,
    /// `EXT_texture_filter_anisotropic`: how many samples minification may take along the
    /// footprint's long axis, 1 to [`MAX_ANISOTROPY`] (1: isotropic, the default).
    pub max_anisotropy: f32,
}

/// `GL_MAX_TEXTURE_LOD_BIAS_EXT`: the largest magnitude of a level-of-detail bias.
pub const MAX_LOD_BIAS: f32 = 16.0;

/// `GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT`.
pub const MAX_ANISOTROPY: f32 = 16.0;

impl PartialEq for Sampler {
    /// The same images (by identity) and parameters.
    fn eq(&self, o: &Sampler) -> bool {
        self.levels.len() == o.levels.len()
            && self
                .levels
                .iter()
                .zip(&o.levels)
                .all(|(a, b)| Arc::ptr_eq(a, b))
            && (self.min, self.mag, self.wrap_s, self.wrap_t) == (o.min, o.mag, o.wrap_s, o.wrap_t)
            && self.lod_bias.to_bits() == o.lod_bias.to_bits()
            && self.max_anisotropy.to_bits() == o.max_anisotropy.to_bits()
            && match (&self.cube, &o.cube) {
                (None, None) => true,
                (Some(a), Some(b)) => Arc::ptr_eq(a, b) || a[..] == b[..],
                _ => false,
            }
    }
}

const INV_255: f32 = 1.0 / 255.0;

/// log2(x) in plain f32 arithmetic, so that a loop over lanes vectorizes (libm's `log2f`
/// is a call per lane: a tenth of a per-pixel trilinear profile). Exact at powers of two,
/// so λ is exact where a level begins; elsewhere within 1e-7 of the true value plus the
/// rounding of the result to f32. 0 gives −∞, +∞ gives +∞, NaN and negative values NaN,
/// as `f32::log2` does.
#[inline(always)]
pub fn log2(x: f32) -> f32 {
    // Subnormals are scaled into the normal range and the scale taken off again.
    let tiny = x < f32::MIN_POSITIVE;
    let xs = if tiny { x * 8_388_608.0 } else { x };
    // x = 2^e · m with m in [√½, √2), centred on 1 so the series converges fast: e counts
    // the octaves above √½ (the bits of √½ subtracted), m keeps x's mantissa with the
    // exponent of that octave.
    let bits = xs.to_bits();
    let off = bits.wrapping_sub(0x3F35_04F3) as i32;
    let e = (off >> 23) as f32 - if tiny { 23.0 } else { 0.0 };
    let m = f32::from_bits(bits.wrapping_sub(off as u32 & 0xFF80_0000));
    // log2 m = (2 / ln 2) · atanh z with z = (m − 1)/(m + 1), |z| ≤ 0.172: five odd terms
    // leave a truncation error below 2e-9 (m − 1 is exact, and z = 0 at m = 1).
    let z = (m - 1.0) / (m + 1.0);
    let z2 = z * z;
    const K: f32 = std::f32::consts::LOG2_E * 2.0;
    let series = z * (K + z2 * (K / 3.0 + z2 * (K / 5.0 + z2 * (K / 7.0 + z2 * (K / 9.0)))));
    let r = e + series;
    let r = if x == 0.0 { f32::NEG_INFINITY } else { r };
    let r = if x == f32::INFINITY { x } else { r };
    if x >= 0.0 {
        r
    } else {
        f32::NAN
    }
}

#[inline(always)]
fn unpack_f32(w: u32) -> [f32; 4] {
    let b = w.to_le_bytes();
    [b[0] as f32, b[1] as f32, b[2] as f32, b[3] as f32]
}

/// Floor of a texel-space coordinate as an index; huge values and NaN saturate (any index
/// is then wrapped or clamped into the level), so no coordinate can fault.
#[inline(always)]
fn floor_index(u: f32) -> i32 {
    u.floor() as i32
}

impl Sampler {
    pub fn new(
        levels: Vec<Arc<Image>>,
        min: MinFilter,
        mag: MagFilter,
        wrap_s: Wrap,
        wrap_t: Wrap,
    ) -> Sampler {
        let c = if mag == MagFilter::Linear
            && matches!(
                min,
                MinFilter::NearestMipmapNearest | MinFilter::NearestMipmapLinear
            ) {
            0.5
        } else {
            0.0
        };
        let format = levels[0].format;
        Sampler {
            levels,
            min,
            mag,
            wrap_s,
            wrap_t,
            format,
            c,
            cube: None,
            lod_bias: 0.0,
            max_anisotropy: 1.0,
        }
    }

    /// This sampler with level-of-detail bias `bias` (`EXT_texture_lod_bias`), clamped to
    /// ±[`MAX_LOD_BIAS`] (NaN counts as 0), on every cube face as well. Shares `self` when
    /// the bias is unchanged.
    pub fn with_lod_bias(self: &Arc<Sampler>, bias: f32) -> Arc<Sampler> {
        let bias = if bias.is_nan() {
            0.0
        } else {
            bias.clamp(-MAX_LOD_BIAS, MAX_LOD_BIAS)
        };
        if bias.to_bits() == self.lod_bias.to_bits() {
            return self.clone();
        }
        let mut s = (**self).clone();
        s.lod_bias = bias;
        if let Some(faces) = &s.cube {
            let mut faces = (**faces).clone();
            faces.iter_mut().for_each(|f| f.lod_bias = bias);
            s.cube = Some(Arc::new(faces));
        }
        Arc::new(s)
    }

    /// Level 0's width and height.
    #[inline]
    pub fn size(&self) -> (u32, u32) {
        (self.levels[0].width, self.levels[0].height)
    }

    /// The texel at wrapped integer coordinates (i, j) of `level`, as an RGBA8 word.
    #[inline(always)]
    pub fn texel(&self, level: usize, i: i32, j: i32) -> u32 {
        let img = &self.levels[level];
        let (w, h) = (img.width as i32, img.height as i32);
        let x = self.wrap_s.index(i, w);
        let y = self.wrap_t.index(j, h);
        // SAFETY-free: indices are in range by construction of `Wrap::index`.
        img.texels[(y * w + x) as usize]
    }

    /// NEAREST at (s, t) in `level`, in 0 ..= 255 per channel.
    #[inline(always)]
    pub fn nearest(&self, level: usize, s: f32, t: f32) -> [f32; 4] {
        let img = &self.levels[level];
        let i = floor_index(s * img.width as f32);
        let j = floor_index(t * img.height as f32);
        unpack_f32(self.texel(level, i, j))
    }

    /// LINEAR (bilinear) at (s, t) in `level`, in 0 ..= 255 per channel.
    #[inline(always)]
    pub fn bilinear(&self, level: usize, s: f32, t: f32) -> [f32; 4] {
        let img = &self.levels[level];
        let u = s * img.width as f32 - 0.5;
        let v = t * img.height as f32 - 0.5;
        let (fu, fv) = (u.floor(), v.floor());
        let (i, j) = (fu as i32, fv as i32);
        let (a, b) = (u - fu, v - fv);
        let t00 = unpack_f32(self.texel(level, i, j));
        let t10 = unpack_f32(self.texel(level, i.wrapping_add(1), j));
        let t01 = unpack_f32(self.texel(level, i, j.wrapping_add(1)));
        let t11 = unpack_f32(self.texel(level, i.wrapping_add(1), j.wrapping_add(1)));
        std::array::from_fn(|c| {
            let top = t00[c] + (t10[c] - t00[c]) * a;
            let bottom = t01[c] + (t11[c] - t01[c]) * a;
            top + (bottom - top) * b
        })
    }

    #[inline(always)]
    fn filter(&self, linear: bool, level: usize, s: f32, t: f32) -> [f32; 4] {
        if linear {
            self.bilinear(level, s, t)
        } else {
            self.nearest(level, s, t)
        }
    }

    /// λ from ρ², the larger squared length of the texel-space derivative vectors
    /// (`du/dx, dv/dx` and `du/dy, dv/dy`, in level-0 texels per pixel).
    #[inline(always)]
    pub fn lambda(rho2: f32) -> f32 {
        // log2(sqrt(x)) = log2(x) / 2; ρ = 0 gives −∞ (magnification).
        0.5 * log2(rho2)
    }

    /// LINEAR_MIPMAP_LINEAR minification, LINEAR magnification, in 0 ..= 255 per channel.
    #[inline(always)]
    pub fn trilinear(&self, s: f32, t: f32, lambda: f32) -> [f32; 4] {
        let lambda = lambda + self.lod_bias;
        if lambda.is_nan() || lambda <= self.c {
            return self.bilinear(0, s, t);
        }
        let q = self.levels.len() - 1;
        if lambda >= q as f32 {
            return self.bilinear(q, s, t);
        }
        let d1 = lambda as usize;
        let f = lambda - d1 as f32;
        let a = self.bilinear(d1, s, t);
        let b = self.bilinear(d1 + 1, s, t);
        std::array::from_fn(|c| a[c] + (b[c] - a[c]) * f)
    }

    /// The filtered texture value at (s, t) with level of detail λ (before the bias), in
    /// [0, 1] per channel.
    #[inline]
    pub fn sample(&self, s: f32, t: f32, lambda: f32) -> [f32; 4] {
        let v = self.sample_255(s, t, lambda);
        v.map(|c| c * INV_255)
    }

    /// [`Sampler::sample`] in 0 ..= 255 per channel.
    #[inline]
    pub fn sample_255(&self, s: f32, t: f32, lambda: f32) -> [f32; 4] {
        let lambda = lambda + self.lod_bias;
        // NaN λ (from degenerate derivatives) counts as magnification.
        if lambda.is_nan() || lambda <= self.c {
            return self.filter(self.mag == MagFilter::Linear, 0, s, t);
        }
        let q = self.levels.len() - 1;
        match self.min {
            MinFilter::Nearest => self.nearest(0, s, t),
            MinFilter::Linear => self.bilinear(0, s, t),
            MinFilter::NearestMipmapNearest | MinFilter::LinearMipmapNearest => {
                let d = if lambda <= 0.5 {
                    0
                } else {
                    ((lambda + 0.5).ceil() - 1.0).min(q as f32) as usize
                };
                self.filter(self.min == MinFilter::LinearMipmapNearest, d, s, t)
            }
            MinFilter::NearestMipmapLinear | MinFilter::LinearMipmapLinear => {
                let linear = self.min == MinFilter::LinearMipmapLinear;
                if lambda >= q as f32 {
                    return self.filter(linear, q, s, t);
                }
                let d1 = lambda.floor() as usize;
                let f = lambda - d1 as f32;
                let a = self.filter(linear, d1, s, t);
                let b = self.filter(linear, d1 + 1, s, t);
                std::array::from_fn(|c| a[c] + (b[c] - a[c]) * f)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log2_is_exact_at_powers_of_two_and_close_elsewhere() {
        for e in -149..=127 {
            let x = if e >= -126 {
                f32::from_bits(((e + 127) as u32) << 23)
            } else {
                f32::from_bits(1 << (e + 149))
            };
            assert_eq!(log2(x), e as f32, "2^{e}");
        }
        // Spread over the whole range, subnormals included, against the f64 logarithm: the
        // error is the series' (below 1e-7) plus the rounding of the result to f32.
        let mut bits = 1u32;
        while bits < f32::INFINITY.to_bits() {
            let x = f32::from_bits(bits);
            let exact = (x as f64).log2();
            let err = (log2(x) as f64 - exact).abs();
            let ulp = (exact.abs() as f32).max(1.0) as f64 * f32::EPSILON as f64;
            assert!(err <= 1e-7 + ulp, "log2({x:e}) off by {err:e}");
            bits += 9_973;
        }
        assert_eq!(log2(0.0), f32::NEG_INFINITY);
        assert_eq!(log2(-0.0), f32::NEG_INFINITY);
        assert_eq!(log2(f32::INFINITY), f32::INFINITY);
        assert!(log2(f32::NAN).is_nan());
        assert!(log2(-1.0).is_nan());
        assert!(log2(f32::NEG_INFINITY).is_nan());
    }

    /// The floating-point quotient against the reference renderer's integer division: every size up to 4 096 near
    /// the multiples of the period where a wrong floor would show, and the ends of the i32
    /// range for sizes up to 2³⁰.
    #[test]
    fn npot_wrap_is_the_integer_remainder() {
        let wraps = [Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat];
        let check = |i: i32, n: i32| {
            for wrap in wraps {
                assert_eq!(
                    wrap.index_npot(i, n) as usize,
                    crate::reference::texturing::index(wrap, i as i64, n as i64),
                    "{wrap:?} {i} mod {n}"
                );
            }
        };
        for n in 1..=4096 {
            for k in [-(1 << 22) / n, -3, -2, -1, 0, 1, 2, 3, (1 << 22) / n] {
                for d in -2..=2 {
                    check(k * n + d, n);
                    check(k * 2 * n + d, n);
                }
            }
        }
        for n in [3, 5, 7, 1000, 4095, 65_537, (1 << 30) - 1, 1 << 30] {
            for i in [i32::MIN, i32::MIN + 1, -1, 0, i32::MAX - 1, i32::MAX] {
                check(i, n);
            }
        }
    }
}
