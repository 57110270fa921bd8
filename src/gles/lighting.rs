//! Lighting state (ES 1.1 §2.12): lights, the light model and the material. Positions and
//! spot directions are stored in eye coordinates, transformed when specified.
#![forbid(unsafe_code)]

use glam::{Mat3, Vec3, Vec4};

use super::context::{Context, MAX_LIGHTS};
use super::get::Value;
use super::params::Params;
use super::tokens::*;
use super::types::*;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    pub ambient: [f32; 4],
    pub diffuse: [f32; 4],
    pub specular: [f32; 4],
    /// Eye coordinates; w = 0 is a directional light.
    pub position: [f32; 4],
    /// Eye coordinates.
    pub spot_direction: [f32; 3],
    pub spot_exponent: f32,
    pub spot_cutoff: f32,
    pub constant_attenuation: f32,
    pub linear_attenuation: f32,
    pub quadratic_attenuation: f32,
}

impl Light {
    /// Light 0 starts white; the others start black (ES 1.1 table 6.10).
    fn new(index: usize) -> Light {
        let c = if index == 0 {
            [1.0; 4]
        } else {
            [0.0, 0.0, 0.0, 1.0]
        };
        Light {
            ambient: [0.0, 0.0, 0.0, 1.0],
            diffuse: c,
            specular: c,
            position: [0.0, 0.0, 1.0, 0.0],
            spot_direction: [0.0, 0.0, -1.0],
            spot_exponent: 0.0,
            spot_cutoff: 180.0,
            constant_attenuation: 1.0,
            linear_attenuation: 0.0,
            quadratic_attenuation: 0.0,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    pub ambient: [f32; 4],
    pub diffuse: [f32; 4],
    pub specular: [f32; 4],
    pub emission: [f32; 4],
    pub shininess: f32,
}

impl Default for Material {
    fn default() -> Material {
        Material {
            ambient: [0.2, 0.2, 0.2, 1.0],
            diffuse: [0.8, 0.8, 0.8, 1.0],
            specular: [0.0, 0.0, 0.0, 1.0],
            emission: [0.0, 0.0, 0.0, 1.0],
            shininess: 0.0,
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Lighting {
    pub lights: [Light; MAX_LIGHTS],
    pub model_ambient: [f32; 4],
    pub two_side: bool,
    /// ES 1.1 sets front and back materials together (`GL_FRONT_AND_BACK` only), so one
    /// material serves both faces.
    pub material: Material,
}

impl Default for Lighting {
    fn default() -> Lighting {
        Lighting {
            lights: std::array::from_fn(Light::new),
            model_ambient: [0.2, 0.2, 0.2, 1.0],
            two_side: false,
            material: Material::default(),
        }
    }
}

impl Lighting {
    /// With `GL_COLOR_MATERIAL` enabled the current color is the material's ambient and
    /// diffuse color: called when the color changes and when tracking is enabled.
    pub fn track_color(&mut self, rgba: [f32; 4]) {
        self.material.ambient = rgba;
        self.material.diffuse = rgba;
    }
}

/// How many values `glLight*v` reads for `light` and `pname` (`None`: invalid names).
pub fn light_parameter_count(light: GLenum, pname: GLenum) -> Option<usize> {
    light_index(light)?;
    match pname {
        GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_POSITION => Some(4),
        GL_SPOT_DIRECTION => Some(3),
        GL_SPOT_EXPONENT
        | GL_SPOT_CUTOFF
        | GL_CONSTANT_ATTENUATION
        | GL_LINEAR_ATTENUATION
        | GL_QUADRATIC_ATTENUATION => Some(1),
        _ => None,
    }
}

/// How many values `glLightModel*v` reads for `pname` (`None`: an invalid name).
pub fn light_model_parameter_count(pname: GLenum) -> Option<usize> {
    match pname {
        GL_LIGHT_MODEL_AMBIENT => Some(4),
        GL_LIGHT_MODEL_TWO_SIDE => Some(1),
        _ => None,
    }
}

/// How many values `glMaterial*v` reads for `face` and `pname` (`None`: invalid names).
pub fn material_parameter_count(face: GLenum, pname: GLenum) -> Option<usize> {
    if face != GL_FRONT_AND_BACK {
        return None;
    }
    match pname {
        GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION | GL_AMBIENT_AND_DIFFUSE => Some(4),
        GL_SHININESS => Some(1),
        _ => None,
    }
}

fn light_index(light: GLenum) -> Option<usize> {
    let i = light.checked_sub(GL_LIGHT0)? as usize;
    (i < MAX_LIGHTS).then_some(i)
}

impl Context {
    /// `glLight{f,x}[v]`. A vector name through a single-value call is `GL_INVALID_ENUM`.
    pub fn light(&mut self, light: GLenum, pname: GLenum, p: Params<'_>) {
        let Some(i) = light_index(light) else {
            return self.bad_enum("light", light);
        };
        if light_parameter_count(light, pname).is_none_or(|n| p.len() < n) {
            return self.set_error(GL_INVALID_ENUM);
        }
        let mv = *self.modelview.last().expect("stack never empty");
        let l = &mut self.lighting.lights[i];
        let v = p.number(0);
        match pname {
            GL_AMBIENT => l.ambient = p.numbers(),
            GL_DIFFUSE => l.diffuse = p.numbers(),
            GL_SPECULAR => l.specular = p.numbers(),
            GL_POSITION => l.position = (mv * Vec4::from_array(p.numbers())).to_array(),
            GL_SPOT_DIRECTION => {
                let d = Mat3::from_mat4(mv) * Vec3::from_array(p.numbers());
                l.spot_direction = d.to_array();
            }
            GL_SPOT_EXPONENT if (0.0..=128.0).contains(&v) => l.spot_exponent = v,
            GL_SPOT_CUTOFF if (0.0..=90.0).contains(&v) || v == 180.0 => l.spot_cutoff = v,
            GL_CONSTANT_ATTENUATION if v >= 0.0 => l.constant_attenuation = v,
            GL_LINEAR_ATTENUATION if v >= 0.0 => l.linear_attenuation = v,
            GL_QUADRATIC_ATTENUATION if v >= 0.0 => l.quadratic_attenuation = v,
            GL_SPOT_EXPONENT
            | GL_SPOT_CUTOFF
            | GL_CONSTANT_ATTENUATION
            | GL_LINEAR_ATTENUATION
            | GL_QUADRATIC_ATTENUATION => self.set_error(GL_INVALID_VALUE),
            _ => self.bad_enum("pname", pname),
        }
    }

    /// `glGetLight{f,x}v`.
    pub fn get_light(&mut self, light: GLenum, pname: GLenum) -> Option<Value> {
        let Some(i) = light_index(light) else {
            self.bad_enum("light", light);
            return None;
        };
        let l = &self.lighting.lights[i];
        let f = |v: &[f32]| Value::floats(v);
        Some(match pname {
            GL_AMBIENT => Value::norm(&l.ambient),
            GL_DIFFUSE => Value::norm(&l.diffuse),
            GL_SPECULAR => Value::norm(&l.specular),
            GL_POSITION => f(&l.position),
            GL_SPOT_DIRECTION => f(&l.spot_direction),
            GL_SPOT_EXPONENT => f(&[l.spot_exponent]),
            GL_SPOT_CUTOFF => f(&[l.spot_cutoff]),
            GL_CONSTANT_ATTENUATION => f(&[l.constant_attenuation]),
            GL_LINEAR_ATTENUATION => f(&[l.linear_attenuation]),
            GL_QUADRATIC_ATTENUATION => f(&[l.quadratic_attenuation]),
            _ => {
                self.bad_enum("pname", pname);
                return None;
            }
        })
    }

    /// `glLightModel{f,x}[v]`: `GL_LIGHT_MODEL_TWO_SIDE` is true for any nonzero value.
    pub fn light_model(&mut self, pname: GLenum, p: Params<'_>) {
        if light_model_parameter_count(pname).is_none_or(|n| p.len() < n) {
            return self.set_error(GL_INVALID_ENUM);
        }
        match pname {
            GL_LIGHT_MODEL_AMBIENT => self.lighting.model_ambient = p.numbers(),
            GL_LIGHT_MODEL_TWO_SIDE => self.lighting.two_side = p.number(0) != 0.0,
            _ => self.bad_enum("pname", pname),
        }
    }

    /// `glMaterial{f,x}[v]`: ES 1.1 accepts only `GL_FRONT_AND_BACK`.
    pub fn material(&mut self, face: GLenum, pname: GLenum, p: Params<'_>) {
        if material_parameter_count(face, pname).is_none_or(|n| p.len() < n) {
            return self.set_error(GL_INVALID_ENUM);
        }
        let m = &mut self.lighting.material;
        match pname {
            GL_AMBIENT => m.ambient = p.numbers(),
            GL_DIFFUSE => m.diffuse = p.numbers(),
            GL_SPECULAR => m.specular = p.numbers(),
            GL_EMISSION => m.emission = p.numbers(),
            GL_AMBIENT_AND_DIFFUSE => {
                m.ambient = p.numbers();
                m.diffuse = m.ambient;
            }
            GL_SHININESS => {
                let v = p.number(0);
                if !(0.0..=128.0).contains(&v) {
                    return self.set_error(GL_INVALID_VALUE);
                }
                m.shininess = v;
            }
            _ => self.bad_enum("pname", pname),
        }
    }

    /// `glGetMaterial{f,x}v`: face `GL_FRONT` or `GL_BACK`.
    pub fn get_material(&mut self, face: GLenum, pname: GLenum) -> Option<Value> {
        let m = &self.lighting.material;
        let v = match (face, pname) {
            (GL_FRONT | GL_BACK, GL_AMBIENT) => Value::norm(&m.ambient),
            (GL_FRONT | GL_BACK, GL_DIFFUSE) => Value::norm(&m.diffuse),
            (GL_FRONT | GL_BACK, GL_SPECULAR) => Value::norm(&m.specular),
            (GL_FRONT | GL_BACK, GL_EMISSION) => Value::norm(&m.emission),
            (GL_FRONT | GL_BACK, GL_SHININESS) => Value::floats(&[m.shininess]),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        };
        Some(v)
    }

    pub(super) fn lighting_value(&self, pname: GLenum) -> Option<Value> {
        let l = &self.lighting;
        Some(match pname {
            GL_LIGHT_MODEL_AMBIENT => Value::norm(&l.model_ambient),
            GL_LIGHT_MODEL_TWO_SIDE => Value::bools(&[l.two_side]),
            _ => return None,
        })
    }
}
