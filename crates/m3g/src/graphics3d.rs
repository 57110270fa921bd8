//! `Graphics3D`: binds a target and renders scene graphs and submeshes into it through the
//! core (ARCHITECTURE decision 7): each submesh becomes a `RenderState` plus a
//! `DrawCall`, recorded into a `Frame` and flushed into the [`Target`].
//!
//! This file holds binding and the API; [`collect`] finds what a scene graph draws and culls
//! it, [`draw`] turns a submesh into a state and a draw call, and [`sprite`] draws sprites.
//! The translation of an `Appearance`'s components into the core's state lives beside them
//! in `appearance.rs`.

mod collect;
mod draw;
mod sprite;

use std::cell::RefCell;
use std::collections::HashMap;
use std::rc::Rc;

use glam::Mat4;

use gles_cm_core::{ColorFormat, DepthFormat, Frame, Rect, Target, TargetFormat};

use super::appearance::{argb_to_rgba, Appearance, Background, MAX_TEXTURE_DIMENSION};
use super::camera::Camera;
use super::error::{iae, ioobe, ise, Result};
use super::image::Image2D;
use super::light::Light;
use super::mesh::MAX_SPRITE_CROP_DIMENSION;
use super::modes::{ImageFormat, ImageMode, RenderHints};
use super::node::{node_data, root_of, to_ancestor, NodeExt, World};
use super::object::{tf, Kind};
use super::transform::{invert, Transform};
use super::vertex::{IndexBuffer, VertexBuffer, NUM_TEXTURE_UNITS};

use collect::{collect_at, collect_lights, is_blended, validate, Item, What};
use draw::TexCache;

pub(crate) use sprite::sprite_rect;

/// The largest viewport and target width and height.
pub const MAX_VIEWPORT_DIMENSION: i32 = gles_cm_core::MAX_VIEWPORT_DIM as i32;

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
    format: ImageFormat,
    depth: bool,
    hints: RenderHints,
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

/// `Graphics3D`: the render context.
///
/// | Java | Rust |
/// |---|---|
/// | `getInstance()` | [`get_instance`](Self::get_instance) (one per thread) or [`new`](Self::new) |
/// | `bindTarget(Image2D[, depth, hints])` | [`bind_image`](Self::bind_image) |
/// | `bindTarget(Graphics …)` | [`bind_target`](Self::bind_target) with a [`Target`] |
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
    /// A new, unbound context: depth range [0, 1], no camera, no lights.
    ///
    /// ```
    /// use m3g::prelude::*;
    ///
    /// # fn main() -> m3g::Result<()> {
    /// // Clear a mutable RGB image to a background color.
    /// let image = Image2D::new(ImageFormat::Rgb, 4, 4)?;
    /// let background = Background::new();
    /// background.set_color(Color::BLUE);
    /// let mut g3d = Graphics3D::new();
    /// g3d.bind_image(&image, true, RenderHints::DITHER)?;
    /// g3d.clear(Some(&background))?;
    /// g3d.release_target(); // the frame is written into the image here
    /// assert_eq!(image.pixels()[..3], [0, 0, 255]);
    /// # Ok(())
    /// # }
    /// ```
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

    fn check_bind(&self, w: u32, h: u32) -> Result<()> {
        if self.bound.is_some() {
            return ise("a target is already bound");
        }
        if w as i64 > MAX_VIEWPORT_DIMENSION as i64 || h as i64 > MAX_VIEWPORT_DIMENSION as i64 {
            return iae("target larger than the maximum viewport");
        }
        Ok(())
    }

    fn bind(&mut self, target: Target, image: Option<Image2D>, depth: bool, hints: RenderHints) {
        let format = match (&image, target.format().color) {
            (Some(i), _) => i.format(),
            (None, ColorFormat::Rgba8888) => ImageFormat::Rgba,
            (None, _) => ImageFormat::Rgb,
        };
        self.bind_as(target, image, format, depth, hints);
    }

    fn bind_as(
        &mut self,
        target: Target,
        image: Option<Image2D>,
        format: ImageFormat,
        depth: bool,
        hints: RenderHints,
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

    /// `bindTarget(image, depthBuffer, hints)` (`bindTarget(image)` is
    /// `(image, true, RenderHints::empty())`). IllegalState if a target is bound (here or,
    /// for this image, anywhere); IllegalArgument for an immutable image, a format other than
    /// RGB and RGBA, or an image larger than the maximum viewport. The viewport becomes the
    /// whole image.
    pub fn bind_image(
        &mut self,
        image: &Image2D,
        depth_buffer: bool,
        hints: RenderHints,
    ) -> Result<()> {
        let d = image.d();
        if d.bound {
            return ise("the image is already bound to a Graphics3D");
        }
        if !d.mutable {
            return iae("the target image is immutable");
        }
        let color = match d.format {
            ImageFormat::Rgb => ColorFormat::Rgb888,
            ImageFormat::Rgba => ColorFormat::Rgba8888,
            _ => return iae("the target image must be RGB or RGBA"),
        };
        self.check_bind(d.width as u32, d.height as u32)?;
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

    /// `bindTarget` for a [`Target`] (what an EGL surface owns; its row 0 is the bottom
    /// row, so M3G's top-left origin is its top row). The target is moved in and given back
    /// by [`release_target`](Self::release_target). The depth buffer is used only if the
    /// target has one and `depth_buffer` is true.
    pub fn bind_target(
        &mut self,
        target: Target,
        depth_buffer: bool,
        hints: RenderHints,
    ) -> Result<()> {
        self.check_bind(target.width(), target.height())?;
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
        hints: RenderHints,
    ) -> Result<()> {
        self.check_bind(target.width(), target.height())?;
        self.bind_as(target, None, ImageFormat::Rgb, depth_buffer, hints);
        Ok(())
    }

    /// `releaseTarget()`: finishes rendering and unbinds. An Image2D target receives the
    /// pixels; a [`Target`] is returned. Nothing bound: nothing happens.
    pub fn release_target(&mut self) -> Option<Target> {
        let mut b = self.bound.take()?;
        b.frame.flush_into(&mut b.target);
        match b.image {
            Some(img) => {
                let mut d = img.dm();
                d.bound = false;
                let (w, h) = (d.width as usize, d.height as usize);
                let bpp = if d.format == ImageFormat::Rgb { 3 } else { 4 };
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

    /// The bound [`Target`] with every pending pixel written (for any kind of target).
    pub fn target(&mut self) -> Option<&Target> {
        let b = self.bound.as_mut()?;
        b.frame.flush_into(&mut b.target);
        Some(&b.target)
    }

    /// `getHints()`: as given to the bind call (empty when unbound).
    pub fn hints(&self) -> RenderHints {
        self.bound
            .as_ref()
            .map_or(RenderHints::empty(), |b| b.hints)
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
    pub fn add_light(&mut self, light: &Light, t: Option<&Transform>) -> usize {
        self.lights
            .push(Some((light.clone(), t.map_or(Mat4::IDENTITY, |t| t.m))));
        self.lights.len() - 1
    }

    /// `setLight(index, light, transform)`: `None` empties the slot. IndexOutOfBounds for a
    /// bad index.
    pub fn set_light(
        &mut self,
        index: usize,
        light: Option<&Light>,
        t: Option<&Transform>,
    ) -> Result<()> {
        if index >= self.lights.len() {
            return ioobe("light index");
        }
        self.lights[index] = light.map(|l| (l.clone(), t.map_or(Mat4::IDENTITY, |t| t.m)));
        Ok(())
    }

    /// `resetLights()`.
    pub fn reset_lights(&mut self) {
        self.lights.clear();
    }

    /// `getLightCount()`: including empty slots.
    pub fn light_count(&self) -> usize {
        self.lights.len()
    }

    /// `getLight(index, transform)`: the light and its transform, `None` for an empty slot.
    /// IndexOutOfBounds for a bad index.
    pub fn light(&self, index: usize) -> Result<Option<(Light, Transform)>> {
        if index >= self.lights.len() {
            return ioobe("light index");
        }
        Ok(self.lights[index]
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
            None => (true, true, 0, None, [ImageMode::Border; 2], [0; 4]),
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
                    let pick = |v: i32, n: i32, mode: ImageMode| -> Option<i32> {
                        if (0..n).contains(&v) {
                            Some(v)
                        } else if mode == ImageMode::Repeat {
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
}

/// The name of an `Image2D` format, for messages.
fn format_name(format: ImageFormat) -> &'static str {
    match format {
        ImageFormat::Alpha => "ALPHA",
        ImageFormat::Luminance => "LUMINANCE",
        ImageFormat::LuminanceAlpha => "LUMINANCE_ALPHA",
        ImageFormat::Rgb => "RGB",
        ImageFormat::Rgba => "RGBA",
    }
}
