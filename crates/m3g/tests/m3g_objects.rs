//! M3G object model: each class's defaults, semantics and errors.

use m3g::*;

fn is_iae<T: std::fmt::Debug>(r: Result<T>) -> bool {
    matches!(r, Err(Error::IllegalArgument(_)))
}
fn is_ioobe<T: std::fmt::Debug>(r: Result<T>) -> bool {
    matches!(r, Err(Error::IndexOutOfBounds(_)))
}
fn is_ise<T: std::fmt::Debug>(r: Result<T>) -> bool {
    matches!(r, Err(Error::IllegalState(_)))
}
fn is_ae<T: std::fmt::Debug>(r: Result<T>) -> bool {
    matches!(r, Err(Error::Arithmetic(_)))
}
fn close(a: &[f32], b: &[f32]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-4)
}

#[test]
fn handles_are_references() {
    let g = Group::new();
    let h = g.clone();
    h.set_user_id(7);
    assert_eq!(g.user_id(), 7);
    assert_eq!(g, h);
    assert_ne!(g, Group::new());
    let o: Object3D = g.clone().into();
    assert_eq!(o.downcast::<Group>(), Some(g.clone()));
    assert!(o.downcast::<Mesh>().is_none());
    let w = World::new();
    assert!(
        Object3D::from(&w).downcast::<Group>().is_some(),
        "a World is a Group"
    );
    assert!(g.as_node().downcast::<Group>().is_some());
}

#[test]
fn transform_operations() {
    let mut t = Transform::new();
    assert_eq!(t.get(), Transform::new().get());
    let m: Vec<f32> = (0..16).map(|i| i as f32).collect();
    t.set(&m).unwrap();
    assert_eq!(t.get().to_vec(), m, "row-major round trip");
    assert!(is_iae(t.set(&m[..15])));
    t.transpose();
    assert_eq!(t.get()[1], 4.0);
    let mut s = Transform::new();
    assert!(is_ae(t.invert()), "singular matrix");
    s.post_translate(1.0, 2.0, 3.0);
    s.post_scale(2.0, 2.0, 2.0);
    let mut v = [1.0, 1.0, 1.0, 1.0];
    s.transform(&mut v).unwrap();
    assert_eq!(v, [3.0, 4.0, 5.0, 1.0]);
    assert!(is_iae(s.transform(&mut [0.0; 3])));
    let mut inv = s;
    inv.invert().unwrap();
    inv.post_multiply(&s);
    assert!(close(&inv.get(), &Transform::new().get()));
    let mut r = Transform::new();
    r.post_rotate(90.0, 0.0, 0.0, 2.0).unwrap();
    let mut x = [1.0, 0.0, 0.0, 0.0];
    r.transform(&mut x).unwrap();
    assert!(close(&x, &[0.0, 1.0, 0.0, 0.0]));
    assert!(is_iae(r.post_rotate(10.0, 0.0, 0.0, 0.0)));
    assert!(r.post_rotate(0.0, 0.0, 0.0, 0.0).is_ok());
    let mut q = Transform::new();
    assert!(is_iae(q.post_rotate_quat(0.0, 0.0, 0.0, 0.0)));
    q.post_rotate_quat(0.0, 0.0, 0.0, 5.0).unwrap();
    assert!(
        close(&q.get(), &Transform::new().get()),
        "zero vector part = identity"
    );
    q.post_rotate_quat(0.0, 0.0, 1.0, 1.0).unwrap(); // 90° about z, unnormalized
    assert!(close(&q.get(), &r.get()));
    let va = VertexArray::new(2, 2, 1).unwrap();
    va.set_bytes(0, &[1, 2, 3, 4]).unwrap();
    let out = s.transform_vertex_array(&va, true).unwrap();
    assert_eq!(out, vec![3.0, 6.0, 3.0, 1.0, 7.0, 10.0, 3.0, 1.0]);
    let va4 = VertexArray::new(1, 4, 1).unwrap();
    assert!(is_iae(s.transform_vertex_array(&va4, false)));
}

#[test]
fn transformable_components() {
    let n = Group::new();
    assert_eq!(n.get_scale(), [1.0; 3]);
    assert_eq!(n.get_orientation()[0], 0.0);
    n.set_translation(1.0, 2.0, 3.0);
    n.translate(1.0, 0.0, 0.0);
    assert_eq!(n.get_translation(), [2.0, 2.0, 3.0]);
    n.set_scale(2.0, 3.0, 4.0);
    n.scale(0.5, 1.0, 1.0);
    assert_eq!(n.get_scale(), [1.0, 3.0, 4.0]);
    n.set_orientation(90.0, 0.0, 0.0, 3.0).unwrap();
    let o = n.get_orientation();
    assert!(close(&o, &[90.0, 0.0, 0.0, 1.0]), "{o:?}");
    assert!(is_iae(n.set_orientation(5.0, 0.0, 0.0, 0.0)));
    n.post_rotate(90.0, 0.0, 0.0, 1.0).unwrap();
    assert!((n.get_orientation()[0] - 180.0).abs() < 1e-3);
    n.pre_rotate(-180.0, 0.0, 0.0, 1.0).unwrap();
    assert!(n.get_orientation()[0].abs() < 1e-3);
    let mut m = Transform::new();
    m.set(&[
        1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0,
    ])
    .unwrap();
    assert!(
        is_iae(n.set_transform(Some(&m))),
        "a node needs the bottom row 0 0 0 1"
    );
    let img = Image2D::new(ImageFormat::Rgb, 4, 4).unwrap();
    let tex = Texture2D::new(&img).unwrap();
    tex.set_transform(Some(&m)).unwrap();
    assert_eq!(tex.get_transform().get(), m.get());
    // Composite = T R S M.
    let g = Group::new();
    g.set_translation(5.0, 0.0, 0.0);
    g.set_scale(2.0, 2.0, 2.0);
    let mut p = [1.0, 0.0, 0.0, 1.0];
    g.get_composite_transform().transform(&mut p).unwrap();
    assert_eq!(p, [7.0, 0.0, 0.0, 1.0]);
    g.set_transform(None).unwrap();
}

#[test]
fn node_flags_and_errors() {
    let g = Group::new();
    assert!(g.is_rendering_enabled() && g.is_picking_enabled());
    assert_eq!(g.scope(), -1);
    assert_eq!(g.alpha_factor(), 1.0);
    assert!(is_iae(g.set_alpha_factor(1.5)));
    assert!(is_iae(g.set_alpha_factor(-0.1)));
    g.set_alpha_factor(0.25).unwrap();
    g.set_scope(3);
    assert_eq!(g.scope(), 3);
    assert_eq!(
        g.alignment_target(AlignTarget::ZAxis).unwrap(),
        AlignTarget::None
    );
    assert!(is_iae(g.alignment_target(AlignTarget::XAxis)));
    assert!(is_iae(AlignTarget::from_raw(999)));
    assert!(is_iae(g.set_alignment(
        None,
        AlignTarget::Origin,
        None,
        AlignTarget::Origin
    )));
    assert!(is_iae(g.set_alignment(
        Some(&g.as_node()),
        AlignTarget::Origin,
        None,
        AlignTarget::None
    )));
}

#[test]
fn group_children_rules() {
    let a = Group::new();
    let b = Group::new();
    let c = Group::new();
    a.add_child(&b).unwrap();
    b.add_child(&c).unwrap();
    assert_eq!(c.parent().unwrap(), b.as_node());
    assert!(is_iae(a.add_child(&a)), "self");
    assert!(is_iae(c.add_child(&a)), "ancestor");
    assert!(is_iae(a.add_child(&c)), "other parent");
    assert!(is_iae(a.add_child(&World::new())), "world");
    a.add_child(&b).unwrap();
    assert_eq!(a.child_count(), 1, "adding an existing child is a no-op");
    assert!(is_ioobe(a.child(1)));
    a.remove_child(&c); // not a child: ignored
    assert_eq!(b.child_count(), 1);
    b.remove_child(&c);
    assert!(c.parent().is_none());
    a.add_child(&c).unwrap();
    assert_eq!(a.child_count(), 2);
}

#[test]
fn get_transform_to_paths() {
    let w = World::new();
    let a = Group::new();
    let b = Group::new();
    w.add_child(&a).unwrap();
    w.add_child(&b).unwrap();
    a.set_translation(1.0, 0.0, 0.0);
    b.set_scale(2.0, 2.0, 2.0);
    let t = a.get_transform_to(&b).unwrap().unwrap();
    let mut p = [0.0, 0.0, 0.0, 1.0];
    t.transform(&mut p).unwrap();
    assert_eq!(p, [0.5, 0.0, 0.0, 1.0]);
    assert!(
        a.get_transform_to(&Group::new()).unwrap().is_none(),
        "no path"
    );
    b.set_scale(0.0, 1.0, 1.0);
    assert!(is_ae(a.get_transform_to(&b)), "singular");
}

#[test]
fn object3d_find_references_duplicate() {
    let vb = VertexBuffer::new();
    let pos = VertexArray::new(3, 3, 2).unwrap();
    vb.set_positions(Some(&pos), 1.0, None).unwrap();
    let ib = TriangleStripArray::new_implicit(0, &[3]).unwrap();
    let app = Appearance::new();
    let mesh = Mesh::new(&vb, &ib, Some(&app));
    app.set_user_id(42);
    let g = Group::new();
    g.add_child(&mesh).unwrap();
    let refs = g.get_references();
    assert_eq!(refs, vec![Object3D::from(&mesh)]);
    assert_eq!(mesh.get_references().len(), 3);
    assert_eq!(g.find(42), Some(Object3D::from(&app)));
    assert_eq!(g.find(43), None);
    // Duplicate: nodes deep, components shared, parent null, references remapped.
    let other = Group::new();
    g.add_child(&other).unwrap();
    mesh.set_alignment(
        Some(&other.as_node()),
        AlignTarget::Origin,
        None,
        AlignTarget::None,
    )
    .unwrap();
    mesh.set_user_object(Some(std::rc::Rc::new(5u32)));
    let w = World::new();
    w.add_child(&g).unwrap();
    let d = g.duplicate();
    assert!(d.parent().is_none());
    assert_ne!(d, g);
    let dm = d.child(0).unwrap().downcast::<Mesh>().unwrap();
    assert_ne!(dm, mesh);
    assert_eq!(dm.vertex_buffer(), vb, "vertex buffer shared");
    assert_eq!(dm.appearance(0).unwrap(), Some(app.clone()));
    assert_eq!(
        dm.alignment_reference(AlignTarget::ZAxis).unwrap(),
        Some(d.child(1).unwrap()),
        "alignment remapped to the copy"
    );
    assert!(std::rc::Rc::ptr_eq(
        &dm.user_object().unwrap(),
        &mesh.user_object().unwrap()
    ));
    let a2 = app.duplicate();
    assert_ne!(a2, app);
    assert_eq!(a2.user_id(), 42);
    assert_eq!(g.animate(0).unwrap(), i32::MAX);
    assert!(is_ioobe(g.animation_track(0)));
}

#[test]
fn camera_projection() {
    let c = Camera::new();
    let (k, m) = c.get_projection().unwrap();
    assert_eq!(k, Projection::Generic);
    assert_eq!(m.get(), Transform::new().get());
    assert_eq!(c.get_projection_params(), (Projection::Generic, None));
    assert!(is_iae(c.set_perspective(0.0, 1.0, 1.0, 2.0)));
    assert!(is_iae(c.set_perspective(180.0, 1.0, 1.0, 2.0)));
    assert!(is_iae(c.set_perspective(60.0, 1.0, -1.0, 2.0)));
    assert!(is_iae(c.set_parallel(0.0, 1.0, 1.0, 2.0)));
    c.set_parallel(2.0, 1.0, -5.0, -5.0).unwrap();
    assert!(is_ae(c.get_projection()), "near == far");
    c.set_perspective(90.0, 2.0, 1.0, 3.0).unwrap();
    assert_eq!(
        c.get_projection_params(),
        (Projection::Perspective, Some([90.0, 2.0, 1.0, 3.0]))
    );
    let m = c.get_projection().unwrap().1.get();
    assert!(close(
        &m,
        &[0.5, 0., 0., 0., 0., 1., 0., 0., 0., 0., -2., -3., 0., 0., -1., 0.]
    ));
    c.set_parallel(4.0, 0.5, 0.0, 2.0).unwrap();
    let m = c.get_projection().unwrap().1.get();
    assert!(close(
        &m,
        &[1.0, 0., 0., 0., 0., 0.5, 0., 0., 0., 0., -1., -1., 0., 0., 0., 1.]
    ));
}

#[test]
fn light_defaults_and_errors() {
    let l = Light::new();
    assert_eq!(l.mode(), LightMode::Directional);
    assert_eq!(l.color(), Color(0xFFFFFF));
    assert_eq!(l.intensity(), 1.0);
    assert_eq!(l.spot_angle(), 45.0);
    assert_eq!(l.spot_exponent(), 0.0);
    assert_eq!(l.constant_attenuation(), 1.0);
    assert!(is_iae(LightMode::from_raw(127)));
    assert_eq!(LightMode::from_raw(131).unwrap(), LightMode::Spot);
    assert!(is_iae(l.set_spot_angle(91.0)));
    assert!(is_iae(l.set_spot_exponent(129.0)));
    assert!(is_iae(l.set_attenuation(0.0, 0.0, 0.0)));
    assert!(is_iae(l.set_attenuation(1.0, -1.0, 0.0)));
    l.set_attenuation(0.0, 1.0, 0.0).unwrap();
    assert_eq!(l.linear_attenuation(), 1.0);
    l.set_color(Color(0x7F123456));
    assert_eq!(l.color(), Color(0x123456));
    l.set_intensity(-2.0);
    assert_eq!(l.intensity(), -2.0);
}

#[test]
fn appearance_components() {
    let a = Appearance::new();
    assert_eq!(a.layer(), 0);
    assert!(is_ioobe(a.set_layer(64)));
    assert!(is_ioobe(a.set_layer(-64)));
    a.set_layer(-63).unwrap();
    assert!(is_ioobe(a.set_texture(NUM_TEXTURE_UNITS, None)));
    assert!(is_ioobe(a.texture(NUM_TEXTURE_UNITS)));
    let cm = CompositingMode::new();
    assert_eq!(cm.blending(), Blending::Replace);
    assert!(cm.is_depth_test_enabled() && cm.is_depth_write_enabled());
    assert!(cm.is_color_write_enabled() && cm.is_alpha_write_enabled());
    assert!(is_iae(Blending::from_raw(63)));
    assert!(is_iae(Blending::from_raw(69)));
    assert!(is_iae(cm.set_alpha_threshold(1.1)));
    cm.set_depth_offset(-1.0, 2.0);
    assert_eq!(
        (cm.depth_offset_factor(), cm.depth_offset_units()),
        (-1.0, 2.0)
    );
    a.set_compositing_mode(Some(&cm));
    assert_eq!(a.compositing_mode(), Some(cm));
    let pm = PolygonMode::new();
    assert_eq!(
        (pm.culling(), pm.winding(), pm.shading()),
        (Culling::Back, Winding::Ccw, Shading::Smooth)
    );
    assert!(is_iae(Culling::from_raw(163)));
    assert!(is_iae(Winding::from_raw(167)));
    assert!(is_iae(Shading::from_raw(163)));
    pm.set_local_camera_lighting_enable(true);
    assert!(
        pm.is_local_camera_lighting_enabled(),
        "hints read back as set"
    );
    let m = Material::new();
    assert_eq!(m.color(MaterialColor::AMBIENT).unwrap(), Color(0x333333));
    assert_eq!(m.color(MaterialColor::DIFFUSE).unwrap(), Color(0xFFCCCCCC));
    assert!(is_iae(m.set_color(MaterialColor::empty(), Color::BLACK)));
    assert!(is_iae(MaterialColor::from_raw(1)));
    assert!(is_iae(
        m.color(MaterialColor::AMBIENT | MaterialColor::DIFFUSE)
    ));
    m.set_color(
        MaterialColor::AMBIENT | MaterialColor::SPECULAR,
        Color(0x80102030),
    )
    .unwrap();
    assert_eq!(
        m.color(MaterialColor::SPECULAR).unwrap(),
        Color(0x102030),
        "alpha only for diffuse"
    );
    assert!(is_iae(m.set_shininess(128.5)));
    let f = Fog::new();
    assert_eq!(
        (f.mode(), f.density(), f.near_distance(), f.far_distance()),
        (FogMode::Linear, 1.0, 0.0, 1.0)
    );
    assert!(is_iae(FogMode::from_raw(82)));
    assert!(is_iae(f.set_density(-1.0)));
    f.set_mode(FogMode::Exponential);
    f.set_linear(5.0, 2.0);
    assert_eq!(f.mode(), FogMode::Exponential, "set_linear keeps the mode");
    f.set_color(Color::WHITE);
    assert_eq!(f.color(), Color(0xFFFFFF));
}

#[test]
fn texture_and_background() {
    let img = Image2D::new(ImageFormat::Rgba, 8, 4).unwrap();
    let t = Texture2D::new(&img).unwrap();
    assert_eq!(
        (t.wrapping_s(), t.wrapping_t()),
        (TextureWrap::Repeat, TextureWrap::Repeat)
    );
    assert_eq!(
        (t.level_filter(), t.image_filter()),
        (TextureFilter::BaseLevel, TextureFilter::Nearest)
    );
    assert_eq!(t.blending(), TextureFunction::Modulate);
    assert!(is_iae(Texture2D::new(
        &Image2D::new(ImageFormat::Rgb, 6, 4).unwrap()
    )));
    assert!(is_iae(
        t.set_image(&Image2D::new(ImageFormat::Rgb, 4096, 1).unwrap())
    ));
    assert!(is_iae(
        t.set_filtering(TextureFilter::Linear, TextureFilter::BaseLevel)
    ));
    assert!(is_iae(TextureWrap::from_raw(242)));
    assert!(is_iae(TextureFunction::from_raw(229)));
    t.set_blend_color(Color(0x12345678));
    assert_eq!(t.blend_color(), Color(0x345678));
    let bg = Background::new();
    assert!(bg.is_color_clear_enabled() && bg.is_depth_clear_enabled());
    assert_eq!(bg.color(), Color::TRANSPARENT);
    assert!(is_iae(bg.set_image(Some(
        &Image2D::new(ImageFormat::Alpha, 2, 2).unwrap()
    ))));
    bg.set_image(Some(&img)).unwrap();
    assert_eq!(
        (bg.crop_x(), bg.crop_y(), bg.crop_width(), bg.crop_height()),
        (0, 0, 8, 4)
    );
    assert!(is_iae(bg.set_crop(0, 0, -1, 1)));
    bg.set_crop(-3, -4, 0, 1).unwrap();
    assert!(is_iae(ImageMode::from_raw(34)));
}

#[test]
fn image2d_formats() {
    assert!(is_iae(Image2D::new(ImageFormat::Rgb, 0, 1)));
    assert!(is_iae(ImageFormat::from_raw(101)));
    let m = Image2D::new(ImageFormat::LuminanceAlpha, 2, 1).unwrap();
    assert!(m.is_mutable());
    assert_eq!(m.pixels(), vec![255; 4], "opaque white");
    m.set(1, 0, 1, 1, &[7, 8]).unwrap();
    assert_eq!(m.pixels(), vec![255, 255, 7, 8]);
    assert!(is_iae(m.set(1, 0, 2, 1, &[0; 4])));
    assert!(is_iae(m.set(0, 0, 1, 1, &[0])));
    let i = Image2D::with_pixels(ImageFormat::Rgb, 1, 1, &[1, 2, 3]).unwrap();
    assert!(!i.is_mutable());
    assert!(is_ise(i.set(0, 0, 1, 1, &[0; 3])));
    assert!(is_iae(Image2D::with_pixels(
        ImageFormat::Rgb,
        2,
        1,
        &[0; 5]
    )));
    let p = Image2D::with_palette(ImageFormat::Rgb, 2, 1, &[1, 0], &[9, 9, 9, 4, 5, 6]).unwrap();
    assert_eq!(p.pixels(), vec![4, 5, 6, 9, 9, 9]);
    assert!(is_iae(Image2D::with_palette(
        ImageFormat::Rgb,
        2,
        1,
        &[0],
        &[0; 3]
    )));
    assert!(is_iae(Image2D::with_palette(
        ImageFormat::Rgb,
        1,
        1,
        &[0],
        &[0; 5]
    )));
    assert!(
        Image2D::with_palette(ImageFormat::Rgb, 1, 1, &[0], &[0; 800]).is_ok(),
        "literal rule"
    );
}

#[test]
fn vertex_arrays_and_buffers() {
    assert!(is_iae(VertexArray::new(0, 3, 1)));
    assert!(is_iae(VertexArray::new(65536, 3, 1)));
    assert!(is_iae(VertexArray::new(1, 5, 1)));
    assert!(is_iae(VertexArray::new(1, 3, 3)));
    let va = VertexArray::new(4, 3, 2).unwrap();
    assert!(is_ise(va.set_bytes(0, &[0; 3])));
    va.set_shorts(0, &[]).unwrap(); // no vertices: nothing to write
    assert!(is_iae(va.set_shorts(0, &[0; 5])), "not whole vertices");
    assert!(is_ioobe(va.set_shorts(3, &[0; 6])));
    assert!(is_ioobe(va.set_shorts(4, &[0; 3])));
    assert!(is_ioobe(va.get_shorts(2, 3)));
    va.set_shorts(1, &[-5, 6, 7]).unwrap();
    assert_eq!(va.get_shorts(1, 1).unwrap(), vec![-5, 6, 7]);
    assert_eq!(
        (va.vertex_count(), va.component_count(), va.component_type()),
        (4, 3, 2)
    );
    let vb = VertexBuffer::new();
    assert_eq!(vb.vertex_count(), 0);
    assert_eq!(vb.default_color(), Color(0xFFFFFFFF));
    vb.set_positions(Some(&va), 0.5, Some(&[1.0, 2.0, 3.0]))
        .unwrap();
    assert_eq!(vb.get_positions().1, [0.5, 1.0, 2.0, 3.0]);
    assert!(is_iae(vb.set_positions(Some(&va), 1.0, Some(&[1.0]))));
    let two = VertexArray::new(4, 2, 1).unwrap();
    assert!(is_iae(vb.set_positions(Some(&two), 1.0, None)));
    assert!(is_iae(vb.set_normals(Some(&two))));
    assert!(is_iae(vb.set_colors(Some(&va)),), "colors must be bytes");
    let other = VertexArray::new(5, 3, 1).unwrap();
    assert!(is_iae(vb.set_colors(Some(&other))), "count mismatch");
    vb.set_positions(Some(&other), 1.0, None).unwrap(); // replacing the only array
    assert_eq!(vb.vertex_count(), 5);
    assert!(is_ioobe(vb.set_tex_coords(
        NUM_TEXTURE_UNITS,
        None,
        1.0,
        None
    )));
    let tc = VertexArray::new(5, 2, 2).unwrap();
    assert!(is_iae(vb.set_tex_coords(0, Some(&tc), 1.0, Some(&[1.0]))));
    vb.set_tex_coords(0, Some(&tc), 2.0, Some(&[1.0, 2.0]))
        .unwrap();
    assert_eq!(vb.get_tex_coords(0).unwrap().1, vec![2.0, 1.0, 2.0]);
    let tc4 = VertexArray::new(5, 4, 2).unwrap();
    assert!(is_iae(vb.set_tex_coords(1, Some(&tc4), 1.0, None)));
}

#[test]
fn triangle_strips() {
    let t = TriangleStripArray::new_explicit(&[2, 0, 1, 4], &[4]).unwrap();
    assert_eq!(t.indices(), vec![2, 0, 1, 1, 0, 4]);
    assert_eq!(t.index_count(), 6);
    let t = TriangleStripArray::new_implicit(10, &[3, 4]).unwrap();
    assert_eq!(t.indices(), vec![10, 11, 12, 13, 14, 15, 15, 14, 16]);
    assert!(is_iae(TriangleStripArray::new_implicit(0, &[])));
    assert!(is_iae(TriangleStripArray::new_implicit(0, &[2])));
    assert!(is_ioobe(TriangleStripArray::new_implicit(65534, &[3])));
    assert!(is_iae(TriangleStripArray::new_explicit(&[0, 1], &[3])));
    assert!(is_ioobe(TriangleStripArray::new_implicit(usize::MAX, &[3])));
}

#[test]
fn mesh_and_sprite() {
    let vb = VertexBuffer::new();
    let ib = TriangleStripArray::new_implicit(0, &[3])
        .as_ref()
        .unwrap()
        .as_index_buffer();
    assert!(is_iae(Mesh::with_submeshes(&vb, &[], None)));
    assert!(is_iae(Mesh::with_submeshes(
        &vb,
        &[ib.clone(), ib.clone()],
        Some(&[None])
    )));
    let m = Mesh::with_submeshes(&vb, &[ib.clone(), ib.clone()], None).unwrap();
    assert_eq!(m.submesh_count(), 2);
    assert!(is_ioobe(m.appearance(2)));
    assert!(is_ioobe(m.set_appearance(2, None)));
    assert!(is_ioobe(m.index_buffer(5)));
    let img = Image2D::new(ImageFormat::Rgba, 2000, 3).unwrap();
    let s = Sprite3D::new(true, &img, None);
    assert!(s.is_scaled());
    assert_eq!(
        (s.crop_x(), s.crop_y(), s.crop_width(), s.crop_height()),
        (0, 0, MAX_SPRITE_CROP_DIMENSION, 3)
    );
    assert!(is_iae(s.set_crop(
        0,
        0,
        -(MAX_SPRITE_CROP_DIMENSION + 1),
        1
    )));
    s.set_crop(-5, 2, -3, 4).unwrap();
    assert_eq!(s.crop_width(), -3);
}

#[test]
fn world_camera_background() {
    let w = World::new();
    assert!(w.active_camera().is_none() && w.background().is_none());
    let c = Camera::new();
    w.set_active_camera(&c);
    assert_eq!(w.active_camera(), Some(c));
    let bg = Background::new();
    w.set_background(Some(&bg));
    assert_eq!(w.background(), Some(bg));
}

#[test]
fn alignment() {
    let w = World::new();
    let target = Group::new();
    let n = Group::new();
    w.add_child(&target).unwrap();
    w.add_child(&n).unwrap();
    target.set_translation(0.0, 0.0, -10.0);
    n.set_translation(0.0, 0.0, 0.0);
    // Point +Z at the target's origin: a half turn about some axis.
    n.set_alignment(
        Some(&target.as_node()),
        AlignTarget::Origin,
        None,
        AlignTarget::None,
    )
    .unwrap();
    n.align(None).unwrap();
    let mut z = [0.0, 0.0, 1.0, 0.0];
    n.get_composite_transform().transform(&mut z).unwrap();
    assert!(close(&z, &[0.0, 0.0, -1.0, 0.0]), "{z:?}");
    // Z and Y: face +X with up = world Y.
    target.set_translation(5.0, 0.0, 0.0);
    n.set_alignment(
        Some(&target.as_node()),
        AlignTarget::Origin,
        Some(&w.as_node()),
        AlignTarget::YAxis,
    )
    .unwrap();
    n.align(None).unwrap();
    let t = n.get_composite_transform();
    let (mut z, mut y) = ([0.0, 0.0, 1.0, 0.0], [0.0, 1.0, 0.0, 0.0]);
    t.transform(&mut z).unwrap();
    t.transform(&mut y).unwrap();
    assert!(close(&z, &[1.0, 0.0, 0.0, 0.0]), "{z:?}");
    assert!(close(&y, &[0.0, 1.0, 0.0, 0.0]), "{y:?}");
    // Aligning to a descendant (or self through null) is IllegalState.
    let child = Group::new();
    n.add_child(&child).unwrap();
    n.set_alignment(
        Some(&child.as_node()),
        AlignTarget::Origin,
        None,
        AlignTarget::None,
    )
    .unwrap();
    assert!(is_ise(n.align(None)));
    n.set_alignment(None, AlignTarget::Origin, None, AlignTarget::None)
        .unwrap();
    assert!(is_ise(n.align(None)), "null reference resolves to n itself");
    // A reference in another graph.
    assert!(is_iae(n.align(Some(&Group::new().as_node()))));
}
