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
use gles_cm_core::state::{Blend, BlendFactor, CullFace, Quality, ShadeModel, Winding};
use gles_cm_core::texenv::{
    Combine, CombineFunc, EnvMode, Fog, FogMode, Operand, Source, TexEnv, TextureUnit,
};
use gles_cm_core::texture::{BaseFormat, Image, MagFilter, MinFilter, Sampler, Wrap};
use gles_cm_core::{
    AttribArray, AttribSource, ColorFormat, CompareFunc, ComponentType, DepthFormat, DrawCall,
    Indices, Primitive, RenderState, Target, TargetFormat,
};
use GLES_CM::gles::tokens::{GL_DONT_CARE, GL_FASTEST, GL_NICEST};
use GLES_CM::gles::types::GLenum;

/// The GL scenes, in table order: the main ones, the app-class ones (each at RGB565 with
/// dithering, the default state, and at RGBA8888), then those only the scaling table uses.
pub const NAMES: [&str; 33] = [
    "clear-640",
    "flat-640",
    "smooth-640",
    "texture-640",
    "texture-npot-640",
    "clear-1280",
    "flat-1280",
    "smooth-1280",
    "texture-1280",
    "lit-vbo",
    "lit-arrays",
    "lit-point",
    "demo",
    "multitexture",
    "sprites",
    "flythrough-565",
    "flythrough-8888",
    "gears-300-565",
    "gears-300-8888",
    "gears-1280-565",
    "gears-1280-8888",
    "ui-2d-565",
    "ui-2d-8888",
    "draws-10k-565",
    "draws-10k-8888",
    "state-churn-565",
    "state-churn-8888",
    "smooth-320",
    "lit-offscreen",
    "tris-1k",
    "tris-10k",
    "tris-100k",
    "tris-1m",
];

/// The M3G scenes (not GL scenes: they go through `m3g::Graphics3D`): one animated file,
/// and every file of the corpus.
pub const M3G: &str = "m3g-robot";
pub const M3G_CORPUS: &str = "m3g-corpus";

pub fn is_m3g(name: &str) -> bool {
    name == M3G || name == M3G_CORPUS
}

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
    /// Integer components read as fractions of their maximum (colors always are in GL).
    pub normalized: bool,
}

impl Attr {
    fn float(v: &[f32], size: usize) -> Attr {
        Attr {
            data: v.iter().flat_map(|x| x.to_ne_bytes()).collect(),
            ty: ComponentType::Float,
            size,
            normalized: false,
        }
    }

    /// Unsigned bytes, normalized: what colors in `GL_UNSIGNED_BYTE` are.
    fn ubyte(v: &[u8], size: usize) -> Attr {
        Attr {
            data: v.to_vec(),
            ty: ComponentType::UnsignedByte,
            size,
            normalized: true,
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
            normalized: false,
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
            normalized: self.normalized,
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

/// One directional or positional light, set in eye coordinates (the modelview is the
/// identity then); no attenuation, no spot.
pub struct DirLight {
    /// Towards the light (directional), or where it is (`point`).
    pub direction: [f32; 3],
    pub point: bool,
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
    /// Back faces culled.
    CullFace,
    Normalize,
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
    FrontFace(Winding),
    /// `glBindTexture` of texture `tex` on unit 0, its environment unchanged.
    Bind(usize),
    /// `glDrawTexfOES(x, y, 0, w, h)` of the texture bound on unit 0, after setting its
    /// crop rectangle (texels: x, y, width, height).
    DrawTex {
        rect: [f32; 4],
        crop: [i32; 4],
    },
}

/// What the throughput column counts.
#[derive(Clone, Copy)]
pub enum Unit {
    Pixels,
    Triangles,
    Points,
    /// Draw calls: shown as ns per draw.
    Draws,
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
    /// The pbuffer's color format: RGBA8888 with depth 24, or RGB565 with depth 16.
    pub format: ColorFormat,
    /// `GL_DITHER` left at its default (enabled) rather than disabled.
    pub dither: bool,
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
            "texture-npot-640" => fill(Fill::TexturedNpot, 640, 480, Class::Main),
            "clear-1280" => fill(Fill::Clear, 1280, 960, Class::Main),
            "flat-1280" => fill(Fill::Flat, 1280, 960, Class::Main),
            "smooth-1280" => fill(Fill::Smooth, 1280, 960, Class::Main),
            "texture-1280" => fill(Fill::Textured, 1280, 960, Class::Main),
            "smooth-320" => fill(Fill::Smooth, 320, 240, Class::Scaling),
            "lit-vbo" => lit(true, false, false),
            "lit-arrays" => lit(false, false, false),
            "lit-point" => lit(false, false, true),
            "lit-offscreen" => lit(false, true, false),
            "demo" => demo(),
            "multitexture" => multitexture(),
            "sprites" => sprites(),
            "tris-1k" => small_triangles(1_000),
            "tris-10k" => small_triangles(10_000),
            "tris-100k" => small_triangles(100_000),
            "tris-1m" => small_triangles(1_000_000),
            "flythrough-565" => flythrough(ColorFormat::Rgb565),
            "flythrough-8888" => flythrough(ColorFormat::Rgba8888),
            "gears-300-565" => gears(300, 300, ColorFormat::Rgb565),
            "gears-300-8888" => gears(300, 300, ColorFormat::Rgba8888),
            "gears-1280-565" => gears(1280, 960, ColorFormat::Rgb565),
            "gears-1280-8888" => gears(1280, 960, ColorFormat::Rgba8888),
            "ui-2d-565" => ui_2d(ColorFormat::Rgb565),
            "ui-2d-8888" => ui_2d(ColorFormat::Rgba8888),
            "draws-10k-565" => draws(ColorFormat::Rgb565),
            "draws-10k-8888" => draws(ColorFormat::Rgba8888),
            "state-churn-565" => state_churn(ColorFormat::Rgb565),
            "state-churn-8888" => state_churn(ColorFormat::Rgba8888),
            _ => return None,
        })
    }

    pub fn throughput(&self, seconds: f64) -> String {
        let rate = self.work / seconds / 1e6;
        match self.unit {
            Unit::Pixels => format!("{rate:.0} Mpix/s"),
            Unit::Triangles => format!("{rate:.2} Mtris/s"),
            Unit::Points => format!("{rate:.2} Mpts/s"),
            Unit::Draws => format!("{:.0} ns/draw", seconds * 1e9 / self.work),
        }
    }

    /// The reference's target: exact 8-bit channels, without alpha when the pbuffer has
    /// none (RGB565), so alpha read back as 1 is not counted as error.
    pub fn target(&self) -> Target {
        let mut t = target(self.width, self.height);
        if self.format == ColorFormat::Rgb565 {
            t = Target::new(
                self.width,
                self.height,
                TargetFormat {
                    color: ColorFormat::Rgb888,
                    ..t.format()
                },
            );
        }
        t
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
        let mut normalize = false;
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
                    Cap::CullFace => rs.cull = on.then_some(CullFace::Back),
                    Cap::Normalize => normalize = *on,
                },
                Op::FrontFace(w) => rs.front_face = *w,
                Op::Bind(i) => {
                    if let Some(u) = &mut rs.textures[0] {
                        u.sampler = samplers[*i].clone();
                    }
                }
                Op::DrawTex { rect, crop } => {
                    rs.blend = blending.then_some(blend);
                    self.reference_draw_tex(&rs, *rect, *crop, current, &mut t);
                }
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
                    let lit = lighting.then_some(normalize);
                    self.reference_draw(&rs, *prim, ix, lit, color_array, current, &mut t);
                }
                Op::DrawIndexed {
                    prim,
                    offset,
                    count,
                } => {
                    rs.blend = blending.then_some(blend);
                    let ix = Indices::U16(&self.indices[*offset..*offset + *count]);
                    let lit = lighting.then_some(normalize);
                    self.reference_draw(&rs, *prim, ix, lit, color_array, current, &mut t);
                }
            }
        }
        t
    }

    /// `lighting`: `Some(normalize)` when lit.
    #[allow(clippy::too_many_arguments)]
    fn reference_draw(
        &self,
        rs: &RenderState,
        prim: Primitive,
        ix: Indices<'_>,
        lighting: Option<bool>,
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
        let lit: Option<Attr> = lighting.map(|normalize| {
            let setup = self.lighting.as_ref().expect("a lit scene has LightSetup");
            let normals = self.normal.as_ref().expect("a lit scene has normals");
            let n = self.position.data.len() / self.position.stride();
            let mut out = vec![0.0f32; n * 4];
            for k in 0..ix.len() {
                let i = ix.get(k);
                let c = light_vertex(
                    setup,
                    &rs.modelview,
                    self.position.array().fetch(i),
                    normals.array().fetch(i),
                    base_color(i),
                    normalize,
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
            gles_cm_core::reference::render(rs, &call, t);
        }
    }
}

impl Scene {
    /// `glDrawTexOES` for the reference: the screen rectangle as two triangles through a
    /// pixel-space projection with the current color, the crop rectangle's texture
    /// coordinates at its corners (OES_draw_texture: affine in window x and y), no lighting,
    /// culling or depth test.
    fn reference_draw_tex(
        &self,
        rs: &RenderState,
        [x, y, w, h]: [f32; 4],
        [cx, cy, cw, ch]: [i32; 4],
        current: [f32; 4],
        t: &mut Target,
    ) {
        let Some(unit) = &rs.textures[0] else {
            return;
        };
        let base = &unit.sampler.levels[0];
        let (tw, th) = (base.width as f32, base.height as f32);
        let (s0, s1) = (cx as f32 / tw, (cx + cw) as f32 / tw);
        let (t0, t1) = (cy as f32 / th, (cy + ch) as f32 / th);
        let corners = [
            (x, y, s0, t0),
            (x + w, y, s1, t0),
            (x + w, y + h, s1, t1),
            (x, y, s0, t0),
            (x + w, y + h, s1, t1),
            (x, y + h, s0, t1),
        ];
        let (mut pos, mut tc) = (Vec::new(), Vec::new());
        for (px, py, s, tt) in corners {
            pos.extend([px, py, 0.0]);
            tc.extend([s, tt]);
        }
        let (pos, tc) = (Attr::float(&pos, 3), Attr::float(&tc, 2));
        let mut call = DrawCall::new(
            Primitive::Triangles,
            Indices::Range { first: 0, count: 6 },
            pos.array(),
        );
        call.color = AttribSource::Constant(current);
        call.texcoord[0] = AttribSource::Array(tc.array());
        let mut qs = rs.clone();
        qs.cull = None;
        qs.depth_test = None;
        qs.modelview = Mat4::IDENTITY;
        qs.projection = pixel_ortho(self.width, self.height);
        for u in qs.textures.iter_mut().skip(1) {
            *u = None;
        }
        gles_cm_core::reference::render(&qs, &call, t);
    }
}

/// The lit color (clamped) of a vertex at object position `p` with object normal `n` and
/// color-material color `c` under `mv` (`normalize`: `GL_NORMALIZE`): ES 1.1 §2.12.1 with
/// attenuation and spot factors 1 and a viewer at infinity.
fn light_vertex(
    setup: &LightSetup,
    mv: &Mat4,
    p: [f32; 4],
    n: [f32; 4],
    c: [f32; 4],
    normalize: bool,
) -> [f32; 4] {
    let m = DMat3::from_mat4(mv.as_dmat4()).inverse().transpose();
    let mut n = m * DVec3::new(n[0] as f64, n[1] as f64, n[2] as f64);
    if normalize {
        n = n.normalize_or_zero();
    }
    let eye = mv.as_dmat4() * DVec4::from_array(p.map(f64::from));
    let eye = eye.truncate() / eye.w;
    let c4 = DVec4::from_array(c.map(f64::from));
    let v4 = |a: [f32; 4]| DVec4::from_array(a.map(f64::from));
    let mut sum = c4 * v4(setup.model_ambient);
    for l in &setup.lights {
        let to = DVec3::from_array(l.direction.map(f64::from));
        let vp = if l.point { to - eye } else { to }.normalize();
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
    gles_cm_core::reference::render(&qs, &quads, t);
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
    /// As `Textured` with a 300 × 300 texture (`OES_texture_npot`): what sizes other than
    /// powers of two cost.
    TexturedNpot,
}

/// Full-screen quads, no depth test, each layer covering the previous one (clear: the
/// frame's `glClear` alone).
fn fill(kind: Fill, w: u32, h: u32, class: Class) -> Scene {
    const LAYERS: usize = 4;
    let mut rng = Lcg(640 + w as u64);
    let layers = if kind == Fill::Clear { 0 } else { LAYERS };
    let textured = matches!(kind, Fill::Textured | Fill::TexturedNpot);
    let side: u32 = if kind == Fill::TexturedNpot { 300 } else { 256 };
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
            tc.extend([x / side as f32, y / side as f32]);
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
        Fill::Textured | Fill::TexturedNpot => {
            textures.push(Tex::new(
                side,
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
        Fill::Textured | Fill::TexturedNpot => format!(
            "{LAYERS} full-screen quads, {side}x{side} RGBA texture, LINEAR, REPEAT, MODULATE with smooth colors"
        ),
    };
    let pixels = (w * h) as f64 * layers.max(1) as f64;
    Scene {
        summary: format!("{what} at {w}x{h}; {:.2} Mpix per frame", pixels / 1e6),
        class,
        width: w,
        height: h,
        format: ColorFormat::Rgba8888,
        dither: false,
        unit: Unit::Pixels,
        work: pixels,
        vertices: (layers * 6) as f64,
        pixels,
        clear_color: [0.2, 0.3, 0.4, 1.0],
        position: Attr::float(&pos, 3),
        color: Some(Attr::float(&col, 4)),
        normal: None,
        texcoord: [textured.then(|| Attr::float(&tc, 2)), None],
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
                point: false,
                ambient: [0.1, 0.1, 0.1, 1.0],
                diffuse: [0.8, 0.8, 0.75, 1.0],
                specular: [0.6, 0.6, 0.6, 1.0],
            },
            DirLight {
                direction: [-0.7, -0.2, 0.4],
                point: false,
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
/// stage (transform and lighting) and the rejection of every triangle. `point` makes the
/// first light positional (at (0.5, 0.8, 0.6) in eye space, in front of the sphere).
fn lit(indexed: bool, offscreen: bool, point: bool) -> Scene {
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
            "{tris} smooth triangles of a UV sphere, 2 {} lights with specular, color \
             material, depth test, {how}; {} vertices per frame",
            if point {
                "(a positional and a directional)"
            } else {
                "directional"
            },
            vertices
        ),
        class: if offscreen {
            Class::Scaling
        } else {
            Class::Main
        },
        width: w,
        height: h,
        format: ColorFormat::Rgba8888,
        dither: false,
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
        lighting: Some({
            let mut l = two_lights();
            l.lights[0].point = point;
            l
        }),
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
        format: ColorFormat::Rgba8888,
        dither: false,
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
        format: ColorFormat::Rgba8888,
        dither: false,
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
        format: ColorFormat::Rgba8888,
        dither: false,
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
        format: ColorFormat::Rgba8888,
        dither: false,
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

/// Vertex arrays built up draw by draw: positions, normals, colors (bytes), texture
/// coordinates, one entry per vertex in each.
#[derive(Default)]
struct Arrays {
    pos: Vec<f32>,
    nrm: Vec<f32>,
    col: Vec<u8>,
    tc: Vec<f32>,
}

impl Arrays {
    fn len(&self) -> usize {
        self.pos.len() / 3
    }

    fn push(&mut self, p: Vec3, n: Vec3, c: [u8; 4], st: [f32; 2]) {
        self.pos.extend(p.to_array());
        self.nrm.extend(n.to_array());
        self.col.extend(c);
        self.tc.extend(st);
    }

    /// A triangle with its face normal at every vertex (flat-shaded models carry these).
    fn face(&mut self, [a, b, c]: [Vec3; 3], color: [u8; 4]) {
        let n = (b - a).cross(c - a).normalize_or_zero();
        for p in [a, b, c] {
            self.push(p, n, color, [0.0; 2]);
        }
    }

    /// An axis-aligned rectangle as two counter-clockwise triangles at z = 0.
    fn rect(&mut self, [x0, y0, x1, y1]: [f32; 4], st: [f32; 4]) -> (usize, usize) {
        let first = self.len();
        let corners = [
            (x0, y0, st[0], st[1]),
            (x1, y0, st[2], st[1]),
            (x1, y1, st[2], st[3]),
            (x0, y0, st[0], st[1]),
            (x1, y1, st[2], st[3]),
            (x0, y1, st[0], st[3]),
        ];
        for (x, y, s, t) in corners {
            self.push(Vec3::new(x, y, 0.0), Vec3::Z, [255; 4], [s, t]);
        }
        (first, 6)
    }
}

fn bits_name(format: ColorFormat) -> &'static str {
    if format == ColorFormat::Rgb565 {
        "RGB565 + depth 16, dither on (the default)"
    } else {
        "RGBA8888 + depth 24, dither on (the default; no effect at 8 bits)"
    }
}

fn draw(first: usize, count: usize) -> Op {
    Op::Draw {
        prim: Primitive::Triangles,
        first,
        count,
    }
}

/// The classic GLES 1.x flythrough demo frame of issue 20: a few dozen flat-shaded objects
/// (200 to 2 000 triangles each, each its own `glDrawArrays` under its own modelview, scaled
/// unevenly so `GL_NORMALIZE` matters) lit by three directional lights with color
/// material; `GL_FIXED` positions and normals, `GL_UNSIGNED_BYTE` colors; first their
/// reflection (mirrored modelview, front face CW, blended), then a translucent floor over
/// it, then the objects, then two full-screen alpha-blended fade quads.
fn flythrough(format: ColorFormat) -> Scene {
    const OBJECTS: usize = 24;
    let (w, h) = (640, 480);
    let mut rng = Lcg(1997);
    let mut a = Arrays::default();
    // The floor, y = 0, translucent so the reflection shows through.
    let floor_first = a.len();
    let (fx, fz) = (16.0f32, 48.0f32);
    let grid = 8;
    for j in 0..grid {
        for i in 0..grid {
            let x0 = -fx + 2.0 * fx * i as f32 / grid as f32;
            let x1 = x0 + 2.0 * fx / grid as f32;
            let z0 = -fz * j as f32 / grid as f32;
            let z1 = z0 - fz / grid as f32;
            let c = if (i + j) % 2 == 0 {
                [70, 90, 120, 150]
            } else {
                [150, 150, 140, 150]
            };
            let (p00, p10) = (Vec3::new(x0, 0.0, z0), Vec3::new(x1, 0.0, z0));
            let (p01, p11) = (Vec3::new(x0, 0.0, z1), Vec3::new(x1, 0.0, z1));
            a.face([p00, p10, p11], c);
            a.face([p00, p11, p01], c);
        }
    }
    let floor_count = a.len() - floor_first;
    // The objects: bumpy closed surfaces of `slices` × `stacks` quads.
    let mut objects = Vec::new();
    let mut tris = 0;
    for k in 0..OBJECTS {
        let slices = 10 + (rng.next() * 30.0) as usize;
        let stacks = 5 + (rng.next() * 20.0) as usize;
        let (f1, f2, ph) = (
            2.0 + (rng.next() * 4.0).floor(),
            1.0 + (rng.next() * 3.0).floor(),
            rng.next() * 6.0,
        );
        let base = [
            60 + (rng.next() * 195.0) as u8,
            60 + (rng.next() * 195.0) as u8,
            60 + (rng.next() * 195.0) as u8,
            170,
        ];
        let at = |i: usize, j: usize| {
            let phi = std::f32::consts::TAU * i as f32 / slices as f32;
            let theta = std::f32::consts::PI * j as f32 / stacks as f32;
            let r = 1.0 + 0.2 * (phi * f1 + ph).sin() * (theta * f2).sin();
            Vec3::new(
                r * theta.sin() * phi.cos(),
                r * theta.cos(),
                r * theta.sin() * phi.sin(),
            )
        };
        let first = a.len();
        for j in 0..stacks {
            for i in 0..slices {
                let (p00, p10) = (at(i, j), at(i + 1, j));
                let (p01, p11) = (at(i, j + 1), at(i + 1, j + 1));
                let shade = (i * 7 + j * 3) % 5 * 8;
                let c = [
                    base[0].saturating_sub(shade as u8),
                    base[1].saturating_sub(shade as u8),
                    base[2],
                    base[3],
                ];
                // Outward-facing, counter-clockwise seen from outside.
                if j > 0 {
                    a.face([p00, p10, p11], c);
                    tris += 1;
                }
                if j + 1 < stacks {
                    a.face([p00, p11, p01], c);
                    tris += 1;
                }
            }
        }
        let scale = Vec3::new(
            0.5 + rng.next() * 1.1,
            0.5 + rng.next() * 1.3,
            0.5 + rng.next() * 1.1,
        );
        let side = if k % 2 == 0 { -1.0 } else { 1.0 };
        let pos = Vec3::new(
            side * (2.0 + rng.next() * 9.0),
            scale.y + 0.05 + rng.next() * 0.5,
            -3.0 - 44.0 * (k as f32 + rng.next()) / OBJECTS as f32,
        );
        let model = Mat4::from_translation(pos)
            * Mat4::from_rotation_y(rng.next() * std::f32::consts::TAU)
            * Mat4::from_rotation_x(rng.next() * 0.5)
            * Mat4::from_scale(scale);
        objects.push((model, first, a.len() - first));
    }
    // Full-screen fade quads in a unit orthographic projection.
    let fade = a.rect([0.0, 0.0, 1.0, 1.0], [0.0; 4]);
    let view = Mat4::look_at_rh(
        Vec3::new(1.0, 2.6, 4.0),
        Vec3::new(-1.0, 1.2, -24.0),
        Vec3::new(0.05, 1.0, 0.0),
    );
    let mirror = Mat4::from_scale(Vec3::new(1.0, -1.0, 1.0));
    let projection = Mat4::perspective_rh_gl(1.0, w as f32 / h as f32, 0.5, 80.0);
    let mut frame = vec![
        Op::Projection(projection),
        Op::Enable(Cap::DepthTest, true),
        Op::Enable(Cap::CullFace, true),
        Op::Enable(Cap::Lighting, true),
        Op::ColorArray(true),
        // The reflection: winding flips under the mirror, so the front face does too.
        Op::FrontFace(Winding::Cw),
        Op::Enable(Cap::Blend, true),
    ];
    for &(model, first, count) in &objects {
        frame.push(Op::Modelview(view * mirror * model));
        frame.push(draw(first, count));
    }
    frame.extend([
        Op::FrontFace(Winding::Ccw),
        Op::Modelview(view),
        draw(floor_first, floor_count),
        Op::Enable(Cap::Blend, false),
    ]);
    for &(model, first, count) in &objects {
        frame.push(Op::Modelview(view * model));
        frame.push(draw(first, count));
    }
    frame.extend([
        Op::Enable(Cap::Lighting, false),
        Op::Enable(Cap::DepthTest, false),
        Op::ColorArray(false),
        Op::Projection(Mat4::orthographic_rh_gl(0.0, 1.0, 0.0, 1.0, -1.0, 1.0)),
        Op::Modelview(Mat4::IDENTITY),
        Op::Enable(Cap::Blend, true),
        Op::Color([0.05, 0.05, 0.15, 0.3]),
        draw(fade.0, fade.1),
        Op::Color([1.0, 0.85, 0.6, 0.12]),
        draw(fade.0, fade.1),
        Op::Enable(Cap::Blend, false),
    ]);
    let tris = 2 * tris + floor_count / 3 + 4;
    let draws = 2 * OBJECTS + 3;
    Scene {
        summary: format!(
            "flythrough (issue 20's demo): {OBJECTS} flat-shaded objects (200-2000 triangles, \
             own modelview and glDrawArrays each), 3 directional lights, color material, \
             GL_NORMALIZE, GL_FIXED positions and normals, GL_UNSIGNED_BYTE colors, back faces \
             culled; a mirrored blended pass (front face CW), a translucent floor, the objects, \
             2 full-screen blended fade quads; {}, 640x480; {tris} triangles, {draws} draws \
             per frame",
            bits_name(format)
        ),
        class: Class::Main,
        width: w,
        height: h,
        format,
        dither: true,
        unit: Unit::Triangles,
        work: tris as f64,
        vertices: (a.len() * 2) as f64,
        pixels: (w * h * 4) as f64,
        clear_color: [0.35, 0.45, 0.6, 1.0],
        position: Attr::fixed(&a.pos, 3),
        color: Some(Attr::ubyte(&a.col, 4)),
        normal: Some(Attr::fixed(&a.nrm, 3)),
        texcoord: [None, None],
        indices: Vec::new(),
        buffers: false,
        textures: Vec::new(),
        lighting: Some(LightSetup {
            lights: vec![
                DirLight {
                    direction: [0.4, 0.9, 0.5],
                    point: false,
                    ambient: [0.1, 0.1, 0.1, 1.0],
                    diffuse: [0.7, 0.7, 0.65, 1.0],
                    specular: [0.0, 0.0, 0.0, 1.0],
                },
                DirLight {
                    direction: [-0.8, 0.3, 0.2],
                    point: false,
                    ambient: [0.0, 0.0, 0.0, 1.0],
                    diffuse: [0.25, 0.3, 0.45, 1.0],
                    specular: [0.0, 0.0, 0.0, 1.0],
                },
                DirLight {
                    direction: [0.0, -0.5, 1.0],
                    point: false,
                    ambient: [0.0, 0.0, 0.0, 1.0],
                    diffuse: [0.2, 0.15, 0.1, 1.0],
                    specular: [0.0, 0.0, 0.0, 1.0],
                },
            ],
            model_ambient: [0.2, 0.2, 0.2, 1.0],
            specular: [0.0, 0.0, 0.0, 1.0],
            shininess: 0.0,
        }),
        fog: None,
        setup: vec![
            Op::Shade(ShadeModel::Flat),
            Op::Enable(Cap::Normalize, true),
            Op::BlendFunc(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha),
        ],
        frame,
    }
}

/// One glxgears gear (after Brian Paul's): front and back faces as triangle strips, the
/// teeth's faces and the outward faces as quads (two triangles each), the inner cylinder
/// as a strip, with smooth normals there. Returns the draws, in the arrays `a`.
fn gear(a: &mut Arrays, inner: f32, outer: f32, width: f32, teeth: usize, depth: f32) -> Vec<Op> {
    let (r0, r1, r2) = (inner, outer - depth / 2.0, outer + depth / 2.0);
    let da = std::f32::consts::TAU / teeth as f32 / 4.0;
    let hw = width * 0.5;
    let ang = |i: usize| i as f32 * std::f32::consts::TAU / teeth as f32;
    let p = |r: f32, a: f32, z: f32| Vec3::new(r * a.cos(), r * a.sin(), z);
    let white = [255; 4];
    let mut ops = Vec::new();
    let strip = |a: &mut Arrays, pts: Vec<(Vec3, Vec3)>| {
        let first = a.len();
        for (v, n) in pts {
            a.push(v, n, white, [0.0; 2]);
        }
        Op::Draw {
            prim: Primitive::TriangleStrip,
            first,
            count: a.len() - first,
        }
    };
    let quads = |a: &mut Arrays, qs: Vec<([Vec3; 4], Vec3)>| {
        let first = a.len();
        for (q, n) in qs {
            for k in [0, 1, 2, 0, 2, 3] {
                a.push(q[k], n, white, [0.0; 2]);
            }
        }
        draw(first, a.len() - first)
    };
    for (z, nz) in [(hw, 1.0f32), (-hw, -1.0)] {
        let n = Vec3::new(0.0, 0.0, nz);
        let mut pts = Vec::new();
        for i in 0..=teeth {
            let an = ang(i);
            if nz > 0.0 {
                pts.push((p(r0, an, z), n));
                pts.push((p(r1, an, z), n));
                if i < teeth {
                    pts.push((p(r0, an, z), n));
                    pts.push((p(r1, an + 3.0 * da, z), n));
                }
            } else {
                pts.push((p(r1, an, z), n));
                pts.push((p(r0, an, z), n));
                if i < teeth {
                    pts.push((p(r1, an + 3.0 * da, z), n));
                    pts.push((p(r0, an, z), n));
                }
            }
        }
        ops.push(strip(a, pts));
        let qs = (0..teeth)
            .map(|i| {
                let an = ang(i);
                let q = [
                    p(r1, an, z),
                    p(r2, an + da, z),
                    p(r2, an + 2.0 * da, z),
                    p(r1, an + 3.0 * da, z),
                ];
                let q = if nz > 0.0 {
                    q
                } else {
                    [q[3], q[2], q[1], q[0]]
                };
                (q, n)
            })
            .collect();
        ops.push(quads(a, qs));
    }
    // Outward faces: for each tooth its rising side, top, falling side and the valley.
    let mut qs = Vec::new();
    for i in 0..teeth {
        let an = ang(i);
        let steps = [
            (r1, an),
            (r2, an + da),
            (r2, an + 2.0 * da),
            (r1, an + 3.0 * da),
            (r1, ang(i + 1)),
        ];
        for s in steps.windows(2) {
            let (u, v) = (p(s[0].0, s[0].1, 0.0), p(s[1].0, s[1].1, 0.0));
            let d = v - u;
            let n = Vec3::new(d.y, -d.x, 0.0).normalize_or_zero();
            let q = [
                Vec3::new(u.x, u.y, hw),
                Vec3::new(u.x, u.y, -hw),
                Vec3::new(v.x, v.y, -hw),
                Vec3::new(v.x, v.y, hw),
            ];
            qs.push(([q[0], q[3], q[2], q[1]], n));
        }
    }
    ops.push(quads(a, qs));
    let mut pts = Vec::new();
    for i in 0..=teeth {
        let an = ang(i);
        let n = Vec3::new(-an.cos(), -an.sin(), 0.0);
        pts.push((p(r0, an, -hw), n));
        pts.push((p(r0, an, hw), n));
    }
    ops.push(strip(a, pts));
    ops
}

/// glxgears-style: three smooth-lit gears (strips and quads, 6 draws each) in their own
/// colors and matrices, one positional light.
fn gears(w: u32, h: u32, format: ColorFormat) -> Scene {
    let mut a = Arrays::default();
    let g = [
        (gear(&mut a, 1.0, 4.0, 1.0, 20, 0.7), [0.8, 0.1, 0.0, 1.0]),
        (gear(&mut a, 0.5, 2.0, 2.0, 10, 0.7), [0.0, 0.8, 0.2, 1.0]),
        (gear(&mut a, 1.3, 2.0, 0.5, 10, 0.7), [0.2, 0.2, 1.0, 1.0]),
    ];
    let angle = 12f32.to_radians();
    let view = Mat4::from_translation(Vec3::new(0.0, 0.0, -40.0))
        * Mat4::from_rotation_x(20f32.to_radians())
        * Mat4::from_rotation_y(30f32.to_radians());
    let placed = [
        Mat4::from_translation(Vec3::new(-3.0, -2.0, 0.0)) * Mat4::from_rotation_z(angle),
        Mat4::from_translation(Vec3::new(3.1, -2.0, 0.0))
            * Mat4::from_rotation_z(-2.0 * angle - 9f32.to_radians()),
        Mat4::from_translation(Vec3::new(-3.1, 4.2, 0.0))
            * Mat4::from_rotation_z(-2.0 * angle - 25f32.to_radians()),
    ];
    let mut frame = Vec::new();
    let mut draws = 0;
    for ((ops, color), m) in g.into_iter().zip(placed) {
        frame.push(Op::Modelview(view * m));
        frame.push(Op::Color(color));
        draws += ops.len();
        frame.extend(ops);
    }
    let aspect = h as f32 / w as f32;
    // glFrustum(-1, 1, -aspect, aspect, 5, 60).
    let fovy = 2.0 * (aspect / 5.0).atan();
    let tris = a.len() as f64 / 3.0;
    Scene {
        summary: format!(
            "gears (glxgears-like): 3 smooth-lit gears from triangle strips and quads, one \
             positional light, color material, own modelview and color each, depth test; {}, \
             {w}x{h}; about {tris:.0} triangles, {draws} draws per frame",
            bits_name(format)
        ),
        class: Class::Main,
        width: w,
        height: h,
        format,
        dither: true,
        unit: Unit::Triangles,
        work: tris,
        vertices: a.len() as f64,
        pixels: (w * h) as f64,
        clear_color: [0.0, 0.0, 0.0, 1.0],
        position: Attr::float(&a.pos, 3),
        color: None,
        normal: Some(Attr::float(&a.nrm, 3)),
        texcoord: [None, None],
        indices: Vec::new(),
        buffers: false,
        textures: Vec::new(),
        lighting: Some(LightSetup {
            lights: vec![DirLight {
                direction: [5.0, 5.0, 10.0],
                point: true,
                ambient: [0.0, 0.0, 0.0, 1.0],
                diffuse: [1.0, 1.0, 1.0, 1.0],
                specular: [0.0, 0.0, 0.0, 1.0],
            }],
            model_ambient: [0.2, 0.2, 0.2, 1.0],
            specular: [0.0, 0.0, 0.0, 1.0],
            shininess: 0.0,
        }),
        fog: None,
        setup: vec![
            Op::Projection(Mat4::perspective_rh_gl(fovy, 1.0 / aspect, 5.0, 60.0)),
            Op::Enable(Cap::DepthTest, true),
            Op::Enable(Cap::Lighting, true),
            Op::Enable(Cap::Normalize, true),
            Op::ColorArray(false),
        ],
        frame,
    }
}

/// A 2D interface frame: 500 small alpha-blended textured items, alternately quads through
/// `glDrawArrays` and `glDrawTexOES` sprites (a cell of a 64 × 64 atlas), with a texture
/// bind and a color change before most of them; orthographic, no depth.
fn ui_2d(format: ColorFormat) -> Scene {
    const ITEMS: usize = 500;
    const TEXTURES: usize = 6;
    let (w, h) = (640, 480);
    let mut rng = Lcg(2002);
    let mut a = Arrays::default();
    let mut frame = Vec::new();
    let mut pixels = 0.0;
    let mut bound = usize::MAX;
    for k in 0..ITEMS {
        let size = (16.0 + rng.next() * 48.0).floor();
        let x = (rng.next() * (w as f32 - size)).floor();
        let y = (rng.next() * (h as f32 - size)).floor();
        let tex = (rng.next() * TEXTURES as f32) as usize % TEXTURES;
        // Most items change texture and color; every fourth keeps the previous ones.
        if k % 4 != 3 || bound == usize::MAX {
            if tex != bound {
                frame.push(Op::Bind(tex));
                bound = tex;
            }
            frame.push(Op::Color([
                0.6 + rng.next() * 0.4,
                0.6 + rng.next() * 0.4,
                0.6 + rng.next() * 0.4,
                0.5 + rng.next() * 0.5,
            ]));
        }
        pixels += f64::from(size * size);
        let cell = (rng.next() * 4.0) as i32 % 4;
        if k % 2 == 0 {
            let (s0, t0) = ((cell % 2) as f32 * 0.5, (cell / 2) as f32 * 0.5);
            let (first, count) = a.rect([x, y, x + size, y + size], [s0, t0, s0 + 0.5, t0 + 0.5]);
            frame.push(draw(first, count));
        } else {
            frame.push(Op::DrawTex {
                rect: [x, y, size, size],
                crop: [(cell % 2) * 32, (cell / 2) * 32, 32, 32],
            });
        }
    }
    let textures = (0..TEXTURES)
        .map(|i| {
            let i = i as u32;
            Tex::new(64, MinFilter::Linear, MagFilter::Linear, move |x, y| {
                // Four round icons per atlas, each with a soft edge.
                let (cx, cy) = ((x % 32) as f32 - 15.5, (y % 32) as f32 - 15.5);
                let d = (cx * cx + cy * cy).sqrt();
                let alpha = ((15.0 - d) * 64.0).clamp(0.0, 255.0) as u8;
                let cell = (x / 32 + 2 * (y / 32)) * 50;
                [
                    (60 + i * 35 + cell) as u8,
                    (200 - i * 20 + x * 2) as u8,
                    (90 + y * 2 + i * 10) as u8,
                    alpha,
                ]
            })
        })
        .map(|mut t| {
            t.wrap = Wrap::ClampToEdge;
            t
        })
        .collect();
    let draws = ITEMS;
    Scene {
        summary: format!(
            "2D interface: {ITEMS} alpha-blended textured items of 16-64 px (half quads through \
             glDrawArrays, half glDrawTexOES sprites from a 64x64 atlas, LINEAR, MODULATE), a \
             texture bind and a color change before most; orthographic, no depth; {}, \
             640x480; {draws} draws, {:.2} Mpix per frame",
            bits_name(format),
            pixels / 1e6
        ),
        class: Class::Main,
        width: w,
        height: h,
        format,
        dither: true,
        unit: Unit::Draws,
        work: draws as f64,
        vertices: a.len() as f64,
        pixels,
        clear_color: [0.15, 0.15, 0.2, 1.0],
        position: Attr::float(&a.pos, 3),
        color: None,
        normal: None,
        texcoord: [Some(Attr::float(&a.tc, 2)), None],
        indices: Vec::new(),
        buffers: false,
        textures,
        lighting: None,
        fog: None,
        setup: vec![
            Op::Projection(pixel_ortho(w, h)),
            Op::Modelview(Mat4::IDENTITY),
            Op::Enable(Cap::DepthTest, false),
            Op::Enable(Cap::Blend, true),
            Op::BlendFunc(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha),
            Op::ColorArray(false),
            Op::Texture {
                unit: 0,
                tex: Some(0),
                env: modulate(),
                coord_replace: false,
            },
        ],
        frame,
    }
}

/// 10 000 draws of one 8 × 8-pixel quad (2 triangles), each under its own modelview
/// (a translation) and in its own current color: the cost of a draw call.
fn draws(format: ColorFormat) -> Scene {
    const DRAWS: usize = 10_000;
    let (w, h) = (640, 480);
    let mut rng = Lcg(10_000);
    let mut a = Arrays::default();
    let quad = a.rect([0.0, 0.0, 8.0, 8.0], [0.0; 4]);
    let mut frame = Vec::with_capacity(DRAWS * 3);
    for _ in 0..DRAWS {
        let x = (rng.next() * (w - 8) as f32).floor();
        let y = (rng.next() * (h - 8) as f32).floor();
        frame.push(Op::Modelview(Mat4::from_translation(Vec3::new(x, y, 0.0))));
        frame.push(Op::Color(rgb(&mut rng)));
        frame.push(draw(quad.0, quad.1));
    }
    Scene {
        summary: format!(
            "{DRAWS} draws of a 2-triangle 8x8-pixel quad, a glLoadMatrixf and a glColor4f \
             between draws, no depth; {}, 640x480; ns per draw",
            bits_name(format)
        ),
        class: Class::Main,
        width: w,
        height: h,
        format,
        dither: true,
        unit: Unit::Draws,
        work: DRAWS as f64,
        vertices: (DRAWS * 6) as f64,
        pixels: (DRAWS * 64) as f64,
        clear_color: [0.0, 0.0, 0.0, 1.0],
        position: Attr::float(&a.pos, 3),
        color: None,
        normal: None,
        texcoord: [None, None],
        indices: Vec::new(),
        buffers: false,
        textures: Vec::new(),
        lighting: None,
        fog: None,
        setup: vec![
            Op::Projection(pixel_ortho(w, h)),
            Op::Enable(Cap::DepthTest, false),
            Op::ColorArray(false),
        ],
        frame,
    }
}

/// The cost of a state change: 8 192 draws of one 8 × 8-pixel quad, each under its own
/// modelview, with one of blending, the depth test, texturing and lighting toggled before
/// every draw (in turn), so every draw sees a new fragment key, texture or lighting setup
/// while the rest of the state stays as it was. Each capability is toggled an even number
/// of times, so every frame starts from the same state.
fn state_churn(format: ColorFormat) -> Scene {
    const DRAWS: usize = 8192;
    let (w, h) = (640, 480);
    let mut rng = Lcg(4_004);
    let mut a = Arrays::default();
    let quad = a.rect([0.0, 0.0, 8.0, 8.0], [0.0, 0.0, 1.0, 1.0]);
    let mut frame = Vec::with_capacity(DRAWS * 3);
    let mut on = [false; 4];
    for k in 0..DRAWS {
        let x = (rng.next() * (w - 8) as f32).floor();
        let y = (rng.next() * (h - 8) as f32).floor();
        // Depths on a 1/64 grid, so ties (which fail GL_LESS) are exact at 16 bits too.
        let z = ((rng.next() * 2.0 - 1.0) * 0.9 * 64.0).floor() / 64.0;
        frame.push(Op::Modelview(Mat4::from_translation(Vec3::new(x, y, z))));
        let which = k % 4;
        on[which] = !on[which];
        frame.push(match which {
            0 => Op::Enable(Cap::Blend, on[0]),
            1 => Op::Enable(Cap::DepthTest, on[1]),
            2 => Op::Texture {
                unit: 0,
                tex: on[2].then_some(0),
                env: modulate(),
                coord_replace: false,
            },
            _ => Op::Enable(Cap::Lighting, on[3]),
        });
        frame.push(Op::Color([
            0.3 + rng.next() * 0.7,
            0.3 + rng.next() * 0.7,
            0.3 + rng.next() * 0.7,
            0.4 + rng.next() * 0.6,
        ]));
        frame.push(draw(quad.0, quad.1));
    }
    let texture = Tex::new(8, MinFilter::Nearest, MagFilter::Nearest, |x, y| {
        let c = if (x + y) % 2 == 0 { 255 } else { 128 };
        [c, 255 - x as u8 * 16, 128 + y as u8 * 16, 200]
    });
    Scene {
        summary: format!(
            "{DRAWS} draws of a 2-triangle 8x8-pixel quad, a glLoadMatrixf, a glColor4f and one \
             of GL_BLEND, GL_DEPTH_TEST, GL_TEXTURE_2D (8x8, NEAREST, MODULATE) and GL_LIGHTING \
             (one directional light, color material) toggled in turn between draws; {}, \
             640x480; ns per draw",
            bits_name(format)
        ),
        class: Class::Main,
        width: w,
        height: h,
        format,
        dither: true,
        unit: Unit::Draws,
        work: DRAWS as f64,
        vertices: (DRAWS * 6) as f64,
        pixels: (DRAWS * 64) as f64,
        clear_color: [0.0, 0.0, 0.0, 1.0],
        position: Attr::float(&a.pos, 3),
        color: None,
        normal: Some(Attr::float(&a.nrm, 3)),
        texcoord: [Some(Attr::float(&a.tc, 2)), None],
        indices: Vec::new(),
        buffers: false,
        textures: vec![texture],
        lighting: Some(LightSetup {
            lights: vec![DirLight {
                direction: [0.3, 0.4, 1.0],
                point: false,
                ambient: [0.1, 0.1, 0.1, 1.0],
                diffuse: [0.9, 0.9, 0.9, 1.0],
                specular: [0.0, 0.0, 0.0, 1.0],
            }],
            model_ambient: [0.2, 0.2, 0.2, 1.0],
            specular: [0.0, 0.0, 0.0, 1.0],
            shininess: 0.0,
        }),
        fog: None,
        setup: vec![
            Op::Projection(pixel_ortho(w, h)),
            Op::BlendFunc(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha),
            Op::Enable(Cap::DepthTest, false),
            Op::Enable(Cap::Blend, false),
            Op::Enable(Cap::Lighting, false),
            Op::ColorArray(false),
            Op::Texture {
                unit: 0,
                tex: None,
                env: modulate(),
                coord_replace: false,
            },
        ],
        frame,
    }
}
