//! EGL surfaces: pbuffers, memory pixmaps and memory windows. Each owns a [`Target`] with its
//! config's formats and is a [`gles::Surface`](crate::gles::Surface) a context can draw into.
//!
//! Pixmaps and windows live in client memory; the `ffi` layer wraps that memory in a
//! [`NativeMemory`] so that everything here is safe code over byte slices.
#![forbid(unsafe_code)]

use std::sync::{Mutex, MutexGuard};

use gles_cm_core::{ColorFormat, Target};

use super::config::{self, Config, MAX_PBUFFER_PIXELS, MAX_PBUFFER_SIDE};
use super::native::{
    EGL_MEMORY_BGRA8888, EGL_MEMORY_RGB565, EGL_MEMORY_RGB888, EGL_MEMORY_RGBA8888,
};
use super::tokens::*;
use super::types::EGLint;

/// The description of a memory pixmap or window (the fields of `EGLMemoryPixmap` /
/// `EGLMemoryWindow`, minus the pixel pointer).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MemoryLayout {
    pub width: EGLint,
    pub height: EGLint,
    pub stride: EGLint,
    pub format: EGLint,
}

/// Bytes per pixel of an `EGL_MEMORY_*` format, or `None` for an unknown format.
pub fn bytes_per_pixel(format: EGLint) -> Option<usize> {
    match format {
        EGL_MEMORY_RGB565 => Some(2),
        EGL_MEMORY_RGB888 => Some(3),
        EGL_MEMORY_RGBA8888 | EGL_MEMORY_BGRA8888 => Some(4),
        _ => None,
    }
}

impl MemoryLayout {
    /// True for a layout a surface can use: positive size, known format, rows long enough.
    pub fn is_valid(&self) -> bool {
        let Some(bpp) = bytes_per_pixel(self.format) else {
            return false;
        };
        self.width > 0
            && self.height > 0
            && (self.stride as i64) >= self.width as i64 * bpp as i64
            && self.byte_len().is_some()
    }

    /// The number of bytes the pixels span: `stride · (height − 1) + width · bpp`.
    pub fn byte_len(&self) -> Option<usize> {
        let bpp = bytes_per_pixel(self.format)?;
        let rows = usize::try_from(self.height).ok()?.checked_sub(1)?;
        rows.checked_mul(usize::try_from(self.stride).ok()?)?
            .checked_add(usize::try_from(self.width).ok()?.checked_mul(bpp)?)
    }
}

/// Client memory behind a pixmap or window surface.
pub trait NativeMemory: Send + Sync {
    fn layout(&self) -> MemoryLayout;
    /// Runs `f` on the pixel bytes (`layout().byte_len()` of them).
    fn with_bytes(&self, f: &mut dyn FnMut(&mut [u8]));
}

/// Writes `target`'s color buffer into memory of `layout` (row 0 at the top), converting to
/// the memory format. Only the overlapping area is written.
pub fn write_to_memory(target: &Target, layout: MemoryLayout, bytes: &mut [u8]) {
    let Some(bpp) = bytes_per_pixel(layout.format) else {
        return;
    };
    let w = (layout.width as u32).min(target.width()) as usize;
    let h = (layout.height as u32).min(target.height()) as usize;
    let color = target.color();
    let tw = target.width() as usize;
    for row in 0..h {
        // Memory row `row` (from the top) is target row `height - 1 - row` (from the bottom).
        let ty = target.height() as usize - 1 - row;
        let src = &color[ty * tw..ty * tw + w];
        let start = row * layout.stride as usize;
        let Some(dst) = bytes.get_mut(start..start + w * bpp) else {
            return;
        };
        for (px, out) in src.iter().zip(dst.chunks_exact_mut(bpp)) {
            let [r, g, b, a] = px.to_le_bytes();
            match layout.format {
                EGL_MEMORY_RGB565 => {
                    let q = |v: u8, bits: u32| (v as u32 * ((1 << bits) - 1) + 127) / 255;
                    let word = (q(r, 5) << 11 | q(g, 6) << 5 | q(b, 5)) as u16;
                    out.copy_from_slice(&word.to_ne_bytes());
                }
                EGL_MEMORY_RGB888 => out.copy_from_slice(&[r, g, b]),
                EGL_MEMORY_RGBA8888 => out.copy_from_slice(&[r, g, b, a]),
                _ => out.copy_from_slice(&[b, g, r, a]),
            }
        }
    }
}

/// Loads memory of `layout` (row 0 at the top) into `target`'s color buffer, quantized to
/// the target's format. Only the overlapping area is read.
pub fn read_from_memory(target: &mut Target, layout: MemoryLayout, bytes: &[u8]) {
    let Some(bpp) = bytes_per_pixel(layout.format) else {
        return;
    };
    let w = (layout.width as u32).min(target.width()) as usize;
    let h = (layout.height as u32).min(target.height()) as usize;
    let tw = target.width() as usize;
    let th = target.height() as usize;
    let color_format = target.format().color;
    let color = target.color_mut();
    for row in 0..h {
        let ty = th - 1 - row;
        let start = row * layout.stride as usize;
        let Some(src) = bytes.get(start..start + w * bpp) else {
            return;
        };
        for (px, inp) in color[ty * tw..ty * tw + w]
            .iter_mut()
            .zip(src.chunks_exact(bpp))
        {
            let rgba = match layout.format {
                EGL_MEMORY_RGB565 => {
                    let v = u16::from_ne_bytes([inp[0], inp[1]]) as u32;
                    [
                        gles_cm_core::target::expand_to_8(v >> 11, 5),
                        gles_cm_core::target::expand_to_8((v >> 5) & 63, 6),
                        gles_cm_core::target::expand_to_8(v & 31, 5),
                        255,
                    ]
                }
                EGL_MEMORY_RGB888 => [inp[0], inp[1], inp[2], 255],
                EGL_MEMORY_RGBA8888 => [inp[0], inp[1], inp[2], inp[3]],
                _ => [inp[2], inp[1], inp[0], inp[3]],
            };
            *px = color_format.quantize8(u32::from_le_bytes(rgba));
        }
    }
}

/// True when memory pixels of `format` can hold `color`'s channels exactly (pixmap surfaces
/// and eglCopyBuffers need that).
pub fn memory_compatible(format: EGLint, color: ColorFormat) -> bool {
    config::memory_format_matches(format, color)
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Pbuffer,
    Pixmap,
    Window,
}

/// Attributes set at creation time.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CreateAttribs {
    pub width: EGLint,
    pub height: EGLint,
    pub largest_pbuffer: bool,
    pub texture_format: EGLint,
    pub texture_target: EGLint,
    pub mipmap_texture: bool,
    pub render_buffer: EGLint,
    pub colorspace: EGLint,
    pub alpha_format: EGLint,
}

impl Default for CreateAttribs {
    fn default() -> Self {
        CreateAttribs {
            width: 0,
            height: 0,
            largest_pbuffer: false,
            texture_format: EGL_NO_TEXTURE,
            texture_target: EGL_NO_TEXTURE,
            mipmap_texture: false,
            render_buffer: EGL_BACK_BUFFER,
            colorspace: EGL_COLORSPACE_sRGB,
            alpha_format: EGL_ALPHA_FORMAT_NONPRE,
        }
    }
}

fn boolean(v: EGLint) -> Result<bool, EGLint> {
    match v {
        0 => Ok(false),
        1 => Ok(true),
        _ => Err(EGL_BAD_ATTRIBUTE),
    }
}

/// Parses a surface creation attribute list for `kind` (section 3.5): the attributes each
/// kind accepts, their values, and the consistency rules that do not need the memory.
pub fn parse_attribs(
    kind: Kind,
    config: &Config,
    pairs: &[(EGLint, EGLint)],
) -> Result<CreateAttribs, EGLint> {
    let mut a = CreateAttribs {
        render_buffer: if kind == Kind::Pixmap {
            EGL_SINGLE_BUFFER
        } else {
            EGL_BACK_BUFFER
        },
        ..CreateAttribs::default()
    };
    let pbuffer = kind == Kind::Pbuffer;
    for &(attr, value) in pairs {
        match attr {
            EGL_VG_COLORSPACE => {
                if value != EGL_COLORSPACE_sRGB && value != EGL_COLORSPACE_LINEAR {
                    return Err(EGL_BAD_ATTRIBUTE);
                }
                a.colorspace = value;
            }
            EGL_VG_ALPHA_FORMAT => {
                if value != EGL_ALPHA_FORMAT_NONPRE && value != EGL_ALPHA_FORMAT_PRE {
                    return Err(EGL_BAD_ATTRIBUTE);
                }
                a.alpha_format = value;
            }
            EGL_RENDER_BUFFER if kind == Kind::Window => {
                if value != EGL_BACK_BUFFER && value != EGL_SINGLE_BUFFER {
                    return Err(EGL_BAD_ATTRIBUTE);
                }
                a.render_buffer = value;
            }
            EGL_WIDTH if pbuffer => a.width = value,
            EGL_HEIGHT if pbuffer => a.height = value,
            EGL_LARGEST_PBUFFER if pbuffer => a.largest_pbuffer = boolean(value)?,
            EGL_TEXTURE_FORMAT if pbuffer => {
                if !matches!(value, EGL_NO_TEXTURE | EGL_TEXTURE_RGB | EGL_TEXTURE_RGBA) {
                    return Err(EGL_BAD_ATTRIBUTE);
                }
                a.texture_format = value;
            }
            EGL_TEXTURE_TARGET if pbuffer => {
                if value != EGL_NO_TEXTURE && value != EGL_TEXTURE_2D {
                    return Err(EGL_BAD_ATTRIBUTE);
                }
                a.texture_target = value;
            }
            EGL_MIPMAP_TEXTURE if pbuffer => a.mipmap_texture = boolean(value)?,
            _ => return Err(EGL_BAD_ATTRIBUTE),
        }
    }
    let required_bit = match kind {
        Kind::Pbuffer => EGL_PBUFFER_BIT,
        Kind::Pixmap => EGL_PIXMAP_BIT,
        Kind::Window => EGL_WINDOW_BIT,
    };
    let surface_type = config.attrib(EGL_SURFACE_TYPE).unwrap_or(0);
    if surface_type & required_bit == 0 {
        return Err(EGL_BAD_MATCH);
    }
    // No config has EGL_VG_ALPHA_FORMAT_PRE_BIT.
    if a.alpha_format == EGL_ALPHA_FORMAT_PRE && surface_type & EGL_VG_ALPHA_FORMAT_PRE_BIT == 0 {
        return Err(EGL_BAD_MATCH);
    }
    if pbuffer {
        if (a.texture_format == EGL_NO_TEXTURE) != (a.texture_target == EGL_NO_TEXTURE) {
            return Err(EGL_BAD_MATCH);
        }
        let can_bind = match a.texture_format {
            EGL_TEXTURE_RGB => config.attrib(EGL_BIND_TO_TEXTURE_RGB),
            EGL_TEXTURE_RGBA => config.attrib(EGL_BIND_TO_TEXTURE_RGBA),
            _ => Some(1),
        };
        if can_bind != Some(1) {
            return Err(EGL_BAD_ATTRIBUTE);
        }
        if a.width < 0 || a.height < 0 {
            return Err(EGL_BAD_PARAMETER);
        }
        let too_big = a.width > MAX_PBUFFER_SIDE
            || a.height > MAX_PBUFFER_SIDE
            || a.width as i64 * a.height as i64 > MAX_PBUFFER_PIXELS as i64;
        if too_big {
            if !a.largest_pbuffer {
                return Err(EGL_BAD_ALLOC);
            }
            a.width = a.width.min(MAX_PBUFFER_SIDE);
            a.height = a.height.min(MAX_PBUFFER_SIDE);
        }
    }
    Ok(a)
}

/// State changed by eglSurfaceAttrib, eglSwapInterval and eglBindTexImage.
#[derive(Clone, Copy, Debug)]
pub struct MutableAttribs {
    pub mipmap_level: EGLint,
    pub swap_behavior: EGLint,
    pub multisample_resolve: EGLint,
    pub swap_interval: EGLint,
    /// True between eglBindTexImage and eglReleaseTexImage.
    pub bound_to_texture: bool,
}

pub struct Surface {
    /// Handle value (never reused).
    pub id: usize,
    pub config: &'static Config,
    pub kind: Kind,
    pub attribs: CreateAttribs,
    target: Mutex<Target>,
    state: Mutex<MutableAttribs>,
    /// The client memory of a pixmap or window.
    native: Option<Box<dyn NativeMemory>>,
    /// The address of the native pixmap or window struct (0 for pbuffers).
    pub native_key: usize,
}

fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|e| e.into_inner())
}

impl Surface {
    /// A pbuffer of `attribs`' (already validated) size; `EGL_BAD_ALLOC` when its buffers
    /// cannot be allocated.
    pub fn new_pbuffer(
        id: usize,
        config: &'static Config,
        attribs: CreateAttribs,
    ) -> Result<Surface, EGLint> {
        let target = Target::try_new_multisample(
            attribs.width as u32,
            attribs.height as u32,
            config.target_format(),
            config.multisampled(),
        )
        .ok_or(EGL_BAD_ALLOC)?;
        Ok(Surface::new(
            id,
            config,
            Kind::Pbuffer,
            attribs,
            target,
            None,
            0,
        ))
    }

    /// A pixmap or window surface over `memory` (validated by the caller). A pixmap's color
    /// buffer starts with the pixmap's pixels. Native surfaces have the pbuffers' limits:
    /// past [`MAX_PBUFFER_SIDE`] or [`MAX_PBUFFER_PIXELS`], or when the buffers cannot be
    /// allocated, `EGL_BAD_ALLOC`.
    pub fn new_native(
        id: usize,
        config: &'static Config,
        kind: Kind,
        mut attribs: CreateAttribs,
        memory: Box<dyn NativeMemory>,
        native_key: usize,
    ) -> Result<Surface, EGLint> {
        let layout = memory.layout();
        if layout.width > MAX_PBUFFER_SIDE
            || layout.height > MAX_PBUFFER_SIDE
            || layout.width as i64 * layout.height as i64 > MAX_PBUFFER_PIXELS as i64
        {
            return Err(EGL_BAD_ALLOC);
        }
        attribs.width = layout.width;
        attribs.height = layout.height;
        let mut target = Target::try_new_multisample(
            layout.width as u32,
            layout.height as u32,
            config.target_format(),
            config.multisampled(),
        )
        .ok_or(EGL_BAD_ALLOC)?;
        if kind == Kind::Pixmap {
            memory.with_bytes(&mut |b| read_from_memory(&mut target, layout, b));
            target.broadcast_color();
        }
        Ok(Surface::new(
            id,
            config,
            kind,
            attribs,
            target,
            Some(memory),
            native_key,
        ))
    }

    fn new(
        id: usize,
        config: &'static Config,
        kind: Kind,
        attribs: CreateAttribs,
        target: Target,
        native: Option<Box<dyn NativeMemory>>,
        native_key: usize,
    ) -> Surface {
        Surface {
            id,
            config,
            kind,
            attribs,
            target: Mutex::new(target),
            state: Mutex::new(MutableAttribs {
                mipmap_level: 0,
                swap_behavior: EGL_BUFFER_PRESERVED,
                multisample_resolve: EGL_MULTISAMPLE_RESOLVE_DEFAULT,
                swap_interval: 1,
                bound_to_texture: false,
            }),
            native,
            native_key,
        }
    }

    pub fn state(&self) -> MutableAttribs {
        *lock(&self.state)
    }

    pub fn update_state(&self, f: impl FnOnce(&mut MutableAttribs)) {
        f(&mut lock(&self.state))
    }

    /// eglQuerySurface: `Ok(None)` when the attribute exists but leaves `value` unchanged
    /// (texture attributes of a non-pbuffer).
    pub fn query(&self, attribute: EGLint) -> Result<Option<EGLint>, EGLint> {
        let s = self.state();
        let pbuffer = self.kind == Kind::Pbuffer;
        let a = &self.attribs;
        let v = match attribute {
            EGL_CONFIG_ID => self.config.id,
            EGL_WIDTH => a.width,
            EGL_HEIGHT => a.height,
            EGL_LARGEST_PBUFFER if pbuffer => a.largest_pbuffer as EGLint,
            EGL_TEXTURE_FORMAT if pbuffer => a.texture_format,
            EGL_TEXTURE_TARGET if pbuffer => a.texture_target,
            EGL_MIPMAP_TEXTURE if pbuffer => a.mipmap_texture as EGLint,
            EGL_MIPMAP_LEVEL if pbuffer => s.mipmap_level,
            EGL_LARGEST_PBUFFER | EGL_TEXTURE_FORMAT | EGL_TEXTURE_TARGET | EGL_MIPMAP_TEXTURE
            | EGL_MIPMAP_LEVEL => return Ok(None),
            EGL_RENDER_BUFFER => a.render_buffer,
            EGL_SWAP_BEHAVIOR => s.swap_behavior,
            EGL_MULTISAMPLE_RESOLVE => s.multisample_resolve,
            EGL_VG_COLORSPACE => a.colorspace,
            EGL_VG_ALPHA_FORMAT => a.alpha_format,
            EGL_HORIZONTAL_RESOLUTION | EGL_VERTICAL_RESOLUTION | EGL_PIXEL_ASPECT_RATIO => {
                EGL_UNKNOWN
            }
            _ => return Err(EGL_BAD_ATTRIBUTE),
        };
        Ok(Some(v))
    }

    /// eglSurfaceAttrib.
    pub fn set_attrib(&self, attribute: EGLint, value: EGLint) -> Result<(), EGLint> {
        let surface_type = self.config.attrib(EGL_SURFACE_TYPE).unwrap_or(0);
        match attribute {
            EGL_MIPMAP_LEVEL => {
                // Has an effect only on a texture pbuffer, but may always be set.
                if value < 0 {
                    return Err(EGL_BAD_PARAMETER);
                }
                self.update_state(|s| s.mipmap_level = value);
            }
            EGL_SWAP_BEHAVIOR => {
                match value {
                    EGL_BUFFER_DESTROYED => {}
                    EGL_BUFFER_PRESERVED => {
                        if surface_type & EGL_SWAP_BEHAVIOR_PRESERVED_BIT == 0 {
                            return Err(EGL_BAD_MATCH);
                        }
                    }
                    _ => return Err(EGL_BAD_PARAMETER),
                }
                self.update_state(|s| s.swap_behavior = value);
            }
            EGL_MULTISAMPLE_RESOLVE => {
                match value {
                    EGL_MULTISAMPLE_RESOLVE_DEFAULT => {}
                    EGL_MULTISAMPLE_RESOLVE_BOX => {
                        if surface_type & EGL_MULTISAMPLE_RESOLVE_BOX_BIT == 0 {
                            return Err(EGL_BAD_MATCH);
                        }
                    }
                    _ => return Err(EGL_BAD_PARAMETER),
                }
                self.update_state(|s| s.multisample_resolve = value);
            }
            _ => return Err(EGL_BAD_ATTRIBUTE),
        }
        Ok(())
    }

    /// Copies the color buffer to the window memory (eglSwapBuffers of a window surface).
    /// The back buffer is preserved.
    pub fn present(&self) {
        if self.kind == Kind::Window {
            self.write_native();
        }
    }

    /// Writes the color buffer to the pixmap or window memory.
    fn write_native(&self) {
        if let Some(mem) = &self.native {
            let layout = mem.layout();
            let target = lock(&self.target);
            mem.with_bytes(&mut |b| write_to_memory(&target, layout, b));
        }
    }

    /// Reloads a pixmap surface's color buffer from the pixmap (after native rendering,
    /// eglWaitNative).
    pub fn reload_native(&self) {
        if self.kind != Kind::Pixmap {
            return;
        }
        if let Some(mem) = &self.native {
            let layout = mem.layout();
            let mut target = lock(&self.target);
            mem.with_bytes(&mut |b| read_from_memory(&mut target, layout, b));
        }
    }

    /// eglCopyBuffers: writes the color buffer to `memory`, whose format must hold the
    /// config's color channels exactly.
    pub fn copy_to(&self, memory: &dyn NativeMemory) -> Result<(), EGLint> {
        let layout = memory.layout();
        if !memory_compatible(layout.format, self.config.color) {
            return Err(EGL_BAD_MATCH);
        }
        let target = lock(&self.target);
        memory.with_bytes(&mut |b| write_to_memory(&target, layout, b));
        Ok(())
    }
}

impl crate::gles::Surface for Surface {
    fn target(&self) -> &Mutex<Target> {
        &self.target
    }

    /// A pixmap receives the results of GL rendering when it completes.
    fn rendering_complete(&self) {
        if self.kind == Kind::Pixmap {
            self.write_native();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::egl::config::by_id;

    fn pb(pairs: &[(EGLint, EGLint)]) -> Result<CreateAttribs, EGLint> {
        parse_attribs(Kind::Pbuffer, by_id(1).unwrap(), pairs)
    }

    #[test]
    fn pbuffer_attribute_rules() {
        assert_eq!(pb(&[]).unwrap().width, 0);
        assert_eq!(pb(&[(EGL_WIDTH, -1)]), Err(EGL_BAD_PARAMETER));
        assert_eq!(pb(&[(EGL_WIDTH, 9000)]), Err(EGL_BAD_ALLOC));
        let a = pb(&[(EGL_WIDTH, 9000), (EGL_HEIGHT, 3), (EGL_LARGEST_PBUFFER, 1)]).unwrap();
        assert_eq!((a.width, a.height), (8192, 3));
        assert_eq!(
            pb(&[(EGL_TEXTURE_FORMAT, EGL_TEXTURE_RGB)]),
            Err(EGL_BAD_MATCH)
        );
        assert_eq!(
            pb(&[(EGL_TEXTURE_TARGET, EGL_TEXTURE_2D)]),
            Err(EGL_BAD_MATCH)
        );
        assert!(pb(&[
            (EGL_TEXTURE_FORMAT, EGL_TEXTURE_RGB),
            (EGL_TEXTURE_TARGET, EGL_TEXTURE_2D)
        ])
        .is_ok());
        // RGB565 cannot bind as RGBA.
        assert_eq!(
            pb(&[
                (EGL_TEXTURE_FORMAT, EGL_TEXTURE_RGBA),
                (EGL_TEXTURE_TARGET, EGL_TEXTURE_2D)
            ]),
            Err(EGL_BAD_ATTRIBUTE)
        );
        assert_eq!(
            pb(&[(EGL_RENDER_BUFFER, EGL_BACK_BUFFER)]),
            Err(EGL_BAD_ATTRIBUTE)
        );
        assert_eq!(pb(&[(0x1234, 0)]), Err(EGL_BAD_ATTRIBUTE));
        assert_eq!(pb(&[(EGL_TEXTURE_FORMAT, 5)]), Err(EGL_BAD_ATTRIBUTE));
        assert_eq!(
            pb(&[(EGL_VG_ALPHA_FORMAT, EGL_ALPHA_FORMAT_PRE)]),
            Err(EGL_BAD_MATCH)
        );
    }

    #[test]
    fn window_attributes() {
        let c = by_id(1).unwrap();
        assert!(parse_attribs(Kind::Window, c, &[(EGL_RENDER_BUFFER, EGL_SINGLE_BUFFER)]).is_ok());
        assert_eq!(
            parse_attribs(Kind::Window, c, &[(EGL_WIDTH, 4)]),
            Err(EGL_BAD_ATTRIBUTE)
        );
        assert_eq!(
            parse_attribs(Kind::Pixmap, c, &[(EGL_RENDER_BUFFER, EGL_BACK_BUFFER)]),
            Err(EGL_BAD_ATTRIBUTE)
        );
    }

    #[test]
    fn memory_round_trip_flips_rows_and_converts() {
        let fmt = by_id(13).unwrap().target_format();
        let mut t = Target::new(2, 2, fmt);
        t.color_mut()[0] = u32::from_le_bytes([10, 20, 30, 40]); // bottom left
        t.color_mut()[3] = u32::from_le_bytes([1, 2, 3, 4]); // top right
        for (format, bpp) in [
            (EGL_MEMORY_RGBA8888, 4),
            (EGL_MEMORY_BGRA8888, 4),
            (EGL_MEMORY_RGB888, 3),
        ] {
            let layout = MemoryLayout {
                width: 2,
                height: 2,
                stride: 2 * bpp + 1,
                format,
            };
            let mut mem = vec![0u8; layout.byte_len().unwrap()];
            write_to_memory(&t, layout, &mut mem);
            let bottom_left = &mem[layout.stride as usize..layout.stride as usize + bpp as usize];
            match format {
                EGL_MEMORY_RGBA8888 => assert_eq!(bottom_left, &[10, 20, 30, 40]),
                EGL_MEMORY_BGRA8888 => assert_eq!(bottom_left, &[30, 20, 10, 40]),
                _ => assert_eq!(bottom_left, &[10, 20, 30]),
            }
            let mut back = Target::new(2, 2, fmt);
            read_from_memory(&mut back, layout, &mem);
            if bpp == 4 {
                assert_eq!(back.color(), t.color());
            } else {
                assert_eq!(back.pixel(1, 1), [1, 2, 3, 255]);
            }
        }
        let layout = MemoryLayout {
            width: 2,
            height: 2,
            stride: 4,
            format: EGL_MEMORY_RGB565,
        };
        let mut t = Target::new(2, 2, by_id(1).unwrap().target_format());
        t.clear_color(t.bounds(), [1.0, 0.0, 0.0, 1.0], [true; 4]);
        let mut mem = vec![0u8; 8];
        write_to_memory(&t, layout, &mut mem);
        assert_eq!(u16::from_ne_bytes([mem[0], mem[1]]), 0xF800);
    }

    #[test]
    fn layouts() {
        let l = MemoryLayout {
            width: 3,
            height: 2,
            stride: 12,
            format: EGL_MEMORY_RGBA8888,
        };
        assert!(l.is_valid());
        assert_eq!(l.byte_len(), Some(24));
        assert!(!MemoryLayout { stride: 11, ..l }.is_valid());
        assert!(!MemoryLayout { format: 9, ..l }.is_valid());
        assert!(!MemoryLayout { width: 0, ..l }.is_valid());
    }
}
