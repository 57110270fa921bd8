//! `OES_framebuffer_object`: framebuffer and renderbuffer objects.

use crate::gles::types::*;

use super::texture::names;
use super::{read_slice, with_context, write_values};

/// # Safety
/// A non-null `framebuffers` must have room for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glGenFramebuffersOES(n: GLsizei, framebuffers: *mut GLuint) {
    with_context("glGenFramebuffersOES", (), |c| {
        let v = c.gen_framebuffers(n);
        // SAFETY: the application provides room for `n` names.
        unsafe { write_values(framebuffers, v.into_iter()) }
    })
}

/// # Safety
/// A non-null `framebuffers` must point to `n` names.
#[no_mangle]
pub unsafe extern "C" fn glDeleteFramebuffersOES(n: GLsizei, framebuffers: *const GLuint) {
    with_context("glDeleteFramebuffersOES", (), |c| {
        // SAFETY: the application passes `n` names.
        c.delete_framebuffers(n, unsafe { names(n, framebuffers) })
    })
}

#[no_mangle]
pub extern "C" fn glBindFramebufferOES(target: GLenum, framebuffer: GLuint) {
    with_context("glBindFramebufferOES", (), |c| {
        c.bind_framebuffer(target, framebuffer)
    })
}

#[no_mangle]
pub extern "C" fn glIsFramebufferOES(framebuffer: GLuint) -> GLboolean {
    with_context("glIsFramebufferOES", 0, |c| {
        GLboolean::from(c.is_framebuffer(framebuffer))
    })
}

/// # Safety
/// A non-null `renderbuffers` must have room for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glGenRenderbuffersOES(n: GLsizei, renderbuffers: *mut GLuint) {
    with_context("glGenRenderbuffersOES", (), |c| {
        let v = c.gen_renderbuffers(n);
        // SAFETY: the application provides room for `n` names.
        unsafe { write_values(renderbuffers, v.into_iter()) }
    })
}

/// # Safety
/// A non-null `renderbuffers` must point to `n` names.
#[no_mangle]
pub unsafe extern "C" fn glDeleteRenderbuffersOES(n: GLsizei, renderbuffers: *const GLuint) {
    with_context("glDeleteRenderbuffersOES", (), |c| {
        // SAFETY: the application passes `n` names.
        c.delete_renderbuffers(n, unsafe { names(n, renderbuffers) })
    })
}

#[no_mangle]
pub extern "C" fn glBindRenderbufferOES(target: GLenum, renderbuffer: GLuint) {
    with_context("glBindRenderbufferOES", (), |c| {
        c.bind_renderbuffer(target, renderbuffer)
    })
}

#[no_mangle]
pub extern "C" fn glIsRenderbufferOES(renderbuffer: GLuint) -> GLboolean {
    with_context("glIsRenderbufferOES", 0, |c| {
        GLboolean::from(c.is_renderbuffer(renderbuffer))
    })
}

#[no_mangle]
pub extern "C" fn glRenderbufferStorageOES(
    target: GLenum,
    internalformat: GLenum,
    width: GLsizei,
    height: GLsizei,
) {
    with_context("glRenderbufferStorageOES", (), |c| {
        c.renderbuffer_storage(target, internalformat, width, height)
    })
}

/// # Safety
/// A non-null `params` must have room for one value.
#[no_mangle]
pub unsafe extern "C" fn glGetRenderbufferParameterivOES(
    target: GLenum,
    pname: GLenum,
    params: *mut GLint,
) {
    with_context("glGetRenderbufferParameterivOES", (), |c| {
        if let Some(v) = c.get_renderbuffer_parameter(target, pname) {
            // SAFETY: the application provides room for one value.
            unsafe { write_values(params, std::iter::once(v)) }
        }
    })
}

#[no_mangle]
pub extern "C" fn glFramebufferRenderbufferOES(
    target: GLenum,
    attachment: GLenum,
    renderbuffertarget: GLenum,
    renderbuffer: GLuint,
) {
    with_context("glFramebufferRenderbufferOES", (), |c| {
        c.framebuffer_renderbuffer(target, attachment, renderbuffertarget, renderbuffer)
    })
}

#[no_mangle]
pub extern "C" fn glFramebufferTexture2DOES(
    target: GLenum,
    attachment: GLenum,
    textarget: GLenum,
    texture: GLuint,
    level: GLint,
) {
    with_context("glFramebufferTexture2DOES", (), |c| {
        c.framebuffer_texture_2d(target, attachment, textarget, texture, level)
    })
}

#[no_mangle]
pub extern "C" fn glCheckFramebufferStatusOES(target: GLenum) -> GLenum {
    with_context("glCheckFramebufferStatusOES", 0, |c| {
        c.check_framebuffer_status(target)
    })
}

/// # Safety
/// A non-null `params` must have room for one value.
#[no_mangle]
pub unsafe extern "C" fn glGetFramebufferAttachmentParameterivOES(
    target: GLenum,
    attachment: GLenum,
    pname: GLenum,
    params: *mut GLint,
) {
    with_context("glGetFramebufferAttachmentParameterivOES", (), |c| {
        if let Some(v) = c.get_framebuffer_attachment_parameter(target, attachment, pname) {
            // SAFETY: the application provides room for one value.
            unsafe { write_values(params, std::iter::once(v)) }
        }
    })
}

#[no_mangle]
pub extern "C" fn glGenerateMipmapOES(target: GLenum) {
    with_context("glGenerateMipmapOES", (), |c| c.generate_mipmap(target))
}

/// `EXT_discard_framebuffer`.
///
/// # Safety
/// A non-null `attachments` must point to `num_attachments` values.
#[no_mangle]
pub unsafe extern "C" fn glDiscardFramebufferEXT(
    target: GLenum,
    num_attachments: GLsizei,
    attachments: *const GLenum,
) {
    with_context("glDiscardFramebufferEXT", (), |c| {
        if num_attachments < 0 {
            return c.set_error(crate::gles::tokens::GL_INVALID_VALUE);
        }
        // SAFETY: the application passes `num_attachments` values.
        let list = unsafe { read_slice(attachments, num_attachments as usize) };
        c.discard_framebuffer(target, &list.unwrap_or_default())
    })
}

/// `OES_EGL_image`. The handle is looked up, never dereferenced.
#[no_mangle]
pub extern "C" fn glEGLImageTargetRenderbufferStorageOES(target: GLenum, image: GLeglImageOES) {
    with_context("glEGLImageTargetRenderbufferStorageOES", (), |c| {
        c.egl_image_target_renderbuffer_storage(target, crate::gles::egl_image::get(image as usize))
    })
}
