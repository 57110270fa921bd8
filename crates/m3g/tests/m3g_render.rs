//! M3G Graphics3D rendering and picking: exact pixels, the core reference, and errors.

use gles_cm_core::{ColorFormat, DepthFormat, Target, TargetFormat};
use m3g::*;

fn is_iae<T: std::fmt::Debug>(r: Result<T>) -> bool {
    matches!(r, Err(Error::IllegalArgument(_)))
}
fn is_ise<T: std::fmt::Debug>(r: Result<T>) -> bool {
    matches!(r, Err(Error::IllegalState(_)))
}
fn is_ae<T: std::fmt::Debug>(r: Result<T>) -> bool {
    matches!(r, Err(Error::Arithmetic(_)))
}

/// A square from (-s, -s, z) to (s, s, z), counter-clockwise seen from +Z, as a strip.
fn quad(s: f32, z: i16, argb: u32) -> (VertexBuffer, IndexBuffer) {
    let va = VertexArray::new(4, 3, 2).unwrap();
    va.set_shorts(0, &[-1, -1, z, 1, -1, z, 1, 1, z, -1, 1, z])
        .unwrap();
    let vb = VertexBuffer::new();
    vb.set_positions(Some(&va), s, None).unwrap();
    vb.set_default_color(Color(argb));
    let na = VertexArray::new(4, 3, 1).unwrap();
    na.set_bytes(0, &[0, 0, 127, 0, 0, 127, 0, 0, 127, 0, 0, 127])
        .unwrap();
    vb.set_normals(Some(&na)).unwrap();
    let ib = TriangleStripArray::new_explicit(&[0, 1, 3, 2], &[4])
        .unwrap()
        .as_index_buffer();
    (vb, ib)
}

fn ortho_camera() -> Camera {
    let c = Camera::new();
    c.set_parallel(2.0, 1.0, -10.0, 10.0).unwrap();
    c
}

fn px(img: &Image2D, x: usize, y: usize) -> [u8; 3] {
    let p = img.pixels();
    let b = if img.format() == ImageFormat::Rgba {
        4
    } else {
        3
    };
    let w = img.width() as usize;
    let at = (y * w + x) * b;
    [p[at], p[at + 1], p[at + 2]]
}

#[test]
fn flat_quad_in_a_parallel_camera_is_pixel_exact() {
    let img = Image2D::new(ImageFormat::Rgb, 16, 16).unwrap();
    let mut g = Graphics3D::new();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    assert_eq!(g.viewport(), [0, 0, 16, 16]);
    g.clear(None).unwrap();
    g.set_camera(Some(&ortho_camera()), None).unwrap();
    let (vb, ib) = quad(0.5, 0, 0xFFFF0000);
    g.render_submesh(&vb, &ib, &Appearance::new(), None, -1)
        .unwrap();
    g.release_target();
    for y in 0..16 {
        for x in 0..16 {
            let inside = (4..12).contains(&x) && (4..12).contains(&y);
            let want = if inside { [255, 0, 0] } else { [0, 0, 0] };
            assert_eq!(px(&img, x, y), want, "({x},{y})");
        }
    }
}

#[test]
fn y_points_down_and_viewport_offsets() {
    // A quad in the upper half of NDC lands in the top rows of the image.
    let img = Image2D::new(ImageFormat::Rgba, 8, 8).unwrap();
    let mut g = Graphics3D::new();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    g.clear(None).unwrap();
    g.set_camera(Some(&ortho_camera()), None).unwrap();
    g.set_viewport(4, 0, 4, 4).unwrap();
    let (vb, ib) = quad(1.0, 0, 0xFF00FF00);
    let mut t = Transform::new();
    t.post_translate(0.0, 0.5, 0.0);
    t.post_scale(1.0, 0.5, 1.0);
    g.render_submesh(&vb, &ib, &Appearance::new(), Some(&t), -1)
        .unwrap();
    g.release_target();
    for y in 0..8 {
        for x in 0..8 {
            let want = if x >= 4 && y < 2 {
                [0, 255, 0]
            } else {
                [0, 0, 0]
            };
            assert_eq!(px(&img, x, y), want, "({x},{y})");
        }
    }
}

#[test]
fn world_render_with_background_layers_scope_and_enable() {
    let img = Image2D::new(ImageFormat::Rgb, 16, 16).unwrap();
    let world = World::new();
    let cam = ortho_camera();
    world.add_child(&cam).unwrap();
    world.set_active_camera(&cam);
    let bg = Background::new();
    bg.set_color(Color(0xFF0000FF));
    world.set_background(Some(&bg));
    // Red on layer 1 drawn first in the graph, green on layer 0 at the same depth: green is
    // drawn first, then red over it (depth LEQUAL).
    let (vb1, ib1) = quad(0.5, 0, 0xFFFF0000);
    let a1 = Appearance::new();
    a1.set_layer(1).unwrap();
    let m1 = Mesh::new(&vb1, &ib1, Some(&a1));
    let (vb2, ib2) = quad(0.5, 0, 0xFF00FF00);
    let m2 = Mesh::new(&vb2, &ib2, Some(&Appearance::new()));
    world.add_child(&m1).unwrap();
    world.add_child(&m2).unwrap();
    let mut g = Graphics3D::new();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    g.render_world(&world).unwrap();
    g.release_target();
    assert_eq!(px(&img, 8, 8), [255, 0, 0]);
    assert_eq!(px(&img, 0, 0), [0, 0, 255]);
    // Out of scope, disabled, or without appearance: not drawn.
    m1.set_scope(0);
    m2.set_rendering_enable(false);
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    g.render_world(&world).unwrap();
    g.release_target();
    assert_eq!(px(&img, 8, 8), [0, 0, 255]);
    m1.set_scope(-1);
    m1.set_appearance(0, None).unwrap();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    g.render_world(&world).unwrap();
    g.release_target();
    assert_eq!(px(&img, 8, 8), [0, 0, 255]);
    // A disabled group disables its children; the camera's own flag is ignored.
    m2.set_rendering_enable(true);
    cam.set_rendering_enable(false);
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    g.render_world(&world).unwrap();
    g.release_target();
    assert_eq!(px(&img, 8, 8), [0, 255, 0]);
    assert_eq!(g.light_count(), 0);
    // Color clear disabled keeps the old pixels.
    bg.set_color_clear_enable(false);
    img.set(0, 0, 1, 1, &[9, 9, 9]).unwrap();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    g.render_world(&world).unwrap();
    g.release_target();
    assert_eq!(px(&img, 0, 0), [9, 9, 9]);
}

#[test]
fn opaque_before_blended_within_a_layer() {
    let img = Image2D::new(ImageFormat::Rgb, 8, 8).unwrap();
    let world = World::new();
    let cam = ortho_camera();
    world.add_child(&cam).unwrap();
    world.set_active_camera(&cam);
    // A half-transparent white quad in front, listed first; an opaque blue quad behind.
    let (vb1, ib1) = quad(1.0, 1, 0x80FFFFFF);
    let a1 = Appearance::new();
    let cm = CompositingMode::new();
    cm.set_blending(Blending::Alpha);
    a1.set_compositing_mode(Some(&cm));
    let (vb2, ib2) = quad(1.0, 0, 0xFF0000FF);
    world.add_child(&Mesh::new(&vb1, &ib1, Some(&a1))).unwrap();
    world
        .add_child(&Mesh::new(&vb2, &ib2, Some(&Appearance::new())))
        .unwrap();
    let mut g = Graphics3D::new();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    g.render_world(&world).unwrap();
    g.release_target();
    let p = px(&img, 4, 4);
    assert!(p[0].abs_diff(128) <= 1 && p[2] == 255, "{p:?}");
}

#[test]
fn blend_modes_and_alpha_factor() {
    let cases = [
        (Blending::Replace, [255u8, 128, 0]),
        // Source (255, 128, 0) with alpha 0.5 (the factor), destination (200, 0, 0).
        (Blending::Alpha, [228, 64, 0]),
        (Blending::AlphaAdd, [255, 64, 0]),
        (Blending::Modulate, [200, 0, 0]),
        (Blending::ModulateX2, [255, 0, 0]),
    ];
    for (mode, want) in cases {
        let img = Image2D::new(ImageFormat::Rgb, 4, 4).unwrap();
        let mut g = Graphics3D::new();
        g.bind_image(&img, true, RenderHints::empty()).unwrap();
        let bg = Background::new();
        bg.set_color(Color(0xFFC80000)); // (200, 0, 0)
        g.clear(Some(&bg)).unwrap();
        g.set_camera(Some(&ortho_camera()), None).unwrap();
        let (vb, ib) = quad(1.0, 0, 0xFFFF8000);
        let mesh = Mesh::new(&vb, &ib, Some(&Appearance::new()));
        let cm = CompositingMode::new();
        cm.set_blending(mode);
        mesh.appearance(0)
            .unwrap()
            .unwrap()
            .set_compositing_mode(Some(&cm));
        let grp = Group::new();
        grp.set_alpha_factor(0.5).unwrap();
        grp.add_child(&mesh).unwrap();
        g.render_node(&grp, None).unwrap();
        g.release_target();
        let p = px(&img, 1, 1);
        for c in 0..3 {
            assert!(
                p[c].abs_diff(want[c]) <= 1,
                "mode {mode:?}: {p:?} vs {want:?}"
            );
        }
    }
}

#[test]
fn depth_is_written_with_the_test_off() {
    let img = Image2D::new(ImageFormat::Rgb, 4, 4).unwrap();
    let mut g = Graphics3D::new();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    g.clear(None).unwrap();
    g.set_camera(Some(&ortho_camera()), None).unwrap();
    let (near, ib) = quad(1.0, 5, 0xFFFF0000);
    let (far, _) = quad(1.0, -5, 0xFF00FF00);
    let a = Appearance::new();
    let cm = CompositingMode::new();
    cm.set_depth_test_enable(false);
    a.set_compositing_mode(Some(&cm));
    g.render_submesh(&near, &ib, &a, None, -1).unwrap();
    g.render_submesh(&far, &ib, &Appearance::new(), None, -1)
        .unwrap();
    g.release_target();
    assert_eq!(
        px(&img, 1, 1),
        [255, 0, 0],
        "the far quad fails against the written depth"
    );
    // Without a depth buffer nothing is tested.
    g.bind_image(&img, false, RenderHints::empty()).unwrap();
    g.render_submesh(&far, &ib, &Appearance::new(), None, -1)
        .unwrap();
    g.release_target();
    assert_eq!(px(&img, 1, 1), [0, 255, 0]);
}

#[test]
fn culling_and_winding() {
    let img = Image2D::new(ImageFormat::Rgb, 4, 4).unwrap();
    let mut g = Graphics3D::new();
    let (vb, ib) = quad(1.0, 0, 0xFFFFFFFF);
    for (cull, wind, drawn) in [
        (Culling::Back, Winding::Ccw, true),
        (Culling::Front, Winding::Ccw, false),
        (Culling::Back, Winding::Cw, false),
        (Culling::None, Winding::Cw, true),
    ] {
        g.bind_image(&img, true, RenderHints::empty()).unwrap();
        g.clear(None).unwrap();
        g.set_camera(Some(&ortho_camera()), None).unwrap();
        let a = Appearance::new();
        let pm = PolygonMode::new();
        pm.set_culling(cull);
        pm.set_winding(wind);
        a.set_polygon_mode(Some(&pm));
        g.render_submesh(&vb, &ib, &a, None, -1).unwrap();
        g.release_target();
        assert_eq!(px(&img, 1, 1) == [255; 3], drawn, "{cull:?} {wind:?}");
    }
}

#[test]
fn directional_light_on_a_material() {
    let img = Image2D::new(ImageFormat::Rgb, 4, 4).unwrap();
    let world = World::new();
    let cam = ortho_camera();
    world.add_child(&cam).unwrap();
    world.set_active_camera(&cam);
    let light = Light::new(); // directional along -Z: lights a +Z-facing quad fully
    world.add_child(&light).unwrap();
    let (vb, ib) = quad(1.0, 0, 0xFFFFFFFF);
    let a = Appearance::new();
    let mat = Material::new();
    a.set_material(Some(&mat));
    world.add_child(&Mesh::new(&vb, &ib, Some(&a))).unwrap();
    let mut g = Graphics3D::new();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    g.render_world(&world).unwrap();
    g.release_target();
    assert_eq!(g.light_count(), 1);
    assert_eq!(
        px(&img, 1, 1),
        [204, 204, 204],
        "diffuse 0.8, no scene ambient"
    );
    // An ambient light adds 0.2 · intensity; turning the directional light away removes it.
    light.set_orientation(180.0, 0.0, 1.0, 0.0).unwrap();
    let amb = Light::new();
    amb.set_mode(LightMode::Ambient);
    amb.set_intensity(0.5);
    world.add_child(&amb).unwrap();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    g.render_world(&world).unwrap();
    g.release_target();
    assert_eq!(px(&img, 1, 1), [26, 26, 26], "ambient 0.2 × 0.5");
}

#[test]
fn vertex_colors_scale_and_bias_against_the_reference() {
    // A perspective scene: a byte-position triangle fan with per-vertex colors.
    let va = VertexArray::new(4, 3, 1).unwrap();
    va.set_bytes(0, &[-100, -90, 0, 110, -80, -20, 90, 100, -60, -80, 70, 10])
        .unwrap();
    let ca = VertexArray::new(4, 4, 1).unwrap();
    ca.set_ubytes(
        0,
        &[
            255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 0, 255,
        ],
    )
    .unwrap();
    let vb = VertexBuffer::new();
    vb.set_positions(Some(&va), 2.0 / 255.0, Some(&[0.1, -0.05, 0.0]))
        .unwrap();
    vb.set_colors(Some(&ca)).unwrap();
    let ib = TriangleStripArray::new_explicit(&[0, 1, 3, 2], &[4])
        .unwrap()
        .as_index_buffer();
    let cam = Camera::new();
    cam.set_perspective(60.0, 1.25, 0.5, 20.0).unwrap();
    let mut cam_t = Transform::new();
    cam_t.post_translate(0.2, 0.1, 3.0);
    let mut model = Transform::new();
    model.post_rotate(30.0, 1.0, 1.0, 0.0).unwrap();
    let format = TargetFormat {
        color: ColorFormat::Rgba8888,
        depth: Some(DepthFormat::D24),
        stencil_bits: 0,
    };
    let mut g = Graphics3D::new();
    g.bind_target(Target::new(80, 64, format), true, RenderHints::empty())
        .unwrap();
    g.clear(None).unwrap();
    g.set_camera(Some(&cam), Some(&cam_t)).unwrap();
    let a = Appearance::new();
    let pm = PolygonMode::new();
    pm.set_culling(Culling::None);
    a.set_polygon_mode(Some(&pm));
    g.render_submesh(&vb, &ib, &a, Some(&model), -1).unwrap();
    let ours = g.release_target().unwrap();
    // The same draw described to the reference renderer directly, in floats.
    let mut s = gles_cm_core::RenderState::new(80, 64);
    let mut view = cam_t;
    view.invert().unwrap();
    view.post_multiply(&model);
    s.modelview = view.to_mat4();
    s.projection = cam.get_projection().unwrap().1.to_mat4();
    s.depth_test = Some(gles_cm_core::CompareFunc::LessEqual);
    let raw = [-100i8, -90, 0, 110, -80, -20, 90, 100, -60, -80, 70, 10];
    let pos: Vec<u8> = raw
        .chunks(3)
        .flat_map(|v| {
            let b = [0.1f32, -0.05, 0.0];
            (0..3).map(move |k| v[k] as f32 * (2.0 / 255.0) + b[k])
        })
        .flat_map(|f| f.to_ne_bytes())
        .collect();
    let cols = [
        255u8, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 0, 255,
    ];
    let idx = [0u16, 1, 3, 3, 1, 2];
    let mut call = gles_cm_core::DrawCall::new(
        gles_cm_core::Primitive::Triangles,
        gles_cm_core::Indices::U16(&idx),
        gles_cm_core::AttribArray {
            data: &pos,
            ty: gles_cm_core::ComponentType::Float,
            size: 3,
            stride: 12,
            normalized: false,
        },
    );
    call.color = gles_cm_core::AttribSource::Array(gles_cm_core::AttribArray {
        data: &cols,
        ty: gles_cm_core::ComponentType::UnsignedByte,
        size: 4,
        stride: 4,
        normalized: true,
    });
    let mut reference = Target::new(80, 64, format);
    reference.clear_color(reference.bounds(), [0.0; 4], [true; 4]);
    gles_cm_core::reference::render(&s, &call, &mut reference);
    let e = gles_cm_core::reference::compare(&ours, &reference);
    let covered = ours.color().iter().filter(|&&w| w != 0).count();
    assert!(covered > 500, "the fan covers the view: {covered}");
    assert!(e.over_one < 0.01 && e.mean < 0.5, "{e:?}");
}

#[test]
fn unscaled_sprite_is_pixel_exact() {
    let img = Image2D::new(ImageFormat::Rgb, 16, 16).unwrap();
    let pixels: Vec<u8> = (0..4 * 2).flat_map(|i| [i as u8 * 30, 0, 255]).collect();
    let simg = Image2D::with_pixels(ImageFormat::Rgb, 4, 2, &pixels).unwrap();
    let sprite = Sprite3D::new(false, &simg, Some(&Appearance::new()));
    let mut g = Graphics3D::new();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    g.clear(None).unwrap();
    g.set_camera(Some(&ortho_camera()), None).unwrap();
    g.render_node(&sprite, None).unwrap();
    g.release_target();
    // Centered at (8, 8): columns 6..10, rows 7..9, image pixel (i, j) at (6 + i, 7 + j).
    for y in 0..16 {
        for x in 0..16 {
            let want = if (6..10).contains(&x) && (7..9).contains(&y) {
                [((y - 7) * 4 + (x - 6)) as u8 * 30, 0, 255]
            } else {
                [0, 0, 0]
            };
            assert_eq!(px(&img, x, y), want, "({x},{y})");
        }
    }
    // A crop with a negative width mirrors; crop 0 draws nothing.
    sprite.set_crop(0, 0, -4, 2).unwrap();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    g.render_node(&sprite, None).unwrap();
    g.release_target();
    assert_eq!(px(&img, 6, 7), [90, 0, 255]);
    sprite.set_crop(0, 0, 0, 2).unwrap();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    g.clear(None).unwrap();
    g.render_node(&sprite, None).unwrap();
    g.release_target();
    assert_eq!(px(&img, 7, 7), [0, 0, 0]);
}

#[test]
fn background_image_border_and_repeat() {
    let target = Image2D::new(ImageFormat::Rgb, 4, 4).unwrap();
    let bimg = Image2D::with_pixels(ImageFormat::Rgb, 2, 1, &[10, 0, 0, 20, 0, 0]).unwrap();
    let bg = Background::new();
    bg.set_color(Color(0xFF0000FF));
    bg.set_image(Some(&bimg)).unwrap();
    bg.set_crop(0, 0, 4, 1).unwrap(); // twice the image width
    let mut g = Graphics3D::new();
    g.bind_image(&target, true, RenderHints::empty()).unwrap();
    g.clear(Some(&bg)).unwrap();
    g.release_target();
    assert_eq!(px(&target, 0, 0), [10, 0, 0]);
    assert_eq!(px(&target, 1, 3), [20, 0, 0]);
    assert_eq!(px(&target, 2, 0), [0, 0, 255], "BORDER: background color");
    bg.set_image_mode(ImageMode::Repeat, ImageMode::Border);
    g.bind_image(&target, true, RenderHints::empty()).unwrap();
    g.clear(Some(&bg)).unwrap();
    g.release_target();
    assert_eq!(px(&target, 2, 0), [10, 0, 0], "REPEAT wraps");
    assert_eq!(px(&target, 3, 2), [20, 0, 0]);
    // A format mismatch: IllegalArgument from clear, IllegalState from render(World).
    let rgba = Image2D::new(ImageFormat::Rgba, 2, 2).unwrap();
    bg.set_image(Some(&rgba)).unwrap();
    g.bind_image(&target, true, RenderHints::empty()).unwrap();
    assert!(is_iae(g.clear(Some(&bg))));
    let w = World::new();
    let c = Camera::new();
    w.add_child(&c).unwrap();
    w.set_active_camera(&c);
    w.set_background(Some(&bg));
    assert!(is_ise(g.render_world(&w)));
    g.release_target();
}

#[test]
fn graphics3d_errors_and_state() {
    let mut g = Graphics3D::new();
    let img = Image2D::new(ImageFormat::Rgb, 4, 4).unwrap();
    let (vb, ib) = quad(1.0, 0, 0xFFFFFFFF);
    let app = Appearance::new();
    assert!(is_ise(g.clear(None)), "no target");
    assert!(is_ise(g.render_submesh(&vb, &ib, &app, None, -1)));
    assert!(
        g.release_target().is_none(),
        "release without target is ignored"
    );
    let fixed = Image2D::with_pixels(ImageFormat::Rgb, 1, 1, &[0; 3]).unwrap();
    assert!(
        is_iae(g.bind_image(&fixed, true, RenderHints::empty())),
        "immutable"
    );
    assert!(is_iae(g.bind_image(
        &Image2D::new(ImageFormat::Alpha, 1, 1).unwrap(),
        true,
        RenderHints::empty()
    )));
    assert!(is_iae(RenderHints::from_raw(1)), "bit 0 is not a hint");
    assert!(is_iae(g.bind_image(
        &Image2D::new(ImageFormat::Rgb, MAX_VIEWPORT_DIMENSION + 1, 1).unwrap(),
        true,
        RenderHints::empty()
    )));
    g.bind_image(&img, true, RenderHints::DITHER | RenderHints::OVERWRITE)
        .unwrap();
    assert_eq!(g.hints().as_raw(), 20);
    assert!(g.is_depth_buffer_enabled());
    assert_eq!(g.target_image(), Some(img.clone()));
    assert!(
        is_ise(g.bind_image(&img, true, RenderHints::empty())),
        "already bound"
    );
    assert!(
        is_ise(Graphics3D::new().bind_image(&img, true, RenderHints::empty())),
        "bound elsewhere"
    );
    assert!(
        is_ise(g.render_submesh(&vb, &ib, &app, None, -1)),
        "no camera"
    );
    assert!(is_iae(g.set_viewport(0, 0, 0, 1)));
    assert!(is_iae(g.set_viewport(0, 0, MAX_VIEWPORT_DIMENSION + 1, 1)));
    g.set_viewport(-5, -5, 10, 10).unwrap();
    assert!(is_iae(g.set_depth_range(-0.1, 1.0)));
    g.set_depth_range(1.0, 0.0).unwrap();
    assert_eq!(g.depth_range(), [1.0, 0.0]);
    let mut singular = Transform::new();
    singular.post_scale(0.0, 1.0, 1.0);
    assert!(is_ae(g.set_camera(Some(&Camera::new()), Some(&singular))));
    g.set_camera(Some(&Camera::new()), None).unwrap();
    assert!(is_iae(g.render_node(&Camera::new(), None)));
    assert!(is_iae(g.render_node(&Light::new(), None)));
    // Deferred checks: no positions, an index past the vertex count.
    assert!(is_ise(g.render_submesh(
        &VertexBuffer::new(),
        &ib,
        &app,
        None,
        -1
    )));
    let big = TriangleStripArray::new_implicit(2, &[3])
        .unwrap()
        .as_index_buffer();
    assert!(is_ise(g.render_submesh(&vb, &big, &app, None, -1)));
    // Out of scope: not drawn, not validated.
    let cam = Camera::new();
    cam.set_scope(1);
    g.set_camera(Some(&cam), None).unwrap();
    assert!(g.render_submesh(&vb, &big, &app, None, 2).is_ok());
    // Lights.
    let l = Light::new();
    assert_eq!(g.add_light(&l, None), 0);
    assert_eq!(
        g.add_light(&l, Some(&singular)),
        1,
        "light transforms may be singular"
    );
    g.set_light(0, None, None).unwrap();
    assert_eq!(g.light_count(), 2);
    assert!(g.light(0).unwrap().is_none());
    assert!(matches!(
        g.set_light(2, None, None),
        Err(Error::IndexOutOfBounds(_))
    ));
    assert!(matches!(g.light(2), Err(Error::IndexOutOfBounds(_))));
    g.reset_lights();
    assert_eq!(g.light_count(), 0);
    g.release_target();
    assert!(g.target_image().is_none());
    // World checks.
    let w = World::new();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    assert!(is_ise(g.render_world(&w)), "no active camera");
    let c = Camera::new();
    w.set_active_camera(&c);
    assert!(is_ise(g.render_world(&w)), "camera outside the world");
    w.add_child(&c).unwrap();
    c.set_scale(0.0, 1.0, 1.0);
    assert!(is_ae(g.render_world(&w)), "singular camera transform");
    c.set_scale(1.0, 1.0, 1.0);
    // near == far: nothing rendered, nothing validated.
    c.set_parallel(1.0, 1.0, 2.0, 2.0).unwrap();
    w.add_child(&Mesh::new(&VertexBuffer::new(), &ib, Some(&app)))
        .unwrap();
    assert!(g.render_world(&w).is_ok());
    c.set_parallel(1.0, 1.0, 1.0, 2.0).unwrap();
    assert!(is_ise(g.render_world(&w)), "a mesh without positions");
    g.release_target();
    let props = Graphics3D::get_properties();
    assert_eq!(props["maxLights"], Property::Int(8));
    assert!(props.len() >= 14);
}

#[test]
fn picking_meshes() {
    let w = World::new();
    let cam = Camera::new();
    cam.set_perspective(60.0, 1.0, 1.0, 11.0).unwrap();
    cam.set_translation(0.0, 0.0, 1.0);
    w.add_child(&cam).unwrap();
    let (vb, ib) = quad(1.0, 0, 0xFFFFFFFF);
    let tc = VertexArray::new(4, 2, 1).unwrap();
    tc.set_bytes(0, &[0, 1, 1, 1, 1, 0, 0, 0]).unwrap();
    vb.set_tex_coords(0, Some(&tc), 1.0, None).unwrap();
    let mesh = Mesh::new(&vb, &ib, Some(&Appearance::new()));
    mesh.set_translation(0.0, 0.0, -4.0);
    let g = Group::new();
    g.add_child(&mesh).unwrap();
    w.add_child(&g).unwrap();
    let ri = w
        .pick_ray(-1, [0.5, 0.0, 0.0], [0.0, 0.0, -2.0])
        .unwrap()
        .expect("hit");
    assert!(
        (ri.distance() - 2.0).abs() < 1e-5,
        "in units of the ray length"
    );
    assert_eq!(ri.intersected(), Some(mesh.as_node()));
    assert_eq!(ri.submesh_index(), 0);
    assert!((ri.normal_z() - 1.0).abs() < 1e-4);
    assert!((ri.texture_s(0).unwrap() - 0.75).abs() < 1e-4);
    assert!((ri.texture_t(0).unwrap() - 0.5).abs() < 1e-4);
    assert_eq!(ri.ray(), [0.5, 0.0, 0.0, 0.0, 0.0, -2.0]);
    assert!(matches!(
        ri.texture_s(NUM_TEXTURE_UNITS),
        Err(Error::IndexOutOfBounds(_))
    ));
    assert!(
        w.pick_ray(-1, [2.0, 0.0, 0.0], [0.0, 0.0, -1.0])
            .unwrap()
            .is_none(),
        "miss"
    );
    assert!(
        w.pick_ray(-1, [0.0, 0.0, -8.0], [0.0, 0.0, 1.0])
            .unwrap()
            .is_none(),
        "back face culled"
    );
    assert!(is_iae(w.pick_ray(-1, [0.0; 3], [0.0; 3])));
    // Camera variant: the ray starts on the near plane; the far plane is at distance 1.
    let ri = w.pick(-1, 0.5, 0.5, &cam).unwrap().expect("hit");
    assert!((ri.distance() - 0.4).abs() < 1e-4, "{}", ri.distance());
    // Scope and picking enable.
    assert!(w.pick(2, 0.5, 0.5, &cam).unwrap().is_some());
    mesh.set_scope(1);
    assert!(w.pick(2, 0.5, 0.5, &cam).unwrap().is_none());
    mesh.set_scope(-1);
    g.set_picking_enable(false);
    assert!(w.pick(-1, 0.5, 0.5, &cam).unwrap().is_none());
    g.set_picking_enable(true);
    // Picking from a subgroup: the ray is in that group's coordinates.
    let ri = g.pick(-1, 0.5, 0.5, &cam).unwrap().unwrap();
    assert!((ri.ray()[2] - 0.0).abs() < 1e-4);
    assert!(
        is_ise(w.pick(-1, 0.5, 0.5, &Camera::new())),
        "camera in another graph"
    );
    // Invalid data is IllegalState.
    mesh.set_translation(0.0, 0.0, 0.0);
    let bad = Mesh::new(&VertexBuffer::new(), &ib, Some(&Appearance::new()));
    g.add_child(&bad).unwrap();
    assert!(is_ise(w.pick(-1, 0.5, 0.5, &cam)));
}

#[test]
fn picking_scaled_sprites_checks_alpha() {
    let w = World::new();
    let cam = Camera::new();
    cam.set_parallel(2.0, 1.0, -10.0, 10.0).unwrap();
    w.add_child(&cam).unwrap();
    // Left column transparent, right column opaque.
    let img =
        Image2D::with_pixels(ImageFormat::Rgba, 2, 1, &[0, 0, 0, 0, 255, 255, 255, 255]).unwrap();
    let app = Appearance::new();
    let cm = CompositingMode::new();
    cm.set_alpha_threshold(0.5).unwrap();
    app.set_compositing_mode(Some(&cm));
    let sprite = Sprite3D::new(true, &img, Some(&app));
    w.add_child(&sprite).unwrap();
    // The sprite covers viewport x in [0.25, 0.75).
    assert!(
        w.pick(-1, 0.4, 0.5, &cam).unwrap().is_none(),
        "transparent pixel"
    );
    assert!(w.pick(-1, 0.8, 0.5, &cam).unwrap().is_none(), "outside");
    let ri = w.pick(-1, 0.6, 0.5, &cam).unwrap().expect("opaque pixel");
    assert_eq!(ri.intersected(), Some(sprite.as_node()));
    assert!((ri.distance() - 0.5).abs() < 1e-4);
    assert!(
        w.pick_ray(-1, [0.25, 0.0, 5.0], [0.0, 0.0, -1.0])
            .unwrap()
            .is_none(),
        "ray variant ignores sprites"
    );
}

// ---------------------------------------------------------------------------------------
// Texturing, lighting and fog through the core; scene-graph culling and caching.

/// An 8 × 8 RGB image whose pixel (x, y) is (32x, 32y, 255 − 16(x + y)).
fn test_image(mutable: bool) -> Image2D {
    let pixels: Vec<u8> = (0..64)
        .flat_map(|i| {
            let (x, y) = (i % 8, i / 8);
            [(32 * x) as u8, (32 * y) as u8, (255 - 16 * (x + y)) as u8]
        })
        .collect();
    if mutable {
        let img = Image2D::new(ImageFormat::Rgb, 8, 8).unwrap();
        img.set(0, 0, 8, 8, &pixels).unwrap();
        img
    } else {
        Image2D::with_pixels(ImageFormat::Rgb, 8, 8, &pixels).unwrap()
    }
}

fn texel(x: usize, y: usize) -> [u8; 3] {
    [(32 * x) as u8, (32 * y) as u8, (255 - 16 * (x + y)) as u8]
}

/// `quad(1.0, 0, argb)` covering the whole parallel view, with texture coordinates that
/// put the image's top-left texel at the view's top-left pixel (t grows downward).
fn tex_quad(argb: u32, scale: f32, bias: Option<&[f32]>) -> (VertexBuffer, IndexBuffer) {
    let (vb, ib) = quad(1.0, 0, argb);
    let ta = VertexArray::new(4, 2, 1).unwrap();
    ta.set_bytes(0, &[0, 1, 1, 1, 1, 0, 0, 0]).unwrap();
    vb.set_tex_coords(0, Some(&ta), scale, bias).unwrap();
    (vb, ib)
}

/// Renders one submesh into a fresh `w` × `w` RGB image over a black clear.
fn render_one(
    w: i32,
    vb: &VertexBuffer,
    ib: &IndexBuffer,
    a: &Appearance,
    t: Option<&Transform>,
) -> Image2D {
    let img = Image2D::new(ImageFormat::Rgb, w, w).unwrap();
    let mut g = Graphics3D::new();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    g.clear(None).unwrap();
    g.set_camera(Some(&ortho_camera()), None).unwrap();
    g.render_submesh(vb, ib, a, t, -1).unwrap();
    g.release_target();
    img
}

fn near(p: [u8; 3], want: [f32; 3], tol: f32, what: &str) {
    for c in 0..3 {
        assert!(
            (p[c] as f32 - want[c]).abs() <= tol,
            "{what}: {p:?} vs {want:?}"
        );
    }
}

#[test]
fn textured_quad_nearest_one_to_one_is_exact() {
    let (vb, ib) = tex_quad(0xFFFFFFFF, 1.0, None);
    let tex = Texture2D::new(&test_image(false)).unwrap();
    tex.set_blending(TextureFunction::Replace);
    let a = Appearance::new();
    a.set_texture(0, Some(&tex)).unwrap();
    let img = render_one(8, &vb, &ib, &a, None);
    for y in 0..8 {
        for x in 0..8 {
            assert_eq!(px(&img, x, y), texel(x, y), "({x},{y})");
        }
    }
}

#[test]
fn texture_modulate_with_vertex_colors_and_the_other_functions() {
    let (vb, ib) = tex_quad(0xFFFFFFFF, 1.0, None);
    let ca = VertexArray::new(4, 3, 1).unwrap();
    ca.set_ubytes(0, &[128, 255, 64].repeat(4)).unwrap();
    vb.set_colors(Some(&ca)).unwrap();
    let tex = Texture2D::new(&test_image(false)).unwrap();
    let a = Appearance::new();
    a.set_texture(0, Some(&tex)).unwrap();
    let cf = [128.0f32, 255.0, 64.0];
    // MODULATE (the default): Cf · Ct.
    let img = render_one(8, &vb, &ib, &a, None);
    for (x, y) in [(0, 0), (3, 5), (7, 7), (6, 1)] {
        let t = texel(x, y);
        let want = [0, 1, 2].map(|c| cf[c] * t[c] as f32 / 255.0);
        near(px(&img, x, y), want, 1.0, "modulate");
    }
    // ADD: Cf + Ct, saturated. BLEND: Cf(1 − Ct) + Cc·Ct. DECAL on RGB: Ct.
    tex.set_blending(TextureFunction::Add);
    let img = render_one(8, &vb, &ib, &a, None);
    let t = texel(3, 5);
    near(
        px(&img, 3, 5),
        [0, 1, 2].map(|c| (cf[c] + t[c] as f32).min(255.0)),
        1.0,
        "add",
    );
    tex.set_blending(TextureFunction::Blend);
    tex.set_blend_color(Color(0x00FF0080));
    let img = render_one(8, &vb, &ib, &a, None);
    let cc = [255.0f32, 0.0, 128.0];
    near(
        px(&img, 3, 5),
        [0, 1, 2].map(|c| {
            let ct = t[c] as f32 / 255.0;
            cf[c] * (1.0 - ct) + cc[c] * ct
        }),
        1.0,
        "blend",
    );
    tex.set_blending(TextureFunction::Decal);
    let img = render_one(8, &vb, &ib, &a, None);
    assert_eq!(px(&img, 3, 5), t, "decal");
}

#[test]
fn texture_transform_follows_the_coordinate_scale_and_bias() {
    // Coordinates scaled by 0.5 and biased by 0.5 in s, then the Texture2D's scale (2, 1, 1):
    // s'' = 2 · (0.5 s + 0.5) = s + 1, which REPEAT maps back onto s. The other order
    // (texture transform first) would give s + 0.5: half the image off.
    let (vb, ib) = tex_quad(0xFFFFFFFF, 0.5, Some(&[0.5, 0.0]));
    let tex = Texture2D::new(&test_image(false)).unwrap();
    tex.set_blending(TextureFunction::Replace);
    tex.set_scale(2.0, 2.0, 1.0);
    let a = Appearance::new();
    a.set_texture(0, Some(&tex)).unwrap();
    let img = render_one(8, &vb, &ib, &a, None);
    for y in 0..8 {
        for x in 0..8 {
            assert_eq!(px(&img, x, y), texel(x, y), "({x},{y})");
        }
    }
    // A translation by a quarter: texel x + 2 (mod 8), t unchanged; and with CLAMP the
    // right quarter repeats the last column.
    tex.set_translation(0.25, 0.0, 0.0);
    let img = render_one(8, &vb, &ib, &a, None);
    for x in 0..8 {
        assert_eq!(px(&img, x, 3), texel((x + 2) % 8, 3), "repeat x = {x}");
    }
    let (vb1, ib1) = tex_quad(0xFFFFFFFF, 1.0, None);
    tex.set_scale(1.0, 1.0, 1.0);
    tex.set_wrapping(TextureWrap::Clamp, TextureWrap::Repeat);
    let img = render_one(8, &vb1, &ib1, &a, None);
    for x in 0..8 {
        assert_eq!(px(&img, x, 3), texel((x + 2).min(7), 3), "clamp x = {x}");
    }
}

#[test]
fn mipmaps_are_generated_when_the_level_filter_asks() {
    // A 2 × 2 checker of black and white, drawn into a 1 × 1 viewport: the base level
    // gives one of its texels; a mipmap level filter gives the 1 × 1 level, the mean.
    let img = Image2D::with_pixels(ImageFormat::Luminance, 2, 2, &[0, 255, 255, 0]).unwrap();
    let tex = Texture2D::new(&img).unwrap();
    tex.set_blending(TextureFunction::Replace);
    let a = Appearance::new();
    a.set_texture(0, Some(&tex)).unwrap();
    let (vb, ib) = tex_quad(0xFFFFFFFF, 1.0, None);
    let base = render_one(1, &vb, &ib, &a, None);
    assert!(
        [0, 255].contains(&px(&base, 0, 0)[0]),
        "{:?}",
        px(&base, 0, 0)
    );
    tex.set_filtering(TextureFilter::Nearest, TextureFilter::Nearest)
        .unwrap();
    let mip = render_one(1, &vb, &ib, &a, None);
    assert_eq!(px(&mip, 0, 0), [128, 128, 128]);
}

#[test]
fn a_mutable_texture_image_is_seen_when_edited_and_converted_only_then() {
    let image = test_image(true);
    let tex = Texture2D::new(&image).unwrap();
    tex.set_blending(TextureFunction::Replace);
    let a = Appearance::new();
    a.set_texture(0, Some(&tex)).unwrap();
    let (vb, ib) = tex_quad(0xFFFFFFFF, 1.0, None);
    let img = Image2D::new(ImageFormat::Rgb, 8, 8).unwrap();
    let mut g = Graphics3D::new();
    g.set_camera(Some(&ortho_camera()), None).unwrap();
    for (edit, uploads) in [(false, 1), (false, 1), (true, 2)] {
        if edit {
            image.set(1, 2, 1, 1, &[9, 8, 7]).unwrap();
        }
        g.bind_image(&img, true, RenderHints::empty()).unwrap();
        g.render_submesh(&vb, &ib, &a, None, -1).unwrap();
        g.release_target();
        assert_eq!(g.stats().texture_uploads, uploads);
    }
    assert_eq!(px(&img, 1, 2), [9, 8, 7]);
    assert_eq!(px(&img, 2, 2), texel(2, 2));
}

/// A Material with the given colors (ARGB) and shininess.
fn material(ambient: u32, diffuse: u32, specular: u32, emissive: u32, shininess: f32) -> Material {
    let m = Material::new();
    m.set_color(MaterialColor::AMBIENT, Color(ambient)).unwrap();
    m.set_color(MaterialColor::DIFFUSE, Color(diffuse)).unwrap();
    m.set_color(MaterialColor::SPECULAR, Color(specular))
        .unwrap();
    m.set_color(MaterialColor::EMISSIVE, Color(emissive))
        .unwrap();
    m.set_shininess(shininess).unwrap();
    m
}

/// Renders the +Z-facing `quad(1.0, 0, …)` lit by `lights` (light-to-world transforms)
/// into a 4 × 4 image and returns pixel (1, 1).
fn lit_pixel(a: &Appearance, lights: &[(&Light, Transform)], t: Option<&Transform>) -> [u8; 3] {
    let (vb, ib) = quad(1.0, 0, 0xFFFFFFFF);
    let img = Image2D::new(ImageFormat::Rgb, 4, 4).unwrap();
    let mut g = Graphics3D::new();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    g.clear(None).unwrap();
    g.set_camera(Some(&ortho_camera()), None).unwrap();
    for (l, lt) in lights {
        g.add_light(l, Some(lt));
    }
    g.render_submesh(&vb, &ib, a, t, -1).unwrap();
    g.release_target();
    px(&img, 1, 1)
}

#[test]
fn lit_quad_against_hand_computed_values() {
    let a = Appearance::new();
    // Emissive (16/255), diffuse (0.4, 0.2, 0), specular 128/255, shininess 2.
    a.set_material(Some(&material(0, 0xFF663300, 0x00808080, 0x00101010, 2.0)));
    // A directional light of intensity 0.8 turned 60° about Y: the direction to it is
    // (sin 60°, 0, cos 60°), so n·L = 0.5 and n·h = cos 30° (viewer at infinity).
    let sun = Light::new();
    sun.set_intensity(0.8);
    let mut turn = Transform::new();
    turn.post_rotate(60.0, 0.0, 1.0, 0.0).unwrap();
    let p = lit_pixel(&a, &[(&sun, turn)], None);
    let (ndl, ndh) = (0.5f32, 30f32.to_radians().cos());
    let want = [0.4f32, 0.2, 0.0]
        .map(|d| 255.0 * (16.0 / 255.0 + 0.8 * (d * ndl + 128.0 / 255.0 * ndh * ndh)));
    near(p, want, 1.0, "directional with specular");

    // OMNI at (0, 0, 2) with attenuation (1, 0, 0.25): every corner of the quad is √6
    // away, so the quad is uniform: 0.8 · (2/√6) / (1 + 0.25 · 6).
    let b = Appearance::new();
    b.set_material(Some(&Material::new()));
    let omni = Light::new();
    omni.set_mode(LightMode::Omni);
    omni.set_attenuation(1.0, 0.0, 0.25).unwrap();
    let mut at = Transform::new();
    at.post_translate(0.0, 0.0, 2.0);
    let k = 2.0 / 6f32.sqrt();
    near(
        lit_pixel(&b, &[(&omni, at)], None),
        [255.0 * 0.8 * k / 2.5; 3],
        1.0,
        "omni",
    );
    // SPOT there, pointing down −Z: the corners are 35.3° off axis. A 30° cone leaves the
    // quad dark; a 40° cone with exponent 2 gives 0.8 · (2/√6) · (2/√6)².
    let spot = Light::new();
    spot.set_mode(LightMode::Spot);
    spot.set_spot_angle(30.0).unwrap();
    near(
        lit_pixel(&b, &[(&spot, at)], None),
        [0.0; 3],
        0.0,
        "spot outside",
    );
    spot.set_spot_angle(40.0).unwrap();
    spot.set_spot_exponent(2.0).unwrap();
    near(
        lit_pixel(&b, &[(&spot, at)], None),
        [255.0 * 0.8 * k * k * k; 3],
        1.0,
        "spot inside",
    );
    // AMBIENT: ambient material (0.2) × color × intensity; colors scale per channel.
    let amb = Light::new();
    amb.set_mode(LightMode::Ambient);
    amb.set_color(Color(0x00FF8000));
    amb.set_intensity(2.0);
    near(
        lit_pixel(&b, &[(&amb, Transform::new())], None),
        [255.0 * 0.2 * 2.0, 255.0 * 0.2 * (128.0 / 255.0) * 2.0, 0.0],
        1.0,
        "ambient",
    );
    // A light whose scope shares no bit with the mesh's (immediate mode: the scope
    // argument) does not light it.
    let (vb, ib) = quad(1.0, 0, 0xFFFFFFFF);
    let img = Image2D::new(ImageFormat::Rgb, 4, 4).unwrap();
    let mut g = Graphics3D::new();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    g.set_camera(Some(&ortho_camera()), None).unwrap();
    sun.set_scope(2);
    g.add_light(&sun, None);
    g.render_submesh(&vb, &ib, &b, None, 1).unwrap();
    g.release_target();
    assert_eq!(px(&img, 1, 1), [0, 0, 0], "out of the light's scope");
}

#[test]
fn vertex_color_tracking_and_the_alpha_factor_with_a_material() {
    let sun = Light::new();
    // Tracking: the vertex (default) color is the ambient and diffuse color.
    let (vb, ib) = quad(1.0, 0, 0x80FF8040);
    let m = Material::new();
    m.set_vertex_color_tracking_enable(true);
    let a = Appearance::new();
    a.set_material(Some(&m));
    let mut g = Graphics3D::new();
    let img = Image2D::new(ImageFormat::Rgb, 4, 4).unwrap();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    g.clear(None).unwrap();
    g.set_camera(Some(&ortho_camera()), None).unwrap();
    g.add_light(&sun, None);
    g.render_submesh(&vb, &ib, &a, None, -1).unwrap();
    g.release_target();
    assert_eq!(px(&img, 1, 1), [255, 128, 64]);
    // The alpha factor multiplies the lit alpha: the diffuse alpha without tracking...
    let bg = Background::new();
    bg.set_color(Color(0xFF0000FF));
    let cm = CompositingMode::new();
    cm.set_blending(Blending::Alpha);
    for tracking in [false, true] {
        let m = material(0, 0xFFFFFFFF, 0, 0, 0.0);
        m.set_vertex_color_tracking_enable(tracking);
        let a = Appearance::new();
        a.set_material(Some(&m));
        a.set_compositing_mode(Some(&cm));
        // ... and the tracked vertex alpha (0x80) with it.
        let (vb, ib) = quad(1.0, 0, 0x80FFFFFF);
        let mesh = Mesh::new(&vb, &ib, Some(&a));
        mesh.set_alpha_factor(0.5).unwrap();
        g.bind_image(&img, true, RenderHints::empty()).unwrap();
        g.clear(Some(&bg)).unwrap();
        g.render_node(&mesh, None).unwrap();
        g.release_target();
        let alpha = if tracking { 0.5 * 128.0 / 255.0 } else { 0.5 };
        near(
            px(&img, 1, 1),
            [
                255.0 * alpha,
                255.0 * alpha,
                255.0 * (1.0 - alpha) + 255.0 * alpha,
            ],
            1.0,
            "alpha factor",
        );
    }
}

#[test]
fn two_sided_lighting_lights_the_back_with_the_reversed_normal() {
    // The quad turned 180° about Y shows its back, whose normal points away from the light.
    let mut back = Transform::new();
    back.post_rotate(180.0, 0.0, 1.0, 0.0).unwrap();
    let sun = Light::new();
    let a = Appearance::new();
    a.set_material(Some(&material(0, 0xFFCCCCCC, 0, 0x00101010, 0.0)));
    let pm = PolygonMode::new();
    pm.set_culling(Culling::None);
    a.set_polygon_mode(Some(&pm));
    assert_eq!(
        lit_pixel(&a, &[(&sun, Transform::new())], Some(&back)),
        [16, 16, 16],
        "one-sided: the back takes the front's color, lit from behind: emissive only"
    );
    pm.set_two_sided_lighting_enable(true);
    assert_eq!(
        lit_pixel(&a, &[(&sun, Transform::new())], Some(&back)),
        [220, 220, 220],
        "two-sided: 16/255 + 0.8"
    );
    // The front is unchanged by the flag.
    assert_eq!(
        lit_pixel(&a, &[(&sun, Transform::new())], None),
        [220, 220, 220]
    );
}

#[test]
fn negative_position_scale_does_not_turn_the_normals() {
    // Positions scaled by −1 mirror the quad (so it shows its back: cull none), but
    // normals carry no scale and still face the light.
    let (vb, ib) = quad(1.0, 0, 0xFFFFFFFF);
    let (va, sb) = vb.get_positions();
    vb.set_positions(va.as_ref(), -1.0, Some(&sb[1..4]))
        .unwrap();
    let a = Appearance::new();
    a.set_material(Some(&Material::new()));
    let pm = PolygonMode::new();
    pm.set_culling(Culling::None);
    a.set_polygon_mode(Some(&pm));
    let img = Image2D::new(ImageFormat::Rgb, 4, 4).unwrap();
    let mut g = Graphics3D::new();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    g.set_camera(Some(&ortho_camera()), None).unwrap();
    g.add_light(&Light::new(), None);
    g.render_submesh(&vb, &ib, &a, None, -1).unwrap();
    g.release_target();
    assert_eq!(px(&img, 1, 1), [204, 204, 204]);
}

#[test]
fn linear_and_exponential_fog() {
    // A red quad 5 units in front of the camera, blue fog.
    let mut t = Transform::new();
    t.post_translate(0.0, 0.0, -5.0);
    let (vb, ib) = quad(1.0, 0, 0xFFFF0000);
    let fog = Fog::new();
    fog.set_color(Color(0x000000FF));
    fog.set_linear(0.0, 10.0);
    let a = Appearance::new();
    a.set_fog(Some(&fog));
    // LINEAR: f = (10 − 5)/10.
    let img = render_one(4, &vb, &ib, &a, Some(&t));
    near(px(&img, 1, 1), [127.5, 0.0, 127.5], 1.0, "linear");
    fog.set_linear(6.0, 8.0);
    let img = render_one(4, &vb, &ib, &a, Some(&t));
    assert_eq!(px(&img, 1, 1), [255, 0, 0], "nearer than near: no fog");
    // EXPONENTIAL: f = e^(−0.2 · 5).
    fog.set_mode(FogMode::Exponential);
    fog.set_density(0.2).unwrap();
    let img = render_one(4, &vb, &ib, &a, Some(&t));
    let f = (-1.0f32).exp();
    near(
        px(&img, 1, 1),
        [255.0 * f, 0.0, 255.0 * (1.0 - f)],
        1.0,
        "exp",
    );
}

/// A world: a parallel camera, and `n` quads in a row along x at 3-unit steps.
fn row_world(n: usize) -> (World, Vec<Mesh>) {
    let world = World::new();
    let cam = ortho_camera();
    world.add_child(&cam).unwrap();
    world.set_active_camera(&cam);
    let meshes: Vec<Mesh> = (0..n)
        .map(|i| {
            let (vb, ib) = quad(0.5, 0, 0xFF00FF00 | (i as u32 * 40) << 16);
            let m = Mesh::new(&vb, &ib, Some(&Appearance::new()));
            m.set_translation(3.0 * i as f32, 0.0, 0.0);
            world.add_child(&m).unwrap();
            m
        })
        .collect();
    (world, meshes)
}

#[test]
fn meshes_outside_the_frustum_are_culled_before_their_vertices_are_transformed() {
    let (world, meshes) = row_world(3);
    let render = |g: &mut Graphics3D| {
        let img = Image2D::new(ImageFormat::Rgb, 8, 8).unwrap();
        g.reset_stats();
        g.bind_image(&img, true, RenderHints::empty()).unwrap();
        g.render_world(&world).unwrap();
        g.release_target();
        (img.pixels(), g.stats())
    };
    let mut g = Graphics3D::new();
    let (on, s) = render(&mut g);
    // Only the first quad is in view: the others' vertices never reach the core.
    assert_eq!((s.submeshes_drawn, s.submeshes_culled), (1, 2));
    assert_eq!(s.vertices_transformed, 4);
    g.set_culling_enable(false);
    let (off, s) = render(&mut g);
    assert_eq!((s.submeshes_drawn, s.submeshes_culled), (3, 0));
    assert_eq!(s.vertices_transformed, 12);
    assert_eq!(on, off, "culling changes no pixel");
    // Moving a mesh (its cached world transform is dirty) brings it back into view, and
    // a mesh straddling the frustum's edge is drawn.
    g.set_culling_enable(true);
    meshes[2].set_translation(0.5, 0.5, 0.0);
    meshes[1].set_translation(1.2, 0.0, 0.0);
    let (on, s) = render(&mut g);
    assert_eq!((s.submeshes_drawn, s.submeshes_culled), (3, 0));
    g.set_culling_enable(false);
    assert_eq!(render(&mut g).0, on);
    // A parent's move reaches its children's cached world transforms.
    let grp = Group::new();
    world.remove_child(&meshes[0]);
    grp.add_child(&meshes[0]).unwrap();
    world.add_child(&grp).unwrap();
    grp.set_translation(10.0, 0.0, 0.0);
    g.set_culling_enable(true);
    let s = render(&mut g).1;
    assert_eq!(s.submeshes_culled, 1);
    grp.set_translation(0.0, 0.0, 0.0);
    let s = render(&mut g).1;
    assert_eq!(s.submeshes_culled, 0);
    // Vertex data changed in place: the cached bounds follow it.
    let far = VertexArray::new(4, 3, 2).unwrap();
    far.set_shorts(0, &[100, 100, 0, 101, 100, 0, 101, 101, 0, 100, 101, 0])
        .unwrap();
    let (vb, ib) = quad(1.0, 0, 0xFFFFFFFF);
    vb.set_positions(Some(&far), 1.0, None).unwrap();
    let mut g = Graphics3D::new();
    let img = Image2D::new(ImageFormat::Rgb, 4, 4).unwrap();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    g.set_camera(Some(&ortho_camera()), None).unwrap();
    let a = Appearance::new();
    g.render_submesh(&vb, &ib, &a, None, -1).unwrap();
    assert_eq!(g.stats().submeshes_culled, 1);
    far.set_shorts(0, &[-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0])
        .unwrap();
    g.render_submesh(&vb, &ib, &a, None, -1).unwrap();
    assert_eq!(g.stats().submeshes_culled, 1);
    assert_eq!(g.stats().submeshes_drawn, 1);
    g.release_target();
}

#[test]
fn perspective_textured_fogged_scene_against_the_reference() {
    use gles_cm_core::texture::{BaseFormat, Image, MagFilter, MinFilter, Sampler, Wrap};
    // A receding textured quad with vertex colors and linear fog, trilinear filtering with
    // generated mipmaps. Tolerance: under 2 % of the pixels more than one step off and a
    // mean error under 0.5 step (f32 against f64, per-pixel λ).
    let ta = VertexArray::new(4, 2, 1).unwrap();
    ta.set_bytes(0, &[0, 4, 4, 4, 4, 0, 0, 0]).unwrap();
    let (vb, ib) = quad(1.0, 0, 0xFFFFFFFF);
    vb.set_tex_coords(0, Some(&ta), 1.0, None).unwrap();
    let ca = VertexArray::new(4, 4, 1).unwrap();
    let cols = [
        255u8, 255, 255, 255, 255, 200, 100, 255, 100, 255, 200, 255, 200, 200, 255, 255,
    ];
    ca.set_ubytes(0, &cols).unwrap();
    vb.set_colors(Some(&ca)).unwrap();
    let image = test_image(false);
    let tex = Texture2D::new(&image).unwrap();
    tex.set_filtering(TextureFilter::Linear, TextureFilter::Linear)
        .unwrap();
    tex.set_translation(0.1, 0.0, 0.0);
    let fog = Fog::new();
    fog.set_linear(1.0, 6.0);
    fog.set_color(Color(0x00406080));
    let a = Appearance::new();
    a.set_texture(0, Some(&tex)).unwrap();
    a.set_fog(Some(&fog));
    let cam = Camera::new();
    cam.set_perspective(60.0, 1.25, 0.5, 20.0).unwrap();
    let mut cam_t = Transform::new();
    cam_t.post_translate(0.0, 0.5, 1.5);
    let mut model = Transform::new();
    model.post_rotate(-70.0, 1.0, 0.0, 0.0).unwrap();
    model.post_scale(2.0, 3.0, 1.0);
    let format = TargetFormat {
        color: ColorFormat::Rgba8888,
        depth: Some(DepthFormat::D24),
        stencil_bits: 0,
    };
    let mut g = Graphics3D::new();
    g.bind_target(Target::new(80, 64, format), true, RenderHints::empty())
        .unwrap();
    g.clear(None).unwrap();
    g.set_camera(Some(&cam), Some(&cam_t)).unwrap();
    g.render_submesh(&vb, &ib, &a, Some(&model), -1).unwrap();
    let ours = g.release_target().unwrap();

    // The same draw described to the reference renderer directly.
    let mut s = gles_cm_core::RenderState::new(80, 64);
    let mut view = cam_t;
    view.invert().unwrap();
    view.post_multiply(&model);
    s.modelview = view.to_mat4();
    s.projection = cam.get_projection().unwrap().1.to_mat4();
    s.depth_test = Some(gles_cm_core::CompareFunc::LessEqual);
    s.cull = Some(gles_cm_core::CullFace::Back);
    s.texture_matrices[0] = tex.get_composite_transform().to_mat4();
    let texels: Vec<u32> = (0..64)
        .map(|i| {
            let [r, g, b] = texel(i % 8, i / 8);
            u32::from_le_bytes([r, g, b, 255])
        })
        .collect();
    let mut levels = vec![std::sync::Arc::new(Image {
        width: 8,
        height: 8,
        format: BaseFormat::Rgb,
        texels,
    })];
    while levels.last().unwrap().width > 1 {
        let next = levels.last().unwrap().half();
        levels.push(std::sync::Arc::new(next));
    }
    s.textures[0] = Some(gles_cm_core::texenv::TextureUnit {
        sampler: std::sync::Arc::new(Sampler::new(
            levels,
            MinFilter::LinearMipmapLinear,
            MagFilter::Linear,
            Wrap::Repeat,
            Wrap::Repeat,
        )),
        env: gles_cm_core::texenv::TexEnv::default(),
        coord_replace: false,
    });
    s.fog = Some(gles_cm_core::texenv::Fog {
        mode: gles_cm_core::texenv::FogMode::Linear,
        density: 1.0,
        start: 1.0,
        end: 6.0,
        color: [64.0 / 255.0, 96.0 / 255.0, 128.0 / 255.0, 1.0],
        quality: gles_cm_core::state::Quality::Balanced,
    });
    let pos: Vec<u8> = [-1i16, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0]
        .iter()
        .flat_map(|&v| (v as f32).to_ne_bytes())
        .collect();
    let tc: Vec<u8> = [0f32, 4.0, 4.0, 4.0, 4.0, 0.0, 0.0, 0.0]
        .iter()
        .flat_map(|v| v.to_ne_bytes())
        .collect();
    let idx = [0u16, 1, 3, 3, 1, 2];
    let mut call = gles_cm_core::DrawCall::new(
        gles_cm_core::Primitive::Triangles,
        gles_cm_core::Indices::U16(&idx),
        gles_cm_core::AttribArray {
            data: &pos,
            ty: gles_cm_core::ComponentType::Float,
            size: 3,
            stride: 12,
            normalized: false,
        },
    );
    call.color = gles_cm_core::AttribSource::Array(gles_cm_core::AttribArray {
        data: &cols,
        ty: gles_cm_core::ComponentType::UnsignedByte,
        size: 4,
        stride: 4,
        normalized: true,
    });
    call.texcoord[0] = gles_cm_core::AttribSource::Array(gles_cm_core::AttribArray {
        data: &tc,
        ty: gles_cm_core::ComponentType::Float,
        size: 2,
        stride: 8,
        normalized: false,
    });
    let mut base = Target::new(80, 64, format);
    base.clear_color(base.bounds(), [0.0; 4], [true; 4]);
    let mut reference = base.clone();
    gles_cm_core::reference::render(&s, &call, &mut reference);
    let e = gles_cm_core::reference::compare(&ours, &reference);
    let covered = ours.color().iter().filter(|&&w| w != 0).count();
    assert!(
        covered > 1000,
        "the quad covers much of the view: {covered}"
    );
    assert!(e.over_one < 0.02 && e.mean < 0.5, "{e:?}");
    // And the core's fast path on the same input agrees with ours exactly.
    let (fast, _, _) = gles_cm_core::reference::measure(&s, &[call], &base, 1);
    assert_eq!(fast.color(), ours.color());
}
