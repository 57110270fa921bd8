//! PNG input: one immutable Image2D, its format by the M3G 1.1 rule (colour type and tRNS).

use std::io::Cursor;

use image::{ColorType, DynamicImage, ImageFormat, ImageReader, Limits};

use super::{LoadError, LoadResult};
use crate::m3g::Image2D;

/// The largest PNG accepted, in pixels per side.
const MAX_SIDE: u32 = 8192;

/// Decodes a PNG. Greyscale gives LUMINANCE, truecolour and palette give RGB, greyscale +
/// alpha gives LUMINANCE_ALPHA, truecolour + alpha gives RGBA; a tRNS chunk adds alpha
/// (the decoder expands it, turning L into LA and RGB / palette into RGBA). 16-bit samples
/// are reduced to 8 bits.
pub(crate) fn decode(bytes: &[u8]) -> LoadResult<Image2D> {
    let mut reader = ImageReader::new(Cursor::new(bytes));
    reader.set_format(ImageFormat::Png);
    let mut limits = Limits::default();
    limits.max_image_width = Some(MAX_SIDE);
    limits.max_image_height = Some(MAX_SIDE);
    limits.max_alloc = Some(512 << 20);
    reader.limits(limits);
    let img = reader
        .decode()
        .map_err(|e| LoadError::file(format!("invalid PNG: {e}")))?;
    let (w, h) = (img.width() as i32, img.height() as i32);
    let (format, pixels) = match img.color() {
        ColorType::L8 | ColorType::L16 => (Image2D::LUMINANCE, img.to_luma8().into_raw()),
        ColorType::La8 | ColorType::La16 => {
            (Image2D::LUMINANCE_ALPHA, img.to_luma_alpha8().into_raw())
        }
        ColorType::Rgb8 | ColorType::Rgb16 | ColorType::Rgb32F => {
            (Image2D::RGB, img.to_rgb8().into_raw())
        }
        _ => (Image2D::RGBA, DynamicImage::to_rgba8(&img).into_raw()),
    };
    Image2D::with_pixels(format, w, h, &pixels)
        .map_err(|e| LoadError::file(format!("PNG image rejected: {e}")))
}
