//! Vertices through the vertex stage, eight at a time: skinning or the modelview, the
//! projection, the normal transform (inverse transpose, rescale, normalize), lighting,
//! texture coordinates (generated or fetched, then the texture matrix), the derived point
//! size and the user clip distances. [`Stage::new`] derives everything that is constant over a draw call.

#[cfg(test)]
use glam::Vec3;
use glam::{Mat3, Mat4, Vec4};

use super::lighting::Prepared;
use super::window::ViewportTransform;
#[cfg(test)]
use super::ClipVertex;
use super::{AttribArray, AttribSource, DrawCall, Indices, Layout, Primitive, GUARD, W_MIN};
use crate::lanes::{max_ps, min_ps, Lane, LANES};
use crate::state::{RenderState, ShadeModel, TexGen};
use crate::TEXTURE_UNITS;

/// The matrix that takes object-space normals to eye space: the inverse transpose of the
/// upper-left 3 × 3 of `m` (ES 1.1 §2.11.3). A singular matrix (a scale by 0, say) has no
/// inverse; normals then pass through untransformed, so nothing becomes NaN or infinite
/// (Mesa does the same).
pub fn normal_matrix(m: &Mat4) -> Mat3 {
    let m3 = Mat3::from_mat4(*m);
    let det = m3.determinant();
    if det == 0.0 || !det.is_finite() {
        return Mat3::IDENTITY;
    }
    let n = m3.inverse().transpose();
    if n.is_finite() {
        n
    } else {
        Mat3::IDENTITY
    }
}

/// `GL_RESCALE_NORMAL`'s factor for normal matrix `n`: 1 / the length of the third row of
/// the inverse modelview (the third column of its transpose), which undoes a uniform scale.
pub fn rescale_factor(n: &Mat3) -> f32 {
    let len = n.z_axis.length();
    if len > 0.0 && len.is_finite() {
        1.0 / len
    } else {
        1.0
    }
}

/// Where one unit's texture coordinates come from, with the texture matrix left out when
/// it is the identity.
#[derive(Clone, Copy)]
enum TexSource<'d> {
    /// The current value (no array, no texgen): the same for every vertex, so transformed
    /// once per draw, which rounds exactly as transforming it per vertex.
    Constant(Vec4),
    Array(AttribArray<'d>, Option<Mat4>),
    Gen(TexGen, Option<Mat4>),
}

pub(super) struct Stage<'s, 'd> {
    state: &'s RenderState,
    draw: &'d DrawCall<'d>,
    modelview: Mat4,
    projection: Mat4,
    mvp: Mat4,
    normal: Mat3,
    rescale: f32,
    lighting: Option<Prepared>,
    /// The eye-space position is needed (positional or spot lights, fog, user clip
    /// planes, reflection-map texgen, point attenuation, skinning); otherwise the clip
    /// position comes from one product and `eye` is 0.
    need_eye: bool,
    /// Per palette matrix: it and its normal matrix.
    palette: Option<Vec<(Mat4, Mat3)>>,
    tex: [TexSource<'d>; TEXTURE_UNITS],
    attenuate: bool,
    /// An enabled unit's coordinates are generated from the normal (texgen).
    texgen: bool,
    /// An enabled unit's coordinates are a reflection map (texgen).
    reflection: bool,
    /// What each vertex keeps.
    pub layout: Layout,
    /// Lighting after transforming, only of the vertices whose colors are read (see
    /// [`Deferred`]).
    pub deferred: Option<Deferred>,
    /// Triangles that share vertices have their corners taken to window coordinates
    /// here (see [`super::window`]).
    pub window: Option<ViewportTransform>,
}

/// Lighting after the positions are known, for lit non-indexed triangles and flat-shaded
/// lit lines, where vertex `first + k` belongs to primitive `k / step` alone: only the
/// vertices of triangles that clipping does not drop outright
/// ([`rejects`](crate::vertex::rejects)), and of those only the provoking one under
/// flat shading, are lit. No other vertex's color reaches a pixel: flat shading reads
/// only the provoking vertex's color (clipping and setup keep the original one).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Deferred {
    pub first: usize,
    /// Vertices per primitive: 3 (triangles) or 2 (lines).
    pub step: usize,
    /// Flat shading: only the last vertex of each primitive.
    pub provoking_only: bool,
}

impl<'s, 'd> Stage<'s, 'd> {
    pub fn new(state: &'s RenderState, draw: &'d DrawCall<'d>) -> Self {
        // The inverse of the modelview only where normals may be read (lighting, or the
        // texgen modes of [`Stage::need_normal`] on some unit): a draw of many without
        // them paid for it every time.
        let reads_normals = state.lighting.is_some()
            || state
                .texgen
                .iter()
                .any(|g| matches!(g, Some(TexGen::NormalMap | TexGen::ReflectionMap)));
        let normal = if reads_normals {
            normal_matrix(&state.modelview)
        } else {
            Mat3::IDENTITY
        };
        let lighting = state.lighting.as_ref().map(Prepared::new);
        let two_side = state
            .lighting
            .as_ref()
            .is_some_and(|l| l.two_side && !matches!(draw.primitive, Primitive::Points))
            && !draw.primitive.is_line();
        let tex: [TexSource<'d>; TEXTURE_UNITS] = std::array::from_fn(|u| {
            let m = state.texture_matrices[u];
            let matrix = (m != Mat4::IDENTITY).then_some(m);
            match (state.texgen[u], draw.texcoord[u]) {
                (Some(g), _) => TexSource::Gen(g, matrix),
                (None, AttribSource::Array(a)) => TexSource::Array(a, matrix),
                (None, AttribSource::Constant(c)) => {
                    let tc = Vec4::from_array(c);
                    TexSource::Constant(matrix.map_or(tc, |m| m * tc))
                }
            }
        });
        let layout = Layout::new(state, two_side, draw.primitive == Primitive::Points);
        // Texgen of the enabled units: the others' coordinates are not kept.
        let texgen = |g: TexGen| {
            (0..TEXTURE_UNITS).any(|u| state.texgen[u] == Some(g) && layout.tex(u).is_some())
        };
        let flat = state.shade_model == ShadeModel::Flat;
        let deferred = match (draw.primitive, draw.indices) {
            _ if lighting.is_none() => None,
            (Primitive::Triangles, Indices::Range { first, .. }) => Some(Deferred {
                first,
                step: 3,
                provoking_only: flat,
            }),
            (Primitive::Lines, Indices::Range { first, .. }) if flat => Some(Deferred {
                first,
                step: 2,
                provoking_only: true,
            }),
            _ => None,
        };
        Stage {
            state,
            draw,
            modelview: state.modelview,
            projection: state.projection,
            mvp: state.projection * state.modelview,
            normal,
            rescale: if state.rescale_normal && !state.normalize {
                rescale_factor(&normal)
            } else {
                1.0
            },
            need_eye: lighting.as_ref().is_some_and(Prepared::reads_position)
                || state.fog.is_some()
                || !state.clip_planes.is_empty()
                || texgen(TexGen::ReflectionMap)
                || state.matrix_palette.is_some()
                || (draw.primitive == Primitive::Points
                    && state.point_params.attenuation != [1.0, 0.0, 0.0]),
            lighting,
            palette: state
                .matrix_palette
                .as_ref()
                .map(|p| p.iter().map(|m| (*m, normal_matrix(m))).collect()),
            tex,
            attenuate: state.point_params.attenuation != [1.0, 0.0, 0.0],
            texgen: texgen(TexGen::NormalMap) || texgen(TexGen::ReflectionMap),
            reflection: texgen(TexGen::ReflectionMap),
            layout,
            deferred,
            window: match (draw.primitive, draw.indices) {
                (Primitive::Triangles, Indices::Range { .. }) => None,
                (p, _) if p == Primitive::Points || p.is_line() => None,
                _ => Some(ViewportTransform::new(state)),
            },
        }
    }

    /// Eye-space position and (untransformed-length) eye-space normal of vertex `i`.
    #[cfg(test)]
    fn to_eye(&self, i: usize, p: Vec4) -> (Vec4, Vec3) {
        let n = || self.draw.normal.fetch_vec4(i).truncate();
        let need_normal = self.need_normal();
        let Some(palette) = &self.palette else {
            let ne = if need_normal {
                self.normal * n() * self.rescale
            } else {
                Vec3::ZERO
            };
            let eye = if self.need_eye {
                self.modelview * p
            } else {
                Vec4::ZERO
            };
            return (eye, ne);
        };
        let (mut eye, mut ne) = (Vec4::ZERO, Vec3::ZERO);
        let obj_n = if need_normal { n() } else { Vec3::ZERO };
        for (index, weight) in palette_terms(self.draw, i) {
            // An index past the palette contributes nothing.
            if let Some((m, nm)) = palette.get(index) {
                eye += (*m * p) * weight;
                if need_normal {
                    ne += (*nm * obj_n) * weight;
                }
            }
        }
        (eye, ne)
    }

    /// The eye-space normal is needed: lighting or texgen reads it.
    #[cfg(test)]
    fn need_normal(&self) -> bool {
        self.lighting.is_some() || self.texgen
    }

    /// Runs vertex `i` into `out`, every field written, every vertex lit: the vertex stage
    /// stated one vertex at a time, which [`write_lanes`](Self::write_lanes) must match
    /// bit for bit (the tests compare them).
    #[cfg(test)]
    fn write(&self, i: usize, out: &mut ClipVertex) {
        let p = Vec4::from_array(self.draw.position.fetch(i));
        // The clip position does not depend on lighting or texgen being on (GL's
        // invariance rule for multi-pass rendering): always the one product with the
        // combined matrix, except when skinning.
        let (eye, mut normal) = self.to_eye(i, p);
        let pos = if self.palette.is_some() {
            self.projection * eye
        } else {
            self.mvp * p
        };
        if self.need_normal() && self.state.normalize {
            // A zero-length normal stays zero: it lights nothing but ambient and emission,
            // and never produces NaN.
            normal = normal.normalize_or_zero();
        }
        let given = self.draw.color.fetch_vec4(i);
        let (color, back_color) = match &self.lighting {
            Some(l) => {
                let front = l.shade(eye, normal, given, false);
                let back = if self.layout.two_side() {
                    l.shade(eye, -normal, given, true)
                } else {
                    front
                };
                (front, back)
            }
            _ => {
                let c = clamp01(given);
                (c, c)
            }
        };
        self.finish(i, pos, color, back_color, eye, normal, out);
    }

    /// What follows the colors: texture coordinates, point size, clip distances; then
    /// every field of `out` written.
    #[cfg(test)]
    #[allow(clippy::too_many_arguments)]
    fn finish(
        &self,
        i: usize,
        pos: Vec4,
        color: Vec4,
        back_color: Vec4,
        eye: Vec4,
        normal: Vec3,
        out: &mut ClipVertex,
    ) {
        let mut tex = [Vec4::ZERO; TEXTURE_UNITS];
        for (t, src) in tex.iter_mut().zip(&self.tex) {
            let (tc, matrix) = match *src {
                TexSource::Constant(tc) => {
                    *t = tc;
                    continue;
                }
                TexSource::Array(a, matrix) => (Vec4::from_array(a.fetch(i)), matrix),
                TexSource::Gen(TexGen::NormalMap, matrix) => (normal.extend(1.0), matrix),
                TexSource::Gen(TexGen::ReflectionMap, matrix) => {
                    let e = eye.truncate().normalize_or_zero();
                    let n = normal.normalize_or_zero();
                    ((e - 2.0 * n * n.dot(e)).extend(1.0), matrix)
                }
            };
            *t = matrix.map_or(tc, |m| m * tc);
        }
        let point_size = if self.layout.point_size().is_some() {
            self.point_size(i, eye)
        } else {
            1.0
        };
        let mut clip_dist = [0.0; super::MAX_USER_PLANES];
        for (d, plane) in clip_dist
            .iter_mut()
            .zip(&self.state.clip_planes[..self.layout.planes])
        {
            *d = clip_distance(*plane, eye);
        }
        // Field by field (the pattern is exhaustive, so a new field cannot be missed).
        let ClipVertex {
            pos: out_pos,
            color: out_color,
            back_color: out_back_color,
            tex: out_tex,
            eye: out_eye,
            point_size: out_point_size,
            clip_dist: out_clip_dist,
        } = out;
        *out_pos = pos;
        *out_color = color;
        *out_back_color = back_color;
        *out_tex = tex;
        *out_eye = eye.truncate();
        *out_point_size = point_size;
        *out_clip_dist = clip_dist;
    }

    /// Runs the vertices `idx` (`LANES` of them) into `out` (`layout.stride` floats per
    /// vertex, at most `LANES` vertices: lanes past its end are computed and dropped),
    /// as `write` (the tests' one-vertex statement) would one by one and bit for bit
    /// alike, with positions, normals and colors as structures of arrays so transform,
    /// normalization and lighting vectorize across vertices. Only what the layout keeps
    /// is computed. Returns the vertices' [`reject_code`](super::reject_code)s and their
    /// clip positions.
    #[inline(always)]
    pub fn write_lanes(
        &self,
        idx: &[usize; LANES],
        out: &mut [f32],
        light: bool,
    ) -> (Lane<u32>, [Lane<f32>; 4]) {
        let layout = &self.layout;
        let stride = layout.stride;
        let mut p = [[0.0; LANES]; 4];
        self.draw.position.gather(idx, &mut p);
        let eye = if self.need_eye {
            self.eye_lanes(idx, &p)
        } else {
            [[0.0; LANES]; 4]
        };
        // The clip position does not depend on lighting or texgen being on (GL's
        // invariance rule for multi-pass rendering): always the one product with the
        // combined matrix, except when skinning.
        let pos = if self.palette.is_some() {
            mat4_lanes(&self.projection, &eye)
        } else {
            mat4_lanes(&self.mvp, &p)
        };
        // Texgen reads the normals; lighting shares them then.
        let normal = self.texgen.then(|| self.normals_lanes(idx));
        // Reflection-map coordinates, worked out before the loop over the units and only
        // when a unit reads them: computed inside the loop, the arithmetic was hoisted out
        // of it by LLVM (pure arithmetic may be speculated) and ran for every group of
        // every draw, with or without texgen.
        let reflection = match &normal {
            Some(n) if self.reflection => Some(reflection_lanes(&eye, n)),
            _ => None,
        };
        let (color, back_color) =
            self.colors_lanes(idx, light, self.need_eye.then_some(&eye), normal.as_ref());
        // Colors lit later ([`Deferred`]) are written then; until then their slots keep
        // the zeros `fill` starts its group with, and only the positions are stored here.
        let deferred = self.lighting.is_some() && !light;
        // The position and the color, at the same offsets in every layout.
        for (v, k) in out.chunks_exact_mut(stride).zip(0..LANES) {
            if let Some(v) = v.get_mut(..8) {
                v[..4].copy_from_slice(&[pos[0][k], pos[1][k], pos[2][k], pos[3][k]]);
                if !deferred {
                    v[4..].copy_from_slice(&[color[0][k], color[1][k], color[2][k], color[3][k]]);
                }
            }
        }
        if layout.two_side() && !deferred {
            store(out, stride, layout.back(), &back_color);
        }
        for (u, src) in self.tex.iter().enumerate() {
            let Some(at) = layout.tex(u) else { continue };
            let (mut tc, matrix) = match *src {
                TexSource::Constant(tc) => (tc.to_array().map(|c| [c; LANES]), None),
                TexSource::Array(a, matrix) => {
                    let mut tc = [[0.0; LANES]; 4];
                    a.gather(idx, &mut tc);
                    (tc, matrix)
                }
                TexSource::Gen(g, matrix) => {
                    let n = normal.as_ref().expect("texgen reads the normals");
                    (texgen_lanes(g, n, reflection.as_ref()), matrix)
                }
            };
            if let Some(m) = matrix {
                tc = mat4_lanes(&m, &tc);
            }
            store(out, stride, at, &tc);
        }
        if let Some(at) = layout.eye_z() {
            for (v, k) in out.chunks_exact_mut(stride).zip(0..LANES) {
                v[at] = eye[2][k];
            }
        }
        if layout.point_size().is_some() || layout.planes > 0 {
            let planes = &self.state.clip_planes[..layout.planes];
            for (v, k) in out.chunks_exact_mut(stride).zip(0..LANES) {
                let e = Vec4::new(eye[0][k], eye[1][k], eye[2][k], eye[3][k]);
                if let Some(at) = layout.point_size() {
                    v[at] = self.point_size(idx[k], e);
                }
                for (j, &plane) in planes.iter().enumerate() {
                    v[layout.clip(j)] = clip_distance(plane, e);
                }
            }
        }
        (reject_codes(&pos), pos)
    }

    /// The eye positions of vertices `idx` at object positions `p`: the modelview's
    /// product, or the blend of their palette matrices.
    #[inline(always)]
    fn eye_lanes(&self, idx: &[usize; LANES], p: &[Lane<f32>; 4]) -> [Lane<f32>; 4] {
        match &self.palette {
            None => mat4_lanes(&self.modelview, p),
            Some(palette) => self.skin_lanes(palette, idx, p, |(m, _)| m.to_cols_array_2d()),
        }
    }

    /// The eye-space normals of vertices `idx`, as `to_eye` and `write` derive them: the
    /// normal matrix and the rescale factor (or the blend of the palette's normal
    /// matrices), and with `GL_NORMALIZE` unit length (or zero).
    #[inline(always)]
    fn normals_lanes(&self, idx: &[usize; LANES]) -> [Lane<f32>; 3] {
        let mut n = [[0.0; LANES]; 3];
        self.draw.normal.gather(idx, &mut n);
        let mut normal = match &self.palette {
            Some(palette) => self.skin_lanes(palette, idx, &n, |(_, nm)| nm.to_cols_array_2d()),
            None => {
                let m = self.normal.to_cols_array_2d();
                let mut out = [[0.0; LANES]; 3];
                for r in 0..3 {
                    for k in 0..LANES {
                        out[r][k] = (m[0][r] * n[0][k] + m[1][r] * n[1][k] + m[2][r] * n[2][k])
                            * self.rescale;
                    }
                }
                out
            }
        };
        if self.state.normalize {
            normalize_lanes(&mut normal);
        }
        normal
    }

    /// The front and back colors of vertices `idx` for [`write_lanes`](Self::write_lanes):
    /// without lighting the given colors clamped; with lighting, lit when `light`, and
    /// zero (nothing reads them before [`Deferred`] lighting does) when not. `eye` and
    /// `normal` hold their eye positions and normals when the caller has them; they are
    /// worked out here when lighting needs them and it does not.
    #[inline(always)]
    pub fn colors_lanes(
        &self,
        idx: &[usize; LANES],
        light: bool,
        eye: Option<&[Lane<f32>; 4]>,
        normal: Option<&[Lane<f32>; 3]>,
    ) -> ([Lane<f32>; 4], [Lane<f32>; 4]) {
        if self.lighting.is_some() && !light {
            // Deferred: lit later if a pixel reads the color; if not, it is never read.
            return ([[0.0; LANES]; 4], [[0.0; LANES]; 4]);
        }
        let mut given = [[0.0; LANES]; 4];
        self.draw.color.gather(idx, &mut given);
        let Some(l) = &self.lighting else {
            // Row by row (a flattened iterator does not vectorize).
            for row in &mut given {
                for v in row {
                    *v = min_ps(max_ps(*v, 0.0), 1.0);
                }
            }
            return (given, given);
        };
        let mut normal = match normal {
            Some(n) => *n,
            None => self.normals_lanes(idx),
        };
        let computed;
        let eye = match eye {
            Some(eye) => eye,
            None if l.reads_position() => {
                let mut p = [[0.0; LANES]; 4];
                self.draw.position.gather(idx, &mut p);
                computed = self.eye_lanes(idx, &p);
                &computed
            }
            // Directional lights only: no position is read.
            None => &[[0.0; LANES]; 4],
        };
        let front = l.shade_lanes(eye, &normal, &given, false);
        let back = if self.layout.two_side() {
            for v in normal.iter_mut().flatten() {
                *v = -*v;
            }
            l.shade_lanes(eye, &normal, &given, true)
        } else {
            front
        };
        (front, back)
    }

    /// Skinning (`OES_matrix_palette`) in lanes, as `to_eye` blends one vertex: the sum
    /// over each vertex's palette terms of weight · (matrix · `v`), each lane with its
    /// own matrices (`cols` takes a palette entry's `N` × `N` columns). A term whose index
    /// is past the palette adds nothing, not even a zero (which would turn −0 into +0).
    #[inline(always)]
    fn skin_lanes<const N: usize>(
        &self,
        palette: &[(Mat4, Mat3)],
        idx: &[usize; LANES],
        v: &[Lane<f32>; N],
        cols: impl Fn(&(Mat4, Mat3)) -> [[f32; N]; N],
    ) -> [Lane<f32>; N] {
        // The index and weight elements of the 8 vertices, one format dispatch per array.
        let rows = |a: Option<AttribArray<'_>>| {
            let mut r = [[0.0; LANES]; 4];
            if let Some(a) = a {
                a.gather(idx, &mut r);
            }
            r
        };
        let (index, weight) = (rows(self.draw.matrix_index), rows(self.draw.weight));
        let mut sum = [[0.0; LANES]; N];
        for t in 0..palette_units(self.draw) {
            // Each lane's matrix, column by column, whether it exists, and its weight.
            let mut m = [[[0.0; LANES]; N]; N];
            let mut valid = [false; LANES];
            let mut w = [0.0; LANES];
            for k in 0..LANES {
                let (entry, wk) = palette_term(self.draw, t, index[t][k], weight[t][k]);
                w[k] = wk;
                if let Some(entry) = palette.get(entry) {
                    valid[k] = true;
                    for (c, col) in cols(entry).iter().enumerate() {
                        for (r, &x) in col.iter().enumerate() {
                            m[c][r][k] = x;
                        }
                    }
                }
            }
            for r in 0..N {
                for k in 0..LANES {
                    // glam's order: ((x·c₀ + y·c₁) + z·c₂) + w·c₃.
                    let mut x = m[0][r][k] * v[0][k];
                    for c in 1..N {
                        x += m[c][r][k] * v[c][k];
                    }
                    let term = x * w[k];
                    sum[r][k] = if valid[k] {
                        sum[r][k] + term
                    } else {
                        sum[r][k]
                    };
                }
            }
        }
        sum
    }

    /// ES 1.1 §3.3: the size (array or state) times sqrt(1 / (a + b·d + c·d²)), d the
    /// distance from the eye, clamped to [min, max]. A denominator that is not positive
    /// (the coefficients may be anything) is the limit from above: the size is `max`.
    fn point_size(&self, i: usize, eye: Vec4) -> f32 {
        let pp = &self.state.point_params;
        let mut size = match &self.draw.point_size {
            Some(a) => a.fetch(i)[0],
            None => self.state.point_size,
        };
        if self.attenuate {
            let d = eye.truncate().length();
            let [a, b, c] = pp.attenuation;
            let denom = a + b * d + c * d * d;
            size = if denom > 0.0 {
                size * (1.0 / denom).sqrt()
            } else {
                pp.size_max
            };
        }
        // NaN (from a NaN size or distance) becomes the minimum.
        let size = size.max(pp.size_min);
        if size.is_nan() {
            pp.size_min
        } else {
            size.min(pp.size_max)
        }
    }
}

/// The palette terms of every vertex of `draw` (see [`DrawCall::matrix_index`]).
fn palette_units(draw: &DrawCall<'_>) -> usize {
    draw.weight.map_or(1, |w| w.size.clamp(1, 4))
}

/// Palette term `t` of a vertex whose matrix-index and weight elements have component `t`
/// `index` and `weight` (read only where the arrays exist): the palette entry
/// (`usize::MAX` for none) and its weight.
#[inline(always)]
fn palette_term(draw: &DrawCall<'_>, t: usize, index: f32, weight: f32) -> (usize, f32) {
    let index = match draw.matrix_index {
        Some(a) if t < a.size => index,
        _ => 0.0,
    };
    let weight = if draw.weight.is_some() { weight } else { 1.0 };
    let index = if index >= 0.0 && index.is_finite() {
        index as usize
    } else {
        usize::MAX
    };
    (index, weight)
}

/// The (palette entry, weight) pairs of vertex `i`.
#[cfg(test)]
fn palette_terms<'a>(draw: &'a DrawCall<'_>, i: usize) -> impl Iterator<Item = (usize, f32)> + 'a {
    let fetch = |a: Option<AttribArray<'_>>| a.map_or([0.0; 4], |a| a.fetch(i));
    let (index, weight) = (fetch(draw.matrix_index), fetch(draw.weight));
    (0..palette_units(draw)).map(move |t| palette_term(draw, t, index[t], weight[t]))
}

/// Writes the lanes of `a` at offset `at` of each vertex of `out` (`stride` floats each),
/// component by component: assembling vectors from lanes costs more than the stores.
#[inline(always)]
fn store(out: &mut [f32], stride: usize, at: usize, a: &[Lane<f32>; 4]) {
    for (v, k) in out.chunks_exact_mut(stride).zip(0..LANES) {
        if let Some(v) = v.get_mut(at..at + 4) {
            v.copy_from_slice(&[a[0][k], a[1][k], a[2][k], a[3][k]]);
        }
    }
}

/// [`reject_code`](super::reject_code) of eight clip positions, the same comparisons
/// lane by lane, in 32-bit lanes: written with bytes, or narrowed here, the loop compiled
/// to scalar code (some 45 instructions a vertex, against 4).
#[inline(always)]
fn reject_codes(pos: &[Lane<f32>; 4]) -> Lane<u32> {
    let mut codes = [0; LANES];
    for j in 0..LANES {
        let (x, y, z, w) = (pos[0][j], pos[1][j], pos[2][j], pos[3][j]);
        let finite = x * 0.0 + y * 0.0 + z * 0.0 + w * 0.0 == 0.0;
        let g = GUARD * w;
        let inside = (x.abs() <= g) & (y.abs() <= g) & (z.abs() <= w) & (w >= W_MIN);
        codes[j] = u32::from(-x > w)
            | u32::from(-y > w) << 1
            | u32::from(x > w) << 2
            | u32::from(y > w) << 3
            | u32::from(!finite) << 4
            | u32::from(!inside) << 5;
    }
    codes
}

/// The signed distance of eye position `eye` to user plane `plane`, kept finite and never
/// NaN (an infinite eye position can give either), so the clipper's interpolation
/// parameters stay in [0, 1]; NaN counts as outside.
#[inline]
fn clip_distance(plane: Vec4, eye: Vec4) -> f32 {
    let v = plane.dot(eye);
    if v.is_nan() {
        -f32::MAX
    } else {
        v.clamp(-f32::MAX, f32::MAX)
    }
}

/// `m · p` for each lane, in `Mat4 * Vec4`'s order: ((x·c₀ + y·c₁) + z·c₂) + w·c₃.
#[inline(always)]
fn mat4_lanes(m: &Mat4, p: &[Lane<f32>; 4]) -> [Lane<f32>; 4] {
    let m = m.to_cols_array_2d();
    let mut out = [[0.0; LANES]; 4];
    for r in 0..4 {
        for k in 0..LANES {
            out[r][k] =
                m[0][r] * p[0][k] + m[1][r] * p[1][k] + m[2][r] * p[2][k] + m[3][r] * p[3][k];
        }
    }
    out
}

/// `Vec3::normalize_or_zero` for each lane, in its order: the reciprocal of the length,
/// and zero where that is not finite and positive.
#[inline(always)]
fn normalize_lanes(v: &mut [Lane<f32>; 3]) {
    for k in 0..LANES {
        let len = (v[0][k] * v[0][k] + v[1][k] * v[1][k] + v[2][k] * v[2][k]).sqrt();
        let rcp = 1.0 / len;
        let ok = rcp.is_finite() && rcp > 0.0;
        for axis in v.iter_mut() {
            axis[k] = if ok { axis[k] * rcp } else { 0.0 };
        }
    }
}

/// The eye direction reflected about the normal, each made unit first, for every lane:
/// e − 2n(n·e), the coordinates of a reflection map.
#[inline(always)]
fn reflection_lanes(eye: &[Lane<f32>; 4], n: &[Lane<f32>; 3]) -> [Lane<f32>; 3] {
    let mut e = [eye[0], eye[1], eye[2]];
    normalize_lanes(&mut e);
    let mut u = *n;
    normalize_lanes(&mut u);
    let mut r = [[0.0; LANES]; 3];
    for k in 0..LANES {
        let d = u[0][k] * e[0][k] + u[1][k] * e[1][k] + u[2][k] * e[2][k];
        for a in 0..3 {
            r[a][k] = e[a][k] - 2.0 * u[a][k] * d;
        }
    }
    r
}

/// Generated texture coordinates (s, t, r, 1) of each lane, in `finish`'s order: the
/// eye-space normal `n` itself, or the [`reflection_lanes`] worked out beforehand.
#[inline(always)]
fn texgen_lanes(
    g: TexGen,
    n: &[Lane<f32>; 3],
    reflection: Option<&[Lane<f32>; 3]>,
) -> [Lane<f32>; 4] {
    let one = [1.0; LANES];
    match g {
        TexGen::NormalMap => [n[0], n[1], n[2], one],
        TexGen::ReflectionMap => {
            let r = reflection.expect("reflection maps have their coordinates");
            [r[0], r[1], r[2], one]
        }
    }
}

#[cfg(test)]
fn clamp01(c: Vec4) -> Vec4 {
    // max/min rather than clamp: NaN becomes 0 instead of propagating.
    c.max(Vec4::ZERO).min(Vec4::ONE)
}

#[cfg(test)]
mod tests {
    use super::super::{rejects, run, AttribSource, ComponentType, Indices, Window, CLIPS};
    use super::*;
    use crate::texenv::TextureUnit;

    fn draw<'a>(bytes: &'a [u8], prim: Primitive, count: usize) -> DrawCall<'a> {
        DrawCall::new(
            prim,
            Indices::Range { first: 0, count },
            AttribArray {
                data: bytes,
                ty: ComponentType::Float,
                size: 3,
                stride: 12,
                normalized: false,
            },
        )
    }

    fn bytes(v: &[f32]) -> Vec<u8> {
        v.iter().flat_map(|v| v.to_ne_bytes()).collect()
    }

    /// The bits of vertex `i`'s `floats` (in the stage's layout, NaN included, for exact
    /// comparison) of a draw of `n` vertices from `first` whose triangle has clip
    /// positions `tri`, the colors left out where deferred lighting leaves them unlit
    /// because no pixel reads them (the lanes defer; the one-vertex statement lights every
    /// vertex).
    fn read_bits(
        stage: &Stage<'_, '_>,
        floats: &[f32],
        tri: [Vec4; 3],
        i: usize,
        n: usize,
    ) -> Vec<u32> {
        let layout = &stage.layout;
        let mut f = floats[..layout.stride].to_vec();
        if let Some(d) = stage.deferred {
            let k = i - d.first;
            let whole = k < n / d.step * d.step;
            let rejected = d.step == 3 && rejects(tri[0], tri[1], tri[2]);
            let provoking = k % d.step == d.step - 1;
            if !whole || rejected || (d.provoking_only && !provoking) {
                f[4..8].fill(0.0);
                f[layout.back()..layout.back() + 4].fill(0.0);
            }
        }
        f.into_iter().map(f32::to_bits).collect()
    }

    #[test]
    fn batched_lanes_match_one_vertex_at_a_time_bit_for_bit() {
        use crate::state::{Light, Lighting};
        // Awkward values: zero, huge, tiny, negative zero, NaN, infinities, and lengths
        // that make normals zero or non-unit; 13 vertices, so the last group is short.
        let odd = [
            0.0,
            -0.0,
            1.0,
            -0.75,
            3.0e38,
            1.0e-39,
            f32::NAN,
            f32::INFINITY,
            0.3,
            -2.5,
            0.001,
            7.0,
            -1.0e-20,
        ];
        let n = odd.len();
        let at = |k: usize, j: usize| odd[(k * 5 + j * 3) % n] + (k as f32) * 0.1;
        let pos: Vec<f32> = (0..n).flat_map(|k| (0..3).map(move |j| at(k, j))).collect();
        let nrm: Vec<f32> = (0..n)
            .flat_map(|k| (0..3).map(move |j| at(k + 1, j)))
            .collect();
        let col: Vec<f32> = (0..n)
            .flat_map(|k| (0..4).map(move |j| at(k + 2, j) * 0.5))
            .collect();
        // Positions with a w of their own (2, 0, 1, -0.5, ...): eye positions a positional
        // light divides by their w.
        let pos4: Vec<f32> = (0..n)
            .flat_map(|k| {
                (0..3)
                    .map(move |j| at(k, j))
                    .chain([[2.0, 0.0, 1.0, -0.5][k % 4]])
            })
            .collect();
        let (pb, nb, cb, p4b) = (bytes(&pos), bytes(&nrm), bytes(&col), bytes(&pos4));
        let fixed: Vec<u8> = (0..2 * n as i32)
            .flat_map(|k| (k * 40_000 - 300_000).to_ne_bytes())
            .collect();
        fn array(data: &[u8], size: usize) -> AttribArray<'_> {
            AttribArray {
                data,
                ty: ComponentType::Float,
                size,
                stride: 4 * size,
                normalized: false,
            }
        }
        let light = |dir: Vec3, spec: f32| Light {
            ambient: Vec4::new(0.1, 0.2, 0.3, 1.0),
            diffuse: Vec4::new(0.9, 0.7, 0.5, 1.0),
            specular: Vec4::splat(spec),
            position: dir.extend(0.0),
            ..Light::default()
        };
        // Skinning: three palette matrices (one singular, so its normal matrix is the
        // identity), three terms per vertex with indices past the palette (5), fractional
        // (1.5 reads as 1), negative and NaN among them, and odd weights.
        let palette = vec![
            Mat4::from_rotation_y(0.6) * Mat4::from_translation(Vec3::new(1.0, 0.0, -2.0)),
            Mat4::from_scale(Vec3::new(2.0, 0.5, 0.0)),
            Mat4::from_cols_array(&[
                0.9, 0.1, 0.0, 0.0, -0.2, 1.1, 0.3, 0.0, 0.0, 0.0, 1.0, 0.2, 0.5, -0.5, 0.0, 1.0,
            ]),
        ];
        let skin_index = bytes(
            &(0..3 * n)
                .map(|k| [0.0, 1.0, 2.0, 5.0, 1.5, -1.0, f32::NAN][k % 7])
                .collect::<Vec<_>>(),
        );
        let skin_weight = bytes(&(0..3 * n).map(|k| at(k, 2) * 0.25).collect::<Vec<_>>());
        for case in 0..1024u32 {
            let mut s = RenderState::new(8, 8);
            s.modelview = Mat4::from_scale(Vec3::new(1.5, 0.5, 2.0))
                * Mat4::from_rotation_x(0.4)
                * Mat4::from_translation(Vec3::new(0.25, -1.0, 3.0));
            s.projection = Mat4::perspective_rh_gl(0.9, 1.3, 0.5, 20.0);
            s.normalize = case & 1 != 0;
            s.rescale_normal = case & 2 != 0;
            // What the vertices keep: all four units, or (odd cases) units 0 and 2 and the
            // eye z for fog.
            s.textures =
                std::array::from_fn(|u| (case & 1 == 0 || u % 2 == 0).then(TextureUnit::white));
            if case & 1 != 0 {
                s.fog = Some(crate::texenv::Fog {
                    mode: crate::texenv::FogMode::Linear,
                    density: 1.0,
                    start: 0.0,
                    end: 1.0,
                    color: [0.0; 4],
                    quality: crate::quality::Quality::Balanced,
                });
            }
            if case & 4 != 0 {
                let mut l = Lighting {
                    lights: vec![
                        light(Vec3::new(0.3, 0.5, 1.0), 1.0),
                        light(
                            Vec3::new(-1.0, 0.2, 0.1),
                            if case & 16 != 0 { 0.0 } else { 0.6 },
                        ),
                    ],
                    two_side: case & 8 != 0,
                    color_material: case & 16 == 0,
                    ..Lighting::default()
                };
                if case & 64 != 0 {
                    // Positional lights with attenuation (one at w = 2), a spot light,
                    // and a directional spot light.
                    l.lights[0].position = Vec4::new(1.0, 2.0, -3.0, 1.0);
                    l.lights[0].attenuation = [0.5, 0.25, 0.125];
                    l.lights[1].position = Vec4::new(-2.0, 0.5, 4.0, 2.0);
                    l.lights[1].spot_cutoff = 60.0;
                    l.lights[1].spot_exponent = 3.5;
                    l.lights[1].spot_direction = Vec3::new(0.2, -0.1, -1.0);
                    let mut spot = light(Vec3::new(0.1, 0.9, 0.4), 0.5);
                    spot.spot_cutoff = 90.0;
                    spot.spot_exponent = 1.0;
                    spot.spot_direction = Vec3::new(0.0, -1.0, 0.0);
                    l.lights.push(spot);
                    if case & 128 != 0 {
                        // Zero denominators: saturating lights.
                        l.lights[0].attenuation = [0.0, 0.0, 0.0];
                        l.lights.push(Light {
                            position: Vec4::new(0.5, 0.5, 0.5, 1.0),
                            attenuation: [0.0, 1.0, 0.0],
                            ..light(Vec3::ZERO, 0.2)
                        });
                    }
                }
                l.front.specular = Vec4::new(0.5, 0.6, 0.7, 1.0);
                l.front.shininess = 20.0;
                l.back.shininess = 0.0;
                l.back.specular = Vec4::splat(0.3);
                s.lighting = Some(l);
            }
            // Texture coordinates: a constant, a float array under a texture matrix and a
            // 16.16 array; or, with points and a clip plane, every field per vertex.
            let prim = if case & 32 != 0 {
                s.clip_planes = vec![Vec4::new(0.5, -1.0, 0.25, 2.0)];
                s.point_params.attenuation = [1.0, 0.5, 0.25];
                Primitive::Points
            } else {
                Primitive::Triangles
            };
            let mut d = draw(&pb, prim, n);
            if case & 128 != 0 {
                d.position = array(&p4b, 4);
            }
            if case & 512 != 0 {
                s.matrix_palette = Some(palette.clone());
                d.matrix_index = Some(array(&skin_index, 3));
                d.weight = Some(array(&skin_weight, 3));
            }
            d.normal = AttribSource::Array(array(&nb, 3));
            d.color = AttribSource::Array(array(&cb, 4));
            if case & 2 != 0 {
                d.texcoord[1] = AttribSource::Constant([0.5, 0.25, 0.0, 2.0]);
                d.texcoord[2] = AttribSource::Array(array(&cb, 4));
                s.texture_matrices[2] = Mat4::from_rotation_z(0.3);
                d.texcoord[3] = AttribSource::Array(AttribArray {
                    data: &fixed,
                    ty: ComponentType::Fixed,
                    size: 2,
                    stride: 8,
                    normalized: false,
                });
            }
            if case & 256 != 0 {
                // Texgen: normals on unit 0 (under a texture matrix when case & 2), the
                // reflected eye direction on unit 1 (replacing its constant).
                s.texgen[0] = Some(TexGen::NormalMap);
                s.texgen[1] = Some(TexGen::ReflectionMap);
                if case & 2 != 0 {
                    s.texture_matrices[0] = Mat4::from_scale(Vec3::new(0.5, -2.0, 1.0));
                }
            }
            let stage = Stage::new(&s, &d);
            let v = run(&s, &d).unwrap();
            for i in 0..n {
                let mut one = ClipVertex::new(Vec4::ZERO, Vec4::ZERO);
                stage.write(i, &mut one);
                let t = |k: usize| v.get((i / 3 * 3 + k).min(n - 1)).pos();
                let tri = [t(0), t(1), t(2)];
                assert_eq!(
                    read_bits(&stage, v.get(i).floats, tri, i, n),
                    read_bits(&stage, &stage.layout.pack(&one), tri, i, n),
                    "case {case}, vertex {i}"
                );
            }
        }
    }

    #[test]
    fn batched_lanes_match_one_vertex_for_every_array_type_and_stride() {
        use crate::state::{Light, Lighting};
        // Pseudo-random bytes read as every type: as floats they include NaN, infinities
        // and subnormals. 21 vertices: two full groups and a short one.
        let n = 21;
        let mut x = 0x9e37_79b9_7f4a_7c15_u64;
        let raw: Vec<u8> = (0..64 * n)
            .map(|_| {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                (x >> 24) as u8
            })
            .collect();
        use ComponentType::*;
        // (type, size, stride) per array; stride 0 stands for tightly packed.
        let layouts: [[(ComponentType, usize, usize); 4]; 8] = [
            // position, normal, color, texcoord
            [
                (Byte, 3, 0),
                (Byte, 3, 0),
                (UnsignedByte, 4, 0),
                (Byte, 2, 0),
            ],
            [(Short, 4, 0), (Short, 3, 0), (Fixed, 4, 0), (Short, 3, 0)],
            [
                (Fixed, 2, 0),
                (Fixed, 3, 0),
                (UnsignedByte, 4, 7),
                (Fixed, 4, 0),
            ],
            [
                (Float, 2, 20),
                (Float, 3, 16),
                (Float, 4, 24),
                (Float, 2, 12),
            ],
            [
                (Byte, 4, 5),
                (Short, 3, 9),
                (UnsignedByte, 4, 13),
                (Short, 2, 6),
            ],
            [(Short, 2, 0), (Byte, 3, 3), (Fixed, 4, 20), (Byte, 4, 0)],
            [
                (Fixed, 3, 0),
                (Fixed, 3, 14),
                (UnsignedByte, 4, 4),
                (Fixed, 2, 8),
            ],
            [
                (Float, 3, 12),
                (Float, 3, 12),
                (Float, 4, 16),
                (Float, 3, 0),
            ],
        ];
        for (l, layout) in layouts.iter().enumerate() {
            let arrays: Vec<AttribArray<'_>> = layout
                .iter()
                .enumerate()
                .map(|(which, &(ty, size, stride))| {
                    let stride = if stride == 0 {
                        size * ty.size()
                    } else {
                        stride
                    };
                    // A different offset per array; in the last layout each array ends one
                    // byte short, so its last element reads as the default.
                    let end = if l == 7 {
                        which * 3 + AttribArray::bytes_needed(ty, size, stride, n) - 1
                    } else {
                        raw.len()
                    };
                    AttribArray {
                        data: &raw[which * 3..end],
                        ty,
                        size,
                        stride,
                        // Colors and normals are normalized, as the GL draws them.
                        normalized: which == 1 || which == 2,
                    }
                })
                .collect();
            for case in 0..16u32 {
                let mut s = RenderState::new(8, 8);
                if case & 8 != 0 {
                    // Only the provoking vertices lit (the comparison leaves the others
                    // out).
                    s.shade_model = crate::state::ShadeModel::Flat;
                }
                s.modelview =
                    Mat4::from_rotation_y(0.7) * Mat4::from_scale(Vec3::new(1.0, 2.0, 0.5));
                s.projection = Mat4::perspective_rh_gl(0.9, 1.3, 0.5, 20.0);
                s.normalize = case & 1 != 0;
                if case & 2 != 0 {
                    let mut lt = Lighting {
                        lights: vec![Light {
                            diffuse: Vec4::new(0.9, 0.7, 0.5, 1.0),
                            specular: Vec4::ONE,
                            position: Vec4::new(0.3, 0.5, 1.0, 0.0),
                            ..Light::default()
                        }],
                        color_material: case & 4 != 0,
                        two_side: true,
                        ..Lighting::default()
                    };
                    lt.front.specular = Vec4::new(0.5, 0.6, 0.7, 1.0);
                    lt.front.shininess = 12.0;
                    s.lighting = Some(lt);
                }
                if case & 4 != 0 {
                    s.texture_matrices[0] = Mat4::from_rotation_z(0.3);
                }
                let mut d = DrawCall::new(
                    Primitive::Triangles,
                    Indices::Range { first: 0, count: n },
                    arrays[0],
                );
                d.normal = AttribSource::Array(arrays[1]);
                d.color = AttribSource::Array(arrays[2]);
                d.texcoord[0] = AttribSource::Array(arrays[3]);
                d.texcoord[1] = AttribSource::Array(arrays[0]);
                s.textures[0] = Some(TextureUnit::white());
                s.textures[1] = Some(TextureUnit::white());
                let stage = Stage::new(&s, &d);
                let v = run(&s, &d).unwrap();
                for i in 0..n {
                    let mut one = ClipVertex::new(Vec4::ZERO, Vec4::ZERO);
                    stage.write(i, &mut one);
                    let t = |k: usize| v.get((i / 3 * 3 + k).min(n - 1)).pos();
                    let tri = [t(0), t(1), t(2)];
                    assert_eq!(
                        read_bits(&stage, v.get(i).floats, tri, i, n),
                        read_bits(&stage, &stage.layout.pack(&one), tri, i, n),
                        "layout {l}, case {case}, vertex {i}"
                    );
                    // And the conversion is the scalar fetch's, component by component.
                    assert_eq!(
                        one.tex[1].to_array().map(f32::to_bits),
                        arrays[0].fetch(i).map(f32::to_bits),
                        "layout {l}, vertex {i}"
                    );
                }
            }
        }
    }

    #[test]
    fn flat_shading_lights_only_provoking_vertices_with_the_same_pixels() {
        use crate::state::{Light, Lighting, ShadeModel};
        use crate::{render, ColorFormat, DepthFormat, Target, TargetFormat};
        // A fan of 60 triangles (or 90 lines) around the center, partly off screen so
        // some are clipped, with normals that differ per vertex.
        let mut pos = Vec::new();
        let mut nrm = Vec::new();
        for t in 0..60 {
            let a = t as f32 * 0.11;
            // Every third triangle entirely right of the view volume, and one with a NaN
            // vertex: clipping rejects those without looking at their colors.
            let dx = if t % 3 == 1 { 2.5 } else { 0.0 };
            for (k, r) in [(0, 0.0f32), (1, 1.3), (2, 1.1)] {
                let b = a + k as f32 * 0.07;
                let x = if t == 5 && k == 1 {
                    f32::NAN
                } else {
                    r * b.cos() + dx
                };
                pos.extend([x, r * b.sin(), 0.1 * k as f32]);
                nrm.extend([b.sin(), (3.0 * b).cos(), 1.0 + k as f32]);
            }
        }
        let (pb, nb) = (bytes(&pos), bytes(&nrm));
        let n = pos.len() / 3;
        let all: Vec<u16> = (0..n as u16).collect();
        use ShadeModel::{Flat, Smooth};
        // Skinned draws (a one-matrix palette) defer alike. Positional lights come with
        // texgen.
        for (shade, light_w, two_side, prim, palette) in [
            (Flat, 0.0, false, Primitive::Triangles, false),
            (Flat, 0.0, true, Primitive::Triangles, false),
            (Flat, 1.0, true, Primitive::Triangles, false),
            (Flat, 1.0, true, Primitive::Triangles, true),
            (Flat, 0.0, false, Primitive::Lines, false),
            (Flat, 1.0, false, Primitive::Lines, false),
            (Flat, 1.0, false, Primitive::Lines, true),
            (Smooth, 0.0, true, Primitive::Triangles, false),
            (Smooth, 1.0, false, Primitive::Triangles, true),
        ] {
            let mut s = RenderState::new(48, 48);
            s.shade_model = shade;
            if light_w == 1.0 {
                s.texgen[0] = Some(TexGen::NormalMap);
                s.texgen[1] = Some(TexGen::ReflectionMap);
            }
            if palette {
                s.matrix_palette = Some(vec![Mat4::IDENTITY]);
            }
            s.normalize = true;
            let mut lt = Lighting {
                lights: vec![Light {
                    diffuse: Vec4::new(0.9, 0.6, 0.3, 1.0),
                    specular: Vec4::ONE,
                    position: Vec4::new(0.4, 0.3, 1.0, light_w),
                    ..Light::default()
                }],
                two_side,
                ..Lighting::default()
            };
            lt.front.specular = Vec4::splat(0.5);
            lt.front.shininess = 10.0;
            s.lighting = Some(lt);
            let with_normals = |indices| {
                let mut d = draw(&pb, prim, n);
                d.indices = indices;
                d.normal = AttribSource::Array(AttribArray {
                    data: &nb,
                    ty: ComponentType::Float,
                    size: 3,
                    stride: 12,
                    normalized: false,
                });
                d
            };
            let image = |indices| {
                let mut t = Target::new(
                    48,
                    48,
                    TargetFormat {
                        color: ColorFormat::Rgba8888,
                        depth: Some(DepthFormat::D24),
                        stencil_bits: 0,
                    },
                );
                render(&s, &with_normals(indices), &mut t).unwrap();
                t.color().to_vec()
            };
            let range = with_normals(Indices::Range { first: 0, count: n });
            let step = if prim == Primitive::Lines { 2 } else { 3 };
            let stage = Stage::new(&s, &range);
            let deferred = Deferred {
                first: 0,
                step,
                provoking_only: shade == Flat,
            };
            assert_eq!(stage.deferred, Some(deferred), "{prim:?}");
            // Indexed, every vertex is lit: the reference.
            let lit_all = image(Indices::U16(&all));
            let provoking_only = image(Indices::Range { first: 0, count: n });
            let mut colors = lit_all.clone();
            colors.sort_unstable();
            colors.dedup();
            assert!(colors.len() > 10, "{prim:?}: {} colors", colors.len());
            assert!(
                lit_all == provoking_only,
                "{shade:?} {prim:?}, light w {light_w}"
            );
        }
    }

    #[test]
    fn user_clip_planes_set_under_a_scaled_modelview() {
        // The GL stores planes in eye space (transformed when set); the vertex stage
        // measures eye positions against them.
        let mut s = RenderState::new(8, 8);
        s.modelview = Mat4::from_scale(Vec3::splat(2.0));
        // Object-space plane x ≥ 1 set under scale 2 is eye-space x ≥ 2: (1, 0, 0, −1)·M⁻¹.
        let eye_plane = s.modelview.inverse().transpose() * Vec4::new(1.0, 0.0, 0.0, -1.0);
        s.clip_planes = vec![eye_plane];
        let b = bytes(&[0.5, 0.0, 0.0, 1.5, 0.0, 0.0]);
        let v = run(&s, &draw(&b, Primitive::Points, 2)).unwrap();
        let d = |i| v.get(i).clip_dist(0);
        assert!(d(0) < 0.0 && d(1) > 0.0);
        assert!((d(1) - 0.5).abs() < 1e-6, "{}", d(1));
    }

    #[test]
    fn point_size_attenuation_and_clamps() {
        let mut s = RenderState::new(8, 8);
        s.point_size = 8.0;
        s.point_params.attenuation = [0.0, 0.0, 1.0];
        let b = bytes(&[0.0, 0.0, -2.0, 0.0, 0.0, -0.1, 0.0, 0.0, 0.0]);
        let size = |s: &RenderState, i| {
            let v = run(s, &draw(&b, Primitive::Points, 3)).unwrap();
            v.get(i).point_size()
        };
        assert_eq!(size(&s, 0), 4.0, "8 · sqrt(1 / 2²)");
        assert_eq!(size(&s, 1), s.point_params.size_max, "clamped to max");
        assert_eq!(size(&s, 2), s.point_params.size_max, "zero denominator");
        s.point_params.size_min = 5.0;
        assert_eq!(size(&s, 0), 5.0, "clamped to min");
    }

    #[test]
    fn texture_matrix_applies_to_texcoords_with_q() {
        let mut s = RenderState::new(8, 8);
        s.texture_matrices[1] = Mat4::from_scale(Vec3::new(2.0, 3.0, 1.0));
        let b = bytes(&[0.0; 3]);
        let mut d = draw(&b, Primitive::Triangles, 1);
        d.texcoord[1] = AttribSource::Constant([0.5, 0.5, 0.0, 2.0]);
        s.textures = [
            Some(TextureUnit::white()),
            Some(TextureUnit::white()),
            None,
            None,
        ];
        let v = run(&s, &d).unwrap();
        assert_eq!(v.get(0).tex(1), Vec4::new(1.0, 1.5, 0.0, 2.0));
        assert_eq!(v.get(0).tex(0), Vec4::new(0.0, 0.0, 0.0, 1.0));
        assert_eq!(v.get(0).layout.stride, 16, "position, color, two units");
    }

    #[test]
    fn matrix_palette_blends_weighted_matrices() {
        let mut s = RenderState::new(8, 8);
        s.matrix_palette = Some(vec![
            Mat4::from_translation(Vec3::new(2.0, 0.0, 0.0)),
            Mat4::from_translation(Vec3::new(0.0, 4.0, 0.0)),
        ]);
        let b = bytes(&[0.0; 3]);
        let idx = [0u8, 1, 1, 7];
        let w = bytes(&[0.25, 0.75, 1.0, 1.0]);
        let mut d = draw(&b, Primitive::Triangles, 2);
        d.matrix_index = Some(AttribArray {
            data: &idx,
            ty: ComponentType::UnsignedByte,
            size: 2,
            stride: 2,
            normalized: false,
        });
        d.weight = Some(AttribArray {
            data: &w,
            ty: ComponentType::Float,
            size: 2,
            stride: 8,
            normalized: false,
        });
        d.position.stride = 0;
        // The projection is the identity: clip positions are the eye positions.
        let v = run(&s, &d).unwrap();
        assert_eq!(v.get(0).pos(), Vec4::new(0.5, 3.0, 0.0, 1.0));
        // Index 7 is past the palette: it contributes nothing.
        assert_eq!(v.get(1).pos(), Vec4::new(0.0, 4.0, 0.0, 1.0));
    }

    #[test]
    fn reject_codes_in_lanes_match_one_position_at_a_time() {
        // Around the frustum's planes (w = ±1) and the guard band's (x or y = ±8 with
        // w = 1, z at ±w), with NaN and infinities.
        let v = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            8.0,
            -8.0,
            f32::NAN,
            f32::INFINITY,
            -f32::INFINITY,
            8.000001,
            -2.0,
            1e-31,
        ];
        // Every combination of the values, eight positions at a time.
        let all: Vec<Vec4> = v
            .iter()
            .flat_map(|&x| v.iter().map(move |&y| (x, y)))
            .flat_map(|(x, y)| {
                v.iter()
                    .flat_map(move |&z| v.map(|w| Vec4::new(x, y, z, w)))
            })
            .collect();
        let mut seen = [false; 64];
        for group in all.chunks_exact(LANES) {
            let pos: [Lane<f32>; 4] = std::array::from_fn(|c| std::array::from_fn(|k| group[k][c]));
            let codes = reject_codes(&pos);
            for (&p, &code) in group.iter().zip(&codes) {
                assert_eq!(code, u32::from(crate::vertex::reject_code(p)), "{p}");
                seen[code as usize & 0x3f] = true;
            }
        }
        // Kept positions inside and outside the clip volume, and every rejecting bit.
        assert!(seen[0] && seen[CLIPS as usize], "{seen:?}");
        for bit in 0..5 {
            assert!((0..64).any(|c| c >> bit & 1 == 1 && seen[c]), "bit {bit}");
        }
    }

    #[test]
    fn shared_corners_get_their_window_coordinates_in_the_vertex_stage() {
        let mut s = RenderState::new(97, 61);
        s.viewport = crate::state::Viewport {
            x: -13,
            y: 7,
            width: 97,
            height: 61,
        };
        s.depth_range = [0.25, 0.9];
        // 21 vertices (two groups of eight and a short one) in and around the view.
        let mut rng = crate::tests::Lcg(11);
        let mut v = Vec::new();
        for _ in 0..21 {
            let w = 0.5 + 3.0 * rng.next();
            let mut c = || (rng.next() * 4.0 - 2.0) * w;
            v.extend([c(), c(), c() * 0.5, w]);
        }
        let b = bytes(&v);
        let mut d = draw(&b, Primitive::TriangleStrip, 21);
        (d.position.size, d.position.stride) = (4, 16);
        let viewport = ViewportTransform::new(&s);
        let bits = |w: [Window; 3]| w.map(|w| (w.x, w.y, w.z.to_bits(), w.inv_w.to_bits()));
        let ix: Vec<u16> = (0..21).rev().collect();
        for (prim, indices) in [
            (Primitive::TriangleStrip, d.indices),
            (Primitive::TriangleFan, d.indices),
            (Primitive::Triangles, Indices::U16(&ix)),
        ] {
            (d.primitive, d.indices) = (prim, indices);
            let out = run(&s, &d).unwrap();
            for i in 0..19 {
                let k = [i, i + 1, i + 2].map(|i| out.slot(i));
                let got = out.corners(k).expect("shared vertices");
                let want = viewport.corners(k.map(|k| out.at(k).pos()));
                assert_eq!(bits(got), bits(want), "{prim:?} {i}");
            }
        }
        // Lines, points and a list of separate triangles leave it to set-up.
        d.indices = Indices::Range {
            first: 0,
            count: 21,
        };
        for prim in [Primitive::Lines, Primitive::Points, Primitive::Triangles] {
            d.primitive = prim;
            assert!(
                run(&s, &d).unwrap().corners([0, 1, 2]).is_none(),
                "{prim:?}"
            );
        }
    }

    #[test]
    fn sparse_indices_transform_only_what_they_use() {
        let s = RenderState::new(8, 8);
        let mut b = vec![0u8; 12 * 70000];
        b[12 * 65535..12 * 65535 + 4].copy_from_slice(&7f32.to_ne_bytes());
        let mut d = draw(&b, Primitive::Points, 0);
        let ix = [3u16, 65535, 3];
        d.indices = Indices::U16(&ix);
        let v = run(&s, &d).unwrap();
        assert_eq!(v.len(), 2);
        assert_eq!(v.get(65535).pos().x, 7.0);
        assert_eq!(v.get(3).pos().x, 0.0);
    }
}
