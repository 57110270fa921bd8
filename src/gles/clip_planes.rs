//! User clip planes (ES 1.1 §2.11), stored in eye coordinates.
#![forbid(unsafe_code)]

use glam::Vec4;

use super::context::{Context, MAX_CLIP_PLANES};
use super::tokens::*;
use super::types::*;

#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct ClipPlanes {
    /// Plane i in eye coordinates: (p1, p2, p3, p4) with p·(xe, ye, ze, we) ≥ 0 inside.
    pub planes: [[f32; 4]; MAX_CLIP_PLANES],
}

fn plane_index(plane: GLenum) -> Option<usize> {
    let i = plane.checked_sub(GL_CLIP_PLANE0)? as usize;
    (i < MAX_CLIP_PLANES).then_some(i)
}

/// How many values `glClipPlane*` reads for `plane` (`None`: an invalid plane).
pub fn clip_plane_count(plane: GLenum) -> Option<usize> {
    plane_index(plane).map(|_| 4)
}

impl Context {
    /// `glClipPlane{f,x}`: the plane given in object coordinates is stored in eye
    /// coordinates, multiplied by the inverse of the modelview matrix current now.
    pub fn clip_plane(&mut self, plane: GLenum, equation: [f32; 4]) {
        let Some(i) = plane_index(plane) else {
            return self.bad_enum("plane", plane);
        };
        let mv = *self.modelview.last().expect("stack never empty");
        // (p1 p2 p3 p4) M⁻¹ as a row vector is (M⁻¹)ᵀ applied to the column vector.
        let eye = mv.inverse().transpose() * Vec4::from_array(equation);
        self.clip_planes.planes[i] = eye.to_array();
    }

    /// `glGetClipPlane{f,x}`: the stored eye-coordinate plane.
    pub fn get_clip_plane(&mut self, plane: GLenum) -> Option<[f32; 4]> {
        match plane_index(plane) {
            Some(i) => Some(self.clip_planes.planes[i]),
            None => {
                self.bad_enum("plane", plane);
                None
            }
        }
    }
}
