//! M3G 1.1 (JSR-184) in Rust: the scene graph and immediate-mode API, the Loader and a
//! writer for `.m3g` files, rendering through the `gles-cm-core` software rasterizer (no GPU,
//! no GL library).
//!
//! # Examples
//!
//! A World with a camera, a light and a lit red square, rendered into a [`Target`]; then
//! one pixel read back, and the whole frame as an `image::RgbaImage` right side up (a
//! target's rows are bottom row first, see [`target_to_image`]):
//!
//! ```
//! use m3g::prelude::*;
//!
//! # fn main() -> m3g::Result<()> {
//! // A square from (-1, -1) to (1, 1) at z = 0, facing +Z, as one triangle strip.
//! let positions = VertexArray::new(4, 3, 2)?; // 4 vertices, 3 components, 16-bit
//! positions.set_shorts(0, &[-1, -1, 0, 1, -1, 0, -1, 1, 0, 1, 1, 0])?;
//! let normals = VertexArray::new(4, 3, 1)?; // 8-bit normals, 127 = 1.0
//! normals.set_bytes(0, &[0, 0, 127, 0, 0, 127, 0, 0, 127, 0, 0, 127])?;
//! let vertices = VertexBuffer::new();
//! vertices.set_positions(Some(&positions), 1.0, None)?; // scale 1, no bias
//! vertices.set_normals(Some(&normals))?;
//! let strip = TriangleStripArray::new_implicit(0, &[4])?.as_index_buffer();
//!
//! let red = Material::new();
//! red.set_color(MaterialColor::DIFFUSE, Color::RED)?;
//! let look = Appearance::new();
//! look.set_material(Some(&red));
//!
//! let world = World::new();
//! world.add_child(&Mesh::new(&vertices, &strip, Some(&look)))?;
//! let camera = Camera::new();
//! camera.set_perspective(60.0, 1.0, 0.1, 100.0)?;
//! camera.set_translation(0.0, 0.0, 3.0); // looking down -Z at the square
//! world.add_child(&camera)?;
//! world.set_active_camera(&camera);
//! world.add_child(&Light::new())?; // directional, along -Z: full on the square
//!
//! let format = TargetFormat {
//!     color: ColorFormat::Rgba8888,
//!     depth: Some(DepthFormat::D16),
//!     stencil_bits: 0,
//! };
//! let mut g3d = Graphics3D::new();
//! g3d.bind_target(Target::new(64, 64, format), true, RenderHints::empty())?;
//! g3d.render_world(&world)?; // clears (no Background: black), then draws
//! let target = g3d.release_target().unwrap();
//!
//! assert_eq!(target.pixel(32, 32), [255, 0, 0, 255]); // the middle: lit red
//! assert_eq!(target.pixel(0, 0)[..3], [0, 0, 0]); // a corner: the cleared background
//! let picture = m3g::target_to_image(&target); // an image::RgbaImage, top row first
//! assert_eq!(picture.get_pixel(32, 32).0, [255, 0, 0, 255]);
//! # Ok(())
//! # }
//! ```
//!
//! Animation: a keyframe sequence drives a property through an [`AnimationTrack`];
//! `animate(time)` on any object applies every track reachable from it:
//!
//! ```
//! use m3g::prelude::*;
//!
//! # fn main() -> m3g::Result<()> {
//! let moves = KeyframeSequence::new(2, 3, Interpolation::Linear)?;
//! moves.set_keyframe(0, 0, &[0.0, 0.0, 0.0])?; // at 0 ms
//! moves.set_keyframe(1, 1000, &[4.0, 0.0, 0.0])?; // at 1000 ms
//! moves.set_duration(1000)?;
//! let track = AnimationTrack::new(&moves, AnimationProperty::Translation)?;
//! track.set_controller(Some(&AnimationController::new()));
//!
//! let group = Group::new();
//! group.add_animation_track(&track)?;
//! let world = World::new();
//! world.add_child(&group)?;
//! world.animate(250)?;
//! assert_eq!(group.get_translation(), [1.0, 0.0, 0.0]);
//! # Ok(())
//! # }
//! ```
//!
//! Immediate mode into an [`Image2D`], whose pixels are read back top row first; and the
//! same object graph saved with the [`writer`] and read back with the [`Loader`] (one
//! [`Error`] type: `?` works across both):
//!
//! ```
//! use m3g::prelude::*;
//!
//! # fn main() -> m3g::Result<()> {
//! let positions = VertexArray::new(3, 3, 1)?; // one triangle, 8-bit coordinates
//! positions.set_bytes(0, &[-1, -1, 0, 1, -1, 0, -1, 1, 0])?;
//! let vertices = VertexBuffer::new();
//! vertices.set_positions(Some(&positions), 1.0, None)?;
//! vertices.set_default_color(Color::GREEN); // unlit: the default color
//! let triangle = TriangleStripArray::new_implicit(0, &[3])?.as_index_buffer();
//!
//! let camera = Camera::new();
//! camera.set_parallel(2.0, 1.0, -1.0, 1.0)?; // x and y from -1 to 1
//! let image = Image2D::new(ImageFormat::Rgb, 8, 8)?;
//! let mut g3d = Graphics3D::new();
//! g3d.bind_image(&image, true, RenderHints::empty())?;
//! g3d.clear(None)?;
//! g3d.set_camera(Some(&camera), None)?;
//! g3d.render_submesh(&vertices, &triangle, &Appearance::new(), None, -1)?;
//! g3d.release_target(); // writes the frame into the image
//!
//! let rgb = image::RgbImage::from(&image);
//! assert_eq!(rgb.get_pixel(0, 7).0, [0, 255, 0]); // bottom left: inside the triangle
//! assert_eq!(rgb.get_pixel(7, 0).0, [0, 0, 0]); // top right: outside
//!
//! let mesh = Mesh::new(&vertices, &triangle, Some(&Appearance::new()));
//! mesh.set_user_id(7);
//! let bytes = m3g::writer::save(&[mesh.as_object3d()], true)?; // zlib-compressed .m3g
//! let roots = Loader::load(&bytes)?;
//! let loaded = roots[0].downcast::<Mesh>().unwrap();
//! assert_eq!(loaded.user_id(), 7);
//! assert_eq!(loaded.vertex_buffer().default_color(), Color::GREEN);
//! # Ok(())
//! # }
//! ```
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
//! has no strong cycles and a node has at most one parent. `Debug` prints the class, the
//! user ID and the fields that tell objects apart; referenced objects only as counts.
//!
//! Inheritance maps to traits: [`Object3DExt`] (every handle), [`TransformableExt`]
//! (nodes and Texture2D), [`NodeExt`] (nodes) and [`GroupExt`] (Group, World), all in the
//! [`prelude`]. Upcast with `as_node()`, `as_object3d()` or `Object3D::from`; downcast with
//! [`Object3D::downcast`] / [`Node::downcast`]. Every class with a no-argument Java
//! constructor implements `Default` (the same object as `new()`).
//!
//! # Threads
//!
//! The handles are neither `Send` nor `Sync`. Making them so would put an `Arc` and a lock
//! in every object and a lock acquisition in every getter, setter and per-object step of
//! rendering and animation, for scene graphs that are built and drawn on one thread
//! anyway; M3G's own rule ("concurrent use must not crash") is met here by the type system
//! refusing to share them. To render on another thread, build (or load) the scene **on
//! that thread** and send plain data across: file bytes in, and the rendered [`Target`],
//! an `image::RgbaImage` ([`target_to_image`]) or an `Image2D`'s pixels out.
//!
//! ```
//! use m3g::prelude::*;
//!
//! let frame = std::thread::spawn(|| -> m3g::Result<image::RgbaImage> {
//!     let world = World::new(); // made, animated and rendered here
//!     let camera = Camera::new();
//!     world.add_child(&camera)?;
//!     world.set_active_camera(&camera);
//!     let format = TargetFormat { color: ColorFormat::Rgba8888, depth: None, stencil_bits: 0 };
//!     let mut g3d = Graphics3D::new();
//!     g3d.bind_target(Target::new(8, 8, format), false, RenderHints::empty())?;
//!     g3d.render_world(&world)?;
//!     Ok(m3g::target_to_image(&g3d.release_target().unwrap()))
//! })
//! .join()
//! .unwrap()
//! .unwrap();
//! assert_eq!(frame.dimensions(), (8, 8));
//! ```
//!
//! # Modes, colors and indices
//!
//! The specification's integer constants are enums ([`LightMode`], [`Blending`],
//! [`Interpolation`], [`AnimationProperty`], …) and OR-able flags types ([`MaterialColor`],
//! [`RenderHints`]); each keeps the specification's number (`Blending::Alpha.as_raw() ==
//! 64`), which `from_raw` / `TryFrom<i32>` take back, refusing any other value with
//! IllegalArgument, the exception Java throws for it. Colors are [`Color`] (`0xAARRGGBB`).
//! Indices and counts are `usize`; arrays are slices whose length is the count
//! (`VertexArray::set_shorts(first, &values)` writes `values.len() / component_count()`
//! vertices). Java's `null` is `Option`; where Java throws NullPointerException for a
//! missing required object, the Rust signature takes a reference and cannot receive one.
//! Output arrays become return values (`Transform::get() -> [f32; 16]`,
//! `get_references() -> Vec<_>`).
//!
//! # Errors
//!
//! Fallible calls return [`Result`] with an [`Error`]: one variant per Java exception the
//! specification names (IllegalArgument, IllegalState, IndexOutOfBounds, Arithmetic,
//! NullPointer), the Loader's `IOException` as [`Error::Io`] with the object, class and
//! field at fault ([`LoadError`]), and the writer's refusals as [`Error::Write`].
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
//! | `VertexArray.set(int, int, short[])` / `(…, byte[])` | `set_shorts(first, &[i16])` / `set_bytes(first, &[i8])` (`set_ubytes`) |
//! | `VertexArray.get(…, short[])` / `(…, byte[])` | `get_shorts(first, n)` / `get_bytes(first, n)` |
//! | `TriangleStripArray(int, int[])` / `(int[], int[])` | `new_implicit` / `new_explicit` (indices `&[u16]`) |
//! | `Image2D(fmt, w, h)` / `(…, byte[])` / `(…, byte[], byte[])` | `new` / `with_pixels` / `with_palette` |
//! | `Mesh(vb, ib, app)` / `(vb, ib[], app[])` | `new` / `with_submeshes` |
//! | `Group.pick(scope, ox…dz, ri)` / `(scope, x, y, camera, ri)` | `pick_ray` / `pick` (return `Option<RayIntersection>`) |
//! | `Graphics3D.bindTarget(Image2D…)` / `(Graphics…)` | `bind_image` / `bind_target` (a [`Target`]) |
//! | `Graphics3D.render(World)` / `(Node, T)` / `(vb, ib, app, T[, scope])` | `render_world` / `render_node` / `render_submesh` |
//! | `RayIntersection.getTextureS/T` | `texture_s` / `texture_t` |
//! | `KeyframeSequence.getKeyframe(i, float[])` | `get_keyframe(i) -> (time, values)` |
//! | `MorphingMesh(base, targets, ib, app)` / `(…, ib[], app[])` | `new` / `with_submeshes` |
//! | `SkinnedMesh(vb, ib, app, skeleton)` / `(vb, ib[], app[], skeleton)` | `new` / `with_submeshes` |
//! | `SkinnedMesh.getBoneVertices(bone, int[], float[])` | `get_bone_vertices(bone) -> (indices, weights)` |
//! | `Light.AMBIENT` … `SPOT` | [`LightMode`]`::Ambient` … `Spot` |
//! | `Camera.GENERIC` / `PARALLEL` / `PERSPECTIVE` | [`Projection`]`::Generic` / `Parallel` / `Perspective` |
//! | `CompositingMode.ALPHA` … `REPLACE` | [`Blending`]`::Alpha`, `AlphaAdd`, `Modulate`, `ModulateX2`, `Replace` |
//! | `PolygonMode.CULL_*` / `SHADE_*` / `WINDING_*` | [`Culling`] / [`Shading`] / [`Winding`] |
//! | `Material.AMBIENT` … `SPECULAR` (ORed) | [`MaterialColor`]`::AMBIENT` … (with `\|`) |
//! | `Fog.EXPONENTIAL` / `LINEAR` | [`FogMode`] |
//! | `Texture2D.FILTER_*` / `FUNC_*` / `WRAP_*` | [`TextureFilter`] / [`TextureFunction`] / [`TextureWrap`] |
//! | `Background.BORDER` / `REPEAT` | [`ImageMode`] |
//! | `Image2D.ALPHA` … `RGBA` | [`ImageFormat`] |
//! | `Node.NONE`, `ORIGIN`, `X_AXIS` … `Z_AXIS` | [`AlignTarget`] |
//! | `KeyframeSequence.LINEAR` … `STEP` / `CONSTANT`, `LOOP` | [`Interpolation`] / [`RepeatMode`] |
//! | `AnimationTrack.ALPHA` … `VISIBILITY` | [`AnimationProperty`] |
//! | `Graphics3D.ANTIALIAS` … `OVERWRITE` (ORed) | [`RenderHints`] |
//! | an `int` ARGB / RGB color | [`Color`] |
//!
//! Each class's own table is on its type ([`Object3DExt`], [`TransformableExt`],
//! [`NodeExt`], [`GroupExt`], [`Graphics3D`]).
//!
//! MorphingMesh and SkinnedMesh are Meshes (`Object3D::downcast::<Mesh>` and `as_mesh()`
//! work); they draw and pick a deformed copy of the vertex buffer, recomputed only when an
//! input changed.
//!
//! [`Loader`] reads .m3g and PNG files ([`loader`]); [`writer`] saves any object graph as a
//! .m3g file the Loader reads back. [`Image2D`] converts to and from the `image` crate's
//! buffers (`TryFrom<&image::RgbaImage>`, `From<&Image2D> for image::RgbaImage`, RGB and
//! gray too), rows top first on both sides.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod animation;
mod appearance;
mod camera;
mod color;
mod debug;
mod deform;
mod error;
mod graphics3d;
mod image;
mod image_convert;
mod keyframe;
mod light;
pub mod loader;
mod mesh;
mod modes;
mod morphing_mesh;
mod node;
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
pub use camera::Camera;
pub use color::Color;
pub use error::{Error, Result};
/// The vector and matrix types of the public API (`glam` 0.29).
pub use glam;
/// The render target types of the rasterizer underneath, which [`Graphics3D::bind_target`]
/// draws into.
pub use gles_cm_core::{ColorFormat, DepthFormat, Target, TargetFormat};
pub use graphics3d::{Graphics3D, Property, RenderStats, MAX_LIGHTS, MAX_VIEWPORT_DIMENSION};
pub use image::Image2D;
pub use image_convert::target_to_image;
pub use keyframe::KeyframeSequence;
pub use light::Light;
pub use loader::{LoadError, Loader};
pub use mesh::{Mesh, Sprite3D, MAX_SPRITE_CROP_DIMENSION};
pub use modes::{
    AlignTarget, AnimationProperty, Blending, Culling, FogMode, ImageFormat, ImageMode,
    Interpolation, LightMode, MaterialColor, Projection, RenderHints, RepeatMode, Shading,
    TextureFilter, TextureFunction, TextureWrap, Winding,
};
pub use morphing_mesh::MorphingMesh;
pub use node::{Group, GroupExt, Node, NodeExt, World};
pub use object::{Handle, Object3D, Object3DExt, TransformableExt};
pub use pick::RayIntersection;
pub use skinned_mesh::{SkinnedMesh, MAX_TRANSFORMS_PER_VERTEX};
pub use transform::Transform;
pub use vertex::{IndexBuffer, TriangleStripArray, VertexArray, VertexBuffer, NUM_TEXTURE_UNITS};

/// The README's example, compiled as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

/// The types and traits a program using M3G needs, without the crate's `Result` alias
/// (which would shadow the standard one): `use m3g::prelude::*;`.
pub mod prelude {
    pub use crate::{
        AlignTarget, AnimationController, AnimationProperty, AnimationTrack, Appearance,
        Background, Blending, Camera, Color, ColorFormat, CompositingMode, Culling, DepthFormat,
        Error, Fog, FogMode, Graphics3D, Group, GroupExt, Image2D, ImageFormat, ImageMode,
        IndexBuffer, Interpolation, KeyframeSequence, Light, LightMode, Loader, Material,
        MaterialColor, Mesh, MorphingMesh, Node, NodeExt, Object3D, Object3DExt, PolygonMode,
        Projection, RayIntersection, RenderHints, RepeatMode, Shading, SkinnedMesh, Sprite3D,
        Target, TargetFormat, Texture2D, TextureFilter, TextureFunction, TextureWrap, Transform,
        TransformableExt, TriangleStripArray, VertexArray, VertexBuffer, Winding, World,
    };
}
