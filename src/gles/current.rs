//! The calling thread's current GL context. EGL sets it in `eglMakeCurrent`; every `gl*`
//! entry point reads it.
#![forbid(unsafe_code)]

use std::cell::RefCell;
use std::sync::{Arc, Mutex, MutexGuard};

use super::context::Context;

/// A context as EGL shares it between threads: one lock, taken per GL call.
pub type SharedContext = Arc<Mutex<Context>>;

thread_local! {
    static CURRENT: RefCell<Option<SharedContext>> = const { RefCell::new(None) };
}

/// Makes `ctx` the calling thread's current GL context (or none). False when the thread's
/// locals are already destroyed (a call from an `atexit` handler or a thread-local
/// destructor): the thread can have no context then.
pub fn set(ctx: Option<SharedContext>) -> bool {
    CURRENT.try_with(|c| *c.borrow_mut() = ctx).is_ok()
}

/// The calling thread's current context, if any (none once its locals are destroyed, so a
/// GL call at that point is a silent no-op instead of an abort).
pub fn get() -> Option<SharedContext> {
    CURRENT.try_with(|c| c.borrow().clone()).ok().flatten()
}

/// Locks a context, recovering it if a caught panic poisoned the lock: the state is still
/// consistent enough to report `GL_OUT_OF_MEMORY` and carry on.
pub fn lock(ctx: &Mutex<Context>) -> MutexGuard<'_, Context> {
    ctx.lock().unwrap_or_else(|e| e.into_inner())
}

/// Runs `f` on the current context; `None` when the thread has none (GL calls are then
/// silently ignored, as the specification leaves them undefined).
pub fn with<R>(f: impl FnOnce(&mut Context) -> R) -> Option<R> {
    let ctx = get()?;
    let mut guard = lock(&ctx);
    Some(f(&mut guard))
}
