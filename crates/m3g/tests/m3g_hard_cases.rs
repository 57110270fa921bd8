//! The M3G hard cases of `m3g-checklist.md` §5 that `crates/m3g/tests/m3g_*.rs` do not cover with
//! pixels: camera near == far, a polygon crossing W = 0, a non-invertible modelview,
//! degenerate triangles and setCamera with a singular transform. Each checks that only the
//! clear color or colors the draw can produce appear.

use m3g::*;

const CLEAR: [u8; 3] = [0, 0, 0];

/// A strip over the given short positions and index list, in one color.
fn mesh(pos: &[i16], strip: &[u16], lens: &[usize], argb: u32) -> (VertexBuffer, IndexBuffer) {
    let n = pos.len() / 3;
    let va = VertexArray::new(n, 3, 2).unwrap();
    va.set_shorts(0, pos).unwrap();
    let vb = VertexBuffer::new();
    vb.set_positions(Some(&va), 1.0, None).unwrap();
    vb.set_default_color(Color(argb));
    let ib = TriangleStripArray::new_explicit(strip, lens)
        .unwrap()
        .as_index_buffer();
    (vb, ib)
}

fn pixels(img: &Image2D) -> Vec<[u8; 3]> {
    img.pixels().chunks(3).map(|c| [c[0], c[1], c[2]]).collect()
}

fn render(
    cam: &Camera,
    t: Option<&Transform>,
    vb: &VertexBuffer,
    ib: &IndexBuffer,
    app: &Appearance,
) -> (Result<()>, Vec<[u8; 3]>) {
    let img = Image2D::new(ImageFormat::Rgb, 16, 16).unwrap();
    let mut g = Graphics3D::new();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    g.clear(None).unwrap();
    g.set_camera(Some(cam), None).unwrap();
    let r = g.render_submesh(vb, ib, app, t, -1);
    g.release_target();
    (r, pixels(&img))
}

fn covered(px: &[[u8; 3]]) -> usize {
    px.iter().filter(|p| **p != CLEAR).count()
}

fn only(px: &[[u8; 3]], color: [u8; 3]) {
    assert!(
        px.iter().all(|p| *p == CLEAR || *p == color),
        "garbage: {px:?}"
    );
}

fn square(z: i16) -> (VertexBuffer, IndexBuffer) {
    mesh(
        &[-1, -1, z, 1, -1, z, -1, 1, z, 1, 1, z],
        &[0, 1, 2, 3],
        &[4],
        0xFFFF0000,
    )
}

#[test]
fn camera_near_equal_to_far_renders_nothing() {
    let (vb, ib) = square(-2);
    let app = Appearance::new();
    for parallel in [true, false] {
        let c = Camera::new();
        if parallel {
            c.set_parallel(4.0, 1.0, 2.0, 2.0).unwrap();
        } else {
            c.set_perspective(60.0, 1.0, 2.0, 2.0).unwrap();
        }
        assert!(matches!(c.get_projection(), Err(Error::Arithmetic(_))));
        let (r, px) = render(&c, None, &vb, &ib, &app);
        assert!(r.is_ok(), "{r:?}");
        assert_eq!(covered(&px), 0, "parallel {parallel}");
        // Not validated either: a mesh without positions renders "nothing" without ISE.
        let (r, _) = render(&c, None, &VertexBuffer::new(), &ib, &app);
        assert!(r.is_ok(), "{r:?}");
    }
}

#[test]
fn polygon_crossing_w_zero_keeps_only_the_w_positive_part() {
    let c = Camera::new();
    c.set_perspective(90.0, 1.0, 0.5, 50.0).unwrap();
    // The clipped part's winding flips in the view: draw both faces.
    let app = Appearance::new();
    let pm = PolygonMode::new();
    pm.set_culling(Culling::None);
    app.set_polygon_mode(Some(&pm));
    // One vertex behind the eye (z = +4), two in front: only the front part is drawn.
    let (vb, ib) = mesh(
        &[-2, -2, -4, 2, -2, -4, 0, 1, 4],
        &[0, 1, 2],
        &[3],
        0xFF00FF00,
    );
    let (r, px) = render(&c, None, &vb, &ib, &app);
    r.unwrap();
    only(&px, [0, 255, 0]);
    let n = covered(&px);
    assert!(n > 0 && n < 256, "{n}");
    // Everything behind the eye: the whole polygon is dropped.
    let (vb, ib) = mesh(
        &[-2, -2, 4, 2, -2, 4, 0, 1, 4],
        &[0, 1, 2],
        &[3],
        0xFF00FF00,
    );
    let (r, px) = render(&c, None, &vb, &ib, &app);
    r.unwrap();
    assert_eq!(covered(&px), 0);
    // A vertex exactly at W = 0 (on the eye plane).
    let (vb, ib) = mesh(
        &[-2, -2, -4, 2, -2, -4, 0, 1, 0],
        &[0, 1, 2],
        &[3],
        0xFF00FF00,
    );
    let (r, px) = render(&c, None, &vb, &ib, &app);
    r.unwrap();
    only(&px, [0, 255, 0]);
}

#[test]
fn non_invertible_modelview_renders_without_error() {
    let c = Camera::new();
    c.set_parallel(4.0, 1.0, -10.0, 10.0).unwrap();
    let (vb, ib) = square(0);
    let na = VertexArray::new(4, 3, 1).unwrap();
    na.set_bytes(0, &[0, 0, 127, 0, 0, 127, 0, 0, 127, 0, 0, 127])
        .unwrap();
    vb.set_normals(Some(&na)).unwrap();
    // Lit and fogged: both undefined under a singular modelview, but no exception and no
    // non-finite garbage — every covered pixel one color (flat, equal normals).
    let app = Appearance::new();
    let m = Material::new();
    m.set_vertex_color_tracking_enable(true);
    app.set_material(Some(&m));
    app.set_fog(Some(&Fog::new()));
    let mut t = Transform::new();
    t.post_scale(1.0, 1.0, 0.0);
    let img = Image2D::new(ImageFormat::Rgb, 16, 16).unwrap();
    let mut g = Graphics3D::new();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    g.clear(None).unwrap();
    g.set_camera(Some(&c), None).unwrap();
    g.add_light(&Light::new(), None);
    g.render_submesh(&vb, &ib, &app, Some(&t), -1).unwrap();
    g.release_target();
    let px = pixels(&img);
    assert_eq!(covered(&px), 64, "the xy footprint is intact");
    let first = *px.iter().find(|p| **p != CLEAR).unwrap();
    only(&px, first);
}

#[test]
fn degenerate_triangles_produce_no_fragments() {
    let c = Camera::new();
    c.set_parallel(4.0, 1.0, -10.0, 10.0).unwrap();
    // Additive blending: a fragment from a degenerate triangle would brighten a pixel.
    let app = Appearance::new();
    let cm = CompositingMode::new();
    cm.set_blending(Blending::AlphaAdd);
    app.set_compositing_mode(Some(&cm));
    // Repeated indices only, and coincident and collinear positions.
    let pos = [0, 0, 0, 0, 0, 0, 1, 1, 0, -1, -1, 0, 1, 1, 0];
    for strip in [
        &[0, 0, 0][..],
        &[0, 1, 0],
        &[0, 1, 2],
        &[3, 0, 2],
        &[2, 2, 4, 4],
    ] {
        let (vb, ib) = mesh(&pos, strip, &[strip.len()], 0xFF808080);
        let (r, px) = render(&c, None, &vb, &ib, &app);
        r.unwrap();
        assert_eq!(covered(&px), 0, "{strip:?}");
    }
    // Two quads stitched by degenerate triangles: each pixel exactly once.
    let pos = [
        -2, -2, 0, 0, -2, 0, -2, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 0, 0, 2, 0, 2, 2, 0,
    ];
    let (vb, ib) = mesh(&pos, &[0, 1, 2, 3, 3, 4, 4, 5, 6, 7], &[10], 0xFF808080);
    let (r, px) = render(&c, None, &vb, &ib, &app);
    r.unwrap();
    only(&px, [128, 128, 128]);
    assert_eq!(covered(&px), 128);
}

#[test]
fn set_camera_with_a_singular_transform_throws_arithmetic_exception() {
    let img = Image2D::new(ImageFormat::Rgb, 4, 4).unwrap();
    let mut g = Graphics3D::new();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    let c = Camera::new();
    g.set_camera(Some(&c), None).unwrap();
    for m in [
        [0.0f32; 16],
        [
            1., 0., 0., 0., 0., 0., 0., 0., 0., 0., 1., 0., 0., 0., 0., 1.,
        ],
        [
            1., 2., 3., 4., 2., 4., 6., 8., 0., 0., 1., 0., 0., 0., 0., 1.,
        ],
    ] {
        let mut t = Transform::new();
        t.set(&m).unwrap();
        assert!(
            matches!(g.set_camera(Some(&c), Some(&t)), Err(Error::Arithmetic(_))),
            "{m:?}"
        );
        // The previous camera stays in effect.
        assert!(g.camera().is_some());
    }
    g.release_target();
}
