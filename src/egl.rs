//! EGL 1.5: the display, configs, surfaces (pbuffers, memory pixmaps and memory windows),
//! contexts and the per-thread current binding, with the C entry points in `ffi`.
//!
//! Core logic lives in safe modules; `ffi` (the C entry points) and `glvnd` (the glvnd vendor
//! interface) are the only places with `unsafe` code; every other file forbids it
//! (`#![forbid(unsafe_code)]`), so the compiler keeps it so.

pub mod capture;
pub mod config;
pub mod context;
pub mod display;
pub mod ffi;
pub mod glvnd;
pub mod native;
pub mod surface;
pub mod thread;
pub mod tokens;
pub mod types;
