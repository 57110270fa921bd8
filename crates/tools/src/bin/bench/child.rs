//! The measuring side: one process per (scene, renderer). The parent has already set the
//! environment that picks the driver and the thread count, which both libraries read once
//! when they load. This process loads one library, renders the scene through the C API,
//! prints its frame times and writes the read-back pixels to a file.
//!
//! Output on stdout, one item per line: `renderer <GL_RENDERER>`, `times <ms> <ms> …`, or
//! `unavailable <why>` when the library cannot be loaded or initialized.

use std::ffi::CStr;
use std::path::{Path, PathBuf};
use std::time::Instant;

use GLES_CM::gles::tokens::*;
use GLES_CM::gles::types::GLenum;

use crate::api::{Api, Egl, Library};
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
    let ctx = match Egl::new(gl, WIDTH, HEIGHT) {
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
                gles_cm_core::Primitive::Points => GL_POINTS,
                gles_cm_core::Primitive::Lines => GL_LINES,
                _ => GL_TRIANGLES,
            };
            (gl.glDrawArrays)(mode, d.first as i32, d.count as i32);
        }
        (gl.glFinish)();
    }
}
