//! Per-fragment operation state (ES 1.1 §4.1) and the polygon offset (§3.5.5): alpha test,
//! stencil test, blending, logic op, sample coverage, and their translation into the core's
//! [`RenderState`]. Sample coverage has no effect: no config has sample buffers.
#![forbid(unsafe_code)]

use gles_cm_core::state::{
    AlphaTest, Blend, BlendEquation, BlendFactor, LogicOp, PolygonOffset, StencilOp, StencilTest,
};
use gles_cm_core::{CompareFunc, RenderState};

use super::context::{compare_func, compare_func_enum, Context};
use super::get::Value;
use super::params::clamp01;
use super::tokens::*;
use super::tokens_ext::*;
use super::types::*;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FragmentState {
    pub alpha_func: CompareFunc,
    /// Clamped to [0, 1] when specified.
    pub alpha_ref: f32,
    /// Blend factors for color and alpha (`glBlendFunc` sets both pairs;
    /// `OES_blend_func_separate` each), as their enumerants.
    pub blend_src: GLenum,
    pub blend_dst: GLenum,
    pub blend_src_alpha: GLenum,
    pub blend_dst_alpha: GLenum,
    /// `OES_blend_subtract` / `OES_blend_equation_separate` equations for color and alpha.
    pub blend_eq: GLenum,
    pub blend_eq_alpha: GLenum,
    pub logic_op: GLenum,
    pub stencil_func: CompareFunc,
    /// As given; clamped to [0, 2^s - 1] where it is used and queried.
    pub stencil_ref: i32,
    pub stencil_value_mask: u32,
    pub stencil_fail: GLenum,
    pub stencil_pass_depth_fail: GLenum,
    pub stencil_pass_depth_pass: GLenum,
    /// Clamped to [0, 1] when specified.
    pub sample_coverage_value: f32,
    pub sample_coverage_invert: bool,
    pub polygon_offset_factor: f32,
    pub polygon_offset_units: f32,
    /// `EXT_polygon_offset_clamp`.
    pub polygon_offset_clamp: f32,
}

impl Default for FragmentState {
    fn default() -> FragmentState {
        FragmentState {
            alpha_func: CompareFunc::Always,
            alpha_ref: 0.0,
            blend_src: GL_ONE,
            blend_dst: GL_ZERO,
            blend_src_alpha: GL_ONE,
            blend_dst_alpha: GL_ZERO,
            blend_eq: GL_FUNC_ADD_OES,
            blend_eq_alpha: GL_FUNC_ADD_OES,
            logic_op: GL_COPY,
            stencil_func: CompareFunc::Always,
            stencil_ref: 0,
            stencil_value_mask: u32::MAX,
            stencil_fail: GL_KEEP,
            stencil_pass_depth_fail: GL_KEEP,
            stencil_pass_depth_pass: GL_KEEP,
            sample_coverage_value: 1.0,
            sample_coverage_invert: false,
            polygon_offset_factor: 0.0,
            polygon_offset_units: 0.0,
            polygon_offset_clamp: 0.0,
        }
    }
}

/// Source factors of `glBlendFunc` (ES 1.1 table 4.1).
fn is_blend_src(f: GLenum) -> bool {
    matches!(
        f,
        GL_ZERO
            | GL_ONE
            | GL_DST_COLOR
            | GL_ONE_MINUS_DST_COLOR
            | GL_SRC_ALPHA
            | GL_ONE_MINUS_SRC_ALPHA
            | GL_DST_ALPHA
            | GL_ONE_MINUS_DST_ALPHA
            | GL_SRC_ALPHA_SATURATE
    )
}

/// Destination factors of `glBlendFunc` (ES 1.1 table 4.1).
fn is_blend_dst(f: GLenum) -> bool {
    matches!(
        f,
        GL_ZERO
            | GL_ONE
            | GL_SRC_COLOR
            | GL_ONE_MINUS_SRC_COLOR
            | GL_SRC_ALPHA
            | GL_ONE_MINUS_SRC_ALPHA
            | GL_DST_ALPHA
            | GL_ONE_MINUS_DST_ALPHA
    )
}

/// `glStencilOp` operations, with `OES_stencil_wrap`'s two.
fn is_stencil_op(op: GLenum) -> bool {
    matches!(
        op,
        GL_KEEP
            | GL_ZERO
            | GL_REPLACE
            | GL_INCR
            | GL_DECR
            | GL_INVERT
            | GL_INCR_WRAP_OES
            | GL_DECR_WRAP_OES
    )
}

fn blend_equation(mode: GLenum) -> Option<BlendEquation> {
    Some(match mode {
        GL_FUNC_ADD_OES => BlendEquation::Add,
        GL_FUNC_SUBTRACT_OES => BlendEquation::Subtract,
        GL_FUNC_REVERSE_SUBTRACT_OES => BlendEquation::ReverseSubtract,
        GL_MIN_EXT => BlendEquation::Min,
        GL_MAX_EXT => BlendEquation::Max,
        _ => return None,
    })
}

impl Context {
    pub fn alpha_func(&mut self, func: GLenum, reference: f32) {
        match compare_func(func) {
            Some(f) => {
                self.fragment.alpha_func = f;
                self.fragment.alpha_ref = clamp01(reference);
            }
            None => self.bad_enum("func", func),
        }
    }

    pub fn blend_func(&mut self, src: GLenum, dst: GLenum) {
        if !is_blend_src(src) || !is_blend_dst(dst) {
            return self.set_error(GL_INVALID_ENUM);
        }
        self.blend_func_separate(src, dst, src, dst);
    }

    /// `glBlendFuncSeparateOES`: the factor sets are those of `glBlendFunc`.
    pub fn blend_func_separate(&mut self, src: GLenum, dst: GLenum, src_a: GLenum, dst_a: GLenum) {
        if !is_blend_src(src) || !is_blend_dst(dst) || !is_blend_src(src_a) || !is_blend_dst(dst_a)
        {
            return self.set_error(GL_INVALID_ENUM);
        }
        let s = &mut self.fragment;
        (
            s.blend_src,
            s.blend_dst,
            s.blend_src_alpha,
            s.blend_dst_alpha,
        ) = (src, dst, src_a, dst_a);
    }

    /// `glBlendEquationSeparateOES` (and `glBlendEquationOES` with one mode for both).
    pub fn blend_equation(&mut self, rgb: GLenum, alpha: GLenum) {
        if blend_equation(rgb).is_none() || blend_equation(alpha).is_none() {
            return self.set_error(GL_INVALID_ENUM);
        }
        (self.fragment.blend_eq, self.fragment.blend_eq_alpha) = (rgb, alpha);
    }

    pub fn logic_op(&mut self, op: GLenum) {
        if !(GL_CLEAR..=GL_SET).contains(&op) {
            return self.bad_enum("opcode", op);
        }
        self.fragment.logic_op = op;
    }

    pub fn stencil_func(&mut self, func: GLenum, reference: i32, mask: u32) {
        let Some(f) = compare_func(func) else {
            return self.bad_enum("func", func);
        };
        let s = &mut self.fragment;
        s.stencil_func = f;
        s.stencil_ref = reference;
        s.stencil_value_mask = mask;
    }

    pub fn stencil_op(&mut self, fail: GLenum, zfail: GLenum, zpass: GLenum) {
        if !is_stencil_op(fail) || !is_stencil_op(zfail) || !is_stencil_op(zpass) {
            return self.set_error(GL_INVALID_ENUM);
        }
        let s = &mut self.fragment;
        s.stencil_fail = fail;
        s.stencil_pass_depth_fail = zfail;
        s.stencil_pass_depth_pass = zpass;
    }

    pub fn sample_coverage(&mut self, value: f32, invert: bool) {
        self.fragment.sample_coverage_value = clamp01(value);
        self.fragment.sample_coverage_invert = invert;
    }

    /// `glPolygonOffset`, which is `glPolygonOffsetClampEXT` with clamp 0
    /// (`EXT_polygon_offset_clamp`).
    pub fn polygon_offset(&mut self, factor: f32, units: f32, clamp: f32) {
        self.fragment.polygon_offset_factor = factor;
        self.fragment.polygon_offset_units = units;
        self.fragment.polygon_offset_clamp = clamp;
    }

    /// The stencil reference value clamped to the draw surface's stencil range.
    pub fn effective_stencil_ref(&self) -> i32 {
        let bits = self.draw_format().map_or(0, |f| f.stencil_bits.min(31));
        let max = ((1i64 << bits) - 1) as i32;
        self.fragment.stencil_ref.clamp(0, max)
    }

    /// The `glGet*` values of this area.
    pub(super) fn fragment_value(&self, pname: GLenum) -> Option<Value> {
        let s = &self.fragment;
        let e = |v: GLenum| Value::int(v as i64);
        Some(match pname {
            GL_ALPHA_TEST_FUNC => e(compare_func_enum(s.alpha_func)),
            GL_ALPHA_TEST_REF => Value::norm(&[s.alpha_ref]),
            GL_BLEND_SRC => e(s.blend_src),
            GL_BLEND_DST => e(s.blend_dst),
            GL_BLEND_SRC_RGB_OES => e(s.blend_src),
            GL_BLEND_DST_RGB_OES => e(s.blend_dst),
            GL_BLEND_SRC_ALPHA_OES => e(s.blend_src_alpha),
            GL_BLEND_DST_ALPHA_OES => e(s.blend_dst_alpha),
            GL_BLEND_EQUATION_RGB_OES => e(s.blend_eq),
            GL_BLEND_EQUATION_ALPHA_OES => e(s.blend_eq_alpha),
            GL_LOGIC_OP_MODE => e(s.logic_op),
            GL_STENCIL_FUNC => e(compare_func_enum(s.stencil_func)),
            GL_STENCIL_REF => Value::int(self.effective_stencil_ref() as i64),
            GL_STENCIL_VALUE_MASK => Value::int(s.stencil_value_mask as i32 as i64),
            GL_STENCIL_FAIL => e(s.stencil_fail),
            GL_STENCIL_PASS_DEPTH_FAIL => e(s.stencil_pass_depth_fail),
            GL_STENCIL_PASS_DEPTH_PASS => e(s.stencil_pass_depth_pass),
            GL_SAMPLE_COVERAGE_VALUE => Value::floats(&[s.sample_coverage_value]),
            GL_SAMPLE_COVERAGE_INVERT => Value::bools(&[s.sample_coverage_invert]),
            GL_POLYGON_OFFSET_FACTOR => Value::floats(&[s.polygon_offset_factor]),
            GL_POLYGON_OFFSET_UNITS => Value::floats(&[s.polygon_offset_units]),
            GL_POLYGON_OFFSET_CLAMP_EXT => Value::floats(&[s.polygon_offset_clamp]),
            _ => return None,
        })
    }
}

/// The core's blend factor for a validated `glBlendFunc` enumerant.
fn blend_factor(f: GLenum) -> BlendFactor {
    match f {
        GL_ZERO => BlendFactor::Zero,
        GL_SRC_COLOR => BlendFactor::SrcColor,
        GL_ONE_MINUS_SRC_COLOR => BlendFactor::OneMinusSrcColor,
        GL_DST_COLOR => BlendFactor::DstColor,
        GL_ONE_MINUS_DST_COLOR => BlendFactor::OneMinusDstColor,
        GL_SRC_ALPHA => BlendFactor::SrcAlpha,
        GL_ONE_MINUS_SRC_ALPHA => BlendFactor::OneMinusSrcAlpha,
        GL_DST_ALPHA => BlendFactor::DstAlpha,
        GL_ONE_MINUS_DST_ALPHA => BlendFactor::OneMinusDstAlpha,
        GL_SRC_ALPHA_SATURATE => BlendFactor::SrcAlphaSaturate,
        _ => BlendFactor::One,
    }
}

fn stencil_op(op: GLenum) -> StencilOp {
    match op {
        GL_ZERO => StencilOp::Zero,
        GL_REPLACE => StencilOp::Replace,
        GL_INCR => StencilOp::Incr,
        GL_DECR => StencilOp::Decr,
        GL_INVERT => StencilOp::Invert,
        GL_INCR_WRAP_OES => StencilOp::IncrWrap,
        GL_DECR_WRAP_OES => StencilOp::DecrWrap,
        _ => StencilOp::Keep,
    }
}

fn logic_op(op: GLenum) -> LogicOp {
    const OPS: [LogicOp; 16] = [
        LogicOp::Clear,
        LogicOp::And,
        LogicOp::AndReverse,
        LogicOp::Copy,
        LogicOp::AndInverted,
        LogicOp::Noop,
        LogicOp::Xor,
        LogicOp::Or,
        LogicOp::Nor,
        LogicOp::Equiv,
        LogicOp::Invert,
        LogicOp::OrReverse,
        LogicOp::CopyInverted,
        LogicOp::OrInverted,
        LogicOp::Nand,
        LogicOp::Set,
    ];
    // GL_CLEAR .. GL_SET are consecutive, in this order.
    OPS.get(op.wrapping_sub(GL_CLEAR) as usize)
        .copied()
        .unwrap_or(LogicOp::Copy)
}

impl Context {
    /// Fills in the per-fragment part of `rs` from the enables and this area's state.
    pub(super) fn fragment_render_state(&self, rs: &mut RenderState) {
        let (e, s) = (&self.enables, &self.fragment);
        rs.alpha_test = e.alpha_test.then_some(AlphaTest {
            func: s.alpha_func,
            reference: s.alpha_ref,
        });
        rs.stencil_test = e.stencil_test.then_some(StencilTest {
            func: s.stencil_func,
            reference: self.effective_stencil_ref(),
            mask: s.stencil_value_mask,
            fail: stencil_op(s.stencil_fail),
            depth_fail: stencil_op(s.stencil_pass_depth_fail),
            depth_pass: stencil_op(s.stencil_pass_depth_pass),
        });
        let eq = |m| blend_equation(m).unwrap_or(BlendEquation::Add);
        rs.blend = e.blend.then(|| Blend {
            src_rgb: blend_factor(s.blend_src),
            dst_rgb: blend_factor(s.blend_dst),
            src_alpha: blend_factor(s.blend_src_alpha),
            dst_alpha: blend_factor(s.blend_dst_alpha),
            eq_rgb: eq(s.blend_eq),
            eq_alpha: eq(s.blend_eq_alpha),
        });
        rs.logic_op = e.color_logic_op.then(|| logic_op(s.logic_op));
        rs.polygon_offset = e.polygon_offset_fill.then_some(PolygonOffset {
            factor: s.polygon_offset_factor,
            units: s.polygon_offset_units,
            clamp: s.polygon_offset_clamp,
        });
        rs.multisample = gles_cm_core::multisample::Multisample {
            enabled: e.multisample,
            coverage: e
                .sample_coverage
                .then_some((s.sample_coverage_value, s.sample_coverage_invert)),
            alpha_to_coverage: e.sample_alpha_to_coverage,
            alpha_to_one: e.sample_alpha_to_one,
        };
    }
}
