//! `Camera`: the node that holds a projection.

use glam::Mat4;

use super::error::{ae, iae, Result};
use super::modes::Projection;
use super::node::NodeExt;
use super::object::{class_data, handle, Inner, Kind, TransformableExt};
use super::transform::Transform;

#[derive(Clone, Debug)]
pub(crate) struct CameraData {
    pub projection: Projection,
    /// fovy (or height), aspect, near, far as set.
    pub params: [f32; 4],
    pub matrix: Mat4,
}

handle!(
    /// `Camera`: a node that defines a projection; it looks along its local −Z.
    Camera,
    |i| matches!(i.kind, Kind::Camera(_))
);
class_data!(Camera, Camera, CameraData);
impl TransformableExt for Camera {}
impl NodeExt for Camera {}

impl Default for Camera {
    fn default() -> Self {
        Camera::new()
    }
}

impl Camera {
    /// `Camera()`: GENERIC with the identity matrix.
    ///
    /// ```
    /// use m3g::prelude::*;
    ///
    /// # fn main() -> m3g::Result<()> {
    /// let camera = Camera::new();
    /// camera.set_perspective(60.0, 4.0 / 3.0, 0.1, 100.0)?;
    /// camera.set_translation(0.0, 1.0, 5.0); // it looks along its −Z
    /// let world = World::new();
    /// world.add_child(&camera)?;
    /// world.set_active_camera(&camera);
    /// let (kind, params) = camera.get_projection_params();
    /// assert_eq!(kind, Projection::Perspective);
    /// assert_eq!(params, Some([60.0, 4.0 / 3.0, 0.1, 100.0]));
    /// # Ok(())
    /// # }
    /// ```
    pub fn new() -> Camera {
        Camera(Inner::new(
            Kind::Camera(CameraData {
                projection: Projection::Generic,
                params: [0.0; 4],
                matrix: Mat4::IDENTITY,
            }),
            true,
            true,
        ))
    }

    /// `setPerspective(fovy, aspect, near, far)`: fovy in degrees. IllegalArgument if any
    /// argument is ≤ 0 or fovy ≥ 180. near and far may come in either order.
    pub fn set_perspective(&self, fovy: f32, aspect: f32, near: f32, far: f32) -> Result<()> {
        if !(fovy > 0.0 && aspect > 0.0 && near > 0.0 && far > 0.0) || fovy >= 180.0 {
            return iae("perspective parameters must be positive and fovy < 180");
        }
        let mut d = self.dm();
        d.projection = Projection::Perspective;
        d.params = [fovy, aspect, near, far];
        Ok(())
    }

    /// `setParallel(height, aspect, near, far)`: IllegalArgument if height or aspect ≤ 0.
    /// near and far may be anything.
    pub fn set_parallel(&self, height: f32, aspect: f32, near: f32, far: f32) -> Result<()> {
        if !(height > 0.0 && aspect > 0.0) {
            return iae("parallel height and aspect must be positive");
        }
        let mut d = self.dm();
        d.projection = Projection::Parallel;
        d.params = [height, aspect, near, far];
        Ok(())
    }

    /// `setGeneric(T)`: the matrix is copied.
    pub fn set_generic(&self, t: &Transform) {
        let mut d = self.dm();
        d.projection = Projection::Generic;
        d.matrix = t.m;
    }

    /// `getProjection(Transform)`: the projection type and matrix. Arithmetic for a
    /// PERSPECTIVE or PARALLEL projection with near == far.
    pub fn get_projection(&self) -> Result<(Projection, Transform)> {
        let kind = self.d().projection;
        match self.projection_matrix() {
            Some(m) => Ok((kind, Transform::from_mat4(m))),
            None => ae("near == far"),
        }
    }

    /// `getProjection(float[])`: the type and, for PERSPECTIVE and PARALLEL, the parameters
    /// exactly as set ([fovy or height, aspect, near, far]); `None` for GENERIC.
    pub fn get_projection_params(&self) -> (Projection, Option<[f32; 4]>) {
        let d = self.d();
        (
            d.projection,
            (d.projection != Projection::Generic).then_some(d.params),
        )
    }

    /// The projection matrix, `None` when the view volume is empty (near == far).
    pub(crate) fn projection_matrix(&self) -> Option<Mat4> {
        let d = self.d();
        let [p, aspect, near, far] = d.params;
        match d.projection {
            Projection::Generic => Some(d.matrix),
            _ if near == far => None,
            Projection::Perspective => {
                let h = (p.to_radians() * 0.5).tan();
                let w = aspect * h;
                let dz = far - near;
                Some(Mat4::from_cols_array(&[
                    1.0 / w,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    1.0 / h,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    -(near + far) / dz,
                    -1.0,
                    0.0,
                    0.0,
                    -2.0 * near * far / dz,
                    0.0,
                ]))
            }
            _ => {
                let (h, w, dz) = (p, aspect * p, far - near);
                Some(Mat4::from_cols_array(&[
                    2.0 / w,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    2.0 / h,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    -2.0 / dz,
                    0.0,
                    0.0,
                    0.0,
                    -(near + far) / dz,
                    1.0,
                ]))
            }
        }
    }
}
