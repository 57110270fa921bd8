//! What every `extern "C"` entry point runs its body through. A panic is caught before it
//! could unwind into C, and it prints nothing: a library must not write to its host's
//! stderr, and the entry point reports its documented error instead (`GL_OUT_OF_MEMORY`,
//! `EGL_BAD_ALLOC`).

use std::cell::Cell;
use std::panic::{self, AssertUnwindSafe};
use std::sync::Once;

thread_local! {
    /// How many entry points the thread is inside (a GL call from an EGL one nests).
    static DEPTH: Cell<u32> = const { Cell::new(0) };
}

/// Runs `f`, returning `None` if it panicked.
pub(crate) fn catch<R>(f: impl FnOnce() -> R) -> Option<R> {
    static HOOK: Once = Once::new();
    HOOK.call_once(|| {
        // Panics outside the entry points (in a Rust program that also links the library)
        // still reach the hook that was there before.
        let previous = panic::take_hook();
        panic::set_hook(Box::new(move |info| {
            let inside = DEPTH.try_with(|d| d.get() > 0).unwrap_or(true);
            if !inside {
                previous(info);
            }
        }));
    });
    let _ = DEPTH.try_with(|d| d.set(d.get() + 1));
    let r = panic::catch_unwind(AssertUnwindSafe(f)).ok();
    let _ = DEPTH.try_with(|d| d.set(d.get() - 1));
    r
}
