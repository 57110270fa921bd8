//! Whole-framebuffer operations: clears and pixel read-back.
#![forbid(unsafe_code)]

use gles_cm_core::target::keep_mask;
use gles_cm_core::{ColorFormat, Target};

use super::context::{lock_target, Context};
use super::tokens::*;
use super::tokens_ext::{
    GL_BGRA_EXT, GL_UNSIGNED_SHORT_1_5_5_5_REV_EXT, GL_UNSIGNED_SHORT_4_4_4_4_REV_EXT,
};
use super::types::*;

/// How `glReadPixels` lays out its result in client memory.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelLayout {
    pub format: GLenum,
    pub ty: GLenum,
    pub bytes_per_pixel: usize,
    /// Bytes from one row to the next, after `GL_PACK_ALIGNMENT`.
    pub row_stride: usize,
    /// Bytes the whole read touches.
    pub len: usize,
}

impl Context {
    pub fn clear(&mut self, mask: GLbitfield) {
        if mask & !(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT) != 0 {
            return self.bad_value("mask", mask as i64, "mask may hold only GL_COLOR_BUFFER_BIT, GL_DEPTH_BUFFER_BIT and GL_STENCIL_BUFFER_BIT");
        }
        if !self.framebuffer_ready() {
            return;
        }
        // Only the scissor box limits a clear.
        let scissor = self.enables.scissor_test.then_some(self.scissor_box);
        let (color, depth, stencil) = (self.clear_color, self.clear_depth, self.clear_stencil);
        let (color_mask, depth_mask, stencil_mask) =
            (self.color_mask, self.depth_mask, self.stencil_writemask);
        self.with_frame(|frame, _| {
            let rect = frame.bounds().scissored(scissor);
            let format = frame.format();
            if mask & GL_COLOR_BUFFER_BIT != 0 {
                frame.clear_color(rect, format.color.encode(color), keep_mask(color_mask));
            }
            if let Some(df) = format
                .depth
                .filter(|_| mask & GL_DEPTH_BUFFER_BIT != 0 && depth_mask)
            {
                frame.clear_depth(rect, df.quantize(depth as f64));
            }
            if format.stencil_bits > 0 && mask & GL_STENCIL_BUFFER_BIT != 0 {
                frame.clear_stencil(rect, stencil as u8, stencil_mask as u8);
            }
        });
    }

    /// The implementation-chosen read format and type (`OES_read_format`) for the read surface.
    pub fn implementation_read_format(&self) -> (GLenum, GLenum) {
        let format = if self.fbo.bound != 0 {
            self.current_draw_format().map(|f| f.color)
        } else {
            self.read
                .as_ref()
                .map(|r| lock_target(r.as_ref()).format().color)
        };
        match format {
            Some(ColorFormat::Rgba4444) => (GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4),
            Some(ColorFormat::Rgba5551) => (GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1),
            Some(ColorFormat::Rgb565) => (GL_RGB, GL_UNSIGNED_SHORT_5_6_5),
            Some(ColorFormat::Rgb888) => (GL_RGB, GL_UNSIGNED_BYTE),
            Some(ColorFormat::Rgba8888) | None => (GL_RGBA, GL_UNSIGNED_BYTE),
        }
    }

    /// Validates a `glReadPixels` request and says how much client memory it writes. Unknown
    /// enums are `GL_INVALID_ENUM`; known ones in a combination other than RGBA/UNSIGNED_BYTE
    /// and the implementation read format are `GL_INVALID_OPERATION`.
    pub fn read_pixels_layout(
        &self,
        w: i32,
        h: i32,
        format: GLenum,
        ty: GLenum,
    ) -> Result<PixelLayout, GLenum> {
        let formats = [
            GL_ALPHA,
            GL_RGB,
            GL_RGBA,
            GL_LUMINANCE,
            GL_LUMINANCE_ALPHA,
            GL_BGRA_EXT,
        ];
        let types = [
            GL_UNSIGNED_BYTE,
            GL_UNSIGNED_SHORT_5_6_5,
            GL_UNSIGNED_SHORT_4_4_4_4,
            GL_UNSIGNED_SHORT_5_5_5_1,
            GL_UNSIGNED_SHORT_4_4_4_4_REV_EXT,
            GL_UNSIGNED_SHORT_1_5_5_5_REV_EXT,
        ];
        if !formats.contains(&format) || !types.contains(&ty) {
            return Err(GL_INVALID_ENUM);
        }
        if w < 0 || h < 0 {
            return Err(GL_INVALID_VALUE);
        }
        // EXT_read_format_bgra: BGRA bytes are readable always, as RGBA bytes are. Its
        // reversed 16-bit types are valid names, readable only as an implementation read
        // format, which none of ours is (Mesa reads them the same way).
        if (format, ty) != (GL_RGBA, GL_UNSIGNED_BYTE)
            && (format, ty) != (GL_BGRA_EXT, GL_UNSIGNED_BYTE)
            && (format, ty) != self.implementation_read_format()
        {
            return Err(GL_INVALID_OPERATION);
        }
        let bpp = match (format, ty) {
            (GL_RGBA | GL_BGRA_EXT, GL_UNSIGNED_BYTE) => 4,
            (GL_RGB, GL_UNSIGNED_BYTE) => 3,
            _ => 2,
        };
        let (w, h) = (w as usize, h as usize);
        let a = self.pack_alignment;
        let row = w.checked_mul(bpp).ok_or(GL_OUT_OF_MEMORY)?;
        let row_stride = row.checked_add(a - 1).ok_or(GL_OUT_OF_MEMORY)? / a * a;
        let len = if h == 0 || w == 0 {
            0
        } else {
            row_stride
                .checked_mul(h - 1)
                .and_then(|v| v.checked_add(row))
                .ok_or(GL_OUT_OF_MEMORY)?
        };
        Ok(PixelLayout {
            format,
            ty,
            bytes_per_pixel: bpp,
            row_stride,
            len,
        })
    }

    /// Reads the rectangle at (x, y) of the read surface into `out` (at least `layout.len`
    /// bytes). Pixels outside the surface are left as they were in `out`.
    pub fn read_pixels(
        &mut self,
        x: i32,
        y: i32,
        w: i32,
        h: i32,
        layout: PixelLayout,
        out: &mut [u8],
    ) {
        if !self.framebuffer_ready() {
            return;
        }
        // The read surface may be the draw surface: its pending work must land first.
        self.flush();
        let Some(surface) = self.read_surface() else {
            return;
        };
        let t = lock_target(surface.as_ref());
        read_rect(&t, x, y, w, h, layout, out);
    }
}

fn read_rect(t: &Target, x: i32, y: i32, w: i32, h: i32, layout: PixelLayout, out: &mut [u8]) {
    let (tw, th) = (t.width() as i64, t.height() as i64);
    let bpp = layout.bytes_per_pixel;
    for row in 0..h as i64 {
        let sy = y as i64 + row;
        if sy < 0 || sy >= th {
            continue;
        }
        let x0 = (x as i64).max(0);
        let x1 = (x as i64 + w as i64).min(tw);
        for sx in x0..x1 {
            let px = t.pixel(sx as u32, sy as u32);
            let at = row as usize * layout.row_stride + (sx - x as i64) as usize * bpp;
            let dst = &mut out[at..at + bpp];
            match (layout.format, layout.ty) {
                (GL_RGBA, GL_UNSIGNED_BYTE) => dst.copy_from_slice(&px),
                (GL_BGRA_EXT, GL_UNSIGNED_BYTE) => {
                    dst.copy_from_slice(&[px[2], px[1], px[0], px[3]])
                }
                (GL_RGB, GL_UNSIGNED_BYTE) => dst.copy_from_slice(&px[..3]),
                (GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4) => {
                    let q = |v: u8| (v as u32 * 15 + 127) / 255;
                    let v = q(px[0]) << 12 | q(px[1]) << 8 | q(px[2]) << 4 | q(px[3]);
                    dst.copy_from_slice(&(v as u16).to_ne_bytes());
                }
                (GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1) => {
                    let q = |v: u8| (v as u32 * 31 + 127) / 255;
                    let a = (px[3] >= 128) as u32;
                    let v = q(px[0]) << 11 | q(px[1]) << 6 | q(px[2]) << 1 | a;
                    dst.copy_from_slice(&(v as u16).to_ne_bytes());
                }
                _ => {
                    let q = |v: u8, bits: u32| (v as u32 * ((1 << bits) - 1) + 127) / 255;
                    let v = (q(px[0], 5) << 11) | (q(px[1], 6) << 5) | q(px[2], 5);
                    dst.copy_from_slice(&(v as u16).to_ne_bytes());
                }
            }
        }
    }
}
