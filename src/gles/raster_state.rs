//! Point and line rasterization state (ES 1.1 §3.3, §3.4): widths, sizes and the point
//! parameters of distance attenuation.
#![forbid(unsafe_code)]

use super::context::Context;
use super::get::Value;
use super::params::Params;
use super::tokens::*;
use super::types::*;

/// The implementation's point and line size ranges (the same for aliased and smooth
/// primitives).
pub const ALIASED_POINT_SIZE_RANGE: [f32; 2] = [1.0, 64.0];
pub const SMOOTH_POINT_SIZE_RANGE: [f32; 2] = [1.0, 64.0];
pub const ALIASED_LINE_WIDTH_RANGE: [f32; 2] = [1.0, 64.0];
pub const SMOOTH_LINE_WIDTH_RANGE: [f32; 2] = [1.0, 64.0];

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointLineState {
    pub line_width: f32,
    pub point_size: f32,
    pub point_size_min: f32,
    pub point_size_max: f32,
    pub point_fade_threshold_size: f32,
    /// The a, b, c of the attenuation 1 / (a + b·d + c·d²).
    pub point_distance_attenuation: [f32; 3],
}

impl Default for PointLineState {
    fn default() -> PointLineState {
        PointLineState {
            line_width: 1.0,
            point_size: 1.0,
            point_size_min: 0.0,
            // The largest size either point range allows.
            point_size_max: ALIASED_POINT_SIZE_RANGE[1].max(SMOOTH_POINT_SIZE_RANGE[1]),
            point_fade_threshold_size: 1.0,
            point_distance_attenuation: [1.0, 0.0, 0.0],
        }
    }
}

/// How many values `glPointParameter*v` reads for `pname` (`None`: an invalid name).
pub fn point_parameter_count(pname: GLenum) -> Option<usize> {
    match pname {
        GL_POINT_SIZE_MIN | GL_POINT_SIZE_MAX | GL_POINT_FADE_THRESHOLD_SIZE => Some(1),
        GL_POINT_DISTANCE_ATTENUATION => Some(3),
        _ => None,
    }
}

impl Context {
    /// Widths ≤ 0 are `GL_INVALID_VALUE`; NaN is rejected the same way.
    pub fn line_width(&mut self, width: f32) {
        if width.is_nan() || width <= 0.0 {
            return self.fail(
                GL_INVALID_VALUE,
                super::debug::Why::Rule("width must be greater than 0"),
            );
        }
        self.points_lines.line_width = width;
    }

    pub fn point_size(&mut self, size: f32) {
        if size.is_nan() || size <= 0.0 {
            return self.fail(
                GL_INVALID_VALUE,
                super::debug::Why::Rule("size must be greater than 0"),
            );
        }
        self.points_lines.point_size = size;
    }

    /// `glPointParameter{f,x}[v]`. Single-value calls pass one value, so a vector name
    /// through them is `GL_INVALID_ENUM`. Negative sizes and thresholds are
    /// `GL_INVALID_VALUE`; the attenuation coefficients are not restricted.
    pub fn point_parameter(&mut self, pname: GLenum, p: Params<'_>) {
        if point_parameter_count(pname).is_none_or(|n| p.len() < n) {
            return self.set_error(GL_INVALID_ENUM);
        }
        let s = &mut self.points_lines;
        let slot = match pname {
            GL_POINT_SIZE_MIN => &mut s.point_size_min,
            GL_POINT_SIZE_MAX => &mut s.point_size_max,
            GL_POINT_FADE_THRESHOLD_SIZE => &mut s.point_fade_threshold_size,
            GL_POINT_DISTANCE_ATTENUATION => {
                s.point_distance_attenuation = p.numbers();
                return;
            }
            _ => return self.bad_enum("pname", pname),
        };
        let v = p.number(0);
        if v.is_nan() || v < 0.0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        *slot = v;
    }

    pub(super) fn points_lines_value(&self, pname: GLenum) -> Option<Value> {
        let s = &self.points_lines;
        Some(match pname {
            GL_LINE_WIDTH => Value::floats(&[s.line_width]),
            GL_POINT_SIZE => Value::floats(&[s.point_size]),
            GL_POINT_SIZE_MIN => Value::floats(&[s.point_size_min]),
            GL_POINT_SIZE_MAX => Value::floats(&[s.point_size_max]),
            GL_POINT_FADE_THRESHOLD_SIZE => Value::floats(&[s.point_fade_threshold_size]),
            GL_POINT_DISTANCE_ATTENUATION => Value::floats(&s.point_distance_attenuation),
            GL_ALIASED_POINT_SIZE_RANGE => Value::floats(&ALIASED_POINT_SIZE_RANGE),
            GL_SMOOTH_POINT_SIZE_RANGE => Value::floats(&SMOOTH_POINT_SIZE_RANGE),
            GL_ALIASED_LINE_WIDTH_RANGE => Value::floats(&ALIASED_LINE_WIDTH_RANGE),
            GL_SMOOTH_LINE_WIDTH_RANGE => Value::floats(&SMOOTH_LINE_WIDTH_RANGE),
            _ => return None,
        })
    }
}
