//! The EGL scalar and handle types, as the Khronos headers define them for this platform.

use std::ffi::c_void;

use super::native::{EGLMemoryPixmap, EGLMemoryWindow};

pub type EGLint = i32;
pub type EGLBoolean = u32;
pub type EGLenum = u32;
pub type EGLDisplay = *mut c_void;
pub type EGLConfig = *mut c_void;
pub type EGLSurface = *mut c_void;
pub type EGLContext = *mut c_void;
pub type EGLClientBuffer = *mut c_void;
pub type EGLNativeDisplayType = *mut c_void;
pub type EGLNativePixmapType = *mut EGLMemoryPixmap;
pub type EGLNativeWindowType = *mut EGLMemoryWindow;

/// What `eglGetProcAddress` returns: a generic function pointer the caller casts to the real
/// signature (`None` is the C null pointer).
#[allow(non_camel_case_types)]
pub type __eglMustCastToProperFunctionPointerType = Option<unsafe extern "C" fn()>;
