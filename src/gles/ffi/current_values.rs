//! Current normal and texture coordinates, texture unit selection, the normal, texture
//! coordinate and point size arrays, and `glGetPointerv`.

use crate::gles::arrays::ArrayKind;
use crate::gles::types::*;
use gles_cm_core::fixed::to_f32 as fx;

use super::{client_ptr, with_context};

#[no_mangle]
pub extern "C" fn glNormal3f(nx: GLfloat, ny: GLfloat, nz: GLfloat) {
    with_context("glNormal3f", (), |c| c.normal([nx, ny, nz]))
}

#[no_mangle]
pub extern "C" fn glNormal3x(nx: GLfixed, ny: GLfixed, nz: GLfixed) {
    with_context("glNormal3x", (), |c| c.normal([fx(nx), fx(ny), fx(nz)]))
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord4f(
    target: GLenum,
    s: GLfloat,
    t: GLfloat,
    r: GLfloat,
    q: GLfloat,
) {
    with_context("glMultiTexCoord4f", (), |c| {
        c.multi_tex_coord(target, [s, t, r, q])
    })
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord4x(
    target: GLenum,
    s: GLfixed,
    t: GLfixed,
    r: GLfixed,
    q: GLfixed,
) {
    with_context("glMultiTexCoord4x", (), |c| {
        c.multi_tex_coord(target, [fx(s), fx(t), fx(r), fx(q)])
    })
}

#[no_mangle]
pub extern "C" fn glActiveTexture(texture: GLenum) {
    with_context("glActiveTexture", (), |c| c.active_texture(texture))
}

#[no_mangle]
pub extern "C" fn glClientActiveTexture(texture: GLenum) {
    with_context("glClientActiveTexture", (), |c| {
        c.client_active_texture(texture)
    })
}

#[no_mangle]
pub extern "C" fn glNormalPointer(ty: GLenum, stride: GLsizei, ptr: *const GLvoid) {
    with_context("glNormalPointer", (), |c| {
        c.array_pointer(ArrayKind::Normal, 3, ty, stride, client_ptr(ptr))
    })
}

#[no_mangle]
pub extern "C" fn glTexCoordPointer(size: GLint, ty: GLenum, stride: GLsizei, ptr: *const GLvoid) {
    with_context("glTexCoordPointer", (), |c| {
        c.array_pointer(ArrayKind::TexCoord, size, ty, stride, client_ptr(ptr))
    })
}

#[no_mangle]
pub extern "C" fn glPointSizePointerOES(ty: GLenum, stride: GLsizei, ptr: *const GLvoid) {
    with_context("glPointSizePointerOES", (), |c| {
        c.array_pointer(ArrayKind::PointSize, 1, ty, stride, client_ptr(ptr))
    })
}

/// # Safety
/// A non-null `params` must have room for one pointer.
#[no_mangle]
pub unsafe extern "C" fn glGetPointerv(pname: GLenum, params: *mut *mut GLvoid) {
    with_context("glGetPointerv", (), |c| {
        if let Some(p) = c.get_pointer(pname) {
            if !params.is_null() {
                // SAFETY: non-null, and by the caller's contract room for one pointer.
                unsafe { params.write_unaligned(p as *mut GLvoid) }
            }
        }
    })
}
