//! The arguments of the `gl*{f,i,x}[v]` parameter setters and the replies of their dedicated
//! getters (`glGetLightfv`, `glGetTexEnviv`, ...), converted in one place.
//!
//! Setters receive their values untouched as [`Params`]; each state area asks for a value in
//! the form its parameter has: a number, an enumerant or a color component. Fixed-point
//! arguments are converted with `gles_cm_core::fixed` (ARCHITECTURE decision 1), except enumerants,
//! which the `x` commands pass unconverted.
#![forbid(unsafe_code)]

use gles_cm_core::fixed;

use super::get::{Kind, Value};
use super::types::*;

/// The values a `gl*Parameter`-style call passes, as the C caller typed them.
#[derive(Clone, Copy, Debug)]
pub enum Params<'a> {
    Float(&'a [f32]),
    Int(&'a [i32]),
    Fixed(&'a [i32]),
}

impl Params<'_> {
    pub fn len(&self) -> usize {
        match self {
            Params::Float(v) => v.len(),
            Params::Int(v) | Params::Fixed(v) => v.len(),
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Value `i` as a number: integers exactly, fixed-point values converted from 16.16.
    pub fn number(&self, i: usize) -> f32 {
        match self {
            Params::Float(v) => v[i],
            Params::Int(v) => v[i] as f32,
            Params::Fixed(v) => fixed::to_f32(v[i]),
        }
    }

    /// The first `N` values as numbers.
    pub fn numbers<const N: usize>(&self) -> [f32; N] {
        std::array::from_fn(|i| self.number(i))
    }

    /// Value `i` as an enumerant. Integer and fixed-point arguments carry the enumerant's
    /// value itself; a float must be exactly an enumerant's value (`None` otherwise, which
    /// the caller reports as `GL_INVALID_ENUM`).
    pub fn enumerant(&self, i: usize) -> Option<GLenum> {
        match self {
            Params::Float(v) => {
                let f = v[i];
                (f >= 0.0 && f <= u32::MAX as f32 && f.fract() == 0.0).then_some(f as u32)
            }
            Params::Int(v) | Params::Fixed(v) => Some(v[i] as u32),
        }
    }

    /// Value `i` as a color component: integers map linearly from their whole range onto
    /// [-1, 1] (ES 1.1 §2.7 conversion table), the other kinds as numbers.
    pub fn color_component(&self, i: usize) -> f32 {
        match self {
            Params::Int(v) => ((2.0 * v[i] as f64 + 1.0) / (u32::MAX as f64)) as f32,
            _ => self.number(i),
        }
    }

    /// The first four values as a color.
    pub fn color(&self) -> [f32; 4] {
        std::array::from_fn(|i| self.color_component(i))
    }
}

/// Converts a dedicated getter's reply for a `GLfixed` destination. Unlike `glGetFixedv`,
/// the fixed-point parameter getters return enumerants (`Kind::Int` replies) unconverted,
/// mirroring the setters that take them unconverted; numbers and colors become 16.16.
pub fn fixed_reply(v: &Value) -> impl Iterator<Item = GLfixed> + '_ {
    let kind = v.kind;
    v.values().iter().map(move |&x| match kind {
        Kind::Int => x as i32,
        Kind::Bool => x as i32,
        _ => fixed::from_f32(x as f32),
    })
}

/// The integer reply of a dedicated getter: enumerants exactly, numbers rounded, colors
/// mapped onto the whole integer range (as `glGetIntegerv` converts).
pub fn int_reply(v: &Value) -> impl Iterator<Item = GLint> + '_ {
    v.as_integers()
}

/// Clamps to [0, 1]; NaN becomes 0 so it never reaches stored state.
pub fn clamp01(v: f32) -> f32 {
    if v > 0.0 {
        v.min(1.0)
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn conversions_per_kind() {
        assert_eq!(Params::Fixed(&[0x18000]).number(0), 1.5);
        assert_eq!(Params::Int(&[3]).number(0), 3.0);
        assert_eq!(Params::Float(&[2.5]).enumerant(0), None);
        assert_eq!(Params::Float(&[-1.0]).enumerant(0), None);
        assert_eq!(Params::Float(&[8449.0]).enumerant(0), Some(8449));
        assert_eq!(Params::Fixed(&[8449]).enumerant(0), Some(8449));
        assert_eq!(Params::Int(&[i32::MAX]).color_component(0), 1.0);
        assert_eq!(Params::Int(&[i32::MIN]).color_component(0), -1.0);
        assert_eq!(Params::Fixed(&[0x8000]).color_component(0), 0.5);
    }
}
