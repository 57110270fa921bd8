//! `EXT_texture_compression_dxt1`, `ANGLE_texture_compression_dxt3` and `_dxt5`: S3TC
//! images decoded on upload, as the extensions (and `EXT_texture_compression_s3tc`, which
//! defines the blocks) describe them.
//!
//! 4 × 4 texel blocks in rows, the first block row being the image's first rows. A color
//! block is two RGB565 endpoints (little-endian 16-bit) and sixteen 2-bit indices, texel
//! (x, y) at bits 2(4y + x). DXT3 puts sixteen explicit 4-bit alphas before it; DXT5 two
//! 8-bit alpha endpoints and sixteen 3-bit indices.

use super::{BaseFormat, Image};

/// One of the four S3TC formats.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum S3tcFormat {
    /// `COMPRESSED_RGB_S3TC_DXT1_EXT`: the fourth color of the three-color mode is black.
    Dxt1Rgb,
    /// `COMPRESSED_RGBA_S3TC_DXT1_EXT`: the fourth color of the three-color mode is
    /// transparent black.
    Dxt1Rgba,
    Dxt3,
    Dxt5,
}

impl S3tcFormat {
    fn block_bytes(self) -> usize {
        match self {
            S3tcFormat::Dxt1Rgb | S3tcFormat::Dxt1Rgba => 8,
            S3tcFormat::Dxt3 | S3tcFormat::Dxt5 => 16,
        }
    }

    /// The bytes of a `width` × `height` image: whole blocks, partial ones at the edges
    /// counted whole.
    pub fn image_size(self, width: u32, height: u32) -> usize {
        width.div_ceil(4) as usize * height.div_ceil(4) as usize * self.block_bytes()
    }

    pub fn base_format(self) -> BaseFormat {
        match self {
            S3tcFormat::Dxt1Rgb => BaseFormat::Rgb,
            _ => BaseFormat::Rgba,
        }
    }

    /// Decodes a `width` × `height` image from exactly [`S3tcFormat::image_size`] bytes;
    /// `None` for another size.
    pub fn decode(self, width: u32, height: u32, data: &[u8]) -> Option<Image> {
        if data.len() != self.image_size(width, height) {
            return None;
        }
        let mut texels = Vec::new();
        texels
            .try_reserve_exact(width as usize * height as usize)
            .ok()?;
        texels.resize(width as usize * height as usize, 0);
        let blocks_x = width.div_ceil(4) as usize;
        for (n, b) in data.chunks_exact(self.block_bytes()).enumerate() {
            let (bx, by) = (n % blocks_x * 4, n / blocks_x * 4);
            let px = self.block(b);
            for y in 0..4 {
                for x in 0..4 {
                    let (tx, ty) = (bx + x, by + y);
                    if tx < width as usize && ty < height as usize {
                        texels[ty * width as usize + tx] = u32::from_le_bytes(px[y * 4 + x]);
                    }
                }
            }
        }
        Some(Image {
            width,
            height,
            format: self.base_format(),
            texels,
        })
    }

    /// The sixteen RGBA texels of one block, `out[4y + x]`.
    pub fn block(self, b: &[u8]) -> [[u8; 4]; 16] {
        let (alpha, color) = match self {
            S3tcFormat::Dxt1Rgb | S3tcFormat::Dxt1Rgba => (None, b),
            S3tcFormat::Dxt3 => (Some(explicit_alpha(&b[..8])), &b[8..]),
            S3tcFormat::Dxt5 => (Some(interpolated_alpha(&b[..8])), &b[8..]),
        };
        // DXT3 and DXT5 always use the four-color mode.
        let mut out = color_block(color, alpha.is_some(), self == S3tcFormat::Dxt1Rgba);
        if let Some(a) = alpha {
            for (t, a) in out.iter_mut().zip(a) {
                t[3] = a;
            }
        }
        out
    }
}

/// An RGB565 endpoint widened to 8 bits per channel by bit replication.
fn rgb565(v: u16) -> [u32; 3] {
    let (r, g, b) = (
        u32::from(v >> 11),
        u32::from(v >> 5 & 63),
        u32::from(v & 31),
    );
    [r << 3 | r >> 2, g << 2 | g >> 4, b << 3 | b >> 2]
}

/// The color half of a block. `four`: always the four-color mode; `punch`: the
/// three-color mode's fourth color is transparent.
fn color_block(b: &[u8], four: bool, punch: bool) -> [[u8; 4]; 16] {
    let (e0, e1) = (
        u16::from_le_bytes([b[0], b[1]]),
        u16::from_le_bytes([b[2], b[3]]),
    );
    let (c0, c1) = (rgb565(e0), rgb565(e1));
    let mix = |w0: u32, w1: u32, d: u32| -> [u8; 4] {
        let c: [u32; 3] = std::array::from_fn(|k| (w0 * c0[k] + w1 * c1[k] + d / 2) / d);
        [c[0] as u8, c[1] as u8, c[2] as u8, 255]
    };
    let palette = if four || e0 > e1 {
        [mix(1, 0, 1), mix(0, 1, 1), mix(2, 1, 3), mix(1, 2, 3)]
    } else {
        let fourth = if punch { [0, 0, 0, 0] } else { [0, 0, 0, 255] };
        [mix(1, 0, 1), mix(0, 1, 1), mix(1, 1, 2), fourth]
    };
    let bits = u32::from_le_bytes([b[4], b[5], b[6], b[7]]);
    std::array::from_fn(|i| palette[(bits >> (2 * i) & 3) as usize])
}

/// DXT3's alphas: sixteen 4-bit values, texel i at bits 4i, widened by replication.
fn explicit_alpha(b: &[u8]) -> [u8; 16] {
    let bits = u64::from_le_bytes(b.try_into().expect("8 bytes"));
    std::array::from_fn(|i| {
        let a = (bits >> (4 * i) & 15) as u8;
        a << 4 | a
    })
}

/// DXT5's alphas: endpoints a0, a1 and sixteen 3-bit codes (texel i at bits 16 + 3i).
/// a0 > a1: codes 2 ..= 7 interpolate six steps; else four, with 6 → 0 and 7 → 255.
fn interpolated_alpha(b: &[u8]) -> [u8; 16] {
    let (a0, a1) = (u32::from(b[0]), u32::from(b[1]));
    let bits = u64::from_le_bytes(b.try_into().expect("8 bytes")) >> 16;
    std::array::from_fn(|i| {
        let code = (bits >> (3 * i) & 7) as u32;
        let a = match code {
            0 => a0,
            1 => a1,
            _ if a0 > a1 => ((8 - code) * a0 + (code - 1) * a1 + 3) / 7,
            6 => 0,
            7 => 255,
            _ => ((6 - code) * a0 + (code - 1) * a1 + 2) / 5,
        };
        a as u8
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn four_and_three_color_modes() {
        // e0 = pure red (0xF800) > e1 = pure blue (0x001F): four colors; indices 0, 1, 2, 3
        // in the first row.
        let b = [0x00, 0xF8, 0x1F, 0x00, 0b1110_0100, 0, 0, 0];
        let px = S3tcFormat::Dxt1Rgb.block(&b);
        assert_eq!(px[0], [255, 0, 0, 255]);
        assert_eq!(px[1], [0, 0, 255, 255]);
        assert_eq!(px[2], [170, 0, 85, 255]);
        assert_eq!(px[3], [85, 0, 170, 255]);
        assert_eq!(px[4], [255, 0, 0, 255]);
        // Swapped endpoints: three colors and black, transparent for the RGBA format.
        let b = [0x1F, 0x00, 0x00, 0xF8, 0b1110_0100, 0, 0, 0];
        assert_eq!(S3tcFormat::Dxt1Rgb.block(&b)[2], [128, 0, 128, 255]);
        assert_eq!(S3tcFormat::Dxt1Rgb.block(&b)[3], [0, 0, 0, 255]);
        assert_eq!(S3tcFormat::Dxt1Rgba.block(&b)[3], [0, 0, 0, 0]);
    }

    #[test]
    fn dxt3_and_dxt5_alpha() {
        let mut b = [0u8; 16];
        b[0] = 0x0F; // texel 0: 15 → 255; texel 1: 0
        b[8..12].copy_from_slice(&[0xFF, 0xFF, 0xFF, 0xFF]); // white endpoints
        let px = S3tcFormat::Dxt3.block(&b);
        assert_eq!(px[0], [255, 255, 255, 255]);
        assert_eq!(px[1], [255, 255, 255, 0]);
        // DXT5, a0 = 255 > a1 = 0: code 2 is (6·255 + 0)/7 rounded = 219; a0 ≤ a1: codes 6
        // and 7 are 0 and 255.
        let mut b = [0u8; 16];
        b[0] = 255;
        b[2] = 0b010; // texel 0: code 2
        assert_eq!(S3tcFormat::Dxt5.block(&b)[0][3], 219);
        b[0] = 0;
        b[1] = 100;
        b[2] = 0b111_110; // texel 0: code 6, texel 1: code 7
        let px = S3tcFormat::Dxt5.block(&b);
        assert_eq!((px[0][3], px[1][3]), (0, 255));
    }

    #[test]
    fn images_crop_partial_blocks() {
        assert_eq!(S3tcFormat::Dxt1Rgb.image_size(5, 3), 16);
        assert_eq!(S3tcFormat::Dxt5.image_size(5, 3), 32);
        let mut data = vec![0u8; 16];
        data[8..10].copy_from_slice(&0xF800u16.to_le_bytes()); // second block red
        let img = S3tcFormat::Dxt1Rgb.decode(5, 3, &data).expect("decodes");
        assert_eq!(img.texels.len(), 15);
        assert_eq!(img.texels[4].to_le_bytes(), [255, 0, 0, 255]);
        assert_eq!(img.texels[3].to_le_bytes(), [0, 0, 0, 255]);
        assert!(S3tcFormat::Dxt1Rgb.decode(5, 3, &data[..8]).is_none());
    }
}
