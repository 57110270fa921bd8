//! Vertex arrays, current values and draw calls.

use crate::gles::arrays::ArrayKind;
use crate::gles::context::Context;
use crate::gles::tokens::*;
use crate::gles::types::*;
use gles_cm_core::fixed::to_f32 as fx;
use gles_cm_core::Indices;

use super::{client_bytes, client_ptr, read_slice, with_context, write_values};

#[no_mangle]
pub extern "C" fn glVertexPointer(size: GLint, ty: GLenum, stride: GLsizei, ptr: *const GLvoid) {
    with_context("glVertexPointer", (), |c| {
        c.array_pointer(ArrayKind::Vertex, size, ty, stride, client_ptr(ptr))
    })
}

#[no_mangle]
pub extern "C" fn glColorPointer(size: GLint, ty: GLenum, stride: GLsizei, ptr: *const GLvoid) {
    with_context("glColorPointer", (), |c| {
        c.array_pointer(ArrayKind::Color, size, ty, stride, client_ptr(ptr))
    })
}

#[no_mangle]
pub extern "C" fn glEnableClientState(array: GLenum) {
    with_context("glEnableClientState", (), |c| c.client_state(array, true))
}

#[no_mangle]
pub extern "C" fn glDisableClientState(array: GLenum) {
    with_context("glDisableClientState", (), |c| c.client_state(array, false))
}

#[no_mangle]
pub extern "C" fn glColor4f(r: GLfloat, g: GLfloat, b: GLfloat, a: GLfloat) {
    with_context("glColor4f", (), |c| c.color([r, g, b, a]))
}

#[no_mangle]
pub extern "C" fn glColor4x(r: GLfixed, g: GLfixed, b: GLfixed, a: GLfixed) {
    with_context("glColor4x", (), |c| c.color([fx(r), fx(g), fx(b), fx(a)]))
}

#[no_mangle]
pub extern "C" fn glColor4ub(r: GLubyte, g: GLubyte, b: GLubyte, a: GLubyte) {
    with_context("glColor4ub", (), |c| {
        c.color([r, g, b, a].map(|v| v as f32 / 255.0))
    })
}

#[no_mangle]
pub extern "C" fn glDrawArrays(mode: GLenum, first: GLint, count: GLsizei) {
    with_context("glDrawArrays", (), |c| c.draw_arrays(mode, first, count))
}

/// # Safety
/// A non-null `indices` must point to `count` indices of type `ty`.
#[no_mangle]
pub unsafe extern "C" fn glDrawElements(
    mode: GLenum,
    count: GLsizei,
    ty: GLenum,
    indices: *const GLvoid,
) {
    // SAFETY: forwarded to the application's contract.
    with_context("glDrawElements", (), |c| unsafe {
        draw_elements(c, mode, count, ty, indices)
    })
}

/// `glDrawElements` on the current context.
///
/// # Safety
/// A non-null `indices` must point to `count` indices of type `ty`.
unsafe fn draw_elements(
    c: &mut Context,
    mode: GLenum,
    count: GLsizei,
    ty: GLenum,
    indices: *const GLvoid,
) {
    let size = match ty {
        GL_UNSIGNED_BYTE => 1,
        GL_UNSIGNED_SHORT => 2,
        // OES_element_index_uint.
        crate::gles::tokens_ext::GL_UNSIGNED_INT => 4,
        _ => return c.set_error(GL_INVALID_ENUM),
    };
    if count < 0 {
        return c.set_error(GL_INVALID_VALUE);
    }
    if !c.buffers.element_array.is_none() {
        // With an element buffer bound, `indices` is a byte offset into it.
        return c.draw_elements_from_buffer(mode, count as usize, size, indices as usize);
    }
    if indices.is_null() || count == 0 {
        // Still validate the mode, as a draw of nothing must.
        return c.draw_elements(mode, Indices::Range { first: 0, count: 0 });
    }
    let n = count as usize;
    // SAFETY: the application passes `count` indices of type `ty` at `indices`.
    let bytes = unsafe { client_bytes(indices as usize, n * size) };
    match size {
        1 => c.draw_elements(mode, Indices::U8(bytes)),
        2 => {
            let shorts: Vec<u16> = bytes
                .chunks_exact(2)
                .map(|b| u16::from_ne_bytes([b[0], b[1]]))
                .collect();
            c.draw_elements(mode, Indices::U16(&shorts));
        }
        _ => {
            let ints: Vec<u32> = bytes
                .chunks_exact(4)
                .map(|b| u32::from_ne_bytes([b[0], b[1], b[2], b[3]]))
                .collect();
            c.draw_elements(mode, Indices::U32(&ints));
        }
    }
}

/// `EXT_multi_draw_arrays`: `primcount` draws, as `glDrawArrays(mode, first[i], count[i])`
/// each (a negative `primcount` is `GL_INVALID_VALUE`).
///
/// # Safety
/// Non-null `first` and `count` must point to `primcount` values each.
#[no_mangle]
pub unsafe extern "C" fn glMultiDrawArraysEXT(
    mode: GLenum,
    first: *const GLint,
    count: *const GLsizei,
    primcount: GLsizei,
) {
    with_context("glMultiDrawArraysEXT", (), |c| {
        if primcount < 0 {
            return c.set_error(GL_INVALID_VALUE);
        }
        let n = primcount as usize;
        // SAFETY: the application passes `primcount` values in each array.
        let (Some(first), Some(count)) = (unsafe { read_slice(first, n) }, unsafe {
            read_slice(count, n)
        }) else {
            return;
        };
        for (f, n) in first.into_iter().zip(count) {
            c.draw_arrays(mode, f, n);
        }
    })
}

/// `EXT_multi_draw_arrays`: `primcount` draws, as `glDrawElements(mode, count[i], ty,
/// indices[i])` each.
///
/// # Safety
/// Non-null `count` and `indices` must point to `primcount` values each, and each
/// `indices[i]` as `glDrawElements` requires.
#[no_mangle]
pub unsafe extern "C" fn glMultiDrawElementsEXT(
    mode: GLenum,
    count: *const GLsizei,
    ty: GLenum,
    indices: *const *const GLvoid,
    primcount: GLsizei,
) {
    with_context("glMultiDrawElementsEXT", (), |c| {
        if primcount < 0 {
            return c.set_error(GL_INVALID_VALUE);
        }
        let n = primcount as usize;
        // SAFETY: the application passes `primcount` values in each array.
        let (Some(count), Some(indices)) = (unsafe { read_slice(count, n) }, unsafe {
            read_slice(indices, n)
        }) else {
            return;
        };
        for (n, i) in count.into_iter().zip(indices) {
            // SAFETY: each `indices[i]` holds `count[i]` indices of type `ty`.
            unsafe { draw_elements(c, mode, n, ty, i) };
        }
    })
}

/// # Safety
/// A non-null `arrays` must have room for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glGenVertexArraysOES(n: GLsizei, arrays: *mut GLuint) {
    with_context("glGenVertexArraysOES", (), |c| {
        let v = c.gen_vertex_arrays(n);
        // SAFETY: the application provides room for `n` names.
        unsafe { write_values(arrays, v.into_iter()) }
    })
}

#[no_mangle]
pub extern "C" fn glBindVertexArrayOES(array: GLuint) {
    with_context("glBindVertexArrayOES", (), |c| c.bind_vertex_array(array))
}

/// # Safety
/// A non-null `arrays` must point to `n` names.
#[no_mangle]
pub unsafe extern "C" fn glDeleteVertexArraysOES(n: GLsizei, arrays: *const GLuint) {
    with_context("glDeleteVertexArraysOES", (), |c| {
        // SAFETY: the application passes `n` names.
        let names = unsafe { read_slice(arrays, n.max(0) as usize) }.unwrap_or_default();
        c.delete_vertex_arrays(n, &names)
    })
}

#[no_mangle]
pub extern "C" fn glIsVertexArrayOES(array: GLuint) -> GLboolean {
    with_context("glIsVertexArrayOES", 0, |c| {
        GLboolean::from(c.is_vertex_array(array))
    })
}
