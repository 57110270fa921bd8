//! Per-fragment operations: alpha and stencil tests, blending, logic op, sample coverage,
//! polygon offset.

use crate::gles::types::*;
use gles_cm_core::fixed::to_f32 as fx;

use super::with_context;

#[no_mangle]
pub extern "C" fn glAlphaFunc(func: GLenum, reference: GLclampf) {
    with_context("glAlphaFunc", (), |c| c.alpha_func(func, reference))
}

#[no_mangle]
pub extern "C" fn glAlphaFuncx(func: GLenum, reference: GLclampx) {
    with_context("glAlphaFuncx", (), |c| c.alpha_func(func, fx(reference)))
}

#[no_mangle]
pub extern "C" fn glBlendFunc(sfactor: GLenum, dfactor: GLenum) {
    with_context("glBlendFunc", (), |c| c.blend_func(sfactor, dfactor))
}

#[no_mangle]
pub extern "C" fn glBlendFuncSeparateOES(
    src_rgb: GLenum,
    dst_rgb: GLenum,
    src_alpha: GLenum,
    dst_alpha: GLenum,
) {
    with_context("glBlendFuncSeparateOES", (), |c| {
        c.blend_func_separate(src_rgb, dst_rgb, src_alpha, dst_alpha)
    })
}

#[no_mangle]
pub extern "C" fn glBlendEquationOES(mode: GLenum) {
    with_context("glBlendEquationOES", (), |c| c.blend_equation(mode, mode))
}

#[no_mangle]
pub extern "C" fn glBlendEquationSeparateOES(mode_rgb: GLenum, mode_alpha: GLenum) {
    with_context("glBlendEquationSeparateOES", (), |c| {
        c.blend_equation(mode_rgb, mode_alpha)
    })
}

#[no_mangle]
pub extern "C" fn glLogicOp(opcode: GLenum) {
    with_context("glLogicOp", (), |c| c.logic_op(opcode))
}

#[no_mangle]
pub extern "C" fn glStencilFunc(func: GLenum, reference: GLint, mask: GLuint) {
    with_context("glStencilFunc", (), |c| {
        c.stencil_func(func, reference, mask)
    })
}

#[no_mangle]
pub extern "C" fn glStencilOp(fail: GLenum, zfail: GLenum, zpass: GLenum) {
    with_context("glStencilOp", (), |c| c.stencil_op(fail, zfail, zpass))
}

#[no_mangle]
pub extern "C" fn glSampleCoverage(value: GLclampf, invert: GLboolean) {
    with_context("glSampleCoverage", (), |c| {
        c.sample_coverage(value, invert != 0)
    })
}

#[no_mangle]
pub extern "C" fn glSampleCoveragex(value: GLclampx, invert: GLboolean) {
    with_context("glSampleCoveragex", (), |c| {
        c.sample_coverage(fx(value), invert != 0)
    })
}

#[no_mangle]
pub extern "C" fn glPolygonOffset(factor: GLfloat, units: GLfloat) {
    with_context("glPolygonOffset", (), |c| {
        c.polygon_offset(factor, units, 0.0)
    })
}

#[no_mangle]
pub extern "C" fn glPolygonOffsetx(factor: GLfixed, units: GLfixed) {
    with_context("glPolygonOffsetx", (), |c| {
        c.polygon_offset(fx(factor), fx(units), 0.0)
    })
}

/// `EXT_polygon_offset_clamp`: `glPolygonOffset` whose offset is bounded by `clamp`.
#[no_mangle]
pub extern "C" fn glPolygonOffsetClampEXT(factor: GLfloat, units: GLfloat, clamp: GLfloat) {
    with_context("glPolygonOffsetClampEXT", (), |c| {
        c.polygon_offset(factor, units, clamp)
    })
}
