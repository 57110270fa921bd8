//! Client pixel unpacking: the pixel types of OpenGL ES 1.1, the byte layout of a client
//! image (row stride after the unpack alignment), and the conversion of every
//! format/type pair to RGBA8 words.

use super::BaseFormat;
use crate::target::expand_to_8;

/// The client pixel types of OpenGL ES 1.1.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PixelType {
    UnsignedByte,
    UnsignedShort565,
    UnsignedShort4444,
    UnsignedShort5551,
    /// `EXT_texture_format_BGRA8888`: GL_BGRA_EXT with GL_UNSIGNED_BYTE (an RGBA image
    /// with red and blue swapped in client memory).
    UnsignedByteBgra,
}

impl PixelType {
    /// Bytes per pixel of `format` in this type, or `None` when the pair is not allowed
    /// (packed types go with exactly one format).
    pub fn pixel_size(self, format: BaseFormat) -> Option<usize> {
        match (self, format) {
            (PixelType::UnsignedByte, f) => Some(f.components()),
            (PixelType::UnsignedByteBgra, BaseFormat::Rgba) => Some(4),
            (PixelType::UnsignedShort565, BaseFormat::Rgb) => Some(2),
            (PixelType::UnsignedShort4444 | PixelType::UnsignedShort5551, BaseFormat::Rgba) => {
                Some(2)
            }
            _ => None,
        }
    }
}

/// The byte layout of an unpacked client image: `row_stride` bytes from one row to the next
/// (the unpack alignment applied), `len` bytes in all.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelRect {
    pub width: usize,
    pub height: usize,
    pub pixel_size: usize,
    pub row_stride: usize,
    pub len: usize,
}

impl PixelRect {
    /// The layout of a `width` × `height` image, rows padded to `alignment` (1, 2, 4 or 8).
    /// `None` when it does not fit in memory.
    pub fn new(width: usize, height: usize, pixel_size: usize, alignment: usize) -> Option<Self> {
        let row = width.checked_mul(pixel_size)?;
        let row_stride = row.checked_add(alignment - 1)? / alignment * alignment;
        let len = if width == 0 || height == 0 {
            0
        } else {
            row_stride.checked_mul(height - 1)?.checked_add(row)?
        };
        Some(PixelRect {
            width,
            height,
            pixel_size,
            row_stride,
            len,
        })
    }
}

pub(super) fn word(r: u8, g: u8, b: u8, a: u8) -> u32 {
    u32::from_le_bytes([r, g, b, a])
}

/// Converts one client pixel to an RGBA8 word.
pub(super) fn unpack_pixel(format: BaseFormat, ty: PixelType, p: &[u8]) -> u32 {
    let short = || u16::from_ne_bytes([p[0], p[1]]) as u32;
    match ty {
        PixelType::UnsignedByte => match format {
            BaseFormat::Alpha => word(0, 0, 0, p[0]),
            BaseFormat::Luminance => word(p[0], p[0], p[0], 255),
            BaseFormat::LuminanceAlpha => word(p[0], p[0], p[0], p[1]),
            BaseFormat::Rgb => word(p[0], p[1], p[2], 255),
            BaseFormat::Rgba => word(p[0], p[1], p[2], p[3]),
        },
        PixelType::UnsignedByteBgra => word(p[2], p[1], p[0], p[3]),
        PixelType::UnsignedShort565 => unpack_565(short()),
        PixelType::UnsignedShort4444 => unpack_4444(short()),
        PixelType::UnsignedShort5551 => unpack_5551(short()),
    }
}

pub(super) fn unpack_565(v: u32) -> u32 {
    word(
        expand_to_8(v >> 11, 5),
        expand_to_8((v >> 5) & 63, 6),
        expand_to_8(v & 31, 5),
        255,
    )
}

pub(super) fn unpack_4444(v: u32) -> u32 {
    word(
        expand_to_8(v >> 12, 4),
        expand_to_8((v >> 8) & 15, 4),
        expand_to_8((v >> 4) & 15, 4),
        expand_to_8(v & 15, 4),
    )
}

pub(super) fn unpack_5551(v: u32) -> u32 {
    word(
        expand_to_8(v >> 11, 5),
        expand_to_8((v >> 6) & 31, 5),
        expand_to_8((v >> 1) & 31, 5),
        expand_to_8(v & 1, 1),
    )
}

/// Unpacks a client image laid out as `rect` (`data` holds at least `rect.len` bytes) into
/// RGBA8 words, row 0 first.
pub fn unpack(format: BaseFormat, ty: PixelType, rect: PixelRect, data: &[u8]) -> Option<Vec<u32>> {
    let mut out = Vec::new();
    out.try_reserve_exact(rect.width.checked_mul(rect.height)?)
        .ok()?;
    for y in 0..rect.height {
        let row = &data[y * rect.row_stride..][..rect.width * rect.pixel_size];
        out.extend(
            row.chunks_exact(rect.pixel_size)
                .map(|p| unpack_pixel(format, ty, p)),
        );
    }
    Some(out)
}

/// Forces a word to what `format` keeps: components the format lacks read as GL defines
/// them for that base format (used when a color buffer is copied into a texture).
pub fn convert_word(format: BaseFormat, w: u32) -> u32 {
    let [r, g, b, a] = w.to_le_bytes();
    match format {
        BaseFormat::Alpha => word(0, 0, 0, a),
        BaseFormat::Luminance => word(r, r, r, 255),
        BaseFormat::LuminanceAlpha => word(r, r, r, a),
        BaseFormat::Rgb => word(r, g, b, 255),
        BaseFormat::Rgba => w,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unpack_respects_alignment_and_expands() {
        // 3 × 2 luminance, rows padded to 4 bytes.
        let rect = PixelRect::new(3, 2, 1, 4).unwrap();
        assert_eq!((rect.row_stride, rect.len), (4, 7));
        let data = [10, 20, 30, 99, 40, 50, 60];
        let t = unpack(BaseFormat::Luminance, PixelType::UnsignedByte, rect, &data).unwrap();
        assert_eq!(t[3].to_le_bytes(), [40, 40, 40, 255]);
        assert_eq!(t[2].to_le_bytes(), [30, 30, 30, 255]);
        let rect = PixelRect::new(1, 1, 1, 1).unwrap();
        let a = unpack(BaseFormat::Alpha, PixelType::UnsignedByte, rect, &[77]).unwrap();
        assert_eq!(a[0].to_le_bytes(), [0, 0, 0, 77]);
        let rect = PixelRect::new(1, 1, 2, 1).unwrap();
        let p = unpack(
            BaseFormat::Rgba,
            PixelType::UnsignedShort4444,
            rect,
            &0x8f0fu16.to_ne_bytes(),
        )
        .unwrap();
        assert_eq!(p[0].to_le_bytes(), [0x88, 0xff, 0x00, 0xff]);
        let p = unpack(
            BaseFormat::Rgb,
            PixelType::UnsignedShort565,
            rect,
            &0xf800u16.to_ne_bytes(),
        )
        .unwrap();
        assert_eq!(p[0].to_le_bytes(), [255, 0, 0, 255]);
        let p = unpack(
            BaseFormat::Rgba,
            PixelType::UnsignedShort5551,
            rect,
            &0x07c0u16.to_ne_bytes(),
        )
        .unwrap();
        assert_eq!(p[0].to_le_bytes(), [0, 255, 0, 0]);
    }

    #[test]
    fn bgra_swaps_red_and_blue() {
        let rect = PixelRect::new(1, 1, 4, 1).unwrap();
        let p = unpack(
            BaseFormat::Rgba,
            PixelType::UnsignedByteBgra,
            rect,
            &[1, 2, 3, 4],
        )
        .unwrap();
        assert_eq!(p[0].to_le_bytes(), [3, 2, 1, 4]);
    }

    #[test]
    fn packed_types_go_with_one_format() {
        assert_eq!(
            PixelType::UnsignedShort565.pixel_size(BaseFormat::Rgba),
            None
        );
        assert_eq!(
            PixelType::UnsignedShort4444.pixel_size(BaseFormat::Rgb),
            None
        );
        assert_eq!(
            PixelType::UnsignedShort5551.pixel_size(BaseFormat::Rgba),
            Some(2)
        );
        assert_eq!(
            PixelType::UnsignedByte.pixel_size(BaseFormat::LuminanceAlpha),
            Some(2)
        );
    }
}
