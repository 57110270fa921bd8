//! `MorphingMesh`: a Mesh whose drawn vertices are `R = B + Σ wᵢ·(Tᵢ − B)`.

use super::appearance::Appearance;
use super::deform::{array_like, write_ints, Cache, InputKey, MeshExt};
use super::error::{iae, ioobe, ise, Result};
use super::mesh::Mesh;
use super::node::NodeExt;
use super::object::{handle, Kind, ObjRef, TransformableExt};
use super::vertex::{IndexBuffer, VertexArray, VertexBuffer, NUM_TEXTURE_UNITS};

#[derive(Clone, Debug)]
pub(crate) struct MorphData {
    pub targets: Vec<VertexBuffer>,
    pub weights: Vec<f32>,
    pub cache: Cache,
}

handle!(
    /// `MorphingMesh`: a [`Mesh`] drawn as a weighted blend of its base vertex buffer and
    /// morph targets. It is a Mesh: `as_mesh()` (or `Object3D::downcast::<Mesh>`) gives the
    /// Mesh methods (appearances, submeshes, vertex buffer = the base).
    MorphingMesh,
    |i| matches!(&i.kind, Kind::Mesh(m) if matches!(m.ext, MeshExt::Morphing(_)))
);
impl TransformableExt for MorphingMesh {}
impl NodeExt for MorphingMesh {}

impl MorphingMesh {
    /// `MorphingMesh(base, targets, triangles, appearance)`: one submesh, every weight 0.
    /// IllegalArgument if `targets` is empty.
    pub fn new(
        base: &VertexBuffer,
        targets: &[VertexBuffer],
        ib: &IndexBuffer,
        app: Option<&Appearance>,
    ) -> Result<MorphingMesh> {
        Self::with_submeshes(
            base,
            targets,
            std::slice::from_ref(ib),
            Some(&[app.cloned()]),
        )
    }

    /// `MorphingMesh(base, targets, triangles[], appearances[])`: as
    /// [`Mesh::with_submeshes`], plus IllegalArgument if `targets` is empty.
    pub fn with_submeshes(
        base: &VertexBuffer,
        targets: &[VertexBuffer],
        ibs: &[IndexBuffer],
        apps: Option<&[Option<Appearance>]>,
    ) -> Result<MorphingMesh> {
        if targets.is_empty() {
            return iae("a MorphingMesh needs at least one morph target");
        }
        let mesh = Mesh::with_submeshes(base, ibs, apps)?;
        mesh.dm().ext = MeshExt::Morphing(MorphData {
            targets: targets.to_vec(),
            weights: vec![0.0; targets.len()],
            cache: Cache::default(),
        });
        Ok(MorphingMesh(mesh.0))
    }

    fn m<R>(&self, f: impl FnOnce(&MorphData) -> R) -> R {
        let d = self.as_mesh();
        let d = d.d();
        match &d.ext {
            MeshExt::Morphing(m) => f(m),
            _ => unreachable!("a MorphingMesh"),
        }
    }

    /// This object as a [`Mesh`] reference.
    pub fn as_mesh(&self) -> Mesh {
        Mesh(self.0.clone())
    }
    /// `getMorphTargetCount()`.
    pub fn morph_target_count(&self) -> usize {
        self.m(|m| m.targets.len())
    }
    /// `getMorphTarget(index)`: IndexOutOfBounds for a bad index.
    pub fn morph_target(&self, index: usize) -> Result<VertexBuffer> {
        match self.m(|m| m.targets.get(index).cloned()) {
            Some(t) => Ok(t),
            None => ioobe("morph target index"),
        }
    }
    /// `setWeights(weights)`: the first `getMorphTargetCount()` values, any values (negative,
    /// sums ≠ 1). IllegalArgument if `weights` is shorter than the target count.
    pub fn set_weights(&self, weights: &[f32]) -> Result<()> {
        let n = self.morph_target_count();
        if weights.len() < n {
            return iae("fewer weights than morph targets");
        }
        let mesh = self.as_mesh();
        let mut d = mesh.dm();
        if let MeshExt::Morphing(m) = &mut d.ext {
            m.weights = weights[..n].to_vec();
        }
        Ok(())
    }
    /// `getWeights(weights)`: the current weights.
    pub fn weights(&self) -> Vec<f32> {
        self.m(|m| m.weights.clone())
    }
    /// The morphed vertex buffer as rendering and picking use it (a Rust extension):
    /// positions, normals, colors and texture coordinates present in the targets are
    /// morphed (rounded to the base arrays' integers; the base's scale and bias), the rest
    /// shared with the base. Recomputed only when an input changed. IllegalState when the
    /// targets do not match each other or the base.
    pub fn morphed_vertex_buffer(&self) -> Result<VertexBuffer> {
        deform(&self.0)
    }
    /// How many times the morphed buffer was computed (a Rust extension, for cache tests).
    pub fn deform_count(&self) -> u64 {
        self.m(|m| m.cache.computed)
    }
}

/// (components, size, vertex count) of an array.
type Shape = Option<(usize, usize, usize)>;

fn shape(a: Option<&VertexArray>) -> Shape {
    a.map(|a| (a.component_count(), a.component_type(), a.vertex_count()))
}

/// The arrays of a vertex buffer in a fixed order: positions, normals, colors, texcoords.
fn arrays(vb: &VertexBuffer) -> Vec<Option<VertexArray>> {
    let d = vb.d();
    let mut v = vec![d.positions.clone(), d.normals.clone(), d.colors.clone()];
    v.extend(d.texcoords.iter().map(|t| t.as_ref().map(|t| t.0.clone())));
    v
}

/// Computes (or reuses) the morphed vertex buffer of MorphingMesh `r`.
pub(crate) fn deform(r: &ObjRef) -> Result<VertexBuffer> {
    let mesh = Mesh(r.clone());
    let (base, targets, weights) = {
        let d = mesh.d();
        match &d.ext {
            MeshExt::Morphing(m) => (d.vb.clone(), m.targets.clone(), m.weights.clone()),
            _ => unreachable!("a MorphingMesh"),
        }
    };
    let mut key = InputKey::default();
    key.add_vb(&base);
    for t in &targets {
        key.add_vb(t);
    }
    key.floats = weights.clone();
    {
        let d = mesh.d();
        if let MeshExt::Morphing(m) = &d.ext {
            if let (Some(k), Some(out)) = (&m.cache.key, &m.cache.out) {
                if *k == key {
                    return Ok(out.clone());
                }
            }
        }
    }
    // Deferred checks: the targets alike, the base a superset.
    let base_arrays = arrays(&base);
    let target_arrays: Vec<Vec<Option<VertexArray>>> = targets.iter().map(arrays).collect();
    let shapes: Vec<Shape> = target_arrays[0].iter().map(|a| shape(a.as_ref())).collect();
    for t in &target_arrays[1..] {
        if t.iter()
            .map(|a| shape(a.as_ref()))
            .ne(shapes.iter().copied())
        {
            return ise("the morph targets differ in their arrays");
        }
    }
    for (k, s) in shapes.iter().enumerate() {
        if s.is_some() && shape(base_arrays[k].as_ref()) != *s {
            return ise("a morph target array is missing from the base or differs from it");
        }
    }
    let old = mesh.d().ext_cache_out();
    let out = old.clone().unwrap_or_default();
    let old_arrays = old.as_ref().map(arrays);
    let mut new_arrays: Vec<Option<VertexArray>> = Vec::with_capacity(base_arrays.len());
    for (k, b) in base_arrays.iter().enumerate() {
        let Some(b) = b else {
            new_arrays.push(None);
            continue;
        };
        if shapes[k].is_none() {
            new_arrays.push(Some(b.clone()));
            continue;
        }
        let prev = old_arrays
            .as_ref()
            .and_then(|o| o[k].clone())
            .filter(|a| base_arrays.iter().flatten().all(|x| x != a));
        let (comps, size, count) = shapes[k].unwrap();
        let a = array_like(prev.as_ref(), count, comps, size);
        let colors = k == 2;
        let read = |va: &VertexArray| -> Vec<f64> {
            let d = va.d();
            if colors {
                d.data.iter().map(|&x| x as f64).collect()
            } else {
                let n = (d.count * d.comps) as usize;
                (0..n)
                    .map(|i| d.get(i / d.comps as usize, i % d.comps as usize) as f64)
                    .collect()
            }
        };
        let bv = read(b);
        let mut acc = bv.clone();
        for (t, &w) in target_arrays.iter().zip(&weights) {
            let tv = read(t[k].as_ref().unwrap());
            for ((r, &x), &y) in acc.iter_mut().zip(&tv).zip(&bv) {
                *r += w as f64 * (x - y);
            }
        }
        let (lo, hi) = match (colors, size) {
            (true, _) => (0.0, 255.0),
            (false, 1) => (-128.0, 127.0),
            _ => (-32768.0, 32767.0),
        };
        let ints: Vec<i32> = acc
            .iter()
            .map(|&v| {
                if v.is_nan() {
                    0
                } else {
                    v.round().clamp(lo, hi) as i32
                }
            })
            .collect();
        write_ints(&a, &ints);
        new_arrays.push(Some(a));
    }
    // The default color (A, R, G, B bytes) is always morphed.
    let ch = |c: u32, s: u32| ((c >> s) & 0xFF) as f64;
    let bc = base.d().default_color;
    let mut color = 0u32;
    for s in [0, 8, 16, 24] {
        let mut v = ch(bc, s);
        for (t, &w) in targets.iter().zip(&weights) {
            v += w as f64 * (ch(t.d().default_color, s) - ch(bc, s));
        }
        let v = if v.is_nan() {
            0.0
        } else {
            v.round().clamp(0.0, 255.0)
        };
        color |= (v as u32) << s;
    }
    {
        let bd = base.d().clone();
        let mut od = out.dm();
        od.positions = new_arrays[0].clone();
        od.pos_scale = bd.pos_scale;
        od.pos_bias = bd.pos_bias;
        od.normals = new_arrays[1].clone();
        od.colors = new_arrays[2].clone();
        for u in 0..NUM_TEXTURE_UNITS {
            od.texcoords[u] = match (&new_arrays[3 + u], &bd.texcoords[u]) {
                (Some(a), Some((_, s, b))) => Some((a.clone(), *s, *b)),
                _ => None,
            };
        }
        od.default_color = color;
    }
    let mut d = mesh.dm();
    if let MeshExt::Morphing(m) = &mut d.ext {
        m.cache.key = Some(key);
        m.cache.out = Some(out.clone());
        m.cache.computed += 1;
    }
    Ok(out)
}

impl super::mesh::MeshData {
    /// The cached output buffer of a deformed mesh.
    pub(crate) fn ext_cache_out(&self) -> Option<VertexBuffer> {
        match &self.ext {
            MeshExt::Morphing(m) => m.cache.out.clone(),
            MeshExt::Skinned(s) => s.cache.out.clone(),
            MeshExt::None => None,
        }
    }
}
