//! `GL_KHR_debug` entry points: message control, insertion, the callback, the log, debug
//! groups and object labels.

use std::ffi::{c_void, CStr};

use crate::gles::debug::{Message, GLDEBUGPROCKHR};
use crate::gles::types::*;

use super::{read_slice, with_context};

/// The bytes of an application string: `length` bytes at `p`, or up to its terminator when
/// `length` is negative; empty for a null pointer.
///
/// # Safety
/// A non-null `p` must point to `length` readable bytes, or to a NUL-terminated string when
/// `length` is negative.
unsafe fn app_string(p: *const GLchar, length: GLsizei) -> Vec<u8> {
    if p.is_null() {
        return Vec::new();
    }
    if length < 0 {
        // SAFETY: non-null and, by the caller's contract, NUL-terminated.
        return unsafe { CStr::from_ptr(p) }.to_bytes().to_vec();
    }
    // SAFETY: non-null and, by the caller's contract, `length` readable bytes.
    unsafe { read_slice(p as *const u8, length as usize) }.unwrap_or_default()
}

/// Writes `text` and a terminator at `dst`, cut to `room` bytes in all.
///
/// # Safety
/// A non-null `dst` must have room for `room` bytes.
unsafe fn write_string(dst: *mut GLchar, room: usize, text: &[u8]) -> usize {
    if dst.is_null() || room == 0 {
        return 0;
    }
    let n = text.len().min(room - 1);
    // SAFETY: n + 1 <= room bytes, which the caller guarantees writable.
    unsafe {
        std::ptr::copy_nonoverlapping(text.as_ptr(), dst as *mut u8, n);
        dst.add(n).write(0);
    }
    n
}

/// Calls the application's callback with each message, in order (the context is unlocked).
pub(super) fn deliver(callback: GLDEBUGPROCKHR, user: usize, messages: Vec<Message>) {
    let Some(f) = callback else {
        return;
    };
    for m in messages {
        let mut text = m.text.into_bytes();
        let len = text.len();
        text.push(0);
        // SAFETY: the application installed `f` with glDebugMessageCallbackKHR as a
        // GLDEBUGPROCKHR; the message is NUL-terminated and lives through the call.
        unsafe {
            f(
                m.source,
                m.ty,
                m.id,
                m.severity,
                len as GLsizei,
                text.as_ptr() as *const GLchar,
                user as *const c_void,
            )
        };
    }
}

/// # Safety
/// A non-null `ids` must point to `count` readable names.
#[no_mangle]
pub unsafe extern "C" fn glDebugMessageControlKHR(
    source: GLenum,
    ty: GLenum,
    severity: GLenum,
    count: GLsizei,
    ids: *const GLuint,
    enabled: GLboolean,
) {
    with_context("glDebugMessageControlKHR", (), |c| {
        // SAFETY: the caller's contract for `ids`.
        let ids = unsafe { read_slice(ids, count.max(0) as usize) }.unwrap_or_default();
        c.debug_message_control(source, ty, severity, count, &ids, enabled != 0)
    })
}

/// # Safety
/// `buf` must be a NUL-terminated string when `length` is negative, else `length` readable
/// bytes.
#[no_mangle]
pub unsafe extern "C" fn glDebugMessageInsertKHR(
    source: GLenum,
    ty: GLenum,
    id: GLuint,
    severity: GLenum,
    length: GLsizei,
    buf: *const GLchar,
) {
    with_context("glDebugMessageInsertKHR", (), |c| {
        // SAFETY: the caller's contract for `buf`.
        let text = unsafe { app_string(buf, length) };
        c.debug_message_insert(source, ty, id, severity, length, &text)
    })
}

#[no_mangle]
pub extern "C" fn glDebugMessageCallbackKHR(callback: GLDEBUGPROCKHR, user_param: *const c_void) {
    with_context("glDebugMessageCallbackKHR", (), |c| {
        c.debug.callback = callback;
        c.debug.user_param = user_param as usize;
    })
}

/// # Safety
/// Each non-null array must have room for `count` values; a non-null `message_log` for
/// `buf_size` bytes.
#[no_mangle]
pub unsafe extern "C" fn glGetDebugMessageLogKHR(
    count: GLuint,
    buf_size: GLsizei,
    sources: *mut GLenum,
    types: *mut GLenum,
    ids: *mut GLuint,
    severities: *mut GLenum,
    lengths: *mut GLsizei,
    message_log: *mut GLchar,
) -> GLuint {
    with_context("glGetDebugMessageLogKHR", 0, |c| {
        let room = (!message_log.is_null()).then_some(buf_size);
        let fetched = c.debug_message_log(count, room);
        let mut at = 0usize;
        for (i, m) in fetched.iter().enumerate() {
            // SAFETY: i < count, and each non-null array has room for count values; the
            // log fetched only messages that fit in buf_size bytes.
            unsafe {
                if !sources.is_null() {
                    sources.add(i).write_unaligned(m.source);
                }
                if !types.is_null() {
                    types.add(i).write_unaligned(m.ty);
                }
                if !ids.is_null() {
                    ids.add(i).write_unaligned(m.id);
                }
                if !severities.is_null() {
                    severities.add(i).write_unaligned(m.severity);
                }
                if !lengths.is_null() {
                    lengths.add(i).write_unaligned(m.text.len() as GLsizei + 1);
                }
                if !message_log.is_null() {
                    at +=
                        write_string(message_log.add(at), m.text.len() + 1, m.text.as_bytes()) + 1;
                }
            }
        }
        fetched.len() as GLuint
    })
}

/// # Safety
/// `message` must be a NUL-terminated string when `length` is negative, else `length`
/// readable bytes.
#[no_mangle]
pub unsafe extern "C" fn glPushDebugGroupKHR(
    source: GLenum,
    id: GLuint,
    length: GLsizei,
    message: *const GLchar,
) {
    with_context("glPushDebugGroupKHR", (), |c| {
        // SAFETY: the caller's contract for `message`.
        let text = unsafe { app_string(message, length) };
        c.push_debug_group(source, id, length, &text)
    })
}

#[no_mangle]
pub extern "C" fn glPopDebugGroupKHR() {
    with_context("glPopDebugGroupKHR", (), |c| c.pop_debug_group())
}

/// # Safety
/// A non-null `label` must be a NUL-terminated string when `length` is negative, else
/// `length` readable bytes.
#[no_mangle]
pub unsafe extern "C" fn glObjectLabelKHR(
    identifier: GLenum,
    name: GLuint,
    length: GLsizei,
    label: *const GLchar,
) {
    with_context("glObjectLabelKHR", (), |c| {
        // SAFETY: the caller's contract for `label`.
        let text = (!label.is_null()).then(|| unsafe { app_string(label, length) });
        c.object_label(identifier, name, length, text.as_deref())
    })
}

/// # Safety
/// A non-null `length` must have room for one value, a non-null `label` for `buf_size`
/// bytes.
#[no_mangle]
pub unsafe extern "C" fn glGetObjectLabelKHR(
    identifier: GLenum,
    name: GLuint,
    buf_size: GLsizei,
    length: *mut GLsizei,
    label: *mut GLchar,
) {
    with_context("glGetObjectLabelKHR", (), |c| {
        let Some(text) = c.object_label_of(identifier, name, buf_size) else {
            return;
        };
        // SAFETY: the caller's contract for `label` and `length`.
        unsafe { return_label(text.as_bytes(), buf_size, length, label) }
    })
}

/// Writes a label for `glGetObject*LabelKHR`: at most `buf_size - 1` characters and a
/// terminator; `length` receives the characters written, or the label's length when
/// `label` is null.
///
/// # Safety
/// As for `glGetObjectLabelKHR`.
unsafe fn return_label(text: &[u8], buf_size: GLsizei, length: *mut GLsizei, label: *mut GLchar) {
    let n = if label.is_null() {
        text.len()
    } else {
        // SAFETY: forwarded to the caller's contract.
        unsafe { write_string(label, buf_size.max(0) as usize, text) }
    };
    if !length.is_null() {
        // SAFETY: non-null, room for one value by the caller's contract.
        unsafe { length.write_unaligned(n as GLsizei) };
    }
}

/// No pointer names an object in OpenGL ES 1.1 (it has no sync objects): always
/// `GL_INVALID_VALUE`, and the label is never read.
#[no_mangle]
pub extern "C" fn glObjectPtrLabelKHR(ptr: *const c_void, length: GLsizei, label: *const GLchar) {
    let _ = (length, label);
    with_context("glObjectPtrLabelKHR", (), |c| {
        c.object_ptr_label(ptr as usize, None)
    })
}

/// As `glObjectPtrLabelKHR`: always an error, and nothing is written.
#[no_mangle]
pub extern "C" fn glGetObjectPtrLabelKHR(
    ptr: *const c_void,
    buf_size: GLsizei,
    length: *mut GLsizei,
    label: *mut GLchar,
) {
    let _ = (length, label);
    with_context("glGetObjectPtrLabelKHR", (), |c| {
        c.object_ptr_label(ptr as usize, Some(buf_size))
    })
}

/// # Safety
/// A non-null `params` must have room for one pointer.
#[no_mangle]
pub unsafe extern "C" fn glGetPointervKHR(pname: GLenum, params: *mut *mut c_void) {
    with_context("glGetPointervKHR", (), |c| {
        if let Some(p) = c.get_pointer(pname) {
            if !params.is_null() {
                // SAFETY: non-null, and by the caller's contract room for one pointer.
                unsafe { params.write_unaligned(p as *mut c_void) }
            }
        }
    })
}
