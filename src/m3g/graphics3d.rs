//! `Graphics3D`: binds a target and renders scene graphs and submeshes into it through the
//! core (ARCHITECTURE decision 7): each submesh becomes a `core::RenderState` plus a
//! `core::DrawCall`, recorded into a `core::Frame` and flushed into the `core::Target`.

use std::cell::RefCell;
use std::collections::HashMap;
use std::rc::Rc;
use std::sync::Arc;

use glam::{Mat4, Vec3, Vec4};

use crate::core::state::{
    AlphaTest, Blend, BlendFactor, Light as CoreLight, Lighting, Material as CoreMaterial,
};
use crate::core::texenv::{self, EnvMode, FogMode, TexEnv, TextureUnit};
use crate::core::texture::{BaseFormat, Image as TexImage, MagFilter, MinFilter, Sampler, Wrap};
use crate::core::{
    self, AttribArray, AttribSource, ColorFormat, CompareFunc, CullFace, DepthFormat, DrawCall,
    Frame, Indices, Primitive, Rect, RenderState, ShadeModel, Target, TargetFormat, Viewport,
    Winding,
};

use super::appearance::{
    Appearance, Background, CompositingMode, Fog, FogData, MaterialData, PolygonMode, Texture2D,
    TextureData, MAX_TEXTURE_DIMENSION,
};
use super::camera::Camera;
use super::error::{iae, ioobe, ise, Result};
use super::image::{Image2D, ImageData};
use super::light::Light;
use super::mesh::{Mesh, Sprite3D, MAX_SPRITE_CROP_DIMENSION};
use super::node::{node_data, root_of, to_ancestor, NodeExt, World};
use super::object::{tf, Handle, Kind, ObjRef};
use super::transform::{invert, Transform};
use super::vertex::{IndexBuffer, VertexBuffer, VertexBufferData, NUM_TEXTURE_UNITS};

/// The largest viewport and target width and height.
pub const MAX_VIEWPORT_DIMENSION: i32 = core::MAX_VIEWPORT_DIM as i32;
/// The most lights that affect one submesh (`maxLights`).
pub const MAX_LIGHTS: usize = 8;

/// A value of [`Graphics3D::get_properties`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Property {
    /// A `java.lang.Boolean`.
    Bool(bool),
    /// A `java.lang.Integer`.
    Int(i32),
}

struct Bound {
    target: Target,
    frame: Frame,
    image: Option<Image2D>,
    /// The `Image2D` format the target stands for: a background image must have it.
    format: i32,
    depth: bool,
    hints: i32,
}

/// A light as the core takes it (eye coordinates, intensity folded into the colors) with
/// the scope of its node.
#[derive(Clone, Copy, Debug)]
struct EyeLight {
    light: CoreLight,
    scope: i32,
}

/// One thing to draw, found in a scene graph.
struct Item {
    layer: i32,
    blended: bool,
    what: What,
    model: Mat4,
    alpha: f32,
    scope: i32,
    /// Whether the item may be culled against its bounds (a plain Mesh's submesh or an
    /// immediate-mode submesh; deformed meshes are not, as their base bounds do not hold).
    cullable: bool,
}

/// What rendering has done since the context was made or [`Graphics3D::reset_stats`] was
/// called (a Rust extension, for tests and profiling).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RenderStats {
    /// Submeshes handed to the core.
    pub submeshes_drawn: u64,
    /// Submeshes skipped because their bounding sphere lies outside the view frustum.
    pub submeshes_culled: u64,
    /// Vertices handed to the core to transform: the index range of every drawn submesh.
    pub vertices_transformed: u64,
    /// Texture images converted into core textures (again only when the image contents,
    /// filters or wrapping change).
    pub texture_uploads: u64,
}

/// A texture image converted for the core, with what it was made from.
struct TexEntry {
    /// Keeps the image alive, so its address (the key) is not reused.
    _image: Image2D,
    /// The pixels converted, for a mutable image (whose contents may change in place).
    pixels: Option<Vec<u8>>,
    sampler: Arc<Sampler>,
    /// The render call that last used it.
    used: u64,
}

type TexKey = (usize, MinFilter, MagFilter, Wrap, Wrap);

/// The core textures of the Texture2D images in use, kept across render calls.
#[derive(Default)]
struct TexCache {
    entries: HashMap<TexKey, TexEntry>,
    /// Render calls so far.
    calls: u64,
}

enum What {
    Submesh(VertexBuffer, IndexBuffer, Appearance),
    Sprite(Sprite3D, Appearance),
}

/// `Graphics3D`: the render context.
///
/// | Java | Rust |
/// |---|---|
/// | `getInstance()` | [`get_instance`](Self::get_instance) (one per thread) or [`new`](Self::new) |
/// | `bindTarget(Image2D[, depth, hints])` | [`bind_image`](Self::bind_image) |
/// | `bindTarget(Graphics …)` | [`bind_target`](Self::bind_target) with a `core::Target` |
/// | `releaseTarget()` | [`release_target`](Self::release_target) |
/// | `getTarget()` | [`target_image`](Self::target_image), [`target`](Self::target) |
/// | `getHints()` / `isDepthBufferEnabled()` | [`hints`](Self::hints) / [`is_depth_buffer_enabled`](Self::is_depth_buffer_enabled) |
/// | `setViewport` / `getViewportX/Y/Width/Height` | [`set_viewport`](Self::set_viewport) / [`viewport`](Self::viewport) |
/// | `setDepthRange` / `getDepthRangeNear/Far` | [`set_depth_range`](Self::set_depth_range) / [`depth_range`](Self::depth_range) |
/// | `clear(Background)` | [`clear`](Self::clear) |
/// | `render(World)` | [`render_world`](Self::render_world) |
/// | `render(Node, Transform)` | [`render_node`](Self::render_node) |
/// | `render(VertexBuffer, IndexBuffer, Appearance, Transform[, scope])` | [`render_submesh`](Self::render_submesh) |
/// | `setCamera` / `getCamera` | [`set_camera`](Self::set_camera) / [`camera`](Self::camera) |
/// | `addLight` / `setLight` / `resetLights` / `getLightCount` / `getLight` | [`add_light`](Self::add_light) / [`set_light`](Self::set_light) / [`reset_lights`](Self::reset_lights) / [`light_count`](Self::light_count) / [`light`](Self::light) |
/// | `getProperties()` | [`get_properties`](Self::get_properties) |
///
/// # Rendering
///
/// Every rendering semantic comes from the core: an Appearance becomes a `RenderState`
/// (CompositingMode, PolygonMode, the Material as `core` lighting with zero scene ambient,
/// vertex color tracking as color material and two-sided lighting from the PolygonMode;
/// Fog as the core's per-pixel fog; each Texture2D as a texture unit with its blending
/// function, blend color, wrapping, filters and generated mipmaps, and its T·R·S·M after
/// the coordinates' scale and bias in the texture matrix) and a VertexBuffer a `DrawCall`.
/// The alpha factor multiplies the material's diffuse alpha, or the vertex alpha when
/// there is no Material or it tracks vertex colors. Local camera lighting is not supported
/// (`supportLocalCameraLighting` is false: the core's lighting has the viewer at infinity,
/// as M3G's default); perspective correction is always exact.
///
/// Scene graphs: node-to-world transforms and the bounds of position arrays are cached
/// with dirty flags, and a submesh whose bounding sphere lies outside the view frustum is
/// skipped before any of its vertices is transformed ([`stats`](Self::stats) counts both;
/// [`set_culling_enable`](Self::set_culling_enable) turns culling off).
pub struct Graphics3D {
    bound: Option<Bound>,
    viewport: [i32; 4],
    depth_range: [f32; 2],
    camera: Option<(Camera, Mat4)>,
    lights: Vec<Option<(Light, Mat4)>>,
    culling: bool,
    clamp_after_lighting: bool,
    stats: RenderStats,
    textures: TexCache,
}

impl Default for Graphics3D {
    fn default() -> Self {
        Graphics3D::new()
    }
}

thread_local! {
    static INSTANCE: Rc<RefCell<Graphics3D>> = Rc::new(RefCell::new(Graphics3D::new()));
}

impl Graphics3D {
    /// Antialiasing hint.
    pub const ANTIALIAS: i32 = 2;
    /// Dithering hint.
    pub const DITHER: i32 = 4;
    /// High-precision color hint.
    pub const TRUE_COLOR: i32 = 8;
    /// The target's previous contents need not be kept.
    pub const OVERWRITE: i32 = 16;

    /// A new, unbound context: depth range [0, 1], no camera, no lights.
    pub fn new() -> Graphics3D {
        Graphics3D {
            bound: None,
            viewport: [0, 0, 0, 0],
            depth_range: [0.0, 1.0],
            camera: None,
            lights: Vec::new(),
            culling: true,
            clamp_after_lighting: true,
            stats: RenderStats::default(),
            textures: TexCache::default(),
        }
    }

    /// Turns view-frustum culling of submeshes on (the default) or off (a Rust extension:
    /// the pixels are the same either way; culling only skips work).
    pub fn set_culling_enable(&mut self, enable: bool) {
        self.culling = enable;
    }

    /// Whether view-frustum culling is on.
    pub fn is_culling_enabled(&self) -> bool {
        self.culling
    }

    /// Whether lit colors are clamped to [0, 1] right after lighting (the default, as the
    /// OpenGL 1.3 lighting that M3G cites requires) or only after texturing (a Rust
    /// extension). The JSR-184 reference images in the M3G corpus were rendered on Mesa,
    /// which clamps late: a specular highlight above 1 then brightens the texture it
    /// modulates. Turn clamping off to reproduce those images.
    pub fn set_clamp_after_lighting(&mut self, enable: bool) {
        self.clamp_after_lighting = enable;
    }

    /// Whether lit colors are clamped right after lighting.
    pub fn is_clamp_after_lighting(&self) -> bool {
        self.clamp_after_lighting
    }

    /// What rendering has done so far (a Rust extension).
    pub fn stats(&self) -> RenderStats {
        self.stats
    }

    /// Sets every counter of [`stats`](Self::stats) to 0.
    pub fn reset_stats(&mut self) {
        self.stats = RenderStats::default();
    }

    /// `getInstance()`: the same context every time (per thread: M3G objects are not `Send`).
    pub fn get_instance() -> Rc<RefCell<Graphics3D>> {
        INSTANCE.with(|i| i.clone())
    }

    fn check_bind(&self, w: u32, h: u32, hints: i32) -> Result<()> {
        if self.bound.is_some() {
            return ise("a target is already bound");
        }
        if w as i64 > MAX_VIEWPORT_DIMENSION as i64 || h as i64 > MAX_VIEWPORT_DIMENSION as i64 {
            return iae("target larger than the maximum viewport");
        }
        if hints & !0x1E != 0 {
            return iae("invalid hints");
        }
        Ok(())
    }

    fn bind(&mut self, target: Target, image: Option<Image2D>, depth: bool, hints: i32) {
        let format = match (&image, target.format().color) {
            (Some(i), _) => i.format(),
            (None, ColorFormat::Rgba8888) => Image2D::RGBA,
            (None, _) => Image2D::RGB,
        };
        self.bind_as(target, image, format, depth, hints);
    }

    fn bind_as(
        &mut self,
        target: Target,
        image: Option<Image2D>,
        format: i32,
        depth: bool,
        hints: i32,
    ) {
        let (w, h) = (target.width(), target.height());
        self.viewport = [0, 0, w as i32, h as i32];
        self.bound = Some(Bound {
            frame: Frame::new(w, h, target.format()),
            depth: depth && target.format().depth.is_some(),
            target,
            image,
            format,
            hints,
        });
    }

    /// `bindTarget(image, depthBuffer, hints)` (`bindTarget(image)` is `(image, true, 0)`).
    /// IllegalState if a target is bound (here or, for this image, anywhere);
    /// IllegalArgument for an immutable image, a format other than RGB and RGBA, an image
    /// larger than the maximum viewport, or hints outside ANTIALIAS | DITHER | TRUE_COLOR |
    /// OVERWRITE. The viewport becomes the whole image.
    pub fn bind_image(&mut self, image: &Image2D, depth_buffer: bool, hints: i32) -> Result<()> {
        let d = image.d();
        if d.bound {
            return ise("the image is already bound to a Graphics3D");
        }
        if !d.mutable {
            return iae("the target image is immutable");
        }
        let color = match d.format {
            Image2D::RGB => ColorFormat::Rgb888,
            Image2D::RGBA => ColorFormat::Rgba8888,
            _ => return iae("the target image must be RGB or RGBA"),
        };
        self.check_bind(d.width as u32, d.height as u32, hints)?;
        let (w, h) = (d.width as u32, d.height as u32);
        let mut target = Target::new(
            w,
            h,
            TargetFormat {
                color,
                depth: Some(DepthFormat::D24),
                stencil_bits: 0,
            },
        );
        let b = if color == ColorFormat::Rgb888 { 3 } else { 4 };
        for y in 0..h as usize {
            for x in 0..w as usize {
                let p = &d.pixels[(y * w as usize + x) * b..][..b];
                let a = if b == 4 { p[3] } else { 255 };
                target.color_mut()[(h as usize - 1 - y) * w as usize + x] =
                    u32::from_le_bytes([p[0], p[1], p[2], a]);
            }
        }
        drop(d);
        image.dm().bound = true;
        self.bind(target, Some(image.clone()), depth_buffer, hints);
        Ok(())
    }

    /// `bindTarget` for a `core::Target` (what an EGL surface owns; its row 0 is the bottom
    /// row, so M3G's top-left origin is its top row). The target is moved in and given back
    /// by [`release_target`](Self::release_target). The depth buffer is used only if the
    /// target has one and `depth_buffer` is true.
    pub fn bind_target(&mut self, target: Target, depth_buffer: bool, hints: i32) -> Result<()> {
        self.check_bind(target.width(), target.height(), hints)?;
        self.bind(target, None, depth_buffer, hints);
        Ok(())
    }

    /// `bindTarget(graphics, depthBuffer, hints)` for a MIDP `Graphics` target, whose format
    /// is always RGB (M3G 1.1, `Graphics3D`): `target` is the buffer that renders it (RGBA
    /// as a phone's back buffer is, or RGB), and a background image must be RGB, as content
    /// made for phones has it. Otherwise as [`bind_target`](Self::bind_target).
    pub fn bind_graphics_target(
        &mut self,
        target: Target,
        depth_buffer: bool,
        hints: i32,
    ) -> Result<()> {
        self.check_bind(target.width(), target.height(), hints)?;
        self.bind_as(target, None, Image2D::RGB, depth_buffer, hints);
        Ok(())
    }

    /// `releaseTarget()`: finishes rendering and unbinds. An Image2D target receives the
    /// pixels; a `core::Target` is returned. Nothing bound: nothing happens.
    pub fn release_target(&mut self) -> Option<Target> {
        let mut b = self.bound.take()?;
        b.frame.flush_into(&mut b.target);
        match b.image {
            Some(img) => {
                let mut d = img.dm();
                d.bound = false;
                let (w, h) = (d.width as usize, d.height as usize);
                let bpp = if d.format == Image2D::RGB { 3 } else { 4 };
                for y in 0..h {
                    for x in 0..w {
                        let px = b.target.color()[(h - 1 - y) * w + x].to_le_bytes();
                        d.pixels[(y * w + x) * bpp..][..bpp].copy_from_slice(&px[..bpp]);
                    }
                }
                None
            }
            None => Some(b.target),
        }
    }

    /// `getTarget()` for an Image2D target.
    pub fn target_image(&self) -> Option<Image2D> {
        self.bound.as_ref().and_then(|b| b.image.clone())
    }

    /// The bound `core::Target` with every pending pixel written (for any kind of target).
    pub fn target(&mut self) -> Option<&Target> {
        let b = self.bound.as_mut()?;
        b.frame.flush_into(&mut b.target);
        Some(&b.target)
    }

    /// `getHints()`: as given to the bind call (0 when unbound).
    pub fn hints(&self) -> i32 {
        self.bound.as_ref().map_or(0, |b| b.hints)
    }

    /// `isDepthBufferEnabled()` (false when unbound).
    pub fn is_depth_buffer_enabled(&self) -> bool {
        self.bound.as_ref().is_some_and(|b| b.depth)
    }

    /// `setViewport(x, y, width, height)`: top-left origin; x and y may be anything.
    /// IllegalArgument for a size ≤ 0 or above the maximum.
    pub fn set_viewport(&mut self, x: i32, y: i32, width: i32, height: i32) -> Result<()> {
        if width <= 0
            || height <= 0
            || width > MAX_VIEWPORT_DIMENSION
            || height > MAX_VIEWPORT_DIMENSION
        {
            return iae("invalid viewport size");
        }
        self.viewport = [x, y, width, height];
        Ok(())
    }

    /// `getViewportX/Y/Width/Height()`: [x, y, width, height].
    pub fn viewport(&self) -> [i32; 4] {
        self.viewport
    }

    /// `setDepthRange(near, far)`: IllegalArgument unless both are in [0, 1]; near > far is
    /// allowed.
    pub fn set_depth_range(&mut self, near: f32, far: f32) -> Result<()> {
        if !(0.0..=1.0).contains(&near) || !(0.0..=1.0).contains(&far) {
            return iae("depth range must be in [0, 1]");
        }
        self.depth_range = [near, far];
        Ok(())
    }

    /// `getDepthRangeNear/Far()`: [near, far].
    pub fn depth_range(&self) -> [f32; 2] {
        self.depth_range
    }

    /// `setCamera(camera, transform)`: the camera-to-world transform is copied (`None` =
    /// identity). Arithmetic if it is not invertible.
    pub fn set_camera(&mut self, camera: Option<&Camera>, t: Option<&Transform>) -> Result<()> {
        let m = t.map_or(Mat4::IDENTITY, |t| t.m);
        invert(&m)?;
        self.camera = camera.map(|c| (c.clone(), m));
        Ok(())
    }

    /// `getCamera(transform)`: the camera and its camera-to-world transform.
    pub fn camera(&self) -> Option<(Camera, Transform)> {
        self.camera
            .as_ref()
            .map(|(c, m)| (c.clone(), Transform::from_mat4(*m)))
    }

    /// `addLight(light, transform)`: appends the light with its light-to-world transform
    /// (`None` = identity) and returns its index.
    pub fn add_light(&mut self, light: &Light, t: Option<&Transform>) -> i32 {
        self.lights
            .push(Some((light.clone(), t.map_or(Mat4::IDENTITY, |t| t.m))));
        self.lights.len() as i32 - 1
    }

    /// `setLight(index, light, transform)`: `None` empties the slot. IndexOutOfBounds for a
    /// bad index.
    pub fn set_light(
        &mut self,
        index: i32,
        light: Option<&Light>,
        t: Option<&Transform>,
    ) -> Result<()> {
        if index < 0 || index as usize >= self.lights.len() {
            return ioobe("light index");
        }
        self.lights[index as usize] = light.map(|l| (l.clone(), t.map_or(Mat4::IDENTITY, |t| t.m)));
        Ok(())
    }

    /// `resetLights()`.
    pub fn reset_lights(&mut self) {
        self.lights.clear();
    }

    /// `getLightCount()`: including empty slots.
    pub fn light_count(&self) -> i32 {
        self.lights.len() as i32
    }

    /// `getLight(index, transform)`: the light and its transform, `None` for an empty slot.
    /// IndexOutOfBounds for a bad index.
    pub fn light(&self, index: i32) -> Result<Option<(Light, Transform)>> {
        if index < 0 || index as usize >= self.lights.len() {
            return ioobe("light index");
        }
        Ok(self.lights[index as usize]
            .as_ref()
            .map(|(l, m)| (l.clone(), Transform::from_mat4(*m))))
    }

    /// `getProperties()`: the implementation's capabilities.
    pub fn get_properties() -> HashMap<&'static str, Property> {
        use Property::{Bool, Int};
        HashMap::from([
            ("supportAntialiasing", Bool(false)),
            ("supportTrueColor", Bool(false)),
            ("supportDithering", Bool(true)),
            ("supportMipmapping", Bool(true)),
            ("supportPerspectiveCorrection", Bool(true)),
            ("supportLocalCameraLighting", Bool(false)),
            ("maxLights", Int(MAX_LIGHTS as i32)),
            ("maxViewportWidth", Int(MAX_VIEWPORT_DIMENSION)),
            ("maxViewportHeight", Int(MAX_VIEWPORT_DIMENSION)),
            ("maxViewportDimension", Int(MAX_VIEWPORT_DIMENSION)),
            ("maxTextureDimension", Int(MAX_TEXTURE_DIMENSION)),
            ("maxSpriteCropDimension", Int(MAX_SPRITE_CROP_DIMENSION)),
            ("maxTransformsPerVertex", Int(4)),
            ("numTextureUnits", Int(NUM_TEXTURE_UNITS as i32)),
        ])
    }

    // ----------------------------------------------------------------------------------
    // Clearing

    fn bound_mut(&mut self) -> Result<&mut Bound> {
        match self.bound.as_mut() {
            Some(b) => Ok(b),
            None => ise("no target is bound"),
        }
    }

    /// The viewport ∩ target rectangle in the core's bottom-up rows.
    fn clear_rect(&self) -> Rect {
        let b = self.bound.as_ref().unwrap();
        let th = b.target.height() as i32;
        let [x, y, w, h] = self.viewport;
        Rect::new(x, th - y - h, w, h).intersect(b.target.bounds())
    }

    /// Checks that `bg`'s image (if any) has the target's format; the error names both.
    fn check_bg_format(&self, bg: Option<&Background>) -> std::result::Result<(), String> {
        let want = self.bound.as_ref().unwrap().format;
        match bg.and_then(|bg| bg.image()).map(|i| i.format()) {
            Some(f) if f != want => Err(format!(
                "background image format {} differs from the target's {}",
                format_name(f),
                format_name(want)
            )),
            _ => Ok(()),
        }
    }

    /// `clear(background)`: clears viewport ∩ target as `background` says (`None`: color
    /// transparent black and depth). IllegalState without a target; IllegalArgument if the
    /// background image's format differs from the target's.
    pub fn clear(&mut self, background: Option<&Background>) -> Result<()> {
        self.bound_mut()?;
        if let Err(m) = self.check_bg_format(background) {
            return iae(m);
        }
        self.do_clear(background);
        self.flush();
        Ok(())
    }

    fn do_clear(&mut self, background: Option<&Background>) {
        let rect = self.clear_rect();
        let [vx, vy, vw, vh] = self.viewport;
        let b = self.bound.as_mut().unwrap();
        let (color_clear, depth_clear, argb, image, modes, crop) = match background {
            Some(bg) => {
                let d = bg.d();
                (
                    d.color_clear,
                    d.depth_clear,
                    d.color,
                    d.image.clone(),
                    d.mode,
                    d.crop,
                )
            }
            None => (true, true, 0, None, [0; 2], [0; 4]),
        };
        let format = b.target.format();
        let bg_rgba = argb_to_rgba(argb);
        if color_clear {
            match image.filter(|_| crop[2] > 0 && crop[3] > 0) {
                None => b.frame.clear_color(rect, format.color.encode(bg_rgba), 0),
                Some(img) => {
                    b.frame.flush_into(&mut b.target);
                    let d = img.d();
                    let th = b.target.height() as i32;
                    let tw = b.target.width() as usize;
                    let pick = |v: i32, n: i32, mode: i32| -> Option<i32> {
                        if (0..n).contains(&v) {
                            Some(v)
                        } else if mode == Background::REPEAT {
                            Some(v.rem_euclid(n))
                        } else {
                            None
                        }
                    };
                    for gy in rect.y0..rect.y1 {
                        let py = th - 1 - gy; // M3G row
                        let v = crop[1]
                            + (((py - vy) as f64 + 0.5) * crop[3] as f64 / vh as f64).floor()
                                as i32;
                        for px in rect.x0..rect.x1 {
                            let u = crop[0]
                                + (((px - vx) as f64 + 0.5) * crop[2] as f64 / vw as f64).floor()
                                    as i32;
                            let c = match (pick(u, d.width, modes[0]), pick(v, d.height, modes[1]))
                            {
                                (Some(x), Some(y)) => d.rgba(x, y),
                                _ => bg_rgba,
                            };
                            b.target.color_mut()[gy as usize * tw + px as usize] =
                                format.color.encode(c);
                        }
                    }
                }
            }
        }
        if depth_clear && b.depth {
            if let Some(f) = format.depth {
                b.frame.clear_depth(rect, f.max());
            }
        }
    }

    fn flush(&mut self) {
        if let Some(b) = self.bound.as_mut() {
            b.frame.flush_into(&mut b.target);
        }
    }

    // ----------------------------------------------------------------------------------
    // Rendering

    /// `render(world)`: clears with the World's background, makes its active camera and its
    /// enabled lights the current ones (replacing the immediate-mode camera and lights) and
    /// draws every enabled, in-scope mesh and sprite, layer by layer, opaque before blended.
    /// IllegalState without a target, without an active camera in the world, for a
    /// background image of the wrong format, or invalid mesh data; Arithmetic if the
    /// camera's transform to the world is singular.
    pub fn render_world(&mut self, world: &World) -> Result<()> {
        self.bound_mut()?;
        let Some(camera) = world.active_camera() else {
            return ise("the world has no active camera");
        };
        if !Rc::ptr_eq(&root_of(&camera.0), &world.0) {
            return ise("the active camera is not in the world");
        }
        let bg = world.background();
        if let Err(m) = self.check_bg_format(bg.as_ref()) {
            return ise(m);
        }
        let cam_to_world = to_ancestor(&camera.0, &world.0);
        invert(&cam_to_world)?;
        self.camera = Some((camera.clone(), cam_to_world));
        self.lights.clear();
        let mut lights = Vec::new();
        collect_lights(&world.0, &mut lights);
        self.lights = lights.into_iter().map(Some).collect();
        self.do_clear(bg.as_ref());
        let children = world.0.borrow().group().unwrap().children.clone();
        let mut items = Vec::new();
        let scope = node_data(&camera.0).scope;
        if camera.projection_matrix().is_some() {
            for c in &children {
                // In its own statement: the borrow of `c` must end before its items are
                // collected (a SkinnedMesh writes its own cache then).
                let m = tf(c).world(Mat4::IDENTITY);
                collect_at(c, m, 1.0, scope, &mut items)?;
            }
        }
        let r = self.draw_items(items);
        self.flush();
        r
    }

    /// `render(node, transform)`: draws a Mesh, Sprite3D or Group (a World counts as a
    /// Group) with `transform` as its node-to-world transform (`None` = identity), ignoring
    /// the node's own transform and ancestors, with the current camera and lights. It does not
    /// clear. IllegalArgument for a Camera or Light; IllegalState without a target or camera,
    /// or for invalid mesh data.
    pub fn render_node<N: NodeExt>(&mut self, node: &N, t: Option<&Transform>) -> Result<()> {
        if matches!(node.raw().borrow().kind, Kind::Camera(_) | Kind::Light(_)) {
            return iae("cannot render a Camera or Light");
        }
        self.bound_mut()?;
        let Some((camera, _)) = self.camera.clone() else {
            return ise("no camera");
        };
        let m = t.map_or(Mat4::IDENTITY, |t| t.m);
        let mut items = Vec::new();
        if camera.projection_matrix().is_some() {
            collect_at(node.raw(), m, 1.0, node_data(&camera.0).scope, &mut items)?;
        }
        let r = self.draw_items(items);
        self.flush();
        r
    }

    /// `render(vertices, triangles, appearance, transform, scope)` (use scope −1 for the
    /// 4-argument form): draws one submesh if `scope` shares a bit with the camera's.
    /// IllegalState without a target or camera, or for invalid data.
    pub fn render_submesh(
        &mut self,
        vb: &VertexBuffer,
        ib: &IndexBuffer,
        app: &Appearance,
        t: Option<&Transform>,
        scope: i32,
    ) -> Result<()> {
        self.bound_mut()?;
        let Some((camera, _)) = self.camera.clone() else {
            return ise("no camera");
        };
        if camera.projection_matrix().is_none() || node_data(&camera.0).scope & scope == 0 {
            return Ok(());
        }
        validate(vb, ib)?;
        let item = Item {
            layer: app.layer(),
            blended: is_blended(app),
            what: What::Submesh(vb.clone(), ib.clone(), app.clone()),
            model: t.map_or(Mat4::IDENTITY, |t| t.m),
            alpha: 1.0,
            scope,
            cullable: true,
        };
        let r = self.draw_items(vec![item]);
        self.flush();
        r
    }

    fn draw_items(&mut self, mut items: Vec<Item>) -> Result<()> {
        let Some((camera, cam_to_world)) = self.camera.clone() else {
            return ise("no camera");
        };
        let Some(projection) = camera.projection_matrix() else {
            return Ok(());
        };
        let view = invert(&cam_to_world)?;
        let lights = self.eye_lights(&view);
        items.sort_by_key(|i| (i.layer, i.blended));
        let base = self.base_state(projection);
        let Graphics3D {
            bound,
            culling,
            clamp_after_lighting,
            stats,
            textures,
            ..
        } = self;
        let b = bound.as_mut().unwrap();
        textures.calls += 1;
        for item in &items {
            let mut s = base.clone();
            let modelview = view * item.model;
            match &item.what {
                What::Submesh(vb, ib, app) => {
                    if *culling && item.cullable && outside_frustum(&vb.d(), modelview, projection)
                    {
                        stats.submeshes_culled += 1;
                        continue;
                    }
                    s.modelview = modelview;
                    let lit = LitBy {
                        lights: &lights,
                        clamp_after_lighting: *clamp_after_lighting,
                    };
                    draw_submesh(&mut s, b, textures, stats, vb, ib, app, item, lit);
                }
                What::Sprite(sprite, app) => {
                    draw_sprite(&s, b, sprite, app, modelview, item.alpha);
                }
            }
            b.frame.flush_if_full(&mut b.target);
        }
        // Textures unused for a while are dropped.
        let calls = textures.calls;
        textures
            .entries
            .retain(|_, e| calls.saturating_sub(e.used) < 16);
        Ok(())
    }

    /// The enabled lights of the light array in eye coordinates, as core lights (M3G §2.6:
    /// the intensity scales the colors; AMBIENT has only an ambient color, the others only
    /// diffuse and specular; directional lights shine along their local −Z).
    fn eye_lights(&self, view: &Mat4) -> Vec<EyeLight> {
        let mut out = Vec::new();
        for (light, m) in self.lights.iter().flatten() {
            let nd = node_data(&light.0);
            if !nd.rendering {
                continue;
            }
            let d = light.d();
            let mv = *view * *m;
            let [r, g, b, _] = argb_to_rgba(d.color);
            let color = (Vec3::new(r, g, b) * d.intensity).extend(1.0);
            let black = Vec4::new(0.0, 0.0, 0.0, 1.0);
            let mut l = CoreLight {
                ambient: black,
                diffuse: color,
                specular: color,
                ..CoreLight::default()
            };
            match d.mode {
                Light::AMBIENT => {
                    l.ambient = color;
                    l.diffuse = black;
                    l.specular = black;
                }
                Light::DIRECTIONAL => l.position = mv * Vec4::Z,
                _ => {
                    l.position = mv * Vec4::W;
                    l.attenuation = d.attenuation;
                    if d.mode == Light::SPOT {
                        l.spot_direction = (mv * Vec4::NEG_Z).truncate();
                        l.spot_cutoff = d.spot_angle;
                        l.spot_exponent = d.spot_exponent;
                    }
                }
            }
            out.push(EyeLight {
                light: l,
                scope: nd.scope,
            });
        }
        out
    }

    fn base_state(&self, projection: Mat4) -> RenderState {
        let b = self.bound.as_ref().unwrap();
        let (tw, th) = (b.target.width() as i32, b.target.height() as i32);
        let [x, y, w, h] = self.viewport;
        let mut s = RenderState::new(tw, th);
        s.projection = projection;
        s.viewport = Viewport {
            x,
            y: th - y - h,
            width: w,
            height: h,
        };
        s.scissor = Some(self.clear_rect());
        s.depth_range = self.depth_range;
        s.dither = b.hints & Graphics3D::DITHER != 0;
        s
    }
}

fn argb_to_rgba(c: u32) -> [f32; 4] {
    let f = |s: u32| ((c >> s) & 0xFF) as f32 / 255.0;
    [f(16), f(8), f(0), f(24)]
}

/// The enabled lights under `world` in depth-first pre-order (the order the lights are
/// numbered in). A heap stack, not recursion: a loaded file can nest groups deeper than the
/// thread's stack allows.
fn collect_lights(world: &ObjRef, out: &mut Vec<(Light, Mat4)>) {
    let mut stack = vec![world.clone()];
    while let Some(r) = stack.pop() {
        let (enabled, children, is_light) = {
            let i = r.borrow();
            (
                i.node.as_ref().is_some_and(|n| n.rendering),
                i.group()
                    .map(|g| g.children.clone())
                    .unwrap_or_default()
                    .into_iter()
                    .chain(super::deform::skeleton_of(&r))
                    .collect::<Vec<_>>(),
                matches!(i.kind, Kind::Light(_)),
            )
        };
        if !enabled {
            continue;
        }
        if is_light {
            out.push((Light(r.clone()), to_ancestor(&r, world)));
        }
        stack.extend(children.into_iter().rev());
    }
}

fn is_blended(app: &Appearance) -> bool {
    app.compositing_mode()
        .is_some_and(|c| c.blending() != CompositingMode::REPLACE)
}

/// The deferred checks of a submesh: positions present, indices inside the buffer.
fn validate(vb: &VertexBuffer, ib: &IndexBuffer) -> Result<()> {
    let d = vb.d();
    if d.positions.is_none() {
        return ise("the vertex buffer has no positions");
    }
    let n = d.vertex_count();
    if ib.d().triangles.iter().any(|&i| i as i32 >= n) {
        return ise("an index is past the vertex count");
    }
    Ok(())
}

/// One step of the drawable-item traversal.
enum Step {
    /// Visit a node whose own node-to-world transform is the matrix.
    Node(ObjRef, Mat4, f32),
    /// Emit a mesh's or sprite's items (after its skeleton's, which are its children's).
    Emit(ObjRef, Mat4, f32, i32),
}

/// Collects the drawable items of `r` and its descendants, with `m` as `r`'s own
/// node-to-world transform, in depth-first pre-order (a SkinnedMesh after its skeleton),
/// stopping at the first invalid submesh. A heap stack, not recursion: a loaded file can
/// nest groups deeper than the thread's stack allows.
fn collect_at(r: &ObjRef, m: Mat4, alpha: f32, cam_scope: i32, out: &mut Vec<Item>) -> Result<()> {
    let mut stack = vec![Step::Node(r.clone(), m, alpha)];
    while let Some(step) = stack.pop() {
        match step {
            Step::Node(r, m, alpha) => {
                let (rendering, a, scope) = {
                    let n = node_data(&r);
                    (n.rendering, n.alpha, n.scope)
                };
                if !rendering {
                    continue;
                }
                let alpha = alpha * a;
                let kind_children = r.borrow().group().map(|g| g.children.clone());
                if let Some(children) = kind_children {
                    for c in children.iter().rev() {
                        let cm = tf(c).world(m);
                        stack.push(Step::Node(c.clone(), cm, alpha));
                    }
                    continue;
                }
                stack.push(Step::Emit(r.clone(), m, alpha, scope));
                // A SkinnedMesh's skeleton is its child branch.
                if let Some(skeleton) = super::deform::skeleton_of(&r) {
                    let sm = tf(&skeleton).world(m);
                    stack.push(Step::Node(skeleton, sm, alpha));
                }
            }
            Step::Emit(r, m, alpha, scope) => {
                if scope & cam_scope != 0 {
                    emit(&r, m, alpha, scope, out)?;
                }
            }
        }
    }
    Ok(())
}

/// The items of one Mesh or Sprite3D.
fn emit(r: &ObjRef, m: Mat4, alpha: f32, scope: i32, out: &mut Vec<Item>) -> Result<()> {
    // MorphingMesh / SkinnedMesh: the deformed copy (recomputed only when needed).
    let deformed = super::deform::deformed_vertex_buffer(r)?;
    if let Some(mesh) = Mesh::accepts(&r.borrow()).then(|| Mesh(r.clone())) {
        // Only a plain Mesh is culled against the bounds of its positions (a deformed
        // copy's arrays are rewritten in place).
        let cullable = deformed.is_none();
        let d = mesh.d();
        let vb = deformed.as_ref().unwrap_or(&d.vb);
        for (ib, app) in d.ibs.iter().zip(&d.apps) {
            let Some(app) = app else { continue };
            validate(vb, ib)?;
            out.push(Item {
                layer: app.layer(),
                blended: is_blended(app),
                what: What::Submesh(vb.clone(), ib.clone(), app.clone()),
                model: m,
                alpha,
                scope,
                cullable,
            });
        }
    } else if let Some(sprite) = Sprite3D::accepts(&r.borrow()).then(|| Sprite3D(r.clone())) {
        if let Some(app) = sprite.appearance() {
            out.push(Item {
                layer: app.layer(),
                blended: is_blended(&app),
                what: What::Sprite(sprite.clone(), app),
                model: m,
                alpha,
                scope,
                cullable: false,
            });
        }
    }
    Ok(())
}

/// Applies a CompositingMode (or its defaults) to `s`.
fn apply_compositing(s: &mut RenderState, cm: Option<&CompositingMode>, depth: bool) {
    let d = cm.map(|c| c.d().clone());
    let (blending, threshold, offset, test, write, color, alpha) = match &d {
        Some(d) => (
            d.blending,
            d.alpha_threshold,
            d.depth_offset,
            d.depth_test,
            d.depth_write,
            d.color_write,
            d.alpha_write,
        ),
        None => (
            CompositingMode::REPLACE,
            0.0,
            [0.0; 2],
            true,
            true,
            true,
            true,
        ),
    };
    use BlendFactor::*;
    s.blend = match blending {
        CompositingMode::ALPHA => Some(Blend::func(SrcAlpha, OneMinusSrcAlpha)),
        CompositingMode::ALPHA_ADD => Some(Blend::func(SrcAlpha, One)),
        CompositingMode::MODULATE => Some(Blend::func(DstColor, Zero)),
        CompositingMode::MODULATE_X2 => Some(Blend::func(DstColor, SrcColor)),
        _ => None,
    };
    if threshold > 0.0 {
        s.alpha_test = Some(AlphaTest {
            func: CompareFunc::GreaterEqual,
            reference: threshold,
        });
    }
    s.color_mask = [color, color, color, alpha];
    if depth {
        // M3G writes depth even with the test off: emulate with ALWAYS.
        s.depth_test = match (test, write) {
            (true, _) => Some(CompareFunc::LessEqual),
            (false, true) => Some(CompareFunc::Always),
            (false, false) => None,
        };
        s.depth_write = write;
        if offset != [0.0, 0.0] {
            s.polygon_offset = Some(crate::core::state::PolygonOffset {
                factor: offset[0],
                units: offset[1],
                clamp: 0.0,
            });
        }
    } else {
        s.depth_test = None;
        s.depth_write = false;
    }
}

fn apply_polygon_mode(s: &mut RenderState, pm: Option<&PolygonMode>) {
    let (culling, winding, shading) = match pm {
        Some(p) => {
            let d = p.d();
            (d.culling, d.winding, d.shading)
        }
        None => (
            PolygonMode::CULL_BACK,
            PolygonMode::WINDING_CCW,
            PolygonMode::SHADE_SMOOTH,
        ),
    };
    s.cull = match culling {
        PolygonMode::CULL_BACK => Some(CullFace::Back),
        PolygonMode::CULL_FRONT => Some(CullFace::Front),
        _ => None,
    };
    s.front_face = if winding == PolygonMode::WINDING_CW {
        Winding::Cw
    } else {
        Winding::Ccw
    };
    s.shade_model = if shading == PolygonMode::SHADE_FLAT {
        ShadeModel::Flat
    } else {
        ShadeModel::Smooth
    };
}

/// The one place a `core::DrawCall` is built (the core's DrawCall is growing fields).
fn draw_call<'a>(
    indices: Indices<'a>,
    position: AttribArray<'a>,
    color: AttribSource<'a>,
) -> DrawCall<'a> {
    let mut call = DrawCall::new(Primitive::Triangles, indices, position);
    call.color = color;
    call
}

fn f32_bytes(v: &[f32]) -> Vec<u8> {
    v.iter().flat_map(|x| x.to_ne_bytes()).collect()
}

fn rgba_of(c: u32) -> Vec4 {
    Vec4::from_array(argb_to_rgba(c))
}

/// The core's fog for an M3G Fog: LINEAR from `near` to `far`, or EXPONENTIAL with the
/// density; the distance is |z_eye| (M3G allows that approximation), per pixel.
fn core_fog(f: &FogData) -> texenv::Fog {
    let [r, g, b, _] = argb_to_rgba(f.color);
    texenv::Fog {
        mode: if f.mode == Fog::LINEAR {
            FogMode::Linear
        } else {
            FogMode::Exp
        },
        density: f.density,
        start: f.near,
        end: f.far,
        color: [r, g, b, 1.0],
        quality: core::state::Quality::Balanced,
    }
}

/// The core material for an M3G Material whose lit alpha is the diffuse alpha times
/// `alpha` (without vertex color tracking; with it the tracked vertex alpha carries the
/// factor instead).
fn core_material(m: &MaterialData, alpha: f32) -> CoreMaterial {
    let opaque = |c: u32| rgba_of(c).truncate().extend(1.0);
    let mut diffuse = rgba_of(m.diffuse);
    if !m.tracking {
        diffuse.w *= alpha;
    }
    CoreMaterial {
        ambient: opaque(m.ambient),
        diffuse,
        specular: opaque(m.specular),
        emission: opaque(m.emissive),
        shininess: m.shininess,
    }
}

/// M3G's level filter × image filter → the core's minification filter (checklist §2.1).
fn min_filter(level: i32, image: i32) -> MinFilter {
    let linear = image == Texture2D::FILTER_LINEAR;
    match (level, linear) {
        (Texture2D::FILTER_NEAREST, false) => MinFilter::NearestMipmapNearest,
        (Texture2D::FILTER_NEAREST, true) => MinFilter::LinearMipmapNearest,
        (Texture2D::FILTER_LINEAR, false) => MinFilter::NearestMipmapLinear,
        (Texture2D::FILTER_LINEAR, true) => MinFilter::LinearMipmapLinear,
        (_, false) => MinFilter::Nearest,
        (_, true) => MinFilter::Linear,
    }
}

/// An Image2D as a core texture: its format mapped to the core's base format (texels
/// expanded as `core::texture` stores them), row 0 (the top row) at t = 0, and the mipmap
/// chain (2 × 2 box filter) when `min` uses one.
fn build_sampler(d: &ImageData, min: MinFilter, mag: MagFilter, ws: Wrap, wt: Wrap) -> Sampler {
    let format = match d.format {
        Image2D::ALPHA => BaseFormat::Alpha,
        Image2D::LUMINANCE => BaseFormat::Luminance,
        Image2D::LUMINANCE_ALPHA => BaseFormat::LuminanceAlpha,
        Image2D::RGB => BaseFormat::Rgb,
        _ => BaseFormat::Rgba,
    };
    let bpp = format.components();
    let texels = d
        .pixels
        .chunks_exact(bpp)
        .map(|p| {
            u32::from_le_bytes(match format {
                BaseFormat::Alpha => [0, 0, 0, p[0]],
                BaseFormat::Luminance => [p[0], p[0], p[0], 255],
                BaseFormat::LuminanceAlpha => [p[0], p[0], p[0], p[1]],
                BaseFormat::Rgb => [p[0], p[1], p[2], 255],
                BaseFormat::Rgba => [p[0], p[1], p[2], p[3]],
            })
        })
        .collect();
    let mut levels = vec![Arc::new(TexImage {
        width: d.width as u32,
        height: d.height as u32,
        format,
        texels,
    })];
    if min.uses_mipmaps() {
        loop {
            let last = levels.last().unwrap();
            if last.width == 1 && last.height == 1 {
                break;
            }
            let next = last.half();
            levels.push(Arc::new(next));
        }
    }
    Sampler::new(levels, min, mag, ws, wt)
}

impl TexCache {
    /// The core texture of `t`, converted again only when needed.
    fn sampler(&mut self, t: &TextureData, stats: &mut RenderStats) -> Arc<Sampler> {
        let wrap = |w: i32| {
            if w == Texture2D::WRAP_CLAMP {
                Wrap::ClampToEdge
            } else {
                Wrap::Repeat
            }
        };
        let min = min_filter(t.level_filter, t.image_filter);
        let mag = if t.image_filter == Texture2D::FILTER_LINEAR {
            MagFilter::Linear
        } else {
            MagFilter::Nearest
        };
        let (ws, wt) = (wrap(t.wrap[0]), wrap(t.wrap[1]));
        let key = (Rc::as_ptr(&t.image.0) as usize, min, mag, ws, wt);
        let d = t.image.d();
        if let Some(e) = self.entries.get_mut(&key) {
            if e.pixels.as_ref().is_none_or(|p| *p == d.pixels) {
                e.used = self.calls;
                return e.sampler.clone();
            }
        }
        stats.texture_uploads += 1;
        let sampler = Arc::new(build_sampler(&d, min, mag, ws, wt));
        self.entries.insert(
            key,
            TexEntry {
                _image: t.image.clone(),
                pixels: d.mutable.then(|| d.pixels.clone()),
                sampler: sampler.clone(),
                used: self.calls,
            },
        );
        sampler
    }
}

/// The core's environment for a Texture2D blending function and blend color (the M3G
/// table of §2.8 is GL's REPLACE, MODULATE, DECAL, BLEND and ADD).
fn tex_env(t: &TextureData) -> TexEnv {
    let [r, g, b, _] = argb_to_rgba(t.blend_color);
    TexEnv {
        mode: match t.blending {
            Texture2D::FUNC_REPLACE => EnvMode::Replace,
            Texture2D::FUNC_DECAL => EnvMode::Decal,
            Texture2D::FUNC_BLEND => EnvMode::Blend,
            Texture2D::FUNC_ADD => EnvMode::Add,
            _ => EnvMode::Modulate,
        },
        color: [r, g, b, 1.0],
    }
}

/// Whether the bounding sphere of `vb`'s positions (from the cached bounding box of the
/// position array, after scale and bias) lies wholly outside one plane of the view
/// frustum. The planes come from the projection's rows, so any camera works; a modelview
/// that is not affine is never culled.
fn outside_frustum(vb: &VertexBufferData, modelview: Mat4, projection: Mat4) -> bool {
    let Some(pos) = &vb.positions else {
        return false;
    };
    if modelview.row(3) != Vec4::W {
        return false;
    }
    let [lo, hi] = pos.d().bounds();
    let (lo, hi) = (Vec3::from(lo), Vec3::from(hi));
    let s = vb.pos_scale;
    let center = (lo + hi) * 0.5 * s + Vec3::from(vb.pos_bias);
    let radius = (hi - lo).length() * 0.5 * s.abs();
    let eye = modelview * center.extend(1.0);
    let stretch = (0..3)
        .map(|c| modelview.col(c).truncate().length())
        .fold(0.0f32, f32::max);
    // A margin keeps rounding from culling what touches the frustum.
    let r = radius * stretch * 1.001 + 1e-6;
    if !eye.is_finite() || !r.is_finite() {
        return false;
    }
    let w = projection.row(3);
    (0..3).any(|i| {
        [1.0f32, -1.0].iter().any(|&sign| {
            let plane = w + projection.row(i) * sign;
            let n = plane.truncate().length();
            plane.dot(eye) < -r * n
        })
    })
}

/// The scene's lights in eye space and how their result is clamped.
#[derive(Clone, Copy)]
struct LitBy<'a> {
    lights: &'a [EyeLight],
    clamp_after_lighting: bool,
}

/// Draws one submesh: the Appearance becomes the state (compositing, polygon mode,
/// lighting, fog, texture units), the VertexBuffer the draw call (positions with scale and
/// bias in the modelview, normals, colors, texture coordinates with their scale and bias
/// in the texture matrices), and the core does the rest.
#[allow(clippy::too_many_arguments)]
fn draw_submesh(
    s: &mut RenderState,
    b: &mut Bound,
    textures: &mut TexCache,
    stats: &mut RenderStats,
    vb: &VertexBuffer,
    ib: &IndexBuffer,
    app: &Appearance,
    item: &Item,
    lit: LitBy,
) {
    let a = app.d().clone();
    apply_compositing(s, a.compositing_mode.as_ref(), b.depth);
    apply_polygon_mode(s, a.polygon_mode.as_ref());
    let vbd = vb.d();
    let pos = vbd.positions.clone().expect("validated");
    let pd = pos.d();
    let scale = vbd.pos_scale;
    // Scale and bias fold into the modelview.
    s.modelview = s.modelview
        * Mat4::from_translation(Vec3::from_array(vbd.pos_bias))
        * Mat4::from_scale(Vec3::splat(scale));
    // Lighting (only with a Material): no scene ambient, one material for both faces,
    // vertex color tracking as color material, normals always normalized.
    let material = a.material.as_ref().map(|m| m.d().clone());
    if let Some(m) = &material {
        let two_side = a.polygon_mode.as_ref().is_some_and(|p| p.d().two_sided);
        let mat = core_material(m, item.alpha);
        s.lighting = Some(Lighting {
            lights: lit
                .lights
                .iter()
                .filter(|l| l.scope & item.scope != 0)
                .take(MAX_LIGHTS)
                .map(|l| l.light)
                .collect(),
            model_ambient: Vec4::ZERO,
            two_side,
            front: mat,
            back: mat,
            color_material: m.tracking,
            clamp_after_lighting: lit.clamp_after_lighting,
        });
        s.normalize = true;
    }
    s.fog = a.fog.as_ref().map(|f| core_fog(&f.d()));
    // The alpha factor multiplies the post-lighting alpha: the material's diffuse alpha
    // (folded above), else the vertex color's.
    let alpha_on_vertex = material.as_ref().is_none_or(|m| m.tracking) && item.alpha != 1.0;
    let colors = vbd.colors.clone();
    let cd = colors.as_ref().map(|c| c.d());
    let float_colors: Vec<u8>;
    let color = match &cd {
        Some(cd) if alpha_on_vertex => {
            let comps = cd.comps as usize;
            float_colors = cd
                .data
                .chunks_exact(comps)
                .flat_map(|p| {
                    let a = if comps == 4 { p[3] as f32 / 255.0 } else { 1.0 };
                    [
                        p[0] as f32 / 255.0,
                        p[1] as f32 / 255.0,
                        p[2] as f32 / 255.0,
                        a * item.alpha,
                    ]
                })
                .flat_map(f32::to_ne_bytes)
                .collect();
            AttribSource::Array(AttribArray {
                data: &float_colors,
                ty: core::ComponentType::Float,
                size: 4,
                stride: 16,
                normalized: false,
            })
        }
        Some(cd) => AttribSource::Array(AttribArray {
            data: &cd.data,
            ty: core::ComponentType::UnsignedByte,
            size: cd.comps as usize,
            stride: cd.comps as usize,
            normalized: true,
        }),
        None => {
            let mut c = rgba_of(vbd.default_color);
            if alpha_on_vertex {
                c.w *= item.alpha;
            }
            AttribSource::Constant(c.to_array())
        }
    };
    // Normals carry no scale: a negative position scale (in the modelview) would turn them
    // around, so they are turned back.
    let normals = vbd.normals.clone().filter(|_| s.lighting.is_some());
    let nd = normals.as_ref().map(|n| n.d());
    let flipped: Vec<u8>;
    let normal = match &nd {
        Some(nd) => {
            let arr = AttribArray {
                data: &nd.data,
                ty: component_type(nd.size),
                size: 3,
                stride: 3 * nd.size as usize,
                normalized: true,
            };
            if scale < 0.0 {
                flipped = (0..nd.count as usize)
                    .flat_map(|v| {
                        let n = arr.fetch(v);
                        [-n[0], -n[1], -n[2]]
                    })
                    .flat_map(f32::to_ne_bytes)
                    .collect();
                AttribSource::Array(AttribArray {
                    data: &flipped,
                    ty: core::ComponentType::Float,
                    size: 3,
                    stride: 12,
                    normalized: false,
                })
            } else {
                AttribSource::Array(arr)
            }
        }
        None => AttribSource::Constant([0.0, 0.0, 1.0, 0.0]),
    };
    // Texture units: the Texture2D's image and parameters, its transform T·R·S·M after the
    // coordinates' scale and bias.
    let mut units = Vec::new();
    for (u, t) in a.textures.iter().enumerate() {
        let Some(t) = t else { continue };
        let td = t.d();
        s.textures[u] = Some(TextureUnit {
            sampler: textures.sampler(&td, stats),
            env: tex_env(&td),
            coord_replace: false,
        });
        let tex_m = tf(t.raw()).composite();
        s.texture_matrices[u] = match &vbd.texcoords[u] {
            Some((va, tscale, tbias)) => {
                units.push((u, va.clone()));
                tex_m
                    * Mat4::from_translation(Vec3::from_array(*tbias))
                    * Mat4::from_scale(Vec3::splat(*tscale))
            }
            None => tex_m,
        };
    }
    let tds: Vec<_> = units.iter().map(|(u, va)| (*u, va.d())).collect();
    let ibd = ib.d();
    let indices = Indices::U16(&ibd.triangles);
    let mut call = DrawCall::new(
        Primitive::Triangles,
        indices,
        AttribArray {
            data: &pd.data,
            ty: component_type(pd.size),
            size: 3,
            stride: 3 * pd.size as usize,
            normalized: false,
        },
    );
    call.color = color;
    call.normal = normal;
    for (u, td) in &tds {
        call.texcoord[*u] = AttribSource::Array(AttribArray {
            data: &td.data,
            ty: component_type(td.size),
            size: td.comps as usize,
            stride: (td.comps * td.size) as usize,
            normalized: false,
        });
    }
    stats.submeshes_drawn += 1;
    if let Some((lo, hi)) = indices.range() {
        stats.vertices_transformed += (hi - lo + 1) as u64;
    }
    // Out of memory drops the draw (M3G has no such exception).
    let _ = core::record_into(s, &call, &mut b.frame, &mut b.target);
}

fn component_type(size: i32) -> core::ComponentType {
    if size == 1 {
        core::ComponentType::Byte
    } else {
        core::ComponentType::Short
    }
}

/// A sprite's screen rectangle (M3G window coordinates: x right, y down), depth in NDC, and
/// eye distance; `None` when culled.
pub(crate) fn sprite_rect(
    sprite: &Sprite3D,
    modelview: Mat4,
    projection: Mat4,
    viewport: [i32; 4],
) -> Option<([f32; 4], f32, f32)> {
    let d = sprite.d();
    let [vx, vy, vw, vh] = viewport.map(|v| v as f32);
    let o = modelview * Vec4::new(0.0, 0.0, 0.0, 1.0);
    let oc = projection * o;
    if oc.w <= 0.0 {
        return None;
    }
    let on = oc.truncate() / oc.w;
    if !(-1.0..=1.0).contains(&on.z) {
        return None;
    }
    let (w, h) = if d.scaled {
        let x = modelview * Vec4::new(1.0, 0.0, 0.0, 1.0);
        let y = modelview * Vec4::new(0.0, 1.0, 0.0, 1.0);
        let o3 = o.truncate() / o.w;
        let dx = (x.truncate() / x.w - o3).length();
        let dy = (y.truncate() / y.w - o3).length();
        let xc = projection * (o + Vec4::new(dx, 0.0, 0.0, 0.0));
        let yc = projection * (o + Vec4::new(0.0, dy, 0.0, 0.0));
        let sx = (xc.truncate() / xc.w - on).truncate().length();
        let sy = (yc.truncate() / yc.w - on).truncate().length();
        (0.5 * sx * vw, 0.5 * sy * vh)
    } else {
        (d.crop[2].abs() as f32, d.crop[3].abs() as f32)
    };
    let cx = vx + (on.x + 1.0) * 0.5 * vw;
    let cy = vy + (1.0 - on.y) * 0.5 * vh;
    let (mut x0, mut y0) = (cx - w * 0.5, cy - h * 0.5);
    if !d.scaled {
        x0 = x0.round();
        y0 = y0.round();
    }
    Some(([x0, y0, w, h], on.z, -o.z / o.w))
}

/// Draws a sprite as one flat quad per crop pixel, in NDC, through the core (so blending,
/// alpha and depth tests are the core's).
fn draw_sprite(
    base: &RenderState,
    b: &mut Bound,
    sprite: &Sprite3D,
    app: &Appearance,
    mv: Mat4,
    alpha: f32,
) {
    let [crop_x, crop_y, cw, ch] = sprite.d().crop;
    if cw == 0 || ch == 0 {
        return;
    }
    let vp = base.viewport;
    let th = b.target.height() as i32;
    let viewport = [vp.x, th - vp.y - vp.height, vp.width, vp.height];
    let Some(([x0, y0, w, h], z, dist)) = sprite_rect(sprite, mv, base.projection, viewport) else {
        return;
    };
    let mut s = base.clone();
    s.modelview = Mat4::IDENTITY;
    s.projection = Mat4::IDENTITY;
    s.shade_model = ShadeModel::Flat;
    s.cull = None;
    let a = app.d().clone();
    apply_compositing(&mut s, a.compositing_mode.as_ref(), b.depth);
    // Fog at the sprite's depth, by the core's fog equation.
    let fog = a.fog.as_ref().map(|f| {
        let fog = core_fog(&f.d());
        (fog.factor(dist.abs()), fog)
    });
    let img = sprite.image();
    let id = img.d();
    let (ncols, nrows) = (cw.unsigned_abs() as usize, ch.unsigned_abs() as usize);
    let (vx, vy, vw, vh) = (
        viewport[0] as f32,
        viewport[1] as f32,
        viewport[2] as f32,
        viewport[3] as f32,
    );
    let ndc_x = |x: f32| (x - vx) / vw * 2.0 - 1.0;
    let ndc_y = |y: f32| 1.0 - (y - vy) / vh * 2.0;
    let mut pos = Vec::new();
    let mut col = Vec::new();
    for j in 0..nrows {
        let iy = crop_y
            + if ch > 0 {
                j as i32
            } else {
                (nrows - 1 - j) as i32
            };
        if !(0..id.height).contains(&iy) {
            continue;
        }
        for i in 0..ncols {
            let ix = crop_x
                + if cw > 0 {
                    i as i32
                } else {
                    (ncols - 1 - i) as i32
                };
            if !(0..id.width).contains(&ix) {
                continue;
            }
            let mut c = Vec4::from_array(id.rgba(ix, iy));
            c.w *= alpha;
            if let Some((f, fog)) = &fog {
                let mut rgba = c.to_array();
                fog.apply(*f, &mut rgba);
                c = Vec4::from_array(rgba);
            }
            let (xa, xb) = (
                x0 + w * i as f32 / ncols as f32,
                x0 + w * (i + 1) as f32 / ncols as f32,
            );
            let (ya, yb) = (
                y0 + h * j as f32 / nrows as f32,
                y0 + h * (j + 1) as f32 / nrows as f32,
            );
            let (l, r, t, bt) = (ndc_x(xa), ndc_x(xb), ndc_y(ya), ndc_y(yb));
            for (px, py) in [(l, bt), (r, bt), (r, t), (l, bt), (r, t), (l, t)] {
                pos.extend([px, py, z]);
                col.extend(c.to_array());
            }
        }
    }
    if pos.is_empty() {
        return;
    }
    let (pb, cb) = (f32_bytes(&pos), f32_bytes(&col));
    let call = draw_call(
        Indices::Range {
            first: 0,
            count: pos.len() / 3,
        },
        AttribArray {
            data: &pb,
            ty: core::ComponentType::Float,
            size: 3,
            stride: 12,
            normalized: false,
        },
        AttribSource::Array(AttribArray {
            data: &cb,
            ty: core::ComponentType::Float,
            size: 4,
            stride: 16,
            normalized: false,
        }),
    );
    let _ = core::record_into(&s, &call, &mut b.frame, &mut b.target);
}

/// The name of an `Image2D` format, for messages.
fn format_name(format: i32) -> &'static str {
    match format {
        Image2D::ALPHA => "ALPHA",
        Image2D::LUMINANCE => "LUMINANCE",
        Image2D::LUMINANCE_ALPHA => "LUMINANCE_ALPHA",
        Image2D::RGB => "RGB",
        Image2D::RGBA => "RGBA",
        _ => "unknown",
    }
}
