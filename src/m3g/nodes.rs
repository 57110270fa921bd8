//! `Camera` and `Light`.

use glam::Mat4;

use super::error::{ae, iae, Result};
use super::node::NodeExt;
use super::object::{class_data, handle, Inner, Kind, TransformableExt};
use super::transform::Transform;

#[derive(Clone, Debug)]
pub(crate) struct CameraData {
    pub projection: i32,
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
    /// A projection given as a matrix.
    pub const GENERIC: i32 = 48;
    /// A parallel projection.
    pub const PARALLEL: i32 = 49;
    /// A perspective projection.
    pub const PERSPECTIVE: i32 = 50;

    /// `Camera()`: GENERIC with the identity matrix.
    pub fn new() -> Camera {
        Camera(Inner::new(
            Kind::Camera(CameraData {
                projection: Camera::GENERIC,
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
        d.projection = Camera::PERSPECTIVE;
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
        d.projection = Camera::PARALLEL;
        d.params = [height, aspect, near, far];
        Ok(())
    }

    /// `setGeneric(T)`: the matrix is copied.
    pub fn set_generic(&self, t: &Transform) {
        let mut d = self.dm();
        d.projection = Camera::GENERIC;
        d.matrix = t.m;
    }

    /// `getProjection(Transform)`: the projection type and matrix. Arithmetic for a
    /// PERSPECTIVE or PARALLEL projection with near == far.
    pub fn get_projection(&self) -> Result<(i32, Transform)> {
        let kind = self.d().projection;
        match self.projection_matrix() {
            Some(m) => Ok((kind, Transform::from_mat4(m))),
            None => ae("near == far"),
        }
    }

    /// `getProjection(float[])`: the type and, for PERSPECTIVE and PARALLEL, the parameters
    /// exactly as set ([fovy or height, aspect, near, far]); `None` for GENERIC.
    pub fn get_projection_params(&self) -> (i32, Option<[f32; 4]>) {
        let d = self.d();
        (
            d.projection,
            (d.projection != Camera::GENERIC).then_some(d.params),
        )
    }

    /// The projection matrix, `None` when the view volume is empty (near == far).
    pub(crate) fn projection_matrix(&self) -> Option<Mat4> {
        let d = self.d();
        let [p, aspect, near, far] = d.params;
        match d.projection {
            Camera::GENERIC => Some(d.matrix),
            _ if near == far => None,
            Camera::PERSPECTIVE => {
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

#[derive(Clone, Debug)]
pub(crate) struct LightData {
    pub mode: i32,
    pub color: u32,
    pub intensity: f32,
    pub attenuation: [f32; 3],
    pub spot_angle: f32,
    pub spot_exponent: f32,
}

handle!(
    /// `Light`: an ambient, directional, omnidirectional or spot light node.
    Light,
    |i| matches!(i.kind, Kind::Light(_))
);
class_data!(Light, Light, LightData);
impl TransformableExt for Light {}
impl NodeExt for Light {}

impl Default for Light {
    fn default() -> Self {
        Light::new()
    }
}

impl Light {
    /// Ambient light.
    pub const AMBIENT: i32 = 128;
    /// Directional light, shining along the node's −Z.
    pub const DIRECTIONAL: i32 = 129;
    /// A point light at the node's origin.
    pub const OMNI: i32 = 130;
    /// A spot light at the origin, pointing along −Z.
    pub const SPOT: i32 = 131;

    /// `Light()`: DIRECTIONAL, white, intensity 1, attenuation (1, 0, 0), spot angle 45°,
    /// spot exponent 0.
    pub fn new() -> Light {
        Light(Inner::new(
            Kind::Light(LightData {
                mode: Light::DIRECTIONAL,
                color: 0x00FF_FFFF,
                intensity: 1.0,
                attenuation: [1.0, 0.0, 0.0],
                spot_angle: 45.0,
                spot_exponent: 0.0,
            }),
            true,
            true,
        ))
    }
    /// `setMode(mode)`: IllegalArgument unless AMBIENT, DIRECTIONAL, OMNI or SPOT.
    pub fn set_mode(&self, mode: i32) -> Result<()> {
        if !(Light::AMBIENT..=Light::SPOT).contains(&mode) {
            return iae("invalid light mode");
        }
        self.dm().mode = mode;
        Ok(())
    }
    /// `getMode()`.
    pub fn mode(&self) -> i32 {
        self.d().mode
    }
    /// `setIntensity(i)`: any value (negative makes an "antilight").
    pub fn set_intensity(&self, intensity: f32) {
        self.dm().intensity = intensity;
    }
    /// `getIntensity()`.
    pub fn intensity(&self) -> f32 {
        self.d().intensity
    }
    /// `setColor(RGB)`: the top byte is ignored.
    pub fn set_color(&self, rgb: i32) {
        self.dm().color = rgb as u32 & 0xFF_FFFF;
    }
    /// `getColor()`: 0x00RRGGBB.
    pub fn color(&self) -> i32 {
        self.d().color as i32
    }
    /// `setSpotAngle(a)`: IllegalArgument unless 0 ≤ a ≤ 90 (degrees, the cone's half angle).
    pub fn set_spot_angle(&self, angle: f32) -> Result<()> {
        if !(0.0..=90.0).contains(&angle) {
            return iae("spot angle must be in [0, 90]");
        }
        self.dm().spot_angle = angle;
        Ok(())
    }
    /// `getSpotAngle()`.
    pub fn spot_angle(&self) -> f32 {
        self.d().spot_angle
    }
    /// `setSpotExponent(e)`: IllegalArgument unless 0 ≤ e ≤ 128.
    pub fn set_spot_exponent(&self, exponent: f32) -> Result<()> {
        if !(0.0..=128.0).contains(&exponent) {
            return iae("spot exponent must be in [0, 128]");
        }
        self.dm().spot_exponent = exponent;
        Ok(())
    }
    /// `getSpotExponent()`.
    pub fn spot_exponent(&self) -> f32 {
        self.d().spot_exponent
    }
    /// `setAttenuation(c, l, q)`: the factor is 1 / (c + l·d + q·d²). IllegalArgument if any
    /// is negative or all are zero.
    pub fn set_attenuation(&self, constant: f32, linear: f32, quadratic: f32) -> Result<()> {
        let a = [constant, linear, quadratic];
        if a.iter().any(|&v| v < 0.0 || v.is_nan()) || a.iter().all(|&v| v == 0.0) {
            return iae("attenuation must be non-negative and not all zero");
        }
        self.dm().attenuation = a;
        Ok(())
    }
    /// `getConstantAttenuation()`.
    pub fn constant_attenuation(&self) -> f32 {
        self.d().attenuation[0]
    }
    /// `getLinearAttenuation()`.
    pub fn linear_attenuation(&self) -> f32 {
        self.d().attenuation[1]
    }
    /// `getQuadraticAttenuation()`.
    pub fn quadratic_attenuation(&self) -> f32 {
        self.d().attenuation[2]
    }
}
