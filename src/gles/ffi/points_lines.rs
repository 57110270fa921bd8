//! Line widths, point sizes and point parameters.

use crate::gles::params::Params;
use crate::gles::raster_state::point_parameter_count;
use crate::gles::types::*;
use gles_cm_core::fixed::to_f32 as fx;

use super::{valid_params, with_context};

#[no_mangle]
pub extern "C" fn glLineWidth(width: GLfloat) {
    with_context("glLineWidth", (), |c| c.line_width(width))
}

#[no_mangle]
pub extern "C" fn glLineWidthx(width: GLfixed) {
    with_context("glLineWidthx", (), |c| c.line_width(fx(width)))
}

#[no_mangle]
pub extern "C" fn glPointSize(size: GLfloat) {
    with_context("glPointSize", (), |c| c.point_size(size))
}

#[no_mangle]
pub extern "C" fn glPointSizex(size: GLfixed) {
    with_context("glPointSizex", (), |c| c.point_size(fx(size)))
}

#[no_mangle]
pub extern "C" fn glPointParameterf(pname: GLenum, param: GLfloat) {
    with_context("glPointParameterf", (), |c| {
        c.point_parameter(pname, Params::Float(&[param]))
    })
}

#[no_mangle]
pub extern "C" fn glPointParameterx(pname: GLenum, param: GLfixed) {
    with_context("glPointParameterx", (), |c| {
        c.point_parameter(pname, Params::Fixed(&[param]))
    })
}

/// # Safety
/// A non-null `params` must point to as many values as `pname` takes.
#[no_mangle]
pub unsafe extern "C" fn glPointParameterfv(pname: GLenum, params: *const GLfloat) {
    with_context("glPointParameterfv", (), |c| {
        // SAFETY: the caller passes pname's values.
        if let Some(v) = unsafe { valid_params(c, point_parameter_count(pname), params) } {
            c.point_parameter(pname, Params::Float(&v))
        }
    })
}

/// # Safety
/// A non-null `params` must point to as many values as `pname` takes.
#[no_mangle]
pub unsafe extern "C" fn glPointParameterxv(pname: GLenum, params: *const GLfixed) {
    with_context("glPointParameterxv", (), |c| {
        // SAFETY: the caller passes pname's values.
        if let Some(v) = unsafe { valid_params(c, point_parameter_count(pname), params) } {
            c.point_parameter(pname, Params::Fixed(&v))
        }
    })
}
