//! State queries: `glGet{Boolean,Integer,Float,Fixed}v`, `glGetString`.
//!
//! Every queryable value is produced once, in its natural type, by [`Context::state_value`];
//! the four getters only convert, with the specification's rules (ES 1.1 §6.1.2).
#![forbid(unsafe_code)]

use gles_cm_core::{fixed, MAX_VIEWPORT_DIM, SUBPIXEL_BITS};

use super::context::*;
use super::tokens::*;
use super::tokens_ext::*;
use super::types::*;

/// The natural type of a state value, which decides how each getter converts it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Integers and enums: floats get the exact value.
    Int,
    /// Floats: integer queries round to nearest.
    Float,
    /// Colors, normals and depth values: integer queries map [-1, 1] linearly onto the whole
    /// integer range.
    Normalized,
    Bool,
}

/// The most values a state query answers: `GL_COMPRESSED_TEXTURE_FORMATS`' list (19), then
/// a matrix (16).
pub(crate) const MAX_VALUES: usize = 24;

/// Up to `MAX_VALUES` values of one kind.
#[derive(Clone, Copy, Debug)]
pub struct Value {
    pub kind: Kind,
    pub len: usize,
    pub data: [f64; MAX_VALUES],
}

impl Value {
    pub(crate) fn new(kind: Kind, values: &[f64]) -> Value {
        let mut data = [0.0; MAX_VALUES];
        data[..values.len()].copy_from_slice(values);
        Value {
            kind,
            len: values.len(),
            data,
        }
    }
    pub(crate) fn ints(v: &[i64]) -> Value {
        Value::new(Kind::Int, &v.iter().map(|&x| x as f64).collect::<Vec<_>>())
    }
    pub(crate) fn int(v: i64) -> Value {
        Value::ints(&[v])
    }
    pub(crate) fn floats(v: &[f32]) -> Value {
        Value::new(
            Kind::Float,
            &v.iter().map(|&x| x as f64).collect::<Vec<_>>(),
        )
    }
    pub(crate) fn norm(v: &[f32]) -> Value {
        Value::new(
            Kind::Normalized,
            &v.iter().map(|&x| x as f64).collect::<Vec<_>>(),
        )
    }
    pub(crate) fn bools(v: &[bool]) -> Value {
        Value::new(
            Kind::Bool,
            &v.iter()
                .map(|&x| f64::from(u8::from(x)))
                .collect::<Vec<_>>(),
        )
    }

    pub fn values(&self) -> &[f64] {
        &self.data[..self.len]
    }

    pub fn as_booleans(&self) -> impl Iterator<Item = GLboolean> + '_ {
        self.values().iter().map(|&v| {
            if v != 0.0 {
                GL_TRUE as GLboolean
            } else {
                GL_FALSE as GLboolean
            }
        })
    }

    pub fn as_integers(&self) -> impl Iterator<Item = GLint> + '_ {
        let kind = self.kind;
        self.values().iter().map(move |&v| match kind {
            Kind::Normalized => {
                let m = ((u32::MAX as f64) * v - 1.0) / 2.0;
                (m + 0.5).floor().clamp(i32::MIN as f64, i32::MAX as f64) as i32
            }
            _ => v.round().clamp(i32::MIN as f64, i32::MAX as f64) as i32,
        })
    }

    pub fn as_floats(&self) -> impl Iterator<Item = GLfloat> + '_ {
        self.values().iter().map(|&v| v as f32)
    }

    pub fn as_fixed(&self) -> impl Iterator<Item = GLfixed> + '_ {
        self.values().iter().map(|&v| fixed::from_f32(v as f32))
    }
}

/// The `glGetString` answers, NUL-terminated for C.
pub const VENDOR: &[u8] = b"gles-cm project\0";
pub const RENDERER: &[u8] = b"gles-cm software rasterizer\0";
/// "OpenGL ES-CM 1.1", a space, then the implementation's own version (ES 1.1 §6.1.5).
pub const VERSION: &[u8] =
    concat!("OpenGL ES-CM 1.1 gles-cm-", env!("CARGO_PKG_VERSION"), "\0").as_bytes();
/// The extensions `GL_EXTENSIONS` names, one per line (add a line where one starts working).
const EXTENSION_LIST: &[&str] = &[
    "GL_OES_read_format",
    "GL_OES_byte_coordinates",
    "GL_OES_fixed_point",
    "GL_OES_single_precision",
    "GL_OES_point_size_array",
    "GL_OES_compressed_paletted_texture",
    "GL_OES_mapbuffer",
    "GL_OES_blend_subtract",
    "GL_OES_blend_func_separate",
    "GL_OES_blend_equation_separate",
    "GL_OES_stencil_wrap",
    "GL_OES_element_index_uint",
    "GL_OES_matrix_get",
    "GL_OES_matrix_palette",
    "GL_OES_query_matrix",
    "GL_OES_point_sprite",
    "GL_OES_texture_mirrored_repeat",
    "GL_OES_framebuffer_object",
    "GL_OES_compressed_ETC1_RGB8_texture",
    "GL_EXT_texture_format_BGRA8888",
    "GL_OES_draw_texture",
    "GL_OES_texture_cube_map",
    "GL_EXT_texture_lod_bias",
    "GL_OES_rgb8_rgba8",
    "GL_OES_depth24",
    "GL_OES_stencil8",
    "GL_EXT_discard_framebuffer",
    "GL_EXT_multi_draw_arrays",
    "GL_OES_fbo_render_mipmap",
    "GL_EXT_read_format_bgra",
    "GL_OES_vertex_array_object",
    "GL_APPLE_texture_max_level",
    "GL_EXT_blend_minmax",
    "GL_OES_texture_npot",
    "GL_APPLE_texture_2D_limited_npot",
    "GL_IMG_texture_compression_pvrtc",
    "GL_EXT_texture_compression_dxt1",
    "GL_ANGLE_texture_compression_dxt3",
    "GL_ANGLE_texture_compression_dxt5",
    "GL_EXT_compressed_ETC1_RGB8_sub_texture",
    "GL_EXT_map_buffer_range",
    "GL_EXT_polygon_offset_clamp",
    "GL_OES_required_internalformat",
    "GL_OES_packed_depth_stencil",
    "GL_OES_texture_env_crossbar",
    "GL_EXT_texture_filter_anisotropic",
    "GL_OES_surfaceless_context",
    "GL_OES_EGL_image",
    "GL_OES_EGL_sync",
    "GL_KHR_debug",
];

/// `EXTENSION_LIST` as the NUL-terminated, space-separated string `glGetString` returns.
fn extensions() -> &'static [u8] {
    static STRING: std::sync::OnceLock<Vec<u8>> = std::sync::OnceLock::new();
    STRING.get_or_init(|| {
        let mut s = EXTENSION_LIST.join(" ").into_bytes();
        s.push(0);
        s
    })
}

impl Context {
    /// The NUL-terminated string for `glGetString`, or `None` for an invalid name.
    pub fn string(&mut self, name: GLenum) -> Option<&'static [u8]> {
        Some(match name {
            GL_VENDOR => VENDOR,
            GL_RENDERER => RENDERER,
            GL_VERSION => VERSION,
            GL_EXTENSIONS => extensions(),
            _ => {
                self.bad_enum("name", name);
                return None;
            }
        })
    }

    /// The value of state variable `pname`, or `None` when `pname` names no state
    /// (`GL_INVALID_ENUM`).
    pub fn state_value(&mut self, pname: GLenum) -> Option<Value> {
        let unit = self.active_texture;
        if let Some(flag) = self.enables.flag(pname, unit) {
            return Some(Value::bools(&[*flag]));
        }
        if let Some(v) = self
            .fragment_value(pname)
            .or_else(|| self.points_lines_value(pname))
            .or_else(|| self.lighting_value(pname))
            .or_else(|| self.fog_value(pname))
            .or_else(|| self.current_values_value(pname))
            .or_else(|| self.texture_value(pname))
            .or_else(|| self.buffer_value(pname))
            .or_else(|| self.fbo_value(pname))
            .or_else(|| self.vertex_array_value(pname))
            .or_else(|| self.debug_value(pname))
        {
            return Some(v);
        }
        let bits = self.draw_format().map(|f| {
            let c = f.color.bits();
            [
                c[0],
                c[1],
                c[2],
                c[3],
                f.depth.map_or(0, |d| d.bits()),
                f.stencil_bits,
            ]
        });
        let bits = bits.unwrap_or([0; 6]);
        let vp = self.viewport;
        let sb = self.scissor_box;
        let a = &self.arrays;
        let matrix = |m: &glam::Mat4| Value::floats(&m.to_cols_array());
        let float_bits = |m: &glam::Mat4| {
            let b = m.to_cols_array().map(|v| v.to_bits() as i32 as i64);
            Value::ints(&b)
        };
        Some(match pname {
            GL_VIEWPORT => {
                Value::ints(&[vp.x as i64, vp.y as i64, vp.width as i64, vp.height as i64])
            }
            GL_SCISSOR_BOX => Value::ints(&[
                sb.x0 as i64,
                sb.y0 as i64,
                sb.x1 as i64 - sb.x0 as i64,
                sb.y1 as i64 - sb.y0 as i64,
            ]),
            GL_DEPTH_RANGE => Value::norm(&self.depth_range),
            GL_COLOR_CLEAR_VALUE => Value::norm(&self.clear_color),
            GL_DEPTH_CLEAR_VALUE => Value::norm(&[self.clear_depth]),
            GL_STENCIL_CLEAR_VALUE => Value::int(self.clear_stencil as i64),
            GL_COLOR_WRITEMASK => Value::bools(&self.color_mask),
            GL_DEPTH_WRITEMASK => Value::bools(&[self.depth_mask]),
            GL_STENCIL_WRITEMASK => Value::int(self.stencil_writemask as i32 as i64),
            GL_DEPTH_FUNC => Value::int(compare_func_enum(self.depth_func) as i64),
            GL_CULL_FACE_MODE => Value::int(match self.cull_face {
                gles_cm_core::CullFace::Front => GL_FRONT,
                gles_cm_core::CullFace::Back => GL_BACK,
                gles_cm_core::CullFace::FrontAndBack => GL_FRONT_AND_BACK,
            } as i64),
            GL_FRONT_FACE => Value::int(match self.front_face {
                gles_cm_core::Winding::Ccw => GL_CCW,
                gles_cm_core::Winding::Cw => GL_CW,
            } as i64),
            GL_SHADE_MODEL => Value::int(match self.shade_model {
                gles_cm_core::ShadeModel::Flat => GL_FLAT,
                gles_cm_core::ShadeModel::Smooth => GL_SMOOTH,
            } as i64),
            GL_MATRIX_MODE => Value::int(match self.matrix_mode {
                MatrixMode::Modelview => GL_MODELVIEW,
                MatrixMode::Projection => GL_PROJECTION,
                MatrixMode::Texture => GL_TEXTURE,
                MatrixMode::Palette => GL_MATRIX_PALETTE_OES,
            } as i64),
            GL_MODELVIEW_MATRIX => matrix(self.modelview.last()?),
            GL_PROJECTION_MATRIX => matrix(self.projection.last()?),
            GL_TEXTURE_MATRIX => matrix(self.texture[unit].last()?),
            // OES_matrix_get: the IEEE-754 bit patterns, for glGetIntegerv.
            GL_MODELVIEW_MATRIX_FLOAT_AS_INT_BITS_OES => float_bits(self.modelview.last()?),
            GL_PROJECTION_MATRIX_FLOAT_AS_INT_BITS_OES => float_bits(self.projection.last()?),
            GL_TEXTURE_MATRIX_FLOAT_AS_INT_BITS_OES => float_bits(self.texture[unit].last()?),
            GL_MAX_PALETTE_MATRICES_OES => Value::int(MAX_PALETTE_MATRICES as i64),
            GL_MAX_VERTEX_UNITS_OES => Value::int(MAX_VERTEX_UNITS as i64),
            GL_CURRENT_PALETTE_MATRIX_OES => Value::int(self.current_palette as i64),
            GL_MATRIX_INDEX_ARRAY_OES => Value::bools(&[a.matrix_index.enabled]),
            GL_MATRIX_INDEX_ARRAY_SIZE_OES => Value::int(a.matrix_index.size as i64),
            GL_MATRIX_INDEX_ARRAY_TYPE_OES => Value::int(a.matrix_index.ty as i64),
            GL_MATRIX_INDEX_ARRAY_STRIDE_OES => Value::int(a.matrix_index.stride as i64),
            GL_MATRIX_INDEX_ARRAY_BUFFER_BINDING_OES => {
                Value::int(a.matrix_index.buffer.name as i64)
            }
            GL_WEIGHT_ARRAY_OES => Value::bools(&[a.weight.enabled]),
            GL_WEIGHT_ARRAY_SIZE_OES => Value::int(a.weight.size as i64),
            GL_WEIGHT_ARRAY_TYPE_OES => Value::int(a.weight.ty as i64),
            GL_WEIGHT_ARRAY_STRIDE_OES => Value::int(a.weight.stride as i64),
            GL_WEIGHT_ARRAY_BUFFER_BINDING_OES => Value::int(a.weight.buffer.name as i64),
            GL_MODELVIEW_STACK_DEPTH => Value::int(self.modelview.len() as i64),
            GL_PROJECTION_STACK_DEPTH => Value::int(self.projection.len() as i64),
            GL_TEXTURE_STACK_DEPTH => Value::int(self.texture[unit].len() as i64),
            GL_MAX_MODELVIEW_STACK_DEPTH => Value::int(MAX_MODELVIEW_STACK_DEPTH as i64),
            GL_MAX_PROJECTION_STACK_DEPTH => Value::int(MAX_PROJECTION_STACK_DEPTH as i64),
            GL_MAX_TEXTURE_STACK_DEPTH => Value::int(MAX_TEXTURE_STACK_DEPTH as i64),
            GL_MAX_TEXTURE_UNITS => Value::int(MAX_TEXTURE_UNITS as i64),
            GL_MAX_LIGHTS => Value::int(MAX_LIGHTS as i64),
            GL_MAX_CLIP_PLANES => Value::int(MAX_CLIP_PLANES as i64),
            GL_MAX_VIEWPORT_DIMS => {
                Value::ints(&[MAX_VIEWPORT_DIM as i64, MAX_VIEWPORT_DIM as i64])
            }
            GL_SUBPIXEL_BITS => Value::int(SUBPIXEL_BITS as i64),
            super::tokens_ext::GL_MAX_TEXTURE_LOD_BIAS_EXT => {
                Value::floats(&[gles_cm_core::texture::MAX_LOD_BIAS])
            }
            super::tokens_ext::GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT => {
                Value::floats(&[gles_cm_core::texture::MAX_ANISOTROPY])
            }
            // The draw surface's (framebuffer objects are single-sample).
            GL_SAMPLE_BUFFERS => Value::int((self.draw_samples() > 0) as i64),
            GL_SAMPLES => Value::int(self.draw_samples() as i64),
            GL_RED_BITS => Value::int(bits[0] as i64),
            GL_GREEN_BITS => Value::int(bits[1] as i64),
            GL_BLUE_BITS => Value::int(bits[2] as i64),
            GL_ALPHA_BITS => Value::int(bits[3] as i64),
            GL_DEPTH_BITS => Value::int(bits[4] as i64),
            GL_STENCIL_BITS => Value::int(bits[5] as i64),
            GL_PACK_ALIGNMENT => Value::int(self.pack_alignment as i64),
            GL_UNPACK_ALIGNMENT => Value::int(self.unpack_alignment as i64),
            GL_PERSPECTIVE_CORRECTION_HINT => Value::int(self.hints.perspective_correction as i64),
            GL_POINT_SMOOTH_HINT => Value::int(self.hints.point_smooth as i64),
            GL_LINE_SMOOTH_HINT => Value::int(self.hints.line_smooth as i64),
            GL_FOG_HINT => Value::int(self.hints.fog as i64),
            GL_GENERATE_MIPMAP_HINT => Value::int(self.hints.generate_mipmap as i64),
            GL_IMPLEMENTATION_COLOR_READ_FORMAT_OES => {
                Value::int(self.implementation_read_format().0 as i64)
            }
            GL_IMPLEMENTATION_COLOR_READ_TYPE_OES => {
                Value::int(self.implementation_read_format().1 as i64)
            }
            GL_CURRENT_COLOR => Value::norm(&a.color_value),
            GL_VERTEX_ARRAY => Value::bools(&[a.vertex.enabled]),
            GL_VERTEX_ARRAY_SIZE => Value::int(a.vertex.size as i64),
            GL_VERTEX_ARRAY_TYPE => Value::int(a.vertex.ty as i64),
            GL_VERTEX_ARRAY_STRIDE => Value::int(a.vertex.stride as i64),
            GL_COLOR_ARRAY => Value::bools(&[a.color.enabled]),
            GL_COLOR_ARRAY_SIZE => Value::int(a.color.size as i64),
            GL_COLOR_ARRAY_TYPE => Value::int(a.color.ty as i64),
            GL_COLOR_ARRAY_STRIDE => Value::int(a.color.stride as i64),
            GL_NORMAL_ARRAY => Value::bools(&[a.normal.enabled]),
            GL_TEXTURE_COORD_ARRAY => Value::bools(&[a.texcoord[a.client_active_texture].enabled]),
            GL_POINT_SIZE_ARRAY_OES => Value::bools(&[a.point_size.enabled]),
            _ => return None,
        })
    }
}
