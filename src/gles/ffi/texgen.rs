//! `OES_texture_cube_map`'s texture coordinate generation: `glTexGen*OES` and
//! `glGetTexGen*vOES` (one state per unit, `GL_TEXTURE_GEN_MODE_OES` of
//! `GL_TEXTURE_GEN_STR_OES`). Enum values pass unconverted in every form, the fixed-point
//! ones included.

use crate::gles::types::*;

use crate::gles::texture::tex_gen_parameter_count;

use super::{valid_params, with_context, write_values};

#[no_mangle]
pub extern "C" fn glTexGenfOES(coord: GLenum, pname: GLenum, param: GLfloat) {
    with_context("glTexGenfOES", (), |c| {
        c.tex_gen(coord, pname, param as f64)
    })
}

#[no_mangle]
pub extern "C" fn glTexGeniOES(coord: GLenum, pname: GLenum, param: GLint) {
    with_context("glTexGeniOES", (), |c| {
        c.tex_gen(coord, pname, param as f64)
    })
}

#[no_mangle]
pub extern "C" fn glTexGenxOES(coord: GLenum, pname: GLenum, param: GLfixed) {
    with_context("glTexGenxOES", (), |c| {
        c.tex_gen(coord, pname, param as f64)
    })
}

/// # Safety
/// A non-null `params` must point to one value.
#[no_mangle]
pub unsafe extern "C" fn glTexGenfvOES(coord: GLenum, pname: GLenum, params: *const GLfloat) {
    with_context("glTexGenfvOES", (), |c| {
        // SAFETY: the application passes one value.
        if let Some(v) = unsafe { valid_params(c, tex_gen_parameter_count(coord, pname), params) } {
            c.tex_gen(coord, pname, v[0] as f64)
        }
    })
}

/// # Safety
/// A non-null `params` must point to one value.
#[no_mangle]
pub unsafe extern "C" fn glTexGenivOES(coord: GLenum, pname: GLenum, params: *const GLint) {
    with_context("glTexGenivOES", (), |c| {
        // SAFETY: the application passes one value.
        if let Some(v) = unsafe { valid_params(c, tex_gen_parameter_count(coord, pname), params) } {
            c.tex_gen(coord, pname, v[0] as f64)
        }
    })
}

/// # Safety
/// A non-null `params` must point to one value.
#[no_mangle]
pub unsafe extern "C" fn glTexGenxvOES(coord: GLenum, pname: GLenum, params: *const GLfixed) {
    with_context("glTexGenxvOES", (), |c| {
        // SAFETY: the application passes one value.
        if let Some(v) = unsafe { valid_params(c, tex_gen_parameter_count(coord, pname), params) } {
            c.tex_gen(coord, pname, v[0] as f64)
        }
    })
}

/// # Safety
/// A non-null `params` must have room for one value.
#[no_mangle]
pub unsafe extern "C" fn glGetTexGenfvOES(coord: GLenum, pname: GLenum, params: *mut GLfloat) {
    with_context("glGetTexGenfvOES", (), |c| {
        if let Some(m) = c.get_tex_gen(coord, pname) {
            // SAFETY: the application provides room for one value.
            unsafe { write_values(params, std::iter::once(m as GLfloat)) }
        }
    })
}

/// # Safety
/// A non-null `params` must have room for one value.
#[no_mangle]
pub unsafe extern "C" fn glGetTexGenivOES(coord: GLenum, pname: GLenum, params: *mut GLint) {
    with_context("glGetTexGenivOES", (), |c| {
        if let Some(m) = c.get_tex_gen(coord, pname) {
            // SAFETY: the application provides room for one value.
            unsafe { write_values(params, std::iter::once(m as GLint)) }
        }
    })
}

/// # Safety
/// A non-null `params` must have room for one value.
#[no_mangle]
pub unsafe extern "C" fn glGetTexGenxvOES(coord: GLenum, pname: GLenum, params: *mut GLfixed) {
    with_context("glGetTexGenxvOES", (), |c| {
        if let Some(m) = c.get_tex_gen(coord, pname) {
            // SAFETY: the application provides room for one value.
            unsafe { write_values(params, std::iter::once(m as GLfixed)) }
        }
    })
}
