//! `Node`, `Group` and `World`: the scene graph.

use std::rc::Rc;

use glam::{Mat4, Quat, Vec3, Vec4};

use super::appearance::Background;
use super::camera::Camera;
use super::error::{iae, ioobe, ise, Result};
use super::modes::AlignTarget;
use super::object::{class_data, handle, tf, Handle, Inner, Kind, ObjRef, WeakRef};
use super::pick::{self, RayIntersection};
use super::transform::{invert, Transform};

/// The Node part of an object.
#[derive(Clone, Debug)]
pub(crate) struct NodeData {
    pub parent: Option<WeakRef>,
    pub rendering: bool,
    pub picking: bool,
    pub alpha: f32,
    pub scope: i32,
    /// (target, reference) for the Z axis, then the Y axis.
    pub alignment: [(AlignTarget, Option<WeakRef>); 2],
}

impl Default for NodeData {
    fn default() -> Self {
        NodeData {
            parent: None,
            rendering: true,
            picking: true,
            alpha: 1.0,
            scope: -1,
            alignment: [(AlignTarget::None, None), (AlignTarget::None, None)],
        }
    }
}

pub(crate) fn node_data(r: &ObjRef) -> std::cell::Ref<'_, NodeData> {
    std::cell::Ref::map(r.borrow(), |i| i.node.as_ref().expect("a Node"))
}

pub(crate) fn parent_of(r: &ObjRef) -> Option<ObjRef> {
    r.borrow()
        .node
        .as_ref()
        .and_then(|n| n.parent.as_ref())
        .and_then(|w| w.upgrade())
}

/// `r` and its ancestors, nearest first.
pub(crate) fn ancestors(r: &ObjRef) -> Vec<ObjRef> {
    let mut v = vec![r.clone()];
    while let Some(p) = parent_of(v.last().unwrap()) {
        v.push(p);
    }
    v
}

/// The node's own transform (composite T R S M).
pub(crate) fn local(r: &ObjRef) -> Mat4 {
    tf(r).composite()
}

/// The transform from `r`'s coordinates to those of its ancestor `anc` (identity if equal).
pub(crate) fn to_ancestor(r: &ObjRef, anc: &ObjRef) -> Mat4 {
    let mut m = Mat4::IDENTITY;
    let mut cur = r.clone();
    while !Rc::ptr_eq(&cur, anc) {
        m = local(&cur) * m;
        match parent_of(&cur) {
            Some(p) => cur = p,
            None => break,
        }
    }
    m
}

/// The transform from `from`'s coordinates to `to`'s, `None` when they are in different
/// scene graphs, Arithmetic when an inverse needed is singular.
pub(crate) fn transform_between(from: &ObjRef, to: &ObjRef) -> Result<Option<Mat4>> {
    let a = ancestors(from);
    let b = ancestors(to);
    let Some(common) = a.iter().find(|x| b.iter().any(|y| Rc::ptr_eq(x, y))) else {
        return Ok(None);
    };
    let up = to_ancestor(from, common);
    let down = to_ancestor(to, common);
    Ok(Some(invert(&down)? * up))
}

pub(crate) fn is_descendant_or_self(r: &ObjRef, anc: &ObjRef) -> bool {
    ancestors(r).iter().any(|x| Rc::ptr_eq(x, anc))
}

pub(crate) fn root_of(r: &ObjRef) -> ObjRef {
    ancestors(r).pop().unwrap()
}

handle!(
    /// A reference to a node of any class (`Node`): Camera, Light, Group, World, Mesh or
    /// Sprite3D. Get one with `as_node()`; view it as its class with `downcast`.
    Node,
    |i| i.node.is_some()
);

impl Node {
    /// This node viewed as class `T`, or `None` if it is not one.
    pub fn downcast<T: Handle>(&self) -> Option<T> {
        T::accepts(&self.0.borrow()).then(|| T::from_raw(self.0.clone()))
    }
}

impl super::object::TransformableExt for Node {}
impl NodeExt for Node {}

/// The methods of `Node`, available on every node handle.
///
/// | Java | Rust |
/// |---|---|
/// | `setRenderingEnable` / `isRenderingEnabled` | [`set_rendering_enable`](Self::set_rendering_enable) / [`is_rendering_enabled`](Self::is_rendering_enabled) |
/// | `setPickingEnable` / `isPickingEnabled` | [`set_picking_enable`](Self::set_picking_enable) / [`is_picking_enabled`](Self::is_picking_enabled) |
/// | `setScope` / `getScope` | [`set_scope`](Self::set_scope) / [`scope`](Self::scope) |
/// | `setAlphaFactor` / `getAlphaFactor` | [`set_alpha_factor`](Self::set_alpha_factor) / [`alpha_factor`](Self::alpha_factor) |
/// | `getParent` | [`parent`](Self::parent) |
/// | `getTransformTo(Node, Transform)` | [`get_transform_to`](Self::get_transform_to) |
/// | `setAlignment` | [`set_alignment`](Self::set_alignment) |
/// | `getAlignmentTarget` / `getAlignmentReference` | [`alignment_target`](Self::alignment_target) / [`alignment_reference`](Self::alignment_reference) |
/// | `align(Node)` | [`align`](Self::align) |
pub trait NodeExt: Handle {
    /// This node as a plain [`Node`] reference.
    fn as_node(&self) -> Node {
        Node(self.raw().clone())
    }
    /// `setRenderingEnable(b)`.
    fn set_rendering_enable(&self, enable: bool) {
        self.raw().borrow_mut().node.as_mut().unwrap().rendering = enable;
    }
    /// `isRenderingEnabled()`: the local flag (the effective one is the AND over ancestors).
    fn is_rendering_enabled(&self) -> bool {
        node_data(self.raw()).rendering
    }
    /// `setPickingEnable(b)`.
    fn set_picking_enable(&self, enable: bool) {
        self.raw().borrow_mut().node.as_mut().unwrap().picking = enable;
    }
    /// `isPickingEnabled()`: the local flag.
    fn is_picking_enabled(&self) -> bool {
        node_data(self.raw()).picking
    }
    /// `setScope(mask)`.
    fn set_scope(&self, scope: i32) {
        self.raw().borrow_mut().node.as_mut().unwrap().scope = scope;
    }
    /// `getScope()`.
    fn scope(&self) -> i32 {
        node_data(self.raw()).scope
    }
    /// `setAlphaFactor(a)`: IllegalArgument unless 0 ≤ a ≤ 1.
    fn set_alpha_factor(&self, alpha: f32) -> Result<()> {
        if !(0.0..=1.0).contains(&alpha) {
            return iae("alpha factor must be in [0, 1]");
        }
        self.raw().borrow_mut().node.as_mut().unwrap().alpha = alpha;
        Ok(())
    }
    /// `getAlphaFactor()`: the local value.
    fn alpha_factor(&self) -> f32 {
        node_data(self.raw()).alpha
    }
    /// `getParent()`.
    fn parent(&self) -> Option<Node> {
        parent_of(self.raw()).map(Node)
    }
    /// `getTransformTo(target, T)`: the transform from this node's coordinates to `target`'s,
    /// or `None` when there is no path (different scene graphs). Arithmetic when an inverse
    /// the path needs is singular.
    fn get_transform_to<N: NodeExt>(&self, target: &N) -> Result<Option<Transform>> {
        Ok(transform_between(self.raw(), target.raw())?.map(Transform::from_mat4))
    }
    /// `setAlignment(zRef, zTarget, yRef, yTarget)`. A `None` reference means the node
    /// `align` is called with. IllegalArgument for both references and targets equal (and
    /// not [`AlignTarget::None`]), or for a reference that is this node.
    fn set_alignment(
        &self,
        z_ref: Option<&Node>,
        z_target: AlignTarget,
        y_ref: Option<&Node>,
        y_target: AlignTarget,
    ) -> Result<()> {
        if z_target == y_target && z_target != AlignTarget::None && z_ref == y_ref {
            return iae("Z and Y alignment are the same");
        }
        for r in [z_ref, y_ref].into_iter().flatten() {
            if Rc::ptr_eq(&r.0, self.raw()) {
                return iae("a node cannot be aligned to itself");
            }
        }
        let mut i = self.raw().borrow_mut();
        let n = i.node.as_mut().unwrap();
        n.alignment = [
            (z_target, z_ref.map(|r| Rc::downgrade(&r.0))),
            (y_target, y_ref.map(|r| Rc::downgrade(&r.0))),
        ];
        Ok(())
    }
    /// `getAlignmentTarget(axis)`: IllegalArgument unless `axis` is
    /// [`AlignTarget::YAxis`] or [`AlignTarget::ZAxis`].
    fn alignment_target(&self, axis: AlignTarget) -> Result<AlignTarget> {
        let k = axis_slot(axis)?;
        Ok(node_data(self.raw()).alignment[k].0)
    }
    /// `getAlignmentReference(axis)`: IllegalArgument unless `axis` is
    /// [`AlignTarget::YAxis`] or [`AlignTarget::ZAxis`].
    fn alignment_reference(&self, axis: AlignTarget) -> Result<Option<Node>> {
        let k = axis_slot(axis)?;
        Ok(node_data(self.raw()).alignment[k]
            .1
            .as_ref()
            .and_then(|w| w.upgrade())
            .map(Node))
    }
    /// `align(ref)`: computes the alignment of this node and its descendants (§ Node).
    /// IllegalArgument if `reference` is in another scene graph; IllegalState if a node is
    /// aligned to itself, a descendant or a node of another graph; Arithmetic when a needed
    /// inverse is singular.
    fn align(&self, reference: Option<&Node>) -> Result<()> {
        if let Some(r) = reference {
            if !Rc::ptr_eq(&root_of(&r.0), &root_of(self.raw())) {
                return iae("the reference is in another scene graph");
            }
        }
        let common = reference.map_or_else(|| self.raw().clone(), |r| r.0.clone());
        let mut stack = vec![self.raw().clone()];
        while let Some(n) = stack.pop() {
            align_one(&n, &common)?;
            if let Some(g) = n.borrow().group() {
                stack.extend(g.children.iter().cloned());
            }
        }
        Ok(())
    }
}

fn axis_slot(axis: AlignTarget) -> Result<usize> {
    match axis {
        AlignTarget::ZAxis => Ok(0),
        AlignTarget::YAxis => Ok(1),
        _ => iae("axis must be Y_AXIS or Z_AXIS"),
    }
}

/// The target vector of one alignment axis in the frame of `n`'s translation, or `None`.
fn align_target(n: &ObjRef, slot: usize, common: &ObjRef) -> Result<Option<Vec3>> {
    let (target, r) = node_data(n).alignment[slot].clone();
    if target == AlignTarget::None {
        return Ok(None);
    }
    let r = match r {
        Some(w) => match w.upgrade() {
            Some(r) => r,
            None => return ise("the alignment reference no longer exists"),
        },
        None => common.clone(),
    };
    if !Rc::ptr_eq(&root_of(&r), &root_of(n)) {
        return ise("the alignment reference is in another scene graph");
    }
    if is_descendant_or_self(&r, n) {
        return ise("a node cannot be aligned to itself or a descendant");
    }
    let parent = parent_of(n).expect("a node with a reference outside it has a parent");
    let to_parent = transform_between(&r, &parent)?.expect("same graph");
    let t = tf(n).translation;
    let m = Mat4::from_translation(-t) * to_parent;
    let v = match target {
        AlignTarget::Origin => m * Vec4::new(0.0, 0.0, 0.0, 1.0),
        AlignTarget::XAxis => m * Vec4::X,
        AlignTarget::YAxis => m * Vec4::Y,
        _ => m * Vec4::Z,
    };
    Ok(Some(v.truncate()))
}

/// The shortest rotation taking `from` to `to` (both unit); antiparallel vectors rotate by
/// π about a fixed perpendicular axis (deterministic).
fn arc(from: Vec3, to: Vec3) -> Quat {
    let to = to.normalize_or_zero();
    if to == Vec3::ZERO {
        return Quat::IDENTITY;
    }
    Quat::from_rotation_arc(from, to)
}

fn align_one(n: &ObjRef, common: &ObjRef) -> Result<()> {
    let z = align_target(n, 0, common)?;
    let y = align_target(n, 1, common)?;
    let q = match (z, y) {
        (None, None) => return Ok(()),
        (None, Some(ty)) => arc(Vec3::Y, ty),
        (Some(tz), ty) => {
            let rz = arc(Vec3::Z, tz);
            match ty {
                None => rz,
                Some(ty) => {
                    let p = rz.inverse() * ty;
                    if p.x == 0.0 && p.y == 0.0 {
                        rz
                    } else {
                        rz * Quat::from_rotation_z((-p.x).atan2(p.y))
                    }
                }
            }
        }
    };
    super::object::tf_mut(n).orientation = q.normalize();
    Ok(())
}

/// The children list of groups and worlds.
#[derive(Clone, Default)]
pub(crate) struct GroupData {
    pub children: Vec<ObjRef>,
}

handle!(
    /// `Group`: a node with child nodes. A [`World`] can be viewed as a Group.
    Group,
    |i| matches!(i.kind, Kind::Group(_) | Kind::World(_))
);

impl Group {
    /// `Group()`: no children.
    pub fn new() -> Group {
        Group(Inner::new(Kind::Group(GroupData::default()), true, true))
    }
}

impl Default for Group {
    fn default() -> Self {
        Group::new()
    }
}

impl super::object::TransformableExt for Group {}
impl NodeExt for Group {}
impl GroupExt for Group {}

/// The methods of `Group` (on [`Group`] and [`World`]).
///
/// | Java | Rust |
/// |---|---|
/// | `addChild` / `removeChild` | [`add_child`](Self::add_child) / [`remove_child`](Self::remove_child) |
/// | `getChildCount` / `getChild` | [`child_count`](Self::child_count) / [`child`](Self::child) |
/// | `pick(scope, ox, oy, oz, dx, dy, dz, ri)` | [`pick_ray`](Self::pick_ray) |
/// | `pick(scope, x, y, camera, ri)` | [`pick`](Self::pick) |
pub trait GroupExt: NodeExt {
    /// `addChild(node)`. IllegalArgument if `node` is this group, a World, has another parent,
    /// or is an ancestor of this group. Adding a child of this group again does nothing.
    fn add_child<N: NodeExt>(&self, node: &N) -> Result<()> {
        let n = node.raw();
        if Rc::ptr_eq(n, self.raw()) {
            return iae("a group cannot be its own child");
        }
        if matches!(n.borrow().kind, Kind::World(_)) {
            return iae("a World cannot be a child");
        }
        if let Some(p) = parent_of(n) {
            if Rc::ptr_eq(&p, self.raw()) {
                return Ok(());
            }
            return iae("the node already has a parent");
        }
        if is_descendant_or_self(self.raw(), n) {
            return iae("the node is an ancestor of this group");
        }
        n.borrow_mut().node.as_mut().unwrap().parent = Some(Rc::downgrade(self.raw()));
        self.raw()
            .borrow_mut()
            .group_mut()
            .unwrap()
            .children
            .push(n.clone());
        Ok(())
    }
    /// `removeChild(node)`: a node that is not a child is ignored.
    fn remove_child<N: NodeExt>(&self, node: &N) {
        let n = node.raw();
        let mut i = self.raw().borrow_mut();
        let g = i.group_mut().unwrap();
        if let Some(k) = g.children.iter().position(|c| Rc::ptr_eq(c, n)) {
            g.children.remove(k);
            drop(i);
            n.borrow_mut().node.as_mut().unwrap().parent = None;
        }
    }
    /// `getChildCount()`.
    fn child_count(&self) -> usize {
        self.raw().borrow().group().unwrap().children.len()
    }
    /// `getChild(i)`: IndexOutOfBounds unless `i < child_count()`.
    fn child(&self, i: usize) -> Result<Node> {
        match self.raw().borrow().group().unwrap().children.get(i) {
            Some(c) => Ok(Node(c.clone())),
            None => ioobe("child index"),
        }
    }
    /// `pick(scope, ox, oy, oz, dx, dy, dz, ri)`: the nearest mesh hit by the ray from o
    /// along d (this group's coordinates), or `None`. IllegalArgument if d is zero;
    /// IllegalState for invalid mesh data.
    fn pick_ray(
        &self,
        scope: i32,
        origin: [f32; 3],
        direction: [f32; 3],
    ) -> Result<Option<RayIntersection>> {
        pick::pick_ray(self.raw(), scope, origin, direction)
    }
    /// `pick(scope, x, y, camera, ri)`: the nearest mesh or scaled sprite under the viewport
    /// point (x, y) ((0, 0) top-left, (1, 1) bottom-right) seen through `camera`, or `None`.
    /// IllegalState if the camera is not in this group's scene graph.
    fn pick(&self, scope: i32, x: f32, y: f32, camera: &Camera) -> Result<Option<RayIntersection>> {
        pick::pick_camera(self.raw(), scope, x, y, camera)
    }
}

/// The World part: the root's camera and background.
#[derive(Clone, Default)]
pub(crate) struct WorldData {
    pub group: GroupData,
    pub camera: Option<Camera>,
    pub background: Option<Background>,
}

handle!(
    /// `World`: the root of a scene graph, with an active camera and a background.
    World,
    |i| matches!(i.kind, Kind::World(_))
);
class_data!(World, World, WorldData);

impl World {
    /// `World()`: no children, no camera, no background.
    ///
    /// ```
    /// use m3g::prelude::*;
    ///
    /// # fn main() -> m3g::Result<()> {
    /// let world = World::new();
    /// let camera = Camera::new();
    /// world.add_child(&camera)?;
    /// world.set_active_camera(&camera);
    /// let sky = Background::new();
    /// sky.set_color(Color::rgb(40, 60, 90));
    /// world.set_background(Some(&sky));
    /// let group = Group::new(); // children are positioned relative to their parent
    /// group.set_translation(0.0, 0.0, -5.0);
    /// world.add_child(&group)?;
    /// assert_eq!(world.child_count(), 2);
    /// assert_eq!(group.parent(), Some(world.as_node()));
    /// # Ok(())
    /// # }
    /// ```
    pub fn new() -> World {
        World(Inner::new(Kind::World(WorldData::default()), true, true))
    }
    /// `setActiveCamera(camera)`.
    pub fn set_active_camera(&self, camera: &Camera) {
        self.dm().camera = Some(camera.clone());
    }
    /// `getActiveCamera()`.
    pub fn active_camera(&self) -> Option<Camera> {
        self.d().camera.clone()
    }
    /// `setBackground(bg)`: `None` clears to transparent black.
    pub fn set_background(&self, background: Option<&Background>) {
        self.dm().background = background.cloned();
    }
    /// `getBackground()`.
    pub fn background(&self) -> Option<Background> {
        self.d().background.clone()
    }
    /// This World as a [`Group`] reference.
    pub fn as_group(&self) -> Group {
        Group(self.0.clone())
    }
}

impl Default for World {
    fn default() -> Self {
        World::new()
    }
}

impl super::object::TransformableExt for World {}
impl NodeExt for World {}
impl GroupExt for World {}
