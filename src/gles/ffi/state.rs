//! Capabilities, hints, errors, strings, queries and synchronization.

use crate::gles::get::Value;
use crate::gles::tokens::*;
use crate::gles::types::*;

use super::{with_context, write_values};

#[no_mangle]
pub extern "C" fn glEnable(cap: GLenum) {
    with_context("glEnable", (), |c| c.set_capability(cap, true))
}

#[no_mangle]
pub extern "C" fn glDisable(cap: GLenum) {
    with_context("glDisable", (), |c| c.set_capability(cap, false))
}

#[no_mangle]
pub extern "C" fn glIsEnabled(cap: GLenum) -> GLboolean {
    with_context("glIsEnabled", GL_FALSE as GLboolean, |c| {
        c.is_enabled(cap) as GLboolean
    })
}

#[no_mangle]
pub extern "C" fn glHint(target: GLenum, mode: GLenum) {
    with_context("glHint", (), |c| c.hint(target, mode))
}

#[no_mangle]
pub extern "C" fn glGetError() -> GLenum {
    with_context("glGetError", GL_NO_ERROR, |c| c.take_error())
}

#[no_mangle]
pub extern "C" fn glGetString(name: GLenum) -> *const GLubyte {
    with_context("glGetString", std::ptr::null(), |c| {
        c.string(name).map_or(std::ptr::null(), |s| s.as_ptr())
    })
}

/// Looks `pname` up and hands the value to `write`, or records `GL_INVALID_ENUM`.
fn get(call: &'static str, pname: GLenum, write: impl FnOnce(&Value)) {
    with_context(call, (), |c| match c.state_value(pname) {
        Some(v) => write(&v),
        None => c.bad_enum("pname", pname),
    })
}

/// # Safety
/// `params` must have room for every value of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glGetBooleanv(pname: GLenum, params: *mut GLboolean) {
    // SAFETY: the caller provides room for pname's values.
    get("glGetBooleanv", pname, |v| unsafe {
        write_values(params, v.as_booleans())
    })
}

/// # Safety
/// `params` must have room for every value of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glGetIntegerv(pname: GLenum, params: *mut GLint) {
    // SAFETY: the caller provides room for pname's values.
    get("glGetIntegerv", pname, |v| unsafe {
        write_values(params, v.as_integers())
    })
}

/// # Safety
/// `params` must have room for every value of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glGetFloatv(pname: GLenum, params: *mut GLfloat) {
    // SAFETY: the caller provides room for pname's values.
    get("glGetFloatv", pname, |v| unsafe {
        write_values(params, v.as_floats())
    })
}

/// # Safety
/// `params` must have room for every value of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glGetFixedv(pname: GLenum, params: *mut GLfixed) {
    // SAFETY: the caller provides room for pname's values.
    get("glGetFixedv", pname, |v| unsafe {
        write_values(params, v.as_fixed())
    })
}

#[no_mangle]
pub extern "C" fn glFlush() {
    with_context("glFlush", (), |c| c.flush())
}

#[no_mangle]
pub extern "C" fn glFinish() {
    with_context("glFinish", (), |c| c.finish());
    crate::egl::capture::after_finish();
}
