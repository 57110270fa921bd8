//! The specialized span routines, run over groups of up to [`LANES`] pixels with one array
//! per channel, in the lane vocabulary of [`crate::lanes`] that the vertex stage shares.
//! Each step (depth, color interpolation, blending, encoding) is a loop over the whole group
//! with its state decisions taken once outside it, which the compiler turns into SIMD; per
//! pixel, the arithmetic is exactly the per-pixel code's (same operations in the same order,
//! no fused multiply-add), so the images are bit-identical to it.

// Lane loops index several arrays in step; that is the shape the vectorizer wants.
#![allow(clippy::needless_range_loop)]

use super::*;
use crate::lanes::{Lane, INDEX_F32, INDEX_F64, LANES};
use crate::texenv::{Combine, CombineFunc, EnvMode, FogMode, Operand, Source, TexEnv};
use crate::texture::{BaseFormat, MagFilter, MinFilter, Wrap};

/// Texels are unpacked to 0 ..= 255 and filtered there, then scaled to 0 ..= 1.
const INV_255: f32 = 1.0 / 255.0;

/// `v` clamped to [0, 1] with NaN mapped to 0 (`clamp` would keep NaN).
#[inline(always)]
#[allow(clippy::manual_clamp)]
fn unit_or_zero(v: f32) -> f32 {
    v.max(0.0).min(1.0)
}

/// [`unit_or_zero`] for f64.
#[inline(always)]
#[allow(clippy::manual_clamp)]
fn unit_or_zero_f64(v: f64) -> f64 {
    v.max(0.0).min(1.0)
}

/// `floor(v)` as an integer for `v` in [0, 2³²), in plain f64 arithmetic that vectorizes
/// (a saturating cast does not); see [`floor_i32`].
#[inline(always)]
fn floor_u32_f64(v: f64) -> u32 {
    const MAGIC: f64 = 4_503_599_627_370_496.0;
    let r = (v + MAGIC) - MAGIC;
    let f = if r > v { r - 1.0 } else { r };
    ((f + MAGIC).to_bits() - MAGIC.to_bits()) as u32
}

/// One array per channel: r, g, b, a.
type Channels = [Lane<f32>; 4];

/// Runs the depth test over the group at `i0` against `depth`, writing passing depths when
/// `write` is set; returns a mask per lane (all ones where the fragment passes).
#[inline(always)]
fn depth_test(
    interp: &SpanInterp,
    func: CompareFunc,
    format: DepthFormat,
    write: bool,
    i0: usize,
    live: Lane<u32>,
    depth: &mut Lane<u32>,
) -> Lane<u32> {
    let max = format.max() as f64;
    let fi0 = i0 as f64;
    let mut z = [0u32; LANES];
    for (j, z) in z.iter_mut().enumerate() {
        // DepthFormat::quantize of SpanInterp::z, written out so it vectorizes (NaN → 0).
        let v = interp.z0 + interp.dz * (fi0 + INDEX_F64[j]);
        *z = floor_u32_f64(unit_or_zero_f64(v) * max + 0.5);
    }
    let mut pass = [0u32; LANES];
    macro_rules! cmp {
        ($op:tt) => {
            for j in 0..LANES {
                pass[j] = 0u32.wrapping_sub((z[j] $op depth[j]) as u32);
            }
        };
    }
    match func {
        CompareFunc::Never => {}
        CompareFunc::Less => cmp!(<),
        CompareFunc::Equal => cmp!(==),
        CompareFunc::LessEqual => cmp!(<=),
        CompareFunc::Greater => cmp!(>),
        CompareFunc::NotEqual => cmp!(!=),
        CompareFunc::GreaterEqual => cmp!(>=),
        CompareFunc::Always => pass = [!0; LANES],
    }
    for j in 0..LANES {
        pass[j] &= live[j];
    }
    if write {
        for j in 0..LANES {
            depth[j] = (depth[j] & !pass[j]) | (z[j] & pass[j]);
        }
    }
    pass
}

/// The interpolated colors of the group at `i0`.
#[inline(always)]
fn colors(interp: &SpanInterp, i0: usize) -> Channels {
    // Built as values, one whole vector per channel: arrays filled piecewise in memory and
    // then reloaded whole stall store forwarding.
    let fi0 = i0 as f32;
    let (c0, dc) = (interp.c0, interp.dc);
    match interp.divide {
        Divide::None => {
            std::array::from_fn(|c| std::array::from_fn(|j| c0[c] + dc[c] * (fi0 + INDEX_F32[j])))
        }
        Divide::Exact => {
            let (w0, dw) = (interp.inv_w0, interp.d_inv_w);
            let w: Lane<f32> = std::array::from_fn(|j| 1.0 / (w0 + dw * (fi0 + INDEX_F32[j])));
            std::array::from_fn(|c| {
                std::array::from_fn(|j| (c0[c] + dc[c] * (fi0 + INDEX_F32[j])) * w[j])
            })
        }
    }
}

/// The encoded words of an unblended smooth group, interpolated and encoded in one pass
/// (no per-channel arrays in memory between the steps: storing them piecewise and
/// reloading them whole stalls store forwarding). `None` for formats narrower than 8
/// bits, which take the general steps.
#[inline(always)]
fn smooth_words(interp: &SpanInterp, i0: usize, format: ColorFormat) -> Option<Lane<u32>> {
    let alpha = match format {
        ColorFormat::Rgba8888 => 0,
        ColorFormat::Rgb888 => 0xFF00_0000,
        _ => return None,
    };
    let alpha_mask = if alpha == 0 { 0xFF } else { 0 };
    let fi0 = i0 as f32;
    let (c0, dc) = (interp.c0, interp.dc);
    let (w0, dw) = (interp.inv_w0, interp.d_inv_w);
    let word = |c: [f32; 4]| {
        channel_byte(c[0])
            | channel_byte(c[1]) << 8
            | channel_byte(c[2]) << 16
            | (channel_byte(c[3]) & alpha_mask) << 24
            | alpha
    };
    match interp.divide {
        Divide::None => Some(std::array::from_fn(|j| {
            let f = fi0 + INDEX_F32[j];
            word(std::array::from_fn(|c| c0[c] + dc[c] * f))
        })),
        Divide::Exact => Some(std::array::from_fn(|j| {
            let f = fi0 + INDEX_F32[j];
            let w = 1.0 / (w0 + dw * f);
            word(std::array::from_fn(|c| (c0[c] + dc[c] * f) * w))
        })),
    }
}

/// The stored colors of a group as values in [0, 1] (see `decode`). `fast` (the
/// `GL_FASTEST` perspective hint) lets narrow channels be scaled by a rounded reciprocal
/// instead of divided: at most 1 ulp apart, far below a step of any format, and no
/// division per channel and group (see `decode_channel`).
#[inline(always)]
fn decode_lanes(format: ColorFormat, w: &Lane<u32>, out: &mut Channels, fast: bool) {
    match format {
        // One call per channel with its shift a constant: a loop over the channels with the
        // shift as its variable stayed scalar.
        ColorFormat::Rgba8888 | ColorFormat::Rgb888 => {
            out[0] = decode_byte::<0>(w);
            out[1] = decode_byte::<8>(w);
            out[2] = decode_byte::<16>(w);
            out[3] = decode_byte::<24>(w);
        }
        // One arm per format, with the bit counts as constants.
        ColorFormat::Rgb565 => decode_narrow::<5, 6, 5, 0>(w, out, fast),
        ColorFormat::Rgba4444 => decode_narrow::<4, 4, 4, 4>(w, out, fast),
        ColorFormat::Rgba5551 => decode_narrow::<5, 5, 5, 1>(w, out, fast),
    }
}

/// The byte at `SHIFT` of every word over 255, as `decode` divides an 8-bit channel.
#[inline(always)]
fn decode_byte<const SHIFT: u32>(w: &Lane<u32>) -> Lane<f32> {
    std::array::from_fn(|j| ((w[j] >> SHIFT) & 0xFF) as i32 as f32 * INV_255)
}

/// [`decode_lanes`] for channels of R, G, B, A bits (0: absent, read as 1).
#[inline(always)]
fn decode_narrow<const R: u32, const G: u32, const B: u32, const A: u32>(
    w: &Lane<u32>,
    out: &mut Channels,
    fast: bool,
) {
    out[0] = decode_channel::<R>(w, 0, fast);
    out[1] = decode_channel::<G>(w, 8, fast);
    out[2] = decode_channel::<B>(w, 16, fast);
    out[3] = decode_channel::<A>(w, 24, fast);
}

/// One channel of N bits stored at byte `shift`: the n-bit value, which is the stored
/// byte's top n bits, over 2ⁿ − 1, divided as `decode` divides. With `fast`, multiplied
/// by 1 / (2ⁿ − 1) instead: no f32 constant makes that product equal the quotient for
/// every n-bit value, so the exact routes keep the division (the slowest instruction of a
/// blended group on a narrow target).
#[inline(always)]
fn decode_channel<const N: u32>(w: &Lane<u32>, shift: u32, fast: bool) -> Lane<f32> {
    if N == 0 {
        return [1.0; LANES];
    }
    let max = ((1u32 << N) - 1) as f32;
    if fast {
        let inv = 1.0 / max;
        return std::array::from_fn(|j| (((w[j] >> shift) & 0xFF) >> (8 - N)) as i32 as f32 * inv);
    }
    std::array::from_fn(|j| (((w[j] >> shift) & 0xFF) >> (8 - N)) as i32 as f32 / max)
}

/// A channel's 8-bit value, `unorm(c, 8)`, as a word to shift into place; written so it
/// vectorizes (`max` maps NaN to 0 as `unorm` does).
#[inline(always)]
fn channel_byte(c: f32) -> u32 {
    floor_i32(unit_or_zero(c) * 255.0 + 0.5).0 as u32
}

/// Encodes a group to stored words (see `ColorFormat::encode`), with ordered dithering by
/// the group's `thresholds` when given (see `encode_dithered`; only narrow formats dither).
#[inline(always)]
fn encode_lanes(format: ColorFormat, c: &Channels, thresholds: Option<&Lane<f32>>) -> Lane<u32> {
    let mut out = [0u32; LANES];
    match format {
        ColorFormat::Rgba8888 => {
            for (j, o) in out.iter_mut().enumerate() {
                *o = channel_byte(c[0][j])
                    | channel_byte(c[1][j]) << 8
                    | channel_byte(c[2][j]) << 16
                    | channel_byte(c[3][j]) << 24;
            }
        }
        ColorFormat::Rgb888 => {
            for (j, o) in out.iter_mut().enumerate() {
                *o = channel_byte(c[0][j])
                    | channel_byte(c[1][j]) << 8
                    | channel_byte(c[2][j]) << 16
                    | 0xFF00_0000;
            }
        }
        ColorFormat::Rgb565 => out = encode_narrow::<5, 6, 5, 0>(c, thresholds),
        ColorFormat::Rgba4444 => out = encode_narrow::<4, 4, 4, 4>(c, thresholds),
        ColorFormat::Rgba5551 => out = encode_narrow::<5, 5, 5, 1>(c, thresholds),
    }
    out
}

/// [`encode_lanes`] for channels of R, G, B, A bits (0: absent, stored as 255).
#[inline(always)]
fn encode_narrow<const R: u32, const G: u32, const B: u32, const A: u32>(
    c: &Channels,
    thresholds: Option<&Lane<f32>>,
) -> Lane<u32> {
    let (r, g) = (
        encode_channel::<R>(&c[0], thresholds),
        encode_channel::<G>(&c[1], thresholds),
    );
    let (b, a) = (
        encode_channel::<B>(&c[2], thresholds),
        encode_channel::<A>(&c[3], thresholds),
    );
    std::array::from_fn(|j| r[j] | g[j] << 8 | b[j] << 16 | a[j] << 24)
}

/// One channel to N bits, widened to its stored byte as `expand_to_8` does. Without
/// thresholds the value is `unorm(c, N)`; with them `floor(clamp(c) · (2ᴺ − 1) + t)`, where
/// NaN gives 2ᴺ − 1 as the per-pixel `min` makes it (see `encode_dithered`). One loop per
/// step, each of which vectorizes (written as one expression per lane, they did not).
#[inline(always)]
#[allow(clippy::manual_clamp)]
fn encode_channel<const N: u32>(c: &Lane<f32>, thresholds: Option<&Lane<f32>>) -> Lane<u32> {
    if N == 0 {
        return [0xFF; LANES];
    }
    let max_i = (1i32 << N) - 1;
    let max = max_i as f32;
    let mut s = [0.0f32; LANES];
    match thresholds {
        None => {
            for j in 0..LANES {
                s[j] = unit_or_zero(c[j]) * max + 0.5;
            }
        }
        Some(t) => {
            // `min` first takes NaN to 1, so it ends at 2ᴺ − 1 (t < 1) without a select;
            // elsewhere this is `clamp`.
            for j in 0..LANES {
                s[j] = c[j].min(1.0).max(0.0) * max + t[j];
            }
        }
    }
    let mut v = [0i32; LANES];
    for j in 0..LANES {
        v[j] = floor_i32(s[j]).0;
    }
    let mut out = [0u32; LANES];
    for j in 0..LANES {
        out[j] = expand_to_8(v[j] as u32, N) as u32;
    }
    out
}

/// One blend factor for channel `c` of every lane (the alpha lane of `SRC_ALPHA_SATURATE`
/// is 1), as `factors` gives it per pixel.
#[inline(always)]
fn factor_lanes(f: BlendFactor, c: usize, src: &Channels, dst: &Channels) -> Lane<f32> {
    let mut out = [0.0; LANES];
    let each = |out: &mut Lane<f32>, g: &dyn Fn(usize) -> f32| {
        for (j, o) in out.iter_mut().enumerate() {
            *o = g(j);
        }
    };
    match f {
        BlendFactor::Zero => {}
        BlendFactor::One => out = [1.0; LANES],
        BlendFactor::SrcColor => out = src[c],
        BlendFactor::OneMinusSrcColor => each(&mut out, &|j| 1.0 - src[c][j]),
        BlendFactor::DstColor => out = dst[c],
        BlendFactor::OneMinusDstColor => each(&mut out, &|j| 1.0 - dst[c][j]),
        BlendFactor::SrcAlpha => out = src[3],
        BlendFactor::OneMinusSrcAlpha => each(&mut out, &|j| 1.0 - src[3][j]),
        BlendFactor::DstAlpha => out = dst[3],
        BlendFactor::OneMinusDstAlpha => each(&mut out, &|j| 1.0 - dst[3][j]),
        BlendFactor::SrcAlphaSaturate if c == 3 => out = [1.0; LANES],
        BlendFactor::SrcAlphaSaturate => each(&mut out, &|j| src[3][j].min(1.0 - dst[3][j])),
    }
    out
}

/// `blend` over a group: `src` is clamped to [0, 1] first (in place); the result replaces
/// `dst` and is clamped by the encoder.
#[inline(always)]
fn blend_lanes(b: &Blend, src: &mut Channels, dst: &mut Channels) {
    for ch in src.iter_mut() {
        for c in ch.iter_mut() {
            *c = c.clamp(0.0, 1.0);
        }
    }
    let src = &*src;
    if add_blend(b, src, dst) {
        return;
    }
    let mut out = [[0.0; LANES]; 4];
    for (c, out) in out.iter_mut().enumerate() {
        let (fs, fd, eq) = if c < 3 {
            (b.src_rgb, b.dst_rgb, b.eq_rgb)
        } else {
            (b.src_alpha, b.dst_alpha, b.eq_alpha)
        };
        let sf = factor_lanes(fs, c, src, dst);
        let df = factor_lanes(fd, c, src, dst);
        let (s, d) = (&src[c], &dst[c]);
        match eq {
            BlendEquation::Add => {
                for j in 0..LANES {
                    out[j] = s[j] * sf[j] + d[j] * df[j];
                }
            }
            BlendEquation::Subtract => {
                for j in 0..LANES {
                    out[j] = s[j] * sf[j] - d[j] * df[j];
                }
            }
            BlendEquation::ReverseSubtract => {
                for j in 0..LANES {
                    out[j] = d[j] * df[j] - s[j] * sf[j];
                }
            }
            BlendEquation::Min => {
                for j in 0..LANES {
                    out[j] = s[j].min(d[j]);
                }
            }
            BlendEquation::Max => {
                for j in 0..LANES {
                    out[j] = s[j].max(d[j]);
                }
            }
        }
    }
    *dst = out;
}

/// The blend functions programs use most (alpha, premultiplied alpha, additive,
/// modulation), with the ADD equation and the same factors for color and alpha: each
/// factor is written out in a loop of its own instead of selected per channel and group.
/// The arithmetic is `blend_lanes`' own, `s·sf + d·df` lane by lane, so the results are
/// the same bits. Returns false (and leaves `dst`) for every other blend.
#[inline(always)]
fn add_blend(b: &Blend, src: &Channels, dst: &mut Channels) -> bool {
    use BlendFactor::*;
    if b.eq_rgb != BlendEquation::Add
        || b.eq_alpha != BlendEquation::Add
        || b.src_rgb != b.src_alpha
        || b.dst_rgb != b.dst_alpha
    {
        return false;
    }
    // `sf(c, j)` and `df(c, j)`: the factors of channel c, lane j, given the destination.
    #[inline(always)]
    fn each(
        src: &Channels,
        dst: &mut Channels,
        sf: impl Fn(&Channels, &Channels, usize, usize) -> f32,
        df: impl Fn(&Channels, &Channels, usize, usize) -> f32,
    ) {
        let d = *dst;
        for c in 0..4 {
            for j in 0..LANES {
                dst[c][j] = src[c][j] * sf(src, &d, c, j) + d[c][j] * df(src, &d, c, j);
            }
        }
    }
    match (b.src_rgb, b.dst_rgb) {
        (SrcAlpha, OneMinusSrcAlpha) => {
            each(src, dst, |s, _, _, j| s[3][j], |s, _, _, j| 1.0 - s[3][j])
        }
        (One, OneMinusSrcAlpha) => each(src, dst, |_, _, _, _| 1.0, |s, _, _, j| 1.0 - s[3][j]),
        (SrcAlpha, One) => each(src, dst, |s, _, _, j| s[3][j], |_, _, _, _| 1.0),
        (One, One) => each(src, dst, |_, _, _, _| 1.0, |_, _, _, _| 1.0),
        (DstColor, Zero) => each(src, dst, |_, d, c, j| d[c][j], |_, _, _, _| 0.0),
        (Zero, SrcColor) => each(src, dst, |_, _, _, _| 0.0, |s, _, c, j| s[c][j]),
        _ => return false,
    }
    true
}

/// The blend of a source color that is the same at every pixel of a span (flat shading,
/// points) by factors that do not read the destination, worked out once per span: every
/// channel is then `add + d·mul`, one multiply and one add per lane. For ADD that is
/// `s·sf + d·df` with `s·sf` the product `blend` forms; SUBTRACT negates the factor
/// (`s·sf + d·(−df)` is `s·sf − d·df`, bit for bit) and REVERSE_SUBTRACT the source term
/// (`−(s·sf) + d·df` is `d·df − s·sf`), so the results are the per-pixel blend's bits.
#[derive(Clone, Copy)]
struct ConstantBlend {
    add: [f32; 4],
    mul: [f32; 4],
}

/// Spans shorter than this blend a flat color group by group as any other: working the
/// blend out once costs about as much as blending three groups.
const CONSTANT_BLEND_MIN: usize = 4 * LANES;

impl ConstantBlend {
    /// `None` when a factor reads the destination or an equation is MIN or MAX.
    fn new(b: &Blend, src: [f32; 4]) -> Option<ConstantBlend> {
        use BlendFactor::*;
        let reads_dst = |f: BlendFactor| {
            matches!(
                f,
                DstColor | OneMinusDstColor | DstAlpha | OneMinusDstAlpha | SrcAlphaSaturate
            )
        };
        if [b.src_rgb, b.dst_rgb, b.src_alpha, b.dst_alpha]
            .into_iter()
            .any(reads_dst)
        {
            return None;
        }
        let src = src.map(|c| c.clamp(0.0, 1.0));
        // The factors above never read this.
        let dst = [0.0; 4];
        let (sf, df) = (
            factors(b.src_rgb, &src, &dst),
            factors(b.dst_rgb, &src, &dst),
        );
        let sa = factors(b.src_alpha, &src, &dst)[3];
        let da = factors(b.dst_alpha, &src, &dst)[3];
        let (mut add, mut mul) = ([0.0; 4], [0.0; 4]);
        for c in 0..4 {
            let (eq, s, f) = if c < 3 {
                (b.eq_rgb, src[c] * sf[c], df[c])
            } else {
                (b.eq_alpha, src[3] * sa, da)
            };
            (add[c], mul[c]) = match eq {
                BlendEquation::Add => (s, f),
                BlendEquation::Subtract => (s, -f),
                BlendEquation::ReverseSubtract => (-s, f),
                BlendEquation::Min | BlendEquation::Max => return None,
            };
        }
        Some(ConstantBlend { add, mul })
    }

    /// Replaces the destination colors `dst` by the blend.
    #[inline(always)]
    fn apply(&self, dst: &mut Channels) {
        for c in 0..4 {
            for j in 0..LANES {
                dst[c][j] = self.add[c] + dst[c][j] * self.mul[c];
            }
        }
    }
}

/// Runs `$group(i0, live, color, depth)` over the groups of the span of `$len` pixels at
/// `$start` in `$band`. `live` masks the lanes inside the span: a partial last group works
/// in place on the band's next pixels, writing none of them (the group routines AND their
/// writes with `live`), or, at the very end of the band, on copies padded to [`LANES`]
/// (a copy of a few pixels is a library call, too slow to take for every small span).
/// `depth` is `None` only for groups without a depth test. A macro, not a function taking
/// a closure: closures do not inherit the instruction set the span routines are compiled
/// for.
macro_rules! for_each_group {
    ($depth_test:expr, $band:expr, $start:expr, $len:expr, |$i0:ident, $live:ident, $color:ident, $depth:ident| $group:expr) => {{
        let (band, start, len): (&mut BandMut<'_>, usize, usize) = ($band, $start, $len);
        let mut i0 = 0;
        while i0 < len {
            let m = (len - i0).min(LANES);
            let at = start + i0;
            let in_place =
                at + LANES <= band.color.len() && (!$depth_test || at + LANES <= band.depth.len());
            if m == LANES || in_place {
                let $i0 = i0;
                let $live: Lane<u32> = if m == LANES {
                    [!0; LANES]
                } else {
                    live_lanes(m)
                };
                let $color: &mut Lane<u32> = (&mut band.color[at..at + LANES])
                    .try_into()
                    .expect("a whole group");
                let $depth: Option<&mut Lane<u32>> = if $depth_test {
                    (&mut band.depth[at..at + LANES]).try_into().ok()
                } else {
                    None
                };
                $group;
            } else {
                let color = &mut band.color[at..at + m];
                let depth = if $depth_test {
                    &mut band.depth[at..at + m]
                } else {
                    &mut [][..]
                };
                let (mut c, mut d) = ([0; LANES], [0; LANES]);
                c[..m].copy_from_slice(color);
                d[..depth.len()].copy_from_slice(depth);
                {
                    let $i0 = i0;
                    let $live: Lane<u32> = live_lanes(m);
                    let $color: &mut Lane<u32> = &mut c;
                    let $depth: Option<&mut Lane<u32>> = Some(&mut d);
                    $group;
                }
                color.copy_from_slice(&c[..m]);
                let n = depth.len();
                depth.copy_from_slice(&d[..n]);
            }
            i0 += m;
        }
    }};
}

/// The mask of the first `m` lanes.
#[inline(always)]
fn live_lanes(m: usize) -> Lane<u32> {
    let mut live = [0; LANES];
    for (j, l) in live.iter_mut().enumerate() {
        *l = 0u32.wrapping_sub((j < m) as u32);
    }
    live
}

/// The depth test of the `live` lanes of a group (when `DEPTH`), giving the lanes that
/// pass, or `None` when nothing is left to write: every lane failed, or the color mask
/// keeps every bit.
#[inline(always)]
fn group_pass<const DEPTH: bool>(
    k: &FragmentKey,
    interp: &SpanInterp,
    i0: usize,
    live: Lane<u32>,
    depth: Option<&mut Lane<u32>>,
) -> Option<Lane<u32>> {
    let mut pass = live;
    if DEPTH {
        let (func, df) = k.depth.expect("DEPTH routes have a depth test");
        let depth = depth.expect("DEPTH routes have a depth buffer");
        pass = depth_test(interp, func, df, k.depth_write, i0, live, depth);
        if pass == [0; LANES] {
            return None;
        }
    }
    (k.keep != u32::MAX).then_some(pass)
}

/// The stored words of a group's fragment colors `src`, blended over `color` when `BLEND`,
/// dithered by `thresholds` when given.
#[inline(always)]
fn shade_words<const BLEND: bool>(
    k: &FragmentKey,
    color: &Lane<u32>,
    src: &mut Channels,
    thresholds: Option<&Lane<f32>>,
) -> Lane<u32> {
    if BLEND {
        let b = k.blend.expect("BLEND routes blend");
        let mut dst: Channels = [[0.0; LANES]; 4];
        decode_lanes(k.color, color, &mut dst, k.perspective == Quality::Fastest);
        blend_lanes(&b, src, &mut dst);
        encode_lanes(k.color, &dst, thresholds)
    } else {
        encode_lanes(k.color, src, thresholds)
    }
}

/// The dither thresholds of every group of a span when the key dithers. Groups start
/// [`LANES`] pixels apart, a multiple of the matrix's period 4, so one lane serves them all.
#[inline(always)]
fn span_thresholds(k: &FragmentKey, span: Span) -> Option<Lane<f32>> {
    k.dither
        .then(|| THRESHOLDS[(span.y & 3) as usize][(span.x0 & 3) as usize])
}

/// `dither_threshold(x + j, y)` for lane j of a group at x, by y mod 4 and x mod 4: a
/// lookup per span instead of eight.
static THRESHOLDS: [[Lane<f32>; 4]; 4] = {
    let mut t = [[[0.0; LANES]; 4]; 4];
    let mut y = 0;
    while y < 4 {
        let mut x = 0;
        while x < 4 {
            let mut j = 0;
            while j < LANES {
                t[y][x][j] = (BAYER[y][(x + j) % 4] as f32 + 0.5) / 16.0;
                j += 1;
            }
            x += 1;
        }
        y += 1;
    }
    t
};

/// Writes `words` where the fragment passes, through the color mask.
#[inline(always)]
fn store(k: &FragmentKey, color: &mut Lane<u32>, pass: &Lane<u32>, words: &Lane<u32>) {
    for j in 0..LANES {
        let write = pass[j] & !k.keep;
        color[j] = (color[j] & !write) | (words[j] & write);
    }
}

/// Spans shorter than this run pixel by pixel: for fewer pixels one group of lanes, its
/// depths, colors and encoding computed for all [`LANES`], costs more. Measured (task-clock,
/// 1 thread, AVX2): 4 against the 6 used before, gears-300-565 174 → 164 ms for 400
/// frames, draws-10k-565 746 → 677 ms for 60; 3 and 2 were no better on gears.
const SHORT: usize = 4;

/// The span routine for keys without alpha test, stencil or logic op. Called once a span:
/// a loop over a primitive's spans around it, as [`textured`] has, measured slower on small
/// triangles (lit-vbo 16.5 → 17.4 ms, gears-300-565 0.54 → 0.56 ms), where there are one
/// or two spans a primitive.
#[cfg_attr(
    not(fuzzing),
    multiversion::multiversion(targets("x86_64+avx2", "x86_64+sse4.1"))
)]
pub(super) fn simple<const DEPTH: bool, const SMOOTH: bool, const BLEND: bool>(
    k: &FragmentKey,
    t: &Shading,
    span: Span,
    band: &mut BandMut<'_>,
) {
    // Points and lines carry a flat color and planes alike: the route says which is read.
    let interp = if SMOOTH {
        SpanInterp::new(t, span)
    } else {
        SpanInterp::depth_only(t, span)
    };
    let flat = t.flat.unwrap_or_default();
    // An unblended flat color stores the same words in every group of the span, dithered
    // or not (groups start a multiple of the dither period apart): encoded once here, where
    // every group and every short-span pixel would otherwise encode it again.
    let flat_words = (!SMOOTH && !BLEND).then(|| {
        let thresholds = span_thresholds(k, span);
        encode_lanes(k.color, &flat.map(|c| [c; LANES]), thresholds.as_ref())
    });
    if interp.len < SHORT {
        return simple_pixels::<DEPTH, SMOOTH, BLEND>(k, t, span, band, interp, flat_words);
    }
    // Only groups that encode a color of their own read the thresholds: looked up after
    // the short spans, which dither pixel by pixel, have gone.
    let thresholds = if flat_words.is_some() {
        None
    } else {
        span_thresholds(k, span)
    };
    let thresholds = thresholds.as_ref();
    let start = (span.y - band.y0) as usize * band.width + span.x0 as usize;
    let len = interp.len;
    let constant_blend = match k.blend {
        Some(b) if BLEND && !SMOOTH && len >= CONSTANT_BLEND_MIN => ConstantBlend::new(&b, flat),
        _ => None,
    };
    if let (false, Some(words)) = (DEPTH, flat_words) {
        // A fill of the span with the words' pattern, through the color mask.
        let keep = k.keep;
        for group in band.color[start..start + len].chunks_mut(LANES) {
            for (px, &word) in group.iter_mut().zip(&words) {
                *px = (*px & keep) | (word & !keep);
            }
        }
        return;
    }
    for_each_group!(DEPTH, band, start, len, |i0, live, color, depth| {
        simple_group::<DEPTH, SMOOTH, BLEND>(
            k,
            &interp,
            flat,
            flat_words.as_ref(),
            constant_blend.as_ref(),
            i0,
            live,
            color,
            depth,
            thresholds,
        )
    });
}

/// One group of [`simple`]: lanes beyond the span are computed and discarded by the caller.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn simple_group<const DEPTH: bool, const SMOOTH: bool, const BLEND: bool>(
    k: &FragmentKey,
    interp: &SpanInterp,
    flat: [f32; 4],
    flat_words: Option<&Lane<u32>>,
    constant_blend: Option<&ConstantBlend>,
    i0: usize,
    live: Lane<u32>,
    color: &mut Lane<u32>,
    depth: Option<&mut Lane<u32>>,
    thresholds: Option<&Lane<f32>>,
) {
    let Some(pass) = group_pass::<DEPTH>(k, interp, i0, live, depth) else {
        return;
    };
    if let Some(words) = flat_words {
        return store(k, color, &pass, words);
    }
    if let (true, Some(cb)) = (BLEND, constant_blend) {
        let mut dst: Channels = [[0.0; LANES]; 4];
        decode_lanes(k.color, color, &mut dst, k.perspective == Quality::Fastest);
        cb.apply(&mut dst);
        return store(k, color, &pass, &encode_lanes(k.color, &dst, thresholds));
    }
    // Measured: with a depth test in the same group the separate steps are faster.
    let fused = if SMOOTH && !BLEND && !DEPTH {
        smooth_words(interp, i0, k.color)
    } else {
        None
    };
    let words = match fused {
        Some(words) => words,
        None => {
            let mut src = if SMOOTH {
                colors(interp, i0)
            } else {
                flat.map(|c| [c; LANES])
            };
            shade_words::<BLEND>(k, color, &mut src, thresholds)
        }
    };
    store(k, color, &pass, &words);
}

/// [`simple`] one pixel at a time, for short spans (inlined, so it takes the caller's
/// instruction set).
#[inline(always)]
fn simple_pixels<const DEPTH: bool, const SMOOTH: bool, const BLEND: bool>(
    k: &FragmentKey,
    t: &Shading,
    span: Span,
    band: &mut BandMut<'_>,
    interp: SpanInterp,
    flat_words: Option<Lane<u32>>,
) {
    let row = (span.y - band.y0) as usize * band.width;
    let flat = t.flat.unwrap_or_default();
    let write_color = k.keep != u32::MAX;
    for (i, x) in (span.x0..span.x1).enumerate() {
        let at = row + x as usize;
        if DEPTH {
            let (func, df) = k.depth.expect("DEPTH routes have a depth test");
            let z = df.quantize(interp.z(i));
            if !func.test(z, band.depth[at]) {
                continue;
            }
            if k.depth_write {
                band.depth[at] = z;
            }
        }
        if !write_color {
            continue;
        }
        let dst = band.color[at];
        if let Some(words) = &flat_words {
            band.color[at] = (dst & k.keep) | (words[i % LANES] & !k.keep);
            continue;
        }
        let src = if SMOOTH { interp.color(i) } else { flat };
        let src = if BLEND {
            let b = k.blend.expect("BLEND routes blend");
            blend(&b, src, decode(k.color, dst))
        } else {
            src
        };
        let word = if k.dither {
            encode_dithered(k.color, src, x, span.y)
        } else {
            k.color.encode(src)
        };
        band.color[at] = (dst & k.keep) | (word & !k.keep);
    }
}

/// Texel-space coordinates below this magnitude take the vectorized floor and wrap; beyond
/// it (or NaN) a group samples pixel by pixel with the scalar sampler. 2²¹ keeps the
/// integer coordinates within ±2²¹, where [`wrap_npot`] is exact in f32.
const FAST_COORD: f32 = 2_097_152.0;

/// `floor(u)` as an integer and as a float for |u| < 2²², vectorizable: adding 1.5 · 2²³
/// rounds to an integer (to nearest), one step down corrects rounding up, and the integer
/// is the difference of the bits.
#[inline(always)]
fn floor_i32(u: f32) -> (i32, f32) {
    const M: f32 = 12_582_912.0;
    let r = (u + M) - M;
    let f = if r > u { r - 1.0 } else { r };
    (
        ((f + M).to_bits() as i32).wrapping_sub(M.to_bits() as i32),
        f,
    )
}

/// Texture coordinates (s, t) of the group at `i0`, as `UnitCoords::st` gives them, and the
/// reciprocal of q/w they were divided by (1 on affine spans, where nothing is divided).
#[inline(always)]
fn st_lanes(ts: &UnitCoords, i0: usize) -> (Lane<f32>, Lane<f32>, Lane<f32>) {
    let fi0 = i0 as f32;
    let (mut s, mut t, mut r) = ([0.0; LANES], [0.0; LANES], [1.0; LANES]);
    for j in 0..LANES {
        let fi = fi0 + INDEX_F32[j];
        s[j] = ts.s0 + ts.ds * fi;
        t[j] = ts.t0 + ts.dt * fi;
    }
    if !ts.affine {
        for j in 0..LANES {
            r[j] = 1.0 / (ts.q0 + ts.dq * (fi0 + INDEX_F32[j]));
            s[j] *= r[j];
            t[j] *= r[j];
        }
    }
    (s, t, r)
}

/// Wrapped texel indices of integer coordinates (`Wrap::index`, one decision per group:
/// `wrap` and `n` are the same for every lane, so each arm's loop vectorizes). |i| ≤ 2²¹.
#[inline(always)]
fn wrap_lanes(wrap: Wrap, i: &mut Lane<i32>, n: i32) {
    if wraps_by_mask(wrap, n) {
        wrap_pot(wrap, i, n);
    } else {
        wrap_npot(wrap, i, None, n);
    }
}

/// [`wrap_lanes`] of `i` and of its right or lower neighbours `i + 1`, into `next`.
#[inline(always)]
fn wrap_pair_lanes(wrap: Wrap, i: &mut Lane<i32>, next: &mut Lane<i32>, n: i32) {
    if wraps_by_mask(wrap, n) {
        for j in 0..LANES {
            next[j] = i[j] + 1;
        }
        wrap_pot(wrap, i, n);
        wrap_pot(wrap, next, n);
    } else {
        wrap_npot(wrap, i, Some(next), n);
    }
}

/// Whether [`wrap_pot`] wraps size `n` (a power of two, or any size under CLAMP_TO_EDGE);
/// otherwise [`wrap_npot`] does.
#[inline(always)]
fn wraps_by_mask(wrap: Wrap, n: i32) -> bool {
    n & (n - 1) == 0 || wrap == Wrap::ClampToEdge
}

/// [`wrap_lanes`] for `n` a power of two, or under CLAMP_TO_EDGE (which clamps alike at
/// every size).
#[inline(always)]
fn wrap_pot(wrap: Wrap, i: &mut Lane<i32>, n: i32) {
    use Wrap::*;
    let lanes = i.iter_mut();
    match wrap {
        Repeat => lanes.for_each(|i| *i = Repeat.index_pot(*i, n)),
        ClampToEdge => lanes.for_each(|i| *i = ClampToEdge.index_pot(*i, n)),
        MirroredRepeat => lanes.for_each(|i| *i = MirroredRepeat.index_pot(*i, n)),
    }
}

/// [`wrap_lanes`] (and [`wrap_pair_lanes`] with `next`) under REPEAT or MIRRORED_REPEAT
/// for `n` not a power of two.
///
/// The remainder m of i modulo the period p (n, or 2n mirrored) comes from an f32 quotient,
/// eight lanes to a register where `Wrap::index_npot`'s f64 takes two and conversions: for
/// |i| ≤ 2²¹, i + ½ is exact in f32, (i + ½)/p lies at least 1/(2p) from every integer, and
/// the computed product (i + ½)·fl(1/p) is within (2²¹ + ½)/p · 2⁻²³ · (1 + 2⁻²⁴) < 1/(2p)
/// of it, so its floor is ⌊i/p⌋. The neighbour's remainder is m + 1, or 0 at the end of
/// the period, so it needs no second quotient; mirroring reflects both.
#[inline(always)]
fn wrap_npot(wrap: Wrap, i: &mut Lane<i32>, next: Option<&mut Lane<i32>>, n: i32) {
    let p = if wrap == Wrap::MirroredRepeat {
        2 * n
    } else {
        n
    };
    let inv = 1.0 / p as f32;
    let mut m = [0; LANES];
    for j in 0..LANES {
        let (q, _) = floor_i32((i[j] as f32 + 0.5) * inv);
        m[j] = i[j] - q * p;
    }
    // Under REPEAT every remainder is below n and the reflection changes nothing.
    let reflect = |m: i32| if m >= n { p - 1 - m } else { m };
    if let Some(next) = next {
        for j in 0..LANES {
            next[j] = reflect(if m[j] + 1 == p { 0 } else { m[j] + 1 });
        }
    }
    for j in 0..LANES {
        i[j] = reflect(m[j]);
    }
}

/// How a level's rows are addressed: by a shift where the width is a power of two (SSE2
/// has no 32-bit vector multiply), else by multiplying with the width (`OES_texture_npot`).
#[derive(Clone, Copy)]
enum Rows {
    Shift(u32),
    Width(i32),
}

impl Rows {
    fn of(width: u32) -> Rows {
        if width.is_power_of_two() {
            Rows::Shift(width.trailing_zeros())
        } else {
            Rows::Width(width as i32)
        }
    }

    /// The slice indices of wrapped (x, y).
    #[inline(always)]
    fn indices(self, x: &Lane<i32>, y: &Lane<i32>) -> Lane<usize> {
        let mut k = [0; LANES];
        match self {
            Rows::Shift(shift) => {
                for j in 0..LANES {
                    k[j] = (y[j] << shift | x[j]) as u32 as usize;
                }
            }
            Rows::Width(w) => {
                for j in 0..LANES {
                    k[j] = (y[j] * w + x[j]) as u32 as usize;
                }
            }
        }
        k
    }
}

/// The texel words at wrapped (x, y) of a level with at least one texel.
#[inline(always)]
fn fetch(texels: &[u32], rows: Rows, x: &Lane<i32>, y: &Lane<i32>) -> Lane<u32> {
    // Wrapped coordinates are inside the level; clamping to the slice's last index lets
    // the compiler drop the per-lane bounds check.
    let last = texels.len() - 1;
    let k = rows.indices(x, y);
    let mut words = [0; LANES];
    for j in 0..LANES {
        words[j] = texels[k[j].min(last)];
    }
    words
}

/// The texel words at wrapped (x, y) and (x + 1, y) of a level of at least two texels, for
/// lanes whose x + 1 does not wrap: one 8-byte load per lane where the compiler merges the
/// two adjacent reads.
#[inline(always)]
fn fetch_pairs(texels: &[u32], rows: Rows, x: &Lane<i32>, y: &Lane<i32>) -> (Lane<u32>, Lane<u32>) {
    // As in `fetch`, the clamp only lets the compiler drop the bounds checks.
    let last = texels.len() - 2;
    let ks = rows.indices(x, y);
    let (mut left, mut right) = ([0; LANES], [0; LANES]);
    for j in 0..LANES {
        let k = ks[j].min(last);
        let pair = u64::from(texels[k]) | u64::from(texels[k + 1]) << 32;
        left[j] = pair as u32;
        right[j] = (pair >> 32) as u32;
    }
    (left, right)
}

/// 4, the channels of a texel, as a value the optimizer cannot see. Unpacking and
/// filtering loop over the channels; unrolled (which a known count of 4 invites), the four
/// channels of one pixel look alike and the vectorizer packs them into one vector, pixel
/// by pixel, instead of packing the group's pixels channel by channel: measured 2× the
/// instructions.
#[inline(always)]
fn channel_count() -> usize {
    std::hint::black_box(4)
}

/// Channel `c` of texel words, in 0 ..= 255.
#[inline(always)]
fn unpack(words: &Lane<u32>, c: usize) -> Lane<f32> {
    let mut out = [0.0; LANES];
    for j in 0..LANES {
        out[j] = ((words[j] >> (8 * c)) & 0xFF) as i32 as f32;
    }
    out
}

/// NEAREST or LINEAR samples of a group from `level` (`Sampler::nearest` and
/// `Sampler::bilinear` exactly, in 0 ..= 255) times `scale`, or `false` when a coordinate is
/// out of the fast range.
#[inline(always)]
fn sample_level(
    sm: &Sampler,
    level: usize,
    linear: bool,
    scale: f32,
    s: &Lane<f32>,
    t: &Lane<f32>,
    out: &mut Channels,
) -> bool {
    let img = &*sm.levels[level];
    let (w, h) = (img.width as f32, img.height as f32);
    let off = if linear { 0.5 } else { 0.0 };
    let (mut u, mut v) = ([0.0f32; LANES], [0.0f32; LANES]);
    for j in 0..LANES {
        u[j] = s[j] * w - off;
        v[j] = t[j] * h - off;
    }
    if !every(&u, |u| u.abs() < FAST_COORD) || !every(&v, |v| v.abs() < FAST_COORD) {
        return false;
    }
    let (mut i, mut jj) = ([0i32; LANES], [0i32; LANES]);
    let (mut a, mut b) = ([0.0f32; LANES], [0.0f32; LANES]);
    for j in 0..LANES {
        let (fi, fu) = floor_i32(u[j]);
        let (fj, fv) = floor_i32(v[j]);
        i[j] = fi;
        jj[j] = fj;
        a[j] = u[j] - fu;
        b[j] = v[j] - fv;
    }
    // A complete texture has no empty level; an empty one samples as zero rather than
    // panicking.
    let (texels, rows) = (&img.texels[..], Rows::of(img.width));
    if texels.is_empty() {
        *out = [[0.0; LANES]; 4];
        return true;
    }
    let (wi, hi) = (img.width as i32, img.height as i32);
    // A weight of exactly 0 makes the lerp return its first operand bit for bit (x + d·0 is
    // x for texel values), so the texels it would blend in need not be fetched. Texels
    // mapped 1:1 onto pixels (sprites, 2D blits, UI) sample texel centers: one fetch of four,
    // as NEAREST.
    let (flat_s, flat_t) = (every(&a, |a| a == 0.0), every(&b, |b| b == 0.0));
    if !linear || (flat_s && flat_t) {
        wrap_lanes(sm.wrap_s, &mut i, wi);
        wrap_lanes(sm.wrap_t, &mut jj, hi);
        let words = fetch(texels, rows, &i, &jj);
        for (c, out) in out.iter_mut().enumerate().take(channel_count()) {
            *out = scaled(unpack(&words, c), scale);
        }
        return true;
    }
    let (mut i1, mut j1) = ([0; LANES], [0; LANES]);
    wrap_pair_lanes(sm.wrap_s, &mut i, &mut i1, wi);
    wrap_pair_lanes(sm.wrap_t, &mut jj, &mut j1, hi);
    // Where no lane's right neighbour wraps around, the two texels of a row are adjacent
    // and come as one pair (half the loads).
    let mut adjacent = texels.len() >= 2;
    for j in 0..LANES {
        adjacent &= i1[j] == i[j].wrapping_add(1);
    }
    let (w00, w10, w01, w11) = if adjacent && !flat_s && !flat_t {
        let (w00, w10) = fetch_pairs(texels, rows, &i, &jj);
        let (w01, w11) = fetch_pairs(texels, rows, &i, &j1);
        (w00, w10, w01, w11)
    } else {
        let w00 = fetch(texels, rows, &i, &jj);
        let w10 = if flat_s {
            w00
        } else {
            fetch(texels, rows, &i1, &jj)
        };
        let (w01, w11) = if flat_t {
            (w00, w10)
        } else if flat_s {
            let w01 = fetch(texels, rows, &i, &j1);
            (w01, w01)
        } else {
            (fetch(texels, rows, &i, &j1), fetch(texels, rows, &i1, &j1))
        };
        (w00, w10, w01, w11)
    };
    for (c, out) in out.iter_mut().enumerate().take(channel_count()) {
        let top = lerp_lanes(&unpack(&w00, c), &unpack(&w10, c), &a);
        let bottom = lerp_lanes(&unpack(&w01, c), &unpack(&w11, c), &a);
        *out = scaled(lerp_lanes(&top, &bottom, &b), scale);
    }
    true
}

/// Whether `f` holds for every lane, testing them all (a short-circuit test splits the
/// group into lanes).
#[inline(always)]
fn every(lanes: &[f32], f: impl Fn(f32) -> bool) -> bool {
    lanes.iter().fold(true, |all, &l| all & f(l))
}

/// `v · scale` per lane. (A loop: `map`'s closure is not always inlined, and then it
/// runs without the routine's instruction set.)
#[inline(always)]
fn scaled(mut v: Lane<f32>, scale: f32) -> Lane<f32> {
    for v in v.iter_mut() {
        *v *= scale;
    }
    v
}

/// `x + (y − x)·t` per lane.
#[inline(always)]
fn lerp_lanes(x: &Lane<f32>, y: &Lane<f32>, t: &Lane<f32>) -> Lane<f32> {
    let mut out = [0.0; LANES];
    for j in 0..LANES {
        out[j] = x[j] + (y[j] - x[j]) * t[j];
    }
    out
}

/// λ of a unit's coordinates `ts` for the group (`UnitCoords::lambda` of each lane): ρ²
/// and the logarithm as vectors.
#[inline(always)]
fn lambda_lanes(ts: &UnitCoords, s: &Lane<f32>, t: &Lane<f32>, r: &Lane<f32>) -> Lane<f32> {
    let mut out = [0.0; LANES];
    let mut rho2 = [0.0f32; LANES];
    for j in 0..LANES {
        // UnitCoords::lambda, written out (on affine spans r is 1, which changes no bit).
        let r = r[j];
        let ux = (ts.ds - s[j] * ts.dq) * r * ts.w;
        let vx = (ts.dt - t[j] * ts.dq) * r * ts.h;
        let uy = (ts.sy - s[j] * ts.qy) * r * ts.w;
        let vy = (ts.ty - t[j] * ts.qy) * r * ts.h;
        rho2[j] = (ux * ux + vx * vx).max(uy * uy + vy * vy);
    }
    if every(&rho2, |r| r == rho2[0]) {
        out = [Sampler::lambda(rho2[0]); LANES];
    } else {
        for j in 0..LANES {
            out[j] = Sampler::lambda(rho2[j]);
        }
    }
    out
}

/// A filter pair that depends on λ (`Sampler::sample_255`, scaled to 0 ..= 1) over a group
/// whose lanes all magnify, or all minify from the same level (or pair of levels), or for
/// `TRI` partly magnify; `false` otherwise. `TRI`: the pair is LINEAR_MIPMAP_LINEAR and
/// LINEAR (the code for the other pairs left out).
#[inline(always)]
fn mipmap_lanes<const TRI: bool>(
    sm: &Sampler,
    ts: &UnitCoords,
    s: &Lane<f32>,
    t: &Lane<f32>,
    r: &Lane<f32>,
    out: &mut Channels,
) -> bool {
    // Every lane, those past the span's end included (their λ is extrapolated), so that
    // the tests vectorize.
    let mut lambda = lambda_lanes(ts, s, t, r);
    for l in lambda.iter_mut() {
        *l += sm.lod_bias;
    }
    if every(&lambda, |l| l.is_nan() || l <= sm.c) {
        let linear = TRI || sm.mag == MagFilter::Linear;
        return sample_level(sm, 0, linear, INV_255, s, t, out);
    }
    if !every(&lambda, |l| l > sm.c) {
        // A group across the edge of magnification (a ring in a tunnel, a line across a
        // floor). Under LINEAR magnification and c = 0 a magnified lane samples level 0
        // bilinearly, which is the trilinear blend at λ = 0: level 0 plus a weight of 0
        // times the step to level 1, bit for bit (x + (y − x)·0 is x for texel values).
        if !TRI || sm.c != 0.0 {
            return false;
        }
        for l in lambda.iter_mut() {
            if l.is_nan() || *l <= 0.0 {
                *l = 0.0;
            }
        }
    }
    let q = sm.levels.len() - 1;
    let qf = q as f32;
    let min = if TRI {
        MinFilter::LinearMipmapLinear
    } else {
        sm.min
    };
    match min {
        MinFilter::Nearest => sample_level(sm, 0, false, INV_255, s, t, out),
        MinFilter::Linear => sample_level(sm, 0, true, INV_255, s, t, out),
        MinFilter::NearestMipmapNearest | MinFilter::LinearMipmapNearest => {
            // The level of λ: 0 up to 0.5, else ⌈λ + ½⌉ − 1, at most q.
            let mut d = [0.0; LANES];
            for j in 0..LANES {
                let l = lambda[j];
                d[j] = if l <= 0.5 {
                    0.0
                } else {
                    ((l + 0.5).ceil() - 1.0).min(qf)
                };
            }
            if !every(&d, |v| v == d[0]) {
                return false;
            }
            let linear = sm.min == MinFilter::LinearMipmapNearest;
            sample_level(sm, d[0] as usize, linear, INV_255, s, t, out)
        }
        MinFilter::NearestMipmapLinear | MinFilter::LinearMipmapLinear => {
            let linear = min == MinFilter::LinearMipmapLinear;
            if every(&lambda, |l| l >= qf) {
                return sample_level(sm, q, linear, INV_255, s, t, out);
            }
            // The lanes' first levels d1 = ⌊λ⌋: one level for the whole group, or two
            // neighbouring ones where the group crosses a level boundary (a tunnel or a
            // floor does that on every row); then a third level is sampled and each lane
            // blends its own pair.
            let mut floor = [0.0f32; LANES];
            for j in 0..LANES {
                floor[j] = lambda[j].floor();
            }
            let lo = floor.iter().fold(f32::INFINITY, |m, &d| m.min(d));
            let hi = floor.iter().fold(f32::NEG_INFINITY, |m, &d| m.max(d));
            if !(every(&lambda, |l| l < qf) && hi - lo <= 1.0) {
                return false;
            }
            let d1 = lo as usize;
            let mut b: Channels = [[0.0; LANES]; 4];
            if !sample_level(sm, d1, linear, 1.0, s, t, out)
                || !sample_level(sm, d1 + 1, linear, 1.0, s, t, &mut b)
            {
                return false;
            }
            if hi > lo {
                // Lanes on the upper pair blend level d1 + 1 into d1 + 2 (which exists:
                // their λ < q).
                let mut c2: Channels = [[0.0; LANES]; 4];
                if !sample_level(sm, d1 + 2, linear, 1.0, s, t, &mut c2) {
                    return false;
                }
                for c in 0..4 {
                    for j in 0..LANES {
                        let upper = floor[j] > lo;
                        out[c][j] = if upper { b[c][j] } else { out[c][j] };
                        b[c][j] = if upper { c2[c][j] } else { b[c][j] };
                    }
                }
            }
            for c in 0..4 {
                for j in 0..LANES {
                    let f = lambda[j] - floor[j];
                    out[c][j] = (out[c][j] + (b[c][j] - out[c][j]) * f) * INV_255;
                }
            }
            true
        }
    }
}

/// The texture environment over a group (`texenv::apply`; `primary` `None` means the
/// previous color):
/// REPLACE and MODULATE vectorized, the other modes pixel by pixel.
#[inline(always)]
fn texenv_lanes(
    env: &TexEnv,
    format: BaseFormat,
    tex: &Channels,
    c: &mut Channels,
    primary: Option<&Channels>,
) {
    let (has_color, has_alpha) = (format.has_color(), format.has_alpha());
    match env.mode {
        EnvMode::Replace => {
            if has_color {
                c[..3].copy_from_slice(&tex[..3]);
            }
            if has_alpha {
                c[3] = tex[3];
            }
        }
        EnvMode::Modulate => {
            if has_color {
                for k in 0..3 {
                    for j in 0..LANES {
                        c[k][j] = (c[k][j] * tex[k][j]).clamp(0.0, 1.0);
                    }
                }
            }
            if has_alpha {
                for j in 0..LANES {
                    c[3][j] *= tex[3][j];
                }
            }
        }
        EnvMode::Combine(k) if !k.is_dot3() => {
            let prev = *c;
            combine_lanes(&k, env.color, tex, &prev, primary.unwrap_or(&prev), c)
        }
        _ => texenv_by_pixel(env, format, tex, c, primary),
    }
}

/// COMBINE without the DOT3 functions over a group (`texenv::combine` exactly), into `out`.
#[inline(always)]
fn combine_lanes(
    k: &Combine,
    constant: [f32; 4],
    tex: &Channels,
    prev: &Channels,
    primary: &Channels,
    out: &mut Channels,
) {
    let mut lanes: Channels = [[0.0; LANES]; 4];
    for (l, v) in lanes.iter_mut().zip(constant) {
        *l = [v; LANES];
    }
    let constant = lanes;
    let src = |s: Source| match s {
        Source::Texture => tex,
        Source::Constant => &constant,
        Source::PrimaryColor => primary,
        Source::Previous => prev,
        // Crossbar environments take the general route (`FragmentKey::new`).
        Source::Unit(_) => unreachable!("crossbar environment on the 8-wide route"),
    };
    // Argument `n` of channel `ch` (3: alpha), as `texenv::combine`'s arguments give it.
    let arg = |n: usize, ch: usize| -> Lane<f32> {
        let (source, operand) = if ch < 3 {
            (k.src_rgb[n], k.operand_rgb[n])
        } else {
            (k.src_alpha[n], k.operand_alpha[n])
        };
        let c = src(source);
        let (from, invert) = match operand {
            Operand::SrcColor => (ch, false),
            Operand::OneMinusSrcColor => (ch, true),
            Operand::SrcAlpha => (3, false),
            Operand::OneMinusSrcAlpha => (3, true),
        };
        let mut v = c[from];
        if invert {
            for v in v.iter_mut() {
                *v = 1.0 - *v;
            }
        }
        v
    };
    for ch in 0..4 {
        let (f, scale) = if ch < 3 {
            (k.rgb, k.rgb_scale)
        } else {
            (k.alpha, k.alpha_scale)
        };
        let a = arg(0, ch);
        let mut o = [0.0; LANES];
        match f {
            CombineFunc::Replace => o = a,
            CombineFunc::Interpolate => {
                let (b, c) = (arg(1, ch), arg(2, ch));
                for j in 0..LANES {
                    o[j] = a[j] * c[j] + b[j] * (1.0 - c[j]);
                }
            }
            _ => {
                let b = arg(1, ch);
                for j in 0..LANES {
                    o[j] = match f {
                        CombineFunc::Modulate => a[j] * b[j],
                        CombineFunc::Add => a[j] + b[j],
                        CombineFunc::AddSigned => a[j] + b[j] - 0.5,
                        CombineFunc::Subtract => a[j] - b[j],
                        _ => 0.0,
                    };
                }
            }
        }
        for j in 0..LANES {
            out[ch][j] = (o[j] * scale).clamp(0.0, 1.0);
        }
    }
}

/// [`texenv_lanes`] for the modes it does not vectorize. Out of line, like
/// [`texels_by_pixel`], for the same reason.
#[inline(never)]
fn texenv_by_pixel(
    env: &TexEnv,
    format: BaseFormat,
    tex: &Channels,
    c: &mut Channels,
    primary: Option<&Channels>,
) {
    for j in 0..LANES {
        let at = |v: &Channels| [v[0][j], v[1][j], v[2][j], v[3][j]];
        let prev = at(c);
        let out = texenv::apply(env, format, at(tex), prev, primary.map_or(prev, at));
        for k in 0..4 {
            c[k][j] = out[k];
        }
    }
}

/// Fog over a group (`SpanTexturing::fog`).
#[inline(always)]
fn fog_lanes(tex: &SpanTexturing, f: &Fog, i0: usize, c: &mut Channels) {
    let fi0 = i0 as f32;
    let mut factor = [0.0f32; LANES];
    for (j, factor) in factor.iter_mut().enumerate() {
        let fi = fi0 + INDEX_F32[j];
        *factor = (tex.fog0 + tex.dfog * fi) / (tex.inv_w0 + tex.d_inv_w * fi);
    }
    let d = f.end - f.start;
    if !f.per_pixel() {
        factor.iter_mut().for_each(|v| *v = v.clamp(0.0, 1.0));
    } else if f.mode == FogMode::Linear && d != 0.0 {
        for v in factor.iter_mut() {
            let g = (f.end - *v) / d;
            *v = if g.is_nan() { 0.0 } else { g.clamp(0.0, 1.0) };
        }
    } else {
        factor.iter_mut().for_each(|v| *v = f.factor(*v));
    }
    for k in 0..3 {
        let fog = f.color[k];
        for j in 0..LANES {
            c[k][j] = fog + (c[k][j] - fog) * factor[j];
        }
    }
}

/// The texels of unit `n` for the group at `i0` (of a span of `len` pixels), in 0 ..= 1,
/// sampled with `filter` (the unit's `F_*` class).
#[inline(always)]
fn unit_texels(
    tex: &mut SpanTexturing,
    len: usize,
    sm: &Sampler,
    filter: u8,
    n: usize,
    i0: usize,
) -> Channels {
    let (s, tt, r) = st_lanes(&tex.spans[n], i0);
    let mut texel: Channels = [[0.0; LANES]; 4];
    let fast = match filter {
        F_NEAREST => sample_level(sm, 0, false, INV_255, &s, &tt, &mut texel),
        F_BILINEAR => sample_level(sm, 0, true, INV_255, &s, &tt, &mut texel),
        F_TRILINEAR => mipmap_lanes::<true>(sm, &tex.spans[n], &s, &tt, &r, &mut texel),
        F_LOD => mipmap_lanes::<false>(sm, &tex.spans[n], &s, &tt, &r, &mut texel),
        _ => false,
    };
    if !fast {
        texels_by_pixel(tex, len, sm, filter, n, i0, &s, &tt, &mut texel);
    }
    texel
}

/// The scalar sampler over a group (scaled to 0 ..= 1), for what the vectorized one does
/// not take. Out of
/// line: inlined, its pixel-major writes lead the vectorizer to transpose the fast path's
/// channel arrays.
#[inline(never)]
#[allow(clippy::too_many_arguments)]
fn texels_by_pixel(
    tex: &mut SpanTexturing,
    len: usize,
    sm: &Sampler,
    filter: u8,
    n: usize,
    i0: usize,
    s: &Lane<f32>,
    tt: &Lane<f32>,
    texel: &mut Channels,
) {
    for j in 0..LANES.min(len - i0) {
        let (i, s, tt) = (i0 + j, s[j], tt[j]);
        let v = match filter {
            F_NEAREST => sm.nearest(0, s, tt),
            F_BILINEAR => sm.bilinear(0, s, tt),
            _ => sm.sample_255(s, tt, tex.spans[n].lambda(i, s, tt)),
        };
        for ch in 0..4 {
            texel[ch][j] = v[ch] * INV_255;
        }
    }
}

/// The span routine for textured or fogged keys without cube maps, alpha test, stencil or
/// logic op: every unit in order, then fog. The depth test runs before texturing,
/// which gives the same result (ES 1.1 §3.7: nothing between them can discard a fragment
/// here) and skips the sampling of hidden fragments.
#[cfg_attr(
    not(fuzzing),
    multiversion::multiversion(targets("x86_64+avx2", "x86_64+sse4.1"))
)]
pub(super) fn textured<const F: u8, const DEPTH: bool, const BLEND: bool>(
    k: &FragmentKey,
    t: &Shading,
    spans: &[Span],
    band: &mut BandMut<'_>,
) {
    for &span in spans {
        textured_span::<F, DEPTH, BLEND>(k, t, span, band);
    }
}

/// One span of [`textured`].
#[inline(always)]
fn textured_span<const F: u8, const DEPTH: bool, const BLEND: bool>(
    k: &FragmentKey,
    t: &Shading,
    span: Span,
    band: &mut BandMut<'_>,
) {
    let stage = k.tex.as_deref().expect("textured routes have a stage");
    let interp = SpanInterp::new(t, span);
    let mut tex = SpanTexturing::new(stage, t, span);
    let start = (span.y - band.y0) as usize * band.width + span.x0 as usize;
    let len = interp.len;
    let thresholds = span_thresholds(k, span);
    let thresholds = thresholds.as_ref();
    for_each_group!(DEPTH, band, start, len, |i0, live, color, depth| {
        textured_group::<F, DEPTH, BLEND>(
            k, t, &interp, &mut tex, i0, live, color, depth, thresholds,
        )
    });
}

/// One group of [`textured_span`]; lanes beyond the span are computed and discarded by the
/// caller (their coordinates are extrapolated, so they may take the scalar sampler). `F`
/// is the route's filter class: `F_NONE` (fog only), the filter of a single unit (a
/// straight path for it alone, which the compiler can keep in registers), or `F_MULTI`.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn textured_group<const F: u8, const DEPTH: bool, const BLEND: bool>(
    k: &FragmentKey,
    t: &Shading,
    interp: &SpanInterp,
    tex: &mut SpanTexturing,
    i0: usize,
    live: Lane<u32>,
    color: &mut Lane<u32>,
    depth: Option<&mut Lane<u32>>,
    thresholds: Option<&Lane<f32>>,
) {
    let Some(pass) = group_pass::<DEPTH>(k, interp, i0, live, depth) else {
        return;
    };
    let mut c: Channels = match t.flat {
        Some(f) => f.map(|v| [v; LANES]),
        None => colors(interp, i0),
    };
    // Without planes (cannot happen for primitives set up with this state) texturing is off.
    if F != F_NONE && t.tex.is_some() {
        let stage = tex.stage;
        if F != F_MULTI {
            let (_, u) = &stage.units[0];
            let texel = unit_texels(tex, interp.len, &u.sampler, F, 0, i0);
            texenv_lanes(&u.env, u.sampler.format, &texel, &mut c, None);
        } else {
            // The untextured color, read by COMBINE past the first unit (on the first it is
            // the previous color).
            let primary = (stage.units.len() > 1).then_some(c);
            for (n, (_, u)) in stage.units.iter().enumerate() {
                let sm = &*u.sampler;
                let texel = unit_texels(tex, interp.len, sm, filter_of(sm), n, i0);
                let primary = primary.as_ref().filter(|_| n > 0);
                texenv_lanes(&u.env, sm.format, &texel, &mut c, primary);
            }
        }
    }
    if let Some(f) = &tex.stage.fog {
        fog_lanes(tex, f, i0, &mut c);
    }
    let words = shade_words::<BLEND>(k, color, &mut c, thresholds);
    store(k, color, &pass, &words);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every pair of blend factors with the ADD equation (so the functions `add_blend`
    /// writes out and the general loop alike), and every equation with one factor pair,
    /// lane by lane against the per-pixel `blend`, to the bit.
    #[test]
    fn blend_lanes_match_the_per_pixel_blend() {
        use BlendFactor::*;
        const FACTORS: [BlendFactor; 11] = [
            Zero,
            One,
            SrcColor,
            OneMinusSrcColor,
            DstColor,
            OneMinusDstColor,
            SrcAlpha,
            OneMinusSrcAlpha,
            DstAlpha,
            OneMinusDstAlpha,
            SrcAlphaSaturate,
        ];
        let values = [0.0, 1.0, 0.3, 0.71, -0.5, 1.7, 0.5, 0.999, 0.001, 0.25];
        let lane = |at: usize| -> Channels {
            std::array::from_fn(|c| std::array::from_fn(|j| values[(at + 3 * c + j) % 10]))
        };
        let mut blends = Vec::new();
        for &src in &FACTORS {
            for &dst in &FACTORS {
                blends.push(Blend::func(src, dst));
            }
        }
        for eq in [
            BlendEquation::Subtract,
            BlendEquation::ReverseSubtract,
            BlendEquation::Min,
            BlendEquation::Max,
        ] {
            blends.push(Blend {
                eq_rgb: eq,
                eq_alpha: eq,
                ..Blend::func(SrcAlpha, OneMinusSrcAlpha)
            });
        }
        blends.push(Blend {
            src_alpha: One,
            ..Blend::func(SrcAlpha, OneMinusSrcAlpha)
        });
        blends.push(Blend {
            eq_rgb: BlendEquation::ReverseSubtract,
            eq_alpha: BlendEquation::Subtract,
            ..Blend::func(OneMinusSrcColor, SrcAlpha)
        });
        let mut constant = 0;
        for b in &blends {
            for at in 0..10 {
                let (mut src, mut dst) = (lane(at), lane(at + 4));
                let (src0, dst0) = (src, dst);
                blend_lanes(b, &mut src, &mut dst);
                // The same source at every lane, blended as a span of one flat color.
                let flat: [f32; 4] = std::array::from_fn(|c| src0[c][0]);
                let mut over = dst0;
                let cb = ConstantBlend::new(b, flat);
                if let Some(cb) = &cb {
                    cb.apply(&mut over);
                    constant += 1;
                }
                for j in 0..LANES {
                    let d = std::array::from_fn(|c| dst0[c][j]);
                    let want = blend(b, std::array::from_fn(|c| src0[c][j]), d);
                    let want_flat = blend(b, flat, d);
                    for c in 0..4 {
                        assert_eq!(dst[c][j].to_bits(), want[c].to_bits(), "{b:?} lane {j}");
                        if cb.is_some() {
                            let got = over[c][j].to_bits();
                            assert_eq!(got, want_flat[c].to_bits(), "{b:?} flat, lane {j}");
                        }
                    }
                }
            }
        }
        // The blends that read no destination, at 10 sources each: 6 × 6 factor pairs,
        // SUBTRACT, REVERSE_SUBTRACT, another alpha factor, different equations.
        assert_eq!(constant, (36 + 4) * 10);
    }

    /// Wrapped indices of a group and of its neighbours, at every size up to 300 and some
    /// large ones, with coordinates next to multiples of the period, near zero and at the
    /// ends of the fast range (±2²¹), against `Wrap::index`.
    #[test]
    fn wrapped_lanes_and_neighbours_match_the_scalar_wrap() {
        const EDGE: i32 = 1 << 21;
        let sizes = (1..=300).chain([1023, 1024, 2047, 2048, 4095, 4096, 8191]);
        for n in sizes {
            for wrap in [Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat] {
                let mut coords = vec![-EDGE, -EDGE + 1, EDGE - 2, EDGE - 1];
                for k in [
                    -EDGE / (2 * n),
                    -3,
                    -2,
                    -1,
                    0,
                    1,
                    2,
                    3,
                    (EDGE - 1) / (2 * n),
                ] {
                    for d in -2..=2 {
                        coords.push(k * n + d);
                        coords.push(k * 2 * n + d);
                    }
                }
                coords.retain(|&i| (-EDGE..EDGE).contains(&i));
                for group in coords.chunks(LANES) {
                    let mut i = [0; LANES];
                    i[..group.len()].copy_from_slice(group);
                    let (mut got, mut next) = (i, [0; LANES]);
                    wrap_pair_lanes(wrap, &mut got, &mut next, n);
                    let mut alone = i;
                    wrap_lanes(wrap, &mut alone, n);
                    for j in 0..LANES {
                        let what = format!("{wrap:?} {} mod {n}", i[j]);
                        assert_eq!(got[j], wrap.index(i[j], n), "{what}");
                        assert_eq!(alone[j], got[j], "{what}, alone");
                        assert_eq!(next[j], wrap.index(i[j] + 1, n), "{what}, next");
                    }
                }
            }
        }
    }

    /// Inputs around every rounding and dithering boundary of the narrow formats, plus values
    /// outside [0, 1], signed zeros and NaN, against the per-pixel encoders and decoder.
    #[test]
    fn narrow_lanes_encode_and_decode_as_the_per_pixel_code() {
        let mut values = vec![f32::NAN, -0.0, 0.0, -1.0, 1.0, 1.5, f32::INFINITY, 1e-30];
        for max in [1.0f32, 15.0, 31.0, 63.0] {
            for k in 0..=(max as i32 * 16) {
                let v = k as f32 / (16.0 * max);
                values.extend([v, v.next_up(), v.next_down()]);
            }
        }
        for format in [
            ColorFormat::Rgb565,
            ColorFormat::Rgba4444,
            ColorFormat::Rgba5551,
            ColorFormat::Rgba8888,
            ColorFormat::Rgb888,
        ] {
            for (g, chunk) in values.chunks(LANES).enumerate() {
                let mut c: Channels = [[0.0; LANES]; 4];
                for (j, &v) in chunk.iter().enumerate() {
                    // Each channel sees every value, at another lane.
                    for ch in 0..4 {
                        c[ch][(j + ch) % LANES] = v;
                    }
                }
                let words = encode_lanes(format, &c, None);
                let (x0, y) = (g as i32 % 4, g as i32 / 4);
                let t: Lane<f32> = std::array::from_fn(|j| dither_threshold(x0 + j as i32, y));
                let dithered = encode_lanes(format, &c, Some(&t));
                let mut back: Channels = [[0.0; LANES]; 4];
                decode_lanes(format, &words, &mut back, false);
                for j in 0..LANES {
                    let px = [c[0][j], c[1][j], c[2][j], c[3][j]];
                    assert_eq!(words[j], format.encode(px), "{format:?} {px:?}");
                    if format != ColorFormat::Rgba8888 && format != ColorFormat::Rgb888 {
                        let want = encode_dithered(format, px, x0 + j as i32, y);
                        assert_eq!(dithered[j], want, "{format:?} dithered {px:?}");
                    }
                    let want = decode(format, words[j]);
                    for ch in 0..4 {
                        assert_eq!(back[ch][j].to_bits(), want[ch].to_bits(), "{format:?}");
                    }
                }
            }
        }
    }

    /// The FASTEST decode reads every stored narrow value back within 1 ulp of the exact
    /// one, and re-encodes it to the same word: a pixel blended with nothing changes not.
    #[test]
    fn fast_decode_stays_within_an_ulp_and_round_trips() {
        for format in [
            ColorFormat::Rgb565,
            ColorFormat::Rgba4444,
            ColorFormat::Rgba5551,
        ] {
            let words: Vec<u32> = (0..=0xFFFFu32)
                .map(|v| format.encode(decode(format, v.wrapping_mul(0x9E37_79B9))))
                .collect();
            for chunk in words.chunks(LANES) {
                let mut w = [0u32; LANES];
                w[..chunk.len()].copy_from_slice(chunk);
                let (mut exact, mut fast): (Channels, Channels) = Default::default();
                decode_lanes(format, &w, &mut exact, false);
                decode_lanes(format, &w, &mut fast, true);
                for j in 0..LANES {
                    for ch in 0..4 {
                        let (e, f) = (exact[ch][j], fast[ch][j]);
                        assert!(e.to_bits().abs_diff(f.to_bits()) <= 1, "{format:?} {e} {f}");
                    }
                    let px = [fast[0][j], fast[1][j], fast[2][j], fast[3][j]];
                    assert_eq!(format.encode(px), w[j], "{format:?}");
                }
            }
        }
    }

    #[test]
    fn the_threshold_table_is_the_dither_matrix() {
        for y in -4..8 {
            for x in -4..8 {
                let k = FragmentKey::new(
                    &RenderState {
                        dither: true,
                        ..RenderState::new(8, 8)
                    },
                    crate::TargetFormat {
                        color: ColorFormat::Rgb565,
                        depth: None,
                        stencil_bits: 0,
                    },
                    false,
                );
                let span = Span {
                    y,
                    x0: x,
                    x1: x + 8,
                };
                let t = span_thresholds(&k, span).expect("the key dithers");
                for (j, t) in t.iter().enumerate() {
                    assert_eq!(*t, dither_threshold(x + j as i32, y), "({x}, {y}) lane {j}");
                }
            }
        }
    }
}
