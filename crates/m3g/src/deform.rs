//! What MorphingMesh and SkinnedMesh add to a Mesh, and the deformed vertex buffer that
//! rendering and picking use instead of the base one.
//!
//! A deformed mesh keeps a cache: the output VertexBuffer and the *input key* it was built
//! from (the identity and modification generation of every vertex buffer and array read,
//! the morph weights, or the bone matrices). The deformation is recomputed only when the key
//! differs. The output buffer shares the base's untouched arrays; the deformed ones are
//! arrays of its own, rewritten in place (through `dm()`, so their generation moves).

use glam::Mat4;

use super::error::Result;
use super::object::{Handle, Kind, ObjRef};
use super::vertex::{VertexArray, VertexBuffer};

/// The subclass part of a Mesh.
#[derive(Clone, Debug, Default)]
pub(crate) enum MeshExt {
    /// A plain Mesh.
    #[default]
    None,
    /// A MorphingMesh.
    Morphing(super::morphing_mesh::MorphData),
    /// A SkinnedMesh.
    Skinned(super::skinned_mesh::SkinData),
}

impl MeshExt {
    pub fn is_morphing(&self) -> bool {
        matches!(self, MeshExt::Morphing(_))
    }
    pub fn morph_weights_mut(&mut self) -> Option<&mut Vec<f32>> {
        match self {
            MeshExt::Morphing(m) => Some(&mut m.weights),
            _ => None,
        }
    }
    pub fn class_name(&self) -> &'static str {
        match self {
            MeshExt::None => "Mesh",
            MeshExt::Morphing(_) => "MorphingMesh",
            MeshExt::Skinned(_) => "SkinnedMesh",
        }
    }
    /// The extra references (morph targets; the skeleton).
    pub fn references(&self) -> Vec<ObjRef> {
        match self {
            MeshExt::None => Vec::new(),
            MeshExt::Morphing(m) => m.targets.iter().map(|t| t.0.clone()).collect(),
            MeshExt::Skinned(s) => vec![s.skeleton.0.clone()],
        }
    }
}

/// One input of a deformation: an object and its modification generation.
#[derive(Clone, Debug)]
pub(crate) struct KeyPart(pub super::object::Object3D, pub u64);

impl PartialEq for KeyPart {
    fn eq(&self, o: &Self) -> bool {
        self.0 == o.0 && self.1 == o.1
    }
}

/// The input key of a deformation.
#[derive(Clone, Debug, PartialEq, Default)]
pub(crate) struct InputKey {
    pub objects: Vec<KeyPart>,
    pub floats: Vec<f32>,
}

impl InputKey {
    /// Adds a vertex buffer and every array it holds.
    pub fn add_vb(&mut self, vb: &VertexBuffer) {
        self.add(vb.raw());
        let d = vb.d();
        let arrays = [&d.positions, &d.normals, &d.colors]
            .into_iter()
            .flatten()
            .chain(d.texcoords.iter().flatten().map(|t| &t.0));
        for a in arrays {
            self.add(a.raw());
        }
    }
    pub fn add(&mut self, r: &ObjRef) {
        let g = r.borrow().gen;
        self.objects
            .push(KeyPart(super::object::Object3D(r.clone()), g));
    }
    pub fn add_mat(&mut self, m: &Mat4) {
        self.floats.extend_from_slice(&m.to_cols_array());
    }
}

/// The cached output of a deformation. Cloning (duplicate) gives an empty cache, so copies
/// never share an output buffer.
#[derive(Debug, Default)]
pub(crate) struct Cache {
    pub key: Option<InputKey>,
    pub out: Option<VertexBuffer>,
    /// How many times the deformation was computed (a counter for tests).
    pub computed: u64,
}

impl Clone for Cache {
    fn clone(&self) -> Self {
        Cache::default()
    }
}

/// An array of `n` vertices × `comps` components of `size` bytes, reusing `old` when its
/// shape matches.
pub(crate) fn array_like(
    old: Option<&VertexArray>,
    n: usize,
    comps: usize,
    size: usize,
) -> VertexArray {
    match old {
        Some(a)
            if a.vertex_count() == n
                && a.component_count() == comps
                && a.component_type() == size =>
        {
            a.clone()
        }
        _ => VertexArray::new(n.max(1), comps, size).expect("valid array shape"),
    }
}

/// Writes `values` (one per component, already in range) into `a`.
pub(crate) fn write_ints(a: &VertexArray, values: &[i32]) {
    let mut d = a.dm();
    if d.size == 1 {
        for (k, &v) in values.iter().enumerate() {
            d.data[k] = v as u8;
        }
    } else {
        for (k, &v) in values.iter().enumerate() {
            d.data[2 * k..2 * k + 2].copy_from_slice(&(v as i16).to_ne_bytes());
        }
    }
}

/// The vertex buffer to draw or pick for mesh `r`: the deformed one for a MorphingMesh or
/// SkinnedMesh (recomputed only if an input changed), `None` for a plain Mesh. IllegalState
/// for the deferred checks of the subclasses.
pub(crate) fn deformed_vertex_buffer(r: &ObjRef) -> Result<Option<VertexBuffer>> {
    let which = match &r.borrow().kind {
        Kind::Mesh(m) => match &m.ext {
            MeshExt::None => return Ok(None),
            MeshExt::Morphing(_) => 0,
            MeshExt::Skinned(_) => 1,
        },
        _ => return Ok(None),
    };
    if which == 0 {
        super::morphing_mesh::deform(r).map(Some)
    } else {
        super::skinned_mesh::deform(r).map(Some)
    }
}

/// The skeleton of a SkinnedMesh, for traversals that must visit it as the mesh's child.
pub(crate) fn skeleton_of(r: &ObjRef) -> Option<ObjRef> {
    match &r.borrow().kind {
        Kind::Mesh(m) => match &m.ext {
            MeshExt::Skinned(s) => Some(s.skeleton.0.clone()),
            _ => None,
        },
        _ => None,
    }
}
