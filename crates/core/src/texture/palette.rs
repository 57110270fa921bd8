//! `OES_compressed_paletted_texture`: palette entry formats, sizes and the decoder.

use super::unpack::{unpack_4444, unpack_5551, unpack_565, word};
use super::{BaseFormat, Image};

/// The palette entry formats of `OES_compressed_paletted_texture`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PaletteEntry {
    Rgb8,
    Rgba8,
    R5G6B5,
    Rgba4,
    Rgb5A1,
}

/// A paletted format: 4-bit (16 entries) or 8-bit (256 entries) indices into a palette.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct PaletteFormat {
    pub index_bits: u32,
    pub entry: PaletteEntry,
}

impl PaletteFormat {
    pub fn entries(self) -> usize {
        1 << self.index_bits
    }

    pub fn entry_size(self) -> usize {
        match self.entry {
            PaletteEntry::Rgb8 => 3,
            PaletteEntry::Rgba8 => 4,
            _ => 2,
        }
    }

    pub fn base_format(self) -> BaseFormat {
        match self.entry {
            PaletteEntry::Rgb8 | PaletteEntry::R5G6B5 => BaseFormat::Rgb,
            _ => BaseFormat::Rgba,
        }
    }

    /// The exact size of a blob holding the palette and `levels` levels starting at
    /// `width` × `height`. Each level's indices start on a byte; 4-bit indices pack two to
    /// a byte, the first texel in the high nibble, with no padding between rows.
    pub fn image_size(self, width: u32, height: u32, levels: usize) -> usize {
        let mut size = self.entries() * self.entry_size();
        let (mut w, mut h) = (width as usize, height as usize);
        for _ in 0..levels {
            let n = w * h;
            size += if self.index_bits == 4 {
                n.div_ceil(2)
            } else {
                n
            };
            (w, h) = ((w / 2).max(1), (h / 2).max(1));
        }
        size
    }

    fn palette_word(self, e: &[u8]) -> u32 {
        let short = || u16::from_ne_bytes([e[0], e[1]]) as u32;
        match self.entry {
            PaletteEntry::Rgb8 => word(e[0], e[1], e[2], 255),
            PaletteEntry::Rgba8 => word(e[0], e[1], e[2], e[3]),
            PaletteEntry::R5G6B5 => unpack_565(short()),
            PaletteEntry::Rgba4 => unpack_4444(short()),
            PaletteEntry::Rgb5A1 => unpack_5551(short()),
        }
    }

    /// Decodes a blob of exactly [`PaletteFormat::image_size`] bytes into `levels` images,
    /// or `None` when `data` has another size.
    pub fn decode(self, width: u32, height: u32, levels: usize, data: &[u8]) -> Option<Vec<Image>> {
        if data.len() != self.image_size(width, height, levels) {
            return None;
        }
        let (palette, mut rest) = data.split_at(self.entries() * self.entry_size());
        let palette: Vec<u32> = palette
            .chunks_exact(self.entry_size())
            .map(|e| self.palette_word(e))
            .collect();
        let mut out = Vec::with_capacity(levels);
        let (mut w, mut h) = (width, height);
        for _ in 0..levels {
            let n = w as usize * h as usize;
            let bytes = if self.index_bits == 4 {
                n.div_ceil(2)
            } else {
                n
            };
            let (indices, tail) = rest.split_at(bytes);
            rest = tail;
            let texels = (0..n)
                .map(|i| {
                    let index = if self.index_bits == 4 {
                        let b = indices[i / 2];
                        if i % 2 == 0 {
                            b >> 4
                        } else {
                            b & 15
                        }
                    } else {
                        indices[i]
                    };
                    palette[index as usize]
                })
                .collect();
            out.push(Image {
                width: w,
                height: h,
                format: self.base_format(),
                texels,
            });
            (w, h) = ((w / 2).max(1), (h / 2).max(1));
        }
        Some(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paletted_sizes_and_decode() {
        let f = PaletteFormat {
            index_bits: 4,
            entry: PaletteEntry::Rgb8,
        };
        // 16·3 palette + 4×4 level (8 bytes) + 2×2 (2) + 1×1 (1).
        assert_eq!(f.image_size(4, 4, 3), 48 + 8 + 2 + 1);
        let mut blob = vec![0u8; f.image_size(2, 1, 2)];
        blob[3..6].copy_from_slice(&[1, 2, 3]); // entry 1
        blob[15 * 3..16 * 3].copy_from_slice(&[7, 8, 9]); // entry 15
        blob[48] = 0x1f; // texels 0 and 1 of level 0: entries 1 and 15
        blob[49] = 0xf0; // level 1's only texel: entry 15
        let levels = f.decode(2, 1, 2, &blob).unwrap();
        assert_eq!(levels[0].texel(0, 0), [1, 2, 3, 255]);
        assert_eq!(levels[0].texel(1, 0), [7, 8, 9, 255]);
        assert_eq!(levels[1].texel(0, 0), [7, 8, 9, 255]);
        assert_eq!(levels[1].format, BaseFormat::Rgb);
        assert!(f.decode(2, 1, 2, &blob[1..]).is_none());

        let f8 = PaletteFormat {
            index_bits: 8,
            entry: PaletteEntry::Rgb5A1,
        };
        assert_eq!(f8.image_size(2, 2, 1), 512 + 4);
        let mut blob = vec![0u8; 516];
        blob[2 * 200..2 * 200 + 2].copy_from_slice(&0xf801u16.to_ne_bytes());
        blob[512 + 3] = 200;
        let levels = f8.decode(2, 2, 1, &blob).unwrap();
        assert_eq!(levels[0].texel(1, 1), [255, 0, 0, 255]);
        assert_eq!(levels[0].texel(0, 0), [0, 0, 0, 0]);
        assert_eq!(levels[0].format, BaseFormat::Rgba);
    }
}
