//! Per-fragment operations, in the specification's order (ES 1.1 chapters 3.7-4): texturing
//! and fog, alpha test, stencil test, depth test, blending, dither, logic op, and the masked
//! write. The scissor test is applied earlier, by clipping
//! every primitive's pixels to the scissor box.
//!
//! A [`FragmentKey`] is derived from the state once per draw call. It picks a span routine:
//! the common keys (no alpha test, stencil or logic op; any color format, dithered or not)
//! run a routine specialized at compile time on whether depth is tested, whether color is
//! interpolated and whether it is blended (`simple`), or, textured, on the filter as well
//! (`textured`), so a disabled feature costs nothing per pixel; keys that write nothing run
//! none; every other key runs the general routine, which tests each feature per pixel.
//!
//! Multisample operations (`GL_SAMPLE_COVERAGE`, `GL_SAMPLE_ALPHA_TO_COVERAGE`,
//! `GL_SAMPLE_ALPHA_TO_ONE`) are skipped: every config has `EGL_SAMPLE_BUFFERS` 0, and the
//! specification skips them then (ES 1.1 §4.1.3).

use std::ops::Range;
use std::sync::Arc;

use super::multisample::SamplePass;
use super::raster::{Prim, Span};
use super::setup::{Shading, TexPlanes};
use super::state::{
    AlphaTest, Blend, BlendEquation, BlendFactor, CompareFunc, LogicOp, Quality, RenderState,
    StencilOp, StencilTest,
};
use super::target::{expand_to_8, keep_mask, BandMut, ColorFormat, DepthFormat, TargetFormat};
use super::texenv::{self, Fog, TextureUnit};
use super::texture::{MagFilter, MinFilter, Sampler};
use super::TEXTURE_UNITS;

mod routines;
use routines::{simple, textured};

/// Which span routine a key runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Route {
    /// Nothing reaches the color buffer and no test can change depth or stencil (so
    /// coverage, which only changes alpha, cannot matter either).
    Nothing,
    /// `Simple<DEPTH, SMOOTH, BLEND>`: no alpha test, stencil or logic op.
    Simple {
        depth: bool,
        smooth: bool,
        blend: bool,
    },
    /// `textured<TEX, DEPTH, BLEND>`: texture units (any environment, no cube maps) and
    /// fog, no alpha test, stencil or logic op. `filter` is the first unit's `F_*`
    /// class (`F_NONE`: fog only).
    Textured {
        filter: u8,
        depth: bool,
        blend: bool,
    },
    General,
}

/// Texture filters the textured span routine is specialized on.
const F_NONE: u8 = 0;
/// NEAREST for both minification and magnification: level 0, no level of detail. On
/// affine spans (q/w constant) texture coordinates step without a divide.
const F_NEAREST: u8 = 1;
/// LINEAR for both: bilinear on level 0, no level of detail.
const F_BILINEAR: u8 = 2;
/// LINEAR_MIPMAP_LINEAR with LINEAR magnification.
const F_TRILINEAR: u8 = 3;
/// Any other filter pair: λ picks the filter and the levels.
const F_LOD: u8 = 4;
/// More than one unit: each unit's filter is chosen per group.
const F_MULTI: u8 = 5;

/// Texturing and fog for a draw call: the enabled units (index and state) in order, fog,
/// and where the level of detail is computed.
#[derive(Debug, PartialEq)]
pub struct TexStage {
    units: Vec<(usize, TextureUnit)>,
    fog: Option<Fog>,
    /// An environment reads another unit's texel (`OES_texture_env_crossbar`): every unit
    /// is sampled before the first environment, on the general route only.
    crossbar: bool,
    /// A unit filters anisotropically (`EXT_texture_filter_anisotropic`): the general
    /// route only.
    anisotropic: bool,
}

impl TexStage {
    fn new(state: &RenderState) -> Option<TexStage> {
        let units: Vec<(usize, TextureUnit)> = state
            .textures
            .iter()
            .enumerate()
            .filter_map(|(i, u)| u.clone().map(|u| (i, u)))
            .collect();
        if units.is_empty() && state.fog.is_none() {
            return None;
        }
        let crossbar = units.iter().any(|(_, u)| u.env.reads_other_units());
        let anisotropic = units.iter().any(|(_, u)| u.sampler.max_anisotropy > 1.0);
        Some(TexStage {
            units,
            fog: state.fog,
            crossbar,
            anisotropic,
        })
    }

    /// The filter class of a single unit, `F_NONE` for none, `F_MULTI` for more. F_NEAREST
    /// and F_BILINEAR skip λ: their minification and magnification filters are the same
    /// filter on level 0, so no λ, whatever the `EXT_texture_lod_bias` bias, changes what
    /// they sample; every route that picks a level adds the bias.
    fn filter(&self) -> u8 {
        match &self.units[..] {
            [] => F_NONE,
            [(_, u)] => filter_of(&u.sampler),
            _ => F_MULTI,
        }
    }
}

/// The filter class of a sampler.
fn filter_of(sm: &Sampler) -> u8 {
    match (sm.min, sm.mag) {
        (MinFilter::Nearest, MagFilter::Nearest) => F_NEAREST,
        (MinFilter::Linear, MagFilter::Linear) => F_BILINEAR,
        (MinFilter::LinearMipmapLinear, MagFilter::Linear) => F_TRILINEAR,
        _ => F_LOD,
    }
}

/// One unit's texture coordinates along a span: s/w, t/w, q/w at the first pixel and their
/// steps per pixel in x (and per row in y, for the level of detail). Affine spans (q/w the
/// same everywhere) are divided once, here.
#[derive(Clone, Copy, Debug, Default)]
struct UnitCoords {
    s0: f32,
    t0: f32,
    q0: f32,
    ds: f32,
    dt: f32,
    dq: f32,
    sy: f32,
    ty: f32,
    qy: f32,
    w: f32,
    h: f32,
    affine: bool,
    /// r/w and its steps, for cube maps (whose s/w, t/w above are then undivided).
    r0: f32,
    dr: f32,
    ry: f32,
}

impl UnitCoords {
    #[inline]
    fn new(p: &TexPlanes, px: i32, py: i32, (w, h): (u32, u32), cube: bool) -> UnitCoords {
        let q0 = p.q.at(px, py);
        // Cube maps ignore q (it only scales the direction), so nothing is divided.
        let affine = !cube && p.q.dx == 0.0 && p.q.dy == 0.0 && q0 != 0.0;
        let k = if affine { 1.0 / q0 } else { 1.0 };
        UnitCoords {
            s0: (p.s.at(px, py) * k) as f32,
            t0: (p.t.at(px, py) * k) as f32,
            q0: (q0 * k) as f32,
            ds: (p.s.dx * k) as f32,
            dt: (p.t.dx * k) as f32,
            dq: (p.q.dx * k) as f32,
            sy: (p.s.dy * k) as f32,
            ty: (p.t.dy * k) as f32,
            qy: (p.q.dy * k) as f32,
            w: w as f32,
            h: h as f32,
            affine,
            r0: p.r.at(px, py) as f32,
            dr: p.r.dx as f32,
            ry: p.r.dy as f32,
        }
    }

    /// A cube map's value at pixel `i` (`OES_texture_cube_map`): the face whose axis is
    /// the largest component of (s, t, r) (ties go to x, then y), the face coordinates
    /// ((sc/|ma| + 1)/2, (tc/|ma| + 1)/2) of the specification's table, and λ from their
    /// exact derivatives (each a ratio of two quantities linear in window space: the 1/w
    /// of perspective and any q cancel), sampled in that face, in [0, 1].
    #[inline]
    fn cube(&self, faces: &[Sampler; 6], i: usize) -> [f32; 4] {
        let fi = i as f32;
        // (value, d/dx, d/dy) of s/w, t/w, r/w.
        let s = (self.s0 + self.ds * fi, self.ds, self.sy);
        let t = (self.t0 + self.dt * fi, self.dt, self.ty);
        let r = (self.r0 + self.dr * fi, self.dr, self.ry);
        let (face, sc, tc, ma) = cube_face(s, t, r);
        let faces = &faces[face];
        let (u, v, rho2) = cube_coords(sc, tc, ma, faces.size().0 as f32);
        faces.sample(u, v, Sampler::lambda(rho2))
    }
}

/// A value linear in window space at a pixel, with its x and y derivatives.
type Lin = (f32, f32, f32);

fn neg((a, b, c): Lin) -> Lin {
    (-a, -b, -c)
}

/// Face selection (`OES_texture_cube_map`'s table): the face index (POSITIVE_X,
/// NEGATIVE_X, POSITIVE_Y, NEGATIVE_Y, POSITIVE_Z, NEGATIVE_Z) and sc, tc, ma.
#[inline]
fn cube_face(s: Lin, t: Lin, r: Lin) -> (usize, Lin, Lin, Lin) {
    let (ax, ay, az) = (s.0.abs(), t.0.abs(), r.0.abs());
    if ax >= ay && ax >= az {
        if s.0 >= 0.0 {
            (0, neg(r), neg(t), s)
        } else {
            (1, r, neg(t), s)
        }
    } else if ay >= az {
        if t.0 >= 0.0 {
            (2, s, r, t)
        } else {
            (3, s, neg(r), t)
        }
    } else if r.0 >= 0.0 {
        (4, s, neg(t), r)
    } else {
        (5, neg(s), neg(t), r)
    }
}

/// Face coordinates ((sc/|ma| + 1)/2, (tc/|ma| + 1)/2) and ρ² for a face `size` texels
/// wide, from the quotient rule on the linear sc, tc and ma.
#[inline]
fn cube_coords(sc: Lin, tc: Lin, ma: Lin, size: f32) -> (f32, f32, f32) {
    let m = if ma.0 < 0.0 { neg(ma) } else { ma };
    let inv = 1.0 / m.0;
    let u = 0.5 * (sc.0 * inv + 1.0);
    let v = 0.5 * (tc.0 * inv + 1.0);
    let k = 0.5 * inv * inv * size;
    let ux = (sc.1 * m.0 - sc.0 * m.1) * k;
    let uy = (sc.2 * m.0 - sc.0 * m.2) * k;
    let vx = (tc.1 * m.0 - tc.0 * m.1) * k;
    let vy = (tc.2 * m.0 - tc.0 * m.2) * k;
    (u, v, (ux * ux + vx * vx).max(uy * uy + vy * vy))
}

#[cfg(test)]
pub(crate) fn cube_lookup(s: f32, t: f32, r: f32) -> (usize, f32, f32) {
    let (f, sc, tc, ma) = cube_face((s, 0.0, 0.0), (t, 0.0, 0.0), (r, 0.0, 0.0));
    let (u, v, _) = cube_coords(sc, tc, ma, 1.0);
    (f, u, v)
}

impl UnitCoords {
    /// (s, t) at pixel `i` of the span.
    #[inline(always)]
    fn st(&self, i: usize) -> (f32, f32) {
        let fi = i as f32;
        let (s, t) = (self.s0 + self.ds * fi, self.t0 + self.dt * fi);
        if self.affine {
            (s, t)
        } else {
            let r = 1.0 / (self.q0 + self.dq * fi);
            (s * r, t * r)
        }
    }

    /// λ at pixel `i` where the coordinates are (s, t): ρ from the exact derivatives of
    /// the quotients (d(a/q) = (da − (a/q)·dq)/q).
    #[inline(always)]
    fn lambda(&self, i: usize, s: f32, t: f32) -> f32 {
        let r = if self.affine {
            1.0
        } else {
            1.0 / (self.q0 + self.dq * i as f32)
        };
        let ux = (self.ds - s * self.dq) * r * self.w;
        let vx = (self.dt - t * self.dq) * r * self.h;
        let uy = (self.sy - s * self.qy) * r * self.w;
        let vy = (self.ty - t * self.qy) * r * self.h;
        Sampler::lambda((ux * ux + vx * vx).max(uy * uy + vy * vy))
    }

    /// `EXT_texture_filter_anisotropic` at pixel `i` where the coordinates are (s, t), as
    /// the extension suggests: with P_max and P_min the footprint's long and short axes in
    /// texels, N = min(⌈P_max / P_min⌉, the sampler's limit) samples at λ = log₂(P_max / N),
    /// spread evenly along the long axis ((k + 1)/(N + 1) − ½ of it, k < N) and averaged.
    /// N = 1 is exactly isotropic filtering.
    fn anisotropic(&self, sm: &Sampler, i: usize, s: f32, t: f32) -> [f32; 4] {
        let r = if self.affine {
            1.0
        } else {
            1.0 / (self.q0 + self.dq * i as f32)
        };
        // Derivatives of (s, t) per pixel in x and in y.
        let (sx, tx) = ((self.ds - s * self.dq) * r, (self.dt - t * self.dq) * r);
        let (sy, ty) = ((self.sy - s * self.qy) * r, (self.ty - t * self.qy) * r);
        let px2 = (sx * self.w).powi(2) + (tx * self.h).powi(2);
        let py2 = (sy * self.w).powi(2) + (ty * self.h).powi(2);
        let (major2, minor2, ds, dt) = if px2 >= py2 {
            (px2, py2, sx, tx)
        } else {
            (py2, px2, sy, ty)
        };
        let ratio = (major2 / minor2).sqrt().ceil();
        // NaN (a point footprint) and infinity (a line) are caught by the comparisons.
        let n = if ratio >= 1.0 {
            ratio.min(sm.max_anisotropy.floor()) as usize
        } else {
            1
        };
        let lambda = Sampler::lambda(major2 / (n * n) as f32);
        if n == 1 {
            return sm.sample(s, t, lambda);
        }
        let mut sum = [0.0; 4];
        for k in 0..n {
            let o = (k + 1) as f32 / (n + 1) as f32 - 0.5;
            let v = sm.sample(s + ds * o, t + dt * o, lambda);
            sum.iter_mut().zip(v).for_each(|(a, v)| *a += v);
        }
        sum.map(|a| a / n as f32)
    }
}

/// Texturing and fog along one span.
struct SpanTexturing<'a> {
    stage: &'a TexStage,
    spans: [UnitCoords; TEXTURE_UNITS],
    fog0: f32,
    dfog: f32,
    inv_w0: f32,
    d_inv_w: f32,
}

impl<'a> SpanTexturing<'a> {
    // Inlined so that the caller builds it in place: returned, it is a copy of several
    // hundred bytes per span.
    #[inline(always)]
    fn new(stage: &'a TexStage, t: &Shading, span: Span) -> SpanTexturing<'a> {
        let (px, py) = (span.x0 - t.origin.0, span.y - t.origin.1);
        let mut spans = [UnitCoords::default(); TEXTURE_UNITS];
        if let Some(planes) = t.tex.as_deref() {
            for (n, (u, unit)) in stage.units.iter().enumerate() {
                let cube = unit.sampler.cube.is_some();
                spans[n] = UnitCoords::new(&planes[*u], px, py, unit.sampler.size(), cube);
            }
        }
        SpanTexturing {
            stage,
            spans,
            fog0: t.fog.at(px, py) as f32,
            dfog: t.fog.dx as f32,
            inv_w0: t.inv_w.at(px, py) as f32,
            d_inv_w: t.inv_w.dx as f32,
        }
    }

    /// Fog on `c` at pixel `i`.
    #[inline(always)]
    fn fog(&self, i: usize, c: &mut [f32; 4]) {
        if let Some(f) = &self.stage.fog {
            let fi = i as f32;
            let v = (self.fog0 + self.dfog * fi) / (self.inv_w0 + self.d_inv_w * fi);
            let factor = if f.per_pixel() {
                f.factor(v)
            } else {
                v.clamp(0.0, 1.0)
            };
            f.apply(factor, c);
        }
    }

    /// Every enabled unit in order, then fog: the textured color at pixel `i` of a
    /// fragment whose primary color is `primary`.
    #[inline]
    fn apply(&mut self, i: usize, primary: [f32; 4]) -> [f32; 4] {
        let stage = self.stage;
        if stage.crossbar {
            return self.apply_crossbar(i, primary);
        }
        let mut c = primary;
        for (n, (_, unit)) in stage.units.iter().enumerate() {
            let texel = self.texel(n, i);
            c = texenv::apply(&unit.env, unit.sampler.format, texel, c, primary);
        }
        self.fog(i, &mut c);
        c
    }

    /// [`SpanTexturing::apply`] when an environment reads other units: every texel first.
    #[inline(never)]
    fn apply_crossbar(&mut self, i: usize, primary: [f32; 4]) -> [f32; 4] {
        let stage = self.stage;
        let mut texels = [[0.0; 4]; TEXTURE_UNITS];
        for (n, (u, _)) in stage.units.iter().enumerate() {
            texels[*u] = self.texel(n, i);
        }
        let mut c = primary;
        for (u, unit) in &stage.units {
            let (env, format) = (&unit.env, unit.sampler.format);
            c = texenv::apply_crossbar(env, format, texels[*u], c, primary, &texels);
        }
        self.fog(i, &mut c);
        c
    }

    /// The texel of the `n`th enabled unit at pixel `i`.
    #[inline(always)]
    fn texel(&mut self, n: usize, i: usize) -> [f32; 4] {
        let unit = &self.stage.units[n].1;
        if let Some(faces) = &unit.sampler.cube {
            return self.spans[n].cube(faces, i);
        }
        let (s, t) = self.spans[n].st(i);
        if unit.sampler.max_anisotropy > 1.0 {
            return self.spans[n].anisotropic(&unit.sampler, i, s, t);
        }
        let lambda = self.spans[n].lambda(i, s, t);
        unit.sampler.sample(s, t, lambda)
    }
}

/// What the fragment stage does for the current state, decided once per draw call.
#[derive(Clone, Debug, PartialEq)]
pub struct FragmentKey {
    color: ColorFormat,
    /// Stored bits the color mask protects; all ones means color is not written.
    keep: u32,
    /// The depth test, present only when enabled and the target has depth.
    depth: Option<(CompareFunc, DepthFormat)>,
    depth_write: bool,
    /// Present only when enabled and the target has stencil.
    stencil: Option<StencilTest>,
    stencil_writemask: u8,
    alpha: Option<AlphaTest>,
    /// A sample plane's alpha to coverage and alpha to one (ES 1.1 §4.1.3), present only
    /// when either is on.
    sample: Option<SamplePass>,
    blend: Option<Blend>,
    logic_op: Option<LogicOp>,
    /// Ordered dithering, only where it changes something: channels narrower than 8 bits.
    dither: bool,
    flat: bool,
    perspective: Quality,
    /// Texturing and fog, when either is on.
    tex: Option<Arc<TexStage>>,
    route: Route,
}

impl FragmentKey {
    /// The key of a draw with `state` into a target of `format`; `flat` when each of its
    /// primitives takes one color ([`crate::flat_colors`]).
    pub fn new(state: &RenderState, format: TargetFormat, flat: bool) -> FragmentKey {
        let depth = state.depth_test.zip(format.depth);
        // The reference clamped to the 8-bit buffer once here, not per fragment.
        let stencil = state
            .stencil_test
            .filter(|_| format.stencil_bits > 0)
            .map(|s| StencilTest {
                reference: s.reference.clamp(0, 255),
                ..s
            });
        let keep = keep_mask(state.color_mask);
        let logic_op = state.logic_op;
        // Logic op replaces blending (ES 1.1 §4.1.10).
        let blend = state.blend.filter(|_| logic_op.is_none());
        let dither = state.dither
            && format.color != ColorFormat::Rgba8888
            && format.color != ColorFormat::Rgb888;
        let mut key = FragmentKey {
            color: format.color,
            keep,
            depth,
            // Depth is written only when the test is enabled (ES 1.1 §4.1.6).
            depth_write: depth.is_some() && state.depth_write,
            stencil,
            stencil_writemask: state.stencil_writemask as u8,
            alpha: state.alpha_test,
            sample: state
                .sample
                .filter(|s| s.alpha_min.is_some() || s.alpha_to_one),
            blend,
            logic_op,
            dither,
            flat,
            perspective: state.perspective,
            tex: TexStage::new(state).map(Arc::new),
            route: Route::General,
        };
        key.route = if key.stencil.is_none() && keep == u32::MAX && !key.depth_write {
            Route::Nothing
        } else if key.alpha.is_some()
            || key.stencil.is_some()
            || key.logic_op.is_some()
            || key.sample.is_some()
        {
            Route::General
        } else if let Some(stage) = &key.tex {
            // Cube maps, crossbar environments and anisotropic filtering run the general
            // routine.
            if !stage.crossbar
                && !stage.anisotropic
                && stage.units.iter().all(|(_, u)| u.sampler.cube.is_none())
            {
                Route::Textured {
                    filter: stage.filter(),
                    depth: key.depth.is_some(),
                    blend: key.blend.is_some(),
                }
            } else {
                Route::General
            }
        } else {
            Route::Simple {
                depth: key.depth.is_some(),
                smooth: !key.flat,
                blend: key.blend.is_some(),
            }
        };
        key
    }

    /// Shades the pixels of primitive `p` on rows `rows`, which lie inside the band.
    pub fn shade(&self, p: &Prim, rows: Range<i32>, band: &mut BandMut<'_>) {
        let t = p.shading();
        if let (Route::Simple { .. }, None) = (self.route, &t.coverage) {
            return p.spans(rows, |span| self.simple(t, span, band));
        }
        // The textured and the general routes take a primitive's spans in one call, so the
        // route and its instruction set are chosen once for them all (sprites 20.0 → 18.5
        // ms). A primitive is convex: a span a row, and a band has 16 rows.
        let mut spans = [Span { y: 0, x0: 0, x1: 0 }; 16];
        let mut n = 0;
        p.spans(rows, |span| {
            if n == spans.len() {
                self.spans(t, &spans, band);
                n = 0;
            }
            spans[n] = span;
            n += 1;
        });
        self.spans(t, &spans[..n], band);
    }

    /// A span of a primitive that takes the `Simple` route.
    #[inline]
    fn simple(&self, t: &Shading, span: Span, band: &mut BandMut<'_>) {
        let Route::Simple {
            depth,
            smooth,
            blend,
        } = self.route
        else {
            unreachable!("called for the simple route")
        };
        match (depth, smooth, blend) {
            (false, false, false) => simple::<false, false, false>(self, t, span, band),
            (false, false, true) => simple::<false, false, true>(self, t, span, band),
            (false, true, false) => simple::<false, true, false>(self, t, span, band),
            (false, true, true) => simple::<false, true, true>(self, t, span, band),
            (true, false, false) => simple::<true, false, false>(self, t, span, band),
            (true, false, true) => simple::<true, false, true>(self, t, span, band),
            (true, true, false) => simple::<true, true, false>(self, t, span, band),
            (true, true, true) => simple::<true, true, true>(self, t, span, band),
        }
    }

    /// Spans of one primitive on the textured or the general route.
    fn spans(&self, t: &Shading, spans: &[Span], band: &mut BandMut<'_>) {
        // An antialiased primitive always takes the general route.
        if t.coverage.is_some() {
            return general(self, t, spans, band);
        }
        match self.route {
            Route::Nothing => {}
            Route::Textured {
                filter,
                depth,
                blend,
            } => {
                macro_rules! by_filter {
                    ($d:literal, $b:literal) => {
                        match filter {
                            F_NONE => textured::<F_NONE, $d, $b>(self, t, spans, band),
                            F_NEAREST => textured::<F_NEAREST, $d, $b>(self, t, spans, band),
                            F_BILINEAR => textured::<F_BILINEAR, $d, $b>(self, t, spans, band),
                            F_TRILINEAR => textured::<F_TRILINEAR, $d, $b>(self, t, spans, band),
                            F_LOD => textured::<F_LOD, $d, $b>(self, t, spans, band),
                            _ => textured::<F_MULTI, $d, $b>(self, t, spans, band),
                        }
                    };
                }
                match (depth, blend) {
                    (false, false) => by_filter!(false, false),
                    (false, true) => by_filter!(false, true),
                    (true, false) => by_filter!(true, false),
                    (true, true) => by_filter!(true, true),
                }
            }
            Route::Simple { .. } | Route::General => general(self, t, spans, band),
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Divide {
    /// w is the same at every vertex (no perspective): colors are linear, no divide.
    None,
    /// A divide per pixel.
    Exact,
}

/// Interpolates a primitive's color and depth along one span: values at the span's first
/// pixel plus a per-pixel step, evaluated as `start + i·step` so error does not accumulate.
struct SpanInterp {
    z0: f64,
    dz: f64,
    inv_w0: f32,
    d_inv_w: f32,
    c0: [f32; 4],
    dc: [f32; 4],
    divide: Divide,
    len: usize,
}

impl SpanInterp {
    #[inline]
    fn new(t: &Shading, span: Span) -> SpanInterp {
        let depth = SpanInterp::depth_only(t, span);
        let (px, py) = (span.x0 - t.origin.0, span.y - t.origin.1);
        // Written out per channel: `array::map` leaves its closure as a call per span.
        let (at, dx) = (t.color_w.at(px, py), t.color_w.dx);
        let mut c0 = [at[0] as f32, at[1] as f32, at[2] as f32, at[3] as f32];
        let mut dc = [dx[0] as f32, dx[1] as f32, dx[2] as f32, dx[3] as f32];
        let inv_w0 = t.inv_w.at(px, py) as f32;
        let divide = if t.inv_w.dx == 0.0 && t.inv_w.dy == 0.0 {
            // Constant w: fold it into the planes once.
            let w = 1.0 / inv_w0;
            for (c, d) in c0.iter_mut().zip(&mut dc) {
                *c *= w;
                *d *= w;
            }
            Divide::None
        } else {
            Divide::Exact
        };
        SpanInterp {
            inv_w0,
            d_inv_w: t.inv_w.dx as f32,
            c0,
            dc,
            divide,
            ..depth
        }
    }

    /// The span's depth alone, for a routine that reads no interpolated color (flat
    /// shading): no color plane evaluated and no 1/w divided per span.
    #[inline]
    fn depth_only(t: &Shading, span: Span) -> SpanInterp {
        let (px, py) = (span.x0 - t.origin.0, span.y - t.origin.1);
        SpanInterp {
            z0: t.z.at(px, py),
            dz: t.z.dx,
            inv_w0: 1.0,
            d_inv_w: 0.0,
            c0: [0.0; 4],
            dc: [0.0; 4],
            divide: Divide::None,
            len: (span.x1 - span.x0) as usize,
        }
    }

    #[inline]
    fn z(&self, i: usize) -> f64 {
        self.z0 + self.dz * i as f64
    }

    #[inline]
    fn exact(&self, i: usize) -> [f32; 4] {
        let fi = i as f32;
        let w = 1.0 / (self.inv_w0 + self.d_inv_w * fi);
        std::array::from_fn(|c| (self.c0[c] + self.dc[c] * fi) * w)
    }

    /// The color at pixel `i` of the span.
    #[inline(always)]
    fn color(&self, i: usize) -> [f32; 4] {
        match self.divide {
            Divide::None => {
                let fi = i as f32;
                std::array::from_fn(|c| self.c0[c] + self.dc[c] * fi)
            }
            Divide::Exact => self.exact(i),
        }
    }
}

/// The routine for every key: each enabled operation, per pixel, in the specification's
/// order, over a primitive's spans in a band.
#[cfg_attr(
    not(fuzzing),
    multiversion::multiversion(targets("x86_64+avx2", "x86_64+sse4.1"))
)]
fn general<'a>(k: &FragmentKey, t: &Shading, spans: &[Span], band: &mut BandMut<'a>) {
    for &span in spans {
        general_span(k, t, span, band);
    }
}

/// One span of [`general`].
#[inline(always)]
fn general_span(k: &FragmentKey, t: &Shading, span: Span, band: &mut BandMut<'_>) {
    let interp = if t.flat.is_some() {
        SpanInterp::depth_only(t, span)
    } else {
        SpanInterp::new(t, span)
    };
    let mut tex = k
        .tex
        .as_deref()
        .map(|stage| SpanTexturing::new(stage, t, span));
    let row = (span.y - band.y0) as usize * band.width;
    for (i, x) in (span.x0..span.x1).enumerate() {
        let at = row + x as usize;
        let mut src = match t.flat {
            Some(c) => c,
            None => interp.color(i),
        };
        if let Some(c) = &t.coverage {
            // Antialiasing multiplies alpha by coverage (ES 1.1 §3.2); a pixel the
            // primitive misses produces no fragment.
            let share = c.at(x, span.y);
            if share == 0.0 {
                continue;
            }
            if let Some(tex) = &mut tex {
                src = tex.apply(i, src);
            }
            src[3] *= share;
        } else if let Some(tex) = &mut tex {
            src = tex.apply(i, src);
        }
        if let Some(s) = k.sample {
            // §4.1.3 comes before the alpha test: a fragment whose alpha leaves this
            // plane's sample out of the mask stops here, and alpha to one feeds the rest.
            if s.alpha_min.is_some_and(|min| alpha_byte(src[3]) < min) {
                continue;
            }
            if s.alpha_to_one {
                src[3] = 1.0;
            }
        }
        if let Some(a) = k.alpha {
            // Both sides at 8-bit precision, so a reference equal to a vertex alpha compares
            // equal however the alpha was interpolated.
            if !a.func.test(alpha_byte(src[3]), alpha_byte(a.reference)) {
                continue;
            }
        }
        if let Some(s) = k.stencil {
            let stored = band.stencil[at];
            let reference = s.reference as u8;
            let mask = s.mask as u8;
            if !s.func.test(reference & mask, stored & mask) {
                band.stencil[at] = stencil_write(s.fail, stored, reference, k.stencil_writemask);
                continue;
            }
        }
        if let Some((func, df)) = k.depth {
            let z = df.quantize(interp.z(i));
            if !func.test(z, band.depth[at]) {
                if let Some(s) = k.stencil {
                    let stored = band.stencil[at];
                    let r = s.reference as u8;
                    band.stencil[at] = stencil_write(s.depth_fail, stored, r, k.stencil_writemask);
                }
                continue;
            }
            if k.depth_write {
                band.depth[at] = z;
            }
        }
        if let Some(s) = k.stencil {
            let stored = band.stencil[at];
            let r = s.reference as u8;
            band.stencil[at] = stencil_write(s.depth_pass, stored, r, k.stencil_writemask);
        }
        if k.keep == u32::MAX {
            continue;
        }
        let dst = band.color[at];
        let src = match k.blend {
            Some(b) => blend(&b, src, decode(k.color, dst)),
            None => src,
        };
        let mut word = if k.dither {
            encode_dithered(k.color, src, x, span.y)
        } else {
            k.color.encode(src)
        };
        if let Some(op) = k.logic_op {
            word = logic_op(k.color, op, word, dst);
        }
        band.color[at] = (dst & k.keep) | (word & !k.keep);
    }
}

/// An alpha value as the 8-bit number the alpha test and `alpha_min` compare.
fn alpha_byte(c: f32) -> u8 {
    (c.clamp(0.0, 1.0) * 255.0 + 0.5) as u8
}

/// The new stencil value after `op`, through the write mask.
fn stencil_write(op: StencilOp, stored: u8, reference: u8, writemask: u8) -> u8 {
    let v = match op {
        StencilOp::Keep => return stored,
        StencilOp::Zero => 0,
        StencilOp::Replace => reference,
        StencilOp::Incr => stored.saturating_add(1),
        StencilOp::Decr => stored.saturating_sub(1),
        StencilOp::Invert => !stored,
        StencilOp::IncrWrap => stored.wrapping_add(1),
        StencilOp::DecrWrap => stored.wrapping_sub(1),
    };
    (stored & !writemask) | (v & writemask)
}

/// The stored color as values in [0, 1]: each channel's n-bit value over 2ⁿ − 1, exactly
/// (not the widened 8-bit byte over 255); 1 for a missing alpha.
#[inline(always)]
fn decode(format: ColorFormat, word: u32) -> [f32; 4] {
    const INV_255: f32 = 1.0 / 255.0;
    let bytes = word.to_le_bytes();
    match format {
        // Every 8-bit byte is its own value; a missing alpha is stored as 255.
        ColorFormat::Rgba8888 | ColorFormat::Rgb888 => bytes.map(|b| b as f32 * INV_255),
        _ => {
            let bits = format.bits();
            std::array::from_fn(|c| match bits[c] {
                0 => 1.0,
                n => (bytes[c] >> (8 - n)) as f32 / ((1u32 << n) - 1) as f32,
            })
        }
    }
}

/// A blend factor for all four channels at once (one decision per pixel, not per channel).
/// The alpha lane of `SRC_ALPHA_SATURATE` is 1.
#[inline(always)]
fn factors(f: BlendFactor, src: &[f32; 4], dst: &[f32; 4]) -> [f32; 4] {
    match f {
        BlendFactor::Zero => [0.0; 4],
        BlendFactor::One => [1.0; 4],
        BlendFactor::SrcColor => *src,
        BlendFactor::OneMinusSrcColor => src.map(|c| 1.0 - c),
        BlendFactor::DstColor => *dst,
        BlendFactor::OneMinusDstColor => dst.map(|c| 1.0 - c),
        BlendFactor::SrcAlpha => [src[3]; 4],
        BlendFactor::OneMinusSrcAlpha => [1.0 - src[3]; 4],
        BlendFactor::DstAlpha => [dst[3]; 4],
        BlendFactor::OneMinusDstAlpha => [1.0 - dst[3]; 4],
        BlendFactor::SrcAlphaSaturate => {
            let f = src[3].min(1.0 - dst[3]);
            [f, f, f, 1.0]
        }
    }
}

/// One channel of the blend equation of source `s` and destination `d` with their
/// factors (which MIN and MAX do not use).
#[inline]
fn combine(eq: BlendEquation, s: f32, sf: f32, d: f32, df: f32) -> f32 {
    match eq {
        BlendEquation::Add => s * sf + d * df,
        BlendEquation::Subtract => s * sf - d * df,
        BlendEquation::ReverseSubtract => d * df - s * sf,
        BlendEquation::Min => s.min(d),
        BlendEquation::Max => s.max(d),
    }
}

/// Blends `src` (clamped to [0, 1] first) over `dst`; the result is clamped by the encoder.
#[inline(always)]
fn blend(b: &Blend, src: [f32; 4], dst: [f32; 4]) -> [f32; 4] {
    let src = src.map(|c| c.clamp(0.0, 1.0));
    let sf = factors(b.src_rgb, &src, &dst);
    let df = factors(b.dst_rgb, &src, &dst);
    let mut out = [0.0; 4];
    if b.eq_rgb == BlendEquation::Add {
        for c in 0..3 {
            out[c] = src[c] * sf[c] + dst[c] * df[c];
        }
    } else {
        for c in 0..3 {
            out[c] = combine(b.eq_rgb, src[c], sf[c], dst[c], df[c]);
        }
    }
    let (sa, da) = if (b.src_alpha, b.dst_alpha) == (b.src_rgb, b.dst_rgb) {
        (sf[3], df[3])
    } else {
        (
            factors(b.src_alpha, &src, &dst)[3],
            factors(b.dst_alpha, &src, &dst)[3],
        )
    };
    out[3] = combine(b.eq_alpha, src[3], sa, dst[3], da);
    out
}

/// The 4×4 ordered-dither (Bayer) matrix, by y and x mod 4.
const BAYER: [[u8; 4]; 4] = [[0, 8, 2, 10], [12, 4, 14, 6], [3, 11, 1, 9], [15, 7, 13, 5]];

/// A 4×4 ordered-dither threshold for pixel (x, y), in (0, 1).
#[inline(always)]
fn dither_threshold(x: i32, y: i32) -> f32 {
    (BAYER[(y & 3) as usize][(x & 3) as usize] as f32 + 0.5) / 16.0
}

/// Quantizes with ordered dithering: `floor(c · (2ⁿ − 1) + t)` picks one of the two nearest
/// representable values, and a value that is already representable stays itself. Inlined,
/// so `floor` takes the calling span routine's instruction set (a libm call otherwise).
#[inline(always)]
fn encode_dithered(format: ColorFormat, rgba: [f32; 4], x: i32, y: i32) -> u32 {
    let bits = format.bits();
    let t = dither_threshold(x, y);
    let bytes: [u8; 4] = std::array::from_fn(|c| match bits[c] {
        0 => 255,
        n => {
            let max = ((1u32 << n) - 1) as f32;
            let v = (rgba[c].clamp(0.0, 1.0) * max + t).floor().min(max) as u32;
            expand_to_8(v, n)
        }
    });
    u32::from_le_bytes(bytes)
}

/// Applies `op` to the stored n-bit values of each channel.
fn logic_op(format: ColorFormat, op: LogicOp, src: u32, dst: u32) -> u32 {
    let bits = format.bits();
    let (s, d) = (src.to_le_bytes(), dst.to_le_bytes());
    let bytes: [u8; 4] = std::array::from_fn(|c| match bits[c] {
        0 => 255,
        n => {
            let shift = 8 - n;
            let v = op.apply((s[c] >> shift) as u32, (d[c] >> shift) as u32) & ((1 << n) - 1);
            expand_to_8(v, n)
        }
    });
    u32::from_le_bytes(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dithering_keeps_representable_values_and_picks_a_neighbour_otherwise() {
        for x in 0..4 {
            for y in 0..4 {
                let w = encode_dithered(ColorFormat::Rgb565, [1.0, 0.0, 16.0 / 31.0, 1.0], x, y);
                assert_eq!(w, ColorFormat::Rgb565.encode([1.0, 0.0, 16.0 / 31.0, 1.0]));
                let v = 10.4 / 31.0;
                let b = encode_dithered(ColorFormat::Rgb565, [v, v, v, 1.0], x, y).to_le_bytes();
                assert!(b[0] == expand_to_8(10, 5) || b[0] == expand_to_8(11, 5));
            }
        }
    }

    #[test]
    fn decode_inverts_encode_exactly() {
        for f in [
            ColorFormat::Rgb565,
            ColorFormat::Rgb888,
            ColorFormat::Rgba8888,
        ] {
            for v in 0..=31u32 {
                let c = v as f32 / 31.0;
                let w = f.encode([c, c, c, c]);
                assert_eq!(f.encode(decode(f, w)), w);
            }
        }
    }

    #[test]
    fn logic_ops_work_on_the_stored_bits() {
        let f = ColorFormat::Rgb565;
        let s = f.encode([1.0, 0.0, 1.0, 1.0]);
        let d = f.encode([1.0, 1.0, 0.0, 1.0]);
        assert_eq!(
            logic_op(f, LogicOp::Xor, s, d),
            f.encode([0.0, 1.0, 1.0, 1.0])
        );
        assert_eq!(logic_op(f, LogicOp::Set, s, d), f.encode([1.0; 4]));
        let g = ColorFormat::Rgba8888;
        assert_eq!(logic_op(g, LogicOp::Invert, 0, 0x12345678), !0x12345678u32);
    }

    #[test]
    fn stencil_ops_saturate_wrap_and_respect_the_write_mask() {
        assert_eq!(stencil_write(StencilOp::Incr, 255, 0, 0xFF), 255);
        assert_eq!(stencil_write(StencilOp::Decr, 0, 0, 0xFF), 0);
        assert_eq!(stencil_write(StencilOp::IncrWrap, 255, 0, 0xFF), 0);
        assert_eq!(stencil_write(StencilOp::DecrWrap, 0, 0, 0xFF), 255);
        assert_eq!(stencil_write(StencilOp::Replace, 0xF0, 0x0F, 0x03), 0xF3);
        assert_eq!(stencil_write(StencilOp::Invert, 0x0F, 0, 0xF0), 0xFF);
    }

    #[test]
    fn cube_faces_follow_the_extension_table() {
        // (direction) -> (face, s, t): sc/|ma| and tc/|ma| of 0.5 map to 0.75.
        let cases = [
            ((1.0, -0.5, -0.5), (0, 0.75, 0.75)),
            ((-1.0, -0.5, 0.5), (1, 0.75, 0.75)),
            ((0.5, 1.0, 0.5), (2, 0.75, 0.75)),
            ((0.5, -1.0, -0.5), (3, 0.75, 0.75)),
            ((0.5, -0.5, 1.0), (4, 0.75, 0.75)),
            ((-0.5, -0.5, -1.0), (5, 0.75, 0.75)),
            // Ties go to x, then y.
            ((1.0, 1.0, 1.0), (0, 0.0, 0.0)),
            ((0.0, -1.0, 1.0), (3, 0.5, 0.0)),
        ];
        for ((s, t, r), want) in cases {
            assert_eq!(cube_lookup(s, t, r), want, "({s}, {t}, {r})");
        }
    }

    #[test]
    fn saturate_blends_by_the_smaller_of_source_alpha_and_free_destination() {
        let b = Blend::func(BlendFactor::SrcAlphaSaturate, BlendFactor::One);
        let out = blend(&b, [1.0, 1.0, 1.0, 0.75], [0.0, 0.0, 0.0, 0.5]);
        assert_eq!(out, [0.5, 0.5, 0.5, 0.75 + 0.5]);
    }
}
