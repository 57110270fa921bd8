//! The measuring side: one process per (scene, renderer). The parent has already set the
//! environment that picks the driver and the thread count, which both libraries read once
//! when they load. This process loads one library, renders the scene through the C API,
//! prints its frame times and writes the read-back pixels to a file.
//!
//! Output on stdout, one item per line: `renderer <GL_RENDERER>`, `times <ms> <ms> …`, or
//! `unavailable <why>` when the library cannot be loaded or initialized.

use std::ffi::CStr;
use std::path::{Path, PathBuf};
use std::ptr::null_mut;
use std::time::Instant;

use GLES_CM::egl::tokens::*;
use GLES_CM::egl::types::{EGLConfig, EGLint};
use GLES_CM::gles::tokens::*;
use GLES_CM::gles::types::GLenum;

use crate::api::{Api, Library};
use crate::scene::{Scene, HEIGHT, WIDTH};

/// Which library to load.
pub enum Which {
    Ours(PathBuf),
    Mesa,
}

pub struct Job {
    pub which: Which,
    pub hint: GLenum,
    pub scene: String,
    pub out: PathBuf,
    pub frames: usize,
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
            println!("unavailable {e}");
            return Ok(());
        }
    };
    let gl = &api;
    let ctx = match Egl::new(gl) {
        Ok(c) => c,
        Err(e) => {
            println!("unavailable {e}");
            return Ok(());
        }
    };
    // SAFETY: a context is current on this thread (Egl::new made it so); GL_RENDERER is a
    // valid name, and the string returned is NUL-terminated and static for the context.
    let renderer = unsafe {
        let p = (gl.glGetString)(GL_RENDERER);
        if p.is_null() {
            "?".to_owned()
        } else {
            CStr::from_ptr(p.cast()).to_string_lossy().into_owned()
        }
    };
    println!("renderer {renderer}");

    setup(gl, &scene, job.hint);
    let mut times = Vec::with_capacity(job.frames);
    draw_frame(gl, &scene); // warm-up: first-use allocations, JIT compilation
    for _ in 0..job.frames {
        let start = Instant::now();
        draw_frame(gl, &scene);
        times.push(start.elapsed().as_secs_f64() * 1e3);
    }
    let mut pixels = vec![0u8; (WIDTH * HEIGHT * 4) as usize];
    // SAFETY: `pixels` holds WIDTH × HEIGHT RGBA8 pixels with PACK_ALIGNMENT 4 (rows of
    // WIDTH × 4 bytes need no padding), exactly what this call writes; a context is current.
    let error = unsafe {
        (gl.glPixelStorei)(GL_PACK_ALIGNMENT, 4);
        (gl.glReadPixels)(
            0,
            0,
            WIDTH as i32,
            HEIGHT as i32,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            pixels.as_mut_ptr().cast(),
        );
        (gl.glGetError)()
    };
    if error != GL_NO_ERROR {
        return Err(format!("GL error 0x{error:04X}"));
    }
    write(&job.out, &pixels)?;
    let list: Vec<String> = times.iter().map(|t| format!("{t:.4}")).collect();
    println!("times {}", list.join(" "));
    ctx.destroy(gl);
    Ok(())
}

fn write(path: &Path, pixels: &[u8]) -> Result<(), String> {
    std::fs::write(path, pixels).map_err(|e| format!("write {}: {e}", path.display()))
}

/// The state every frame shares: viewport, matrices, enables, the perspective hint and the
/// client arrays (the scene's vectors outlive every draw that reads them).
fn setup(gl: &Api, scene: &Scene, hint: GLenum) {
    // SAFETY: a context is current on this thread. The matrices are 16 floats each; the
    // array pointers address `scene.positions` (3 floats a vertex) and `scene.colors`
    // (4 floats a vertex), which live until the process ends, past every glDrawArrays that
    // reads them.
    unsafe {
        (gl.glViewport)(0, 0, WIDTH as i32, HEIGHT as i32);
        (gl.glMatrixMode)(GL_PROJECTION);
        (gl.glLoadMatrixf)(scene.projection.to_cols_array().as_ptr());
        (gl.glMatrixMode)(GL_MODELVIEW);
        (gl.glLoadMatrixf)(scene.modelview.to_cols_array().as_ptr());
        (gl.glDisable)(GL_DITHER);
        if scene.depth_test {
            (gl.glEnable)(GL_DEPTH_TEST);
            (gl.glDepthFunc)(GL_LESS);
        } else {
            (gl.glDisable)(GL_DEPTH_TEST);
        }
        if scene.blend {
            (gl.glEnable)(GL_BLEND);
            (gl.glBlendFunc)(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        } else {
            (gl.glDisable)(GL_BLEND);
        }
        (gl.glHint)(GL_PERSPECTIVE_CORRECTION_HINT, hint);
        (gl.glLineWidth)(1.0);
        let [r, g, b, a] = scene.clear_color;
        (gl.glClearColor)(r, g, b, a);
        (gl.glClearDepthf)(1.0);
        (gl.glEnableClientState)(GL_VERTEX_ARRAY);
        (gl.glEnableClientState)(GL_COLOR_ARRAY);
        (gl.glVertexPointer)(3, GL_FLOAT, 12, scene.positions.as_ptr().cast());
        (gl.glColorPointer)(4, GL_FLOAT, 16, scene.colors.as_ptr().cast());
    }
}

/// One timed frame: clear, every draw, and glFinish (rasterization is deferred to flush
/// points, so the frame is not done before it).
fn draw_frame(gl: &Api, scene: &Scene) {
    // SAFETY: a context is current and `setup` pointed the arrays at the scene's vectors,
    // which hold `first + count` vertices for every draw.
    unsafe {
        (gl.glClear)(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        for d in &scene.draws {
            (gl.glPointSize)(d.point_size);
            let mode = match d.primitive {
                GLES_CM::core::Primitive::Points => GL_POINTS,
                GLES_CM::core::Primitive::Lines => GL_LINES,
                _ => GL_TRIANGLES,
            };
            (gl.glDrawArrays)(mode, d.first as i32, d.count as i32);
        }
        (gl.glFinish)();
    }
}

/// An initialized display with a 640×480 RGBA8888 + depth 24 pbuffer and a current ES 1.x
/// context.
struct Egl {
    display: *mut std::ffi::c_void,
    surface: *mut std::ffi::c_void,
    context: *mut std::ffi::c_void,
}

impl Egl {
    fn new(gl: &Api) -> Result<Egl, String> {
        // SAFETY: every pointer passed is valid for the call: attribute lists end in
        // EGL_NONE, `configs` has room for the `configs.len()` entries announced, the out
        // parameters point at live locals. Handles come from the same display.
        unsafe {
            let dpy = (gl.eglGetDisplay)(EGL_DEFAULT_DISPLAY);
            if dpy.is_null() {
                return Err(format!("eglGetDisplay: 0x{:04X}", (gl.eglGetError)()));
            }
            let (mut major, mut minor) = (0, 0);
            if (gl.eglInitialize)(dpy, &mut major, &mut minor) == 0 {
                return Err(format!("eglInitialize: 0x{:04X}", (gl.eglGetError)()));
            }
            (gl.eglBindAPI)(EGL_OPENGL_ES_API);
            let attribs = [
                EGL_SURFACE_TYPE,
                EGL_PBUFFER_BIT,
                EGL_RENDERABLE_TYPE,
                EGL_OPENGL_ES_BIT,
                EGL_RED_SIZE,
                8,
                EGL_GREEN_SIZE,
                8,
                EGL_BLUE_SIZE,
                8,
                EGL_ALPHA_SIZE,
                8,
                EGL_DEPTH_SIZE,
                24,
                EGL_NONE,
            ];
            let mut configs: Vec<EGLConfig> = vec![null_mut(); 256];
            let mut n: EGLint = 0;
            if (gl.eglChooseConfig)(
                dpy,
                attribs.as_ptr(),
                configs.as_mut_ptr(),
                configs.len() as EGLint,
                &mut n,
            ) == 0
            {
                return Err(format!("eglChooseConfig: 0x{:04X}", (gl.eglGetError)()));
            }
            // EGL sorts deeper color first (10-bit configs on Mesa): keep exact sizes, and
            // of those the one with the least stencil.
            let attr = |c: EGLConfig, a: EGLint| {
                let mut v = -1;
                (gl.eglGetConfigAttrib)(dpy, c, a, &mut v);
                v
            };
            let config = configs[..n.max(0) as usize]
                .iter()
                .copied()
                .filter(|&c| {
                    [EGL_RED_SIZE, EGL_GREEN_SIZE, EGL_BLUE_SIZE, EGL_ALPHA_SIZE]
                        .iter()
                        .all(|&a| attr(c, a) == 8)
                        && attr(c, EGL_DEPTH_SIZE) == 24
                })
                .min_by_key(|&c| attr(c, EGL_STENCIL_SIZE))
                .ok_or("no RGBA8888 / depth 24 pbuffer config")?;
            let size = [
                EGL_WIDTH,
                WIDTH as EGLint,
                EGL_HEIGHT,
                HEIGHT as EGLint,
                EGL_NONE,
            ];
            let surface = (gl.eglCreatePbufferSurface)(dpy, config, size.as_ptr());
            if surface.is_null() {
                return Err(format!(
                    "eglCreatePbufferSurface: 0x{:04X}",
                    (gl.eglGetError)()
                ));
            }
            let ctx_attribs = [EGL_CONTEXT_CLIENT_VERSION, 1, EGL_NONE];
            let context = (gl.eglCreateContext)(dpy, config, EGL_NO_CONTEXT, ctx_attribs.as_ptr());
            if context.is_null() {
                return Err(format!("eglCreateContext: 0x{:04X}", (gl.eglGetError)()));
            }
            if (gl.eglMakeCurrent)(dpy, surface, surface, context) == 0 {
                return Err(format!("eglMakeCurrent: 0x{:04X}", (gl.eglGetError)()));
            }
            Ok(Egl {
                display: dpy,
                surface,
                context,
            })
        }
    }

    /// Releases the context and surface. The display is left initialized: terminating it
    /// as the process exits gains nothing.
    fn destroy(self, gl: &Api) {
        // SAFETY: the handles were created on this display and are released once.
        unsafe {
            (gl.eglMakeCurrent)(self.display, null_mut(), null_mut(), EGL_NO_CONTEXT);
            (gl.eglDestroyContext)(self.display, self.context);
            (gl.eglDestroySurface)(self.display, self.surface);
        }
    }
}
