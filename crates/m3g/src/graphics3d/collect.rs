//! Collecting what a scene graph draws, in the order M3G numbers it, and culling submeshes
//! whose bounds lie outside the view frustum before any vertex is transformed.

use glam::{Mat4, Vec3, Vec4};

use crate::appearance::Appearance;
use crate::error::{ise, Result};
use crate::light::Light;
use crate::mesh::{Mesh, Sprite3D};
use crate::modes::Blending;
use crate::node::{node_data, to_ancestor};
use crate::object::{tf, Handle, Kind, ObjRef};
use crate::vertex::{IndexBuffer, VertexBuffer, VertexBufferData};

/// One thing to draw, found in a scene graph.
pub(super) struct Item {
    pub(super) layer: i32,
    pub(super) blended: bool,
    pub(super) what: What,
    pub(super) model: Mat4,
    pub(super) alpha: f32,
    pub(super) scope: i32,
    /// Whether the item may be culled against its bounds (a plain Mesh's submesh or an
    /// immediate-mode submesh; deformed meshes are not, as their base bounds do not hold).
    pub(super) cullable: bool,
}

pub(super) enum What {
    Submesh(VertexBuffer, IndexBuffer, Appearance),
    Sprite(Sprite3D, Appearance),
}

/// The enabled lights under `world` in depth-first pre-order (the order the lights are
/// numbered in). A heap stack, not recursion: a loaded file can nest groups deeper than the
/// thread's stack allows.
pub(super) fn collect_lights(world: &ObjRef, out: &mut Vec<(Light, Mat4)>) {
    let mut stack = vec![world.clone()];
    while let Some(r) = stack.pop() {
        let (enabled, children, is_light) = {
            let i = r.borrow();
            (
                i.node.as_ref().is_some_and(|n| n.rendering),
                i.group()
                    .map(|g| g.children.clone())
                    .unwrap_or_default()
                    .into_iter()
                    .chain(crate::deform::skeleton_of(&r))
                    .collect::<Vec<_>>(),
                matches!(i.kind, Kind::Light(_)),
            )
        };
        if !enabled {
            continue;
        }
        if is_light {
            out.push((Light(r.clone()), to_ancestor(&r, world)));
        }
        stack.extend(children.into_iter().rev());
    }
}

pub(super) fn is_blended(app: &Appearance) -> bool {
    app.compositing_mode()
        .is_some_and(|c| c.blending() != Blending::Replace)
}

/// The deferred checks of a submesh: positions present, indices inside the buffer.
pub(super) fn validate(vb: &VertexBuffer, ib: &IndexBuffer) -> Result<()> {
    let d = vb.d();
    if d.positions.is_none() {
        return ise("the vertex buffer has no positions");
    }
    let n = d.vertex_count();
    if ib.d().triangles.iter().any(|&i| i as usize >= n) {
        return ise("an index is past the vertex count");
    }
    Ok(())
}

/// One step of the drawable-item traversal.
enum Step {
    /// Visit a node whose own node-to-world transform is the matrix.
    Node(ObjRef, Mat4, f32),
    /// Emit a mesh's or sprite's items (after its skeleton's, which are its children's).
    Emit(ObjRef, Mat4, f32, i32),
}

/// Collects the drawable items of `r` and its descendants, with `m` as `r`'s own
/// node-to-world transform, in depth-first pre-order (a SkinnedMesh after its skeleton),
/// stopping at the first invalid submesh. A heap stack, not recursion: a loaded file can
/// nest groups deeper than the thread's stack allows.
pub(super) fn collect_at(
    r: &ObjRef,
    m: Mat4,
    alpha: f32,
    cam_scope: i32,
    out: &mut Vec<Item>,
) -> Result<()> {
    let mut stack = vec![Step::Node(r.clone(), m, alpha)];
    while let Some(step) = stack.pop() {
        match step {
            Step::Node(r, m, alpha) => {
                let (rendering, a, scope) = {
                    let n = node_data(&r);
                    (n.rendering, n.alpha, n.scope)
                };
                if !rendering {
                    continue;
                }
                let alpha = alpha * a;
                let kind_children = r.borrow().group().map(|g| g.children.clone());
                if let Some(children) = kind_children {
                    for c in children.iter().rev() {
                        let cm = tf(c).world(m);
                        stack.push(Step::Node(c.clone(), cm, alpha));
                    }
                    continue;
                }
                stack.push(Step::Emit(r.clone(), m, alpha, scope));
                // A SkinnedMesh's skeleton is its child branch.
                if let Some(skeleton) = crate::deform::skeleton_of(&r) {
                    let sm = tf(&skeleton).world(m);
                    stack.push(Step::Node(skeleton, sm, alpha));
                }
            }
            Step::Emit(r, m, alpha, scope) => {
                if scope & cam_scope != 0 {
                    emit(&r, m, alpha, scope, out)?;
                }
            }
        }
    }
    Ok(())
}

/// The items of one Mesh or Sprite3D.
fn emit(r: &ObjRef, m: Mat4, alpha: f32, scope: i32, out: &mut Vec<Item>) -> Result<()> {
    // MorphingMesh / SkinnedMesh: the deformed copy (recomputed only when needed).
    let deformed = crate::deform::deformed_vertex_buffer(r)?;
    if let Some(mesh) = Mesh::accepts(&r.borrow()).then(|| Mesh(r.clone())) {
        // Only a plain Mesh is culled against the bounds of its positions (a deformed
        // copy's arrays are rewritten in place).
        let cullable = deformed.is_none();
        let d = mesh.d();
        let vb = deformed.as_ref().unwrap_or(&d.vb);
        for (ib, app) in d.ibs.iter().zip(&d.apps) {
            let Some(app) = app else { continue };
            validate(vb, ib)?;
            out.push(Item {
                layer: app.layer(),
                blended: is_blended(app),
                what: What::Submesh(vb.clone(), ib.clone(), app.clone()),
                model: m,
                alpha,
                scope,
                cullable,
            });
        }
    } else if let Some(sprite) = Sprite3D::accepts(&r.borrow()).then(|| Sprite3D(r.clone())) {
        if let Some(app) = sprite.appearance() {
            out.push(Item {
                layer: app.layer(),
                blended: is_blended(&app),
                what: What::Sprite(sprite.clone(), app),
                model: m,
                alpha,
                scope,
                cullable: false,
            });
        }
    }
    Ok(())
}

/// Whether the bounding sphere of `vb`'s positions (from the cached bounding box of the
/// position array, after scale and bias) lies wholly outside one plane of the view
/// frustum. The planes come from the projection's rows, so any camera works; a modelview
/// that is not affine is never culled.
pub(super) fn outside_frustum(vb: &VertexBufferData, modelview: Mat4, projection: Mat4) -> bool {
    let Some(pos) = &vb.positions else {
        return false;
    };
    if modelview.row(3) != Vec4::W {
        return false;
    }
    let [lo, hi] = pos.d().bounds();
    let (lo, hi) = (Vec3::from(lo), Vec3::from(hi));
    let s = vb.pos_scale;
    let center = (lo + hi) * 0.5 * s + Vec3::from(vb.pos_bias);
    let radius = (hi - lo).length() * 0.5 * s.abs();
    let eye = modelview * center.extend(1.0);
    let stretch = (0..3)
        .map(|c| modelview.col(c).truncate().length())
        .fold(0.0f32, f32::max);
    // A margin keeps rounding from culling what touches the frustum.
    let r = radius * stretch * 1.001 + 1e-6;
    if !eye.is_finite() || !r.is_finite() {
        return false;
    }
    let w = projection.row(3);
    (0..3).any(|i| {
        [1.0f32, -1.0].iter().any(|&sign| {
            let plane = w + projection.row(i) * sign;
            let n = plane.truncate().length();
            plane.dot(eye) < -r * n
        })
    })
}
