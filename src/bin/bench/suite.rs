//! The benchmark's scenes. Each is one description (arrays, textures, lights, fog, and a list
//! of state changes and draws) from which both the GL call sequence (`worker.rs`) and the core
//! `RenderState` + `DrawCall` pairs for the reference renderer (`Scene::reference`) are
//! generated, so the two can never drift apart.
//!
//! The reference renderer has no lighting: for lit draws `Scene::reference` evaluates the
//! ES 1.1 §2.12.1 equation itself, in f64, for directional lights only (no attenuation, no
//! spot), and hands the reference the lit colors with lighting off. It has no point sprites
//! either: each sprite is drawn there as the square the sprite covers, with the
//! `COORD_REPLACE` texture coordinates at its corners (they are affine in window x and y,
//! so interpolating them gives the sprite's coordinates exactly at every pixel center).

use std::sync::Arc;

use glam::{DMat3, DVec3, DVec4, Mat4, Vec3};
use GLES_CM::core::state::{Blend, BlendFactor, Quality, ShadeModel};
use GLES_CM::core::texenv::{
    Combine, CombineFunc, EnvMode, Fog, FogMode, Operand, Source, TexEnv, TextureUnit,
};
use GLES_CM::core::texture::{BaseFormat, Image, MagFilter, MinFilter, Sampler, Wrap};
use GLES_CM::core::{
    AttribArray, AttribSource, ColorFormat, CompareFunc, ComponentType, DepthFormat, DrawCall,
    Indices, Primitive, RenderState, Target, TargetFormat,
};
use GLES_CM::gles::tokens::{GL_DONT_CARE, GL_FASTEST, GL_NICEST};
use GLES_CM::gles::types::GLenum;

/// The GL scenes, in table order: the main ones, then those only the scaling table uses.
pub const NAMES: [&str; 19] = [
    "clear-640",
    "flat-640",
    "smooth-640",
    "texture-640",
    "clear-1280",
    "flat-1280",
    "smooth-1280",
    "texture-1280",
    "lit-vbo",
    "lit-arrays",
    "demo",
    "multitexture",
    "sprites",
    "smooth-320",
    "lit-offscreen",
    "tris-1k",
    "tris-10k",
    "tris-100k",
    "tris-1m",
];

/// The M3G scene (not a GL scene: it goes through `m3g::Graphics3D`).
pub const M3G: &str = "m3g-robot";

/// The hint modes: every `glHint` target (perspective correction, point and line smoothing,
/// fog) set to one value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    Fastest,
    DontCare,
    Nicest,
}

impl Mode {
    pub const ALL: [Mode; 3] = [Mode::Fastest, Mode::DontCare, Mode::Nicest];

    pub fn gl(self) -> GLenum {
        match self {
            Mode::Fastest => GL_FASTEST,
            Mode::DontCare => GL_DONT_CARE,
            Mode::Nicest => GL_NICEST,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Mode::Fastest => "FASTEST",
            Mode::DontCare => "DONT_CARE",
            Mode::Nicest => "NICEST",
        }
    }

    pub fn parse(s: &str) -> Option<Mode> {
        Mode::ALL
            .into_iter()
            .find(|m| m.name().eq_ignore_ascii_case(s))
    }
}

/// A fixed pseudo-random sequence, so every process builds the same scene.
pub struct Lcg(pub u64);
impl Lcg {
    pub fn next(&mut self) -> f32 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 40) as f32 / (1u64 << 24) as f32
    }
}

/// A tightly packed vertex array.
pub struct Attr {
    pub data: Vec<u8>,
    pub ty: ComponentType,
    pub size: usize,
}

impl Attr {
    fn float(v: &[f32], size: usize) -> Attr {
        Attr {
            data: v.iter().flat_map(|x| x.to_ne_bytes()).collect(),
            ty: ComponentType::Float,
            size,
        }
    }

    /// 16.16 fixed point, rounded to nearest.
    fn fixed(v: &[f32], size: usize) -> Attr {
        Attr {
            data: v
                .iter()
                .flat_map(|x| ((x * 65536.0).round() as i32).to_ne_bytes())
                .collect(),
            ty: ComponentType::Fixed,
            size,
        }
    }

    pub fn stride(&self) -> usize {
        self.size * self.ty.size()
    }

    pub fn array(&self) -> AttribArray<'_> {
        AttribArray {
            data: &self.data,
            ty: self.ty,
            size: self.size,
            stride: self.stride(),
            normalized: false,
        }
    }
}

/// A 2D RGBA texture with its whole mipmap chain (uploaded level by level, so both sides
/// sample the same texels).
pub struct Tex {
    pub levels: Vec<Image>,
    pub min: MinFilter,
    pub mag: MagFilter,
    pub wrap: Wrap,
}

impl Tex {
    /// `texel(x, y)` over a `size` × `size` base level; the chain when `min` uses mipmaps.
    fn new(size: u32, min: MinFilter, mag: MagFilter, texel: impl Fn(u32, u32) -> [u8; 4]) -> Tex {
        let mut texels = Vec::with_capacity((size * size) as usize);
        for y in 0..size {
            for x in 0..size {
                texels.push(u32::from_le_bytes(texel(x, y)));
            }
        }
        let mut levels = vec![Image {
            width: size,
            height: size,
            format: BaseFormat::Rgba,
            texels,
        }];
        if min.uses_mipmaps() {
            while levels.last().is_some_and(|l| l.width > 1) {
                let next = levels.last().map(Image::half).expect("a level");
                levels.push(next);
            }
        }
        Tex {
            levels,
            min,
            mag,
            wrap: Wrap::Repeat,
        }
    }

    fn sampler(&self) -> Arc<Sampler> {
        Arc::new(Sampler::new(
            self.levels.iter().cloned().map(Arc::new).collect(),
            self.min,
            self.mag,
            self.wrap,
            self.wrap,
        ))
    }
}

/// One directional light, set in eye coordinates (the modelview is the identity then).
pub struct DirLight {
    /// Towards the light.
    pub direction: [f32; 3],
    pub ambient: [f32; 4],
    pub diffuse: [f32; 4],
    pub specular: [f32; 4],
}

/// Lighting with `GL_COLOR_MATERIAL` on: the vertex (or current) color is the ambient and
/// diffuse material; the rest is fixed here.
pub struct LightSetup {
    pub lights: Vec<DirLight>,
    pub model_ambient: [f32; 4],
    pub specular: [f32; 4],
    pub shininess: f32,
}

/// Linear fog.
pub struct FogSetup {
    pub start: f32,
    pub end: f32,
    pub color: [f32; 4],
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cap {
    DepthTest,
    Blend,
    Fog,
    Lighting,
    PointSprite,
}

/// One state change or draw, in GL order.
pub enum Op {
    Enable(Cap, bool),
    BlendFunc(BlendFactor, BlendFactor),
    Shade(ShadeModel),
    Projection(Mat4),
    Modelview(Mat4),
    /// `glColor4f`: the current color, used while the color array is disabled.
    Color([f32; 4]),
    ColorArray(bool),
    PointSize(f32),
    /// Texture `tex` (an index into `Scene::textures`) on `unit` with its environment, or
    /// the unit disabled.
    Texture {
        unit: usize,
        tex: Option<usize>,
        env: TexEnv,
        coord_replace: bool,
    },
    Draw {
        prim: Primitive,
        first: usize,
        count: usize,
    },
    /// `glDrawElements` of `count` indices of `Scene::indices` from `offset`.
    DrawIndexed {
        prim: Primitive,
        offset: usize,
        count: usize,
    },
}

/// What the throughput column counts.
#[derive(Clone, Copy)]
pub enum Unit {
    Pixels,
    Triangles,
    Points,
}

/// Which rows a scene gets.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Class {
    /// Every mode and every peer.
    Main,
    /// DONT_CARE only, ours and llvmpipe: the scaling table.
    Scaling,
}

pub struct Scene {
    pub summary: String,
    pub class: Class,
    pub width: u32,
    pub height: u32,
    /// Per frame: what the throughput counts, and the vertices the vertex stage sees (for
    /// ns per vertex) and pixels written (for ns per pixel).
    pub unit: Unit,
    pub work: f64,
    pub vertices: f64,
    pub pixels: f64,
    pub clear_color: [f32; 4],
    pub position: Attr,
    pub color: Option<Attr>,
    pub normal: Option<Attr>,
    pub texcoord: [Option<Attr>; 2],
    pub indices: Vec<u16>,
    /// Arrays and indices in buffer objects rather than client memory.
    pub buffers: bool,
    pub textures: Vec<Tex>,
    pub lighting: Option<LightSetup>,
    pub fog: Option<FogSetup>,
    /// Run once before the first frame.
    pub setup: Vec<Op>,
    /// Every frame, after `glClear` of color and depth; `glFinish` ends it.
    pub frame: Vec<Op>,
}

impl Scene {
    pub fn by_name(name: &str) -> Option<Scene> {
        Some(match name {
            "clear-640" => fill(Fill::Clear, 640, 480, Class::Main),
            "flat-640" => fill(Fill::Flat, 640, 480, Class::Main),
            "smooth-640" => fill(Fill::Smooth, 640, 480, Class::Main),
            "texture-640" => fill(Fill::Textured, 640, 480, Class::Main),
            "clear-1280" => fill(Fill::Clear, 1280, 960, Class::Main),
            "flat-1280" => fill(Fill::Flat, 1280, 960, Class::Main),
            "smooth-1280" => fill(Fill::Smooth, 1280, 960, Class::Main),
            "texture-1280" => fill(Fill::Textured, 1280, 960, Class::Main),
            "smooth-320" => fill(Fill::Smooth, 320, 240, Class::Scaling),
            "lit-vbo" => lit(true, false),
            "lit-arrays" => lit(false, false),
            "lit-offscreen" => lit(false, true),
            "demo" => demo(),
            "multitexture" => multitexture(),
            "sprites" => sprites(),
            "tris-1k" => small_triangles(1_000),
            "tris-10k" => small_triangles(10_000),
            "tris-100k" => small_triangles(100_000),
            "tris-1m" => small_triangles(1_000_000),
            _ => return None,
        })
    }

    pub fn throughput(&self, seconds: f64) -> String {
        let rate = self.work / seconds / 1e6;
        match self.unit {
            Unit::Pixels => format!("{rate:.0} Mpix/s"),
            Unit::Triangles => format!("{rate:.2} Mtris/s"),
            Unit::Points => format!("{rate:.2} Mpts/s"),
        }
    }

    pub fn target(&self) -> Target {
        target(self.width, self.height)
    }

    /// The reference image: the cleared target, then the setup and one frame through the
    /// f64 renderer. The reference ignores the hints, so one image serves every mode.
    pub fn reference(&self) -> Target {
        let mut t = self.target();
        t.clear_color(t.bounds(), self.clear_color, [true; 4]);
        t.clear_depth(t.bounds(), 1.0);
        let mut rs = RenderState::new(self.width as i32, self.height as i32);
        rs.dither = false;
        rs.depth_test = None;
        let samplers: Vec<Arc<Sampler>> = self.textures.iter().map(Tex::sampler).collect();
        let mut blend = Blend::func(BlendFactor::One, BlendFactor::Zero);
        let (mut blending, mut lighting, mut color_array) = (false, false, self.color.is_some());
        let mut current = [1.0f32; 4];
        for op in self.setup.iter().chain(&self.frame) {
            match op {
                Op::Enable(cap, on) => match cap {
                    Cap::DepthTest => rs.depth_test = on.then_some(CompareFunc::Less),
                    Cap::Blend => blending = *on,
                    Cap::Fog => {
                        rs.fog = if *on {
                            let f = self.fog.as_ref().expect("a scene with fog has FogSetup");
                            Some(Fog {
                                mode: FogMode::Linear,
                                density: 1.0,
                                start: f.start,
                                end: f.end,
                                color: f.color,
                                quality: Quality::Balanced,
                            })
                        } else {
                            None
                        }
                    }
                    Cap::Lighting => lighting = *on,
                    Cap::PointSprite => rs.point_sprite = *on,
                },
                Op::BlendFunc(s, d) => blend = Blend::func(*s, *d),
                Op::Shade(m) => rs.shade_model = *m,
                Op::Projection(m) => rs.projection = *m,
                Op::Modelview(m) => rs.modelview = *m,
                Op::Color(c) => current = *c,
                Op::ColorArray(on) => color_array = *on,
                Op::PointSize(s) => rs.point_size = *s,
                Op::Texture {
                    unit,
                    tex,
                    env,
                    coord_replace,
                } => {
                    rs.textures[*unit] = tex.map(|i| TextureUnit {
                        sampler: samplers[i].clone(),
                        env: *env,
                        coord_replace: *coord_replace,
                    })
                }
                Op::Draw { prim, first, count } => {
                    rs.blend = blending.then_some(blend);
                    let ix = Indices::Range {
                        first: *first,
                        count: *count,
                    };
                    self.reference_draw(&rs, *prim, ix, lighting, color_array, current, &mut t);
                }
                Op::DrawIndexed {
                    prim,
                    offset,
                    count,
                } => {
                    rs.blend = blending.then_some(blend);
                    let ix = Indices::U16(&self.indices[*offset..*offset + *count]);
                    self.reference_draw(&rs, *prim, ix, lighting, color_array, current, &mut t);
                }
            }
        }
        t
    }

    #[allow(clippy::too_many_arguments)]
    fn reference_draw(
        &self,
        rs: &RenderState,
        prim: Primitive,
        ix: Indices<'_>,
        lighting: bool,
        color_array: bool,
        current: [f32; 4],
        t: &mut Target,
    ) {
        let colors = self.color.as_ref().filter(|_| color_array);
        let base_color = |i: usize| match colors {
            Some(c) => c.array().fetch(i),
            None => current,
        };
        // Lit colors for the vertices this draw reads (the others stay unused).
        let lit: Option<Attr> = lighting.then(|| {
            let setup = self.lighting.as_ref().expect("a lit scene has LightSetup");
            let normals = self.normal.as_ref().expect("a lit scene has normals");
            let n = self.position.data.len() / self.position.stride();
            let mut out = vec![0.0f32; n * 4];
            for k in 0..ix.len() {
                let i = ix.get(k);
                let c = light_vertex(
                    setup,
                    &rs.modelview,
                    normals.array().fetch(i),
                    base_color(i),
                );
                out[i * 4..i * 4 + 4].copy_from_slice(&c);
            }
            Attr::float(&out, 4)
        });
        let color = match (&lit, colors) {
            (Some(l), _) => AttribSource::Array(l.array()),
            (None, Some(c)) => AttribSource::Array(c.array()),
            (None, None) => AttribSource::Constant(current),
        };
        let mut call = DrawCall::new(prim, ix, self.position.array());
        call.color = color;
        for (u, tc) in self.texcoord.iter().enumerate() {
            if let Some(tc) = tc {
                call.texcoord[u] = AttribSource::Array(tc.array());
            }
        }
        if prim == Primitive::Points && rs.point_sprite {
            sprite_quads(rs, &call, t);
        } else {
            GLES_CM::core::reference::render(rs, &call, t);
        }
    }
}

/// The lit color (clamped) of a vertex with object normal `n` and color-material color `c`
/// under `mv`, for directional lights: ES 1.1 §2.12.1 with attenuation and spot factors 1.
fn light_vertex(setup: &LightSetup, mv: &Mat4, n: [f32; 4], c: [f32; 4]) -> [f32; 4] {
    let m = DMat3::from_mat4(mv.as_dmat4()).inverse().transpose();
    let n = m * DVec3::new(n[0] as f64, n[1] as f64, n[2] as f64);
    let c4 = DVec4::from_array(c.map(f64::from));
    let v4 = |a: [f32; 4]| DVec4::from_array(a.map(f64::from));
    let mut sum = c4 * v4(setup.model_ambient);
    for l in &setup.lights {
        let vp = DVec3::from_array(l.direction.map(f64::from)).normalize();
        let h = (vp + DVec3::Z).normalize();
        let ndotvp = n.dot(vp).max(0.0);
        sum += c4 * v4(l.ambient) + c4 * v4(l.diffuse) * ndotvp;
        if ndotvp != 0.0 {
            sum += v4(setup.specular)
                * v4(l.specular)
                * n.dot(h).max(0.0).powf(setup.shininess as f64);
        }
    }
    let out = sum.truncate().extend(c4.w).clamp(DVec4::ZERO, DVec4::ONE);
    out.to_array().map(|v| v as f32)
}

/// Point sprites for the reference: each point becomes the square the rasterization rules
/// give it (ES 1.1 §3.3: side `round(size)`, centered on the snapped window position), as
/// two triangles through a pixel-space projection, with `COORD_REPLACE` coordinates
/// s = ½ + (x − x_w)/size and t = ½ − (y − y_w)/size at its corners.
fn sprite_quads(rs: &RenderState, call: &DrawCall<'_>, t: &mut Target) {
    let (w, h) = (rs.viewport.width as f64, rs.viewport.height as f64);
    let mvp = rs.projection.as_dmat4() * rs.modelview.as_dmat4();
    let size = (rs.point_size as f64).clamp(1.0, 64.0).round().max(1.0);
    let snap = |c: f64| {
        if size as i64 % 2 == 1 {
            c.floor() + 0.5
        } else {
            (c + 0.5).floor()
        }
    };
    let (mut pos, mut col, mut tex) = (Vec::new(), Vec::new(), Vec::new());
    for k in 0..call.indices.len() {
        let i = call.indices.get(k);
        let p = mvp * DVec4::from_array(call.position.fetch(i).map(f64::from));
        if p.w <= 0.0 || [p.x, p.y, p.z].iter().any(|c| c.abs() > p.w) {
            continue;
        }
        let ndc = p / p.w;
        let (x, y) = (snap((ndc.x + 1.0) * w / 2.0), snap((ndc.y + 1.0) * h / 2.0));
        let r = size / 2.0;
        let corners = [
            (x - r, y - r, 0.0, 1.0),
            (x + r, y - r, 1.0, 1.0),
            (x + r, y + r, 1.0, 0.0),
            (x - r, y - r, 0.0, 1.0),
            (x + r, y + r, 1.0, 0.0),
            (x - r, y + r, 0.0, 0.0),
        ];
        let c = call.color.fetch(i);
        for (cx, cy, s, tt) in corners {
            pos.extend([cx as f32, cy as f32, ndc.z as f32]);
            col.extend(c);
            tex.extend([s as f32, tt as f32]);
        }
    }
    let (pos, col, tex) = (
        Attr::float(&pos, 3),
        Attr::float(&col, 4),
        Attr::float(&tex, 2),
    );
    let mut quads = DrawCall::new(
        Primitive::Triangles,
        Indices::Range {
            first: 0,
            count: pos.data.len() / pos.stride(),
        },
        pos.array(),
    );
    quads.color = AttribSource::Array(col.array());
    for (u, unit) in rs.textures.iter().enumerate() {
        quads.texcoord[u] = if unit.as_ref().is_some_and(|u| u.coord_replace) {
            AttribSource::Array(tex.array())
        } else {
            call.texcoord[u]
        };
    }
    let mut qs = rs.clone();
    qs.point_sprite = false;
    qs.modelview = Mat4::IDENTITY;
    // Window z is the ndc z here: depth range [0, 1] maps it back as the point's.
    qs.projection = Mat4::orthographic_rh_gl(0.0, w as f32, 0.0, h as f32, 1.0, -1.0);
    GLES_CM::core::reference::render(&qs, &quads, t);
}

/// An empty RGBA8888 / D24 target: the pbuffer's format.
pub fn target(width: u32, height: u32) -> Target {
    Target::new(
        width,
        height,
        TargetFormat {
            color: ColorFormat::Rgba8888,
            depth: Some(DepthFormat::D24),
            stencil_bits: 0,
        },
    )
}

/// Object x, y straight to window pixels, z in [-1, 1] to depth.
fn pixel_ortho(w: u32, h: u32) -> Mat4 {
    Mat4::orthographic_rh_gl(0.0, w as f32, 0.0, h as f32, -1.0, 1.0)
}

fn modulate() -> TexEnv {
    TexEnv {
        mode: EnvMode::Modulate,
        color: [0.0; 4],
    }
}

fn rgb(rng: &mut Lcg) -> [f32; 4] {
    [rng.next(), rng.next(), rng.next(), 1.0]
}

#[derive(Clone, Copy, PartialEq)]
enum Fill {
    Clear,
    Flat,
    Smooth,
    Textured,
}

/// Full-screen quads, no depth test, each layer covering the previous one (clear: the
/// frame's `glClear` alone).
fn fill(kind: Fill, w: u32, h: u32, class: Class) -> Scene {
    const LAYERS: usize = 4;
    let mut rng = Lcg(640 + w as u64);
    let layers = if kind == Fill::Clear { 0 } else { LAYERS };
    let (fw, fh) = (w as f32, h as f32);
    let (mut pos, mut col, mut tc) = (Vec::new(), Vec::new(), Vec::new());
    for _ in 0..layers {
        let corners = [
            (0.0, 0.0),
            (fw, 0.0),
            (fw, fh),
            (0.0, 0.0),
            (fw, fh),
            (0.0, fh),
        ];
        let quad: Vec<[f32; 4]> = (0..4).map(|_| rgb(&mut rng)).collect();
        for (k, (x, y)) in corners.into_iter().enumerate() {
            pos.extend([x, y, 0.0]);
            col.extend(quad[[0, 1, 2, 0, 2, 3][k]]);
            // About one texel per pixel at 640 × 480.
            tc.extend([x / 256.0, y / 256.0]);
        }
    }
    let mut setup = vec![
        Op::Projection(pixel_ortho(w, h)),
        Op::Modelview(Mat4::IDENTITY),
        Op::Enable(Cap::DepthTest, false),
    ];
    let mut textures = Vec::new();
    match kind {
        Fill::Flat => setup.push(Op::Shade(ShadeModel::Flat)),
        Fill::Textured => {
            textures.push(Tex::new(
                256,
                MinFilter::Linear,
                MagFilter::Linear,
                |x, y| {
                    let c = ((x / 16 + y / 16) % 2) as u8;
                    [x as u8, y as u8, if c == 1 { 220 } else { 40 }, 255]
                },
            ));
            setup.push(Op::Texture {
                unit: 0,
                tex: Some(0),
                env: modulate(),
                coord_replace: false,
            });
        }
        _ => {}
    }
    let frame = (0..layers)
        .map(|l| Op::Draw {
            prim: Primitive::Triangles,
            first: l * 6,
            count: 6,
        })
        .collect();
    let what = match kind {
        Fill::Clear => "glClear of color and depth".to_owned(),
        Fill::Flat => format!("{LAYERS} full-screen flat-shaded quads"),
        Fill::Smooth => format!("{LAYERS} full-screen smooth-shaded quads"),
        Fill::Textured => format!(
            "{LAYERS} full-screen quads, 256x256 RGBA texture, LINEAR, MODULATE with smooth colors"
        ),
    };
    let pixels = (w * h) as f64 * layers.max(1) as f64;
    Scene {
        summary: format!("{what} at {w}x{h}; {:.2} Mpix per frame", pixels / 1e6),
        class,
        width: w,
        height: h,
        unit: Unit::Pixels,
        work: pixels,
        vertices: (layers * 6) as f64,
        pixels,
        clear_color: [0.2, 0.3, 0.4, 1.0],
        position: Attr::float(&pos, 3),
        color: Some(Attr::float(&col, 4)),
        normal: None,
        texcoord: [(kind == Fill::Textured).then(|| Attr::float(&tc, 2)), None],
        indices: Vec::new(),
        buffers: false,
        textures,
        lighting: None,
        fog: None,
        setup,
        frame,
    }
}

fn two_lights() -> LightSetup {
    LightSetup {
        lights: vec![
            DirLight {
                direction: [0.5, 0.8, 0.6],
                ambient: [0.1, 0.1, 0.1, 1.0],
                diffuse: [0.8, 0.8, 0.75, 1.0],
                specular: [0.6, 0.6, 0.6, 1.0],
            },
            DirLight {
                direction: [-0.7, -0.2, 0.4],
                ambient: [0.0, 0.0, 0.0, 1.0],
                diffuse: [0.25, 0.3, 0.45, 1.0],
                specular: [0.0, 0.0, 0.0, 1.0],
            },
        ],
        model_ambient: [0.2, 0.2, 0.2, 1.0],
        specular: [0.5, 0.5, 0.5, 1.0],
        shininess: 16.0,
    }
}

/// 100 000 lit smooth triangles: a UV sphere of 500 × 100 quads filling most of the screen,
/// two directional lights, color material from a per-vertex color, depth-tested. Indexed
/// from buffer objects, or the same triangles expanded to 300 000 vertices in client arrays.
/// `offscreen` moves the sphere wholly outside the view volume: what is left is the vertex
/// stage (transform and lighting) and the rejection of every triangle.
fn lit(indexed: bool, offscreen: bool) -> Scene {
    const SLICES: usize = 500;
    const STACKS: usize = 100;
    let (w, h) = (640, 480);
    let (mut pos, mut nrm, mut col) = (Vec::new(), Vec::new(), Vec::new());
    for j in 0..=STACKS {
        let theta = std::f32::consts::PI * j as f32 / STACKS as f32;
        for i in 0..=SLICES {
            let phi = std::f32::consts::TAU * i as f32 / SLICES as f32;
            // A slightly bumpy sphere, so neighbouring triangles differ.
            let bump = 1.0 + 0.04 * (phi * 12.0).sin() * (theta * 9.0).sin();
            let n = Vec3::new(
                theta.sin() * phi.cos(),
                theta.cos(),
                theta.sin() * phi.sin(),
            );
            let p = n * bump;
            pos.extend(p.to_array());
            nrm.extend(n.to_array());
            col.extend([
                0.55 + 0.45 * (phi * 3.0).sin(),
                0.55 + 0.45 * (theta * 4.0).cos(),
                0.6,
                1.0,
            ]);
        }
    }
    let row = SLICES + 1;
    let mut idx: Vec<u16> = Vec::with_capacity(SLICES * STACKS * 6);
    for j in 0..STACKS {
        for i in 0..SLICES {
            let a = (j * row + i) as u16;
            let b = a + 1;
            let c = a + row as u16;
            let d = c + 1;
            idx.extend([a, c, b, b, c, d]);
        }
    }
    let tris = idx.len() / 3;
    let (position, normal, color, indices, frame, vertices);
    if indexed {
        vertices = (pos.len() / 3) as f64;
        position = Attr::float(&pos, 3);
        normal = Attr::float(&nrm, 3);
        color = Attr::float(&col, 4);
        frame = vec![Op::DrawIndexed {
            prim: Primitive::Triangles,
            offset: 0,
            count: idx.len(),
        }];
        indices = idx;
    } else {
        let expand = |v: &[f32], n: usize| -> Vec<f32> {
            idx.iter()
                .flat_map(|&i| v[i as usize * n..i as usize * n + n].iter().copied())
                .collect()
        };
        vertices = idx.len() as f64;
        position = Attr::float(&expand(&pos, 3), 3);
        normal = Attr::float(&expand(&nrm, 3), 3);
        color = Attr::float(&expand(&col, 4), 4);
        frame = vec![Op::Draw {
            prim: Primitive::Triangles,
            first: 0,
            count: idx.len(),
        }];
        indices = Vec::new();
    }
    let x = if offscreen { 8.0 } else { 0.0 };
    let mv = Mat4::from_translation(Vec3::new(x, 0.0, -2.6))
        * Mat4::from_rotation_x(0.5)
        * Mat4::from_rotation_y(0.3);
    let how = match (indexed, offscreen) {
        (true, _) => "indexed (unsigned short) from buffer objects",
        (false, false) => "non-indexed from client arrays",
        (false, true) => "non-indexed from client arrays, all outside the view volume",
    };
    Scene {
        summary: format!(
            "{tris} smooth triangles of a UV sphere, 2 directional lights with specular, color \
             material, depth test, {how}; {} vertices per frame",
            vertices
        ),
        class: if offscreen {
            Class::Scaling
        } else {
            Class::Main
        },
        width: w,
        height: h,
        unit: Unit::Triangles,
        work: tris as f64,
        vertices,
        pixels: (w * h) as f64,
        clear_color: [0.05, 0.05, 0.08, 1.0],
        position,
        color: Some(color),
        normal: Some(normal),
        texcoord: [None, None],
        indices,
        buffers: indexed,
        textures: Vec::new(),
        lighting: Some(two_lights()),
        fog: None,
        setup: vec![
            Op::Projection(Mat4::perspective_rh_gl(0.9, w as f32 / h as f32, 0.5, 20.0)),
            Op::Modelview(mv),
            Op::Enable(Cap::DepthTest, true),
            Op::Enable(Cap::Lighting, true),
        ],
        frame,
    }
}

/// A demo-class frame: a textured, fogged ground of 16 × 16 quads, then 2 000 lit,
/// flat-shaded, alpha-blended cubes in 16.16 fixed point, each with its own modelview and
/// color, in the same fog.
fn demo() -> Scene {
    const OBJECTS: usize = 2000;
    const GRID: usize = 16;
    let (w, h) = (640, 480);
    let mut rng = Lcg(1984);
    let (mut pos, mut nrm, mut tc) = (Vec::new(), Vec::new(), Vec::new());
    // Ground: y = 0, x in [-40, 40], z in [-80, 0], texture repeated every 2.5 units.
    let (x0, z0, side) = (-40.0f32, -80.0f32, 80.0 / GRID as f32);
    for j in 0..GRID {
        for i in 0..GRID {
            let (xa, za) = (x0 + i as f32 * side, z0 + j as f32 * side);
            let (xb, zb) = (xa + side, za + side);
            for (x, z) in [(xa, zb), (xb, zb), (xb, za), (xa, zb), (xb, za), (xa, za)] {
                pos.extend([x, 0.0, z]);
                nrm.extend([0.0, 1.0, 0.0]);
                tc.extend([x / 2.5, z / 2.5]);
            }
        }
    }
    let ground = GRID * GRID * 6;
    // A cube of side 1 on the ground, one normal per face.
    let faces: [([f32; 3], [f32; 3], [f32; 3]); 6] = [
        ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]),
        ([-1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]),
        ([0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]),
        ([0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]),
        ([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
        ([0.0, 0.0, -1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]),
    ];
    for (n, u, v) in faces {
        let (n, u, v) = (Vec3::from(n), Vec3::from(u), Vec3::from(v));
        let c = n * 0.5 + Vec3::new(0.0, 0.5, 0.0);
        let q = [
            c - u * 0.5 - v * 0.5,
            c + u * 0.5 - v * 0.5,
            c + u * 0.5 + v * 0.5,
            c - u * 0.5 + v * 0.5,
        ];
        for k in [0, 1, 2, 0, 2, 3] {
            pos.extend(q[k].to_array());
            nrm.extend(n.to_array());
            tc.extend([0.0, 0.0]);
        }
    }
    let view = Mat4::look_at_rh(
        Vec3::new(0.0, 3.0, 4.0),
        Vec3::new(0.0, 0.5, -12.0),
        Vec3::Y,
    );
    let ground_tex = Tex::new(
        256,
        MinFilter::LinearMipmapNearest,
        MagFilter::Linear,
        |x, y| {
            let stone = ((x / 32 + y / 32) % 2) as u8 * 60;
            let n = ((x * 7919 + y * 104729) % 61) as u8;
            [90 + stone + n, 110 + stone / 2 + n, 70 + n, 255]
        },
    );
    let mut frame = vec![
        Op::Modelview(view),
        Op::Enable(Cap::Lighting, false),
        Op::Enable(Cap::Blend, false),
        Op::Color([1.0; 4]),
        Op::Texture {
            unit: 0,
            tex: Some(0),
            env: modulate(),
            coord_replace: false,
        },
        Op::Draw {
            prim: Primitive::Triangles,
            first: 0,
            count: ground,
        },
        Op::Texture {
            unit: 0,
            tex: None,
            env: modulate(),
            coord_replace: false,
        },
        Op::Enable(Cap::Lighting, true),
        Op::Enable(Cap::Blend, true),
    ];
    for _ in 0..OBJECTS {
        // Each at its own height: cubes of one height would have coplanar tops, and the
        // ground and the bottoms too, whose depth fight no two renderers settle alike.
        let lift = 0.02 + rng.next() * 0.6;
        let at = Vec3::new(rng.next() * 50.0 - 25.0, lift, -rng.next() * 60.0 - 2.0);
        let turn = rng.next() * std::f32::consts::TAU;
        let c = [
            0.3 + rng.next() * 0.7,
            0.3 + rng.next() * 0.7,
            0.3 + rng.next() * 0.7,
            0.75,
        ];
        frame.push(Op::Modelview(
            view * Mat4::from_translation(at) * Mat4::from_rotation_y(turn),
        ));
        frame.push(Op::Color(c));
        frame.push(Op::Draw {
            prim: Primitive::Triangles,
            first: ground,
            count: 36,
        });
    }
    let tris = ground / 3 + OBJECTS * 12;
    Scene {
        summary: format!(
            "{GRID}x{GRID}-quad textured ground (LINEAR_MIPMAP_NEAREST) + {OBJECTS} lit \
             flat-shaded alpha-blended cubes (own modelview and glColor each), 16.16 fixed-point \
             arrays, linear fog, 640x480; {tris} triangles, {} draws per frame",
            OBJECTS + 1
        ),
        class: Class::Main,
        width: w,
        height: h,
        unit: Unit::Triangles,
        work: tris as f64,
        vertices: (ground + OBJECTS * 36) as f64,
        pixels: (w * h) as f64,
        clear_color: [0.6, 0.65, 0.75, 1.0],
        position: Attr::fixed(&pos, 3),
        color: None,
        normal: Some(Attr::fixed(&nrm, 3)),
        texcoord: [Some(Attr::fixed(&tc, 2)), None],
        indices: Vec::new(),
        buffers: false,
        textures: vec![ground_tex],
        lighting: Some(two_lights()),
        fog: Some(FogSetup {
            start: 8.0,
            end: 60.0,
            color: [0.6, 0.65, 0.75, 1.0],
        }),
        setup: vec![
            Op::Projection(Mat4::perspective_rh_gl(
                1.0,
                w as f32 / h as f32,
                0.5,
                100.0,
            )),
            Op::Enable(Cap::DepthTest, true),
            Op::Enable(Cap::Fog, true),
            Op::Shade(ShadeModel::Flat),
            Op::BlendFunc(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha),
            Op::ColorArray(false),
        ],
        frame,
    }
}

/// A tunnel filling the screen, two trilinear-filtered (LINEAR_MIPMAP_LINEAR) textures:
/// unit 0 MODULATE, unit 1 COMBINE INTERPOLATE(texture, previous, primary alpha).
fn multitexture() -> Scene {
    const SEGMENTS: usize = 12;
    let (w, h) = (640, 480);
    let mut rng = Lcg(303);
    let (mut pos, mut col, mut tc0, mut tc1) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    // Four walls of a 4 × 3 box from z = 0 to -48, then the far wall.
    let (hw, hh, depth) = (2.0f32, 1.5f32, 48.0f32);
    let walls: [([f32; 2], [f32; 2], f32); 4] = [
        ([-hw, -hh], [hw, -hh], 2.0 * hw),
        ([hw, -hh], [hw, hh], 2.0 * hh),
        ([hw, hh], [-hw, hh], 2.0 * hw),
        ([-hw, hh], [-hw, -hh], 2.0 * hh),
    ];
    for (a, b, across) in walls {
        for s in 0..SEGMENTS {
            let (za, zb) = (
                -depth * s as f32 / SEGMENTS as f32,
                -depth * (s + 1) as f32 / SEGMENTS as f32,
            );
            let c: Vec<[f32; 4]> = (0..4)
                .map(|_| {
                    [
                        0.7 + rng.next() * 0.3,
                        0.7 + rng.next() * 0.3,
                        0.8,
                        rng.next(),
                    ]
                })
                .collect();
            let q = [(a, za, 0.0), (b, za, across), (b, zb, across), (a, zb, 0.0)];
            for k in [0, 1, 2, 0, 2, 3] {
                let (p, z, u) = q[k];
                pos.extend([p[0], p[1], z]);
                col.extend(c[k]);
                tc0.extend([u / 2.0, -z / 2.0]);
                tc1.extend([u / 0.7, -z / 0.9]);
            }
        }
    }
    for k in [0, 1, 2, 0, 2, 3] {
        let p = [[-hw, -hh], [hw, -hh], [hw, hh], [-hw, hh]][k];
        pos.extend([p[0], p[1], -depth]);
        col.extend([1.0, 1.0, 1.0, 0.5]);
        tc0.extend([p[0] / 2.0, p[1] / 2.0]);
        tc1.extend([p[0], p[1]]);
    }
    let count = pos.len() / 3;
    let base = Tex::new(
        256,
        MinFilter::LinearMipmapLinear,
        MagFilter::Linear,
        |x, y| {
            let brick = (((y / 16) % 2) * 16 + x) / 32 + y / 16;
            let mortar = y % 16 == 0 || (x + ((y / 16) % 2) * 16) % 32 == 0;
            if mortar {
                [200, 200, 190, 255]
            } else {
                [
                    150 + (brick % 5) as u8 * 20,
                    70 + (brick % 3) as u8 * 15,
                    50,
                    255,
                ]
            }
        },
    );
    let detail = Tex::new(
        64,
        MinFilter::LinearMipmapLinear,
        MagFilter::Linear,
        |x, y| {
            let v = (((x * 37 + y * 91) ^ (x * y)) % 96) as u8 + 120;
            [v, v, (v / 2) + 100, 255]
        },
    );
    let interpolate = Combine {
        rgb: CombineFunc::Interpolate,
        alpha: CombineFunc::Replace,
        src_rgb: [Source::Texture, Source::Previous, Source::PrimaryColor],
        src_alpha: [Source::Previous, Source::Previous, Source::Previous],
        operand_rgb: [Operand::SrcColor, Operand::SrcColor, Operand::SrcAlpha],
        operand_alpha: [Operand::SrcAlpha, Operand::SrcAlpha, Operand::SrcAlpha],
        rgb_scale: 1.0,
        alpha_scale: 1.0,
    };
    let tris = count / 3;
    Scene {
        summary: format!(
            "a tunnel of {tris} triangles covering the 640x480 screen, two textures \
             (256x256 and 64x64, LINEAR_MIPMAP_LINEAR, REPEAT): unit 0 MODULATE, unit 1 \
             COMBINE INTERPOLATE(texture, previous, primary alpha); Mpix/s counts one screen"
        ),
        class: Class::Main,
        width: w,
        height: h,
        unit: Unit::Pixels,
        work: (w * h) as f64,
        vertices: count as f64,
        pixels: (w * h) as f64,
        clear_color: [0.0, 0.0, 0.0, 1.0],
        position: Attr::float(&pos, 3),
        color: Some(Attr::float(&col, 4)),
        normal: None,
        texcoord: [Some(Attr::float(&tc0, 2)), Some(Attr::float(&tc1, 2))],
        indices: Vec::new(),
        buffers: false,
        textures: vec![base, detail],
        lighting: None,
        fog: None,
        setup: vec![
            Op::Projection(Mat4::perspective_rh_gl(
                1.1,
                w as f32 / h as f32,
                0.25,
                60.0,
            )),
            // Off-center and turned a little, so no corner of the tunnel runs exactly
            // through pixel centers (where which wall owns a pixel is a tie).
            Op::Modelview(
                Mat4::from_rotation_y(0.031)
                    * Mat4::from_translation(Vec3::new(0.2137, -0.1419, -0.3)),
            ),
            Op::Enable(Cap::DepthTest, true),
            Op::Texture {
                unit: 0,
                tex: Some(0),
                env: modulate(),
                coord_replace: false,
            },
            Op::Texture {
                unit: 1,
                tex: Some(1),
                env: TexEnv {
                    mode: EnvMode::Combine(interpolate),
                    color: [0.0; 4],
                },
                coord_replace: false,
            },
        ],
        frame: vec![Op::Draw {
            prim: Primitive::Triangles,
            first: 0,
            count,
        }],
    }
}

/// 18 000 point sprites of sizes 4 to 32 with a 32 × 32 radial texture (LINEAR, MODULATE
/// with the point color), additively blended (SRC_ALPHA, ONE), no depth test.
fn sprites() -> Scene {
    let groups: [(usize, f32); 4] = [(8000, 4.0), (6000, 8.0), (3000, 16.0), (1000, 32.0)];
    let (w, h) = (640, 480);
    let mut rng = Lcg(77);
    let (mut pos, mut col) = (Vec::new(), Vec::new());
    let mut frame = Vec::new();
    let mut pixels = 0.0;
    for (n, size) in groups {
        let first = pos.len() / 3;
        for _ in 0..n {
            // A quarter pixel off the centers and edges, so no snapping rule is on a tie.
            let x = (rng.next() * (w - 8) as f32).floor() + 4.25;
            let y = (rng.next() * (h - 8) as f32).floor() + 4.25;
            pos.extend([x, y, 0.0]);
            col.extend([
                0.5 + rng.next() * 0.5,
                0.3 + rng.next() * 0.6,
                0.1 + rng.next() * 0.5,
                // Faint, so 7 screens of additive overdraw stay mostly below saturation.
                0.04 + rng.next() * 0.12,
            ]);
        }
        pixels += n as f64 * (size * size) as f64;
        frame.push(Op::PointSize(size));
        frame.push(Op::Draw {
            prim: Primitive::Points,
            first,
            count: n,
        });
    }
    let count = pos.len() / 3;
    let blob = Tex::new(32, MinFilter::Linear, MagFilter::Linear, |x, y| {
        let (dx, dy) = (x as f32 - 15.5, y as f32 - 15.5);
        let d = (dx * dx + dy * dy).sqrt() / 16.0;
        let a = ((1.0 - d).max(0.0) * 255.0) as u8;
        [255, 255 - a / 3, 200 - a / 2, a]
    });
    Scene {
        summary: format!(
            "{count} point sprites (sizes 4, 8, 16, 32), 32x32 RGBA texture with COORD_REPLACE, \
             LINEAR, MODULATE, blend SRC_ALPHA + ONE, no depth; {:.2} Mpix per frame",
            pixels / 1e6
        ),
        class: Class::Main,
        width: w,
        height: h,
        unit: Unit::Points,
        work: count as f64,
        vertices: count as f64,
        pixels,
        clear_color: [0.0, 0.0, 0.05, 1.0],
        position: Attr::float(&pos, 3),
        color: Some(Attr::float(&col, 4)),
        normal: None,
        texcoord: [None, None],
        indices: Vec::new(),
        buffers: false,
        textures: vec![blob],
        lighting: None,
        fog: None,
        setup: vec![
            Op::Projection(pixel_ortho(w, h)),
            Op::Modelview(Mat4::IDENTITY),
            Op::Enable(Cap::DepthTest, false),
            Op::Enable(Cap::Blend, true),
            Op::BlendFunc(BlendFactor::SrcAlpha, BlendFactor::One),
            Op::Enable(Cap::PointSprite, true),
            Op::Texture {
                unit: 0,
                tex: Some(0),
                env: modulate(),
                coord_replace: true,
            },
        ],
        frame,
    }
}

/// `n` small smooth triangles (right triangles with 4-pixel legs: 8 pixels each) at random
/// places and depths, depth-tested, from client arrays: the per-triangle cost.
fn small_triangles(n: usize) -> Scene {
    let (w, h) = (640, 480);
    let mut rng = Lcg(n as u64);
    let mut pos = Vec::with_capacity(n * 9);
    let mut col = Vec::with_capacity(n * 12);
    for _ in 0..n {
        let x = (rng.next() * (w - 6) as f32).floor() + 1.0;
        let y = (rng.next() * (h - 6) as f32).floor() + 1.0;
        let z = rng.next() * 1.8 - 0.9;
        for (dx, dy) in [(0.0, 0.0), (4.0, 0.0), (0.0, 4.0)] {
            pos.extend([x + dx, y + dy, z]);
            col.extend(rgb(&mut rng));
        }
    }
    Scene {
        summary: format!(
            "{n} smooth depth-tested triangles of 8 pixels each, client arrays, 640x480"
        ),
        class: Class::Scaling,
        width: w,
        height: h,
        unit: Unit::Triangles,
        work: n as f64,
        vertices: (n * 3) as f64,
        pixels: (n * 8) as f64,
        clear_color: [0.0, 0.0, 0.0, 1.0],
        position: Attr::float(&pos, 3),
        color: Some(Attr::float(&col, 4)),
        normal: None,
        texcoord: [None, None],
        indices: Vec::new(),
        buffers: false,
        textures: Vec::new(),
        lighting: None,
        fog: None,
        setup: vec![
            Op::Projection(pixel_ortho(w, h)),
            Op::Modelview(Mat4::IDENTITY),
            Op::Enable(Cap::DepthTest, true),
        ],
        frame: vec![Op::Draw {
            prim: Primitive::Triangles,
            first: 0,
            count: n * 3,
        }],
    }
}
