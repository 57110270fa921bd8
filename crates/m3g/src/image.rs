//! `Image2D`.

use super::error::{iae, ise, Result};
use super::modes::ImageFormat;
use super::object::{class_data, handle, Inner, Kind};

#[derive(Clone, Debug)]
pub(crate) struct ImageData {
    pub format: ImageFormat,
    pub width: i32,
    pub height: i32,
    pub mutable: bool,
    /// Pixels left to right, top to bottom, `bpp` bytes each (palettes are expanded).
    pub pixels: Vec<u8>,
    /// True while the image is a Graphics3D render target.
    pub bound: bool,
}

handle!(
    /// `Image2D`: a 2D image in one of five formats, mutable or immutable.
    Image2D,
    |i| matches!(i.kind, Kind::Image2D(_))
);
class_data!(Image2D, Image2D, ImageData);

impl ImageFormat {
    /// Bytes per pixel.
    pub fn bytes_per_pixel(self) -> usize {
        match self {
            ImageFormat::Alpha | ImageFormat::Luminance => 1,
            ImageFormat::LuminanceAlpha => 2,
            ImageFormat::Rgb => 3,
            ImageFormat::Rgba => 4,
        }
    }
}

fn check(format: ImageFormat, width: i32, height: i32) -> Result<usize> {
    if width <= 0 || height <= 0 {
        return iae("width and height must be positive");
    }
    Ok(format.bytes_per_pixel())
}

impl Image2D {
    fn make(
        format: ImageFormat,
        width: i32,
        height: i32,
        mutable: bool,
        pixels: Vec<u8>,
    ) -> Image2D {
        Image2D(Inner::new(
            Kind::Image2D(ImageData {
                format,
                width,
                height,
                mutable,
                pixels,
                bound: false,
            }),
            false,
            false,
        ))
    }

    /// `Image2D(format, width, height)`: a mutable image, every pixel opaque white.
    /// IllegalArgument for a non-positive size.
    pub fn new(format: ImageFormat, width: i32, height: i32) -> Result<Image2D> {
        let b = check(format, width, height)?;
        let n = width as usize * height as usize * b;
        Ok(Image2D::make(format, width, height, true, vec![0xFF; n]))
    }

    /// `Image2D(format, width, height, byte[] image)`: an immutable image from `pixels`
    /// (left to right, top to bottom). IllegalArgument if `pixels` is too short.
    pub fn with_pixels(
        format: ImageFormat,
        width: i32,
        height: i32,
        pixels: &[u8],
    ) -> Result<Image2D> {
        let b = check(format, width, height)?;
        let n = width as usize * height as usize * b;
        if pixels.len() < n {
            return iae("pixel array too short");
        }
        Ok(Image2D::make(
            format,
            width,
            height,
            false,
            pixels[..n].to_vec(),
        ))
    }

    /// [`with_pixels`](Self::with_pixels) taking the pixels without a copy (the PNG
    /// loader's decoded buffer: a second copy would double its peak memory).
    pub(crate) fn with_pixel_vec(
        format: ImageFormat,
        width: i32,
        height: i32,
        mut pixels: Vec<u8>,
    ) -> Result<Image2D> {
        let b = check(format, width, height)?;
        let n = width as usize * height as usize * b;
        if pixels.len() < n {
            return iae("pixel array too short");
        }
        pixels.truncate(n);
        Ok(Image2D::make(format, width, height, false, pixels))
    }

    /// `Image2D(format, width, height, byte[] image, byte[] palette)`: an immutable
    /// palettized image, one index byte per pixel into up to 256 palette entries of the
    /// format's size (entries past 256 are ignored, missing ones read as 0).
    /// IllegalArgument if `indices` is too short or (as the specification literally says)
    /// the palette is shorter than 256 entries and not a whole number of entries.
    pub fn with_palette(
        format: ImageFormat,
        width: i32,
        height: i32,
        indices: &[u8],
        palette: &[u8],
    ) -> Result<Image2D> {
        let b = check(format, width, height)?;
        let n = width as usize * height as usize;
        if indices.len() < n {
            return iae("index array too short");
        }
        if palette.len() < 256 * b && palette.len() % b != 0 {
            return iae("palette length is not a multiple of the pixel size");
        }
        let mut pixels = Vec::with_capacity(n * b);
        for &i in &indices[..n] {
            let at = i as usize * b;
            for c in 0..b {
                pixels.push(palette.get(at + c).copied().unwrap_or(0));
            }
        }
        Ok(Image2D::make(format, width, height, false, pixels))
    }

    /// `set(x, y, width, height, image)`: replaces a rectangle of a mutable image.
    /// IllegalState if the image is immutable; IllegalArgument for a rectangle outside the
    /// image or a too-short array.
    pub fn set(&self, x: i32, y: i32, width: i32, height: i32, pixels: &[u8]) -> Result<()> {
        let mut d = self.dm();
        if !d.mutable {
            return ise("the image is immutable");
        }
        if x < 0
            || y < 0
            || width <= 0
            || height <= 0
            || x as i64 + width as i64 > d.width as i64
            || y as i64 + height as i64 > d.height as i64
        {
            return iae("rectangle outside the image");
        }
        let b = d.format.bytes_per_pixel();
        let row = width as usize * b;
        if pixels.len() < row * height as usize {
            return iae("pixel array too short");
        }
        let stride = d.width as usize * b;
        for r in 0..height as usize {
            let dst = (y as usize + r) * stride + x as usize * b;
            d.pixels[dst..dst + row].copy_from_slice(&pixels[r * row..(r + 1) * row]);
        }
        Ok(())
    }

    /// `isMutable()`.
    pub fn is_mutable(&self) -> bool {
        self.d().mutable
    }
    /// `getFormat()`.
    pub fn format(&self) -> ImageFormat {
        self.d().format
    }
    /// `getWidth()`.
    pub fn width(&self) -> i32 {
        self.d().width
    }
    /// `getHeight()`.
    pub fn height(&self) -> i32 {
        self.d().height
    }
    /// A copy of the pixels, left to right, top to bottom (a Rust extension: read back what
    /// Graphics3D rendered into a target image).
    pub fn pixels(&self) -> Vec<u8> {
        self.d().pixels.clone()
    }
}

impl ImageData {
    /// The pixel at (x, y) as RGBA in [0, 1], missing components 1 (luminance replicates).
    pub fn rgba(&self, x: i32, y: i32) -> [f32; 4] {
        let b = self.format.bytes_per_pixel();
        let at = (y as usize * self.width as usize + x as usize) * b;
        let p = &self.pixels[at..at + b];
        let f = |v: u8| v as f32 / 255.0;
        match self.format {
            ImageFormat::Alpha => [1.0, 1.0, 1.0, f(p[0])],
            ImageFormat::Luminance => [f(p[0]), f(p[0]), f(p[0]), 1.0],
            ImageFormat::LuminanceAlpha => [f(p[0]), f(p[0]), f(p[0]), f(p[1])],
            ImageFormat::Rgb => [f(p[0]), f(p[1]), f(p[2]), 1.0],
            ImageFormat::Rgba => [f(p[0]), f(p[1]), f(p[2]), f(p[3])],
        }
    }
}
