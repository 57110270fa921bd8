//! The one EGL display and its object tables, and the EGL operations on them.
//!
//! Every native display value names the same display (handle [`DISPLAY_HANDLE`]): there is no
//! window system to connect to. Configs are named by their EGL_CONFIG_ID; surfaces and
//! contexts by ids from one counter that never repeats, so a handle of a destroyed object
//! stays invalid. A handle is only ever looked up in these tables, never dereferenced.
//!
//! Objects live in `Arc`s: the tables hold the handles' references, and a thread's current
//! binding holds its own, so a context or surface that is destroyed (or whose display is
//! terminated) while current stays alive until it is released, while its handle is already
//! invalid.
#![forbid(unsafe_code)]

use std::collections::{BTreeMap, BTreeSet};
use std::ffi::CStr;
use std::sync::{Arc, Mutex, MutexGuard, Weak};

use crate::gles::current as gl_current;
use crate::gles::texture::ImageSourceError;

use super::capture;
use super::config::{self, Config, Criteria, MAX_SWAP_INTERVAL, MIN_SWAP_INTERVAL};
use super::context::{self, Context};
use super::surface::{self, Kind, MemoryLayout, NativeMemory, Surface};
use super::thread::{self, Current};
use super::tokens::*;
use super::types::{EGLenum, EGLint};

/// The handle of the display.
pub const DISPLAY_HANDLE: usize = 1;

pub const VENDOR: &CStr = c"gles-cm";
pub const VERSION: &CStr = c"1.5 gles-cm 0.1.0";
pub const CLIENT_APIS: &CStr = c"OpenGL_ES";
/// Only what is implemented: eglGetProcAddress answers for every function.
pub const EXTENSIONS: &CStr = c"EGL_KHR_get_all_proc_addresses EGL_KHR_surfaceless_context EGL_KHR_create_context EGL_KHR_fence_sync EGL_KHR_wait_sync EGL_KHR_image_base EGL_KHR_gl_texture_2D_image";

/// The client extensions (EGL_EXT_client_extensions): what eglQueryString answers for
/// EGL_NO_DISPLAY, before any display exists.
pub const CLIENT_EXTENSIONS: &CStr =
    c"EGL_EXT_client_extensions EGL_EXT_platform_base EGL_MESA_platform_surfaceless";

/// EGL_MESA_platform_surfaceless's platform (`EGL_PLATFORM_SURFACELESS_MESA`).
pub const PLATFORM_SURFACELESS_MESA: EGLenum = 0x31DD;

/// Result of an EGL operation: the error code on failure.
pub type EglResult<T> = Result<T, EGLint>;

struct Egl {
    initialized: bool,
    next_id: usize,
    surfaces: BTreeMap<usize, Arc<Surface>>,
    contexts: BTreeMap<usize, Arc<Context>>,
    /// The thread each current context or surface (by id) is current on, handles alive or not.
    current_on: BTreeMap<usize, u64>,
    /// The draw surface kind of each current context (for EGL_RENDER_BUFFER).
    draw_kind: BTreeMap<usize, Kind>,
    /// Addresses of native pixmaps and windows that have a surface.
    natives: BTreeSet<usize>,
    /// Fence sync objects (EGL 1.5, EGL_KHR_fence_sync).
    syncs: BTreeMap<usize, Fence>,
}

static EGL: Mutex<Egl> = Mutex::new(Egl {
    initialized: false,
    next_id: 0x1000,
    surfaces: BTreeMap::new(),
    contexts: BTreeMap::new(),
    current_on: BTreeMap::new(),
    draw_kind: BTreeMap::new(),
    natives: BTreeSet::new(),
    syncs: BTreeMap::new(),
});

/// Locks the display; a lock poisoned by a caught panic is still usable.
fn egl() -> MutexGuard<'static, Egl> {
    EGL.lock().unwrap_or_else(|e| e.into_inner())
}

impl Egl {
    fn check(&self, dpy: usize) -> EglResult<()> {
        if dpy != DISPLAY_HANDLE {
            Err(EGL_BAD_DISPLAY)
        } else if !self.initialized {
            Err(EGL_NOT_INITIALIZED)
        } else {
            Ok(())
        }
    }

    fn config(&self, handle: usize) -> EglResult<&'static Config> {
        EGLint::try_from(handle)
            .ok()
            .and_then(config::by_id)
            .ok_or(EGL_BAD_CONFIG)
    }

    fn surface(&self, handle: usize) -> EglResult<Arc<Surface>> {
        self.surfaces.get(&handle).cloned().ok_or(EGL_BAD_SURFACE)
    }

    fn context(&self, handle: usize) -> EglResult<Arc<Context>> {
        self.contexts.get(&handle).cloned().ok_or(EGL_BAD_CONTEXT)
    }

    fn new_id(&mut self) -> usize {
        self.next_id += 1;
        self.next_id
    }

    fn unbind(&mut self, c: &Current) {
        for id in c.ids() {
            self.current_on.remove(&id);
        }
        self.draw_kind.remove(&c.ctx.id);
    }
}

/// Called when a thread exits with a current binding.
pub(crate) fn forget_thread_binding(c: &Current) {
    egl().unbind(c);
}

/// eglGetDisplay: every native display value maps to the one display.
pub fn get_display(_native: usize) -> usize {
    DISPLAY_HANDLE
}

/// eglGetPlatformDisplayEXT. The surfaceless platform's display is the one display: it has
/// no window system, and memory windows and pixmaps are client memory, so they stay usable.
pub fn get_platform_display<A>(
    platform: EGLenum,
    native: usize,
    attribs: &[(A, A)],
) -> EglResult<usize> {
    if platform != PLATFORM_SURFACELESS_MESA {
        return Err(EGL_BAD_PARAMETER);
    }
    // EGL_MESA_platform_surfaceless: the native display must be EGL_DEFAULT_DISPLAY.
    if native != 0 {
        return Err(EGL_BAD_PARAMETER);
    }
    // The platform defines no display attributes.
    if !attribs.is_empty() {
        return Err(EGL_BAD_ATTRIBUTE);
    }
    Ok(DISPLAY_HANDLE)
}

/// eglInitialize: (major, minor).
pub fn initialize(dpy: usize) -> EglResult<(EGLint, EGLint)> {
    let mut g = egl();
    if dpy != DISPLAY_HANDLE {
        return Err(EGL_BAD_DISPLAY);
    }
    g.initialized = true;
    Ok((1, 5))
}

/// eglTerminate: every handle becomes invalid; objects current to some thread live on until
/// released.
pub fn terminate(dpy: usize) -> EglResult<()> {
    let (surfaces, contexts);
    {
        let mut g = egl();
        if dpy != DISPLAY_HANDLE {
            return Err(EGL_BAD_DISPLAY);
        }
        g.initialized = false;
        surfaces = std::mem::take(&mut g.surfaces);
        contexts = std::mem::take(&mut g.contexts);
        g.natives.clear();
        g.syncs.clear();
        crate::gles::egl_image::clear();
    }
    // Dropped outside the lock.
    drop(surfaces);
    drop(contexts);
    Ok(())
}

pub fn query_string(dpy: usize, name: EGLint) -> EglResult<&'static CStr> {
    if dpy == 0 && name == EGL_EXTENSIONS {
        return Ok(CLIENT_EXTENSIONS);
    }
    egl().check(dpy)?;
    match name {
        EGL_VENDOR => Ok(VENDOR),
        EGL_VERSION => Ok(VERSION),
        EGL_EXTENSIONS => Ok(EXTENSIONS),
        EGL_CLIENT_APIS => Ok(CLIENT_APIS),
        _ => Err(EGL_BAD_PARAMETER),
    }
}

/// eglGetConfigs: every config handle.
pub fn get_configs(dpy: usize) -> EglResult<Vec<usize>> {
    egl().check(dpy)?;
    Ok(config::all().iter().map(|c| c.id as usize).collect())
}

/// eglChooseConfig. `pixmap` reads the layout of the EGL_MATCH_NATIVE_PIXMAP value (`None`
/// when it is no valid pixmap).
pub fn choose_config(
    dpy: usize,
    pairs: &[(EGLint, EGLint)],
    pixmap: impl Fn(EGLint) -> Option<MemoryLayout>,
) -> EglResult<Vec<usize>> {
    egl().check(dpy)?;
    let criteria = Criteria::parse(pairs)?;
    let layout = match criteria.match_native_pixmap {
        Some(p) => Some(pixmap(p).ok_or(EGL_BAD_NATIVE_PIXMAP)?),
        None => None,
    };
    let chosen = criteria
        .choose(|c| layout.is_some_and(|l| config::memory_format_matches(l.format, c.color)));
    Ok(chosen.iter().map(|c| c.id as usize).collect())
}

pub fn get_config_attrib(dpy: usize, cfg: usize, attribute: EGLint) -> EglResult<EGLint> {
    let g = egl();
    g.check(dpy)?;
    g.config(cfg)?.attrib(attribute).ok_or(EGL_BAD_ATTRIBUTE)
}

pub fn create_pbuffer(dpy: usize, cfg: usize, pairs: &[(EGLint, EGLint)]) -> EglResult<usize> {
    let config = {
        let g = egl();
        g.check(dpy)?;
        g.config(cfg)?
    };
    let attribs = surface::parse_attribs(Kind::Pbuffer, config, pairs)?;
    let mut g = egl();
    let id = g.new_id();
    let s = Surface::new_pbuffer(id, config, attribs)?;
    g.surfaces.insert(id, Arc::new(s));
    Ok(id)
}

/// eglCreatePixmapSurface / eglCreateWindowSurface. `memory` is `None` when the native
/// handle is no valid pixmap or window; `key` is its address.
pub fn create_native(
    dpy: usize,
    cfg: usize,
    kind: Kind,
    key: usize,
    memory: Option<Box<dyn NativeMemory>>,
    pairs: &[(EGLint, EGLint)],
) -> EglResult<usize> {
    let mut g = egl();
    g.check(dpy)?;
    let config = g.config(cfg)?;
    let bad_native = if kind == Kind::Window {
        EGL_BAD_NATIVE_WINDOW
    } else {
        EGL_BAD_NATIVE_PIXMAP
    };
    let memory = memory.ok_or(bad_native)?;
    if !memory.layout().is_valid() {
        return Err(bad_native);
    }
    let attribs = surface::parse_attribs(kind, config, pairs)?;
    if kind == Kind::Pixmap && !surface::memory_compatible(memory.layout().format, config.color) {
        return Err(EGL_BAD_MATCH);
    }
    if g.natives.contains(&key) {
        return Err(EGL_BAD_ALLOC);
    }
    let id = g.new_id();
    let s = Surface::new_native(id, config, kind, attribs, memory, key)?;
    g.natives.insert(key);
    g.surfaces.insert(id, Arc::new(s));
    Ok(id)
}

/// eglDestroySurface: the handle goes at once, the surface when no thread has it current.
pub fn destroy_surface(dpy: usize, s: usize) -> EglResult<()> {
    let removed = {
        let mut g = egl();
        g.check(dpy)?;
        let surf = g.surfaces.remove(&s).ok_or(EGL_BAD_SURFACE)?;
        if surf.native_key != 0 {
            g.natives.remove(&surf.native_key);
        }
        surf
    };
    drop(removed);
    Ok(())
}

pub fn query_surface(dpy: usize, s: usize, attribute: EGLint) -> EglResult<Option<EGLint>> {
    let g = egl();
    g.check(dpy)?;
    g.surface(s)?.query(attribute)
}

pub fn surface_attrib(dpy: usize, s: usize, attribute: EGLint, value: EGLint) -> EglResult<()> {
    let g = egl();
    g.check(dpy)?;
    g.surface(s)?.set_attrib(attribute, value)
}

pub fn create_context(
    dpy: usize,
    cfg: usize,
    share: usize,
    pairs: &[(EGLint, EGLint)],
) -> EglResult<usize> {
    let (config, share) = {
        let g = egl();
        g.check(dpy)?;
        let config = g.config(cfg)?;
        let share = if share == 0 {
            None
        } else {
            Some(g.context(share)?)
        };
        (config, share)
    };
    if thread::api() != EGL_OPENGL_ES_API {
        return Err(EGL_BAD_MATCH);
    }
    let request = context::parse_attribs(pairs)?;
    let mut g = egl();
    let id = g.new_id();
    let ctx = Context::new(id, config, request, share.as_deref());
    g.contexts.insert(id, Arc::new(ctx));
    Ok(id)
}

/// eglDestroyContext: the handle goes at once, the context when no thread has it current.
pub fn destroy_context(dpy: usize, c: usize) -> EglResult<()> {
    let removed = {
        let mut g = egl();
        g.check(dpy)?;
        g.contexts.remove(&c).ok_or(EGL_BAD_CONTEXT)?
    };
    drop(removed);
    Ok(())
}

pub fn query_context(dpy: usize, c: usize, attribute: EGLint) -> EglResult<EGLint> {
    let g = egl();
    g.check(dpy)?;
    let ctx = g.context(c)?;
    let render_buffer = match g.draw_kind.get(&c) {
        None => EGL_NONE,
        Some(Kind::Pixmap) => EGL_SINGLE_BUFFER,
        Some(_) => EGL_BACK_BUFFER,
    };
    ctx.query(attribute, render_buffer)
}

/// eglMakeCurrent. Validation comes first, so a failed call changes nothing.
pub fn make_current(dpy: usize, draw: usize, read: usize, ctx: usize) -> EglResult<()> {
    let mut g = egl();
    if dpy != DISPLAY_HANDLE {
        return Err(EGL_BAD_DISPLAY);
    }
    let release = ctx == 0 && draw == 0 && read == 0;
    // Releasing is allowed on a terminated display, so threads can let go of what
    // eglTerminate left alive.
    if !g.initialized && !release {
        return Err(EGL_NOT_INITIALIZED);
    }
    // A thread whose locals are being destroyed (an `atexit` handler, a thread-local
    // destructor) has already released its binding and cannot hold a new one.
    if !release && !thread::alive() {
        return Err(EGL_BAD_ACCESS);
    }
    let c = if ctx == 0 {
        None
    } else {
        Some(g.context(ctx)?)
    };
    let d = if draw == 0 {
        None
    } else {
        Some(g.surface(draw)?)
    };
    let r = if read == 0 {
        None
    } else {
        Some(g.surface(read)?)
    };
    let new = match (c, d, r) {
        (None, None, None) => None,
        // Both surfaces, or neither (EGL_KHR_surfaceless_context: our GL contexts support
        // OES_surfaceless_context).
        (Some(c), d, r) if d.is_some() == r.is_some() => Some(Current {
            ctx: c,
            draw: d,
            read: r,
        }),
        // Surfaces need a context.
        _ => return Err(EGL_BAD_MATCH),
    };
    let me = thread::id();
    if let Some(n) = &new {
        for id in n.ids() {
            if g.current_on.get(&id).is_some_and(|t| *t != me) {
                return Err(EGL_BAD_ACCESS);
            }
        }
        let config = n.ctx.config.id;
        if n.draw.iter().chain(&n.read).any(|s| s.config.id != config) {
            return Err(EGL_BAD_MATCH);
        }
    }

    // Switch: complete the old context's rendering, then bind the new one.
    let old = thread::replace_current(None);
    if let Some(o) = &old {
        let mut gl = gl_current::lock(&o.ctx.gl);
        gl.finish();
        if new.as_ref().map(|n| n.ctx.id) != Some(o.ctx.id) {
            gl.make_current(None, None);
        }
        drop(gl);
        g.unbind(o);
    }
    match &new {
        Some(n) => {
            for id in n.ids() {
                g.current_on.insert(id, me);
            }
            if let Some(d) = &n.draw {
                g.draw_kind.insert(n.ctx.id, d.kind);
            }
            let gl_surface = |s: &Arc<Surface>| -> Arc<dyn crate::gles::Surface> { s.clone() };
            let (draw, read) = (
                n.draw.as_ref().map(gl_surface),
                n.read.as_ref().map(gl_surface),
            );
            gl_current::lock(&n.ctx.gl).make_current(draw, read);
            gl_current::set(Some(n.ctx.gl.clone()));
        }
        None => {
            gl_current::set(None);
        }
    }
    thread::replace_current(new);
    drop(g);
    drop(old);
    Ok(())
}

/// eglReleaseThread: releases the current context and resets the thread's state.
pub fn release_thread() {
    if thread::current().is_some() {
        let _ = make_current(DISPLAY_HANDLE, 0, 0, 0);
    }
    thread::set_api(EGL_OPENGL_ES_API);
}

pub fn current_context() -> usize {
    thread::current().map_or(0, |c| c.ctx.id)
}

pub fn current_display() -> usize {
    thread::current().map_or(0, |_| DISPLAY_HANDLE)
}

pub fn current_surface(which: EGLint) -> EglResult<usize> {
    let cur = thread::current();
    match which {
        EGL_DRAW => Ok(cur.and_then(|c| c.draw).map_or(0, |s| s.id)),
        EGL_READ => Ok(cur.and_then(|c| c.read).map_or(0, |s| s.id)),
        _ => Err(EGL_BAD_PARAMETER),
    }
}

/// eglSwapBuffers: `s` must be the calling thread's current draw surface. Presents a window
/// (the back buffer is kept: swap behavior is effectively always preserved); a pbuffer or
/// pixmap only gets the implicit flush.
pub fn swap_buffers(dpy: usize, s: usize) -> EglResult<()> {
    let g = egl();
    g.check(dpy)?;
    let surf = g.surface(s)?;
    drop(g);
    let cur = thread::current()
        .filter(|c| c.draws_to(s))
        .ok_or(EGL_BAD_SURFACE)?;
    if surf.kind == Kind::Window {
        cur.ctx.finish();
        surf.present();
    } else if capture::enabled() {
        // A capture reads the target: everything drawn so far must be in it.
        cur.ctx.finish();
    } else {
        cur.ctx.flush();
    }
    capture::after_swap(&surf);
    Ok(())
}

/// eglCopyBuffers into a memory pixmap (`None`: not a valid pixmap).
pub fn copy_buffers(dpy: usize, s: usize, pixmap: Option<Box<dyn NativeMemory>>) -> EglResult<()> {
    let g = egl();
    g.check(dpy)?;
    let surf = g.surface(s)?;
    drop(g);
    let pixmap = pixmap
        .filter(|p| p.layout().is_valid())
        .ok_or(EGL_BAD_NATIVE_PIXMAP)?;
    if let Some(cur) = thread::current().filter(|c| c.draws_to(s)) {
        cur.ctx.finish();
    }
    surf.copy_to(pixmap.as_ref())
}

/// eglSwapInterval: clamped to the configs' range and stored on the current draw surface.
pub fn swap_interval(dpy: usize, interval: EGLint) -> EglResult<()> {
    let g = egl();
    g.check(dpy)?;
    let cur = thread::current().ok_or(EGL_BAD_CONTEXT)?;
    let draw = cur.draw.filter(|d| g.surfaces.contains_key(&d.id));
    let draw = draw.ok_or(EGL_BAD_SURFACE)?;
    let v = interval.clamp(MIN_SWAP_INTERVAL, MAX_SWAP_INTERVAL);
    draw.update_state(|s| s.swap_interval = v);
    Ok(())
}

fn texture_surface(dpy: usize, s: usize, buffer: EGLint) -> EglResult<Arc<Surface>> {
    let g = egl();
    g.check(dpy)?;
    let surf = g.surface(s)?;
    if surf.kind != Kind::Pbuffer {
        return Err(EGL_BAD_SURFACE);
    }
    if surf.attribs.texture_format == EGL_NO_TEXTURE {
        return Err(EGL_BAD_MATCH);
    }
    // Only the back buffer can be bound. The EGL 1.4 specification (§3.6.1) names
    // EGL_BAD_PARAMETER here; the reference pages say EGL_BAD_MATCH. The specification rules.
    if buffer != EGL_BACK_BUFFER {
        return Err(EGL_BAD_PARAMETER);
    }
    Ok(surf)
}

/// eglBindTexImage: validation and EGL-side state; the texel hookup is [`bind_tex_image`].
pub fn bind_tex_image_egl(dpy: usize, s: usize, buffer: EGLint) -> EglResult<()> {
    let surf = texture_surface(dpy, s, buffer)?;
    if surf.state().bound_to_texture {
        return Err(EGL_BAD_ACCESS);
    }
    // Ignored without a current context (section 3.6.1).
    let Some(cur) = thread::current() else {
        return Ok(());
    };
    // Rendering to the pbuffer issued so far must be visible in the texture.
    if cur.uses(s) {
        cur.ctx.finish();
    }
    if !bind_tex_image(&cur.ctx, &surf) {
        return Err(EGL_BAD_ALLOC);
    }
    surf.update_state(|st| st.bound_to_texture = true);
    Ok(())
}

/// Takes the pbuffer's color buffer as level 0 of the texture object bound to
/// GL_TEXTURE_2D of `ctx`'s active unit, in the surface's texture format; with
/// EGL_MIPMAP_TEXTURE the lower levels are generated from it. False when the texels cannot
/// be allocated.
pub fn bind_tex_image(ctx: &Context, surface: &Surface) -> bool {
    let rgba = surface.attribs.texture_format == EGL_TEXTURE_RGBA;
    let target = crate::gles::context::lock_target(surface);
    gl_current::lock(&ctx.gl).bind_tex_image(&target, rgba, surface.attribs.mipmap_texture)
}

/// eglReleaseTexImage: the texture loses the surface's image (its levels become
/// undefined, ES 1.1 with EGL 1.4 §3.6.2).
pub fn release_tex_image(dpy: usize, s: usize, buffer: EGLint) -> EglResult<()> {
    let surf = texture_surface(dpy, s, buffer)?;
    if surf.state().bound_to_texture {
        if let Some(cur) = thread::current() {
            gl_current::lock(&cur.ctx.gl).release_tex_image();
        }
    }
    surf.update_state(|st| st.bound_to_texture = false);
    Ok(())
}

/// eglWaitClient / eglWaitGL: completes the current context's rendering.
pub fn wait_client() -> EglResult<()> {
    let Some(cur) = thread::current() else {
        return Ok(());
    };
    check_current_surfaces(&cur)?;
    cur.ctx.finish();
    Ok(())
}

/// eglWaitNative: native rendering is complete, so a pixmap draw surface reloads its pixels.
pub fn wait_native(engine: EGLint) -> EglResult<()> {
    if engine != EGL_CORE_NATIVE_ENGINE {
        return Err(EGL_BAD_PARAMETER);
    }
    let Some(cur) = thread::current() else {
        return Ok(());
    };
    check_current_surfaces(&cur)?;
    cur.ctx.flush();
    if let Some(d) = &cur.draw {
        d.reload_native();
    }
    Ok(())
}

fn check_current_surfaces(cur: &Current) -> EglResult<()> {
    let g = egl();
    if cur
        .draw
        .iter()
        .chain(&cur.read)
        .any(|s| !g.surfaces.contains_key(&s.id))
    {
        return Err(EGL_BAD_CURRENT_SURFACE);
    }
    Ok(())
}

/// eglBindAPI: only OpenGL ES is supported.
pub fn bind_api(api: EGLenum) -> EglResult<()> {
    if api != EGL_OPENGL_ES_API {
        return Err(EGL_BAD_PARAMETER);
    }
    thread::set_api(api);
    Ok(())
}

pub fn query_api() -> EGLenum {
    thread::api()
}

/// A fence sync: signaled once every command its context had issued before it completes.
/// Rendering is deferred until a flush, so the fence is kept unsignaled and completed (the
/// context finished) the first time anyone looks at it: a status query, a client wait or
/// a server wait. A fence whose context is gone has nothing left to wait for.
pub struct Fence {
    ctx: Weak<Context>,
    signaled: bool,
}

/// Which entry point a sync call came through: EGL 1.5 and EGL_KHR_fence_sync name
/// different errors for a type they do not support.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum SyncApi {
    Core,
    Khr,
}

/// eglCreateSync / eglCreateSyncKHR: a fence after the current context's commands.
pub fn create_sync<A>(
    dpy: usize,
    kind: EGLenum,
    attribs: &[(A, A)],
    api: SyncApi,
) -> EglResult<usize> {
    let mut g = egl();
    g.check(dpy)?;
    if kind != EGL_SYNC_FENCE as EGLenum {
        return Err(match api {
            SyncApi::Core => EGL_BAD_PARAMETER,
            SyncApi::Khr => EGL_BAD_ATTRIBUTE,
        });
    }
    // A fence takes no attributes.
    if !attribs.is_empty() {
        return Err(EGL_BAD_ATTRIBUTE);
    }
    // The fence follows the commands of the calling thread's current context.
    let cur = thread::current().ok_or(EGL_BAD_MATCH)?;
    let id = g.new_id();
    g.syncs.insert(
        id,
        Fence {
            ctx: Arc::downgrade(&cur.ctx),
            signaled: false,
        },
    );
    Ok(id)
}

/// Completes the work a fence waits for and marks it signaled (EGL_BAD_PARAMETER for no
/// such fence).
fn signal(dpy: usize, sync: usize) -> EglResult<()> {
    let ctx = {
        let g = egl();
        g.check(dpy)?;
        let f = g.syncs.get(&sync).ok_or(EGL_BAD_PARAMETER)?;
        if f.signaled {
            return Ok(());
        }
        f.ctx.upgrade()
    };
    // Outside the display lock: finishing may wait for another thread's GL call.
    if let Some(c) = ctx {
        c.finish();
    }
    if let Some(f) = egl().syncs.get_mut(&sync) {
        f.signaled = true;
    }
    Ok(())
}

/// EGL_BAD_PARAMETER unless `sync` is a fence of display `dpy` (after the display's own
/// checks).
fn check_sync(dpy: usize, sync: usize) -> EglResult<()> {
    let g = egl();
    g.check(dpy)?;
    if g.syncs.contains_key(&sync) {
        Ok(())
    } else {
        Err(EGL_BAD_PARAMETER)
    }
}

/// eglClientWaitSync: every wait ends with the condition satisfied, since waiting is
/// completing the fence's context here.
pub fn client_wait_sync(dpy: usize, sync: usize) -> EglResult<EGLint> {
    signal(dpy, sync)?;
    Ok(EGL_CONDITION_SATISFIED)
}

/// eglWaitSync: the current context's later commands wait for the fence; completing the
/// fence now is the strongest such wait.
pub fn wait_sync(dpy: usize, sync: usize, flags: EGLint) -> EglResult<()> {
    check_sync(dpy, sync)?;
    if flags != 0 {
        return Err(EGL_BAD_PARAMETER);
    }
    if thread::current().is_none() {
        return Err(EGL_BAD_MATCH);
    }
    signal(dpy, sync)
}

/// eglGetSyncAttrib.
pub fn get_sync_attrib(dpy: usize, sync: usize, attribute: EGLint) -> EglResult<EGLint> {
    check_sync(dpy, sync)?;
    match attribute {
        EGL_SYNC_TYPE => Ok(EGL_SYNC_FENCE),
        EGL_SYNC_CONDITION => Ok(EGL_SYNC_PRIOR_COMMANDS_COMPLETE),
        // Asking is looking: the fence is completed, so a polling loop ends.
        EGL_SYNC_STATUS => signal(dpy, sync).map(|()| EGL_SIGNALED),
        _ => Err(EGL_BAD_ATTRIBUTE),
    }
}

/// eglDestroySync.
pub fn destroy_sync(dpy: usize, sync: usize) -> EglResult<()> {
    let mut g = egl();
    g.check(dpy)?;
    g.syncs.remove(&sync).map(|_| ()).ok_or(EGL_BAD_PARAMETER)
}

/// eglCreateImage / eglCreateImageKHR from a GL 2D texture (`EGL_KHR_gl_texture_2D_image`,
/// the one target offered): the image holds a copy of the level.
pub fn create_image<A: Copy + Into<i64>>(
    dpy: usize,
    ctx: usize,
    target: EGLenum,
    buffer: usize,
    attribs: &[(A, A)],
) -> EglResult<usize> {
    let ctx = {
        let g = egl();
        g.check(dpy)?;
        if target != EGL_GL_TEXTURE_2D as EGLenum {
            return Err(EGL_BAD_PARAMETER);
        }
        g.context(ctx)?
    };
    let mut level = 0;
    for &(a, v) in attribs {
        let (a, v) = (a.into(), v.into());
        match a {
            a if a == i64::from(EGL_GL_TEXTURE_LEVEL) => {
                level = usize::try_from(v).map_err(|_| EGL_BAD_MATCH)?;
            }
            // Contents are always preserved: the image is a copy.
            a if a == i64::from(EGL_IMAGE_PRESERVED) && (v == 0 || v == 1) => {}
            _ => return Err(EGL_BAD_PARAMETER),
        }
    }
    let name = u32::try_from(buffer).map_err(|_| EGL_BAD_PARAMETER)?;
    if name == 0 {
        return Err(EGL_BAD_PARAMETER);
    }
    let image = gl_current::lock(&ctx.gl)
        .egl_image_source(name, level)
        .map_err(|e| match e {
            ImageSourceError::NotATexture2D => EGL_BAD_PARAMETER,
            ImageSourceError::NoSuchLevel => EGL_BAD_MATCH,
        })?;
    let id = egl().new_id();
    crate::gles::egl_image::insert(id, image);
    Ok(id)
}

/// eglDestroyImage.
pub fn destroy_image(dpy: usize, image: usize) -> EglResult<()> {
    egl().check(dpy)?;
    if crate::gles::egl_image::remove(image) {
        Ok(())
    } else {
        Err(EGL_BAD_PARAMETER)
    }
}

#[cfg(test)]
mod tests {
    //! The display is process-wide, so everything runs in one test, in order.
    use super::*;

    fn pbuffer(cfg: usize, w: EGLint, h: EGLint) -> usize {
        create_pbuffer(DISPLAY_HANDLE, cfg, &[(EGL_WIDTH, w), (EGL_HEIGHT, h)]).unwrap()
    }

    #[test]
    fn display_lifecycle_and_errors() {
        let d = get_display(0);
        assert_eq!(d, DISPLAY_HANDLE);
        assert_eq!(initialize(2), Err(EGL_BAD_DISPLAY));
        assert_eq!(initialize(d), Ok((1, 5)));
        assert_eq!(query_string(d, 0x1234), Err(EGL_BAD_PARAMETER));
        assert_eq!(query_string(d, EGL_CLIENT_APIS), Ok(CLIENT_APIS));
        assert_eq!(get_configs(d).unwrap().len(), 36);
        assert_eq!(get_config_attrib(d, 37, EGL_RED_SIZE), Err(EGL_BAD_CONFIG));
        assert_eq!(get_config_attrib(d, 1, 0x1234), Err(EGL_BAD_ATTRIBUTE));

        let s1 = pbuffer(1, 4, 4);
        let s2 = pbuffer(2, 4, 4);
        let c1 = create_context(d, 1, 0, &[]).unwrap();
        assert_eq!(create_context(d, 1, 12345, &[]), Err(EGL_BAD_CONTEXT));
        assert_eq!(create_context(d, 99, 0, &[]), Err(EGL_BAD_CONFIG));
        let c2 = create_context(d, 1, c1, &[]).unwrap();

        // Errors leave the binding as it was.
        assert_eq!(make_current(d, s1, s1, 777), Err(EGL_BAD_CONTEXT));
        assert_eq!(make_current(d, 777, s1, c1), Err(EGL_BAD_SURFACE));
        assert_eq!(make_current(d, s1, s1, 0), Err(EGL_BAD_MATCH));
        // One surface without the other (no surfaces at all is a surfaceless binding).
        assert_eq!(make_current(d, 0, s1, c1), Err(EGL_BAD_MATCH));
        assert_eq!(make_current(d, s1, 0, c1), Err(EGL_BAD_MATCH));
        assert_eq!(make_current(d, s2, s2, c1), Err(EGL_BAD_MATCH));
        assert_eq!(current_context(), 0);

        make_current(d, s1, s1, c1).unwrap();
        assert_eq!(current_context(), c1);
        assert_eq!(current_surface(EGL_DRAW), Ok(s1));
        assert_eq!(query_context(d, c1, EGL_RENDER_BUFFER), Ok(EGL_BACK_BUFFER));
        assert_eq!(query_context(d, c2, EGL_RENDER_BUFFER), Ok(EGL_NONE));

        // Another thread cannot take c1 or s1.
        let t = std::thread::spawn(move || make_current(d, s1, s1, c2));
        assert_eq!(t.join().unwrap(), Err(EGL_BAD_ACCESS));

        // Destroying while current defers deletion but invalidates the handle.
        destroy_surface(d, s1).unwrap();
        assert_eq!(query_surface(d, s1, EGL_WIDTH), Err(EGL_BAD_SURFACE));
        assert_eq!(current_surface(EGL_DRAW), Ok(s1));
        assert_eq!(wait_client(), Err(EGL_BAD_CURRENT_SURFACE));
        make_current(d, 0, 0, 0).unwrap();
        assert_eq!(current_context(), 0);

        assert_eq!(swap_buffers(d, s2), Err(EGL_BAD_SURFACE));
        terminate(d).unwrap();
        assert_eq!(
            query_context(d, c1, EGL_CONFIG_ID),
            Err(EGL_NOT_INITIALIZED)
        );
        initialize(d).unwrap();
        assert_eq!(query_context(d, c1, EGL_CONFIG_ID), Err(EGL_BAD_CONTEXT));
        assert_eq!(destroy_surface(d, s2), Err(EGL_BAD_SURFACE));
        terminate(d).unwrap();
    }
}
