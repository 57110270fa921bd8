//! `OES_draw_texture`: `glDrawTex*OES` draws a screen-aligned rectangle at window position
//! (x, y) of size w × h, at window depth z mapped through the depth range, each enabled
//! texture unit sampled across its texture's crop rectangle (`GL_TEXTURE_CROP_RECT_OES`).
//!
//! It goes through the core like any draw: a quad in clip space with identity matrices,
//! w = 1, under a viewport covering the whole target (so only the scissor box and the
//! target's edges limit it, not the application's viewport or user clip planes). Texture
//! coordinates come from the crop rectangles, untransformed by the texture matrices and never
//! generated; the color is the current color, unlit. Fragments see fog at eye distance 0 (the
//! rectangle has no eye-space position), then every per-fragment operation.
#![forbid(unsafe_code)]

use glam::{Mat4, Vec3};

use gles_cm_core::{AttribArray, AttribSource, ComponentType, DrawCall, Indices, Primitive};

use super::buffer::lock_objects;
use super::context::{Context, MAX_TEXTURE_UNITS};
use super::tokens::*;

impl Context {
    /// The crop rectangle (u, v, width, height) of the 2D texture bound to `unit`.
    fn unit_crop_rect(&self, unit: usize) -> [i32; 4] {
        let bound = &self.textures.bound[unit];
        if bound.is_none() {
            self.textures.default.crop_rect
        } else {
            lock_objects(&self.shared)
                .textures
                .get(bound)
                .map_or([0; 4], |t| t.crop_rect)
        }
    }

    /// `glDrawTex{s,i,x,f}[v]OES` with the values converted to float.
    pub fn draw_texture(&mut self, x: f32, y: f32, z: f32, width: f32, height: f32) {
        // NaN sizes are as invalid as non-positive ones.
        if !(width > 0.0 && height > 0.0) {
            return self.fail(
                GL_INVALID_VALUE,
                super::debug::Why::Rule("width and height must be greater than 0"),
            );
        }
        if !self.framebuffer_ready() {
            return;
        }
        let Some(b) = self.with_frame(|f, _| f.bounds()) else {
            return;
        };
        if b.is_empty() {
            return;
        }
        let (x, y, w, h) = (x as f64, y as f64, width as f64, height as f64);
        // The part of the rectangle inside the target.
        let x0 = x.max(b.x0 as f64);
        let x1 = (x + w).min(b.x1 as f64);
        let y0 = y.max(b.y0 as f64);
        let y1 = (y + h).min(b.y1 as f64);
        if !(x0 < x1 && y0 < y1) {
            return;
        }
        let mut rs = self.take_render_state();
        let (vw, vh) = ((b.x1 - b.x0) as f64, (b.y1 - b.y0) as f64);
        rs.viewport = gles_cm_core::Viewport {
            x: b.x0,
            y: b.y0,
            width: b.x1 - b.x0,
            height: b.y1 - b.y0,
        };
        // Window depth n + clamp(z, 0, 1)·(f − n) is normalized depth 2·clamp(z) − 1.
        let zn = 2.0 * z.clamp(0.0, 1.0) - 1.0;
        let zn = if zn.is_nan() { -1.0 } else { zn };
        rs.modelview = Mat4::IDENTITY;
        rs.projection = Mat4::from_translation(Vec3::new(0.0, 0.0, zn));
        rs.lighting = None;
        rs.matrix_palette = None;
        rs.clip_planes.clear();
        rs.cull = None;
        rs.texture_matrices = [Mat4::IDENTITY; gles_cm_core::TEXTURE_UNITS];
        rs.texgen = [None; gles_cm_core::TEXTURE_UNITS];
        let corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)];
        let ndc = |(cx, cy): (f64, f64)| {
            [
                ((cx - b.x0 as f64) / vw * 2.0 - 1.0) as f32,
                ((cy - b.y0 as f64) / vh * 2.0 - 1.0) as f32,
            ]
        };
        // A plain loop: the nested `flat_map` it replaces compiled (after the frame
        // binding moved into the core) to code memcheck reports as branching on
        // uninitialised iterator state.
        let bytes = |v: &[[f32; 2]]| -> Vec<u8> {
            let mut out = Vec::with_capacity(v.len() * 8);
            for c in v.iter().flatten() {
                out.extend_from_slice(&c.to_ne_bytes());
            }
            out
        };
        let position = bytes(&corners.map(ndc));
        let mut tex: [Vec<u8>; MAX_TEXTURE_UNITS] = Default::default();
        for (u, unit) in rs.textures.iter_mut().enumerate() {
            let Some(t) = unit else { continue };
            if t.sampler.cube.is_some() {
                // Cube maps have no crop rectangle: such units are off here.
                *unit = None;
                continue;
            }
            let [cu, cv, cw, ch] = self.unit_crop_rect(u).map(f64::from);
            let (tw, th) = t.sampler.size();
            let st = |(cx, cy): (f64, f64)| {
                [
                    ((cu + (cx - x) * cw / w) / tw as f64) as f32,
                    ((cv + (cy - y) * ch / h) / th as f64) as f32,
                ]
            };
            tex[u] = bytes(&corners.map(st));
        }
        fn array(data: &[u8]) -> AttribArray<'_> {
            AttribArray {
                data,
                ty: ComponentType::Float,
                size: 2,
                stride: 8,
                normalized: false,
            }
        }
        let mut call = DrawCall::new(
            Primitive::TriangleFan,
            Indices::Range { first: 0, count: 4 },
            array(&position),
        );
        call.color = AttribSource::Constant(self.arrays.color_value);
        for (u, data) in tex.iter().enumerate() {
            if !data.is_empty() {
                call.texcoord[u] = AttribSource::Array(array(data));
            }
        }
        let recorded =
            self.with_frame(|frame, to| gles_cm_core::record_into(&rs, &call, frame, to));
        self.put_back_render_state(rs);
        if let Some(Err(_)) = recorded {
            self.set_error(GL_OUT_OF_MEMORY);
        }
    }
}
