//! The OpenGL ES 1.1 Common profile state machine and its C entry points.
//!
//! Only `ffi` (the entry points) has `unsafe` code. A `forbid` here would bind `ffi` too and
//! could not be lifted there, so every other file of this module says
//! `#![forbid(unsafe_code)]` itself.

pub mod arrays;
pub mod buffer;
pub mod clip_planes;
pub mod context;
pub mod current;
pub mod current_values;
pub mod debug;
pub mod draw_texture;
pub mod egl_image;
pub mod fbo;
pub mod ffi;
pub mod fog;
pub mod framebuffer;
pub mod get;
pub mod lighting;
pub mod matrix;
pub mod objects;
pub mod params;
pub mod per_fragment;
pub mod raster_state;
pub mod state;
pub mod texenv;
pub mod texture;
pub mod tokens;
pub mod tokens_ext;
pub mod types;
pub mod vertex_array;

pub use context::{Context, Surface};

#[cfg(test)]
mod area_tests;
#[cfg(test)]
mod tests;
