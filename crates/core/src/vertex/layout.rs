//! The post-transform vertex: a run of floats holding exactly the values a draw's
//! primitives and fragment state read, at offsets fixed per draw.
//!
//! One flat layout per draw rather than a struct with every field: a vertex of a lit,
//! untextured, fogless triangle is its clip position and color (8 floats), where a struct
//! of every field is 38 floats that the vertex stage would have to fill and clipping to
//! interpolate. Monomorphized layouts would each compile the vertex stage, clipping and
//! setup once more, for the few combinations that dominate; offsets read at run time cost a
//! load each and serve every combination with one copy of the code.

use glam::Vec4;

use super::MAX_USER_PLANES;
use crate::state::RenderState;
use crate::TEXTURE_UNITS;

/// The most floats a vertex holds: position, front and back color, four texture units,
/// eye z, point size and six clip distances.
pub const MAX_STRIDE: usize = 4 + 4 + 4 + 4 * TEXTURE_UNITS + 1 + 1 + MAX_USER_PLANES;

/// The floats a [`VertexRef`] sees: the vertex's [`Layout::stride`] floats first, then
/// whatever follows (the next vertices, or padding). A fixed length lets every read at a
/// constant offset (the position, the color) go unchecked. Clipping makes vertices of this
/// type; vertex lists end with padding so their last vertex has this many floats too.
pub type Floats = [f32; MAX_STRIDE];

/// Where each value lies in a vertex of one draw. The clip position is at 0 and the color
/// (lit, clamped to [0, 1]) at 4 in every layout; the rest only where it is read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layout {
    /// Floats per vertex.
    pub stride: usize,
    /// The back color (two-sided lighting of triangles, lit with the reversed normal and the
    /// back material); the color's offset when there is none.
    back: usize,
    /// Texture coordinates after the texture matrix (q included, not divided), for the
    /// enabled units only.
    tex: [Option<usize>; TEXTURE_UNITS],
    /// The eye-space z (fog's distance is |z|).
    eye_z: Option<usize>,
    /// The derived point size, before the rasterizer's clamp (points only).
    point_size: Option<usize>,
    /// Signed distances to the enabled user clip planes, in `RenderState::clip_planes`
    /// order, from this offset; negative is outside.
    clip: usize,
    /// How many user clip planes apply.
    pub planes: usize,
}

impl Layout {
    const COLOR: usize = 4;

    /// The layout of a draw of `points` (or not) under `state`, with a back color when
    /// `two_side`.
    pub fn new(state: &RenderState, two_side: bool, points: bool) -> Layout {
        Layout::keeping(
            two_side,
            state.textures.each_ref().map(Option::is_some),
            state.fog.is_some(),
            points,
            state.clip_planes.len(),
        )
    }

    /// The layout that keeps everything, with `planes` user planes (for tests and tools).
    pub fn full(planes: usize) -> Layout {
        Layout::keeping(true, [true; TEXTURE_UNITS], true, true, planes)
    }

    /// The layout keeping a back color, the units `units`, the eye z, the point size and
    /// the distances to `planes` user planes (at most six).
    fn keeping(
        two_side: bool,
        units: [bool; TEXTURE_UNITS],
        eye_z: bool,
        points: bool,
        planes: usize,
    ) -> Layout {
        let mut at = 8;
        let mut take = |present: bool, n: usize| {
            present.then(|| {
                at += n;
                at - n
            })
        };
        let back = take(two_side, 4).unwrap_or(Self::COLOR);
        let tex = units.map(|on| take(on, 4));
        let eye_z = take(eye_z, 1);
        let point_size = take(points, 1);
        let planes = planes.min(MAX_USER_PLANES);
        let clip = at;
        Layout {
            stride: clip + planes,
            back,
            tex,
            eye_z,
            point_size,
            clip,
            planes,
        }
    }

    /// Whether the back color is stored apart from the color.
    #[inline]
    pub fn two_side(&self) -> bool {
        self.back != Self::COLOR
    }

    /// Where unit `u`'s coordinates are, if it is enabled.
    #[inline]
    pub fn tex(&self, u: usize) -> Option<usize> {
        self.tex[u]
    }

    #[inline]
    pub fn back(&self) -> usize {
        self.back
    }

    #[inline]
    pub fn eye_z(&self) -> Option<usize> {
        self.eye_z
    }

    #[inline]
    pub fn point_size(&self) -> Option<usize> {
        self.point_size
    }

    /// Where the distance to user plane `i` (< `planes`) is.
    #[inline]
    pub fn clip(&self, i: usize) -> usize {
        self.clip + i
    }

    /// The vertex at the start of `floats`, read through this layout.
    #[inline]
    pub fn view<'a>(&'a self, floats: &'a Floats) -> VertexRef<'a> {
        VertexRef {
            floats,
            layout: self,
        }
    }
}

/// One vertex: its floats (the first `layout.stride` of them) and their layout.
#[derive(Clone, Copy, Debug)]
pub struct VertexRef<'a> {
    pub floats: &'a Floats,
    pub layout: &'a Layout,
}

impl VertexRef<'_> {
    /// The vertex's own floats.
    #[inline]
    pub fn own(&self) -> &[f32] {
        &self.floats[..self.layout.stride]
    }

    #[inline]
    fn vec4(&self, at: usize) -> Vec4 {
        Vec4::from_slice(&self.floats[at..at + 4])
    }

    /// The clip-space position.
    #[inline]
    pub fn pos(&self) -> Vec4 {
        self.vec4(0)
    }

    #[inline]
    pub fn color(&self) -> Vec4 {
        self.vec4(Layout::COLOR)
    }

    /// The back-facing triangles' color; the color itself without two-sided lighting.
    #[inline]
    pub fn back_color(&self) -> Vec4 {
        self.vec4(self.layout.back)
    }

    /// Unit `u`'s coordinates; the default (0, 0, 0, 1) for a unit that is not enabled.
    #[inline]
    pub fn tex(&self, u: usize) -> Vec4 {
        self.layout
            .tex(u)
            .map_or(Vec4::new(0.0, 0.0, 0.0, 1.0), |at| self.vec4(at))
    }

    /// The eye-space z; 0 without fog.
    #[inline]
    pub fn eye_z(&self) -> f32 {
        self.layout.eye_z.map_or(0.0, |at| self.floats[at])
    }

    /// The point size; 1 for other primitives.
    #[inline]
    pub fn point_size(&self) -> f32 {
        self.layout.point_size.map_or(1.0, |at| self.floats[at])
    }

    /// The distance to user plane `i`; 0 (inside) past the enabled planes.
    #[inline]
    pub fn clip_dist(&self, i: usize) -> f32 {
        if i < self.layout.planes {
            self.floats[self.layout.clip(i)]
        } else {
            0.0
        }
    }
}

/// The vertex `t` of the way from `a` to `b` into `out`, every value interpolated linearly
/// in clip space, as clipping requires.
#[inline]
pub fn lerp(a: &[f32], b: &[f32], t: f32, out: &mut [f32]) {
    for ((o, &a), &b) in out.iter_mut().zip(a).zip(b) {
        *o = a + (b - a) * t;
    }
}

/// Every value a vertex can carry, whatever a layout keeps, for tests and tools: the
/// tests' one-vertex statement of the vertex stage writes these, [`Layout::pack`] keeps
/// what a layout stores and [`VertexRef::unpack`] reads a stored vertex back.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClipVertex {
    pub pos: Vec4,
    pub color: Vec4,
    pub back_color: Vec4,
    pub tex: [Vec4; TEXTURE_UNITS],
    pub eye: glam::Vec3,
    pub point_size: f32,
    pub clip_dist: [f32; MAX_USER_PLANES],
}

impl ClipVertex {
    /// A vertex at clip position `pos` with `color` and every other value at its default.
    pub fn new(pos: Vec4, color: Vec4) -> ClipVertex {
        ClipVertex {
            pos,
            color,
            back_color: color,
            tex: [Vec4::new(0.0, 0.0, 0.0, 1.0); TEXTURE_UNITS],
            eye: glam::Vec3::ZERO,
            point_size: 1.0,
            clip_dist: [0.0; MAX_USER_PLANES],
        }
    }
}

impl Layout {
    /// The values of `v` this layout keeps (the floats past `stride` are 0).
    pub fn pack(&self, v: &ClipVertex) -> Floats {
        let mut f = [0.0; MAX_STRIDE];
        f[..4].copy_from_slice(&v.pos.to_array());
        f[4..8].copy_from_slice(&v.color.to_array());
        f[self.back..self.back + 4].copy_from_slice(&v.back_color.to_array());
        for u in 0..TEXTURE_UNITS {
            if let Some(at) = self.tex[u] {
                f[at..at + 4].copy_from_slice(&v.tex[u].to_array());
            }
        }
        if let Some(at) = self.eye_z {
            f[at] = v.eye.z;
        }
        if let Some(at) = self.point_size {
            f[at] = v.point_size;
        }
        f[self.clip..self.stride].copy_from_slice(&v.clip_dist[..self.planes]);
        f
    }
}

impl VertexRef<'_> {
    /// Every value, the ones the layout does not keep at their defaults.
    pub fn unpack(&self) -> ClipVertex {
        ClipVertex {
            pos: self.pos(),
            color: self.color(),
            back_color: self.back_color(),
            tex: std::array::from_fn(|u| self.tex(u)),
            eye: glam::Vec3::new(0.0, 0.0, self.eye_z()),
            point_size: self.point_size(),
            clip_dist: std::array::from_fn(|i| self.clip_dist(i)),
        }
    }
}
