//! Shared by the fuzz targets: renders whatever a load produced into a small target, so
//! that hostile content reaches animation, light collection, culling, deformation and the
//! rasterizer. Every result must be `Ok` or an error, never a panic, hang or abort.

use m3g::loader::{render_roots, RenderTarget};
use m3g::{Camera, Graphics3D, Node, Object3D, Object3DExt, TransformableExt};
use m3g::{ColorFormat, DepthFormat, RenderHints, Target, TargetFormat};

/// Renders the first World (at two times, so animation runs) and each root node with a
/// default camera, into 16 × 16 targets.
pub fn render_loaded(roots: &[Object3D]) {
    let _ = render_roots(roots, 0, 16, 16, false, RenderTarget::Graphics);
    let _ = render_roots(roots, 1000, 16, 16, true, RenderTarget::RgbaImage);
    let camera = Camera::new();
    if camera.set_perspective(60.0, 1.0, 0.1, 100.0).is_err() {
        return;
    }
    camera.set_translation(0.0, 0.0, 5.0);
    for node in roots.iter().filter_map(|r| r.downcast::<Node>()) {
        let mut g = Graphics3D::new();
        let target = Target::new(
            16,
            16,
            TargetFormat {
                color: ColorFormat::Rgba8888,
                depth: Some(DepthFormat::D16),
                stencil_bits: 0,
            },
        );
        if g.bind_target(target, true, RenderHints::empty()).is_err() {
            return;
        }
        let _ = node.animate(500);
        if g.set_camera(Some(&camera), None).is_ok() {
            let _ = g.render_node(&node, None);
        }
        g.release_target();
    }
}
