//! Scenes shared by the invariance tests (`crates/core/tests/invariance.rs`) and the accuracy report
//! (`crates/tools/src/bin/accuracy.rs`), both including this file by path, so the scenes a test checks
//! are the ones the report measures: owned vertex data from which
//! `DrawCall`s are made, the states that draw them, and an f64 lighting of the lit scene
//! for the reference renderer (which takes colors as given and does no lighting itself).

#![allow(dead_code)]

use std::sync::Arc;

use glam::{DMat3, DVec3, DVec4, Mat4, Vec3, Vec4};
use gles_cm_core::state::{Light, Lighting, Material, Quality};
use gles_cm_core::texenv::{EnvMode, TexEnv, TextureUnit};
use gles_cm_core::texture::{BaseFormat, Image, MagFilter, MinFilter, Sampler, Texture, Wrap};
use gles_cm_core::{
    AttribArray, AttribSource, ColorFormat, CompareFunc, ComponentType, DepthFormat, DrawCall,
    Indices, Primitive, RenderState, Target, TargetFormat,
};

/// A fixed pseudo-random sequence in [0, 1).
pub struct Lcg(pub u64);
impl Lcg {
    pub fn next(&mut self) -> f32 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 40) as f32 / (1u64 << 24) as f32
    }
    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.next()
    }
}

pub fn bytes(v: &[f32]) -> Vec<u8> {
    v.iter().flat_map(|x| x.to_ne_bytes()).collect()
}

fn array(data: &[u8], size: usize) -> AttribArray<'_> {
    AttribArray {
        data,
        ty: ComponentType::Float,
        size,
        stride: size * 4,
        normalized: false,
    }
}

/// An RGBA8888 / D24 / S8 target cleared to opaque dark blue, depth 1, stencil 0.
pub fn target(w: u32, h: u32) -> Target {
    let mut t = Target::new(
        w,
        h,
        TargetFormat {
            color: ColorFormat::Rgba8888,
            depth: Some(DepthFormat::D24),
            stencil_bits: 8,
        },
    );
    t.clear_color(t.bounds(), [0.05, 0.05, 0.2, 1.0], [true; 4]);
    t.clear_depth(t.bounds(), 1.0);
    t.clear_stencil(t.bounds(), 0, u32::MAX);
    t
}

/// Vertex data of one draw: positions (xyz), colors (rgba), normals (xyz), texture
/// coordinates (st), optional 16-bit indices.
pub struct Mesh {
    pub primitive: Primitive,
    pub pos: Vec<u8>,
    pub col: Option<Vec<u8>>,
    pub nrm: Option<Vec<u8>>,
    pub st: Option<Vec<u8>>,
    pub idx: Option<Vec<u16>>,
    pub vertices: usize,
}

impl Mesh {
    pub fn call(&self) -> DrawCall<'_> {
        let indices = match &self.idx {
            Some(i) => Indices::U16(i),
            None => Indices::Range {
                first: 0,
                count: self.vertices,
            },
        };
        let mut c = DrawCall::new(self.primitive, indices, array(&self.pos, 3));
        if let Some(col) = &self.col {
            c.color = AttribSource::Array(array(col, 4));
        }
        if let Some(n) = &self.nrm {
            c.normal = AttribSource::Array(array(n, 3));
        }
        if let Some(st) = &self.st {
            c.texcoord[0] = AttribSource::Array(array(st, 2));
        }
        c
    }
}

/// A perspective view (60° vertical field, near 0.5, far 50) with depth test LESS.
pub fn perspective_state(w: u32, h: u32, q: Quality) -> RenderState {
    let mut s = RenderState::new(w as i32, h as i32);
    s.projection = Mat4::perspective_rh_gl(1.05, w as f32 / h as f32, 0.5, 50.0);
    s.depth_test = Some(CompareFunc::Less);
    s.perspective = q;
    s.line_quality = q;
    s.point_quality = q;
    s
}

/// `n` random smooth-colored triangles at eye depths 2 to 12, strongly tilted in depth.
pub fn smooth_triangles(n: usize, seed: u64) -> Mesh {
    triangles(n, seed, 2.0)
}

/// `n` random smooth-colored triangles a few pixels across (spans shorter than a group),
/// at eye depths 2 to 12.
pub fn small_triangles(n: usize, seed: u64) -> Mesh {
    triangles(n, seed, 0.15)
}

/// `n` random smooth-colored triangles whose corners lie within `spread` of their center
/// in x and y, and within 0.75 · `spread` in z.
fn triangles(n: usize, seed: u64, spread: f32) -> Mesh {
    let mut r = Lcg(seed);
    let (mut pos, mut col) = (Vec::new(), Vec::new());
    for _ in 0..n {
        let (cx, cy, cz) = (r.range(-4.0, 4.0), r.range(-3.0, 3.0), r.range(-12.0, -2.0));
        for _ in 0..3 {
            pos.extend([
                cx + r.range(-spread, spread),
                cy + r.range(-spread, spread),
                cz + r.range(-0.75 * spread, 0.75 * spread),
            ]);
            col.extend([r.next(), r.next(), r.next(), 1.0]);
        }
    }
    Mesh {
        primitive: Primitive::Triangles,
        pos: bytes(&pos),
        col: Some(bytes(&col)),
        nrm: None,
        st: None,
        idx: None,
        vertices: 3 * n,
    }
}

/// `n` random lines (or points with `points`) at eye depths 2 to 12, smooth colors.
pub fn lines_or_points(n: usize, seed: u64, points: bool) -> Mesh {
    let mut r = Lcg(seed);
    let (mut pos, mut col) = (Vec::new(), Vec::new());
    let per = if points { 1 } else { 2 };
    for _ in 0..n {
        let (cx, cy, cz) = (r.range(-4.0, 4.0), r.range(-3.0, 3.0), r.range(-12.0, -2.0));
        for _ in 0..per {
            pos.extend([
                cx + r.range(-1.5, 1.5),
                cy + r.range(-1.5, 1.5),
                cz + r.range(-1.0, 1.0),
            ]);
            col.extend([r.next(), r.next(), r.next(), r.range(0.5, 1.0)]);
        }
    }
    Mesh {
        primitive: if points {
            Primitive::Points
        } else {
            Primitive::Lines
        },
        pos: bytes(&pos),
        col: Some(bytes(&col)),
        nrm: None,
        st: None,
        idx: None,
        vertices: per * n,
    }
}

/// A 64 × 32 texture with detail at every scale (a checker of 4-texel cells over
/// gradients, so every mip level differs), mipmapped, repeated.
pub fn texture(min: MinFilter, mag: MagFilter) -> Arc<Sampler> {
    texture_sized(64, 32, min, mag, Wrap::Repeat)
}

/// [`texture`] at any size (`OES_texture_npot`) and wrap mode.
pub fn texture_sized(w: u32, h: u32, min: MinFilter, mag: MagFilter, wrap: Wrap) -> Arc<Sampler> {
    let texels = (0..w * h)
        .map(|i| {
            let (x, y) = (i % w, i / w);
            let check = ((x / 4 + y / 4) % 2) as u8 * 120;
            u32::from_le_bytes([
                check + (x * 2) as u8,
                (y * 7) as u8 ^ check,
                (x * y) as u8,
                255 - (x + y) as u8,
            ])
        })
        .collect();
    let mut t = Texture::new();
    t.generate_mipmap = true;
    t.min_filter = min;
    t.mag_filter = mag;
    t.wrap_s = wrap;
    t.wrap_t = wrap;
    t.set_level(
        0,
        Image {
            width: w,
            height: h,
            format: BaseFormat::Rgba,
            texels,
        },
    );
    t.sampler().expect("complete")
}

/// A floor receding from the viewer to depth 40 (the texture repeated 6 × 12 times) and a
/// magnified wall close up, smooth colors modulated by the texture.
pub fn floor() -> Mesh {
    let pos = [
        -4.0, -1.0, -1.0, 4.0, -1.0, -1.0, -4.0, -1.0, -40.0, 4.0, -1.0, -40.0, // floor
        -0.6, 0.2, -1.5, 0.3, 0.1, -1.2, -0.5, 0.9, -1.4, 0.4, 0.8, -1.1, // wall
    ];
    let st = [
        0.0, 0.0, 6.0, 0.0, 0.0, 12.0, 6.0, 12.0, // floor
        0.1, 0.2, 0.6, 0.2, 0.1, 0.5, 0.6, 0.5, // wall
    ];
    let col = [
        1.0, 1.0, 1.0, 1.0, 0.8, 0.9, 1.0, 1.0, 0.9, 1.0, 0.7, 1.0, 1.0, 0.6, 0.9, 1.0, //
        1.0, 1.0, 1.0, 1.0, 0.5, 1.0, 1.0, 1.0, 1.0, 0.5, 1.0, 1.0, 1.0, 1.0, 0.5, 1.0,
    ];
    Mesh {
        primitive: Primitive::Triangles,
        pos: bytes(&pos),
        col: Some(bytes(&col)),
        nrm: None,
        st: Some(bytes(&st)),
        idx: Some(vec![0, 1, 2, 2, 1, 3, 4, 5, 6, 6, 5, 7]),
        vertices: 8,
    }
}

/// The floor's state: perspective, unit 0 textured with `min`/`mag`, MODULATE.
pub fn floor_state(w: u32, h: u32, min: MinFilter, mag: MagFilter, q: Quality) -> RenderState {
    let mut s = perspective_state(w, h, q);
    s.textures[0] = Some(TextureUnit {
        sampler: texture(min, mag),
        env: TexEnv {
            mode: EnvMode::Modulate,
            color: [0.0; 4],
        },
        coord_replace: false,
    });
    s
}

/// A unit sphere of `rings` × `segments` quads with unit normals, as indexed triangles.
pub fn sphere(rings: usize, segments: usize) -> Mesh {
    let (mut pos, mut nrm) = (Vec::new(), Vec::new());
    for i in 0..=rings {
        let th = std::f32::consts::PI * i as f32 / rings as f32;
        for j in 0..=segments {
            let ph = std::f32::consts::TAU * j as f32 / segments as f32;
            let n = [th.sin() * ph.cos(), th.cos(), th.sin() * ph.sin()];
            pos.extend(n);
            nrm.extend(n);
        }
    }
    let mut idx = Vec::new();
    let row = (segments + 1) as u16;
    for i in 0..rings as u16 {
        for j in 0..segments as u16 {
            let (a, b) = (i * row + j, (i + 1) * row + j);
            idx.extend([a, b, a + 1, a + 1, b, b + 1]);
        }
    }
    Mesh {
        primitive: Primitive::Triangles,
        pos: bytes(&pos),
        col: None,
        nrm: Some(bytes(&nrm)),
        st: None,
        idx: Some(idx),
        vertices: (rings + 1) * (segments + 1),
    }
}

/// Two lights: a white directional one from the upper left with specular, and a warm
/// positional one in front with attenuation; a shiny reddish material.
pub fn lighting() -> Lighting {
    Lighting {
        lights: vec![
            Light {
                ambient: Vec4::new(0.05, 0.05, 0.05, 1.0),
                diffuse: Vec4::new(0.8, 0.8, 0.8, 1.0),
                specular: Vec4::new(1.0, 1.0, 1.0, 1.0),
                position: Vec4::new(-0.5, 0.7, 0.6, 0.0),
                ..Light::default()
            },
            Light {
                ambient: Vec4::new(0.0, 0.0, 0.0, 1.0),
                diffuse: Vec4::new(0.9, 0.6, 0.3, 1.0),
                specular: Vec4::new(0.5, 0.4, 0.3, 1.0),
                position: Vec4::new(1.5, -0.5, -2.0, 1.0),
                attenuation: [0.5, 0.2, 0.05],
                ..Light::default()
            },
        ],
        front: Material {
            ambient: Vec4::new(0.3, 0.1, 0.1, 1.0),
            diffuse: Vec4::new(0.8, 0.3, 0.25, 1.0),
            specular: Vec4::new(0.6, 0.6, 0.6, 1.0),
            emission: Vec4::new(0.02, 0.0, 0.02, 1.0),
            shininess: 24.0,
        },
        ..Lighting::default()
    }
}

/// The lit scene's state for one of its spheres (a modelview placing it).
pub fn lit_state(w: u32, h: u32, q: Quality, modelview: Mat4) -> RenderState {
    let mut s = perspective_state(w, h, q);
    s.modelview = modelview;
    s.lighting = Some(lighting());
    s
}

/// The modelviews of the lit scene: three spheres of different sizes and distances.
pub fn lit_modelviews() -> [Mat4; 3] {
    [
        Mat4::from_translation(Vec3::new(-1.2, 0.2, -4.0)) * Mat4::from_rotation_y(0.4),
        Mat4::from_translation(Vec3::new(1.3, -0.3, -5.0))
            * Mat4::from_rotation_x(-0.7)
            * Mat4::from_scale(Vec3::splat(1.0)),
        Mat4::from_translation(Vec3::new(0.2, 1.4, -9.0)) * Mat4::from_rotation_z(1.1),
    ]
}

/// The ES 1.1 §2.12.1 lighting of every vertex of `mesh` in f64 (viewer at infinity, no
/// spot cones, one-sided): the colors the reference renderer is given in place of
/// lighting. Normals are transformed by the inverse transpose and used as they come out
/// (the scene's modelviews are rigid, so they stay unit).
pub fn lit_colors_f64(state: &RenderState, mesh: &Mesh) -> Vec<f32> {
    let l = state.lighting.as_ref().expect("lighting");
    let mv = state.modelview.as_dmat4();
    let nm = DMat3::from_mat4(mv).inverse().transpose();
    let f = |b: &[u8], i: usize| f32::from_ne_bytes([b[i], b[i + 1], b[i + 2], b[i + 3]]) as f64;
    let v4 = |v: Vec4| v.as_dvec4();
    let m = &l.front;
    let mut out = Vec::with_capacity(mesh.vertices * 4);
    let nrm = mesh.nrm.as_ref().expect("normals");
    for k in 0..mesh.vertices {
        let p = DVec4::new(
            f(&mesh.pos, 12 * k),
            f(&mesh.pos, 12 * k + 4),
            f(&mesh.pos, 12 * k + 8),
            1.0,
        );
        let n = nm * DVec3::new(f(nrm, 12 * k), f(nrm, 12 * k + 4), f(nrm, 12 * k + 8));
        let pe = (mv * p).truncate();
        let mut c = v4(m.emission) + v4(m.ambient) * v4(l.model_ambient);
        for light in &l.lights {
            let lp = v4(light.position);
            let (vp, att) = if lp.w == 0.0 {
                (lp.truncate().normalize(), 1.0)
            } else {
                let d = lp.truncate() / lp.w - pe;
                let len = d.length();
                let [kc, kl, kq] = light.attenuation.map(f64::from);
                (d / len, 1.0 / (kc + kl * len + kq * len * len))
            };
            let ndl = n.dot(vp).max(0.0);
            let h = (vp + DVec3::Z).normalize();
            let spec = if ndl != 0.0 {
                let nh = n.dot(h).max(0.0);
                if m.shininess == 0.0 {
                    1.0
                } else {
                    nh.powf(m.shininess as f64)
                }
            } else {
                0.0
            };
            c += (v4(m.ambient) * v4(light.ambient)
                + v4(m.diffuse) * v4(light.diffuse) * ndl
                + v4(m.specular) * v4(light.specular) * spec)
                * att;
        }
        let c = c.clamp(DVec4::ZERO, DVec4::ONE);
        out.extend([
            c.x as f32,
            c.y as f32,
            c.z as f32,
            m.diffuse.w.clamp(0.0, 1.0),
        ]);
    }
    out
}
