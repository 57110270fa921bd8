//! The vertex stage: fetch any array type to f32, transform to eye and clip space (with
//! matrix-palette skinning), light, transform texture coordinates, derive point sizes and
//! user clip distances, and carry the per-vertex values the later stages interpolate.
//! `transform` runs eight vertices at a time; `lighting` holds the lighting equation.

use glam::Vec4;

use super::fixed;
use super::state::RenderState;
use super::{OutOfMemory, TEXTURE_UNITS};

mod layout;
pub mod lighting;
pub mod power;
mod transform;
pub(crate) mod window;

pub use layout::{lerp, ClipVertex, Floats, Layout, VertexRef, MAX_STRIDE};
pub use window::{ViewportTransform, Window};

use super::lanes::{Lane, LANES};

/// The component types vertex arrays can hold.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ComponentType {
    Byte,
    UnsignedByte,
    Short,
    Fixed,
    Float,
}

impl ComponentType {
    pub fn size(self) -> usize {
        match self {
            ComponentType::Byte | ComponentType::UnsignedByte => 1,
            ComponentType::Short => 2,
            ComponentType::Fixed | ComponentType::Float => 4,
        }
    }
}

/// One vertex array as the pipeline reads it: `data` starts at element 0 and is long enough
/// for every element the draw call reads (the caller checked); `stride` is the distance in
/// bytes between elements, never 0.
#[derive(Clone, Copy, Debug)]
pub struct AttribArray<'a> {
    pub data: &'a [u8],
    pub ty: ComponentType,
    pub size: usize,
    pub stride: usize,
    /// Integer types map to [0, 1] (unsigned) or [-1, 1] (signed) as colors and normals do.
    pub normalized: bool,
}

/// An attribute's value where its array has no element: GL's default (0, 0, 0, 1).
const DEFAULT: [f32; 4] = [0.0, 0.0, 0.0, 1.0];

impl AttribArray<'_> {
    /// The bytes an array of `count` elements with this layout needs.
    pub fn bytes_needed(ty: ComponentType, size: usize, stride: usize, count: usize) -> usize {
        if count == 0 {
            0
        } else {
            (count - 1) * stride + size * ty.size()
        }
    }

    /// Element `i` as four floats, missing components taken from `(0, 0, 0, 1)`. Reads
    /// outside `data` give the default rather than panicking.
    #[inline]
    pub fn fetch(&self, i: usize) -> [f32; 4] {
        (self.monomorphized(Element))(self.data, self.stride, i)
    }

    /// [`AttribSource::gather`] of an array.
    #[inline]
    pub fn gather<const N: usize>(&self, idx: &[usize; LANES], out: &mut [Lane<f32>; N]) {
        (self.monomorphized(Gather::<N>))(self, idx, out)
    }

    /// The array's format as a [`format`](mod@format) constant.
    #[inline]
    fn format(&self) -> u8 {
        use format::*;
        match (self.ty, self.normalized) {
            (ComponentType::Float, _) => FLOAT,
            (ComponentType::Fixed, _) => FIXED,
            (ComponentType::UnsignedByte, false) => UBYTE,
            (ComponentType::UnsignedByte, true) => UBYTE_NORM,
            (ComponentType::Byte, false) => BYTE,
            (ComponentType::Byte, true) => BYTE_NORM,
            (ComponentType::Short, false) => SHORT,
            (ComponentType::Short, true) => SHORT_NORM,
        }
    }

    /// `f`'s function for this array's format and size.
    fn monomorphized<M: Monomorphize>(&self, f: M) -> M::Fn {
        macro_rules! sized {
            ($f:expr) => {
                match self.size {
                    0 => f.at::<{ $f }, 0>(),
                    1 => f.at::<{ $f }, 1>(),
                    2 => f.at::<{ $f }, 2>(),
                    3 => f.at::<{ $f }, 3>(),
                    _ => f.at::<{ $f }, 4>(),
                }
            };
        }
        use format::*;
        match self.format() {
            FLOAT => sized!(FLOAT),
            FIXED => sized!(FIXED),
            UBYTE => sized!(UBYTE),
            UBYTE_NORM => sized!(UBYTE_NORM),
            BYTE => sized!(BYTE),
            BYTE_NORM => sized!(BYTE_NORM),
            SHORT => sized!(SHORT),
            _ => sized!(SHORT_NORM),
        }
    }
}

/// A fetch monomorphized per element format `F` and size `S`, chosen once per array.
trait Monomorphize {
    type Fn;
    fn at<const F: u8, const S: usize>(self) -> Self::Fn;
}

/// One element: [`element`].
struct Element;

impl Monomorphize for Element {
    type Fn = fn(&[u8], usize, usize) -> [f32; 4];
    fn at<const F: u8, const S: usize>(self) -> Self::Fn {
        element::<F, S>
    }
}

/// `LANES` elements, `N` components of each: [`gather_as`].
struct Gather<const N: usize>;

impl<const N: usize> Monomorphize for Gather<N> {
    type Fn = GatherFn<N>;
    fn at<const F: u8, const S: usize>(self) -> Self::Fn {
        gather_as::<F, S, N>
    }
}

type GatherFn<const N: usize> = fn(&AttribArray<'_>, &[usize; LANES], &mut [Lane<f32>; N]);

/// The element formats, as const parameters: one monomorphized fetch per format and size,
/// chosen once per array (per 8 vertices in the batched path) instead of per component.
mod format {
    pub const FLOAT: u8 = 0;
    pub const FIXED: u8 = 1;
    pub const UBYTE: u8 = 2;
    pub const UBYTE_NORM: u8 = 3;
    pub const BYTE: u8 = 4;
    pub const BYTE_NORM: u8 = 5;
    pub const SHORT: u8 = 6;
    pub const SHORT_NORM: u8 = 7;

    pub const fn bytes(f: u8) -> usize {
        match f {
            FLOAT | FIXED => 4,
            SHORT | SHORT_NORM => 2,
            _ => 1,
        }
    }
}

/// Component `k` of an element in format `F` (`b` starts at the element). Both the
/// one-vertex and the batched fetch convert through this, so they agree bit for bit.
#[inline(always)]
fn component<const F: u8>(b: &[u8], k: usize) -> f32 {
    use format::*;
    // Whole-word slices, not four byte indexings: one bounds check and one load per word.
    let word = |k: usize| -> [u8; 4] { b[4 * k..4 * k + 4].try_into().expect("a word") };
    let short = |k: usize| i16::from_ne_bytes(b[2 * k..2 * k + 2].try_into().expect("a short"));
    match F {
        FLOAT => f32::from_ne_bytes(word(k)),
        FIXED => fixed::to_f32(i32::from_ne_bytes(word(k))),
        UBYTE => b[k] as f32,
        UBYTE_NORM => b[k] as f32 / 255.0,
        BYTE => (b[k] as i8) as f32,
        // Signed normalization as GL 1.x defines it: (2c + 1) / (2ⁿ − 1).
        BYTE_NORM => (2.0 * (b[k] as i8) as f32 + 1.0) / 255.0,
        SHORT => short(k) as f32,
        _ => (2.0 * short(k) as f32 + 1.0) / 65535.0,
    }
}

/// Element `i` of format `F` with `S` components, missing ones from the default; an
/// element reaching outside `data` is the default.
#[inline(always)]
fn element<const F: u8, const S: usize>(data: &[u8], stride: usize, i: usize) -> [f32; 4] {
    let base = i * stride;
    let Some(b) = data.get(base..base + S * format::bytes(F)) else {
        return DEFAULT;
    };
    let mut out = DEFAULT;
    for (k, o) in out.iter_mut().enumerate().take(S) {
        *o = component::<F>(b, k);
    }
    out
}

/// `LANES` elements into rows `out[component][lane]` (the first `N` components).
#[inline(never)]
fn gather_as<const F: u8, const S: usize, const N: usize>(
    a: &AttribArray<'_>,
    idx: &[usize; LANES],
    out: &mut [Lane<f32>; N],
) {
    // Consecutive elements packed back to back (a draw's vertices in order from an array
    // without gaps) are one slice of fixed-size chunks: one bounds check for the group,
    // not one per element.
    let size = S * format::bytes(F);
    if size > 0 && a.stride == size && (0..LANES).all(|k| idx[k] == idx[0].wrapping_add(k)) {
        let block = idx[0]
            .checked_mul(size)
            .and_then(|start| a.data.get(start..start.checked_add(LANES * size)?));
        if let Some(block) = block {
            for (k, b) in block.chunks_exact(size).enumerate() {
                for (row, v) in out.iter_mut().zip(element::<F, S>(b, size, 0)) {
                    row[k] = v;
                }
            }
            return;
        }
    }
    for (k, &i) in idx.iter().enumerate() {
        let v = element::<F, S>(a.data, a.stride, i);
        for (row, v) in out.iter_mut().zip(v) {
            row[k] = v;
        }
    }
}

/// Where a vertex attribute comes from.
#[derive(Clone, Copy, Debug)]
pub enum AttribSource<'a> {
    Array(AttribArray<'a>),
    Constant([f32; 4]),
}

impl AttribSource<'_> {
    #[inline]
    pub fn fetch(&self, i: usize) -> [f32; 4] {
        match self {
            AttribSource::Array(a) => a.fetch(i),
            AttribSource::Constant(c) => *c,
        }
    }

    /// [`fetch`](Self::fetch) as a vector.
    #[cfg(test)]
    pub fn fetch_vec4(&self, i: usize) -> Vec4 {
        Vec4::from_array(self.fetch(i))
    }

    /// Elements `idx` as rows `out[component][lane]` (the first `N` components), bit for
    /// bit what [`fetch`](Self::fetch) gives per element. The array's format is matched
    /// once for all lanes, and every format has its own loop, so byte, short and 16.16
    /// arrays cost the batched path no more than float ones.
    #[inline]
    pub fn gather<const N: usize>(&self, idx: &[usize; LANES], out: &mut [Lane<f32>; N]) {
        match self {
            AttribSource::Array(a) => a.gather(idx, out),
            AttribSource::Constant(c) => {
                for (row, &v) in out.iter_mut().zip(c) {
                    *row = [v; LANES];
                }
            }
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Primitive {
    Points,
    Lines,
    LineLoop,
    LineStrip,
    Triangles,
    TriangleStrip,
    TriangleFan,
}

/// Which vertices a draw call uses, in order.
#[derive(Clone, Copy, Debug)]
pub enum Indices<'a> {
    Range { first: usize, count: usize },
    U8(&'a [u8]),
    U16(&'a [u16]),
    U32(&'a [u32]),
}

impl<'a> Indices<'a> {
    /// Positions `start .. end` of the list.
    pub fn sub(&self, start: usize, end: usize) -> Indices<'a> {
        match *self {
            Indices::Range { first, .. } => Indices::Range {
                first: first + start,
                count: end - start,
            },
            Indices::U8(i) => Indices::U8(&i[start..end]),
            Indices::U16(i) => Indices::U16(&i[start..end]),
            Indices::U32(i) => Indices::U32(&i[start..end]),
        }
    }

    pub fn len(&self) -> usize {
        match self {
            Indices::Range { count, .. } => *count,
            Indices::U8(i) => i.len(),
            Indices::U16(i) => i.len(),
            Indices::U32(i) => i.len(),
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The vertex number at position `k` of the list.
    #[inline]
    pub fn get(&self, k: usize) -> usize {
        match self {
            Indices::Range { first, .. } => first + k,
            Indices::U8(i) => i[k] as usize,
            Indices::U16(i) => i[k] as usize,
            Indices::U32(i) => i[k] as usize,
        }
    }

    /// The smallest and largest vertex number used, or `None` for an empty list.
    pub fn range(&self) -> Option<(usize, usize)> {
        if self.is_empty() {
            return None;
        }
        match self {
            Indices::Range { first, count } => Some((*first, first + count - 1)),
            _ => {
                let (mut lo, mut hi) = (usize::MAX, 0);
                for k in 0..self.len() {
                    let v = self.get(k);
                    lo = lo.min(v);
                    hi = hi.max(v);
                }
                Some((lo, hi))
            }
        }
    }
}

impl Primitive {
    /// Calls `f` with the vertex numbers of every triangle the primitive assembles, in an
    /// order that keeps strip winding consistent; the third vertex is always the provoking
    /// one (the one whose color flat shading uses).
    pub fn for_each_triangle(self, ix: &Indices<'_>, f: impl FnMut(usize, usize, usize)) {
        self.triangles_of(ix.len(), |k| ix.get(k), f);
    }

    /// [`Primitive::for_each_triangle`] over `n` positions, `at(k)` what `f` is given for
    /// position `k`: a vertex number, or (`Vertices::for_each_kept_triangle`) a slot. Inlined,
    /// so a caller with one index type gets a loop of its own.
    #[inline(always)]
    fn triangles_of(
        self,
        n: usize,
        at: impl Fn(usize) -> usize,
        mut f: impl FnMut(usize, usize, usize),
    ) {
        match self {
            Primitive::Triangles => {
                for t in 0..n / 3 {
                    f(at(3 * t), at(3 * t + 1), at(3 * t + 2));
                }
            }
            Primitive::TriangleStrip => {
                for t in 0..n.saturating_sub(2) {
                    let (a, b) = if t % 2 == 0 { (t, t + 1) } else { (t + 1, t) };
                    f(at(a), at(b), at(t + 2));
                }
            }
            Primitive::TriangleFan => {
                for t in 0..n.saturating_sub(2) {
                    f(at(0), at(t + 1), at(t + 2));
                }
            }
            _ => {}
        }
    }

    /// Calls `f` with the vertex numbers of every line segment the primitive assembles; the
    /// second vertex is the provoking one.
    pub fn for_each_line(self, ix: &Indices<'_>, mut f: impl FnMut(usize, usize)) {
        let n = ix.len();
        match self {
            Primitive::Lines => {
                for l in 0..n / 2 {
                    f(ix.get(2 * l), ix.get(2 * l + 1));
                }
            }
            Primitive::LineStrip | Primitive::LineLoop if n >= 2 => {
                for l in 0..n - 1 {
                    f(ix.get(l), ix.get(l + 1));
                }
                if self == Primitive::LineLoop {
                    f(ix.get(n - 1), ix.get(0));
                }
            }
            _ => {}
        }
    }

    pub fn is_line(self) -> bool {
        matches!(
            self,
            Primitive::Lines | Primitive::LineStrip | Primitive::LineLoop
        )
    }
}

/// Everything a draw call reads. Arrays that are disabled are `Constant` sources holding the
/// current value. Build one with [`DrawCall::new`] and set the inputs that are used.
#[derive(Clone, Copy, Debug)]
pub struct DrawCall<'a> {
    pub primitive: Primitive,
    pub indices: Indices<'a>,
    pub position: AttribArray<'a>,
    /// Colors as given (not clamped); the vertex stage clamps them.
    pub color: AttribSource<'a>,
    /// Read only when lighting or normal-based texgen is on.
    pub normal: AttribSource<'a>,
    pub texcoord: [AttribSource<'a>; TEXTURE_UNITS],
    /// `OES_point_size_array`: per-vertex sizes (component 0); `None` takes
    /// `RenderState::point_size`.
    pub point_size: Option<AttribArray<'a>>,
    /// `OES_matrix_palette`, read when `RenderState::matrix_palette` is `Some`: per vertex,
    /// `weight.size` palette matrices, indices (`matrix_index`, whole numbers) and weights.
    /// Without an index array every index is 0; without a weight array the vertex takes
    /// matrix `index[0]` with weight 1.
    pub matrix_index: Option<AttribArray<'a>>,
    pub weight: Option<AttribArray<'a>>,
}

impl<'a> DrawCall<'a> {
    /// A draw of `position` with every other input at its GL default: color (1, 1, 1, 1),
    /// normal (0, 0, 1), texture coordinates (0, 0, 0, 1), the state's point size, no
    /// palette arrays.
    pub fn new(primitive: Primitive, indices: Indices<'a>, position: AttribArray<'a>) -> Self {
        DrawCall {
            primitive,
            indices,
            position,
            color: AttribSource::Constant([1.0; 4]),
            normal: AttribSource::Constant([0.0, 0.0, 1.0, 0.0]),
            texcoord: [AttribSource::Constant([0.0, 0.0, 0.0, 1.0]); TEXTURE_UNITS],
            point_size: None,
            matrix_index: None,
            weight: None,
        }
    }
}

/// `GL_MAX_CLIP_PLANES`: the user clip planes a vertex carries distances for.
pub const MAX_USER_PLANES: usize = 6;

/// The smallest w that survives clipping. A vertex at (0, 0, 0, 0) lies inside all six
/// frustum planes, so this plane is what keeps 1/w finite.
pub const W_MIN: f32 = 1e-30;

/// The guard band's half-width in normalized device coordinates. Window coordinates then
/// stay within (GUARD + 1) × MAX_VIEWPORT_DIM / 2 < 2¹⁶ pixels of the viewport, which keeps
/// snapped coordinates below 2²⁴ and edge products far below 2⁶³.
pub const GUARD: f32 = 8.0;

/// A bit per frustum x or y plane that clip position `p` is strictly outside of (x < −w,
/// y < −w, x > w, y > w; negating is exact).
#[inline]
fn frustum_code(p: Vec4) -> u32 {
    Vec4::new(-p.x, -p.y, p.x, p.y)
        .cmpgt(Vec4::splat(p.w))
        .bitmask()
}

/// Whether every coordinate of `ps` is finite: x · 0 is 0 for finite x and NaN otherwise.
/// glam's `is_finite` was not inlined where clipping and the vertex stage call it (a call
/// per vertex in callgrind's counts).
#[inline]
pub fn all_finite<const N: usize>(ps: [Vec4; N]) -> bool {
    let zero = ps.iter().fold(Vec4::ZERO, |z, p| z + *p * 0.0);
    zero.cmpeq(Vec4::ZERO).all()
}

/// The code bits of [`reject_code`] from [`frustum_code`].
const OUTSIDE_FRUSTUM: u8 = 0xf;

/// A code bit of [`reject_code`]: a coordinate is infinite or NaN.
const NOT_FINITE: u8 = 1 << 4;

/// A code bit of [`reject_code`]: the position is outside a plane triangles are clipped
/// against (the guard band's x and y planes, the near and far planes, w = [`W_MIN`]), so a
/// triangle with this vertex may need clipping.
pub(crate) const CLIPS: u8 = 1 << 5;

/// Whether clip position `p` is outside a plane of [`CLIPS`], as `clip::outcode` decides
/// for a finite position: its distance `x + g ≥ 0` (g = GUARD · w) holds exactly
/// when x ≥ −g (a sum of two floats rounds to 0 only when it is 0), and with `g − x ≥ 0`
/// that is |x| ≤ g; likewise |y| ≤ g and |z| ≤ w. NaN counts as outside.
#[inline]
fn clips(p: Vec4) -> bool {
    let g = GUARD * p.w;
    let inside = (p.x.abs() <= g) & (p.y.abs() <= g) & (p.z.abs() <= p.w) & (p.w >= W_MIN);
    !inside
}

/// What set-up reads of one clip position, as a byte: its [`frustum_code`],
/// [`NOT_FINITE`] and [`CLIPS`]. The vertex stage keeps one per vertex, computed eight at
/// a time (the tests hold that to this statement), so a triangle outside the view is
/// dropped from three bytes, before its vertices are read, and one inside the clip volume
/// goes to set-up without the clipper's tests.
#[inline]
pub(crate) fn reject_code(p: Vec4) -> u8 {
    frustum_code(p) as u8
        | if all_finite([p]) { 0 } else { NOT_FINITE }
        | if clips(p) { CLIPS } else { 0 }
}

/// [`rejects`] from the three vertices' [`reject_code`]s.
#[inline]
fn rejects_codes(a: u8, b: u8, c: u8) -> bool {
    // Infinite or NaN coordinates have no meaningful clipped shape; drop the triangle rather
    // than let NaN reach the rasterizer. Outside one of the frustum's x or y planes with all
    // three vertices, the triangle is outside it everywhere (the plane's half-space is
    // convex, whatever the signs of w), so it could only cover pixels beyond the viewport,
    // which the rasterizer never draws. Most such triangles lie inside the guard band and
    // would otherwise be set up in full only for their bounding box to come out empty.
    // One test of both bits, without a branch between them: the walks over a draw's
    // triangles run this for every one.
    ((a | b | c) & NOT_FINITE) | (a & b & c & OUTSIDE_FRUSTUM) != 0
}

/// Whether clipping drops the triangle with clip positions (a, b, c) from the positions
/// alone, before any clipping: [`clip::triangle`](super::clip::triangle) asks this first,
/// and the deferred lighting lights no vertex of such a triangle.
#[inline]
pub fn rejects(a: Vec4, b: Vec4, c: Vec4) -> bool {
    rejects_codes(reject_code(a), reject_code(b), reject_code(c))
}

/// Transformed vertices of one piece of a draw call (up to 2048 primitives), addressed by
/// vertex number. This is the post-transform vertex cache: every distinct vertex number a
/// piece uses is transformed and lit once, however often its primitives refer to it (a
/// vertex shared by two pieces is transformed in each).
pub struct Vertices {
    /// `layout.stride` floats per vertex, then padding to make the last vertex's view a
    /// whole [`Floats`].
    data: Vec<f32>,
    /// Each vertex's [`reject_code`].
    codes: Vec<u8>,
    /// Each vertex's window coordinates, where the draw's triangles share vertices;
    /// otherwise empty (see [`Vertices::corners`]).
    windows: Vec<Window>,
    layout: Layout,
    /// Where vertex number `i` is: in slot `keys[k] == i` when `sparse` (the sorted
    /// distinct numbers of a sparse index list), else in slot `i − base` (every number of
    /// the index range).
    sparse: bool,
    base: usize,
    keys: Vec<usize>,
}

impl Default for Vertices {
    fn default() -> Vertices {
        Vertices {
            data: Vec::new(),
            codes: Vec::new(),
            windows: Vec::new(),
            layout: Layout::full(0),
            sparse: false,
            base: 0,
            keys: Vec::new(),
        }
    }
}

impl Vertices {
    /// Vertex number `i` (one the draw uses).
    #[inline]
    pub fn get(&self, i: usize) -> VertexRef<'_> {
        self.at(self.slot(i))
    }

    /// Where vertex number `i` (one the draw uses) is kept, for [`Vertices::at`].
    #[inline]
    pub fn slot(&self, i: usize) -> usize {
        if self.sparse {
            self.keys.binary_search(&i).expect("vertex of this draw")
        } else {
            i - self.base
        }
    }

    /// [`rejects`] of the triangle of the vertices in slots `a`, `b` and `c`, from their
    /// codes alone.
    #[inline]
    fn rejects(&self, a: usize, b: usize, c: usize) -> bool {
        rejects_codes(self.codes[a], self.codes[b], self.codes[c])
    }

    /// Calls `f` with the slots of each triangle `prim` assembles from `ix` (as
    /// [`Primitive::for_each_triangle`] orders them) that [`rejects`] keeps: those not
    /// dropped by their vertices' codes alone.
    ///
    /// Over a dense range of vertex numbers (not `sparse`) each index type has a loop of its
    /// own, with the slot a subtraction, and a list of consecutive vertices
    /// (`glDrawArrays`) reads its codes three at a time: a triangle dropped there costs
    /// about 12 instructions, where the general walk, with a call per triangle and the
    /// index type matched per vertex, cost about 53 (lit-offscreen, whose 100 000
    /// triangles a frame are all outside the view).
    pub fn for_each_kept_triangle(
        &self,
        prim: Primitive,
        ix: &Indices<'_>,
        mut f: impl FnMut([usize; 3]),
    ) {
        let base = self.base;
        if let (Primitive::Triangles, Indices::Range { first, count }, false) =
            (prim, *ix, self.sparse)
        {
            // Slots first − base ..: an empty draw keeps no codes, and no slot is read.
            let s0 = first - base;
            let codes = self.codes.get(s0..s0 + count / 3 * 3).unwrap_or_default();
            for (t, c) in codes.chunks_exact(3).enumerate() {
                if !rejects_codes(c[0], c[1], c[2]) {
                    let s = s0 + 3 * t;
                    f([s, s + 1, s + 2]);
                }
            }
            return;
        }
        let mut kept = |a: usize, b: usize, c: usize| {
            // Most triangles outside the view end here, from three bytes.
            if !self.rejects(a, b, c) {
                f([a, b, c]);
            }
        };
        if self.sparse {
            return prim
                .for_each_triangle(ix, |a, b, c| kept(self.slot(a), self.slot(b), self.slot(c)));
        }
        match *ix {
            Indices::Range { first, count } => prim.triangles_of(count, |k| first - base + k, kept),
            Indices::U8(i) => prim.triangles_of(i.len(), |k| i[k] as usize - base, kept),
            Indices::U16(i) => prim.triangles_of(i.len(), |k| i[k] as usize - base, kept),
            Indices::U32(i) => prim.triangles_of(i.len(), |k| i[k] as usize - base, kept),
        }
    }

    /// Whether the triangle of the vertices in slots `a`, `b` and `c`, not rejected, may
    /// need clipping: a vertex's code has the `CLIPS` bit, or user planes are enabled.
    /// Otherwise [`clip::triangle`](super::clip::triangle) would pass it on as it is.
    #[inline]
    pub fn may_clip(&self, a: usize, b: usize, c: usize) -> bool {
        self.layout.planes > 0 || (self.codes[a] | self.codes[b] | self.codes[c]) & CLIPS != 0
    }

    /// The window coordinates of the vertices in slots `k`, if the vertex stage worked
    /// them out (see [`ViewportTransform`]).
    #[inline]
    pub fn corners(&self, k: [usize; 3]) -> Option<[Window; 3]> {
        (!self.windows.is_empty())
            .then(|| [self.windows[k[0]], self.windows[k[1]], self.windows[k[2]]])
    }

    /// The vertex in slot `k` ([`Vertices::slot`]).
    #[inline]
    pub fn at(&self, k: usize) -> VertexRef<'_> {
        let at = k * self.layout.stride;
        let floats = self.data[at..at + MAX_STRIDE]
            .try_into()
            .expect("a view's length");
        self.layout.view(floats)
    }

    /// The floats and keys of storage held, used or not.
    pub fn capacity(&self) -> usize {
        self.data.capacity() + self.keys.capacity()
    }

    /// How many vertices were transformed.
    #[cfg(test)]
    fn len(&self) -> usize {
        self.data.len().saturating_sub(MAX_STRIDE) / self.layout.stride
    }
}

/// Runs the vertex stage for every distinct vertex the draw call uses. An index list that
/// touches at least half of its range is transformed over the whole range (no lookup
/// structure); a sparser one only at its distinct indices. The counts come from the
/// caller, so allocations are fallible rather than aborting.
pub fn run(state: &RenderState, draw: &DrawCall<'_>) -> Result<Vertices, OutOfMemory> {
    let mut out = Vertices::default();
    run_into(state, draw, &mut out)?;
    Ok(out)
}

/// [`run`] into `out`, whose storage is reused: a draw of six vertices spent some 600
/// instructions allocating and freeing its vertices, against 1 500 transforming them.
pub fn run_into(
    state: &RenderState,
    draw: &DrawCall<'_>,
    out: &mut Vertices,
) -> Result<(), OutOfMemory> {
    let stage = transform::Stage::new(state, draw);
    let layout = stage.layout;
    out.data.clear();
    out.codes.clear();
    out.windows.clear();
    out.keys.clear();
    out.layout = layout;
    out.sparse = false;
    let Vertices {
        data,
        codes,
        windows,
        keys,
        ..
    } = out;
    let Some((lo, hi)) = draw.indices.range() else {
        out.base = 0;
        return Ok(());
    };
    // The vertices' floats and the padding after the last.
    let mut reserve = |count: usize| {
        let floats = count
            .checked_mul(layout.stride)
            .and_then(|f| f.checked_add(MAX_STRIDE))
            .ok_or(OutOfMemory)?;
        data.try_reserve_exact(floats).map_err(|_| OutOfMemory)?;
        if stage.window.is_some() {
            windows.try_reserve_exact(count).map_err(|_| OutOfMemory)?;
        }
        codes.try_reserve_exact(count).map_err(|_| OutOfMemory)
    };
    let span = hi - lo + 1;
    let n = draw.indices.len();
    if matches!(draw.indices, Indices::Range { .. }) || span <= n.saturating_mul(2) {
        reserve(span)?;
        fill(data, codes, windows, &stage, lo..=hi, span);
        out.base = lo;
        return Ok(());
    }
    keys.try_reserve_exact(n).map_err(|_| OutOfMemory)?;
    keys.extend((0..n).map(|k| draw.indices.get(k)));
    keys.sort_unstable();
    keys.dedup();
    reserve(keys.len())?;
    fill(
        data,
        codes,
        windows,
        &stage,
        keys.iter().copied(),
        keys.len(),
    );
    out.sparse = true;
    Ok(())
}

/// Appends the `count` vertices `numbers` yields to `data` (which has the room), then the
/// padding, their reject codes to `codes` and, for triangles that share vertices, their
/// window coordinates to `windows`. Compiled also for AVX2 and SSE4.1 (the whole vertex
/// computation is inlined here) and chosen at run time.
#[cfg_attr(
    not(fuzzing),
    multiversion::multiversion(targets("x86_64+avx2", "x86_64+sse4.1"))
)]
fn fill(
    data: &mut Vec<f32>,
    codes: &mut Vec<u8>,
    windows: &mut Vec<Window>,
    stage: &transform::Stage<'_, '_>,
    numbers: impl Iterator<Item = usize>,
    count: usize,
) {
    let stride = stage.layout.stride;
    let start = data.len();
    let mut numbers = numbers;
    let light_all = stage.deferred.is_none();
    // Each group is written here, then appended: the list is written once, not first
    // initialized. Slots a group leaves unwritten (deferred colors) stay zero.
    let mut group = [0.0; LANES * MAX_STRIDE];
    for first in (0..count).step_by(LANES) {
        // A short last group repeats its first vertex in the unused lanes.
        let used = (count - first).min(LANES);
        let mut idx = [0; LANES];
        for slot in &mut idx[..used] {
            *slot = numbers.next().unwrap_or_default();
        }
        for k in used..LANES {
            idx[k] = idx[0];
        }
        let out = &mut group[..used * stride];
        let (code, pos) = stage.write_lanes(&idx, out, light_all);
        data.extend_from_slice(out);
        // Narrowed as a whole group (the codes fit a byte), then appended at once.
        let bytes: [u8; LANES] = std::array::from_fn(|k| code[k] as u8);
        codes.extend_from_slice(&bytes[..used]);
        if let Some(viewport) = &stage.window {
            windows.extend_from_slice(&viewport.lanes(pos)[..used]);
        }
    }
    data.resize(data.len() + MAX_STRIDE, 0.0);
    let Some(d) = stage.deferred else {
        return;
    };
    // The vertex numbers are the dense range first ..= first + count − 1; the vertices to
    // light are gathered into full groups.
    let vertices = &mut data[start..];
    let mut idx = [0; LANES];
    let mut m = 0;
    let from = if d.provoking_only { d.step - 1 } else { 0 };
    // The primitives' codes in chunks: a triangle dropped here (matched as three codes,
    // so without bounds checks) costs a few instructions.
    for (p, c) in codes[..count / d.step * d.step]
        .chunks_exact(d.step)
        .enumerate()
    {
        if let [a, b, c] = *c {
            if rejects_codes(a, b, c) {
                continue;
            }
        }
        let at = p * d.step;
        for k in from..d.step {
            idx[m] = d.first + at + k;
            m += 1;
            if m == LANES {
                light(stage, vertices, d.first, &idx, m);
                m = 0;
            }
        }
    }
    if m > 0 {
        for k in m..LANES {
            idx[k] = idx[0];
        }
        light(stage, vertices, d.first, &idx, m);
    }
}

/// Lights the first `m` of vertices `idx` (all `LANES` computed) in `vertices`, which
/// starts at vertex number `first`.
#[inline(always)]
fn light(
    stage: &transform::Stage<'_, '_>,
    vertices: &mut [f32],
    first: usize,
    idx: &[usize; LANES],
    m: usize,
) {
    let layout = &stage.layout;
    let (color, back_color) = stage.colors_lanes(idx, true, None, None);
    for (k, &i) in idx.iter().enumerate().take(m) {
        let v = &mut vertices[(i - first) * layout.stride..];
        for c in 0..4 {
            v[4 + c] = color[c][k];
        }
        if layout.two_side() {
            for c in 0..4 {
                v[layout.back() + c] = back_color[c][k];
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fetch_converts_every_type() {
        let bytes: Vec<u8> = [-128i8, 127, 0].iter().map(|&b| b as u8).collect();
        let a = AttribArray {
            data: &bytes,
            ty: ComponentType::Byte,
            size: 3,
            stride: 3,
            normalized: true,
        };
        assert_eq!(a.fetch(0), [-1.0, 1.0, 1.0 / 255.0, 1.0]);
        let a = AttribArray {
            normalized: false,
            size: 2,
            ..a
        };
        assert_eq!(a.fetch(0), [-128.0, 127.0, 0.0, 1.0]);
        let a = AttribArray {
            ty: ComponentType::UnsignedByte,
            normalized: true,
            size: 4,
            stride: 4,
            ..a
        };
        assert_eq!(a.fetch(0), [0.0, 0.0, 0.0, 1.0], "4 bytes past 3");
        let ub = [0u8, 255, 51, 128];
        let a = AttribArray { data: &ub, ..a };
        assert_eq!(a.fetch(0), [0.0, 1.0, 0.2, 128.0 / 255.0]);
        let sh: Vec<u8> = [-32768i16, 32767, 7]
            .iter()
            .flat_map(|v| v.to_ne_bytes())
            .collect();
        let a = AttribArray {
            data: &sh,
            ty: ComponentType::Short,
            size: 3,
            stride: 6,
            normalized: true,
        };
        assert_eq!(a.fetch(0), [-1.0, 1.0, 15.0 / 65535.0, 1.0]);
        let a = AttribArray {
            normalized: false,
            ..a
        };
        assert_eq!(a.fetch(0), [-32768.0, 32767.0, 7.0, 1.0]);
        let fx: Vec<u8> = [0x10000i32, -0x8000]
            .iter()
            .flat_map(|v| v.to_ne_bytes())
            .collect();
        let a = AttribArray {
            data: &fx,
            ty: ComponentType::Fixed,
            size: 2,
            stride: 8,
            normalized: false,
        };
        assert_eq!(a.fetch(0), [1.0, -0.5, 0.0, 1.0]);
        assert_eq!(
            a.fetch(1),
            [0.0, 0.0, 0.0, 1.0],
            "out of range reads give the default"
        );
    }

    #[test]
    fn float_fetch_reads_three_or_four_components_and_checks_the_whole_element() {
        let fl: Vec<u8> = [1.0f32, 2.0, 3.0, 4.0, 5.0]
            .iter()
            .flat_map(|v| v.to_ne_bytes())
            .collect();
        let a = |size| AttribArray {
            data: &fl,
            ty: ComponentType::Float,
            size,
            stride: 8,
            normalized: false,
        };
        assert_eq!(a(3).fetch(0), [1.0, 2.0, 3.0, 1.0]);
        assert_eq!(a(4).fetch(0), [1.0, 2.0, 3.0, 4.0]);
        assert_eq!(a(3).fetch(1), [3.0, 4.0, 5.0, 1.0]);
        assert_eq!(
            a(4).fetch(1),
            [0.0, 0.0, 0.0, 1.0],
            "last component outside"
        );
        assert_eq!(
            a(2).fetch(2),
            [0.0, 0.0, 0.0, 1.0],
            "second component outside"
        );
        assert_eq!(a(1).fetch(2), [5.0, 0.0, 0.0, 1.0]);
    }

    /// Coordinates where the frustum tests and the finiteness test change their answer.
    const EDGES: [f32; 9] = [
        0.0,
        -0.0,
        1.0,
        -1.0,
        2.0,
        -2.0,
        f32::NAN,
        f32::INFINITY,
        -1e30,
    ];

    /// The rejection rule stated directly: a coordinate that is not finite, or one of the
    /// planes x = −w, y = −w, x = w, y = w with all three positions strictly beyond it.
    fn rejected_by_rule(ps: [Vec4; 3]) -> bool {
        let beyond = |axis: fn(Vec4) -> f32, sign: f32| ps.iter().all(|&p| sign * axis(p) > p.w);
        ps.iter()
            .any(|p| p.to_array().iter().any(|c| !c.is_finite()))
            || beyond(|p| p.x, -1.0)
            || beyond(|p| p.y, -1.0)
            || beyond(|p| p.x, 1.0)
            || beyond(|p| p.y, 1.0)
    }

    #[test]
    fn reject_codes_decide_as_the_rule_says() {
        // Positions on and around the planes x = ±w and y = ±w, with infinities and NaN.
        let ps: Vec<Vec4> = EDGES
            .iter()
            .flat_map(|&x| EDGES.iter().map(move |&y| (x, y)))
            .flat_map(|(x, y)| [1.0, -1.0, 2.0, f32::NAN].map(|w| Vec4::new(x, y, 0.5, w)))
            .chain([Vec4::new(0.0, 0.0, f32::INFINITY, 1.0)])
            .collect();
        let (mut rejected, mut kept) = (0, 0);
        for (i, &a) in ps.iter().enumerate() {
            for &b in &ps[i % 7..] {
                for &c in ps.iter().step_by(5) {
                    let by_rule = rejected_by_rule([a, b, c]);
                    assert_eq!(rejects(a, b, c), by_rule, "{a} {b} {c}");
                    rejected += usize::from(by_rule);
                    kept += usize::from(!by_rule);
                }
            }
        }
        // Both answers occur, so the comparison can fail either way.
        assert!(rejected > 0 && kept > 0, "{rejected} rejected, {kept} kept");
        // Every vertex beyond the guard band, each on another side: kept, to be clipped.
        let far = [(-1e30, 0.0), (1e30, 0.0), (0.0, 1e30)].map(|(x, y)| Vec4::new(x, y, 0.5, 1.0));
        assert!(far.iter().all(|&p| reject_code(p) & CLIPS != 0));
        assert!(!rejects(far[0], far[1], far[2]));
    }

    /// The triangles kept from consecutive vertices (read from their codes in order) and
    /// from indices of each type are the ones the general walk keeps, in the same order
    /// and winding, for lists, strips and fans of every length to 13 (the codes a mix of
    /// inside, outside one plane, and not finite, so each triangle may go either way).
    #[test]
    fn kept_triangles_match_the_general_walk() {
        let mut rng = crate::tests::Lcg(0x2545_f491);
        let mut next = |n: usize| (rng.next() * n as f32) as usize;
        let choices = [0, 0, 0, 1, 1, 2, CLIPS, NOT_FINITE];
        let (mut kept, mut dropped) = (0, 0);
        for prim in [
            Primitive::Triangles,
            Primitive::TriangleStrip,
            Primitive::TriangleFan,
        ] {
            for count in 0..14 {
                for _ in 0..20 {
                    let first = 5;
                    let vertices = Vertices {
                        codes: (0..count).map(|_| choices[next(8)]).collect(),
                        base: first,
                        ..Vertices::default()
                    };
                    // The same vertices in order, and shuffled through each index type.
                    let order: Vec<usize> = (0..count)
                        .map(|k| first + (k * 7 + next(2)) % count.max(1))
                        .collect();
                    let (u8s, u16s, u32s): (Vec<u8>, Vec<u16>, Vec<u32>) = (
                        order.iter().map(|&i| i as u8).collect(),
                        order.iter().map(|&i| i as u16).collect(),
                        order.iter().map(|&i| i as u32).collect(),
                    );
                    for ix in [
                        Indices::Range { first, count },
                        Indices::U8(&u8s),
                        Indices::U16(&u16s),
                        Indices::U32(&u32s),
                    ] {
                        let mut expected = Vec::new();
                        prim.for_each_triangle(&ix, |a, b, c| {
                            let s = [a - first, b - first, c - first];
                            let codes = s.map(|s| vertices.codes[s]);
                            if !rejects_codes(codes[0], codes[1], codes[2]) {
                                expected.push(s);
                            }
                        });
                        let mut got = Vec::new();
                        vertices.for_each_kept_triangle(prim, &ix, |s| got.push(s));
                        assert_eq!(got, expected, "{prim:?} of {count}, {ix:?}");
                    }
                    let ix = Indices::Range { first, count };
                    let mut got = Vec::new();
                    vertices.for_each_kept_triangle(prim, &ix, |s| got.push(s));
                    let all = count.saturating_sub(2);
                    kept += got.len();
                    dropped += if prim == Primitive::Triangles {
                        count / 3
                    } else {
                        all
                    } - got.len();
                }
            }
        }
        assert!(
            kept > 100 && dropped > 100,
            "{kept} kept, {dropped} dropped"
        );
    }

    #[test]
    fn strips_keep_winding_and_provoking_vertex() {
        let mut tris = Vec::new();
        Primitive::TriangleStrip
            .for_each_triangle(&Indices::Range { first: 0, count: 5 }, |a, b, c| {
                tris.push((a, b, c))
            });
        assert_eq!(tris, vec![(0, 1, 2), (2, 1, 3), (2, 3, 4)]);
        let mut fan = Vec::new();
        Primitive::TriangleFan
            .for_each_triangle(&Indices::U8(&[7, 8, 9, 10]), |a, b, c| fan.push((a, b, c)));
        assert_eq!(fan, vec![(7, 8, 9), (7, 9, 10)]);
    }

    #[test]
    fn lines_strips_and_loops_assemble_segments() {
        let collect = |p: Primitive, n| {
            let mut v = Vec::new();
            p.for_each_line(&Indices::Range { first: 0, count: n }, |a, b| {
                v.push((a, b))
            });
            v
        };
        assert_eq!(collect(Primitive::Lines, 5), vec![(0, 1), (2, 3)]);
        assert_eq!(collect(Primitive::LineStrip, 3), vec![(0, 1), (1, 2)]);
        assert_eq!(
            collect(Primitive::LineLoop, 3),
            vec![(0, 1), (1, 2), (2, 0)]
        );
        assert_eq!(collect(Primitive::LineLoop, 1), vec![]);
    }
}
