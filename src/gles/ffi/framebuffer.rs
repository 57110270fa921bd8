//! Per-fragment and framebuffer state, clears and read-back.

use crate::gles::types::*;
use gles_cm_core::fixed::to_f32 as fx;

use super::with_context;

fn b(v: GLboolean) -> bool {
    v != 0
}

#[no_mangle]
pub extern "C" fn glClear(mask: GLbitfield) {
    with_context("glClear", (), |c| c.clear(mask))
}

#[no_mangle]
pub extern "C" fn glClearColor(r: GLclampf, g: GLclampf, bl: GLclampf, a: GLclampf) {
    with_context("glClearColor", (), |c| c.clear_color([r, g, bl, a]))
}

#[no_mangle]
pub extern "C" fn glClearColorx(r: GLclampx, g: GLclampx, bl: GLclampx, a: GLclampx) {
    with_context("glClearColorx", (), |c| {
        c.clear_color([fx(r), fx(g), fx(bl), fx(a)])
    })
}

#[no_mangle]
pub extern "C" fn glClearDepthf(depth: GLclampf) {
    with_context("glClearDepthf", (), |c| c.clear_depth(depth))
}

#[no_mangle]
pub extern "C" fn glClearDepthx(depth: GLclampx) {
    with_context("glClearDepthx", (), |c| c.clear_depth(fx(depth)))
}

#[no_mangle]
pub extern "C" fn glClearStencil(s: GLint) {
    with_context("glClearStencil", (), |c| c.clear_stencil(s))
}

#[no_mangle]
pub extern "C" fn glColorMask(r: GLboolean, g: GLboolean, bl: GLboolean, a: GLboolean) {
    with_context("glColorMask", (), |c| {
        c.color_mask([b(r), b(g), b(bl), b(a)])
    })
}

#[no_mangle]
pub extern "C" fn glDepthMask(flag: GLboolean) {
    with_context("glDepthMask", (), |c| c.depth_mask(b(flag)))
}

#[no_mangle]
pub extern "C" fn glStencilMask(mask: GLuint) {
    with_context("glStencilMask", (), |c| c.stencil_mask(mask))
}

#[no_mangle]
pub extern "C" fn glDepthFunc(func: GLenum) {
    with_context("glDepthFunc", (), |c| c.depth_func(func))
}

#[no_mangle]
pub extern "C" fn glDepthRangef(near: GLclampf, far: GLclampf) {
    with_context("glDepthRangef", (), |c| c.depth_range(near, far))
}

#[no_mangle]
pub extern "C" fn glDepthRangex(near: GLclampx, far: GLclampx) {
    with_context("glDepthRangex", (), |c| c.depth_range(fx(near), fx(far)))
}

#[no_mangle]
pub extern "C" fn glViewport(x: GLint, y: GLint, width: GLsizei, height: GLsizei) {
    with_context("glViewport", (), |c| c.viewport(x, y, width, height))
}

#[no_mangle]
pub extern "C" fn glScissor(x: GLint, y: GLint, width: GLsizei, height: GLsizei) {
    with_context("glScissor", (), |c| c.scissor(x, y, width, height))
}

#[no_mangle]
pub extern "C" fn glCullFace(mode: GLenum) {
    with_context("glCullFace", (), |c| c.cull_face(mode))
}

#[no_mangle]
pub extern "C" fn glFrontFace(mode: GLenum) {
    with_context("glFrontFace", (), |c| c.front_face(mode))
}

#[no_mangle]
pub extern "C" fn glShadeModel(mode: GLenum) {
    with_context("glShadeModel", (), |c| c.shade_model(mode))
}

#[no_mangle]
pub extern "C" fn glPixelStorei(pname: GLenum, param: GLint) {
    with_context("glPixelStorei", (), |c| c.pixel_store(pname, param))
}

/// # Safety
/// A non-null `pixels` must have room for the rectangle laid out by `GL_PACK_ALIGNMENT`.
#[no_mangle]
pub unsafe extern "C" fn glReadPixels(
    x: GLint,
    y: GLint,
    width: GLsizei,
    height: GLsizei,
    format: GLenum,
    ty: GLenum,
    pixels: *mut GLvoid,
) {
    with_context("glReadPixels", (), |c| {
        let layout = match c.read_pixels_layout(width, height, format, ty) {
            Ok(l) => l,
            Err(e) => return c.set_error(e),
        };
        if pixels.is_null() || layout.len == 0 {
            return;
        }
        // SAFETY: the application provides `layout.len` writable bytes at `pixels`, the size
        // of the rectangle under the current pack alignment.
        let out = unsafe { std::slice::from_raw_parts_mut(pixels as *mut u8, layout.len) };
        c.read_pixels(x, y, width, height, layout, out);
    })
}
