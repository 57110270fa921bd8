//! Per-thread EGL state: the last error, the bound client API and the current context with
//! its draw and read surfaces.
#![forbid(unsafe_code)]

use std::cell::RefCell;
use std::sync::atomic::{AtomicI32, AtomicU64, Ordering};
use std::sync::Arc;

use super::context::Context;
use super::surface::Surface;
use super::tokens::*;
use super::types::{EGLenum, EGLint};

/// A thread's current context and surfaces: both surfaces, or neither
/// (`EGL_KHR_surfaceless_context`).
#[derive(Clone)]
pub struct Current {
    pub ctx: Arc<Context>,
    pub draw: Option<Arc<Surface>>,
    pub read: Option<Arc<Surface>>,
}

impl Current {
    /// The handles of the context and its surfaces.
    pub fn ids(&self) -> impl Iterator<Item = usize> + '_ {
        std::iter::once(self.ctx.id).chain(self.draw.iter().chain(&self.read).map(|s| s.id))
    }

    /// Whether surface `s` is the draw surface.
    pub fn draws_to(&self, s: usize) -> bool {
        self.draw.as_ref().is_some_and(|d| d.id == s)
    }

    /// Whether surface `s` is the draw or the read surface.
    pub fn uses(&self, s: usize) -> bool {
        self.draws_to(s) || self.read.as_ref().is_some_and(|r| r.id == s)
    }
}

struct ThreadState {
    error: EGLint,
    api: EGLenum,
    current: Option<Current>,
}

impl Drop for ThreadState {
    /// A thread that exits with a current context releases it, so other threads may bind it.
    fn drop(&mut self) {
        if let Some(c) = self.current.take() {
            super::display::forget_thread_binding(&c);
        }
    }
}

thread_local! {
    static STATE: RefCell<ThreadState> = const {
        RefCell::new(ThreadState {
            error: EGL_SUCCESS,
            api: EGL_OPENGL_ES_API,
            current: None,
        })
    };
}

static NEXT_THREAD_ID: AtomicU64 = AtomicU64::new(1);

thread_local! {
    static THREAD_ID: u64 = NEXT_THREAD_ID.fetch_add(1, Ordering::Relaxed);
}

/// A number naming the calling thread, never reused (`std::thread::current` would allocate a
/// handle the main thread never frees).
pub fn id() -> u64 {
    THREAD_ID.try_with(|t| *t).unwrap_or(0)
}

/// The last error of threads whose locals are already destroyed (EGL calls from `atexit`
/// handlers or thread-local destructors). They share this one slot: such calls come at
/// process or thread exit, where a program checks the error right after the call.
static LATE_ERROR: AtomicI32 = AtomicI32::new(EGL_SUCCESS);

/// Whether the calling thread can still hold EGL and GL state (false once its locals are
/// being destroyed).
pub fn alive() -> bool {
    STATE.try_with(|_| ()).is_ok()
}

/// Records the result of an EGL call (EGL_SUCCESS after a successful one).
pub fn set_error(e: EGLint) {
    if STATE.try_with(|s| s.borrow_mut().error = e).is_err() {
        LATE_ERROR.store(e, Ordering::Relaxed);
    }
}

/// eglGetError: returns the last error and resets it to EGL_SUCCESS.
pub fn take_error() -> EGLint {
    STATE
        .try_with(|s| std::mem::replace(&mut s.borrow_mut().error, EGL_SUCCESS))
        .unwrap_or_else(|_| LATE_ERROR.swap(EGL_SUCCESS, Ordering::Relaxed))
}

pub fn api() -> EGLenum {
    STATE
        .try_with(|s| s.borrow().api)
        .unwrap_or(EGL_OPENGL_ES_API)
}

pub fn set_api(api: EGLenum) {
    let _ = STATE.try_with(|s| s.borrow_mut().api = api);
}

/// The calling thread's current context and surfaces.
pub fn current() -> Option<Current> {
    STATE
        .try_with(|s| s.borrow().current.clone())
        .ok()
        .flatten()
}

/// Replaces the calling thread's current binding, returning the previous one.
pub fn replace_current(new: Option<Current>) -> Option<Current> {
    STATE
        .try_with(|s| std::mem::replace(&mut s.borrow_mut().current, new))
        .ok()
        .flatten()
}
