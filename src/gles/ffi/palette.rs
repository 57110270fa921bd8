//! `OES_matrix_palette` and `OES_query_matrix`.

use crate::gles::arrays::ArrayKind;
use crate::gles::types::*;

use super::{client_ptr, with_context};

#[no_mangle]
pub extern "C" fn glCurrentPaletteMatrixOES(index: GLuint) {
    with_context("glCurrentPaletteMatrixOES", (), |c| {
        c.current_palette_matrix(index)
    })
}

#[no_mangle]
pub extern "C" fn glLoadPaletteFromModelViewMatrixOES() {
    with_context("glLoadPaletteFromModelViewMatrixOES", (), |c| {
        c.load_palette_from_modelview()
    })
}

#[no_mangle]
pub extern "C" fn glMatrixIndexPointerOES(
    size: GLint,
    ty: GLenum,
    stride: GLsizei,
    ptr: *const GLvoid,
) {
    with_context("glMatrixIndexPointerOES", (), |c| {
        c.array_pointer(ArrayKind::MatrixIndex, size, ty, stride, client_ptr(ptr))
    })
}

#[no_mangle]
pub extern "C" fn glWeightPointerOES(size: GLint, ty: GLenum, stride: GLsizei, ptr: *const GLvoid) {
    with_context("glWeightPointerOES", (), |c| {
        c.array_pointer(ArrayKind::Weight, size, ty, stride, client_ptr(ptr))
    })
}

/// `glQueryMatrixxOES`: the current matrix as `mantissa[i] · 2^exponent[i]` (mantissas
/// 16.16); bit i of the result is set when element i is NaN or infinite. Without a current
/// context the status is all ones (nothing was written).
///
/// # Safety
/// Non-null `mantissa` and `exponent` must each have room for 16 values.
#[no_mangle]
pub unsafe extern "C" fn glQueryMatrixxOES(
    mantissa: *mut GLfixed,
    exponent: *mut GLint,
) -> GLbitfield {
    with_context("glQueryMatrixxOES", 0xFFFF, |c| {
        let (m, e, status) = c.query_matrix();
        if !mantissa.is_null() {
            // SAFETY: the caller provides room for 16 values.
            unsafe { std::ptr::copy_nonoverlapping(m.as_ptr(), mantissa, 16) };
        }
        if !exponent.is_null() {
            // SAFETY: as above.
            unsafe { std::ptr::copy_nonoverlapping(e.as_ptr(), exponent, 16) };
        }
        status
    })
}
