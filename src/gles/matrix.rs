//! The matrix stacks and the operations on the current matrix.
#![forbid(unsafe_code)]

use glam::{Mat4, Vec3};

use super::context::{
    Context, MatrixMode, MAX_MODELVIEW_STACK_DEPTH, MAX_PALETTE_MATRICES,
    MAX_PROJECTION_STACK_DEPTH, MAX_TEXTURE_STACK_DEPTH,
};
use super::tokens::*;
use super::tokens_ext::*;
use super::types::*;

impl Context {
    fn stack(&mut self) -> (&mut Vec<Mat4>, usize) {
        match self.matrix_mode {
            MatrixMode::Modelview => (&mut self.modelview, MAX_MODELVIEW_STACK_DEPTH),
            MatrixMode::Projection => (&mut self.projection, MAX_PROJECTION_STACK_DEPTH),
            MatrixMode::Texture => (
                &mut self.texture[self.active_texture],
                MAX_TEXTURE_STACK_DEPTH,
            ),
            // The palette has no stack (OES_matrix_palette): see push_matrix.
            MatrixMode::Palette => unreachable!("the palette has no stack"),
        }
    }

    fn current(&mut self) -> &mut Mat4 {
        if self.matrix_mode == MatrixMode::Palette {
            return &mut self.palette[self.current_palette];
        }
        self.stack().0.last_mut().expect("stack never empty")
    }

    /// The current matrix of the current matrix mode.
    pub(super) fn current_matrix(&self) -> Mat4 {
        match self.matrix_mode {
            MatrixMode::Modelview => *self.modelview.last().expect("stack never empty"),
            MatrixMode::Projection => *self.projection.last().expect("stack never empty"),
            MatrixMode::Texture => *self.texture[self.active_texture]
                .last()
                .expect("stack never empty"),
            MatrixMode::Palette => self.palette[self.current_palette],
        }
    }

    /// `glQueryMatrixxOES`: each element of the current matrix as a 16.16 mantissa and a
    /// power-of-two exponent (exact to 2⁻¹⁵ relative), and the status bits of the elements
    /// that are NaN or infinite (their mantissa and exponent are 0).
    pub fn query_matrix(&self) -> ([GLfixed; 16], [GLint; 16], GLbitfield) {
        let m = self.current_matrix().to_cols_array();
        let (mut mant, mut exp, mut status) = ([0; 16], [0; 16], 0);
        for (i, &v) in m.iter().enumerate() {
            if !v.is_finite() {
                status |= 1 << i;
                continue;
            }
            // Shift large values down until the mantissa fits below 2¹⁵.
            let mut e = 0;
            let mut f = v as f64;
            while f.abs() >= 32767.0 {
                f *= 0.5;
                e += 1;
            }
            mant[i] = gles_cm_core::fixed::from_f32(f as f32);
            exp[i] = e;
        }
        (mant, exp, status)
    }

    /// `glCurrentPaletteMatrixOES`: selects the palette matrix that matrix operations in
    /// `GL_MATRIX_PALETTE_OES` mode change.
    pub fn current_palette_matrix(&mut self, index: u32) {
        if index as usize >= MAX_PALETTE_MATRICES {
            return self.bad_value(
                "index",
                index as i64,
                "index must be less than GL_MAX_PALETTE_MATRICES_OES (32)",
            );
        }
        self.current_palette = index as usize;
    }

    /// `glLoadPaletteFromModelViewMatrixOES`: copies the current modelview matrix into the
    /// current palette matrix.
    pub fn load_palette_from_modelview(&mut self) {
        self.palette[self.current_palette] = *self.modelview.last().expect("stack never empty");
    }

    pub fn matrix_mode(&mut self, mode: GLenum) {
        self.matrix_mode = match mode {
            GL_MODELVIEW => MatrixMode::Modelview,
            GL_PROJECTION => MatrixMode::Projection,
            GL_TEXTURE => MatrixMode::Texture,
            GL_MATRIX_PALETTE_OES => MatrixMode::Palette,
            _ => return self.bad_enum("mode", mode),
        };
    }

    pub fn push_matrix(&mut self) {
        // The palette matrices have no stacks: pushing or popping them is an invalid
        // operation (OES_matrix_palette).
        if self.matrix_mode == MatrixMode::Palette {
            return self.bad_operation(
                "the matrix mode is GL_MATRIX_PALETTE_OES, whose matrices have no stacks",
            );
        }
        let (stack, max) = self.stack();
        if stack.len() >= max {
            return self.set_error(GL_STACK_OVERFLOW);
        }
        let top = *stack.last().expect("stack never empty");
        stack.push(top);
    }

    pub fn pop_matrix(&mut self) {
        if self.matrix_mode == MatrixMode::Palette {
            return self.bad_operation(
                "the matrix mode is GL_MATRIX_PALETTE_OES, whose matrices have no stacks",
            );
        }
        let (stack, _) = self.stack();
        if stack.len() <= 1 {
            return self.set_error(GL_STACK_UNDERFLOW);
        }
        stack.pop();
    }

    pub fn load_identity(&mut self) {
        *self.current() = Mat4::IDENTITY;
    }

    /// `m` is column-major, as GL passes matrices.
    pub fn load_matrix(&mut self, m: &[f32; 16]) {
        *self.current() = Mat4::from_cols_array(m);
    }

    pub fn mult_matrix(&mut self, m: &[f32; 16]) {
        let c = self.current();
        *c *= Mat4::from_cols_array(m);
    }

    pub fn translate(&mut self, x: f32, y: f32, z: f32) {
        let c = self.current();
        *c *= Mat4::from_translation(Vec3::new(x, y, z));
    }

    pub fn scale(&mut self, x: f32, y: f32, z: f32) {
        let c = self.current();
        *c *= Mat4::from_scale(Vec3::new(x, y, z));
    }

    /// Rotation by `angle` degrees about (x, y, z); a zero axis leaves the matrix unchanged
    /// rather than filling it with NaN.
    pub fn rotate(&mut self, angle: f32, x: f32, y: f32, z: f32) {
        let axis = Vec3::new(x, y, z);
        let len = axis.length();
        if len.is_nan() || len <= 0.0 || !len.is_finite() {
            return;
        }
        let c = self.current();
        *c *= Mat4::from_axis_angle(axis / len, angle.to_radians());
    }

    pub fn frustum(&mut self, l: f32, r: f32, b: f32, t: f32, n: f32, f: f32) {
        if n <= 0.0 || f <= 0.0 || l == r || b == t || n == f {
            return self.fail(
                GL_INVALID_VALUE,
                super::debug::Why::Rule(
                    "near and far must be positive, and left != right, bottom != top, near != far",
                ),
            );
        }
        let m = Mat4::from_cols_array(&[
            2.0 * n / (r - l),
            0.0,
            0.0,
            0.0,
            0.0,
            2.0 * n / (t - b),
            0.0,
            0.0,
            (r + l) / (r - l),
            (t + b) / (t - b),
            -(f + n) / (f - n),
            -1.0,
            0.0,
            0.0,
            -2.0 * f * n / (f - n),
            0.0,
        ]);
        let c = self.current();
        *c *= m;
    }

    pub fn ortho(&mut self, l: f32, r: f32, b: f32, t: f32, n: f32, f: f32) {
        if l == r || b == t || n == f {
            return self.fail(
                GL_INVALID_VALUE,
                super::debug::Why::Rule("left != right, bottom != top and near != far must hold"),
            );
        }
        let m = Mat4::from_cols_array(&[
            2.0 / (r - l),
            0.0,
            0.0,
            0.0,
            0.0,
            2.0 / (t - b),
            0.0,
            0.0,
            0.0,
            0.0,
            -2.0 / (f - n),
            0.0,
            -(r + l) / (r - l),
            -(t + b) / (t - b),
            -(f + n) / (f - n),
            1.0,
        ]);
        let c = self.current();
        *c *= m;
    }
}
