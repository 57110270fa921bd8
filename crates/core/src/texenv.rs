//! Texture environments and fog as the core sees them (ES 1.1 §3.7.12 tables 3.15-3.18,
//! §3.8): the per-unit function that combines a texel with the incoming fragment color, and
//! the fog blend. The fast path's f32 form lives here; `core::reference` has its own f64
//! form written from the tables.

use std::sync::Arc;

use super::quality::Quality;
use super::texture::{BaseFormat, Sampler};

/// `GL_COMBINE_RGB` / `GL_COMBINE_ALPHA`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CombineFunc {
    Replace,
    Modulate,
    Add,
    AddSigned,
    Interpolate,
    Subtract,
    /// RGB only.
    Dot3Rgb,
    /// RGB only; the alpha function is ignored.
    Dot3Rgba,
}

/// `GL_SRCn_RGB` / `GL_SRCn_ALPHA`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Source {
    Texture,
    Constant,
    PrimaryColor,
    Previous,
    /// `GL_TEXTUREn` (`OES_texture_env_crossbar`): the texel of unit `n`, which must be
    /// enabled with a complete texture (the GL layer makes a unit that names another pass
    /// its input through otherwise, as the extension says).
    Unit(u8),
}

/// `GL_OPERANDn_RGB` / `GL_OPERANDn_ALPHA` (alpha operands use the two alpha forms).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Operand {
    SrcColor,
    OneMinusSrcColor,
    SrcAlpha,
    OneMinusSrcAlpha,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Combine {
    pub rgb: CombineFunc,
    pub alpha: CombineFunc,
    pub src_rgb: [Source; 3],
    pub src_alpha: [Source; 3],
    pub operand_rgb: [Operand; 3],
    pub operand_alpha: [Operand; 3],
    /// 1, 2 or 4.
    pub rgb_scale: f32,
    pub alpha_scale: f32,
}

impl Combine {
    /// Whether the RGB function is DOT3_RGB or DOT3_RGBA (which replace alpha too).
    pub fn is_dot3(&self) -> bool {
        matches!(self.rgb, CombineFunc::Dot3Rgb | CombineFunc::Dot3Rgba)
    }

    /// The units whose texels this combiner names as `Source::Unit`.
    pub fn crossbar_units(&self) -> impl Iterator<Item = usize> + '_ {
        self.src_rgb
            .iter()
            .chain(&self.src_alpha)
            .filter_map(|s| match s {
                Source::Unit(u) => Some(usize::from(*u)),
                _ => None,
            })
    }

    /// Passes the previous color through unchanged: a unit whose combiner names a unit
    /// that is disabled or incomplete acts as if its texturing were disabled.
    pub const PASS_THROUGH: Combine = Combine {
        rgb: CombineFunc::Replace,
        alpha: CombineFunc::Replace,
        src_rgb: [Source::Previous; 3],
        src_alpha: [Source::Previous; 3],
        operand_rgb: [Operand::SrcColor; 3],
        operand_alpha: [Operand::SrcAlpha; 3],
        rgb_scale: 1.0,
        alpha_scale: 1.0,
    };
}

impl TexEnv {
    /// Whether the environment reads the texel of another unit (`GL_TEXTUREn` sources).
    pub fn reads_other_units(&self) -> bool {
        matches!(&self.mode, EnvMode::Combine(k) if k.crossbar_units().next().is_some())
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum EnvMode {
    Replace,
    Modulate,
    Decal,
    Blend,
    Add,
    Combine(Combine),
}

/// One texture unit's environment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexEnv {
    pub mode: EnvMode,
    /// `GL_TEXTURE_ENV_COLOR`, in [0, 1].
    pub color: [f32; 4],
}

impl Default for TexEnv {
    fn default() -> TexEnv {
        TexEnv {
            mode: EnvMode::Modulate,
            color: [0.0; 4],
        }
    }
}

/// An enabled texture unit whose texture is complete.
#[derive(Clone, Debug, PartialEq)]
pub struct TextureUnit {
    pub sampler: Arc<Sampler>,
    pub env: TexEnv,
    /// `GL_COORD_REPLACE_OES`: point sprites replace this unit's s and t.
    pub coord_replace: bool,
}

impl TextureUnit {
    /// A unit sampling a 1 × 1 white image with the default environment: for tests and
    /// tools that need a unit enabled (vertices keep the coordinates of enabled units only).
    pub fn white() -> TextureUnit {
        use super::texture::{Image, MagFilter, MinFilter, Wrap};
        let image = Image {
            width: 1,
            height: 1,
            format: BaseFormat::Rgba,
            texels: vec![u32::MAX],
        };
        TextureUnit {
            sampler: Arc::new(Sampler::new(
                vec![Arc::new(image)],
                MinFilter::Nearest,
                MagFilter::Nearest,
                Wrap::Repeat,
                Wrap::Repeat,
            )),
            env: TexEnv::default(),
            coord_replace: false,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FogMode {
    Linear,
    Exp,
    Exp2,
}

/// Fog (ES 1.1 §3.8), applied after texturing to RGB. The distance is |z_eye|, the
/// absolute eye-space z the specification allows in place of the true distance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fog {
    pub mode: FogMode,
    pub density: f32,
    pub start: f32,
    pub end: f32,
    /// In [0, 1].
    pub color: [f32; 4],
    /// `GL_FOG_HINT`: FASTEST computes the factor per vertex and interpolates it; otherwise
    /// the distance is interpolated and the factor computed per pixel.
    pub quality: Quality,
}

impl Fog {
    /// The fog factor f at eye distance `z`, clamped to [0, 1].
    #[inline]
    pub fn factor(&self, z: f32) -> f32 {
        let f = match self.mode {
            FogMode::Linear => {
                let d = self.end - self.start;
                if d == 0.0 {
                    // Undefined by the equation; treat start == end as a hard edge.
                    if z < self.end {
                        1.0
                    } else {
                        0.0
                    }
                } else {
                    (self.end - z) / d
                }
            }
            FogMode::Exp => (-self.density * z).exp(),
            FogMode::Exp2 => {
                let dz = self.density * z;
                (-dz * dz).exp()
            }
        };
        if f.is_nan() {
            0.0
        } else {
            f.clamp(0.0, 1.0)
        }
    }

    /// Whether the factor is computed per pixel (else per vertex).
    pub fn per_pixel(&self) -> bool {
        self.quality != Quality::Fastest
    }

    /// C = f·C + (1 − f)·C_fog on RGB; alpha unchanged.
    #[inline]
    pub fn apply(&self, f: f32, c: &mut [f32; 4]) {
        for (c, fog) in c.iter_mut().zip(&self.color).take(3) {
            *c = fog + (*c - fog) * f;
        }
    }
}

#[inline(always)]
fn clamp01(v: f32) -> f32 {
    v.clamp(0.0, 1.0)
}

/// Applies environment `env` for a texel `tex` (in [0, 1], expanded as
/// [`super::texture`] stores it) of base format `format` to `prev` (the previous unit's
/// result, or the primary color on the first enabled unit). `primary` is the untextured
/// fragment color. Results are clamped to [0, 1].
#[inline]
pub fn apply(
    env: &TexEnv,
    format: BaseFormat,
    tex: [f32; 4],
    prev: [f32; 4],
    primary: [f32; 4],
) -> [f32; 4] {
    apply_crossbar(env, format, tex, prev, primary, &[])
}

/// [`apply`] where COMBINE may read other units' texels: `units[n]` is unit `n`'s.
#[inline]
pub fn apply_crossbar(
    env: &TexEnv,
    format: BaseFormat,
    tex: [f32; 4],
    prev: [f32; 4],
    primary: [f32; 4],
    units: &[[f32; 4]],
) -> [f32; 4] {
    use BaseFormat as F;
    let [cf0, cf1, cf2, af] = prev;
    let cf = [cf0, cf1, cf2];
    let cs = [tex[0], tex[1], tex[2]];
    let r#as = tex[3];
    let has_alpha = format.has_alpha();
    let has_color = format.has_color();
    let cc = env.color;
    let rgb = |f: &dyn Fn(usize) -> f32| [clamp01(f(0)), clamp01(f(1)), clamp01(f(2))];
    match env.mode {
        EnvMode::Replace => {
            let c = if has_color { cs } else { cf };
            let a = if has_alpha { r#as } else { af };
            [c[0], c[1], c[2], a]
        }
        EnvMode::Modulate => {
            let c = if has_color {
                rgb(&|i| cf[i] * cs[i])
            } else {
                cf
            };
            let a = if has_alpha { af * r#as } else { af };
            [c[0], c[1], c[2], a]
        }
        EnvMode::Decal => match format {
            F::Rgb => [cs[0], cs[1], cs[2], af],
            F::Rgba => {
                let c = rgb(&|i| cf[i] + (cs[i] - cf[i]) * r#as);
                [c[0], c[1], c[2], af]
            }
            // Undefined for the other formats: the fragment passes unchanged.
            _ => prev,
        },
        EnvMode::Blend => {
            let c = if has_color {
                rgb(&|i| cf[i] * (1.0 - cs[i]) + cc[i] * cs[i])
            } else {
                cf
            };
            let a = if has_alpha { af * r#as } else { af };
            [c[0], c[1], c[2], a]
        }
        EnvMode::Add => {
            let c = if has_color {
                rgb(&|i| cf[i] + cs[i])
            } else {
                cf
            };
            let a = if has_alpha { af * r#as } else { af };
            [c[0], c[1], c[2], a]
        }
        EnvMode::Combine(k) => combine(&k, tex, prev, primary, cc, units),
    }
}

#[inline]
fn combine(
    k: &Combine,
    tex: [f32; 4],
    prev: [f32; 4],
    primary: [f32; 4],
    constant: [f32; 4],
    units: &[[f32; 4]],
) -> [f32; 4] {
    let src = |s: Source| match s {
        Source::Texture => tex,
        Source::Constant => constant,
        Source::PrimaryColor => primary,
        Source::Previous => prev,
        Source::Unit(u) => units.get(usize::from(u)).copied().unwrap_or(prev),
    };
    let arg_rgb = |n: usize| -> [f32; 3] {
        let c = src(k.src_rgb[n]);
        match k.operand_rgb[n] {
            Operand::SrcColor => [c[0], c[1], c[2]],
            Operand::OneMinusSrcColor => [1.0 - c[0], 1.0 - c[1], 1.0 - c[2]],
            Operand::SrcAlpha => [c[3]; 3],
            Operand::OneMinusSrcAlpha => [1.0 - c[3]; 3],
        }
    };
    let arg_alpha = |n: usize| -> f32 {
        let c = src(k.src_alpha[n]);
        match k.operand_alpha[n] {
            Operand::OneMinusSrcAlpha | Operand::OneMinusSrcColor => 1.0 - c[3],
            _ => c[3],
        }
    };
    let uses = |f: CombineFunc| match f {
        CombineFunc::Replace => 1,
        CombineFunc::Interpolate => 3,
        _ => 2,
    };
    let n_rgb = uses(k.rgb);
    let a0 = arg_rgb(0);
    let a1 = if n_rgb > 1 { arg_rgb(1) } else { [0.0; 3] };
    let a2 = if n_rgb > 2 { arg_rgb(2) } else { [0.0; 3] };
    let f3 = |f: CombineFunc, a: f32, b: f32, c: f32| match f {
        CombineFunc::Replace => a,
        CombineFunc::Modulate => a * b,
        CombineFunc::Add => a + b,
        CombineFunc::AddSigned => a + b - 0.5,
        CombineFunc::Interpolate => a * c + b * (1.0 - c),
        CombineFunc::Subtract => a - b,
        CombineFunc::Dot3Rgb | CombineFunc::Dot3Rgba => 0.0,
    };
    let s = k.rgb_scale;
    match k.rgb {
        CombineFunc::Dot3Rgb | CombineFunc::Dot3Rgba => {
            let d = 4.0
                * ((a0[0] - 0.5) * (a1[0] - 0.5)
                    + (a0[1] - 0.5) * (a1[1] - 0.5)
                    + (a0[2] - 0.5) * (a1[2] - 0.5));
            let d = clamp01(d * s);
            if k.rgb == CombineFunc::Dot3Rgba {
                return [d; 4];
            }
            let n_a = uses(k.alpha);
            let (b0, b1, b2) = (
                arg_alpha(0),
                if n_a > 1 { arg_alpha(1) } else { 0.0 },
                if n_a > 2 { arg_alpha(2) } else { 0.0 },
            );
            [d, d, d, clamp01(f3(k.alpha, b0, b1, b2) * k.alpha_scale)]
        }
        f => {
            let n_a = uses(k.alpha);
            let (b0, b1, b2) = (
                arg_alpha(0),
                if n_a > 1 { arg_alpha(1) } else { 0.0 },
                if n_a > 2 { arg_alpha(2) } else { 0.0 },
            );
            [
                clamp01(f3(f, a0[0], a1[0], a2[0]) * s),
                clamp01(f3(f, a0[1], a1[1], a2[1]) * s),
                clamp01(f3(f, a0[2], a1[2], a2[2]) * s),
                clamp01(f3(k.alpha, b0, b1, b2) * k.alpha_scale),
            ]
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn env(mode: EnvMode) -> TexEnv {
        TexEnv {
            mode,
            color: [0.25, 0.5, 0.75, 1.0],
        }
    }

    const CF: [f32; 4] = [0.5, 0.25, 1.0, 0.5];
    const TEX: [f32; 4] = [1.0, 0.5, 0.0, 0.25];

    #[test]
    fn basic_modes_follow_the_format_tables() {
        use BaseFormat as F;
        // REPLACE: RGBA (Cs, As); RGB (Cs, Af); A (Cf, As).
        assert_eq!(apply(&env(EnvMode::Replace), F::Rgba, TEX, CF, CF), TEX);
        assert_eq!(
            apply(&env(EnvMode::Replace), F::Rgb, [1.0, 0.5, 0.0, 1.0], CF, CF),
            [1.0, 0.5, 0.0, 0.5]
        );
        assert_eq!(
            apply(
                &env(EnvMode::Replace),
                F::Alpha,
                [0.0, 0.0, 0.0, 0.25],
                CF,
                CF
            ),
            [0.5, 0.25, 1.0, 0.25]
        );
        // MODULATE: RGBA (Cf·Cs, Af·As); L (Cf·L, Af).
        assert_eq!(
            apply(&env(EnvMode::Modulate), F::Rgba, TEX, CF, CF),
            [0.5, 0.125, 0.0, 0.125]
        );
        assert_eq!(
            apply(
                &env(EnvMode::Modulate),
                F::Luminance,
                [0.5, 0.5, 0.5, 1.0],
                CF,
                CF
            ),
            [0.25, 0.125, 0.5, 0.5]
        );
        // DECAL RGBA: Cf(1 − As) + Cs·As, Af.
        let d = apply(&env(EnvMode::Decal), F::Rgba, TEX, CF, CF);
        assert_eq!(d, [0.625, 0.3125, 0.75, 0.5]);
        // BLEND: Cf(1 − Cs) + Cc·Cs, Af·As.
        let b = apply(&env(EnvMode::Blend), F::Rgba, TEX, CF, CF);
        assert_eq!(b, [0.25, 0.375, 1.0, 0.125]);
        // ADD: Cf + Cs clamped, Af·As.
        let a = apply(&env(EnvMode::Add), F::Rgba, TEX, CF, CF);
        assert_eq!(a, [1.0, 0.75, 1.0, 0.125]);
        // LA under BLEND: alpha multiplies.
        let la = apply(
            &env(EnvMode::Blend),
            F::LuminanceAlpha,
            [1.0, 1.0, 1.0, 0.5],
            CF,
            CF,
        );
        assert_eq!(la, [0.25, 0.5, 0.75, 0.25]);
    }

    #[test]
    fn combine_functions_operands_and_scales() {
        let k = |rgb, alpha| Combine {
            rgb,
            alpha,
            src_rgb: [Source::Texture, Source::Previous, Source::Constant],
            src_alpha: [Source::Texture, Source::Previous, Source::Constant],
            operand_rgb: [Operand::SrcColor, Operand::SrcColor, Operand::SrcAlpha],
            operand_alpha: [Operand::SrcAlpha; 3],
            rgb_scale: 1.0,
            alpha_scale: 1.0,
        };
        let e = |c: Combine| env(EnvMode::Combine(c));
        let f = BaseFormat::Rgba;
        let r = apply(
            &e(k(CombineFunc::AddSigned, CombineFunc::Subtract)),
            f,
            TEX,
            CF,
            CF,
        );
        assert_eq!(r, [1.0, 0.25, 0.5, 0.0]);
        // INTERPOLATE with a2 = constant alpha (1): a0.
        let r = apply(
            &e(k(CombineFunc::Interpolate, CombineFunc::Interpolate)),
            f,
            TEX,
            CF,
            CF,
        );
        assert_eq!(r, TEX);
        let mut c = k(CombineFunc::Modulate, CombineFunc::Add);
        c.rgb_scale = 4.0;
        c.alpha_scale = 2.0;
        c.operand_rgb[1] = Operand::OneMinusSrcColor;
        let r = apply(&e(c), f, TEX, CF, CF);
        assert_eq!(r, [1.0, 1.0, 0.0, 1.0]);
        // DOT3_RGBA of a vector with itself: 4·Σ(c − ½)² = 4·(¼ + 0 + ¼) = 2 → 1.
        let r = apply(
            &e(k(CombineFunc::Dot3Rgba, CombineFunc::Replace)),
            f,
            TEX,
            TEX,
            CF,
        );
        assert_eq!(r, [1.0; 4]);
        let r = apply(
            &e(k(CombineFunc::Dot3Rgb, CombineFunc::Replace)),
            f,
            [0.5, 0.5, 0.75, 0.25],
            [0.5, 0.5, 0.75, 0.5],
            CF,
        );
        assert_eq!(r, [0.25, 0.25, 0.25, 0.25]);
    }

    #[test]
    fn fog_factors() {
        let mut fog = Fog {
            mode: FogMode::Linear,
            density: 0.5,
            start: 2.0,
            end: 6.0,
            color: [1.0; 4],
            quality: Quality::Nicest,
        };
        assert_eq!(fog.factor(4.0), 0.5);
        assert_eq!(fog.factor(10.0), 0.0);
        assert_eq!(fog.factor(0.0), 1.0);
        fog.mode = FogMode::Exp;
        assert!((fog.factor(2.0) - (-1.0f32).exp()).abs() < 1e-6);
        fog.mode = FogMode::Exp2;
        assert!((fog.factor(2.0) - (-1.0f32).exp()).abs() < 1e-6);
        let mut c = [0.0, 0.5, 1.0, 0.25];
        fog.apply(0.5, &mut c);
        assert_eq!(c, [0.5, 0.75, 1.0, 0.25]);
    }
}
