//! Picking: `Group.pick` and `RayIntersection`.

use glam::{Mat4, Vec3, Vec4};

use super::camera::Camera;
use super::error::ioobe;
use super::error::{iae, ise, Result};
use super::graphics3d::sprite_rect;
use super::mesh::{Mesh, Sprite3D};
use super::modes::{Culling, Winding};
use super::node::{local, node_data, transform_between, Node};
use super::object::{tf, Handle, ObjRef};
use super::transform::invert;
use super::vertex::NUM_TEXTURE_UNITS;

/// `RayIntersection`: what a pick hit.
#[derive(Clone, Debug)]
pub struct RayIntersection {
    ray: [f32; 6],
    node: Option<Node>,
    submesh: usize,
    distance: f32,
    tex: [[f32; 2]; NUM_TEXTURE_UNITS],
    normal: [f32; 3],
}

impl Default for RayIntersection {
    fn default() -> Self {
        RayIntersection::new()
    }
}

impl RayIntersection {
    /// `RayIntersection()`: ray (0,0,0) → (0,0,1), no node, submesh 0, distance 0,
    /// texture coordinates 0, normal (0, 0, 1).
    pub fn new() -> RayIntersection {
        RayIntersection {
            ray: [0.0, 0.0, 0.0, 0.0, 0.0, 1.0],
            node: None,
            submesh: 0,
            distance: 0.0,
            tex: [[0.0; 2]; NUM_TEXTURE_UNITS],
            normal: [0.0, 0.0, 1.0],
        }
    }
    /// `getIntersected()`: the Mesh or Sprite3D hit.
    pub fn intersected(&self) -> Option<Node> {
        self.node.clone()
    }
    /// `getRay(float[6])`: origin and direction in the picked group's coordinates.
    pub fn ray(&self) -> [f32; 6] {
        self.ray
    }
    /// `getDistance()`: the hit is at origin + distance · direction.
    pub fn distance(&self) -> f32 {
        self.distance
    }
    /// `getSubmeshIndex()`: 0 for sprites.
    pub fn submesh_index(&self) -> usize {
        self.submesh
    }
    /// `getTextureS(unit)`: IndexOutOfBounds for a bad unit.
    pub fn texture_s(&self, unit: usize) -> Result<f32> {
        match self.tex.get(unit) {
            Some(t) => Ok(t[0]),
            None => ioobe("texture unit index"),
        }
    }
    /// `getTextureT(unit)`: IndexOutOfBounds for a bad unit.
    pub fn texture_t(&self, unit: usize) -> Result<f32> {
        match self.tex.get(unit) {
            Some(t) => Ok(t[1]),
            None => ioobe("texture unit index"),
        }
    }
    /// `getNormalX()`: the unit normal at the hit, in the node's coordinates.
    pub fn normal_x(&self) -> f32 {
        self.normal[0]
    }
    /// `getNormalY()`.
    pub fn normal_y(&self) -> f32 {
        self.normal[1]
    }
    /// `getNormalZ()`.
    pub fn normal_z(&self) -> f32 {
        self.normal[2]
    }
}

struct Pick {
    best: Option<RayIntersection>,
    o: Vec3,
    d: Vec3,
    scope: i32,
    /// With the camera variant: projection and camera-to-group, for sprites.
    sprites: Option<(Mat4, Mat4)>,
}

pub(crate) fn pick_ray(
    group: &ObjRef,
    scope: i32,
    o: [f32; 3],
    d: [f32; 3],
) -> Result<Option<RayIntersection>> {
    if d == [0.0; 3] {
        return iae("the pick direction is zero");
    }
    run(group, scope, Vec3::from_array(o), Vec3::from_array(d), None)
}

pub(crate) fn pick_camera(
    group: &ObjRef,
    scope: i32,
    x: f32,
    y: f32,
    camera: &Camera,
) -> Result<Option<RayIntersection>> {
    let Some(cam_to_group) = transform_between(&camera.0, group)? else {
        return ise("the camera is not in the group's scene graph");
    };
    let Some(p) = camera.projection_matrix() else {
        return super::error::ae("the projection is not invertible");
    };
    let inv = invert(&p)?;
    let unproject = |z: f32| {
        let v = inv * Vec4::new(2.0 * x - 1.0, 1.0 - 2.0 * y, z, 1.0);
        cam_to_group * (v / v.w)
    };
    let near = unproject(-1.0).truncate();
    let far = unproject(1.0).truncate();
    run(group, scope, near, far - near, Some((p, cam_to_group)))
}

fn run(
    group: &ObjRef,
    scope: i32,
    o: Vec3,
    d: Vec3,
    sprites: Option<(Mat4, Mat4)>,
) -> Result<Option<RayIntersection>> {
    let mut p = Pick {
        best: None,
        o,
        d,
        scope,
        sprites,
    };
    let children = group.borrow().group().unwrap().children.clone();
    for c in &children {
        visit(c, local(c), &mut p)?;
    }
    Ok(p.best.map(|mut ri| {
        ri.ray = [o.x, o.y, o.z, d.x, d.y, d.z];
        ri
    }))
}

/// Picks `r` (whose node-to-group transform is `m`) and its descendants in depth-first
/// pre-order, a SkinnedMesh after its skeleton. A heap stack, not recursion: a loaded file
/// can nest groups deeper than the thread's stack allows.
fn visit(r: &ObjRef, m: Mat4, p: &mut Pick) -> Result<()> {
    // `true`: the node's own geometry, once its skeleton has been picked.
    let mut stack = vec![(r.clone(), m, false)];
    while let Some((r, m, own)) = stack.pop() {
        let (picking, scope) = {
            let n = node_data(&r);
            (n.picking, n.scope)
        };
        if own {
            if scope & p.scope == 0 {
                continue;
            }
            if Mesh::accepts(&r.borrow()) {
                pick_mesh(&Mesh(r.clone()), m, p)?;
            } else if Sprite3D::accepts(&r.borrow()) {
                pick_sprite(&Sprite3D(r.clone()), m, p);
            }
            continue;
        }
        if !picking {
            continue;
        }
        let children = r.borrow().group().map(|g| g.children.clone());
        if let Some(children) = children {
            for c in children.iter().rev() {
                stack.push((c.clone(), m * local(c), false));
            }
            continue;
        }
        stack.push((r.clone(), m, true));
        // A SkinnedMesh's skeleton is its child branch.
        if let Some(skeleton) = super::deform::skeleton_of(&r) {
            let sm = m * local(&skeleton);
            stack.push((skeleton, sm, false));
        }
    }
    Ok(())
}

fn pick_mesh(mesh: &Mesh, m: Mat4, p: &mut Pick) -> Result<()> {
    let inv = invert(&m)?;
    let o = (inv * p.o.extend(1.0)).truncate();
    let d = (inv * p.d.extend(0.0)).truncate();
    let mirrored = m.determinant() < 0.0;
    // MorphingMesh / SkinnedMesh: the deformed copy.
    let deformed = super::deform::deformed_vertex_buffer(&mesh.0)?;
    let md = mesh.d();
    let vbd = deformed.as_ref().unwrap_or(&md.vb).d();
    for (k, (ib, app)) in md.ibs.iter().zip(&md.apps).enumerate() {
        let Some(app) = app else { continue };
        let Some(pos) = &vbd.positions else {
            return ise("the vertex buffer has no positions");
        };
        let pd = pos.d();
        let tris = ib.d().triangles.clone();
        if tris.iter().any(|&i| i as i32 >= pd.count) {
            return ise("an index is past the vertex count");
        }
        let (culling, ccw) = app.polygon_mode().map_or((Culling::Back, true), |pm| {
            (pm.culling(), pm.winding() == Winding::Ccw)
        });
        let vertex = |v: usize| {
            Vec3::new(
                pd.get(v, 0) as f32,
                pd.get(v, 1) as f32,
                pd.get(v, 2) as f32,
            ) * vbd.pos_scale
                + Vec3::from_array(vbd.pos_bias)
        };
        for t in tris.chunks(3) {
            let [a, b, c] = [t[0] as usize, t[1] as usize, t[2] as usize];
            let (va, vb, vc) = (vertex(a), vertex(b), vertex(c));
            let (e1, e2) = (vb - va, vc - va);
            let n = e1.cross(e2);
            let facing = n.dot(d) * if mirrored { -1.0 } else { 1.0 };
            let front = if ccw { facing < 0.0 } else { facing > 0.0 };
            if (culling == Culling::Back && !front) || (culling == Culling::Front && front) {
                continue;
            }
            // Möller–Trumbore.
            let pv = d.cross(e2);
            let det = e1.dot(pv);
            if det == 0.0 {
                continue;
            }
            let tv = o - va;
            let u = tv.dot(pv) / det;
            if !(0.0..=1.0).contains(&u) {
                continue;
            }
            let qv = tv.cross(e1);
            let v = d.dot(qv) / det;
            if v < 0.0 || u + v > 1.0 {
                continue;
            }
            let dist = e2.dot(qv) / det;
            if dist < 0.0 || p.best.as_ref().is_some_and(|b| b.distance <= dist) {
                continue;
            }
            let w = 1.0 - u - v;
            let normal = match &vbd.normals {
                Some(na) => {
                    let nd = na.d();
                    let dec = |i: usize| {
                        let f = |c| {
                            let x = nd.get(i, c) as f32;
                            if nd.size == 1 {
                                (2.0 * x + 1.0) / 255.0
                            } else {
                                (2.0 * x + 1.0) / 65535.0
                            }
                        };
                        Vec3::new(f(0), f(1), f(2))
                    };
                    dec(a) * w + dec(b) * u + dec(c) * v
                }
                None => n,
            }
            .normalize_or_zero();
            let mut tex = [[0.0f32; 2]; NUM_TEXTURE_UNITS];
            for (unit, slot) in tex.iter_mut().enumerate() {
                let Some((ta, s, bias)) = &vbd.texcoords[unit] else {
                    continue;
                };
                let td = ta.d();
                let tc = |i: usize| {
                    let g = |c: usize| {
                        if c < td.comps as usize {
                            td.get(i, c) as f32 * s + bias[c]
                        } else {
                            0.0
                        }
                    };
                    Vec4::new(g(0), g(1), g(2), 1.0)
                };
                let mut q = tc(a) * w + tc(b) * u + tc(c) * v;
                if let Ok(Some(tex2d)) = app.texture(unit) {
                    q = tf(&tex2d.0).composite() * q;
                }
                *slot = [q.x / q.w, q.y / q.w];
            }
            p.best = Some(RayIntersection {
                ray: [0.0; 6],
                node: Some(Node(mesh.0.clone())),
                submesh: k,
                distance: dist,
                tex,
                normal: normal.to_array(),
            });
        }
    }
    Ok(())
}

/// Scaled sprites, camera variant only: tested in NDC against the sprite's rectangle.
fn pick_sprite(sprite: &Sprite3D, m: Mat4, p: &mut Pick) {
    let Some((proj, cam_to_group)) = p.sprites else {
        return;
    };
    if !sprite.is_scaled() {
        return;
    }
    let Some(app) = sprite.appearance() else {
        return;
    };
    let Ok(group_to_cam) = invert(&cam_to_group) else {
        return;
    };
    let mv = group_to_cam * m;
    // A unit viewport: NDC [-1, 1] maps to [0, 2] with y down.
    let Some(([x0, y0, w, h], z, _)) = sprite_rect(sprite, mv, proj, [0, 0, 2, 2]) else {
        return;
    };
    // The ray's point on the sprite's depth plane, in NDC.
    let to_ndc = |v: Vec3| {
        let c = proj * (group_to_cam * v.extend(1.0));
        c.truncate() / c.w
    };
    let (a, b) = (to_ndc(p.o), to_ndc(p.o + p.d));
    if a.z == b.z {
        return;
    }
    let t = (z - a.z) / (b.z - a.z);
    let hit = a + (b - a) * t;
    let (sx, sy) = (hit.x + 1.0, 1.0 - hit.y);
    if w <= 0.0 || h <= 0.0 || sx < x0 || sx >= x0 + w || sy < y0 || sy >= y0 + h {
        return;
    }
    // The image pixel there must pass the alpha test (before the alpha factor).
    let [cx, cy, cw, ch] = sprite.d().crop;
    let (fu, fv) = ((sx - x0) / w, (sy - y0) / h);
    let ix = cx
        + if cw > 0 {
            (fu * cw as f32) as i32
        } else {
            ((1.0 - fu) * (-cw) as f32) as i32
        };
    let iy = cy
        + if ch > 0 {
            (fv * ch as f32) as i32
        } else {
            ((1.0 - fv) * (-ch) as f32) as i32
        };
    let img = sprite.image();
    let id = img.d();
    if !(0..id.width).contains(&ix) || !(0..id.height).contains(&iy) {
        return;
    }
    let threshold = app.compositing_mode().map_or(0.0, |c| c.alpha_threshold());
    if id.rgba(ix, iy)[3] < threshold {
        return;
    }
    if p.best.as_ref().is_some_and(|b| b.distance <= t) {
        return;
    }
    let mut tex = [[0.0f32; 2]; NUM_TEXTURE_UNITS];
    tex[0] = [
        (ix as f32 + 0.5) / id.width as f32,
        (iy as f32 + 0.5) / id.height as f32,
    ];
    p.best = Some(RayIntersection {
        ray: [0.0; 6],
        node: Some(Node(sprite.0.clone())),
        submesh: 0,
        distance: t,
        tex,
        normal: [0.0, 0.0, 1.0],
    });
}
