//! Rendering a loaded scene the way the corpus reference images were made (the code path of
//! the `m3g` tool, shared with the tests).

use crate::{Error, Graphics3D, Object3D, Object3DExt, RenderHints, Result, World};
use gles_cm_core::{ColorFormat, DepthFormat, Target, TargetFormat};

/// What [`render_roots`] renders into, which decides the format a World's background image
/// must have.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum RenderTarget {
    /// A MIDP `Graphics` target, always RGB: what content made for phones renders to.
    #[default]
    Graphics,
    /// A mutable RGBA `Image2D`.
    RgbaImage,
}

/// Renders the first World among `roots` (a file without one is an error) at `time_ms` with
/// its active camera into `target` (rendered, either way, through a `width` × `height`
/// 8-bit RGBA buffer with a 16-bit depth buffer, as the reference images were) with hints 0,
/// cleared by the World's Background (or to black and depth 1 without one). A background
/// image of another format than the target's is an error naming both.
/// `clamp_after_lighting` as in [`Graphics3D::set_clamp_after_lighting`] (`false` for the
/// reference images). Returns RGB bytes, top row first.
pub fn render_roots(
    roots: &[Object3D],
    time_ms: i32,
    width: u32,
    height: u32,
    clamp_after_lighting: bool,
    target_kind: RenderTarget,
) -> Result<Vec<u8>> {
    let world = roots
        .iter()
        .find_map(|r| r.downcast::<World>())
        .ok_or_else(|| {
            let first = roots.first().map_or("nothing", |r| r.class_name());
            Error::IllegalArgument(format!(
                "no World among the root objects (the first root is a {first})"
            ))
        })?;
    world
        .animate(time_ms)
        .map_err(|e| e.context(&format!("animate({time_ms}) failed")))?;
    let target = Target::new(
        width,
        height,
        TargetFormat {
            color: ColorFormat::Rgba8888,
            depth: Some(DepthFormat::D16),
            stencil_bits: 0,
        },
    );
    let mut g = Graphics3D::new();
    g.set_clamp_after_lighting(clamp_after_lighting);
    match target_kind {
        RenderTarget::Graphics => g.bind_graphics_target(target, true, RenderHints::empty()),
        RenderTarget::RgbaImage => g.bind_target(target, true, RenderHints::empty()),
    }
    .map_err(|e| e.context(&format!("cannot bind a {width}x{height} target")))?;
    let r = g.render_world(&world);
    let target = g.release_target().expect("a core target");
    r.map_err(|e| e.context("render(World) failed"))?;
    let (w, h) = (width as usize, height as usize);
    let mut out = Vec::with_capacity(w * h * 3);
    for y in 0..h {
        let row = &target.color()[(h - 1 - y) * w..][..w];
        for px in row {
            out.extend_from_slice(&px.to_le_bytes()[..3]);
        }
    }
    Ok(out)
}
