//! Fog parameters.

use crate::gles::fog::fog_parameter_count;
use crate::gles::params::Params;
use crate::gles::types::*;

use super::{valid_params, with_context};

#[no_mangle]
pub extern "C" fn glFogf(pname: GLenum, param: GLfloat) {
    with_context("glFogf", (), |c| c.fog(pname, Params::Float(&[param])))
}

/// `GL_FOG_MODE`'s enumerant is passed as is; other values are 16.16.
#[no_mangle]
pub extern "C" fn glFogx(pname: GLenum, param: GLfixed) {
    with_context("glFogx", (), |c| c.fog(pname, Params::Fixed(&[param])))
}

/// # Safety
/// A non-null `params` must point to as many values as `pname` takes.
#[no_mangle]
pub unsafe extern "C" fn glFogfv(pname: GLenum, params: *const GLfloat) {
    with_context("glFogfv", (), |c| {
        // SAFETY: the caller passes pname's values.
        if let Some(v) = unsafe { valid_params(c, fog_parameter_count(pname), params) } {
            c.fog(pname, Params::Float(&v))
        }
    })
}

/// # Safety
/// A non-null `params` must point to as many values as `pname` takes.
#[no_mangle]
pub unsafe extern "C" fn glFogxv(pname: GLenum, params: *const GLfixed) {
    with_context("glFogxv", (), |c| {
        // SAFETY: the caller passes pname's values.
        if let Some(v) = unsafe { valid_params(c, fog_parameter_count(pname), params) } {
            c.fog(pname, Params::Fixed(&v))
        }
    })
}
