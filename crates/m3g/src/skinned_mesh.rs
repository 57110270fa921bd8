//! `SkinnedMesh`: a Mesh whose vertices follow the bones of its skeleton,
//! `v' = Σ wᵢ·Mᵢ·Bᵢ·v` with the reference space the SkinnedMesh's own coordinates.

use std::collections::HashMap;
use std::rc::Rc;

use glam::{Mat3, Mat4, Vec3};

use super::appearance::Appearance;
use super::deform::{array_like, write_ints, Cache, InputKey, MeshExt};
use super::error::{iae, ioobe, ise, Result};
use super::mesh::Mesh;
use super::node::{is_descendant_or_self, to_ancestor, transform_between, Group, Node, NodeExt};
use super::object::{handle, Inner, Kind, ObjRef, TransformableExt};
use super::transform::Transform;
use super::vertex::{IndexBuffer, VertexBuffer};

/// The most bones that act on one vertex: the highest weights win (as the Nokia engine,
/// `M3G_MAX_VERTEX_TRANSFORMS`).
pub const MAX_TRANSFORMS_PER_VERTEX: usize = 4;

/// One `addTransform` call.
#[derive(Clone, Debug)]
pub(crate) struct BoneEntry {
    pub bone: Node,
    /// B: SkinnedMesh → bone at rest.
    pub at_rest: Mat4,
    pub weight: i32,
    pub first: i32,
    pub count: i32,
}

#[derive(Clone, Debug)]
pub(crate) struct SkinData {
    pub skeleton: Group,
    pub entries: Vec<BoneEntry>,
    pub cache: Cache,
}

handle!(
    /// `SkinnedMesh`: a [`Mesh`] deformed by the bones of its skeleton Group, which is its
    /// only child. `as_mesh()` gives the Mesh methods.
    SkinnedMesh,
    |i| matches!(&i.kind, Kind::Mesh(m) if matches!(m.ext, MeshExt::Skinned(_)))
);
impl TransformableExt for SkinnedMesh {}
impl NodeExt for SkinnedMesh {}

impl SkinnedMesh {
    /// `SkinnedMesh(vertices, triangles, appearance, skeleton)`: one submesh, no bones.
    /// IllegalArgument if `skeleton` is a World or already has a parent.
    pub fn new(
        vb: &VertexBuffer,
        ib: &IndexBuffer,
        app: Option<&Appearance>,
        skeleton: &Group,
    ) -> Result<SkinnedMesh> {
        Self::with_submeshes(
            vb,
            std::slice::from_ref(ib),
            Some(&[app.cloned()]),
            skeleton,
        )
    }

    /// `SkinnedMesh(vertices, triangles[], appearances[], skeleton)`: as
    /// [`Mesh::with_submeshes`], plus the skeleton checks of [`new`](Self::new).
    pub fn with_submeshes(
        vb: &VertexBuffer,
        ibs: &[IndexBuffer],
        apps: Option<&[Option<Appearance>]>,
        skeleton: &Group,
    ) -> Result<SkinnedMesh> {
        if matches!(skeleton.0.borrow().kind, Kind::World(_)) {
            return iae("the skeleton cannot be a World");
        }
        if skeleton.parent().is_some() {
            return iae("the skeleton already has a parent");
        }
        let mesh = Mesh::with_submeshes(vb, ibs, apps)?;
        mesh.dm().ext = MeshExt::Skinned(SkinData {
            skeleton: skeleton.clone(),
            entries: Vec::new(),
            cache: Cache::default(),
        });
        skeleton.0.borrow_mut().node.as_mut().unwrap().parent = Some(Rc::downgrade(&mesh.0));
        Ok(SkinnedMesh(mesh.0))
    }

    fn s<R>(&self, f: impl FnOnce(&SkinData) -> R) -> R {
        let m = Mesh(self.0.clone());
        let d = m.d();
        match &d.ext {
            MeshExt::Skinned(s) => f(s),
            _ => unreachable!("a SkinnedMesh"),
        }
    }

    /// This object as a [`Mesh`] reference.
    pub fn as_mesh(&self) -> Mesh {
        Mesh(self.0.clone())
    }
    /// `getSkeleton()`.
    pub fn skeleton(&self) -> Group {
        self.s(|s| s.skeleton.clone())
    }

    fn check_bone(&self, bone: &Node) -> Result<()> {
        let skel = self.skeleton();
        if !is_descendant_or_self(&bone.0, &skel.0) {
            return iae("the bone is not in the skeleton");
        }
        Ok(())
    }

    /// `addTransform(bone, weight, firstVertex, numVertices)`: the vertices
    /// [first, first + count) follow `bone` with weight `weight`; the at-rest transform
    /// `this.getTransformTo(bone)` is recorded now. IllegalArgument if the bone is not the
    /// skeleton or a descendant, weight ≤ 0 or count = 0; IndexOutOfBounds if
    /// first + count > 65535; Arithmetic if the at-rest transform is singular.
    pub fn add_transform(
        &self,
        bone: &Node,
        weight: i32,
        first: usize,
        count: usize,
    ) -> Result<()> {
        self.check_bone(bone)?;
        if weight <= 0 {
            return iae("bone weight must be positive");
        }
        if count == 0 {
            return iae("vertex count must be positive");
        }
        if first.saturating_add(count) > 65535 {
            return ioobe("vertex range outside [0, 65535]");
        }
        // Both fit in i32 now: at most 65535.
        let (first, count) = (first as i32, count as i32);
        let at_rest = transform_between(&self.0, &bone.0)?.expect("the bone is a descendant");
        let mesh = self.as_mesh();
        let mut d = mesh.dm();
        if let MeshExt::Skinned(s) = &mut d.ext {
            s.entries.push(BoneEntry {
                bone: bone.clone(),
                at_rest,
                weight,
                first,
                count,
            });
        }
        Ok(())
    }

    /// `getBoneTransform(bone, T)`: the at-rest transform recorded for `bone` (the first one
    /// if it was added several times; identity if never added). IllegalArgument if the bone
    /// is not in the skeleton.
    pub fn get_bone_transform(&self, bone: &Node) -> Result<Transform> {
        self.check_bone(bone)?;
        let m = self.s(|s| {
            s.entries
                .iter()
                .find(|e| e.bone == *bone)
                .map_or(Mat4::IDENTITY, |e| e.at_rest)
        });
        Ok(Transform::from_mat4(m))
    }

    /// `getBoneVertices(bone, indices, weights)`: the vertices `bone` moves and its
    /// normalized weight in each (after keeping the [`MAX_TRANSFORMS_PER_VERTEX`] highest
    /// weights of a vertex); no duplicates, no zero weights. IllegalArgument if the bone is
    /// not in the skeleton.
    pub fn get_bone_vertices(&self, bone: &Node) -> Result<(Vec<usize>, Vec<f32>)> {
        self.check_bone(bone)?;
        let (bones, infl) = self.s(|s| influences(&s.entries, None));
        let Some(b) = bones.iter().position(|e| e.bone == *bone) else {
            return Ok((Vec::new(), Vec::new()));
        };
        let (mut idx, mut w) = (Vec::new(), Vec::new());
        for (v, list) in infl.iter().enumerate() {
            if let Some(&(_, x)) = list.iter().find(|(k, x)| *k == b && *x > 0.0) {
                idx.push(v);
                w.push(x);
            }
        }
        Ok((idx, w))
    }

    /// The skinned positions and normals in this mesh's coordinates, as floats (a Rust
    /// extension, for exact checks). IllegalState if a bone's vertex range passes the vertex
    /// count or the buffer has no positions.
    #[allow(clippy::type_complexity)]
    pub fn skinned_vertices(&self) -> Result<(Vec<[f32; 3]>, Option<Vec<[f32; 3]>>)> {
        let (p, n) = compute(&self.0)?;
        Ok((
            p.iter().map(|v| v.to_array()).collect(),
            n.map(|n| n.iter().map(|v| v.to_array()).collect()),
        ))
    }
    /// The skinned vertex buffer as rendering and picking use it (a Rust extension): 16-bit
    /// positions and normals, colors and texture coordinates shared with the base.
    /// Recomputed only when the base buffer or a bone's transform changed.
    pub fn skinned_vertex_buffer(&self) -> Result<VertexBuffer> {
        deform(&self.0)
    }
    /// How many times the skinned buffer was computed (a Rust extension, for cache tests).
    pub fn deform_count(&self) -> u64 {
        self.s(|s| s.cache.computed)
    }
}

/// The distinct bones (first entry of each) and, per vertex, up to
/// [`MAX_TRANSFORMS_PER_VERTEX`] (bone index, normalized weight) pairs.
#[allow(clippy::type_complexity)]
fn influences(
    entries: &[BoneEntry],
    vertex_count: Option<usize>,
) -> (Vec<BoneEntry>, Vec<Vec<(usize, f32)>>) {
    let mut bones: Vec<BoneEntry> = Vec::new();
    let mut which = Vec::with_capacity(entries.len());
    for e in entries {
        match bones.iter().position(|b| b.bone == e.bone) {
            Some(k) => which.push(k),
            None => {
                which.push(bones.len());
                bones.push(e.clone());
            }
        }
    }
    let n = vertex_count.unwrap_or_else(|| {
        entries
            .iter()
            .map(|e| (e.first + e.count) as usize)
            .max()
            .unwrap_or(0)
    });
    let mut raw: Vec<Vec<(usize, i64)>> = vec![Vec::new(); n];
    for (e, &b) in entries.iter().zip(&which) {
        let end = ((e.first + e.count) as usize).min(n);
        for list in raw.iter_mut().take(end).skip(e.first as usize) {
            match list.iter_mut().find(|(k, _)| *k == b) {
                Some(x) => x.1 += e.weight as i64,
                None => list.push((b, e.weight as i64)),
            }
        }
    }
    let out = raw
        .into_iter()
        .map(|mut list| {
            // Highest weights first; ties go to the bone added first.
            list.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
            list.truncate(MAX_TRANSFORMS_PER_VERTEX);
            let sum: i64 = list.iter().map(|x| x.1).sum();
            list.into_iter()
                .map(|(k, w)| (k, if sum == 0 { 0.0 } else { w as f32 / sum as f32 }))
                .collect()
        })
        .collect();
    (bones, out)
}

/// The inverse transpose of the upper 3×3 of `m`, or zero when it is singular (a bone with
/// zero scale contributes no normal).
fn normal_matrix(m: &Mat4) -> Mat3 {
    let a = Mat3::from_mat4(*m);
    let det = a.determinant();
    if det == 0.0 || !det.is_finite() {
        return Mat3::ZERO;
    }
    let n = a.inverse().transpose();
    if n.is_finite() {
        n
    } else {
        Mat3::ZERO
    }
}

fn skin_data(r: &ObjRef) -> (VertexBuffer, Vec<BoneEntry>) {
    let mesh = Mesh(r.clone());
    let d = mesh.d();
    match &d.ext {
        MeshExt::Skinned(s) => (d.vb.clone(), s.entries.clone()),
        _ => unreachable!("a SkinnedMesh"),
    }
}

/// The per-bone matrices Mᵢ·Bᵢ (bone → mesh now, times mesh → bone at rest).
fn bone_matrices(r: &ObjRef, bones: &[BoneEntry]) -> Vec<Mat4> {
    bones
        .iter()
        .map(|b| to_ancestor(&b.bone.0, r) * b.at_rest)
        .collect()
}

/// Skinned positions and normals (floats, mesh coordinates).
#[allow(clippy::type_complexity)]
fn compute(r: &ObjRef) -> Result<(Vec<Vec3>, Option<Vec<Vec3>>)> {
    let (vb, entries) = skin_data(r);
    let vbd = vb.d().clone();
    let Some(pos) = &vbd.positions else {
        return ise("the vertex buffer has no positions");
    };
    let n = pos.vertex_count();
    if entries.iter().any(|e| (e.first + e.count) as usize > n) {
        return ise("a bone's vertex range passes the vertex count");
    }
    let (bones, infl) = influences(&entries, Some(n));
    let mats = bone_matrices(r, &bones);
    let nmats: Vec<Mat3> = mats.iter().map(normal_matrix).collect();
    let pd = pos.d();
    let bias = Vec3::from_array(vbd.pos_bias);
    let positions: Vec<Vec3> = (0..n)
        .map(|v| {
            let p = Vec3::new(
                pd.get(v, 0) as f32,
                pd.get(v, 1) as f32,
                pd.get(v, 2) as f32,
            ) * vbd.pos_scale
                + bias;
            if infl[v].is_empty() {
                return p;
            }
            infl[v].iter().fold(Vec3::ZERO, |acc, &(k, w)| {
                acc + w * mats[k].transform_point3(p)
            })
        })
        .collect();
    let normals = vbd.normals.as_ref().map(|na| {
        let nd = na.d();
        (0..n)
            .map(|v| {
                let k = |c: usize| {
                    let x = nd.get(v, c) as f32;
                    if nd.size == 1 {
                        (2.0 * x + 1.0) / 255.0
                    } else {
                        (2.0 * x + 1.0) / 65535.0
                    }
                };
                let nv = Vec3::new(k(0), k(1), k(2));
                if infl[v].is_empty() {
                    return nv;
                }
                let s = infl[v]
                    .iter()
                    .fold(Vec3::ZERO, |acc, &(b, w)| acc + w * (nmats[b] * nv));
                if s.length_squared() > 0.0 && s.is_finite() {
                    s.normalize() * nv.length()
                } else {
                    nv
                }
            })
            .collect()
    });
    Ok((positions, normals))
}

/// Computes (or reuses) the skinned vertex buffer of SkinnedMesh `r`.
pub(crate) fn deform(r: &ObjRef) -> Result<VertexBuffer> {
    let (vb, entries) = skin_data(r);
    let (bones, _) = influences(&entries, Some(0));
    let mut key = InputKey::default();
    key.add_vb(&vb);
    key.floats.push(entries.len() as f32);
    for m in bone_matrices(r, &bones) {
        key.add_mat(&m);
    }
    let mesh = Mesh(r.clone());
    let old = {
        let d = mesh.d();
        match &d.ext {
            MeshExt::Skinned(s) => {
                if let (Some(k), Some(out)) = (&s.cache.key, &s.cache.out) {
                    if *k == key {
                        return Ok(out.clone());
                    }
                }
                s.cache.out.clone()
            }
            _ => unreachable!("a SkinnedMesh"),
        }
    };
    let (positions, normals) = compute(r)?;
    let n = positions.len();
    let out = old.unwrap_or_default();
    let (old_pos, old_nrm) = {
        let od = out.d();
        (od.positions.clone(), od.normals.clone())
    };
    // Positions: 16 bits over the bounding box.
    let (lo, hi) = positions.iter().fold(
        (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    );
    let (center, half) = if n == 0 || !lo.is_finite() || !hi.is_finite() {
        (Vec3::ZERO, 0.0)
    } else {
        ((lo + hi) * 0.5, ((hi - lo) * 0.5).max_element())
    };
    let scale = if half > 0.0 { half / 32767.0 } else { 1.0 };
    let pa = array_like(old_pos.as_ref(), n, 3, 2);
    let ints: Vec<i32> = positions
        .iter()
        .flat_map(|p| ((*p - center) / scale).to_array())
        .map(|x| x.round().clamp(-32767.0, 32767.0) as i32)
        .collect();
    write_ints(&pa, &ints);
    let na = normals.map(|nv| {
        let a = array_like(old_nrm.as_ref(), n, 3, 2);
        let ints: Vec<i32> = nv
            .iter()
            .flat_map(|v| v.normalize_or_zero().to_array())
            .map(|x| (x * 32767.0).round().clamp(-32768.0, 32767.0) as i32)
            .collect();
        write_ints(&a, &ints);
        a
    });
    {
        let bd = vb.d().clone();
        let mut od = out.dm();
        od.positions = Some(pa);
        od.pos_scale = scale;
        od.pos_bias = center.to_array();
        od.normals = na;
        od.colors = bd.colors.clone();
        od.texcoords = bd.texcoords.clone();
        od.default_color = bd.default_color;
    }
    let mut d = mesh.dm();
    if let MeshExt::Skinned(s) = &mut d.ext {
        s.cache.key = Some(key);
        s.cache.out = Some(out.clone());
        s.cache.computed += 1;
    }
    Ok(out)
}

/// After a SkinnedMesh node `copy` was duplicated: gives it a copy of the skeleton (made by
/// `dup`, with `copy` as its parent).
pub(crate) fn duplicate_skeleton(copy: &ObjRef, dup: &mut dyn FnMut(&ObjRef) -> ObjRef) {
    let Some(skel) = super::deform::skeleton_of(copy) else {
        return;
    };
    let new = dup(&skel);
    if let Kind::Mesh(m) = &mut copy.borrow_mut().kind {
        if let MeshExt::Skinned(s) = &mut m.ext {
            s.skeleton = Group(new);
        }
    }
}

/// Points the bones of a duplicated SkinnedMesh at the copied nodes.
pub(crate) fn remap_bones(i: &mut Inner, map: &HashMap<*const std::cell::RefCell<Inner>, ObjRef>) {
    if let Kind::Mesh(m) = &mut i.kind {
        if let MeshExt::Skinned(s) = &mut m.ext {
            for e in &mut s.entries {
                if let Some(n) = map.get(&Rc::as_ptr(&e.bone.0)) {
                    e.bone = Node(n.clone());
                }
            }
        }
    }
}
