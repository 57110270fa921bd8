//! Texture environments (ES 1.1 §3.7.12), one per texture unit, and the per-unit point
//! sprite coordinate replacement (OES_point_sprite). Not part of any texture object.
#![forbid(unsafe_code)]

use gles_cm_core::state::{Quality, TexGen};
use gles_cm_core::texenv as core_env;
use gles_cm_core::RenderState;

use super::context::{Context, MAX_TEXTURE_UNITS};
use super::get::Value;
use super::params::{clamp01, Params};
use super::tokens::*;
use super::tokens_ext::{
    GL_NORMAL_MAP_OES, GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT,
};
use super::types::*;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexEnvUnit {
    /// `GL_MODULATE`, `GL_REPLACE`, `GL_DECAL`, `GL_BLEND`, `GL_ADD` or `GL_COMBINE`.
    pub mode: GLenum,
    /// Clamped to [0, 1] when specified.
    pub color: [f32; 4],
    pub combine_rgb: GLenum,
    pub combine_alpha: GLenum,
    pub src_rgb: [GLenum; 3],
    pub src_alpha: [GLenum; 3],
    pub operand_rgb: [GLenum; 3],
    pub operand_alpha: [GLenum; 3],
    /// 1, 2 or 4.
    pub rgb_scale: f32,
    pub alpha_scale: f32,
    /// `GL_COORD_REPLACE_OES` of the `GL_POINT_SPRITE_OES` target.
    pub coord_replace: bool,
    /// `GL_TEXTURE_LOD_BIAS_EXT` of the `GL_TEXTURE_FILTER_CONTROL_EXT` target
    /// (`EXT_texture_lod_bias`), as set: clamped to ±`GL_MAX_TEXTURE_LOD_BIAS_EXT` when used.
    pub lod_bias: f32,
}

impl Default for TexEnvUnit {
    fn default() -> TexEnvUnit {
        TexEnvUnit {
            mode: GL_MODULATE,
            color: [0.0; 4],
            combine_rgb: GL_MODULATE,
            combine_alpha: GL_MODULATE,
            src_rgb: [GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT],
            src_alpha: [GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT],
            operand_rgb: [GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA],
            operand_alpha: [GL_SRC_ALPHA, GL_SRC_ALPHA, GL_SRC_ALPHA],
            rgb_scale: 1.0,
            alpha_scale: 1.0,
            coord_replace: false,
            lod_bias: 0.0,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct TexEnv {
    pub units: [TexEnvUnit; MAX_TEXTURE_UNITS],
}

/// How many values `glTexEnv*v` reads for `target` and `pname` (`None`: invalid names).
pub fn tex_env_parameter_count(target: GLenum, pname: GLenum) -> Option<usize> {
    match (target, pname) {
        (GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR) => Some(4),
        (GL_TEXTURE_ENV, p) => slot(p).map(|_| 1),
        (GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES)
        | (GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT) => Some(1),
        _ => None,
    }
}

/// Which slot of a unit's environment `pname` names, with the values it accepts.
enum Slot {
    Mode,
    Color,
    CombineRgb,
    CombineAlpha,
    SrcRgb(usize),
    SrcAlpha(usize),
    OperandRgb(usize),
    OperandAlpha(usize),
    RgbScale,
    AlphaScale,
}

fn slot(pname: GLenum) -> Option<Slot> {
    Some(match pname {
        GL_TEXTURE_ENV_MODE => Slot::Mode,
        GL_TEXTURE_ENV_COLOR => Slot::Color,
        GL_COMBINE_RGB => Slot::CombineRgb,
        GL_COMBINE_ALPHA => Slot::CombineAlpha,
        GL_SRC0_RGB => Slot::SrcRgb(0),
        GL_SRC1_RGB => Slot::SrcRgb(1),
        GL_SRC2_RGB => Slot::SrcRgb(2),
        GL_SRC0_ALPHA => Slot::SrcAlpha(0),
        GL_SRC1_ALPHA => Slot::SrcAlpha(1),
        GL_SRC2_ALPHA => Slot::SrcAlpha(2),
        GL_OPERAND0_RGB => Slot::OperandRgb(0),
        GL_OPERAND1_RGB => Slot::OperandRgb(1),
        GL_OPERAND2_RGB => Slot::OperandRgb(2),
        GL_OPERAND0_ALPHA => Slot::OperandAlpha(0),
        GL_OPERAND1_ALPHA => Slot::OperandAlpha(1),
        GL_OPERAND2_ALPHA => Slot::OperandAlpha(2),
        GL_RGB_SCALE => Slot::RgbScale,
        GL_ALPHA_SCALE => Slot::AlphaScale,
        _ => return None,
    })
}

impl Context {
    /// `glTexEnv{f,i,x}[v]` for the active texture unit (also `EXT_texture_lod_bias`'s
    /// `GL_TEXTURE_FILTER_CONTROL_EXT` / `GL_TEXTURE_LOD_BIAS_EXT`, any float, stored as
    /// given and clamped when used). Unknown targets and names, and
    /// enumerants a name does not accept, are `GL_INVALID_ENUM`; scales other than 1, 2
    /// and 4 and a `GL_COORD_REPLACE_OES` other than TRUE/FALSE are `GL_INVALID_VALUE`.
    pub fn tex_env(&mut self, target: GLenum, pname: GLenum, p: Params<'_>) {
        let unit = self.active_texture;
        if tex_env_parameter_count(target, pname).is_none_or(|n| p.len() < n) {
            return self.set_error(GL_INVALID_ENUM);
        }
        match (target, pname) {
            (GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES) => {
                // A boolean: like enumerants, passed unconverted by the fixed-point calls.
                let on = match p.enumerant(0) {
                    Some(0) => false,
                    Some(1) => true,
                    _ => return self.set_error(GL_INVALID_VALUE),
                };
                self.texenv.units[unit].coord_replace = on;
                return;
            }
            (GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT) => {
                self.texenv.units[unit].lod_bias = p.number(0);
                return;
            }
            (GL_TEXTURE_ENV, _) => {}
            _ => return self.bad_enum("target", target),
        }
        let Some(s) = slot(pname) else {
            return self.bad_enum("pname", pname);
        };
        let u = &mut self.texenv.units[unit];
        match s {
            Slot::Color => {
                u.color = p.color().map(clamp01);
                return;
            }
            Slot::RgbScale | Slot::AlphaScale => {
                let v = p.number(0);
                if v != 1.0 && v != 2.0 && v != 4.0 {
                    return self.set_error(GL_INVALID_VALUE);
                }
                match s {
                    Slot::RgbScale => u.rgb_scale = v,
                    _ => u.alpha_scale = v,
                }
                return;
            }
            _ => {}
        }
        let Some(e) = p.enumerant(0) else {
            return self.set_error(GL_INVALID_ENUM);
        };
        let ok = match s {
            Slot::Mode => matches!(
                e,
                GL_MODULATE | GL_REPLACE | GL_DECAL | GL_BLEND | GL_ADD | GL_COMBINE
            ),
            Slot::CombineRgb => matches!(
                e,
                GL_REPLACE
                    | GL_MODULATE
                    | GL_ADD
                    | GL_ADD_SIGNED
                    | GL_INTERPOLATE
                    | GL_SUBTRACT
                    | GL_DOT3_RGB
                    | GL_DOT3_RGBA
            ),
            Slot::CombineAlpha => matches!(
                e,
                GL_REPLACE | GL_MODULATE | GL_ADD | GL_ADD_SIGNED | GL_INTERPOLATE | GL_SUBTRACT
            ),
            Slot::SrcRgb(_) | Slot::SrcAlpha(_) => {
                matches!(e, GL_TEXTURE | GL_CONSTANT | GL_PRIMARY_COLOR | GL_PREVIOUS)
                    || crossbar_unit(e).is_some()
            }
            Slot::OperandRgb(_) => matches!(
                e,
                GL_SRC_COLOR | GL_ONE_MINUS_SRC_COLOR | GL_SRC_ALPHA | GL_ONE_MINUS_SRC_ALPHA
            ),
            Slot::OperandAlpha(_) => matches!(e, GL_SRC_ALPHA | GL_ONE_MINUS_SRC_ALPHA),
            Slot::Color | Slot::RgbScale | Slot::AlphaScale => false,
        };
        if !ok {
            return self.set_error(GL_INVALID_ENUM);
        }
        match s {
            Slot::Mode => u.mode = e,
            Slot::CombineRgb => u.combine_rgb = e,
            Slot::CombineAlpha => u.combine_alpha = e,
            Slot::SrcRgb(i) => u.src_rgb[i] = e,
            Slot::SrcAlpha(i) => u.src_alpha[i] = e,
            Slot::OperandRgb(i) => u.operand_rgb[i] = e,
            Slot::OperandAlpha(i) => u.operand_alpha[i] = e,
            Slot::Color | Slot::RgbScale | Slot::AlphaScale => {}
        }
    }

    /// `glGetTexEnv{f,i,x}v` for the active texture unit. Enumerants are `Kind::Int`
    /// replies, the color `Kind::Normalized`, the scales `Kind::Float`.
    pub fn get_tex_env(&mut self, target: GLenum, pname: GLenum) -> Option<Value> {
        let u = &self.texenv.units[self.active_texture];
        let e = |v: GLenum| Value::int(v as i64);
        let v = match (target, pname) {
            (GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES) => Value::int(u.coord_replace as i64),
            (GL_TEXTURE_FILTER_CONTROL_EXT, GL_TEXTURE_LOD_BIAS_EXT) => {
                Value::floats(&[u.lod_bias])
            }
            (GL_TEXTURE_ENV, _) => match slot(pname) {
                Some(Slot::Mode) => e(u.mode),
                Some(Slot::Color) => Value::norm(&u.color),
                Some(Slot::CombineRgb) => e(u.combine_rgb),
                Some(Slot::CombineAlpha) => e(u.combine_alpha),
                Some(Slot::SrcRgb(i)) => e(u.src_rgb[i]),
                Some(Slot::SrcAlpha(i)) => e(u.src_alpha[i]),
                Some(Slot::OperandRgb(i)) => e(u.operand_rgb[i]),
                Some(Slot::OperandAlpha(i)) => e(u.operand_alpha[i]),
                Some(Slot::RgbScale) => Value::floats(&[u.rgb_scale]),
                Some(Slot::AlphaScale) => Value::floats(&[u.alpha_scale]),
                None => {
                    self.set_error(GL_INVALID_ENUM);
                    return None;
                }
            },
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        };
        Some(v)
    }
}

fn combine_func(e: GLenum) -> core_env::CombineFunc {
    use core_env::CombineFunc as F;
    match e {
        GL_REPLACE => F::Replace,
        GL_ADD => F::Add,
        GL_ADD_SIGNED => F::AddSigned,
        GL_INTERPOLATE => F::Interpolate,
        GL_SUBTRACT => F::Subtract,
        GL_DOT3_RGB => F::Dot3Rgb,
        GL_DOT3_RGBA => F::Dot3Rgba,
        _ => F::Modulate,
    }
}

/// The unit `GL_TEXTUREn` names as a combiner source (`OES_texture_env_crossbar`).
fn crossbar_unit(e: GLenum) -> Option<usize> {
    let n = e.checked_sub(GL_TEXTURE0)? as usize;
    (n < MAX_TEXTURE_UNITS).then_some(n)
}

/// The core's source for `e` on unit `own`; `GL_TEXTUREn` naming the unit itself is its
/// own texel, which keeps the draw off the crossbar route.
fn source(e: GLenum, own: usize) -> core_env::Source {
    use core_env::Source as S;
    match e {
        GL_TEXTURE => S::Texture,
        GL_CONSTANT => S::Constant,
        GL_PRIMARY_COLOR => S::PrimaryColor,
        _ => match crossbar_unit(e) {
            Some(n) if n == own => S::Texture,
            Some(n) => S::Unit(n as u8),
            None => S::Previous,
        },
    }
}

fn operand(e: GLenum) -> core_env::Operand {
    use core_env::Operand as O;
    match e {
        GL_SRC_COLOR => O::SrcColor,
        GL_ONE_MINUS_SRC_COLOR => O::OneMinusSrcColor,
        GL_ONE_MINUS_SRC_ALPHA => O::OneMinusSrcAlpha,
        _ => O::SrcAlpha,
    }
}

impl TexEnvUnit {
    /// The core's form of this environment of unit `own` (the enums were validated when
    /// set).
    pub fn to_core(&self, own: usize) -> core_env::TexEnv {
        use core_env::EnvMode as M;
        let mode = match self.mode {
            GL_REPLACE => M::Replace,
            GL_DECAL => M::Decal,
            GL_BLEND => M::Blend,
            GL_ADD => M::Add,
            GL_COMBINE => M::Combine(core_env::Combine {
                rgb: combine_func(self.combine_rgb),
                alpha: combine_func(self.combine_alpha),
                src_rgb: self.src_rgb.map(|e| source(e, own)),
                src_alpha: self.src_alpha.map(|e| source(e, own)),
                operand_rgb: self.operand_rgb.map(operand),
                operand_alpha: self.operand_alpha.map(operand),
                rgb_scale: self.rgb_scale,
                alpha_scale: self.alpha_scale,
            }),
            _ => M::Modulate,
        };
        core_env::TexEnv {
            mode,
            color: self.color,
        }
    }
}

impl Context {
    /// Fills the texture units (snapshots of the complete textures bound to enabled units),
    /// fog and the point sprite enable of `rs`.
    pub(super) fn texture_render_state(&self, rs: &mut RenderState) {
        for u in 0..MAX_TEXTURE_UNITS {
            // A cube map enabled on a unit takes precedence over its 2D texture.
            let bias = self.texenv.units[u].lod_bias;
            let sampler = if self.enables.texture_cube_map[u] {
                Some(self.unit_snapshot(u, true, bias))
            } else if self.enables.texture_2d[u] {
                Some(self.unit_snapshot(u, false, bias))
            } else {
                None
            };
            rs.texgen[u] = self.enables.texture_gen_str[u].then(|| {
                if self.textures.texgen_mode[u] == GL_NORMAL_MAP_OES {
                    TexGen::NormalMap
                } else {
                    TexGen::ReflectionMap
                }
            });
            rs.textures[u] = if let Some(sampler) = sampler {
                sampler.map(|sampler| core_env::TextureUnit {
                    sampler,
                    env: self.texenv.units[u].to_core(u),
                    coord_replace: self.texenv.units[u].coord_replace,
                })
            } else {
                None
            };
        }
        // OES_texture_env_crossbar: a unit whose combiner names a unit that is disabled or
        // has no complete texture acts as if its texturing were disabled.
        let live: [bool; MAX_TEXTURE_UNITS] = std::array::from_fn(|u| rs.textures[u].is_some());
        for unit in rs.textures.iter_mut().flatten() {
            if let core_env::EnvMode::Combine(k) = &unit.env.mode {
                if k.crossbar_units().any(|n| !live[n]) {
                    unit.env.mode = core_env::EnvMode::Combine(core_env::Combine::PASS_THROUGH);
                }
            }
        }
        rs.point_sprite = self.enables.point_sprite;
        rs.fog = self.enables.fog.then(|| {
            let f = &self.fog;
            core_env::Fog {
                mode: match f.mode {
                    GL_LINEAR => core_env::FogMode::Linear,
                    GL_EXP2 => core_env::FogMode::Exp2,
                    _ => core_env::FogMode::Exp,
                },
                density: f.density,
                start: f.start,
                end: f.end,
                color: f.color,
                quality: match self.hints.fog {
                    GL_FASTEST => Quality::Fastest,
                    GL_NICEST => Quality::Nicest,
                    _ => Quality::Balanced,
                },
            }
        });
    }
}
