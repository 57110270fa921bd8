//! PNG input: one immutable Image2D, its format by the M3G 1.1 rule (colour type and tRNS).

use std::io::Cursor;

use image::{ColorType, ImageReader, Limits};

use crate::modes::ImageFormat;

use super::{LoadError, LoadResult, Loader};
use crate::Image2D;

/// The largest PNG accepted, in pixels per side.
const MAX_SIDE: u32 = 8192;

/// What the header promises: (width, height, bytes per decoded pixel, bytes per pixel of
/// the 8-bit image kept). Read from IHDR and the chunks before IDAT, so that the memory a
/// decode needs is known (and counted) before the decoder allocates it.
fn plan(bytes: &[u8]) -> LoadResult<(u64, u64, u64, u64)> {
    let bad = |m: &str| LoadError::file(format!("invalid PNG: {m}"));
    let be = |i: usize| u32::from_be_bytes([bytes[i], bytes[i + 1], bytes[i + 2], bytes[i + 3]]);
    if bytes.len() < 33 || &bytes[12..16] != b"IHDR" || be(8) != 13 {
        return Err(bad("no IHDR chunk first"));
    }
    let (w, h, depth, colour) = (be(16), be(20), bytes[24], bytes[25]);
    if w == 0 || h == 0 {
        return Err(bad("empty image"));
    }
    if w > MAX_SIDE || h > MAX_SIDE {
        return Err(bad(&format!(
            "{w}x{h} is larger than the loader's {MAX_SIDE} pixels per side"
        )));
    }
    // A tRNS chunk (before IDAT) adds an alpha channel to the decoded pixels.
    let mut trns = false;
    let mut at = 8usize;
    while at + 8 <= bytes.len() {
        let len = be(at) as usize;
        let ty = &bytes[at + 4..at + 8];
        if ty == b"IDAT" || ty == b"IEND" {
            break;
        }
        trns |= ty == b"tRNS";
        at = at.saturating_add(12).saturating_add(len);
    }
    let channels: u64 = match colour {
        0 => 1 + trns as u64,
        2 | 3 => 3 + trns as u64,
        4 => 2,
        6 => 4,
        c => return Err(bad(&format!("colour type {c}"))),
    };
    let sample = if depth == 16 { 2 } else { 1 };
    Ok((w as u64, h as u64, channels * sample, channels))
}

/// Decodes a PNG. Greyscale gives LUMINANCE, truecolour and palette give RGB, greyscale +
/// alpha gives LUMINANCE_ALPHA, truecolour + alpha gives RGBA; a tRNS chunk adds alpha
/// (the decoder expands it, turning L into LA and RGB / palette into RGBA). 16-bit samples
/// are reduced to 8 bits.
pub(crate) fn decode(loader: &mut Loader, bytes: &[u8]) -> LoadResult<Image2D> {
    let (w, h, decoded, kept) = plan(bytes)?;
    // 8-bit output is the decoder's buffer itself; 16-bit samples need a second one.
    let need = w * h * decoded + if decoded != kept { w * h * kept } else { 0 };
    loader.charge(need, || format!("a {w}x{h} PNG"))?;
    let mut reader = ImageReader::new(Cursor::new(bytes));
    reader.set_format(image::ImageFormat::Png);
    let mut limits = Limits::default();
    limits.max_image_width = Some(MAX_SIDE);
    limits.max_image_height = Some(MAX_SIDE);
    // What was counted above, with slack for the decoder's row buffers.
    limits.max_alloc = Some(need + (16 << 20));
    reader.limits(limits);
    let img = reader
        .decode()
        .map_err(|e| LoadError::file(format!("invalid PNG: {e}")))?;
    let (w, h) = (img.width() as i32, img.height() as i32);
    let (format, pixels) = match img.color() {
        ColorType::L8 | ColorType::L16 => (ImageFormat::Luminance, img.into_luma8().into_raw()),
        ColorType::La8 | ColorType::La16 => (
            ImageFormat::LuminanceAlpha,
            img.into_luma_alpha8().into_raw(),
        ),
        ColorType::Rgb8 | ColorType::Rgb16 | ColorType::Rgb32F => {
            (ImageFormat::Rgb, img.into_rgb8().into_raw())
        }
        _ => (ImageFormat::Rgba, img.into_rgba8().into_raw()),
    };
    Image2D::with_pixel_vec(format, w, h, pixels)
        .map_err(|e| LoadError::file(format!("PNG image rejected: {e}")))
}
