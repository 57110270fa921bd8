//! Texture environments and point sprite coordinate replacement.

use crate::gles::params::{fixed_reply, int_reply, Params};
use crate::gles::texenv::tex_env_parameter_count;
use crate::gles::types::*;

use super::{valid_params, with_context, write_values};

#[no_mangle]
pub extern "C" fn glTexEnvf(target: GLenum, pname: GLenum, param: GLfloat) {
    with_context("glTexEnvf", (), |c| {
        c.tex_env(target, pname, Params::Float(&[param]))
    })
}

#[no_mangle]
pub extern "C" fn glTexEnvi(target: GLenum, pname: GLenum, param: GLint) {
    with_context("glTexEnvi", (), |c| {
        c.tex_env(target, pname, Params::Int(&[param]))
    })
}

/// Enumerants are passed as is; scales and colors are 16.16.
#[no_mangle]
pub extern "C" fn glTexEnvx(target: GLenum, pname: GLenum, param: GLfixed) {
    with_context("glTexEnvx", (), |c| {
        c.tex_env(target, pname, Params::Fixed(&[param]))
    })
}

/// # Safety
/// A non-null `params` must point to as many values as `pname` takes.
#[no_mangle]
pub unsafe extern "C" fn glTexEnvfv(target: GLenum, pname: GLenum, params: *const GLfloat) {
    with_context("glTexEnvfv", (), |c| {
        // SAFETY: the caller passes pname's values.
        if let Some(v) = unsafe { valid_params(c, tex_env_parameter_count(target, pname), params) }
        {
            c.tex_env(target, pname, Params::Float(&v))
        }
    })
}

/// # Safety
/// A non-null `params` must point to as many values as `pname` takes.
#[no_mangle]
pub unsafe extern "C" fn glTexEnviv(target: GLenum, pname: GLenum, params: *const GLint) {
    with_context("glTexEnviv", (), |c| {
        // SAFETY: the caller passes pname's values.
        if let Some(v) = unsafe { valid_params(c, tex_env_parameter_count(target, pname), params) }
        {
            c.tex_env(target, pname, Params::Int(&v))
        }
    })
}

/// # Safety
/// A non-null `params` must point to as many values as `pname` takes.
#[no_mangle]
pub unsafe extern "C" fn glTexEnvxv(target: GLenum, pname: GLenum, params: *const GLfixed) {
    with_context("glTexEnvxv", (), |c| {
        // SAFETY: the caller passes pname's values.
        if let Some(v) = unsafe { valid_params(c, tex_env_parameter_count(target, pname), params) }
        {
            c.tex_env(target, pname, Params::Fixed(&v))
        }
    })
}

/// # Safety
/// A non-null `params` must have room for every value of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glGetTexEnvfv(target: GLenum, pname: GLenum, params: *mut GLfloat) {
    with_context("glGetTexEnvfv", (), |c| {
        if let Some(v) = c.get_tex_env(target, pname) {
            // SAFETY: the caller provides room for pname's values.
            unsafe { write_values(params, v.as_floats()) }
        }
    })
}

/// # Safety
/// A non-null `params` must have room for every value of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glGetTexEnviv(target: GLenum, pname: GLenum, params: *mut GLint) {
    with_context("glGetTexEnviv", (), |c| {
        if let Some(v) = c.get_tex_env(target, pname) {
            // SAFETY: the caller provides room for pname's values.
            unsafe { write_values(params, int_reply(&v)) }
        }
    })
}

/// # Safety
/// A non-null `params` must have room for every value of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glGetTexEnvxv(target: GLenum, pname: GLenum, params: *mut GLfixed) {
    with_context("glGetTexEnvxv", (), |c| {
        if let Some(v) = c.get_tex_env(target, pname) {
            // SAFETY: the caller provides room for pname's values.
            unsafe { write_values(params, fixed_reply(&v)) }
        }
    })
}
