//! The numerical hard cases of the GLES checklist (§4, cases 1–30), one test
//! each, named after the case, and the M3G hard cases of `m3g-checklist.md` §5 that
//! `crates/m3g/tests/m3g_*.rs` do not already cover (in `crates/m3g/tests/m3g_hard_cases.rs`). Each asserts the
//! behavior the specification prescribes or, where it leaves room, the one we document, and
//! that no NaN, infinity or garbage pixel appears: every pixel is either the clear color or
//! a color the draw can produce.
//!
//! Cases that need the GL state machine (matrix stacks, queries, textures, EGL) drive the C
//! API of the library linked into this test; the rest drive the core (`RenderState` +
//! `DrawCall`) directly, often against the f64 reference renderer.

use std::ffi::c_void;
use std::ptr::{null, null_mut};

use glam::{Mat4, Vec3, Vec4};
use gles_cm_core::reference;
use gles_cm_core::state::{
    Blend, BlendFactor, Light, Lighting, LogicOp, Material, PolygonOffset, StencilOp, StencilTest,
};
use gles_cm_core::texenv::{Fog, FogMode};
use gles_cm_core::{
    clip, AttribArray, AttribSource, ColorFormat, CompareFunc, ComponentType, DepthFormat,
    DrawCall, Indices, Primitive, RenderState, Target, TargetFormat,
};
use GLES_CM::egl::ffi::*;
use GLES_CM::egl::tokens::*;
use GLES_CM::egl::types::*;
use GLES_CM::gles::tokens::*;

// ---------------------------------------------------------------------------------------
// Core helpers.

fn fmt(color: ColorFormat, depth: Option<DepthFormat>, stencil_bits: u32) -> TargetFormat {
    TargetFormat {
        color,
        depth,
        stencil_bits,
    }
}

fn target(w: u32, h: u32) -> Target {
    let mut t = Target::new(w, h, fmt(ColorFormat::Rgba8888, Some(DepthFormat::D24), 8));
    t.clear_depth(t.bounds(), 1.0);
    t
}

/// A state whose projection maps object x, y straight to window pixels, z in [−1, 1].
fn pixel_state(w: i32, h: i32) -> RenderState {
    let mut s = RenderState::new(w, h);
    s.projection = Mat4::orthographic_rh_gl(0.0, w as f32, 0.0, h as f32, -1.0, 1.0);
    s
}

fn bytes<T: Copy>(v: &[T]) -> Vec<u8> {
    let n = std::mem::size_of_val(v);
    // SAFETY: any initialized plain-data slice may be viewed as bytes.
    unsafe { std::slice::from_raw_parts(v.as_ptr().cast::<u8>(), n).to_vec() }
}

fn array(data: &[u8], ty: ComponentType, size: usize) -> AttribArray<'_> {
    AttribArray {
        data,
        ty,
        size,
        stride: size * ty.size(),
        normalized: false,
    }
}

/// A draw of float positions (`size` per vertex) with per-vertex RGBA colors, or white.
fn call<'a>(prim: Primitive, pos: &'a [u8], size: usize, col: Option<&'a [u8]>) -> DrawCall<'a> {
    let count = pos.len() / (4 * size);
    let mut c = DrawCall::new(
        prim,
        Indices::Range { first: 0, count },
        array(pos, ComponentType::Float, size),
    );
    if let Some(col) = col {
        c.color = AttribSource::Array(array(col, ComponentType::Float, 4));
    }
    c
}

fn draw(s: &RenderState, t: &mut Target, prim: Primitive, pos: &[f32], size: usize, col: &[f32]) {
    let (p, c) = (bytes(pos), bytes(col));
    let d = call(prim, &p, size, (!col.is_empty()).then_some(&c[..]));
    gles_cm_core::render(s, &d, t).unwrap();
}

/// The same draw through the reference renderer.
fn draw_ref(
    s: &RenderState,
    t: &mut Target,
    prim: Primitive,
    pos: &[f32],
    size: usize,
    col: &[f32],
) {
    let (p, c) = (bytes(pos), bytes(col));
    let d = call(prim, &p, size, (!col.is_empty()).then_some(&c[..]));
    reference::render(s, &d, t);
}

/// Fast and reference images of one draw on fresh targets.
fn both(
    s: &RenderState,
    w: u32,
    h: u32,
    prim: Primitive,
    pos: &[f32],
    size: usize,
    col: &[f32],
) -> (Target, Target) {
    let (mut a, mut b) = (target(w, h), target(w, h));
    draw(s, &mut a, prim, pos, size, col);
    draw_ref(s, &mut b, prim, pos, size, col);
    (a, b)
}

fn count(t: &Target, f: impl Fn([u8; 4]) -> bool) -> usize {
    t.color().iter().filter(|w| f(w.to_le_bytes())).count()
}

fn covered(t: &Target) -> usize {
    count(t, |p| p != [0, 0, 0, 0])
}

/// Every pixel is the clear color (0) or has each channel within [lo − 1, hi + 1] of the
/// colors the draw can produce: no garbage.
fn assert_clean(t: &Target, lo: [u8; 4], hi: [u8; 4]) {
    for (i, w) in t.color().iter().enumerate() {
        let p = w.to_le_bytes();
        if p == [0; 4] {
            continue;
        }
        for c in 0..4 {
            assert!(
                p[c].saturating_add(1) >= lo[c] && p[c] <= hi[c].saturating_add(1),
                "garbage pixel {p:?} at {} (allowed {lo:?}..{hi:?})",
                i
            );
        }
    }
}

/// The vertex stage's output for a draw, every texture unit enabled so that every unit's
/// coordinates are computed: every value finite.
fn assert_vertices_finite(
    s: &RenderState,
    d: &DrawCall<'_>,
) -> Vec<gles_cm_core::vertex::ClipVertex> {
    let mut s = s.clone();
    s.textures = std::array::from_fn(|_| Some(gles_cm_core::texenv::TextureUnit::white()));
    let v = gles_cm_core::vertex::run(&s, d).unwrap();
    let (lo, hi) = d.indices.range().unwrap();
    let out: Vec<_> = (lo..=hi).map(|i| v.get(i).unpack()).collect();
    for v in &out {
        assert!(v.color.is_finite() && v.back_color.is_finite(), "{v:?}");
        assert!(v.tex.iter().all(|t| t.is_finite()), "{v:?}");
    }
    out
}

/// The two images' coverage as text (`#` both, `f` fast only, `r` reference only).
fn picture(a: &Target, b: &Target) -> String {
    let mut s = String::from("\n");
    for y in (0..a.height()).rev() {
        for x in 0..a.width() {
            let (p, q) = (a.pixel(x, y) != [0; 4], b.pixel(x, y) != [0; 4]);
            s.push(match (p, q) {
                (true, true) => '#',
                (true, false) => 'f',
                (false, true) => 'r',
                _ => '.',
            });
        }
        s.push('\n');
    }
    s
}

fn rgba(c: [f32; 4], n: usize) -> Vec<f32> {
    (0..n).flat_map(|_| c).collect()
}

// ---------------------------------------------------------------------------------------
// GL helpers: a pbuffer context through the library's own C entry points.

#[allow(non_snake_case, dead_code)]
extern "C" {
    fn glGetError() -> u32;
    fn glViewport(x: i32, y: i32, w: i32, h: i32);
    fn glMatrixMode(m: u32);
    fn glLoadIdentity();
    fn glLoadMatrixf(m: *const f32);
    fn glOrthof(l: f32, r: f32, b: f32, t: f32, n: f32, f: f32);
    fn glScalef(x: f32, y: f32, z: f32);
    fn glTranslatef(x: f32, y: f32, z: f32);
    fn glClipPlanef(p: u32, eq: *const f32);
    fn glGetClipPlanef(p: u32, eq: *mut f32);
    fn glEnable(cap: u32);
    fn glDisable(cap: u32);
    fn glClearColor(r: f32, g: f32, b: f32, a: f32);
    fn glClear(mask: u32);
    fn glColor4f(r: f32, g: f32, b: f32, a: f32);
    fn glNormal3f(x: f32, y: f32, z: f32);
    fn glEnableClientState(a: u32);
    fn glDisableClientState(a: u32);
    fn glVertexPointer(size: i32, ty: u32, stride: i32, p: *const c_void);
    fn glTexCoordPointer(size: i32, ty: u32, stride: i32, p: *const c_void);
    fn glDrawArrays(mode: u32, first: i32, count: i32);
    fn glDrawElements(mode: u32, count: i32, ty: u32, p: *const c_void);
    fn glReadPixels(x: i32, y: i32, w: i32, h: i32, f: u32, ty: u32, p: *mut c_void);
    fn glPixelStorei(p: u32, v: i32);
    fn glGetIntegerv(p: u32, v: *mut i32);
    fn glGetFloatv(p: u32, v: *mut f32);
    fn glGetFixedv(p: u32, v: *mut i32);
    fn glLightfv(l: u32, p: u32, v: *const f32);
    fn glMaterialf(f: u32, p: u32, v: f32);
    fn glQueryMatrixxOES(m: *mut i32, e: *mut i32) -> u32;
    fn glPointSize(s: f32);
    fn glPointParameterf(p: u32, v: f32);
    fn glPointParameterfv(p: u32, v: *const f32);
    fn glTexEnvi(t: u32, p: u32, v: i32);
    fn glGenTextures(n: i32, t: *mut u32);
    fn glBindTexture(t: u32, n: u32);
    fn glTexParameteri(t: u32, p: u32, v: i32);
    fn glTexImage2D(
        t: u32,
        l: i32,
        i: i32,
        w: i32,
        h: i32,
        b: i32,
        f: u32,
        ty: u32,
        p: *const c_void,
    );
    fn glCompressedTexImage2D(
        t: u32,
        l: i32,
        f: u32,
        w: i32,
        h: i32,
        b: i32,
        n: i32,
        p: *const c_void,
    );
    fn glGenBuffers(n: i32, b: *mut u32);
    fn glBindBuffer(t: u32, b: u32);
    fn glBufferData(t: u32, n: isize, p: *const c_void, u: u32);
    fn glFinish();
}

/// A pbuffer surface and a current ES 1.x context on this thread; released on drop.
struct Gl {
    dpy: EGLDisplay,
    surface: EGLSurface,
    context: EGLContext,
    w: i32,
    h: i32,
}

fn config(dpy: EGLDisplay, red: i32, depth: i32, stencil: i32) -> EGLConfig {
    let attribs = [
        EGL_SURFACE_TYPE,
        EGL_PBUFFER_BIT,
        EGL_RENDERABLE_TYPE,
        EGL_OPENGL_ES_BIT,
        EGL_RED_SIZE,
        red,
        EGL_DEPTH_SIZE,
        depth,
        EGL_STENCIL_SIZE,
        stencil,
        EGL_NONE,
    ];
    let mut configs = [null_mut(); 64];
    let mut n = 0;
    // SAFETY: the attribute list ends in EGL_NONE; `configs` holds 64 entries.
    unsafe {
        assert_eq!(
            eglChooseConfig(dpy, attribs.as_ptr(), configs.as_mut_ptr(), 64, &mut n),
            1
        );
        let attr = |c: EGLConfig, a: EGLint| {
            let mut v = -1;
            eglGetConfigAttrib(dpy, c, a, &mut v);
            v
        };
        configs[..n as usize]
            .iter()
            .copied()
            .find(|&c| {
                attr(c, EGL_RED_SIZE) == red
                    && attr(c, EGL_DEPTH_SIZE) == depth
                    && attr(c, EGL_STENCIL_SIZE) == stencil
                    && (red == 5 || attr(c, EGL_ALPHA_SIZE) == 8)
            })
            .expect("config")
    }
}

impl Gl {
    /// RGBA8888 (or RGB565 with `red == 5`) with the given depth and stencil bits.
    fn new(w: i32, h: i32, red: i32, depth: i32, stencil: i32) -> Gl {
        // SAFETY: handles come from this display; attribute lists end in EGL_NONE.
        unsafe {
            let dpy = eglGetDisplay(null_mut());
            assert_eq!(eglInitialize(dpy, null_mut(), null_mut()), 1);
            let cfg = config(dpy, red, depth, stencil);
            let pb = [EGL_WIDTH, w, EGL_HEIGHT, h, EGL_NONE];
            let surface = eglCreatePbufferSurface(dpy, cfg, pb.as_ptr());
            let context = eglCreateContext(dpy, cfg, null_mut(), null());
            assert!(!surface.is_null() && !context.is_null());
            assert_eq!(eglMakeCurrent(dpy, surface, surface, context), 1);
            Gl {
                dpy,
                surface,
                context,
                w,
                h,
            }
        }
    }

    fn rgba8(w: i32, h: i32) -> Gl {
        Gl::new(w, h, 8, 24, 8)
    }

    /// The color buffer as RGBA bytes, row 0 at the bottom.
    fn read(&self) -> Vec<[u8; 4]> {
        let mut px = vec![[0u8; 4]; (self.w * self.h) as usize];
        // SAFETY: `px` holds w × h RGBA8 pixels with alignment 4.
        unsafe {
            glPixelStorei(GL_PACK_ALIGNMENT, 4);
            glReadPixels(
                0,
                0,
                self.w,
                self.h,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                px.as_mut_ptr().cast(),
            );
        }
        assert_eq!(err(), GL_NO_ERROR);
        px
    }

    /// Pixel-aligned orthographic projection, identity modelview, cleared to black.
    fn pixel_ortho(&self) {
        // SAFETY: a context is current.
        unsafe {
            glMatrixMode(GL_PROJECTION);
            glLoadIdentity();
            glOrthof(0.0, self.w as f32, 0.0, self.h as f32, -1.0, 1.0);
            glMatrixMode(GL_MODELVIEW);
            glLoadIdentity();
            glClearColor(0.0, 0.0, 0.0, 0.0);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        }
    }
}

impl Drop for Gl {
    fn drop(&mut self) {
        // The handles were created on this display and are released once.
        eglMakeCurrent(self.dpy, null_mut(), null_mut(), null_mut());
        eglDestroyContext(self.dpy, self.context);
        eglDestroySurface(self.dpy, self.surface);
    }
}

fn err() -> u32 {
    // SAFETY: no preconditions beyond a current context (none: GL_NO_ERROR... never UB).
    unsafe { glGetError() }
}

/// Draws float xyz triangles (or `mode`) from client memory.
fn gl_draw(mode: u32, xyz: &[f32]) {
    // SAFETY: `xyz` outlives the draw, which reads `len / 3` vertices of 3 floats.
    unsafe {
        glEnableClientState(GL_VERTEX_ARRAY);
        glVertexPointer(3, GL_FLOAT, 0, xyz.as_ptr().cast());
        glDrawArrays(mode, 0, (xyz.len() / 3) as i32);
    }
}

fn gl_covered(px: &[[u8; 4]]) -> usize {
    px.iter().filter(|p| p[..3] != [0, 0, 0]).count()
}

// ---------------------------------------------------------------------------------------
// Geometry, clipping and depth.

/// A perspective state for a `w` × `h` target: 60° field of view, near 0.5, far 50.
fn perspective(w: i32, h: i32) -> RenderState {
    let mut s = RenderState::new(w, h);
    s.projection = Mat4::perspective_rh_gl(1.0, w as f32 / h as f32, 0.5, 50.0);
    s
}

#[test]
fn case_01_w_negative_vertices_are_clipped_before_the_divide() {
    let s = perspective(64, 48);
    // One vertex behind the eye (eye z > 0), two in front: a wedge reaching the screen's edge.
    let pos = [-1.0, -0.5, -2.0, 1.0, -0.5, -2.0, 0.0, 0.3, 3.0];
    let col = [1., 0., 0., 1., 0., 1., 0., 1., 0., 0., 1., 1.];
    let (fast, slow) = both(&s, 64, 48, Primitive::Triangles, &pos, 3, &col);
    let e = reference::compare(&fast, &slow);
    assert!(e.max <= 2 && e.over_one < 0.01, "{e:?}");
    assert!(covered(&fast) > 100);
    assert_clean(&fast, [0, 0, 0, 255], [255, 255, 255, 255]);
    // Every vertex behind the eye: nothing, even though x/w, y/w would land on screen.
    let behind = [-1.0, -0.5, 2.0, 1.0, -0.5, 2.0, 0.0, 0.3, 3.0];
    let (fast, _) = both(&s, 64, 48, Primitive::Triangles, &behind, 3, &col);
    assert_eq!(covered(&fast), 0);
    // Clip-space vertices with w < 0 given directly (xyzw), some with w = 0.
    let mut id = RenderState::new(64, 48);
    id.projection = Mat4::IDENTITY;
    let xyzw = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 0.0, -1.0, -1.0, 1.0, 0.5, 1.0];
    let (fast, slow) = both(&id, 64, 48, Primitive::Triangles, &xyzw, 4, &col);
    assert_eq!(covered(&fast), covered(&slow), "{}", picture(&fast, &slow));
    assert_clean(&fast, [0, 0, 0, 255], [255, 255, 255, 255]);
    // Reversed depth (M3G allows parallel projections with far < near, and negative ones):
    // an orthographic projection with near 5, far −5 inverts the depth order.
    let mut rev = RenderState::new(16, 16);
    rev.projection = Mat4::orthographic_rh_gl(-1.0, 1.0, -1.0, 1.0, 5.0, -5.0);
    rev.depth_test = Some(CompareFunc::Less);
    let quad = |z: f32| {
        [
            -1.0, -1.0, z, 1.0, -1.0, z, 1.0, 1.0, z, -1.0, -1.0, z, 1.0, 1.0, z, -1.0, 1.0, z,
        ]
    };
    let mut t = target(16, 16);
    draw(
        &rev,
        &mut t,
        Primitive::Triangles,
        &quad(-2.0),
        3,
        &rgba([1., 0., 0., 1.], 6),
    );
    draw(
        &rev,
        &mut t,
        Primitive::Triangles,
        &quad(2.0),
        3,
        &rgba([0., 1., 0., 1.], 6),
    );
    // Eye z = 2 is behind z = −2 for this camera (it looks down +z): red stays.
    assert_eq!(count(&t, |p| p == [255, 0, 0, 255]), 256);
}

#[test]
fn case_02_near_plane_crossing_screen_covering_triangle() {
    use gles_cm_core::vertex::{ClipVertex, Layout};
    let v = |x: f32, y: f32, z: f32, w: f32| ClipVertex::new(Vec4::new(x, y, z, w), Vec4::ONE);
    // Crosses the near plane (z = −w) and leaves the band on two sides.
    let (a, b, c) = (
        v(-30.0, -30.0, -3.0, 1.0),
        v(30.0, -30.0, 2.0, 1.0),
        v(0.0, 40.0, 0.5, 1.0),
    );
    let mut n = 0;
    let full = Layout::full(0);
    let [fa, fb, fc] = [a, b, c].map(|v| full.pack(&v));
    clip::triangle(full.view(&fa), full.view(&fb), full.view(&fc), |p| {
        n = p.len();
        for q in p {
            let q = q.pos();
            let w = q.w;
            assert!(w >= clip::W_MIN);
            assert!(q.z >= -w * 1.0001 && q.z <= w * 1.0001, "{q:?}");
            assert!(q.x.abs() <= clip::GUARD * w * 1.0001, "{q:?}");
            assert!(q.y.abs() <= clip::GUARD * w * 1.0001, "{q:?}");
        }
    });
    assert!((3..=9).contains(&n), "{n} vertices after frustum clipping");
    // With six user planes the polygon may grow by one vertex per plane.
    let mut cut = [a, b, c];
    for (k, q) in cut.iter_mut().enumerate() {
        q.clip_dist = std::array::from_fn(|i| ((i + k) as f32 * 1.7).sin());
    }
    let mut m = 0;
    let six = Layout::full(6);
    let cut = cut.map(|v| six.pack(&v));
    clip::triangle(
        six.view(&cut[0]),
        six.view(&cut[1]),
        six.view(&cut[2]),
        |p| m = p.len(),
    );
    assert!(m <= 9 + 6, "{m}");
    // Attribute continuity along the clip edge: a smooth triangle crossing the near plane
    // and covering the screen matches the exactly clipped reference.
    let s = perspective(64, 48);
    let pos = [-20.0, -20.0, -0.1, 20.0, -20.0, -0.1, 0.0, 20.0, -8.0];
    let col = [1., 0., 0., 1., 0., 1., 0., 1., 0., 0., 1., 1.];
    let (fast, slow) = both(&s, 64, 48, Primitive::Triangles, &pos, 3, &col);
    let e = reference::compare(&fast, &slow);
    assert!(e.max <= 2 && e.over_one < 0.01, "{e:?}");
    assert_eq!(covered(&fast), covered(&slow));
}

struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f32 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 40) as f32 / (1u64 << 24) as f32
    }
}

/// Random smooth-colored triangles in perspective.
fn random_scene(rng: &mut Lcg, n: usize) -> (Vec<f32>, Vec<f32>) {
    let (mut pos, mut col) = (Vec::new(), Vec::new());
    for _ in 0..n {
        let c = [
            rng.next() * 8.0 - 4.0,
            rng.next() * 6.0 - 3.0,
            -2.0 - rng.next() * 10.0,
        ];
        for _ in 0..3 {
            pos.extend([
                c[0] + rng.next() * 2.0 - 1.0,
                c[1] + rng.next() * 2.0 - 1.0,
                c[2] + rng.next() - 0.5,
            ]);
            col.extend([rng.next(), rng.next(), rng.next(), 1.0]);
        }
    }
    (pos, col)
}

#[test]
fn case_03_tile_invariance_with_adjusted_projections() {
    let (w, h) = (96, 64);
    let (pos, col) = random_scene(&mut Lcg(3), 300);
    let mut whole_s = perspective(w, h);
    whole_s.depth_test = Some(CompareFunc::Less);
    let mut whole = target(w as u32, h as u32);
    draw(&whole_s, &mut whole, Primitive::Triangles, &pos, 3, &col);
    let mut differ = 0;
    for (i, j) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
        // Tile (i, j) of a 2 × 2 split: NDC [−1 + i, i] × [−1 + j, j] scaled to [−1, 1].
        let adjust =
            Mat4::from_translation(Vec3::new(1.0 - 2.0 * i as f32, 1.0 - 2.0 * j as f32, 0.0))
                * Mat4::from_scale(Vec3::new(2.0, 2.0, 1.0));
        let mut s = perspective(w / 2, h / 2);
        s.projection = adjust * whole_s.projection;
        s.depth_test = Some(CompareFunc::Less);
        let mut tile = target(w as u32 / 2, h as u32 / 2);
        draw(&s, &mut tile, Primitive::Triangles, &pos, 3, &col);
        for y in 0..h as u32 / 2 {
            for x in 0..w as u32 / 2 {
                let (gx, gy) = (x + i * w as u32 / 2, y + j * h as u32 / 2);
                let (a, b) = (tile.pixel(x, y), whole.pixel(gx, gy));
                if a != b {
                    differ += 1;
                }
            }
        }
    }
    // The projection is multiplied by exact powers of two but its translation rounds: a
    // vertex may snap 1/256 pixel differently, moving at most a few edge pixels.
    assert!(
        differ <= (w * h) as usize / 500,
        "{differ} pixels differ between tiles and the whole"
    );
}

#[test]
fn case_04_huge_coordinates_and_viewports_larger_than_the_surface() {
    let s = pixel_state(64, 48);
    let col = [1., 0., 0., 1., 0., 1., 0., 1., 0., 0., 1., 1.];
    // Float positions up to 2³² covering the screen.
    let big = 4294967296.0f32;
    let pos = [-big, -big, 0.0, big, -big, 0.0, 0.0, big, 0.0];
    let (fast, slow) = both(&s, 64, 48, Primitive::Triangles, &pos, 3, &col);
    assert_eq!(covered(&fast), 64 * 48, "{}", picture(&fast, &slow));
    let e = reference::compare(&fast, &slow);
    assert!(e.max <= 2, "{e:?}");
    // Fixed positions at the ends of their range (±32767.99), and short and byte ones.
    let fx: [i32; 9] = [i32::MIN, i32::MIN, 0, i32::MAX, i32::MIN, 0, 0, i32::MAX, 0];
    let sh: [i16; 9] = [-32768, -32768, 0, 32767, -32768, 0, 0, 32767, 0];
    let by: [i8; 9] = [-128, -128, 0, 127, -128, 0, 0, 127, 0];
    for (data, ty) in [
        (bytes(&fx), ComponentType::Fixed),
        (bytes(&sh), ComponentType::Short),
        (bytes(&by), ComponentType::Byte),
    ] {
        let d = DrawCall::new(
            Primitive::Triangles,
            Indices::Range { first: 0, count: 3 },
            array(&data, ty, 3),
        );
        let (mut a, mut b) = (target(64, 48), target(64, 48));
        gles_cm_core::render(&s, &d, &mut a).unwrap();
        reference::render(&s, &d, &mut b);
        assert_eq!(covered(&a), covered(&b), "{ty:?}");
        assert!(covered(&a) > 64 * 48 / 3, "{ty:?}");
    }
    // A 8192 × 8192 viewport (GL_MAX_VIEWPORT_DIMS) on a 64 × 48 surface, offset so the
    // surface sees part of it: pixels match the reference.
    let mut v = RenderState::new(64, 48);
    v.viewport = gles_cm_core::Viewport {
        x: -4000,
        y: -4000,
        width: 8192,
        height: 8192,
    };
    let tri = [
        -0.021, -0.021, 0.0, -0.016, -0.0205, 0.0, -0.019, -0.015, 0.0,
    ];
    let (fast, slow) = both(&v, 64, 48, Primitive::Triangles, &tri, 3, &col);
    assert_eq!(covered(&fast), covered(&slow));
    assert!(covered(&fast) > 0);
    // A size-8 point whose center (window (−2, 30)) lies inside the viewport but outside
    // the surface: drawn where it covers the surface, 2 columns of 8.
    v.point_size = 8.0;
    let p = [-98.0 / 4096.0, -66.0 / 4096.0, 0.0];
    let (fast, slow) = both(&v, 64, 48, Primitive::Points, &p, 3, &[]);
    assert_eq!(covered(&fast), 16);
    assert_eq!(covered(&slow), 16);
}

#[test]
fn case_05_near_far_ratio_depth_range_slices_and_a_sky() {
    let quad = |z: f32, s: f32| [-s, -s, z, s, -s, z, s, s, z, -s, -s, z, s, s, z, -s, s, z];
    let red = rgba([1., 0., 0., 1.], 6);
    let green = rgba([0., 1., 0., 1.], 6);
    // n = 0.01, f = 10⁵: at distance 1000 two quads 20 units apart are 3.4 steps apart in
    // a 24-bit buffer and 0.013 steps in a 16-bit one (see tests/depth_precision in
    // properties.rs and ACCURACY.md for the whole table).
    for (depth, resolves) in [(DepthFormat::D24, true), (DepthFormat::D16, false)] {
        let mut s = RenderState::new(16, 16);
        s.projection = Mat4::perspective_rh_gl(1.0, 1.0, 0.01, 1e5);
        s.depth_test = Some(CompareFunc::Less);
        let mut t = Target::new(16, 16, fmt(ColorFormat::Rgba8888, Some(depth), 0));
        t.clear_depth(t.bounds(), 1.0);
        draw(
            &s,
            &mut t,
            Primitive::Triangles,
            &quad(-1020.0, 2000.0),
            3,
            &green,
        );
        draw(
            &s,
            &mut t,
            Primitive::Triangles,
            &quad(-1000.0, 2000.0),
            3,
            &red,
        );
        let reds = count(&t, |p| p == [255, 0, 0, 255]);
        assert_eq!(reds == 256, resolves, "{depth:?}: {reds} red");
    }
    // Depth-range slices: a far object in [0, 0.1] beats a near one in [0.1, 1]; a sky at
    // [1, 1] with LEQUAL fills only what nothing else covered.
    let mut s = perspective(32, 32);
    s.depth_test = Some(CompareFunc::LessEqual);
    let mut t = target(32, 32);
    s.depth_range = [0.1, 1.0];
    draw(
        &s,
        &mut t,
        Primitive::Triangles,
        &quad(-1.0, 0.3),
        3,
        &green,
    );
    s.depth_range = [0.0, 0.1];
    draw(
        &s,
        &mut t,
        Primitive::Triangles,
        &quad(-40.0, 20.0),
        3,
        &red,
    );
    let reds = count(&t, |p| p == [255, 0, 0, 255]);
    s.depth_range = [1.0, 1.0];
    draw(
        &s,
        &mut t,
        Primitive::Triangles,
        &quad(-10.0, 100.0),
        3,
        &rgba([0., 0., 1., 1.], 6),
    );
    assert_eq!(
        count(&t, |p| p == [0, 255, 0, 255]),
        0,
        "the far slice's object is in front"
    );
    assert_eq!(
        count(&t, |p| p == [255, 0, 0, 255]),
        reds,
        "the sky never covers"
    );
    assert_eq!(count(&t, |p| p == [0, 0, 255, 255]), 32 * 32 - reds);
}

#[test]
fn case_06_polygon_offset_on_grazing_polygons() {
    // A floor seen at a grazing angle: depth slopes are large, and a decal drawn over it
    // with the same vertices must win everywhere with a negative offset, lose everywhere
    // with a positive one, and z-fight (LESS never passes) without one.
    let floor = [
        -2.0, -1.0, -0.6, 2.0, -1.0, -0.6, 2.0, -0.9, -40.0, -2.0, -1.0, -0.6, 2.0, -0.9, -40.0,
        -2.0, -0.9, -40.0,
    ];
    let (w, h) = (64, 48);
    for depth in [DepthFormat::D16, DepthFormat::D24] {
        for (offset, want_all) in [
            (Some((-1.0, -1.0)), Some(true)),
            (Some((1.0, 1.0)), Some(false)),
            (Some((-2.0, 0.0)), Some(true)),
            (Some((0.0, -2.0)), None),
        ] {
            let mut s = perspective(w, h);
            s.depth_test = Some(CompareFunc::Less);
            let mut t = Target::new(
                w as u32,
                h as u32,
                fmt(ColorFormat::Rgba8888, Some(depth), 0),
            );
            t.clear_depth(t.bounds(), 1.0);
            draw(
                &s,
                &mut t,
                Primitive::Triangles,
                &floor,
                3,
                &rgba([0., 1., 0., 1.], 6),
            );
            let wall = count(&t, |p| p == [0, 255, 0, 255]);
            assert!(wall > 300);
            s.polygon_offset = offset.map(|(factor, units)| PolygonOffset {
                factor,
                units,
                clamp: 0.0,
            });
            draw(
                &s,
                &mut t,
                Primitive::Triangles,
                &floor,
                3,
                &rgba([1., 0., 0., 1.], 6),
            );
            let decal = count(&t, |p| p == [255, 0, 0, 255]);
            match want_all {
                Some(true) => assert_eq!(decal, wall, "{depth:?} {offset:?}"),
                Some(false) => assert_eq!(decal, 0, "{depth:?} {offset:?}"),
                // Units alone: two steps always separate the same interpolated depth.
                None => assert_eq!(decal, wall, "{depth:?} {offset:?}"),
            }
        }
    }
}

#[test]
fn case_07_degenerate_triangles_produce_no_pixels() {
    let s = pixel_state(32, 32);
    // Stitching triangles of a strip (repeated indices), collinear and coincident vertices.
    let pos = [
        4.0, 4.0, 0.0, 20.0, 4.0, 0.0, 4.0, 20.0, 0.0, // 0 1 2
        4.0, 4.0, 0.0, 12.0, 12.0, 0.0, 28.3, 28.3, 0.0, // collinear 3 4 5
        7.0, 9.0, 0.0, 7.0, 9.0, 0.0, 7.0, 9.0, 0.0, // coincident 6 7 8
    ];
    let p = bytes(&pos);
    for idx in [
        &[0u16, 0, 1][..],
        &[1, 2, 2],
        &[3, 4, 5],
        &[6, 7, 8],
        &[0, 1, 1, 2, 2, 2],
    ] {
        for prim in [
            Primitive::Triangles,
            Primitive::TriangleStrip,
            Primitive::TriangleFan,
        ] {
            let d = DrawCall::new(prim, Indices::U16(idx), array(&p, ComponentType::Float, 3));
            let mut t = target(32, 32);
            gles_cm_core::render(&s, &d, &mut t).unwrap();
            assert_eq!(covered(&t), 0, "{idx:?} {prim:?}");
            assert_vertices_finite(&s, &d);
        }
    }
    // A strip stitched with degenerate triangles covers what its real triangles cover,
    // each pixel once (additive blending would show a second hit).
    let mut add = s.clone();
    add.blend = Some(Blend::func(BlendFactor::One, BlendFactor::One));
    let strip = [0u16, 1, 2, 2, 6, 6, 4, 5];
    let d = DrawCall {
        color: AttribSource::Constant([0.2, 0.0, 0.0, 0.0]),
        ..DrawCall::new(
            Primitive::TriangleStrip,
            Indices::U16(&strip),
            array(&p, ComponentType::Float, 3),
        )
    };
    let mut t = target(32, 32);
    gles_cm_core::render(&add, &d, &mut t).unwrap();
    assert_eq!(count(&t, |p| p[0] > 51), 0, "no pixel hit twice");
}

#[test]
fn case_08_subpixel_and_sliver_triangles_match_exact_coverage() {
    // Vertices on the 1/256 subpixel grid snap exactly, so coverage must equal the
    // reference's literal sampling, pixel for pixel, even for long slivers.
    let s = pixel_state(64, 64);
    let mut rng = Lcg(8);
    let q = |v: f32| (v * 256.0).round() / 256.0;
    for i in 0..300 {
        let (x, y) = (q(rng.next() * 64.0), q(rng.next() * 64.0));
        let pos = if i % 2 == 0 {
            // A long sliver, under a pixel thick.
            let (dx, dy) = (q(rng.next() * 60.0 - 30.0), q(rng.next() * 60.0 - 30.0));
            let t = q(rng.next() * 0.8);
            [x, y, 0.0, x + dx, y + dy, 0.0, x + dx + t, y + dy - t, 0.0]
        } else {
            // Subpixel: all three vertices within one pixel.
            [
                x,
                y,
                0.0,
                x + q(rng.next() * 0.9),
                y,
                0.0,
                x,
                y + q(rng.next() * 0.9),
                0.0,
            ]
        };
        let (fast, slow) = both(&s, 64, 64, Primitive::Triangles, &pos, 3, &[]);
        assert_eq!(
            covered(&fast),
            covered(&slow),
            "{pos:?}{}",
            picture(&fast, &slow)
        );
        assert!(fast.color() == slow.color(), "{pos:?}");
        if i % 2 == 1 {
            assert!(covered(&fast) <= 1);
        }
    }
}

#[test]
fn case_09_shared_edges_are_covered_exactly_once() {
    let mut s = pixel_state(48, 48);
    s.blend = Some(Blend::func(BlendFactor::One, BlendFactor::One));
    let one = 1.0 / 255.0;
    let mut rng = Lcg(9);
    // A jittered strip and a fan around a non-integer center.
    let mut strip = Vec::new();
    for i in 0..=12 {
        let x = 2.0 + i as f32 * 3.6 + rng.next() * 0.8;
        strip.extend([
            x,
            3.0 + rng.next() * 2.0,
            0.0,
            x + rng.next(),
            44.0 - rng.next() * 2.0,
            0.0,
        ]);
    }
    let mut fan = vec![23.7f32, 24.2, 0.0];
    for i in 0..=17 {
        let a = i as f32 / 17.0 * std::f32::consts::TAU;
        fan.extend([23.7 + 20.3 * a.cos(), 24.2 + 19.1 * a.sin(), 0.0]);
    }
    for (prim, pos) in [
        (Primitive::TriangleStrip, &strip),
        (Primitive::TriangleFan, &fan),
    ] {
        let mut t = target(48, 48);
        draw(
            &s,
            &mut t,
            prim,
            pos,
            3,
            &rgba([one, one, one, one], pos.len() / 3),
        );
        assert_eq!(count(&t, |p| p[0] > 1), 0, "{prim:?}: a pixel hit twice");
        assert!(count(&t, |p| p[0] == 1) > 48 * 48 / 2, "{prim:?}");
        // No cracks: every pixel inside the covered span of each row is hit.
        for y in 6..42 {
            let row: Vec<bool> = (0..48).map(|x| t.pixel(x, y)[0] == 1).collect();
            if let (Some(a), Some(b)) = (row.iter().position(|&v| v), row.iter().rposition(|&v| v))
            {
                assert!(row[a..=b].iter().all(|&v| v), "{prim:?}: crack in row {y}");
            }
        }
    }
}

#[test]
fn case_10_wide_points_and_lines_at_the_viewport_border() {
    let mut s = pixel_state(32, 32);
    s.point_size = 8.0;
    // Center just outside: the whole point vanishes. Just inside: the part on the surface.
    // (An even-sized aliased point's square is centered on the pixel corner nearest its
    // center, ES 1.1 §3.3: x = 0.5 covers columns 0 to 4.)
    for (x, want) in [
        (-0.5f32, 0usize),
        (-0.01, 0),
        (0.5, 40),
        (31.5, 32),
        (32.01, 0),
        (16.0, 64),
    ] {
        let (fast, slow) = both(&s, 32, 32, Primitive::Points, &[x, 16.0, 0.0], 3, &[]);
        assert_eq!(covered(&fast), want, "x = {x}");
        assert_eq!(covered(&slow), want, "x = {x}");
    }
    // Wide lines crossing the border keep exactly the reference's pieces.
    for width in [1.0, 3.0, 5.0, 8.0] {
        s.line_width = width;
        let pos = [
            -10.0, 3.3, 0.0, 20.2, 40.0, 0.0, 5.5, -3.0, 0.0, 40.0, 12.7, 0.0,
        ];
        let (fast, slow) = both(&s, 32, 32, Primitive::Lines, &pos, 3, &[]);
        assert_eq!(
            covered(&fast),
            covered(&slow),
            "width {width}{}",
            picture(&fast, &slow)
        );
    }
}

/// A draw of one screen-covering pixel-space quad with a constant normal.
fn lit_vertices(
    s: &RenderState,
    pos: &[f32],
    size: usize,
    normal: [f32; 4],
) -> Vec<gles_cm_core::vertex::ClipVertex> {
    let p = bytes(pos);
    let mut d = call(Primitive::Triangles, &p, size, None);
    d.normal = AttribSource::Constant(normal);
    assert_vertices_finite(s, &d)
}

fn one_light(light: Light, material: Material) -> Lighting {
    Lighting {
        lights: vec![light],
        model_ambient: Vec4::ZERO,
        front: material,
        back: material,
        ..Lighting::default()
    }
}

#[test]
fn case_12_singular_modelview_for_2d_drawing() {
    // The book's example: glScalef(2, −2, 0) on the modelview, (.5, −.5, 0) on the texture
    // matrix. Positions are fine (z = 0 everywhere); the normal matrix is singular.
    let mut s = pixel_state(32, 32);
    s.modelview = Mat4::from_scale(Vec3::new(2.0, -2.0, 0.0))
        * Mat4::from_translation(Vec3::new(0.0, -16.0, 0.0));
    s.texture_matrices[0] = Mat4::from_scale(Vec3::new(0.5, -0.5, 0.0));
    let quad = [
        0.0, 0.0, 3.0, 8.0, 0.0, 3.0, 8.0, 8.0, 3.0, 0.0, 0.0, 3.0, 8.0, 8.0, 3.0, 0.0, 8.0, 3.0,
    ];
    let mut t = target(32, 32);
    draw(&s, &mut t, Primitive::Triangles, &quad, 3, &[]);
    assert_eq!(
        covered(&t),
        16 * 16,
        "the scaled quad covers rows 16..32, columns 0..16"
    );
    // With lighting (and NORMALIZE) on, the output is defined: finite and the same at
    // every vertex (the normal matrix of the flattening scale still maps +z to ±z).
    s.normalize = true;
    s.lighting = Some(one_light(
        Light {
            diffuse: Vec4::ONE,
            ..Light::default()
        },
        Material::default(),
    ));
    let v = lit_vertices(&s, &quad, 3, [0.0, 0.0, 1.0, 0.0]);
    assert!(v.iter().all(|x| x.color == v[0].color), "{v:?}");
}

#[test]
fn case_13_zero_non_unit_rescaled_and_integer_normals() {
    let mut s = RenderState::new(8, 8);
    let light = Light {
        diffuse: Vec4::ONE,
        ..Light::default()
    };
    let m = Material {
        ambient: Vec4::ZERO,
        diffuse: Vec4::splat(0.5),
        ..Material::default()
    };
    s.lighting = Some(one_light(light, m));
    let tri = [0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.5, 0.0];
    // Zero-length with NORMALIZE: no NaN, n · l = 0.
    s.normalize = true;
    assert_eq!(lit_vertices(&s, &tri, 3, [0.0; 4])[0].color.x, 0.0);
    // A non-unit normal is normalized with NORMALIZE, used as is without (saturating).
    assert!((lit_vertices(&s, &tri, 3, [0.0, 0.0, 3.0, 0.0])[0].color.x - 0.5).abs() < 1e-6);
    s.normalize = false;
    assert_eq!(
        lit_vertices(&s, &tri, 3, [0.0, 0.0, 3.0, 0.0])[0].color.x,
        1.0
    );
    // RESCALE_NORMAL under a uniform scale equals NORMALIZE.
    s.modelview = Mat4::from_scale(Vec3::splat(3.0));
    s.rescale_normal = true;
    let a = lit_vertices(&s, &tri, 3, [0.0, 0.6, 0.8, 0.0])[0].color;
    s.rescale_normal = false;
    s.normalize = true;
    let b = lit_vertices(&s, &tri, 3, [0.0, 0.6, 0.8, 0.0])[0].color;
    assert!((a - b).abs().max_element() < 1e-6, "{a} {b}");
    // Byte and short normals map max positive to +1 ((2c + 1) / (2ⁿ − 1)).
    let bn: [i8; 9] = [0, 0, 127, 0, 0, 127, 0, 0, 127];
    let p = bytes(&tri);
    let nb = bytes(&bn);
    let mut d = call(Primitive::Triangles, &p, 3, None);
    d.normal = AttribSource::Array(AttribArray {
        normalized: true,
        ..array(&nb, ComponentType::Byte, 3)
    });
    s.normalize = false;
    s.modelview = Mat4::IDENTITY;
    assert!((assert_vertices_finite(&s, &d)[0].color.x - 0.5).abs() < 1e-6);
}

#[test]
fn case_14_lighting_edges() {
    let tri = [0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.5, 0.0];
    let mut s = RenderState::new(8, 8);
    let spec = Material {
        ambient: Vec4::ZERO,
        diffuse: Vec4::ZERO,
        specular: Vec4::ONE,
        shininess: 0.0,
        ..Material::default()
    };
    // Shininess 0: (n · h)⁰ = 1 whenever n · l ≠ 0 ...
    let light = Light {
        specular: Vec4::ONE,
        position: Vec4::new(0.0, 1.0, 1.0, 0.0),
        ..Light::default()
    };
    s.lighting = Some(one_light(light, spec));
    assert_eq!(
        lit_vertices(&s, &tri, 3, [0.0, 0.0, 1.0, 0.0])[0].color.x,
        1.0
    );
    // ... and f = 0 when n · l is exactly 0 (a light in the surface's plane).
    let grazing = Light {
        position: Vec4::new(1.0, 0.0, 0.0, 0.0),
        ..light
    };
    s.lighting = Some(one_light(grazing, spec));
    assert_eq!(
        lit_vertices(&s, &tri, 3, [0.0, 0.0, 1.0, 0.0])[0].color.x,
        0.0
    );
    // Spot cutoffs 90 and 180, exponent 128; a vertex behind a 90° spot is dark.
    let diffuse = Material {
        ambient: Vec4::ZERO,
        diffuse: Vec4::ONE,
        ..Material::default()
    };
    for (cutoff, exponent, in_front, behind) in [
        (180.0, 0.0, 1.0, 1.0),
        (90.0, 0.0, 1.0, 0.0),
        (90.0, 128.0, 1.0, 0.0),
    ] {
        let spot = Light {
            diffuse: Vec4::ONE,
            position: Vec4::new(0.0, 0.0, 1.0, 1.0),
            spot_direction: Vec3::new(0.0, 0.0, -1.0),
            spot_cutoff: cutoff,
            spot_exponent: exponent,
            ..Light::default()
        };
        s.lighting = Some(one_light(spot, diffuse));
        // Vertex 0 at the origin, straight in front of the spot; a vertex above it (z = 2)
        // is behind the spot (it faces the light with normal +z).
        let c = lit_vertices(
            &s,
            &[0.0, 0.0, 0.0, 0.0, 0.0, 2.0, 1.0, 0.0, 0.0],
            3,
            [0.0, 0.0, 1.0, 0.0],
        );
        assert!(
            (c[0].color.x - in_front).abs() < 1e-5,
            "{cutoff} {exponent}: {:?}",
            c[0].color
        );
        let back = lit_vertices(
            &s,
            &[0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0],
            3,
            [0.0, 0.0, -1.0, 0.0],
        );
        assert!(
            (back[0].color.x - behind).abs() < 1e-5,
            "{cutoff}: {:?}",
            back[0].color
        );
    }
    // Attenuation denominator 0 (k_c = 0, k_l = 1, the vertex on the light): saturates.
    let at = Light {
        diffuse: Vec4::ONE,
        ambient: Vec4::splat(0.5),
        position: Vec4::new(0.0, 0.0, 0.0, 1.0),
        attenuation: [0.0, 1.0, 0.0],
        ..Light::default()
    };
    s.lighting = Some(one_light(
        at,
        Material {
            ambient: Vec4::ONE,
            ..diffuse
        },
    ));
    assert_eq!(
        lit_vertices(&s, &tri, 3, [0.0, 0.0, 1.0, 0.0])[0]
            .color
            .truncate(),
        Vec3::ONE
    );
    // Overbright and negative light colors are clamped after lighting.
    for (c, want) in [(4.0, 1.0), (-3.0, 0.0)] {
        let l = Light {
            diffuse: Vec4::splat(c),
            ..Light::default()
        };
        s.lighting = Some(one_light(l, diffuse));
        assert_eq!(
            lit_vertices(&s, &tri, 3, [0.0, 0.0, 1.0, 0.0])[0].color.x,
            want
        );
    }
    // Homogeneous vertices with w ∉ {0, 1} light like their divided position.
    let pl = Light {
        diffuse: Vec4::ONE,
        position: Vec4::new(0.0, 0.0, 2.0, 1.0),
        attenuation: [0.0, 0.0, 1.0],
        ..Light::default()
    };
    s.lighting = Some(one_light(
        pl,
        Material {
            ambient: Vec4::ZERO,
            diffuse: Vec4::splat(0.5),
            ..diffuse
        },
    ));
    let a = lit_vertices(
        &s,
        &[0.0, 0.0, 0.5, 1.0, 1.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0],
        4,
        [0.0, 0.0, 1.0, 0.0],
    )[0]
    .color;
    let b = lit_vertices(
        &s,
        &[0.0, 0.0, 1.5, 3.0, 1.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0],
        4,
        [0.0, 0.0, 1.0, 0.0],
    )[0]
    .color;
    assert!((a - b).abs().max_element() < 1e-6, "{a} {b}");
}

#[test]
fn case_15_fog_clipped_at_far_zero_density_start_equals_end_huge_z() {
    let fog = |mode, density, start, end| Fog {
        mode,
        density,
        start,
        end,
        color: [0.0, 0.0, 1.0, 1.0],
        quality: gles_cm_core::state::Quality::Nicest,
    };
    // An EXP2-fogged triangle crossing the far plane: the fog factor stays continuous up to
    // the clip edge (the reference clips exactly).
    let mut s = perspective(64, 48);
    s.fog = Some(fog(FogMode::Exp2, 0.05, 0.0, 1.0));
    let pos = [-3.0, -2.0, -5.0, 3.0, -2.0, -5.0, 0.0, 40.0, -80.0];
    let (fast, slow) = both(
        &s,
        64,
        48,
        Primitive::Triangles,
        &pos,
        3,
        &rgba([1., 0., 0., 1.], 3),
    );
    let e = reference::compare(&fast, &slow);
    assert!(e.max <= 2, "{e:?}");
    // Density 0: no fog. start == end: a hard edge (documented in gles_cm_core::texenv). Huge z.
    assert_eq!(fog(FogMode::Exp, 0.0, 0.0, 1.0).factor(1e30), 1.0);
    assert_eq!(fog(FogMode::Exp2, 0.0, 0.0, 1.0).factor(f32::MAX), 1.0);
    let edge = fog(FogMode::Linear, 0.0, 5.0, 5.0);
    assert_eq!((edge.factor(4.9), edge.factor(5.1)), (1.0, 0.0));
    for z in [0.0, 1e10, 1e30, f32::MAX, f32::INFINITY] {
        for m in [FogMode::Linear, FogMode::Exp, FogMode::Exp2] {
            let f = fog(m, 0.5, 1.0, 10.0).factor(z);
            assert!((0.0..=1.0).contains(&f), "{m:?} {z}: {f}");
        }
    }
}

#[test]
fn case_20_fixed_point_overflow_saturation_and_nan() {
    use gles_cm_core::fixed;
    assert_eq!(fixed::from_f32(32768.0), i32::MAX);
    assert_eq!(fixed::from_f32(-32769.0), i32::MIN);
    assert_eq!(fixed::from_f32(f32::INFINITY), i32::MAX);
    assert_eq!(fixed::from_f32(f32::NEG_INFINITY), i32::MIN);
    assert_eq!(fixed::from_f32(f32::NAN), 0);
    // Products below 2⁻¹⁶ round to 0 (nearest), not to garbage.
    assert_eq!(fixed::from_f32(1e-6), 0);
    assert_eq!(fixed::from_f32(-1e-6), 0);
    // The state is float: a fixed vertex at ±32768 through a scaling modelview does not
    // overflow (the fixed-point core of App. A.1 would).
    let mut s = pixel_state(32, 32);
    s.modelview = Mat4::from_scale(Vec3::splat(1.0 / 2048.0));
    let fx: [i32; 9] = [i32::MIN, 0, 0, 0, 0, 0, 0, i32::MAX, 0];
    let d = bytes(&fx);
    let call = DrawCall::new(
        Primitive::Triangles,
        Indices::Range { first: 0, count: 3 },
        array(&d, ComponentType::Fixed, 3),
    );
    let v = assert_vertices_finite(&s, &call);
    assert!(
        (v[0].pos.x - (2.0 * -16.0 / 32.0 - 1.0)).abs() < 1e-6,
        "{:?}",
        v[0].pos
    );
}

#[test]
fn case_22_blending_edges_match_the_reference() {
    let configs: Vec<(ColorFormat, Option<Blend>, Option<LogicOp>)> = vec![
        (
            ColorFormat::Rgba8888,
            Some(Blend::func(BlendFactor::SrcAlphaSaturate, BlendFactor::One)),
            None,
        ),
        (
            ColorFormat::Rgb565,
            Some(Blend::func(BlendFactor::SrcAlphaSaturate, BlendFactor::One)),
            None,
        ),
        (
            ColorFormat::Rgb565,
            Some(Blend::func(BlendFactor::DstAlpha, BlendFactor::Zero)),
            None,
        ),
        (
            ColorFormat::Rgba8888,
            Some(Blend::func(BlendFactor::One, BlendFactor::One)),
            None,
        ),
        (
            ColorFormat::Rgba8888,
            Some(Blend::func(BlendFactor::One, BlendFactor::One)),
            Some(LogicOp::Xor),
        ),
    ];
    for (color, blend, logic) in configs {
        let mut s = pixel_state(16, 16);
        s.blend = blend;
        s.logic_op = logic;
        let quad = [
            1.0, 1.0, 0.0, 15.0, 1.0, 0.0, 15.0, 15.0, 0.0, 1.0, 1.0, 0.0, 15.0, 15.0, 0.0, 1.0,
            15.0, 0.0,
        ];
        let (mut a, mut b) = (
            Target::new(16, 16, fmt(color, None, 0)),
            Target::new(16, 16, fmt(color, None, 0)),
        );
        // Repeated accumulation: 8 passes of a dim overbright-prone color.
        for k in 0..8 {
            let c = rgba([0.3, 0.45, 0.2, 0.1 * k as f32], 6);
            draw(&s, &mut a, Primitive::Triangles, &quad, 3, &c);
            draw_ref(&s, &mut b, Primitive::Triangles, &quad, 3, &c);
        }
        let e = reference::compare(&a, &b);
        assert!(e.max <= 1, "{color:?} {blend:?} {logic:?}: {e:?}");
        if logic.is_none()
            && color == ColorFormat::Rgba8888
            && blend.unwrap().src_rgb == BlendFactor::One
        {
            assert_eq!(
                a.pixel(8, 8)[..3],
                [255, 255, 255],
                "clamped after blending"
            );
        }
    }
}

#[test]
fn case_23_stencil_edges() {
    let quad = [
        0.0, 0.0, 0.0, 8.0, 0.0, 0.0, 8.0, 8.0, 0.0, 0.0, 0.0, 0.0, 8.0, 8.0, 0.0, 0.0, 8.0, 0.0,
    ];
    let test = |func, reference, op| StencilTest {
        func,
        reference,
        mask: u32::MAX,
        fail: StencilOp::Keep,
        depth_fail: StencilOp::Keep,
        depth_pass: op,
    };
    // No stencil buffer: the test always passes.
    let mut s = pixel_state(8, 8);
    s.stencil_test = Some(test(CompareFunc::Never, 0, StencilOp::Keep));
    let mut t = Target::new(8, 8, fmt(ColorFormat::Rgba8888, None, 0));
    draw(&s, &mut t, Primitive::Triangles, &quad, 3, &[]);
    assert_eq!(covered(&t), 64);
    // INCR saturates at 255, DECR at 0; a reference above 2⁸ − 1 is clamped.
    let mut t = target(8, 8);
    s.stencil_test = Some(test(CompareFunc::Always, 0, StencilOp::Incr));
    for _ in 0..300 {
        draw(&s, &mut t, Primitive::Triangles, &quad, 3, &[]);
    }
    assert!(t.stencil().iter().all(|&v| v == 255));
    s.stencil_test = Some(test(CompareFunc::Equal, 1000, StencilOp::Keep));
    t.clear_color(t.bounds(), [0.0; 4], [true; 4]);
    draw(&s, &mut t, Primitive::Triangles, &quad, 3, &[]);
    assert_eq!(covered(&t), 64, "ref 1000 compares as 255");
    s.stencil_test = Some(test(CompareFunc::Always, 0, StencilOp::Decr));
    for _ in 0..300 {
        draw(&s, &mut t, Primitive::Triangles, &quad, 3, &[]);
    }
    assert!(t.stencil().iter().all(|&v| v == 0));
    // Clear values are masked to the buffer's bits and by the write mask.
    t.clear_stencil(t.bounds(), 0x1F3, 0x0F);
    assert!(t.stencil().iter().all(|&v| v == 0x03));
}

#[test]
fn case_29_out_of_range_indices_do_not_crash() {
    let s = pixel_state(16, 16);
    let pos = [1.0f32, 1.0, 0.0, 15.0, 1.0, 0.0, 8.0, 15.0, 0.0];
    let p = bytes(&pos);
    // Indices past the array read the default position (0, 0, 0, 1): documented, no panic.
    for idx in [&[0u32, 1, 7][..], &[0, 1, u32::MAX], &[1_000_000, 2, 0]] {
        let d = DrawCall::new(
            Primitive::Triangles,
            Indices::U32(idx),
            array(&p, ComponentType::Float, 3),
        );
        let mut t = target(16, 16);
        gles_cm_core::render(&s, &d, &mut t).unwrap();
        assert_clean(&t, [255; 4], [255; 4]);
        let mut r = target(16, 16);
        reference::render(&s, &d, &mut r);
        assert_eq!(covered(&t), covered(&r), "{idx:?}");
    }
}

#[test]
fn case_11_user_clip_plane_under_singular_and_odd_modelviews() {
    let gl = Gl::rgba8(32, 32);
    gl.pixel_ortho();
    let quad = [
        0.0, 0.0, 0.0, 32.0, 0.0, 0.0, 32.0, 32.0, 0.0, 0.0, 0.0, 0.0, 32.0, 32.0, 0.0, 0.0, 32.0,
        0.0,
    ];
    // SAFETY: a context is current; the plane arrays hold 4 floats.
    unsafe {
        // An odd modelview (non-uniform scale and translation): the plane x ≥ 4 in object
        // coordinates is x_eye ≥ 2·4 + 3 = 11 in eye coordinates.
        glTranslatef(3.0, 0.0, 0.0);
        glScalef(2.0, 0.5, 1.0);
        glClipPlanef(GL_CLIP_PLANE0, [1.0, 0.0, 0.0, -4.0].as_ptr());
        glLoadIdentity();
        glEnable(GL_CLIP_PLANE0);
        glColor4f(1.0, 1.0, 1.0, 1.0);
        gl_draw(GL_TRIANGLES, &quad);
        let px = gl.read();
        assert_eq!(gl_covered(&px), (32 - 11) * 32);
        // A singular modelview: no crash, no error, no garbage. Documented: the stored
        // plane is whatever the inverse transpose gives (non-finite here), and a plane
        // with non-finite coefficients clips everything.
        glClear(GL_COLOR_BUFFER_BIT);
        glScalef(0.0, 0.0, 0.0);
        glClipPlanef(GL_CLIP_PLANE0, [1.0, 0.0, 0.0, -4.0].as_ptr());
        assert_eq!(err(), GL_NO_ERROR);
        let mut eq = [0.0f32; 4];
        glGetClipPlanef(GL_CLIP_PLANE0, eq.as_mut_ptr());
        glLoadIdentity();
        gl_draw(GL_TRIANGLES, &quad);
        let px = gl.read();
        let n = gl_covered(&px);
        assert!(px.iter().all(|p| *p == [0, 0, 0, 0] || *p == [255; 4]));
        if eq.iter().all(|c| c.is_finite()) {
            assert!(n == 0 || n == 32 * 32, "{eq:?}: {n}");
        } else {
            assert_eq!(n, 0, "{eq:?}");
        }
        glDisable(GL_CLIP_PLANE0);
    }
}

// ---------------------------------------------------------------------------------------
// Texturing, quantized vertices, read-back, queries, animation and EGL (cases 16–30).

#[allow(non_snake_case, dead_code)]
extern "C" {
    fn glTexSubImage2D(
        t: u32,
        l: i32,
        x: i32,
        y: i32,
        w: i32,
        h: i32,
        f: u32,
        ty: u32,
        p: *const c_void,
    );
    fn glActiveTexture(t: u32);
    fn glClientActiveTexture(t: u32);
    fn glMultiTexCoord4f(t: u32, s: f32, tt: f32, r: f32, q: f32);
    fn glTexEnvf(t: u32, p: u32, v: f32);
    fn glScissor(x: i32, y: i32, w: i32, h: i32);
    fn glFogf(p: u32, v: f32);
    fn glGetBooleanv(p: u32, v: *mut u8);
    fn glCurrentPaletteMatrixOES(i: u32);
}

const RED: [u8; 4] = [255, 0, 0, 255];
const GREEN: [u8; 4] = [0, 255, 0, 255];
const BLUE: [u8; 4] = [0, 0, 255, 255];
const WHITE: [u8; 4] = [255; 4];

/// A bound RGBA8 texture `w` × `h` (level 0) with NEAREST filters and `wrap` on s and t.
fn gl_texture(w: i32, h: i32, texels: &[[u8; 4]], wrap: u32) -> u32 {
    let mut name = 0;
    // SAFETY: a context is current; `texels` holds w × h RGBA8 texels.
    unsafe {
        glGenTextures(1, &mut name);
        glBindTexture(GL_TEXTURE_2D, name);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap as i32);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap as i32);
        tex_level(0, w, h, texels);
        glEnable(GL_TEXTURE_2D);
    }
    name
}

fn tex_level(level: i32, w: i32, h: i32, texels: &[[u8; 4]]) {
    assert_eq!(texels.len(), (w * h) as usize);
    // SAFETY: a context is current; `texels` holds w × h RGBA8 texels.
    unsafe {
        glTexImage2D(
            GL_TEXTURE_2D,
            level,
            GL_RGBA as i32,
            w,
            h,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            texels.as_ptr().cast(),
        );
    }
}

/// A quad from (x0, y0) to (x1, y1) whose corners (counter-clockwise from the lower left)
/// carry the `n`-component texture coordinates `tc`.
fn gl_tex_quad(x0: f32, y0: f32, x1: f32, y1: f32, tc: &[f32], n: usize) {
    assert_eq!(tc.len(), 4 * n);
    let xyz = [
        x0, y0, 0.0, x1, y0, 0.0, x1, y1, 0.0, x0, y0, 0.0, x1, y1, 0.0, x0, y1, 0.0,
    ];
    let mut t = Vec::new();
    for k in [0, 1, 2, 0, 2, 3] {
        t.extend_from_slice(&tc[k * n..(k + 1) * n]);
    }
    // SAFETY: both arrays outlive the draw and hold 6 vertices.
    unsafe {
        glColor4f(1.0, 1.0, 1.0, 1.0);
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glTexCoordPointer(n as i32, GL_FLOAT, 0, t.as_ptr().cast());
        gl_draw(GL_TRIANGLES, &xyz);
        glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    }
}

/// Texture coordinates (s, t) that vary only in s, from `s0` on the left to `s1`.
fn s_ramp(s0: f32, s1: f32) -> [f32; 8] {
    [s0, 0.5, s1, 0.5, s1, 0.5, s0, 0.5]
}

fn assert_only(px: &[[u8; 4]], allowed: &[[u8; 4]]) {
    for (i, p) in px.iter().enumerate() {
        assert!(allowed.contains(p), "garbage pixel {p:?} at {i}");
    }
}

#[test]
fn case_16_texture_coordinate_ranges_and_projective_q() {
    let gl = Gl::rgba8(64, 4);
    gl.pixel_ortho();
    let tex = gl_texture(2, 1, &[RED, GREEN], GL_REPEAT);
    let row = |gl: &Gl| gl.read()[..64].to_vec();
    let draw = |tc: &[f32], n: usize| {
        // SAFETY: a context is current.
        unsafe { glClear(GL_COLOR_BUFFER_BIT) };
        gl_tex_quad(0.0, 0.0, 64.0, 4.0, tc, n);
        assert_eq!(err(), GL_NO_ERROR);
        let px = gl.read();
        assert_only(&px, &[RED, GREEN]);
        row(&gl)
    };
    // REPEAT: shifts by whole periods up to the required range 2¹⁰ give the same image.
    let base = draw(&s_ramp(0.0, 1.0), 2);
    assert_eq!(base[..32], [RED; 32]);
    assert_eq!(base[32..], [GREEN; 32]);
    for s0 in [1023.0, -1024.0, 512.0, -1.0] {
        assert_eq!(draw(&s_ramp(s0, s0 + 1.0), 2), base, "s from {s0}");
    }
    // Negative values: −0.7 … 3.0 is 3.7 repeats, each pixel its texel of fract(s).
    let px = draw(&s_ramp(-0.7, 3.0), 2);
    for (x, p) in px.iter().enumerate() {
        let s = -0.7 + 3.7 * (x as f64 + 0.5) / 64.0;
        let f = (s * 2.0).rem_euclid(2.0);
        if (f - f.round()).abs() < 0.02 {
            continue;
        }
        let want = if f < 1.0 { RED } else { GREEN };
        assert_eq!(*p, want, "x {x}, s {s}");
    }
    // Exactly 0 and 1: CLAMP_TO_EDGE gives the edge texels, REPEAT wraps 1 to texel 0.
    assert_eq!(draw(&s_ramp(1.0, 1.0), 2), [RED; 64]);
    // SAFETY: a context is current.
    unsafe { glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE as i32) };
    assert_eq!(draw(&s_ramp(0.0, 0.0), 2), [RED; 64]);
    assert_eq!(draw(&s_ramp(1.0, 1.0), 2), [GREEN; 64]);
    assert_eq!(draw(&s_ramp(-5.0, 6.0)[..], 2)[0], RED);
    // Projective q: (q·s, q·t, 0, q) is (s, t) for any uniform q, also negative.
    let strq = |s0: f32, s1: f32, q: [f32; 4]| {
        let s = [s0, s1, s1, s0];
        let mut v = Vec::new();
        for k in 0..4 {
            v.extend_from_slice(&[s[k] * q[k], 0.5 * q[k], 0.0, q[k]]);
        }
        v
    };
    for q in [2.0, -1.0, 1e-3, 1e3] {
        assert_eq!(draw(&strq(0.0, 1.0, [q; 4]), 4), base, "q {q}");
    }
    // Per-pixel q: s/q interpolated per fragment, not per vertex. Left q = 1, s/q = 0;
    // right q = 3, s/q = 1: s/q = 3u / (1 + 2u) crosses 0.5 at u = ¼ (per-vertex: ½).
    let px = draw(&strq(0.0, 1.0, [1.0, 3.0, 3.0, 1.0]), 4);
    assert_eq!(px[12], RED);
    assert_eq!(px[20], GREEN, "q interpolated per pixel");
    assert_eq!(px[28], GREEN);
    // q of differing signs and q → 0: undefined texels, but only texels.
    draw(&strq(0.0, 1.0, [1.0, -1.0, -1.0, 1.0]), 4);
    draw(&strq(0.0, 1.0, [1.0, 1e-30, 1e-30, 1.0]), 4);
    draw(&strq(0.0, 1.0, [0.0, 1.0, 1.0, 0.0]), 4);
    // SAFETY: a context is current.
    unsafe {
        glDisable(GL_TEXTURE_2D);
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    let _ = tex;
}

fn level_color(k: usize) -> [u8; 4] {
    [(k * 40) as u8, 255 - (k * 30) as u8, (k * 17) as u8, 255]
}

#[test]
fn case_17_texture_shapes_mip_chains_incomplete_and_generate_mipmap() {
    let gl = Gl::rgba8(64, 64);
    gl.pixel_ortho();
    let full = [0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0];
    let clear = || {
        // SAFETY: a context is current.
        unsafe { glClear(GL_COLOR_BUFFER_BIT) }
    };
    // 1×1: one color everywhere, whatever the coordinates.
    gl_texture(1, 1, &[BLUE], GL_REPEAT);
    clear();
    gl_tex_quad(
        0.0,
        0.0,
        64.0,
        64.0,
        &[-3.0, -3.0, 5.5, -3.0, 5.5, 7.0, -3.0, 7.0],
        2,
    );
    assert!(gl.read().iter().all(|p| *p == BLUE));
    // 1×N: horizontal stripes; N×1: vertical ones.
    let four = [RED, GREEN, BLUE, WHITE];
    gl_texture(1, 4, &four, GL_REPEAT);
    clear();
    gl_tex_quad(0.0, 0.0, 64.0, 64.0, &full, 2);
    let px = gl.read();
    for y in 0..64 {
        assert!(
            px[y * 64..][..64].iter().all(|p| *p == four[y / 16]),
            "row {y}"
        );
    }
    gl_texture(4, 1, &four, GL_REPEAT);
    clear();
    gl_tex_quad(0.0, 0.0, 64.0, 64.0, &full, 2);
    let px = gl.read();
    for x in 0..64 {
        assert!(
            (0..64).all(|y| px[y * 64 + x] == four[x / 16]),
            "column {x}"
        );
    }
    // The full chain of a 64×32 texture: 7 levels, each a solid color. A square quad of
    // 64 / 2ᵏ pixels has ρ = 2ᵏ and samples level k (NEAREST_MIPMAP_NEAREST).
    let chain = |levels: &[(usize, i32, i32)]| {
        gl_texture(64, 32, &vec![level_color(0); 64 * 32], GL_REPEAT);
        for &(k, w, h) in levels {
            tex_level(k as i32, w, h, &vec![level_color(k); (w * h) as usize]);
        }
        // SAFETY: a context is current.
        unsafe {
            glTexParameteri(
                GL_TEXTURE_2D,
                GL_TEXTURE_MIN_FILTER,
                GL_NEAREST_MIPMAP_NEAREST as i32,
            )
        };
    };
    let sizes: Vec<_> = (1..7)
        .map(|k| (k, (64 >> k).max(1), (32 >> k).max(1)))
        .collect();
    chain(&sizes);
    assert_eq!(err(), GL_NO_ERROR);
    for k in 0..7 {
        clear();
        let side = (64 >> k) as f32;
        gl_tex_quad(0.0, 0.0, side, side, &full, 2);
        assert_eq!(gl.read()[0], level_color(k), "level {k}");
    }
    // Incomplete: a wrong level size, or mixed formats. The unit is disabled (white).
    let mut wrong = sizes.clone();
    wrong[2] = (3, 8, 8);
    chain(&wrong);
    clear();
    gl_tex_quad(0.0, 0.0, 4.0, 4.0, &full, 2);
    assert_eq!(gl.read()[0], WHITE, "wrong level size");
    chain(&sizes);
    // SAFETY: a context is current; 4 RGB texels.
    unsafe {
        glTexImage2D(
            GL_TEXTURE_2D,
            4,
            GL_RGB as i32,
            4,
            2,
            0,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            [9u8; 24].as_ptr().cast(),
        );
    }
    clear();
    gl_tex_quad(0.0, 0.0, 4.0, 4.0, &full, 2);
    assert_eq!(gl.read()[0], WHITE, "mixed formats");
    // ... but a non-mipmapped filter needs only level 0.
    // SAFETY: a context is current.
    unsafe { glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32) };
    clear();
    gl_tex_quad(0.0, 0.0, 4.0, 4.0, &full, 2);
    assert_eq!(gl.read()[0], level_color(0));
    // GENERATE_MIPMAP: levels follow level 0, also through TexSubImage; turned off, they
    // keep what they had.
    gl_texture(64, 32, &vec![RED; 64 * 32], GL_REPEAT);
    let sub = |c: [u8; 4]| {
        // SAFETY: a context is current; 64 × 32 RGBA8 texels.
        unsafe {
            glTexSubImage2D(
                GL_TEXTURE_2D,
                0,
                0,
                0,
                64,
                32,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                vec![c; 64 * 32].as_ptr().cast(),
            )
        }
    };
    let tiny_and_big = || {
        clear();
        gl_tex_quad(0.0, 0.0, 1.0, 1.0, &full, 2);
        gl_tex_quad(
            32.0,
            32.0,
            64.0,
            64.0,
            &[0.0, 0.0, 0.5, 0.0, 0.5, 1.0, 0.0, 1.0],
            2,
        );
        let px = gl.read();
        (px[0], px[40 * 64 + 40])
    };
    // SAFETY: a context is current.
    unsafe {
        glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 1);
        glTexParameteri(
            GL_TEXTURE_2D,
            GL_TEXTURE_MIN_FILTER,
            GL_NEAREST_MIPMAP_NEAREST as i32,
        );
    }
    assert_eq!(
        tiny_and_big(),
        (WHITE, WHITE),
        "levels 1+ not generated yet: incomplete"
    );
    tex_level(0, 64, 32, &vec![RED; 64 * 32]);
    assert_eq!(tiny_and_big(), (RED, RED));
    sub(BLUE);
    assert_eq!(tiny_and_big(), (BLUE, BLUE), "TexSubImage regenerates");
    // SAFETY: a context is current.
    unsafe { glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 0) };
    sub(GREEN);
    assert_eq!(tiny_and_big(), (BLUE, GREEN), "generation off");
    assert_eq!(err(), GL_NO_ERROR);
}

#[test]
fn case_18_paletted_textures_nibbles_levels_and_all_formats() {
    let gl = Gl::rgba8(8, 8);
    gl.pixel_ortho();
    let full = [0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0];
    gl_texture(1, 1, &[WHITE], GL_REPEAT);
    let upload = |format: u32, level: i32, w: i32, h: i32, blob: &[u8]| {
        // SAFETY: a context is current; `blob` holds `len` bytes.
        unsafe {
            glCompressedTexImage2D(
                GL_TEXTURE_2D,
                level,
                format,
                w,
                h,
                0,
                blob.len() as i32,
                blob.as_ptr().cast(),
            );
            glClear(GL_COLOR_BUFFER_BIT);
        }
        let e = err();
        gl_tex_quad(0.0, 0.0, 8.0, 8.0, &full, 2);
        (e, gl.read())
    };
    // Entry 0 black-ish and entry 1 a known color, in each entry type's encoding
    // (16-bit entries in native byte order).
    let entries: [(u32, Vec<u8>, [u8; 4]); 5] = [
        (0, vec![255, 0, 0], RED),
        (1, vec![0, 255, 0, 255], GREEN),
        (2, 0x001Fu16.to_ne_bytes().to_vec(), BLUE),
        (3, 0xF00Fu16.to_ne_bytes().to_vec(), RED),
        (4, 0x07C1u16.to_ne_bytes().to_vec(), GREEN),
    ];
    for (bits, base) in [(4usize, GL_PALETTE4_RGB8_OES), (8, GL_PALETTE8_RGB8_OES)] {
        for (k, entry, want) in &entries {
            let n = 1usize << bits;
            let size = entry.len();
            let mut palette = vec![0u8; n * size];
            palette[size..2 * size].copy_from_slice(entry);
            // 2×1 texels: [1, 0]. 4-bit: first texel in the high nibble.
            let mut blob = palette.clone();
            blob.extend_from_slice(if bits == 4 { &[0x10][..] } else { &[1, 0] });
            let (e, px) = upload(base + k, 0, 2, 1, &blob);
            assert_eq!(e, GL_NO_ERROR, "format {:#x}", base + k);
            assert_eq!(px[0], *want, "format {:#x}: left texel", base + k);
            assert_ne!(px[7], *want, "format {:#x}: right texel", base + k);
            assert!(px[..4].iter().all(|p| p == want) && px[4..8].iter().all(|p| p == &px[7]));
        }
    }
    // A 1×1 level with a 4-bit index: one byte, the high nibble used.
    let mut blob = vec![0u8; 16 * 3];
    blob[3..6].copy_from_slice(&[0, 0, 255]);
    blob.push(0x10);
    assert_eq!(upload(GL_PALETTE4_RGB8_OES, 0, 1, 1, &blob).1[0], BLUE);
    // Negative levels: −n gives levels 0 … n in one blob (2×2, 1×1 here: 2 + 1 bytes);
    // positive levels and a wrong size are INVALID_VALUE.
    let mut blob = vec![0u8; 16 * 3];
    blob[3..6].copy_from_slice(&[0, 0, 255]);
    blob.extend_from_slice(&[0x11, 0x11, 0x10]);
    let (e, px) = upload(GL_PALETTE4_RGB8_OES, -1, 2, 2, &blob);
    assert_eq!(e, GL_NO_ERROR);
    assert!(px.iter().all(|p| *p == BLUE));
    assert_eq!(
        upload(GL_PALETTE4_RGB8_OES, 1, 2, 2, &blob).0,
        GL_INVALID_VALUE
    );
    assert_eq!(
        upload(GL_PALETTE4_RGB8_OES, -1, 2, 2, &blob[..blob.len() - 1]).0,
        GL_INVALID_VALUE
    );
    assert_eq!(
        upload(GL_PALETTE4_RGB8_OES, -5, 2, 2, &blob).0,
        GL_INVALID_VALUE
    );
}

#[test]
fn case_19_point_sprites_size_clamps_errors_flipped_t_and_coord_replace() {
    let gl = Gl::rgba8(32, 32);
    gl.pixel_ortho();
    let point = |size: f32| {
        // SAFETY: a context is current.
        unsafe {
            glClear(GL_COLOR_BUFFER_BIT);
            glPointSize(size);
        }
        gl_draw(GL_POINTS, &[16.0, 16.0, 0.0]);
        let px = gl.read();
        // Products of the texels on two units may be black.
        assert_only(&px, &[[0; 4], WHITE, RED, GREEN, BLUE, [0, 0, 0, 255]]);
        px
    };
    // SAFETY: a context is current; arrays hold 3 floats.
    unsafe {
        glColor4f(1.0, 1.0, 1.0, 1.0);
        assert_eq!(gl_covered(&point(4.0)), 16);
        // Derived sizes are clamped to [SIZE_MIN, SIZE_MAX].
        glPointParameterf(GL_POINT_SIZE_MAX, 3.0);
        assert_eq!(gl_covered(&point(10.0)), 9);
        glPointParameterf(GL_POINT_SIZE_MIN, 6.0);
        glPointParameterf(GL_POINT_SIZE_MAX, 64.0);
        assert_eq!(gl_covered(&point(1.0)), 36);
        // Attenuation with a zero denominator (all coefficients 0), and a negative one:
        // no crash, no garbage, at most SIZE_MAX wide.
        for att in [[0.0f32, 0.0, 0.0], [-1.0, 0.0, 0.0]] {
            glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att.as_ptr());
            assert_eq!(err(), GL_NO_ERROR);
            assert!(gl_covered(&point(4.0)) <= 64 * 64);
        }
        glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, [1.0f32, 0.0, 0.0].as_ptr());
        glPointParameterf(GL_POINT_SIZE_MIN, 0.0);
        glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 8.0);
        assert_eq!(gl_covered(&point(4.0)), 16, "fade affects alpha only");
        // Size 0 or negative: INVALID_VALUE, the size unchanged.
        glPointSize(0.0);
        assert_eq!(err(), GL_INVALID_VALUE);
        glPointSize(-2.0);
        assert_eq!(err(), GL_INVALID_VALUE);
        let mut size = 0.0f32;
        glGetFloatv(GL_POINT_SIZE, &mut size);
        assert_eq!(size, 4.0);
        // Sprites: s left to right, t from the top down (origin upper left).
        gl_texture(2, 2, &[RED, GREEN, BLUE, WHITE], GL_CLAMP_TO_EDGE);
        glEnable(GL_POINT_SPRITE_OES);
        glTexEnvi(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES, 1);
        let px = point(8.0);
        let at = |x: usize, y: usize| px[y * 32 + x];
        // Window rows 12..20; the top row (y = 19) is t ≈ 0: texture row 0.
        assert_eq!((at(13, 18), at(18, 18)), (RED, GREEN), "top = t 0");
        assert_eq!((at(13, 13), at(18, 13)), (BLUE, WHITE), "bottom = t 1");
        // COORD_REPLACE off: the current texture coordinate, constant over the sprite.
        glTexEnvi(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES, 0);
        glMultiTexCoord4f(GL_TEXTURE0, 0.75, 0.25, 0.0, 1.0);
        let px = point(8.0);
        assert!(px.iter().all(|p| *p == [0; 4] || *p == GREEN));
        // COORD_REPLACE on unit 0 only: unit 1 keeps its constant coordinate.
        glTexEnvi(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES, 1);
        glActiveTexture(GL_TEXTURE1);
        gl_texture(2, 1, &[RED, WHITE], GL_CLAMP_TO_EDGE);
        glMultiTexCoord4f(GL_TEXTURE1, 0.75, 0.5, 0.0, 1.0);
        let px = point(8.0);
        assert_eq!((px[18 * 32 + 13], px[13 * 32 + 18]), (RED, WHITE));
        glMultiTexCoord4f(GL_TEXTURE1, 0.25, 0.5, 0.0, 1.0);
        let px = point(8.0);
        assert_eq!((px[18 * 32 + 13], px[13 * 32 + 18]), (RED, RED));
        glDisable(GL_TEXTURE_2D);
        glActiveTexture(GL_TEXTURE0);
        glDisable(GL_TEXTURE_2D);
        glDisable(GL_POINT_SPRITE_OES);
    }
}

#[test]
fn case_21_quantized_byte_and_short_meshes_meet_without_cracks() {
    // A byte quad 0..8 scaled by 2 and a short quad 16..32 at scale 1 share the edge
    // x = 16; additive blending shows any pixel covered twice or not at all.
    let mut s = pixel_state(32, 16);
    s.blend = Some(Blend::func(BlendFactor::One, BlendFactor::One));
    let mut t = target(32, 16);
    let bq: [i8; 18] = [0, 0, 0, 8, 0, 0, 8, 8, 0, 0, 0, 0, 8, 8, 0, 0, 8, 0];
    let sq: [i16; 18] = [
        16, 0, 0, 32, 0, 0, 32, 16, 0, 16, 0, 0, 32, 16, 0, 16, 16, 0,
    ];
    let col = bytes(&rgba([0.5, 0.5, 0.5, 0.5], 6));
    for (data, ty, scale) in [
        (bytes(&bq), ComponentType::Byte, 2.0),
        (bytes(&sq), ComponentType::Short, 1.0),
    ] {
        s.modelview = Mat4::from_scale(Vec3::new(scale, scale, 1.0));
        let mut d = DrawCall::new(
            Primitive::Triangles,
            Indices::Range { first: 0, count: 6 },
            array(&data, ty, 3),
        );
        d.color = AttribSource::Array(array(&col, ComponentType::Float, 4));
        gles_cm_core::render(&s, &d, &mut t).unwrap();
    }
    for y in 0..16 {
        for x in 0..32 {
            assert_eq!(t.pixel(x, y)[0], 128, "({x}, {y}) covered once");
        }
    }
    // M3G: morph results beyond the 8-bit range are undefined, but finite and no error.
    use m3g::{MorphingMesh, TriangleStripArray, VertexArray, VertexBuffer};
    let vb = |v: i8| {
        let a = VertexArray::new(3, 3, 1).unwrap();
        a.set_bytes(0, &[v, 0, 0, 0, v, 0, 0, 0, v]).unwrap();
        let b = VertexBuffer::new();
        b.set_positions(Some(&a), 1.0, None).unwrap();
        b
    };
    let ib = TriangleStripArray::new_implicit(0, &[3])
        .unwrap()
        .as_index_buffer();
    let m = MorphingMesh::new(&vb(100), &[vb(127), vb(-128)], &ib, None).unwrap();
    m.set_weights(&[3.0, -2.0]).unwrap();
    let out = m.morphed_vertex_buffer().unwrap();
    let (_, sb) = out.get_positions();
    assert!(sb.iter().all(|x| x.is_finite()), "{sb:?}");
}

#[test]
fn case_24_read_pixels_alignment_outside_regions_and_565_expansion() {
    let gl = Gl::rgba8(8, 8);
    gl.pixel_ortho();
    // SAFETY: a context is current; every buffer is large enough for the read.
    unsafe {
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, 0, 3, 8);
        glClearColor(1.0, 0.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
        // Odd widths (3 RGBA pixels = 12 bytes per row) at every alignment: rows padded
        // to the alignment, padding left untouched.
        for align in [1usize, 2, 4, 8] {
            glPixelStorei(GL_PACK_ALIGNMENT, align as i32);
            let stride = 12usize.div_ceil(align) * align;
            let mut buf = vec![0xABu8; stride * 3];
            glReadPixels(
                1,
                1,
                3,
                3,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                buf.as_mut_ptr().cast(),
            );
            assert_eq!(err(), GL_NO_ERROR);
            for row in 0..3 {
                let r = &buf[row * stride..];
                assert_eq!(
                    r[..12],
                    [255, 0, 0, 255, 255, 0, 0, 255, 0, 0, 0, 0],
                    "{align}"
                );
                if row < 2 {
                    assert!(r[12..stride].iter().all(|&b| b == 0xAB), "padding {align}");
                }
            }
        }
        // A region partly outside: the pixels outside are left as they were (documented).
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        let mut buf = vec![[7u8; 4]; 16];
        glReadPixels(
            -2,
            -2,
            4,
            4,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            buf.as_mut_ptr().cast(),
        );
        assert_eq!(err(), GL_NO_ERROR);
        for (i, p) in buf.iter().enumerate() {
            let inside = i / 4 >= 2 && i % 4 >= 2;
            assert_eq!(*p, if inside { RED } else { [7; 4] }, "{i}");
        }
        // The implementation read format works too.
        let (mut f, mut t) = (0, 0);
        glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_FORMAT_OES, &mut f);
        glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_TYPE_OES, &mut t);
        let mut any = vec![0u8; 8 * 8 * 4];
        glReadPixels(0, 0, 8, 8, f as u32, t as u32, any.as_mut_ptr().cast());
        assert_eq!(err(), GL_NO_ERROR);
    }
}

#[test]
fn case_24_read_pixels_565_to_8888_expansion_is_exact() {
    // RGB565 → RGBA8888: c / (2ⁿ − 1) rounded to 8 bits, exactly, for every level.
    let gl = Gl::new(32, 2, 5, 16, 0);
    gl.pixel_ortho();
    // SAFETY: a context is current.
    unsafe { glEnable(GL_SCISSOR_TEST) };
    for x in 0..32 {
        let v = x as f32 / 31.0;
        // SAFETY: a context is current.
        unsafe {
            glScissor(x, 0, 1, 2);
            glClearColor(v, x as f32 * 2.0 / 63.0, v, 1.0);
            glClear(GL_COLOR_BUFFER_BIT);
        }
    }
    // SAFETY: a context is current.
    unsafe { glDisable(GL_SCISSOR_TEST) };
    let px = gl.read();
    for (x, p) in px.iter().take(32).enumerate() {
        let r = ((x as f64) * 255.0 / 31.0).round() as u8;
        let g = ((2 * x) as f64 * 255.0 / 63.0).round() as u8;
        assert_eq!(*p, [r, g, r, 255], "level {x}");
    }
}

#[test]
fn case_25_get_conversions_rounding_normalization_saturation_and_float_bits() {
    let _gl = Gl::rgba8(4, 4);
    // SAFETY: a context is current; outputs hold 16 values.
    unsafe {
        let mut i = [0i32; 16];
        let mut x = [0i32; 16];
        glPointSize(2.4);
        glGetIntegerv(GL_POINT_SIZE, i.as_mut_ptr());
        assert_eq!(i[0], 2);
        glPointSize(2.6);
        glGetIntegerv(GL_POINT_SIZE, i.as_mut_ptr());
        assert_eq!(i[0], 3, "float → int rounds to nearest");
        // Colors and normals map [−1, 1] onto the whole integer range.
        glClearColor(1.0, 0.0, 0.5, 1.0);
        glGetIntegerv(GL_COLOR_CLEAR_VALUE, i.as_mut_ptr());
        // (c·(2³² − 1) − 1) / 2: 0.5 gives 2³⁰ − 1.
        assert_eq!(i[..4], [i32::MAX, 0, (1 << 30) - 1, i32::MAX]);
        glNormal3f(1.0, -1.0, 0.0);
        glGetIntegerv(GL_CURRENT_NORMAL, i.as_mut_ptr());
        assert_eq!(i[..3], [i32::MAX, i32::MIN, 0]);
        // Saturation on overflow, integer and fixed.
        glFogf(GL_FOG_END, 1e20);
        glGetIntegerv(GL_FOG_END, i.as_mut_ptr());
        assert_eq!(i[0], i32::MAX);
        glGetFixedv(GL_FOG_END, x.as_mut_ptr());
        assert_eq!(x[0], i32::MAX);
        glFogf(GL_FOG_END, -1e20);
        glGetFixedv(GL_FOG_END, x.as_mut_ptr());
        assert_eq!(x[0], i32::MIN);
        let mut b = [9u8; 4];
        glGetBooleanv(GL_FOG_END, b.as_mut_ptr());
        assert_eq!(b[0], 1);
        // The matrix as FLOAT_AS_INT_BITS: the float's bits, unconverted.
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glScalef(0.1, -3.5, 1e30);
        use GLES_CM::gles::tokens_ext::GL_MODELVIEW_MATRIX_FLOAT_AS_INT_BITS_OES;
        glGetIntegerv(GL_MODELVIEW_MATRIX_FLOAT_AS_INT_BITS_OES, i.as_mut_ptr());
        assert_eq!(i[0], 0.1f32.to_bits() as i32);
        assert_eq!(i[5], (-3.5f32).to_bits() as i32);
        assert_eq!(i[10], 1e30f32.to_bits() as i32);
        assert_eq!(i[15], 1.0f32.to_bits() as i32);
        assert_eq!(err(), GL_NO_ERROR);
    }
}

#[test]
fn case_26_skinning_precision_palette_indices_and_weights() {
    use m3g::*;
    // A chain of 32 bones, each 1 unit along its parent's x and rotated 10° about z: the
    // tip vertex against an f64 evaluation of the compounded matrices.
    const N: usize = 32;
    let va = VertexArray::new(3, 3, 2).unwrap();
    va.set_shorts(0, &[0, 0, 0, N as i16, 0, 0, N as i16 - 1, 1, 0])
        .unwrap();
    let vb = VertexBuffer::new();
    vb.set_positions(Some(&va), 1.0, None).unwrap();
    let ib = TriangleStripArray::new_implicit(0, &[3])
        .unwrap()
        .as_index_buffer();
    let skeleton = Group::new();
    let mut bones = vec![Group::new()];
    skeleton.add_child(&bones[0]).unwrap();
    for _ in 1..N {
        let b = Group::new();
        b.set_translation(1.0, 0.0, 0.0);
        bones.last().unwrap().add_child(&b).unwrap();
        bones.push(b);
    }
    let m = SkinnedMesh::new(&vb, &ib, None, &skeleton).unwrap();
    m.add_transform(&bones[N - 1].as_node(), 1, 1, 2).unwrap();
    m.add_transform(&bones[0].as_node(), 1, 0, 1).unwrap();
    for b in &bones {
        b.set_orientation(10.0, 0.0, 0.0, 1.0).unwrap();
    }
    let (p, _) = m.skinned_vertices().unwrap();
    let a = 10f64.to_radians();
    let tip = |local: [f64; 2]| {
        let mut v = local;
        for i in (0..N).rev() {
            v = [
                v[0] * a.cos() - v[1] * a.sin(),
                v[0] * a.sin() + v[1] * a.cos(),
            ];
            if i > 0 {
                v[0] += 1.0;
            }
        }
        v
    };
    for (k, local) in [(1, [1.0, 0.0]), (2, [0.0, 1.0])] {
        let want = tip(local);
        assert!(
            (p[k][0] as f64 - want[0]).abs() < 1e-3 && (p[k][1] as f64 - want[1]).abs() < 1e-3,
            "vertex {k}: {:?} vs {want:?}",
            p[k]
        );
    }
    // M3G weights that do not sum to 1 are normalized: 1 : 3 is ¼ : ¾.
    let (vb2, ib2) = (vb.clone(), ib.clone());
    let skel = Group::new();
    let (b0, b1) = (Group::new(), Group::new());
    skel.add_child(&b0).unwrap();
    skel.add_child(&b1).unwrap();
    let m = SkinnedMesh::new(&vb2, &ib2, None, &skel).unwrap();
    m.add_transform(&b0.as_node(), 1, 0, 3).unwrap();
    m.add_transform(&b1.as_node(), 3, 0, 3).unwrap();
    b1.set_translation(0.0, 4.0, 0.0);
    let (p, _) = m.skinned_vertices().unwrap();
    assert!((p[0][1] - 3.0).abs() < 1e-4, "{:?}", p[0]);
    // GL matrix palette: an index at MAX_PALETTE_MATRICES is INVALID_VALUE; in an index
    // array it contributes nothing (documented in gles_cm_core::vertex); weights are used as given.
    let _gl = Gl::rgba8(4, 4);
    let mut max = 0;
    // SAFETY: a context is current.
    unsafe {
        use GLES_CM::gles::tokens_ext::GL_MAX_PALETTE_MATRICES_OES;
        glGetIntegerv(GL_MAX_PALETTE_MATRICES_OES, &mut max);
        assert!(max >= 9);
        glCurrentPaletteMatrixOES(max as u32);
        assert_eq!(err(), GL_INVALID_VALUE);
        glCurrentPaletteMatrixOES(max as u32 - 1);
        assert_eq!(err(), GL_NO_ERROR);
    }
    let mut s = RenderState::new(8, 8);
    s.matrix_palette = Some(vec![Mat4::from_translation(Vec3::X); max as usize]);
    let pos = bytes(&[0.0f32; 3]);
    let idx = [0u8, max as u8, 0, 255];
    let w = bytes(&[0.5f32, 0.25, 0.3, 0.3]);
    let mut d = DrawCall::new(
        Primitive::Points,
        Indices::Range { first: 0, count: 2 },
        array(&pos, ComponentType::Float, 3),
    );
    d.position.stride = 0;
    d.matrix_index = Some(array(&idx, ComponentType::UnsignedByte, 2));
    d.weight = Some(array(&w, ComponentType::Float, 2));
    // The projection is the identity: the clip positions are the eye positions.
    let v = gles_cm_core::vertex::run(&s, &d).unwrap();
    assert_eq!(v.get(0).pos(), Vec4::new(0.5, 0.0, 0.0, 0.5));
    assert_eq!(v.get(1).pos(), Vec4::new(0.3, 0.0, 0.0, 0.3));
}

#[test]
fn case_27_quaternion_slerp_small_angles_and_the_4d_path() {
    use m3g::{Interpolation, KeyframeSequence as KS};
    let q = |deg: f64| {
        let h = (deg * 0.5).to_radians();
        [0.0, 0.0, h.sin() as f32, h.cos() as f32]
    };
    let seq = |a: [f32; 4], b: [f32; 4]| {
        let s = KS::new(2, 4, Interpolation::Slerp).unwrap();
        s.set_keyframe(0, 0, &a).unwrap();
        s.set_keyframe(1, 100, &b).unwrap();
        s.set_duration(100).unwrap();
        s
    };
    // θ → 0: sin θ ≈ 0 in the denominator; the result stays finite and unit.
    for tiny in [1e-3, 1e-6, 0.0] {
        let s = seq(q(30.0), q(30.0 + tiny));
        for t in [0.0, 25.0, 50.0, 99.0] {
            let v = s.sample(t).unwrap();
            let n: f32 = v.iter().map(|c| c * c).sum();
            assert!(
                v.iter().all(|c| c.is_finite()) && (n - 1.0).abs() < 1e-5,
                "{v:?}"
            );
            assert!((v[2] - q(30.0)[2]).abs() < 1e-4, "{v:?}");
        }
    }
    // q vs −q: the 4D path, no sign flip. Identity → 200° about z (4D angle 100°): the
    // midpoint is 100°, not −80°.
    let v = seq(q(0.0), q(200.0)).sample(50.0).unwrap();
    let want = q(100.0);
    for c in 0..4 {
        assert!((v[c] - want[c]).abs() < 1e-5, "{v:?} vs {want:?}");
    }
    // Adjacent keys under 180° (4D angle < 90°): the short way.
    let v = seq(q(0.0), q(170.0)).sample(50.0).unwrap();
    assert!((v[2] - q(85.0)[2]).abs() < 1e-5, "{v:?}");
}

#[test]
fn case_28_m3g_non_invertible_camera_and_node_transforms() {
    use m3g::*;
    let ae = |r: Result<()>| matches!(r, Err(Error::Arithmetic(_)));
    // A singular camera transform: setCamera and render(World) throw ArithmeticException.
    let img = Image2D::new(ImageFormat::Rgb, 4, 4).unwrap();
    let mut g = Graphics3D::new();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    let mut singular = Transform::new();
    singular.post_scale(1.0, 0.0, 1.0);
    assert!(ae(g.set_camera(Some(&Camera::new()), Some(&singular))));
    let w = World::new();
    let c = Camera::new();
    let holder = Group::new();
    holder.add_child(&c).unwrap();
    w.add_child(&holder).unwrap();
    w.set_active_camera(&c);
    holder.set_scale(1.0, 1.0, 0.0);
    assert!(ae(g.render_world(&w)), "singular path to the camera");
    holder.set_scale(1.0, 1.0, 1.0);
    assert!(g.render_world(&w).is_ok());
    g.release_target();
    // getTransformTo across a singular path: from a node below a zero scale to one
    // outside it needs the inverse — ArithmeticException; the other way round is fine.
    let a = Group::new();
    let b = Group::new();
    holder.add_child(&a).unwrap();
    w.add_child(&b).unwrap();
    holder.set_scale(0.0, 1.0, 1.0);
    assert!(matches!(b.get_transform_to(&a), Err(Error::Arithmetic(_))));
    let t = a.get_transform_to(&b).unwrap().unwrap();
    assert!(t.get().iter().all(|x| x.is_finite()));
}

/// Case 30, EGL: swap then read, the default 0 × 0 pbuffer, LARGEST_PBUFFER, binding a
/// pbuffer as a texture while rendering to it, deleting a shared texture another context is
/// drawing with, destroying a current surface and context (freed when released), and one
/// context made current from two threads. Documented behavior where EGL leaves room: swaps
/// preserve the buffer (EGL_BUFFER_PRESERVED), and binding the current draw surface first
/// finishes its rendering, so the texture holds what was drawn so far.
#[test]
fn case_30_egl_surfaces_contexts_and_threads() {
    use GLES_CM::gles::ffi as gl;
    let g = Gl::rgba8(8, 8);
    let (dpy, cfg) = (g.dpy, config(g.dpy, 8, 24, 8));
    let query = |s: EGLSurface, attr: EGLint| -> EGLint {
        let mut v = -1;
        // SAFETY: `v` is one writable EGLint.
        unsafe { eglQuerySurface(dpy, s, attr, &mut v) };
        v
    };

    // Swap, then read: the pbuffer keeps its contents.
    g.pixel_ortho();
    // SAFETY: a context is current.
    unsafe {
        glClearColor(0.0, 1.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    assert_eq!(eglSwapBuffers(dpy, g.surface), 1);
    assert!(g.read().iter().all(|&p| p == GREEN));

    // The default pbuffer is 0 × 0: current, drawn to and read from without harm.
    // SAFETY: the attribute list ends in EGL_NONE.
    let empty = unsafe { eglCreatePbufferSurface(dpy, cfg, [EGL_NONE].as_ptr()) };
    assert!(!empty.is_null());
    assert_eq!((query(empty, EGL_WIDTH), query(empty, EGL_HEIGHT)), (0, 0));
    assert_eq!(eglMakeCurrent(dpy, empty, empty, g.context), 1);
    let mut px = [7u8; 4];
    // SAFETY: a context is current; `px` has room for the (empty) read.
    unsafe {
        glClear(GL_COLOR_BUFFER_BIT);
        gl_draw(GL_TRIANGLES, &[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]);
        glReadPixels(
            0,
            0,
            1,
            1,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            px.as_mut_ptr().cast(),
        );
    }
    assert_eq!(err(), GL_NO_ERROR);

    // LARGEST_PBUFFER: an oversized request is clamped to the largest size instead of failing.
    let big = [
        EGL_WIDTH,
        1 << 20,
        EGL_HEIGHT,
        16,
        EGL_LARGEST_PBUFFER,
        EGL_TRUE as EGLint,
        EGL_NONE,
    ];
    // SAFETY: the attribute list ends in EGL_NONE.
    let largest = unsafe { eglCreatePbufferSurface(dpy, cfg, big.as_ptr()) };
    assert!(!largest.is_null());
    let w = query(largest, EGL_WIDTH);
    assert!(
        w > 0 && w < 1 << 20 && query(largest, EGL_HEIGHT) == 16,
        "{w}"
    );
    assert_eq!(eglDestroySurface(dpy, largest), 1);

    // Binding the current draw surface as a texture: the rendering so far is finished first.
    let tex_attrs = [
        EGL_WIDTH,
        4,
        EGL_HEIGHT,
        4,
        EGL_TEXTURE_FORMAT,
        EGL_TEXTURE_RGBA,
        EGL_TEXTURE_TARGET,
        EGL_TEXTURE_2D,
        EGL_NONE,
    ];
    // SAFETY: the attribute list ends in EGL_NONE.
    let tex_surface = unsafe { eglCreatePbufferSurface(dpy, cfg, tex_attrs.as_ptr()) };
    assert!(!tex_surface.is_null());
    assert_eq!(eglMakeCurrent(dpy, tex_surface, tex_surface, g.context), 1);
    let mut tex = 0u32;
    // SAFETY: a context is current; `tex` receives one name.
    unsafe {
        glClearColor(1.0, 0.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glGenTextures(1, &mut tex);
        glBindTexture(GL_TEXTURE_2D, tex);
    }
    assert_eq!(eglBindTexImage(dpy, tex_surface, EGL_BACK_BUFFER), 1);
    assert_eq!(eglReleaseTexImage(dpy, tex_surface, EGL_BACK_BUFFER), 1);

    // A second context sharing objects deletes the texture the first one is drawing with;
    // the first one's pending and later draws neither crash nor read freed memory.
    assert_eq!(eglMakeCurrent(dpy, g.surface, g.surface, g.context), 1);
    // SAFETY: a context is current; the texel array holds 2 × 2 RGBA bytes.
    unsafe {
        glBindTexture(GL_TEXTURE_2D, tex);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
        let texels = [BLUE; 4];
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            2,
            2,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            texels.as_ptr().cast(),
        );
        glEnable(GL_TEXTURE_2D);
        gl::glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    }
    g.pixel_ortho();
    let quad = [0.0, 0.0, 0.0, 8.0, 0.0, 0.0, 0.0, 8.0, 0.0, 8.0, 8.0, 0.0];
    // Lives until the last draw that reads it, at the end of this test.
    let uv = [0.0f32, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 1.0];
    // SAFETY: a context is current; `uv` outlives every draw reading it.
    unsafe {
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glTexCoordPointer(2, GL_FLOAT, 0, uv.as_ptr().cast());
        gl_draw(GL_TRIANGLE_STRIP, &quad);
    }
    // SAFETY: the share context is valid.
    let other = unsafe { eglCreateContext(dpy, cfg, g.context, null()) };
    assert!(!other.is_null());
    // Handles cross threads as integers (the raw pointers are not Send).
    let (d2, o2) = (dpy as usize, other as usize);
    let t2 = std::thread::spawn(move || {
        let (dpy, other) = (d2 as EGLDisplay, o2 as EGLContext);
        // SAFETY: 0 × 0 pbuffer attribute list ends in EGL_NONE; `tex` names one texture.
        unsafe {
            let s = eglCreatePbufferSurface(dpy, config(dpy, 8, 24, 8), [EGL_NONE].as_ptr());
            assert_eq!(eglMakeCurrent(dpy, s, s, other), 1);
            gl::glDeleteTextures(1, &tex);
            glFinish();
            eglMakeCurrent(dpy, null_mut(), null_mut(), null_mut());
            eglDestroySurface(dpy, s);
        }
    });
    t2.join().unwrap();
    gl_draw(GL_TRIANGLE_STRIP, &quad);
    let px = g.read();
    assert!(
        px.iter().all(|&p| p == BLUE || p == WHITE),
        "{:?}",
        &px[..4]
    );

    // One context current on two threads: the second gets EGL_BAD_ACCESS.
    let (d, c) = (dpy as usize, g.context as usize);
    let t3 = std::thread::spawn(move || {
        let (dpy, ctx) = (d as EGLDisplay, c as EGLContext);
        // SAFETY: the attribute list ends in EGL_NONE.
        let s = unsafe { eglCreatePbufferSurface(dpy, config(dpy, 8, 24, 8), [EGL_NONE].as_ptr()) };
        let made = eglMakeCurrent(dpy, s, s, ctx);
        let error = eglGetError();
        eglDestroySurface(dpy, s);
        (made, error)
    });
    assert_eq!(t3.join().unwrap(), (0, EGL_BAD_ACCESS));

    // Destroying a current surface and context defers the free until they are released.
    // SAFETY: the share context is valid.
    let spare_ctx = unsafe { eglCreateContext(dpy, cfg, null_mut(), null()) };
    assert_eq!(eglMakeCurrent(dpy, empty, empty, spare_ctx), 1);
    assert_eq!(eglDestroySurface(dpy, empty), 1);
    assert_eq!(eglDestroyContext(dpy, spare_ctx), 1);
    // SAFETY: a context is still current.
    unsafe { glClear(GL_COLOR_BUFFER_BIT) };
    assert_eq!(err(), GL_NO_ERROR);
    assert_eq!(eglMakeCurrent(dpy, g.surface, g.surface, g.context), 1);
    assert_eq!(
        query(empty, EGL_WIDTH),
        -1,
        "the destroyed surface is gone after release"
    );
    assert_eq!(eglGetError(), EGL_BAD_SURFACE);
    assert_eq!(eglDestroySurface(dpy, tex_surface), 1);
    assert_eq!(eglDestroyContext(dpy, other), 1);
}
