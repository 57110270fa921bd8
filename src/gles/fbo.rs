//! `OES_framebuffer_object`: framebuffer and renderbuffer objects, attachments, completeness
//! and rendering into them through the same core as EGL surfaces.
//!
//! Renderbuffers are shared by the contexts of a share group (they live in
//! [`SharedObjects`]); framebuffer objects belong to the context that made them, as the
//! extension says.
//!
//! **How rendering reaches the attachments.** While a complete framebuffer object is bound,
//! the context draws into a [`Target`] it assembles from the attachments (an [`FboSurface`]:
//! color from a texture level or a color renderbuffer, depth and stencil from renderbuffers;
//! without a color attachment, a scratch color buffer whose contents are dropped). The target
//! is loaded from the attachments' contents when it is assembled, and written back into them
//! (texture level, renderbuffer storage) at the flush points: `glFlush`, `glFinish`,
//! `glReadPixels`, `glCopyTex*`, binding another framebuffer, changing an attachment or an
//! attached object (`glFramebuffer*`, `glRenderbufferStorageOES`, any texture change made
//! by this context), deleting objects and `eglMakeCurrent`. Draws recorded after that see the
//! texture's new contents (a sampler snapshot is taken when a draw is recorded). The
//! assembled target is kept while the attachments and their versions stay the same, so a
//! write-back does not force a reload.
#![forbid(unsafe_code)]

use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};

use gles_cm_core::target::try_filled;
use gles_cm_core::texture::{BaseFormat, Image, Texture, MAX_LEVEL, MAX_TEXTURE_SIZE};
use gles_cm_core::{ColorFormat, DepthFormat, Target, TargetFormat};

use super::buffer::lock_objects;
use super::context::{Context, SharedObjects, Surface};
use super::get::Value;
use super::objects::{Binding, Names};
use super::tokens::*;
use super::tokens_ext::*;
use super::types::*;

/// `GL_MAX_RENDERBUFFER_SIZE_OES`: the largest renderbuffer side (and, since texture levels
/// can be attached, the same as the largest texture).
pub const MAX_RENDERBUFFER_SIZE: u32 = MAX_TEXTURE_SIZE;

static GENERATION: AtomicU64 = AtomicU64::new(1);

fn next_generation() -> u64 {
    GENERATION.fetch_add(1, Ordering::Relaxed)
}

/// What a renderbuffer's storage holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RenderbufferKind {
    Color(ColorFormat),
    Depth(DepthFormat),
    Stencil,
    /// `OES_packed_depth_stencil`: 24-bit depth and 8-bit stencil in one renderbuffer,
    /// attachable to both points.
    DepthStencil,
}

/// A renderbuffer: its internal format, size and storage (color words as a [`Target`]
/// stores them, quantized depth values, or stencil bytes; row 0 at the bottom).
#[derive(Clone, Debug)]
pub struct Renderbuffer {
    pub internal_format: GLenum,
    pub width: u32,
    pub height: u32,
    pub kind: RenderbufferKind,
    words: Vec<u32>,
    bytes: Vec<u8>,
    version: u64,
}

impl Default for Renderbuffer {
    /// The initial state: 0 × 0, internal format RGBA4.
    fn default() -> Renderbuffer {
        Renderbuffer {
            internal_format: GL_RGBA4_OES,
            width: 0,
            height: 0,
            kind: RenderbufferKind::Color(ColorFormat::Rgba4444),
            words: Vec::new(),
            bytes: Vec::new(),
            version: next_generation(),
        }
    }
}

/// The renderbuffer internal formats and what they store.
pub fn renderbuffer_kind(internal_format: GLenum) -> Option<RenderbufferKind> {
    use RenderbufferKind::*;
    Some(match internal_format {
        GL_RGBA8_OES => Color(ColorFormat::Rgba8888),
        GL_RGB8_OES => Color(ColorFormat::Rgb888),
        GL_RGB565_OES => Color(ColorFormat::Rgb565),
        GL_RGBA4_OES => Color(ColorFormat::Rgba4444),
        GL_RGB5_A1_OES => Color(ColorFormat::Rgba5551),
        GL_DEPTH_COMPONENT16_OES => Depth(DepthFormat::D16),
        GL_DEPTH_COMPONENT24_OES => Depth(DepthFormat::D24),
        GL_STENCIL_INDEX8_OES => Stencil,
        GL_DEPTH24_STENCIL8_OES => DepthStencil,
        _ => return None,
    })
}

impl Renderbuffer {
    /// Channel sizes: red, green, blue, alpha, depth, stencil.
    pub fn sizes(&self) -> [u32; 6] {
        if self.width == 0 || self.height == 0 {
            // No storage yet: every size is 0 (only the format is reported).
            return [0; 6];
        }
        match self.kind {
            RenderbufferKind::Color(c) => {
                let b = c.bits();
                [b[0], b[1], b[2], b[3], 0, 0]
            }
            RenderbufferKind::Depth(d) => [0, 0, 0, 0, d.bits(), 0],
            RenderbufferKind::Stencil => [0, 0, 0, 0, 0, 8],
            RenderbufferKind::DepthStencil => [0, 0, 0, 0, 24, 8],
        }
    }
}

/// Names of objects a context keeps to itself (framebuffer objects, vertex array objects):
/// `None` for names generated but not yet bound.
#[derive(Debug)]
pub struct ContextNames<T> {
    objects: HashMap<GLuint, Option<T>>,
    next: GLuint,
}

impl<T> Default for ContextNames<T> {
    fn default() -> Self {
        ContextNames {
            objects: HashMap::new(),
            next: 0,
        }
    }
}

impl<T: Default> ContextNames<T> {
    pub fn get(&self, name: GLuint) -> Option<&T> {
        self.objects.get(&name)?.as_ref()
    }

    pub fn get_mut(&mut self, name: GLuint) -> Option<&mut T> {
        self.objects.get_mut(&name)?.as_mut()
    }

    pub(super) fn get_or_create(&mut self, name: GLuint) -> &mut T {
        self.objects
            .entry(name)
            .or_insert(None)
            .get_or_insert_with(T::default)
    }

    pub(super) fn generate(&mut self) -> GLuint {
        loop {
            self.next = self.next.wrapping_add(1).max(1);
            if !self.objects.contains_key(&self.next) {
                self.objects.insert(self.next, None);
                return self.next;
            }
        }
    }

    pub(super) fn remove(&mut self, name: GLuint) -> bool {
        self.objects.remove(&name).is_some()
    }

    /// Whether `name` was generated (or bound) and not deleted.
    pub(super) fn contains(&self, name: GLuint) -> bool {
        self.objects.contains_key(&name)
    }
}

/// The renderbuffers of a share group.
pub type RenderbufferNames = Names<Renderbuffer>;

/// What an attachment point holds. An attached object stays alive while attached, even
/// when its name is deleted (the extension detaches it only from the bound framebuffer).
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub enum Attachment {
    #[default]
    None,
    Renderbuffer(Binding),
    /// A texture level; `face` 0 for a 2D texture, 1 ..= 6 for the cube map faces
    /// POSITIVE_X .. NEGATIVE_Z.
    Texture {
        object: Binding,
        level: usize,
        face: u8,
    },
}

/// A framebuffer object's attachment points: color 0, depth, stencil.
#[derive(Clone, Debug, Default)]
pub struct Framebuffer {
    pub points: [Attachment; 3],
}

const COLOR: usize = 0;
const DEPTH: usize = 1;
const STENCIL: usize = 2;

fn attachment_point(attachment: GLenum) -> Option<usize> {
    Some(match attachment {
        GL_COLOR_ATTACHMENT0_OES => COLOR,
        GL_DEPTH_ATTACHMENT_OES => DEPTH,
        GL_STENCIL_ATTACHMENT_OES => STENCIL,
        _ => return None,
    })
}

/// The render target of a bound framebuffer object.
pub struct FboSurface {
    target: Mutex<Target>,
}

impl Surface for FboSurface {
    fn target(&self) -> &Mutex<Target> {
        &self.target
    }
}

/// One attachment as seen when the target was assembled: the object and its version.
type Key = [(Attachment, u64); 3];

/// A context's framebuffer objects and bindings.
#[derive(Default)]
pub struct FramebufferState {
    names: ContextNames<Framebuffer>,
    /// `GL_FRAMEBUFFER_BINDING_OES` (0: the EGL surfaces).
    pub bound: GLuint,
    /// `GL_RENDERBUFFER_BINDING_OES`.
    pub renderbuffer: Binding,
    /// The assembled target of the bound framebuffer, and what it was assembled from.
    surface: Option<(Arc<FboSurface>, Key)>,
    /// Work was recorded into `surface` since it was last written back.
    pub(super) dirty: bool,
}

/// A complete framebuffer's size and target format.
struct Layout {
    width: u32,
    height: u32,
    format: TargetFormat,
    key: Key,
}

/// The size, version and what an attached image provides, or `None` when the attachment
/// is not attachment-complete for `point`.
fn image_info(
    o: &SharedObjects,
    a: &Attachment,
    point: usize,
) -> Option<(u32, u32, u64, Provides)> {
    match a {
        Attachment::None => None,
        Attachment::Renderbuffer(object) => {
            let rb = o.renderbuffers.get(object)?;
            let p = match (rb.kind, point) {
                (RenderbufferKind::Color(c), COLOR) => Provides::Color(c),
                (RenderbufferKind::Depth(d), DEPTH) => Provides::Depth(d),
                (RenderbufferKind::Stencil | RenderbufferKind::DepthStencil, STENCIL) => {
                    Provides::Stencil
                }
                (RenderbufferKind::DepthStencil, DEPTH) => Provides::Depth(DepthFormat::D24),
                _ => return None,
            };
            Some((rb.width, rb.height, rb.version, p))
        }
        Attachment::Texture {
            object,
            level,
            face,
        } => {
            let t = o.textures.get(object)?;
            let img = t.face_level(*face, *level)?;
            // Only RGB and RGBA textures are color-renderable here.
            let c = match (img.format, point) {
                (BaseFormat::Rgb, COLOR) => ColorFormat::Rgb888,
                (BaseFormat::Rgba, COLOR) => ColorFormat::Rgba8888,
                _ => return None,
            };
            Some((img.width, img.height, t.version(), Provides::Color(c)))
        }
    }
}

#[derive(Clone, Copy)]
enum Provides {
    Color(ColorFormat),
    Depth(DepthFormat),
    Stencil,
}

/// The completeness rules (`OES_framebuffer_object` §4.4.5), in the extension's order.
fn layout(o: &SharedObjects, fb: &Framebuffer) -> Result<Layout, GLenum> {
    let mut format = TargetFormat {
        color: ColorFormat::Rgba8888,
        depth: None,
        stencil_bits: 0,
    };
    let mut size: Option<(u32, u32)> = None;
    let mut same_size = true;
    let mut key: Key = Default::default();
    for (point, a) in fb.points.iter().enumerate() {
        if *a == Attachment::None {
            continue;
        }
        let Some((w, h, version, provides)) = image_info(o, a, point) else {
            return Err(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_OES);
        };
        if w == 0 || h == 0 {
            return Err(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_OES);
        }
        match size {
            None => size = Some((w, h)),
            Some(s) => same_size &= s == (w, h),
        }
        match provides {
            Provides::Color(c) => format.color = c,
            Provides::Depth(d) => format.depth = Some(d),
            Provides::Stencil => format.stencil_bits = 8,
        }
        key[point] = (a.clone(), version);
    }
    let Some((width, height)) = size else {
        return Err(GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT_OES);
    };
    if !same_size {
        return Err(GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS_OES);
    }
    Ok(Layout {
        width,
        height,
        format,
        key,
    })
}

/// A target holding the attachments' current contents, or `None` when it cannot be
/// allocated.
fn load(o: &SharedObjects, l: &Layout) -> Option<Target> {
    let mut t = Target::try_new(l.width, l.height, l.format)?;
    for (point, (a, _)) in l.key.iter().enumerate() {
        match a {
            Attachment::None => {}
            Attachment::Renderbuffer(object) => {
                let Some(rb) = o.renderbuffers.get(object) else {
                    continue;
                };
                match point {
                    COLOR => t.color_mut().copy_from_slice(&rb.words),
                    DEPTH => t.depth_mut().copy_from_slice(&rb.words),
                    _ => t.stencil_mut().copy_from_slice(&rb.bytes),
                }
            }
            Attachment::Texture {
                object,
                level,
                face,
            } => {
                if let Some(img) = o
                    .textures
                    .get(object)
                    .and_then(|t| t.face_level(*face, *level))
                {
                    let color = l.format.color;
                    for (d, &s) in t.color_mut().iter_mut().zip(&img.texels) {
                        *d = color.quantize8(s);
                    }
                }
            }
        }
    }
    Some(t)
}

/// Copies the target's buffers into the attachments it was assembled from.
fn store(o: &mut SharedObjects, t: &Target, key: &Key) {
    for (point, (a, _)) in key.iter().enumerate() {
        match a {
            Attachment::None => {}
            Attachment::Renderbuffer(object) => {
                let Some(rb) = o.renderbuffers.get_mut(object) else {
                    continue;
                };
                let n = rb.width as usize * rb.height as usize;
                let ok = match point {
                    COLOR if rb.words.len() == n && t.color().len() == n => {
                        rb.words.copy_from_slice(t.color());
                        true
                    }
                    DEPTH if rb.words.len() == n && t.depth().len() == n => {
                        rb.words.copy_from_slice(t.depth());
                        true
                    }
                    STENCIL if rb.bytes.len() == n && t.stencil().len() == n => {
                        rb.bytes.copy_from_slice(t.stencil());
                        true
                    }
                    _ => false,
                };
                if ok {
                    rb.version = next_generation();
                }
            }
            Attachment::Texture {
                object,
                level,
                face,
            } => {
                if let Some(tex) = o.textures.get_mut(object) {
                    tex.store_rendered_face(*face, *level, t.color());
                }
            }
        }
    }
}

impl Context {
    fn check_target(&mut self, target: GLenum) -> bool {
        if target != GL_FRAMEBUFFER_OES {
            self.bad_enum("target", target);
            return false;
        }
        true
    }

    /// The surface draws go to: the bound framebuffer object's target, else the EGL draw
    /// surface. [`Context::framebuffer_ready`] assembles the former.
    pub(super) fn draw_surface(&self) -> Option<Arc<dyn Surface>> {
        if self.fbo.bound == 0 {
            return self.draw.clone();
        }
        let (s, _) = self.fbo.surface.as_ref()?;
        Some(s.clone() as Arc<dyn Surface>)
    }

    /// The surface reads come from (`glReadPixels`, `glCopyTex*`).
    pub(super) fn read_surface(&self) -> Option<Arc<dyn Surface>> {
        if self.fbo.bound == 0 {
            return self.read.clone();
        }
        self.draw_surface()
    }

    /// The format of what draws go to: the bound framebuffer's (`None` when incomplete) or
    /// the draw surface's.
    /// `GL_SAMPLES` of what draws go to: the draw surface's samples per pixel, 0 for a
    /// single-sample surface, a framebuffer object or none.
    pub(super) fn draw_samples(&self) -> u32 {
        match (&self.draw, self.fbo.bound) {
            (Some(d), 0) => super::context::lock_target(d.as_ref()).samples(),
            _ => 0,
        }
    }

    pub(super) fn current_draw_format(&self) -> Option<TargetFormat> {
        if self.fbo.bound == 0 {
            let d = self.draw.as_ref()?;
            // Known without the target's lock, which workers may hold, when a frame
            // records for it.
            if let Some(f) = self.frame.as_ref().and_then(|r| r.format_for(d)) {
                return Some(f);
            }
            return Some(super::context::lock_target(d.as_ref()).format());
        }
        let fb = self.fbo.names.get(self.fbo.bound)?;
        layout(&lock_objects(&self.shared), fb)
            .ok()
            .map(|l| l.format)
    }

    /// Called before a draw, clear or read: checks the bound framebuffer (object, or the
    /// default one, which a surfaceless context lacks) is complete (else
    /// `GL_INVALID_FRAMEBUFFER_OPERATION_OES` and false) and makes a framebuffer object's target
    /// current, reloading it when its attachments changed since it was assembled.
    pub(super) fn framebuffer_ready(&mut self) -> bool {
        if self.fbo.bound == 0 {
            // OES_surfaceless_context: current without surfaces, the default framebuffer
            // does not exist, so it is never complete.
            if self.draw.is_none() {
                self.set_error(GL_INVALID_FRAMEBUFFER_OPERATION_OES);
                return false;
            }
            return true;
        }
        let fb = self
            .fbo
            .names
            .get(self.fbo.bound)
            .cloned()
            .unwrap_or_default();
        let shared = self.shared.clone();
        let l = {
            let o = lock_objects(&shared);
            match layout(&o, &fb) {
                Ok(l) => l,
                Err(_) => {
                    drop(o);
                    self.set_error(GL_INVALID_FRAMEBUFFER_OPERATION_OES);
                    return false;
                }
            }
        };
        if matches!(&self.fbo.surface, Some((_, k)) if k == &l.key) {
            return true;
        }
        // Pending work belongs to the old attachments: land it there first.
        self.flush();
        let o = lock_objects(&shared);
        // The write-back may have changed versions: assemble from what is there now.
        let l = layout(&o, &fb).unwrap_or(l);
        let target = load(&o, &l);
        drop(o);
        let Some(target) = target else {
            self.set_error(GL_OUT_OF_MEMORY);
            return false;
        };
        self.frame = None;
        self.fbo.surface = Some((
            Arc::new(FboSurface {
                target: Mutex::new(target),
            }),
            l.key,
        ));
        true
    }

    /// Writes the framebuffer object's rendered buffers into its attachments (after the
    /// frame was flushed). The shared objects must not be locked by the caller.
    pub(super) fn fbo_write_back(&mut self) {
        if !self.fbo.dirty {
            return;
        }
        self.fbo.dirty = false;
        let Some((surface, key)) = self.fbo.surface.clone() else {
            return;
        };
        // The write-back may go to a texture this context samples: written in place then.
        self.forget_snapshots();
        let shared = self.shared.clone();
        let mut o = lock_objects(&shared);
        store(&mut o, &super::context::lock_target(surface.as_ref()), &key);
        // Record the versions the write-back gave, so the target is not reloaded for them.
        let new_key: Key = std::array::from_fn(|p| {
            let (a, v) = &key[p];
            let v = image_info(&o, a, p).map_or(*v, |i| i.2);
            (a.clone(), v)
        });
        self.fbo.surface = Some((surface, new_key));
    }

    /// Completes pending framebuffer-object rendering before its attachments change.
    fn fbo_changing(&mut self) {
        if self.fbo.bound != 0 {
            self.flush();
        }
    }

    /// `glDiscardFramebufferEXT`: the named buffers' contents become undefined. Keeping them
    /// is one of the allowed outcomes, and costs nothing here (there is no tile memory to
    /// spare a write-back from); only the arguments are checked. Attachments are named as
    /// for framebuffer objects while one is bound, else as `GL_COLOR_EXT`, `GL_DEPTH_EXT`
    /// and `GL_STENCIL_EXT`.
    pub fn discard_framebuffer(&mut self, target: GLenum, attachments: &[GLenum]) {
        if !self.check_target(target) {
            return;
        }
        let valid = |a: &GLenum| {
            if self.fbo.bound == 0 {
                matches!(*a, GL_COLOR_EXT | GL_DEPTH_EXT | GL_STENCIL_EXT)
            } else {
                attachment_point(*a).is_some()
            }
        };
        if !attachments.iter().all(valid) {
            self.set_error(GL_INVALID_ENUM);
        }
    }

    pub fn gen_framebuffers(&mut self, n: i32) -> Vec<GLuint> {
        if n < 0 {
            self.bad_value("n", n as i64, "n must not be negative");
            return Vec::new();
        }
        (0..n).map(|_| self.fbo.names.generate()).collect()
    }

    pub fn bind_framebuffer(&mut self, target: GLenum, name: GLuint) {
        if !self.check_target(target) {
            return;
        }
        if name == self.fbo.bound {
            return;
        }
        self.flush();
        self.frame = None;
        self.fbo.surface = None;
        if name != 0 {
            self.fbo.names.get_or_create(name);
        }
        self.fbo.bound = name;
    }

    pub fn delete_framebuffers(&mut self, n: i32, names: &[GLuint]) {
        if n < 0 {
            return self.bad_value("n", n as i64, "n must not be negative");
        }
        self.forget_labels(GL_FRAMEBUFFER_OES, names);
        for &name in names {
            if name == 0 {
                continue;
            }
            if name == self.fbo.bound {
                self.bind_framebuffer(GL_FRAMEBUFFER_OES, 0);
            }
            self.fbo.names.remove(name);
        }
    }

    pub fn is_framebuffer(&self, name: GLuint) -> bool {
        name != 0 && self.fbo.names.get(name).is_some()
    }

    pub fn gen_renderbuffers(&mut self, n: i32) -> Vec<GLuint> {
        if n < 0 {
            self.bad_value("n", n as i64, "n must not be negative");
            return Vec::new();
        }
        let mut o = lock_objects(&self.shared);
        (0..n).map(|_| o.renderbuffers.generate()).collect()
    }

    pub fn bind_renderbuffer(&mut self, target: GLenum, name: GLuint) {
        if target != GL_RENDERBUFFER_OES {
            return self.bad_enum("target", target);
        }
        self.fbo.renderbuffer = lock_objects(&self.shared)
            .renderbuffers
            .bind(name, Renderbuffer::default);
    }

    /// `glDeleteRenderbuffersOES`: a deleted renderbuffer is unbound, and detached from the
    /// bound framebuffer object. Other framebuffer objects keep it attached, and other
    /// contexts keep it bound, until they let it go (see [`super::objects`]).
    pub fn delete_renderbuffers(&mut self, n: i32, names: &[GLuint]) {
        if n < 0 {
            return self.bad_value("n", n as i64, "n must not be negative");
        }
        self.forget_labels(GL_RENDERBUFFER_OES, names);
        self.fbo_changing();
        let shared = self.shared.clone();
        for &name in names {
            let Some(gone) = lock_objects(&shared).renderbuffers.delete(name) else {
                continue;
            };
            if self.fbo.renderbuffer.same_object(&gone) {
                self.fbo.renderbuffer = Binding::NONE;
            }
            self.detach(|a| matches!(a, Attachment::Renderbuffer(b) if b.same_object(&gone)));
        }
        self.fbo.surface = None;
        lock_objects(&shared).renderbuffers.sweep();
    }

    /// Detaches from the bound framebuffer object the attachments `f` picks.
    fn detach(&mut self, f: impl Fn(&Attachment) -> bool) {
        if self.fbo.bound == 0 {
            return;
        }
        if let Some(fb) = self.fbo.names.get_mut(self.fbo.bound) {
            for p in &mut fb.points {
                if f(p) {
                    *p = Attachment::None;
                }
            }
        }
    }

    /// Called when textures are deleted: they are detached from the bound framebuffer.
    pub(super) fn textures_deleted(&mut self, deleted: &[Binding]) {
        self.detach(|a| {
            matches!(a, Attachment::Texture { object, .. }
                if deleted.iter().any(|d| d.same_object(object)))
        });
        if !deleted.is_empty() {
            // The assembled target may hold the last reference to a deleted attachment.
            self.fbo.surface = None;
        }
    }

    /// Called before a texture changes: pending rendering into it lands first.
    pub(super) fn fbo_texture_changing(&mut self) {
        self.fbo_changing();
    }

    pub fn is_renderbuffer(&self, name: GLuint) -> bool {
        lock_objects(&self.shared)
            .renderbuffers
            .named(name)
            .is_some()
    }

    /// `glEGLImageTargetRenderbufferStorageOES` (`OES_EGL_image`): the bound renderbuffer
    /// becomes an RGBA8 color buffer holding `image`.
    pub fn egl_image_target_renderbuffer_storage(&mut self, target: GLenum, image: Option<Image>) {
        if target != GL_RENDERBUFFER_OES {
            return self.set_error(GL_INVALID_ENUM);
        }
        let Some(image) = image else {
            return self.set_error(GL_INVALID_VALUE);
        };
        if self.fbo.renderbuffer.is_none() {
            return self.set_error(GL_INVALID_OPERATION);
        }
        self.fbo_changing();
        let mut o = lock_objects(&self.shared);
        let Some(rb) = o.renderbuffers.get_mut(&self.fbo.renderbuffer) else {
            return;
        };
        // Texture images hold RGBA8 words, which is the RGBA8 renderbuffer's encoding too.
        *rb = Renderbuffer {
            internal_format: GL_RGBA8_OES,
            width: image.width,
            height: image.height,
            kind: RenderbufferKind::Color(ColorFormat::Rgba8888),
            words: image.texels,
            bytes: Vec::new(),
            version: next_generation(),
        };
    }

    pub fn renderbuffer_storage(
        &mut self,
        target: GLenum,
        internal_format: GLenum,
        w: i32,
        h: i32,
    ) {
        if target != GL_RENDERBUFFER_OES {
            return self.bad_enum("target", target);
        }
        let Some(kind) = renderbuffer_kind(internal_format) else {
            return self.bad_enum("internalformat", internal_format);
        };
        let max = MAX_RENDERBUFFER_SIZE as i32;
        if !(0..=max).contains(&w) || !(0..=max).contains(&h) {
            return self.bad_value(
                if (0..=max).contains(&w) {
                    "height"
                } else {
                    "width"
                },
                if (0..=max).contains(&w) { h } else { w } as i64,
                "sizes must lie in 0..=GL_MAX_RENDERBUFFER_SIZE_OES",
            );
        }
        if self.fbo.renderbuffer.is_none() {
            return self.bad_operation(
                "no renderbuffer is bound to GL_RENDERBUFFER_OES (name 0 is bound)",
            );
        }
        self.fbo_changing();
        let n = w as usize * h as usize;
        let storage = match kind {
            // Undefined contents: zeros (color), the far plane (depth), zero (stencil).
            RenderbufferKind::Color(c) => {
                try_filled(n, c.encode([0.0; 4])).map(|w| (w, Vec::new()))
            }
            RenderbufferKind::Depth(d) => try_filled(n, d.max()).map(|w| (w, Vec::new())),
            RenderbufferKind::Stencil => try_filled(n, 0).map(|b| (Vec::new(), b)),
            RenderbufferKind::DepthStencil => {
                try_filled(n, DepthFormat::D24.max()).and_then(|w| Some((w, try_filled(n, 0)?)))
            }
        };
        let Some((words, bytes)) = storage else {
            return self.set_error(GL_OUT_OF_MEMORY);
        };
        let mut o = lock_objects(&self.shared);
        let Some(rb) = o.renderbuffers.get_mut(&self.fbo.renderbuffer) else {
            return;
        };
        *rb = Renderbuffer {
            internal_format,
            width: w as u32,
            height: h as u32,
            kind,
            words,
            bytes,
            version: next_generation(),
        };
    }

    pub fn get_renderbuffer_parameter(&mut self, target: GLenum, pname: GLenum) -> Option<i32> {
        if target != GL_RENDERBUFFER_OES {
            self.bad_enum("target", target);
            return None;
        }
        let index = match pname {
            GL_RENDERBUFFER_WIDTH_OES
            | GL_RENDERBUFFER_HEIGHT_OES
            | GL_RENDERBUFFER_INTERNAL_FORMAT_OES => None,
            GL_RENDERBUFFER_RED_SIZE_OES => Some(0),
            GL_RENDERBUFFER_GREEN_SIZE_OES => Some(1),
            GL_RENDERBUFFER_BLUE_SIZE_OES => Some(2),
            GL_RENDERBUFFER_ALPHA_SIZE_OES => Some(3),
            GL_RENDERBUFFER_DEPTH_SIZE_OES => Some(4),
            GL_RENDERBUFFER_STENCIL_SIZE_OES => Some(5),
            _ => {
                self.bad_enum("pname", pname);
                return None;
            }
        };
        if self.fbo.renderbuffer.is_none() {
            self.bad_operation("no renderbuffer is bound to GL_RENDERBUFFER_OES (name 0 is bound)");
            return None;
        }
        let o = lock_objects(&self.shared);
        let rb = o.renderbuffers.get(&self.fbo.renderbuffer)?;
        Some(match (pname, index) {
            (_, Some(i)) => rb.sizes()[i] as i32,
            (GL_RENDERBUFFER_WIDTH_OES, _) => rb.width as i32,
            (GL_RENDERBUFFER_HEIGHT_OES, _) => rb.height as i32,
            _ => rb.internal_format as i32,
        })
    }

    pub fn framebuffer_renderbuffer(
        &mut self,
        target: GLenum,
        attachment: GLenum,
        rb_target: GLenum,
        rb: GLuint,
    ) {
        if !self.check_target(target) {
            return;
        }
        let Some(point) = attachment_point(attachment) else {
            return self.bad_enum("attachment", attachment);
        };
        if rb_target != GL_RENDERBUFFER_OES {
            return self.bad_enum("renderbuffertarget", rb_target);
        }
        if self.fbo.bound == 0 {
            return self.bad_operation(
                "the default framebuffer (name 0) is bound; its attachments cannot change",
            );
        }
        let a = if rb == 0 {
            Attachment::None
        } else {
            let mut o = lock_objects(&self.shared);
            if o.renderbuffers.named(rb).is_none() {
                drop(o);
                return self.bad_operation(
                    "renderbuffer is not the name of an existing renderbuffer object",
                );
            }
            Attachment::Renderbuffer(o.renderbuffers.bind(rb, Renderbuffer::default))
        };
        self.fbo_changing();
        if let Some(fb) = self.fbo.names.get_mut(self.fbo.bound) {
            fb.points[point] = a;
        }
    }

    pub fn framebuffer_texture_2d(
        &mut self,
        target: GLenum,
        attachment: GLenum,
        tex_target: GLenum,
        texture: GLuint,
        level: i32,
    ) {
        if !self.check_target(target) {
            return;
        }
        let Some(point) = attachment_point(attachment) else {
            return self.bad_enum("attachment", attachment);
        };
        let face = match tex_target {
            GL_TEXTURE_2D => 0u8,
            t if (GL_TEXTURE_CUBE_MAP_POSITIVE_X_OES..=GL_TEXTURE_CUBE_MAP_NEGATIVE_Z_OES)
                .contains(&t) =>
            {
                (t - GL_TEXTURE_CUBE_MAP_POSITIVE_X_OES + 1) as u8
            }
            _ if texture == 0 => 0,
            _ => return self.bad_enum("textarget", tex_target),
        };
        if self.fbo.bound == 0 {
            return self.bad_operation(
                "the default framebuffer (name 0) is bound; its attachments cannot change",
            );
        }
        let a = if texture == 0 {
            Attachment::None
        } else {
            // OES_fbo_render_mipmap: any level a texture of the largest size has.
            if !(0..=MAX_LEVEL as i32).contains(&level) {
                return self.bad_value(
                    "level",
                    level as i64,
                    "level must lie in 0..=log2(GL_MAX_TEXTURE_SIZE)",
                );
            }
            let mut o = lock_objects(&self.shared);
            let Some(is_cube) = o.textures.named(texture).map(|t| t.is_cube_map()) else {
                drop(o);
                return self.bad_operation("texture is not the name of an existing texture object");
            };
            if is_cube != (face != 0) {
                drop(o);
                return self.bad_operation("textarget does not match the texture's kind (a cube map face for a cube map texture, GL_TEXTURE_2D for a 2D one)");
            }
            Attachment::Texture {
                object: o.textures.bind(texture, Texture::new),
                level: level as usize,
                face,
            }
        };
        self.fbo_changing();
        if let Some(fb) = self.fbo.names.get_mut(self.fbo.bound) {
            fb.points[point] = a;
        }
    }

    pub fn check_framebuffer_status(&mut self, target: GLenum) -> GLenum {
        if !self.check_target(target) {
            return 0;
        }
        if self.fbo.bound == 0 {
            return if self.draw.is_some() {
                GL_FRAMEBUFFER_COMPLETE_OES
            } else {
                GL_FRAMEBUFFER_UNDEFINED_OES
            };
        }
        let fb = self
            .fbo
            .names
            .get(self.fbo.bound)
            .cloned()
            .unwrap_or_default();
        match layout(&lock_objects(&self.shared), &fb) {
            Ok(_) => GL_FRAMEBUFFER_COMPLETE_OES,
            Err(e) => e,
        }
    }

    pub fn get_framebuffer_attachment_parameter(
        &mut self,
        target: GLenum,
        attachment: GLenum,
        pname: GLenum,
    ) -> Option<i32> {
        if !self.check_target(target) {
            return None;
        }
        let Some(point) = attachment_point(attachment) else {
            self.bad_enum("attachment", attachment);
            return None;
        };
        if self.fbo.bound == 0 {
            self.bad_operation(
                "the default framebuffer (name 0) is bound; it has no attachments to query",
            );
            return None;
        }
        let a = self.fbo.names.get(self.fbo.bound)?.points[point].clone();
        let v = match (pname, a) {
            (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_OES, Attachment::None) => Some(0),
            (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_OES, Attachment::Renderbuffer(_)) => {
                Some(GL_RENDERBUFFER_OES as i32)
            }
            (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_OES, Attachment::Texture { .. }) => {
                Some(GL_TEXTURE as i32)
            }
            (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_OES, Attachment::Renderbuffer(b)) => {
                Some(b.name as i32)
            }
            (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_OES, Attachment::Texture { object, .. }) => {
                Some(object.name as i32)
            }
            (GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL_OES, Attachment::Texture { level, .. }) => {
                Some(level as i32)
            }
            (
                GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE_OES,
                Attachment::Texture { face, .. },
            ) => Some(if face == 0 {
                0
            } else {
                (GL_TEXTURE_CUBE_MAP_POSITIVE_X_OES + face as u32 - 1) as i32
            }),
            _ => None,
        };
        if v.is_none() {
            self.bad_enum("pname", pname);
        }
        v
    }

    /// `glGenerateMipmapOES`: rebuilds the bound texture's chain from level 0 (each cube
    /// face from its own level 0).
    pub fn generate_mipmap(&mut self, target: GLenum) {
        let cube = match target {
            GL_TEXTURE_2D => false,
            GL_TEXTURE_CUBE_MAP_OES => true,
            _ => return self.bad_enum("target", target),
        };
        self.fbo_changing();
        let ok = self.with_target_texture(cube, |t| t.generate_mipmaps_checked());
        if !ok {
            self.bad_operation("the cube map's faces are not cube complete at level 0 (each face square, of one size and format)");
        }
    }

    /// The `glGet*` values of this area.
    pub(super) fn fbo_value(&self, pname: GLenum) -> Option<Value> {
        Some(match pname {
            GL_FRAMEBUFFER_BINDING_OES => Value::int(self.fbo.bound as i64),
            GL_RENDERBUFFER_BINDING_OES => Value::int(self.fbo.renderbuffer.name as i64),
            GL_MAX_RENDERBUFFER_SIZE_OES => Value::int(MAX_RENDERBUFFER_SIZE as i64),
            _ => return None,
        })
    }
}
