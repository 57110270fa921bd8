//! The object model: one shared, reference-counted cell per M3G object, typed handles over
//! it, and the `Object3D` and `Transformable` behaviour every class shares.

use std::any::Any;
use std::cell::{Ref, RefCell, RefMut};
use std::collections::{HashMap, HashSet};
use std::rc::{Rc, Weak};

use glam::{Mat4, Quat, Vec3};

use super::appearance::{
    AppearanceData, BackgroundData, CompositingModeData, FogData, MaterialData, PolygonModeData,
    TextureData,
};
use super::camera::CameraData;
use super::error::{iae, ioobe, Result};
use super::image::ImageData;
use super::light::LightData;
use super::mesh::{MeshData, SpriteData};
use super::node::{GroupData, NodeData, WorldData};
use super::transform::{quaternion, rotation, Transform};
use super::vertex::{IndexData, VertexArrayData, VertexBufferData};

/// The shared cell every handle points to.
pub type ObjRef = Rc<RefCell<Inner>>;
pub(crate) type WeakRef = Weak<RefCell<Inner>>;

/// The state of one M3G object: the parts common to every class, the Transformable and Node
/// parts when the class has them, and the class's own data.
#[derive(Clone)]
pub struct Inner {
    pub(crate) user_id: i32,
    pub(crate) user_object: Option<Rc<dyn Any>>,
    /// Attached animation tracks.
    pub(crate) tracks: Vec<Object3D>,
    /// Bumped by every `dm()` of the class data (and by animation writes): lets deformed
    /// meshes tell whether an input changed.
    pub(crate) gen: u64,
    pub(crate) tf: Option<TransformableData>,
    pub(crate) node: Option<NodeData>,
    pub(crate) kind: Kind,
}

/// The class of an object and its own data.
#[derive(Clone)]
pub(crate) enum Kind {
    Group(GroupData),
    World(WorldData),
    Camera(CameraData),
    Light(LightData),
    Mesh(MeshData),
    Sprite(SpriteData),
    Appearance(AppearanceData),
    Background(BackgroundData),
    CompositingMode(CompositingModeData),
    PolygonMode(PolygonModeData),
    Material(MaterialData),
    Fog(FogData),
    Texture2D(TextureData),
    Image2D(ImageData),
    VertexArray(VertexArrayData),
    VertexBuffer(VertexBufferData),
    IndexBuffer(IndexData),
    KeyframeSequence(super::keyframe::KeyframeData),
    AnimationController(super::animation::ControllerData),
    AnimationTrack(super::animation::TrackData),
}

impl Inner {
    pub(crate) fn new(kind: Kind, transformable: bool, node: bool) -> ObjRef {
        Rc::new(RefCell::new(Inner {
            user_id: 0,
            user_object: None,
            tracks: Vec::new(),
            gen: 0,
            tf: (transformable || node).then(TransformableData::default),
            node: node.then(NodeData::default),
            kind,
        }))
    }

    /// The children, for groups and worlds.
    pub(crate) fn group(&self) -> Option<&GroupData> {
        match &self.kind {
            Kind::Group(g) => Some(g),
            Kind::World(w) => Some(&w.group),
            _ => None,
        }
    }

    pub(crate) fn group_mut(&mut self) -> Option<&mut GroupData> {
        match &mut self.kind {
            Kind::Group(g) => Some(g),
            Kind::World(w) => Some(&mut w.group),
            _ => None,
        }
    }

    pub(crate) fn class_name(&self) -> &'static str {
        match &self.kind {
            Kind::Group(_) => "Group",
            Kind::World(_) => "World",
            Kind::Camera(_) => "Camera",
            Kind::Light(_) => "Light",
            Kind::Mesh(m) => m.ext.class_name(),
            Kind::Sprite(_) => "Sprite3D",
            Kind::Appearance(_) => "Appearance",
            Kind::Background(_) => "Background",
            Kind::CompositingMode(_) => "CompositingMode",
            Kind::PolygonMode(_) => "PolygonMode",
            Kind::Material(_) => "Material",
            Kind::Fog(_) => "Fog",
            Kind::Texture2D(_) => "Texture2D",
            Kind::Image2D(_) => "Image2D",
            Kind::VertexArray(_) => "VertexArray",
            Kind::VertexBuffer(_) => "VertexBuffer",
            Kind::IndexBuffer(_) => "TriangleStripArray",
            Kind::KeyframeSequence(_) => "KeyframeSequence",
            Kind::AnimationController(_) => "AnimationController",
            Kind::AnimationTrack(_) => "AnimationTrack",
        }
    }

    /// Every non-null direct reference, in a fixed order, duplicates kept; the parent and
    /// alignment references are not included (Object3D.getReferences).
    pub(crate) fn references(&self) -> Vec<Object3D> {
        let mut out: Vec<Object3D> = self.tracks.clone();
        let mut push = |r: &ObjRef| out.push(Object3D(r.clone()));
        match &self.kind {
            Kind::Group(g) => g.children.iter().for_each(&mut push),
            Kind::World(w) => {
                w.group.children.iter().for_each(&mut push);
                if let Some(b) = &w.background {
                    push(&b.0);
                }
                if let Some(c) = &w.camera {
                    push(&c.0);
                }
            }
            Kind::Mesh(m) => {
                push(&m.vb.0);
                for (ib, app) in m.ibs.iter().zip(&m.apps) {
                    push(&ib.0);
                    if let Some(a) = app {
                        push(&a.0);
                    }
                }
                m.ext.references().iter().for_each(&mut push);
            }
            Kind::AnimationTrack(t) => {
                push(&t.sequence.0);
                if let Some(c) = &t.controller {
                    push(&c.0);
                }
            }
            Kind::Sprite(s) => {
                push(&s.image.0);
                if let Some(a) = &s.appearance {
                    push(&a.0);
                }
            }
            Kind::Appearance(a) => {
                for r in [
                    a.compositing_mode.as_ref().map(|x| &x.0),
                    a.fog.as_ref().map(|x| &x.0),
                    a.polygon_mode.as_ref().map(|x| &x.0),
                    a.material.as_ref().map(|x| &x.0),
                ]
                .into_iter()
                .flatten()
                {
                    push(r);
                }
                a.textures.iter().flatten().for_each(|t| push(&t.0));
            }
            Kind::Background(b) => {
                if let Some(i) = &b.image {
                    push(&i.0);
                }
            }
            Kind::Texture2D(t) => push(&t.image.0),
            Kind::VertexBuffer(v) => {
                for a in [&v.positions, &v.normals, &v.colors].into_iter().flatten() {
                    push(&a.0);
                }
                v.texcoords
                    .iter()
                    .flatten()
                    .for_each(|(a, _, _)| push(&a.0));
            }
            _ => {}
        }
        out
    }
}

/// Access to the shared cell behind a typed handle. Implemented by every handle type; not
/// meant to be implemented outside this crate.
pub trait Handle: Sized + Clone {
    /// The shared cell.
    #[doc(hidden)]
    fn raw(&self) -> &ObjRef;
    /// A handle of this type over `r` (which must be of this class).
    #[doc(hidden)]
    fn from_raw(r: ObjRef) -> Self;
    /// Whether an object of `inner`'s class can be viewed through this handle type.
    #[doc(hidden)]
    fn accepts(inner: &Inner) -> bool;
}

/// Declares a typed handle: a newtype over the shared cell with reference semantics
/// (`Clone` gives the same object, `==` is identity).
macro_rules! handle {
    ($(#[$m:meta])* $Name:ident, |$i:ident| $accepts:expr) => {
        $crate::object::handle!(@core $(#[$m])* $Name, |$i| $accepts);
        impl From<$Name> for $crate::object::Object3D {
            fn from(h: $Name) -> Self {
                $crate::object::Object3D(h.0)
            }
        }
        impl From<&$Name> for $crate::object::Object3D {
            fn from(h: &$Name) -> Self {
                $crate::object::Object3D(h.0.clone())
            }
        }
    };
    (@core $(#[$m:meta])* $Name:ident, |$i:ident| $accepts:expr) => {
        $(#[$m])*
        #[derive(Clone)]
        pub struct $Name(pub(crate) $crate::object::ObjRef);

        impl $crate::object::Handle for $Name {
            fn raw(&self) -> &$crate::object::ObjRef {
                &self.0
            }
            fn from_raw(r: $crate::object::ObjRef) -> Self {
                $Name(r)
            }
            #[allow(unused_variables)]
            fn accepts($i: &$crate::object::Inner) -> bool {
                $accepts
            }
        }

        impl PartialEq for $Name {
            fn eq(&self, o: &Self) -> bool {
                std::rc::Rc::ptr_eq(&self.0, &o.0)
            }
        }
        impl Eq for $Name {}
        impl std::hash::Hash for $Name {
            fn hash<H: std::hash::Hasher>(&self, h: &mut H) {
                std::rc::Rc::as_ptr(&self.0).hash(h)
            }
        }
        impl std::fmt::Debug for $Name {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                $crate::debug::fmt_object(&self.0, f)
            }
        }
    };
}
pub(crate) use handle;

/// Declares the borrow helpers of a class whose data is `Kind::$Variant`.
macro_rules! class_data {
    ($Name:ident, $Variant:ident, $Data:ty) => {
        impl $Name {
            #[allow(dead_code)]
            pub(crate) fn d(&self) -> std::cell::Ref<'_, $Data> {
                std::cell::Ref::map(self.0.borrow(), |i| match &i.kind {
                    $crate::object::Kind::$Variant(d) => d,
                    _ => unreachable!("handle of the wrong class"),
                })
            }
            #[allow(dead_code)]
            pub(crate) fn dm(&self) -> std::cell::RefMut<'_, $Data> {
                std::cell::RefMut::map(self.0.borrow_mut(), |i| {
                    match {
                        i.gen = i.gen.wrapping_add(1);
                        &mut i.kind
                    } {
                        $crate::object::Kind::$Variant(d) => d,
                        _ => unreachable!("handle of the wrong class"),
                    }
                })
            }
        }
    };
}
pub(crate) use class_data;

handle!(
    @core
    /// A reference to an object of any class (`Object3D`). Convert typed handles into it with
    /// `From`, and back with [`Object3D::downcast`].
    Object3D,
    |i| true
);

impl Object3D {
    /// The object viewed as class `T` (a Java cast), or `None` if it is not one.
    /// `World` objects can be viewed as `Group`, every node as `Node`.
    pub fn downcast<T: Handle>(&self) -> Option<T> {
        T::accepts(&self.0.borrow()).then(|| T::from_raw(self.0.clone()))
    }

    /// The class name, e.g. `"Mesh"` (a Rust extension for diagnostics).
    pub fn class_name(&self) -> &'static str {
        self.0.borrow().class_name()
    }
}

fn ptr(r: &ObjRef) -> *const RefCell<Inner> {
    Rc::as_ptr(r)
}

/// Visits `root` and every object reachable from it through references (not through parent
/// or alignment links), each once.
pub(crate) fn for_each_reachable(root: &ObjRef, f: &mut dyn FnMut(&ObjRef) -> bool) {
    let mut seen = HashSet::new();
    let mut stack = vec![root.clone()];
    while let Some(r) = stack.pop() {
        if !seen.insert(ptr(&r)) {
            continue;
        }
        if !f(&r) {
            return;
        }
        let refs = r.borrow().references();
        stack.extend(refs.into_iter().rev().map(|o| o.0));
    }
}

/// The methods of `Object3D`, available on every handle.
///
/// | Java | Rust |
/// |---|---|
/// | `getUserID` / `setUserID` | [`user_id`](Self::user_id) / [`set_user_id`](Self::set_user_id) |
/// | `getUserObject` / `setUserObject` | [`user_object`](Self::user_object) / [`set_user_object`](Self::set_user_object) |
/// | `find(int)` | [`find`](Self::find) |
/// | `getReferences(Object3D[])` | [`get_references`](Self::get_references) (returns them all) |
/// | `duplicate()` | [`duplicate`](Self::duplicate) |
/// | `animate(int)` | [`animate`](Self::animate) |
/// | `addAnimationTrack` / `removeAnimationTrack` | [`add_animation_track`](Self::add_animation_track) / [`remove_animation_track`](Self::remove_animation_track) |
/// | `getAnimationTrackCount` / `getAnimationTrack` | [`animation_track_count`](Self::animation_track_count) / [`animation_track`](Self::animation_track) |
pub trait Object3DExt: Handle {
    /// `getUserID()`.
    fn user_id(&self) -> i32 {
        self.raw().borrow().user_id
    }
    /// `setUserID(id)`.
    fn set_user_id(&self, id: i32) {
        self.raw().borrow_mut().user_id = id;
    }
    /// `getUserObject()`: the object given to [`set_user_object`](Self::set_user_object).
    fn user_object(&self) -> Option<Rc<dyn Any>> {
        self.raw().borrow().user_object.clone()
    }
    /// `setUserObject(o)`: held by reference, never looked at by the implementation.
    fn set_user_object(&self, o: Option<Rc<dyn Any>>) {
        self.raw().borrow_mut().user_object = o;
    }
    /// `find(userID)`: this object or any object reachable from it with that user ID.
    fn find(&self, user_id: i32) -> Option<Object3D> {
        let mut found = None;
        for_each_reachable(self.raw(), &mut |r| {
            if r.borrow().user_id == user_id {
                found = Some(Object3D(r.clone()));
                false
            } else {
                true
            }
        });
        found
    }
    /// `getReferences(Object3D[])`: every non-null direct reference (duplicates kept), not
    /// the parent nor alignment references. The Java call's count is the length.
    fn get_references(&self) -> Vec<Object3D> {
        self.raw().borrow().references()
    }
    /// `duplicate()`: a new object of the same class. Non-nodes are copied shallowly (same
    /// referenced objects); a node is copied with all its descendants, without a parent, and
    /// references among the copied nodes (alignment, a World's camera) point to the copies.
    fn duplicate(&self) -> Self {
        Self::from_raw(duplicate_raw(self.raw()))
    }
    /// `animate(worldTime)`: applies the animation tracks of this object and of everything
    /// reachable from it (blended per property: Σ weight·value, orientation normalized after
    /// the sum) and returns the validity interval: how long from `world_time` no animated
    /// value will change (conservative; `0x7FFFFFFF` when nothing will). IllegalState if an
    /// active track's KeyframeSequence is invalid.
    fn animate(&self, world_time: i32) -> Result<i32> {
        super::animation::animate(self.raw(), world_time)
    }
    /// `addAnimationTrack(track)`: IllegalArgument if the track's property does not apply to
    /// this class, the track is already attached, or another attached track animates the
    /// same property with a different component count.
    fn add_animation_track(&self, track: &super::animation::AnimationTrack) -> Result<()> {
        super::animation::add_track(self.raw(), track)
    }
    /// `removeAnimationTrack(track)`: `None` or a track not attached is ignored.
    fn remove_animation_track(&self, track: Option<&super::animation::AnimationTrack>) {
        super::animation::remove_track(self.raw(), track)
    }
    /// `getAnimationTrackCount()`.
    fn animation_track_count(&self) -> usize {
        self.raw().borrow().tracks.len()
    }
    /// `getAnimationTrack(i)`: IndexOutOfBounds unless `i < animation_track_count()`.
    fn animation_track(&self, i: usize) -> Result<super::animation::AnimationTrack> {
        match self.raw().borrow().tracks.get(i) {
            Some(t) => Ok(super::animation::AnimationTrack(t.0.clone())),
            None => ioobe("animation track index"),
        }
    }
    /// This object as a plain [`Object3D`] reference.
    fn as_object3d(&self) -> Object3D {
        Object3D(self.raw().clone())
    }
}

impl<T: Handle> Object3DExt for T {}

fn duplicate_raw(r: &ObjRef) -> ObjRef {
    if r.borrow().node.is_none() {
        return Rc::new(RefCell::new(r.borrow().clone()));
    }
    let mut map: HashMap<*const RefCell<Inner>, ObjRef> = HashMap::new();
    let copy = duplicate_node(r, None, &mut map);
    // Remap node references that point into the copied set.
    let remap = |w: &WeakRef| -> WeakRef {
        match map.get(&w.as_ptr()) {
            Some(n) => Rc::downgrade(n),
            None => w.clone(),
        }
    };
    for n in map.values() {
        let mut i = n.borrow_mut();
        if let Some(nd) = i.node.as_mut() {
            for a in nd.alignment.iter_mut() {
                if let Some(w) = &a.1 {
                    a.1 = Some(remap(w));
                }
            }
        }
        super::skinned_mesh::remap_bones(&mut i, &map);
        if let Kind::World(w) = &mut i.kind {
            if let Some(c) = &w.camera {
                if let Some(n) = map.get(&ptr(&c.0)) {
                    w.camera = Some(super::camera::Camera(n.clone()));
                }
            }
        }
    }
    copy
}

/// Copies `r` (a node) and everything below it: children and a SkinnedMesh's skeleton,
/// each copy parented to the copy of its parent. Iterative, because a loaded file can nest
/// groups deeper than the thread's stack allows recursion.
fn duplicate_node(
    r: &ObjRef,
    parent: Option<&ObjRef>,
    map: &mut HashMap<*const RefCell<Inner>, ObjRef>,
) -> ObjRef {
    let mut copy_one = |o: &ObjRef, parent: Option<&ObjRef>| {
        let mut inner = o.borrow().clone();
        if let Some(n) = inner.node.as_mut() {
            n.parent = parent.map(Rc::downgrade);
        }
        let c = Rc::new(RefCell::new(inner));
        map.insert(ptr(o), c.clone());
        c
    };
    let root = copy_one(r, parent);
    // Each copy on the stack still refers to the original children and skeleton (a shallow
    // clone); they are replaced by their copies when it is popped.
    let mut stack = vec![root.clone()];
    while let Some(c) = stack.pop() {
        let originals = c
            .borrow_mut()
            .group_mut()
            .map(|g| std::mem::take(&mut g.children))
            .unwrap_or_default();
        let copies: Vec<ObjRef> = originals.iter().map(|o| copy_one(o, Some(&c))).collect();
        if let Some(g) = c.borrow_mut().group_mut() {
            g.children = copies.clone();
        }
        stack.extend(copies.into_iter().rev());
        super::skinned_mesh::duplicate_skeleton(&c, &mut |s| {
            let n = copy_one(s, Some(&c));
            stack.push(n.clone());
            n
        });
    }
    root
}

impl Drop for Inner {
    /// Dropping the last reference to the top of a deep Group chain would otherwise drop
    /// each level inside the previous level's drop and overflow the stack: the children
    /// (and a SkinnedMesh's skeleton's children) that nothing else holds are taken out and
    /// dropped one by one from a heap stack instead.
    fn drop(&mut self) {
        let mut stack = self.take_owned_subtrees();
        while let Some(r) = stack.pop() {
            if let Ok(cell) = Rc::try_unwrap(r) {
                let mut inner = cell.into_inner();
                stack.extend(inner.take_owned_subtrees());
            }
        }
    }
}

impl Inner {
    fn take_owned_subtrees(&mut self) -> Vec<ObjRef> {
        if let Some(g) = self.group_mut() {
            return std::mem::take(&mut g.children);
        }
        if let Kind::Mesh(m) = &mut self.kind {
            if let super::deform::MeshExt::Skinned(s) = &mut m.ext {
                // Only a skeleton this mesh alone holds may be emptied: another holder still
                // sees it.
                if Rc::strong_count(&s.skeleton.0) == 1 {
                    if let Some(g) = s.skeleton.0.borrow_mut().group_mut() {
                        return std::mem::take(&mut g.children);
                    }
                }
            }
        }
        Vec::new()
    }
}

/// The Transformable part: translation T, orientation R, scale S and general matrix M.
///
/// Write the fields only through [`tf_mut`]: it sets the dirty flags of the cached
/// composite and world transforms ([`TfCache`]).
#[derive(Clone, Debug)]
pub(crate) struct TransformableData {
    pub translation: Vec3,
    pub scale: Vec3,
    pub orientation: Quat,
    pub matrix: Mat4,
    pub cache: TfCache,
}

/// The cached transforms of a Transformable, `None` while dirty: the composite T·R·S·M and,
/// for a node, its node-to-world transform with the parent's node-to-world transform it was
/// computed from (so a new parent or a moved ancestor shows up as a different parent
/// transform and recomputes it).
#[derive(Clone, Debug, Default)]
pub(crate) struct TfCache {
    composite: std::cell::Cell<Option<Mat4>>,
    world: std::cell::Cell<Option<(Mat4, Mat4)>>,
}

impl TfCache {
    /// Marks both transforms dirty.
    pub fn invalidate(&self) {
        self.composite.set(None);
        self.world.set(None);
    }
}

impl Default for TransformableData {
    fn default() -> Self {
        TransformableData {
            translation: Vec3::ZERO,
            scale: Vec3::ONE,
            orientation: Quat::IDENTITY,
            matrix: Mat4::IDENTITY,
            cache: TfCache::default(),
        }
    }
}

impl TransformableData {
    /// C = T · R · S · M (cached until the next [`tf_mut`]).
    pub fn composite(&self) -> Mat4 {
        if let Some(m) = self.cache.composite.get() {
            return m;
        }
        let m = Mat4::from_translation(self.translation)
            * Mat4::from_quat(self.orientation)
            * Mat4::from_scale(self.scale)
            * self.matrix;
        self.cache.composite.set(Some(m));
        m
    }

    /// `parent · C`: the node-to-world transform of a node whose parent's is `parent`,
    /// cached until the next [`tf_mut`] or a different `parent`.
    pub fn world(&self, parent: Mat4) -> Mat4 {
        if let Some((p, w)) = self.cache.world.get() {
            if p == parent {
                return w;
            }
        }
        let w = parent * self.composite();
        self.cache.world.set(Some((parent, w)));
        w
    }
}

pub(crate) fn tf(r: &ObjRef) -> Ref<'_, TransformableData> {
    Ref::map(r.borrow(), |i| i.tf.as_ref().expect("a Transformable"))
}
/// The Transformable part for writing; marks its cached transforms dirty.
pub(crate) fn tf_mut(r: &ObjRef) -> RefMut<'_, TransformableData> {
    RefMut::map(r.borrow_mut(), |i| {
        let t = i.tf.as_mut().expect("a Transformable");
        t.cache.invalidate();
        t
    })
}

/// The methods of `Transformable` (nodes and [`Texture2D`](super::Texture2D)).
///
/// | Java | Rust |
/// |---|---|
/// | `setOrientation` / `getOrientation(float[4])` | [`set_orientation`](Self::set_orientation) / [`get_orientation`](Self::get_orientation) |
/// | `preRotate` / `postRotate` | [`pre_rotate`](Self::pre_rotate) / [`post_rotate`](Self::post_rotate) |
/// | `setScale` / `scale` / `getScale` | [`set_scale`](Self::set_scale) / [`scale`](Self::scale) / [`get_scale`](Self::get_scale) |
/// | `setTranslation` / `translate` / `getTranslation` | [`set_translation`](Self::set_translation) / [`translate`](Self::translate) / [`get_translation`](Self::get_translation) |
/// | `setTransform` / `getTransform` | [`set_transform`](Self::set_transform) / [`get_transform`](Self::get_transform) |
/// | `getCompositeTransform` | [`get_composite_transform`](Self::get_composite_transform) |
pub trait TransformableExt: Handle {
    /// `setOrientation(angle, ax, ay, az)`: angle in degrees, any non-zero axis.
    /// IllegalArgument for a zero axis with a non-zero angle.
    fn set_orientation(&self, angle: f32, ax: f32, ay: f32, az: f32) -> Result<()> {
        let q = Quat::from_mat4(&rotation(angle, ax, ay, az)?).normalize();
        tf_mut(self.raw()).orientation = q;
        Ok(())
    }
    /// `setOrientation` from a quaternion (x, y, z, w), normalized here: the quaternion form
    /// Java reaches through `Transform.postRotateQuat`. IllegalArgument for the zero quaternion.
    fn set_orientation_quat(&self, x: f32, y: f32, z: f32, w: f32) -> Result<()> {
        tf_mut(self.raw()).orientation = quaternion(x, y, z, w)?;
        Ok(())
    }
    /// `preRotate(angle, ax, ay, az)`: R' = rotation · R.
    fn pre_rotate(&self, angle: f32, ax: f32, ay: f32, az: f32) -> Result<()> {
        let q = Quat::from_mat4(&rotation(angle, ax, ay, az)?);
        let mut t = tf_mut(self.raw());
        t.orientation = (q * t.orientation).normalize();
        Ok(())
    }
    /// `postRotate(angle, ax, ay, az)`: R' = R · rotation.
    fn post_rotate(&self, angle: f32, ax: f32, ay: f32, az: f32) -> Result<()> {
        let q = Quat::from_mat4(&rotation(angle, ax, ay, az)?);
        let mut t = tf_mut(self.raw());
        t.orientation = (t.orientation * q).normalize();
        Ok(())
    }
    /// `getOrientation(float[4])`: (angle in degrees, ax, ay, az), angle in [0, 180]. An
    /// angle of 0 comes with the axis (0, 0, 1) (any axis is equivalent then).
    fn get_orientation(&self) -> [f32; 4] {
        let q = tf(self.raw()).orientation;
        // q and −q are the same rotation: report the one with angle ≤ 180°.
        let q = if q.w < 0.0 { -q } else { q };
        let (axis, angle) = q.to_axis_angle();
        if angle == 0.0 || !axis.is_finite() {
            return [0.0, 0.0, 0.0, 1.0];
        }
        [angle.to_degrees(), axis.x, axis.y, axis.z]
    }
    /// The orientation as a unit quaternion (x, y, z, w) (a Rust extension).
    fn get_orientation_quat(&self) -> [f32; 4] {
        tf(self.raw()).orientation.to_array()
    }
    /// `setScale(sx, sy, sz)`.
    fn set_scale(&self, sx: f32, sy: f32, sz: f32) {
        tf_mut(self.raw()).scale = Vec3::new(sx, sy, sz);
    }
    /// `scale(sx, sy, sz)`: multiplies the scale component-wise.
    fn scale(&self, sx: f32, sy: f32, sz: f32) {
        tf_mut(self.raw()).scale *= Vec3::new(sx, sy, sz);
    }
    /// `getScale(float[3])`.
    fn get_scale(&self) -> [f32; 3] {
        tf(self.raw()).scale.to_array()
    }
    /// `setTranslation(tx, ty, tz)`.
    fn set_translation(&self, tx: f32, ty: f32, tz: f32) {
        tf_mut(self.raw()).translation = Vec3::new(tx, ty, tz);
    }
    /// `translate(tx, ty, tz)`: adds to the translation.
    fn translate(&self, tx: f32, ty: f32, tz: f32) {
        tf_mut(self.raw()).translation += Vec3::new(tx, ty, tz);
    }
    /// `getTranslation(float[3])`.
    fn get_translation(&self) -> [f32; 3] {
        tf(self.raw()).translation.to_array()
    }
    /// `setTransform(T)`: sets M (`None` = identity); T, R and S are untouched.
    /// IllegalArgument if this is a Node and the bottom row is not (0, 0, 0, 1).
    fn set_transform(&self, t: Option<&Transform>) -> Result<()> {
        let m = t.map_or(Mat4::IDENTITY, |t| t.m);
        if self.raw().borrow().node.is_some() && m.row(3) != glam::Vec4::new(0.0, 0.0, 0.0, 1.0) {
            return iae("a node's transform must have the bottom row (0, 0, 0, 1)");
        }
        tf_mut(self.raw()).matrix = m;
        Ok(())
    }
    /// `getTransform(T)`: M only.
    fn get_transform(&self) -> Transform {
        Transform::from_mat4(tf(self.raw()).matrix)
    }
    /// `getCompositeTransform(T)`: T · R · S · M.
    fn get_composite_transform(&self) -> Transform {
        Transform::from_mat4(tf(self.raw()).composite())
    }
}
