//! The reference per-fragment operations: the specification's sequence written out per
//! fragment in f64 (ES 1.1 §4.1), independent of `core::fragment`. Where the specification
//! leaves a choice to the implementation (the precision of the alpha test, the dither
//! pattern) this follows the documented choices of the fast path, so the two are comparable.

use glam::DVec4;

use crate::state::{BlendEquation, BlendFactor, RenderState, StencilOp};
use crate::target::{expand_to_8, keep_mask, ColorFormat, TargetFormat};

/// The buffers of one pixel.
pub struct Pixel<'a> {
    pub color: &'a mut u32,
    pub depth: Option<&'a mut u32>,
    pub stencil: Option<&'a mut u8>,
}

/// Runs one fragment at window pixel (x, y) with color `c` and depth `z` (polygon offset
/// applied) through the tests and into `px`.
pub fn process(
    state: &RenderState,
    format: TargetFormat,
    x: i32,
    y: i32,
    c: DVec4,
    z: f64,
    px: Pixel<'_>,
) {
    let c = c.clamp(DVec4::ZERO, DVec4::ONE);
    if let Some(a) = state.alpha_test {
        let q = |v: f64| (v.clamp(0.0, 1.0) * 255.0).round() as u8;
        if !a.func.test(q(c.w), q(a.reference as f64)) {
            return;
        }
    }
    let writemask = state.stencil_writemask as u8;
    let mut stencil = px.stencil;
    let stencil_op = |op: StencilOp, s: &mut u8, reference: u8| {
        let v = match op {
            StencilOp::Keep => *s,
            StencilOp::Zero => 0,
            StencilOp::Replace => reference,
            StencilOp::Incr => {
                if *s == 255 {
                    255
                } else {
                    *s + 1
                }
            }
            StencilOp::Decr => {
                if *s == 0 {
                    0
                } else {
                    *s - 1
                }
            }
            StencilOp::Invert => !*s,
            StencilOp::IncrWrap => ((*s as u32 + 1) % 256) as u8,
            StencilOp::DecrWrap => ((*s as u32 + 255) % 256) as u8,
        };
        *s = (*s & !writemask) | (v & writemask);
    };
    let st = state.stencil_test.filter(|_| stencil.is_some());
    if let (Some(t), Some(s)) = (st, stencil.as_deref_mut()) {
        let reference = t.reference.clamp(0, 255) as u8;
        let m = t.mask as u8;
        if !t.func.test(reference & m, *s & m) {
            stencil_op(t.fail, s, reference);
            return;
        }
    }
    if let (Some(func), Some(df), Some(d)) = (state.depth_test, format.depth, px.depth) {
        let zq = (z.clamp(0.0, 1.0) * df.max() as f64).round() as u32;
        if !func.test(zq, *d) {
            if let (Some(t), Some(s)) = (st, stencil.as_deref_mut()) {
                stencil_op(t.depth_fail, s, t.reference.clamp(0, 255) as u8);
            }
            return;
        }
        if state.depth_write {
            *d = zq;
        }
    }
    if let (Some(t), Some(s)) = (st, stencil) {
        stencil_op(t.depth_pass, s, t.reference.clamp(0, 255) as u8);
    }
    let keep = keep_mask(state.color_mask);
    if keep == u32::MAX {
        return;
    }
    let bits = format.color.bits();
    let max = |i: usize| ((1u32 << bits[i]) - 1) as f64;
    let stored = px.color.to_le_bytes();
    let dst = DVec4::from_array(std::array::from_fn(|i| {
        if bits[i] == 0 {
            1.0
        } else {
            (stored[i] >> (8 - bits[i])) as f64 / max(i)
        }
    }));
    let mut out = c;
    if let Some(b) = state.blend.filter(|_| state.logic_op.is_none()) {
        let f = |f: BlendFactor, i: usize| -> f64 {
            match f {
                BlendFactor::Zero => 0.0,
                BlendFactor::One => 1.0,
                BlendFactor::SrcColor => c[i],
                BlendFactor::OneMinusSrcColor => 1.0 - c[i],
                BlendFactor::DstColor => dst[i],
                BlendFactor::OneMinusDstColor => 1.0 - dst[i],
                BlendFactor::SrcAlpha => c.w,
                BlendFactor::OneMinusSrcAlpha => 1.0 - c.w,
                BlendFactor::DstAlpha => dst.w,
                BlendFactor::OneMinusDstAlpha => 1.0 - dst.w,
                BlendFactor::SrcAlphaSaturate if i == 3 => 1.0,
                BlendFactor::SrcAlphaSaturate => c.w.min(1.0 - dst.w),
            }
        };
        for i in 0..4 {
            let (sf, df, eq) = if i < 3 {
                (b.src_rgb, b.dst_rgb, b.eq_rgb)
            } else {
                (b.src_alpha, b.dst_alpha, b.eq_alpha)
            };
            let (s, d) = (c[i] * f(sf, i), dst[i] * f(df, i));
            out[i] = match eq {
                BlendEquation::Add => s + d,
                BlendEquation::Subtract => s - d,
                BlendEquation::ReverseSubtract => d - s,
                BlendEquation::Min => c[i].min(dst[i]),
                BlendEquation::Max => c[i].max(dst[i]),
            }
            .clamp(0.0, 1.0);
        }
    }
    let dithers = state.dither && format.color == ColorFormat::Rgb565;
    const BAYER: [[u8; 4]; 4] = [[0, 8, 2, 10], [12, 4, 14, 6], [3, 11, 1, 9], [15, 7, 13, 5]];
    let threshold = (BAYER[(y & 3) as usize][(x & 3) as usize] as f64 + 0.5) / 16.0;
    let mut word = [255u8; 4];
    for i in 0..4 {
        if bits[i] == 0 {
            continue;
        }
        let v = if dithers {
            (out[i] * max(i) + threshold).floor().min(max(i))
        } else {
            (out[i] * max(i)).round()
        } as u32;
        let v = match state.logic_op {
            Some(op) => op.apply(v, (stored[i] >> (8 - bits[i])) as u32) & max(i) as u32,
            None => v,
        };
        word[i] = expand_to_8(v, bits[i]);
    }
    let word = u32::from_le_bytes(word);
    *px.color = (*px.color & keep) | (word & !keep);
}
