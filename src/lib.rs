//! A drop-in OpenGL ES 1.1 Common + EGL 1.5 library with a C ABI, and an M3G 1.1 API in Rust,
//! both backed by one software rasterizer (`core`).
#![allow(non_snake_case)]
#![deny(unsafe_op_in_unsafe_fn)]
#![deny(clippy::undocumented_unsafe_blocks)]

mod boundary;
pub mod core;
pub mod egl;
pub mod gles;
pub mod m3g;
