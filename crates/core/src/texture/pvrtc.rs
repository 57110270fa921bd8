//! `IMG_texture_compression_pvrtc`: PVRTC1 at 4 and 2 bits per pixel, decoded on upload
//! as the Khronos Data Format Specification describes the format (chapter "PVRTC
//! Compressed Texture Image Formats").
//!
//! An image is a grid of 64-bit little-endian words in reflected Morton order, one per
//! 4 × 4 (4 bpp) or 8 × 4 (2 bpp) pixels. Each word holds a color of two low-resolution
//! images A and B and the modulation of its pixels. The low-resolution images are
//! upscaled bilinearly with their samples at the block centres, wrapping around the image
//! edges, and each pixel blends A into B by its modulation weight in eighths.
//!
//! One point where the description and the PowerVR SDK's decoder part: for 2 bpp words in
//! the interpolated mode, the description gives the stored 2-bit values the punch-through
//! weights of 4 bpp; the SDK's decoder (the one content was checked against when it was
//! made) gives them the standard weights 0, 3, 5 and 8 with no punch-through. We follow
//! the SDK there.

use super::{BaseFormat, Image};

/// One of the four PVRTC1 formats.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PvrtcFormat {
    /// 2 or 4 bits per pixel.
    pub two_bpp: bool,
    pub alpha: bool,
}

impl PvrtcFormat {
    /// Pixels per word across (down is always 4).
    fn block_width(self) -> u32 {
        if self.two_bpp {
            8
        } else {
            4
        }
    }

    /// The bytes of a `width` × `height` level: at least 2 × 2 words, however small the
    /// level (`max(w, 8) · max(h, 8) / 2` at 4 bpp, `max(w, 16) · max(h, 8) / 4` at 2 bpp).
    pub fn image_size(self, width: u32, height: u32) -> usize {
        let (bw, bh) = self.words(width, height);
        bw as usize * bh as usize * 8
    }

    /// Words across and down of a `width` × `height` level.
    fn words(self, width: u32, height: u32) -> (u32, u32) {
        let bw = self.block_width();
        ((width.max(2 * bw)) / bw, height.max(8) / 4)
    }

    pub fn base_format(self) -> BaseFormat {
        if self.alpha {
            BaseFormat::Rgba
        } else {
            BaseFormat::Rgb
        }
    }

    /// Decodes a level of power-of-two `width` × `height` from exactly
    /// [`PvrtcFormat::image_size`] bytes; `None` for another size. A level smaller than
    /// the words' 2 × 2 blocks is the top-left corner of what they encode.
    pub fn decode(self, width: u32, height: u32, data: &[u8]) -> Option<Image> {
        if data.len() != self.image_size(width, height)
            || !width.is_power_of_two()
            || !height.is_power_of_two()
        {
            return None;
        }
        let (ww, wh) = self.words(width, height);
        let words: Vec<u64> = data
            .chunks_exact(8)
            .map(|b| u64::from_le_bytes(b.try_into().expect("8 bytes")))
            .collect();
        let word = |x: i64, y: i64| -> u64 {
            let (x, y) = (
                x.rem_euclid(ww as i64) as u32,
                y.rem_euclid(wh as i64) as u32,
            );
            words[morton(x, y, ww, wh)]
        };
        let bw = self.block_width() as i64;
        let (full_w, full_h) = (ww as i64 * bw, wh as i64 * 4);
        let weights = self.weights(&word, full_w, full_h);
        let mut texels = Vec::new();
        texels
            .try_reserve_exact(width as usize * height as usize)
            .ok()?;
        for y in 0..height as i64 {
            for x in 0..width as i64 {
                let (a, b) = self.upscaled(&word, x, y);
                let (w, punch) = weights[(y * full_w + x) as usize];
                let mut c: [u32; 4] = std::array::from_fn(|k| (a[k] * (8 - w) + b[k] * w) / 8);
                if punch {
                    c[3] = 0;
                }
                if !self.alpha {
                    c[3] = 255;
                }
                texels.push(u32::from_le_bytes(c.map(|v| v as u8)));
            }
        }
        Some(Image {
            width,
            height,
            format: self.base_format(),
            texels,
        })
    }

    /// Colors A and B of pixel (x, y) of the upscaled images, 8 bits per channel
    /// ([r, g, b, a]).
    fn upscaled(self, word: &impl Fn(i64, i64) -> u64, x: i64, y: i64) -> ([u32; 4], [u32; 4]) {
        let bw = self.block_width() as i64;
        let (x0, y0) = ((x - bw / 2).div_euclid(bw), (y - 2).div_euclid(4));
        let (xr, yr) = ((x - bw / 2) - bw * x0, (y - 2) - 4 * y0);
        let corners = [
            (word(x0, y0), (bw - xr) * (4 - yr)),
            (word(x0 + 1, y0), xr * (4 - yr)),
            (word(x0, y0 + 1), (bw - xr) * yr),
            (word(x0 + 1, y0 + 1), xr * yr),
        ];
        let mut sum = [[0i64; 4]; 2];
        for (w, f) in corners {
            for (s, color) in sum.iter_mut().zip([color_a(w), color_b(w)]) {
                for k in 0..4 {
                    s[k] += color[k] as i64 * f;
                }
            }
        }
        // The sums are fixed-point with 4 (4 bpp) or 5 (2 bpp) fraction bits over 5-bit
        // color and 4-bit alpha; the description's conversions to 8 bits.
        let to8 = |s: [i64; 4]| -> [u32; 4] {
            let s = s.map(|v| v as u32);
            if self.two_bpp {
                [
                    s[0] / 4 + s[0] / 128,
                    s[1] / 4 + s[1] / 128,
                    s[2] / 4 + s[2] / 128,
                    s[3] / 2 + s[3] / 32,
                ]
            } else {
                [
                    s[0] / 2 + s[0] / 64,
                    s[1] / 2 + s[1] / 64,
                    s[2] / 2 + s[2] / 64,
                    s[3] + s[3] / 16,
                ]
            }
        };
        (to8(sum[0]), to8(sum[1]))
    }

    /// Every pixel's modulation weight (eighths of color B) and punch-through flag, over
    /// the whole grid of words (2 bpp's interpolated pixels read their neighbours, across
    /// words and around the edges).
    fn weights(self, word: &impl Fn(i64, i64) -> u64, w: i64, h: i64) -> Vec<(u32, bool)> {
        let bw = self.block_width() as i64;
        let at = |x: i64, y: i64| word(x.div_euclid(bw), y.div_euclid(4));
        // The stored value of pixel (x, y) as a 2-bit code, and its word's mode.
        let code = |x: i64, y: i64| -> (u32, bool) {
            let wd = at(x, y);
            let m = (wd >> 32) & 1 == 1;
            let bits = wd as u32;
            let (px, py) = (x.rem_euclid(bw) as u32, y.rem_euclid(4) as u32);
            if !self.two_bpp {
                return ((bits >> (2 * (py * 4 + px))) & 3, m);
            }
            if !m {
                // One bit per pixel, doubled: 0 → 00, 1 → 11.
                return (((bits >> (py * 8 + px)) & 1) * 3, m);
            }
            // Checkerboard: the stored pixels (x + y even) in order, 2 bits each; the
            // first one's low bit is the flag (its value is its high bit, doubled), and
            // with that flag set, bit 20 is F and (4, 2)'s value is bit 21, doubled.
            let slot = (py * 8 + px) / 2;
            let mut bits = bits;
            if bits & 1 == 1 {
                bits = (bits & !(1 << 20)) | ((bits >> 1) & (1 << 20));
            }
            bits = (bits & !1) | ((bits >> 1) & 1);
            ((bits >> (2 * slot)) & 3, m)
        };
        const STANDARD: [u32; 4] = [0, 3, 5, 8];
        let mut out = Vec::with_capacity((w * h) as usize);
        for y in 0..h {
            for x in 0..w {
                let (c, m) = code(x, y);
                out.push(if !self.two_bpp {
                    if m {
                        ([0, 4, 4, 8][c as usize], c == 2)
                    } else {
                        (STANDARD[c as usize], false)
                    }
                } else if !m || (x + y) % 2 == 0 {
                    (STANDARD[c as usize], false)
                } else {
                    let wd = at(x, y) as u32;
                    let wt = |dx: i64, dy: i64| STANDARD[code(x + dx, y + dy).0 as usize];
                    // The neighbours' mean, halves rounded up.
                    let weight = if wd & 1 == 0 {
                        (wt(-1, 0) + wt(0, -1) + wt(1, 0) + wt(0, 1) + 2) / 4
                    } else if wd & (1 << 20) != 0 {
                        (wt(0, -1) + wt(0, 1)).div_ceil(2)
                    } else {
                        (wt(-1, 0) + wt(1, 0)).div_ceil(2)
                    };
                    (weight, false)
                });
            }
        }
        out
    }
}

/// The index of word (x, y) of a `ww` × `wh` grid (both powers of two) in reflected Morton
/// order: the low bits of x and y interleaved, y's in the lower place of each pair, as far
/// as the smaller dimension needs; the larger one's remaining bits above.
fn morton(x: u32, y: u32, ww: u32, wh: u32) -> usize {
    let min = ww.min(wh);
    let (mut offset, mut shift, mut mask) = (0u32, 0u32, 1u32);
    while mask < min {
        offset |= ((y & mask) | ((x & mask) << 1)) << shift;
        shift += 1;
        mask <<= 1;
    }
    (offset | ((x | y) >> shift) << (2 * shift)) as usize
}

/// Color A of a word as [r, g, b, a]: 5-bit color, 4-bit alpha.
fn color_a(word: u64) -> [u32; 4] {
    let c = (word >> 32) as u32 & 0xFFFF;
    if c & 0x8000 != 0 {
        // 1 RRRRR GGGGG BBBB M
        [(c >> 10) & 31, (c >> 5) & 31, widen4((c >> 1) & 15), 15]
    } else {
        // 0 AAA RRRR GGGG BBB M
        [
            widen4((c >> 8) & 15),
            widen4((c >> 4) & 15),
            widen3((c >> 1) & 7),
            ((c >> 12) & 7) << 1,
        ]
    }
}

/// Color B of a word as [r, g, b, a]: 5-bit color, 4-bit alpha.
fn color_b(word: u64) -> [u32; 4] {
    let c = (word >> 48) as u32;
    if c & 0x8000 != 0 {
        // 1 RRRRR GGGGG BBBBB
        [(c >> 10) & 31, (c >> 5) & 31, c & 31, 15]
    } else {
        // 0 AAA RRRR GGGG BBBB
        [
            widen4((c >> 8) & 15),
            widen4((c >> 4) & 15),
            widen4(c & 15),
            ((c >> 12) & 7) << 1,
        ]
    }
}

/// A 4-bit channel to 5 bits by replicating its top bit.
fn widen4(v: u32) -> u32 {
    (v << 1) | (v >> 3)
}

/// A 3-bit channel to 5 bits by replicating its top two bits.
fn widen3(v: u32) -> u32 {
    (v << 2) | (v >> 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    const RGBA4: PvrtcFormat = PvrtcFormat {
        two_bpp: false,
        alpha: true,
    };
    const RGBA2: PvrtcFormat = PvrtcFormat {
        two_bpp: true,
        alpha: true,
    };

    /// A word with opaque colors A and B (5-bit r, g, b; A's blue 4 bits), mode `m` and
    /// modulation bits `modulation`.
    fn word(a: [u32; 3], b: [u32; 3], m: bool, modulation: u32) -> [u8; 8] {
        let ca = 0x8000 | a[0] << 10 | a[1] << 5 | a[2] << 1 | m as u32;
        let cb = 0x8000 | b[0] << 10 | b[1] << 5 | b[2];
        (u64::from(modulation) | u64::from(ca) << 32 | u64::from(cb) << 48).to_le_bytes()
    }

    fn uniform(f: PvrtcFormat, w: u32, h: u32, wd: [u8; 8]) -> Vec<u8> {
        wd.repeat(f.image_size(w, h) / 8)
    }

    #[test]
    fn sizes_follow_the_extension() {
        assert_eq!(RGBA4.image_size(8, 8), 32);
        assert_eq!(RGBA4.image_size(1, 1), 32);
        assert_eq!(RGBA4.image_size(64, 16), 512);
        assert_eq!(RGBA2.image_size(16, 8), 32);
        // max(2, 16) × 32 pixels at 2 bits each.
        assert_eq!(RGBA2.image_size(2, 32), 128);
        assert!(RGBA4.decode(8, 8, &[0; 31]).is_none());
        assert!(RGBA4.decode(12, 8, &[0; 48]).is_none());
    }

    #[test]
    fn morton_order_matches_the_worked_example() {
        // The description's 16 × 4-word example: word (13, 2) is at 54.
        assert_eq!(morton(13, 2, 16, 4), 54);
        assert_eq!(morton(0, 0, 4, 4), 0);
        assert_eq!(morton(0, 1, 4, 4), 1);
        assert_eq!(morton(1, 0, 4, 4), 2);
        // Taller than wide: y's high bits go above.
        assert_eq!(morton(1, 3, 2, 4), 0b111);
    }

    #[test]
    fn uniform_words_decode_to_their_colors() {
        // Every word A = white, B = (31, 0, 0): weight 0 gives A exactly, 8 gives B, 3 and
        // 5 the blends floor((255·(8 − w) + B·w) / 8).
        for (bits, expect) in [
            (0x0000_0000u32, [255, 255, 255, 255]),
            (0xFFFF_FFFF, [255, 0, 0, 255]),
            (0x5555_5555, [255, 159, 159, 255]),
            (0xAAAA_AAAA, [255, 95, 95, 255]),
        ] {
            let data = uniform(RGBA4, 8, 8, word([31, 31, 15], [31, 0, 0], false, bits));
            let img = RGBA4.decode(8, 8, &data).expect("decodes");
            for t in &img.texels {
                assert_eq!(t.to_le_bytes(), expect, "modulation {bits:#x}");
            }
        }
    }

    #[test]
    fn punch_through_clears_alpha_and_halves() {
        let data = uniform(
            RGBA4,
            8,
            8,
            word([31, 31, 15], [0, 0, 0], true, 0xAAAA_AAAA),
        );
        let img = RGBA4.decode(8, 8, &data).expect("decodes");
        assert_eq!(img.texels[0].to_le_bytes(), [127, 127, 127, 0]);
        let rgb = PvrtcFormat {
            alpha: false,
            ..RGBA4
        };
        let img = rgb.decode(8, 8, &data).expect("decodes");
        assert_eq!(img.texels[0].to_le_bytes(), [127, 127, 127, 255]);
    }

    #[test]
    fn translucent_colors_expand_by_the_description() {
        // Color A translucent: alpha 3 bits 0b101 → 4 bits 0b1010 → 8 bits 0xAA; red 4 bits
        // 0b1000 → 5 bits 0b10001 → 8 bits 0x8C.
        let ca: u32 = 0b0101_1000_0000_0000; // 0 101 1000 0000 000 0
        let wd = (u64::from(ca) << 32).to_le_bytes();
        let img = RGBA4
            .decode(8, 8, &uniform(RGBA4, 8, 8, wd))
            .expect("decodes");
        assert_eq!(img.texels[5].to_le_bytes(), [0x8C, 0, 0, 0xAA]);
    }

    #[test]
    fn colors_interpolate_between_block_centres() {
        // 8 × 8 at 4 bpp: 2 × 2 words. Word (0, 0) has A = red 31, the others A = 0;
        // modulation 0 everywhere, so the image is A. At the word's centre (2, 2) the
        // color is its own; at (4, 2), halfway to word (1, 0), half of it: 31·8 = 248 in
        // 5.4 fixed point → 124 + 3 = 127; at (6, 2), the next centre, 0 (the wrap brings
        // word (0, 0) back only beyond it).
        let mut data = Vec::new();
        for n in 0..4 {
            let a = if n == 0 { [31, 0, 0] } else { [0, 0, 0] };
            data.extend(word(a, [0, 0, 0], false, 0));
        }
        let img = RGBA4.decode(8, 8, &data).expect("decodes");
        let r = |x: u32, y: u32| img.texels[(y * 8 + x) as usize].to_le_bytes()[0];
        assert_eq!(r(2, 2), 255);
        assert_eq!(r(4, 2), 127);
        assert_eq!(r(6, 2), 0);
        // Wrapping: pixel (0, 2) is halfway between word 1 (at x = −2, wrapped) and word 0.
        assert_eq!(r(0, 2), 127);
    }

    #[test]
    fn two_bpp_direct_and_interpolated_modulation() {
        // Direct: one bit per pixel; bit 1 of the word's row 0 selects B for pixel (1, 0).
        let data = uniform(RGBA2, 16, 8, word([0, 0, 0], [31, 31, 31], false, 0b10));
        let img = RGBA2.decode(16, 8, &data).expect("decodes");
        assert_eq!(img.texels[0].to_le_bytes(), [0, 0, 0, 255]);
        assert_eq!(img.texels[1].to_le_bytes(), [255, 255, 255, 255]);
        // Interpolated, H + V: every stored value 11 (B), so the others average to 8: B.
        // Bit 0 is the flag (0 here); the first pixel's value is bit 1 doubled.
        let data = uniform(
            RGBA2,
            16,
            8,
            word([0, 0, 0], [31, 31, 31], true, 0xFFFF_FFFE),
        );
        let img = RGBA2.decode(16, 8, &data).expect("decodes");
        assert!(img.texels.iter().all(|t| t.to_le_bytes() == [255; 4]));
        // Stored values alternate 11 and 00 along rows (slot order: (0,0), (2,0), …): the
        // pixel between two stored pixels of a row averages horizontally (flag 1, F = 0)
        // to (8 + 0 + 1) / 2 = 4.
        // Slots 0, 2, 4, … = 11; flag bit 0 = 1 and F (bit 20) = 0: horizontal.
        let bits = (0x3333_3333 & !(1 << 20)) | 1;
        let data = uniform(RGBA2, 16, 8, word([0, 0, 0], [31, 31, 31], true, bits));
        let img = RGBA2.decode(16, 8, &data).expect("decodes");
        assert_eq!(img.texels[1].to_le_bytes(), [127, 127, 127, 255]);
    }

    #[test]
    fn small_levels_are_the_top_left_corner() {
        let data = uniform(RGBA4, 1, 1, word([31, 0, 0], [0, 31, 0], false, 0));
        let img = RGBA4.decode(1, 1, &data).expect("decodes");
        assert_eq!((img.width, img.height), (1, 1));
        assert_eq!(img.texels[0].to_le_bytes(), [255, 0, 0, 255]);
    }
}
