//! The EGL scalar and handle types, as the Khronos headers define them for this platform.
#![forbid(unsafe_code)]

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
/// EGL 1.5: attribute values wide enough for a pointer.
pub type EGLAttrib = isize;
/// EGL 1.5: nanoseconds.
pub type EGLTime = u64;
pub type EGLSync = *mut c_void;
pub type EGLImage = *mut c_void;
/// The extensions' names for the same types (EGL_KHR_fence_sync, EGL_KHR_image_base).
pub type EGLTimeKHR = u64;
pub type EGLSyncKHR = *mut c_void;
pub type EGLImageKHR = *mut c_void;
pub type EGLNativePixmapType = *mut EGLMemoryPixmap;
pub type EGLNativeWindowType = *mut EGLMemoryWindow;

/// What `eglGetProcAddress` returns: a generic function pointer the caller casts to the real
/// signature (`None` is the C null pointer).
#[allow(non_camel_case_types)]
pub type __eglMustCastToProperFunctionPointerType = Option<unsafe extern "C" fn()>;
