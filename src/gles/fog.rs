//! Fog state (ES 1.1 §3.8).
#![forbid(unsafe_code)]

use super::context::Context;
use super::get::Value;
use super::params::{clamp01, Params};
use super::tokens::*;
use super::types::*;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fog {
    /// `GL_LINEAR`, `GL_EXP` or `GL_EXP2`.
    pub mode: GLenum,
    pub density: f32,
    pub start: f32,
    pub end: f32,
    /// Clamped to [0, 1] when specified.
    pub color: [f32; 4],
}

impl Default for Fog {
    fn default() -> Fog {
        Fog {
            mode: GL_EXP,
            density: 1.0,
            start: 0.0,
            end: 1.0,
            color: [0.0; 4],
        }
    }
}

/// How many values `glFog*v` reads for `pname` (`None`: an invalid name).
pub fn fog_parameter_count(pname: GLenum) -> Option<usize> {
    match pname {
        GL_FOG_MODE | GL_FOG_DENSITY | GL_FOG_START | GL_FOG_END => Some(1),
        GL_FOG_COLOR => Some(4),
        _ => None,
    }
}

impl Context {
    /// `glFog{f,x}[v]`. A vector name through a single-value call is `GL_INVALID_ENUM`.
    pub fn fog(&mut self, pname: GLenum, p: Params<'_>) {
        if fog_parameter_count(pname).is_none_or(|n| p.len() < n) {
            return self.set_error(GL_INVALID_ENUM);
        }
        let f = &mut self.fog;
        match pname {
            GL_FOG_MODE => match p.enumerant(0) {
                Some(m @ (GL_LINEAR | GL_EXP | GL_EXP2)) => f.mode = m,
                _ => self.set_error(GL_INVALID_ENUM),
            },
            GL_FOG_DENSITY => {
                let d = p.number(0);
                if d.is_nan() || d < 0.0 {
                    return self.set_error(GL_INVALID_VALUE);
                }
                f.density = d;
            }
            GL_FOG_START => f.start = p.number(0),
            GL_FOG_END => f.end = p.number(0),
            GL_FOG_COLOR => f.color = p.color().map(clamp01),
            _ => self.bad_enum("pname", pname),
        }
    }

    pub(super) fn fog_value(&self, pname: GLenum) -> Option<Value> {
        let f = &self.fog;
        Some(match pname {
            GL_FOG_MODE => Value::int(f.mode as i64),
            GL_FOG_DENSITY => Value::floats(&[f.density]),
            GL_FOG_START => Value::floats(&[f.start]),
            GL_FOG_END => Value::floats(&[f.end]),
            GL_FOG_COLOR => Value::norm(&f.color),
            _ => return None,
        })
    }
}
