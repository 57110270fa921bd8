//! Texture objects, parameters and image specification.

#![allow(clippy::too_many_arguments)]

use crate::gles::texture::ParamKind;
use crate::gles::types::*;

use super::{client_bytes, with_context, write_values};

/// Reads `n` names from a C array (none for a null pointer or `n` ≤ 0).
///
/// # Safety
/// A non-null `names` must point to `n` readable names.
pub(super) unsafe fn names<'a>(n: GLsizei, names: *const GLuint) -> &'a [GLuint] {
    if n <= 0 || names.is_null() {
        return &[];
    }
    // SAFETY: the caller guarantees `n` readable names.
    unsafe { std::slice::from_raw_parts(names, n as usize) }
}

/// # Safety
/// A non-null `textures` must have room for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glGenTextures(n: GLsizei, textures: *mut GLuint) {
    with_context("glGenTextures", (), |c| {
        let v = c.gen_textures(n);
        // SAFETY: the application provides room for `n` names.
        unsafe { write_values(textures, v.into_iter()) }
    })
}

/// # Safety
/// A non-null `textures` must point to `n` names.
#[no_mangle]
pub unsafe extern "C" fn glDeleteTextures(n: GLsizei, textures: *const GLuint) {
    with_context("glDeleteTextures", (), |c| {
        // SAFETY: the application passes `n` names.
        c.delete_textures(n, unsafe { names(n, textures) })
    })
}

#[no_mangle]
pub extern "C" fn glBindTexture(target: GLenum, texture: GLuint) {
    with_context("glBindTexture", (), |c| c.bind_texture(target, texture))
}

#[no_mangle]
pub extern "C" fn glIsTexture(texture: GLuint) -> GLboolean {
    with_context("glIsTexture", 0, |c| GLboolean::from(c.is_texture(texture)))
}

#[no_mangle]
pub extern "C" fn glTexParameteri(target: GLenum, pname: GLenum, param: GLint) {
    with_context("glTexParameteri", (), |c| {
        c.tex_parameter(target, pname, &[param as f64], ParamKind::Int, false)
    })
}

#[no_mangle]
pub extern "C" fn glTexParameterf(target: GLenum, pname: GLenum, param: GLfloat) {
    with_context("glTexParameterf", (), |c| {
        c.tex_parameter(target, pname, &[param as f64], ParamKind::Float, false)
    })
}

#[no_mangle]
pub extern "C" fn glTexParameterx(target: GLenum, pname: GLenum, param: GLfixed) {
    with_context("glTexParameterx", (), |c| {
        c.tex_parameter(target, pname, &[param as f64], ParamKind::Fixed, false)
    })
}

/// The number of values `glTexParameter*v` reads for `pname`.
fn param_count(pname: GLenum) -> usize {
    if pname == crate::gles::tokens_ext::GL_TEXTURE_CROP_RECT_OES {
        4
    } else {
        1
    }
}

/// # Safety
/// A non-null `params` must point to the values `pname` takes (4 for the crop rectangle).
unsafe fn read_params<T: Copy + Into<f64>>(pname: GLenum, params: *const T) -> Vec<f64> {
    if params.is_null() {
        return Vec::new();
    }
    (0..param_count(pname))
        // SAFETY: the caller guarantees this many values.
        .map(|i| unsafe { params.add(i).read_unaligned() }.into())
        .collect()
}

/// # Safety
/// A non-null `params` must point to the values `pname` takes (4 for the crop rectangle).
#[no_mangle]
pub unsafe extern "C" fn glTexParameteriv(target: GLenum, pname: GLenum, params: *const GLint) {
    with_context("glTexParameteriv", (), |c| {
        // SAFETY: forwarded to the application's contract.
        let v = unsafe { read_params(pname, params) };
        c.tex_parameter(target, pname, &v, ParamKind::Int, true)
    })
}

/// # Safety
/// A non-null `params` must point to the values `pname` takes (4 for the crop rectangle).
#[no_mangle]
pub unsafe extern "C" fn glTexParameterfv(target: GLenum, pname: GLenum, params: *const GLfloat) {
    with_context("glTexParameterfv", (), |c| {
        // SAFETY: forwarded to the application's contract.
        let v = unsafe { read_params(pname, params) };
        c.tex_parameter(target, pname, &v, ParamKind::Float, true)
    })
}

/// # Safety
/// A non-null `params` must point to the values `pname` takes (4 for the crop rectangle).
#[no_mangle]
pub unsafe extern "C" fn glTexParameterxv(target: GLenum, pname: GLenum, params: *const GLfixed) {
    with_context("glTexParameterxv", (), |c| {
        // SAFETY: forwarded to the application's contract.
        let v = unsafe { read_params(pname, params) };
        c.tex_parameter(target, pname, &v, ParamKind::Fixed, true)
    })
}

/// # Safety
/// A non-null `params` must have room for the values of `pname` (4 for the crop rectangle).
#[no_mangle]
pub unsafe extern "C" fn glGetTexParameteriv(target: GLenum, pname: GLenum, params: *mut GLint) {
    with_context("glGetTexParameteriv", (), |c| {
        if let Some(v) = c.get_tex_parameter(target, pname, ParamKind::Int) {
            // SAFETY: the application provides room for the values.
            unsafe { write_values(params, v.into_iter().map(|x| x as GLint)) }
        }
    })
}

/// # Safety
/// A non-null `params` must have room for the values of `pname` (4 for the crop rectangle).
#[no_mangle]
pub unsafe extern "C" fn glGetTexParameterfv(target: GLenum, pname: GLenum, params: *mut GLfloat) {
    with_context("glGetTexParameterfv", (), |c| {
        if let Some(v) = c.get_tex_parameter(target, pname, ParamKind::Float) {
            // SAFETY: the application provides room for the values.
            unsafe { write_values(params, v.into_iter().map(|x| x as GLfloat)) }
        }
    })
}

/// # Safety
/// A non-null `params` must have room for the values of `pname` (4 for the crop rectangle).
#[no_mangle]
pub unsafe extern "C" fn glGetTexParameterxv(target: GLenum, pname: GLenum, params: *mut GLfixed) {
    with_context("glGetTexParameterxv", (), |c| {
        if let Some(v) = c.get_tex_parameter(target, pname, ParamKind::Fixed) {
            // SAFETY: the application provides room for the values.
            unsafe { write_values(params, v.into_iter().map(|x| x as GLfixed)) }
        }
    })
}

/// # Safety
/// A non-null `pixels` must point to the image laid out by `GL_UNPACK_ALIGNMENT`.
#[no_mangle]
pub unsafe extern "C" fn glTexImage2D(
    target: GLenum,
    level: GLint,
    internalformat: GLint,
    width: GLsizei,
    height: GLsizei,
    border: GLint,
    format: GLenum,
    ty: GLenum,
    pixels: *const GLvoid,
) {
    with_context("glTexImage2D", (), |c| {
        let up = match c.tex_image_2d_layout(
            target,
            level,
            internalformat,
            width,
            height,
            border,
            format,
            ty,
        ) {
            Ok(u) => u,
            Err(e) => return c.set_error(e),
        };
        // SAFETY: the application provides the whole image at a non-null `pixels`.
        let data =
            (!pixels.is_null()).then(|| unsafe { client_bytes(pixels as usize, up.rect.len) });
        c.tex_image_2d(up, data)
    })
}

/// # Safety
/// A non-null `pixels` must point to the region laid out by `GL_UNPACK_ALIGNMENT`.
#[no_mangle]
pub unsafe extern "C" fn glTexSubImage2D(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    yoffset: GLint,
    width: GLsizei,
    height: GLsizei,
    format: GLenum,
    ty: GLenum,
    pixels: *const GLvoid,
) {
    with_context("glTexSubImage2D", (), |c| {
        let up = match c
            .tex_sub_image_2d_layout(target, level, xoffset, yoffset, width, height, format, ty)
        {
            Ok(u) => u,
            Err(e) => return c.set_error(e),
        };
        if pixels.is_null() {
            return;
        }
        // SAFETY: the application provides the whole region at `pixels`.
        let data = unsafe { client_bytes(pixels as usize, up.rect.len) };
        c.tex_sub_image_2d(up, data)
    })
}

/// # Safety
/// A non-null `data` must point to `image_size` readable bytes.
#[no_mangle]
pub unsafe extern "C" fn glCompressedTexImage2D(
    target: GLenum,
    level: GLint,
    internalformat: GLenum,
    width: GLsizei,
    height: GLsizei,
    border: GLint,
    image_size: GLsizei,
    data: *const GLvoid,
) {
    with_context("glCompressedTexImage2D", (), |c| {
        let (format, levels, face) = match c.compressed_tex_image_2d_check(
            target,
            level,
            internalformat,
            width,
            height,
            border,
            image_size,
        ) {
            Ok(v) => v,
            Err(e) => return c.set_error(e),
        };
        // SAFETY: the application provides `image_size` bytes at a non-null `data`.
        let bytes =
            (!data.is_null()).then(|| unsafe { client_bytes(data as usize, image_size as usize) });
        c.compressed_tex_image_2d(face, format, internalformat, levels, width, height, bytes)
    })
}

/// # Safety
/// A non-null `data` must point to `image_size` readable bytes.
#[no_mangle]
pub unsafe extern "C" fn glCompressedTexSubImage2D(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    yoffset: GLint,
    width: GLsizei,
    height: GLsizei,
    format: GLenum,
    image_size: GLsizei,
    data: *const GLvoid,
) {
    with_context("glCompressedTexSubImage2D", (), |c| {
        let update = match c.compressed_tex_sub_image_2d_check(
            target, level, xoffset, yoffset, width, height, format, image_size,
        ) {
            Ok(u) => u,
            Err(e) => return c.set_error(e),
        };
        // SAFETY: the application provides `image_size` bytes at a non-null `data`.
        let bytes =
            (!data.is_null()).then(|| unsafe { client_bytes(data as usize, image_size as usize) });
        c.compressed_tex_sub_image_2d(update, bytes)
    })
}

#[no_mangle]
pub extern "C" fn glCopyTexImage2D(
    target: GLenum,
    level: GLint,
    internalformat: GLenum,
    x: GLint,
    y: GLint,
    width: GLsizei,
    height: GLsizei,
    border: GLint,
) {
    with_context("glCopyTexImage2D", (), |c| {
        c.copy_tex_image_2d(target, level, internalformat, x, y, width, height, border)
    })
}

#[no_mangle]
pub extern "C" fn glCopyTexSubImage2D(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    yoffset: GLint,
    x: GLint,
    y: GLint,
    width: GLsizei,
    height: GLsizei,
) {
    with_context("glCopyTexSubImage2D", (), |c| {
        c.copy_tex_sub_image_2d(target, level, xoffset, yoffset, x, y, width, height)
    })
}

/// `OES_EGL_image`. The handle is looked up, never dereferenced.
#[no_mangle]
pub extern "C" fn glEGLImageTargetTexture2DOES(target: GLenum, image: GLeglImageOES) {
    with_context("glEGLImageTargetTexture2DOES", (), |c| {
        c.egl_image_target_texture_2d(target, crate::gles::egl_image::get(image as usize))
    })
}
