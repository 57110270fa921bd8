//! The rendering core: plain Rust, no FFI types. Both faces of the library, the GL/EGL state
//! machines and the M3G scene graph, describe what to draw as a [`RenderState`] plus a
//! [`DrawCall`] and hand it to [`render`], which runs
//! vertex → clip → setup → raster → fragment into a [`Target`].

pub mod clip;
pub mod fixed;
pub mod fragment;
pub mod raster;
pub mod setup;
pub mod state;
pub mod target;
pub mod vertex;

pub use state::{CompareFunc, CullFace, RenderState, ShadeModel, Viewport, Winding};
pub use target::{ColorFormat, DepthFormat, Rect, Target, TargetFormat};
pub use vertex::{AttribArray, AttribSource, ComponentType, DrawCall, Indices, Primitive};

/// The subpixel precision of window coordinates: positions snap to 1/2⁸ pixel.
pub const SUBPIXEL_BITS: u32 = 8;
/// The largest viewport width and height. With [`SUBPIXEL_BITS`] it bounds every snapped
/// coordinate the rasterizer sees to 2¹⁴·2⁸ = 2²², so edge products stay far below 2⁶³.
pub const MAX_VIEWPORT_DIM: u32 = 8192;

/// Draws `draw` with `state` into `target`, returning when every pixel is written.
pub fn render(state: &RenderState, draw: &DrawCall<'_>, target: &mut Target) {
    let vertices = vertex::run(state, draw);
    let bounds = state.pixel_bounds(target);
    if bounds.is_empty() {
        return;
    }
    let fragment = fragment::FragmentKey::new(state, target.format());
    draw.primitive.for_each_triangle(&draw.indices, |a, b, c| {
        let (a, b, c) = (&vertices[a], &vertices[b], &vertices[c]);
        clip::triangle(a, b, c, |poly| {
            // The clipped polygon is convex: fan it out from its first vertex.
            for i in 1..poly.len() - 1 {
                let tri = [&poly[0], &poly[i], &poly[i + 1]];
                if let Some(t) = setup::triangle(state, tri, c, bounds) {
                    raster::triangle(&t, |span| fragment.shade(&t, span, target));
                }
            }
        });
    });
}
