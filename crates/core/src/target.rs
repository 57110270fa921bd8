//! Render targets: the color, depth and stencil buffers that every surface, pbuffer, pixmap,
//! window and M3G `Image2D` target owns.
//!
//! Rows are stored bottom-up (row 0 is window y = 0), as GL addresses them, so `glReadPixels`
//! is a row copy. Color is always stored as RGBA8 words (`[r, g, b, a]` bytes in memory), but
//! every stored value is exactly representable in the target's format: RGB565 values are
//! quantized on write and widened to 8 bits as round(v · 255 / (2ⁿ − 1)), and formats without
//! alpha keep 255.
//! One storage layout means one set of span routines; the format only changes the quantizer.

use super::multisample;

/// The color formats a target can have.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ColorFormat {
    Rgb565,
    Rgb888,
    Rgba8888,
    /// 4 bits per channel (`OES_framebuffer_object` RGBA4 renderbuffers).
    Rgba4444,
    /// 5 bits of red, green and blue, 1 of alpha (RGB5_A1 renderbuffers).
    Rgba5551,
}

impl ColorFormat {
    /// Bits per channel, red, green, blue, alpha.
    pub fn bits(self) -> [u32; 4] {
        match self {
            ColorFormat::Rgb565 => [5, 6, 5, 0],
            ColorFormat::Rgb888 => [8, 8, 8, 0],
            ColorFormat::Rgba8888 => [8, 8, 8, 8],
            ColorFormat::Rgba4444 => [4, 4, 4, 4],
            ColorFormat::Rgba5551 => [5, 5, 5, 1],
        }
    }

    /// Converts a color in [0, 1] (clamped here) to the stored RGBA8 word, rounding to the
    /// nearest value the format can hold: `round(c · (2ⁿ − 1))`.
    #[inline(always)]
    pub fn encode(self, rgba: [f32; 4]) -> u32 {
        let byte = |c: f32| unorm(c, 8);
        match self {
            ColorFormat::Rgba8888 => u32::from_le_bytes(rgba.map(|c| byte(c) as u8)),
            ColorFormat::Rgb888 => {
                byte(rgba[0]) | byte(rgba[1]) << 8 | byte(rgba[2]) << 16 | 0xFF00_0000
            }
            _ => self.encode_narrow(rgba),
        }
    }

    fn encode_narrow(self, rgba: [f32; 4]) -> u32 {
        let b = self.bits();
        let mut bytes = [0u8; 4];
        for i in 0..4 {
            bytes[i] = if b[i] == 0 {
                255
            } else {
                expand_to_8(unorm(rgba[i], b[i]), b[i])
            };
        }
        u32::from_le_bytes(bytes)
    }

    /// Requantizes an RGBA8 word so it is representable in this format.
    pub fn quantize8(self, word: u32) -> u32 {
        let b = self.bits();
        let mut bytes = word.to_le_bytes();
        for i in 0..4 {
            bytes[i] = match b[i] {
                0 => 255,
                8 => bytes[i],
                n => expand_to_8((bytes[i] as u32 * ((1 << n) - 1) + 127) / 255, n),
            };
        }
        u32::from_le_bytes(bytes)
    }
}

/// `round(clamp(c) · (2ⁿ − 1))`; NaN maps to 0 so garbage never reaches memory.
#[inline]
pub fn unorm(c: f32, bits: u32) -> u32 {
    let max = ((1u32 << bits) - 1) as f32;
    let c = if c > 0.0 { c.min(1.0) } else { 0.0 };
    (c * max + 0.5) as u32
}

/// Widens an n-bit unsigned normalized value to 8 bits as `round(v · 255 / (2ⁿ − 1))`, the
/// conversion ES 1.1 §4.3.1 gives for reading pixels (bit replication is off by one for some
/// values, e.g. 3 of 31). The n-bit value is still the byte's top n bits, so it can be
/// recovered by a shift. The division by 2ⁿ − 1 is a multiply and a shift, exact for every
/// v < 2ⁿ, n ≤ 8 (a test checks them all): a division by a number known only at run time
/// is slow and does not vectorize.
#[inline(always)]
pub fn expand_to_8(v: u32, bits: u32) -> u8 {
    let max = (1u32 << bits) - 1;
    let magic = (1u32 << 20).div_ceil(max);
    (((v * 255 + max / 2) * magic) >> 20) as u8
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DepthFormat {
    D16,
    D24,
}

impl DepthFormat {
    pub fn bits(self) -> u32 {
        match self {
            DepthFormat::D16 => 16,
            DepthFormat::D24 => 24,
        }
    }

    pub fn max(self) -> u32 {
        (1 << self.bits()) - 1
    }

    /// Quantizes a window-space depth in [0, 1] (clamped) to the format: `round(z · (2ⁿ − 1))`.
    pub fn quantize(self, z: f64) -> u32 {
        let z = if z > 0.0 { z.min(1.0) } else { 0.0 };
        (z * self.max() as f64 + 0.5) as u32
    }
}

/// What a target is made of; equal descriptions make interchangeable targets.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct TargetFormat {
    pub color: ColorFormat,
    pub depth: Option<DepthFormat>,
    pub stencil_bits: u32,
}

/// An axis-aligned pixel rectangle, half-open: `x0 <= x < x1`, `y0 <= y < y1`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Rect {
    pub x0: i32,
    pub y0: i32,
    pub x1: i32,
    pub y1: i32,
}

impl Rect {
    pub fn new(x: i32, y: i32, w: i32, h: i32) -> Rect {
        Rect {
            x0: x,
            y0: y,
            x1: x.saturating_add(w),
            y1: y.saturating_add(h),
        }
    }

    pub fn intersect(self, o: Rect) -> Rect {
        Rect {
            x0: self.x0.max(o.x0),
            y0: self.y0.max(o.y0),
            x1: self.x1.min(o.x1),
            y1: self.y1.min(o.y1),
        }
    }

    pub fn is_empty(self) -> bool {
        self.x0 >= self.x1 || self.y0 >= self.y1
    }

    /// The part inside the scissor box, when there is one.
    pub fn scissored(self, scissor: Option<Rect>) -> Rect {
        match scissor {
            Some(s) => self.intersect(s),
            None => self,
        }
    }
}

/// A color, depth and stencil buffer set of one size.
#[derive(Clone, Debug)]
pub struct Target {
    width: u32,
    height: u32,
    format: TargetFormat,
    color: Vec<u32>,
    depth: Vec<u32>,
    stencil: Vec<u8>,
    /// The sample planes of a multisampled target ([`super::multisample`]), empty for a
    /// single-sample one. With planes, `color` holds their resolve, and `depth` and
    /// `stencil` are unused.
    samples: Vec<Target>,
}

/// A target that lives behind a lock beyond one call (an EGL surface's, a framebuffer
/// object's): the workers lock it to rasterize a frame while its owner records the next
/// ([`super::Frame::flush_behind`]).
pub trait SharedTarget: Send + Sync {
    fn target(&self) -> &std::sync::Mutex<Target>;
}

impl SharedTarget for std::sync::Mutex<Target> {
    fn target(&self) -> &std::sync::Mutex<Target> {
        self
    }
}

/// Channel write mask for color clears and fragment writes.
pub type ColorMask = [bool; 4];

/// Rows `y0 .. y0 + rows` of a target, borrowed mutably: the unit one worker thread owns.
pub struct BandMut<'a> {
    pub y0: i32,
    pub rows: i32,
    pub width: usize,
    pub color: &'a mut [u32],
    /// Empty when the target has no depth buffer.
    pub depth: &'a mut [u32],
    /// Empty when the target has no stencil buffer.
    pub stencil: &'a mut [u8],
}

impl BandMut<'_> {
    /// The rows of `rect` (within the target, or empty) that fall in this band, as index
    /// ranges into the band's buffers.
    pub fn rows_of(&self, rect: Rect) -> impl Iterator<Item = std::ops::Range<usize>> + '_ {
        // An empty rect can have corners anywhere, negative ones included (a scissor box
        // wholly off the surface): it has no rows.
        let y0 = rect.y0.max(self.y0);
        let y1 = if rect.is_empty() {
            y0
        } else {
            rect.y1.min(self.y0 + self.rows)
        };
        let (x0, x1) = (rect.x0 as usize, rect.x1 as usize);
        (y0..y1).map(move |y| {
            let start = (y - self.y0) as usize * self.width;
            start + x0..start + x1
        })
    }

    /// Fills `rect` with the color word `word`, keeping the bits in `keep`.
    pub fn clear_color(&mut self, rect: Rect, word: u32, keep: u32) {
        let rows: Vec<_> = self.rows_of(rect).collect();
        for r in rows {
            let row = &mut self.color[r];
            if keep == 0 {
                row.fill(word);
            } else {
                row.iter_mut()
                    .for_each(|p| *p = (*p & keep) | (word & !keep));
            }
        }
    }

    pub fn clear_depth(&mut self, rect: Rect, value: u32) {
        if self.depth.is_empty() {
            return;
        }
        let rows: Vec<_> = self.rows_of(rect).collect();
        for r in rows {
            self.depth[r].fill(value);
        }
    }

    pub fn clear_stencil(&mut self, rect: Rect, value: u8, mask: u8) {
        if self.stencil.is_empty() {
            return;
        }
        let rows: Vec<_> = self.rows_of(rect).collect();
        for r in rows {
            self.stencil[r]
                .iter_mut()
                .for_each(|s| *s = (*s & !mask) | (value & mask));
        }
    }
}

impl Target {
    /// A target with undefined-but-deterministic contents (zeros; depth at its maximum).
    /// Callers check sizes first: the buffers are allocated here.
    pub fn new(width: u32, height: u32, format: TargetFormat) -> Target {
        Target::try_new(width, height, format).expect("target buffers allocated")
    }

    /// [`Target::new`], or `None` when the buffers cannot be allocated (so a surface or
    /// framebuffer too large for the machine is an error, not an abort).
    pub fn try_new(width: u32, height: u32, format: TargetFormat) -> Option<Target> {
        let n = (width as usize).checked_mul(height as usize)?;
        Some(Target {
            width,
            height,
            format,
            color: try_filled(n, format.color.encode([0.0, 0.0, 0.0, 0.0]))?,
            depth: try_filled(
                if format.depth.is_some() { n } else { 0 },
                format.depth.map_or(0, DepthFormat::max),
            )?,
            stencil: try_filled(if format.stencil_bits > 0 { n } else { 0 }, 0)?,
            samples: Vec::new(),
        })
    }

    /// [`Target::try_new`] with [`multisample::SAMPLES`] sample planes when `multisampled`.
    pub fn try_new_multisample(
        width: u32,
        height: u32,
        format: TargetFormat,
        multisampled: bool,
    ) -> Option<Target> {
        let mut t = Target::try_new(width, height, format)?;
        if multisampled {
            t.samples = (0..multisample::SAMPLES)
                .map(|_| Target::try_new(width, height, format))
                .collect::<Option<Vec<_>>>()?;
        }
        Some(t)
    }

    /// Samples per pixel: 0 for a single-sample target (`GL_SAMPLES`' convention).
    pub fn samples(&self) -> u32 {
        self.samples.len() as u32
    }

    /// The sample planes (empty for a single-sample target).
    pub fn sample_planes_mut(&mut self) -> &mut [Target] {
        &mut self.samples
    }

    /// Recomputes the color buffer as the box-filtered mean of the sample planes.
    pub fn resolve(&mut self) {
        let [a, b, c, d] = &self.samples[..] else {
            return;
        };
        let format = self.format.color;
        let planes = (
            a.color.iter(),
            b.color.iter(),
            c.color.iter(),
            d.color.iter(),
        );
        let words = planes.0.zip(planes.1).zip(planes.2).zip(planes.3);
        for (out, (((&a, &b), &c), &d)) in self.color.iter_mut().zip(words) {
            *out = resolve_words(format, &[a, b, c, d]);
        }
    }

    /// Copies the color buffer into every sample plane, after something other than
    /// rendering wrote it (a pixmap's initial pixels).
    pub fn broadcast_color(&mut self) {
        for s in &mut self.samples {
            s.color.copy_from_slice(&self.color);
        }
    }

    pub fn width(&self) -> u32 {
        self.width
    }
    pub fn height(&self) -> u32 {
        self.height
    }
    pub fn format(&self) -> TargetFormat {
        self.format
    }
    pub fn bounds(&self) -> Rect {
        Rect::new(0, 0, self.width as i32, self.height as i32)
    }

    /// Color words, bottom row first.
    pub fn color(&self) -> &[u32] {
        &self.color
    }
    pub fn color_mut(&mut self) -> &mut [u32] {
        &mut self.color
    }
    /// Quantized depth values (empty without a depth buffer), bottom row first.
    pub fn depth(&self) -> &[u32] {
        &self.depth
    }
    pub fn stencil(&self) -> &[u8] {
        &self.stencil
    }
    pub fn depth_mut(&mut self) -> &mut [u32] {
        &mut self.depth
    }
    pub fn stencil_mut(&mut self) -> &mut [u8] {
        &mut self.stencil
    }

    /// The pixel at (x, y) as `[r, g, b, a]` bytes.
    pub fn pixel(&self, x: u32, y: u32) -> [u8; 4] {
        self.color[(y * self.width + x) as usize].to_le_bytes()
    }

    /// Disjoint mutable views of the three buffers, for the fragment stage.
    pub fn buffers_mut(&mut self) -> (&mut [u32], &mut [u32], &mut [u8]) {
        (&mut self.color, &mut self.depth, &mut self.stencil)
    }

    /// The whole target as one band.
    pub fn as_band(&mut self) -> BandMut<'_> {
        BandMut {
            y0: 0,
            rows: self.height as i32,
            width: self.width as usize,
            color: &mut self.color,
            depth: &mut self.depth,
            stencil: &mut self.stencil,
        }
    }

    /// Splits the target into bands of `rows` rows (the last may be shorter), bottom first.
    pub fn bands_mut(&mut self, rows: u32) -> Vec<BandMut<'_>> {
        let width = self.width as usize;
        let per = width * rows as usize;
        let count = (self.height as usize).div_ceil(rows.max(1) as usize);
        let (mut color, mut depth, mut stencil) = (
            &mut self.color[..],
            &mut self.depth[..],
            &mut self.stencil[..],
        );
        let mut out = Vec::with_capacity(count);
        for i in 0..count {
            let take = per.min(color.len());
            let (take_d, take_s) = (take.min(depth.len()), take.min(stencil.len()));
            let (c, rest) = std::mem::take(&mut color).split_at_mut(take);
            color = rest;
            let (d, rest) = std::mem::take(&mut depth).split_at_mut(take_d);
            depth = rest;
            let (s, rest) = std::mem::take(&mut stencil).split_at_mut(take_s);
            stencil = rest;
            out.push(BandMut {
                y0: (i * rows as usize) as i32,
                rows: (take / width.max(1)) as i32,
                width,
                color: c,
                depth: d,
                stencil: s,
            });
        }
        out
    }

    /// Fills `rect` (clipped to the target) with `rgba`, writing only the channels in `mask`.
    pub fn clear_color(&mut self, rect: Rect, rgba: [f32; 4], mask: ColorMask) {
        for s in &mut self.samples {
            s.clear_color(rect, rgba, mask);
        }
        let word = self.format.color.encode(rgba);
        let rect = rect.intersect(self.bounds());
        self.as_band().clear_color(rect, word, keep_mask(mask));
    }

    /// Fills the depth buffer inside `rect` with `z` in [0, 1].
    pub fn clear_depth(&mut self, rect: Rect, z: f64) {
        for s in &mut self.samples {
            s.clear_depth(rect, z);
        }
        let Some(f) = self.format.depth else { return };
        let rect = rect.intersect(self.bounds());
        self.as_band().clear_depth(rect, f.quantize(z));
    }

    /// Fills the stencil buffer inside `rect` with `value`, writing only the bits in `mask`.
    pub fn clear_stencil(&mut self, rect: Rect, value: u32, mask: u32) {
        for s in &mut self.samples {
            s.clear_stencil(rect, value, mask);
        }
        let rect = rect.intersect(self.bounds());
        self.as_band().clear_stencil(rect, value as u8, mask as u8);
    }
}

/// The bits of a stored word that a color mask protects.
pub fn keep_mask(mask: ColorMask) -> u32 {
    let mut keep = 0u32;
    for (i, &write) in mask.iter().enumerate() {
        if !write {
            keep |= 0xff << (8 * i);
        }
    }
    keep
}

/// `n` copies of `value`, or `None` when they cannot be allocated.
pub fn try_filled<T: Clone>(n: usize, value: T) -> Option<Vec<T>> {
    let mut v = Vec::new();
    v.try_reserve_exact(n).ok()?;
    v.resize(n, value);
    Some(v)
}

/// The box-filter resolve of one pixel's sample words (stored RGBA8 words of `format`): per
/// channel the mean of the n-bit values, rounded half up, widened back to 8 bits.
pub fn resolve_words(format: ColorFormat, words: &[u32; multisample::SAMPLES]) -> u32 {
    if words.iter().all(|&w| w == words[0]) {
        return words[0];
    }
    let bits = format.bits();
    let mut out = [255u8; 4];
    for (c, &n) in bits.iter().enumerate() {
        if n == 0 {
            continue;
        }
        // A stored n-bit value is its byte's top n bits (see `expand_to_8`).
        let sum: u32 = words
            .iter()
            .map(|w| ((w >> (8 * c)) & 0xFF) >> (8 - n))
            .sum();
        let mean = (sum + multisample::SAMPLES as u32 / 2) / multisample::SAMPLES as u32;
        out[c] = expand_to_8(mean, n);
    }
    u32::from_le_bytes(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn expand_to_8_is_the_rounded_quotient_for_every_value() {
        for n in 1..=8 {
            let max = (1u32 << n) - 1;
            for v in 0..=max {
                let want = (v * 255 + max / 2) / max;
                assert_eq!(expand_to_8(v, n) as u32, want, "{v} of {n} bits");
            }
        }
    }

    #[test]
    fn rgb565_round_trips_through_storage() {
        for v in 0..32u32 {
            let c = v as f32 / 31.0;
            let w = ColorFormat::Rgb565.encode([c, 0.0, c, 0.5]);
            let b = w.to_le_bytes();
            assert_eq!(b[0] as u32 >> 3, v);
            assert_eq!(b[2] as u32 >> 3, v);
            assert_eq!(b[3], 255, "no alpha bits reads as 1");
            assert_eq!(ColorFormat::Rgb565.quantize8(w), w);
        }
    }

    #[test]
    fn unorm_rounds_and_clamps() {
        assert_eq!(unorm(0.5, 8), 128);
        assert_eq!(unorm(-1.0, 8), 0);
        assert_eq!(unorm(2.0, 8), 255);
        assert_eq!(unorm(f32::NAN, 8), 0);
        assert_eq!(DepthFormat::D16.quantize(1.0), 65535);
        assert_eq!(DepthFormat::D24.quantize(0.5), 8388608);
    }

    #[test]
    fn masked_clear_keeps_protected_channels() {
        let fmt = TargetFormat {
            color: ColorFormat::Rgba8888,
            depth: None,
            stencil_bits: 0,
        };
        let mut t = Target::new(4, 4, fmt);
        t.clear_color(t.bounds(), [1.0, 1.0, 1.0, 1.0], [true; 4]);
        t.clear_color(Rect::new(1, 1, 2, 2), [0.0; 4], [false, true, false, true]);
        assert_eq!(t.pixel(0, 0), [255, 255, 255, 255]);
        assert_eq!(t.pixel(1, 1), [255, 0, 255, 0]);
        assert_eq!(t.pixel(3, 3), [255, 255, 255, 255]);
    }
}
