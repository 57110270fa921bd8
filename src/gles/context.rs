//! A GL ES 1.1 context: the state machine behind the `gl*` entry points. State is kept in
//! the specification's float form; [`Context::with_render_state`] turns it into the core's
//! [`RenderState`] for each draw.
#![forbid(unsafe_code)]

use std::sync::{Arc, Mutex, MutexGuard};

use glam::Mat4;

use gles_cm_core::state::Quality;
use gles_cm_core::{
    CompareFunc, CullFace, Destination, Frame, Rect, RenderState, ShadeModel, SharedTarget, Target,
    TargetFormat, Viewport, Winding,
};

use super::arrays::ClientArrays;
use super::clip_planes::ClipPlanes;
use super::current_values::CurrentValues;
use super::fog::Fog;
use super::lighting::Lighting;
use super::per_fragment::FragmentState;
use super::raster_state::PointLineState;
use super::texenv::TexEnv;
use super::tokens::*;
use super::tokens_ext::*;
use super::types::*;

/// What a context draws into. EGL surfaces implement it; the context only needs the target
/// and a way to say "the rendering issued so far is complete" (pixmap surfaces copy their
/// pixels out to the caller's memory then).
pub trait Surface: Send + Sync {
    fn target(&self) -> &Mutex<Target>;
    /// Called after `glFinish` (and other points where the specification says rendering to
    /// the surface is complete) with the target unlocked.
    fn rendering_complete(&self) {}
}

/// A surface as the core's workers see it: a target they lock while the context records on
/// ([`Frame::flush_behind`]).
pub(super) struct SurfaceTarget(Arc<dyn Surface>);

impl SharedTarget for SurfaceTarget {
    fn target(&self) -> &Mutex<Target> {
        self.0.target()
    }
}

/// The frame that records work for one surface, and that surface.
pub(super) struct Recording {
    frame: Frame,
    surface: Arc<SurfaceTarget>,
}

impl Recording {
    /// True when the frame records for `surface` (the same object; a surface's target
    /// never changes size or format).
    fn is_for(&self, surface: &Arc<dyn Surface>) -> bool {
        std::ptr::addr_eq(Arc::as_ptr(&self.surface.0), Arc::as_ptr(surface))
    }

    /// The surface's format, when the frame records for `surface`.
    pub(super) fn format_for(&self, surface: &Arc<dyn Surface>) -> Option<TargetFormat> {
        self.is_for(surface).then(|| self.frame.format())
    }

    /// Rasterizes everything recorded and waits for what the workers have.
    fn flush(&mut self) {
        self.frame.wait();
        if !self.frame.is_empty() {
            self.frame
                .flush_into(&mut lock_target(self.surface.0.as_ref()));
        }
    }
}

/// Objects shared between the contexts of one share group: texture and buffer objects.
#[derive(Default)]
pub struct SharedObjects {
    pub textures: super::texture::TextureNames,
    pub buffers: super::buffer::BufferNames,
    /// `OES_framebuffer_object` renderbuffers (framebuffer objects are per context).
    pub renderbuffers: super::fbo::RenderbufferNames,
    /// `KHR_debug` labels of buffers, textures and renderbuffers, by namespace and name.
    pub labels: std::collections::HashMap<(GLenum, GLuint), String>,
}

pub const MAX_TEXTURE_UNITS: usize = gles_cm_core::TEXTURE_UNITS;
pub const MAX_LIGHTS: usize = 8;
pub const MAX_CLIP_PLANES: usize = 6;
pub const MAX_MODELVIEW_STACK_DEPTH: usize = 32;
pub const MAX_PROJECTION_STACK_DEPTH: usize = 2;
pub const MAX_TEXTURE_STACK_DEPTH: usize = 2;
/// `OES_matrix_palette`: palette matrices and matrices per vertex.
pub const MAX_PALETTE_MATRICES: usize = 32;
pub const MAX_VERTEX_UNITS: usize = 4;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MatrixMode {
    Modelview,
    Projection,
    Texture,
    /// `GL_MATRIX_PALETTE_OES`: the current palette matrix.
    Palette,
}

/// The `glHint` targets, each FASTEST, NICEST or DONT_CARE.
#[derive(Clone, Copy, Debug)]
pub struct Hints {
    pub perspective_correction: GLenum,
    pub point_smooth: GLenum,
    pub line_smooth: GLenum,
    pub fog: GLenum,
    pub generate_mipmap: GLenum,
}

/// The server-side capabilities of `glEnable`, one flag each.
#[derive(Clone, Copy, Debug, Default)]
pub struct Enables {
    pub alpha_test: bool,
    pub blend: bool,
    pub color_logic_op: bool,
    pub clip_plane: [bool; MAX_CLIP_PLANES],
    pub color_material: bool,
    pub cull_face: bool,
    pub depth_test: bool,
    pub dither: bool,
    pub fog: bool,
    pub light: [bool; MAX_LIGHTS],
    pub lighting: bool,
    pub line_smooth: bool,
    pub matrix_palette: bool,
    pub multisample: bool,
    pub normalize: bool,
    pub point_smooth: bool,
    pub point_sprite: bool,
    pub polygon_offset_fill: bool,
    pub rescale_normal: bool,
    pub sample_alpha_to_coverage: bool,
    pub sample_alpha_to_one: bool,
    pub sample_coverage: bool,
    pub scissor_test: bool,
    pub stencil_test: bool,
    pub texture_2d: [bool; MAX_TEXTURE_UNITS],
    /// `OES_texture_cube_map`: `GL_TEXTURE_CUBE_MAP_OES` (takes precedence over
    /// `GL_TEXTURE_2D`) and `GL_TEXTURE_GEN_STR_OES`, per unit.
    pub texture_cube_map: [bool; MAX_TEXTURE_UNITS],
    pub texture_gen_str: [bool; MAX_TEXTURE_UNITS],
}

impl Enables {
    /// The flag for `cap`, or `None` when `cap` is not a capability (`GL_INVALID_ENUM`).
    /// `GL_TEXTURE_2D` is per texture unit: `unit` picks the active one.
    pub fn flag(&mut self, cap: GLenum, unit: usize) -> Option<&mut bool> {
        Some(match cap {
            GL_ALPHA_TEST => &mut self.alpha_test,
            GL_BLEND => &mut self.blend,
            GL_COLOR_LOGIC_OP => &mut self.color_logic_op,
            GL_COLOR_MATERIAL => &mut self.color_material,
            GL_CULL_FACE => &mut self.cull_face,
            GL_DEPTH_TEST => &mut self.depth_test,
            GL_DITHER => &mut self.dither,
            GL_FOG => &mut self.fog,
            GL_LIGHTING => &mut self.lighting,
            GL_LINE_SMOOTH => &mut self.line_smooth,
            GL_MATRIX_PALETTE_OES => &mut self.matrix_palette,
            GL_MULTISAMPLE => &mut self.multisample,
            GL_NORMALIZE => &mut self.normalize,
            GL_POINT_SMOOTH => &mut self.point_smooth,
            GL_POINT_SPRITE_OES => &mut self.point_sprite,
            GL_POLYGON_OFFSET_FILL => &mut self.polygon_offset_fill,
            GL_RESCALE_NORMAL => &mut self.rescale_normal,
            GL_SAMPLE_ALPHA_TO_COVERAGE => &mut self.sample_alpha_to_coverage,
            GL_SAMPLE_ALPHA_TO_ONE => &mut self.sample_alpha_to_one,
            GL_SAMPLE_COVERAGE => &mut self.sample_coverage,
            GL_SCISSOR_TEST => &mut self.scissor_test,
            GL_STENCIL_TEST => &mut self.stencil_test,
            GL_TEXTURE_2D => &mut self.texture_2d[unit],
            GL_TEXTURE_CUBE_MAP_OES => &mut self.texture_cube_map[unit],
            GL_TEXTURE_GEN_STR_OES => &mut self.texture_gen_str[unit],
            c if (GL_CLIP_PLANE0..GL_CLIP_PLANE0 + MAX_CLIP_PLANES as GLenum).contains(&c) => {
                &mut self.clip_plane[(c - GL_CLIP_PLANE0) as usize]
            }
            c if (GL_LIGHT0..GL_LIGHT0 + MAX_LIGHTS as GLenum).contains(&c) => {
                &mut self.light[(c - GL_LIGHT0) as usize]
            }
            _ => return None,
        })
    }
}

pub struct Context {
    pub(super) shared: Arc<Mutex<SharedObjects>>,
    pub(super) draw: Option<Arc<dyn Surface>>,
    pub(super) read: Option<Arc<dyn Surface>>,
    /// Set on the first `make_current`: the viewport and scissor start at the surface size.
    pub(super) initialized: bool,
    pub(super) error: GLenum,
    /// The entry point running now (set at the C boundary), for debug messages.
    pub(crate) call: &'static str,
    /// `KHR_debug` state.
    pub(crate) debug: super::debug::Debug,

    pub(super) enables: Enables,
    pub(super) matrix_mode: MatrixMode,
    /// Each stack's last element is its current matrix; stacks are never empty.
    pub(super) modelview: Vec<Mat4>,
    pub(super) projection: Vec<Mat4>,
    pub(super) texture: [Vec<Mat4>; MAX_TEXTURE_UNITS],
    pub(super) active_texture: usize,
    /// `OES_matrix_palette`: the palette and `glCurrentPaletteMatrixOES`'s index.
    pub(super) palette: [Mat4; MAX_PALETTE_MATRICES],
    pub(super) current_palette: usize,
    pub(super) viewport: Viewport,
    pub(super) depth_range: [f32; 2],
    pub(super) scissor_box: Rect,
    pub(super) depth_func: CompareFunc,
    pub(super) cull_face: CullFace,
    pub(super) front_face: Winding,
    pub(super) shade_model: ShadeModel,
    pub(super) color_mask: [bool; 4],
    pub(super) depth_mask: bool,
    pub(super) stencil_writemask: u32,
    pub(super) clear_color: [f32; 4],
    pub(super) clear_depth: f32,
    pub(super) clear_stencil: i32,
    pub(super) pack_alignment: usize,
    pub(super) unpack_alignment: usize,
    pub(super) hints: Hints,
    pub(super) arrays: ClientArrays,
    /// `OES_vertex_array_object`: the objects not bound now, and which one is.
    pub(super) vertex_arrays: super::vertex_array::VertexArrays,
    /// Current normal and texture coordinates.
    pub(super) current: CurrentValues,
    /// Alpha, stencil, blend, logic op, sample coverage and polygon offset state.
    pub(super) fragment: FragmentState,
    pub(super) points_lines: PointLineState,
    pub(super) clip_planes: ClipPlanes,
    pub(super) lighting: Lighting,
    pub(super) fog: Fog,
    pub(super) texenv: TexEnv,
    pub(super) textures: super::texture::TextureUnits,
    pub(super) buffers: super::buffer::BufferBindings,
    /// Work recorded for the draw surface and not yet rasterized.
    pub(super) frame: Option<Recording>,
    /// Framebuffer objects, bindings and the bound one's assembled target.
    pub(super) fbo: super::fbo::FramebufferState,
    /// The core's state of the last draw, kept to be filled in place by the next one (see
    /// [`Context::with_render_state`]); `None` while a draw holds it.
    render_state: Option<Box<RenderState>>,
}

impl Context {
    /// A new context, sharing objects with `share` when given.
    pub fn new(share: Option<&Context>) -> Context {
        Context {
            shared: share.map_or_else(Default::default, |s| s.shared.clone()),
            draw: None,
            read: None,
            initialized: false,
            error: GL_NO_ERROR,
            call: "gl",
            debug: Default::default(),
            enables: Enables {
                dither: true,
                multisample: true,
                ..Enables::default()
            },
            matrix_mode: MatrixMode::Modelview,
            modelview: vec![Mat4::IDENTITY],
            projection: vec![Mat4::IDENTITY],
            texture: std::array::from_fn(|_| vec![Mat4::IDENTITY]),
            active_texture: 0,
            palette: [Mat4::IDENTITY; MAX_PALETTE_MATRICES],
            current_palette: 0,
            viewport: Viewport {
                x: 0,
                y: 0,
                width: 0,
                height: 0,
            },
            depth_range: [0.0, 1.0],
            scissor_box: Rect::default(),
            depth_func: CompareFunc::Less,
            cull_face: CullFace::Back,
            front_face: Winding::Ccw,
            shade_model: ShadeModel::Smooth,
            color_mask: [true; 4],
            depth_mask: true,
            stencil_writemask: u32::MAX,
            clear_color: [0.0; 4],
            clear_depth: 1.0,
            clear_stencil: 0,
            pack_alignment: 4,
            unpack_alignment: 4,
            hints: Hints {
                perspective_correction: GL_DONT_CARE,
                point_smooth: GL_DONT_CARE,
                line_smooth: GL_DONT_CARE,
                fog: GL_DONT_CARE,
                generate_mipmap: GL_DONT_CARE,
            },
            arrays: ClientArrays::default(),
            vertex_arrays: Default::default(),
            current: CurrentValues::default(),
            fragment: FragmentState::default(),
            points_lines: PointLineState::default(),
            clip_planes: ClipPlanes::default(),
            lighting: Lighting::default(),
            fog: Fog::default(),
            texenv: TexEnv::default(),
            textures: Default::default(),
            buffers: Default::default(),
            frame: None,
            fbo: Default::default(),
            render_state: None,
        }
    }

    /// True when `self` and `other` share texture and buffer objects.
    pub fn shares_with(&self, other: &Context) -> bool {
        Arc::ptr_eq(&self.shared, &other.shared)
    }

    /// Binds the draw and read surfaces (on `eglMakeCurrent`). The first time a context is
    /// bound, the viewport and scissor box are set to the draw surface's size.
    pub fn make_current(&mut self, draw: Option<Arc<dyn Surface>>, read: Option<Arc<dyn Surface>>) {
        self.flush();
        self.frame = None;
        if !self.initialized {
            if let Some(d) = &draw {
                let t = lock_target(d.as_ref());
                let (w, h) = (t.width() as i32, t.height() as i32);
                self.viewport = Viewport {
                    x: 0,
                    y: 0,
                    width: w,
                    height: h,
                };
                self.scissor_box = Rect::new(0, 0, w, h);
                self.initialized = true;
            }
        }
        self.draw = draw;
        self.read = read;
    }

    /// Completes all rendering issued so far (the `glFinish` semantics), then tells the draw
    /// surface. EGL calls this before a context stops being current and on `eglWaitClient`.
    pub fn finish(&mut self) {
        self.flush();
        if let Some(d) = &self.draw {
            d.rendering_complete();
        }
    }

    /// Rasterizes all recorded work into the draw surface (or the bound framebuffer
    /// object, whose attachments then receive it). The share group must not be locked.
    pub fn flush(&mut self) {
        self.flush_frame();
        self.fbo_write_back();
    }

    /// Rasterizes all recorded work into the surface it was recorded for.
    fn flush_frame(&mut self) {
        if let Some(r) = &mut self.frame {
            r.flush();
        }
    }

    /// Runs `f` with the frame that records work for the draw surface (created for it) and
    /// where the frame goes when it fills during a draw ([`gles_cm_core::record_into`]). A
    /// full frame is first handed to the workers, which rasterize it while this thread
    /// records more; the target is not locked here, so that they can. `None` without a
    /// draw surface.
    pub(super) fn with_frame<R>(
        &mut self,
        f: impl FnOnce(&mut Frame, Destination<'_>) -> R,
    ) -> Option<R> {
        let surface = self.draw_surface()?;
        self.fbo.dirty |= self.fbo.bound != 0;
        if !self.frame.as_ref().is_some_and(|r| r.is_for(&surface)) {
            // Work recorded for another surface lands there first.
            self.flush_frame();
            let frame = Frame::for_target(&lock_target(surface.as_ref()));
            self.frame = Some(Recording {
                frame,
                surface: Arc::new(SurfaceTarget(surface)),
            });
        }
        let r = self.frame.as_mut()?;
        let shared: Arc<dyn SharedTarget> = r.surface.clone();
        if r.frame.is_full() {
            r.frame.flush_behind(shared.clone());
        }
        Some(f(&mut r.frame, Destination::Behind(shared)))
    }

    /// The format of what draws go to (the bound framebuffer object or the draw surface).
    pub fn draw_format(&self) -> Option<TargetFormat> {
        self.current_draw_format()
    }

    /// Records `e` unless an earlier error is still unread (the first error sticks).
    /// A debug context (EGL's request): `GL_DEBUG_OUTPUT_KHR` starts enabled.
    pub fn set_debug_context(&mut self, debug: bool) {
        self.debug.output = debug;
    }

    /// Records error `e` (a debug message names the call and the error; [`Context::fail`]
    /// says more).
    pub fn set_error(&mut self, e: GLenum) {
        self.raise(e, None);
    }

    /// Returns and clears the recorded error.
    pub fn take_error(&mut self) -> GLenum {
        std::mem::replace(&mut self.error, GL_NO_ERROR)
    }

    /// Runs `f` with the core's view of the current state ([`Context::take_render_state`]).
    pub fn with_render_state<R>(&mut self, f: impl FnOnce(&mut Self, &RenderState) -> R) -> R {
        let rs = self.take_render_state();
        let result = f(self, &rs);
        self.put_back_render_state(rs);
        result
    }

    /// The core's view of the current state, to be handed back with
    /// [`Context::put_back_render_state`]. It is filled in place of the last draw's, so a
    /// draw neither builds a default state nor copies one out, and the lists (lights, clip
    /// planes, palette) keep their allocations.
    pub fn take_render_state(&mut self) -> Box<RenderState> {
        let mut rs = self
            .render_state
            .take()
            .unwrap_or_else(|| Box::new(RenderState::new(0, 0)));
        self.fill_render_state(&mut rs);
        rs
    }

    /// Keeps `rs` for the next draw (whatever a caller changed in it is written over then).
    /// Its texture snapshots are let go now: a kept snapshot shares the texture's images,
    /// so a later `glTexSubImage2D` would copy a level instead of writing it in place, and
    /// a deleted texture's images would live on (see `forget_snapshots`).
    pub fn put_back_render_state(&mut self, mut rs: Box<RenderState>) {
        rs.textures = Default::default();
        self.render_state = Some(rs);
    }

    /// Writes every field of `rs` from the current state.
    fn fill_render_state(&self, rs: &mut RenderState) {
        // Every field is written below or by the three parts: a field added to RenderState
        // must be named here, so none keeps a value from the last draw.
        let RenderState {
            modelview: _,
            projection: _,
            viewport: _,
            depth_range: _,
            scissor: _,
            cull: _,
            front_face: _,
            shade_model: _,
            depth_test: _,
            depth_write: _,
            color_mask: _,
            polygon_offset: _,
            alpha_test: _,
            stencil_test: _,
            stencil_writemask: _,
            blend: _,
            logic_op: _,
            dither: _,
            line_width: _,
            line_smooth: _,
            point_size: _,
            point_smooth: _,
            perspective: _,
            line_quality: _,
            point_quality: _,
            lighting: _,
            normalize: _,
            rescale_normal: _,
            clip_planes: _,
            texture_matrices: _,
            texgen: _,
            point_params: _,
            matrix_palette: _,
            textures: _,
            fog: _,
            point_sprite: _,
            multisample: _,
            sample: _,
        } = rs;
        let e = &self.enables;
        let pl = &self.points_lines;
        rs.modelview = *self.modelview.last().expect("stack never empty");
        rs.projection = *self.projection.last().expect("stack never empty");
        rs.viewport = self.viewport;
        rs.depth_range = self.depth_range;
        rs.scissor = e.scissor_test.then_some(self.scissor_box);
        rs.cull = e.cull_face.then_some(self.cull_face);
        rs.front_face = self.front_face;
        rs.shade_model = self.shade_model;
        rs.depth_test = e.depth_test.then_some(self.depth_func);
        rs.depth_write = self.depth_mask;
        rs.color_mask = self.color_mask;
        rs.stencil_writemask = self.stencil_writemask;
        rs.dither = e.dither;
        rs.line_width = pl.line_width;
        rs.line_smooth = e.line_smooth;
        rs.point_size = pl.point_size;
        rs.point_smooth = e.point_smooth;
        rs.perspective = quality(self.hints.perspective_correction);
        rs.line_quality = quality(self.hints.line_smooth);
        rs.point_quality = quality(self.hints.point_smooth);
        // Set per sample plane by the core when it draws into a multisampled target.
        rs.sample = None;
        self.fragment_render_state(rs);
        self.texture_render_state(rs);
        self.geometry_render_state(rs);
    }

    /// The vertex-stage part of the core's state: lighting, normal processing, user clip
    /// planes, texture matrices, point parameters and the matrix palette.
    fn geometry_render_state(&self, rs: &mut RenderState) {
        use glam::{Vec3, Vec4};
        use gles_cm_core::state;
        let e = &self.enables;
        let l = &self.lighting;
        if e.lighting {
            let v4 = Vec4::from_array;
            let material = state::Material {
                ambient: v4(l.material.ambient),
                diffuse: v4(l.material.diffuse),
                specular: v4(l.material.specular),
                emission: v4(l.material.emission),
                shininess: l.material.shininess,
            };
            let mut lights = rs.lighting.take().map(|l| l.lights).unwrap_or_default();
            lights.clear();
            lights.extend(
                l.lights
                    .iter()
                    .zip(e.light)
                    .filter(|(_, on)| *on)
                    .map(|(g, _)| state::Light {
                        ambient: v4(g.ambient),
                        diffuse: v4(g.diffuse),
                        specular: v4(g.specular),
                        position: v4(g.position),
                        spot_direction: Vec3::from_array(g.spot_direction),
                        spot_exponent: g.spot_exponent,
                        spot_cutoff: g.spot_cutoff,
                        attenuation: [
                            g.constant_attenuation,
                            g.linear_attenuation,
                            g.quadratic_attenuation,
                        ],
                    }),
            );
            rs.lighting = Some(state::Lighting {
                lights,
                model_ambient: v4(l.model_ambient),
                two_side: l.two_side,
                front: material,
                back: material,
                color_material: e.color_material,
                clamp_after_lighting: true,
            });
        } else {
            rs.lighting = None;
        }
        rs.normalize = e.normalize;
        rs.rescale_normal = e.rescale_normal;
        rs.clip_planes.clear();
        rs.clip_planes.extend(
            self.clip_planes
                .planes
                .iter()
                .zip(e.clip_plane)
                .filter(|(_, on)| *on)
                .map(|(p, _)| Vec4::from_array(*p)),
        );
        rs.texture_matrices =
            std::array::from_fn(|u| *self.texture[u].last().expect("stack never empty"));
        let pl = &self.points_lines;
        rs.point_params = state::PointParams {
            size_min: pl.point_size_min,
            size_max: pl.point_size_max,
            attenuation: pl.point_distance_attenuation,
            fade_threshold: pl.point_fade_threshold_size,
        };
        if e.matrix_palette {
            let palette = rs.matrix_palette.get_or_insert_with(Vec::new);
            palette.clear();
            palette.extend_from_slice(&self.palette);
        } else {
            rs.matrix_palette = None;
        }
    }
}

/// What a hint's mode asks of the core; `GL_DONT_CARE` is the balanced default (see the
/// README's figures).
fn quality(mode: GLenum) -> Quality {
    match mode {
        GL_FASTEST => Quality::Fastest,
        GL_NICEST => Quality::Nicest,
        _ => Quality::Balanced,
    }
}

/// Locks a surface's target, recovering from a lock poisoned by a caught panic.
pub fn lock_target(s: &dyn Surface) -> MutexGuard<'_, Target> {
    s.target().lock().unwrap_or_else(|e| e.into_inner())
}

/// Parses a comparison function enum.
pub(super) fn compare_func(func: GLenum) -> Option<CompareFunc> {
    Some(match func {
        GL_NEVER => CompareFunc::Never,
        GL_LESS => CompareFunc::Less,
        GL_EQUAL => CompareFunc::Equal,
        GL_LEQUAL => CompareFunc::LessEqual,
        GL_GREATER => CompareFunc::Greater,
        GL_NOTEQUAL => CompareFunc::NotEqual,
        GL_GEQUAL => CompareFunc::GreaterEqual,
        GL_ALWAYS => CompareFunc::Always,
        _ => return None,
    })
}

pub(super) fn compare_func_enum(f: CompareFunc) -> GLenum {
    match f {
        CompareFunc::Never => GL_NEVER,
        CompareFunc::Less => GL_LESS,
        CompareFunc::Equal => GL_EQUAL,
        CompareFunc::LessEqual => GL_LEQUAL,
        CompareFunc::Greater => GL_GREATER,
        CompareFunc::NotEqual => GL_NOTEQUAL,
        CompareFunc::GreaterEqual => GL_GEQUAL,
        CompareFunc::Always => GL_ALWAYS,
    }
}
