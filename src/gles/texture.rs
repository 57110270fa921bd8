//! Texture objects (ES 1.1 §3.7): names, bindings, parameters and image specification,
//! including `OES_compressed_paletted_texture`, copies from the read surface and the hooks
//! `eglBindTexImage` / `eglReleaseTexImage` use. The objects themselves and their data are
//! [`gles_cm_core::texture`]; this module validates and converts GL arguments.
//!
//! Named textures live in the share group's [`SharedObjects`](super::context::SharedObjects); texture 0 (the default
//! texture) belongs to each context. A name deleted in another context of the share group
//! while bound here is recreated, empty, the next time this context uses the binding.
//!
//! Flush points (ARCHITECTURE decision 5): recorded draws hold snapshots of the images they
//! sample, so changing a texture needs no flush; only while a framebuffer object is bound,
//! whose attachment may be that texture, does a change first complete the recorded work.
//! [`Texture::version`] changes with each change, for caches that want to notice.
#![forbid(unsafe_code)]

use gles_cm_core::fixed;
use gles_cm_core::texture::pvrtc::PvrtcFormat;
use gles_cm_core::texture::s3tc::S3tcFormat;
use gles_cm_core::texture::{
    convert_word, BaseFormat, Image, MagFilter, MinFilter, PaletteEntry, PaletteFormat, PixelRect,
    PixelType, Texture, Wrap, MAX_LEVEL, MAX_TEXTURE_SIZE,
};
use gles_cm_core::{ColorFormat, Target};

use super::buffer::lock_objects;
use super::context::{lock_target, Context, MAX_TEXTURE_UNITS};
use super::get::Value;
use super::objects::{Binding, Names};
use super::tokens::*;
use super::tokens_ext::*;
use super::types::*;

/// The texture objects of a share group.
pub type TextureNames = Names<Texture>;

/// A context's texture bindings and its default texture.
#[derive(Debug)]
pub struct TextureUnits {
    /// The object bound to `GL_TEXTURE_2D` on each unit (none: the default texture).
    pub bound: [Binding; MAX_TEXTURE_UNITS],
    pub default: Texture,
    /// The object bound to `GL_TEXTURE_CUBE_MAP_OES` on each unit, and the default cube map.
    pub bound_cube: [Binding; MAX_TEXTURE_UNITS],
    pub default_cube: Texture,
    /// `GL_TEXTURE_GEN_MODE_OES` of each unit: `GL_NORMAL_MAP_OES` or
    /// `GL_REFLECTION_MAP_OES` (the initial value).
    pub texgen_mode: [GLenum; MAX_TEXTURE_UNITS],
    /// Each unit's last snapshot, reused by the next draw while the texture and the bias
    /// are unchanged (rebuilding it, with the completeness check and two allocations, was
    /// a large part of a state change's cost). Dropped before any texture changes (see
    /// `forget_snapshots`).
    snapshots: std::cell::RefCell<[Option<Snapshot>; MAX_TEXTURE_UNITS]>,
}

/// A texture snapshot with what it was made from: the texture's version (which no other
/// texture or later state of this one has), whether the cube map was sampled, and the
/// level-of-detail bias's bits.
#[derive(Debug)]
struct Snapshot {
    key: (u64, bool, u32),
    sampler: Option<std::sync::Arc<gles_cm_core::texture::Sampler>>,
}

/// How many values `glTexGen*vOES` reads for `coord` and `pname` (`None`: invalid names).
pub fn tex_gen_parameter_count(coord: GLenum, pname: GLenum) -> Option<usize> {
    (coord == GL_TEXTURE_GEN_STR_OES && pname == GL_TEXTURE_GEN_MODE_OES).then_some(1)
}

impl Context {
    /// glTexGen / glGetTexGen (`OES_texture_cube_map`): `coord` must be
    /// `GL_TEXTURE_GEN_STR_OES` and `pname` `GL_TEXTURE_GEN_MODE_OES`.
    pub fn tex_gen(&mut self, coord: GLenum, pname: GLenum, param: f64) {
        if tex_gen_parameter_count(coord, pname).is_none() {
            return self.set_error(GL_INVALID_ENUM);
        }
        let mode = if param.fract() == 0.0 && (0.0..=u32::MAX as f64).contains(&param) {
            param as GLenum
        } else {
            GL_NONE_INVALID
        };
        if mode != GL_NORMAL_MAP_OES && mode != GL_REFLECTION_MAP_OES {
            return self.set_error(GL_INVALID_ENUM);
        }
        self.textures.texgen_mode[self.active_texture] = mode;
    }

    /// The active unit's `GL_TEXTURE_GEN_MODE_OES`, or `None` (`GL_INVALID_ENUM` raised).
    pub fn get_tex_gen(&mut self, coord: GLenum, pname: GLenum) -> Option<GLenum> {
        if tex_gen_parameter_count(coord, pname).is_none() {
            self.set_error(GL_INVALID_ENUM);
            return None;
        }
        Some(self.textures.texgen_mode[self.active_texture])
    }
}

impl Default for TextureUnits {
    fn default() -> Self {
        TextureUnits {
            bound: [const { Binding::NONE }; MAX_TEXTURE_UNITS],
            default: Texture::new(),
            bound_cube: [const { Binding::NONE }; MAX_TEXTURE_UNITS],
            default_cube: Texture::new_cube_map(),
            texgen_mode: [GL_REFLECTION_MAP_OES; MAX_TEXTURE_UNITS],
            snapshots: Default::default(),
        }
    }
}

/// The compressed formats `glGetIntegerv(GL_COMPRESSED_TEXTURE_FORMATS)` lists.
pub const COMPRESSED_FORMATS: [GLenum; 19] = [
    GL_PALETTE4_RGB8_OES,
    GL_PALETTE4_RGBA8_OES,
    GL_PALETTE4_R5_G6_B5_OES,
    GL_PALETTE4_RGBA4_OES,
    GL_PALETTE4_RGB5_A1_OES,
    GL_PALETTE8_RGB8_OES,
    GL_PALETTE8_RGBA8_OES,
    GL_PALETTE8_R5_G6_B5_OES,
    GL_PALETTE8_RGBA4_OES,
    GL_PALETTE8_RGB5_A1_OES,
    GL_ETC1_RGB8_OES,
    GL_COMPRESSED_RGB_PVRTC_4BPPV1_IMG,
    GL_COMPRESSED_RGB_PVRTC_2BPPV1_IMG,
    GL_COMPRESSED_RGBA_PVRTC_4BPPV1_IMG,
    GL_COMPRESSED_RGBA_PVRTC_2BPPV1_IMG,
    GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
    GL_COMPRESSED_RGBA_S3TC_DXT1_EXT,
    GL_COMPRESSED_RGBA_S3TC_DXT3_ANGLE,
    GL_COMPRESSED_RGBA_S3TC_DXT5_ANGLE,
];

// The list is one state value: it must fit in a query's answer.
const _: () = assert!(COMPRESSED_FORMATS.len() <= super::get::MAX_VALUES);

/// `OES_required_internalformat`: a sized internal format's base format, the bits it
/// keeps per channel ([r, g, b, a]; luminance in r, g and b) and the packed client type
/// it takes besides `GL_UNSIGNED_BYTE`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SizedFormat {
    pub internal: GLenum,
    pub base: BaseFormat,
    pub bits: [u32; 4],
    packed: Option<GLenum>,
}

pub fn sized_format(internal: GLenum) -> Option<SizedFormat> {
    use BaseFormat::*;
    let (base, bits, packed) = match internal {
        GL_ALPHA8_OES => (Alpha, [8; 4], None),
        GL_LUMINANCE8_OES => (Luminance, [8; 4], None),
        GL_LUMINANCE8_ALPHA8_OES => (LuminanceAlpha, [8; 4], None),
        GL_LUMINANCE4_ALPHA4_OES => (LuminanceAlpha, [4; 4], None),
        GL_RGB8_OES => (Rgb, [8; 4], None),
        GL_RGBA8_OES => (Rgba, [8; 4], None),
        GL_RGB565_OES => (Rgb, [5, 6, 5, 8], Some(GL_UNSIGNED_SHORT_5_6_5)),
        GL_RGBA4_OES => (Rgba, [4; 4], Some(GL_UNSIGNED_SHORT_4_4_4_4)),
        GL_RGB5_A1_OES => (Rgba, [5, 5, 5, 1], Some(GL_UNSIGNED_SHORT_5_5_5_1)),
        _ => return None,
    };
    Some(SizedFormat {
        internal,
        base,
        bits,
        packed,
    })
}

impl SizedFormat {
    /// Whether client data of `format` and `ty` may specify it (the extension's table: the
    /// base format's own enum, with unsigned bytes or the format's packed type).
    fn takes(&self, format: GLenum, ty: GLenum) -> bool {
        format == base_format_enum(self.base) && (ty == GL_UNSIGNED_BYTE || Some(ty) == self.packed)
    }

    /// Rounds texels to the format's precision (nothing for the 8-bit formats).
    fn store(&self, texels: &mut [u32]) {
        if self.bits != [8; 4] {
            gles_cm_core::texture::requantize(texels, self.bits);
        }
    }
}

/// The compressed formats `glCompressedTexImage2D` takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Compressed {
    Palette(PaletteFormat),
    /// `OES_compressed_ETC1_RGB8_texture`, decoded to RGB on upload.
    Etc1,
    /// `IMG_texture_compression_pvrtc`, decoded on upload.
    Pvrtc(PvrtcFormat),
    /// `EXT_texture_compression_dxt1`, `ANGLE_texture_compression_dxt3` / `_dxt5`,
    /// decoded on upload.
    S3tc(S3tcFormat),
}

fn pvrtc_format(format: GLenum) -> Option<PvrtcFormat> {
    let (two_bpp, alpha) = match format {
        GL_COMPRESSED_RGB_PVRTC_4BPPV1_IMG => (false, false),
        GL_COMPRESSED_RGB_PVRTC_2BPPV1_IMG => (true, false),
        GL_COMPRESSED_RGBA_PVRTC_4BPPV1_IMG => (false, true),
        GL_COMPRESSED_RGBA_PVRTC_2BPPV1_IMG => (true, true),
        _ => return None,
    };
    Some(PvrtcFormat { two_bpp, alpha })
}

fn s3tc_format(format: GLenum) -> Option<S3tcFormat> {
    Some(match format {
        GL_COMPRESSED_RGB_S3TC_DXT1_EXT => S3tcFormat::Dxt1Rgb,
        GL_COMPRESSED_RGBA_S3TC_DXT1_EXT => S3tcFormat::Dxt1Rgba,
        GL_COMPRESSED_RGBA_S3TC_DXT3_ANGLE => S3tcFormat::Dxt3,
        GL_COMPRESSED_RGBA_S3TC_DXT5_ANGLE => S3tcFormat::Dxt5,
        _ => return None,
    })
}

/// Whether a block-compressed image side is allowed where the extension asks for whole
/// blocks (`ANGLE_texture_compression_dxt3/5`): a multiple of 4, or 1 or 2 (small mipmap
/// levels).
fn whole_blocks(side: i32) -> bool {
    side % 4 == 0 || side == 1 || side == 2
}

/// A validated `glCompressedTexSubImage2D` request: the region of a level to decode into.
#[derive(Clone, Copy, Debug)]
pub struct CompressedUpdate {
    face: u8,
    level: usize,
    kind: Compressed,
    x: u32,
    y: u32,
    width: u32,
    height: u32,
}

/// A validated `glTexImage2D` / `glTexSubImage2D` request: where the texels go and how the
/// client memory is laid out (`rect.len` bytes are read when pixels are given).
#[derive(Clone, Copy, Debug)]
pub struct TexUpload {
    /// 0 for `GL_TEXTURE_2D`, 1 ..= 6 for the cube map faces.
    pub face: u8,
    pub level: usize,
    pub x: u32,
    pub y: u32,
    pub format: BaseFormat,
    pub ty: PixelType,
    pub rect: PixelRect,
    /// `OES_required_internalformat`: the sized format `glTexImage2D` named (`None` for
    /// sub-images: the level's own format is looked up when they are written).
    pub sized: Option<SizedFormat>,
}

/// The image a `glTexImage2D`-style target names: 0 for `GL_TEXTURE_2D`, 1 ..= 6 for the
/// cube map faces POSITIVE_X .. NEGATIVE_Z (`OES_texture_cube_map`).
pub fn image_target(target: GLenum) -> Option<u8> {
    match target {
        GL_TEXTURE_2D => Some(0),
        GL_TEXTURE_CUBE_MAP_POSITIVE_X_OES..=GL_TEXTURE_CUBE_MAP_NEGATIVE_Z_OES => {
            Some((target - GL_TEXTURE_CUBE_MAP_POSITIVE_X_OES + 1) as u8)
        }
        _ => None,
    }
}

/// Whether a texture object target is the cube map one (`None`: neither it nor 2D).
fn object_target(target: GLenum) -> Option<bool> {
    match target {
        GL_TEXTURE_2D => Some(false),
        GL_TEXTURE_CUBE_MAP_OES => Some(true),
        _ => None,
    }
}

pub fn base_format(format: GLenum) -> Option<BaseFormat> {
    Some(match format {
        GL_ALPHA => BaseFormat::Alpha,
        GL_LUMINANCE => BaseFormat::Luminance,
        GL_LUMINANCE_ALPHA => BaseFormat::LuminanceAlpha,
        GL_RGB => BaseFormat::Rgb,
        GL_RGBA => BaseFormat::Rgba,
        _ => return None,
    })
}

pub fn base_format_enum(format: BaseFormat) -> GLenum {
    match format {
        BaseFormat::Alpha => GL_ALPHA,
        BaseFormat::Luminance => GL_LUMINANCE,
        BaseFormat::LuminanceAlpha => GL_LUMINANCE_ALPHA,
        BaseFormat::Rgb => GL_RGB,
        BaseFormat::Rgba => GL_RGBA,
    }
}

fn pixel_type(ty: GLenum) -> Option<PixelType> {
    Some(match ty {
        GL_UNSIGNED_BYTE => PixelType::UnsignedByte,
        GL_UNSIGNED_SHORT_5_6_5 => PixelType::UnsignedShort565,
        GL_UNSIGNED_SHORT_4_4_4_4 => PixelType::UnsignedShort4444,
        GL_UNSIGNED_SHORT_5_5_5_1 => PixelType::UnsignedShort5551,
        _ => return None,
    })
}

/// The base format and client type of a `format`, `type` pair: the ES 1.1 formats, and
/// `GL_BGRA_EXT` (`EXT_texture_format_BGRA8888`, with `GL_UNSIGNED_BYTE` only).
fn client_format(format: GLenum, ty: GLenum) -> Result<(BaseFormat, PixelType), GLenum> {
    let t = pixel_type(ty).ok_or(GL_INVALID_ENUM)?;
    if format == GL_BGRA_EXT {
        return match t {
            PixelType::UnsignedByte => Ok((BaseFormat::Rgba, PixelType::UnsignedByteBgra)),
            _ => Err(GL_INVALID_OPERATION),
        };
    }
    Ok((base_format(format).ok_or(GL_INVALID_ENUM)?, t))
}

pub fn palette_format(format: GLenum) -> Option<PaletteFormat> {
    let i = COMPRESSED_FORMATS[..10].iter().position(|&f| f == format)?;
    let entry = [
        PaletteEntry::Rgb8,
        PaletteEntry::Rgba8,
        PaletteEntry::R5G6B5,
        PaletteEntry::Rgba4,
        PaletteEntry::Rgb5A1,
    ][i % 5];
    Some(PaletteFormat {
        index_bits: if i < 5 { 4 } else { 8 },
        entry,
    })
}

/// Whether a level-`level` image of `width` × `height` is allowed: level in
/// 0 ..= log2(max size), sides non-negative and no larger than the level's maximum. Any
/// size is allowed (`OES_texture_npot`; core ES 1.1 would require powers of two).
pub fn valid_image_size(level: i32, width: i32, height: i32) -> bool {
    if !(0..=MAX_LEVEL as i32).contains(&level) {
        return false;
    }
    let max = (MAX_TEXTURE_SIZE >> level) as i32;
    let side = |s: i32| (0..=max).contains(&s);
    side(width) && side(height)
}

/// The base formats a color buffer of `color` can be copied into (ES 1.1 table 3.15: every
/// component of the texture format must exist in the buffer).
fn copy_compatible(color: ColorFormat, format: BaseFormat) -> bool {
    let alpha = color.bits()[3] > 0;
    alpha || !format.has_alpha()
}

/// Reads the `w` × `h` rectangle at (x, y) of `t` as words converted to `format`; pixels
/// outside the target (undefined in GL) read as zero. `None` when the words cannot be
/// allocated.
fn read_region(t: &Target, x: i32, y: i32, w: u32, h: u32, format: BaseFormat) -> Option<Vec<u32>> {
    let mut out = Vec::new();
    out.try_reserve_exact(w as usize * h as usize).ok()?;
    for row in 0..h as i64 {
        for col in 0..w as i64 {
            let (sx, sy) = (x as i64 + col, y as i64 + row);
            let inside =
                (0..t.width() as i64).contains(&sx) && (0..t.height() as i64).contains(&sy);
            let word = if inside {
                u32::from_le_bytes(t.pixel(sx as u32, sy as u32))
            } else {
                0
            };
            out.push(convert_word(format, word));
        }
    }
    Some(out)
}

/// How a `glTexParameter*` / `glGetTexParameter*` call passes its values.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParamKind {
    /// `i` / `iv`: integers as given.
    Int,
    /// `f` / `fv`: enums converted from float, the crop rectangle rounded.
    Float,
    /// `x` / `xv`: enums passed unconverted, the crop rectangle as 16.16 fixed point.
    Fixed,
}

impl Context {
    /// Called before a texture changes. Recorded draws hold snapshots of the images they
    /// sample ([`Texture::sampler`]; a changed level is copied, not altered in place), so
    /// no flush is needed: pending draws keep seeing the contents they were recorded with.
    /// With a framebuffer object bound, its pending rendering lands in its attachments first
    /// (they may be this texture).
    fn texture_changing(&mut self) {
        self.forget_snapshots();
        self.fbo_texture_changing();
    }

    /// Drops the units' kept snapshots. A kept snapshot shares the texture's images, so a
    /// change would copy a level rather than write it in place (every `glTexSubImage2D` of
    /// a bound texture, say), and a deleted texture's images would live on until the
    /// unit's next draw.
    pub(super) fn forget_snapshots(&self) {
        *self.textures.snapshots.borrow_mut() = Default::default();
    }

    /// The snapshot of the 2D texture or (`cube`) the cube map bound to `unit`, with the
    /// unit's level-of-detail `bias`; `None` when it is not complete. The same `Arc` as
    /// the last draw's while nothing about the texture or the bias changed.
    pub(super) fn unit_snapshot(
        &self,
        unit: usize,
        cube: bool,
        bias: f32,
    ) -> Option<std::sync::Arc<gles_cm_core::texture::Sampler>> {
        let (bound, default) = if cube {
            (&self.textures.bound_cube[unit], &self.textures.default_cube)
        } else {
            (&self.textures.bound[unit], &self.textures.default)
        };
        let objects;
        let texture = if bound.is_none() {
            default
        } else {
            objects = lock_objects(&self.shared);
            objects.textures.get(bound)?
        };
        let key = (texture.version(), cube, bias.to_bits());
        let mut cache = self.textures.snapshots.borrow_mut();
        if let Some(s) = cache[unit].as_ref().filter(|s| s.key == key) {
            return s.sampler.clone();
        }
        let sampler = texture.sampler().map(|s| s.with_lod_bias(bias));
        cache[unit] = Some(Snapshot {
            key,
            sampler: sampler.clone(),
        });
        sampler
    }

    /// Runs `f` on the texture bound to the active unit's target for image `face` (0: 2D,
    /// 1 ..= 6: the cube map).
    fn with_face_texture<R>(&mut self, face: u8, f: impl FnOnce(&mut Texture) -> R) -> R {
        self.with_target_texture(face != 0, f)
    }

    /// Runs `f` on the texture bound to the active unit.
    pub fn with_bound_texture<R>(&mut self, f: impl FnOnce(&mut Texture) -> R) -> R {
        self.with_target_texture(false, f)
    }

    /// Runs `f` on the texture bound to the active unit's cube map target (`cube`) or 2D
    /// target. A bound object lives while it is bound, even if another context of the share
    /// group deleted its name.
    pub fn with_target_texture<R>(&mut self, cube: bool, f: impl FnOnce(&mut Texture) -> R) -> R {
        let unit = self.active_texture;
        let (bound, default) = if cube {
            (
                &self.textures.bound_cube[unit],
                &mut self.textures.default_cube,
            )
        } else {
            (&self.textures.bound[unit], &mut self.textures.default)
        };
        if bound.is_none() {
            return f(default);
        }
        let mut o = lock_objects(&self.shared);
        f(o.textures.get_mut(bound).expect("bound objects live"))
    }

    /// The name bound to `GL_TEXTURE_2D` on texture unit `unit`.
    pub fn texture_binding(&self, unit: usize) -> GLuint {
        self.textures.bound[unit].name
    }

    pub fn gen_textures(&mut self, n: i32) -> Vec<GLuint> {
        if n < 0 {
            self.bad_value("n", n as i64, "n must not be negative");
            return Vec::new();
        }
        let mut o = lock_objects(&self.shared);
        (0..n).map(|_| o.textures.generate()).collect()
    }

    /// `glDeleteTextures(n, names)`: names bound on any unit of this context revert to 0.
    /// Other contexts that have a deleted texture bound keep it (see [`super::objects`]).
    pub fn delete_textures(&mut self, n: i32, names: &[GLuint]) {
        if n < 0 {
            return self.bad_value("n", n as i64, "n must not be negative");
        }
        self.forget_labels(GL_TEXTURE, names);
        self.texture_changing();
        let shared = self.shared.clone();
        let mut o = lock_objects(&shared);
        let mut deleted = Vec::new();
        for &name in names {
            let Some(gone) = o.textures.delete(name) else {
                continue;
            };
            for b in self
                .textures
                .bound
                .iter_mut()
                .chain(self.textures.bound_cube.iter_mut())
            {
                if b.same_object(&gone) {
                    *b = Binding::NONE;
                }
            }
            deleted.push(gone);
        }
        drop(o);
        self.textures_deleted(&deleted);
        lock_objects(&shared).textures.sweep();
    }

    /// `glBindTexture`: a name first bound to one target keeps that kind; binding it to
    /// the other is `GL_INVALID_OPERATION`.
    pub fn bind_texture(&mut self, target: GLenum, name: GLuint) {
        let Some(cube) = object_target(target) else {
            return self.bad_enum("target", target);
        };
        let mut o = lock_objects(&self.shared);
        let b = o.textures.bind(name, || {
            if cube {
                Texture::new_cube_map()
            } else {
                Texture::new()
            }
        });
        if o.textures.get(&b).is_some_and(|t| t.is_cube_map() != cube) {
            drop(o);
            return self.bad_operation(
                "texture was first bound to the other target (2D vs cube map) and keeps that kind",
            );
        }
        drop(o);
        let unit = self.active_texture;
        if cube {
            self.textures.bound_cube[unit] = b;
        } else {
            self.textures.bound[unit] = b;
        }
    }

    pub fn is_texture(&mut self, name: GLuint) -> bool {
        lock_objects(&self.shared).textures.named(name).is_some()
    }

    pub fn tex_parameter(
        &mut self,
        target: GLenum,
        pname: GLenum,
        values: &[f64],
        kind: ParamKind,
        vector: bool,
    ) {
        let Some(cube) = object_target(target) else {
            return self.bad_enum("target", target);
        };
        if pname == GL_TEXTURE_CROP_RECT_OES {
            if !vector || values.len() < 4 {
                return self.set_error(GL_INVALID_ENUM);
            }
            let rect: [i32; 4] = std::array::from_fn(|i| {
                let v = match kind {
                    ParamKind::Fixed => fixed::to_f32(values[i] as i32) as f64,
                    _ => values[i],
                };
                v.round().clamp(i32::MIN as f64, i32::MAX as f64) as i32
            });
            self.texture_changing();
            return self.with_target_texture(cube, |t| {
                t.crop_rect = rect;
                t.touch();
            });
        }
        let Some(&v) = values.first() else {
            return self.set_error(GL_INVALID_ENUM);
        };
        // Enum values arrive unconverted in every form (a float holding the enum's value).
        let e = if v.fract() == 0.0 && (0.0..=u32::MAX as f64).contains(&v) {
            v as GLenum
        } else {
            GL_NONE_INVALID
        };
        enum Set {
            Min(MinFilter),
            Mag(MagFilter),
            WrapS(Wrap),
            WrapT(Wrap),
            Generate(bool),
            MaxLevel(u32),
            MaxAnisotropy(f32),
        }
        let wrap = |e| match e {
            GL_REPEAT => Some(Wrap::Repeat),
            GL_CLAMP_TO_EDGE => Some(Wrap::ClampToEdge),
            GL_MIRRORED_REPEAT_OES => Some(Wrap::MirroredRepeat),
            _ => None,
        };
        let set = match pname {
            GL_TEXTURE_MIN_FILTER => match e {
                GL_NEAREST => Some(Set::Min(MinFilter::Nearest)),
                GL_LINEAR => Some(Set::Min(MinFilter::Linear)),
                GL_NEAREST_MIPMAP_NEAREST => Some(Set::Min(MinFilter::NearestMipmapNearest)),
                GL_LINEAR_MIPMAP_NEAREST => Some(Set::Min(MinFilter::LinearMipmapNearest)),
                GL_NEAREST_MIPMAP_LINEAR => Some(Set::Min(MinFilter::NearestMipmapLinear)),
                GL_LINEAR_MIPMAP_LINEAR => Some(Set::Min(MinFilter::LinearMipmapLinear)),
                _ => None,
            },
            GL_TEXTURE_MAG_FILTER => match e {
                GL_NEAREST => Some(Set::Mag(MagFilter::Nearest)),
                GL_LINEAR => Some(Set::Mag(MagFilter::Linear)),
                _ => None,
            },
            GL_TEXTURE_WRAP_S => wrap(e).map(Set::WrapS),
            GL_TEXTURE_WRAP_T => wrap(e).map(Set::WrapT),
            GL_GENERATE_MIPMAP => match e {
                0 => Some(Set::Generate(false)),
                1 => Some(Set::Generate(true)),
                _ => None,
            },
            // APPLE_texture_max_level: any level number; negative ones are invalid values.
            GL_TEXTURE_MAX_LEVEL_APPLE => {
                if v < 0.0 || v.is_nan() {
                    return self.set_error(GL_INVALID_VALUE);
                }
                Some(Set::MaxLevel(v.min(u32::MAX as f64) as u32))
            }
            // EXT_texture_filter_anisotropic: any value of at least 1 (kept as set; the
            // sampler uses at most GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT).
            GL_TEXTURE_MAX_ANISOTROPY_EXT => {
                let a = match kind {
                    ParamKind::Fixed => fixed::to_f32(v as i32) as f64,
                    _ => v,
                };
                if a.is_nan() || a < 1.0 {
                    return self.set_error(GL_INVALID_VALUE);
                }
                Some(Set::MaxAnisotropy(a.min(f32::MAX as f64) as f32))
            }
            _ => None,
        };
        let Some(set) = set else {
            return self.bad_enum("pname", pname);
        };
        self.texture_changing();
        self.with_target_texture(cube, |t| {
            match set {
                Set::Min(f) => t.min_filter = f,
                Set::Mag(f) => t.mag_filter = f,
                Set::WrapS(w) => t.wrap_s = w,
                Set::WrapT(w) => t.wrap_t = w,
                Set::Generate(g) => t.generate_mipmap = g,
                Set::MaxLevel(l) => t.max_level = l,
                Set::MaxAnisotropy(a) => t.max_anisotropy = a,
            }
            t.touch();
        })
    }

    /// `glGetTexParameter{i,f,x}v`: the values, already in the form `kind` returns (fixed
    /// point for the crop rectangle of the `x` form, enums unconverted).
    pub fn get_tex_parameter(
        &mut self,
        target: GLenum,
        pname: GLenum,
        kind: ParamKind,
    ) -> Option<Vec<f64>> {
        let Some(cube) = object_target(target) else {
            self.bad_enum("target", target);
            return None;
        };
        let v = self.with_target_texture(cube, |t| -> Option<Vec<f64>> {
            let e = |v: GLenum| Some(vec![v as f64]);
            match pname {
                GL_TEXTURE_MIN_FILTER => e(match t.min_filter {
                    MinFilter::Nearest => GL_NEAREST,
                    MinFilter::Linear => GL_LINEAR,
                    MinFilter::NearestMipmapNearest => GL_NEAREST_MIPMAP_NEAREST,
                    MinFilter::LinearMipmapNearest => GL_LINEAR_MIPMAP_NEAREST,
                    MinFilter::NearestMipmapLinear => GL_NEAREST_MIPMAP_LINEAR,
                    MinFilter::LinearMipmapLinear => GL_LINEAR_MIPMAP_LINEAR,
                }),
                GL_TEXTURE_MAG_FILTER => e(match t.mag_filter {
                    MagFilter::Nearest => GL_NEAREST,
                    MagFilter::Linear => GL_LINEAR,
                }),
                GL_TEXTURE_WRAP_S | GL_TEXTURE_WRAP_T => {
                    let w = if pname == GL_TEXTURE_WRAP_S {
                        t.wrap_s
                    } else {
                        t.wrap_t
                    };
                    e(match w {
                        Wrap::Repeat => GL_REPEAT,
                        Wrap::ClampToEdge => GL_CLAMP_TO_EDGE,
                        Wrap::MirroredRepeat => GL_MIRRORED_REPEAT_OES,
                    })
                }
                GL_GENERATE_MIPMAP => e(GLenum::from(t.generate_mipmap)),
                GL_TEXTURE_MAX_LEVEL_APPLE => Some(vec![t.max_level as f64]),
                GL_TEXTURE_MAX_ANISOTROPY_EXT => Some(vec![match kind {
                    ParamKind::Fixed => fixed::from_f32(t.max_anisotropy) as f64,
                    ParamKind::Int => (t.max_anisotropy as f64).round(),
                    _ => t.max_anisotropy as f64,
                }]),
                GL_TEXTURE_CROP_RECT_OES => Some(
                    t.crop_rect
                        .iter()
                        .map(|&c| match kind {
                            ParamKind::Fixed => fixed::from_f32(c as f32) as f64,
                            _ => c as f64,
                        })
                        .collect(),
                ),
                _ => None,
            }
        });
        if v.is_none() {
            self.bad_enum("pname", pname);
        }
        v
    }

    /// Validates `glTexImage2D`'s arguments (ES 1.1 §3.7.1). The caller then reads
    /// `rect.len` bytes of pixels (if any) and calls [`Context::tex_image_2d`].
    #[allow(clippy::too_many_arguments)]
    pub fn tex_image_2d_layout(
        &self,
        target: GLenum,
        level: i32,
        internal_format: i32,
        width: i32,
        height: i32,
        border: i32,
        format: GLenum,
        ty: GLenum,
    ) -> Result<TexUpload, GLenum> {
        let face = image_target(target).ok_or(GL_INVALID_ENUM)?;
        let (f, t) = client_format(format, ty)?;
        // Cube map faces are square.
        if face != 0 && width != height {
            return Err(GL_INVALID_VALUE);
        }
        let sized = u32::try_from(internal_format).ok().and_then(sized_format);
        let internal = u32::try_from(internal_format).ok().and_then(|i| {
            if i == GL_BGRA_EXT {
                Some(BaseFormat::Rgba)
            } else {
                base_format(i).or(sized.map(|s| s.base))
            }
        });
        if internal.is_none() || !valid_image_size(level, width, height) || border != 0 {
            return Err(GL_INVALID_VALUE);
        }
        // The internal format must be the format (BGRA with BGRA), or a sized format that
        // takes it.
        let matches = match sized {
            Some(s) => s.takes(format, ty),
            None => {
                internal == Some(f)
                    && (internal_format as u32 == GL_BGRA_EXT) == (format == GL_BGRA_EXT)
            }
        };
        if !matches {
            return Err(GL_INVALID_OPERATION);
        }
        let size = t.pixel_size(f).ok_or(GL_INVALID_OPERATION)?;
        let rect = PixelRect::new(width as usize, height as usize, size, self.unpack_alignment)
            .ok_or(GL_OUT_OF_MEMORY)?;
        Ok(TexUpload {
            face,
            level: level as usize,
            x: 0,
            y: 0,
            format: f,
            ty: t,
            rect,
            sized,
        })
    }

    /// Specifies a level from validated arguments and the client pixels (`None`: contents
    /// left zeroed).
    pub fn tex_image_2d(&mut self, up: TexUpload, pixels: Option<&[u8]>) {
        let (w, h) = (up.rect.width as u32, up.rect.height as u32);
        let image = match pixels {
            Some(p) => {
                gles_cm_core::texture::unpack(up.format, up.ty, up.rect, p).map(|texels| Image {
                    width: w,
                    height: h,
                    format: up.format,
                    texels,
                })
            }
            None => Image::try_blank(w, h, up.format),
        };
        let Some(mut image) = image else {
            return self.set_error(GL_OUT_OF_MEMORY);
        };
        if let Some(s) = up.sized {
            s.store(&mut image.texels);
        }
        self.texture_changing();
        self.with_face_texture(up.face, |t| {
            t.set_face_level(up.face, up.level, image);
            if let Some(s) = up.sized {
                t.tag_level(up.face, up.level, s.internal);
            }
        });
    }

    /// Validates `glTexSubImage2D`'s arguments against the bound texture.
    #[allow(clippy::too_many_arguments)]
    pub fn tex_sub_image_2d_layout(
        &mut self,
        target: GLenum,
        level: i32,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
        format: GLenum,
        ty: GLenum,
    ) -> Result<TexUpload, GLenum> {
        let face = image_target(target).ok_or(GL_INVALID_ENUM)?;
        let (f, t) = client_format(format, ty)?;
        let level_format = self.check_sub_region(face, level, x, y, width, height)?;
        if level_format != f {
            return Err(GL_INVALID_OPERATION);
        }
        let size = t.pixel_size(f).ok_or(GL_INVALID_OPERATION)?;
        let rect = PixelRect::new(width as usize, height as usize, size, self.unpack_alignment)
            .ok_or(GL_OUT_OF_MEMORY)?;
        Ok(TexUpload {
            face,
            level: level as usize,
            x: x as u32,
            y: y as u32,
            format: f,
            ty: t,
            rect,
            sized: None,
        })
    }

    /// The level's format when (x, y, w, h) fits inside level `level` of the bound texture:
    /// `GL_INVALID_VALUE` for a bad level or region, `GL_INVALID_OPERATION` when the level
    /// was never specified.
    fn check_sub_region(
        &mut self,
        face: u8,
        level: i32,
        x: i32,
        y: i32,
        w: i32,
        h: i32,
    ) -> Result<BaseFormat, GLenum> {
        if !(0..=MAX_LEVEL as i32).contains(&level) || w < 0 || h < 0 || x < 0 || y < 0 {
            return Err(GL_INVALID_VALUE);
        }
        let dims = self.with_face_texture(face, |t| {
            t.face_level(face, level as usize)
                .map(|i| (i.width, i.height, i.format))
        });
        let Some((lw, lh, format)) = dims else {
            return Err(GL_INVALID_OPERATION);
        };
        if x as i64 + w as i64 > lw as i64 || y as i64 + h as i64 > lh as i64 {
            return Err(GL_INVALID_VALUE);
        }
        Ok(format)
    }

    pub fn tex_sub_image_2d(&mut self, up: TexUpload, pixels: &[u8]) {
        let Some(texels) = gles_cm_core::texture::unpack(up.format, up.ty, up.rect, pixels) else {
            return self.set_error(GL_OUT_OF_MEMORY);
        };
        let (w, h) = (up.rect.width as u32, up.rect.height as u32);
        if w == 0 || h == 0 {
            return;
        }
        self.write_level_region(up.face, up.level, [up.x, up.y, w, h], texels);
    }

    /// Writes texels over a region of a level, rounded to the precision of the sized format
    /// the level was specified in.
    fn write_level_region(&mut self, face: u8, level: usize, r: [u32; 4], mut texels: Vec<u32>) {
        self.texture_changing();
        self.with_face_texture(face, |t| {
            let tag = t.level_tag(face, level);
            if let Some(s) = tag.and_then(sized_format) {
                s.store(&mut texels);
            }
            t.write_face_region(face, level, r[0], r[1], r[2], r[3], &texels);
            // The write may have copied the level (draws still reading the old one): the
            // copy keeps the level's format.
            if let Some(tag) = tag {
                t.tag_level(face, level, tag);
            }
        });
    }

    /// Validates `glCompressedTexImage2D`: the data must be exactly `image_size` bytes.
    /// Returns the format, the number of levels the blob holds and the image target's face
    /// ([`image_target`]).
    #[allow(clippy::too_many_arguments)]
    pub fn compressed_tex_image_2d_check(
        &self,
        target: GLenum,
        level: i32,
        internal_format: GLenum,
        width: i32,
        height: i32,
        border: i32,
        image_size: i32,
    ) -> Result<(Compressed, usize, u8), GLenum> {
        let face = image_target(target).ok_or(GL_INVALID_ENUM)?;
        if face != 0 && width != height {
            return Err(GL_INVALID_VALUE);
        }
        if internal_format == GL_ETC1_RGB8_OES {
            // One level per call; the size must be the blocks' (8 bytes per 4 × 4 block).
            if !valid_image_size(level, width, height) || border != 0 || image_size < 0 {
                return Err(GL_INVALID_VALUE);
            }
            let size = gles_cm_core::texture::etc1_size(width as u32, height as u32);
            if image_size as usize != size {
                return Err(GL_INVALID_VALUE);
            }
            return Ok((Compressed::Etc1, level as usize, face));
        }
        if let Some(f) = pvrtc_format(internal_format) {
            // PVRTC1 images are powers of two, whatever OES_texture_npot allows others.
            let pot = |s: i32| s > 0 && (s as u32).is_power_of_two();
            if !valid_image_size(level, width, height)
                || border != 0
                || image_size < 0
                || !pot(width)
                || !pot(height)
                || image_size as usize != f.image_size(width as u32, height as u32)
            {
                return Err(GL_INVALID_VALUE);
            }
            return Ok((Compressed::Pvrtc(f), level as usize, face));
        }
        if let Some(f) = s3tc_format(internal_format) {
            if !valid_image_size(level, width, height)
                || border != 0
                || image_size < 0
                || image_size as usize != f.image_size(width as u32, height as u32)
            {
                return Err(GL_INVALID_VALUE);
            }
            let angle = matches!(f, S3tcFormat::Dxt3 | S3tcFormat::Dxt5);
            if angle && !(whole_blocks(width) && whole_blocks(height)) {
                return Err(GL_INVALID_OPERATION);
            }
            return Ok((Compressed::S3tc(f), level as usize, face));
        }
        let Some(f) = palette_format(internal_format) else {
            return Err(GL_INVALID_ENUM);
        };
        // Paletted images give level 0 and, with level -n, n further levels in one blob.
        if level > 0
            || level < -(MAX_LEVEL as i32)
            || !valid_image_size(0, width, height)
            || border != 0
        {
            return Err(GL_INVALID_VALUE);
        }
        // -level may exceed the image's own chain (as long as it stays within the largest
        // texture's): the extra levels are 1 × 1, as the size formula counts them.
        let levels = (1 - level) as usize;
        if image_size < 0 {
            return Err(GL_INVALID_VALUE);
        }
        if image_size as usize != f.image_size(width as u32, height as u32, levels) {
            return Err(GL_INVALID_VALUE);
        }
        Ok((Compressed::Palette(f), levels, face))
    }

    /// Specifies levels 0 .. `levels` from a paletted blob (`None`: contents zeroed).
    /// For the other formats, one level: `levels` is its number. `tag` is the format's
    /// enum, kept with single levels for [`Context::compressed_tex_sub_image_2d`].
    #[allow(clippy::too_many_arguments)]
    pub fn compressed_tex_image_2d(
        &mut self,
        face: u8,
        format: Compressed,
        tag: GLenum,
        levels: usize,
        width: i32,
        height: i32,
        data: Option<&[u8]>,
    ) {
        let (w, h) = (width as u32, height as u32);
        let single = |decoded: Option<Image>, base: BaseFormat| {
            decoded.unwrap_or_else(|| Image::blank(w, h, base))
        };
        let image = match format {
            Compressed::Palette(f) => {
                return self.paletted_tex_image_2d(face, f, levels, w, h, data)
            }
            Compressed::Etc1 => single(
                data.and_then(|d| gles_cm_core::texture::decode_etc1(w, h, d)),
                BaseFormat::Rgb,
            ),
            Compressed::Pvrtc(f) => single(data.and_then(|d| f.decode(w, h, d)), f.base_format()),
            Compressed::S3tc(f) => single(data.and_then(|d| f.decode(w, h, d)), f.base_format()),
        };
        self.texture_changing();
        self.with_face_texture(face, |t| {
            t.set_face_level(face, levels, image);
            t.tag_level(face, levels, tag);
        });
    }

    /// Levels 0 .. `levels` from a paletted blob (`None`: contents zeroed).
    fn paletted_tex_image_2d(
        &mut self,
        face: u8,
        format: PaletteFormat,
        levels: usize,
        w: u32,
        h: u32,
        data: Option<&[u8]>,
    ) {
        let images = match data.and_then(|d| format.decode(w, h, levels, d)) {
            Some(images) => images,
            None => {
                let mut v = Vec::new();
                let (mut lw, mut lh) = (w, h);
                for _ in 0..levels {
                    v.push(Image::blank(lw, lh, format.base_format()));
                    (lw, lh) = ((lw / 2).max(1), (lh / 2).max(1));
                }
                v
            }
        };
        self.texture_changing();
        // With GENERATE_MIPMAP, a single-level blob gets its chain generated (set_level does
        // it for level 0); an explicit chain is kept as given.
        self.with_face_texture(face, |t| {
            let generate = t.generate_mipmap && images.len() > 1;
            if generate {
                t.generate_mipmap = false;
            }
            for (l, img) in images.into_iter().enumerate() {
                t.set_face_level(face, l, img);
            }
            if generate {
                t.generate_mipmap = true;
            }
        });
    }

    /// Validates `glCompressedTexSubImage2D`; `Ok` carries what
    /// [`Context::compressed_tex_sub_image_2d`] needs. Paletted images take no updates
    /// (ES 1.1 §3.7.3). ETC1 (`EXT_compressed_ETC1_RGB8_sub_texture`) and S3TC update
    /// whole 4 × 4 blocks: offsets on block boundaries, sizes whole blocks or reaching the
    /// level's edge. PVRTC replaces whole levels only (offset 0, the level's size). The
    /// format must be the one the level was specified in.
    #[allow(clippy::too_many_arguments)]
    pub fn compressed_tex_sub_image_2d_check(
        &mut self,
        target: GLenum,
        level: i32,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
        format: GLenum,
        image_size: i32,
    ) -> Result<CompressedUpdate, GLenum> {
        let face = image_target(target).ok_or(GL_INVALID_ENUM)?;
        let kind = if format == GL_ETC1_RGB8_OES {
            Compressed::Etc1
        } else if let Some(f) = pvrtc_format(format) {
            Compressed::Pvrtc(f)
        } else if let Some(f) = s3tc_format(format) {
            Compressed::S3tc(f)
        } else if let Some(f) = palette_format(format) {
            Compressed::Palette(f)
        } else {
            return Err(GL_INVALID_ENUM);
        };
        if !(0..=MAX_LEVEL as i32).contains(&level)
            || x < 0
            || y < 0
            || width < 0
            || height < 0
            || image_size < 0
        {
            return Err(GL_INVALID_VALUE);
        }
        let level = level as usize;
        let (lw, lh, tag) = self
            .with_face_texture(face, |t| {
                let img = t.face_level(face, level)?;
                Some((
                    img.width as i64,
                    img.height as i64,
                    t.level_tag(face, level),
                ))
            })
            .ok_or(GL_INVALID_OPERATION)?;
        if matches!(kind, Compressed::Palette(_)) || tag != Some(format) {
            return Err(GL_INVALID_OPERATION);
        }
        let (x64, y64, w64, h64) = (x as i64, y as i64, width as i64, height as i64);
        if x64 + w64 > lw || y64 + h64 > lh {
            return Err(GL_INVALID_VALUE);
        }
        let (w, h) = (width as u32, height as u32);
        let size = match kind {
            Compressed::Pvrtc(f) => {
                if (x, y, w64, h64) != (0, 0, lw, lh) {
                    return Err(GL_INVALID_VALUE);
                }
                f.image_size(w, h)
            }
            Compressed::S3tc(f) => f.image_size(w, h),
            _ => gles_cm_core::texture::etc1_size(w, h),
        };
        if !matches!(kind, Compressed::Pvrtc(_)) {
            let fits = |o: i64, n: i64, edge: i64| o % 4 == 0 && (n % 4 == 0 || o + n == edge);
            if !fits(x64, w64, lw) || !fits(y64, h64, lh) {
                return Err(GL_INVALID_OPERATION);
            }
        }
        if image_size as usize != size {
            return Err(GL_INVALID_VALUE);
        }
        Ok(CompressedUpdate {
            face,
            level,
            kind,
            x: x as u32,
            y: y as u32,
            width: w,
            height: h,
        })
    }

    /// `glCompressedTexSubImage2D` after [`Context::compressed_tex_sub_image_2d_check`]:
    /// decodes `data` and writes it over the level's region (PVRTC: replaces the level,
    /// keeping its tag).
    pub fn compressed_tex_sub_image_2d(&mut self, up: CompressedUpdate, data: Option<&[u8]>) {
        let (w, h) = (up.width, up.height);
        let Some(data) = data.filter(|_| w > 0 && h > 0) else {
            return;
        };
        let decoded = match up.kind {
            Compressed::Pvrtc(f) => f.decode(w, h, data),
            Compressed::S3tc(f) => f.decode(w, h, data),
            _ => gles_cm_core::texture::decode_etc1(w, h, data),
        };
        let Some(image) = decoded else {
            return;
        };
        self.texture_changing();
        self.with_face_texture(up.face, |t| {
            let tag = t.level_tag(up.face, up.level);
            if matches!(up.kind, Compressed::Pvrtc(_)) {
                t.set_face_level(up.face, up.level, image);
                if let Some(tag) = tag {
                    t.tag_level(up.face, up.level, tag);
                }
            } else {
                t.write_face_region(up.face, up.level, up.x, up.y, w, h, &image.texels);
                // The write may have copied the level (draws still reading the old one):
                // the copy keeps the level's format.
                if let Some(tag) = tag {
                    t.tag_level(up.face, up.level, tag);
                }
            }
        });
    }

    /// The read surface's color format, flushing its pending rendering first.
    fn read_color_format(&mut self) -> Option<ColorFormat> {
        if !self.framebuffer_ready() {
            return None;
        }
        self.flush();
        let r = self.read_surface()?;
        let f = lock_target(r.as_ref()).format().color;
        Some(f)
    }

    /// `glCopyTexImage2D` (ES 1.1 §3.7.2).
    #[allow(clippy::too_many_arguments)]
    pub fn copy_tex_image_2d(
        &mut self,
        target: GLenum,
        level: i32,
        internal_format: GLenum,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
        border: i32,
    ) {
        let Some(face) = image_target(target) else {
            return self.bad_enum("target", target);
        };
        let sized = sized_format(internal_format);
        let Some(format) = base_format(internal_format).or(sized.map(|s| s.base)) else {
            return self.bad_enum("internalformat", internal_format);
        };
        if !valid_image_size(level, width, height) || border != 0 || (face != 0 && width != height)
        {
            return self.set_error(GL_INVALID_VALUE);
        }
        let Some(color) = self.read_color_format() else {
            return self.bad_operation("the read framebuffer has no color buffer to copy from");
        };
        if !copy_compatible(color, format) {
            return self.bad_operation(
                "internalformat needs components the read framebuffer's color buffer does not have",
            );
        }
        let r = self.read_surface().expect("checked");
        let texels = read_region(
            &lock_target(r.as_ref()),
            x,
            y,
            width as u32,
            height as u32,
            format,
        );
        let Some(mut texels) = texels else {
            return self.set_error(GL_OUT_OF_MEMORY);
        };
        if let Some(s) = sized {
            s.store(&mut texels);
        }
        let image = Image {
            width: width as u32,
            height: height as u32,
            format,
            texels,
        };
        self.texture_changing();
        self.with_face_texture(face, |t| {
            t.set_face_level(face, level as usize, image);
            if let Some(s) = sized {
                t.tag_level(face, level as usize, s.internal);
            }
        });
    }

    /// `glCopyTexSubImage2D`.
    #[allow(clippy::too_many_arguments)]
    pub fn copy_tex_sub_image_2d(
        &mut self,
        target: GLenum,
        level: i32,
        xoffset: i32,
        yoffset: i32,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
    ) {
        let Some(face) = image_target(target) else {
            return self.bad_enum("target", target);
        };
        let format = match self.check_sub_region(face, level, xoffset, yoffset, width, height) {
            Ok(f) => f,
            Err(e) => return self.set_error(e),
        };
        let Some(color) = self.read_color_format() else {
            return self.bad_operation("the read framebuffer has no color buffer to copy from");
        };
        if !copy_compatible(color, format) {
            return self.bad_operation("the level's format needs components the read framebuffer's color buffer does not have");
        }
        if width == 0 || height == 0 {
            return;
        }
        let r = self.read_surface().expect("checked");
        let texels = read_region(
            &lock_target(r.as_ref()),
            x,
            y,
            width as u32,
            height as u32,
            format,
        );
        let Some(texels) = texels else {
            return self.set_error(GL_OUT_OF_MEMORY);
        };
        let region = [xoffset as u32, yoffset as u32, width as u32, height as u32];
        self.write_level_region(face, level as usize, region, texels);
    }

    /// The texture state `glGet*` reports.
    pub(super) fn texture_value(&mut self, pname: GLenum) -> Option<Value> {
        Some(match pname {
            GL_TEXTURE_BINDING_2D => {
                Value::int(self.textures.bound[self.active_texture].name as i64)
            }
            GL_TEXTURE_BINDING_CUBE_MAP_OES => {
                Value::int(self.textures.bound_cube[self.active_texture].name as i64)
            }
            GL_MAX_TEXTURE_SIZE | GL_MAX_CUBE_MAP_TEXTURE_SIZE_OES => {
                Value::int(MAX_TEXTURE_SIZE as i64)
            }
            GL_NUM_COMPRESSED_TEXTURE_FORMATS => Value::int(COMPRESSED_FORMATS.len() as i64),
            GL_COMPRESSED_TEXTURE_FORMATS => Value::ints(&COMPRESSED_FORMATS.map(|f| f as i64)),
            _ => return None,
        })
    }

    /// The `eglBindTexImage` hook: copies `target`'s color buffer into level 0 of the texture
    /// bound to the active unit as RGBA (`rgba`, for `EGL_TEXTURE_RGBA`) or RGB, replacing
    /// all levels; with `mipmap` (`EGL_MIPMAP_TEXTURE` true) the chain below is generated.
    /// The caller has completed the surface's own rendering (EGL flushes the context that
    /// draws into it) and locked `target`. Raises no GL error; false when the texels cannot
    /// be allocated (the texture is then unchanged).
    pub fn bind_tex_image(&mut self, target: &Target, rgba: bool, mipmap: bool) -> bool {
        let format = if rgba {
            BaseFormat::Rgba
        } else {
            BaseFormat::Rgb
        };
        let Some(texels) = read_region(target, 0, 0, target.width(), target.height(), format)
        else {
            return false;
        };
        let image = Image {
            width: target.width(),
            height: target.height(),
            format,
            texels,
        };
        self.texture_changing();
        self.with_bound_texture(|t| {
            t.clear_levels();
            t.set_level(0, image);
            if mipmap {
                t.generate_mipmaps();
            }
        });
        true
    }

    /// The `eglReleaseTexImage` hook: the texture bound to the active unit loses its images.
    pub fn release_tex_image(&mut self) {
        self.texture_changing();
        self.with_bound_texture(Texture::clear_levels);
    }
    /// The `eglCreateImage` hook (`EGL_KHR_gl_texture_2D_image`): a copy of `level` of the
    /// 2D texture named `name`.
    pub fn egl_image_source(&self, name: GLuint, level: usize) -> Result<Image, ImageSourceError> {
        let o = lock_objects(&self.shared);
        let t = o
            .textures
            .named(name)
            .filter(|t| !t.is_cube_map())
            .ok_or(ImageSourceError::NotATexture2D)?;
        // Level 0 must exist; another level must be one the texture has.
        let image = t.level(level).ok_or(if level == 0 {
            ImageSourceError::NotATexture2D
        } else {
            ImageSourceError::NoSuchLevel
        })?;
        Ok(image.clone())
    }

    /// `glEGLImageTargetTexture2DOES` (`OES_EGL_image`): the texture bound to the active
    /// unit's `GL_TEXTURE_2D` takes `image` as its only level.
    pub fn egl_image_target_texture_2d(&mut self, target: GLenum, image: Option<Image>) {
        if target != GL_TEXTURE_2D {
            return self.set_error(GL_INVALID_ENUM);
        }
        let Some(image) = image else {
            return self.set_error(GL_INVALID_VALUE);
        };
        self.texture_changing();
        self.with_bound_texture(|t| {
            t.clear_levels();
            t.set_level(0, image);
        });
    }
}

/// Why a texture cannot be the source of an EGLImage.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImageSourceError {
    /// No 2D texture of that name, or its level 0 is not specified.
    NotATexture2D,
    /// The texture has no such level.
    NoSuchLevel,
}

/// A value no GL enum has, for parameters that did not convert to an integer.
const GL_NONE_INVALID: GLenum = u32::MAX;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn image_sizes_must_fit_the_level() {
        assert!(valid_image_size(0, 0, 0));
        assert!(valid_image_size(0, 1, 2048));
        assert!(!valid_image_size(0, 4096, 1));
        assert!(valid_image_size(0, 3, 300));
        assert!(valid_image_size(1, 1023, 1));
        assert!(!valid_image_size(1, 1025, 1));
        assert!(!valid_image_size(0, -1, 4));
        assert!(valid_image_size(1, 1024, 1024));
        assert!(!valid_image_size(1, 2048, 1));
        assert!(valid_image_size(11, 1, 1));
        assert!(!valid_image_size(12, 1, 1));
        assert!(!valid_image_size(-1, 1, 1));
    }

    #[test]
    fn palette_formats_in_registry_order() {
        let f = palette_format(GL_PALETTE8_RGBA4_OES).unwrap();
        assert_eq!((f.index_bits, f.entry), (8, PaletteEntry::Rgba4));
        let f = palette_format(GL_PALETTE4_R5_G6_B5_OES).unwrap();
        assert_eq!((f.index_bits, f.entry), (4, PaletteEntry::R5G6B5));
        assert!(palette_format(GL_RGBA).is_none());
    }

    #[test]
    fn copies_need_the_components_of_the_texture_format() {
        assert!(copy_compatible(ColorFormat::Rgb565, BaseFormat::Luminance));
        assert!(copy_compatible(ColorFormat::Rgb888, BaseFormat::Rgb));
        assert!(!copy_compatible(ColorFormat::Rgb888, BaseFormat::Alpha));
        assert!(!copy_compatible(
            ColorFormat::Rgb565,
            BaseFormat::LuminanceAlpha
        ));
        assert!(copy_compatible(ColorFormat::Rgba8888, BaseFormat::Alpha));
    }
}
