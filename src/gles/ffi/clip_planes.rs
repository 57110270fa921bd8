//! User clip planes.

use crate::gles::types::*;
use gles_cm_core::fixed::{from_f32, to_f32 as fx};

use crate::gles::clip_planes::clip_plane_count;

use super::{valid_params, with_context, write_values};

/// # Safety
/// A non-null `equation` must point to four values.
#[no_mangle]
pub unsafe extern "C" fn glClipPlanef(plane: GLenum, equation: *const GLfloat) {
    with_context("glClipPlanef", (), |c| {
        // SAFETY: the caller passes four values.
        if let Some(eq) = unsafe { valid_params(c, clip_plane_count(plane), equation) } {
            c.clip_plane(plane, [eq[0], eq[1], eq[2], eq[3]])
        }
    })
}

/// # Safety
/// A non-null `equation` must point to four values.
#[no_mangle]
pub unsafe extern "C" fn glClipPlanex(plane: GLenum, equation: *const GLfixed) {
    with_context("glClipPlanex", (), |c| {
        // SAFETY: the caller passes four values.
        if let Some(eq) = unsafe { valid_params(c, clip_plane_count(plane), equation) } {
            c.clip_plane(plane, [eq[0], eq[1], eq[2], eq[3]].map(fx))
        }
    })
}

/// # Safety
/// A non-null `equation` must have room for four values.
#[no_mangle]
pub unsafe extern "C" fn glGetClipPlanef(plane: GLenum, equation: *mut GLfloat) {
    with_context("glGetClipPlanef", (), |c| {
        if let Some(eq) = c.get_clip_plane(plane) {
            // SAFETY: the caller provides room for four values.
            unsafe { write_values(equation, eq.into_iter()) }
        }
    })
}

/// # Safety
/// A non-null `equation` must have room for four values.
#[no_mangle]
pub unsafe extern "C" fn glGetClipPlanex(plane: GLenum, equation: *mut GLfixed) {
    with_context("glGetClipPlanex", (), |c| {
        if let Some(eq) = c.get_clip_plane(plane) {
            // SAFETY: the caller provides room for four values.
            unsafe { write_values(equation, eq.into_iter().map(from_f32)) }
        }
    })
}
