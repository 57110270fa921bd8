//! The lighting equation of ES 1.1 §2.12.1 (the GL 1.5 equation without local viewer,
//! secondary color or separate specular), per vertex in eye space:
//!
//! ```text
//! c = e_cm + a_cm·a_cs
//!   + Σ_i att_i · spot_i · ( a_cm·a_cli + (n ⊙ VP̂_i)·d_cm·d_cli + f_i·(n ⊙ ĥ_i)^s_rm·s_cm·s_cli )
//! ```
//!
//! The per-light ambient term sits inside att·spot, as the specification writes it (the
//! book's Eq. 3.3 places it outside). `x ⊙ y` is max(x·y, 0); n is the eye-space normal as
//! transformed (unit only with `GL_NORMALIZE`, or `GL_RESCALE_NORMAL` under a uniform scale);
//! VP̂ is the unit vector from the vertex to the light (the light's direction when its w is
//! 0); ĥ = normalize(VP̂ + (0, 0, 1)) (the viewer at infinity); f_i is 1 when n ⊙ VP̂ ≠ 0 and
//! 0 otherwise; (n ⊙ ĥ)^0 is 1, 0⁰ included. Alpha is the diffuse material's alpha. Each
//! channel is clamped to [0, 1] (or only to [0, ∞) when `clamp_after_lighting` is off).
//!
//! - att = 1 for directional lights, else 1 / (k_c + k_l·d + k_q·d²). A **zero denominator**
//!   (all three coefficients may be 0, and k_c = 0 with the vertex on the light) counts as
//!   the largest finite float: every nonzero contribution of that light saturates its
//!   channel, zero contributions stay zero, and nothing is NaN or infinite.
//! - spot = 1 when the cutoff is 180; otherwise (P̂V·ŝ)^exponent when P̂V·ŝ ≥ cos(cutoff),
//!   else 0 (P̂V the unit vector from the light to the vertex, ŝ the unit spot direction).
//!   A cutoff of exactly 90 uses cos = 0, so the half-space in front of the light is lit.
//! - A light or vertex with w ∉ {0, 1} is divided by its w first (a vertex with w = 0 is
//!   taken as is).
//! - `GL_COLOR_MATERIAL` makes the vertex color the ambient and diffuse material color.
//! - The back color (two-sided lighting) is the same equation with −n and the back material.

use glam::{Vec3, Vec4};

use super::power::{pow, pow_lanes};
use crate::lanes::{max_ps, min_ps, Lane, LANES};
use crate::state::{Light, Lighting, Material};

/// A light with what does not depend on the vertex worked out.
#[derive(Clone, Copy, Debug)]
struct Prepared1 {
    light: Light,
    /// Directional: the unit direction to the light and the unit half vector.
    directional: Option<(Vec3, Vec3)>,
    /// Positional: the light's position divided by its w.
    position: Vec3,
    /// Spot lights: the unit spot direction and the cosine of the cutoff.
    spot: Option<(Vec3, f32)>,
    /// Per face (front, back): the material-times-light products. The ambient and diffuse
    /// ones are only used without color material (the vertex color replaces the material
    /// then). They are the leftmost factors of the equation's products, so computing them
    /// once rounds exactly as computing them per vertex.
    ambient: [Vec4; 2],
    diffuse: [Vec4; 2],
    specular: [Vec4; 2],
    /// Per face: the specular product is exactly zero in r, g and b (alpha is never read:
    /// the lit alpha is the diffuse one) and the shininess is in (0, 64], so for n ⊙ ĥ ≤ 2
    /// the power is finite and `0 · power` equals `0 · 1` bit for bit: `powf` can be
    /// skipped.
    pow_free: [bool; 2],
}

/// One face's material with what does not depend on the vertex worked out.
#[derive(Clone, Copy, Debug)]
struct Face {
    material: Material,
    /// e_cm + a_cm·a_cs, used without color material.
    base: Vec4,
}

/// The lighting state of one draw call, ready to light vertices.
#[derive(Clone, Debug)]
pub struct Prepared {
    lights: Vec<Prepared1>,
    model_ambient: Vec4,
    faces: [Face; 2],
    color_material: bool,
    /// The upper bound of a lit channel: 1, or the largest float when lit colors are not
    /// clamped after lighting.
    ceiling: f32,
    /// See [`reads_position`](Self::reads_position); asked per group of vertices, so
    /// derived once.
    reads_position: bool,
}

/// The cosine of a spot cutoff in degrees, exact at 90.
pub fn cos_cutoff(degrees: f32) -> f32 {
    if degrees == 90.0 {
        0.0
    } else {
        (degrees as f64).to_radians().cos() as f32
    }
}

impl Prepared {
    pub fn new(l: &Lighting) -> Prepared {
        let lights: Vec<Prepared1> = l
            .lights
            .iter()
            .map(|light| {
                let p = light.position;
                let directional = (p.w == 0.0).then(|| {
                    let vp = p.truncate().normalize_or_zero();
                    (vp, (vp + Vec3::Z).normalize_or_zero())
                });
                let position = if p.w == 0.0 || p.w == 1.0 {
                    p.truncate()
                } else {
                    p.truncate() / p.w
                };
                let spot = (light.spot_cutoff != 180.0).then(|| {
                    (
                        light.spot_direction.normalize_or_zero(),
                        cos_cutoff(light.spot_cutoff),
                    )
                });
                let faces = [&l.front, &l.back];
                let pow_free = faces.map(|m| {
                    (m.specular * light.specular).truncate() == Vec3::ZERO
                        && m.shininess > 0.0
                        && m.shininess <= 64.0
                });
                Prepared1 {
                    light: *light,
                    directional,
                    position,
                    spot,
                    ambient: faces.map(|m| m.ambient * light.ambient),
                    diffuse: faces.map(|m| m.diffuse * light.diffuse),
                    specular: faces.map(|m| m.specular * light.specular),
                    pow_free,
                }
            })
            .collect();
        let face = |m: &Material| Face {
            material: *m,
            base: m.emission + m.ambient * l.model_ambient,
        };
        let reads_position = lights
            .iter()
            .any(|pl| pl.directional.is_none() || pl.spot.is_some());
        Prepared {
            reads_position,
            lights,
            model_ambient: l.model_ambient,
            faces: [face(&l.front), face(&l.back)],
            color_material: l.color_material,
            ceiling: if l.clamp_after_lighting {
                1.0
            } else {
                f32::MAX
            },
        }
    }

    /// Some light depends on the vertex position (a positional or spot light), so
    /// [`shade_lanes`](Self::shade_lanes) reads the eye positions.
    pub fn reads_position(&self) -> bool {
        self.reads_position
    }

    /// [`shade`](Self::shade) for `LANES` vertices at once, structure of arrays (eye
    /// positions `eye[axis][lane]`, read only when [`reads_position`](Self::reads_position),
    /// normals `n[axis][lane]`, colors `color[channel][lane]`), so the lanes vectorize. The
    /// operations and their order are `shade`'s (glam's `Vec3` arithmetic written out per
    /// component), so the results are bit for bit the same; for a directional light that is
    /// not a spot light the factor att·spot is exactly 1 and left out, and `max`/`min`
    /// where `shade` uses vector ones follow their NaN rule (the second operand wins).
    #[inline(always)]
    pub fn shade_lanes(
        &self,
        eye: &[Lane<f32>; 4],
        n: &[Lane<f32>; 3],
        color: &[Lane<f32>; 4],
        back: bool,
    ) -> [Lane<f32>; 4] {
        let f = usize::from(back);
        let face = &self.faces[f];
        let m = &face.material;
        let mut c = [[0.0; LANES]; 4];
        if self.color_material {
            let (e, a) = (m.emission.to_array(), self.model_ambient.to_array());
            for ch in 0..3 {
                for k in 0..LANES {
                    c[ch][k] = e[ch] + color[ch][k] * a[ch];
                }
            }
        } else {
            let base = face.base.to_array();
            for ch in 0..3 {
                c[ch] = [base[ch]; LANES];
            }
        }
        for pl in &self.lights {
            match pl.directional {
                // The common case: the same vectors for every lane, att·spot exactly 1.
                Some((vp, h)) if pl.spot.is_none() => {
                    self.add_light(pl, f, n, color, &vp, &h, None, &mut c)
                }
                _ => add_light_seen_from(self, pl, f, eye, n, color, &mut c),
            }
        }
        c[3] = if self.color_material {
            color[3]
        } else {
            [m.diffuse.w; LANES]
        };
        for ch in c.iter_mut() {
            for v in ch.iter_mut() {
                *v = min_ps(max_ps(*v, 0.0), self.ceiling);
            }
        }
        c
    }

    /// Adds light `pl`'s term for face `f` to `c`, lane by lane, as `shade` does: `vp` and
    /// `h` are the unit vector to the light and the half vector, `k` att·spot (`None`: 1).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn add_light<D: Direction>(
        &self,
        pl: &Prepared1,
        f: usize,
        n: &[Lane<f32>; 3],
        color: &[Lane<f32>; 4],
        vp: &D,
        h: &D,
        k: Option<&Lane<f32>>,
        c: &mut [Lane<f32>; 4],
    ) {
        let l = &pl.light;
        let m = &self.faces[f].material;
        let mut ndotvp = [0.0; LANES];
        let mut ndoth = [0.0; LANES];
        for j in 0..LANES {
            ndotvp[j] =
                (n[0][j] * vp.at(0, j) + n[1][j] * vp.at(1, j) + n[2][j] * vp.at(2, j)).max(0.0);
            ndoth[j] =
                (n[0][j] * h.at(0, j) + n[1][j] * h.at(1, j) + n[2][j] * h.at(2, j)).max(0.0);
        }
        let mut sum = [[0.0; LANES]; 3];
        if self.color_material {
            let (la, ld) = (l.ambient.to_array(), l.diffuse.to_array());
            for ch in 0..3 {
                for j in 0..LANES {
                    sum[ch][j] = color[ch][j] * la[ch] + color[ch][j] * ld[ch] * ndotvp[j];
                }
            }
        } else {
            let (pa, pd) = (pl.ambient[f].to_array(), pl.diffuse[f].to_array());
            for ch in 0..3 {
                for j in 0..LANES {
                    sum[ch][j] = pa[ch] + pd[ch] * ndotvp[j];
                }
            }
        }
        // The powers, computed in every lane and kept where `shade` computes one.
        let mut power = [1.0; LANES];
        if m.shininess != 0.0 {
            let p = pow_lanes(&ndoth, m.shininess);
            for j in 0..LANES {
                if ndotvp[j] != 0.0 && !(pl.pow_free[f] && ndoth[j] <= 2.0) {
                    power[j] = p[j];
                }
            }
        }
        let s = pl.specular[f].to_array();
        for ch in 0..3 {
            for j in 0..LANES {
                let mut lit = if ndotvp[j] != 0.0 {
                    sum[ch][j] + s[ch] * power[j]
                } else {
                    sum[ch][j]
                };
                if let Some(k) = k {
                    // `shade` skips a light whose att·spot is 0 or NaN.
                    if k[j] == 0.0 || k[j].is_nan() {
                        continue;
                    }
                    lit *= k[j];
                }
                c[ch][j] += min_ps(max_ps(lit, -f32::MAX), f32::MAX);
            }
        }
    }

    /// The lit color of a vertex at eye position `eye` with eye-space normal `n` (already
    /// reversed for the back face) and vertex color `color`; `back` picks the back material.
    #[inline(always)]
    pub fn shade(&self, eye: Vec4, n: Vec3, color: Vec4, back: bool) -> Vec4 {
        let f = usize::from(back);
        let face = &self.faces[f];
        let m = &face.material;
        let v = if eye.w == 0.0 || eye.w == 1.0 {
            eye.truncate()
        } else {
            eye.truncate() / eye.w
        };
        let mut c = if self.color_material {
            m.emission + color * self.model_ambient
        } else {
            face.base
        };
        for pl in &self.lights {
            let l = &pl.light;
            let (vp, h, att) = match pl.directional {
                Some((vp, h)) => (vp, h, 1.0),
                None => {
                    let d = pl.position - v;
                    let dist = d.length();
                    let vp = if dist > 0.0 && dist.is_finite() {
                        d / dist
                    } else {
                        d.normalize_or_zero()
                    };
                    let [kc, kl, kq] = l.attenuation;
                    let denom = kc + kl * dist + kq * dist * dist;
                    let att = if denom > 0.0 { 1.0 / denom } else { f32::MAX };
                    (vp, (vp + Vec3::Z).normalize_or_zero(), att)
                }
            };
            let spot = match pl.spot {
                None => 1.0,
                Some((s, cos)) => {
                    let dot = (-vp).dot(s);
                    if dot >= cos {
                        pow(dot.max(0.0), l.spot_exponent)
                    } else {
                        0.0
                    }
                }
            };
            let k = att * spot;
            if k == 0.0 || k.is_nan() {
                continue;
            }
            let ndotvp = n.dot(vp).max(0.0);
            let (ambient, diffuse) = if self.color_material {
                (color * l.ambient, color * l.diffuse)
            } else {
                (pl.ambient[f], pl.diffuse[f])
            };
            let mut sum = ambient + diffuse * ndotvp;
            if ndotvp != 0.0 {
                let ndoth = n.dot(h).max(0.0);
                // x⁰ is 1 for every x, NaN and ∞ included, as powf defines it.
                let power = if m.shininess == 0.0 || (pl.pow_free[f] && ndoth <= 2.0) {
                    1.0
                } else {
                    pow(ndoth, m.shininess)
                };
                sum += pl.specular[f] * power;
            }
            let term = sum * k;
            // A saturating light (zero denominator) stays finite, so lights of opposite
            // sign cannot meet as ∞ − ∞.
            c += term.max(Vec4::splat(-f32::MAX)).min(Vec4::splat(f32::MAX));
        }
        let alpha = if self.color_material {
            color.w
        } else {
            m.diffuse.w
        };
        let c = c.truncate().extend(alpha);
        // max/min rather than clamp: NaN (from NaN inputs) becomes 0.
        c.max(Vec4::ZERO).min(Vec4::splat(self.ceiling))
    }
}

/// A light's direction (or half vector) as the lanes read it: one vector for every lane,
/// or one per lane.
trait Direction {
    fn at(&self, axis: usize, lane: usize) -> f32;
}

impl Direction for Vec3 {
    #[inline(always)]
    fn at(&self, axis: usize, _lane: usize) -> f32 {
        self[axis]
    }
}

impl Direction for [Lane<f32>; 3] {
    #[inline(always)]
    fn at(&self, axis: usize, lane: usize) -> f32 {
        self[axis][lane]
    }
}

/// `Vec3::normalize_or_zero` of one lane's vector, in its order.
#[inline(always)]
fn normalize_or_zero3(v: [f32; 3]) -> [f32; 3] {
    let rcp = 1.0 / (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if rcp.is_finite() && rcp > 0.0 {
        v.map(|x| x * rcp)
    } else {
        [0.0; 3]
    }
}

/// [`Prepared::add_light`] for a positional or spot light, whose vectors and
/// att·spot differ per lane. Kept out of line: inlined, its code made the whole batched
/// vertex loop (`vertex::fill`) worse even for draws that never call it (lit-offscreen,
/// directional lights only, 4 frames: 381.0 M instructions inlined, 370.0 M out of line;
/// lit-point, which calls it, 1 688.8 M against 1 718.7 M). Out of line it is not in
/// `fill`'s AVX2 and SSE4.1 clones, so it has its own (with SSE2's two f64 lanes, the
/// powers took lit-point from 1 718.7 M to 1 773.0 M); every clone rounds exactly alike.
#[cfg_attr(
    not(fuzzing),
    multiversion::multiversion(targets("x86_64+avx2", "x86_64+sse4.1"))
)]
fn add_light_seen_from(
    lighting: &Prepared,
    pl: &Prepared1,
    f: usize,
    eye: &[Lane<f32>; 4],
    n: &[Lane<f32>; 3],
    color: &[Lane<f32>; 4],
    c: &mut [Lane<f32>; 4],
) {
    let (vp, h, k) = light_lanes(pl, eye);
    lighting.add_light(pl, f, n, color, &vp, &h, Some(&k), c);
}

/// Light `pl` seen from each lane's eye position, as [`Prepared::shade`] works it out: the
/// unit vector to the light, the half vector, and att·spot. For positional and spot lights
/// (a directional light that is not a spot light needs none of it).
#[inline(always)]
fn light_lanes(
    pl: &Prepared1,
    eye: &[Lane<f32>; 4],
) -> ([Lane<f32>; 3], [Lane<f32>; 3], Lane<f32>) {
    let mut vp = [[0.0; LANES]; 3];
    let mut h = [[0.0; LANES]; 3];
    let mut k = [1.0; LANES];
    match pl.directional {
        Some((d, hv)) => {
            (vp, h) = (
                [[d.x; LANES], [d.y; LANES], [d.z; LANES]],
                [[hv.x; LANES], [hv.y; LANES], [hv.z; LANES]],
            );
        }
        None => {
            let p = pl.position;
            let [kc, kl, kq] = pl.light.attenuation;
            for j in 0..LANES {
                let w = eye[3][j];
                let v = if w == 0.0 || w == 1.0 {
                    [eye[0][j], eye[1][j], eye[2][j]]
                } else {
                    [eye[0][j] / w, eye[1][j] / w, eye[2][j] / w]
                };
                let d = [p.x - v[0], p.y - v[1], p.z - v[2]];
                let dist = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
                let u = if dist > 0.0 && dist.is_finite() {
                    d.map(|x| x / dist)
                } else {
                    normalize_or_zero3(d)
                };
                let half = normalize_or_zero3([u[0] + 0.0, u[1] + 0.0, u[2] + 1.0]);
                let denom = kc + kl * dist + kq * dist * dist;
                k[j] = if denom > 0.0 { 1.0 / denom } else { f32::MAX };
                for a in 0..3 {
                    vp[a][j] = u[a];
                    h[a][j] = half[a];
                }
            }
        }
    }
    if let Some((s, cos)) = pl.spot {
        let (mut dot, mut base) = ([0.0; LANES], [0.0; LANES]);
        for j in 0..LANES {
            dot[j] = -vp[0][j] * s.x + -vp[1][j] * s.y + -vp[2][j] * s.z;
            base[j] = dot[j].max(0.0);
        }
        let p = pow_lanes(&base, pl.light.spot_exponent);
        for j in 0..LANES {
            k[j] *= if dot[j] >= cos { p[j] } else { 0.0 };
        }
    }
    (vp, h, k)
}

#[cfg(test)]
mod tests {
    use super::super::{AttribArray, ComponentType, DrawCall, Indices, Primitive};
    use super::*;
    use crate::state::RenderState;
    use glam::Mat4;

    fn light0() -> Light {
        Light {
            diffuse: Vec4::ONE,
            specular: Vec4::ONE,
            ..Light::default()
        }
    }

    fn lighting(lights: Vec<Light>) -> Lighting {
        Lighting {
            lights,
            ..Lighting::default()
        }
    }

    /// Lights one vertex at `pos` with normal `n` through the whole vertex stage. The draw
    /// is one triangle of that vertex three times, indexed: a non-indexed draw of one
    /// vertex forms no triangle, so no pixel reads its color and it is not lit.
    fn lit(state: &RenderState, pos: [f32; 3], n: [f32; 3]) -> super::super::ClipVertex {
        let bytes: Vec<u8> = pos.iter().flat_map(|v| v.to_ne_bytes()).collect();
        let mut call = DrawCall::new(
            Primitive::Triangles,
            Indices::U8(&[0, 0, 0]),
            AttribArray {
                data: &bytes,
                ty: ComponentType::Float,
                size: 3,
                stride: 12,
                normalized: false,
            },
        );
        call.normal = super::super::AttribSource::Constant([n[0], n[1], n[2], 0.0]);
        super::super::run(state, &call).unwrap().get(0).unpack()
    }

    fn close(a: Vec4, b: [f32; 4]) {
        assert!(
            (a - Vec4::from_array(b)).abs().max_element() < 1e-5,
            "{a:?} vs {b:?}"
        );
    }

    #[test]
    fn defaults_light_a_facing_vertex_hand_computed() {
        // e + a_cm·a_cs + d_cm·d_cl·(n·l) = 0 + 0.2·0.2 + 0.8·1·1; alpha = d_cm alpha.
        let mut s = RenderState::new(8, 8);
        s.lighting = Some(lighting(vec![light0()]));
        close(
            lit(&s, [0.0; 3], [0.0, 0.0, 1.0]).color,
            [0.84, 0.84, 0.84, 1.0],
        );
        // Facing away: only the global ambient.
        close(
            lit(&s, [0.0; 3], [0.0, 0.0, -1.0]).color,
            [0.04, 0.04, 0.04, 1.0],
        );
    }

    #[test]
    fn per_light_ambient_is_inside_attenuation_and_spot() {
        // The specification's equation, not the book's Eq. 3.3: a light at distance 2 with
        // k_l = 1 halves its own ambient term too.
        let l = Light {
            ambient: Vec4::ONE,
            position: Vec4::new(0.0, 0.0, 2.0, 1.0),
            attenuation: [0.0, 1.0, 0.0],
            ..Light::default()
        };
        let p = Prepared::new(&Lighting {
            model_ambient: Vec4::ZERO,
            ..lighting(vec![l])
        });
        let c = p.shade(Vec4::W, Vec3::Z, Vec4::ONE, false);
        close(c, [0.1, 0.1, 0.1, 1.0]);
    }

    #[test]
    fn spot_cutoff_90_and_180() {
        let spot = |cutoff: f32| Light {
            diffuse: Vec4::ONE,
            position: Vec4::new(0.0, 0.0, 0.0, 1.0),
            spot_direction: Vec3::new(0.0, 0.0, -1.0),
            spot_cutoff: cutoff,
            ..Light::default()
        };
        let shade = |cutoff: f32, v: Vec3, n: Vec3| {
            Prepared::new(&Lighting {
                model_ambient: Vec4::ZERO,
                ..lighting(vec![spot(cutoff)])
            })
            .shade(v.extend(1.0), n, Vec4::ONE, false)
        };
        // Cutoff 90: the half-space in front of the light is lit, behind it is not; the
        // boundary plane itself (P̂V·ŝ = 0 = cos 90°) is inside.
        close(
            shade(90.0, Vec3::new(0.0, 0.0, -1.0), Vec3::Z),
            [0.8, 0.8, 0.8, 1.0],
        );
        close(
            shade(90.0, Vec3::new(0.0, 0.0, 1.0), -Vec3::Z),
            [0.0, 0.0, 0.0, 1.0],
        );
        close(
            shade(90.0, Vec3::new(1.0, 0.0, 0.0), -Vec3::X),
            [0.8, 0.8, 0.8, 1.0],
        );
        // Cutoff 180: no cone at all.
        close(
            shade(180.0, Vec3::new(0.0, 0.0, 1.0), -Vec3::Z),
            [0.8, 0.8, 0.8, 1.0],
        );
        // Exponent: (cos 60°)^2 = 0.25 inside a 70° cone.
        let mut l = spot(70.0);
        l.spot_exponent = 2.0;
        let v = Vec3::new(60f32.to_radians().sin(), 0.0, -60f32.to_radians().cos());
        let c = Prepared::new(&Lighting {
            model_ambient: Vec4::ZERO,
            ..lighting(vec![l])
        })
        .shade(v.extend(1.0), -v, Vec4::ONE, false);
        close(c, [0.2, 0.2, 0.2, 1.0]);
    }

    #[test]
    fn zero_attenuation_denominator_saturates_without_nan() {
        let l = Light {
            diffuse: Vec4::new(1.0, 0.0, 0.0, 1.0),
            position: Vec4::new(0.0, 0.0, 1.0, 1.0),
            attenuation: [0.0, 0.0, 0.0],
            ..Light::default()
        };
        let p = Prepared::new(&lighting(vec![l]));
        let c = p.shade(Vec4::W, Vec3::Z, Vec4::ONE, false);
        close(c, [1.0, 0.04, 0.04, 1.0]);
        // k_c = 0, k_l = 1 and the vertex on the light: d = 0.
        let l = Light {
            attenuation: [0.0, 1.0, 0.0],
            position: Vec4::W,
            ..l
        };
        let c = Prepared::new(&lighting(vec![l])).shade(Vec4::W, Vec3::Z, Vec4::ONE, false);
        assert!(c.is_finite(), "{c:?}");
    }

    #[test]
    fn shininess_zero_gives_zero_to_the_zero_as_one() {
        // n·VP > 0 while n·h = 0: the specular term is s_cm·s_cl·0⁰ = s_cm·s_cl.
        let l = Light {
            specular: Vec4::ONE,
            position: Vec4::new(1.0, 0.0, 0.0, 0.0),
            ..Light::default()
        };
        let n = Vec3::new(1.0, 0.0, -1.0).normalize();
        let mut lt = Lighting {
            model_ambient: Vec4::ZERO,
            ..lighting(vec![l])
        };
        lt.front.specular = Vec4::new(0.5, 0.5, 0.5, 1.0);
        lt.front.diffuse = Vec4::new(0.0, 0.0, 0.0, 1.0);
        close(
            Prepared::new(&lt).shade(Vec4::W, n, Vec4::ONE, false),
            [0.5, 0.5, 0.5, 1.0],
        );
        lt.front.shininess = 10.0;
        close(
            Prepared::new(&lt).shade(Vec4::W, n, Vec4::ONE, false),
            [0.0, 0.0, 0.0, 1.0],
        );
    }

    #[test]
    fn two_sided_back_color_uses_the_reversed_normal() {
        let mut s = RenderState::new(8, 8);
        s.lighting = Some(Lighting {
            two_side: true,
            ..lighting(vec![light0()])
        });
        let v = lit(&s, [0.0; 3], [0.0, 0.0, -1.0]);
        close(v.color, [0.04, 0.04, 0.04, 1.0]);
        close(v.back_color, [0.84, 0.84, 0.84, 1.0]);
    }

    #[test]
    fn color_material_takes_the_vertex_color() {
        let mut s = RenderState::new(8, 8);
        s.lighting = Some(Lighting {
            color_material: true,
            model_ambient: Vec4::ZERO,
            ..lighting(vec![light0()])
        });
        let bytes: Vec<u8> = [0f32; 3].iter().flat_map(|v| v.to_ne_bytes()).collect();
        let mut call = DrawCall::new(
            Primitive::Triangles,
            Indices::U8(&[0, 0, 0]),
            AttribArray {
                data: &bytes,
                ty: ComponentType::Float,
                size: 3,
                stride: 12,
                normalized: false,
            },
        );
        call.color = super::super::AttribSource::Constant([0.5, 0.25, 1.0, 0.5]);
        close(
            super::super::run(&s, &call).unwrap().get(0).color(),
            [0.5, 0.25, 1.0, 0.5],
        );
    }

    #[test]
    fn zero_length_normals_with_normalize_light_only_ambient() {
        let mut s = RenderState::new(8, 8);
        s.lighting = Some(lighting(vec![light0()]));
        s.normalize = true;
        let v = lit(&s, [0.0; 3], [0.0, 0.0, 0.0]);
        close(v.color, [0.04, 0.04, 0.04, 1.0]);
    }

    #[test]
    fn non_uniform_scale_rescale_normal_against_normalize() {
        let mut s = RenderState::new(8, 8);
        s.lighting = Some(lighting(vec![light0()]));
        // Uniform scale 4: RESCALE_NORMAL restores unit normals exactly like NORMALIZE.
        s.modelview = Mat4::from_scale(Vec3::splat(4.0));
        close(
            lit(&s, [0.0; 3], [0.0, 0.0, 1.0]).color,
            [0.24, 0.24, 0.24, 1.0],
        );
        s.rescale_normal = true;
        close(
            lit(&s, [0.0; 3], [0.0, 0.0, 1.0]).color,
            [0.84, 0.84, 0.84, 1.0],
        );
        // Non-uniform (1, 1, 4): a normal tilted 45° in x-z. Its exact eye normal is
        // (1, 0, 1/4)/√2 normalized; NORMALIZE gets n·l = 0.25/|(1, 0, .25)| = 0.2425;
        // RESCALE_NORMAL scales by 4 (the z row) and gets (4, 0, 1)/√2 · z = 0.7071.
        s.modelview = Mat4::from_scale(Vec3::new(1.0, 1.0, 4.0));
        let n = [0.5f32.sqrt(), 0.0, 0.5f32.sqrt()];
        let r = lit(&s, [0.0; 3], n).color.x;
        assert!((r - (0.04 + 0.8 * 0.5f32.sqrt())).abs() < 1e-5, "{r}");
        s.rescale_normal = false;
        s.normalize = true;
        let k = 0.25 / (1.0f32 + 0.0625).sqrt();
        let r = lit(&s, [0.0; 3], n).color.x;
        assert!((r - (0.04 + 0.8 * k)).abs() < 1e-5, "{r}");
    }

    #[test]
    fn singular_modelview_with_lighting_on_and_off() {
        // glScale(2, -2, 0): no inverse. Normals pass through untransformed; positions
        // are flattened; nothing is NaN.
        let mut s = RenderState::new(8, 8);
        s.modelview = Mat4::from_scale(Vec3::new(2.0, -2.0, 0.0));
        let off = lit(&s, [1.0, 1.0, 5.0], [0.0, 0.0, 1.0]);
        assert_eq!(off.pos, Vec4::new(2.0, -2.0, 0.0, 1.0));
        close(off.color, [1.0; 4]);
        s.lighting = Some(lighting(vec![light0()]));
        let on = lit(&s, [1.0, 1.0, 5.0], [0.0, 0.0, 1.0]);
        close(on.color, [0.84, 0.84, 0.84, 1.0]);
        s.normalize = true;
        assert!(lit(&s, [1.0, 1.0, 5.0], [0.0, 0.0, 1.0]).color.is_finite());
    }

    #[test]
    fn huge_positions_stay_finite() {
        let mut s = RenderState::new(8, 8);
        s.lighting = Some(lighting(vec![Light {
            position: Vec4::new(0.0, 0.0, 0.0, 1.0),
            attenuation: [0.0, 0.0, 1.0],
            ..light0()
        }]));
        for e in [20, 24, 31] {
            let big = (1u64 << e) as f32;
            let v = lit(&s, [big, -big, big], [0.0, 0.0, 1.0]);
            assert!(v.pos.is_finite() && v.color.is_finite(), "2^{e}: {v:?}");
        }
    }
}
