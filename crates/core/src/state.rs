//! `RenderState`: everything the pipeline needs to know about how to draw, in the
//! specification's float form (ARCHITECTURE decision 1). The GL context and the M3G renderer
//! both fill one in; the pipeline never sees where it came from.

use glam::{Mat4, Vec3, Vec4};

pub use super::quality::Quality;
use super::target::{ColorMask, Rect};

/// The largest aliased and antialiased line width and point size.
pub const MAX_LINE_WIDTH: f32 = 64.0;
pub const MAX_POINT_SIZE: f32 = 64.0;

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CompareFunc {
    Never,
    Less,
    Equal,
    LessEqual,
    Greater,
    NotEqual,
    GreaterEqual,
    Always,
}

impl CompareFunc {
    #[inline]
    pub fn test<T: PartialOrd>(self, incoming: T, stored: T) -> bool {
        match self {
            CompareFunc::Never => false,
            CompareFunc::Less => incoming < stored,
            CompareFunc::Equal => incoming == stored,
            CompareFunc::LessEqual => incoming <= stored,
            CompareFunc::Greater => incoming > stored,
            CompareFunc::NotEqual => incoming != stored,
            CompareFunc::GreaterEqual => incoming >= stored,
            CompareFunc::Always => true,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CullFace {
    Front,
    Back,
    FrontAndBack,
}

/// Which window-space orientation counts as front-facing.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Winding {
    Ccw,
    Cw,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ShadeModel {
    Flat,
    Smooth,
}

/// `glAlphaFunc`: fragments pass when `func(alpha, reference)` holds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AlphaTest {
    pub func: CompareFunc,
    /// Clamped to [0, 1].
    pub reference: f32,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum StencilOp {
    Keep,
    Zero,
    Replace,
    /// Saturates at the largest stencil value.
    Incr,
    /// Saturates at 0.
    Decr,
    Invert,
    /// `OES_stencil_wrap`: wraps around.
    IncrWrap,
    DecrWrap,
}

/// `glStencilFunc` and `glStencilOp`: the test compares `reference & mask` with
/// `stored & mask`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StencilTest {
    pub func: CompareFunc,
    pub reference: i32,
    pub mask: u32,
    pub fail: StencilOp,
    pub depth_fail: StencilOp,
    pub depth_pass: StencilOp,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BlendFactor {
    Zero,
    One,
    SrcColor,
    OneMinusSrcColor,
    DstColor,
    OneMinusDstColor,
    SrcAlpha,
    OneMinusSrcAlpha,
    DstAlpha,
    OneMinusDstAlpha,
    SrcAlphaSaturate,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BlendEquation {
    Add,
    Subtract,
    ReverseSubtract,
    /// `EXT_blend_minmax`: the smaller or larger of source and destination, factors unused.
    Min,
    Max,
}

/// Blending, with separate color and alpha factors and equations
/// (`OES_blend_func_separate`, `OES_blend_equation_separate`, `OES_blend_subtract`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Blend {
    pub src_rgb: BlendFactor,
    pub dst_rgb: BlendFactor,
    pub src_alpha: BlendFactor,
    pub dst_alpha: BlendFactor,
    pub eq_rgb: BlendEquation,
    pub eq_alpha: BlendEquation,
}

impl Blend {
    /// `glBlendFunc(src, dst)` with the ADD equation.
    pub fn func(src: BlendFactor, dst: BlendFactor) -> Blend {
        Blend {
            src_rgb: src,
            dst_rgb: dst,
            src_alpha: src,
            dst_alpha: dst,
            eq_rgb: BlendEquation::Add,
            eq_alpha: BlendEquation::Add,
        }
    }
}

/// The 16 logic operations of `glLogicOp`, applied to the stored bits of each channel.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LogicOp {
    Clear,
    And,
    AndReverse,
    Copy,
    AndInverted,
    Noop,
    Xor,
    Or,
    Nor,
    Equiv,
    Invert,
    OrReverse,
    CopyInverted,
    OrInverted,
    Nand,
    Set,
}

impl LogicOp {
    /// `s op d` on bit patterns.
    #[inline]
    pub fn apply(self, s: u32, d: u32) -> u32 {
        match self {
            LogicOp::Clear => 0,
            LogicOp::And => s & d,
            LogicOp::AndReverse => s & !d,
            LogicOp::Copy => s,
            LogicOp::AndInverted => !s & d,
            LogicOp::Noop => d,
            LogicOp::Xor => s ^ d,
            LogicOp::Or => s | d,
            LogicOp::Nor => !(s | d),
            LogicOp::Equiv => !(s ^ d),
            LogicOp::Invert => !d,
            LogicOp::OrReverse => s | !d,
            LogicOp::CopyInverted => !s,
            LogicOp::OrInverted => !s | d,
            LogicOp::Nand => !(s & d),
            LogicOp::Set => u32::MAX,
        }
    }
}

/// `glPolygonOffset`, applied to filled triangles when `GL_POLYGON_OFFSET_FILL` is enabled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PolygonOffset {
    pub factor: f32,
    pub units: f32,
    /// `EXT_polygon_offset_clamp`: the offset's bound in its own sign (a positive clamp
    /// bounds it from above, a negative one from below); 0 or NaN bounds nothing.
    pub clamp: f32,
}

impl PolygonOffset {
    /// The depth offset of a triangle whose larger window-space depth slope is `slope`, in
    /// a depth buffer of `depth_max` steps (ES 1.1 §3.5.5: factor × slope + units × one
    /// step), clamped.
    pub fn offset(&self, slope: f64, depth_max: f64) -> f64 {
        let o = self.factor as f64 * slope + self.units as f64 / depth_max;
        let c = self.clamp as f64;
        if c > 0.0 {
            o.min(c)
        } else if c < 0.0 {
            o.max(c)
        } else {
            o
        }
    }
}

/// The viewport rectangle in window pixels (width and height already clamped to the maximum).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Viewport {
    pub x: i32,
    pub y: i32,
    pub width: i32,
    pub height: i32,
}

/// One enabled light (ES 1.1 §2.12.1), positions and directions in eye coordinates (the GL
/// transforms them by the modelview current when they are set).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    pub ambient: Vec4,
    pub diffuse: Vec4,
    pub specular: Vec4,
    /// w = 0: a directional light shining from direction (x, y, z).
    pub position: Vec4,
    pub spot_direction: Vec3,
    /// [0, 128].
    pub spot_exponent: f32,
    /// Degrees: [0, 90], or 180 for no cone.
    pub spot_cutoff: f32,
    /// Constant, linear and quadratic attenuation (each ≥ 0).
    pub attenuation: [f32; 3],
}

impl Default for Light {
    /// GL's defaults for lights other than `GL_LIGHT0`.
    fn default() -> Light {
        Light {
            ambient: Vec4::new(0.0, 0.0, 0.0, 1.0),
            diffuse: Vec4::new(0.0, 0.0, 0.0, 1.0),
            specular: Vec4::new(0.0, 0.0, 0.0, 1.0),
            position: Vec4::new(0.0, 0.0, 1.0, 0.0),
            spot_direction: Vec3::new(0.0, 0.0, -1.0),
            spot_exponent: 0.0,
            spot_cutoff: 180.0,
            attenuation: [1.0, 0.0, 0.0],
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    pub ambient: Vec4,
    pub diffuse: Vec4,
    pub specular: Vec4,
    pub emission: Vec4,
    /// [0, 128].
    pub shininess: f32,
}

impl Default for Material {
    fn default() -> Material {
        Material {
            ambient: Vec4::new(0.2, 0.2, 0.2, 1.0),
            diffuse: Vec4::new(0.8, 0.8, 0.8, 1.0),
            specular: Vec4::new(0.0, 0.0, 0.0, 1.0),
            emission: Vec4::new(0.0, 0.0, 0.0, 1.0),
            shininess: 0.0,
        }
    }
}

/// Lighting (`GL_LIGHTING` enabled): see `core::vertex` for the equation.
#[derive(Clone, Debug, PartialEq)]
pub struct Lighting {
    /// The enabled lights only, in any order.
    pub lights: Vec<Light>,
    /// `GL_LIGHT_MODEL_AMBIENT`.
    pub model_ambient: Vec4,
    /// `GL_LIGHT_MODEL_TWO_SIDE`: back-facing triangles take the color lit with the
    /// reversed normal and the back material.
    pub two_side: bool,
    pub front: Material,
    pub back: Material,
    /// `GL_COLOR_MATERIAL`: the vertex color (array or current) replaces the ambient and
    /// diffuse colors of both materials.
    pub color_material: bool,
    /// Whether lit colors are clamped to [0, 1] right after lighting, as GL (ES 1.1
    /// §2.12.7) and M3G (GL 1.3 §2.13.6) require. `false` keeps channels above 1 until the
    /// texture environment's result is clamped, which is what Mesa's softpipe and llvmpipe
    /// do; the M3G corpus references were rendered that way.
    pub clamp_after_lighting: bool,
}

impl Default for Lighting {
    fn default() -> Lighting {
        Lighting {
            lights: Vec::new(),
            model_ambient: Vec4::new(0.2, 0.2, 0.2, 1.0),
            two_side: false,
            front: Material::default(),
            back: Material::default(),
            color_material: false,
            clamp_after_lighting: true,
        }
    }
}

/// Texture coordinates generated from the eye-space normal and position (cube-map texgen,
/// `OES_texture_cube_map`), before the texture matrix.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TexGen {
    /// (s, t, r) = the eye-space normal.
    NormalMap,
    /// (s, t, r) = the eye-space reflection vector u − 2n(n·u), u the unit vector from the
    /// eye to the vertex.
    ReflectionMap,
}

/// Point parameters (ES 1.1 §3.3): the derived size is
/// `clamp(size · sqrt(1 / (a + b·d + c·d²)), min, max)` with d the eye-space distance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointParams {
    pub size_min: f32,
    pub size_max: f32,
    /// a, b, c.
    pub attenuation: [f32; 3],
    /// Used only with multisampling (which no target has): below it a point would be drawn
    /// at the threshold size with its alpha faded.
    pub fade_threshold: f32,
}

impl Default for PointParams {
    fn default() -> PointParams {
        PointParams {
            size_min: 0.0,
            size_max: MAX_POINT_SIZE,
            attenuation: [1.0, 0.0, 0.0],
            fade_threshold: 1.0,
        }
    }
}

#[derive(Clone, Debug)]
pub struct RenderState {
    pub modelview: Mat4,
    pub projection: Mat4,
    pub viewport: Viewport,
    /// `glDepthRange` near and far, each clamped to [0, 1].
    pub depth_range: [f32; 2],
    pub scissor: Option<Rect>,
    pub cull: Option<CullFace>,
    pub front_face: Winding,
    pub shade_model: ShadeModel,
    /// `Some(func)` when the depth test is enabled.
    pub depth_test: Option<CompareFunc>,
    pub depth_write: bool,
    pub color_mask: ColorMask,
    pub polygon_offset: Option<PolygonOffset>,
    pub alpha_test: Option<AlphaTest>,
    pub stencil_test: Option<StencilTest>,
    /// Stencil bits fragments may write (`glStencilMask`).
    pub stencil_writemask: u32,
    pub blend: Option<Blend>,
    /// When enabled, replaces blending (ES 1.1 §4.1.10).
    pub logic_op: Option<LogicOp>,
    pub dither: bool,
    /// `glLineWidth` and `GL_LINE_SMOOTH`.
    pub line_width: f32,
    pub line_smooth: bool,
    /// `glPointSize` and `GL_POINT_SMOOTH`.
    pub point_size: f32,
    pub point_smooth: bool,
    /// `GL_PERSPECTIVE_CORRECTION_HINT`, `GL_LINE_SMOOTH_HINT`, `GL_POINT_SMOOTH_HINT`.
    pub perspective: Quality,
    pub line_quality: Quality,
    pub point_quality: Quality,
    /// `Some` when `GL_LIGHTING` is enabled.
    pub lighting: Option<Lighting>,
    /// `GL_NORMALIZE` and `GL_RESCALE_NORMAL`.
    pub normalize: bool,
    pub rescale_normal: bool,
    /// The enabled user clip planes in eye coordinates (p · (xe, ye, ze, we) ≥ 0 is
    /// inside); at most [`crate::clip::MAX_USER_PLANES`] are used.
    pub clip_planes: Vec<Vec4>,
    /// Per texture unit: the texture matrix, and generated coordinates replacing the
    /// unit's texture coordinates when `Some`.
    pub texture_matrices: [Mat4; crate::TEXTURE_UNITS],
    pub texgen: [Option<TexGen>; crate::TEXTURE_UNITS],
    /// `glPointParameter`.
    pub point_params: PointParams,
    /// `OES_matrix_palette` (`GL_MATRIX_PALETTE_OES` enabled): the palette matrices, which
    /// replace the modelview for positions (weighted by the draw call's weights) and, by
    /// their inverse transposes, for normals.
    pub matrix_palette: Option<Vec<Mat4>>,
    /// Per texture unit: `Some` when `GL_TEXTURE_2D` is enabled there and the bound
    /// texture is complete (a snapshot of its images, shared, so pending draws keep the
    /// contents they were recorded with), with the unit's environment.
    pub textures: [Option<super::texenv::TextureUnit>; crate::TEXTURE_UNITS],
    /// `Some` when `GL_FOG` is enabled.
    pub fog: Option<super::texenv::Fog>,
    /// `GL_POINT_SPRITE_OES`.
    pub point_sprite: bool,
    /// `GL_MULTISAMPLE` and the sample mask state; used only by multisampled targets.
    pub multisample: super::multisample::Multisample,
    /// Set by the core while recording a draw into one sample plane of a multisampled
    /// target; `None` everywhere else (and then nothing changes).
    pub sample: Option<super::multisample::SamplePass>,
}

impl RenderState {
    /// The initial state for a surface of the given size: identity matrices, a viewport and
    /// scissor box covering the surface, everything disabled, all writes enabled.
    pub fn new(width: i32, height: i32) -> RenderState {
        RenderState {
            modelview: Mat4::IDENTITY,
            projection: Mat4::IDENTITY,
            viewport: Viewport {
                x: 0,
                y: 0,
                width,
                height,
            },
            depth_range: [0.0, 1.0],
            scissor: None,
            cull: None,
            front_face: Winding::Ccw,
            shade_model: ShadeModel::Smooth,
            depth_test: None,
            depth_write: true,
            color_mask: [true; 4],
            polygon_offset: None,
            alpha_test: None,
            stencil_test: None,
            stencil_writemask: u32::MAX,
            blend: None,
            logic_op: None,
            dither: false,
            line_width: 1.0,
            line_smooth: false,
            point_size: 1.0,
            point_smooth: false,
            perspective: Quality::Balanced,
            line_quality: Quality::Balanced,
            point_quality: Quality::Balanced,
            lighting: None,
            normalize: false,
            rescale_normal: false,
            clip_planes: Vec::new(),
            texture_matrices: [Mat4::IDENTITY; crate::TEXTURE_UNITS],
            texgen: [None; crate::TEXTURE_UNITS],
            point_params: PointParams::default(),
            matrix_palette: None,
            textures: Default::default(),
            fog: None,
            point_sprite: false,
            multisample: Default::default(),
            sample: None,
        }
    }

    /// The pixels a draw may touch in a target with `bounds`: those inside the scissor box.
    pub fn pixel_bounds(&self, b: Rect) -> Rect {
        b.scissored(self.scissor)
    }
}
