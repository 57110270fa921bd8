//! `Transform`: a 4 × 4 float matrix (not an Object3D).

use glam::{DMat4, Mat4, Quat, Vec3, Vec4};

use super::error::{ae, iae, Result};
use super::vertex::VertexArray;

/// A generic 4 × 4 matrix, as `javax.microedition.m3g.Transform`. A plain value: `Clone`
/// copies it, as the Java API copies a Transform wherever it takes one.
///
/// The arrays of [`Transform::set`] and [`Transform::get`] are **row-major** (element 4 is
/// row 1, column 0), as in M3G; internally the matrix is a column-major `glam::Mat4`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    pub(crate) m: Mat4,
}

impl Default for Transform {
    fn default() -> Self {
        Transform::new()
    }
}

/// The rotation matrix of `glRotate` (M3G Transform.postRotate), or `None` for a zero axis
/// (identity when the angle is 0, an error otherwise: the caller decides).
pub(crate) fn rotation(angle_deg: f32, ax: f32, ay: f32, az: f32) -> Result<Mat4> {
    let len = (ax * ax + ay * ay + az * az).sqrt();
    if len == 0.0 || !len.is_finite() {
        if angle_deg == 0.0 {
            return Ok(Mat4::IDENTITY);
        }
        return iae("rotation axis is zero and the angle is not");
    }
    Ok(Mat4::from_axis_angle(
        Vec3::new(ax / len, ay / len, az / len),
        angle_deg.to_radians(),
    ))
}

/// A unit quaternion from (x, y, z, w), normalized first. IAE for the zero quaternion.
pub(crate) fn quaternion(x: f32, y: f32, z: f32, w: f32) -> Result<Quat> {
    let len = (x * x + y * y + z * z + w * w).sqrt();
    if len == 0.0 || !len.is_finite() {
        return iae("zero quaternion");
    }
    Ok(Quat::from_xyzw(x / len, y / len, z / len, w / len))
}

/// The inverse of `m`, computed in f64, or an Arithmetic error when it is singular.
pub(crate) fn invert(m: &Mat4) -> Result<Mat4> {
    let d = m.as_dmat4();
    let det = d.determinant();
    // Relative to the size of the elements, so scaled matrices are judged alike.
    let scale = d.to_cols_array().iter().fold(0.0f64, |a, v| a.max(v.abs()));
    if det == 0.0 || !det.is_finite() || scale == 0.0 || (det / scale.powi(4)).abs() < 1e-12 {
        return ae("the matrix is not invertible");
    }
    let inv: DMat4 = d.inverse();
    let out = inv.as_mat4();
    if !out.is_finite() {
        return ae("the matrix is not invertible");
    }
    Ok(out)
}

impl Transform {
    /// `Transform()`: the identity.
    pub fn new() -> Transform {
        Transform { m: Mat4::IDENTITY }
    }

    /// A transform holding `m` (a Rust extension).
    pub fn from_mat4(m: Mat4) -> Transform {
        Transform { m }
    }

    /// The matrix as a `glam::Mat4` (a Rust extension).
    pub fn to_mat4(&self) -> Mat4 {
        self.m
    }

    /// `setIdentity()`.
    pub fn set_identity(&mut self) {
        self.m = Mat4::IDENTITY;
    }

    /// `set(Transform)`: copies `t`.
    pub fn set_transform(&mut self, t: &Transform) {
        self.m = t.m;
    }

    /// `set(float[16])`: row-major. IllegalArgument if `matrix` has fewer than 16 elements.
    pub fn set(&mut self, matrix: &[f32]) -> Result<()> {
        if matrix.len() < 16 {
            return iae("matrix must have 16 elements");
        }
        let mut a = [0.0f32; 16];
        a.copy_from_slice(&matrix[..16]);
        self.m = Mat4::from_cols_array(&a).transpose();
        Ok(())
    }

    /// `get(float[16])`: the matrix, row-major.
    pub fn get(&self) -> [f32; 16] {
        self.m.transpose().to_cols_array()
    }

    /// `invert()`: Arithmetic if the matrix is singular (it is then unchanged).
    pub fn invert(&mut self) -> Result<()> {
        self.m = invert(&self.m)?;
        Ok(())
    }

    /// `transpose()`.
    pub fn transpose(&mut self) {
        self.m = self.m.transpose();
    }

    /// `postMultiply(T)`: this = this · T.
    pub fn post_multiply(&mut self, t: &Transform) {
        self.m *= t.m;
    }

    /// `postScale(sx, sy, sz)`: this = this · diag(sx, sy, sz, 1).
    pub fn post_scale(&mut self, sx: f32, sy: f32, sz: f32) {
        self.m *= Mat4::from_scale(Vec3::new(sx, sy, sz));
    }

    /// `postTranslate(tx, ty, tz)`: this = this · translation.
    pub fn post_translate(&mut self, tx: f32, ty: f32, tz: f32) {
        self.m *= Mat4::from_translation(Vec3::new(tx, ty, tz));
    }

    /// `postRotate(angle, ax, ay, az)`: this = this · R, with R the `glRotate` matrix (angle
    /// in degrees, axis normalized here). IllegalArgument for a zero axis with a non-zero angle.
    pub fn post_rotate(&mut self, angle: f32, ax: f32, ay: f32, az: f32) -> Result<()> {
        self.m *= rotation(angle, ax, ay, az)?;
        Ok(())
    }

    /// `postRotateQuat(qx, qy, qz, qw)`: the quaternion is normalized first.
    /// IllegalArgument if all four are zero.
    pub fn post_rotate_quat(&mut self, qx: f32, qy: f32, qz: f32, qw: f32) -> Result<()> {
        self.m *= Mat4::from_quat(quaternion(qx, qy, qz, qw)?);
        Ok(())
    }

    /// `transform(VertexArray, float[], boolean)`: every vertex of `input` (its raw integer
    /// values, no scale or bias) as (x, y, z, w) with z = 0 for 2-component input and w = 1 if
    /// `w` else 0, multiplied by this matrix. Returns 4 floats per vertex.
    /// IllegalArgument if the array has 4 components.
    pub fn transform_vertex_array(&self, input: &VertexArray, w: bool) -> Result<Vec<f32>> {
        let (n, comps) = (input.vertex_count(), input.component_count());
        if comps == 4 {
            return iae("the vertex array has 4 components");
        }
        let values = input.values_f32();
        let mut out = Vec::with_capacity(n * 4);
        for v in values.chunks(comps) {
            let p = Vec4::new(
                v[0],
                v[1],
                if comps > 2 { v[2] } else { 0.0 },
                if w { 1.0 } else { 0.0 },
            );
            out.extend_from_slice(&(self.m * p).to_array());
        }
        Ok(out)
    }

    /// `transform(float[])`: multiplies each (x, y, z, w) quadruplet in place, with no divide
    /// by w. IllegalArgument if the length is not a multiple of 4.
    pub fn transform(&self, vectors: &mut [f32]) -> Result<()> {
        if vectors.len() % 4 != 0 {
            return iae("the array length is not a multiple of 4");
        }
        for v in vectors.chunks_mut(4) {
            let r = self.m * Vec4::new(v[0], v[1], v[2], v[3]);
            v.copy_from_slice(&r.to_array());
        }
        Ok(())
    }
}
