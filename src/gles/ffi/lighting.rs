//! Lights, the light model and the material.

use crate::gles::lighting::{
    light_model_parameter_count, light_parameter_count, material_parameter_count,
};
use crate::gles::params::{fixed_reply, Params};
use crate::gles::types::*;

use super::{valid_params, with_context, write_values};

#[no_mangle]
pub extern "C" fn glLightf(light: GLenum, pname: GLenum, param: GLfloat) {
    with_context("glLightf", (), |c| {
        c.light(light, pname, Params::Float(&[param]))
    })
}

#[no_mangle]
pub extern "C" fn glLightx(light: GLenum, pname: GLenum, param: GLfixed) {
    with_context("glLightx", (), |c| {
        c.light(light, pname, Params::Fixed(&[param]))
    })
}

/// # Safety
/// A non-null `params` must point to as many values as `pname` takes.
#[no_mangle]
pub unsafe extern "C" fn glLightfv(light: GLenum, pname: GLenum, params: *const GLfloat) {
    with_context("glLightfv", (), |c| {
        // SAFETY: the caller passes pname's values.
        if let Some(v) = unsafe { valid_params(c, light_parameter_count(light, pname), params) } {
            c.light(light, pname, Params::Float(&v))
        }
    })
}

/// # Safety
/// A non-null `params` must point to as many values as `pname` takes.
#[no_mangle]
pub unsafe extern "C" fn glLightxv(light: GLenum, pname: GLenum, params: *const GLfixed) {
    with_context("glLightxv", (), |c| {
        // SAFETY: the caller passes pname's values.
        if let Some(v) = unsafe { valid_params(c, light_parameter_count(light, pname), params) } {
            c.light(light, pname, Params::Fixed(&v))
        }
    })
}

/// # Safety
/// A non-null `params` must have room for every value of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glGetLightfv(light: GLenum, pname: GLenum, params: *mut GLfloat) {
    with_context("glGetLightfv", (), |c| {
        if let Some(v) = c.get_light(light, pname) {
            // SAFETY: the caller provides room for pname's values.
            unsafe { write_values(params, v.as_floats()) }
        }
    })
}

/// # Safety
/// A non-null `params` must have room for every value of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glGetLightxv(light: GLenum, pname: GLenum, params: *mut GLfixed) {
    with_context("glGetLightxv", (), |c| {
        if let Some(v) = c.get_light(light, pname) {
            // SAFETY: the caller provides room for pname's values.
            unsafe { write_values(params, fixed_reply(&v)) }
        }
    })
}

#[no_mangle]
pub extern "C" fn glLightModelf(pname: GLenum, param: GLfloat) {
    with_context("glLightModelf", (), |c| {
        c.light_model(pname, Params::Float(&[param]))
    })
}

#[no_mangle]
pub extern "C" fn glLightModelx(pname: GLenum, param: GLfixed) {
    with_context("glLightModelx", (), |c| {
        c.light_model(pname, Params::Fixed(&[param]))
    })
}

/// # Safety
/// A non-null `params` must point to as many values as `pname` takes.
#[no_mangle]
pub unsafe extern "C" fn glLightModelfv(pname: GLenum, params: *const GLfloat) {
    with_context("glLightModelfv", (), |c| {
        // SAFETY: the caller passes pname's values.
        if let Some(v) = unsafe { valid_params(c, light_model_parameter_count(pname), params) } {
            c.light_model(pname, Params::Float(&v))
        }
    })
}

/// # Safety
/// A non-null `params` must point to as many values as `pname` takes.
#[no_mangle]
pub unsafe extern "C" fn glLightModelxv(pname: GLenum, params: *const GLfixed) {
    with_context("glLightModelxv", (), |c| {
        // SAFETY: the caller passes pname's values.
        if let Some(v) = unsafe { valid_params(c, light_model_parameter_count(pname), params) } {
            c.light_model(pname, Params::Fixed(&v))
        }
    })
}

#[no_mangle]
pub extern "C" fn glMaterialf(face: GLenum, pname: GLenum, param: GLfloat) {
    with_context("glMaterialf", (), |c| {
        c.material(face, pname, Params::Float(&[param]))
    })
}

#[no_mangle]
pub extern "C" fn glMaterialx(face: GLenum, pname: GLenum, param: GLfixed) {
    with_context("glMaterialx", (), |c| {
        c.material(face, pname, Params::Fixed(&[param]))
    })
}

/// # Safety
/// A non-null `params` must point to as many values as `pname` takes.
#[no_mangle]
pub unsafe extern "C" fn glMaterialfv(face: GLenum, pname: GLenum, params: *const GLfloat) {
    with_context("glMaterialfv", (), |c| {
        // SAFETY: the caller passes pname's values.
        if let Some(v) = unsafe { valid_params(c, material_parameter_count(face, pname), params) } {
            c.material(face, pname, Params::Float(&v))
        }
    })
}

/// # Safety
/// A non-null `params` must point to as many values as `pname` takes.
#[no_mangle]
pub unsafe extern "C" fn glMaterialxv(face: GLenum, pname: GLenum, params: *const GLfixed) {
    with_context("glMaterialxv", (), |c| {
        // SAFETY: the caller passes pname's values.
        if let Some(v) = unsafe { valid_params(c, material_parameter_count(face, pname), params) } {
            c.material(face, pname, Params::Fixed(&v))
        }
    })
}

/// # Safety
/// A non-null `params` must have room for every value of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glGetMaterialfv(face: GLenum, pname: GLenum, params: *mut GLfloat) {
    with_context("glGetMaterialfv", (), |c| {
        if let Some(v) = c.get_material(face, pname) {
            // SAFETY: the caller provides room for pname's values.
            unsafe { write_values(params, v.as_floats()) }
        }
    })
}

/// # Safety
/// A non-null `params` must have room for every value of `pname`.
#[no_mangle]
pub unsafe extern "C" fn glGetMaterialxv(face: GLenum, pname: GLenum, params: *mut GLfixed) {
    with_context("glGetMaterialxv", (), |c| {
        if let Some(v) = c.get_material(face, pname) {
            // SAFETY: the caller provides room for pname's values.
            unsafe { write_values(params, fixed_reply(&v)) }
        }
    })
}
