//! The OpenGL ES 1.1 Common profile state machine and its C entry points.

pub mod context;
pub mod current;
pub mod ffi;
pub mod tokens;
pub mod types;

pub use context::{Context, Surface};
