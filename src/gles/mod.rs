//! The OpenGL ES 1.1 Common profile state machine and its C entry points.

pub mod arrays;
pub mod context;
pub mod current;
pub mod ffi;
pub mod framebuffer;
pub mod get;
pub mod matrix;
pub mod state;
pub mod tokens;
pub mod tokens_ext;
pub mod types;

pub use context::{Context, Surface};

#[cfg(test)]
mod tests;
