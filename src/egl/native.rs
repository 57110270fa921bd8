//! The native pixmap and window types of this EGL: blocks of client memory.
//!
//! There is no window system. A native pixmap or window is a pointer to one of the structs
//! below, owned by the application, which must keep the struct and its pixels valid (and not
//! move or resize them) for as long as an EGL surface made from it exists. `build.rs` copies
//! these definitions, with their documentation, into `include/EGL/eglplatform.h`.
#![forbid(unsafe_code)]

use std::ffi::c_void;

/// `format`: 16-bit words, red in bits 15..11, green 10..5, blue 4..0 (native byte order).
pub const EGL_MEMORY_RGB565: i32 = 1;
/// `format`: 3 bytes per pixel, red, green, blue.
pub const EGL_MEMORY_RGB888: i32 = 2;
/// `format`: 4 bytes per pixel, red, green, blue, alpha.
pub const EGL_MEMORY_RGBA8888: i32 = 3;
/// `format`: 4 bytes per pixel, blue, green, red, alpha.
pub const EGL_MEMORY_BGRA8888: i32 = 4;

/// A native pixmap: `height` rows of `width` pixels in `format` (an `EGL_MEMORY_*` value),
/// row 0 at the top, rows `stride` bytes apart (at least `width` times the pixel size).
/// A pixmap surface starts with these pixels, and GL rendering results are written back to
/// them when rendering completes (glFinish, eglWaitGL, eglWaitClient, and when the surface's
/// context stops being current). eglCopyBuffers writes into one as well.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct EGLMemoryPixmap {
    pub width: i32,
    pub height: i32,
    pub stride: i32,
    pub format: i32,
    pub pixels: *mut c_void,
}

/// A native window: the same layout as a pixmap, row 0 at the top. eglSwapBuffers copies the
/// back buffer of a window surface into `pixels`, converting to `format`. The window's size is
/// read when the surface is created.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct EGLMemoryWindow {
    pub width: i32,
    pub height: i32,
    pub stride: i32,
    pub format: i32,
    pub pixels: *mut c_void,
}
