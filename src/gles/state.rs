//! Simple state setters: capabilities, hints, per-fragment state, clear values, the viewport,
//! scissor box and pixel storage. Each validates its arguments as the specification says and
//! leaves the state untouched on error.
#![forbid(unsafe_code)]

use gles_cm_core::{CullFace, Rect, ShadeModel, Winding, MAX_VIEWPORT_DIM};

use super::context::{compare_func, Context};
use super::tokens::*;
use super::types::*;

impl Context {
    pub fn set_capability(&mut self, cap: GLenum, on: bool) {
        let unit = self.active_texture;
        if let Some(flag) = self.debug_flag(cap) {
            *flag = on;
            return;
        }
        match self.enables.flag(cap, unit) {
            Some(flag) => *flag = on,
            None => return self.bad_enum("cap", cap),
        }
        // While enabled, the material's ambient and diffuse colors track the current color.
        if cap == GL_COLOR_MATERIAL && on {
            self.lighting.track_color(self.arrays.color_value);
        }
    }

    pub fn is_enabled(&mut self, cap: GLenum) -> bool {
        // glIsEnabled also answers for the client-side arrays (ES 1.1 §6.1.1).
        if let Some(on) = self.client_array_enabled(cap) {
            return on;
        }
        if let Some(flag) = self.debug_flag(cap) {
            return *flag;
        }
        let unit = self.active_texture;
        match self.enables.flag(cap, unit) {
            Some(flag) => *flag,
            None => {
                self.bad_enum("cap", cap);
                false
            }
        }
    }

    pub fn hint(&mut self, target: GLenum, mode: GLenum) {
        if !matches!(mode, GL_FASTEST | GL_NICEST | GL_DONT_CARE) {
            return self.bad_enum("mode", mode);
        }
        let h = &mut self.hints;
        let slot = match target {
            GL_PERSPECTIVE_CORRECTION_HINT => &mut h.perspective_correction,
            GL_POINT_SMOOTH_HINT => &mut h.point_smooth,
            GL_LINE_SMOOTH_HINT => &mut h.line_smooth,
            GL_FOG_HINT => &mut h.fog,
            GL_GENERATE_MIPMAP_HINT => &mut h.generate_mipmap,
            _ => return self.bad_enum("target", target),
        };
        *slot = mode;
    }

    pub fn depth_func(&mut self, func: GLenum) {
        match compare_func(func) {
            Some(f) => self.depth_func = f,
            None => self.bad_enum("func", func),
        }
    }

    pub fn cull_face(&mut self, mode: GLenum) {
        self.cull_face = match mode {
            GL_FRONT => CullFace::Front,
            GL_BACK => CullFace::Back,
            GL_FRONT_AND_BACK => CullFace::FrontAndBack,
            _ => return self.bad_enum("mode", mode),
        };
    }

    pub fn front_face(&mut self, mode: GLenum) {
        self.front_face = match mode {
            GL_CCW => Winding::Ccw,
            GL_CW => Winding::Cw,
            _ => return self.bad_enum("mode", mode),
        };
    }

    pub fn shade_model(&mut self, mode: GLenum) {
        self.shade_model = match mode {
            GL_FLAT => ShadeModel::Flat,
            GL_SMOOTH => ShadeModel::Smooth,
            _ => return self.bad_enum("mode", mode),
        };
    }

    pub fn color_mask(&mut self, mask: [bool; 4]) {
        self.color_mask = mask;
    }

    pub fn depth_mask(&mut self, on: bool) {
        self.depth_mask = on;
    }

    pub fn stencil_mask(&mut self, mask: u32) {
        self.stencil_writemask = mask;
    }

    /// Clear values are clamped to [0, 1] when specified (ES 1.1 §4.2.3).
    pub fn clear_color(&mut self, rgba: [f32; 4]) {
        self.clear_color = rgba.map(clamp01);
    }

    pub fn clear_depth(&mut self, z: f32) {
        self.clear_depth = clamp01(z);
    }

    pub fn clear_stencil(&mut self, s: i32) {
        self.clear_stencil = s;
    }

    pub fn depth_range(&mut self, near: f32, far: f32) {
        self.depth_range = [clamp01(near), clamp01(far)];
    }

    /// Negative sizes are errors; sizes beyond `GL_MAX_VIEWPORT_DIMS` are silently clamped.
    pub fn viewport(&mut self, x: i32, y: i32, w: i32, h: i32) {
        if w < 0 || h < 0 {
            return self.bad_value(
                if w < 0 { "width" } else { "height" },
                w.min(h) as i64,
                "width and height must not be negative",
            );
        }
        let max = MAX_VIEWPORT_DIM as i32;
        self.viewport = gles_cm_core::Viewport {
            x,
            y,
            width: w.min(max),
            height: h.min(max),
        };
    }

    pub fn scissor(&mut self, x: i32, y: i32, w: i32, h: i32) {
        if w < 0 || h < 0 {
            return self.bad_value(
                if w < 0 { "width" } else { "height" },
                w.min(h) as i64,
                "width and height must not be negative",
            );
        }
        self.scissor_box = Rect::new(x, y, w, h);
    }

    pub fn pixel_store(&mut self, pname: GLenum, param: i32) {
        let slot = match pname {
            GL_PACK_ALIGNMENT => &mut self.pack_alignment,
            GL_UNPACK_ALIGNMENT => &mut self.unpack_alignment,
            _ => return self.bad_enum("pname", pname),
        };
        match param {
            1 | 2 | 4 | 8 => *slot = param as usize,
            _ => self.bad_value("param", param as i64, "an alignment must be 1, 2, 4 or 8"),
        }
    }
}

/// Clamps to [0, 1]; NaN becomes 0 so it never reaches stored state.
pub(super) fn clamp01(v: f32) -> f32 {
    if v > 0.0 {
        v.min(1.0)
    } else {
        0.0
    }
}
