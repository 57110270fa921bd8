//! Triangle setup: from corners in window space (snapped to [`SUBPIXEL_BITS`] fixed-point
//! subpixels by [`ViewportTransform`]), integer edge functions with a top-left fill rule,
//! facing and culling, and the planes of the attributes.

use super::state::{CullFace, RenderState, Winding};
use super::target::{DepthFormat, Rect};
use super::vertex::{VertexRef, ViewportTransform, Window};
use super::{SUBPIXEL_BITS, TEXTURE_UNITS};

const ONE: i64 = 1 << SUBPIXEL_BITS;
const HALF: i64 = ONE / 2;

/// `v.round() as i64`, bit for bit (half away from zero, NaN to 0, saturating), without
/// the libm call `f64::round` compiles to on baseline x86-64 (no SSE4.1 `roundsd`).
#[inline]
pub(crate) fn round_i64(v: f64) -> i64 {
    // Truncating v + ±(½ − 2⁻⁵⁴) rounds half away from zero: with a fraction of exactly ½
    // the sum rounds up to the next integer (for v = ½ by a tie, to the even 1), with a
    // smaller one it stays below it, and from 2⁵² on v is an integer the sum rounds back
    // to (the test below holds this to `f64::round`). No branches: which way a vertex
    // rounds is a coin toss a branch predictor loses half the time.
    (v + (0.5 - f64::EPSILON / 4.0).copysign(v)) as i64
}

/// An edge function `E(x, y) = a·x + b·y + c` over subpixel coordinates relative to the
/// triangle's origin; positive inside. [`Edge::bias`] is 0 for edges that own the pixels
/// exactly on them (top and left edges) and 1 otherwise, so `E − bias ≥ 0` is the coverage
/// test and a pixel on an edge shared by two triangles is drawn by exactly one of them.
///
/// `a` and `b` are differences of snapped coordinates, below 2²⁵ in magnitude (see
/// [`crate::clip::GUARD`]), so they fit an i32; with the bias derived from them rather than
/// stored an edge takes 16 bytes, and every primitive copied into a frame 48 fewer.
#[derive(Clone, Copy, Debug)]
pub struct Edge {
    pub a: i32,
    pub b: i32,
    pub c: i64,
}

impl Edge {
    fn new(x0: i64, y0: i64, x1: i64, y1: i64) -> Edge {
        let (dx, dy) = (x1 - x0, y1 - y0);
        debug_assert!(dx.abs() < 1 << 31 && dy.abs() < 1 << 31);
        Edge {
            a: -dy as i32,
            b: dx as i32,
            c: dy * x0 - dx * y0,
        }
    }

    /// 0 when the edge owns the pixel centers exactly on it, 1 otherwise. With y up and
    /// counter-clockwise vertices the inside lies to the left of each edge: a downward edge
    /// (a > 0) is a left edge, a leftward horizontal edge (a = 0, b < 0) a top edge.
    #[inline]
    pub fn bias(&self) -> i64 {
        let owns = self.a > 0 || (self.a == 0 && self.b < 0);
        i64::from(!owns)
    }

    /// The edge function at the center of pixel (px, py), given relative to the origin.
    #[inline]
    pub fn at_center(&self, px: i64, py: i64) -> i64 {
        self.a as i64 * (px * ONE + HALF) + self.b as i64 * (py * ONE + HALF) + self.c
    }
}

/// A quantity interpolated linearly in window space: `dx·px + dy·py + c` at the center of
/// pixel (px, py), counted from the triangle's origin.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Plane {
    pub dx: f64,
    pub dy: f64,
    pub c: f64,
}

/// The barycentric weights of a triangle's vertices as planes: vertex i's weight at a pixel
/// center is `E_i / area` of the edge opposite it, which is linear in the pixel coordinates.
/// Worked out once per triangle, so each attribute plane costs no division.
struct Weights([Plane; 3]);

impl Weights {
    fn new(edges: &[Edge; 3], area: f64) -> Weights {
        // Nine quotients by one divisor, in one loop so that they compile to vector
        // divisions (the same quotients as one at a time).
        let mut q = [0.0; 9];
        for (q, e) in q.chunks_exact_mut(3).zip(edges) {
            let (a, b, c) = (e.a as f64, e.b as f64, e.c as f64);
            q[0] = a * ONE as f64;
            q[1] = b * ONE as f64;
            q[2] = a * HALF as f64 + b * HALF as f64 + c;
        }
        for q in &mut q {
            *q /= area;
        }
        let plane = |i: usize| Plane {
            dx: q[3 * i],
            dy: q[3 * i + 1],
            c: q[3 * i + 2],
        };
        Weights([plane(0), plane(1), plane(2)])
    }
}

impl Plane {
    const ZERO: Plane = Plane {
        dx: 0.0,
        dy: 0.0,
        c: 0.0,
    };

    /// The plane through the values `v` at the vertices: the weighted sum of the weight
    /// planes, exact up to f64 rounding.
    fn through(w: &Weights, v: [f64; 3]) -> Plane {
        let mut p = Plane::default();
        for (w, v) in w.0.iter().zip(v) {
            p.dx += v * w.dx;
            p.dy += v * w.dy;
            p.c += v * w.c;
        }
        p
    }

    /// The value at the center of pixel (px, py), relative to the origin.
    #[inline]
    pub fn at(&self, px: i32, py: i32) -> f64 {
        self.dx * px as f64 + self.dy * py as f64 + self.c
    }
}

/// Four planes over one primitive, the color channels divided by w: each coefficient as four
/// lanes rather than four planes of three, so building and evaluating them is vector
/// arithmetic. Channel by channel the same operations as [`Plane`]'s.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Planes4 {
    pub dx: [f64; 4],
    pub dy: [f64; 4],
    pub c: [f64; 4],
}

impl Planes4 {
    pub const ZERO: Planes4 = Planes4 {
        dx: [0.0; 4],
        dy: [0.0; 4],
        c: [0.0; 4],
    };

    pub fn from_planes(p: [Plane; 4]) -> Planes4 {
        Planes4 {
            dx: p.map(|p| p.dx),
            dy: p.map(|p| p.dy),
            c: p.map(|p| p.c),
        }
    }

    /// [`Plane::through`] for each channel of `v` (a value per vertex and channel).
    #[inline(always)]
    #[allow(clippy::needless_range_loop)] // lanes of three arrays in step
    fn through(w: &Weights, v: [[f64; 4]; 3]) -> Planes4 {
        let mut p = Planes4::ZERO;
        for (w, v) in w.0.iter().zip(v) {
            for ch in 0..4 {
                p.dx[ch] += v[ch] * w.dx;
                p.dy[ch] += v[ch] * w.dy;
                p.c[ch] += v[ch] * w.c;
            }
        }
        p
    }

    /// [`Plane::at`] for each channel.
    #[inline(always)]
    pub fn at(&self, px: i32, py: i32) -> [f64; 4] {
        let (x, y) = (px as f64, py as f64);
        let at = |ch: usize| self.dx[ch] * x + self.dy[ch] * y + self.c[ch];
        [at(0), at(1), at(2), at(3)]
    }
}

/// How the fragments of one primitive get their depth and color: planes in window space,
/// and for antialiased lines and points, the share of each pixel the primitive covers.
#[derive(Clone, Debug)]
pub struct Shading {
    /// Pixel (origin.0, origin.1) is where plane coordinates are 0.
    pub origin: (i32, i32),
    /// Window-space depth, polygon offset included (clamped to [0, 1] when quantized).
    pub z: Plane,
    /// 1/w, and each color channel divided by w: their quotient is the perspective-correct
    /// color.
    pub inv_w: Plane,
    pub color_w: Planes4,
    /// The color when it does not vary: flat shading, points.
    pub flat: Option<[f32; 4]>,
    /// Boxed: only antialiased lines and points have one, and it would make every
    /// primitive a quarter larger.
    pub coverage: Option<Box<Coverage>>,
    /// Texture coordinates of the enabled units (`None` when texturing is off).
    pub tex: Option<UnitPlanes>,
    /// With fog: the fog distance |z_eye| (per-pixel fog) or the fog factor (per-vertex
    /// fog), divided by w.
    pub fog: Plane,
}

/// The texture coordinate planes of every unit of a primitive (boxed: most primitives
/// have none).
pub type UnitPlanes = Box<[TexPlanes; TEXTURE_UNITS]>;

/// One texture unit's coordinates across a primitive: s, t, r and q each divided by w, so
/// the texture coordinates at a pixel are (s/w)/(q/w) and (t/w)/(q/w), perspective-correct
/// without a separate 1/w. Under REPEAT (and MIRRORED_REPEAT) whole periods are removed
/// from s and t at setup, so coordinates of magnitude 2¹⁰ and beyond keep their fraction's
/// precision.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TexPlanes {
    pub s: Plane,
    pub t: Plane,
    pub r: Plane,
    pub q: Plane,
}

/// The whole wrap periods to remove from coordinate `c` (s or t) of the vertices of a
/// primitive (`q` their q): a multiple of `period` near the coordinates' mean.
fn period_offset(c: &[f64], q: &[f64], period: Option<f64>) -> f64 {
    let Some(p) = period else {
        return 0.0;
    };
    let (mut sum, mut n) = (0.0, 0);
    for (&c, &q) in c.iter().zip(q) {
        let v = c / q;
        if q.abs() > 1e-6 && v.is_finite() {
            sum += v;
            n += 1;
        }
    }
    if n == 0 {
        return 0.0;
    }
    let off = (sum / n as f64 / p).floor() * p;
    if off.is_finite() {
        off
    } else {
        0.0
    }
}

/// Builds the plane through per-vertex values given by a function of the vertex index.
pub(crate) type PlaneBuilder<'a> = &'a dyn Fn(&dyn Fn(usize) -> f64) -> Plane;

/// The texture and fog planes of a primitive with vertices `v` (and 1/w `inv_w`):
/// `plane(f)` builds the plane through the per-vertex values `f(i)`, i indexing `v`.
/// `spare` is storage for the texture planes that the caller no longer needs (a reused
/// primitive's): a textured triangle then allocates nothing.
pub(crate) fn attribute_planes(
    state: &RenderState,
    v: &[VertexRef<'_>],
    inv_w: &[f64],
    plane: PlaneBuilder<'_>,
    spare: Option<UnitPlanes>,
) -> (Option<UnitPlanes>, Plane) {
    let fog = match &state.fog {
        Some(f) => {
            let per_pixel = f.per_pixel();
            plane(&|i| {
                let z = v[i].eye_z().abs();
                let value = if per_pixel { z } else { f.factor(z) };
                value as f64 * inv_w[i]
            })
        }
        None => Plane::default(),
    };
    if state.textures.iter().all(Option::is_none) {
        return (None, fog);
    }
    let mut planes = spare.unwrap_or_default();
    for (u, unit) in state.textures.iter().enumerate() {
        let Some(unit) = unit else {
            planes[u] = TexPlanes::default();
            continue;
        };
        // Primitives have at most three vertices: arrays, not a heap allocation each.
        let n = v.len();
        let (mut q, mut s, mut t) = ([0.0; 3], [0.0; 3], [0.0; 3]);
        for (i, v) in v.iter().enumerate() {
            let tc = v.tex(u);
            q[i] = tc.w as f64;
            s[i] = tc.x as f64;
            t[i] = tc.y as f64;
        }
        let os = period_offset(&s[..n], &q[..n], unit.sampler.wrap_s.period());
        let ot = period_offset(&t[..n], &q[..n], unit.sampler.wrap_t.period());
        planes[u] = TexPlanes {
            s: plane(&|i| (s[i] - os * q[i]) * inv_w[i]),
            t: plane(&|i| (t[i] - ot * q[i]) * inv_w[i]),
            // r is read only as a cube map's third coordinate.
            r: if unit.sampler.cube.is_some() {
                plane(&|i| v[i].tex(u).z as f64 * inv_w[i])
            } else {
                Plane::ZERO
            },
            q: plane(&|i| q[i] * inv_w[i]),
        };
    }
    (Some(planes), fog)
}

/// Antialiasing coverage: the share of a pixel's square inside the primitive, estimated
/// with `samples` × `samples` sample points (the hint decides how many).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Coverage {
    pub shape: Shape,
    pub samples: i32,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shape {
    /// A rectangle along a line: from (x, y) in unit direction (ux, uy) for `len`, `half`
    /// to either side.
    Line {
        x: f64,
        y: f64,
        ux: f64,
        uy: f64,
        len: f64,
        half: f64,
    },
    /// A disc.
    Point { x: f64, y: f64, radius: f64 },
}

impl Coverage {
    /// The covered share of pixel (px, py), in [0, 1].
    pub fn at(&self, px: i32, py: i32) -> f32 {
        let n = self.samples;
        let mut hits = 0;
        for sy in 0..n {
            for sx in 0..n {
                let x = px as f64 + (sx as f64 + 0.5) / n as f64;
                let y = py as f64 + (sy as f64 + 0.5) / n as f64;
                let inside = match self.shape {
                    Shape::Line {
                        x: x0,
                        y: y0,
                        ux,
                        uy,
                        len,
                        half,
                    } => {
                        let (dx, dy) = (x - x0, y - y0);
                        let along = dx * ux + dy * uy;
                        let across = dx * uy - dy * ux;
                        (0.0..len).contains(&along) && across.abs() < half
                    }
                    Shape::Point {
                        x: cx,
                        y: cy,
                        radius,
                    } => (x - cx) * (x - cx) + (y - cy) * (y - cy) < radius * radius,
                };
                hits += inside as i32;
            }
        }
        hits as f32 / (n * n) as f32
    }
}

/// A triangle ready to rasterize.
#[derive(Clone, Debug)]
pub struct Triangle {
    /// `edges[i]` is the edge opposite vertex i; coordinates relative to `shading.origin`.
    pub edges: [Edge; 3],
    /// The pixels the triangle may cover, within the draw bounds.
    pub bbox: Rect,
    pub shading: Shading,
}

impl Triangle {
    /// A triangle covering nothing, for storage that [`triangle`] then fills.
    pub const BLANK: Triangle = Triangle {
        edges: [Edge { a: 0, b: 0, c: 0 }; 3],
        bbox: Rect {
            x0: 0,
            y0: 0,
            x1: 0,
            y1: 0,
        },
        shading: Shading {
            origin: (0, 0),
            z: Plane::ZERO,
            inv_w: Plane::ZERO,
            color_w: Planes4::ZERO,
            flat: None,
            coverage: None,
            tex: None,
            fog: Plane::ZERO,
        },
    };
}

/// Where set-up builds the triangles it keeps: in place, in the storage that keeps them.
/// A triangle is some 300 bytes; built on set-up's stack and returned, it was copied
/// three times on its way into the frame (a tenth of a lit scene's time, with a
/// store-forwarding stall on the first copy).
pub trait TriangleSlot {
    /// Storage for a kept triangle that will cover `bbox`, to be overwritten.
    fn triangle_slot(&mut self, bbox: Rect) -> &mut Triangle;
}

/// One triangle, for callers that take them one at a time.
impl TriangleSlot for Option<Triangle> {
    fn triangle_slot(&mut self, _: Rect) -> &mut Triangle {
        self.insert(Triangle::BLANK)
    }
}

/// Sets up a clipped triangle of vertices `v` for rasterization inside `bounds` of a
/// target with `depth` bits into a slot of `out`, or returns `false` (and takes no slot)
/// when it is culled, has no area, or cannot touch `bounds`. `corners` are the vertices'
/// window coordinates when the vertex stage has them, else they are worked out here
/// (both by [`ViewportTransform::lanes`]). `flat` is the vertex whose color the whole
/// triangle takes ([`crate::flat_colors`]), `None` when colors are interpolated.
/// Compiled also for AVX2 and SSE4.1 and chosen at run time, as the vertex and span loops
/// are: the same f64 operations, so the same results.
#[cfg_attr(
    not(fuzzing),
    multiversion::multiversion(targets("x86_64+avx2", "x86_64+sse4.1"))
)]
pub fn triangle<'v, 's>(
    state: &RenderState,
    v: [VertexRef<'v>; 3],
    corners: Option<[Window; 3]>,
    flat: Option<VertexRef<'v>>,
    bounds: Rect,
    depth: Option<DepthFormat>,
    out: &'s mut dyn TriangleSlot,
) -> bool {
    // In a sample plane, the primitive moves so that pixel centers sample it at the
    // plane's sample position (exact: the offsets are on the subpixel grid).
    let [ox, oy] = state.sample.map_or([0, 0], |s| s.offset.map(|o| o as i64));
    // Here rather than in the caller, so that it takes this function's instruction set
    // (baseline x86-64 rounds by a library call).
    let [a, b, c] = corners.unwrap_or_else(|| {
        ViewportTransform::new(state).corners([v[0].pos(), v[1].pos(), v[2].pos()])
    });
    let win = [
        (a.x - ox, a.y - oy),
        (b.x - ox, b.y - oy),
        (c.x - ox, c.y - oy),
    ];
    let (z, inv_w) = ([a.z, b.z, c.z], [a.inv_w, b.inv_w, c.inv_w]);
    // Facing and culling need only the snapped vertices (the area is the same from any
    // origin), so culled triangles skip the bounding box and the planes.
    let area = (win[1].0 - win[0].0) * (win[2].1 - win[0].1)
        - (win[2].0 - win[0].0) * (win[1].1 - win[0].1);
    if area == 0 {
        return false;
    }
    let ccw = area > 0;
    let front = ccw == (state.front_face == Winding::Ccw);
    match state.cull {
        Some(CullFace::FrontAndBack) => return false,
        Some(CullFace::Front) if front => return false,
        Some(CullFace::Back) if !front => return false,
        _ => {}
    }
    // Pixel bounding box: pixel centers strictly inside the snapped extent.
    let min_x = win[0].0.min(win[1].0).min(win[2].0);
    let max_x = win[0].0.max(win[1].0).max(win[2].0);
    let min_y = win[0].1.min(win[1].1).min(win[2].1);
    let max_y = win[0].1.max(win[1].1).max(win[2].1);
    let to_px = |lo: i64, hi: i64| -> (i64, i64) {
        ((lo - HALF).div_euclid(ONE), (hi - HALF).div_euclid(ONE) + 1)
    };
    let (px0, px1) = to_px(min_x, max_x);
    let (py0, py1) = to_px(min_y, max_y);
    let clamp = |v: i64| v.clamp(i32::MIN as i64, i32::MAX as i64) as i32;
    let bbox = Rect {
        x0: clamp(px0),
        y0: clamp(py0),
        x1: clamp(px1),
        y1: clamp(py1),
    }
    .intersect(bounds);
    if bbox.is_empty() {
        return false;
    }
    // Work relative to the bounding box so every coordinate is small (see MAX_VIEWPORT_DIM).
    let (ox, oy) = (bbox.x0 as i64 * ONE, bbox.y0 as i64 * ONE);
    // Reordered to counter-clockwise so one coverage test serves both windings. Arrays are
    // indexed explicitly here and below: `array::map` and `from_fn` leave their closures
    // as calls, which cost more than the arithmetic they wrap.
    let order = if ccw { [0, 1, 2] } else { [0, 2, 1] };
    let q = [win[order[0]], win[order[1]], win[order[2]]];
    let q = [
        (q[0].0 - ox, q[0].1 - oy),
        (q[1].0 - ox, q[1].1 - oy),
        (q[2].0 - ox, q[2].1 - oy),
    ];
    let edges = [
        Edge::new(q[1].0, q[1].1, q[2].0, q[2].1),
        Edge::new(q[2].0, q[2].1, q[0].0, q[0].1),
        Edge::new(q[0].0, q[0].1, q[1].0, q[1].1),
    ];
    let area = area.abs() as f64;
    let weights = Weights::new(&edges, area);
    // The plane through per-vertex values `v`, in the original vertex order.
    let through = |v: [f64; 3]| Plane::through(&weights, [v[order[0]], v[order[1]], v[order[2]]]);
    let mut z_plane = through(z);
    if let (Some(o), Some(df)) = (state.polygon_offset, depth) {
        // ES 1.1 §3.5.5: factor × the larger depth slope (per pixel, in window space) plus
        // units × the smallest resolvable difference, one step of the depth buffer.
        let slope = z_plane.dx.abs().max(z_plane.dy.abs());
        z_plane.c += o.offset(slope, df.max() as f64);
    }
    // Back-facing triangles take the back colors (two-sided lighting; equal to the front
    // colors otherwise).
    let color = |v: VertexRef<'_>| {
        if front {
            v.color()
        } else {
            v.back_color()
        }
    };
    // Stored field by field into the slot, so that each value is written once.
    let t = out.triangle_slot(bbox);
    t.edges = edges;
    t.bbox = bbox;
    let shading = &mut t.shading;
    shading.origin = (bbox.x0, bbox.y0);
    shading.z = z_plane;
    shading.inv_w = through(inv_w);
    shading.flat = flat.map(|v| color(v).to_array());
    shading.color_w = if shading.flat.is_some() {
        Planes4::ZERO
    } else {
        let c = |k: usize| {
            let c = color(v[order[k]]).to_array();
            c.map(|c| c as f64 * inv_w[order[k]])
        };
        Planes4::through(&weights, [c(0), c(1), c(2)])
    };
    shading.coverage = None;
    let spare = shading.tex.take();
    shading.fog = Plane::ZERO;
    // Checked here too: without fog or textures the call would build nothing. Assigned
    // field by field rather than chosen as a pair first: the chosen pair was stored and
    // read back across two stores, a store-forwarding stall in every triangle's set-up.
    if state.fog.is_some() || state.textures.iter().any(Option::is_some) {
        (shading.tex, shading.fog) =
            attribute_planes(state, &v, &inv_w, &|f| through([f(0), f(1), f(2)]), spare);
    }
    true
}

#[cfg(test)]
mod tests {
    use super::round_i64;
    use crate::vertex::window::snap;

    #[test]
    fn inline_rounding_matches_f64_round() {
        let mut values = vec![
            0.0,
            -0.0,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::MAX,
            f64::MIN,
            f64::MIN_POSITIVE,
            9.3e18,
            -9.3e18,
            (1u64 << 52) as f64 + 0.5,
            4503599627370495.5,
            -4503599627370495.5,
            0.49999999999999994,
            -0.49999999999999994,
        ];
        let mut x = 0x2545_f491_4f6c_dd1d_u64;
        for i in -2000..2000 {
            values.push(i as f64 * 0.25);
            values.push(i as f64 * 0.5 + 1e-9);
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            values.push(f64::from_bits(x));
            values.push((x >> 11) as f64 / (1u64 << 30) as f64 - 4096.0);
        }
        for v in values {
            assert_eq!(round_i64(v), v.round() as i64, "{v:e}");
            if v.is_nan() || v.abs() < (1u64 << 51) as f64 {
                assert_eq!(snap(v), round_i64(v), "{v:e}");
            }
        }
        // Ties and their neighbours at every scale a snapped coordinate takes.
        for e in 0..51 {
            let m = (1u64 << e) as f64;
            for v in [m + 0.5, m - 0.5, m + 1.5, m.next_up() + 0.5] {
                for v in [v, -v, v.next_up(), v.next_down()] {
                    assert_eq!(snap(v), round_i64(v), "{v:e}");
                }
            }
        }
    }
}
