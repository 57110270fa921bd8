//! A drop-in OpenGL ES 1.1 Common + EGL 1.5 library with a C ABI (`libGLES_CM.so`): the GL
//! and EGL state machines over the `gles-cm-core` rasterizer. The M3G API is the `m3g` crate,
//! beside this one on the same core.
#![allow(non_snake_case)]
#![deny(unsafe_op_in_unsafe_fn)]
#![deny(clippy::undocumented_unsafe_blocks)]

mod boundary;
pub mod egl;
pub mod gles;
