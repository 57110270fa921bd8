//! Texture objects: sampler parameters, mip chains of RGBA8 texels, pixel unpacking, mipmap
//! generation and the `OES_compressed_paletted_texture` and ETC1 decoders (PVRTC and S3TC
//! in [`pvrtc`] and [`s3tc`]). Plain Rust: the GL layer
//! (`gles/texture.rs`) validates enums and sizes and calls in here.
//!
//! Every level keeps its base format (what GL reports and what texture environments combine
//! with) and its texels expanded to RGBA8 words (`[r, g, b, a]` bytes, little-endian `u32`,
//! as [`super::Target`] stores color): L → (L, L, L, 255), A → (0, 0, 0, A),
//! LA → (L, L, L, A), RGB → (R, G, B, 255). Packed 16-bit types widen as round(v · 255 / (2ⁿ − 1))
//! ([`super::target::expand_to_8`]), so 5-bit 31 is 255 and 4-bit 8 is 0x88. Row 0 is the
//! first row the application gave (t = 0).

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Weak};

use super::target::expand_to_8;

pub mod pvrtc;
pub mod s3tc;

/// The largest width and height of a level-0 image (`GL_MAX_TEXTURE_SIZE`).
pub const MAX_TEXTURE_SIZE: u32 = 2048;
/// log2([`MAX_TEXTURE_SIZE`]): the largest mipmap level number.
pub const MAX_LEVEL: usize = 11;

/// The base internal formats of OpenGL ES 1.1.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BaseFormat {
    Alpha,
    Luminance,
    LuminanceAlpha,
    Rgb,
    Rgba,
}

impl BaseFormat {
    /// Components per texel in client memory with `GL_UNSIGNED_BYTE`.
    pub fn components(self) -> usize {
        match self {
            BaseFormat::Alpha | BaseFormat::Luminance => 1,
            BaseFormat::LuminanceAlpha => 2,
            BaseFormat::Rgb => 3,
            BaseFormat::Rgba => 4,
        }
    }

    pub fn has_alpha(self) -> bool {
        matches!(
            self,
            BaseFormat::Alpha | BaseFormat::LuminanceAlpha | BaseFormat::Rgba
        )
    }

    pub fn has_color(self) -> bool {
        !matches!(self, BaseFormat::Alpha)
    }
}

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

fn word(r: u8, g: u8, b: u8, a: u8) -> u32 {
    u32::from_le_bytes([r, g, b, a])
}

/// Converts one client pixel to an RGBA8 word.
fn unpack_pixel(format: BaseFormat, ty: PixelType, p: &[u8]) -> u32 {
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

fn unpack_565(v: u32) -> u32 {
    word(
        expand_to_8(v >> 11, 5),
        expand_to_8((v >> 5) & 63, 6),
        expand_to_8(v & 31, 5),
        255,
    )
}

fn unpack_4444(v: u32) -> u32 {
    word(
        expand_to_8(v >> 12, 4),
        expand_to_8((v >> 8) & 15, 4),
        expand_to_8((v >> 4) & 15, 4),
        expand_to_8(v & 15, 4),
    )
}

fn unpack_5551(v: u32) -> u32 {
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

/// One mipmap level.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    pub width: u32,
    pub height: u32,
    pub format: BaseFormat,
    /// `width * height` RGBA8 words, row 0 first.
    pub texels: Vec<u32>,
}

impl Image {
    /// An image of `format` filled with the expansion of zero bytes (the contents of a level
    /// specified without data are undefined; zeros keep them deterministic).
    pub fn blank(width: u32, height: u32, format: BaseFormat) -> Image {
        Image::try_blank(width, height, format).expect("texels allocated")
    }

    /// [`Image::blank`], or `None` when the texels cannot be allocated.
    pub fn try_blank(width: u32, height: u32, format: BaseFormat) -> Option<Image> {
        let zero = unpack_pixel(format, PixelType::UnsignedByte, &[0; 4]);
        Some(Image {
            width,
            height,
            format,
            texels: crate::core::target::try_filled(width as usize * height as usize, zero)?,
        })
    }

    pub fn texel(&self, x: u32, y: u32) -> [u8; 4] {
        self.texels[(y * self.width + x) as usize].to_le_bytes()
    }

    /// The next smaller mipmap level: a box filter over 2 × 2 texels (2 × 1 or 1 × 2 once a
    /// side is 1), each channel the rounded mean `(sum + n/2) / n`.
    pub fn half(&self) -> Image {
        let (w, h) = ((self.width / 2).max(1), (self.height / 2).max(1));
        let sx = if self.width > 1 { 2 } else { 1 };
        let sy = if self.height > 1 { 2 } else { 1 };
        let n = sx * sy;
        let mut texels = Vec::with_capacity(w as usize * h as usize);
        for y in 0..h {
            for x in 0..w {
                let mut sum = [0u32; 4];
                for dy in 0..sy {
                    for dx in 0..sx {
                        let t = self.texel(x * sx + dx, y * sy + dy);
                        for c in 0..4 {
                            sum[c] += t[c] as u32;
                        }
                    }
                }
                let m = sum.map(|s| ((s + n / 2) / n) as u8);
                texels.push(u32::from_le_bytes(m));
            }
        }
        Image {
            width: w,
            height: h,
            format: self.format,
            texels,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MinFilter {
    Nearest,
    Linear,
    NearestMipmapNearest,
    LinearMipmapNearest,
    NearestMipmapLinear,
    LinearMipmapLinear,
}

impl MinFilter {
    pub fn uses_mipmaps(self) -> bool {
        !matches!(self, MinFilter::Nearest | MinFilter::Linear)
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MagFilter {
    Nearest,
    Linear,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Wrap {
    Repeat,
    ClampToEdge,
    /// `OES_texture_mirrored_repeat`.
    MirroredRepeat,
}

impl Wrap {
    /// The texel index `i` of a level `n` texels wide lands on (`OES_texture_npot`: any
    /// `n` ≥ 1). Powers of two wrap with a mask; other sizes pay a division.
    #[inline(always)]
    pub fn index(self, i: i32, n: i32) -> i32 {
        if n & (n - 1) == 0 {
            self.index_pot(i, n)
        } else {
            self.index_npot(i, n)
        }
    }

    /// [`Wrap::index`] for `n` a power of two.
    #[inline(always)]
    pub fn index_pot(self, i: i32, n: i32) -> i32 {
        match self {
            Wrap::Repeat => i & (n - 1),
            Wrap::ClampToEdge => i.clamp(0, n - 1),
            Wrap::MirroredRepeat => {
                let m = i & (2 * n - 1);
                if m >= n {
                    2 * n - 1 - m
                } else {
                    m
                }
            }
        }
    }

    /// [`Wrap::index`] for any `n` ≥ 1 (in i64: 2n and the remainder of i32::MIN stay in
    /// range).
    #[inline(always)]
    pub fn index_npot(self, i: i32, n: i32) -> i32 {
        let (i, n) = (i as i64, n as i64);
        (match self {
            Wrap::Repeat => i.rem_euclid(n),
            Wrap::ClampToEdge => i.clamp(0, n - 1),
            Wrap::MirroredRepeat => {
                let m = i.rem_euclid(2 * n);
                if m >= n {
                    2 * n - 1 - m
                } else {
                    m
                }
            }
        }) as i32
    }

    /// Whether adding `k` to a coordinate changes nothing sampled: whole periods under
    /// REPEAT, even ones under MIRRORED_REPEAT (the pipeline subtracts such offsets to keep
    /// large coordinates precise).
    pub fn period(self) -> Option<f64> {
        match self {
            Wrap::Repeat => Some(1.0),
            Wrap::MirroredRepeat => Some(2.0),
            Wrap::ClampToEdge => None,
        }
    }
}

/// A source of generations: every change to any texture takes a new number, so a
/// (texture, version) pair seen once never reappears after a change, deletion or reuse.
static GENERATION: AtomicU64 = AtomicU64::new(1);

fn next_generation() -> u64 {
    GENERATION.fetch_add(1, Ordering::Relaxed)
}

/// Rounds every channel of RGBA8 `texels` to `bits` bits ([r, g, b, a], 8 leaves a
/// channel alone) and widens it back, as a texture stored at that precision reads
/// (`OES_required_internalformat`'s 16-bit and luminance-4 formats).
pub fn requantize(texels: &mut [u32], bits: [u32; 4]) {
    for t in texels {
        let b = t.to_le_bytes();
        let q: [u8; 4] = std::array::from_fn(|c| {
            let n = bits[c];
            if n >= 8 {
                return b[c];
            }
            let max = (1u32 << n) - 1;
            expand_to_8((b[c] as u32 * max + 127) / 255, n)
        });
        *t = u32::from_le_bytes(q);
    }
}

/// Replaces levels 1 .. of `chain` with box-filtered reductions of its level 0.
fn generate_chain(chain: &mut [Option<Arc<Image>>]) {
    let Some(mut img) = chain[0].as_deref().cloned() else {
        return;
    };
    for slot in &mut chain[1..] {
        if img.width <= 1 && img.height <= 1 {
            *slot = None;
            continue;
        }
        img = img.half();
        *slot = Some(Arc::new(img.clone()));
    }
}

/// A 2D texture object.
#[derive(Clone, Debug)]
pub struct Texture {
    pub min_filter: MinFilter,
    pub mag_filter: MagFilter,
    pub wrap_s: Wrap,
    pub wrap_t: Wrap,
    pub generate_mipmap: bool,
    /// `OES_draw_texture`'s crop rectangle: u, v, width, height in texels.
    pub crop_rect: [i32; 4],
    /// `APPLE_texture_max_level`: the deepest level mipmapping uses (as set: initially
    /// 1000; levels past [`MAX_LEVEL`] do not exist anyway).
    pub max_level: u32,
    /// `EXT_texture_filter_anisotropic`'s `GL_TEXTURE_MAX_ANISOTROPY_EXT` as set (≥ 1);
    /// samplers use at most [`MAX_ANISOTROPY`].
    pub max_anisotropy: f32,
    /// Levels 0 ..= [`MAX_LEVEL`]; `None` where none has been specified. Shared with the
    /// [`Sampler`] snapshots of pending draws, so a change copies a level rather than
    /// altering what those draws read.
    levels: Vec<Option<Arc<Image>>>,
    /// `OES_texture_cube_map`: set once the texture was first bound as a cube map. Its
    /// POSITIVE_X face is `levels`; the other five faces, in the order of the face enums,
    /// are here.
    cube: Option<Box<[Chain; 5]>>,
    /// The internal formats levels were specified in where the base format does not say
    /// it all (compressed and sized formats), for the GL layer: (face, level, the image as
    /// specified, the format's tag). A tag holds only while that very image is the
    /// level's, so respecifying, generating or clearing a level drops it without
    /// bookkeeping here. Empty for textures never given such formats.
    level_tags: Vec<(u8, usize, Weak<Image>, u32)>,
    version: u64,
}

/// One face's mipmap levels.
type Chain = Vec<Option<Arc<Image>>>;

impl Default for Texture {
    fn default() -> Texture {
        Texture::new()
    }
}

impl Texture {
    /// A texture with the initial state of the specification: no images,
    /// NEAREST_MIPMAP_LINEAR / LINEAR filters, REPEAT wrapping, no mipmap generation.
    pub fn new() -> Texture {
        Texture {
            min_filter: MinFilter::NearestMipmapLinear,
            mag_filter: MagFilter::Linear,
            wrap_s: Wrap::Repeat,
            wrap_t: Wrap::Repeat,
            generate_mipmap: false,
            crop_rect: [0; 4],
            max_level: 1000,
            max_anisotropy: 1.0,
            levels: vec![None; MAX_LEVEL + 1],
            cube: None,
            level_tags: Vec::new(),
            version: next_generation(),
        }
    }

    /// A new texture of the cube map kind (`OES_texture_cube_map`).
    pub fn new_cube_map() -> Texture {
        Texture {
            cube: Some(Box::new(std::array::from_fn(|_| vec![None; MAX_LEVEL + 1]))),
            ..Texture::new()
        }
    }

    pub fn is_cube_map(&self) -> bool {
        self.cube.is_some()
    }

    /// The level chain of `face`: 0 for a 2D texture, 1 ..= 6 for the cube faces POSITIVE_X,
    /// NEGATIVE_X, POSITIVE_Y, NEGATIVE_Y, POSITIVE_Z, NEGATIVE_Z. `None` for a face the
    /// texture does not have.
    fn chain(&self, face: u8) -> Option<&Vec<Option<Arc<Image>>>> {
        match (face, &self.cube) {
            (0, None) | (1, Some(_)) => Some(&self.levels),
            (2..=6, Some(c)) => Some(&c[face as usize - 2]),
            _ => None,
        }
    }

    fn chain_mut(&mut self, face: u8) -> Option<&mut Vec<Option<Arc<Image>>>> {
        match (face, &mut self.cube) {
            (0, None) | (1, Some(_)) => Some(&mut self.levels),
            (2..=6, Some(c)) => Some(&mut c[face as usize - 2]),
            _ => None,
        }
    }

    /// Level `level` of `face` (see [`Texture::chain`] for face numbers).
    pub fn face_level(&self, face: u8, level: usize) -> Option<&Image> {
        self.chain(face)?.get(level)?.as_deref()
    }

    /// Marks the current image of `face`'s `level` as specified in the internal format
    /// `tag` (see [`Texture::level_tag`]).
    pub fn tag_level(&mut self, face: u8, level: usize, tag: u32) {
        let Some(img) = self.chain(face).and_then(|c| c.get(level)?.as_ref()) else {
            return;
        };
        let img = Arc::downgrade(img);
        self.level_tags
            .retain(|(f, l, i, _)| (*f, *l) != (face, level) && i.strong_count() > 0);
        self.level_tags.push((face, level, img, tag));
    }

    /// The tag [`Texture::tag_level`] gave `face`'s `level`, while that image is still the
    /// level's; `None` for a level specified otherwise.
    pub fn level_tag(&self, face: u8, level: usize) -> Option<u32> {
        let img = self.chain(face)?.get(level)?.as_ref()?;
        self.level_tags
            .iter()
            .find(|(f, l, i, _)| (*f, *l) == (face, level) && Weak::ptr_eq(i, &Arc::downgrade(img)))
            .map(|e| e.3)
    }

    /// [`Texture::store_rendered`] for a face.
    pub fn store_rendered_face(&mut self, face: u8, level: usize, texels: &[u32]) -> bool {
        if face <= 1 {
            return (face == 0) == self.cube.is_none() && self.store_rendered(level, texels);
        }
        let Some(img) = self
            .chain_mut(face)
            .and_then(|c| c.get_mut(level))
            .and_then(Option::as_mut)
        else {
            return false;
        };
        if img.texels.len() != texels.len() {
            return false;
        }
        let img = Arc::make_mut(img);
        let format = img.format;
        for (d, &s) in img.texels.iter_mut().zip(texels) {
            *d = convert_word(format, s);
        }
        self.touch();
        true
    }

    /// Replaces level `level` of cube face `face` (1 ..= 6) with `image`; with
    /// [`Texture::generate_mipmap`] set, a new level 0 regenerates that face's chain.
    pub fn set_face_level(&mut self, face: u8, level: usize, image: Image) {
        if face <= 1 {
            return self.set_level(level, image);
        }
        let generate = level == 0 && self.generate_mipmap;
        if let Some(c) = self.chain_mut(face) {
            c[level] = Some(Arc::new(image));
            if generate {
                generate_chain(c);
            }
        }
        self.touch();
    }

    /// `glGenerateMipmapOES`: regenerates every face's chain from its level 0. False (and
    /// nothing changed) when a cube map's faces are not cube complete at level 0 (same
    /// square size and format).
    pub fn generate_mipmaps_checked(&mut self) -> bool {
        if self.cube.is_some() && !self.base_cube_complete() {
            return false;
        }
        self.generate_mipmaps();
        if let Some(c) = &mut self.cube {
            c.iter_mut().for_each(|f| generate_chain(f));
        }
        self.touch();
        true
    }

    /// Whether the six level-0 images exist, are square, and share size and format.
    pub fn base_cube_complete(&self) -> bool {
        let Some(c) = &self.cube else {
            return false;
        };
        let Some(b) = self.level(0) else {
            return false;
        };
        b.width == b.height
            && b.width > 0
            && c.iter().all(|f| {
                matches!(f[0].as_deref(), Some(i)
                    if (i.width, i.height, i.format) == (b.width, b.height, b.format))
            })
    }

    /// Changes whenever anything about the texture (images or parameters) changes.
    pub fn version(&self) -> u64 {
        self.version
    }

    /// Records a change made through the public parameter fields.
    pub fn touch(&mut self) {
        self.version = next_generation();
    }

    pub fn level(&self, level: usize) -> Option<&Image> {
        self.levels.get(level)?.as_deref()
    }

    /// Replaces `level` (≤ [`MAX_LEVEL`]) with `image`. With [`Texture::generate_mipmap`] set,
    /// a new level 0 also regenerates the whole chain below it.
    pub fn set_level(&mut self, level: usize, image: Image) {
        self.levels[level] = Some(Arc::new(image));
        if level == 0 && self.generate_mipmap {
            self.generate_mipmaps();
        }
        self.touch();
    }

    /// Removes every level (for `eglReleaseTexImage`).
    pub fn clear_levels(&mut self) {
        self.levels.iter_mut().for_each(|l| *l = None);
        self.touch();
    }

    /// Writes `texels` (`w * h` words, row 0 first) at (x, y) of `level`, which exists and
    /// contains the rectangle (the caller checked). Texels are converted to the level's base
    /// format. Regenerates the chain as [`Texture::set_level`] does.
    pub fn write_region(&mut self, level: usize, x: u32, y: u32, w: u32, h: u32, texels: &[u32]) {
        let img = Arc::make_mut(
            self.levels[level]
                .as_mut()
                .expect("caller checked the level"),
        );
        for row in 0..h {
            let dst = ((y + row) * img.width + x) as usize;
            let src = (row * w) as usize;
            for i in 0..w as usize {
                img.texels[dst + i] = convert_word(img.format, texels[src + i]);
            }
        }
        if level == 0 && self.generate_mipmap {
            self.generate_mipmaps();
        }
        self.touch();
    }

    /// [`Texture::write_region`] on level `level` of `face` (see [`Texture::chain`]),
    /// regenerating that face's chain when its level 0 changes with `generate_mipmap` set.
    #[allow(clippy::too_many_arguments)]
    pub fn write_face_region(
        &mut self,
        face: u8,
        level: usize,
        x: u32,
        y: u32,
        w: u32,
        h: u32,
        texels: &[u32],
    ) {
        if face <= 1 {
            return self.write_region(level, x, y, w, h, texels);
        }
        let generate = level == 0 && self.generate_mipmap;
        let Some(c) = self.chain_mut(face) else {
            return;
        };
        let Some(img) = c.get_mut(level).and_then(Option::as_mut) else {
            return;
        };
        let img = Arc::make_mut(img);
        for row in 0..h {
            let dst = ((y + row) * img.width + x) as usize;
            let src = (row * w) as usize;
            for i in 0..w as usize {
                img.texels[dst + i] = convert_word(img.format, texels[src + i]);
            }
        }
        if generate {
            generate_chain(c);
        }
        self.touch();
    }

    /// Overwrites all of `level` with rendered `texels` (a framebuffer object's color
    /// buffer, RGBA8 words row 0 first), converted to the level's base format. Returns false
    /// (and changes nothing) when the level is missing or has another texel count. Rendering
    /// does not trigger `GENERATE_MIPMAP` (`glGenerateMipmapOES` does).
    pub fn store_rendered(&mut self, level: usize, texels: &[u32]) -> bool {
        let Some(img) = self.levels.get_mut(level).and_then(Option::as_mut) else {
            return false;
        };
        if img.texels.len() != texels.len() {
            return false;
        }
        let img = Arc::make_mut(img);
        let format = img.format;
        for (d, &s) in img.texels.iter_mut().zip(texels) {
            *d = convert_word(format, s);
        }
        self.touch();
        true
    }

    /// Replaces levels 1 ..= log2(max(width, height)) with box-filtered reductions of level
    /// 0 (see [`Image::half`]); deeper levels are removed.
    pub fn generate_mipmaps(&mut self) {
        let Some(mut img) = self.levels[0].as_deref().cloned() else {
            return;
        };
        if img.width == 0 || img.height == 0 {
            // An empty base image has no chain.
            self.levels[1..].iter_mut().for_each(|l| *l = None);
            self.touch();
            return;
        }
        for l in 1..=MAX_LEVEL {
            if img.width == 1 && img.height == 1 {
                self.levels[l] = None;
                continue;
            }
            img = img.half();
            self.levels[l] = Some(Arc::new(img.clone()));
        }
        self.touch();
    }

    /// Whether the texture is mipmap-complete: level 0 exists and levels 1 ..= p halve it
    /// with the same base format (p stops at `max_level`).
    pub fn mipmap_complete(&self) -> bool {
        let Some(base) = self.level(0) else {
            return false;
        };
        let (mut w, mut h) = (base.width, base.height);
        let mut l = 0;
        while (w > 1 || h > 1) && l < self.max_level as usize {
            (w, h) = ((w / 2).max(1), (h / 2).max(1));
            l += 1;
            match self.level(l) {
                Some(i) if i.width == w && i.height == h && i.format == base.format => {}
                _ => return false,
            }
        }
        true
    }

    /// Whether sampling with the current filters has the images it needs (else texturing
    /// with this unit is disabled, ES 1.1 §3.7.10).
    pub fn is_complete(&self) -> bool {
        match self.level(0) {
            Some(b) if b.width > 0 && b.height > 0 => {
                !self.min_filter.uses_mipmaps() || self.mipmap_complete()
            }
            _ => false,
        }
    }
}

impl Texture {
    /// Whether a cube map can be sampled with its current filters: the six level-0 images
    /// are square with one size and format, and with a mipmap filter every face is
    /// mipmap-complete (ES 1.1 with `OES_texture_cube_map`: cube complete).
    pub fn cube_complete(&self) -> bool {
        if !self.base_cube_complete() {
            return false;
        }
        if !self.min_filter.uses_mipmaps() {
            return true;
        }
        let base = self.level(0).expect("cube complete");
        (1..=6u8).all(|face| {
            let (mut w, mut l) = (base.width, 0);
            while w > 1 && l < self.max_level as usize {
                w /= 2;
                l += 1;
                match self.face_level(face, l) {
                    Some(i) if i.width == w && i.height == w && i.format == base.format => {}
                    _ => return false,
                }
            }
            true
        })
    }

    /// A snapshot of a cube map for sampling (see [`Texture::sampler`]): `None` unless it
    /// is cube complete. Faces are sampled with CLAMP_TO_EDGE whatever the wrap modes say.
    fn cube_sampler(&self) -> Option<Arc<Sampler>> {
        if !self.cube_complete() {
            return None;
        }
        let base = self.level(0)?;
        let q = if self.min_filter.uses_mipmaps() {
            (base.width.ilog2() as usize).min(self.max_level as usize)
        } else {
            0
        };
        let faces: [Sampler; 6] = std::array::from_fn(|f| {
            let chain = self.chain(f as u8 + 1).expect("cube faces");
            Sampler::new(
                chain[..=q]
                    .iter()
                    .map(|l| l.clone().expect("complete"))
                    .collect(),
                self.min_filter,
                self.mag_filter,
                Wrap::ClampToEdge,
                Wrap::ClampToEdge,
            )
        });
        let mut s = faces[0].clone();
        s.cube = Some(Arc::new(faces));
        Some(Arc::new(s))
    }
}

impl Texture {
    /// A snapshot of the texture for sampling, sharing its images: `None` when the texture
    /// is incomplete for its filters (the unit then acts as if texturing were disabled,
    /// ES 1.1 §3.7.10). Pending draws hold the snapshot, so they keep reading these images
    /// even if the texture is redefined or deleted before they are rasterized.
    pub fn sampler(&self) -> Option<Arc<Sampler>> {
        if self.cube.is_some() {
            return self.cube_sampler();
        }
        if !self.is_complete() {
            return None;
        }
        let base = self.level(0)?;
        let q = if self.min_filter.uses_mipmaps() {
            (base.width.max(base.height).ilog2() as usize).min(self.max_level as usize)
        } else {
            0
        };
        let levels = self.levels[..=q]
            .iter()
            .map(|l| l.clone().expect("complete"))
            .collect();
        let mut sampler = Sampler::new(
            levels,
            self.min_filter,
            self.mag_filter,
            self.wrap_s,
            self.wrap_t,
        );
        sampler.max_anisotropy = self.max_anisotropy.min(MAX_ANISOTROPY);
        Some(Arc::new(sampler))
    }
}

/// What a texture unit samples: the images of a complete texture (level 0, and the whole
/// chain when the minification filter uses mipmaps) and its sampler parameters.
///
/// Sampling follows ES 1.1 §3.7.7-3.7.8: texel centers at (i + ½)/N; NEAREST takes texel
/// ⌊u⌋, LINEAR the four texels around u − ½, v − ½ weighted by the fractions, computed in
/// f32 (24-bit mantissa: with the pipeline's removal of whole REPEAT periods, weights are
/// exact to well under 2⁻¹² of a texel for every level size). λ = log₂ ρ; λ ≤ c is
/// magnification, with c = ½ when the magnification filter is LINEAR and the minification
/// filter NEAREST_MIPMAP_NEAREST or NEAREST_MIPMAP_LINEAR, else 0. `EXT_texture_lod_bias`:
/// [`Sampler::lod_bias`] is added to λ before that decision and the level selection.
#[derive(Clone, Debug)]
pub struct Sampler {
    pub levels: Vec<Arc<Image>>,
    pub min: MinFilter,
    pub mag: MagFilter,
    pub wrap_s: Wrap,
    pub wrap_t: Wrap,
    pub format: BaseFormat,
    /// The minification / magnification switch-over point.
    pub c: f32,
    /// `OES_texture_cube_map`: for a cube map, the six faces' samplers (POSITIVE_X,
    /// NEGATIVE_X, POSITIVE_Y, NEGATIVE_Y, POSITIVE_Z, NEGATIVE_Z), each clamping to its
    /// edges; this sampler is then the POSITIVE_X face's.
    pub cube: Option<Arc<[Sampler; 6]>>,
    /// `EXT_texture_lod_bias`: the unit's bias, already clamped to ±[`MAX_LOD_BIAS`], added
    /// to λ by [`Sampler::sample_255`] and [`Sampler::trilinear`] (the cube faces carry it
    /// too). 0 unless set by [`Sampler::with_lod_bias`].
    pub lod_bias: f32,
    /// `EXT_texture_filter_anisotropic`: how many samples minification may take along the
    /// footprint's long axis, 1 to [`MAX_ANISOTROPY`] (1: isotropic, the default).
    pub max_anisotropy: f32,
}

/// `GL_MAX_TEXTURE_LOD_BIAS_EXT`: the largest magnitude of a level-of-detail bias.
pub const MAX_LOD_BIAS: f32 = 16.0;

/// `GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT`.
pub const MAX_ANISOTROPY: f32 = 16.0;

impl PartialEq for Sampler {
    /// The same images (by identity) and parameters.
    fn eq(&self, o: &Sampler) -> bool {
        self.levels.len() == o.levels.len()
            && self
                .levels
                .iter()
                .zip(&o.levels)
                .all(|(a, b)| Arc::ptr_eq(a, b))
            && (self.min, self.mag, self.wrap_s, self.wrap_t) == (o.min, o.mag, o.wrap_s, o.wrap_t)
            && self.lod_bias.to_bits() == o.lod_bias.to_bits()
            && self.max_anisotropy.to_bits() == o.max_anisotropy.to_bits()
            && match (&self.cube, &o.cube) {
                (None, None) => true,
                (Some(a), Some(b)) => Arc::ptr_eq(a, b) || a[..] == b[..],
                _ => false,
            }
    }
}

const INV_255: f32 = 1.0 / 255.0;

/// log2(x) in plain f32 arithmetic, so that a loop over lanes vectorizes (libm's `log2f`
/// is a call per lane: a tenth of a per-pixel trilinear profile). Exact at powers of two,
/// so λ is exact where a level begins; elsewhere within 1e-7 of the true value plus the
/// rounding of the result to f32. 0 gives −∞, +∞ gives +∞, NaN and negative values NaN,
/// as `f32::log2` does.
#[inline(always)]
pub fn log2(x: f32) -> f32 {
    // Subnormals are scaled into the normal range and the scale taken off again.
    let tiny = x < f32::MIN_POSITIVE;
    let xs = if tiny { x * 8_388_608.0 } else { x };
    // x = 2^e · m with m in [√½, √2), centred on 1 so the series converges fast: e counts
    // the octaves above √½ (the bits of √½ subtracted), m keeps x's mantissa with the
    // exponent of that octave.
    let bits = xs.to_bits();
    let off = bits.wrapping_sub(0x3F35_04F3) as i32;
    let e = (off >> 23) as f32 - if tiny { 23.0 } else { 0.0 };
    let m = f32::from_bits(bits.wrapping_sub(off as u32 & 0xFF80_0000));
    // log2 m = (2 / ln 2) · atanh z with z = (m − 1)/(m + 1), |z| ≤ 0.172: five odd terms
    // leave a truncation error below 2e-9 (m − 1 is exact, and z = 0 at m = 1).
    let z = (m - 1.0) / (m + 1.0);
    let z2 = z * z;
    const K: f32 = std::f32::consts::LOG2_E * 2.0;
    let series = z * (K + z2 * (K / 3.0 + z2 * (K / 5.0 + z2 * (K / 7.0 + z2 * (K / 9.0)))));
    let r = e + series;
    let r = if x == 0.0 { f32::NEG_INFINITY } else { r };
    let r = if x == f32::INFINITY { x } else { r };
    if x >= 0.0 {
        r
    } else {
        f32::NAN
    }
}

#[inline(always)]
fn unpack_f32(w: u32) -> [f32; 4] {
    let b = w.to_le_bytes();
    [b[0] as f32, b[1] as f32, b[2] as f32, b[3] as f32]
}

/// Floor of a texel-space coordinate as an index; huge values and NaN saturate (any index
/// is then wrapped or clamped into the level), so no coordinate can fault.
#[inline(always)]
fn floor_index(u: f32) -> i32 {
    u.floor() as i32
}

impl Sampler {
    pub fn new(
        levels: Vec<Arc<Image>>,
        min: MinFilter,
        mag: MagFilter,
        wrap_s: Wrap,
        wrap_t: Wrap,
    ) -> Sampler {
        let c = if mag == MagFilter::Linear
            && matches!(
                min,
                MinFilter::NearestMipmapNearest | MinFilter::NearestMipmapLinear
            ) {
            0.5
        } else {
            0.0
        };
        let format = levels[0].format;
        Sampler {
            levels,
            min,
            mag,
            wrap_s,
            wrap_t,
            format,
            c,
            cube: None,
            lod_bias: 0.0,
            max_anisotropy: 1.0,
        }
    }

    /// This sampler with level-of-detail bias `bias` (`EXT_texture_lod_bias`), clamped to
    /// ±[`MAX_LOD_BIAS`] (NaN counts as 0), on every cube face as well. Shares `self` when
    /// the bias is unchanged.
    pub fn with_lod_bias(self: &Arc<Sampler>, bias: f32) -> Arc<Sampler> {
        let bias = if bias.is_nan() {
            0.0
        } else {
            bias.clamp(-MAX_LOD_BIAS, MAX_LOD_BIAS)
        };
        if bias.to_bits() == self.lod_bias.to_bits() {
            return self.clone();
        }
        let mut s = (**self).clone();
        s.lod_bias = bias;
        if let Some(faces) = &s.cube {
            let mut faces = (**faces).clone();
            faces.iter_mut().for_each(|f| f.lod_bias = bias);
            s.cube = Some(Arc::new(faces));
        }
        Arc::new(s)
    }

    /// Level 0's width and height.
    #[inline]
    pub fn size(&self) -> (u32, u32) {
        (self.levels[0].width, self.levels[0].height)
    }

    /// The texel at wrapped integer coordinates (i, j) of `level`, as an RGBA8 word.
    #[inline(always)]
    pub fn texel(&self, level: usize, i: i32, j: i32) -> u32 {
        let img = &self.levels[level];
        let (w, h) = (img.width as i32, img.height as i32);
        let x = self.wrap_s.index(i, w);
        let y = self.wrap_t.index(j, h);
        // SAFETY-free: indices are in range by construction of `Wrap::index`.
        img.texels[(y * w + x) as usize]
    }

    /// NEAREST at (s, t) in `level`, in 0 ..= 255 per channel.
    #[inline(always)]
    pub fn nearest(&self, level: usize, s: f32, t: f32) -> [f32; 4] {
        let img = &self.levels[level];
        let i = floor_index(s * img.width as f32);
        let j = floor_index(t * img.height as f32);
        unpack_f32(self.texel(level, i, j))
    }

    /// LINEAR (bilinear) at (s, t) in `level`, in 0 ..= 255 per channel.
    #[inline(always)]
    pub fn bilinear(&self, level: usize, s: f32, t: f32) -> [f32; 4] {
        let img = &self.levels[level];
        let u = s * img.width as f32 - 0.5;
        let v = t * img.height as f32 - 0.5;
        let (fu, fv) = (u.floor(), v.floor());
        let (i, j) = (fu as i32, fv as i32);
        let (a, b) = (u - fu, v - fv);
        let t00 = unpack_f32(self.texel(level, i, j));
        let t10 = unpack_f32(self.texel(level, i.wrapping_add(1), j));
        let t01 = unpack_f32(self.texel(level, i, j.wrapping_add(1)));
        let t11 = unpack_f32(self.texel(level, i.wrapping_add(1), j.wrapping_add(1)));
        std::array::from_fn(|c| {
            let top = t00[c] + (t10[c] - t00[c]) * a;
            let bottom = t01[c] + (t11[c] - t01[c]) * a;
            top + (bottom - top) * b
        })
    }

    #[inline(always)]
    fn filter(&self, linear: bool, level: usize, s: f32, t: f32) -> [f32; 4] {
        if linear {
            self.bilinear(level, s, t)
        } else {
            self.nearest(level, s, t)
        }
    }

    /// λ from ρ², the larger squared length of the texel-space derivative vectors
    /// (`du/dx, dv/dx` and `du/dy, dv/dy`, in level-0 texels per pixel).
    #[inline(always)]
    pub fn lambda(rho2: f32) -> f32 {
        // log2(sqrt(x)) = log2(x) / 2; ρ = 0 gives −∞ (magnification).
        0.5 * log2(rho2)
    }

    /// LINEAR_MIPMAP_LINEAR minification, LINEAR magnification, in 0 ..= 255 per channel.
    #[inline(always)]
    pub fn trilinear(&self, s: f32, t: f32, lambda: f32) -> [f32; 4] {
        let lambda = lambda + self.lod_bias;
        if lambda.is_nan() || lambda <= self.c {
            return self.bilinear(0, s, t);
        }
        let q = self.levels.len() - 1;
        if lambda >= q as f32 {
            return self.bilinear(q, s, t);
        }
        let d1 = lambda as usize;
        let f = lambda - d1 as f32;
        let a = self.bilinear(d1, s, t);
        let b = self.bilinear(d1 + 1, s, t);
        std::array::from_fn(|c| a[c] + (b[c] - a[c]) * f)
    }

    /// The filtered texture value at (s, t) with level of detail λ (before the bias), in
    /// [0, 1] per channel.
    #[inline]
    pub fn sample(&self, s: f32, t: f32, lambda: f32) -> [f32; 4] {
        let v = self.sample_255(s, t, lambda);
        v.map(|c| c * INV_255)
    }

    /// [`Sampler::sample`] in 0 ..= 255 per channel.
    #[inline]
    pub fn sample_255(&self, s: f32, t: f32, lambda: f32) -> [f32; 4] {
        let lambda = lambda + self.lod_bias;
        // NaN λ (from degenerate derivatives) counts as magnification.
        if lambda.is_nan() || lambda <= self.c {
            return self.filter(self.mag == MagFilter::Linear, 0, s, t);
        }
        let q = self.levels.len() - 1;
        match self.min {
            MinFilter::Nearest => self.nearest(0, s, t),
            MinFilter::Linear => self.bilinear(0, s, t),
            MinFilter::NearestMipmapNearest | MinFilter::LinearMipmapNearest => {
                let d = if lambda <= 0.5 {
                    0
                } else {
                    ((lambda + 0.5).ceil() - 1.0).min(q as f32) as usize
                };
                self.filter(self.min == MinFilter::LinearMipmapNearest, d, s, t)
            }
            MinFilter::NearestMipmapLinear | MinFilter::LinearMipmapLinear => {
                let linear = self.min == MinFilter::LinearMipmapLinear;
                if lambda >= q as f32 {
                    return self.filter(linear, q, s, t);
                }
                let d1 = lambda.floor() as usize;
                let f = lambda - d1 as f32;
                let a = self.filter(linear, d1, s, t);
                let b = self.filter(linear, d1 + 1, s, t);
                std::array::from_fn(|c| a[c] + (b[c] - a[c]) * f)
            }
        }
    }
}

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

/// `OES_compressed_ETC1_RGB8_texture`: bytes of a `width` × `height` image, 8 per 4 × 4
/// block (partial blocks at the edges count whole).
pub fn etc1_size(width: u32, height: u32) -> usize {
    width.div_ceil(4) as usize * height.div_ceil(4) as usize * 8
}

/// The ETC1 intensity modifier tables, indexed by the 3-bit table codeword; pixel index
/// values 0 and 1 add the two entries, 2 and 3 subtract them.
const ETC1_MODIFIERS: [[i32; 2]; 8] = [
    [2, 8],
    [5, 17],
    [9, 29],
    [13, 42],
    [18, 60],
    [24, 80],
    [33, 106],
    [47, 183],
];

/// ETC1 widens its 5-bit base colors by bit replication (the format's own rule, which differs
/// from GL's rounding conversion for some values).
fn etc1_widen5(v: u32) -> i32 {
    ((v << 3) | (v >> 2)) as i32
}

/// Decodes one 64-bit ETC1 block (read big-endian) into 16 RGB texels, `out[y * 4 + x]`.
pub fn etc1_block(block: [u8; 8]) -> [[u8; 3]; 16] {
    let hi = u32::from_be_bytes([block[0], block[1], block[2], block[3]]);
    let lo = u32::from_be_bytes([block[4], block[5], block[6], block[7]]);
    let diff = hi & 2 != 0;
    let flip = hi & 1 != 0;
    // Base colors of the two subblocks, 8 bits per channel.
    let mut base = [[0i32; 3]; 2];
    #[allow(clippy::needless_range_loop)] // c indexes both subblocks' channels
    for c in 0..3 {
        let shift = 24 - 8 * c as u32;
        if diff {
            let b1 = (hi >> (shift + 3)) & 31;
            let d = ((hi >> shift) & 7) as i32;
            let d = if d >= 4 { d - 8 } else { d };
            let b2 = (b1 as i32 + d) & 31;
            base[0][c] = etc1_widen5(b1);
            base[1][c] = etc1_widen5(b2 as u32);
        } else {
            base[0][c] = expand_to_8((hi >> (shift + 4)) & 15, 4) as i32;
            base[1][c] = expand_to_8((hi >> shift) & 15, 4) as i32;
        }
    }
    let tables = [(hi >> 5) & 7, (hi >> 2) & 7];
    let mut out = [[0u8; 3]; 16];
    for x in 0..4 {
        for y in 0..4 {
            let sub = if flip {
                (y >= 2) as usize
            } else {
                (x >= 2) as usize
            };
            let i = x * 4 + y;
            let msb = (lo >> (16 + i)) & 1;
            let lsb = (lo >> i) & 1;
            let m = ETC1_MODIFIERS[tables[sub] as usize];
            let modifier = match (msb << 1) | lsb {
                0 => m[0],
                1 => m[1],
                2 => -m[0],
                _ => -m[1],
            };
            out[y * 4 + x] = base[sub].map(|b| (b + modifier).clamp(0, 255) as u8);
        }
    }
    out
}

/// Decodes an ETC1 image of exactly [`etc1_size`] bytes into an RGB level, or `None` when
/// `data` has another size.
pub fn decode_etc1(width: u32, height: u32, data: &[u8]) -> Option<Image> {
    if data.len() != etc1_size(width, height) {
        return None;
    }
    let mut texels = vec![0u32; width as usize * height as usize];
    let blocks_x = width.div_ceil(4) as usize;
    for (n, b) in data.chunks_exact(8).enumerate() {
        let (bx, by) = (n % blocks_x * 4, n / blocks_x * 4);
        let px = etc1_block(b.try_into().expect("8 bytes"));
        for y in 0..4 {
            for x in 0..4 {
                let (tx, ty) = (bx + x, by + y);
                if tx < width as usize && ty < height as usize {
                    let [r, g, b] = px[y * 4 + x];
                    texels[ty * width as usize + tx] = word(r, g, b, 255);
                }
            }
        }
    }
    Some(Image {
        width,
        height,
        format: BaseFormat::Rgb,
        texels,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log2_is_exact_at_powers_of_two_and_close_elsewhere() {
        for e in -149..=127 {
            let x = if e >= -126 {
                f32::from_bits(((e + 127) as u32) << 23)
            } else {
                f32::from_bits(1 << (e + 149))
            };
            assert_eq!(log2(x), e as f32, "2^{e}");
        }
        // Spread over the whole range, subnormals included, against the f64 logarithm: the
        // error is the series' (below 1e-7) plus the rounding of the result to f32.
        let mut bits = 1u32;
        while bits < f32::INFINITY.to_bits() {
            let x = f32::from_bits(bits);
            let exact = (x as f64).log2();
            let err = (log2(x) as f64 - exact).abs();
            let ulp = (exact.abs() as f32).max(1.0) as f64 * f32::EPSILON as f64;
            assert!(err <= 1e-7 + ulp, "log2({x:e}) off by {err:e}");
            bits += 9_973;
        }
        assert_eq!(log2(0.0), f32::NEG_INFINITY);
        assert_eq!(log2(-0.0), f32::NEG_INFINITY);
        assert_eq!(log2(f32::INFINITY), f32::INFINITY);
        assert!(log2(f32::NAN).is_nan());
        assert!(log2(-1.0).is_nan());
        assert!(log2(f32::NEG_INFINITY).is_nan());
    }

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
    fn etc1_individual_and_differential_blocks() {
        // Individual mode, no flip: left subblock base (0x1, 0x2, 0x3) -> (17, 34, 51) with
        // table 0, right subblock base (0xf, 0xe, 0xd) with table 7. All indices 0 (+a)
        // except pixel (x=1, y=2): index 3 (-b); pixel (x=3, y=0): index 1 (+b).
        let hi: u32 = 0x1f << 24 | 0x2e << 16 | 0x3d << 8 | (7 << 2);
        let i_12 = 4 + 2; // x * 4 + y
        let i_30 = 3 * 4;
        let lo: u32 = (1 << (16 + i_12)) | (1 << i_12) | (1 << i_30);
        let mut b = [0u8; 8];
        b[..4].copy_from_slice(&hi.to_be_bytes());
        b[4..].copy_from_slice(&lo.to_be_bytes());
        let px = etc1_block(b);
        assert_eq!(px[0], [19, 36, 53]); // (0, 0): +2
        assert_eq!(px[2 * 4 + 1], [9, 26, 43]); // (1, 2): -8
        assert_eq!(px[2], [255, 255, 255]); // (2, 0): (255, 238, 221) + 47, clamped
        assert_eq!(px[3], [255, 255, 255]); // (3, 0): +183 clamped

        // Differential mode with flip: top base 5-bit (16, 8, 4), delta (-1, +3, 0).
        let hi: u32 = (16 << 3 | 7) << 24 | (8 << 3 | 3) << 16 | (4 << 3) << 8 | 3;
        b[..4].copy_from_slice(&hi.to_be_bytes());
        b[4..].copy_from_slice(&0u32.to_be_bytes());
        let px = etc1_block(b);
        let e = |v: u32| etc1_widen5(v) + 2;
        assert_eq!(px[0], [e(16) as u8, e(8) as u8, e(4) as u8]);
        assert_eq!(px[3 * 4 + 3], [e(15) as u8, e(11) as u8, e(4) as u8]);
        // Sizes: partial blocks count whole; a 2 × 2 image keeps its top-left texels.
        assert_eq!(etc1_size(4, 4), 8);
        assert_eq!(etc1_size(5, 1), 16);
        let img = decode_etc1(2, 2, &b).unwrap();
        assert_eq!(img.texel(1, 1), [e(16) as u8, e(8) as u8, e(4) as u8, 255]);
        assert!(decode_etc1(8, 8, &b).is_none());
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

    #[test]
    fn generated_chain_is_complete_and_averaged() {
        let mut t = Texture::new();
        t.generate_mipmap = true;
        let texels = vec![
            word(0, 0, 0, 255),
            word(255, 0, 0, 255),
            word(0, 255, 0, 255),
            word(255, 255, 0, 255),
            word(0, 0, 0, 255),
            word(0, 0, 0, 255),
            word(0, 0, 0, 255),
            word(0, 0, 0, 255),
        ];
        let v0 = t.version();
        t.set_level(
            0,
            Image {
                width: 4,
                height: 2,
                format: BaseFormat::Rgb,
                texels,
            },
        );
        assert_ne!(t.version(), v0);
        assert!(t.mipmap_complete());
        assert!(t.is_complete());
        let l1 = t.level(1).unwrap();
        assert_eq!((l1.width, l1.height), (2, 1));
        assert_eq!(l1.texel(0, 0), [64, 0, 0, 255]);
        assert_eq!(l1.texel(1, 0), [64, 128, 0, 255]);
        let l2 = t.level(2).unwrap();
        assert_eq!(l2.texel(0, 0), [64, 64, 0, 255]);
        assert!(t.level(3).is_none());
    }

    #[test]
    fn empty_base_level_has_no_chain() {
        let mut t = Texture::new();
        t.generate_mipmap = true;
        t.set_level(0, Image::blank(2, 2, BaseFormat::Rgb));
        t.set_level(0, Image::blank(0, 0, BaseFormat::Rgb));
        assert!(t.level(1).is_none());
        assert!(!t.is_complete());
    }

    #[test]
    fn incomplete_without_levels() {
        let mut t = Texture::new();
        assert!(!t.is_complete());
        t.set_level(0, Image::blank(2, 2, BaseFormat::Alpha));
        assert!(!t.is_complete(), "default min filter needs mipmaps");
        t.min_filter = MinFilter::Linear;
        assert!(t.is_complete());
        assert_eq!(t.level(0).unwrap().texel(1, 1), [0, 0, 0, 0]);
    }
}
