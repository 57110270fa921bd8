//! Reference texturing and fog, literal and in f64 (ES 1.1 §3.7.7-3.7.13, §3.8),
//! independent of `core::texture`'s sampling and `core::texenv`: coordinates wrapped by the
//! specification's formulas (REPEAT takes the fraction, CLAMP_TO_EDGE clamps to
//! [1/2N, 1 − 1/2N], MIRRORED_REPEAT mirrors odd periods), λ = log₂ ρ with ρ from the exact
//! derivatives of s/q and t/q at the pixel, plus the `EXT_texture_lod_bias` bias, the
//! environment tables written out, and fog per pixel from the interpolated |z_eye|.

use glam::DVec4;

use crate::state::RenderState;
use crate::texenv::{CombineFunc, EnvMode, FogMode, Operand, Source, TexEnv};
use crate::texture::{BaseFormat, Image, MagFilter, MinFilter, Sampler, Wrap};

/// Texture coordinates (s, t, q already combined: s/q, t/q) and their window-space
/// derivatives at one pixel, for one unit.
#[derive(Clone, Copy, Debug)]
pub struct Coords {
    pub s: f64,
    pub t: f64,
    pub ds_dx: f64,
    pub dt_dx: f64,
    pub ds_dy: f64,
    pub dt_dy: f64,
    /// For a cube map, the face (0 ..= 5: POSITIVE_X .. NEGATIVE_Z) the coordinates are in.
    pub face: Option<usize>,
}

/// Cube map coordinates (`OES_texture_cube_map`) from the direction (s, t, r) at the
/// pixel and at its right and upper neighbours, each given as values linear in window
/// space (any common factor such as 1/w or q cancels): the face from the table (the largest
/// magnitude, ties to x then y), ((sc/|ma| + 1)/2, (tc/|ma| + 1)/2) and their exact
/// derivatives by the quotient rule, in the pixel's face.
pub fn cube_coords(d0: [f64; 3], dx: [f64; 3], dy: [f64; 3]) -> Coords {
    let [x, y, z] = d0;
    let (ax, ay, az) = (x.abs(), y.abs(), z.abs());
    // (face, sc, tc, ma) as (component index, sign) pairs.
    let (face, sc, tc, ma) = if ax >= ay && ax >= az {
        if x >= 0.0 {
            (0, (2, -1.0), (1, -1.0), 0)
        } else {
            (1, (2, 1.0), (1, -1.0), 0)
        }
    } else if ay >= az {
        if y >= 0.0 {
            (2, (0, 1.0), (2, 1.0), 1)
        } else {
            (3, (0, 1.0), (2, -1.0), 1)
        }
    } else if z >= 0.0 {
        (4, (0, 1.0), (1, -1.0), 2)
    } else {
        (5, (0, -1.0), (1, -1.0), 2)
    };
    let sign = d0[ma].signum();
    let at = |d: &[f64; 3], (i, k): (usize, f64)| d[i] * k;
    let coord = |c: (usize, f64)| {
        let (n0, m0) = (at(&d0, c), d0[ma] * sign);
        let v = 0.5 * (n0 / m0 + 1.0);
        let der = |d: &[f64; 3]| {
            let (dn, dm) = (at(d, c) - n0, d[ma] * sign - m0);
            0.5 * (dn * m0 - n0 * dm) / (m0 * m0)
        };
        (v, der(&dx), der(&dy))
    };
    let (s, ds_dx, ds_dy) = coord(sc);
    let (t, dt_dx, dt_dy) = coord(tc);
    Coords {
        s,
        t,
        ds_dx,
        dt_dx,
        ds_dy,
        dt_dy,
        face: Some(face),
    }
}

/// The wrapped coordinate in [0, 1] (spec formulas, before the texel lookup).
fn wrap(w: Wrap, c: f64, n: f64) -> f64 {
    match w {
        Wrap::Repeat => c - c.floor(),
        Wrap::ClampToEdge => c.clamp(0.5 / n, 1.0 - 0.5 / n),
        Wrap::MirroredRepeat => {
            let f = c - c.floor();
            if (c.floor() as i64).rem_euclid(2) == 0 {
                f
            } else {
                1.0 - f
            }
        }
    }
}

/// Texel index i from a texel-space value u in a level of n texels, with the wrap mode
/// applied to indices (as the specification does for LINEAR's i0, i1).
pub(crate) fn index(w: Wrap, i: i64, n: i64) -> usize {
    (match w {
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
    }) as usize
}

fn texel(img: &Image, i: usize, j: usize) -> DVec4 {
    let b = img.texels[j * img.width as usize + i].to_le_bytes();
    DVec4::new(b[0] as f64, b[1] as f64, b[2] as f64, b[3] as f64) / 255.0
}

fn nearest(sm: &Sampler, img: &Image, s: f64, t: f64) -> DVec4 {
    let (w, h) = (img.width as f64, img.height as f64);
    let u = wrap(sm.wrap_s, s, w) * w;
    let v = wrap(sm.wrap_t, t, h) * h;
    // u = N exactly (s = 1 under REPEAT cannot happen; CLAMP stops short) picks N − 1.
    let i = (u.floor() as i64).min(img.width as i64 - 1);
    let j = (v.floor() as i64).min(img.height as i64 - 1);
    texel(img, i as usize, j as usize)
}

fn linear(sm: &Sampler, img: &Image, s: f64, t: f64) -> DVec4 {
    let (w, h) = (img.width as i64, img.height as i64);
    // For REPEAT the fraction is taken first; the neighbours then wrap by index.
    let ws = if sm.wrap_s == Wrap::ClampToEdge {
        s
    } else {
        wrap(sm.wrap_s, s, w as f64)
    };
    let wt = if sm.wrap_t == Wrap::ClampToEdge {
        t
    } else {
        wrap(sm.wrap_t, t, h as f64)
    };
    let u = ws * w as f64 - 0.5;
    let v = wt * h as f64 - 0.5;
    let (i0, j0) = (u.floor() as i64, v.floor() as i64);
    let (a, b) = (u - u.floor(), v - v.floor());
    let (i1, j1) = (i0 + 1, j0 + 1);
    let (ws_, wt_) = (sm.wrap_s, sm.wrap_t);
    let t00 = texel(img, index(ws_, i0, w), index(wt_, j0, h));
    let t10 = texel(img, index(ws_, i1, w), index(wt_, j0, h));
    let t01 = texel(img, index(ws_, i0, w), index(wt_, j1, h));
    let t11 = texel(img, index(ws_, i1, w), index(wt_, j1, h));
    t00 * ((1.0 - a) * (1.0 - b)) + t10 * (a * (1.0 - b)) + t01 * ((1.0 - a) * b) + t11 * (a * b)
}

/// The filtered value of `sm` at `c` (ES 1.1 §3.7.7-3.7.8), in [0, 1].
pub fn sample(sm: &Sampler, c: &Coords) -> DVec4 {
    let (w, h) = (sm.levels[0].width as f64, sm.levels[0].height as f64);
    let px = ((c.ds_dx * w).powi(2) + (c.dt_dx * h).powi(2)).sqrt();
    let py = ((c.ds_dy * w).powi(2) + (c.dt_dy * h).powi(2)).sqrt();
    if sm.max_anisotropy > 1.0 && sm.cube.is_none() {
        // EXT_texture_filter_anisotropic's suggested filter: N samples along the long axis
        // of the footprint, each with the level of detail of P_max / N.
        let (major, minor, ds, dt) = if px >= py {
            (px, py, c.ds_dx, c.dt_dx)
        } else {
            (py, px, c.ds_dy, c.dt_dy)
        };
        let ratio = (major / minor).ceil();
        let n = if ratio >= 1.0 {
            ratio.min(sm.max_anisotropy.floor() as f64)
        } else {
            1.0
        };
        let sum: DVec4 = (1..=n as usize)
            .map(|k| {
                let o = k as f64 / (n + 1.0) - 0.5;
                let at = Coords {
                    s: c.s + ds * o,
                    t: c.t + dt * o,
                    ..*c
                };
                sample_lod(sm, &at, (major / n).log2())
            })
            .sum();
        return sum / n;
    }
    sample_lod(sm, c, px.max(py).log2())
}

/// [`sample`] at level of detail `lambda` before the bias.
fn sample_lod(sm: &Sampler, c: &Coords, lambda: f64) -> DVec4 {
    // EXT_texture_lod_bias: the unit's bias (clamped when it was set) before everything.
    let lambda = lambda + sm.lod_bias as f64;
    let cswitch = if sm.mag == MagFilter::Linear
        && matches!(
            sm.min,
            MinFilter::NearestMipmapNearest | MinFilter::NearestMipmapLinear
        ) {
        0.5
    } else {
        0.0
    };
    let f = |linear_filter: bool, level: usize| {
        let img = &sm.levels[level];
        if linear_filter {
            linear(sm, img, c.s, c.t)
        } else {
            nearest(sm, img, c.s, c.t)
        }
    };
    if lambda.is_nan() || lambda <= cswitch {
        return f(sm.mag == MagFilter::Linear, 0);
    }
    let q = (sm.levels.len() - 1) as f64;
    match sm.min {
        MinFilter::Nearest => f(false, 0),
        MinFilter::Linear => f(true, 0),
        MinFilter::NearestMipmapNearest | MinFilter::LinearMipmapNearest => {
            let d = if lambda <= 0.5 {
                0.0
            } else {
                ((lambda + 0.5).ceil() - 1.0).min(q)
            };
            f(sm.min == MinFilter::LinearMipmapNearest, d as usize)
        }
        MinFilter::NearestMipmapLinear | MinFilter::LinearMipmapLinear => {
            let lin = sm.min == MinFilter::LinearMipmapLinear;
            if lambda >= q {
                return f(lin, q as usize);
            }
            let d1 = lambda.floor();
            let frac = lambda - d1;
            f(lin, d1 as usize) * (1.0 - frac) + f(lin, d1 as usize + 1) * frac
        }
    }
}

fn clamp01(v: DVec4) -> DVec4 {
    v.clamp(DVec4::ZERO, DVec4::ONE)
}

/// Table 3.15-3.18 of ES 1.1: the environment `env` for texel `cs` of `format`, applied
/// to the previous color `cf`; `cp` is the primary color, `units[n]` unit `n`'s texel
/// (`OES_texture_env_crossbar`).
pub fn env(
    env: &TexEnv,
    format: BaseFormat,
    cs: DVec4,
    cf: DVec4,
    cp: DVec4,
    units: &[Option<DVec4>],
) -> DVec4 {
    let cc = DVec4::from_array(env.color.map(f64::from));
    let rgb = |v: DVec4| v.truncate();
    let out = |c: glam::DVec3, a: f64| clamp01(c.extend(a));
    let (l, a_only) = (format.has_color(), !format.has_color());
    let has_a = format.has_alpha();
    match env.mode {
        EnvMode::Replace => match (a_only, has_a) {
            (true, _) => out(rgb(cf), cs.w),
            (false, true) => out(rgb(cs), cs.w),
            (false, false) => out(rgb(cs), cf.w),
        },
        EnvMode::Modulate => {
            let c = if l { rgb(cf) * rgb(cs) } else { rgb(cf) };
            out(c, if has_a { cf.w * cs.w } else { cf.w })
        }
        EnvMode::Decal => match format {
            BaseFormat::Rgb => out(rgb(cs), cf.w),
            BaseFormat::Rgba => out(rgb(cf) * (1.0 - cs.w) + rgb(cs) * cs.w, cf.w),
            _ => cf,
        },
        EnvMode::Blend => {
            let c = if l {
                rgb(cf) * (glam::DVec3::ONE - rgb(cs)) + rgb(cc) * rgb(cs)
            } else {
                rgb(cf)
            };
            out(c, if has_a { cf.w * cs.w } else { cf.w })
        }
        EnvMode::Add => {
            let c = if l { rgb(cf) + rgb(cs) } else { rgb(cf) };
            out(c, if has_a { cf.w * cs.w } else { cf.w })
        }
        EnvMode::Combine(k) => {
            let src = |s: Source| match s {
                Source::Texture => cs,
                Source::Constant => cc,
                Source::PrimaryColor => cp,
                Source::Previous => cf,
                Source::Unit(u) => units.get(usize::from(u)).copied().flatten().unwrap_or(cf),
            };
            let arg = |n: usize| {
                let c = src(k.src_rgb[n]);
                match k.operand_rgb[n] {
                    Operand::SrcColor => rgb(c),
                    Operand::OneMinusSrcColor => glam::DVec3::ONE - rgb(c),
                    Operand::SrcAlpha => glam::DVec3::splat(c.w),
                    Operand::OneMinusSrcAlpha => glam::DVec3::splat(1.0 - c.w),
                }
            };
            let arg_a = |n: usize| {
                let c = src(k.src_alpha[n]);
                match k.operand_alpha[n] {
                    Operand::OneMinusSrcAlpha | Operand::OneMinusSrcColor => 1.0 - c.w,
                    _ => c.w,
                }
            };
            let f = |func: CombineFunc, a0: f64, a1: f64, a2: f64| match func {
                CombineFunc::Replace => a0,
                CombineFunc::Modulate => a0 * a1,
                CombineFunc::Add => a0 + a1,
                CombineFunc::AddSigned => a0 + a1 - 0.5,
                CombineFunc::Interpolate => a0 * a2 + a1 * (1.0 - a2),
                CombineFunc::Subtract => a0 - a1,
                CombineFunc::Dot3Rgb | CombineFunc::Dot3Rgba => f64::NAN,
            };
            let (a0, a1, a2) = (arg(0), arg(1), arg(2));
            let alpha = f(k.alpha, arg_a(0), arg_a(1), arg_a(2)) * k.alpha_scale as f64;
            let s = k.rgb_scale as f64;
            match k.rgb {
                CombineFunc::Dot3Rgb | CombineFunc::Dot3Rgba => {
                    let d = 4.0 * (a0 - 0.5).dot(a1 - 0.5) * s;
                    let a = if k.rgb == CombineFunc::Dot3Rgba {
                        d
                    } else {
                        alpha
                    };
                    clamp01(DVec4::new(d, d, d, a))
                }
                func => clamp01(DVec4::new(
                    f(func, a0.x, a1.x, a2.x) * s,
                    f(func, a0.y, a1.y, a2.y) * s,
                    f(func, a0.z, a1.z, a2.z) * s,
                    alpha,
                )),
            }
        }
    }
}

/// Every enabled unit in order, then fog at eye distance `z_eye` (|z| of eye space).
pub fn shade(state: &RenderState, primary: DVec4, coords: &[Option<Coords>], z_eye: f64) -> DVec4 {
    // Every texel first: a crossbar environment reads later units' texels too.
    let texels: Vec<Option<DVec4>> = state
        .textures
        .iter()
        .enumerate()
        .map(|(u, unit)| {
            let (Some(unit), Some(Some(co))) = (unit, coords.get(u)) else {
                return None;
            };
            Some(match (co.face, &unit.sampler.cube) {
                (Some(f), Some(faces)) => sample(&faces[f], co),
                _ => sample(&unit.sampler, co),
            })
        })
        .collect();
    let mut c = primary;
    for (unit, cs) in state.textures.iter().zip(&texels) {
        if let (Some(unit), Some(cs)) = (unit, cs) {
            c = env(&unit.env, unit.sampler.format, *cs, c, primary, &texels);
        }
    }
    if let Some(fog) = &state.fog {
        let z = z_eye.abs();
        let f = match fog.mode {
            FogMode::Linear => (fog.end as f64 - z) / (fog.end as f64 - fog.start as f64),
            FogMode::Exp => (-(fog.density as f64) * z).exp(),
            FogMode::Exp2 => (-(fog.density as f64 * z).powi(2)).exp(),
        };
        let f = if f.is_nan() { 0.0 } else { f.clamp(0.0, 1.0) };
        let fc = DVec4::from_array(fog.color.map(f64::from));
        c = (c * f + fc * (1.0 - f)).with_w(c.w);
    }
    c
}
