//! Buffer objects and `OES_mapbuffer`.

use crate::gles::types::*;

use super::{client_bytes, with_context, write_values};

/// # Safety
/// A non-null `buffers` must have room for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glGenBuffers(n: GLsizei, buffers: *mut GLuint) {
    with_context("glGenBuffers", (), |c| {
        let v = c.gen_buffers(n);
        // SAFETY: the application provides room for `n` names.
        unsafe { write_values(buffers, v.into_iter()) }
    })
}

/// # Safety
/// A non-null `buffers` must point to `n` names.
#[no_mangle]
pub unsafe extern "C" fn glDeleteBuffers(n: GLsizei, buffers: *const GLuint) {
    with_context("glDeleteBuffers", (), |c| {
        let names: &[GLuint] = if n <= 0 || buffers.is_null() {
            &[]
        } else {
            // SAFETY: the application passes `n` names.
            unsafe { std::slice::from_raw_parts(buffers, n as usize) }
        };
        c.delete_buffers(n, names)
    })
}

#[no_mangle]
pub extern "C" fn glBindBuffer(target: GLenum, buffer: GLuint) {
    with_context("glBindBuffer", (), |c| c.bind_buffer(target, buffer))
}

#[no_mangle]
pub extern "C" fn glIsBuffer(buffer: GLuint) -> GLboolean {
    with_context("glIsBuffer", 0, |c| GLboolean::from(c.is_buffer(buffer)))
}

/// # Safety
/// A non-null `data` must point to `size` readable bytes.
#[no_mangle]
pub unsafe extern "C" fn glBufferData(
    target: GLenum,
    size: GLsizeiptr,
    data: *const GLvoid,
    usage: GLenum,
) {
    with_context("glBufferData", (), |c| {
        // SAFETY: the application provides `size` bytes at a non-null `data`.
        let bytes = (!data.is_null() && size > 0)
            .then(|| unsafe { client_bytes(data as usize, size as usize) });
        c.buffer_data(target, size, bytes, usage)
    })
}

/// # Safety
/// A non-null `data` must point to `size` readable bytes.
#[no_mangle]
pub unsafe extern "C" fn glBufferSubData(
    target: GLenum,
    offset: GLintptr,
    size: GLsizeiptr,
    data: *const GLvoid,
) {
    with_context("glBufferSubData", (), |c| {
        if size < 0 {
            return c.set_error(crate::gles::tokens::GL_INVALID_VALUE);
        }
        if data.is_null() {
            return c.buffer_sub_data(target, offset, &[]);
        }
        // SAFETY: the application provides `size` bytes at `data`.
        let bytes = unsafe { client_bytes(data as usize, size as usize) };
        c.buffer_sub_data(target, offset, bytes)
    })
}

/// # Safety
/// A non-null `params` must have room for one value.
#[no_mangle]
pub unsafe extern "C" fn glGetBufferParameteriv(target: GLenum, pname: GLenum, params: *mut GLint) {
    with_context("glGetBufferParameteriv", (), |c| {
        if let Some(v) = c.buffer_parameter(target, pname) {
            // SAFETY: the application provides room for one value.
            unsafe { write_values(params, std::iter::once(v)) }
        }
    })
}

#[no_mangle]
pub extern "C" fn glMapBufferOES(target: GLenum, access: GLenum) -> *mut GLvoid {
    with_context("glMapBufferOES", std::ptr::null_mut(), |c| {
        c.map_buffer(target, access)
            .map_or(std::ptr::null_mut(), |p| p as *mut GLvoid)
    })
}

#[no_mangle]
pub extern "C" fn glUnmapBufferOES(target: GLenum) -> GLboolean {
    with_context("glUnmapBufferOES", 0, |c| {
        GLboolean::from(c.unmap_buffer(target))
    })
}

/// # Safety
/// A non-null `params` must have room for one pointer.
#[no_mangle]
pub unsafe extern "C" fn glGetBufferPointervOES(
    target: GLenum,
    pname: GLenum,
    params: *mut *mut GLvoid,
) {
    with_context("glGetBufferPointervOES", (), |c| {
        if let Some(p) = c.buffer_pointer(target, pname) {
            // SAFETY: the application provides room for one pointer.
            unsafe { write_values(params, std::iter::once(p as *mut GLvoid)) }
        }
    })
}

/// `EXT_map_buffer_range`: `length` bytes at `offset` of the bound buffer, or null after an
/// error.
#[no_mangle]
pub extern "C" fn glMapBufferRangeEXT(
    target: GLenum,
    offset: GLintptr,
    length: GLsizeiptr,
    access: GLbitfield,
) -> *mut GLvoid {
    with_context("glMapBufferRangeEXT", std::ptr::null_mut(), |c| {
        c.map_buffer_range(target, offset, length, access)
            .map_or(std::ptr::null_mut(), |p| p as *mut GLvoid)
    })
}

#[no_mangle]
pub extern "C" fn glFlushMappedBufferRangeEXT(
    target: GLenum,
    offset: GLintptr,
    length: GLsizeiptr,
) {
    with_context("glFlushMappedBufferRangeEXT", (), |c| {
        c.flush_mapped_buffer_range(target, offset, length)
    })
}

#[cfg(test)]
mod tests {
    use crate::gles::buffer::lock_objects;
    use crate::gles::context::Context;
    use crate::gles::tokens::*;
    use crate::gles::tokens_ext::*;

    #[test]
    fn a_write_through_the_mapping_reaches_the_store() {
        let mut c = Context::new(None);
        let b = c.gen_buffers(1)[0];
        c.bind_buffer(GL_ARRAY_BUFFER, b);
        c.buffer_data(GL_ARRAY_BUFFER, 4, Some(&[1, 2, 7, 8]), GL_DYNAMIC_DRAW);
        let p = c.map_buffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY_OES).unwrap();
        // SAFETY: the store is 4 bytes and stays put while mapped.
        unsafe { *p = 5 };
        assert!(c.unmap_buffer(GL_ARRAY_BUFFER));
        let o = lock_objects(&c.shared);
        assert_eq!(o.buffers.named(b).unwrap().data(), &[5, 2, 7, 8]);
    }
}
