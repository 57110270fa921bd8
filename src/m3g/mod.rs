//! M3G 1.1 (JSR-184) in Rust: the scene graph and immediate-mode API, rendering through the
//! crate's own rasterizer (`crate::core`), not through the `gl*` functions.
//!
//! # Handles
//!
//! Every M3G object lives in one `Rc<RefCell<…>>` cell; the types here ([`Mesh`],
//! [`Group`], [`Appearance`], …) are typed handles over it that behave like Java
//! references: `clone()` gives another reference to the **same** object, `==` is identity,
//! and an object lives as long as something refers to it. `Rc` rather than an arena
//! because M3G objects are shared freely between scene graphs and outlive any one owner
//! (an Image2D used by a texture, a background and a render target), which is exactly
//! reference counting; the parent link and alignment references are `Weak`, so the graph
//! has no strong cycles and a node has at most one parent. The handles are not `Send`:
//! M3G's "concurrent use must not crash" is met by the type system refusing to share them.
//!
//! Inheritance maps to traits: [`Object3DExt`] (every handle), [`TransformableExt`]
//! (nodes and Texture2D), [`NodeExt`] (nodes) and [`GroupExt`] (Group, World). Upcast with
//! `as_node()`, `as_object3d()` or `Object3D::from`; downcast with
//! [`Object3D::downcast`] / [`Node::downcast`].
//!
//! Constants keep the specification's integer values (`CompositingMode::ALPHA == 64`) so
//! that the file format, animation targets and every IllegalArgument check map one to one.
//! Java's `null` is `Option`; where Java throws NullPointerException for a missing required
//! object, the Rust signature takes a reference and cannot receive one. Output arrays
//! become return values (`Transform::get() -> [f32; 16]`, `get_references() -> Vec<_>`).
//!
//! # Errors
//!
//! Fallible calls return [`Result`] with an [`M3gError`] named after the Java exception.
//!
//! # Name mapping
//!
//! Java names become snake_case; getters drop `get`/`is` only where Rust convention
//! prefers it (`getLayer` → `layer`, `isMutable` → `is_mutable`); overloads get suffixes:
//!
//! | Java | Rust |
//! |---|---|
//! | `Transform.set(Transform)` / `set(float[])` | `set_transform` / `set` |
//! | `Transform.transform(VertexArray, float[], boolean)` | `transform_vertex_array` |
//! | `Camera.getProjection(Transform)` / `(float[])` | `get_projection` / `get_projection_params` |
//! | `VertexArray.set(int, int, short[])` / `(…, byte[])` | `set_shorts` / `set_bytes` (`set_ubytes`) |
//! | `VertexArray.get(…, short[])` / `(…, byte[])` | `get_shorts` / `get_bytes` |
//! | `TriangleStripArray(int, int[])` / `(int[], int[])` | `new_implicit` / `new_explicit` |
//! | `Image2D(fmt, w, h)` / `(…, byte[])` / `(…, byte[], byte[])` | `new` / `with_pixels` / `with_palette` |
//! | `Mesh(vb, ib, app)` / `(vb, ib[], app[])` | `new` / `with_submeshes` |
//! | `Group.pick(scope, ox…dz, ri)` / `(scope, x, y, camera, ri)` | `pick_ray` / `pick` (return `Option<RayIntersection>`) |
//! | `Graphics3D.bindTarget(Image2D…)` / `(Graphics…)` | `bind_image` / `bind_target` (a `core::Target`) |
//! | `Graphics3D.render(World)` / `(Node, T)` / `(vb, ib, app, T[, scope])` | `render_world` / `render_node` / `render_submesh` |
//! | `RayIntersection.getTextureS/T` | `texture_s` / `texture_t` |
//!
//! Each class's own table is on its type ([`Object3DExt`], [`TransformableExt`],
//! [`NodeExt`], [`GroupExt`], [`Graphics3D`]).
//!
//! | `KeyframeSequence.getKeyframe(i, float[])` | `get_keyframe(i) -> (time, values)` |
//! | `MorphingMesh(base, targets, ib, app)` / `(…, ib[], app[])` | `new` / `with_submeshes` |
//! | `SkinnedMesh(vb, ib, app, skeleton)` / `(vb, ib[], app[], skeleton)` | `new` / `with_submeshes` |
//! | `SkinnedMesh.getBoneVertices(bone, int[], float[])` | `get_bone_vertices(bone) -> (indices, weights)` |
//!
//! MorphingMesh and SkinnedMesh are Meshes (`Object3D::downcast::<Mesh>` and `as_mesh()`
//! work); they draw and pick a deformed copy of the vertex buffer, recomputed only when an
//! input changed.
//!
//! [`Loader`] reads .m3g and PNG files ([`loader`]); [`writer`] saves any object graph as a
//! .m3g file the Loader reads back.
#![warn(missing_docs)]

mod animation;
mod appearance;
mod deform;
mod error;
mod graphics3d;
mod image;
mod keyframe;
pub mod loader;
mod mesh;
mod morphing_mesh;
mod node;
mod nodes;
mod object;
mod pick;
mod skinned_mesh;
mod transform;
mod vertex;
pub mod writer;

pub use animation::{AnimationController, AnimationTrack};
pub use appearance::{
    Appearance, Background, CompositingMode, Fog, Material, PolygonMode, Texture2D,
    MAX_TEXTURE_DIMENSION,
};
pub use error::{M3gError, Result};
pub use graphics3d::{Graphics3D, Property, RenderStats, MAX_LIGHTS, MAX_VIEWPORT_DIMENSION};
pub use image::Image2D;
pub use keyframe::KeyframeSequence;
pub use loader::{LoadError, Loader};
pub use mesh::{Mesh, Sprite3D, MAX_SPRITE_CROP_DIMENSION};
pub use morphing_mesh::MorphingMesh;
pub use node::{Group, GroupExt, Node, NodeExt, World};
pub use nodes::{Camera, Light};
pub use object::{Handle, Object3D, Object3DExt, TransformableExt};
pub use pick::RayIntersection;
pub use skinned_mesh::{SkinnedMesh, MAX_TRANSFORMS_PER_VERTEX};
pub use transform::Transform;
pub use vertex::{IndexBuffer, TriangleStripArray, VertexArray, VertexBuffer, NUM_TEXTURE_UNITS};
