//! Conversions between [`Image2D`] and the `image` crate's buffers, and a rendered
//! [`Target`] as an `image` buffer.
//!
//! Row order: an `Image2D` stores its top row first, as `image` buffers do, so the
//! conversions copy rows as they are. A [`Target`] stores its **bottom** row first (OpenGL's
//! convention: `target.pixel(0, 0)` is the bottom-left pixel); [`target_to_image`] turns it
//! right side up.

use image::{GrayAlphaImage, GrayImage, RgbImage, RgbaImage};

use super::error::{Error, Result};
use super::image::Image2D;
use super::modes::ImageFormat;
use gles_cm_core::Target;

/// An immutable Image2D of `format` from an `image` buffer's size and bytes; IllegalArgument
/// for an empty image or one wider or taller than `i32::MAX`.
fn from_buffer(format: ImageFormat, width: u32, height: u32, bytes: &[u8]) -> Result<Image2D> {
    let dim = |v: u32| {
        i32::try_from(v).map_err(|_| Error::IllegalArgument(format!("dimension {v} too large")))
    };
    Image2D::with_pixels(format, dim(width)?, dim(height)?, bytes)
}

impl TryFrom<&RgbaImage> for Image2D {
    type Error = Error;
    /// An immutable RGBA image.
    fn try_from(img: &RgbaImage) -> Result<Image2D> {
        from_buffer(ImageFormat::Rgba, img.width(), img.height(), img.as_raw())
    }
}

impl TryFrom<&RgbImage> for Image2D {
    type Error = Error;
    /// An immutable RGB image.
    fn try_from(img: &RgbImage) -> Result<Image2D> {
        from_buffer(ImageFormat::Rgb, img.width(), img.height(), img.as_raw())
    }
}

impl TryFrom<&GrayImage> for Image2D {
    type Error = Error;
    /// An immutable LUMINANCE image.
    fn try_from(img: &GrayImage) -> Result<Image2D> {
        from_buffer(
            ImageFormat::Luminance,
            img.width(),
            img.height(),
            img.as_raw(),
        )
    }
}

impl TryFrom<&GrayAlphaImage> for Image2D {
    type Error = Error;
    /// An immutable LUMINANCE_ALPHA image.
    fn try_from(img: &GrayAlphaImage) -> Result<Image2D> {
        from_buffer(
            ImageFormat::LuminanceAlpha,
            img.width(),
            img.height(),
            img.as_raw(),
        )
    }
}

/// The pixels of `img` as RGBA bytes, as texturing reads them: luminance replicated into
/// red, green and blue, a missing alpha opaque, an ALPHA image white.
fn rgba_bytes(img: &Image2D) -> Vec<u8> {
    let d = img.d();
    let p = &d.pixels;
    match d.format {
        ImageFormat::Rgba => p.clone(),
        ImageFormat::Rgb => p.chunks(3).flat_map(|c| [c[0], c[1], c[2], 255]).collect(),
        ImageFormat::Luminance => p.iter().flat_map(|&l| [l, l, l, 255]).collect(),
        ImageFormat::LuminanceAlpha => p.chunks(2).flat_map(|c| [c[0], c[0], c[0], c[1]]).collect(),
        ImageFormat::Alpha => p.iter().flat_map(|&a| [255, 255, 255, a]).collect(),
    }
}

impl From<&Image2D> for RgbaImage {
    /// Any format, expanded as [`Image2D`] texturing reads it (luminance replicated, a
    /// missing alpha opaque, an ALPHA image white).
    fn from(img: &Image2D) -> RgbaImage {
        let (w, h) = (img.width() as u32, img.height() as u32);
        RgbaImage::from_raw(w, h, rgba_bytes(img)).expect("one RGBA pixel per image pixel")
    }
}

impl From<&Image2D> for RgbImage {
    /// Any format, as [`RgbaImage::from`] without the alpha.
    fn from(img: &Image2D) -> RgbImage {
        let (w, h) = (img.width() as u32, img.height() as u32);
        let rgb = rgba_bytes(img)
            .chunks(4)
            .flat_map(|c| [c[0], c[1], c[2]])
            .collect();
        RgbImage::from_raw(w, h, rgb).expect("one RGB pixel per image pixel")
    }
}

/// A rendered [`Target`] as an RGBA image, right side up (the target's rows are bottom row
/// first, an image's top row first).
///
/// ```
/// use m3g::prelude::*;
///
/// let format = TargetFormat { color: ColorFormat::Rgba8888, depth: None, stencil_bits: 0 };
/// let mut target = Target::new(2, 2, format);
/// let bottom = gles_cm_core::Rect::new(0, 0, 2, 1); // the core's row 0 is the bottom one
/// target.clear_color(bottom, [1.0, 0.0, 0.0, 1.0], [true; 4]);
/// let img = m3g::target_to_image(&target);
/// assert_eq!(img.get_pixel(0, 1).0, [255, 0, 0, 255]); // the bottom row of the picture
/// assert_eq!(img.get_pixel(0, 0).0[0], 0);
/// ```
pub fn target_to_image(target: &Target) -> RgbaImage {
    let (w, h) = (target.width(), target.height());
    RgbaImage::from_fn(w, h, |x, y| image::Rgba(target.pixel(x, h - 1 - y)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn image_buffers_round_trip_top_row_first() {
        // 2 x 2: the top row red, green; the bottom row blue, half-transparent white.
        let px = [
            255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128,
        ];
        let rgba = RgbaImage::from_raw(2, 2, px.to_vec()).unwrap();
        let img = Image2D::try_from(&rgba).unwrap();
        assert_eq!(img.format(), ImageFormat::Rgba);
        assert!(!img.is_mutable());
        assert_eq!(img.pixels(), px); // the top row first, as in the buffer
        assert_eq!(RgbaImage::from(&img), rgba);
        let rgb = RgbImage::from(&img);
        assert_eq!(rgb.get_pixel(0, 1).0, [0, 0, 255]);
        let back = Image2D::try_from(&rgb).unwrap();
        assert_eq!(back.format(), ImageFormat::Rgb);
        assert_eq!(back.pixels()[..3], [255, 0, 0]);
    }

    #[test]
    fn gray_images_expand_like_textures() {
        let gray = GrayImage::from_raw(2, 1, vec![10, 200]).unwrap();
        let img = Image2D::try_from(&gray).unwrap();
        assert_eq!(img.format(), ImageFormat::Luminance);
        assert_eq!(
            RgbaImage::from(&img).into_raw(),
            [10, 10, 10, 255, 200, 200, 200, 255]
        );
        let ga = GrayAlphaImage::from_raw(1, 1, vec![7, 9]).unwrap();
        let img = Image2D::try_from(&ga).unwrap();
        assert_eq!(RgbaImage::from(&img).into_raw(), [7, 7, 7, 9]);
        let alpha = Image2D::with_pixels(ImageFormat::Alpha, 1, 1, &[33]).unwrap();
        assert_eq!(RgbaImage::from(&alpha).into_raw(), [255, 255, 255, 33]);
    }

    #[test]
    fn an_empty_buffer_is_an_illegal_argument() {
        let empty = RgbaImage::new(0, 3);
        assert!(matches!(
            Image2D::try_from(&empty),
            Err(Error::IllegalArgument(_))
        ));
    }
}
