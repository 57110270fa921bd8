//! Texture objects: base formats, mip chains of RGBA8 texels and mipmap generation, with
//! the rest of texturing in one file per concern: client pixel unpacking ([`unpack`](mod@unpack)),
//! sampling ([`sampler`]), and the compressed formats' decoders ([`palette`] for
//! `OES_compressed_paletted_texture`, [`etc1`], [`pvrtc`], [`s3tc`]). Plain Rust: the GL
//! layer (`gles/texture.rs`) validates enums and sizes and calls in here.
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

pub mod etc1;
pub mod palette;
pub mod pvrtc;
pub mod s3tc;
pub mod sampler;
pub mod unpack;

pub use etc1::{decode_etc1, etc1_block, etc1_size};
pub use palette::{PaletteEntry, PaletteFormat};
pub use sampler::{log2, MagFilter, MinFilter, Sampler, Wrap, MAX_ANISOTROPY, MAX_LOD_BIAS};
pub use unpack::{convert_word, unpack, PixelRect, PixelType};

use unpack::unpack_pixel;

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
            texels: crate::target::try_filled(width as usize * height as usize, zero)?,
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

    /// Level `level` of `face` (see `Texture::chain` for face numbers).
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

    /// [`Texture::write_region`] on level `level` of `face` (see `Texture::chain`),
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

#[cfg(test)]
mod tests {
    use super::unpack::word;
    use super::*;

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
