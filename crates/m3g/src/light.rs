//! `Light`: the ambient, directional, omni and spot light nodes.

use super::color::Color;
use super::error::{iae, Result};
use super::modes::LightMode;
use super::node::NodeExt;
use super::object::{class_data, handle, Inner, Kind, TransformableExt};

#[derive(Clone, Debug)]
pub(crate) struct LightData {
    pub mode: LightMode,
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
    /// `Light()`: DIRECTIONAL, white, intensity 1, attenuation (1, 0, 0), spot angle 45°,
    /// spot exponent 0.
    ///
    /// ```
    /// use m3g::prelude::*;
    ///
    /// # fn main() -> m3g::Result<()> {
    /// // A yellow spot light two units above the origin, pointing down.
    /// let spot = Light::new();
    /// spot.set_mode(LightMode::Spot);
    /// spot.set_color(Color::rgb(255, 255, 0));
    /// spot.set_spot_angle(30.0)?;
    /// spot.set_translation(0.0, 2.0, 0.0);
    /// spot.set_orientation(-90.0, 1.0, 0.0, 0.0)?; // −Z turned to −Y
    /// let world = World::new();
    /// world.add_child(&spot)?;
    /// assert_eq!(spot.color(), Color(0x00FFFF00)); // RGB: alpha reads as 0
    /// # Ok(())
    /// # }
    /// ```
    pub fn new() -> Light {
        Light(Inner::new(
            Kind::Light(LightData {
                mode: LightMode::Directional,
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
    /// `setMode(mode)`.
    pub fn set_mode(&self, mode: LightMode) {
        self.dm().mode = mode;
    }
    /// `getMode()`.
    pub fn mode(&self) -> LightMode {
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
    /// `setColor(RGB)`: the alpha byte is ignored.
    pub fn set_color(&self, rgb: Color) {
        self.dm().color = rgb.0 & 0xFF_FFFF;
    }
    /// `getColor()`: 0x00RRGGBB.
    pub fn color(&self) -> Color {
        Color(self.d().color)
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
