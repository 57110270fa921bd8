//! A .m3g writer (beyond the specification): serializes an object graph to a valid file,
//! uncompressed or zlib-compressed, that the [`Loader`] reads back.
//!
//! Every object reachable from the given roots (through `getReferences`, plus node alignment
//! references) is written once, leaf first, in one object section after the header section.
//! Representation choices, all lossless for what the API can observe:
//! - index buffers are written as explicit strips of 3 (the object model keeps triangles);
//! - palettized images are written expanded (the object model keeps expanded pixels);
//! - keyframes are written as Float32 (encoding 0), vertex arrays raw (encoding 0);
//! - orientation is written as angle and axis, from the stored quaternion;
//! - user parameters are written when the user object is a
//!   [`UserParameters`] map (as the Loader makes it);
//! - −0.0 and denormal floats are written as +0.0 (the format forbids them).
//!
//! A graph the format cannot hold is refused with an [`Error::Write`]: a reference cycle (a node
//! aligned to one of its ancestors), a NaN or infinite value, or a gap in an Appearance's
//! texture units or a VertexBuffer's texture-coordinate units.

use std::collections::HashMap;

use glam::Mat4;

use super::deform::MeshExt;
use super::loader::{adler32, UserParameters, FILE_IDENTIFIER};
use super::object::{tf, Handle, Inner, Kind, ObjRef};
use super::*;

/// Writer options.
#[derive(Clone, Debug, Default)]
pub struct WriteOptions {
    /// Compress the object section with zlib (compression scheme 1).
    pub compress: bool,
    /// The header's AuthoringField.
    pub authoring: String,
}

/// Serializes the graph reachable from `roots` (uncompressed when `compress` is false).
pub fn save(roots: &[Object3D], compress: bool) -> Result<Vec<u8>> {
    save_with(
        roots,
        &WriteOptions {
            compress,
            authoring: String::new(),
        },
    )
}

type Key = *const std::cell::RefCell<Inner>;

/// Serializes with options.
pub fn save_with(roots: &[Object3D], opts: &WriteOptions) -> Result<Vec<u8>> {
    // Leaf-first order.
    let mut order: Vec<ObjRef> = Vec::new();
    let mut state: HashMap<Key, bool> = HashMap::new(); // false = in progress, true = done
    for r in roots {
        visit(r.raw(), &mut order, &mut state)?;
    }
    if order.is_empty() {
        return Err(Error::Write("no objects to write".into()));
    }
    let index: HashMap<Key, u32> = order
        .iter()
        .enumerate()
        .map(|(i, r)| (std::rc::Rc::as_ptr(r), i as u32 + 2))
        .collect();
    let mut objects = Vec::new();
    for r in &order {
        let mut w = W {
            b: Vec::new(),
            index: &index,
            class: r.borrow().class_name(),
        };
        let ty = write_object(&mut w, r)?;
        objects.push(ty);
        objects.extend_from_slice(&(w.b.len() as u32).to_le_bytes());
        objects.extend_from_slice(&w.b);
    }
    let scene = section(&objects, opts.compress);
    let header_len = 11 + opts.authoring.len() + 1;
    let total = 12 + 13 + 5 + header_len + scene.len();
    let mut h = Vec::with_capacity(5 + header_len);
    h.push(0);
    h.extend_from_slice(&(header_len as u32).to_le_bytes());
    h.extend_from_slice(&[1, 0, 0]);
    h.extend_from_slice(&(total as u32).to_le_bytes());
    h.extend_from_slice(&(total as u32).to_le_bytes());
    h.extend_from_slice(opts.authoring.as_bytes());
    h.push(0);
    let mut out = Vec::with_capacity(total);
    out.extend_from_slice(&FILE_IDENTIFIER);
    out.extend_from_slice(&section(&h, false));
    out.extend_from_slice(&scene);
    debug_assert_eq!(out.len(), total);
    Ok(out)
}

fn section(data: &[u8], compress: bool) -> Vec<u8> {
    let stored = if compress {
        miniz_oxide::deflate::compress_to_vec_zlib(data, 9)
    } else {
        data.to_vec()
    };
    let mut s = Vec::with_capacity(stored.len() + 13);
    s.push(compress as u8);
    s.extend_from_slice(&(stored.len() as u32 + 13).to_le_bytes());
    s.extend_from_slice(&(data.len() as u32).to_le_bytes());
    s.extend_from_slice(&stored);
    let sum = adler32(&s);
    s.extend_from_slice(&sum.to_le_bytes());
    s
}

/// What an object must come after: its references and its alignment references.
fn dependencies(r: &ObjRef) -> Vec<ObjRef> {
    let i = r.borrow();
    let mut v: Vec<ObjRef> = i.references().into_iter().map(|o| o.0).collect();
    if let Some(n) = &i.node {
        v.extend(n.alignment.iter().filter_map(|a| a.1.as_ref()?.upgrade()));
    }
    v
}

/// Appends `r` and everything it depends on to `order`, dependencies first (a post-order
/// depth-first walk; `state` is `false` while an object is on the path, `true` once
/// written). A heap stack, not recursion: a graph can nest groups deeper than the thread's
/// stack allows.
fn visit(r: &ObjRef, order: &mut Vec<ObjRef>, state: &mut HashMap<Key, bool>) -> Result<()> {
    if state.get(&std::rc::Rc::as_ptr(r)) == Some(&true) {
        return Ok(());
    }
    state.insert(std::rc::Rc::as_ptr(r), false);
    // Each entry: an object on the path and its dependencies not yet visited, last first.
    let mut stack: Vec<(ObjRef, Vec<ObjRef>)> = vec![(r.clone(), rev(dependencies(r)))];
    while let Some((obj, deps)) = stack.last_mut() {
        let Some(d) = deps.pop() else {
            let obj = obj.clone();
            stack.pop();
            state.insert(std::rc::Rc::as_ptr(&obj), true);
            order.push(obj);
            continue;
        };
        let k = std::rc::Rc::as_ptr(&d);
        match state.get(&k) {
            Some(true) => {}
            Some(false) => {
                return Err(Error::Write(format!(
                    "a reference cycle through a {} (a node aligned to its ancestor?)",
                    d.borrow().class_name()
                )))
            }
            None => {
                state.insert(k, false);
                let dd = rev(dependencies(&d));
                stack.push((d, dd));
            }
        }
    }
    Ok(())
}

fn rev(mut v: Vec<ObjRef>) -> Vec<ObjRef> {
    v.reverse();
    v
}

struct W<'a> {
    b: Vec<u8>,
    index: &'a HashMap<Key, u32>,
    class: &'static str,
}

type WResult = Result<()>;

impl W<'_> {
    fn u8(&mut self, v: u8) {
        self.b.push(v);
    }
    fn bool(&mut self, v: bool) {
        self.b.push(v as u8);
    }
    fn u16(&mut self, v: u16) {
        self.b.extend_from_slice(&v.to_le_bytes());
    }
    fn u32(&mut self, v: u32) {
        self.b.extend_from_slice(&v.to_le_bytes());
    }
    fn i32(&mut self, v: i32) {
        self.u32(v as u32);
    }
    fn f32(&mut self, v: f32) -> WResult {
        if !v.is_finite() {
            return Err(Error::Write(format!("a {} holds {v}", self.class)));
        }
        let v = if v == 0.0 || v.is_subnormal() { 0.0 } else { v };
        self.u32(v.to_bits());
        Ok(())
    }
    fn f32s(&mut self, v: &[f32]) -> WResult {
        v.iter().try_for_each(|&x| self.f32(x))
    }
    fn rgb(&mut self, argb: u32) {
        self.b
            .extend_from_slice(&[(argb >> 16) as u8, (argb >> 8) as u8, argb as u8]);
    }
    fn rgba(&mut self, argb: u32) {
        self.b.extend_from_slice(&[
            (argb >> 16) as u8,
            (argb >> 8) as u8,
            argb as u8,
            (argb >> 24) as u8,
        ]);
    }
    fn unit(&mut self, x: f32) {
        self.u8((x.clamp(0.0, 1.0) * 255.0).round() as u8);
    }
    fn idx(&mut self, r: Option<&ObjRef>) {
        let v = r.map_or(0, |r| self.index[&std::rc::Rc::as_ptr(r)]);
        self.u32(v);
    }
    fn obj(&mut self, r: &ObjRef) {
        self.idx(Some(r));
    }
}

fn matrix_rows(m: &Mat4) -> [f32; 16] {
    Transform::from_mat4(*m).get()
}

fn write_o3d(w: &mut W, i: &Inner) -> WResult {
    w.i32(i.user_id);
    w.u32(i.tracks.len() as u32);
    for t in &i.tracks {
        w.obj(&t.0);
    }
    let params = i
        .user_object
        .as_ref()
        .and_then(|o| o.downcast_ref::<UserParameters>());
    match params {
        Some(p) => {
            w.u32(p.len() as u32);
            for (id, v) in p {
                w.i32(*id);
                w.u32(v.len() as u32);
                w.b.extend_from_slice(v);
            }
        }
        None => w.u32(0),
    }
    Ok(())
}

fn write_tf(w: &mut W, r: &ObjRef) -> WResult {
    let t = tf(r).clone();
    let q = if t.orientation.w < 0.0 {
        -t.orientation
    } else {
        t.orientation
    };
    let identity_q = q.x == 0.0 && q.y == 0.0 && q.z == 0.0;
    let comp = t.translation != glam::Vec3::ZERO || t.scale != glam::Vec3::ONE || !identity_q;
    w.bool(comp);
    if comp {
        w.f32s(&t.translation.to_array())?;
        w.f32s(&t.scale.to_array())?;
        let (axis, angle) = q.normalize().to_axis_angle();
        if identity_q || angle == 0.0 || !axis.is_finite() {
            w.f32s(&[0.0, 0.0, 0.0, 1.0])?;
        } else {
            w.f32(angle.to_degrees())?;
            w.f32s(&axis.to_array())?;
        }
    }
    let general = t.matrix != Mat4::IDENTITY;
    w.bool(general);
    if general {
        w.f32s(&matrix_rows(&t.matrix))?;
    }
    Ok(())
}

fn write_node(w: &mut W, r: &ObjRef) -> WResult {
    write_tf(w, r)?;
    let n = r.borrow().node.clone().expect("a node");
    w.bool(n.rendering);
    w.bool(n.picking);
    w.unit(n.alpha);
    w.i32(n.scope);
    let refs: Vec<Option<ObjRef>> = n
        .alignment
        .iter()
        .map(|a| a.1.as_ref().and_then(|x| x.upgrade()))
        .collect();
    let has =
        n.alignment.iter().any(|a| a.0 != AlignTarget::None) || refs.iter().any(Option::is_some);
    w.bool(has);
    if has {
        w.u8(n.alignment[0].0 as u8);
        w.u8(n.alignment[1].0 as u8);
        w.idx(refs[0].as_ref());
        w.idx(refs[1].as_ref());
    }
    Ok(())
}

fn write_mesh_part(w: &mut W, m: &mesh::MeshData) {
    w.obj(&m.vb.0);
    w.u32(m.ibs.len() as u32);
    for (ib, app) in m.ibs.iter().zip(&m.apps) {
        w.obj(&ib.0);
        w.idx(app.as_ref().map(|a| &a.0));
    }
}

fn write_object(w: &mut W, r: &ObjRef) -> Result<u8> {
    let i = r.borrow().clone();
    write_o3d(w, &i)?;
    let ty = match &i.kind {
        Kind::AnimationController(c) => {
            w.f32(c.speed)?;
            w.f32(c.weight)?;
            w.i32(c.start);
            w.i32(c.end);
            w.f32(c.ref_seq)?;
            w.i32(c.ref_world);
            1
        }
        Kind::AnimationTrack(t) => {
            w.obj(&t.sequence.0);
            w.idx(t.controller.as_ref().map(|c| &c.0));
            w.i32(t.property.as_raw());
            2
        }
        Kind::Appearance(a) => {
            w.u8(a.layer as i8 as u8);
            w.idx(a.compositing_mode.as_ref().map(|x| &x.0));
            w.idx(a.fog.as_ref().map(|x| &x.0));
            w.idx(a.polygon_mode.as_ref().map(|x| &x.0));
            w.idx(a.material.as_ref().map(|x| &x.0));
            let n = a
                .textures
                .iter()
                .rposition(Option::is_some)
                .map_or(0, |k| k + 1);
            if a.textures[..n].iter().any(Option::is_none) {
                return Err(Error::Write(
                    "an Appearance has a gap in its texture units".into(),
                ));
            }
            w.u32(n as u32);
            for t in a.textures[..n].iter().flatten() {
                w.obj(&t.0);
            }
            3
        }
        Kind::Background(b) => {
            w.rgba(b.color);
            w.idx(b.image.as_ref().map(|x| &x.0));
            w.u8(b.mode[0] as u8);
            w.u8(b.mode[1] as u8);
            for c in b.crop {
                w.i32(c);
            }
            w.bool(b.depth_clear);
            w.bool(b.color_clear);
            4
        }
        Kind::Camera(c) => {
            write_node(w, r)?;
            w.u8(c.projection as u8);
            if c.projection == Projection::Generic {
                w.f32s(&matrix_rows(&c.matrix))?;
            } else {
                w.f32s(&c.params)?;
            }
            5
        }
        Kind::CompositingMode(c) => {
            w.bool(c.depth_test);
            w.bool(c.depth_write);
            w.bool(c.color_write);
            w.bool(c.alpha_write);
            w.u8(c.blending as u8);
            w.unit(c.alpha_threshold);
            w.f32s(&c.depth_offset)?;
            6
        }
        Kind::Fog(f) => {
            w.rgb(f.color);
            w.u8(f.mode as u8);
            if f.mode == FogMode::Exponential {
                w.f32(f.density)?;
            } else {
                w.f32(f.near)?;
                w.f32(f.far)?;
            }
            7
        }
        Kind::PolygonMode(p) => {
            w.u8(p.culling as u8);
            w.u8(p.shading as u8);
            w.u8(p.winding as u8);
            w.bool(p.two_sided);
            w.bool(p.local_camera);
            w.bool(p.perspective);
            8
        }
        Kind::Group(g) => {
            write_node(w, r)?;
            w.u32(g.children.len() as u32);
            for c in &g.children {
                w.obj(c);
            }
            9
        }
        Kind::World(wd) => {
            write_node(w, r)?;
            w.u32(wd.group.children.len() as u32);
            for c in &wd.group.children {
                w.obj(c);
            }
            w.idx(wd.camera.as_ref().map(|x| &x.0));
            w.idx(wd.background.as_ref().map(|x| &x.0));
            22
        }
        Kind::Image2D(d) => {
            w.u8(d.format as u8);
            w.bool(d.mutable);
            w.u32(d.width as u32);
            w.u32(d.height as u32);
            if !d.mutable {
                w.u32(0);
                w.u32(d.pixels.len() as u32);
                w.b.extend_from_slice(&d.pixels);
            }
            10
        }
        Kind::IndexBuffer(d) => {
            let wide = d.triangles.iter().any(|&x| x > 255);
            w.u8(if wide { 130 } else { 129 });
            w.u32(d.triangles.len() as u32);
            for &x in &d.triangles {
                if wide {
                    w.u16(x);
                } else {
                    w.u8(x as u8);
                }
            }
            w.u32((d.triangles.len() / 3) as u32);
            for _ in 0..d.triangles.len() / 3 {
                w.u32(3);
            }
            11
        }
        Kind::Light(l) => {
            write_node(w, r)?;
            w.f32s(&l.attenuation)?;
            w.rgb(l.color);
            w.u8(l.mode as u8);
            w.f32(l.intensity)?;
            w.f32(l.spot_angle)?;
            w.f32(l.spot_exponent)?;
            12
        }
        Kind::Material(m) => {
            w.rgb(m.ambient);
            w.rgba(m.diffuse);
            w.rgb(m.emissive);
            w.rgb(m.specular);
            w.f32(m.shininess)?;
            w.bool(m.tracking);
            13
        }
        Kind::Mesh(m) => {
            write_node(w, r)?;
            write_mesh_part(w, m);
            match &m.ext {
                MeshExt::None => 14,
                MeshExt::Morphing(md) => {
                    w.u32(md.targets.len() as u32);
                    for (t, wt) in md.targets.iter().zip(&md.weights) {
                        w.obj(&t.0);
                        w.f32(*wt)?;
                    }
                    15
                }
                MeshExt::Skinned(s) => {
                    w.obj(&s.skeleton.0);
                    w.u32(s.entries.len() as u32);
                    for e in &s.entries {
                        w.obj(&e.bone.0);
                        w.i32(e.first);
                        w.i32(e.count);
                        w.i32(e.weight);
                    }
                    16
                }
            }
        }
        Kind::Texture2D(t) => {
            write_tf(w, r)?;
            w.obj(&t.image.0);
            w.rgb(t.blend_color);
            w.u8(t.blending as u8);
            w.u8(t.wrap[0] as u8);
            w.u8(t.wrap[1] as u8);
            w.u8(t.level_filter as u8);
            w.u8(t.image_filter as u8);
            17
        }
        Kind::Sprite(s) => {
            write_node(w, r)?;
            w.obj(&s.image.0);
            w.idx(s.appearance.as_ref().map(|x| &x.0));
            w.bool(s.scaled);
            for c in s.crop {
                w.i32(c);
            }
            18
        }
        Kind::KeyframeSequence(k) => {
            w.u8(k.interpolation as u8);
            w.u8(k.repeat as u8);
            w.u8(0);
            w.i32(k.duration);
            w.u32(k.first as u32);
            w.u32(k.last as u32);
            w.u32(k.comps as u32);
            w.u32(k.times.len() as u32);
            for (t, v) in k.times.iter().zip(&k.values) {
                w.i32(*t);
                w.f32s(v)?;
            }
            19
        }
        Kind::VertexArray(v) => {
            w.u8(v.size as u8);
            w.u8(v.comps as u8);
            w.u8(0);
            w.u16(v.count as u16);
            if v.size == 1 {
                w.b.extend_from_slice(&v.data);
            } else {
                for c in v.data.chunks_exact(2) {
                    w.u16(u16::from_ne_bytes([c[0], c[1]]));
                }
            }
            20
        }
        Kind::VertexBuffer(v) => {
            w.rgba(v.default_color);
            w.idx(v.positions.as_ref().map(|x| &x.0));
            w.f32s(&v.pos_bias)?;
            w.f32(v.pos_scale)?;
            w.idx(v.normals.as_ref().map(|x| &x.0));
            w.idx(v.colors.as_ref().map(|x| &x.0));
            let n = v
                .texcoords
                .iter()
                .rposition(Option::is_some)
                .map_or(0, |k| k + 1);
            if v.texcoords[..n].iter().any(Option::is_none) {
                return Err(Error::Write(
                    "a VertexBuffer has a gap in its texture-coordinate units".into(),
                ));
            }
            w.u32(n as u32);
            for (va, scale, bias) in v.texcoords[..n].iter().flatten() {
                w.obj(&va.0);
                let mut b = *bias;
                if va.component_count() == 2 {
                    b[2] = 0.0;
                }
                w.f32s(&b)?;
                w.f32(*scale)?;
            }
            21
        }
    };
    Ok(ty)
}
