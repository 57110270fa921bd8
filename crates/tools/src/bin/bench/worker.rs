//! The measuring side: one process per (scene, renderer), alive for the whole scene so the
//! parent can interleave the renderers frame by frame. The parent has already set the
//! environment that picks the driver and the thread count, which both libraries read once
//! when they load. This process loads one library, sets the scene up through the C API and
//! then answers commands on stdin, one a line:
//!
//! - `frame`: draws one frame (clear, the scene's ops, `glFinish`), answers `t <ms>`;
//! - `memset`: fills a buffer of the color + depth buffers' byte count, answers `m <ms>`;
//! - `image <path>`: writes the read-back RGBA pixels (bottom row first), answers `ok`;
//! - `quit`.
//!
//! Before the commands it prints `renderer <GL_RENDERER>` and `ready`, or
//! `unavailable <why>` when the library cannot be loaded or initialized.

use std::ffi::CStr;
use std::io::{BufRead, Write};
use std::path::{Path, PathBuf};
use std::ptr::null_mut;
use std::time::Instant;

use gles_cm_core::state::{BlendFactor, ShadeModel, Winding};
use gles_cm_core::texenv::{CombineFunc, EnvMode, Operand, Source, TexEnv};
use gles_cm_core::texture::{MagFilter, MinFilter, Wrap};
use gles_cm_core::{ColorFormat, ComponentType, Primitive};
use GLES_CM::gles::tokens::*;
use GLES_CM::gles::types::{GLenum, GLuint};

use crate::api::{Api, Egl, Library};
use crate::suite::{Cap, Mode, Op, Scene};

/// Which library to load.
pub enum Which {
    Ours(PathBuf),
    Mesa,
}

pub struct Job {
    pub which: Which,
    pub mode: Mode,
    pub scene: String,
    /// Samples per pixel of the pbuffer config: 0 (single-sample) or 4 (`--msaa`).
    pub samples: i32,
}

/// Prints one protocol line and flushes it (stdout is a pipe, so it is block-buffered).
fn say(line: &str) {
    let mut out = std::io::stdout().lock();
    let _ = writeln!(out, "{line}");
    let _ = out.flush();
}

/// What the command loop asks of a scene.
trait Frames {
    fn frame(&mut self);
    /// RGBA bytes, bottom row first.
    fn pixels(&mut self) -> Result<Vec<u8>, String>;
    /// Bytes of the color and depth buffers, for the memset comparison.
    fn buffer_bytes(&self) -> usize;
}

fn serve(f: &mut dyn Frames) -> Result<(), String> {
    say("ready");
    let mut scratch: Vec<u32> = Vec::new();
    let mut fill = 0u32;
    for line in std::io::stdin().lock().lines() {
        let line = line.map_err(|e| format!("stdin: {e}"))?;
        let (cmd, arg) = line.split_once(' ').unwrap_or((line.as_str(), ""));
        match cmd {
            "frame" => {
                let start = Instant::now();
                f.frame();
                say(&format!("t {:.4}", start.elapsed().as_secs_f64() * 1e3));
            }
            "memset" => {
                if scratch.is_empty() {
                    // Faulted in before the first timing, as the surface's buffers are.
                    scratch = vec![1; f.buffer_bytes() / 4];
                }
                fill = fill.wrapping_add(0x0101_0101);
                let start = Instant::now();
                scratch.fill(fill);
                std::hint::black_box(&mut scratch);
                say(&format!("m {:.4}", start.elapsed().as_secs_f64() * 1e3));
            }
            "image" => {
                let px = f.pixels()?;
                std::fs::write(Path::new(arg), &px).map_err(|e| format!("write {arg}: {e}"))?;
                say("ok");
            }
            "quit" => break,
            other => return Err(format!("unknown command {other:?}")),
        }
    }
    Ok(())
}

/// Runs `job`; an `Err` is a failure the parent reports (it exits non-zero).
pub fn run(job: &Job) -> Result<(), String> {
    let scene = Scene::by_name(&job.scene).ok_or_else(|| format!("no scene {}", job.scene))?;
    let libs = match &job.which {
        Which::Ours(path) => Library::open(&path.to_string_lossy()).map(|l| vec![l]),
        Which::Mesa => Library::open("libEGL.so.1")
            .and_then(|egl| Ok(vec![egl, Library::open("libGLESv1_CM.so.1")?])),
    };
    let api = match libs.and_then(Api::load) {
        Ok(api) => api,
        Err(e) => {
            say(&format!("unavailable {e}"));
            return Ok(());
        }
    };
    let gl = &api;
    let rgb565 = scene.format == ColorFormat::Rgb565;
    let ctx = match Egl::with_config(gl, scene.width, scene.height, rgb565, job.samples) {
        Ok(c) => c,
        Err(e) => {
            say(&format!("unavailable {e}"));
            return Ok(());
        }
    };
    // SAFETY: a context is current on this thread (Egl::new made it so); the names are
    // valid, and the strings returned are NUL-terminated and static for the context.
    let string = |name| unsafe {
        let p = (gl.glGetString)(name);
        if p.is_null() {
            "?".to_owned()
        } else {
            CStr::from_ptr(p.cast()).to_string_lossy().into_owned()
        }
    };
    say(&format!(
        "renderer {} | {}",
        string(GL_RENDERER),
        string(GL_VERSION)
    ));
    let buffers = setup(gl, &scene, job.mode);
    let mut runner = GlFrames {
        gl,
        scene: &scene,
        _buffers: buffers,
    };
    let r = serve(&mut runner);
    ctx.destroy(gl);
    r
}

struct GlFrames<'a> {
    gl: &'a Api,
    scene: &'a Scene,
    _buffers: Vec<GLuint>,
}

impl Frames for GlFrames<'_> {
    fn frame(&mut self) {
        let gl = self.gl;
        // SAFETY: a context is current on this thread.
        unsafe { (gl.glClear)(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT) };
        for op in &self.scene.frame {
            apply(gl, self.scene, op);
        }
        // SAFETY: as above.
        unsafe { (gl.glFinish)() };
    }

    fn pixels(&mut self) -> Result<Vec<u8>, String> {
        let (w, h) = (self.scene.width, self.scene.height);
        let mut pixels = vec![0u8; (w * h * 4) as usize];
        let gl = self.gl;
        // SAFETY: `pixels` holds w × h RGBA8 pixels with PACK_ALIGNMENT 4 (rows of w × 4
        // bytes need no padding), exactly what this call writes; a context is current.
        let error = unsafe {
            (gl.glPixelStorei)(GL_PACK_ALIGNMENT, 4);
            (gl.glReadPixels)(
                0,
                0,
                w as i32,
                h as i32,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                pixels.as_mut_ptr().cast(),
            );
            (gl.glGetError)()
        };
        if error != GL_NO_ERROR {
            return Err(format!("GL error 0x{error:04X}"));
        }
        Ok(pixels)
    }

    fn buffer_bytes(&self) -> usize {
        (self.scene.width * self.scene.height * 8) as usize
    }
}

fn cap(c: Cap) -> GLenum {
    match c {
        Cap::DepthTest => GL_DEPTH_TEST,
        Cap::Blend => GL_BLEND,
        Cap::Fog => GL_FOG,
        Cap::Lighting => GL_LIGHTING,
        Cap::PointSprite => GL_POINT_SPRITE_OES,
        Cap::CullFace => GL_CULL_FACE,
        Cap::Normalize => GL_NORMALIZE,
    }
}

fn blend_factor(f: BlendFactor) -> GLenum {
    match f {
        BlendFactor::Zero => GL_ZERO,
        BlendFactor::One => GL_ONE,
        BlendFactor::SrcColor => GL_SRC_COLOR,
        BlendFactor::OneMinusSrcColor => GL_ONE_MINUS_SRC_COLOR,
        BlendFactor::DstColor => GL_DST_COLOR,
        BlendFactor::OneMinusDstColor => GL_ONE_MINUS_DST_COLOR,
        BlendFactor::SrcAlpha => GL_SRC_ALPHA,
        BlendFactor::OneMinusSrcAlpha => GL_ONE_MINUS_SRC_ALPHA,
        BlendFactor::DstAlpha => GL_DST_ALPHA,
        BlendFactor::OneMinusDstAlpha => GL_ONE_MINUS_DST_ALPHA,
        BlendFactor::SrcAlphaSaturate => GL_SRC_ALPHA_SATURATE,
    }
}

fn primitive(p: Primitive) -> GLenum {
    match p {
        Primitive::Points => GL_POINTS,
        Primitive::Lines => GL_LINES,
        Primitive::LineLoop => GL_LINE_LOOP,
        Primitive::LineStrip => GL_LINE_STRIP,
        Primitive::Triangles => GL_TRIANGLES,
        Primitive::TriangleStrip => GL_TRIANGLE_STRIP,
        Primitive::TriangleFan => GL_TRIANGLE_FAN,
    }
}

fn component(t: ComponentType) -> GLenum {
    match t {
        ComponentType::Byte => GL_BYTE,
        ComponentType::UnsignedByte => GL_UNSIGNED_BYTE,
        ComponentType::Short => GL_SHORT,
        ComponentType::Fixed => GL_FIXED,
        ComponentType::Float => GL_FLOAT,
    }
}

fn min_filter(f: MinFilter) -> GLenum {
    match f {
        MinFilter::Nearest => GL_NEAREST,
        MinFilter::Linear => GL_LINEAR,
        MinFilter::NearestMipmapNearest => GL_NEAREST_MIPMAP_NEAREST,
        MinFilter::LinearMipmapNearest => GL_LINEAR_MIPMAP_NEAREST,
        MinFilter::NearestMipmapLinear => GL_NEAREST_MIPMAP_LINEAR,
        MinFilter::LinearMipmapLinear => GL_LINEAR_MIPMAP_LINEAR,
    }
}

fn combine_func(f: CombineFunc) -> GLenum {
    match f {
        CombineFunc::Replace => GL_REPLACE,
        CombineFunc::Modulate => GL_MODULATE,
        CombineFunc::Add => GL_ADD,
        CombineFunc::AddSigned => GL_ADD_SIGNED,
        CombineFunc::Interpolate => GL_INTERPOLATE,
        CombineFunc::Subtract => GL_SUBTRACT,
        CombineFunc::Dot3Rgb => GL_DOT3_RGB,
        CombineFunc::Dot3Rgba => GL_DOT3_RGBA,
    }
}

fn source(s: Source) -> GLenum {
    match s {
        Source::Texture => GL_TEXTURE,
        Source::Constant => GL_CONSTANT,
        Source::PrimaryColor => GL_PRIMARY_COLOR,
        Source::Previous => GL_PREVIOUS,
        Source::Unit(n) => GL_TEXTURE0 + GLenum::from(n),
    }
}

fn operand(o: Operand) -> GLenum {
    match o {
        Operand::SrcColor => GL_SRC_COLOR,
        Operand::OneMinusSrcColor => GL_ONE_MINUS_SRC_COLOR,
        Operand::SrcAlpha => GL_SRC_ALPHA,
        Operand::OneMinusSrcAlpha => GL_ONE_MINUS_SRC_ALPHA,
    }
}

/// The texture environment of the active unit.
fn tex_env(gl: &Api, env: &TexEnv) {
    // SAFETY: a context is current; the color pointer addresses 4 floats.
    unsafe {
        let e = GL_TEXTURE_ENV;
        (gl.glTexEnvfv)(e, GL_TEXTURE_ENV_COLOR, env.color.as_ptr());
        let mode = match env.mode {
            EnvMode::Replace => GL_REPLACE,
            EnvMode::Modulate => GL_MODULATE,
            EnvMode::Decal => GL_DECAL,
            EnvMode::Blend => GL_BLEND,
            EnvMode::Add => GL_ADD,
            EnvMode::Combine(c) => {
                (gl.glTexEnvi)(e, GL_COMBINE_RGB, combine_func(c.rgb) as i32);
                (gl.glTexEnvi)(e, GL_COMBINE_ALPHA, combine_func(c.alpha) as i32);
                for k in 0..3u32 {
                    (gl.glTexEnvi)(e, GL_SRC0_RGB + k, source(c.src_rgb[k as usize]) as i32);
                    (gl.glTexEnvi)(e, GL_SRC0_ALPHA + k, source(c.src_alpha[k as usize]) as i32);
                    (gl.glTexEnvi)(
                        e,
                        GL_OPERAND0_RGB + k,
                        operand(c.operand_rgb[k as usize]) as i32,
                    );
                    (gl.glTexEnvi)(
                        e,
                        GL_OPERAND0_ALPHA + k,
                        operand(c.operand_alpha[k as usize]) as i32,
                    );
                }
                (gl.glTexEnvf)(e, GL_RGB_SCALE, c.rgb_scale);
                (gl.glTexEnvf)(e, GL_ALPHA_SCALE, c.alpha_scale);
                GL_COMBINE
            }
        };
        (gl.glTexEnvi)(e, GL_TEXTURE_ENV_MODE, mode as i32);
    }
}

/// `GL_TEXTURE_CROP_RECT_OES` (OES_draw_texture).
const GL_TEXTURE_CROP_RECT_OES: GLenum = 0x8B9D;

type DrawTexf = unsafe extern "C" fn(f32, f32, f32, f32, f32);

/// `glDrawTexfOES`, an extension entry point: Mesa's `libGLESv1_CM` does not export it, so
/// it comes from `eglGetProcAddress` (once; a process loads one library).
fn draw_tex(gl: &Api) -> Option<DrawTexf> {
    static F: std::sync::OnceLock<Option<DrawTexf>> = std::sync::OnceLock::new();
    *F.get_or_init(|| {
        // SAFETY: the name is NUL-terminated; a non-null result is the address of
        // glDrawTexfOES, whose prototype is `DrawTexf`.
        unsafe {
            let p = (gl.eglGetProcAddress)(c"glDrawTexfOES".as_ptr());
            (!p.is_null()).then(|| std::mem::transmute::<*mut std::ffi::c_void, DrawTexf>(p))
        }
    })
}

/// One op as GL calls.
fn apply(gl: &Api, scene: &Scene, op: &Op) {
    // SAFETY: a context is current on this thread. Matrices are 16 floats, colors 4; the
    // draws read the arrays `setup` pointed at (the scene's vectors, alive for the whole
    // process, or buffer objects holding copies), which hold every vertex and index drawn.
    unsafe {
        match op {
            Op::Enable(c, on) => {
                if *on {
                    (gl.glEnable)(cap(*c))
                } else {
                    (gl.glDisable)(cap(*c))
                }
            }
            Op::BlendFunc(s, d) => (gl.glBlendFunc)(blend_factor(*s), blend_factor(*d)),
            Op::Shade(m) => (gl.glShadeModel)(match m {
                ShadeModel::Flat => GL_FLAT,
                ShadeModel::Smooth => GL_SMOOTH,
            }),
            Op::Projection(m) => {
                (gl.glMatrixMode)(GL_PROJECTION);
                (gl.glLoadMatrixf)(m.to_cols_array().as_ptr());
                (gl.glMatrixMode)(GL_MODELVIEW);
            }
            Op::Modelview(m) => (gl.glLoadMatrixf)(m.to_cols_array().as_ptr()),
            Op::Color([r, g, b, a]) => (gl.glColor4f)(*r, *g, *b, *a),
            Op::ColorArray(on) => {
                if *on {
                    (gl.glEnableClientState)(GL_COLOR_ARRAY)
                } else {
                    (gl.glDisableClientState)(GL_COLOR_ARRAY)
                }
            }
            Op::PointSize(s) => (gl.glPointSize)(*s),
            Op::Texture {
                unit,
                tex,
                env,
                coord_replace,
            } => {
                (gl.glActiveTexture)(GL_TEXTURE0 + *unit as u32);
                match tex {
                    Some(t) => {
                        (gl.glBindTexture)(GL_TEXTURE_2D, *t as u32 + 1);
                        (gl.glEnable)(GL_TEXTURE_2D);
                        tex_env(gl, env);
                        (gl.glTexEnvi)(
                            GL_POINT_SPRITE_OES,
                            GL_COORD_REPLACE_OES,
                            i32::from(*coord_replace),
                        );
                    }
                    None => (gl.glDisable)(GL_TEXTURE_2D),
                }
                (gl.glActiveTexture)(GL_TEXTURE0);
            }
            Op::Draw { prim, first, count } => {
                (gl.glDrawArrays)(primitive(*prim), *first as i32, *count as i32)
            }
            Op::DrawIndexed {
                prim,
                offset,
                count,
            } => {
                let ptr = if scene.buffers {
                    (offset * 2) as *const std::ffi::c_void
                } else {
                    scene.indices[*offset..].as_ptr().cast()
                };
                (gl.glDrawElements)(primitive(*prim), *count as i32, GL_UNSIGNED_SHORT, ptr);
            }
            Op::FrontFace(w) => (gl.glFrontFace)(match w {
                Winding::Ccw => GL_CCW,
                Winding::Cw => GL_CW,
            }),
            Op::Bind(t) => (gl.glBindTexture)(GL_TEXTURE_2D, *t as u32 + 1),
            Op::DrawTex { rect, crop } => {
                (gl.glTexParameteriv)(GL_TEXTURE_2D, GL_TEXTURE_CROP_RECT_OES, crop.as_ptr());
                if let Some(f) = draw_tex(gl) {
                    let [x, y, w, h] = *rect;
                    f(x, y, 0.0, w, h);
                }
            }
        }
    }
}

/// Everything before the first frame: viewport, hints, lights, fog, textures, arrays (in
/// buffer objects when the scene asks), then the scene's setup ops. Returns the buffer
/// names, which must outlive the draws.
fn setup(gl: &Api, scene: &Scene, mode: Mode) -> Vec<GLuint> {
    let mut names = Vec::new();
    // SAFETY: a context is current on this thread. Every pointer passed addresses live data
    // of the size the call reads: parameter vectors of 4 floats, texture levels of
    // width × height RGBA8 words (UNPACK_ALIGNMENT 4, rows need no padding), and the
    // scene's arrays, which live until the process ends.
    unsafe {
        (gl.glViewport)(0, 0, scene.width as i32, scene.height as i32);
        if !scene.dither {
            (gl.glDisable)(GL_DITHER);
        }
        for h in [
            GL_PERSPECTIVE_CORRECTION_HINT,
            GL_POINT_SMOOTH_HINT,
            GL_LINE_SMOOTH_HINT,
            GL_FOG_HINT,
        ] {
            (gl.glHint)(h, mode.gl());
        }
        let [r, g, b, a] = scene.clear_color;
        (gl.glClearColor)(r, g, b, a);
        (gl.glClearDepthf)(1.0);
        (gl.glDepthFunc)(GL_LESS);
        (gl.glMatrixMode)(GL_MODELVIEW);
        (gl.glLoadIdentity)();
        if let Some(l) = &scene.lighting {
            // Lights are set under the identity modelview: their directions are eye space.
            for (i, light) in l.lights.iter().enumerate() {
                let id = GL_LIGHT0 + i as u32;
                (gl.glEnable)(id);
                let [x, y, z] = light.direction;
                let p = [x, y, z, if light.point { 1.0 } else { 0.0 }];
                (gl.glLightfv)(id, GL_POSITION, p.as_ptr());
                (gl.glLightfv)(id, GL_AMBIENT, light.ambient.as_ptr());
                (gl.glLightfv)(id, GL_DIFFUSE, light.diffuse.as_ptr());
                (gl.glLightfv)(id, GL_SPECULAR, light.specular.as_ptr());
            }
            (gl.glLightModelfv)(GL_LIGHT_MODEL_AMBIENT, l.model_ambient.as_ptr());
            (gl.glMaterialfv)(GL_FRONT_AND_BACK, GL_SPECULAR, l.specular.as_ptr());
            (gl.glMaterialf)(GL_FRONT_AND_BACK, GL_SHININESS, l.shininess);
            (gl.glEnable)(GL_COLOR_MATERIAL);
        }
        if let Some(f) = &scene.fog {
            (gl.glFogf)(GL_FOG_MODE, GL_LINEAR as f32);
            (gl.glFogf)(GL_FOG_START, f.start);
            (gl.glFogf)(GL_FOG_END, f.end);
            (gl.glFogfv)(GL_FOG_COLOR, f.color.as_ptr());
        }
        (gl.glPixelStorei)(GL_UNPACK_ALIGNMENT, 4);
        for (i, t) in scene.textures.iter().enumerate() {
            // Names 1, 2, …: fixed, so ops can refer to them by index.
            (gl.glBindTexture)(GL_TEXTURE_2D, i as u32 + 1);
            for (level, img) in t.levels.iter().enumerate() {
                (gl.glTexImage2D)(
                    GL_TEXTURE_2D,
                    level as i32,
                    GL_RGBA as i32,
                    img.width as i32,
                    img.height as i32,
                    0,
                    GL_RGBA,
                    GL_UNSIGNED_BYTE,
                    img.texels.as_ptr().cast(),
                );
            }
            let wrap = match t.wrap {
                Wrap::Repeat => GL_REPEAT,
                Wrap::ClampToEdge => GL_CLAMP_TO_EDGE,
                Wrap::MirroredRepeat => 0x8370,
            } as i32;
            (gl.glTexParameteri)(
                GL_TEXTURE_2D,
                GL_TEXTURE_MIN_FILTER,
                min_filter(t.min) as i32,
            );
            let mag = match t.mag {
                MagFilter::Nearest => GL_NEAREST,
                MagFilter::Linear => GL_LINEAR,
            };
            (gl.glTexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mag as i32);
            (gl.glTexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
            (gl.glTexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
        }
        (gl.glBindTexture)(GL_TEXTURE_2D, 0);
        // Binds `data` to a new ARRAY_BUFFER (or none) and returns the pointer argument.
        let mut source = |data: &[u8]| -> *const std::ffi::c_void {
            if scene.buffers {
                let mut name = 0;
                (gl.glGenBuffers)(1, &mut name);
                (gl.glBindBuffer)(GL_ARRAY_BUFFER, name);
                (gl.glBufferData)(
                    GL_ARRAY_BUFFER,
                    data.len() as isize,
                    data.as_ptr().cast(),
                    GL_STATIC_DRAW,
                );
                names.push(name);
                null_mut()
            } else {
                data.as_ptr().cast()
            }
        };
        let p = &scene.position;
        (gl.glEnableClientState)(GL_VERTEX_ARRAY);
        (gl.glVertexPointer)(
            p.size as i32,
            component(p.ty),
            p.stride() as i32,
            source(&p.data),
        );
        if let Some(c) = &scene.color {
            (gl.glEnableClientState)(GL_COLOR_ARRAY);
            (gl.glColorPointer)(
                c.size as i32,
                component(c.ty),
                c.stride() as i32,
                source(&c.data),
            );
        }
        if let Some(n) = &scene.normal {
            (gl.glEnableClientState)(GL_NORMAL_ARRAY);
            (gl.glNormalPointer)(component(n.ty), n.stride() as i32, source(&n.data));
        }
        for (u, tc) in scene.texcoord.iter().enumerate() {
            if let Some(tc) = tc {
                (gl.glClientActiveTexture)(GL_TEXTURE0 + u as u32);
                (gl.glEnableClientState)(GL_TEXTURE_COORD_ARRAY);
                (gl.glTexCoordPointer)(
                    tc.size as i32,
                    component(tc.ty),
                    tc.stride() as i32,
                    source(&tc.data),
                );
            }
        }
        (gl.glClientActiveTexture)(GL_TEXTURE0);
        if scene.buffers {
            (gl.glBindBuffer)(GL_ARRAY_BUFFER, 0);
            if !scene.indices.is_empty() {
                let mut name = 0;
                (gl.glGenBuffers)(1, &mut name);
                (gl.glBindBuffer)(GL_ELEMENT_ARRAY_BUFFER, name);
                (gl.glBufferData)(
                    GL_ELEMENT_ARRAY_BUFFER,
                    (scene.indices.len() * 2) as isize,
                    scene.indices.as_ptr().cast(),
                    GL_STATIC_DRAW,
                );
                names.push(name);
            }
        }
    }
    for op in &scene.setup {
        apply(gl, scene, op);
    }
    names
}

/// The M3G scene: `file` from the corpus loaded with `m3g::loader`, its World animated and
/// rendered through `Graphics3D` into a 240 × 320 target (the corpus references' size and
/// format) each frame; the image is the frame at `image_ms`.
pub fn run_m3g(file: &Path, image_ms: i32) -> Result<(), String> {
    use gles_cm_core::{ColorFormat, DepthFormat, Target, TargetFormat};
    use m3g::{Graphics3D, Loader, Object3DExt, RenderHints, World};

    let roots = match Loader::load_path(file) {
        Ok(r) => r,
        Err(e) => {
            say(&format!("unavailable {}: {e}", file.display()));
            return Ok(());
        }
    };
    let world = roots
        .iter()
        .find_map(|r| r.downcast::<World>())
        .ok_or("no World in the file")?;
    say(&format!(
        "renderer GLES_CM m3g ({} threads)",
        gles_cm_core::pool::thread_count()
    ));
    struct M3g {
        world: World,
        g: Graphics3D,
        target: Option<Target>,
        time: i32,
        image_ms: i32,
    }
    impl M3g {
        fn render(&mut self, time: i32) -> Result<(), String> {
            self.world
                .animate(time)
                .map_err(|e| format!("animate: {e}"))?;
            let t = self.target.take().ok_or("no target")?;
            self.g
                .bind_target(t, true, RenderHints::empty())
                .map_err(|e| e.to_string())?;
            let r = self.g.render_world(&self.world);
            self.target = self.g.release_target();
            r.map_err(|e| format!("render: {e}"))
        }
    }
    impl Frames for M3g {
        fn frame(&mut self) {
            // Steps through the animation, so skinning and keyframes are recomputed.
            self.time = (self.time + 40) % 5000;
            if let Err(e) = self.render(self.time) {
                eprintln!("{e}");
                std::process::exit(1);
            }
        }

        fn pixels(&mut self) -> Result<Vec<u8>, String> {
            self.render(self.image_ms)?;
            let t = self.target.as_ref().ok_or("no target")?;
            Ok(t.color().iter().flat_map(|w| w.to_le_bytes()).collect())
        }

        fn buffer_bytes(&self) -> usize {
            240 * 320 * 6
        }
    }
    let target = Target::new(
        240,
        320,
        TargetFormat {
            color: ColorFormat::Rgba8888,
            depth: Some(DepthFormat::D16),
            stencil_bits: 0,
        },
    );
    let mut g = Graphics3D::new();
    // The corpus references were rendered with Mesa's late clamp.
    g.set_clamp_after_lighting(false);
    let mut m = M3g {
        world,
        g,
        target: Some(target),
        time: 0,
        image_ms,
    };
    serve(&mut m)
}

/// Tiles per row of the `m3g-corpus` mosaic.
pub const MOSAIC_COLUMNS: usize = 4;

/// The corpus files (`*.m3g` of `dir`), sorted by name.
pub fn corpus_files(dir: &Path) -> Result<Vec<PathBuf>, String> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(|e| format!("{}: {e}", dir.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "m3g"))
        .collect();
    files.sort();
    if files.is_empty() {
        return Err(format!("no .m3g file in {}", dir.display()));
    }
    Ok(files)
}

/// `tiles` (all the same size) side by side, [`MOSAIC_COLUMNS`] a row, the first row at the
/// top; tiles missing from the last row are opaque black. Rows are bottom-up, as in a target.
pub fn mosaic(tiles: &[gles_cm_core::Target]) -> gles_cm_core::Target {
    use gles_cm_core::Target;
    let (w, h) = tiles
        .first()
        .map_or((1, 1), |t| (t.width() as usize, t.height() as usize));
    let rows = tiles.len().div_ceil(MOSAIC_COLUMNS).max(1);
    let format = tiles
        .first()
        .map_or_else(|| crate::suite::target(1, 1).format(), Target::format);
    let mut out = Target::new((w * MOSAIC_COLUMNS) as u32, (h * rows) as u32, format);
    out.color_mut().fill(0xff00_0000);
    let stride = w * MOSAIC_COLUMNS;
    for (i, tile) in tiles.iter().enumerate() {
        let (col, row) = (i % MOSAIC_COLUMNS, i / MOSAIC_COLUMNS);
        let y0 = (rows - 1 - row) * h;
        for (y, src) in tile.color().chunks(w).enumerate() {
            let at = (y0 + y) * stride + col * w;
            out.color_mut()[at..at + w].copy_from_slice(src);
        }
    }
    out
}

/// The `m3g-corpus` scene: every file of the corpus in `dir` loaded once; each frame
/// animates every World to t = 0 and renders it through `Graphics3D` into its own 240 × 320
/// target (the corpus references' size and conditions); the image is the [`mosaic`] of them.
pub fn run_m3g_corpus(dir: &Path) -> Result<(), String> {
    use gles_cm_core::{ColorFormat, DepthFormat, Target, TargetFormat};
    use m3g::{Graphics3D, Loader, Object3DExt, RenderHints, World};

    let mut worlds = Vec::new();
    for file in corpus_files(dir)? {
        let roots = Loader::load_path(&file).map_err(|e| format!("{}: {e}", file.display()))?;
        let world = roots
            .iter()
            .find_map(|r| r.downcast::<World>())
            .ok_or_else(|| format!("{}: no World", file.display()))?;
        worlds.push(world);
    }
    say(&format!(
        "renderer GLES_CM m3g ({} threads)",
        gles_cm_core::pool::thread_count()
    ));
    struct Corpus {
        worlds: Vec<World>,
        g: Graphics3D,
        targets: Vec<Option<Target>>,
    }
    impl Corpus {
        fn render(&mut self) -> Result<(), String> {
            for (world, slot) in self.worlds.iter().zip(&mut self.targets) {
                world.animate(0).map_err(|e| format!("animate: {e}"))?;
                let t = slot.take().ok_or("no target")?;
                self.g
                    .bind_target(t, true, RenderHints::empty())
                    .map_err(|e| e.to_string())?;
                let r = self.g.render_world(world);
                *slot = self.g.release_target();
                r.map_err(|e| format!("render: {e}"))?;
            }
            Ok(())
        }
    }
    impl Frames for Corpus {
        fn frame(&mut self) {
            if let Err(e) = self.render() {
                eprintln!("{e}");
                std::process::exit(1);
            }
        }

        fn pixels(&mut self) -> Result<Vec<u8>, String> {
            self.render()?;
            let tiles: Vec<Target> = self.targets.iter().flatten().cloned().collect();
            if tiles.len() != self.worlds.len() {
                return Err("a target was lost".into());
            }
            let m = mosaic(&tiles);
            Ok(m.color().iter().flat_map(|w| w.to_le_bytes()).collect())
        }

        fn buffer_bytes(&self) -> usize {
            240 * 320 * 6 * self.worlds.len()
        }
    }
    let format = TargetFormat {
        color: ColorFormat::Rgba8888,
        depth: Some(DepthFormat::D16),
        stencil_bits: 0,
    };
    let mut g = Graphics3D::new();
    // The corpus references were rendered with Mesa's late clamp.
    g.set_clamp_after_lighting(false);
    let targets = worlds
        .iter()
        .map(|_| Some(Target::new(240, 320, format)))
        .collect();
    serve(&mut Corpus { worlds, g, targets })
}
