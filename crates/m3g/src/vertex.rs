//! `VertexArray`, `VertexBuffer`, `IndexBuffer` and `TriangleStripArray`.

use super::color::Color;
use super::error::{iae, ioobe, ise, Result};
use super::object::{class_data, handle, Handle, Inner, Kind, ObjRef};

/// Texture units of the implementation (`numTextureUnits`).
pub const NUM_TEXTURE_UNITS: usize = gles_cm_core::TEXTURE_UNITS;

#[derive(Clone, Debug)]
pub(crate) struct VertexArrayData {
    pub count: i32,
    pub comps: i32,
    /// Bytes per component: 1 or 2.
    pub size: i32,
    /// Components in native byte order (i8 or i16).
    pub data: Vec<u8>,
    /// The cached per-component minimum and maximum of the first three components (the
    /// bounding box of a position array), `None` while dirty: whatever writes `data`
    /// outside the setters here must call [`VertexArrayData::touch`].
    pub bounds: std::cell::Cell<Option<[[f32; 3]; 2]>>,
}

impl VertexArrayData {
    /// Marks the cached bounds dirty after `data` changed.
    pub fn touch(&self) {
        self.bounds.set(None);
    }

    /// The minimum and maximum of components 0..3 over every vertex (cached).
    pub fn bounds(&self) -> [[f32; 3]; 2] {
        if let Some(b) = self.bounds.get() {
            return b;
        }
        let comps = (self.comps as usize).min(3);
        let range = |c: usize, f: fn(f32, f32) -> f32, init: f32| {
            if c >= comps {
                return 0.0;
            }
            (0..self.count as usize).fold(init, |m, v| f(m, self.get(v, c) as f32))
        };
        let b = [
            [0, 1, 2].map(|c| range(c, f32::min, f32::MAX)),
            [0, 1, 2].map(|c| range(c, f32::max, f32::MIN)),
        ];
        self.bounds.set(Some(b));
        b
    }

    /// Component `c` of vertex `v` as a signed integer.
    pub fn get(&self, v: usize, c: usize) -> i32 {
        let k = v * self.comps as usize + c;
        if self.size == 1 {
            self.data[k] as i8 as i32
        } else {
            i16::from_ne_bytes([self.data[2 * k], self.data[2 * k + 1]]) as i32
        }
    }
}

handle!(
    /// `VertexArray`: an array of 2- to 4-component vertex attributes of 8 or 16 bits.
    VertexArray,
    |i| matches!(i.kind, Kind::VertexArray(_))
);
class_data!(VertexArray, VertexArray, VertexArrayData);

impl VertexArray {
    /// `VertexArray(numVertices, numComponents, componentSize)`: zero-filled.
    /// IllegalArgument unless 1 ≤ numVertices ≤ 65535, 2 ≤ numComponents ≤ 4 and
    /// componentSize (bytes) is 1 or 2.
    pub fn new(
        num_vertices: usize,
        num_components: usize,
        component_size: usize,
    ) -> Result<VertexArray> {
        if !(1..=65535).contains(&num_vertices)
            || !(2..=4).contains(&num_components)
            || !(1..=2).contains(&component_size)
        {
            return iae("invalid vertex array dimensions");
        }
        Ok(VertexArray(Inner::new(
            Kind::VertexArray(VertexArrayData {
                count: num_vertices as i32,
                comps: num_components as i32,
                size: component_size as i32,
                data: vec![0; num_vertices * num_components * component_size],
                bounds: Default::default(),
            }),
            false,
            false,
        )))
    }

    /// The vertex count of `len` components starting at vertex `first`, after the checks
    /// of `set` and `get`: IllegalState for the other component size, IllegalArgument for a
    /// length that is not whole vertices, IndexOutOfBounds past the last vertex.
    fn check(&self, first: usize, len: usize, size: i32) -> Result<usize> {
        let d = self.d();
        if d.size != size {
            return ise("the component size does not match");
        }
        let comps = d.comps as usize;
        if len % comps != 0 {
            return iae(format!(
                "{len} values are not whole vertices of {comps} components"
            ));
        }
        let n = len / comps;
        if first.saturating_add(n) > d.count as usize {
            return ioobe("vertex range outside the array");
        }
        Ok(n)
    }

    /// `set(firstVertex, numVertices, short[])` for 16-bit arrays: `values` holds whole
    /// vertices, their count is `values.len() / component_count()`.
    pub fn set_shorts(&self, first: usize, values: &[i16]) -> Result<()> {
        self.check(first, values.len(), 2)?;
        let mut d = self.dm();
        let at = first * d.comps as usize * 2;
        for (k, v) in values.iter().enumerate() {
            d.data[at + 2 * k..at + 2 * k + 2].copy_from_slice(&v.to_ne_bytes());
        }
        d.touch();
        Ok(())
    }

    /// `set(firstVertex, numVertices, byte[])` for 8-bit arrays, as
    /// [`set_shorts`](Self::set_shorts). Java bytes are signed; `i8` keeps that. See
    /// [`set_ubytes`](Self::set_ubytes).
    pub fn set_bytes(&self, first: usize, values: &[i8]) -> Result<()> {
        let u: Vec<u8> = values.iter().map(|&v| v as u8).collect();
        self.set_ubytes(first, &u)
    }

    /// `set(firstVertex, numVertices, byte[])` with the bytes given unsigned (colors).
    pub fn set_ubytes(&self, first: usize, values: &[u8]) -> Result<()> {
        self.check(first, values.len(), 1)?;
        let mut d = self.dm();
        let at = first * d.comps as usize;
        d.data[at..at + values.len()].copy_from_slice(values);
        d.touch();
        Ok(())
    }

    /// `get(firstVertex, numVertices, short[])`: the components of `n` vertices, with the
    /// checks of `set`.
    pub fn get_shorts(&self, first: usize, n: usize) -> Result<Vec<i16>> {
        let len = n.saturating_mul(self.component_count());
        self.check(first, len, 2)?;
        let d = self.d();
        let at = first * d.comps as usize * 2;
        Ok(d.data[at..at + len * 2]
            .chunks(2)
            .map(|b| i16::from_ne_bytes([b[0], b[1]]))
            .collect())
    }

    /// `get(firstVertex, numVertices, byte[])`: as [`get_shorts`](Self::get_shorts).
    pub fn get_bytes(&self, first: usize, n: usize) -> Result<Vec<i8>> {
        let len = n.saturating_mul(self.component_count());
        self.check(first, len, 1)?;
        let d = self.d();
        let at = first * d.comps as usize;
        Ok(d.data[at..at + len].iter().map(|&b| b as i8).collect())
    }

    /// `getVertexCount()`.
    pub fn vertex_count(&self) -> usize {
        self.d().count as usize
    }
    /// `getComponentCount()`.
    pub fn component_count(&self) -> usize {
        self.d().comps as usize
    }
    /// `getComponentType()`: the component size in bytes, 1 (byte) or 2 (short).
    pub fn component_type(&self) -> usize {
        self.d().size as usize
    }

    /// Every component as a float (the raw integers).
    pub(crate) fn values_f32(&self) -> Vec<f32> {
        let d = self.d();
        let n = (d.count * d.comps) as usize;
        (0..n)
            .map(|k| d.get(k / d.comps as usize, k % d.comps as usize) as f32)
            .collect()
    }
}

/// One texture-coordinate array with its scale and bias.
pub(crate) type TexCoords = (VertexArray, f32, [f32; 3]);

#[derive(Clone, Debug)]
pub(crate) struct VertexBufferData {
    pub positions: Option<VertexArray>,
    pub pos_scale: f32,
    pub pos_bias: [f32; 3],
    pub normals: Option<VertexArray>,
    pub colors: Option<VertexArray>,
    pub texcoords: [Option<TexCoords>; NUM_TEXTURE_UNITS],
    pub default_color: u32,
}

impl VertexBufferData {
    fn arrays(&self) -> impl Iterator<Item = &VertexArray> {
        [&self.positions, &self.normals, &self.colors]
            .into_iter()
            .flatten()
            .chain(self.texcoords.iter().flatten().map(|t| &t.0))
    }

    pub fn vertex_count(&self) -> usize {
        self.arrays().next().map_or(0, |a| a.vertex_count())
    }

    /// IllegalArgument if `va` differs in length from another array than `except`.
    fn check_count(&self, va: &VertexArray, except: &ObjRef) -> Result<()> {
        let n = va.vertex_count();
        for a in self.arrays() {
            if !std::rc::Rc::ptr_eq(&a.0, except) && a.vertex_count() != n {
                return iae("vertex count differs from the other arrays");
            }
        }
        Ok(())
    }
}

handle!(
    /// `VertexBuffer`: positions, normals, colors and texture coordinates of a mesh.
    VertexBuffer,
    |i| matches!(i.kind, Kind::VertexBuffer(_))
);
class_data!(VertexBuffer, VertexBuffer, VertexBufferData);

impl Default for VertexBuffer {
    fn default() -> Self {
        VertexBuffer::new()
    }
}

/// A cell no array is: for count checks that exclude nothing.
fn none_ref() -> ObjRef {
    thread_local!(static NONE: ObjRef = Inner::new(Kind::IndexBuffer(IndexData::default()), false, false));
    NONE.with(|n| n.clone())
}

impl VertexBuffer {
    /// `VertexBuffer()`: no arrays, default color opaque white.
    ///
    /// ```
    /// use m3g::prelude::*;
    ///
    /// # fn main() -> m3g::Result<()> {
    /// let positions = VertexArray::new(2, 3, 2)?; // 16-bit
    /// positions.set_shorts(0, &[0, 0, 0, 100, 0, 0])?; // two whole vertices
    /// let colors = VertexArray::new(2, 4, 1)?; // RGBA bytes
    /// colors.set_ubytes(0, &[255, 0, 0, 255, 0, 0, 255, 255])?;
    /// let vertices = VertexBuffer::new();
    /// vertices.set_positions(Some(&positions), 0.01, Some(&[0.0, 0.0, -1.0]))?; // 100 → 1.0
    /// vertices.set_colors(Some(&colors))?;
    /// assert_eq!(vertices.vertex_count(), 2);
    /// // A slice that is not whole vertices is refused.
    /// assert!(matches!(positions.set_shorts(0, &[1, 2]), Err(Error::IllegalArgument(_))));
    /// # Ok(())
    /// # }
    /// ```
    pub fn new() -> VertexBuffer {
        VertexBuffer(Inner::new(
            Kind::VertexBuffer(VertexBufferData {
                positions: None,
                pos_scale: 1.0,
                pos_bias: [0.0; 3],
                normals: None,
                colors: None,
                texcoords: Default::default(),
                default_color: 0xFFFF_FFFF,
            }),
            false,
            false,
        ))
    }

    /// `getVertexCount()`: the shared vertex count, 0 without arrays.
    pub fn vertex_count(&self) -> usize {
        self.d().vertex_count()
    }

    /// `setPositions(va, scale, bias)`: positions are `scale · v + bias` (`None` bias = 0).
    /// IllegalArgument unless `va` has 3 components, for a count mismatch with the other
    /// arrays, or a bias shorter than 3.
    pub fn set_positions(
        &self,
        va: Option<&VertexArray>,
        scale: f32,
        bias: Option<&[f32]>,
    ) -> Result<()> {
        let mut d = self.dm();
        if let Some(va) = va {
            if va.component_count() != 3 {
                return iae("positions must have 3 components");
            }
            let except = d.positions.as_ref().map_or_else(none_ref, |a| a.0.clone());
            d.check_count(va, &except)?;
        }
        let b = match bias {
            Some(b) if b.len() < 3 => return iae("bias must have 3 elements"),
            Some(b) => [b[0], b[1], b[2]],
            None => [0.0; 3],
        };
        d.positions = va.cloned();
        d.pos_scale = scale;
        d.pos_bias = b;
        Ok(())
    }

    /// `setTexCoords(index, va, scale, bias)`. IndexOutOfBounds for a unit outside
    /// [0, numTextureUnits); IllegalArgument unless `va` has 2 or 3 components, for a count
    /// mismatch, or a bias shorter than the component count.
    pub fn set_tex_coords(
        &self,
        index: usize,
        va: Option<&VertexArray>,
        scale: f32,
        bias: Option<&[f32]>,
    ) -> Result<()> {
        if index >= NUM_TEXTURE_UNITS {
            return ioobe("texture unit index");
        }
        let mut d = self.dm();
        let Some(va) = va else {
            d.texcoords[index] = None;
            return Ok(());
        };
        let c = va.component_count();
        if !(2..=3).contains(&c) {
            return iae("texture coordinates must have 2 or 3 components");
        }
        let except = d.texcoords[index]
            .as_ref()
            .map_or_else(none_ref, |t| t.0 .0.clone());
        d.check_count(va, &except)?;
        let mut b = [0.0; 3];
        if let Some(bias) = bias {
            if bias.len() < c {
                return iae("bias too short");
            }
            b[..c].copy_from_slice(&bias[..c]);
        }
        d.texcoords[index] = Some((va.clone(), scale, b));
        Ok(())
    }

    /// `setNormals(va)`: IllegalArgument unless 3 components, or for a count mismatch.
    pub fn set_normals(&self, va: Option<&VertexArray>) -> Result<()> {
        let mut d = self.dm();
        if let Some(va) = va {
            if va.component_count() != 3 {
                return iae("normals must have 3 components");
            }
            let except = d.normals.as_ref().map_or_else(none_ref, |a| a.0.clone());
            d.check_count(va, &except)?;
        }
        d.normals = va.cloned();
        Ok(())
    }

    /// `setColors(va)`: unsigned bytes, 3 (RGB) or 4 (RGBA) components. IllegalArgument
    /// otherwise, or for a count mismatch.
    pub fn set_colors(&self, va: Option<&VertexArray>) -> Result<()> {
        let mut d = self.dm();
        if let Some(va) = va {
            if va.component_type() != 1 || !(3..=4).contains(&va.component_count()) {
                return iae("colors must be 8-bit with 3 or 4 components");
            }
            let except = d.colors.as_ref().map_or_else(none_ref, |a| a.0.clone());
            d.check_count(va, &except)?;
        }
        d.colors = va.cloned();
        Ok(())
    }

    /// `getPositions(float[] scaleBias)`: the array and [scale, bias x, bias y, bias z].
    pub fn get_positions(&self) -> (Option<VertexArray>, [f32; 4]) {
        let d = self.d();
        let b = d.pos_bias;
        (d.positions.clone(), [d.pos_scale, b[0], b[1], b[2]])
    }

    /// `getTexCoords(index, float[] scaleBias)`: the array and [scale, bias...] (one bias
    /// per component). IndexOutOfBounds for a bad unit.
    pub fn get_tex_coords(&self, index: usize) -> Result<(Option<VertexArray>, Vec<f32>)> {
        if index >= NUM_TEXTURE_UNITS {
            return ioobe("texture unit index");
        }
        let d = self.d();
        Ok(match &d.texcoords[index] {
            Some((va, s, b)) => {
                let mut v = vec![*s];
                v.extend_from_slice(&b[..va.component_count()]);
                (Some(va.clone()), v)
            }
            None => (None, Vec::new()),
        })
    }

    /// `getNormals()`.
    pub fn normals(&self) -> Option<VertexArray> {
        self.d().normals.clone()
    }
    /// `getColors()`.
    pub fn colors(&self) -> Option<VertexArray> {
        self.d().colors.clone()
    }
    /// `setDefaultColor(ARGB)`: used when there is no color array.
    pub fn set_default_color(&self, argb: Color) {
        self.dm().default_color = argb.0;
    }
    /// `getDefaultColor()`.
    pub fn default_color(&self) -> Color {
        Color(self.d().default_color)
    }
}

#[derive(Clone, Debug, Default)]
pub(crate) struct IndexData {
    /// The triangles, three indices each, strips expanded with their winding kept.
    pub triangles: Vec<u16>,
}

handle!(
    /// `IndexBuffer`: the triangles of a submesh. Made by [`TriangleStripArray`].
    IndexBuffer,
    |i| matches!(i.kind, Kind::IndexBuffer(_))
);
class_data!(IndexBuffer, IndexBuffer, IndexData);

impl IndexBuffer {
    /// `getIndexCount()`: three per triangle.
    pub fn index_count(&self) -> usize {
        self.d().triangles.len()
    }
    /// `getIndices(int[])`: the triangles as index triplets.
    pub fn indices(&self) -> Vec<u16> {
        self.d().triangles.clone()
    }
}

/// `TriangleStripArray`: an [`IndexBuffer`] of triangle strips, explicit or implicit. It
/// dereferences to the IndexBuffer (the Java subclass relation).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct TriangleStripArray(pub IndexBuffer);

impl std::ops::Deref for TriangleStripArray {
    type Target = IndexBuffer;
    fn deref(&self) -> &IndexBuffer {
        &self.0
    }
}

impl Handle for TriangleStripArray {
    fn raw(&self) -> &ObjRef {
        &self.0 .0
    }
    fn from_raw(r: ObjRef) -> Self {
        TriangleStripArray(IndexBuffer(r))
    }
    fn accepts(i: &Inner) -> bool {
        matches!(i.kind, Kind::IndexBuffer(_))
    }
}

impl From<TriangleStripArray> for super::object::Object3D {
    fn from(t: TriangleStripArray) -> Self {
        super::object::Object3D(t.0 .0)
    }
}

fn check_lengths(lengths: &[usize]) -> Result<usize> {
    if lengths.is_empty() {
        return iae("no strips");
    }
    if lengths.iter().any(|&l| l < 3) {
        return iae("a strip is shorter than 3");
    }
    Ok(lengths.iter().fold(0, |a, &l| a.saturating_add(l)))
}

fn expand(strip_indices: impl Fn(usize) -> u16, lengths: &[usize]) -> Vec<u16> {
    let mut tris = Vec::new();
    let mut at = 0;
    for &l in lengths {
        for k in 0..l - 2 {
            let (a, b, c) = (
                strip_indices(at + k),
                strip_indices(at + k + 1),
                strip_indices(at + k + 2),
            );
            if k % 2 == 0 {
                tris.extend([a, b, c]);
            } else {
                tris.extend([b, a, c]);
            }
        }
        at += l;
    }
    tris
}

fn make(triangles: Vec<u16>) -> TriangleStripArray {
    TriangleStripArray(IndexBuffer(Inner::new(
        Kind::IndexBuffer(IndexData { triangles }),
        false,
        false,
    )))
}

impl TriangleStripArray {
    /// `TriangleStripArray(firstIndex, stripLengths)`: strips over consecutive vertices
    /// from `first`. IllegalArgument for no strips or one shorter than 3; IndexOutOfBounds if
    /// the vertices run past 65535.
    pub fn new_implicit(first: usize, lengths: &[usize]) -> Result<TriangleStripArray> {
        let total = check_lengths(lengths)?;
        if first.saturating_add(total) > 65535 {
            return ioobe("indices outside [0, 65535]");
        }
        Ok(make(expand(|k| (first + k) as u16, lengths)))
    }

    /// `TriangleStripArray(indices, stripLengths)`: strips over explicit indices.
    /// IllegalArgument for no strips, one shorter than 3, or too few indices (indices are
    /// 16-bit: the specification's range [0, 65535]).
    pub fn new_explicit(indices: &[u16], lengths: &[usize]) -> Result<TriangleStripArray> {
        let total = check_lengths(lengths)?;
        if indices.len() < total {
            return iae("fewer indices than the strips need");
        }
        Ok(make(expand(|k| indices[k], lengths)))
    }

    /// This strip array as an [`IndexBuffer`] reference.
    pub fn as_index_buffer(&self) -> IndexBuffer {
        self.0.clone()
    }
}
