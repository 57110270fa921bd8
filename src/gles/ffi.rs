//! The `extern "C"` `gl*` entry points: thin shims that catch panics, find the current
//! context, turn C pointers into checked slices and call a safe [`Context`] method
//! (ARCHITECTURE decision 8). One file per state area.

use std::ffi::c_void;

use super::context::Context;
use super::current;
use super::tokens::GL_OUT_OF_MEMORY;

mod arrays;
mod buffer;
mod clip_planes;
mod current_values;
mod debug;
mod draw_texture;
mod fbo;
mod fog;
mod framebuffer;
mod lighting;
mod matrix;
mod oes_aliases;
mod palette;
mod per_fragment;
mod points_lines;
mod state;
mod texenv;
mod texgen;
mod texture;

pub use arrays::*;
pub use buffer::*;
pub use clip_planes::*;
pub use current_values::*;
pub use debug::*;
pub use draw_texture::*;
pub use fbo::*;
pub use fog::*;
pub use framebuffer::*;
pub use lighting::*;
pub use matrix::*;
pub use oes_aliases::*;
pub use palette::*;
pub use per_fragment::*;
pub use points_lines::*;
pub use state::*;
pub use texenv::*;
pub use texgen::*;
pub use texture::*;

/// Runs `f` on the calling thread's current context, as entry point `call` (the name debug
/// messages give). Without a context the call does nothing and returns `default` (so also
/// once the thread's locals are destroyed, as in an `atexit` handler). A panic inside is
/// caught here, never crossing into C, and reported as `GL_OUT_OF_MEMORY` (the only error GL
/// lets an implementation raise at any time). Debug messages for the application's callback
/// are delivered after the context is unlocked, before the entry point returns.
pub(crate) fn with_context<R>(
    call: &'static str,
    default: R,
    f: impl FnOnce(&mut Context) -> R,
) -> R {
    let Some(ctx) = current::get() else {
        return default;
    };
    let ran = crate::boundary::catch(|| {
        let mut c = current::lock(&ctx);
        c.call = call;
        let r = f(&mut c);
        (r, c.debug.take_pending())
    });
    let (r, pending) = ran.unwrap_or_else(|| {
        let mut c = current::lock(&ctx);
        c.call = call;
        c.set_error(GL_OUT_OF_MEMORY);
        (default, c.debug.take_pending())
    });
    if let Some((callback, user, messages)) = pending {
        debug::deliver(callback, user, messages);
    }
    r
}

/// Views `len` bytes of client memory at `ptr` (a non-null address `len` bytes of which the
/// application guarantees readable).
///
/// # Safety
/// The memory must stay valid and unaliased by writes for the duration of the borrow.
pub(crate) unsafe fn client_bytes<'a>(ptr: usize, len: usize) -> &'a [u8] {
    if len == 0 {
        return &[];
    }
    // SAFETY: forwarded to the caller's contract above.
    unsafe { std::slice::from_raw_parts(ptr as *const u8, len) }
}

/// What a program passed to a `gl*Pointer` call: the number `glGetPointerv` gives back, and
/// when no buffer object was bound, the address of client memory that draw calls read long
/// after the call returned. Only [`ClientPtr::new`] (`unsafe`, called by the shims here) makes
/// one that can be read, so the safe modules store and read client arrays without handling
/// an address themselves.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ClientPtr {
    addr: usize,
    /// False for a value that is not an address the program vouched for (a buffer offset).
    readable: bool,
}

impl ClientPtr {
    /// The pointer as a `gl*Pointer` shim receives it.
    ///
    /// # Safety
    /// When the array is specified with no buffer object bound to `GL_ARRAY_BUFFER`, the
    /// program must keep every byte a later draw call reads through `ptr` readable, and not
    /// write it during that call, for as long as the array is in use: the contract GL sets
    /// for client arrays (ES 1.1 §2.8). With a buffer object bound, `ptr` is an offset and
    /// the crate never reads it as an address (`Context::array_pointer` keeps it as
    /// [`ClientPtr::offset`]).
    pub unsafe fn new(ptr: *const c_void) -> ClientPtr {
        ClientPtr {
            addr: ptr as usize,
            readable: true,
        }
    }

    /// A value that is never read as memory: an offset into a buffer object.
    pub const fn offset(offset: usize) -> ClientPtr {
        ClientPtr {
            addr: offset,
            readable: false,
        }
    }

    /// The value as given (what `glGetPointerv` returns; the offset into a buffer object).
    pub fn addr(self) -> usize {
        self.addr
    }

    /// The `len` bytes of client memory at the pointer, or `None` for a null pointer, an
    /// offset, or an extent beyond the address space.
    pub fn bytes<'a>(self, len: usize) -> Option<&'a [u8]> {
        if !self.readable || self.addr == 0 {
            return None;
        }
        if self.addr.checked_add(len).is_none() || len > isize::MAX as usize {
            return None;
        }
        // SAFETY: the pointer came from `new`, whose caller passed on the program's promise
        // that the bytes a draw reads stay readable while the array is in use.
        Some(unsafe { client_bytes(self.addr, len) })
    }
}

/// The pointer a `gl*Pointer` shim received, for [`Context::array_pointer`]. Only those
/// shims call this.
fn client_ptr(ptr: *const c_void) -> ClientPtr {
    // SAFETY: `ptr` is a `gl*Pointer` argument, given under GL's client-array contract,
    // which is `ClientPtr::new`'s.
    unsafe { ClientPtr::new(ptr) }
}

/// Reads `N` values from a C array argument, or `None` for a null pointer.
///
/// # Safety
/// A non-null `p` must point to at least `N` readable values.
pub(crate) unsafe fn read_array<T: Copy, const N: usize>(p: *const T) -> Option<[T; N]> {
    if p.is_null() {
        return None;
    }
    // SAFETY: non-null and, by the caller's contract, N readable values.
    Some(unsafe { std::ptr::read_unaligned(p as *const [T; N]) })
}

/// The values of a vector setter, read only after its names were validated, so that a bad
/// name is reported even with a bad pointer: `count` is `None` for invalid names (then
/// `GL_INVALID_ENUM`, and the pointer is never read). A null pointer gives `None` (nothing
/// to set).
///
/// # Safety
/// A non-null `p` must point to at least `count` readable values.
pub(crate) unsafe fn valid_params<T: Copy>(
    c: &mut Context,
    count: Option<usize>,
    p: *const T,
) -> Option<Vec<T>> {
    let Some(n) = count else {
        c.set_error(super::tokens::GL_INVALID_ENUM);
        return None;
    };
    // SAFETY: forwarded to the caller's contract.
    unsafe { read_slice(p, n) }
}

/// Reads `n` values from a C array argument, or `None` for a null pointer.
///
/// # Safety
/// A non-null `p` must point to at least `n` readable values.
pub(crate) unsafe fn read_slice<T: Copy>(p: *const T, n: usize) -> Option<Vec<T>> {
    if p.is_null() {
        return None;
    }
    // SAFETY: non-null and, by the caller's contract, n readable values.
    Some(
        (0..n)
            .map(|i| unsafe { p.add(i).read_unaligned() })
            .collect(),
    )
}

/// Writes query results to a C array argument, ignoring a null pointer.
///
/// # Safety
/// A non-null `p` must have room for every value `values` yields.
pub(crate) unsafe fn write_values<T>(p: *mut T, values: impl Iterator<Item = T>) {
    if p.is_null() {
        return;
    }
    for (i, v) in values.enumerate() {
        // SAFETY: by the caller's contract, there is room for this value.
        unsafe { p.add(i).write_unaligned(v) };
    }
}

macro_rules! proc_table {
    ($($name:ident),* $(,)?) => {
        /// The address of the `gl*` function called `name`, for `eglGetProcAddress`.
        pub fn proc_address(name: &str) -> Option<*const c_void> {
            match name {
                $(stringify!($name) => Some($name as *const c_void),)*
                _ => None,
            }
        }

        /// Every `gl*` function this library exports.
        pub const PROC_NAMES: &[&str] = &[$(stringify!($name)),*];
    };
}

// build.rs lists every exported `gl*` function, so the table cannot miss one.
include!(concat!(env!("OUT_DIR"), "/gl_proc_table.rs"));
